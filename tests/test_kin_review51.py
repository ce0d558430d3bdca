"""Stop 51 (the lead's LINK51: the crank O1A turns clockwise, its stone 2 slides in the coulisse O3B
rocking about O3, whose end B drives the rod BD to the rocker O4D — I(0-1) → II(2-3) ВПВ → II(4-5)
ВВВ). The truth here is the closed-form mechanism, worked out in this file alone: the coulisse along
O3A, B at 0,40 m from O3 along it, D the intersection of the circles (B, 0,30) and (O4, 0,16).
Position 0 is the coulisse's extreme where O1A ⊥ O3A (the crank at −90° − arccos(r/O1O3) =
−156,42°), where the rocker stands at its extreme D′ too; the rocker then swings through ψ5 = 62,33°
to its other extreme wherever O3, B and D are collinear (twice a turn), dwelling near it: D's
positions 4, 7, 8 and 5, 6, 9 fall within a millimetre of each other on the plan."""
from __future__ import annotations

import cmath
import math

import numpy as np
import pytest

from conftest import scene_study
from review_scenes import LINK51

O1, O3, O4 = 0.20j, 0j, 0.25 + 0.55j
R1, L3, L4, L5 = 0.08, 0.40, 0.30, 0.16
W1 = -90 * 2 * math.pi / 60                  # clockwise
TH0 = -math.pi / 2 - math.acos(R1 / abs(O1 - O3))   # position 0: O1A ⊥ O3A


def _d(th: float) -> complex:
    """D at the crank's angle θ (from the x axis): the circles' intersection on the scene's branch
    (the one whose swing is 62,33°, checked below)."""
    a = O1 + R1 * cmath.exp(1j * th)
    b = O3 + L3 * (a - O3) / abs(a - O3)
    dist = abs(O4 - b)
    x = (L4 * L4 - L5 * L5 + dist * dist) / (2 * dist)
    e = (O4 - b) / dist
    return b + x * e + 1j * e * math.sqrt(max(L4 * L4 - x * x, 0.0))


def _psi(th: float) -> float:
    """ψ5 as the diagrams draw it: the rocker's turn from D′ (position 0), + clockwise, rad."""
    return cmath.phase((_d(TH0) - O4) / (_d(th) - O4))


def _rates(turn_deg: float, h: float = 1e-5) -> tuple[float, float]:
    """ω5, ε5 of the diagrams (+ clockwise) at the crank's turn from position 0, deg."""
    th = TH0 - math.radians(turn_deg)
    m, z, p = (_psi(th - j * h) for j in (-1, 0, 1))      # the crank turns clockwise: θ falls
    return (p - m) / (2 * h) * abs(W1), (p - 2 * z + m) / (h * h) * W1 * W1


@pytest.fixture(scope="module")
def study():
    return scene_study(LINK51)


@pytest.fixture(scope="module")
def plans(study):
    from graphplan.graphic.plans import build_plans
    return build_plans(study, count=12, accel=[2], precision=0.5, mu_l=0.0025)    # the A1 sheet's


def test_the_swing_and_the_dwell_agree_with_the_closed_form(plans):
    """ψ_max = 62,33° between D′ (position 0, ψ5's extreme at the coulisse's) and D″ (O3, B, D
    collinear, twice a turn: one swing, one dwell between); position 0's crank angle 203,58°."""
    from graphplan.drawing.plans import swing
    fine = [_psi(TH0 - math.radians(k / 4)) for k in range(1441)]
    assert min(fine) == pytest.approx(0.0, abs=1e-9)
    assert swing(plans) == pytest.approx(math.degrees(max(fine)), abs=0.01)
    assert math.degrees(max(fine)) == pytest.approx(62.33, abs=0.005)
    assert plans.positions[0].phi % 360 == pytest.approx(math.degrees(TH0) % 360, abs=0.05)


def test_the_dwelling_positions_of_d_are_numbered_together(plans):
    """D's positions nearer each other than SAME_SPOT on the plan (the closed form at the plan's μl:
    4, 7, 8 within 0,9 mm and 5, 6, 9 within 1,0 mm near D″) are numbered once, "4, 7, 8" and "5, 6,
    9" — before, the numbers 5 and 7 were left out, three numbers finding no spot of their own. Every
    other pair of D's positions lies farther apart and keeps its own number."""
    from graphplan.drawing.plans import SAME_SPOT, position_record
    from graphplan.util.markup import plain
    mm = [_d(TH0 - math.radians(30 * k)) / plans.mu_l for k in range(12)]
    close = {(i, j) for i in range(12) for j in range(i + 1, 12) if abs(mm[i] - mm[j]) < SAME_SPOT}
    assert close == {(4, 7), (4, 8), (7, 8), (5, 6), (5, 9)}     # 6 and 9: 1,5 mm, joined through 5
    texts = {plain(q.text) for q in position_record(plans).items if q.kind == "text"}
    assert {"4, 7, 8", "5, 6, 9"} <= texts
    for k in (1, 2, 3, 10, 11):                      # D's other positions, each its own number
        assert str(k) in texts


def _readings(d) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The diagram's ω5 and ε5 read at the positions (+ clockwise, rad/s, rad/s²) and the
    closed form's there. The diagrams draw ψ5 upward from D′ (the turn measured as ``_psi``): a value
    is its ordinate, mm, times its scale."""
    k = d.at_positions
    up = 1.0 if d.drawn.s.max() > -d.drawn.s.min() else -1.0
    assert d.drawn.s[k] * up * d.mu_s == pytest.approx([_psi(TH0 - math.radians(t)) for t in d.turn[k]], abs=0.01)
    w = up * d.drawn.v_at[k] * d.mu_v
    e = up * d.drawn.a_at[k] * d.mu_a
    truth = np.array([_rates(float(t)) for t in d.turn[k]])
    return w, e, truth


def test_a_far_off_diagram_is_redrawn_with_smaller_intervals(study):
    """The first drawing (30° steps) read ε5 57 % off the exact at position 8: the rocker's ε5 runs
    from +74 to −165 rad/s² between positions 8 and 9. The lab's smaller intervals where the curve
    bends, with other poles that keep the block its size, now draw it: the largest |δ| of ω5 and ε5
    at the positions (judged against the closed form, as the lab judges: of the value, or of the
    cycle's largest where the value is under a tenth of it) at most half the first drawing's. And
    qualitatively right: the drawn ω5 changes sign once near each of the closed form's zeros (ω5 = 0
    at the coulisse's extreme and where O3, B, D are collinear) and nowhere else."""
    from graphplan.graphic.diagrams import chord_diagrams
    from graphplan.sheets.form import form
    from graphplan.sheets.kinematics import diagram_options, first_options
    from graphplan.sheets.kinlayout import room
    opts = diagram_options(study, 1.0, None, 0.5, room(form("A1")), 0.0)
    assert opts.get("adaptive") is True
    turns = np.arange(0.0, 360.0, 0.25)
    rates = np.array([_rates(t) for t in turns])
    big_w, big_e = np.abs(rates).max(axis=0)

    def worst(d) -> float:
        w, e, truth = _readings(d)
        out = 0.0
        for got, true, big in ((w, truth[:, 0], big_w), (e, truth[:, 1], big_e)):
            den = np.where(np.abs(true) >= 0.1 * big, true, big)
            out = max(out, float(np.max(np.abs(100 * (got - true) / den))))
        return out
    first = chord_diagrams(study, precision=0.5, **first_options(study, 1.0, None))
    now = chord_diagrams(study, precision=0.5, **{k: v for k, v in opts.items() if k != "redrawn"})
    assert worst(first) > 40.0
    assert worst(now) <= 0.5 * worst(first)
    # the zeros of ω5: the drawn curve's sign changes between its middles against the closed form's
    w = rates[:, 0]
    zeros = [t for t, a, b in zip(turns[1:], w[:-1], w[1:])        # (position 0's own zero: the ends)
             if a * b < 0 and abs(a - b) < 0.2 * big_w and 5.0 < t < 355.0]
    assert np.round(zeros) == pytest.approx([162, 227, 272], abs=1)   # 5,38, 7,57 and 9,08 positions
    mids = (now.turn[:-1] + now.turn[1:]) / 2
    v = now.drawn.v
    drawn = [(m1 + m2) / 2 for m1, m2, a, b in zip(mids[:-1], mids[1:], v[:-1], v[1:]) if a * b < 0]
    assert len(drawn) == len(zeros), (drawn, zeros)
    assert all(abs(a - b) <= 15.0 for a, b in zip(drawn, zeros)), (drawn, zeros)


# -- kin51's own: a rocker driving a Scotch yoke (II(4-5) ВПП), its slot through the yoke's D ----------

Y_R, Y_L2, Y_L3, Y_LC, Y_O2 = 0.06, 0.25, 0.18, 0.30, 0.30 + 0j
Y_W = -120 * 2 * math.pi / 60


def _yoke_c(th: float) -> complex:
    """OWN_YOKE51's C (the rocker's end, in the yoke's vertical slot) at the crank's angle θ: B from
    the circles (A, 0,25) and (O2, 0,18) on the left of A → O2, C = O2 + 0,30·(B − O2)/0,18."""
    a = Y_R * cmath.exp(1j * th)
    dist = abs(Y_O2 - a)
    x = (Y_L2 * Y_L2 - Y_L3 * Y_L3 + dist * dist) / (2 * dist)
    e = (Y_O2 - a) / dist
    b = a + x * e + 1j * e * math.sqrt(Y_L2 * Y_L2 - x * x)
    return Y_O2 + Y_LC * (b - Y_O2) / Y_L3


def test_own_yoke_driven_by_a_rocker_is_drawn_with_its_slot_through_c():
    """The yoke's slot passing through its own D (the rod's point) left the rod no length on the
    plan's outline measure, and the sheet stopped with ZeroDivisionError. Now the plan draws, in
    either language, at every thin position a slot line through the closed form's C (its x at μl
    from position 0's), and the stroke between D′ and D″ is the closed form's 2·l_C·…: 166,7 mm."""
    from graphplan.drawing.plans import joints_at, position_record, stroke_ends
    from graphplan.graphic.plans import build_plans
    from review_scenes import OWN_YOKE51
    plans = build_plans(scene_study(OWN_YOKE51), count=12, accel=[4], precision=0.5, mu_l=0.002)
    turns = np.radians(np.arange(0.0, 360.0, 0.01))
    xs = np.array([_yoke_c(t).real for t in turns])
    ends = stroke_ends(plans)
    sc = plans.scheme
    d_ends = [joints_at(sc, lay)["D"] for lay in ends]
    assert abs(d_ends[0] - d_ends[1]) * plans.mu_l == pytest.approx(np.ptp(xs), abs=1e-4)
    assert np.ptp(xs) == pytest.approx(0.16667, abs=1e-4)
    th0 = math.radians(plans.positions[0].phi)
    assert _yoke_c(th0).real == pytest.approx(xs.max(), abs=1e-6)          # start = "max": D′ at x_max
    for lang in ("uk", "en"):
        rec = position_record(plans, lang=lang)
        d0 = joints_at(sc, plans.positions[0].layout)["D"]
        for p in plans.positions:
            if p.key in plans.accel_keys:
                continue
            x = d0.real + (_yoke_c(math.radians(p.phi)).real - _yoke_c(th0).real) / plans.mu_l
            slots = [q for q in rec.items if q.kind == "segment" and q.step == f"position {p.index}"
                     and abs(q.points[0][0] - q.points[-1][0]) < 1e-6 and abs(q.points[0][1] - q.points[-1][1]) > 20]
            assert any(abs(q.points[0][0] - x) < 0.05 for q in slots), (lang, p.index, x)


def test_own_yoke_dimensions_name_the_rockers_pivot_and_only_the_rows_given():
    """Table 3 gave the yoke's guide as "e = 0,340" (the crank-slider's offset from O1) and its
    legend explained an e₅ the table did not have (the slot passes through D: no row). The guide
    driven by the rocker's end is X from the rocker's O2 — its distance from the guide's line
    y = 0,34 (O2 on y = 0): 0,340 m; the legend says α₅ alone. The Scotch yoke of review 11 (the
    crank's stone, its slot 0,02 m from D) keeps its row e₃ and the legend naming it."""
    from graphplan.sheets.kintables import dimensions_table
    from graphplan.util.markup import plain
    from review_scenes import OWN_YOKE51, YOKE11
    texts = [plain(i.text) for i in dimensions_table(scene_study(OWN_YOKE51), 0.002, "uk").items if i.kind == "text"]
    assert "X від O₂" in texts and texts[texts.index("X від O₂") + 1] == "0,340"
    assert not any(t.startswith("e") for t in texts)
    assert "α₅ — кут паза" in " ".join(texts) and "e₅" not in " ".join(texts)
    texts = [plain(i.text) for i in dimensions_table(scene_study(YOKE11), 0.002, "en").items if i.kind == "text"]
    assert texts[texts.index("e₃") + 1] == "0.020" and "e₃: from D to the slot" in " ".join(texts)
