"""The Zhukovsky lever's arms each named once (review 7 #8: twenty arms' names knotted at b, d, s4),
measured on the drawing itself at the lever's own μv (v_A / p_a, the lab's rule): every arm h
drawn — a segment from the pole p_v, its text "h_{…} = … mm to F" — is named by exactly one label,
and two forces on one line share one arm and one name (h_{G3,Φ3,P_B})."""
from __future__ import annotations

import pytest

from conftest import scene_study
from review_scenes import PRESS_EN, SIXBAR


@pytest.fixture(scope="module", params=["sixbar", "press"])
def lever(request):
    from graphplan.drawing.forces import lever_record
    from graphplan.sheets import forces as sf
    from graphplan.sheets.compose import SheetOptions
    st = scene_study(SIXBAR if request.param == "sixbar" else PRESS_EN)
    fp = sf.ForceDrafter(st, SheetOptions(precision=0.5, sheet="forces")).fp()
    return request.param, fp, lever_record(fp, "uk")


def test_every_arm_is_named_once(lever):
    name, fp, rec = lever
    arms = {p.text.split(" = ")[0][3:-1] for p in rec.items
            if p.kind == "segment" and p.text.startswith("h_{") and " mm to " in p.text}
    assert arms
    from graphplan.drawing.forces import arm_symbol
    armed = {arm_symbol(t.name)[3:-1] for t in fp.lever.terms if t.vector and abs(t.arm_mm) >= 1.0}
    assert arms == armed, (name, arms, armed)
    named = [s for q in rec.items if q.kind == "text" and q.text.startswith("h_{") for s in q.text[3:-1].split(",")]
    assert sorted(named) == sorted(arms), (name, named, sorted(arms))
