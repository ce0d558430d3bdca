"""Over a full turn (seed 003, figs. 4–5): the balancing moment against the crank angle and the
hodographs of the reactions in the revolute pairs — as matplotlib charts (PNG and SVG, byte-stable)
and as construction records for the force sheet."""
from __future__ import annotations

import io
import math
from collections.abc import Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path

import numpy as np

from graphplan.util.markup import plain
from graphplan.util.words import force_symbol, num, unit, word
from graphplan.drawing.labels import NUMBERS_APART, place_beside, place_labels
from graphplan.graphic.record import LabelRequest, Primitive, Record
from graphplan.drawing.diagrams import AXIS_W   # a diagram's axes: solid, between thin and thick (GOST 2.303)
from graphplan.graphic.forceplans import standard_scale
from graphplan.graphic.scales import GOST_BETWEEN, SERIES, at_least, at_most, series_value
from graphplan.exact.kinetostatics import Kinetostatics, full_turn
from graphplan.util.files import write_atomic
from graphplan.exact.positions import Study
from graphplan.model.mechanism import FRAME

SAMPLES = 360


@dataclass
class Turn:
    """The force analysis over one turn from position 0: ``turn_deg`` = crank turn since position 0."""
    ks: Kinetostatics
    turn_deg: np.ndarray
    count: int                      # the scene's number of positions (marked on the charts)
    memo: dict = field(default_factory=dict, repr=False, compare=False)   # drawings of this turn (hodograph_record)

    @property
    def revolute(self) -> list[str]:
        """Keys of the reactions in revolute pairs, in the order the groups found them."""
        return [k for g in self.ks.groups for k in g.reactions if self.ks.reactions[k].kind == "R"]

    def position_index(self) -> list[tuple[int, int]]:
        """(sample index, position number) of the scene's positions on the sample grid."""
        n = len(self.turn_deg)
        step = n // self.count if n % self.count == 0 else None
        if step is None:
            return []
        return [(k * step, k) for k in range(self.count)]


def turn(st: Study, samples: int = SAMPLES) -> Turn:
    """Kinetostatics at ``samples`` crank angles from position 0 (every 1° by default)."""
    ks = full_turn(st, samples)
    return Turn(ks, np.arange(samples) * 360.0 / samples, st.mech.task.count)


def _stroke_starts(t: Turn) -> list[int]:
    """The samples k where a stroke starts (working[k] ≠ working[k − 1], over the closed turn)."""
    work = np.asarray(t.ks.working)
    return np.flatnonzero(work != np.roll(work, 1)).tolist()


def _load_changes(t: Turn) -> dict[int, list]:
    """The samples k where an external load changes at once between k − 1 and k (over the closed
    turn), each with those loads: switched on or off (acting on one side, nil on the other — a
    working-stroke force at the stroke's change) or reversed (acting on both sides, its direction
    turned by more than a right angle in one step that is no step of a load varying smoothly
    through nought — an "oppose" moment on a rocker at its extremes, where ω changes sign: the
    pump six-bar's M5 = 25 N·m). Found once per turn."""
    def make() -> dict[int, list]:
        n = len(t.ks.working)
        out: dict[int, list] = {}
        for ld in (x for x in t.ks.loads if x.kind == "external"):
            force = np.broadcast_to(np.asarray(ld.force, dtype=complex), (n,))
            couple = np.broadcast_to(np.asarray(ld.couple, dtype=float), (n,))
            size = np.abs(force) + np.abs(couple)
            on = size > 0.0
            before_f, before_c = np.roll(force, 1), np.roll(couple, 1)
            step = np.abs(force - before_f) + np.abs(couple - before_c)
            typical = float(np.median(step))
            turned = (force * np.conj(before_f)).real + couple * before_c < 0.0
            reversed_ = on & np.roll(on, 1) & turned & (step > 3.0 * typical + 1e-9 * (1.0 + float(np.max(size))))
            for k in np.flatnonzero((on != np.roll(on, 1)) | reversed_).tolist():
                out.setdefault(k, []).append(ld)
        return dict(sorted(out.items()))
    if "load changes" not in t.memo:
        t.memo["load changes"] = make()
    return t.memo["load changes"]


def _cuts(t: Turn) -> list[int]:
    """The samples k where the reactions may jump: an external load switched on or off, or
    reversed, between k − 1 and k (``_load_changes``)."""
    return list(_load_changes(t))


JUMP_RATIO = 3.0     # a step this many times its neighbours' (and the turn's typical one) is a jump


def _jump_samples(t: Turn, f: np.ndarray) -> list[int]:
    """The load changes' samples k (``_load_changes``) where the reaction ``f`` itself jumps: its
    step f[k] − f[k − 1] more than ``JUMP_RATIO`` times the larger of its two neighbouring steps
    and of the turn's median step. A reaction the changed load does not reach (the rocker six-bar's
    R24, R45, R05 — group II(4-5) is solved before the slider's group carries P_B) steps there as
    anywhere else: no jump to draw or to caption (stop 47: "dashed — the jump due to P_B" under
    hodographs with no jump, their ordinary 0.9 mm step drawn dashed)."""
    n = len(f)
    if n < 3:
        return []
    step = np.abs(f - np.roll(f, 1))
    typical = float(np.median(step))
    floor = 1e-9 * (1.0 + float(np.max(np.abs(f))))
    return [k for k in _load_changes(t)
            if step[k] > JUMP_RATIO * max(typical, float(step[(k - 1) % n]), float(step[(k + 1) % n])) + floor]


def _pieces(t: Turn, values: np.ndarray, cuts: list[int] | None = None) -> list[tuple[np.ndarray, np.ndarray]]:
    """Split a closed curve where an external load switches on or off or reverses (the reactions
    jump; ``_cuts``), or at ``cuts``: (indices, values) pieces, closed over the turn."""
    n = len(t.ks.working)
    cuts = _cuts(t) if cuts is None else cuts
    if not cuts:
        idx = np.r_[np.arange(n), 0]
        return [(idx, values[idx])]
    out = []
    for a, b in zip(cuts, cuts[1:] + [cuts[0] + n]):
        idx = np.arange(a, b) % n
        out.append((idx, values[idx]))
    return out


# -- matplotlib ------------------------------------------------------------------------------

def _figure_bytes(fig, fmt: str) -> bytes:
    import matplotlib
    matplotlib.rcParams["svg.hashsalt"] = "graphplan"
    buf = io.BytesIO()
    meta = {"Date": None} if fmt == "svg" else {"Software": None}
    fig.savefig(buf, format=fmt, metadata=meta, dpi=150, bbox_inches="tight")
    return buf.getvalue()


def moment_figure(t: Turn, title: str = "", lang: str = "uk"):
    """M_b(φ): closed form (line) and power balance (dots), the working stroke shaded."""
    import matplotlib
    matplotlib.use("Agg")
    from matplotlib.figure import Figure
    fig = Figure(figsize=(7.0, 3.6))
    ax = fig.add_subplot()
    ks = t.ks
    x = t.turn_deg
    ax.plot(np.r_[x, 360.0], np.r_[ks.balancing, ks.balancing[0]], color="black", lw=1.2,
            label=word("closed form", lang))
    every = max(1, len(x) // 36)
    ax.plot(x[::every], ks.power()[::every], "o", ms=3, mfc="none", color="black",
            label=word("by power", lang))
    work = ks.working
    for idx, _ in _pieces(t, work.astype(float), _stroke_starts(t)):
        if work[idx[0]]:
            ax.axvspan(x[idx[0]], x[idx[0]] + len(idx) * (x[1] - x[0]), color="0.9", lw=0)
    ax.axhline(0.0, color="0.5", lw=0.6)
    for k, pos in t.position_index():
        ax.axvline(x[k], color="0.85", lw=0.5)
    ax.set_xlim(0, 360)
    ax.set_xticks(np.arange(0, 361, 30))
    ax.set_xlabel(word("chart turn", lang))
    ax.set_ylabel(f"{word('balancing moment', lang)} {plain(word('M_b', lang))}, {unit('N·m', lang)}")
    ax.set_title(title or word("balancing moment crank", lang))
    ax.legend(loc="best", fontsize=8)
    return fig


def hodograph_figure(t: Turn, title: str = "", lang: str = "uk"):
    """The hodographs of the revolute-pair reactions: the tip of R over the turn, positions marked."""
    import matplotlib
    matplotlib.use("Agg")
    from matplotlib.figure import Figure
    keys = t.revolute
    cols = min(3, len(keys)) or 1
    rows = math.ceil(len(keys) / cols) or 1
    fig = Figure(figsize=(3.4 * cols, 3.4 * rows))
    for n, key in enumerate(keys):
        ax = fig.add_subplot(rows, cols, n + 1)
        f = t.ks.reactions[key].force
        for idx, z in _pieces(t, f, _jump_samples(t, f)):
            ax.plot(z.real, z.imag, color="black", lw=1.0)
        for k, pos in t.position_index():
            ax.plot(f[k].real, f[k].imag, "o", ms=2.5, color="black")
            ax.annotate(str(pos), (f[k].real, f[k].imag), fontsize=7, xytext=(3, 3),
                        textcoords="offset points")
        ax.plot([0], [0], "+", color="black", ms=8)
        ax.axhline(0, color="0.8", lw=0.5)
        ax.axvline(0, color="0.8", lw=0.5)
        ax.set_aspect("equal", adjustable="datalim")
        ax.set_title(f"{key} ({word('pair', lang)} {t.ks.reactions[key].point})", fontsize=9)
        ax.set_xlabel(f"R_x, {unit('N', lang)}", fontsize=8)
        ax.set_ylabel(f"R_y, {unit('N', lang)}", fontsize=8)
        ax.tick_params(labelsize=7)
    fig.suptitle(title or word("hodographs", lang), fontsize=10)
    fig.tight_layout()
    return fig


def write_charts(t: Turn, folder: str | Path, title: str = "", lang: str = "uk") -> list[Path]:
    """balancing_moment.{png,svg} and hodographs.{png,svg} in ``folder``."""
    folder = Path(folder)
    written = []
    for stem, fig in (("balancing_moment", moment_figure(t, title, lang)),
                      ("hodographs", hodograph_figure(t, title, lang))):
        for fmt in ("png", "svg"):
            written.append(write_atomic(folder / f"{stem}.{fmt}", _figure_bytes(fig, fmt)))
    return written


# -- records for the sheet ---------------------------------------------------------------------

def turn_scale(width: float) -> float:
    """μφ (°/mm) of a chart over the turn in ``width`` mm: the finest value of the round series
    (1, 1.5, 2, 2.5, 4, 5, 7.5 × 10ⁿ: graphic.scales' series with GOST 2.302's 1.5, 7.5) whose
    turn 360°/μφ fits the length — the chart's length follows from it (252 mm → 1.5 °/mm, 240 mm;
    115 mm → 4 °/mm, 90 mm). A teacher expects μ from the series: the lab's μφ = 360°/L drew the
    crusher's charts at 3.273 °/mm (110 mm), a scale no ruler reads."""
    need = 360.0 / width
    k0 = math.floor(math.log10(need))
    rounds = sorted(series_value(m, k) for k in (k0, k0 + 1) for m in SERIES + GOST_BETWEEN)
    return next(m for m in rounds if m >= need * (1 - 1e-12))


TICK_MM = 8.0         # an ordinate axis's round values at least this far apart


def axis_step(mu: float, gap_mm: float = TICK_MM) -> float:
    """The ordinate's value step: the smallest 1, 2 or 5 × 10ⁿ drawn ≥ ``gap_mm`` apart at μ."""
    lo = gap_mm * mu
    e = math.floor(math.log10(lo))
    return min(series_value(m, k) for k in (e, e + 1) for m in (1.0, 2.0, 5.0)
               if series_value(m, k) >= lo * (1 - 1e-12))


def _over_turn(t: Turn, values: np.ndarray, title: str, axis: str, per_mm: str, mm_unit: str,
               width: float, height: float, lang: str) -> tuple[Record, float]:
    """A quantity over the turn as the course draws it: abscissa = crank turn from position 0 at
    a round μφ (``turn_scale``: the turn 360°/μφ within ``width``), ordinate at the standard scale μ
    that fits ``height``; each position's ordinate drawn, as the points are plotted from the table;
    the ordinate's values at a round step (``axis_step``) from below the lowest to past the peak,
    the axis drawn through them. Returns the record and μ."""
    rec = Record(title)
    step = title
    lo, hi = min(0.0, float(np.min(values))), max(0.0, float(np.max(values)))
    mu = standard_scale((hi - lo) / height) if hi > lo else 1.0
    mu_phi = turn_scale(width)
    width = 360.0 / mu_phi
    rec.scales["mu_phi"] = mu_phi
    tick = axis_step(mu)
    v_lo = math.floor(lo / tick + 1e-9) * tick if lo < 0 else 0.0     # the round values bracketing the curve
    v_hi = math.ceil(hi / tick - 1e-9) * tick if hi > 0 else 0.0
    rec.segment((0.0, 0.0), (width + 5.0, 0.0), role="construction", width=AXIS_W, layer="diagrams", step=step)
    rec.vector((0.0, min(lo / mu, v_lo / mu) - 3.0), (0.0, max(hi / mu, v_hi / mu) + 8.0), role="construction",
               layer="diagrams", step=step)
    pts = [(float(x / mu_phi), float(v / mu)) for x, v in zip(np.r_[t.turn_deg, 360.0], np.r_[values, values[0]])]
    rec.add("polyline", pts, role="curve", layer="diagrams", step=step)
    numbers = []
    for k, pos in t.position_index():
        x = float(t.turn_deg[k] / mu_phi)
        rec.segment((x, -1.5), (x, 1.5), role="construction", layer="diagrams", step=step)
        y = float(values[k] / mu)
        if abs(y) > 1.5:      # the position's ordinate, as the points are plotted from the table
            rec.segment((x, 0.0), (x, y), role="grid", layer="diagrams", step=step)
        # the position's thin line across the chart's field, as the s, v, a diagrams draw theirs
        for a, b in ((lo / mu, min(0.0, y)), (max(0.0, y), hi / mu)):
            if b - a > 1.0:
                rec.segment((x, a), (x, b), role="grid", layer="diagrams", step=f"positions of {step}")
        numbers.append(LabelRequest(complex(x, 0.0), str(pos), -1 + -2j if y > 0 else -1 + 2j, 2.5, step=step))
    if numbers:
        # the turn closes at position 0 again, numbered as the lab numbers the divisions, 0 … 12
        y = float(values[0] / mu)
        rec.segment((width, -1.5), (width, 1.5), role="construction", layer="diagrams", step=step)
        if abs(y) > 1.5:
            rec.segment((width, 0.0), (width, y), role="grid", layer="diagrams", step=step)
        for a, b in ((lo / mu, min(0.0, y)), (max(0.0, y), hi / mu)):
            if b - a > 1.0:
                rec.segment((width, a), (width, b), role="grid", layer="diagrams", step=f"positions of {step}")
        numbers.append(LabelRequest(complex(width, 0.0), str(t.count), -1 + -2j if y > 0 else -1 + 2j, 2.5,
                                    step=step))
    rec.label((width + 6.0, -1.0), "φ", size=3.5, step=step)
    rec.label((2.0, max(hi / mu, v_hi / mu) + 5.0), axis, size=3.5, step=step)
    for i in range(round(v_lo / tick), round(v_hi / tick) + 1):
        v = i * tick
        y = v / mu
        rec.segment((-1.5, y), (0.0, y), role="construction", layer="diagrams", step=step)
        rec.label((-2.5, y - 1.2), num(round(v, 9), lang).replace("-", "−"), size=2.5, anchor="end", step=step)
    place_labels(rec, numbers)                  # each number beside its line, clear of the curve
    rec.label((0.0, rec.bounds()[1] - 6.0), f"{per_mm} = {num(mu, lang)} {mm_unit}, "
              f"μ_φ = {num(mu_phi, lang)} {unit('deg/mm', lang)}", size=2.5, step=step)
    return rec, mu


def moment_record(t: Turn, width: float = 180.0, height: float = 70.0, lang: str = "uk") -> Record:
    """M_b(φ) as a drawing: abscissa = crank turn from position 0, ordinate at μM (N·m per mm)."""
    rec, mu = _over_turn(t, t.ks.balancing, "balancing moment M_b(φ)", f"{word('M_b', lang)}, {unit('N·m', lang)}",
                         "μ_M", unit('N·m/mm', lang), width, height, lang)
    rec.scales["mu_M"] = mu
    return rec


def slider_reactions(t: Turn) -> list[str]:
    """The sliding pairs with the frame (the ram on its guide): their reaction keeps its line, so it
    is drawn as a chart over the turn (seed 003, fig. 5a), not as a hodograph."""
    return [k for k, r in t.ks.reactions.items() if r.kind == "P" and r.frm == "0"]


def normal_component(t: Turn, key: str) -> np.ndarray:
    """A sliding pair's reaction as a signed number: its component on the guide's normal n (the
    guide turned by +90°: up for a horizontal guide), R·n."""
    r = t.ks.reactions[key]
    n = np.asarray(r.guide) * 1j
    return np.real(r.force * np.conj(n)) / np.abs(n)


def reaction_record(t: Turn, key: str, width: float = 180.0, height: float = 60.0, lang: str = "uk") -> Record:
    """Seed 003's fig. 5a: the frame's reaction on the slider over the turn (N, on the guide's normal)."""
    rec, mu = _over_turn(t, normal_component(t, key), f"reaction {key}",
                         f"{force_symbol(key, lang)}, {unit('N', lang)}", "μ_R", unit('N/mm', lang),
                         width, height, lang)
    rec.scales["mu_R"] = mu
    return rec


CLUSTER_MM = 1.5   # points nearer than this (their dots 1 mm across all but touch) a number on a leader
                   # no longer tells apart: a hodograph draws them again in a detail at a larger scale
RULER_MM = 0.5     # consecutive positions this close on the drawing are one point to the ruler: one
                   # number "3–4" for them, and a note says they coincide


def _clusters(points: list[tuple[int, complex]], near: float = RULER_MM) -> list[tuple[int, int, complex]]:
    """Consecutive positions drawn within ``near`` of the run's last point (and twice it of its
    first), as (first, last, the run's middle point): one number "3–4" for points the ruler's
    0.5 mm cannot tell apart, not two numbers on one spot."""
    runs: list[list[tuple[int, complex]]] = []
    for pos, w in points:
        if (runs and pos == runs[-1][-1][0] + 1 and abs(w - runs[-1][-1][1]) <= near
                and abs(w - runs[-1][0][1]) <= 2 * near):
            runs[-1].append((pos, w))
        else:
            runs.append([(pos, w)])
    return [(r[0][0], r[-1][0], r[len(r) // 2][1]) for r in runs]


def crowded(points: list[tuple[int, complex]], near: float = CLUSTER_MM) -> list[int]:
    """The positions whose point has another position's point within ``near`` mm."""
    return [p for p, w in points if any(q != p and abs(w - v) < near for q, v in points)]


HODOGRAPH_MM = 60.0    # a hodograph's larger extent (its curve with the origin) at size factor 1: with its
                       # axes 70 mm, what a teacher reads on A1


def hodograph_scale(span: float, size: float) -> float:
    """μR (N/mm) that draws a hodograph's larger extent ``span`` (N) at most ``size`` mm: the
    smallest value of the standard series 1, 2, 2.5, 4, 5 × 10^k (LAYOUT.md: every μF of the force
    sheet; the force plans' too) that does — 270 and 260 N/mm on the press's sheet were no scale a
    draftsman sets (now 400 and 400; the curve at least half the size), review 59 #2's 7.5 N/mm none
    of the series."""
    return at_least(span / size)


FLAT_GROWTH = 2.0      # a flat hodograph's larger extent grows up to this much over a round one's


def hodograph_growth(t: Turn, key: str) -> float:
    """How much larger than a round one a hodograph's larger extent may be drawn: 1/√(its aspect),
    at most ``FLAT_GROWTH`` — a flat one (the press's R12, 8000 N down, 300 N across: 60 × 15 mm,
    its idle-stroke points 2 mm from the origin) over the area of a round one."""
    f = t.ks.reactions[key].force
    w = max(0.0, float(np.max(f.real))) - min(0.0, float(np.min(f.real)))
    h = max(0.0, float(np.max(f.imag))) - min(0.0, float(np.min(f.imag)))
    if max(w, h) <= 0:
        return 1.0
    return min(FLAT_GROWTH, 1.0 / math.sqrt(max(min(w, h) / max(w, h), FLAT_GROWTH ** -2)))


DETAIL_MM = 45.0       # a hodograph's detail (its crowded points at a larger scale): its larger extent at
                       # size factor 1
DETAIL_GAIN = 2.0      # … drawn only where it is at least this much larger than the hodograph
DETAIL_NAME = "I"      # GOST 2.305's extension element: the spot ringed and named, drawn beside at its scale


POLE_SHARE = 0.25      # a detail takes in the pole where it lies within this share of the points' spread
DETAIL_APART = 3.0     # mm: the nearest two points a detail tells apart drawn at least this far apart


def _series_below(x: float) -> float:
    """The largest value of the series (``hodograph_scale``'s) not above ``x``."""
    return at_most(x)


@dataclass
class Detail:
    """The window (in N: x0, y0, x1, y1) of a hodograph's crowded points and its μR (N/mm)."""
    box: tuple[float, float, float, float]
    mu: float


def hodograph_detail(points: list[tuple[int, complex]], mu_r: float, size: float = DETAIL_MM) -> Detail | None:
    """Where a hodograph's points (N) crowd — each within the lettering's ``CLUSTER_MM`` of
    another at μR — the window round them (with the pole where it lies within ``POLE_SHARE`` of their
    spread) and the series μR that draws it ``size`` mm across (``hodograph_scale``), or coarser
    where that still draws its nearest two points ``DETAIL_APART`` apart; None where none crowd or
    the detail would not be ``DETAIL_GAIN`` times larger. The press4's R34: 0–3, 9–11 within
    1.5 mm of each other at 150 N/mm → 4 N/mm."""
    near = crowded([(p, w / mu_r) for p, w in points])
    if not near:
        return None
    ws = [w for p, w in points if p in near]
    x0, x1 = min(w.real for w in ws), max(w.real for w in ws)
    y0, y1 = min(w.imag for w in ws), max(w.imag for w in ws)
    spread = max(x1 - x0, y1 - y0, CLUSTER_MM * mu_r)
    if max(x0, -x1, y0, -y1, 0.0) <= POLE_SHARE * spread:      # the pole close by: drawn in it too
        x0, x1, y0, y1 = min(x0, 0.0), max(x1, 0.0), min(y0, 0.0), max(y1, 0.0)
    mu = hodograph_scale(max(x1 - x0, y1 - y0) or mu_r, size)
    # no larger than its points need: the nearest two it tells apart DETAIL_APART mm apart
    ws = [w for _, w in points if x0 <= w.real <= x1 and y0 <= w.imag <= y1]
    gaps = [abs(a - b) for i, a in enumerate(ws) for b in ws[i + 1:] if abs(a - b) > RULER_MM * mu]
    if gaps:
        mu = max(mu, _series_below(min(gaps) / DETAIL_APART))
    if mu * DETAIL_GAIN > mu_r * (1 + 1e-9):
        return None
    return Detail((x0, y0, x1, y1), mu)


def _clipped(z: np.ndarray, box: tuple[float, float, float, float]) -> list[list[tuple[float, float]]]:
    """The parts of the polyline ``z`` inside ``box`` (shapely's intersection)."""
    from shapely.geometry import LineString, box as shapely_box
    if len(z) < 2:
        return []
    cut = LineString(np.column_stack([z.real, z.imag]).astype(float)).intersection(shapely_box(*box))
    parts = getattr(cut, "geoms", [cut])
    return [list(g.coords) for g in parts if g.geom_type == "LineString" and len(g.coords) >= 2]


def _hodograph_lines(rec: Record, t: Turn, f: np.ndarray, mu: float, step: str,
                     box: tuple[float, float, float, float] | None = None) -> int:
    """The hodograph's curve at μ (within ``box``, mm, where given) and the dashed jumps where the
    resistance switches on or off; returns the count of jumps drawn."""
    cuts = _jump_samples(t, f)
    pieces = _pieces(t, f, cuts)
    for _, z in pieces:
        for part in ([list(zip((z.real / mu).tolist(), (z.imag / mu).tolist()))] if box is None
                     else _clipped(z / mu, box)):
            rec.add("polyline", part, role="curve", layer="diagrams", step=step)
    jumps = 0
    if cuts:                # one jump leaves one piece, open between its ends (a press's P_E ramping up, cut off)
        # where the resistance switches on or off the reaction jumps: the two ends joined by a thin
        # dashed line, so that the gap reads as the jump (the caption says so), not as a curve left open
        for (_, z), (_, z_next) in zip(pieces, pieces[1:] + pieces[:1]):
            a, b = z[-1] / mu, z_next[0] / mu
            if abs(b - a) > 0.5:
                jumps += 1
                for part in ([[(float(a.real), float(a.imag)), (float(b.real), float(b.imag))]] if box is None
                             else [q for q in _clipped(np.array([a, b]), box)
                                   if math.dist(q[0], q[-1]) >= 3.0]):     # no stray dash at a detail's edge
                    rec.segment(part[0], part[-1], role="projection", layer="diagrams",
                                step=f"{step}: the jump" if box is None else f"{step}: the jump's part")
    return jumps


def _switching(t: Turn, f: np.ndarray, lang: str) -> list[str]:
    """The external loads a reaction's jump is due to: those switched on or off, or reversed, where
    the reaction itself jumps (``_load_changes``) — not a load constant over the turn, nor one on a
    piston the reaction does not carry (review 13: a V-twin's constant P_B named under R45's jump
    from P_C); the pump six-bar's R12 jumps from P_B at the strokes' changes and from M5 at the
    rocker's extremes (review 45 #3). Where no load changes there, every external one is named."""
    changes = _load_changes(t)
    named = [ld for k in _jump_samples(t, f) for ld in changes[k]]
    ext = [ld for ld in t.ks.loads if ld.kind == "external"]
    order = {id(ld): i for i, ld in enumerate(ext)}          # in the scene's order
    named = sorted({id(ld): ld for ld in named}.values(), key=lambda ld: order[id(ld)])
    return list(dict.fromkeys(force_symbol(ld.name, lang) for ld in (named or ext)))


def _numbered(rec: Record, points: list[tuple[int, complex]], step: str, centre: complex = 0j) -> list[str]:
    """Each position's point and its number beside it, on the side away from ``centre`` (the pole;
    a detail's middle), on a leader where crowded; points the ruler's 0.5 mm cannot tell apart
    share one number "3–4". Returns those shared numbers."""
    numbers, shared = [], []
    for first, last, w in _clusters(points):
        text = str(first) if first == last else f"{first}–{last}"
        if first != last:
            shared.append(text)
        numbers.append(LabelRequest(w, text, w - centre if abs(w - centre) > 1e-9 else 1j, 2.5, step=step,
                                    sight=True))
    for _, w in points:
        rec.point((float(w.real), float(w.imag)), layer="diagrams", step=step)
    n = len(rec.items)
    place_labels(rec, numbers)      # each position's number by its point, clear of the curve and the
                                    # other numbers (on a leader where its point is crowded)
    _lead_far(rec, n, numbers, step)
    # … and one still past LEAD_FROM_MM of its point with no leader (``_lead_far``'s would pass by
    # another number or cross a line) set again as a diagram's number (labels.place_beside: beside
    # its own point within LEAD_FROM_MM and nearer it than any other point, else on a leader that
    # says whose it is) — review55 #14: the beam pump's R34 "4" 6 mm from its point, its leader
    # passing by "3"
    stray = [req for req in numbers if _stray(rec.items[n:], req)]
    if stray:
        spots = [w for _, _, w in _clusters(points)]
        rec.items[n:] = [q for q in rec.items[n:] if not (q.kind == "text" and any(q.text == r.text for r in stray))]
        for req in stray:
            place_beside(rec, [replace(req, rivals=tuple(z for z in spots if abs(z - req.at) > 1e-9))],
                         beside=LEAD_FROM_MM)
    return shared


def _stray(added: list, req: LabelRequest) -> bool:
    """Whether a position's number (``req``) the placer set among ``added`` stands past
    ``LEAD_FROM_MM`` of its point with no leader from it."""
    from graphplan.drawing.labels import _box_gap
    q = next((q for q in added if q.kind == "text" and q.text == req.text), None)
    if q is None:
        return False
    box = q.ink()
    if _box_gap(box, req.at) <= LEAD_FROM_MM + 1e-9:
        return False
    return not any(q2.kind == "segment" and q2.role == "label"
                   and min(abs(complex(*e) - req.at) for e in q2.points) < 1.3
                   and min(_box_gap(box, complex(*e)) for e in q2.points) < 1.5 for q2 in added)


LEAD_FROM_MM = 2.5   # a number standing farther than this from its point gets a leader to it


def _lead_far(rec: Record, since: int, asked: list[LabelRequest], step: str) -> None:
    """A number the placer set a few mm off its point without a leader (the press4's "11" 5 mm from
    its dot in R34's detail, read as no point's) joined to its point by a thin leader, where the
    leader crosses no line of the curve."""
    from graphplan.drawing.labels import CLEAR, _box_gap, box_to_segment
    added = rec.items[since:]
    led = [q for q in added if q.kind == "segment" and q.role == "label"]
    lines = [q for q in rec.items[:since] if q.kind in ("segment", "polyline", "vector") and q.role != "label"]
    for q in [q for q in added if q.kind == "text"]:
        req = next((r for r in asked if r.text == q.text), None)
        if req is None:
            continue
        box = q.ink()
        gap = _box_gap(box, req.at)
        if gap <= LEAD_FROM_MM or any(min(_box_gap(box, complex(*e)) for e in ld.points) < 1.0 for ld in led):
            continue
        near = complex(min(max(req.at.real, box[0]), box[2]), min(max(req.at.imag, box[1]), box[3]))
        u = (near - req.at) / abs(near - req.at)
        a, b = req.at + 0.9 * u, near - (CLEAR + 0.3) * u      # as labels._leader ends short of its box
        if abs(b - a) < 0.6:
            continue
        if any(_crosses_line(a, b, ln) for ln in lines):
            continue
        if any(_crosses_line(a, b, ld) for ld in led):       # nor another number's leader (an X)
            continue
        if any(box_to_segment(o.ink(), a, b) < CLEAR + 0.3 for o in rec.items            # nor by another
               if o.kind == "text" and o is not q):                                       # number (9 by 10–11's)
            continue
        led.append(rec.segment((a.real, a.imag), (b.real, b.imag), role="label", layer="labels", step=step))


def _crosses_line(a: complex, b: complex, q: Primitive) -> bool:
    """Whether the segment a–b crosses the primitive's polyline."""
    from shapely.geometry import LineString
    return len(q.points) >= 2 and LineString([(a.real, a.imag), (b.real, b.imag)]).crosses(LineString(q.points))


FAN_GAPS = (3.0, 5.0, 7.0, 9.5, 12.0)    # mm past the detail's outermost point a fanned number stands
FAN_TURNS = (0.0, 12.0, -12.0, 24.0, -24.0, 36.0, -36.0)    # degrees off its point's own direction


def _fanned(rec: Record, points: list[tuple[int, complex]], step: str) -> list[str]:
    """A detail's points numbered as a draftsman calls out a crowded spot: each number out past
    the points in its own point's direction from their middle, on a thin leader to it — in turn
    round the middle, clear of the lines, the points, the other numbers (3 mm, labels.NUMBERS_APART)
    and their leaders; a number that finds no such spot is placed as any other (``place_labels``).
    Points the ruler's 0.5 mm cannot tell apart share a number. Returns those shared numbers."""
    from shapely.geometry import LineString, Point, box
    from shapely.ops import unary_union
    from graphplan.drawing.labels import _SKETCH
    all_runs = _clusters(points)
    for _, w in points:
        rec.point((float(w.real), float(w.imag)), layer="diagrams", step=step)
    if _SKETCH[-1]:                 # a sketch (drawing.labels.sketched): the numbers asked for, not placed
        return [f"{a}–{b}" for a, b, _ in all_runs if a != b]
    # only the crowded points fanned, about their own middle; the others numbered beside their points
    tight = set(crowded([(a, w) for a, _, w in all_runs], CLUSTER_MM + 1.0))
    runs = [r for r in all_runs if r[0] in tight]
    alone = [r for r in all_runs if r[0] not in tight]
    shared = [f"{a}–{b}" for a, b, _ in alone if a != b]
    if not runs:
        rest = [LabelRequest(w, str(a) if a == b else f"{a}–{b}", 1j, 2.5, step=step, sight=True)
                for a, b, w in alone]
        n = len(rec.items)
        place_labels(rec, rest)
        _lead_far(rec, n, rest, step)
        return shared
    mid = sum(w for _, _, w in runs) / len(runs)
    reach = max(abs(w - mid) for _, _, w in runs)
    lines = unary_union([g for g in (_shape(q) for q in rec.items) if g is not None])
    ink = lines.buffer(0.5)
    dots = [Point(w.real, w.imag).buffer(0.9) for _, w in points]
    boxes, leaders, left = [], [], []
    for first, last, w in sorted(runs, key=lambda r: math.atan2((r[2] - mid).imag, (r[2] - mid).real)):
        text = str(first) if first == last else f"{first}–{last}"
        if first != last:
            shared.append(text)
        u = (w - mid) / abs(w - mid) if abs(w - mid) > 1e-9 else 1j
        spot = None
        for gap in FAN_GAPS:
            for turn in FAN_TURNS:
                at = mid + (reach + gap) * u * complex(math.cos(math.radians(turn)), math.sin(math.radians(turn)))
                prim = Primitive("text", ((at.real, at.imag - 1.25),), text=text, size=2.5, anchor="middle")
                bx = box(*prim.ink())
                if (bx.buffer(0.5).intersects(ink) or any(bx.buffer(3.0).intersects(b) for b in boxes)
                        or any(bx.buffer(0.6).intersects(q) for q in leaders)):
                    continue
                end = bx.exterior.interpolate(bx.exterior.project(Point(w.real, w.imag)))
                lead = LineString([(w.real, w.imag), (end.x, end.y)])
                if lead.length < 1.5:
                    continue
                a = lead.interpolate(0.9)
                b = lead.interpolate(max(0.9, lead.length - 0.4))
                lead = LineString([(a.x, a.y), (b.x, b.y)])
                if (any(lead.crosses(q) or lead.intersects(q) for q in leaders)
                        or any(lead.intersects(d) for k, d in enumerate(dots) if abs(points[k][1] - w) > 1e-9)
                        or any(lead.intersects(b_) for b_ in boxes) or lead.crosses(lines)):
                    continue
                spot = (prim, bx, lead)
                break
            if spot:
                break
        if spot is None:
            left.append(LabelRequest(w, text, u, 2.5, step=step, sight=True))
            continue
        prim, bx, lead = spot
        (x0, y0), (x1, y1) = lead.coords
        rec.segment((x0, y0), (x1, y1), role="label", layer="labels", step=step)
        rec.label(prim.points[0], text, size=2.5, anchor="middle", step=step, layer="labels")
        boxes.append(bx)
        leaders.append(lead)
    rest = left + [LabelRequest(w, str(a) if a == b else f"{a}–{b}", w - mid, 2.5, step=step, sight=True)
                   for a, b, w in alone]
    n = len(rec.items)
    place_labels(rec, rest)
    _lead_far(rec, n, rest, step)
    return shared


def hodograph_record(t: Turn, key: str, size: float = HODOGRAPH_MM, lang: str = "uk", say_jump: bool = True,
                     beside: bool = False) -> Record:
    """One reaction's hodograph (``_hodograph_record``), remembered per turn: the force sheet draws
    each at the size it measures its cells at, then again on the sheet (a copy is returned: its
    primitives are immutable, its list and scales the caller's)."""
    from graphplan.drawing.labels import _SKETCH
    memo_key = ("hodograph", key, size, lang, say_jump, beside, _SKETCH[-1])
    rec = t.memo.get(memo_key)
    if rec is None:
        rec = t.memo[memo_key] = _hodograph_record(t, key, size, lang, say_jump, beside)
    return Record(rec.title, list(rec.items), dict(rec.scales))


def _hodograph_record(t: Turn, key: str, size: float, lang: str, say_jump: bool, beside: bool) -> Record:
    """One reaction's hodograph: the tip of R over the turn at μR (N/mm), positions numbered. The
    axes through the origin reach just past the curve: μR draws the curve and the origin together
    ``size`` mm across (``hodograph_scale``; a reaction that keeps its direction draws its loop
    large in one quadrant instead of small in the middle of a bare cross). Every position's number
    stands beside its point. Where points crowd closer than the lettering (a press's idle stroke:
    eleven reactions of 100–700 N by the pole of an 8000 N curve) the spot is ringed and named "I"
    and drawn again beside at a larger series μR (``hodograph_detail``, GOST 2.305's extension
    element), each of its points numbered there; only points the ruler's 0.5 mm cannot tell apart
    share a number ("3–4"), and a note says so."""
    f = t.ks.reactions[key].force
    rec = Record(f"hodograph {key}")
    step = f"hodograph {key}"
    xlo, xhi = min(0.0, float(np.min(f.real))), max(0.0, float(np.max(f.real)))
    ylo, yhi = min(0.0, float(np.min(f.imag))), max(0.0, float(np.max(f.imag)))
    span = max(xhi - xlo, yhi - ylo) or 1.0
    mu_r = hodograph_scale(span, size)
    rec.scales["mu_R"] = mu_r
    pad = 5.0
    x0, x1, y0, y1 = xlo / mu_r - pad, xhi / mu_r + pad, ylo / mu_r - pad, yhi / mu_r + pad
    rec.segment((x0, 0.0), (x1, 0.0), role="construction", width=AXIS_W, layer="diagrams", step=step)
    rec.segment((0.0, y0), (0.0, y1), role="construction", width=AXIS_W, layer="diagrams", step=step)
    jumps = _hodograph_lines(rec, t, f, mu_r, step)
    points = [(pos, complex(f[k])) for k, pos in t.position_index()]
    inside: list[tuple[int, complex]] = []
    shared: list[str] = []
    # the field the hodograph already takes: its axes' extent, as wide as the lettering under it
    under = [f"{force_symbol(key, lang)}: μ_R = {num(mu_r, lang)} {unit('N/mm', lang)}"]
    if say_jump and _jump_samples(t, f):
        under.append(word("fs jump", lang, what=", ".join(_switching(t, f, lang))))
    wide = max(Primitive("text", ((0.0, 0.0),), text=plain(u), size=2.5).ink()[2] for u in under)
    field = (x0, y0, max(x1, x0 + wide), y1)
    # a flat hodograph (a sliver of a cell) may take its detail beside it (``beside``) — only where it would
    # otherwise number two positions as one ("0–2"): its cell grows for that alone
    flat = (beside and hodograph_growth(t, key) > 1.0 + 1e-9
            and any(a != b for a, b, _ in _clusters([(p, w / mu_r) for p, w in points])))
    ink = None
    for share in DETAIL_SHARES + ((None,) if flat else ()):   # the largest detail with room in the field
        detail = hodograph_detail(points, mu_r, DETAIL_MM * (share or 1.0) * size / HODOGRAPH_MM)
        if detail is None:
            break
        bx0, by0, bx1, by1 = detail.box
        near = [(p, w) for p, w in points if bx0 - 1e-9 <= w.real <= bx1 + 1e-9 and by0 - 1e-9 <= w.imag <= by1 + 1e-9]
        if len(near) < DETAIL_POINTS:       # two points are numbered on leaders, not drawn again
            break
        c = complex(bx0 + bx1, by0 + by1) / 2 / mu_r          # the spot ringed on the hodograph and named
        r = abs(complex(bx1 - bx0, by1 - by0)) / 2 / mu_r + 1.5
        if ink is None:
            ink = _InkOf(rec.items)       # grown only where a corner asks (most details do not fit the field)
        if share is not None:           # the sketch first: where it finds no room, neither does the lettered one
            from graphplan.drawing.labels import sketched
            with sketched():
                rough, _ = _detail(t, f, detail, near, lang, f"{step}: detail")
            if _corner(ink, rough, (c, r), field) is None:
                continue
        det, det_shared = _detail(t, f, detail, near, lang, f"{step}: detail")
        if share is None:                                     # beside the field, tops level
            d0, _, _, d3 = det.bounds()
            moved = det.moved(field[2] + DETAIL_GAP - d0, field[3] - d3)
        else:
            moved = _corner(ink, det, (c, r), field)
        if moved is None:
            continue
        n0 = len(rec.items)
        rec.circle((c.real, c.imag), r, role="construction", layer="diagrams", step=f"{step}: detail")
        rec.extend(moved)
        from graphplan.drawing.labels import collisions
        if not _detail_mark(rec, c, r, f"{step}: detail mark") or collisions(rec):
            del rec.items[n0:]          # its mark or its numbers would touch a line: the next size, or none
            continue                    # (a generated four-bar's "I" stood on the jump's dashed line)
        inside, shared = near, det_shared
        rec.scales["mu_R detail"] = detail.mu
        break
    shared = _numbered(rec, [(p, w / mu_r) for p, w in points if (p, w) not in inside], step) + shared
    y = rec.bounds()[1] - 6.0
    rec.label((x0, y), f"{force_symbol(key, lang)}: μ_R = {num(mu_r, lang)} {unit('N/mm', lang)}",
              size=2.5, step=step)
    notes = []
    if jumps and say_jump:      # said under every hodograph that draws a jump
        notes.append(word("fs jump", lang, what=", ".join(_switching(t, f, lang))))
    rec.scales["shared numbers"] = float(len(shared))    # said once in the sheet's notes ("fs coincide")
    for k, text in enumerate(notes, 1):
        rec.label((x0, y - 5.0 * k), text, size=2.5, step=step)
    return rec


DETAIL_SHARES = (1.0, 0.8, 0.6, 0.45, 0.35)   # the detail's sizes tried, in DETAIL_MM
DETAIL_POINTS = 3      # a detail is drawn only for at least this many points (two are hardly worth it)
SHELF_LEAD = 4.0       # mm: the mark's leader from the ring to its shelf (GOST 2.305, 2.316)
SHELF_MM = 4.5         # mm: the shelf the mark's letter stands on


def _detail_mark(rec: Record, c: complex, r: float, step: str, within: bool = True,
                 leads: tuple[float, ...] = (SHELF_LEAD,), name: str = DETAIL_NAME) -> bool:
    """The ringed spot's mark as GOST 2.305 draws an extension element: a thin leader from the
    ring out to a shelf, the letter "I" standing on the shelf — not a bare stroke by the ring (the
    sieve's "I" read as a dash of the jump line). The first of the four diagonals (up-left first)
    whose leader, shelf and letter keep clear of the hodograph's lines, points and lettering; False
    (nothing drawn) where none does; ``within``: only within the record's extent (a hodograph's room);
    ``leads``: the leader's lengths past the ring tried, the shortest first (a force plan's spot where
    its closing lines meet needs a longer one)."""
    from shapely.geometry import LineString, box
    prim = Primitive("text", ((0.0, 0.0),), text=name, size=3.5)
    i0, j0, i1, j1 = prim.ink()
    w = max(SHELF_MM, i1 - i0 + 1.5)
    ink = _ink_of(rec).buffer(-DETAIL_CLEAR + 0.6)
    texts = [box(*q.ink()).buffer(0.8) for q in rec.items if q.kind == "text"]
    best = None
    tried = []
    rx0, ry0, rx1, ry1 = rec.bounds()
    field = box(rx0, ry0, rx1, ry1)
    for lead, d in ((lead, d) for lead in leads for d in (-1 + 1j, 1 + 1j, -1 - 1j, 1 - 1j)):
        u = d / abs(d)
        a, b = c + r * u, c + (r + lead) * u
        e = b + (w if d.real > 0 else -w)
        x = min(b.real, e.real) + w / 2 - (i0 + i1) / 2       # the letter in the shelf's middle
        tb = box(x + i0, b.imag + 0.8 + j0, x + i1, b.imag + 0.8 + j1)
        lines = LineString([(a.real, a.imag), (b.real, b.imag), (e.real, e.imag)])
        hit = (lines.intersects(ink) or tb.intersects(ink) or any(tb.intersects(t) or lines.intersects(t) for t in texts)
               or (within and not field.contains(tb.union(lines))))   # within the hodograph's room, not past it
        if not hit:
            best = (a, b, e, x)
            break
        tried.append((a, b, e, x))
    from graphplan.drawing.labels import collisions
    for a, b, e, x in ([best] if best is not None else tried):   # else the first whose letter touches nothing
        n0 = len(rec.items)
        rec.add("polyline", [(a.real, a.imag), (b.real, b.imag), (e.real, e.imag)], role="label", layer="labels",
                step=step)
        rec.label((x, b.imag + 0.8), name, size=3.5, step=step)
        if best is not None or not collisions(rec):
            return True
        del rec.items[n0:]
    return False
DETAIL_GAP = 6.0       # mm between a flat hodograph's field and the detail drawn beside it
DETAIL_CLEAR = 2.0     # mm between a detail and the hodograph's lines, points and ring


def _shape(q: Primitive):
    """A primitive's lines as a shapely geometry (None for lettering)."""
    from shapely.geometry import LineString, Point
    if q.kind in ("segment", "vector", "polyline") and len(q.points) >= 2:
        return LineString(q.points)
    if q.kind == "point":
        return Point(q.points[0]).buffer(0.6)
    if q.kind == "circle":
        return Point(q.points[0]).buffer(q.radius).exterior
    return None


def _ink_of(rec: Record):
    """The record's lines and points grown by ``DETAIL_CLEAR`` (shapely), remembered by their
    geometry (the buffer is most of a hodograph's cost; its two languages and the sheet's trial
    sizes ask for the same ink)."""
    key = tuple((q.kind, q.points, q.radius) for q in rec.items if q.kind != "text")
    ink = _INKS.get(key)
    if ink is None:
        from shapely.ops import unary_union
        ink = unary_union([g for g in (_shape(q) for q in rec.items) if g is not None]
                          ).simplify(0.1).buffer(DETAIL_CLEAR, quad_segs=4)
        if len(_INKS) >= 128:
            _INKS.pop(next(iter(_INKS)))
        _INKS[key] = ink
    return ink


_INKS: dict[tuple, object] = {}     # geometry → its grown ink (shapely geometries are immutable)


class _InkOf:
    """``_ink_of`` of the primitives as they are now, grown when first asked (``_corner``)."""

    def __init__(self, items: list[Primitive]) -> None:
        self.items, self.ink = list(items), None

    def geometry(self):
        if self.ink is None:
            self.ink = _ink_of(Record("", self.items))
        return self.ink


def _corner(ink, det: Record, ring: tuple[complex, float],
            field: tuple[float, float, float, float], grow: float = 0.0) -> Record | None:
    """``det`` moved into a corner of the hodograph's ``field`` (its axes' extent, mm) where it
    keeps ``DETAIL_CLEAR`` off every line, point and the ``ring`` — the room a hodograph that keeps
    to one quadrant or a diagonal leaves — or None: the sheet's composition is not disturbed."""
    from shapely.geometry import Point, box
    ringed = Point(ring[0].real, ring[0].imag).buffer(ring[1] + DETAIL_CLEAR)
    x0, y0, x1, y1 = field
    d0, e0, d1, e1 = det.bounds()
    w, h = d1 - d0 + 2 * grow, e1 - e0 + 2 * grow       # ``grow``: room kept round a sketch for its numbers
    d0, e0 = d0 - grow, e0 - grow
    if w > x1 - x0 or h > y1 - y0:
        return None
    for cx, cy in ((x1 - w, y1 - h), (x0, y1 - h), (x1 - w, y0), (x0, y0)):
        spot = box(cx, cy, cx + w, cy + h)
        if not spot.intersects(ringed) and not spot.intersects(ink.geometry() if isinstance(ink, _InkOf) else ink):
            return det.moved(cx - d0, cy - e0)
    return None


def _detail(t: Turn, f: np.ndarray, d: Detail, inside: list[tuple[int, complex]], lang: str,
            step: str) -> tuple[Record, list[str]]:
    """The detail "I" at its μR: the window's curve, the axes where the pole is in it, every point
    numbered, the name and scale under it. Returns it and its shared numbers."""
    det = Record(step)
    pad = 3.0
    bx0, by0, bx1, by1 = (v / d.mu for v in d.box)
    box = (bx0 - pad, by0 - pad, bx1 + pad, by1 + pad)
    if box[0] <= 0.0 <= box[2]:
        det.segment((0.0, box[1]), (0.0, box[3]), role="construction", width=AXIS_W, layer="diagrams", step=step)
    if box[1] <= 0.0 <= box[3]:
        det.segment((box[0], 0.0), (box[2], 0.0), role="construction", width=AXIS_W, layer="diagrams", step=step)
    _hodograph_lines(det, t, f, d.mu, step, box)
    shared = _fanned(det, [(p, w / d.mu) for p, w in inside], step)
    b = det.bounds()
    # over the detail, as GOST 2.305 names an extension element: "I (μ_R = 4 N/mm)"
    # its box (μ's and the brackets' descent included) 1.5 mm over the detail's numbers: set at
    # the baseline 1.5 mm over them, the press's "3" under "(μ" stood 0.74 mm off
    caption = f"{DETAIL_NAME} (μ_R = {num(d.mu, lang)} {unit('N/mm', lang)})"
    det.label((b[0], b[3] + 1.5), caption, size=2.5, step=step)
    descent = b[3] + 1.5 - det.items[-1].bounds()[1]
    if descent > 1e-9:
        del det.items[-1]
        det.label((b[0], b[3] + 1.5 + descent), caption, size=2.5, step=step)
    return det, shared


def path_travelled(t: Turn, point: str | None = None) -> np.ndarray:
    """The output's path from position 0 over the cycle at the turn's samples and back at position 0
    (n + 1 values): the stroke out, then the stroke back — each position once, in the order the
    crank passes it (m for a slide, degrees for a link); ``point``: another slide's (a second piston)."""
    from graphplan.exact.positions import Output
    st = t.ks.st
    out = st.output if point is None else Output("slide", point)
    vals = np.asarray(out.value(t.ks.kin), dtype=float)
    if out.kind != "slide":
        vals = np.degrees(vals)
    last = vals[0] - vals[-1]
    if out.kind != "slide":
        last = (last + 180.0) % 360.0 - 180.0
    steps = np.abs(np.r_[np.diff(vals), last])
    return np.r_[0.0, np.cumsum(steps)]


HATCH_PITCH_MM = 2.5    # the resistance diagram's hatching: one line every this many mm of its path axis


def hatch_lines(curve: list[tuple[float, float]], pitch: float) -> list[tuple[float, float]]:
    """Hatch lines (x, height) under a curve drawn as a polyline whose x never decreases (a jump is a
    vertical step): one every ``pitch`` mm from x = pitch/2, each as high as the curve there (linear
    between its vertices), only where that height is above the axis."""
    out: list[tuple[float, float]] = []
    if not curve:
        return out
    x_end = max(x for x, _ in curve)
    x = 0.5 * pitch + min(x for x, _ in curve)
    pieces = [(a, b) for a, b in zip(curve, curve[1:]) if b[0] - a[0] > 1e-9]
    i = 0
    while x < x_end and pieces:
        while i < len(pieces) - 1 and x > pieces[i][1][0]:
            i += 1
        (x0, y0), (x1, y1) = pieces[i]
        y = y0 + (y1 - y0) * (x - x0) / (x1 - x0)
        if y > 1e-6:
            out.append((x, y))
        x += pitch
    return out


def resistance_loads(t: Turn, point: str | None = None) -> tuple[list, bool]:
    """The loads the resistance diagram draws, and whether they are moments: the output's own —
    the forces at its point (forces on two pistons are not summed, review 13: a V-twin's chart drew
    |P_C + P_B|, P_B constant on the other piston), else the moments on an output link that turns
    (stop 57: the kneading machine's rocker carries its 70 N·m working moment, the slider it is
    driven through 300 N on both strokes — the chart drew that constant 300 N over the rocker's
    angle ψ₅, a hatched rectangle with no stroke in it, and left out the rocker's own resistance) —
    else every external force, else every external moment. ([], False) without an external load.
    ``point``: the forces at that slide (``other_pistons``)."""
    ext = [ld for ld in t.ks.loads if ld.kind == "external"]
    out = t.ks.st.output
    forces = [ld for ld in ext if ld.point is not None]
    if point is not None:
        return [ld for ld in forces if ld.point == point], False
    own = [ld for ld in forces if ld.point == out.name]
    moments = [ld for ld in ext if ld.point is None and out.kind != "slide" and ld.link == out.name]
    if own:
        return own, False
    if moments:
        return moments, True
    return (forces, False) if forces else (ext, bool(ext))


def other_pistons(t: Turn) -> list[str]:
    """The slides besides the output whose stroke-bound forces get a resistance diagram of their own
    (stop 58: a V-twin compressor's 900 N on piston C went undrawn beside P_B's diagram — the lab
    draws one per piston, each over its own path and strokes): the points of the scene's
    ``[[force]]``s bound to a stroke that slide on a frame guide, when the diagram draws the output's
    own force. (A constant load on both strokes, review 13's P_B on the other piston, is no resistance
    over a stroke.)"""
    from graphplan.exact.positions import point_slider
    st = t.ks.st
    mech = st.mech
    own = [ld for ld in t.ks.loads if ld.kind == "external" and ld.point is not None]
    if st.output.kind != "slide" or not any(ld.point == st.output.name for ld in own):
        return []
    out: list[str] = []
    for f in mech.forces:
        slider = point_slider(mech, f.point)
        if (f.stroke != "both" and f.point != st.output.name and f.point not in out and slider is not None
                and mech.guides[mech.links[slider].slides_on].body == FRAME):
            out.append(f.point)
    return out


def resistance_record(t: Turn, width: float = 180.0, height: float = 60.0, lang: str = "uk",
                      point: str | None = None) -> Record | None:
    """Seed 000's diagram of the resistance force: |P| of the output's external force (else of the
    external forces) along the output's path
    over the cycle from position 0 (the stroke out, then back), so the working stroke carries the
    force and the idle stroke lies on the axis (unless a load acts on it too), the loaded spans hatched — each position numbered once, under its own stroke
    (the scene's ``positions.working_stroke``); None when the scene has no external force."""
    ext, couple = resistance_loads(t, point)
    if not ext:
        return None
    st = t.ks.st
    path = path_travelled(t, point)
    dist_unit = unit("m", lang) if st.output.kind == "slide" or point is not None else "°"
    # a slide's path s with μ_s; a rocking output's angle ψ_5 from position 0 (the kinematics sheet's
    # letter for a rocker's angle, graphic.diagrams.angle_symbol) with μ_ψ
    if point is not None:
        sym, what, mu_sym = "s", f"s_{{{point}}}", "μ_s"
    elif st.output.kind == "slide":
        sym, what, mu_sym = "s", f"s_{{{st.output.name}}}", "μ_s"
    else:
        from graphplan.graphic.diagrams import angle_symbol
        letter = angle_symbol(st, st.output.name)
        sym = what = f"{letter}_{{{st.mech.links[st.output.name].number}}}"
        mu_sym = f"μ_{letter}"
    force = np.abs(sum(ld.couple for ld in ext)) if couple else np.abs(sum(ld.force for ld in ext))
    f_unit, f_mu = (unit("N·m", lang), "μ_M") if couple else (unit("N", lang), "μ_P")
    work = np.asarray(t.ks.working, dtype=bool)
    if point is not None:                  # the piston's own strokes (kinetostatics.own_stroke)
        from graphplan.exact.kinetostatics import force_working
        work = np.asarray(force_working(st, point, t.ks.kin.phi_deg, work), dtype=bool)
    n = len(force)
    reach = float(path[-1]) or 1.0
    mu_s = standard_scale(reach / width)
    top = float(np.max(force)) or 1.0
    mu_p = standard_scale(top / height)
    # each symbol once: two [[moment]]s on one lever (one per stroke) are one M_3 (review 53 #4: "M₃, M₃")
    name = ", ".join(dict.fromkeys(ld.name for ld in ext))
    rec = Record(f"resistance {name}")
    rec.scales.update({"mu_s": mu_s, "mu_P": mu_p})
    step = f"{name}(s)"
    x_end, y_end = reach / mu_s, top / mu_p
    X = lambda k: float(path[k] / mu_s)  # noqa: E731
    rec.segment((0.0, 0.0), (x_end + 8.0, 0.0), role="construction", width=AXIS_W, layer="diagrams", step=step)
    rec.vector((0.0, -2.0), (0.0, y_end + 8.0), role="construction", layer="diagrams", step=step)
    pts = [(X(0), float(force[0] / mu_p))]
    for k in range(1, n + 1):
        y = float(force[min(k, n - 1)] / mu_p) if k < n else float(force[n - 1] / mu_p)
        if k < n and work[k] != work[k - 1]:          # the force switches on or off at the extreme
            pts.append((X(k), float(force[k - 1] / mu_p)))
        pts.append((X(k), y))
    rec.add("polyline", pts, role="curve", layer="diagrams", step=step)
    # the resistance hatched down to the axis where it acts, on either stroke (review 53 #4: a lever's
    # 260 N·m on the idle stroke was left blank beside the working stroke's hatched 40 N·m) — at an
    # even pitch along the path, as a draftsman hatches an area (stop 54: hatched at every 48th of the
    # turn, the jaw crusher's lines crowded into a black bar by the extreme, where the path hardly grows)
    for x, y in hatch_lines(pts, HATCH_PITCH_MM):
        rec.segment((x, 0.0), (x, y), role="hatch", layer="diagrams", step=step)
    # each stroke named under the axis, across its span
    cuts = [0] + [k for k in range(1, n) if work[k] != work[k - 1]] + [n]
    marks = t.position_index()
    if marks:        # the cycle closes at position 0 again: the lab numbers its end 12
        marks = marks + [(n, t.count)]
    # the positions' numbers in one row under their ticks: where two stand closer than their ink
    # (0 and 1, 6 and 7, 11 and 12 by a rocker's extremes, where the path hardly grows) each is set
    # aside just enough, on a short leader from its tick (review 12 #18: three rows under the axis)
    xs = [X(k) for k, _ in marks]
    inks = [Primitive("text", ((0.0, 0.0),), text=str(pos), size=2.5, anchor="middle").ink() for _, pos in marks]
    mids = [0.5 * (i[0] + i[2]) for i in inks]            # a number's ink is not centred on its x ("1")
    # … "0" not pushed left past the force axis (the rocker six-bar's "0" stood 4 mm left of it, by
    # the axis's own 0, its 1, 2, 3 fanned on leaders): a run at the start set apart rightwards
    halves = [0.5 * (i[2] - i[0]) for i in inks]
    centres = [x + m for x, m in zip(xs, mids)]
    lo = centres[0] - halves[0] if xs else -math.inf
    at = [c - m for c, m in zip(spread_apart(centres, halves, NUMBER_GAP_MM, lo), mids)]
    moved = any(abs(a - x) > 1e-6 for a, x in zip(at, xs))
    low = -7.0 if moved else -5.0          # room for the leaders: 2 mm from the tick, 1 mm off the ink
    for (k, pos), x, a, ink, m in zip(marks, xs, at, inks, mids):
        rec.segment((x, -1.5), (x, 1.5), role="construction", layer="diagrams", step=step)
        if abs(a - x) > 1e-6:
            rec.segment((x, -1.5), (a + m, low + ink[3] + 1.0), role="label", layer="labels", step=step)
        rec.label((a, low), str(pos), size=2.5, anchor="middle", step=step)
    low = _path_values(rec, reach, mu_s, low, lang, step)
    for a, b in zip(cuts, cuts[1:]):
        xa, xb = X(a), X(b)
        rec.segment((xa, low - 4.0), (xb, low - 4.0), role="construction", layer="diagrams", step=step)
    # the strokes' bar ticked at its ends and where one stroke gives way to the other, so each
    # name reads under its own span (stop 54: «робочий хід | холостий хід» under one unbroken line)
    for k in cuts:
        rec.segment((X(k), low - 5.5), (X(k), low - 2.5), role="construction", layer="diagrams", step=step)
    for a, b in zip(cuts, cuts[1:]):
        xa, xb = X(a), X(b)
        rec.label((0.5 * (xa + xb), low - 8.5), word("fs working" if work[a] else "fs idle", lang), size=2.5,
                  anchor="middle", step=step)
    rec.label((x_end + 9.0, -1.0), f"{sym}, {dist_unit}", size=3.5, step=step)
    rec.label((2.0, y_end + 5.0), f"{force_symbol(name, lang)}, {f_unit}", size=3.5, step=step)
    tick = axis_step(mu_p)        # the force axis graduated at a round step, as the other charts
    for i in range(0, math.floor(top / tick + 1e-9) + 1):
        y = i * tick / mu_p
        rec.segment((-1.5, y), (0.0, y), role="construction", layer="diagrams", step=step)
        rec.label((-2.5, y - 1.2), num(round(i * tick, 9), lang), size=2.5, anchor="end", step=step)
    rec.label((0.0, low - 15.0), word("fs path", lang, s=what, u=dist_unit) + f"; {mu_sym} = {num(mu_s, lang)} "
              f"{dist_unit}/{unit('mm', lang)}, {f_mu} = {num(mu_p, lang)} {f_unit}/{unit('mm', lang)}", size=2.5,
              step=step)
    return rec


VALUE_GAP_MM = 20.0    # the path axis's values at least this far apart
NUMBER_GAP_MM = NUMBERS_APART    # paper between two positions' numbers in their row ("11 12", not "1112")


def spread_apart(xs: Sequence[float], halves: Sequence[float], gap: float,
                 lo: float = -math.inf, hi: float = math.inf) -> list[float]:
    """Centres for labels of half widths ``halves`` wanted at ``xs`` in one row: each as near its
    own as may be, neighbours ``gap`` apart at least — runs that would meet set side by side about
    their wanted centres' mean (a 1-D cluster placement), each run's ink kept within ``lo`` … ``hi``
    where the row is wide enough (a diagram's numbers not pushed out past its axes)."""
    order = sorted(range(len(xs)), key=lambda i: xs[i])
    runs: list[tuple[list[int], float]] = []        # (members in order, the run's left edge)

    def width(members: list[int]) -> float:
        return sum(2.0 * halves[i] for i in members) + gap * (len(members) - 1)

    def left_of(members: list[int]) -> float:
        off, wanted = 0.0, []
        for i in members:
            wanted.append(xs[i] - (off + halves[i]))
            off += 2.0 * halves[i] + gap
        return max(lo, min(sum(wanted) / len(wanted), hi - width(members)))

    for i in order:
        runs.append(([i], left_of([i])))
        while len(runs) > 1 and runs[-2][1] + width(runs[-2][0]) + gap > runs[-1][1] + 1e-9:
            members = runs[-2][0] + runs[-1][0]
            runs[-2:] = [(members, left_of(members))]
    out = [0.0] * len(xs)
    for members, left in runs:
        for i in members:
            out[i] = left + halves[i]
            left += 2.0 * halves[i] + gap
    return out


def _path_values(rec: Record, reach: float, mu_s: float, low: float, lang: str, step: str) -> float:
    """The path axis's values (0, 0.1, 0.2 … m, or degrees) in a row under the positions' numbers,
    each at a tick above the axis, at a round step (1, 2 or 5 × 10ⁿ) no closer than
    ``VALUE_GAP_MM``: the axis "s, m" reads in metres, not only in position numbers. Returns the
    lowest row's y."""
    if reach <= 0:
        return low
    lo = VALUE_GAP_MM * mu_s
    step_v = min(m * 10.0 ** e for e in range(math.floor(math.log10(lo)) - 1, math.floor(math.log10(lo)) + 2)
                 for m in (1.0, 2.0, 5.0) if m * 10.0 ** e >= lo * (1 - 1e-9))
    y = low - 4.5
    k = 0
    # (the tolerance relative to the step: an absolute 1e-9 m against a step of 1e-15 m — an output
    # that hardly moves, a toggle's ram assembled on its fixed pivot — set a million ticks)
    while k * step_v <= reach + 1e-9 * step_v:
        x = k * step_v / mu_s
        rec.segment((x, 0.0), (x, 2.5), role="construction", layer="diagrams", step=step)
        rec.label((x, y), num(round(k * step_v, 9), lang), size=2.5, anchor="middle", step=step)
        k += 1
    return y


def records(t: Turn, k: float = 1.0, lang: str = "uk", k_hodographs: float | None = None) -> dict[str, Record]:
    """"moment", "resistance" (when the scene has an external force), "reaction <key>" for every
    sliding pair with the frame and "hodograph <key>" for every revolute pair, in ``lang``: the charts
    k times their length at their one height (a taller chart is mostly bare paper above its curve),
    the hodographs ``k_hodographs`` (k when not given) times their size."""
    kh = k if k_hodographs is None else k_hodographs
    out = {"moment": moment_record(t, 180.0 * k, 70.0, lang=lang)}
    res = resistance_record(t, 160.0 * k, 60.0, lang=lang)
    if res is not None:
        out["resistance"] = res
        for p in other_pistons(t):          # one diagram per loaded piston (stop 58's V-twin)
            more = resistance_record(t, 160.0 * k, 60.0, lang=lang, point=p)
            if more is not None:
                out[f"resistance {p}"] = more
    for key in slider_reactions(t):
        out[f"reaction {key}"] = reaction_record(t, key, 180.0 * k, 60.0, lang=lang)
    for key in t.revolute:      # each hodograph that draws a jump says what the dashes are
        out[f"hodograph {key}"] = hodograph_record(t, key, HODOGRAPH_MM * kh, lang=lang)
    return out
