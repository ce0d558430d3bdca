"""Diagrams redrawn until they are qualitatively right, as a student redraws them (seed 002).

A diagram whose French curve has extrema or zero crossings the motion lacks (or misses some it has:
graphic.qualitative) is not handed in: the student redraws it with what the lab allows — the area
correction of the chords (graphic.correction: only the curves are drawn again), other pole distances
(H1, H2 within the lab's 15–50 mm: a taller diagram, the ruler's half division a smaller share of
it), a longer abscissa L (where the sheet has room), smaller intervals where the curve bends
(``refine``, the adaptive mode). ``redraw`` tries them in that order, cheapest first, and takes the
first drawing whose v and a diagrams are both qualitatively right; where none is, the first drawing
stays and its note with it.

A candidate is judged on the diagram alone — the construction (``construct``) and the qualitative
comparison (``qualitative.of_ordinates``), the exact motion sampled once — a few milliseconds each,
not a sheet."""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, Callable, Iterator

import numpy as np

from graphplan.exact.positions import exact_motion
from graphplan.graphic import qualitative
from graphplan.graphic.chords import midpoints, periodic_spline, read
from graphplan.graphic.diagrams import (CYCLE, drawing_sign, choose_mu_s, differentiate, division_turns, judged_pct,
                                        LAB_LIMIT, refine, resolve_output, stops, v_knots)

LAB_POLES = (15.0, 50.0)    # mm: the pole distances H1, H2 the lab manual allows
POLE_STEP = 5.0             # mm: a pole distance is tried larger in these steps
LONGER = (1.25, 1.5, 2.0)   # L tried this many times longer, up to the longest the sheet allows
CORRECTED_PAIRS = 16        # the nearest pole pairs tried with the correction too (it is the costly one)
TALLER = (1.25,)    # the s diagram tried this many times taller (the sheet's room permitting)
LOWER = (0.8, 0.64, 0.5, 0.4)   # … and this many times lower, where a right drawing's larger poles outgrow the room
WORTHWHILE = 0.8    # a redrawing that reaches no 5 % is taken where it cuts the largest |δ| at least to this share
FINER = 0.25                # mm: the adaptive mode's tolerance tried after its default (0.5 mm)
LAB_ALLOWANCE = 0.05    # the lab's allowed |δ| at the positions
# A redrawing draws the v and a peaks at least READABLE_MM high (or as high as first drawn): there the ruler's
# 0.5 mm is 2.5 % of the peak, half the lab's 5 %, and a diagram of both signs spans 40 mm, the seeds' 40–80 mm.
READABLE_MM = 0.5 / (LAB_ALLOWANCE / 2)


@dataclass(frozen=True)
class Redrawing:
    """What ``redraw`` chose: the options changed from the first drawing (``chord_diagrams``
    keywords: ``correct``, ``H1``, ``H2``, ``L``, ``adaptive``, ``tolerance``, ``height``), the first
    drawing's and the chosen drawing's qualitatively wrong diagrams ("v", "a"), the candidates
    tried, and the largest |δ| at the positions of each (judged_pct)."""
    changed: dict[str, Any] = field(default_factory=dict)
    wrong_before: tuple[str, ...] = ()
    wrong_after: tuple[str, ...] = ()
    tried: int = 0
    first: dict[str, Any] = field(default_factory=dict)   # the first drawing's values of the changed keys
    off_before: float | None = None   # the largest |δ|, % at the positions: the first drawing's
    off_after: float | None = None    # … and the chosen one's (None: not measured)
    searched: frozenset[str] = frozenset()   # the options the candidates varied (a longer "L" only where room was)

    @property
    def right(self) -> bool:
        return not self.wrong_after

    @property
    def within(self) -> bool:
        """Whether the chosen drawing reads within the lab's 5 % at the positions."""
        return self.off_after is not None and self.off_after <= LAB_LIMIT

    @property
    def for_errors(self) -> bool:
        """Whether the drawing was changed for its errors at the positions alone (it was right)."""
        return bool(self.changed) and not self.wrong_before

    def to_json(self) -> dict[str, Any]:
        return {"changed": dict(self.changed), "before": dict(self.first), "wrong_before": list(self.wrong_before),
                "wrong_after": list(self.wrong_after), "tried": self.tried,
                "worst_pct_before": self.off_before, "worst_pct_after": self.off_after}


_JUDGED: dict[tuple, Any] = {}     # ``Probe``'s judgments of a drawing, kept across probes of one output
JUDGED_MOST = 50_000              # judgments kept (some 15 MB at most); past it the memo starts afresh


class Probe:
    """The exact motion of one output sampled once — the division ordinates' s and the comparison's
    v, a — on which drawings of different L, H1, H2, correction and divisions are tried.

    A drawing's judgments (``wrong``, ``off``, ``peaks``) are kept across the probes of the same
    mechanism, output, divisions and ruler (the module's ``_JUDGED``), keyed on the drawing's options
    with its s height as the μs it chooses (``choose_mu_s``: the construction reads the height
    through μs alone) — a set's diagrams' sizes are searched by height factor (kinlayout
    ``tallest``), each height redrawn with the same menu of pole distances over a few μs."""

    def __init__(self, st, point: str | None, divisions, precision: float) -> None:
        self.st = st
        self.out, _, _, _, self.unit = resolve_output(st, point)
        self.turns = division_turns(st.mech.task.count if divisions is None else divisions)
        cycle = np.arange(CYCLE + 1) * 360.0 / CYCLE
        s_c, v_c, a_c = exact_motion(st, self.out, cycle)
        self.s_range = float(np.ptp(s_c))
        self.sign = drawing_sign(self.out, s_c)
        self.s, self.v_pos, self.a_pos = exact_motion(st, self.out, self.turns)
        self.max_s, self.max_v, self.max_a = (float(np.max(np.abs(q))) for q in (s_c, v_c, a_c))
        self.sample = qualitative.sample_turns()
        _, self.v, self.a = exact_motion(st, self.out, self.sample)
        self.precision = precision
        self.omega = abs(st.mech.omega1)
        self.memo: dict = {}
        self.mus: dict = {}
        self.key = (repr(st.mech), point, self.turns.tobytes(), float(precision))

    def _judged(self, what: str, L, H1, H2, correct, adaptive, tolerance, height, make, *extra, fit: bool = False):
        """``make()`` for this drawing, once across the probes of this output (``_JUDGED``)."""
        if (height, fit) not in self.mus:
            self.mus[height, fit] = choose_mu_s(self.st, self.unit, self.s_range, height, fit)
        key = (self.key, what, L, H1, H2, correct, adaptive, tolerance, self.mus[height, fit], *extra)
        if key not in _JUDGED:
            if len(_JUDGED) >= JUDGED_MOST:
                _JUDGED.clear()
            _JUDGED[key] = make()
        return _JUDGED[key]

    def readings(self, L: float, H1: float, H2: float, correct: bool = False, adaptive: bool = False,
                 tolerance: float = 0.5, height: float | None = None, fit: bool = False):
        """The drawing with these options, as ``chord_diagrams`` constructs it: (turns, μs, μv, μa,
        the read v and a at the middles, the v and a curves read at the division ordinates, s read);
        each drawing constructed once (``wrong`` and ``off`` judge the same one)."""
        key = (L, H1, H2, correct, adaptive, tolerance, height, fit)
        if key not in self.memo:
            if len(self.memo) > 4:
                self.memo.clear()
            self.memo[key] = self._readings(*key)
        return self.memo[key]

    def _readings(self, L, H1, H2, correct, adaptive, tolerance, height, fit=False):
        turns, s = self.turns, self.s
        mu_s = choose_mu_s(self.st, self.unit, self.s_range, height, fit and height is not None)
        if adaptive:
            turns = refine(self.st, self.out, turns, self.sign, mu_s, L, H1, H2, tolerance, self.precision)
            if len(turns) != len(self.turns):
                s = exact_motion(self.st, self.out, turns)[0]
        x = L * turns / 360.0
        v_pos = self.v_pos if len(turns) == len(self.turns) else exact_motion(self.st, self.out, turns)[1]
        zeros = stops(x, v_pos, self.max_v)
        s_r, _, v, v_at, _, a = differentiate(x, self.sign * s / mu_s, L, H1, H2, self.precision, correct, zeros)
        mu_t = 2 * math.pi / (self.omega * L)
        mu_v = mu_s / (mu_t * H1)
        mu_a = mu_v / (mu_t * H2)
        return turns, x, mu_s, mu_v, mu_a, v, a, v_at, s_r, zeros

    def wrong(self, L: float, H1: float, H2: float, correct: bool = False, adaptive: bool = False,
              tolerance: float = 0.5, height: float | None = None, all_of: bool = True, fit: bool = False
              ) -> tuple[str, ...]:
        """The diagrams ("v", "a") a drawing with these options gets qualitatively wrong, as
        ``chord_diagrams`` would report them (the same construction, ruler and comparison);
        ``all_of`` False: the first wrong one only (enough to reject a candidate)."""
        return self._judged("wrong", L, H1, H2, correct, adaptive, tolerance, height,
                            lambda: self._wrong(L, H1, H2, correct, adaptive, tolerance, height, all_of, fit), all_of,
                            fit=fit)

    def _wrong(self, L, H1, H2, correct, adaptive, tolerance, height, all_of, fit=False) -> tuple[str, ...]:
        turns, x, _, mu_v, mu_a, v, a, _, _, zeros = self.readings(L, H1, H2, correct, adaptive, tolerance, height, fit)
        window, visible = qualitative.window_of(turns), max(qualitative.VISIBLE_MM, self.precision)
        xm = midpoints(x)
        wrong = []
        for key, knots, exact, mu in (("v", v_knots(xm, v, zeros), self.v, mu_v), ("a", (xm, a), self.a, mu_a)):
            if qualitative.of_ordinates(self.sample, *knots, L, self.sign * exact / mu, window, visible).wrong:
                wrong.append(key)
                if not all_of:
                    break
        return tuple(wrong)

    def off(self, L: float, H1: float, H2: float, correct: bool = False, adaptive: bool = False,
            tolerance: float = 0.5, height: float | None = None, fit: bool = False) -> float:
        """The largest |δ|, % of s, v, a read at the mechanism's positions off a drawing with these
        options, judged as the lab's 5 % judges them (graphic.diagrams.judged_pct)."""
        return self._judged("off", L, H1, H2, correct, adaptive, tolerance, height,
                            lambda: self._off(L, H1, H2, correct, adaptive, tolerance, height, fit), fit=fit)

    def _off(self, L, H1, H2, correct, adaptive, tolerance, height, fit=False) -> float:
        turns, x, mu_s, mu_v, mu_a, _, a, v_at, s_r, _ = self.readings(L, H1, H2, correct, adaptive, tolerance, height,
                                                                       fit)
        at = np.isin(np.round(turns[:-1], 9), np.round(self.turns[:-1], 9))
        a_at = read(periodic_spline(midpoints(x), a, L)(x), self.precision)
        worst = 0.0
        for got, mu, truth, big in ((s_r, mu_s, self.s, self.max_s), (v_at, mu_v, self.v_pos, self.max_v),
                                    (a_at, mu_a, self.a_pos, self.max_a)):
            pct = judged_pct(self.sign * got[:-1][at] * mu, truth[:-1], big)
            worst = max(worst, float(np.max(np.abs(pct))))
        return worst

    def peaks(self, L: float, H1: float, H2: float, correct: bool = False, adaptive: bool = False,
              tolerance: float = 0.5, height: float | None = None, fit: bool = False) -> tuple[float, float, float]:
        """The drawing's largest ordinates, mm: |v| and |a| read at the middles, and the s diagram's
        height (its range)."""
        def make() -> tuple[float, float, float]:
            _, _, _, _, _, v, a, _, s_r, _ = self.readings(L, H1, H2, correct, adaptive, tolerance, height, fit)
            return float(np.max(np.abs(v))), float(np.max(np.abs(a))), float(np.ptp(s_r))
        return self._judged("peaks", L, H1, H2, correct, adaptive, tolerance, height, make, fit=fit)


def readable(peaks: tuple[float, float, float], first: tuple[float, float, float], zone: float,
             precision: float = 0.5) -> bool:
    """Whether a redrawing's v and a diagrams are as readable as the lab asks: each one's largest
    ordinate at least ``READABLE_MM`` (20 mm: the ruler's 0.5 mm then costs 2.5 % of the peak, half
    the lab's 5 %; ``zone``, the s diagram's allowance on the sheet, caps it where the band is lower
    than 40 mm), or — where the first drawing's was
    lower (its poles at the lab's 50 mm, a low s) — no lower than the first drawing's, to the ruler's
    ``precision``. A drawing the lab sends back as flat is not a redrawing: the crank-slider of
    review 42 went from H2 32 to 20 mm for 4.9 % at the positions and drew its a diagram 28.5 mm high
    in an 80-mm band."""
    return all(got >= min(READABLE_MM, zone / 2, was) - precision - 1e-9 for got, was in zip(peaks[:2], first[:2]))


POLE_MENU = tuple(float(h) for h in range(15, 51, 5))   # mm: the pole distances a redrawing takes (the lab's 15–50)


def _larger(h: float, top: float) -> list[float]:
    """The menu's pole distances above ``h`` up to ``top``."""
    return [p for p in POLE_MENU if h + 1e-9 < p <= top + 1e-9]


def candidates(L: float, H1: float, H2: float, wrong: tuple[str, ...], poles=LAB_POLES,
               longest: float | None = None, fixed: frozenset[str] = frozenset(), height: float | None = None,
               tallest: float | None = None) -> Iterator[dict[str, Any]]:
    """The redrawings in the order a student tries them, each a dict of changed options:

    1. the area correction (the curves alone drawn again);
    2. the pole distance of the wrong diagram larger (H2 for a, H1 for v — H1 scales the v diagram
       and so the curve a starts from), step by step to the lab's largest, then both;
    3. a longer L (up to ``longest``) and the s diagram as high or taller in proportion (up to
       ``tallest``: a finer μs), the pole distances as they are (the diagrams flatter) and grown with
       it (the diagrams as tall), with and without the correction;
    4. smaller intervals where the curve bends (the adaptive mode, then a finer tolerance);
    5. any other pair of pole distances from the menu (15–50 mm), nearest the first drawing's first,
       the nearest ``CORRECTED_PAIRS`` also with the correction — the ruler's readings fall
       differently on each;
    6. smaller intervals where the curve bends with each of the nearest ``CORRECTED_PAIRS`` pairs
       (the adaptive mode's taller a diagram over the first poles may not fit where lower poles
       do: the coulisse driving a rocker of stop 51 read ε5 57 % off at 30° steps, 25 % with
       smaller intervals at the first poles, a block 6 % taller, and 17 % at H1 20, H2 25 mm).

    ``fixed``: options the scene gives (H1, H2, L), not changed."""
    lo, top = poles
    yield {"correct": True}
    first = ("H1",) if wrong == ("v",) else ("H2", "H1")
    for key in first:
        if key in fixed:
            continue
        for h in _larger(H1 if key == "H1" else H2, top):
            yield {key: h}
    if not {"H1", "H2"} & fixed:
        for h in _larger(min(H1, H2), top):
            yield {"H1": max(H1, h), "H2": max(H2, h)}
    if longest is not None and "L" not in fixed:
        for f in sorted({f for f in LONGER if L * f <= longest + 1e-9} | ({longest / L} if longest > L + 1e-9 else set())):
            grown = {} if {"H1", "H2"} & fixed else {"H1": min(top, H1 * f), "H2": min(top, H2 * f)}
            taller = ({"height": min(tallest, height * f)} if height is not None and tallest is not None
                      and height < tallest - 1e-9 else {})
            for size in ({}, taller) if taller else ({},):
                for poles_ in ({}, grown):
                    yield {"L": L * f, **size, **poles_}
                    yield {"L": L * f, **size, **poles_, "correct": True}
    for extra in ({}, {"correct": True}):
        yield {"adaptive": True, **extra}
        yield {"adaptive": True, "tolerance": FINER, **extra}
    if {"H1", "H2"} & fixed:
        return
    menu = [h for h in POLE_MENU if lo - 1e-9 <= h <= top + 1e-9]
    pairs = sorted(((h1, h2) for h1 in menu for h2 in menu),
                   key=lambda p: (abs(p[0] - H1) + abs(p[1] - H2), p))
    for h1, h2 in pairs:
        yield {"H1": h1, "H2": h2}
    for h1, h2 in pairs[:CORRECTED_PAIRS]:
        yield {"H1": h1, "H2": h2, "correct": True}
    for h1, h2 in pairs[:CORRECTED_PAIRS]:
        yield {"H1": h1, "H2": h2, "adaptive": True}


def taller(height: float | None, H1: float | None = None, H2: float | None = None,
           fixed: frozenset[str] = frozenset(), poles=LAB_POLES) -> Iterator[dict[str, Any]]:
    """The s diagram drawn taller (a finer μs: the ruler's half division a smaller share of every
    ordinate, the v and a diagrams as much taller), with and without the correction; then, where
    the pole distances are free, with the other pairs of the menu, nearest the first drawing's
    first, with the correction and without (a finer μs doubles the v and a ordinates: the poles
    the first drawing needed over a low s draw them too tall — the coulisse's A3 set kept H1 50,
    H2 43 over an s 36 mm high, its a-diagram with a shoulder and 29 % off, where the A1's s 72 mm
    high with H1 25, H2 35 and the correction is right); the caller's ``fits`` bounds it by the
    sheet's room."""
    if height is None:
        return
    for f in TALLER:
        yield {"height": height * f}
        yield {"height": height * f, "correct": True}
    if H1 is None or H2 is None or {"H1", "H2"} & fixed:
        return
    lo, top = poles
    menu = [h for h in POLE_MENU if lo - 1e-9 <= h <= top + 1e-9]
    pairs = sorted(((h1, h2) for h1 in menu for h2 in menu), key=lambda p: (abs(p[0] - H1) + abs(p[1] - H2), p))
    for h1, h2 in pairs[CORRECTED_PAIRS:]:       # the rest of the menu corrected, as high as first drawn
        yield {"H1": h1, "H2": h2, "correct": True}
    for f in TALLER:
        for h1, h2 in pairs:
            yield {"height": height * f, "H1": h1, "H2": h2, "correct": True}
            yield {"height": height * f, "H1": h1, "H2": h2}


def lower(probe: "Probe", base: dict[str, Any], right: list[tuple[float, int, dict[str, Any]]],
          fits: Callable[[dict[str, Any], bool], bool], options: dict[str, Any]) -> tuple[dict[str, Any], float] | None:
    """A right drawing every one of whose candidates outgrew the room (larger poles make the v and a
    ordinates proportionally taller: y_v = H1·Δs/Δx, y_a = H2·Δy_v/Δx): the same poles over an s
    diagram ``LOWER`` times as high (a coarser μs; the v and a diagrams as much lower), the first that
    is still right and fits — the student's redrawing at a size the sheet holds (a generated
    four-bar's ε was left "qualitatively wrong" though H1 = H2 = 50 mm draws it right, 2.5 times as
    tall). None where there is no s height to lower or nothing fits."""
    if base.get("height") is None:
        return None
    for off, _, change in sorted(right, key=lambda r: r[:2]):
        if not change:
            continue
        for f in LOWER:
            change_ = {**change, "height": float(base["height"]) * f}
            trial = {**base, **change_}
            if probe.wrong(**trial, all_of=False) or not fits({**options, **change_}, True):
                continue
            return change_, probe.off(**trial)
    return None


FIT_BELOW = 0.7    # a standard μs drawing s lower than this share of its allowance leaves room to fit μs


def fitted(probe: "Probe", base: dict[str, Any], first_peaks, zone: float, precision: float, fits, options,
           fixed: frozenset[str], poles, seen: set) -> tuple[dict[str, Any], float] | None:
    """A wrong first drawing whose every readable right redrawing outgrew the room, its s diagram
    drawn by a standard μs at less than ``FIT_BELOW`` of its allowance (the next step of the series
    would be up to twice as tall): the series' next finer μs (``choose_mu_s`` ``fit``), the s diagram
    taller than its allowance by less than that step, with the first poles, then each pair of the
    menu nearest them, with and without the correction — of the readable right ones (v and a at least
    ``READABLE_MM``), the one read closest to the exact at the positions that ``fits`` (the room: a
    student takes 0,01 rad/mm where it fits, else the standard 0,02, never the seed's ψmax/h to two
    figures, 0,011 — review 61 #2). Review: the V-compressor's A1 drew s 50 mm high under an 80-mm
    allowance (μs 0,002) and, its first a diagram wrong, took H1 15 mm for a right one: v and a 10 and
    12 mm high under a 70-mm band."""
    height = base.get("height")
    if height is None or base.get("fit") or first_peaks[2] >= FIT_BELOW * float(height):
        return None
    menu = [h for h in POLE_MENU if poles[0] - 1e-9 <= h <= poles[1] + 1e-9]
    H1, H2 = base["H1"], base["H2"]
    pairs = [(H1, H2)] + ([] if {"H1", "H2"} & fixed else
                          sorted(((h1, h2) for h1 in menu for h2 in menu),
                                 key=lambda p: (abs(p[0] - H1) + abs(p[1] - H2), p)))
    right: list[tuple[float, int, dict[str, Any]]] = []
    for order, (h1, h2) in enumerate(pairs):
        for corr in (False, True):
            change = {"fit": True, "H1": h1, "H2": h2, "correct": corr}
            trial = {**base, **change}
            key = tuple(sorted(trial.items()))
            if key in seen:
                continue
            seen.add(key)
            if not readable(probe.peaks(**trial), first_peaks, zone, precision) or probe.wrong(**trial, all_of=False):
                continue
            right.append((probe.off(**trial), order, {k: v for k, v in change.items() if trial[k] != base[k]}))
    for off, _, change in sorted(right, key=lambda r: r[:2]):
        if fits is None or fits({**options, **change}, True):
            return change, off
    return None


def redraw(st, options: dict[str, Any], precision: float, poles=LAB_POLES, longest: float | None = None,
           fixed: frozenset[str] = frozenset(), tallest: float | None = None,
           fits: Callable[[dict[str, Any]], bool] | None = None, menu: bool = False) -> tuple[dict[str, Any], Redrawing]:
    """The options of a drawing both qualitatively right and read within the lab's 5 % at the
    positions: ``options`` (``chord_diagrams`` keywords: point, divisions, L, H1, H2, height) as given
    where that drawing is both, else the first candidate (``candidates``, then ``taller``; each tried
    once) that is and that ``fits`` (the caller's room: a drawing too large for it is passed over;
    its second argument False where the first drawing was right: no larger than it). ``menu``: a
    wrong first drawing is also tried with every pair of the pole menu, corrected, and over a taller
    s (``taller``) — a set's diagrams, on a sheet of their own (on an A1 a taller right drawing
    the room passes may not fit beside the plans: a press's went from 0.8 to 0.64 of its size).
    Where none reaches 5 %: the qualitatively right one with the smallest largest |δ| at the
    positions (the first drawing, unless another cuts that by at least ``WORTHWHILE``); none right:
    ``options`` unchanged (their warnings stay). Returns the options and what was done."""
    probe = Probe(st, options.get("point"), options.get("divisions"), precision)
    L, H1, H2 = float(options["L"]), float(options["H1"]), float(options["H2"])
    base = {"L": L, "H1": H1, "H2": H2, "correct": bool(options.get("correct", False)),
            "adaptive": bool(options.get("adaptive", False)), "tolerance": float(options.get("tolerance", 0.5)),
            "height": options.get("height"), "fit": bool(options.get("fit", False))}
    wrong = probe.wrong(**base)
    off0 = probe.off(**base)
    if not wrong and off0 <= LAB_LIMIT:
        return dict(options), Redrawing(off_before=off0, off_after=off0)
    first_peaks = probe.peaks(**base)
    zone = float(base["height"]) if base["height"] is not None else first_peaks[2]
    seen = {tuple(sorted(base.items()))}
    right: list[tuple[float, int, dict[str, Any]]] = [] if wrong else [(off0, 0, {})]

    def done(change: dict[str, Any], off: float) -> tuple[dict[str, Any], Redrawing]:
        return ({**options, **change},
                Redrawing(dict(change), wrong, (), len(seen) - 1, {k: base[k] for k in change}, off0, off, searched))

    # the whole menu over the taller s only where the first drawing is wrong: a right one redrawn
    # for its errors alone stays about its size (a press's H1 50 mm grew its diagrams into the room
    # of its velocity plans)
    cands = (list(candidates(L, H1, H2, wrong, poles, longest, fixed, base["height"], tallest))
             + list(taller(base["height"], H1, H2, fixed if wrong and menu else frozenset({"H1", "H2"}), poles)))
    searched = frozenset(key for change in cands for key in change)
    passed: list[tuple[int, dict[str, Any], float]] = []      # right, or not judged: worse than a right one
    for order, change in enumerate(cands, 1):
        trial = {**base, **change}
        key = tuple(sorted(trial.items()))
        if key in seen:
            continue
        seen.add(key)
        off = probe.off(**trial)
        if off > LAB_LIMIT and right and off >= min(r[0] for r in right):
            passed.append((order, change, off))
            continue                  # no better than one already right: not judged further (below if none fits)
        if not readable(probe.peaks(**trial), first_peaks, zone, precision):
            passed.append((order, change, off))
            continue                  # flat: judged below only where no readable drawing is right
        if probe.wrong(**trial, all_of=False):
            continue
        change = {k: v for k, v in change.items() if trial[k] != base[k]}
        if off <= LAB_LIMIT:
            if fits is None or fits({**options, **change}, bool(wrong)):
                return done(change, off)
            continue
        right.append((off, order, change))
    for off, _, change in sorted(right, key=lambda r: r[:2]):
        if not change or (not wrong and off > WORTHWHILE * off0):
            break
        if fits is None or fits({**options, **change}, bool(wrong)):
            return done(change, off)
    if wrong:    # a low s under a tall allowance: the series' next finer μs, before a flat drawing
        found = fitted(probe, base, first_peaks, zone, precision, fits, options, fixed, poles, seen)
        if found is not None:
            return done(*found)
    if wrong:    # every readable right one too large for the room: those passed over (or flat), judged
        for order, change, off in sorted(passed, key=lambda r: (r[2], r[0])):   # now (a generated six-bar's
            trial = {**base, **change}                                        # a stayed "wrong" though
            if probe.wrong(**trial, all_of=False):                            # H1 30 / H2 15 draws it right)
                continue
            change = {k: v for k, v in change.items() if trial[k] != base[k]}
            right.append((off, order, change))
            if fits is None or fits({**options, **change}, True):
                return done(change, off)
    if wrong and fits is not None:
        found = lower(probe, base, right, fits, options)
        if found is not None:
            seen.add(tuple(sorted({**base, **found[0]}.items())))
            return done(*found)
    if not wrong:    # a right first drawing far off: those passed over as no better than a right one too large
        for order, change, off in sorted(passed, key=lambda r: (r[2], r[0])):   # for the room (stop 51: the
            if off > WORTHWHILE * off0:                                       # adaptive mode at H1 20, H2 20
                break                                                         # mm fits, 27 % for 57 %)
            trial = {**base, **change}
            if not readable(probe.peaks(**trial), first_peaks, zone, precision) or probe.wrong(**trial, all_of=False):
                continue
            change = {k: v for k, v in change.items() if trial[k] != base[k]}
            if fits is None or fits({**options, **change}, False):
                return done(change, off)
        return dict(options), Redrawing({}, (), (), len(seen) - 1, {}, off0, off0, searched)
    return dict(options), Redrawing({}, wrong, wrong, len(seen) - 1, {}, off0, off0, searched)
