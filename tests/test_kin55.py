"""Stop 55 (kinematics): a set's sheet is not left half empty where the next table could stand on it
(LEFT54: the blind review's A3 coupler-slider set, sheet 4 — one acceleration plan and Table 1 over
an empty lower half, Table 2 on sheet 5; the jaw crusher's A2 sheet 3, a 380 × 80 mm band). The
tables joined the last plan's row one beside another, so a table too tall for the room beside the
plan went to the next sheet though the room under Table 1 held it; the first tables may now stand
one over another as one column beside the plan (``kinlayout.set_tail``'s ``beside``)."""
from __future__ import annotations

import numpy as np
import pytest

import review_scenes
from conftest import scene_study
from graphplan.drawing.layout import GAP, Leaf, Stack, flow
from graphplan.sheets.compose import SheetOptions, field_of, keep_out, later_keep
from graphplan.sheets.form import form
from graphplan.sheets.kinlayout import _empty_rect, _lines, set_blanks, set_rows, set_tail
from test_kin_review47 import _holds

CELL = 2.0      # mm: the grid the free room of a drawn sheet is measured on


def _free(page, n: int) -> np.ndarray:
    """The drawn sheet's field as cells, True where no drawing's, table's or note's ink and no title
    block lies (form 1 on the first sheet, 2a on the later ones)."""
    f = page.form
    x0, y0, x1, y1 = field_of(f)
    free = np.ones((int((y1 - y0) / CELL), int((x1 - x0) / CELL)), dtype=bool)
    for b in [keep_out(f) if n == 0 else later_keep(f)] + [p.record.bounds() for p in page.placed]:
        i0, i1 = int((b[0] - x0) // CELL), int(np.ceil((b[2] - x0) / CELL))
        j0, j1 = int((b[1] - y0) // CELL), int(np.ceil((b[3] - y0) / CELL))
        free[max(j0, 0):max(j1, 0), max(i0, 0):max(i1, 0)] = False
    return free


def _tables(page) -> list:
    return [p for p in page.placed if "table" in p.name]


def test_tables_beside_the_last_plan_stand_one_over_another_and_fill_the_sheet():
    """Rows as the A3 coupler-slider's sheet 4 had them (sizes from its set, rounded): the last
    acceleration plan 150 × 240 mm with Table 1 (170 × 90) beside it, Table 2 (140 × 120) too wide
    for the rest of the row. One beside another, Table 2 goes to the next sheet and the sheet under
    Table 1 stays blank; as one column beside the plan, Table 2 stands under Table 1 on the same
    sheet, the reading order kept (Table 1 over Table 2, both right of the plan), no more sheets."""
    f = form("A3")
    region = field_of(f)
    width = region[2] - region[0]
    P, D = Leaf("position", 190.0, 200.0), Leaf("diagrams", 180.0, 200.0)
    A = [Leaf("acceleration 0", 150.0, 240.0)]
    tabs = [Leaf("t1", 170.0, 90.0), Leaf("t2", 140.0, 120.0), Leaf("t3", 150.0, 100.0)]
    notes = Leaf("notes", 185.0, 60.0)

    def laid(beside: tuple):
        return flow(set_rows(P, D, [], A, set_tail(tabs, notes, 0, beside), width), region, keep_out(f),
                    later=later_keep(f), ragged=True)
    flat, column = laid(()), laid((1, 1))
    assert flat is not None and column is not None
    where = {n: {leaf.name: (k, b) for k, page in enumerate(pages) for leaf, b in page}
             for n, pages in (("flat", flat), ("column", column))}
    # one beside another, Table 2 went to the next sheet; since stop 59 the plan's row is a shelf whose
    # line of columns (``layout._columns``) sets it under Table 1 there too
    assert where["flat"]["t2"][0] == where["flat"]["acceleration 0"][0]
    k, b1 = where["column"]["t1"]
    assert where["column"]["t2"][0] == k == where["column"]["acceleration 0"][0]
    b2 = where["column"]["t2"][1]
    a = where["column"]["acceleration 0"][1]
    assert b1[1] >= b2[3] - 1e-6 and min(b1[0], b2[0]) >= a[2] - 1e-6          # T1 over T2, right of the plan
    assert len(column) <= len(flat)
    blank = lambda pages: max(set_blanks(pages, f)[:-1], default=0.0)
    assert blank(column) <= blank(flat) + 1e-6


def test_set_tail_keeps_the_reading_order_of_the_tables():
    """The column beside the plan holds the first tables in order; the rest follow; the notes last
    (and, stacked, over the notes as before)."""
    tabs = [Leaf(f"t{i}", 100.0, 50.0) for i in range(1, 5)]
    notes = Leaf("notes", 185.0, 60.0)

    def names(node):
        return [node.name] if isinstance(node, Leaf) else [n for c in node.children for n in names(c)]
    for stacked in (0, 1, 2):
        for beside in _lines(4, 4):
            tail = set_tail(tabs, notes, stacked, beside)
            assert [n for item in tail for n in names(item)] == ["t1", "t2", "t3", "t4", "notes"]
            if sum(beside) <= 4 - stacked:
                assert isinstance(tail[0], Stack) and names(tail[0]) == [f"t{i}" for i in range(1, sum(beside) + 1)]
                assert len(tail[0].children) == len(beside)


def test_lines_are_every_way_to_break_the_first_tables_in_order():
    """``_lines(4, 3)``: the first 2 or 3 tables in two or more lines — (1, 1); (1, 2), (2, 1),
    (1, 1, 1) — each once."""
    assert sorted(_lines(4, 3)) == sorted([(1, 1), (1, 2), (2, 1), (1, 1, 1)])
    assert list(_lines(1, 4)) == []


def test_empty_rect_measures_the_largest_blank():
    """``_empty_rect``, the helper the blank is measured with: a 300 × 200 field with a box over its
    left 100 mm leaves 200 × 200 blank (on its 5-mm grid); a blank narrower than 50 mm counts 0."""
    assert _empty_rect((0, 0, 300, 200), [(0, 0, 100, 200)]) == pytest.approx(200 * 200)
    assert _empty_rect((0, 0, 300, 200), [(0, 0, 260, 200)]) == 0.0


SETS = [("COUPLER_SLIDER_REVIEW54", "A3"),
        # stop 60: with the position plan kept at a 30-mm crank (kin60) its set's tail — Table 4 stacked over the 376-mm
        # notes — no longer fits under Tables 1–3 on sheet 5 and leaves Table 4's room blank there; ranking that blank
        # in the set search fixes it but takes the shaper's A3 to 5 sheets (a sheet at 16,5 %): no 6-sheet layout the
        # search tries avoids all three defects (kin60c). Strict: it fails the day the search finds one.
        pytest.param("CYLINDER_REVIEW54", "A3", marks=pytest.mark.xfail(strict=True, reason="stop 60: the tail's stacked "
                     "block leaves Table 4's room blank on sheet 5 (no layout tried avoids it; kin60c)")),
        ("LINK54", "A2")]


@pytest.mark.slow
@pytest.mark.parametrize("name, fmt", SETS)
def test_no_sheet_of_a_set_leaves_room_for_the_next_table(name, fmt):
    """On the drawn set, no sheet but the last has a blank (off every drawing's, table's and note's
    ink and the title block) that holds the next table in reading order with ``GAP`` around it —
    the table that could have moved up to it — and none is more than a third blank in one piece."""
    from graphplan.sheets.kinematics import build_kinematics_sheet
    f = form(fmt)
    sheet = build_kinematics_sheet(scene_study(getattr(review_scenes, name)), f, SheetOptions(lang="uk"))
    pages = sheet.pages
    x0, y0, x1, y1 = field_of(f)
    field = (x1 - x0) * (y1 - y0)
    for n, page in enumerate(pages[:-1]):
        later = [t for q in pages[n + 1:] for t in _tables(q)]
        if not later:
            continue
        nxt = later[0].record.bounds()
        w = int(np.ceil((nxt[2] - nxt[0] + 2 * GAP) / CELL))
        h = int(np.ceil((nxt[3] - nxt[1] + 2 * GAP) / CELL))
        assert not _holds(_free(page, n), w, h), f"{name} {fmt}: sheet {n + 1} holds {later[0].name}"
        ink = [keep_out(f) if n == 0 else later_keep(f)] + [p.record.bounds() for p in page.placed]
        assert _empty_rect(field_of(f), ink) < field / 3, f"{name} {fmt}: sheet {n + 1}"


def test_a_lever_with_one_joint_has_its_number_by_its_bar_not_by_its_pivot():
    """The dosing drive's slotted lever O3E (link 5) is pivoted at O3, its only joint; E and S5 are
    its own points. Its number stood at the pivot, "O₃ 5" read as one; now it stands beside the bar
    O3E (within a few mm of the segment), well away from the letter O₃."""
    from graphplan.drawing.plans import position_record
    from graphplan.graphic.plans import build_plans
    plans = build_plans(scene_study(review_scenes.KIN55_DOSING), precision=0.5)
    rec = position_record(plans)
    texts = [(it.text, complex(*it.points[0]), getattr(it, "size", 0.0)) for it in rec.items if it.kind == "text"]
    five = [z for t, z, s in texts if t == "5" and s >= 4.9]
    o3 = [z for t, z, s in texts if t == "O_3"]
    assert len(five) == 1 and len(o3) == 1
    assert abs(five[0] - o3[0]) > 20.0


def test_a_shelf_of_its_own_opens_the_block_into_its_tables():
    """The block is for the last acceleration plan's row: where the tables are a shelf of their own
    (the diagrams after the plans), the shelf gets the tables one by one, in order, and breaks them
    into lines itself."""
    from graphplan.drawing.layout import Shelf
    f = form("A3")
    region = field_of(f)
    P, D = Leaf("position", 300.0, 200.0), Leaf("diagrams", 300.0, 200.0)
    A = [Leaf("acceleration 0", 150.0, 240.0)]
    tabs = [Leaf(f"t{i}", 100.0, 50.0) for i in range(1, 4)]
    rows = set_rows(P, D, [], A, set_tail(tabs, Leaf("notes", 185.0, 60.0), 0, (1, 1)), region[2] - region[0],
                    after=True)
    shelf = rows[-1]
    assert isinstance(shelf, Shelf) and [t.name for t in shelf] == ["t1", "t2", "t3", "notes"]
