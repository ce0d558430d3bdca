"""Review51 #4 (six.toml's force sheet, the Zhukovsky lever at position 3): a, b and s2 coincide there
(ω2 = 0) and the lever lettered the spot "s2" only — P_зр applied at a with no "a" drawn. The truth:
a central crank-slider at φ = 90° has ω2 = ω1·r·cos φ / (l·cos β) = 0, so a and b (and every point of
the rod) have one velocity image; every image off the pole is lettered, those at one spot in one
label by it ("a, b", as the plan of velocities does)."""
from __future__ import annotations

import pytest

from conftest import example


@pytest.fixture(scope="module")
def lever():
    from graphplan.drawing.forces import lever_record
    from graphplan.graphic import forceplans
    fp = forceplans.construct(example("crank_slider"), 90.0)
    return fp.lever, lever_record(fp, "en")


def test_the_coinciding_images_are_lettered_together(lever):
    lv, rec = lever
    a, b = lv.images["A"], lv.images["B"]
    assert abs(a) > 10.0 and abs(a - b) < 0.05         # ω2 = 0: one spot, off the pole
    spot = 1j * a                                       # the lever is the plan turned by 90°
    texts = [q for q in rec.items if q.kind == "text"]
    names = {t.strip() for q in texts for t in q.text.split(",")}
    assert {"a", "b"} <= names
    q = next(q for q in texts if {t.strip() for t in q.text.split(",")} == {"a", "b"})
    x0, y0, x1, y1 = q.ink()
    gap = abs(complex(max(x0 - spot.real, 0.0, spot.real - x1), max(y0 - spot.imag, 0.0, spot.imag - y1)))
    assert gap < 4.0, gap                               # beside its spot
