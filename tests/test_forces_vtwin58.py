"""Stop 58: the lead's V-twin compressor (LINK58): one crank, two groups II(2-3) and II(4-5) pinned
at the crank pin A, pistons B and C on guides through O1 at 60° and 120°, 900 N gas forces on each
piston's OWN working stroke. Checked against an independent numpy model of the mechanism (closed-form
slider positions, central differences for velocities and accelerations, virtual power for M_b) —
nothing of graphplan's but the scene's numbers."""
import numpy as np
import pytest

from conftest import scene_study

R, L, Q, K_I, G, P = 0.05, 0.2, 20.0, 0.1, 9.81, 900.0
OMEGA = -720 * 2 * np.pi / 60                 # clockwise
GUIDES = {"B": 60.0, "C": 120.0}


def _pos(phi):
    a = R * np.exp(1j * phi)
    out = {"A": a}
    for name, ang in GUIDES.items():
        u = np.exp(1j * np.radians(ang))
        rel = a * np.conj(u)
        out[name] = (rel.real + np.sqrt(L * L - rel.imag ** 2)) * u
        out["S" + name] = a + 0.35 * (out[name] - a)
        out["th" + name] = np.angle(out[name] - a)
    return out


def _motion(phi, h=1e-4):
    p0, pp, pm = _pos(phi), _pos(phi + h), _pos(phi - h)
    v = {k: (pp[k] - pm[k]) / (2 * h) * OMEGA for k in p0}
    a = {k: (pp[k] - 2 * p0[k] + pm[k]) / h ** 2 * OMEGA ** 2 for k in p0}
    return v, a


def _dot(a, b):
    return (a * np.conj(b)).real


def _on_working_stroke(name, v):
    """The scene's default "slow" stroke of a centred slider is a tie (180° each); the program takes
    the one from the outer dead centre, the piston moving in towards O1 — each piston on its own."""
    return _dot(v[name], np.exp(1j * np.radians(GUIDES[name]))) < 0


def _balancing_moment(phi_deg):
    """M_b (+ counter-clockwise) from M_b·ω1 + Σ F·v + Σ M·ω = 0."""
    v, a = _motion(np.radians(phi_deg))
    m_rod, m_piston = Q * L, 2.5
    i_rod = K_I * m_rod * L * L
    power = 0.0
    for s, m in (("SB", m_rod), ("SC", m_rod), ("B", m_piston), ("C", m_piston)):
        power += _dot(-1j * m * G - m * a[s], v[s])
    for th in ("thB", "thC"):
        power += -i_rod * a[th] * v[th]
    for name in GUIDES:
        if _on_working_stroke(name, v):
            power += -P * abs(v[name])
    return -power / OMEGA


@pytest.fixture(scope="module")
def link58():
    from review_scenes import LINK58
    return scene_study(LINK58)


def test_each_piston_takes_its_gas_force_on_its_own_working_stroke(link58):
    """P_C followed B's strokes (on from B's dead centre at crank 60°, not C's at 120°): over the
    turn each force is 900 N exactly where its own piston moves in, nil elsewhere."""
    from graphplan.exact.kinetostatics import analyse
    phi = np.arange(0.0, 360.0, 5.0) + 2.5          # off the dead centres (60°, 120°, 240°, 300°)
    ks = analyse(link58, phi)
    for name in GUIDES:
        got = np.abs(next(ld.force for ld in ks.loads if ld.name == f"P_{name}"))
        want = np.array([P if _on_working_stroke(name, _motion(np.radians(f))[0]) else 0.0 for f in phi])
        assert np.allclose(got, want), (name, phi[~np.isclose(got, want)])


def test_the_balancing_moment_agrees_with_virtual_power_over_the_turn(link58):
    """M_b at the force position (crank 15°: both pistons loaded, −83.32 N·m) and round the turn."""
    from graphplan.exact.kinetostatics import analyse, at_scene_angle
    phi0 = at_scene_angle(link58)
    assert abs(phi0 - 15.0) < 1e-9
    phi = np.r_[phi0, np.arange(0.0, 360.0, 10.0) + 2.5]
    got = analyse(link58, phi).balancing
    want = np.array([_balancing_moment(f) for f in phi])
    assert abs(want[0] - (-83.32)) < 0.01
    assert np.allclose(got, want, rtol=1e-5, atol=1e-4), np.c_[phi, got, want]


def test_the_crank_group_carries_both_rods_reactions(link58):
    """I(0-1) is loaded by R21 and R41 (both rods at the pin A): R01 closes G1 + R21 + R41."""
    from graphplan.exact.kinetostatics import analyse, at_scene_angle
    ks = analyse(link58, [at_scene_angle(link58)])
    crank = next(g for g in ks.groups if g.label == "I(0-1)")
    r = {k: complex(np.atleast_1d(v.force)[0]) for k, v in ks.reactions.items()}
    assert crank.reactions == ("R01",)
    # action and reaction at A: R21 = −R12, R41 = −R14; the crank's balance with its weight
    total = -r["R12"] - r["R14"] + r["R01"] - 1j * Q * R * G
    assert abs(total) < 1e-6 * abs(r["R01"])


def test_one_resistance_diagram_per_piston_each_over_its_own_path(link58):
    """The resistance diagram drew P_B only though C carries 900 N too: a second diagram draws P_C
    over s_C — its stroke 2r = 0.1 m out and back, 900 N on C's working stroke (positions 10 … 4),
    nil on its idle stroke."""
    from graphplan.drawing.charts import other_pistons, resistance_record, turn
    t = turn(link58, 360)
    assert other_pistons(t) == ["C"]
    for point, name in ((None, "B"), ("C", "C")):
        rec = resistance_record(t, lang="uk", point=point)
        curve = next(q for q in rec.items if q.kind == "polyline")
        xs = np.array([x for x, _ in curve.points]) * rec.scales["mu_s"]
        ys = np.array([y for _, y in curve.points]) * rec.scales["mu_P"]
        assert abs(xs.max() - 4 * R) < 1e-6 and abs(ys.max() - P) < 1e-6 and ys.min() == 0.0
        assert f"P_{{{name}}}, Н" in [q.text for q in rec.items if q.kind == "text"]
        # the loaded share of the abscissa is one stroke: 2r of the 4r out and back
        loaded = sum(b[0] - a[0] for a, b in zip(curve.points, curve.points[1:]) if a[1] > 0 and b[1] > 0)
        assert abs(loaded * rec.scales["mu_s"] - 2 * R) < 1e-3
