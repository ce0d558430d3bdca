"""The lab's own language: one catalogue complete in Ukrainian and English, numbers as the lab writes
them, the typesetting markup, and every person-facing output scanned for the other language.

The scans: a Ukrainian text may hold Latin only as symbols (letters of at most two, the lab's
subscripts such as max), names the scene or the variant table gives (points, links, file names, the
designation) and command-line options; no Latin unit (m, mm, N, s, rad, m/s …) and, on sheets, no
decimal point. An English text holds no Cyrillic but the names the scene gives.
"""
from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET

import pytest
from hypothesis import given, strategies as hs

from conftest import ROOT
from graphplan.util.markup import Run, escape, plain, runs
from graphplan.util.words import (LANGS, UNITS, WORDS, check_lang, fixed, force_symbol, num, pair_kind, pick,
                                  said, unit, word)
from graphplan.util.errors import GraphplanError

LATIN_WORD = re.compile(r"[A-Za-z]{3,}")
CYRILLIC = re.compile(r"[А-Яа-яІіЇїЄєҐґ]")
# a Latin unit: mm, rad, rpm, kg anywhere; m, N, s as part of a compound (m/s, N·m, (m/s)/mm) or after a number
# — not a subscripted point's name after another's index (the gear sheet's N₁N₂, read "N 1 N 2")
LATIN_UNIT = re.compile(r"(?<![A-Za-z_])(?:mm|rad|rpm|kg)(?![A-Za-z])|(?<![A-Za-z_])(?:m|N|s)/|N·m|\(m/"
                        r"|\d\s?(?:m|s|N)(?![A-Za-z0-9_])(?!\s\d)")
SYMBOLS = {"max", "min", "graphplan", "Tab", "sin", "cos"}   # the lab's subscripts; the program's name; sin, cos
FIELDS = re.compile(r"\{[^{}]*\}")


def latin_words(text: str, allowed: set[str]) -> list[str]:
    """Latin words of 3+ letters in ``text`` that are neither symbols nor names nor --options nor
    file paths nor a file name's extension (.html)."""
    text = re.sub(r"--[a-z-]+|(?<!\S)(?:/[\w.-]+)+|(?<![\w.])\.[a-z]{2,5}\b", " ", text)   # .html: an extension
    return [w for w in LATIN_WORD.findall(text) if w not in SYMBOLS and w not in allowed
            and not re.fullmatch(r"[A-Za-z](?:max|min)", w)]          # Mmax: M with its index, plain


def scene_names(path) -> set[str]:
    """The words a scene gives: its points, links, guides, keys, titles and sheet fields."""
    import tomllib
    data = tomllib.loads(path.read_text(encoding="utf-8"))
    names: set[str] = set()

    def walk(v) -> None:
        if isinstance(v, dict):
            for k, x in v.items():
                names.update(LATIN_WORD.findall(str(k)))
                walk(x)
        elif isinstance(v, list):
            for x in v:
                walk(x)
        elif isinstance(v, str):
            names.update(LATIN_WORD.findall(v))
            names.update(CYRILLIC.findall(v))
    walk(data)
    return names | {path.stem} | set(path.stem.split("_"))


# -- the catalogue ------------------------------------------------------------------------------------

@pytest.mark.parametrize("key", sorted(WORDS))
def test_every_word_has_both_languages(key):
    uk, en = WORDS[key]
    assert uk.strip() and en.strip(), f"{key!r} lacks a language"
    assert sorted(FIELDS.findall(uk)) == sorted(FIELDS.findall(en)), f"{key!r}: the fields differ"
    bare_uk, bare_en = FIELDS.sub(" ", uk), FIELDS.sub(" ", en)
    assert not CYRILLIC.search(bare_en), f"{key!r}: Cyrillic in the English text"
    assert not latin_words(bare_uk, set()), f"{key!r}: English words in the Ukrainian text: {bare_uk}"
    assert not LATIN_UNIT.search(bare_uk), f"{key!r}: a Latin unit in the Ukrainian text"
    for lang in LANGS:      # every field fills
        word(key, lang, **{f.strip("{}"): "x" for f in FIELDS.findall(uk) if f.strip("{}") not in UNITS})


def test_units_in_both_languages():
    for key, (uk, en) in UNITS.items():
        assert not LATIN_WORD.search(uk) and not LATIN_UNIT.search(uk), key
        assert not CYRILLIC.search(en), key
    assert unit("(m/s²)/mm", "uk") == "(м/с²)/мм" and unit("N·m/mm", "uk") == "Н·м/мм"
    assert unit("1/s", "uk") == "с⁻¹" and unit("(m/s)/mm", "en") == "(m/s)/mm"


def test_language_choice():
    assert pick(None, None) == "uk" and pick(None, "en") == "en" and pick("uk", "en") == "uk"
    assert check_lang(None) == "uk"
    with pytest.raises(GraphplanError):
        check_lang("de")


def test_lab_symbols():
    assert [pair_kind(k, "uk") for k in ("RPR", "RRP", "RRR", "PRP", "RPP")] == ["ВПВ", "ВВП", "ВВВ", "ПВП", "ВПП"]
    assert pair_kind("RPR", "en") == "RPR"
    assert force_symbol("R34τ", "uk") == "R^{τ}_{34}" and force_symbol("R34n", "en") == "R^{n}_{34}"
    assert force_symbol("M_b", "uk") == "M_зр" and force_symbol("P_b", "uk") == "P_зр"
    assert force_symbol("P_b", "en") == "P_bal"      # not P_b beside a point B's P_B (review 13 #4)
    assert force_symbol("M_b", "en") == "M_b" and force_symbol("G2", "uk") == "G_{2}"
    assert force_symbol("MΦ3''", "uk") == "M^{Φ}_{3}''"


# -- numbers -------------------------------------------------------------------------------------------

def test_numbers_as_the_lab_writes_them():
    assert num(0.0025, "uk") == "0,0025" and num(0.0025, "en") == "0.0025"
    assert num(5346.1, "uk") == "5346" and num(11.0812, "uk") == "11,08" and num(-0.44, "uk") == "-0,44"
    assert num(7.146e-05, "uk") == "7,146·10⁻⁵" and num(None, "uk") == "—" and num(math.nan, "en") == "—"
    assert num(9.99996, "en") == "10" and num(0.0, "uk") == "0"
    assert fixed(30.0, "uk", 1) == "30,0" and fixed(-0.001, "en", 1) == "0.0"
    assert fixed(1.0834, "uk", 2, plus=True) == "+1,08" and fixed(-0.004, "uk", 2, plus=True) == "+0,00"


@given(hs.floats(min_value=-1e9, max_value=1e9, allow_nan=False).filter(lambda v: v == 0 or abs(v) > 1e-12))
def test_num_keeps_four_significant_figures(v):
    en, uk = num(v, "en"), num(v, "uk")
    assert uk == en.replace(".", ",")                       # one formatter, only the decimal sign differs
    assert "." not in uk
    mantissa, _, power = en.partition("·10")
    back = float(mantissa) * (10 ** int(power.translate(str.maketrans("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789")))
                              if power else 1)
    assert back == pytest.approx(v, rel=5.01e-4, abs=1e-300)


def test_said_formats_each_language():
    s = said("grade near zero", bound=0.000625, tol=5.0, floor=0.0125)
    assert s["uk"] == "майже нуль: допуск ±0,000625 (5 % від 0,0125)"
    assert s["en"] == "near zero: within ±0.000625 (5 % of 0.0125)"


# -- markup ---------------------------------------------------------------------------------------------

def test_markup_runs():
    assert runs("a^τ_BA") == [Run("a"), Run("τ", 1), Run("BA", -1, stacked=True)]
    assert runs("M_зр = 3") == [Run("M"), Run("зр", -1), Run(" = 3")]
    assert runs("W = 3n − 2p_5 − p_4")[1] == Run("5", -1)
    assert runs("R_{1-10}") == [Run("R"), Run("1-10", -1)]
    assert runs(escape("crank_slider^2")) == [Run("crank_slider^2")]
    assert runs("a_ b") == [Run("a_ b")]                   # no script without a letter after the mark
    assert plain("W = 3n − 2p_5 − p_4") == "W = 3n − 2p₅ − p₄" and plain("a^n_BA") == "aⁿ_BA"
    assert plain("a^τ_BA") == "a^τ_BA" and plain(escape("x_y")) == "x_y"


def test_width_counts_small_scripts():
    from graphplan.graphic.record import plain_width, text_width
    assert text_width("a^τ_BA", 5.0) < plain_width("aτBA", 5.0)
    assert text_width("a^τ_BA", 5.0) == pytest.approx(plain_width("a", 5.0) + 0.7 * plain_width("BA", 5.0))
    assert text_width(escape("a_b"), 5.0) == pytest.approx(plain_width("a_b", 5.0))


def test_svg_draws_scripts_as_tspans_with_baseline_shifts():
    from graphplan.drawing.svg import render
    from graphplan.graphic.record import Record
    rec = Record("t")
    rec.label((10.0, 10.0), "a^τ_BA = 3", size=5.0)
    rec.label((10.0, 20.0), "I(0-1) → II(2-3)", size=5.0)
    root = ET.fromstring(render(rec, 100.0, 40.0))
    spans = [e for e in root.iter() if e.tag.endswith("tspan")]
    by_text = {e.text.replace("\u00a0", " ").strip(): e.attrib for e in spans}
    from graphplan.graphic.record import em
    assert float(by_text["τ"]["font-size"]) == pytest.approx(0.7 * em(5.0), abs=1e-3) and float(by_text["τ"]["dy"]) < 0
    assert float(by_text["BA"]["dy"]) > 0 and by_text["BA"]["x"].split()[0] == by_text["τ"]["x"].split()[0]  # stacked
    assert float(by_text["= 3"]["dy"]) == pytest.approx(-float(by_text["τ"]["dy"]) - float(by_text["BA"]["dy"]))
    assert "DejaVu" in by_text["→"]["font-family"]        # osifont has no arrow


def test_dxf_draws_scripts_smaller_on_shifted_baselines():
    import io

    import ezdxf

    from graphplan.drawing.dxf import to_dxf
    from graphplan.graphic.record import Record
    rec = Record("t")
    rec.label((10.0, 10.0), "M_зр", size=5.0)
    doc = ezdxf.read(io.StringIO(to_dxf(rec, 100.0, 40.0).decode("utf-8")))
    texts = {t.dxf.text: t for t in doc.modelspace().query("TEXT")}
    assert texts["M"].dxf.height == 5.0 and texts["зр"].dxf.height == pytest.approx(3.5)
    assert texts["зр"].dxf.insert[1] < texts["M"].dxf.insert[1] and texts["зр"].dxf.insert[0] > 10.0


# -- the sheets ------------------------------------------------------------------------------------------

def svg_runs(path) -> list[list[str]]:
    """Each <text> of an SVG as the list of its text pieces (the text and its tspans)."""
    root = ET.parse(path).getroot()
    out = []
    for el in root.iter():
        if el.tag.endswith("}text"):
            out.append([t for t in el.itertext() if t.strip()])
    return out


def gallery(lang: str) -> list[tuple[str, str]]:
    from graphplan.cli.gallery import available
    out = []
    for scene, kind, lg, name, fmt in available():
        if lg == lang:
            stem = name[:-len(".svg")]
            out += [(scene, name)] + [(scene, p.name) for p in sorted((ROOT / "drawings").glob(f"{stem}-*.svg"))]
    return out


@pytest.mark.parametrize("scene,name", gallery("uk"))
def test_ukrainian_gallery_sheet_has_no_english(scene, name):
    """drawings/ is the gallery rendered in Ukrainian (test_gallery keeps it current)."""
    names = scene_names(ROOT / "examples" / f"{scene}.toml")
    texts = svg_runs(ROOT / "drawings" / name)
    assert len(texts) > (20 if re.search(r"_a\d|-\d", name) else 100)   # an A2/A3 set shares the text out
    designation = re.compile(r"^[А-ЯA-Z]+\.[\w.]+$")
    table_number = re.compile(r"Таблиця \d+\.\d+")            # "Таблиця 2.1": a number, not a decimal
    for pieces in texts:
        line = " ".join(pieces)
        assert not latin_words(line, names), f"{name}: English in {line!r}"
        assert not LATIN_UNIT.search(re.sub(r"d ?[2²]? ?s ?/ ?dφ ?[2²]?", "", line)), f"{name}: a Latin unit in {line!r}"
        if not designation.match("".join(pieces)):          # a kerned designation comes in two runs
            assert not re.search(r"\d\.\d", table_number.sub("", line)), f"{name}: a decimal point in {line!r}"


@pytest.mark.parametrize("scene,name", gallery("en"))
def test_english_gallery_sheet_has_no_cyrillic(scene, name):
    names = scene_names(ROOT / "examples" / f"{scene}.toml")
    for pieces in svg_runs(ROOT / "drawings" / name):
        line = " ".join(pieces)
        stray = [c for c in CYRILLIC.findall(line) if c not in names]
        words = [w for w in re.findall(r"[А-Яа-яІіЇїЄєҐґ]+", line) if w not in " ".join(
            str(v) for v in names)]
        assert not stray or not words, f"{name}: Cyrillic in {line!r}"


def test_plan_labels_are_typeset():
    text = (ROOT / "drawings" / "shaper.svg").read_text(encoding="utf-8")
    assert re.search(r">p</tspan><tspan dy=\"[0-9.]+\" font-size=\"[0-9.]+\"[^>]*>v</tspan>", text)   # the pole p_v
    assert re.search(r">a</tspan><tspan dy=\"-[0-9.]+\" font-size=\"[0-9.]+\"[^>]*>τ</tspan>", text)   # a^τ in tables
    assert re.search(r"(?<![А-Яа-я])ВПВ(?![А-Яа-я])", text)           # the dyad's kind, as a word


# -- every command's terminal output ---------------------------------------------------------------------

def run(capsys, *argv):
    from graphplan.cli.main import main
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


def assert_ukrainian(text: str, names: set[str], what: str) -> None:
    for line in text.splitlines():
        assert not latin_words(line, names), f"{what}: English in {line!r}"
        bare = re.sub(r"[A-Za-z]+", lambda m: "" if m.group(0) in names else m.group(0), line)
        assert not LATIN_UNIT.search(bare), f"{what}: a Latin unit in {line!r}"


@pytest.mark.parametrize("scene", ["shaper", "slotter", "lab_crank_slider"])
@pytest.mark.parametrize("command", [["analyze", "--positions", "4"], ["plans"], ["diagrams"], ["forces"]])
def test_ukrainian_output_of_every_command(capsys, tmp_path, scene, command):
    path = ROOT / "examples" / f"{scene}.toml"
    code, out, err = run(capsys, command[0], path, *command[1:], "--lang", "uk")
    assert code == 0, err
    assert_ukrainian(out, scene_names(path), f"{command[0]} {scene}")
    code, default, _ = run(capsys, command[0], path, *command[1:])
    assert default == out                                   # Ukrainian is everyone's default
    code, en, _ = run(capsys, command[0], path, *command[1:], "--lang", "en")
    assert not [ln for ln in en.splitlines()[1:] if CYRILLIC.search(ln)
                and not set(CYRILLIC.findall(ln)) <= scene_names(path)]


def test_sheet_reports_in_its_language(capsys, tmp_path):
    path = ROOT / "examples" / "four_bar.toml"
    code, out, err = run(capsys, "sheet", path, "-o", tmp_path / "s.svg", "--format", "A2")
    assert code == 0 and "мм" in err and "блоків" in err
    assert_ukrainian(err.replace(str(tmp_path), ""), scene_names(path), "sheet")


def test_ukrainian_key_and_check(capsys, tmp_path):
    table = ROOT / "examples" / "crank_slider_variants.csv"
    names = set(LATIN_WORD.findall(table.read_text(encoding="utf-8"))) | {"csv", "variants"}   # its columns
    code, out, err = run(capsys, "key", table, "-o", tmp_path / "k", "--no-pdf", "--quiet", "--lang", "uk")
    assert code == 0, err
    assert_ukrainian(out, names, "key")
    for piece in svg_runs(tmp_path / "k" / "01" / "key.svg") + svg_runs(tmp_path / "k" / "summary.svg"):
        line = " ".join(piece)
        assert not latin_words(line, names | {"crank", "slider", "an", "at", "ak", "ar"}), f"key sheet: {line!r}"
        assert not re.search(r"\d\.\d", line), f"key sheet: a decimal point in {line!r}"
    student = tmp_path / "s.csv"
    student.write_text("variant,position,quantity,value\n01,1,v_B,7.2\n01,1,v_A,18.76\n01,1,omega_AB,-53.2\n")
    code, out, err = run(capsys, "check", tmp_path / "k" / "01", student, "--lang", "uk")
    assert code == 0, err
    assert_ukrainian(out, {"csv", "key", "json", "omega"} | names, "check")


def test_scene_lang_is_the_default(tmp_path, capsys):
    text = (ROOT / "examples" / "four_bar.toml").read_text(encoding="utf-8")
    path = tmp_path / "four_bar_en.toml"
    path.write_text('lang = "en"\n' + text, encoding="utf-8")
    _, out, _ = run(capsys, "plans", path)
    assert "Velocities read off" in out
    _, out, _ = run(capsys, "plans", path, "--lang", "uk")
    assert "Швидкості" in out
    path.write_text('lang = "de"\n' + text, encoding="utf-8")
    code, _, err = run(capsys, "plans", path)
    assert code == 2 and "lang" in err and err.count("\n") == 1


def test_every_command_takes_lang():
    from graphplan.cli.main import build_parser
    parser = build_parser()
    sub = next(a for a in parser._actions if a.__class__.__name__ == "_SubParsersAction")
    for name, p in sub.choices.items():
        options = {o for a in p._actions for o in a.option_strings}
        assert "--lang" in options, f"{name} has no --lang"
        assert p.get_default("lang") is None                # one default for all: the scene's, else uk


# the shaper: slow (the same words; the default run keeps the slotter, the longer of the two runs)
@pytest.mark.parametrize("scene", [pytest.param("shaper", marks=pytest.mark.slow), "slotter"])
def test_ukrainian_output_of_dynamics(capsys, scene):
    """The dynamics' tables in Ukrainian (decimal comma, Ukrainian units), and Ukrainian by default."""
    path = ROOT / "examples" / f"{scene}.toml"
    code, out, err = run(capsys, "dynamics", path, "--lang", "uk")
    assert code == 0, err
    assert_ukrainian(out, scene_names(path), f"dynamics {scene}")
    assert not re.search(r"\d\.\d", out), "a decimal point in the Ukrainian tables"
    code, default, _ = run(capsys, "dynamics", path)
    assert default == out


def test_ukrainian_counts_agree_with_their_number():
    """«1 поділка, 2–4 поділки, 5–20 поділок», by the last two digits (11–14 take the many form)."""
    from graphplan.util.words import uk_count, word
    forms = ("поділка", "поділки", "поділок")
    expect = {1: 0, 2: 1, 4: 1, 5: 2, 11: 2, 12: 2, 14: 2, 21: 0, 22: 1, 24: 1, 25: 2, 101: 0, 111: 2, 112: 2, 360: 2}
    for n, k in expect.items():
        assert uk_count(n, *forms) == forms[k], n
    assert word("divisions count", "uk", n=24) == "24 поділки"
    assert word("divisions count", "en", n=24) == "24 divisions"



def test_every_sheet_word_has_its_glyphs():
    """Review 13 #6: a cam note's English quotes “—” drew as empty boxes — osifont lacks U+201C/D.
    Every catalogue word, every drawing or sheet module's own WORDS and the cam's δ-dash note, as
    drawn (``lettering`` replaces what the GOST font lacks), use only characters the packaged fonts
    have."""
    import importlib
    import pkgutil
    from pathlib import Path

    from fontTools.ttLib import TTFont

    import graphplan
    from graphplan.graphic.record import FONTS, lettering
    from graphplan.report.cam import short_note
    from graphplan.util.words import WORDS
    fonts = Path(graphplan.__file__).parent / "data" / "fonts"
    have: set[int] = set()
    for name in FONTS:
        with TTFont(str(fonts / name)) as f:
            have |= set(f.getBestCmap())

    def strings(v):
        if isinstance(v, str):
            yield v
        elif isinstance(v, dict):
            for w in v.values():
                yield from strings(w)
        elif isinstance(v, (tuple, list)):
            for w in v:
                yield from strings(w)

    texts = list(strings(WORDS))
    for room in ("drawing", "sheets"):
        pkg = importlib.import_module(f"graphplan.{room}")
        for info in pkgutil.iter_modules(pkg.__path__):
            texts += list(strings(getattr(importlib.import_module(f"graphplan.{room}.{info.name}"), "WORDS", {})))
    texts += [short_note({"precision_mm": 0.5}, lang) for lang in ("uk", "en")]
    assert len(texts) > 500
    missing = {c for t in texts for c in lettering(t) if ord(c) >= 32 and ord(c) not in have}
    assert not missing, sorted(missing)
