"""1. The position plan: each position of each Assur group found with the compass and ruler in
drawing millimetres — two arcs (circle ∩ circle) for RRR, an arc and the guide for RRP, the rocker's
line through the block for RPR, two lines for PRP and RPP."""
from __future__ import annotations

import cmath
import math
from dataclasses import dataclass, field


from graphplan.util.markup import indexed
from graphplan.model.mechanism import FRAME, Mechanism
from graphplan.exact.positions import Study
from graphplan.model.structure import Dyad
from graphplan.graphic.draftsman import circle_circle, circle_line, crossing_angle, line_line, line_through_pivot


# -- where bodies lie and how their points move on a plan ----------------------------------------

@dataclass(frozen=True)
class Pose:
    """A body on the position plan: its local point ``local`` (m) drawn at ``ref`` (mm), turned θ."""
    ref: complex
    local: complex
    theta: float
    k: float            # drawing mm per metre = 1/μl

    def at(self, p: complex) -> complex:
        return self.ref + (p - self.local) * cmath.exp(1j * self.theta) * self.k

    def direction(self, angle: float) -> complex:
        return cmath.exp(1j * (self.theta + angle))


@dataclass(frozen=True)
class Image:
    """A body's image on a velocity or acceleration plan (the similarity theorem): the point drawn
    at X on the position plan has its plan point at p0 + F·(X − X0). F = iω·μl/μv on a velocity
    plan, (iε − ω²)·μl/μa on an acceleration plan — found from two constructed plan points."""
    X0: complex
    p0: complex
    F: complex

    def at(self, X: complex) -> complex:
        return self.p0 + self.F * (X - self.X0)

    @staticmethod
    def through(X0: complex, p0: complex, X1: complex, p1: complex) -> Image:
        """The similar figure through two plan points: F = (p1 − p0)/(X1 − X0)."""
        return Image(X0, p0, (p1 - p0) / (X1 - X0))


@dataclass(frozen=True)
class Arc:
    """A compass arc (засічка): about ``centre`` with ``radius`` (mm), crossing at ``at``."""
    centre: complex
    radius: float
    at: complex
    group: str


@dataclass(frozen=True)
class Line:
    """A guide (``kind`` "guide") or the rocker's line ("rocker") drawn through ``through`` along
    ``direction``, meeting the point found at ``at``; ``offset`` of the rocker's slot (mm)."""
    kind: str
    through: complex
    direction: complex
    at: complex
    group: str
    offset: float = 0.0


@dataclass(frozen=True)
class Crossing:
    """The angle at which a construction's two arcs or lines meet (small = ill-conditioned)."""
    group: str
    what: str
    angle: float   # degrees
    kind: str      # "arcs" or "lines"


@dataclass
class Layout:
    """One position of the mechanism on the position plan."""
    key: int
    index: int | None
    phi: float
    poses: dict[str, Pose]
    angles: list[Crossing] = field(default_factory=list)    # how well each construction is conditioned
    drawn: list[Arc | Line] = field(default_factory=list)    # the construction's marks


# -- the mechanism as the draftsman sees it ------------------------------------------------------

def sub(name: str) -> str:
    """Plan notation: the mechanism point's lowercase letter, its number as a subscript (util.markup:
    S2 → s_2, A3 → a_3, B → b)."""
    return indexed(name.lower())


class Scheme:
    """Read-only facts about the mechanism the constructions use: numbers, local points, guides."""

    def __init__(self, st: Study):
        self.st = st
        self.mech: Mechanism = st.mech
        self.rotating = self._rotating()
        self.coincident: dict[tuple[str, str], str] = {}

    def number(self, body: str) -> int:
        return 0 if body == FRAME else self.mech.links[body].number

    def local(self, body: str, point: str) -> complex:
        return self.mech.frame[point] if body == FRAME else self.mech.links[body].local[point]

    def body_of(self, point: str) -> str:
        holders = self.mech.bodies_of(point)
        return FRAME if FRAME in holders else holders[0]

    def fixed(self, point: str) -> bool:
        return point in self.mech.frame

    def name_at(self, point: str, body: str) -> str:
        """The name of ``body``'s point that is at ``point`` now (A3: the rocker's point at A)."""
        key = (point, body)
        if key not in self.coincident:
            name = f"{point}{self.number(body)}"
            if name in self.mech.point_names():
                name = f"{point}_{self.number(body)}"
            self.coincident[key] = name
        return self.coincident[key]

    def _rotating(self) -> dict[str, bool]:
        """Which bodies can turn: pinned links do; a slider turns with the body carrying its guide."""
        rot = {FRAME: False, self.mech.crank.link: True}
        for d in self.st.structure.dyads:
            if d.kind == "RRR":
                rot[d.a] = rot[d.b] = True
            elif d.kind == "RRP":
                rot[d.a] = True
                rot[d.b] = rot[self.mech.guides[d.outer_b.guide].body]
            elif d.kind == "RPR":
                rot[d.a] = rot[d.b] = True
            elif d.kind == "PRP":
                rot[d.a] = rot[self.mech.guides[d.outer_a.guide].body]
                rot[d.b] = rot[self.mech.guides[d.outer_b.guide].body]
            else:  # RPP
                rot[d.a] = rot[d.b] = rot[self.mech.guides[d.outer_b.guide].body]
        return rot


# -- 1. the position plan -----------------------------------------------------------------------

def construct_position(sc: Scheme, phi: float, mu_l: float, key: int = 0,
                       index: int | None = None) -> Layout:
    """One position: the crank at φ, then each group with its compass-and-ruler construction."""
    mech = sc.mech
    k = 1.0 / mu_l
    pivot = mech.frame[mech.crank.pivot]
    poses = {FRAME: Pose(-pivot * k, 0j, 0.0, k)}
    crank = mech.links[mech.crank.link]
    poses[crank.name] = Pose(0j, crank.local[mech.crank.pivot], math.radians(phi), k)
    lay = Layout(key, index, phi, poses)
    for d in sc.st.structure.dyads:
        POSITION_STEPS[d.kind](sc, lay, d, mech.branches.get(d.key, 1))
    return lay


def where(sc: Scheme, lay: Layout, body: str, point: str) -> complex:
    return lay.poses[body].at(sc.local(body, point))


def guide_line(sc: Scheme, lay: Layout, guide_name: str, slider: str, point: str) -> tuple[complex, complex]:
    """The line the slider's ``point`` runs along, drawn: a point on it and its direction."""
    g = sc.mech.guides[guide_name]
    pose = lay.poses[g.body]
    through = g.through + sc.local(slider, point) * cmath.exp(1j * g.angle)
    return pose.at(through), pose.direction(g.angle)


def pose_from_two(sc: Scheme, body: str, p: str, X: complex, q: str, Y: complex, k: float) -> Pose:
    """A link drawn through two of its constructed points."""
    lp, lq = sc.local(body, p), sc.local(body, q)
    return Pose(X, lp, cmath.phase(Y - X) - cmath.phase(lq - lp), k)


def position_rrr(sc: Scheme, lay: Layout, d: Dyad, branch: int) -> None:
    """Arcs of radii l_a about P1 and l_b about P3 cross at C (засічки)."""
    p1, p3, c = d.outer_a.point, d.outer_b.point, d.inner.point
    k = lay.poses[FRAME].k
    X1 = where(sc, lay, d.outer_a.other(d.a), p1)
    X3 = where(sc, lay, d.outer_b.other(d.b), p3)
    la = abs(sc.local(d.a, c) - sc.local(d.a, p1)) * k
    lb = abs(sc.local(d.b, c) - sc.local(d.b, p3)) * k
    C = circle_circle(X1, la, X3, lb, branch)
    lay.poses[d.a] = pose_from_two(sc, d.a, p1, X1, c, C, k)
    lay.poses[d.b] = pose_from_two(sc, d.b, p3, X3, c, C, k)
    lay.angles.append(Crossing(d.label, f"the arcs about {p1} and {p3} meeting at {c}", crossing_angle(C - X1, C - X3),
                       "arcs"))
    lay.drawn += [Arc(X1, la, C, d.label), Arc(X3, lb, C, d.label)]


def position_rrp(sc: Scheme, lay: Layout, d: Dyad, branch: int) -> None:
    """An arc of radius l_a about P1 crosses the guide line at C."""
    p1, c = d.outer_a.point, d.inner.point
    k = lay.poses[FRAME].k
    X1 = where(sc, lay, d.outer_a.other(d.a), p1)
    G, g = guide_line(sc, lay, d.outer_b.guide, d.b, c)
    la = abs(sc.local(d.a, c) - sc.local(d.a, p1)) * k
    C = circle_line(X1, la, G, g, branch)
    lay.poses[d.a] = pose_from_two(sc, d.a, p1, X1, c, C, k)
    guide = sc.mech.guides[d.outer_b.guide]
    lay.poses[d.b] = Pose(C, sc.local(d.b, c), lay.poses[guide.body].theta + guide.angle, k)
    # the arc crosses the line at 90° − (angle between the radius and the line)
    lay.angles.append(Crossing(d.label, f"the arc about {p1} meeting the guide at {c}",
                       90.0 - crossing_angle(C - X1, g), "arcs"))
    lay.drawn += [Arc(X1, la, C, d.label), Line("guide", G, g, C, d.label)]


def position_rpr(sc: Scheme, lay: Layout, d: Dyad, branch: int) -> None:
    """The rocker's line drawn through its pivot Pc and the block's point Ps (or tangent to the
    circle of the slot's offset about Pc)."""
    slider, carrier, outer_s, outer_c = d.block_parts
    ps, pc = outer_s.point, outer_c.point
    k = lay.poses[FRAME].k
    Xs = where(sc, lay, outer_s.other(slider), ps)
    Xc = where(sc, lay, outer_c.other(carrier), pc)
    guide = sc.mech.guides[d.inner.guide]
    through = guide.through + sc.local(slider, ps) * cmath.exp(1j * guide.angle)
    offset = ((through - sc.local(carrier, pc)) * cmath.exp(-1j * guide.angle)).imag * k
    th_line = line_through_pivot(Xs, Xc, offset, branch)
    lay.poses[carrier] = Pose(Xc, sc.local(carrier, pc), th_line - guide.angle, k)
    lay.poses[slider] = Pose(Xs, sc.local(slider, ps), th_line, k)
    lay.drawn += [Line("rocker", Xc, cmath.exp(1j * th_line), Xs, d.label, offset)]


def position_prp(sc: Scheme, lay: Layout, d: Dyad, branch: int) -> None:
    """Two guide lines cross at C."""
    c = d.inner.point
    k = lay.poses[FRAME].k
    G1, g1 = guide_line(sc, lay, d.outer_a.guide, d.a, c)
    G2, g2 = guide_line(sc, lay, d.outer_b.guide, d.b, c)
    C = line_line(G1, g1, G2, g2)
    for link, pair in ((d.a, d.outer_a), (d.b, d.outer_b)):
        guide = sc.mech.guides[pair.guide]
        lay.poses[link] = Pose(C, sc.local(link, c), lay.poses[guide.body].theta + guide.angle, k)
    lay.angles.append(Crossing(d.label, f"the guides crossing at {c}", crossing_angle(g1, g2), "lines"))
    lay.drawn += [Line("guide", G1, g1, C, d.label), Line("guide", G2, g2, C, d.label)]


def position_rpp(sc: Scheme, lay: Layout, d: Dyad, branch: int) -> None:
    """The yoke's slot through the block's point A crosses the yoke's guide at the yoke's point."""
    pa = d.outer_a.point
    k = lay.poses[FRAME].k
    XA = where(sc, lay, d.outer_a.other(d.a), pa)
    ref = next(iter(sc.mech.links[d.b].local))
    G, g = guide_line(sc, lay, d.outer_b.guide, d.b, ref)
    guide = sc.mech.guides[d.outer_b.guide]
    th_b = lay.poses[guide.body].theta + guide.angle
    slot = sc.mech.guides[d.inner.guide]
    q = (slot.through + sc.local(d.a, pa) * cmath.exp(1j * slot.angle)) * k * cmath.exp(1j * th_b)
    dd = cmath.exp(1j * (th_b + slot.angle))
    Y = line_line(G, g, XA - q, dd)
    lay.poses[d.b] = Pose(Y, sc.local(d.b, ref), th_b, k)
    lay.poses[d.a] = Pose(XA, sc.local(d.a, pa), th_b + slot.angle, k)
    lay.angles.append(Crossing(d.label, f"the slot through {pa} crossing the yoke's guide", crossing_angle(g, dd),
                       "lines"))
    lay.drawn += [Line("guide", G, g, Y, d.label), Line("guide", XA - q, dd, XA, d.label)]


POSITION_STEPS = {"RRR": position_rrr, "RRP": position_rrp, "RPR": position_rpr,
                  "PRP": position_prp, "RPP": position_rpp}
