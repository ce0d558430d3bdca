"""The dynamics sheet read as a teacher reads it: every value of a dimensional quantity in the notes,
tables and lettering carries its unit, no number longer than the sheet's 4 significant figures, the
given δ written as given, ω_m²·δ typeset, the field filled — on two mechanisms nobody drew before
(a six-bar press and an offset crank-slider with a 1000 rpm motor, the review's scenes)."""
from __future__ import annotations

import math
import re

import numpy as np
import pytest

from conftest import scene_sheet
from graphplan.util.markup import plain, runs

SIXBAR = """title = "Шестиланковий важільний механізм преса"
title_en = "Six-bar lever mechanism of a press"
designation = "ТММ.21.00.000"

[sheet]
student = "Петренко І."
teacher = "Коваль О."
group = "МБ-31"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]
O2 = [0.32, 0.05]

[frame.guides]
ram = { through = [0.34, 0], angle_deg = 90, title_uk = "повзуна", title_en = "of the ram" }

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.09
rpm = 90
points = { S1 = 0.5 }
mass = 4
inertia = 0.02

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.30
points = { S2 = 0.5 }
mass = 8
inertia = 0.08

[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = 0.22
shape = { C = [0.30, 0] }
points = { S3 = 0.4 }
mass = 10
inertia = 0.12

[[link]]
name = "CD"
number = 4
joints = ["C", "D"]
length = 0.35
points = { S4 = 0.5 }
mass = 6
inertia = 0.07

[[link]]
name = "D"
number = 5
joints = ["D"]
slides_on = "ram"
mass = 30

[branch]
B = 1
D = 1

[positions]
count = 12
start = "max"
accel = [2]
force_phi_deg = 60

[loads]
g = 9.81

[[force]]
point = "D"
magnitude = 2000
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.05
efficiency = 0.9
"""

OFFSET = """title = "Кривошипно-повзунний механізм з дезаксіалом"
title_en = "Offset crank-slider mechanism"
designation = "ТММ.22.00.000"

[sheet]
student = "Петренко І."
teacher = "Коваль О."
group = "МБ-31"
organisation = "НУБіП України"

[params]
r = 0.08
l = 0.30
e = 0.03

[frame.points]
O = [0, 0]

[frame.guides]
x = { through = [0, "e"], angle_deg = 0 }

[crank]
name = "OA"
pivot = "O"
pin = "A"
length = "r"
rpm = 240
points = { S1 = 0.3 }
mass = 3
inertia = 0.01

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = "l"
points = { S2 = 0.3 }
mass = 5
inertia = 0.05

[[link]]
name = "B"
number = 3
joints = ["B"]
slides_on = "x"
mass = 12

[branch]
B = 1

[positions]
count = 12
start = "outer"
accel = [4]
force_phi_deg = 120

[loads]
g = 9.81

[[force]]
point = "B"
magnitude = 1200
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.03
efficiency = 0.95
synchronous_rpm = 1000
"""

UNITS = ("Н·м", "N·m", "Дж", "J", "кг·м²", "kg·m²", "рад", "rad", "мм", "mm", "°", "%", "кВт", "kW", "об/хв", "rpm")
DIMENSIONLESS = {"δ", "δ_дв", "δ_mot", "i", "η"}
LETTERED = {"notes", "positions table", "flywheel table", "motor table", "speed", "wittenbauer"}


@pytest.fixture(scope="module")
def sheets():
    """The three dynamics sheets, each composed alone (``conftest.composed``; no test here reads the
    project's numbering, which would compose the six-bar's and the crank-slider's kinematics and force
    sheets to count them: 24 of the fixture's 31 s of CPU)."""
    out = {}
    for name, text, langs in (("sixbar", SIXBAR, ("uk", "en")), ("offset", OFFSET, ("uk",))):
        for lang in langs:
            out[name, lang] = scene_sheet(text, "dynamics", "A1", lang, precision=0.5)
    return out


def lettering(sheet) -> list[str]:
    return [item.text for p in sheet.placed if p.name in LETTERED for item in p.record.items if item.kind == "text"]


def note_lines(sheet) -> list[str]:
    """The notes' lines as written, each wrapped line joined again (a continuation stands indented
    from the block's left edge: compose.note_block), whatever width the notes are set in."""
    items = sorted((it for p in sheet.placed if p.name == "notes" for it in p.record.items if it.kind == "text"),
                   key=lambda it: -it.points[0][1])
    left = min(it.points[0][0] for it in items)
    out: list[str] = []
    for it in items:
        if abs(it.points[0][0] - left) < 1e-6 or not out:
            out.append(it.text)
        else:
            out[-1] += " " + it.text
    return out


def clauses(text: str) -> list[str]:
    return re.split(r";\s|,\s|:\s", plain(text))


NUMBER = re.compile(r"^[−-]?\d+(?:[.,]\d+)?\s*(.*)$")


@pytest.mark.parametrize("key", [("sixbar", "uk"), ("sixbar", "en"), ("offset", "uk")])
def test_every_value_of_a_dimensional_quantity_has_its_unit(sheets, key):
    bare = []
    for text in lettering(sheets[key]):
        for clause in clauses(text):
            if "=" not in clause:
                continue
            parts = clause.split("=")
            m = NUMBER.match(parts[-1].strip())
            if m is None or m.group(1).startswith(UNITS):
                continue
            symbol = parts[0].split()[-1].lstrip("(") if parts[0].split() else ""   # "(δ = …)" is δ
            if symbol not in DIMENSIONLESS:
                bare.append(clause)
    assert bare == []


def significant(token: str) -> int:
    digits = token.replace(",", "").replace(".", "").lstrip("0")
    return len(digits if ("," in token or "." in token) else digits.rstrip("0")) or 1


@pytest.mark.parametrize("key", [("sixbar", "uk"), ("sixbar", "en"), ("offset", "uk")])
def test_no_number_longer_than_four_significant_figures(sheets, key):
    sep = "," if key[1] == "uk" else "."
    token = re.compile(rf"(?<![\w.,])\d+(?:{re.escape(sep)}\d+)?")
    long = [(t, text) for text in lettering(sheets[key]) for t in token.findall(plain(text)) if significant(t) > 4]
    assert long == []


@pytest.mark.parametrize("key, given", [(("sixbar", "uk"), "0,05"), (("sixbar", "en"), "0.05"),
                                        (("offset", "uk"), "0,03")])
def test_the_achieved_delta_is_written_as_given(sheets, key, given):
    notes = [plain(t) for t in lettering(sheets[key])]
    word = "Досягнуто" if key[1] == "uk" else "Achieved"
    line = next(t for t in notes if t.startswith(word))
    assert line.startswith(f"{word}: δ = {given};")


@pytest.mark.parametrize("key", [("sixbar", "uk"), ("sixbar", "en")])
def test_omega_m_squared_delta_is_typeset(sheets, key):
    """ω with m below and 2 above, then ·δ on the line — in the flywheel's formula and in tg ψ (English: tan ψ,
    review 58 #7: English texts write tan)."""
    found = 0
    for text in lettering(sheets[key]):
        if not (text.startswith("J = ") or text.startswith(("tg ψ", "tan ψ"))):
            continue
        r = runs(text)
        for k, run in enumerate(r[:-2]):
            if run.level == 0 and run.text.endswith("ω") and r[k + 1] == type(run)("m", -1) \
                    and (r[k + 2].text, r[k + 2].level) == ("2", 1):
                found += 1
                assert r[k + 3].level == 0
        assert not any("δ" in run.text for run in r if run.level != 0)
    assert found == 2


def covered(sheet) -> float:
    """The share of the field (less the title block) under the drawings' and tables' extents."""
    from graphplan.sheets.compose import field_of, keep_out
    x0, y0, x1, y1 = field_of(sheet.form)
    k = keep_out(sheet.form)
    X, Y = np.meshgrid(np.arange(x0, x1, 2.0) + 1.0, np.arange(y0, y1, 2.0) + 1.0)
    free = ~((X >= k[0]) & (Y <= k[3]))
    cov = np.zeros_like(free)
    for p in sheet.placed:
        b = p.record.bounds()
        cov |= (X >= b[0]) & (X <= b[2]) & (Y >= b[1]) & (Y <= b[3])
    return float((cov & free).sum() / free.sum())


@pytest.mark.parametrize("key", [("sixbar", "uk"), ("offset", "uk")])
def test_the_diagrams_grow_into_the_field(sheets, key):
    """The review found about a quarter of the field empty (57 % under the drawings' extents): ω(φ)
    takes the room over the tables and the bands grow to the next size."""
    assert covered(sheets[key]) > 0.68


@pytest.mark.parametrize("key", [("sixbar", "uk"), ("sixbar", "en"), ("offset", "uk")])
def test_the_notes_fill_the_room_under_the_energy_diagram(sheets, key):
    """The band (ΔT(φ) beside the energy–mass diagram, I*(φ) turned under it) is an L: the review
    found the room under ΔT(φ) empty (about 220 × 150 mm on the four-bar's A1 sheet). The notes
    stand there — under ΔT(φ), left of the turned I*(φ), their tops level with one another, a GAP
    under ΔT(φ) or under the energy–mass diagram — and the field is covered more than before (0.70)."""
    from graphplan.drawing.layout import GAP
    box = {p.name: p.record.bounds() for p in sheets[key].placed}
    notes, energy, inertia, witt = box["notes"], box["energy"], box["inertia"], box["wittenbauer"]
    assert notes[2] <= inertia[0] - GAP + 1.0 and (notes[2] <= witt[0] - GAP + 1.0 or notes[3] < witt[1])
    assert notes[3] <= energy[1] - GAP + 1.0 and notes[1] >= inertia[1] - 1.0
    assert min(abs(notes[3] - (energy[1] - GAP)), abs(notes[3] - (witt[1] - GAP))) < 3.0     # not adrift
    assert covered(sheets[key]) > 0.72


# -- the review's corrections 7, 15 (one ω_m per symbol; the broken ω axis; ΔT's unit; δ, %; Latin) --------

N1 = {"sixbar": 90.0, "offset": 240.0}     # the scenes' crank rpm: the flywheel's ω_m = πn_1/30
VALUE = re.compile(r"^[−-]?\d+(?:[.,]\d+)?")
OMEGA = re.compile(r"ω_?[a-z0-9₀-₉]+(?: дв| mot)?$")


def rows(sheet, name: str) -> list[list[str]]:
    """A table's cells (plain text) row by row: its text items grouped by their baseline, left to right."""
    rec = next(p.record for p in sheet.placed if p.name == name)
    by_y: dict[float, list] = {}
    for it in rec.items:
        if it.kind == "text":
            by_y.setdefault(round(it.points[0][1], 1), []).append(it)
    return [[plain(it.text) for it in sorted(v, key=lambda it: it.points[0][0])] for v in by_y.values()]


def omega_values(sheet) -> dict[str, set[float]]:
    """Every value the lettering gives an ω symbol (ω_m, ω_m дв …): "sym = … = value" clauses in the
    notes, legends and tables, and the motor table's "sym, unit; δ" | "value; δ" rows."""
    out: dict[str, set[float]] = {}

    def put(sym: str, text: str) -> None:
        m = VALUE.match(text.strip())
        if m:
            out.setdefault(sym, set()).add(float(m.group(0).replace(",", ".").replace("−", "-")))
    for text in lettering(sheet):
        for clause in re.split(r";\s|,\s(?!дв|mot)|:\s|\s\(", plain(text)):
            parts = clause.split("=")
            for head in parts[:-1]:
                sym = OMEGA.search(head.strip())
                if sym:
                    put(sym.group(0), parts[-1])
    for row in rows(sheet, "motor table"):
        if len(row) == 2:
            for head, value in zip(row[0].split("; "), row[1].split("; ")):
                sym = OMEGA.search(head.split(",")[0].strip())
                if sym and "/" not in head:
                    put(sym.group(0), value)
    return out


@pytest.mark.parametrize("key", [("sixbar", "uk"), ("sixbar", "en"), ("offset", "uk")])
def test_one_value_per_symbol_and_the_flywheel_omega_is_the_scenes_n1(sheets, key):
    """The review's fourbar: "ω_m = 9,425" in the notes, "ω_m = 10,14" in Table 3 (the motor-driven
    crank, 7.6 % faster). The flywheel's ω_m is πn_1/30; the motor's mean speed has its own symbol."""
    values = omega_values(sheets[key])
    assert all(len(v) == 1 for v in values.values()), values
    (wm,) = values["ω_m"]
    assert wm == pytest.approx(math.pi * N1[key[0]] / 30, abs=6e-3)
    motor = "ω_m дв" if key[1] == "uk" else "ω_m mot"
    assert motor in values and values[motor] != values["ω_m"]
    said = [t for t in (plain(t).replace("\u00a0", " ") for t in note_lines(sheets[key]))
            if f"{motor} = " in t and "ω_m = πn₁/30" in t]
    assert len(said) == 1                            # the line saying which serves what


@pytest.mark.parametrize("key", [("sixbar", "uk"), ("offset", "uk")])
def test_the_truncated_omega_axis_is_broken(sheets, key):
    """ω(φ) swings a few per cent about ω_m: its scale starts near ω_min, so between the φ axis
    (ω = 0, lettered 0) and the lowest tick the ordinate axis carries a zigzag (GOST 2.303)."""
    rec = next(p.record for p in sheets[key].placed if p.name == "speed")
    phi_axis = next(it for it in rec.items if it.kind == "vector" and it.points[0][1] == it.points[1][1])
    x0, y0 = phi_axis.points[0]
    ticks = sorted((float(it.text.replace(",", ".")), it.points[0][1]) for it in rec.items
                   if it.kind == "text" and it.anchor == "end" and VALUE.fullmatch(it.text))
    (v1, y1), (v2, y2) = ticks[1], ticks[-1]
    zero = y1 - v1 * (y2 - y1) / (v2 - v1)             # where ω = 0 would be on the ticks' scale
    assert ticks[0][0] == 0 and zero < y0 - 50.0       # lettered 0 at the φ axis, far above the true zero
    zig = [it for it in rec.items if it.kind == "polyline"
           and all(abs(x - x0) < 3.0 and y0 <= y <= y1 for x, y in it.points)]
    assert zig and max(x for x, _ in zig[0].points) > x0 + 1.0 and min(x for x, _ in zig[0].points) < x0 - 1.0


@pytest.mark.parametrize("key", [("sixbar", "uk"), ("sixbar", "en")])
def test_the_energy_axes_carry_the_unit_and_table_2_heads_delta(sheets, key):
    uk = key[1] == "uk"
    texts = [plain(it.text) for p in sheets[key].placed if p.name in ("energy", "wittenbauer")
             for it in p.record.items if it.kind == "text" and plain(it.text).startswith("ΔT")]
    assert texts and all(t.startswith("ΔT, Дж" if uk else "ΔT, J") for t in texts)
    assert any(re.search(r"μ_T = \d", t) for t in texts)
    cells = [c for row in rows(sheets[key], "flywheel table") for c in row]
    assert "δ, %" in cells and not any("похибка" in c or "error" in c for c in cells)


def test_the_english_sheet_writes_the_motor_in_latin(sheets):
    """The catalogue's 4АМ… (Cyrillic А, М, В) in Latin on an English sheet; the Ukrainian keeps it."""
    cyrillic = [t for t in lettering(sheets["sixbar", "en"]) if re.search("[\u0400-\u04ff]", t)]
    assert cyrillic == []
    def names(lang: str) -> list[str]:
        return [c for row in rows(sheets["sixbar", lang], "motor table") for c in row if c.startswith("4")]
    assert len(names("en")) == 1 and re.fullmatch(r"4AM\d+[A-Z]\d", names("en")[0])
    assert len(names("uk")) == 1 and re.fullmatch(r"4АМ\d+[A-ZА-Я]\d", names("uk")[0])


def _number(text: str) -> float:
    return float(text.replace(",", ".").replace("−", "-"))


@pytest.mark.parametrize("key", [("sixbar", "uk"), ("offset", "uk")])
def test_omega_m_and_the_extremes_are_drawn_where_the_axis_reads_them(sheets, key):
    """Stop 46 (the rocker's ω(φ): three ticks, its extremes between them, no ω_m): the ordinate axis
    graduated at least five times, each mean speed a dash-dot line at the height the ticks give its
    legend's value, and ω_max, ω_min lettered at the solid curve's highest and lowest points, their
    printed values giving the printed δ = (ω_max − ω_min)/ω_m to the rounding of the figures."""
    rec = next(p.record for p in sheets[key].placed if p.name == "speed")
    texts = [it for it in rec.items if it.kind == "text"]
    ticks = sorted((_number(it.text), it.points[0][1] + 1.0) for it in texts if it.step == "ω ticks" and it.text != "0")
    assert len(ticks) >= 5
    a, b = np.polyfit([v for v, _ in ticks], [y for _, y in ticks], 1)
    value = lambda y: (y - b) / a                                   # noqa: E731  the drawn height → ω
    legends = [plain(it.text) for it in texts if "рад/с" in it.text and ":" in it.text]
    means = {m.group(1): _number(m.group(2)) for t in legends for m in re.finditer(r"(ω_m(?: дв)?) = (\d+(?:,\d+)?)", t)}
    assert set(means) == {"ω_m", "ω_m дв"}
    for sym, wm in means.items():
        line = next(it for it in rec.items if it.kind == "segment" and it.role == "axis" and plain(it.step) == f"{sym} line")
        assert value(line.points[0][1]) == pytest.approx(wm, abs=0.006)
    solid = np.array(next(it for it in rec.items if it.kind == "polyline" and it.role == "curve").points)
    got = {}
    for name, pick in (("max", np.max), ("min", np.min)):
        label = next(it for it in texts if it.step == f"ω_{name}")
        got[name] = _number(plain(label.text).split("= ")[1].split()[0])
        assert got[name] == pytest.approx(value(pick(solid[:, 1])), abs=0.01)
    delta = (got["max"] - got["min"]) / means["ω_m"]
    given = _number(re.search(r"δ = (\d+(?:,\d+)?)", legends[0]).group(1))
    assert delta == pytest.approx(given, rel=0.02)


@pytest.mark.parametrize("key", [("sixbar", "uk"), ("sixbar", "en"), ("offset", "uk")])
def test_table_1s_delta_is_the_printed_pairs_over_the_printed_span(sheets, key):
    """Stop 46: a reader recomputes Table 1's δ from the printed ΔT гр. and ΔT and the range the note
    under the table prints (ΔT_max − ΔT_min = a − (b) = c): c is the printed difference, a and b the
    exact column's extremes, and every row's δ that pair's (g − e)/c to the printed decimal."""
    table = [r for r in rows(sheets[key], "positions table") if len(r) == 11]
    head, body = table[0], [[c.rstrip("*") for c in r] for r in table[1:]]
    assert head[8].startswith("ΔT") and head[9].startswith("ΔT") and head[10] == "δ, %"
    text = " ".join(plain(it.text) for p in sheets[key].placed if p.name == "positions table"
                    for it in p.record.items if it.kind == "text" and it.step == "chord heights")
    m = re.search(r"ΔT_max − ΔT_min = ([−\d,.]+) − \(?([−\d,.]+)\)? = ([\d,.]+)", text.replace("\u00a0", " "))
    assert m, text
    hi, lo, span = (_number(g) for g in m.groups())
    exact = [_number(r[9]) for r in body]
    assert (hi, lo) == (max(exact), min(exact)) and span == pytest.approx(hi - lo, abs=1e-9)
    for r in body:
        assert _number(r[10]) == pytest.approx(round(100 * (_number(r[8]) - _number(r[9])) / span, 1), abs=1e-9), r


def _decimals(text: str) -> int:
    return len(text.split(",")[1]) if "," in text else 0


@pytest.mark.parametrize("key", [("sixbar", "uk"), ("offset", "uk")])
def test_the_flywheels_arithmetic_gives_table_2s_values_from_its_printed_numbers(sheets, key):
    """Stop 46 (the rocker: J = 0,952·68,5/(14,66²·0,06) = 5,057 and I_мах = J − 0,3231 printed
    4,733, the printed numbers giving 4,734; the approximate (21,9 − (−44,7))/(14,66²·0,06) − 0,05746
    − 0,3231 printed 4,787, giving 4,784): a reader working each chain from its printed numbers gets
    its printed result, and Table 2's graphical and approximate rows are those results."""
    sheet = sheets[key]
    lines = [plain(t).replace("\u00a0", " ") for t in note_lines(sheet)]
    j_line = " ".join(lines)
    n = r"(−?\d+(?:,\d+)?)"
    m = re.search(rf"= {n}·{n}/\({n}²·{n}\) = {n} кг·м²; I_мах = J − I_рот·i² = {n}", j_line)
    assert m, j_line
    mu, kl, w, d, J = (_number(m.group(k)) for k in range(1, 6))
    assert round(mu * kl / (w * w * d), _decimals(m.group(5))) == pytest.approx(J, abs=1e-9)
    rotor = next(r[1] for r in rows(sheet, "motor table") if r[0].startswith("I_рот"))   # Table 3's I_рот·i²
    subtracted = _number(rotor)
    graphical = m.group(6)
    assert round(J - subtracted, _decimals(graphical)) == pytest.approx(_number(graphical), abs=1e-9)
    rec = next(p.record for p in sheet.placed if p.name == "flywheel table")
    approx = " ".join(plain(it.text).replace("\u00a0", " ") for it in rec.items
                      if it.kind == "text" and it.step == "approximate arithmetic")
    m = re.search(rf"= \({n} − \(?{n}\)?\)/\({n}²·{n}\)((?: − {n})+) = {n} кг·м²", approx)
    assert m, approx
    hi, lo, w, d = (_number(m.group(k)) for k in range(1, 5))
    subtracted = sum(_number(v) for v in re.findall(n, m.group(5)))
    value = m.group(7)
    assert round((hi - lo) / (w * w * d) - subtracted, _decimals(value)) == pytest.approx(_number(value), abs=1e-9)
    table = {r[0]: r[1] for r in rows(sheet, "flywheel table") if len(r) == 3}
    assert next(v for k, v in table.items() if k.startswith("графічно")) == graphical
    assert next(v for k, v in table.items() if k.startswith("наближ.: (")) == value


def test_the_english_sheet_writes_tan_and_the_ukrainian_tg(sheets):
    """Review 58 #7: the tangents' slope in the notes is «tg ψ» on the Ukrainian sheet (ДСТУ) and «tan ψ»
    on the English one, as English texts write it."""
    en = [t for t in lettering(sheets[("sixbar", "en")]) if "ψ = μ" in t]
    uk = [t for t in lettering(sheets[("sixbar", "uk")]) if "ψ = μ" in t]
    assert en and all(t.startswith("tan ψ") for t in en), en
    assert uk and all(t.startswith("tg ψ") for t in uk), uk
