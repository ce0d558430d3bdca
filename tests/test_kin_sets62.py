"""Stop 62 (kin62): the kinematics sheet graded as a strict teacher grades it.

1. LINK62's slider B on its inclined guide carries on its pin the block 4 of the lever's slot: the
   slider drawn as a carriage along its guide, the block in front of it along the slot (the two
   equal 9 × 5 blocks drawn over each other read as one eight-pointed knot), each numbered by its
   own block; the slider's stroke H dimensioned by B′B″, not 110 mm off past the lever's C″.
2. A set's diagrams read off more than 5 % and twice as badly as at another size the set tries
   weigh like one more sheet (the crusher's A3 ε₃ 20,6 % beside the plans, the gate's A2 12,8 %).
3. The swing's «ψ_max = …» stays within the position plan's lines: at 1:2,5 the crusher's stood on
   a 40-mm leader below B″ and grew the A3 plan past its sheet (it fell to 1:4)."""
from __future__ import annotations

import cmath
import math

import pytest

from conftest import scene_study
from graphplan.drawing.plans import (BLOCK, CARRIAGE, STONE, SWING_OUT, block_size, other_slides, pinned_blocks, position_record,
                                     slide_ends, stroke_ends)
from graphplan.graphic.plans import build_plans, where
from graphplan.model.mechanism import FRAME
from graphplan.sheets.kinlayout import MISREAD, misread_diagrams
from review_scenes import COULISSE_REVIEW58, DYN61B_GATE, KIN60B_CRUSHER, LINK62


def test_a_size_read_off_twice_as_badly_as_the_best_and_over_5_percent_weighs_a_sheet():
    """By hand: sizes read off 14.92, 12.84, 5.65, 7.59 % (the gate's A2): the best is 5.65, twice it
    11.3 — 14.92 and 12.84 weigh a sheet, 7.59 (over 5 %, under 11.3) and 5.65 do not; where every
    size reads off alike, or the best over 10 % (the method's own error) none does; none under 5 %."""
    read = {0.5: 14.92, 0.64: 12.84, 0.8: 5.65, 1.0: 7.59}
    assert [misread_diagrams(read, k) for k in read] == [1, 1, 0, 0]
    assert MISREAD == 2.0
    alike = {0.5: 21.0, 0.8: 20.0, 1.0: 20.5}
    assert not any(misread_diagrams(alike, k) for k in alike)
    small = {0.5: 4.9, 1.0: 1.0}
    assert not any(misread_diagrams(small, k) for k in small)
    # the shaper's A2: 26.36 % at the size that keeps 2 sheets, 13.16 % at best — no size reads
    # within twice the lab's 5 %: the method's own error, not the size's
    shaper = {0.5: 44.87, 0.64: 19.26, 0.8: 26.36, 1.0: 22.6, (1.0, 1.25): 13.16}
    assert not any(misread_diagrams(shaper, k) for k in shaper)


@pytest.fixture(scope="module")
def link62():
    st = scene_study(LINK62)
    plans = build_plans(st, mu_l=0.002)
    return st, plans, position_record(plans)


def _segment_distance(z: complex, a: complex, b: complex) -> float:
    t = max(0.0, min(1.0, ((z - a) * (b - a).conjugate()).real / abs(b - a) ** 2))
    return abs(z - (a + t * (b - a)))


def _inside(z: complex, poly: list[complex]) -> bool:
    """Whether z lies strictly inside the convex polygon."""
    sides = [((b - a).conjugate() * (z - a)).imag for a, b in zip(poly, poly[1:] + poly[:1])]
    return all(s > 1e-6 for s in sides) or all(s < -1e-6 for s in sides)


def test_the_slider_is_a_carriage_along_its_guide_and_the_block_a_stone_in_front_along_the_slot(link62):
    """The slider 3 ("B") on the frame's inclined guide and the block 4 ("B4") in the lever's slot share
    the pin B: the slider is drawn 12 × 6 along the guide (20°), the block 8 × 4 along the lever O3B
    (its direction from the drawn O3 and B), the slider's edges hidden where the block covers them —
    what is drawn of them lies on the 12 × 6 rectangle, outside the block, shorter than its 36 mm
    perimeter; a block that shares no pin stays 9 × 5."""
    st, plans, rec = link62
    sc = plans.scheme
    assert pinned_blocks(sc, "B") == ["B4"] and pinned_blocks(sc, "B4") == []
    assert block_size(sc, "B") == CARRIAGE == (12.0, 6.0) and block_size(sc, "B4") == STONE == (8.0, 4.0)
    coulisse = build_plans(scene_study(COULISSE_REVIEW58)).scheme
    assert {block_size(coulisse, n) for n, l in coulisse.mech.links.items()
            if l.slides_on is not None and len(l.joints) <= 1} == {BLOCK}
    lay = next(p.layout for p in plans.positions if p.layout.key in plans.accel_keys)
    B, O3 = where(sc, lay, sc.body_of("B"), "B"), where(sc, lay, FRAME, "O3")
    lever = (O3 - B) / abs(O3 - B)
    guide = cmath.exp(1j * math.radians(20.0))
    stone = [q for q in rec.items if q.kind == "polygon" and abs(sum(complex(*p) for p in q.points) / 4 - B) < 1e-6]
    assert len(stone) == 1
    zs = [complex(*p) for p in stone[0].points]
    along, across = zs[1] - zs[0], zs[3] - zs[0]
    assert abs(along) == pytest.approx(8.0) and abs(across) == pytest.approx(4.0)
    assert abs((along / lever).imag) < 1e-6 * abs(along)

    def on_carriage(z: complex) -> bool:
        w = (z - B) / guide
        return (abs(w.real) <= 6.0 + 1e-6 and abs(w.imag) <= 3.0 + 1e-6
                and (abs(abs(w.real) - 6.0) < 1e-6 or abs(abs(w.imag) - 3.0) < 1e-6))
    pieces = [(complex(*q.points[0]), complex(*q.points[1])) for q in rec.items
              if q.kind == "segment" and q.role == "link" and all(on_carriage(complex(*p)) for p in q.points)]
    drawn = sum(abs(b - a) for a, b in pieces)
    assert 20.0 < drawn < 36.0 - 1.0
    assert not any(_inside(0.5 * (a + b), zs) for a, b in pieces)


def test_the_sliders_stroke_is_dimensioned_by_its_own_extremes(link62):
    """«H = 121,5 мм» (the slider B's stroke: its two dead centres, by hand below) stands nearer the
    segment B′B″ than the lever's C′C″ — a reader takes it for B's stroke (it stood 110 mm below the
    guide, by C″)."""
    st, plans, rec = link62
    sc = plans.scheme
    assert other_slides(plans) == ["B"]
    Bs = [where(sc, lay, sc.body_of("B"), "B") for lay in slide_ends(plans, "B")]
    Cs = [where(sc, lay, sc.body_of("C"), "C") for lay in stroke_ends(plans)]
    # by hand: B on the guide through (0, −0.04) at 20°, the crank 0.06 and the rod 0.25 in one line at
    # the dead centres: the foot of O1 on the guide, e its distance, B at ±√((l ± r)² − e²) from it
    u = cmath.exp(1j * math.radians(20.0))
    e = abs(((0 - (-0.04j)) / u).imag)
    H = math.sqrt(0.31 ** 2 - e ** 2) - math.sqrt(0.19 ** 2 - e ** 2)
    assert abs(Bs[1] - Bs[0]) * plans.mu_l == pytest.approx(H, abs=1e-9)
    label = [q for q in rec.items if q.kind == "text" and q.text.startswith("H = ")]
    assert [q.text for q in label] == [f"H = {H * 1000:.1f} мм".replace(".", ",")]
    x0, y0, x1, y1 = label[0].ink()
    mid = complex(0.5 * (x0 + x1), 0.5 * (y0 + y1))
    assert _segment_distance(mid, *Bs) < _segment_distance(mid, *Cs)
    assert _segment_distance(mid, *Bs) < 60.0


@pytest.mark.parametrize("scene, mu", [(KIN60B_CRUSHER, 0.0025), (COULISSE_REVIEW58, None)], ids=["crusher", "coulisse58"])
def test_the_swing_is_lettered_within_the_plans_lines(scene, mu):
    """«ψ_max = …» stands within the box of the plan's lines, or a line of lettering out of it (it grows
    no plan past its sheet): the crusher's at 1:2,5 stood on a 40-mm leader 20 mm below them."""
    plans = build_plans(scene_study(scene), mu_l=mu)
    bare = position_record(plans, lettered=False).bounds()
    rec = position_record(plans)
    label = [q for q in rec.items if q.kind == "text" and q.text.startswith("ψ_max")]
    assert len(label) == 1
    x0, y0, x1, y1 = label[0].ink()
    out = SWING_OUT + 1e-6       # a line of lettering over its arc, where the arc is the plan's edge
    assert bare[0] - out <= x0 and x1 <= bare[2] + out and bare[1] - out <= y0 and y1 <= bare[3] + out


@pytest.mark.slow
@pytest.mark.parametrize("scene, fmt", [(KIN60B_CRUSHER, "A3"), (DYN61B_GATE, "A2")], ids=["crusher-A3", "gate-A2"])
def test_a_sets_diagrams_read_as_close_as_a_sheet_of_their_own_allows(scene, fmt):
    """The gate's A2 set drew its diagrams 12,8 % off (μψ 0,02) where another size the set tries reads
    5,65 %: the set now takes a size that reads within twice its best (or within the lab's 5 %). The
    crusher's A3 set drew its 1:4 plan and diagrams 20,6 % off beside it on sheet 1; its plan is
    back at 1:2,5 (the swing's lettering no longer grows it) and its diagrams, on a sheet of their
    own, read closer."""
    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.form import form
    from graphplan.sheets.kinematics import _options, plan
    from graphplan.sheets.kinlayout import room, set_diagrams
    st = scene_study(scene)
    p, nat, dr = plan(st, form(fmt), _options(SheetOptions(sheet="kinematics")))
    assert p.shape == "set"
    tried = {k: dr.diagrams(k).worst_pct() for k in set_diagrams(dr, nat, room(form(fmt), later=True))}
    worst = dr.diagrams(p.diagrams).worst_pct()
    assert worst <= max(5.0, MISREAD * min(tried.values())) + 1e-9, (p.diagrams, worst, tried)
    assert worst < 15.0
    if scene is KIN60B_CRUSHER:
        assert p.mu["position"] == pytest.approx(0.0025)       # the plan back at 1:2,5 (kin61: 1:4)
