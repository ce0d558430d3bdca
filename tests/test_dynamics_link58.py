"""Stop 58: the lead's V-twin compressor (LINK58: one crank O1A = 50 mm, two rods AB = AC = 200 mm pinned at
the crank pin, pistons B and C on guides through O1 at 60° and 120°, 720 rpm clockwise, 900 N on each
piston over its own compression stroke — outwards, to its cylinder head, working_stroke = "to_max" —, q = 20 kg/m, I_S = 0.1·m·l², the pistons 2.5 kg, δ = 1/40,
a 1500-rpm motor). The truth here is this file's own: the V's closed-form kinematics (each piston on its
line, s = r·cos(φ − α) + √(l² − r²·sin²(φ − α))), velocities by five-point differences, the reduction by
the kinetic energy and by the power, the work by Simpson's rule split at the load's breaks, the steady
states by a fixed-step RK4 of dT/dφ = M*_d(ω) − M*_c(φ) on that closed form — nothing of graphplan's
kinematics, splines or integrator.

Also the motor's shooting (exact.dynamics ``_periodic_start``) on LINK57: it settles in a few integrations —
its stop at a step of 1e-12 of ω(0) waited for a lucky jitter of the integrator (rtol 1e-11) and fell back
to the bracketing search, ~20 integrations a steady state (LINK57's analysis: 258 integrations, 6.8 s)."""
from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import brentq, fsolve

from conftest import scene_study

sys.path.insert(0, str(Path(__file__).parent))
from review_scenes import LINK58  # noqa: E402

R, L, S = 0.05, 0.2, 0.35            # crank, rods, the rods' centres of mass from A
Q, K, G = 20.0, 0.1, 9.81
M_ROD, M_PISTON, M_CRANK = Q * L, 2.5, Q * R
I_ROD, I_CRANK = K * M_ROD * L * L, K * M_CRANK * R * R
F = 900.0
W1 = 720 * math.pi / 30
DELTA = 1 / 40
PHI0 = math.radians(240)              # position 0: B at its inner dead centre (the crank pointing away from B's guide,
                                      # where B's compression, the working stroke "to_max", starts)
GUIDES = (math.radians(60), math.radians(120))


def _geometry(turn: np.ndarray) -> dict[str, np.ndarray]:
    """Points (complex, m) and the rods' angles at crank turns ``turn`` (rad, clockwise from position 0)."""
    A = R * np.exp(1j * (PHI0 - turn))
    out = {}
    for name, alpha in zip("BC", GUIDES):
        u = np.exp(1j * alpha)
        along, off = (A * np.conj(u)).real, (A * np.conj(u)).imag
        P = (along + np.sqrt(L * L - off * off)) * u
        out[name], out["S" + name], out["psi" + name] = P, A + S * (P - A), np.angle(P - A)
    return out


def _rates(turn: np.ndarray, h: float = 1e-4) -> dict[str, np.ndarray]:
    """d/dφ of every point and angle (the velocities over ω1), five-point differences."""
    g = [_geometry(turn + k * h) for k in (-2, -1, 1, 2)]
    return {key: (g[0][key] - 8 * g[1][key] + 8 * g[2][key] - g[3][key]) / (12 * h) for key in g[0]}


def _reduced(turn: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """I*_m and M*_c (+ resisting) at ``turn``: each piston's force acts while that piston moves outwards
    along its own guide (its compression), against its motion."""
    d = _rates(turn)
    inertia = (I_CRANK + M_ROD * (np.abs(d["SB"]) ** 2 + np.abs(d["SC"]) ** 2) + I_ROD * (d["psiB"] ** 2 + d["psiC"] ** 2)
               + M_PISTON * (np.abs(d["B"]) ** 2 + np.abs(d["C"]) ** 2))
    gravity = -G * (M_ROD * (d["SB"].imag + d["SC"].imag) + M_PISTON * (d["B"].imag + d["C"].imag))
    forces = 0.0
    for name, alpha in zip("BC", GUIDES):
        out = (d[name] * np.exp(-1j * alpha)).real             # d(s)/dφ along the guide, + outwards
        forces = forces + np.where(out > 0, -F * np.abs(d[name]), 0.0)
    return inertia, -(gravity + forces)


# the load's breaks: B's dead centres (turn 0°, 180°: its force switches) and C's (120°, 300°: the crank along
# C's guide at 120° and away from it at 300°, 60° of clockwise turn after B's)
BREAKS = np.radians([0.0, 120.0, 180.0, 300.0, 360.0])
EPS = 1e-9


@pytest.fixture(scope="module")
def study58():
    return scene_study(LINK58)


def test_the_v_twins_reduced_inertia_and_moment_at_the_positions(study58):
    from graphplan.exact.dynamics import reduce
    turn = np.radians(np.arange(12) * 30.0) + EPS       # just past each position (position 6: B's stroke ends)
    got = reduce(study58, turn)
    inertia, moment = _reduced(turn)
    assert np.allclose(got.inertia, inertia, rtol=1e-8, atol=1e-12)
    assert np.allclose(got.moment, moment, rtol=1e-7, atol=1e-7)
    # the model's own numbers, as the sheet's Table 1 prints them: position 0 (B at its inner dead centre)
    # I* = 0.01720 kg·m²; both pistons compress over positions 1–4, the largest M*_c at position 2
    assert got.inertia[0] == pytest.approx(0.017200, abs=5e-6)
    assert int(np.argmax(got.moment)) == 2 and got.moment[2] == pytest.approx(83.362, abs=1e-3)


def _simpson(f, a: float, b: float, n: int = 400) -> float:
    x = np.linspace(a, b, 2 * n + 1)
    y = f(x)
    return float((b - a) / (6 * n) * (y[0] + y[-1] + 4 * y[1:-1:2].sum() + 2 * y[2:-1:2].sum()))


def test_the_v_twins_work_and_driving_moment(study58):
    from graphplan.exact.dynamics import cycle
    work = sum(_simpson(lambda t: _reduced(t)[1], a + EPS, b - EPS) for a, b in zip(BREAKS[:-1], BREAKS[1:]))
    c = cycle(study58)
    assert c.work == pytest.approx(work, rel=1e-6)
    assert c.driving == pytest.approx(work / (2 * math.pi), rel=1e-6)


def _grid(step_deg: float = 0.05):
    """The turn on a grid that has every break on it, I*_m there and M*_c just after and just before each
    node (the load jumps at 180°: a step takes its own piece's ends)."""
    n = int(round(360 / step_deg))
    turn = np.linspace(0.0, 2 * math.pi, n + 1)
    inertia, after = _reduced(turn + EPS)
    before = _reduced(turn - EPS)[1]
    return turn, inertia, after, before


@pytest.fixture(scope="module")
def steady58(study58):
    from graphplan.exact.dynamics import analyse
    return analyse(study58)


def _rk4_return(turn, inertia, after, before, md, const: float, w0: float) -> np.ndarray:
    """ω along the turn from ω(0) = w0: RK4 of dT/dφ = M*_d(ω) − M*_c(φ) on the grid's steps, each step's
    middle from the grid of half steps (so the grid is taken two samples a step)."""
    t = 0.5 * (inertia[0] + const) * w0 * w0
    out = [w0]
    for k in range(0, len(turn) - 2, 2):
        h = turn[k + 2] - turn[k]
        i0, i1, i2 = inertia[k] + const, inertia[k + 1] + const, inertia[k + 2] + const
        m0, m1, m2 = after[k], after[k + 1], before[k + 2]
        k1 = md(math.sqrt(2 * t / i0)) - m0
        k2 = md(math.sqrt(2 * (t + 0.5 * h * k1) / i1)) - m1
        k3 = md(math.sqrt(2 * (t + 0.5 * h * k2) / i1)) - m1
        k4 = md(math.sqrt(2 * (t + h * k3) / i2)) - m2
        t += h * (k1 + 2 * k2 + 2 * k3 + k4) / 6
        out.append(math.sqrt(2 * t / i2))
    return np.array(out)


@pytest.mark.slow                     # the closed form on 14 400 points and ~60 RK4 turns: ~15 s
def test_the_v_twins_flywheels_and_steady_states_by_an_independent_integration(steady58):
    dyn = steady58
    turn, inertia, after, before = _grid(0.025)
    # ΔT(φ) by the trapezoid on the steps (the jump at 180° lies on the grid: each step its own ends)
    work = np.concatenate([[0.0], np.cumsum(0.5 * (after[:-1] + before[1:]) * np.diff(turn))])
    energy = work[-1] / (2 * math.pi) * turn - work
    assert dyn.cycle.work == pytest.approx(work[-1], rel=1e-5)

    def classical(x):
        j, t0 = x
        w = np.sqrt(2 * (t0 + energy) / (inertia + j))
        return [(w.max() - w.min()) / W1 - DELTA, 0.5 * (w.max() + w.min()) / W1 - 1.0]
    j, t0 = fsolve(classical, [0.5, 0.25 * W1 * W1], xtol=1e-12)
    assert dyn.flywheel_total == pytest.approx(j, rel=2e-4)                  # J = 0.7100 kg·m²
    w = np.sqrt(2 * (t0 + energy) / (inertia + j))
    assert dyn.motion.omega_max == pytest.approx(w.max(), rel=1e-5)
    assert dyn.motion.omega_min == pytest.approx(w.min(), rel=1e-5)
    # the motor: 4АМ132S4 by the power rule (max M*_c·ω1/η = 6.91 kW → 7.5 kW), its line through the reducer
    dr = dyn.drive
    assert float(np.max(after)) * W1 / dr.efficiency / 1000 == pytest.approx(dr.power_needed_kW, rel=1e-5)
    a, b = dr.motor.line
    k = dr.ratio * dr.efficiency

    def md(omega: float) -> float:
        return k * (a * dr.ratio * omega + b)
    rotor = dr.rotor_reduced + dr.reducer_reduced

    def steady(fl: float) -> np.ndarray:
        w0 = brentq(lambda w: _rk4_return(turn, inertia, after, before, md, rotor + fl, w)[-1] - w,
                    0.9 * dr.omega_sync * 0.95, dr.omega_sync, xtol=1e-11)
        return _rk4_return(turn, inertia, after, before, md, rotor + fl, w0)

    def delta(fl: float) -> float:
        w = steady(fl)
        return (w.max() - w.min()) / (0.5 * (w.max() + w.min()))
    fl = brentq(lambda x: delta(x) - DELTA, 0.5 * dyn.motor_flywheel, 2.0 * dyn.motor_flywheel, xtol=1e-7)
    assert dyn.motor_flywheel == pytest.approx(fl, rel=2e-4)                 # I_fl = 0.2846 kg·m²
    w = steady(dyn.motor_flywheel)
    assert dyn.motor_motion.omega_max == pytest.approx(w.max(), rel=1e-5)   # 77.94 rad/s
    assert dyn.motor_motion.omega_min == pytest.approx(w.min(), rel=1e-5)   # 76.02 rad/s


def test_the_motors_shooting_settles_in_a_few_integrations():
    """Newton's shooting (LINK57's six-bar, where it mattered) at flywheels from half to 1.5 times the motor's
    (1.73 kg·m²), each from the last one's ω(0): each settles (not None, so no bracketing) in at most 3
    integrations — with the stop at 1e-12 of ω(0) the last two jittered 12 times and gave up — and its
    steady state closes to 1e-10."""
    import graphplan.exact.dynamics as dy
    from review_scenes import LINK_DYN57
    st, _ = dy.bounded(scene_study(LINK_DYN57))
    c = dy.cycle(st)
    dr = dy.drive(st, c)
    count = {"n": 0}
    real = dy._integrate

    def counted(*args, **kw):
        count["n"] += 1
        return real(*args, **kw)
    guess = 0.99 * dr.omega_sync
    try:
        dy._integrate = counted
        for share in (0.5, 0.75, 1.0, 1.25, 1.5):
            count["n"] = 0
            w0 = dy._periodic_start(c, dr, dr.rotor_reduced + dr.reducer_reduced + 1.73 * share, guess)
            assert w0 is not None and count["n"] <= 3
            guess = w0
    finally:
        dy._integrate = real
    m = dy.motor_motion(c, dr, 1.73 * 1.5, guess)
    assert m.closure < 1e-10
