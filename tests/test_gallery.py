"""drawings/ is current: every gallery sheet redrawn from examples/ equals the committed file."""
from __future__ import annotations

import pytest

from conftest import ROOT
from graphplan.cli.gallery import available, build


@pytest.mark.parametrize("scene,kind,lang,name", available())
def test_gallery_sheet_is_current(scene, kind, lang, name):
    path = ROOT / "drawings" / name
    assert path.exists(), f"drawings/{name} is missing: run python -m graphplan.cli.gallery"
    assert path.read_text(encoding="utf-8") == build(scene, kind, lang), \
        f"drawings/{name} is out of date: run python -m graphplan.cli.gallery"
