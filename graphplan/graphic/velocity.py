"""2. The velocity plan: from the pole p_v, v_A = ω1·l_OA ⊥ OA laid off as p_v a; each group's two
vector equations drawn as direction lines (∥ a guide, ⊥ a link) through known plan points and
intersected, e.g. v_B = v_A + v_BA (⊥ AB) with v_B ∥ the guide; the slotted link
v_A3 = v_A2 + v_A3A2 (∥ the rocker) with v_A3 ⊥ O A."""
from __future__ import annotations

import math

import numpy as np

from graphplan.util.words import LANGS, fixed, word
from graphplan.model.mechanism import FRAME
from graphplan.util.errors import GraphplanError
from graphplan.model.structure import Dyad
from graphplan.graphic.draftsman import measure
from graphplan.graphic.position_plan import Image, Layout, Scheme, guide_line, sub, where
from graphplan.graphic.plan import Equation, Exact, Plan, PlanWarning, VANISH


class VelocityPlan(Plan):
    kind = "velocity"
    pole = "p_v"
    rate_kind = "omega"
    index = 1

    def __init__(self, sc: Scheme, lay: Layout, exact: Exact, mu: float, precision: float):
        super().__init__(sc, lay, exact, mu, precision)
        self.rocker_length: dict[str, float] = {}   # l_PcA measured off the position plan, m

    def crank(self) -> None:
        """v_A = ω1·l_OA ⊥ OA in the sense of ω1: the segment p_v a."""
        sc, cr = self.sc, self.sc.mech.crank
        O, A = where(sc, self.lay, FRAME, cr.pivot), where(sc, self.lay, cr.link, cr.pin)
        a = self.scaled(cr.omega * cr.length, 1j * math.copysign(1.0, cr.omega) * (A - O))
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
        order = [d.label for d in st.structure.dyads]
        groups = sorted({g for g, _ in stopped}, key=order.index)
        names = ", ".join(f"v_{n}" for _, n in stopped)
        said = {}
        for lang in LANGS:
            near = "" if not st.extremes else word("near extreme", lang, phi=fixed(st.extremes[j], lang, 2),
                                                   angle=fixed(angle, lang, 2))
            said[lang] = word("warn dead centre", lang, groups=f" {word('and', lang)} ".join(groups),
                              phi=fixed(phi, lang, 2), near=near, names=names,
                              verb=word("vanishes" if len(stopped) == 1 else "vanish", lang))
        self.warnings.append(PlanWarning("velocity", " ".join(groups), "dead centre", angle,
                                         said["en"], said["uk"]))

    def finish(self) -> None:
        super().finish()
        self.dead_centres()


# -- the five groups on the velocity plan ---------------------------------------------------------

def velocity_rrr(plan: VelocityPlan, d: Dyad) -> None:
    """v_C = v_P1 + v_CP1 (⊥ P1C) = v_P3 + v_CP3 (⊥ P3C): two lines ⊥ the links cross at c."""
    sc, lay, ex = plan.sc, plan.lay, plan.exact
    p1, p3, c = d.outer_a.point, d.outer_b.point, d.inner.point
    K1, K3 = d.outer_a.other(d.a), d.outer_b.other(d.b)
    X1, X3, XC = where(sc, lay, K1, p1), where(sc, lay, K3, p3), where(sc, lay, d.a, c)
    v1, v3 = plan.plan_point(K1, p1), plan.plan_point(K3, p3)
    step = f"v_{c} = v_{p1} + v_{c}{p1} = v_{p3} + v_{c}{p3}"
    vc = plan.solve(d.label, sub(c),
                    Equation(v1, 1j * (XC - X1), "relative", name=plan.known(p1), term=f"v_{c}{p1}",
                             rule=("perp", f"{c}{p1}")),
                    Equation(v3, 1j * (XC - X3), "relative", name=plan.known(p3), term=f"v_{c}{p3}",
                             rule=("perp", f"{c}{p3}")), step)
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
        along = Equation(vk, g, "relative", name="", term=f"v_{c}", rule=("guide", c))
    else:
        step = f"v_{c} = v_{p1} + v_{c}{p1} = v_{sc.name_at(c, K)} + v_{rel_key}"
        along = Equation(vk, g, "relative", name=sub(sc.name_at(c, K)), term=f"v_{rel_key}", rule=("link", K))
    vc = plan.solve(d.label, sub(c),
                    Equation(v1, 1j * (XC - X1), "relative", name=plan.known(p1), term=f"v_{c}{p1}",
                             rule=("perp", f"{c}{p1}")), along, step)
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
    return d.block_parts


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
    v3 = plan.solve(d.label, sub(a3),
                    Equation(vs, g, "relative", name=plan.known(ps), term=f"v_{a3}{a2}", rule=("link", carrier)),
                    Equation(vpc, 1j * (Xs - Xc), "relative", name=plan.known(pc), term=f"v_{a3}{pc}",
                             rule=("perp", f"{pc}{ps}")), step)
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
    if plan.rocker_length[carrier] == 0:
        raise GraphplanError(f"{plan.kind} plan at φ = {lay.phi:.4g}°, {d.label}: the block is at the "
                             f"rocker's pivot {pc} (their distance reads 0 mm on the position plan), "
                             "ω of the rocker cannot be read there", sc.mech.source)
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
    sides = [(link, K, key, Equation(plan.images[K].at(XC), g, "relative",
                                     name="" if K == FRAME else sub(sc.name_at(c, K)), term=f"v_{key}",
                                     rule=("guide", c) if K == FRAME else ("link", K)))
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
    vb = plan.solve(d.label, sub(ab),
                    Equation(vk, g, "relative", name="" if K == FRAME else sub(sc.name_at(pa, K)),
                             term=f"v_{guide_key}", rule=("guide", ab) if K == FRAME else ("link", K)),
                    Equation(va, slot, "relative", name=plan.known(pa), term=f"v_{slot_key}",
                             rule=("link", d.a)), step)
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
