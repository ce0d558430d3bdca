"""Lettering that never overprints: the one label placer of every drawing, and the check of a record.

A label is a box of ink (its letters' glyph boxes, ``Primitive.ink``). It is placed where that box,
grown by a clearance, meets no line of the drawing (each line by its own width) and no other label:
first at candidate spots around its point (the preferred side first, 1–3 mm off), then — when none
is free — farther out with a short thin leader from the point to it (the leader stops short of the
letters). An optional label (a position number) that finds no free spot is left out; a label that
must be drawn and finds none goes to the least crowded spot, and ``collisions`` reports it.

``collisions(record)`` is the same geometry used as a check: every label against every line and
every other label of the record (the tests run it on whole sheets).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from graphplan.graphic.record import LabelRequest, Primitive, Record, arrowhead

Box = tuple[float, float, float, float]

CLEAR = 0.5          # mm of paper between a label's ink and a line's ink when placing
CHECK = 0.3          # … the least the check accepts (a reader sees 0.25 mm as touching)
APART = 1.0          # mm between two labels' ink
DIRECTIONS = 16      # candidate directions around a point
NEAR = (0.8, 1.5, 3.0)                    # mm from the point to the box: beside it
FAR = (5.0, 7.0, 9.5, 12.5, 16.0, 20.0, 25.0, 32.0)   # … farther out, with a leader


@dataclass
class Obstacles:
    """A record's lines as segments with their half widths (mm), and its labels' ink boxes."""
    segs: np.ndarray        # (n, 4): x1, y1, x2, y2
    half: np.ndarray        # (n,): half the line width
    boxes: list[Box]
    solid: list[Box]        # closed figures whose inside stays free of lettering (slider blocks)

    def __post_init__(self) -> None:
        self._reach()

    def _reach(self) -> None:
        """Each segment's own box grown by its half width, for a quick reject."""
        s, h = self.segs, self.half
        self.lo_x = np.minimum(s[:, 0], s[:, 2]) - h
        self.hi_x = np.maximum(s[:, 0], s[:, 2]) + h
        self.lo_y = np.minimum(s[:, 1], s[:, 3]) - h
        self.hi_y = np.maximum(s[:, 1], s[:, 3]) + h

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
        tip = arrowhead(pts[0], pts[1], length=3.0 if p.line_width >= 0.5 else 2.5)
        out += [(tip[0], tip[1], 0.05), (tip[1], tip[2], 0.05), (tip[2], tip[0], 0.05)]
    out += [(a, b, hw) for a, b in zip(pts, pts[1:])]
    return out


def obstacles(items: list[Primitive]) -> Obstacles:
    """What a new label must keep clear of, from the primitives already drawn."""
    segs, half, boxes, solid = [], [], [], []
    for p in items:
        if p.kind == "text":
            boxes.append(p.ink())
            continue
        for a, b, hw in strokes(p):
            segs.append((a[0], a[1], b[0], b[1]))
            half.append(hw)
        if p.kind == "polygon":
            solid.append(p.bounds())
    return Obstacles(np.array(segs, dtype=float).reshape(-1, 4), np.array(half, dtype=float), boxes, solid)


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


def _conflicts(ob: Obstacles, box: Box, clear: float = CLEAR) -> int:
    """How many lines and labels the box would touch (a closed figure's inside counts too)."""
    n = len(_hits(ob, box, clear))
    n += sum(_meets(box, b, APART) for b in ob.boxes)
    n += sum(_meets(box, s) for s in ob.solid)
    return n


def _segment_meets_box(a: complex, b: complex, box: Box) -> bool:
    return _clips(a.real, a.imag, b.real, b.imag, *box)


def _box_at(at: complex, u: complex, w: float, ink: Box, gap: float) -> tuple[Box, complex]:
    """The ink box of a label whose ink lies wholly on the side ``u`` of ``at``, ``gap`` clear of it,
    and the text's anchor (its start on the baseline) for that place."""
    iw, ih = ink[2] - ink[0], ink[3] - ink[1]
    m = max(abs(u.real), abs(u.imag))
    centre = at + complex(u.real / m * (iw / 2 + gap), u.imag / m * (ih / 2 + gap))
    box = (centre.real - iw / 2, centre.imag - ih / 2, centre.real + iw / 2, centre.imag + ih / 2)
    start = complex(box[0] - ink[0], box[1] - ink[1])
    return box, start


def _directions(toward: complex, n: int = DIRECTIONS) -> list[complex]:
    """``n`` unit directions around a point: the preferred one, then alternately either side of it."""
    pref = toward / abs(toward) if abs(toward) > 1e-12 else 1j
    out = []
    for k in range(n):
        j = (k + 1) // 2 * (1 if k % 2 else -1)
        out.append(pref * complex(math.cos(2 * math.pi * j / n), math.sin(2 * math.pi * j / n)))
    return out


def place_labels(record: Record, requests: list[LabelRequest], layer: str = "labels") -> Record:
    """Add the labels to ``record`` where they overprint nothing (see the module's docstring);
    returns the record."""
    ob = obstacles(record.items)
    for req in requests:
        probe = Primitive("text", ((0.0, 0.0),), text=req.text, size=req.size)
        ink = probe.ink()
        spot = _near(ob, req, ink) or _far(ob, req, ink)
        leader = None
        if spot is None:
            if req.optional:
                continue
            spot = _least(ob, req, ink)
        box, start, leader = spot
        if leader is not None:
            a, b = leader
            record.segment((a.real, a.imag), (b.real, b.imag), role="label", layer=layer, step=req.step)
            ob.add_segment((a.real, a.imag), (b.real, b.imag), 0.125)
        record.label((start.real, start.imag), req.text, size=req.size, anchor="start", step=req.step, layer=layer)
        ob.boxes.append(box)
    return record


def _near(ob: Obstacles, req: LabelRequest, ink: Box):
    w = ink[2] - ink[0]
    for gap in (max(req.gap, NEAR[0]),) + tuple(g for g in NEAR[1:] if g > req.gap):
        for u in _directions(req.toward):
            box, start = _box_at(req.at, u, w, ink, gap)
            if _conflicts(ob, box) == 0:
                return box, start, None
    return None


def _far(ob: Obstacles, req: LabelRequest, ink: Box):
    """A free spot farther out, joined to the point by a leader that crosses no label."""
    w = ink[2] - ink[0]
    for gap in FAR:
        for u in _directions(req.toward, 2 * DIRECTIONS):
            box, start = _box_at(req.at, u, w, ink, gap)
            if _conflicts(ob, box) != 0:
                continue
            a, b = _leader(req.at, box)
            if any(_segment_meets_box(a, b, (q[0] - 0.4, q[1] - 0.4, q[2] + 0.4, q[3] + 0.4)) for q in ob.boxes):
                continue
            return box, start, (a, b)
    return None


def _leader(at: complex, box: Box) -> tuple[complex, complex]:
    """A leader from just off the point to just short of the box (its nearest point)."""
    near = complex(min(max(at.real, box[0]), box[2]), min(max(at.imag, box[1]), box[3]))
    d = near - at
    n = abs(d) or 1.0
    u = d / n
    return at + 1.2 * u, near - (CLEAR + 0.3) * u


def _least(ob: Obstacles, req: LabelRequest, ink: Box):
    """The spot that touches the fewest lines and labels (nothing free anywhere)."""
    w = ink[2] - ink[0]
    best = None
    for gap in NEAR + FAR:
        for u in _directions(req.toward):
            box, start = _box_at(req.at, u, w, ink, gap)
            score = _conflicts(ob, box) + 0.01 * gap
            if best is None or score < best[0]:
                leader = _leader(req.at, box) if gap >= FAR[0] else None
                best = (score, box, start, leader)
    assert best is not None
    return best[1], best[2], best[3]


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
