"""Review 6, items 17–19, and the notes' signs and bands: a linear law's rigid shocks drawn on the
d²ψ/dφ² diagram as arrows to ±∞; the centre profile's corners where dψ/dφ jumps said (ρ = 0 there,
ρ_min over the smooth parts) and the working profile there the roller disc's erosion (no notch);
a rocking follower's dψ/dφ, never ds/dφ; the true minus in the notes; both pressure bands lettered."""
from __future__ import annotations

import functools
import math
import re
import tomllib

import numpy as np
import pytest

from graphplan.drawing.cam import diagrams, pressure_diagram, profile_drawing
from graphplan.exact.cam import solve
from graphplan.graphic.cam import construct
from graphplan.model.cam import build
from graphplan.report.cam import cam_json, cam_lines, cam_table
from graphplan.sheets.cam import notes
from graphplan.util.markup import plain

ROCK = '''title = "Кулачок"
title_en = "Cam"
[cam]
follower = "rocking"
swing_deg = 24
arm = 0.11
centre_distance = 0.13
roller_radius = 0.01
phases_deg = { rise = 110, dwell_far = 30, return = 90, dwell_near = 130 }
laws = { rise = "parabolic", return = "linear" }
pressure_angle_deg = { rise = 40, return = 50 }
rpm = 90
direction = "cw"
'''

LINEAR_RISE = '''title = "Кулачок"
[cam]
follower = "translating"
stroke = 0.03
offset = 0.005
roller_radius = ROLLER
phases_deg = { rise = 100, dwell_far = 40, return = 100, dwell_near = 120 }
laws = { rise = "linear", return = "cosine" }
pressure_angle_deg = { rise = 30, return = 30 }
omega = 10
'''


def _cam(text: str):
    return build(tomllib.loads(text))


@functools.lru_cache(maxsize=None)
def _solved(text: str, n: int = 8):
    """The cam solved and constructed, once per text for the module's tests (ROCK's was solved six
    times, 0,3 s of CPU each): read it, never change it."""
    sol = solve(_cam(text))
    return sol, construct(sol, n)


def test_the_corners_are_where_the_linear_law_jumps_with_its_closed_form_jump():
    """ψ_max = 24° over φ_с = 90° by the linear law: dψ/dφ = −24/90 rad/rad on the return, 0 on the
    dwells — corners at φ = 140° (convex: the profile leaves the far dwell inward) and 230° (concave)."""
    sol = solve(_cam(ROCK))
    cs = sol.corners()
    assert [c.phi_deg for c in cs] == [140.0, 230.0]
    jump = math.radians(24) / math.radians(90)
    assert cs[0].v_before == pytest.approx(0.0, abs=1e-12) and cs[0].v_after == pytest.approx(-jump, rel=1e-9)
    assert cs[1].v_before == pytest.approx(-jump, rel=1e-9) and cs[1].v_after == pytest.approx(0.0, abs=1e-12)
    assert [c.convex for c in cs] == [True, False]
    # the tangent turns at a corner: the one-sided chords of P 1e-4° long meet at an angle
    for c in cs:
        P = sol.at(np.array([c.phi_deg - 1e-4, c.phi_deg, c.phi_deg + 1e-4]))["P"]
        turn = abs(np.angle((P[2] - P[1]) / (P[1] - P[0])))
        assert turn > math.radians(5)
    # a linear rise (translating, h/φ_п = 0.03/(100° in rad)): corners at 0° (concave) and 100° (convex)
    cs = solve(_cam(LINEAR_RISE.replace("ROLLER", "0.008"))).corners()
    h = 0.03 / math.radians(100)
    assert [(c.phi_deg, c.convex) for c in cs] == [(0.0, False), (100.0, True)]
    assert cs[0].v_after == pytest.approx(h, rel=1e-9) and cs[1].v_before == pytest.approx(h, rel=1e-9)
    # no linear law, no corner
    assert solve(_cam(ROCK.replace('"linear"', '"cosine"'))).corners() == []


def _shocks(rec):
    return [q for q in rec.items if q.kind == "vector" and q.step.startswith("shock")]


def test_the_rigid_shocks_are_drawn_as_arrows_to_infinity_at_the_phase_ends():
    """At the return's start dψ/dφ falls 0 → −ψ_max/φ_с: d²ψ/dφ² = −∞ (an arrow down), at its end it
    rises back: +∞ (up); each at its turn's abscissa φ/μ_φ on the d²ψ/dφ² axis, lettered ∞."""
    sol, g = _solved(ROCK)
    rec = diagrams(sol, g, "en")
    axis = next(q for q in rec.items if q.step == "axis a").points[0][1]
    arrows = _shocks(rec)
    assert len(arrows) == 2
    for q, phi, sign in zip(arrows, (140.0, 230.0), (-1, 1)):
        (xa, ya), (xb, yb) = q.points
        assert xa == pytest.approx(math.radians(phi) / g.mu_phi, abs=1e-6) and xb == pytest.approx(xa)
        assert ya == pytest.approx(axis) and (yb - ya) * sign >= 12.0
    infinities = [q for q in rec.items if q.kind == "text" and q.text == "∞"]
    assert len(infinities) == 2
    for q, arrow in zip(sorted(infinities, key=lambda t: t.points[0][0]), arrows):
        (x, y), tip = q.points[0], arrow.points[1]
        assert math.hypot(x - tip[0], y - tip[1]) < 10.0          # lettered by its own arrow's point
    # a linear rise: +∞ at the origin, −∞ at the rise's end; no arrows without a linear law
    sol, g = _solved(LINEAR_RISE.replace("ROLLER", "0.008"))
    signs = [(round(q.points[0][0] * g.mu_phi, 9), np.sign(q.points[1][1] - q.points[0][1]))
             for q in _shocks(diagrams(sol, g, "uk"))]
    assert signs == [(0.0, 1.0), (round(math.radians(100), 9), -1.0)]
    sol, g = _solved(ROCK.replace('"linear"', '"cosine"'))
    assert _shocks(diagrams(sol, g, "en")) == []


@pytest.mark.parametrize("roller", ["0.01", "0.02"])
def test_the_working_profile_at_a_corner_is_the_rollers_erosion_without_a_notch(roller):
    """The working profile stays r from the centre profile everywhere (no point nearer: the old
    pointwise offset C − r·n crossed itself at the convex corner), one simple ring; at the concave
    corner (230°) it is an arc of radius r about the corner point."""
    from shapely.geometry import LineString, LinearRing, Point
    sol, g = _solved(ROCK.replace("roller_radius = 0.01", f"roller_radius = {roller}"))
    rec = profile_drawing(sol, g, "en")
    mu, r = g.mu_l, float(roller) / g.mu_l
    W = next(q for q in rec.items if q.step == "working profile").points
    P = next(q for q in rec.items if q.step == "centre profile").points
    assert LinearRing(W).is_simple
    centre = LineString(P)
    gaps = np.array([centre.distance(Point(p)) for p in W[::3]])
    assert gaps.min() >= r - 1e-3 * r
    corner = sol.at(np.array([230.0]))["P"][0] / mu
    near = [p for p in W if abs(math.hypot(p[0] - corner.real, p[1] - corner.imag) - r) < 1e-6 * r + 1e-3]
    assert len(near) >= 5                 # an arc of the roller's radius about the corner, not a chord


@pytest.mark.parametrize("lang", ["uk", "en"])
def test_the_notes_say_the_corners_rho_over_the_smooth_parts_and_dpsi(lang):
    sol, g = _solved(ROCK)
    cam = sol.cam
    doc = cam_json(sol, g, "")
    lines = notes(doc, lang, cam)
    text = "\n".join(lines)
    assert "ds/dφ" not in text and "d^{2}s" not in text          # a rocking follower: ψ, never s
    assert "dψ/dφ" in text
    # «на гладких (опуклих) ділянках»: stop 62 — a profile with a concave stretch too says its ρ_min is the
    # convex parts' (this one is concave at φ ≈ 0…25°)
    smooth = "на гладких" if lang == "uk" else "over the smooth"
    rho = f"{doc['curvature_min_m'] * 1000:.2f}".replace(".", "," if lang == "uk" else ".")
    curv = next(x for x in lines if "ρ_{min}" in x and rho in x)      # 37,08 mm (the arm under O–O1, stop 60)
    assert smooth in curv
    corners = next(x for x in lines if "140°" in x and "ρ = 0" in x)      # not the shocks line (stop 55), which names 140° too
    jump = f"{24 / 90 * 180 / math.pi:.2f}".replace(".", "," if lang == "uk" else ".")
    assert "230°" in corners and "ρ = 0" in corners and f"0 → −{jump}" in corners and f"−{jump} → 0" in corners
    # the terminal says the same lines
    assert all(plain(x) in cam_table(doc, lang, "T") for x in cam_lines(doc, lang))
    # a knife-edge follower meets a sharp corner
    sol, g = _solved(LINEAR_RISE.replace("ROLLER", "0"))
    kn = "\n".join(cam_lines(cam_json(sol, g, ""), lang))
    assert ("гострий злам" if lang == "uk" else "sharp corner") in kn and "ds/dφ" in kn


@pytest.mark.parametrize("lang", ["uk", "en"])
def test_the_notes_write_a_negative_number_with_the_true_minus(lang):
    """e = −6 mm (a negative offset) as the table and the terminal write it: U+2212, no hyphen."""
    sol, g = _solved(LINEAR_RISE.replace("ROLLER", "0.008").replace("offset = 0.005", "offset = -0.006"))
    lines = notes(cam_json(sol, g, ""), lang, sol.cam)
    assert any("e = −6" in x for x in lines)
    assert not [x for x in lines if re.search(r"(?<![\w])-\d", x)]


def test_both_pressure_bands_are_lettered():
    """Each active phase's ±[ϑ] lines lettered: [ϑ] = 40° over the upper, −40° under the lower (review 12
    #15: "−[ϑ] = −40°" read as a double minus)."""
    sol, g = _solved(ROCK)
    mu_t = 2.0
    rec = pressure_diagram(sol, g, "en", 0.02, mu_t)
    texts = {q.text: q for q in rec.items if q.kind == "text"}
    for allowed in (40, 50):
        up, down = texts[f"[ϑ] = {allowed}°"], texts[f"−{allowed}°"]
        assert up.ink()[1] > allowed / mu_t - 0.5 and down.ink()[3] < -allowed / mu_t + 0.5


def test_without_a_near_dwell_the_shock_at_the_turns_start_is_drawn_at_both_ends_of_the_abscissa():
    """Linear rise 120°, linear return 240°, no dwells: one corner at 0° ≡ 360°, where ds/dφ jumps
    −h/φ_с → +h/φ_п (up, +∞), and one at 120° (down); the arrow up at both ends of the abscissa."""
    text = (LINEAR_RISE.replace("ROLLER", "0.008").replace("return = \"cosine\"", "return = \"linear\"")
            .replace("rise = 100, dwell_far = 40, return = 100, dwell_near = 120",
                     "rise = 120, dwell_far = 0, return = 240, dwell_near = 0"))
    sol, g = _solved(text)
    h = 0.03
    cs = sol.corners()
    assert [c.phi_deg for c in cs] == [0.0, 120.0]
    assert cs[0].v_after - cs[0].v_before == pytest.approx(h / math.radians(120) + h / math.radians(240), rel=1e-9)
    signs = [(round(math.degrees(q.points[0][0] * g.mu_phi), 6), np.sign(q.points[1][1] - q.points[0][1]))
             for q in _shocks(diagrams(sol, g, "en"))]
    assert signs == [(0.0, 1.0), (120.0, -1.0), (360.0, 1.0)]
