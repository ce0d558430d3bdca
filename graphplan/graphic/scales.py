"""Scale coefficients from the standard series: 1, 2, 2.5, 4, 5 × 10^k units per millimetre.

A scale coefficient μ is "real value per drawn millimetre" (μl = l_OA / OA, m/mm). The draftsman
picks the one of the series that makes a chosen segment (the crank OA, the vector p_v a, π a) fill a
target range of drawn lengths, and takes a coarser one when another segment would not fit the figure.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from graphplan.util.errors import GraphplanError

SERIES = (1.0, 2.0, 2.5, 4.0, 5.0)

UNITS = {"mu_l": "m/mm", "mu_v": "(m/s)/mm", "mu_a": "(m/s²)/mm", "mu_F": "N/mm"}
SYMBOLS = {"mu_l": "μl", "mu_v": "μv", "mu_a": "μa", "mu_F": "μF"}


@dataclass(frozen=True)
class Targets:
    """Drawn lengths (mm) the scales aim at. ``crank``: the crank OA on the position plan;
    ``velocity``: p_v a; ``acceleration``: π a; ``figure``: the longest vector of any plan;
    ``layout``: the widest extent of the position plan. A sheet asks for smaller or larger
    figures by passing its own Targets."""
    crank: tuple[float, float] = (40.0, 70.0)
    velocity: tuple[float, float] = (50.0, 100.0)
    acceleration: tuple[float, float] = (60.0, 120.0)
    figure: float = 200.0
    layout: float = 450.0

    def scaled(self, k: float) -> Targets:
        """All targets multiplied by ``k`` (k < 1: smaller figures)."""
        def pair(p: tuple[float, float]) -> tuple[float, float]:
            return p[0] * k, p[1] * k
        return Targets(pair(self.crank), pair(self.velocity), pair(self.acceleration),
                       self.figure * k, self.layout * k)


def series_value(m: float, k: int) -> float:
    """m·10^k as the nearest float (0.0025, not 0.0025000000000000005)."""
    return float(f"{m:g}e{k}")


def series_around(value: float) -> list[float]:
    """The standard scale values from about value/1000 to value·1000, ascending."""
    k0 = math.floor(math.log10(value))
    return [series_value(m, k) for k in range(k0 - 4, k0 + 5) for m in SERIES]


def at_least(value: float) -> float:
    """The smallest coefficient of the standard series 1, 2, 2.5, 4, 5 × 10^k that is ≥ ``value``."""
    if not (value > 0 and math.isfinite(value)):
        raise GraphplanError(f"cannot choose a scale for a segment of size {value!r}")
    return next(m for m in series_around(value) if m >= value * (1 - 1e-12))


def standard_scale(value: float, target_mm: tuple[float, float], fixed: float | None = None,
                   largest: float | None = None, limit_mm: float | None = None) -> float:
    """The scale coefficient μ of the standard series for a segment of real size ``value``.

    The finest μ (largest drawing) with value/μ ≤ target_mm[1]; the series steps by at most ×2, so
    the drawn length lands in the target whenever hi/lo ≥ 2. If ``largest``/μ would exceed
    ``limit_mm`` (another segment would not fit), the next coarser values are taken until it fits.
    ``fixed`` (the user's choice) is returned as it is after a check.
    """
    if fixed is not None:
        if not (isinstance(fixed, (int, float)) and math.isfinite(fixed) and fixed > 0):
            raise GraphplanError(f"a scale coefficient must be a positive number, got {fixed!r}")
        return float(fixed)
    lo, hi = target_mm
    if not (value > 0 and math.isfinite(value)):
        raise GraphplanError(f"cannot choose a scale for a segment of size {value!r}")
    if not 0 < lo <= hi:
        raise GraphplanError(f"a target range must have 0 < lo ≤ hi, got {target_mm!r}")
    need = value / hi
    if largest is not None and limit_mm is not None and largest > 0 and limit_mm > 0:
        need = max(need, largest / limit_mm)
    return at_least(need)


def format_scale(name: str, mu: float) -> str:
    """"μv = 0.2 (m/s)/mm" — the coefficient with its symbol and unit."""
    from graphplan.util.numbers import plain
    return f"{SYMBOLS.get(name, name)} = {plain(mu)} {UNITS.get(name, '')}".rstrip()
