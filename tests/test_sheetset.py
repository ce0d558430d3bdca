"""Issue 32, items 5–8: a scene's sheets numbered as one project (designation, "Аркуш N / Аркушів M",
form 2a on the later sheets of a set, the scale box, «Змн.»); SVG lettering placed letter by letter
by the packaged font's own advances (read here from the TTF); no raw markup on any sheet kind; the
motor catalogue's 1000 and 750 rpm lines under seed 003's rule; assembly errors in the scene's
language; the dynamics table's graphical columns that check by subtraction."""
from __future__ import annotations

import math
import re
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

from conftest import ROOT, composed, example_sheet
from coursework_scenes import crank_slider, shaper
from graphplan.exact.positions import study
from graphplan.model.scene import load, loads
from graphplan.sheets.compose import SheetOptions
from graphplan.sheets.form import BLOCK_2A_H, form, title_block_box
from graphplan.sheets.sheet import BUILDERS, designation

EXAMPLES = ROOT / "examples"


def _texts(page) -> list[str]:
    return [p.text for p in page.record.items if p.kind == "text"]


def _block(page) -> list:
    """The title block's primitives of a page."""
    return [p for p in page.record.items if p.step == "title block"]


@pytest.fixture(scope="module")
def shaper_a1():
    """The shaper's three A1 sheets as numbered in its project, shared with the other modules that
    read them (``conftest.example_sheet``)."""
    return {k: example_sheet("shaper", k) for k in ("kinematics", "forces", "dynamics")}


def test_a_scenes_sheets_are_numbered_as_one_project(shaper_a1):
    """The shaper has loads, a [[force]] and [dynamics]: three documents, sheets 1, 2, 3 of 3, the
    designation's last group the document's number; the scale box filled on every sheet."""
    for n, kind in enumerate(("kinematics", "forces", "dynamics"), 1):
        sheet = shaper_a1[kind]
        texts = _texts(sheet)
        assert f"Аркуш {n}" in texts and "Аркушів 3" in texts, (kind, [t for t in texts if "Арк" in t])
        assert f"ТММ.КП.00.00{n}" in texts and "ТММ.КП.00.000" not in texts
        assert "Змн." in texts and "Зм." not in texts
        x0, y0, x1, y1 = title_block_box(sheet.form)
        scale = [p.text for p in _block(sheet) if p.kind == "text" and 167 <= p.points[0][0] - x0 <= 185
                 and 20 <= p.points[0][1] - y0 <= 35]
        assert scale and scale[0].strip(), (kind, scale)
        if kind != "dynamics":        # a drawing's scale as GOST 2.302 writes it: 1:n or n:1
            assert re.fullmatch(r"\d+(,\d+)?:\d+(,\d+)?", scale[0]), scale


def test_a_scene_without_loads_is_a_project_of_one_sheet():
    sheet = BUILDERS["kinematics"](study(load(EXAMPLES / "four_bar.toml")), form("A1"), SheetOptions())
    texts = _texts(sheet)
    assert "Аркуш 1" in texts and "Аркушів 1" in texts and "ТММ.03.00.001" in texts


def test_a_document_that_flows_onto_a_second_a1_sheet_is_counted_in_the_project(monkeypatch):
    """On A1 a document may take two sheets (stop 47's six-bar: its force analysis). The other
    documents' "Аркушів" count it: with a compressor's (COMPRESSOR_DYN) forces stood in by a
    two-sheet document, its kinematics sheet says 1 of 4 — before stop 47 it said "of 3", A1 being
    taken as one sheet a document without composing it."""
    from graphplan.graphic.record import Record
    from graphplan.sheets import sheet as sheet_mod
    from graphplan.sheets.compose import Sheet
    from review_scenes import COMPRESSOR_DYN
    st = study(loads(COMPRESSOR_DYN))

    def two_sheets(scene, f, options):          # only the count matters to the others' numbers
        return Sheet(f, Record(), more=[Sheet(f, Record())])

    monkeypatch.setattr(sheet_mod, "_PAGES", {})
    monkeypatch.setattr(sheet_mod, "RAW", dict(sheet_mod.RAW, forces=two_sheets))
    monkeypatch.setenv("GRAPHPLAN_CACHE", "off")
    kinds = sheet_mod.kinds_of(st, "kinematics")
    assert kinds == ("kinematics", "forces", "dynamics"), kinds
    kin = BUILDERS["kinematics"](st, form("A1"), SheetOptions(sheet="kinematics"))
    assert {"Аркуш 1", "Аркушів 4"} <= set(_texts(kin))


def test_a_document_the_scene_cannot_make_does_not_refuse_the_others(monkeypatch):
    """A cycle needing more than the largest catalogue motor refuses its dynamics sheet with one line;
    the kinematics sheet, asked alone, is still made (stop 48: it was refused for the dynamics'
    fault, the numbering having composed the dynamics document) and numbered without it: 1 of 2."""
    from graphplan.sheets import sheet as sheet_mod
    from graphplan.util.errors import SceneError
    from review_scenes import COMPRESSOR_DYN
    st = study(loads(COMPRESSOR_DYN))

    def refused(scene, f, options):
        raise SceneError("dynamics: the cycle needs 186 kW, more than the catalogue's largest motor")

    monkeypatch.setattr(sheet_mod, "_PAGES", {})
    monkeypatch.setattr(sheet_mod, "RAW", dict(sheet_mod.RAW, dynamics=refused,
                                               forces=lambda scene, f, options: _one_sheet(f)))
    monkeypatch.setenv("GRAPHPLAN_CACHE", "off")
    kin = BUILDERS["kinematics"](st, form("A1"), SheetOptions(sheet="kinematics"))
    assert {"Аркуш 1", "Аркушів 2"} <= set(_texts(kin))


def _one_sheet(f):
    from graphplan.graphic.record import Record
    from graphplan.sheets.compose import Sheet
    return Sheet(f, Record())


@pytest.mark.slow
def test_the_six_bars_a1_sheets_are_numbered_by_their_real_count():
    """Stop 47's six-bar (LINK47) on A1: its documents' real sheets, counted, are what every title
    block numbers — forces 2 and 3 when it takes two, the total the sum on every first sheet."""
    from review_scenes import LINK47
    st = study(loads(LINK47))
    docs = {k: BUILDERS[k](st, form("A1"), SheetOptions(sheet=k)) for k in ("kinematics", "forces", "dynamics")}
    total = sum(len(d.pages) for d in docs.values())
    first = 1
    for kind, doc in docs.items():
        texts = _texts(doc)
        assert {f"Аркуш {first}", f"Аркушів {total}"} <= set(texts), (kind, [t for t in texts if "Арк" in t])
        for n, page in enumerate(doc.pages[1:], first + 1):
            assert str(n) in {p.text for p in _block(page) if p.kind == "text"}
        first += len(doc.pages)

@pytest.mark.slow
def test_an_a3_set_continues_the_numbering_on_form_2a():
    """On A3 each document is a set: its first sheet carries form 1 (185×55) with "Аркушів" the
    project's total, the later ones form 2a (185×15) with "Арк." and their running number; the
    forces' first sheet comes right after the kinematics' last."""
    st = study(load(EXAMPLES / "shaper.toml"))
    kin = BUILDERS["kinematics"](st, form("A3"), SheetOptions(sheet="kinematics"))
    forces = BUILDERS["forces"](st, form("A3"), SheetOptions(sheet="forces"))
    assert len(kin.pages) > 1
    total = int(next(t for t in _texts(kin) if t.startswith("Аркушів")).split()[1])
    assert total >= len(kin.pages) + len(forces.pages) + 1          # and the dynamics' sheets
    assert f"Аркуш {len(kin.pages) + 1}" in _texts(forces)
    for n, page in enumerate(kin.pages[1:], 2):
        block = _block(page)
        texts = {p.text for p in block if p.kind == "text"}
        assert {"Змн.", "Арк.", "№ докум.", "Підпис", "Дата", str(n), "ТММ.КП.00.001"} <= texts
        assert not any(t.startswith("Аркуш") for t in texts)
        top = max(max(y for _, y in p.points) for p in block)
        assert top == pytest.approx(page.form.frame_box[1] + BLOCK_2A_H)
        x0 = min(min(x for x, _ in p.points) for p in block)
        assert x0 == pytest.approx(page.form.frame_box[2] - 185.0)


@pytest.mark.parametrize("base,kind,expected", [
    ("ТММ.КП.00.000", "kinematics", "ТММ.КП.00.001"), ("ТММ.КП.00.000", "dynamics", "ТММ.КП.00.003"),
    ("ТММ.04.00.000", "cam", "ТММ.04.00.005"), ("КП-7", "forces", "КП-2"), ("ТММ", "gears", "ТММ.4"),
    ("", "kinematics", "")])
def test_the_designation_ends_in_the_documents_number(base, kind, expected):
    assert designation(base, kind) == expected


@pytest.mark.parametrize("base,kind,expected", [
    ("ТММ.КП.08.400", "cam", "ТММ.КП.08.400"), ("ТММ.КП.08.000", "cam", "ТММ.КП.08.000"),
    ("ТММ.КП.08.300", "gears", "ТММ.КП.08.300"), ("ТММ.ЗП.54.000", "gears", "ТММ.ЗП.54.000"),
    ("ТММ", "gears", "ТММ"), ("", "cam", "")])
def test_a_scenes_one_document_keeps_the_number_its_student_gave(base, kind, expected):
    """A cam or gear scene is one document, a project of its own ("Аркуш 1, Аркушів 1"): its
    designation stands as written (review 8: ТММ.КП.08.400 printed as .005; stop 54: GEARS54's
    ТММ.ЗП.54.000 printed as .004 — document 4 of a project without documents 1–3)."""
    assert designation(base, kind, alone=True) == expected


# -- SVG lettering without its font ---------------------------------------------------------------

def test_svg_letters_stand_where_the_fonts_advances_put_them():
    """Every letter of a text carries its own x: the differences are osifont's advance widths
    (read from the TTF's hmtx table here, not from metrics.json) × the em; the text anchored at its
    start, its middle where the record centred it."""
    from fontTools.ttLib import TTFont

    from graphplan.drawing.fonts import font_path
    from graphplan.drawing.svg import render
    from graphplan.graphic.record import Record, em
    font = TTFont(str(font_path()))
    upm, cmap, hmtx = font["head"].unitsPerEm, font.getBestCmap(), font["hmtx"]
    rec = Record()
    text = "Аркушів 14"
    rec.label((100.0, 50.0), text, size=3.5, anchor="middle")
    svg = render(rec, 200.0, 100.0)
    xs = [float(v) for v in re.search(r'<text[^>]*x="([^"]+)"[^>]*>Аркушів 14<', svg).group(1).split()]
    assert 'text-anchor="start"' in svg and len(xs) == len(text)
    adv = [hmtx[cmap[ord(c)]][0] / upm * em(3.5) for c in text]
    assert [b - a for a, b in zip(xs, xs[1:])] == pytest.approx(adv[:-1], abs=2e-3)
    assert xs[0] + sum(adv) / 2 == pytest.approx(100.0, abs=2e-3)


FONTS_CONF = """<?xml version="1.0"?><!DOCTYPE fontconfig SYSTEM "fonts.dtd">
<fontconfig><dir>{dir}</dir><cachedir>{cache}</cachedir>
<include ignore_missing="yes">/etc/fonts/conf.d</include></fontconfig>"""


@pytest.mark.slow
def test_sheets_read_the_same_without_the_font(tmp_path):
    """Rendered as a viewer without osifont renders them (fontconfig told of DejaVu only, the
    packaged fonts not registered): no word of the shaper's kinematics and dynamics sheets is
    overprinted (tests/inkcheck.py)."""
    dejavu = Path("/usr/share/fonts/truetype/dejavu")
    if not dejavu.is_dir():
        pytest.skip("DejaVu fonts not installed")
    conf = tmp_path / "fonts.conf"
    conf.write_text(FONTS_CONF.format(dir=dejavu, cache=tmp_path / "cache"), encoding="utf-8")
    st = study(load(EXAMPLES / "shaper.toml"))
    names = []
    for kind in ("kinematics", "dynamics"):
        path = tmp_path / f"{kind}.svg"
        path.write_text(BUILDERS[kind](st, form("A1"), SheetOptions(sheet=kind)).svg(), encoding="utf-8")
        names.append(str(path))
    code = ("import json, sys\n"
            f"sys.path.insert(0, {str(ROOT / 'tests')!r})\n"
            "from inkcheck import overprinted\n"
            f"print(json.dumps({{n: overprinted(open(n, encoding='utf-8').read()) for n in {names!r}}}))\n")
    import json
    import os
    env = dict(os.environ, FONTCONFIG_FILE=str(conf))
    check = subprocess.run([sys.executable, "-c", "import subprocess; print(subprocess.run(['fc-match', "
                            "'osifont'], capture_output=True, text=True).stdout)"], capture_output=True, text=True,
                           env=env)
    assert "osifont" not in check.stdout.lower()       # the font is really absent
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, check=True)
    assert {n: w for n, w in json.loads(done.stdout).items() if w} == {}


# -- no raw markup in any lettering -----------------------------------------------------------------

RAW = re.compile(r"[_^{}]")


def lettering_of(svg: str) -> list[str]:
    """What a viewer letters: each <text>'s characters, its spans joined (the embedded font's CSS
    left out)."""
    body = re.sub(r"<style.*?</style>", "", svg, flags=re.S)
    return [re.sub(r"<[^>]+>", "", m.group(1)) for m in re.finditer(r"<text\b[^>]*>(.*?)</text>", body, re.S)]


def _sheets_of(text: str | Path, kind: str, lang: str):
    """The sheet composed alone (``conftest.composed``: the markup tests read its lettering, not the
    project's numbering, which would compose the scene's other documents to count them). An example's
    cam is a project of its own (numbered 1 of 1, nothing else composed): the gallery's shared sheet
    (``conftest.example_sheet``), not composed a second time (3.7 s of CPU)."""
    if kind == "cam" and isinstance(text, Path) and text.parent == EXAMPLES:
        return example_sheet(text.stem, kind, "A1", lang)
    if kind == "cam":
        from graphplan.model.cam import load as load_cam
        scene = load_cam(text)
    else:
        scene = study(load(text) if isinstance(text, Path) else loads(text, "<generated>"))
    return composed(kind, scene, form("A1"), SheetOptions(sheet=kind, lang=lang))


@pytest.mark.parametrize("kind", ["kinematics", "forces", "dynamics"])
def test_no_lettering_of_the_shapers_sheets_carries_raw_markup(shaper_a1, kind):
    """No _, ^, { or } reaches the paper: every symbol is typeset."""
    assert [t for page in shaper_a1[kind].pages for t in lettering_of(page.svg()) if RAW.search(t)] == []


GENERATED = {"crank-slider": crank_slider(0.08, 4.0, 0.2, 600.0, 60.0, 2500.0, 12.0),
             "shaper": shaper(1.6, 0.4, 0.5, 0.8, 0.6, 90.0, 50.0, 3000.0, 30.0)}


@pytest.mark.parametrize("scene,kind,lang", [
    ("crank-slider", "forces", "uk"),
    (EXAMPLES / "cam_translating.toml", "cam", "uk"),
    pytest.param(EXAMPLES / "slotter.toml", "forces", "en", marks=pytest.mark.slow),
    pytest.param(EXAMPLES / "four_bar.toml", "kinematics", "en", marks=pytest.mark.slow),
    pytest.param("shaper", "dynamics", "en", marks=pytest.mark.slow),
    pytest.param("shaper", "kinematics", "en", marks=pytest.mark.slow)],
    ids=lambda v: v.name if isinstance(v, Path) else str(v))     # (a path's name: ids the same in every checkout)
def test_no_lettering_carries_raw_markup(scene, kind, lang):
    """… on the examples' sheets and on sheets of mechanisms nobody drew (tests/coursework_scenes.py)."""
    sheet = _sheets_of(GENERATED.get(scene, scene), kind, lang)
    leaks = [t for page in sheet.pages for t in lettering_of(page.svg()) if RAW.search(t)]
    assert leaks == []


@pytest.mark.slow
@pytest.mark.parametrize("lang", ["uk", "en"])
@pytest.mark.parametrize("kind", ["kinematics", "forces", "dynamics"])
def test_no_raw_markup_on_generated_mechanisms(kind, lang):
    from hypothesis import HealthCheck, assume, given, settings
    from hypothesis import strategies as st_

    from graphplan.util.errors import GraphplanError

    @settings(max_examples=4, deadline=None, suppress_health_check=list(HealthCheck))
    @given(st_.floats(0.03, 0.2), st_.floats(2.8, 6.0), st_.floats(-0.4, 0.4), st_.floats(60.0, 1500.0))
    def check(r, ratio, offset, rpm):
        try:
            sheet = _sheets_of(crank_slider(r, ratio, offset, rpm, 60.0, 2000.0, 10.0), kind, lang)
        except GraphplanError:
            assume(False)
        assert [t for page in sheet.pages for t in lettering_of(page.svg()) if RAW.search(t)] == []
    check()


# -- the dynamics table ---------------------------------------------------------------------------------

def test_the_dynamics_tables_graphical_columns_check_by_subtraction(shaper_a1):
    """Table 1's graphical columns, labelled "гр.": A_д − A_с = ΔT in every row to the last printed
    digit (the work diagram's two ordinates read and subtracted)."""
    rec = shaper_a1["dynamics"].record
    texts = [p for p in rec.items if p.kind == "text"]
    heads = {p.text: p.points[0][0] for p in texts if p.text in ("A_с гр., Дж", "A_д гр., Дж", "ΔT гр., Дж")}
    assert len(heads) == 3
    top = min(p.points[0][1] for p in texts if p.text in heads)     # y up: a diagram's division numbers stand above

    def value(t: str) -> float:
        return float(t.replace("−", "-").replace(",", "."))
    rows: dict[float, dict[str, float]] = {}
    for p in texts:
        if re.fullmatch(r"−?[\d,]+", p.text) and p.points[0][1] < top:     # the rows under the head
            for name, x in heads.items():
                if abs(p.points[0][0] - x) < 19.0 and p.points[0][0] > x:       # right-aligned in its cell
                    rows.setdefault(round(p.points[0][1], 1), {})[name] = value(p.text)
    full = [r for r in rows.values() if len(r) == 3]
    assert len(full) >= 12
    for r in full:
        a_c, a_d, dt = r["A_с гр., Дж"], r["A_д гр., Дж"], r["ΔT гр., Дж"]
        assert a_d - a_c == pytest.approx(dt, abs=0.51 * 10 ** (math.floor(math.log10(max(abs(a_d), 1))) - 3) * 2
                                          + 0.51 * 10 ** (math.floor(math.log10(max(abs(dt), 1))) - 3)), r


def test_the_flywheel_formula_is_typeset(shaper_a1):
    from graphplan.util.markup import runs
    notes = [p.text for p in shaper_a1["dynamics"].record.items if p.kind == "text" and "|kl|/" in p.text]
    assert notes
    pieces = [(r.text, r.level) for r in runs(notes[0])]
    assert ("m", -1) in pieces and ("2", 1) in pieces and not any("δ" in t and level for t, level in pieces)


# -- the motor catalogue ------------------------------------------------------------------------------

def _catalogue() -> list[dict]:
    path = ROOT / "graphplan" / "data" / "motors.toml"
    return tomllib.loads(path.read_text(encoding="utf-8"))["motor"]


def test_each_motor_runs_at_its_poles_synchronous_speed():
    """A 4А name ends in its number of poles 2p: n_c = 60·50/p (3000, 1500, 1000, 750 rpm); the
    rated speed lies a slip of 1–12 % below it (the 4АА63А6: 11,5 %); within a line, more power on a larger
    rotor."""
    lines: dict[float, list[dict]] = {}
    for m in _catalogue():
        poles = int(m["name"][-1])
        assert m["rpm_sync"] == 6000 / poles, m["name"]
        assert 0.01 <= 1 - m["rpm_rated"] / m["rpm_sync"] <= 0.12, m["name"]
        lines.setdefault(m["rpm_sync"], []).append(m)
    assert set(lines) == {3000, 1500, 1000, 750}
    for line in lines.values():
        line.sort(key=lambda m: m["power_kW"])
        assert all(a["inertia"] <= b["inertia"] for a, b in zip(line, line[1:]))


# the 750 rpm line: slow (the same rule on another line of the catalogue, the slotter's dynamics again: 5 s)
@pytest.mark.parametrize("sync", [1000, pytest.param(750, marks=pytest.mark.slow)])
def test_a_scene_asking_1000_or_750_rpm_gets_the_next_size_up(tmp_path, capsys, sync):
    """Seed 003's rule on the new lines: the smallest motor of the line whose power is at least
    P = max M*_c·ω1/η (found here by scanning the catalogue file)."""
    import json
    text = (EXAMPLES / "slotter.toml").read_text(encoding="utf-8")
    text = re.sub(r'(?m)^motor = .*$', "", text)
    text = text.replace("[dynamics]", f"[dynamics]\nsynchronous_rpm = {sync}", 1)
    path = tmp_path / "s.toml"
    path.write_text(text, encoding="utf-8")
    from graphplan.cli.main import main
    assert main(["dynamics", str(path), "--json"]) == 0
    motor = json.loads(capsys.readouterr().out)["motor"]
    line = sorted((m for m in _catalogue() if m["rpm_sync"] == sync), key=lambda m: m["power_kW"])
    expected = next(m for m in line if m["power_kW"] >= motor["power_needed_kW"])
    assert motor["name"] == expected["name"] and motor["rpm_sync"] == sync


# -- assembly errors in the scene's language ---------------------------------------------------------

BAD = """{lang}[frame.points]
O = [0, 0]
C = [0.1, 0]
[crank]
pivot = "O"
pin = "A"
length = 0.2
omega = 10
[[link]]
joints = ["A", "B"]
length = 0.05
[[link]]
joints = ["B", "C"]
length = 0.05
"""


@pytest.mark.parametrize("lang,option,words", [
    ("", [], "не складається за жодного кута кривошипа"), ('lang = "en"\n', [], "cannot be assembled at any"),
    ("", ["--lang", "en"], "cannot be assembled at any"), ('lang = "en"\n', ["--lang", "uk"], "не складається")])
def test_an_assembly_error_speaks_the_scenes_language(tmp_path, capsys, lang, option, words):
    """A four-bar whose links (0.05 + 0.05 m) cannot reach across 0.1 m from a 0.2 m crank: refused
    with one line, in the scene's language unless --lang says otherwise."""
    path = tmp_path / "bad.toml"
    path.write_text(BAD.format(lang=lang), encoding="utf-8")
    from graphplan.cli.main import main
    assert main(["analyze", str(path), *option]) == 2
    lines = capsys.readouterr().err.strip().splitlines()
    assert len(lines) == 1 and words in lines[0] and str(path) in lines[0]


@pytest.mark.slow
def test_a_gear_scenes_sheet_carries_its_designation_as_written():
    """The gallery's gear sheet (examples/gears.toml, "ТММ.03.00.000"), numbered as BUILDERS numbers
    it: its title block prints the scene's designation unchanged, sheet 1 of 1 (stop 54's GEARS54
    printed ТММ.ЗП.54.000 as .004)."""
    from conftest import example_sheet
    sheet = example_sheet("gears", "gears", "A1", "uk")
    texts = _texts(sheet)
    assert "ТММ.03.00.000" in texts and "ТММ.03.00.004" not in texts
    assert "Аркуш 1" in texts and "Аркушів 1" in texts
