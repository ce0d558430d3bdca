"""Review 55 #1: the A1 force sheet's scheme and groups drawn as large as the composition allows."""
from __future__ import annotations

import pytest

from conftest import scene_study


@pytest.mark.slow
def test_the_a1_scheme_is_not_left_small_where_the_lever_and_the_acceleration_plan_could_give_way():
    """LAYOUT.md's "the scheme left, large", as a property of the one-sheet composition: with the
    scheme and the groups a standard step larger, no smaller lever (its μv choices) or acceleration
    plan (the series' steps) that each stay larger against their targets than the smallest main
    drawing as chosen fits the sheet in the chosen arrangement — searched exhaustively here, not by
    the planner's growth. The beam pump's A1 sheet drew them at 1:10 beside ~180 × 85 mm blank while
    1:5 fitted with the lever at 0.0293 (m/s)/mm, smaller than its 0.0219 but still 0.30 of its
    target against the scheme's 0.25 (review 55 #1)."""
    import review_scenes
    from graphplan.graphic.scales import larger_choices, series_around
    from graphplan.sheets import forces as sf
    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.form import form
    st = scene_study(review_scenes.BEAM_PUMP55)
    f = form("A1")
    p, nat, dr = sf.plan(st, f, SheetOptions(precision=0.5, sheet="forces"))
    fam = nat.families
    assert p.sheets == 1 and p.mu["groups"] <= p.mu["scheme"] * (1 + 1e-9)
    least = min(fam[n].rel(p.mu[n]) for n in sf.MAIN)
    s1 = fam["scheme"].finer(p.mu["scheme"])
    lv = fam["lever"]
    levers = sorted({p.mu["lever"]} | {m for m, _ in larger_choices(lv.principal, p.mu["lever"] * 4, lv.principal / p.mu["lever"])
                                       if m > p.mu["lever"]})
    accels = sorted({p.mu["acceleration"]} | {m for m in series_around(p.mu["acceleration"]) if m > p.mu["acceleration"]})
    base = {k: v for k, v in p.mu.items() if k in sf.FAMILIES}
    for m_v in levers:
        for m_a in accels:
            if min(fam["lever"].rel(m_v), fam["acceleration"].rel(m_a)) <= least * (1 + 1e-9):
                continue
            mu = {**base, "scheme": s1, "groups": s1, "lever": m_v, "acceleration": m_a}
            assert not sf._fits(nat, f, p, sf._leaves(nat, mu)), (p.mu, m_v, m_a)
