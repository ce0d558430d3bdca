"""`graphplan sheet`: the drawing sheets — the kinematic analysis (sheets/kinematics.py), the force
analysis (sheets/forces.py), the dynamics and the flywheel (sheets/dynamics.py) — each composed by
construction in zones (sheets/compose.py, drawing/layout.py; docs/composition.md) and carried over to
further sheets of a set when a small format cannot hold them. The output's suffix picks SVG, PDF,
PNG or DXF; every format views the same construction record.

``BUILDERS[kind](study, form, options)`` → ``Sheet``; options: positions, accel (degrees or "#3"),
precision (mm), lang — a ``SheetOptions`` or any object with those attributes."""
from __future__ import annotations

from collections.abc import Callable

from graphplan.sheets.compose import FORMATS_OUT, Sheet, SheetOptions, drawing_scale, page_path  # noqa: F401

Options = SheetOptions


def build_kinematics_sheet(st, f, options) -> Sheet:
    """Sheet 1 (sheets/kinematics.py): plans, diagrams, tables."""
    from graphplan.sheets.kinematics import build_kinematics_sheet as build
    return build(st, f, options)


def build_forces_sheet(st, f, options) -> Sheet:
    """Sheet 2 (sheets/forces.py): the force analysis at the scene's force position."""
    from graphplan.sheets.forces import build_forces_sheet as build
    return build(st, f, options)


def build_dynamics_sheet(st, f, options) -> Sheet:
    """Sheet 3 (sheets/dynamics.py): the flywheel by the Wittenbauer construction and the motor."""
    from graphplan.sheets.dynamics import build_dynamics_sheet as build
    return build(st, f, options)


def build_cam_sheet(cam, f, options) -> Sheet:
    """Sheet 4 (sheets/cam.py): the cam synthesised — its first argument the cam (model.cam.Cam),
    not a lever mechanism's study."""
    from graphplan.sheets.cam import build_cam_sheet as build
    return build(cam, f, options)


def build_gears_sheet(gears, f, options) -> Sheet:
    """The gear synthesis sheet (sheets/gears.py): its first argument the gear scene (model.gears.Gears)."""
    from graphplan.sheets.gears import build_gears_sheet as build
    return build(gears, f, options)


BUILDERS: dict[str, Callable[..., Sheet]] = {
    "kinematics": build_kinematics_sheet,
    "forces": build_forces_sheet,
    "dynamics": build_dynamics_sheet,
    "cam": build_cam_sheet,
    "gears": build_gears_sheet,
}
