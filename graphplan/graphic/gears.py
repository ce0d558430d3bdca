"""The gear sheet's constructions as a draftsman makes them (REFERENCE §12; docs/gears.md), in drawing
millimetres (x right, y up), every laid-off length rounded by the ruler of the drafting precision and
every reading taken with it (graphic.draftsman.measure):

1. The meshing: the centres O1 (below) and O2 at aw; the five circles rf, rb, r, rw, ra of each wheel;
   the line of action N1N2, the common tangent of the base circles, crossing O1O2 at the pitch point P
   (rw read off as O1P, O2P); its active part B1B2 cut by the tip circles (B1 on wheel 2's, B2 on wheel
   1's); the involutes as the draftsman builds them — N1P (N2P) divided into four equal parts, the same
   arcs laid off along the base circle, tangents at the division points with the unrolled lengths;
   the tooth thickness s laid off as its chord on the pitch circle, the other flank mirrored about the
   tooth's axis; three teeth of each wheel with the fillets (radius 0.38m) to the root circle; the
   working parts of the flanks in mesh marked; the arc of action on both rolling circles.
   Read: B1B2 with the ruler, εα = B1B2/pb (pb laid off); s, sa as chords (turned into arcs).
2. The specific sliding λ1, λ2 over N1N2 (at the meshing's length scale; λ at 20 mm a unit).
3. The planetary train: its scheme at μl (the upper half, radii on one vertical line), the velocity
   picture (vA = ω1·r1 at μv; each member's velocities a straight line: the sun's through O, the
   planet's through its contact C with the fixed ring, the carrier's through O and the planet's axis),
   the plan of angular velocities (rays from a pole h below a horizontal, parallel to those lines:
   ω = segment·μv/(μl·h)); u1H = the sun's segment over the carrier's.

The bounds on the graphical error (``eps_bound``, ``ratio_bound``) are first-order: each laid-off and
each read length off by at most half the precision, the errors added in absolute value.
"""
from __future__ import annotations

import cmath
import itertools
import math
from dataclasses import dataclass, field

import numpy as np

from graphplan.exact.gears import PairSolution, TrainSolution
from graphplan.graphic.draftsman import circle_line, lay_off, measure
from graphplan.graphic.record import Primitive, Record, text_width
from graphplan.util.words import fixed, num

LAYER = "gears"
TEXT = 3.5
DEPTH_MM = (40.0, 60.0)        # the whole depth 2.25m drawn this tall
ENLARGE = (1.0, 2.0, 2.5, 4.0, 5.0, 10.0, 20.0, 40.0, 50.0, 100.0)   # GOST 2.302 enlargements, 1:1 …
REDUCE = (0.1, 0.2, 0.25, 0.4, 0.5)                                   # … and reductions, 1:10 … 1:2
DIVISIONS = 4                  # equal parts of N1P for the involute
LEADER = 7.0                   # mm: a letter farther than this from its point gets a leader
SMALL = 2.5                    # mm: GOST 2.304's least letters (s, p, a1 … on the meshing; a crowded point's)
NEAR_CLEAR = 0.9               # mm: a point's letter's glyphs this far off the lines' middles where placed near
FILLET = 0.38                  # the rack's fillet radius, ρf = 0.38m
LAMBDA_MM = 20.0               # the λ diagrams: 1 unit = 20 mm
LAMBDA_CLIP = 3.0              # |λ| drawn up to 3 (±∞ at N1, N2)
TEETH = 3                      # teeth drawn of each wheel (the one in mesh at P in the middle) …
MORE_TEETH = (7, 5)            # … or more where the meshing's zone holds them (a sheet's main drawing)
TEETH_SPAN = math.radians(85.0)   # the outer teeth's circles reach at most this far from the centre line


def _f(z: complex) -> tuple[float, float]:
    return (z.real, z.imag)


# -- placing letters clear of every line ---------------------------------------------------------

class Placer:
    """Letters put where no ink is: the record's lines sampled every 0.4 mm into 2-mm cells, each
    label at the first candidate spot around its anchor whose box, grown by ``clear`` mm, holds
    no ink and no earlier letter."""
    CELL = 2.0

    def __init__(self, rec: Record, clear: float = 0.8):
        self.rec, self.clear = rec, clear
        self.cells: dict[tuple[int, int], list[tuple[float, float]]] = {}
        self.letters: dict[tuple[int, int], list[tuple[float, float]]] = {}     # the letters' ink alone
        for p in rec.items:
            self._add(_ink_points(p))

    def _add(self, pts, into=None) -> None:
        # (a gear sheet's search draws ~30 trains, each Placer sampling ~10⁵ points: the loop kept tight)
        c = self.CELL
        cells = self.cells if into is None else into
        get, floor = cells.get, math.floor
        for x, y in pts:
            key = (floor(x / c), floor(y / c))
            got = get(key)
            if got is None:
                cells[key] = [(x, y)]
            else:
                got.append((x, y))

    def free(self, box, cells=None) -> bool:
        x0, y0, x1, y1 = box
        m, c = self.clear, self.CELL
        cells = self.cells if cells is None else cells
        for i in range(int(math.floor((x0 - m) / c)), int(math.floor((x1 + m) / c)) + 1):
            for j in range(int(math.floor((y0 - m) / c)), int(math.floor((y1 + m) / c)) + 1):
                for x, y in cells.get((i, j), ()):
                    if x0 - m <= x <= x1 + m and y0 - m <= y <= y1 + m:
                        return False
        return True

    def free_path(self, a: complex, b: complex, letters_only: bool = False) -> bool:
        """Whether a leader from a to b passes clear of every line and letter (of the letters only)."""
        n = max(1, int(abs(b - a) / 0.4))
        for k in range(n + 1):
            q = a + (b - a) * k / n
            if not self.free((q.real, q.imag, q.real, q.imag), self.letters if letters_only else None):
                return False
        return True

    def label(self, at: complex, text: str, size: float = TEXT, toward: complex | None = None,
              radii=(1.5, 2.5, 4.0, 6.0, 7.5, 9.0, 10.5, 12.0, 13.0, 15.0, 18.0, 24.0, 32.0), optional: bool = False,
              near: bool = False) -> bool:
        """``near``: a point's letter (N1, B1, P …) tried first close to its point in 32 directions
        before it is taken farther on a leader (review 5: N1 7 mm off)."""
        w = text_width(text, size)
        dirs = [cmath.exp(1j * math.pi * k / 16) for k in range(32)] if near else \
            [cmath.exp(1j * math.pi * k / 8) for k in range(16)]
        if toward is not None and abs(toward) > 0:
            u = toward / abs(toward)
            dirs.sort(key=lambda d: -((d * u.conjugate()).real))
        far = tuple(r for r in (18.0, 24.0, 32.0, 45.0, 60.0) if r > max(radii))
        close = (0.8, 1.2, 1.8, 2.5, 3.5, 4.5, 5.5, 6.5)     # past 3.5 mm on a short leader
        # a near letter's glyphs (its ink, not its advance box) kept NEAR_CLEAR off the lines' middles:
        # less a thick line's half width (0.35 mm) and the sampled lines' 0.4 mm steps (0.2 mm), still
        # more than the check's 0.3 mm
        # (stop 49: GEARS47's B2 went 16,5 mm off on a leader where 2,5-mm letters — GOST 2.304's least,
        # the meshing's own for s, p, a1 … — stand beside it: a point's letter tried so before the leader)
        small = ((True, close, True, SMALL),) if near and size > SMALL else ()
        passes = ([(True, close, True, size)] if near else []) + list(small) + [
            (True, tuple(radii) + far, False, size), (False, tuple(radii) + far, False, size)]
        full = size
        for strict, rads, by_ink, size in passes:   # first with the leader's path clear too, then the box alone
            w = text_width(text, size)
            for rad in rads:
                for d in dirs:
                    # the box's nearest side ``rad`` from the anchor along d
                    cx = at.real + d.real * (rad + w / 2)
                    cy = at.imag + d.imag * (rad + size / 2)
                    prim = Primitive("text", ((cx - w / 2, cy - size / 2),), text=text, size=size)
                    box = prim.bounds()
                    if by_ink:
                        keep, self.clear = self.clear, NEAR_CLEAR
                        ok = self.free(prim.ink())
                        self.clear = keep
                        if not ok:
                            continue
                    elif not self.free(box):
                        continue
                    end = None
                    if rad > (3.5 if by_ink else LEADER):   # far from its point: a thin leader to the box
                        q = complex(min(max(at.real, box[0]), box[2]), min(max(at.imag, box[1]), box[3]))
                        end = at + (q - at) * (1 - 1.2 / abs(q - at))
                        if not self.free_path(at + (end - at) * min(0.5, 3.0 / abs(end - at)), end,
                                              letters_only=by_ink or not strict) or not self.free_path(at, end, True):
                            continue            # (no leader through a letter, even near its point)
                    self.rec.label((cx - w / 2, cy - size / 2), text, size=size, layer=LAYER)
                    self._add_box(box)
                    if end is not None:
                        seg = self.rec.segment(_f(at), _f(end), role="construction", layer=LAYER, step="leader")
                        self._add(_ink_points(seg))
                    return True
        if optional:                          # a circle's name where five circles crowd: left out
            return False
        self.rec.label((at.real + 2.0, at.imag + 2.0), text, size=full, layer=LAYER)
        return False

    def _add_box(self, box) -> None:
        x0, y0, x1, y1 = box
        xs, ys = np.arange(x0, x1 + 0.4, 0.8).tolist(), np.arange(y0, y1 + 0.4, 0.8).tolist()
        pts = [(x, y) for x in np.arange(x0, x1 + 0.4, 0.4).tolist() for y in (y0, y1)] + \
              [(x, y) for y in np.arange(y0, y1 + 0.4, 0.4).tolist() for x in (x0, x1)] + \
              [(x, y) for x in xs for y in ys]
        self._add(pts)
        self._add(pts, self.letters)


def _ink_points(p) -> list[tuple[float, float]]:
    step = 0.4
    if p.kind in ("segment", "vector", "polyline", "polygon"):
        pts = list(p.points) + ([p.points[0]] if p.kind == "polygon" else [])
        out = []
        half = 0.5 * p.line_width if p.line_width > 0.75 else 0.0   # a line heavier than THICK: its edges
        for a, b in zip(pts[:-1], pts[1:]):
            d = math.hypot(b[0] - a[0], b[1] - a[1])
            n = max(1, int(d / step))
            line = [(a[0] + (b[0] - a[0]) * t / n, a[1] + (b[1] - a[1]) * t / n) for t in range(n + 1)]
            out += line
            if half and d > 0:    # (λ1's 1-mm working part: its label 0.8 mm off the middle touched the edge)
                nx, ny = -(b[1] - a[1]) / d * half, (b[0] - a[0]) / d * half
                out += [(x + sx * nx, y + sx * ny) for x, y in line for sx in (-1.0, 1.0)]
        if p.kind == "vector":                # the arrowhead's filled triangle, wider than the line
            from graphplan.graphic.record import vector_arrow
            tri, _ = vector_arrow(p.points[0], p.points[1], p.line_width, p.role == "head")
            for a, b in ((tri[0], tri[1]), (tri[1], tri[2]), (tri[2], tri[0])):
                n = max(1, int(math.hypot(b[0] - a[0], b[1] - a[1]) / step))
                out += [(a[0] + (b[0] - a[0]) * t / n, a[1] + (b[1] - a[1]) * t / n) for t in range(n + 1)]
        return out
    if p.kind in ("arc", "circle"):
        (cx, cy), r = p.points[0], p.radius
        a0, a1 = (0.0, 360.0) if p.kind == "circle" else p.angles
        sweep = (a1 - a0) % 360.0 or 360.0
        n = max(2, int(math.radians(sweep) * r / step))
        return [(cx + r * math.cos(math.radians(a0 + sweep * t / n)), cy + r * math.sin(math.radians(a0 + sweep * t / n)))
                for t in range(n + 1)]
    if p.kind == "point":
        x, y = p.points[0]
        return [(x, y), (x + 0.6, y), (x - 0.6, y), (x, y + 0.6), (x, y - 0.6)]
    if p.kind == "text":
        x0, y0, x1, y1 = p.bounds()
        return [(x, y) for x in np.arange(x0, x1 + step, step).tolist() for y in (y0, y1)] + \
               [(x, y) for y in np.arange(y0, y1 + step, step).tolist() for x in (x0, x1)]
    return [tuple(q) for q in p.points]


# -- the meshing ------------------------------------------------------------------------------------

@dataclass
class Mesh:
    """The drawn meshing and what was read off it."""
    mu_l: float                     # m/mm
    module_mm: float                # the module as drawn
    precision: float
    drawn: dict[str, float]         # the laid-off lengths, mm: aw, r1, rb1, ra1, rf1, … , pb
    read: dict[str, float]          # the readings, mm: B1B2, rw1, rw2, s1, s2, sa1, sa2 (chords)
    eps: float                      # εα = B1B2/pb, graphically
    eps_bound: float                # its first-order bound from the precision
    s: tuple[float, float]          # m, the chords turned into arcs
    sa: tuple[float, float]
    rw: tuple[float, float]
    record: Record
    lam: Record
    points: dict[str, complex] = field(default_factory=dict)
    warnings: list[tuple[str, str]] = field(default_factory=list)
    sa_bound: tuple[float, float] = (0.0, 0.0)      # m: the bound of each sa read, from the precision
    o1_shown: bool = False          # the pinion's centre drawn under a broken meshing (``centre_shown``)
    lang: str = "uk"                # the lettering's language (the λ diagrams' values: the decimal comma)


def _inv_at(R: float, rho: float) -> float:
    """inv α at the radius ρ of the involute of the base circle R: tg α − α, cos α = R/ρ."""
    a = math.acos(min(1.0, R / rho))
    return math.tan(a) - a


def tip_chord(R: float, r: float, ra: float, chord: float) -> float:
    """The chord across a tooth's tip as the draftsman gets it: the flanks the involutes of the base
    circle R through the ends of the chord ``chord`` laid off on the pitch circle r, cut by the tip
    circle ra — 2·ra·sin(asin(chord/2r) + inv α(r) − inv α(ra)) (the tooth's half angle at the tip)."""
    return 2 * ra * math.sin(math.asin(min(1.0, chord / (2 * r))) + _inv_at(R, r) - _inv_at(R, ra))


def sa_bound(sol: PairSolution, k: int, mu: float, precision: float) -> float:
    """The bound of |sa(graphical) − sa| of wheel k (m) from the drafting precision p: rb, r, ra and
    the chord s laid off and the tip's chord read, each within p/2 (drawing mm), through
    ``tip_chord`` — its worst corner of the four laid-off lengths at ± p/2 plus p/2 read (a thin tip
    of a few teeth moves by a fraction of a millimetre as rb or ra does: review 45's 11-tooth pinion
    with x = 0,6 reads sa +9,8 % off an 8,2-mm chord)."""
    h = precision / 2
    R, r, ra = sol.rb[k] / mu, sol.r[k] / mu, sol.ra[k] / mu
    chord = 2 * r * math.sin(sol.s[k] / (2 * sol.r[k]))
    exact = tip_chord(R, r, ra, chord)
    worst = max(abs(tip_chord(R + a, r + b, ra + c, chord + d) - exact)
                for a, b, c, d in itertools.product((-h, h), repeat=4))
    return (worst + h) * mu


def _extent(sol: PairSolution, md: float, teeth: int = TEETH, o1: bool = True) -> tuple[float, float, float]:
    """The meshing's window about P at the module ``md`` mm (width, height, mm) and the centre
    distance drawn, mm: the circles' arcs over the three teeth and the line of action, N1 and N2,
    the λ diagram's length N1N2 below it (about)."""
    k = md / (sol.pair.module * 1000.0) * 1000.0               # mm of drawing per metre
    aw_, D = sol.alpha_w, sol.aw * k
    tau = [2 * math.pi / z for z in sol.pair.z]
    rb, ra, rf = [v * k for v in sol.rb], [v * k for v in sol.ra], [v * k for v in sol.rf]
    n_x = [rb[0] * math.sin(aw_), rb[1] * math.sin(aw_)]
    half_w = _half_width(n_x, tau, ra, teeth)
    low, high = [], []
    for j, rads in ((0, (rf[0], ra[0])), (1, (rf[1], ra[1]))):
        for rad in rads:
            span = _span(rad, half_w, tau[j], aw_, teeth)
            (low if j == 0 else high).append(rad * math.cos(span) if j == 0 else D - rad * math.cos(span))
    y_lo = min(low + [rb[0] * math.cos(aw_)]) - 8.0
    y_hi = max(high + [D - rb[1] * math.cos(aw_)]) + 8.0
    g = sol.g * k
    if o1 and centre_shown(y_lo):     # O1 drawn under the window instead of the lower break (O1 at y = 0)
        y_lo = min(y_lo, -O1_BELOW)
    return max(2 * half_w + 50.0, g + 30.0), y_hi - y_lo, D       # the letters r_a1 … right, a_w left


O1_NEAR = 30.0                 # mm: the pinion's centre drawn where the window's break would stand this near it
O1_BELOW = 13.0                # mm: the centre line past O1 and its letter


def centre_shown(y_lo: float) -> bool:
    """Whether the broken meshing draws the centre O1 (at y = 0) rather than breaking the centre line
    under the window whose bottom is ``y_lo`` mm: when the break (6 mm under the window) would stand
    within ``O1_NEAR`` of it — stop 48's 12/31 put the break and «↓ O_1» on O1 itself, stop 49's 9/40
    9,5 mm over it: a teacher asks why a centre in reach is broken off."""
    return y_lo - 6.0 <= O1_NEAR


def _half_width(n_x, tau, ra, teeth: int) -> float:
    """Half the window's width about P, mm: N1, N2 and the teeth (``teeth`` of each wheel) with 12 mm."""
    k = teeth / 2 + 0.2
    return max(n_x[0], n_x[1], k * tau[0] * ra[0], k * tau[1] * ra[1]) + 12.0


def most_teeth(sol: PairSolution, md: float, height_mm: float, width_mm: float) -> int:
    """How many teeth of each wheel the meshing drawn with the module ``md`` mm shows in the zone
    ``width_mm`` × ``height_mm``: the most of ``MORE_TEETH`` whose window (the centres shown or the
    centre line broken, as ``mesh_scale`` counts it) fits and whose outer teeth stay within
    ``TEETH_SPAN`` of the centre line on both wheels, else ``TEETH``."""
    for n in MORE_TEETH:
        if any((n / 2 + 0.3) * 2 * math.pi / z > TEETH_SPAN for z in sol.pair.z):
            continue
        w, h, D = _extent(sol, md, n)
        tall = h + 12.0 if broken(sol, md, n) else max(h, D + 30.0)     # (the upper break's 12 mm: either)
        if tall + 20.0 <= height_mm and w <= width_mm:
            return n
    return TEETH


def broken(sol: PairSolution, md: float, teeth: int = TEETH) -> bool:
    """Whether the centres are left off the drawing (the centre line broken, aw dimensioned, as the
    textbook draws wheels whose centres lie far from the teeth): when drawing them would make the
    meshing more than 1.4 times as tall as its window about P."""
    w, h, D = _extent(sol, md, teeth, o1=False)
    return D + 30.0 > 1.4 * h


def mesh_scale(sol: PairSolution, height_mm: float = 480.0, width_mm: float = 780.0,
               line_mm: float | None = None) -> float:
    """The drawn module, mm, at a standard scale (GOST 2.302: 1:5 … 1:1 … 100:1; μl then a round
    number): the largest that draws the whole depth 2.25m 40–60 mm tall and fits the zone
    ``width_mm`` × ``height_mm`` (the window about P, the centres shown or the centre line broken);
    when none draws 40–60 mm, the fitting scale whose depth comes nearest that band (the larger of
    two as near); when none fits, the smallest of the series. ``line_mm``: the longest N1N2 the
    λ diagrams' place takes (they are drawn at the meshing's scale)."""
    m = sol.pair.module * 1000.0                     # mm

    def fits(md: float) -> bool:
        w, h, D = _extent(sol, md)
        tall = h + 12.0 if broken(sol, md) else max(h, D + 30.0)
        return tall + 20.0 <= height_mm and w <= width_mm and (line_mm is None or sol.g * md / m * 1000.0 <= line_mm)

    series = sorted(ENLARGE + REDUCE)
    ok = [k for k in series if fits(m * k)]
    if not ok:
        return m * series[0]
    band = [k for k in ok if DEPTH_MM[0] <= 2.25 * m * k <= DEPTH_MM[1]]
    if band:
        return m * max(band)
    far = lambda k: max(DEPTH_MM[0] / (2.25 * m * k), 2.25 * m * k / DEPTH_MM[1])     # noqa: E731
    return m * min(ok, key=lambda k: (far(k), -k))


SAG = 0.02                     # mm: the largest sagitta of a chord standing for an arc of a profile (no
#                                corner shows at the drawing's scale, review 5 item 19)


def arc_points(r: float, sweep: float, least: int = 3) -> int:
    """Points enough to draw an arc of radius ``r`` mm over ``sweep`` rad as chords of sagitta at
    most ``SAG``: r·(1 − cos(Δ/2)) ≤ SAG, Δ ≤ 2·acos(1 − SAG/r)."""
    if r <= SAG:
        return least
    return max(least, int(math.ceil(abs(sweep) / (2 * math.acos(1 - SAG / r)))) + 1)


def involute_points(R: float, t0: float, t1: float, least: int = 12) -> int:
    """Points enough for the involute of the base circle R from the unrolled length t0 to t1 as
    chords of sagitta at most ``SAG``: its tangent turns by dt/R and its radius of curvature is t, so
    a chord over Δt sags about t·(Δt/R)²/8."""
    dt = R * math.sqrt(8 * SAG / max(t1, 1e-9))
    return max(least, int(math.ceil((t1 - t0) / dt)) + 1)


def _involute(R: float, theta_s: float, t: np.ndarray) -> np.ndarray:
    """Points of the involute of the circle R (centre 0) unrolled from the angle θS: the tangent
    points at θS − t/R, the unrolled length t laid off along each tangent."""
    th = theta_s - t / R
    return R * np.exp(1j * th) + t * 1j * np.exp(1j * th)


def _flank_at(R: float, theta_s: float, radius: float) -> complex:
    """The involute's point at ``radius`` (≥ R)."""
    t = math.sqrt(max(radius * radius - R * R, 0.0))
    return complex(_involute(R, theta_s, np.array([t]))[0])


def _tooth(R: float, theta_s: float, rf: float, ra: float, axis: float, md: float, n: int | None = None) -> list[complex]:
    """One tooth's outline (centre 0), from its left root fillet over the tip to its right one: the
    fillet (radius 0.38m, tangent to the root circle and to the radial line under the involute),
    the radial line to the base circle, the involute to the tip circle, the tip arc, the mirror."""
    start = max(R, rf + 1e-9)
    t0 = math.sqrt(max(start * start - R * R, 0.0))
    t1 = math.sqrt(ra * ra - R * R)
    inv_pts = list(_involute(R, theta_s, np.linspace(t0, t1, n or involute_points(R, t0, t1, 64))))
    beta = cmath.phase(inv_pts[0])
    left: list[complex] = []
    gap = start - rf
    if gap > 1e-6:
        rho = min(FILLET * md, 0.9 * gap)
        d = math.asin(rho / (rf + rho))
        c = (rf + rho) * cmath.exp(1j * (beta + d))
        a_from, a_to = beta + d - math.pi, beta - math.pi / 2
        left += [c + rho * cmath.exp(1j * a) for a in np.linspace(a_from, a_to, arc_points(rho, a_to - a_from, 8))]
    left += inv_pts
    # mirror about the axis: angle a → 2·axis − a
    mirror = [abs(q) * cmath.exp(1j * (2 * axis - cmath.phase(q))) for q in reversed(left)]
    a_left, a_right = cmath.phase(left[-1]), cmath.phase(mirror[0])
    if _wrap(a_left - axis) * _wrap(a_right - axis) >= 0:       # pointed within the tip circle
        return left + mirror
    sweep = _wrap(a_right - a_left)
    tip = [ra * cmath.exp(1j * a) for a in np.linspace(a_left, a_left + sweep, arc_points(ra, sweep, 6))[1:-1]]
    return left + tip + mirror


def _span(rad: float, half_w: float, tau: float, aw_: float, teeth: int = TEETH) -> float:
    """Half the angle of a circle's arc drawn over the window: to the window's side, at most
    teeth/2 + 0.3 pitch angles (1.8 for three teeth; or αw + 10°), rad."""
    return min(math.asin(min(1.0, half_w / rad)), max((teeth / 2 + 0.3) * tau, aw_ + math.radians(10.0)))


def _wrap(a: float) -> float:
    return (a + math.pi) % (2 * math.pi) - math.pi


def aw_decimals(precision: float, mu_l: float) -> int:
    """The decimals of the dimension aw, mm, as Table 1 prints aw (report.gears.length_decimals of
    table_decimals): one past the ruler's resolution on the part, precision·μl, and at least two — the
    lab prints aw to 0,01 mm (stop 46: the dimension said 104,4 mm beside Table 1's 104,37); four at
    precision 0."""
    res = precision * mu_l * 1000.0
    return max(2, 4 if res <= 0 else max(0, math.ceil(-math.log10(res) - 1e-9)) + 1)


def construct_mesh(sol: PairSolution, precision: float = 0.5, lang: str = "uk",
                   height_mm: float = 480.0, module_mm: float | None = None, width_mm: float = 780.0,
                   line_mm: float | None = None, teeth: int = TEETH, o1: bool = True) -> Mesh:
    """The meshing of ``sol`` drawn and read with a ruler of ``precision`` mm (0: exact), the module
    drawn ``module_mm`` long (default: ``mesh_scale``), ``teeth`` teeth of each wheel (odd: the
    middle one of wheel 1 in mesh at P)."""
    pair = sol.pair
    z1, z2 = pair.z
    md = module_mm or mesh_scale(sol, height_mm, width_mm, line_mm)
    mu = pair.module / md                                     # m/mm
    L = lambda v: lay_off(v / mu, precision)                  # noqa: E731   a length laid off
    d = {"aw": L(sol.aw), "r1": L(sol.r[0]), "r2": L(sol.r[1]), "rb1": L(sol.rb[0]), "rb2": L(sol.rb[1]),
         "ra1": L(sol.ra[0]), "ra2": L(sol.ra[1]), "rf1": L(sol.rf[0]), "rf2": L(sol.rf[1]), "pb": L(sol.pb)}
    D, R1, R2 = d["aw"], d["rb1"], d["rb2"]
    if not (d["pb"] > 0 and d["ra1"] > R1 > 0 and d["ra2"] > R2 > 0 and D > R1 + R2 and d["r1"] > 0 and d["r2"] > 0):
        from graphplan.util.errors import GraphplanError
        raise GraphplanError(f"--precision {precision:g} mm: the meshing drawn with the module {md:g} mm long cannot "
                             "be laid off at this precision (its circles and pitch collapse); take a finer one")
    O1, O2 = 0j, 1j * D
    aw_ = math.acos(min(1.0, (R1 + R2) / D))                  # the common tangent's angle
    N1 = R1 * complex(math.sin(aw_), math.cos(aw_))
    N2 = O2 - R2 * complex(math.sin(aw_), math.cos(aw_))
    u = (N2 - N1) / abs(N2 - N1)
    P = 1j * D * R1 / (R1 + R2)                               # where the tangent crosses O1O2
    B1 = circle_line(O2, d["ra2"], N1, u, -1)                  # wheel 2's tip circle, near N1
    B2 = circle_line(O1, d["ra1"], N1, u, +1)                  # wheel 1's tip circle, near N2
    read = {"B1B2": measure(abs(B2 - B1) * (1 if ((B2 - B1) / u).real >= 0 else -1), precision),
            "rw1": measure(abs(P - O1), precision), "rw2": measure(abs(O2 - P), precision)}
    eps = read["B1B2"] / d["pb"]
    rec = Record("meshing")
    # the five circles of each wheel, as arcs over the window of the teeth and the line of action
    tau = (2 * math.pi / z1, 2 * math.pi / z2)
    half_w = _half_width((abs(N1.real), abs(N2.real)), tau, (d["ra1"], d["ra2"]), teeth)
    circles = {1: [("rf", d["rf1"]), ("rb", R1), ("r", d["r1"]), ("rw", read["rw1"]), ("ra", d["ra1"])],
               2: [("rf", d["rf2"]), ("rb", R2), ("r", d["r2"]), ("rw", read["rw2"]), ("ra", d["ra2"])]}
    for k, centre, up in ((1, O1, 1.0), (2, O2, -1.0)):
        for name, rad in circles[k]:
            span = math.degrees(_span(rad, half_w, tau[k - 1], aw_, teeth))
            mid = 90.0 if up > 0 else 270.0
            role = "axis" if name == "r" else "construction"      # the pitch circle dash-dot (GOST 2.402)
            rec.arc(_f(centre), rad, mid - span, mid + span, role=role, layer=LAYER, step=f"circle {name}{k}")
    cut = broken(sol, md, teeth)
    show1 = False
    if cut:          # the centres off the drawing: the centre line broken above and below the window
        wlo = min(N1.imag, min(rad * math.cos(_span(rad, half_w, tau[0], aw_, teeth)) for _, rad in circles[1])) - 8.0
        whi = max(N2.imag, max(D - rad * math.cos(_span(rad, half_w, tau[1], aw_, teeth)) for _, rad in circles[2])) + 8.0
        show1 = o1 and centre_shown(wlo)   # the pinion's centre in reach: drawn, the line broken above only
        low = -8.0 if show1 else wlo - 6.0                   # the centre line's lower end
        for y0, y1 in ((low, wlo), (whi, whi + 6.0)):
            rec.segment((0.0, y0), (0.0, y1), role="axis", layer=LAYER, step="O1O2")
        rec.segment((0.0, wlo), (0.0, whi), role="axis", layer=LAYER, step="O1O2")
        for y in ((whi + 6.0,) if show1 else (wlo - 6.0, whi + 6.0)):   # the break marks (GOST 2.303, a thin zigzag)
            rec.add("polyline", [(-6.0, y), (-1.5, y), (-0.8, y + 2.0), (0.8, y - 2.0), (1.5, y), (6.0, y)],
                    role="construction", layer=LAYER, step="break")
        xd = -half_w - 4.0                                   # aw dimensioned on a broken dimension line
        foot = 0.0 if show1 else wlo - 6.0                   # the dimension's lower end: O1 or the break
        ymid = 0.5 * (foot + whi + 6.0)
        rec.segment((xd - 2.0, foot), (-2.0 if show1 else -8.0, foot), role="construction", layer=LAYER, step="aw")
        rec.segment((xd - 2.0, whi + 6.0), (-8.0, whi + 6.0), role="construction", layer=LAYER, step="aw")
        rec.vector((xd, ymid), (xd, foot), role="construction", layer=LAYER, step="aw")     # one unbroken line
        rec.vector((xd, ymid), (xd, whi + 6.0), role="construction", layer=LAYER, step="aw")
        # the number along the line, over it (left of a vertical line), read from the right (GOST 2.307):
        # mm of the part, no unit
        aw_text = f"a_w = {fixed(sol.aw * 1000.0, lang, aw_decimals(precision, mu))}"
        below = min(0.0, Primitive("text", ((0.0, 0.0),), text=aw_text, size=TEXT).ink()[1])   # w's depth
        rec.label((xd - 1.0 + below, ymid), aw_text, size=TEXT, anchor="middle", layer=LAYER, step="aw", turn=90.0)
        for y, name, toward in (() if show1 else ((wlo - 6.0, "O_1", -1j),)) + ((whi + 6.0, "O_2", 1j),):
            rec.vector((3.0, y + (4.0 if toward == -1j else -4.0)), (3.0, y + (-6.0 if toward == -1j else 6.0)),
                       role="construction", layer=LAYER, step=f"to {name}")
            rec.label((5.0, y + (-6.0 if toward == -1j else 2.5)), name, size=TEXT, layer=LAYER, step=name)
    else:
        rec.segment(_f(O1 - 8j), _f(O2 + 8j), role="axis", layer=LAYER, step="O1O2")
    # the line of action, extended a little past N1 and N2
    rec.segment(_f(N1 - 6 * u), _f(N2 + 6 * u), role="relative", layer=LAYER, step="line of action N1N2")
    rec.segment(_f(P - 30.0), _f(P + 30.0), role="construction", layer=LAYER, step="tangent at P")
    if cut:          # the radii to N1, N2 (perpendicular to the line of action) as far as the window
        rec.segment(_f(N1), _f(O1 if show1 else N1 + (O1 - N1) / abs(O1 - N1) * min(20.0, abs(O1 - N1))),
                    role="construction", layer=LAYER)
        rec.segment(_f(N2), _f(N2 + (O2 - N2) / abs(O2 - N2) * min(20.0, abs(O2 - N2))), role="construction",
                    layer=LAYER)
    else:
        rec.segment(_f(O1), _f(N1), role="construction", layer=LAYER)
        rec.segment(_f(O2), _f(N2), role="construction", layer=LAYER)
    # the involutes by the draftsman's steps, the teeth
    teeth_pts = {}
    s_read, sa_read = [], []
    for k, centre, N, R, r_, rf, ra, z, s_ex in ((1, O1, N1, R1, d["r1"], d["rf1"], d["ra1"], z1, sol.s[0]),
                                                  (2, O2, N2, R2, d["r2"], d["rf2"], d["ra2"], z2, sol.s[1])):
        tP = abs(P - N)
        step = tP / DIVISIONS
        thN = cmath.phase(N - centre)
        theta_s = thN + tP / R                                   # where the involute through P starts
        jmax = int(math.floor(math.sqrt(ra * ra - R * R) / step + 1e-9))   # no mark past the tip circle
        marks = _involute(R, theta_s, step * np.arange(0, jmax + 1))
        for j in range(1, min(jmax, DIVISIONS + 2) + 1):     # the tangents with the unrolled lengths, their ends
            q = R * cmath.exp(1j * (theta_s - j * step / R))
            if j != DIVISIONS:                                 # the fourth is NP itself
                rec.segment(_f(centre + q), _f(centre + marks[j]), role="construction", layer=LAYER,
                            step=f"involute {k}: tangent {j}")
                rec.point(_f(centre + marks[j]), role="construction", layer=LAYER, step=f"involute {k}: mark {j}")
        for j in range(1, DIVISIONS):
            q = N + j * step * (P - N) / tP
            if min(abs(q - B1), abs(q - B2)) > 1.5:       # (on a lettered B1, B2 its dot is theirs)
                rec.point(_f(q), role="construction", layer=LAYER)
        # the tooth thickness laid off as a chord on the pitch circle; the axis between the flanks
        chord = lay_off(2 * (r_ * mu) * math.sin(s_ex / (2 * (r_ * mu))) / mu, precision)
        F = _flank_at(R, theta_s, r_)
        half = math.asin(min(1.0, chord / (2 * r_)))
        axis = cmath.phase(F) - half
        s_read.append(measure(chord, precision))
        A = _flank_at(R, theta_s, ra)
        ha_ = _wrap(cmath.phase(A) - axis)
        sa_read.append(measure(2 * ra * math.sin(ha_) if ha_ > 0 else 0.0, precision))
        one = _tooth(R, theta_s, rf, ra, axis, md)
        outline: list[complex] = []
        for j in range(teeth // 2, -(teeth // 2) - 1, -1):   # counter-clockwise to clockwise, as each tooth runs
            rot = cmath.exp(1j * j * tau[k - 1])
            pts = [q * rot for q in one]
            if outline:                              # the root circle between the teeth
                a0, a1 = cmath.phase(outline[-1]), cmath.phase(pts[0])
                sweep = _wrap(a1 - a0)
                outline += [rf * cmath.exp(1j * (a0 + sweep * t))
                            for t in np.linspace(0, 1, arc_points(rf, sweep, 8))[1:-1]]
            outline += pts
        teeth_pts[k] = (theta_s, axis, R, r_, ra, centre)
        rec.add("polyline", [_f(centre + q) for q in outline], role="link", layer=LAYER, step=f"teeth {k}")
        # the working part of the flank in mesh: from the radius of B1 (wheel 1) or B2 (wheel 2) to the tip
        low = abs((B1 if k == 1 else B2) - centre)
        t_lo = math.sqrt(max(low * low - R * R, 0.0))
        t_hi = math.sqrt(ra * ra - R * R)
        ts = np.linspace(t_lo, t_hi, involute_points(R, t_lo, t_hi, 48))
        wp = _involute(R, theta_s, ts)
        normal = [-1j * cmath.exp(1j * (theta_s - t / R)) for t in ts]
        rec.add("polyline", [_f(centre + q + 0.45 * nrm) for q, nrm in zip(wp, normal)], role="result",
                layer=LAYER, step=f"working part {k}", width=0.9)
    # what Table 1 reads, drawn where it is read (review 5, item 18): s and sa as chords on the pitch
    # and tip circles of each wheel's tooth beside the one at P, p as the arc between like flanks of
    # two teeth on wheel 1's pitch circle, pb laid off on N1N2 from B1, the active part B1B2 bold
    marks = _readings(rec, teeth_pts, tau, B1, B2, u, d["pb"], P, min(2, teeth // 2))
    # the arc of action on the rolling circles
    arc_ends: list[tuple[complex, str, complex]] = []
    for k, centre, rw, R, sign in ((1, O1, read["rw1"], R1, 1.0), (2, O2, read["rw2"], R2, -1.0)):
        base = 90.0 if k == 1 else 270.0
        rhoP, a, b = abs(P - N1), (abs(B1 - N1) if ((B1 - N1) / u).real >= 0 else -abs(B1 - N1)), abs(B2 - N1)
        a0 = base + sign * math.degrees((a - rhoP) / R)
        a1 = base + sign * math.degrees((b - rhoP) / R)
        rr = rw
        rec.arc(_f(centre), rr, min(a0, a1), max(a0, a1), role="relative", layer=LAYER, step=f"arc of action {k}")
        for a_, name in ((a0, "a"), (a1, "b")):                # its ends ticked and lettered a1 b1, a2 b2
            e = cmath.exp(1j * math.radians(a_))
            rec.segment(_f(centre + (rr - 1.5) * e), _f(centre + (rr + 1.5) * e), role="relative", layer=LAYER,
                        step=f"arc of action {k}")
            arc_ends.append((centre + rr * e, f"{name}_{k}", e if k == 1 else -e))
    for q in (N1, N2, B1, B2, P) + ((O1,) if show1 else () if cut else (O1, O2)):
        rec.point(_f(q), role="pole", layer=LAYER)
    pl = Placer(rec)
    if not cut or show1:
        pl.label(O1, "O_1", toward=1 + 0j if cut else -1 + 0j)     # (a_w's dimension left of O1 when broken)
    if not cut:
        pl.label(O2, "O_2", toward=-1 + 0j)
    pl.label(P, "P", toward=1 + 0.3j, near=True)
    pl.label(N1, "N_1", toward=1 + 0j, near=True)
    pl.label(N2, "N_2", toward=-1 + 0j, near=True)
    pl.label(B1, "B_1", toward=-1j * u, near=True)
    pl.label(B2, "B_2", toward=1j * u, near=True)
    for at, name, out in marks:
        pl.label(at, name, size=2.5, toward=out, radii=(1.0, 2.0, 3.5, 5.5, 9.0, 13.0), near=True)
    for at, name, out in arc_ends:
        pl.label(at, name, size=2.5, toward=out, radii=(1.0, 2.0, 3.5, 5.5, 9.0, 13.0), optional=True)
    alpha_w_mark(rec, pl, P, aw_)
    for k, centre in ((1, O1), (2, O2)):
        for name, rad in circles[k]:
            ang = _span(rad, half_w, tau[k - 1], aw_, teeth)
            end = centre + rad * cmath.exp(1j * ((math.pi / 2 - ang) if k == 1 else (-math.pi / 2 + ang)))
            sub = {"rf": "f", "rb": "b", "r": "", "rw": "w", "ra": "a"}[name]
            pl.label(end, f"r_{sub}{k}" if sub else f"r_{k}", size=2.5, toward=1 + 0j,
                     radii=(1.0, 2.0, 3.5, 5.5, 9.0, 13.0), optional=True)
    rec.scales.update(mu_l=mu)
    # readings in SI
    s_g = tuple(2 * (rr * mu) * math.asin(min(1.0, c / (2 * rr))) for c, rr in zip(s_read, (d["r1"], d["r2"])))
    sa_g = tuple(2 * (rr * mu) * math.asin(min(1.0, c / (2 * rr))) for c, rr in zip(sa_read, (d["ra1"], d["ra2"])))
    read.update(s1=s_read[0], s2=s_read[1], sa1=sa_read[0], sa2=sa_read[1])
    mesh = Mesh(mu, md, precision, d, read, eps, eps_bound(sol, mu, precision), (s_g[0], s_g[1]), (sa_g[0], sa_g[1]),
                (read["rw1"] * mu, read["rw2"] * mu), rec, Record("sliding"),
                {"O1": O1, "O2": O2, "N1": N1, "N2": N2, "B1": B1, "B2": B2, "P": P},
                sa_bound=(sa_bound(sol, 0, mu, precision), sa_bound(sol, 1, mu, precision)), o1_shown=show1,
                lang=lang)
    if 2.25 * md < DEPTH_MM[0]:
        mesh.warnings.append((f"the meshing is drawn with the whole depth {2.25 * md:.4g} mm (no standard scale "
                              "that fits the zone draws it 40–60 mm tall)",
                              f"зачеплення накреслено з висотою зуба {format(2.25 * md, '.4g').replace('.', ',')} мм (жоден стандартний масштаб, "
                              "що вміщується в зону, не дає 40–60 мм)"))
    mesh.lam = sliding_diagram(sol, mesh)
    return mesh


ALPHA_W_ARC = (8.0, 40.0)       # mm: the radius of αw's arc, least and most


def in_angle(q: complex, P: complex, aw_: float, side: int, margin: float) -> bool:
    """Whether ``q`` lies inside the angle of mesh at P, ``margin`` mm clear of both its sides: left
    of P between the tangent t–t and the line of action rising to N2 (``side`` 1), or the vertically
    opposite angle right of P under the tangent (``side`` −1) — the same angle αw."""
    v = side * (q - P)
    d = cmath.exp(1j * (math.pi - aw_))                # the line of action's direction toward N2
    return v.real < 0 and v.imag >= margin and (d.conjugate() * v).imag >= margin


def alpha_w_mark(rec: Record, pl: "Placer", P: complex, aw_: float, size: float = TEXT) -> tuple[complex, int] | None:
    """The angle of mesh αw marked at P as the textbook marks it: an arc between the tangent t–t and the
    line of action and the letter α_w inside the angle (stop 49: the letter stood outside it, the spots
    inside crossed by p_b's dimension). The letter at the first spot inside the angle — left of P over
    the tangent, else the vertically opposite angle right of P under it — whose box, ``pl``'s clearance
    round it, holds no ink and stays 0.6 mm inside both sides; the arc then just inside the letter (just
    outside it where that arc would be shorter than ``ALPHA_W_ARC``'s least), clear of every letter.
    The letter's size ``size``, 2,5 mm (GOST 2.304's least) where no spot holds it. (The letter's centre,
    the side) or None when no spot is free (the arc alone at 22 mm, left of P)."""
    for size, side in ((size, 1), (size, -1), (2.5, 1), (2.5, -1)):
        w = text_width("α_w", size)
        for rho in np.arange(6.0, 60.0, 1.0):
            for t in (0.5, 0.4, 0.6, 0.3, 0.7):
                c = P + side * rho * cmath.exp(1j * (math.pi - t * aw_))
                prim = Primitive("text", ((c.real - w / 2, c.imag - size / 2),), text="α_w", size=size)
                x0, y0, x1, y1 = prim.bounds()
                corners = (complex(x0, y0), complex(x0, y1), complex(x1, y0), complex(x1, y1))
                if not all(in_angle(q, P, aw_, side, 0.6) for q in corners):
                    continue
                keep, pl.clear = pl.clear, NEAR_CLEAR       # the glyphs' ink clear of the lines, as a point's
                ok = pl.free(prim.ink())                    # letter near it (``Placer.label``'s ``near``)
                pl.clear = keep
                if not ok:
                    continue
                near, far = min(abs(q - P) for q in corners), max(abs(q - P) for q in corners)
                radius = near - 1.5 if near - 1.5 >= ALPHA_W_ARC[0] else far + 1.5
                if radius > ALPHA_W_ARC[1]:
                    continue
                a0 = 180.0 - math.degrees(aw_) if side == 1 else 360.0 - math.degrees(aw_)
                arc = Primitive("arc", (_f(P),), radius=radius, angles=(a0, a0 + math.degrees(aw_)))
                if not all(pl.free((x, y, x, y), pl.letters) for x, y in _ink_points(arc)):
                    continue
                drawn = rec.arc(_f(P), radius, a0, a0 + math.degrees(aw_), role="construction", layer=LAYER,
                                step="αw")
                pl._add(_ink_points(drawn))
                rec.label((c.real - w / 2, c.imag - size / 2), "α_w", size=size, layer=LAYER, step="αw")
                pl._add_box(prim.bounds())
                return c, side
    arc = rec.arc(_f(P), 22.0, 180.0 - math.degrees(aw_), 180.0, role="construction", layer=LAYER, step="αw")
    pl._add(_ink_points(arc))             # (a crowded small meshing, A3's 2,5:1: the letter by its arc, as near
    pl.label(P + 24 * cmath.exp(1j * (math.pi - aw_ / 2)), "α_w", toward=-1 + 0j)   # as it goes — never left out)
    return None


def dimension(rec: Record, a: complex, b: complex, step: str) -> None:
    """A thin dimension line from a to b with an arrowhead at each end (GOST 2.307)."""
    rec.segment(_f(a), _f(b), role="construction", layer=LAYER, step=step)
    n = abs(b - a)
    if n <= 0:
        return
    head = min(2.5, 0.4 * n) * (b - a) / n
    rec.vector(_f(a + head), _f(a), role="head", layer=LAYER, step=step)
    rec.vector(_f(b - head), _f(b), role="head", layer=LAYER, step=step)


def arc_dimension(rec: Record, centre: complex, r: float, a0: float, a1: float, step: str) -> None:
    """A thin dimension arc of radius r about ``centre`` from the angle a0 to a1 (rad, a0 < a1) with
    an arrowhead at each end."""
    from graphplan.graphic.record import arc_head
    rec.arc(_f(centre), r, math.degrees(a0), math.degrees(a1), role="construction", layer=LAYER, step=step)
    for end, sense in ((a1, 1), (a0, -1)):
        tail, tip = arc_head(centre, r, math.degrees(end), sense, length=2.5)
        rec.vector(tail, tip, role="head", layer=LAYER, step=step)


def _readings(rec: Record, teeth_pts: dict, tau, B1: complex, B2: complex, u: complex, pb: float,
              P: complex, j: int = 1) -> list[tuple[complex, str, complex]]:
    """The constructions Table 1 reads, drawn and their letters' anchors returned (anchor, letter,
    the side to put it): on each wheel's ``j``-th tooth counter-clockwise from the one at P (left of
    P on wheel 1, right on wheel 2; the second where five or seven are drawn, clear of P's lines)
    the chord s on the pitch circle and sa on the tip circle (a dimension 4 mm outside the tip on
    extension lines), p on wheel 1's pitch circle as the arc between like flanks of that tooth and
    the one before it (a dimension arc 6 mm inside on extension lines), pb laid off on N1N2 from B1 (ticks and a dimension 6 mm off the line), B1B2
    the active part of the line of action, bold."""
    out: list[tuple[complex, str, complex]] = []
    for k in (1, 2):
        theta_s, axis, R, r_, ra, centre = teeth_pts[k]
        rot = cmath.exp(1j * j * tau[k - 1])                 # the j-th tooth, counter-clockwise
        F = _flank_at(R, theta_s, r_)
        M = abs(F) * cmath.exp(1j * (2 * axis - cmath.phase(F)))
        a, b = centre + F * rot, centre + M * rot
        dimension(rec, a, b, f"s{k}")
        outward = cmath.exp(1j * (axis + j * tau[k - 1]))   # the tooth's axis, from its centre out
        out.append((0.5 * (a + b), f"s_{k}", -outward))
        A = _flank_at(R, theta_s, ra)
        half = _wrap(cmath.phase(A) - axis)
        if half > 0:
            A2 = abs(A) * cmath.exp(1j * (2 * axis - cmath.phase(A)))
            a, b = centre + A * rot, centre + A2 * rot
            off = 4.0 * outward
            for q in (a, b):
                rec.segment(_f(q + 0.8 * outward), _f(q + off + 1.5 * outward), role="construction", layer=LAYER,
                            step=f"sa{k}")
            dimension(rec, a + off, b + off, f"sa{k}")
            out.append((0.5 * (a + b) + off, f"s_a{k}", outward))
        if k == 1:                                           # p: from tooth j − 1's flank to tooth j's
            f0, f1 = F * rot * cmath.exp(-1j * tau[0]), F * rot
            a0, a1 = cmath.phase(f0), cmath.phase(f1)
            rp = r_ - 6.0
            for q in (f0, f1):
                e = q / abs(q)
                rec.segment(_f(centre + (r_ - 1.0) * e), _f(centre + (rp - 1.5) * e), role="construction",
                            layer=LAYER, step="p")
            arc_dimension(rec, centre, rp, min(a0, a1), max(a0, a1), "p")
            mid = cmath.exp(1j * 0.5 * (a0 + a1))
            out.append((centre + rp * mid, "p", -mid))
    # pb laid off on N1N2 from B1 toward B2: ticks square to the line, the dimension 6 mm off it on the
    # side of the angle of mesh right of P under the tangent, so that the angle left of P over it is
    # clear for αw's letter (stop 49: the dimension crossed it, the letter stood outside its angle)
    n = -1j * u                      # the line's normal toward the tangent's right half
    E = B1 + pb * u
    for q in (B1, E):
        rec.segment(_f(q + 1.5 * n), _f(q + 7.5 * n), role="construction", layer=LAYER, step="pb")
    dimension(rec, B1 + 6.0 * n, E + 6.0 * n, "pb")
    out.append((B1 + 0.25 * (E - B1) + 6.0 * n, "p_b", n))      # lettered near B1, clear of P
    rec.segment(_f(B1), _f(B2), role="result", layer=LAYER, step="active part B1B2", width=0.9)
    return out


def eps_bound(sol: PairSolution, mu: float, precision: float) -> float:
    """The bound of |εα(graphical) − εα| (absolute, εα has no unit) from the drafting precision p:
    aw, rb1, rb2, ra1, ra2, pb laid off and B1B2 read, each within p/2 (drawing mm), through
    εα = B1B2/pb with B1B2 = e1 + e2 − √(aw² − R²), e_k = √(ra_k² − rb_k²), R = rb1 + rb2.

    First order: (p/2)/pb·[1 + ra1/e1 + ra2/e2 + |R/G − rb1/e1| + |R/G − rb2/e2| + aw/G + εα]
    (G = N1N2); the margin: the formula evaluated at every corner of the seven lengths at ± p/2 (the
    ratio is monotone in each length over so small a box, so its worst corner is the worst case to
    every order); the larger of the two is stated."""
    h = precision / 2
    ra, rb = [v / mu for v in sol.ra], [v / mu for v in sol.rb]
    e = [math.sqrt(ra[k] ** 2 - rb[k] ** 2) for k in (0, 1)]
    G, R, D, pb = sol.g / mu, (rb[0] + rb[1]), sol.aw / mu, sol.pb / mu
    terms = 1 + ra[0] / e[0] + ra[1] / e[1] + abs(R / G - rb[0] / e[0]) + abs(R / G - rb[1] / e[1]) + D / G + abs(sol.eps)
    first = h / pb * terms
    worst = 0.0
    for sg in itertools.product((-h, h), repeat=7):
        d_, r1, r2, a1, a2, p_ = D + sg[0], rb[0] + sg[1], rb[1] + sg[2], ra[0] + sg[3], ra[1] + sg[4], pb + sg[5]
        if min(a1 - r1, a2 - r2, d_ - r1 - r2, p_) <= 0:
            return math.inf                 # the precision as coarse as the drawing: no bound
        b = math.sqrt(a1 * a1 - r1 * r1) + math.sqrt(a2 * a2 - r2 * r2) - math.sqrt(d_ * d_ - (r1 + r2) ** 2)
        worst = max(worst, abs((b + sg[6]) / p_ - sol.eps))
    return max(first, worst)


LAMBDA_LINE = 200.0            # mm: N1N2 drawn at most this long under the λ diagrams (two curves)


def lambda_mu(sol: PairSolution, mu_l: float) -> float:
    """The λ diagrams' abscissa scale, m/mm: the meshing's ``mu_l`` where N1N2 drawn at it is at most
    ``LAMBDA_LINE``, else the largest GOST 2.302 scale at which it is (review 12, mark 22: N1N2 =
    48,58 mm at the meshing's 5:1 made a 300 × 220 mm zone for two curves; at 4:1 it is 194 mm). The
    caption states it, as the meshing's: the abscissa is a length along N1N2 of the part."""
    if sol.g / mu_l <= LAMBDA_LINE + 1e-9:
        return mu_l
    fit = [k for k in ENLARGE + REDUCE if sol.g * 1000.0 * k <= LAMBDA_LINE + 1e-9]
    return 0.001 / max(fit) if fit else mu_l


def sliding_diagram(sol: PairSolution, mesh: Mesh, unit_mm: float = LAMBDA_MM, mu_x: float | None = None) -> Record:
    """λ1 and λ2 over N1N2 drawn horizontally at ``mu_x`` m/mm (``lambda_mu``: the meshing's scale, or a
    smaller standard one where N1N2 would be longer than ``LAMBDA_LINE``), λ at ``unit_mm`` a unit (20 mm
    unless the sheet grows it): the ordinates at B1, P, B2; each curve thin over N1N2 and heavy over
    the working part B1B2 (the lab draws the working part heavy, review 10 mark 15); cut where it
    passes λ = −3 (λ1 → −∞ at N1, λ2 at N2) with a break: a short arrow on down and "−∞"."""
    rec = Record("sliding")
    mu = mu_x if mu_x is not None else lambda_mu(sol, mesh.mu_l)
    G = sol.g / mu
    z1, z2 = sol.pair.z
    c = LAMBDA_CLIP
    # where each curve reaches −c: λ1 = 1 − (G − ρ)/ρ·z1/z2 = −c at ρ = G·z1/(z1 + (1 + c)·z2);
    # λ2 = 1 − ρ/(G − ρ)·z2/z1 = −c at ρ = G·(1 + c)·z1/((1 + c)·z1 + z2)
    cut1 = G * z1 / (z1 + (1 + c) * z2)
    cut2 = G * (1 + c) * z1 / ((1 + c) * z1 + z2)
    k = unit_mm
    rec.segment((-4.0, 0.0), (G + 8.0, 0.0), role="construction", width=0.35, layer=LAYER, step="λ axis")   # a diagram's
    rec.segment((0.0, -c * k - 3), (0.0, k + 8.0), role="construction", width=0.35, layer=LAYER)  # axes: solid
    xB1, xB2 = sol.rho_B1 / mu, sol.rho_B2 / mu
    q = {"sliding_ends": (float(sol.sliding(sol.rho_B1)[0]), float(sol.sliding(sol.rho_B2)[1]))}   # λ1(B1), λ2(B2)
    # (to Table 2's decimals: four significant figures of the smaller, report.gears.alike)
    q["decimals"] = max([max(0, 3 - math.floor(math.log10(abs(v)))) for v in q["sliding_ends"]
                         if math.isfinite(v) and v] or [0])
    ends = []
    for idx, (lo, hi, name) in enumerate(((cut1, G, "λ_1"), (0.0, cut2, "λ_2"))):
        xs = np.linspace(lo, hi, 401)
        ys = sol.sliding(xs * mu)[idx] * k
        ok = np.isfinite(ys)
        rec.add("polyline", list(zip(xs[ok], ys[ok])), role="curve", layer=LAYER, step=f"{name}(ρ)")
        a, b = max(lo, xB1), min(hi, xB2)                  # the working part, heavy
        if b > a:
            xw = np.linspace(a, b, 201)
            yw = sol.sliding(xw * mu)[idx] * k
            okw = np.isfinite(yw)
            rec.add("polyline", list(zip(xw[okw], yw[okw])), role="result", width=1.0, layer=LAYER,
                    step=f"{name} on B1B2")
        ends.append(complex(cut1 if idx == 0 else cut2, -c * k))
    for v in (1.0, -1.0, -2.0, -3.0):
        rec.segment((-1.5, v * k), (1.5, v * k), role="construction", layer=LAYER)
    marks = {"N_1": 0.0, "B_1": xB1, "P": sol.rho_P / mu, "B_2": xB2, "N_2": G}
    for name, x in marks.items():
        if name in ("B_1", "B_2", "P"):
            rec.segment((x, -c * k), (x, k + 4.0), role="projection", layer=LAYER, step=name)
    rec.segment((G, -c * k), (G, k + 4.0), role="construction", layer=LAYER)
    for end in ends:                  # the break: the curve goes on to −∞ (its asymptote N1 or N2)
        rec.vector(_f(end), _f(end - 6j), role="curve", layer=LAYER, step="λ → −∞")
    pl = Placer(rec)
    for name, x in marks.items():
        pl.label(complex(x, 0), name, size=2.5, toward=-1j, radii=(1.0, 2.0, 3.0, 5.0, 9.0, 13.0))
    for v, t in ((1.0, "1"), (-1.0, "−1"), (-2.0, "−2"), (-3.0, "−3")):
        pl.label(complex(-1.5, v * k), t, size=2.5, toward=-1 + 0j, radii=(0.8, 1.5, 3.0, 6.0))
    pl.label(complex(0.0, k + 8.0), "λ", size=3.5, toward=1j, radii=(1.0, 2.0, 4.0))     # the ordinate's name
    pl.label(complex(G + 8.0, 0.0), "ρ", size=3.5, toward=1j, radii=(1.0, 2.0, 4.0))   # the abscissa's (stop 46)
    for idx, end in enumerate(ends):  # "−∞" right of each arrow: off the axis of λ and the ordinate at B2 —
        # or, where the working part itself passes the cut (λ1 at B1 under −3: stop 51's 18/72, −8,27), the
        # value at its end, λ1(B1) or λ2(B2), which Table 2 prints: the arrow is not −∞ there
        past = ((xB1 < cut1) if idx == 0 else (xB2 > cut2)) and math.isfinite(q["sliding_ends"][idx])
        text = (f"λ_{idx + 1}(B_{idx + 1}) = " + fixed(q["sliding_ends"][idx], mesh.lang, q["decimals"]).replace("-", "−")
                if past else "−∞")
        pl.label(end - 4j, text, size=2.5, toward=1 + 0j, radii=(0.8, 1.5, 3.0, 5.0, 8.0, 12.0))
    # each curve lettered midway between P (where the two cross, λ = 0) and its own end of N1N2:
    # λ2 over N1P (λ1 runs off to −∞ there), λ1 over PN2 — never at the crossing
    xP = sol.rho_P / mu
    for idx, x, name in ((0, 0.5 * (xP + G), "λ_1"), (1, 0.5 * xP, "λ_2")):
        y = float(sol.sliding(x * mu)[idx]) * k
        pl.label(complex(x, y), name, toward=1j, radii=(1.5, 3.0, 5.0, 8.0, 12.0))
    rec.scales.update(mu_lambda=1.0 / k, mu_l=mu)
    return rec


# -- the planetary train ---------------------------------------------------------------------------

@dataclass
class Velocities:
    """The train's scheme, velocity picture and plan of angular velocities, and their readings."""
    mu_l: float
    mu_v: float
    h: float
    precision: float
    heights: dict[str, float]       # laid off, mm: A (r1), O2 (aw), C (the ring's contact)
    va_mm: float
    segments: dict[str, float]      # read off the plan of angular velocities, mm (signed)
    omega: dict[str, float]         # rad/s, graphically
    ratio: float
    ratio_bound: float
    record: Record
    h_carrier: float | None = None  # the carrier's own pole distance h_H, mm (its ray from p'_ω), or None

    @property
    def mu_omega(self) -> float:
        """The plan of angular velocities' scale, (rad/s)/mm: μω = μv/(μl·h) (ωi = segment·μω)."""
        return self.mu_v / (self.mu_l * self.h)

    @property
    def mu_omega_carrier(self) -> float:
        """The carrier's scale, (rad/s)/mm: μv/(μl·h_H) where it has its own pole, else μω."""
        return self.mu_v / (self.mu_l * (self.h_carrier or self.h))


MU_OMEGA = {"uk": "μ_ω = μ_v/(μ_l·h) = {v} (рад/с)/мм", "en": "μ_ω = μ_v/(μ_l·h) = {v} (rad/s)/mm"}
MU_OMEGA_H = {"uk": "μ'_ω = μ_v/(μ_l·h_H) = {v} (рад/с)/мм", "en": "μ'_ω = μ_v/(μ_l·h_H) = {v} (rad/s)/mm"}
SEGMENT_MIN = 20.0      # mm: a plan's segment shorter than this reads worse than ±1,25 % (the ruler's 0,25 mm)


def mu_omega_text(mu_omega: float, lang: str) -> str:
    """The plan of angular velocities' scale as the lab writes it under the plan, to four significant
    figures (a segment of 200 mm × its rounding is within 0,01 %, under the ruler's half-millimetre)."""
    return MU_OMEGA[lang].format(v=num(mu_omega, lang, 4))


ROUND_OMEGA = (1.0, 1.25, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0)   # μω's round values × 10^k, (rad/s)/mm
H_RANGE = (20.0, 150.0)         # mm: the pole distance h of the plan of angular velocities
H_CARRIER = 200.0               # mm: the carrier's own pole distance h_H at most


def pole_distances(ratio: float, least: float = H_RANGE[0], most: float = H_RANGE[1]) -> list[float]:
    """The pole distances h (mm, ascending, ``least`` … ``most``) whose scale μω = μv/(μl·h) — ``ratio``
    = μv/μl, (m/s)/m — is a round value (``ROUND_OMEGA`` × 10^k: 0,5 (рад/с)/мм, not the 0,4762 of
    h = 42 mm) and which the ruler lays off (a whole or half millimetre): h = ratio/μω."""
    k0 = math.floor(math.log10(ratio / max(most, 1.0))) - 1
    hs = {ratio / float(f"{m:g}e{k}") for k in range(k0, k0 + 6) for m in ROUND_OMEGA}
    return sorted(float(round(2.0 * h) / 2.0) for h in hs
                  if max(least, 1.0) - 1e-9 <= h <= most + 1e-9 and abs(2.0 * h - round(2.0 * h)) < 1e-6)


def pole_distance(ratio: float, want: float, least: float = H_RANGE[0], most: float = H_RANGE[1]) -> float:
    """The longest of ``pole_distances`` not longer than ``want`` (the plan no larger than asked), the
    shortest where none is; ``want`` itself rounded (μω then not round) where the range holds none."""
    ok = pole_distances(ratio, least, most)
    if not ok:
        return float(min(most, max(least, round(want))))
    below = [h for h in ok if h <= want + 1e-9]
    return max(below) if below else ok[0]


def _nice(v: float) -> float:
    from graphplan.graphic.scales import at_least
    return at_least(v)


def construct_train(tr: TrainSolution, precision: float = 0.5, lang: str = "uk", ring_mm: float = 80.0,
                    sun_segment_mm: float = 100.0, va_mm: float = 60.0, h_carrier: float | None = None,
                    full: bool = False) -> Velocities:
    """The scheme at μl (the ring's radius about ``ring_mm``, μl the next round value of the series
    1, 2, 2.5, 4, 5·10ⁿ), the velocity picture with vA about ``va_mm`` (μv round likewise), the plan of
    angular velocities with h chosen so the sun's segment is about ``sun_segment_mm``.
    ``h_carrier`` (mm, longer than h): the carrier's ray drawn from a pole p'_ω of its own on h
    produced, h_H below the plan's line — as any pole distance serves a plan of angular velocities
    (ω = segment·μv/(μl·h)), the slow carrier of a large ratio gets one that makes its segment
    readable (review 13 #9: ωH off 3,8 mm, +5,54 %) while the sun's ray keeps the sheet's width;
    then ωH = segment·μv/(μl·h_H) and u1H = (s1/h)/(sH/h_H).
    ``full``: the scheme over and under the central axis (both planets, the carrier across them, the
    ring's frame on both sides), the plan of angular velocities then under the velocity picture, right
    of the scheme's lower half; else the scheme over the axis alone (the half-section), the plan under
    it from its left end (stop 57: the full scheme where the sheet holds it at the same scale)."""
    rad = tr.radii
    kind = tr.train.kind
    mu = _nice(rad["3"] / ring_mm)                          # m/mm
    L = lambda v: lay_off(v / mu, precision)                 # noqa: E731
    yA, yO2 = L(rad["1"]), L(rad["H"])
    yC = L(rad["3"])
    if not 0 < yA < yO2 < yC:
        from graphplan.util.errors import GraphplanError
        raise GraphplanError(f"--precision {precision:g} mm: the train's radii drawn at μl = {mu:g} m/mm "
                             "collapse (r1, aw, r3 read the same); take a finer precision")
    vA = tr.omega["1"] * rad["1"]
    mu_v = _nice(vA / va_mm)
    va = lay_off(vA / mu_v, precision)
    h = pole_distance(mu_v / mu, sun_segment_mm * yA / va)          # μω = μv/(μl·h) round (review 48)
    hH = float(round(2.0 * h_carrier) / 2.0) if h_carrier is not None else None   # (the caller's: μ'ω round
    hH = hH if hH is not None and hH > h else None                                   # where it can be)
    v_o2 = va * (yC - yO2) / (yC - yA)                       # on the planet's line, at the axis' height
    slopes = {"1": va / yA, "2": va / (yA - yC), "H": v_o2 / yO2, "3": 0.0}
    dist = {k: (hH if k == "H" and hH else h) for k in slopes}     # each ray's pole distance
    seg = {k: measure(dist[k] * s, precision) for k, s in slopes.items()}
    omega = {k: seg[k] * mu_v / (mu * dist[k]) for k in seg}
    ratio = (seg["1"] / h) / (seg["H"] / dist["H"]) if seg["H"] else math.nan
    rec = Record("planetary")
    starts = _scheme(rec, tr, mu, yA, yO2, yC, full)
    # the velocity picture: the radii on one vertical line right of the scheme — midway along the room the
    # plan of angular velocities leaves right of the scheme, where the plan is the wider (stop 50: the
    # picture stood against the scheme, a 100–200 × 155-mm blank right of it over the plan's long rays)
    X0 = max(60.0, rec.bounds()[2] + 16.0)
    xs = [dist[k] * s for k, s in slopes.items()]
    xp = min(X0, (under_axis_right(rec) + 10.0) if full else (rec.bounds()[0] + 6.0)) - min(0.0, min(xs)) + 4.0
    #                                     (the plan's pole, as below)
    tip = lambda p, q: (q + (q - p) / abs(q - p) * 14.0).real           # noqa: E731   a line's end, x
    wide = max(tip(0j, complex(va, yA)), tip(complex(0.0, yC), complex(va, yA)),
               tip(0j, complex(v_o2, yO2))) + 10.0                      # the picture's width, its letters too
    X0 += max(0.0, 0.5 * (xp + max(xs + [0.0]) + 6.0 - (X0 + wide)))
    rec.segment((X0, -4.0), (X0, yC + 8.0), role="axis", layer=LAYER, step="radii")
    for y, x in zip((yA, yO2, yC), starts):     # from the scheme's points A, O2, C across
        rec.segment((x, y), (X0, y), role="projection", layer=LAYER)
    a = complex(X0 + va, yA)
    o2 = complex(X0 + v_o2, yO2)
    C = complex(X0, yC)
    O = complex(X0, 0.0)
    rec.vector(_f(complex(X0, yA)), _f(a), role="absolute", layer=LAYER, step="vA = ω1·r1")
    rec.vector(_f(complex(X0, yO2)), _f(o2), role="absolute", layer=LAYER, step="vO2")
    run = lambda p, q, mm: q + (q - p) / abs(q - p) * mm           # noqa: E731   q, then mm further from p
    end1 = run(O, a, 14.0)
    rec.segment(_f(O), _f(end1), role="relative", layer=LAYER, step="line 1")
    low = run(C, a, 14.0)
    rec.segment(_f(C), _f(low), role="relative", layer=LAYER, step="line 2")
    endH = run(O, o2, 14.0)
    rec.segment(_f(O), _f(endH), role="relative", layer=LAYER, step="line H")
    for q in (a, o2, C, O):
        rec.point(_f(q), role="pole", layer=LAYER)
    # the plan of angular velocities below: a horizontal, the pole h under it
    y0 = -26.0
    # the plan under the scheme and the velocity picture from the scheme's left end (``full``: from the right
    # of the scheme's half under the axis, under the velocity picture), not from the
    # picture's axis: the sun's segment then takes the pictures' whole width — review 13 #9, an A3
    # set's plan 90 mm wide under a 230-mm picture read ωH off 2,5 mm): ``xp`` above
    left, right = xp + min(xs + [0.0]) - 6.0, xp + max(xs + [0.0]) + 6.0
    xd = left - 4.0                       # h_H's dimension line, left of the plan
    rec.segment((xd - 2.0 if hH else left, y0), (right, y0), role="construction", layer=LAYER, step="plan of ω")
    pole = complex(xp, y0 - h)
    poles = {k: (complex(xp, y0 - hH) if hH and k == "H" else pole) for k in slopes}
    rec.point(_f(pole), role="pole", layer=LAYER)
    rec.segment(_f(pole), (xp, y0), role="construction", layer=LAYER, step="h")
    if hH:                                # h produced to the carrier's pole, its length dimensioned
        rec.segment(_f(poles["H"]), _f(pole), role="construction", layer=LAYER, step="h_H")
        rec.point(_f(poles["H"]), role="pole", layer=LAYER)
        rec.segment(_f(poles["H"]), (xd - 2.0, y0 - hH), role="construction", layer=LAYER, step="h_H extension")
        dimension(rec, complex(xd, y0), complex(xd, y0 - hH), "h_H dimension")
    for k, s in slopes.items():
        if k != "3":      # the fixed ring's ray (ω3 = 0) is h itself: its point the foot of h
            rec.segment(_f(poles[k]), (xp + dist[k] * s, y0), role="ray", layer=LAYER, step=f"ray {k}")
        rec.point((xp + dist[k] * s, y0), role="pole", layer=LAYER, step=f"point {k}")
    pl = Placer(rec)
    names = {"1": "1", "2": "2" if kind == "A" else "2, 2'", "H": "H", "3": "3"}
    for k, s in slopes.items():      # every point lettered, the ring's 3 (ω = 0) too
        pl.label(complex(xp + dist[k] * s, y0), names[k], size=TEXT, toward=1j, radii=(1.0, 2.0, 3.5, 5.5, 9.0, 13.0))
    pl.label(pole, "p_ω", toward=-1 + 0j)
    pl.label(complex(xp, y0 - h / 2), "h", toward=1 + 0j, radii=(1.0, 2.0, 3.0, 6.0))
    if hH:
        pl.label(poles["H"], "p'_ω", toward=1 + 0j)
        pl.label(complex(xd, y0 - hH / 2), "h_H", toward=-1 + 0j, radii=(1.0, 2.0, 3.0))
    pl.label(end1, "1", toward=end1 - a, radii=(1.0, 2.0, 3.5, 5.5))     # the lines' numbers at their ends,
    pl.label(low, names["2"], toward=low - a, radii=(1.0, 2.0, 3.5, 5.5))  # far from a's letter
    pl.label(endH, "H", toward=endH - o2, radii=(1.0, 2.0, 3.5, 5.5))
    pl.label(a, "a", toward=1 + 0j)
    pl.label(o2, "o_2", toward=1 + 0j)
    pl.label(C, "c", toward=1j)
    pl.label(O, "o", toward=-1j)
    pl.label(complex(X0 + va / 2, yA), "v_A", size=3.5, toward=1j, radii=(0.8, 1.5, 3.0, 5.0, 9.0))
    pl.label(complex(X0 + v_o2 / 2, yO2), "v_{O_2}", size=3.5, toward=1j, radii=(0.8, 1.5, 3.0, 5.0, 9.0))
    _mu_omega_label(rec, pl, pole, left, right, mu_omega_text(mu_v / (mu * h), lang))
    rec.scales.update(mu_l=mu, mu_v=mu_v, h=h, mu_omega=mu_v / (mu * h))
    if hH:
        _mu_omega_label(rec, pl, poles["H"] + 10.0, xd - 2.0, right,      # (clear of p'_ω's letter)
                        MU_OMEGA_H[lang].format(v=num(mu_v / (mu * hH), lang, 4)))
        rec.scales.update(h_H=hH, mu_omega_H=mu_v / (mu * hH))
    out = Velocities(mu, mu_v, h, precision, {"A": yA, "O2": yO2, "C": yC}, va, seg, omega, ratio,
                     ratio_bound(tr, mu, h, va, precision, hH), rec, hH)
    return out


def _mu_omega_label(rec: Record, pl: Placer, pole: complex, left: float, right: float, text: str) -> None:
    """The plan of angular velocities' scale μω written at the plan's foot (review 10, mark 5), where
    the lab writes it: on the pole's level beside its letter where no ray or letter is (the picture no
    taller), else under the plan."""
    size = 3.5
    w = text_width(text, size)
    y = pole.imag - size / 2                                        # the baseline, the text centred on the pole
    spots = [(pole.real - gap - w, y) for gap in (10.0, 14.0, 20.0, 28.0)] + \
            [(pole.real + gap, y) for gap in (8.0, 12.0, 18.0, 26.0)]
    for x, yb in spots:
        box = Primitive("text", ((x, yb),), text=text, size=size).bounds()
        if pl.free(box):
            rec.label((x, yb), text, size=size, layer=LAYER, step="μω")
            pl._add_box(box)
            return
    rec.label(((left + right) / 2, rec.bounds()[1] - 3.0 - size), text, size=size, anchor="middle", layer=LAYER,
              step="μω")


def ratio_bound(tr: TrainSolution, mu: float, h: float, va: float, precision: float,
                h_carrier: float | None = None) -> float:
    """The bound of |u1H(graphical) − u1H| (absolute, u1H has no unit) from the drafting precision p,
    through u1H = s1/sH with s1 = h·vA/yA, sH = h·vA·(yC − yO2)/((yC − yA)·yO2) (vA and h cancel):

    - the heights yA = r1, yO2 = aw, yC = r3 laid off at μl from the computed radii, each off by what
      the ruler's rounding made of it, |lay_off(y) − y| (at most p/2; none where the radius falls on a
      mark of the ruler — stop 56: GEARS_OWN55's r1, aw, r3 are 17, 81 and 101 mm at 1:1, laid off
      exactly, yet the bound took p/2 on each and stated ±6,7 % where the reading was +0,55 %);
    - the segments s1, sH read off the plan, each within p/2 (where the reading falls is not known).

    First order: Σ δy·|∂u/∂y| over the heights (∂ln u/∂yA = −1/yA − 1/(yC − yA), ∂ln u/∂yO2 = 1/yO2
    + 1/(yC − yO2), ∂ln u/∂yC = 1/(yC − yA) − 1/(yC − yO2)) + (p/2)·u·(1/s1 + 1/sH); the margin: u at
    every corner of the lengths at ± their bounds (monotone in each, so the worst corner is the worst
    case to every order); the larger of the two is stated.
    ``h_carrier``: the carrier's ray from its own pole (``construct_train``): sH = h_H·vA·(…), u1H =
    (s1/h)/(sH/h_H), and h, h_H — no longer cancelling — laid off too, each off by its rounding."""
    rad = tr.radii
    yA, yO2, yC = rad["1"] / mu, rad["H"] / mu, rad["3"] / mu
    u = tr.ratio
    hH = h_carrier or h
    s1 = h * va / yA
    sH = hH / h * s1 / u
    hp = precision / 2
    off = lambda y: abs(lay_off(y, precision) - y)               # noqa: E731   a laid-off length's rounding
    dA, dO, dC = off(yA), off(yO2), off(yC)
    dh, dhH = (off(h), off(hH)) if h_carrier else (0.0, 0.0)
    first = u * (dA * (1 / yA + 1 / (yC - yA)) + dO * (1 / yO2 + 1 / (yC - yO2))
                 + dC * abs(1 / (yC - yA) - 1 / (yC - yO2)) + hp * (1 / s1 + 1 / sH) + dh / h + dhH / hH)
    worst = 0.0
    for sg in itertools.product((-1.0, 1.0), repeat=7):
        a, o, c = yA + sg[0] * dA, yO2 + sg[1] * dO, yC + sg[2] * dC
        k1, kH = h + sg[5] * dh, hH + sg[6] * dhH                   # the pole distances as laid off
        g1 = k1 * va / a + sg[3] * hp
        gH = kH * va * (c - o) / ((c - a) * o) + sg[4] * hp
        if min(a, o - a, c - o, g1, gH) <= 0:
            return math.inf                 # the precision as coarse as the drawing: no bound
        worst = max(worst, abs((g1 / h) / (gH / hH) - u))
    return max(first, worst)


def outside(graphical: float | None, exact: float, bound: float | None) -> bool:
    """Whether a graphical reading lies outside its stated bound (round-off of 1e-9 relative allowed)."""
    if graphical is None or bound is None or not math.isfinite(graphical):
        return False
    return abs(graphical - exact) > bound + 1e-9 * max(1.0, abs(exact))


BEARING = 1.6                # mm: a bearing's bars either side of its shaft (GOST 2.770)


def _bearing(rec: Record, x: float, y: float, frame: bool = False, half: float = 2.5) -> None:
    """A radial bearing on a shaft (GOST 2.770): two short bars parallel to the shaft either side of
    it; ``frame``: set in the frame, hatched under its lower bar."""
    for dy in (-BEARING, BEARING):
        rec.segment((x - half, y + dy), (x + half, y + dy), role="link", layer=LAYER, step="bearing")
    if frame:
        yb = y - BEARING
        rec.segment((x - half - 1.5, yb - 1.2), (x + half + 1.5, yb - 1.2), role="link", layer=LAYER, step="frame")
        rec.segment((x, yb), (x, yb - 1.2), role="link", layer=LAYER, step="frame")
        for k in range(4):
            x0 = x - half - 1.5 + 2.0 * k
            rec.segment((x0 + 2.0, yb - 1.2), (x0, yb - 3.2), role="hatch", layer=LAYER, step="frame")


def _frame_over(rec: Record, x0: float, x1: float, y: float, down: bool = False) -> None:
    """The frame (the housing) as a thick line with hatching above it (``down``: below it)."""
    rec.segment((x0, y), (x1, y), role="link", layer=LAYER, step="frame")
    n = max(2, int((x1 - x0) / 2.5))
    d = -2.5 if down else 2.5
    for k in range(n):
        x = x0 + (x1 - x0) * k / n
        rec.segment((x, y), (x + 2.5, y + d), role="hatch", layer=LAYER, step="frame")


def _scheme(rec: Record, tr: TrainSolution, mu: float, yA: float, yO2: float, yC: float,
            full: bool = True) -> tuple[float, float, float]:
    """The kinematic scheme over and under the central axis, as the textbook draws a 2K-H train
    (GOST 2.770; review 5, item 17; stop 57: the half over the axis alone looked sparse — the lead
    asked for both planets, the carrier across them, the fixed ring hatched on both sides) — or, not
    ``full``, its half over the axis (the half-section: the velocity picture needs no more): each wheel
    a rectangle of its face width whose edge toward its mate is its pitch circle (at μl: ±r1, ±(aw ± r2),
    ±r3) — the sun's rim on a web from the input shaft, a planet whole on its axle over the axis and
    one under it (their axes dash-dotted) turning in bearings, the ring's rim on webs into the frame,
    hatched, over and under —; the carrier H across both planets' axles to the output shaft; the shafts
    in bearings set in the frame; the members numbered 1, 2 (2'), 3, H once, over the axis (where the
    velocity picture is drawn). Returns where the velocity picture's projections start at the heights
    of A, O2 and C (the scheme's points)."""
    kind = tr.train.kind
    rad = tr.radii
    b = min(16.0, max(8.0, 0.18 * yC))       # a wheel's face width drawn
    rim = min(6.0, max(3.0, 0.07 * yC))      # the sun's and the ring's rim drawn this deep
    x1 = 0.0                                 # row 1: the sun, the planet 2 (and the ring for type A)
    xb = 0.0 if kind == "A" else b + 6.0     # row 2 (type B): the planet 2', the ring
    xh = xb + b / 2 + 7.0                    # the carrier's arm
    end = xh + 24.0                          # the output shaft's end
    rec.segment((-50.0, 0.0), (end + 4.0, 0.0), role="axis", layer=LAYER, step="central axis")

    def box(xc: float, y0: float, y1: float, step: str) -> None:
        rec.add("polygon", [(xc - b / 2, y0), (xc + b / 2, y0), (xc + b / 2, y1), (xc - b / 2, y1)],
                role="link", layer=LAYER, step=step)
    # the input shaft 1 in its bearing, the sun's web across the axis and its rim (its pitch circle the
    # rim's outer edge) over and under it
    rec.segment((-42.0, 0.0), (x1, 0.0), role="link", layer=LAYER, step="shaft 1")
    _bearing(rec, -30.0, 0.0, frame=True)
    rec.segment((x1, -(yA - rim) if full else 0.0), (x1, yA - rim), role="link", layer=LAYER, step="1 web")
    r2 = rad["2"] / mu
    r2b = rad["2'"] / mu if kind == "B" else 0.0
    for sg in ((1.0, -1.0) if full else (1.0,)):      # the half over the axis, then its mirror under it
        box(x1, sg * (yA - rim), sg * yA, "1")
        # a planet 2 (block 2–2'), whole, its axis dash-dotted, on its axle
        box(x1, sg * (yO2 - r2), sg * (yO2 + r2), "2")
        if kind == "B":
            box(xb, sg * (yO2 - r2b), sg * (yO2 + r2b), "2'")
        rec.segment((x1 - b / 2 - 4.0, sg * yO2), (xb + b / 2 + 4.0, sg * yO2), role="axis", layer=LAYER,
                    step="planet axis")
        rec.segment((x1 - b / 2 - 2.0, sg * yO2), (xh, sg * yO2), role="link", layer=LAYER, step="H axle")
        _bearing(rec, xb + b / 2 + 3.0, sg * yO2, half=1.5)
        # the ring 3: its rim (the pitch circle its inner edge, the teeth inside), the web into the frame
        box(xb, sg * yC, sg * (yC + rim), "3")
        top = yC + rim + 5.0
        rec.segment((xb, sg * (yC + rim)), (xb, sg * top), role="link", layer=LAYER, step="3 web")
        _frame_over(rec, xb - b / 2 - 4.0, xb + b / 2 + 4.0, sg * top, down=sg < 0)
    # the carrier H: its arm across both planets' axles, the output shaft from it in its bearing
    rec.segment((xh, yO2), (xh, -yO2 if full else 0.0), role="link", layer=LAYER, step="H")
    rec.segment((xh, 0.0), (end, 0.0), role="link", layer=LAYER, step="shaft H")
    _bearing(rec, xh + 13.0, 0.0, frame=True)
    pl = Placer(rec)
    pl.label(complex(x1 - b / 2, yA - rim / 2), "1", toward=-1 + 0j)
    pl.label(complex(x1 - b / 2, yO2 + r2 * 0.5), "2", toward=-1 + 0j)
    if kind == "B":
        pl.label(complex(xb + b / 2, yO2 + rad["2'"] / mu * 0.6), "2'", toward=1 + 0j)
    pl.label(complex(xb - b / 2, yC + rim / 2), "3", toward=-1 + 0j)
    # the carrier's letter midway up its arm — clear of the sun's pitch line yA, whose projection line runs
    # right across the arm to the velocity picture (stop 51's 29/31/91: yO2/2 = 37,5 mm, yA 36,25 mm)
    yH = yO2 * 0.5 if abs(yO2 * 0.5 - yA) >= 5.0 else (0.5 * (yA + yO2) if yO2 - yA > yA else 0.5 * yA)
    pl.label(complex(xh, yH), "H", toward=1 + 0j)
    pl.label(complex(-46.0, 0.0), "O", toward=1j)
    return x1 + b / 2, xh, xb + b / 2


def under_axis_right(rec: Record, below: float = -8.0) -> float:
    """The right end of the scheme's half under the central axis (what stands lower than ``below``,
    mm: the shafts' bearings and their frames on the axis left out) — the plan of angular velocities,
    under the velocity picture, starts right of it."""
    return max((x for p in rec.items if p.points and max(y for _, y in p.points) < below for x, _ in p.points),
               default=rec.bounds()[0])
