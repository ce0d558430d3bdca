"""The kinematics sheet's diagrams read at the positions (the second review, items 2, 3 and 6): the
values the diagrams give at the plans' positions are within the lab's 5 % of the exact (of |max| near
a zero) or the notes name each miss; the readings table prints what the drawing shows; a rocker's
diagrams carry the tables' sign and the notes speak of φ3, ω3, ε3."""
from __future__ import annotations

import re

import numpy as np
import pytest

import review_scenes
from conftest import example, scene_study
from test_sheets_composition import printed  # a cell printing a value to its own decimals
from graphplan.drawing.diagrams import draw
from graphplan.graphic.diagrams import chord_diagrams, judged_pct
from graphplan.report.diagrams import NAMED, sheet_notes
from graphplan.report.plans import plans_json
from graphplan.sheets.compose import SheetOptions
from graphplan.sheets.form import form
from graphplan.sheets.kinematics import plan
from graphplan.sheets.kintables import diagram_readings, notes_lines, printed_frame, printed_readings, readings_table


def sheet_parts(st, lang="en"):
    """The A1 kinematics sheet's plans and diagrams (what it draws and tabulates)."""
    p, _, dr = plan(st, form("A1"), SheetOptions())
    return dr.plans(p.mu), dr.diagrams(p.diagrams, lang)


def drawn_ordinate(rec, sym: str, x: float) -> float:
    """The ordinate (mm) of the curve ``sym``(t) at abscissa x, over its time axis, off the drawing."""
    curve = next(p for p in rec.items if p.kind == "polyline" and p.step == f"{sym}(t)")
    axis = next(p for p in rec.items if p.kind == "vector" and p.step == f"axes of {sym}(t)"
                and abs(p.points[0][1] - p.points[1][1]) < 1e-9)
    xs, ys = np.array(curve.points).T
    return float(np.interp(x, xs, ys)) - axis.points[0][1]


@pytest.fixture(scope="module")
def coulisse():
    return scene_study(review_scenes.COULISSE)


@pytest.fixture(scope="module")
def rocker():
    return scene_study(review_scenes.FOURBAR)


def test_the_table_prints_what_the_drawing_shows(coulisse):
    """Each value of the readings table is the curve's ordinate at the position, measured on the drawn
    record (±half a ruler division: the ordinate read), times the diagram's scale."""
    plans, d = sheet_parts(coulisse)
    rec = draw(d, "en")
    rows = diagram_readings(d, plans_json(plans))
    assert [r["position"] for r in rows] == list(range(coulisse.mech.task.count))
    texts = {p.text for p in readings_table(d, plans_json(plans), "en", 9).items if p.kind == "text"}
    for r, k in zip(rows, d.at_positions):
        for key, sym, mu in (("s", d.symbols[0], d.mu_s), ("v", d.symbols[1], d.mu_v), ("a", d.symbols[2], d.mu_a)):
            got = d.sign * drawn_ordinate(rec, sym, d.x[k]) * mu
            assert abs(r[key] - got) <= (d.precision / 2 + 0.05) * mu, (key, r["position"])
            # the table writes it as drawn: from the extreme position 0, + the way it grows (stop 49)
            assert printed(d.sign * r[key], texts), (key, r["position"])
        truth = d.truth["a_at"][k]
        assert r["delta_a"] == pytest.approx(float(judged_pct(r["a"], truth, d.maxima["a"])))


def test_the_coulisse_a_diagram_no_longer_contradicts_its_plan_silently(coulisse):
    """The review: a_C at position 3 read 25.7 m/s² off the diagram (−22.3 %) against 33.25 on the
    plan, and nothing said so. Now the drawing is the closest the lab allows, and each position still
    past 5 % is named in the notes with its δ."""
    plans, d = sheet_parts(coulisse)
    rows = {r["position"]: r for r in diagram_readings(d, plans_json(plans))}
    assert abs(rows[3]["delta_a"]) < 15.0 and rows[3]["a_plan"] == pytest.approx(33.1, rel=0.02)
    notes = " ".join(sheet_notes(d, "en"))
    for n, r in rows.items():
        for key in ("delta_s", "delta_v", "delta_a"):
            # the two worst a diagram (report.diagrams.NAMED; Table 5 marks every one past 5 %)
            if abs(r[key]) > 5.0 and abs(r[key]) >= sorted(abs(q[key]) for q in rows.values())[-NAMED]:
                assert f" {n} (" in notes, (n, key, notes)
    assert "exceed the 5 % the lab allows" in notes
    rd = d.redrawn           # the sheet states the drawing's largest |δ| (not the search's before → after)
    assert "→" not in notes
    assert (f"largest |δ| {rd.off_after:.2f} %" in notes) == (not rd.wrong_before)


@pytest.mark.parametrize("name", ["crank_slider", "four_bar", "lab_crank_slider"])
def test_examples_within_five_percent_or_said(name):
    st = example(name)
    _, d = sheet_parts(st)
    worst = max(float(np.max(np.abs(e))) for e in d.position_errors().values())
    notes = " ".join(sheet_notes(d, "en"))
    assert (worst > 5.0) == ("exceed the 5 % the lab allows" in notes)
    if name == "crank_slider":          # a smooth curve: within 5 % at every position
        assert worst <= 5.0


def test_a_rocker_is_drawn_from_its_extreme_position(rocker):
    """The four-bar's rocker swings clockwise from position 0: ψ3 is drawn rising from the extreme
    position (seed 002's displacement, stop 49), its ω3 on the diagram opposite Table 1's sign (ω_O2B,
    + counter-clockwise) at every position where the plan reads it, and the notes say both senses;
    they name ψ3, ω3, ε3, not s, v, a."""
    plans, d = sheet_parts(rocker, "uk")
    assert d.output.kind == "link" and d.sign == -1
    rec = draw(d, "uk")
    rows = diagram_readings(d, plans_json(plans))
    signs = 0
    for r, k in zip(rows, d.at_positions):
        assert d.drawn.s[k] >= -d.precision          # the ψ3 ordinate read off the drawing, mm
        if r["v_plan"] and abs(r["v_plan"]) > 0.1 * d.maxima["v"]:
            assert np.sign(r["v"]) == np.sign(r["v_plan"]) == -np.sign(drawn_ordinate(rec, d.symbols[1], d.x[k]))
            signs += 1
    assert signs >= 8
    text = " ".join(notes_lines(rocker, plans, d, "uk", 0.5))
    assert "ψ_{3} — кут повороту ланки O_{2}B від крайнього положення 0" in text   # a rocker's angle: ψ, its link O₂B
    assert "+ за годинниковою стрілкою" in text and "+ проти годинникової стрілки" in text
    assert "s, v, a" not in text and "−s" not in text


def test_the_terminal_judges_a_reading_near_a_zero_as_the_sheet_does():
    """The fourth review's item 14: `diagrams` printed a at position 4 as −948,96 % off (0,384 read
    where the exact is −0,045) while the sheet's Table 4 printed 3,57 % of |max|. The JSON positions
    now carry error_pct_judged — of the exact value where |exact| ≥ 10 % of the cycle's |max|, else
    of |max| — and the text table prints it; checked against the rule worked out here."""
    import numpy as np

    from conftest import ROOT
    from graphplan import api
    doc = api.diagrams(str(ROOT / "examples" / "crank_slider.toml")).to_json()
    for key in ("v", "a"):
        cells = [p[key] for p in doc["positions"]]
        big = max(abs(c["analytic"]) for c in cells)
        near = 0
        for c in cells:
            if abs(c["analytic"]) >= 0.1 * big:
                assert c["error_pct_judged"] == pytest.approx(100 * (c["value"] - c["analytic"]) / c["analytic"])
            else:
                near += 1
                assert c["error_pct_judged"] == pytest.approx(100 * (c["value"] - c["analytic"]) / big, abs=0.02)
        assert np.isfinite([c["error_pct_judged"] for c in cells]).all()
        assert near >= 1 or key == "a"        # a dead centre: v ≈ 0 there


def test_the_notes_percents_are_the_tables():
    """An inclined compressor's a_B at 8 missed 5 % by −5,01 % in Table 5 while the notes said
    "(−5,0 %)", and "у положеннях 16,8 → 5,0 %" read as positions 16 and 8: the notes now give every
    δ with the tables' two decimals, each with its % sign."""
    from test_kin_drafting import INCLINED
    st = scene_study(INCLINED.replace('[positions]', '[positions]\naccel = [3, 8]'))
    for lang in ("uk", "en"):
        p, nat, dr = plan(st, form("A1"), SheetOptions(sheet="kinematics", lang=lang))
        diag = dr.diagrams(p.diagrams, lang)
        doc = plans_json(dr.plans(p.mu))
        cells = set()       # δ as the table prints it: of the printed pair, in the diagrams' sense (review 54 #1)
        for r in printed_readings(diag, doc, lang, 0.5):
            for key in ("delta_v", "delta_a"):
                if r[key] is not None:
                    cells.add(f"{r[key]:+.2f}".replace("-", "−"))
        for r in diagram_readings(diag, doc):   # s: no δ column; the note's s in the table's sense
            cells.add(f"{printed_frame(r, diag.sign, diag.maxima)['delta_s']:+.2f}".replace("-", "−"))
        notes = " ".join(notes_lines(st, dr.plans(p.mu), diag, lang, 0.5))
        said = re.findall(r"\(([−+]\d+[.,]\d+) %\)", notes)
        assert said, notes
        assert all(s.replace(",", ".") in cells for s in said), (said, notes)
        assert not re.search(r"(positions|положеннях) \d+[.,]\d+ →", notes), notes
        largest = max(abs(float(c.replace("−", "-"))) for c in cells if c.lstrip("+−") != "nan")
        for quoted in re.findall(r"\|δ\| (\d+[.,]\d+) %", notes):   # the redrawing's line: the table's figure
            assert float(quoted.replace(",", ".")) == pytest.approx(largest, abs=0.005), (quoted, largest, notes)


def test_the_largest_printed_delta_skips_what_the_table_does_not_print():
    """The redrawing's line quotes the largest |δ| of v and a as the table prints them (NaN where it
    prints none; s has no δ column): the crusher's ε₅ −7,66 in Table 4 was quoted 7,67 (the search's
    unrounded figure) in the line above the one quoting the table."""
    from graphplan.report.diagrams import _largest_printed
    got = _largest_printed({"v_at": np.array([1.0, np.nan, -2.5]), "a_at": np.array([np.nan, -7.66, 3.0])})
    assert got == pytest.approx(7.66)
    assert _largest_printed({"v_at": np.array([np.nan])}) is None and _largest_printed(None) is None


@pytest.mark.slow
def test_the_crushers_redrawing_line_quotes_table_4s_largest_delta():
    """LINK54 (review 54): the notes' «найбільша |δ| X %» is Table 4's largest printed |δ| (7,66)."""
    st = scene_study(review_scenes.LINK54)
    p, _, dr = plan(st, form("A1"), SheetOptions(sheet="kinematics", lang="uk"))
    diag = dr.diagrams(p.diagrams, "uk")
    cells = [abs(r[k]) for r in printed_readings(diag, plans_json(dr.plans(p.mu)), "uk", 0.5)
             for k in ("delta_v", "delta_a") if r[k] is not None]
    notes = " ".join(notes_lines(st, dr.plans(p.mu), diag, "uk", 0.5))
    quoted = re.findall(r"\|δ\| (\d+,\d+) %", notes)
    assert quoted and all(float(q.replace(",", ".")) == pytest.approx(max(cells), abs=0.005) for q in quoted), notes
