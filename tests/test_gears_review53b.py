"""Stop 53's gear-set review (helper gear53b): the lab's tables are lettered 3,5 mm (GOST 2.304, as the other
sheets' tables); a set of A3/A2 sheets took the ruled 2,5-mm tables wherever that saved a sheet (GEARS53's A3
set, GEARS52's A2, GEARS51's A3). A set one sheet longer with readable tables is what a teacher signs: the
letter height read off the drawn record of every table of the set."""
from __future__ import annotations

import dataclasses
import functools
import tomllib

import pytest

from review_scenes import GEARS53

TABLES = ("geometry", "quality", "train")


@functools.lru_cache(maxsize=None)
def _set(name: str, text: str, fmt: str, lang: str, train: bool):
    """The set's pages as the sheet draws them (``on_sheet``); ``train`` False: the pair alone (its set is
    planned in well under a second, the train's pictures grown over the set take several)."""
    from graphplan.exact.gears import solve
    from graphplan.model.gears import build
    from graphplan.sheets.form import form
    from graphplan.sheets.gears import on_sheet
    g = build(tomllib.loads(text), name)
    sol = solve(g)
    if not train:
        sol = dataclasses.replace(sol, train=None)
    return on_sheet(g, sol, form(fmt), 0.5, lang)[2]


def _cell_heights(pages) -> dict[str, set[float]]:
    """Each table's cells' letter heights, mm, read off the drawn record: the lettering under the table's
    top rule (its title stands over it)."""
    out: dict[str, set[float]] = {}
    for page in pages:
        for p in page:
            if p.name in TABLES:
                top = max(y for q in p.record.items if q.kind == "segment" for _, y in q.points)
                out[p.name] = {q.size for q in p.record.items if q.kind == "text" and q.points[0][1] < top}
    return out


@pytest.mark.parametrize("lang", ["en", "uk"])
def test_a_sets_tables_are_lettered_3_5_mm(lang):
    """GEARS53's pair on A3: at the ruled 2,5 mm its Tables 1 and 2 shared a sheet with the λ diagrams and the
    set took 2 sheets; lettered 3,5 mm the set is a sheet longer. Every cell of both tables 3,5 mm high."""
    pages = _set("GEARS53", GEARS53, "A3", lang, False)
    got = _cell_heights(pages)
    assert set(got) == {"geometry", "quality"}
    for name, sizes in got.items():
        assert sizes == {3.5}, (name, sizes)


@pytest.mark.slow
@pytest.mark.parametrize("lang", ["en", "uk"])
def test_gears53s_a3_set_letters_all_three_tables_3_5_mm(lang):
    """The whole scene (the train's Table 3 too): stop 53's A3 set lettered Table 3 (uk) or all three (en)
    2,5 mm."""
    got = _cell_heights(_set("GEARS53", GEARS53, "A3", lang, True))
    assert set(got) == set(TABLES)
    for name, sizes in got.items():
        assert sizes == {3.5}, (name, sizes)


@pytest.mark.parametrize("text", ["r_a", "r_b", "r_w", "r_f", "r_{w1}"])
def test_an_index_after_r_stands_under_its_arm(text):
    """GEARS50's en A3 Table 1: the a of r_a set at r's full advance hung 0,6 mm right of the arm's end and
    1,7 mm off the stem — a word apart from its letter (the overprint checker read r and a as two words
    whose boxes overlapped). The index's ink now starts at the arm's end (not further right), right of the
    stem's middle (not tucked into a ligature "ra"), and stays under the arm (its top, a tall b or f too,
    under 0,6 of r's height: the arm's curve comes down to about 0,75 of it), measured on the drawn ink at
    3,5 mm."""
    from graphplan.graphic.record import ink_boxes
    r, index = ink_boxes(text, 3.5)[:2]
    assert index[0] <= r[2] + 0.05
    assert index[0] >= (r[0] + r[2]) / 2
    assert index[3] < 0.6 * r[3]
