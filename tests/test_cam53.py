"""Stop 53's cam (CAM53: a rocking roller follower, a cosine rise of 120° straight into a parabolic return
of 90° — no far dwell —, a counter-clockwise cam, R0 given 70 mm), against truth found apart from the code:

- the pressure angle at the divisions from a brute-force inversion (the roller centre's path in the cam's
  frame differentiated numerically, its normal against the velocity of C square to the arm O1C), and the
  smallest R0 as the bisection of that brute force against [ϑ] = 40°, 45°;
- the near dwell's ϑ from the triangle OO1C (a, l, R0) by the cosine rule;
- no far dwell lettered anywhere (a zero-width phase carries no dimension, no «0°»);
- a set's s diagram on a sheet of its own integrates from its own pole P2 (review 52, mark: its rays
  were drawn on the sheet before), every chord parallel to a ray of that drawing."""
from __future__ import annotations

import math
import tomllib

import numpy as np
import pytest

from graphplan.exact.cam import solve
from graphplan.graphic.cam import construct
from graphplan.model.cam import build
from review_scenes import CAM53

A, L = 0.15, 0.12


@pytest.fixture(scope="module")
def cam53():
    sol = solve(build(tomllib.loads(CAM53), "<cam53>"))
    return sol, construct(sol, measure=False, series="rad")


def _psi(phi: float) -> float:
    """The swing (rad) the scene asks: cosine rise 120°, parabolic return 90° at once, ψ_max 30°."""
    h, rise, ret = math.radians(30.0), math.radians(120.0), math.radians(90.0)
    if phi <= rise:
        return h * (1 - math.cos(math.pi * phi / rise)) / 2
    x = (phi - rise) / ret
    if x <= 1.0:
        return h * (1 - 2 * x * x) if x <= 0.5 else 2 * h * (1 - x) ** 2
    return 0.0


def _theta(R0: float, phi: float, dh: float = 1e-6) -> float:
    """|ϑ| (°) by inversion: O at 0, O1 at (a, 0), C above at β = ψ0 + ψ from O1O; the cam turning
    counter-clockwise, the follower's frame turned by −φ in the cam's."""
    b0 = math.acos((A * A + L * L - R0 * R0) / (2 * A * L))

    def centre(p: float) -> np.ndarray:
        b = b0 + _psi(p)
        c = np.array([A - L * math.cos(b), L * math.sin(b)])
        r = np.array([[math.cos(-p), -math.sin(-p)], [math.sin(-p), math.cos(-p)]])
        return r @ c
    t = (centre(phi + dh) - centre(phi - dh)) / (2 * dh)
    back = np.array([[math.cos(phi), -math.sin(phi)], [math.sin(phi), math.cos(phi)]])
    t = back @ t
    n = np.array([-t[1], t[0]])
    b = b0 + _psi(phi)
    v = np.array([L * math.sin(b), L * math.cos(b)])
    return math.degrees(math.acos(min(1.0, abs(n @ v) / np.linalg.norm(n) / np.linalg.norm(v))))


def test_the_pressure_angle_at_the_divisions_is_the_brute_forces(cam53):
    sol, _ = cam53
    phi = np.concatenate([np.arange(0.0, 120.0, 10.0), 120.0 + np.arange(0.0, 90.01, 7.5)])
    theta = sol.at(phi)["theta"]
    for p, t in zip(phi, theta):
        assert abs(float(t)) == pytest.approx(_theta(0.07, math.radians(float(p))), abs=0.02)
    # the worked numbers a teacher checks: 29.66° at division 7 of the rise, 35.49° at division 7 of the return
    assert _theta(0.07, math.radians(70.0)) == pytest.approx(29.66, abs=0.01)
    assert _theta(0.07, math.radians(172.5)) == pytest.approx(35.49, abs=0.01)


def test_the_near_dwells_pressure_angle_is_the_triangles(cam53):
    """ϑ = 90° − ∠OCO1, cos ∠OCO1 = (l² + R0² − a²) / (2 l R0): −10.98° at R0 = 70 mm."""
    sol, _ = cam53
    R0 = 0.07
    angle = math.degrees(math.acos((L * L + R0 * R0 - A * A) / (2 * L * R0)))
    assert float(sol.at(np.array([300.0]))["theta"][0]) == pytest.approx(90.0 - angle, abs=0.01)
    assert 90.0 - angle == pytest.approx(-10.98, abs=0.01)


def test_the_smallest_base_radius_is_the_brute_forces_bisection(cam53):
    sol, _ = cam53

    def ok(R0: float) -> bool:
        rise = max(_theta(R0, p) for p in np.linspace(0.0, math.radians(120.0), 121))
        ret = max(_theta(R0, p) for p in np.linspace(math.radians(120.0), math.radians(210.0), 91))
        return rise <= 40.0 and ret <= 45.0
    lo, hi = 0.04, 0.07
    for _ in range(18):
        mid = (lo + hi) / 2
        lo, hi = (lo, mid) if ok(mid) else (mid, hi)
    assert sol.R0_min == pytest.approx(hi, abs=2e-4)      # 55.67 mm (the grid of 1° costs ~0.1 mm)


def test_no_far_dwell_is_lettered(cam53):
    """A zero-width far dwell: no φ_вв / φ_far on the profile's phase arcs nor under ψ."""
    from graphplan.drawing.cam import diagrams, profile_drawing
    sol, g = cam53
    for lang, far in (("uk", "φ_вв"), ("en", "φ_{far}")):
        for rec in (profile_drawing(sol, g, lang), diagrams(sol, g, lang, ("s",))):
            texts = [q.text for q in rec.items if getattr(q, "text", None)]
            assert texts and not any(far in t for t in texts)
            assert not any(t.strip().endswith(" 0°") for t in texts)


def test_the_s_sheet_integrates_from_its_own_pole(cam53):
    """s drawn alone (a set's sheet after d²s/dφ² and ds/dφ): P2 at H2 left of the carried ordinates
    on s's φ axis, and every chord of s parallel (to 0.05°) to a ray from it on the same drawing."""
    from graphplan.drawing.cam import diagrams
    sol, g = cam53
    rec = diagrams(sol, g, "uk", ("s",))
    (pole,) = [q for q in rec.items if q.step == "pole P2"]
    P = complex(*pole.points[0])
    rays = [q for q in rec.items if q.step and q.step.startswith("ray P2")]
    ends = [complex(*q.points[1]) for q in rays]
    assert ends and all(e.real - P.real == pytest.approx(g.H2) for e in ends)
    slopes = [math.degrees(math.atan2((e - P).imag, (e - P).real)) for e in ends]
    chords = [q for q in rec.items if q.step and q.step.startswith("chord s")]
    assert chords
    for c in chords:
        (x0, y0), (x1, y1) = c.points
        angle = math.degrees(math.atan2(y1 - y0, x1 - x0))
        assert min(abs(angle - s) for s in slopes) < 0.05
    (axis,) = [q for q in rec.items if q.step == "axis s"]
    assert P.imag == pytest.approx(axis.points[0][1])


@pytest.mark.slow
@pytest.mark.parametrize("fmt,lang", [("A2", "uk"), ("A3", "en")])
def test_cam53s_sets_carry_the_pressure_angle(fmt, lang, tmp_path):
    """The lead's A2 and A3 sets of CAM53 (stop 53): ϑ(φ) stood on none of their sheets."""
    from graphplan.cli.main import main
    scene = tmp_path / "cam53.toml"
    scene.write_text(CAM53, encoding="utf-8")
    out = tmp_path / "cam.svg"
    assert main(["sheet", str(scene), "--sheet", "cam", "--format", fmt, "--lang", lang, "-o", str(out)]) in (0, None)
    caption = "Кут тиску ϑ(φ)" if lang == "uk" else "Pressure angle ϑ(φ)"
    sheets = sorted(tmp_path.glob("cam*.svg"))
    assert len(sheets) >= 2
    assert sum(caption in p.read_text(encoding="utf-8") for p in sheets) == 1


def test_omega_stands_clear_of_the_rays_of_a_cam_with_no_near_dwell():
    """OWN_CAM53 (a translating roller follower, e = 6.6 mm, R0 = 23 mm, no near dwell): the rays are
    lines tangent to the offset circle, and ω's arc about O must stand in a sector that none of them
    crosses at the arc's radius (it was placed by the profile points' angles and drawn over the rays)."""
    from graphplan.drawing.cam import profile_drawing
    from review_scenes import OWN_CAM53
    sol = solve(build(tomllib.loads(OWN_CAM53), "<own53>"))
    g = construct(sol, measure=False, series="rad")
    rec = profile_drawing(sol, g, "en")
    (arc,) = [q for q in rec.items if q.step == "ω" and q.kind == "arc"]
    c = complex(*arc.points[0])
    rr = float(arc.radius)
    assert abs(c) < 1e-9 and rr > 0.0
    a0, a1 = (float(a) for a in arc.angles)
    rays = [q for q in rec.items if q.step and q.step.startswith("ray ")]
    assert len(rays) >= 21
    for q in rays:
        p, r = (complex(*pt) for pt in q.points)
        z = p + np.linspace(0.0, 1.0, 4001) * (r - p)
        for w in z[np.abs(np.abs(z) - rr) < 0.05]:
            ang = (math.degrees(math.atan2(w.imag, w.real)) - a0) % 360.0
            assert not ang <= (a1 - a0) % 360.0, (q.step, ang, a0, a1)
