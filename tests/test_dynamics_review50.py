"""Stop 50's dynamics sheet: LINK50 (tests/review_scenes.py) — a crank-rocker four-bar O1ABO2 (crank
ccw, 75 rpm) whose rocker O2B carries the pin C of a stone sliding in the coulisse O3D; the coulisse
rocks about O3 and carries 120 N·m against its motion on the working stroke (the slow one), gravity
on every link. Everything reduced to the crank is computed here from the geometry alone: the
four-bar closed by two circles, C on the line O2B 0.24 m from O2, the coulisse's angle
θ5 = atan2(C − O3), each ratio dθ/dφ and dy_S/dφ by central differences (h = 1e-6 rad) —
M*_c = 120·|ω5/ω1| on the working stroke + Σ m·g·dy_S/dφ, I*_m = Σ m·|dS/dφ|² + I_S·(dθ/dφ)² —, the
flywheel by the energy form of the equation of motion at a constant M*_d (ω = √(2(T0 + ΔT)/(I*_m + J)),
T0 and J solved for ω_m = πn/30 and δ = 0.05)."""
from __future__ import annotations

import math
import re

import numpy as np
import pytest
from conftest import scene_study
from review_scenes import LINK49, LINK50

O1, O2, O3 = np.array([0.0, 0.0]), np.array([0.30, 0.03]), np.array([0.52, 0.26])
R1, L2, L3, LC = 0.07, 0.28, 0.16, 0.24
MASSES = {"S1": 3.0, "S2": 5.0, "S3": 6.0, "C": 1.2, "S5": 7.0}
INERTIAS = {"t1": 0.003, "t2": 0.04, "t3": 0.05, "t5": 0.07}
MOMENT, G, DELTA, ETA = 120.0, 9.81, 0.05, 0.85
W1 = 75 * math.pi / 30


def _circles(p, r, q, s):
    """The intersection of circles (p, r) and (q, s) left of p→q (the scene's branch B = 1)."""
    d = q - p
    dist = math.hypot(*d)
    a = (r * r - s * s + dist * dist) / (2 * dist)
    h = math.sqrt(r * r - a * a)
    return p + a * d / dist + h * np.array([-d[1], d[0]]) / dist


def pose(phi: float) -> dict:
    """Points and link angles at the crank angle φ (rad from x)."""
    a = O1 + R1 * np.array([math.cos(phi), math.sin(phi)])
    b = _circles(a, L2, O2, L3)
    u = (b - O2) / L3
    c = O2 + LC * u
    e5 = (c - O3) / math.hypot(*(c - O3))
    t5 = math.atan2(-e5[1], -e5[0])                # the coulisse's angle less π: it points near 180°
    return {"S1": a / 2, "S2": (a + b) / 2, "S3": O2 + 0.08 * u, "C": c, "S5": O3 + 0.23 * e5,
            "t1": phi, "t2": math.atan2(*(b - a)[::-1]), "t3": math.atan2(u[1], u[0]), "t5": t5}


def rates(phi: float, h: float = 1e-6, of=None) -> dict:
    """d/dφ of every point and angle of ``of`` (LINK50's ``pose`` unless given; central
    differences, an angle's difference taken across ±π)."""
    of = of or pose
    p, q = of(phi + h), of(phi - h)
    out = {}
    for k in p:
        d = np.asarray(p[k]) - np.asarray(q[k])
        if k.startswith("t"):
            d = (d + math.pi) % (2 * math.pi) - math.pi
        out[k] = d / (2 * h)
    return out


def theta5(phi):
    return pose(phi)["t5"]


def stroke_ends() -> tuple[float, float]:
    """The crank angles of the coulisse's extreme positions (its θ5 least, then greatest)."""
    from scipy.optimize import minimize_scalar
    grid = np.radians(np.arange(0.0, 360.0, 0.5))
    th = np.array([theta5(p) for p in grid])
    out = []
    for k in (int(np.argmin(th)), int(np.argmax(th))):
        sign = 1.0 if k == int(np.argmin(th)) else -1.0
        got = minimize_scalar(lambda p: sign * theta5(p), bracket=(grid[k] - 0.02, grid[k], grid[k] + 0.02),
                              tol=1e-12)
        out.append(got.x % (2 * math.pi))
    return out[0], out[1]


LO, HI = stroke_ends()
WORKING = (HI - LO) % (2 * math.pi)           # the crank's turn from θ5 least to greatest, ccw
SLOW_FROM = LO if WORKING >= math.pi else HI   # the working stroke: the slow one (the longer turn)
SLOW = max(WORKING, 2 * math.pi - WORKING)


def reduced(turn: float) -> tuple[float, float]:
    """M*_c and I*_m at the crank's turn from the start of the working stroke (position 0)."""
    phi = SLOW_FROM + turn
    d = rates(phi)
    resistance = MOMENT * abs(d["t5"]) if turn % (2 * math.pi) < SLOW else 0.0
    gravity = G * sum(m * d[k][1] for k, m in MASSES.items())
    inertia = sum(m * float(d[k] @ d[k]) for k, m in MASSES.items()) + sum(i * d[k] ** 2 for k, i in INERTIAS.items())
    return resistance + gravity, inertia


@pytest.fixture(scope="module")
def six():
    """LINK50's equation of motion and its construction as the A1 sheet draws it (L = 330 mm,
    heights × 1.15), with its ``dynamics --json`` document."""
    from graphplan.exact.dynamics import analyse
    from graphplan.graphic.flywheel import redrawn
    from graphplan.report.dynamics import dynamics_json
    dyn = analyse(scene_study(LINK50), None)
    f = redrawn(dyn, None, 0.5, L=330.0, size=1.15)
    return dyn, f, dynamics_json(f)


@pytest.fixture(scope="module")
def cycle():
    """The closed forms over the turn at 0.25°: the turn, M*_c, I*_m, and ΔT = M*_d·φ − A_c(φ)."""
    from scipy.integrate import cumulative_trapezoid
    turn = np.radians(np.arange(0.0, 360.0 + 1e-9, 0.25))
    mc, im = np.array([reduced(u) for u in turn]).T
    work = cumulative_trapezoid(mc, turn, initial=0.0)
    return turn, mc, im, work[-1] / (2 * math.pi) * turn - work, work[-1]


def test_position_0_starts_the_slow_stroke_and_table_1_is_the_closed_forms(six):
    """Position 0 is the coulisse's extreme that starts the slow (working) stroke, 32.9°; M*_c and
    I*_m at every position are the closed forms."""
    _, _, doc = six
    assert doc["start_phi_deg"] == pytest.approx(math.degrees(SLOW_FROM), abs=0.05)
    for p in doc["positions"]:
        m, i = reduced(math.radians(p["turn_deg"]))
        assert p["moment_resistance"] == pytest.approx(m, abs=2e-4)
        assert p["inertia"] == pytest.approx(i, rel=1e-5)


def test_the_work_of_resistance_and_the_exact_flywheel_are_the_closed_forms(six, cycle):
    """A_c over the cycle = ∫M*_c dφ (30.80 J), M*_d = A_c/2π; the flywheel J (with the rotor) that
    holds δ = 0.05 about ω_m = πn/30 with a constant M*_d solved from ω = √(2(T0 + ΔT)/(I*_m + J))."""
    from scipy.optimize import brentq
    dyn, _, doc = six
    turn, _, im, dT, work = cycle
    assert doc["work_resistance"] == pytest.approx(work, rel=1e-5)
    assert doc["moment_driving"] == pytest.approx(work / (2 * math.pi), rel=1e-5)
    wm = W1

    def delta(J: float) -> float:
        def spread(T0):
            w = np.sqrt(2 * (T0 + dT) / (im + J))
            return (w.max() + w.min()) / 2 - wm
        T0 = brentq(spread, -dT.min() + 1e-9, 1e5)
        w = np.sqrt(2 * (T0 + dT) / (im + J))
        return (w.max() - w.min()) / wm
    J = brentq(lambda j: delta(j) - DELTA, 0.5, 100.0)
    assert dyn.flywheel + dyn.constant == pytest.approx(J, rel=2e-4)


def test_the_tangents_and_kl_follow_from_the_exact_flywheel(six):
    """tg ψ = μ_I·ω_m²(1 ± δ)/(2μ_T) (4,054° and 3,669°), and the drawn |kl| within the ruler's
    0.5 mm of J·ω_m²·δ/μ_T with the equation of motion's J (flywheel + rotor)."""
    dyn, f, doc = six
    s = doc["scales"]
    for key, sign in (("tg_psi_max", 1), ("tg_psi_min", -1)):
        assert doc["flywheel"][key] == pytest.approx(s["mu_I"] * W1 ** 2 * (1 + sign * DELTA) / (2 * s["mu_T"]),
                                                     rel=1e-9)
    J = dyn.flywheel + dyn.constant
    assert abs(abs(f.kl) - J * W1 ** 2 * DELTA / f.mu_T) <= f.precision


@pytest.fixture(scope="module")
def six_given():
    """LINK50 with the scene giving the motor the rule chose until stop 56, 4АМ71А4 (0,55 kW: the 1500-rpm
    line then began there); the rule now picks 4АА56А4 (0,12 kW), whose softer, lighter run needs a
    flywheel (δ_дв 0,079 > 0,05 alone) — the path "the motor alone keeps δ" is kept on the given motor."""
    from graphplan.exact.dynamics import analyse
    from graphplan.graphic.flywheel import redrawn
    from graphplan.report.dynamics import dynamics_json
    text = LINK50.replace("[dynamics]\n", '[dynamics]\nmotor = "4АМ71А4"\n', 1)
    dyn = analyse(scene_study(text), None)
    f = redrawn(dyn, None, 0.5, L=330.0, size=1.15)
    return dyn, f, dynamics_json(f)


def test_the_speed_extremes_give_delta_and_the_motor_holds_its_own_delta_alone(six_given, cycle):
    """ω(φ) with the flywheel: (ω_max − ω_min)/ω_m = 0.05, (ω_max + ω_min)/2 = πn/30; with the
    motor alone (its rotor I·i² the only addition, its line M = i·η·(A·i·ω + B) at the crank) the
    periodic motion integrated here has δ_дв = 0.0156 < 0.05: Table 2's last row, the note under it
    and the notes' motor sentence all say no flywheel, and the ω(φ) legend prints the same δ_дв."""
    six = six_given
    from graphplan.report.dynamics import design_note, motor_note
    from graphplan.drawing.flywheel import speed_record
    from graphplan.sheets.dynamics import flywheel_table, motor_table
    from graphplan.util.markup import plain
    _, f, doc = six
    mo = doc["motion"]
    assert (mo["omega_max"] - mo["omega_min"]) / mo["omega_mean"] == pytest.approx(DELTA, rel=1e-6)
    assert mo["omega_mean"] == pytest.approx(W1, rel=1e-9)
    turn, mc, im, _, _ = cycle
    m = doc["motor"]
    i = m["rpm_rated"] / 75.0
    a = m["moment_rated"] / ((m["rpm_rated"] - m["rpm_sync"]) * math.pi / 30)
    b = -a * m["rpm_sync"] * math.pi / 30
    inertia = im + m["rotor_inertia"] * i * i

    half_turn = (turn[:-1] + turn[1:]) / 2           # RK4 over the table's 0.25° steps (the motor's
    at = {"I": (inertia, np.interp(half_turn, turn, inertia)),     # relaxation 23/rad: h·λ = 0.1), two
          "M": (mc, np.interp(half_turn, turn, mc))}                # turns: the first's start forgotten

    def rhs(T: float, k: int, half: bool) -> float:
        j = 1 if half else 0
        inert, load = at["I"][j][k], at["M"][j][k]
        return i * ETA * (a * i * math.sqrt(2 * T / inert) + b) - load
    h = turn[1] - turn[0]
    T = 0.5 * inertia[0] * W1 ** 2
    w = np.empty(len(turn))
    for _ in range(2):
        w[0] = math.sqrt(2 * T / inertia[0])
        for k in range(len(turn) - 1):
            k1 = rhs(T, k, False)
            k2 = rhs(T + h / 2 * k1, k, True)
            k3 = rhs(T + h / 2 * k2, k, True)
            T4 = T + h * k3
            k4 = i * ETA * (a * i * math.sqrt(2 * T4 / inertia[k + 1]) + b) - mc[k + 1]
            T = T + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
            w[k + 1] = math.sqrt(2 * T / inertia[k + 1])
    delta = (w.max() - w.min()) / ((w.max() + w.min()) / 2)
    assert m["motion"]["delta"] == pytest.approx(delta, rel=5e-3)
    assert delta < DELTA and doc["flywheel"]["motor"] == 0
    for lang, none in (("uk", "не потрібен"), ("en", "not needed")):
        cells = [plain(it.text) for it in flywheel_table(doc, lang).items if it.kind == "text"]
        assert any(none in c for c in cells), cells
        said = plain(motor_note(doc, lang) + " " + design_note(doc, lang)).replace("\u00a0", " ")
        assert ("не потрібен" if lang == "uk" else "no flywheel") in said
        shown = f"{delta:.3g}".replace(".", "," if lang == "uk" else ".")      # δ_дв to 3 figures, 0,0156
        assert said.count(f"{shown} < 0{',' if lang == 'uk' else '.'}05") == 2, said
        # one value written one way on the whole sheet (stop 50: the ω(φ) legend and Table 3 printed
        # 0,01559 beside Table 2's and the notes' 0,0156): every δ_дв the sheet prints is ``shown``
        legend = [plain(it.text) for it in speed_record(f, lang, width=330.0, height=160.0).items
                  if it.kind == "text" and ("δ_дв" in plain(it.text) or "δ_mot" in plain(it.text))]
        motor = [plain(it.text) for it in motor_table(doc, lang).items if it.kind == "text"]
        printed = (re.findall(r"δ_(?:дв|mot) = ([\d,.]+?),? ", " ".join(legend)) +
                   [motor[k + 1].split("; ")[1] for k, c in enumerate(motor) if re.search(r"; δ_(?:дв|mot)$", c)] +
                   re.findall(r"δ_(?:дв|mot) = ([\d,.]+) <", " ".join(cells) + " " + said))
        assert len(printed) >= 5 and set(printed) == {shown}, printed     # legend, Tables 3 and 2, notes


@pytest.mark.parametrize("lang", ["uk", "en"])
def test_the_motor_is_the_next_size_up_and_the_note_says_so_only_when_smallest(six, cycle, lang):
    """P = M*_c max·ω1/η (the closed form's peak, 94.1 W): the rule takes the 1500-rpm line's next size up.
    Until stop 56 the catalogue began at 0,55 kW (4АМ71А4, six times the power asked: the note called it
    the catalogue's smallest); the line now runs down to the series' smallest, 4АА50А4 (0,06 kW), so the
    rule's motor is 4АА56А4 (0,12 kW) and the note says nothing about the smallest. The same sentence
    with the motor marked the line's smallest and oversized says it (a teacher asks why so large)."""
    from graphplan.model.motors import catalogue
    from graphplan.report.dynamics import motor_note
    from graphplan.util.markup import plain
    _, _, doc = six
    _, mc, _, _, _ = cycle
    need = mc.max() * W1 / ETA / 1000.0
    m = doc["motor"]
    assert m["power_needed_kW"] == pytest.approx(need, rel=1e-3)
    line = sorted((c.power_kW, c.name) for c in catalogue() if c.rpm_sync == 1500)
    assert m["name"] == next(name for p, name in line if p >= need) == "4АА56А4"
    said = plain(motor_note(doc, lang)).replace("\u00a0", " ")
    assert "найменший" not in said and "smallest" not in said, said
    big = {**doc, "motor": {**m, "name": "4АМ71А4", "power_kW": 0.55, "smallest": True}}
    said = plain(motor_note(big, lang)).replace("\u00a0", " ")
    assert re.search(r"найменший у каталозі на 1500 об/хв" if lang == "uk" else
                     r"the catalogue's smallest at 1500 rpm", said), said


def test_a_motor_given_or_sized_snugly_is_not_called_the_smallest(six):
    """The remark only where the rule's motor is the line's smallest and over twice the power asked."""
    from graphplan.report.dynamics import catalogue_floor
    _, _, doc = six
    snug = {**doc, "motor": {**doc["motor"], "power_needed_kW": 0.5}}
    given = {**doc, "motor": {**doc["motor"], "smallest": False}}
    assert catalogue_floor(snug, "uk") == "" and catalogue_floor(given, "en") == ""


def test_an_axis_is_lettered_at_a_round_step_only():
    """Every 2nd tick, or every 4th, 5th or 10th where that step is round (1, 2, 2,5, 5 × 10^k):
    ticks every 0,025 lettered by 0,05, 0,1 or 0,25 — never 0,125 (stop 49's A2 energy–mass axis)."""
    from graphplan.drawing.flywheel import lettered_steps
    assert lettered_steps(0.025) == (1, 2, 4, 10)
    assert lettered_steps(0.02) == (1, 2, 5, 10)
    assert lettered_steps(5.0) == (1, 2, 4, 5, 10)
    assert lettered_steps(2.5) == (1, 2, 4, 10)
    for unit in (0.01, 0.02, 0.025, 0.05, 0.1, 0.2, 0.25, 0.5, 1.0, 2.0, 2.5, 5.0):
        for e in lettered_steps(unit):
            v = unit * e
            mant = v / 10 ** math.floor(math.log10(v) + 1e-9)
            assert e <= 2 or any(abs(mant - r) < 1e-6 for r in (1, 2, 2.5, 5, 10)), (unit, e)


@pytest.mark.slow                     # LINK49 analysed and its energy–mass diagram drawn: ~3 s
def test_link49s_a2_energy_mass_axis_letters_a_round_step():
    """LINK49's A2 set draws the energy–mass diagram at L = 330 mm, heights × 1.3 (μ_I = 0,002): its
    I* axis, ticked every 0,025, was lettered 0,125 and 0,25; now a round run (0,1 0,2 0,3), each
    value at its tick's abscissa."""
    from graphplan.exact.dynamics import analyse
    from graphplan.graphic.flywheel import redrawn
    from graphplan.drawing.flywheel import wittenbauer_record
    dyn = analyse(scene_study(LINK49), None)
    f = redrawn(dyn, None, 0.5, L=330.0, size=1.3)
    rec = wittenbauer_record(f, "uk")
    texts = [it for it in rec.items if it.kind == "text" and it.step == "I* graduation"]
    values = sorted(float(it.text.replace(",", ".")) for it in texts)
    assert len(values) >= 2
    gap = values[1] - values[0]
    assert all(abs((b - a) - gap) < 1e-9 for a, b in zip(values, values[1:]))
    mant = gap / 10 ** math.floor(math.log10(gap) + 1e-9)
    assert any(abs(mant - r) < 1e-6 for r in (1, 2, 2.5, 5)), values
    for it in texts:
        x0, _, x1, _ = it.ink()
        assert (x0 + x1) / 2 == pytest.approx(float(it.text.replace(",", ".")) / f.mu_I, abs=1.0)


# -- DRAGLINK50: the helper's own mechanism --------------------------------------------------------------
# A drag-link (double-crank) four-bar O1ABO2 — O1O2 = 0.05 m the shortest, so both cranks turn full
# circles — whose second crank O2B carries C 0.10 m past O2; the rod CD (0.36 m) drives the ram D on a
# horizontal guide through O2: O2-C-D a centric crank-slider, the ram's stroke 2·O2C = 0.20 m whatever
# the four-bar does, so A_c = 1200 N · 0.20 m = 240 J over a cycle (the ram's weight does no work on a
# level guide, the links' weights none over a cycle).

DO1, DO2 = np.array([0.0, 0.0]), np.array([0.05, 0.0])
DA, DB, DC, DR, OC = 0.12, 0.14, 0.13, 0.36, 0.10
D_MASSES = {"S1": 4.0, "S2": 3.0, "S3": 5.0, "S4": 6.0, "D": 25.0}
D_INERTIAS = {"t1": 0.006, "t2": 0.006, "t3": 0.012, "t4": 0.07}


def drag_pose(phi: float) -> dict:
    a = DO1 + DA * np.array([math.cos(phi), math.sin(phi)])
    b = _circles(a, DB, DO2, DC)
    u = (b - DO2) / DC
    c = DO2 - OC * u                              # C on the line BO2 past O2
    d = np.array([c[0] + math.sqrt(DR ** 2 - c[1] ** 2), 0.0])     # the ram right of C on y = 0
    return {"S1": a / 2, "S2": (a + b) / 2, "S3": DO2 + 0.013 * u, "S4": (c + d) / 2, "D": d,
            "t1": phi, "t2": math.atan2(*(b - a)[::-1]), "t3": math.atan2(u[1], u[0]),
            "t4": math.atan2(*(d - c)[::-1])}


def drag_rates(phi: float, h: float = 1e-6) -> dict:
    return rates(phi, h, drag_pose)


@pytest.fixture(scope="module")
def drag():
    from graphplan.exact.dynamics import analyse
    from graphplan.graphic.flywheel import redrawn
    from graphplan.report.dynamics import dynamics_json
    from review_scenes import DRAGLINK50
    dyn = analyse(scene_study(DRAGLINK50), None)
    f = redrawn(dyn, None, 0.5, L=330.0, size=1.15)
    return dyn, f, dynamics_json(f)


def test_the_drag_links_work_of_resistance_is_the_force_over_twice_o2c(drag):
    """A_c = 1200·2·O2C = 240 J, M*_d = A_c/2π; position 0 the ram's extreme that starts its slow
    stroke; M*_c and I*_m at every position the closed forms (the force 1200·|v_D|/ω1 against the ram
    on the working stroke, gravity Σ m·g·dy_S/dφ, the masses' kinetic energy over ω1²/2)."""
    _, _, doc = drag
    assert doc["work_resistance"] == pytest.approx(1200.0 * 2 * OC, rel=1e-6)
    assert doc["moment_driving"] == pytest.approx(240.0 / (2 * math.pi), rel=1e-6)
    grid = np.radians(np.arange(0.0, 360.0, 0.1))
    xd = np.array([drag_pose(p)["D"][0] for p in grid])
    ends = sorted(float(np.degrees(grid[k])) for k in (int(np.argmin(xd)), int(np.argmax(xd))))
    phi0 = doc["start_phi_deg"]
    assert min(abs(phi0 - e) for e in ends) < 0.1
    other = next(e for e in ends if abs(phi0 - e) >= 0.1)
    slow = (other - phi0) % 360.0
    assert slow > 180.0                             # the working stroke the slow one, ccw from position 0
    for p in doc["positions"]:
        u = p["turn_deg"]
        d = drag_rates(math.radians(phi0 + u))
        force = 1200.0 * abs(d["D"][0]) if u < slow else 0.0
        gravity = G * sum(m * d[k][1] for k, m in D_MASSES.items())
        inertia = (sum(m * float(d[k] @ d[k]) for k, m in D_MASSES.items())
                   + sum(i * d[k] ** 2 for k, i in D_INERTIAS.items()))
        assert p["moment_resistance"] == pytest.approx(force + gravity, abs=2e-3)
        assert p["inertia"] == pytest.approx(inertia, rel=1e-5)


def test_the_drag_links_kl_reads_the_exact_flywheel_and_its_motor_is_sized_snugly(drag):
    """|kl| within 1.5 ruler divisions (0.75 mm) of J·ω_m²·δ/μ_T; the motor the smallest of the 1000-rpm line
    over P = M*_c max·ω1/η (0,75 kW for 0,713 kW: not the line's smallest, no catalogue remark)."""
    from graphplan.model.motors import catalogue
    from graphplan.report.dynamics import motor_note
    dyn, f, doc = drag
    J = dyn.flywheel + dyn.constant
    # within 1.5 ruler divisions: the tangents rest on points each read to ±½ division, and since stop 56
    # the chords take the points added at M*_c's breaks (dead centres) too — one reading more each
    assert abs(abs(f.kl) - J * dyn.omega_mean ** 2 * dyn.delta / f.mu_T) <= 1.5 * f.precision
    need = doc["motor"]["power_needed_kW"]
    line = sorted((c.power_kW, c.name) for c in catalogue() if c.rpm_sync == 1000 and c.power_kW >= need)
    assert doc["motor"]["name"] == line[0][1]
    for lang in ("uk", "en"):
        assert "каталоз" not in motor_note(doc, lang) and "catalogue" not in motor_note(doc, lang)


@pytest.mark.parametrize("lang", ["uk", "en"])
def test_the_notes_name_the_abscissa_their_mu_phi_divides(six, lang):
    """"μ_φ = 2π/L" left L unnamed on the sheet (ΔT(φ)'s own μ_φ prints its 258,6): the notes now
    print L, the drawn M*_c(φ)'s span over the turn, and 2π over it gives the printed μ_φ."""
    from graphplan.drawing.flywheel import moments_record
    from graphplan.sheets.compose import lines_of
    from graphplan.sheets.dynamics import notes
    from graphplan.util.markup import plain
    _, f, doc = six
    text = " ".join(plain(t) for t in lines_of(notes(f, doc, lang))).replace("\u00a0", " ")
    got = re.search(r"L = (\d+(?:[.,]\d+)?) (?:мм|mm), μ_φ = 2π/L = (\d+[.,]\d+)", text)
    assert got, text
    L, mu = (float(g.replace(",", ".")) for g in got.groups())
    curve = next(it for it in moments_record(f, lang).items if it.kind == "polyline" and it.step == "M*_c(φ)")
    xs = [x for x, _ in curve.points]
    assert max(xs) - min(xs) == pytest.approx(L, abs=0.05)
    assert 2 * math.pi / L == pytest.approx(mu, rel=5e-4)
