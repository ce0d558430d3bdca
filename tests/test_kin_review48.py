"""Review 48 (a teacher's look at the kinematics sheet of the lead's V-compressor, LINK48: two
connecting rods on one crank pin, pistons on guides at 45° and 135°): measured on the drawn records."""
from __future__ import annotations

import numpy as np
import pytest

from conftest import scene_study
from review_scenes import LINK48


@pytest.fixture(scope="module")
def link48():
    return scene_study(LINK48)


@pytest.fixture(scope="module")
def velocity_plans(link48):
    from graphplan.drawing.plans import velocity_records
    from graphplan.graphic.plans import build_plans
    plans = build_plans(link48)
    return plans, velocity_records(plans)


def _crosses(a: complex, b: complex, c: complex, d: complex) -> bool:
    """Whether the segments ab and cd properly cross (each one's ends on both sides of the other)."""
    def side(p, q, r):
        return ((q - p).conjugate() * (r - p)).imag
    return side(a, b, c) * side(a, b, d) < 0 and side(c, d, a) * side(c, d, b) < 0


def test_each_point_letter_of_the_velocity_plans_is_in_sight_of_its_point_or_led_to_it(velocity_plans):
    """A plan's letter reads as its point's where the straight line from the point to the letter's
    box crosses no drawn line (s1 at 0.3 of p_v a was set across the vector p_v s2 beside it, as if
    that vector's), or where a leader joins them. Measured on the records: each point letter's box,
    the segment from its point (0.9 mm off it: the lines through the point) to the box's nearest
    point, against every drawn line and vector."""
    plans, recs = velocity_plans
    checked = 0
    for q in plans.positions:
        rec, plan = recs[q.key], q.velocity
        wanted = {r.text: r.at for r in plan.labels}
        lines = [(complex(*p.points[0]), complex(*p.points[-1])) for p in rec.items
                 if p.kind in ("segment", "vector") and p.role != "label"]
        leaders = [(complex(*p.points[0]), complex(*p.points[-1])) for p in rec.items
                   if p.kind == "segment" and p.role == "label"]
        for p in rec.items:
            if p.kind != "text" or p.text not in wanted:
                continue
            at = wanted[p.text]
            x0, y0, x1, y1 = p.bounds()
            near = complex(min(max(at.real, x0), x1), min(max(at.imag, y0), y1))
            if abs(near - at) <= 0.9:
                continue
            if any(abs(a - at) < 1.5 for a, _ in leaders) and any(
                    abs(complex(min(max(b.real, x0), x1), min(max(b.imag, y0), y1)) - b) < 1.0 for _, b in leaders):
                continue                                    # on a leader from its point
            start = at + (near - at) / abs(near - at) * 0.9
            crossed = [(c, d) for c, d in lines if _crosses(start, near, c, d)]
            assert not crossed, (q.key, p.text, crossed)
            checked += 1
    assert checked >= 40        # most letters beside their points, free


def _inside(z: complex, poly: list[complex]) -> bool:
    """Whether z lies inside the convex polygon (its corners in order, either sense)."""
    signs = [((b - a).conjugate() * (z - a)).imag for a, b in zip(poly, poly[1:] + poly[:1])]
    return all(s > 0 for s in signs) or all(s < 0 for s in signs)


def test_the_guides_hatching_stops_at_the_slider_blocks(velocity_plans):
    """The guide's hatching lies on the side the 9 × 5 mm block covers: a stroke through a block
    reads as drawn over it (the two pistons B and C at position 2). No hatch stroke has a point
    inside a block of the position plan (sampled along the stroke), and the guides stay hatched."""
    from graphplan.drawing.plans import position_record
    plans, _ = velocity_plans
    rec = position_record(plans, lettered=False)
    blocks = [[complex(*p) for p in q.points] for q in rec.items if q.kind == "polygon" and q.layer == "mechanism"]
    hatch = [(complex(*q.points[0]), complex(*q.points[-1])) for q in rec.items if q.role == "hatch"]
    assert len(blocks) == 2 and len(hatch) > 20
    for a, b in hatch:
        for t in np.linspace(0.0, 1.0, 9):
            assert not any(_inside(a + t * (b - a), poly) for poly in blocks), (a, b)


def test_a_sets_acceleration_plan_stands_beside_the_diagrams_where_their_row_holds_it():
    """The V-compressor's A2 set drew its diagrams (about 330 × 280 mm) alone in a row, 230 mm of the
    sheet's width beside them empty, and its acceleration plan (about 120 × 150 mm) on the next
    sheet with the tables. Flowed with the A2 field's arithmetic: the plan on the diagrams' sheet,
    to their right, in the field; the tables after them."""
    from graphplan.drawing.layout import Leaf, flow
    from graphplan.sheets.compose import field_of, keep_out, later_keep
    from graphplan.sheets.form import form
    from graphplan.sheets.kinlayout import set_rows
    f = form("A2")
    region = field_of(f)
    width = region[2] - region[0]
    P, D = Leaf("position plan", 440.0, 270.0), Leaf("diagrams", 330.0, 280.0)
    V = [Leaf(f"velocity plan {i}", 95.0, 80.0) for i in range(12)]
    A = [Leaf("acceleration plan 1", 120.0, 150.0)]
    tail = [Leaf("velocity table", 240.0, 110.0), Leaf("notes", 185.0, 120.0)]
    pages = flow(set_rows(P, D, V, A, tail, width), region, keep_out(f), later=later_keep(f))
    where = {leaf.name: (i, b) for i, page in enumerate(pages) for leaf, b in page}
    (pd, d), (pa, a) = where["diagrams"], where["acceleration plan 1"]
    assert pa == pd and a[0] >= d[2] - 1e-6
    assert region[0] - 1e-6 <= a[0] and a[2] <= region[2] + 1e-6
    assert where["velocity table"][0] >= pd
    # a plan taller than the diagrams keeps its own row (the row would grow for it)
    tall = [Leaf("acceleration plan 1", 120.0, 300.0)]
    rows = set_rows(P, D, V, tall, tail, width)
    assert not any(any(getattr(c, "name", "") == "diagrams" for c in r) and
                   any(getattr(c, "name", "") == "acceleration plan 1" for c in r) for r in rows if isinstance(r, list))
