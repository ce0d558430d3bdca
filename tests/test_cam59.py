"""Stop 59's cam sheet: the lead's CAM59 (a translating roller follower, the cam CLOCKWISE, a NEGATIVE offset
e = −6 mm — to the side that raises the rise's pressure angle —, a cosine rise of 100°, a far dwell of 40°, a
parabolic return of 110°, h = 35 mm, r = 12 mm, [ϑ] 28°/35°, 8 divisions) against closed forms written here
(tg ϑ = (ds/dφ − e)/(s0 + s) with s0 = √(R0² − e²), the laws' own formulas, R0 by bisection); its phase
diagram and profile read off their records (O's side, the angles at O, the offset dimensioned); and CAM58's
rocking phase diagram, whose [ϑ] lines cross past the drawn ends: both boundaries of the region hatched."""
from __future__ import annotations

import math

import numpy as np
import pytest

from camfixtures import cam_fixture
from review_scenes import CAM58, CAM59

cam59 = cam_fixture("cam59", CAM59, 8)
cam58 = cam_fixture("cam58", CAM58, 10)

H, E = 35.0, -6.0                                  # mm
RISE, FAR, RET = 100.0, 40.0, 110.0                # degrees
ALLOWED = (28.0, 35.0)


def _s(phi):
    """(s, ds/dφ) in mm and mm/rad at the cam's turns ``phi`` (degrees): the cosine rise, the far dwell,
    the parabolic return (two parabolas meeting at its middle), the near dwell."""
    phi = np.asarray(phi, float)
    s, v = np.zeros_like(phi), np.zeros_like(phi)
    m = phi <= RISE
    u = phi[m] / RISE
    s[m] = H / 2 * (1 - np.cos(np.pi * u))
    v[m] = H * np.pi / (2 * math.radians(RISE)) * np.sin(np.pi * u)
    s[(phi > RISE) & (phi <= RISE + FAR)] = H
    m = (phi > RISE + FAR) & (phi <= RISE + FAR + RET)
    u = (phi[m] - RISE - FAR) / RET
    s[m] = np.where(u < 0.5, H * (1 - 2 * u * u), 2 * H * (1 - u) ** 2)
    v[m] = np.where(u < 0.5, -4 * H * u, -4 * H * (1 - u)) / math.radians(RET)
    return s, v


PHI = np.linspace(0.0, 360.0, 360001)
S, V = _s(PHI)
ON = (PHI <= RISE, (PHI >= RISE + FAR) & (PHI <= RISE + FAR + RET))


def _theta(R0: float, s=S, v=V):
    """ϑ in degrees at the base radius R0 (mm), either sense of the cam (the axis at σe: the sense enters
    only through which side O is drawn on, not the angle's value)."""
    return np.degrees(np.arctan((v - E) / (math.sqrt(R0 * R0 - E * E) + s)))


def _least() -> float:
    def worst(R0):
        th = _theta(R0)
        return max(np.max(np.abs(th[ON[0]])) / ALLOWED[0], np.max(np.abs(th[ON[1]])) / ALLOWED[1])
    lo, hi = 10.0, 200.0
    for _ in range(60):
        mid = (lo + hi) / 2
        lo, hi = (lo, mid) if worst(mid) <= 1.0 else (mid, hi)
    return hi


def test_cam59_base_radius_and_pressure_angles_by_closed_forms(cam59):
    """R0 min 55,881 mm (the rise binds: 28° at φ ≈ 40,9°, the negative offset adding to ds/dφ); at the
    taken R0 = 56 mm each phase's largest ϑ and its turn, and ϑ at the 18 divisions — the dwells' ϑ not
    0 (O off the axis: atan(6/s0) = 6,15° on the near dwell)."""
    cam, sol, g, doc = cam59
    least = _least()
    assert least == pytest.approx(55.881, abs=1e-3)
    assert doc["base_radius_min_m"] * 1000 == pytest.approx(least, abs=1e-3)
    assert doc["base_radius_m"] == pytest.approx(0.056)
    th = _theta(56.0)
    for name, m in zip(("rise", "return"), ON):
        k = int(np.argmax(np.abs(th[m])))
        assert doc["pressure_angle_extreme_deg"][name] == pytest.approx(th[m][k], abs=0.01)
        assert doc["pressure_angle_extreme_phi_deg"][name] == pytest.approx(PHI[m][k], abs=0.05)
    assert doc["pressure_angle_extreme_deg"]["rise"] == pytest.approx(27.96, abs=0.01)
    assert doc["pressure_angle_extreme_deg"]["return"] == pytest.approx(-22.60, abs=0.01)
    for p in doc["positions"]:
        s, v = _s([p["phi_deg"]])
        assert p["exact"]["pressure_angle_deg"] == pytest.approx(float(_theta(56.0, s, v)[0]), abs=0.01), p["number"]
    assert doc["positions"][0]["exact"]["pressure_angle_deg"] == pytest.approx(
        math.degrees(math.atan(6.0 / math.sqrt(56.0 ** 2 - 36.0))), abs=0.01)


def _one(rec, step):
    return next(p for p in rec.items if p.step == step)


def test_cam59_phase_diagram_draws_o_on_its_side_and_the_offset_dimensioned(cam59):
    """The phase diagram read off its record: the s axis 6 mm (at μ_s) to the RIGHT of the drawn O (the cam
    clockwise, e < 0: the axis at σe = +6 mm); the SIGNED angle at O from the s axis to each drawn K is the
    closed form's ϑ within 1° (an O mirrored to the axis' other side reads atan((ds/dφ − 6)/…): 7–10° off on
    the rise); e drawn from O to the axis with two arrows inside, one at the axis, one at the edge of O's dot."""
    from graphplan.drawing.cam import O_DOT, phase_diagram
    cam, sol, g, doc = cam59
    rec = phase_diagram(sol, g, "uk")
    mu = g.mu_s * 1000                                                       # mm of s a drawn mm
    O = complex(*_one(rec, "O").points[0])
    axis = [complex(*q) for q in _one(rec, "follower axis").points]
    assert axis[0].real == pytest.approx(axis[1].real)
    assert (axis[0].real - O.real) * mu == pytest.approx(6.0, abs=1e-6)
    for k, p in enumerate(doc["positions"]):
        K = complex(*_one(rec, f"K {k}").points[0]) - O
        s, v = _s([p["phi_deg"]])
        assert math.degrees(math.atan2(K.real, K.imag)) == pytest.approx(float(_theta(56.0, s, v)[0]), abs=1.0), k
    C0 = complex(*_one(rec, "K 0").points[0])
    assert abs(C0 - O) * mu == pytest.approx(56.0, abs=1e-6)
    tips = sorted((complex(*q.points[1]) for q in rec.items if q.step == "offset e dimension"), key=abs)
    assert len(tips) == 2
    assert tips[0] == pytest.approx(O + O_DOT) and tips[1] == pytest.approx(complex(axis[0].real, O.imag))


def test_cam59_profile_dimensions_the_offset_to_the_right_of_o(cam59):
    """On the profile (μ_l) the follower's axis stands |e| right of O (the start position, the cam
    clockwise, e < 0), dimensioned: the line O — axis with its two arrows inside (6 mm drawn at 1:1, not
    under SMALL_OFFSET: no arrows outside)."""
    from graphplan.drawing.cam import O_DOT, profile_drawing
    cam, sol, g, doc = cam59
    rec = profile_drawing(sol, g, "uk")
    x = 6.0 / (g.mu_l * 1000)
    tips = sorted((complex(*q.points[1]) for q in rec.items if q.step == "offset e dimension"), key=abs)
    assert len(tips) == 2
    assert tips[0] == pytest.approx(complex(O_DOT, 0.0)) and tips[1] == pytest.approx(complex(x, 0.0))
    assert not any(q.step == "offset e extension" for q in rec.items)
    axis = _one(rec, "follower axis").points
    assert axis[0][0] == pytest.approx(x) and axis[1][0] == pytest.approx(x)


def test_cam58_rocking_phase_diagram_hatches_both_boundaries_of_the_region(cam58):
    """CAM58's [ϑ] = 40° and 45° lines (10° apart) cross past where stop 58 ended them: both are drawn on
    to their crossing and past it, and the region — O's side of BOTH lines — is hatched along both
    boundaries: the 45° line from past O to the crossing, the 40° line beyond it; every stroke (both its
    ends) on O's side of both lines (computed here from the drawn lines: a stroke outside would mark
    a place of O that sees a point past [ϑ])."""
    from graphplan.drawing.cam import phase_diagram
    cam, sol, g, doc = cam58
    rec = phase_diagram(sol, g, "uk")
    O = complex(*_one(rec, "O").points[0])
    lines = [[complex(*q) for q in _one(rec, f"[ϑ] line {j}").points] for j in (0, 1)]

    def side(z, line):
        a, b = line
        return ((z - a) * (b - a).conjugate()).imag

    (a0, b0), (a1, b1) = lines
    d0, d1 = b0 - a0, b1 - a1
    t0 = ((a1 - a0).conjugate() * d1).imag / (d0.conjugate() * d1).imag
    t1 = ((a1 - a0).conjugate() * d0).imag / (d0.conjugate() * d1).imag
    assert 0.0 < t0 < 1.0 and 0.0 < t1 < 1.0                    # the corner of the region drawn
    corner = a0 + t0 * d0
    for j in (0, 1):
        strokes = [[complex(*q) for q in p.points] for p in rec.items if p.step == f"region {j}"]
        assert len(strokes) >= 4, j
        for foot, tip in strokes:                                # the foot on its own line, the tip off it
            for line in lines:
                assert side(tip, line) * side(O, line) > 0 and side(foot, line) * side(O, line) > -1e-9
    # the line nearer O bounds it up to the corner, the other past it: the strokes on each lie on one
    # side of the corner only, on opposite sides for the two lines
    where = [{np.sign(((complex(*p.points[0]) - corner) * (b - a).conjugate()).real)
              for p in rec.items if p.step == f"region {j}"} for j, (a, b) in enumerate(lines)]
    assert all(len(w) == 1 for w in where) and where[0] != where[1]
