"""The graphical plans, constructed as a draftsman draws them and measured like a student.

* **Position plan** — the crank circle divided into N parts from position 0; each position of each
  Assur group found with the compass and ruler in drawing millimetres: two arcs ("засічки",
  circle ∩ circle) for RRR, an arc and the guide (circle ∩ line) for RRP, the rocker's line through
  the block (a line through a pivot) for RPR, two lines (line ∩ line) for PRP and RPP.
* **Velocity plan** — from the pole p_v: v_A = ω1·l_OA ⊥ OA laid off as p_v a; every group's two
  vector equations are solved by drawing their known direction lines (∥ a guide, ⊥ a link) through
  the known plan points and intersecting them, e.g. v_B = v_A + v_BA (⊥ AB) with v_B ∥ the guide;
  the slotted link: v_A3 = v_A2 + v_A3A2 (∥ the rocker) with v_A3 ⊥ O A. Further points of a link by
  the similarity theorem (the link's figure on the plan is similar to the link, turned 90°).
* **Acceleration plan** — from the pole π: a_A, then for each group normal components
  a^n = v²/l laid off ∥ the link toward its centre (n ends), Coriolis a^k = 2·ω·v_rel laid off along
  v_rel turned 90° in the sense of ω (k ends), and the lines of the unknown tangential/relative
  components intersected.

Every length read off a plan is rounded to the drafting precision (a ruler: 0.5 mm; 0 = exact) and
multiplied by the scale; lengths computed from measured values (normal and Coriolis components) are
laid off with the same ruler. The analytic solver is used only for the comparison (and to choose the
scales' sizes); nothing of its velocities or accelerations enters a plan.
"""
from __future__ import annotations

import cmath
import math
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np

from graphplan.graphic.record import LabelRequest, Record
from graphplan.util.errors import GraphplanError
from graphplan.exact.kinematics import Kinematics
from graphplan.model.mechanism import FRAME, Mechanism
from graphplan.exact.positions import Study
from graphplan.graphic.scales import Targets, standard_scale
from graphplan.model.structure import Dyad

NEAR_ZERO = 1e-3        # exact vectors below this share of the plan's largest (or below one ruler
                        # division) get no percent error
VANISH = 1e-3           # a constructed velocity this short (share of the plan's largest) = a dead centre
SMALL_ANGLE_DEG = 15.0  # direction lines / arcs crossing at less than this are ill-conditioned


# -- measuring with a ruler ---------------------------------------------------------------------

def measure(length_mm: float, precision: float) -> float:
    """A length read with a ruler: rounded to the nearest multiple of ``precision`` (0 = exact)."""
    if precision <= 0:
        return float(length_mm)
    return math.floor(length_mm / precision + 0.5) * precision


lay_off = measure   # laying a computed length off with the same ruler rounds it the same way


def unit(z: complex) -> complex:
    n = abs(z)
    return z / n if n > 0 else 0j


def cross(u: complex, w: complex) -> float:
    """z-component of u × w."""
    return (u.conjugate() * w).imag


def dot(u: complex, w: complex) -> float:
    return (u.conjugate() * w).real


def crossing_angle(d1: complex, d2: complex) -> float:
    """The acute angle (deg) between two lines of directions d1, d2."""
    s = abs(cross(unit(d1), unit(d2)))
    c = abs(dot(unit(d1), unit(d2)))
    return math.degrees(math.atan2(s, c))


# -- the compass-and-ruler constructions (drawing mm, complex numbers) ---------------------------

def line_line(p1: complex, d1: complex, p2: complex, d2: complex) -> complex:
    """The intersection of the line through p1 along d1 with the line through p2 along d2."""
    det = cross(d1, d2)
    if det == 0:
        raise GraphplanError("two direction lines are parallel: the construction has no intersection")
    t = cross(p2 - p1, d2) / det
    return p1 + t * d1


def circle_circle(c1: complex, r1: float, c2: complex, r2: float, branch: int) -> complex:
    """Two compass arcs (засічки): the intersection of circles (c1, r1), (c2, r2) to the left of
    c1→c2 for branch +1, to the right for −1."""
    span = c2 - c1
    dist = abs(span)
    along = (dist ** 2 + r1 ** 2 - r2 ** 2) / (2 * dist)
    h = math.sqrt(max(r1 ** 2 - along ** 2, 0.0))
    return c1 + (along + 1j * branch * h) * span / dist


def circle_line(c: complex, r: float, p: complex, d: complex, branch: int) -> complex:
    """An arc of radius r about c crossing the line through p along d (unit): the crossing ahead
    of the foot of the perpendicular from c (along d) for branch +1, behind it for −1."""
    foot = -dot(d, p - c)
    disc = foot ** 2 - abs(p - c) ** 2 + r ** 2
    return p + (foot + branch * math.sqrt(max(disc, 0.0))) * d


def line_through_pivot(ps: complex, pc: complex, offset: float, branch: int) -> float:
    """The direction angle (rad) of the rocker's line through the block's point ``ps`` that passes
    at the distance ``offset`` (signed, left of the line) from the pivot ``pc`` — for a slot through
    the pivot, simply the line pc→ps (branch +1) or ps→pc (−1)."""
    rho = ps - pc
    beta = math.asin(max(-1.0, min(1.0, offset / abs(rho))))
    if branch < 0:
        beta = math.pi - beta
    return cmath.phase(rho) - beta


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


@dataclass
class Layout:
    """One position of the mechanism on the position plan."""
    key: int
    index: int | None
    phi: float
    poses: dict[str, Pose]
    angles: list[tuple[str, str, float, str]] = field(default_factory=list)  # (group, what, deg, kind)
    drawn: list[tuple] = field(default_factory=list)                    # construction marks


@dataclass
class Entry:
    """One measured quantity: the plan's magnitude (``mm`` × scale, or ω, ε from them) beside
    the exact one. ``vector``/``exact`` keep the directions (plan vector × scale in SI; for ω, ε the
    signed values) so the sense can be checked too; ``basis`` is the analytic size of the vector the
    entry derives from (for the near-zero rule)."""
    key: str
    kind: str
    mm: float | None
    value: float
    analytic: float
    vector: complex
    exact: complex
    basis: float
    sense: str | None = None
    error_pct: float | None = None


@dataclass
class PlanWarning:
    """An ill-conditioned construction, with the angle that makes it so (for a dead centre: how
    far the crank is from the extreme position)."""
    plan: str        # "position", "velocity", "acceleration"
    group: str
    kind: str        # "lines", "arcs", "dead centre"
    angle: float
    text: str


@dataclass
class Equation:
    """One vector equation drawn on a plan: from the known plan point ``base`` the known components
    ``chain`` (vector mm, role, end label, entry key) are laid off; the unknown component lies on
    the line through the chain's end along ``direction``."""
    base: complex
    direction: complex
    unknown_role: str
    chain: list[tuple[complex, str, str, str]] = field(default_factory=list)

    @property
    def end(self) -> complex:
        return self.base + sum((v for v, *_ in self.chain), 0j)


# -- the mechanism as the draftsman sees it ------------------------------------------------------

def sub(name: str) -> str:
    """Plan notation: the mechanism point's lowercase letter (S2 → s2, A3 → a3). Plain ASCII: the
    drawing font (osifont) has no subscript digits."""
    return name.lower()


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
    lay.angles.append((d.label, f"the arcs about {p1} and {p3} meeting at {c}", crossing_angle(C - X1, C - X3),
                       "arcs"))
    lay.drawn += [("arc", X1, la, C, d.label), ("arc", X3, lb, C, d.label)]


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
    lay.angles.append((d.label, f"the arc about {p1} meeting the guide at {c}",
                       90.0 - crossing_angle(C - X1, g), "arcs"))
    lay.drawn += [("arc", X1, la, C, d.label), ("guide", G, g, C, d.label)]


def position_rpr(sc: Scheme, lay: Layout, d: Dyad, branch: int) -> None:
    """The rocker's line drawn through its pivot Pc and the block's point Ps (or tangent to the
    circle of the slot's offset about Pc)."""
    slider = d.inner.slider
    carrier = d.b if slider == d.a else d.a
    outer_s = d.outer_a if slider == d.a else d.outer_b
    outer_c = d.outer_b if slider == d.a else d.outer_a
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
    lay.drawn += [("rocker", Xc, cmath.exp(1j * th_line), Xs, d.label, offset)]


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
    lay.angles.append((d.label, f"the guides crossing at {c}", crossing_angle(g1, g2), "lines"))
    lay.drawn += [("guide", G1, g1, C, d.label), ("guide", G2, g2, C, d.label)]


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
    lay.angles.append((d.label, f"the slot through {pa} crossing the yoke's guide", crossing_angle(g, dd),
                       "lines"))
    lay.drawn += [("guide", G, g, Y, d.label), ("guide", XA - q, dd, XA, d.label)]


POSITION_STEPS = {"RRR": position_rrr, "RRP": position_rrp, "RPR": position_rpr,
                  "PRP": position_prp, "RPP": position_rpp}


# -- 2, 3. velocity and acceleration plans --------------------------------------------------------

class Exact:
    """The analytic solution at one crank angle — used only for the comparison."""

    def __init__(self, kin: Kinematics, k: int):
        self.kin, self.k = kin, k

    def point(self, name: str) -> tuple[complex, complex, complex]:
        x, v, a = self.kin.point(name)
        return complex(x[self.k]), complex(v[self.k]), complex(a[self.k])

    def at(self, body: str, point: str) -> tuple[complex, complex]:
        """Velocity and acceleration of ``body``'s point that is at ``point``'s place now."""
        if body == FRAME:
            return 0j, 0j
        b, k = self.kin.bodies[body], self.k
        r = self.point(point)[0] - complex(b.origin[k])
        w, e = float(b.omega[k]), float(b.eps[k])
        return complex(b.vo[k]) + 1j * w * r, complex(b.ao[k]) + (1j * e - w * w) * r

    def omega(self, body: str) -> float:
        return 0.0 if body == FRAME else float(self.kin.bodies[body].omega[self.k])

    def eps(self, body: str) -> float:
        return 0.0 if body == FRAME else float(self.kin.bodies[body].eps[self.k])


class Plan:
    """A velocity or acceleration plan being drawn: plan points, body images, the record, entries.

    ``rates`` holds the measured ω (velocity plan) or ε (acceleration plan) of each body, signed
    (+ counter-clockwise); ``basis`` the analytic size of the relative vector each was read from."""

    kind = ""
    pole = ""
    rate_kind = ""
    index = 1          # 1: velocities, 2: accelerations in Kinematics.point(); 0/1 in Exact.at()

    def __init__(self, sc: Scheme, lay: Layout, exact: Exact, mu: float, precision: float):
        self.sc, self.lay, self.exact = sc, lay, exact
        self.mu, self.precision = mu, precision
        self.images: dict[str, Image] = {FRAME: Image(0j, 0j, 0j)}
        self.rates: dict[str, float] = {FRAME: 0.0}
        self.basis: dict[str, float] = {FRAME: 0.0}
        self.entries: dict[str, Entry] = {}
        self.record = Record()
        self.labels: list[LabelRequest] = []
        self.named: dict[str, complex] = {}
        self.warnings: list[PlanWarning] = []
        self.found: list[tuple[str, str, complex]] = []   # (group, point, constructed plan point)
        self.ends = {"n": 0, "k": 0}
        self.segments: list[tuple[complex, complex]] = []

    # the ruler -------------------------------------------------------------------------------------
    def read(self, vec_mm: complex) -> tuple[float, float]:
        """(mm, value): a plan segment read with the ruler and multiplied by the scale."""
        mm = measure(abs(vec_mm), self.precision)
        return mm, mm * self.mu

    def laid(self, value: float, direction: complex) -> complex:
        """A computed magnitude laid off with the ruler along ``direction`` (a plan vector, mm)."""
        return lay_off(abs(value) / self.mu, self.precision) * unit(direction)

    # what is measured --------------------------------------------------------------------------------
    def entry(self, key: str, kind: str, vec_mm: complex, exact: complex, laid: bool = False) -> None:
        """A segment of the plan: read off (or, for a laid-off component, its laid length)."""
        mm, value = (abs(vec_mm), abs(vec_mm) * self.mu) if laid else self.read(vec_mm)
        self.entries[key] = Entry(key, kind, mm, value, abs(exact), vec_mm * self.mu, exact, abs(exact))

    def rate(self, link: str, value: float, exact: float, basis: float) -> None:
        """ω (or ε) of a link: its measured signed value beside the exact one."""
        self.rates[link], self.basis[link] = value, basis
        if self.sc.rotating.get(link) and link != self.sc.mech.crank.link:
            sense = None if value == 0 else ("ccw" if value > 0 else "cw")
            key = f"{self.rate_kind}_{link}"
            self.entries[key] = Entry(key, self.rate_kind, None, abs(value), abs(exact), value, exact,
                                      basis, sense)

    def inherit(self, link: str, carrier: str) -> None:
        """A slider turns with the body that carries its guide: the same ω and ε."""
        exact = self.exact.omega(link) if self.kind == "velocity" else self.exact.eps(link)
        self.rate(link, self.rates[carrier], exact, self.basis[carrier])

    def turn_rate(self, link: str, X: complex, C: complex, rel_mm: complex, length: float,
                  exact_rel: complex) -> None:
        """ω = v_CX / l (or ε = a^τ_CX / l) with its sense, the sign of (C − X) × the plan segment."""
        _, value = self.read(rel_mm)
        signed = math.copysign(value / length, cross(C - X, rel_mm)) if value else 0.0
        exact = self.exact.omega(link) if self.kind == "velocity" else self.exact.eps(link)
        self.rate(link, signed, exact, abs(exact_rel))

    # drawing -----------------------------------------------------------------------------------------
    def vector(self, a: complex, b: complex, role: str, step: str) -> None:
        if abs(b - a) > 0.3:
            self.record.vector((a.real, a.imag), (b.real, b.imag), role=role, layer="vectors", step=step)
            self.segments.append((a, b))

    def drawn(self, a: complex, b: complex) -> bool:
        """Is the segment ab (either way) already drawn as a vector?"""
        return any(min(abs(a - p) + abs(b - q), abs(a - q) + abs(b - p)) < 1e-6 for p, q in self.segments)

    def link_figures(self) -> None:
        """The similar figure of every link on the plan: its joints' plan points joined thin
        (the line ab on which s2 lies, the triangle of a three-joint link)."""
        sc = self.sc
        for name, link in sc.mech.links.items():
            if name == sc.mech.crank.link or name not in self.images:
                continue
            pts = [self.plan_point(name, j) for j in link.joints]
            pairs = list(zip(pts, pts[1:])) + ([(pts[-1], pts[0])] if len(pts) > 2 else [])
            for a, b in pairs:
                if abs(b - a) > 0.3 and not self.drawn(a, b):
                    self.record.segment((a.real, a.imag), (b.real, b.imag), role="construction",
                                        layer="construction", step=f"similarity: link {name}")

    def name_point(self, label: str, at: complex) -> None:
        self.named.setdefault(label, at)

    def end_label(self, letter: str) -> str:
        self.ends[letter] += 1
        return sub(f"{letter}{self.ends[letter]}")

    def direction_line(self, through: complex, found: complex, direction: complex, step: str) -> None:
        """A thin line along ``direction`` through the known end, reaching past the intersection."""
        u = unit(direction)
        t = dot(u, found - through)
        lo, hi = min(0.0, t) - 6.0, max(0.0, t) + 6.0
        a, b = through + lo * u, through + hi * u
        self.record.segment((a.real, a.imag), (b.real, b.imag), role="direction", layer="construction",
                            step=step)

    def solve(self, group: str, what: str, e1: Equation, e2: Equation, step: str) -> complex:
        """Lay off both equations' known components, draw their direction lines; the unknown plan
        point is where the lines cross. A warning when they cross at a small angle."""
        angle = crossing_angle(e1.direction, e2.direction)
        if angle < 1e-9:
            raise GraphplanError(f"{self.kind} plan at φ = {self.lay.phi:.4g}°, {group}: the direction "
                                 f"lines of {step} are parallel (a toggle position); the plan has no "
                                 "intersection there", self.sc.mech.source)
        x = line_line(e1.end, e1.direction, e2.end, e2.direction)
        for eq in (e1, e2):
            at = eq.base
            for vec, role, label, _key in eq.chain:
                self.vector(at, at + vec, role, step)
                if label and abs(vec) > 0.3:
                    self.name_point(label, at + vec)
                at = at + vec
            self.direction_line(eq.end, x, eq.direction, step)
            self.vector(eq.end, x, eq.unknown_role, step)
        if angle < SMALL_ANGLE_DEG:
            slip = 0.5 / math.sin(math.radians(max(angle, 1e-9)))
            self.warnings.append(PlanWarning(
                self.kind, group, "lines", angle,
                f"{self.kind} plan, {group} ({step}): the direction lines cross at {angle:.1f}° "
                f"(< {SMALL_ANGLE_DEG:g}°); a 0.5 mm slip moves {what} by {slip:.1f} mm"))
        return x

    # images -------------------------------------------------------------------------------------------
    def plan_point(self, body: str, point: str) -> complex:
        return self.images[body].at(where(self.sc, self.lay, body, point))

    def finish(self) -> None:
        """Every point by similarity; absolute vectors from the pole; labels; percent errors."""
        sc, lay = self.sc, self.lay
        for name in sc.mech.point_names():
            if sc.fixed(name):
                continue
            p = self.plan_point(sc.body_of(name), name)
            self.entry(name, "point", p, self.exact.point(name)[self.index])
            self.name_point(sub(name), p)
        for (point, body), name in sc.coincident.items():
            if body in self.images:
                X = where(sc, lay, sc.body_of(point), point)
                p = self.images[body].at(X)
                if name not in self.entries:
                    self.entry(name, "point", p, self.exact.at(body, point)[self.index - 1])
                self.name_point(sub(name), p)
        drawn: list[complex] = []
        for e in self.entries.values():
            p = e.vector / self.mu
            if e.kind == "point" and all(abs(p - q) > 1e-6 for q in drawn):
                self.vector(0j, p, "absolute", "similarity" if e.key in sc.mech.point_names() else "")
                drawn.append(p)
        self.link_figures()
        self.record.point((0.0, 0.0), role="pole", layer="vectors")
        self.group_labels()
        self.percent_errors()

    def group_labels(self) -> None:
        """One label per place: plan points closer than 1.5 mm share it ("pv, b")."""
        groups: list[tuple[complex, list[str]]] = [(0j, [self.pole])]
        for label, p in self.named.items():
            for at, names in groups:
                if abs(at - p) < 1.5:
                    if label not in names:
                        names.append(label)
                    break
            else:
                groups.append((p, [label]))
        centre = sum((p for p, _ in groups), 0j) / len(groups)
        for at, names in groups:
            toward = at - centre if abs(at - centre) > 1e-9 else -1j
            self.labels.append(LabelRequest(at, ", ".join(names), toward=toward, size=3.5))

    def percent_errors(self) -> None:
        """error % = 100·(value − analytic)/analytic, left out (None) where the exact vector the
        entry derives from is shorter than NEAR_ZERO of the plan's largest vector or than one
        division of the ruler (``precision`` mm on the plan): no percent means anything there."""
        largest = max((e.basis for e in self.entries.values()), default=0.0)
        floor = max(NEAR_ZERO * largest, self.precision * self.mu)
        for e in self.entries.values():
            if e.basis > floor and e.analytic > 0:
                e.error_pct = 100.0 * (e.value - e.analytic) / e.analytic


class VelocityPlan(Plan):
    kind = "velocity"
    pole = "pv"
    rate_kind = "omega"
    index = 1

    def __init__(self, sc: Scheme, lay: Layout, exact: Exact, mu: float, precision: float):
        super().__init__(sc, lay, exact, mu, precision)
        self.rocker_length: dict[str, float] = {}   # l_PcA measured off the position plan, m

    def crank(self) -> None:
        """v_A = ω1·l_OA ⊥ OA in the sense of ω1: the segment p_v a."""
        sc, cr = self.sc, self.sc.mech.crank
        O, A = where(sc, self.lay, FRAME, cr.pivot), where(sc, self.lay, cr.link, cr.pin)
        a = self.laid(cr.omega * cr.length, 1j * math.copysign(1.0, cr.omega) * (A - O))
        self.images[cr.link] = Image.through(O, 0j, A, a)
        self.rates[cr.link], self.basis[cr.link] = cr.omega, abs(cr.omega) * cr.length

    def group(self, d: Dyad) -> None:
        VELOCITY_STEPS[d.kind](self, d)

    def dead_centres(self) -> None:
        """A constructed plan point at the pole while the crank turns: the group is at a dead
        centre — its velocities vanish and their percent errors are left out."""
        largest = max((abs(e.vector) / self.mu for e in self.entries.values() if e.kind == "point"),
                      default=0.0)
        stopped = [(g, n) for g, n, p in self.found if abs(p) <= VANISH * largest]
        if not stopped:
            return
        st, phi = self.sc.st, self.lay.phi
        angle, near = 0.0, ""
        if st.extremes:
            gaps = [abs((phi - e + 180.0) % 360.0 - 180.0) for e in st.extremes]
            j = int(np.argmin(gaps))
            angle = gaps[j]
            near = f", {angle:.2f}° from the extreme position φ = {st.extremes[j]:.2f}°"
        order = [d.label for d in st.structure.dyads]
        groups = sorted({g for g, _ in stopped}, key=order.index)
        names = ", ".join(f"v_{n}" for _, n in stopped)
        verb = "vanishes" if len(stopped) == 1 else "vanish"
        self.warnings.append(PlanWarning(
            "velocity", " ".join(groups), "dead centre", angle,
            f"dead centre of {' and '.join(groups)} at φ = {phi:.2f}°{near}: {names} {verb}; "
            "their percent errors are left out"))

    def finish(self) -> None:
        super().finish()
        self.dead_centres()


class AccelerationPlan(Plan):
    kind = "acceleration"
    pole = "π"
    rate_kind = "epsilon"
    index = 2

    def __init__(self, sc: Scheme, lay: Layout, exact: Exact, mu: float, precision: float,
                 vel: VelocityPlan):
        super().__init__(sc, lay, exact, mu, precision)
        self.vel = vel

    def crank(self) -> None:
        """a_A = a^n_AO (ω1²·l_OA, ∥ AO toward O) + a^τ_AO (ε1·l_OA ⊥ OA)."""
        sc, cr = self.sc, self.sc.mech.crank
        O, A = where(sc, self.lay, FRAME, cr.pivot), where(sc, self.lay, cr.link, cr.pin)
        n = self.laid(cr.omega ** 2 * cr.length, O - A)
        t = self.laid(cr.epsilon * cr.length, 1j * math.copysign(1.0, cr.epsilon) * (A - O)) if cr.epsilon else 0j
        step = f"a_{cr.pin} = a^n_{cr.pin}{cr.pivot} + a^τ_{cr.pin}{cr.pivot}"
        if cr.epsilon:
            self.vector(0j, n, "normal", step)
            self.vector(n, n + t, "tangential", step)
            self.name_point(self.end_label("n"), n)
        self.images[cr.link] = Image.through(O, 0j, A, n + t)
        self.rates[cr.link], self.basis[cr.link] = cr.epsilon, abs(cr.epsilon) * cr.length

    def group(self, d: Dyad) -> None:
        ACCELERATION_STEPS[d.kind](self, d)

    def normal(self, rel_v_mm: complex, length: float, toward: complex) -> complex:
        """a^n = v²/l from the measured relative velocity, laid off toward the centre."""
        _, v = self.vel.read(rel_v_mm)
        return self.laid(v * v / length, toward)

    def coriolis(self, carrier: str, rel_v_mm: complex) -> complex:
        """a^k = 2·ω·v_rel, along v_rel turned 90° in the sense of ω (measured ω and v_rel)."""
        w = self.vel.rates[carrier]
        _, v = self.vel.read(rel_v_mm)
        if w == 0 or v == 0:
            return 0j
        return self.laid(2 * abs(w) * v, 1j * math.copysign(1.0, w) * rel_v_mm)


# -- the five groups on the velocity plan ---------------------------------------------------------

def velocity_rrr(plan: VelocityPlan, d: Dyad) -> None:
    """v_C = v_P1 + v_CP1 (⊥ P1C) = v_P3 + v_CP3 (⊥ P3C): two lines ⊥ the links cross at c."""
    sc, lay, ex = plan.sc, plan.lay, plan.exact
    p1, p3, c = d.outer_a.point, d.outer_b.point, d.inner.point
    K1, K3 = d.outer_a.other(d.a), d.outer_b.other(d.b)
    X1, X3, XC = where(sc, lay, K1, p1), where(sc, lay, K3, p3), where(sc, lay, d.a, c)
    v1, v3 = plan.plan_point(K1, p1), plan.plan_point(K3, p3)
    step = f"v_{c} = v_{p1} + v_{c}{p1} = v_{p3} + v_{c}{p3}"
    vc = plan.solve(d.label, sub(c), Equation(v1, 1j * (XC - X1), "relative"),
                    Equation(v3, 1j * (XC - X3), "relative"), step)
    plan.found.append((d.label, c, vc))
    plan.images[d.a] = Image.through(X1, v1, XC, vc)
    plan.images[d.b] = Image.through(X3, v3, XC, vc)
    for link, p, X, vp in ((d.a, p1, X1, v1), (d.b, p3, X3, v3)):
        rel = ex.point(c)[1] - ex.point(p)[1]
        if not sc.fixed(p):
            plan.entry(f"{c}{p}", "relative", vc - vp, rel)
        plan.turn_rate(link, X, XC, vc - vp, abs(sc.local(link, c) - sc.local(link, p)), rel)


def velocity_rrp(plan: VelocityPlan, d: Dyad) -> None:
    """v_C = v_P1 + v_CP1 (⊥ P1C) = v_C(K) + v_C(b)C(K) (∥ the guide)."""
    sc, lay, ex = plan.sc, plan.lay, plan.exact
    p1, c = d.outer_a.point, d.inner.point
    K1, K = d.outer_a.other(d.a), sc.mech.guides[d.outer_b.guide].body
    X1, XC = where(sc, lay, K1, p1), where(sc, lay, d.a, c)
    _, g = guide_line(sc, lay, d.outer_b.guide, d.b, c)
    v1, vk = plan.plan_point(K1, p1), plan.images[K].at(XC)
    rel_key = f"{c}{sc.number(d.b)}{c}{sc.number(K)}"
    if K == FRAME:
        step = f"v_{c} = v_{p1} + v_{c}{p1}, v_{c} ∥ the guide"
    else:
        step = f"v_{c} = v_{p1} + v_{c}{p1} = v_{sc.name_at(c, K)} + v_{rel_key}"
    vc = plan.solve(d.label, sub(c), Equation(v1, 1j * (XC - X1), "relative"),
                    Equation(vk, g, "relative"), step)
    plan.found.append((d.label, c, vc))
    plan.images[d.a] = Image.through(X1, v1, XC, vc)
    plan.images[d.b] = Image(XC, vc, plan.images[K].F)
    rel = ex.point(c)[1] - ex.point(p1)[1]
    if not sc.fixed(p1):
        plan.entry(f"{c}{p1}", "relative", vc - v1, rel)
    plan.turn_rate(d.a, X1, XC, vc - v1, abs(sc.local(d.a, c) - sc.local(d.a, p1)), rel)
    plan.inherit(d.b, K)
    if K != FRAME:
        plan.entry(rel_key, "relative", vc - vk, ex.point(c)[1] - ex.at(K, c)[0])


def rpr_parts(d: Dyad):
    """The slotted link's parts: (block, rocker, the block's outer pair, the rocker's outer pair)."""
    slider = d.inner.slider
    carrier = d.b if slider == d.a else d.a
    outer_s = d.outer_a if slider == d.a else d.outer_b
    outer_c = d.outer_b if slider == d.a else d.outer_a
    return slider, carrier, outer_s, outer_c


def velocity_rpr(plan: VelocityPlan, d: Dyad) -> None:
    """The slotted link: v_A3 = v_A2 + v_A3A2 (∥ the rocker) = v_Pc + v_A3Pc (⊥ Pc A)."""
    sc, lay, ex = plan.sc, plan.lay, plan.exact
    slider, carrier, outer_s, outer_c = rpr_parts(d)
    ps, pc = outer_s.point, outer_c.point
    Ks, Kc = outer_s.other(slider), outer_c.other(carrier)
    Xs, Xc = where(sc, lay, Ks, ps), where(sc, lay, Kc, pc)
    g = lay.poses[slider].direction(0.0)
    vs, vpc = plan.plan_point(Ks, ps), plan.plan_point(Kc, pc)
    a3, a2 = sc.name_at(ps, carrier), f"{ps}{sc.number(slider)}"
    step = f"v_{a3} = v_{a2} + v_{a3}{a2} = v_{pc} + v_{a3}{pc}"
    v3 = plan.solve(d.label, sub(a3), Equation(vs, g, "relative"),
                    Equation(vpc, 1j * (Xs - Xc), "relative"), step)
    plan.found.append((d.label, a3, v3))
    plan.images[carrier] = Image.through(Xc, vpc, Xs, v3)
    plan.images[slider] = Image(Xs, vs, plan.images[carrier].F)
    e3 = ex.at(carrier, ps)[0]
    plan.entry(a3, "point", v3, e3)
    plan.entry(f"{a3}{a2}", "relative", v3 - vs, e3 - ex.point(ps)[1])
    rel = e3 - ex.point(pc)[1]
    if not sc.fixed(pc):
        plan.entry(f"{a3}{pc}", "relative", v3 - vpc, rel)
    # ω = v_A3Pc / l_PcA with the distance Pc A measured off the position plan
    plan.rocker_length[carrier] = measure(abs(Xs - Xc), plan.precision) / lay.poses[FRAME].k
    plan.turn_rate(carrier, Xc, Xs, v3 - vpc, plan.rocker_length[carrier], rel)
    plan.inherit(slider, carrier)


def prp_guides(sc, lay, d: Dyad) -> list[tuple[str, str, str, complex]]:
    """The two guides crossing at a PRP group's joint C: (link, carrier K, pair key "C2C0", direction)."""
    c = d.inner.point
    out = []
    for link, pair in ((d.a, d.outer_a), (d.b, d.outer_b)):
        K = sc.mech.guides[pair.guide].body
        _, g = guide_line(sc, lay, pair.guide, link, c)
        out.append((link, K, f"{c}{sc.number(link)}{c}{sc.number(K)}", g))
    return out


def velocity_prp(plan: VelocityPlan, d: Dyad) -> None:
    """v_C = v_C(K1) + v_rel (∥ guide 1) = v_C(K2) + v_rel (∥ guide 2): two guide lines cross at c."""
    sc, lay, ex = plan.sc, plan.lay, plan.exact
    c = d.inner.point
    XC = where(sc, lay, d.a, c)
    sides = [(link, K, key, Equation(plan.images[K].at(XC), g, "relative"))
             for link, K, key, g in prp_guides(sc, lay, d)]
    terms = " = ".join((f"v_{sc.name_at(c, K)} + v_{key}" if K != FRAME else f"v_{key}")
                       for _, K, key, _ in sides)
    vc = plan.solve(d.label, sub(c), sides[0][3], sides[1][3], f"v_{c} = {terms}")
    plan.found.append((d.label, c, vc))
    for link, K, key, eq in sides:
        plan.images[link] = Image(XC, vc, plan.images[K].F)
        plan.inherit(link, K)
        if K != FRAME:
            plan.entry(key, "relative", vc - eq.base, ex.point(c)[1] - ex.at(K, c)[0])


def velocity_rpp(plan: VelocityPlan, d: Dyad) -> None:
    """The yoke b: v_A(b) = v_A(K) + v_A(b)A(K) (∥ its guide) = v_A + v_A(b)A (∥ the slot)."""
    sc, lay, ex = plan.sc, plan.lay, plan.exact
    pa, Ka = d.outer_a.point, d.outer_a.other(d.a)
    K = sc.mech.guides[d.outer_b.guide].body
    XA = where(sc, lay, Ka, pa)
    g, slot = lay.poses[d.b].direction(0.0), lay.poses[d.a].direction(0.0)
    va, vk = plan.plan_point(Ka, pa), plan.images[K].at(XA)
    ab = sc.name_at(pa, d.b)
    slot_key, guide_key = f"{ab}{pa}{sc.number(d.a)}", f"{ab}{pa}{sc.number(K)}"
    first = f"v_{sc.name_at(pa, K)} + v_{guide_key}" if K != FRAME else f"v_{guide_key}"
    step = f"v_{ab} = {first} = v_{pa} + v_{slot_key}"
    vb = plan.solve(d.label, sub(ab), Equation(vk, g, "relative"), Equation(va, slot, "relative"), step)
    plan.found.append((d.label, ab, vb))
    plan.images[d.b] = Image(XA, vb, plan.images[K].F)
    plan.images[d.a] = Image(XA, va, plan.images[K].F)
    plan.inherit(d.b, K)
    plan.inherit(d.a, K)
    eb = ex.at(d.b, pa)[0]
    plan.entry(ab, "point", vb, eb)
    plan.entry(slot_key, "relative", vb - va, eb - ex.point(pa)[1])
    if K != FRAME:
        plan.entry(guide_key, "relative", vb - vk, eb - ex.at(K, pa)[0])


VELOCITY_STEPS = {"RRR": velocity_rrr, "RRP": velocity_rrp, "RPR": velocity_rpr,
                  "PRP": velocity_prp, "RPP": velocity_rpp}


# -- the five groups on the acceleration plan -----------------------------------------------------

def normal_and_tangent(plan: AccelerationPlan, link: str, p: str, X: complex, ap: complex,
                       c: str, XC: complex, length: float, step_keys: list) -> Equation:
    """a_C = a_P + a^n_CP (v_CP²/l, ∥ CP toward P) + a^τ_CP (⊥ CP): the known part of one equation."""
    n = plan.normal(plan.vel.plan_point(link, c) - plan.vel.plan_point(link, p), length, X - XC)
    step_keys.append((link, p, X, n, length))
    return Equation(ap, 1j * (XC - X), "tangential", [(n, "normal", plan.end_label("n"), f"n_{c}{p}")])


def rotation_entries(plan: AccelerationPlan, link: str, p: str, X: complex, ap: complex, c: str,
                     XC: complex, ac: complex, n: complex, length: float, r: complex) -> None:
    """Entries a^n_CP (laid off), a^τ_CP (read), a_CP, and ε = a^τ_CP / l with its sense;
    ``r`` = C − P on the mechanism (exact, for the comparison)."""
    w, e = plan.exact.omega(link), plan.exact.eps(link)
    plan.entry(f"n_{c}{p}", "normal", n, -w * w * r, laid=True)
    plan.entry(f"t_{c}{p}", "tangential", ac - ap - n, 1j * e * r)
    if not plan.sc.fixed(p):
        plan.entry(f"{c}{p}", "relative", ac - ap, (1j * e - w * w) * r)
    plan.turn_rate(link, X, XC, ac - ap - n, length, 1j * e * r)


def acceleration_rrr(plan: AccelerationPlan, d: Dyad) -> None:
    """a_C = a_P1 + a^n_CP1 + a^τ_CP1 = a_P3 + a^n_CP3 + a^τ_CP3."""
    sc, lay, ex = plan.sc, plan.lay, plan.exact
    p1, p3, c = d.outer_a.point, d.outer_b.point, d.inner.point
    K1, K3 = d.outer_a.other(d.a), d.outer_b.other(d.b)
    X1, X3, XC = where(sc, lay, K1, p1), where(sc, lay, K3, p3), where(sc, lay, d.a, c)
    a1, a3 = plan.plan_point(K1, p1), plan.plan_point(K3, p3)
    parts: list = []
    e1 = normal_and_tangent(plan, d.a, p1, X1, a1, c, XC, abs(sc.local(d.a, c) - sc.local(d.a, p1)), parts)
    e3 = normal_and_tangent(plan, d.b, p3, X3, a3, c, XC, abs(sc.local(d.b, c) - sc.local(d.b, p3)), parts)
    step = f"a_{c} = a_{p1} + a^n_{c}{p1} + a^τ_{c}{p1} = a_{p3} + a^n_{c}{p3} + a^τ_{c}{p3}"
    ac = plan.solve(d.label, sub(c), e1, e3, step)
    plan.images[d.a] = Image.through(X1, a1, XC, ac)
    plan.images[d.b] = Image.through(X3, a3, XC, ac)
    for (link, p, X, n, length), ap in zip(parts, (a1, a3)):
        rotation_entries(plan, link, p, X, ap, c, XC, ac, n, length, ex.point(c)[0] - ex.point(p)[0])


def slide_equation(plan: AccelerationPlan, K: str, X: complex, base: complex, rel_v_mm: complex,
                   direction: complex, key: str) -> Equation:
    """a_C = a_C(K) + a^k (2·ω_K·v_rel, v_rel turned 90° in the sense of ω_K) + a^r (∥ the guide)."""
    chain = []
    if plan.sc.rotating[K]:
        k = plan.coriolis(K, rel_v_mm)
        chain.append((k, "coriolis", plan.end_label("k"), f"k_{key}"))
    return Equation(base, direction, "relative", chain)


def slide_entries(plan: AccelerationPlan, key: str, eq: Equation, found: complex, K: str,
                  exact_abs: complex, exact_carrier: complex, exact_rel_v: complex) -> None:
    """Entries a^k (laid off) and a^r (read) of a sliding pair on a moving guide."""
    if K == FRAME:
        return
    k = eq.chain[0][0] if eq.chain else 0j
    ek = 2j * plan.exact.omega(K) * exact_rel_v if plan.sc.rotating[K] else 0j
    if plan.sc.rotating[K]:
        plan.entry(f"k_{key}", "coriolis", k, ek, laid=True)
    plan.entry(f"r_{key}", "relative", found - eq.end, exact_abs - exact_carrier - ek)


def acceleration_rrp(plan: AccelerationPlan, d: Dyad) -> None:
    """a_C = a_P1 + a^n_CP1 + a^τ_CP1 = a_C(K) + a^k + a^r (∥ the guide)."""
    sc, lay, ex = plan.sc, plan.lay, plan.exact
    p1, c = d.outer_a.point, d.inner.point
    K1, K = d.outer_a.other(d.a), sc.mech.guides[d.outer_b.guide].body
    X1, XC = where(sc, lay, K1, p1), where(sc, lay, d.a, c)
    _, g = guide_line(sc, lay, d.outer_b.guide, d.b, c)
    a1 = plan.plan_point(K1, p1)
    key = f"{c}{sc.number(d.b)}{c}{sc.number(K)}"
    parts: list = []
    e1 = normal_and_tangent(plan, d.a, p1, X1, a1, c, XC, abs(sc.local(d.a, c) - sc.local(d.a, p1)), parts)
    rel_v = plan.vel.plan_point(d.b, c) - plan.vel.images[K].at(XC)
    e2 = slide_equation(plan, K, XC, plan.images[K].at(XC), rel_v, g, key)
    if K == FRAME:
        step = f"a_{c} = a_{p1} + a^n_{c}{p1} + a^τ_{c}{p1}, a_{c} ∥ the guide"
    else:
        kk = f" + a^k_{key}" if sc.rotating[K] else ""
        step = f"a_{c} = a_{p1} + a^n_{c}{p1} + a^τ_{c}{p1} = a_{sc.name_at(c, K)}{kk} + a^r_{key}"
    ac = plan.solve(d.label, sub(c), e1, e2, step)
    plan.images[d.a] = Image.through(X1, a1, XC, ac)
    plan.images[d.b] = Image(XC, ac, plan.images[K].F)
    link, p, X, n, length = parts[0]
    rotation_entries(plan, link, p, X, a1, c, XC, ac, n, length, ex.point(c)[0] - ex.point(p1)[0])
    plan.inherit(d.b, K)
    vk, ak = ex.at(K, c)
    slide_entries(plan, key, e2, ac, K, ex.point(c)[2], ak, ex.point(c)[1] - vk)


def acceleration_rpr(plan: AccelerationPlan, d: Dyad) -> None:
    """a_A3 = a_A2 + a^k_A3A2 + a^r_A3A2 (∥ the rocker) = a_Pc + a^n_A3Pc + a^τ_A3Pc (⊥ Pc A)."""
    sc, lay, ex = plan.sc, plan.lay, plan.exact
    slider, carrier, outer_s, outer_c = rpr_parts(d)
    ps, pc = outer_s.point, outer_c.point
    Ks, Kc = outer_s.other(slider), outer_c.other(carrier)
    Xs, Xc = where(sc, lay, Ks, ps), where(sc, lay, Kc, pc)
    g = lay.poses[slider].direction(0.0)
    a_s, a_c = plan.plan_point(Ks, ps), plan.plan_point(Kc, pc)
    a3, a2 = sc.name_at(ps, carrier), f"{ps}{sc.number(slider)}"
    key = f"{a3}{a2}"
    vel = plan.vel
    rel_v = vel.images[carrier].at(Xs) - vel.plan_point(Ks, ps)        # v_A3A2 on the velocity plan
    e1 = slide_equation(plan, carrier, Xs, a_s, rel_v, g, key)
    length = vel.rocker_length[carrier]
    n = plan.normal(vel.images[carrier].at(Xs) - vel.plan_point(Kc, pc), length, Xc - Xs)
    e2 = Equation(a_c, 1j * (Xs - Xc), "tangential", [(n, "normal", plan.end_label("n"), f"n_{a3}{pc}")])
    step = f"a_{a3} = a_{a2} + a^k_{key} + a^r_{key} = a_{pc} + a^n_{a3}{pc} + a^τ_{a3}{pc}"
    x3 = plan.solve(d.label, sub(a3), e1, e2, step)
    plan.images[carrier] = Image.through(Xc, a_c, Xs, x3)
    plan.images[slider] = Image(Xs, a_s, plan.images[carrier].F)
    v3, acc3 = ex.at(carrier, ps)
    plan.entry(a3, "point", x3, acc3)
    slide_entries(plan, key, e1, x3, carrier, acc3, ex.point(ps)[2], v3 - ex.point(ps)[1])
    rotation_entries(plan, carrier, pc, Xc, a_c, a3, Xs, x3, n, length, ex.point(ps)[0] - ex.point(pc)[0])
    plan.inherit(slider, carrier)


def acceleration_prp(plan: AccelerationPlan, d: Dyad) -> None:
    """a_C = a_C(K1) + a^k + a^r (∥ guide 1) = a_C(K2) + a^k + a^r (∥ guide 2)."""
    sc, lay, ex = plan.sc, plan.lay, plan.exact
    c = d.inner.point
    XC = where(sc, lay, d.a, c)
    sides = []
    for link, K, key, g in prp_guides(sc, lay, d):
        rel_v = plan.vel.plan_point(link, c) - plan.vel.images[K].at(XC)
        sides.append((link, K, key, slide_equation(plan, K, XC, plan.images[K].at(XC), rel_v, g, key)))
    terms = " = ".join((f"a_{sc.name_at(c, K)}" + (f" + a^k_{key}" if sc.rotating[K] else "") + f" + a^r_{key}")
                       if K != FRAME else f"a^r_{key}" for _, K, key, _ in sides)
    ac = plan.solve(d.label, sub(c), sides[0][3], sides[1][3], f"a_{c} = {terms}")
    for link, K, key, eq in sides:
        plan.images[link] = Image(XC, ac, plan.images[K].F)
        plan.inherit(link, K)
        vk, ak = ex.at(K, c)
        slide_entries(plan, key, eq, ac, K, ex.point(c)[2], ak, ex.point(c)[1] - vk)


def acceleration_rpp(plan: AccelerationPlan, d: Dyad) -> None:
    """a_A(b) = a_A(K) + a^k + a^r (∥ the yoke's guide) = a_A + a^k_A(b)A + a^r_A(b)A (∥ the slot)."""
    sc, lay, ex = plan.sc, plan.lay, plan.exact
    pa, Ka = d.outer_a.point, d.outer_a.other(d.a)
    K = sc.mech.guides[d.outer_b.guide].body
    XA = where(sc, lay, Ka, pa)
    g, slot = lay.poses[d.b].direction(0.0), lay.poses[d.a].direction(0.0)
    ab = sc.name_at(pa, d.b)
    slot_key, guide_key = f"{ab}{pa}{sc.number(d.a)}", f"{ab}{pa}{sc.number(K)}"
    vel = plan.vel
    vb = vel.images[d.b].at(XA)
    e1 = slide_equation(plan, K, XA, plan.images[K].at(XA), vb - vel.images[K].at(XA), g, guide_key)
    e2 = slide_equation(plan, d.a, XA, plan.plan_point(Ka, pa), vb - vel.plan_point(Ka, pa), slot, slot_key)
    first = (f"a_{sc.name_at(pa, K)}" + (f" + a^k_{guide_key}" if sc.rotating[K] else "") + f" + a^r_{guide_key}"
             if K != FRAME else f"a^r_{guide_key}")
    second = f"a_{pa}" + (f" + a^k_{slot_key}" if sc.rotating[d.a] else "") + f" + a^r_{slot_key}"
    xb = plan.solve(d.label, sub(ab), e1, e2, f"a_{ab} = {first} = {second}")
    plan.images[d.b] = Image(XA, xb, plan.images[K].F)
    plan.images[d.a] = Image(XA, plan.plan_point(Ka, pa), plan.images[K].F)
    plan.inherit(d.b, K)
    plan.inherit(d.a, K)
    v_b, a_b = ex.at(d.b, pa)
    plan.entry(ab, "point", xb, a_b)
    _, va, aa = ex.point(pa)
    # the slot's pair: A(b) relative to the block a, which turns with ω_K
    ek = 2j * ex.omega(d.a) * (v_b - va) if sc.rotating[d.a] else 0j
    if sc.rotating[d.a]:
        plan.entry(f"k_{slot_key}", "coriolis", e2.chain[0][0], ek, laid=True)
    plan.entry(f"r_{slot_key}", "relative", xb - e2.end, a_b - aa - ek)
    vk, ak = ex.at(K, pa)
    slide_entries(plan, guide_key, e1, xb, K, a_b, ak, v_b - vk)


ACCELERATION_STEPS = {"RRR": acceleration_rrr, "RRP": acceleration_rrp, "RPR": acceleration_rpr,
                      "PRP": acceleration_prp, "RPP": acceleration_rpp}


# -- all the plans of a mechanism ----------------------------------------------------------------

@dataclass
class PositionPlans:
    """One position: its layout on the position plan, its velocity plan and maybe its
    acceleration plan. ``key`` is the position's index, or N, N+1, … for extra crank angles."""
    key: int
    index: int | None
    phi: float
    layout: Layout
    velocity: VelocityPlan
    acceleration: AccelerationPlan | None
    warnings: list[PlanWarning]


@dataclass
class Plans:
    """Every plan of a mechanism, measured. Records are in drawing mm with their own origin: the
    crank's pivot on the position plan, the pole on the velocity and acceleration plans."""
    study: Study
    scheme: Scheme
    count: int
    precision: float
    mu_l: float
    mu_v: float
    mu_a: float
    targets: Targets
    positions: list[PositionPlans]
    extremes: list[Layout]
    trajectories: tuple[str, ...]

    @property
    def scales(self) -> dict[str, float]:
        return {"mu_l": self.mu_l, "mu_v": self.mu_v, "mu_a": self.mu_a}

    def at(self, key: int) -> PositionPlans:
        return next(p for p in self.positions if p.key == key)

    @property
    def accel_keys(self) -> list[int]:
        return [p.key for p in self.positions if p.acceleration is not None]


def resolve_accel(st: Study, phis: np.ndarray, accel: Sequence[str | int | float] | None
                  ) -> tuple[list[int], list[float]]:
    """Positions with acceleration plans: indices (an int, or "#3") and crank angles (a float, or
    "200" degrees; an angle on a position is that position). Default: the scene's, else position 1."""
    specs = list(accel) if accel else (list(st.mech.accel) or [1])
    n = len(phis)
    indices: list[int] = []
    extra: list[float] = []
    for spec in specs:
        index, phi = None, None
        if isinstance(spec, (int, np.integer)) and not isinstance(spec, bool):
            index = int(spec)
        elif isinstance(spec, (float, np.floating)):
            phi = float(spec)
        else:
            text = str(spec).strip()
            try:
                if text.startswith("#"):
                    index = int(text[1:])
                else:
                    phi = float(text.rstrip("°"))
            except ValueError:
                raise GraphplanError(f"--accel {text!r}: give a crank angle in degrees or a position "
                                     "index like #3") from None
            if phi is not None and not math.isfinite(phi):
                raise GraphplanError(f"--accel {text!r}: the angle must be finite")
        if index is not None:
            if not 0 <= index < n:
                raise GraphplanError(f"--accel #{index}: there are {n} positions (#0–#{n - 1})")
            indices.append(index)
            continue
        phi %= 360.0
        gaps = np.abs((phis - phi + 180.0) % 360.0 - 180.0)
        if np.min(gaps) < 1e-9:
            indices.append(int(np.argmin(gaps)))
        elif not any(abs((phi - e + 180.0) % 360.0 - 180.0) < 1e-9 for e in extra):
            extra.append(phi)
    extra.sort(key=lambda p: float(st.from_position0(p)))
    return sorted(set(indices)), extra


def choose_scales(st: Study, kin: Kinematics, phis: np.ndarray, accel_at: list[int], targets: Targets,
                  mu_l: float | None, mu_v: float | None, mu_a: float | None) -> tuple[float, float, float]:
    """μl from the crank (and the whole mechanism's extent), μv from p_v a, μa from π a — each
    the standard value that fills its target and keeps every figure within its limit. The sizes
    come from the exact solution: a draftsman sketches before choosing a scale."""
    mech = st.mech
    names = [n for n in mech.point_names()]
    xs = np.concatenate([np.atleast_1d(kin.point(n)[0]) for n in names])
    extent = max(np.ptp(xs.real), np.ptp(xs.imag))
    r = mech.crank.length
    ml = standard_scale(r, targets.crank, mu_l, extent, targets.layout)
    moving = [n for n in names if n not in mech.frame]
    v = max(float(np.max(np.abs(kin.point(n)[1]))) for n in moving)
    mv = standard_scale(abs(mech.omega1) * r, targets.velocity, mu_v, v, targets.figure)
    a_a = r * math.hypot(mech.omega1 ** 2, mech.crank.epsilon)
    a = max([float(np.max(np.abs(kin.point(n)[2][accel_at]))) for n in moving] + [a_a]) if accel_at else a_a
    ma = standard_scale(a_a, targets.acceleration, mu_a, a, targets.figure)
    return ml, mv, ma


def default_trajectories(mech: Mechanism) -> tuple[str, ...]:
    """Points whose paths are worth drawing: the extra points (centres of mass, coupler points) of
    the links after the crank."""
    joints = {j for link in mech.links.values() for j in link.joints}
    out = []
    for name, link in mech.links.items():
        if name == mech.crank.link:
            continue
        out += [p for p in link.local if p not in joints and p not in mech.frame and p not in out
                and p != next(iter(link.local))]
    return tuple(out)


def build_plans(st: Study, count: int | None = None, accel: Sequence[str | int | float] | None = None,
                precision: float = 0.5, mu_l: float | None = None, mu_v: float | None = None,
                mu_a: float | None = None, targets: Targets | None = None,
                trajectories: Sequence[str] | None = None) -> Plans:
    """The position plan of ``count`` positions (default: the scene's), the velocity plan of every
    position and acceleration plans at ``accel`` (indices / "#3" / crank angles in degrees; default:
    the scene's, else position 1), drawn with the scales given or chosen for ``targets``, read with
    a ruler of ``precision`` mm (0 = exact)."""
    if not (isinstance(precision, (int, float)) and math.isfinite(precision) and 0 <= precision <= 10):
        raise GraphplanError(f"--precision must be from 0 to 10 mm, got {precision!r}")
    n = count or st.mech.count
    if not 2 <= n <= 3600:
        raise GraphplanError(f"--positions must be from 2 to 3600, got {n}")
    targets = targets or Targets()
    phis = np.asarray(st.positions(n), dtype=float)
    accel_idx, extra = resolve_accel(st, phis, accel)
    all_phi = np.concatenate([phis, np.asarray(extra, dtype=float)])
    kin = st.solve(all_phi)
    acc_keys = accel_idx + list(range(n, n + len(extra)))
    ml, mv, ma = choose_scales(st, kin, all_phi, acc_keys, targets, mu_l, mu_v, mu_a)
    sc = Scheme(st)
    trajectories = tuple(trajectories) if trajectories is not None else default_trajectories(st.mech)
    for name in trajectories:
        if name not in st.mech.point_names():
            raise GraphplanError(f"trajectory: no point named {name!r}")
    results = []
    for key, phi in enumerate(all_phi):
        index = key if key < n else None
        lay = construct_position(sc, float(phi), ml, key, index)
        exact = Exact(kin, key)
        vel = VelocityPlan(sc, lay, exact, mv, precision)
        vel.crank()
        for d in st.structure.dyads:
            vel.group(d)
        vel.finish()
        acc = None
        if key in acc_keys:
            acc = AccelerationPlan(sc, lay, exact, ma, precision, vel)
            acc.crank()
            for d in st.structure.dyads:
                acc.group(d)
            acc.finish()
        warnings = [PlanWarning("position", g, kind, angle,
                                f"position plan, {g}: {what} at {angle:.1f}° (< {SMALL_ANGLE_DEG:g}°), "
                                + ("nearly tangent" if kind == "arcs" else "nearly parallel"))
                    for g, what, angle, kind in lay.angles if angle < SMALL_ANGLE_DEG]
        warnings += vel.warnings + (acc.warnings if acc else [])
        results.append(PositionPlans(key, index, float(phi), lay, vel, acc, warnings))
    extremes = [construct_position(sc, float(e), ml, -1 - j) for j, e in enumerate(st.extremes)]
    return Plans(st, sc, n, float(precision), ml, mv, ma, targets, results, extremes, trajectories)
