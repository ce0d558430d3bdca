"""Stop 54 (kinematics): the jaw crusher (LINK54) — the tables' column leaves no blank zone where a
composition drawing no smaller has none (LAYOUT.md: no big empty areas), and the diagrams' advice
names a sharp bend only where the chords' own error is what misses the lab's 5 %."""
from __future__ import annotations

import pytest

import review_scenes
from conftest import scene_study
from graphplan.graphic.diagrams import LAB_LIMIT, chord_diagrams, why_not


@pytest.mark.parametrize("name, kw", [
    ("INCLINED_ROCKER53", dict(L=240.0, H1=42.0, H2=34.0, height=80.0, correct=True)),
    ("INCLINED_ROCKER53", dict(L=240.0, H1=42.0, H2=34.0, height=80.0, correct=True, divisions=8)),
])
def test_a_sharp_bend_is_named_only_where_the_chords_own_error_misses_the_limit(name, kw):
    """The exact drawing's largest |δ| at the positions (the chords' own error, ruler 0) decides:
    the inclined crank-slider's a reads 8.3 % at 12 divisions with the 0.5-mm ruler, 1.0 % exact —
    the ruler's, not a bend's; at 8 divisions (45° steps) its chords alone read 7.8 %."""
    d = chord_diagrams(scene_study(getattr(review_scenes, name)), precision=0.5, lang="en", **kw)
    own = d.worst_pct(d.exact)
    text = why_not(d, "en")
    assert "own error" in text          # more divisions read worse here: the advice says why
    assert ("a bend sharp" in text) == (own > LAB_LIMIT)
    assert ("згин, крутий" in why_not(d, "uk")) == (own > LAB_LIMIT)


def _apart(a, b) -> bool:
    return a[2] <= b[0] + 1e-6 or b[2] <= a[0] + 1e-6 or a[3] <= b[1] + 1e-6 or b[3] <= a[1] + 1e-6


def test_accel_column_sets_the_acceleration_plan_over_the_tables_over_the_notes():
    """The "accel-column" composition (the jaw crusher's A1): the position plan over the diagrams
    (left), the velocity plans the field's whole height, and in the right column in reading order
    the acceleration plan at the top, the tables under it, the notes at the foot (over the title
    block's room); the column's spare height between them, none of it in one piece under the tables;
    every box in the field, none meeting another."""
    from graphplan.drawing.layout import Grid, Leaf, arrange
    from graphplan.sheets.kinlayout import tree
    field = (0.0, 0.0, 806.0, 574.0)
    P, D = Leaf("position", 218.0, 280.0), Leaf("diagrams", 358.0, 280.0)
    V = [Leaf(f"v{i}", 62.0, 60.0) for i in range(12)]
    A = [Leaf("a", 207.0, 78.0)]
    T, N = Leaf("tables", 250.0, 270.0), Leaf("notes", 245.0, 206.0)
    got = {leaf.name: b for leaf, b in arrange(tree("accel-column", P, D, Grid(V, 2, fitted=True),
                                                    Grid(A, 1, fitted=True), None, (T, N)), field)}
    for b in got.values():
        assert field[0] - 1e-6 <= b[0] and b[2] <= field[2] + 1e-6 and field[1] - 1e-6 <= b[1] and b[3] <= field[3] + 1e-6
    names = list(got)
    assert all(_apart(got[m], got[n]) for i, m in enumerate(names) for n in names[i + 1:])
    a, t, n = got["a"], got["tables"], got["notes"]
    assert abs(a[3] - field[3]) < 1e-6 and a[1] >= t[3] - 1e-6 and t[1] >= n[3] - 1e-6
    assert abs(n[1] - field[1]) < 1e-6 and abs(t[2] - field[2]) < 1e-6
    spare = field[3] - field[1] - (A[0].h + T.h + N.h)
    assert (t[1] - n[3]) < spare and (a[1] - t[3]) > 0.0      # shared out, not all under the tables
    assert abs(got["v0"][3] - field[3]) < 1e-6 and abs(got["v11"][1] - field[1]) < 1e-6


@pytest.mark.slow
def test_link54_a1_leaves_no_blank_under_its_tables_that_holds_its_acceleration_plan():
    """The jaw crusher's A1: its tables (two columns under Table 1, 250 × 270 mm) and notes left
    250 × 92 mm blank between them while the acceleration plan, 177 × 70 mm, stood under the
    velocity plans. Now no blank of the field (off every drawing's, table's and the notes' ink and
    the title block) holds the acceleration plan with 5 mm around it."""
    import numpy as np

    from graphplan.sheets.compose import SheetOptions, field_of, keep_out
    from graphplan.sheets.form import form
    from graphplan.sheets.kinematics import build_kinematics_sheet
    from test_kin_review47 import _holds
    f = form("A1")
    sheet = build_kinematics_sheet(scene_study(review_scenes.LINK54), f, SheetOptions(lang="uk"))
    x0, y0, x1, y1 = field_of(f)
    cell = 2.0
    free = np.ones((int((y1 - y0) / cell), int((x1 - x0) / cell)), dtype=bool)

    def block(b) -> None:
        i0, i1 = int((b[0] - x0) // cell), int(np.ceil((b[2] - x0) / cell))
        j0, j1 = int((b[1] - y0) // cell), int(np.ceil((b[3] - y0) / cell))
        free[max(j0, 0):max(j1, 0), max(i0, 0):max(i1, 0)] = False
    accel = None
    for p in sheet.placed:
        block(p.record.bounds())
        if p.name.startswith("acceleration plan"):
            accel = p.record.bounds()
    block(keep_out(f))
    assert accel is not None
    w, h = int(np.ceil((accel[2] - accel[0] + 10.0) / cell)), int(np.ceil((accel[3] - accel[1] + 10.0) / cell))
    assert not _holds(free, w, h)


def test_a_centre_of_mass_on_its_pivot_is_lettered_with_it():
    """Review 54 #12: the jaw crusher's crank has S1 = 0 (its centre of mass on the pivot O1). The
    position plan letters the one point once, "O₁, S₁" at O₁ (as the velocity plan letters the points
    at its pole "p_v, s₁"), not a separate S₁ up and left of O₁ on the crank's line; the crank's pin
    A (S1 ≠ A) keeps its own letter."""
    from graphplan.drawing.plans import position_record
    from graphplan.graphic.plans import build_plans
    st = scene_study(review_scenes.LINK54)
    plans = build_plans(st, precision=0.5)
    words = [p.text for p in position_record(plans).items if p.kind == "text"]
    assert "O_1, S_1" in words
    assert "S_1" not in words and "O_1" not in words
    assert any(w == "A" or w.startswith("A_{") for w in words)


def test_the_notes_say_in_one_sentence_why_twice_the_divisions_are_not_drawn():
    """Review 54 #2/#9: a diagram past 5 % kept at 12 divisions. The inclined crank-slider's a reads
    8.3 % at 12 divisions; drawn on 24 (measured here, a construction of its own) it reads worse
    (the ruler's half division over half the step). The sheet's note says so in one plain sentence
    with that measured |δ|, and narrates no search (no arrow between trial numbers)."""
    from graphplan.report.diagrams import short_limit_note
    kw = dict(L=240.0, H1=42.0, H2=34.0, height=80.0, correct=True)
    st = scene_study(review_scenes.INCLINED_ROCKER53)
    d = chord_diagrams(st, precision=0.5, lang="en", **kw)
    d24 = chord_diagrams(st, precision=0.5, lang="en", **{**kw, "divisions": 24})
    import numpy as np
    # at the 12 positions the first drawing reads (every second division of the 24)
    worse = max(float(np.max(np.abs(e[::2]))) for e in d24.position_errors().values())
    assert worse > d.worst_pct() > LAB_LIMIT
    en, uk = short_limit_note(d, "en"), short_limit_note(d, "uk")
    assert "24 divisions read " in en and "the ruler errs more" in en and "→" not in en
    said = float(en.split("24 divisions read ")[1].split(" %")[0])
    assert said == pytest.approx(worse, abs=0.6)
    assert "24 поділки дають " in uk and "похибка лінійки" in uk
