"""What `graphplan diagrams` and the sheet's notes advise where the values read off the diagrams miss
the lab's 5 %: only what was tried and measured to do better (review 9: the terminal suggested
--adaptive for a crank-rocker's ε3 where it read no better, and more divisions where they read far
worse)."""
from __future__ import annotations

import numpy as np
import pytest

import review_scenes
from conftest import scene_study
from graphplan.graphic.diagrams import LAB_LIMIT, chord_diagrams, judged_pct
from graphplan.report.diagrams import sheet_notes
from graphplan.sheets.kinematics import diagram_options
from graphplan.sheets.kinlayout import room
from graphplan.sheets.form import form


@pytest.fixture(scope="module")
def rocker():
    return scene_study(review_scenes.ROCKER9)


@pytest.fixture(scope="module")
def sheet_diagrams(rocker):
    """The crank-rocker's diagrams as its A1 sheet draws them (graphic.redraw's choice)."""
    options = diagram_options(rocker, 1.0, None, 0.5, room(form("A1")))
    rd = options.pop("redrawn")
    return chord_diagrams(rocker, precision=0.5, redrawn=rd, **options), options


def worst_at(d, every: int = 1) -> float:
    """The largest |δ| at every ``every``-th division ordinate (the positions of a drawing with
    ``every`` times the divisions), computed here from the values and the analytic truth."""
    k = list(range(0, d.divisions, every))
    vals = d.values()
    return max(float(np.max(np.abs(judged_pct(vals[key][k], d.truth[key][k], d.maxima[key[0]]))))
               for key in ("s", "v_at", "a_at"))


def test_each_trial_is_what_its_option_draws(sheet_diagrams, rocker):
    """The trials' numbers are those of the drawing the named option makes (independently drawn
    here by ``chord_diagrams`` and judged at the same positions)."""
    d, options = sheet_diagrams
    base = {k: options[k] for k in ("L", "H1", "H2", "height", "fit") if k in options}   # fit: μs = s_max/h
    trials = {t.key: t for t in d.alternatives()}
    assert {"double", "tangents"} <= set(trials)
    double = chord_diagrams(rocker, precision=0.5, divisions=2 * d.divisions, correct=d.correct, **base)
    assert trials["double"].worst_pct == pytest.approx(worst_at(double, 2), abs=1e-9)
    tangents = chord_diagrams(rocker, precision=0.5, method="tangents", **base)
    assert trials["tangents"].worst_pct == pytest.approx(worst_at(tangents), abs=1e-9)
    if "correct" in trials:
        corrected = chord_diagrams(rocker, precision=0.5, correct=True, **base)
        assert trials["correct"].worst_pct == pytest.approx(worst_at(corrected), abs=1e-9)
    if "adaptive" in trials:
        adaptive = chord_diagrams(rocker, precision=0.5, adaptive=True, **base)
        assert trials["adaptive"].worst_pct == pytest.approx(adaptive.worst_pct(), abs=1e-9)


def test_the_advice_names_only_what_reads_better(sheet_diagrams):
    """ε3 misses 5 %; the advice names no option that reads no better, and says none reaches 5 %
    where none does, with why more divisions read worse (measured: the exact drawing improves, the
    drawing with the ruler does not)."""
    d, _ = sheet_diagrams
    w0 = d.worst_pct()
    assert w0 > LAB_LIMIT
    advice = next(w for w in d.warnings if w["kind"] == "advice")
    trials = d.alternatives()
    for t in trials:
        if t.option and t.option in advice["message"]:
            assert t.worst_pct < w0 or "none of the constructions tried" in advice["message"], t
    if all(t.worst_pct > LAB_LIMIT for t in trials):
        assert "5 %" in advice["message"] and "within 5 %" not in advice["message"]
    double = next(t for t in trials if t.key == "double")
    if double.worst_pct > w0:
        assert "--adaptive" not in advice["message"] and "amplified by the smaller step" in advice["message"]
        assert double.exact_pct < d.worst_pct(d.exact)       # the chords alone would do better
    # no other warning suggests the untried: the chord error's and the qualitative's advice measured
    for w in d.warnings:
        assert "(--adaptive) or more divisions" not in w["message"] and "take more divisions" not in w["message"]
        assert "більше поділок" not in w["message_uk"] or w["kind"] == "qualitative"


@pytest.mark.parametrize("lang", ["en", "uk"])
def test_the_sheet_note_says_what_was_tried(sheet_diagrams, lang):
    """The sheet's note is short (stop 48: the long one, every trial's number, was hard to read; the
    terminal keeps it): the worst readings with their δ, one measured cause a symbol — the same
    drawing with an exact ruler (the chords' own error) past 5 % at the worst reading, else the
    ruler on s alone — and whether any construction tried reaches 5 %."""
    from graphplan.graphic.diagrams import ruler_on_s
    d, _ = sheet_diagrams
    note = next(n for n in sheet_notes(d, lang) if "5 %" in n and ("tried" in n or "випробувана" in n))
    errs, own, on_s = d.position_errors(), d.position_errors(d.exact), ruler_on_s(d)
    comma = (lambda x: x.replace(".", ",")) if lang == "uk" else (lambda x: x)
    for key in ("v_at", "a_at"):
        if np.max(np.abs(errs[key])) <= LAB_LIMIT:
            continue
        worst = int(np.argmax(np.abs(errs[key])))
        assert comma(f"{abs(errs[key][worst]):.2f} %") in note
        chords = abs(own[key][worst]) > LAB_LIMIT
        cause = own[key][worst] if chords or abs(on_s[key][worst]) <= LAB_LIMIT else on_s[key][worst]
        assert comma(f"{abs(cause):.1f} %") in note
        assert (("own error" in note) if lang == "en" else ("власна похибка" in note)) or not chords
    if all(t.worst_pct > LAB_LIMIT for t in d.alternatives()):
        assert ("no other construction tried keeps within 5 %" in note) if lang == "en" else ("не вкладається в 5 %" in note)
    assert "_" not in note.replace("_{", "") and "^" not in note
    # about three lines of the notes' column, not six — and, where twice the divisions read worse, the
    # one sentence saying so (review 54 #2/#9: why 12 divisions are kept)
    # … and, where the readings past 5 % are small values by an extreme position (issue 32 #2: ω3 at 7 is
    # 17 % of |max|), the parenthesis saying so with their share of |max| (stop 57)
    small = "of |max|)" in note or "від |max|" in note
    assert len(note) < 330 + (70 if "24 divisions read" in note or "24 поділки дають" in note else 0) \
        + (100 if small else 0), note


def test_a_drawing_within_five_percent_gets_no_advice():
    st = scene_study(review_scenes.COMPRESSOR42)
    options = diagram_options(st, 1.0, None, 0.5, room(form("A1")))
    rd = options.pop("redrawn")
    d = chord_diagrams(st, precision=0.5, redrawn=rd, **options)
    assert d.worst_pct() <= LAB_LIMIT
    assert not [w for w in d.warnings if w["kind"] == "advice"]
