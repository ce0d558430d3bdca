"""Stop 62's cam sheets against numbers worked out apart from the code: the lead's CAM62 (a translating
roller follower, the cam CLOCKWISE, a NEGATIVE offset e = −6 mm, a parabolic rise, a cosine return) —
its smallest R0, the phases' largest pressure angles and ρ_min with the parabolic law's one-sided limit
by tg ϑ = (ds/dφ − e)/(s0 + s) and the centre profile turned point by point —, and CAM61's faintly concave
stretch of the profile (a knife-edge, a trapezoidal rise, a cycloidal return) found by a brute force and
said in the notes."""
from __future__ import annotations

import math

import numpy as np
import pytest

from camfixtures import cam_fixture
from review_scenes import CAM61, CAM62

cam62 = cam_fixture("cam62", CAM62, 8)
cam61 = cam_fixture("cam61", CAM61, 10)


def _parabolic(u):
    return np.where(u <= 0.5, 2 * u ** 2, 1 - 2 * (1 - u) ** 2)


def _trapezoidal(u):
    """The trapezoidal-acceleration law's s/h: its acceleration (ramps over the first and last eighths and
    the middle quarter) integrated twice numerically, scaled to 1 at u = 1."""
    grid = np.linspace(0.0, 1.0, 400001)
    a = np.interp(grid, [0, 1 / 8, 3 / 8, 5 / 8, 7 / 8, 1], [0, 1, 1, -1, -1, 0])
    v = np.concatenate([[0.0], np.cumsum((a[1:] + a[:-1]) / 2 * np.diff(grid))])
    s = np.concatenate([[0.0], np.cumsum((v[1:] + v[:-1]) / 2 * np.diff(grid))])
    return np.interp(u, grid, s / s[-1])


def _s(phi, h, phases, f_rise, f_ret):
    """s(φ) over a turn (φ in degrees), the rise by f_rise, the return by 1 − f_ret."""
    rise, far, ret, _ = phases
    p = np.mod(np.asarray(phi, float), 360.0)
    out = np.zeros_like(p)
    m = p <= rise
    out[m] = h * f_rise(p[m] / rise)
    out[(p > rise) & (p <= rise + far)] = h
    m = (p > rise + far) & (p <= rise + far + ret)
    out[m] = h * (1.0 - f_ret((p[m] - rise - far) / ret))
    return out


def _centre_profile(phi, s, e, R0, sense):
    """The centre profile seen from the cam turning by φ (sense +1 counter-clockwise): the follower's
    point C = (sense·e, s0 + s) turned back by −sense·φ."""
    s0 = math.sqrt(R0 ** 2 - e ** 2)
    return (sense * e + 1j * (s0 + s)) * np.exp(-1j * sense * np.radians(phi))


def _signed_rho(P, dphi):
    """ρ by central differences, + where convex (the curve's turning taken against its own orientation)."""
    d1 = (np.roll(P, -1) - np.roll(P, 1)) / (2 * dphi)
    d2 = (np.roll(P, -1) - 2 * P + np.roll(P, 1)) / dphi ** 2
    cross = (np.conj(d1) * d2).imag
    area = 0.5 * float(np.sum((np.conj(P) * np.roll(P, -1)).imag))   # > 0: counter-clockwise
    return np.sign(area) * np.abs(d1) ** 3 / cross


@pytest.mark.slow
def test_cam62_radius_angles_and_curvature_by_brute_force(cam62):
    """CAM62 (h = 25 mm, e = −6 mm, [ϑ] 30°/40°, roller 8 mm, clockwise): s0 ≥ (ds/dφ − e)/tg[ϑ] − s over
    the rise (the return's |ds/dφ − e|/tg 40° − s is far less) gives R0_min = √(e² + s0²) = 47.889 mm; at the
    48 mm taken the rise's largest ϑ is 29.95° at φ = 50° (the parabolic law's middle, where ds/dφ is
    largest), the return's −9.64° at 215.9°; the centre profile's ρ_min 42.94 mm is the middle's limit from
    the decelerating side (d²s/dφ² = −4h/Φ²), no concave stretch; ϑ at the divisions as Table 2 prints."""
    cam, sol, g, doc = cam62
    h, e, rise, ret = 25.0, -6.0, 100.0, 140.0
    phi = np.linspace(0.0, 360.0, 1440001)
    cos = lambda u: (1 - np.cos(np.pi * u)) / 2        # noqa: E731
    s = _s(phi, h, (rise, 40.0, ret, 80.0), _parabolic, cos)
    v = np.gradient(s, np.radians(phi[1] - phi[0]))
    up, down = phi <= rise, (phi >= 140.0) & (phi <= 280.0)
    s0 = max(float(np.max((v[up] - e) / math.tan(math.radians(30)) - s[up])),
             float(np.max(-(v[down] - e) / math.tan(math.radians(40)) - s[down])))
    r0 = math.hypot(e, s0)
    assert r0 == pytest.approx(47.889, abs=2e-3) and sol.R0_min * 1000 == pytest.approx(r0, abs=2e-3)
    assert doc["base_radius_m"] == 0.048 == math.ceil(r0) / 1000
    theta = np.degrees(np.arctan((v - e) / (math.sqrt(48.0 ** 2 - e ** 2) + s)))
    i, j = np.argmax(np.where(up, theta, -90)), np.argmin(np.where(down, theta, 90))
    assert doc["pressure_angle_extreme_deg"]["rise"] == pytest.approx(theta[i], abs=0.01) and phi[i] == pytest.approx(50.0, abs=1e-3)
    assert doc["pressure_angle_extreme_deg"]["return"] == pytest.approx(theta[j], abs=0.01)
    assert doc["pressure_angle_extreme_phi_deg"]["return"] == pytest.approx(phi[j], abs=0.1)
    # ρ: the centre profile turned point by point (clockwise: sense −1), on a grid apart from the knots
    grid = np.linspace(0.0, 360.0, 360001)[:-1]
    P = _centre_profile(grid, _s(grid, h, (rise, 40.0, ret, 80.0), _parabolic, cos) / 1000, e / 1000, 0.048, -1)
    rho = _signed_rho(P, np.radians(grid[1] - grid[0]))
    assert np.all(rho > 0) and not doc["profile_concave"]
    # the one-sided limit at the middle: at 50° + a hair (the decelerating side) ρ is the smallest
    assert float(np.min(rho)) == pytest.approx(doc["curvature_min_m"], rel=2e-3)
    assert doc["curvature_min_m"] * 1000 == pytest.approx(42.94, abs=0.01) and doc["curvature_min_m"] > 0.008
    tab = [p["exact"]["pressure_angle_deg"] for p in doc["positions"]]
    want = np.degrees(np.arctan((np.interp([12.5 * k for k in range(9)], phi, v) - e)
                                / (math.sqrt(48.0 ** 2 - e ** 2) + np.interp([12.5 * k for k in range(9)], phi, s))))
    assert tab[:9] == pytest.approx(list(want), abs=0.02)


@pytest.mark.slow
def test_cam61_concave_stretch_found_and_said(cam61):
    """CAM61 (knife-edge, counter-clockwise, e "auto" = 0.5 mm, R0 = 26 mm): the brute force's centre
    profile is concave over φ ≈ 272.5…281.3° of the cycloidal return, |ρ| ≥ 601.6 mm there — the JSON's
    profile_concave says the same run, and the notes' curvature line says it in both languages, ρ_min
    (26 mm, the base circle's on the near dwell) «over the convex parts»."""
    from graphplan.report.cam import cam_lines
    cam, sol, g, doc = cam61
    e, R0 = sol.geometry.e, sol.geometry.R0
    assert R0 == pytest.approx(0.026) and e == pytest.approx(0.0005, abs=1e-6)
    cyc = lambda u: u - np.sin(2 * np.pi * u) / (2 * np.pi)      # noqa: E731
    grid = np.linspace(0.0, 360.0, 144001)[:-1]
    P = _centre_profile(grid, _s(grid, 0.03, (150.0, 20.0, 130.0, 60.0), _trapezoidal, cyc), e, R0, 1)
    rho = _signed_rho(P, np.radians(grid[1] - grid[0]))
    hollow = grid[rho < 0]
    assert len(hollow) and hollow.min() > 270.0 and hollow.max() < 285.0
    least = float(np.min(-rho[rho < 0]))
    [run] = doc["profile_concave"]
    assert run["from_deg"] == pytest.approx(hollow.min(), abs=0.05) and run["to_deg"] == pytest.approx(hollow.max(), abs=0.05)
    assert run["rho_min_m"] == pytest.approx(least, rel=2e-3)
    assert doc["curvature_min_m"] == pytest.approx(float(np.min(rho[rho > 0])), rel=1e-3)
    a, b = f"{hollow.min():.1f}", f"{hollow.max():.1f}"
    for lang, words in (("uk", ("ρ_{min} на опуклих ділянках = 26 мм", f"угнутий при φ = {a}…{b}°".replace(".", ","),
                                f"(|ρ| ≥ {least * 1000:.1f} мм)".replace(".", ","))),
                        ("en", ("ρ_{min} over the convex parts = 26 mm", f"concave at φ = {a}…{b}°",
                                f"(|ρ| ≥ {least * 1000:.1f} mm)"))):
        line = next(x for x in cam_lines(doc, lang) if "ρ_{min}" in x)
        assert all(w in line for w in words), (lang, line)
