"""Stop 61 (gears61): the A1 gear sheet's blanks a strict teacher marked in stop 60 — beside the planetary pictures
where they have the row under the meshing alone (GEARS60: about 150 × 340 mm each side), and under the λ diagrams
where these share the row with them (GEARS57 300 × 120 mm, GEARS59 245 × 143 mm). The measure is this module's own:
the largest rectangle of the field, off the title block and its clearance, that no placed drawing, table or note
meets (the histogram method on a 5-mm grid, written here, not the layout's ``kinlayout._empty_rect``)."""
from __future__ import annotations

import math
import tomllib

import numpy as np
import pytest

import review_scenes

CELL = 5.0


def largest_blank(boxes, field) -> tuple[float, float]:
    """(width, height) mm of the largest-area rectangle of ``field`` that meets none of ``boxes`` (x0, y0, x1, y1),
    on a ``CELL`` grid (a cell free when no box overlaps it by more than 1e-6)."""
    x0, y0, x1, y1 = field
    nx, ny = int((x1 - x0) // CELL), int((y1 - y0) // CELL)
    free = np.ones((ny, nx), dtype=bool)
    for b in boxes:
        i0, i1 = int(math.floor((b[0] - x0) / CELL + 1e-6)), int(math.ceil((b[2] - x0) / CELL - 1e-6))
        j0, j1 = int(math.floor((b[1] - y0) / CELL + 1e-6)), int(math.ceil((b[3] - y0) / CELL - 1e-6))
        free[max(j0, 0):max(j1, 0), max(i0, 0):max(i1, 0)] = False
    best, h = (0.0, 0.0), np.zeros(nx, dtype=int)
    for row in free:
        h = np.where(row, h + 1, 0)
        for i in range(nx):                 # each column's run upwards, widened both ways while as tall
            if not h[i]:
                continue
            lo = i
            while lo > 0 and h[lo - 1] >= h[i]:
                lo -= 1
            hi = i
            while hi < nx - 1 and h[hi + 1] >= h[i]:
                hi += 1
            w, t = (hi - lo + 1) * CELL, h[i] * CELL
            if w * t > best[0] * best[1]:
                best = (w, t)
    return best


def test_largest_blank_measures_a_hole():
    """A 300 × 200 field with a box over its left 100 mm and one over the top 50 mm of the rest: the largest
    blank is the 200 × 150 under the second."""
    assert largest_blank([(0, 0, 100, 200), (100, 150, 300, 200)], (0, 0, 300, 200)) == (200.0, 150.0)
    assert largest_blank([], (0, 0, 50, 20)) == (50.0, 20.0)


def _sheet(name: str, lang: str = "uk"):
    from graphplan.model.gears import build
    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.form import form
    from graphplan.sheets.gears import build_gears_sheet
    g = build(tomllib.loads(getattr(review_scenes, name)), name)
    return build_gears_sheet(g, form("A1"), SheetOptions(lang=lang, sheet="gears"))


def _blank(sheet):
    from graphplan.sheets.compose import field_of, keep_out
    f = sheet.pages[0].form
    return largest_blank([keep_out(f)] + [p.record.bounds() for p in sheet.placed], field_of(f))


@pytest.mark.slow
@pytest.mark.parametrize("name, lang, was", [("GEARS57", "uk", (300.0, 120.0)), ("GEARS59", "uk", (245.0, 143.0)),
                                             ("GEARS61", "en", (270.0, 105.0))])
def test_the_pairs_notes_fill_the_room_under_the_lambda_diagrams(name, lang, was):
    """Where the λ diagrams share the row with the planetary pictures, the pair's notes (its task data first) stand
    under them, wrapped to their width, and the train's notes at the column's foot: the blank that was under the λ
    diagrams (stop 60's measure: GEARS57 300 × 120 mm, GEARS59 245 × 143, GEARS61 270 × 105 on its first
    sheet) is gone — no blank left holds a rectangle of half its area with both sides at least 100 mm —, and the
    sheet reads in order: the pair's notes under its drawings, the train's data and notes under Table 3."""
    sheet = _sheet(name, lang)
    assert len(sheet.pages) == 1
    ext = {p.name: p.record.bounds() for p in sheet.placed}
    assert "train notes" in ext and "notes" in ext
    lam, notes, t3, tn = ext["sliding"], ext["notes"], ext["train"], ext["train notes"]
    assert notes[3] <= lam[1] and abs(notes[0] - lam[0]) < 1.0             # under the λ diagrams, at their left
    assert tn[3] <= t3[1] and tn[0] >= min(ext["planetary"][2], lam[2])     # the train's notes under Table 3
    said = " ".join(q.text for p in sheet.placed if p.name == "notes" for q in p.record.items if q.kind == "text")
    assert ("Вихідні дані пари" if lang == "uk" else "The pair's data") in said
    w, h = _blank(sheet)
    assert not (min(w, h) >= 100.0 and w * h >= 0.5 * was[0] * was[1]), (w, h)


@pytest.mark.slow
@pytest.mark.parametrize("lang", ["uk", "en"])
def test_the_planetary_pictures_alone_in_their_row_take_its_width(lang):
    """GEARS60: the λ diagrams beside the meshing, the row under it the planetary pictures' alone. At vA 1,4 times
    its size the pictures stood 319 mm wide centred in a 614-mm room (52 %; 150 × 385 mm blank beside them); with vA
    up to 4 times (``ALONE_SHARES``) the velocity picture and the plan of angular velocities take the row: the
    pictures' width at least 80 % of the room, no blank of both sides 140 mm or more, and u1H read off them within
    a bound no wider than the 1,4-vA pictures' ±0,86 % (stop 60's sheet), the reading inside it."""
    from graphplan.sheets.compose import GAP, field_of, keep_out
    sheet = _sheet("GEARS60", lang)
    f = sheet.pages[0].form
    ext = {p.name: p.record.bounds() for p in sheet.placed}
    p, m = ext["planetary"], ext["meshing"]
    assert ext["sliding"][1] >= p[3]                                       # the λ diagrams up by the meshing
    x0 = field_of(f)[0]
    room = min(ext[n][0] for n in ("geometry", "quality", "train", "notes")) - GAP - x0
    assert p[2] - p[0] >= 0.8 * room, (p, room)                            # (stop 60: 319 of 614 mm, 52 %)
    w, h = _blank(sheet)
    assert min(w, h) < 140.0, (w, h)
    from graphplan.exact.gears import solve
    from graphplan.model.gears import build
    from graphplan.sheets.gears import on_sheet
    g = build(tomllib.loads(review_scenes.GEARS60), "GEARS60")
    sol = solve(g)
    _, vel, _ = on_sheet(g, sol, f, 0.5, lang)
    u = 1 + 85 / 19                                                        # Willis, type A: 1 + z3/z1
    assert sol.train.ratio == pytest.approx(u)
    assert 100 * vel.ratio_bound / u <= 0.86
    assert abs(vel.ratio - u) <= vel.ratio_bound + 1e-12                   # the reading within its bound
