"""The title block's [sheet] fields in the sheet's language: ``student_en`` … on an English sheet, as
``title_en`` is; where no English is given romanised (util/romanize.py), on a Ukrainian sheet as written."""
from __future__ import annotations

from conftest import ROOT
from graphplan.sheets.compose import organisation, sheet_field

META = {"sheet.student": "Іваненко І. І.", "sheet.student_en": "I. I. Ivanenko", "sheet.teacher": "Петренко П. П.",
        "sheet.group": "МБ-21", "sheet.group_en": "MB-21", "sheet.organisation": "НУБіП України",
        "sheet.organisation_en": "NULES of Ukraine"}


def test_english_variants_on_an_english_sheet_only():
    assert sheet_field(META, "student", "en") == "I. I. Ivanenko"
    assert sheet_field(META, "student", "uk") == "Іваненко І. І."
    assert sheet_field(META, "teacher", "en") == "Petrenko P. P."          # no teacher_en: romanised (stop 55)
    assert sheet_field(META, "teacher", "uk") == "Петренко П. П."
    assert sheet_field(META, "nothing", "en") == ""
    assert organisation(META, "en") == "NULES of Ukraine, group\u00a0MB-21"
    assert organisation(META, "uk") == "НУБіП України, гр.\u00a0МБ-21"


def test_a_scene_s_english_fields_reach_the_title_block(tmp_path):
    from graphplan.exact.positions import study
    from graphplan.model.scene import load
    from graphplan.sheets.kintables import fields
    text = (ROOT / "examples" / "crank_slider.toml").read_text(encoding="utf-8")
    # the example carries its English fields (student_en, teacher_en, organisation_en) since stop 55
    assert 'teacher_en = "Teacher"' in text
    path = tmp_path / "scene.toml"
    path.write_text(text, encoding="utf-8")
    st = study(load(path))
    en, uk = fields(st, "en", "1:1"), fields(st, "uk", "1:1")
    assert (en["student"], en["teacher"]) == ("Student", "Teacher") and en["organisation"].startswith("NULES")
    assert (uk["student"], uk["teacher"]) == ("Студент", "Викладач") and uk["organisation"].startswith("НУБіП")


def test_a_scene_without_a_title_is_titled_in_the_sheet_s_language(tmp_path):
    """A scene that gives no title: «Механізм» on a Ukrainian sheet, "Mechanism" on an English one (the
    loader's default word "mechanism" was lettered on both)."""
    import re as _re
    from graphplan.exact.positions import study
    from graphplan.model.scene import load
    from graphplan.sheets.kintables import title_in
    text = (ROOT / "examples" / "crank_slider.toml").read_text(encoding="utf-8")
    text = _re.sub(r'(?m)^title(_en)? = .*\n', '', text)
    path = tmp_path / "scene.toml"
    path.write_text(text, encoding="utf-8")
    st = study(load(path))
    assert (title_in(st, "uk"), title_in(st, "en")) == ("Механізм", "Mechanism")
