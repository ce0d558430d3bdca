"""Stop 54: the lead's Blake jaw crusher (LINK54) — I(0-1) → II(2-3) ВВВ → II(4-5) ВВВ, the pin B
shared by the pitman 2, the back toggle 3 and the front toggle 4; 900 N·m on the jaw 5 against its
stroke towards "min". The force analysis checked against an independent solver (every link's three
equations at once, kinematics by finite differences of the loop's own closure) and against the
power balance M_b·ω1 = −Σ(P·v + M·ω); the resistance diagram's hatching checked on its drawing."""
from __future__ import annotations

import math

import numpy as np
import pytest

from tests.conftest import scene_study
from tests.review_scenes import LINK54

O1, O2, O3 = 0j, 0.17 - 0.29j, -0.24 + 0.10j
R1, L2, L3, L4, L5 = 0.04, 0.36, 0.18, 0.20, 0.40
MASS, INERTIA, G = (12, 20, 6, 6, 40), (0.08, 0.25, 0.02, 0.025, 0.9), 9.81
W1 = 250 * 2 * math.pi / 60          # rad/s, counter-clockwise


def _circles(p: complex, rp: float, q: complex, rq: float, branch: int) -> complex:
    """The point at rp from p and rq from q, on the ``branch`` side of p→q (+1 left)."""
    d = abs(q - p)
    a = (rp ** 2 - rq ** 2 + d ** 2) / (2 * d)
    u = (q - p) / d
    return p + a * u + branch * math.sqrt(rp ** 2 - a ** 2) * 1j * u


def _frame(th: float):
    """Joints, centres of mass (mid-links; S1 at O1) and link angles at crank angle th (the scene's
    assembly: B right of A→O2, C left of B→O3 — as the drawn sheet shows it)."""
    a = O1 + R1 * complex(math.cos(th), math.sin(th))
    b = _circles(a, L2, O2, L3, -1)
    c = _circles(b, L4, O3, L5, +1)
    s = [O1, (a + b) / 2, (O2 + b) / 2, (b + c) / 2, (O3 + c) / 2]
    ang = [th, np.angle(b - a), np.angle(b - O2), np.angle(c - b), np.angle(c - O3)]
    return a, b, c, s, np.array(ang)


def _unwrap(x: float) -> float:
    return (x + math.pi) % (2 * math.pi) - math.pi


def _equations(col: dict, s: list, force: list, couple: list):
    """The 15 equilibrium equations of five links, three a link (ΣX, ΣY, ΣM about a point), as a
    matrix and right side filled row by row: ``put`` a reaction (its unknown x, y at ``col[key]``)
    acting at ``at``, ``given`` link i's own loads (weight, inertia force at S, couple)."""
    m, rhs = np.zeros((15, 15)), np.zeros(15)

    def put(row: int, key: str, sign: float, at: complex, about: complex) -> None:
        j, r = col[key], at - about
        m[row, j] += sign
        m[row + 1, j + 1] += sign
        m[row + 2, j] += -sign * r.imag
        m[row + 2, j + 1] += sign * r.real

    def given(row: int, i: int, about: complex) -> None:
        r, f = s[i] - about, force[i]
        rhs[row] -= f.real
        rhs[row + 1] -= f.imag
        rhs[row + 2] -= r.real * f.imag - r.imag * f.real + couple[i]

    return m, rhs, put, given


def independent(th: float) -> dict:
    """Reactions (on the link named second: R12 of 1 on 2), M_b and the power balance's M_b."""
    h = 1e-4
    f0, fp, fm = _frame(th), _frame(th + h), _frame(th - h)
    a, b, c, s, _ = f0
    v = [(fp[3][i] - fm[3][i]) / (2 * h) * W1 for i in range(5)]
    acc = [(fp[3][i] - 2 * s[i] + fm[3][i]) / h ** 2 * W1 ** 2 for i in range(5)]
    om = [_unwrap(fp[4][i] - fm[4][i]) / (2 * h) * W1 for i in range(5)]
    eps = [(_unwrap(fp[4][i] - f0[4][i]) - _unwrap(f0[4][i] - fm[4][i])) / h ** 2 * W1 ** 2 for i in range(5)]
    force = [-1j * MASS[i] * G - MASS[i] * acc[i] for i in range(5)]
    couple = [-INERTIA[i] * eps[i] for i in range(5)]
    force[0], couple[0] = -1j * MASS[0] * G, 0.0
    couple[4] += -math.copysign(900.0, om[4])           # against the jaw's motion
    # unknowns (x, y): R01, R21 (2 on 1), R03, R42 (4 on 2, the pin B carried by 2), R23, R45, R05; M_b
    col = {"R01": 0, "R21": 2, "R03": 4, "R42": 6, "R23": 8, "R45": 10, "R05": 12}
    m, rhs, put, given = _equations(col, s, force, couple)

    put(0, "R01", 1, O1, O1), put(0, "R21", 1, a, O1), given(0, 0, O1)
    m[2, 14] = 1.0
    put(3, "R21", -1, a, a), put(3, "R23", -1, b, a), put(3, "R42", 1, b, a), given(3, 1, a)
    put(6, "R03", 1, O2, O2), put(6, "R23", 1, b, O2), given(6, 2, O2)
    put(9, "R42", -1, b, b), put(9, "R45", -1, c, b), given(9, 3, b)
    put(12, "R05", 1, O3, O3), put(12, "R45", 1, c, O3), given(12, 4, O3)
    x = np.linalg.solve(m, rhs)
    r = {k: complex(x[j], x[j + 1]) for k, j in col.items()}
    out = {"R01": r["R01"], "R12": -r["R21"], "R03": r["R03"], "R24": -r["R42"], "R23": r["R23"],
           "R45": r["R45"], "R05": r["R05"], "Mb": x[14]}
    out["Mb_power"] = -sum((force[i].conjugate() * v[i]).real + couple[i] * om[i] for i in range(5)) / W1
    return out


@pytest.fixture(scope="module")
def st():
    return scene_study(LINK54)


def test_the_crushers_reactions_and_balancing_moment_agree_with_an_independent_solution(st):
    """Every reaction and M_b of the program's analysis at the force position within 0.1 % of the
    independent solution's, whose M_b the power balance gives again (within 0.1 %)."""
    from graphplan.exact.kinetostatics import analyse, at_scene_angle
    phi = at_scene_angle(st)
    ks = analyse(st, phi)
    mine = independent(math.radians(phi))
    assert mine["Mb_power"] == pytest.approx(mine["Mb"], rel=1e-3)
    assert float(np.atleast_1d(ks.balancing)[0]) == pytest.approx(mine["Mb"], rel=1e-3)
    for key in ("R01", "R12", "R03", "R23", "R24", "R45", "R05"):
        got = complex(np.atleast_1d(ks.reactions[key].force)[0])
        assert abs(got - mine[key]) <= 1e-3 * abs(mine[key]), (key, got, mine[key])


def test_the_resistance_diagram_is_hatched_evenly_under_the_moment(st):
    """The jaw's 900 N·m hatched at an even pitch along the swing's path axis (not at every 48th of
    the turn, which crowded the lines into a black bar by the extreme, where ψ hardly grows), every
    line from the axis up to 900 N·m, none on the idle stroke."""
    from graphplan.drawing.charts import HATCH_PITCH_MM, resistance_record, turn
    rec = resistance_record(turn(st), lang="en")
    mu = rec.scales["mu_P"]
    lines = sorted((q.points[0][0], abs(q.points[1][1] - q.points[0][1]) * mu)
                   for q in rec.items if q.role == "hatch")
    assert len(lines) >= 10
    xs = np.array([x for x, _ in lines])
    assert np.allclose(np.diff(xs), HATCH_PITCH_MM)
    assert all(abs(h - 900.0) < 1e-6 for _, h in lines)
    curve = next(q for q in rec.items if q.role == "curve")
    top = [p[0] for p in curve.points if abs(p[1] * mu - 900.0) < 1e-6]
    assert xs[0] > 0 and xs[-1] <= max(top) + 1e-9


def test_a_path_axis_of_a_hardly_moving_output_has_a_few_ticks():
    """The resistance diagram's path axis over a reach of 4e-14 m (a ram assembled on its fixed
    pivot: the scene's other branch) ticks at its round steps only — a handful of them, not the
    million an absolute 1e-9 m tolerance against a 1e-15 m step set (the sheet ran out of memory)."""
    from graphplan.drawing.charts import VALUE_GAP_MM, _path_values
    from graphplan.graphic.record import Record
    rec = Record("path")
    reach, mu_s = 3.95e-14, 2.5e-16
    _path_values(rec, reach, mu_s, -5.0, "en", "s")
    ticks = [q for q in rec.items if q.kind == "segment"]
    assert 1 <= len(ticks) <= 1 + reach / (VALUE_GAP_MM * mu_s)     # no closer than their gap
    assert max(q.points[0][0] for q in ticks) * mu_s <= reach * (1 + 1e-9)


def knee_press(th: float) -> dict:
    """OWN_KNEE_PRESS54 solved independently at crank angle th: the crank O1A (60 mm, 90 rpm ccw),
    the coupler AB, the toggle O2B–BC, the ram C on the vertical guide x = 0.40 m, 15 kN against the
    ram on its stroke down. Unknowns: R01, R21, R03, R42, R23, R45 (x, y), the guide's normal force
    N05 and its couple, M_b — fifteen, from the five links' three equations each."""
    o2, xg, r1, l2, l3, l4 = 0.40 + 0.30j, 0.40, 0.06, 0.47, 0.30, 0.30
    mass, inertia, w1 = (8, 15, 10, 10, 40), (0.02, 0.3, 0.08, 0.08, 0.0), 90 * 2 * math.pi / 60

    def frame(t: float):
        a = r1 * complex(math.cos(t), math.sin(t))
        b = _circles(a, l2, o2, l3, -1)
        c = complex(xg, b.imag - math.sqrt(l4 ** 2 - (xg - b.real) ** 2))     # the ram below the knee
        return a, b, c, [0j, (a + b) / 2, (o2 + b) / 2, (b + c) / 2, c], \
            np.array([t, np.angle(b - a), np.angle(b - o2), np.angle(c - b), 0.0])

    h = 1e-4
    f0, fp, fm = frame(th), frame(th + h), frame(th - h)
    a, b, c, s, _ = f0
    v = [(fp[3][i] - fm[3][i]) / (2 * h) * w1 for i in range(5)]
    acc = [(fp[3][i] - 2 * s[i] + fm[3][i]) / h ** 2 * w1 ** 2 for i in range(5)]
    om = [_unwrap(fp[4][i] - fm[4][i]) / (2 * h) * w1 for i in range(5)]
    eps = [(_unwrap(fp[4][i] - f0[4][i]) - _unwrap(f0[4][i] - fm[4][i])) / h ** 2 * w1 ** 2 for i in range(5)]
    force = [-1j * mass[i] * G - mass[i] * acc[i] for i in range(5)]
    couple = [-inertia[i] * eps[i] for i in range(5)]
    force[0] = -1j * mass[0] * G
    if v[4].imag < 0:                                    # the stroke down: the press's force up
        force[4] += 15000j
    col = {"R01": 0, "R21": 2, "R03": 4, "R42": 6, "R23": 8, "R45": 10}
    m, rhs, put, given = _equations(col, s, force, couple)

    put(0, "R01", 1, 0j, 0j), put(0, "R21", 1, a, 0j), given(0, 0, 0j)
    m[2, 14] = 1.0
    put(3, "R21", -1, a, a), put(3, "R23", -1, b, a), put(3, "R42", 1, b, a), given(3, 1, a)
    put(6, "R03", 1, o2, o2), put(6, "R23", 1, b, o2), given(6, 2, o2)
    put(9, "R42", -1, b, b), put(9, "R45", -1, c, b), given(9, 3, b)
    put(12, "R45", 1, c, c), given(12, 4, c)
    m[12, 12] = 1.0                                      # the guide's normal force, across it (x)
    m[14, 13] = 1.0                                      # … and its couple
    x = np.linalg.solve(m, rhs)
    r = {k: complex(x[j], x[j + 1]) for k, j in col.items()}
    out = {"R01": r["R01"], "R12": -r["R21"], "R03": r["R03"], "R24": -r["R42"], "R23": r["R23"],
           "R45": r["R45"], "R05": complex(x[12], 0.0), "Mb": x[14]}
    out["Mb_power"] = -sum((force[i].conjugate() * v[i]).real + couple[i] * om[i] for i in range(5)) / w1
    return out


def test_the_knee_presss_reactions_and_balancing_moment_agree_with_an_independent_solution():
    """OWN_KNEE_PRESS54 at its force position (120° past the ram's top, on the stroke down): every
    reaction and M_b within 0.1 % of the independent solution, whose M_b the power balance gives."""
    from graphplan.exact.kinetostatics import analyse, at_scene_angle
    from tests.review_scenes import OWN_KNEE_PRESS54
    st = scene_study(OWN_KNEE_PRESS54)
    phi = at_scene_angle(st)
    ks = analyse(st, phi)
    mine = knee_press(math.radians(phi))
    assert mine["Mb_power"] == pytest.approx(mine["Mb"], rel=1e-3)
    assert float(np.atleast_1d(ks.balancing)[0]) == pytest.approx(mine["Mb"], rel=1e-3)
    for key in ("R01", "R12", "R03", "R23", "R24", "R45", "R05"):
        got = complex(np.atleast_1d(ks.reactions[key].force)[0])
        assert abs(got - mine[key]) <= 1e-3 * abs(mine[key]), (key, got, mine[key])


def test_the_strokes_bar_is_ticked_where_the_working_stroke_gives_way_to_the_idle_one(st):
    """The bar «робочий хід | холостий хід» under the resistance diagram's path axis has a tick at
    each end and one where the strokes meet — at the jaw's whole swing from position 0 (its extreme
    "max"), ψ5's range over a turn of the independent kinematics (``_frame``), within 0.5 %."""
    from graphplan.drawing.charts import resistance_record, turn
    rec = resistance_record(turn(st), lang="en")
    mu = rec.scales["mu_s"]
    low = min(q.points[0][1] for q in rec.items if q.kind == "segment" and q.role == "construction"
              and abs(q.points[0][1] - q.points[1][1]) < 1e-9 and q.points[1][0] - q.points[0][0] > 5.0)
    ticks = sorted(q.points[0][0] for q in rec.items if q.kind == "segment" and
                   abs(q.points[0][0] - q.points[1][0]) < 1e-9 and
                   min(q.points[0][1], q.points[1][1]) < low < max(q.points[0][1], q.points[1][1]))
    swing = np.ptp(np.unwrap([_frame(t)[4][4] for t in np.linspace(0, 2 * math.pi, 20001)]))
    assert len(ticks) == 3
    assert ticks[0] == pytest.approx(0.0, abs=1e-9)
    assert ticks[1] * mu == pytest.approx(math.degrees(swing), rel=5e-3)
    assert ticks[2] * mu == pytest.approx(2 * math.degrees(swing), rel=5e-3)
