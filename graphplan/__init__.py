"""graphplan — the graphical methods of the theory of machines and mechanisms, emulated and checked.

Position, velocity and acceleration plans, kinematic diagrams by chords and force plans, each
measured off the drawing and compared with an exact analytic solver. The calls a notebook starts
from (docs/api.md)::

    import graphplan
    s = graphplan.load("examples/shaper.toml")      # a scene (the built-in crank-slider without a path)
    p = graphplan.plans(s, precision=0.5)           # position, velocity and acceleration plans
    p.velocity(1); p.acceleration()                 # each displays itself in Jupyter
    graphplan.diagrams(s); graphplan.forces(s)      # s–v–a diagrams; force plans and the lever
    graphplan.dynamics(s)                           # the flywheel: Wittenbauer against exact
    graphplan.sheet(s, format="A1").save("shaper.pdf")

Every result has ``to_json()``, ``table()`` and an SVG/HTML display. Nothing heavy is imported
until a call needs it.
"""
from __future__ import annotations

from typing import Any

__version__ = "0.1.0"
__all__ = ["load", "study", "plans", "diagrams", "forces", "dynamics", "sheet", "cam", "gears", "__version__"]

_LAZY = {name: "graphplan.api" for name in ("load", "study", "plans", "diagrams", "forces", "dynamics", "sheet",
                                            "cam", "gears")}


def __getattr__(name: str) -> Any:
    """The public calls, imported on first use (``import graphplan`` stays light)."""
    if name in _LAZY:
        from importlib import import_module
        value = getattr(import_module(_LAZY[name]), name)
        globals()[name] = value
        return value
    raise AttributeError(f"module 'graphplan' has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_LAZY))
