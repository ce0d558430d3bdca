"""Stop 52: the lead's eight-bar LINK52 on two A1 force sheets (one sheet since: A1 is one sheet
where one holds). Sheet 1 left a 200 × 400 mm blank under its scheme: group II(4-5), read after
group II(6-7) (which ends 190 mm down), had a place under the scheme whose depth there (184 mm)
was 6 mm too high to read after it, so the skyline skipped that column and set the group right of
the scheme. Sheet 2 set its eight hodographs as a row of seven and one alone over a 480 × 120 mm
hole. The truths are the skyline's places measured by hand, and the drawn sheet's boxes."""
from __future__ import annotations

import pytest


def test_a_group_goes_under_the_scheme_lowered_to_read_after_the_group_before():
    """A 800 × 550 field: the scheme 184 × 152 at the top-left, the acceleration plan beside it
    (194…345, 174 deep), the first group 355…596 × 180; the next group (319 × 135) must read after
    the first (wholly right of it, or from 190 mm down). Under the scheme it reaches 184 mm deep
    (the plan's foot and the gap): lowered to 190 it fits there, at x = 0 — not right of the scheme."""
    from graphplan.drawing.layout import Leaf
    from graphplan.sheets import forceset as fs
    page = fs.Skyline(800.0, 550.0, 615.0, 495.0, 10.0)
    for name, x, w, h in (("scheme", 0, 184, 152), ("acceleration", 194, 151, 174), ("group II(6-7)", 355, 241, 180)):
        page.put(fs.Spot(Leaf(name, w, h), x, 0, w, h))
    first = page.spots[-1]
    x, d = page.where(319, 135, follows=first)
    assert (x, d) == pytest.approx((0.0, 190.0))
    # read after the first group: wholly under it
    assert d >= first.d + first.h + 10.0 - 1e-9


def largest_blank_square(boxes, field, keep, step: float = 5.0) -> float:
    """The side (mm) of the largest square of the field that no drawing's box and not the title
    block's corner meets, on a ``step`` mm grid (the classic largest-square dynamic programme over
    the free cells)."""
    x0, y0, x1, y1 = field
    nx, ny = int((x1 - x0) // step), int((y1 - y0) // step)
    busy = [[False] * nx for _ in range(ny)]
    for bx0, by0, bx1, by1 in list(boxes) + [keep]:
        for j in range(max(0, int((by0 - y0) // step)), min(ny, int((by1 - y0) // step) + 1)):
            for i in range(max(0, int((bx0 - x0) // step)), min(nx, int((bx1 - x0) // step) + 1)):
                busy[j][i] = True
    best, prev = 0, [0] * nx
    for j in range(ny):
        cur = [0] * nx
        for i in range(nx):
            if not busy[j][i]:
                cur[i] = 1 + (min(prev[i], cur[i - 1], prev[i - 1]) if i and j else 0)
                best = max(best, cur[i])
        prev = cur
    return best * step


def test_largest_blank_square_measures_a_hole():
    """A 100 × 100 field with one box over its left half: the blank right half holds a 50 mm
    square (less a grid cell where the box's edge falls)."""
    side = largest_blank_square([(0, 0, 50, 100)], (0, 0, 100, 100), (200, 200, 210, 210))
    assert 40.0 <= side <= 50.0


@pytest.mark.slow
def test_link52s_a1_forces_sheet_leaves_no_large_hole():
    """LINK52's A1 forces, measured on the drawn sheet. Stop 52 drew two A1 sheets; A1 is one sheet
    where one holds (``plan``), and LINK52's has been one since before stop 58 (the test asked for two
    from then to stop 59). The hodographs' rows hold as many each, within one (3 + 3 + 2 — stop
    52's sheet 2 set 7 + 1); no blank square of 180 mm (stop 52's sheets had 190 × 400 mm under the
    scheme and a 270 mm square between the tables and the notes); every drawing inside the field."""
    from conftest import scene_study
    from review_scenes import LINK52
    from graphplan.sheets.compose import SheetOptions, field_of, keep_out
    from graphplan.sheets.forces import build_forces_sheet
    from graphplan.sheets.form import form
    f = form("A1")
    sheet = build_forces_sheet(scene_study(LINK52), f, SheetOptions(lang="uk", sheet="forces"))
    assert len(sheet.pages) == 1
    hods = [pl for page in sheet.pages for pl in page.placed if pl.name.startswith("hodograph")]
    assert len(hods) == 8
    rows: dict[float, int] = {}
    for pl in hods:
        rows[round(pl.box[3], 3)] = rows.get(round(pl.box[3], 3), 0) + 1
    assert max(rows.values()) - min(rows.values()) <= 1, rows
    x0, y0, x1, y1 = field_of(f)
    for page in sheet.pages:
        boxes = [pl.record.bounds() for pl in page.placed]
        for b in boxes:
            assert x0 - 1e-6 <= b[0] and b[2] <= x1 + 1e-6 and y0 - 1e-6 <= b[1] and b[3] <= y1 + 1e-6, b
        assert largest_blank_square(boxes, field_of(f), keep_out(f)) < 180.0


def test_tables_columns_spread_to_the_notes():
    """Three columns of tables 10 mm apart at the left of a 800 mm wide sheet (x 0, 136, 404; the
    last 140 wide), the notes at x 625…806 from 447 mm down: the columns' lefts stretched from 0
    alike until the 132 mm wide T7 comes 10 mm before the notes (its foot, 489 mm, is under their
    top; T6 over it ends 320 mm down, above them) — s = (625 − 10 − 132) / 404; a table alone in
    its column keeps its place."""
    from graphplan.drawing.layout import Leaf
    from graphplan.sheets import forceset as fs
    spots = [fs.Spot(Leaf(n, w, h), x, d, w, h, fixed=True) for n, x, d, w, h in (
        ("T1", 0, 286, 126, 263), ("T2", 136, 286, 236, 91), ("T3", 136, 388, 258, 34),
        ("T6", 404, 286, 140, 34), ("T7", 404, 330, 132, 159), ("notes", 625, 447, 181, 111))]
    out = fs._columns_spread(spots, 806.0, 620.0, 500.0, 10.0)
    s = (625 - 10 - 132) / 404
    assert [q.x for q in out] == pytest.approx([0, 136 * s, 136 * s, 404 * s, 404 * s, 625], abs=1e-6)
    assert [q.d for q in out] == [q.d for q in spots]
    one = [spots[0], spots[-1]]
    assert fs._columns_spread(one, 806.0, 620.0, 500.0, 10.0) == one
