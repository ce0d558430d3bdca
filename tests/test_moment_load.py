"""A resistance moment on a rocker (`[[moment]]`): the couple in the kinetostatics, the force plans,
the lever, the dynamics and the sheets, against the four-bar's closed form."""
from __future__ import annotations

import cmath
import math

import numpy as np
import pytest

from conftest import scene_study
from graphplan.cli.main import main
from graphplan.exact.dynamics import resistance
from graphplan.exact.kinematics import solve
from graphplan.exact.kinetostatics import analyse
from graphplan.graphic.forceplans import construct

R, L2, L3, O2 = 0.08, 0.32, 0.22, complex(0.30, 0.04)
W1, M = 9.42477796076938, 120.0

FOUR_BAR = f"""
title = "four-bar with a moment on the rocker"
[frame.points]
O1 = [0, 0]
O2 = [{O2.real}, {O2.imag}]
[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = {R}
omega = {W1}
[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = {L2}
[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = {L3}
[branch]
B = 1
[positions]
count = 12
[[moment]]
link = LINK
magnitude = {M}
stroke = "both"
direction = "DIR"
"""


def scene(link: str = "3", direction: str = "oppose") -> str:
    return FOUR_BAR.replace("LINK", link).replace("DIR", direction)


def rocker_angle(phi_deg: np.ndarray, near: np.ndarray) -> np.ndarray:
    """θ3 = arg(B − O2), B where the circles (A, l2) and (O2, l3) meet (the one nearer ``near``)."""
    a = R * np.exp(1j * np.radians(phi_deg))
    d = O2 - a
    dist = np.abs(d)
    along = (dist ** 2 + L2 ** 2 - L3 ** 2) / (2 * dist)
    across = np.sqrt(L2 ** 2 - along ** 2)
    u = d / dist
    b1, b2 = a + u * (along + 1j * across), a + u * (along - 1j * across)
    b = np.where(np.abs(b1 - near) < np.abs(b2 - near), b1, b2)
    return np.angle(b - O2)


def omega3(st, phi_deg: np.ndarray) -> np.ndarray:
    """ω3 = dθ3/dφ·ω1 by central differences of the closed-form position (h = 1e-4°)."""
    near = solve(st.mech, st.structure, phi_deg).bodies["AB"].at(st.mech.links["AB"].local["B"])[0]
    h = 1e-4
    up, down = rocker_angle(phi_deg + h, near), rocker_angle(phi_deg - h, near)
    return np.angle(np.exp(1j * (up - down))) / math.radians(2 * h) * W1


PHI = np.array([15.0, 70.0, 130.0, 200.0, 260.0, 330.0])


@pytest.mark.parametrize("link", ["3", '"O2B"'])
def test_a_moment_opposing_the_rocker_needs_m_times_omega3_over_omega1(link):
    """No masses: the crank balances M·|ω3|/ω1 (power balance), group by group, on the force plans
    and on the lever alike; the dynamics reduces it to M*_c = M·|ω3|/|ω1|."""
    st = scene_study(scene(link))
    w3 = omega3(st, PHI)
    ks = analyse(st, PHI)
    assert np.allclose(ks.balancing, M * np.abs(w3) / W1, rtol=1e-7)
    moment = [ld for ld in ks.loads if ld.name == "M_3"]
    assert len(moment) == 1 and np.allclose(moment[0].couple, -M * np.sign(w3))
    for k, phi in enumerate(PHI):
        fp = construct(st, phi, precision=0)
        assert fp.balancing == pytest.approx(ks.balancing[k], rel=1e-9)
        assert fp.lever.balancing == pytest.approx(ks.balancing[k], rel=1e-9)
    kin = solve(st.mech, st.structure, PHI)
    assert np.allclose(resistance(st, kin, np.ones(PHI.shape, bool)), M * np.abs(w3) / W1, rtol=1e-7)


def test_a_moment_of_a_fixed_sense_is_resisted_and_driven_in_turn():
    """"ccw": M3 = +M at every position — the crank balances −M·ω3/ω1, resisting where the rocker
    turns clockwise and driving where it turns counter-clockwise."""
    st = scene_study(scene(direction="ccw"))
    w3 = omega3(st, PHI)
    assert np.any(w3 > 0) and np.any(w3 < 0)
    ks = analyse(st, PHI)
    assert np.allclose(ks.balancing, -M * w3 / W1, rtol=1e-7)


def test_the_force_sheet_draws_and_names_the_moment(tmp_path, capsys):
    """The scheme and the group carry M₃'s arc, the loads table lists it in N·m, the chart is the
    resistance moment's; the dynamics takes it."""
    path = tmp_path / "m.toml"
    path.write_text(scene() + "[loads]\nmass_per_length = 30\n", encoding="utf-8")
    assert main(["forces", str(path)]) == 0
    out = capsys.readouterr().out
    row = next(line for line in out.splitlines() if line.split()[:2] == ["M₃", "O2B"])
    assert "Н·м" in row
    svg = tmp_path / "f.svg"
    assert main(["sheet", str(path), "--sheet", "forces", "-o", str(svg)]) == 0
    text = svg.read_text(encoding="utf-8")
    assert "моменту корисного опору" in text
    capsys.readouterr()
    assert main(["dynamics", str(path), "--json"]) == 0


@pytest.mark.parametrize("bad, words", [
    ('link = 7', "moment[0].link: no link named or numbered '7'"),
    ('direction = "up"', 'moment[0].direction: must be "oppose", "ccw" or "cw"'),
])
def test_a_bad_moment_is_refused_in_one_line(tmp_path, capsys, bad, words):
    key = bad.split(" = ")[0]            # "link" and "direction" are the moment's lines alone here
    text = "\n".join(bad if line.startswith(key + " = ") else line for line in scene().splitlines())
    path = tmp_path / "bad.toml"
    path.write_text(text, encoding="utf-8")
    assert main(["forces", str(path), "--lang", "en"]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and words in err, err


def test_the_closed_form_rocker_angle_agrees_with_the_law_of_cosines():
    """The test's own truth checked once: at φ = 0 the angle at O2 between O2→A and O2→B is γ of
    the triangle O2AB."""
    st = scene_study(scene())
    phi = np.array([0.0])
    theta = rocker_angle(phi, solve(st.mech, st.structure, phi).bodies["AB"].at(st.mech.links["AB"].local["B"])[0])
    a = complex(R, 0)
    d = abs(O2 - a)
    gamma = math.acos((d ** 2 + L3 ** 2 - L2 ** 2) / (2 * d * L3))     # at O2 between O2→A and O2→B
    base = cmath.phase(a - O2)
    assert min(abs(cmath.phase(cmath.exp(1j * (theta[0] - base - s * gamma)))) for s in (1, -1)) < 1e-12


@pytest.mark.parametrize("sense", [1.0, -1.0])
def test_the_json_balancing_force_is_the_moment_over_the_crank_for_either_sense(sense):
    """P_b = M_b / l_OA (its moment on the crank in M_b's sense) from the lever and from the exact
    analysis alike — a clockwise crank's lever gave −4591 N against +4601 N."""
    from graphplan.report.forces import forces_json
    turn = 'direction = "cw"\n' if sense < 0 else ""
    st = scene_study(scene().replace(f"omega = {W1}\n", f"omega = {W1}\n{turn}"))
    assert math.copysign(1.0, st.mech.omega1) == sense
    doc = forces_json(construct(st, 130.0, precision=0))
    assert doc["balancing_force"]["analytic"] == pytest.approx(doc["balancing_moment"]["analytic"] / R, rel=1e-9)
    assert doc["balancing_force"]["lever"] == pytest.approx(doc["balancing_force"]["analytic"], rel=1e-9)
