"""kin61b: the kinematic diagrams' s scale is a value of the standard series 1, 2, 2.5, 4, 5 × 10^k on every
sheet (review 61 #2: the hopper gate's A1 printed μψ = 0,011 rad/mm, the seed's ψmax/h to two figures, where
0,01 draws ψ 83 mm in its 80-mm allowance; a student takes a scale off the series)."""
from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import random_mechanisms as rm
from conftest import scene_study

MANTISSAS = (1.0, 2.0, 2.5, 4.0, 5.0)


def on_the_series(mu: float) -> bool:
    """Written here from the series' definition (not graphplan.graphic.scales): mu = m·10^k, m in 1, 2, 2.5, 4, 5."""
    k = math.floor(math.log10(mu) + 1e-12)
    m = mu / 10.0 ** k
    return any(abs(m - x) <= 1e-9 * x for x in MANTISSAS)


@settings(max_examples=300, deadline=None)
@given(span=st.floats(1e-4, 50.0), height=st.floats(30.0, 110.0), fit=st.booleans())
def test_the_s_scale_is_always_a_series_value(span, height, fit):
    """``choose_mu_s`` at a height allowance: a series value; the standard one draws s within the
    allowance and more than half of it (the series steps by at most ×2); the fitted one (the next
    finer) draws s taller than the allowance, by less than the series' step (×2)."""
    from graphplan.graphic.diagrams import choose_mu_s
    mu = choose_mu_s(None, "m", span, height, fit)
    assert on_the_series(mu)
    drawn = span / mu
    if fit:
        assert height * (1 - 1e-9) <= drawn < 2 * height * (1 + 1e-9)
    else:
        assert height / 2 * (1 - 1e-9) < drawn <= height * (1 + 1e-9)



# generated rockers (r, d, l2, l3) and sliders (r, l, e, guide angle): Grashof / assemblable over the turn
ROCKERS = [(0.08, 0.33, 0.30, 0.20), (0.05, 0.30, 0.28, 0.15), (0.03, 0.20, 0.22, 0.12), (0.06, 0.25, 0.30, 0.25)]
SLIDERS = [(0.05, 0.20, 0.0, 0.0), (0.04, 0.18, 0.03, 0.0), (0.06, 0.30, -0.02, 30.0)]


def _scenes():
    from review_scenes import KIN61B_GATE, LINK48
    out = [("gate61", KIN61B_GATE), ("LINK48", LINK48)]
    for i, (r, d, l2, l3) in enumerate(ROCKERS):
        text, ok = rm.rrr(r, d, l2, l3, 12.0, 1)
        assert ok
        out.append((f"rocker{i}", text + "output = \"O2B\"\n"))
    for i, (r, ln, e, a) in enumerate(SLIDERS):
        text, ok = rm.rrp(r, ln, e, a, 12.0, 1)
        assert ok
        out.append((f"slider{i}", text))
    return out


@pytest.mark.slow
@pytest.mark.parametrize("name,text", _scenes(), ids=[n for n, _ in _scenes()])
def test_every_sheet_diagram_prints_a_series_mu_s(name, text):
    """The diagrams an A1 sheet and an A3 set draw (``diagram_options`` with the sheet's room, as
    redrawn): μs a series value. The gate and LINK48 are the review's cases (their first drawing
    wrong under a low s: before, μψ 0,011 and μs 0,0013 m/mm); there the s diagram drawn at the
    series' finer value is right and within the room."""
    from graphplan.graphic.diagrams import chord_diagrams
    from graphplan.sheets.form import form
    from graphplan.sheets.kinematics import DIAGRAM_MM, diagram_options
    from graphplan.sheets.kinlayout import room
    stu = scene_study(text)
    for k, f, floor in ((1.0, "A1", 0.0), ((1.0, 1.0), "A3", DIAGRAM_MM)):
        opts = diagram_options(stu, k, None, 0.5, room(form(f), later=f != "A1"), floor)
        d = chord_diagrams(stu, precision=0.5, **{key: v for key, v in opts.items() if key != "redrawn"})
        assert on_the_series(d.mu_s), (name, f, d.mu_s)
        if name in ("gate61", "LINK48") and f == "A1":
            assert opts.get("fit") is True and opts["redrawn"].right
            assert opts["height"] < (max(d.exact.s) - min(d.exact.s)) + 1e-9   # taller than its allowance
