"""`graphplan sheet`: the drawing sheets — frame and title block, the position plan, the velocity and
acceleration plans, the s–v–a diagrams and the tables (sheets/kinematics.py), the force analysis
(sheets/forces.py), the dynamics and the flywheel (sheets/dynamics.py), laid out so nothing overlaps
and carried over to further sheets of a set when they do not fit (sheets/compose.py; REFERENCE §3).
The output's suffix picks SVG, PDF, PNG or DXF; every format views the same construction record.

``BUILDERS[kind](study, form, options)`` → ``Sheet``; options: positions, accel (degrees or "#3"),
precision (mm), lang — a ``SheetOptions`` or any object with those attributes."""
from __future__ import annotations

from collections.abc import Callable

from graphplan.sheets.compose import (FORMATS_OUT, Sheet, SheetOptions, compose, drawing_scale,  # noqa: F401
                                      page_path)
from graphplan.sheets.forces import build_forces_sheet, force_scales  # noqa: F401
from graphplan.sheets.kinematics import (FACTORS, acceleration_table, build_kinematics_sheet,  # noqa: F401
                                         fields, flow, kinematics_blocks, notes, sheet_scales,
                                         velocity_table)
from graphplan.util.words import num

Options = SheetOptions


def fmt(v: float | None, lang: str, digits: int = 4) -> str:
    """Numbers for tables (util.words.num): 4 significant digits, the language's decimal sign, a
    true minus, '—' for none."""
    return num(v, lang, digits).replace("-", "−")


def build_dynamics_sheet(st, f, args) -> Sheet:
    """Sheet 3 (sheets/dynamics.py): the flywheel by the Wittenbauer construction and the motor."""
    from graphplan.sheets.dynamics import build_dynamics_sheet as build
    return build(st, f, args)


BUILDERS: dict[str, Callable[..., Sheet]] = {
    "kinematics": build_kinematics_sheet,
    "forces": build_forces_sheet,
    "dynamics": build_dynamics_sheet,
}
