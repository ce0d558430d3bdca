"""The graphical plans against independent truth: the analytic solver (exact with --precision 0,
directions and senses included), a ruler's errors with the default precision, the Coriolis vector
of the slotted links, the dead centres found by the analytic extremes, and the scale series."""
from __future__ import annotations

import cmath
import json
import math
import re

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st_

import random_mechanisms as rm
from conftest import EXAMPLES, ROOT, example, scene_study
from graphplan.cli.main import main
from graphplan.drawing.plans import acceleration_records, position_record, velocity_records
from graphplan.report.plans import plans_json, plans_table
from graphplan.graphic.plans import NEAR_ZERO, SMALL_ANGLE_DEG, build_plans, measure, where
from graphplan.graphic.scales import SERIES, Targets, standard_scale

FAST = settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.too_slow])


def every_position(st, count=None):
    n = count or st.mech.task.count
    return [f"#{k}" for k in range(n)]


def check_exact(plans, rel=1e-9):
    """Every measured vector equals the analytic one (direction and sense too), every percent
    error is within 1e-7 %, and only near-zero quantities have none."""
    checked = 0
    for p in plans.positions:
        for plan in (p.velocity, p.acceleration):
            if plan is None:
                continue
            rates = [e for e in plan.entries.values() if e.kind in ("omega", "epsilon")]
            largest = max(abs(e.exact) for e in plan.entries.values() if e not in rates)
            w1 = abs(plans.study.mech.omega1)
            fastest = max([abs(e.exact) for e in rates] + [w1 if plan.kind == "velocity" else w1 * w1])
            for e in plan.entries.values():
                if e in rates:
                    assert abs(e.vector - e.exact) <= rel * fastest, e.key    # signed: the sense too
                else:
                    assert abs(e.vector - e.exact) <= rel * largest, (p.key, plan.kind, e.key)
                if e.error_pct is None:
                    assert e.basis <= NEAR_ZERO * max(x.basis for x in plan.entries.values()) + 1e-300
                else:
                    assert abs(e.error_pct) < 1e-7, (p.key, plan.kind, e.key, e.error_pct)
                    checked += 1
    return checked


# -- exact with --precision 0 ---------------------------------------------------------------------

@pytest.mark.parametrize("name", EXAMPLES)
def test_precision_zero_is_exact_on_every_example(name):
    st = example(name)
    plans = build_plans(st, precision=0, accel=every_position(st))
    assert all(p.acceleration is not None for p in plans.positions)
    assert check_exact(plans) > 6 * len(plans.positions)


@pytest.mark.parametrize("name", EXAMPLES)
def test_position_plan_constructions_are_the_mechanism(name):
    """The arcs, guide crossings and rocker lines put every point where the solver does."""
    st = example(name)
    plans = build_plans(st, precision=0)
    kin = st.solve([p.phi for p in plans.positions])
    pivot = st.mech.frame[st.mech.crank.pivot]
    for k, p in enumerate(plans.positions):
        for point in st.mech.point_names():
            drawn = where(plans.scheme, p.layout, plans.scheme.body_of(point), point)
            assert abs(drawn * plans.mu_l + pivot - kin.point(point)[0][k]) < 1e-12, point


def mechanisms():
    """Hypothesis strategies of scene texts of every group kind, guides fixed and moving."""
    w = st_.sampled_from([-30.0, -5.0, 7.5, 100.0])
    b = st_.sampled_from([1, -1])
    four_bar = dict(r=st_.floats(0.02, 0.06), d=st_.floats(0.2, 0.3), l2=st_.floats(0.2, 0.35),
                    l3=st_.floats(0.15, 0.3))
    return {
        "RRR": st_.builds(rm.rrr, st_.floats(0.02, 0.1), st_.floats(0.15, 0.4), st_.floats(0.05, 0.5),
                          st_.floats(0.05, 0.5), w, b),
        "RRP": st_.builds(rm.rrp, st_.floats(0.02, 0.1), st_.floats(0.05, 0.5), st_.floats(-0.05, 0.05),
                          st_.floats(-180, 180), w, b),
        "RPR": st_.builds(rm.rpr, st_.floats(0.03, 0.15), st_.floats(0.0, 0.3), st_.floats(-0.02, 0.02), w, b),
        "PRP": st_.builds(rm.prp, **four_bar, alpha=st_.floats(-60, 60), beta=st_.floats(0, 180), omega=w),
        "RPP": st_.builds(rm.rpp, st_.floats(0.02, 0.2), st_.floats(20, 160), st_.floats(-90, 90), w),
        "RRP moving": st_.builds(rm.rrp_moving, **four_bar, l4=st_.floats(0.4, 0.6), alpha=st_.floats(-60, 60),
                                 omega=w, branch=b),
        "RPP moving": st_.builds(rm.rpp_moving, **four_bar, alpha=st_.floats(30, 150), beta=st_.floats(-60, 60),
                                 omega=w),
    }


def assemblable(text, ok, kind):
    assume(ok)
    try:
        st = scene_study(text)
    except Exception:
        assume(False)
    kin = st.solve(np.linspace(0, 360, 145))
    # keep away from the toggle positions where any construction degenerates
    assume(all(float(np.min(c)) > 0.05 for c in kin.condition.values()))
    return st


@pytest.mark.parametrize("kind", list(mechanisms()))
def test_precision_zero_random_mechanisms(kind):
    @FAST
    @given(scene=mechanisms()[kind])
    def run(scene):
        st = assemblable(*scene, kind)
        kinds = [d.kind for d in st.structure.dyads]
        assert kind.split()[0] in kinds
        plans = build_plans(st, count=8, precision=0, accel=every_position(st, 8))
        check_exact(plans)
    run()


# -- a ruler's errors with the default precision --------------------------------------------------

def test_crank_slider_position_1():
    st = example("crank_slider")
    plans = build_plans(st)
    p = plans.at(1)
    b = p.velocity.entries["B"]
    assert b.analytic == pytest.approx(11.081, abs=5e-4)          # REFERENCE §2
    assert b.value == pytest.approx(11.081, abs=plans.precision * plans.mu_v)
    assert b.mm == measure(b.mm, 0.5)                              # read to 0.5 mm
    assert plans.scales == {"mu_l": 0.001, "mu_v": 0.2, "mu_a": 50.0}
    assert p.velocity.entries["omega_AB"].sense == "cw"


@pytest.mark.parametrize("name", EXAMPLES)
def test_default_precision_gives_ruler_errors(name):
    """Readings are whole ruler divisions; long vectors are off by tenths of a percent, and never
    by more than a few millimetres on the plan (propagated slips included)."""
    st = example(name)
    plans = build_plans(st, accel=every_position(st))
    long_errors = []
    for p in plans.positions:
        for plan in (p.velocity, p.acceleration):
            for e in plan.entries.values():
                if e.mm is None:
                    continue
                if plan.is_crank_pin(e.key):     # the scale's own vector, p_v a = v_A / μv, laid to 0.1 mm
                    assert abs(e.mm / 0.1 - round(e.mm / 0.1)) < 1e-9 and abs(e.mm - e.analytic / plan.mu) <= 0.05 + 1e-9
                    assert e.value == pytest.approx(e.mm * plan.mu, rel=1e-12) or e.value == e.analytic
                    continue
                assert abs(e.mm / 0.5 - round(e.mm / 0.5)) < 1e-9
                assert abs(e.mm - e.analytic / plan.mu) < 2.5, (p.key, plan.kind, e.key)
                if e.error_pct is not None and e.analytic / plan.mu > 40:
                    long_errors.append(abs(e.error_pct))
    assert 0.02 < np.mean(long_errors) < 0.6
    assert max(long_errors) < 4.0


def test_precision_changes_only_the_readings():
    st = example("four_bar")
    coarse = build_plans(st, precision=2.0)
    fine = build_plans(st, precision=0.1)

    def worst(plans):
        return max(abs(e.error_pct) for p in plans.positions for e in p.velocity.entries.values()
                   if e.error_pct is not None)
    assert worst(fine) < worst(coarse)
    assert coarse.scales == fine.scales


# -- the Coriolis vector of the slotted links -------------------------------------------------------

@pytest.mark.parametrize("name, rocker", [("shaper", "OB"), ("slotter", "BC")])
@pytest.mark.parametrize("precision", [0.0, 0.5])
def test_coriolis_of_the_slotted_link(name, rocker, precision):
    """a^k_A3A2 = 2·ω3·v_A3A2, along v_A3A2 turned 90° in the sense of ω3 — checked against the
    solver's slide (the block's motion along the rocker, v·g) and the rocker's ω."""
    st = example(name)
    plans = build_plans(st, precision=precision, accel=every_position(st))
    kin = st.solve([p.phi for p in plans.positions])
    slide = kin.slides["A"]
    for k, p in enumerate(plans.positions):
        acc, vel = p.acceleration, p.velocity
        e = acc.entries["k_A3A2"]
        w3 = float(kin.bodies[rocker].omega[k])
        v_rel = -complex(slide.v[k] * slide.direction[k])      # A3 relative to the block A2
        truth = 2j * w3 * v_rel
        assert e.analytic == pytest.approx(2 * abs(w3 * slide.v[k]), rel=1e-12)
        assert e.exact == pytest.approx(truth, abs=1e-12 * abs(truth) + 1e-12)
        drawn = [it for it in acc.record.items if it.role == "coriolis"]
        if abs(truth) / plans.mu_a < 1.0:
            continue
        assert len(drawn) == 1
        (x0, y0), (x1, y1) = drawn[0].points
        vec = complex(x1 - x0, y1 - y0)
        assert abs(vec) == pytest.approx(e.mm)
        v_plan = vel.entries["A3A2"].vector
        turn = vec / v_plan                                     # k ⟂ v_rel, turned as ω3 turns
        assert abs(cmath.phase(turn) - math.copysign(math.pi / 2, w3)) < 1e-9
        if precision == 0:
            assert e.error_pct == pytest.approx(0, abs=1e-7)
            assert abs(e.vector - truth) <= 1e-9 * abs(truth)
        else:
            assert abs(e.value - e.analytic) <= 2 * precision * plans.mu_a + 0.03 * e.analytic


# -- ill-conditioned constructions ----------------------------------------------------------------

@pytest.mark.parametrize("name", EXAMPLES)
def test_warnings_exactly_at_the_dead_centres(name):
    """Warnings appear at the positions the analytic extremes fall on, and nowhere else."""
    st = example(name)
    plans = build_plans(st, accel=every_position(st))
    at_extreme = {p.key for p in plans.positions
                  if any(abs((p.phi - e + 180) % 360 - 180) < 1e-6 for e in st.extremes)}
    warned = {p.key for p in plans.positions if p.warnings}
    assert warned == at_extreme
    for k in warned:
        (w,) = plans.at(k).warnings
        assert w.kind == "dead centre" and w.angle == pytest.approx(0, abs=1e-6)
        assert re.search(r"0\.00°", w.text) and "v_" in w.text


def test_dead_centres_of_four_bar_and_crank_slider():
    for name, keys in (("four_bar", {0}), ("crank_slider", {0, 6})):
        plans = build_plans(example(name))
        assert {p.key for p in plans.positions if p.warnings} == keys
        for k in keys:
            assert plans.at(k).velocity.entries[
                "B"].error_pct is None
            assert "dead centre" in plans.at(k).warnings[0].text


def test_small_angle_between_direction_lines_is_reported():
    """A four-bar near its toggle: the coupler and rocker nearly in line. The arcs (position plan)
    and the direction lines (both plans) cross at the transmission angle — reported with it."""
    text, _ = rm.rrr(0.05, 0.318, 0.27, 0.1, 10.0, 1)    # l2 + l3 − (d + r) = 2 mm: a small angle
    st = scene_study(text)
    plans = build_plans(st, count=24, accel=[f"#{k}" for k in range(24)])
    kin = st.solve([p.phi for p in plans.positions])
    seen = 0
    for k, p in enumerate(plans.positions):
        ab = kin.point("B")[0][k] - kin.point("A")[0][k]
        ob = kin.point("B")[0][k] - kin.point("O2")[0][k]
        mu = math.degrees(abs(math.atan2((ab.conjugate() * ob).imag, (ab.conjugate() * ob).real)))
        mu = min(mu, 180 - mu)
        kinds = {w.kind for w in p.warnings}
        if mu < SMALL_ANGLE_DEG - 1e-6:
            assert {"arcs", "lines"} <= kinds
            for w in p.warnings:
                if w.kind in ("arcs", "lines"):
                    assert w.angle == pytest.approx(mu, abs=1e-6)
                    assert f"{mu:.1f}°" in w.text
            seen += 1
        elif mu > SMALL_ANGLE_DEG + 1e-6:
            assert not kinds & {"arcs", "lines"}
    assert seen >= 1


def test_arc_meeting_the_guide_almost_tangentially():
    """A crank-slider whose rod barely reaches its guide: l = r + e + 2 mm. Near the farthest crank
    position the arc about A touches the guide line."""
    text, _ = rm.rrp(0.05, 0.072, 0.02, 0.0, 10.0, 1)
    st = scene_study(text)
    plans = build_plans(st, count=24)
    arcs = [w for p in plans.positions for w in p.warnings if w.kind == "arcs"]
    assert arcs and min(w.angle for w in arcs) < 15
    assert all("nearly tangent" in w.text for w in arcs)


# -- scales ---------------------------------------------------------------------------------------

def test_standard_scales_of_the_seeds():
    assert standard_scale(0.064, (40, 70)) == 0.001
    assert standard_scale(293.07 * 0.064, (50, 100)) == 0.2                    # seed 004: μv = 0.2
    assert standard_scale(293.07 ** 2 * 0.064, (60, 120)) == 50.0              # seed 004: μa = 50
    assert standard_scale(1.0, (50, 100), fixed=0.03) == 0.03
    assert standard_scale(1.0, (50, 100), largest=30.0, limit_mm=200) == 0.2   # 30/0.2 = 150 mm


@settings(max_examples=200, deadline=None)
@given(value=st_.floats(1e-6, 1e6), lo=st_.floats(1, 200), ratio=st_.floats(2, 5))
def test_standard_scale_fills_the_target(value, lo, ratio):
    hi = lo * ratio
    mu = standard_scale(value, (lo, hi))
    mantissa = mu / 10 ** math.floor(math.log10(mu) + 1e-12)
    assert any(abs(mantissa - m) < 1e-9 for m in SERIES)
    assert lo * (1 - 1e-9) <= value / mu <= hi * (1 + 1e-9)


def test_targets_make_figures_smaller():
    st = example("shaper")
    big = build_plans(st)
    small = build_plans(st, targets=Targets().scaled(0.5))
    assert small.mu_l > big.mu_l and small.mu_v > big.mu_v and small.mu_a > big.mu_a
    fixed = build_plans(st, mu_l=0.005, mu_v=0.1, mu_a=5)
    assert fixed.scales == {"mu_l": 0.005, "mu_v": 0.1, "mu_a": 5}


# -- records ---------------------------------------------------------------------------------------

def test_records_have_their_own_origin():
    plans = build_plans(example("slotter"))
    for rec in list(velocity_records(plans).values()) + list(acceleration_records(plans).values()):
        poles = [it for it in rec.items if it.role == "pole"]
        assert len(poles) == 1 and poles[0].points[0] == (0.0, 0.0)
        assert any(it.kind == "vector" for it in rec.items)
        assert any(it.kind == "text" for it in rec.items)
    pos = position_record(plans)
    joints = [it.points[0] for it in pos.items if it.kind == "point"]
    assert (0.0, 0.0) in joints                                   # the crank's pivot
    assert set(acceleration_records(plans)) == {1}
    roles = {it.role for it in acceleration_records(plans)[1].items}
    assert {"absolute", "normal", "tangential", "coriolis", "relative", "direction"} <= roles
    steps = {it.step for it in acceleration_records(plans)[1].items}
    assert any("a^k_A3A2" in s for s in steps)


def test_labels_do_not_collide():
    """No label of a plan touches a line or another label (drawing.labels.collisions)."""
    from graphplan.drawing.labels import collisions
    for name in EXAMPLES:
        plans = build_plans(example(name))
        for rec in [velocity_records(plans)[1], acceleration_records(plans)[1], position_record(plans)]:
            assert collisions(rec) == [], (name, rec.title)


# -- the command ------------------------------------------------------------------------------------

def run(capsys, *argv):
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def test_plans_json_contract(capsys):
    # --format none: the plans' own scales (the default draws at the A1 sheet's, see
    # tests/test_sheets_composition.py::test_terminal_plans_print_what_the_sheet_draws)
    code, out, err = run(capsys, "plans", str(ROOT / "examples" / "crank_slider.toml"), "--json",
                         "--format", "none")
    assert code == 0 and err == ""
    doc = json.loads(out)
    assert doc["scene"] and doc["mu_l"] == 0.001
    pos = doc["positions"]
    assert [p["index"] for p in pos] == list(range(12))
    p1 = pos[1]
    assert p1["phi_deg"] == pytest.approx(30.0) and p1["mu_v"] == 0.2 and p1["mu_a"] == 50.0
    b = p1["velocity"]["B"]
    assert set(b) == {"mm", "value", "analytic", "error_pct"}
    assert b["value"] == pytest.approx(b["mm"] * 0.2)
    assert b["error_pct"] == pytest.approx(100 * (b["value"] - b["analytic"]) / b["analytic"])
    assert {"BA", "omega_AB"} <= set(p1["velocity"])
    assert {"B", "n_BA", "t_BA", "epsilon_AB"} <= set(p1["acceleration"])
    assert "acceleration" not in pos[2] and pos[2]["warnings"] == []
    assert pos[0]["velocity"]["B"]["error_pct"] is None and pos[0]["warnings"]


def test_plans_json_precision_zero_shaper(capsys):
    code, out, _ = run(capsys, "plans", str(ROOT / "examples" / "shaper.toml"), "--json",
                       "--precision", "0", "--accel", "#1", "200", "#3")
    doc = json.loads(out)
    assert [p["index"] for p in doc["positions"]] == list(range(12)) + [None]
    extra = doc["positions"][-1]
    assert extra["phi_deg"] == pytest.approx(200.0)
    with_acc = [p for p in doc["positions"] if "acceleration" in p]
    assert [p["index"] for p in with_acc] == [1, 3, None]
    for p in doc["positions"]:
        for part in ("velocity", "acceleration"):
            for key, e in p.get(part, {}).items():
                assert e["error_pct"] is None or abs(e["error_pct"]) < 1e-7, key
    assert with_acc[0]["acceleration"]["k_A3A2"]["analytic"] > 0


def test_plans_table(capsys):
    code, out, _ = run(capsys, "plans", str(ROOT / "examples" / "crank_slider.toml"), "--format", "none", "--lang", "en")
    assert code == 0
    assert "μ_v = 0.2 (m/s)/mm" in out and "μ_a = 50 (m/s²)/mm" in out
    rows = [line.split() for line in out.splitlines() if re.match(r"\s+1\s+30\.00\s", line)]
    assert rows and rows[0][5] == "11.1"                           # v_B at position 1
    assert "dead centre" in out


def test_plans_and_diagrams_tables_give_the_sheets_turn_beside_the_angle_from_x(capsys):
    """The shaper's position 0 is its extreme position, where the crank is perpendicular to the
    rocker: φ₀ = 180° + arcsin(r/l_OB)·(sense) from +x — the terminal's φ column keeps that angle,
    the turn column gives the sheets' φ (0, 30, … in the crank's sense)."""
    import tomllib
    sense = {"ccw": 1.0, "cw": -1.0}[tomllib.loads((ROOT / "examples" / "shaper.toml").read_text(
        encoding="utf-8"))["crank"]["direction"]]
    for command in ("plans", "diagrams"):
        code, out, _ = run(capsys, command, str(ROOT / "examples" / "shaper.toml"), "--lang", "en")
        assert code == 0 and "turn, °" in out and "the sheets' φ" in out
        rows = [line.split() for line in out.splitlines() if re.match(r"\s+\d+\s+\d+\.\d\d\s+\d+\.\d\d\s", line)]
        first = {int(r[0]): (float(r[1]), float(r[2])) for r in reversed(rows)}
        phi0 = first[0][0]
        assert first[0][1] == 0.0 and phi0 not in (0.0, 360.0)
        for k, (phi, turn) in first.items():
            assert turn == pytest.approx(30.0 * k)
            assert (sense * (phi - phi0)) % 360.0 == pytest.approx(turn, abs=0.011)
    code, out, _ = run(capsys, "plans", str(ROOT / "examples" / "slotter.toml"), "--lang", "uk")
    # since kinmarks a subscript's digits after a letter are set lower, in the terminal too: A₃A₂
    assert "Швидкості" in out and "aᵏ_A₃A₂" in out


def test_plans_svg_files(capsys, tmp_path):
    code, out, _ = run(capsys, "plans", str(ROOT / "examples" / "four_bar.toml"), "--svg",
                       str(tmp_path / "svg"), "--accel", "#1", "#4")
    assert code == 0
    names = sorted(p.name for p in (tmp_path / "svg").iterdir())
    assert names == sorted(["positions.svg", "acceleration_01.svg", "acceleration_04.svg"]
                           + [f"velocity_{k:02d}.svg" for k in range(12)])
    text = (tmp_path / "svg" / "velocity_03.svg").read_text(encoding="utf-8")
    w = re.search(r' width="([\d.]+)mm"', text).group(1)
    h = re.search(r' height="([\d.]+)mm"', text).group(1)
    assert f'viewBox="0 0 {w} {h}"' in text
    assert "transform" not in text
    from graphplan.drawing.svg import to_png
    assert to_png(text)[:4] == b"\x89PNG"


@pytest.mark.parametrize("argv, part", [
    (["--accel", "#12"], "#12"), (["--accel", "abc"], "--accel"), (["--precision", "-1"], "--precision"),
    (["--positions", "1"], "--positions"), (["--mu-v", "0"], "--mu-v")])
def test_plans_bad_options(capsys, argv, part):
    code, out, err = run(capsys, "plans", str(ROOT / "examples" / "crank_slider.toml"), *argv)
    assert code == 2 and out == ""
    assert len(err.strip().splitlines()) == 1 and part in err


def test_plans_output_is_deterministic(capsys):
    a = run(capsys, "plans", str(ROOT / "examples" / "slotter.toml"), "--json")[1]
    b = run(capsys, "plans", str(ROOT / "examples" / "slotter.toml"), "--json")[1]
    assert a == b


def test_accel_angles_and_indices():
    st = example("crank_slider")
    plans = build_plans(st, accel=["30", "#3", 45.0, 7])
    assert plans.accel_keys == [1, 3, 7, 12]
    extra = plans.at(12)
    assert extra.index is None and extra.phi == pytest.approx(45.0)
    assert plans.at(12).velocity.entries["B"].analytic == pytest.approx(
        abs(st.solve([45.0]).point("B")[1][0]))


def test_crank_with_angular_acceleration_is_exact():
    """ε1 ≠ 0: a_A = a^n_AO + a^τ_AO, both laid off; still exact with precision 0."""
    text = (ROOT / "examples" / "crank_slider.toml").read_text(encoding="utf-8")
    text = text.replace("omega = 293.07          # rad/s, counter-clockwise",
                        "omega = 293.07\nepsilon = -20000")
    st = scene_study(text)
    assert st.mech.crank.epsilon == -20000
    plans = build_plans(st, precision=0, accel=every_position(st))
    check_exact(plans)
    roles = {it.role for it in acceleration_records(plans)[0].items}
    assert "tangential" in roles and "normal" in roles


def test_python_api_for_the_sheet():
    plans = build_plans(example("shaper"), targets=Targets().scaled(0.6))
    doc = plans_json(plans)
    assert json.loads(json.dumps(doc))["positions"][1]["acceleration"]["k_A3A2"]["mm"] > 0
    text = plans_table(plans, "uk")
    assert "Прискорення в положенні 1" in text and re.search(r"μ_l = 0,\d+ м/мм", text)
    assert set(velocity_records(plans)) == set(range(12)) and set(acceleration_records(plans)) == {1}
    for rec in [position_record(plans), *velocity_records(plans).values()]:
        x0, y0, x1, y1 = rec.bounds()
        assert x1 - x0 < 0.6 * 450 + 60 and y1 - y0 < 0.6 * 450 + 60
