"""Diagrams redrawn until qualitatively right (graphic.redraw): the sheet and `graphplan diagrams`
without options carry no "qualitatively wrong" note that the area correction, other pole distances or
smaller intervals would remove; where one of them does, the notes say what was changed."""
from __future__ import annotations

import json

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, example, given, settings
from hypothesis import strategies as st_

import random_mechanisms as rm
from conftest import ROOT, scene_study
from conftest import example as example_study
from graphplan.cli.main import main
from graphplan.graphic.diagrams import chord_diagrams
from graphplan.graphic.redraw import READABLE_MM
from graphplan.report.diagrams import sheet_notes
from graphplan.sheets.form import form
from graphplan.sheets.kinematics import diagram_options, first_options
from graphplan.sheets.kinlayout import room
from graphplan.util.errors import GraphplanError

A1_ROOM = room(form("A1"))            # where the A1 sheet lets a redrawn diagrams' block go


def wrong(d) -> list[str]:
    return [w["diagram"] for w in d.warnings if w["kind"] == "qualitative"]


# what a student may redraw with (the lab's 15–50 mm poles, the correction, smaller intervals)
ALTERNATIVES = ([{"correct": True}, {"adaptive": True}, {"adaptive": True, "correct": True}]
                + [{"H1": h1, "H2": h2} for h1 in (15.0, 30.0, 50.0) for h2 in (15.0, 30.0, 50.0)])


def check_sheet_diagrams(st, k: float = 1.0) -> str:
    """The sheet's diagrams at size factor k: right, or no alternative makes them right; the notes
    say what was redrawn. Returns "first", "redrawn" or "kept"."""
    options = diagram_options(st, k, None, 0.5, A1_ROOM)
    rd = options.pop("redrawn")
    d = chord_diagrams(st, precision=0.5, redrawn=rd, **options)
    notes = " ".join(sheet_notes(d, "en"))
    # the values read at the positions: within the lab's 5 % (of |max| near a zero), or the notes say
    # which miss it; the search measured the very drawing the sheet draws
    errs = d.position_errors()
    worst = max(float(np.max(np.abs(e))) for e in errs.values())
    assert rd.off_after == pytest.approx(worst, abs=1e-9)
    assert ("exceed the 5 % the lab allows" in notes) == (worst > 5.0), (worst, notes)
    if rd.changed and not rd.wrong_before:
        # redrawn for its errors at the positions alone: no flatter than READABLE_MM (20 mm: the ruler's
        # 0.5 mm is then 2.5 % of the peak, half the lab's 5 %) or, where the first drawing was lower,
        # than the first drawing (review 10's six-bar: H1 = H2 = 15 mm drew v 11 mm and a 5 mm high)
        first = first_options(st, k)
        was = chord_diagrams(st, precision=0.5, **first).drawn
        for got, before in ((d.drawn.v, was.v), (d.drawn.a, was.a)):
            assert np.max(np.abs(got)) >= min(READABLE_MM, first["height"] / 2, np.max(np.abs(before))) - 0.5, rd
    if not wrong(d):
        assert "qualitatively wrong" not in notes
        if rd.wrong_before:                       # the first drawing was wrong: say what changed
            first = first_options(st, k)
            assert wrong(chord_diagrams(st, precision=0.5, **first)), "the first drawing was right"
            assert "chosen so that" in notes and rd.changed and "(not " not in notes
            for key, value in rd.changed.items():
                assert options[key] == value and first.get(key, False) != value
            return "redrawn"
        return "first"
    assert not rd.right and "redrawings the lab allows and the sheet holds" in notes
    base = {key: options[key] for key in ("divisions", "L", "H1", "H2", "height")}
    dg = st.mech.task.diagram
    for alt in ALTERNATIVES:
        if any(f"{key}_mm" in dg for key in alt if key in ("H1", "H2")):
            continue                              # the scene's own pole distances stay
        assert wrong(chord_diagrams(st, precision=0.5, **{**base, **alt})), alt
    return "kept"


# the default run draws a few cases of each sweep (each a redrawing search and its alternatives, 1–4 s;
# twelve of each took 90 s of the suite on two cores), the slow run the long sweeps (``…_many``)
FAST = settings(max_examples=4, deadline=None, derandomize=True, database=None,   # the same cases every run (CI)
                suppress_health_check=[HealthCheck.too_slow])
LONG = settings(max_examples=30, deadline=None, derandomize=True, database=None,
                suppress_health_check=[HealthCheck.too_slow])
omega = st_.sampled_from([-30.0, 7.5, 100.0])
branch = st_.sampled_from([1, -1])


OFFSET_SLIDERS = dict(r=st_.floats(0.02, 0.1), l=st_.floats(0.08, 0.5), e=st_.floats(-0.05, 0.05),
                      ang=st_.sampled_from([0.0, 30.0, 90.0]), w=omega, b=branch)
FOUR_BARS = dict(r=st_.floats(0.02, 0.1), d=st_.floats(0.15, 0.4), l2=st_.floats(0.05, 0.5),
                 l3=st_.floats(0.05, 0.5), w=omega, b=branch)


def check_offset_slider(r, l, e, ang, w, b) -> None:
    text, ok = rm.rrp(r, l, e, ang, w, b)
    assume(ok)
    check_sheet_diagrams(scene_study(text))


def check_four_bar(r, d, l2, l3, w, b) -> None:
    text, ok = rm.rrr(r, d, l2, l3, w, b)
    assume(ok)
    try:
        st = scene_study(text)
    except GraphplanError:
        assume(False)
    check_sheet_diagrams(st)


@FAST
@given(**OFFSET_SLIDERS)
def test_offset_crank_slider_diagrams_are_right_or_cannot_be(r, l, e, ang, w, b):
    check_offset_slider(r, l, e, ang, w, b)


@pytest.mark.slow
@LONG
@given(**OFFSET_SLIDERS)
def test_offset_crank_slider_diagrams_are_right_or_cannot_be_many(r, l, e, ang, w, b):
    check_offset_slider(r, l, e, ang, w, b)


@FAST
@given(**FOUR_BARS)
# found by the fuzz: ε wrong at H1 39 / H2 20, right at H1 = H2 = 50 mm but 2.5 times as tall as the room
# allows — drawn right over a lower s diagram (redraw.lower), no longer "no redrawing makes it right"
@example(r=0.07410053556313063, d=0.3126182027418761, l2=1 / 3, l3=0.1193980924402145, w=-30.0, b=1)
def test_four_bar_diagrams_are_right_or_cannot_be(r, d, l2, l3, w, b):
    check_four_bar(r, d, l2, l3, w, b)


@pytest.mark.slow
@LONG
@given(**FOUR_BARS)
def test_four_bar_diagrams_are_right_or_cannot_be_many(r, d, l2, l3, w, b):
    check_four_bar(r, d, l2, l3, w, b)


@pytest.mark.slow
@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(r=st_.floats(0.02, 0.06), d=st_.floats(0.2, 0.3), l2=st_.floats(0.2, 0.35), l3=st_.floats(0.15, 0.3),
       l4=st_.floats(0.3, 0.6), alpha=st_.floats(-60, 60), w=omega, b=branch, k=st_.sampled_from([1.0, 0.5]))
def test_six_bar_diagrams_are_right_or_cannot_be(r, d, l2, l3, l4, alpha, w, b, k):
    text, ok = rm.rrp_moving(r, d, l2, l3, l4, alpha, w, b)
    assume(ok)
    try:
        st = scene_study(text)
    except GraphplanError:
        assume(False)
    check_sheet_diagrams(st, k)


# an offset crank-slider whose a diagram, drawn as the sheet first chose it (H2 = 30 mm), has a max
# and a min the motion lacks near the outer dead centre: the sheet redraws it with a larger pole
OFFSET = (0.0962, 0.31, -0.0041, 30, 100.0, -1)


def test_the_offset_crank_slider_is_redrawn_with_a_larger_pole():
    st = scene_study(rm.rrp(*OFFSET)[0])
    first = first_options(st, 1.0)
    assert wrong(chord_diagrams(st, precision=0.5, **first)) == ["a"]
    assert check_sheet_diagrams(st) == "redrawn"
    options = diagram_options(st, 1.0, None, 0.5, A1_ROOM)
    changed = options["redrawn"].changed
    assert changed and all(15.0 <= options[h] <= 50.0 for h in ("H1", "H2"))


def test_terminal_diagrams_draw_what_the_sheet_draws(tmp_path, capsys):
    """`graphplan diagrams` without options: the sheet's redrawn diagrams, the JSON saying how."""
    scene = tmp_path / "offset.toml"
    scene.write_text(rm.rrp(*OFFSET)[0], encoding="utf-8")
    assert main(["diagrams", str(scene), "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    # the sheet's own choice (kin61b: since stop 60 the A1 draws this slider's s taller, ``finer_s``, where the
    # first drawing is right and is redrawn for its errors at the positions alone — wrong_before is then [])
    from graphplan.sheets.kinematics import sheet_scales
    sheet = sheet_scales(scene_study(rm.rrp(*OFFSET)[0]), "A1")["diagrams"]["redrawn"].to_json()
    assert doc["redrawn"]["wrong_before"] == sheet["wrong_before"] and doc["redrawn"]["changed"] == sheet["changed"]
    assert doc["redrawn"]["wrong_after"] == []
    assert not [w for w in doc["warnings"] if w["kind"] == "qualitative"]
    assert doc["redrawn"]["changed"] and doc["redrawn"]["worst_pct_after"] <= doc["redrawn"]["worst_pct_before"]
    for key, value in doc["redrawn"]["changed"].items():
        if key in ("H1", "H2"):
            assert doc[f"{key}_mm"] == value != doc["redrawn"]["before"][key]
    # an option given: the drawing as asked, no search
    before = doc["redrawn"]["before"]
    h1, h2 = (before.get(h, doc[f"{h}_mm"]) for h in ("H1", "H2"))
    assert main(["diagrams", str(scene), "--json", "--h1", str(h1), "--h2", str(h2)]) == 0
    asked = json.loads(capsys.readouterr().out)
    assert asked["redrawn"] is None
    assert bool([w for w in asked["warnings"] if w["kind"] == "qualitative"]) == bool(sheet["wrong_before"])
    assert main(["diagrams", str(scene)]) == 0
    assert "побудовано заново: " in capsys.readouterr().out


@pytest.mark.parametrize("name", ["crank_slider", "four_bar", "shaper", "slotter", "lab_crank_slider"])
def test_examples_on_the_a1_sheet(name):
    assert check_sheet_diagrams(example_study(name)) in ("first", "redrawn")


def test_a_diagram_nothing_helps_keeps_its_note():
    """A slotted link turning round (crank 0.1 m, pivots 0.048 m apart): ω varies little over half
    the turn and the 0.5-mm ruler's steps show as extrema on ω and ε at any pole distance — the note
    stays, and says that nothing the lab allows helped."""
    st = scene_study(rm.rpr(0.09974448205344037, 0.04751486107644167, -0.002773214388349255, -5.0, 1)[0])
    assert check_sheet_diagrams(st) == "kept"


def test_a_redrawing_for_the_errors_keeps_the_diagrams_readable():
    """Review 42's compressor crank-slider: first drawn at H1 43, H2 32 mm (9.8 % at the positions);
    a redrawing keeps each diagram's largest ordinate at READABLE_MM (20 mm, where the ruler's 0.5 mm
    is 2.5 % of it) or more, and still reads within the lab's 5 %."""
    import review_scenes
    st = scene_study(review_scenes.COMPRESSOR42)
    assert check_sheet_diagrams(st) == "first"
    options = diagram_options(st, 1.0, None, 0.5, A1_ROOM)
    rd = options.pop("redrawn")
    d = chord_diagrams(st, precision=0.5, redrawn=rd, **options)
    assert rd.changed and rd.within
    for ordinates in (d.drawn.v, d.drawn.a):
        assert np.max(np.abs(ordinates)) >= READABLE_MM - 0.5
