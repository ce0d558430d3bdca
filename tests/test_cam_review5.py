"""Review 4, items 19–20: the A1 cam sheet composed without the blank room under the phase diagram
(375–570, 335–590 mm from the sheet's left/top was empty: 42 % of the sheet), and Table 1's
graphical values to what the ruler gives (s гр. = 0,3982 from a reading of 1 mm)."""
from __future__ import annotations

import math

import pytest

from conftest import ROOT
from graphplan.model.cam import load
from graphplan.sheets.compose import SheetOptions, defects, field_of, keep_out
from graphplan.sheets.form import form

CELL = 20.0


def _marks(q) -> list[tuple[float, float]]:
    """Points along a primitive's ink about every millimetre (a text: its ink box filled)."""
    if q.kind == "text":
        x0, y0, x1, y1 = q.ink()
        nx, ny = max(2, int((x1 - x0) + 2)), max(2, int((y1 - y0) + 2))
        return [(x0 + (x1 - x0) * i / (nx - 1), y0 + (y1 - y0) * j / (ny - 1)) for i in range(nx) for j in range(ny)]
    if q.kind in ("circle", "arc"):
        (cx, cy), r = q.points[0], q.radius
        a0, sweep = (0.0, 360.0) if q.kind == "circle" else (q.angles[0], (q.angles[1] - q.angles[0]) % 360.0 or 360.0)
        n = max(4, int(math.radians(sweep) * r) + 2)
        return [(cx + r * math.cos(math.radians(a0 + sweep * k / (n - 1))),
                 cy + r * math.sin(math.radians(a0 + sweep * k / (n - 1)))) for k in range(n)]
    pts = list(q.points) + ([q.points[0]] if q.kind == "polygon" else [])
    out = list(pts)
    for (xa, ya), (xb, yb) in zip(pts, pts[1:]):
        n = int(math.hypot(xb - xa, yb - ya)) + 2
        out += [(xa + (xb - xa) * k / n, ya + (yb - ya) * k / n) for k in range(1, n)]
    return out


def empty_share(sheet) -> tuple[float, set]:
    """The share of the field's CELL-mm cells (the title block's left out) where no placed drawing
    puts ink, read off the sheet's records; and the empty cells (column, row)."""
    x0, y0, x1, y1 = field_of(sheet.form)
    kx0, _, _, ky1 = keep_out(sheet.form)
    cols, rows = int(math.ceil((x1 - x0) / CELL)), int(math.ceil((y1 - y0) / CELL))
    inked = set()
    for placed in sheet.placed:
        for q in placed.record.items:
            for x, y in _marks(q):
                inked.add((int((x - x0) // CELL), int((y - y0) // CELL)))
    cells = {(i, j) for i in range(cols) for j in range(rows)
             if not (x0 + (i + 1) * CELL > kx0 and y0 + j * CELL < ky1)}
    empty = cells - inked
    return len(empty) / len(cells), empty


def _sheet(path, lang):
    from graphplan.sheets.cam import build_cam_sheet
    return build_cam_sheet(load(path), form("A1"), SheetOptions(lang=lang, sheet="cam"))
