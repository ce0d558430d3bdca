"""The exact analytic solver: closed-form vector loops, vectorised over crank angles (numpy).

Every body's motion is kept as the position, velocity and acceleration of its origin plus its
angle θ, angular velocity ω and angular acceleration ε, so a point fixed at local ``p`` has

    r = p·e^{iθ},  x = O + r,  v = v_O + iω·r,  a = a_O + (iε − ω²)·r          (complex numbers)

Each class-II dyad reduces to one 2×2 real system  x·u + y·w = rhs  (``solve2``) for the velocity
unknowns and the same matrix for the acceleration unknowns; positions come in closed form
(circle ∩ circle, circle ∩ line, line through a pivot, line ∩ line).
"""
from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property

import numpy as np

from graphplan.util.errors import SceneError, said_error
from graphplan.util.words import pair_kind, word
from graphplan.model.mechanism import FRAME, Mechanism
from graphplan.model.structure import Dyad, Structure

Array = np.ndarray


def cross(u: Array | complex, w: Array | complex) -> Array:
    """z-component of u × w for complex vectors: Im(conj(u)·w) = u_x·w_y − u_y·w_x."""
    return np.real(u) * np.imag(w) - np.imag(u) * np.real(w)


def dot(u: Array | complex, w: Array | complex) -> Array:
    return np.real(u) * np.real(w) + np.imag(u) * np.imag(w)


class System2:
    """x·u + y·w = rhs for real x, y (Cramer): x = (rhs × w)/(u × w), y = (u × rhs)/(u × w).

    The velocity and the acceleration of a dyad share u, w (the same directions on both plans)."""

    def __init__(self, u: Array | complex, w: Array | complex):
        self.u, self.w = u, w
        self.det = cross(u, w)

    def __call__(self, rhs: Array | complex) -> tuple[Array, Array]:
        return cross(rhs, self.w) / self.det, cross(self.u, rhs) / self.det


def solve2(u: Array | complex, w: Array | complex, rhs: Array | complex) -> tuple[Array, Array]:
    """Real x, y with x·u + y·w = rhs."""
    return System2(u, w)(rhs)


@dataclass
class Body:
    """Motion of a rigid body: origin O (position, velocity, acceleration), its turn e^{iθ}, ω, ε."""
    origin: Array
    vo: Array
    ao: Array
    turn: Array
    omega: Array
    eps: Array

    @property
    def theta(self) -> Array:
        """θ in (−π, π]."""
        return np.angle(self.turn)

    @cached_property
    def _iw(self) -> Array:
        return 1j * self.omega

    @cached_property
    def _k(self) -> Array:
        """iε − ω²: r ↦ the acceleration of a point at r relative to the origin."""
        return 1j * self.eps - self.omega * self.omega

    def at(self, p: complex) -> tuple[Array, Array, Array]:
        """Position, velocity, acceleration of the body's point at local ``p``."""
        if p == 0:
            return self.origin, self.vo, self.ao
        r = p * self.turn
        return self.origin + r, self.vo + self._iw * r, self.ao + self._k * r

    def coincident(self, x: Array) -> tuple[Array, Array]:
        """Velocity and acceleration of the body's point that is at ``x`` now (for slides)."""
        r = x - self.origin
        return self.vo + self._iw * r, self.ao + self._k * r


def place(p: complex, x: Array, v: Array, a: Array, turn: Array, omega: Array, eps: Array) -> Body:
    """The body whose local point ``p`` moves as (x, v, a) while the body turns as (e^{iθ}, ω, ε)."""
    if p == 0:
        return Body(x, v, a, turn, omega, eps)
    r = p * turn
    return Body(x - r, v - 1j * omega * r, a - (1j * eps - omega ** 2) * r, turn, omega, eps)



@dataclass
class Slide:
    """Relative motion in a sliding pair: coordinate t along the guide g, its rates, and the
    Coriolis acceleration 2·ω_guide × v_rel (a vector: v_rel turned 90° in the sense of ω)."""
    slider: str
    carrier: str
    point: str
    t: Array
    v: Array
    a: Array
    direction: Array
    omega: Array  # the guide's (carrier's) angular velocity

    @cached_property
    def coriolis(self) -> Array:
        """a^k = 2iω·v_rel·g: v_rel turned 90° in the sense of ω, magnitude 2|ω·v_rel|."""
        return 2j * self.omega * self.v * self.direction

    @property
    def coriolis_magnitude(self) -> Array:
        return 2.0 * np.abs(self.omega * self.v)


@dataclass
class Kinematics:
    """The solved mechanism at crank angles ``phi_deg``."""
    mech: Mechanism
    structure: Structure
    phi_deg: Array
    bodies: dict[str, Body]
    slides: dict[str, Slide] = field(default_factory=dict)
    valid: dict[str, Array] = field(default_factory=dict)       # per dyad label: assembled
    condition: dict[str, Array] = field(default_factory=dict)   # per dyad label: |sin| of the 2×2

    def body_of(self, point: str) -> str:
        holders = self.mech.bodies_of(point)
        if not holders:
            raise said_error(SceneError, "kn no point", self.mech.source, self.mech.task.meta.get("lang"), point=point)
        return holders[-1] if holders[0] == FRAME and len(holders) == 1 else holders[0]

    def point(self, name: str) -> tuple[Array, Array, Array]:
        """Position, velocity, acceleration of a named point (complex arrays)."""
        body = self.body_of(name)
        if body == FRAME:
            x = np.full(self.phi_deg.shape, self.mech.frame[name], dtype=complex)
            return x, np.zeros_like(x), np.zeros_like(x)
        return self.bodies[body].at(self.mech.links[body].local[name])


def solve(mech: Mechanism, structure: Structure, phi_deg: Array | list[float] | float) -> Kinematics:
    """Positions, velocities and accelerations of every body at the given crank angles (deg)."""
    phi = np.atleast_1d(np.asarray(phi_deg, dtype=float))
    zero = np.zeros_like(phi)
    crank = mech.crank
    pivot = mech.frame[crank.pivot]
    theta1 = np.radians(phi)
    bodies = {
        FRAME: Body(zero + 0j, zero + 0j, zero + 0j, zero + 1 + 0j, zero, zero),
        crank.link: Body(pivot + zero, zero + 0j, zero + 0j, np.exp(1j * theta1), zero + crank.omega,
                         zero + crank.epsilon),
    }
    kin = Kinematics(mech, structure, phi, bodies)
    with np.errstate(all="ignore"):
        for dyad in structure.dyads:
            _SOLVERS[dyad.kind](kin, dyad, mech.branches.get(dyad.key, 1))
            _finite(kin, dyad)
    return kin


REACH = 1e4   # m: a body whose origin runs farther (10× the scene's coordinate bound) is nearly locked


def _finite(kin: Kinematics, dyad: Dyad) -> None:
    """Where a group's solution is not finite (a near-singular 2×2, an overflow) or throws a body
    beyond REACH (a Scotch yoke whose slot is 1e-9 rad off its guide runs 6·10⁷ m) it is not
    assembled: Study.solve names the group and the crank angle instead of passing it on."""
    ok = kin.valid.get(dyad.label, np.ones(kin.phi_deg.shape, dtype=bool))
    for name in (dyad.a, dyad.b):
        body = kin.bodies.get(name)
        if body is None:
            continue
        for arr in (body.origin, body.vo, body.ao, body.turn, body.omega, body.eps):
            ok = ok & np.isfinite(arr)
        ok = ok & (np.abs(body.origin) <= REACH)
    kin.valid[dyad.label] = ok


# -- helpers shared by the dyad solvers ------------------------------------------------------------

def _known(kin: Kinematics, body: str, point: str) -> tuple[Array, Array, Array]:
    if body == FRAME:
        x = np.full(kin.phi_deg.shape, kin.mech.frame[point], dtype=complex)
        return x, np.zeros_like(x), np.zeros_like(x)
    return kin.bodies[body].at(kin.mech.links[body].local[point])


def _line(kin: Kinematics, guide_name: str, slider: str, point: str) -> tuple[str, Array, Array, float]:
    """The line along which the slider's ``point`` runs: (carrier, a point on it, unit direction,
    the guide's angle in the carrier). Offsets of the point on the slider shift the line."""
    guide = kin.mech.guides[guide_name]
    through = guide.through + kin.mech.links[slider].local[point] * np.exp(1j * guide.angle)
    carrier = kin.bodies[guide.body]
    return guide.body, carrier.origin + through * carrier.turn, np.exp(1j * guide.angle) * carrier.turn, guide.angle


def _local_turn(kin: Kinematics, link: str, frm: str, to: str) -> complex:
    """e^{−iα} for the local direction α from ``frm`` to ``to``: world direction × this = the link's turn."""
    local = kin.mech.links[link].local
    d = local[to] - local[frm]
    return complex(np.conj(d) / abs(d))


def _distance(kin: Kinematics, link: str, p: str, q: str) -> float:
    local = kin.mech.links[link].local
    return float(abs(local[q] - local[p]))


def _slide(kin: Kinematics, key: str, slider: str, carrier: str, t: Array, v: Array, a: Array,
           g: Array) -> None:
    if key in kin.slides:
        key = f"{key}:{slider}"
    kin.slides[key] = Slide(slider, carrier, key.split(":")[0], t, v, a, g, kin.bodies[carrier].omega)


LOCKED = 1e-12  # |sin| of the angle between a group's direction lines below which it locks


def _record(kin: Kinematics, dyad: Dyad, ok: Array, condition: Array) -> None:
    """Assembled where the position exists and the velocity system is not singular (a group whose
    direction lines coincide locks: its velocities are unbounded)."""
    cond = np.abs(condition)
    kin.valid[dyad.label] = ok & np.isfinite(cond) & (cond > LOCKED)
    kin.condition[dyad.label] = cond


# -- the five dyad kinds -----------------------------------------------------------------------

def _rrr(kin: Kinematics, d: Dyad, branch: int) -> None:
    """Circle ∩ circle: |C − P1| = la, |C − P3| = lb; C left of P1→P3 for branch +1.
    v: iωa·ra − iωb·rb = v_P3 − v_P1;  a: iεa·ra − iεb·rb = a_P3 − a_P1 + ωa²·ra − ωb²·rb."""
    p1, p3, c = d.outer_a.point, d.outer_b.point, d.inner.point
    x1, v1, a1 = _known(kin, d.outer_a.other(d.a), p1)
    x3, v3, a3 = _known(kin, d.outer_b.other(d.b), p3)
    la, lb = _distance(kin, d.a, p1, c), _distance(kin, d.b, p3, c)
    span = x3 - x1
    dist = np.abs(span)
    along = (dist ** 2 + la ** 2 - lb ** 2) / (2 * dist)
    h2 = la ** 2 - along ** 2
    ok = (h2 >= 0) & (dist > 0)
    xc = x1 + (along + 1j * branch * np.sqrt(h2)) * span / dist
    ra, rb = xc - x1, xc - x3
    th_a = ra / la * _local_turn(kin, d.a, p1, c)
    th_b = rb / lb * _local_turn(kin, d.b, p3, c)
    system = System2(1j * ra, -1j * rb)
    wa, wb = system(v3 - v1)
    ea, eb = system(a3 - a1 + wa * wa * ra - wb * wb * rb)
    kin.bodies[d.a] = place(kin.mech.links[d.a].local[p1], x1, v1, a1, th_a, wa, ea)
    kin.bodies[d.b] = place(kin.mech.links[d.b].local[p3], x3, v3, a3, th_b, wb, eb)
    _record(kin, d, ok, -system.det / (la * lb))


def _rrp(kin: Kinematics, d: Dyad, branch: int) -> None:
    """Circle ∩ line: C = G + t·g, |C − P1| = la; branch +1 = C ahead of the foot of P1 along g.
    v: iωa·ra − ṫ·g = v_K(C) − v_P1;  a: iεa·ra − ẗ·g = a_K(C) + 2iω_K·ṫ·g − a_P1 + ωa²·ra."""
    p1, c = d.outer_a.point, d.inner.point
    x1, v1, a1 = _known(kin, d.outer_a.other(d.a), p1)
    if d.outer_b.slider != d.b:
        raise said_error(SceneError, "kn known slider", kin.mech.source, kin.mech.task.meta.get("lang"),
                         dyad=_named(d))
    carrier, gx, g, alpha = _line(kin, d.outer_b.guide, d.b, c)
    la = _distance(kin, d.a, p1, c)
    rel = gx - x1
    foot = -dot(g, rel)
    disc = foot ** 2 - np.abs(rel) ** 2 + la ** 2
    ok = disc >= 0
    t = foot + branch * np.sqrt(disc)
    xc = gx + t * g
    ra = xc - x1
    body_k = kin.bodies[carrier]
    vk, ak = body_k.coincident(xc)
    system = System2(1j * ra, -g)
    wa, tv = system(vk - v1)
    ea, ta = system(ak + 2j * body_k.omega * tv * g - a1 + wa * wa * ra)
    th_a = ra / la * _local_turn(kin, d.a, p1, c)
    kin.bodies[d.a] = place(kin.mech.links[d.a].local[p1], x1, v1, a1, th_a, wa, ea)
    vc, ac = v1 + 1j * wa * ra, a1 + (1j * ea - wa ** 2) * ra
    kin.bodies[d.b] = place(kin.mech.links[d.b].local[c], xc, vc, ac, body_k.turn * np.exp(1j * alpha),
                            body_k.omega, body_k.eps)
    _slide(kin, c, d.b, carrier, t, tv, ta, g)
    _record(kin, d, ok, system.det / la)


def _rpr(kin: Kinematics, d: Dyad, branch: int) -> None:
    """Slotted link: the carrier turns about Pc so its guide passes through the slider's point Ps;
    (Ps − Pc)·e^{−iθ_line} = s' + i·e, branch +1 = s' > 0 (Ps ahead of the pivot's foot).
    v: iω·(Ps − Pc) + ṫ·d = v_Ps − v_Pc;  a: iε·(Ps − Pc) + ẗ·d = a_Ps − a_Pc + ω²·(Ps − Pc) − 2iω·ṫ·d."""
    slider, carrier, outer_s, outer_c = d.block_parts
    ps, pc = outer_s.point, outer_c.point
    xs, vs, as_ = _known(kin, outer_s.other(slider), ps)
    xc, vc, ac = _known(kin, outer_c.other(carrier), pc)
    guide = kin.mech.guides[d.inner.guide]
    links = kin.mech.links
    through = guide.through + links[slider].local[ps] * np.exp(1j * guide.angle)
    offset = (through - links[carrier].local[pc]) * np.exp(-1j * guide.angle)
    along0, e = offset.real, offset.imag
    rho_v = xs - xc
    rho = np.abs(rho_v)
    ok = rho > abs(e)
    sin_b = e / rho                                   # β: the slot's line turned from Ps − Pc
    cos_b = branch * np.sqrt(1.0 - sin_b ** 2)
    line = rho_v / rho * (cos_b - 1j * sin_b)         # e^{i(ψ − β)}
    t = rho * cos_b - along0
    system = System2(1j * rho_v, line)
    w, tv = system(vs - vc)
    eps, ta = system(as_ - ac + w * w * rho_v - 2j * w * tv * line)
    kin.bodies[carrier] = place(links[carrier].local[pc], xc, vc, ac, line * np.exp(-1j * guide.angle), w, eps)
    kin.bodies[slider] = place(links[slider].local[ps], xs, vs, as_, line, w, eps)
    _slide(kin, ps, slider, carrier, t, tv, ta, line)
    _record(kin, d, ok, system.det / np.maximum(rho, 1e-300))


def _prp(kin: Kinematics, d: Dyad, branch: int) -> None:
    """Line ∩ line: G1 + t1·g1 = G2 + t2·g2.
    v: ṫ1·g1 − ṫ2·g2 = v_K2(C) − v_K1(C);  a: ẗ1·g1 − ẗ2·g2 = a_K2(C) − a_K1(C) + 2i(ω2·ṫ2·g2 − ω1·ṫ1·g1)."""
    c = d.inner.point
    k1, gx1, g1, al1 = _line(kin, d.outer_a.guide, d.a, c)
    k2, gx2, g2, al2 = _line(kin, d.outer_b.guide, d.b, c)
    system = System2(g1, -g2)
    t1, t2 = system(gx2 - gx1)
    xc = gx1 + t1 * g1
    b1, b2 = kin.bodies[k1], kin.bodies[k2]
    vk1, ak1 = b1.coincident(xc)
    vk2, ak2 = b2.coincident(xc)
    tv1, tv2 = system(vk2 - vk1)
    ta1, ta2 = system(ak2 - ak1 + 2j * (b2.omega * tv2 * g2 - b1.omega * tv1 * g1))
    vc = vk1 + tv1 * g1
    acc = ak1 + ta1 * g1 + 2j * b1.omega * tv1 * g1
    links = kin.mech.links
    kin.bodies[d.a] = place(links[d.a].local[c], xc, vc, acc, g1, b1.omega, b1.eps)
    kin.bodies[d.b] = place(links[d.b].local[c], xc, vc, acc, g2, b2.omega, b2.eps)
    slides = [(d.a, k1, t1, tv1, ta1, g1), (d.b, k2, t2, tv2, ta2, g2)]
    if k2 == FRAME != k1:       # the point's own name keys its absolute slide (a wedge press's ram, not
        slides.reverse()        # the block's slide along the moving wedge: the output, the diagrams)
    for slider, carrier, t, tv, ta, g in slides:
        _slide(kin, c, slider, carrier, t, tv, ta, g)
    cond = cross(g1, g2)
    _record(kin, d, np.abs(cond) > 1e-12, cond)


def _rpp(kin: Kinematics, d: Dyad, branch: int) -> None:
    """Block in a yoke: A = G + t3·g + q·e^{iθb} + t2·d  (the yoke b slides on K's guide g,
    the block a on the yoke's slot d).
    v: ṫ3·g + ṫ2·d = v_A − v_K(A);  a: ẗ3·g + ẗ2·d = a_A − a_K(A) − 2iω_K(ṫ3·g + ṫ2·d)."""
    if d.inner.slider != d.a:
        raise said_error(SceneError, "kn yoke slot", kin.mech.source, kin.mech.task.meta.get("lang"), dyad=_named(d))
    pa = d.outer_a.point
    xa, va, aa = _known(kin, d.outer_a.other(d.a), pa)
    links = kin.mech.links
    ref = next(iter(links[d.b].local))
    carrier, gx, g, alpha = _line(kin, d.outer_b.guide, d.b, ref)
    body_k = kin.bodies[carrier]
    turn = g                                  # the yoke's x-axis runs along K's guide
    slot = kin.mech.guides[d.inner.guide]
    q = slot.through + links[d.a].local[pa] * np.exp(1j * slot.angle)
    dd = np.exp(1j * slot.angle) * turn
    system = System2(g, dd)
    t3, t2 = system(xa - gx - q * turn)
    vk, ak = body_k.coincident(xa)
    tv3, tv2 = system(va - vk)
    ta3, ta2 = system(aa - ak - 2j * body_k.omega * (tv3 * g + tv2 * dd))
    xy = gx + t3 * g
    vky, aky = body_k.coincident(xy)
    vy = vky + tv3 * g
    ay = aky + ta3 * g + 2j * body_k.omega * tv3 * g
    kin.bodies[d.b] = place(0j, xy, vy, ay, turn, body_k.omega, body_k.eps)
    kin.bodies[d.a] = place(links[d.a].local[pa], xa, va, aa, dd, body_k.omega, body_k.eps)
    _slide(kin, pa, d.a, d.b, t2, tv2, ta2, dd)
    _slide(kin, ref, d.b, carrier, t3, tv3, ta3, g)
    cond = cross(g, dd)
    _record(kin, d, np.abs(cond) > 1e-12, cond)


_SOLVERS = {"RRR": _rrr, "RRP": _rrp, "RPR": _rpr, "PRP": _prp, "RPP": _rpp}


def _named(d):
    """A dyad as a refusal names it, in the language asked for (as exact.positions names it)."""
    return lambda lang: word("dyad title", lang, label=d.label, kind=pair_kind(d.kind, lang), a=d.a, b=d.b)
