"""`graphplan diagrams`: the contract's JSON and the tables for the terminal (Ukrainian or English)."""
from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np

if TYPE_CHECKING:
    from graphplan.graphic.diagrams import Diagrams


def _num(v) -> float | None:
    v = float(v)
    return v if math.isfinite(v) else None


def _entry(values: dict, pct: dict, truth: dict, key: str, k: int, mm: float) -> dict[str, Any]:
    return {"mm": float(mm), "value": float(values[key][k]), "analytic": float(truth[key][k]),
            "error_pct": _num(pct[key][k])}


def diagrams_json(d: Diagrams) -> dict[str, Any]:
    """The contract's ``diagrams --json`` document, with the lab's table and the diagnostics."""
    from graphplan.graphic.diagrams import ruler_effect
    n = d.divisions
    r = d.drawn
    values, truth = d.values(), d.truth
    pct = {key: d.errors_pct(key) for key in ("s", "v_mid", "a_mid", "v_at", "a_at")}
    cell = lambda key, k, mm: _entry(values, pct, truth, key, k, mm)  # noqa: E731
    at = lambda phi, t: {"phi_deg": float(phi), "t": float(t)}  # noqa: E731
    s = [at(d.phi[k], d.t[k]) | cell("s", k, r.s[k]) for k in range(n + 1)]
    v = [at(d.phi_mid[k], d.t_mid[k]) | cell("v_mid", k, r.v[k]) for k in range(n)]
    a = [at(d.phi_mid[k], d.t_mid[k]) | cell("a_mid", k, r.a[k]) for k in range(n)]
    positions = []
    for k in range(n):
        positions.append({"index": k, "position": d.position[k]} | at(d.phi[k], d.t[k]) | {
            "s": cell("s", k, r.s[k]), "v": cell("v_at", k, r.v_at[k]), "a": cell("a_at", k, r.a_at[k])})
    ex = d.exact
    integration = {
        "v_from_a": _integral(r.v_int, r.v_at, d.maxima["v"] / d.mu_v),
        "s_from_a": _integral(r.s_int, r.s, d.maxima["s"] / d.mu_s),
        "s_from_v": _integral(r.s_int_v, r.s, d.maxima["s"] / d.mu_s),
    }
    return {
        "scene": d.study.mech.title,
        "point": d.point,
        "output": {"kind": d.output.kind, "name": d.output.name, "unit": d.unit},
        "sign": d.sign,
        "divisions": n,
        "L_mm": d.L, "H1_mm": d.H1, "H2_mm": d.H2,
        "precision_mm": d.precision,
        "adaptive": d.adaptive,
        "mu_s": d.mu_s, "mu_t": d.mu_t, "mu_v": d.mu_v, "mu_a": d.mu_a,
        "s": s, "v": v, "a": a,
        "positions": positions,
        "chosen": list(d.chosen),
        "max_error_pct_of_max": {
            "v": float(np.max(np.abs(d.errors_of_max("v_mid")))),
            "a": float(np.max(np.abs(d.errors_of_max("a_mid")))),
            "v_at": float(np.max(np.abs(d.errors_of_max("v_at")))),
            "a_at": float(np.max(np.abs(d.errors_of_max("a_at"))))},
        "chord_error": {
            "v_max_pct_of_max": float(np.max(np.abs(d.errors_of_max("v_mid", ex)))),
            "a_max_pct_of_max": float(np.max(np.abs(d.errors_of_max("a_mid", ex)))),
            "v_estimate_mm": [float(e) for e in d.estimate["v_mm"]],
            "a_estimate_mm": [float(e) for e in d.estimate["a_mm"]]},
        "ruler": ruler_effect(d),
        "integration": integration,
        "warnings": [{k: (float(x) if isinstance(x, (np.floating,)) else x) for k, x in w.items()}
                     for w in d.warnings],
    }


def _integral(got: np.ndarray, ref: np.ndarray, max_mm: float) -> dict[str, Any]:
    dev = got - ref
    return {"mm": [float(g) for g in got], "max_dev_mm": float(np.max(np.abs(dev))),
            "max_dev_pct_of_max": float(100 * np.max(np.abs(dev)) / max_mm),
            "closure_mm": float(dev[-1])}


# -- tables ----------------------------------------------------------------------------------------

WORDS = {
    "uk": {"title": "Кінематичні діаграми {what} методом хорд", "point": "точки", "link": "ланки",
           "scales": "Масштаби", "at": "На ординатах поділу (крива, прочитана на ординатах)",
           "mid": "Ординати методу хорд (посередині інтервалів)", "chosen": "У двох заданих положеннях",
           "no": "№", "int": "інт.", "graph": "графічно", "exact": "точно", "err": "δ, %",
           "integ": "Графічне інтегрування (зворотна побудова)", "warn": "Попередження",
           "v_from_a": "v з a", "s_from_a": "s з a через v", "s_from_v": "s з ординат v",
           "dev": "найбільше відхилення {mm:.2f} мм ({pct:.2f} % від максимуму), незамикання {cl:+.2f} мм",
           "m": "м", "s": "с", "mm": "мм", "rad": "рад", "none": "немає",
           "period": "T = 2π/ω1 = {T:.4g} с на L = {L:g} мм"},
    "en": {"title": "Kinematic diagrams of {what} by the method of chords", "point": "point", "link": "link",
           "scales": "Scales", "at": "At the division ordinates (the curves read there)",
           "mid": "The chords' ordinates (at the middles of the intervals)", "chosen": "At the two chosen positions",
           "no": "No", "int": "int.", "graph": "graph.", "exact": "exact", "err": "δ, %",
           "integ": "Graphical integration (the reverse construction)", "warn": "Warnings",
           "v_from_a": "v from a", "s_from_a": "s from a through v", "s_from_v": "s from the v ordinates",
           "dev": "largest deviation {mm:.2f} mm ({pct:.2f} % of the maximum), closure {cl:+.2f} mm",
           "m": "m", "s": "s", "mm": "mm", "rad": "rad", "none": "none",
           "period": "T = 2π/ω1 = {T:.4g} s over L = {L:g} mm"},
}


def units(d: Diagrams, lang: str) -> tuple[str, str, str]:
    w = WORDS[lang]
    base = w["m"] if d.unit == "m" else w["rad"]
    return base, f"{base}/{w['s']}", f"{base}/{w['s']}²"


def scale_lines(d: Diagrams, lang: str) -> list[str]:
    w = WORDS[lang]
    us, uv, ua = units(d, lang)
    s, v, a = d.symbols
    return [f"μ{s} = {fmt(d.mu_s, lang)} {us}/{w['mm']}",
            f"μt = T/L = 2π/(ω1·L) = {fmt(d.mu_t, lang)} {w['s']}/{w['mm']}",
            f"μ{v} = μ{s}/(μt·H1) = {fmt(d.mu_v, lang)} ({uv})/{w['mm']},  H1 = {d.H1:g} {w['mm']}",
            f"μ{a} = μ{v}/(μt·H2) = {fmt(d.mu_a, lang)} ({ua})/{w['mm']},  H2 = {d.H2:g} {w['mm']}"]


SUPER = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


def fmt(v: float, lang: str = "en", digits: int = 4) -> str:
    """A scale or value as a draftsman writes it: 4 significant digits, ·10ⁿ for very small or
    large numbers, the decimal comma in Ukrainian."""
    if v == 0 or not math.isfinite(v):
        text = f"{v:g}"
    else:
        e = math.floor(math.log10(abs(v)))
        if -4 <= e < 6:
            text = f"{v:.{max(digits - 1 - e, 0)}f}"
            if "." in text:
                text = text.rstrip("0").rstrip(".")
        else:
            m = f"{v / 10 ** e:.{digits - 1}f}".rstrip("0").rstrip(".")
            text = f"{m}·10{str(e).translate(SUPER)}"
    return text.replace(".", ",") if lang == "uk" else text


def _pct(p) -> str:
    return "—" if p is None or not math.isfinite(p) else f"{p:+.2f}"


def diagrams_table(d: Diagrams, lang: str = "uk") -> str:
    w = WORDS[lang]
    s_, v_, a_ = d.symbols
    us, uv, ua = units(d, lang)
    what = f"{w['point'] if d.output.kind == 'slide' else w['link']} {d.point}"
    lines = [d.study.mech.title, w["title"].format(what=what),
             w["period"].format(T=d.study.mech.period, L=d.L), f"{w['scales']}:"]
    lines += ["  " + t for t in scale_lines(d, lang)]
    vals = d.values()

    def block(title: str, head: list[str], rows: list[list[str]]) -> None:
        widths = [max(len(h), *(len(r[i]) for r in rows)) for i, h in enumerate(head)]
        lines.append("")
        lines.append(title)
        lines.append("  ".join(h.rjust(wd) for h, wd in zip(head, widths)))
        for r in rows:
            lines.append("  ".join(c.rjust(wd) for c, wd in zip(r, widths)))

    def g(x: float, key: str) -> str:
        """5 significant digits; round-off below 1e-9 of the cycle's maximum shows as 0."""
        return f"{0.0 if abs(x) <= 1e-9 * d.maxima[key] else x + 0.0:.5g}"

    def row_at(k: int) -> list[str]:
        r = d.drawn
        pos = d.position[k]
        return [str(pos if pos is not None else f"({k})"), f"{d.phi[k]:.2f}", f"{r.s[k]:.1f}",
                g(vals['s'][k], "s"), g(d.truth['s'][k], "s"),
                f"{r.v_at[k]:.1f}", g(vals['v_at'][k], "v"), g(d.truth['v_at'][k], "v"),
                _pct(d.errors_pct('v_at')[k]),
                f"{r.a_at[k]:.1f}", g(vals['a_at'][k], "a"), g(d.truth['a_at'][k], "a"),
                _pct(d.errors_pct('a_at')[k])]

    mm = w["mm"]
    head = [w["no"], "φ, °", f"{s_}, {mm}", f"{s_}, {us}", w["exact"], f"{v_}, {mm}", f"{v_}, {uv}", w["exact"],
            w["err"], f"{a_}, {mm}", f"{a_}, {ua}", w["exact"], w["err"]]
    block(w["at"], head, [row_at(k) for k in range(d.divisions)])
    chosen = [k for k in range(d.divisions) if d.position[k] in d.chosen]
    if chosen:
        block(w["chosen"], head, [row_at(k) for k in chosen])
    rows = []
    for k in range(d.divisions):
        r = d.drawn
        rows.append([f"{k}–{k + 1}", f"{d.phi_mid[k]:.2f}", f"{r.v[k]:.1f}", g(vals['v_mid'][k], "v"),
                     g(d.truth['v_mid'][k], "v"), _pct(d.errors_pct('v_mid')[k]),
                     f"{r.a[k]:.1f}", g(vals['a_mid'][k], "a"), g(d.truth['a_mid'][k], "a"),
                     _pct(d.errors_pct('a_mid')[k])])
    block(w["mid"], [w["int"], "φ, °", f"{v_}, {mm}", f"{v_}, {uv}", w["exact"], w["err"],
                     f"{a_}, {mm}", f"{a_}, {ua}", w["exact"], w["err"]], rows)
    lines.append("")
    lines.append(w["integ"] + ":")
    r = d.drawn
    for key, got, ref, mx in (("v_from_a", r.v_int, r.v_at, d.maxima["v"] / d.mu_v),
                              ("s_from_a", r.s_int, r.s, d.maxima["s"] / d.mu_s),
                              ("s_from_v", r.s_int_v, r.s, d.maxima["s"] / d.mu_s)):
        dev = got - ref
        lines.append(f"  {w[key]}: " + w["dev"].format(mm=float(np.max(np.abs(dev))),
                                                        pct=float(100 * np.max(np.abs(dev)) / mx), cl=float(dev[-1])))
    lines.append("")
    lines.append(w["warn"] + ":" + ("" if d.warnings else " " + w["none"]))
    for item in d.warnings:
        lines.append("  - " + item["message_uk" if lang == "uk" else "message"])
    return "\n".join(lines) + "\n"
