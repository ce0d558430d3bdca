"""Stop 51's gear-sheet review (helper gear51): the lead's pair 14/26 with a large module m = 8 mm and the
shifts chosen by the rule, and a type-A train for u = 5,6, K = 4, n1 = 1440 rpm (GEARS51); the helper's own
unshifted 18/72 with m = 2 mm and a type-A train for u = 4,2 with five planets (GEARS_OWN51) — checked
against the closed forms written out here (not the code's) and measured on the drawn records."""
from __future__ import annotations

import math
import tomllib

import pytest

from review_scenes import GEARS51, GEARS_OWN51
from test_gears_review50 import pair_closed


def _solved(text: str, name: str):
    from graphplan.exact.gears import solve
    from graphplan.model.gears import build
    g = build(tomllib.loads(text), name)
    return g, solve(g)


def _sheet(text: str, name: str, lang: str):
    from graphplan.sheets.compose import compose
    from graphplan.sheets.form import form
    from graphplan.sheets.gears import _fields, on_sheet
    g, sol = _solved(text, name)
    mesh, vel, pages = on_sheet(g, sol, form("A1"), 0.5, lang)
    return sol, mesh, vel, compose(form("A1"), pages, _fields(g, lang, mesh.mu_l), lang, g.title_in(lang))


@pytest.fixture(scope="module")
def sheet51():
    """GEARS51's A1 sheet in Ukrainian as build_gears_sheet composes it (about 5 s)."""
    return _sheet(GEARS51, "GEARS51", "uk")


def test_the_pair_and_the_train_are_the_closed_forms():
    """GEARS51 by hand: x = 0,6/0,55 (the rule's choice) give inv αw = 2·1,15·tg 20°/40 + inv 20° →
    αw = 26,4453°, aw = 160·cos 20°/cos αw = 167,922 mm, y = 0,9903, Δy = 0,1597, ra = 67,522/115,122 mm,
    sa = 4,250/5,753 mm, εα = 1,2014; the train z = 19/33/85: z3 = z1 + 2z2, (19 + 85)/4 = 26,
    52·sin 45° = 36,77 > 35, u1H = 1 + 85/19 = 5,4737, ω1 = 1440π/30, ωH = ω1/u1H, ω2 = ωH − (ω1 − ωH)·z1/z2.
    GEARS_OWN51: the standard 18/72 (αw = α, aw = a = 90 mm, εα = 1,671) and z = 29/31/91, K = 5."""
    g, sol = _solved(GEARS51, "GEARS51")
    p = sol.pair
    assert tuple(p.x) == pytest.approx((0.6, 0.55))
    c = pair_closed(14, 26, 0.008, 0.6, 0.55)
    assert math.degrees(c["alpha_w"]) == pytest.approx(26.4453, abs=5e-5)
    assert math.degrees(p.alpha_w) == pytest.approx(math.degrees(c["alpha_w"]), abs=1e-9)
    assert p.aw == pytest.approx(c["aw"], rel=1e-12) and c["aw"] * 1000 == pytest.approx(167.922, abs=1e-3)
    assert p.y == pytest.approx(c["y"], abs=1e-12) and p.dy == pytest.approx(c["dy"], abs=1e-12)
    for k in (0, 1):
        assert p.ra[k] == pytest.approx(c["ra"][k], rel=1e-12) and p.rf[k] == pytest.approx(c["rf"][k], rel=1e-12)
        assert p.sa[k] == pytest.approx(c["sa"][k], rel=1e-9) and p.s[k] == pytest.approx(c["s"][k], rel=1e-12)
    assert [round(v * 1000, 3) for v in c["sa"]] == [4.25, 5.753]
    assert p.eps == pytest.approx(c["eps"], rel=1e-12) and round(c["eps"], 4) == 1.2014
    assert round(c["lam1_B1"], 3) == -1.351 and round(c["lam2_B2"], 3) == -1.42
    z1, z2, z3 = sol.train.z
    assert (z1, z2, z3) == (19, 33, 85)
    assert z3 == z1 + 2 * z2 and (z1 + z3) % 4 == 0 and (z1 + z2) * math.sin(math.pi / 4) > z2 + 2
    w1 = 1440 * math.pi / 30
    u = 1 + z3 / z1
    wH = w1 / u
    assert sol.train.ratio == pytest.approx(u, rel=1e-12)
    assert sol.train.omega["H"] == pytest.approx(wH, rel=1e-12)
    assert sol.train.omega["2"] == pytest.approx(wH - (w1 - wH) * z1 / z2, rel=1e-12)
    g, sol = _solved(GEARS_OWN51, "GEARS_OWN51")
    c = pair_closed(18, 72, 0.002, 0.0, 0.0)
    assert sol.pair.aw == pytest.approx(0.09, rel=1e-12) and sol.pair.eps == pytest.approx(c["eps"], rel=1e-12)
    assert round(c["eps"], 3) == 1.671
    z1, z2, z3 = sol.train.z
    assert z3 == z1 + 2 * z2 and (z1 + z3) % 5 == 0 and (z1 + z2) * math.sin(math.pi / 5) > z2 + 2
    assert abs(1 + z3 / z1 - 4.2) <= 0.04 * 4.2


def _rules_and_cells(rec):
    """A drawn table's horizontal rules (their y, descending) and its texts under the top rule."""
    ys = sorted({round(q.points[0][1], 6) for q in rec.items if q.kind == "segment" and q.role == "table"
                 and abs(q.points[0][1] - q.points[1][1]) < 1e-9}, reverse=True)
    cells = [q for q in rec.items if q.kind == "text" and q.points[0][1] < ys[0]]
    return ys, cells


def test_the_a1_tables_letter_at_3_5_mm_in_rows_that_hold_them(sheet51):
    """Stop 51: the three tables and the notes of gears.toml were 19 mm taller than the column over the title
    block at the other sheets' size (3,5-mm letters, 8,4-mm rows): the tables fell back to 2,5-mm letters with
    35-mm gaps between them. Now they take 3,5-mm letters in 7-mm rows — measured on the drawn tables: every
    cell's letters 3,5 mm, the rows 7 mm apart, each cell's lettering between its two rules, and the column
    still clear of the title block."""
    from graphplan.sheets.compose import keep_out
    from graphplan.sheets.form import form
    *_, s = sheet51
    placed = {p.name: p for p in s.placed}
    for name in ("geometry", "quality", "train"):
        ys, cells = _rules_and_cells(placed[name].record)
        gaps = {round(a - b, 6) for a, b in zip(ys, ys[1:])}
        assert gaps == {7.0}, (name, gaps)
        assert cells and {q.size for q in cells} == {3.5}, name
        for q in cells:                   # the lettering within its row, clear of both rules
            b = q.bounds()
            row = [(a, c) for a, c in zip(ys, ys[1:]) if c <= q.points[0][1] <= a]
            assert row, (name, q.text)
            top, bottom = row[0]
            assert b[3] <= top - 0.3 and b[1] >= bottom + 0.3, (name, q.text, b, top, bottom)
    keep = keep_out(form("A1"))
    assert min(placed[n].record.bounds()[1] for n in ("geometry", "quality", "train", "notes")) >= keep[3]


@pytest.mark.slow
def test_the_english_a1_tables_letter_at_3_5_mm_too():
    """The English sheet's notes are a line or two longer: its tables took 2,5-mm letters before stop 51."""
    *_, s = _sheet(GEARS51, "GEARS51", "en")
    placed = {p.name: p for p in s.placed}
    for name in ("geometry", "quality", "train"):
        _, cells = _rules_and_cells(placed[name].record)
        assert {q.size for q in cells} == {3.5}, name


def test_table_2_prints_both_largest_slidings_to_one_count_of_decimals(sheet51):
    """Stop 51: Table 2 (and the terminal) printed «1,351» beside «1,42». Now both to the decimals that give
    the smaller four figures, equal to the closed form's λ1(B1), λ2(B2) (the largest |λ| on the working
    part: λ is monotonic along it) — and the interference row's millimetres to one count of decimals."""
    from graphplan.report.gears import gears_json, pair_lines
    from test_sheet_content import record_texts
    *_, s = sheet51
    c = pair_closed(14, 26, 0.008, 0.6, 0.55)
    cells = record_texts({p.name: p for p in s.placed}["quality"].record)
    want = [f"{abs(c['lam1_B1']):.3f}".replace(".", ","), f"{abs(c['lam2_B2']):.3f}".replace(".", ",")]
    assert want == ["1,351", "1,420"] and all(w in cells for w in want)
    rho_B2 = c["g"] - c["rho_B2"]
    assert f"{c['rho_B1'] * 1000:.2f} ≥ ".replace(".", ",") in "|".join(cells)
    assert f"{rho_B2 * 1000:.2f} ≥ ".replace(".", ",") in "|".join(cells)
    row = next(t for t in cells if t.startswith(f"{c['rho_B1'] * 1000:.2f}".replace(".", ",")))
    assert all(len(side.strip().split(",")[1]) == 2 for side in row.split("≥")), row
    sol, mesh, vel, _ = sheet51           # the terminal's lines of the same constructions
    text = "\n".join(pair_lines(gears_json(sol, mesh, vel, "")["pair"], "uk"))
    assert "|λ1| = 1,351, |λ2| = 1,420" in text      # (their magnitudes: λ1(B1) < 0)


def test_table_3_writes_the_neighbourhood_condition_out(sheet51):
    """Stop 51: Table 3's neighbourhood row read «36,77 > 35» — a number with no formula. Now it is
    written out, (z1 + z2)·sin(180°/K) = … > z2 + 2, computed here from the chosen teeth."""
    from test_sheet_content import texts
    sol, _, _, s = sheet51
    z1, z2, z3 = sol.train.z
    near = (z1 + z2) * math.sin(math.pi / 4)
    assert f"({z1} + {z2})·sin 45° = {near:.2f}".replace(".", ",") + f" > {z2 + 2}: викон." in texts(s)


def test_a_working_part_past_the_cut_of_the_lambda_diagram_prints_its_end_value():
    """GEARS_OWN51's 18/72: B1 lies 0,81 mm from N1, λ1(B1) = 1 − (ρ2/ρ1)(z1/z2) = −8,271 — under the diagram's
    cut at −3. The sheet drew the heavy working part into the cut's arrow lettered «−∞», which Table 2's
    8,271 contradicts. Now that arrow is lettered with the working end's value; the other keeps «−∞»."""
    from graphplan.graphic.gears import construct_mesh
    g, sol = _solved(GEARS_OWN51, "GEARS_OWN51")
    c = pair_closed(18, 72, 0.002, 0.0, 0.0)
    assert round(c["lam1_B1"], 3) == -8.271 and c["lam2_B2"] > -3
    mesh = construct_mesh(sol.pair, 0.5, "uk", module_mm=20.0)
    words = [q.text for q in mesh.lam.items if q.kind == "text"]
    assert "λ_1(B_1) = −8,271" in words and words.count("−∞") == 1
    mesh = construct_mesh(sol.pair, 0.5, "en", module_mm=20.0)
    assert "λ_1(B_1) = −8.271" in [q.text for q in mesh.lam.items if q.kind == "text"]


def test_the_carriers_letter_stands_clear_of_the_suns_projection_line():
    """GEARS_OWN51's train 29/31/91 at m = 2,5 mm: the carrier's letter H, set midway up its arm (yO2/2 =
    37,5 mm), sat on the dashed projection line of the sun's pitch point (r1 = 36,25 mm) that runs across the
    arm to the velocity picture (overprint.py: 1 word). Now it stands clear of it: the letter's box meets no
    projection line."""
    from graphplan.graphic.gears import construct_train
    g, sol = _solved(GEARS_OWN51, "GEARS_OWN51")
    assert (sol.train.z[0] * 2.5 / 2, (sol.train.z[0] + sol.train.z[1]) * 2.5 / 2) == (36.25, 75.0)
    v = construct_train(sol.train, 0.5, "uk", ring_mm=110.0)
    rec = v.record
    lines = [q for q in rec.items if q.kind == "segment" and q.role == "projection"]
    hs = [q for q in rec.items if q.kind == "text" and q.text == "H"]
    assert lines and hs
    for h in hs:
        b = h.bounds()
        for q in lines:
            (ax, ay), (bx, by) = q.points
            if abs(ay - by) < 1e-9 and min(ax, bx) <= b[2] and max(ax, bx) >= b[0]:
                assert not (b[1] - 0.2 <= ay <= b[3] + 0.2), (b, ay)
