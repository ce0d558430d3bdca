"""Stop 51 (a teacher's grading of a generated type-B train, English A1): Table 3's «z′₂» in a 7-mm row
of 3.5-mm letters put its raised prime on the row's top rule — a word the rendered sheet shows
overprinted. A cell whose ink reaches up to a rule is lowered (or centred) in its row; the judge is
the rendered drawing (``inkcheck.overprinted``), not the code's own ink boxes."""
from __future__ import annotations

import pytest

from inkcheck import overprinted

ROWS = [["величина", "точно"],
        ["числа зубців", "z_1 = 17, z_2 = 64, z'_2 = 20, z_3 = 101"],
        ["Й, Ї", "ω^2, кг·м²"],
        ["μ'_ω", "p'_ω = 12,5"]]


def _clear(rec) -> bool:
    from graphplan.drawing import svg
    page, w, h = svg.page_for(rec)
    return overprinted(svg.render(page, w, h)) == []


@pytest.mark.parametrize("row_h, size", [(7.0, 3.5), (6.0, 2.5), (8.4, 3.5)])
def test_a_raised_prime_keeps_clear_of_the_rules(row_h, size):
    from graphplan.drawing.tables import table
    assert _clear(table(ROWS, [40.0, 90.0], row_h=row_h, size=size, title="Table 3. Planetary train"))


def test_the_gear_sheets_tight_tables_keep_the_prime_clear():
    """The A1 gear column's tables, ruled at 2.5 mm in 6-mm rows and drawn at 3.5 mm in 7-mm rows
    (``sheets.gears.tight``) — the way the z′₂ cell reached the rule."""
    from graphplan.drawing.tables import table
    from graphplan.sheets.gears import tight
    assert _clear(tight(table(ROWS, [34.0, 60.0], row_h=6.0, size=2.5, title="Table 3. Planetary train")))


def test_an_ordinary_cell_keeps_its_place():
    """Cells whose ink is clear of the rules stand where they always did (the gallery's tables)."""
    from graphplan.drawing.tables import table
    rec = table([["a", "12,5"]], [20.0, 20.0], row_h=7.0, size=3.5)
    ys = {round(p.points[0][1], 6) for p in rec.items if p.kind == "text"}
    assert ys == {round(-7.0 + (7.0 - 3.5) / 2 + 0.15 * 3.5, 6)}


def test_a_lowered_row_keeps_one_baseline():
    """The cell with the raised prime lowers its whole row: every cell of a row on one baseline (the
    tables are read by rows)."""
    from graphplan.drawing.tables import table
    from graphplan.sheets.gears import tight
    for rec in (table(ROWS, [40.0, 90.0], row_h=7.0, size=3.5), tight(table(ROWS, [34.0, 60.0], row_h=6.0, size=2.5))):
        ys = sorted({round(p.points[0][1], 6) for p in rec.items if p.kind == "text"}, reverse=True)
        assert len(ys) == len(ROWS)
