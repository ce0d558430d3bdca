"""The cam's construction drawn (records in drawing mm, y up): the three diagrams of the law with
their chords, poles and division numbers; the phase diagram with the lines at the allowed pressure
angle; and the profile by inversion with the base circle, the follower in its start position (its
guide and the offset line), ω's arrow, the follower's turned positions numbered, the phase angles as
arcs, the centre and working profiles. Each record carries its scales; every letter is placed by the
one label placer (drawing.labels), clear of the lines."""
from __future__ import annotations

import cmath
import dataclasses
import math

import numpy as np

from graphplan.drawing.labels import LabelRequest, place_labels
from graphplan.exact.cam import Solution, centre_path, jump_points, motion, profile
from graphplan.graphic.cam import CamConstruction, division_numbers, phase_curve, working_angle
from graphplan.graphic.record import POINT_INK, Record
from graphplan.drawing.diagrams import AXIS_W   # a diagram's axes: solid (GOST 2.303); dash-dot is for centre lines

LAYER = "cam"
TEXT = 3.5
NUMBER = 2.5          # the division numbers
BELOW = 1.0           # a number under its axis: its baseline this many letter heights lower (1.2 mm clear
                      # with the font; a viewer's wider fallback font (DejaVu) reaches 0.27 letter higher)
NUMBER_NEAR = 0.3     # mm: a number's nearest start to its division where NUMBER_OFF leaves no room
NUMBER_GAP = 1.0      # mm: the least room between two division numbers on one axis
UNCLOSED_W = 0.18     # mm: the s diagram's chords before its closing (a dashed first traverse)
NUMBER_OFF = 0.8      # mm a diagram's division number starts right of its division (clear of a bold phase line)
PHASE_NAMES = {"uk": ("φ_п", "φ_вв", "φ_с", "φ_бв"), "en": ("φ_{rise}", "φ_{far}", "φ_{return}", "φ_{near}")}


def symbols(rocking: bool) -> dict[str, str]:
    """The follower's displacement and its analogues in the lab's letters (markup): a translating
    follower's s, ds/dφ, d²s/dφ²; a rocking follower's arm angle ψ, dψ/dφ, d²ψ/dφ² (REFERENCE §11,
    docs/cams.md: the swing ψ_max, ψ_0 — an angle is not s)."""
    q = "ψ" if rocking else "s"
    return {"s": q, "v": f"d{q}/dφ", "a": f"d^{{2}}{q}/dφ^{{2}}",
            "mu_s": f"μ_{q}", "mu_v": f"μ_{{d{q}/dφ}}", "mu_a": f"μ_{{d²{q}/dφ²}}"}


def scale_units(rocking: bool, lang: str) -> dict[str, str]:
    """The unit of each scale (the value per drawn millimetre): s in m, its analogues per radian of
    the cam's turn; a rocking follower's ψ in degrees as the table gives it (° per mm, its analogues
    (°/рад)/мм and (°/рад²)/мм: one unit for each quantity on the drawing, in the notes and the table)."""
    uk = lang == "uk"
    m, rad, mm = ("м", "рад", "мм") if uk else ("m", "rad", "mm")
    per = {"mu_phi": f"{rad}/{mm}", "mu_l": f"{m}/{mm}"}
    if rocking:
        per.update(mu_s=f"°/{mm}", mu_v=f"(°/{rad})/{mm}", mu_a=f"(°/{rad}^{{2}})/{mm}")
    else:
        per.update(mu_s=f"{m}/{mm}", mu_v=f"{m}/({rad}·{mm})", mu_a=f"{m}/({rad}^{{2}}·{mm})")
    return per


def scale_text(key: str, value: float, rocking: bool, lang: str) -> str:
    """“μ_s = 0,0005 м/мм” in the lab's notation (markup). The analogues' scales are named by their
    quantity, μ_{ds/dφ} and μ_{d²s/dφ²} (rocking μ_ψ, μ_{dψ/dφ}, μ_{d²ψ/dφ²}, their values in degrees:
    ``value`` is per radian as construct keeps it): μ_v and μ_a are the kinematic velocity's and
    acceleration's (m/s per mm), which a cam's analogues per radian of its turn are not."""
    from graphplan.util.words import num
    sym = {"mu_phi": "μ_φ", "mu_l": "μ_l", **symbols(rocking)}[key]
    if rocking and key in ("mu_s", "mu_v", "mu_a"):
        value = math.degrees(value)
    text = f"{sym} = {num(value, lang, 4)} {scale_units(rocking, lang)[key]}"
    if key == "mu_phi" and value > 0:       # a standard one in degrees said so (review 8: 0.01745 rad/mm is 1 °/mm)
        deg = math.degrees(value)
        mantissa = deg / 10 ** math.floor(math.log10(deg) + 1e-9)
        if any(abs(mantissa - m) < 1e-6 for m in (1.0, 2.0, 2.5, 4.0, 5.0)):
            text += f" ({num(deg, lang, 4)} °/{'мм' if lang == 'uk' else 'mm'})"
    return text


def _pt(z: complex) -> tuple[float, float]:
    return (float(z.real), float(z.imag))


def numbered(n_points: int, spacing: float, size: float = NUMBER) -> list[int]:
    """The division numbers that are lettered where the divisions lie ``spacing`` mm apart: every
    one, or every second, fifth … so that two numbers' widths fit between neighbours (the first
    and the last always): the widest number's ink and NUMBER_GAP between neighbours, with 0.2 mm for
    the glyphs' uneven side bearings (review 13 #5: at 4.69 mm a division "24" and "25" stood 0.98 mm
    apart, the old estimate 0.7·h a digit being short of osifont's 1.8·h/2.5)."""
    from graphplan.graphic.record import Primitive
    ink = Primitive("text", ((0.0, 0.0),), text="8" * len(str(n_points - 1)), size=size).ink()
    width = ink[2] - ink[0] + NUMBER_GAP + 0.2
    every = next(k for k in (1, 2, 4, 5, 10, 20, 50, 100) if k * spacing >= width or k == 100)
    keep = [k for k in range(n_points) if k % every == 0]
    if keep[-1] != n_points - 1:
        if len(keep) > 1 and (n_points - 1 - keep[-1]) * spacing < width:
            keep.pop()              # the last always: not one beside it ("32 33" 1 mm apart)
        keep.append(n_points - 1)
    return keep


def spots(pos, lang: str, period: float | None = None, size: float = NUMBER, spacing: float | None = None,
          names: list[int] | None = None) -> list[tuple[list[int], str]]:
    """The division numbers lettered, one label a spot (``pos``: the divisions along their axis, mm;
    ``period``: the axis's length where it closes on itself, the profile's circle): divisions at one
    place — the end of the rise and the start of the return where there is no far dwell, on the
    profile also the last and 0 where there is no near dwell — share one label, the numbers apart as
    the phase diagram writes them ("6; 7" in uk, where the comma is the decimal sign; "6, 7" in en),
    not one drawn over the other. Thinned as ``numbered`` thins them (the first and the last spot
    always); a shared spot's label is always drawn, and a neighbour within its wider lettering and
    1.5 mm of it left out (``spacing``: the spots' spacing ``numbered`` thins by, else their least
    distance). ``names``: the number each division carries (graphic.cam.division_numbers: with no far
    dwell the rise's end and the return's start are one point, one number). Each: the divisions, the
    text."""
    from graphplan.graphic.record import Primitive
    pos = np.asarray(pos, float)
    sep = "; " if lang == "uk" else ", "

    def apart(a: float, b: float) -> float:
        d = abs(a - b)
        return min(d, period - d) if period else d
    groups: list[list[int]] = []
    for k, p in enumerate(pos):
        at = next((g for g in groups if apart(pos[g[0]], p) < 1e-6), None)
        if at is None:
            groups.append([k])
        else:
            at.append(k)
    if not groups:
        return []
    at = [float(pos[g[0]]) for g in groups]
    gaps = [apart(a, b) for a, b in zip(at, at[1:])]
    keep = numbered(len(groups), spacing or (min(gaps) if gaps else 10.0), size)
    names = list(range(len(pos))) if names is None else list(names)
    text = [sep.join(dict.fromkeys(str(names[k]) for k in g)) for g in groups]
    shared = [i for i, g in enumerate(groups) if sep in text[i]]

    def width(i: int) -> float:
        b = Primitive("text", ((0.0, 0.0),), text=text[i], size=size).ink()
        return b[2] - b[0]
    out = []
    for i in sorted(set(keep) | set(shared)):
        crowded = any(apart(at[i], at[j]) < max(width(i), width(j)) + 1.5 for j in shared if j != i)
        if i in shared or not crowded or i == 0:
            out.append(i)
    return [(groups[i], text[i]) for i in out]


def diagrams(sol: Solution, g: CamConstruction, lang: str, keys: tuple[str, ...] = ("a", "v", "s")) -> Record:
    """d²s/dφ², ds/dφ and s over the turn (L mm), one above another on one φ axis (s on top, where the
    phase diagram stands beside it), integrated upward by chords: on the d²s/dφ² diagram's axis the
    pole P1 at H1 left of the origin, each interval's mean ordinate carried across to the ordinate
    axis and joined to P1 by a ray, the chords of ds/dφ laid parallel to the rays; the same with P2 at
    H2 on the ds/dφ diagram for the chords of s. The drawn ordinates at the divisions, the divisions
    numbered under the s diagram as in the table and on the profile. ``keys``: the diagrams drawn
    (a set of sheets too small for the three at a legible size: ("a", "v") on one sheet, ("s",) on
    the next — its chords parallel to the rays from P2 on the first, sheets.cam.set_sizes)."""
    cam = sol.cam
    rec = Record("cam diagrams")
    work = math.degrees(working_angle(cam))
    L = math.radians(work) / g.mu_phi          # the abscissa: the working angle φ_р (μ_φ = φ_р/L)
    fine = np.linspace(0.0, work - 1e-9, 721)  # its end the return's end (the near dwell not drawn)
    # and either side of each jump of d²s/dφ² (a phase's end, a law's knot): its vertical drawn upright,
    # not slanted over the grid's step (stop 49: the parabolic return's mid jump leant 0.25 mm)
    knots = jump_points(cam)
    knots = knots[(knots > 1e-6) & (knots < work - 1e-6)]
    fine = np.unique(np.concatenate([fine, knots - 1e-7, knots + 1e-7]))
    s, v, a = motion(cam, fine)
    xf = np.radians(fine) / g.mu_phi
    x = np.radians(g.phi) / g.mu_phi
    # the intervals' ends, rise then return (as the mean ordinates are kept)
    xe = np.concatenate([np.column_stack((x[g.phase == ph][:-1], x[g.phase == ph][1:])) for ph in (0, 1)])
    bands = {}
    labels: list[LabelRequest] = []
    y = 0.0
    sym = symbols(cam.rocking)
    shocks = rigid_shocks(sol, g.mu_phi)
    for key, curve, drawn, letter, pole in (("a", a / g.mu_a, g.a_mm, sym["a"], g.H1),
                                             ("v", v / g.mu_v, g.v_mm, sym["v"], g.H2),
                                             ("s", s / g.mu_s, g.s_mm, sym["s"], 0.0)):
        if key not in keys:
            continue
        lo, hi = min(float(np.min(curve)), 0.0), max(float(np.max(curve)), 0.0)
        reach = SHOCK_LEAST
        if key == "a" and shocks:      # room for the rigid shocks' arrows to ±∞ and their ∞
            reach = max(SHOCK_LEAST, SHOCK_PART * max(hi, -lo))
            if any(sg > 0 for _, sg in shocks):
                hi = max(hi, reach + 6.0)
            if any(sg < 0 for _, sg in shocks):
                lo = min(lo, -reach - 6.0)
        if key == "s" and bands:       # room under s's numbers for its phases' dimensions (_phase_spans)
            y += PHASE_ROOM
        y0 = y - lo
        bands[key] = y0
        left = -pole - 4.0 if pole else 0.0
        rec.segment((left, y0), (L + 6.0, y0), role="construction", width=AXIS_W, layer=LAYER, step=f"axis {key}")
        rec.vector((0.0, y0 + lo - 3.0 if lo < 0 else y0), (0.0, y0 + hi + 6.0), role="construction", width=AXIS_W,
                   layer=LAYER, step=f"ordinate {key}")
        labels.append(LabelRequest(complex(0.0, y0 + hi + 6.0), letter, toward=1 + 0.3j, size=TEXT))
        labels.append(LabelRequest(complex(L + 6.0, y0), "φ", toward=1 - 1j, size=TEXT))
        mu = {"s": g.mu_s, "v": g.mu_v, "a": g.mu_a}[key]
        labels.append(LabelRequest(complex(L, y0 + hi + 4.0), scale_text(f"mu_{key}", mu, cam.rocking, lang),
                                   toward=-0.2 + 1j, size=TEXT))
        pts_curve = list(zip(xf, y0 + curve))
        if key == "a" and abs(curve[-1]) > 0.05:
            # the return's end a soft shock (the cosine or parabolic law's d²s/dφ² jumps to the near dwell's
            # 0): drawn down to the axis, as the jump at the return's start is (stop 48: the curve stopped
            # in the air at the last division)
            pts_curve.append((float(xf[-1]), y0))
        if key == "a" and abs(curve[0]) > 0.05:
            # and so the rise's start: the near dwell's 0 jumps to the law's first ordinate (the cosine
            # law's soft shock), drawn up the ordinate axis in the curve's line (stop 49: the curve began
            # in the air at the axis's top, its jump only the thin axis)
            pts_curve.insert(0, (0.0, y0))
        rec.add("polyline", pts_curve, role="curve", layer=LAYER, step=f"{key}(φ) exact")
        if key == "a":
            for j, (xs, sg) in enumerate(shocks):     # the rigid shock: d²s/dφ² → ±∞ at the jump of ds/dφ
                tip = (xs, y0 + sg * reach)
                rec.vector((xs, y0), tip, role="curve", layer=LAYER, step=f"shock {j}")
                labels.append(LabelRequest(complex(*tip), "∞", toward=complex(1.0, 0.6 * sg), size=TEXT,
                                           step=f"shock {j}"))
        for k in range(len(x)):
            rec.segment((x[k], y0), (x[k], y0 + drawn[k]), role="construction", layer=LAYER, step=f"{key} at {k}")
        if key in ("v", "s"):     # the chords of the integral, parallel to the rays below
            chord = g.v_chord if key == "v" else g.s_chord
            # s closed by the correction (close_phases): the chords of a phase that missed its closing
            # are the first traverse, drawn dashed and thinner than any line kept (the lab erases them;
            # review 13 #16: kept thin but solid 2 mm over ψ_max at the rise's end, they read as ink)
            for ph in (0, 1):
                first = key == "s" and abs(g.closing[ph]) > 0
                role, width = ("projection", UNCLOSED_W) if first else ("chord", None)
                sel = np.flatnonzero(g.phase == ph)
                for j in range(len(sel) - 1):
                    p, q = sel[j], sel[j + 1]
                    rec.segment((x[p], y0 + chord[p]), (x[q], y0 + chord[q]), role=role, layer=LAYER,
                                width=width, step=f"chord {key} {ph} {j}")
        if pole:
            _pole(rec, y0, lo, pole, g.a_mid if key == "a" else g.v_mid, xe, "1" if key == "a" else "2",
                  key, labels)
        if key == "s" and "v" not in keys:
            _pole_carried(rec, y0, g.H2, g.v_mid, labels)
        y = y0 + hi + 20.0
    marks = spots(x, lang, names=division_numbers(cam.phases, len(x)))   # a point of the cam one number
    y_s = bands.get("s", 0.0)
    for ks, text in (marks if "s" in keys else []):   # s: under the axis, and under a chord ending below it
        low = min([0.0] + [float(g.s_chord[k]) for k in ks if len(g.s_chord)] + [float(g.s_mm[k]) for k in ks])
        rec.label((x[ks[0]], y_s + low - 2.0 - NUMBER), text, size=NUMBER, anchor="middle", layer=LAYER,
                  step=f"division {ks[0]}")
    if "s" in keys:
        low = min([0.0] + [float(v) for v in g.s_chord] + [float(v) for v in g.s_mm])
        _phase_spans(rec, sol, g.mu_phi, y_s + low - 2.0 - NUMBER - PHASE_BELOW, lang)
    for key in ("v", "a"):
        if key in keys:
            _division_numbers(rec, x, bands[key], marks, key)
    place_labels(rec, labels, layer=LAYER)
    rec.scales.update(mu_phi=g.mu_phi, mu_a=g.mu_a, mu_v=g.mu_v, mu_s=g.mu_s, H1=g.H1, H2=g.H2)
    return rec


PHASE_BELOW = 3.0      # mm: the phases' dimension line under the s diagram's division numbers
PHASE_ROOM = 9.0       # mm added between ds/dφ and s for that line and its names


def _phase_spans(rec: Record, sol: Solution, mu_phi: float, y: float, lang: str) -> None:
    """The phases named on the φ axis, as the lab's s diagram names them: under the division numbers a
    dimension line across each phase of the working angle (φ_п, φ_вв, φ_с; the near dwell, left off
    the abscissa, not), its arrowheads at the phase's ends (x = φ/μ_φ), its name under its middle,
    and a thin extension line up from each phase's end to the line."""
    rise, far, ret, _ = sol.cam.phases
    ends = np.radians(np.cumsum([0.0, rise, far, ret])) / mu_phi
    for j, name in enumerate(PHASE_NAMES[lang][:3]):
        xa, xb = float(ends[j]), float(ends[j + 1])
        if xb - xa < 1e-6:
            continue
        m = 0.5 * (xa + xb)
        rec.vector((m, y), (xa, y), role="construction", layer=LAYER, step=f"phase span {j}")
        rec.vector((m, y), (xb, y), role="construction", layer=LAYER, step=f"phase span {j}")
        rec.label((m, y - 1.5 - TEXT), name, size=TEXT, anchor="middle", layer=LAYER, step=f"phase span {j}")
    for xe in ends:
        rec.segment((float(xe), y - 1.5), (float(xe), y + 1.5), role="construction", layer=LAYER,
                    step="phase span end")


SHOCK_LEAST = 12.0     # mm: the shortest arrow of a rigid shock on the d²s/dφ² diagram
SHOCK_PART = 0.8       # of the diagram's largest ordinate: the arrow's length where that is longer


def rigid_shocks(sol: Solution, mu_phi: float) -> list[tuple[float, int]]:
    """The rigid shocks on the d²s/dφ² diagram (drawn over the working angle): at each corner of the
    centre profile (exact.cam.profile_corners: ds/dφ jumps, the linear law's ends) the acceleration is
    an impulse, d²s/dφ² = Δ(ds/dφ)·δ(φ − φ_k) — infinite, of the sign of the jump. Its abscissa (mm at
    ``mu_phi``) and sign (+1 up, −1 down); two jumps at one turn (no dwell between) summed."""
    work = math.degrees(working_angle(sol.cam))
    out: dict[float, float] = {}
    for c in sol.corners():
        # no near dwell: the turn 0 is also the abscissa's end (the return's end and the rise's start)
        turns = [c.phi_deg] + ([360.0] if c.phi_deg == 0.0 and work >= 360.0 - 1e-9 else [])
        for phi in turns:
            if -1e-9 <= phi <= work + 1e-9:
                x = round(math.radians(phi) / mu_phi, 9)
                out[x] = out.get(x, 0.0) + (c.v_after - c.v_before)
    return [(x, 1 if d > 0 else -1) for x, d in sorted(out.items()) if abs(d) > 1e-12]


def _division_numbers(rec: Record, x: np.ndarray, y0: float, marks: list[tuple[list[int], str]], key: str) -> None:
    """The divisions 0…N numbered on a diagram's φ axis as on the s diagram (the lab numbers every
    diagram): each number just right of its division, 1.2 mm off the axis on the side the curve
    leaves free — the next division's ordinate's other side (the curve leaving the division), or this
    one's where the next is on the axis —, the other side where its letters would touch a line drawn
    there (the curve, an ordinate, a chord, a mean ordinate carried across to the pole); where both
    sides are crossed only by the mean ordinates' thin lines (a small diagram, ordinates near the
    axis), those lines are broken 1.5 mm round the number, as a draftsman leaves a gap for it."""
    import dataclasses
    from graphplan.graphic.record import Primitive
    ours = [q for q in rec.items if q.kind in ("segment", "polyline")
            and q.step.startswith((f"{key} at", f"{key}(φ)", f"chord {key}", f"mean {key}"))]
    drawn = {int(q.step.split()[-1]): q.points[1][1] - y0 for q in ours if q.step.startswith(f"{key} at ")}

    pieces: dict[int, tuple] = {}        # each line's segments as arrays (a line asked of per number)

    def segments(q):
        got = pieces.get(id(q))
        if got is None or got[0] is not q:
            p = np.asarray(q.points, float)
            ax, ay, bx, by = p[:-1, 0], p[:-1, 1], p[1:, 0], p[1:, 1]
            got = pieces[id(q)] = (q, ax, ay, bx, by, np.maximum(ax, bx), np.minimum(ax, bx),
                                   np.maximum(ay, by), np.minimum(ay, by))
        return got[1:]

    def bundle(lines) -> tuple:
        """The lines' segments as one set of arrays, each segment's line by its index: ``hits`` asks
        of all of them at once (a line at a time, the cam sheet spent a fifth of its time here)."""
        parts = [segments(q) for q in lines]
        owner = np.concatenate([np.full(len(p[0]), i) for i, p in enumerate(parts)]) if parts else np.zeros(0, int)
        return lines, owner, [np.concatenate([p[j] for p in parts]) if parts else np.zeros(0) for j in range(8)]

    def hits(box, lines) -> list:
        """The lines (a ``bundle``) within the check's paper of the box, in their order: a line whose
        segment near the box is upright, or the part of a segment within the box's x range reaching
        into its y range."""
        pad = 0.6        # the check's 0.3 mm of paper (labels.CHECK) past a thin line's half width
        x0, y_0, x1, y_1 = box[0] - pad, box[1] - pad, box[2] + pad, box[3] + pad
        qs, owner, (ax, ay, bx, by, hx, lx, hy, ly) = lines
        near = np.nonzero(~((hx < x0) | (lx > x1) | (hy < y_0) | (ly > y_1)))[0]
        if not len(near):
            return []
        ax, ay, bx, by, own = ax[near], ay[near], bx[near], by[near], owner[near]
        upright = np.abs(bx - ax) < 1e-9
        with np.errstate(all="ignore"):      # an upright segment's quotients are not read
            # the part of each segment within the box's x range: does it reach into its y range?
            ua, ub = (x0 - ax) / (bx - ax), (x1 - ax) / (bx - ax)
            u0, u1 = np.maximum(np.minimum(ua, ub), 0.0), np.minimum(np.maximum(ua, ub), 1.0)
            ya, yb = ay + u0 * (by - ay), ay + u1 * (by - ay)
            reach = ~((np.maximum(ya, yb) < y_0) | (np.minimum(ya, yb) > y_1))
        return [qs[i] for i in np.unique(own[upright | reach])]

    taken: list[tuple] = []    # the numbers lettered on this axis so far (their ink boxes)
    bundled = None             # (this diagram's lines, every line) as ``bundle``s

    def crowded(box) -> bool:
        """Whether a number's box comes within NUMBER_GAP of one already lettered (review 13 #5: "24",
        moved left off the jump line at 25, stood 0.8 mm from "23", one read over the other)."""
        return any(box[0] < b[2] + NUMBER_GAP and b[0] < box[2] + NUMBER_GAP
                   and box[1] < b[3] + NUMBER_GAP and b[1] < box[3] + NUMBER_GAP for b in taken)

    for ks, text in marks:     # a shared spot ("6; 7"): the curve leaving it is its last division's
        k = ks[-1]
        right = drawn.get(k + 1, 0.0)
        up = right < -0.25 or (abs(right) <= 0.25 and drawn.get(k, 0.0) < -0.25)
        if bundled is None:      # the lines change only where a number breaks one (below)
            bundled = (bundle([q for q in rec.items if q.kind in ("segment", "polyline")
                               and q.step.startswith((f"{key} at", f"{key}(φ)", f"chord {key}", f"mean {key}"))]),
                       bundle([q for q in rec.items if q.kind in ("segment", "polyline", "vector")]))
        lines, everything = bundled
        best = None
        anchor, xs = "start", x[k] + NUMBER_OFF
        # left of a division any line counts (the pole's rays end at division 0's ordinate axis)
        # right of the division on either side of the axis; where the curve crosses the axis there
        # (a steep zero of d²s/dφ² mid-phase runs through both), left of it
        # (then nearer the division, 0.3 mm off it: between a jump's vertical and a neighbour's
        # number, review 13's A3 "24" had 4.46 mm of ink in 4.69 mm)
        # last, over its division (a thinned axis has the room either side: stop 49's upright jump at 25,
        # 0.5 mm right of "24", left it no other place clear of the line and of "22")
        for where, sx in (("start", x[k] + NUMBER_OFF), ("end", x[k] - NUMBER_OFF),
                          ("start", x[k] + NUMBER_NEAR), ("end", x[k] - NUMBER_NEAR), ("middle", x[k])):
            for side in ((1, -1) if up else (-1, 1)):
                y = y0 + 1.2 if side > 0 else y0 - 1.2 - NUMBER * BELOW
                box = Primitive("text", ((sx, y),), text=text, size=NUMBER, anchor=where).ink()
                if crowded(box):
                    continue
                crossed = hits(box, lines if where == "start" else everything)
                if not crossed:
                    best, anchor, xs = (y, box, []), where, sx
                    break
                if best is None and sx == x[k] + NUMBER_OFF and all(q.step.startswith(f"mean {key}") for q in crossed):
                    best = (y, box, crossed)
            if best is not None and not best[2]:
                break
        if best is None:
            y = y0 + 1.2 if up else y0 - 1.2 - NUMBER * BELOW
            best = (y, None, [])
        y, box, broken = best
        bundled = None if broken else bundled
        for q in broken:           # a horizontal thin line: two pieces, 1.5 mm clear of the number
            (ax, ay), (bx, by) = q.points
            lo, hi = sorted((ax, bx))
            at = rec.items.index(q)
            if abs(ay - y0) <= NUMBER + 2.0:     # a near-zero mean carried along the number row: it
                del rec.items[at]                # would thread the numbers ("0 _ 1 _ 2"), and reads
                continue                         # as the axis itself; its ray from P still shows it
            pieces = [((lo, ay), (box[0] - 1.5, ay)), ((box[2] + 1.5, ay), (hi, ay))]
            rec.items[at:at + 1] = [dataclasses.replace(q, points=pc) for pc in pieces if pc[1][0] - pc[0][0] > 0.3]
        placed = rec.label((xs, y), text, size=NUMBER, anchor=anchor, layer=LAYER, step=f"division {key} {ks[0]}")
        taken.append(placed.ink())


def _pole(rec: Record, y0: float, lo: float, H: float, mid: np.ndarray, ends: np.ndarray, index: str, key: str,
          labels: list[LabelRequest]) -> None:
    """The pole P at ``H`` left of the origin on the axis of the diagram integrated; over each interval
    (``ends``: its abscissas) the step of its mean ordinate — the chord method's step of equal area,
    drawn across the interval (not in the division numbers' row by the axis, where it would read as
    the axis and thread the numbers), its middle marked —, carried across to the ordinate axis and joined to
    P by a ray (the direction of the integral's chord over that interval); H dimensioned under the axis."""
    pole = (-H, y0)
    rec.point(pole, role="pole", layer=LAYER, step=f"pole P{index}")
    labels.append(LabelRequest(complex(-H, y0), f"P_{index}", toward=-0.6 + 1j, size=TEXT))
    carried: set[float] = set()       # a level carried across once (equal steps of a symmetric law share it)
    for j, (h, (xa, xb)) in enumerate(zip(mid, ends)):
        if not np.isfinite(h):        # a linear law's ds/dφ: drawn directly, no ray
            continue
        if abs(h) > NUMBER + 2.0:     # in the division numbers' row a step would read as the axis
            rec.segment((xa, y0 + h), (xb, y0 + h), role="construction", layer=LAYER, step=f"mean {key} {j} step")
        if round(float(h), 6) not in carried:
            carried.add(round(float(h), 6))
            rec.segment((xa, y0 + h), (0.0, y0 + h), role="projection", layer=LAYER, step=f"mean {key} {j}")
        rec.point((0.5 * (xa + xb), y0 + h), role="construction", layer=LAYER, step=f"mean {key} {j}")
        rec.segment(pole, (0.0, y0 + h), role="ray", layer=LAYER, step=f"ray P{index} {j}")
    yd = y0 + lo - 4.0
    rec.segment((-H, y0), (-H, yd - 1.5), role="construction", layer=LAYER, step=f"H{index}")
    rec.vector((-H / 2, yd), (-H, yd), role="construction", layer=LAYER, step=f"H{index}")
    rec.vector((-H / 2, yd), (0.0, yd), role="construction", layer=LAYER, step=f"H{index}")
    rec.label((-H / 2, yd - 4.5), f"H_{index}", size=TEXT, anchor="middle", layer=LAYER, step=f"H{index}")


CARRIED_AT = -8.0      # mm: the s diagram's own copy of ds/dφ's mean ordinates, left of its ordinate axis


def _pole_carried(rec: Record, y0: float, H: float, mid: np.ndarray, labels: list[LabelRequest]) -> None:
    """On the s diagram of a set's sheet of its own (ds/dφ on the sheet before): ds/dφ's mean ordinates
    laid off with dividers on a vertical CARRIED_AT left of s's ordinate axis, the pole P2 at H2 left of
    it on s's φ axis and the rays — the chords of s laid parallel to rays on their own sheet (review 52:
    integrated with rays from P2 on the sheet before; a draftsman cannot carry a parallel between
    sheets). Each chord over an interval rises h/H2 per mm, as the ray to its ordinate h does."""
    h = np.asarray([v for v in mid if np.isfinite(v)], dtype=float)
    if h.size == 0:
        return
    xa = CARRIED_AT
    pole = (xa - H, y0)
    lo_, hi_ = min(0.0, float(h.min())), max(0.0, float(h.max()))
    rec.segment((xa, y0 + lo_ - 2.0), (xa, y0 + hi_ + 2.0), role="construction", layer=LAYER, step="ds/dφ carried")
    rec.segment((xa - H - 4.0, y0), (0.0, y0), role="construction", width=AXIS_W, layer=LAYER, step="axis s left")
    rec.point(pole, role="pole", layer=LAYER, step="pole P2")
    labels.append(LabelRequest(complex(*pole), "P_2", toward=-0.6 + 1j, size=TEXT))
    for j, v in enumerate(sorted({round(float(v), 6) for v in h})):
        rec.point((xa, y0 + v), role="construction", layer=LAYER, step=f"mean v carried {j}")
        rec.segment(pole, (xa, y0 + v), role="ray", layer=LAYER, step=f"ray P2 {j}")
    yd = y0 + lo_ - 6.0
    rec.segment((xa - H, y0), (xa - H, yd - 1.5), role="construction", layer=LAYER, step="H2")
    rec.segment((xa, y0 + lo_ - 2.0), (xa, yd - 1.5), role="construction", layer=LAYER, step="H2")
    rec.vector((xa - H / 2, yd), (xa - H, yd), role="construction", layer=LAYER, step="H2")
    rec.vector((xa - H / 2, yd), (xa, yd), role="construction", layer=LAYER, step="H2")
    rec.label((xa - H / 2, yd - 4.5), "H_2", size=TEXT, anchor="middle", layer=LAYER, step="H2")


def phase_points(sol: Solution, g: CamConstruction) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The phase diagram's construction in the fixed frame (complex, m; the cam's centre O at 0): at
    each division the roller's centre C from the drawn s, the direction u of its motion as s grows, and
    the point K = C + iσ·dC/dφ — the velocity analogue (ds/dφ, rocking l·dψ/dφ) laid off from C along
    u turned by 90° in the sense of ω. The line OK is the profile's normal (dP/dφ·e^{iσφ} = C′ − iσC =
    −iσ·(C + iσC′)), so the angle between OK and u is the pressure angle ϑ (exact.cam.profile)."""
    cam = sol.cam
    C, C1, _, u = centre_path(cam, sol.geometry, g.s, g.v, np.zeros_like(g.s))
    return C, u, C + 1j * cam.sense * C1


def phase_scale(sol: Solution, g: CamConstruction) -> float:
    """The phase diagram's scale, m/mm: a translating follower's at μ_s (its s axis reads across from
    the s diagram's); a rocking follower's at the profile's μ_l, as the lab draws it — the arm and its
    arcs l·ψ at the scale of the profile, so R0 and the arm carry over to it (at μ_s·l the arm alone
    would be 1/μ_s mm long, larger than the profile, the main drawing) — or, where the sheet has room
    (review 11, mark 16: 1:1 on an A1 sheet, its numbers, R_0 and [ϑ] crowded by O), at an enlarging
    scale the sheet chose, ``g.mu_phase``."""
    return (g.mu_phase or g.mu_l) if sol.cam.rocking else g.mu_s


def coincident_numbers(K: np.ndarray, lang: str, tol: float = 0.5, names: list[int] | None = None
                       ) -> list[tuple[int, str]]:
    """The division numbers of the points ``K`` (mm), one label a place: points within ``tol`` mm of
    an earlier one share its label, the numbers apart — "0; 21" (uk, where the comma is the decimal
    sign), "0, 21" (en) —, not two numbers side by side that read as one ("0 21" as 021); ``names``:
    the number each point carries (graphic.cam.division_numbers), one point's number once."""
    sep = "; " if lang == "uk" else ", "
    names = list(range(len(K))) if names is None else list(names)
    out: list[tuple[int, list[str]]] = []
    for k, z in enumerate(K):
        same = next((o for o in out if abs(K[o[0]] - z) <= tol), None)
        if same is None:
            out.append((k, [str(names[k])]))
        elif str(names[k]) not in same[1]:
            same[1].append(str(names[k]))
    return [(k, sep.join(names)) for k, names in out]


NEAR_MM = 3.0        # mm: a dwell's number this near its point is by it (_own_spot's nearest search not needed)
CROWDED_MAX = 12     # numbers with a rival dot near that are set one by one (``_own_spot``); more: the placer's order


def _own_spot(rec: Record, req: LabelRequest, nearest: bool = False) -> None:
    """A number whose dot has another numbered dot within a few mm set so that its lettering is
    nearer its own dot than any of ``req.rivals`` (on a leader where need be): the placer tried with
    the preferred side turned in 16 directions, the first that gives that kept, else the nearest.
    ``nearest``: where that spot is not by its dot (NEAR_MM), 8 directions tried, the one nearest its dot kept among those that give that (a dwell's
    point where R0, the [ϑ] lines and the arm's line meet: the first went 10 mm off, stop 51)."""
    from graphplan.drawing.labels import _box_gap
    n0 = len(rec.items)
    if nearest:
        _own_spot(rec, req)                 # the first spot that does (one trial, mostly), kept when by its dot
        text = [p for p in rec.items[n0:] if p.kind == "text"]
        if text and _box_gap(text[0].ink(), req.at) <= NEAR_MM:
            return None
        del rec.items[n0:]
        return _nearest_spot(rec, req)
    best, score = None, -math.inf
    for trial, box in _turned_spots(rec, req, 16):
        margin = min(_box_gap(box, z) for z in req.rivals) - _box_gap(box, req.at)
        if margin > score:
            best, score = trial, margin
        if margin >= 1.0:
            break
    if best is not None:
        rec.items[:] = best.items


def _turned_spots(rec: Record, req: LabelRequest, n: int):
    """The placer tried on copies of ``rec`` with the preferred side turned by ±k·360°/n (0, +1, −1,
    +2 … steps): each (trial record, the number's ink box) where it set the number."""
    base = req.toward / abs(req.toward)
    for j in range(n):
        trial = dataclasses.replace(rec, items=list(rec.items), scales=dict(rec.scales))   # primitives are frozen
        turn = cmath.exp(2j * math.pi * ((j + 1) // 2) * (1 if j % 2 else -1) / n)
        place_labels(trial, [dataclasses.replace(req, toward=base * turn, optional=False)], layer=LAYER)
        text = [p for p in trial.items[len(rec.items):] if p.kind == "text"]
        if text:
            yield trial, text[0].ink()


def _nearest_spot(rec: Record, req: LabelRequest) -> None:
    """_own_spot's directions, every 45°, all tried: the lettering nearest its own dot among those at least
    1 mm nearer it than any rival's, else the one farthest from the rivals relative to its own."""
    from graphplan.drawing.labels import _box_gap
    best, key = None, (math.inf, math.inf)
    for trial, box in _turned_spots(rec, req, 8):     # every 45° (16 directions cost 0.5 s of an A3 set's sizing)
        own = _box_gap(box, req.at)
        margin = min(_box_gap(box, z) for z in req.rivals) - own
        k = (0.0, own) if margin >= 1.0 else (1.0, -margin)
        if k < key:
            best, key = trial, k
    if best is not None:
        rec.items[:] = best.items


def phase_diagram(sol: Solution, g: CamConstruction, lang: str) -> Record:
    """The phase diagram as the textbook draws it, in the fixed frame at the scale of s (rocking: the
    arm's arcs l·ψ at the profile's μ_l, phase_scale): the follower's axis (rocking: the arc of the roller's centre and the arm's
    lines toward its pivot), the drawn ds/dφ laid off from each position of the roller's centre turned
    by 90° in the sense of ω, the lines at [ϑ] to the follower's motion through the points seen at the
    largest angle, bounding the region of the cam's centre (hatched along them), and the centre O
    chosen in it: the angle at O between OK and the follower's motion is a division's pressure angle."""
    cam = sol.cam
    rec = Record("phase diagram")
    labels: list[LabelRequest] = []
    mu = phase_scale(sol, g)
    C, u, K = phase_points(sol, g)
    C, K = C / mu, K / mu
    sig = cam.sense
    # the exact curve of K over the active phases, thin
    fine, fine_phase = phase_curve(cam)
    s, v, a = motion(cam, fine, fine_phase)
    Cf, C1f, _, uf = centre_path(cam, sol.geometry, s, v, a)
    Kf = (Cf + 1j * sig * C1f) / mu
    half = len(fine) // 2
    for part in (Kf[:half], Kf[half:]):
        rec.add("polyline", list(zip(part.real, part.imag)), role="curve", layer=LAYER, step="phase curve exact")
    if cam.rocking:        # the arc of the roller's centre about the arm's pivot
        A = cam.centre_distance / mu
        ang = np.angle(C - A)
        t = np.linspace(float(np.min(ang)) - 0.05, float(np.max(ang)) + 0.05, 61)
        arc = A + cam.arm / mu * np.exp(1j * t)
        rec.add("polyline", list(zip(arc.real, arc.imag)), role="trajectory", layer=LAYER, step="roller path")
        for k in range(len(C)):     # the arm's line through C (toward the pivot) and K
            w = (C[k] - A) / abs(C[k] - A)
            ends = sorted([0.0, float(((K[k] - C[k]) * w.conjugate()).real)])
            p0, p1 = C[k] + (ends[0] - 4.0) * w, C[k] + (ends[1] + 4.0) * w
            rec.segment((p0.real, p0.imag), (p1.real, p1.imag), role="construction", layer=LAYER, step=f"arm {k}")
    else:                  # the follower's axis
        x = float(C[0].real)
        top = float(max(np.max(C.imag), np.max(K.imag))) + 6.0
        rec.segment((x, -4.0), (x, top), role="construction", width=AXIS_W, layer=LAYER,   # the s axis
                    step="follower axis")
        labels.append(LabelRequest(complex(x, top), "s", toward=1 + 0.2j, size=TEXT))
    for k in range(len(C)):
        if abs(K[k] - C[k]) > 1e-9:
            rec.segment((C[k].real, C[k].imag), (K[k].real, K[k].imag), role="construction", layer=LAYER,
                        step=f"ds/dφ {k}")
        rec.point((K[k].real, K[k].imag), role="construction", layer=LAYER, step=f"K {k}")
    O = 0j
    K_all, u_all = np.concatenate([K, Kf]), np.concatenate([u, uf])
    phase_all = np.concatenate([np.asarray(g.phase), fine_phase])
    ends: list[complex] = []
    bounds: list[tuple[complex, complex, complex]] = []
    # the boundary of the allowed region: of the lines at ±[ϑ] to the follower's motion through the
    # phase's drawn points, the one O is nearest (allowed_line: the textbook's tangent at [ϑ], not the
    # line through the point seen at the largest angle, which cut the curve where that phase does not
    # bind), drawn from its point to a little past O's foot on it
    # — of the drawn points and the curve drawn through them: the line touches the curve, never
    # cuts it between two divisions (stop 50)
    lines = [allowed_line(K_all, u_all, np.flatnonzero(phase_all == ph), math.radians(cam.allowed[ph]), O)
             for ph in (0, 1)]
    reach = [max(float(((O - K_all[k]) * d.conjugate()).real), 0.0) + PAST_O for k, _, d in lines]
    met = _crossing([(K_all[k], d) for k, _, d in lines])
    wedge = False
    if met is not None and all(t > 0.0 for t in met) and 0.0 < max(t - r for t, r in zip(met, reach)) <= CROSS_REACH:
        # the lines cross a little past their ends (CAM58: the rocking arm's 40° and 45° lines, 10° apart,
        # 20 mm past): both drawn to the crossing and on, the region's two boundaries meeting there as the
        # lab draws the wedge — else only the line nearer O bounded the drawn part and was hatched alone
        # (each letter then on its own side of the wedge: the ends need not stand ENDS_APART apart)
        reach = [max(r, t + PAST_CROSS) for t, r in zip(met, reach)]
        wedge = True
    for ph in (0, 1):
        k, turn, d = lines[ph]
        length = start = reach[ph]
        end = K_all[k] + d * length
        # the two lines cross near O: each lettered at its own end, the ends drawn ENDS_APART apart at least
        # (review 11: both [ϑ] lettered within 15 mm of O, beside "0, 17" and R0, read as either line's)
        while ends and not wedge and abs(end - ends[0]) < ENDS_APART and length < start + 40.0:
            length += 2.0
            end = K_all[k] + d * length
        ends.append(end)
        rec.segment((K_all[k].real, K_all[k].imag), (end.real, end.imag), role="direction", layer=LAYER,
                    step=f"[ϑ] line {ph}")
        bounds.append((K_all[k], end, d))
    for ph, (_, end, d) in enumerate(bounds):
        # lettered by its end on the side away from the other line's end (between the two ends a
        # letter read as either line's: review 11)
        other = bounds[1 - ph][1]
        side = d * 1j if ((other - end) * (d * 1j).conjugate()).real < 0 else d * -1j
        labels.append(LabelRequest(end - d * 4.0, allowed_text(cam.allowed[ph], lang),
                                   toward=side, size=TEXT, step=f"[ϑ] {ph}"))
    # no ray from O to those points: at R0 a little over the smallest it runs 1–2 mm beside its [ϑ]
    # line, unlettered, and reads as that line drawn twice (review 12 #16, review 13 #15); the region
    # of O hatched along both lines below their crossing instead, as the lab draws it
    _hatch_region(rec, bounds, O)
    if cam.rocking:
        # O's locus: the arc of radius a about the arm's pivot (off the drawing), on which O is chosen in
        # the region — turning O about the pivot turns the arm's start ψ0 and leaves every angle drawn
        # (the textbook's construction where a is given); dash-dot as a centre's path, lettered a
        A = cam.centre_distance / mu
        span = LOCUS_MM / abs(A)
        t = math.pi + np.linspace(-span, span, 41)
        arc = A + abs(A) * np.exp(1j * t)
        rec.add("polyline", list(zip(arc.real, arc.imag)), role="trajectory", layer=LAYER, step="O locus")
        labels.append(LabelRequest(complex(arc[0]), "a", toward=1 + 0j, size=TEXT, step="O locus"))
    # the smallest R0's centre O_min beside the chosen O (stop 50: a given R0 above the smallest; review 58 #5:
    # a given R0 below it, O_min then below O, O outside the region; review 59 #4: R0 rounded up from the
    # smallest, O_min 3 mm above O at the [ϑ] lines' crossing, unlettered while the caption named the
    # smallest) — |O_min C₀| the smallest R0 the notes print as read off the diagram, O_min marked and
    # lettered, nearer its own dot than O's (else on a leader); closer than two dots a note says how far
    o_min, o_rivals = smallest_centre(sol, g, mu, complex(C[0])), ()
    if o_min is not None:
        apart = abs(o_min - O)
        if apart >= DOTS_APART:
            near = apart < O_MIN_APART
            o_rivals = (o_min,) if near else ()
            rec.point(_pt(o_min), role="pole", layer=LAYER, step="O min")
            labels.append(LabelRequest(o_min, "O_{min}", toward=-1 + 0j, size=TEXT, step="O min",
                                       rivals=(O,) if near else ()))
        else:
            labels.append(LabelRequest(O, _o_min_note(apart, lang), toward=-1 + 0j, size=TEXT, step="O min"))
    rec.point((O.real, O.imag), role="pole", layer=LAYER, step="O")
    rec.segment(_pt(O), _pt(C[0]), role="construction", layer=LAYER, step="R0")   # |OC₀| = R0, measured
    labels.append(LabelRequest(0.5 * (O + C[0]), _chosen_R0(sol, g, lang), toward=1 + 0j, size=TEXT))
    if not cam.rocking and abs(C[0].real) > 0.5:
        _offset_dimension(rec, _pt(O), (C[0].real, 0.0))
        labels.append(LabelRequest(complex(C[0].real / 2, 0.0), "e", toward=-1j, size=TEXT))
    labels.append(LabelRequest(O, "O", toward=-1j, size=TEXT, rivals=o_rivals))
    # the axis of ds/dφ: a translating follower's through C0 (s = 0) square to its axis, lettered at its
    # end; a rocking follower's ds/dφ lies along the arm's line, lettered at the end of the longest
    j = int(np.argmax(np.abs(K - C)))
    if cam.rocking:
        w = (K[j] - C[j]) / abs(K[j] - C[j])
        labels.append(LabelRequest(K[j] + 4.0 * w, "l·dψ/dφ", toward=w, size=TEXT, step="axis ds/dφ"))
    else:
        y0 = float(C[0].imag)
        lo, hi = float(min(np.min(K.real), C[0].real)) - 4.0, float(max(np.max(K.real), C[0].real)) + 8.0
        rec.segment((lo, y0), (hi, y0), role="construction", width=AXIS_W, layer=LAYER, step="axis ds/dφ")
        labels.append(LabelRequest(complex(hi, y0), "ds/dφ", toward=1 - 1j, size=TEXT, step="axis ds/dφ"))
    # each number by its own dot: nearer it than any other numbered dot, else on a leader to it (review 9,
    # finding 1: the rocking cam's "18" and "0, 19" stood at each other's dots, R0 read as drawn to 18)
    # Those with a rival dot near are set first (before the letters R_0, O, [ϑ] take the room)
    marked = coincident_numbers(K, lang, names=division_numbers(cam.phases, len(K)))
    numbers, first = [], []
    for k, text in marked:
        rivals = tuple(complex(K[j]) for j, _ in marked if j != k and abs(K[j] - K[k]) < 25.0)
        # a dwell's point (K = C: dψ/dφ = 0) where R0, the [ϑ] lines and the arm's line meet is set first too
        # (stop 51: «0; 13» went 10 mm off C0 into the diagram, among the arc's ticks)
        close = any(abs(z - K[k]) < 8.0 for z in rivals) or (bool(rivals) and abs(K[k] - C[k]) < 1e-9)
        numbers.append(LabelRequest(K[k], text, toward=(K[k] - C[k]) or 1j, size=NUMBER, optional=not rivals,
                                    rivals=rivals, step=f"number {k}"))
        first.append(close)
    if sum(first) > CROWDED_MAX:        # many divisions (--divisions 64): every number has a rival near,
        first = [False] * len(first)    # the placer's own order serves (16 trials each cost minutes)
    for k, q in ((k, q) for (k, _), q, c in zip(marked, numbers, first) if c):
        _own_spot(rec, q, nearest=abs(K[k] - C[k]) < 1e-9)
    place_labels(rec, labels + [q for q, c in zip(numbers, first) if not c], layer=LAYER)
    rec.scales.update(mu_phase=mu)
    return rec


def smallest_centre(sol, g, mu: float, C0: complex) -> complex | None:
    """Where the smallest R0 read off the phase diagram puts the cam's centre, O_min (drawing mm, O at 0),
    where the profile's R0 is over or under it (None where it is that one): a translating follower's on
    O's line parallel to its axis, |O_min C₀| = R0_drawn (the legs √(R0² − e²) differ by the shift); a
    rocking follower's on O's locus, the arc of radius a about the arm's pivot A, on O's side of AC₀."""
    if not math.isfinite(g.R0_drawn) or abs(sol.geometry.R0 - g.R0_drawn) <= 1e-9:
        return None
    r = g.R0_drawn / mu
    if not sol.cam.rocking:
        e = sol.geometry.e
        return 1j * (math.sqrt(sol.geometry.R0 ** 2 - e ** 2) - math.sqrt(g.R0_drawn ** 2 - e ** 2)) / mu
    A = complex(sol.cam.centre_distance / mu)
    d = abs(C0 - A)
    w = (C0 - A) / d
    x = (d * d + abs(A) ** 2 - r * r) / (2.0 * d)
    if abs(x) > abs(A):
        return None
    side = 1.0 if ((0j - A) * w.conjugate()).imag >= 0 else -1.0
    return A + w * complex(x, side * math.sqrt(abs(A) ** 2 - x * x))


def _o_min_note(apart: float, lang: str) -> str:
    """O_min within two dots of O: one note by O how far it lies (drawn mm), for the caption names both."""
    x = f"{apart:.1f}"
    if x == "0.0":
        return "O = O_{min}"
    return f"O_{{min}} за {x.replace('.', ',')} мм від O" if lang == "uk" else f"O_{{min}} {x} mm from O"


def _chosen_R0(sol, g, lang: str) -> str:
    """The letter of |OC₀| on the phase diagram: «R_0 = 39 мм», the radius taken, where it is over the
    smallest read off the diagram — O is then the centre chosen in the region, not its vertex (review 52:
    O, 2 mm under the vertex, was read as drawn at the smallest R₀ = 38,2 while the profile took 39 mm);
    a rocking follower's too (stop 60: CAM60's |OC₀| drawn at the 55 mm taken, O_min 1,6 mm from O, was
    lettered «R_0» alone under the caption «найменший і прийнятий R_0»); else «R_0»."""
    if not math.isfinite(g.R0_drawn) or abs(sol.geometry.R0 - g.R0_drawn) <= 1e-9:
        return "R_0"
    from graphplan.util.words import num
    return f"R_0 = {num(sol.geometry.R0 * 1000.0, lang, 3)} {'мм' if lang == 'uk' else 'mm'}"


O_MIN_APART = 6.0    # mm: O_min this far from O and more lettered freely, nearer: its letter nearer it than O (rivals)
DOTS_APART = 2.0     # mm: O_min nearer O than this (the dots would touch) said in a note by O, not dotted
LOCUS_MM = 20.0      # mm: a rocking follower's arc of O (radius a about the pivot) drawn either side of O
ENDS_APART = 24.0    # mm: the two [ϑ] lines' ends at least this far apart (a letter is ~19 mm long)
PAST_O = 24.0        # mm: each [ϑ] line drawn past O's foot on it (room for its hatching and letter)


def allowed_line(K: np.ndarray, u: np.ndarray, idx: np.ndarray, allowed: float, O: complex = 0j
                 ) -> tuple[int, float, complex]:
    """A phase's boundary of the region of the cam's centre: the line through a drawn point K_k at
    ±[ϑ] (``allowed``, rad) to the follower's motion −u_k, of all the phase's points and both signs the
    one O lies nearest inside (the smallest margin: O's signed distance from it, + on the side where
    the line's point sees O at |ϑ| ≤ [ϑ]). For a translating follower the lines of one sign are
    parallel and the nearest is the curve's tangent at [ϑ] (the textbook's construction); the point
    seen at the largest angle from a chosen O is that tangent's point only where the phase binds.
    Returns k, the signed turn from −u_k and the line's direction."""
    best = None
    for k in idx:
        for sign in (1.0, -1.0):
            d = -u[k] * cmath.exp(1j * sign * allowed)
            margin = -sign * float(((O - K[k]) * d.conjugate()).imag)
            if best is None or margin < best[0] - 1e-9:
                best = (margin, int(k), sign * allowed, d)
    return best[1], best[2], best[3]


HATCH_STEP, HATCH_LEN = 3.0, 2.5     # mm: the strokes along a boundary line, on the region's side
HATCH_CLEAR = 6.0                    # mm: the first stroke past O (its letter, R0 and e stand there)


CROSS_REACH = 60.0   # mm: two [ϑ] lines crossing at most this far past their ends drawn on to the crossing
PAST_CROSS = 20.0    # mm: and this far past it (the wedge's two sides hatched beyond the corner)


def _crossing(lines: list[tuple[complex, complex]]) -> tuple[float, float] | None:
    """Where two lines (a point, a unit direction) cross: the distances along each from its point (None:
    parallel)."""
    (k0, d0), (k1, d1) = lines
    den = (d0.conjugate() * d1).imag
    if abs(den) <= 1e-9:
        return None
    return ((k1 - k0).conjugate() * d1).imag / den, ((k1 - k0).conjugate() * d0).imag / den


def _hatch_region(rec: Record, bounds: list[tuple[complex, complex, complex]], O: complex) -> None:
    """The region of the cam's centre (where no drawn point is seen at more than [ϑ]) hatched along
    its two boundaries: short thin strokes at 45° on O's side of each [ϑ] line (``bounds``: its drawn
    point K, its end and its direction), from HATCH_CLEAR past O's foot on it to its end, only where the
    stroke stands on O's side of the other line too (the region is the two half-planes' intersection):
    the wedge O is chosen in — below the lines' crossing where O is, or, where O stands between the
    curve and the crossing (CAM58's rocking arm), the line nearer O up to the crossing and the other
    past it (stop 58 started each line's strokes past the crossing: the line bounding O's side had none
    before it, the other none at all on the drawing)."""
    if len(bounds) != 2:
        return
    for j, (k, e, d) in enumerate(bounds):
        n = d * 1j if ((O - k) * d.conjugate()).imag > 0 else d * -1j     # toward O's side
        out = (n + d) / abs(n + d) * HATCH_LEN
        # from past O (its letter, R0 and the e line stand there) to the line's end
        foot = ((O - k) * d.conjugate()).real
        at = foot + HATCH_CLEAR
        ok, oe, od = bounds[1 - j]
        inside = ((O - ok) * od.conjugate()).imag       # O's side of the other line
        while at <= abs(e - k) - 1.0:
            p = k + d * at
            at += HATCH_STEP
            if abs(p - O) < HATCH_CLEAR / 2 or any(((z - ok) * od.conjugate()).imag * inside <= 0 for z in (p, p + out)):
                continue        # by O's dot, or past the other line: not the region
            rec.segment(_pt(p), _pt(p + out), role="hatch", layer=LAYER, step=f"region {j}")


CORNER_MARK = 0.8      # mm: the radius of the ring that marks a corner of the centre profile


def corner_name(j: int) -> str:
    """The letter of the centre profile's j-th corner (from 1, by φ), on the profile and in the notes."""
    return f"K_{j}"


def profile_drawing(sol: Solution, g: CamConstruction, lang: str) -> Record:
    """The profile by inversion at μ_l: the base circle and R_0, the follower's axis at each division
    turned against ω (numbered 0…N as in the table), the drawn s laid off, the centre profile through
    those points, the roller circles and the working profile; the follower in its start position with
    its guide (rocking: its arm on the fixed pivot), the offset line e, ω's arrow and the phase angles
    as arcs with their names."""
    cam = sol.cam
    rec = Record("cam profile")
    mu = g.mu_l
    labels: list[LabelRequest] = []
    r0 = sol.geometry.R0 / mu
    rec.circle((0.0, 0.0), r0, role="construction", layer=LAYER, step="base circle")
    corners = sol.corners()
    fine = np.unique(np.concatenate([np.linspace(0.0, 360.0, 1441), [c.phi_deg for c in corners]]))
    p = sol.at(fine)
    P, W = p["P"] / mu, p["working"] / mu
    if cam.roller > 0 and corners:
        W = eroded(P, cam.roller / mu, W)
    # the centre (theoretical) profile a thin line, the working one thick (GOST 2.303); a knife-edge's
    # centre profile is the working profile
    rec.add("polyline", list(zip(P.real, P.imag)), role="construction" if cam.roller > 0 else "link",
            layer=LAYER, step="centre profile")
    if cam.roller > 0:
        rec.add("polyline", list(zip(W.real, W.imag)), role="link", layer=LAYER, step="working profile")
    pts = profile(cam, sol.geometry, g.phi, g.s, g.v, np.zeros_like(g.phi))["P"] / mu
    back = np.exp(-1j * cam.sense * np.radians(g.phi))     # the follower turned against ω
    outer = float(np.max(np.abs(P))) + cam.roller / mu
    if cam.rocking:        # the pivot's circle; each arm from its turned pivot to the roller's centre
        a_mm = cam.centre_distance / mu
        feet = a_mm * back
        rec.circle((0.0, 0.0), a_mm, role="trajectory", layer=LAYER, step="pivot circle")
        rays = list(feet)
    else:                  # the offset's circle; each axis from its foot on it to the point laid off
        e = sol.geometry.e / mu
        if abs(e) > 0.5:
            rec.circle((0.0, 0.0), abs(e), role="trajectory", layer=LAYER, step="offset circle")
        feet = cam.sense * e * back
        rays = []
        for k in range(len(pts)):
            d = 1j * back[k]
            t = math.sqrt(max((outer + 6.0) ** 2 - abs(feet[k]) ** 2, 0.0))
            rays.append(feet[k] + t * d)
    for k, q in enumerate(pts):
        rec.segment(_pt(feet[k]), _pt(rays[k] if not cam.rocking else q), role="construction", layer=LAYER,
                    step=f"ray {k}")
        rec.point(_pt(q), role="construction", layer=LAYER, step=f"profile point {k}")
        if cam.roller > 0:     # the roller at every division: the working profile their envelope (stop 52:
            # at every second one the envelope was drawn past circles never constructed)
            rec.circle(_pt(q), cam.roller / mu, role="construction", layer=LAYER, step=f"roller {k}")
    rec.point((0.0, 0.0), role="pole", layer=LAYER, step="O")
    # the centre profile's corners (the notes' K_1, K_2, …: ds/dφ jumps there) marked and lettered where
    # they are, inside the cam by the point (stop 56: named in the notes, not found on the profile)
    for j, c in enumerate(sorted(corners, key=lambda c: c.phi_deg), 1):
        q = complex(sol.at(np.array([c.phi_deg]))["P"][0]) / mu
        rec.circle(_pt(q), CORNER_MARK, role="link", layer=LAYER, step=f"corner {j}")
        labels.append(LabelRequest(q, corner_name(j), toward=-q / abs(q) if abs(q) else 1j, size=TEXT,
                                   breaks=True))
    _follower(rec, sol, g, pts[0], labels, clear=outer + ARC_OUT + 1.5, lang=lang)
    _phase_arcs(rec, sol, g, feet, rays, outer, lang, labels)
    # R_0 drawn in the widest sector free of rays, O and ω in the sector opposite the follower
    angles = np.sort(np.mod(np.angle(np.concatenate([pts, [pts[0] * 3]])), 2 * math.pi))
    gaps = np.diff(np.append(angles, angles[0] + 2 * math.pi))
    k = int(np.argmax(gaps))
    side = angles[k] + gaps[k] / 3
    along = cmath.exp(1j * side)
    rec.segment((0.0, 0.0), _pt(r0 * along), role="construction", layer=LAYER, step="R0")
    # R_0 lettered nearer the base circle than ω's arc (_omega: 0.6 R_0, its letter inside it): at
    # 0.55 R_0 the two letters stood at one radius side by side and read «ω R₀» (review 52)
    labels.append(LabelRequest(0.82 * r0 * along, "R_0", toward=-along * 1j, size=TEXT))
    rr = omega_radius(r0, cam.roller / mu)
    toward, room = _omega_sector(feet, rays, angles[k] + 2 * gaps[k] / 3, min(gaps[k], 1.2), side, rr, cam.rocking)
    _omega(rec, rr, cam.sense, toward, room, labels)
    labels.append(LabelRequest(0j, "O", toward=-along, size=TEXT, breaks=True))   # by its dot, among the rays
    tips = np.asarray(rays if not cam.rocking else feet)
    reach = float(np.mean(np.abs(tips)))       # the numbers' circle: one label where two rays meet
    along_ = np.radians(np.mod(g.phi, 360.0)) * reach
    for ks, text in spots(along_, lang, 2 * math.pi * reach, spacing=2 * math.pi * outer / max(len(pts), 1),
                          names=division_numbers(cam.phases, len(pts))):
        k = ks[0]
        tip = rays[k] if not cam.rocking else feet[k]
        if cam.rocking and k == 0:
            # the start's pivot is O_1 (on +x, the arm up to the left, the support under it), lettered up
            # and out: its 0 left of the support's hatching, below it, a row under O_1's letters and on
            # the other side (beside them on one line it read "0 O_1"), off the pivots' circle
            # — placed at once, clear of every line drawn (position 1's arm ran under a fixed spot: review 11),
            # the others then placed round it
            _zero_by_support(rec, tip, text, feet, cam.sense)
            continue
        labels.append(LabelRequest(tip, text, toward=tip / abs(tip) if abs(tip) else 1j, size=NUMBER,
                                   optional=True))
    place_labels(rec, labels, layer=LAYER)
    rec.scales.update(mu_l=mu)
    return rec


def _zero_by_support(rec: Record, A: complex, text: str, feet, sense: int = 1) -> None:
    """The start's number at a rocking follower's pivot O_1 (``A``), below and left of the support as
    docs/cams.md asks: the first spot, turning from below-left (225°) out to the left and down and
    stepping out from 5 to 16 mm, whose lettering keeps 0.6 mm off every line and dot drawn so far
    (position 1's arm and the pivots' circle pass there for a ccw cam: review 11 found the 0 set on
    the arm) and stands at least 1 mm nearer O_1 than any other pivot; else the spot farthest from
    the lines."""
    from shapely.geometry import LineString, Point, box as shp_box
    from shapely.strtree import STRtree
    from graphplan.drawing.labels import _box_gap
    shapes = []
    for q in rec.items:
        if q.kind in ("segment", "vector", "polyline") and len(q.points) > 1:
            shapes.append(LineString(q.points))
        elif q.kind == "polygon" and len(q.points) > 2:
            shapes.append(LineString(list(q.points) + [q.points[0]]))
        elif q.kind in ("circle", "arc"):
            a0, a1 = q.angles if q.kind == "arc" else (0.0, 360.0)
            t = np.radians(np.linspace(a0, a1 if a1 > a0 else a1 + 360.0, 181))
            c = q.points[0]
            shapes.append(LineString(list(zip(c[0] + q.radius * np.cos(t), c[1] + q.radius * np.sin(t)))))
        elif q.kind == "point":
            shapes.append(Point(q.points[0]).buffer(0.8))
    tree = STRtree(shapes)
    others = [complex(z) for z in feet if abs(complex(z) - A) > 0.5]
    best, clear_best = None, -math.inf
    for r in np.arange(5.0, 16.5, 1.0):
        for turn in (0, 15, -15, 30, -30, 45, -45, 60):
            u = cmath.exp(1j * math.radians(225.0 + turn))
            if sense < 0:       # a clockwise cam's layout mirrored about O–O1: the support over O_1
                u = u.conjugate()
            z = A + r * u
            trial = rec.label((z.real, z.imag - NUMBER / 2), text, size=NUMBER, anchor="middle", layer=LAYER,
                              step="division 0")
            rec.items.pop()
            ink = trial.ink()
            own = _box_gap(ink, A)
            if others and min(_box_gap(ink, w) for w in others) < own + 1.0:
                continue
            area = shp_box(*ink)
            near = [shapes[i] for i in tree.query(area.buffer(2.0))]
            clear = min((area.distance(g) for g in near), default=2.0)
            if clear >= 0.6:
                rec.items.append(trial)
                return
            if clear > clear_best:
                best, clear_best = trial, clear
    if best is not None:
        rec.items.append(best)


def eroded(P: np.ndarray, r: float, offset: np.ndarray) -> np.ndarray:
    """The working profile where the centre profile ``P`` (mm, complex, closed) has corners: the cam
    is what stays at least r from every roller position — the centre profile's region eroded by the
    roller's disc (shapely's inner buffer): at a concave corner an arc of radius r about it, at a
    convex one a sharp edge (the pointwise offset C − r·n crosses itself there, or leaves a chord).
    ``offset`` (the pointwise offset) where the erosion is not one ring (an undercut)."""
    from shapely.geometry import Polygon
    body = Polygon(list(zip(P.real, P.imag))).buffer(0).buffer(-r, quad_segs=32)
    if body.is_empty or body.geom_type != "Polygon":
        return offset
    xy = np.asarray(body.exterior.coords)
    return xy[:, 0] + 1j * xy[:, 1]


OMEGA_AT = 0.6       # of R_0: the radius of ω's arc …
OMEGA_CLEAR = 5.0    # mm: … at most the working profile's least radius, R_0 − r, less this (its arrow and letter inside the cam)


def omega_radius(r0: float, roller: float) -> float:
    """The radius (drawn mm) of ω's arc on the profile: OMEGA_AT of R_0, inside the cam's body — no nearer
    the working profile than OMEGA_CLEAR (its points lie at least R_0 − r from O, the near dwell's arc
    there; stop 60: cg60's cam, R_0 = 36 mm and a 15-mm roller, drew ω's arc at 21.6 mm along its
    21-mm working profile, the arrow read as part of the profile's line)."""
    return max(min(OMEGA_AT * r0, r0 - roller - OMEGA_CLEAR), 0.3 * r0)


def _omega_sector(feet, rays, at: float, room: float, side: float, rr: float, rocking: bool) -> tuple[complex, float]:
    """Where ω's arc goes: a translating follower's rays are lines tangent to the offset circle, so at ω's
    radius ``rr`` each crosses at atan2 of foot + √(rr² − e²)·(ray's direction), not at its profile
    point's angle (own cam of stop 53, e = 6.6 mm, R_0 = 23 mm and no near dwell: the arc put 2/3 into the
    gap between the profile points lay among the rays, the arrow drawn over them) — the widest gap between
    those crossings and R_0's line ``side``, its middle and width; a rocking follower's arm lines stay
    outside the base circle: ``at`` and ``room`` (the profile points' gap) as given."""
    feet = np.asarray(feet, dtype=complex)
    crossing = []
    for f, r in zip(feet, np.asarray(rays, dtype=complex)):
        d = r - f
        if rocking or abs(d) < 1e-12 or abs(f) >= rr:
            continue
        crossing.append(cmath.phase(f + math.sqrt(rr * rr - abs(f) ** 2) * d / abs(d)))
    if rocking or len(crossing) < 2:
        return cmath.exp(1j * at), room
    ang = np.sort(np.mod(np.asarray(crossing + [side]), 2 * math.pi))
    gaps = np.diff(np.append(ang, ang[0] + 2 * math.pi))
    j = int(np.argmax(gaps))
    return cmath.exp(1j * (ang[j] + gaps[j] / 2)), min(float(gaps[j]), 1.2)


def _omega(rec: Record, rr: float, sense: int, toward: complex, room: float, labels: list[LabelRequest]) -> None:
    """ω's arrow: an arc of radius ``rr`` about O inside the cam (``omega_radius``), in the sector free of
    rays (``room`` rad wide about ``toward``), its head in the cam's sense."""
    mid = math.degrees(cmath.phase(toward))
    half = min(25.0, math.degrees(room) / 4)
    a0, a1 = mid - half, mid + half
    rec.arc((0.0, 0.0), rr, a0, a1, role="relative", layer=LAYER, step="ω")
    end = math.radians(a1 if sense > 0 else a0)
    tip = rr * cmath.exp(1j * end)
    tail = rr * cmath.exp(1j * (end - (1 if sense > 0 else -1) * 8.0 / rr))    # a chord 8 mm back on the arc
    rec.vector(_pt(tail), _pt(tip), role="relative", layer=LAYER, step="ω")
    labels.append(LabelRequest(rr * cmath.exp(1j * math.radians(mid)), "ω", toward=-toward, size=TEXT))


ARC_OUT = 18.0       # mm: the phase angles' arcs outside the centre profile (a translating follower's)


def _follower(rec: Record, sol: Solution, g: CamConstruction, C0: complex, labels: list[LabelRequest],
              clear: float = 0.0, lang: str = "uk") -> None:
    """The follower in its start position (φ = 0, the nearest position): a translating one's rod on its
    axis through the roller's centre (or the knife-edge's point), its guide hatched — outside the
    circle of radius ``clear`` about O (the phase angles' arcs, whose arrows meet on the follower's
    axis: the guide stood on them) —, the offset e from O to the axis; a rocking one's arm from its
    fixed pivot, the pivot's support."""
    cam = sol.cam
    mu = g.mu_l
    r = cam.roller / mu
    if cam.roller > 0:
        rec.circle(_pt(C0), r, role="link", layer=LAYER, step="roller")
        rec.point(_pt(C0), role="joint", layer=LAYER)
    if cam.rocking:
        A = complex(cam.centre_distance / mu, 0.0)
        d = (C0 - A) / abs(C0 - A)
        rec.segment(_pt(A), _pt(C0 - r * d if r else C0), role="link", layer=LAYER, step="arm")
        # the support on the side of O–O1 away from the arm: under O_1 for a counter-clockwise cam, over it
        # for a clockwise one (the whole layout mirrored about O–O1: exact.cam.centre_path, stop 60)
        m = 1.0 if cam.sense > 0 else -1.0
        for z in (A + complex(-3.5, -5.0 * m), A + complex(3.5, -5.0 * m)):
            rec.segment(_pt(A), _pt(z), role="frame", width=0.35, layer=LAYER)
        rec.segment(_pt(A + complex(-5.0, -5.0 * m)), _pt(A + complex(5.0, -5.0 * m)), role="frame", layer=LAYER)
        for k in range(5):
            z = A + complex(-5.0 + 2.5 * k, -5.0 * m)
            rec.segment(_pt(z), _pt(z + complex(-1.8, -1.8 * m)), role="hatch", layer=LAYER)
        rec.point(_pt(A), role="joint", layer=LAYER, step="pivot")
        labels.append(LabelRequest(A, "O_1", toward=1 + 1j * m, size=TEXT))
        _swing(rec, sol, A, C0, r, labels, lang)
        return
    up = 1j
    h = cam.stroke / mu
    base = C0 + (r if r else 0.0) * up
    if not r:          # the knife-edge: a point
        rec.segment(_pt(C0), _pt(C0 + complex(-1.5, 3.0)), role="link", layer=LAYER, step="knife-edge")
        rec.segment(_pt(C0), _pt(C0 + complex(1.5, 3.0)), role="link", layer=LAYER, step="knife-edge")
        base = C0 + 3.0j
    at = max(h + 8.0, math.sqrt(max(clear ** 2 - C0.real ** 2, 0.0)) - base.imag)   # the guide's foot over base
    guide = base + at * up
    top = guide + 14.0 * up
    rec.segment(_pt(base), _pt(top), role="link", layer=LAYER, step="rod")
    for side in (-1.0, 1.0):   # the guide: two short walls either side of the rod, hatched outward
        x = side * 3.0
        rec.segment(_pt(guide + x), _pt(guide + x + 10.0j), role="frame", width=0.35, layer=LAYER, step="guide")
        for t in (1.0, 4.0, 7.0):
            z = guide + x + 1j * t
            rec.segment(_pt(z), _pt(z + side * 1.8 + 1.8j), role="hatch", layer=LAYER)
    x_axis = C0.real
    foot = -3.0
    if SMALL_OFFSET > abs(x_axis) > 0.5:      # too short to letter between: dimensioned from outside
        foot = _small_offset(rec, x_axis, labels)
    elif abs(x_axis) > 0.5:     # the offset dimensioned from O across to the axis, e lettered under it
        _offset_dimension(rec, (0.0, 0.0), (x_axis, 0.0))
        labels.append(LabelRequest(complex(x_axis / 2, 0.0), "e", toward=-1j, size=TEXT))
    rec.segment((x_axis, foot), _pt(top + 4.0j), role="axis", layer=LAYER, step="follower axis")
    _stroke(rec, cam, C0, r, h, labels)


SMALL_OFFSET = 6.0    # mm drawn: an offset shorter than this is dimensioned with its arrows outside
DIM_BELOW = -9.0      # mm: that dimension line this far under O — over it, by the follower's axis, where
                      # the fewest rays pass (under O the return's rays fan out: its letter went 6 mm off)


def _offset_dimension(rec: Record, o: tuple[float, float], foot: tuple[float, float]) -> None:
    """The offset e from O to its foot on the follower's axis (the s axis) as a dimension (GOST 2.307): the
    line between them with its arrows inside, pointing out to O and to the axis — a segment lettered e
    alone (stop 59's CAM59, e = 6 mm at 1:1) reads as one more construction line among the rays at O, not
    as a size. Shorter than SMALL_OFFSET the two arrows would not stand inside: on the profile
    ``_small_offset`` puts them outside, on the phase diagram (its e among no rays) the line alone."""
    mid = (0.5 * (o[0] + foot[0]), 0.5 * (o[1] + foot[1]))
    rec.segment(o, foot, role="construction", layer=LAYER, step="offset e")
    if math.dist(o, foot) < SMALL_OFFSET:
        return
    d = math.dist(o, foot)
    at_o = (o[0] + (foot[0] - o[0]) * O_DOT / d, o[1] + (foot[1] - o[1]) * O_DOT / d)   # at O's dot, not under it
    for end in (at_o, foot):
        rec.vector(mid, end, role="construction", layer=LAYER, step="offset e dimension")


O_DOT = POINT_INK["dot"] + 0.05   # mm: the offset's arrow stops at the edge of O's dot (its tip showed under it)


def _small_offset(rec: Record, x_axis: float, labels: list[LabelRequest]) -> float:
    """A short offset e (under SMALL_OFFSET drawn — stop 52: e = 1.8 mm at 1:1, its letter by a 1.8 mm
    line among the rays at O, unreadable) dimensioned as GOST 2.307 gives a small size: an extension
    line from O and the follower's axis, the dimension line between them at −DIM_BELOW (over O) with
    the arrows outside, pointing in, and e lettered past the axis' arrow. Returns the axis' foot."""
    y = -DIM_BELOW
    sgn = 1.0 if x_axis > 0 else -1.0
    rec.segment((0.0, 0.0), (x_axis, 0.0), role="construction", layer=LAYER, step="offset e")
    rec.segment((0.0, 0.0), (0.0, y + math.copysign(2.0, y)), role="construction", layer=LAYER,
                step="offset e extension")
    rec.segment((0.0, y), (x_axis, y), role="construction", layer=LAYER, step="offset e dimension")
    rec.vector((-sgn * 5.0, y), (0.0, y), role="construction", layer=LAYER, step="offset e dimension")
    rec.vector((x_axis + sgn * 5.0, y), (x_axis, y), role="construction", layer=LAYER, step="offset e dimension")
    labels.append(LabelRequest(complex(x_axis + sgn * 5.0, y), "e", toward=sgn, size=TEXT, step="offset e"))
    return min(-3.0, y - 2.0)


SWING_ARC = 0.55      # of the arm: the radius of ψ_max's dimension arc about O_1


def _swing(rec: Record, sol: Solution, A: complex, C0: complex, r: float, labels: list[LabelRequest],
           lang: str) -> None:
    """A rocking follower's swing, as the task gives it (the translating follower's stroke h, _stroke):
    the arm in its top position dashed (C = A + l·e^{i(π − ψ0 − ψ_max)}, exact.cam.centre_path), the
    knife-edge's (the roller centre's) path — its arc of radius l about O_1 from the start to the top
    position, thin dash-dot — and ψ_max dimensioned as an angle (GOST 2.307: an arc about O_1 between
    the two arms, arrowheads on them, «ψ_max = 22°» at its middle; stop 48: the profile drew the arm
    at the start alone, the swing the task names nowhere on it)."""
    from graphplan.graphic.gears import arc_dimension
    from graphplan.util.words import num
    cam = sol.cam
    l = abs(C0 - A)
    start = cmath.phase(C0 - A)
    sig = 1 if cam.sense > 0 else -1
    # ψ grows clockwise about O_1 for a counter-clockwise cam, counter-clockwise for a clockwise one (centre_path)
    top = A + (C0 - A) * cmath.exp(-1j * sig * cam.stroke)
    d = (top - A) / l
    rec.segment(_pt(A), _pt(top - r * d if r else top), role="projection", layer=LAYER, step="swing top arm")
    if r:
        rec.circle(_pt(top), r, role="projection", layer=LAYER, step="swing top roller")
    over = min(0.25 * cam.stroke, math.radians(4.0))
    lo, hi = sorted((start, start - sig * cam.stroke))
    rec.arc(_pt(A), l, math.degrees(lo - over), math.degrees(hi + over), role="trajectory",
            layer=LAYER, step="swing path")
    rd = SWING_ARC * l
    arc_dimension(rec, A, rd, lo, hi, "swing psi_max")
    m = cmath.exp(1j * (start - sig * cam.stroke / 2))
    labels.append(LabelRequest(A + rd * m, f"ψ_max = {num(math.degrees(cam.stroke), lang, 4)}°",
                               toward=m, size=TEXT, step="swing psi_max"))


def _stroke(rec: Record, cam, C0: complex, r: float, h: float, labels: list[LabelRequest]) -> None:
    """The stroke h dimensioned along the follower's axis (GOST 2.307), as the lab's task states it: the
    roller (or the knife-edge's point) in its top position dashed, extension lines square to the
    axis from its start and top centres, the dimension line between them with arrowheads, h lettered —
    on the side of the near dwell, where the profile stays on the base circle (the inversion turns the
    dwell's last positions by +σ from the axis: left of it for ccw, right for cw)."""
    from graphplan.graphic.gears import dimension
    top = C0 + h * 1j
    if r:
        rec.circle(_pt(top), r, role="projection", layer=LAYER, step="stroke h")
    else:
        for dx in (-1.5, 1.5):
            rec.segment(_pt(top), _pt(top + complex(dx, 3.0)), role="projection", layer=LAYER, step="stroke h")
    side = -1.0 if cam.sense > 0 else 1.0
    near, far = (r + 1.0 if r else 2.5), (r + 7.0 if r else 8.5)
    for y in (C0, top):
        rec.segment(_pt(y + side * near), _pt(y + side * far), role="construction", layer=LAYER, step="stroke h")
    x = side * (far - 2.0)
    dimension(rec, C0 + x, top + x, "stroke h")
    labels.append(LabelRequest(C0 + x + h / 2 * 1j, "h", toward=side, size=TEXT, step="stroke h"))


def allowed_text(value: float, lang: str) -> str:
    """The allowed pressure angle with its value, «[ϑ] = 30°»."""
    from graphplan.util.words import num
    return f"[ϑ] = {num(value, lang, 4)}°"


def phase_text(name: str, size: float, lang: str) -> str:
    """A phase angle's lettering: its name and its value, «φ_п = 120°»."""
    from graphplan.util.words import num
    return f"{name} = {num(size, lang, 4)}°"


def _phase_arcs(rec: Record, sol: Solution, g: CamConstruction, feet, rays, outer: float, lang: str,
                labels: list[LabelRequest]) -> None:
    """The phase angles dimensioned as angles are (GOST 2.307): about O, outside the division numbers,
    an arc between extension lines along the follower's positions at the phases' starts (the rays
    turned against ω), its arrowheads on them, its name and value at its middle («φ_п = 120°»)."""
    cam = sol.cam
    rise, far, ret, near = cam.phases
    starts = [0.0, rise, rise + far, rise + far + ret]
    sizes = [rise, far, ret, near]
    if cam.rocking:        # the numbers at the arms' pivots (radius a): the arcs outside them (docs/cams.md;
        # review 9: inside, they crossed every arm's line), the extension lines from past the numbers
        a = cam.centre_distance / g.mu_l
        ref = cmath.phase(feet[0])
        R, root = a + 14.0, a + 8.0
    else:                  # the numbers at the rays' tips (outer + 6 mm)
        ref = cmath.phase(rays[0])
        R, root = outer + ARC_OUT, outer + 7.0
    sig = cam.sense
    for j, (name, start, size) in enumerate(zip(PHASE_NAMES[lang], starts, sizes)):
        if size < 1.0:
            continue
        a0 = ref - sig * math.radians(start)
        a1 = ref - sig * math.radians(start + size)
        lo, hi = sorted((a0, a1))
        rec.arc((0.0, 0.0), R, math.degrees(lo), math.degrees(hi), role="construction", layer=LAYER,
                step=f"phase {j}")
        for t, inward in ((lo, 1.0), (hi, -1.0)):
            z = cmath.exp(1j * t)
            rec.segment(_pt(root * z), _pt((R + 2.0) * z), role="construction", layer=LAYER, step=f"phase {j} end")
            back = min(6.0, 0.4 * R * (hi - lo)) / R           # the arrow 6 mm along the arc, less on a short one
            tail = R * cmath.exp(1j * (t + inward * back))
            rec.vector(_pt(tail), _pt(R * z), role="construction", layer=LAYER, step=f"phase {j} arrow")
        m = cmath.exp(1j * (lo + hi) / 2)
        labels.append(LabelRequest(R * m, phase_text(name, size, lang), toward=m, size=TEXT, step=f"phase {j}"))


def records(sol: Solution, g: CamConstruction, lang: str) -> dict[str, Record]:
    return {"diagrams": diagrams(sol, g, lang), "phase": phase_diagram(sol, g, lang),
            "profile": profile_drawing(sol, g, lang)}


PRESSURE_NAMES = {"uk": "Кут тиску ϑ(φ)", "en": "Pressure angle ϑ(φ)"}


def pressure_diagram(sol: Solution, g: CamConstruction, lang: str, mu_phi: float, mu_theta: float) -> Record:
    """The pressure angle over the working angle φ_р: the exact ϑ(φ) a curve, the protractor's reading
    at each division (Table 1's «ϑ гр.») an ordinate from the φ axis, the divisions numbered as on the
    other diagrams, and each phase's band |ϑ| ≤ [ϑ] between dashed lines over that phase (the phase
    diagram's condition read along the turn). φ at ``mu_phi`` rad/mm, ϑ at ``mu_theta`` °/mm."""
    cam = sol.cam
    rec = Record("pressure angle")
    rise, far, ret, _ = cam.phases
    work = rise + far + ret
    L = math.radians(work) / mu_phi
    fine = np.linspace(0.0, work - 1e-9, 721)
    theta = sol.at(fine)["theta"]
    xf = np.radians(fine) / mu_phi
    x = np.radians(g.phi) / mu_phi
    lo = min(float(np.min(theta)), float(np.min(g.theta)), -max(cam.allowed), 0.0) / mu_theta
    hi = max(float(np.max(theta)), float(np.max(g.theta)), max(cam.allowed), 0.0) / mu_theta
    labels: list[LabelRequest] = []
    rec.segment((0.0, 0.0), (L + 6.0, 0.0), role="construction", width=AXIS_W, layer=LAYER, step="axis ϑ")
    rec.vector((0.0, lo - 3.0), (0.0, hi + 6.0), role="construction", width=AXIS_W, layer=LAYER, step="ordinate ϑ")
    labels.append(LabelRequest(complex(0.0, hi + 6.0), "ϑ, °", toward=1 + 0.3j, size=TEXT))
    labels.append(LabelRequest(complex(L + 6.0, 0.0), "φ", toward=1 - 1j, size=TEXT))
    _graduate(rec, lo, hi, mu_theta, lang)
    for ph, (a, b) in enumerate(((0.0, rise), (rise + far, work))):
        xa, xb = math.radians(a) / mu_phi, math.radians(b) / mu_phi
        band = cam.allowed[ph] / mu_theta
        for sign in (1.0, -1.0):
            rec.segment((xa, sign * band), (xb, sign * band), role="projection", layer=LAYER, step=f"[ϑ] {ph}")  # dashed
        labels.append(LabelRequest(complex((xa + xb) / 2, band + 1.0), allowed_text(cam.allowed[ph], lang),
                                   toward=1j, size=TEXT, step=f"[ϑ] {ph}"))   # 1 mm more: a fallback font's bracket
        # the lower band by its value alone: "−[ϑ] = −30°" read as a double minus (review 12 #15)
        labels.append(LabelRequest(complex((xa + xb) / 2, -band - 1.0),
                                   "−" + allowed_text(cam.allowed[ph], lang).split(" = ", 1)[1],
                                   toward=-1j, size=TEXT, step=f"−[ϑ] {ph}"))
    rec.add("polyline", list(zip(xf, theta / mu_theta)), role="curve", layer=LAYER, step="ϑ(φ) exact")
    # a phase whose largest |ϑ| exceeds its [ϑ] (a given R0 below the smallest): that extreme marked and
    # lettered with «*», as the notes print it (review 57: the curve crossed the 25° line unmarked)
    from graphplan.util.words import fixed
    for ph, (p_deg, t_deg) in enumerate(sol.pressure_extreme_points()):
        if abs(t_deg) > cam.allowed[ph] + 1e-9:
            spot = complex(math.radians(p_deg) / mu_phi, t_deg / mu_theta)
            rec.point((spot.real, spot.imag), role="pole", layer=LAYER, step=f"ϑ over [ϑ] {ph}")
            labels.append(LabelRequest(spot, fixed(t_deg, lang, 2).replace("-", "−") + "°*",
                                       toward=(1j if t_deg > 0 else -1j) + 0.6, size=TEXT, step=f"ϑ over [ϑ] {ph}"))
    for k in range(len(x)):
        y = float(g.theta[k]) / mu_theta
        if abs(y) > 1e-9:
            rec.segment((x[k], 0.0), (x[k], y), role="construction", layer=LAYER, step=f"ϑ at {k}")
        rec.point((x[k], y), role="construction", layer=LAYER, step=f"ϑ at {k}")
    for ks, text in spots(x, lang, names=division_numbers(cam.phases, len(x))):   # no far dwell: one number
        k = ks[-1]
        side = -1j if g.theta[k] >= 0 else 1j            # the side the ordinate leaves free
        labels.append(LabelRequest(complex(x[k], 0.0), text, toward=side, size=NUMBER, optional=True))
    place_labels(rec, labels, layer=LAYER)
    rec.scales.update(mu_phi=mu_phi, mu_theta=mu_theta)
    return rec


def theta_ticks(lo: float, hi: float, mu_theta: float) -> list[float]:
    """The ϑ axis's graduation (degrees): the round step of ``charts.axis_step`` (1, 2 or 5 × 10ⁿ, at
    least 8 mm apart at ``mu_theta`` °/mm) at every value within the drawn range [lo, hi] mm, 0 left
    out (the φ axis and division 0 stand there; stop 52: the axis had no graduations at all)."""
    from graphplan.drawing.charts import axis_step
    tick = axis_step(mu_theta)
    first, last = math.ceil(lo * mu_theta / tick - 1e-9), math.floor(hi * mu_theta / tick + 1e-9)
    return [round(i * tick, 9) for i in range(first, last + 1) if i != 0]


def _graduate(rec: Record, lo: float, hi: float, mu_theta: float, lang: str) -> None:
    """Ticks 1.5 mm left of the ϑ axis at ``theta_ticks`` with their values (2.5 mm, right-aligned
    1 mm off the tick's end, the minus a true minus)."""
    from graphplan.util.words import num
    for v in theta_ticks(lo, hi, mu_theta):
        y = v / mu_theta
        rec.segment((-1.5, y), (0.0, y), role="construction", width=AXIS_W, layer=LAYER, step="ϑ graduation")
        rec.label((-2.5, y - 1.2), num(v, lang).replace("-", "−"), size=NUMBER, anchor="end", layer=LAYER,
                  step="ϑ graduation")


def pressure_scales(sol: Solution, width: float, height: float) -> tuple[float, float]:
    """μ_φ (rad/mm, a standard one in °/mm: the working angle in at most ``width`` mm less the axis's
    end and its letters) and the
    finest standard μ_ϑ (°/mm: 1, 2, 2.5, 4, 5 × 10^k) that puts ϑ's range and the bands ±[ϑ] in
    ``height`` mm less the letters above and below."""
    from graphplan.graphic.scales import series_around
    cam = sol.cam
    rise, far, ret, _ = cam.phases
    need_phi = (rise + far + ret) / max(width - 20.0, 10.0)          # °/mm: the series' at or above it
    mu_phi = math.radians(min(m for m in series_around(need_phi) if m >= need_phi * (1 - 1e-12)))
    theta = sol.at(np.linspace(0.0, rise + far + ret, 721))["theta"]
    span = max(float(np.max(theta)), max(cam.allowed)) - min(float(np.min(theta)), -max(cam.allowed))
    need = span / max(height - 18.0, 5.0)
    return mu_phi, min(m for m in series_around(need) if m >= need * (1 - 1e-12))
