"""Kinematic diagrams s, v, a by the method of chords (seed 002, REFERENCE §1.5), measured like a
student and compared with the analytic solver; `graphplan diagrams`.

The displacement s(t) of the output from position 0 (an extreme position; the angle φ(t) for a
rocking or turning output) is drawn over an abscissa of L mm for one crank period,
μt = T/L = 2π/(ω1·L). The curve is replaced by chords between the division ordinates; rays from the
pole P at H1 left of the origin, parallel to the chords, cut heights on the ordinate axis that are
carried to the middles of the intervals: the velocity ordinates, μv = μs/(μt·H1). A smooth periodic
curve through them (the French curve) is read at the division ordinates and differentiated again
with H2: μa = μv/(μt·H2). Every ordinate is read with the drafting precision.

Signs: the diagrams are drawn the way the lab draws them, s growing away from position 0 (for a
crank-slider starting at the outer dead centre the curve rises toward the inner one). ``sign``
(+1 or −1) relates the drawing to the output's guide: value = sign · mm · μ, signed along the guide
(or counter-clockwise for an angle), as the analytic solver gives it.
"""
from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from graphplan.util.words import fixed, num, uk_count
from graphplan.graphic.chords import (chord_error_estimate, integrate_by_chords, midpoints, periodic_spline,
                     pole_heights, read, standard_scale)
from graphplan.graphic import qualitative
from graphplan.graphic.scales import at_most
from graphplan.graphic.correction import area_correction
from graphplan.graphic.tangents import (ANGLE_ERROR_DEG, MAX_ANGLE_ERROR_DEG, SEED, TangentReading,
                                        construct_tangents)
from graphplan.util.errors import GraphplanError
from graphplan.exact.positions import Output, Study, crank_angle, exact_motion  # noqa: F401  (re-exported)

MAX_S_HEIGHT = 100.0    # mm: a taller s diagram gets a coarser μs (the seed: "reduce the ordinates")
ANGLE_HEIGHT = 80.0     # mm: the height an angle diagram is fitted to
CRANK_MM = 70.0         # μl: the crank drawn at most 70 mm (so 35–70 mm), as on the position plan
NEAR_ZERO = 1e-6        # |analytic| below this share of the cycle's maximum: no percent error (null)
LAB_LIMIT = 5.0         # %, what the lab accepts
MEANINGFUL = 0.10       # percent errors are judged against 5 % where |analytic| ≥ 10 % of the maximum
CYCLE = 720             # samples of the exact cycle for maxima and the drawing's sign
MAX_DIVISIONS = 720
REFINE_LEVELS = 3       # the adaptive mode splits an interval at most into 2³ parts
METHODS = ("chords", "tangents")


@dataclass
class Reading:
    """One run of the construction at one drafting precision; all ordinates in drawing mm."""
    s: np.ndarray        # s at the division ordinates (n + 1)
    v_ray: np.ndarray    # the heights the rays cut (exact geometry of the drawn chords), n
    v: np.ndarray        # … read with the ruler: v at the middles of the intervals, n
    v_at: np.ndarray     # the French curve through them read at the division ordinates, n + 1
    a_ray: np.ndarray    # heights of the rays parallel to the chords of the v curve, n
    a: np.ndarray        # … read: a at the middles, n
    a_at: np.ndarray     # the a curve read at the division ordinates, n + 1
    v_int: np.ndarray    # integration a → v (chords), at the division ordinates, n + 1
    s_int: np.ndarray    # … then v → s, at the division ordinates, n + 1
    s_int_v: np.ndarray  # integration of the v ordinates straight back to s, n + 1
    v_zeros: np.ndarray = field(default_factory=lambda: np.zeros(0))  # abscissae (mm) where the v curve is drawn through 0


STOPS = 1e-9            # |exact v| at a division ordinate below this share of the cycle's max: the output stops there


def stops(x: np.ndarray, v_exact: np.ndarray, v_max: float) -> np.ndarray:
    """The abscissae (mm, in [0, L)) of the division ordinates where the output stops — an extreme
    position of s (a dead centre), which the position analysis and the velocity plan give exactly:
    v = 0 there. The lab draws the v curve through zero at them (the chord's tangent is horizontal at
    an extremum of s); ``x`` and ``v_exact`` at the n + 1 division ordinates."""
    if v_max <= 0:
        return np.zeros(0)
    return np.asarray(x[:-1], dtype=float)[np.abs(np.asarray(v_exact[:-1])) <= STOPS * v_max]


def v_knots(xm: np.ndarray, v: np.ndarray, zeros: np.ndarray = np.zeros(0)) -> tuple[np.ndarray, np.ndarray]:
    """The points the French curve of v passes through: the ordinates read at the middles of the
    intervals and a 0 at every extreme position in ``zeros`` (an added point, not a changed
    reading), sorted along the abscissa."""
    if len(zeros) == 0:
        return np.asarray(xm, dtype=float), np.asarray(v, dtype=float)
    knots = np.concatenate((xm, zeros))
    values = np.concatenate((v, np.zeros(len(zeros))))
    order = np.argsort(knots, kind="stable")
    return knots[order], values[order]


def differentiate(x: np.ndarray, s_mm: np.ndarray, L: float, H1: float, H2: float, precision: float,
                  correct: bool = False, zeros: np.ndarray = np.zeros(0)) -> tuple[np.ndarray, ...]:
    """The two differentiations by chords (seed 002, fig. 2.5), in mm: s read, the rays' heights and
    the v read at the middles, the v curve read at the division ordinates, the same for a.
    ``correct``: the lab's area correction of each French curve (graphic.correction), v and a then
    read on it. ``zeros``: the extreme positions' abscissae (``stops``), where the v curve is drawn
    through 0 (seed 002: v = 0 where s has its extremum). Returns (s, v_ray, v, v_at, a_ray, a)."""
    xm = midpoints(x)
    s = read(s_mm, precision)
    v_ray = pole_heights(x, s, H1)
    v = read(v_ray, precision)
    if correct:
        v = read(area_correction(x, v, L, precision).points, precision)
    v_curve = periodic_spline(*v_knots(xm, v, zeros), L)
    v_at = read(v_curve(x), precision)
    a_ray = pole_heights(x, v_at, H2)
    a = read(a_ray, precision)
    if correct:
        a = read(area_correction(x, a, L, precision).points, precision)
    return s, v_ray, v, v_at, a_ray, a


def construct(x: np.ndarray, s_mm: np.ndarray, L: float, H1: float, H2: float,
              precision: float, correct: bool = False, zeros: np.ndarray = np.zeros(0)) -> Reading:
    """The draftsman's sequence on one sheet (seed 002, figs. 2.5 and 2.7), in mm: ``differentiate``
    (the v curve through 0 at ``zeros``), the a curve read at the division ordinates, and the
    graphical integration back."""
    xm = midpoints(x)
    s, v_ray, v, v_at, a_ray, a = differentiate(x, s_mm, L, H1, H2, precision, correct, zeros)
    a_at = read(periodic_spline(xm, a, L)(x), precision)
    # graphical integration, the reverse construction: a → v from v(0), then v → s from s(0)
    v_int = integrate_by_chords(x, a, H2, v_at[0])
    v_int_mid = read(periodic_spline(x[:-1], v_int[:-1], L)(xm), precision)
    s_int = read(integrate_by_chords(x, v_int_mid, H1, s[0]), precision)
    s_int_v = read(integrate_by_chords(x, v, H1, s[0]), precision)
    return Reading(s, v_ray, v, v_at, a_ray, a, a_at, read(v_int, precision), s_int, s_int_v,
                   np.asarray(zeros, dtype=float))


@dataclass
class Diagrams:
    """The three diagrams of one output with their pole constructions, readings and errors.

    ``method`` is "chords" or "tangents". The method's own ordinates of v and a (the keys
    ``v_mid``/``a_mid``, ``x_mid``, ``phi_mid``, ``t_mid``) lie where it yields them: the middles of
    the intervals for chords, the division ordinates 0 … n−1 for tangents."""
    study: Study
    output: Output
    point: str
    symbols: tuple[str, str, str]   # s, v, a (or φ, ω, ε)
    sub: str                        # the subscript: the point's or the link's name
    unit: str                       # "m" or "rad"
    sign: int
    L: float
    H1: float
    H2: float
    precision: float
    adaptive: bool
    tolerance: float
    mu_s: float
    mu_t: float
    mu_v: float
    mu_a: float
    turn: np.ndarray                # crank turn from position 0 at the division ordinates, deg (n + 1)
    position: list[int | None]      # the mechanism's position number at each division ordinate
    x: np.ndarray                   # division ordinates' abscissae, mm (n + 1: 0 … L)
    phi: np.ndarray                 # crank angles there, deg
    phi_mid: np.ndarray             # crank angles at the middles
    drawn: Reading | TangentReading  # at the drafting precision (and the tangents' angular error)
    exact: Reading | TangentReading  # the same construction, precision 0 (and exact tangents)
    truth: dict[str, np.ndarray]    # analytic s (n + 1), v_mid, a_mid (n), v_at, a_at (n + 1), signed
    maxima: dict[str, float]        # the cycle's max |s|, |v|, |a| (analytic)
    chosen: tuple[int, ...]         # the positions of the lab's table
    estimate: dict[str, np.ndarray]  # per interval: the chord error a draftsman can estimate, mm
    lang: str = "uk"
    method: str = "chords"
    angle_error_deg: float = 0.0    # tangents: the bound of each tangent's angular error
    correct: bool = False           # chords: the lab's area correction applied
    redrawn: Any = None             # graphic.redraw.Redrawing: how the drawing was changed to be right
    # the sheet's other s scales tried (kinlayout.taller_in_place): (μs, the largest |δ| at the positions, %,
    # or "room" where the sheet does not hold that drawing, "flat" where its v or a would be lower, "wrong")
    s_tried: tuple = ()
    _trials: list | None = field(default=None, repr=False, compare=False)   # ``alternatives``, once measured
    # ``warnings`` once diagnosed: shared with the copies ``dataclasses.replace`` makes (the other
    # language's: ``diagnose`` words both) — a drawing only measured (a redrawing's candidate size,
    # kinematics ``_block_size``) is never diagnosed, its alternatives never tried
    _diagnosed: dict = field(default_factory=dict, repr=False, compare=False)

    @property
    def warnings(self) -> list[dict[str, Any]]:
        """Warnings (``diagnose``), each with its numbers and messages in both languages; diagnosed
        on first reading."""
        if "warnings" not in self._diagnosed:
            self._diagnosed["warnings"] = diagnose(self)
        return self._diagnosed["warnings"]

    @warnings.setter
    def warnings(self, value: list[dict[str, Any]]) -> None:
        self._diagnosed["warnings"] = value

    # -- geometry ------------------------------------------------------------------------------------
    @property
    def divisions(self) -> int:
        return len(self.x) - 1

    @property
    def x_mid(self) -> np.ndarray:
        """Abscissae of the method's own v and a ordinates (middles, or division ordinates)."""
        return self.x[:-1] if self.method == "tangents" else midpoints(self.x)

    @property
    def t(self) -> np.ndarray:
        return self.x * self.mu_t

    @property
    def t_mid(self) -> np.ndarray:
        return self.x_mid * self.mu_t

    # -- values (SI, signed along the guide) ----------------------------------------------------
    def values(self, reading: Reading | None = None) -> dict[str, np.ndarray]:
        r = reading or self.drawn
        k = self.sign
        raw = {"s": r.s * self.mu_s, "v_mid": r.v * self.mu_v, "v_at": r.v_at * self.mu_v,
               "a_mid": r.a * self.mu_a, "a_at": r.a_at * self.mu_a,
               "s_int": r.s_int * self.mu_s, "v_int": r.v_int * self.mu_v}
        return {key: k * value + 0.0 for key, value in raw.items()}  # + 0.0: no −0 in the output

    def errors_pct(self, key: str, reading: Reading | None = None) -> np.ndarray:
        """100·(graphical − analytic)/analytic; NaN where the analytic value is near zero."""
        value = self.values(reading)[key]
        truth = self.truth[key]
        big = self.maxima[key[0]]
        with np.errstate(all="ignore"):          # near-zero truths (even denormal) are masked below
            pct = 100.0 * (value - truth) / truth
        return np.where(np.abs(truth) > NEAR_ZERO * big, pct, np.nan)

    def errors_of_max(self, key: str, reading: Reading | None = None) -> np.ndarray:
        """The error in percent of the cycle's maximum |value| (what the bench charts)."""
        return 100.0 * (self.values(reading)[key] - self.truth[key]) / self.maxima[key[0]]

    @property
    def at_positions(self) -> list[int]:
        """The division ordinates that are the mechanism's positions 0 … N − 1 (the plans')."""
        return [k for k, p in enumerate(self.position[:-1]) if p is not None]

    def position_errors(self, reading: Reading | None = None) -> dict[str, np.ndarray]:
        """δ, % of s, v, a read off the diagrams at the positions (``at_positions``), judged as the
        lab judges them (``judged_pct``): keys "s", "v_at", "a_at"."""
        k = self.at_positions
        vals = self.values(reading)
        return {key: judged_pct(vals[key][k], self.truth[key][k], self.maxima[key[0]])
                for key in ("s", "v_at", "a_at")}

    def worst_pct(self, reading: Reading | None = None) -> float:
        """The largest |δ|, % of s, v, a read at the positions (``position_errors``): what the lab's
        5 % judges."""
        errs = self.position_errors(reading)
        return max((float(np.max(np.abs(e))) for e in errs.values() if e.size), default=0.0)

    def alternatives(self) -> list[Trial]:
        """The lab's other constructions of these diagrams, each tried once (``try_alternatives``)."""
        if self._trials is None:
            if "trials" not in self._diagnosed:      # shared with the other language's copy, as ``warnings``
                self._diagnosed["trials"] = try_alternatives(self)
            self._trials = self._diagnosed["trials"]
        return self._trials


def judged_pct(value: np.ndarray, truth: np.ndarray, big: float) -> np.ndarray:
    """δ, % as the lab's 5 % judges a diagram's reading: 100·(graphical − analytic)/analytic where
    |analytic| ≥ ``MEANINGFUL`` of the cycle's maximum ``big``, else 100·(graphical − analytic)/big
    (near a zero a reading's share of the value means nothing; its share of the maximum does)."""
    value, truth = np.asarray(value, dtype=float), np.asarray(truth, dtype=float)
    big = max(float(big), 1e-300)
    meaningful = np.abs(truth) >= MEANINGFUL * big
    return 100.0 * (value - truth) / np.where(meaningful, np.where(truth == 0, 1.0, truth), big)


@dataclass(frozen=True)
class Trial:
    """Another construction of the same diagrams the lab allows (same L, H1, H2, μs and ruler): which
    (``key``: "adaptive" — smaller intervals where the curve bends, "double" — twice the divisions,
    "correct" — the area correction, "tangents" or "chords" — the other method), its divisions, the
    option that draws it, and the largest |δ| at the first drawing's positions drawn with the ruler
    (``worst_pct``) and exactly (``exact_pct``: the method's own error)."""
    key: str
    divisions: int
    option: str
    worst_pct: float
    exact_pct: float

    def to_json(self) -> dict[str, Any]:
        return {"construction": self.key, "divisions": self.divisions, "option": self.option,
                "worst_pct": self.worst_pct, "exact_pct": self.exact_pct}


def _trial_worst(d: Diagrams, turns: np.ndarray, method: str, correct: bool) -> tuple[float, float]:
    """The construction over the division ordinates ``turns`` (containing the drawing's positions),
    read at the positions: the largest |δ| (judged_pct) at the drafting precision and exactly."""
    x = d.L * turns / 360.0
    s_t, v_t, _ = exact_motion(d.study, d.output, turns)
    s_mm = d.sign * s_t / d.mu_s
    zeros = stops(x, v_t, d.maxima["v"])    # the v curve through 0 at the stops, as ``chord_diagrams`` draws it
    k = d.at_positions
    idx = np.searchsorted(np.round(turns, 9), np.round(d.turn[k], 9))
    out = []
    for precision in (d.precision, 0.0):
        if method == "tangents":
            r = construct_tangents(x, s_mm, d.L, d.H1, d.H2, precision,
                                   d.angle_error_deg if precision and d.method == "tangents" else
                                   (ANGLE_ERROR_DEG if precision else 0.0), SEED)
        else:
            r = construct(x, s_mm, d.L, d.H1, d.H2, precision, correct, zeros)
        worst = 0.0
        for key, got, mu in (("s", r.s, d.mu_s), ("v_at", r.v_at, d.mu_v), ("a_at", r.a_at, d.mu_a)):
            pct = judged_pct(d.sign * got[idx] * mu, d.truth[key][k], d.maxima[key[0]])
            worst = max(worst, float(np.max(np.abs(pct))))
        out.append(worst)
    return out[0], out[1]


def subdivided(turns: np.ndarray, factor: int) -> np.ndarray:
    """The division ordinates ``turns`` (deg, n + 1) with each interval cut into ``factor`` equal
    parts (the positions kept as every factor-th ordinate)."""
    if factor == 1:
        return np.asarray(turns, dtype=float)
    parts = [np.linspace(a, b, factor + 1)[:-1] for a, b in zip(turns[:-1], turns[1:])]
    return np.append(np.concatenate(parts), turns[-1])


def ruler_on_s(d: Diagrams, factor: int = 1) -> dict[str, np.ndarray] | None:
    """δ, % (judged_pct) of v and a at the positions (keys "v_at", "a_at", as ``position_errors``)
    where the ruler reads the s ordinates alone: the s diagram at its μs read with the drafting
    precision, every later step (rays, French curves, the correction if drawn, the readings of v and
    a) exact, over the drawing's divisions cut ``factor`` times finer. The construction after s is
    then linear in the s ordinates and its values (mm × μ) do not depend on L, H1 or H2 (y_v =
    H1·Δs/Δx, y_a = H2·Δy_v/Δx; μv = μs/(μt·H1), μa = μv/(μt·H2), μt = T/L): no pole distance or
    abscissa changes this share of the error, only a finer μs (a taller s) or other divisions; it
    holds the chords' own error at those divisions. None for tangents, an exact ruler or no
    positions."""
    if d.method != "chords" or d.precision == 0 or not d.at_positions:
        return None
    turns = subdivided(d.turn, factor)
    x = d.L * turns / 360.0
    s_mm = read(d.sign * exact_motion(d.study, d.output, turns)[0] / d.mu_s, d.precision)
    k = d.at_positions
    idx = np.searchsorted(np.round(turns, 9), np.round(d.turn[k], 9))
    r = construct(x, s_mm, d.L, d.H1, d.H2, 0.0, d.correct, getattr(d.drawn, "v_zeros", np.zeros(0)))
    return {key: judged_pct(d.sign * got[idx] * mu, d.truth[key][k], d.maxima[key[0]])
            for key, got, mu in (("v_at", r.v_at, d.mu_v), ("a_at", r.a_at, d.mu_a))}


def try_alternatives(d: Diagrams) -> list[Trial]:
    """What a student would try where the values read at the positions miss the lab's 5 %, each
    drawn on the exact s at the same scales and read with the same ruler (a few ms, no sheet):
    smaller intervals where the curve bends (``refine``), twice the divisions (the positions kept
    as every other ordinate), the area correction, the other method. Judged as the lab judges
    (the largest |δ| at the positions), so that a hint names only what does better."""
    if not d.at_positions:
        return []
    trials: list[Trial] = []
    n = d.divisions
    uniform = d.method == "chords" and not d.adaptive
    if uniform:
        fine = refine(d.study, d.output, d.turn, d.sign, d.mu_s, d.L, d.H1, d.H2, d.tolerance, d.precision)
        if len(fine) != len(d.turn):
            trials.append(Trial("adaptive", len(fine) - 1, "--adaptive", *_trial_worst(d, fine, "chords", d.correct)))
        else:       # no interval where halving pays (the ruler's error would grow more than the chords' falls)
            trials.append(Trial("adaptive none", n, "", d.worst_pct(), d.worst_pct(d.exact)))
    if 2 * n <= MAX_DIVISIONS:
        double = np.sort(np.concatenate((d.turn, midpoints(d.turn))))
        trials.append(Trial("double", 2 * n, f"--divisions {2 * n}" if uniform or d.method == "tangents" else "",
                            *_trial_worst(d, double, d.method, d.correct)))
    if d.method == "chords":
        if not d.correct:
            trials.append(Trial("correct", n, "--correct", *_trial_worst(d, d.turn, "chords", True)))
        trials.append(Trial("tangents", n, "--method tangents", *_trial_worst(d, d.turn, "tangents", False)))
    else:
        trials.append(Trial("chords", n, "--method chords", *_trial_worst(d, d.turn, "chords", False)))
    return trials


TRIAL_WORDS = {"adaptive": ("smaller intervals where the curve bends, {n} divisions", "менші інтервали там, де крива "
                            "згинається, {n} {many}"),
               "adaptive none": ("the adaptive mode, which finds no interval worth halving",
                                 "адаптивний поділ, що не знаходить інтервалу, який варто поділити"),
               "double": ("{n} divisions", "{n} {many}"),
               "correct": ("the area correction", "корекція площ"),
               "tangents": ("the method of tangents", "метод дотичних"),
               "chords": ("the method of chords", "метод хорд")}


def trial_words(t: Trial, lang: str) -> str:
    """A trial named as the notes name it (with its divisions)."""
    en, uk = TRIAL_WORDS[t.key]
    return (uk if lang == "uk" else en).format(n=t.divisions, many=uk_count(t.divisions, "поділка", "поділки", "поділок"))


def advice(d: Diagrams, lang: str) -> str:
    """What to do where the values at the positions miss the lab's 5 %, from the trials
    (``alternatives``), not from a rule: the constructions that read within 5 % (with their
    options), else those that do better, else that none does and why (the chords' own error
    against the ruler's amplified by the smaller intervals). Empty where all are within 5 %."""
    w0 = d.worst_pct()
    if w0 <= LAB_LIMIT:
        return ""
    uk = lang == "uk"
    trials = d.alternatives()
    f = (lambda v: fixed(v, "uk", 1)) if uk else (lambda v: f"{v:.1f}")   # noqa: E731
    named = lambda t: trial_words(t, lang) + (f" ({t.option})" if t.option else "")  # noqa: E731
    within = [t for t in trials if t.worst_pct <= LAB_LIMIT]
    if within:
        best = sorted(within, key=lambda t: t.worst_pct)
        items = "; ".join(f"{named(t)}: {f(t.worst_pct)} %" for t in best)
        return (f"у межах 5 % у положеннях: {items}" if uk else f"within 5 % at the positions: {items}")
    better = sorted((t for t in trials if t.worst_pct < w0 - 0.05 and t.key != "adaptive none"), key=lambda t: t.worst_pct)
    tried = "; ".join(trial_words(t, lang) + ("" if t.key == "adaptive none" else f" {f(t.worst_pct)} %")
                      for t in trials)
    if better:
        items = "; ".join(f"{named(t)}: {f(t.worst_pct)} %" for t in better)
        rest = "; ".join(trial_words(t, lang) + ("" if t.key == "adaptive none" else f" {f(t.worst_pct)} %")
                         for t in trials if t not in better)
        return (f"найбільша |δ| у положеннях, {f(w0)} %, менша з: {items}" + (f"; не менша з: {rest}" if rest else "")
                + "; жодна з цих побудов не дає 5 %" if uk else
                f"the largest |δ| at the positions, {f(w0)} %, is smaller with {items}"
                + (f"; not with {rest}" if rest else "") + "; none of these reaches 5 %")
    why = why_not(d, lang)
    searched = d.redrawn is not None and d.redrawn.off_after is not None
    return (f"жодна з випробуваних побудов не зменшує найбільшу |δ| у положеннях, {f(w0)} % ({tried}){why}; "
            + ("і жодна з побудов, які аркуш випробував у межах свого місця (H1, H2 15–50 мм, корекція площ, менші "
               "інтервали, вища діаграма s), теж не дає 5 %" if searched else
               "залишаються інші полюсні відстані (--h1, --h2) і вища діаграма s (--height)") if uk else
            f"none of the constructions tried lowers the largest |δ| at the positions, {f(w0)} % ({tried}){why}; "
            + ("nor does any the sheet tried in its room (H1, H2 15–50 mm, the area correction, smaller intervals, a "
               "taller s): no lab construction that fits reaches 5 % here" if searched else
               "other pole distances (--h1, --h2) and a taller s (--height) are left to try"))


def why_not(d: Diagrams, lang: str) -> str:
    """Why more divisions do not help, measured: the method's own error (the exact drawing's
    largest |δ| at the positions) at these divisions and at twice as many, against the drawing with
    the ruler at twice as many — the chords miss a peak that is sharp for the step, and halving the
    step amplifies the ruler's half division more than it removes that. Empty where not so."""
    dbl = next((t for t in d.alternatives() if t.key == "double"), None)
    w0 = d.worst_pct()
    if dbl is None or not (dbl.exact_pct < dbl.worst_pct and dbl.worst_pct > w0):
        return ""
    uk = lang == "uk"
    f = (lambda v: fixed(v, "uk", 1)) if uk else (lambda v: f"{v:.1f}")   # noqa: E731
    own, n, p = d.worst_pct(d.exact), d.divisions, num(d.precision, lang)
    step = num(360.0 / n, lang, 3)
    # the bend named only where it is what misses the lab's limit: the inclined crank-slider's chords
    # read 1.0 % on their own — its 8.3 % is the ruler's, and "a bend sharp for the step" misled
    sharp = own > LAB_LIMIT
    return (f": власна похибка методу при {n} {uk_count(n, 'поділці', 'поділках', 'поділках')} — {f(own)} %"
            + (f" (згин, крутий для кроку {step}°)" if sharp else "")
            + f", при {dbl.divisions} — {f(dbl.exact_pct)} %, але похибка лінійки {p} мм, "
            f"підсилена меншим кроком, дає {f(dbl.worst_pct)} %" if uk else
            f": the method's own error is {f(own)} % at {n} divisions"
            + (f" (a bend sharp for the {step}° step)" if sharp else "")
            + f" and {f(dbl.exact_pct)} % at {dbl.divisions}, but the ruler's {p} mm amplified by the smaller step "
            f"gives {f(dbl.worst_pct)} %")


def drawing_sign(out: Output, s_cycle: np.ndarray) -> int:
    """How the diagram is drawn (value = sign · mm · μ): a turning output's angle grows upward; a
    swinging one's — a slider's s, a rocker's ψ — is the displacement from the extreme position 0,
    drawn rising on the way out (seed 002: "відкладаємо … переміщення точки B повзуна від крайнього
    його положення B_0", the paths travelled, ≥ 0), whichever way along its guide or round its
    pivot it goes: the sheet then writes it so too (``kintables.drawn_sense``)."""
    growth, span = s_cycle[-1] - s_cycle[0], float(np.ptp(s_cycle))
    if abs(growth) > 1e-9 * max(span, 1e-300):
        return int(np.sign(growth))
    return 1 if np.mean(s_cycle) >= 0 else -1


# -- the study ---------------------------------------------------------------------------------------

def resolve_output(st: Study, point: str | None) -> tuple[Output, str, tuple[str, str, str], str, str]:
    """The output named by ``--point``: a sliding point (its coordinate along its guide) or a link
    (its angle). Returns (output, name, symbols, subscript, unit)."""
    mech = st.mech
    if point is None:
        out = st.output
    elif point in mech.links and (mech.links[point].slides_on is None or point == mech.crank.link):
        out = Output("link", point)
    else:
        keys = {key for key in st.solve([st.phi0]).slides}
        if point in keys:
            out = Output("slide", point)
        elif point in mech.links and next(iter(mech.links[point].local)) in keys:
            out = Output("slide", next(iter(mech.links[point].local)))
        else:
            links = ", ".join(n for n, l in mech.links.items() if l.slides_on is None)
            raise GraphplanError(f"--point {point}: not a sliding point ({', '.join(sorted(keys)) or 'none'}) "
                                 f"nor a link ({links})", mech.source)
    if out.kind == "link" and out.name == mech.crank.link:
        raise GraphplanError(f"--point {out.name}: the crank turns uniformly, its diagrams are a straight "
                             "line and two constants; name a sliding point or another link", mech.source)
    if out.kind == "slide":
        return out, out.name, ("s", "v", "a"), out.name, "m"
    return out, out.name, (angle_symbol(st, out.name), "ω", "ε"), str(mech.links[out.name].number), "rad"


def angle_symbol(st: Study, link: str) -> str:
    """The letter of a link's angle as the textbook writes it: ψ for a rocker's (a link pivoted on the
    frame that swings, never turning round: O2B of a crank-rocker, a rocking slotted lever; review
    12 #18), φ for any other (a crank, a slotted link turning round, a coupler)."""
    mech = st.mech
    lk = mech.links[link]
    if link == mech.crank.link or not any(j in mech.frame for j in lk.joints):
        return "φ"
    turn = np.unwrap(st.solve(np.linspace(0.0, 360.0, 73)).bodies[link].theta)
    return "ψ" if float(np.ptp(turn)) < 2.0 * math.pi - 1e-6 else "φ"


def division_turns(divisions: int | Sequence[float], where: str = "divisions",
                   where_file: str | None = None) -> np.ndarray:
    """Crank turns (deg) of the division ordinates from position 0, ending with 360; a refusal
    names ``where`` (the key) and ``where_file`` (the scene)."""
    if isinstance(divisions, (int, np.integer)):
        n = int(divisions)
        if not 4 <= n <= MAX_DIVISIONS:
            raise GraphplanError(f"{where} must be from 4 to {MAX_DIVISIONS}, got {n}", where_file)
        return np.arange(n + 1) * 360.0 / n
    turns = np.asarray([float(d) for d in divisions])
    if turns.size == 0 or not np.all(np.isfinite(turns)):
        raise GraphplanError(f"{where}: give a number or crank turns in degrees from position 0")
    if np.any(turns < 0) or np.any(turns >= 360):
        raise GraphplanError(f"{where}: crank turns must lie in [0, 360), got {turns.min():g}…{turns.max():g}")
    if turns[0] != 0.0:
        turns = np.concatenate(([0.0], turns))
    if np.any(np.diff(turns) <= 0):
        raise GraphplanError(f"{where}: crank turns must increase")
    if not 4 <= len(turns) <= MAX_DIVISIONS:
        raise GraphplanError(f"{where}: from 4 to {MAX_DIVISIONS} intervals, got {len(turns)}")
    return np.append(turns, 360.0)


def fitted_scale(value: float) -> float:
    """The s diagram's μs fitted to its height allowance where the series' standard value (``at_least``:
    the stroke within the allowance) draws it low: the next finer value of the same series 1, 2, 2.5,
    4, 5 × 10^k (``at_most``), the s diagram taller than the allowance by less than the series' step
    (the caller checks the room) — a student takes a scale off the series, never the seed's μS = l/h
    to two figures (review 61 #2: μψ 0,011 rad/mm where 0,01 draws ψ 83 mm in an 80-mm allowance):
    0.1 m over 80 mm → 0,00125 → 0,001 m/mm (100 mm)."""
    return at_most(value)


def choose_mu_s(st: Study, unit: str, s_range: float, height: float | None, fit: bool = False) -> float:
    """μs = μl by default (the crank 35–70 mm on the position plan, standard series); coarser when
    the stroke would be taller than 100 mm; fitted to ``height`` mm when given — a standard value
    drawing s within it, or with ``fit`` the series' next finer value (``fitted_scale``: the s diagram
    taller than its allowance, where the standard value leaves it little more than half of it).
    Angles: fitted to 80 mm (or ``height``). Always a value of the series 1, 2, 2.5, 4, 5 × 10^k."""
    span = max(s_range, 1e-12)
    if height is not None:
        return fitted_scale(span / height) if fit else standard_scale(span / height)
    if unit == "rad":
        return standard_scale(span / ANGLE_HEIGHT)
    mu = standard_scale(st.mech.crank.length / CRANK_MM)
    return mu if span / mu <= MAX_S_HEIGHT else standard_scale(span / MAX_S_HEIGHT)


def refine(st: Study, out: Output, turns: np.ndarray, sign: int, mu_s: float, L: float, H1: float,
           H2: float, tolerance: float, precision: float) -> np.ndarray:
    """The adaptive mode: split the intervals whose estimated chord error (of v or of a, in mm on
    their diagrams) exceeds ``tolerance``, the way the seed asks for smaller intervals near extrema
    and sharp bends — but only where halving pays: the chord error falls 4× while the ruler's
    error, amplified by H/h (v) and H1·H2/h² (a), grows (see ``ruler_noise``). Neighbours are kept
    within 2:1 so the spacing changes gradually."""
    for _ in range(REFINE_LEVELS):
        x = L * turns / 360.0
        s = sign * exact_motion(st, out, turns)[0] / mu_s
        e_v, e_a = chord_error_estimate(x[:-1], s[:-1] - (s[-1] - s[0]) * x[:-1] / L, L)
        h = np.diff(x)
        chord = e_v * H1 + e_a * H1 * H2
        now = chord + ruler_noise(h, H1, H2, precision)
        halved = chord / 4 + ruler_noise(h / 2, H1, H2, precision)
        split = (np.maximum(e_v * H1, e_a * H1 * H2) > tolerance) & (halved < now)
        if not split.any():
            break
        for _ in range(REFINE_LEVELS + 1):  # 2:1 balance with the neighbours after splitting
            new_h = np.where(split, h / 2, h)
            too_big = (new_h > 2.0001 * np.roll(new_h, 1)) | (new_h > 2.0001 * np.roll(new_h, -1))
            if not (too_big & ~split).any():
                break
            split |= too_big
        if len(turns) - 1 + int(split.sum()) > MAX_DIVISIONS:
            break
        mids = midpoints(turns)[split]
        turns = np.sort(np.concatenate((turns, mids)))
    return turns


def ruler_noise(h: np.ndarray, H1: float, H2: float, precision: float) -> np.ndarray:
    """Expected RMS error (mm) the ruler puts on a v and an a ordinate over intervals h: readings
    off by up to ±p/2 (RMS σ = p/√12); a chord's slope differences two of them (√2·σ·H1/h), the
    second differentiation three (√6·σ·H1·H2/h²)."""
    sigma = precision / math.sqrt(12.0)
    return math.sqrt(2.0) * sigma * H1 / h + math.sqrt(6.0) * sigma * H1 * H2 / h ** 2


def chord_diagrams(st: Study, point: str | None = None, divisions: int | Sequence[float] | None = None,
                   L: float = 240.0, H1: float = 30.0, H2: float = 30.0, precision: float = 0.5,
                   adaptive: bool = False, height: float | None = None, *,
                   tolerance: float = 0.5, chosen: Sequence[int] | None = None,
                   lang: str = "uk", method: str = "chords", angle_error_deg: float = ANGLE_ERROR_DEG,
                   correct: bool = False, seed: int = SEED, redrawn: Any = None, fit: bool = False) -> Diagrams:
    """The s, v, a diagrams of the output (or ``point``: a sliding point or a link) by chords.

    ``divisions``: a number of equal intervals (default: the scene's positions count) or the crank
    turns from position 0 (deg) of non-uniform division ordinates. ``adaptive`` splits intervals where
    the chord error estimate exceeds ``tolerance`` mm. ``height``: fit the s diagram to this many mm.
    ``chosen``: the positions of the lab's table (default: 1 and the first past half a turn).
    ``method``: "chords" (``correct``: the lab's area correction) or "tangents" (each tangent off by
    up to ``angle_error_deg``, deterministic from ``seed``; see graphic.tangents). ``redrawn``: what
    graphic.redraw changed to make these options (kept for the notes and the JSON). ``fit``: μs the
    series' next value finer than the one that draws s within ``height`` mm (``choose_mu_s``): s taller."""
    _check_positive(L=L, H1=H1, H2=H2, tolerance=tolerance)
    if method not in METHODS:
        raise GraphplanError(f"--method must be chords or tangents, got {method!r}")
    if not (0 <= angle_error_deg <= MAX_ANGLE_ERROR_DEG):
        raise GraphplanError(f"--angle-error must be from 0 to {MAX_ANGLE_ERROR_DEG:g} degrees, got {angle_error_deg}")
    if correct and method != "chords":
        raise GraphplanError("--correct is the chords' area correction; the method of tangents has none")
    if height is not None:
        _check_positive(height=height)
    if not (precision >= 0 and math.isfinite(precision)) or precision > 10:
        raise GraphplanError(f"--precision must be from 0 to 10 mm, got {precision}")
    if lang not in ("uk", "en"):
        raise GraphplanError(f"--lang must be uk or en, got {lang!r}")
    mech = st.mech
    out, name, symbols, sub, unit = resolve_output(st, point)
    turns = division_turns(mech.task.count if divisions is None else divisions,
                           "positions.count (the diagrams' divisions when [diagrams] divisions is not given)"
                           if divisions is None else "divisions", mech.source)

    cycle_turn = np.arange(CYCLE + 1) * 360.0 / CYCLE
    s_c, v_c, a_c = exact_motion(st, out, cycle_turn)
    s_range = float(np.ptp(s_c))
    sign = drawing_sign(out, s_c)
    mu_s = choose_mu_s(st, unit, s_range, height, fit and height is not None)
    mu_t = 2 * math.pi / (abs(mech.omega1) * L)     # μt = T/L = 2π/(ω1·L)
    mu_v = mu_s / (mu_t * H1)
    mu_a = mu_v / (mu_t * H2)

    uniform = turns.copy()
    if adaptive:
        turns = refine(st, out, turns, sign, mu_s, L, H1, H2, tolerance, precision)
    x = L * turns / 360.0
    s_t, v_at_t, a_at_t = exact_motion(st, out, turns)
    own = turns[:-1] if method == "tangents" else midpoints(turns)   # where the method yields v, a
    _, v_mid_t, a_mid_t = exact_motion(st, out, own)
    truth = {"s": s_t, "v_mid": v_mid_t, "v_at": v_at_t, "a_mid": a_mid_t, "a_at": a_at_t,
             "s_int": s_t, "v_int": v_at_t}
    maxima = {"s": float(np.max(np.abs(s_c))), "v": float(np.max(np.abs(v_c))),
              "a": float(np.max(np.abs(a_c)))}
    s_mm = sign * s_t / mu_s
    if method == "tangents":
        drawn = construct_tangents(x, s_mm, L, H1, H2, precision, angle_error_deg, seed)
        exact = construct_tangents(x, s_mm, L, H1, H2, 0.0, 0.0, seed)
    else:
        zeros = stops(x, v_at_t, maxima["v"])
        drawn = construct(x, s_mm, L, H1, H2, precision, correct, zeros)
        exact = construct(x, s_mm, L, H1, H2, 0.0, correct, zeros)

    on_grid = {round(float(u), 9): k for k, u in enumerate(uniform[:-1])}
    position = [on_grid.get(round(float(u), 9)) for u in turns[:-1]] + [0]
    if chosen is None:
        n0 = len(uniform) - 1
        chosen = tuple(p for p in (1, n0 // 2 + 1) if p < n0)
    else:
        chosen = tuple(int(c) for c in chosen)
        n0 = len(uniform) - 1
        for c in chosen:
            if not 0 <= c < n0:
                raise GraphplanError(f"--at: positions are 0 … {n0 - 1}, got {c}")
    e_v, e_a = chord_error_estimate(x[:-1], s_mm[:-1] - (s_mm[-1] - s_mm[0]) * x[:-1] / L, L)
    d = Diagrams(st, out, name, symbols, sub, unit, sign, float(L), float(H1), float(H2), float(precision),
                 bool(adaptive), float(tolerance), mu_s, mu_t, mu_v, mu_a, turns, position, x,
                 crank_angle(st, turns), crank_angle(st, own), drawn, exact, truth, maxima,
                 chosen, {"v_mm": e_v * H1, "a_mm": e_a * H1 * H2}, lang=lang, method=method,
                 angle_error_deg=float(angle_error_deg) if method == "tangents" else 0.0, correct=bool(correct),
                 redrawn=redrawn)
    return d        # its ``warnings`` diagnosed where read


def _check_positive(**values: float) -> None:
    for key, value in values.items():
        if not (value > 0 and math.isfinite(value)):
            raise GraphplanError(f"--{key.lower()} must be a positive number of mm, got {value}")


# -- where the method fails ----------------------------------------------------------------------

def rms(a: np.ndarray) -> float:
    return float(np.sqrt(np.mean(np.square(a)))) if len(a) else 0.0


def _amplified(ruler: dict, lang: str) -> str:
    """How each differentiation multiplies the reading error; a stage drawn exactly (no error to
    amplify: the tangents' directions alone err) is said so instead of an infinite factor."""
    parts = []
    for k, (en, uk) in enumerate((("the first differentiation", "перше диференціювання"),
                                   ("the second", "друге"))):
        f = ruler["first" if k == 0 else "second"]
        if f is None:
            parts.append(f"{en} starts from an exact curve (its error is the tangents' own)" if lang == "en"
                         else f"{uk} починається з точної кривої (похибка — від напрямів дотичних)")
        else:
            parts.append(f"{en} amplifies it ×{f:.1f}" if lang == "en" and k == 0 else
                         f"{en} ×{f:.1f}" if lang == "en" else
                         f"{uk} підсилює її ×{fixed(f, 'uk', 1)}" if k == 0 else f"{uk} ×{fixed(f, 'uk', 1)}")
    return ", ".join(parts)


def ruler_effect(d: Diagrams) -> dict[str, float] | None:
    """The ruler's share of the error: drawing at the precision minus the exact drawing, RMS in
    percent of each diagram's maximum, and the factor each differentiation multiplies it by."""
    if d.precision == 0 and d.angle_error_deg == 0:
        return None
    mx = {key: d.maxima[key] / mu for key, mu in (("s", d.mu_s), ("v", d.mu_v), ("a", d.mu_a))}
    dr, ex = d.drawn, d.exact
    s = 100 * rms(dr.s - ex.s) / mx["s"]
    v = 100 * rms(dr.v - ex.v) / mx["v"]
    a = 100 * rms(dr.a - ex.a) / mx["a"]
    return {"s_rms_pct": s, "v_rms_pct": v, "a_rms_pct": a,
            # no amplification to speak of where the stage before is exact (precision 0 with the
            # tangents' angular error: s is drawn exactly, v's error is the tangents' own)
            "first": v / s if s > 0 else None, "second": a / v if v > 0 else None,
            "v_max_pct": 100 * float(np.max(np.abs(dr.v - ex.v))) / mx["v"],
            "a_max_pct": 100 * float(np.max(np.abs(dr.a - ex.a))) / mx["a"]}


def _near_extreme(d: Diagrams, k: int) -> float | None:
    """An extreme position (crank turn, deg) within one interval of interval k, if any."""
    st = d.study
    lo, hi = d.turn[k], d.turn[k + 1]
    width = hi - lo
    for e in st.extremes:
        u = float(st.from_position0(e))
        for cand in (u, u + 360.0, u - 360.0):
            if lo - width <= cand <= hi + width:
                return float(e)
    return None


def _where(d: Diagrams, k: int, lang: str) -> str:
    """Interval k with its crank angles and why the chord misses there."""
    e = _near_extreme(d, k)
    a = 100 * abs(d.truth["a_mid"][k]) / d.maxima["a"]
    sym = d.symbols[2]
    if lang == "uk":
        place = f"{k}–{k + 1} (φ = {fixed(d.phi[k], lang, 1)}…{fixed(d.phi[k + 1], lang, 1)}°"
        if e is not None:
            return place + f", біля крайнього положення φ = {fixed(e, lang, 1)}°)"
        return place + f", крутий згин: |{sym}| = {a:.0f} % від максимуму)"
    place = f"{k}–{k + 1} (φ = {d.phi[k]:.1f}…{d.phi[k + 1]:.1f}°"
    if e is not None:
        return place + f", next to the extreme position at φ = {e:.1f}°)"
    return place + f", a sharp bend: |{sym}| = {a:.0f} % of its maximum)"


def _tangent_error(d: Diagrams, sym: str, err: np.ndarray, bad: np.ndarray) -> dict[str, Any]:
    """The exact tangents' own error past the lab's 5 %: tangents to the French curve through the
    s (or v) ordinates are not the tangents of the motion's curve."""
    worst = bad[np.argsort(-np.abs(err[bad]))][:3]
    en = "; ".join(f"{err[k]:+.1f} % at ordinate {k} (φ = {d.phi[k]:.1f}°)" for k in worst)
    uk = "; ".join(f"{err[k]:+.1f} % на ординаті {k} (φ = {d.phi[k]:.1f}°)" for k in worst)
    return {"kind": "tangent_error", "diagram": sym, "ordinates": [int(k) for k in bad],
            "max_pct_of_max": float(np.max(np.abs(err))),
            "message": f"exact tangents to the drawn curve miss {sym} by more than {LAB_LIMIT:g} % of |{sym}|max "
                       f"at {bad.size} of {d.divisions} ordinates: {en}" + _within_tail(d, "en"),
            "message_uk": f"точні дотичні до накресленої кривої дають {sym} з похибкою понад {LAB_LIMIT:g} % від "
                          f"|{sym}|max на {bad.size} з {d.divisions} ординат: {uk}" + _within_tail(d, "uk")}


def _within_tail(d: Diagrams, lang: str) -> str:
    """A method's error past 5 % between the positions, where the values at the positions are within
    the lab's 5 % (what the lab judges): said so; else nothing (the ``advice`` warning says what helps)."""
    w0 = d.worst_pct()
    if w0 > LAB_LIMIT or not d.at_positions:
        return ""
    return (f"; значення в положеннях — у межах 5 % (найбільша |δ| {fixed(w0, 'uk', 1)} %)" if lang == "uk" else
            f"; the values at the positions are within 5 % (largest |δ| {w0:.1f} %)")


def diagnose(d: Diagrams) -> list[dict[str, Any]]:
    """Warnings, each with its numbers and a ``message`` (English) and ``message_uk``: the chord
    error of v and a (the exact drawing's, so the ruler does not hide it), the division ordinates
    past the lab's 5 %, the ruler's error amplified by each differentiation, diagrams too tall or
    too flat for their pole distances."""
    out: list[dict[str, Any]] = []
    n = d.divisions
    for key, sym in (("v_mid", d.symbols[1]), ("a_mid", d.symbols[2])):
        err = d.errors_of_max(key, d.exact)
        bad = np.flatnonzero(np.abs(err) > LAB_LIMIT)
        if bad.size and d.method == "tangents":
            out.append(_tangent_error(d, sym, err, bad))
        elif bad.size:
            worst = bad[np.argsort(-np.abs(err[bad]))][:3]
            en = "; ".join(f"{err[k]:+.1f} % in interval {_where(d, k, 'en')}" for k in worst)
            uk = "; ".join(f"{fixed(err[k], 'uk', 1, plus=True)} % в інтервалі {_where(d, k, 'uk')}" for k in worst)
            out.append({"kind": "chord_error", "diagram": sym, "intervals": [int(k) for k in bad],
                        "max_pct_of_max": float(np.max(np.abs(err))),
                        "message": f"chord error of {sym} exceeds {LAB_LIMIT:g} % of |{sym}|max in {bad.size} "
                                   f"of {n} intervals: {en}" + _within_tail(d, "en"),
                        "message_uk": f"похибка хорд для {sym} перевищує {num(LAB_LIMIT, 'uk')} % від |{sym}|_max у "
                                      f"{bad.size} з {n} інтервалів: {uk}" + _within_tail(d, "uk")})
    for key, sym in (("v_at", d.symbols[1]), ("a_at", d.symbols[2])):
        pct = d.errors_pct(key)[:-1]
        judged = np.abs(d.truth[key][:-1]) >= MEANINGFUL * d.maxima[key[0]]
        bad = np.flatnonzero(judged & (np.abs(np.nan_to_num(pct)) > LAB_LIMIT))
        if bad.size:
            text = ", ".join(f"{k} ({pct[k]:+.1f} %)" for k in bad[:8]) + (" …" if bad.size > 8 else "")
            out.append({"kind": "lab_limit", "diagram": sym, "ordinates": [int(k) for k in bad],
                        "error_pct": [float(pct[k]) for k in bad],
                        "message": f"{sym} read at the division ordinates misses the lab's {LAB_LIMIT:g} % at "
                                   f"{text}",
                        "message_uk": f"{sym}, прочитане на ординатах поділу, виходить за {num(LAB_LIMIT, 'uk')} % "
                                      f"лабораторної роботи в " + ", ".join(
                                          f"{k} ({fixed(pct[k], 'uk', 1, plus=True)} %)" for k in bad[:8])
                                      + (" …" if bad.size > 8 else "")})
    if d.worst_pct() > LAB_LIMIT:
        trials = d.alternatives()
        out.append({"kind": "advice", "worst_pct": d.worst_pct(), "tried": [t.to_json() for t in trials],
                    "message": advice(d, "en"), "message_uk": advice(d, "uk")})
    ruler = ruler_effect(d)
    if ruler is not None:
        s0, v1, v2 = d.symbols
        errs = f"{s0} {ruler['s_rms_pct']:.2f} %, {v1} {ruler['v_rms_pct']:.2f} %, {v2} {ruler['a_rms_pct']:.2f} %"
        en, uk = f"the ruler's {d.precision:g} mm", f"похибка відліку лінійкою {d.precision:g} мм"
        if d.angle_error_deg:
            en += f" and the tangents' ±{d.angle_error_deg:g}°"
            uk += f" і дотичних ±{d.angle_error_deg:g}°"
        out.append({"kind": "ruler", "amplification_first": ruler["first"],
                    "amplification_second": ruler["second"],
                    "message": f"{en} reading error (RMS, % of the maximum): {errs}; " + _amplified(ruler, "en"),
                    "message_uk": f"похибка відліку лінійкою {num(d.precision, 'uk')} мм (СКВ, % від максимуму): "
                                  f"{errs.replace('.', ',')}; " + _amplified(ruler, "uk")})
    for sym, rd, H, opt in ((d.symbols[1], d.drawn.v, d.H1, "--h1"), (d.symbols[2], d.drawn.a, d.H2, "--h2")):
        tall = float(np.ptp(np.append(rd, 0.0)))
        if tall > 200 or tall < 15:
            better = H * 60.0 / max(tall, 1e-9)
            out.append({"kind": "height", "diagram": sym, "height_mm": tall,
                        "message": f"the {sym} diagram is {tall:.0f} mm tall with H = {H:g} mm; "
                                   f"{opt} {better:.0f} would make it about 60 mm",
                        "message_uk": f"діаграма {sym} має висоту {tall:.0f} мм при H = {num(H, 'uk')} мм; "
                                      f"{opt} {better:.0f} дасть близько 60 мм"})
    out.extend(qualitative.check(d))
    if d.study.mech.crank.epsilon != 0:
        out.append({"kind": "epsilon1",
                    "message": "the diagrams take one crank period at constant ω1; the scene's ε1 ≠ 0 is in "
                               "the analytic values only",
                    "message_uk": "діаграми побудовано для сталої ω1; задане ε1 ≠ 0 враховане лише в "
                                  "аналітичних значеннях"})
    return out
