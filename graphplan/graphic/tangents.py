"""Graphical differentiation by the method of tangents (seed 002, REFERENCE §1.10), as drawn.

At each division point of the drawn curve the draftsman draws the tangent; a ray from the pole P,
H to the left of the origin, parallel to the tangent, cuts the ordinate axis at y' = H·tg α, and that
height, read with the ruler, is carried to the SAME abscissa (not the middle of an interval, as with
chords): y'(x_k) = H·dy/dx(x_k), the scale μ_y' = μ_y/(μ_x·H), the same as for chords.

**The technique: the mirror.** A flat mirror (or the polished edge of a ruler) is stood on the paper
across the curve at the point and turned until the curve and its reflection join without a kink; the
mirror then lies along the normal, and the tangent is drawn perpendicular to it with a set square.
It is chosen over "a chord pair symmetric about the point" because its only error is the angle the eye
accepts: the chord pair adds a truncation error (δ²/6·y‴ for chords ±δ about the point) that the
method of chords already shows, and the point of the tangents is to avoid it.

**The angular error model.** A kink between the curve and its reflection is seen when the two
branches part by about one line width over the stretch the eye compares: the reflection turns by
twice the mirror's misalignment δ, so 2δ·ℓ ≈ s. With the thin line s ≈ 0.35 mm (GOST 2.303: s/2 of
0.7 mm) and ℓ ≈ 10 mm on each side of the point, δ ≈ 0.35/20 rad ≈ 1.0°: the default bound
``ANGLE_ERROR_DEG``. Each tangent's direction is off by an angle drawn uniformly from [−ε, +ε] by
numpy's PCG64 generator seeded with (``seed``, stage): deterministic — the same sheet gives the same
drawing — and a larger ε scales the same draws, so the error grows with ε. ε = 0 is the exact
tangent. The parallel carried to the pole is taken as exact, as the chords' rays are.
"""
from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from graphplan.graphic.chords import integrate_by_chords, midpoints, periodic_spline, periodic_spline_slope, read

ANGLE_ERROR_DEG = 1.0   # the eye's bound on a tangent by the mirror: 0.35 mm line over 2 × 10 mm
SEED = 2002             # the drafting error's generator seed (seed 002's lab)
MAX_ANGLE_ERROR_DEG = 30.0


@dataclass(frozen=True)
class Curve:
    """A curve as it lies on the drawing: ordinate and slope (mm and mm/mm) at any abscissa."""
    at: Callable[[np.ndarray], np.ndarray]
    slope: Callable[[np.ndarray], np.ndarray]


def drawn_curve(x: np.ndarray, y: np.ndarray, period: float) -> Curve:
    """The French curve through the points (x_k, y_k), k = 0 … n (x_n = x_0 + period): periodic
    after taking off the trend y_n − y_0 over the period (a turning link's angle keeps growing)."""
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    trend = (y[-1] - y[0]) / period
    base = y[:-1] - trend * (x[:-1] - x[0])
    at, slope = periodic_spline(x[:-1], base, period), periodic_spline_slope(x[:-1], base, period)
    return Curve(lambda q: at(q) + trend * (np.asarray(q, dtype=float) - x[0]),
                 lambda q: slope(q) + trend)


def angle_errors(n: int, bound_deg: float, stage: int, seed: int = SEED) -> np.ndarray:
    """The draftsman's error of each of ``n`` tangents (rad): uniform in [−ε, +ε], ε = ``bound_deg``,
    from PCG64 seeded with (seed, stage) — deterministic, and proportional to ε for the same draws."""
    if bound_deg == 0:
        return np.zeros(n)
    unit = np.random.default_rng([seed, stage]).uniform(-1.0, 1.0, n)
    return unit * math.radians(bound_deg)


def mirror_tangents(curve: Curve, x: np.ndarray, errors: np.ndarray) -> np.ndarray:
    """The tangents' directions at the abscissae ``x`` found with the mirror (see the module's
    docstring): the curve's own direction α = atan(dy/dx), turned by the draftsman's error (rad)."""
    return np.arctan(curve.slope(x)) + errors


def tangent_heights(alpha: np.ndarray, pole: float) -> np.ndarray:
    """The heights cut on the ordinate axis by rays from the pole P (H left of the origin) parallel
    to tangents at angles α: y' = H·tg α."""
    return pole * np.tan(alpha)


@dataclass
class TangentReading:
    """One run of the method of tangents, in drawing mm; the fields mirror the chords' Reading, with
    v and a at the division ordinates 0 … n−1 (where the tangents are drawn)."""
    s: np.ndarray        # s read at the division ordinates (n + 1)
    v_ray: np.ndarray    # the heights the rays parallel to the tangents of s cut, n
    v: np.ndarray        # … read: v at the division ordinates, n
    v_at: np.ndarray     # the same closed by the period (n + 1)
    a_ray: np.ndarray    # heights of the rays parallel to the tangents of the v curve, n
    a: np.ndarray        # … read, n
    a_at: np.ndarray     # closed by the period, n + 1
    v_int: np.ndarray    # graphical integration a → v (chords), at the division ordinates, n + 1
    s_int: np.ndarray    # … then v → s, n + 1
    s_int_v: np.ndarray  # integration of the v curve straight back to s, n + 1
    alpha_s: np.ndarray  # the tangents' directions drawn on s (rad), n
    alpha_v: np.ndarray  # … on v, n


def construct_tangents(x: np.ndarray, s_mm: np.ndarray, L: float, H1: float, H2: float, precision: float,
                       angle_error_deg: float = ANGLE_ERROR_DEG, seed: int = SEED,
                       s_curve: Curve | None = None, v_curve: Curve | None = None) -> TangentReading:
    """The draftsman's sequence with tangents: s read at the division ordinates and the French curve
    drawn through them (or ``s_curve``, e.g. the exact s(t)); a tangent at each division point by the
    mirror; the ray from P at H1 parallel to it; its height read and carried to the same abscissa:
    v. Then the French curve through the v points (or ``v_curve``) and the same with H2: a."""
    x = np.asarray(x, dtype=float)
    at = x[:-1]
    n = len(at)
    s = read(s_mm, precision)
    s_curve = s_curve or drawn_curve(x, s, L)
    alpha_s = mirror_tangents(s_curve, at, angle_errors(n, angle_error_deg, 1, seed))
    v_ray = tangent_heights(alpha_s, H1)
    v = read(v_ray, precision)
    v_at = np.append(v, v[0])
    v_curve = v_curve or drawn_curve(x, v_at, L)
    alpha_v = mirror_tangents(v_curve, at, angle_errors(n, angle_error_deg, 2, seed))
    a_ray = tangent_heights(alpha_v, H2)
    a = read(a_ray, precision)
    a_at = np.append(a, a[0])
    # graphical integration, the reverse construction by chords: the curves read at the middles
    xm = midpoints(x)
    a_mid = read(periodic_spline(at, a, L)(xm), precision)
    v_int = integrate_by_chords(x, a_mid, H2, v_at[0])
    v_int_mid = read(periodic_spline(at, v_int[:-1], L)(xm), precision)
    s_int = read(integrate_by_chords(x, v_int_mid, H1, s[0]), precision)
    s_int_v = read(integrate_by_chords(x, read(v_curve.at(xm), precision), H1, s[0]), precision)
    return TangentReading(s, v_ray, v, v_at, a_ray, a, a_at, read(v_int, precision), s_int, s_int_v,
                          alpha_s, alpha_v)
