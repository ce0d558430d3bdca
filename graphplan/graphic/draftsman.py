"""The draftsman's acts in drawing millimetres, on complex numbers: a length read with a ruler,
two compass arcs (засічки), a line through a point along a direction, their intersections."""
from __future__ import annotations

import cmath
import math


from graphplan.util.errors import GraphplanError


# -- measuring with a ruler ---------------------------------------------------------------------

def measure(length_mm: float, precision: float) -> float:
    """A length read with a ruler: rounded to the nearest multiple of ``precision`` (0 = exact).

    The one ruler of every construction (plans, force plans, diagrams). A reading exactly half a
    division between two marks goes to the even mark, as numpy and Python round: constructions
    whose lengths are multiples of earlier readings meet such ties often (a chord's height with
    H/Δx = 1.5 turns 0.5 mm into 0.75 mm), and always rounding them up biases every integrated
    diagram (the shaper's s from a, 12 divisions: 7.0 % of the maximum against 1.0 %)."""
    if precision <= 0:
        return float(length_mm)
    return float(precision * round(length_mm / precision))


def measure_all(mm, precision: float):
    """The same ruler over an array of lengths (diagram ordinates), ties to the even mark;
    readings rounded to 1e-10 mm so 0.1-mm readings print as 27.3, not 27.300000000000004."""
    import numpy as np
    y = np.asarray(mm, dtype=float)
    if precision <= 0:
        return y
    return np.round(np.round(y / precision) * precision, 10) + 0.0  # + 0.0: no −0 readings


lay_off = measure   # laying a computed length off with the same ruler rounds it the same way


def unit(z: complex) -> complex:
    n = abs(z)
    return z / n if n > 0 else 0j


def cross(u: complex, w: complex) -> float:
    """z-component of u × w."""
    return (u.conjugate() * w).imag


def dot(u: complex, w: complex) -> float:
    return (u.conjugate() * w).real


def crossing_angle(d1: complex, d2: complex) -> float:
    """The acute angle (deg) between two lines of directions d1, d2."""
    s = abs(cross(unit(d1), unit(d2)))
    c = abs(dot(unit(d1), unit(d2)))
    return math.degrees(math.atan2(s, c))


# -- the compass-and-ruler constructions (drawing mm, complex numbers) ---------------------------

def line_line(p1: complex, d1: complex, p2: complex, d2: complex) -> complex:
    """The intersection of the line through p1 along d1 with the line through p2 along d2."""
    det = cross(d1, d2)
    if det == 0:
        raise GraphplanError("two direction lines are parallel: the construction has no intersection")
    t = cross(p2 - p1, d2) / det
    return p1 + t * d1


def circle_circle(c1: complex, r1: float, c2: complex, r2: float, branch: int) -> complex:
    """Two compass arcs (засічки): the intersection of circles (c1, r1), (c2, r2) to the left of
    c1→c2 for branch +1, to the right for −1."""
    span = c2 - c1
    dist = abs(span)
    along = (dist ** 2 + r1 ** 2 - r2 ** 2) / (2 * dist)
    h = math.sqrt(max(r1 ** 2 - along ** 2, 0.0))
    return c1 + (along + 1j * branch * h) * span / dist


def circle_line(c: complex, r: float, p: complex, d: complex, branch: int) -> complex:
    """An arc of radius r about c crossing the line through p along d (unit): the crossing ahead
    of the foot of the perpendicular from c (along d) for branch +1, behind it for −1."""
    foot = -dot(d, p - c)
    disc = foot ** 2 - abs(p - c) ** 2 + r ** 2
    return p + (foot + branch * math.sqrt(max(disc, 0.0))) * d


def line_through_pivot(ps: complex, pc: complex, offset: float, branch: int) -> float:
    """The direction angle (rad) of the rocker's line through the block's point ``ps`` that passes
    at the distance ``offset`` (signed, left of the line) from the pivot ``pc`` — for a slot through
    the pivot, simply the line pc→ps (branch +1) or ps→pc (−1)."""
    rho = ps - pc
    beta = math.asin(max(-1.0, min(1.0, offset / abs(rho))))
    if branch < 0:
        beta = math.pi - beta
    return cmath.phase(rho) - beta
