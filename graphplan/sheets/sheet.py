"""`graphplan sheet`: the drawing sheets — frame and title block, the position plan, the velocity and
acceleration plans, the s–v–a diagrams and the tables (sheets/kinematics.py), the force analysis
(sheets/forces.py), laid out so nothing overlaps and carried over to further sheets of a set when
they do not fit (sheets/compose.py; REFERENCE §3). The output's suffix picks SVG, PDF, PNG or DXF;
every format views the same construction record.

``BUILDERS[kind](study, form, options)`` → ``Sheet``; options: positions, accel (degrees or "#3"),
precision (mm), lang — a ``SheetOptions`` or any object with those attributes."""
from __future__ import annotations

from collections.abc import Callable

from graphplan.sheets.compose import (FORMATS_OUT, Sheet, SheetOptions, compose, drawing_scale,  # noqa: F401
                                      page_path)
from graphplan.sheets.forces import FORCE_WORDS, build_forces_sheet, force_scales  # noqa: F401
from graphplan.sheets.kinematics import (FACTORS, WORDS, acceleration_table, build_kinematics_sheet,  # noqa: F401
                                         fields, flow, kinematics_blocks, notes, sheet_scales,
                                         velocity_table)
from graphplan.util.numbers import number as fmt  # noqa: F401

Options = SheetOptions

BUILDERS: dict[str, Callable[..., Sheet]] = {
    "kinematics": build_kinematics_sheet,
    "forces": build_forces_sheet,
}
