"""The flywheel by the course's graphical method (the third sheet, REFERENCE §1.9), measured with
a ruler and compared with the exact flywheel of exact.dynamics.

The draftsman's sequence, in drawing millimetres over an abscissa of L mm for one turn
(μ_φ = 2π/L rad/mm), N divisions from position 0:
1. the diagram of the reduced moment of resistance M*_c(φ), μ_M from the standard series;
2. its graphical integration by chords (chords.integrate_by_chords): the ordinate at the middle
   of each interval (where M*_c drops or bends inside the interval — a load switching at a dead
   centre, a force profile's corner — the equal-area mean ordinate instead, ``mean_ordinates``), carried to the ordinate axis and joined to the pole at the pole distance H,
   gives the direction of the work curve's chord; A_c(φ) with μ_A = μ_M·μ_φ·H;
3. the driving work A_d: the straight line from the origin to A_c(2π) (a constant M*_d, whose
   ordinate on the moment diagram is the ray's height H·A_c(L)/L);
4. the change of kinetic energy ΔT = A_d − A_c: both ordinates read at each division and subtracted,
   as the lab's table does (μ_T = μ_A) — the sheet's table prints A_c, A_d and ΔT that agree;
5. the diagram of I*_m(φ) (μ_I);
6. the energy–mass (Wittenbauer) curve ΔT(I*_m) — φ eliminated, the points (I_k, ΔT_k) joined
   by the French curve — and its two tangents at tg ψ_max,min = μ_I·ω_m²·(1 ± δ)/(2·μ_T), which cut
   the ΔT axis at k and l: the constant reduced inertia J = μ_T·|kl|/(ω_m²·δ) and the flywheel
   I_fl = J − I_rotor·i² − I_reducer;
7. the approximate method: J ≈ (ΔT_max − ΔT_min)/(ω_m²·δ) − I*_mean, and Mertsalov's, which takes
   the mechanism's own kinetic energy ½·ω_m²·I*_m out of ΔT first.
The course's slopes drop the δ²/4 of ω²_max,min = ω_m²(1 ± δ/2)²; ``slopes="exact"`` keeps it
(then the construction converges to the exact flywheel as the divisions grow at precision 0).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from graphplan.exact.dynamics import Dynamics, reduce
from graphplan.graphic.chords import integrate_by_chords, midpoints, periodic_pchip, periodic_spline, read, standard_scale

M_HEIGHT = 100.0      # mm: the largest |M*_c| drawn about this high
A_HEIGHT = 120.0      # mm: the pole distance H is picked so A_c(2π) is drawn about this high
I_WIDTH = 140.0       # mm: the largest I*_m drawn about this long
ENERGY_SMALL = 0.25   # ΔT(φ) drawn at its own scale μ_T only where its span at μ_A is below this share of A_HEIGHT …
ENERGY_HEIGHT = 60.0  # mm: … then its span drawn about this high (μ_T the series' value at or above span/this)
CURVE = 40            # samples of the French curve per interval


@dataclass
class Flywheel:
    """The construction and its readings (mm) with the scales; values in SI."""
    dyn: Dynamics
    divisions: int
    L: float
    H: float
    precision: float
    slopes: str                 # "course" (1 ± δ) or "exact" ((1 ± δ/2)²)
    mu_M: float                 # N·m/mm
    mu_phi: float               # rad/mm
    mu_A: float                 # J/mm: the work diagrams'
    mu_I: float                 # kg·m²/mm
    x: np.ndarray               # division ordinates, mm (N + 1)
    turn: np.ndarray            # crank turns there, rad
    moment_exact: np.ndarray    # M*_c at the divisions, N·m (N + 1)
    inertia_exact: np.ndarray   # I*_m at the divisions (N + 1)
    d_inertia_exact: np.ndarray
    M: np.ndarray               # M*_c read at the divisions, mm (N + 1)
    M_mid: np.ndarray           # … at the middles of the intervals (the integration's heights), mm (N)
    A_drawn: np.ndarray         # the work curve's vertices by chords (geometry), mm (N + 1)
    A: np.ndarray               # … read, mm
    Md: float                   # the driving moment's ordinate on the M diagram, mm
    dT: np.ndarray              # ΔT read between A_d and A_c, mm (N + 1)
    I: np.ndarray               # I*_m read, mm (N + 1)
    tangent: dict[str, float]   # slopes tg ψ (mm/mm), the intercepts k, l (mm), the touching points
    kl: float                   # |kl| read, mm
    redrawn: Any = field(default=None)   # Redrawing: how ``redrawn`` chose the divisions (None: not asked)
    equal_area: tuple[int, ...] = ()     # intervals whose height is the equal-area mean (``mean_ordinates``)
    energy_scale: float | None = None    # J/mm: ΔT's own μ_T where it is finer than μ_A (``energy_scale``)
    # the construction's points: the divisions and, between them, the points added where M*_c jumps
    # or bends (exact.dynamics' ``breaks``: a load switching at a dead centre, a force profile's corner —
    # the lab divides where the curve bends, so ΔT's extremum there is constructed, not interpolated);
    # None: only the divisions. ``M_mid`` and ``equal_area_all`` are over these points' intervals
    x_all: np.ndarray | None = None
    turn_all: np.ndarray | None = None
    M_all: np.ndarray | None = None
    A_drawn_all: np.ndarray | None = None
    dT_all: np.ndarray | None = None
    I_all: np.ndarray | None = None
    added: tuple[int, ...] = ()          # indices into the ``*_all`` arrays of the added points
    equal_area_all: tuple[int, ...] = ()

    def points(self, name: str) -> tuple[np.ndarray, np.ndarray]:
        """(x, ordinates) of every constructed point of ``name`` ("dT", "I", "A_drawn", "M")."""
        y = getattr(self, f"{name}_all")
        return (self.x, getattr(self, name)) if y is None else (self.x_all, y)

    def added_label(self, j: int) -> str:
        """An added point lettered as the draftsman letters it: the division before it primed
        (2′, a second in the same interval 2″)."""
        xs = self.x_all
        k = int(np.searchsorted(self.x, xs[j], side="right")) - 1
        primes = sum(1 for i in self.added if self.x[k] < xs[i] <= xs[j])
        return f"{k}" + "′" * primes if primes < 3 else f"{k}({primes})"

    @property
    def mu_T(self) -> float:
        """ΔT(φ)'s and the energy–mass diagram's scale, J/mm: μ_A, or its own where ΔT is small."""
        return self.energy_scale or self.mu_A

    # -- results ----------------------------------------------------------------------------------
    @property
    def omega_mean(self) -> float:
        return self.dyn.omega_mean

    @property
    def total(self) -> float:
        """J = μ_T·|kl|/(ω_m²·δ): rotor, reducer and flywheel together, kg·m²."""
        return self.mu_T * self.kl / (self.omega_mean ** 2 * self.dyn.delta)

    @property
    def flywheel(self) -> float:
        """I_fl = J − I_rotor·i² − I_reducer, or 0 where the construction's J is no larger than
        rotor and reducer together (no flywheel is needed: never a negative moment of inertia)."""
        return max(self.total - self.dyn.constant, 0.0)

    @property
    def energy_extremes(self) -> dict[str, float]:
        """ΔT_max and ΔT_min as the approximate method reads them: off the drawn ΔT(φ) curve (the
        French curve through the division ordinates, ``energy_curve``) at its highest and lowest
        points, with the ruler — not at the divisions (review 13: the V-twin's ΔT peaked at 64,9 J
        between positions 2 and 3 where the table's ordinates give 61,3). mm, and the points' φ in
        degrees of the crank's turn from position 0."""
        fine = np.linspace(0.0, self.L, 4 * int(self.L) + 1)[:-1]      # one turn: 2π is 0 again
        xs, ys = self.points("dT")
        fine = np.union1d(fine, xs[:-1])                                  # the constructed points themselves
        y = energy_curve(xs, ys, self.L, fine, self.corners)
        out = {}
        for key, k in (("max", int(np.argmax(y))), ("min", int(np.argmin(y)))):
            value, at = float(read(y[k], self.precision)), float(fine[k])
            # where the curve's extreme reads no more than a division's ordinate it is that ordinate
            # (ΔT = 0 at position 0, not "at 359°" where the ruler's residual lifts the curve's end)
            same = [j for j in range(len(xs) - 1) if abs(float(ys[j]) - value) <= 1e-9]
            if same:
                at = float(xs[min(same, key=lambda j: abs(float(xs[j]) - at))])
            out[key], out[f"{key}_deg"] = value, at / self.L * 360.0
        return out

    @property
    def approximate_total(self) -> float:
        """J ≈ (ΔT_max − ΔT_min)/(ω_m²·δ) − I*_mean: ΔT_max,min off the drawn curve
        (``energy_extremes``), I*_mean the divisions' readings' mean."""
        e = self.energy_extremes
        span = (e["max"] - e["min"]) * self.mu_T
        mean = float(np.mean(self.I[:-1])) * self.mu_I
        return span / (self.omega_mean ** 2 * self.dyn.delta) - mean

    @property
    def approximate(self) -> float:
        return max(self.approximate_total - self.dyn.constant, 0.0)

    @property
    def merkalov_total(self) -> float:
        """Mertsalov's method: the flywheel's own energy change ΔT − ½·ω_m²·I*_m (the mechanism's
        kinetic energy at ω_m taken out): J ≈ (its max − its min)/(ω_m²·δ), from the readings."""
        wm2 = self.omega_mean ** 2
        own = self.points("dT")[1] * self.mu_T - 0.5 * wm2 * self.points("I")[1] * self.mu_I
        return (float(np.max(own)) - float(np.min(own))) / (wm2 * self.dyn.delta)

    @property
    def merkalov(self) -> float:
        return max(self.merkalov_total - self.dyn.constant, 0.0)

    @property
    def driving(self) -> float:
        """M*_d read off the moment diagram, N·m."""
        return self.Md * self.mu_M

    def error_pct(self, value: float) -> float:
        exact = self.dyn.flywheel
        return 100.0 * (value - exact) / exact if exact > 0 else math.nan

    def curve(self) -> tuple[np.ndarray, np.ndarray]:
        """The Wittenbauer curve as the French curve through (I_k, ΔT_k): X, Y in mm."""
        return _curve(self.points("I")[0], self.points("I")[1], self.points("dT")[1], self.L, self.corners)

    @property
    def corners(self) -> tuple[int, ...]:
        """The points (indices into ``points``) where M*_c jumps or bends: ΔT's slope turns there."""
        return self.added


def _corner_swap(x: np.ndarray, L: float, corners, at: np.ndarray) -> np.ndarray:
    """Which abscissae ``at`` lie in an interval next to one of the ``corners`` (indices into x)."""
    n = len(x) - 1
    k = np.clip(np.searchsorted(x, np.mod(at, L), side="right") - 1, 0, n - 1)
    near = set()
    for c in corners:
        near.update({(c - 1) % n, c % n})
    return np.isin(k, sorted(near))


def energy_curve(x: np.ndarray, y_mm: np.ndarray, L: float, at: np.ndarray, corners=(), trend: bool = True) -> np.ndarray:
    """The French curve of a periodic diagram that may not close exactly (ΔT read: A_d − A_c at the
    end may miss 0 by the ruler) through its division ordinates at the abscissae ``at``: the periodic
    cubic spline of the ordinates less their linear trend, the trend added back. Next to a point
    where M*_c jumps or bends (``corners``: indices into x) the curve has a corner the spline would
    swing past (the toggle press's ΔT peaked at 50 J between 38,1 and 41,3 by the spline alone, review
    56): there the shape-preserving cubic (never beyond its two ordinates), so the extremum drawn is
    the point constructed."""
    at = np.asarray(at, dtype=float)
    trend = float(y_mm[-1] - y_mm[0]) if trend else 0.0
    base = y_mm[:-1] - trend * x[:-1] / L
    y = periodic_spline(x[:-1], base, L)(at)
    if len(corners):
        swap = _corner_swap(x, L, corners, at)
        if swap.any():
            y = np.where(swap, periodic_pchip(x[:-1], base, L)(at), y)
    return y + trend * at / L


def inertia_curve(x: np.ndarray, i_mm: np.ndarray, L: float, at: np.ndarray) -> np.ndarray:
    """The French curve of I*_m through the division ordinates (x, i_mm; periodic over L mm) at the
    abscissae ``at``: the periodic cubic spline — the curve ΔT(φ) and the energy–mass diagram are
    drawn by —, and in an interval where it would dip below zero (the cubic's overshoot by a steep
    ordinate: I* < 0 drawn) the shape-preserving cubic there (chords.periodic_pchip, never below its
    ordinates); both pass through every ordinate, so the two joined stay one line. The I*(φ) diagram
    and the energy–mass curve draw the same I* this way (review 8 #6: a pchip I*(φ) peaked at 4.78
    where the spline's Wittenbauer curve bulged to 5.1 kg·m²)."""
    at = np.asarray(at, dtype=float)
    spline = periodic_spline(x[:-1], i_mm[:-1], L)
    y = spline(at)
    n = len(x) - 1
    probe = np.linspace(0.0, L, CURVE * n + 1)          # each interval's dip, at the curve's own samples
    dips = probe[spline(probe) < 0.0]
    if dips.size:
        bad = np.unique(np.clip(np.searchsorted(x, dips, side="right") - 1, 0, n - 1))
        k = np.clip(np.searchsorted(x, np.mod(at, L), side="right") - 1, 0, n - 1)
        swap = np.isin(k, bad)
        if swap.any():
            y = np.where(swap, periodic_pchip(x[:-1], i_mm[:-1], L)(at), y)
    return y


def _curve(x: np.ndarray, i_mm: np.ndarray, dt_mm: np.ndarray, L: float, corners=()) -> tuple[np.ndarray, np.ndarray]:
    n = len(x) - 1
    fine = np.union1d(np.linspace(0.0, L, CURVE * n + 1), x)
    return inertia_curve(x, i_mm, L, fine), energy_curve(x, dt_mm, L, fine, corners, trend=False)


def tangents(X: np.ndarray, Y: np.ndarray, s_max: float, s_min: float) -> dict[str, float]:
    """The two tangents to the curve (X, Y): the line of slope s_max with the whole curve below it
    and the line of slope s_min with the whole curve above it; where each cuts the ΔT axis (X = 0)
    and where it touches the curve."""
    up = Y - s_max * X
    down = Y - s_min * X
    ku, kd = int(np.argmax(up)), int(np.argmin(down))
    return {"s_max": s_max, "s_min": s_min, "k": float(up[ku]), "l": float(down[kd]),
            "touch_max_x": float(X[ku]), "touch_max_y": float(Y[ku]),
            "touch_min_x": float(X[kd]), "touch_min_y": float(Y[kd])}


_REDUCED: dict[tuple[int, int], tuple] = {}


def _reduced(st, n: int, turn: np.ndarray | None = None):
    """I*_m, dI*_m/dφ and M*_c at the ``n`` divisions of the turn and at their middles (exact.dynamics
    ``reduce``): the same whatever L and size the construction is drawn at, so solved once per study
    and divisions (a sheet tries a few hundred scales of one construction). The study is kept with
    them: a study made later at the same address is not taken for it."""
    turn = np.linspace(0.0, 2 * math.pi, n + 1) if turn is None else np.asarray(turn, dtype=float)
    key = (id(st), n, tuple(np.round(turn, 12)))
    hit = _REDUCED.get(key)
    if hit is None or hit[0] is not st:
        hit = (st, reduce(st, turn), reduce(st, midpoints(turn)))
        for r in hit[1:]:                     # shared by every construction: nobody writes into them
            for v in vars(r).values():
                if isinstance(v, np.ndarray):
                    v.flags.writeable = False
        if len(_REDUCED) >= 16:
            _REDUCED.pop(next(iter(_REDUCED)))
        _REDUCED[key] = hit
    return hit[1], hit[2]


def mean_ordinates(dyn: Dynamics, turn: np.ndarray, mid_moment: np.ndarray, mu_M: float,
                   precision: float) -> tuple[np.ndarray, tuple[int, ...]]:
    """The heights the chords integrate, N·m: each interval's middle ordinate, except where the
    middle ordinate is not the interval's mean — the reduced moment drops or bends inside it (one of
    exact.dynamics' ``breaks`` — a load switching at a dead centre, a force profile's corner — falls
    strictly inside), or it curves so that the middle ordinate misses the mean by more than the
    ruler's division ``precision`` (mm at μ_M; at 0 every such interval). There the textbook takes the
    equal-area mean ordinate, the horizontal that cuts off as much area above the curve as it adds
    below: M̄_k = (A_c(φ_{k+1}) − A_c(φ_k))/(φ_{k+1} − φ_k), A_c = ∫M*_c dφ (review 10's six-bar,
    interval 3–4: the middle ordinate 1,97 N·m for a true mean 4,40, ΔT at 4 +30 %).
    Returns the heights and the intervals so taken."""
    c = dyn.cycle
    inner = np.asarray(c.breaks, dtype=float)[1:-1]
    tol = 1e-9
    out = np.array(mid_moment, dtype=float)
    work = np.asarray(c.resistance_work(np.asarray(turn, dtype=float)), dtype=float)
    taken = []
    for k in range(len(turn) - 1):
        a, b = float(turn[k]), float(turn[k + 1])
        mean = float(work[k + 1] - work[k]) / (b - a)
        jump = bool(np.any((inner > a + tol) & (inner < b - tol)))
        if jump or abs(mean - out[k]) / mu_M > max(precision, 1e-9):
            out[k] = mean
            taken.append(k)
    return out, tuple(taken)


def construct(dyn: Dynamics, divisions: int | None = None, precision: float = 0.5, L: float | None = None,
              H: float | None = None, slopes: str = "course", size: float = 1.0,
              energy: float | None = None) -> Flywheel:
    """The draftsman's flywheel construction (module docstring), every length read with the ruler;
    ``size`` scales the drawn heights the scales aim at (a sheet with room to spare draws larger);
    ``energy``: ΔT(φ)'s own scale μ_T, J/mm, where the sheet has room to draw it finer than
    ``own_energy_scale`` does (sheets.dynamics ``finer_energy``: the largest standard scale whose
    construction the sheet holds) — taken only where finer than μ_A."""
    from graphplan.util.errors import GraphplanError
    st = dyn.study
    settings = st.mech.task.flywheel
    n = int(divisions or settings.get("divisions") or st.mech.task.count)
    if n < 4:
        raise GraphplanError(f"--divisions must be at least 4, got {n}")
    if not (math.isfinite(precision) and precision >= 0):
        raise GraphplanError(f"--precision must be a length ≥ 0 in mm, got {precision:g}")
    L = float(L or settings.get("L_mm", 240.0))
    turn_u = np.linspace(0.0, 2 * math.pi, n + 1)
    turn = division_points(dyn, n)
    uni = np.searchsorted(turn, turn_u - 1e-12)         # the divisions among the points
    added = tuple(int(j) for j in np.setdiff1d(np.arange(len(turn)), uni))
    x = turn / (2 * math.pi) * L
    at, mid = _reduced(st, n, turn)
    mu_M = standard_scale(float(np.max(np.abs(at.moment))) / (M_HEIGHT * size))
    mu_phi = 2 * math.pi / L
    if H is None:
        H = float(settings.get("H_mm") or 5.0 * max(2, math.ceil(dyn.cycle.work / (mu_M * mu_phi * A_HEIGHT * size) / 5.0)))
    mu_A = mu_M * mu_phi * H
    mu_I = standard_scale(float(np.max(at.inertia)) / (I_WIDTH * size))
    M = read(at.moment / mu_M, precision)
    heights, equal_area = mean_ordinates(dyn, turn, mid.moment, mu_M, precision)
    M_mid = read(heights / mu_M, precision)
    A_drawn = integrate_by_chords(x, M_mid, H, 0.0)
    A = read(A_drawn, precision)
    dT = read(A_drawn[-1] * x / L, precision) - A        # A_d and A_c read at each point, subtracted
    mu_T = own_energy_scale(float(np.ptp(dT)) * mu_A, mu_A, size)
    if energy is not None and energy < mu_A * (1 - 1e-9):
        mu_T = float(energy)
    if mu_T != mu_A:                                       # … and redrawn at ΔT's own scale
        dT = read(dT * mu_A / mu_T, precision)
    I = read(at.inertia / mu_I, precision)
    wm, d = dyn.omega_mean, dyn.delta
    hi, lo = ((1 + d), (1 - d)) if slopes == "course" else ((1 + d / 2) ** 2, (1 - d / 2) ** 2)
    tg = tangents(*_curve(x, I, dT, L, added), mu_I * wm ** 2 * hi / (2 * mu_T), mu_I * wm ** 2 * lo / (2 * mu_T))
    kl = float(read(tg["k"] - tg["l"], precision))
    # the divisions' own intervals an equal-area mean was taken in (the notes number them so)
    eq_u = tuple(sorted({int(np.searchsorted(uni, j, side="right")) - 1 for j in equal_area}))
    mine = {"x_all": x, "turn_all": turn, "M_all": M, "A_drawn_all": A_drawn, "dT_all": dT, "I_all": I,
            "added": added, "equal_area_all": tuple(equal_area)} if added else {}
    return Flywheel(dyn, n, L, H, precision, slopes, mu_M, mu_phi, mu_A, mu_I, x[uni], turn_u, at.moment[uni],
                    at.inertia[uni], at.d_inertia[uni], M[uni], M_mid, A_drawn[uni], A[uni],
                    float(read(A_drawn[-1] * H / L, precision)), dT[uni], I[uni], tg, kl,
                    equal_area=eq_u if added else equal_area, energy_scale=mu_T if mu_T != mu_A else None, **mine)


ADDED_LEAST = 0.05    # of an interval: a break nearer a division than this is that division (no point added)


def division_points(dyn: Dynamics, n: int) -> np.ndarray:
    """The construction's points, crank turns: the ``n`` equal divisions and, between them, the turns
    where M*_c jumps or bends (exact.dynamics ``breaks``: the output's dead centres, where a load
    switches; a force profile's corners) — the lab divides where the curve bends, as the kinematic
    diagrams subdivide, so an extremum of ΔT there is a constructed point, not the French curve's
    guess between two divisions (review 56: the toggle press's force sets in at 81,5° inside 60–90°,
    the exact ΔT_max 53,67 J at 82,75°; the spline through 38,1 and 41,3 gave 50,0)."""
    step = 2 * math.pi / n
    turn = list(np.linspace(0.0, 2 * math.pi, n + 1))
    for b in np.asarray(dyn.cycle.breaks, dtype=float)[1:-1]:
        if abs(b / step - round(b / step)) > ADDED_LEAST:
            turn.append(float(b))
    return np.array(sorted(turn))


def own_energy_scale(span: float, mu_A: float, size: float = 1.0) -> float:
    """ΔT(φ)'s scale μ_T, J/mm. ΔT = A_d − A_c is read between the work diagrams at μ_A; where its span
    (J) there is small (below ENERGY_SMALL·A_HEIGHT·size mm: a flat curve, and a short |kl| to read the
    flywheel off) the draftsman redraws it at its own finer scale, the series' value at or above
    span/(ENERGY_HEIGHT·size) (REFERENCE §9 names μ_T apart from μ_A: tg ψ = μ_I·ω_m²·(1 ± δ)/(2μ_T),
    I_fl = μ_T·|kl|/(ω_m²·δ)); otherwise μ_T = μ_A."""
    if span <= 0.0 or span / mu_A >= ENERGY_SMALL * A_HEIGHT * size:
        return mu_A
    own = standard_scale(span / (ENERGY_HEIGHT * size))
    return own if own < mu_A else mu_A


# -- redrawn with more divisions until right ------------------------------------------------------

LAB_LIMIT = 5.0      # %: what the lab accepts of the graphical flywheel and M*_d (graphic.diagrams.LAB_LIMIT)


def inertia_miss(f: Flywheel) -> float:
    """How far the largest I*_m the diagram draws — the French curve through the ordinates
    (``inertia_curve``, the energy–mass curve's abscissa) — misses the exact largest I*_m, in %
    (exact.dynamics' cycle, sampled at ≤ 0,25°): a peak between two divisions the curve guesses
    wrong (review 8's coulisse at 8 divisions: −20 %; at 12 its ordinates give 4,78 against 5,293
    at 9,65, −9,7 %, but the curve 5,058, −4,45 %: within the lab's 5 %); NaN where I* is constant
    (nothing to miss: a moment-loaded four-bar whose only masses turn about fixed axes)."""
    exact = float(np.max(f.dyn.cycle.samples.inertia))
    if exact <= 0.0 or float(np.ptp(f.dyn.cycle.samples.inertia)) <= 1e-9 * exact:
        return math.nan
    return 100.0 * (float(np.max(f.curve()[0])) * f.mu_I - exact) / exact


def errors(f: Flywheel) -> dict[str, float]:
    """The construction's errors the lab judges, in %: the graphical flywheel against the exact one
    (NaN where none is needed: no percent of 0), the graphical M*_d (the ray's height on the
    moment diagram) against A_c/2π, and the largest I*_m the ordinates give against the exact
    largest (``inertia_miss``)."""
    exact_md = f.dyn.cycle.driving
    return {"flywheel": f.error_pct(f.flywheel),
            "driving": 100.0 * (f.driving - exact_md) / exact_md if exact_md else math.nan,
            "inertia": inertia_miss(f)}


def ruler_bound(f: Flywheel) -> float:
    """The most the ruler alone may put the graphical flywheel off, %: k and l each read to half the
    ruler's step, so |kl| to ``precision`` mm, J = μ_T·|kl|/(ω_m²·δ) to precision/|kl| of itself, and
    I_fl = J − I_rotor·i² − I_reducer to J/I_fl times that (the exact J and I_fl; inf where no
    flywheel is needed or |kl| is nil)."""
    exact = f.dyn.flywheel
    if exact <= 0 or f.kl <= 0:
        return math.inf
    return 100.0 * f.precision / abs(f.kl) * (exact + f.dyn.constant) / exact


def over(errs: dict[str, float], limit: float = LAB_LIMIT) -> tuple[str, ...]:
    """The keys of ``errs`` past the lab's limit (NaN is not judged)."""
    return tuple(k for k, v in errs.items() if math.isfinite(v) and abs(v) > limit)


def finer(first: int, top: int) -> list[int]:
    """The divisions a redrawing tries: the first drawing's multiplied by 2, 3, 4 … up to ``top``
    (the scene's positions stay among the divisions, each interval split equally)."""
    return [first * k for k in range(2, top // first + 1)]


@dataclass(frozen=True)
class Redrawing:
    """What ``redrawn`` did: the first drawing's divisions and errors (``errors``), the drawn one's;
    ``given`` — the divisions were given (``"scene"`` its [dynamics] divisions, ``"option"`` the
    command's --divisions) and kept, ``better``/``better_errors`` then the first finer drawing that
    would be within the lab's limit (None: none up to the bound); ``tried`` the finer drawings
    constructed."""
    first: int
    divisions: int
    before: dict[str, float]
    after: dict[str, float]
    given: str | None = None
    better: int | None = None
    better_errors: dict[str, float] | None = None
    tried: int = 0
    ruler: bool = False      # not redrawn: the ruler's reading of |kl| alone may exceed the limit (``ruler_bound``)

    @property
    def needed(self) -> bool:
        """The first drawing was past the lab's limit."""
        return bool(over(self.before))

    @property
    def right(self) -> bool:
        """The drawing kept is within the lab's limit."""
        return not over(self.after)

    def to_json(self) -> dict[str, Any]:
        return {"needed": self.needed, "right": self.right, "first_divisions": self.first,
                "divisions": self.divisions, "given": self.given, "errors_before": dict(self.before),
                "errors_after": dict(self.after), "better_divisions": self.better,
                "better_errors": None if self.better_errors is None else dict(self.better_errors),
                "tried": self.tried, "ruler": self.ruler}


def redrawn(dyn: Dynamics, divisions: int | None = None, precision: float = 0.5, L: float | None = None,
            H: float | None = None, slopes: str = "course", size: float = 1.0,
            given: str | None = None, energy: float | None = None) -> Flywheel:
    """The construction a student hands in: drawn with ``divisions`` (``construct``); where its
    graphical flywheel or M*_d is past the lab's 5 % (``errors``), drawn again with more divisions —
    the first's × 2, × 3 … up to bounds.DYNAMICS_DIVISIONS (``finer``) — and the first within the
    limit taken, as a student redraws a diagram whose intervals are too coarse for the curves (a
    reduced moment that jumps inside an interval: the chords' middle ordinates miss the jump).
    ``given`` (``"scene"``, ``"option"``): the divisions were asked for and are kept — the finer
    drawing that would be right is found for the note only. Nothing within the bound right: the
    first drawing stays. ``redrawn`` on the result says what was done."""
    from graphplan.model.bounds import DYNAMICS_DIVISIONS
    if given is None and divisions is None and "divisions" in dyn.study.mech.task.flywheel:
        given = "scene"
    first = construct(dyn, divisions, precision, L, H, slopes, size, energy)
    before = errors(first)
    if not over(before):
        first.redrawn = Redrawing(first.divisions, first.divisions, before, before, given)
        return first
    if over(before) == ("flywheel",) and ruler_bound(first) > LAB_LIMIT:
        # the flywheel a small difference J − I_rotor·i²: the ruler's reading of |kl| alone may put it
        # past the lab's 5 % — more divisions would only change which way the ruler rounds
        first.redrawn = Redrawing(first.divisions, first.divisions, before, before, given, ruler=True)
        return first
    tried, fallback = 0, None
    for n in finer(first.divisions, DYNAMICS_DIVISIONS[1]):
        f = construct(dyn, n, precision, L, H, slopes, size, energy)
        tried += 1
        after = errors(f)
        if not over(after):
            break
        if fallback is None and "flywheel" in over(before) and "flywheel" not in over(after):
            fallback = (f, after)       # the answer within the limit, M*_d's short ordinate still not
    else:
        # no drawing has both: the first whose flywheel (the answer) is within, where one is — M*_d
        # is read off the ray's height H·A_c/L, which no number of divisions makes longer
        if fallback is None:
            first.redrawn = Redrawing(first.divisions, first.divisions, before, before, given, tried=tried)
            return first
        f, after = fallback
    if given:
        first.redrawn = Redrawing(first.divisions, first.divisions, before, before, given, f.divisions, after, tried)
        return first
    f.redrawn = Redrawing(first.divisions, f.divisions, before, after, None, tried=tried)
    return f
