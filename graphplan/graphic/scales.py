"""Scale coefficients from the standard series: 1, 2, 2.5, 4, 5 × 10^k units per millimetre.

A scale coefficient μ is "real value per drawn millimetre" (μl = l_OA / OA, m/mm). The draftsman
picks the one of the series that makes a chosen segment (the crank OA, the vector p_v a, π a) fill a
target range of drawn lengths, and takes a coarser one when another segment would not fit the figure.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache

from graphplan.util.errors import GraphplanError

SERIES = (1.0, 2.0, 2.5, 4.0, 5.0)
LEGIBLE_MM = 40.0   # docs/scenes.md: a plan reads when the crank pin's p_v a (π a) is at least this long

UNITS = {"mu_l": "m/mm", "mu_v": "(m/s)/mm", "mu_a": "(m/s²)/mm", "mu_F": "N/mm"}
SYMBOLS = {"mu_l": "μ_l", "mu_v": "μ_v", "mu_a": "μ_a", "mu_F": "μ_F", "mu_t": "μ_t", "mu_s": "μ_s",
           "mu_M": "μ_M"}   # markup (util.markup): μ with a subscript


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


@lru_cache(maxsize=4096)
def series_value(m: float, k: int) -> float:
    """m·10^k as the nearest float (0.0025, not 0.0025000000000000005)."""
    return float(f"{m:g}e{k}")


@lru_cache(maxsize=256)
def _series_from(k0: int) -> tuple[float, ...]:
    return tuple(series_value(m, k) for k in range(k0 - 4, k0 + 5) for m in SERIES)


def series_around(value: float) -> list[float]:
    """The standard scale values from about value/1000 to value·1000, ascending."""
    return list(_series_from(math.floor(math.log10(value))))


def at_least(value: float) -> float:
    """The smallest coefficient of the standard series 1, 2, 2.5, 4, 5 × 10^k that is ≥ ``value``."""
    if not (value > 0 and math.isfinite(value)):
        raise GraphplanError(f"cannot choose a scale for a segment of size {value!r}")
    return next(m for m in series_around(value) if m >= value * (1 - 1e-12))


def at_most(value: float) -> float:
    """The largest coefficient of the standard series 1, 2, 2.5, 4, 5 × 10^k that is ≤ ``value``."""
    if not (value > 0 and math.isfinite(value)):
        raise GraphplanError(f"cannot choose a scale for a segment of size {value!r}")
    return max(m for m in series_around(value) if m <= value * (1 + 1e-12))


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


GOST_BETWEEN = (1.5, 7.5)   # GOST 2.302's reductions 1:15 and 1:75 (×10^k) between the series' steps


def legible_values(mu: float, finer: float) -> list[float]:
    """The scale coefficients a draftsman may take between the series' ``mu`` and the next finer
    ``finer`` (a drawing twice as large): GOST 2.302's 1.5 and 7.5 × 10^k — 0.015 between 0.02 and
    0.01 — then ``finer`` itself; coarsest (smallest drawing) first."""
    k0 = math.floor(math.log10(mu))
    inner = [series_value(m, k) for k in range(k0 - 2, k0 + 2) for m in GOST_BETWEEN]
    return sorted({v for v in inner if finer * (1 + 1e-9) < v < mu * (1 - 1e-9)} | {finer}, reverse=True)


LEGIBLE_READS = 0.25   # mm: a vector this much short of ``LEGIBLE_MM`` reads 40 on the 0.5-mm ruler
PLAN_MM = 100.0        # … or its largest plan drawn at least this across (sheets.kinlayout; the explorer's step 0)


def chosen_length(value: float, length_mm: float, reads_mm: float = 0.0) -> float:
    """The lab's own way (REFERENCE §3, seed 004's π a = 110 mm): choose the drawn length of the
    crank pin's vector, then μ = value / length — written to three significant figures, rounded
    down, so the vector is drawn at least ``length_mm`` long (v_A = 0.754 m/s, p_v a = 40 mm:
    μv = 0.0188 (m/s)/mm, p_v a = 40.1 mm). With ``reads_mm`` (half the ruler's division) a μ of
    two figures is written where it draws the vector within that of the length, or at most 1 %
    longer — as a student rounds it (v_A = 1.398 m/s, 40 mm: μv = 0.035, p_v a = 39.94 mm, read
    40.0; not 0.0349)."""
    if not (value > 0 and length_mm > 0 and math.isfinite(value / length_mm)):
        raise GraphplanError(f"cannot choose a scale for a segment of size {value!r} drawn {length_mm!r} mm")
    raw = value / length_mm
    if reads_mm > 0:
        two = float(f"{raw:.2g}")
        if length_mm - reads_mm <= value / two < length_mm * 1.01:
            return two
    k = math.floor(math.log10(raw)) - 2
    return series_value(math.floor(raw / 10.0 ** k * (1 + 1e-12)), k)


GOST_LENGTH_BETWEEN = (15.0, 75.0)   # GOST 2.302 draws 1.5, 7.5 × 10^k only as 1:15 and 1:75 (μl 0.015, 0.075 m/mm)


def gost_length(mu_l: float) -> bool:
    """Whether μl (m/mm) is a drawing scale of GOST 2.302: the series' 1, 2, 2.5, 4, 5 × 10^k
    (1:2.5, 2:1, 4:1 …: the series holds its reciprocals) or the reductions 1:15 and 1:75 — not
    0.00075 m/mm (1.333:1) nor 0.0015 (1:1.5)."""
    ratio = mu_l * 1000.0
    return on_series(mu_l) or any(abs(ratio - g) <= 1e-9 * g for g in GOST_LENGTH_BETWEEN)


def next_round(mu: float) -> float:
    """The next finer round coefficient (a larger drawing): the series' 1, 2, 2.5, 4, 5 and GOST
    2.302's 1.5, 7.5 × 10^k — 0.04 → 0.025, 0.02 → 0.015 → 0.01."""
    k0 = math.floor(math.log10(mu))
    return max(series_value(m, k) for k in range(k0 - 1, k0 + 2) for m in SERIES + GOST_BETWEEN
               if series_value(m, k) < mu * (1 - 1e-9))


def larger_choices(value: float, mu: float, longest_mm: float, step_mm: float = 5.0) -> list[tuple[float, bool]]:
    """The scale coefficients that draw ``value`` larger than ``mu`` does, up to ``longest_mm``, as
    the plans choose theirs (sheets/kinlayout.legible_where_room): the round ones — the series'
    1, 2, 2.5, 4, 5 and GOST 2.302's 1.5, 7.5 × 10^k — and the lab's own, the drawn length chosen
    (multiples of ``step_mm``) with μ = value / length at three figures (``chosen_length``).
    (μ, round?) pairs, the smallest drawing first."""
    if not (value > 0 and mu > 0 and math.isfinite(value / mu)):
        return []
    k0 = math.floor(math.log10(value / longest_mm)) if longest_mm > 0 else 0
    rounds = {series_value(m, k) for k in range(k0 - 1, k0 + 3) for m in SERIES + GOST_BETWEEN}
    drawn = value / mu
    lengths = [step_mm * j for j in range(int(drawn // step_mm) + 1, int(longest_mm // step_mm) + 1)]
    chosen = {chosen_length(value, n) for n in lengths}
    out = {(m, True) for m in rounds} | {(m, False) for m in chosen - rounds}
    return sorted(((m, r) for m, r in out if value / m <= longest_mm + 1e-9 and m < mu * (1 - 1e-9)),
                  key=lambda c: (-c[0], not c[1]))


def series_choices(value: float, mu: float, longest_mm: float) -> list[float]:
    """The standard series' coefficients (1, 2, 2.5, 4, 5 × 10^k) that draw ``value`` larger than
    ``mu`` does, up to ``longest_mm``, the smallest drawing first: a set's plans grown into the room
    its sheets give (sheets.kinlayout's ``set_of_sheets``) at the series' scales, as docs and LAYOUT require ("the
    largest standard value whose drawings fit") — not GOST 2.302's 1.5, 7.5 × 10^k nor the lab's
    own π a chosen in 5-mm steps (review 58 #2: 0.0272 (m/s²)/mm, π a 145 mm)."""
    if not (value > 0 and mu > 0 and math.isfinite(value / mu)):
        return []
    return sorted((m for m in series_around(mu) if m < mu * (1 - 1e-9) and value / m <= longest_mm + 1e-9),
                  reverse=True)


def on_round(mu: float) -> bool:
    """Whether μ is a round value: the series' or GOST 2.302's 1.5, 7.5 × 10^k."""
    k = math.floor(math.log10(mu))
    return on_series(mu) or any(abs(mu - series_value(g, k)) <= 1e-12 * mu for g in GOST_BETWEEN)


ROUND_SHARE = 0.9     # a round coefficient is taken where it draws at least this share of the chosen length


def filling(value: float, length_mm: float, figures: int = 2) -> float:
    """The coefficient that draws ``value`` as nearly ``length_mm`` long as the lab draws it, and no
    longer: a round one (the series, GOST's 1.5, 7.5 × 10^k) where that draws it at least
    ``ROUND_SHARE`` of the length, else μ = value / length to ``figures`` significant figures
    rounded up (the lab's own way, ``chosen_length``; 9150 N in 70 mm: 140 N/mm, drawn 65.4 mm —
    two figures draw it at least 0.91 of the length)."""
    if not (value > 0 and length_mm > 0 and math.isfinite(value / length_mm)):
        raise GraphplanError(f"cannot choose a scale for a segment of size {value!r} drawn {length_mm!r} mm")
    need = value / length_mm
    k0 = math.floor(math.log10(need))
    rounds = sorted(series_value(m, k) for k in (k0, k0 + 1) for m in SERIES + GOST_BETWEEN)
    best = next(m for m in rounds if m >= need * (1 - 1e-12))
    if need / best >= ROUND_SHARE - 1e-12:
        return best
    k = k0 - (figures - 1)
    return series_value(math.ceil(need / 10.0 ** k * (1 - 1e-12)), k)


def on_series(mu: float) -> bool:
    """Whether μ is a value of the standard series 1, 2, 2.5, 4, 5 × 10^k."""
    return mu > 0 and abs(at_least(mu) - mu) <= 1e-12 * mu


def format_scale(name: str, mu: float, lang: str = "en") -> str:
    """"μ_v = 0.2 (m/s)/mm" (Ukrainian: "μ_v = 0,2 (м/с)/мм") — the coefficient with its symbol
    (markup) and unit in the language."""
    from graphplan.util.words import num, unit
    u = UNITS.get(name)
    return f"{SYMBOLS.get(name, name)} = {num(mu, lang)} {unit(u, lang) if u else ''}".rstrip()
