"""Kinetostatics against independent truth: equilibrium of every link summed here from the raw
loads and reactions, closed forms of a crank-slider, power balance (d'Alembert's virtual power, a
different computation from the group-by-group statics), and the graphical plans at precision 0."""
from __future__ import annotations

import hashlib
import json
import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st_

import random_mechanisms as rm
from conftest import ROOT, example, scene_study
from graphplan.cli.main import main
from graphplan.graphic.forceplans import construct, measure, standard_scale
from graphplan.exact.kinematics import cross, dot
from graphplan.exact.kinetostatics import analyse, at_scene_angle, full_turn
from graphplan.model.mechanism import FRAME

LOADED = ["shaper", "slotter"]
FAST = settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.too_slow])


def run(capsys, *argv):
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def residuals(ks):
    """Largest |ΣF| and |ΣM_origin| over the links, summed here from loads, reactions and M_b."""
    worst_f = worst_m = 0.0
    crank = ks.mech.crank.link
    for link in ks.mech.links:
        f = np.zeros(len(ks.phi_deg), complex)
        m = np.zeros(len(ks.phi_deg))
        for ld in ks.loads:
            if ld.link == link:
                f, m = f + ld.force, m + ld.couple + cross(ld.at, ld.force)
        for r in ks.reactions.values():
            sign = 1 if r.on == link else -1 if r.frm == link else 0
            f, m = f + sign * r.force, m + sign * (r.couple + cross(r.at, r.force))
        if link == crank:
            m = m + ks.balancing
        worst_f, worst_m = max(worst_f, np.max(np.abs(f))), max(worst_m, np.max(np.abs(m)))
    return worst_f, worst_m


def scale(ks):
    return max(max(float(np.max(np.abs(ld.force))) for ld in ks.loads), 1.0)


# -- the examples ------------------------------------------------------------------------------

@pytest.mark.parametrize("name", LOADED)
def test_exact_mode_four_moments_agree(name):
    st = example(name)
    fp = construct(st, at_scene_angle(st), precision=0)
    a = fp.analytic
    assert abs(a) > 1.0
    for value in (fp.balancing, fp.lever.balancing, fp.power):
        assert abs(value - a) <= 1e-9 * abs(a)              # 1e-7 %
    for m in fp.reactions().values():
        assert m.error_pct is not None and abs(m.error_pct) < 1e-7, m.key
        assert abs((m.angle_deg - m.analytic_angle_deg + 180) % 360 - 180) < 1e-7


@pytest.mark.parametrize("name", LOADED)
def test_drafting_precision_within_the_labs_five_percent(name):
    st = example(name)
    fp = construct(st, at_scene_angle(st), precision=0.5)
    a = fp.analytic
    for value in (fp.balancing, fp.lever.balancing):
        assert 0 < abs(value - a) <= 0.05 * abs(a)          # realistic: not exact, within 5 %
    errors = [abs(m.error_pct) for m in fp.reactions().values() if m.error_pct is not None]
    assert max(errors) > 0.01


def test_inertia_loads_are_read_off_the_acceleration_plan():
    """Review 10 #14: the draftsman's Φ = m·(πs)·μa, against π s as drawn, and M^Φ = −I_S·ε with ε
    of his own acceleration plan load the force plans and the lever (not the closed form's); at
    precision 0 they are the closed form's m·a_S, −I_S·ε."""
    from graphplan.graphic.forceplans import acceleration_plan
    st = example("shaper")
    phi = at_scene_angle(st)
    accel = acceleration_plan(st, phi, precision=0.5)
    plan = next(q.acceleration for q in accel.positions if q.acceleration is not None)
    fp = construct(st, phi, precision=0.5, accel=accel)
    kin = st.solve([phi])
    loaded = {f.name: f for gp in fp.groups for f in gp.forces}
    lever = {t.name: t for t in fp.lever.terms}
    assert set(fp.inertia) == {n for n, l in st.mech.links.items() if l.mass or l.inertia}
    for name, i in fp.inertia.items():
        link = st.mech.links[name]
        e = plan.entries[link.com or next(iter(link.local))]
        assert abs(abs(i.force) - link.mass * e.mm * accel.mu_a) <= 1e-9 * abs(i.force)     # ruler mm × μa × m
        assert abs(i.force / abs(i.force) + e.vector / abs(e.vector)) < 1e-12                # against π s as drawn
        assert i.couple == -(link.inertia or 0.0) * plan.rates[name]
        phi_n = f"Φ{link.number}"
        assert loaded[phi_n].force == i.force and lever[phi_n].vector == i.force
        exact = abs(kin.bodies[name].at(link.local[link.com or next(iter(link.local))])[2][0]) * link.mass
        assert 0 < abs(abs(i.force) - exact) <= 0.05 * exact                                # realistic, not exact
    exact_fp = construct(st, phi, precision=0)
    for name, i in exact_fp.inertia.items():
        assert abs(i.force - i.exact_force) <= 1e-9 * abs(i.exact_force)
        assert abs(i.couple - i.exact_couple) <= 1e-9 * max(abs(i.exact_couple), 1.0)
        b = kin.bodies[name]
        link = st.mech.links[name]
        assert abs(i.exact_force + link.mass * b.at(link.local[link.com or next(iter(link.local))])[2][0]) < 1e-9
        assert i.exact_couple == pytest.approx(-(link.inertia or 0) * float(b.eps[0]), abs=1e-12)


@pytest.mark.parametrize("name", LOADED)
def test_every_link_is_in_equilibrium_over_the_turn(name):
    ks = full_turn(example(name), 72)
    f, m = residuals(ks)
    assert f <= 1e-9 * scale(ks) and m <= 1e-9 * scale(ks)


@pytest.mark.parametrize("name", LOADED)
def test_power_balance_and_lever_over_the_turn(name):
    ks = full_turn(example(name), 360)
    top = np.max(np.abs(ks.balancing))
    assert np.max(np.abs(ks.balancing - ks.power())) <= 1e-10 * top
    assert np.max(np.abs(ks.balancing - ks.lever())) <= 1e-10 * top


@settings(max_examples=20, deadline=None)
@given(turn=st_.floats(0.0, 359.99), name=st_.sampled_from(LOADED))
def test_graphical_lever_equals_power_balance_exactly(turn, name):
    st = example(name)
    phi = (st.phi0 + turn) % 360.0
    fp = construct(st, phi, precision=0)
    tol = 1e-9 * max(abs(fp.power), 1e-3 * float(np.max(np.abs(full_turn(st, 36).balancing))))
    assert abs(fp.lever.balancing - fp.power) <= tol
    assert abs(fp.balancing - fp.power) <= tol


def test_shaper_cutting_force_on_the_working_stroke_only():
    st = example("shaper")
    ks = full_turn(st, 360)
    p = next(ld for ld in ks.loads if ld.name == "P_C")
    v = ks.kin.point("C")[1]
    moving = np.abs(v) > 1e-6
    # the working stroke is the slower one: 180° + θ = 231.4° of crank turn, after the idle one
    assert np.sum(ks.working) == pytest.approx(180 + st.mech.derived["theta_deg"], abs=1.0)
    assert not ks.working[0] and ks.working[int(st.from_position0(at_scene_angle(st)))]
    assert np.allclose(np.abs(p.force[ks.working]), 5800.0)
    assert np.all(p.force[~ks.working] == 0)
    assert np.all(dot(p.force, v)[moving & ks.working] < 0)          # it opposes the ram


def test_slotter_cuts_on_the_downward_stroke():
    ks = full_turn(example("slotter"), 360)
    p = next(ld for ld in ks.loads if ld.name == "P_D")
    vy = ks.kin.point("D")[1].imag
    moving = np.abs(vy) > 1e-6
    assert np.all((np.abs(p.force) > 0)[moving] == (vy < 0)[moving])
    assert np.allclose(p.force[ks.working], 1500j)                  # upward, against the cut


# -- closed forms ------------------------------------------------------------------------------

CRANK_SLIDER = """
[frame.points]
O = [0, 0]
[frame.guides]
x = { through = [0, 0], angle_deg = 0 }
[crank]
name = "OA"
pivot = "O"
pin = "A"
length = 0.064
omega = 293.07
[[link]]
name = "AB"
joints = ["A", "B"]
length = 0.307
[[link]]
name = "B"
joints = ["B"]
slides_on = "x"
[positions]
start = "max"
[[force]]
point = "B"
magnitude = 1000
stroke = "both"
direction = "oppose"
"""


def test_crank_slider_with_one_force_closed_form():
    """No masses, F against the slider's motion: M_b = F·|v_B|/ω1; the rod is a two-force member,
    |R23| = F/cos β, the guide's reaction N = F·tan β with sin β = r·sin φ / l."""
    st = scene_study(CRANK_SLIDER)
    phi = np.array([10.0, 37.0, 80.0, 150.0, 200.0, 300.0])
    ks = analyse(st, phi)
    r, l, w, f = 0.064, 0.307, 293.07, 1000.0
    p = np.radians(phi)
    root = np.sqrt(l ** 2 - r ** 2 * np.sin(p) ** 2)
    vb = -r * w * np.sin(p) - r ** 2 * w * np.sin(p) * np.cos(p) / root
    assert np.allclose(ks.balancing, f * np.abs(vb) / w, rtol=1e-12)
    cos_b, tan_b = root / l, r * np.sin(p) / root
    assert np.allclose(np.abs(ks.reactions["R23"].force), f / cos_b, rtol=1e-12)
    assert np.allclose(np.abs(ks.reactions["R03"].force), f * np.abs(tan_b), rtol=1e-12)
    assert np.allclose(np.abs(ks.reactions["R01"].force), f / cos_b, rtol=1e-12)
    for k, a in enumerate(phi):
        fp = construct(st, a, precision=0)
        assert fp.balancing == pytest.approx(ks.balancing[k], rel=1e-12)
        assert fp.lever.balancing == pytest.approx(ks.balancing[k], rel=1e-12)


def test_weight_and_inertia_of_the_crank_alone_loaded():
    """Only the crank has a mass (S1 at OA/2): M_b = m·g·x_S1 (the weight's moment about O; Φ1 is
    radial), and the pivot takes the rest: R01 = m·g·i − m·ω²·OS1·e^{iφ}."""
    text = CRANK_SLIDER.replace("length = 0.064\n", "length = 0.064\npoints = { S1 = 0.5 }\nmass = 3\n")
    st = scene_study(text.split("[[force]]")[0])
    phi = np.array([0.0, 45.0, 120.0, 260.0])
    ks = analyse(st, phi)
    m, g, rs, w = 3.0, 9.81, 0.032, 293.07
    e = np.exp(1j * np.radians(phi))
    assert np.allclose(ks.balancing, m * g * rs * e.real, rtol=1e-12, atol=1e-12)
    assert np.allclose(ks.reactions["R01"].force, 1j * m * g - m * w ** 2 * rs * e, rtol=1e-12)
    assert np.allclose(ks.reactions["R12"].force, 0, atol=1e-9)


# -- random mechanisms of every dyad kind --------------------------------------------------------

def loaded(text: str, point: str, angle: float) -> str:
    """Masses on every link (q·l, or 1.5 kg on links without a length), I = 0.1·m·l², a force."""
    out = []
    for line in text.splitlines():
        out.append(line)
        if line.startswith("slides_on") or line.startswith('joints = ["P"]'):
            out += ["mass = 1.5", "inertia = 0.004"]
    return ("\n".join(out) + "\n[loads]\nmass_per_length = 12\ninertia_factor = 0.1\n"
            f"[[force]]\npoint = \"{point}\"\nmagnitude = 250\nstroke = \"both\"\ndirection = {angle}\n")


KINDS = {
    "RRR": (lambda: rm.rrr(0.05, 0.3, 0.3, 0.25, 10.0, 1), "B"),
    "RRP": (lambda: rm.rrp(0.05, 0.2, 0.02, 20, -7.5, 1), "B"),
    "RPR": (lambda: rm.rpr(0.05, 0.15, 0.01, 7.5, -1), "A"),
    "PRP": (lambda: rm.prp(0.05, 0.3, 0.3, 0.25, 30, 100, 7.5), "C"),
    "RPP": (lambda: rm.rpp(0.05, 80, 10, -7.5), "A"),
}


@pytest.mark.parametrize("kind", sorted(KINDS))
def test_every_dyad_kind_equilibrium_and_checks(kind):
    make, point = KINDS[kind]
    st = scene_study(loaded(make()[0], point, 30.0))
    assert st.structure.dyads[-1].kind == kind
    ks = full_turn(st, 48)
    f, m = residuals(ks)
    assert f <= 1e-9 * scale(ks) and m <= 1e-9 * scale(ks)
    top = np.max(np.abs(ks.balancing))
    assert np.max(np.abs(ks.balancing - ks.power())) <= 1e-10 * top
    assert np.max(np.abs(ks.balancing - ks.lever())) <= 1e-10 * top
    for phi in ks.phi_deg[::12]:
        fp = construct(st, phi, precision=0)
        assert abs(fp.balancing - fp.analytic) <= 1e-9 * top
        assert abs(fp.lever.balancing - fp.analytic) <= 1e-9 * top
        for r in fp.reactions().values():
            assert abs(r.value - r.analytic) <= 1e-9 * scale(ks), r.key


@FAST
@given(kind=st_.sampled_from(sorted(KINDS)), angle=st_.floats(0, 360), turn=st_.floats(0, 360))
def test_lever_equals_power_for_any_force(kind, angle, turn):
    make, point = KINDS[kind]
    st = scene_study(loaded(make()[0], point, angle))
    ks = analyse(st, [turn])
    ref = max(abs(float(ks.power()[0])), 1e-6)
    assert abs(ks.lever()[0] - ks.power()[0]) <= 1e-9 * ref + 1e-12
    assert abs(ks.balancing[0] - ks.power()[0]) <= 1e-9 * ref + 1e-9


# -- drafting helpers --------------------------------------------------------------------------

def test_standard_scale_series():
    assert standard_scale(56.2) == 100.0
    assert standard_scale(30.0) == 40.0
    assert standard_scale(0.0042) == 0.005
    assert standard_scale(0.002) == 0.002
    assert standard_scale(2.1e-3) == 0.0025
    assert measure(12.26, 0.5) == 12.5 and measure(12.24, 0) == 12.24


# -- the command -------------------------------------------------------------------------------

@pytest.mark.parametrize("name", LOADED)
def test_forces_json_contract(capsys, name):
    code, out, err = run(capsys, "forces", str(ROOT / "examples" / f"{name}.toml"), "--json")
    assert code == 0 and err == ""
    doc = json.loads(out)
    assert set(doc) >= {"phi_deg", "mu_F", "balancing_moment", "error_pct", "reactions", "inertia"}
    assert set(doc["balancing_moment"]) == {"analytic", "plans", "lever", "power"}
    assert set(doc["error_pct"]) == {"plans", "lever", "power"}
    st = example(name)
    assert doc["phi_deg"] == pytest.approx(at_scene_angle(st))
    assert all(abs(doc["error_pct"][k]) < 5 for k in ("plans", "lever"))
    for key, r in doc["reactions"].items():
        assert key.startswith("R") and {"value", "angle_deg", "analytic", "error_pct"} <= set(r)
        assert 0 <= r["angle_deg"] < 360
    ks = analyse(st, [doc["phi_deg"]])
    for key, item in doc["inertia"].items():
        link = st.mech.links[item["link"]]
        a = ks.kin.bodies[item["link"]].at(link.local[link.com or next(iter(link.local))])[2][0]
        assert item["force"] == pytest.approx((link.mass or 0) * abs(a), rel=1e-12)
        eps = ks.kin.bodies[item["link"]].eps[0]
        assert item["moment"] == pytest.approx(-(link.inertia or 0) * eps, rel=1e-12, abs=1e-12)


def test_forces_exact_and_phi_option(capsys):
    path = str(ROOT / "examples" / "shaper.toml")
    code, out, _ = run(capsys, "forces", path, "--phi", "100", "--precision", "0", "--json")
    doc = json.loads(out)
    assert doc["phi_deg"] == 100.0
    assert all(abs(v) < 1e-7 for v in doc["error_pct"].values())
    assert all(abs(r["error_pct"]) < 1e-7 for r in doc["reactions"].values() if r["error_pct"] is not None)


def test_forces_table_and_files(capsys, tmp_path):
    path = str(ROOT / "examples" / "slotter.toml")
    code, out, err = run(capsys, "forces", path, "--svg", str(tmp_path / "svg"),
                         "--charts", str(tmp_path / "charts"), "--lang", "en")
    assert code == 0 and err == ""
    assert "Group II(4-5) RRP" in out and "Zhukovsky lever" in out and "power balance" in out
    assert "drawn, mm" in out and "R₀₃" in out
    code, uk, err = run(capsys, "forces", path)
    assert "Група II(4-5) ВВП" in uk and "Важіль Жуковського" in uk and "M_зр" in uk
    import svgelements
    for name in ("forces.svg", "lever.svg"):
        doc = svgelements.SVG.parse(str(tmp_path / "svg" / name))
        assert len(list(doc.elements())) > 50
    first = {p.name: hashlib.sha256(p.read_bytes()).hexdigest() for p in (tmp_path / "charts").iterdir()}
    assert set(first) == {"balancing_moment.png", "balancing_moment.svg", "hodographs.png", "hodographs.svg"}
    run(capsys, "forces", path, "--charts", str(tmp_path / "charts"), "--lang", "en")
    again = {p.name: hashlib.sha256(p.read_bytes()).hexdigest() for p in (tmp_path / "charts").iterdir()}
    assert again == first


def test_forces_output_is_deterministic(capsys):
    path = str(ROOT / "examples" / "shaper.toml")
    assert run(capsys, "forces", path, "--json")[1] == run(capsys, "forces", path, "--json")[1]


@pytest.mark.parametrize("argv, words", [
    (["--precision", "-1"], "--precision"),
    (["--phi", "nan"], "--phi"),
])
def test_forces_bad_input_one_line(capsys, argv, words):
    code, out, err = run(capsys, "forces", str(ROOT / "examples" / "shaper.toml"), *argv)
    assert code == 2 and out == "" and err.count("\n") == 1 and words in err


def test_force_profile_over_the_output_distance():
    """A cutting force that grows linearly with the ram's distance from position 0."""
    text = (ROOT / "examples" / "shaper.toml").read_text(encoding="utf-8")
    text = text.replace('direction = "oppose"', 'direction = "oppose"\nprofile = [[0.0, 0.0], [0.5, 1.0]]')
    st = scene_study(text)
    ks = full_turn(st, 90)
    p = next(ld for ld in ks.loads if ld.name == "P_C")
    s = np.abs(ks.kin.point("C")[0].real - ks.kin.point("C")[0][0].real)
    expected = np.where(ks.working, 5800.0 * np.minimum(s / 0.5, 1.0), 0.0)
    assert np.allclose(np.abs(p.force), expected, atol=1e-6)
    assert np.max(np.abs(ks.balancing - ks.power())) <= 1e-10 * np.max(np.abs(ks.balancing))


def test_bad_profile_is_one_line(capsys, tmp_path):
    text = (ROOT / "examples" / "shaper.toml").read_text(encoding="utf-8")
    bad = tmp_path / "bad.toml"
    bad.write_text(text.replace('direction = "oppose"', 'direction = "oppose"\nprofile = [[0.2, 1], [0.1, 0]]'),
                   encoding="utf-8")
    code, out, err = run(capsys, "forces", str(bad))
    assert code == 2 and "force[0].profile" in err and err.count("\n") == 1


@pytest.mark.parametrize("kind", sorted(KINDS))
def test_drawings_of_every_dyad_kind(kind):
    """Each group's scheme, its force polygon and the lever are drawn and render."""
    from graphplan.drawing import forces as forcedraw
    from graphplan.drawing import svg
    make, point = KINDS[kind]
    st = scene_study(loaded(make()[0], point, 30.0))
    fp = construct(st, 40.0, precision=0.5)
    recs = forcedraw.records(fp)
    assert {f"group {g.label}" for g in fp.groups} <= set(recs) and "lever" in recs
    for g in fp.groups:
        drawn = {s.name for s in g.sides}
        # every reaction is a side of its polygon, named as it acts on the group's link
        assert {m.name for m in g.reactions.values()} <= drawn
    page, w, h = svg.page_for(forcedraw.drawing(fp))
    text = svg.render(page, w, h)
    assert text.count("<line") > 20 and ">R</tspan><tspan" in text and ">01</tspan>" in text   # R₀₁
