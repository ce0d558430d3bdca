"""The cam's results for people and programs: the contract's ``cam --json`` and the terminal's tables
(both languages, the lab's notation: s, ds/dφ, d²s/dφ², R0, e, ϑ, [ϑ], μ_s, μ_φ)."""
from __future__ import annotations

import math
from typing import Any

import numpy as np

from graphplan.exact.cam import Solution
from graphplan.graphic.cam import SHORT_DIVISIONS, CamConstruction, division_numbers, errors_pct, read
from graphplan.graphic.diagrams import LAB_LIMIT
from graphplan.drawing.cam import corner_name, scale_text, symbols
from graphplan.util.markup import plain
from graphplan.util.words import column_decimals, fixed, num


def _f(x) -> float | None:
    x = float(x)
    return x if math.isfinite(x) else None


def cam_json(sol: Solution, g: CamConstruction, scene: str) -> dict[str, Any]:
    """The contract's document (lengths in m, angles in degrees; a rocking follower's s in degrees of
    the arm's swing, its ds/dφ and d²s/dφ² per radian of the cam's turn)."""
    cam = sol.cam
    ex = sol.at(g.phi, g.phase)
    for key in ("s", "v", "a", "theta"):          # round-off below 1e-12 of the largest value is 0
        big = float(np.max(np.abs(ex[key]))) or 1.0
        ex[key] = np.where(np.abs(ex[key]) < 1e-12 * big, 0.0, ex[key])
    unit = math.degrees(1.0) if cam.rocking else 1.0        # a rocking follower's angles in degrees
    s_scale = cam.stroke
    v_scale = float(np.max(np.abs(sol.at(np.linspace(0, 360, 3601))["v"])))
    # no δ where the exact ordinate is under two ruler divisions (graphic.cam.errors_pct)
    es = errors_pct(g.s, ex["s"], s_scale, SHORT_DIVISIONS * g.precision * g.mu_s)
    ev = errors_pct(g.v, ex["v"], v_scale, SHORT_DIVISIONS * g.precision * g.mu_v)
    et = errors_pct(g.theta, ex["theta"], max(cam.allowed))
    positions = []
    names = division_numbers(cam.phases, len(g.phi))      # no far dwell: the rise's end and the return's start one point
    for k, phi in enumerate(g.phi):
        P = ex["P"][k]
        positions.append({
            "number": names[k], "phi_deg": float(phi), "phase": "rise" if g.phase[k] == 0 else "return",
            "exact": {"s" + ("_deg" if cam.rocking else "_m"): float(ex["s"][k] * unit),
                      "ds_dphi" + ("_deg" if cam.rocking else "_m"): float(ex["v"][k] * unit),
                      "d2s_dphi2" + ("_deg" if cam.rocking else "_m"): float(ex["a"][k] * unit),
                      "pressure_angle_deg": float(ex["theta"][k]), "radius_m": float(ex["radius"][k]),
                      "profile_m": [float(P.real), float(P.imag)]},
            "graphical": {"s" + ("_deg" if cam.rocking else "_m"): float(g.s[k] * unit),
                          "ds_dphi" + ("_deg" if cam.rocking else "_m"): float(g.v[k] * unit),
                          "d2s_dphi2" + ("_deg" if cam.rocking else "_m"): float(g.a[k] * unit),
                          "pressure_angle_deg": float(g.theta[k]),
                          "radius_m": float(g.radius_mm[k] * g.mu_l),
                          "s_mm": float(g.s_mm[k]), "ds_dphi_mm": float(g.v_mm[k]), "d2s_dphi2_mm": float(g.a_mm[k]),
                          "radius_mm": float(g.radius_mm[k])},
            "error_pct": {"s": es[k], "ds_dphi": ev[k], "pressure_angle": et[k]}})
    doc: dict[str, Any] = {
        "scene": scene, "follower": cam.follower, "roller_radius_m": cam.roller, "omega_rad_s": cam.omega,
        "sense": "ccw" if cam.sense > 0 else "cw",
        "phases_deg": dict(zip(("rise", "dwell_far", "return", "dwell_near"), cam.phases)),
        "laws": {"rise": cam.laws[0], "return": cam.laws[1]},
        "pressure_angle_allowed_deg": {"rise": cam.allowed[0], "return": cam.allowed[1]},
        "base_radius_min_m": sol.R0_min, "base_radius_m": sol.geometry.R0,
        "base_radius_given": cam.base_radius is not None,
        "divisions": int(len(g.phi) // 2 - 1), "precision_mm": g.precision,
        "scales": {"mu_phi_rad_mm": g.mu_phi, "mu_a_mm": g.mu_a, "mu_v_mm": g.mu_v, "mu_s_mm": g.mu_s,
                   "mu_l_m_mm": g.mu_l, "H1_mm": g.H1, "H2_mm": g.H2},
        "positions": positions,
        "base_radius_graphical_m": _f(g.R0_min),
        "base_radius_error_pct": None if not math.isfinite(g.R0_min) else 100.0 * (g.R0_min - sol.R0_min) / sol.R0_min,
        "pressure_angle_max_deg": dict(zip(("rise", "return"), sol.pressure_maxima())),
        "pressure_angle_extreme_deg": dict(zip(("rise", "return"), sol.pressure_extremes())),
        # where each phase's largest |ϑ| falls (stop 56: a rocking arm's rise has it at φ = 0°, where it rests)
        "pressure_angle_extreme_phi_deg": dict(zip(("rise", "return"), (p for p, _ in sol.pressure_extreme_points()))),
        "curvature_min_m": _f(sol.curvature_min()),
        # the centre profile's concave stretches (stop 62): ρ_min is over the convex parts
        "profile_concave": [{"from_deg": a, "to_deg": b, "rho_min_m": r} for a, b, r in sol.concave()],
        "profile_corners": [{"phi_deg": c.phi_deg, "ds_dphi_before" + ("_deg" if cam.rocking else "_m"): c.v_before * unit,
                             "ds_dphi_after" + ("_deg" if cam.rocking else "_m"): c.v_after * unit,
                             "convex": c.convex, **_sides_theta(sol, c.phi_deg)} for c in sol.corners()],
        # the shocks by kind, from the one-sided ds/dφ, d²s/dφ² (exact.cam.shocks), not the law's name
        "shocks": [{"phi_deg": x.phi_deg, "kind": x.kind} for x in sol.shocks()],
        "closing_mm": {"rise": float(g.closing[0]), "return": float(g.closing[1])},
        "redrawn": None if g.redrawn is None else {
            "divisions_first": int(g.redrawn[0]),
            "closing_mm_first": {"rise": float(g.redrawn[1]), "return": float(g.redrawn[2])},
            "closing_bound_mm_first": float(g.redrawn[3]),
            "divisions_first_given": bool(g.redrawn[4]) if len(g.redrawn) > 4 else False},
        "warnings": [en for en, _ in sol.warnings + g.warnings],
        "warnings_uk": [uk for _, uk in sol.warnings + g.warnings]}
    if cam.rocking:
        doc.update(swing_deg=math.degrees(cam.stroke), arm_m=cam.arm, centre_distance_m=cam.centre_distance,
                   arm_angle_deg=math.degrees(sol.geometry.psi0), **_dwells(sol))
    else:
        doc.update(stroke_m=cam.stroke, offset_m=sol.geometry.e, offset_auto=cam.offset is None)
    return doc


WORDS = {
    "uk": {"title": "Синтез кулачкового механізму", "translating": "поступальний штовхач",
           "rocking": "коромисловий штовхач", "law": "закони: підйом — {r}, опускання — {t}",
           "laws": {"parabolic": "параболічний", "cosine": "косинусоїдальний", "cycloidal": "синусоїдальний (циклоїдальний)",
                    "linear": "лінійний", "trapezoidal": "трапецеїдальний"},
           "phases": "фази: φ_п = {a}°, φ_вв = {b}°, φ_с = {c}°, φ_бв = {d}°",
           "radius": "R_0 найменший = {m} мм (графічно {g} мм, похибка {e} %); прийнято R_0 = {r} мм",
           "radius_under": "R_0 найменший = {m} мм (графічно {g} мм, похибка {e} %); прийнято R_0 = {r} мм — "
                           "точний найменший, округлений угору (графічний більший на похибку побудови)",
           "radius_given": "R_0 найменший = {m} мм (графічно {g} мм, похибка {e} %); задано R_0 = {r} мм",
           "radius_small": "R_0 найменший = {m} мм (графічно {g} мм, похибка {e} %); задано R_0 = {r} мм — менший "
                           "за найменший: кут тиску перевищує допустимий (*), слід прийняти R_0 ≥ {k} мм",
           "stroke": "хід h = {h} мм", "swing": "кут розмаху ψ_{{max}} = {h}°",
           "omega": "кулачок обертається {d}, ω = {w} рад/с",
           "sense": {"cw": "за годинниковою стрілкою", "ccw": "проти годинникової стрілки"},
           "offset": "ексцентриситет e = {e} мм",
           "dwell": "на ближньому вистої ϑ = {t}° ≠ 0: профіль там — дуга кола з центром O, його нормаль — пряма "
                    "CO, а {c} рухається перпендикулярно до коромисла O_{{1}}C, тож ϑ = {f} "
                    "з трикутника OO_{{1}}C (a, l, R_0)",
           "dwells": "на вистоях ϑ ≠ 0 (ближньому {t}°, віддаленому {u}°): профіль там — дуги кіл з центром O, їх "
                     "нормаль — пряма CO, а {c} рухається перпендикулярно до коромисла O_{{1}}C, тож "
                     "ϑ = {f} з трикутника OO_{{1}}C (a, l і R_0 = {r} мм на ближньому, "
                     "R_{{max}} = {m} мм на віддаленому)",
           "offset_side": " (вісь штовхача на {d} мм {side} від O: {effect} кут тиску на підйомі й {other} — на "
                          "опусканні{why})",
           "offset_auto": "; e обрано так, щоб R_0 був найменшим",
           "central": " (центральний штовхач: його вісь проходить через O)",
           "side": ("праворуч", "ліворуч"), "effect": ("зменшує", "збільшує"), "other": ("збільшує", "зменшує"), "arm": "коромисло l = {l} мм, a = {a} мм, ψ_0 = {p}°",
           "angles": "найбільший кут тиску на фазі: підйом {r}, опускання {t} (допустимо [ϑ] = {ar}°, {at}°)",
           "angle_at": "{a}° при φ = {p}°", "angle_end": ("на початку фази", "в кінці фази"),
           "curv": "найменший радіус кривини центрового профілю ρ_{{min}} = {c} мм, ролик r = {r} мм",
           "knife": "найменший радіус кривини профілю ρ_{{min}} = {c} мм (штовхач із вістрям, без ролика)",
           "smooth": "на гладких ділянках",
           "convex_parts": "на опуклих ділянках", "smooth_convex": "на гладких опуклих ділянках",
           "concave_at": "угнутий при φ = {l}", "concave_one": "{a}…{b}° (|ρ| ≥ {r} мм)",
           "corners": "центровий профіль має злами (ρ = 0, ρ_{{min}} там не визначений), де {v} стрибає: {c}",
           "corner": "{n} при φ = {p}° ({a} → {b} {u}; {k})",
           "shocks": "удари: {l}", "no_shocks": "ударів немає ({v}, {a} неперервні)",
           "shock": {"rigid": "жорсткі (стрибок {v}) при φ = {p}", "soft": "м’які (стрибок {a}) при φ = {p}"},
           "convex": "опуклий: на робочому профілі гостре ребро, ролик перекочується через нього, його центр "
                     "іде дугою радіуса r навколо ребра, зрізаючи злам",
           "concave": "угнутий: робочий профіль тут — дуга радіуса r навколо зламу",
           "sharp": "штовхач із вістрям натрапляє на гострий злам",
           "scales": "масштаби: {p}, {a}, {v}, {s}, {l}; H_1\u00a0=\u00a0{h1}\u00a0мм, H_2\u00a0=\u00a0{h2}\u00a0мм",
           "closing": "графік {q} замкнуто: {which} розподілено по поділках пропорційно "
                      "куту (ординату y_k зменшено на Δ·k/n){tail}",
           "closing_one": ("похибку замикання підйому Δ = {d} мм", "похибку замикання опускання Δ = {d} мм"),
           "closing_tail": ("; підйом замкнувся без поправки (Δ = 0)", "; опускання замкнулося без поправки (Δ = 0)"),
           "closing_two": "похибки замикання підйому Δ = {r} мм і опускання Δ = {t} мм",
           "closed": "графік {q} замкнувся без поправки: похибка замикання підйому й опускання Δ = 0 "
                     "(з точністю лінійки)",
           "redrawn": "діаграми перебудовано з {n} поділками замість {f}: при {f} {q} не замкнулося на Δ = {r} мм "
                      "(підйом), {t} мм (опускання) — правило: {q} замикається в межах 2\u00a0% ходу на кресленні й "
                      "половини поділки лінійки ({b} мм)",
           "given": "{f} {word} задано; графік {q} побудовано при {n}, бо при {f} він не замикається "
                    "({D}\u00a0=\u00a0{d}\u00a0>\u00a0{b}\u00a0мм)",
           "head": ["φ, °", "s, {s}", "s граф.", "δs, %", "ds/dφ, {v}", "ds/dφ граф.", "δ, %", "ϑ, °", "ϑ граф.",
                    "R, мм", "R граф."],
           "warn": "Попередження",
           "point_c": ("центр ролика C", "вістря C")},
    "en": {"title": "Cam synthesis", "translating": "translating follower", "rocking": "rocking follower",
           "law": "laws: rise {r}, return {t}",
           "laws": {"parabolic": "parabolic", "cosine": "cosine (harmonic)", "cycloidal": "cycloidal (sine)",
                    "linear": "linear", "trapezoidal": "trapezoidal"},
           "phases": "phases: φ_{{rise}} = {a}°, φ_{{far}} = {b}°, φ_{{return}} = {c}°, φ_{{near}} = {d}°",
           "radius": "smallest R_0 = {m} mm (graphically {g} mm, error {e} %); R_0 taken = {r} mm",
           "radius_under": "smallest R_0 = {m} mm (graphically {g} mm, error {e} %); R_0 taken = {r} mm — the exact "
                           "smallest rounded up (the graphical one is over it by the construction's error)",
           "radius_given": "smallest R_0 = {m} mm (graphically {g} mm, error {e} %); R_0 given = {r} mm",
           "radius_small": "smallest R_0 = {m} mm (graphically {g} mm, error {e} %); R_0 given = {r} mm — below the "
                           "smallest: the pressure angle exceeds the allowed one (*); take R_0 ≥ {k} mm",
           "stroke": "stroke h = {h} mm", "swing": "swing ψ_{{max}} = {h}°",
           "omega": "the cam turning {d}, ω = {w} rad/s",
           "sense": {"cw": "clockwise", "ccw": "counter-clockwise"},
           "offset": "offset e = {e} mm",
           "dwell": "on the near dwell ϑ = {t}° ≠ 0: the profile there an arc about O, its normal the line CO, "
                    "and {c} moves square to the arm O_{{1}}C, so ϑ = {f} from the triangle "
                    "OO_{{1}}C (a, l, R_0)",
           "dwells": "on the dwells ϑ ≠ 0 (near {t}°, far {u}°): the profile there arcs about O, their normal the "
                     "line CO, and {c} moves square to the arm O_{{1}}C, so ϑ = {f} from the "
                     "triangle OO_{{1}}C (a, l and R_0 = {r} mm on the near dwell, R_{{max}} = {m} mm on the far one)",
           "offset_side": " (the axis of the follower {d} mm {side} of O, {effect} the pressure angle of the rise "
                          "and {other} that of the return{why})",
           "offset_auto": "; e chosen for the smallest R_0",
           "central": " (a central follower: its axis passes through O)",
           "side": ("right", "left"), "effect": ("lowering", "raising"), "other": ("raising", "lowering"), "arm": "arm l = {l} mm, a = {a} mm, ψ_0 = {p}°",
           "angles": "largest pressure angle over the phase: rise {r}, return {t} (allowed [ϑ] = {ar}°, {at}°)",
           "angle_at": "{a}° at φ = {p}°", "angle_end": ("the start of the phase", "the end of the phase"),
           "curv": "smallest radius of curvature of the centre profile ρ_{{min}} = {c} mm, roller r = {r} mm",
           "knife": "smallest radius of curvature of the profile ρ_{{min}} = {c} mm (a knife-edge follower, no roller)",
           "smooth": "over the smooth parts",
           "convex_parts": "over the convex parts", "smooth_convex": "over the smooth convex parts",
           "concave_at": "concave at φ = {l}", "concave_one": "{a}…{b}° (|ρ| ≥ {r} mm)",
           "corners": "corners of the centre profile (ρ = 0 there, ρ_{{min}} undefined) where {v} jumps: {c}",
           "corner": "{n} at φ = {p}° ({a} → {b} {u}; {k})",
           "shocks": "shocks: {l}", "no_shocks": "no shocks ({v}, {a} continuous)",
           "shock": {"rigid": "rigid (a jump of {v}) at φ = {p}", "soft": "soft (a jump of {a}) at φ = {p}"},
           "convex": "convex: a sharp edge on the working profile, which the roller rolls over, its centre "
                     "cutting the corner on an arc of radius r about the edge",
           "concave": "concave: the working profile there an arc of radius r about it",
           "sharp": "a knife-edge follower meets a sharp corner",
           "scales": "scales: {p}, {a}, {v}, {s}, {l}; H_1\u00a0=\u00a0{h1}\u00a0mm, H_2\u00a0=\u00a0{h2}\u00a0mm",
           "closing": "the graphical {q} closed: {which} laid back over the divisions in proportion to the "
                      "turn (the ordinate y_k lowered by Δ·k/n){tail}",
           "closing_one": ("the closing error of the rise Δ = {d} mm", "the closing error of the return Δ = {d} mm"),
           "closing_tail": ("; the rise closed as drawn (Δ = 0)", "; the return closed as drawn (Δ = 0)"),
           "closing_two": "the closing errors Δ = {r} mm (rise) and Δ = {t} mm (return)",
           "closed": "the graphical {q} closed as drawn: the closing error of the rise and of the return "
                     "Δ = 0 (to the ruler)",
           "redrawn": "the diagrams redrawn with {n} divisions instead of {f}: at {f} {q} missed its closing by "
                      "Δ = {r} mm (rise), {t} mm (return) — the rule: {q} closes within 2\u00a0% of the stroke drawn "
                      "and the ruler's half division ({b} mm)",
           "given": "{f} divisions given; the {q} diagram drawn with {n}, as at {f} it does not close "
                    "({D}\u00a0=\u00a0{d}\u00a0>\u00a0{b}\u00a0mm)",
           "head": ["φ, °", "s, {s}", "s gr.", "δs, %", "ds/dφ, {v}", "ds/dφ gr.", "δ, %", "ϑ, °", "ϑ gr.",
                    "R, mm", "R gr."],
           "warn": "Warnings",
           "point_c": ("the roller centre C", "the knife-edge's point C")},
}


def _dwell_formula(doc: dict[str, Any], near: float) -> str:
    """ϑ on a rocking follower's dwell from the triangle OO₁C with the sign the table prints it with:
    «90° − ∠OCO₁» or «∠OCO₁ − 90°» (the sign turns with the cam's sense; stop 51: a clockwise cam's
    note said 90° − ∠OCO₁ = 90° − 107.18° beside its printed +17.18°), ∠OCO₁ by the law of cosines from
    a, l and R0: cos ∠OCO₁ = (l² + R0² − a²)/(2·l·R0)."""
    a, l, r = doc["centre_distance_m"], doc["arm_m"], doc["base_radius_m"]
    gamma = math.degrees(math.acos(max(-1.0, min(1.0, (l * l + r * r - a * a) / (2 * l * r)))))
    return "90° − ∠OCO_{1}" if abs((90.0 - gamma) - near) <= abs((gamma - 90.0) - near) else "∠OCO_{1} − 90°"


def _sides_theta(sol: Solution, phi: float) -> dict[str, float]:
    """The exact pressure angle just before and just after a corner of the centre profile at ``phi``°
    (ds/dφ jumps there, and ϑ with it: the linear law's ends — stop 51, Table 1 gave one side)."""
    from graphplan.exact.cam import profile, sides
    before, after = sides(sol.cam, phi)          # the law's own values at the phase's ends (stop 55)
    s, v, a = (np.array([x, y]) for x, y in zip(before, after))
    th = profile(sol.cam, sol.geometry, np.array([phi, phi]), s, v, a)["theta"]
    return {"pressure_angle_before_deg": float(th[0]), "pressure_angle_after_deg": float(th[1])}


def _dwells(sol: Solution) -> dict[str, Any]:
    """A rocking follower's pressure angle in the middle of each dwell and |OC| there (R0 on the near
    dwell, R_max on the far one; None where the dwell is 0°): the profile there an arc about O, its
    normal CO, C moving square to the arm O₁C, so ϑ = 90° − ∠OCO₁ of the triangle OO₁C — ≠ 0."""
    rise, far, ret, near = sol.cam.phases
    mids = {"near": rise + far + ret + near / 2 if near > 0 else None, "far": rise + far / 2 if far > 0 else None}
    theta, radius = {}, {}
    for k, phi in mids.items():
        if phi is None:
            theta[k] = radius[k] = None
            continue
        at = sol.at(np.array([phi % 360.0]))
        theta[k], radius[k] = float(at["theta"][0]), float(abs(at["P"][0]))
    return {"dwell_pressure_angle_deg": theta, "dwell_radius_m": radius}


def printed_error(graphical: str, exact: str, judged: bool) -> float | None:
    """δ = 100·(g − e)/|e| % worked out from the two printed numbers (the sign by the graphical
    value's side of the exact, as graphic.cam ``errors_pct``), so a reader who recomputes δ from the
    table gets the printed δ; None where the exact value has no error (below 1 % of the largest) or
    prints 0."""
    if not judged or graphical in ("—", "") or exact in ("—", ""):
        return None
    g, e = (float(x.replace("−", "-").replace(",", ".")) for x in (graphical, exact))
    return 100.0 * (g - e) / abs(e) if e else None


def ruler_decimals(values, mm, precision: float) -> int:
    """The most decimals a column read off the drawing writes: one past the decimal of its reading's
    resolution, μ × the ruler's step (μ_s = 0,38 mm/mm at 0.5 mm: ±0,19 mm, so two: 0,38 from a
    1 mm ordinate, 31,99 from 84 mm — not 31,985, five figures out of a ruler's three). An exact
    ruler (0) or nothing read: no bound."""
    mus = [abs(v / y) for v, y in zip(values, mm) if y and v]
    if not mus or precision <= 0:
        return 99
    return max(0, math.ceil(-math.log10(mus[0] * precision))) + 1


def table_columns(doc: dict[str, Any], lang: str) -> dict[str, list[str]]:
    """Table 1's columns as the sheet and the terminal both print them: one count of decimals a
    column, the exact and the graphical value of a quantity to the same decimals (``util.words.
    column_decimals`` over both, no finer than the reading supports: ``ruler_decimals``), δ % to 0.01 worked out from the printed pair (``printed_error``;
    "*" past the lab's 5 %), the ruler's ordinates y to its 0.1 mm (0.01 mm for a finer ruler), ϑ to
    0.1°; s (translating, mm; rocking ψ, °) and ds/dφ (per radian of the cam's turn)."""
    rocking = doc["follower"] == "rocking"
    key = "_deg" if rocking else "_m"
    k = 1.0 if rocking else 1000.0
    ps = doc["positions"]
    precision = doc.get("precision_mm", 0.5)
    ruler = 1 if precision >= 0.1 or precision == 0 else 2
    turns = [p["phi_deg"] for p in ps]
    whole = all(abs(x - round(x)) < 1e-9 for x in turns)      # 10 divisions of 100°: 10, not 10,0
    out: dict[str, list[str]] = {"phi": cells(turns, lang, 0 if whole else 1)}
    for name, q in (("s", "s"), ("v", "ds_dphi")):
        ex = [p["exact"][q + key] * k for p in ps]
        gr = [p["graphical"][q + key] * k for p in ps]
        d = min(column_decimals(ex + gr), ruler_decimals(gr, [p["graphical"][q + "_mm"] for p in ps], precision))
        out[name], out[name + "_gr"] = cells(ex, lang, d), cells(gr, lang, d)
        out[name + "_mm"] = cells([p["graphical"][q + "_mm"] for p in ps], lang, ruler)
        errs = [printed_error(g, e, p["error_pct"][q] is not None)
                for g, e, p in zip(out[name + "_gr"], out[name], ps)]
        out["d" + name] = ["—" if v is None else cells([v], lang, 2)[0] + ("*" if abs(round(v, 2)) > LAB_LIMIT else "")
                           for v in errs]
    # ϑ to 0.1°, «*» where the printed value is past its phase's allowed [ϑ] (as δ's «*» judges the printed δ):
    # the notes star the phase's largest (angles_over), the rows past [ϑ] were bare (review 60 #5: 30,8° > 30°)
    allowed = doc["pressure_angle_allowed_deg"]
    for name, side in (("theta", "exact"), ("theta_gr", "graphical")):
        vals = [p[side]["pressure_angle_deg"] for p in ps]
        out[name] = [c + ("*" if abs(round(v, 1)) > allowed[p["phase"]] + 1e-9 else "")
                     for c, v, p in zip(cells(vals, lang, 1), vals, ps)]
    jumps(out, doc, lang, d, ruler)          # d: the ds/dφ columns' decimals (the loop's last)
    ex = [p["exact"]["radius_m"] * 1000 for p in ps]
    gr = [p["graphical"]["radius_mm"] * doc["scales"]["mu_l_m_mm"] * 1000 for p in ps]
    d = column_decimals(ex + gr)
    out["R"], out["R_gr"] = cells(ex, lang, d), cells(gr, lang, d)
    return out


def cells(values, lang: str, decimals: int) -> list[str]:
    """A column of Table 1 to one count of decimals, a true minus; a value that prints as zero the bare
    number 0, as the seeds' tables write it (seed 000's Tables 2.2–2.3: 0 beside 1,4 and 23,5; seed
    004's Table 3: 0 beside −18,75) and the kinematics and dynamics tables do (``util.words.
    decimals_column``) — stop 54 took the seeds' rule over stop 53's 0,00."""
    return ["0" if round(float(v), decimals) == 0 else fixed(v, lang, decimals).replace("-", "−") for v in values]


def jumps(out: dict[str, list[str]], doc: dict[str, Any], lang: str, decimals: int, ruler: int) -> None:
    """Table 1's ds/dφ cells at a jump of ds/dφ (the linear law's ends, ``profile_corners``) as the
    notes write it, both sides: «0 → 20,37» (exact), «0 → 51,0» (the ruler's ordinate) and
    «0 → 20,40» (graphical) — one side was the row's alone (stop 50). The side the row lacks is read
    as the drawing reads a linear law's ordinate, ds/dφ/μ to the ruler's ``precision_mm`` (graphic.
    cam ``read``: a dwell's 0 is 0), with μ the row's own value over its ordinate; δ stays the row's."""
    rocking = doc["follower"] == "rocking"
    key, k = ("_deg", 1.0) if rocking else ("_m", 1000.0)
    precision = doc.get("precision_mm", 0.5)
    # a jump's zero side the bare 0, as the notes write it («φ = 0° (0 → 20,37 мм/рад)»): "0,00 → 20,37" widened
    # the 3.5-mm table's column past the A1 sheet's right column (stop 53: CAM50's diagrams a μ_φ coarser)
    cell = lambda v, d: "0" if round(v, d) == 0 else fixed(v, lang, d).replace("-", "−")       # noqa: E731
    # μ of the ds/dφ diagram from the rows whose ordinate is not 0 (one scale for all): a row whose own side is 0
    # (a parabolic rise's end into a linear return, stop 55) read the other side through μ too — it had none,
    # and printed «0» for the ruler's ordinate and the graphical value where the exact cell says «0 → −28,65»
    mus = [p["graphical"]["ds_dphi" + key] * k / p["graphical"]["ds_dphi_mm"] for p in doc["positions"]
           if p["graphical"]["ds_dphi_mm"]]
    mu_all = float(np.median(mus)) if mus else None
    for corner in doc.get("profile_corners") or []:
        before, after = (corner["ds_dphi_" + side + key] * k for side in ("before", "after"))
        for j, p in enumerate(doc["positions"]):
            if abs((p["phi_deg"] - corner["phi_deg"] + 180.0) % 360.0 - 180.0) > 1e-6:
                continue
            own, y = p["exact"]["ds_dphi" + key] * k, p["graphical"]["ds_dphi_mm"]
            mu = p["graphical"]["ds_dphi" + key] * k / y if y else mu_all
            other = before if abs(own - after) <= abs(own - before) else after
            y_other = None if mu is None else float(read(np.array(other / mu), precision))
            sides = {"v": (cell(before, decimals), cell(after, decimals))}
            if y_other is not None:
                mine = (out["v_mm"][j], out["v_gr"][j])
                theirs = (cell(y_other, ruler), cell(y_other * mu, decimals))       # a zero the bare 0, as the column
                first = other == before
                sides["v_mm"] = (theirs[0], mine[0]) if first else (mine[0], theirs[0])
                sides["v_gr"] = (theirs[1], mine[1]) if first else (mine[1], theirs[1])
            th = (corner.get("pressure_angle_before_deg"), corner.get("pressure_angle_after_deg"))
            if None not in th:     # ϑ jumps with ds/dφ (stop 51: one side), the protractor's ½° graphically
                sides["theta"] = tuple(fixed(t, lang, 1).replace("-", "−") for t in th)
                sides["theta_gr"] = tuple(fixed(round(t * 2) / 2, lang, 1).replace("-", "−") for t in th)
            for c, (a, b) in sides.items():
                out[c][j] = f"{a} → {b}"


def _tenth(x: float, lang: str) -> str:
    """An angle to 0.1°, a whole one without its ",0" (φ = 0°, not 0,0°)."""
    t = fixed(round(x, 1), lang, 1).replace("-", "−")
    return t[:-2] if t[-2:] in (",0", ".0") else t


def angles_over(doc: dict[str, Any]) -> list[str]:
    """The phases ("rise", "return") whose largest pressure angle exceeds the allowed one — each marked
    «*» in the notes (and on ϑ(φ)), the sheet's legend saying so."""
    top = doc.get("pressure_angle_extreme_deg") or doc["pressure_angle_max_deg"]
    return [k for k in ("rise", "return")
            if abs(top[k]) > doc["pressure_angle_allowed_deg"][k] + 1e-9]


def cam_lines(doc: dict[str, Any], lang: str) -> list[str]:
    """The data, the base radius exact and measured, the largest pressure angles, ρ_min, the scales
    and the closing of s, in the lab's notation (markup: the sheet's notes typeset it)."""
    w = WORDS[lang]
    n = lambda x, d=4: num(x, lang, d).replace("-", "−") if x is not None else "—"      # noqa: E731  a true minus
    rocking = doc["follower"] == "rocking"
    # the task as the lab states it (review 10): the stroke with the follower, ω and its sense with the phases
    stroke = w["swing"].format(h=n(doc["swing_deg"])) if rocking else w["stroke"].format(h=n(doc["stroke_m"] * 1000))
    lines = [w[doc["follower"]] + ", " + stroke + "; " + w["law"].format(
        r=w["laws"][doc["laws"]["rise"]], t=w["laws"][doc["laws"]["return"]]),
        w["phases"].format(a=n(doc["phases_deg"]["rise"]), b=n(doc["phases_deg"]["dwell_far"]),
                           c=n(doc["phases_deg"]["return"]), d=n(doc["phases_deg"]["dwell_near"]))]
    lines[-1] += "; " + w["omega"].format(w=n(doc["omega_rad_s"]), d=w["sense"][doc["sense"]])
    if "shocks" in doc:            # every law's shocks (a TMM teacher asks them), after the laws and phases they follow from
        kinds = [(k, [x["phi_deg"] for x in doc["shocks"] if x["kind"] == k]) for k in ("rigid", "soft")]
        a2 = symbols(rocking)["a"]
        said = [w["shock"][k].format(v=symbols(rocking)["v"], a=a2, p=", ".join(n(p) + "°" for p in at))
                for k, at in kinds if at]
        lines.append(w["shocks"].format(l="; ".join(said)) if said else w["no_shocks"].format(v=symbols(rocking)["v"], a=a2))
    lines.append(w["arm"].format(l=n(doc["arm_m"] * 1000), a=n(doc["centre_distance_m"] * 1000),
                                 p=n(doc["arm_angle_deg"])) if rocking else offset_line(w, doc, n))
    g = doc["base_radius_graphical_m"]
    # a scene's own R0 is given, not taken (stop 50: «прийнято R_0 = 60 мм» of a given 60 read as chosen)
    # a given R0 below the smallest said plainly, with the radius to take (review 57: a warning alone)
    small = doc.get("base_radius_given") and doc["base_radius_m"] < doc["base_radius_min_m"] * (1 - 1e-9)
    key = "radius_small" if small else "radius_given" if doc.get("base_radius_given") else "radius"
    # the radius taken under the one read off the phase diagram (stop 62: CAM62 took 48 mm, the exact 47,889
    # rounded up, under the graphical 48,12 — a teacher asks why the taken R0 is under the student's own
    # smallest): the line says what it is rounded up from and why the drawn one is over it
    if key == "radius" and g is not None and doc["base_radius_m"] < g * (1 - 1e-9):
        key = "radius_under"
    lines.append(w[key].format(m=n(doc["base_radius_min_m"] * 1000, 5), g=n(None if g is None else g * 1000),
                                    k=math.ceil(doc["base_radius_min_m"] * 1000 - 1e-9),
                                    # to 0.01 %, as Table 1's δ (a teacher reads "−0,00805 %" as false precision)
                                    e=("—" if doc["base_radius_error_pct"] is None
                                       else fixed(doc["base_radius_error_pct"], lang, 2).replace("-", "−")),
                                    r=n(doc["base_radius_m"] * 1000)))
    ang = lambda x: fixed(x, lang, 2).replace("-", "−")       # noqa: E731  both to 0.01°, signed as Table 1
    top = doc.get("pressure_angle_extreme_deg") or doc["pressure_angle_max_deg"]
    where = doc.get("pressure_angle_extreme_phi_deg")

    def at(k: str, first: float, length: float) -> str:
        """The phase's largest ϑ with the φ it falls at and, at an end, which (stop 56: the rocking
        arm's rise printed −27,04° with nothing saying it is the start, where the arm still rests)."""
        # «*» where the phase's largest exceeds its allowed angle (review 57: 25,14° over 25° unmarked)
        over = "*" if k in angles_over(doc) else ""
        if where is None:
            return ang(top[k]) + "°" + over
        p = where[k]
        said = w["angle_at"].format(a=ang(top[k]), p=_tenth(p, lang)).replace("°", "°" + over, 1)
        ends = [abs(p - first) < 1e-3, abs(p - first - length) < 1e-3]
        if any(ends):
            said += " (" + w["angle_end"][ends.index(True)] + ")"
        return said
    ph = doc["phases_deg"]
    lines.append(w["angles"].format(r=at("rise", 0.0, ph["rise"]), t=at("return", ph["rise"] + ph["dwell_far"], ph["return"]),
                                    ar=n(doc["pressure_angle_allowed_deg"]["rise"]),
                                    at=n(doc["pressure_angle_allowed_deg"]["return"])))
    dwell = doc.get("dwell_pressure_angle_deg") or {}
    # a rocking follower's ϑ ≠ 0 where it rests (stop 46: "−29,3 at 0?"); the dwell's own, not the row at
    # 0°, which a linear rise gives its side of the jump (stop 51: «ближньому 34,72°» where the dwell has 17,19°)
    start = dwell.get("near")
    if start is None and rocking:
        start = doc["positions"][0]["exact"]["pressure_angle_deg"]
    if rocking and abs(start) >= 0.5:
        # a knife-edge's point, not a roller's centre (stop 48: the knife-edge cam's note named a roller)
        c = w["point_c"][doc["roller_radius_m"] <= 0]
        f = _dwell_formula(doc, start)
        far = dwell.get("far")
        if far is not None and abs(far) >= 0.5:      # stop 51: Table 1's 6.4° on the far dwell unexplained
            lines.append(w["dwells"].format(t=ang(start), u=ang(far), c=c, f=f, r=n(doc["base_radius_m"] * 1000),
                                            m=fixed(doc["dwell_radius_m"]["far"] * 1000, lang, 2)))
        else:
            lines.append(w["dwell"].format(t=ang(start), c=c, f=f))
    c = doc["curvature_min_m"]
    roller = doc["roller_radius_m"] > 0
    curv = w["curv" if roller else "knife"].format(c=n(None if c is None else c * 1000), r=n(doc["roller_radius_m"] * 1000))
    corners = doc.get("profile_corners") or []
    hollow = doc.get("profile_concave") or []
    if corners or hollow:   # ρ_min holds over the smooth parts only (at a corner ρ = 0), the convex ones only
        curv = curv.replace("ρ_{min}", "ρ_{min} " + w["smooth_convex" if corners and hollow else
                                                     "smooth" if corners else "convex_parts"], 1)
    if hollow:              # where the profile is concave, and how gently (stop 62: CAM61's |ρ| ≥ 601,6 mm unsaid)
        curv += "; " + w["concave_at"].format(l=", ".join(
            w["concave_one"].format(a=_tenth(x["from_deg"], lang), b=_tenth(x["to_deg"], lang),
                                    r=fixed(x["rho_min_m"] * 1000, lang, 1)) for x in hollow))
    lines.append(curv)
    q = symbols(rocking)
    key = "_deg" if rocking else "_m"
    k = 1.0 if rocking else 1000.0
    unit = ("°/рад" if lang == "uk" else "°/rad") if rocking else ("мм/рад" if lang == "uk" else "mm/rad")
    if corners:
        order = sorted(range(len(corners)), key=lambda j: corners[j]["phi_deg"])
        each = [w["corner"].format(n=corner_name(order.index(j) + 1), p=n(cn["phi_deg"]), a=n(cn["ds_dphi_before" + key] * k),
                                   b=n(cn["ds_dphi_after" + key] * k), u=unit,
                                   k=w["sharp" if not roller else "convex" if cn["convex"] else "concave"])
                for j, cn in enumerate(corners)]
        lines.append(w["corners"].format(v=q["v"], c=", ".join(each)))
    sc = doc["scales"]
    mu = {k: scale_text(k, sc[f"{k}_mm" if k != "mu_phi" else "mu_phi_rad_mm"] if k != "mu_l" else sc["mu_l_m_mm"],
                        rocking, lang) for k in ("mu_phi", "mu_a", "mu_v", "mu_s", "mu_l")}
    lines.append(w["scales"].format(p=mu["mu_phi"], a=mu["mu_a"], v=mu["mu_v"], s=mu["mu_s"], l=mu["mu_l"],
                                    h1=n(sc["H1_mm"]), h2=n(sc["H2_mm"])))
    close = doc.get("closing_mm")
    if close:
        lines.append(closing_line(w, symbols(rocking)["s"], close["rise"], close["return"], n))
    again = doc.get("redrawn")
    if again and again.get("divisions_first_given"):
        first = again["closing_mm_first"]
        worst = max((first["rise"], first["return"]), key=abs)
        lines.append(w["given"].format(q=symbols(rocking)["s"], n=doc["divisions"], f=again["divisions_first"],
                                       word=_divisions_uk(again["divisions_first"]),
                                       D="Δ" if worst >= 0 else "|Δ|", d=n(abs(worst), 3),
                                       b=n(again["closing_bound_mm_first"], 3)))
    elif again:
        lines.append(w["redrawn"].format(q=symbols(rocking)["s"], n=doc["divisions"], f=again["divisions_first"],
                                         r=n(again["closing_mm_first"]["rise"], 3).replace("-", "−"),
                                         t=n(again["closing_mm_first"]["return"], 3).replace("-", "−"),
                                         b=n(again["closing_bound_mm_first"], 3)))
    return [x[:1].upper() + x[1:] for x in lines]       # each a sentence: a capital first letter


def offset_line(w: dict, doc: dict, n) -> str:
    """The offset e with its side as drawn: the follower's axis stands at x = σe from O (σ = +1 for a
    cam turning counter-clockwise; exact.cam) — right of O for σe > 0 — and e > 0 lowers the rise's
    pressure angle, tg ϑ = (ds/dφ − e)/(s0 + s) (stop 46: «e = −6 мм» said neither) and, ds/dφ < 0 there,
    raises the return's — both said (stop 52: «e = −1,8 мм …, збільшує кут тиску на підйомі» alone read as
    a wrong choice where the return's bound decides); an offset the program chose ("auto") says why."""
    e = doc["offset_m"] * 1000
    text = w["offset"].format(e=n(e))
    if abs(e) < 1e-9:          # e = 0 said to be the central follower (stop 50: «e = 0 мм» alone)
        return text + w["central"]
    x = e * (1 if doc["sense"] == "ccw" else -1)
    which = 0 if e > 0 else 1
    return text + w["offset_side"].format(d=n(abs(e)), side=w["side"][0 if x > 0 else 1],
                                          effect=w["effect"][which], other=w["other"][which],
                                          why=w["offset_auto"] if doc.get("offset_auto") else "")


def closing_line(w: dict, q: str, rise: float, ret: float, n) -> str:
    """The notes' line on the closing of s: the phases whose error Δ was laid back, each with its Δ,
    and a phase that closed as drawn said to have (Δ = 0, nothing laid back — not «its error Δ = 0
    laid back»); ``n`` formats a number."""
    sign = lambda x: n(x, 3).replace("-", "−")              # noqa: E731
    missed = [ph for ph, d in enumerate((rise, ret)) if d != 0]
    if not missed:
        return w["closed"].format(q=q)
    if len(missed) == 1:
        ph = missed[0]
        return w["closing"].format(q=q, which=w["closing_one"][ph].format(d=sign((rise, ret)[ph])),
                                   tail=w["closing_tail"][1 - ph])
    return w["closing"].format(q=q, which=w["closing_two"].format(r=sign(rise), t=sign(ret)), tail="")


def _divisions_uk(k: int) -> str:
    """«поділку», «поділки» or «поділок» after the number ``k`` (Ukrainian agreement)."""
    if k % 10 == 1 and k % 100 != 11:
        return "поділку"
    if 2 <= k % 10 <= 4 and not 12 <= k % 100 <= 14:
        return "поділки"
    return "поділок"


def short_ordinates(doc: dict) -> bool:
    """Whether Table 1 leaves a δ out ("—") for a value that is not zero: its ordinate shorter than
    the ruler's SHORT_DIVISIONS divisions (graphic.cam.errors_pct)."""
    key = "_deg" if doc["follower"] == "rocking" else "_m"
    return any(p["error_pct"][q] is None and p["exact"][q + key] != 0
               for p in doc["positions"] for q in ("s", "ds_dphi"))


def short_note(doc: dict, lang: str) -> str:
    """The notes' line saying why a δ is "—": the value zero, under 1 % of the largest, or its exact
    ordinate under two ruler divisions, where half a division read is a quarter of it or more (the lab
    judges δ against 5 %) — the rule errors_pct applies, word for word. The bound is the EXACT value's
    ordinate and is not itself short: OWN_CAM54's ψ = 0,25° at μ = 0,2 °/мм (1.25 mm, read 1,0 mm) keeps
    its δ = −20,00* — half a division of 1.25 mm, judged and starred as the rule says (stop 55 decided
    LEFT54's «— may read better» by the rule's own logic: ±0.25 mm is 20 % there, under the 25 % it
    excludes); the drawn ordinate is not the test, or a construction gone wrong to a short ordinate
    would hide its error behind «—»."""
    step = doc.get("precision_mm", 0.5)
    least = num(SHORT_DIVISIONS * step, lang, 3)
    half = num(step / 2, lang, 3)
    if lang == "uk":
        return (f"«—» у стовпцях δ: значення нульове, менше за 1 % найбільшого або його точна ордината (значення/μ) "
                f"коротша за {SHORT_DIVISIONS} поділки лінійки ({least} мм) — відлік з точністю ±{half} мм дає тут "
                "понад 25 %, δ не оцінюється")
    return (f"“—” in the δ columns: the value is zero, under 1 % of the largest, or its exact ordinate (value/μ) "
            f"is under {SHORT_DIVISIONS} ruler divisions ({least} mm) — read to ±{half} mm it errs by over 25 % "
            "there, δ is not judged")


def table_rows(doc: dict[str, Any]) -> list[int]:
    """The positions Table 1 prints, one row a point of the cam: with no far dwell the rise's end and the
    return's start are one point (one number, graphic.cam.division_numbers), printed once (stop 49:
    rows 10 and 11 stood with identical values)."""
    ps = doc["positions"]
    return [j for j, p in enumerate(ps) if j == 0 or p.get("number", j) != ps[j - 1].get("number", j - 1)]


def cam_table(doc: dict[str, Any], lang: str, title: str) -> str:
    """The terminal's report: the data, the base radius exact and measured, the per-division table."""
    w = WORDS[lang]
    rocking = doc["follower"] == "rocking"
    lines = [f"{title} — {w['title']}"] + [plain(x) for x in cam_lines(doc, lang)]
    lines.append("")
    q = symbols(rocking)                     # rocking: ψ, dψ/dφ (an angle is not s)
    unit = "°" if rocking else ("мм" if lang == "uk" else "mm")
    per = unit + "/" + ("рад" if lang == "uk" else "rad")
    head = [x.replace("ds/dφ", plain(q["v"])).replace("δs", "δ" + q["s"]) for x in w["head"]]
    rows = [[(q["s"] + x[1:] if x[:2] in ("s ", "s,") else x).replace("{s}", unit).replace("{v}", per) for x in head]]
    cols = table_columns(doc, lang)          # the sheet's Table 1 cell for cell (its "*" explained there)
    keys = ("phi", "s", "s_gr", "ds", "v", "v_gr", "dv", "theta", "theta_gr", "R", "R_gr")
    for j in table_rows(doc):
        rows.append([cols[c][j].rstrip("*") for c in keys])
    widths = [max(len(r[k]) for r in rows) for k in range(len(rows[0]))]
    for r in rows:
        lines.append("  ".join(x.rjust(wd) for x, wd in zip(r, widths)).replace("-", "−"))
    if short_ordinates(doc):
        lines += ["", plain(short_note(doc, lang))]
    warnings = doc["warnings_uk"] if lang == "uk" else doc["warnings"]
    if warnings:
        lines += ["", w["warn"] + ":"] + [f"  - {x}" for x in warnings]
    return "\n".join(lines) + "\n"
