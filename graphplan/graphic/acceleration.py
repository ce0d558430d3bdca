"""3. The acceleration plan: from the pole π, a_A; for each group the normal components
a^n = v²/l laid off ∥ the link toward its centre (n ends), the Coriolis a^k = 2·ω·v_rel along v_rel
turned 90° in the sense of ω (k ends), and the lines of the unknown tangential/relative
components intersected."""
from __future__ import annotations

import math


from graphplan.model.mechanism import FRAME
from graphplan.model.structure import Dyad
from graphplan.graphic.position_plan import Image, Layout, Scheme, guide_line, sub, where
from graphplan.graphic.plan import Equation, Exact, Plan
from graphplan.graphic.velocity import VelocityPlan, prp_guides, rpr_parts


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
        n = self.scaled(cr.omega ** 2 * cr.length, O - A)
        t = self.scaled(cr.epsilon * cr.length, 1j * math.copysign(1.0, cr.epsilon) * (A - O)) if cr.epsilon else 0j
        step = f"a_{cr.pin} = a^n_{cr.pin}{cr.pivot} + a^τ_{cr.pin}{cr.pivot}"
        if cr.epsilon:
            self.crank_items = [i for i in (self.vector(0j, n, "normal", step),
                                            self.vector(n, n + t, "tangential", step)) if i is not None]
            self.name_point(self.end_label("n", cr.link), n)
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


# -- the five groups on the acceleration plan -----------------------------------------------------

def normal_and_tangent(plan: AccelerationPlan, link: str, p: str, X: complex, ap: complex,
                       c: str, XC: complex, length: float, step_keys: list) -> Equation:
    """a_C = a_P + a^n_CP (v_CP²/l, ∥ CP toward P) + a^τ_CP (⊥ CP): the known part of one equation."""
    n = plan.normal(plan.vel.plan_point(link, c) - plan.vel.plan_point(link, p), length, X - XC)
    step_keys.append((link, p, X, n, length))
    return Equation(ap, 1j * (XC - X), "tangential", [(n, "normal", plan.end_label("n", link), f"n_{c}{p}")],
                    name=plan.known(p), term=f"a^τ_{c}{p}", rule=("perp", f"{c}{p}"))


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
                   direction: complex, key: str, name: str = "", term: str = "",
                   rule: tuple[str, str] = ("", "")) -> Equation:
    """a_C = a_C(K) + a^k (2·ω_K·v_rel, v_rel turned 90° in the sense of ω_K) + a^r (∥ the guide).
    ``name``, ``term`` and ``rule`` word it (Equation); the term defaults to a^r_key."""
    chain = []
    if plan.sc.rotating[K]:
        k = plan.coriolis(K, rel_v_mm)
        chain.append((k, "coriolis", plan.end_label("k"), f"k_{key}"))
    return Equation(base, direction, "relative", chain, name=name, term=term or f"a^r_{key}",
                    rule=rule if rule[0] else ("link", K))


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
    if K == FRAME:
        e2 = slide_equation(plan, K, XC, plan.images[K].at(XC), rel_v, g, key, term=f"a_{c}", rule=("guide", c))
    else:
        e2 = slide_equation(plan, K, XC, plan.images[K].at(XC), rel_v, g, key, name=sub(sc.name_at(c, K)))
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
    e1 = slide_equation(plan, carrier, Xs, a_s, rel_v, g, key, name=plan.known(ps))
    length = vel.rocker_length[carrier]
    n = plan.normal(vel.images[carrier].at(Xs) - vel.plan_point(Kc, pc), length, Xc - Xs)
    e2 = Equation(a_c, 1j * (Xs - Xc), "tangential", [(n, "normal", plan.end_label("n", carrier), f"n_{a3}{pc}")],
                  name=plan.known(pc), term=f"a^τ_{a3}{pc}", rule=("perp", f"{pc}{ps}"))
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
        sides.append((link, K, key, slide_equation(
            plan, K, XC, plan.images[K].at(XC), rel_v, g, key, name="" if K == FRAME else sub(sc.name_at(c, K)),
            rule=("guide", c) if K == FRAME else ("link", K))))
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
    e1 = slide_equation(plan, K, XA, plan.images[K].at(XA), vb - vel.images[K].at(XA), g, guide_key,
                        name="" if K == FRAME else sub(sc.name_at(pa, K)),
                        rule=("guide", ab) if K == FRAME else ("link", K))
    e2 = slide_equation(plan, d.a, XA, plan.plan_point(Ka, pa), vb - vel.plan_point(Ka, pa), slot, slot_key,
                        name=plan.known(pa), rule=("link", d.a))
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
