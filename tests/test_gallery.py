"""drawings/ is current: every gallery sheet (every sheet of a set) redrawn from examples/ equals
the committed file.

The comparison leaves out only the embedded font subset (the base64 data of the SVG's @font-face
rules): its bytes are fontTools' to write and change with its version, not with the drawing (the
glyphs it carries follow from the text, which is compared)."""
from __future__ import annotations

import re

import pytest

from conftest import ROOT, example_sheet
from graphplan.cli.gallery import available, build_set, file_names

FONT_DATA = re.compile(r"url\(data:font/woff;base64,[A-Za-z0-9+/=]+\)")


def drawing(svg: str) -> str:
    return FONT_DATA.sub("url(data:font/woff;base64,…)", svg)


@pytest.mark.parametrize("scene,kind,lang,name,fmt", available())
def test_gallery_sheet_is_current(scene, kind, lang, name, fmt):
    """(The set as ``build_set`` makes it — ``BUILDERS`` on the example with the default options —
    built once per worker for every module that reads it: ``conftest.example_sheet``;
    test_the_gallery_builds_its_sets_as_the_tests_do checks that they are one.)"""
    pages = [page.svg() for page in example_sheet(scene, kind, fmt, lang).pages]
    for file, text in zip(file_names(name, len(pages)), pages):
        path = ROOT / "drawings" / file
        assert path.exists(), f"drawings/{file} is missing: run python -m graphplan.cli.gallery"
        assert drawing(path.read_text(encoding="utf-8")) == drawing(text), \
            f"drawings/{file} is out of date: run python -m graphplan.cli.gallery"
    stem = name[:-len(".svg")]
    assert not (ROOT / "drawings" / f"{stem}-{len(pages) + 1}.svg").exists(), "a stale sheet of the set"


def test_the_gallery_builds_its_sets_as_the_tests_do():
    """``build_set`` (what `python -m graphplan.cli.gallery` writes) draws the very sheets the tests
    share (``conftest.example_sheet``), on one of them (the four-bar's kinematics, a few seconds)."""
    assert build_set("four_bar", "kinematics", "uk", "A1") == [p.svg() for p in example_sheet("four_bar").pages]


def test_font_metrics_are_the_fonts():
    """graphplan/data/fonts/metrics.json (read instead of parsing the fonts) is what the packaged
    fonts say: every advance, ink box and foot."""
    import json

    from graphplan.graphic.record import METRICS, metrics_from_fonts
    stored = json.loads((ROOT / "graphplan" / "data" / "fonts" / METRICS).read_text(encoding="utf-8"))
    assert stored == json.loads(json.dumps(metrics_from_fonts()))


def test_fallback_boxes_are_the_fallback_font():
    """graphplan/data/fonts/fallback.json (the glyph boxes of the font a viewer without ours letters
    with, which the layout keeps lines clear of) is what that font says, where it is installed."""
    import json

    from graphplan.graphic.record import FALLBACK, fallback_font, fallback_from_font
    font = fallback_font()
    if font is None:
        pytest.skip("the fallback font (DejaVu Sans) is not installed")
    stored = json.loads((ROOT / "graphplan" / "data" / "fonts" / FALLBACK).read_text(encoding="utf-8"))
    assert stored == json.loads(json.dumps(fallback_from_font(font)))


def test_a_label_keeps_clear_of_either_fonts_ink():
    """A label's ink box (what lines are kept clear of) holds both fonts' glyphs set at our font's
    advances: DejaVu Sans's wider "м" and "=" reach past osifont's, and the box reaches them."""
    from fontTools.ttLib import TTFont

    from graphplan.graphic.record import Primitive, em, fallback_font
    from graphplan.drawing.svg import glyph_xs
    font = fallback_font()
    if font is None:
        pytest.skip("the fallback font (DejaVu Sans) is not installed")
    text, size = "мм = 4", 3.5
    ink = Primitive("text", ((0.0, 0.0),), text=text, size=size).ink()
    with TTFont(font) as f:
        upem, glyf, cmap = f["head"].unitsPerEm, f["glyf"], f.getBestCmap()
        for c, x in zip(text, glyph_xs(text, size, 0.0)):
            g = glyf[cmap[ord(c)]]
            if not getattr(g, "numberOfContours", 0):
                continue
            x0, x1 = x + g.xMin / upem * em(size), x + g.xMax / upem * em(size)
            assert ink[0] - 1e-9 <= x0 and x1 <= ink[2] + 1e-9, (c, x0, x1, ink)
            assert g.yMax / upem * em(size) <= ink[3] + 1e-9


def test_the_composition_picture_is_current():
    """docs/composition/zones.svg (the shaper's sheet with each drawing's box) is redrawn from the
    example."""
    from graphplan.cli.gallery import zones_svg
    path = ROOT / "docs" / "composition" / "zones.svg"
    assert drawing(path.read_text(encoding="utf-8")) == drawing(zones_svg()), \
        "docs/composition/zones.svg is out of date: run python -m graphplan.cli.gallery"
