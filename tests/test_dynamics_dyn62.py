"""Stop 62's dynamics sheet graded on LINK62 (tests/review_scenes.py): a crank-slider on a guide inclined at
20° whose slider B carries the block of a slotted lever O3C — I(0-1) → II(2-3) RRP → II(4-5) RPR —, the crank
ccw at 90 rpm, 60 N·m against the lever's motion over its working (slow) stroke, masses by length (18 kg/m,
I_S = 0.1·m·l²), the slider 4 kg and the block 1.5 kg, a 1500-rpm motor, δ = 0.04.

My own model (numpy only): B where the circle about A meets the guide (the + root: ahead of the foot of the
perpendicular from A along the guide), the lever along O3→B, its speed ratios by central differences; I* by
the kinetic energy, M*_c by the power of the weights and the moment, the energy method for J."""
from __future__ import annotations

import math
import re

import numpy as np
import pytest
from conftest import scene_study
from review_scenes import LINK62

R, L2, L5 = 0.06, 0.25, 0.34
O3 = np.array([0.30, 0.20])
P0 = np.array([0.0, -0.04])
U = np.array([math.cos(math.radians(20.0)), math.sin(math.radians(20.0))])
Q, K, G = 18.0, 0.1, 9.81
M1, M2, M3, M4, M5 = Q * R, Q * L2, 4.0, 1.5, Q * L5
I1, I2, I5 = K * M1 * R ** 2, K * M2 * L2 ** 2, K * M5 * L5 ** 2     # the block has no length: no I_S
W1 = 90.0 * math.pi / 30.0
MOMENT, DELTA, ETA = 60.0, 0.04, 0.8


def _pos(phi: np.ndarray) -> dict[str, np.ndarray]:
    a = R * np.stack([np.cos(phi), np.sin(phi)], axis=-1)
    d = P0 - a
    b = d @ U
    s = -b + np.sqrt(b * b - np.sum(d * d, axis=-1) + L2 ** 2)
    B = P0 + s[:, None] * U
    e = (B - O3) / np.linalg.norm(B - O3, axis=-1)[:, None]
    return {"S2": a + 0.4 * (B - a), "B": B, "S5": O3 + 0.5 * L5 * e,
            "th2": np.unwrap(np.arctan2(*(B - a).T[::-1])), "th5": np.unwrap(np.arctan2(e[:, 1], e[:, 0]))}


def _rates(phi: np.ndarray, h: float = 1e-6) -> dict[str, np.ndarray]:
    """d/dφ of every coordinate (the speed ratios v/ω1, ω/ω1)."""
    p, m = _pos(phi + h), _pos(phi - h)
    return {k: (p[k] - m[k]) / (2 * h) for k in p}


def mine(phi0: float, turn: np.ndarray, working: float) -> tuple[np.ndarray, np.ndarray]:
    """M*_c and I*_m at the crank's turn from position 0 (ccw): the moment 60·|ω5/ω1| over the working
    stroke (the first ``working`` rad of the turn), the weights' −Σ G·v_y/ω1 against the crank."""
    d = _rates(phi0 + turn)
    sq = lambda v: np.sum(v * v, axis=-1)                                          # noqa: E731
    inertia = (I1 + M2 * sq(d["S2"]) + I2 * d["th2"] ** 2 + (M3 + M4) * sq(d["B"])
               + (M5 * sq(d["S5"]) + I5 * d["th5"] ** 2))
    moment = G * (M2 * d["S2"][:, 1] + (M3 + M4) * d["B"][:, 1] + M5 * d["S5"][:, 1])
    moment = moment + np.where(turn < working, MOMENT * np.abs(d["th5"]), 0.0)
    return moment, inertia


def extremes() -> tuple[float, float]:
    """The lever's extreme positions (dθ5/dφ = 0) by bisection: the crank angles where the slow stroke
    starts and ends."""
    def root(a: float, b: float) -> float:
        f = lambda x: float(_rates(np.array([x]))["th5"][0])                         # noqa: E731
        for _ in range(80):
            m = 0.5 * (a + b)
            a, b = (m, b) if f(a) * f(m) > 0 else (a, m)
        return 0.5 * (a + b)
    return root(math.radians(180), math.radians(195)), root(math.radians(5), math.radians(20))


@pytest.fixture(scope="module")
def link62():
    """LINK62's equation of motion and its construction as the A1 sheet draws it (L = 210 mm), with its
    ``dynamics --json`` document."""
    from graphplan.exact.dynamics import analyse
    from graphplan.graphic.flywheel import redrawn
    from graphplan.report.dynamics import dynamics_json
    dyn = analyse(scene_study(LINK62), None)
    f = redrawn(dyn, None, 0.5, L=210.0, size=1.0)
    return dyn, f, dynamics_json(f)


def test_link62s_position_0_and_reduced_quantities_are_my_model(link62):
    """Position 0 where the lever's slow (working) stroke starts — 188,59° from x, the stroke 184,45° of
    the turn —, and I*_m, M*_c at all 12 positions (my model against the program's)."""
    _, _, doc = link62
    start, end = extremes()
    working = end + 2 * math.pi - start
    assert math.degrees(working) == pytest.approx(184.446, abs=1e-3)
    assert doc["start_phi_deg"] == pytest.approx(math.degrees(start), abs=1e-6)
    turn = np.radians([p["turn_deg"] for p in doc["positions"]])
    moment, inertia = mine(start, turn, working)
    assert [p["inertia"] for p in doc["positions"]] == pytest.approx(list(inertia), rel=1e-6)
    assert [p["moment_resistance"] for p in doc["positions"]] == pytest.approx(list(moment), abs=1e-4)
    assert max(moment) == pytest.approx(21.35, abs=0.01)                   # Table 1's row 4


def test_link62s_work_flywheel_and_motor_by_the_energy_method(link62):
    """A_c = ∫M*_c dφ (the weights give none over a cycle: 60 N·m × the lever's swing), M*_д = A_c/2π, the
    flywheel J from ½(J + I*)ω² = T0 + ΔT with (ω_max − ω_min)/ω_m = δ about ω_m = πn/30, I_мах = J − I_рот·i²;
    the power rule P = M*_c max·ω1/η = 0,2558 kW → 4АА63В4 (0,37 kW; 4АА63А4's 0,25 kW short)."""
    _, _, doc = link62
    start, end = extremes()
    working = end + 2 * math.pi - start
    n = 7200
    turn = np.linspace(0.0, 2 * math.pi, n + 1)
    moment, inertia = mine(start, turn, working)
    work = np.concatenate([[0.0], np.cumsum((moment[1:] + moment[:-1]) / 2 * np.diff(turn))])
    swing = abs(float(np.diff(_pos(np.array([start, end]))["th5"])[0]))
    assert work[-1] == pytest.approx(MOMENT * swing, rel=1e-5)
    assert doc["work_resistance"] == pytest.approx(work[-1], rel=1e-5)
    assert doc["moment_driving"] == pytest.approx(work[-1] / (2 * math.pi), rel=1e-5)
    energy = work[-1] / (2 * math.pi) * turn - work
    wm = W1

    def swing_of(J: float) -> float:        # T0 chosen so that (ω_max + ω_min)/2 = ω_m, by bisection
        lo_, hi_ = -energy.min() + 1e-9, 10 * J * wm ** 2
        for _ in range(60):
            t0 = 0.5 * (lo_ + hi_)
            w = np.sqrt(2 * (t0 + energy) / (J + inertia))
            lo_, hi_ = (t0, hi_) if (w.max() + w.min()) / 2 < wm else (lo_, t0)
        return float((w.max() - w.min()) / wm)
    a, b = 1.0, 20.0
    for _ in range(40):
        J = 0.5 * (a + b)
        a, b = (a, J) if swing_of(J) < DELTA else (J, b)
    fw = doc["flywheel"]
    assert fw["total_exact"] == pytest.approx(J, rel=1e-4)
    assert fw["exact"] == pytest.approx(J - fw["rotor_reduced"], rel=1e-4)
    m = doc["motor"]
    assert m["power_needed_kW"] == pytest.approx(moment.max() * W1 / ETA / 1000.0, rel=1e-4)
    assert (m["name"], m["power_kW"], m["rpm_rated"]) == ("4АА63В4", 0.37, 1365)
    assert fw["rotor_reduced"] == pytest.approx(m["rotor_inertia"] * (m["rpm_rated"] / 90.0) ** 2, rel=1e-9)


@pytest.mark.parametrize("lang", ["uk", "en"])
def test_every_extreme_on_the_speed_chart_reads_to_four_figures(link62, lang):
    """ω(φ)'s four extremes, each to four significant figures as ω_m: LINK62's motor curve was lettered
    10,37 and 9,96 (its mean's decimals) beside 9,613 and 9,236 — a teacher asks why ω_min дв has three
    figures. Each printed value the curve's extreme to its rounding."""
    from graphplan.drawing.flywheel import speed_record
    from graphplan.util.markup import plain
    dyn, f, _ = link62
    rec = speed_record(f, lang, width=330.0, height=160.0)
    got = {}
    for it in rec.items:
        if it.kind == "text" and it.step.startswith(("ω_max", "ω_min")):
            value = plain(it.text).replace("\u00a0", " ").split("= ")[1].split()[0]
            got[it.step] = value
    assert set(got) == {"ω_max", "ω_min", "ω_max motor", "ω_min motor"}
    truth = {"ω_max": dyn.motion.omega.max(), "ω_min": dyn.motion.omega.min(),
             "ω_max motor": dyn.motor_motion.omega.max(), "ω_min motor": dyn.motor_motion.omega.min()}
    for step, value in got.items():
        digits = re.sub(r"\D", "", value).lstrip("0")
        assert len(digits) == 4, (step, value)
        places = len(value.split("," if lang == "uk" else ".")[1])
        assert float(value.replace(",", ".")) == pytest.approx(truth[step], abs=0.5 * 10 ** -places + 1e-12)
    assert got["ω_min motor"] == ("9,965" if lang == "uk" else "9.965")


@pytest.mark.parametrize("lang", ["uk", "en"])
def test_the_approximate_flywheels_delta_t_is_named_graphical_where_it_is_quoted(link62, lang):
    """Review 61's remark 6: the approximate flywheel reads ΔT_max, ΔT_min off the drawn ΔT(φ) curve
    (LINK62: 2,88 at 45°, −19,50 at 180°) while Table 1's note quotes the exact column's 2,56 and −19,51
    under the same symbols. Table 2's row and the note under it name them graphical («гр», as Table 1's
    «ΔT гр.» column), and the note's numbers are the graphical readings; Table 1's note keeps the exact
    column's ΔT (no «гр»)."""
    from graphplan.report.dynamics import approximate_note, chords_note
    from graphplan.sheets.dynamics import flywheel_table
    from graphplan.util.markup import plain
    _, _, doc = link62
    gr = "гр" if lang == "uk" else "gr"
    texts = [plain(it.text).replace("\u00a0", " ") for it in flywheel_table(doc, lang).items if it.kind == "text"]
    row = next(t for t in texts if t.startswith(("наближ.: (", "approx.: (")))
    assert f"(ΔT_max {gr}−ΔT_min {gr})/" in row, row
    note = plain(approximate_note(doc, lang)).replace("\u00a0", " ")
    assert f"(ΔT_max {gr}, ΔT_min {gr} " in note, note
    e = doc["flywheel"]["approximate_energy"]
    hi = max(p["energy"] for p in doc["positions"])
    assert e["max"] > hi + 0.2                           # the drawn curve's peak between positions 1 and 2
    dec = "," if lang == "uk" else "."
    said = lambda v: f"{v:.2f}".replace(".", dec).replace("-", "−")       # noqa: E731  (Table 1's decimals)
    assert f"({said(e['max'])} − ({said(e['min'])}))/" in note, note
    chords = plain(chords_note(doc, lang)).replace("\u00a0", " ")
    assert gr not in chords.split(";")[1] and f"2{dec}56 − (−19{dec}51)" in chords, chords
