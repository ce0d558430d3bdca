"""Teachers' keys for cam variants (docs/cams.md, docs/keys.md): the exact answers of one cam — the
smallest base radius, the offset, the largest pressure angles and, at every division of the rise and
the return, s, ds/dφ, the pressure angle and the centre profile's radius — in the key format `check`
grades (its quantities of the position family, so a student's long table of the divisions is graded
like a lever mechanism's), with an A4 key sheet and a summary row of their own."""
from __future__ import annotations

import math
from typing import Any

import numpy as np

from graphplan.exact.cam import Solution
from graphplan.graphic.cam import divisions as division_turns
from graphplan.graphic.record import Record
from graphplan.model.variants import tolerance_for
from graphplan.teach.keys import FORMAT, ZERO_FRACTION
from graphplan.util.markup import escape
from graphplan.util.words import fixed, num

# the quantities at each division: name → (unit translating, unit rocking, signed, what)
QUANTITIES = {"s": ("m", "°", True, "the follower's displacement"),
              "ds_dphi": ("m", "°", True, "the velocity analogue ds/dφ, per radian"),
              "theta": ("°", "°", True, "the pressure angle"),
              "R": ("m", "m", False, "the centre profile's radius")}


def make_cam_key(sol: Solution, *, variant: str = "", student: str = "", base: str = "",
                 overrides: dict[str, Any] | None = None, scene: dict[str, Any] | None = None,
                 divisions: int | None = None, tolerances=()) -> dict[str, Any]:
    """The key of one cam variant as a JSON-ready document in the lever keys' layout (``positions``
    with ``values``, ``quantities`` with units and tolerances), plus the cam's headline answers."""
    cam = sol.cam
    n = divisions or cam.divisions
    phi, phase = division_turns(sol, n)
    at = sol.at(phi, phase)
    deg = math.degrees(1.0) if cam.rocking else 1.0
    values = {"s": at["s"] * deg, "ds_dphi": at["v"] * deg, "theta": at["theta"], "R": at["radius"]}
    fine = sol.at(np.linspace(0.0, 360.0, 3601))
    scales = {"s": float(np.max(np.abs(fine["s"]))) * deg, "ds_dphi": float(np.max(np.abs(fine["v"]))) * deg,
              "theta": float(np.max(np.abs(fine["theta"]))), "R": float(np.max(fine["radius"]))}
    for k in values:                      # round-off below 1e-12 of the largest is 0
        values[k] = np.where(np.abs(values[k]) < 1e-12 * (scales[k] or 1.0), 0.0, values[k])
    positions = [{"index": j, "phi_deg": float(p), "turn_deg": float(p), "phase": "rise" if phase[j] == 0 else "return",
                  "values": {k: float(values[k][j]) for k in QUANTITIES}} for j, p in enumerate(phi)]
    return {
        "format": FORMAT, "kind": "cam", "variant": variant, "student": student, "base": base,
        "overrides": dict(overrides or {}), "title": cam.title, "title_en": cam.title_in("en"),
        "follower": cam.follower, "stroke": cam.stroke * deg, "phases_deg": list(cam.phases),
        "laws": list(cam.laws), "pressure_angle_allowed_deg": list(cam.allowed),
        "base_radius_min_m": sol.R0_min, "base_radius_m": sol.geometry.R0,
        "offset_m": sol.geometry.e, "arm_angle_deg": math.degrees(sol.geometry.psi0),
        "pressure_angle_max_deg": list(sol.pressure_maxima()),
        "curvature_min_m": _finite(sol.curvature_min()),
        "warnings": [en for en, _ in sol.warnings], "warnings_uk": [uk for _, uk in sol.warnings],
        "count": len(positions), "accel": [], "divisions": n, "zero_fraction": ZERO_FRACTION,
        "quantities": {k: {"unit": (u_rock if cam.rocking else u_tr), "family": "velocity", "signed": signed,
                           "text": text, "scale": scales[k], "tolerance_pct": tolerance_for(k, *tolerances)}
                       for k, (u_tr, u_rock, signed, text) in QUANTITIES.items()},
        "positions": positions, "diagram": [], "scene": scene,
    }


def _finite(x: float) -> float | None:
    return x if math.isfinite(x) else None


def summary_row(key: dict[str, Any]) -> dict[str, Any]:
    """One line of the group's summary: the variant's inputs and the cam's headline answers."""
    row: dict[str, Any] = {"variant": key["variant"], "student": key["student"], "status": "ok"}
    row.update(key["overrides"])
    row.update({"R0_min": key["base_radius_min_m"], "R0": key["base_radius_m"], "e": key["offset_m"],
                "theta_rise": key["pressure_angle_max_deg"][0], "theta_return": key["pressure_angle_max_deg"][1],
                "rho_min": key["curvature_min_m"]})
    return row


def summary_units(key: dict[str, Any]) -> dict[str, str]:
    return {"R0_min": "m", "R0": "m", "e": "m", "theta_rise": "°", "theta_return": "°", "rho_min": "m"}


def key_sheet(key: dict[str, Any], lang: str = "uk") -> Record:
    """The cam variant's A4 key sheet: the data, the headline answers, the table of the divisions."""
    from graphplan.teach.keysheet import A4_PORTRAIT, EDGE, INSET, LEFT, MEDIUM, SMALL, frame, table, heading
    W, H = A4_PORTRAIT
    uk = lang == "uk"
    rec, x0, y = heading(key, lang)
    if key["overrides"]:
        y -= 5.5
        rec.label((x0, y), ("дані варіанта: " if uk else "variant data: ") + escape(
            ", ".join(f"{k} = {v}" for k, v in key["overrides"].items())), size=SMALL)
    mm = "мм" if uk else "mm"
    lines = [f"R_0 min = {fixed(key['base_radius_min_m'] * 1000, lang, 3)} {mm}, R_0 = "
             f"{fixed(key['base_radius_m'] * 1000, lang, 1)} {mm}, e = {fixed(key['offset_m'] * 1000, lang, 2)} {mm}",
             ("ϑ max: підйом " if uk else "ϑ max: rise ") + fixed(key["pressure_angle_max_deg"][0], lang, 2)
             + ("°, опускання " if uk else "°, return ") + fixed(key["pressure_angle_max_deg"][1], lang, 2)
             + f"° ([ϑ] = {num(key['pressure_angle_allowed_deg'][0], lang)}°, "
               f"{num(key['pressure_angle_allowed_deg'][1], lang)}°)"]
    if key["curvature_min_m"] is not None:
        lines.append(f"ρ min = {fixed(key['curvature_min_m'] * 1000, lang, 2)} {mm}")
    for line in lines:
        y -= 5.5
        rec.label((x0, y), line, size=SMALL)
    rocking = key["follower"] == "rocking"
    unit = "°" if rocking else mm
    k = 1.0 if rocking else 1000.0
    from graphplan.drawing.cam import symbols
    q = symbols(rocking)                    # rocking: ψ, dψ/dφ per radian of the cam's turn, as on the sheet
    header = [["№" if uk else "No.", "φ, °", f"{q['s']}, {unit}", f"{q['v']}, {unit}/{'рад' if uk else 'rad'}", "ϑ, °", f"R, {mm}"]]
    rows = [[str(p["index"]), fixed(p["phi_deg"], lang, 1), num(p["values"]["s"] * k, lang),
             num(p["values"]["ds_dphi"] * k, lang), fixed(p["values"]["theta"], lang, 2),
             fixed(p["values"]["R"] * 1000, lang, 2)] for p in key["positions"]]
    rows = [[c.replace("-", "−") for c in r] for r in rows]
    table(rec, x0, y - 6.0, header, rows, row_h=5.0)
    return rec
