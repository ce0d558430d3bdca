"""The one mechanism model: frame, crank, links, pairs and loads, in SI units.

Local coordinates of a link's points are complex numbers u + i·w (along, across)
in the link's own frame. A link's angle is the direction of its local x-axis:
from its first joint toward its second one, or along the guide it slides on.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

from graphplan.model.motors import Motor

FRAME = "0"


@dataclass(frozen=True)
class Guide:
    """A straight guide (a slide's line) carried by a body, in that body's frame. ``titles``: how a
    sheet in each language names it ((lang, text) pairs from the scene's ``title_uk``/``title_en``);
    without one, its name."""
    name: str
    body: str
    through: complex
    angle: float  # rad, in the body's frame
    titles: tuple[tuple[str, str], ...] = ()

    def title(self, lang: str) -> str:
        """The guide's name on a sheet in ``lang``."""
        return dict(self.titles).get(lang, self.name)


@dataclass(frozen=True)
class Link:
    """A rigid moving link: revolute joints, local geometry and, maybe, a sliding pair."""
    name: str
    number: int
    joints: tuple[str, ...]
    local: dict[str, complex]
    slides_on: str | None = None  # name of the guide this link slides along
    length: float | None = None   # the link's length (for q·l masses and I = k·m·l²)
    mass: float | None = None
    inertia: float | None = None
    com: str | None = None        # name of the centre-of-mass point



@dataclass(frozen=True)
class Crank:
    """The input link 1 turning about a frame point: ω1 signed (+ counter-clockwise)."""
    link: str
    pivot: str
    pin: str
    length: float
    omega: float
    epsilon: float = 0.0


@dataclass(frozen=True)
class Force:
    """An external force on a point: a magnitude, the strokes it acts on, and its direction.

    ``direction`` is "oppose" (against the point's velocity) or an angle in degrees. ``profile``
    (optional) scales the magnitude by a factor interpolated linearly over the output's distance
    from position 0 (m for a slide, degrees for a rocker): pairs (distance, factor).
    """
    point: str
    magnitude: float
    stroke: str = "working"  # "working", "idle" or "both"
    direction: str | float = "oppose"
    profile: tuple[tuple[float, float], ...] = ()


@dataclass(frozen=True)
class Moment:
    """An external couple on a link (a resistance moment on a rocker, a pump's or a loom's shaft):
    its magnitude in N·m, the strokes it acts on, its sense ("oppose": against the link's angular
    velocity; "ccw" or "cw") and, like a force, an optional profile over the output's distance."""
    link: str
    magnitude: float
    stroke: str = "working"  # "working", "idle" or "both"
    direction: str = "oppose"
    profile: tuple[tuple[float, float], ...] = ()


@dataclass(frozen=True)
class Task:
    """What the exercise asks of the mechanism — not its physics: how many positions, where the
    acceleration plans and the force analysis are, the diagrams' settings and the title block."""
    count: int = 12                                   # positions 0 … N−1
    accel: tuple[str | int | float, ...] = ()          # acceleration plans: indices, "#3", angles
    force_phi: float | None = None                    # the force analysis, deg of turn from position 0
    diagram: dict[str, object] = field(default_factory=dict)  # [diagrams]: L_mm, H1_mm, H2_mm, divisions, point
    meta: dict[str, str] = field(default_factory=dict)        # title_en, designation, sheet.* fields
    flywheel: dict[str, float] = field(default_factory=dict)  # [dynamics]: delta, L_mm, H_mm, divisions


@dataclass(frozen=True)
class Drive:
    """What turns the crank (scene's [dynamics], seed 003): a motor (given, or chosen from the
    catalogue's ``rpm_sync`` line), a reducer of ratio i = ω_motor/ω_crank (None: rated motor speed
    over the crank's) and efficiency η, the reducer's moment of inertia reduced to the crank and/or
    its three shafts with the first stage's ratio (seed 003 eq. 4), and a rotor inertia overriding
    the motor's. ``warnings``: what the scene's motor data said wrong."""
    motor: Motor | None = None
    rpm_sync: float = 3000.0
    ratio: float | None = None
    efficiency: float = 1.0
    reducer_inertia: float = 0.0
    rotor_inertia: float | None = None
    warnings: tuple[tuple[str, str], ...] = ()     # (English, Ukrainian)
    shafts: tuple[float, float, float] = (0.0, 0.0, 0.0)   # reducer's input, intermediate, output shafts, kg·m²
    first_stage: float | None = None               # i1: motor shaft / intermediate shaft


@dataclass
class Mechanism:
    """A planar lever mechanism as its kinematic scheme shows it."""
    title: str
    frame: dict[str, complex]
    guides: dict[str, Guide]
    links: dict[str, Link]          # the crank first, then the scene's order
    crank: Crank
    branches: dict[str, int] = field(default_factory=dict)
    output: str | None = None
    start: str | float = "max"
    working_stroke: str = "slow"    # which stroke of the output is the working one: slow, fast, to_max, to_min
    forces: tuple[Force, ...] = ()
    moments: tuple[Moment, ...] = ()
    g: float = 9.81
    params: dict[str, float] = field(default_factory=dict)
    derived: dict[str, float] = field(default_factory=dict)
    task: Task = field(default_factory=lambda: Task())
    drive: Drive = field(default_factory=lambda: Drive())
    source: str = "<scene>"

    @property
    def omega1(self) -> float:
        return self.crank.omega

    @property
    def period(self) -> float:
        """T = 2π/|ω1| (s)."""
        return 2 * math.pi / abs(self.crank.omega)

    def bodies_of(self, point: str) -> list[str]:
        """Names of the bodies (the frame "0" included) that carry a point."""
        found = [FRAME] if point in self.frame else []
        found += [name for name, link in self.links.items() if point in link.local]
        return found

    def point_names(self) -> list[str]:
        """Every named point: frame points, joints and extra points, first seen first."""
        names = list(self.frame)
        for link in self.links.values():
            names += [p for p in link.local if p not in names]
        return names
