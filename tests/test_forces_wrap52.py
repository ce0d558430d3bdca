"""Stop 52: the one-sheet A1 force composition let the lever's row wrap. ROCKING_BLOCK51 drew its
lever 80 × 70 mm (μv 0.0209) between the acceleration plan and the M_зр chart — P_C's and Φ5's heads
2 mm apart at c — while the row under it (the other two charts) was half empty: the lever's row always
held the first chart. Now the composer may move every chart to the row under the lever (``_tree``'s
``cut``). The truths are widths added by hand and the drawn sheet's boxes."""
from __future__ import annotations

import pytest

from graphplan.drawing.layout import GAP, Leaf, arrange, extent


def _leaves():
    return {"scheme": [Leaf("scheme", 200, 150)], "groups": [Leaf("g0", 90, 80), Leaf("g1", 60, 70)],
            "forces": [Leaf("p0", 100, 60), Leaf("p1", 80, 50)], "acceleration": [Leaf("acc", 150, 100)],
            "lever": [Leaf("lever", 220, 140)], "charts": [Leaf("c0", 160, 90), Leaf("c1", 140, 90),
                                                           Leaf("c2", 150, 90)],
            "hodographs": []}


def test_the_lever_row_wraps_its_charts_to_the_row_under_it():
    """"column" shape, the tables' column 300 wide, the scheme beside the groups (each beside its
    plan) 406 wide: with the first chart beside them, the
    acceleration plan, the lever and the chart make a row 150 + 220 + 160 + 2 gaps wide; wrapped
    (cut 0), the widest row is the three charts, 150 + 140 + 160 + 2 gaps, and every chart lies
    wholly under the lever."""
    from graphplan.sheets.forces import SPACE, _tree
    leaves, column = _leaves(), Leaf("column", 300, 300)
    unwrapped = extent(_tree("column", leaves, 1, column))[0]
    wrapped = extent(_tree("column", leaves, 1, column, cut=0))[0]
    assert unwrapped == pytest.approx(max(200 + GAP + 90 + SPACE + 100, 150 + 220 + 160 + 2 * GAP) + GAP + 300)
    assert wrapped == pytest.approx(max(200 + GAP + 90 + SPACE + 100, 150 + 140 + 160 + 2 * GAP) + GAP + 300)
    boxes = {leaf.name: b for leaf, b in arrange(_tree("column", leaves, 1, column, cut=0), (0, 0, 1200, 900))}
    assert all(boxes[c][3] <= boxes["lever"][1] + 1e-6 for c in ("c0", "c1", "c2"))


@pytest.mark.slow
def test_rocking_block_lever_is_drawn_large_on_its_a1_sheet():
    """ROCKING_BLOCK51's A1 force sheet (one sheet): its lever drawn at least 100 mm across (was
    about 80 × 70 mm beside the M_зр chart), no chart beside it in its row, every drawing clear."""
    import review_scenes
    from conftest import scene_study

    from graphplan.sheets.compose import SheetOptions, defects
    from graphplan.sheets.form import form
    from graphplan.sheets.forces import build_forces_sheet
    sheet = build_forces_sheet(scene_study(review_scenes.ROCKING_BLOCK51), form("A1"),
                               SheetOptions(precision=0.5, sheet="forces"))
    assert len(sheet.pages) == 1
    boxes = {q.name: q.record.bounds() for q in sheet.pages[0].placed}
    lever = boxes["lever"]
    assert max(lever[2] - lever[0], lever[3] - lever[1]) >= 100.0, lever
    for name in ("moment", "resistance", "reaction R05"):
        b = boxes[name]
        assert b[3] <= lever[1] or b[1] >= lever[3], (name, b, lever)     # not in the lever's band
    assert defects(sheet) == []


@pytest.mark.slow
def test_the_shapers_lever_stays_within_lever_mm_with_the_row_wrapped():
    """The gallery shaper's A1 force sheet with the lever's row wrapped (it drew its lever 172 mm
    across: the last growth into the room left went up to 200 mm): the lever's lines, measured on the
    composed sheet, at most ``LEVER_MM`` across, and at least 100 mm (seed 000's p_v c is 102 mm)."""
    from conftest import example_sheet

    from graphplan.graphic.record import Record
    from graphplan.sheets.forces import LEVER_MM
    sheet = example_sheet("shaper", "forces")
    lever = next(q.record for q in sheet.pages[0].placed if q.name == "lever")
    b = Record(items=[q for q in lever.items if q.kind != "text"]).bounds()
    assert 100.0 <= max(b[2] - b[0], b[3] - b[1]) <= LEVER_MM + 1e-6, b


def test_a_force_point_off_the_links_points_is_not_lettered_as_its_centre_of_mass():
    """WEDGE52's wedge 3 (one point, B — its centre of mass, the scene naming none): R03 and R43 act
    30 mm along the guide from B, a point of no name — not "S3", which would read as the centre of
    mass; at B the point is B."""
    from types import SimpleNamespace

    from graphplan.drawing.forces import _point_name
    link = SimpleNamespace(local={"B": 0j}, com=None, number=3, joints=["B"])
    body = SimpleNamespace(at=lambda local: [[complex(0.10, 0.02) + local]])
    fp = SimpleNamespace(ks=SimpleNamespace(mech=SimpleNamespace(links={"3": link}),
                                            kin=SimpleNamespace(bodies={"3": body})))
    mu = 0.002
    b = complex(0.10, 0.02) / mu
    assert _point_name(fp, "3", b, mu) == "B"
    assert _point_name(fp, "3", b + 30.0, mu) == ""
