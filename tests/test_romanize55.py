"""English sheets of a Ukrainian scene letter no Cyrillic (review55's finding 3: «ТММ.КП.77.001»,
«Рецензент Р. Р.», «НУБіП України» on an English title block): ``designation_en`` as ``title_en``,
else the scene's text romanised by the Cabinet of Ministers' resolution No. 55 of 2010
(graphplan/util/romanize.py); the Ukrainian sheets letter the scene's text as written."""
from __future__ import annotations

import re
import xml.etree.ElementTree as ET

import pytest
from hypothesis import given, settings
from hypothesis import strategies as hs

import review_scenes as R
from conftest import scene_sheet
from graphplan.util.romanize import has_cyrillic, romanize, scene_text, scene_title

# the resolution's own table of examples (its column 3), letter by letter
OFFICIAL = {"Алушта": "Alushta", "Андрій": "Andrii", "Борщагівка": "Borshchahivka", "Вінниця": "Vinnytsia",
            "Гадяч": "Hadiach", "Згорани": "Zghorany", "Ґалаґан": "Galagan", "Дон": "Don", "Рівне": "Rivne",
            "Євген": "Yevhen", "Короп'є": "Koropie", "Житомир": "Zhytomyr", "Жанна": "Zhanna", "Закарпаття": "Zakarpattia",
            "Медвин": "Medvyn", "Іванків": "Ivankiv", "Їжакевич": "Yizhakevych", "Кадиївка": "Kadyivka",
            "Йосипівка": "Yosypivka", "Стрий": "Stryi", "Олексій": "Oleksii", "Київ": "Kyiv", "Лебедин": "Lebedyn",
            "Миколаїв": "Mykolaiv", "Ніжин": "Nizhyn", "Одеса": "Odesa", "Полтава": "Poltava", "Решетилівка": "Reshetylivka",
            "Суми": "Sumy", "Тернопіль": "Ternopil", "Ужгород": "Uzhhorod", "Фастів": "Fastiv", "Харків": "Kharkiv",
            "Біла Церква": "Bila Tserkva", "Чернівці": "Chernivtsi", "Шостка": "Shostka", "Гоща": "Hoshcha",
            "Русь": "Rus", "Юрій": "Yurii", "Крюківка": "Kriukivka", "Яготин": "Yahotyn", "Ічня": "Ichnia",
            "Знам'янка": "Znamianka", "Розгон": "Rozghon"}


@pytest.mark.parametrize("uk,en", sorted(OFFICIAL.items()))
def test_the_resolution_s_own_examples(uk, en):
    assert romanize(uk) == en
    assert romanize(uk.replace("'", "\u2019")) == en           # the typographic apostrophe likewise


def test_the_review_s_title_block():
    assert romanize("Рецензент Р. Р.") == "Retsenzent R. R."
    assert romanize("НУБіП України") == "NUBiP Ukrainy"
    assert romanize("ТММ.КП.77.001") == "TMM.KP.77.001"
    assert romanize("МБ-77") == "MB-77"
    assert romanize("ЩЕРБАК") == "SHCHERBAK" and romanize("Щербак") == "Shcherbak" and romanize("ХПІ") == "KhPI"


# 100 random texts (300 took 1,2 s of the default run): the resolution's own examples and the title
# block's above fix the mapping, the digits and the signs kept; these the properties over any text
@settings(max_examples=100, deadline=None)
@given(hs.text(alphabet=hs.characters(min_codepoint=0x20, max_codepoint=0x52f, blacklist_categories=("Cs",)),
               max_size=40))
def test_romanised_text_has_no_cyrillic_and_latin_stays(text):
    out = romanize(text)
    assert not has_cyrillic(out)
    assert romanize(out) == out
    if not has_cyrillic(text):
        assert out == text                        # a Latin name (or any text without Cyrillic) as written
    # what is not Cyrillic is kept in its order: digits and signs survive
    assert re.sub(r"[^0-9.,;:()\- ]", "", out) == re.sub(r"[^0-9.,;:()\- ]", "", re.sub(r"(?<=[\u0400-\u052f])['’ʼ`](?=[\u0400-\u052f])", "", text)) \
        or "'" in text or "’" in text


def test_scene_text_per_language():
    meta = {"designation": "ТММ.КП.77.000", "title": "Кулачок", "sheet.student": "Рецензент Р. Р.",
            "sheet.teacher": "Викладач", "sheet.teacher_en": "Teacher", "title_en": "A cam (Кулачок)"}
    assert scene_text(meta, "designation", "uk") == "ТММ.КП.77.000"
    assert scene_text(meta, "designation", "en") == "TMM.KP.77.000"
    assert scene_text({**meta, "designation_en": "TMM.CP.77.000"}, "designation", "en") == "TMM.CP.77.000"
    assert scene_text(meta, "sheet.student", "en") == "Retsenzent R. R."
    assert scene_text(meta, "sheet.teacher", "en") == "Teacher" and scene_text(meta, "sheet.teacher", "uk") == "Викладач"
    assert scene_title(meta, "Кулачок", "en") == "A cam (Kulachok)"          # a Cyrillic _en is romanised too
    assert scene_title({}, "Кулачок", "en") == "Kulachok" and scene_title(meta, "Кулачок", "uk") == "Кулачок"


# -- the loaders: designation_en as title_en ------------------------------------------------------------

def _strip_en(text: str) -> str:
    """A review scene as a Ukrainian student writes it: no ``_en`` key anywhere, ``lang`` "uk"."""
    text = re.sub(r"^\w+_en = .*\n", "", text, flags=re.M)
    text = re.sub(r",\s*title_en = \"[^\"]*\"", "", text)
    text = re.sub(r"title_en = \"[^\"]*\",\s*", "", text)
    return re.sub(r'^lang = "en"', 'lang = "uk"', text, flags=re.M)


@pytest.mark.parametrize("text,loader", [(R.FOURBAR, "scene"), (R.CAM_KN, "cam"), (R.GEARS_17_40, "gears")])
def test_loaders_take_designation_en_and_name_it_when_refusing(tmp_path, text, loader):
    import importlib

    from graphplan.util.errors import GraphplanError
    load = importlib.import_module(f"graphplan.model.{loader}").load
    path = tmp_path / "s.toml"
    path.write_text('designation_en = "TMM.CP.07.000"\n' + _strip_en(text), encoding="utf-8")
    got = load(path)
    meta = dict(got.task.meta if loader == "scene" else got.meta)
    assert meta["designation_en"] == "TMM.CP.07.000"
    path.write_text('designation_EN = "x"\n' + _strip_en(text), encoding="utf-8")
    with pytest.raises(GraphplanError) as e:
        load(path)
    assert "designation_en" in e.value.line("uk") and "designation_en" in e.value.line("en")
    assert "невідомий ключ" in e.value.line("uk") and "unknown key" in e.value.line("en")


# -- the sheets ------------------------------------------------------------------------------------------

def _scene(text: str, kind: str, tmp_path):
    """What the kind's builder takes: a lever scene studied, a cam or a gear scene loaded."""
    from conftest import scene_study
    if kind in ("cam", "gears"):
        import importlib
        path = tmp_path / f"{kind}.toml"
        path.write_text(text, encoding="utf-8")
        return importlib.import_module(f"graphplan.model.{kind}").load(path)
    return scene_study(text)


def _sheet(text: str, kind: str, lang: str, tmp_path):
    if kind in ("cam", "gears"):            # cheap (1–3 s): built here
        from conftest import composed
        from graphplan.sheets.compose import SheetOptions
        from graphplan.sheets.form import form
        return composed(kind, _scene(text, kind, tmp_path), form("A1"), SheetOptions(lang=lang, sheet=kind))
    return scene_sheet(text, kind, "A1", lang)

def lettering(sheet) -> list[str]:
    """Every text of the set's SVGs: the <title> and each <text> with its tspans."""
    out = []
    for page in sheet.pages:
        root = ET.fromstring(page.svg())
        for el in root.iter():
            if el.tag.split("}")[-1] in ("text", "title"):
                t = "".join(el.itertext())
                if t.strip():
                    out.append(t)
    return out


SHEETS = [(R.FOURBAR, "kinematics"), (R.FOURBAR, "forces"), (R.FOURBAR, "dynamics"), (R.SIXBAR7, "kinematics"),
          (R.SIXBAR7, "dynamics"), (R.CAM_KN, "cam"), (R.CAM_TR, "cam"), (R.GEARS_17_40, "gears"),
          (R.GEARS_REVIEW, "gears")]


@pytest.mark.slow
@pytest.mark.parametrize("text,kind", SHEETS, ids=[f"{k}-{i}" for i, (_, k) in enumerate(SHEETS)])
def test_english_sheet_of_a_ukrainian_scene_letters_no_cyrillic(text, kind, tmp_path):
    scene = _strip_en(text)
    texts = lettering(_sheet(scene, kind, "en", tmp_path))
    bad = [t for t in texts if has_cyrillic(t)]
    assert not bad, f"Cyrillic on the English {kind} sheet: {bad[:5]}"
    designation = re.search(r'^designation = "([^"]*)"', scene, re.M).group(1)
    student = re.search(r'^student = "([^"]*)"', scene, re.M).group(1)
    joined = " ".join(texts)
    assert romanize(designation) in joined and romanize(student) in joined     # the title block, romanised
    assert "NUBiP Ukrainy" in joined


@pytest.mark.slow
@pytest.mark.parametrize("text,kind", [(R.FOURBAR, "kinematics"), (R.CAM_KN, "cam"), (R.GEARS_17_40, "gears")],
                         ids=["kinematics", "cam", "gears"])
def test_ukrainian_sheet_letters_the_scene_as_written(monkeypatch, text, kind, tmp_path):
    """A Ukrainian sheet never romanises: built with the romaniser broken it letters the scene's
    designation, student and organisation as the scene writes them, Cyrillic."""
    import graphplan.util.romanize as rz

    def refuse(_text):
        raise AssertionError("a Ukrainian sheet romanised its text")
    from conftest import composed
    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.form import form
    scene = _strip_en(text)
    monkeypatch.setattr(rz, "romanize", refuse)
    sheet = composed(kind, _scene(scene, kind, tmp_path), form("A1"), SheetOptions(lang="uk", sheet=kind))
    joined = " ".join(lettering(sheet))
    for key in ("designation", "student"):
        assert re.search(rf'^{key} = "([^"]*)"', scene, re.M).group(1) in joined
    assert "НУБіП України" in joined


@pytest.mark.slow
def test_english_sheet_takes_designation_en(tmp_path):
    scene = 'designation_en = "TMM.CP.41.000"\n' + _strip_en(R.CAM_KN)
    joined = " ".join(lettering(_sheet(scene, "cam", "en", tmp_path)))
    assert "TMM.CP.41.000" in joined and "TMM.KM" not in joined


def test_english_terminal_of_a_ukrainian_scene_letters_no_cyrillic(tmp_path, capsys):
    from graphplan.cli.main import main
    path = tmp_path / "s.toml"
    path.write_text(_strip_en(R.CAM_KN), encoding="utf-8")
    main(["cam", str(path), "--lang", "en"])
    out = capsys.readouterr().out
    assert out.strip() and not has_cyrillic(out), [line for line in out.splitlines() if has_cyrillic(line)][:3]
    assert romanize("Кулачковий механізм з поступальним загостреним штовхачем") in out
