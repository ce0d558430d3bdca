"""`graphplan forces`: the contract's JSON and the readable tables of a force analysis (seed 000,
tables 2.4–2.5; the lever; the balancing moment four ways)."""
from __future__ import annotations

import math
from typing import Any

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
    inertia = {}
    for key, item in ks.inertia().items():
        inertia[key] = {"force": float(item["force"][0]), "moment": float(item["moment"][0]),
                        "force_angle_deg": angle_deg(complex(math.cos(float(item["angle"][0])),
                                                             math.sin(float(item["angle"][0])))),
                        "link": item["link"]}
    return _clean({
        "scene": st.mech.title,
        "phi_deg": fp.phi_deg,
        "from_position0_deg": float(st.from_position0(fp.phi_deg)),
        "stroke": "working" if bool(ks.working[0]) else "idle",
        "precision_mm": fp.precision,
        "mu_l": fp.mu_l,
        "mu_F": fp.mu_F,
        "mu_v": fp.lever.mu_v,
        "balancing_moment": moments,
        "error_pct": {k: _pct(v, a, scale) for k, v in moments.items() if k != "analytic"},
        "balancing_force": {"lever": fp.lever.balancing_force, "analytic": float(ks.balancing_force[0]),
                            "pa_mm": fp.lever.pa_mm},
        "reactions": reactions,
        "inertia": inertia,
        "groups": [{"label": g.label, "kind": g.kind, "links": list(g.links),
                    "reactions": list(g.reactions)} for g in fp.groups],
    })


def _row(cells: list[str], widths: list[int]) -> str:
    return "  ".join(c.rjust(w) for c, w in zip(cells, widths)).rstrip()


def forces_table(fp) -> str:
    """Readable tables: the loads, each group's forces and reactions (seed 000, tables 2.4–2.5),
    the moment equations, the lever and the balancing moment four ways."""
    ks, mech = fp.ks, fp.ks.mech
    st = ks.st
    lines = [mech.title,
             f"force analysis at φ = {fp.phi_deg:.3f}° ({float(st.from_position0(fp.phi_deg)):.3f}° of crank "
             f"turn from position 0, {'working' if ks.working[0] else 'idle'} stroke)",
             f"ω1 = {mech.omega1:.5g} rad/s; drafting precision {fp.precision:g} mm; μl = {fp.mu_l:g} m/mm, "
             f"μF = {fp.mu_F:g} N/mm, μv = {fp.lever.mu_v:g} (m/s)/mm", "",
             "Loads: G = m·g, Φ = −m·a_S, M_Φ = −I_S·ε (+ counter-clockwise), external forces"]
    if not ks.loads:
        lines.append("  none: the scene gives no masses and no forces, so every reaction is zero")
    w = [8, 6, 11, 9]
    if ks.loads:
        lines.append(_row(["load", "link", "value", "angle, °"], w))
    for ld in ks.loads:
        f, c = complex(ld.force[0]), float(ld.couple[0])
        if ld.kind == "couple":
            lines.append(_row([ld.name, ld.link, f"{c + 0.0:.4g} N·m", ""], w))
        else:
            lines.append(_row([ld.name, ld.link, f"{abs(f):.4g} N",
                               f"{math.degrees(math.atan2(f.imag, f.real)) % 360:.1f}" if f else ""], w))
    for gp in fp.groups:
        lines += ["", f"Group {gp.label} {gp.kind if gp.kind != 'crank' else '(the crank)'}, "
                      f"links {', '.join(gp.links)}"]
        for eq in gp.equations:
            terms = " ".join(f"{'+' if t.value >= 0 else '−'} {t.name}" +
                             ("" if t.couple else f"·{abs(t.arm_mm):g}") for t in eq.terms)
            if eq.unknown == "M_b":
                lines.append(f"  ΣM_{eq.about} = 0: M_b {terms} = 0 (forces × arms in mm × μl) "
                             f"→ M_b = {eq.result:.5g} N·m")
            else:
                sign = "" if eq.arm_mm >= 0 else "−"
                lines.append(f"  ΣM_{eq.about} = 0: {sign}{eq.unknown}·{abs(eq.arm_mm):.4g} {terms} = 0 "
                             f"→ {eq.unknown} = {eq.result:.5g} N")
        cells = []
        for f in gp.forces:
            if f.force:
                cells.append((f.name, f"{abs(f.force):.5g}", f"{abs(f.force) / fp.mu_F:.4g}"))
            if f.couple:
                cells.append((f.name, f"{f.couple:.5g} N·m", "—"))
        lines.append("  forces on the group (table as in seed 000):")
        lines.append("  " + _row(["force", "P, N", "drawn, mm"], [10, 12, 10]))
        lines += ["  " + _row(list(c), [10, 12, 10]) for c in cells]
        lines.append("  reactions from the force plan:")
        rw = [8, 9, 10, 9, 11, 9, 9]
        lines.append("  " + _row(["R", "mm", "value, N", "angle, °", "exact, N", "exact, °", "δ, %"], rw))
        for m in gp.reactions.values():
            lines.append("  " + _row([m.key, f"{m.mm:.4g}", f"{m.value:.5g}", f"{m.angle_deg:.1f}",
                                      f"{m.analytic:.5g}", f"{m.analytic_angle_deg:.1f}",
                                      "—" if m.error_pct is None else f"{m.error_pct:+.2f}"], rw))
    lv = fp.lever
    lines += ["", f"Zhukovsky lever (velocity plan turned 90°, μv = {lv.mu_v:g} (m/s)/mm, pa = {lv.pa_mm:g} mm):"]
    lw = [10, 6, 10, 8, 12]
    lines.append("  " + _row(["force", "image", "F, N", "h, mm", "F·h, N·mm"], lw))
    for t in lv.terms:
        lines.append("  " + _row([t.name, t.image.lower(), f"{t.force:.5g}", f"{t.arm_mm + 0.0:g}",
                                  f"{t.moment + 0.0:.6g}"], lw))
    lines.append(f"  ΣF·h = {lv.total:.6g} N·mm (h + counter-clockwise about the pole)")
    if math.isfinite(lv.balancing):
        lines.append(f"  P_b = ΣF·h / pa = {lv.balancing_force:.5g} N;  M_b = P_b·l_OA = {lv.balancing:.5g} N·m")
    else:
        lines.append("  pa reads 0 mm at this μv: the lever gives no P_b (choose a finer --precision)")
    a = fp.analytic
    lines += ["", "Balancing moment on the crank M_b (N·m, + counter-clockwise):"]
    for name, value in (("closed form (kinetostatics)", a), ("force plans", fp.balancing),
                        ("Zhukovsky lever", lv.balancing), ("power balance", fp.power)):
        err = _pct(value, a, abs(a) or 1.0)
        tail = "" if name.startswith("closed") or err is None else f"   δ = {err:+.3f} %"
        shown = f"{value:12.6g}" if math.isfinite(value) else f"{'—':>12}"
        lines.append(f"  {name:<28} {shown}{tail}")
    return "\n".join(lines) + "\n"
