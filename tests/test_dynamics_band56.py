"""Stop 56: the energy–mass diagram's I* values under its foot and the turned I*(φ)'s projections
that come up to that foot. The band is drawn as two records meeting at the foot: the energy–mass
diagram broke its own projections under each value (1.2 mm clear), but the turned I*(φ)'s pieces ran
on up to the foot, 0.4 mm under «2,5» and «10,0» on the shaper's A1 (`defects` sent it back). The
band as the sheet composes it (`sheets.dynamics.band`, both records joined) is read here with the
check the composition uses (`drawing.labels.collisions`): no lettering touches a line."""
from __future__ import annotations

import pytest
from conftest import example, scene_study


def _scene(name):
    import review_scenes as R
    return example(name) if name in ("shaper", "slotter") else scene_study(getattr(R, name))


@pytest.mark.slow
@pytest.mark.parametrize("name", ["shaper", "slotter", "LINK55"])
def test_no_value_of_the_band_touches_a_projection(name):
    from graphplan.drawing.labels import collisions
    from graphplan.exact.dynamics import analyse
    from graphplan.graphic.flywheel import redrawn
    from graphplan.sheets.dynamics import FOOT_CLEAR, _union, band, dynamics_scales, lettering_foot
    st = _scene(name)
    dyn = analyse(st, None)
    s = dynamics_scales(st, dyn, "A1")
    f = redrawn(dyn, None, 0.5, given=None, **s)
    for length in (0.5 * s["L"], 0.75 * s["L"], s["L"]):
        for lang in ("uk", "en"):
            parts, boxes = band(f, lang, length)
            foot = boxes["wittenbauer"][1]
            assert lettering_foot(parts["wittenbauer"], boxes["wittenbauer"][0]) >= foot + FOOT_CLEAR - 1e-9
            assert collisions(_union(parts)) == [], (name, length, lang)
