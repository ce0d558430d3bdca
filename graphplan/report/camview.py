"""The explorer of a cam mechanism (`graphplan view` on a [cam] scene): one offline HTML page with the
cam turning and the follower moving, the pressure angle at the contact live, the point running on the
phase diagram and on the s, ds/dφ, d²s/dφ² diagrams, and the profile's construction by inversion
replayed step by step.

Everything is computed here from the exact solution (graphplan.exact.cam) and the graphical
construction (graphplan.graphic.cam) — the numbers `graphplan cam --json` prints — and written into
the page as one JSON object; the page's script only draws it. Drawing lengths are millimetres at the
profile's scale μ_l of the construction. Deterministic, no network request.
"""
from __future__ import annotations

import html
import json
import math
from typing import Any

import numpy as np

from graphplan.util.errors import GraphplanError
from graphplan.util.words import LANGS, fixed, num

MM = 3      # decimals of drawing millimetres


def _mm(z: complex, mu: float) -> list[float]:
    """A point (m, complex) as drawing mm at ``mu`` m/mm, rounded, no −0."""
    x, y = round(z.real / mu, MM) + 0.0, round(z.imag / mu, MM) + 0.0
    return [x, y]


def _col(values, digits: int = 9) -> list[float]:
    """Values to ``digits`` significant digits; round-off below 1e-12 of the largest is 0."""
    a = np.asarray(values, dtype=float)
    big = float(np.max(np.abs(a))) if a.size else 0.0
    return [0.0 if abs(v) <= 1e-12 * big or v == 0 else float(f"{v:.{digits}g}") for v in a]


def cam_grid(sol, g, step: float) -> np.ndarray:
    """The cam's turns shown: every ``step`` degrees and the construction's divisions, ascending."""
    if not (math.isfinite(step) and 0.05 <= step <= 30.0):
        raise GraphplanError(f"--step must be from 0.05 to 30 degrees, got {step!r}")
    n = int(round(360.0 / step))
    every = np.concatenate([np.arange(n) * (360.0 / n), np.mod(np.asarray(g.phi, dtype=float), 360.0)])
    every = np.sort(np.round(every, 9) % 360.0)
    return every[np.concatenate([[True], np.diff(every) > 1e-6])]


SAY: dict[str, tuple[str, str]] = {
    "base": ("Крок 0: масштаб і основна шайба. Профіль креслимо в масштабі μ_l = {mu} м/мм. З центра O кулачка "
             "проводимо основне коло R_0 = {R0} мм ({R0mm} мм на кресленні){extra}; штовхач у нижньому положенні "
             "(φ = 0): його центр ролика на основному колі",
             "Step 0: the scale and the base circle. The profile is drawn at μ_l = {mu} m/mm. About the cam's "
             "centre O draw the base circle R_0 = {R0} mm ({R0mm} mm on the drawing){extra}; the follower in its "
             "lowest position (φ = 0): the roller's centre on the base circle"),
    "offset": ("; коло ексцентриситету e = {e} мм: вісь штовхача дотична до нього",
               "; the offset circle e = {e} mm: the follower's axis is tangent to it"),
    "arm": ("; коло центрів коромисла радіусом a = {a} мм: на ньому опора O_1, коромисло l = {l} мм",
            "; the circle of the rocker's pivots, radius a = {a} mm: the pivot O_1 on it, the arm l = {l} mm"),
    "point": ("Обернений рух: повертаємо штовхач навколо O проти ω на φ_{{{k}}} = {phi}°; від основного кола вздовж "
              "його осі відкладаємо s_{{{k}}} = {s}: точка {k} центрового профілю (радіус {r} мм)",
              "Inversion: turn the follower about O against ω by φ_{{{k}}} = {phi}°; from the base circle along its "
              "axis lay off s_{{{k}}} = {s}: the point {k} of the centre profile (radius {r} mm)"),
    "point rocking": ("Обернений рух: повертаємо опору O_1 навколо O проти ω на φ_{{{k}}} = {phi}°; з нової опори "
                      "дугою радіуса l відкладаємо кут коромисла ψ_{{{k}}} = {s}: точка {k} центрового профілю (радіус {r} мм)",
                      "Inversion: turn the pivot O_1 about O against ω by φ_{{{k}}} = {phi}°; from the new pivot with an "
                      "arc of radius l lay off the arm's angle ψ_{{{k}}} = {s}: the point {k} of the centre profile "
                      "(radius {r} mm)"),
    "centre": ("Точки з'єднуємо плавною кривою (на вистоях — дуги кіл з центром O): центровий (теоретичний) профіль",
               "Join the points with a smooth curve (arcs about O over the dwells): the centre (theoretical) profile"),
    "working": ("Кола ролика r = {r} мм з центрами на центровому профілі; їхня внутрішня обвідна — робочий профіль",
                "Circles of the roller r = {r} mm centred on the centre profile; their inner envelope is the working profile"),
    "knife": ("Ролика немає (вістря): робочий профіль — сам центровий", "No roller (a knife edge): the working profile is the centre profile"),
}


def say(key: str, **fields: Any) -> dict[str, str]:
    out = {}
    for lang in LANGS:
        text = SAY[key][0 if lang == "uk" else 1]
        out[lang] = text.format(**{k: (v[lang] if isinstance(v, dict) else v) for k, v in fields.items()})
    return out


def both(f) -> dict[str, str]:
    return {lang: f(lang) for lang in LANGS}


def inversion_steps(sol, g) -> list[dict[str, Any]]:
    """The profile by inversion, as the student draws it: the base circle (and the offset circle, or
    the circle of the rocker's pivots), then at each division the follower turned against ω with the
    drawn s laid off — a point of the centre profile —, the centre profile, the working profile."""
    from graphplan.exact.cam import centre_path, profile
    cam, geo, mu = sol.cam, sol.geometry, g.mu_l
    sig = 1 if cam.sense > 0 else -1
    steps: list[dict[str, Any]] = []
    mmf = lambda v: both(lambda lang: fixed(v, lang, 1))     # noqa: E731
    extra = (say("arm", a=mmf(cam.centre_distance * 1000), l=mmf(cam.arm * 1000)) if cam.rocking
             else say("offset", e=mmf(abs(geo.e) * 1000)) if geo.e else {lang: "" for lang in LANGS})
    steps.append({"caption": say("base", mu=both(lambda lang: num(mu, lang)), R0=mmf(geo.R0 * 1000),
                                 R0mm=mmf(geo.R0 / mu), extra=extra),
                  "draw": {"kind": "base"}})
    zero = np.zeros_like(g.phi)
    P = profile(cam, geo, g.phi, g.s, g.v, zero)["P"]          # the drawn s laid off: the construction's points
    C0, _, _, _ = centre_path(cam, geo, np.zeros_like(g.phi), zero, zero)   # s = 0: on the base circle
    for k, phi in enumerate(g.phi):
        turn = np.exp(-1j * sig * math.radians(float(phi)))
        base = complex(C0[k]) * turn
        if cam.rocking:
            pivot = cam.centre_distance * turn
            s_text = both(lambda lang: fixed(math.degrees(float(g.s[k])), lang, 2) + "°")
            key = "point rocking"
        else:
            pivot = None
            s_text = both(lambda lang: fixed(float(g.s[k]) * 1000, lang, 2) + (" мм" if lang == "uk" else " mm"))
            key = "point"
        steps.append({"caption": say(key, k=k, phi=both(lambda lang: fixed(float(phi), lang, 1)), s=s_text,
                                     r=mmf(abs(complex(P[k])) / mu)),
                      "draw": {"kind": "point", "k": k, "base": _mm(base, mu), "at": _mm(complex(P[k]), mu),
                               "pivot": None if pivot is None else _mm(pivot, mu),
                               "axis": _mm(turn * 1j, 1.0) if not cam.rocking else None}})
    steps.append({"caption": say("centre"), "draw": {"kind": "centre"}})
    if cam.roller > 0:
        steps.append({"caption": say("working", r=mmf(cam.roller * 1000)), "draw": {"kind": "working"}})
    else:
        steps.append({"caption": say("knife"), "draw": {"kind": "working"}})
    return steps


def cam_data(sol, g, step: float = 1.0, lang: str = "uk", scene: str = "") -> dict[str, Any]:
    """Everything the cam page shows (drawing mm at μ_l; s in m, or in degrees for a rocking follower),
    the words in both languages."""
    from graphplan.exact.cam import centre_path
    from graphplan.report.cam import cam_json
    if lang not in LANGS:
        raise GraphplanError(f"--lang must be uk or en, got {lang!r}")
    cam, geo, mu = sol.cam, sol.geometry, g.mu_l
    sig = 1 if cam.sense > 0 else -1
    phi = cam_grid(sol, g, step)
    ex = sol.at(phi)
    C, _, _, u = centre_path(cam, geo, ex["s"], ex["v"], ex["a"])
    turn = np.exp(1j * sig * np.radians(phi))                # the cam's frame turned to the fixed one
    contact = ex["working"] * turn
    ring = sol.at(np.linspace(0.0, 360.0, 721))
    unit = math.degrees(1.0) if cam.rocking else 1.0
    arm = cam.arm if cam.rocking else 1.0          # a rocking follower's angles as the arc of its arm
    doc = cam_json(sol, g, scene)
    # the phase diagram (translating): ds/dφ across, s up, the cam's centre at (σe, −s0); the line
    # from it to the running point makes the pressure angle with the follower's axis
    s0 = math.sqrt(max(geo.R0 ** 2 - geo.e ** 2, 0.0))
    centre = None
    if not cam.rocking:
        for side in (1.0, -1.0):
            th = np.degrees(np.arctan2(ex["v"] - side * geo.e, ex["s"] + s0))
            if np.allclose(th, ex["theta"], atol=1e-6):
                centre = [round(side * geo.e / mu, MM) + 0.0, round(-s0 / mu, MM) + 0.0]
                break
            if np.allclose(-th, ex["theta"], atol=1e-6):
                centre = [round(side * geo.e / mu, MM) + 0.0, round(-s0 / mu, MM) + 0.0, -1]
                break
    return {
        "kind": "cam", "lang": lang, "title": {"uk": cam.title_in("uk"), "en": cam.title_in("en")},
        "follower": cam.follower, "rocking": cam.rocking, "sense": sig, "omega": cam.omega,
        "phases": list(cam.phases), "laws": list(cam.laws), "allowed": list(cam.allowed),
        "R0": geo.R0, "R0_min": sol.R0_min, "e": geo.e, "roller": cam.roller, "arm": cam.arm,
        "centre_distance": cam.centre_distance, "mu_l": mu, "step": step, "unit": "°" if cam.rocking else "m",
        "grid": {"phi": [round(float(p), 6) for p in phi],
                 "s": _col(ex["s"] * unit), "v": _col(ex["v"] * unit), "a": _col(ex["a"] * unit),
                 "theta": _col(ex["theta"]),
                 "C": [_mm(complex(z), mu) for z in C], "contact": [_mm(complex(z), mu) for z in contact],
                 "u": [[round(float(z.real), 6) + 0.0, round(float(z.imag), 6) + 0.0] for z in np.broadcast_to(u, C.shape)],
                 "phase_x": [round(float(v) * arm / mu, MM) + 0.0 for v in ex["v"]],
                 "phase_y": [round(float(s) * arm / mu, MM) + 0.0 for s in ex["s"]]},
        "profile": {"centre": [_mm(complex(z), mu) for z in ring["P"]],
                    "working": [_mm(complex(z), mu) for z in ring["working"]]},
        "pivot": _mm(complex(cam.centre_distance), mu) if cam.rocking else None,
        "phase_centre": centre,
        "divisions": [{"phi": p["phi_deg"], "phase": p["phase"],
                       "theta": p["exact"]["pressure_angle_deg"], "theta_g": p["graphical"]["pressure_angle_deg"],
                       "s": p["exact"]["s_deg" if cam.rocking else "s_m"], "s_g": p["graphical"]["s_deg" if cam.rocking else "s_m"],
                       "v": p["exact"]["ds_dphi_deg" if cam.rocking else "ds_dphi_m"],
                       "v_g": p["graphical"]["ds_dphi_deg" if cam.rocking else "ds_dphi_m"],
                       "a_g": p["graphical"]["d2s_dphi2_deg" if cam.rocking else "d2s_dphi2_m"],
                       "error": p["error_pct"]} for p in doc["positions"]],
        "scales": doc["scales"], "precision": g.precision, "warnings": {"en": doc["warnings"], "uk": doc["warnings_uk"]},
        "theta_max": doc["pressure_angle_max_deg"],
        "steps": inversion_steps(sol, g),
    }


def cam_html(sol, g, step: float = 1.0, lang: str = "uk", scene: str = "") -> str:
    """The cam's explorer as one self-contained HTML page."""
    from graphplan.report.explorer import _asset
    data = cam_data(sol, g, step, lang, scene)
    payload = json.dumps(data, ensure_ascii=False, separators=(",", ":"), allow_nan=False).replace("</", "<\\/")
    return (_asset("camview.html").replace("{{lang}}", lang)
            .replace("{{title}}", html.escape(data["title"][lang]))
            .replace("{{style}}", _asset("explorer.css") + _asset("camview.css"))
            .replace("{{data}}", payload)
            .replace("{{script}}", _asset("camview.js").replace("/*{{helpers}}*/", helpers())))


def helpers() -> str:
    """The explorer's own drawing helpers (the lab's markup, numbers as the language writes them, SVG,
    drawings that zoom and pan by pointer and keyboard, labels off the lines), shared by the cam's page."""
    from graphplan.report.explorer import _asset
    text = _asset("explorer.js")
    start = text.index("  // -- the lab's markup")
    return text[start:text.index("  // -- the grid, in the turn", start)]
