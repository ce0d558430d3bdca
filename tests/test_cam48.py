"""Stop 48's look at the cam sheet (the lead's rocking knife-edge cam CAM48: cycloidal rise 120°, cosine
return 90°, 8 divisions). Each checked against what the test works out itself — the laws' closed forms,
quadrature of the drawn curve, the triangle OO₁C — or measured off the drawn primitives:

- the ψ diagram integrated with the steps of equal area of the drawn dψ/dφ curve (the lab's correction
  for chords), not the chord's middle (the trapezoid rule put ψ 48 % over at division 1 — 0.63 mm on a
  1.37 mm ordinate, more than the ruler's reading — and 10 % at division 2);
- the profile shows the swing ψ_max: the arm in its top position, the knife-edge's arc about O₁, the
  angle dimensioned;
- the near dwell's note names the knife-edge's point, not a roller's centre;
- the d²ψ/dφ² curve of a law with a soft shock at the return's end drawn down to the axis there."""
from __future__ import annotations

import cmath
import math

import numpy as np
import pytest

from graphplan.drawing.cam import diagrams, profile_drawing
from graphplan.exact.cam import solve
from graphplan.graphic.cam import construct
from graphplan.model.cam import load
from review_scenes import CAM48, CAM_ROCKING_CW47


@pytest.fixture(scope="module")
def cam48(tmp_path_factory):
    path = tmp_path_factory.mktemp("cam48") / "cam48.toml"
    path.write_text(CAM48, encoding="utf-8")
    sol = solve(load(path))
    return sol, construct(sol, measure=False, series="rad")


@pytest.fixture(scope="module")
def cw47(tmp_path_factory):
    path = tmp_path_factory.mktemp("cam48") / "cw47.toml"
    path.write_text(CAM_ROCKING_CW47, encoding="utf-8")
    sol = solve(load(path))
    return sol, construct(sol, measure=False, series="rad")


def _psi(phi_deg: np.ndarray) -> np.ndarray:
    """ψ of CAM48 written out here (rad): cycloidal rise Ψ(u − sin 2πu/2π) over 120°, far dwell to 150°,
    cosine return Ψ(1 + cos πw)/2 over 90°."""
    Psi = math.radians(22.0)
    d = np.asarray(phi_deg, dtype=float)
    u = np.clip(d / 120.0, 0.0, 1.0)
    w = np.clip((d - 150.0) / 90.0, 0.0, 1.0)
    return np.where(d <= 120.0, Psi * (u - np.sin(2 * math.pi * u) / (2 * math.pi)),
                    np.where(d <= 150.0, Psi, Psi * (1 + np.cos(math.pi * w)) / 2))


def test_psi_at_every_division_within_the_rulers_reading_of_the_closed_form(cam48):
    """Each ψ ordinate within the ruler's division (0.5 mm) and the closing laid back of the closed
    form's — division 1's too (1.37 mm drawn 2.0 mm with the chords' middles: 0.63 mm over)."""
    sol, g = cam48
    exact = _psi(g.phi) / g.mu_s
    laid = max(abs(c) for c in g.closing)
    assert np.max(np.abs(g.s_mm - exact)) <= g.precision + laid + 1e-9
    assert abs(g.s_mm[1] - exact[1]) <= g.precision / 2 + laid + 1e-9


def test_with_an_exact_ruler_psi_is_exact_at_the_divisions(cam48):
    """Steps of equal area integrate exactly: with an exact ruler ψ at every division is the closed
    form's (the trapezoid rule's error fell only as 1/n²: 48 % at division 1 of 8)."""
    sol, _ = cam48
    g = construct(sol, 8, 0.0, measure=False)
    assert np.max(np.abs(g.s - _psi(g.phi))) < 1e-12


@pytest.mark.parametrize("which", ["cam48", "cw47"])
def test_the_psi_steps_are_drawn_with_the_dpsi_curves_area(which, cam48, cw47):
    """On the drawn dψ/dφ diagram each step (the level the ray to P2 starts from) has the area of the
    drawn dψ/dφ curve over its interval, within the ruler's half division and the vertices' readings —
    the chord's middle missed it by the curvilinear triangles' difference."""
    sol, g = {"cam48": cam48, "cw47": cw47}[which]
    rec = diagrams(sol, g, "uk")
    by = {q.step: q for q in rec.items}
    y0 = by["axis v"].points[0][1]
    curve = np.asarray(by["v(φ) exact"].points)
    x = np.radians(g.phi) / g.mu_phi
    ends = [(x[p], x[p + 1]) for p in range(len(x) - 1) if g.phase[p] == g.phase[p + 1]]
    worst = 0.0
    for j, (xa, xb) in enumerate(ends):
        xs = np.linspace(xa, xb, 801)
        area = float(np.trapezoid(np.interp(xs, curve[:, 0], curve[:, 1]) - y0, xs)) / (xb - xa)
        level = by[f"ray P2 {j}"].points[1][1] - y0
        worst = max(worst, abs(level - area))
    assert worst <= g.precision / 2 + g.precision / 2 + 1e-6


def _primitives(rec, step: str):
    return [q for q in rec.items if q.step == step]


@pytest.mark.parametrize("which", ["cam48", "cw47"])
def test_the_profile_shows_the_swing(which, cam48, cw47):
    """The arm in its top position: from O₁ at the arm's length, turned ψ_max from the start's arm
    (measured at the drawn O₁), its end at the far dwell's radius of the triangle OO₁C,
    √(a² + l² − 2al·cos(ψ0 + ψ_max)) with cos ψ0 = (a² + l² − R0²)/(2al); the knife-edge's (roller
    centre's) path an arc of radius l about O₁ over the swing; ψ_max dimensioned by an arc about O₁
    spanning the swing and lettered."""
    sol, g = {"cam48": cam48, "cw47": cw47}[which]
    cam = sol.cam
    rec = profile_drawing(sol, g, "uk")
    mu = g.mu_l
    a, l, R0, Psi = cam.centre_distance / mu, cam.arm / mu, sol.geometry.R0 / mu, cam.stroke
    A = complex(*_primitives(rec, "pivot")[0].points[0])
    assert A == pytest.approx(complex(a, 0.0))
    start = complex(*_primitives(rec, "arm")[0].points[1])
    top_arm = _primitives(rec, "swing top arm")[0]
    top = complex(*top_arm.points[1])
    r = cam.roller / mu
    assert abs(start - A) + r == pytest.approx(l, abs=1e-6)
    assert abs(top - A) + r == pytest.approx(l, abs=1e-6)
    turned = abs(cmath.phase((top - A) / (start - A)))
    assert math.degrees(turned) == pytest.approx(math.degrees(Psi), abs=1e-6)
    psi0 = math.acos((a * a + l * l - R0 * R0) / (2 * a * l))
    far = math.sqrt(a * a + l * l - 2 * a * l * math.cos(psi0 + Psi))
    tip = A + (top - A) * l / abs(top - A)
    assert abs(tip) == pytest.approx(far, rel=1e-6)
    assert top_arm.role == "projection"                  # dashed
    path = _primitives(rec, "swing path")[0]
    assert path.radius == pytest.approx(l) and complex(*path.points[0]) == pytest.approx(A)
    lo, hi = path.angles
    assert hi - lo >= math.degrees(Psi)
    dim = [q for q in _primitives(rec, "swing psi_max") if q.kind == "arc"][0]
    assert complex(*dim.points[0]) == pytest.approx(A)
    assert dim.angles[1] - dim.angles[0] == pytest.approx(math.degrees(Psi))
    texts = [q.text for q in rec.items if q.kind == "text"]
    assert any(t.startswith("ψ_max = ") and t.endswith(f"{math.degrees(Psi):g}°".replace(".", ",")) for t in texts)


def test_the_near_dwells_note_names_the_knife_edge(cam48, cw47):
    """A knife-edge follower's near-dwell note speaks of its point, a roller follower's of its centre."""
    from graphplan.report.cam import cam_json
    from graphplan.sheets.cam import notes
    for (sol, g), word_uk, word_en in ((cam48, "вістря C", "knife-edge's point C"),
                                       (cw47, "центр ролика C", "roller centre C")):
        doc = cam_json(sol, g, "")
        uk = " ".join(notes(doc, "uk", sol.cam))
        en = " ".join(notes(doc, "en", sol.cam))
        assert word_uk in uk and word_en in en
        assert ("центр ролика" in uk) == (sol.cam.roller > 0)


def test_the_return_ends_its_soft_shock_on_the_axis(cam48):
    """The cosine return's d²ψ/dφ² at its end is −Ψπ²/(2Φ²)·cos π ≠ 0 (a jump to the near dwell's 0):
    the drawn curve comes down to the axis there, at the working angle's end."""
    sol, g = cam48
    rec = diagrams(sol, g, "uk")
    by = {q.step: q for q in rec.items}
    y0 = by["axis a"].points[0][1]
    curve = np.asarray(by["a(φ) exact"].points)
    Phi = math.radians(90.0)
    jump = math.radians(22.0) * math.pi ** 2 / (2 * Phi ** 2) / g.mu_a      # mm
    end = math.radians(240.0) / g.mu_phi
    assert curve[-1] == pytest.approx((end, y0), abs=1e-6)
    assert curve[-2][1] - y0 == pytest.approx(jump, rel=0.01)


# -- cam48's own cam: a translating roller follower, ccw, a given negative offset, parabolic / cosine --------

def _own_motion(d: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """s and ds/dφ (m, m/rad) of CAM_OWN48 written out here: h = 25 mm, a parabolic rise over 90°
    (2hu² to u = ½, then h − 2h(1 − u)²), far dwell to 150°, a cosine return over 150°."""
    h = 0.025
    s, v = np.zeros_like(d), np.zeros_like(d)
    rise, ret = math.radians(90.0), math.radians(150.0)
    r = d <= 90.0
    u = d[r] / 90.0
    s[r] = np.where(u <= 0.5, 2 * h * u ** 2, h - 2 * h * (1 - u) ** 2)
    v[r] = np.where(u <= 0.5, 4 * h * u / rise, 4 * h * (1 - u) / rise)
    s[(d > 90.0) & (d <= 150.0)] = h
    t = (d > 150.0) & (d <= 300.0)
    w = (d[t] - 150.0) / 150.0
    s[t] = h * (1 + np.cos(math.pi * w)) / 2
    v[t] = -h * math.pi / (2 * ret) * np.sin(math.pi * w)
    return s, v


def test_the_own_cams_smallest_base_radius_and_pressure_angles_are_the_closed_forms(tmp_path):
    """CAM_OWN48 (e = −8 mm raising the rise's pressure angle): the smallest R0 is the root of
    max|ϑ| = [ϑ] with tg ϑ = (ds/dφ − e)/(s0 + s), s0 = √(R0² − e²), worked out here on a 0.01° grid
    and brentq (57.053 mm: the rise binds at its middle, 29.66° at the R0 = 58 mm taken); the return's
    largest |ϑ| at the phase's ends, atan(8/s0) = 7.93°."""
    from scipy.optimize import brentq

    from review_scenes import CAM_OWN48
    path = tmp_path / "own.toml"
    path.write_text(CAM_OWN48, encoding="utf-8")
    sol = solve(load(path))
    e = -0.008
    d = np.linspace(0.0, 360.0, 36001)
    s, v = _own_motion(d)

    def theta(R0: float) -> np.ndarray:
        return np.degrees(np.arctan((v - e) / (math.sqrt(R0 ** 2 - e ** 2) + s)))
    rise, ret = d <= 90.0, (d >= 150.0) & (d <= 300.0)
    R0 = brentq(lambda R: max(np.max(np.abs(theta(R)[rise])), np.max(np.abs(theta(R)[ret]))) - 30.0, 0.03, 0.1)
    assert sol.R0_min == pytest.approx(R0, abs=2e-6)
    assert sol.geometry.R0 == pytest.approx(0.058)
    g = construct(sol, measure=False)
    from graphplan.report.cam import cam_json
    doc = cam_json(sol, g, "")
    th = theta(0.058)
    assert doc["pressure_angle_max_deg"]["rise"] == pytest.approx(np.max(np.abs(th[rise])), abs=0.01)
    assert doc["pressure_angle_max_deg"]["return"] == pytest.approx(np.max(np.abs(th[ret])), abs=0.01)
    assert doc["pressure_angle_max_deg"]["return"] == pytest.approx(math.degrees(math.atan(0.008 / math.sqrt(0.058 ** 2 - e ** 2))), abs=0.01)
