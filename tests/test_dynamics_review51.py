"""Stop 51's dynamics sheet: LINK51 (tests/review_scenes.py) — the crank O1A (clockwise, 90 rpm) drives
the stone 2 in the coulisse O3B rocking about O3; B drives the rod BD to the rocker O4D, which carries
90 N·m against its motion on the working stroke; gravity on every link. Computed here from the
geometry alone: A on the crank circle, θ3 = atan2(A − O3), B = O3 + 0.40·e(θ3), D on the circles
(O4, 0.16) and (B, 0.30) (the scene's branch), θ5 = atan2(D − O4); each d/dφ by central differences
(h = 1e-6 rad). M*_c = 90·|dθ5/dφ| on the working stroke + Σ m·g·dy_S/dφ (φ the crank's turn in its
sense), I*_m = Σ m·|dS/dφ|² + I_S·(dθ/dφ)²; the flywheel by ω = √(2(T0 + ΔT)/(I*_m + J)) for δ = 0.06
about ω_m = πn/30.

The rocker reaches its least angle (124,6°) twice a turn — the coulisse swings B past the point
where O3, B and D line up, the rocker turns back and returns — so its two extremes of least value
are equal to one ulp, and which of them ended the working stroke was decided by round-off."""
from __future__ import annotations

import math
import re

import numpy as np
import pytest
from conftest import scene_study
from review_scenes import LINK51

O1, O3, O4 = np.array([0.0, 0.20]), np.array([0.0, 0.0]), np.array([0.25, 0.55])
R1, L3, L4, L5 = 0.08, 0.40, 0.30, 0.16
MASSES = {"S1": 3.0, "A": 1.0, "S3": 8.0, "S4": 4.0, "S5": 5.0}
INERTIAS = {"t1": 0.004, "t3": 0.11, "t4": 0.025, "t5": 0.02}
MOMENT, G, DELTA = 90.0, 9.81, 0.06
W1 = 90 * math.pi / 30


def pose(phi: float) -> dict:
    """Points and link angles at the crank angle φ (rad from x, counter-clockwise)."""
    a = O1 + R1 * np.array([math.cos(phi), math.sin(phi)])
    e3 = (a - O3) / math.hypot(*(a - O3))
    b = O3 + L3 * e3
    d = b - O4
    dist = math.hypot(*d)
    x = (L5 * L5 - L4 * L4 + dist * dist) / (2 * dist)
    h = math.sqrt(L5 * L5 - x * x)
    pd = O4 + x * d / dist - h * np.array([-d[1], d[0]]) / dist      # the scene's branch D = 1
    return {"S1": (O1 + a) / 2, "A": a, "S3": (O3 + b) / 2, "S4": (b + pd) / 2, "S5": (O4 + pd) / 2,
            "t1": phi, "t3": math.atan2(e3[1], e3[0]), "t4": math.atan2(*(pd - b)[::-1]),
            "t5": math.atan2(*(pd - O4)[::-1])}


def rates(phi: float, h: float = 1e-6) -> dict:
    """d/dφ (φ counter-clockwise) of every point and angle, an angle's difference taken across ±π."""
    p, q = pose(phi + h), pose(phi - h)
    out = {}
    for k in p:
        d = np.asarray(p[k]) - np.asarray(q[k])
        if k.startswith("t"):
            d = (d + math.pi) % (2 * math.pi) - math.pi
        out[k] = d / (2 * h)
    return out


def rocker_deg(phi: float) -> float:
    return math.degrees(pose(phi)["t5"]) % 360.0


def extremes() -> list[float]:
    """The crank angles (rad) where the rocker stops: dθ5/dφ changes sign (a 0.1° grid, then bisection)."""
    grid = np.radians(np.arange(0.0, 360.0, 0.1))
    rate = np.array([rates(p)["t5"] for p in grid])
    out = []
    for k in range(len(grid)):
        lo, hi = grid[k], grid[(k + 1) % len(grid)] + (2 * math.pi if k + 1 == len(grid) else 0.0)
        if rate[k] * rate[(k + 1) % len(grid)] < 0:
            for _ in range(60):
                mid = (lo + hi) / 2
                if rates(mid)["t5"] * rates(lo)["t5"] > 0:
                    lo = mid
                else:
                    hi = mid
            out.append(((lo + hi) / 2) % (2 * math.pi))
    return sorted(out)


@pytest.fixture(scope="module")
def ends():
    """Position 0 (the rocker's largest angle, 187°) and the two crank turns (clockwise from it) at
    which the rocker stands at its least angle: 161,3° and 272,1°."""
    ex = extremes()
    values = [rocker_deg(p) for p in ex]
    start = ex[int(np.argmax(values))]
    least = min(values)
    turns = sorted(math.degrees((start - p) % (2 * math.pi)) for p, v in zip(ex, values) if v < least + 1e-6)
    return start, turns


def reduced(start: float, turn: float, working_end: float) -> tuple[float, float]:
    """M*_c and I*_m at the crank's clockwise turn ``turn`` (rad) from position 0."""
    d = rates(start - turn)
    resistance = MOMENT * abs(d["t5"]) if turn % (2 * math.pi) < working_end else 0.0
    gravity = -G * sum(m * d[k][1] for k, m in MASSES.items())        # dy/d(turn) = −dy/dφ: clockwise
    inertia = sum(m * float(d[k] @ d[k]) for k, m in MASSES.items()) + sum(i * d[k] ** 2 for k, i in INERTIAS.items())
    return resistance + gravity, inertia


@pytest.fixture(scope="module")
def link():
    """LINK51's equation of motion and its construction as the A1 sheet draws it (L = 330 mm,
    heights × 1.0), with its ``dynamics --json`` document."""
    from graphplan.exact.dynamics import analyse
    from graphplan.graphic.flywheel import redrawn
    from graphplan.report.dynamics import dynamics_json
    dyn = analyse(scene_study(LINK51), None)
    f = redrawn(dyn, None, 0.5, L=330.0, size=1.0)
    return dyn, f, dynamics_json(f)


def test_the_rocker_reaches_its_least_angle_twice_and_the_working_stroke_is_the_slow_swing(ends):
    """The geometry's own fact the next tests stand on: the least angle at 161,3° and 272,1° of the
    turn from the largest; the swing down (161,3°) slower than the swing back up (360 − 272,1 = 87,9°)."""
    _, turns = ends
    assert len(turns) == 2 and turns[0] == pytest.approx(161.34, abs=0.05) and turns[1] == pytest.approx(272.09,
                                                                                                          abs=0.05)


@pytest.mark.parametrize("nudge", [0, 1, 2])
def test_which_tied_least_angle_ends_the_working_stroke_is_not_round_off(ends, nudge):
    """The working ("slow") stroke runs from position 0 through the swing down and the wobble to the
    second visit of the least angle (0…272,1° of the turn): the 90 N·m on the slow swing, never on the
    fast one back up — whichever of the two equal least values is the smaller by an ulp (``nudge``:
    none, the first or the second made smaller by 1e-15 rad)."""
    from dataclasses import replace

    from graphplan.exact.kinetostatics import working_stroke
    start, turns = ends
    st = scene_study(LINK51)
    real = st.output

    class Nudged:
        def __getattr__(self, name):
            return getattr(real, name)

        def value(self, kin):
            v = np.array(real.value(kin), dtype=float)
            lows = np.flatnonzero(v <= v.min() + 1e-9)
            if nudge and len(lows) == 2:
                v[lows[nudge - 1]] -= 1e-15
            return v
    st = replace(st, output=Nudged())
    turn = np.arange(0.5, 360.0, 1.0)
    phi = math.degrees(start) - turn
    assert np.array_equal(working_stroke(st, phi), turn < turns[1])


def test_table_1_the_work_and_the_exact_flywheel_are_the_closed_forms(link, ends):
    """M*_c and I*_m at the positions; A_c = ∫M*_c dφ (126,0 J); the flywheel J (rotor included) that
    holds δ = 0.06 about ω_m = πn/30 with a constant M*_d; tg ψ = μ_I·ω_m²(1 ± δ)/(2μ_T) and the
    drawn |kl| within the ruler's 0.5 mm of J·ω_m²·δ/μ_T."""
    from scipy.integrate import cumulative_trapezoid
    from scipy.optimize import brentq
    dyn, f, doc = link
    start, turns = ends
    assert doc["start_phi_deg"] == pytest.approx(math.degrees(start), abs=0.05)
    for p in doc["positions"]:
        m, i = reduced(start, math.radians(p["turn_deg"]), math.radians(turns[1]))
        assert p["moment_resistance"] == pytest.approx(m, abs=2e-4)
        assert p["inertia"] == pytest.approx(i, rel=1e-5)
    turn = np.radians(np.arange(0.0, 360.0 + 1e-9, 0.5))
    mc, im = np.array([reduced(start, u, math.radians(turns[1])) for u in turn]).T
    work = cumulative_trapezoid(mc, turn, initial=0.0)
    assert doc["work_resistance"] == pytest.approx(work[-1], rel=2e-4)
    dT = work[-1] / (2 * math.pi) * turn - work

    def spread(J: float) -> float:
        T0 = brentq(lambda t: (np.sqrt(2 * (t + dT) / (im + J)).max() + np.sqrt(2 * (t + dT) / (im + J)).min()) / 2
                    - W1, -dT.min() + 1e-12, 1e7)
        w = np.sqrt(2 * (T0 + dT) / (im + J))
        return (w.max() - w.min()) / W1
    J = brentq(lambda j: spread(j) - DELTA, 1.0, 100.0)
    assert dyn.flywheel + dyn.constant == pytest.approx(J, rel=1e-3)
    s = doc["scales"]
    for key, sign in (("tg_psi_max", 1), ("tg_psi_min", -1)):
        assert doc["flywheel"][key] == pytest.approx(s["mu_I"] * W1 ** 2 * (1 + sign * DELTA) / (2 * s["mu_T"]),
                                                     rel=1e-9)
    assert abs(abs(f.kl) - J * W1 ** 2 * DELTA / f.mu_T) <= f.precision


def motor_run(link, ends, flywheel: float, turns: int = 4, steps: int = 720) -> np.ndarray:
    """ω(turn) of the steady run with the 4АМ80А6 from its catalogue line alone (0.75 kW, 1000/916 rpm,
    rotor 0.0031 kg·m²): M = M_n·(ω_c − ω)/(ω_c − ω_n) at the motor shaft, at the crank ×i·η with
    ω = i·ω_1, i = 916/90, η = 0.9; d(½Iω²)/dφ = M_d(ω) − M*_c(φ) by RK4 (the closed forms' M*_c and
    I*_m), the last of ``turns`` turns (the motor's slope damps a disturbance by ~e⁻⁶ a turn)."""
    start, turns_ = ends
    grid = np.radians(np.arange(0.0, 360.0 + 1e-9, 0.5))
    mc, im = np.array([reduced(start, u, math.radians(turns_[1])) for u in grid]).T
    wc, wn, i, eta = 1000 * math.pi / 30, 916 * math.pi / 30, 916 / 90, 0.9
    mn = 750.0 / wn
    const = flywheel + 0.0031 * i * i

    def rhs(u: float, T: float) -> float:
        u %= 2 * math.pi
        w = math.sqrt(2 * T / (np.interp(u, grid, im) + const))
        return mn * (wc - i * w) / (wc - wn) * i * eta - np.interp(u, grid, mc)
    h = 2 * math.pi / steps
    T = 0.5 * (im[0] + const) * W1 ** 2
    out = []
    for _ in range(turns):
        out = []
        for k in range(steps):
            u = k * h
            out.append(math.sqrt(2 * T / (np.interp(u, grid, im) + const)))
            k1 = rhs(u, T)
            k2 = rhs(u + h / 2, T + h / 2 * k1)
            k3 = rhs(u + h / 2, T + h / 2 * k2)
            k4 = rhs(u + h, T + h * k3)
            T += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
    return np.array(out)


@pytest.mark.parametrize("lang", ["uk", "en"])
def test_the_design_answer_names_the_motors_faster_crank_as_a_cause(link, ends, lang):
    """Table 2's answer is the motor's flywheel, 7,30 kg·m² against 10,91 for a constant M*_d: with
    it the motor's run (integrated here) keeps δ = 0.06 about ω_m дв = 10,09 rad/s, 7,02 % above
    πn/30 — and the flywheel for a δ goes as 1/ω_m², a factor (9,425/10,09)² = 0,873 of the
    difference. The note under Table 2 says so beside the motor's falling M(ω)."""
    import re

    from graphplan.report.dynamics import design_note
    from graphplan.util.markup import plain
    _, _, doc = link
    w = motor_run(link, ends, doc["flywheel"]["motor"])
    wm = (w.max() + w.min()) / 2
    assert (w.max() - w.min()) / wm == pytest.approx(DELTA, abs=5e-4)
    note = plain(design_note(doc, lang))
    got = re.search(r"(\d+[.,]\d+) % (більша|higher) \(J ~ 1/ω_m²\)", note.replace("\u00a0", " "))
    assert got, note
    assert float(got.group(1).replace(",", ".")) == pytest.approx(100 * (wm / W1 - 1), abs=0.01)


# -- helper dyn51's own mechanism: a Scotch yoke driven by a rocker (YOKE_ROCKER51) ---------------------

Y_O2, Y_R1, Y_L2, Y_L3, Y_LC = np.array([0.20, 0.10]), 0.05, 0.22, 0.15, 0.30


def yoke_c(phi: float) -> np.ndarray:
    """The rocker's end C (the stone in the yoke's horizontal slot) at the crank angle φ: B on the
    circles (A, 0.22) and (O2, 0.15), left of A→O2 (branch B = 1), C = O2 + 0.30·(B − O2)/0.15."""
    a = Y_R1 * np.array([math.cos(phi), math.sin(phi)])
    d = Y_O2 - a
    dist = math.hypot(*d)
    x = (Y_L2 * Y_L2 - Y_L3 * Y_L3 + dist * dist) / (2 * dist)
    b = a + x * d / dist + math.sqrt(Y_L2 * Y_L2 - x * x) * np.array([-d[1], d[0]]) / dist
    return Y_O2 + Y_LC * (b - Y_O2) / Y_L3


def test_the_yoke_whose_slot_runs_through_its_rod_point_draws_its_position_plan():
    """The yoke's slot through its own point D (the rod starting at the slot): the rod's span before
    the bushing is 0, and the position plan's link outlines divided by it (ZeroDivisionError on every
    sheet of the scene, the dynamics sheet too, which counts the kinematics sheet's pages). Position 0
    (start = "min") is the yoke at its lowest: C's closed-form height least there."""
    from graphplan.drawing.plans import position_record
    from graphplan.graphic.plans import build_plans
    from review_scenes import YOKE_ROCKER51
    st = scene_study(YOKE_ROCKER51)
    plans = build_plans(st, precision=0.5)
    rec = position_record(plans)             # lettered: the links' numbers need their outlines
    assert rec.items
    c = yoke_c(math.radians(st.phi0))
    assert c[1] == pytest.approx(min(yoke_c(math.radians(p))[1] for p in np.arange(0.0, 360.0, 0.05)), abs=1e-6)


@pytest.fixture(scope="module")
def own_sheet():
    """YOKE_ROCKER51's A1 dynamics sheet (uk) composed alone (``conftest.composed``)."""
    from conftest import scene_sheet
    from review_scenes import YOKE_ROCKER51
    return scene_sheet(YOKE_ROCKER51, "dynamics", "A1", "uk", precision=0.5)


@pytest.mark.slow                     # the A1 sheet composed: ~6 s of CPU
def test_the_yokes_work_of_resistance_is_the_force_over_the_stroke(own_sheet):
    """A_c = 600 N × the yoke's stroke (gravity does no work over the turn): the stroke from C's
    closed form, 0.15240 m → 91.44 J; the notes print it."""
    ys = [yoke_c(math.radians(p))[1] for p in np.arange(0.0, 360.0, 0.05)]
    work = 600.0 * (max(ys) - min(ys))
    from graphplan.util.markup import plain
    notes = " ".join(plain(it.text) for p in own_sheet.placed if p.name == "notes"
                     for it in p.record.items if it.kind == "text")
    got = re.search(r"A_с = (\d+,\d+) Дж", notes)
    assert got and float(got.group(1).replace(",", ".")) == pytest.approx(work, abs=0.01)


@pytest.mark.slow                     # the A1 sheet composed: ~6 s of CPU
def test_the_speed_chart_takes_the_room_beside_the_moments_over_the_band(own_sheet):
    """ω(φ) is drawn from the moments' right side (GAP = 6 mm off, up to a GAP more for centring), not from the
    band's right side (a 90 × 230 mm strip empty beside the moments before), and overlaps nothing.
    Since review 54 the composition sets the band (ΔT(φ), energy–mass, I*(φ)) over the title block's
    column and ω(φ) under ΔT(φ) beside the moments, so it no longer stands above the band (looked at,
    stop 59: no strip empty beside the moments)."""
    from graphplan.drawing.layout import GAP
    boxes = {p.name: p.record.bounds() for p in own_sheet.placed}
    moments, speed = boxes["moments"], boxes["speed"]
    band = [b for name, b in boxes.items() if name in ("energy", "wittenbauer", "inertia")]
    assert band
    # beside the moments: GAP off at least, centred under ΔT(φ) at most a GAP more (401,8 mm against the
    # moments' 392,0: 9,8 mm), nowhere near the 90-mm strip of review 51
    assert moments[2] + GAP - 1e-6 <= speed[0] <= moments[2] + 2 * GAP
    for name, b in boxes.items():
        if name != "speed" and b[2] > speed[0] and b[0] < speed[2]:
            assert b[3] <= speed[1] + 1e-6 or b[1] >= speed[3] - 1e-6, name
