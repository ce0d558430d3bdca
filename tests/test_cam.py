"""The cam mechanism (issue 27): the laws against their closed forms written here, the smallest base
radius against the allowed pressure angle, the profile's geometry, the graphical construction's
convergence, the command's JSON and its refusals."""
from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

from conftest import ROOT, cli
from fuzz_scenes import check_run, run
from graphplan.exact import cam as X
from graphplan.graphic.cam import construct
from graphplan.model.cam import load

TRANSLATING = ROOT / "examples" / "cam_translating.toml"
ROCKING = ROOT / "examples" / "cam_rocking.toml"
U = np.linspace(0.0, 1.0, 1001)


# -- the laws -------------------------------------------------------------------------------------------

@pytest.mark.parametrize("name, f, f1, f2", [
    ("parabolic", lambda u: np.where(u <= 0.5, 2 * u ** 2, 1 - 2 * (1 - u) ** 2),
     lambda u: np.where(u <= 0.5, 4 * u, 4 - 4 * u), lambda u: np.where(u <= 0.5, 4.0, -4.0)),
    ("cosine", lambda u: 0.5 - 0.5 * np.cos(math.pi * u), lambda u: 0.5 * math.pi * np.sin(math.pi * u),
     lambda u: 0.5 * math.pi ** 2 * np.cos(math.pi * u)),
    ("cycloidal", lambda u: u - np.sin(2 * math.pi * u) / (2 * math.pi), lambda u: 1 - np.cos(2 * math.pi * u),
     lambda u: 2 * math.pi * np.sin(2 * math.pi * u)),
    ("linear", lambda u: u, lambda u: np.ones_like(u), lambda u: np.zeros_like(u)),
])
def test_each_law_is_its_closed_form(name, f, f1, f2):
    got = X.law(name, U)
    for g, want in zip(got, (f(U), f1(U), f2(U))):
        assert np.max(np.abs(g - want)) < 1e-12


def test_the_trapezoidal_law_integrates_its_acceleration():
    """The trapezoidal law's f″ is the trapezoid (ramps over the first and last eighths and the middle
    quarter); f′ and f are its integrals from 0 (checked by quadrature to 1e-12), f(1) = 1, f′(1) = 0,
    and the peak A = 16/3: the velocity it gives peaks at 3A/8 in the middle and encloses 3A/16."""
    from scipy.integrate import quad
    f, f1, f2 = X.law("trapezoidal", U)
    assert f[-1] == pytest.approx(1.0, abs=1e-12) and abs(f1[-1]) < 1e-12
    assert np.max(f2) == pytest.approx(16 / 3, abs=1e-12)
    acc = lambda u: float(X.law("trapezoidal", np.array([u]))[2][0])           # noqa: E731
    vel = lambda u: float(X.law("trapezoidal", np.array([u]))[1][0])           # noqa: E731
    for u in (0.1, 0.3, 0.5, 0.77, 0.95):
        pts = [p for p in (0.125, 0.375, 0.625, 0.875) if p < u]
        assert vel(u) == pytest.approx(quad(acc, 0, u, points=pts, epsabs=1e-14)[0], abs=1e-12)
        assert float(X.law("trapezoidal", np.array([u]))[0][0]) == pytest.approx(
            quad(vel, 0, u, points=pts, epsabs=1e-14)[0], abs=1e-12)


def test_the_motion_over_the_turn_follows_the_phases():
    cam = load(TRANSLATING)
    rise, far, ret, _ = cam.phases
    h = cam.stroke
    phi = np.array([0.0, rise / 2, rise, rise + far / 2, rise + far + ret / 2, 359.0])
    s, v, a = X.motion(cam, phi)
    R = math.radians(rise)
    assert s[1] == pytest.approx(h / 2, abs=1e-15) and v[1] == pytest.approx(h * math.pi / 2 / R, rel=1e-12)
    assert s[2] == pytest.approx(h) and s[3] == h and s[5] == 0 and v[3] == 0 and a[5] == 0
    # the return is parabolic: at its middle s = h/2 and |ds/dφ| = 2h/Φ_return
    assert s[4] == pytest.approx(h / 2, abs=1e-15) and v[4] == pytest.approx(-2 * h / math.radians(ret), rel=1e-12)


# -- the exact geometry ----------------------------------------------------------------------------------

def largest_angles(cam, sol_geometry):
    phi = np.concatenate([np.linspace(0, cam.phases[0], 20001),
                          cam.phases[0] + cam.phases[1] + np.linspace(0, cam.phases[2], 20001)])
    th = np.abs(X.profile(cam, sol_geometry, phi)["theta"])
    ph = X.phase_of(cam, phi)
    return [float(np.max(th[ph == k])) for k in (0, 1)]


@pytest.mark.parametrize("path", [TRANSLATING, ROCKING])
def test_the_smallest_base_radius_makes_the_largest_pressure_angle_the_allowed_one(path):
    cam = load(path)
    r = X.min_base_radius(cam)
    worst = X._refined_worst(cam, r, cam.offset)
    assert worst == pytest.approx(1.0, abs=1e-9 / 90)               # 1e-9° of a [ϑ] ≤ 90°
    ratios = [a / b for a, b in zip(largest_angles(cam, X.geometry(cam, r)), cam.allowed)]
    assert max(ratios) == pytest.approx(1.0, abs=1e-6)              # a fine grid agrees
    assert X._refined_worst(cam, r * 0.999, cam.offset) > 1         # a smaller R0 is not allowed


@pytest.mark.parametrize("sense", [1, -1])
def test_the_translating_followers_profile_and_pressure_angle_in_closed_form(sense):
    """Centre profile points at √((s0+s)² + e²) from the cam's centre, the pressure angle
    tg ϑ = (ds/dφ − e)/(s0 + s) for either sense, the profile turned against ω: P(φ)·e^{iσφ} is the
    roller centre."""
    from dataclasses import replace
    cam = replace(load(TRANSLATING), sense=sense)
    sol = X.solve(cam)
    g = sol.geometry
    phi = np.linspace(0, 360, 3601)
    s, v, _ = X.motion(cam, phi)
    p = sol.at(phi)
    s0 = math.sqrt(g.R0 ** 2 - g.e ** 2)
    assert np.max(np.abs(p["radius"] - np.sqrt((s0 + s) ** 2 + g.e ** 2))) < 1e-15
    assert np.max(np.abs(np.tan(np.radians(p["theta"])) - (v - g.e) / (s0 + s))) < 1e-12
    C = p["P"] * np.exp(1j * cam.sense * np.radians(phi))
    assert np.max(np.abs(C.real - cam.sense * g.e)) < 1e-15


def test_the_rocking_followers_roller_stays_on_its_arm():
    """In the cam's frame the pivot turns back by φ; the roller centre stays at the arm's length from it,
    the arm at ψ0 + s to the line of centres."""
    cam = load(ROCKING)
    sol = X.solve(cam)
    phi = np.linspace(0, 360, 3601)
    s, _, _ = X.motion(cam, phi)
    P = sol.at(phi)["P"]
    A = cam.centre_distance * np.exp(-1j * cam.sense * np.radians(phi))
    assert np.max(np.abs(np.abs(P - A) - cam.arm)) < 1e-15
    angle = np.angle((P - A) / (-A))
    assert np.max(np.abs(np.abs(angle) - (sol.geometry.psi0 + s))) < 1e-12


def test_curvature_of_a_circle_and_the_undercut_warning():
    """A dwell is an arc of the base circle: ρ = R0 there; a roller larger than the smallest convex
    radius of curvature is said to undercut the working profile."""
    cam = load(TRANSLATING)
    sol = X.solve(cam)
    rise, far, _, _ = cam.phases
    rho = sol.at(np.array([rise + far / 2, 355.0]))["rho"]
    assert rho[1] == pytest.approx(sol.geometry.R0, rel=1e-12)
    from dataclasses import replace
    rho = sol.curvature_min()
    assert rho < sol.geometry.R0                      # the flank is flatter than the base circle
    roller = 0.5 * (rho + sol.geometry.R0)            # larger than ρ_min, smaller than the base circle
    under = X.solve(replace(cam, roller=roller, base_radius=sol.geometry.R0))
    assert any("undercut" in en for en, _ in under.warnings)
    assert not any("undercut" in en for en, _ in sol.warnings)


# -- the graphical construction ------------------------------------------------------------------------------

@pytest.mark.parametrize("path", [TRANSLATING, ROCKING])
def test_the_construction_converges_to_the_exact_solution(path):
    """Exact readings (precision 0): s and ds/dφ are exact at the divisions at any count (the steps of
    equal area integrate exactly), R0's error falls with the divisions and at 128 is below 0.05 %; at
    the lab's 0.5 mm it stays finite and is reported."""
    cam = load(path)
    sol = X.solve(cam)
    errs = []
    for n in (8, 32, 128):
        g = construct(sol, n, 0.0)
        s, v, _ = X.motion(cam, g.phi)
        errs.append((float(np.max(np.abs(g.s - s))) / cam.stroke,
                     float(np.max(np.abs(g.v - v))) / float(np.max(np.abs(v))),
                     abs(g.R0_min - sol.R0_min) / sol.R0_min))
    # ds/dφ at the divisions is exact at any divisions: each interval's step is its mean ordinate, of
    # the area ∫d²s/dφ² dφ = Δ(ds/dφ) (stop 47; it fell with the divisions while the middle ordinate was taken);
    # s too, its steps the ds/dφ curve's of equal area, ∫ds/dφ dφ = Δs (stop 48; with the chord's middle,
    # the trapezoid rule, it fell as 1/n²)
    assert max(e[1] for e in errs) < 1e-12
    assert max(e[0] for e in errs) < 1e-12
    assert errs[2][2] <= max(errs[0][2], 1e-12)     # the translating example's R0 exact at every count
    assert max(errs[2]) < 5e-4
    g = construct(sol, 8, 0.5)
    assert 0 < abs(g.R0_min - sol.R0_min) / sol.R0_min < 0.05


# -- the command ---------------------------------------------------------------------------------------------

def test_cam_json_holds_the_contracts_fields():
    code, out, err = cli("cam", TRANSLATING, "--json")
    doc = check_run(["cam", "--json"], code, out, err)
    for key in ("scene", "follower", "roller_radius_m", "omega_rad_s", "stroke_m", "phases_deg", "laws",
                "pressure_angle_allowed_deg", "base_radius_min_m", "base_radius_m", "offset_m", "positions",
                "base_radius_graphical_m", "base_radius_error_pct", "curvature_min_m", "warnings"):
        assert key in doc, key
    p = doc["positions"][3]
    for key in ("s_m", "ds_dphi_m", "d2s_dphi2_m", "pressure_angle_deg", "radius_m", "profile_m"):
        assert key in p["exact"], key
    assert set(p["error_pct"]) == {"s", "ds_dphi", "pressure_angle"}
    assert doc["base_radius_m"] >= doc["base_radius_min_m"]
    assert doc["positions"][0]["exact"]["radius_m"] == pytest.approx(doc["base_radius_m"])
    code, out, err = cli("cam", ROCKING, "--json")
    doc = check_run(["cam", "--json"], code, out, err)
    assert {"swing_deg", "arm_m", "centre_distance_m"} <= set(doc)


def test_cam_tables_and_drawings(tmp_path):
    code, out, err = run(["cam", str(TRANSLATING), "--svg", str(tmp_path)])
    assert code == 0, err
    assert "R₀" in out and "ds/dφ" in out
    assert sorted(p.name for p in tmp_path.iterdir()) == ["diagrams.svg", "phase.svg", "profile.svg"]
    code, out, _ = run(["cam", str(ROCKING), "--lang", "en"])
    assert code == 0 and "Rocking follower, " in out         # the notes capitalised (review 2)


BASE = TRANSLATING.read_text(encoding="utf-8")


@pytest.mark.parametrize("old, new, words", [
    ("dwell_near = 90", "dwell_near = 80", ["cam.phases_deg", "sum to 360"]),
    ("stroke = 0.04 ", "stroke = -0.01 ", ["cam.stroke"]),
    ("stroke = 0.04 ", "stroke = \"x\" ", ["cam.stroke", "must be a number"]),
    ('rise = "cosine"', 'rise = "sinusoid"', ["cam.laws.rise", "unknown law"]),
    ("roller_radius = 0.01 ", "roller_radius = 0.01\nbase_radius = 0.009 ", ["cam.roller_radius", "smaller than the base"]),
    ("pressure_angle_deg = { rise = 30, return = 30 }", "pressure_angle_deg = { rise = 95, return = 30 }",
     ["cam.pressure_angle_deg.rise"]),
    ("omega = 10 ", "omega = [1] ", ["cam.omega"]),
    ('follower = "translating"', 'follower = "flat"', ["cam.follower"]),
])
def test_bad_cam_scenes_are_one_line_naming_the_key(tmp_path, old, new, words):
    assert old in BASE
    path = tmp_path / "cam.toml"
    path.write_text(BASE.replace(old, new), encoding="utf-8")
    code, out, err = run(["cam", str(path), "--lang", "en"])
    check_run(["cam"], code, out, err)
    assert code == 2
    for w in words + [str(path)]:
        assert w in err, (w, err)


def test_the_api_shows_the_cam():
    import graphplan
    c = graphplan.cam(TRANSLATING, lang="en")
    assert c.to_json()["base_radius_min_m"] == pytest.approx(X.min_base_radius(load(TRANSLATING)), rel=1e-12)
    assert "Cam synthesis" in c.table() and "<svg" in c._repr_html_()


@pytest.mark.parametrize("scene", ["cam_translating", "cam_rocking"])
def test_gallery_cam_drawings_are_current(scene):
    from graphplan.cli.gallery import cam_drawings
    from test_gallery import drawing
    for name, text in cam_drawings(scene).items():
        path = ROOT / "drawings" / name
        assert path.exists(), f"drawings/{name} is missing: run python -m graphplan.cli.gallery"
        assert drawing(path.read_text(encoding="utf-8")) == drawing(text), \
            f"drawings/{name} is out of date: run python -m graphplan.cli.gallery"


def test_the_bench_section_charts_convergence_and_the_failures(tmp_path, monkeypatch):
    """`graphplan bench --section cam` (quick): with the exact ruler the profile's error at the
    divisions falls as they grow, or is nil at every count (stop 48: s exact at the divisions with the
    steps of equal area); the translating example's R0 is exact at every even count: the parabolic return's
    binding point is a division, and chords integrate its piecewise-constant acceleration exactly); the
    failure rows warn of the linear law's rigid shocks and of the undercut, and a [ϑ] near 90° ends in a
    one-line refusal (the base circle collapses inside the roller)."""
    from graphplan.bench import run as bench
    monkeypatch.setattr(bench, "SECTIONS", {"cam": bench.SECTIONS["cam"]})
    rows = bench.run(tmp_path, quick=True, show_progress=False)
    assert (tmp_path / "cam.png").read_bytes()[:4] == b"\x89PNG"
    exact = [r for r in rows if r["method"] == "graphical" and r["precision_mm"] == 0]
    for scene in ("cam_translating", "cam_rocking"):
        errs = [r["profile_error_pct"] for r in exact if r["scene"] == scene]
        assert errs[-1] < max(errs[0] / 10, 1e-9) and errs[-1] < 0.1
    assert all(abs(r["R0_error_pct"]) < 1e-9 for r in exact if r["scene"] == "cam_translating")
    failures = {r["setting"]: r for r in rows if r["method"] == "failure"}
    assert any("rigid shocks" in w for w in failures["linear law (rigid shocks)"]["warnings"])
    assert any("undercut" in w for w in failures["roller 55.6 mm (undercut)"]["warnings"])
    assert failures["[ϑ] = 85° (near 90°)"]["status"] == "refused"


def test_keys_for_cam_variants_are_graded_by_check(tmp_path):
    """`graphplan key` on a table of cam variants (dotted [cam] columns over the translating example):
    each variant's smallest base radius is the exact one for its data; its key.csv, filled in as a
    student would, passes `check`; a wrong value fails."""
    table = tmp_path / "cams.csv"
    table.write_text(f"# base = {TRANSLATING}\nvariant,cam.stroke,cam.offset,cam.roller_radius\n"
                     "01,0.04,0.005,0.01\n02,0.05,0.0,0.012\n", encoding="utf-8")
    out = tmp_path / "keys"
    code, stdout, err = run(["key", str(table), "-o", str(out), "--quiet", "--no-pdf", "--jobs", "1", "--json"])
    assert code == 0, err
    rows = {r["variant"]: r for r in json.loads(stdout)["rows"]}
    from dataclasses import replace
    cam = load(TRANSLATING)
    assert rows["02"]["R0_min"] == pytest.approx(
        X.min_base_radius(replace(cam, stroke=0.05, offset=0.0, roller=0.012)), rel=1e-12)
    code, report, err = run(["check", str(out), str(out / "01" / "key.csv"), "--json"])
    assert code == 0, err
    doc = json.loads(report)
    assert doc["rows"] and all(r["pass"] for r in doc["rows"])
    wrong = tmp_path / "student.csv"
    wrong.write_text("variant,position,quantity,value\n01,4,s,0.03\n", encoding="utf-8")
    code, report, err = run(["check", str(out), str(wrong), "--json"])
    assert code == 0 and json.loads(report)["rows"][0]["status"] == "fail"


def test_each_kind_of_scene_to_its_commands():
    """A lever command on a cam scene and `cam` on a lever scene each say so in one line."""
    for argv, words in ((["analyze", str(TRANSLATING), "--lang", "en"], ["a cam scene", "graphplan cam"]),
                        (["cam", str(ROOT / "examples" / "shaper.toml"), "--lang", "en"], ["no [cam] table"])):
        code, out, err = run(argv)
        check_run(argv, code, out, err)
        assert code == 2 and all(w in err for w in words), err
