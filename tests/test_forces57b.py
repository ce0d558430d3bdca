"""Stop 57b: a reaction the ruler reads 0 mm (or one division) on its force plan is read off the plan's
detail — the spot drawn again at a finer μF_I, as the crank group's plan draws its G1 — not printed 0.
FRC56_PUMP's R05 (the vertical plunger's guide, 1.18 N exact) is 0.23 mm at the sheet's 5 N/mm: the
ruler read it 0 mm and Table 7 printed R05 = 0 (−100 %)."""
from __future__ import annotations

import pytest

from conftest import group_of, scene_force_plans
from graphplan.drawing.forces import polygon_record
from graphplan.graphic.draftsman import measure
from review_scenes import FRC56_PUMP, INCLINED_ROCKER53, YOKE_ROCKER51

LAB_LIMIT = 5.0


@pytest.fixture(scope="module")
def pump():
    # the sheet's scale of II(4-5)'s plan (its caption "μF = 5 Н/мм; Rτ24, R05 < 3 мм")
    return scene_force_plans(FRC56_PUMP, group_mu_F={"II(4-5)": 5.0})


def test_a_reaction_the_ruler_reads_0_mm_is_read_off_the_detail_within_the_labs_limit(pump):
    gp = group_of(pump, "II(4-5)")
    side = next(s for s in gp.sides if s.name == "R05")
    assert measure(side.mm, pump.precision) == 0.0          # the plan's own side: under half a division
    m = gp.reactions["R05"]
    assert 0 < m.detail_mu <= 5.0 / 2
    assert m.mm >= 4.0 - pump.precision / 2                  # drawn at least READ_DETAIL_MM long there
    assert m.value == pytest.approx(m.mm * m.detail_mu)      # the detail's reading times its μF_I
    # the exact closed form's 1.18 N (kinetostatics), not the 0 the plan's ruler gave
    assert m.analytic == pytest.approx(1.18, abs=0.01)
    assert abs(m.value - m.analytic) / m.analytic * 100 < LAB_LIMIT


def test_the_plans_detail_is_drawn_at_the_scale_the_reaction_was_read_at(pump):
    gp = group_of(pump, "II(4-5)")
    rec = polygon_record(pump, gp, "uk")
    assert rec.scales.get("mu_F detail") == gp.reactions["R05"].detail_mu
    texts = [q.text for q in rec.items if q.kind == "text"]
    assert any("0,25" in t and t.startswith("I (") for t in texts)


def test_where_no_corner_of_the_plan_is_free_the_detail_goes_under_it_with_its_mark_on_a_longer_leader():
    # the English sheet draws II(4-5) at 20 N/mm: R05 0.075 mm, read at 1 N/mm; its spot is where P_D,
    # R24, R45 and the closing lines meet at the plan's foot — the table's "1.5 (I)" needs the detail drawn
    fp = scene_force_plans(FRC56_PUMP, group_mu_F={"II(4-5)": 20.0})
    gp = group_of(fp, "II(4-5)")
    m = gp.reactions["R05"]
    assert m.detail_mu == 1.0 and m.mm == 1.5
    for lang in ("uk", "en"):
        assert polygon_record(fp, gp, lang).scales.get("mu_F detail") == m.detail_mu


def test_a_detail_reads_the_drawn_side_to_its_own_ruler_and_a_zero_reaction_takes_none():
    # INCLINED_ROCKER53's R45 (3.76 N exact) is 0.4 mm at 20 N/mm: read off the detail, its value is the
    # side drawn there to the detail's half-division — the polygon laid again at μF_I, its knowns rounded
    # there (stop 59: the plan's side enlarged carried the plan's ±5 N a known and read 7 N, +86 %)
    fp = scene_force_plans(INCLINED_ROCKER53)
    read = [m for g in fp.groups for m in g.reactions.values() if m.detail_mu]
    assert read
    for m in read:
        gp = next(g for g in fp.groups if m.key in g.reactions)
        side = next(s for s in gp.sides if s.name == m.name)
        assert measure(side.mm, fp.precision) < 1.0
        fine = next(s for s in gp.detail_sides if s.name == m.name)
        assert abs(m.value - fine.mm * m.detail_mu) <= m.detail_mu * fp.precision / 2 + 1e-9
    # a reaction exactly 0 (the yoke's guide, no sideways load) is 0, with no detail at a 1e-14 N/mm
    yoke = scene_force_plans(YOKE_ROCKER51)
    assert all(m.detail_mu == 0 for g in yoke.groups for m in g.reactions.values() if m.analytic < 1e-6)
