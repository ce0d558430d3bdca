"""graphplan — the graphical methods of the theory of machines and mechanisms, emulated and checked.

Position, velocity and acceleration plans, kinematic diagrams by chords and force plans, each
measured off the drawing and compared with an exact analytic solver.
"""
from __future__ import annotations

__version__ = "0.1.0"
