"""The force plans and the Zhukovsky lever, drawn and measured like a student (seed 000 §2.6).

Each group, from the last to the crank, is drawn at the length scale μl with every force at its
point. The tangential components of the outer revolute reactions come from the moment equation of
each link about the inner joint, Σ F·h = 0, with the arms h read off the drawing (mm, rounded to the
drafting precision) — "R^τ·BC + P'·BC + Φ·h2 − G·h1 = 0". The force polygon is then laid off at μF
(N/mm, the standard series): the known forces head to tail, each drawn to the nearest precision mm,
and closed by lines of the unknown directions; where they cross the reactions are read off (mm,
rounded) and multiplied by μF. A reaction found in one group enters the next one as a known force
with its measured value. The crank's equilibrium gives the balancing moment M_b = R21·h·μl.

The lever: the velocity plan is built from the measured plan vectors p_v x (mm at μv, rounded),
turned 90° counter-clockwise; each force is carried to its point's image (a couple as a pair
M/l at its link's joints); Σ F·h about the pole, with h read off the lever, balances the force P_b
at the crank pin's image: P_b·pa = ΣF·h, M_b = P_b·l_OA.

The inertia loads are the draftsman's own: Φ = −m·a_S and M^Φ = −I_S·ε with a_S (π s × μa, against π s
as drawn) and ε read off the force position's acceleration plan (``plan_inertia``), as the lab takes them.

With precision 0 nothing is rounded and every result equals the closed form (kinetostatics.py).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from graphplan.graphic.draftsman import measure  # noqa: F401  (the one ruler)
from graphplan.graphic.scales import SERIES, at_least as standard_scale  # noqa: F401  (the one series)
from graphplan.exact.kinematics import cross, dot
from graphplan.exact.kinetostatics import CRANK_LABEL, Kinetostatics, analyse, number, reaction_key
from graphplan.model.mechanism import FRAME
from graphplan.exact.positions import Study
from graphplan.graphic.lever import Lever, LeverTerm, lever, velocity_scale  # noqa: F401

DEFAULT_PRECISION = 0.5
POLYGON_MM = 150.0     # the largest force of the analysis is drawn at most this long
MECHANISM_MM = 250.0   # the mechanism's extent over the turn fits in this many mm


def angle_deg(z: complex) -> float:
    """The direction of a vector, degrees in [0, 360) (0 for the zero vector)."""
    if abs(z) == 0:
        return 0.0
    a = math.degrees(math.atan2(z.imag, z.real)) % 360.0
    return 0.0 if a >= 360.0 else a + 0.0


def error_pct(value: float, analytic: float, scale: float) -> float | None:
    """100·(value − analytic)/analytic, or None when |analytic| < 1e-6·scale (a percent of
    nearly nothing means nothing)."""
    if abs(analytic) < 1e-6 * scale or abs(analytic) == 0:
        return None
    return 100.0 * (value - analytic) / analytic


# -- what the plans are made of ------------------------------------------------------------------

@dataclass
class GForce:
    """A force (or couple) known to act on a link of a group: a load or a transferred reaction."""
    name: str
    link: str
    at: complex          # m
    force: complex       # N, as the draftsman uses it (loads exact, reactions as measured)
    couple: float = 0.0  # N·m
    kind: str = "load"   # "load", "reaction" (handed over by a group solved before) or "balancing" (M_зр)


@dataclass
class Term:
    """One term ±F·h of a moment equation; h in drawing mm (measured), value in N·m. A couple
    enters as it is (``couple`` True, ``force`` = M)."""
    name: str
    force: float
    arm_mm: float
    value: float
    foot: complex = 0j   # the foot of the arm on the force's line (drawing mm)
    couple: bool = False


@dataclass
class MomentEquation:
    """Σ M_P = 0 for a link (or the group) about point P, solved for one unknown component."""
    about: str
    links: tuple[str, ...]
    terms: list[Term]
    unknown: str
    arm_mm: float        # the unknown's arm (the link's length, or the block's distance)
    result: float        # the unknown component (N), signed along its reference direction


@dataclass
class Side:
    """A side of a force polygon, in the polygon's mm."""
    name: str
    start: complex
    end: complex
    role: str            # "known", "reaction", "component"

    @property
    def mm(self) -> float:
        return abs(self.end - self.start)


@dataclass
class Measured:
    """A reaction read off its polygon: mm, value = mm·μF, its direction, and the truth."""
    key: str
    mm: float
    value: float
    angle_deg: float
    analytic: float
    analytic_angle_deg: float
    error_pct: float | None
    vector: complex      # the measured force on the higher-numbered link, N (as ``key`` reads it)
    name: str = ""       # R<from><to> as the group it was found in bears it: <to> in that group
    acting: complex = 0j  # the measured force on that group's link (``name``), N
    line: complex | None = None   # a sliding pair's reaction: a point of its line of action found by ΣM = 0 (m)
    detail_mu: float = 0.0   # its side under the ruler's division on the plan: read off the plan's detail at this μF_I


@dataclass
class GroupPlan:
    """One group's construction: its forces, moment equations, force polygon and reactions."""
    label: str
    kind: str
    links: tuple[str, ...]
    forces: list[GForce]
    equations: list[MomentEquation]
    sides: list[Side]
    lines: list[tuple[complex, complex]]            # direction lines of the unknowns (mm)
    reactions: dict[str, Measured]
    points: dict[str, complex]                      # the group's points on the drawing (mm)
    segments: list[tuple[str, str]]                 # the group's links as point pairs
    mu_l: float = 0.0                               # the scale the group is drawn (and measured) at, m/mm
    mu_F: float = 0.0                               # the scale its force plan is drawn (and read) at, N/mm
    detail_sides: list[Side] = field(default_factory=list)   # its polygon laid again at the detail's μF_I (mm
                                                    # there), where a reaction is read off the detail


@dataclass
class Inertia:
    """One link's inertia loads as the draftsman takes them (seed 000 §2.5, table 2.3): a_S and ε read
    off the force position's acceleration plan — π s (mm, ruler) × μa along the drawn vector, ε from
    its relative tangential vector, as its Table 1 prints them — and Φ = −m·a_S (against the drawn
    π s), M^Φ = −I_S·ε (+ counter-clockwise); beside them the closed form's (``exact_*``).
    ``source`` is "plan", or "exact" where the plan has no such reading (a centre of mass it does
    not construct)."""
    link: str
    point: str                       # the centre of mass (a link without one: its first point)
    mass: float                      # kg
    inertia: float                   # I_S, kg·m²
    a_mm: float | None               # π s as read, mm (None: not read off the plan)
    a: complex                       # a_S as read, m/s²
    eps: float                       # ε as read, rad/s², + counter-clockwise
    exact_a: complex
    exact_eps: float
    source: str = "plan"

    @property
    def force(self) -> complex:
        """Φ = −m·a_S, N."""
        return -self.mass * self.a + 0j

    @property
    def couple(self) -> float:
        """M^Φ = −I_S·ε, N·m (+ counter-clockwise)."""
        return -self.inertia * self.eps + 0.0

    @property
    def exact_force(self) -> complex:
        return -self.mass * self.exact_a + 0j

    @property
    def exact_couple(self) -> float:
        return -self.inertia * self.exact_eps + 0.0


@dataclass
class ForcePlans:
    """The whole graphical force analysis at one crank angle. Its inertia loads are the acceleration
    plan's (``inertia``, ``loads``); ``ks`` is the closed form every reading is compared with."""
    ks: Kinetostatics
    phi_deg: float
    precision: float
    mu_l: float
    mu_F: float
    groups: list[GroupPlan]          # last group first, the crank last
    balancing: float                 # M_b from the crank's equilibrium (plans), N·m
    balancing_arm_mm: float
    lever: Lever
    warnings: list[str] = field(default_factory=list)
    inertia: dict[str, Inertia] = field(default_factory=dict)   # link → its Φ, M^Φ from the plan
    loads: list = field(default_factory=list)                   # the loads the plans and the lever take
    mu_a: float = 0.0                # the acceleration plan's scale the inertia loads were read at

    @property
    def analytic(self) -> float:
        return float(self.ks.balancing[0])

    @property
    def power(self) -> float:
        return float(self.ks.power()[0])

    def reactions(self) -> dict[str, Measured]:
        out: dict[str, Measured] = {}
        for g in self.groups:
            out.update(g.reactions)
        return out


# -- the construction ----------------------------------------------------------------------------

class _Draftsman:
    """Draws at μl and μF and reads lengths to the precision."""

    def __init__(self, ks: Kinetostatics, precision: float, mu_l: float, mu_F: float, loads: list | None = None):
        self.ks, self.mech, self.kin = ks, ks.mech, ks.kin
        self.p, self.mu_l, self.mu_F = precision, mu_l, mu_F
        self.known: dict[str, list[GForce]] = {name: [] for name in self.mech.links}
        for ld in (ks.loads if loads is None else loads):
            f, c = complex(ld.force[0]), float(ld.couple[0])
            if f == 0 and c == 0:
                continue
            self.known[ld.link].append(GForce(ld.name, ld.link, complex(ld.at[0]), f, c))
        self.scale = max([abs(g.force) for fs in self.known.values() for g in fs]
                         + [float(np.max(np.abs(r.force))) for r in ks.reactions.values()] + [1.0])

    # the drawing of the mechanism
    def mm(self, x: complex) -> complex:
        return x / self.mu_l

    def at(self, point: str, link: str | None = None) -> complex:
        """A point's position (m); on ``link`` when given (a slider's own point)."""
        if link is not None and point in self.mech.links[link].local:
            return complex(self.kin.bodies[link].at(self.mech.links[link].local[point])[0][0])
        return complex(self.kin.point(point)[0][0])

    def pair_at(self, pair) -> complex:
        body = pair.slider if pair.kind == "P" else next(b for b in pair.bodies if b != FRAME)
        return self.at(pair.point, body)

    def guide(self, pair) -> complex:
        g = self.mech.guides[pair.guide]
        return complex(np.exp(1j * (self.kin.bodies[g.body].theta[0] + g.angle)))

    # measuring
    def length(self, a: complex, b: complex) -> float:
        """A distance on the mechanism's drawing, measured (m)."""
        return measure(abs(self.mm(b - a)), self.p) * self.mu_l

    def term(self, f: GForce, about: complex) -> list[Term]:
        """±F·h about a point with h read off the drawing; a couple enters as it is."""
        out = []
        if f.force != 0:
            r = self.mm(f.at - about)
            unit = f.force / abs(f.force)
            arm = cross(r, unit)
            h = math.copysign(measure(abs(arm), self.p), arm)
            foot = r - dot(r, unit) * unit + self.mm(about)
            out.append(Term(f.name, abs(f.force), h, abs(f.force) * h * self.mu_l, complex(foot)))
        if f.couple:
            out.append(Term(f.name, f.couple, 0.0, f.couple, couple=True))
        return out

    def moments(self, links: tuple[str, ...], about: complex) -> list[Term]:
        return [t for link in links for f in self.known[link] for t in self.term(f, about)]

    def drawn(self, force: complex) -> complex:
        """A known force laid off at μF: its length rounded, its direction exact (mm)."""
        if force == 0:
            return 0j
        return measure(abs(force) / self.mu_F, self.p) * force / abs(force)

    def read(self, vec_mm: complex) -> tuple[float, complex]:
        """An unknown read off the polygon: (mm, the force in N)."""
        mm = measure(abs(vec_mm), self.p)
        if abs(vec_mm) == 0:
            return 0.0, 0j
        return mm, mm * self.mu_F * vec_mm / abs(vec_mm)



READ_LEAST_MM = 1.0     # a reaction the ruler reads shorter than this on its plan (0 mm or one division) …
READ_DETAIL_MM = 4.0    # … is read off the plan's detail, where it is drawn at least this long …
DETAIL_GAIN_MOST = 20.0  # … at most this many times larger (a side under 1/20 mm is 0 to any detail)


def detail_scale(side_mm: float, mu_F: float) -> float:
    """The detail's μF_I a side ``side_mm`` long on a plan at ``mu_F`` is read at: the largest value
    of the standard series (1, 2, 2.5, 4, 5 × 10^k: LAYOUT.md's for every μF, review 59 #2's inset
    at 1.5 N/mm none of it) that draws it at least ``READ_DETAIL_MM`` long, and at most half the
    plan's μF (the plan's ``plan_detail`` offers the same value)."""
    from graphplan.graphic.scales import at_most
    return at_most(max(min(mu_F * side_mm / READ_DETAIL_MM, mu_F / 2.0), mu_F / DETAIL_GAIN_MOST))


class _Polygon:
    """A force polygon: known forces head to tail, then the unknowns closing it."""

    def __init__(self, d: _Draftsman):
        self.d = d
        self.sides: list[Side] = []
        self.lines: list[tuple[complex, complex]] = []
        self.end = 0j

    def lay(self, name: str, force: complex, role: str = "known") -> complex:
        """Lay a known force from the current end; returns the vertex it starts at."""
        start = self.end
        vec = self.d.drawn(force)
        if vec != 0:
            self.sides.append(Side(name, start, start + vec, role))
        self.end = start + vec
        return start

    def lay_all(self, forces: list[GForce]) -> None:
        for f in forces:
            if f.force != 0:
                self.lay(f.name, f.force)

    def close_two(self, u_end: complex, u_start: complex, start: complex = 0j) -> complex:
        """Lines ∥ u_end through the current end and ∥ u_start through ``start``: their crossing."""
        e = self.end
        # e + s·u_end = start + t·u_start
        s = cross(start - e, u_start) / cross(u_end, u_start)
        k = complex(e + s * u_end)
        for base, u in ((e, u_end), (start, u_start)):
            reach = dot(k - base, u)
            lo, hi = min(0.0, reach) - 8.0, max(0.0, reach) + 8.0
            self.lines.append((complex(base + lo * u), complex(base + hi * u)))
        return k

    def side(self, name: str, a: complex, b: complex, role: str = "reaction") -> Side:
        s = Side(name, a, b, role)
        self.sides.append(s)
        return s


def _orient(mech, frm: str, on: str, force: complex) -> complex:
    """The force as the key R<lo><hi> reads it: on the higher-numbered body."""
    return -force if number(mech, frm) > number(mech, on) else force


class _Plans:
    def __init__(self, ks: Kinetostatics, precision: float, mu_l: float, mu_F: float, loads: list | None = None):
        self.d = _Draftsman(ks, precision, mu_l, mu_F, loads)
        self.ks, self.mech = ks, ks.mech
        self.groups: list[GroupPlan] = []
        self.detailed = False       # the group being drawn has a reaction read off its detail
        self.fine: dict[str, tuple[float, complex]] = {}   # a reaction read off the detail: (μF_I, its side there, mm)
        self.raw: dict[str, complex] | None = None        # a pass at μF_I: each reaction's side as laid (mm)

    def measured(self, key: str, vec_mm: complex, frm: str, on: str, pair, at: complex,
                 couple_line: complex | None = None, tau: complex | None = None) -> Measured:
        """Read a reaction (the force on ``on`` from ``frm``) and hand it to the links it loads.
        With ``tau`` (a revolute's R^τ, N, as its moment equation found it) the reaction is the
        textbook's R = R^τ + R^n: R^n read off the polygon along the link (``vec_mm`` is then R^n's
        side), R^τ as computed — not the closing side read whole, whose direction the ruler takes
        from a R^τ rounded to the drafting precision (a 51 N R^τ12 drawn 0.5 mm at 200 N/mm as
        100 N turned R12 by 1.6° and M_b by the plans 4.4 % off, review 56 #1)."""
        mm, force = self.d.read(vec_mm)
        mu_I = 0.0
        if self.raw is not None:
            self.raw[key] = vec_mm
        if key in self.fine:
            # read off the detail, where the group's polygon is laid again at μF_I (``group``)
            self.detailed = True
            mu_I, fine = self.fine[key]
            mm = measure(abs(fine), self.p)
            force = mm * mu_I * fine / abs(fine) if abs(fine) > 0 else 0j
        elif (tau is None and mm < READ_LEAST_MM and abs(vec_mm) * DETAIL_GAIN_MOST >= 1.0 and self.p > 0
                and not self.detailed and self.raw is None):
            # the ruler reads the side 0 mm or one division at μF (FRC56_PUMP's R05: 0.23 mm, 1.15 N,
            # at 5 N/mm, printed 0): read off the plan's detail, the spot drawn again at a finer μF_I
            # (drawing.forces.plan_detail) — one a plan, its first such reaction's
            self.detailed = True
            mu_I = detail_scale(abs(vec_mm), self.d.mu_F)
            mm = measure(abs(vec_mm) * self.d.mu_F / mu_I, self.p)
            force = mm * mu_I * vec_mm / abs(vec_mm)
        if tau is not None:
            force = force + tau
            mm = measure(abs(force) / self.d.mu_F, self.p)
        for body, other, f in ((frm, on, -force), (on, frm, force)):
            if body != FRAME and body not in self.current:
                where = couple_line if couple_line is not None else at
                # handed over to a later group: the force of ``other`` on ``body``, named so (R43)
                self.d.known[body].append(GForce(reaction_key(self.mech, other, body), body, where, f,
                                                 0.0, "reaction"))
        truth = self.ks.reactions[key]
        t = complex(truth.force[0])
        v = _orient(self.mech, frm, on, force)
        return Measured(key, mm, abs(v), angle_deg(v), abs(t), angle_deg(t),
                        error_pct(abs(v), abs(t), self.d.scale), v, reaction_key(self.mech, frm, on), force,
                        couple_line if pair is not None and pair.kind == "P" else None, mu_I)

    def key_of(self, group: str, pair) -> str:
        for k, r in self.ks.reactions.items():
            if r.group == group and r.point == pair.point and {r.frm, r.on} == set(pair.bodies):
                return k
        raise KeyError(pair)

    def equation(self, about_name: str, about: complex, links: tuple[str, ...], unknown: str,
                 arm_m: float, extra: list[Term] | None = None) -> MomentEquation:
        """Σ M_about(known) + R·arm = 0 → R = −Σ/arm (the arm measured, signed)."""
        terms = self.d.moments(links, about) + (extra or [])
        total = sum(t.value for t in terms)
        result = -total / arm_m + 0.0 if arm_m else 0.0
        return MomentEquation(about_name, links, terms, unknown, arm_m / self.d.mu_l, result)

    def group(self, gf) -> None:
        """A group's construction (``_group``); where the ruler reads a reaction 0 mm or one
        division on its plan (FRC56_PUMP's R05: 0.37 mm at 10 N/mm), the polygon laid again at the
        detail's μF_I — every known rounded to the ruler at that scale, the closing lines crossing
        there — and the reaction read off that: the plan's side enlarged kept the plan's rounding
        (the knowns' 0.25 mm at 10 N/mm each, twice the reaction's 1.18 N) and read 3.75 N, +217 %.
        Where the side laid at μF_I is still under ``READ_DETAIL_MM``, once more at the finer μF_I
        it asks (within ``DETAIL_GAIN_MOST``)."""
        known = {k: list(v) for k, v in self.d.known.items()}
        self._group(gf)
        fine = next(((m.key, m.detail_mu) for m in self.groups[-1].reactions.values() if m.detail_mu), None)
        if fine is None:
            return
        key, mu_I = fine
        mu_F = self.d.mu_F
        for attempt in range(3):
            # a pass at μF_I: nothing handed over, nothing kept but the sides laid
            self.groups.pop()
            self.d.known = {k: list(v) for k, v in known.items()}
            self.d.mu_F, self.raw = mu_I, {}
            self._group(gf)
            side, sides = self.raw[key], self.groups[-1].sides
            self.raw, self.d.mu_F = None, mu_F
            finer = detail_scale(abs(side) * mu_I / mu_F, mu_F)
            if abs(side) >= READ_DETAIL_MM or finer >= mu_I - 1e-12 or attempt == 2:
                break
            mu_I = finer
        self.groups.pop()
        self.d.known = known
        self.fine = {key: (mu_I, side)}
        self._group(gf)
        self.fine = {}
        self.groups[-1].detail_sides = sides

    def _group(self, gf) -> None:
        d = gf.dyad
        self.current = (d.a, d.b)
        self.detailed = False
        kind = d.kind
        poly = _Polygon(self.d)
        eqs: list[MomentEquation] = []
        found: dict[str, Measured] = {}
        pts: dict[str, complex] = {}
        segs: list[tuple[str, str]] = []
        fa, fb = self.d.known[d.a], self.d.known[d.b]

        def pair_key(pair):
            return self.key_of(d.label, pair)

        def on(pair, body):
            """The reaction in ``pair`` as it acts on the group's ``body``: R<from><to>."""
            return reaction_key(self.mech, pair.other(body), body)

        if kind in ("RRR", "RRP"):
            p1, c = self.d.pair_at(d.outer_a), self.d.pair_at(d.inner)
            la = self.d.length(p1, c)
            ua = (c - p1) / abs(c - p1)
            # moment of link a about C: M_a(C) − l·τ_a = 0 (τ along i·u_a)
            ea = self.equation(d.inner.point, c, (d.a,), f"{on(d.outer_a, d.a)}τ", -la)
            eqs.append(ea)
            ta = ea.result
            poly.lay(f"{on(d.outer_a, d.a)}τ", 1j * ta * ua, "component")
            t_end = poly.end
            poly.lay_all(fa)
            vb = poly.end
            poly.lay_all(fb)
            if kind == "RRR":
                p3 = self.d.pair_at(d.outer_b)
                lb = self.d.length(p3, c)
                ub = (c - p3) / abs(c - p3)
                eb = self.equation(d.inner.point, c, (d.b,), f"{on(d.outer_b, d.b)}τ", -lb)
                eqs.append(eb)
                u_start = poly.lay(f"{on(d.outer_b, d.b)}τ", 1j * eb.result * ub, "component")
                k = poly.close_two(ub, ua)
                poly.side(f"{on(d.outer_b, d.b)}n", poly.end, k, "component")
                kb = pair_key(d.outer_b)
                found[kb] = self.measured(kb, k - poly.end, d.outer_b.other(d.b), d.b, d.outer_b, p3,
                                          tau=1j * eb.result * ub)
                poly.side(found[kb].name, u_start, k)
                pts[d.outer_b.point] = p3
            else:
                ng = 1j * self.d.guide(d.outer_b)
                k = poly.close_two(ng, ua)
                kb = pair_key(d.outer_b)
                xb = self.d.pair_at(d.outer_b)
                _, force_b = self.d.read(k - poly.end)
                # the slider's moment about C places the guide's reaction along the guide
                line = self.p_line(d.b, c, d.outer_b, xb, force_b)
                found[kb] = self.measured(kb, k - poly.end, d.outer_b.other(d.b), d.b, d.outer_b, xb, line)
                poly.side(found[kb].name, poly.end, k)
                pts[d.outer_b.point + "'"] = xb
            poly.side(f"{on(d.outer_a, d.a)}n", k, 0j, "component")
            ka, ki = pair_key(d.outer_a), pair_key(d.inner)
            found[ka] = self.measured(ka, 0j - k, d.outer_a.other(d.a), d.a, d.outer_a, p1, tau=1j * ta * ua)
            poly.side(found[ka].name, k, t_end)
            found[ki] = self.measured(ki, vb - k, d.a, d.b, d.inner, c)
            poly.side(found[ki].name, k, vb)
            pts[d.outer_a.point], pts[d.inner.point] = p1, c
            segs = [(d.outer_a.point, d.inner.point)] + ([(d.outer_b.point, d.inner.point)]
                                                         if kind == "RRR" else [])
        elif kind == "RPR":
            slider, carrier, outer_s, outer_c = d.block_parts
            ps, pc = self.d.pair_at(outer_s), self.d.pair_at(outer_c)
            g = self.d.guide(d.inner)
            n = 1j * g
            ks_ = pair_key(outer_s)
            # the block's forces along the guide are balanced by its pin: r_along = −ΣF_s·g
            r_along = -sum(dot(self.d.drawn(f.force), g) for f in self.d.known[slider]) * self.d.mu_F
            rho = self.d.mm(ps - pc)
            along_arm = math.copysign(measure(abs(dot(rho, g)), self.p), dot(rho, g)) * self.d.mu_l
            off_arm = math.copysign(measure(abs(cross(rho, g)), self.p), cross(rho, g)) * self.d.mu_l
            foot = self.d.mm(ps + dot(pc - ps, g) * g)      # on the guide's line through the block
            extra = ([Term(f"{on(outer_s, slider)}^∥", r_along, off_arm / self.d.mu_l, r_along * off_arm, foot)]
                     if r_along else [])
            e = self.equation(outer_c.point, pc, (slider, carrier), f"{on(outer_s, slider)}^⊥", along_arm, extra)
            eqs.append(e)
            r_s = r_along * g + e.result * n
            start = poly.lay(on(outer_s, slider), r_s, "known")
            poly.lay_all(self.d.known[slider])
            vc = poly.end
            poly.lay_all(self.d.known[carrier])
            found[ks_] = self.measured(ks_, self.d.drawn(r_s), outer_s.other(slider), slider, outer_s, ps)
            kc, ki = pair_key(outer_c), pair_key(d.inner)
            found[kc] = self.measured(kc, start - poly.end, outer_c.other(carrier), carrier, outer_c, pc)
            poly.side(found[kc].name, poly.end, start)
            found[ki] = self.measured(ki, start - vc, carrier, slider, d.inner, ps)
            poly.side(found[ki].name, vc, start, "component")
            pts[outer_s.point], pts[outer_c.point] = ps, pc
            # the rocker's drawn extent: its pivot, the block and any joint it carries
            far = [p for p in self.mech.links[carrier].joints if p != outer_c.point]
            for p in far:
                pts[p] = self.d.at(p, carrier)
                segs.append((outer_c.point, p))
            segs.append((outer_c.point, outer_s.point))
        elif kind == "PRP":
            c = self.d.pair_at(d.inner)
            na_, nb_ = 1j * self.d.guide(d.outer_a), 1j * self.d.guide(d.outer_b)
            poly.lay_all(fa)
            vb = poly.end
            poly.lay_all(fb)
            k = poly.close_two(nb_, na_)
            kb, ka, ki = pair_key(d.outer_b), pair_key(d.outer_a), pair_key(d.inner)
            xa, xb = self.d.pair_at(d.outer_a), self.d.pair_at(d.outer_b)
            _, force_b = self.d.read(k - poly.end)
            _, force_a = self.d.read(0j - k)
            found[kb] = self.measured(kb, k - poly.end, d.outer_b.other(d.b), d.b, d.outer_b, xb,
                                      self.p_line(d.b, c, d.outer_b, xb, force_b))
            poly.side(found[kb].name, poly.end, k)
            found[ka] = self.measured(ka, 0j - k, d.outer_a.other(d.a), d.a, d.outer_a, xa,
                                      self.p_line(d.a, c, d.outer_a, xa, force_a))
            poly.side(found[ka].name, k, 0j)
            found[ki] = self.measured(ki, vb - k, d.a, d.b, d.inner, c)
            poly.side(found[ki].name, k, vb)
            pts[d.inner.point] = c
        elif kind == "RPP":
            pa = self.d.pair_at(d.outer_a)
            n_in = 1j * self.d.guide(d.inner)
            ng = 1j * self.d.guide(d.outer_b)
            poly.lay_all(fb)
            k = poly.close_two(ng, n_in)
            kb, ki, ka = pair_key(d.outer_b), pair_key(d.inner), pair_key(d.outer_a)
            x_in, xb = self.d.pair_at(d.inner), self.d.pair_at(d.outer_b)
            _, r_in = self.d.read(k - 0j)                       # on the block from the yoke
            in_line = self.p_line(d.a, pa, d.inner, x_in, r_in)
            _, r_b = self.d.read(k - poly.end)
            back = -abs(r_in) * cross(self.d.mm(in_line - xb), r_in / abs(r_in)) * self.d.mu_l if r_in else 0.0
            found[kb] = self.measured(kb, k - poly.end, d.outer_b.other(d.b), d.b, d.outer_b, xb,
                                      self.p_line(d.b, xb, d.outer_b, xb, r_b, back))
            poly.side(found[kb].name, poly.end, k)
            found[ki] = self.measured(ki, k - 0j, d.b, d.a, d.inner, x_in)
            poly.side(found[ki].name, 0j, k)
            poly.end = k
            poly.lay_all(fa)
            found[ka] = self.measured(ka, 0j - poly.end, d.outer_a.other(d.a), d.a, d.outer_a, pa)
            poly.side(found[ka].name, poly.end, 0j)
            pts[d.outer_a.point] = pa
        forces = self.d.known[d.a] + self.d.known[d.b]
        self.groups.append(GroupPlan(d.label, kind, (d.a, d.b), forces, eqs, poly.sides, poly.lines,
                                     found, {k: self.d.mm(v) for k, v in pts.items()}, segs, self.d.mu_l,
                                     self.d.mu_F))

    @property
    def p(self) -> float:
        return self.d.p

    def p_line(self, link: str, about: complex, pair, x_ref: complex, force: complex,
               extra: float = 0.0) -> complex:
        """Where a sliding pair's reaction acts on ``link``: the link's moment equation about a
        point (arms measured) gives its couple M about the pair's reference point; the line of
        action is shifted along the guide by M/(g × R)."""
        if force == 0:
            return x_ref
        total = sum(t.value for t in self.d.moments((link,), about)) + extra
        unit = force / abs(force)
        arm = cross(self.d.mm(x_ref - about), unit)
        total += abs(force) * math.copysign(measure(abs(arm), self.p), arm) * self.d.mu_l
        g = self.d.guide(pair)
        return x_ref + (-total / cross(g, force)) * g

    def crank(self) -> tuple[float, float]:
        """R01 closes the crank's polygon; M_b = −ΣM_O with the arms measured."""
        mech = self.mech
        crank = mech.crank.link
        self.current = (crank,)
        self.detailed = False
        o, a = self.d.at(mech.crank.pivot), self.d.at(mech.crank.pin)
        poly = _Polygon(self.d)
        poly.lay_all(self.d.known[crank])
        key = next(k for k, r in self.ks.reactions.items() if r.group == CRANK_LABEL)
        found = {key: self.measured(key, 0j - poly.end, FRAME, crank, None, o)}
        poly.side(key, poly.end, 0j)
        terms = self.d.moments((crank,), o)
        m_b = -float(sum(t.value for t in terms))
        eq = MomentEquation(mech.crank.pivot, (crank,), terms, "M_b", 0.0, m_b)
        transferred = [t for t in terms if t.name.startswith("R")]
        arm = transferred[0].arm_mm if len(transferred) == 1 else float("nan")
        # the balancing moment M_зр (found here) acts on the crank with its sense: drawn and tabulated
        balancing = GForce("M_b", crank, o, 0j, m_b, "balancing")
        self.groups.append(GroupPlan(CRANK_LABEL, "crank", (crank,), list(self.d.known[crank]) + [balancing], [eq],
                                     poly.sides, poly.lines, found,
                                     {mech.crank.pivot: self.d.mm(o), mech.crank.pin: self.d.mm(a)},
                                     [(mech.crank.pivot, mech.crank.pin)], self.d.mu_l, self.d.mu_F))
        return m_b, arm


def group_extent(ks: Kinetostatics, links: tuple[str, ...]) -> float:
    """The larger side of the box around a group's points (its links' joints and centres of mass) in
    the analysed position, m."""
    mech, kin = ks.mech, ks.kin
    pts = [complex(kin.bodies[link].at(mech.links[link].local[p])[0][0])
           for link in links for p in mech.links[link].local]
    if len(pts) < 2:
        return 0.0
    xs, ys = [z.real for z in pts], [z.imag for z in pts]
    return max(max(xs) - min(xs), max(ys) - min(ys))


def mechanism_scale(st: Study, target_mm: float = MECHANISM_MM) -> float:
    """μl (m/mm, standard series) so that the mechanism's extent over a turn fits ``target_mm``."""
    kin = st.solve(np.arange(0.0, 360.0, 5.0))
    xs = [kin.point(p)[0] for p in st.mech.point_names()]
    allx = np.concatenate(xs)
    extent = max(np.ptp(allx.real), np.ptp(allx.imag), st.mech.crank.length)
    return standard_scale(extent / target_mm)


def force_scale(ks: Kinetostatics, target_mm: float = POLYGON_MM) -> float:
    """μF (N/mm, standard series) so that the largest force of the analysis is ≤ ``target_mm``."""
    biggest = max([float(np.max(np.abs(ld.force))) for ld in ks.loads]
                  + [float(np.max(np.abs(r.force))) for r in ks.reactions.values()] + [0.0])
    return standard_scale(biggest / target_mm) if biggest > 0 else 1.0


def plan_inertia(ks: Kinetostatics, accel) -> dict[str, Inertia]:
    """Each loaded link's a_S and ε read off the acceleration plan ``accel`` (a ``graphic.plans.Plans``
    holding the plan of ``ks``'s angle, as ``acceleration_plan`` draws it): π s read with the ruler ×
    μa along the vector as drawn, ε the plan's (its Table 1 values) — Φ = −m·a_S, M^Φ = −I_S·ε (seed
    000: "Φ = m·a_S = m·(πs)·μa"). With precision 0 they are the closed form's to ~1e-9."""
    mech, kin = ks.mech, ks.kin
    plan = next(q.acceleration for q in accel.positions if q.acceleration is not None)
    out: dict[str, Inertia] = {}
    for name, link in mech.links.items():
        m, inertia = link.mass or 0.0, link.inertia or 0.0
        if not m and not inertia:
            continue
        com = link.com or next(iter(link.local))
        body = kin.bodies[name]
        exact_a, exact_eps = complex(body.at(link.local[com])[2][0]), float(body.eps[0])
        e = plan.entries.get(com)
        read = e is not None and e.kind == "point"
        if read:
            a = e.value * e.vector / abs(e.vector) if e.value and e.vector else 0j
        else:
            a = exact_a
        eps = plan.rates.get(name)
        out[name] = Inertia(name, com, m, inertia, e.mm if read else None, complex(a),
                            float(exact_eps if eps is None else eps), exact_a, exact_eps,
                            "plan" if read and eps is not None else "exact")
    return out


def drawn_loads(ks: Kinetostatics, inertia: dict[str, Inertia]) -> list:
    """``ks``'s loads with each inertia force and couple the plan's (``plan_inertia``); the weights and
    the external forces as they are."""
    from dataclasses import replace
    out = []
    for ld in ks.loads:
        i = inertia.get(ld.link)
        if i is not None and ld.kind == "inertia":
            ld = replace(ld, force=np.array([i.force]))
        elif i is not None and ld.kind == "couple":
            ld = replace(ld, couple=np.array([i.couple]))
        out.append(ld)
    return out


def construct(st: Study, phi_deg: float, precision: float = DEFAULT_PRECISION,
              mu_l: float | None = None, mu_F: float | None = None,
              mu_v: float | None = None, group_mu: dict[str, float] | None = None,
              group_mu_F: dict[str, float] | None = None, mu_a: float | None = None,
              count: int | None = None, accel=None) -> ForcePlans:
    """The force plans of every group, the crank's balancing moment and the lever at one angle.
    Every group is drawn (and its arms measured) at ``mu_l``, a group named in ``group_mu`` (label →
    m/mm) at its own scale — the force sheet draws a small group (the crank's) larger where its cell
    has room (sheets.forces); likewise each force plan at ``mu_F`` or its own ``group_mu_F`` (label →
    N/mm: a group whose forces are small drawn at a finer μF where its cell has room).
    The inertia loads Φ = −m·a_S and M^Φ = −I_S·ε are read off the force position's acceleration
    plan (``accel``, else drawn here as the force sheet draws it: ``acceleration_plan`` at ``mu_a``
    over ``count`` positions) — the draftsman's own, as the lab takes them; the closed form
    (``ks``) is the truth they and every reaction are compared with."""
    phi = float(phi_deg) % 360.0
    ks = analyse(st, [phi])
    mu_l = mu_l or mechanism_scale(st)
    mu_F = mu_F or force_scale(ks)
    if accel is None:
        accel = acceleration_plan(st, phi, count, precision, mu_a)
    inertia = plan_inertia(ks, accel)
    loads = drawn_loads(ks, inertia)
    plans = _Plans(ks, precision, mu_l, mu_F, loads)
    scales = dict(group_mu or {})
    forces = dict(group_mu_F or {})
    for gf in ks.groups:
        if gf.dyad is not None:
            plans.d.mu_l = scales.get(gf.label, mu_l)
            plans.d.mu_F = forces.get(gf.label, mu_F)
            plans.group(gf)
    plans.d.mu_l = scales.get(CRANK_LABEL, mu_l)
    plans.d.mu_F = forces.get(CRANK_LABEL, mu_F)
    m_b, arm = plans.crank()
    return ForcePlans(ks, phi, precision, mu_l, mu_F, plans.groups, m_b, arm, lever(ks, precision, mu_v, loads),
                      inertia=inertia, loads=loads, mu_a=accel.mu_a)



def acceleration_plan(st: Study, phi_deg: float, count: int | None = None, precision: float = DEFAULT_PRECISION,
                      mu_a: float | None = None):
    """The plans the force sheet draws at the force position ``phi_deg``: its position, velocity and
    acceleration plans only — at the scales ``graphic.plans.build_plans(st, count, accel=[phi_deg])``
    chooses (μl and μv from the exact solution over all ``count`` positions, vectorised), keyed and
    measured as there, so the drawing is the same while the work no longer grows with the count."""
    from graphplan.graphic import plans as gp
    from graphplan.util.errors import GraphplanError
    n = count or st.mech.task.count
    if not 2 <= n <= 3600:
        raise GraphplanError(f"--positions must be from 2 to 3600, got {n}")
    targets = gp.Targets()
    phis = np.asarray(st.positions(n), dtype=float)
    accel_idx, extra = gp.resolve_accel(st, phis, [phi_deg])
    all_phi = np.concatenate([phis, np.asarray(extra, dtype=float)])
    kin = st.solve(all_phi)
    acc_keys = accel_idx + list(range(n, n + len(extra)))
    ml, mv, ma = gp.choose_scales(st, kin, all_phi, acc_keys, targets, None, None, mu_a)
    sc = gp.Scheme(st)
    results = []
    for key in acc_keys:                       # one key: the force position (on a position or extra)
        phi = float(all_phi[key])
        lay = gp.construct_position(sc, phi, ml, key, key if key < n else None)
        exact = gp.Exact(kin, key)
        vel = gp.VelocityPlan(sc, lay, exact, mv, precision)
        _draw(vel, st)
        acc = gp.AccelerationPlan(sc, lay, exact, ma, precision, vel)
        _draw(acc, st)
        results.append(gp.PositionPlans(key, key if key < n else None, phi, lay, vel, acc,
                                        vel.warnings + acc.warnings))
    return gp.Plans(st, sc, n, float(precision), ml, mv, ma, targets, results, [], ())


def _draw(plan, st: Study) -> None:
    """A velocity or acceleration plan drawn from the crank, group by group, and finished."""
    plan.crank()
    for d in st.structure.dyads:
        plan.group(d)
    plan.finish()


@dataclass(frozen=True)
class SlideArm:
    """Where a sliding pair's reaction acts on its slider (the yoke's R03, a slider's R03): its
    line's distance h from the pair's point along the guide, from the slider's ΣM = 0 with the arms
    measured (``h_mm`` at the group's μl, ``value`` m) against the closed form's (``analytic``, m:
    ``Reaction.line_point``, h = M/(g × R))."""
    key: str
    point: str
    group: str
    h_mm: float
    value: float
    analytic: float
    error_pct: float | None
    link: int = 0        # the number of the link it acts on (3: the yoke)


def slide_arms(fp: ForcePlans) -> list[SlideArm]:
    """The arm of every sliding pair's reaction found on a group (the RPP group's R03 from ΣM = 0 of
    the yoke, the RRP group's R03 from the slider's), graphical and exact."""
    out = []
    for gp in fp.groups:
        mu = gp.mu_l or fp.mu_l
        for key, m in gp.reactions.items():
            r = fp.ks.reactions[key]
            if m.line is None or r.guide is None or m.value == 0:
                continue
            g, at = complex(r.guide[0]), complex(r.at[0])
            h = float(dot(m.line - at, g))
            exact = float(dot(complex(r.line_point()[0]) - at, g))
            if abs(h) < 1e-9 and abs(exact) < 1e-9:      # through the pair's point (a slider's R03 at B)
                continue
            out.append(SlideArm(key, r.point, gp.label, h / mu, h, exact, error_pct(h, exact, mu),
                                number(fp.ks.mech, r.on)))
    return out
