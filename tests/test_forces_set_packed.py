"""The fifth review's sent-back force set (item 1): a desaxial press with a vertical ram drew its force
analysis on seven A3 sheets, three of them 84–87 % empty — one tall, narrow drawing to a row. The
set now runs the drawings together (a group beside its force plan) and the sheets' rows take them
side by side while they fit across: fewer sheets, the reading order kept."""
from __future__ import annotations

from conftest import scene_study
from graphplan.sheets.compose import SheetOptions, defects
from graphplan.sheets.form import form
from review_scenes import PRESS_EN


def test_a_tall_narrow_mechanisms_force_set_packs_its_drawings():
    from graphplan.sheets.forces import build_forces_sheet, plan
    st = scene_study(PRESS_EN)
    p, _, _ = plan(st, form("A3"), SheetOptions(precision=0.5, sheet="forces"))
    assert p.shape == "set" and p.packed and p.sheets <= 5          # seven before
    sheet = build_forces_sheet(st, form("A3"), SheetOptions(precision=0.5, lang="en", sheet="forces"))
    assert len(sheet.pages) <= p.sheets and defects(sheet) == []
    names = [[pl.name for pl in page.placed] for page in sheet.pages]
    flat = [n for page in names for n in page]
    assert flat[0] == "mechanism"                                  # the reading order kept
    assert flat.index("group II(2-3)") < flat.index("group I(0-1)") < flat.index("lever")
    for page in names:                                             # a group beside its own force plan
        for n in page:
            if n.startswith("group "):
                assert "polygon " + n.split()[1] in page, (n, page)
