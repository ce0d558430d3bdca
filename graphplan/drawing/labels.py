"""Placing labels on a drawing so they collide neither with each other nor with its lines.

A label is tried at candidate places around its anchor (its preferred side first); each place is
scored by the lines its box crosses and the labels it overlaps, and the best one is taken. Optional
labels (position numbers) are dropped when no free place is left.
"""
from __future__ import annotations

import math

import numpy as np

from graphplan.graphic.record import LabelRequest, Primitive, Record, text_width

STEPS = 16         # candidate directions around an anchor


def _segments(items: list[Primitive]) -> np.ndarray:
    """Obstacles as segments (x1, y1, x2, y2): lines, vectors, polylines, arcs as chords."""
    segs: list[tuple[float, float, float, float]] = []
    for p in items:
        if p.layer == "labels" or p.kind == "text":
            continue
        pts = list(p.points)
        if p.kind in ("circle", "arc"):
            (cx, cy), r = p.points[0], p.radius
            a0, a1 = p.angles if p.kind == "arc" else (0.0, 360.0)
            sweep = (a1 - a0) % 360.0 or 360.0
            n = max(4, int(sweep / 10))
            pts = [(cx + r * math.cos(math.radians(a0 + sweep * k / n)),
                    cy + r * math.sin(math.radians(a0 + sweep * k / n))) for k in range(n + 1)]
        elif p.kind == "point":
            (x, y), = p.points
            pts = [(x - 0.6, y), (x + 0.6, y)]
        elif p.kind == "polygon":
            pts = pts + pts[:1]
        for (x1, y1), (x2, y2) in zip(pts, pts[1:]):
            segs.append((x1, y1, x2, y2))
    return np.array(segs, dtype=float).reshape(-1, 4)


def _crossings(segs: np.ndarray, box: tuple[float, float, float, float]) -> int:
    """How many segments pass through the box (Liang–Barsky clipping, vectorised)."""
    if len(segs) == 0:
        return 0
    x0, y0, x1, y1 = box
    sx, sy, ex, ey = segs.T
    dx, dy = ex - sx, ey - sy
    t0 = np.zeros(len(segs))
    t1 = np.ones(len(segs))
    ok = np.ones(len(segs), dtype=bool)
    for p, q in ((-dx, sx - x0), (dx, x1 - sx), (-dy, sy - y0), (dy, y1 - sy)):
        zero = np.abs(p) < 1e-12
        ok &= ~(zero & (q < 0))
        with np.errstate(all="ignore"):
            r = np.where(zero, 0.0, q / np.where(zero, 1.0, p))
        t0 = np.where(~zero & (p < 0), np.maximum(t0, r), t0)
        t1 = np.where(~zero & (p > 0), np.minimum(t1, r), t1)
    return int(np.count_nonzero(ok & (t0 <= t1)))


def _overlap(a: tuple[float, float, float, float], b: tuple[float, float, float, float]) -> float:
    w = min(a[2], b[2]) - max(a[0], b[0])
    h = min(a[3], b[3]) - max(a[1], b[1])
    return w * h if w > 0 and h > 0 else 0.0


def _box(centre: complex, w: float, h: float) -> tuple[float, float, float, float]:
    return centre.real - w / 2, centre.imag - h / 2, centre.real + w / 2, centre.imag + h / 2


def place_labels(record: Record, requests: list[LabelRequest], layer: str = "labels") -> Record:
    """Add the labels to ``record`` at the least crowded places; returns the record."""
    segs = _segments(record.items)
    taken: list[tuple[float, float, float, float]] = [
        p.bounds() for p in record.items if p.kind == "text"]
    # closed figures (slider blocks) keep labels out of their inside too
    solid = [p.bounds() for p in record.items if p.kind == "polygon"]
    for req in requests:
        w, h = text_width(req.text, req.size), req.size
        pref = req.toward / abs(req.toward) if abs(req.toward) > 1e-12 else 1j
        best = None
        for k in range(STEPS):
            # alternate sides of the preferred direction: 0, +1, −1, +2, −2, …
            j = (k + 1) // 2 * (1 if k % 2 else -1)
            u = pref * complex(math.cos(2 * math.pi * j / STEPS), math.sin(2 * math.pi * j / STEPS))
            for extra in (0.0, 1.5, 4.0):
                # the box lies wholly on the side u of the anchor, ``gap`` clear of it
                m = max(abs(u.real), abs(u.imag))
                g = req.gap + extra
                centre = req.at + complex(u.real / m * (w / 2 + g), u.imag / m * (h / 2 + g))
                box = _box(centre, w, h)
                score = 10.0 * sum(_overlap(box, t) > 0 for t in taken) + _crossings(segs, box)
                score += 2.0 * sum(_overlap(box, t) > 0 for t in solid)
                score += 0.02 * abs(j) + 0.05 * extra
                if best is None or score < best[0]:
                    best = (score, box)
            if best[0] < 0.5:
                break
        assert best is not None
        if req.optional and best[0] >= 1.0:
            continue
        x0, y0, x1, _ = best[1]
        record.label(((x0 + x1) / 2, y0 + 0.22 * h), req.text, size=req.size, anchor="middle",
                     step=req.step, layer=layer)
        taken.append(best[1])
    return record
