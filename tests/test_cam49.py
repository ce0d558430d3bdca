"""Stop 49's look at the cam sheet (the lead's CAM49: a translating knife-edge follower, the cam clockwise,
the offset chosen by the rule, a cosine rise of 100° straight into a parabolic return of 140° — no far
dwell —, 10 divisions; and cam49's own CAM_OWN49, a rocking roller follower with no far dwell). Each
checked against what the test works out itself — the laws' closed forms, the cam's geometry turned
about O by brute force — or read off the drawn primitives:

- one point of the cam, one number: with no far dwell the rise's end and the return's start are one
  point, numbered N once (the sheet printed "10; 11" on it, and Table 1 two identical rows);
- the cosine rise's soft shock at φ = 0 drawn up the ordinate axis in the curve's line;
- the offset's printed side and the printed largest pressure angles are those of the cam turned
  clockwise with its follower's axis on that side (a brute-force inversion, no formula of the code)."""
from __future__ import annotations

import math
import re

import numpy as np
import pytest

from graphplan.drawing.cam import diagrams, phase_diagram, profile_drawing
from graphplan.exact.cam import solve
from graphplan.graphic.cam import construct
from graphplan.model.cam import load
from graphplan.report.cam import cam_json, offset_line
from graphplan.sheets.cam import positions_table
from review_scenes import CAM49, CAM_OWN49

NUMBER = re.compile(r"^\d+(?:[;,] \d+)*$")


def _solved(tmp_path_factory, name: str, text: str):
    path = tmp_path_factory.mktemp("cam49") / f"{name}.toml"
    path.write_text(text, encoding="utf-8")
    sol = solve(load(path))
    return sol, construct(sol, measure=False, series="rad")


@pytest.fixture(scope="module")
def cam49(tmp_path_factory):
    # the offset the rule chooses for CAM49 (e = 5 mm, R0 = 27 mm on the sheet) given: the same cam
    # without the rule's search (10 s)
    return _solved(tmp_path_factory, "cam49", CAM49.replace('offset = "auto"', "offset = 0.005"))


@pytest.fixture(scope="module")
def own49(tmp_path_factory):
    return _solved(tmp_path_factory, "own49", CAM_OWN49)


def _numbers(rec) -> list[str]:
    return [q.text for q in rec.items if q.kind == "text" and NUMBER.match(q.text)]


@pytest.mark.parametrize("which", ["cam49", "own49"])
def test_one_point_one_number_on_the_drawings_and_in_table_1(which, request):
    """The rise's N divisions and the return's N (no far dwell) are 2N + 1 points of the cam, numbered
    0…2N: every drawing letters N alone (never "N; N+1"), the φ axes every number 0…2N, and Table 1
    one row a point, its φ k·φ_п/N up to N and φ_п + (k − N)·φ_с/N after (the laws' division turns)."""
    sol, g = request.getfixturevalue(which)
    n = sol.cam.divisions
    rise, far, ret, _ = sol.cam.phases
    assert far == 0.0
    dia, phase, prof = diagrams(sol, g, "uk"), phase_diagram(sol, g, "uk"), profile_drawing(sol, g, "uk")
    for rec in (dia, phase, prof):
        assert not any(t.startswith(f"{n}; ") or t.endswith(f"; {n + 1}") for t in _numbers(rec))
    axis = [t for t in _numbers(dia)]
    assert {int(x) for t in axis for x in re.split(r"; ", t)} == set(range(2 * n + 1))
    assert axis.count(str(n)) == 3                        # under s, ds/dφ and d²s/dφ²
    assert _numbers(phase).count(str(n)) == 1 and _numbers(prof).count(str(n)) == 1
    table = positions_table(cam_json(sol, g, ""), "uk")
    cells = [q for q in table.items if q.kind == "text"]
    # the body's first column: the numbers 0…2N once each, in order (x of the № column's cells)
    first = min(q.points[0][0] for q in cells if q.text == "0")
    numbers = [q.text for q in sorted(cells, key=lambda q: -q.points[0][1])
               if abs(q.points[0][0] - first) < 1e-6 and q.text.isdigit()]
    assert numbers == [str(k) for k in range(2 * n + 1)]
    turns = [k * rise / n if k <= n else rise + (k - n) * ret / n for k in range(2 * n + 1)]
    phis = sorted({round(p["phi_deg"], 9) for p in cam_json(sol, g, "")["positions"]})
    assert np.allclose(phis, turns)


def test_the_cosine_rise_starts_with_its_soft_shock_drawn_up_the_axis(cam49):
    """d²s/dφ² of the cosine rise is h·π²/(2Φ²)·cos(πφ/Φ): at φ = 0 it jumps from the near dwell's 0 to
    h·π²/(2Φ²); the curve's line starts on the axis and goes up the ordinate axis to that value (the
    curve began in the air at the axis's top)."""
    sol, g = cam49
    dia = diagrams(sol, g, "uk", ("a",))
    axis = next(q for q in dia.items if q.step == "axis a")
    curve = next(q for q in dia.items if q.step == "a(φ) exact")
    y0 = axis.points[0][1]
    (x_a, y_a), (x_b, y_b) = curve.points[0], curve.points[1]
    Phi = math.radians(sol.cam.phases[0])
    jump = sol.cam.stroke * math.pi ** 2 / (2 * Phi ** 2) / g.mu_a
    assert (x_a, y_a) == pytest.approx((0.0, y0), abs=1e-9)
    assert x_b == pytest.approx(0.0, abs=1e-9) and y_b - y0 == pytest.approx(jump, rel=1e-3)


def test_the_printed_offset_side_and_pressure_angles_are_the_clockwise_cams(cam49):
    """The cam turned clockwise about O by brute force — the knife-edge on the vertical line x = x_f at
    height s0 + s(φ), the profile its locus in the cam's frame, ϑ the angle between the profile's
    normal and the follower's axis — with the follower's axis where the notes put it (left of O:
    «ліворуч від O»): its rise's and return's largest |ϑ| are the printed maxima; on the other side they
    are not (there the rise's exceeds [ϑ] = 28°)."""
    sol, _ = cam49
    cam = sol.cam
    doc = {"offset_m": sol.geometry.e, "sense": "cw"}
    from graphplan.report.cam import WORDS
    line = offset_line(WORDS["uk"], doc, lambda v: f"{v:g}")
    e, R0, h = abs(sol.geometry.e), sol.geometry.R0, cam.stroke
    x_f = -e if "ліворуч" in line else e
    rise, ret = math.radians(100.0), math.radians(140.0)
    phi = np.linspace(0.0, rise + ret, 48001)
    u, w = phi / rise, (phi - rise) / ret
    s = np.where(phi <= rise, h / 2 * (1 - np.cos(np.pi * u)),
                 np.where(w <= 0.5, h - 2 * h * w ** 2, 2 * h * (1 - w) ** 2))
    s0 = math.sqrt(R0 ** 2 - e ** 2)

    def largest(x: float) -> tuple[float, float]:
        c, sn = np.cos(phi), np.sin(phi)             # clockwise cam: its frame turned back by +φ
        P = np.stack([c * x - sn * (s0 + s), sn * x + c * (s0 + s)])
        t = np.gradient(P, phi, axis=1)
        t /= np.linalg.norm(t, axis=0)
        axis = np.stack([-sn, c])                    # the follower's axis in the cam's frame
        theta = np.degrees(np.arcsin(np.clip(np.abs(t[0] * axis[0] + t[1] * axis[1]), 0.0, 1.0)))
        return float(theta[phi <= rise].max()), float(theta[phi > rise].max())
    printed = sol.pressure_maxima()
    assert largest(x_f) == pytest.approx((abs(printed[0]), abs(printed[1])), abs=0.05)
    assert largest(-x_f)[0] > cam.allowed[0]


def test_the_own_rocking_cams_printed_angles_and_curvature_by_brute_force(own49):
    """CAM_OWN49 (rocking roller follower, cw, cycloidal rise 90° into a trapezoidal return 120°, the
    trapezoid's ramps an eighth of the phase each) turned clockwise by brute force: the pivot O₁ at
    (a, 0), the arm at ψ0 + ψ from O₁O under the line O–O1 (a clockwise cam's layout: the counter-clockwise
    one mirrored, stop 60) (ψ0 from the triangle OO₁C: a, l, R0 — the cosine rule), the
    roller's centre's locus in the cam's frame; ϑ between its normal and C's velocity (square to
    the arm); ρ its radius of curvature where convex. The printed ψ0, largest angles and ρ_min."""
    sol, _ = own49
    a, l, R0 = sol.cam.centre_distance, sol.cam.arm, sol.geometry.R0
    Psi, rise, ret = math.radians(18.0), math.radians(90.0), math.radians(120.0)
    phi = np.linspace(0.0, 2 * math.pi, 36001)
    x = np.linspace(0.0, 1.0, 4001)            # the trapezoid's d²/du² (ramps 1/8) integrated twice
    acc = np.interp(x, [0, 1 / 8, 3 / 8, 5 / 8, 7 / 8, 1], [0, 1, 1, -1, -1, 0])
    v = np.concatenate([[0.0], np.cumsum((acc[1:] + acc[:-1]) / 2 * np.diff(x))])
    s = np.concatenate([[0.0], np.cumsum((v[1:] + v[:-1]) / 2 * np.diff(x))])
    u, w = np.clip(phi / rise, 0, 1), np.clip((phi - rise) / ret, 0, 1)
    psi = np.where(phi <= rise, Psi * (u - np.sin(2 * math.pi * u) / (2 * math.pi)),
                   np.where(phi <= rise + ret, Psi * (1 - np.interp(w, x, s / s[-1])), 0.0))
    psi0 = math.acos((a * a + l * l - R0 * R0) / (2 * a * l))
    ang = math.pi - (psi0 + psi)
    c, sn = np.cos(phi), np.sin(phi)
    C = np.stack([a + l * np.cos(ang), -l * np.sin(ang)])
    P = np.stack([c * C[0] - sn * C[1], sn * C[0] + c * C[1]])
    t = np.gradient(P, phi, axis=1)
    vel = np.stack([-np.sin(ang), -np.cos(ang)])
    velc = np.stack([c * vel[0] - sn * vel[1], sn * vel[0] + c * vel[1]])
    theta = np.degrees(np.arcsin(np.clip(np.abs((t / np.linalg.norm(t, axis=0) * velc).sum(axis=0)), 0, 1)))
    dd = np.gradient(t, phi, axis=1)
    rho = np.linalg.norm(t, axis=0) ** 3 / (t[0] * dd[1] - t[1] * dd[0])
    up, down = phi <= rise, (phi > rise) & (phi <= rise + ret)
    assert sol.geometry.psi0 == pytest.approx(psi0, abs=1e-9)
    assert (theta[up].max(), theta[down].max()) == pytest.approx(tuple(abs(x) for x in sol.pressure_maxima()), abs=0.05)
    assert float(rho[rho > 0].min()) == pytest.approx(sol.curvature_min(), rel=2e-3)


def test_the_parabolic_returns_jumps_are_drawn_upright(cam49):
    """The parabolic return's d²s/dφ² is −4h/Φ² over its first half and +4h/Φ² over its second: at its
    middle (170°) the curve's line goes straight up by 8h/Φ² (drawn at μ_a), and at the rise's end
    (100°) it steps from the cosine's −hπ²/(2Φ_п²) to −4h/Φ_с², each at one abscissa (it leant over the
    grid's step)."""
    sol, g = cam49
    dia = diagrams(sol, g, "uk", ("a",))
    pts = np.asarray(next(q for q in dia.items if q.step == "a(φ) exact").points)
    h, rise, ret = sol.cam.stroke, math.radians(100.0), math.radians(140.0)
    for at, jump in ((rise + ret / 2, 8 * h / ret ** 2),
                     (rise, -4 * h / ret ** 2 + h * math.pi ** 2 / (2 * rise ** 2))):
        x = at / g.mu_phi
        near = np.flatnonzero(np.abs(pts[:, 0] - x) < 1e-4)         # the points at that abscissa
        assert len(near) >= 2
        assert pts[near[-1], 1] - pts[near[0], 1] == pytest.approx(jump / g.mu_a, rel=1e-3)


@pytest.mark.slow
def test_the_own_cams_a2_set_draws_its_diagrams_across_the_sheet(tmp_path):
    """CAM_OWN49 on A2: the three diagrams drew 210° at 1 °/mm over 268 of the 564 mm field (s grown
    first to the sheet's height), a third of sheet 1 blank beside them; at the next standard μ_φ
    (0,01 рад/мм), their ordinates shortened to fit, they span at least 70 % of the field's width."""
    from graphplan.sheets.cam import build_cam_sheet
    from graphplan.sheets.compose import SheetOptions, defects, field_of
    from graphplan.sheets.form import form
    path = tmp_path / "own49.toml"
    path.write_text(CAM_OWN49, encoding="utf-8")
    f = form("A2")
    sheet = build_cam_sheet(load(path), f, SheetOptions(lang="uk", sheet="cam"))
    assert defects(sheet) == []
    first = {p.name: p for p in sheet.pages[0].placed}
    b = first["diagrams"].record.bounds()
    x0, _, x1, _ = field_of(f)
    assert b[2] - b[0] >= 0.7 * (x1 - x0)
    assert first["diagrams"].record.scales["mu_phi"] == pytest.approx(0.01)
