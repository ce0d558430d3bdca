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
    """``plan_may_grow``: no longer than the largest plan's longest side, or, while the plan's
    shortest load is drawn under 10 mm, up to 1.5 times it — and no further."""
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
    st = scene_study(ROCKER46)
    p, _, dr = sf.plan(st, form("A1"), SheetOptions(precision=0.5, sheet="forces"))
    return {"st": st, "p": p, "dr": dr, "fp": dr.groups_fp(p.mu), "drawings": dr.drawings(p.mu, "uk")}


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
