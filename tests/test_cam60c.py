"""Stop 60 (cam60c): a CLOCKWISE cam's rocking follower laid as the counter-clockwise layout mirrored about the
line O–O1 — the arm under it, on the side the phase diagram ψ–dψ/dφ finds favourable for a clockwise turn
(before, the arm stood over O–O1 for either sense: CAM60's R0 min was 54,44 mm, 49,44 with the arm mirrored).

The truth: the mirror itself (a clockwise cam's pressure angle, curvature and smallest base radius are the
counter-clockwise cam's, its centre and working profiles their mirror images), and the pressure angle by the
instant centre of the cam and the arm (not the program's formula): the force's line through P on O–O1, where
ω_cam·OP = ω_arm·AP, its angle to the roller centre's velocity (square to the arm)."""
from __future__ import annotations

import cmath
import dataclasses
import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings, strategies as st

from camfixtures import cam_fixture
from graphplan.exact.cam import geometry, min_base_radius, motion, phase_of, profile
from graphplan.model.cam import LAWS, Cam
from review_scenes import CAM60

cam60 = cam_fixture("cam60", CAM60, 12)


def _rocking(laws, phases, swing_deg, a, l, sense) -> Cam:
    return Cam("c", "rocking", math.radians(swing_deg), phases, laws, (40.0, 45.0), 10.0, sense,
               roller=0.01, offset=None, arm=l, centre_distance=a)


def _instant_centre_theta(cam: Cam, R0: float, phi: np.ndarray) -> np.ndarray:
    """|ϑ| (deg) of a clockwise cam with the arm UNDER O–O1, C = A + l·e^{−i(π − ψ0 − ψ)}: the arm turns
    counter-clockwise at dψ/dφ as ψ grows, the cam clockwise at 1; P on O–O1 has one velocity on both."""
    a, l = cam.centre_distance, cam.arm
    s, v, _ = motion(cam, phi)
    psi0 = math.acos((a * a + l * l - R0 * R0) / (2 * a * l))
    C = a + l * np.exp(-1j * (np.pi - psi0 - s))
    wa, wc = v, -1.0
    P = wa * a / (wa - wc)
    n = (P - C) / np.abs(P - C)
    u = 1j * (C - a) / l                                # C's velocity as ψ grows
    return np.degrees(np.arccos(np.clip(np.abs(np.real(np.conj(n) * u)), 0.0, 1.0)))


@st.composite
def rocking_cams(draw):
    laws = (draw(st.sampled_from(LAWS)), draw(st.sampled_from(LAWS)))
    rise = draw(st.integers(60, 150))
    ret = draw(st.integers(60, 150))
    far = draw(st.integers(0, 360 - rise - ret))
    swing = draw(st.integers(10, 30))
    a = draw(st.integers(90, 160)) / 1000.0
    l = draw(st.integers(60, 130)) / 1000.0
    lo, hi = abs(a - l), a + l
    R0 = lo + (hi - lo) * draw(st.floats(0.25, 0.75))
    return laws, (float(rise), float(far), float(ret), float(360 - rise - far - ret)), swing, a, l, R0


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(rocking_cams())
def test_a_clockwise_rocking_cam_is_the_counter_clockwise_one_mirrored(case):
    """Over laws, phases, swings, arms, centre distances and base radii: a clockwise cam's ϑ(φ) and ρ(φ) are the
    counter-clockwise cam's, its centre and working profiles their mirror images about O–O1 (conjugates), and
    its |ϑ| the instant centre's with the arm under O–O1."""
    laws, phases, swing, a, l, R0 = case
    cw, ccw = (_rocking(laws, phases, swing, a, l, s) for s in (-1, +1))
    phi = np.linspace(0.0, 360.0, 1441)
    g = geometry(cw, R0)
    p, q = profile(cw, g, phi), profile(ccw, g, phi)
    np.testing.assert_allclose(p["theta"], q["theta"], atol=1e-9)
    finite = np.isfinite(q["rho"]) & (np.abs(q["rho"]) < 1e3)
    np.testing.assert_allclose(p["rho"][finite], q["rho"][finite], rtol=1e-9, atol=1e-12)
    np.testing.assert_allclose(p["P"], np.conj(q["P"]), atol=1e-12)
    np.testing.assert_allclose(p["working"], np.conj(q["working"]), atol=1e-12)
    active = phase_of(cw, phi) >= 0
    np.testing.assert_allclose(np.abs(p["theta"][active]), _instant_centre_theta(cw, R0, phi[active]), atol=1e-6)
    # the arm under O–O1 at the nearest position: C₀ below the line, |C₀| = R0
    C0 = p["P"][0]
    assert C0.imag < 0 and abs(C0) == pytest.approx(R0, rel=1e-12)


@pytest.mark.slow     # 7 s: 12 root-finds; the default suite has the mirror itself (ϑ equal at every φ) and CAM60's R0
@settings(max_examples=6, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(rocking_cams())
def test_a_clockwise_rocking_cams_smallest_base_radius_is_the_counter_clockwise_ones(case):
    """R0 min of the clockwise cam equals the counter-clockwise cam's (the mirror), and at it the instant centre's
    largest |ϑ| of the phase that binds reaches its allowed angle."""
    laws, phases, swing, a, l, _ = case
    cw, ccw = (_rocking(laws, phases, swing, a, l, s) for s in (-1, +1))
    try:
        r_cw = min_base_radius(cw)
    except Exception as err:                           # no base radius allows [ϑ]: the same for both senses
        with pytest.raises(type(err)):
            min_base_radius(ccw)
        return
    assert r_cw == pytest.approx(min_base_radius(ccw), abs=1e-9)
    phi = np.linspace(0.0, 360.0, 14401)
    phase = phase_of(cw, phi)
    th = _instant_centre_theta(cw, r_cw, phi)
    worst = max(th[phase == k].max() / cw.allowed[k] for k in (0, 1))
    assert worst <= 1.0 + 1e-3


def test_cam60s_smallest_base_radius_by_bisection_on_the_instant_centre(cam60):
    """CAM60 (cw; a = 130, l = 100 mm, ψ_max = 20°, cycloidal rise 120°, cosine return 100°, [ϑ] 35°/40°): the
    first allowed R0 of a scan of the arm's reach, bisected, with the instant centre's ϑ — 49,44 mm (54,44 mm
    with the arm over O–O1)."""
    cam, sol, g, doc = cam60
    phi = np.linspace(0.0, 360.0, 28801)
    phase = phase_of(cam, phi)

    def worst(R):
        th = _instant_centre_theta(cam, R, phi)
        return max(th[phase == k].max() / cam.allowed[k] for k in (0, 1))
    lo, hi = abs(cam.centre_distance - cam.arm) + 1e-6, cam.centre_distance + cam.arm - 1e-6
    scan = np.linspace(lo, hi, 200)
    k = next(i for i, R in enumerate(scan) if worst(R) <= 1.0)
    lo, hi = scan[k - 1], scan[k]
    for _ in range(50):
        mid = (lo + hi) / 2
        lo, hi = (lo, mid) if worst(mid) <= 1.0 else (mid, hi)
    assert hi * 1000 == pytest.approx(49.441, abs=2e-3)
    assert doc["base_radius_min_m"] == pytest.approx(hi, abs=2e-6)


def test_cam60s_profile_draws_the_arm_under_the_line_and_omega_clockwise(cam60):
    """The profile's start position: the arm from O_1 (on +x) to the roller under O–O1, its top position
    (dashed) turned counter-clockwise about O_1 by ψ_max — away from O, under it too —, the support over
    O_1 (the side away from the arm), ψ_max's dimension arc between the two arms, ω's arrow clockwise and
    the pivots numbered counter-clockwise (against ω)."""
    from graphplan.drawing.cam import profile_drawing
    cam, sol, g, doc = cam60
    rec = profile_drawing(sol, g, "uk")
    (arm,) = [q for q in rec.items if q.step == "arm"]
    A, C = (complex(*z) for z in arm.points)
    assert A.imag == pytest.approx(0.0) and A.real > 0 and C.imag < 0
    (top,) = [q for q in rec.items if q.step == "swing top arm"]
    T = complex(*top.points[1])
    turn = cmath.phase((T - A) / (C - A))
    assert turn == pytest.approx(cam.stroke, abs=1e-6) and T.imag < C.imag and abs(T) > abs(C)
    frame = [complex(*z) for q in rec.items if q.role == "frame" for z in q.points]
    assert frame and all(z.imag >= A.imag - 1e-9 for z in frame) and max(z.imag for z in frame) > A.imag + 4
    (vec,) = [q for q in rec.items if q.step == "ω" and q.kind == "vector"]
    tail, tip = (complex(*z) for z in vec.points)
    assert ((tip - tail) * tip.conjugate()).imag < 0          # OP × (tip − tail) < 0: the head turns clockwise
    dim = [q for q in rec.items if q.step == "swing psi_max" and q.kind == "arc"]
    (d,) = dim
    lo, hi = sorted(math.radians(x) for x in d.angles)
    assert hi - lo == pytest.approx(cam.stroke, abs=1e-6)
    assert cmath.phase(C - A) == pytest.approx(hi, abs=1e-6) or cmath.phase(C - A) == pytest.approx(lo, abs=1e-6)


def test_cam60s_phase_diagram_is_the_counter_clockwise_cams_mirrored(cam60):
    """The phase diagram's roller centres C, the directions u of their motion and the ends K of the drawn
    l·dψ/dφ laid off square to it in ω's sense: the counter-clockwise cam's mirrored about O–O1."""
    from graphplan.drawing.cam import phase_points
    from graphplan.exact.cam import Solution
    cam, sol, g, doc = cam60
    mirror = Solution(dataclasses.replace(cam, sense=1), sol.geometry, sol.R0_min, [])
    for x, y in zip(phase_points(sol, g), phase_points(mirror, g)):
        np.testing.assert_allclose(x, np.conj(y), atol=1e-12)
    C, u, K = phase_points(sol, g)
    assert np.all(C.imag < 0)                                 # the arm's roller under O–O1
