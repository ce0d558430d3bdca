"""A dynamics set reads in the order of the work (review 7 #12, after review 5 #15 and review 4 #16: the
press's, a compressor's and the slotter's A3 sets gave tables on their first sheet and the constructions they
report on after them): the moments and the work on the first sheet, the energy–mass band next, the
tables (with ω(φ)) after the band — no sheet nearly empty, and a |kl| short of the A1 sheet's said in
the notes (the order costs |kl| only where the A1 sheet's is out of reach either way)."""
from __future__ import annotations

import re
from types import SimpleNamespace

import pytest

from conftest import ROOT, scene_study
from review_scenes import COMPRESSOR_DYN as COMPRESSOR, PRESS_EN


TABLES = ("positions table", "flywheel table", "motor table")
FILLED = 1 / 3        # the least share of a set's sheet's field its drawings' and tables' boxes cover (a third)


def _set(text: str, lang: str):
    from graphplan.sheets.form import form
    from graphplan.sheets.sheet import BUILDERS
    args = SimpleNamespace(positions=None, accel=None, precision=0.5, lang=lang, sheet="dynamics")
    return BUILDERS["dynamics"](scene_study(text), form("A3"), args)


@pytest.mark.slow
@pytest.mark.parametrize("scene, lang", [(PRESS_EN, "en"), (COMPRESSOR, "uk"),
                                         ((ROOT / "examples" / "slotter.toml").read_text(encoding="utf-8"), "uk")],
                         ids=["press", "compressor", "slotter"])
def test_an_a3_set_reads_constructions_then_tables(scene, lang):
    from graphplan.sheets.compose import field_of
    sheet = _set(scene, lang)
    at = {p.name: n for n, page in enumerate(sheet.pages) for p in page.placed}
    assert len(sheet.pages) > 1
    assert at["moments"] == 0 and at["moments"] < at["wittenbauer"], at
    assert all(at[t] >= at["wittenbauer"] for t in TABLES), at
    for n, page in enumerate(sheet.pages, 1):
        x0, y0, x1, y1 = field_of(page.form)
        covered = sum((b[2] - b[0]) * (b[3] - b[1]) for b in (p.record.bounds() for p in page.placed))
        assert covered / ((x1 - x0) * (y1 - y0)) >= FILLED, (n, [p.name for p in page.placed])
    kl = [t.text for page in sheet.pages for p in page.placed for t in p.record.items
          if t.kind == "text" and (t.text or "").startswith("|kl| = ")]
    drawn = float(re.match(r"\|kl\| = ([\d.,]+)", kl[0]).group(1).replace(",", "."))
    said = [t for t in kl[1:] if "A1" in t]          # short of the A1 sheet's: the notes say so, in numbers
    assert said and said[0].startswith(kl[0] + " ("), kl
    assert drawn >= 0.5 / 0.02 - 1e-9                 # the ruler's 0.5 mm within 2 % of |kl|
