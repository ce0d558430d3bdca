"""Review 54 #1 and #10: the kinematics sheet's readings table (s, v, a read off the diagrams beside the
plans and the exact values) prints s, v, a in the diagrams' sense — mirrored where the diagrams are
drawn against the guide — and each δ beside them must be the δ of the pair it stands under:
δ = 100·(g − e)/e, or 100·(g − e)/|max| where |e| < 10 % of |max| (the note under the table says so).
The δ of |max| kept the guide's sign: a_E −1,30 vs −0,75 was printed +3,68 (should be ≈ −3,7).

Truth here is the printed table itself (a reader's check): the cells are parsed from the table's
record, δ recomputed from the printed pair with its rounding, and the cycle's |max| of the exact
motion; the sheet's note naming the readings past 5 % must quote the same δ as the table."""
from __future__ import annotations

import re

import pytest

import review_scenes
from conftest import scene_study
from test_kin_marks import _table_rows
from graphplan.graphic.diagrams import MEANINGFUL, chord_diagrams
from graphplan.graphic.plans import build_plans
from graphplan.report.plans import plans_json
from graphplan.sheets.kintables import readings_table

# (scene, H1 = H2): the short poles of the last one put a δ of |max| past 5 % (a_D at 3) in the note
SCENES = [("CYLINDER_REVIEW54", 25), ("COUPLER_SLIDER_REVIEW54", 25), ("LINK53", 25), ("INCLINED_ROCKER53", 25),
          ("COUPLER_SLIDER_REVIEW54", 10)]


def _number(cell: str) -> float:
    return float(cell.rstrip("*").replace("−", "-").replace(",", "."))


def _half(cell: str) -> float:
    """Half a unit of the last decimal a cell is printed to (its rounding)."""
    c = cell.rstrip("*").replace(",", ".")
    return 0.5 * 10.0 ** -(len(c.split(".")[1]) if "." in c else 0)


@pytest.fixture(scope="module", params=SCENES, ids=lambda p: f"{p[0]}-H{p[1]}")
def table(request):
    """A scene's diagrams (12 chords, as the sheet's first drawing) and its readings table's rows."""
    name, h = request.param
    st = scene_study(getattr(review_scenes, name))
    plans = build_plans(st)
    d = chord_diagrams(st, divisions=12, L=240, H1=h, H2=h)
    rec = readings_table(d, plans_json(plans), "en", 4, plans.precision)
    texts = " ".join(q.text for q in rec.items if q.kind == "text")
    return f"{name}-H{h}", d, _table_rows(rec), (st, plans, texts)


def _deltas(grid: list[list[str]], sym: str) -> list[tuple[int, str, str, str]]:
    """(position, reading, exact, δ) of one quantity: its rows are reading, plan, exact, δ."""
    at = next(i for i, r in enumerate(grid) if r[0].startswith(f"δ_{{{sym}}}"))
    return list(zip((int(c) for c in grid[0][1:]), grid[at - 3][1:], grid[at - 1][1:], grid[at][1:]))


def test_every_printed_delta_is_of_the_printed_pair(table):
    """δ = 100·(g − e)/ref of the printed cells, to δ's two decimals (ref = e, or |max| of the exact
    cycle where |e| < 10 % of it; near that border either), so sign(δ) = sign((g − e)/ref) with the
    printed signs; the table's signs are the diagrams' (mirrored for four of the cases)."""
    name, d, grid, (_, _, texts) = table
    checked = 0
    for sym, key in ((d.symbols[1], "v"), (d.symbols[2], "a")):
        big = float(d.maxima[key])
        for n, gc, ec, dc in _deltas(grid, sym):
            if dc == "—":
                continue
            g, e, delta = _number(gc), _number(ec), _number(dc)
            slack = 0.0                  # δ of the printed pair itself (as Tables 1–2 give theirs)
            refs = [r for r, ok in ((e, abs(e) + _half(ec) >= MEANINGFUL * big),
                                    (big, abs(e) - _half(ec) < MEANINGFUL * big)) if ok and r != 0]
            fits = [r for r in refs if abs(delta - 100 * (g - e) / r) <= 100 * slack / abs(r) + 0.006]
            assert fits, (name, sym, n, gc, ec, dc, big)
            if g != e:
                assert any((delta > 0) == ((g - e) / r > 0) or delta == 0 for r in fits), (name, sym, n, gc, ec, dc)
            checked += 1
            if abs(e) - _half(ec) >= MEANINGFUL * big or abs(e) + _half(ec) < MEANINGFUL * big:
                of_max = abs(e) < MEANINGFUL * big         # clear of the border: the footnote's |max|
                top = re.search(rf"{sym}_\{{{d.sub}\}}: (\d+\.\d+) ", texts)
                assert (top is not None) >= of_max, (name, sym, n, texts)
                if of_max:
                    assert float(top.group(1)) == pytest.approx(big, abs=_half(top.group(1))), (name, top.group(1), big)
    assert checked >= 12, (name, checked)


def test_the_note_quotes_the_tables_delta(table):
    """The sheet's note on readings past the lab's 5 % ("… at positions 10 (−15.52 %)") gives each the
    δ its table prints at that position, and names only readings the table marks past 5 %."""
    from graphplan.sheets.kintables import notes_lines
    name, d, grid, (st, plans, _) = table
    said_all = [line for line in notes_lines(st, plans, d, "en", plans.precision) if "exceed the 5 %" in line]
    if not said_all:
        assert not any(c.endswith("*") for r in grid for c in r[1:] if r[0].startswith("δ")), (name, grid)
        return
    note = said_all[0]
    for sym in (d.symbols[1], d.symbols[2]):
        printed = {n: dc for n, _, _, dc in _deltas(grid, sym)}
        said = re.search(rf"{sym}_\{{{d.sub}\}} at positions? ([^;—]*)", note)
        if said is None:
            assert not any(c.endswith("*") for c in printed.values()), (name, sym, note)
            continue
        for n, value in re.findall(r"(\d+) \(([+−][\d.]+) %\)", said.group(1)):
            assert printed[int(n)].endswith("*"), (name, sym, n, printed[int(n)], note)
            assert printed[int(n)].rstrip("*") == value.lstrip("+"), (name, sym, n, value, printed[int(n)], note)


@pytest.mark.parametrize("lang", ["en", "uk"])
def test_the_terminal_says_when_its_mm_and_values_differ_in_sign(table, lang):
    """`diagrams` prints the ordinates as drawn (mm) beside the values signed along the guide; where the
    diagrams are mirrored a row's s = −mm·μ_s (read off the printed columns) and the terminal says so
    once, and that the sheet's δ of |max| has the other sign; unmirrored, s = +mm·μ_s and no such line."""
    from graphplan.report.diagrams import diagrams_table
    name, d, _, _ = table
    text = diagrams_table(d, lang)
    said = [line for line in text.splitlines() if ("mirrored" if lang == "en" else "дзеркально") in line]
    assert len(said) == (1 if d.sign < 0 else 0), (name, said)
    rows = text.split("\n\n")[2].splitlines()[2:]        # the block at the division ordinates
    for row in rows[:12]:
        cells = row.split()
        mm, s = _number(cells[3]), _number(cells[4])
        if abs(mm) > 1.0:
            assert s / (mm * d.mu_s) == pytest.approx(-1.0 if d.sign < 0 else 1.0, abs=0.02), (name, row)
