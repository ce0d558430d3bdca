"""Stop 58 (gears58b): the A1 gear sheet's column and the row under the meshing."""
import pytest

from graphplan.drawing.layout import GAP, Leaf
from graphplan.graphic.record import Record


def _box(name: str, w: float, h: float) -> Leaf:
    r = Record()
    r.segment((0.0, 0.0), (w, h))
    return Leaf(name, record=r)


def _column_room():
    from graphplan.sheets.compose import field_of, keep_out
    from graphplan.sheets.form import form
    f = form("A1")
    y1, keep = field_of(f)[3], keep_out(f)
    return f, y1 - keep[3] - GAP        # the column's height from the field's top to GAP over the title block


@pytest.mark.parametrize("over", [0.0, 1.01, 4.0, 5.9])
def test_the_column_closes_its_gaps_to_keep_its_tables_size(over):
    """Stop 58: GEARS51's English column needed 513,0 mm for 512 (x_min's note a line longer) and its tables
    fell to the ruled 2,5-mm letters. Parts GAP apart that overrun the room by less than 3·(GAP − COLUMN_GAP)
    now stand closer, never under COLUMN_GAP, each below the last, the notes on the title block."""
    from graphplan.sheets.gears import COLUMN_GAP, zones
    f, room = _column_room()
    hs = [120.0, 50.0, 85.0]
    notes = room + over - sum(hs) - 3 * GAP
    side = [_box(n, 180.0, h) for n, h in zip(("geometry", "quality", "train"), hs)] + [_box("notes", 180.0, notes)]
    pages = zones([_box("meshing", 300.0, 300.0)], side, f, 185.0)
    assert pages is not None
    got = sorted((p for p in pages[0] if p.name != "meshing"), key=lambda p: -p.box[3])
    assert [p.name for p in got] == ["geometry", "quality", "train", "notes"]
    gaps = [a.box[1] - b.box[3] for a, b in zip(got, got[1:])]
    assert all(g >= COLUMN_GAP - 1e-9 for g in gaps), gaps
    assert sum(gaps) == pytest.approx(3 * GAP - over, abs=1e-6) if over else all(g >= GAP - 1e-9 for g in gaps)
    from graphplan.sheets.compose import keep_out
    assert got[-1].box[1] == pytest.approx(keep_out(f)[3] + GAP)      # the notes stand on the title block


def test_a_column_too_tall_for_the_least_gaps_is_refused():
    """Past 3·(GAP − COLUMN_GAP) the column does not fit: the caller tries the smaller tables (``SIZES``)."""
    from graphplan.sheets.gears import COLUMN_GAP, zones
    f, room = _column_room()
    hs = [120.0, 50.0, 85.0]
    notes = room + 3 * (GAP - COLUMN_GAP) + 0.1 - sum(hs) - 3 * GAP
    side = [_box(n, 180.0, h) for n, h in zip(("geometry", "quality", "train"), hs)] + [_box("notes", 180.0, notes)]
    assert zones([_box("meshing", 300.0, 300.0)], side, f, 185.0) is None
