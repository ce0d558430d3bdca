"""The s, v, a diagrams as a construction record (drawing mm, y up), stacked on one time base as in
seed 002's figure 2.7: axes, division ordinates, chords, poles P with H1 and H2, rays parallel to the
chords, projection lines to the middles of the intervals, the French curves, labels and scales."""
from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from graphplan.graphic.chords import periodic_spline
from graphplan.graphic.diagrams import v_knots
from graphplan.graphic.record import Record, line_pitch
from graphplan.util.markup import subscripted
from graphplan.util.words import num, unit, word

if TYPE_CHECKING:
    from graphplan.graphic.diagrams import Diagrams

LAYER = "diagrams"
AXIS_W = 0.35          # coordinate axes: solid, between thin and thick
GAP = 14.0             # mm between one diagram's lowest drawing and the next one's highest
TOP = 9.0              # the ordinate axis reaches this far above a diagram's highest point
NUM = 2.5              # lettering of the division numbers
TEXT = 3.5             # lettering of the symbols and scales


def method_words(d: Diagrams, lang: str) -> str:
    """Which graphical differentiation drew the diagrams, as the title and the sheet's notes say it."""
    key = "corrected" if d.correct else d.method
    return word(f"method {key}", lang, e=num(d.angle_error_deg, lang))


def units(d: Diagrams, lang: str) -> tuple[str, str, str]:
    base = "m" if d.unit == "m" else "rad"
    return unit(base, lang), unit(f"{base}/s", lang), unit(f"{base}/s²", lang)


def scale_symbols(d: Diagrams) -> tuple[str, str, str]:
    """The diagrams' scale subscripts in the lab's lower case, named apart from the plans' μ_v, μ_a
    by the quantity each diagram draws: μ_{sF}, μ_{vF}, μ_{aF} for a sliding output F's s_F, v_F, a_F
    (review 10: seed 002's μ_S, μ_V, μ_A read as capitals beside μ_t; μ_A is the dynamics' work
    scale); μ_φ, μ_ω, μ_ε for a link's angle (μ_ψ for a rocker's, ``graphic.diagrams.angle_symbol``)."""
    if d.unit != "m":
        return d.symbols
    p = d.point
    return (f"s{p}", f"v{p}", f"a{p}")


def mu(sub: str) -> str:
    """μ with its subscript as markup: μ_t, μ_{vF}."""
    return f"μ_{sub}" if len(sub) == 1 else f"μ_{{{sub}}}"


def scale_lines(d: Diagrams, lang: str) -> list[str]:
    us, uv, ua = units(d, lang)
    s, v, a = scale_symbols(d)
    mm = unit("mm", lang)
    return [f"{mu(s)} = {fmt(d.mu_s, lang)} {us}/{mm}",
            f"μ_t = T/L = 2π/(ω_1·L) = {fmt(d.mu_t, lang)} {unit('s/mm', lang)}",
            f"{mu(v)} = {mu(s)}/(μ_t·H_1) = {fmt(d.mu_v, lang)} ({uv})/{mm},  H_1 = {fmt(d.H1, lang)} {mm}",
            f"{mu(a)} = {mu(v)}/(μ_t·H_2) = {fmt(d.mu_a, lang)} ({ua})/{mm},  H_2 = {fmt(d.H2, lang)} {mm}"]


def fmt(v: float, lang: str = "en", digits: int = 4) -> str:
    """A scale or value as a draftsman writes it (util.words.num)."""
    return num(v, lang, digits)


def _extent(*arrays) -> tuple[float, float]:
    values = np.concatenate([np.atleast_1d(np.asarray(a, dtype=float)) for a in arrays] + [[0.0]])
    return float(values.min()), float(values.max())


def draw(d: Diagrams, lang: str = "uk") -> Record:
    """The three diagrams of ``d`` stacked (s on top), sharing the abscissa 0 … L mm."""
    r = d.drawn
    x, xm, L, n = d.x, d.x_mid, d.L, d.divisions
    fine = np.linspace(0.0, L, int(round(4 * L)) + 1)
    trend = r.s[-1] - r.s[0]
    s_curve = periodic_spline(x[:-1], r.s[:-1] - trend * x[:-1] / L, L)(fine) + trend * fine / L
    v_curve = periodic_spline(*v_knots(xm, r.v, getattr(r, "v_zeros", np.zeros(0))), L)(fine)
    a_curve = periodic_spline(xm, r.a, L)(fine)
    s_lo, s_hi = _extent(s_curve, r.s)
    v_lo, v_hi = _extent(v_curve, r.v, r.v_ray, r.v_at)
    a_lo, a_hi = _extent(a_curve, r.a, r.a_ray, r.a_at)

    s_sym, v_sym, a_sym = d.symbols
    mu_s, mu_v, mu_a = scale_symbols(d)
    what = word("sliding output" if d.output.kind == "slide" else "rotating output", lang) + " " + subscripted(d.point)
    rec = Record(title=word("diagrams title", lang, what=what, how=method_words(d, lang)),
                 scales={"mu_s": d.mu_s, "mu_t": d.mu_t, "mu_v": d.mu_v, "mu_a": d.mu_a,
                         "H1_mm": d.H1, "H2_mm": d.H2, "L_mm": d.L})
    y_s = 0.0
    y_v = y_s + s_lo - 6.0 - GAP - TOP - v_hi          # 6 mm for the division numbers under s
    y_a = y_v + v_lo - 8.0 - GAP - TOP - a_hi          # 8 mm for the H1 dimension under v
    us, uv, ua = units(d, lang)
    mm = unit("mm", lang)
    left = -max(d.H1, d.H2) - 14.0
    letters = word("letters", lang).split()

    # -- s(t) ------------------------------------------------------------------------------------
    _axes(rec, y_s, s_lo, s_hi, -3.0, L, s_sym, d.sub, "s(t)")
    # one time base (seed 002: "в точках поділу креслимо вздовж осі ординат тонкі лінії"): each
    # division's thin ordinate runs down through the three diagrams, broken for the numbers under s
    _ordinates(rec, x, y_s + s_lo - 1.0, 0.0, s_hi - s_lo + 1.0, "s(t)")
    _ordinates(rec, x, y_a + a_lo, 0.0, (y_s + s_lo - 6.0) - (y_a + a_lo), "v(t), a(t)")
    tangents = d.method == "tangents"
    if tangents:
        _tangents(rec, x[:-1], y_s + r.s[:-1], r.alpha_s, s_sym)
    else:
        for k in range(n):
            rec.segment((x[k], y_s + r.s[k]), (x[k + 1], y_s + r.s[k + 1]), role="chord", layer=LAYER,
                        step=f"chord {k}–{k + 1} of {s_sym}(t)")
    for k in range(n + 1):
        rec.point((x[k], y_s + r.s[k]), role="construction", layer=LAYER, step=f"{s_sym} at ordinate {k}")
    rec.add("polyline", list(zip(fine, y_s + s_curve)), role="curve", layer=LAYER, step=f"{s_sym}(t)")
    _numbers(rec, d, y_s + s_lo - 4.5)
    rec.label((left, y_s + s_hi), letters[0], size=TEXT, layer=LAYER)
    _caption(rec, L, y_s + s_hi, [f"{mu(mu_s)} = {fmt(d.mu_s, lang)} {us}/{mm}",
                                  f"μ_t = {fmt(d.mu_t, lang)} {unit('s/mm', lang)}"])

    # -- v(t): pole P at H1, rays ∥ the chords of s, heights carried to the middles ------------------
    _pole_diagram(rec, d, y_v, v_lo, v_hi, d.H1, r.v_ray, r.v, xm, v_curve, fine, v_sym, "1",
                  source=s_sym)
    if tangents:        # the tangents to the v curve at the division points, for a
        _tangents(rec, x[:-1], y_v + r.v, r.alpha_v, v_sym)
    else:
        for k in range(n):  # the chords of the v curve between the division ordinates, for a
            rec.segment((x[k], y_v + r.v_at[k]), (x[k + 1], y_v + r.v_at[k + 1]), role="chord", layer=LAYER,
                        step=f"chord {k}–{k + 1} of {v_sym}(t)")
    rec.label((left, y_v + v_hi), letters[1], size=TEXT, layer=LAYER)
    _caption(rec, L, y_v + v_hi, [f"{mu(mu_v)} = {fmt(d.mu_v, lang)} ({uv})/{mm}", f"H_1 = {fmt(d.H1, lang)} {mm}"])

    # -- a(t): pole P at H2, rays ∥ the chords of v ------------------------------------------------
    _pole_diagram(rec, d, y_a, a_lo, a_hi, d.H2, r.a_ray, r.a, xm, a_curve, fine, a_sym, "2",
                  source=v_sym)
    _numbers(rec, d, y_a + a_lo - 8.0 - 4.0)
    rec.label((left, y_a + a_hi), letters[2], size=TEXT, layer=LAYER)
    _caption(rec, L, y_a + a_hi, [f"{mu(mu_a)} = {fmt(d.mu_a, lang)} ({ua})/{mm}", f"H_2 = {fmt(d.H2, lang)} {mm}"])
    return rec


def _axes(rec: Record, y0: float, lo: float, hi: float, x_from: float, L: float, sym: str, sub: str,
          step: str) -> None:
    """The ordinate axis (arrow up) at x = 0 and the time axis (arrow right), with their letters."""
    rec.vector((0.0, y0 + lo - 1.0), (0.0, y0 + hi + TOP), role="construction", width=AXIS_W,
               layer=LAYER, step=f"axes of {step}")
    rec.vector((x_from, y0), (L + 10.0, y0), role="construction", width=AXIS_W, layer=LAYER,
               step=f"axes of {step}")
    rec.label((1.8, y0 + hi + TOP - 3.0), f"{sym}_{{{sub}}}" if sub else sym, size=TEXT, layer=LAYER,
              step=f"axes of {step}")
    rec.label((L + 11.5, y0 - 1.2), "t", size=TEXT, layer=LAYER, step=f"axes of {step}")


def _ordinates(rec: Record, x: np.ndarray, y0: float, lo: float, hi: float, step: str) -> None:
    """Thin division ordinates from y0 + lo to y0 + hi."""
    for xk in x[1:]:
        rec.segment((xk, y0 + lo), (xk, y0 + hi), role="grid", layer=LAYER, step=f"division ordinates of {step}")


def _numbers(rec: Record, d: Diagrams, y: float) -> None:
    """The position numbers under the division ordinates (0 … N; every 2nd, 4th … when crowded)."""
    n0 = sum(p is not None for p in d.position[:-1])
    marks = [(xk, d.position[k] if k < d.divisions else n0) for k, xk in enumerate(d.x)]
    marks = [(xk, p) for xk, p in marks if p is not None]
    gap = min(b[0] - a[0] for a, b in zip(marks, marks[1:]))
    every = 1
    while gap * every < 5.0:
        every *= 2
    for xk, p in marks:
        if p % every == 0 or p == n0:
            rec.label((xk, y), str(p), size=NUM, anchor="middle", layer=LAYER, step="division numbers")


def _pole_diagram(rec: Record, d: Diagrams, y0: float, lo: float, hi: float, H: float, ray: np.ndarray,
                  read_: np.ndarray, xm: np.ndarray, curve: np.ndarray, fine: np.ndarray, sym: str,
                  index: str, source: str) -> None:
    """One derived diagram: axes extended left to the pole P, the rays from P to the heights cut on
    the ordinate axis, the projection lines to the middles of the intervals, the points, the curve."""
    step = f"{sym} = d{source}/dt"
    _axes(rec, y0, lo, hi, -H - 4.0, d.L, sym, d.sub, f"{sym}(t)")
    pole = (-H, y0)
    rec.point(pole, role="joint", layer=LAYER, step=f"pole P, H{index} = {H:g} mm")
    rec.label((-H - 1.8, y0 + 1.2), "P", size=TEXT, anchor="end", layer=LAYER, step=f"pole P{index}")
    tangents = d.method == "tangents"
    for k, (h_ray, h_read, xk) in enumerate(zip(ray, read_, xm)):
        rec.segment(pole, (0.0, y0 + h_ray), role="ray", layer=LAYER,
                    step=f"ray P∥tangent at {k} ({step})" if tangents else f"ray P∥chord {k}–{k + 1} ({step})")
        at = f"ordinate {k}" if tangents else f"the middle of {k}–{k + 1}"
        level = h_ray if d.correct else h_read    # corrected: the point moved off its horizontal
        if abs(xk) > 0:
            rec.segment((0.0, y0 + level), (xk, y0 + level), role="projection", layer=LAYER,
                        step=f"{sym} carried to {at}")
        if d.correct:      # the interval's horizontal, against which the areas are balanced
            rec.segment((d.x[k], y0 + h_ray), (d.x[k + 1], y0 + h_ray), role="projection", layer=LAYER,
                        step=f"horizontal of {k}–{k + 1} ({sym})")
        rec.point((xk, y0 + h_read), role="construction", layer=LAYER, step=f"{sym} at {at}")
    rec.add("polyline", list(zip(fine, y0 + curve)), role="curve", layer=LAYER, step=f"{sym}(t)")
    # the pole distance as a dimension under the diagram
    yd = y0 + lo - 4.0
    rec.segment((-H, y0), (-H, yd - 1.5), role="construction", layer=LAYER, step=f"H{index}")
    rec.vector((-H / 2, yd), (-H, yd), role="construction", layer=LAYER, step=f"H{index}")
    rec.vector((-H / 2, yd), (0.0, yd), role="construction", layer=LAYER, step=f"H{index}")
    rec.label((-H / 2, yd - 4.5), f"H_{index}", size=TEXT, anchor="middle", layer=LAYER, step=f"H{index}")


def _tangents(rec: Record, x: np.ndarray, y: np.ndarray, alpha: np.ndarray, sym: str,
              half: float = 10.0) -> None:
    """The tangents drawn at the division points (directions as drawn, with the eye's error)."""
    for k, (xk, yk, a) in enumerate(zip(x, y, alpha)):
        dx, dy = half * math.cos(a), half * math.sin(a)
        rec.segment((xk - dx, yk - dy), (xk + dx, yk + dy), role="chord", layer=LAYER,
                    step=f"tangent at {k} of {sym}(t)")


def _caption(rec: Record, L: float, y: float, lines: list[str]) -> None:
    """Scale captions to the right of a diagram."""
    for i, line in enumerate(lines):
        rec.label((L + 18.0, y - 1.0 - line_pitch(TEXT) * i), line, size=TEXT, layer=LAYER, step="scales")


def diagrams_svg(d: Diagrams, lang: str | None = None) -> str:
    """The three diagrams with their pole constructions as one SVG page in true millimetres."""
    from graphplan.drawing.svg import page_for, render
    rec, w, h = page_for(draw(d, lang or d.lang))
    return render(rec, w, h, rec.title)
