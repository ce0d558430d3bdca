"""Stop 58, kin58b: the output rocker's ψ_max is lettered along its own dimension arc clear of the
frame's other pivots (the blind review's slotted lever O3E: «ψmax = 57,75°» stood beside O2's
support, the OTHER rocker's pivot, and read as rocker 3's swing)."""
from __future__ import annotations

import cmath
import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as hs

from graphplan.drawing.plans import SWING_CLEAR, SWING_TRIES, swing_label_at


def on_arc(P, R, a1, a2, t):
    return P + R * cmath.exp(1j * math.radians(a1 + t * (a2 - a1)))


def test_the_middle_where_no_other_pivot_is_near():
    assert swing_label_at(0j, 100.0, 10.0, 70.0, []) == 0.5
    assert swing_label_at(0j, 100.0, 10.0, 70.0, [300 + 0j, -50j]) == 0.5


def test_a_pivot_at_the_arcs_middle_moves_the_lettering_along_the_arc_clear_of_it():
    """O2 right on the middle of O3's arc (R 100 mm, a 60° sweep): the lettering goes to the nearest
    share 20 mm clear of O2 — 0.4 of the sweep is 6° off the middle, 10.5 mm: not enough;
    0.3 is 12°, 2·100·sin 6° = 20.9 mm clear."""
    O2 = on_arc(0j, 100.0, 10.0, 70.0, 0.5)
    t = swing_label_at(0j, 100.0, 10.0, 70.0, [O2], 20.0)
    assert t == 0.3
    assert abs(on_arc(0j, 100.0, 10.0, 70.0, t) - O2) == pytest.approx(2 * 100 * math.sin(math.radians(6)), rel=1e-9)


def test_a_short_arc_takes_the_share_farthest_from_the_pivot():
    """A 10° arc of 50 mm beside a pivot at its middle clears no share by 20 mm: its end farthest
    from the pivot (0.2 or 0.8, equally far: the first of the tries)."""
    O2 = on_arc(0j, 50.0, 0.0, 10.0, 0.5)
    t = swing_label_at(0j, 50.0, 0.0, 10.0, [O2], 20.0)
    assert t in (0.2, 0.8)


@settings(max_examples=60, deadline=None)
@given(R=hs.floats(30.0, 300.0), a1=hs.floats(-180.0, 180.0), sweep=hs.floats(5.0, 170.0),
       others=hs.lists(hs.tuples(hs.floats(-400.0, 400.0), hs.floats(-400.0, 400.0)), max_size=3),
       need=hs.floats(SWING_CLEAR, 60.0))
def test_the_lettering_is_as_clear_as_any_try_allows(R, a1, sweep, others, need):
    """Whatever the pivots: the chosen share clears them by ``need`` where any try does (and is
    the try nearest the middle that does), else it is the try farthest from them."""
    pts = [complex(x, y) for x, y in others]
    clear = {t: min((abs(on_arc(0j, R, a1, a1 + sweep, t) - o) for o in pts), default=math.inf) for t in SWING_TRIES}
    t = swing_label_at(0j, R, a1, a1 + sweep, pts, need)
    good = [s for s in SWING_TRIES if clear[s] >= need]
    if good:
        assert clear[t] >= need and abs(t - 0.5) == min(abs(s - 0.5) for s in good)
    else:
        assert clear[t] == max(clear.values())


def test_the_review_coulisses_swing_is_lettered_clear_of_the_other_rockers_pivot():
    """The blind review's scene: the slotted lever O3E's swing arc (about O3) passes O2, the pivot of
    the four-bar's rocker; «ψ_max = 57,75°» is lettered by its own arc, its text at least SWING_CLEAR
    from O2 (it stood 9 mm from O2, beside its support), within a few mm of its own arc."""
    from conftest import scene_study
    from review_scenes import COULISSE_REVIEW58
    from graphplan.drawing.plans import position_record, swing
    from graphplan.graphic.plans import build_plans, where
    from graphplan.graphic.record import text_width
    from graphplan.model.mechanism import FRAME
    st = scene_study(COULISSE_REVIEW58)
    plans = build_plans(st)
    psi = swing(plans)
    lay = plans.positions[0].layout
    O2, O3 = (where(plans.scheme, lay, FRAME, j) for j in ("O2", "O3"))
    rec = position_record(plans, lang="uk")
    label = next(it for it in rec.items if it.kind == "text" and it.text.startswith("ψ_max"))
    assert label.text == f"ψ_max = {psi:.2f}°".replace(".", ",")
    arc = next(it for it in rec.items if it.kind == "arc" and it.step == "dimensions")
    assert complex(*arc.points[0]) == pytest.approx(O3, abs=1e-6)       # the arc is O3's: the lever's
    (x, y), w, h = label.points[0], text_width(label.text, label.size), label.size
    assert label.anchor == "start"
    gap = math.hypot(max(x - O2.real, 0.0, O2.real - (x + w)), max(y - O2.imag, 0.0, O2.imag - (y + h)))
    assert gap >= SWING_CLEAR, (label.points, O2)
    # by its own arc: the text's nearest corner within a few mm of the circle about O3
    corners = [complex(x + a, y + b) for a in (0.0, w) for b in (0.0, h)]
    assert min(abs(abs(c - O3) - arc.radius) for c in corners) <= 6.0
