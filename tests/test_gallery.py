"""drawings/ is current: every gallery sheet (every sheet of a set) redrawn from examples/ equals
the committed file.

The comparison leaves out only the embedded font subset (the base64 data of the SVG's @font-face
rules): its bytes are fontTools' to write and change with its version, not with the drawing (the
glyphs it carries follow from the text, which is compared)."""
from __future__ import annotations

import re

import pytest

from conftest import ROOT
from graphplan.cli.gallery import available, build_set, file_names

FONT_DATA = re.compile(r"url\(data:font/woff;base64,[A-Za-z0-9+/=]+\)")


def drawing(svg: str) -> str:
    return FONT_DATA.sub("url(data:font/woff;base64,…)", svg)


@pytest.mark.parametrize("scene,kind,lang,name,fmt", available())
def test_gallery_sheet_is_current(scene, kind, lang, name, fmt):
    pages = build_set(scene, kind, lang, fmt)
    for file, text in zip(file_names(name, len(pages)), pages):
        path = ROOT / "drawings" / file
        assert path.exists(), f"drawings/{file} is missing: run python -m graphplan.cli.gallery"
        assert drawing(path.read_text(encoding="utf-8")) == drawing(text), \
            f"drawings/{file} is out of date: run python -m graphplan.cli.gallery"
    stem = name[:-len(".svg")]
    assert not (ROOT / "drawings" / f"{stem}-{len(pages) + 1}.svg").exists(), "a stale sheet of the set"


def test_font_metrics_are_the_fonts():
    """graphplan/data/fonts/metrics.json (read instead of parsing the fonts) is what the packaged
    fonts say: every advance, ink box and foot."""
    import json

    from graphplan.graphic.record import METRICS, metrics_from_fonts
    stored = json.loads((ROOT / "graphplan" / "data" / "fonts" / METRICS).read_text(encoding="utf-8"))
    assert stored == json.loads(json.dumps(metrics_from_fonts()))


def test_the_composition_picture_is_current():
    """docs/composition/zones.svg (the shaper's sheet with each drawing's box) is redrawn from the
    example."""
    from graphplan.cli.gallery import zones_svg
    path = ROOT / "docs" / "composition" / "zones.svg"
    assert drawing(path.read_text(encoding="utf-8")) == drawing(zones_svg()), \
        "docs/composition/zones.svg is out of date: run python -m graphplan.cli.gallery"
