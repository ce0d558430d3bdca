"""Overprinting as a reader's eye sees it, from the rendered sheet alone (independent of the records'
geometry): the sheet is rendered twice — its lettering only, everything but its lettering — the
lettering's ink is grouped into words (letters closer than about 1.6 mm join), and a word is
overprinted when a line's ink comes within a pixel of its letters (more than 3 % of its ink) or
another word's ink lies inside its box. The same judgement a teacher's count makes."""
from __future__ import annotations

import io
import re


def _mask(svg: str, w: float, h: float, px_per_mm: float):
    import cairosvg
    import numpy as np
    from PIL import Image
    png = cairosvg.svg2png(bytestring=svg.encode(), output_width=int(w * px_per_mm),
                           output_height=int(h * px_per_mm))
    im = Image.open(io.BytesIO(png)).convert("RGBA")
    white = Image.new("RGBA", im.size, (255, 255, 255, 255))
    white.alpha_composite(im)
    return np.asarray(white.convert("L")) < 200


def overprinted(svg: str, px_per_mm: float = 4.0) -> list[tuple[float, float]]:
    """Where overprinted words begin (mm from the sheet's left and bottom edges); empty when none."""
    from scipy import ndimage
    w = float(re.search(r'width="([\d.]+)mm"', svg[:3000]).group(1))
    h = float(re.search(r'height="([\d.]+)mm"', svg[:3000]).group(1))
    lines = _mask(re.sub(r"<text\b.*?</text>", "", svg, flags=re.S), w, h, px_per_mm)
    letters = _mask(re.sub(r"<(line|path|polyline|polygon|circle|ellipse|rect)\b[^>]*/>", "", svg), w, h, px_per_mm)
    words, _ = ndimage.label(ndimage.binary_dilation(letters, iterations=int(0.8 * px_per_mm)))
    out = []
    for i, sl in enumerate(ndimage.find_objects(words), 1):
        own = letters[sl] & (words[sl] == i)
        if own.sum() < 4:
            continue
        crossed = (lines[sl] & ndimage.binary_dilation(own, iterations=1)).sum() / own.sum()
        others = (letters[sl] & (words[sl] != i) & (words[sl] != 0)).sum() / own.sum()
        if crossed > 0.03 or others > 0.03:
            out.append((round(sl[1].start / px_per_mm, 1), round(h - sl[0].stop / px_per_mm, 1)))
    return out
