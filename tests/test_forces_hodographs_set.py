"""A force set's hodographs (the lead's stop-45 grading of PUMP45 at φ = 120° on A2): the set planned
three sheets and drew four, the six reactions' hodographs ~40 mm each in one row across an otherwise
empty sheet 3 (80 % blank) — planned in cells 63 × 41–97 mm, drawn each in the largest one's 75 × 96.
A sheet that holds small drawings draws them large, or the set puts them where there is room."""
from __future__ import annotations

import pytest
from conftest import scene_study
from review_scenes import PUMP45


def _lines_extent(rec) -> float:
    """The larger extent of a drawing's lines (its lettering, caption and leaders aside), mm."""
    from graphplan.graphic.record import Record
    lines = Record(items=[q for q in rec.items if q.kind != "text" and q.layer != "labels"])
    x0, y0, x1, y1 = lines.bounds()
    return max(x1 - x0, y1 - y0)


def test_a_sets_plan_gives_the_hodographs_the_cells_they_are_drawn_in():
    """The plan's cells are the drawn ones: every hodograph in the largest one's cell, as the sheet
    sets them (a plan that packs them smaller counts a sheet less than it draws)."""
    from graphplan.sheets.compose import Family
    from graphplan.sheets.forces import Natural, _leaves
    fam = Family(1.0, [(40.0, 60.0, 5.0, 5.0), (60.0, 20.0, 5.0, 5.0), (30.0, 30.0, 0.0, 0.0)],
                 caption=(20.0, 8.0), factors=True)
    nat = Natural({"hodographs": fam}, {}, [])
    cells = [(x.w, x.h) for x in _leaves(nat, {"hodographs": 1.0})["hodographs"]]
    assert cells == [(65.0, 73.0)] * 3, cells          # (60 + 5) across, (60 + 5 + 8) up: the largest of each
    assert [(x.w, x.h) for x in _leaves(nat, {"hodographs": 0.5})["hodographs"]] == [(125.0, 133.0)] * 3


@pytest.mark.slow
def test_a_sets_hodographs_are_drawn_large_where_their_sheet_has_room():
    """PUMP45 at φ = 120° on A2 and A3: the set draws no more sheets than its plan counted, and a sheet that
    holds the hodographs either is at least half covered by its drawings and tables, or draws each
    hodograph at least as large as the A1 sheet does (size factor 1, ``HODOGRAPH_MM``) — each one's lines
    across their larger extent, measured off the records the sheet places, against the same hodograph
    drawn at ``HODOGRAPH_MM``.

    (It asked each for 60 mm of lines: ``HODOGRAPH_MM`` is the most a hodograph's extent takes at factor 1,
    μR being the series' next value up — 50.5–62.5 mm on A1 as on this A3 sheet, whose hodographs stay at
    factor 1: at 1.25 the six no longer share a sheet with the third chart and the notes, and the set
    would take a sixth sheet.)"""
    from graphplan.drawing.charts import HODOGRAPH_MM
    from graphplan.sheets import forces as sf
    from graphplan.sheets.compose import SheetOptions, field_of
    from graphplan.sheets.form import form
    from graphplan.drawing.charts import hodograph_record, turn
    st = scene_study(PUMP45.replace("force_phi_deg = 210", "force_phi_deg = 120"))
    t = turn(st)
    a1 = {f"hodograph {k}": _lines_extent(hodograph_record(t, k, HODOGRAPH_MM, lang="uk")) for k in t.revolute}
    for fmt in ("A2", "A3"):
        f = form(fmt)
        p, _, _ = sf.plan(st, f, SheetOptions(sheet="forces"))
        pages = [page.placed for page in sf.build_forces_sheet(st, f, SheetOptions(sheet="forces")).pages]
        assert len(pages) <= p.sheets, (fmt, len(pages), p.sheets)
        x0, y0, x1, y1 = field_of(f)
        for page in pages:
            hods = [it for it in page if it.name.startswith("hodograph")]
            if not hods:
                continue
            covered = sum((b[2] - b[0]) * (b[3] - b[1]) for b in (it.box for it in page)) / ((x1 - x0) * (y1 - y0))
            sizes = {it.name: _lines_extent(it.record) for it in hods}
            assert set(sizes) <= set(a1), sizes
            assert covered >= 0.5 or all(sizes[n] >= a1[n] - 0.25 for n in sizes), (fmt, round(covered, 2), sizes, a1)
