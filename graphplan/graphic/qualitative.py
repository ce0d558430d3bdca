"""Qualitative checks of a derived diagram: does it have the extrema and zero crossings of the exact
curve, no more and no fewer? (Seed 002's rules: where the differentiated curve has an extremum the
derivative crosses zero; a wrong diagram shows bumps the motion does not have.)

Both curves are compared as drawn, in the diagram's millimetres over one period: the French curve
through the method's ordinates, and the exact curve on the same scale. A feature counts only if the
eye can see it on the drawing: extrema whose swing to a neighbouring extremum is below ``visible``
mm are merged away in pairs (the smallest swing first: the persistence of a peak), and a zero
crossing counts only when the curve goes from beyond +visible to beyond −visible (or back). A
diagram's feature matches an exact one of the same kind within ``window`` degrees of crank turn
(one division interval); what is left over is spurious (the diagram's) or missed (the exact curve's).

A shoulder is wrong too: a pair of inflections where the slope flattens and steepens again (or the
other way) while the curve goes on one way — no extremum, but a bend the motion does not have (an A3
a-diagram's slopes per division 3.7 : 2.0 : 5.3 mm where the exact ones steepen 4.8 : 5.2 : 9.2).
``inflections`` finds the drawing's extrema of the slope and keeps a pair only where it bends the
curve visibly: the slope's swing between the two times their distance over 4 (the curve's departure
from the chord across the shoulder) at least ``BEND`` times ``visible`` mm; where the drawing has
more of them than the exact curve even at a quarter of that, those it lacks are spurious.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from graphplan.util.words import uk_count


VISIBLE_MM = 0.5      # the least swing or excursion a feature needs to be seen (the ruler's division)
SHOWN = 6             # features named in a message (the JSON lists all)


@dataclass(frozen=True)
class Feature:
    """An extremum ("max"/"min") or a zero crossing ("up"/"down") at a crank turn from position 0."""
    kind: str
    turn: float


def extrema(turn: np.ndarray, y: np.ndarray, visible: float) -> list[Feature]:
    """Visible extrema of a periodic curve sampled at ``turn`` (deg, one period, no closing sample)."""
    dy = np.diff(np.append(y, y[0]))
    sign = np.sign(dy)
    nz = np.flatnonzero(sign)
    if nz.size == 0:
        return []
    # a change of the slope's sign between consecutive non-flat steps: an extremum at the sample after
    nxt = np.roll(nz, -1)
    turning = nz[sign[nz] != sign[nxt]]
    cand = sorted((("max" if sign[j] > 0 else "min"), int((j + 1) % len(y))) for j in turning)
    cand.sort(key=lambda c: c[1])
    while len(cand) > 2:
        swings = [abs(y[cand[i][1]] - y[cand[(i + 1) % len(cand)][1]]) for i in range(len(cand))]
        i = int(np.argmin(swings))
        if swings[i] >= visible:
            break
        j = (i + 1) % len(cand)
        cand = [c for m, c in enumerate(cand) if m not in (i, j)]
    if len(cand) == 2 and abs(y[cand[0][1]] - y[cand[1][1]]) < visible:
        cand = []
    return [Feature(kind, float(turn[at])) for kind, at in cand]


def inflections(turn: np.ndarray, y: np.ndarray, L: float, visible: float) -> list[Feature]:
    """Visible inflections of a periodic curve drawn over ``L`` mm (``turn``: deg, one period, no
    closing sample): the extrema of its slope dy/dx ("bend+" a maximum of the slope, "bend-" a
    minimum), merged away in pairs, the least first, while a pair bends the curve by less than
    ``visible`` mm — |Δ(dy/dx)|·Δx/4, the departure from the chord across the bend."""
    y = np.asarray(y, dtype=float)
    n = len(y)
    if n < 4 or L <= 0:
        return []
    dx = L / n
    slope = (np.roll(y, -1) - np.roll(y, 1)) / (2.0 * dx)
    ds = np.diff(np.append(slope, slope[0]))
    sign = np.sign(ds)
    nz = np.flatnonzero(sign)
    if nz.size == 0:
        return []
    nxt = np.roll(nz, -1)
    cand = sorted((int((j + 1) % n), "bend+" if sign[j] > 0 else "bend-") for j in nz[sign[nz] != sign[nxt]])

    def bend(i: int, j: int) -> float:
        a, b = cand[i][0], cand[j][0]
        return abs(slope[a] - slope[b]) * (((b - a) % n) * dx) / 4.0
    while len(cand) > 2:
        bends = [bend(i, (i + 1) % len(cand)) for i in range(len(cand))]
        i = int(np.argmin(bends))
        if bends[i] >= visible:
            break
        j = (i + 1) % len(cand)
        cand = [c for m, c in enumerate(cand) if m not in (i, j)]
    return [Feature(kind, float(turn[at])) for at, kind in cand]


def zero_crossings(turn: np.ndarray, y: np.ndarray, visible: float, period: float = 360.0) -> list[Feature]:
    """Visible zero crossings of a periodic curve: the sign flips only past ±``visible``; each is
    placed where the curve last crossed zero on the way (linear interpolation between samples).

    Walking once round from the first sample beyond ±visible: a zero event is a step whose sign
    changes (from a non-zero sample) or that lands on 0; a crossing is a sample beyond ±visible whose
    sign differs from the last such sample's, placed at the last zero event before it."""
    y = np.asarray(y, dtype=float)
    turn = np.asarray(turn, dtype=float)
    n = len(y)
    definite = np.flatnonzero(np.abs(y) >= visible)
    if definite.size == 0:
        return []
    start = int(definite[0])
    k = (start + np.arange(1, n + 1)) % n           # the walk: each step's sample and the one before
    prev = (k - 1) % n
    yk, yp = y[k], y[prev]
    event = ((yp != 0) & (np.sign(yp) != np.sign(yk))) | (yk == 0)
    with np.errstate(all="ignore"):
        frac = np.where(yp != yk, yp / (yp - yk), 0.0)
    at = (turn[prev] + frac * ((turn[k] - turn[prev]) % period)) % period
    steps = np.flatnonzero(np.abs(yk) >= visible)  # the definite samples on the walk, in order
    signs = np.sign(yk[steps])
    before = np.concatenate(([np.sign(y[start])], signs[:-1]))
    flips = steps[signs != before]
    events = np.flatnonzero(event)
    out: list[Feature] = []
    for step in flips:
        last = np.searchsorted(events, step, side="right") - 1
        where = float(at[events[last]]) if last >= 0 else float(turn[k[step]])
        out.append(Feature("up" if yk[step] > 0 else "down", where))
    return sorted(out, key=lambda f: f.turn)


def match(got: list[Feature], want: list[Feature], window: float,
          period: float = 360.0) -> tuple[list[Feature], list[Feature]]:
    """(spurious, missed): the diagram's features with no exact one of the same kind within
    ``window`` degrees, and the exact features the diagram lacks (nearest pairs first)."""
    dist = lambda a, b: abs((a.turn - b.turn + period / 2) % period - period / 2)  # noqa: E731
    pairs = sorted((dist(g, w), i, j) for i, g in enumerate(got) for j, w in enumerate(want)
                   if g.kind == w.kind and dist(g, w) <= window)
    used_g: set[int] = set()
    used_w: set[int] = set()
    for _, i, j in pairs:
        if i not in used_g and j not in used_w:
            used_g.add(i)
            used_w.add(j)
    return ([g for i, g in enumerate(got) if i not in used_g],
            [w for j, w in enumerate(want) if j not in used_w])


@dataclass(frozen=True)
class Verdict:
    """What one derived diagram gets wrong qualitatively (features at crank turns from position 0)."""
    spurious_extrema: list[Feature]
    missed_extrema: list[Feature]
    spurious_zeros: list[Feature]
    missed_zeros: list[Feature]
    spurious_bends: list[Feature] = ()     # inflections (a shoulder) the exact curve lacks

    @property
    def wrong(self) -> bool:
        return bool(self.spurious_extrema or self.missed_extrema or self.spurious_zeros or self.missed_zeros
                    or self.spurious_bends)


BEND = 2.0       # a shoulder is seen where it departs from its chord by this many ``visible`` (two ruler
                 # divisions: the coulisse's A3 a-diagram 1.4 mm; a crank-slider's tangents 0.6 mm, the
                 # coulisse A1's 0.4 mm a teacher passes)
FAINT = 0.25     # the exact curve's inflections are looked for down to this share of that


def compare(turn: np.ndarray, drawn: np.ndarray, exact: np.ndarray, window: float,
            visible: float = VISIBLE_MM, L: float | None = None) -> Verdict:
    """The drawn curve against the exact one, both in mm sampled at the same turns (one period);
    with the abscissa's length ``L`` (mm) also the shoulders (``inflections``): the drawing's
    visible ones the exact curve lacks even faintly."""
    se, me = match(extrema(turn, drawn, visible), extrema(turn, exact, visible), window)
    sz, mz = match(zero_crossings(turn, drawn, visible), zero_crossings(turn, exact, visible), window)
    sb: list[Feature] = []
    if L is not None:
        bend = BEND * visible
        got, want = inflections(turn, drawn, L, bend), inflections(turn, exact, L, FAINT * bend)
        if len(got) > len(want):        # more bends than the motion has (a displaced one is no shoulder)
            sb, _ = match(got, want, window)
    return Verdict(se, me, sz, mz, sb)


def sample_turns(samples: int = 720) -> np.ndarray:
    """The crank turns (deg, one period, no closing sample) both curves are compared at."""
    return np.arange(samples) * 360.0 / samples


def window_of(turns: np.ndarray) -> float:
    """How far (deg) a drawn feature may lie from the exact one: one division interval, the longest."""
    return float(np.max(np.diff(turns)))


def of_ordinates(turn: np.ndarray, x_at: np.ndarray, ordinates: np.ndarray, L: float, truth: np.ndarray,
                 window: float, visible: float) -> Verdict:
    """The verdict on a diagram drawn as the French curve (periodic spline over L mm) through the
    ``ordinates`` at abscissae ``x_at``, against the exact curve ``truth`` (mm) at ``turn``."""
    from graphplan.graphic.chords import periodic_spline
    return compare(turn, periodic_spline(x_at, ordinates, L)(L * turn / 360.0), truth, window, visible, L)


KIND_WORDS = {"en": {"max": "max", "min": "min", "up": "rising", "down": "falling",
                     "bend+": "inflection", "bend-": "inflection"},
              "uk": {"max": "макс.", "min": "мін.", "up": "зростає", "down": "спадає",
                     "bend+": "перегин", "bend-": "перегин"}}


def check(d: Any, samples: int = 720) -> list[dict[str, Any]]:
    """Warnings (kind "qualitative") for the v and a diagrams of ``d`` (graphic.diagrams.Diagrams) whose French curves have
    extrema or zero crossings the exact curves lack, or miss some they have; positions as crank
    angles φ (deg). None when both diagrams are qualitatively right."""
    from graphplan.exact.positions import crank_angle, exact_motion
    turn = sample_turns(samples)
    _, v, a = exact_motion(d.study, d.output, turn)
    window, visible = window_of(d.turn), max(VISIBLE_MM, d.precision)
    out: list[dict[str, Any]] = []
    from graphplan.graphic.diagrams import v_knots
    for sym, key, exact, mu in ((d.symbols[1], "v", v, d.mu_v), (d.symbols[2], "a", a, d.mu_a)):
        truth = d.sign * exact / mu

        def curve(r: Any) -> tuple[np.ndarray, np.ndarray]:
            # the v curve passes through 0 at the extreme positions as drawn (graphic.diagrams.stops)
            zeros = getattr(r, "v_zeros", np.zeros(0)) if key == "v" else np.zeros(0)
            return v_knots(d.x_mid, getattr(r, key), zeros)
        verdict = of_ordinates(turn, *curve(d.drawn), d.L, truth, window, visible)
        if not verdict.wrong:
            continue
        # the cause: the method's own error if the exact drawing is wrong too, else the drafting's
        own = of_ordinates(turn, *curve(d.exact), d.L, truth, window, visible).wrong
        diagram = key
        entry: dict[str, Any] = {"kind": "qualitative", "diagram": sym, "method": d.method,
                                 "cause": "method" if own else "drafting"}
        parts = {"en": [], "uk": []}
        for key, items, en, uk in (
                ("spurious_extrema", verdict.spurious_extrema, "extrema the exact curve lacks",
                 "екстремуми, яких немає в точній кривій"),
                ("missed_extrema", verdict.missed_extrema, "misses the exact curve's extrema",
                 "пропущено екстремуми точної кривої"),
                ("spurious_zeros", verdict.spurious_zeros, "zero crossings the exact curve lacks",
                 "переходи через нуль, яких немає в точній кривій"),
                ("missed_zeros", verdict.missed_zeros, "misses the exact curve's zero crossings",
                 "пропущено переходи точної кривої через нуль"),
                ("spurious_bends", list(verdict.spurious_bends), "a shoulder (inflections) the exact curve lacks",
                 "уступ (точки перегину), якого немає в точній кривій")):
            if not items:
                continue
            phis = crank_angle(d.study, [f.turn for f in items])
            entry[key] = [{"type": f.kind, "phi_deg": round(float(p), 1), "turn_deg": round(f.turn, 1)}
                          for f, p in zip(items, phis)]
            for lang, words in (("en", en), ("uk", uk)):
                where = ", ".join(f"φ = {p:.1f}° ({KIND_WORDS[lang][f.kind]})"
                                  for f, p in list(zip(items, phis))[:SHOWN])
                if len(items) > SHOWN:
                    where += f" … ({len(items)} {'in all' if lang == 'en' else 'усього'})"
                parts[lang].append(f"{words}: {where}")
        how = {"chords": ("by chords", "методом хорд"), "tangents": ("by tangents", "методом дотичних")}[d.method]
        entry["note"], entry["note_uk"] = _short(entry, sym)
        rd = getattr(d, "redrawn", None)
        if rd is not None and diagram in rd.wrong_after:    # graphic.redraw searched: say so, suggest nothing untried
            longer = "L" in rd.searched
            tail_en = (f"; none of the {rd.tried} redrawings tried (the area correction, H1, H2 15–50 mm, "
                       f"{'a longer L, ' if longer else ''}smaller intervals, a taller s diagram) within the sheet's "
                       "room made it right")
            tail_uk = (f"; жодна з {rd.tried} випробуваних побудов (корекція площ, H1, H2 15–50 мм, "
                       f"{'довша L, ' if longer else ''}менші інтервали, вища діаграма s) у межах місця на аркуші не "
                       "зробила її правильною")
        elif own:
            tail_en, tail_uk = "; take more divisions (smaller intervals there)", "; візьміть більше поділок (менші інтервали там)"
        else:
            tail_en = ("; the exact drawing is right: the drafting error does it — take a larger L or H or a finer "
                       "ruler, not more divisions")
            tail_uk = ("; точна побудова правильна: це похибка креслення — візьміть більші L чи H або точнішу "
                       "лінійку, а не більше поділок")
        entry["message"] = (f"the {sym} diagram ({how[0]}, {d.divisions} divisions) is qualitatively wrong — "
                            + "; ".join(parts["en"]) + tail_en)
        entry["message_uk"] = (f"діаграма {sym} ({how[1]}, {d.divisions} {uk_count(d.divisions, 'поділка', 'поділки', 'поділок')}) якісно хибна — "
                               + "; ".join(parts["uk"]) + tail_uk)
        out.append(entry)
    return out


def _short(entry: dict[str, Any], sym: str) -> tuple[str, str]:
    """One short line per diagram for the sheet's notes: where it has features it should not."""
    def where(key: str, comma: bool) -> str:
        items = entry[key]
        text = ", ".join(f"{e['phi_deg']:g}°".replace(".", "," if comma else ".") for e in items[:3])
        return text + (" ..." if len(items) > 3 else "")
    en, uk = [], []
    for key, e_word, u_word in (("spurious_extrema", "spurious extrema", "хибні екстремуми"),
                                ("missed_extrema", "missed extrema", "пропущені екстремуми"),
                                ("spurious_zeros", "spurious zeros", "хибні нулі"),
                                ("missed_zeros", "missed zeros", "пропущені нулі"),
                                ("spurious_bends", "a spurious shoulder", "хибний уступ")):
        if entry.get(key):
            en.append(f"{e_word} φ = {where(key, False)}")
            uk.append(f"{u_word} φ = {where(key, True)}")
    return (f"Diagram {sym} is qualitatively wrong: " + "; ".join(en),
            f"Діаграма {sym} якісно хибна: " + "; ".join(uk))
