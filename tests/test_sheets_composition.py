"""Sheets a teacher accepts: composed by construction — every drawing in its own box, the velocity
plans in position order, no lettering on a line or on lettering (read off the records, and counted
on the rendered sheets as a reader's eye sees it) —, every format drawn (a set of sheets where one
does not hold it), one set of numbers shared with the terminal, no e-notation, the force sheet's
contents and its refusal without loads."""
from __future__ import annotations

import json
import math
import re
import subprocess
import sys

import numpy as np
import pytest

from conftest import EXAMPLES, ROOT, example, example_sheet
from graphplan.cli.gallery import available, file_names
from graphplan.cli.main import main
from graphplan.sheets.compose import SheetOptions, defects
from graphplan.sheets.form import form
from graphplan.sheets.sheet import BUILDERS

E_NOTATION = re.compile(r"\d[eE][+-]?\d")
LOADED = ["shaper", "slotter"]          # the examples with masses and forces


def gallery_files() -> list[str]:
    out = []
    for scene, kind, lang, name, fmt in available():
        stem = name[:-4]
        n = 1 + sum(1 for p in (ROOT / "drawings").glob(f"{stem}-*.svg") if p.stem[len(stem) + 1:].isdigit())
        out += file_names(name, n)
    return out


FALLBACK_ONLY = """<?xml version="1.0"?><!DOCTYPE fontconfig SYSTEM "fonts.dtd">
<fontconfig><dir>{folder}</dir><cachedir>{cache}</cachedir>
<include ignore_missing="yes">/etc/fonts/conf.d</include></fontconfig>"""


def ink_overprints(names: list[str], font: bool = True, tmp=None) -> dict[str, list]:
    """Each committed gallery sheet's overprinted words (tests/inkcheck.py), rendered in a fresh
    process with the packaged fonts registered before cairo draws anything — or, ``font=False``,
    as a viewer without them does: a fontconfig that knows only the fallback family's folder
    (DejaVu Sans, the sheets' font-family's second name), nothing registered."""
    code = ("import json, sys\n"
            f"sys.path.insert(0, {str(ROOT / 'tests')!r})\n"
            + ("from graphplan.drawing.fonts import register\nregister()\n" if font else "")
            + "from inkcheck import overprinted\n"
            f"names = {names!r}\n"
            f"print(json.dumps({{n: overprinted(open({str(ROOT / 'drawings')!r} + '/' + n, encoding='utf-8').read())"
            " for n in names}))\n")
    env = None
    if not font:
        import os
        from pathlib import Path

        from graphplan.graphic.record import fallback_font
        file = fallback_font()
        if file is None:
            pytest.skip("the fallback font (DejaVu Sans) is not installed")
        conf = Path(tmp) / "fonts.conf"
        conf.write_text(FALLBACK_ONLY.format(folder=Path(file).parent, cache=Path(tmp) / "cache"), encoding="utf-8")
        env = dict(os.environ, FONTCONFIG_FILE=str(conf))
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, check=True, env=env)
    return json.loads(done.stdout)


def gallery_chunks(size: int = 5) -> list:
    """The gallery's sheets in groups, each group rendered in one fresh process (a process a sheet
    spent more time starting than counting): the A1 sheets in the default run, the smaller formats'
    sets (A2, A3: the same drawings carried over more sheets) in the slow one."""
    names = gallery_files()
    sets = [n for n in names if re.search(r"_a[23]", n)]
    first = [n for n in names if n not in sets]
    return ([names_ for names_ in (first[k:k + size] for k in range(0, len(first), size))]
            + [pytest.param(sets[k:k + size], marks=pytest.mark.slow) for k in range(0, len(sets), size)])


@pytest.mark.parametrize("names", gallery_chunks(), ids=lambda names: names[0])
def test_no_word_on_a_gallery_sheet_is_overprinted(names):
    """Counted on the rendered sheet, as a reader's eye (and ../shared/tools/overprint.py) does."""
    found = ink_overprints(names)
    assert {n: words for n, words in found.items() if words} == {}


WITHOUT_FONT = ["shaper_forces.svg", "lab_crank_slider_a3-2.svg", "slotter_dynamics.svg", "cam_translating.svg"]


@pytest.mark.parametrize("names", [WITHOUT_FONT] + [
    pytest.param(chunk, marks=pytest.mark.slow)
    for chunk in (lambda rest: [rest[k:k + 6] for k in range(0, len(rest), 6)])(
        [n for n in gallery_files() if n not in WITHOUT_FONT])], ids=lambda names: names[0])
def test_no_word_is_overprinted_without_the_font(names, tmp_path):
    """The same count where a viewer letters the sheet with the fallback font (Inkscape, rsvg,
    cairosvg and ImageMagick ignore the embedded @font-face): every letter stands where our font
    put it, and nothing was laid out within either font's glyph box — in the default run the
    sheets with the most lettering of each kind (a force sheet, an A3 set's crowded page, a
    dynamics sheet, a cam sheet), the whole gallery in the slow one."""
    found = ink_overprints(names, font=False, tmp=tmp_path)
    assert {n: words for n, words in found.items() if words} == {}


def test_the_fallback_check_sees_a_caption_set_as_one_piece(tmp_path):
    """Not vacuous: the A3 set's lettering set in one piece each, centred (as a viewer sets it
    without the font when the SVG gives one x, as the sheets did before), runs into lines."""
    name = "lab_crank_slider_a3-2.svg"
    svg = (ROOT / "drawings" / name).read_text(encoding="utf-8")

    def centred(m: re.Match) -> str:
        xs = [float(v) for v in m.group(2).split()]
        return f'{m.group(1)}text-anchor="middle" x="{(xs[0] + xs[-1]) / 2:.3f}"'
    one = re.sub(r'(<text [^>]*?)text-anchor="start" x="([\d.]+(?: [\d.]+)+)"', centred, svg)
    assert one != svg
    (tmp_path / "one").mkdir()
    code = ("import sys\n"
            f"sys.path.insert(0, {str(ROOT / 'tests')!r})\n"
            "from inkcheck import overprinted\n"
            "print(len(overprinted(sys.stdin.read())))\n")
    from graphplan.graphic.record import fallback_font
    if fallback_font() is None:
        pytest.skip("the fallback font (DejaVu Sans) is not installed")
    import os
    from pathlib import Path
    conf = tmp_path / "fonts.conf"
    conf.write_text(FALLBACK_ONLY.format(folder=Path(fallback_font()).parent, cache=tmp_path / "cache"), encoding="utf-8")
    env = dict(os.environ, FONTCONFIG_FILE=str(conf))
    run = lambda text: int(subprocess.run([sys.executable, "-c", code], input=text, capture_output=True, text=True,
                                          cwd=ROOT, check=True, env=env).stdout)
    assert run(svg) == 0
    assert run(one) > 0


@pytest.mark.parametrize("scene,kind,lang,name,fmt", available())
def test_gallery_sets_are_composed_cleanly(scene, kind, lang, name, fmt):
    """Each gallery set as built: no defect a teacher would send back (sheets.compose.defects)."""
    sheet = example_sheet(scene, kind, fmt, lang)
    assert defects(sheet) == []


def test_the_checks_find_what_they_look_for():
    """The record checks are not vacuous: velocity plans swapped, a label moved onto a line and two
    drawings moved together are each reported."""
    from dataclasses import replace

    from graphplan.drawing.layout import Placed
    sheet = _build("crank_slider", "kinematics", "A1")
    assert defects(sheet) == []
    plans = [p for p in sheet.placed if p.name.startswith("velocity plan ")]
    a, b = plans[0], plans[1]
    swapped = replace(sheet, placed=[replace(p, name=b.name) if p is a else replace(p, name=a.name) if p is b else p
                                     for p in sheet.placed], more=[])
    assert any("velocity plans read" in d for d in defects(swapped))
    line = next(p for p in sheet.record.items if p.kind == "segment" and p.layer == "mechanism")
    crossed = replace(sheet, record=replace(sheet.record, items=sheet.record.items + [
        replace(next(p for p in sheet.record.items if p.kind == "text" and p.layer == "labels"),
                points=(line.points[0],))]), more=[])
    assert any("line" in d for d in defects(crossed))
    moved = [Placed(p.name, p.record, plans[0].box if p is plans[1] else p.box) for p in sheet.placed]
    assert any("meet" in d for d in defects(replace(sheet, placed=moved, more=[])))


def test_lettering_is_at_least_2_5_mm():
    """GOST 2.304: no lettering on a sheet lower than 2.5 mm (the capitals' height)."""
    for name, kind in (("shaper", "kinematics"), ("shaper", "forces"), ("slotter", "dynamics")):
        sheet = _build(name, kind, "A1")
        sizes = {p.size for page in sheet.pages for p in page.record.items if p.kind == "text" and p.text.strip()
                 and p.text != "Змн."}
        assert min(sizes) >= 2.5, (name, kind, sorted(sizes))
        # seed 000's «Змн.» in the form's 7 mm column: 2 mm (osifont's 2.5 mm ink leaves 0.3 mm to the rules)
        small = {p.size for page in sheet.pages for p in page.record.items if p.text == "Змн."}
        assert small and min(small) >= 2.0


def _texts(sheet) -> list[str]:
    return [p.text for page in sheet.pages for p in page.record.items if p.kind == "text"]


def _build(name, kind, fmt):
    """The example's sheet, shared with the other modules that read it (``conftest.example_sheet``)."""
    return example_sheet(name, kind, fmt)


def _check_set(sheet, fmt):
    pages = sheet.pages
    first = int(pages[0].fields["sheet"])       # the set's place in its scene's project (test_sheetset)
    for n, page in enumerate(pages):
        texts = [p.text for p in page.record.items if p.kind == "text"]
        if n == 0:                              # form 1: "Аркуш k", "Аркушів M" of the project
            assert f"Аркуш {first}" in texts and any(t.startswith("Аркушів ") for t in texts)
        else:                                   # form 2a: "Арк." and the running number
            assert "Арк." in texts and str(first + n) in texts and not any(t.startswith("Аркуш") for t in texts)
        assert page.form.name == fmt and page.placed
        assert not [t for t in texts if E_NOTATION.search(t)]


QUICK = [("shaper", "kinematics", "A3"), ("slotter", "forces", "A3"), ("four_bar", "kinematics", "A2")]
MATRIX = [(n, k, f) for n in EXAMPLES for k in ("kinematics", "forces") for f in ("A1", "A2", "A3")
          if k == "kinematics" or n in LOADED]


@pytest.mark.parametrize("name,kind,fmt", QUICK)
def test_every_format_draws_quick(name, kind, fmt):
    _check_set(_build(name, kind, fmt), fmt)


@pytest.mark.slow
@pytest.mark.parametrize("name,kind,fmt", [m for m in MATRIX if m not in QUICK])
def test_every_format_draws(name, kind, fmt):
    _check_set(_build(name, kind, fmt), fmt)


def test_a1_is_one_sheet_and_a3_a_set(tmp_path):
    """The default stays one A1 sheet; a smaller format carries on to x-2.svg, x-3.svg …"""
    assert len(_build("shaper", "kinematics", "A1").pages) == 1
    a3 = _build("shaper", "kinematics", "A3")
    assert len(a3.pages) >= 2
    a3.write(tmp_path / "x.svg")
    names = sorted(p.name for p in tmp_path.iterdir())
    assert names == sorted(["x.svg"] + [f"x-{n}.svg" for n in range(2, len(a3.pages) + 1)])


def test_cli_sheet_set_and_force_refusal(tmp_path, capsys):
    assert main(["sheet", str(ROOT / "examples/lab_crank_slider.toml"), "--format", "A3",
                 "-o", str(tmp_path / "lab.svg")]) == 0
    assert (tmp_path / "lab.svg").exists() and (tmp_path / "lab-2.svg").exists()
    capsys.readouterr()
    assert main(["sheet", str(ROOT / "examples/four_bar.toml"), "--sheet", "forces",
                 "-o", str(tmp_path / "f.svg")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "[loads]" in err[0] and "[[force]]" in err[0] and "four_bar.toml" in err[0]
    assert not (tmp_path / "f.svg").exists()


def test_force_sheet_has_the_force_positions_plan_and_inertia_loads():
    st = example("shaper")
    sheet = _build("shaper", "forces", "A1")
    texts = " ".join(_texts(sheet))
    assert "План прискорень, положення силового розрахунку" in texts
    assert "Маси, моменти інерції, сили та моменти сил інерції" in texts
    assert "Діаграма сили корисного опору за хід" in texts
    from graphplan.exact.kinetostatics import analyse, at_scene_angle
    ks = analyse(st, [at_scene_angle(st)])
    inertia = next(ld for ld in ks.loads if ld.name == "Φ5")      # the ram: Φ5 = m·a_C
    table = next(p.record for p in sheet.placed if p.name == "inertia table")
    cells = [p.text for p in table.items if p.kind == "text"]
    exact = float(abs(inertia.force[0]))
    assert any(abs(value(c) - exact) <= 0.02 * exact
               for c in cells if re.fullmatch(r"−?[\d,.]+", c)), (exact, cells)


def value(text: str) -> float:
    """A number as the Ukrainian sheet writes it (decimal comma, true minus)."""
    return float(text.replace("−", "-").replace(",", "."))


def _notes_value(texts: list[str], key: str) -> float:
    line = next(t for t in texts if t.startswith(key))
    return value(re.search(rf"{key} = ([\d.,]+)", line).group(1))


def test_terminal_plans_print_what_the_sheet_draws(capsys):
    """`plans --json` (default --format A1) and the A1 sheet: the same scales, the same readings."""
    assert main(["plans", str(ROOT / "examples/shaper.toml"), "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    sheet = _build("shaper", "kinematics", "A1")
    notes = next(p.record for p in sheet.placed if p.name == "notes")
    line = " ".join(p.text for p in sorted((p for p in notes.items if p.kind == "text"), key=lambda p: -p.points[0][1]))
    mu = {k: value(re.search(rf"{s} = ([\d.,]+)", line).group(1))
          for k, s in (("mu_l", "μ_l"), ("mu_v", "μ_v"), ("mu_a", "μ_a"))}
    assert mu["mu_l"] == doc["mu_l"] and mu["mu_v"] == doc["positions"][0]["mu_v"]
    assert mu["mu_a"] == next(p["mu_a"] for p in doc["positions"] if "mu_a" in p)
    table = next(p.record for p in sheet.placed if p.name == "velocity table")
    cells = {p.text for p in table.items if p.kind == "text"}
    for pos in doc["positions"]:
        for key in ("A", "C", "B"):
            e = pos["velocity"][key]
            if e["mm"] >= 0.5:
                assert printed(e["value"], cells), (pos["index"], key, e)


def test_terminal_diagrams_use_the_sheets_L(capsys):
    from graphplan.sheets.kinematics import sheet_scales
    st = example("lab_crank_slider")
    assert main(["diagrams", str(ROOT / "examples/lab_crank_slider.toml"), "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    drawn = sheet_scales(st, "A1")
    assert doc["L_mm"] == pytest.approx(drawn["L"]) and doc["H1_mm"] == pytest.approx(drawn["H1"])


def _right_column(rec) -> list[float]:
    """The right-most cell of every body row of a ruled table (its δ column)."""
    rows: dict[float, list] = {}
    for p in rec.items:
        if p.kind == "text" and p.layer == "tables":
            rows.setdefault(round(p.points[0][1], 1), []).append(p)
    out = []
    for y, cells in sorted(rows.items(), reverse=True)[1:]:
        last = max(cells, key=lambda p: p.points[0][0])
        text = last.text.rstrip("*").replace("−", "-").replace(",", ".")     # * marks an error over 5 %
        if re.fullmatch(r"-?\d+(\.\d+)?", text):
            out.append(abs(float(text)))
    return out


@pytest.mark.parametrize("name", ["shaper", "slotter", "crank_slider"])
def test_notes_largest_error_is_the_tables(name):
    sheet = _build(name, "kinematics", "A1")
    errs = []
    for p in sheet.placed:
        if p.name == "velocity table" or p.name.startswith("acceleration table"):
            errs += _right_column(p.record)
    notes = next(p.record for p in sheet.placed if p.name == "notes")
    line = " ".join(p.text for p in sorted((p for p in notes.items if p.kind == "text"), key=lambda p: -p.points[0][1]))
    assert value(re.search(r": ([\d.,]+) %", line).group(1)) == pytest.approx(max(errs), abs=0.006)


def test_velocity_table_has_no_repeated_or_zero_columns():
    """The slotter's block turns with its rocker (ω2 = ωOB) and S3 sits on a fixed pivot: one column
    each of what differs, none that is zero throughout."""
    sheet = _build("slotter", "kinematics", "A1")
    table = next(p.record for p in sheet.placed if p.name == "velocity table")
    edges = sorted({round(p.points[0][0], 3) for p in table.items
                    if p.kind == "segment" and abs(p.points[0][0] - p.points[1][0]) < 1e-9})
    top = max(p.points[0][1] for p in table.items if p.kind == "segment")
    texts = [p for p in table.items if p.kind == "text" and p.bounds()[3] < top]
    header_y = max(p.points[0][1] for p in texts)
    cols: dict[int, list[str]] = {}
    for p in sorted(texts, key=lambda p: -p.points[0][1]):
        if p.points[0][1] >= header_y - 1e-9:
            continue
        x = (p.bounds()[0] + p.bounds()[2]) / 2
        cols.setdefault(next(i for i in range(len(edges) - 1) if edges[i] <= x <= edges[i + 1]), []).append(p.text)
    body = [tuple(c) for c in cols.values()]
    assert len(body) > 4 and len(body) == len(set(body))
    assert not [c for c in body if all(v in ("0", "—") for v in c)]


TITLE_NO = re.compile(r"^(?:Таблиця|Table) (\d+(?:\.\d+)?)\. ")


def table_numbers(sheet) -> list[str]:
    """The numbers of the sheet's (or set's) table titles in reading order, sheet by sheet: on one
    sheet the tables' column is read column by column (a title more than 20 mm to the right of
    another starts a new column), top to bottom; on a set's sheets, by their boxes (tests/reading.py:
    a table left of another in a band of height they share, or above it in a strip of width they
    share, is read first; of two sharing neither, either may be): the numbers as numbered where
    that is a reading order, else one that shows where it is not (stop 61: the tops sorted
    row-wise read a drawing over Table 1 beside Tables 2, 3 down the next column as 2, 1, 3 — a
    reader down the columns reads 1, 2, 3, and the test had read the stacked line as rows)."""
    from reading import in_reading_order
    out = []
    for page in sheet.pages:
        titles = [(p.bounds()[0], -p.bounds()[3], TITLE_NO.match(p.text).group(1))
                  for p in page.record.items if p.kind == "text" and TITLE_NO.match(p.text)]
        if sheet.more or len(sheet.pages) > 1:
            titles.sort(key=lambda t: tuple(int(v) for v in t[2].split(".")))
            boxes = [next(pl.box for pl in page.placed if pl.box[0] - 1 <= t[0] <= pl.box[2] + 1
                          and pl.box[1] - 1 <= -t[1] <= pl.box[3] + 1) for t in titles]
            out += [titles[k][2] for k in in_reading_order(boxes)]
            continue
        titles.sort()

        def box_of(t):
            return next((pl.box for pl in page.placed if pl.box[0] - 1 <= t[0] <= pl.box[2] + 1
                         and pl.box[1] - 1 <= -t[1] <= pl.box[3] + 1), None)
        # a table across under the columns (the last, wide one): its box runs past a column to its
        # right that stands above it — read after the columns
        across = [t for t in titles if (b := box_of(t)) is not None
                  and any(u[0] - t[0] >= 20.0 and u[0] < b[2] - 1 and -u[1] > b[3] for u in titles)]
        columns: list[list[tuple]] = []
        for t in titles:
            if t in across:
                continue
            if columns and t[0] - columns[-1][0][0] < 20.0:
                columns[-1].append(t)
            else:
                columns.append([t])
        out += [n for col in columns for _, _, n in sorted(col, key=lambda t: t[1])]
        out += [n for _, _, n in sorted(across, key=lambda t: t[1])]
    return out


def test_acceleration_tables_are_numbered():
    """Three acceleration plans: the tables are numbered 1, 2, 3 … in reading order (no "2.1"
    beside "3"), in both languages; the notes cite the plans' tables by those numbers."""
    st = example("crank_slider")
    for lang in ("uk", "en"):
        sheet = BUILDERS["kinematics"](st, form("A1"), SheetOptions(accel=["#1", "#4", "#7"], lang=lang))
        numbers = table_numbers(sheet)
        assert numbers == [str(k) for k in range(1, len(numbers) + 1)], numbers
        assert len(numbers) >= 5
        texts = " ".join(_texts(sheet))
        assert ("таблицях 1–4" if lang == "uk" else "tables 1–4") in texts
        assert not E_NOTATION.search(texts)


@pytest.mark.parametrize("name", ["crank_slider", "four_bar", "shaper", "slotter", "lab_crank_slider"])
@pytest.mark.parametrize("fmt", ["A1", "A3"])
def test_kinematics_tables_numbered_in_reading_order(name, fmt):
    """Every example's kinematics sheet (and an A3 set) numbers its tables 1, 2, 3 … as it is read."""
    numbers = table_numbers(_build(name, "kinematics", fmt))
    assert numbers == [str(k) for k in range(1, len(numbers) + 1)] and len(numbers) >= 3, numbers


MU_VALUE = re.compile(r"μ_\{?([^\s=}]+)\}?\s*=\s*(?:[^=;]*=\s*)?(-?\d[\d.,]*)")


def mu_values(sheet) -> dict[str, set[str]]:
    """Every scale symbol μ_x the sheet's lettering gives a value, with its values (a formula
    "μ_V = μ_S/(μ_t·H_1) = 0,1" gives μ_V its last value)."""
    out: dict[str, set[str]] = {}
    for text in _texts(sheet):
        for part in re.split(r";|,\s{2}", text):
            m = MU_VALUE.search(part)
            if m:
                out.setdefault(m.group(1), set()).add(m.group(2).rstrip(".,"))
    return out


@pytest.mark.parametrize("name", ["crank_slider", "four_bar", "shaper"])
def test_one_scale_symbol_one_value(name):
    """The plans' μ_v, μ_a and the diagrams' μ_V, μ_A (μ_ω, μ_ε) are named apart: no μ symbol on a
    kinematics sheet carries two values, in either language; the diagrams' velocity scale is on it."""
    for lang in ("uk", "en"):
        sheet = example_sheet(name, "kinematics", "A1", lang)
        mus = mu_values(sheet)
        assert {"l", "v", "a", "t"} <= set(mus), mus
        assert len(set(mus) - {"l", "v", "a", "t"}) >= 3, mus      # the diagrams' own s, v, a scales
        assert all(len(v) == 1 for v in mus.values()), mus


def test_title_block_scale_is_the_drawings():
    sheet = _build("shaper", "kinematics", "A1")
    tb = [p.text for p in sheet.record.items if p.kind == "text" and p.layer == "frame"]
    assert [t for t in tb if re.fullmatch(r"1:[\d.,]+|[\d.,]+:1", t)]
    assert not [t for t in tb if t.startswith("μl")]


@pytest.mark.parametrize("name", gallery_files())
def test_no_e_notation_on_gallery_sheets(name):
    texts = re.findall(r">([^<]*)</text>", (ROOT / "drawings" / name).read_text(encoding="utf-8"))
    assert texts and not [t for t in texts if E_NOTATION.search(t)]


@pytest.mark.parametrize("name", LOADED)
def test_slider_reaction_chart_plots_the_exact_reaction(name):
    """Seed 003's fig. 5a: the frame's reaction on the slider over the turn. A sliding pair's reaction
    is normal to its guide, so the signed value keeps the whole force (|N| = |R|); each position's
    ordinate is drawn N/μ_R long."""
    from graphplan.drawing import charts
    st = example(name)
    t = charts.turn(st)
    keys = charts.slider_reactions(t)
    assert keys == ["R05"]
    n = charts.normal_component(t, "R05")
    assert np.allclose(np.abs(n), np.abs(t.ks.reactions["R05"].force), rtol=1e-12, atol=1e-9)
    rec = charts.reaction_record(t, "R05", 240.0, 90.0)
    mu, mu_phi = rec.scales["mu_R"], rec.scales["mu_phi"]
    ordinates = {round(p.points[0][0], 6): p.points[1][1] for p in rec.items
                 if p.kind == "segment" and p.role == "grid" and p.step == rec.title}
    for k, _pos in t.position_index():
        x = round(float(t.turn_deg[k] / mu_phi), 6)
        if abs(n[k] / mu) > 1.5:
            assert ordinates[x] == pytest.approx(n[k] / mu, abs=1e-9)
    assert max(abs(v) for v in ordinates.values()) <= 90.0 + 1e-9


def test_force_sheet_draws_the_mechanism_with_every_load():
    """The scheme the groups are taken from: every nonzero weight, inertia force and resistance of the
    exact analysis drawn once — a weight and the resistance along their exact direction, an inertia
    force Φ against a_S as the acceleration plan draws it (the force plans' Φ, review 10 #14) — and
    the balancing moment on the crank."""
    from graphplan.drawing.forces import mechanism_record
    from graphplan.exact.kinetostatics import analyse, at_scene_angle
    from graphplan.graphic.forceplans import acceleration_plan, construct
    st = example("shaper")
    phi = float(np.atleast_1d(at_scene_angle(st))[0])
    ks = analyse(st, [phi])
    accel = acceleration_plan(st, phi)
    plan = next(q.acceleration for q in accel.positions if q.acceleration is not None)
    rec = mechanism_record(construct(st, phi, accel=accel))
    drawn = {p.text: p.points for p in rec.items if p.kind == "vector" and p.text}
    loads = {ld.name: complex(ld.force[0]) for ld in ks.loads if abs(ld.force[0]) > 1e-9}
    for ld in ks.loads:
        if ld.kind == "inertia" and ld.name in loads:        # against π s on the plan
            loads[ld.name] = -plan.entries[ld.point].vector
    assert drawn.pop("M_b", None) is not None       # the balancing moment's arc ends in its arrowhead
    assert set(drawn) == set(loads)
    for name, f in loads.items():
        (x0, y0), (x1, y1) = drawn[name]
        assert math.isclose(math.atan2(y1 - y0, x1 - x0), math.atan2(f.imag, f.real), abs_tol=1e-9), name
    labels = [p.text for p in rec.items if p.kind == "text"]
    assert "M_зр" in labels and any(t.startswith("M^{Φ}") for t in labels)
    texts = " ".join(_texts(_build("shaper", "forces", "A1")))
    assert "Схема механізму з прикладеними силами" in texts and "Реакція стояка на повзун" in texts


def test_a_labels_ink_is_its_letters():
    """A label's ink is its glyphs: the capitals exactly the letter height, lowercase letters about
    0.7 of it, descenders below the baseline, and the advances add up to the label's width."""
    from graphplan.graphic.record import ink_boxes, plain_width
    boxes = ink_boxes("Ax", 10.0)
    assert len(boxes) == 2
    (_, a_lo, _, a_hi), (_, x_lo, x1, x_hi) = boxes
    assert a_hi == pytest.approx(10.0, abs=0.05)          # the letter height h is the capitals' (GOST 2.304)
    assert 6.0 < x_hi < 8.0 and a_lo == pytest.approx(0.0, abs=0.1)
    assert x1 <= plain_width("Ax", 10.0) + 1e-9
    assert ink_boxes("р", 10.0)[0][1] < -1.5             # a descender
    assert ink_boxes(" ", 10.0) == ()


def test_diagrams_share_one_time_base():
    """Seed 002: each division's thin ordinate runs from the top of s down to the bottom of a,
    broken only where the division numbers under s stand."""
    from graphplan.drawing.diagrams import draw
    from graphplan.graphic.diagrams import chord_diagrams
    d = chord_diagrams(example("lab_crank_slider"))
    rec = draw(d)
    curves = [p for p in rec.items if p.kind == "polyline" and p.role == "curve"]
    top = max(y for p in curves for _, y in p.points)
    bottom = min(y for p in curves for _, y in p.points)
    for x in d.x[1:]:
        spans = sorted((min(p.points[0][1], p.points[1][1]), max(p.points[0][1], p.points[1][1]))
                       for p in rec.items if p.kind == "segment" and p.role == "grid"
                       and abs(p.points[0][0] - x) < 1e-9)
        assert len(spans) == 2
        assert spans[0][0] <= bottom + 1e-6 and spans[1][1] >= top - 1e-6
        assert 0.0 < spans[1][0] - spans[0][1] < 8.0          # the gap for the numbers under s


@pytest.mark.parametrize("name", ["crank_slider", "shaper", "four_bar"])
def test_a3_set_fills_its_sheets_in_order(name):
    """An A3 set fills its sheets in reading order: no sheet holds a single drawing while the next
    sheet's first drawing would fit under it above the title block (the offset crank-slider's set
    gave a sheet to one acceleration plan and left the last one half empty); the position plan
    shares its sheet or fills half its height."""
    from graphplan.sheets.compose import field_of, keep_out
    from graphplan.drawing.layout import GAP
    f = form("A3")
    sheet = _build(name, "kinematics", "A3")
    x0, y0, x1, y1 = field_of(f)
    above = y1 - keep_out(f)[3]            # the field's height over the title block
    pages = [page.placed for page in sheet.pages]
    assert len(pages) > 1
    for n, (page, after) in enumerate(zip(pages, pages[1:]), 1):
        if len(page) != 1:
            continue
        h = page[0].record.bounds()[3] - page[0].record.bounds()[1]
        b = after[0].record.bounds()
        assert h + GAP + (b[3] - b[1]) > above or b[2] - b[0] > x1 - x0, (n, page[0].name, after[0].name)
    first = pages[0]
    assert first[0].name == "position plan"
    b = first[0].record.bounds()
    assert len(first) >= 2 or b[3] - b[1] >= (y1 - y0) / 2, [p.name for p in first]


@pytest.mark.parametrize("font", [True, False], ids=["font", "fallback"])
def test_lettering_reads_as_words_wherever_it_stands(font, tmp_path):
    """Headings and table titles in both languages and a product of indexed factors, each drawn at
    25 sub-pixel offsets and counted as the reader's eye does (tests/inkcheck.py), with the packaged
    font and as a viewer without it letters them: no letter splits off its word into another's box —
    a small letter after Г, Т, T kerned under the bar, a thin space after an index
    (graphic.record.kern, SCRIPT_SPACE)."""
    code = ("import json, sys\n"
            f"sys.path.insert(0, {str(ROOT / 'tests')!r})\n"
            + ("from graphplan.drawing.fonts import register\nregister()\n" if font else "")
            + "from inkcheck import overprinted\n"
            "from graphplan.graphic.record import Record\n"
            "from graphplan.drawing.svg import render\n"
            "bad = []\n"
            "for i in range(5):\n"
            "    for j in range(5):\n"
            "        r = Record('t')\n"
            "        y = 8 + 0.05 * j\n"
            "        for text in ('Група II(2–3)', 'Таблиця 2. Гранична сила', 'Table 1. Reduced moments',\n"
            "                     'Type A train, tooth T3', 'Гр. МБ-31'):\n"
            "            r.label((5 + 0.05 * i, y), text, size=5.0)\n"
            "            y += 9\n"
            "        r.label((5 + 0.05 * i, y), 'μ_A = μ_M·μ_φ·H = 24,75 Дж/мм', size=3.5)\n"
            "        hits = overprinted(render(r, 150.0, 64.0, 't'))\n"
            "        if hits: bad.append((i, j, hits))\n"
            "print(json.dumps(bad))\n")
    env = None
    if not font:
        import os
        from pathlib import Path

        from graphplan.graphic.record import fallback_font
        if fallback_font() is None:
            pytest.skip("the fallback font (DejaVu Sans) is not installed")
        conf = tmp_path / "fonts.conf"
        conf.write_text(FALLBACK_ONLY.format(folder=Path(fallback_font()).parent, cache=tmp_path / "cache"),
                        encoding="utf-8")
        env = dict(os.environ, FONTCONFIG_FILE=str(conf))
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, check=True, env=env)
    assert json.loads(done.stdout) == []


def printed(value: float, cells) -> bool:
    """Whether a cell prints ``value`` to the cell's own decimals (the tables write one count of
    decimals a column: 4.3 as "4,30"); a bare "0" is the number zero."""
    for c in cells:
        m = re.fullmatch(r"[−-]?\d+(?:[.,](\d+))?\*?", c)
        if not m:
            continue
        v = float(c.rstrip("*").replace("−", "-").replace(",", "."))
        tol = 1e-12 if c == "0" else 0.5 * 10.0 ** -len(m.group(1) or "") + 1e-9
        if abs(v - value) <= tol:
            return True
    return False
