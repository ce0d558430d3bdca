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
    pixel PNG twice a sheet."""
    import numpy as np
    from cairosvg.parser import Tree
    from cairosvg.surface import PNGSurface
    surface = PNGSurface(Tree(bytestring=svg.encode()), None, 96, output_width=int(w * px_per_mm),
                         output_height=int(h * px_per_mm))
    image = surface.cairo
    image.flush()
    width, height = image.get_width(), image.get_height()
    bgra = np.frombuffer(image.get_data(), np.uint8).reshape(height, image.get_stride() // 4, 4)[:, :width]
    ink = _grey(bgra) < 200
    surface.finish()                   # frees the pixels: read before
    return ink


def _grey(bgra):
    """Grey levels of premultiplied BGRA pixels laid on white: cairo's ``unpremultiply_data``
    (c·255 + a/2) / a, PIL's ``alpha_composite`` over opaque white (7 bits of precision, divisions by
    255 rounded as ((x >> 8) + x) >> 8) and PIL's RGB → L (R·19595 + G·38470 + B·7471 + 2¹⁵) >> 16."""
    import numpy as np
    a = bgra[..., 3].astype(np.uint32)
    some = a > 0
    safe = np.where(some, a, 1)
    coef1 = a * 128
    coef2 = 255 * 128 - coef1

    def over_white(c):
        c = (bgra[..., c].astype(np.uint32) * 255 + safe // 2) // safe
        t = c * coef1 + 255 * coef2 + (0x80 << 7)
        return np.where(some, (((t >> 8) + t) >> 8) >> 7, 255)
    b, g, r = over_white(0), over_white(1), over_white(2)
    return (r * 19595 + g * 38470 + b * 7471 + 0x8000) >> 16


def overprinted(svg: str, px_per_mm: float = 4.0) -> list[tuple[float, float]]:
    """Where overprinted words begin (mm from the sheet's left and bottom edges); empty when none.

    Word i's ink within a pixel of a line is counted over the whole sheet at once: a pixel next to
    word i's letters lies in word i's dilated blob (a blob holds its letters' neighbours) and so in
    its box — the same count as dilating the word's own letters inside its box. Other words' ink in
    its box is the lettering's ink in the box (a summed-area table) less its own."""
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
    inked = np.zeros((letters.shape[0] + 1, letters.shape[1] + 1), np.int64)
    inked[1:, 1:] = letters.cumsum(0, dtype=np.int64).cumsum(1)
    out = []
    for i, sl in enumerate(ndimage.find_objects(words), 1):
        if own[i] < 4:
            continue
        (r0, r1), (c0, c1) = (sl[0].start, sl[0].stop), (sl[1].start, sl[1].stop)
        others = inked[r1, c1] - inked[r0, c1] - inked[r1, c0] + inked[r0, c0] - own[i]
        if crossed[i] / own[i] > 0.03 or others / own[i] > 0.03:
            out.append((round(sl[1].start / px_per_mm, 1), round(h - sl[0].stop / px_per_mm, 1)))
    return out
