"""Stop 58: a point's mark (a pair's ring, a centre of mass's dot) has a box as large as the ink the SVG
draws for it. COULISSE8's A1 force sheet set its scheme's top joint B flush with the field's edge, its
box a bare point: the 1 mm ring stood 1 mm over the field (test_sheet_field)."""
import re

import pytest

from graphplan.graphic.record import Primitive


@pytest.mark.parametrize("role", ["joint", "dot"])
def test_a_points_box_holds_the_ring_or_dot_the_svg_draws(role):
    from graphplan.drawing.svg import _elements
    p = Primitive("point", ((10.0, 20.0),), role=role)
    svg = "".join(_elements(p, 100.0, []))
    r = float(re.search(r' r="([0-9.]+)"', svg).group(1))
    half_stroke = float(re.search(r'stroke-width="([0-9.]+)"', svg).group(1)) / 2
    x0, y0, x1, y1 = p.bounds()
    ink = r + half_stroke
    assert (x0, y0, x1, y1) == pytest.approx((10.0 - ink, 20.0 - ink, 10.0 + ink, 20.0 + ink))
