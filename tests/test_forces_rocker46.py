"""Stop 46 (the lead's check): the six-bar feed mechanism ROCKER46 — a crank-rocker four-bar whose
rocker's arm drives a vertical slider through a rod — graded as a teacher grades its force sheet,
read off the drawings the sheet draws: the crank group's force plan at a scale where its own
loads read (it was drawn at 4 N/mm, G1 6 mm and Φ1 4.5 mm, beside 100 mm of empty room, because
its R01 came out 1.5 mm longer than II(4-5)'s longest at 2.5 N/mm)."""
from __future__ import annotations

import pytest

from conftest import scene_study
from review_scenes import ROCKER46


def test_a_plan_grows_past_the_largest_only_while_its_own_loads_are_short():
    """``plan_may_grow`` (the lengths at the scale tried): no longer than the largest plan's longest
    side, or, while the plan's shortest load is drawn no longer than 10 mm, up to 1.5 times it —
    and no further: the step that makes the shortest load read, not one past it (an A2 set's crank
    plan grew on from 2 N/mm, Φ1 8.75 mm, to 1 N/mm, its R01 238 mm long)."""
    from graphplan.sheets.forces import PLAN_BEYOND, SHORT_FORCE_MM, plan_may_grow
    assert plan_may_grow(90.0, 2.0, 91.5)                          # within the largest: always
    assert plan_may_grow(93.0, SHORT_FORCE_MM - 3.0, 91.5)         # a short load: a step beyond
    assert not plan_may_grow(93.0, SHORT_FORCE_MM + 1.0, 91.5)     # its loads read: not beyond
    assert not plan_may_grow(PLAN_BEYOND * 91.5 + 1.0, 1.0, 91.5)  # never past the bound


@pytest.fixture(scope="module")
def rocker():
    from graphplan.sheets import forces as sf
    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.form import form
    from conftest import shared

    def build():
        st = scene_study(ROCKER46)
        p, _, dr = sf.plan(st, form("A1"), SheetOptions(precision=0.5, sheet="forces"))
        return {"st": st, "p": p, "dr": dr, "fp": dr.groups_fp(p.mu), "drawings": dr.drawings(p.mu, "uk")}
    return shared("test_forces_rocker46.rocker", build)


def _loads_mm(rec) -> dict[str, float]:
    """The force plan's drawn vectors' lengths, mm, by their names."""
    return {q.text: abs(complex(*q.points[1]) - complex(*q.points[0])) for q in rec.items
            if q.kind == "vector" and q.text}


@pytest.mark.slow
def test_the_crank_groups_force_plan_draws_its_loads_long_enough_to_read(rocker):
    """On the drawn plan of I(0-1): G1 and Φ1 (24.5 N and 17.5 N) each at least 6.5 mm, the plan's
    longest vector no longer than 1.5 times the longest of the other plans as drawn."""
    fp, plans = rocker["fp"], rocker["drawings"]["forces"]
    labels = [gp.label for gp in fp.groups]
    drawn = {label: _loads_mm(rec) for label, rec in zip(labels, plans)}
    crank = drawn["I(0-1)"]
    loads = {n: v for n, v in crank.items() if n[0] in "GΦ"}
    assert loads and min(loads.values()) >= 6.5, crank
    others = max(max(d.values()) for label, d in drawn.items() if label != "I(0-1)")
    assert max(crank.values()) <= 1.5 * others + 1e-6, (crank, others)


def test_a_plans_detail_rings_the_knot_of_short_sides_not_a_short_side_far_off():
    """A sliver 90 mm tall: four short loads (0.5–4.5 mm) knotted at its foot, a 3.5 mm component at
    its head. The detail's window holds the knot (and is at most 30 mm across, so a μF of at least
    twice the plan's size is left to draw it at); the far component is no part of it."""
    from graphplan.drawing.forces import DETAIL_MOST_MM, plan_detail
    from graphplan.graphic.forceplans import Side
    foot = [Side("R12τ", 0j, 0.5j, "component"), Side("G2", 0.5j, 0.5j - 4j, "known"),
            Side("Φ2", -3.5j, -3.5j + 4.5, "known"), Side("Φ3", 4.5 - 3.5j, 7.0 - 3.5j, "known")]
    head = [Side("R43", 7.0 - 3.5j, 10.0 + 86j, "reaction"), Side("R03τ", 10.0 + 86j, 13.5 + 86j, "component"),
            Side("R03", 13.5 + 86j, 0j, "reaction")]
    d = plan_detail(foot + head, 10.0)
    assert d is not None and d.choices and all(10.0 / m >= 2.0 for m in d.choices)
    x0, y0, x1, y1 = d.box
    assert max(x1 - x0, y1 - y0) <= DETAIL_MOST_MM
    for s in foot:
        assert all(x0 <= z.real <= x1 and y0 <= z.imag <= y1 for z in (s.start, s.end)), s.name
    assert y1 < 86.0


@pytest.mark.parametrize("xs, halves", [([0.0, 0.9, 3.5, 7.0, 40.0], [0.7] * 5),
                                        ([0.0, 30.0, 59.0, 59.6, 60.0], [0.7] * 5)])
def test_numbers_crowding_at_a_rows_ends_stay_within_it(xs, halves):
    """A run crowding at the row's start (0, 1, 2, 3 by a slider's extreme) or end (11, 12) is set
    apart within the row's span (``lo`` … ``hi``): the first number's ink no further left than at
    its own place, the last's no further right; 1 mm of paper between neighbours, in order."""
    from graphplan.drawing.charts import spread_apart
    lo, hi = xs[0] - halves[0], xs[-1] + halves[-1]
    at = spread_apart(xs, halves, 1.0, lo, hi)
    assert all(a - h >= lo - 1e-9 and a + h <= hi + 1e-9 for a, h in zip(at, halves)), at
    assert all(b - a >= 2 * 0.7 + 1.0 - 1e-9 for a, b in zip(at, at[1:])), at


@pytest.fixture(scope="module")
def rocker_turn():
    from graphplan.drawing.charts import turn
    return turn(scene_study(ROCKER46))


def test_the_resistance_charts_numbers_stand_right_of_its_force_axis(rocker_turn):
    """The P_D chart over the slider's path: position 0 at the force axis (s = 0), 1 about 1 mm from
    it — no number's ink left of the axis, where the axis's own values stand ("0" was pushed
    4 mm left, under the force scale's 0)."""
    from graphplan.drawing.charts import resistance_record
    rec = resistance_record(rocker_turn, lang="uk")
    count = rocker_turn.ks.st.mech.task.count
    nums = [q for q in rec.items if q.kind == "text" and q.text.isdigit() and q.anchor == "middle"
            and q.points[0][1] < 0 and int(q.text) <= count]
    top = max(round(q.points[0][1], 6) for q in nums)
    row = [q for q in nums if round(q.points[0][1], 6) == top]
    assert len(row) == count + 1
    zero = next(q for q in row if q.text == "0")
    assert abs(zero.points[0][0]) < 0.5, zero.points          # at its tick, s = 0
    assert all(q.ink()[0] > zero.ink()[2] for q in row if q is not zero), sorted((q.ink()[0], q.text) for q in row)[:3]
