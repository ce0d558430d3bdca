"""Stop 53: the lead's articulated-rod compressor (LINK53) — the dynamics' numbers against an
independent computation, and the sheet's answer (REFERENCE §9: the course's flywheel is the one read
off Wittenbauer's energy–mass diagram; the motor's run a remark)."""
from __future__ import annotations

import math

import numpy as np
import pytest
from conftest import scene_study
from review_scenes import DYN_OWN53, LINK53

R, L2, L4, W1 = 0.055, 0.22, 0.17, 360 * math.pi / 30
EB = np.array([math.cos(math.pi / 3), math.sin(math.pi / 3)])           # guide b at 60° through O1
EC = np.array([math.cos(2 * math.pi / 3), math.sin(2 * math.pi / 3)])   # guide c at 120°
MASS = {"S1": 3.0, "S2": 2.5, "B": 2.0, "S4": 1.6, "C": 2.0}


def _slide(p: np.ndarray, e: np.ndarray, length: float) -> np.ndarray:
    """The far point of the circle (p, length) on the line t·e through O1 (branch 1)."""
    along, across = p @ e, e[0] * p[1] - e[1] * p[0]
    return (along + math.sqrt(length * length - across * across)) * e


def _points(phi: float) -> dict:
    """A at φ, B on guide b, the lug K at [0.045, 0.04] in AB's frame (across: 90° ccw), C on guide c."""
    a = R * np.array([math.cos(phi), math.sin(phi)])
    b = _slide(a, EB, L2)
    u = (b - a) / L2
    k = a + 0.045 * u + 0.04 * np.array([-u[1], u[0]])
    c = _slide(k, EC, L4)
    return {"S1": 0.3 * a, "S2": a + 0.3 * (b - a), "B": b, "S4": (k + c) / 2, "C": c,
            "t2": math.atan2(u[1], u[0]), "t4": math.atan2(*(c - k)[::-1])}


def _reduced(phi: float) -> tuple[float, float]:
    """I* = Σ(m·v_S² + I_S·ω²)/ω1² and M*_c = −(ΣG·v + F·v_B)/ω1 by central differences, the crank
    clockwise (dφ/dt = −ω1); 1800 N against B only while B moves away from O1."""
    h = 1e-6
    p0, p1 = _points(phi - h), _points(phi + h)
    v = {key: -W1 * (np.asarray(p1[key]) - np.asarray(p0[key])) / (2 * h) for key in MASS}
    w2, w4 = (-W1 * math.remainder(p1[t] - p0[t], 2 * math.pi) / (2 * h) for t in ("t2", "t4"))
    kinetic = sum(m * v[key] @ v[key] for key, m in MASS.items()) + 0.004 * W1 ** 2 + 0.012 * w2 ** 2 + 0.005 * w4 ** 2
    power = -9.81 * sum(m * v[key][1] for key, m in MASS.items())
    vb = v["B"] @ EB
    power -= 1800.0 * vb if vb > 0 else 0.0
    return kinetic / W1 ** 2, -power / W1


@pytest.fixture(scope="module")
def dyn():
    from graphplan.exact.dynamics import analyse
    return analyse(scene_study(LINK53), None)


def test_the_reduced_inertia_moment_and_flywheel_equal_an_independent_computation(dyn):
    """I*, M*_c at the 12 positions (from the outer dead centre, 60°, clockwise), M*_d = A_c/2π, the
    exact flywheel for a constant M*_d (δ = 0.04 about ω_m = πn/30) and the motor's own δ_дв
    (M = i·η·(A·i·ω + B), 4АМ132S6, Euler over a fine grid) against the program's."""
    from scipy.optimize import brentq
    s = dyn.cycle.samples
    for j in np.linspace(0, len(s.turn) - 1, 13).astype(int):      # the samples' own crank turns
        i_star, m_c = _reduced(math.radians(60) - s.turn[j])
        assert s.inertia[j] == pytest.approx(i_star, rel=1e-5)
        assert s.moment[j] == pytest.approx(m_c, abs=1e-3)
    turn = np.linspace(0.0, 2 * math.pi, 3601)
    inertia, moment = np.array([_reduced(math.radians(60) - t) for t in turn]).T
    work = np.concatenate([[0.0], np.cumsum((moment[1:] + moment[:-1]) / 2 * np.diff(turn))])
    assert work[-1] == pytest.approx(dyn.cycle.work, rel=1e-4)
    energy = work[-1] / (2 * math.pi) * turn - work
    rotor = dyn.drive.rotor_reduced
    assert rotor == pytest.approx(0.04 * (967 / 360) ** 2, rel=1e-9)

    def speed(total: float) -> np.ndarray:        # ω(φ) with the mean (max + min)/2 = ω1
        def w(t0: float) -> np.ndarray:
            return np.sqrt(2 * (t0 + energy) / (inertia + total))
        t0 = brentq(lambda t: (w(t).max() + w(t).min()) / 2 - W1, -energy.min() + 1e-9, 1e6)
        return w(t0)
    total = brentq(lambda j: np.ptp(speed(j)) / W1 - 0.04, 0.3, 50.0)
    assert dyn.flywheel_total == pytest.approx(total, rel=2e-3)
    a, b = -15.716833, 1645.8629
    i, T, h, ws = 967 / 360, 0.5 * (inertia[0] + rotor) * W1 ** 2, turn[1] - turn[0], []
    for _ in range(3):
        ws = []
        for k in range(len(turn) - 1):
            w = math.sqrt(2 * T / (inertia[k] + rotor))
            ws.append(w)
            T += h * (i * 0.9 * (a * i * w + b) - moment[k])
    ws = np.array(ws)
    assert dyn.motor_flywheel == 0 and np.ptp(ws) / ((ws.max() + ws.min()) / 2) == pytest.approx(0.02823, rel=1e-2)


@pytest.mark.parametrize("lang", ["uk", "en"])
def test_the_sheets_answer_is_the_wittenbauer_flywheel_and_the_motor_a_remark(dyn, lang):
    """The answer printed is I_fl = μ_T·|kl|/(ω_m²·δ) − I_рот·i² as drawn (REFERENCE §9), the exact one
    beside it; the motor's δ_дв < δ only after «примітка»/«remark»."""
    from graphplan.graphic.flywheel import construct
    from graphplan.report.dynamics import design_note, dynamics_json
    from graphplan.util.markup import plain
    doc = dynamics_json(construct(dyn, 12, 0.5))
    fw = doc["flywheel"]
    read = doc["scales"]["mu_T"] * fw["kl_mm"] / (doc["omega_mean"] ** 2 * doc["delta"]) - fw["rotor_reduced"]
    assert fw["graphical"] == pytest.approx(read, rel=5e-4)
    note = plain(design_note(doc, lang)).replace("\u00a0", " ")
    value = f"{fw['graphical']:.3f}".replace(".", "," if lang == "uk" else ".")
    head, _, tail = note.partition("примітка: " if lang == "uk" else "remark: ")
    assert value in head and ("Віттенбауера" in head if lang == "uk" else "Wittenbauer" in head), note
    assert "0,0282 < 0,04" in tail if lang == "uk" else "0.0282 < 0.04" in tail


# -- helper dyn53's own: a rocking screen with a two-stage reducer (DYN_OWN53) ----------------------------

@pytest.fixture(scope="module")
def screen():
    from graphplan.exact.dynamics import analyse
    return analyse(scene_study(DYN_OWN53), None)


def test_the_screens_reducer_and_rotor_are_subtracted_as_seed_003_reduces_them(screen):
    """Seed 003 eq. 4: I*_ред = I_1p·i² + I_2p·(i/i1)² + I_3p with i = n_н/n_1 = 698/180 (4АМ100L8's
    rated speed) and i1 = 3.2; the rotor I_рот·i² (0.0130 kg·m²); the classical J less both is the
    flywheel — and the screen resists on both strokes: M*_c = 600·|v_E|/ω1 + gravity's, ≥ 0 but for
    gravity (|M*_c| under 2 N·m where the screen stands still)."""
    dyn = screen
    i = 698 / 180
    assert dyn.drive.ratio == pytest.approx(i, rel=1e-9)
    assert dyn.drive.reducer_reduced == pytest.approx(0.0006 * i * i + 0.004 * (i / 3.2) ** 2 + 0.06, rel=1e-9)
    assert dyn.drive.rotor_reduced == pytest.approx(0.013 * i * i, rel=1e-9)
    assert min(dyn.cycle.samples.moment) > -2.0


def test_the_screens_small_energy_change_is_drawn_at_its_own_scale(screen):
    """ΔT spans ~31 J against A_c = 252 J: read between the work diagrams at μ_A = μ_M·μ_φ·H it would be
    a flat curve (< 30 mm) and |kl| short; the draftsman redraws it at its own μ_T (REFERENCE §9 names μ_T
    apart: tg ψ = μ_I·ω_m²(1 ± δ)/(2μ_T), I_fl = μ_T·|kl|/(ω_m²·δ)), a value of the series, finer than
    μ_A, the finest that draws the exact span no higher than 60 mm (so ≥ 30: the series steps by ≤ ×2);
    the flywheel read with it within the lab's 5 %."""
    from graphplan.graphic.flywheel import construct
    from graphplan.graphic.scales import SERIES
    f = construct(screen, 12, 0.5)
    phi = np.linspace(0.0, 2 * math.pi, 4001)
    span = float(np.ptp(screen.cycle.driving * phi - screen.cycle.resistance_work(phi)))
    assert f.mu_A == pytest.approx(f.mu_M * f.mu_phi * f.H)
    assert span / f.mu_A < 30.0 and f.mu_T < f.mu_A
    mantissa = f.mu_T / 10 ** math.floor(math.log10(f.mu_T) + 1e-12)
    assert any(abs(mantissa - m) < 1e-9 for m in SERIES), f.mu_T
    assert 30.0 <= span / f.mu_T <= 60.0 and abs(float(np.ptp(f.dT)) - span / f.mu_T) <= 0.06 * span / f.mu_T
    wm2, d = screen.omega_mean ** 2, screen.delta
    assert f.tangent["s_max"] == pytest.approx(f.mu_I * wm2 * (1 + d) / (2 * f.mu_T))
    assert f.tangent["s_min"] == pytest.approx(f.mu_I * wm2 * (1 - d) / (2 * f.mu_T))
    graphical = f.mu_T * abs(f.kl) / (wm2 * d) - screen.constant
    assert abs(graphical - screen.flywheel) <= 0.05 * screen.flywheel
