"""A dynamics set reads in the order of the work (review 5 #15, review 4 #16: the press's A3 set gave
Tables 1–3 on its first sheet and the constructions they report on the last two): the table of the
positions (the data the diagrams are plotted from) no later than the moments, the moments before
the energy–mass band, the flywheel's and the motor's tables (the results) after the band, and the
|kl| the set draws no shorter than when it led with all its tables."""
from __future__ import annotations

from types import SimpleNamespace

import pytest

from conftest import scene_study
from review_scenes import PRESS_EN


@pytest.mark.slow
def test_the_press_set_at_a3_reads_data_constructions_then_results():
    from graphplan.sheets.form import form
    from graphplan.sheets.sheet import BUILDERS
    args = SimpleNamespace(positions=None, accel=None, precision=0.5, lang="en", sheet="dynamics")
    sheet = BUILDERS["dynamics"](scene_study(PRESS_EN), form("A3"), args)
    at = {p.name: n for n, page in enumerate(sheet.pages) for p in page.placed}
    assert len(sheet.pages) > 1
    assert at["positions table"] <= at["moments"] < at["wittenbauer"], at
    assert at["flywheel table"] >= at["wittenbauer"] and at["motor table"] >= at["wittenbauer"], at
    kl = [t.text for page in sheet.pages for p in page.placed for t in p.record.items
          if t.kind == "text" and (t.text or "").startswith("|kl| = ")]
    assert kl and kl[0] == "|kl| = 68 mm", kl      # the construction (the terminal's) unchanged by the order
