"""How empty a sheet is, measured as the teachers' reviews measure it (review 6 #2, review 7 #1):
the frame's field cut into 20 mm cells, a cell empty where the rendered sheet has no ink in it (the
title block's corner left out) — and, cheaper, the share of the field the drawings' extents cover."""
from __future__ import annotations

import numpy as np

CELL = 20.0           # mm, the reviews' cell
FRAME_LEFT, FRAME = 20.0, 5.0      # mm, the frame's left margin and the others
TITLE_CORNER = (190.0, 60.0)       # mm from the sheet's right and bottom edges the reviews skipped


def ink(page, px: float = 2.0) -> np.ndarray:
    """The page rendered (cairosvg) at ``px`` pixels a mm: True where there is ink, rows from the top."""
    import io

    import cairosvg
    from PIL import Image
    png = cairosvg.svg2png(bytestring=page.svg().encode(), dpi=px * 25.4)
    im = Image.open(io.BytesIO(png)).convert("RGBA")
    return np.asarray(im)[:, :, 3] > 60


def empty_share(page, px: float = 2.0) -> float:
    """The share of the field's 20 mm cells with no ink (review 7's empty.py: cells from the frame's
    top-left corner, each looked at inside a 0.4 mm border, the title block's corner skipped)."""
    a = ink(page, px)
    H, W = a.shape
    c, inset = int(CELL * px), max(1, int(round(0.4 * px)))
    x0, y0, x1, y1 = int(FRAME_LEFT * px), int(FRAME * px), W - int(FRAME * px), H - int(FRAME * px)
    total = empty = 0
    for y in range(y0, y1 - c + 1, c):
        for x in range(x0, x1 - c + 1, c):
            if x > W - int(TITLE_CORNER[0] * px) and y > H - int(TITLE_CORNER[1] * px):
                continue
            total += 1
            empty += not a[y + inset:y + c - inset, x + inset:x + c - inset].any()
    return empty / total


def covered(page) -> float:
    """The share of the page's field its drawings' extents cover (their union, not their sum)."""
    from shapely.geometry import box
    from shapely.ops import unary_union

    from graphplan.sheets.compose import field_of
    field = box(*field_of(page.form))
    drawn = unary_union([box(*p.record.bounds()) for p in page.placed if p.record.items])
    return drawn.intersection(field).area / field.area
