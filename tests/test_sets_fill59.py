"""Stop 59: a set's plans grow at the standard series' scales (review 58 #2), which step by 1.25 to 2
times; capped at ``SET_LARGEST`` of their target, the agitator's A2 acceleration plan stopped at
0.04 (m/s²)/mm, π a 98.7 mm of its 120-mm target, because 0.025 draws 158 mm, 6 mm past the cap —
sheet 2 was 46 % empty under it. A plan short of its target may now take the series' next step past
the cap, where the sheets hold it."""
from __future__ import annotations

import math

import pytest
from hypothesis import given, strategies as st

from graphplan.sheets.kinlayout import SET_LARGEST, set_steps


def _series(mu: float) -> bool:
    k = math.floor(math.log10(mu) + 1e-12)
    return any(abs(mu / 10.0 ** k - m) <= 1e-9 for m in (1, 2, 2.5, 4, 5))


@pytest.mark.parametrize("principal, mu, target, steps", [
    (3.95, 0.04, 120.0, [0.025]),         # the agitator's a_A: 98.7 mm → 158 (0.0272 was the lab's own)
    (4.25, 0.1, 100.0, [0.05, 0.04]),     # the shaper's v_A: 42.5 → 85, 106 mm; 106 ≥ 100, no step past
    (86.8, 2.0, 120.0, [1.0, 0.5]),       # the shaper's a_A: 43.4 → 86.8 (short of 120) → 173.6
    (1.0, 0.01, 100.0, []),               # already 100 mm long: nothing larger within 125
])
def test_a_sets_plan_steps_by_hand(principal, mu, target, steps):
    assert set_steps(principal, mu, target) == pytest.approx(steps)


@given(st.floats(1e-3, 1e3), st.floats(1.0, 300.0), st.floats(20.0, 300.0))
def test_a_plan_short_of_its_target_may_take_one_series_step_past_the_cap(principal, drawn, target):
    """Every step is of the series and draws larger than μ; all within ``SET_LARGEST`` × target
    are offered, smallest drawing first; one more, the series' next, only where the largest of them
    (or μ itself) draws the plan shorter than its target — then never past twice the target. The
    plan drawn ``drawn`` mm at μ, as a set's floor draws it (1 … 300 mm)."""
    mu = principal / drawn
    got = set_steps(principal, mu, target)
    assert got == sorted(got, reverse=True)
    assert all(_series(m) and m < mu * (1 - 1e-9) for m in got)
    within = [m for m in got if principal / m <= target * SET_LARGEST * (1 + 1e-9)]
    past = got[len(within):]
    assert len(past) <= 1
    for a, b in zip(got, got[1:]):
        assert a / b <= 2.0 + 1e-9
    largest = principal / (within[-1] if within else mu)
    if past:
        assert largest < target and principal / past[0] <= 2.0 * target * (1 + 1e-9)
    else:
        assert largest >= target * (1 - 1e-9)


@pytest.mark.slow
def test_the_agitators_a2_set_fills_its_second_sheet():
    """The English agitator's A2 kinematics set: two sheets, neither left half empty (stop 58: sheet 2
    46 % drawn on, its acceleration plan π a 98.7 mm at 0.04); every plan's scale of the series."""
    from review_scenes import AGITATOR_SCALES58
    from conftest import scene_study
    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.form import form
    from graphplan.sheets.sheet import BUILDERS
    from test_sets_fill import fill
    sheet = BUILDERS["kinematics"](scene_study(AGITATOR_SCALES58), form("A2"), SheetOptions(sheet="kinematics"))
    assert len(sheet.pages) == 2
    fills = [fill(page) for page in sheet.pages]
    assert min(fills) >= 0.5, fills             # stop 58: 0.678, 0.463; stop 59: 0.678, 0.506
    plan = next(p for p in sheet.pages[1].placed if p.name.startswith("acceleration plan"))
    x0, y0, x1, y1 = plan.record.bounds()
    assert x1 - x0 >= 150.0                     # π a 158 mm at 0.025 (m/s²)/mm: the plan 161 × 112 mm
