"""Review 53 (frc53b #7): INCLINED_ROCKER53's II(4-5) force plan is drawn small (2 N/mm, about
19 × 25 mm) on its one A1 sheet. The size model ``ForceDrafter.plan_size`` must count the plan as it
is drawn: measured here item by item on the drawn record (the lines' box, each lettering's ink), in
both languages, against the model's cell. At the steps the sheet tries (2.5 … 0.5 N/mm) the cell is
as wide as the sheet's caption under the plan ("Force plan of group II(4-5)", 5 mm) — neither the
figure nor its list of the forces too short to draw ("R24τ, R05n, R45 < 3 mm") sets its width; it is
the height (the polygon a tall sliver) that the one-sheet composition has no room for."""
from __future__ import annotations

import pytest

# the sheet's scales as its plan chose them (inputs of the drawing, not checked here)
MU = {"scheme": 0.002, "groups": 0.002, "forces": 20.0, "acceleration": 0.4, "lever": 0.0125,
      "charts": 1.0, "hodographs": 1.5625}


@pytest.fixture(scope="module")
def drafter():
    import review_scenes
    from conftest import scene_study

    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.forces import ForceDrafter
    return ForceDrafter(scene_study(review_scenes.INCLINED_ROCKER53), SheetOptions(precision=0.5, sheet="forces"))


def _measured(rec) -> tuple[float, float, float]:
    """The record's width and height from its items (the lines' box, every lettering's ink) and
    the width of its widest line of lettering."""
    from graphplan.graphic.record import Record
    lines = Record(items=[q for q in rec.items if q.kind != "text"]).bounds()
    inks = [q.ink() for q in rec.items if q.kind == "text"]
    xs = [lines[0], lines[2]] + [x for b in inks for x in (b[0], b[2])]
    ys = [lines[1], lines[3]] + [y for b in inks for y in (b[1], b[3])]
    return max(xs) - min(xs), max(ys) - min(ys), max([b[2] - b[0] for b in inks] + [0.0])


@pytest.mark.parametrize("mu_F", [2.0, 1.0])
def test_the_plan_cell_is_the_plan_as_drawn(drafter, mu_F):
    from graphplan.drawing import forces as forcedraw
    from graphplan.sheets.forces import group_scales, plan_scales
    labels = [g.label for g in drafter.groups_fp(MU).groups]
    i = labels.index("II(4-5)")
    caption = (forcedraw._caption_across("II(4-5)"), 10.0)
    w, h = drafter.plan_size(MU, i, mu_F, caption)
    own = tuple(sorted({**dict(plan_scales(MU)), "II(4-5)": mu_F}.items()))
    fp = drafter.fp(MU["groups"], MU["forces"], MU["lever"], group_scales(MU), own)
    drawn = [_measured(forcedraw.polygon_record(fp, fp.groups[i], lang)) for lang in ("uk", "en")]
    assert w == pytest.approx(max([d[0] for d in drawn] + [caption[0]]), abs=0.5)
    assert h == pytest.approx(max(d[1] for d in drawn) + caption[1], abs=0.5)
    # the list of short forces is no wider than the sheet's caption: it does not set the cell
    assert max(d[2] for d in drawn) <= caption[0]
    assert w == pytest.approx(caption[0], abs=0.5)
