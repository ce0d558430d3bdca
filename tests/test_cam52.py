"""Stop 52's look at the cam sheet (the lead's CAM52: a translating roller follower, offset "auto", the
cam clockwise, a cycloidal rise of 150°, a far dwell of 40°, a trapezoidal return of 100°, h = 32 mm).
Each number against the test's own closed forms and brute force of the inversion:

- the offset "auto" is the e that minimises R0 by a scan of e with the laws in closed form (the
  trapezoidal law's s integrated here from its acceleration's knots), and R0_min is that scan's;
- the follower's axis stands on the side the notes name (right of O for this clockwise cam, drawn so on
  the profile), and there — by brute force of the clockwise inversion — the rise's largest pressure
  angle is larger and the return's smaller than with the axis on the other side: the note says both
  (it said only «збільшує кут тиску на підйомі», read as a wrong choice) and that e was chosen for
  the smallest R0;
- the ϑ(φ) axis is graduated (it had no values): each tick at its value over μ_ϑ, and the exact largest
  ϑ of each phase read off the graduation (interpolated between its ticks) is the brute force's."""
from __future__ import annotations

import math
import re

import numpy as np
import pytest

from conftest import cam_constructed
from graphplan.exact.cam import solve
from graphplan.graphic.cam import construct
from graphplan.model.cam import load
from review_scenes import CAM52

H = 32.0                                        # mm
RISE, FAR, RET = (math.radians(d) for d in (150.0, 40.0, 100.0))
ALLOWED = (28.0, 35.0)


def _laws(phi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """s and ds/dφ (mm, mm/rad) in closed form: the cycloidal rise s = h(u − sin 2πu/2π); the
    trapezoidal return s = h(1 − f(u)) with f″ ramping 0 → 1 over u ∈ [0, 1/8], 1 to 3/8, → −1 at 5/8,
    −1 to 7/8, → 0 at 1 — f and f′ integrated here (trapezoid rule on a fine grid), scaled to f(1) = 1."""
    u = np.linspace(0.0, 1.0, 80001)
    a = np.interp(u, [0, 1 / 8, 3 / 8, 5 / 8, 7 / 8, 1], [0, 1, 1, -1, -1, 0])
    v = np.r_[0.0, np.cumsum((a[1:] + a[:-1]) / 2 * np.diff(u))]
    f = np.r_[0.0, np.cumsum((v[1:] + v[:-1]) / 2 * np.diff(u))]
    v, f = v / f[-1], f / f[-1]
    s, d = np.zeros_like(phi), np.zeros_like(phi)
    r = phi <= RISE
    w = phi[r] / RISE
    s[r] = H * (w - np.sin(2 * np.pi * w) / (2 * np.pi))
    d[r] = H / RISE * (1 - np.cos(2 * np.pi * w))
    fd = (phi > RISE) & (phi < RISE + FAR)
    s[fd] = H
    t = (phi >= RISE + FAR) & (phi <= RISE + FAR + RET)
    w = (phi[t] - RISE - FAR) / RET
    s[t] = H * (1 - np.interp(w, u, f))
    d[t] = -H / RET * np.interp(w, u, v)
    return s, d


PHI = np.r_[np.linspace(0.0, RISE, 6001), np.linspace(RISE + FAR, RISE + FAR + RET, 6001)]
S, V = _laws(PHI)
IS_RISE = PHI <= RISE


def _smallest(e: float) -> float:
    """R0 (mm) at offset e: |ϑ| ≤ [ϑ] is s0 ≥ |ds/dφ − e|/tg[ϑ] − s on each phase (tg ϑ = (ds/dφ − e)/(s0 + s),
    e > 0 to the side that lowers the rise's angle)."""
    tg = np.where(IS_RISE, math.tan(math.radians(ALLOWED[0])), math.tan(math.radians(ALLOWED[1])))
    s0 = float(np.max(np.abs(V - e) / tg - S))
    return math.hypot(e, s0)


def _largest(x_axis: float, R0: float) -> tuple[float, float]:
    """The rise's and the return's largest |ϑ| (°) by brute force: the roller centre on the vertical
    x = x_axis at height s0 + s, the clockwise cam's frame turned back by +φ, ϑ the angle between the
    centre profile's normal and the follower's axis seen from the cam."""
    s0 = math.sqrt(R0 ** 2 - x_axis ** 2)
    out = []
    for lo, hi in ((0.0, RISE), (RISE + FAR, RISE + FAR + RET)):
        phi = np.linspace(lo, hi, 24001)
        s, _ = _laws(phi)
        P = (x_axis + 1j * (s0 + s)) * np.exp(1j * phi)
        t = np.gradient(P, phi)
        axis = 1j * np.exp(1j * phi)
        out.append(float(np.degrees(np.arcsin(np.clip(np.abs((t * axis.conjugate()).real) / np.abs(t), 0, 1))).max()))
    return out[0], out[1]


@pytest.fixture(scope="module")
def cam52(tmp_path_factory):
    return cam_constructed(CAM52, tmp_path_factory, "cam52")


def test_the_auto_offset_is_the_scans_smallest_R0(cam52):
    sol, _ = cam52
    es = np.linspace(-8.0, 8.0, 1601)
    R = [_smallest(e) for e in es]
    k = int(np.argmin(R))
    fine = np.linspace(es[k] - 0.02, es[k] + 0.02, 81)
    e_best = float(fine[np.argmin([_smallest(e) for e in fine])])
    assert sol.geometry.e * 1000 == pytest.approx(e_best, abs=0.05 + 1e-9)       # rounded to 0.1 mm
    assert sol.R0_min * 1000 == pytest.approx(_smallest(sol.geometry.e * 1000), abs=0.01)
    assert _smallest(sol.geometry.e * 1000) < _smallest(0.0) - 2.0                # the offset pays: 35.6 < 38.2 mm


@pytest.mark.parametrize("lang", ["uk", "en"])
def test_the_axis_side_and_both_phases_effect_are_said_and_drawn(cam52, lang):
    from graphplan.drawing.cam import profile_drawing
    from graphplan.report.cam import cam_json, cam_lines
    sol, g = cam52
    doc = cam_json(sol, g, "x")
    (line,) = [x for x in cam_lines(doc, lang) if x.startswith(("Ексцентриситет", "Offset"))]
    right = ("праворуч" if lang == "uk" else "right") in line
    e = abs(sol.geometry.e) * 1000
    x_axis = e if right else -e
    R0 = doc["base_radius_m"] * 1000
    here, there = _largest(x_axis, R0), _largest(-x_axis, R0)
    assert here == pytest.approx(tuple(abs(x) for x in sol.pressure_maxima()), abs=0.05)
    raises = here[0] > there[0]
    assert here[1] < there[1] if raises else here[1] > there[1]
    want = ("збільшує кут тиску на підйомі й зменшує" if raises else "зменшує кут тиску на підйомі й збільшує") \
        if lang == "uk" else ("raising the pressure angle of the rise and lowering that of the return" if raises
                              else "lowering the pressure angle of the rise and raising that of the return")
    assert want in line
    assert ("R_0 був найменшим" if lang == "uk" else "chosen for the smallest R_0") in line
    # drawn on that side: the follower's axis on the profile at x = ±e/μ_l from O
    rec = profile_drawing(sol, g, lang)
    (axis,) = [q for q in rec.items if q.step == "follower axis"]
    assert axis.points[0][0] == pytest.approx(x_axis / 1000 / g.mu_l, abs=1e-6)


def test_the_pressure_axis_is_graduated_and_reads_the_largest_angles(cam52):
    from graphplan.drawing.cam import pressure_diagram, pressure_scales
    sol, g = cam52
    mu_phi, mu_t = pressure_scales(sol, 300.0, 160.0)
    rec = pressure_diagram(sol, g, "uk", mu_phi, mu_t)
    ticks = [q for q in rec.items if q.step == "ϑ graduation" and q.kind == "segment"]
    texts = [q for q in rec.items if q.step == "ϑ graduation" and q.kind == "text"]
    values = sorted(float(t.text.replace("−", "-").replace(",", ".")) for t in texts)
    ys = sorted(q.points[0][1] for q in ticks)
    assert len(values) == len(ys) >= 6
    assert ys == pytest.approx([v / mu_t for v in values], abs=1e-9)
    step = values[1] - values[0]
    assert step / mu_t >= 8.0 and step in (1.0, 2.0, 5.0, 10.0, 20.0, 50.0)
    assert np.allclose(np.diff(sorted(values + [0.0])), step)          # 0 on the φ axis, unlettered
    assert min(values) <= -ALLOWED[1] + step and max(values) >= ALLOWED[0] - step      # the bands' range
    # the curve's extremes read on the graduation: between the two ticks that bracket them
    curve = np.asarray(next(q for q in rec.items if q.step == "ϑ(φ) exact").points)
    R0 = sol.geometry.R0 * 1000
    truth = _largest(sol.cam.sense * sol.geometry.e * 1000, R0)      # the axis at x = σe
    for y, want in ((curve[:, 1].max(), truth[0]), (-curve[:, 1].min(), truth[1])):
        lo = max(v for v in np.abs(values) if v / mu_t <= y)
        read = lo + (y - lo / mu_t) / (step / mu_t) * step
        assert read == pytest.approx(want, abs=0.1)
    labels = [t for t in texts if re.fullmatch(r"−?\d+", t.text)]
    assert len(labels) == len(texts)            # whole degrees, a true minus


def test_a_roller_circle_at_every_division_touches_the_working_profile(cam52):
    """The working profile as the envelope of roller circles (REFERENCE §11): a circle of the roller's
    radius about every division's centre-profile point (it was drawn at every second one), each
    tangent to the drawn working profile — its nearest point at r from the centre, to the ruler's
    0.5 mm the construction's points are laid off with."""
    from graphplan.drawing.cam import profile_drawing
    sol, g = cam52
    rec = profile_drawing(sol, g, "uk")
    r = sol.cam.roller / g.mu_l
    pts = {int(q.step.split()[2]): complex(*q.points[0]) for q in rec.items
           if q.step and q.step.startswith("profile point ")}
    rollers = {int(q.step.split()[1]): q for q in rec.items if q.step and q.step.startswith("roller ")}
    assert set(rollers) == set(pts) == set(range(len(g.phi)))
    W = np.array([complex(*p) for p in next(q for q in rec.items if q.step == "working profile").points])
    for k, q in rollers.items():
        assert q.kind == "circle" and q.radius == pytest.approx(r)
        assert complex(*q.points[0]) == pytest.approx(pts[k], abs=1e-9)
        # the point is the construction's (s laid off as read, to the ruler's 0.5 mm), the profile exact
        assert _nearest(W, pts[k]) == pytest.approx(r, abs=0.5)


def _nearest(W: np.ndarray, z: complex) -> float:
    """The distance from z to the polyline W (its segments, not only its vertices)."""
    a, b = W[:-1], W[1:]
    t = np.clip(((z - a) * np.conj(b - a)).real / np.maximum(np.abs(b - a) ** 2, 1e-30), 0.0, 1.0)
    return float(np.min(np.abs(a + t * (b - a) - z)))


def test_the_short_offset_is_dimensioned_from_outside(cam52):
    """e = 1.8 mm at 1:1 (its letter by a 1.8 mm line among the rays at O was unreadable): the
    dimension's two arrows end on O's extension line and on the follower's axis, at one level, each
    coming from outside the span, and e is lettered once, clear of the span."""
    from graphplan.drawing.cam import profile_drawing
    sol, g = cam52
    rec = profile_drawing(sol, g, "uk")
    (axis,) = [q for q in rec.items if q.step == "follower axis"]
    x_axis = axis.points[0][0]
    arrows = [q for q in rec.items if q.kind == "vector" and q.step == "offset e dimension"]
    assert len(arrows) == 2
    tips = sorted((q.points[1][0], q.points[0][0], q.points[1][1]) for q in arrows)
    lo, hi = sorted((0.0, x_axis))
    assert tips[0][0] == pytest.approx(lo) and tips[1][0] == pytest.approx(hi)
    assert tips[0][1] < lo and tips[1][1] > hi                       # from outside, pointing in
    assert tips[0][2] == pytest.approx(tips[1][2])
    assert min(p[1] for p in axis.points) <= tips[0][2] <= max(p[1] for p in axis.points)
    (ext,) = [q for q in rec.items if q.step == "offset e extension"]
    assert {p[0] for p in ext.points} == {0.0}
    assert min(p[1] for p in ext.points) <= tips[0][2] <= max(p[1] for p in ext.points)
    (e,) = [q for q in rec.items if q.kind == "text" and q.text == "e"]
    x0, _, x1, _ = e.ink()
    assert x0 >= hi or x1 <= lo


def test_own_cam52_counter_clockwise_auto_offset_lowers_the_steep_rise(tmp_path):
    """OWN_CAM52 (cam ccw, a steep cosine rise of 80°, a parabolic return of 160°, [ϑ] = 30° both): the
    closed forms' scan of e puts the optimum on the side that lowers the rise (e > 0), the program's e
    is it to 0.1 mm, and the note says the axis is right of O (x = σe, σ = +1), lowering the rise's
    angle and raising the return's."""
    from review_scenes import OWN_CAM52

    from graphplan.report.cam import cam_json, cam_lines
    path = tmp_path / "own52.toml"
    path.write_text(OWN_CAM52, encoding="utf-8")
    sol = solve(load(path))
    h, rise, ret, tg = 25.0, math.radians(80.0), math.radians(160.0), math.tan(math.radians(30.0))
    u = np.linspace(0.0, 1.0, 4001)
    s1, v1 = h * (1 - np.cos(np.pi * u)) / 2, h * np.pi / (2 * rise) * np.sin(np.pi * u)
    s2 = h * (1 - np.where(u < 0.5, 2 * u * u, 1 - 2 * (1 - u) ** 2))
    v2 = -h / ret * np.where(u < 0.5, 4 * u, 4 * (1 - u))

    def smallest(e: float) -> float:
        return math.hypot(e, max(np.max(np.abs(v1 - e) / tg - s1), np.max(np.abs(v2 - e) / tg - s2)))
    es = np.linspace(-10.0, 10.0, 4001)
    e_best = float(es[np.argmin([smallest(e) for e in es])])
    assert e_best > 0 and sol.geometry.e * 1000 == pytest.approx(e_best, abs=0.05 + 0.005)
    assert sol.R0_min * 1000 == pytest.approx(smallest(sol.geometry.e * 1000), abs=0.01)
    g = construct(sol, measure=False)
    (line,) = [x for x in cam_lines(cam_json(sol, g, "x"), "uk") if x.startswith("Ексцентриситет")]
    assert "праворуч від O: зменшує кут тиску на підйомі й збільшує — на опусканні" in line
