"""Review 46 (a teacher's look at the kinematics sheet of a six-bar feed mechanism and an offset
vertical press): the drawn geometry measured against the exact solution."""
from __future__ import annotations

import numpy as np
import pytest

from conftest import scene_study
from review_scenes import ROCKER46


@pytest.fixture(scope="module")
def rocker():
    """The six-bar whose slider D stops four times a turn (its rod CD passes its dead centre near
    the top: a 0.3-mm dip between two of the stops), its position plan at 1:2."""
    from graphplan.drawing.plans import position_record
    from graphplan.graphic.plans import build_plans
    st = scene_study(ROCKER46)
    plans = build_plans(st, mu_l=0.002)
    return st, plans, position_record(plans, lang="uk")


def test_the_stroke_is_dimensioned_between_the_largest_and_the_smallest_stop(rocker):
    """H spans the slider's whole stroke, max − min of its position over the turn (sampled finely),
    not the first two of its four stops (it drew H = 1 between 355.7° and 18.6°); D′ and D″ are
    lettered at those two ends."""
    st, plans, rec = rocker
    assert len(st.extremes) == 4
    phi = np.linspace(0.0, 360.0, 7201)
    y = st.solve(phi).point("D")[0].imag          # (position, velocity, acceleration)
    stroke = (y.max() - y.min()) / plans.mu_l                  # mm on the drawing
    dim = [p for p in rec.items if p.step == "dimensions" and p.kind == "vector"]
    assert len(dim) == 2
    (m, a), (_, b) = (p.points for p in dim)
    assert abs(abs(complex(*b) - complex(*a)) - stroke) < 0.05
    text = [p.text for p in rec.items if p.kind == "text" and p.text.startswith("H = ")]
    assert text and abs(float(text[0].split()[2].replace(",", ".")) - stroke * plans.mu_l * 1000.0) < 0.06
    ends = sorted(complex(*a).imag for a in (a, b))
    primes = {p.text: complex(*p.points[0]) for p in rec.items if p.kind == "text" and p.text.startswith("D")}
    for mark in ("′", "″"):
        at = next(z for t, z in primes.items() if t.endswith(mark))
        assert min(abs(at.imag - e) for e in ends) < 8.0, (mark, at, ends)   # lettered by its end


def _boxes(over: bool, under: bool):
    """The six-bar's four tables (mm: velocities 218 × 107, accelerations 90 × 168, dimensions
    77 × 66, the diagrams' readings 192 × 66) placed in two columns from (0, 0) down-left."""
    from graphplan.drawing.layout import Leaf
    from graphplan.sheets.kinlayout import place_tables, table_groups, tables_size
    tabs = [Leaf(f"T{i}", w, h) for i, (w, h) in enumerate(((218, 107), (90, 168), (77, 66), (192, 66)), 1)]
    groups = table_groups(tabs, 2, (), under, over)
    w, h = tables_size(groups, under, over)
    return tabs, (w, h), {p.name: p.box for p in place_tables(groups, w, 0.0, under, over)}


def inside_and_apart(names, boxes, w: float, h: float) -> None:
    """Each table's box (x0, y0, x1, y1; y down from 0) inside the w × h block, no two meeting."""
    for i, a in enumerate(names):
        x0, y0, x1, y1 = boxes[a]
        assert -1e-9 <= x0 and x1 <= w + 1e-9 and -h - 1e-9 <= y0 and y1 <= 1e-9
        for b in names[i + 1:]:
            u0, v0, u1, v1 = boxes[b]
            assert u0 >= x1 - 1e-9 or u1 <= x0 + 1e-9 or v0 >= y1 - 1e-9 or v1 <= y0 + 1e-9, (a, b)


def test_the_first_table_across_over_the_others_reads_in_order_and_leaves_less_blank():
    """The velocities' table (12 rows, 16 columns: the widest) across the top, the others in columns
    under it: no two tables meet, each inside the block, read in order (each next one to the right
    of or under the one before), and the block leaves less blank than the last table across under
    the others (which left 218 × 127 mm blank under Table 1 on the six-bar's A1)."""
    tabs, (w, h), boxes = _boxes(over=True, under=False)
    names = [t.name for t in tabs]
    inside_and_apart(names, boxes, w, h)
    for i, a in enumerate(names):
        x0, y0, x1, y1 = boxes[a]
        for b in names[i + 1:]:
            u0, v0, u1, v1 = boxes[b]
            assert u0 >= x1 - 1e-9 or v1 <= y0 + 1e-9 or (u0 >= x0 - 1e-9 and v1 <= y1 + 1e-9), (a, b)
    blank = w * h - sum(t.w * t.h for t in tabs)
    _, (w2, h2), _ = _boxes(over=False, under=True)
    assert blank < w2 * h2 - sum(t.w * t.h for t in tabs)


@pytest.mark.slow
def test_the_six_bars_position_plan_is_not_crowded_on_a1():
    """The six-bar's A1: the position plan, the sheet's main drawing, at a scale drawing the crank at
    least CRANK_MM long (it drew 26 mm at 1:2.5 beside full-size diagrams), its velocity plans
    legible (p_v a ≥ 40 mm)."""
    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.form import form
    from graphplan.sheets.kinematics import plan
    from graphplan.sheets.kinlayout import CRANK_MM
    st = scene_study(ROCKER46)
    p, nat, dr = plan(st, form("A1"), SheetOptions())
    assert st.mech.crank.length / p.mu["position"] >= CRANK_MM - 1e-9
    assert abs(st.mech.omega1) * st.mech.crank.length / p.mu["velocity"] >= 40.0 - 0.5
