"""Stop 55 (misc55): a negative number reads with a true minus on every sheet, in a viewer that letters
with the packaged osifont and in one that ignores the sheet's @font-face and falls back to DejaVu Sans.

osifont has no U+2212 and DejaVu's minus (0.63 em of ink) is wider than osifont's advance for it, so
the sheets draw the minus as the en dash: the truth checked here is read from the font files
themselves and from the rendered pixels, not from the lettering's own tables."""
from __future__ import annotations

import io
import re
from pathlib import Path

import numpy as np
import pytest

from graphplan.graphic.record import Record, em, lettering

DEJAVU = Path("/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf")


def _font(path):
    from fontTools.ttLib import TTFont
    return TTFont(str(path))


def _box(font, ch):
    """The glyph's ink box in ems, and its advance."""
    g = font.getBestCmap()[ord(ch)]
    gl, upm = font["glyf"][g], font["head"].unitsPerEm
    return tuple(v / upm for v in (gl.xMin, gl.yMin, gl.xMax, gl.yMax)), font["hmtx"][g][0] / upm


def test_the_minus_and_a_sign_typed_as_a_hyphen_are_drawn_alike_words_keep_their_hyphens():
    drawn = lettering("−")
    assert drawn != "-" and len(drawn) == 1
    for text, want in [("−14", drawn + "14"), ("-10", drawn + "10"), ("R = -0,23 Н", f"R = {drawn}0,23 Н"),
                       ("(-3)", f"({drawn}3)"), ("5 − 3", f"5 {drawn} 3"), ("= -.5", f"= {drawn}.5")]:
        assert lettering(text) == want, text
    for text in ("МБ-55", "кривошипно-повзунний", "ГОСТ 2.104-68", "1-2", "x-5", "s-v-a", "-"):
        assert lettering(text) == text, text


def test_the_drawn_minus_in_osifont_is_the_plus_bar():
    """In the packaged font the drawn minus is a thin bar as long as the plus's (± 15 %) at the plus's
    height (± 0.03 em): what a teacher reads as "minus", not a hyphen."""
    from graphplan.drawing.fonts import font_path
    font = _font(font_path())
    assert 0x2212 not in font.getBestCmap()            # why the minus is drawn with another glyph
    (x0, y0, x1, y1), _ = _box(font, lettering("−"))
    (px0, py0, px1, py1), _ = _box(font, "+")
    assert y1 - y0 < 0.1
    assert abs((x1 - x0) / (px1 - px0) - 1) <= 0.15
    assert abs((y0 + y1) / 2 - (py0 + py1) / 2) <= 0.03


@pytest.mark.skipif(not DEJAVU.exists(), reason="DejaVu Sans not installed")
def test_the_drawn_minus_in_the_fallback_font_is_long_and_clear_of_the_next_figure():
    """In DejaVu Sans (a viewer without osifont) the drawn minus is at least 1.4 times the hyphen's
    length and as long as 0.75 of a figure's, and its ink ends before the next figure's begins when
    set at osifont's advance (each letter is placed at its own x: drawing.svg)."""
    from graphplan.drawing.fonts import font_path
    dv, osi = _font(DEJAVU), _font(font_path())
    ch = lettering("−")
    (x0, y0, x1, y1), _ = _box(dv, ch)
    (h0, _, h1, _), _ = _box(dv, "-")
    (z0, _, z1, _), _ = _box(dv, "0")
    assert x1 - x0 >= 1.4 * (h1 - h0) and x1 - x0 >= 0.75 * (z1 - z0)
    _, advance = _box(osi, ch)
    first = min(_box(dv, d)[0][0] for d in "0123456789")
    assert x1 < advance + first
    # DejaVu's own minus would run into the figure: the reason it is not drawn
    (m0, _, m1, _), _ = _box(dv, "\u2212")
    assert m1 > _box(osi, "-")[1] + first


def _raster(svg: str, k: float = 20.0) -> np.ndarray:
    import cairosvg
    from PIL import Image
    w = float(re.search(r'width="([\d.]+)mm"', svg).group(1))
    h = float(re.search(r'height="([\d.]+)mm"', svg).group(1))
    png = cairosvg.svg2png(bytestring=svg.encode(), output_width=int(w * k), output_height=int(h * k),
                           background_color="white")
    return np.asarray(Image.open(io.BytesIO(png)).convert("L")) < 128


@pytest.mark.parametrize("family", ["osifont", "'DejaVu Sans'"])
def test_a_rendered_minus_is_a_long_bar_apart_from_its_figures(family):
    """"−14" on a sheet, rendered with osifont and with the fallback font alone (the font-family
    named as a viewer without the embedded font resolves it): the minus is one stroke at least
    0.35 em long (a hyphen in DejaVu: 0.26 em), not joined to the 1."""
    from scipy import ndimage

    from graphplan.drawing.fonts import register
    from graphplan.drawing.svg import render
    register()
    rec = Record()
    size, k = 5.0, 20.0
    rec.label((2.0, 3.0), "−14", size=size)
    svg = render(rec, 20, 10)
    svg = re.sub(r'font-family="[^"]*"', f'font-family="{family}"', svg)
    ink = _raster(svg, k)
    labels, n = ndimage.label(ink)
    assert n >= 3                                  # −, 1, 4 apart
    parts = sorted(ndimage.find_objects(labels), key=lambda s: s[1].start)
    bar = parts[0]
    length = (bar[1].stop - bar[1].start) / k
    height = (bar[0].stop - bar[0].start) / k
    assert length >= 0.35 * em(size) and height < 0.25 * length, (length, height)


@pytest.mark.slow
def test_no_sheet_letters_a_sign_as_a_hyphen():
    """The shaper's dynamics sheet (axes graduated −500 … −4000) and force sheet: no number in the
    SVG's lettering begins with a hyphen-minus."""
    from conftest import example_sheet
    sign = re.compile(r"(?:^|[\s(=\[])-[0-9]")
    for kind in ("dynamics", "forces"):
        for page in example_sheet("shaper", kind).pages:
            texts = re.findall(r">([^<>]+)<", page.svg())
            assert not [t for t in texts if sign.search(t)], kind
            assert any(lettering("−") in t for t in texts), kind
