"""drawings/ is current: every gallery sheet (every sheet of a set) redrawn from examples/ equals
the committed file."""
from __future__ import annotations

import pytest

from conftest import ROOT
from graphplan.cli.gallery import available, build_set, file_names


@pytest.mark.parametrize("scene,kind,lang,name,fmt", available())
def test_gallery_sheet_is_current(scene, kind, lang, name, fmt):
    pages = build_set(scene, kind, lang, fmt)
    for file, text in zip(file_names(name, len(pages)), pages):
        path = ROOT / "drawings" / file
        assert path.exists(), f"drawings/{file} is missing: run python -m graphplan.cli.gallery"
        assert path.read_text(encoding="utf-8") == text, \
            f"drawings/{file} is out of date: run python -m graphplan.cli.gallery"
    stem = name[:-len(".svg")]
    assert not (ROOT / "drawings" / f"{stem}-{len(pages) + 1}.svg").exists(), "a stale sheet of the set"
