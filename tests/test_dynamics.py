"""Dynamics of the machine: the reduced inertia against the kinetic-energy definition with velocities
from finite differences of positions, the resistance work against force × stroke, the steady
state's periodicity and δ, the graphical flywheel's convergence, the command line."""
from __future__ import annotations

import json
import math

import numpy as np
import pytest

from conftest import ROOT, example, scene_study
from graphplan.cli.main import main
from graphplan.exact import dynamics as dyn
from graphplan.graphic.flywheel import construct
from graphplan.model import motors

SCENES = ["slotter", "shaper"]


@pytest.fixture(scope="module")
def solved():
    """The exact dynamics of both examples (computed once: each takes a few seconds)."""
    return {name: dyn.analyse(example(name)) for name in SCENES}


def _fd_inertia(st, turn: np.ndarray) -> np.ndarray:
    """I*_m = 2T/ω1² with every velocity from a five-point difference of the exact positions (the
    solver's positions only: no velocity of its own enters)."""
    w1 = st.mech.omega1
    h = 0.02                                                   # degrees of crank turn
    phi = dyn.crank_angle(st, turn)
    sign = np.sign(w1)
    frames = [st.solve(np.mod(phi + sign * k * h, 360.0)) for k in (-2, -1, 1, 2)]
    dt = math.radians(h) / abs(w1)
    total = np.zeros(turn.shape)
    for name, link in st.mech.links.items():
        m, i_s = link.mass or 0.0, link.inertia or 0.0
        if not (m or i_s):
            continue
        local = link.local[link.com or next(iter(link.local))]
        x = [f.bodies[name].at(local)[0] for f in frames]
        th = np.unwrap(np.array([f.bodies[name].theta for f in frames]), axis=0)
        v = (x[0] - 8 * x[1] + 8 * x[2] - x[3]) / (12 * dt)
        om = (th[0] - 8 * th[1] + 8 * th[2] - th[3]) / (12 * dt)
        total += m * np.abs(v) ** 2 + i_s * om ** 2
    return total / w1 ** 2


@pytest.mark.parametrize("name", SCENES)
def test_reduced_inertia_is_the_kinetic_energy_definition(name):
    st = example(name)
    turn = np.linspace(0.0, 2 * math.pi, 73)[:-1] + 0.01
    r = dyn.reduce(st, turn)
    fd = _fd_inertia(st, turn)
    assert np.max(np.abs(r.inertia - fd) / fd) < 1e-9


@pytest.mark.parametrize("name", SCENES)
def test_inertia_derivative_against_differences_of_the_inertia(name):
    st = example(name)
    turn = np.linspace(0.0, 2 * math.pi, 37)[:-1] + 0.02
    h = 1e-4
    i = [dyn.reduce(st, turn + k * h).inertia for k in (-2, -1, 1, 2)]
    fd = (i[0] - 8 * i[1] + 8 * i[2] - i[3]) / (12 * h)
    rate = dyn.reduce(st, turn).d_inertia
    assert np.max(np.abs(rate - fd)) < 1e-7 * np.max(np.abs(rate))


@pytest.mark.parametrize("name", SCENES)
def test_resistance_work_is_force_times_stroke(name):
    """Gravity does no work over a cycle; the cutting force (constant, against the motion, on one
    stroke) does F × the output's stroke between its extreme positions."""
    st = example(name)
    c = dyn.cycle(st)
    t = st.solve(list(st.extremes)).slides[st.output.name].t
    stroke = abs(t[1] - t[0])
    force = st.mech.forces[0].magnitude
    assert c.work == pytest.approx(force * stroke, rel=1e-9)
    assert c.resistance_work(2 * math.pi) == pytest.approx(c.work, rel=1e-12)


def test_resistance_work_with_a_force_profile():
    """Seed 003's F_p(s): a trapezoidal profile over the ram's travel from position 0 does
    F·∫f(s)ds = 1500 N × (0.01 + 0.12 + 0.01) m; the cycle breaks at the profile's bends."""
    from graphplan.exact.positions import study
    from graphplan.model.scene import loads
    text = (ROOT / "examples" / "slotter.toml").read_text(encoding="utf-8").replace(
        'direction = "oppose"', 'direction = "oppose"\nprofile = [[0, 0], [0.02, 1], [0.14, 1], [0.16, 0]]')
    c = dyn.cycle(study(loads(text, "<profile>")))
    assert c.work == pytest.approx(1500.0 * 0.14, rel=1e-9)


def test_resistance_moment_reduces_the_force_by_its_velocity():
    """M*_c on the slotter's working stroke: F·|v_D|/ω1 plus gravity's m·g·v_y/ω1 — by hand."""
    st = example("slotter")
    turn = np.radians([20.0, 60.0, 100.0])
    r = dyn.reduce(st, turn)
    kin = st.solve(r.phi_deg)
    w1 = st.mech.omega1
    g = st.mech.g
    grav = sum((link.mass or 0.0) * g * kin.bodies[n].at(link.local[link.com or next(iter(link.local))])[1].imag
               for n, link in st.mech.links.items())
    vd = kin.point("D")[1]
    expected = np.where(r.working, 1500.0 * np.abs(vd), 0.0) / w1 + grav / w1
    assert np.allclose(r.moment, expected, rtol=1e-12, atol=1e-9)


@pytest.mark.parametrize("name", SCENES)
def test_steady_states_are_periodic_and_give_the_requested_delta(solved, name):
    d = solved[name]
    assert d.motion.closure < 1e-9
    assert d.motor_motion.closure < 1e-9
    # simulate again with the flywheels found: δ as requested
    again = dyn.classical(d.cycle, d.flywheel_total, d.omega_mean)
    assert abs(again.delta - d.delta) < 1e-6
    assert abs(again.mean - d.omega_mean) < 1e-9 * d.omega_mean
    if d.motor_flywheel > 0:
        m = dyn.motor_motion(d.cycle, d.drive, d.motor_flywheel)
        assert abs(m.delta - d.delta) < 1e-6


@pytest.mark.parametrize("name", SCENES)
def test_motor_motion_satisfies_the_equation_of_motion(solved, name):
    """The energy form's solution also solves I*·ω·dω/dφ + ½·dI*/dφ·ω² = M*_d − M*_c (eq. 2): the
    residual with dω/dφ by differences of the sampled ω is small against the moments."""
    d = solved[name]
    m = d.motor_motion
    c = d.cycle
    turn = np.linspace(0.3, 6.0, 40)
    h = 1e-5
    w = lambda t: np.interp(t, m.turn, m.omega)  # noqa: E731  (7200 samples: only for the point value)
    from scipy.integrate import solve_ivp
    const = m.inertia_constant
    rhs = lambda t, y: [(float(d.drive.moment(y[0])) - c.moment(t)  # noqa: E731
                         - 0.5 * float(dyn.reduce(d.study, [t]).d_inertia[0]) * y[0] ** 2)
                        / ((c.inertia(t) + const) * y[0])]
    sol = solve_ivp(rhs, (0.0, 1.5), [m.omega[0]], method="DOP853", rtol=1e-10, atol=1e-12, dense_output=True)
    check = np.linspace(0.1, 1.5, 8)
    assert np.max(np.abs(sol.sol(check)[0] - w(check))) < 1e-6 * d.omega_mean
    del turn, h


@pytest.mark.parametrize("name", SCENES)
def test_graphical_flywheel_converges_at_precision_zero(solved, name):
    d = solved[name]
    runs = [construct(d, n, 0.0, slopes="exact") for n in (24, 96, 384)]
    errs = [abs(f.error_pct(f.flywheel)) for f in runs]
    assert errs[2] < errs[0]
    assert errs[2] < 0.01
    course = construct(d, 384, 0.0)
    assert abs(course.error_pct(course.flywheel)) < 100 * d.delta ** 2   # the course's δ² left out
    drawn = construct(d, 12, 0.5)
    assert abs(drawn.error_pct(drawn.flywheel)) < 5.0


def test_motor_line_and_the_seeds_swapped_speeds():
    m, warnings = motors.from_data({"name": "4АМ80А2", "power_kW": 1.5, "rpm_sync": 3000, "rpm_rated": 2850,
                                    "omega_sync": 298.3, "omega_rated": 314}, "dynamics.motor")
    assert m.omega_sync == pytest.approx(314.159, abs=1e-3)
    assert m.omega_rated == pytest.approx(298.451, abs=1e-3)
    assert len(warnings) == 1 and "swapped" in warnings[0][0] and "переставлені" in warnings[0][1]
    a, b = m.line
    assert a * m.omega_rated + b == pytest.approx(m.moment_rated)
    assert a * m.omega_sync + b == pytest.approx(0.0, abs=1e-9)
    assert m.moment_rated == pytest.approx(1500 / m.omega_rated)


def test_choice_rule_takes_the_next_size_up():
    assert motors.choose(1.45, 3000).name == "4АМ80А2"        # seed 003: 1.34 kW / 0.92
    assert motors.choose(1.51, 3000).power_kW == 2.2
    assert motors.find("4AM80A2").name == "4АМ80А2"          # Latin look-alikes


def test_cli_json_keys(capsys):
    code = main(["dynamics", str(ROOT / "examples" / "slotter.toml"), "--json", "--divisions", "12"])
    assert code == 0
    doc = json.loads(capsys.readouterr().out)
    assert {"delta", "omega_mean", "positions", "flywheel", "motion", "motor"} <= set(doc)
    assert set(doc["positions"][0]) >= {"phi_deg", "inertia", "d_inertia", "moment_resistance", "moment_driving"}
    assert {"exact", "graphical", "error_pct", "approximate"} <= set(doc["flywheel"])
    assert doc["motion"]["phi_deg"][0] == 0.0 and doc["motion"]["phi_deg"][-1] == 360.0
    assert doc["motion"]["omega"][0] == pytest.approx(doc["motion"]["omega"][-1], rel=1e-9)
    assert abs(doc["motion"]["delta"] - doc["delta"]) < 1e-6
    assert doc["motor"]["name"] == "4АМ80А2" and doc["motor"]["power_kW"] == 1.5
    assert len(doc["positions"]) == 12
    assert any("swapped" in w for w in doc["warnings"])


NO_MASSES = """
[frame.points]
O = [0, 0]
[frame.guides]
x = { through = [0, 0], angle_deg = 0 }
[crank]
pivot = "O"
pin = "A"
length = 0.1
rpm = 60
[[link]]
name = "AB"
joints = ["A", "B"]
length = 0.3
[[link]]
name = "B"
joints = ["B"]
slides_on = "x"
[[force]]
point = "B"
magnitude = 100
"""


def _bad(tmp_path, capsys, argv, text=None):
    if text is not None:
        path = tmp_path / "scene.toml"
        path.write_text(text, encoding="utf-8")
        argv = [str(path) if a == "SCENE" else a for a in argv]
    code = main(["dynamics", *argv])
    err = capsys.readouterr().err
    assert code == 2
    assert len(err.strip().splitlines()) == 1
    return err


def test_bad_inputs_exit_2_with_one_line(tmp_path, capsys):
    slotter = str(ROOT / "examples" / "slotter.toml")
    assert "(0, 0.5)" in _bad(tmp_path, capsys, [slotter, "--delta", "0.7", "--lang", "en"])
    assert "(0; 0,5)" in _bad(tmp_path, capsys, [slotter, "--delta", "0"])
    assert "no masses" in _bad(tmp_path, capsys, ["SCENE", "--lang", "en"], NO_MASSES)
    weak = (ROOT / "examples" / "slotter.toml").read_text(encoding="utf-8").replace(
        'power_kW = 1.5, rpm_sync', 'power_kW = 0.2, rpm_sync')
    assert "cannot drive the cycle" in _bad(tmp_path, capsys, ["SCENE", "--lang", "en"], weak)
    assert "не може вести цикл" in _bad(tmp_path, capsys, ["SCENE", "--lang", "uk"], weak)
    bad_delta = (ROOT / "examples" / "shaper.toml").read_text(encoding="utf-8").replace(
        "delta = 0.04", "delta = 0.6")
    assert "dynamics.delta" in _bad(tmp_path, capsys, ["SCENE"], bad_delta)


def test_a_scene_without_resistance_is_refused():
    text = NO_MASSES.replace('length = 0.3\n', 'length = 0.3\nmass = 2\n').split("[[force]]")[0]
    with pytest.raises(Exception, match="no work"):
        dyn.analyse(scene_study(text))


# English: slow (the slotter's English dynamics sheet is composed for it and test_dynamics_projection's
# slow case only; an English dynamics sheet stays in the default run: test_review_notation's offset press)
@pytest.mark.parametrize("lang", ["uk", pytest.param("en", marks=pytest.mark.slow)])
def test_the_third_sheet_holds_every_block_and_no_label_overlaps(lang):
    from conftest import example_composed, example_sheet
    from graphplan.sheets.compose import defects
    # shared with the modules that read it; the English one composed alone (its numbering unread here
    # would count the English kinematics and force sheets no other test composes)
    sheet = (example_composed if lang == "en" else example_sheet)("slotter", "dynamics", "A1", lang)
    names = {p.name for p in sheet.placed}
    assert names == {"moments", "wittenbauer", "energy", "inertia", "speed", "positions table",
                     "flywheel table", "motor table", "notes"}
    x0, y0, x1, y1 = sheet.form.frame_box
    for p in sheet.placed:
        assert x0 <= p.box[0] and p.box[2] <= x1 and y0 <= p.box[1] and p.box[3] <= y1
    assert defects(sheet) == []
    texts = " ".join(p.text for p in sheet.record.items if p.kind == "text")
    assert ("Віттенбауера" if lang == "uk" else "Wittenbauer") in texts
    assert "|kl|" in texts


def test_reducer_shafts_reduce_by_their_kinetic_energy():
    """Seed 003 eq. 4: I*_red = I1·i² + I2·(i/i1)² + I3 — with the slotter's i = 2850/120."""
    from graphplan.exact.positions import study
    from graphplan.model.scene import loads
    text = (ROOT / "examples" / "slotter.toml").read_text(encoding="utf-8").replace(
        "efficiency = 0.92", "efficiency = 0.92\nreducer_shafts = [0.0004, 0.002, 0.05]\nfirst_stage_ratio = 4.75")
    st = study(loads(text, "<reducer>"))
    dr = dyn.drive(st, dyn.cycle(st))
    i = 2850 / 120
    assert dr.ratio == pytest.approx(i)
    assert dr.reducer_reduced == pytest.approx(0.0004 * i ** 2 + 0.002 * (i / 4.75) ** 2 + 0.05, rel=1e-12)
