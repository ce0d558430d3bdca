"""Overprinting as a reader's eye sees it, from the rendered sheet alone (independent of the records'
geometry): the sheet is rendered twice — its lettering only, everything but its lettering — the
lettering's ink is grouped into words (letters closer than about 1.6 mm join), and a word is
overprinted when a line's ink comes within a pixel of its letters (more than 3 % of its ink) or
another word's ink lies inside its box. The same judgement a teacher's count makes."""
from __future__ import annotations

import re


def _mask(svg: str, w: float, h: float, px_per_mm: float):
    """The sheet's ink: cairosvg's ARGB image as its PNG would hold it (cairo's un-premultiplied
    channels), laid on white (PIL's ``alpha_composite``) and read as grey (PIL's "L", ITU-R 601-2
    luma) darker than 200 — the same integer arithmetic as writing the PNG and reading it back
    through PIL (bit for bit: tests/test_inkcheck.py), without encoding and decoding a 3364 × 2376
    pixel PNG twice a sheet; read a band of rows at a time (whole-sheet temporaries cost more in
    page faults than the PNG did)."""
    import numpy as np
    from cairosvg.parser import Tree
    from cairosvg.surface import PNGSurface
    surface = PNGSurface(Tree(bytestring=svg.encode()), None, 96, output_width=int(w * px_per_mm),
                         output_height=int(h * px_per_mm))
    image = surface.cairo
    image.flush()
    width, height = image.get_width(), image.get_height()
    bgra = np.frombuffer(image.get_data(), np.uint8).reshape(height, image.get_stride() // 4, 4)[:, :width]
    ink = np.empty((height, width), bool)
    for r in range(0, height, 64):
        ink[r:r + 64] = _grey(bgra[r:r + 64]) < 200
    surface.finish()                   # frees the pixels: read before
    return ink


def _on_white():
    """Each premultiplied channel value c of alpha a (table [a, c]) as PIL reads it laid on white:
    cairo's ``unpremultiply_data`` (c·255 + a/2) / a, then PIL's ``alpha_composite`` over opaque
    white (7 bits of precision, divisions by 255 rounded as ((x >> 8) + x) >> 8); white where a = 0."""
    import numpy as np
    global _ON_WHITE
    if _ON_WHITE is None:
        a, c = np.meshgrid(np.arange(256, dtype=np.uint32), np.arange(256, dtype=np.uint32), indexing="ij")
        safe = np.maximum(a, 1)
        c = (c * 255 + safe // 2) // safe
        t = c * (a * 128) + 255 * (255 * 128 - a * 128) + (0x80 << 7)
        _ON_WHITE = np.where(a > 0, (((t >> 8) + t) >> 8) >> 7, 255).astype(np.uint32).ravel()
    return _ON_WHITE


_ON_WHITE = None


def _grey(bgra):
    """Grey levels of premultiplied BGRA pixels laid on white (``_on_white``), by PIL's RGB → L
    (R·19595 + G·38470 + B·7471 + 2¹⁵) >> 16."""
    import numpy as np
    table = _on_white()
    a = bgra[..., 3].astype(np.intp) << 8
    b, g, r = (table[a | bgra[..., k]] for k in (0, 1, 2))
    return (r * 19595 + g * 38470 + b * 7471 + 0x8000) >> 16


def overprinted(svg: str, px_per_mm: float = 4.0) -> list[tuple[float, float]]:
    """Where overprinted words begin (mm from the sheet's left and bottom edges); empty when none.

    Word i's ink within a pixel of a line is counted over the whole sheet at once: a pixel next to
    word i's letters lies in word i's dilated blob (a blob holds its letters' neighbours) and so in
    its box — the same count as dilating the word's own letters inside its box. Other words' ink in
    its box is the lettering's ink in the box less its own."""
    import numpy as np
    from scipy import ndimage
    w = float(re.search(r'width="([\d.]+)mm"', svg[:3000]).group(1))
    h = float(re.search(r'height="([\d.]+)mm"', svg[:3000]).group(1))
    lines = _mask(re.sub(r"<text\b.*?</text>", "", svg, flags=re.S), w, h, px_per_mm)
    letters = _mask(re.sub(r"<(line|path|polyline|polygon|circle|ellipse|rect)\b[^>]*/>", "", svg), w, h, px_per_mm)
    words, n = ndimage.label(ndimage.binary_dilation(letters, iterations=int(0.8 * px_per_mm)))
    own = np.bincount(words[letters], minlength=n + 1)
    near = lines & ndimage.binary_dilation(letters, iterations=1)
    crossed = np.bincount(words[near], minlength=n + 1)
    out = []
    for i, sl in enumerate(ndimage.find_objects(words), 1):
        if own[i] < 4:
            continue
        others = letters[sl].sum() - own[i]
        if crossed[i] / own[i] > 0.03 or others / own[i] > 0.03:
            out.append((round(sl[1].start / px_per_mm, 1), round(h - sl[0].stop / px_per_mm, 1)))
    return out
