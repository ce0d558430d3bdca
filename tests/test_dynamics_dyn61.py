"""Stop 61, helper dyn61.

1. Bare paper under the notes of an A1 dynamics sheet: where the notes stand in the band's nook (under
   ΔT(φ), left of the turned I*(φ)) and leave most of it bare (LINK61: ~320 × 115 mm under them), the
   results' tables (Table 2, Table 3) go there under the notes and ω(φ) over Table 1 grows into the
   height they leave. Measured on the drawn sheet: the largest blank rectangle (off every drawing's,
   table's and note's ink and the title block, both sides ≥ 50 mm) against the drawings' own boxes.
"""
from __future__ import annotations

import math
import sys
from pathlib import Path

import pytest

from conftest import scene_study

sys.path.insert(0, str(Path(__file__).parent))
from review_scenes import LINK61  # noqa: E402


def _largest_blank(field, ink, cell: float = 5.0, least: float = 50.0) -> tuple[float, tuple]:
    """The largest rectangle of ``field`` (x0, y0, x1, y1 mm) meeting none of the ``ink`` boxes, both sides at
    least ``least`` mm, on a ``cell`` grid — by brute force over the grid's rows (this file's own, not
    graphplan's histogram helper): (area mm², box)."""
    x0, y0, x1, y1 = field
    nx, ny = int((x1 - x0) // cell), int((y1 - y0) // cell)
    free = [[True] * nx for _ in range(ny)]
    for b in ink:
        i0, i1 = max(0, int((b[0] - x0) // cell)), min(nx, math.ceil((b[2] - x0) / cell))
        j0, j1 = max(0, int((b[1] - y0) // cell)), min(ny, math.ceil((b[3] - y0) / cell))
        for j in range(j0, j1):
            for i in range(i0, i1):
                free[j][i] = False
    best = (0.0, None)
    for j0 in range(ny):                        # each bottom row, each top row: the free columns' runs
        col = [True] * nx
        for j1 in range(j0, ny):
            col = [c and f for c, f in zip(col, free[j1])]
            h = (j1 - j0 + 1) * cell
            run = 0
            for i in range(nx + 1):
                if i < nx and col[i]:
                    run += 1
                    continue
                w = run * cell
                if min(w, h) >= least and w * h > best[0]:
                    best = (w * h, (x0 + (i - run) * cell, y0 + j0 * cell, x0 + i * cell, y0 + (j1 + 1) * cell))
                run = 0
            if not any(col):
                break
    return best


@pytest.fixture(scope="module")
def link61_sheets():
    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.dynamics import build_dynamics_sheet
    from graphplan.sheets.form import form
    st = scene_study(LINK61)
    return {lang: build_dynamics_sheet(st, form("A1"), SheetOptions(lang=lang, sheet="dynamics"))
            for lang in ("uk", "en")}


@pytest.mark.slow                     # LINK61's A1 dynamics sheet composed in both languages: ~2 min of CPU
@pytest.mark.parametrize("lang", ["uk", "en"])
def test_link61s_results_tables_fill_the_nook_under_the_notes(link61_sheets, lang):
    """The sheet leaves no blank as large as its own ΔT(φ) diagram (before: 320 × 115 mm under the notes,
    ΔT(φ) 302 × 87 mm); Tables 2 and 3 stand side by side under the notes, left of the turned I*(φ), Table 1
    over the title block with its top over theirs (read top to bottom: 1, then 2 and 3)."""
    from graphplan.sheets.compose import field_of, keep_out
    from graphplan.sheets.form import form
    f = form("A1")
    sheet = link61_sheets[lang]
    at = {p.name: p.record.bounds() for p in sheet.placed}
    area, box = _largest_blank(field_of(f), [keep_out(f)] + list(at.values()))
    energy = at["energy"]
    assert area < (energy[2] - energy[0]) * (energy[3] - energy[1]), (lang, box)
    t1, t2, t3, notes, inertia = (at[k] for k in ("positions table", "flywheel table", "motor table", "notes",
                                                  "inertia"))
    assert t2[3] < notes[1] and t3[3] < notes[1]            # under the notes
    assert t2[2] < t3[0] and max(t2[2], t3[2]) < inertia[0]  # side by side, left of I*(φ)
    assert t1[3] > t2[3] and t1[0] > inertia[2]             # Table 1 at the right, read first
    speed = at["speed"]
    assert speed[1] > t1[3]                                   # ω(φ) over Table 1
