"""Stop 59, helper dyn59.

1. LINK59 (the lead's: a crank-rocker four-bar O1A–AB–O2B whose rocker carries a slot; a block C in the slot
   pinned to a ram on a horizontal guide 0.22 m above the pivots — a PRP group on a ROTATING link; 95 rpm
   clockwise, 1500 N on the ram's working stroke, q = 25 kg/m, I_S = 0.1·m·l², the block 1.5 kg, the ram 18 kg,
   δ = 0.033, a 1000-rpm motor). The truth here is this file's own: the closed-form positions (B on the circles'
   intersection, C where the rocker's line meets y = 0.22), velocities by five-point differences, I* by the
   kinetic energy, M*_c by the power, A_c by the trapezoid split at the ram's dead centre, and the flywheel by
   the energy method: J such that ω = √(2(T0 + ΔT)/(I* + J)) swings by δ about ω_m — nothing of graphplan's
   kinematics, splines or integrator.
2. ΔT(φ) and the energy–mass diagram at ΔT's own finer scale where the sheet has room (sheets.dynamics
   ``finer_energy``): the agitator (review 58 (b)) drew ΔT 37.5 mm tall beside ~340 × 150 mm of bare paper;
   now 60 mm at μ_T = 0.25 J/mm, |kl| 40.5 → 64 mm, the flywheel +1.63 % → +0.34 %.
"""
from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import brentq, minimize_scalar

from conftest import scene_study

sys.path.insert(0, str(Path(__file__).parent))
from review_scenes import AGITATOR_SCALES58, LINK59  # noqa: E402

O2 = 0.24 + 0j
R, L2, L3, Y_GUIDE = 0.07, 0.26, 0.18, 0.22
Q, K, G = 25.0, 0.1, 9.81
M1, M2, M3, M4, M5 = Q * R, Q * L2, Q * L3, 1.5, 18.0
I1, I2, I3 = K * M1 * R * R, K * M2 * L2 * L2, K * M3 * L3 * L3
F = 1500.0
W1 = 95 * math.pi / 30
DELTA = 0.033



def energy_flywheel(energy, inertia, w1: float, delta: float, bracket: tuple[float, float], most_T0: float) -> float:
    """The energy method, independent of the program: ω = √(2(T0 + ΔT)/(I* + J)) over the turn; T0 found so that
    ω's mean (max + min)/2 is ω1, then J so that (max − min)/ω1 is δ (brentq on both; J within ``bracket``)."""
    def unevenness(J: float) -> float:
        def mean_gap(T0: float) -> float:
            w = np.sqrt(2 * (T0 + energy) / (inertia + J))
            return (w.max() + w.min()) / 2 - w1
        T0 = brentq(mean_gap, -energy.min() + 1e-12, most_T0)
        w = np.sqrt(2 * (T0 + energy) / (inertia + J))
        return (w.max() - w.min()) / w1
    return brentq(lambda j: unevenness(j) - delta, *bracket, xtol=1e-10)


def motor_steady_speeds(turn, inertia, moment, J_m: float, i: float, eta: float, rpm_sync: float, rpm_rated: float,
                        power_W: float, w1: float) -> np.ndarray:
    """The machine on its motor's line, independent of the program: M*_d(ω) = i·η·(A·i·ω + B), the line through
    (ω_s, 0) and (ω_n, M_n = P_n/ω_n) of the motor's shaft; the midpoint rule on every 4th point of ``turn`` over turns until periodic
    (T from (I*_0 + J_m)·ω1²/2); ω at the grid's points of the last turn."""
    ws, wn = rpm_sync * math.pi / 30, rpm_rated * math.pi / 30
    a = power_W / wn / (wn - ws)
    b = -a * ws
    grid = turn[::4]
    Ig, Mg = np.interp(grid, turn, inertia), np.interp(grid, turn, moment)
    T = 0.5 * (Ig[0] + J_m) * w1 ** 2
    for _ in range(100):
        T_start, speeds = T, []
        for j in range(len(grid) - 1):
            h = grid[j + 1] - grid[j]
            w = math.sqrt(2 * T / (Ig[j] + J_m))
            speeds.append(w)
            half = T + 0.5 * h * (i * eta * (a * i * w + b) - Mg[j])
            wh = math.sqrt(2 * half / ((Ig[j] + Ig[j + 1]) / 2 + J_m))
            T += h * (i * eta * (a * i * wh + b) - (Mg[j] + Mg[j + 1]) / 2)
        if abs(T - T_start) < 1e-10 * T:
            break
    return np.array(speeds)

def _geometry(th: np.ndarray) -> dict[str, np.ndarray]:
    """Points (complex, m) and angles at the crank's angles ``th`` from the x axis (the upper assembly, B = 1)."""
    A = R * np.exp(1j * th)
    d = O2 - A
    D = np.abs(d)
    a = (L2 * L2 - L3 * L3 + D * D) / (2 * D)
    B = A + d / D * (a + 1j * np.sqrt(L2 * L2 - a * a))
    psi = np.angle(B - O2)
    C = O2 + Y_GUIDE / np.sin(psi) * np.exp(1j * psi)
    return {"B": B, "C": C, "S2": (A + B) / 2, "S3": O2 + (B - O2) / 2, "psi2": np.angle(B - A), "psi3": psi}


def _rates(th: np.ndarray, h: float = 1e-4) -> dict[str, np.ndarray]:
    g = [_geometry(th + k * h) for k in (-2, -1, 1, 2)]
    return {key: (g[0][key] - 8 * g[1][key] + 8 * g[2][key] - g[3][key]) / (12 * h) for key in g[0]}


def _extremes() -> tuple[float, float]:
    """The crank's angles at the ram's extremes (x_C largest, smallest)."""
    th = np.linspace(0.0, 2 * math.pi, 7201)
    x = _geometry(th)["C"].real
    out = []
    for sign, k in ((-1.0, int(np.argmax(x))), (1.0, int(np.argmin(x)))):
        got = minimize_scalar(lambda t: sign * float(_geometry(np.array([t]))["C"].real[0]),
                              bounds=(th[k] - 0.002, th[k] + 0.002), method="bounded", options={"xatol": 1e-10})
        out.append(float(got.x))
    return out[0], out[1]


def _reduced(turn: np.ndarray, th0: float, working: float) -> tuple[np.ndarray, np.ndarray]:
    """I*_m and M*_c (resisting +) at crank turns ``turn`` clockwise from position 0 (crank angle ``th0``); the
    1500 N against the ram's motion while the turn is within the working stroke's ``working`` rad."""
    th = th0 - turn
    v = {k: -x for k, x in _rates(th).items()}          # clockwise: dθ/dt = −ω1, per unit ω1
    inertia = (I1 + M2 * abs(v["S2"]) ** 2 + I2 * v["psi2"] ** 2 + M3 * abs(v["S3"]) ** 2 + I3 * v["psi3"] ** 2
               + M4 * abs(v["C"]) ** 2 + M5 * v["C"].real ** 2)
    gravity = -G * (M2 * v["S2"].imag + M3 * v["S3"].imag + (M4 + M5) * v["C"].imag)
    force = np.where(turn < working, -F * np.abs(v["C"].real), 0.0)
    return inertia, -(gravity + force)


@pytest.fixture(scope="module")
def link59():
    from graphplan.exact.dynamics import analyse
    st = scene_study(LINK59)
    return analyse(st, None)


@pytest.fixture(scope="module")
def truth():
    th_max, th_min = _extremes()
    slow = (th_max - th_min) % (2 * math.pi)              # clockwise from x_C max to x_C min
    th0, working = (th_max, slow) if slow > math.pi else (th_min, 2 * math.pi - slow)   # the slow stroke works
    return th0, working


def test_link59_position_0_starts_the_rams_slow_stroke(link59, truth):
    """Position 0 "working": the crank at the ram's extreme where its slow stroke (195.6° of the turn) begins."""
    from graphplan.exact.positions import crank_angle
    th0, working = truth
    assert math.degrees(working) == pytest.approx(195.61, abs=0.02)
    assert float(crank_angle(link59.study, 0.0)) % 360 == pytest.approx(math.degrees(th0) % 360, abs=1e-3)


@pytest.mark.parametrize("position", [3, 9])
def test_link59_reduced_inertia_and_moment_at_two_positions(link59, truth, position):
    """I*_m (the ram and the block in the slot counted by their velocities, the rocker turning) and M*_c at
    positions 3 (the working stroke) and 9 (the return: the weights only), against the closed form."""
    from graphplan.exact.dynamics import reduce
    th0, working = truth
    turn = np.array([2 * math.pi * position / 12])
    inertia, moment = _reduced(turn, th0, working)
    got = reduce(link59.study, turn)
    assert float(got.inertia[0]) == pytest.approx(float(inertia[0]), rel=1e-7)
    assert float(got.moment[0]) == pytest.approx(float(moment[0]), rel=1e-6, abs=1e-6)
    assert float(got.inertia[0]) > M5 * 0.0 and (position != 3 or float(got.moment[0]) > 100.0)


def test_link59_flywheel_by_the_energy_method(link59, truth):
    """The work A_c = 1500 N × the ram's stroke (the weights give none over a cycle), M*_d = A_c/2π, and the
    constant inertia J = I_rotor·i² + I_fl that keeps δ = 0.033 about ω_m = πn/30 by the energy method
    (ω = √(2(T0 + ΔT)/(I* + J)) on a 1/40° grid, T0 and J by brentq), within 1e-4 of the program's."""
    th0, working = truth
    n = 360 * 40
    turn = np.sort(np.append(np.linspace(0.0, 2 * math.pi, n + 1), [working, working]))
    inertia, moment = _reduced(turn, th0, working)
    k = int(np.searchsorted(turn, working, side="left")) + 1        # the second copy: after the dead centre
    moment[k] = _reduced(np.array([working + 1e-12]), th0, working)[1][0]
    step = np.diff(turn)
    work = np.concatenate([[0.0], np.cumsum(step * (moment[1:] + moment[:-1]) / 2)])
    stroke = float(np.ptp(_geometry(np.linspace(0, 2 * math.pi, 72001))["C"].real))
    assert work[-1] == pytest.approx(F * stroke, rel=1e-5)
    assert link59.cycle.work == pytest.approx(work[-1], rel=1e-5)
    drive = work[-1] / (2 * math.pi)
    assert link59.cycle.driving == pytest.approx(drive, rel=1e-5)
    energy = drive * turn - work

    J = energy_flywheel(energy, inertia, W1, DELTA, (5.0, 1e3), 1e7)
    assert link59.flywheel + link59.constant == pytest.approx(J, rel=1e-4)
    # the 1000-rpm line's 4АМ100L6 (2.2 kW, 949 rpm) for P = max M*_c·ω1/η = 1.72 kW; its rotor reduced
    m = link59.drive.motor
    assert (m.name, m.rpm_sync) == ("4АМ100L6", 1000)
    assert float(np.max(moment)) * W1 / 0.82 / 1000 == pytest.approx(1.7196, abs=2e-4)
    assert link59.constant == pytest.approx(0.013 * (949 / 95) ** 2, rel=1e-6)


# -- ΔT at its own finer scale where the sheet has room ------------------------------------------------------

def _agitator_like(o2: tuple[float, float], crank: float, coupler: float, rocker: float, rpm: float) -> str:
    """A crank-rocker of the agitator's kind (review 58 (b)) with other proportions: generated mechanisms."""
    text = AGITATOR_SCALES58
    for old, new in (("O2 = [0.40, 0.10]", f"O2 = [{o2[0]}, {o2[1]}]"), ("length = 0.10", f"length = {crank}"),
                     ("length = 0.38", f"length = {coupler}"), ("length = 0.26", f"length = {rocker}"),
                     ("rpm = 60", f"rpm = {rpm}")):
        assert old in text
        text = text.replace(old, new, 1)
    return text


SCENES = {"agitator": AGITATOR_SCALES58,
          "agitator_long": _agitator_like((0.45, 0.05), 0.09, 0.42, 0.28, 75),
          "agitator_short": _agitator_like((0.36, 0.12), 0.11, 0.35, 0.25, 50)}


@pytest.mark.slow
@pytest.mark.parametrize("name", sorted(SCENES))
def test_the_energy_scale_fills_its_zone_and_the_flywheel_read_agrees(name, monkeypatch):
    """The one A1 sheet's ΔT scale μ_T is the finest of the series whose construction a composition holds
    (``finer_energy``): the next finer value either draws ΔT's span taller than the cap (A(φ)'s height) or
    was tried by the sheet's search and not held — the construction fills its zone to one step of the
    series (the agitator: ΔT 37.5 mm at μ_T = 0.4 J/mm beside ~340 × 150 mm bare before; on the old code no
    finer value was ever tried). The free paper left above and below the band in its column is less than
    what that step would add to the energy–mass diagram's height plus the zones' gaps. The flywheel read
    off the longer |kl| agrees with the exact one to the ruler's reading (0.5 mm over |kl|) plus 1.5 %."""
    from graphplan.drawing.layout import GAP
    from graphplan.graphic.scales import SERIES
    from graphplan.sheets import dynamics as sd
    from graphplan.sheets.compose import SheetOptions, field_of
    from graphplan.sheets.form import form
    tried: list[float] = []
    real = sd._built

    def spy(dyn_, args_, L_, size_, energy=None):
        if energy is not None:
            tried.append(energy)
        return real(dyn_, args_, L_, size_, energy)
    monkeypatch.setattr(sd, "_built", spy)
    monkeypatch.setattr(sd, "_CONSTRUCTIONS", {})
    monkeypatch.setattr(sd, "_MEMOS", {})      # the searches' measures (stop 60: kept per construction key)
    st = scene_study(SCENES[name])
    f, args = form("A1"), SheetOptions(precision=0.5, sheet="dynamics", lang="en")
    dyn = sd._analysed(st, None)
    L, size, _, shape, _, _, _, energy = sd.construction(st, dyn, f, args)
    assert shape != "set"
    fw = real(dyn, args, L, size, energy)
    assert energy is None or fw.mu_T == energy
    span = float(np.ptp(fw.dT)) * fw.mu_T                  # J
    k = math.floor(math.log10(fw.mu_T))
    values = sorted({m * 10.0 ** e for m in SERIES for e in (k - 1, k)})
    finer = max(m for m in values if m <= fw.mu_T / sd.ENERGY_GAIN * (1 + 1e-9))   # the next step
    capped = span / finer > sd.ENERGY_MOST * size + 1e-9
    assert capped or any(abs(t - finer) <= 1e-12 * finer for t in tried), (name, fw.mu_T, finer, tried)
    # the paper: what the next step adds to the energy–mass diagram's ΔT extent (the curve, k and l)
    X, Y = fw.curve()
    ext = np.concatenate([Y, fw.dT, [fw.tangent["k"], fw.tangent["l"], 0.0]])
    grow = float(np.ptp(ext)) * (fw.mu_T / finer - 1.0)
    sheet = sd.build_dynamics_sheet(st, f, args)
    band = [p for p in sheet.placed if p.name in ("energy", "wittenbauer", "inertia")]
    assert len(band) == 3
    bx0, by0 = (min(p.record.bounds()[j] for p in band) for j in (0, 1))
    bx1, by1 = (max(p.record.bounds()[j] for p in band) for j in (2, 3))
    _, fy0, _, fy1 = field_of(f)
    column = [p.record.bounds() for p in sheet.placed if p.name not in ("energy", "wittenbauer", "inertia")]
    column = [b for b in column if b[2] > bx0 and b[0] < bx1]
    over = [b[1] for b in column if b[1] >= by1 - 1e-6]
    under = [b[3] for b in column if b[3] <= by0 + 1e-6]
    room = ((min(over) - GAP if over else fy1) - by1) + (by0 - (max(under) + GAP if under else fy0))
    assert capped or room < grow + 2 * GAP, (name, fw.mu_T, room, grow)
    # the flywheel read: J = μ_T·|kl|/(ω_m²·δ) against the exact J (rotor and flywheel together)
    exact_J = dyn.flywheel + dyn.constant
    read = fw.mu_T * fw.kl / (dyn.omega_mean ** 2 * dyn.delta)
    assert read == pytest.approx(fw.total)
    assert abs(read - exact_J) / exact_J <= 0.5 / fw.kl + 0.015, (name, read, exact_J, fw.kl)
    assert abs(fw.error_pct(fw.flywheel)) <= 5.0


@pytest.mark.slow
def test_no_energy_scale_a_mere_rounding_finer():
    """CYLINDER_REVIEW54's ΔT at μ_A = 1,047 J/mm: 1 J/mm, a value of the series under it, would draw it 5 %
    taller and call it "redrawn at its own scale" — not a step (``ENERGY_GAIN``): its sheet keeps μ_A, as
    the next real step (0,5) does not hold."""
    from review_scenes import CYLINDER_REVIEW54
    from graphplan.sheets import dynamics as sd
    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.form import form
    st = scene_study(CYLINDER_REVIEW54)
    dyn = sd._analysed(st, None)
    got = sd.construction(st, dyn, form("A1"), SheetOptions(precision=0.5, sheet="dynamics"))
    fw = sd._built(dyn, SheetOptions(precision=0.5, sheet="dynamics"), got[0], got[1], got[7])
    assert got[7] is None or got[7] <= fw.mu_A / sd.ENERGY_GAIN * (1 + 1e-9), got


def test_a_given_energy_scale_is_drawn_and_read(link59):
    """``construct(energy=…)``: ΔT(φ) at that μ_T where finer than μ_A (its ordinates carried over from the work
    diagrams' reading), |kl| longer in proportion, the flywheel the same to the ruler; coarser: μ_A kept."""
    from graphplan.graphic.flywheel import construct
    base = construct(link59, None, 0.5, L=330.0, size=1.0)
    assert base.mu_T == base.mu_A
    finer = construct(link59, None, 0.5, L=330.0, size=1.0, energy=base.mu_A / 2.5)
    assert finer.mu_T == pytest.approx(base.mu_A / 2.5) and finer.energy_scale == finer.mu_T
    assert finer.kl == pytest.approx(base.kl * 2.5, abs=2.5)
    assert finer.total == pytest.approx(base.total, rel=0.5 / base.kl + 1e-3)
    assert np.ptp(finer.dT) == pytest.approx(np.ptp(base.dT) * 2.5, abs=1.0)
    coarser = construct(link59, None, 0.5, L=330.0, size=1.0, energy=base.mu_A * 2)
    assert coarser.mu_T == coarser.mu_A


def test_the_english_protractor_note_writes_tan(link59):
    """LINK59's ψ (2.96°, 2.77°) are too small for a protractor: the English note says the tangents are drawn
    by «tan ψ» as its formula line writes it (it said «tg ψ», the Ukrainian notation, review 58 #7); the
    Ukrainian keeps «tg ψ»."""
    from graphplan.graphic.flywheel import construct
    from graphplan.report.dynamics import tangents_note
    f = construct(link59, None, 0.5, L=330.0, size=1.15)
    en, uk = tangents_note(f, "en"), tangents_note(f, "uk")
    assert en is not None and "tan ψ" in en and "tg" not in en
    assert uk is not None and "tg ψ" in uk
