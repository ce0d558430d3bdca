"""Stop 48's gear-sheet review (helper gear48): the lead's pair 12/31 "auto" + type B u = 16 (GEARS48),
GEARS_B47's primed z′₂ and the plan of angular velocities' scale — checked against the glyphs' ink and
the closed forms, not the code's own numbers."""
from __future__ import annotations

from graphplan.graphic.record import ink_boxes


def test_an_index_after_a_prime_stands_under_the_prime_by_its_letter():
    """z'_2 typeset as z′₂ (the prime high, the 2 low, both right after the z): the 2's ink begins
    within the prime's advance — not past it, hanging apart from its z (GEARS_B47's notes: the 2 a
    word of its own beside z′, overprinted) — and stays clear of the prime's ink below it."""
    for size in (2.5, 3.5, 5.0):
        z, prime, two = ink_boxes("z'_2", size)
        assert two[0] < prime[2]                           # under the prime, not after it
        assert two[0] - z[2] < 0.25 * size                 # beside its letter (as z_2 sets it)
        assert two[3] < prime[1] - 0.2 * size              # clear of the prime's ink
        z_, two_ = ink_boxes("z_2", size)
        assert abs(two[0] - two_[0]) < 1e-9                # where the unprimed z₂ sets it


import math
import tomllib

import pytest

from review_scenes import GEARS48, GEARS_A48

ROUND = (1.0, 1.25, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0)      # a round scale's mantissa


def _round(v: float) -> bool:
    m = v / 10.0 ** math.floor(math.log10(v) + 1e-12)
    return any(abs(m - r) < 1e-9 for r in ROUND)


def _readings(fmts: dict) -> dict:
    from graphplan.exact.gears import solve
    from graphplan.model.gears import build
    from graphplan.sheets.form import form
    from graphplan.sheets.gears import on_sheet
    out = {}
    for name, text in (("GEARS48", GEARS48), ("GEARS_A48", GEARS_A48)):
        g = build(tomllib.loads(text), name)
        sol = solve(g)
        for f in fmts.get(name, ()):
            out[name, f] = (sol, on_sheet(g, sol, form(f), 0.5, "uk")[1])
    return out


@pytest.fixture(scope="module")
def sheets():
    """GEARS48's and GEARS_A48's readings on A1 (about 1.6 s): (solution, velocities)."""
    return _readings({"GEARS48": ("A1",), "GEARS_A48": ("A1",)})


@pytest.fixture(scope="module")
def a3_set():
    """GEARS48's readings in the A3 set (its size search: about 7 s)."""
    return _readings({"GEARS48": ("A3",)})


def test_the_plan_of_angular_velocities_has_a_round_scale_and_a_ruler_length_pole_distance(sheets):
    """μω = μv/(μl·h) a round value (0,5 (рад/с)/мм, not the 0,4762 of h = 42 mm) and h a whole or half
    millimetre, on the A1 sheet and on the sets; each ω read = its segment × μω (ω1 the given one
    within the ruler's half millimetre and the heights laid off)."""
    for (name, f), (sol, vel) in sheets.items():
        mu_w = vel.mu_v / (vel.mu_l * vel.h)
        assert _round(mu_w), (name, f, vel.h, mu_w)
        assert abs(2 * vel.h - round(2 * vel.h)) < 1e-9, (name, f, vel.h)
        assert 20.0 <= vel.h <= 150.0
        assert vel.omega["1"] == pytest.approx(vel.segments["1"] * mu_w, rel=1e-12)
        w1 = sol.train.omega["1"]
        assert abs(vel.omega["1"] - w1) <= 0.25 * mu_w + 0.02 * w1
        if vel.h_carrier is not None and f == "A1":
            assert _round(vel.mu_v / (vel.mu_l * vel.h_carrier)) or abs(vel.segments["H"]) >= 20.0


def test_u1h_is_willis_and_the_drawing_reads_it_within_the_stated_bound(sheets):
    """GEARS48: type B, u = 16, K = 3 → z 17/55/20/92 (coaxial: 17 + 55 = 92 − 20), u1H = 1 + z2·z3/(z1·z2')
    = 15,88 by Willis; the plan's u1H within its stated bound on every format; GEARS_A48: type A
    18/36/90, u1H = 1 + 90/18 = 6."""
    for (name, f), (sol, vel) in sheets.items():
        z = sol.train.z
        u = 1 + z[1] * z[3] / (z[0] * z[2]) if len(z) == 4 else 1 + z[2] / z[0]
        assert sol.train.ratio == pytest.approx(u, rel=1e-12)
        if name == "GEARS48":
            assert tuple(z) == (17, 55, 20, 92) and z[0] + z[1] == z[3] - z[2]
        else:
            assert u == 6.0
        assert abs(vel.ratio - u) <= vel.ratio_bound, (name, f, vel.ratio, u, vel.ratio_bound)
        assert vel.ratio_bound / u < 0.08


@pytest.mark.slow
def test_the_a3_sets_plan_has_a_round_scale_and_reads_u1h_within_its_bound(a3_set):
    """The same on GEARS48's A3 set (the lead's note: μω not round on the sets)."""
    test_the_plan_of_angular_velocities_has_a_round_scale_and_a_ruler_length_pole_distance(a3_set)
    test_u1h_is_willis_and_the_drawing_reads_it_within_the_stated_bound(a3_set)
