"""The gear mechanism's results for people and programs: the contract's ``gears --json`` and the
terminal's tables (both languages, the lab's notation: z, m, x, αw, aw, y, Δy, r, rb, rw, ra, rf, s,
sa, p, pb, εα, λ, u1H, ω)."""
from __future__ import annotations

import math
from typing import Any

from graphplan.exact.gears import CONTACT_MIN, POINTED, Solution
from graphplan.util.words import fixed, num
from graphplan.util.words import num as _num


def solved(path, precision: float = 0.5, height_mm: float = 480.0):
    """A gear scene read, solved by the closed forms and constructed: (gears, solution, mesh, velocities);
    the meshing drawn to fit ``height_mm`` (an A1 sheet's zone by default)."""
    from graphplan.exact.gears import solve
    from graphplan.graphic.gears import construct_mesh, construct_train
    from graphplan.model.gears import load
    gears = load(path)
    sol = solve(gears)
    mesh = construct_mesh(sol.pair, precision, height_mm=height_mm) if sol.pair else None
    vel = construct_train(sol.train, precision) if sol.train else None
    return gears, sol, mesh, vel


def err(g: float | None, e: float) -> float | None:
    """The lab's percent error; None where the exact value is (near) zero or nothing was read."""
    if g is None or not math.isfinite(g) or abs(e) < 1e-12:
        return None
    v = 100.0 * (g - e) / abs(e)
    return 0.0 if abs(v) < 1e-9 else v


def _fin(v) -> float | None:
    return float(v) if v is not None and math.isfinite(v) else None


def pair_json(sol, mesh) -> dict[str, Any]:
    from graphplan.graphic.gears import outside
    p = sol.pair
    q = sol.quality()
    pts = [("N1", 0.0)] + [(None, sol.g * k / 10) for k in range(1, 10)] + [("N2", sol.g)]
    pts += [("B1", sol.rho_B1), ("P", sol.rho_P), ("B2", sol.rho_B2)]
    pts.sort(key=lambda t: t[1])
    sliding = []
    for name, rho in pts:
        l1, l2 = sol.sliding(rho)
        row: dict[str, Any] = {"rho1_m": float(rho), "lambda1": _fin(float(l1)), "lambda2": _fin(float(l2))}
        if name:
            row["point"] = name
        sliding.append(row)
    doc: dict[str, Any] = {
        "z": list(p.z), "module_m": p.module, "alpha_deg": p.alpha_deg, "addendum": p.addendum,
        "clearance": p.clearance, "x": list(sol.x),
        "shifts": "given" if p.shifts is not None else "auto",
        "alpha_w_deg": sol.alpha_w_deg, "a_m": sol.a, "a_w_m": sol.aw, "y": sol.y, "delta_y": sol.dy,
        "r_m": list(sol.r), "rb_m": list(sol.rb), "rw_m": list(sol.rw), "ra_m": list(sol.ra), "rf_m": list(sol.rf),
        "s_m": list(sol.s), "sa_m": list(sol.sa), "pitch_m": sol.p, "base_pitch_m": sol.pb,
        "line_of_action_m": sol.g, "rho_m": {"B1": sol.rho_B1, "P": sol.rho_P, "B2": sol.rho_B2},
        "contact_ratio": {"exact": sol.eps, "graphical": mesh.eps if mesh else None,
                          "error_pct": err(mesh.eps, sol.eps) if mesh else None,
                          "bound": mesh.eps_bound if mesh else None,
                          "outside_bound": outside(mesh.eps, sol.eps, mesh.eps_bound) if mesh else False},
        "quality": {"undercut": q["undercut"], "x_min": q["x_min"], "pointed": q["pointed"],
                    "sa_min_m": POINTED * p.module, "interference": q["interference"],
                    "contact_ratio_min": CONTACT_MIN, "contact_ratio_ok": q["contact_ratio_ok"],
                    "sliding_max": q["sliding_max"],
                    "involute_start_rho_m": list(sol.rho_limit)},
        "sliding": sliding,
        "warnings": [en for en, _ in sol.warnings + (mesh.warnings if mesh else [])],
        "warnings_uk": [uk for _, uk in sol.warnings + (mesh.warnings if mesh else [])]}
    if doc["contact_ratio"]["outside_bound"]:
        _flag(doc, "εα = B1B2/pb", mesh.eps, sol.eps, mesh.eps_bound)
    if sol.auto:
        doc["auto"] = {"rule": sol.auto["rule"], "rule_uk": sol.auto["rule_uk"], "grid": sol.auto["grid"],
                       "tried": sol.auto["tried"], "passing": sol.auto["passing"]}
    if mesh:
        doc["graphical"] = {
            "mu_l_m_mm": mesh.mu_l, "module_mm": mesh.module_mm, "precision_mm": mesh.precision,
            "drawn_mm": dict(mesh.drawn), "read_mm": dict(mesh.read),
            "rw_m": list(mesh.rw), "s_m": list(mesh.s), "sa_m": list(mesh.sa), "sa_bound_m": list(mesh.sa_bound),
            "error_pct": {"rw": [err(mesh.rw[k], sol.rw[k]) for k in (0, 1)],
                          "s": [err(mesh.s[k], sol.s[k]) for k in (0, 1)],
                          "sa": [err(mesh.sa[k], sol.sa[k]) for k in (0, 1)]}}
    return doc


def _flag(doc: dict[str, Any], name: str, graphical: float, exact: float, bound: float) -> None:
    """A reading outside its stated bound: said in the warnings (the terminal's, the sheet's notes)."""
    d = graphical - exact
    num = lambda v, lang, k=4: _num(v, lang, k).replace("-", "−")        # noqa: E731
    doc["warnings"].append(f"{name} read off the drawing, {num(graphical, 'en')}, is off the exact {num(exact, 'en')} "
                           f"by {num(d, 'en', 3)}: outside its bound ±{num(bound, 'en', 2)} from the drafting precision")
    doc["warnings_uk"].append(f"{name}, прочитане з креслення, {num(graphical, 'uk')}, відрізняється від точного "
                              f"{num(exact, 'uk')} на {num(d, 'uk', 3)}: поза межею ±{num(bound, 'uk', 2)} від "
                              "точності креслення")


def train_json(tr, vel) -> dict[str, Any]:
    from graphplan.graphic.gears import outside
    t = tr.train
    doc: dict[str, Any] = {
        "type": t.kind, "planets": t.planets, "z": list(tr.z), "module_m": t.module,
        "ratio_required": t.ratio, "rpm": t.rpm,
        "ratio": {"exact": tr.ratio, "graphical": _fin(vel.ratio) if vel else None,
                  "error_pct": err(vel.ratio, tr.ratio) if vel else None, "bound": vel.ratio_bound if vel else None,
                  "outside_bound": outside(vel.ratio, tr.ratio, vel.ratio_bound) if vel else False},
        "omega_rad_s": dict(tr.omega),
        "radii_m": tr.radii,
        "conditions": dict(tr.conditions),
        "candidates": tr.candidates, "candidates_passing": tr.weighed, "nearest": tr.nearest,
        "warnings": [en for en, _ in tr.warnings], "warnings_uk": [uk for _, uk in tr.warnings]}
    if doc["ratio"]["outside_bound"]:
        _flag(doc, "u1H", vel.ratio, tr.ratio, vel.ratio_bound)
    if tr.train.ratio is not None:
        doc["ratio"]["required_error_pct"] = 100.0 * (tr.ratio - tr.train.ratio) / tr.train.ratio
    if vel:
        doc["graphical"] = {
            "mu_l_m_mm": vel.mu_l, "mu_v_mm": vel.mu_v, "h_mm": vel.h, "precision_mm": vel.precision,
            "va_mm": vel.va_mm, "heights_mm": dict(vel.heights), "segments_mm": dict(vel.segments),
            "h_carrier_mm": vel.h_carrier,
            "omega_rad_s": dict(vel.omega),
            "error_pct": {k: err(vel.omega[k], tr.omega[k]) for k in tr.omega}}
    return doc


def gears_json(sol: Solution, mesh, vel, scene: str) -> dict[str, Any]:
    """The contract's document: ``pair`` for [gears], ``planetary`` for [planetary]."""
    doc: dict[str, Any] = {"scene": scene}
    if sol.pair is not None:
        doc["pair"] = pair_json(sol.pair, mesh)
    if sol.train is not None:
        doc["planetary"] = train_json(sol.train, vel)
    return doc


WORDS = {
    "uk": {"title": "Синтез зубчастих механізмів", "pair": "Евольвентна передача", "train": "Планетарна передача",
           "given": "зміщення задано", "auto": "зміщення вибрано за правилом: {rule}",
           "head": ["величина", "колесо 1", "колесо 2"], "exact": "точно", "graph": "графічно", "eps": "εα",
           "eps_line": "коефіцієнт перекриття εα = {e} (графічно B1B2/pb = {g}, похибка {d} %; межа похибки від точності креслення ±{b} абсолютна, ±{bp} %{out})",
           "data": "z = {z}, m = {m} мм, α = {a}°, h*a = {h}, c* = {c}, x = {x}",
           "geo": "αw = {aw}°, a = {a} мм, aw = {w} мм, y = {y}, Δy = {dy}, p = {p} мм, pb = {pb} мм",
           "quality": "якість: підрізання {u}; загострення (sa ≥ 0,25m) {s}; заклинювання {i}; εα ≥ 1,2 {e} (за формулою; "
                      "з креслення {g}: {gv}); "
                      "найбільше питоме ковзання |λ1| = {l1}, |λ2| = {l2}",
           "yes": "так", "no": "ні", "ok": "виконано", "fail": "не виконано",
           "scale": "масштаб зачеплення μl = {mu} м/мм (модуль {md} мм на кресленні), точність {p} мм",
           "type": "тип {t}, сателітів K = {k}, модуль {m} мм, ω1 = {w} рад/с",
           "zt": "числа зубців z = {z}; u1H = {u}{r}, графічно {g} (похибка {d} %; межа похибки від точності креслення ±{b} абсолютна, ±{bp} %{out})",
           "cond": "умови: співвісність {c}, складання {a}, сусідство {n}, без підрізання {u}",
           "cands": "набори, що задовольняють усі умови (їх {n}), перші за найменшим зовнішнім діаметром у модулях D/m:",
           "nearest": "найближчий до потрібного u1H (найменший з таких): z = {z}: D/m = {D}, u1H = {u} ({e} %)",
           "omega": "ω, рад/с", "vel": "масштаби: μl = {l} м/мм, μv = {v} (м/с)/мм, h = {h} мм",
           "h_H": ", водило — свій полюс, hH = {h} мм",
           "rows": {"r": "r, мм", "rb": "r_b, мм", "rw": "r_w, мм", "ra": "r_a, мм", "rf": "r_f, мм",
                    "s": "s, мм", "sa": "s_a, мм"},
           "wanted": " (потрібно {r})", "warn": "Попередження", "member": "ланка", "given_w1": " (задано)", "within": "у межах похибки креслення", "out": " — ПОЗА МЕЖЕЮ"},
    "en": {"title": "Gear synthesis", "pair": "Involute pair", "train": "Planetary train",
           "given": "shifts given", "auto": "shifts chosen by the rule: {rule}",
           "head": ["quantity", "wheel 1", "wheel 2"], "exact": "exact", "graph": "graphical", "eps": "εα",
           "eps_line": "contact ratio εα = {e} (graphically B1B2/pb = {g}, error {d} %; bound of the error from the drafting precision ±{b} absolute, ±{bp} %{out})",
           "data": "z = {z}, m = {m} mm, α = {a}°, h*a = {h}, c* = {c}, x = {x}",
           "geo": "αw = {aw}°, a = {a} mm, aw = {w} mm, y = {y}, Δy = {dy}, p = {p} mm, pb = {pb} mm",
           "quality": "quality: undercut {u}; pointed (sa ≥ 0.25m) {s}; interference {i}; εα ≥ 1.2 {e} (by the formula; "
                      "off the drawing {g}: {gv}); "
                      "greatest specific sliding |λ1| = {l1}, |λ2| = {l2}",
           "yes": "yes", "no": "no", "ok": "met", "fail": "not met",
           "scale": "meshing scale μl = {mu} m/mm (module drawn {md} mm), precision {p} mm",
           "type": "type {t}, K = {k} planets, module {m} mm, ω1 = {w} rad/s",
           "zt": "teeth z = {z}; u1H = {u}{r}, graphically {g} (error {d} %; bound of the error from the drafting precision ±{b} absolute, ±{bp} %{out})",
           "cond": "conditions: coaxial {c}, assembly {a}, neighbourhood {n}, no undercut {u}",
           "cands": "of {n} sets meeting every condition, the first by the smallest outer diameter in modules D/m:",
           "nearest": "the nearest the wanted u1H (the smallest such): z = {z}: D/m = {D}, u1H = {u} ({e} %)",
           "omega": "ω, rad/s", "vel": "scales: μl = {l} m/mm, μv = {v} (m/s)/mm, h = {h} mm",
           "h_H": ", the carrier's own pole hH = {h} mm",
           "rows": {"r": "r, mm", "rb": "r_b, mm", "rw": "r_w, mm", "ra": "r_a, mm", "rf": "r_f, mm",
                    "s": "s, mm", "sa": "s_a, mm"},
           "wanted": " (wanted {r})", "warn": "Warnings", "member": "member", "given_w1": " (given)",
           "within": "within the drafting error", "out": " — OUTSIDE ITS BOUND"},
}


def table_decimals(g: dict[str, Any]) -> int:
    """The decimals of Table 1's lengths in mm: one past the ruler's resolution on the part,
    precision·μl (0.5 mm at 4:1 → 0.125 mm → two decimals), so that the percent error worked out
    from the printed values is the lab's error and not the rounding's; four at precision 0."""
    res = g["precision_mm"] * g["mu_l_m_mm"] * 1000.0
    return 4 if res <= 0 else max(0, math.ceil(-math.log10(res) - 1e-9)) + 1


def eps_read_verdict(c: dict[str, Any]) -> str:
    """The condition εα ≥ 1.2 judged on the value read off the drawing (B1B2/pb) — a check of the
    drawing, not the design's verdict, which is the formula's (REFERENCE §12: the quality indices are
    computed; the graphical εα is "measured with the ruler and compared"): "ok" when the reading meets
    1.2, "within" when it falls short by no more than its bound from the drafting precision (review 12:
    εα = 1,2033 by the formula, 1,196 read, bound ±0,031), "fail" past that (the reading then also
    lies outside its bound unless the exact value fails too)."""
    g = c.get("graphical")
    if g is None:
        return "fail"
    if g >= CONTACT_MIN:
        return "ok"
    bound = c.get("bound")
    return "within" if bound is not None and g + bound >= CONTACT_MIN else "fail"


def length_decimals(dec: int) -> int:
    """The decimals of Table 1's lengths that are not read off the drawing (aw, a, p, pb): the
    column's ``table_decimals`` and at least two — the lab prints aw to 0,01 mm, the centre distance
    being machined (review 12: «110» for 109,977)."""
    return max(dec, 2)


def agreeing(exact: float, graphical: float | None, decimals: int, lang: str
             ) -> tuple[str, str, float | None]:
    """The exact and the graphical value printed to ``decimals`` places and the percent error δ
    worked out from the two printed numbers, δ = 100·(graphical − exact)/exact, as the student works
    it out: a reader who recomputes δ from the table gets the printed δ (the JSON keeps the unrounded
    error). None where nothing was read or the printed exact value is 0."""
    e = round(float(exact), decimals)
    text = lambda v: (f"{v + 0.0:.{decimals}f}".replace(".", "," if lang == "uk" else ".")   # noqa: E731
                      .replace("-", "−"))
    if graphical is None:
        return text(e), "", None
    g = round(float(graphical), decimals)
    return text(e), text(g), (100.0 * (g - e) / e if e else None)


def contact_ratio_text(exact: float, graphical: float | None, lang: str) -> tuple[str, str, float | None]:
    """εα exact and read off the drawing (B1B2/pb) to ``READ_DIGITS`` significant figures and δ % worked
    out from the two printed numbers (``agreeing``), as the sheet's Table 1 and the terminal print
    them: (exact, graphical, δ)."""
    return agreeing(exact, graphical, sig_decimals(exact), lang)


DELTA_DECIMALS = 2       # δ % as the lab and the other sheets print it (sheets.compose.percent): 2,50 / −0,87 / 0,14


def delta_text(v: float | None, lang: str) -> str:
    """A percent error δ to ``DELTA_DECIMALS`` places (one count of decimals down a table's δ
    column: review 10 had 2,5 beside −0,869 and 0,144), a true
    minus, "—" for none; "0,00" where it rounds to nothing (review 12: «0» beside «0,40»); the sheet's
    tables and the terminal print the same text."""
    if v is None or not math.isfinite(v):
        return "—"
    v = round(v, DELTA_DECIMALS) + 0.0                   # (no "−0,00")
    return f"{v:.{DELTA_DECIMALS}f}".replace(".", "," if lang == "uk" else ".").replace("-", "−")


def bare(text: str) -> str:
    """A printed number without trailing zeros ("42,00" → "42", "−37,500" → "−37,5"), as the other
    sheets and the terminal print values where no reading's resolution is the point; the value and
    so the δ worked out from it are unchanged."""
    if "," not in text and "." not in text:
        return text
    out = text.rstrip("0").rstrip(",.")
    return "0" if out in ("", "−", "-", "−0", "-0") else out


READ_DIGITS = 4          # significant figures of a value read off the drawing (εα, u1H, ω) and of its exact one


def sig_decimals(exact: float, digits: int = READ_DIGITS) -> int:
    """The decimals that give ``exact`` ``digits`` significant figures (u1H 11.81 → 2, ω 100.5 → 1):
    the ratio's and the velocities' rows of the train, printed so that δ reads from them. Four
    figures: the readings' bounds from the drafting precision are a few percent (εα ±0.03, u1H
    ±0.2–0.4), so an eight-decimal εα or a five-figure u1H would print digits the ruler never gave
    (review 5, item 16)."""
    return max(0, digits - 1 - math.floor(math.log10(abs(exact)))) if exact else 0


def alike(values, lang: str, digits: int = READ_DIGITS) -> list[str]:
    """Values of one quantity printed side by side (wheel 1's and wheel 2's largest |λ|) to one count
    of decimals — the one that gives each at least ``digits`` significant figures: «1,351» beside
    «1,420», not «1,42» (stop 51: Table 2 and the terminal printed a column of 3 and 2 decimals)."""
    d = max((sig_decimals(v, digits) for v in values if v), default=0)
    return [fixed(v, lang, d).replace("-", "−") for v in values]


def _share(bound: float | None, exact: float, lang: str) -> str:
    """An absolute bound as a percent of the exact value (what the δ % column is compared with)."""
    return "—" if bound is None or not exact else num(100.0 * bound / abs(exact), lang, 2)


def _table(rows: list[list[str]]) -> list[str]:
    widths = [max(len(r[k]) for r in rows) for k in range(len(rows[0]))]
    return ["  ".join(x.rjust(w) if i else x.ljust(w) for i, (x, w) in enumerate(zip(r, widths))) for r in rows]


def pair_lines(d: dict, lang: str) -> list[str]:
    w = WORDS[lang]
    n = lambda x, k=4: "—" if x is None else num(x, lang, k).replace("-", "−")   # noqa: E731
    yes = lambda b: w["yes"] if b else w["no"]                                      # noqa: E731
    lines = [w["pair"] + ":", w["data"].format(z=", ".join(map(str, d["z"])), m=n(d["module_m"] * 1000),
                                                a=n(d["alpha_deg"]), h=n(d["addendum"]), c=n(d["clearance"]),
                                                x=", ".join(n(v) for v in d["x"]))]
    if d["shifts"] == "auto":
        lines.append(w["auto"].format(rule=d["auto"]["rule_uk" if lang == "uk" else "rule"]))
    g = d.get("graphical")
    ld = length_decimals(table_decimals(g) if g else 4)        # as Table 1: aw to 0,01 mm at least
    mm = lambda v: fixed(v * 1000, lang, ld).replace("-", "−")                      # noqa: E731
    lines.append(w["geo"].format(aw=n(d["alpha_w_deg"], 6), a=mm(d["a_m"]), w=mm(d["a_w_m"]), y=n(d["y"]),
                                 dy=n(d["delta_y"]), p=mm(d["pitch_m"]), pb=mm(d["base_pitch_m"])))
    c = d["contact_ratio"]
    ce, cg, cd = contact_ratio_text(c["exact"], c["graphical"], lang)
    lines.append(w["eps_line"].format(e=ce, g=cg or "—", d=delta_text(cd, lang), b=n(c["bound"], 2),
                                      bp=_share(c["bound"], c["exact"], lang), out=w["out"] if c["outside_bound"] else ""))
    q = d["quality"]
    lines.append(w["quality"].format(u=", ".join(yes(v) for v in q["undercut"]),
                                     s=", ".join(yes(v) for v in q["pointed"]),
                                     i=", ".join(yes(v) for v in q["interference"]),
                                     e=w["ok"] if q["contact_ratio_ok"] else w["fail"], g=cg or "—",
                                     gv=w[eps_read_verdict(c)] if cg else "—",
                                     l1=alike(q["sliding_max"], lang)[0], l2=alike(q["sliding_max"], lang)[1]))
    g = d.get("graphical")
    if g:
        lines.append(w["scale"].format(mu=n(g["mu_l_m_mm"]), md=n(g["module_mm"]), p=n(g["precision_mm"])))
    rows = [[w["head"][0], f"{w['exact']} 1", f"{w['graph']} 1", "δ, %", f"{w['exact']} 2", f"{w['graph']} 2", "δ, %"]]
    dec = table_decimals(g) if g else 4
    for key in ("r", "rb", "rw", "ra", "rf", "s", "sa"):
        ex = d[f"{key}_m"]
        gr = g[f"{key}_m"] if g and f"{key}_m" in g else None
        row = [w["rows"][key].replace("_", "")]
        for k in (0, 1):
            te, tg, e = agreeing(ex[k] * 1000, None if gr is None else gr[k] * 1000, dec, lang)
            row += [te, tg, delta_text(e, lang) if e is not None else ""] if gr is not None else [te, "", ""]
        rows.append(row)
    lines += [""] + _table(rows)
    return lines


def train_lines(d: dict, lang: str) -> list[str]:
    w = WORDS[lang]
    n = lambda x, k=4: "—" if x is None else num(x, lang, k).replace("-", "−")   # noqa: E731
    ok = lambda b: w["ok"] if b else w["fail"]                                      # noqa: E731
    r = d["ratio"]
    ue, ug, ud = agreeing(r["exact"], r["graphical"], sig_decimals(r["exact"]), lang)
    ue, ug = bare(ue), bare(ug) if ug else "—"
    lines = [w["train"] + ":", w["type"].format(t=d["type"], k=d["planets"], m=n(d["module_m"] * 1000),
                                                 w=n(d["omega_rad_s"]["1"])),
             w["zt"].format(z=", ".join(map(str, d["z"])), u=ue,
                            r=w["wanted"].format(r=n(d["ratio_required"])) if d["ratio_required"] is not None else "",
                            g=ug, d=delta_text(ud, lang), b=n(r["bound"], 2),
                            bp=_share(r["bound"], r["exact"], lang), out=w["out"] if r["outside_bound"] else "")]
    c = d["conditions"]
    lines.append(w["cond"].format(c=ok(c["coaxial"]), a=ok(c["assembly"]), n=ok(c["neighbourhood"]),
                                  u=ok(c["no_undercut"])))
    g = d.get("graphical")
    if g:
        lines.append(w["vel"].format(l=n(g["mu_l_m_mm"]), v=n(g["mu_v_mm"]), h=n(g["h_mm"]))
                     + (w["h_H"].format(h=n(g["h_carrier_mm"])) if g.get("h_carrier_mm") else ""))
    rows = [[w["member"], f"ω {w['exact']}", f"ω {w['graph']}", "δ, %"]]
    for k in ("1", "2", "3", "H"):
        name = k if not (k == "2" and d["type"] == "B") else "2, 2'"
        name += w["given_w1"] if k == "1" else ""        # (its reading off the plan a check: stop 49)
        te, tg, e = agreeing(d["omega_rad_s"][k], g["omega_rad_s"][k] if g else None,
                             sig_decimals(d["omega_rad_s"][k]), lang)
        rows.append([name, bare(te), bare(tg) if tg else tg, "" if e is None else delta_text(e, lang)])
    lines += _table(rows)
    if d["candidates"]:
        lines += ["", w["cands"].format(n=d["candidates_passing"])]
        for cnd in d["candidates"]:
            lines.append(f"  z = {', '.join(map(str, cnd['z']))}: D/m = {cnd['diameter_modules']}, u1H = "
                         f"{n(cnd['ratio'])} ({n(cnd['error_pct'], 3)} %)")
        near = d.get("nearest")
        if near and near["z"] not in [c["z"] for c in d["candidates"]]:
            lines.append(w["nearest"].format(z=", ".join(map(str, near["z"])), D=near["diameter_modules"],
                                             u=n(near["ratio"]), e=n(near["error_pct"], 3)))
    return lines


def gears_table(doc: dict[str, Any], lang: str, title: str) -> str:
    """The terminal's report of the pair and the train."""
    w = WORDS[lang]
    lines = [f"{title} — {w['title']}"]
    warnings: list[str] = []
    for key, fn in (("pair", pair_lines), ("planetary", train_lines)):
        if key in doc:
            lines += [""] + fn(doc[key], lang)
            warnings += doc[key]["warnings_uk" if lang == "uk" else "warnings"]
    if warnings:
        lines += ["", w["warn"] + ":"] + [f"  - {x}" for x in warnings]
    return "\n".join(lines).replace("_", "") + "\n"
