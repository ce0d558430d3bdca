"""Review 53 #2: INCLINED_ROCKER53 (a crank-slider on an inclined guide missing the pivot, its slider
driving a rod and rocker; three charts: M_зр, P_B and R03) took TWO A1 force sheets, though A1 is
one sheet. Its three charts, each at least 138 mm wide by its lettering, in one row beside the tables'
column (381 mm in two parts) ran 6 mm over the 806 mm field at every scale; now, where nothing fits
so, the charts wrap two to a row (``_tree``'s ``wrap``). The truths are widths added by hand and
the drawn sheet's page count and boxes."""
from __future__ import annotations

import pytest

from graphplan.drawing.layout import GAP, Leaf, extent


def _leaves():
    return {"scheme": [Leaf("scheme", 150, 100)], "groups": [Leaf("g0", 60, 80)],
            "forces": [Leaf("p0", 100, 60)], "acceleration": [Leaf("acc", 160, 60)],
            "lever": [Leaf("lever", 110, 100)],
            "charts": [Leaf("c0", 140, 110), Leaf("c1", 140, 115), Leaf("c2", 140, 90)], "hodographs": []}


def test_the_charts_row_wraps_two_to_a_row():
    """"low" shape, the tables' column 380 wide: the charts' row in one is 3·140 + 2 gaps wide
    beside the column; wrapped two to a row, 2·140 + 1 gap (the acceleration plan and the lever's
    row 160 + 110 + 1 gap is narrower), and the stack beside the column is one chart row taller."""
    from graphplan.sheets.forces import _tree
    leaves, column = _leaves(), Leaf("column", 380, 300)
    one = extent(_tree("low", leaves, 1, column, cut=0))
    two = extent(_tree("low", leaves, 1, column, cut=0, wrap=2))
    top = 150 + GAP + 60 + GAP + 100          # the scheme, the group beside its plan (SPACE ≤ GAP)
    assert one[0] == pytest.approx(max(top, 3 * 140 + 2 * GAP + GAP + 380), abs=GAP)
    assert two[0] == pytest.approx(2 * 140 + GAP + GAP + 380)
    assert two[0] < one[0] - 140


@pytest.mark.slow
def test_inclined_rocker_forces_fit_one_a1_sheet():
    """INCLINED_ROCKER53's A1 force sheet is one sheet, every drawing clear, the three charts drawn."""
    import review_scenes
    from conftest import scene_study

    from graphplan.sheets.compose import SheetOptions, defects
    from graphplan.sheets.form import form
    from graphplan.sheets.forces import build_forces_sheet
    sheet = build_forces_sheet(scene_study(review_scenes.INCLINED_ROCKER53), form("A1"),
                               SheetOptions(precision=0.5, sheet="forces"))
    assert len(sheet.pages) == 1
    names = {q.name for q in sheet.pages[0].placed}
    assert {"moment", "resistance", "reaction R03", "lever"} <= names, names
    assert defects(sheet) == []
    # frc53b #7: the outer dyad's force plan (the one with R05, the frame's reaction on rocker 5)
    # is drawn to read: its group one step coarser gave it the height (``_plan_over_group``). At
    # 2 N/mm its polygon was 3 × 13 mm, three of its sides under 3 mm named under it.
    plan = next(q.record for q in sheet.pages[0].placed
                if any(t.kind == "vector" and (t.text or "").startswith("R05") for t in q.record.items)
                and any(t.kind == "text" and t.text.startswith("μ_F") for t in q.record.items))
    ends = [complex(*z) for t in plan.items if t.kind == "vector" for z in t.points]
    assert max(z.imag for z in ends) - min(z.imag for z in ends) >= 40.0
    note = next(t.text for t in plan.items if t.kind == "text" and t.text.startswith("μ_F"))
    short = [part.split("<")[0] for part in note.split("; ")[1:] if "<" in part]
    assert sum(len(part.split(", ")) for part in short) <= 1, note     # at most one short side named
