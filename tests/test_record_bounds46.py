"""Record.bounds holds a vector's arrowhead as the SVG draws it (stop 46: a horizontal force's head
stood 0.6 mm over the field of PUMP45's A3 force set, the composition trusting a box of its shaft)."""
from __future__ import annotations

import math
import re

import pytest


def _drawn_points(prim) -> list[tuple[float, float]]:
    """Every point of the primitive's SVG elements (lines' ends, the head's polygon), drawing mm."""
    from graphplan.drawing.svg import _elements
    h = 0.0                                       # the SVG's y = h − y
    out = []
    for el in _elements(prim, h, []):
        nums = [float(v) for v in re.findall(r'(?:x1|x2|y1|y2)="([-\d.e]+)"', el)]
        if nums:
            x1, x2, y1, y2 = nums
            out += [(x1, h - y1), (x2, h - y2)]
        m = re.search(r'points="([^"]+)"', el)
        if m:
            vals = [float(v) for v in re.split(r"[ ,]+", m.group(1).strip())]
            out += [(x, h - y) for x, y in zip(vals[::2], vals[1::2])]
    return out


@pytest.mark.parametrize("role", ["force", "construction", "head"])
@pytest.mark.parametrize("deg", [0.0, 30.0, 90.0, 135.0, 200.0])
def test_a_vectors_bounds_hold_its_drawn_arrowhead(role, deg):
    from graphplan.graphic.record import Record
    rec = Record("t")
    a = (5.0, 7.0)
    b = (a[0] + 12.0 * math.cos(math.radians(deg)), a[1] + 12.0 * math.sin(math.radians(deg)))
    prim = rec.vector(a, b, role=role)
    x0, y0, x1, y1 = prim.bounds()
    pts = _drawn_points(prim)
    assert len(pts) >= 5
    for x, y in pts:
        assert x0 - 1e-3 <= x <= x1 + 1e-3 and y0 - 1e-3 <= y <= y1 + 1e-3, (role, deg, (x, y), (x0, y0, x1, y1))
    if deg == 0.0 and role != "head":            # the head stands out of the shaft's line across it
        assert y1 - y0 > 1.0
