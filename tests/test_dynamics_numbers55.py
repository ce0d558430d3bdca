"""Stop 55: the energy–mass diagram's point numbers read as their own points' and as numbers. A
steep line beside a digit reads as a "1" (the shaper's "2" 0.5 mm right of its vertical projection
read "12"; LINK55's "7" and "4" right of theirs read "17", "14"), so a number keeps 1.2 mm of paper
from every steep line (within 30° of the vertical) — nor sits on one broken under it, whose stub
over the digit reads "|7" the same (the point's own projection ending at it aside) — only from steep
lines: a uniform 1.2 mm pushed point 0, on its own horizontal axis, 3.9 mm off (review 4 asks
≤ 3 mm). A number set beside its point stands within 3 mm of it; the others hang on a leader from
it. A property of the drawn ink (shapely), on several mechanisms at two constructions each."""
from __future__ import annotations

import math

import pytest
from conftest import example, scene_study

SIDEWAYS = 1.2     # mm of paper between a number's ink and a steep line's ink at its side
BESIDE = 3.0       # mm: a number with no leader at most this far from its point (review 4)
STEEP = math.tan(math.radians(30.0))


def _scene(name):
    import review_scenes as R
    return example(name) if name in ("shaper", "slotter") else scene_study(getattr(R, name))


@pytest.mark.slow
@pytest.mark.parametrize("name", ["shaper", "slotter", "PRESS4", "LINK55", "CYLINDER_REVIEW54", "LINK53"])
@pytest.mark.parametrize("L, size", [(330.0, 1.0), (200.0, 0.7)])
def test_point_numbers_stand_clear_of_steep_lines_and_near_their_points(name, L, size):
    from graphplan.drawing.flywheel import wittenbauer_record
    from graphplan.exact.dynamics import analyse
    from graphplan.graphic.flywheel import redrawn
    from graphplan.sheets.dynamics import band
    f = redrawn(analyse(_scene(name), None), None, 0.5, L=L, size=size, given=None)
    check(f, wittenbauer_record(f, "uk", projections=(-20.0, -20.0)), name)
    check(f, band(f, "uk", 0.5 * L)[0]["wittenbauer"], name)     # as the sheet draws it: the projections
    #                                                              from ΔT(φ) and the turned I*(φ)


def check(f, rec, name):
    from shapely.geometry import LineString, Point, box
    steep = []
    for p in rec.items:
        if p.kind in ("segment", "polyline", "vector") and p.role != "label":
            for a, b in zip(p.points, p.points[1:]):
                dx, dy = abs(b[0] - a[0]), abs(b[1] - a[1])
                if dy > 1e-9 and dx <= STEEP * dy:
                    steep.append((LineString([a, b]), p.line_width / 2))
    leaders = {p.step: LineString(p.points) for p in rec.items if p.kind == "segment" and p.role == "label"}
    seen, resort = 0, 0
    for p in rec.items:
        if p.kind != "text" or not (p.step or "").startswith("point ") or not p.text.isdigit():
            continue
        seen += 1
        j = int(p.text)
        at = Point(float(f.I[j]), float(f.dT[j]))
        x0, y0, x1, y1 = p.ink()
        ink = box(x0, y0, x1, y1)
        if p.step in leaders:
            assert leaders[p.step].distance(at) <= 1.5, (name, j)
        else:
            assert ink.distance(at) <= BESIDE + 1e-9, (name, j, round(ink.distance(at), 2))
        near = [line for line, half in steep            # none nearer, but the point's own lines that end
                if line.distance(ink) - half < SIDEWAYS - 1e-6   # at it (its projection)
                and min(Point(c).distance(at) for c in (line.coords[0], line.coords[-1])) > 0.9]
        if p.step in leaders:       # a leader's number near one only as the last resort (no spot kept clear):
            resort += bool(near)    # the cylinder's 24 points in 75 × 55 mm
        else:
            assert not near, (name, j, [round(line.distance(ink), 2) for line in near])
    assert seen == len(f.I) - 1        # every division numbered (the last point is point 0 again)
    assert resort <= seen // 10, (name, resort)
