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


@pytest.fixture(scope="module")
def pump():
    """Stop 45's pump: its Wittenbauer construction at 12 divisions and the ruler's 0.5 mm."""
    from review_scenes import PUMP45

    from graphplan.exact.dynamics import analyse
    from graphplan.graphic.flywheel import construct
    return construct(analyse(scene_study(PUMP45), None), 12, 0.5)


@pytest.mark.parametrize("lang", ["uk", "en"])
def test_k_and_l_are_printed_as_the_ruler_reads_them_k_less_l_the_kl_printed(pump, lang):
    """The tangents' note prints k, l and |kl| consistently (stop 45's pump printed k = 0,715 mm,
    l = −65,1 mm, |kl| = 66 mm): k − l equals |kl| as printed, |kl| is the construction's (J's),
    and k and l lie within a ruler's step of where the tangents cut the ΔT axis (graphic.flywheel
    ``tangents``: the lines' intercepts)."""
    import re

    from graphplan.report.dynamics import tangents_note
    note = tangents_note(pump, lang)
    assert note is not None
    value = r"(−?[\d.,]+)"
    m = re.search(rf"k = {value} (?:мм|mm) (?:і|and) l = {value} (?:мм|mm), \|kl\| = {value}",
                  note.replace("\u00a0", " "))
    assert m, note
    k, l, kl = (float(g.replace("−", "-").replace(",", ".")) for g in m.groups())
    assert k - l == pytest.approx(kl, abs=1e-9)
    assert kl == pytest.approx(pump.kl, abs=1e-9)
    assert abs(k - pump.tangent["k"]) <= 0.25 + 1e-9
    assert abs(l - pump.tangent["l"]) <= 0.5 + 1e-9


@pytest.mark.parametrize("projections", [None, (-20.0, -10.0)])
def test_k_and_l_stand_clear_of_the_axis_and_the_dimension_line_each_by_the_line_it_names(pump, projections):
    """Stop 47: the letter l (one upright stroke) stood 2 mm beside the ΔT axis and read as a third
    line along it. Measured on the drawing: each letter's ink at least 3 mm from the ΔT axis (x = 0)
    and from the |kl| dimension line (the vertical arrows' x), between them, and nearer the level it
    names (k over the line through k, l under the line through l) than the other; the |kl| reading
    clear under the letter l."""
    from graphplan.drawing.flywheel import wittenbauer_record
    rec = wittenbauer_record(pump, "uk", projections=projections)
    xd = next(p for p in rec.items if p.step == "kl" and p.kind == "vector").points[0][0]
    k, l = pump.tangent["k"], pump.tangent["l"]
    for name, level, other, above in (("k", k, l, True), ("l", l, k, False)):
        x0, y0, x1, y1 = next(p for p in rec.items if p.kind == "text" and p.text == name).ink()
        assert xd + 3.0 <= x0 and x1 <= -3.0, (name, x0, x1, xd)
        assert (y0 >= level) if above else (y1 <= level), (name, y0, y1, level)
        assert abs((y0 + y1) / 2 - level) < abs((y0 + y1) / 2 - other)
    ly0 = next(p for p in rec.items if p.kind == "text" and p.text == "l").ink()[1]
    kl = next(p for p in rec.items if p.kind == "text" and p.text.startswith("|kl|")).ink()
    assert kl[3] <= ly0 or kl[2] <= xd, kl            # under the letter l, or left of the dimension line


@pytest.mark.slow                     # one A1 dynamics sheet: ~6 s of CPU
@pytest.mark.parametrize("lang", ["uk", "en"])
def test_the_six_bars_a1_sheet_says_why_a_flywheel_beside_the_motor_in_the_room_under_the_notes(lang):
    """Stop 47: ~200 × 75 mm stood empty under the notes beside I*(φ) while the sentence on why a
    flywheel though the motor is sized by the peak was the terminal's only. It is on the sheet,
    as the terminal words it, every line of the notes inside the field, nothing over the band."""
    from graphplan.util.markup import plain
    from graphplan.report.dynamics import dynamics_json, motor_note
    from graphplan.sheets.compose import field_of
    from graphplan.sheets.dynamics import _analysed, _drawn, construction
    from graphplan.sheets.form import form
    from graphplan.sheets.sheet import RAW
    st, f = scene_study(LINK47), form("A1")
    opts = SheetOptions(lang=lang, sheet="dynamics")
    sheet = RAW["dynamics"](st, f, opts)
    notes = next(p for p in sheet.placed if p.name == "notes")
    text = " ".join(plain(it.text) for it in notes.record.items if it.kind == "text")
    dyn = _analysed(st, None)
    L, size = construction(st, dyn, f, opts)[:2]
    said = plain(motor_note(dynamics_json(_drawn(dyn, opts, L, size, lang)[0]), lang))
    assert " ".join(said.replace("\u00a0", " ").split()) in " ".join(text.replace("\u00a0", " ").split())
    x0, y0, x1, y1 = field_of(f)
    nx0, ny0, nx1, ny1 = notes.record.bounds()
    assert x0 <= nx0 and y0 <= ny0 and nx1 <= x1 and ny1 <= y1
    for p in sheet.placed:
        if p.name in ("energy", "wittenbauer", "inertia"):
            bx0, by0, bx1, by1 = p.record.bounds()
            assert nx1 <= bx0 or bx1 <= nx0 or ny1 <= by0 or by1 <= ny0, p.name
