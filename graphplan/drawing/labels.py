"""Lettering that never overprints: the one label placer of every drawing, and the check of a record.

A label is a box of ink (its letters' glyph boxes, ``Primitive.ink``). It is placed where that box,
grown by a clearance, meets no line of the drawing (each line by its own width) and no other label:
first at candidate spots around its point (the preferred side first, 1–3 mm off), then — when none
is free — farther out with a short thin leader from the point to it (the leader stops short of the
letters). A joint's letter asked with ``breaks`` (a pivot where twelve thin positions meet) is
instead set beside its point where only thin construction lines are in the way, and those lines are
interrupted under it, as a draftsman writes it (``_breaking``). An optional label (a position
number) that finds no free spot is left out; a label that must be drawn and finds none goes to the
least crowded spot, and ``collisions`` reports it.

``collisions(record)`` is the same geometry used as a check: every label against every line and
every other label of the record (the tests run it on whole sheets).
"""
from __future__ import annotations

import math
from contextlib import contextmanager
from dataclasses import dataclass

import numpy as np

from graphplan.graphic.record import LabelRequest, Primitive, Record, vector_arrow

Box = tuple[float, float, float, float]

CLEAR = 0.5          # mm of paper between a label's ink and a line's ink when placing
STEEP_CLEAR = 1.2    # … beside a diagram's point number (``place_beside``), from a steep line at either side of it:
#                      a near-vertical stroke 0.5 mm from a digit reads as a "1" (the shaper's "2" by its vertical
#                      projection read "12"); only sideways and only steep lines — a uniform 1.2 mm pushed point 0,
#                      on its own (horizontal) axis, 3.9 mm off its point (stop 54)
STEEP = math.tan(math.radians(30.0))   # a line within 30° of the vertical is steep (|dx| ≤ STEEP·|dy|)
CHECK = 0.3          # … the least the check accepts (a reader sees 0.25 mm as touching)
APART = 1.6          # mm between two labels' ink (closer than 1.5 mm two words read as one: "s4d")
NUMBERS_APART = 3.0  # mm between two numbers' ink: closer, a link's "3" by a position's "1" reads "31"
LINK_APART = 6.0     # … where one is a link's number (5 mm high: "2" 3 mm from "1" still reads "2 1")
LINK_SIZE = 5.0      # mm: the height of a link's number (drawing.plans.link_numbers)
SUFFIX_APART = 10.0  # mm across between a label ending in an index (S₃, O₁) and a number after it on its
                     # line: closer, the lever's «S₃ 1» (position 1's number 6.7 mm on, its dot between) reads S₃₁ (issue 32 #4)
DIRECTIONS = 16      # candidate directions around a point
NEAR = (0.8, 1.5, 3.0, 4.5)               # mm from the point to the box: beside it
FAR = (5.0, 6.0, 7.0, 8.0, 9.5, 11.0, 12.5, 16.0, 20.0, 25.0, 32.0)   # … farther out, with a leader
FAR_DIRECTIONS = 96  # … in this many directions (a letter finds the sector between a pivot's twelve lines)


@dataclass
class Obstacles:
    """A record's lines as segments with their half widths (mm), and its labels' ink boxes."""
    segs: np.ndarray        # (n, 4): x1, y1, x2, y2
    half: np.ndarray        # (n,): half the line width
    boxes: list[Box]
    solid: list[Box]        # closed figures whose inside stays free of lettering (slider blocks)
    numbers: list[Box] | None = None   # the boxes of labels that are numbers (a subset of boxes) …
    big: list[Box] | None = None       # … of them, links' numbers
    leaders: list[tuple[complex, complex]] | None = None   # the leaders drawn: a new one crosses none
    reach: tuple[np.ndarray, ...] | None = None    # (lo_x, hi_x, lo_y, hi_y) where known (``_reach``)
    indexed: list[Box] | None = None   # the boxes of labels ending in an index (S_{3}: ``ends_indexed``)

    def __post_init__(self) -> None:
        if self.reach is None:
            self._reach()
        else:
            self.lo_x, self.hi_x, self.lo_y, self.hi_y = self.reach
            self.reach = None

    def _reach(self) -> None:
        """Each segment's own box grown by its half width, for a quick reject."""
        s, h = self.segs, self.half
        self.lo_x = np.minimum(s[:, 0], s[:, 2]) - h
        self.hi_x = np.maximum(s[:, 0], s[:, 2]) + h
        self.lo_y = np.minimum(s[:, 1], s[:, 3]) - h
        self.hi_y = np.maximum(s[:, 1], s[:, 3]) + h

    def near(self, at: complex, reach: float) -> Obstacles:
        """Only what lies within ``reach`` mm of the point (a label's candidates look no farther)."""
        x, y = at.real, at.imag
        keep = (self.hi_x > x - reach) & (self.lo_x < x + reach) & (self.hi_y > y - reach) & (self.lo_y < y + reach)

        def close(b: Box) -> bool:
            return b[2] > x - reach and b[0] < x + reach and b[3] > y - reach and b[1] < y + reach
        return Obstacles(self.segs[keep], self.half[keep], [b for b in self.boxes if close(b)],
                         [b for b in self.solid if close(b)], [b for b in self.numbers or [] if close(b)],
                         [b for b in self.big or [] if close(b)], self.leaders,
                         (self.lo_x[keep], self.hi_x[keep], self.lo_y[keep], self.hi_y[keep]),
                         [b for b in self.indexed or [] if close(b)])

    def add_segment(self, a, b, half: float) -> None:
        self.segs = np.vstack([self.segs, [[a[0], a[1], b[0], b[1]]]])
        self.half = np.append(self.half, half)
        self._reach()


def _circle_points(cx: float, cy: float, r: float, a0: float, a1: float) -> list[tuple[float, float]]:
    sweep = (a1 - a0) % 360.0 or 360.0
    n = max(4, int(math.ceil(sweep / 360.0 * max(12.0, 2 * math.pi * r / 1.5))))
    return [(cx + r * math.cos(math.radians(a0 + sweep * k / n)),
             cy + r * math.sin(math.radians(a0 + sweep * k / n))) for k in range(n + 1)]


def strokes(p: Primitive) -> list[tuple[tuple[float, float], tuple[float, float], float]]:
    """The ink of one non-text primitive as segments with half widths: a polyline's pieces, a
    circle or arc as chords no more than 1.5 mm long, an arrow's head as its triangle, a point as
    its little circle."""
    hw = p.line_width / 2
    pts = list(p.points)
    out = []
    if p.kind in ("circle", "arc"):
        (cx, cy), r = p.points[0], p.radius
        a0, a1 = p.angles if p.kind == "arc" else (0.0, 360.0)
        pts = _circle_points(cx, cy, r, a0, a1)
    elif p.kind == "point":
        (cx, cy), = p.points
        r = 1.0 if p.role == "joint" else 0.6
        pts = _circle_points(cx, cy, r, 0.0, 360.0)
        hw = 0.35 / 2
    elif p.kind == "polygon":
        pts = pts + pts[:1]
    elif p.kind == "vector" and len(pts) == 2:
        tip, _ = vector_arrow(pts[0], pts[1], p.line_width, p.role == "head")
        out += [(tip[0], tip[1], 0.05), (tip[1], tip[2], 0.05), (tip[2], tip[0], 0.05)]
    out += [(a, b, hw) for a, b in zip(pts, pts[1:])]
    return out


@dataclass
class _Built:
    """What ``obstacles`` found in a list of primitives, kept to be extended: a label placer asks
    again and again of a record that has only grown by a label or two since (``_BUILT``)."""
    items: list[Primitive]
    segs: np.ndarray
    half: np.ndarray
    boxes: list[Box]
    solid: list[Box]
    numbers: list[Box]
    big: list[Box]
    leaders: list[tuple[complex, complex]]
    reach: tuple[np.ndarray, ...] = ()
    indexed: list[Box] | None = None


_BUILT: list[_Built] = []     # the last few lists of primitives ``obstacles`` was asked of, newest last
_BUILT_KEPT = 4


def _built(items: list[Primitive], since: _Built | None) -> _Built:
    """The obstacles of ``items``, those of their first ``len(since.items)`` taken from ``since``
    (the same primitives: the same strokes, in the same order)."""
    start = len(since.items) if since is not None else 0
    segs: list[tuple[float, float, float, float]] = []
    half: list[float] = []
    boxes, solid, numbers, big, leaders = ((list(since.boxes), list(since.solid), list(since.numbers),
                                            list(since.big), list(since.leaders)) if since is not None
                                           else ([], [], [], [], []))
    indexed = list(since.indexed or []) if since is not None else []
    for p in items[start:]:
        if p.kind == "segment" and p.role == "label" and len(p.points) == 2:
            leaders.append((complex(*p.points[0]), complex(*p.points[1])))
        if p.kind == "text":
            boxes.append(p.ink())
            if is_number(p.text or ""):
                numbers.append(boxes[-1])
                if p.size >= LINK_SIZE:
                    big.append(boxes[-1])
            elif ends_indexed(p.text or ""):
                indexed.append(boxes[-1])
            continue
        for a, b, hw in strokes(p):
            segs.append((a[0], a[1], b[0], b[1]))
            half.append(hw)
        if p.kind == "polygon":
            solid.append(p.bounds())
    new_segs = np.array(segs, dtype=float).reshape(-1, 4)
    new_half = np.array(half, dtype=float)
    if since is not None:
        new_segs = np.concatenate([since.segs, new_segs])
        new_half = np.concatenate([since.half, new_half])
    return _Built(list(items), new_segs, new_half, boxes, solid, numbers, big, leaders, indexed=indexed)


def obstacles(items: list[Primitive]) -> Obstacles:
    """What a new label must keep clear of, from the primitives already drawn."""
    since = None
    for b in _BUILT:               # the longest list asked before that these items begin with
        k = len(b.items)
        if k <= len(items) and (since is None or k > len(since.items)) and items[:k] == b.items:
            since = b
    if since is not None and len(since.items) == len(items):
        built = since
    else:
        built = _built(items, since)
        if since is not None:
            _BUILT.remove(since)
        _BUILT.append(built)
        del _BUILT[:-_BUILT_KEPT]
    ob = Obstacles(built.segs, built.half, list(built.boxes), list(built.solid), list(built.numbers),
                   list(built.big), list(built.leaders), built.reach or None, list(built.indexed or []))
    built.reach = (ob.lo_x, ob.hi_x, ob.lo_y, ob.hi_y)
    return ob


def _hits(ob: Obstacles, box: Box, clear: float) -> list[int]:
    """The segments that pass within ``clear`` + their half width of the box: a quick reject on the
    segments' own boxes (vectorised), then Liang–Barsky clipping of the few near ones against the
    box grown by that much."""
    if len(ob.segs) == 0:
        return []
    x0, y0, x1, y1 = box
    near = np.nonzero((ob.hi_x > x0 - clear) & (ob.lo_x < x1 + clear)
                      & (ob.hi_y > y0 - clear) & (ob.lo_y < y1 + clear))[0]
    out = []
    for i in near.tolist():
        g = ob.half[i] + clear
        sx, sy, ex, ey = ob.segs[i]
        if _clips(sx, sy, ex, ey, x0 - g, y0 - g, x1 + g, y1 + g):
            out.append(i)
    return out


def _clips(sx: float, sy: float, ex: float, ey: float, x0: float, y0: float, x1: float, y1: float) -> bool:
    """Whether the segment (sx, sy)–(ex, ey) meets the box (Liang–Barsky)."""
    dx, dy = ex - sx, ey - sy
    t0, t1 = 0.0, 1.0
    for p, q in ((-dx, sx - x0), (dx, x1 - sx), (-dy, sy - y0), (dy, y1 - sy)):
        if abs(p) < 1e-12:
            if q < 0:
                return False
            continue
        t = q / p
        if p < 0:
            if t > t0:
                t0 = t
        elif t < t1:
            t1 = t
        if t0 > t1:
            return False
    return True


def _meets(a: Box, b: Box, apart: float = 0.0) -> bool:
    return a[0] < b[2] + apart and b[0] < a[2] + apart and a[1] < b[3] + apart and b[1] < a[3] + apart


def _segment_meets_box(a: complex, b: complex, box: Box) -> bool:
    return _clips(a.real, a.imag, b.real, b.imag, *box)


def is_number(text: str) -> bool:
    """Whether a label is a number (a position's, a link's; primes allowed: 0', 12'') or a list of
    them ("1, 9": positions numbered once at one spot) — kept ``NUMBERS_APART`` from other numbers:
    FORCE_COUPLER51's "5" stood 2 mm before B's "1, 9" and read "5 1, 9" (stop 52)."""
    return all(part.rstrip("'").isdigit() for part in text.split(", "))


def ends_indexed(text: str) -> bool:
    """Whether a label (not a number) ends in a numeric index — S_3, S_{3}, «O_{1}, S_{1}» — which a number
    set after it on its line continues (``SUFFIX_APART``)."""
    import re
    return not is_number(text) and re.search(r"_(\{\d+\}|\d+)$", text) is not None


def _number(req: LabelRequest) -> float:
    """A request's height where its text is a number (what ``_counts`` keeps numbers apart by), −1
    where it ends in an index (``ends_indexed``: kept ``SUFFIX_APART`` from a number after it on its
    line), else 0."""
    return req.size if is_number(req.text) else (-1.0 if ends_indexed(req.text) else 0.0)


def _clip_all(sx, sy, ex, ey, x0, y0, x1, y1) -> np.ndarray:
    """``_clips`` of many segments against as many boxes at once (Liang–Barsky: the same quotients,
    the entry parameter the largest of those where the segment enters, the exit the least)."""
    dx, dy = ex - sx, ey - sy
    with np.errstate(all="ignore"):
        zx, zy = np.abs(dx) < 1e-12, np.abs(dy) < 1e-12
        qa, qb, qc, qd = sx - x0, x1 - sx, sy - y0, y1 - sy
        ok = ~((zx & ((qa < 0) | (qb < 0))) | (zy & ((qc < 0) | (qd < 0))))
        ra, rb, rc, rd = qa / -dx, qb / dx, qc / -dy, qd / dy       # q / p of the four sides
        px, nx = ~zx & (dx > 0), ~zx & (dx < 0)
        py, ny = ~zy & (dy > 0), ~zy & (dy < 0)
        t0 = np.maximum(np.maximum(np.where(px, ra, 0.0), np.where(nx, rb, 0.0)),
                        np.maximum(np.where(py, rc, 0.0), np.where(ny, rd, 0.0)))
        t1 = np.minimum(np.minimum(np.where(nx, ra, 1.0), np.where(px, rb, 1.0)),
                        np.minimum(np.where(ny, rc, 1.0), np.where(py, rd, 1.0)))
    return ok & (t0 <= t1)


def _counts(ob: Obstacles, boxes: np.ndarray, clear: float = CLEAR, number: float = 0.0) -> np.ndarray:
    """For each candidate box (m, 4): how many lines (within ``clear`` + half their width), labels
    (within ``APART``; a number's — ``number`` its height, 0 for a word — within ``NUMBERS_APART`` of
    another number's, ``LINK_APART`` where either is a link's) and closed figures it would touch —
    all candidates at once."""
    m = len(boxes)
    out = np.zeros(m, dtype=int)
    bx0, by0, bx1, by1 = (boxes[:, i:i + 1] for i in range(4))
    if len(ob.segs) and m:
        # first the segments near any of the boxes (a quick reject on all of them at once), then
        # each box against those: the same pairs as each box against every segment
        keep = np.nonzero((ob.hi_x > bx0.min() - clear) & (ob.lo_x < bx1.max() + clear)
                          & (ob.hi_y > by0.min() - clear) & (ob.lo_y < by1.max() + clear))[0]
        if len(keep):
            # the boxes' sides as contiguous columns, the pairs' values gathered column by column
            # (``take``): the same numbers as indexing the (m, 4) rows, without strided copies
            c0, c1, c2, c3 = (np.ascontiguousarray(boxes[:, i]) for i in range(4))
            near = ((ob.hi_x[keep] > (c0 - clear)[:, None]) & (ob.lo_x[keep] < (c2 + clear)[:, None])
                    & (ob.hi_y[keep] > (c1 - clear)[:, None]) & (ob.lo_y[keep] < (c3 + clear)[:, None]))
            ci, si = np.nonzero(near)
            if len(ci):
                si = keep[si]
                g = ob.half[si] + clear
                sx, sy, ex, ey = (ob.segs[:, i].take(si) for i in range(4))
                hit = _clip_all(sx, sy, ex, ey, c0.take(ci) - g, c1.take(ci) - g, c2.take(ci) + g, c3.take(ci) + g)
                out += np.bincount(ci[hit], minlength=m)
    groups = [(ob.boxes, APART), (ob.solid, 0.0)]
    if number > 0:
        groups += [(ob.numbers, LINK_APART if number >= LINK_SIZE else NUMBERS_APART), (ob.big, LINK_APART)]
    # a number after a label ending in an index, on its line (the boxes within APART in height), reads
    # as the index's next figure («S₃ 1»): kept SUFFIX_APART across — a position's number (small) after
    # an indexed label, or an indexed label placed before a number already there
    after = ob.indexed if number > 0 and number < LINK_SIZE else (ob.numbers if number < 0 else None)
    if after:
        q = np.asarray(after, dtype=float)
        row = (by0 < q[None, :, 3] + APART) & (q[None, :, 1] < by1 + APART)     # its line, or a hair off it
        if number > 0:       # the candidate number starts within SUFFIX_APART after the label's end
            beside = (bx0 > q[None, :, 0]) & (bx0 < q[None, :, 2] + SUFFIX_APART)
        else:                # the candidate label ends within SUFFIX_APART before the number's start
            beside = (q[None, :, 0] > bx0) & (q[None, :, 0] < bx1 + SUFFIX_APART)
        out += (row & beside).sum(axis=1)
    for group, apart in groups:
        if group:
            q = np.asarray(group, dtype=float)
            hit = ((bx0 < q[None, :, 2] + apart) & (q[None, :, 0] < bx1 + apart)
                   & (by0 < q[None, :, 3] + apart) & (q[None, :, 1] < by1 + apart))
            out += hit.sum(axis=1)
    return out


_TURNS: dict[int, np.ndarray] = {}


def _turns(n: int) -> np.ndarray:
    """exp(i·2πj/n) for j = 0, +1, −1, +2, −2, …: the preferred direction first, then either side."""
    if n not in _TURNS:
        j = np.array([(k + 1) // 2 * (1 if k % 2 else -1) for k in range(n)], dtype=float)
        _TURNS[n] = np.exp(2j * np.pi * j / n)
    return _TURNS[n]


def _candidates(req: LabelRequest, ink: Box, gaps, n: int) -> tuple[np.ndarray, np.ndarray]:
    """The candidate ink boxes (in preference order: nearer first, the preferred side first) and
    the text's anchor (its start on the baseline, as a complex number) for each: the box lies
    wholly on the side u of the point, ``gap`` clear of it."""
    pref = req.toward / abs(req.toward) if abs(req.toward) > 1e-12 else 1j
    iw, ih = ink[2] - ink[0], ink[3] - ink[1]
    dx, dy = _offsets(pref, iw, ih, tuple(float(g) for g in gaps), n)
    cx = req.at.real + dx
    cy = req.at.imag + dy
    boxes = np.empty((len(cx), 4))
    boxes[:, 0] = cx - iw / 2
    boxes[:, 1] = cy - ih / 2
    boxes[:, 2] = cx + iw / 2
    boxes[:, 3] = cy + ih / 2
    starts = (boxes[:, 0] - ink[0]) + 1j * (boxes[:, 1] - ink[1])
    return boxes, starts


_OFFSETS: dict[tuple, tuple[np.ndarray, np.ndarray]] = {}
_OFFSETS_KEPT = 4096


def _offsets(pref: complex, iw: float, ih: float, gaps: tuple[float, ...], n: int) -> tuple[np.ndarray, np.ndarray]:
    """The candidates' centres off the point (``_candidates``): u/‖u‖∞·(w/2 + g) across and
    u/‖u‖∞·(h/2 + g) up for each gap g and direction u — the same for every label of one size and
    side, remembered (each offset computed as ``_candidates`` computed it, the point added after:
    the same boxes to the last bit; the arrays are never written to — stop 52: ~1.5 % of a force
    sheet's CPU)."""
    key = (pref, iw, ih, gaps, n)
    hit = _OFFSETS.get(key)
    if hit is None:
        u = pref * _turns(n)
        m = np.maximum(np.abs(u.real), np.abs(u.imag))
        g = np.repeat(np.asarray(gaps, dtype=float), n)
        uu = np.tile(u, len(gaps))
        mm = np.tile(m, len(gaps))
        hit = (uu.real / mm * (iw / 2 + g), uu.imag / mm * (ih / 2 + g))
        for a in hit:
            a.setflags(write=False)
        if len(_OFFSETS) >= _OFFSETS_KEPT:
            _OFFSETS.pop(next(iter(_OFFSETS)))
        _OFFSETS[key] = hit
    return hit


_SKETCH = [False]


# -- placements remembered ------------------------------------------------------------------------
# A placement is a function of the record's primitives and what is asked: a force sheet draws its
# hodographs and lever in both languages and at the scales it tries, each asking the same labels of
# the same lines again. The primitives placed are kept (they are immutable) and set again.

_PLACED: dict[tuple, tuple] = {}
_PLACED_KEPT = 512
_SAME = object()     # the placement returned its record


def _asked(x):
    """A hashable image of a placement's argument (its value, not its identity): a request by its
    fields, a callable (``accept``) by its code and its closure's values, an array by its bytes;
    TypeError for anything else mutable."""
    if isinstance(x, (str, int, float, complex, bool, type(None))):
        return x
    if isinstance(x, (list, tuple)):
        return tuple(_asked(v) for v in x)
    if isinstance(x, LabelRequest):
        return (LabelRequest,) + tuple(_asked(v) for v in x.__dict__.values())
    if isinstance(x, np.ndarray):
        return (x.dtype.str, x.shape, x.tobytes())
    if callable(x) and hasattr(x, "__code__") and not getattr(x, "__defaults__", None):
        return (x.__code__,) + tuple(_asked(c.cell_contents) for c in (x.__closure__ or ()))
    raise TypeError(f"not remembered: {type(x).__name__}")


def _remembered(place):
    """``place`` (record, …) remembered by the record's primitives and its arguments' values."""
    import functools

    @functools.wraps(place)
    def wrapper(record: Record, *args, **kw):
        if _SKETCH[-1]:
            return place(record, *args, **kw)
        try:
            key = (place.__name__, tuple(record.items), _asked(args), _asked(tuple(sorted(kw.items()))))
            hash(key)
        except TypeError:
            return place(record, *args, **kw)
        hit = _PLACED.get(key)
        if hit is not None:
            record.items[:] = hit[0]
            return record if hit[1] is _SAME else hit[1]
        out = place(record, *args, **kw)
        if len(_PLACED) >= _PLACED_KEPT:
            _PLACED.pop(next(iter(_PLACED)))
        _PLACED[key] = (tuple(record.items), _SAME if out is record else out)
        return out
    return wrapper


@contextmanager
def sketched():
    """Inside it, drawings are sketched: their labels are asked for but not placed — what a
    composition measures of a drawing's lines before the lettering (placing it is most of a
    drawing's cost; the finished drawing is measured again)."""
    _SKETCH.append(True)
    try:
        yield
    finally:
        _SKETCH.pop()


@_remembered
def place_labels(record: Record, requests: list[LabelRequest], layer: str = "labels") -> Record:
    """Add the labels to ``record`` where they overprint nothing (see the module's docstring);
    returns the record."""
    if _SKETCH[-1]:
        return record
    ob = obstacles(record.items)
    for req in requests:
        probe = Primitive("text", ((0.0, 0.0),), text=req.text, size=req.size)
        ink = probe.ink()
        size = (ink[2] - ink[0]) + (ink[3] - ink[1]) + CLEAR + 2.0
        spot = _near(ob.near(req.at, NEAR[-1] + size), req, ink)
        if spot is None and req.breaks:
            spot = _breaking(record, req, ink)
            if spot is not None:
                ob = obstacles(record.items)          # the lines under the letter were broken
        if spot is None:
            local = ob.near(req.at, FAR[-1] + size)
            spot = _far(local, req, ink)
            if spot is None:
                if req.optional:
                    continue
                spot = _outside(ob, record, req, ink) or _least(local, req, ink)
        box, start, leader = spot
        if leader is not None:
            a, b = leader
            record.segment((a.real, a.imag), (b.real, b.imag), role="label", layer=layer, step=req.step)
            ob.add_segment((a.real, a.imag), (b.real, b.imag), 0.125)
            ob.leaders = (ob.leaders or []) + [(a, b)]
        record.label((start.real, start.imag), req.text, size=req.size, anchor="start", step=req.step, layer=layer)
        ob.boxes.append(box)
        if is_number(req.text):
            ob.numbers = (ob.numbers or []) + [box]
            if req.size >= LINK_SIZE:
                ob.big = (ob.big or []) + [box]
        elif ends_indexed(req.text):
            ob.indexed = (ob.indexed or []) + [box]
    return record


def _steep_counts(ob: Obstacles, boxes: np.ndarray, clear: float) -> np.ndarray:
    """For each candidate box (m, 4): how many steep lines (``STEEP``) pass within ``clear`` + half
    their width of it — beside it, or ending over or under it (a tick, the stub of a line broken
    under it): either reads as a "1" by the digit. A steep line cannot pass over a number without
    passing beside it, so only its ends are kept that far above and below."""
    if not len(ob.segs) or not len(boxes):
        return np.zeros(len(boxes), dtype=int)
    dx = np.abs(ob.segs[:, 2] - ob.segs[:, 0])
    dy = np.abs(ob.segs[:, 3] - ob.segs[:, 1])
    steep = np.nonzero((dx <= STEEP * dy) & (dy > 1e-9))[0]
    if not len(steep):
        return np.zeros(len(boxes), dtype=int)
    sub = Obstacles(ob.segs[steep], ob.half[steep], [], [], [], [], None,
                    (ob.lo_x[steep], ob.hi_x[steep], ob.lo_y[steep], ob.hi_y[steep]))
    wide = boxes.copy()
    wide[:, :2] -= clear - CLEAR
    wide[:, 2:] += clear - CLEAR
    return _counts(sub, wide, CLEAR)


def _near(ob: Obstacles, req: LabelRequest, ink: Box, accept=None, steep: float = 0.0,
          rings: tuple[float, ...] = NEAR):
    """The first free spot beside the point (the ``rings``), or None; ``steep`` > 0 keeps a
    number that far from a steep line at either side of it (``_steep_counts``)."""
    gaps = (max(req.gap, rings[0]),) + tuple(g for g in rings[1:] if g > req.gap)
    boxes, starts = _candidates(req, ink, gaps, 2 * DIRECTIONS)
    # the first free spot in order of preference: the nearer rings counted first (most labels find
    # their spot there), the sight line, the rivals and ``accept`` tried only up to the first that passes
    rings = NEAR_FIRST * 2 * DIRECTIONS
    for lo, hi in ((0, rings), (rings, len(boxes))):
        if lo >= hi:
            continue
        count = _counts(ob, boxes[lo:hi], number=_number(req))
        if steep > CLEAR and is_number(req.text):
            count = count + _steep_counts(ob, boxes[lo:hi], steep)
        free = np.nonzero(count == 0)[0] + lo
        for k in free.tolist():
            if req.sight and not _in_sight(ob, req.at, boxes[k]):
                continue
            if req.rivals and not owned(req, boxes[k]):
                continue
            if accept is not None and not accept(tuple(float(v) for v in boxes[k])):
                continue
            return tuple(boxes[k]), complex(starts[k]), None
    return None


NEAR_FIRST = 2       # the rings beside the point ``_near`` counts before the rest


SIGHT_FROM = 0.9     # mm from the point where its sight line starts (the lines through the point itself)


def _in_sight(ob: Obstacles, at: complex, box) -> bool:
    """Whether no line of the drawing crosses the straight line from the point (``SIGHT_FROM`` off
    it) to the nearest point of the label's box: nothing between a number and its point."""
    x0, y0, x1, y1 = (float(v) for v in box)
    near = complex(min(max(at.real, x0), x1), min(max(at.imag, y0), y1))
    d = near - at
    if abs(d) <= SIGHT_FROM or len(ob.segs) == 0:
        return True
    a = at + d / abs(d) * SIGHT_FROM
    sx, sy, ex, ey = ob.segs.T
    ux, uy = near.real - a.real, near.imag - a.imag
    vx, vy = ex - sx, ey - sy
    den = ux * vy - uy * vx
    with np.errstate(all="ignore"):
        t = ((sx - a.real) * vy - (sy - a.imag) * vx) / den
        s = ((sx - a.real) * uy - (sy - a.imag) * ux) / den
    cross = (np.abs(den) > 1e-12) & (t >= 0.0) & (t <= 1.0) & (s >= 0.0) & (s <= 1.0)
    return not bool(np.any(cross))


BREAK_WIDTH = 0.5    # lines thinner than this (the thin positions, trajectories, construction) may be broken
BREAK_ROLES = ("link", "construction", "projection", "trajectory", "arc", "direction", "chord", "ray", "grid")


def breakable(p: Primitive) -> bool:
    """A thin construction or position line a letter may interrupt (a draftsman breaks the thin
    lines under a pivot's letter): a segment, polyline, circle or arc thinner than ``BREAK_WIDTH``
    of a construction role — never a link drawn thick, a vector, the frame, a point or a label."""
    return (p.kind in ("segment", "polyline", "circle", "arc") and p.line_width < BREAK_WIDTH
            and p.role in BREAK_ROLES and p.layer != "frame")


def _breaking(record: Record, req: LabelRequest, ink: Box, accept=None, steep: float = 0.0,
              rings: tuple[float, ...] = NEAR):
    """A joint's letter where the point is crowded by thin lines (the crank's pivot, where twelve
    positions meet): the nearest spot beside the point (within ``NEAR``) that meets no line but
    breakable ones (``breakable``) and no label; the thin lines under it are broken there, each
    piece keeping its role, layer, step and width. None where even that finds no spot. ``steep``, ``rings``:
    as ``_near`` (a number kept that far from the steep lines not broken, the curve's)."""
    hard = obstacles([p for p in record.items if not breakable(p)])
    text_size = (ink[2] - ink[0]) + (ink[3] - ink[1]) + CLEAR + 2.0
    local = hard.near(req.at, NEAR[-1] + text_size)
    gaps = (max(req.gap, rings[0]),) + tuple(g for g in rings[1:] if g > req.gap)
    boxes, starts = _candidates(req, ink, gaps, 2 * DIRECTIONS)
    count = _counts(local, boxes, number=_number(req))
    if steep > CLEAR and is_number(req.text):
        # no steep line, thin or not, that near: one broken under a number leaves its stub over the digit,
        # which reads "|7" as a whole one beside it does (stop 55: LINK55's 7, 4, 8 on their projections)
        thin = obstacles([p for p in record.items if breakable(p)]).near(req.at, NEAR[-1] + text_size)
        count = count + _steep_counts(local, boxes, steep) + _steep_counts(thin, boxes, steep)
    free = np.nonzero(count == 0)[0]
    if req.rivals:
        free = [k for k in list(free) if owned(req, boxes[k])]
    if accept is not None:
        free = [k for k in list(free) if accept(tuple(float(v) for v in boxes[k]))]
    if not len(free):
        return None
    k = int(free[0])
    box = tuple(boxes[k])
    broken = []
    for p in record.items:
        broken += break_under(p, box, CLEAR) if breakable(p) else [p]
    record.items[:] = broken
    return box, complex(starts[k]), None


def _outside_runs(ts: list[float], inside: list[bool]) -> list[tuple[float, float]]:
    """The runs of parameters (sorted ``ts``) whose samples lie outside."""
    runs, start = [], None
    for t, ins in zip(ts, inside):
        if not ins and start is None:
            start = t
        if ins and start is not None:
            runs.append((start, prev))
            start = None
        prev = t
    if start is not None:
        runs.append((start, ts[-1]))
    return runs


def break_under(p: Primitive, box: Box, clear: float) -> list[Primitive]:
    """The primitive with what lies within ``clear`` (+ its half width) of the box cut out: the
    pieces outside, each like the original (role, layer, step, width); the primitive itself where
    it does not meet the box."""
    from dataclasses import replace
    g = clear + p.line_width / 2
    x0, y0, x1, y1 = box[0] - g, box[1] - g, box[2] + g, box[3] + g

    def inside(x: float, y: float) -> bool:
        return x0 <= x <= x1 and y0 <= y <= y1
    if p.kind in ("circle", "arc"):
        (cx, cy), r = p.points[0], p.radius
        a0, a1 = p.angles if p.kind == "arc" else (0.0, 360.0)
        sweep = (a1 - a0) % 360.0 or 360.0
        n = max(8, int(sweep * 4))
        ts = [a0 + sweep * k / n for k in range(n + 1)]
        ins = [inside(cx + r * math.cos(math.radians(t)), cy + r * math.sin(math.radians(t))) for t in ts]
        if not any(ins):
            return [p]
        return [replace(p, kind="arc", angles=(a, b)) for a, b in _outside_runs(ts, ins) if b - a > 0.2]
    out: list[Primitive] = []
    pts = list(p.points)
    if not any(_clips(a[0], a[1], b[0], b[1], x0, y0, x1, y1) for a, b in zip(pts, pts[1:])):
        return [p]
    run: list[tuple[float, float]] = []
    for a, b in zip(pts, pts[1:]):
        ax, ay, bx, by = a[0], a[1], b[0], b[1]
        t0, t1 = _clip_params(ax, ay, bx, by, x0, y0, x1, y1)
        if t0 is None:                    # this piece misses the box
            run = run or [a]
            run.append(b)
            continue
        if t0 > 1e-9:
            run = run or [a]
            run.append((ax + (bx - ax) * t0, ay + (by - ay) * t0))
        if len(run) >= 2 and math.dist(run[0], run[-1]) > 0.05:
            out.append(replace(p, points=tuple(run)))
        run = [(ax + (bx - ax) * t1, ay + (by - ay) * t1), b] if t1 < 1 - 1e-9 else []
    if len(run) >= 2 and math.dist(run[0], run[-1]) > 0.05:
        out.append(replace(p, points=tuple(run)))
    return [replace(q, kind="segment") if p.kind == "segment" else q for q in out]


def _clip_params(sx: float, sy: float, ex: float, ey: float, x0: float, y0: float, x1: float, y1: float
                 ) -> tuple[float | None, float]:
    """The parameters (t0, t1) in [0, 1] of the part of the segment inside the box (Liang–Barsky);
    (None, 0) where it misses."""
    dx, dy = ex - sx, ey - sy
    t0, t1 = 0.0, 1.0
    for p, q in ((-dx, sx - x0), (dx, x1 - sx), (-dy, sy - y0), (dy, y1 - sy)):
        if abs(p) < 1e-12:
            if q < 0:
                return None, 0.0
            continue
        t = q / p
        if p < 0:
            t0 = max(t0, t)
        else:
            t1 = min(t1, t)
        if t0 > t1:
            return None, 0.0
    return t0, t1


def _far(ob: Obstacles, req: LabelRequest, ink: Box, ok=None, *more):
    """A free spot farther out, joined to the point by a leader that crosses no label (and where
    ``ok(box)``, when given; else where the first of ``more`` holds, and so on: each as its own
    search, the candidates counted once for all)."""
    boxes, starts = _candidates(req, ink, FAR, FAR_DIRECTIONS)
    n = FAR_DIRECTIONS
    # a label with rivals: nearer its own point first, then clear of them; its leader off the lines first
    passes = ((True, True), (False, True), (False, False)) if req.rivals else ((False, False),)
    rings = range(len(FAR))
    # a number with rivals: nearer its own point than theirs at any length of leader first; a letter:
    # the nearest ring first (it stays within a few mm), the stricter passes first in each
    order = ([(p, r) for p in passes for r in rings] if is_number(req.text)
             else [(p, r) for r in rings for p in passes])
    counted: dict[int, np.ndarray] = {}
    led: dict[int, list] = {}
    fits: dict[tuple, bool] = {}              # the checks that do not depend on ``ok``, per spot
    for test in (ok, *more):
        for (strict, apart), ring in order:
            if ring not in counted:               # ring by ring, nearest first: counted lazily
                counted[ring] = _counts(ob, boxes[ring * n:(ring + 1) * n], number=_number(req))
            counts = counted[ring]
            free = np.nonzero(counts == 0)[0] + ring * n
            if ring not in led:                   # the free spots' leaders, and which meet a label or a leader
                led[ring] = _led_blocked(ob, req.at, [tuple(boxes[k]) for k in free])
            for k, (box, (a, b), meets, crosses) in zip(free, led[ring]):
                fit = fits.get((k, strict, apart))
                if fit is None:
                    # through a label, or across a drawn leader (two crossing read as an X); nor
                    # across a link or an arrow, where asked; a label with rivals reads as its point's
                    fit = fits[k, strict, apart] = not (
                        meets or crosses or (not req.across and _crosses_thick(ob, a, b))
                        or req.rivals and (not led_owned(req, box, b, strict) or apart and _along_line(ob, a, b)))
                # ``ok`` (pure, and the costliest) asked last: the same first spot as asked first
                if fit and (test is None or test(box)):
                    return box, complex(starts[k]), (a, b)
    return None


def _led_blocked(ob: Obstacles, at: complex, boxes: list[Box]) -> list[tuple[Box, tuple[complex, complex], bool, bool]]:
    """Each box with its ``_leader`` from ``at``, whether that leader meets a label's box grown by
    0.7 mm (``_segment_meets_box``) and whether it properly crosses a drawn leader (``_cross``) —
    every box against every label and leader at once, the same arithmetic as those tests one by one."""
    leads = [_leader(at, box) for box in boxes]
    if not leads:
        return []
    a = np.asarray([p for p, _ in leads], dtype=complex)
    b = np.asarray([q for _, q in leads], dtype=complex)
    meets = np.zeros(len(leads), dtype=bool)
    crosses = np.zeros(len(leads), dtype=bool)
    if ob.boxes:
        q = np.asarray(ob.boxes, dtype=float)
        A, B = a[:, None], b[:, None]
        meets = np.any(_clip_all(A.real, A.imag, B.real, B.imag, q[None, :, 0] - 0.7, q[None, :, 1] - 0.7,
                                  q[None, :, 2] + 0.7, q[None, :, 3] + 0.7), axis=1)
    if ob.leaders:
        crosses = _crosses_all(a, b, np.asarray([c for c, _ in ob.leaders], dtype=complex),
                               np.asarray([d for _, d in ob.leaders], dtype=complex))
    return [(box, lead, bool(m), bool(x)) for box, lead, m, x in zip(boxes, leads, meets, crosses)]


def _cross(a: complex, b: complex, c: complex, d: complex) -> bool:
    """Whether the segments a–b and c–d cross (proper intersection, inside both)."""
    def side(p: complex, q: complex, r: complex) -> float:
        return ((q - p).conjugate() * (r - p)).imag
    return (side(a, b, c) * side(a, b, d) < 0) and (side(c, d, a) * side(c, d, b) < 0)


THICK_HALF = 0.3    # a line this thick (half width, mm) or more — a link, a vector — no leader crosses


def _crosses_thick(ob: Obstacles, a: complex, b: complex) -> bool:
    """Whether the leader a–b crosses a thick line of the drawing (``THICK_HALF``)."""
    if len(ob.segs) == 0:
        return False
    s = ob.segs[ob.half >= THICK_HALF]
    if len(s) == 0:
        return False
    sx, sy, ex, ey = s.T
    ux, uy = b.real - a.real, b.imag - a.imag
    vx, vy = ex - sx, ey - sy
    den = ux * vy - uy * vx
    with np.errstate(all="ignore"):
        t = ((sx - a.real) * vy - (sy - a.imag) * vx) / den
        v = ((sx - a.real) * uy - (sy - a.imag) * ux) / den
    return bool(np.any((np.abs(den) > 1e-12) & (t > 0.0) & (t < 1.0) & (v > 0.0) & (v < 1.0)))


RIVAL_CLEAR = 1.0    # mm: a leader passes no other point of its path nearer than this (it would read as that point's)
RIVAL_BOX = 2.5      # … and the label at its end stands at least this clear of any (else beside that point)
RIVAL_FARTHER = 1.5  # mm: a label beside its point this much nearer it than any rival reads as its


def _along_line(ob: Obstacles, a: complex, b: complex, clear: float = 1.0) -> bool:
    """Whether a leader from ``a`` to ``b`` runs on a drawn line (its middle and three quarters
    within ``clear`` of one line's ink): it would read as part of that line (a dimension's extension)."""
    if len(ob.segs) == 0:
        return False
    sx, sy, ex, ey = ob.segs.T
    dx, dy = ex - sx, ey - sy
    n2 = np.maximum(dx * dx + dy * dy, 1e-12)
    on = np.ones(len(sx), dtype=bool)
    for f in (0.5, 0.75):
        z = a + f * (b - a)
        t = np.clip(((z.real - sx) * dx + (z.imag - sy) * dy) / n2, 0.0, 1.0)
        on &= np.hypot(sx + t * dx - z.real, sy + t * dy - z.imag) - ob.half < clear
    return bool(np.any(on))


def owned(req: LabelRequest, box) -> bool:
    """Whether a label set beside its point (no leader) reads as that point's and not a rival's
    (``req.rivals``, the same path's other positions): its box at most half as far from its own
    point as from any rival, less ``OWN_MARGIN``, or ``RIVAL_FARTHER`` mm farther from every one."""
    mine = _box_gap(box, req.at)
    need = min(2.0 * mine + OWN_MARGIN, mine + RIVAL_FARTHER)
    return all(_box_gap(box, z) >= need for z in req.rivals)


def _off_segment(z: complex, a: complex, b: complex) -> float:
    d = b - a
    t = 0.0 if abs(d) < 1e-12 else min(max(((z - a) * d.conjugate()).real / abs(d) ** 2, 0.0), 1.0)
    return abs(z - (a + t * d))


def led_owned(req: LabelRequest, box, end: complex, strict: bool = False) -> bool:
    """Whether a label on a leader (from its point to ``end``, at the box) reads as its point's:
    the box no nearer a rival than its own point (``strict``; else at least ``RIVAL_BOX`` clear of
    it, where points crowd so that no spot is nearer), and the leader passing no rival within
    ``RIVAL_CLEAR`` — a rival all but on the point (nearer than that) behind the leader, not ahead."""
    mine = _box_gap(box, req.at)
    for z in req.rivals:
        if _box_gap(box, z) < (mine + 0.05 if strict else min(mine, RIVAL_BOX)):
            return False
        if abs(z - req.at) < RIVAL_CLEAR:
            if ((z - req.at) * (end - req.at).conjugate()).real > 0.0:
                return False
        elif _off_segment(z, req.at, end) < RIVAL_CLEAR:
            return False
    return True


def _leader(at: complex, box: Box) -> tuple[complex, complex]:
    """A leader from just off the point to just short of the box (its nearest point)."""
    near = complex(min(max(at.real, box[0]), box[2]), min(max(at.imag, box[1]), box[3]))
    d = near - at
    n = abs(d) or 1.0
    u = d / n
    return at + 1.2 * u, near - (CLEAR + 0.3) * u


def _outside(ob: Obstacles, record: Record, req: LabelRequest, ink: Box):
    """A label that finds no room near its point: beyond the drawing's edge, on a leader from the
    point that crosses no label, the side the point is nearest first."""
    x0, y0, x1, y1 = record.bounds()
    iw, ih = ink[2] - ink[0], ink[3] - ink[1]
    at = req.at
    spots = []
    for out in (3.0, 9.0, 16.0):                 # past each edge, level with the point first
        for shift in (0.0, 6.0, -6.0, 12.0, -12.0, 20.0, -20.0, 30.0, -30.0, 42.0, -42.0):
            spots += [complex(x1 + out + iw / 2, at.imag + shift), complex(x0 - out - iw / 2, at.imag + shift),
                      complex(at.real + shift, y1 + out + ih / 2), complex(at.real + shift, y0 - out - ih / 2)]
    spots.sort(key=lambda c: abs(c - at))
    boxes = [(c.real - iw / 2, c.imag - ih / 2, c.real + iw / 2, c.imag + ih / 2) for c in spots]
    touched: list[int] = []           # the spots' counts, a few spots at a time, as far as asked

    def hits(i: int) -> int:
        while len(touched) <= i:
            touched.extend(_counts(ob, np.asarray(boxes[len(touched):len(touched) + OUTSIDE_CHUNK]),
                                   number=_number(req)).tolist())
        return touched[i]
    led: list = []                    # the spots' leaders, whether each meets a label, crosses a leader

    def leader(i: int):
        while len(led) <= i:
            led.extend(_led_blocked(ob, at, boxes[len(led):len(led) + OUTSIDE_CHUNK]))
        return led[i]
    for strict in (True, False):      # first a leader that crosses no other and is not long
        for i, box in enumerate(boxes):
            if hits(i):
                continue
            _, (a, b), meets, crosses = leader(i)
            if meets:
                continue
            if strict and (abs(b - a) > OUTSIDE_LEADER_MM or crosses):
                continue
            return box, complex(box[0] - ink[0], box[1] - ink[1]), (a, b)
    return None


OUTSIDE_LEADER_MM = 30.0    # a leader out past the drawing's edge no longer than this where it can
OUTSIDE_CHUNK = 12          # the spots past the edge counted at once


def _least(ob: Obstacles, req: LabelRequest, ink: Box):
    """The spot that touches the fewest lines and labels (nothing free anywhere)."""
    boxes, starts = _candidates(req, ink, NEAR + FAR, DIRECTIONS)
    gaps = np.repeat(np.asarray(NEAR + FAR), DIRECTIONS)
    k = int(np.argmin(_counts(ob, boxes, number=_number(req)) + 0.01 * gaps))
    box = tuple(boxes[k])
    return box, complex(starts[k]), (_leader(req.at, box) if gaps[k] >= FAR[0] else None)


def collisions(record: Record, clear: float = CHECK) -> list[str]:
    """Every label of the record that touches a line (within ``clear`` mm of the line's ink) or
    another label's ink: "text ↔ line" / "text ↔ text" with where, an empty list when none."""
    items = record.items
    texts = [p for p in items if p.kind == "text" and p.text.strip()]
    ob = obstacles([p for p in items if p.kind != "text"])
    out = []
    boxes = [p.ink() for p in texts]
    order = sorted(range(len(texts)), key=lambda k: boxes[k][0])
    for k in range(len(texts)):
        box = boxes[k]
        hit = _hits(ob, box, clear)
        if hit:
            j = hit[0]
            out.append(f"{texts[k].text!r} at ({box[0]:.1f}, {box[1]:.1f}) ↔ line "
                       f"({ob.segs[j][0]:.1f}, {ob.segs[j][1]:.1f})–({ob.segs[j][2]:.1f}, {ob.segs[j][3]:.1f})")
    for i, a in enumerate(order):          # labels against labels, swept along x
        for b in order[i + 1:]:
            if boxes[b][0] >= boxes[a][2]:
                break
            if _meets(boxes[a], boxes[b]):
                out.append(f"{texts[a].text!r} ↔ {texts[b].text!r} at ({boxes[a][0]:.1f}, {boxes[a][1]:.1f})")
    return out


ROW_STEP = 0.5       # mm: a row of numbers moves away from its axis by this much at a time …
ROW_REACH = 15.0     # … up to this far


def row_clear(record: Record, row: list[Primitive], away: tuple[float, float]) -> list[Primitive]:
    """A row of lettering set as one (the division numbers along a diagram's axis: a draftsman keeps
    them on one line) moved along ``away`` (a unit direction: down for numbers under a φ axis) by the
    least multiple of ``ROW_STEP`` at which none of them comes within ``CLEAR`` of a line of
    ``record`` (each by its own width: the French curve that dips below its lowest division point,
    a projection line) nor within ``APART`` of its lettering. Not found within ``ROW_REACH``: the
    row where it touches the fewest. Returns the row moved; the caller adds it to the record."""
    if not row:
        return row
    ob = obstacles(record.items)
    ink = np.asarray([p.ink() for p in row], dtype=float)
    ux, uy = away
    best, fewest = 0.0, None
    for k in range(int(ROW_REACH / ROW_STEP) + 1):
        d = k * ROW_STEP
        boxes = ink + np.array([ux * d, uy * d, ux * d, uy * d])
        hits = int(_counts(ob, boxes).sum())
        if fewest is None or hits < fewest:
            best, fewest = d, hits
        if hits == 0:
            break
    return [p.moved(ux * best, uy * best) for p in row]


def beside_first(record: Record, alternatives: list[LabelRequest], accept=None, layer: str = "labels") -> bool:
    """The first of ``alternatives`` (one label asked at several anchors) with a free spot right beside
    its anchor (``_near``: no leader) whose box ``accept`` takes, lettered there; False where none has
    one (the callers' next tries: thin lines broken under it, a leader)."""
    ob = obstacles(record.items)
    for req in alternatives:
        ink = Primitive("text", ((0.0, 0.0),), text=req.text, size=req.size).ink()
        size = (ink[2] - ink[0]) + (ink[3] - ink[1]) + CLEAR + 2.0
        spot = _near(ob.near(req.at, NEAR[-1] + size), req, ink, accept)
        if spot is not None:
            start = spot[1]
            record.label((start.real, start.imag), req.text, size=req.size, anchor="start", step=req.step,
                         layer=layer)
            return True
    return False


@_remembered
def place_first(record: Record, alternatives: list[LabelRequest], layer: str = "labels",
                accept=None) -> Record:
    """One label asked at several anchors in order of preference (a link's number at the middle of
    its bar, then a third and a quarter from either end): the first anchor with a free spot beside
    it takes it; when none has, the first asked with ``breaks`` where only thin lines are in the
    way, those broken under it (``_breaking``, as a joint's letter at a crowded pivot); else as ``place_labels`` places any
    label (farther out, on a leader) — a number stays by its bar, not 15 mm off it. ``accept``
    (box → bool): the spots beside an anchor that may take it (a link's number nearer its own bar
    than any other link's, outside their outlines: ``drawing.plans.number_owner``)."""
    if _SKETCH[-1] or not alternatives:
        return record
    if beside_first(record, alternatives, accept, layer):
        return record
    for req in (r for r in alternatives if r.breaks):   # by its bar, the thin lines broken under it
        ink = Primitive("text", ((0.0, 0.0),), text=req.text, size=req.size).ink()
        spot = _breaking(record, req, ink, accept)
        if spot is not None:
            box, start, _ = spot
            record.label((start.real, start.imag), req.text, size=req.size, anchor="start", step=req.step,
                         layer=layer)
            return record
    return place_labels(record, alternatives[:1], layer)


CROWD_MM = 4.0    # plan points closer than this: each letter must stand nearest its own point
OWN_MARGIN = 0.5  # mm: … at most half as far from it as from any other point, less this much


def _box_gap(box, z: complex) -> float:
    return abs(complex(max(box[0] - z.real, 0.0, z.real - box[2]), max(box[1] - z.imag, 0.0, z.imag - box[3])))


@_remembered
def place_owned(record: Record, requests: list[LabelRequest], layer: str = "labels") -> Record:
    """Labels of points that crowd one another (a plan's a, b and s2 within 4 mm): each is placed
    as ``place_labels`` places it, but only where its box is at most half as far from its own
    point as from any other (less ``OWN_MARGIN``) — else farther out on a leader from its point, which says whose it
    is; a label far from every other point is placed as any label. So "b" is never read as a's."""
    if _SKETCH[-1]:
        return record
    anchors = [r.at for r in requests]
    for req in requests:
        others = [z for z in anchors if abs(z - req.at) > 1e-9]
        if not any(abs(z - req.at) < CROWD_MM for z in others):
            place_labels(record, [req], layer)
            continue
        ob = obstacles(record.items)
        ink = Primitive("text", ((0.0, 0.0),), text=req.text, size=req.size).ink()
        size = (ink[2] - ink[0]) + (ink[3] - ink[1]) + CLEAR + 2.0

        def own(box) -> bool:
            mine = _box_gap(box, req.at)
            return all(_box_gap(box, z) >= 2.0 * mine + OWN_MARGIN for z in others)
        gaps = (max(req.gap, NEAR[0]),) + tuple(g for g in NEAR[1:] if g > req.gap)
        local = ob.near(req.at, NEAR[-1] + size)
        boxes, starts = _candidates(req, ink, gaps, 2 * DIRECTIONS)
        spot = next(((tuple(boxes[k]), complex(starts[k]), None)
                     for k in np.nonzero(_counts(local, boxes, number=_number(req)) == 0)[0]
                     if own(boxes[k]) and (not req.sight or _in_sight(local, req.at, boxes[k]))), None)
        if spot is None:
            spot = _far(ob.near(req.at, FAR[-1] + size), req, ink)
        if spot is None:
            place_labels(record, [req], layer)
            continue
        box, start, leader = spot
        if leader is not None:
            a, b = leader
            record.segment((a.real, a.imag), (b.real, b.imag), role="label", layer=layer, step=req.step)
        record.label((start.real, start.imag), req.text, size=req.size, anchor="start", step=req.step, layer=layer)
    return record


OWN_LINE_MM = 1.0    # a force's letter at least this much nearer its own arrow than any other arrow
LED_CLEAR = 2.0      # … or, on a leader from its head, at least this far from every other arrow


def _segments_cross(a: complex, b: complex, c: complex, d: complex) -> bool:
    """Whether the segments a–b and c–d meet."""
    def side(p: complex, q: complex, r: complex) -> float:
        return ((q - p).conjugate() * (r - p)).imag
    d1, d2, d3, d4 = side(c, d, a), side(c, d, b), side(a, b, c), side(a, b, d)
    return d1 * d2 <= 0 and d3 * d4 <= 0 and (d1 != d2 or d3 != d4)


LEADER_CLEAR = 0.0   # mm: a force's leader passes no other arrow nearer than this (LINK51's "G2" led along
                     # the head of Φ3 0.3 mm off read as Φ3's name)


def segment_gap(a: complex, b: complex, c: complex, d: complex) -> float:
    """The distance (mm) between the segments a–b and c–d: 0 where they meet, else the least of each
    one's ends to the other segment."""
    if _segments_cross(a, b, c, d):
        return 0.0
    return min(_off_segment(a, c, d), _off_segment(b, c, d), _off_segment(c, a, b), _off_segment(d, a, b))


def box_to_segment(box: Box, a: complex, b: complex) -> float:
    """The distance (mm) between a box and the segment a–b (0 where they meet): the least of the
    segment's ends to the box and the box's corners to the segment."""
    if _segment_meets_box(a, b, box):
        return 0.0
    d = b - a
    n2 = abs(d) ** 2

    def to_seg(z: complex) -> float:
        t = 0.0 if n2 < 1e-18 else min(max(((z - a) * d.conjugate()).real / n2, 0.0), 1.0)
        return abs(z - (a + t * d))
    corners = (complex(box[0], box[1]), complex(box[2], box[1]), complex(box[2], box[3]), complex(box[0], box[3]))
    return min([_box_gap(box, a), _box_gap(box, b)] + [to_seg(c) for c in corners])


def owns_line(box: Box, mine: tuple[complex, complex], others: list[tuple[complex, complex]],
              margin: float = OWN_LINE_MM) -> bool:
    """Whether a label's box reads as its own arrow's (``mine``, tail → head): nearer it than any of
    the ``others`` by ``margin`` and by half again its own distance."""
    d = box_to_segment(box, *mine)
    return all(box_to_segment(box, *o) >= max(d + margin, 1.5 * d) for o in others)


@_remembered
def place_owned_line(record: Record, alternatives: list[LabelRequest], mine: tuple[complex, complex],
                     others: list[tuple[complex, complex]], layer: str = "labels") -> Record:
    """A force's letter that must read as its own arrow's where other arrows pass near (Φ4 and P_E
    side by side at the press's ram): the first free spot beside the first of its anchors (its
    head, then along its shaft) that ``owns_line`` with no line between it and the anchor
    (``_in_sight``); else farther out, on a leader, where the box
    still does; else as ``place_labels`` places any label."""
    if _SKETCH[-1] or not alternatives:
        return record
    ob = obstacles(record.items)
    near = [o for o in others if min(abs(o[0] - mine[0]), abs(o[0] - mine[1]), abs(o[1] - mine[0]),
                                     abs(o[1] - mine[1])) < 200.0]
    for req in alternatives:
        ink = Primitive("text", ((0.0, 0.0),), text=req.text, size=req.size).ink()
        size = (ink[2] - ink[0]) + (ink[3] - ink[1]) + CLEAR + 2.0
        gaps = (max(req.gap, NEAR[0]),) + tuple(g for g in NEAR[1:] if g > req.gap)
        local = ob.near(req.at, NEAR[-1] + size)
        boxes, starts = _candidates(req, ink, gaps, 2 * DIRECTIONS)
        # … and no line between the letter and its anchor (stop 54: "Φ2" beside its head but across
        # the link AC, 4.5 mm out, read as the side AC's name)
        k = next((k for k in np.nonzero(_counts(local, boxes, number=_number(req)) == 0)[0]
                  if owns_line(tuple(boxes[k]), mine, near) and _in_sight(local, req.at, boxes[k])), None)
        if k is not None:
            record.label((starts[k].real, starts[k].imag), req.text, size=req.size, anchor="start",
                         step=req.step, layer=layer)
            return record
    req = alternatives[0]
    ink = Primitive("text", ((0.0, 0.0),), text=req.text, size=req.size).ink()
    size = (ink[2] - ink[0]) + (ink[3] - ink[1]) + CLEAR + 2.0
    seen: dict[tuple, tuple] = {}

    def measured(box) -> tuple:
        """A spot's leader, its box's distances to its own arrow and to each other, and whether the
        leader crosses one — measured once for the four searches below."""
        got = seen.get(box)
        if got is None:
            a, b = _leader(req.at, box)
            got = seen[box] = (a, b, box_to_segment(box, *mine), [box_to_segment(box, *o) for o in near],
                               any(_segments_cross(a, b, *o) for o in near), {})
        return got

    def led(box, clear: float = LEADER_CLEAR, nearer: bool = True) -> bool:
        """On a leader from its head: the box clear of the other arrows — ``nearer``: and nearer its
        own than any of them (FRC56_PUSHER's "R43" on a leader 11.8 mm from its arrow, 8.3 mm from
        G2's) —, the leader across none and ``clear`` of them (0: touching is allowed)."""
        a, b, mine_d, dists, crossed, gaps = measured(box)
        d = mine_d + OWN_LINE_MM if nearer else 0.0
        owns = all(x >= max(mine_d + OWN_LINE_MM, 1.5 * mine_d) for x in dists)     # ``owns_line``
        if crossed or not (owns or all(x >= max(LED_CLEAR, d) for x in dists)):
            return False
        if clear not in gaps:
            gaps[clear] = all(segment_gap(a, b, *o) >= clear for o in near)
        return gaps[clear]
    local = ob.near(req.at, FAR[-1] + size)
    # the box nearer its own arrow first; else (a knot of parallel arrows, where no box is) the leader
    # alone names it: its end on its own arrow, the box 2 mm clear of the others
    spot = _far(local, req, ink, led, lambda box: led(box, 0.0), lambda box: led(box, nearer=False),
                lambda box: led(box, 0.0, nearer=False))
    if spot is None:
        return place_labels(record, [req], layer)
    box, start, (a, b) = spot
    record.segment((a.real, a.imag), (b.real, b.imag), role="label", layer=layer, step=req.step)
    record.label((start.real, start.imag), req.text, size=req.size, anchor="start", step=req.step, layer=layer)
    return record


BESIDE_MM = 4.3     # mm: a label set beside its point with no leader no farther from it (farther reads as nobody's)
NUMBER_BESIDE = 3.0                 # … a diagram's point number (``place_beside``): review 4 asks ≤ 3 mm of paper
NUMBER_NEAR = (0.8, 1.5, 2.0, 2.5)  # the rings it tries (along a diagonal a ring's gap is √2 times: 2.5 → 3.5 mm,
#                                     which ``beside`` refuses); 2 and 2.5 where 1.5 mm is too near a steep line


def _led_all(at: complex, boxes: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``_leader`` of every candidate box at once: the leaders' starts and ends (complex arrays)."""
    near = np.clip(at.real, boxes[:, 0], boxes[:, 2]) + 1j * np.clip(at.imag, boxes[:, 1], boxes[:, 3])
    d = near - at
    n = np.abs(d)
    u = d / np.where(n == 0.0, 1.0, n)
    return at + 1.2 * u, near - (CLEAR + 0.3) * u


def _side_all(p, q, r):
    """((q − p)* · (r − p)).imag, broadcast (``_cross``'s side test)."""
    return (np.conj(q - p) * (r - p)).imag


def _crosses_all(a: np.ndarray, b: np.ndarray, c: np.ndarray, d: np.ndarray) -> np.ndarray:
    """For each leader a[i]–b[i]: whether it properly crosses any of the segments c[j]–d[j] (``_cross``)."""
    if len(a) == 0 or len(c) == 0:
        return np.zeros(len(a), dtype=bool)
    A, B = a[:, None], b[:, None]
    C, D = c[None, :], d[None, :]
    return np.any((_side_all(A, B, C) * _side_all(A, B, D) < 0) & (_side_all(C, D, A) * _side_all(C, D, B) < 0),
                  axis=1)


def _thick_all(ob: Obstacles, a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """``_crosses_thick`` of many leaders at once."""
    out = np.zeros(len(a), dtype=bool)
    if len(ob.segs) == 0 or len(a) == 0:
        return out
    s = ob.segs[ob.half >= THICK_HALF]
    if len(s) == 0:
        return out
    sx, sy, ex, ey = (v[None, :] for v in s.T)
    A, B = a[:, None], b[:, None]
    ux, uy = B.real - A.real, B.imag - A.imag
    vx, vy = ex - sx, ey - sy
    den = ux * vy - uy * vx
    with np.errstate(all="ignore"):
        t = ((sx - A.real) * vy - (sy - A.imag) * vx) / den
        v = ((sx - A.real) * uy - (sy - A.imag) * ux) / den
    return np.any((np.abs(den) > 1e-12) & (t > 0.0) & (t < 1.0) & (v > 0.0) & (v < 1.0), axis=1)


def _gap_all(boxes: np.ndarray, z: complex) -> np.ndarray:
    """``_box_gap`` of every box to the point z."""
    gx = np.maximum(np.maximum(boxes[:, 0] - z.real, 0.0), z.real - boxes[:, 2])
    gy = np.maximum(np.maximum(boxes[:, 1] - z.imag, 0.0), z.imag - boxes[:, 3])
    return np.abs(gx + 1j * gy)


def _owned_all(req: LabelRequest, boxes: np.ndarray, end: np.ndarray, strict: bool) -> np.ndarray:
    """``led_owned`` of every candidate (its box and its leader's end) at once."""
    return _owned_both(req, boxes, end)[0 if strict else 1]


def _owned_both(req: LabelRequest, boxes: np.ndarray, end: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``_owned_all`` strict and not, in one pass over the rivals (each rival's gaps and its test of
    the leader computed once for both; what does not depend on the rival, once): the same arithmetic,
    the same answers."""
    mine = _gap_all(boxes, req.at)
    strict = np.ones(len(boxes), dtype=bool)
    loose = np.ones(len(boxes), dtype=bool)
    d = end - req.at
    n2 = np.abs(d) ** 2
    dc = np.conj(d)
    tiny = np.abs(d) < 1e-12
    near_strict, near_loose = mine + 0.05, np.minimum(mine, RIVAL_BOX)
    for z in req.rivals:
        gap = _gap_all(boxes, z)
        strict &= ~(gap < near_strict)
        loose &= ~(gap < near_loose)
        if abs(z - req.at) < RIVAL_CLEAR:
            led = ~(((z - req.at) * dc).real > 0.0)
        else:
            with np.errstate(all="ignore"):
                t = np.where(tiny, 0.0, np.clip(((z - req.at) * dc).real / n2, 0.0, 1.0))
            led = ~(np.abs(z - (req.at + t * d)) < RIVAL_CLEAR)
        strict &= led
        loose &= led
    return strict, loose


@dataclass
class Leads:
    """The leader candidates of one label (``FAR`` rings × ``FAR_DIRECTIONS``, in ``_candidates``'
    order), each with its leader and what it meets — computed at once for every one, so that any
    order of preference among them costs no more than one pass (``place_beside``); or, ``lazy``, ring
    by ring as ``first`` reaches it (each candidate is judged on its own: the same answers; a number
    beside its diagram's point mostly finds its leader on the nearest rings — the drag-link's dynamics
    sheet judged its 1056 candidates each time, 40 % of its CPU)."""
    boxes: np.ndarray
    starts: np.ndarray
    a: np.ndarray
    b: np.ndarray
    base: np.ndarray | None    # free of lines and labels, the leader through no label, across no leader
    strict: np.ndarray | None  # the label nearer its point than any rival (``led_owned`` strict)
    loose: np.ndarray | None   # … at least ``RIVAL_BOX`` clear of them
    ob: Obstacles
    _along: dict
    lazy: tuple | None = None  # (req, steep, {ring: (base, strict, loose)}) where judged ring by ring

    def along(self, k: int) -> bool:
        """Whether candidate k's leader runs on a drawn line (``_along_line``; asked only of the
        candidates that pass every other test, in order, and remembered)."""
        if k not in self._along:
            self._along[k] = _along_line(self.ob, complex(self.a[k]), complex(self.b[k]))
        return self._along[k]

    def ring(self, r: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Ring r's (base, strict, loose)."""
        n = FAR_DIRECTIONS
        if self.lazy is None:
            return self.base[r * n:(r + 1) * n], self.strict[r * n:(r + 1) * n], self.loose[r * n:(r + 1) * n]
        req, steep, rings = self.lazy
        if r not in rings:       # the nearest ring alone (most numbers take a leader there), then the rest at once:
            lo, hi = (0, 1) if r == 0 else (1, len(self.boxes) // n)      # each judging call has its cost
            sl = slice(lo * n, hi * n)
            got = _judged_leads(self.ob, req, self.boxes[sl], self.a[sl], self.b[sl], None, steep)
            for j in range(lo, hi):
                rings[j] = tuple(x[(j - lo) * n:(j - lo + 1) * n] for x in got)
        return rings[r]

    def first(self, req: LabelRequest, extra: np.ndarray | str | None = None, off_lines: bool = False,
              reject=None) -> int | None:
        """The candidate ``_far`` takes where its ``ok`` is ``extra`` ("strict": the candidates'
        own ``strict``; and, where ``off_lines``, the leader along no line; ``reject(k)`` none of it):
        the passes (nearer its own point than the rivals, off the lines; then less near; then along a
        line) over the rings, a number's passes before its rings, a word's rings first; None where
        none passes."""
        n = FAR_DIRECTIONS
        if isinstance(extra, np.ndarray):
            extra = [extra[r * n:(r + 1) * n] for r in range(len(self.boxes) // n)]
        passes = ((("strict", True), ("loose", True), ("loose", False)) if req.rivals else ((None, False),))
        rings = range(len(self.boxes) // n)
        order = ([(p, r) for p in passes for r in rings] if is_number(req.text)
                 else [(p, r) for r in rings for p in passes])
        for (p, apart), r in order:
            base, strict, loose = self.ring(r)
            ok = base if extra is None else base & (strict if isinstance(extra, str) else extra[r])
            if p is not None:
                ok = ok & (strict if p == "strict" else loose)
            for k in (np.nonzero(ok)[0] + r * n).tolist():
                if (off_lines or apart) and self.along(k):
                    continue
                if reject is not None and reject(k):
                    continue
                return k
        return None


def _judged_leads(ob: Obstacles, req: LabelRequest, boxes: np.ndarray, a: np.ndarray, b: np.ndarray, worth,
                  steep: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``leads``' judgment of the candidates ``boxes`` with their leaders a → b: (base, strict, loose),
    each candidate on its own."""
    if worth is None:
        base = _counts(ob, boxes, number=_number(req)) == 0
    else:
        base = np.asarray(worth(np.abs(b - a)), dtype=bool)
        asked = np.nonzero(base)[0]
        if len(asked):
            base[asked] = _counts(ob, boxes[asked], number=_number(req)) == 0
    if steep > CLEAR and is_number(req.text):
        idx = np.nonzero(base)[0]
        if len(idx):
            base[idx[_steep_counts(ob, boxes[idx], steep) > 0]] = False
    if ob.boxes:
        q = np.asarray(ob.boxes, dtype=float)
        idx = np.nonzero(base)[0]
        if len(idx):
            A, B = a[idx][:, None], b[idx][:, None]
            meets = _clip_all(A.real, A.imag, B.real, B.imag, q[None, :, 0] - 0.7, q[None, :, 1] - 0.7,
                              q[None, :, 2] + 0.7, q[None, :, 3] + 0.7)
            base[idx[np.any(meets, axis=1)]] = False
    if ob.leaders:
        idx = np.nonzero(base)[0]
        c = np.asarray([c for c, _ in ob.leaders])
        d = np.asarray([d for _, d in ob.leaders])
        base[idx[_crosses_all(a[idx], b[idx], c, d)]] = False
    if not req.across:
        idx = np.nonzero(base)[0]
        base[idx[_thick_all(ob, a[idx], b[idx])]] = False
    idx = np.nonzero(base)[0]
    strict = np.ones(len(boxes), dtype=bool)
    loose = np.ones(len(boxes), dtype=bool)
    if req.rivals:
        strict[idx], loose[idx] = _owned_both(req, boxes[idx], b[idx])
    return base, strict, loose


def leads(ob: Obstacles, req: LabelRequest, ink: Box, rings: tuple[float, ...] = FAR, worth=None,
          steep: float = 0.0, lazy: bool = False) -> Leads:
    """Every leader candidate of a label (``Leads``) against the obstacles ``ob`` (those near it),
    on the ``rings`` (``FAR``, or its nearer ones); ``worth(lengths)``, where given, the candidates
    worth asking by their leaders' lengths (the others are not free: a caller that takes none of
    them saves counting them — each candidate is counted on its own, so the rest count the same);
    ``steep``: a number's box that far from a steep line at either side (``_steep_counts``);
    ``lazy``: judged ring by ring as ``Leads.first`` asks (its ``base``, ``strict``, ``loose`` then None)."""
    boxes, starts = _candidates(req, ink, rings, FAR_DIRECTIONS)
    a, b = _led_all(req.at, boxes)
    if lazy and worth is None:
        return Leads(boxes, starts, a, b, None, None, None, ob, {}, (req, steep, {}))
    base, strict, loose = _judged_leads(ob, req, boxes, a, b, worth, steep)
    return Leads(boxes, starts, a, b, base, strict, loose, ob, {})


@_remembered
def place_beside(record: Record, asked: list[LabelRequest], layer: str = "labels", beside: float = NUMBER_BESIDE,
                 avoid: np.ndarray | None = None, keep_whole: tuple[str, ...] = (), farthest: float | None = None) -> str:
    """Place one label near its point with a checked leader — a diagram's numbered point among its
    ``rivals`` (the other points: ``LabelRequest.rivals``). ``asked``: the same label asked in order
    of preference (in sight first, say); the last is the one set on a leader. In this order:

    1. "beside": by the first request with a free spot (``_near``) within ``beside`` mm of its point;
    2. "leader": on a leader from the point (``leads``) that crosses no label, no other leader, no
       thick line where not ``across``, passes no rival, runs along no drawn line, its label nearer
       its own point than any rival's — first a leader that crosses no ``avoid`` polyline (complex
       vertices: a curve whose branch a number across it would be read on), then one that may;
    3. "broken": beside it within ``beside`` mm where only thin lines are in the way, broken under it
       (``_breaking``) — never a line whose step is in ``keep_whole``;
    4. "leader": as 2. with the label merely ``RIVAL_BOX`` clear of the rivals;
    5. "leader": on any leader ``_far`` allows; 6. "placed": as ``place_labels`` places it — where
       ``farthest`` is given, only where that sets it within ``farthest`` mm of its point, else "off":
       left off (``place_labels``' last resorts, past the drawing's edge, set the baler's 12 80 mm away
       on its own projection line, stop 62).

    In 2. a leader across ``avoid`` is tried only after 3. and 4. found none that keeps off it (stop 55:
    a number beside its point with a thin line broken under it, or on a looser leader, reads as its
    point's; one across the curve reads as a point of the branch it crosses). A number keeps
    ``STEEP_CLEAR`` sideways from steep lines (beside or on a leader) and, beside, ``beside`` mm of
    its point at most (``NUMBER_NEAR``'s rings).

    Returns which ("" when sketched: nothing placed). A number reads as its own point's: beside it
    with nothing between, or at the end of a leader that says whose it is."""
    if _SKETCH[-1] or not asked:
        return ""
    ob = obstacles(record.items)
    for req in asked:
        ink = Primitive("text", ((0.0, 0.0),), text=req.text, size=req.size).ink()
        reach = (ink[2] - ink[0]) + (ink[3] - ink[1]) + CLEAR + 2.0
        spot = _near(ob.near(req.at, NEAR[-1] + reach), req, ink, steep=STEEP_CLEAR, rings=NUMBER_NEAR,
                     accept=lambda box, at=req.at: _box_gap(box, at) <= beside)
        if spot is not None and _box_gap(spot[0], req.at) <= beside:
            record.label((spot[1].real, spot[1].imag), req.text, size=req.size, anchor="start", step=req.step,
                         layer=layer)
            return "beside"
    req = asked[-1]
    ink = Primitive("text", ((0.0, 0.0),), text=req.text, size=req.size).ink()
    reach = (ink[2] - ink[0]) + (ink[3] - ink[1]) + CLEAR + 2.0
    cand = leads(ob.near(req.at, FAR[-1] + reach), req, ink, steep=STEEP_CLEAR, lazy=True)
    crossing: dict[int, bool] = {}

    def crosses(k: int) -> bool:             # the leader across the ``avoid`` polyline (asked lazily)
        if k not in crossing:
            crossing[k] = avoid is not None and len(avoid) > 1 and bool(_crosses_all(
                cand.a[k:k + 1], cand.b[k:k + 1], avoid[:-1], avoid[1:])[0])
        return crossing[k]
    k = None
    for stage in ("off", "broken", "off loose", "on", "on loose", "any"):
        if stage == "broken":
            if _break_beside(record, req, ink, layer, beside, keep_whole):
                return "broken"
            continue
        k = cand.first(req, None if stage in ("any",) or "loose" in stage else "strict",
                       off_lines=stage != "any", reject=crosses if stage.startswith("off") else None)
        if k is not None:
            break
    if k is None and is_number(req.text):     # the last resort still on a leader that says whose it is,
        cand = leads(ob.near(req.at, FAR[-1] + reach), req, ink, lazy=True)   # near a steep line where no spot
        k = cand.first(req, None, off_lines=False)                    # keeps clear (a crowded diagram)
    if k is None:
        before = list(record.items)
        place_labels(record, asked[:1], layer=layer)
        if farthest is not None and any(p.kind == "text" and _box_gap(p.ink(), req.at) > farthest
                                        for p in record.items[len(before):]):
            record.items[:] = before
            return "off"
        return "placed"
    a, b, start = complex(cand.a[k]), complex(cand.b[k]), complex(cand.starts[k])
    record.segment((a.real, a.imag), (b.real, b.imag), role="label", layer=layer, step=req.step)
    record.label((start.real, start.imag), req.text, size=req.size, anchor="start", step=req.step, layer=layer)
    return "leader"


def _break_beside(record: Record, req: LabelRequest, ink: Box, layer: str, beside: float,
                  keep_whole: tuple[str, ...]) -> bool:
    """The label set beside its point within ``beside`` mm, nearest it of all the rivals, where only
    thin lines are in the way — broken under it (``_breaking``); no line of a ``keep_whole`` step
    broken. Whether it was (the record unchanged where not)."""
    before = list(record.items)
    spot = _breaking(record, req, ink, accept=lambda box: _box_gap(box, req.at) <= beside, steep=STEEP_CLEAR,
                     rings=NUMBER_NEAR)
    whole = {id(p) for p in record.items}
    if spot is None or _box_gap(spot[0], req.at) > beside or any(
            p.step in keep_whole and id(p) not in whole for p in before):
        record.items[:] = before
        return False
    record.label((spot[1].real, spot[1].imag), req.text, size=req.size, anchor="start", step=req.step, layer=layer)
    return True


ALONG_LEADER_MM = 15.0   # a name on a leader from its own line: at most this long (a reader follows it at a glance)
ALONG_APART = 1.0        # mm more than ``APART`` between two names set along lines (a crowded plan's names
                         # closer than their height read as one another's)


@_remembered
def place_along(record: Record, req: LabelRequest, mine: tuple[complex, complex],
                others: list[tuple[complex, complex]], fractions: tuple[float, ...] = (1.0, 0.75, 0.5, 0.25),
                beside: float = BESIDE_MM, longest: float = ALONG_LEADER_MM, apart: float = ALONG_APART,
                layer: str = "labels", accept=None, loose: bool = False, thin: bool = False) -> str:
    """A name that belongs to a line — a force's arrow, an arm of the Zhukovsky lever (``mine``,
    a → b) — set where it reads as that line's, not as any of the ``others``' (``owns_line``):

    1. "beside": free, within ``beside`` mm of one of the points of ``mine`` at ``fractions`` of
       its length (the head first for an arrow), either side — the nearer rings of all the points
       before the farther ones;
    2. "leader": on the shortest leader (≤ ``longest`` mm) from one of those points that crosses
       no drawn line, no label and no other leader, runs along no line, its label owning the line
       or ``LED_CLEAR`` clear of every other;
    3. "" — nothing placed (the caller sets it as any label).

    Other names are kept ``APART`` + ``apart`` away; ``accept(box)``, where given, must hold too
    (a stretch of a line shared with others: the name over its own stretch). ``loose``: a name
    merely nearer its own line than any other owns it (where lines crowd); ``thin``: the leader
    may cross thin lines (construction, projections), never a thick one. ``req.at`` is unused (the points along the
    line are the anchors); ``req.toward`` the side preferred."""
    from dataclasses import replace
    if _SKETCH[-1]:
        return ""
    a0, b0 = mine
    ob = obstacles(record.items)
    if apart:
        ob.boxes = [(x0 - apart, y0 - apart, x1 + apart, y1 + apart) for x0, y0, x1, y1 in ob.boxes]
    ink = Primitive("text", ((0.0, 0.0),), text=req.text, size=req.size).ink()
    reach = (ink[2] - ink[0]) + (ink[3] - ink[1]) + CLEAR + 2.0
    span = abs(b0 - a0)
    def own(box) -> bool:
        if loose:      # nearer its own line than any other by a margin, whatever the font's side bearings
            d = box_to_segment(box, a0, b0)
            return all(box_to_segment(box, *o) > d + 1.0 for o in near)
        return owns_line(box, mine, near)
    near = [o for o in others if min(abs(o[0] - a0), abs(o[1] - b0), abs(o[0] - b0), abs(o[1] - a0))
            < span + 2 * (FAR[-1] + reach) + abs(o[1] - o[0])]
    anchors = [a0 + t * (b0 - a0) for t in fractions]
    gaps = (max(req.gap, NEAR[0]),) + tuple(g for g in NEAR[1:] if g > req.gap)
    n = 2 * DIRECTIONS
    found = [_candidates(replace(req, at=z), ink, gaps, n) for z in anchors]
    local = ob.near(0.5 * (a0 + b0), 0.5 * span + NEAR[-1] + reach)
    for r in range(len(gaps) if found else 0):
        # ring by ring, all the anchors' candidates on it counted at once (most names stand on the first)
        ring = _counts(local, np.concatenate([boxes[r * n:(r + 1) * n] for boxes, _ in found]), number=_number(req))
        for i, (boxes, starts) in enumerate(found):
            for k in (np.nonzero(ring[i * n:(i + 1) * n] == 0)[0] + r * n).tolist():
                box = tuple(float(v) for v in boxes[k])
                if (box_to_segment(box, a0, b0) <= beside and own(box)
                        and (accept is None or accept(box))):
                    record.label((starts[k].real, starts[k].imag), req.text, size=req.size, anchor="start",
                                 step=req.step, layer=layer)
                    return "beside"
    best = None
    for i, z in enumerate(anchors if longest > 0 else ()):
        sub = ob.near(z, min(FAR[-1], longest) + reach)
        # (a ring g out gives leaders at least g − 2 mm long: the farther rings are not asked)
        # only the leaders that could be taken: no longer than ``longest``, shorter than the best so far
        bound = best[0] - 1e-9 if best is not None else math.inf
        cand = leads(sub, replace(req, at=z, across=False), ink, tuple(g for g in FAR if g <= longest + 2.0),
                     worth=lambda lengths, bound=bound: (lengths <= longest) & (lengths < bound))
        length = np.abs(cand.b - cand.a)
        ok = cand.base & (length <= longest)
        idx = np.nonzero(ok)[0]
        s = sub.segs[sub.half >= THICK_HALF] if thin else sub.segs
        if len(idx) and len(s):
            crossing = _crosses_all(cand.a[idx], cand.b[idx], s[:, 0] + 1j * s[:, 1], s[:, 2] + 1j * s[:, 3])
            idx = idx[~crossing]
        for k in idx[np.argsort(length[idx], kind="stable")].tolist():
            if best is not None and length[k] >= best[0] - 1e-9:
                break
            box = tuple(float(v) for v in cand.boxes[k])
            a, b = complex(cand.a[k]), complex(cand.b[k])
            if cand.along(k) or any(_segments_cross(a, b, *o) for o in near):
                continue
            if accept is not None and not accept(box):
                continue
            if own(box) or all(box_to_segment(box, *o) >= LED_CLEAR + 0.9 for o in near):
                best = (float(length[k]), a, b, complex(cand.starts[k]))
                break
    if best is None:
        return ""
    _, a, b, start = best
    record.segment((a.real, a.imag), (b.real, b.imag), role="label", layer=layer, step=req.step)
    record.label((start.real, start.imag), req.text, size=req.size, anchor="start", step=req.step, layer=layer)
    return "leader"
