"""Review 58 #2: a set of sheets prints its plans' scales from the standard series 1, 2, 2.5, 4, 5 × 10^k
(LAYOUT.md: "each family's scale is the largest standard value whose drawings fit"), as the A1 sheet
does. The English crank-rocker's A2 kinematics set drew π a 145 mm at the lab's own μa = 0.0272
(m/s²)/mm and p_v a 50 mm at μv = 0.0125 (m/s)/mm, its A2 forces set group II(2-3)'s force plan at
GOST's 1.5 N/mm (A1 and A3: 2)."""
from __future__ import annotations

import math

import pytest
from hypothesis import given, strategies as st

from conftest import scene_study
from graphplan.graphic.scales import SERIES, on_series


def _series(mu: float) -> bool:
    """Independent of ``on_series``: the mantissa of μ is one of 1, 2, 2.5, 4, 5."""
    k = math.floor(math.log10(mu) + 1e-12)
    return any(abs(mu / 10.0 ** k - m) <= 1e-9 for m in SERIES)


@given(st.floats(1e-4, 1e4), st.floats(1e-5, 1e3), st.floats(5.0, 500.0))
def test_a_sets_larger_choices_are_the_series(value, mu, longest):
    """Every larger scale a set's plans are grown to is of the series, draws the segment larger than
    μ does and no longer than ``longest``; consecutive choices are consecutive series values."""
    from graphplan.sheets.kinlayout import series_choices
    got = series_choices(value, mu, longest)
    assert got == sorted(got, reverse=True)
    for m in got:
        assert _series(m) and m < mu and value / m <= longest * (1 + 1e-9)
    for a, b in zip(got, got[1:]):
        assert a / b <= 2.0 + 1e-9          # the series steps by at most ×2


@pytest.mark.parametrize("mu, nxt", [(2.0, 1.0), (10.0, 5.0), (0.1, 0.05), (0.04, 0.025), (0.025, 0.02),
                                     (0.0272, 0.025)])
def test_a_sets_force_plan_grows_to_the_next_series_value(mu, nxt):
    """2 N/mm → 1 (not GOST's 1.5); 10 → 5 (not 7.5)."""
    from graphplan.sheets.forces import next_series
    assert next_series(mu) == pytest.approx(nxt)


@pytest.mark.slow
def test_agitator_a2_sets_print_series_scales():
    """The reviewer's scene: the A2 kinematics set's μl, μv, μa and the A2 forces set's μF of every
    force plan and its acceleration plan's μa are series values (old: μa 0.0272, μv 0.0125, μF 1.5)."""
    from review_scenes import AGITATOR_SCALES58
    from graphplan.sheets import forces, kinematics
    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.form import form
    study = scene_study(AGITATOR_SCALES58)
    p, _, _ = kinematics.plan(study, form("A2"), kinematics._options(SheetOptions(sheet="kinematics")))
    assert p.shape == "set"
    for fam in ("position", "velocity", "acceleration"):
        assert _series(p.mu[fam]) and on_series(p.mu[fam]), (fam, p.mu)
    q, _, _ = forces.plan(study, form("A2"), SheetOptions(sheet="forces"))
    assert q.shape == "set"
    plans = {k: v for k, v in q.mu.items() if k == "forces" or k.startswith(forces.PLAN) or k == "acceleration"}
    assert plans
    for k, v in plans.items():
        assert _series(v), (k, q.mu)
