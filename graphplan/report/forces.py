"""`graphplan forces`: the contract's JSON and the readable tables of a force analysis (seed 000,
tables 2.4–2.5; the lever; the balancing moment four ways)."""
from __future__ import annotations

import math
from typing import Any

from graphplan.util.markup import plain
from graphplan.util.words import fixed, force_symbol, num, pair_kind, pct, unit, word
from graphplan.util.romanize import scene_title

NULL_BELOW = 1e-6   # error_pct is null where |analytic| < 1e-6 × the largest force (moment) around


def _clean(doc: Any) -> Any:
    """−0.0 → 0.0 everywhere (byte-stable, readable JSON); a value the construction cannot read
    (the lever's P_b when the crank pin's image pa reads 0 mm at the plan's μv) is null."""
    if isinstance(doc, dict):
        return {k: _clean(v) for k, v in doc.items()}
    if isinstance(doc, list):
        return [_clean(v) for v in doc]
    if isinstance(doc, float):
        return doc + 0.0 if math.isfinite(doc) else None
    return doc


def _pct(value: float, analytic: float, scale: float) -> float | None:
    if abs(analytic) < NULL_BELOW * scale or analytic == 0:
        return None
    return 100.0 * (value - analytic) / analytic


def forces_json(fp) -> dict[str, Any]:
    """The contract's ``forces --json`` document (N, N·m, degrees)."""
    from graphplan.graphic.forceplans import angle_deg
    ks = fp.ks
    st = ks.st
    a = fp.analytic
    moments = {"analytic": a, "plans": fp.balancing, "lever": fp.lever.balancing, "power": fp.power}
    scale = max(abs(v) for v in moments.values()) or 1.0
    reactions = {}
    for key, m in fp.reactions().items():
        reactions[key] = {"value": m.value, "angle_deg": m.angle_deg, "analytic": m.analytic,
                          "error_pct": m.error_pct, "mm": m.mm,
                          "analytic_angle_deg": m.analytic_angle_deg,
                          "kind": ks.reactions[key].kind, "point": ks.reactions[key].point}
    from graphplan.graphic.forceplans import slide_arms
    for arm in slide_arms(fp):      # a sliding pair's reaction off its point: its arm along the guide, m
        reactions[arm.key]["arm"] = {"value": arm.value, "analytic": arm.analytic, "mm": arm.h_mm,
                                     "error_pct": arm.error_pct}
    inertia = {}
    drawn = {i.link: i for i in fp.inertia.values()}
    for key, item in ks.inertia().items():
        inertia[key] = {"force": float(item["force"][0]), "moment": float(item["moment"][0]),
                        "force_angle_deg": angle_deg(complex(math.cos(float(item["angle"][0])),
                                                             math.sin(float(item["angle"][0])))),
                        "link": item["link"]}
        i = drawn.get(item["link"])
        if i is not None:           # what the force plans and the lever take: read off the acceleration plan
            inertia[key]["plan"] = {"a_S": abs(i.a), "a_S_mm": i.a_mm, "epsilon": i.eps, "force": abs(i.force),
                                    "force_angle_deg": angle_deg(i.force), "moment": i.couple,
                                    "error_pct": {"force": _pct(abs(i.force), abs(i.exact_force), abs(i.exact_force)),
                                                  "moment": _pct(i.couple, i.exact_couple, abs(i.exact_couple))},
                                    "source": i.source}
    return _clean({
        "scene": st.mech.title,
        "phi_deg": fp.phi_deg,
        "from_position0_deg": float(st.from_position0(fp.phi_deg)),
        "stroke": "working" if bool(ks.working[0]) else "idle",
        "precision_mm": fp.precision,
        "mu_l": fp.mu_l,
        "mu_F": fp.mu_F,
        "mu_v": fp.lever.mu_v,
        "mu_a": fp.mu_a,
        "balancing_moment": moments,
        "error_pct": {k: _pct(v, a, scale) for k, v in moments.items() if k != "analytic"},
        # P_b in the crank's sense, as the analytic one (M_b = P_b·l_OA): the lever's own P_b is signed
        # by its moment about the pole of the plan turned 90°, opposite for a clockwise crank
        "balancing_force": {"lever": math.copysign(1.0, st.mech.omega1) * fp.lever.balancing_force,
                            "analytic": float(ks.balancing_force[0]),
                            "pa_mm": fp.lever.pa_mm},
        "reactions": reactions,
        "inertia": inertia,
        "groups": [{"label": g.label, "kind": g.kind, "links": list(g.links),
                    "reactions": list(g.reactions),
                    "acting": {k: m.name for k, m in g.reactions.items()},
                    "mu_F": g.mu_F or fp.mu_F} for g in fp.groups],
    })


def _row(cells: list[str], widths: list[int]) -> str:
    return "  ".join(c.rjust(w) for c, w in zip(cells, widths)).rstrip()


def drawn_mm(mm: float, precision: float) -> float:
    """A known force's length on its plan as the draftsman lays it off: to the ruler's precision."""
    from graphplan.graphic.draftsman import measure
    return measure(mm, precision) if precision > 0 else mm


def forces_table(fp, lang: str = "uk") -> str:
    """Readable tables: the loads, each group's forces and reactions (seed 000, tables 2.4–2.5),
    the moment equations, the lever and the balancing moment four ways; in ``lang``."""
    ks, mech = fp.ks, fp.ks.mech
    st = ks.st
    w = lambda k_, **kw: word(k_, lang, **kw)  # noqa: E731
    n = lambda v, digits=4: num(v, lang, digits)  # noqa: E731
    sym = lambda name: plain(force_symbol(name, lang))  # noqa: E731
    lines = [scene_title(mech.task.meta, mech.title, lang),
             w("forces at", phi=fixed(fp.phi_deg, lang, 3), turn=fixed(float(st.from_position0(fp.phi_deg)), lang, 3),
               stroke=w("working stroke" if ks.working[0] else "idle stroke")),
             plain(w("forces scales", w=n(mech.omega1, 5), p=n(fp.precision), ml=n(fp.mu_l), mf=n(fp.mu_F),
                     mv=n(fp.lever.mu_v))), "",
             plain(w("loads"))]
    if not ks.loads:
        lines.append("  " + w("no loads"))
    wd = [8, 6, 11, 9, 11, 8]
    drawn = fp.loads or ks.loads        # the inertia loads read off the acceleration plan (forceplans.construct)
    if fp.inertia:
        lines.append(plain(w("loads from plan", ma=n(fp.mu_a))))
    if ks.loads:
        lines.append(_row([w("load"), w("link"), w("value"), w("angle deg"), w("exact"), "δ, %"], wd))
    for ld, exact in zip(drawn, ks.loads):
        f, c = complex(ld.force[0]), float(ld.couple[0])
        fx, cx = complex(exact.force[0]), float(exact.couple[0])
        plan = ld.kind in ("inertia", "couple") and ld.link in fp.inertia
        if ld.point is None:            # a couple: the inertia couple M^Φ or an external moment
            tail = [f"{n(cx + 0.0)} {unit('N·m', lang)}", pct(_pct(c, cx, abs(cx)), lang)] if plan else []
            lines.append(_row([sym(ld.name), ld.link, f"{n(c + 0.0)} {unit('N·m', lang)}", ""] + tail, wd))
        else:
            tail = [f"{n(abs(fx))} {unit('N', lang)}", pct(_pct(abs(f), abs(fx), abs(fx)), lang)] if plan else []
            lines.append(_row([sym(ld.name), ld.link, f"{n(abs(f))} {unit('N', lang)}",
                               fixed(math.degrees(math.atan2(f.imag, f.real)) % 360, lang, 1) if f else ""] + tail, wd))
    for gp in fp.groups:
        kind = pair_kind(gp.kind, lang) if gp.kind != "crank" else w("crank group")
        lines += ["", w("group line", label=gp.label, kind=kind, links=", ".join(gp.links))]
        if gp.mu_F and gp.mu_F != fp.mu_F:      # its force plan at its own scale (the force sheet's)
            lines.append(plain(f"  μ_F = {n(gp.mu_F)} {unit('N/mm', lang)}"))
        for eq in gp.equations:
            # arms in drawing mm: a couple enters as M/μ_l (N·m over m/mm), as the textbook writes it
            # beside F·h with h in mm (review 56 #3: «− M^Φ₄» next to «G₄·49» read N·m beside N·mm);
            # the balancing equation keeps M_зр in N·m, its forces' arms × μ_l (said in its line)
            over = "" if eq.unknown == "M_b" else "/μ_l"
            terms = " ".join(f"{'+' if t.value >= 0 else '−'} {sym(t.name)}" +
                             (over if t.couple else f"·{n(abs(t.arm_mm))}") for t in eq.terms)
            if eq.unknown == "M_b":
                lines.append(plain(w("moment eq balancing", about=eq.about, terms=terms, r=n(eq.result, 5))))
            else:
                sign = "" if eq.arm_mm >= 0 else "−"
                line = (f"  ΣM_{eq.about} = 0: {sign}{sym(eq.unknown)}·{n(abs(eq.arm_mm))} {terms} = 0 "
                        f"→ {sym(eq.unknown)} = {n(eq.result, 5).replace('-', '−')} {unit('N', lang)}")
                if eq.result < 0:     # the assumed sense reversed: said, the tables give |R^τ|
                    line += f" ({w('tau opposite', sym=sym(eq.unknown))})"
                lines.append(line)
            if eq.unknown.endswith("τ"):      # its normal component read off the plan (the sheet's table)
                for s in gp.sides:
                    if s.name == eq.unknown[:-1] + "n" and s.role == "component" and s.mm > 1e-9:
                        mm = drawn_mm(s.mm, fp.precision)
                        lines.append(w("normal component", sym=sym(s.name), mm=n(mm), mm_=unit("mm", lang),
                                       v=n(mm * (gp.mu_F or fp.mu_F), 5)))
        cells = []
        mu_F = gp.mu_F or fp.mu_F
        for f in gp.forces:
            if f.force:
                cells.append((sym(f.name), n(abs(f.force), 5),
                              n(drawn_mm(abs(f.force) / mu_F, fp.precision))))
            if f.couple:
                cells.append((sym(f.name), f"{n(f.couple, 5)} {unit('N·m', lang)}", "—"))
        for eq in gp.equations:       # R^τ as the sheet's table lists it: the magnitude (seed 000)
            if eq.unknown.endswith("τ"):
                cells.append((sym(eq.unknown), n(abs(eq.result), 5),
                              n(drawn_mm(abs(eq.result) / mu_F, fp.precision))))
        lines.append(w("forces on group"))
        lines.append("  " + _row([w("force"), f"P, {unit('N', lang)}", w("drawn mm")], [10, 12, 14]))
        lines += ["  " + _row(list(c), [10, 12, 14]) for c in cells]
        lines.append(w("reactions from plan"))
        rw = [8, 9, 12, 9, 11, 9, 9]
        lines.append("  " + _row(["R", unit("mm", lang), f"{w('value')}, {unit('N', lang)}", w("angle deg"),
                                  w("exact N"), w("exact deg"), "δ, %"], rw))
        for m in gp.reactions.values():
            turn = 0.0 if m.name == m.key else 180.0     # the force on the group's link, as named
            lines.append("  " + _row([sym(m.name), n(m.mm), n(m.value, 5), fixed((m.angle_deg + turn) % 360, lang, 1),
                                      n(m.analytic, 5), fixed((m.analytic_angle_deg + turn) % 360, lang, 1),
                                      pct(m.error_pct, lang)], rw))
        from graphplan.drawing.forces import slide_arm_text
        from graphplan.graphic.forceplans import slide_arms
        lines += ["  " + plain(slide_arm_text(a, lang, h=f"h({sym(a.key)})")) for a in slide_arms(fp)
                  if a.group == gp.label]
    lv = fp.lever
    lines += ["", plain(w("lever head", mv=n(lv.mu_v), pa=n(lv.pa_mm)))]
    lw = [10, 6, 10, 8, 12]
    lines.append("  " + _row([w("force"), w("image"), f"F, {unit('N', lang)}", f"h, {unit('mm', lang)}",
                              f"F·h, {unit('N·mm', lang)}"], lw))
    for t in lv.terms:
        if t.pair:      # a couple carried as its moment M·l_xy/l_XY (its link's image too short for a pair)
            lines.append("  " + _row([sym(t.name), "".join(t.pair).lower(), "—", "—", n(t.moment + 0.0, 6)], lw))
            continue
        lines.append("  " + _row([sym(t.name), t.image.lower(), n(t.force, 5), n(t.arm_mm + 0.0),
                                  n(t.moment + 0.0, 6)], lw))
    lines.append(w("lever sum", s=n(lv.total, 6)))
    if math.isfinite(lv.balancing):
        lines.append(plain(w("lever result", p=n(lv.balancing_force, 5), m=n(lv.balancing, 5))))
    else:
        lines.append(plain(w("lever unreadable")))
    a = fp.analytic
    lines += ["", plain(w("balancing head"))]
    for name, value in (("closed form", a), ("by force plans", fp.balancing),
                        ("by lever", lv.balancing), ("by power", fp.power)):
        err = _pct(value, a, abs(a) or 1.0)
        tail = "" if name == "closed form" or err is None else f"   δ = {fixed(err, lang, 3, plus=True)} %"
        shown = n(value, 6) if math.isfinite(value) else "—"
        lines.append(f"  {w(name):<28} {shown:>12}{tail}")
    return "\n".join(lines) + "\n"
