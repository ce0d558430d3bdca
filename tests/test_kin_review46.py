"""Review 46 (a teacher's look at the kinematics sheet of a six-bar feed mechanism and an offset
vertical press): the drawn geometry measured against the exact solution."""
from __future__ import annotations

import numpy as np
import pytest

from conftest import scene_study
from review_scenes import ROCKER46


@pytest.fixture(scope="module")
def rocker():
    """The six-bar whose slider D stops four times a turn (its rod CD passes its dead centre near
    the top: a 0.3-mm dip between two of the stops), its position plan at 1:2."""
    from graphplan.drawing.plans import position_record
    from graphplan.graphic.plans import build_plans
    st = scene_study(ROCKER46)
    plans = build_plans(st, mu_l=0.002)
    return st, plans, position_record(plans, lang="uk")


def test_the_stroke_is_dimensioned_between_the_largest_and_the_smallest_stop(rocker):
    """H spans the slider's whole stroke, max − min of its position over the turn (sampled finely),
    not the first two of its four stops (it drew H = 1 between 355.7° and 18.6°); D′ and D″ are
    lettered at those two ends."""
    st, plans, rec = rocker
    assert len(st.extremes) == 4
    phi = np.linspace(0.0, 360.0, 7201)
    y = st.solve(phi).point("D")[0].imag          # (position, velocity, acceleration)
    stroke = (y.max() - y.min()) / plans.mu_l                  # mm on the drawing
    dim = [p for p in rec.items if p.step == "dimensions" and p.kind == "vector"]
    assert len(dim) == 2
    (m, a), (_, b) = (p.points for p in dim)
    assert abs(abs(complex(*b) - complex(*a)) - stroke) < 0.05
    text = [p.text for p in rec.items if p.kind == "text" and p.text.startswith("H = ")]
    assert text and abs(float(text[0][4:].replace(",", ".")) - stroke * plans.mu_l * 1000.0) < 0.06
    ends = sorted(complex(*a).imag for a in (a, b))
    primes = {p.text: complex(*p.points[0]) for p in rec.items if p.kind == "text" and p.text.startswith("D")}
    for mark in ("′", "″"):
        at = next(z for t, z in primes.items() if t.endswith(mark))
        assert min(abs(at.imag - e) for e in ends) < 8.0, (mark, at, ends)   # lettered by its end
