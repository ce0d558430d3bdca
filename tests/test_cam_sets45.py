"""Review 13 #7: the rocking cam's A3 set drew d²ψ/dφ², dψ/dφ and ψ on one sheet — ψ 60 mm tall, the
rise's dψ/dφ 12.5 mm (the A1 sheet's: 52 mm) with H2 = 15 mm —, and its Table 1 starred errors the A1
sheet has not. Where the three on one sheet draw s or a phase's ds/dφ under LEGIBLE_MM, a set draws
d²s/dφ² and ds/dφ on one sheet and s on the next (sheets.cam.set_sizes). The drawings' ordinates are
measured off the drawn records and compared with the laws' closed forms written here."""
from __future__ import annotations

import math
import tomllib

import numpy as np
import pytest

from graphplan.model.cam import build
from test_cam_review13 import ROCKING_REV13

SWING, RISE, FAR, RETURN = 24.0, 150.0, 30.0, 75.0          # review 13's cam, degrees


def _trapezoidal(u: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """f(u), f'(u) of the trapezoidal acceleration law (a ramps 0 → A over the first eighth, holds to
    3/8, falls to −A by 5/8, holds to 7/8, ramps back to 0), integrated numerically on a fine grid,
    A from f(1) = 1 — independent of graphplan.exact's piecewise cubics."""
    x = np.linspace(0.0, 1.0, 80001)
    a = np.interp(x, [0, 1 / 8, 3 / 8, 5 / 8, 7 / 8, 1], [0, 1, 1, -1, -1, 0])
    dx = x[1] - x[0]
    v = np.concatenate([[0.0], np.cumsum((a[1:] + a[:-1]) / 2 * dx)])
    f = np.concatenate([[0.0], np.cumsum((v[1:] + v[:-1]) / 2 * dx)])
    return np.interp(u, x, f / f[-1]), np.interp(u, x, v / f[-1])


def _exact(phi: np.ndarray, phase: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """ψ (°) and dψ/dφ (°/rad) at the division turns: the trapezoidal rise over 150°, the parabolic
    return over 75° (ψ = ψmax·(1 − 2u²) to u = ½, 2ψmax·(1 − u)² after it)."""
    psi, dpsi = np.zeros_like(phi), np.zeros_like(phi)
    up = phase == 0
    f, df = _trapezoidal(phi[up] / RISE)
    psi[up], dpsi[up] = SWING * f, SWING * df / math.radians(RISE)
    u = (phi[~up] - RISE - FAR) / RETURN
    first = u <= 0.5
    psi[~up] = SWING * np.where(first, 1 - 2 * u * u, 2 * (1 - u) ** 2)
    dpsi[~up] = -SWING * np.where(first, 4 * u, 4 * (1 - u)) / math.radians(RETURN)
    return psi, dpsi


def _ordinates(rec, key: str) -> np.ndarray:
    """The drawn ordinates of ``key`` (s or v) at the divisions, mm, read off the record's segments."""
    segs = sorted((int(q.step.split()[-1]), q.points[1][1] - q.points[0][1]) for q in rec.items
                  if q.kind == "segment" and q.step.startswith(f"{key} at "))
    return np.array([y for _, y in segs])


@pytest.fixture(scope="module")
def split_a3():
    """Review 13's cam at the sizes its A3 set takes apart (set_sizes: (2.8, 0.9, 2.8, 1.1), H1 = 30 mm,
    H2 = 16 mm; the slow test below builds the set itself)."""
    from graphplan.drawing.cam import diagrams
    from graphplan.exact.cam import solve
    from graphplan.graphic.cam import construct
    sol = solve(build(tomllib.loads(ROCKING_REV13), "<rev13>"))
    g = construct(sol, None, 0.5, size=2.8, profile_size=0.9, height=2.8, accel=1.1, H1=30, H2=16, measure=False,
                  series=True)
    return sol, g, diagrams(sol, g, "en", ("a", "v")), diagrams(sol, g, "en", ("s",))


def test_the_two_sheets_drawings_hold_the_three_diagrams_apart(split_a3):
    """d²ψ/dφ² and dψ/dφ in one record, ψ in the other: each diagram's axis in exactly one, the
    divisions numbered under ψ and on both other axes, the scales of the three in both."""
    _, g, av, s = split_a3
    steps = lambda rec: {q.step for q in rec.items}                     # noqa: E731
    assert {"axis a", "axis v"} <= steps(av) and "axis s" not in steps(av)
    assert "axis s" in steps(s) and not {"axis a", "axis v"} & steps(s)
    n = len(g.phi)
    assert len(_ordinates(s, "s")) == n and len(_ordinates(av, "v")) == n
    assert not any(q.step.startswith(("chord v", "pole P1", "ray P1")) for q in s.items)
    assert "pole P2" in steps(s)         # s integrated from its own sheet's P2 (stop 53: restored with ϑ(φ) kept)
    for rec in (av, s):
        assert rec.scales["mu_phi"] == pytest.approx(math.radians(1.0))


def test_the_split_diagrams_are_legible_and_read_the_closed_forms(split_a3):
    """ψ's stroke and each phase's tallest dψ/dφ at least LEGIBLE_MM (25 mm: on one A3 sheet the rise's
    was 12.5 mm), and the drawn ordinates agree with the closed forms: ψ within the closing bound the
    sheet states (2 % of the stroke drawn), dψ/dφ within one ruler division (0.5 mm)."""
    from graphplan.sheets.cam import LEGIBLE_MM
    _, g, av, s = split_a3
    ys, yv = _ordinates(s, "s"), _ordinates(av, "v")
    mu_psi = math.degrees(s.scales["mu_s"])                  # °/mm
    mu_v = math.degrees(av.scales["mu_v"])                   # (°/rad)/mm
    assert mu_psi == pytest.approx(0.2)
    psi, dpsi = _exact(g.phi, g.phase)
    assert np.max(np.abs(ys)) >= LEGIBLE_MM
    assert min(np.max(np.abs(yv[g.phase == ph])) for ph in (0, 1)) >= LEGIBLE_MM
    assert np.max(np.abs(ys - psi / mu_psi)) <= 0.02 * SWING / mu_psi
    assert np.max(np.abs(yv - dpsi / mu_v)) <= 0.5


@pytest.mark.slow
def test_review_13s_a3_set_draws_psi_on_its_own_sheet_with_theta_under_it():
    """The A3 set: sheet 1 d²ψ/dφ² and dψ/dφ, sheet 2 ψ with ϑ(φ) under it at the same μ_φ (each
    division's ϑ straight under its ψ), the phase diagram and the profile, Table 1; R0 read within 2 %
    (the three on one sheet: 50 mm, +3.1 %)."""
    from graphplan.exact.cam import solve
    from graphplan.sheets.cam import build_cam_sheet, construct_on
    from graphplan.sheets.compose import SheetOptions, defects
    from graphplan.sheets.form import form
    cam = build(tomllib.loads(ROCKING_REV13), "<rev13>")
    sheet = build_cam_sheet(cam, form("A3"), SheetOptions(lang="en", sheet="cam"))
    assert defects(sheet) == []
    pages = [{p.name: p.record for p in page.placed} for page in sheet.pages]
    assert "diagrams" in pages[0] and {"displacement", "pressure"} <= set(pages[1])
    assert pages[1]["pressure"].scales["mu_phi"] == pages[1]["displacement"].scales["mu_phi"]
    b = pages[1]["pressure"].bounds()      # legible: stop 53 drew it 16 mm tall (4 °/mm) on sheet 4
    assert b[3] - b[1] >= 60.0
    x0 = lambda rec, step: next(q for q in rec.items if q.step == step and q.kind == "segment").points[0][0]  # noqa: E731
    for k in (0, 5, 15):
        assert x0(pages[1]["displacement"], f"s at {k}") == pytest.approx(x0(pages[1]["pressure"], f"ϑ at {k}"), abs=1e-6)
    sol = solve(cam)
    g = construct_on(sol, form("A3"))
    assert g.split
    assert abs(g.R0_min - sol.R0_min) / sol.R0_min < 0.02


KNIFE_S44 = '''
[cam]
follower = "translating"
stroke = 0.03
offset = -0.006
roller_radius = 0
phases_deg = { rise = 130, dwell_far = 40, return = 110, dwell_near = 80 }
laws = { rise = "trapezoidal", return = "cycloidal" }
pressure_angle_deg = { rise = 30, return = 40 }
omega = 15
direction = "cw"
'''


@pytest.mark.slow
def test_a_knife_cams_a2_set_keeps_its_phase_diagram_with_the_profile():
    """Stop 44's knife-edge cam on A2: the phase diagram (at μ_s) and the 2:1 profile were judged to
    share a sheet under the first sheet's title block, never did, and the phase diagram took sheet 2
    alone (78 % of its cells blank, four sheets): they share a later sheet, s as tall as lets them."""
    from graphplan.sheets.cam import build_cam_sheet
    from graphplan.sheets.compose import SheetOptions, defects
    from graphplan.sheets.form import form
    sheet = build_cam_sheet(build(tomllib.loads(KNIFE_S44), "<s44>"), form("A2"), SheetOptions(lang="uk", sheet="cam"))
    assert defects(sheet) == []
    names = [{p.name for p in page.placed} for page in sheet.pages]
    assert len(names) == 3 and {"phase", "profile"} <= names[1] and "table" in names[2]


def test_a_cam_too_large_for_a4_is_one_line_and_exit_2(tmp_path, capsys):
    """Review 13's cam on A4 (its profile larger than an A4 field even at half size): one clear line
    on stderr and exit 2, no file — it was an internal TypeError (the set's ϑ(φ) pass counted the
    sheets of a layout that did not exist)."""
    from graphplan.cli.main import main
    scene = tmp_path / "b.toml"
    scene.write_text(ROCKING_REV13, encoding="utf-8")
    out = tmp_path / "x.svg"
    assert main(["sheet", str(scene), "--sheet", "cam", "--format", "A4", "-o", str(out)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "A4" in err[0] and "internal" not in err[0]
    assert not list(tmp_path.glob("x*.svg"))
