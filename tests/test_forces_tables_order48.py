"""Stop 48: a force set's tables read in their numbers' order. LINK48's A2 sheet 3 (the sheet's
room and the tables' sizes as the set measured them, mm) set Table 5 under Table 1, left of
Tables 2–4, with Tables 6–7 at the top right: read by columns, 1, 5, 2, 3, 4, 6, 7. The truth
is the reading order measured on the spots: each table under the one before it in that one's
column, or at the top of a new column wholly right of all before it."""
from __future__ import annotations


def _reads_in_order(spots, gap: float) -> bool:
    for k in range(1, len(spots)):
        s, last = spots[k], spots[k - 1]
        under = s.d >= last.d + last.h + gap - 1e-6 and last.x - 1e-6 <= s.x < last.x + last.w
        right = s.x >= max(p.x + p.w for p in spots[:k]) + gap - 1e-6
        if not (under or right):
            return False
    return True


def test_link48s_a2_tables_read_in_their_order():
    from graphplan.drawing.layout import Leaf
    from graphplan.sheets import forceset as fs
    page = fs.Skyline(559.0, 400.0, 373.0, 384.0, 10.0)
    page.put(fs.Spot(Leaf("hodographs", 547, 126), 0, 0, 547, 126))      # the row of hodographs
    tables = [Leaf(n, w, h) for n, w, h in (("T1", 126, 145), ("T2", 236, 74), ("T3", 238, 34),
                                            ("T4", 258, 34), ("T5", 160, 34), ("T6-7", 132, 134))]
    assert fs._put_tables(page, tables, Leaf("notes", 179, 73))
    spots = [s for s in page.spots if s.node.name.startswith("T")]
    assert [s.node.name for s in spots] == [t.name for t in tables]
    assert _reads_in_order(spots, 10.0), [(s.node.name, s.x, s.d) for s in spots]
    notes = next(s for s in page.spots if s.node.name == "notes")
    # nothing overlaps (the gap kept), and the notes clear of the title block's corner
    boxes = [(s.x, s.d, s.x + s.w, s.d + s.h) for s in page.spots]
    for i, a in enumerate(boxes):
        for b in boxes[i + 1:]:
            assert a[2] + 10 <= b[0] + 1e-6 or b[2] + 10 <= a[0] + 1e-6 or a[3] + 10 <= b[1] + 1e-6 \
                or b[3] + 10 <= a[1] + 1e-6, (a, b)
    assert notes.d + notes.h <= 384.0 + 1e-6
