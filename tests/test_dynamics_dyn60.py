"""Stop 60, helper dyn60.

1. LINK60 (the lead's: an offset crank-slider on a VERTICAL guide x = 0.03 m — a plunger B, 8 kg — whose
   slider drives a rocker O2C through the rod BC; the crank counter-clockwise at 150 rpm; 60 N·m against the
   rocker's turn over its working (slow) swing; q = 22 kg/m, I_S = 0.1·m·l²; δ = 0.04, η = 0.85, a 1500-rpm
   motor). The truth here is this file's own: closed-form positions (B where the circle about A meets the
   guide, C on the circles about B and O2), velocities by five-point differences, I* by the kinetic energy,
   M*_c by the power (the weights and the moment), A_c by the trapezoid split at the rocker's extreme, J by
   the energy method (ω = √(2(T0 + ΔT)/(I* + J)) swinging by δ about ω_m), the motor's steady state by the
   midpoint rule — nothing of graphplan's kinematics, splines or integrator.
2. A set's note «|kl| = X mm (Y mm on the A1 sheet)»: Y is the |kl| the A1 sheet draws (since stop 59 it may
   draw ΔT at its own finer μ_T), not the set search's classical target.
"""
from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import minimize_scalar

from conftest import scene_study

sys.path.insert(0, str(Path(__file__).parent))
from review_scenes import LINK60  # noqa: E402
from test_dynamics_dyn59 import energy_flywheel, motor_steady_speeds  # noqa: E402  (the energy method, written once)

R, L2, L4, L5, X_GUIDE = 0.065, 0.24, 0.20, 0.13, 0.03
O2 = 0.22 + 0.30j
Q, K, G = 22.0, 0.1, 9.81
M1, M2, M3, M4, M5 = Q * R, Q * L2, 8.0, Q * L4, Q * L5
I1, I2, I4, I5 = K * M1 * R * R, K * M2 * L2 * L2, K * M4 * L4 * L4, K * M5 * L5 * L5
MOMENT = 60.0
W1 = 150 * math.pi / 30
DELTA, ETA = 0.04, 0.85


def _geometry(th: np.ndarray) -> dict[str, np.ndarray]:
    """Points (complex, m) and angles at the crank's angles ``th`` from the x axis: B above A on the guide,
    C to the left of the line from B to O2 (the scene's assembly; the other one swings the rocker 20.7°)."""
    A = R * np.exp(1j * th)
    B = X_GUIDE + 1j * (A.imag + np.sqrt(L2 * L2 - (X_GUIDE - A.real) ** 2))
    d = O2 - B
    D = np.abs(d)
    a = (L4 * L4 - L5 * L5 + D * D) / (2 * D)
    C = B + d / D * (a + 1j * np.sqrt(L4 * L4 - a * a))
    return {"B": B, "S2": A + 0.35 * (B - A), "S4": (B + C) / 2, "S5": (O2 + C) / 2,
            "psi2": np.unwrap(np.angle(B - A)), "psi4": np.unwrap(np.angle(C - B)), "psi5": np.unwrap(np.angle(C - O2))}


def _rates(th: np.ndarray, h: float = 1e-4) -> dict[str, np.ndarray]:
    g = [_geometry(th + k * h) for k in (-2, -1, 1, 2)]
    return {key: (g[0][key] - 8 * g[1][key] + 8 * g[2][key] - g[3][key]) / (12 * h) for key in g[0]}


def _swing(th: float) -> float:
    return float(np.angle(_geometry(np.array([th]))["S5"][0] - O2))


def _reduced(turn: np.ndarray, th0: float, working: float) -> tuple[np.ndarray, np.ndarray]:
    """I*_m and M*_c (resisting +) at crank turns ``turn`` counter-clockwise from position 0 (crank angle
    ``th0``); the 60 N·m against the rocker's turn while the turn is within the working swing's ``working`` rad."""
    v = _rates(th0 + turn)                                # counter-clockwise: dθ/dt = +ω1, per unit ω1
    inertia = (I1 + M2 * abs(v["S2"]) ** 2 + I2 * v["psi2"] ** 2 + M3 * abs(v["B"]) ** 2
               + M4 * abs(v["S4"]) ** 2 + I4 * v["psi4"] ** 2 + M5 * abs(v["S5"]) ** 2 + I5 * v["psi5"] ** 2)
    gravity = -G * (M2 * v["S2"].imag + M3 * v["B"].imag + M4 * v["S4"].imag + M5 * v["S5"].imag)
    moment = np.where(turn < working, -MOMENT * np.abs(v["psi5"]), 0.0)
    return inertia, -(gravity + moment)


@pytest.fixture(scope="module")
def link60():
    from graphplan.exact.dynamics import analyse
    return analyse(scene_study(LINK60), None)


@pytest.fixture(scope="module")
def truth():
    """Position 0 (the crank's angle where the rocker's slow swing begins), the working swing's turn (rad)
    and the rocker's swing (rad)."""
    th = np.linspace(0.0, 2 * math.pi, 7201)
    psi = np.angle(_geometry(th)["S5"] - O2)
    ends = []
    for sign, k in ((-1.0, int(np.argmax(psi))), (1.0, int(np.argmin(psi)))):
        got = minimize_scalar(lambda t: sign * _swing(t), bounds=(th[k] - 0.002, th[k] + 0.002), method="bounded",
                              options={"xatol": 1e-10})
        ends.append(float(got.x))
    up = (ends[1] - ends[0]) % (2 * math.pi)              # counter-clockwise from ψ max to ψ min
    th0, working = (ends[0], up) if up > math.pi else (ends[1], 2 * math.pi - up)
    return th0, working, _swing(ends[0]) - _swing(ends[1])


def test_link60_position_0_starts_the_rockers_slow_swing(link60, truth):
    """Position 0 "working": the crank at 260.13° (the plunger's and so the rocker's extreme) where the slow
    swing, 184.23° of the turn, begins; the rocker swings 49.15°."""
    from graphplan.exact.positions import crank_angle
    th0, working, swing = truth
    assert math.degrees(working) == pytest.approx(184.226, abs=0.01)
    assert math.degrees(swing) == pytest.approx(49.15, abs=0.01)
    assert float(crank_angle(link60.study, 0.0)) % 360 == pytest.approx(math.degrees(th0) % 360, abs=1e-3)


@pytest.mark.parametrize("position", [0, 3, 8])
def test_link60_reduced_inertia_and_moment_at_three_positions(link60, truth, position):
    """I*_m (the plunger by its vertical velocity, the rod BC and the rocker turning) and M*_c at positions 0
    (the extreme: the weights only), 3 (the working swing: 36.64 N·m) and 8 (the return: the weights lift
    the rod and the plunger), against the closed form."""
    from graphplan.exact.dynamics import reduce
    th0, working, _ = truth
    turn = np.array([2 * math.pi * position / 12])
    inertia, moment = _reduced(turn, th0, working)
    got = reduce(link60.study, turn)
    assert float(got.inertia[0]) == pytest.approx(float(inertia[0]), rel=1e-7)
    assert float(got.moment[0]) == pytest.approx(float(moment[0]), rel=1e-6, abs=1e-6)
    assert {0: -1.0 < float(moment[0]) < 0.0, 3: float(moment[0]) > 36.0, 8: float(moment[0]) < -10.0}[position]


def test_link60_work_flywheel_and_motor_by_the_energy_method(link60, truth):
    """A_c = 60 N·m × the rocker's swing (the weights give none over a cycle); J = I_rotor·i² + I_fl that keeps
    δ = 0.04 about ω_m = 15.708 rad/s (the energy method on a 1/20° grid); the 1500-rpm line's 4АМ71В4
    (0.75 kW, 1390 rpm) for P = max M*_c·ω1/η = 0.692 kW; and with that motor's line and the program's
    motor flywheel the steady state swings by δ (the midpoint rule over turns until periodic)."""
    th0, working, swing = truth
    n = 360 * 20
    turn = np.sort(np.append(np.linspace(0.0, 2 * math.pi, n + 1), [working, working]))
    inertia, moment = _reduced(turn, th0, working)
    k = int(np.searchsorted(turn, working, side="left")) + 1        # the second copy: after the extreme
    moment[k] = _reduced(np.array([working + 1e-12]), th0, working)[1][0]
    work = np.concatenate([[0.0], np.cumsum(np.diff(turn) * (moment[1:] + moment[:-1]) / 2)])
    assert work[-1] == pytest.approx(MOMENT * swing, rel=1e-5)
    assert link60.cycle.work == pytest.approx(work[-1], rel=1e-5)
    drive = work[-1] / (2 * math.pi)
    assert link60.cycle.driving == pytest.approx(drive, rel=1e-5)
    energy = drive * turn - work

    J = energy_flywheel(energy, inertia, W1, DELTA, (1.0, 1e3), 1e6)
    assert link60.flywheel + link60.constant == pytest.approx(J, rel=1e-4)
    m = link60.drive.motor
    assert (m.name, m.rpm_sync, m.power_kW) == ("4АМ71В4", 1500, 0.75)
    assert float(np.max(moment)) * W1 / ETA / 1000 == pytest.approx(0.69216, abs=2e-5)
    i = 1390 / 150
    assert link60.constant == pytest.approx(0.0014 * i * i, rel=1e-6)
    # the motor's steady state: M*_d(ω) = i·η·(A·i·ω + B), A and B of the line through (ω_s, 0), (ω_n, M_n)
    speeds = motor_steady_speeds(turn, inertia, moment, link60.constant + link60.motor_flywheel, i, ETA, 1500, 1390,
                                 750.0, W1)
    mean = (speeds.max() + speeds.min()) / 2
    assert (speeds.max() - speeds.min()) / mean == pytest.approx(DELTA, rel=2e-3)
    assert mean == pytest.approx(16.706, abs=2e-3)          # less slip than rated: 6.35 % over πn/30


# -- a set's note: the A1 sheet's |kl| as that sheet draws it -----------------------------------------------

def _kl_lettered(sheet) -> float:
    """|kl| as the energy–mass diagram letters it ("|kl| = 113 mm"), on the sheet or the set."""
    import re
    for page in sheet.pages:
        for p in page.placed:
            for it in p.record.items if p.name == "wittenbauer" else ():
                m = it.kind == "text" and re.search(r"\|kl\| = ([\d.]+)", it.text or "")
                if m:
                    return float(m.group(1))
    raise AssertionError("no |kl| lettered")


@pytest.mark.slow                     # LINK53's A1 sheet and A3 set composed: ~1 min of CPU
def test_a_sets_note_gives_the_kl_the_a1_sheet_draws():
    """LINK53's A3 set reads |kl| = 60.5 mm; its note compared it with the set search's target, 74 mm — the
    A1 sheet's |kl| at the classical composition's scales — while the A1 sheet draws ΔT at its own finer
    μ_T = 1 J/mm and letters |kl| = 113 mm. The note's «(Y mm on the A1 sheet)» is the A1 sheet's own
    lettering, and what the note says of it holds: no scale with the moments on the first sheet reads |kl| ≥ Y."""
    import re

    from conftest import scene_sheet
    from review_scenes import LINK53
    on_a1 = _kl_lettered(scene_sheet(LINK53, "dynamics", "A1", "en"))
    sheet = scene_sheet(LINK53, "dynamics", "A3", "en")
    on_a3 = _kl_lettered(sheet)
    words = [it.text for page in sheet.pages for p in page.placed if p.name == "notes"
             for it in p.record.items if it.kind == "text" and it.text]
    text = " ".join(" ".join(words).split())
    # the set keeps the order of the work (the moments on its first sheet, stop 61): the note says no
    # scale reads the A1 sheet's |kl| in that order
    said = re.search(r"\|kl\| = ([\d.]+) mm \(([\d.]+) mm on the A1 sheet\): in the order of the work \(.*?first "
                     r"sheet\) no scale \(L = (\d+)…(\d+) mm\) of an A3 sheet gives \|kl\| ≥ ([\d.]+) mm", text)
    assert said, text
    kl, a1, low, top, claim = (float(g) for g in said.groups())
    assert (kl, a1, claim) == (on_a3, on_a1, on_a1) and on_a3 < on_a1
    assert on_a1 > 100.0                              # 113 mm: ΔT at μ_T = 1 J/mm, not the classical 74 mm


# -- the band's nook run down to the field's foot beside the title block ------------------------------------

def _bare_square(sheet, side: float, right: float) -> bool:
    """Whether the field left of ``right`` (mm) holds an empty ``side`` × ``side`` mm square: no drawing's,
    table's or note's lettered bounds in it (a 1-mm grid, prefix sums)."""
    from graphplan.sheets.compose import field_of
    page = sheet.pages[0]
    x0, y0, x1, y1 = field_of(page.form)
    x1 = min(x1, right)
    nx, ny = int(x1 - x0), int(y1 - y0)
    used = np.zeros((ny, nx), dtype=np.int32)
    for p in page.placed:
        b = p.record.bounds()
        i0, i1 = max(0, int(math.floor(b[1] - y0))), min(ny, int(math.ceil(b[3] - y0)))
        j0, j1 = max(0, int(math.floor(b[0] - x0))), min(nx, int(math.ceil(b[2] - x0)))
        used[i0:i1, j0:j1] = 1
    s = np.pad(used.cumsum(0).cumsum(1), ((1, 0), (1, 0)))
    k = int(side)
    windows = s[k:, k:] - s[:-k, k:] - s[k:, :-k] + s[:-k, :-k]
    return bool((windows == 0).any())


@pytest.mark.slow                     # LINK60's A1 dynamics sheet composed: ~25 s of CPU
@pytest.mark.parametrize("lang", ["uk", "en"])
def test_link60s_nook_runs_down_beside_the_title_block(lang):
    """LINK60's A1 sheet ("nook": the band at the right over the title block, ω(φ) and the notes in the band's
    nook under ΔT(φ)) set ω(φ) 140 mm tall in a nook reaching 19 mm past the title block's left side, and
    ~300 × 170 mm of paper stood bare under it, between the tables and the title block. The nook narrowed
    to that side runs down to the field's foot: ω(φ) grows (now about as tall as wide) and no 100 × 100 mm
    square of the field left of the title block is bare; ω(φ) and the notes stay left of the title block."""
    from conftest import scene_sheet
    from graphplan.sheets.compose import defects, keep_out
    sheet = scene_sheet(LINK60, "dynamics", "A1", lang)
    keep = keep_out(sheet.pages[0].form)
    assert not _bare_square(sheet, 100.0, keep[0])
    got = {p.name: p.record.bounds() for p in sheet.pages[0].placed}
    speed = got["speed"]
    assert speed[3] - speed[1] > 200.0 and max(got["speed"][2], got["notes"][2]) <= keep[0] + 1e-6
    assert defects(sheet) == []
