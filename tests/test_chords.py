"""The drawing-board numerics of the chord method against closed forms and an independent spline."""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st_

from graphplan.graphic.chords import (SERIES, chord_error_estimate, integrate_by_chords, midpoints,
                              periodic_pchip, periodic_spline, pole_heights, read, standard_scale)


@given(st_.floats(min_value=1e-9, max_value=1e9, allow_nan=False, allow_infinity=False))
def test_standard_scale_is_the_smallest_series_value_not_below(x):
    mu = standard_scale(x)
    mantissa = mu / 10 ** math.floor(math.log10(mu) + 1e-12)
    assert any(abs(mantissa - m) < 1e-9 for m in SERIES)
    assert mu >= x * (1 - 1e-12)
    below = [m * 10.0 ** e for m in SERIES for e in range(-12, 12) if m * 10.0 ** e < mu * (1 - 1e-9)]
    assert max(below) < x


@given(st_.lists(st_.floats(-500, 500), min_size=1, max_size=20), st_.sampled_from([0.1, 0.25, 0.5, 1.0]))
def test_ruler_reading_is_the_nearest_multiple(values, p):
    y = np.array(values)
    r = read(y, p)
    assert np.all(np.abs(r - y) <= p / 2 + 1e-9)
    assert np.allclose(r / p, np.round(r / p), atol=1e-6)
    assert np.array_equal(read(y, 0.0), y)
    assert not np.any(np.signbit(read(np.array([-0.1]), 0.5)))  # no "−0" reading


def test_chord_of_a_parabola_is_parallel_to_the_tangent_at_the_middle():
    # f = c·x² + b·x: (f(x2) − f(x1))/(x2 − x1) = f'((x1 + x2)/2) exactly — the seed's mean-value theorem
    x = np.array([0.0, 7.0, 11.5, 30.0, 31.0])
    f = 0.03 * x ** 2 - 0.4 * x
    H = 25.0
    assert np.allclose(pole_heights(x, f, H), H * (0.06 * midpoints(x) - 0.4), rtol=1e-13)


def test_integration_undoes_differentiation_and_integrates_cos():
    rng = np.random.default_rng(1)
    x = np.sort(np.concatenate(([0.0, 240.0], rng.uniform(0, 240, 20))))
    y = rng.normal(size=x.size)
    assert np.allclose(integrate_by_chords(x, pole_heights(x, y, 30.0), 30.0, y[0]), y, atol=1e-12)
    # ∫cos = sin with chords at the middles: error O(h²)
    errs = []
    for n in (16, 32, 64):
        x = np.linspace(0, 2 * np.pi, n + 1)
        got = integrate_by_chords(x, np.cos(midpoints(x)), 1.0, 0.0)
        errs.append(np.max(np.abs(got - np.sin(x))))
    assert errs[0] / errs[1] == pytest.approx(4, rel=0.05) and errs[1] / errs[2] == pytest.approx(4, rel=0.05)


@settings(max_examples=25, deadline=None)
@given(st_.integers(min_value=3, max_value=30), st_.integers(min_value=0, max_value=2 ** 31))
def test_periodic_spline_agrees_with_scipy(n, seed):
    from scipy.interpolate import CubicSpline
    rng = np.random.default_rng(seed)
    period = 240.0
    x = np.sort(rng.uniform(0, period, n))
    if np.min(np.diff(np.append(x, x[0] + period))) < 1e-3:
        return
    y = rng.normal(size=n)
    ours = periodic_spline(x, y, period)
    ref = CubicSpline(np.append(x, x[0] + period), np.append(y, y[0]), bc_type="periodic")
    q = rng.uniform(-period, 2 * period, 50)
    expect = ref(x[0] + np.mod(q - x[0], period))
    assert np.allclose(ours(q), expect, atol=1e-9 * max(1.0, np.max(np.abs(expect))))
    assert np.allclose(ours(x), y, atol=1e-10)


@settings(max_examples=25, deadline=None)
@given(st_.integers(min_value=3, max_value=30), st_.integers(min_value=0, max_value=2 ** 31))
def test_periodic_pchip_keeps_each_piece_between_its_ordinates(n, seed):
    """The shape-preserving curve for a positive quantity: through every point, each piece between
    its two ordinates (so never below the least: I* ≥ 0 drawn), and periodic to the slope (the
    one-sided difference quotients at the seam x_0 and at x_0 + period agree)."""
    rng = np.random.default_rng(seed)
    period = 240.0
    x = np.sort(rng.uniform(0, period, n))
    if np.min(np.diff(np.append(x, x[0] + period))) < 1e-2:
        return
    y = rng.uniform(0.0, 1.0, n) ** 3            # positive, with sharp peaks a cubic spline overshoots
    f = periodic_pchip(x, y, period)
    assert np.allclose(f(x), y, atol=1e-12) and np.allclose(f(x + period), y, atol=1e-12)
    xs, ys = np.append(x, x[0] + period), np.append(y, y[0])
    for a, b, ya, yb in zip(xs[:-1], xs[1:], ys[:-1], ys[1:]):
        q = f(np.linspace(a, b, 41))
        assert np.all(q >= min(ya, yb) - 1e-12) and np.all(q <= max(ya, yb) + 1e-12)
    e = 1e-8                                      # small beside a piece's curvature (pieces ≥ 0.01 long)
    left = (f(np.array([x[0] + period - e]))[0] - y[0]) / -e
    right = (f(np.array([x[0] + e]))[0] - y[0]) / e
    assert left == pytest.approx(right, abs=1e-3 * (1 + abs(right)))


def test_the_cubic_spline_dips_where_the_shape_preserving_curve_does_not():
    """A peak between two flat stretches: the French curve (cubic spline) runs below the least
    ordinate 0.1 beside the peak; the shape-preserving one stays ≥ 0.1."""
    x = np.arange(12.0) * 20.0
    y = np.full(12, 0.1)
    y[5] = 1.0
    q = np.linspace(0.0, 240.0, 2401)
    assert np.min(periodic_spline(x, y, 240.0)(q)) < 0.05
    assert np.min(periodic_pchip(x, y, 240.0)(q)) >= 0.1 - 1e-12


def test_chord_error_estimate_predicts_the_midpoint_error():
    # y = sin(2πx/L)·A: the chord slope misses y' at the middle by ≈ h²/24·y'''; the second chord
    # differentiation misses y'' by ≈ h²/12·y''''
    L, A, n = 240.0, 40.0, 48
    k = 2 * np.pi / L
    x = np.linspace(0, L, n + 1)
    y = A * np.sin(k * x)
    est_v, est_a = chord_error_estimate(x[:-1], y[:-1], L)
    xm = midpoints(x)
    actual_v = np.abs(np.diff(y) / np.diff(x) - A * k * np.cos(k * xm))
    assert np.allclose(est_v, actual_v, rtol=0.02, atol=1e-3 * np.max(actual_v))
    assert np.allclose(est_a, A * k ** 4 * (L / n) ** 2 / 12 * np.abs(np.sin(k * xm)), rtol=0.02,
                       atol=1e-2 * np.max(est_a))
