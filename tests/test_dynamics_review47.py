"""Stop 47's dynamics sheet: the six-bar LINK47 (tests/review_scenes.py) and the project's numbering
read from counts kept on disk (sheets/sheet.py ``pages_of``)."""
from __future__ import annotations

import pytest
from conftest import scene_study
from review_scenes import LINK47

from graphplan.sheets.compose import SheetOptions


@pytest.mark.slow                     # the six-bar's A2 kinematics and forces sets composed: ~50 s of CPU
def test_the_six_bars_a2_numbers_are_its_real_sets_sheets_composed_or_read_back(tmp_path, monkeypatch):
    """The dynamics A2 set numbered with the counts composed (a cold cache) and with them read back
    from disk (the process's memory cleared, the builders unable to compose): the same numbers,
    those of the kinematics and forces sets composed whole."""
    from graphplan.sheets import sheet as S
    from graphplan.sheets.form import form
    monkeypatch.setenv("GRAPHPLAN_CACHE", str(tmp_path))
    monkeypatch.setattr(S, "_PAGES", {})
    st, f = scene_study(LINK47), form("A2")
    opts = SheetOptions(lang="uk", sheet="dynamics")

    def numbers(sheet):
        return [(p.fields["sheet"], p.fields["sheets"]) for p in sheet.pages]
    cold = numbers(S.BUILDERS["dynamics"](st, f, opts))
    real = {k: len(S.RAW[k](st, f, SheetOptions(lang="uk", sheet=k)).pages) for k in ("kinematics", "forces")}
    first = real["kinematics"] + real["forces"] + 1
    assert cold == [(str(first + i), str(first - 1 + len(cold))) for i in range(len(cold))]
    monkeypatch.setattr(S, "_PAGES", {})
    monkeypatch.setitem(S.RAW, "kinematics", None)             # composing now would fail
    monkeypatch.setitem(S.RAW, "forces", None)
    assert numbers(S.BUILDERS["dynamics"](st, f, opts)) == cold
