"""Review 8's coulisse (tests/review_scenes.COULISSE8): the crank's own vector read back as ω1·l, the
A1's position plan given the room, the diagrams' shoulders judged and redrawn, Table 4's X named."""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st_

import random_mechanisms as rm
from conftest import EXAMPLES, example, scene_study
from review_scenes import COULISSE, COULISSE8, FOURBAR, OFFSET_SLIDER, PRESS4, PRESS_EN, SIXBAR, SIXBAR6, SIXBAR7
from graphplan.graphic import qualitative
from graphplan.graphic.plans import build_plans
from graphplan.graphic.scales import chosen_length
from graphplan.util.errors import GraphplanError
from test_redraw import check_sheet_diagrams

LINKAGES = [n for n in EXAMPLES if not n.startswith(("cam_", "gears"))]
REVIEWS = [COULISSE8, COULISSE, FOURBAR, OFFSET_SLIDER, PRESS4, PRESS_EN, SIXBAR, SIXBAR6, SIXBAR7]


def sig3(x: float) -> str:
    return f"{x:.3g}"


def crank_pin_reads(st, plans, figures: bool = True) -> None:
    """Every plan's crank pin is drawn v_A / μv (a_A / μa) long to a tenth of a millimetre (seed 000
    lays π a = 113,6 mm) and reads that length × μ — what the tables print beside it — within
    0.05 mm × μ of |ω1|·l (l·√(ω1⁴ + ε1²)); ``figures``: to three figures too (where the exact value
    is not on a rounding boundary: 5496,96 at μa 99,9 read 5494,5)."""
    cr = st.mech.crank
    v_a = abs(cr.omega) * cr.length
    a_a = cr.length * math.hypot(cr.omega ** 2, cr.epsilon)
    for p in plans.positions:
        for plan, want in ((p.velocity, v_a), (p.acceleration, a_a)):
            if plan is None:
                continue
            e = plan.entries[cr.pin]
            assert abs(e.mm / 0.1 - round(e.mm / 0.1)) < 1e-9, (p.key, plan.kind, e.mm)
            assert abs(e.mm - want / plan.mu) <= 0.05 + 1e-9, (p.key, plan.kind)
            assert e.value == pytest.approx(e.mm * plan.mu, rel=1e-12) or e.value == want
            if figures:
                assert sig3(e.value) == sig3(want), (p.key, plan.kind, e.value, want)


@pytest.mark.parametrize("source", LINKAGES + [f"review {i}" for i in range(len(REVIEWS))])
def test_the_crank_pin_reads_omega_l_at_the_plans_and_the_labs_own_scales(source):
    """Review 8 #2: p_v a = 30 mm at μv = 0.0355 (not 1.0679/30) read v_A 1.065, Table 1 printing 1,06
    where ω1·l = 1,07. At the series' scales and at the lab's own (p_v a chosen 30 mm, μ to three
    figures, rounded down) the crank pin, laid to 0.1 mm, reads ω1·l within 0.05 mm × μ — review 8's
    own case, 1.0679 / 0.0355 = 30.08 mm, laid 30.1 mm, reads 1.0686: Table 1's 1,07."""
    st = example(source) if source in LINKAGES else scene_study(REVIEWS[int(source.split()[1])])
    cr = st.mech.crank
    plans = build_plans(st, count=4, accel=["#0", "#2"])
    crank_pin_reads(st, plans, False)
    if source == "review 0":
        pin = build_plans(st, count=4, accel=["#1"], mu_v=0.0355).positions[1].velocity.entries[cr.pin]
        assert pin.mm == pytest.approx(30.1) and f"{pin.value:.2f}" == f"{abs(cr.omega) * cr.length:.2f}" == "1.07"
    own_v = chosen_length(abs(cr.omega) * cr.length, 30.0)
    own_a = chosen_length(cr.length * math.hypot(cr.omega ** 2, cr.epsilon), 55.0)
    crank_pin_reads(st, build_plans(st, count=4, accel=["#1"], mu_v=own_v, mu_a=own_a), False)


@settings(max_examples=15, deadline=None, derandomize=True, database=None)
@given(length=st_.floats(12.0, 140.0), mm_a=st_.floats(20.0, 160.0), precision=st_.sampled_from([0.5, 1.0, 0.1]))
def test_any_scale_reads_the_crank_pin_back(length, mm_a, precision):
    """Whatever μv, μa (the pin's vector drawn ``length``, ``mm_a`` mm) and ruler: the pin reads ω1·l
    within the 0.05 mm it is laid to (a 12-mm vector's three figures may differ)."""
    st = scene_study(COULISSE8)
    cr = st.mech.crank
    mu_v = abs(cr.omega) * cr.length / length
    mu_a = cr.length * cr.omega ** 2 / mm_a
    crank_pin_reads(st, build_plans(st, count=3, accel=["#1"], mu_v=mu_v, mu_a=mu_a, precision=precision), False)


# -- shoulders --------------------------------------------------------------------------------------

TURN = qualitative.sample_turns()


def falling(turn: np.ndarray) -> np.ndarray:
    """A smooth periodic curve (mm) falling from 0 to 8 of 12 divisions, one max, one min."""
    return 40.0 * np.cos(np.radians(turn) * 1.0) + 12.0 * np.sin(np.radians(turn) * 2.0)


def test_a_shoulder_the_exact_curve_lacks_is_qualitatively_wrong():
    """Review 8 #5: a monotone stretch drawn with a shoulder (slopes 3.7 : 2.0 : 5.3 mm a division where
    the exact ones steepen) has the exact curve's extrema and zeros but is wrong; a faint one (under
    two ruler divisions off its chord) and the exact curve itself are right; the shoulder is named."""
    exact = falling(TURN)
    bump = 6.0 * np.exp(-((TURN - 110.0) / 12.0) ** 2)       # on the fall: the slope flattens, then steepens
    shoulder = exact + bump
    v = qualitative.compare(TURN, shoulder, exact, window=30.0, L=240.0)
    assert not (v.spurious_extrema or v.missed_extrema or v.spurious_zeros or v.missed_zeros)
    assert v.wrong and len(v.spurious_bends) == 2 and all(90 < f.turn < 130 for f in v.spurious_bends)
    assert not qualitative.compare(TURN, exact + 0.2 * bump, exact, window=30.0, L=240.0).wrong
    assert not qualitative.compare(TURN, exact, exact, window=30.0, L=240.0).wrong
    assert not qualitative.compare(TURN, np.roll(exact, 12), exact, window=30.0, L=240.0).wrong   # displaced 6°
    assert not qualitative.compare(TURN, shoulder, exact, window=30.0).wrong     # no L: the old comparison


def test_the_coulisses_a3_a_diagram_is_redrawn_without_its_shoulder():
    """Review 8 #5: the A3 set's a-diagram (H1 50, H2 43 over an s 36 mm high) had a shoulder at
    positions 5–6 and 29 % off, its note saying nothing helps, where the A1 reads 13 %: drawn in
    the A3's room that first drawing is called wrong and redrawn right, within 15 %."""
    from graphplan.graphic.diagrams import chord_diagrams
    from graphplan.graphic.redraw import redraw
    from graphplan.sheets.kinematics import POLES
    st = scene_study(COULISSE8)
    first = {"point": None, "divisions": 12, "L": 240.0, "H1": 50.0, "H2": 43.0, "height": 68.0}
    d = chord_diagrams(st, precision=0.5, **first)
    said = [w for w in d.warnings if w["kind"] == "qualitative"]
    assert [w["diagram"] for w in said] == ["a_{C}"] or [w["diagram"] for w in said] == [d.symbols[2]]
    assert said[0].get("spurious_bends") and not said[0].get("spurious_extrema")
    turns = [b["turn_deg"] / 30.0 for b in said[0]["spurious_bends"]]
    assert any(4.5 <= t <= 6.5 for t in turns), turns
    chosen, done = redraw(st, first, 0.5, POLES, menu=True)     # a set: the diagrams on a sheet of their own
    assert done.wrong_before == ("a",) and done.right and done.off_after < 15.0
    again = chord_diagrams(st, precision=0.5, **chosen)
    assert not [w for w in again.warnings if w["kind"] == "qualitative"]


# -- Table 4 ----------------------------------------------------------------------------------------

def test_table_4_names_the_rams_guide_x_from_the_rockers_pivot():
    """Review 8: Table 4 printed "e = 0,320 м", the ram guide's distance from O1, unexplained. Seed 000
    gives X from O, the rocker's pivot: the row "X: O — напрямна C" (en "X: O to guide C"; review 55
    #10: the ram's point named) = 0.62 m, drawn 155 mm at 1:4; an offset crank-slider keeps its e."""
    from graphplan.sheets.kintables import dimensions_table, link_lengths
    st = scene_study(COULISSE8)
    sizes = dict(link_lengths(st))
    assert "e" not in sizes and sizes["X"] == pytest.approx(0.62)
    for lang, words in (("uk", "X: O — напрямна C"), ("en", "X: O to guide C")):
        texts = [q.text for q in dimensions_table(st, 0.004, lang).items if q.kind == "text"]
        assert texts[texts.index(words) + 1] == ("0,620" if lang == "uk" else "0.620"), texts
        assert texts[texts.index(words) + 2] == ("155,0" if lang == "uk" else "155.0"), texts
    offset = scene_study(OFFSET_SLIDER)
    assert "e" in dict(link_lengths(offset)) and "X" not in dict(link_lengths(offset))


# -- the A1 sheet ---------------------------------------------------------------------------------

@pytest.mark.slow
def test_the_a1_draws_the_coulisses_position_plan_as_large_as_its_room():
    """Review 8 #1: the A1 drew the plan of positions at 1:10 (crank 9.3 mm) beside full-length
    diagrams; now 1:4 at least, every other plan at least 0.9 as large as the full-length diagrams'
    composition draws it — the diagrams drawn shorter only for a larger position plan (since the
    last table may stand under the others, the full-length diagrams' own composition reaches 1:4)."""
    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.form import form
    from graphplan.sheets.kinematics import plan
    from graphplan.sheets.kinlayout import KEPT, one_sheet_at
    st = scene_study(COULISSE8)
    p, nat, dr = plan(st, form("A1"), SheetOptions(sheet="kinematics"))
    assert p.sheets == 1 and p.mu["position"] <= 0.004 + 1e-12
    assert st.mech.crank.length / p.mu["position"] >= 23.0
    full = one_sheet_at(dr, nat, form("A1"), 1.0)[1]
    assert full.mu["position"] >= p.mu["position"]
    if p.diagrams != 1.0:
        assert full.mu["position"] > p.mu["position"]
    for fam in ("velocity", "acceleration"):
        assert nat.drawn(fam, p.mu[fam]) >= KEPT * nat.drawn(fam, full.mu[fam]) - 1e-9


@pytest.mark.slow
@settings(max_examples=10, deadline=None, derandomize=True, database=None)
@given(r=st_.floats(0.06, 0.12), c=st_.floats(0.2, 0.4), e=st_.floats(-0.02, 0.02),
       w=st_.sampled_from([-11.5, 20.0]), k=st_.sampled_from([1.0, (1.0, 0.8)]))
def test_a_generated_coulisses_diagrams_have_no_shoulder_a_redrawing_removes(r, c, e, w, k):
    """Issue 32 #2 with shoulders judged: a generated slotted-lever coulisse's sheet diagrams are right
    (no extrema, zeros or shoulders the motion lacks), or none of the lab's alternatives is."""
    text, ok = rm.rpr(r, c, e, w, 1)
    assume(ok)
    try:
        st = scene_study(text)
    except GraphplanError:
        assume(False)
    check_sheet_diagrams(st, k)
