"""Kinetostatics (seeds 000 §2.5–2.6, 003): loads, reactions in every pair, the balancing moment.

d'Alembert: each moving link is in equilibrium under its gravity G = m·g, its inertia force
Φ = −m·a_S (at the centre of mass S), its inertia couple M_Φ = −I_S·ε, the external forces and the
reactions of its pairs (no friction: a revolute pair's reaction passes through the joint, a
sliding pair's reaction is normal to the guide). The groups are solved from the last Assur group
back to the crank, each in closed form (vectorised over crank angles) by the moment equations and
one 2×2 system ``x·u + y·w = rhs`` (``kinematics.solve2``) for the force sum:

* RRR: τ_a = M_a(C)/l_a, τ_b = M_b(C)/l_b (moments about the inner joint C), then
  n_a·u_a + n_b·u_b = −(ΣF + τ_a·iu_a + τ_b·iu_b);
* RRP: τ_a as above, then n_a·u_a + N·n_g = −(ΣF + τ_a·iu_a);
* RPR: along the guide the block's reaction is −F_s·d, across it from the group's moment about
  the rocker's pivot; the rocker's pivot reaction closes the sum;
* PRP: N_a·n_a + N_b·n_b = −ΣF;
* RPP: the yoke's equilibrium along its guide gives the block–yoke force, the rest closes.

The crank then gives the pivot reaction R01 and the balancing moment M_b = −ΣM_O (+ counter-
clockwise). Checks: power balance M_b·ω1 + Σ F·v + Σ M·ω = 0, and the Zhukovsky lever (the velocity
plan turned 90°, every force at its point's image, moments about the pole) — the same identity read
off a drawing. Complex numbers x + iy are vectors throughout; cross(u, w) = Im(ū·w).
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from graphplan.util.errors import GraphplanError, SceneError, keyed_error, said_error
from graphplan.util.words import Fixed
from graphplan.exact.kinematics import Kinematics, cross, dot, solve, solve2
from graphplan.model.mechanism import FRAME, Mechanism
from graphplan.exact.positions import Study, working_start
from graphplan.model.structure import Dyad, Pair

Array = np.ndarray


@dataclass
class Load:
    """An applied force (at ``at``) or couple on a link: gravity, inertia or an external force."""
    name: str            # G3, Φ3 (inertia force), MΦ3 (inertia couple), P_C (external)
    link: str
    kind: str            # "gravity", "inertia", "couple", "external"
    point: str | None    # the point it acts at (the centre of mass for G and Φ)
    at: Array            # complex position of that point (a couple: the link's centre of mass)
    force: Array         # complex, N (0 for a couple)
    couple: Array        # N·m, + counter-clockwise (0 for a force)
    velocity: Array      # velocity of the point (complex)
    omega: Array         # angular velocity of the link

    @property
    def power(self) -> Array:
        """P = F·v + M·ω."""
        return dot(self.force, self.velocity) + self.couple * self.omega


@dataclass
class Action:
    """Something acting on one link: a force at a point plus a couple (reactions of sliding pairs
    carry a couple: their line of action is off the pair's reference point)."""
    name: str
    at: Array
    force: Array
    couple: Array


@dataclass
class Reaction:
    """The reaction in a pair: the force on ``on`` from ``frm`` (``key`` = R<frm><on> by link
    numbers, frame 0; the lower number first). A sliding pair's force is normal to its guide and
    acts on the line through ``at`` shifted along the guide by ``couple``/(g × F)."""
    key: str
    kind: str            # "R" or "P"
    frm: str
    on: str
    point: str
    at: Array
    force: Array
    couple: Array
    group: str           # the group whose equilibrium gave it ("I(0-1)" for the crank's pivot)
    guide: Array | None = None   # unit direction of the guide (sliding pairs)

    def line_point(self) -> Array:
        """A point on the reaction's line of action: the joint, or for a sliding pair the
        reference point moved along the guide by h = M/(g × F)."""
        if self.guide is None:
            return self.at
        c = cross(self.guide, self.force)
        big = np.abs(self.force) > 1e-12 * max(1.0, float(np.max(np.abs(self.force), initial=0.0)))
        h = np.where(big, self.couple / np.where(big, c, 1.0), 0.0)
        return self.at + h * self.guide

    def on_body(self, body: str) -> Action:
        """The reaction as it acts on ``body`` (one of the pair's two bodies)."""
        if body == self.on:
            return Action(self.key, self.at, self.force, self.couple)
        if body == self.frm:
            return Action(self.key, self.at, -self.force, -self.couple)
        raise KeyError(body)


@dataclass
class GroupForces:
    """One group of the force analysis: its label, kind, links and the reactions found in it."""
    label: str
    kind: str
    links: tuple[str, ...]
    reactions: tuple[str, ...]   # keys, in the order outer a, inner, outer b (crank: R01)
    dyad: Dyad | None = None


@dataclass
class Kinetostatics:
    """The force analysis at crank angles ``phi_deg`` (arrays over those angles)."""
    st: Study
    kin: Kinematics
    phi_deg: Array
    working: Array                      # True on the working stroke
    loads: list[Load]
    reactions: dict[str, Reaction]
    groups: list[GroupForces]           # last group first, the crank last
    balancing: Array                    # M_b from the crank's equilibrium, N·m, + ccw
    balancing_force: Array = field(default=None)  # P_b = M_b / l_OA (⊥ OA at the crank pin), N

    @property
    def mech(self) -> Mechanism:
        return self.st.mech

    def power(self) -> Array:
        """Power balance: M_b = −(Σ F·v + Σ M·ω)/ω1."""
        total = sum((ld.power for ld in self.loads), np.zeros_like(self.phi_deg))
        return -total / self.mech.omega1

    def lever(self) -> Array:
        """The Zhukovsky lever, exact: the velocity plan (μv = 1) turned 90° counter-clockwise;
        each force at its point's image pv ↦ i·v, moments about the pole; a couple M on a link
        becomes the moment −M·ω (the couple's force pair at the link's images). The lever is in
        equilibrium with the balancing force at the crank pin's image: M_b = ΣM_lever/ω1."""
        total = np.zeros_like(self.phi_deg)
        for ld in self.loads:
            total = total + cross(1j * ld.velocity, ld.force) - ld.couple * ld.omega
        return total / self.mech.omega1

    def inertia(self) -> dict[str, dict[str, Array]]:
        """Per centre of mass: |Φ| (N) and M_Φ (N·m, + ccw)."""
        out: dict[str, dict[str, Array]] = {}
        for link_name, link in self.mech.links.items():
            phi = [ld for ld in self.loads if ld.link == link_name and ld.kind == "inertia"]
            mom = [ld for ld in self.loads if ld.link == link_name and ld.kind == "couple"]
            if not phi and not mom:
                continue
            key = link.com or f"S{link.number}"
            zero = np.zeros_like(self.phi_deg)
            out[key] = {"force": np.abs(phi[0].force) if phi else zero,
                        "angle": np.angle(phi[0].force) if phi else zero,
                        "moment": mom[0].couple if mom else zero, "link": link_name}
        return out


# -- naming -------------------------------------------------------------------------------------

def number(mech: Mechanism, body: str) -> int:
    """The link's number (the frame is 0)."""
    return 0 if body == FRAME else mech.links[body].number


def reaction_key(mech: Mechanism, frm: str, on: str) -> str:
    """R<from><to> by link numbers, e.g. R03, R12; R10-11 once a number has two digits."""
    a, b = number(mech, frm), number(mech, on)
    return f"R{a}{'-' if max(a, b) >= 10 else ''}{b}"


# -- strokes and loads --------------------------------------------------------------------------

def working_stroke(st: Study, phi_deg: Array) -> Array:
    """True where the crank is on the working stroke of the output. The output's extreme
    positions split the turn into two strokes; the scene's ``positions.working_stroke`` names the
    working one: "slow" (default: the longer crank turn), "fast", "to_min" or "to_max" (the output
    moving toward its smallest or largest value). An extreme belongs to the stroke it begins. An
    output without extremes is always on its working stroke."""
    phi = np.asarray(phi_deg, dtype=float)
    if len(st.extremes) < 2:
        return np.ones(phi.shape, dtype=bool)
    kin = solve(st.mech, st.structure, list(st.extremes))
    start, length = working_start(st.mech, st.extremes, st.output.value(kin))
    sense = np.sign(st.mech.omega1)
    return ((phi - start) * sense) % 360.0 < length       # from the stroke's first extreme, its turn


def own_stroke(st: Study, point: str) -> tuple[float, float] | None:
    """The working stroke (the crank angle of its first extreme, its crank turn in the crank's sense,
    deg) of a force's own slide when that is not the output's: a piston on a frame guide of its own
    whose dead centres are not the output's (stop 58: a V-twin compressor's piston C, its guide 60°
    from B's, has its dead centres 60° of crank turn from B's — its gas force on B's working stroke
    acted over C's suction half and back). The scene's ``positions.working_stroke`` rule read on that
    slide's own coordinate. None where the force takes the output's stroke: the output's own point,
    a point that slides on no frame guide, or a slide whose working stroke is the output's (an
    opposed twin's second piston, its dead centres the first's, works while the first is idle: its own)."""
    from graphplan.exact.positions import Output, find_extremes, point_slider
    mech = st.mech
    if st.output.kind == "slide" and st.output.name == point:
        return None
    # (a Study made from another by dataclasses.replace shares its memo: keyed by what the stroke reads)
    key = ("own stroke", point, mech.working_stroke, st.extremes, tuple(sorted(mech.frame.items())),
           mech.crank.length)
    if key in st.memo:
        return st.memo[key]
    out = None
    slider = point_slider(mech, point)
    if slider is not None and mech.guides[mech.links[slider].slides_on].body == FRAME:
        own = Output("slide", point)
        ext = find_extremes(mech, st.structure, own)
        if len(ext) >= 2:
            out = working_start(mech, ext, own.value(solve(mech, st.structure, list(ext))))
            if len(st.extremes) >= 2:       # the very stroke the output's is: the output's
                start, length = working_start(mech, st.extremes, st.output.value(solve(mech, st.structure,
                                                                                      list(st.extremes))))
                if abs((out[0] - start + 180.0) % 360.0 - 180.0) < 1e-6 and abs(out[1] - length) < 1e-6:
                    out = None
    st.memo[key] = out
    return out


def force_working(st: Study, point: str, phi_deg: Array, working: Array) -> Array:
    """Where a force at ``point`` is on its working stroke: its own slide's (``own_stroke``), else
    the output's (``working``)."""
    own = own_stroke(st, point)
    if own is None:
        return working
    start, length = own
    return ((np.asarray(phi_deg, dtype=float) - start) * np.sign(st.mech.omega1)) % 360.0 < length


def force_link(mech: Mechanism, point: str) -> str:
    """The link an external force at ``point`` acts on: the slider that carries the point (one on a
    frame guide first) — the ram, not the rod, for a force at their common joint, and not the rod of
    the next group hinged there too — else the last link (in the scene's order) that carries it."""
    holders = [b for b in mech.bodies_of(point) if b != FRAME]
    if not holders:
        raise keyed_error(GraphplanError, mech.source, "force.point", "ks frame force", mech.task.meta.get("lang"),
                          name=repr(point))
    sliders = [b for b in holders if mech.links[b].slides_on is not None]
    framed = [b for b in sliders if mech.guides[mech.links[b].slides_on].body == FRAME]
    return (framed or sliders or holders)[-1]


def _motion_direction(st: Study, link: str, local: complex, phi: Array, v: Array) -> Array:
    """Unit vector of a point's velocity; where the point stands still (an extreme position),
    the direction it starts moving in as the crank turns on."""
    speed = np.abs(v)
    scale = abs(st.mech.omega1) * st.mech.crank.length
    still = speed <= 1e-9 * scale
    out = np.where(still, 0j, v / np.where(still, 1.0, speed))
    if np.any(still):
        step = 1e-4 * np.sign(st.mech.omega1)
        kin = solve(st.mech, st.structure, phi[still] + step)
        vn = kin.bodies[link].at(local)[1]
        out[still] = vn / np.maximum(np.abs(vn), 1e-300)
    return out


def output_distance(st: Study, kin: Kinematics) -> Array:
    """The output's distance from position 0: |s − s0| (m) for a slide, |θ − θ0| (deg) for a rocker."""
    out = st.output
    if out.kind == "slide":
        return np.abs(kin.slides[out.name].t - st.t0[out.name])
    theta0 = solve(st.mech, st.structure, [st.phi0]).bodies[out.name].theta[0]
    turn = np.angle(np.exp(1j * (kin.bodies[out.name].theta - theta0)))
    return np.abs(np.degrees(turn))


def _profile(st: Study, kin: Kinematics, profile: tuple[tuple[float, float], ...]) -> Array:
    """The profile's factor at the output's distance from position 0 (linear between the given
    points, the end values beyond them)."""
    xs, fs = zip(*profile)
    return np.interp(output_distance(st, kin), xs, fs)


def loads(st: Study, kin: Kinematics, working: Array) -> list[Load]:
    """G = m·g (down, −y), Φ = −m·a_S at S, M_Φ = −I_S·ε, and the scene's external forces
    (on their stroke, scaled by their profile over the output's distance from position 0;
    "oppose" = against the point's velocity). A link with a mass but no centre
    of mass point carries its loads at its first point."""
    mech = st.mech
    zero = np.zeros(kin.phi_deg.shape)
    out: list[Load] = []
    for name, link in mech.links.items():
        body = kin.bodies[name]
        com = link.com or next(iter(link.local))
        x, v, a = body.at(link.local[com])
        m, inertia = link.mass or 0.0, link.inertia or 0.0
        n = link.number
        if m:
            out.append(Load(f"G{n}", name, "gravity", com, x, zero - 1j * m * mech.g, zero, v, body.omega))
            out.append(Load(f"Φ{n}", name, "inertia", com, x, -m * a, zero, v, body.omega))
        if inertia:
            out.append(Load(f"MΦ{n}", name, "couple", None, x, zero + 0j, -inertia * body.eps, v, body.omega))
    for f in mech.forces:
        name = force_link(mech, f.point)
        local = mech.links[name].local[f.point]
        body = kin.bodies[name]
        x, v, _ = body.at(local)
        if f.stroke == "both":
            active = np.ones(zero.shape, dtype=bool)
        else:
            mine = force_working(st, f.point, kin.phi_deg, working)
            active = mine if f.stroke == "working" else ~mine
        if f.direction == "oppose":
            unit = -_motion_direction(st, name, local, kin.phi_deg, v)
        else:
            unit = np.exp(1j * np.radians(float(f.direction))) + 0 * zero
        magnitude = f.magnitude * (_profile(st, kin, f.profile) if f.profile else 1.0)
        force = np.where(active, magnitude * unit, 0j)
        out.append(Load(f"P_{f.point}", name, "external", f.point, x, force, zero, v, body.omega))
    for m in mech.moments:
        link = mech.links[m.link]
        body = kin.bodies[m.link]
        x, v, _ = body.at(link.local[link.com or next(iter(link.local))])
        active = np.ones(zero.shape, dtype=bool) if m.stroke == "both" else (
            working if m.stroke == "working" else ~working)
        sense = -_turn_sense(st, m.link, kin.phi_deg, body.omega) if m.direction == "oppose" else (
            zero + (1.0 if m.direction == "ccw" else -1.0))
        magnitude = m.magnitude * (_profile(st, kin, m.profile) if m.profile else 1.0)
        out.append(Load(f"M_{link.number}", m.link, "external", None, x, zero + 0j,
                        np.where(active, magnitude * sense, 0.0), v, body.omega))
    return out


def _turn_sense(st: Study, link: str, phi: Array, omega: Array) -> Array:
    """+1 where the link turns counter-clockwise, −1 clockwise; where it stands still (a rocker's
    extreme position), the sense it starts turning in as the crank turns on."""
    still = np.abs(omega) <= 1e-9 * abs(st.mech.omega1)
    out = np.sign(np.where(still, 1.0, omega))
    if np.any(still):
        step = 1e-4 * np.sign(st.mech.omega1)
        ahead = solve(st.mech, st.structure, phi[still] + step).bodies[link].omega
        out[still] = np.where(ahead >= 0, 1.0, -1.0)
    return out


# -- the group-by-group solution ----------------------------------------------------------------

class _Solver:
    """Keeps what acts on each link while the groups are solved from the last to the crank."""

    def __init__(self, st: Study, kin: Kinematics, load_list: list[Load]):
        self.st, self.kin, self.mech = st, kin, st.mech
        self.zero = np.zeros(kin.phi_deg.shape)
        self.acting: dict[str, list[Action]] = {name: [] for name in self.mech.links}
        for ld in load_list:
            self.acting[ld.link].append(Action(ld.name, ld.at, ld.force, ld.couple))
        self.reactions: dict[str, Reaction] = {}

    # resultants of what is known to act on a link
    def force(self, link: str) -> Array:
        return sum((a.force for a in self.acting[link]), self.zero + 0j)

    def moment(self, link: str, about: Array) -> Array:
        """ΣM about a point: couples + (x − P) × F."""
        return sum((a.couple + cross(a.at - about, a.force) for a in self.acting[link]), self.zero)

    # pair geometry
    def at(self, pair: Pair) -> Array:
        body = pair.slider if pair.kind == "P" else next(b for b in pair.bodies if b != FRAME)
        return self.kin.bodies[body].at(self.mech.links[body].local[pair.point])[0]

    def guide(self, pair: Pair) -> Array:
        g = self.mech.guides[pair.guide]
        return np.exp(1j * (self.kin.bodies[g.body].theta + g.angle))

    def found(self, pair: Pair, on: str, force: Array, couple: Array | None, group: str) -> str:
        """Store the reaction on ``on`` (a link of the group) from its partner in ``pair``."""
        frm = pair.other(on)
        at = self.at(pair)
        couple = self.zero if couple is None else couple
        guide = self.guide(pair) if pair.kind == "P" else None
        if number(self.mech, frm) > number(self.mech, on):
            frm, on, force, couple = on, frm, -force, -couple
        key = reaction_key(self.mech, frm, on)
        if key in self.reactions:
            key = f"{key}:{pair.point}"
        self.reactions[key] = Reaction(key, pair.kind, frm, on, pair.point, at, force, couple, group, guide)
        return key

    def transfer(self, keys: list[str], group_links: tuple[str, ...]) -> None:
        """The group's reactions act back (−R) on the links it is attached to."""
        for key in keys:
            r = self.reactions[key]
            for body in (r.frm, r.on):
                if body != FRAME and body not in group_links:
                    self.acting[body].append(r.on_body(body))


def _rrr(s: _Solver, d: Dyad) -> list[str]:
    """τ from the moments about C; n_a, n_b from the force polygon (2×2)."""
    p1, c, p3 = s.at(d.outer_a), s.at(d.inner), s.at(d.outer_b)
    la, lb = np.abs(c - p1), np.abs(c - p3)
    ua, ub = (c - p1) / la, (c - p3) / lb
    ta, tb = s.moment(d.a, c) / la, s.moment(d.b, c) / lb
    fa, fb = s.force(d.a), s.force(d.b)
    na, nb = solve2(ua, ub, -(fa + fb + 1j * ta * ua + 1j * tb * ub))
    ra, rb = (na + 1j * ta) * ua, (nb + 1j * tb) * ub
    return [s.found(d.outer_a, d.a, ra, None, d.label),
            s.found(d.inner, d.b, -(fb + rb), None, d.label),
            s.found(d.outer_b, d.b, rb, None, d.label)]


def _rrp(s: _Solver, d: Dyad) -> list[str]:
    """τ_a from the moment of a about C; n_a and the guide's N from the polygon (2×2); the slider's
    couple (its reaction's offset along the guide) from its moment about C."""
    p1, c, xb = s.at(d.outer_a), s.at(d.inner), s.at(d.outer_b)
    la = np.abs(c - p1)
    ua = (c - p1) / la
    ng = 1j * s.guide(d.outer_b)
    ta = s.moment(d.a, c) / la
    fa, fb = s.force(d.a), s.force(d.b)
    na, big_n = solve2(ua, ng, -(fa + fb + 1j * ta * ua))
    rb = big_n * ng
    couple_b = -(s.moment(d.b, c) + cross(xb - c, rb))
    return [s.found(d.outer_a, d.a, (na + 1j * ta) * ua, None, d.label),
            s.found(d.inner, d.b, -(fb + rb), None, d.label),
            s.found(d.outer_b, d.b, rb, couple_b, d.label)]


def _rpr(s: _Solver, d: Dyad) -> list[str]:
    """Slotted link: the block's pin force along the guide is −F_s·d; across it, from the group's
    moment about the rocker's pivot; then the block's normal force and the pivot's reaction."""
    slider, carrier, outer_s, outer_c = d.block_parts
    ps, pc, x_in = s.at(outer_s), s.at(outer_c), s.at(d.inner)
    g = s.guide(d.inner)
    n = 1j * g
    fs, fc = s.force(slider), s.force(carrier)
    rho = ps - pc
    r_along = -dot(fs, g)
    r_across = -(s.moment(slider, pc) + s.moment(carrier, pc) + r_along * cross(rho, g)) / dot(rho, g)
    r_s = r_along * g + r_across * n
    big_n = -(r_across + dot(fs, n))
    couple = -(s.moment(slider, ps) + cross(x_in - ps, big_n * n))
    keys = [s.found(outer_s, slider, r_s, None, d.label),
            s.found(d.inner, slider, big_n * n, couple, d.label),
            s.found(outer_c, carrier, big_n * n - fc, None, d.label)]
    return keys if slider == d.a else keys[::-1]


def _prp(s: _Solver, d: Dyad) -> list[str]:
    """Two guides: N_a·n_a + N_b·n_b = −ΣF (2×2); couples from the moments about C."""
    c, xa, xb = s.at(d.inner), s.at(d.outer_a), s.at(d.outer_b)
    na_, nb_ = 1j * s.guide(d.outer_a), 1j * s.guide(d.outer_b)
    fa, fb = s.force(d.a), s.force(d.b)
    big_a, big_b = solve2(na_, nb_, -(fa + fb))
    ra, rb = big_a * na_, big_b * nb_
    return [s.found(d.outer_a, d.a, ra, -(s.moment(d.a, c) + cross(xa - c, ra)), d.label),
            s.found(d.inner, d.b, -(fb + rb), None, d.label),
            s.found(d.outer_b, d.b, rb, -(s.moment(d.b, c) + cross(xb - c, rb)), d.label)]


def _rpp(s: _Solver, d: Dyad) -> list[str]:
    """Block a in yoke b: the yoke's equilibrium along its guide gives the block–yoke force N·n_in;
    the block's pin reaction and the yoke's guide force close the sums; couples from moments."""
    pa, x_in, xb = s.at(d.outer_a), s.at(d.inner), s.at(d.outer_b)
    n_in = 1j * s.guide(d.inner)
    g = s.guide(d.outer_b)
    fa, fb = s.force(d.a), s.force(d.b)
    big_in = dot(fb, g) / dot(n_in, g)
    r_in = big_in * n_in                                   # on the block a from the yoke b
    c_in = -(s.moment(d.a, pa) + cross(x_in - pa, r_in))
    r_b = -(fb - r_in)                                     # on the yoke from its guide
    c_b = -(s.moment(d.b, xb) - c_in - cross(x_in - xb, r_in))
    return [s.found(d.outer_a, d.a, -(fa + r_in), None, d.label),
            s.found(d.inner, d.a, r_in, c_in, d.label),
            s.found(d.outer_b, d.b, r_b, c_b, d.label)]


_GROUPS = {"RRR": _rrr, "RRP": _rrp, "RPR": _rpr, "PRP": _prp, "RPP": _rpp}
CRANK_LABEL = "I(0-1)"


def analyse(st: Study, phi_deg: Array | list[float] | float) -> Kinetostatics:
    """Loads, reactions of every pair and the balancing moment at the given crank angles (deg)."""
    phi = np.atleast_1d(np.asarray(phi_deg, dtype=float))
    kin = st.solve(phi)
    working = working_stroke(st, phi)
    load_list = loads(st, kin, working)
    s = _Solver(st, kin, load_list)
    groups: list[GroupForces] = []
    with np.errstate(all="ignore"):
        for d in reversed(st.structure.dyads):
            keys = _GROUPS[d.kind](s, d)
            s.transfer(keys, (d.a, d.b))
            groups.append(GroupForces(d.label, d.kind, (d.a, d.b), tuple(keys), d))
            _finite(st, phi, d.label, [s.reactions[k].force for k in keys])
        mech = st.mech
        crank = mech.crank.link
        pivot = kin.point(mech.crank.pivot)[0]
        pair = Pair("R", (crank, FRAME), mech.crank.pivot)
        key = s.found(pair, crank, -s.force(crank), None, CRANK_LABEL)
        groups.append(GroupForces(CRANK_LABEL, "crank", (crank,), (key,)))
        m_b = -s.moment(crank, pivot)
    _finite(st, phi, CRANK_LABEL, [s.reactions[key].force, m_b])
    return Kinetostatics(st, kin, phi, working, load_list, s.reactions, groups, m_b,
                         m_b / mech.crank.length)


def _finite(st: Study, phi: Array, group: str, arrays: list[Array]) -> None:
    """A group's reactions must be finite (an overflow of huge loads, a near-singular group): the
    named error with the group and the first crank angle, never NaN passed on to a table or JSON."""
    ok = np.ones(phi.shape, dtype=bool)
    for arr in arrays:
        ok &= np.isfinite(np.broadcast_to(arr, phi.shape))
    if not np.all(ok):
        raise said_error(SceneError, "ks not finite", st.mech.source, st.mech.task.meta.get("lang"), group=group,
                         phi=Fixed(float(phi[~ok][0]), 2))


def at_scene_angle(st: Study) -> float:
    """The crank angle of the force analysis (deg from +x): the scene's positions.force_phi_deg
    (degrees of crank turn from position 0), else position 1."""
    if st.mech.task.force_phi is not None:
        return float((st.phi0 + np.sign(st.mech.omega1) * st.mech.task.force_phi) % 360.0)
    return float(st.positions()[1])


def full_turn(st: Study, count: int = 360) -> Kinetostatics:
    """The force analysis at ``count`` crank angles from position 0 over one turn."""
    return analyse(st, st.positions(count))
