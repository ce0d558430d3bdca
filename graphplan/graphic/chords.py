"""Graphical differentiation and integration by chords, as on a drawing (seed 002, REFERENCE §1.5).

Everything here works in drawing millimetres: abscissae x (mm along the time axis) and ordinates y
(mm). The pole construction turns a chord's slope Δy/Δx into a height y' = H·Δy/Δx on the ordinate
axis (the ray from the pole P, at the pole distance H left of the origin, drawn parallel to the chord);
the scale of the derived diagram is μ_y' = μ_y / (μ_x·H). A periodic cubic spline stands for the
French curve through the constructed points.
"""
from __future__ import annotations

from collections.abc import Callable

import numpy as np

from graphplan.graphic.draftsman import measure_all as read  # noqa: F401  (the one ruler)
from graphplan.graphic.scales import SERIES, at_least as standard_scale  # noqa: F401  (the one series)


def midpoints(x: np.ndarray) -> np.ndarray:
    """Middles of the intervals between consecutive division ordinates."""
    x = np.asarray(x, dtype=float)
    return 0.5 * (x[:-1] + x[1:])


def pole_heights(x: np.ndarray, y: np.ndarray, pole: float) -> np.ndarray:
    """The heights cut on the ordinate axis by rays from the pole parallel to the chords:
    y'_k = H·(y_{k+1} − y_k)/(x_{k+1} − x_k) — the derived ordinate at the middle of interval k."""
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    return pole * np.diff(y) / np.diff(x)


def integrate_by_chords(x: np.ndarray, y_mid: np.ndarray, pole: float, y0: float) -> np.ndarray:
    """The reverse construction (graphical integration): the height y'_k of interval k, carried to
    the ordinate axis and joined to the pole, gives the direction of the integral curve's chord
    over that interval: Y_{k+1} = Y_k + y'_k·(x_{k+1} − x_k)/H, starting from Y_0 = y0."""
    steps = np.asarray(y_mid, dtype=float) * np.diff(np.asarray(x, dtype=float)) / pole
    return y0 + np.concatenate(([0.0], np.cumsum(steps)))


def spline_moments(x: np.ndarray, y: np.ndarray, period: float
                   ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The periodic cubic spline through (x_i, y_i), i = 0 … n−1, of the given period (n ≥ 3,
    x increasing, x_{n−1} < x_0 + period): its knots and ordinates closed by one period (n + 1),
    the knot spacings h (n) and the second derivatives M (n + 1) from the cyclic system
    h_{i−1}M_{i−1} + 2(h_{i−1} + h_i)M_i + h_iM_{i+1} = 6(d_i − d_{i−1}),  d_i = (y_{i+1} − y_i)/h_i."""
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    n = len(x)
    if n < 3:
        raise ValueError("a periodic spline needs at least 3 points")
    xs = np.append(x, x[0] + period)
    ys = np.append(y, y[0])
    h = np.diff(xs)
    d = np.diff(ys) / h
    idx = np.arange(n)
    prev = (idx - 1) % n
    if n > DENSE_MAX:
        M = _cyclic_solve(h[prev], 2 * (h[prev] + h), h, 6 * (d - d[prev]))
        return xs, ys, h, np.append(M, M[0])
    A = np.zeros((n, n))
    A[idx, prev] += h[prev]
    A[idx, idx] += 2 * (h[prev] + h)
    A[idx, (idx + 1) % n] += h
    M = np.linalg.solve(A, 6 * (d - d[prev]))
    return xs, ys, h, np.append(M, M[0])


DENSE_MAX = 64    # the cyclic system solved densely up to this size (n³, fast and bit-stable when small)


def _cyclic_solve(lower: np.ndarray, diag: np.ndarray, upper: np.ndarray, rhs: np.ndarray) -> np.ndarray:
    """The cyclic tridiagonal system lower_i·M_{i−1} + diag_i·M_i + upper_i·M_{i+1} = rhs_i (indices
    mod n) in O(n): the tridiagonal part by scipy's banded solver, the two corner entries by the
    Sherman–Morrison formula (A = B + u·vᵀ, u = (γ, 0 … 0, c), v = (1, 0 … 0, a/γ), γ = −diag_0)."""
    from scipy.linalg import solve_banded
    n = len(diag)
    a, c = lower[0], upper[-1]                 # A[0, n−1] and A[n−1, 0]
    gamma = -diag[0]
    band = np.zeros((3, n))
    band[0, 1:] = upper[:-1]
    band[1] = diag
    band[1, 0] -= gamma
    band[1, -1] -= c * a / gamma
    band[2, :-1] = lower[1:]
    u = np.zeros(n)
    u[0], u[-1] = gamma, c
    y = solve_banded((1, 1), band, rhs)
    z = solve_banded((1, 1), band, u)
    vy = y[0] + a / gamma * y[-1]
    vz = z[0] + a / gamma * z[-1]
    return y - z * vy / (1.0 + vz)


def _piece(xs: np.ndarray, period: float, q: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The query abscissae brought into the first period and the index of the piece holding each."""
    u = xs[0] + np.mod(np.asarray(q, dtype=float) - xs[0], period)
    return u, np.clip(np.searchsorted(xs, u, side="right") - 1, 0, len(xs) - 2)


def periodic_spline(x: np.ndarray, y: np.ndarray, period: float) -> Callable[[np.ndarray], np.ndarray]:
    """The periodic cubic spline through (x_i, y_i) (see ``spline_moments``): the French curve."""
    xs, ys, h, Ms = spline_moments(x, y, period)

    def spline(q: np.ndarray) -> np.ndarray:
        u, i = _piece(xs, period, q)
        hi = h[i]
        a, b = xs[i + 1] - u, u - xs[i]
        return (Ms[i] * a ** 3 + Ms[i + 1] * b ** 3) / (6 * hi) \
            + (ys[i] / hi - Ms[i] * hi / 6) * a + (ys[i + 1] / hi - Ms[i + 1] * hi / 6) * b

    return spline


def periodic_pchip(x: np.ndarray, y: np.ndarray, period: float) -> Callable[[np.ndarray], np.ndarray]:
    """The periodic shape-preserving cubic through (x_i, y_i), i = 0 … n−1 (scipy's
    PchipInterpolator, Fritsch–Carlson slopes): each piece stays between its two ordinates (zero
    slope at a local extremum), so a positive quantity's curve never runs below its least point,
    as the French curve (``periodic_spline``) does between divisions. A slope depends only on the
    two neighbours, so the ordinates continued two points into either next period make it periodic."""
    from scipy.interpolate import PchipInterpolator
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    n = len(x)
    if n < 3:
        raise ValueError("a periodic interpolant needs at least 3 points")
    xs = np.concatenate([x[-2:] - period, x, x[:3] + period])
    ys = np.concatenate([y[-2:], y, y[:3]])
    curve = PchipInterpolator(xs, ys, extrapolate=False)

    def pchip(q: np.ndarray) -> np.ndarray:
        return curve(x[0] + np.mod(np.asarray(q, dtype=float) - x[0], period))

    return pchip


def periodic_spline_slope(x: np.ndarray, y: np.ndarray, period: float) -> Callable[[np.ndarray], np.ndarray]:
    """The slope S'(q) of the same periodic spline: on the piece [x_i, x_{i+1}], with a = x_{i+1} − q,
    b = q − x_i, S' = (M_{i+1}·b² − M_i·a²)/(2h_i) + (y_{i+1} − y_i)/h_i − (M_{i+1} − M_i)·h_i/6."""
    xs, ys, h, Ms = spline_moments(x, y, period)

    def slope(q: np.ndarray) -> np.ndarray:
        u, i = _piece(xs, period, q)
        hi = h[i]
        a, b = xs[i + 1] - u, u - xs[i]
        return (Ms[i + 1] * b ** 2 - Ms[i] * a ** 2) / (2 * hi) + (ys[i + 1] - ys[i]) / hi \
            - (Ms[i + 1] - Ms[i]) * hi / 6

    return slope


def divided_differences(x: np.ndarray, y: np.ndarray, order: int, period: float) -> np.ndarray:
    """Periodic divided differences f[x_k, …, x_{k+order}] of samples of a periodic curve, one per k;
    ``x`` holds one period (n points) and the abscissae continue as x_{k+n} = x_k + period."""
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    n = len(x)
    k = np.arange(n)
    xx = lambda j: x[(k + j) % n] + period * ((k + j) // n)  # noqa: E731
    table = [y[(k + j) % n] for j in range(order + 1)]
    for level in range(1, order + 1):
        table = [(table[j + 1] - table[j]) / (xx(j + level) - xx(j)) for j in range(order + 1 - level)]
    return table[0]


def chord_error_estimate(x: np.ndarray, y: np.ndarray, period: float) -> tuple[np.ndarray, np.ndarray]:
    """What a draftsman can see from the curve alone: per interval k, the error of the derived
    ordinate at its middle, y'(mid) − Δy/Δx ≈ −h²/24·y''', and of the second derivative taken by
    chords again, ≈ −h²/12·y'''' (both in units of y per x^1 and x^2). y''' from the third divided
    difference over the four ordinates around the interval, y'''' from the change of y'''.
    ``x``, ``y`` hold one period (n points, the curve periodic after removing its trend)."""
    x = np.asarray(x, dtype=float)
    n = len(x)
    h = np.diff(np.append(x, x[0] + period))
    d3 = 6 * divided_differences(np.roll(x, 1) - np.where(np.arange(n) == 0, period, 0.0),
                                 np.roll(y, 1), 3, period)  # ordinates k−1 … k+2
    mids = x + h / 2
    d4 = (np.roll(d3, -1) - np.roll(d3, 1)) / (np.roll(mids, -1) - np.roll(mids, 1) + period * _wrap(n))
    return h ** 2 / 24 * np.abs(d3), h ** 2 / 12 * np.abs(d4)


def _wrap(n: int) -> np.ndarray:
    """+1 period where the next-minus-previous middle crosses the period's end (first and last)."""
    w = np.zeros(n)
    w[0] = 1.0
    w[-1] = 1.0
    return w
