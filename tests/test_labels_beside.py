"""drawing.labels.place_beside, the contract of "a label near its point with a checked leader" (the
energy–mass diagram's numbered points): beside its point within ``beside`` mm where a spot is free;
else on a leader that crosses no ``avoid`` polyline where one can, its label nearer its own point
than any rival, the leader along no line and through no lettering; nothing while sketched."""
from __future__ import annotations

import numpy as np

from graphplan.drawing.labels import (BESIDE_MM, _box_gap, collisions, place_beside, sketched)
from graphplan.graphic.record import LabelRequest, Record


def _cross(a, b, c, d) -> bool:
    def side(p, q, r):
        return ((q - p).conjugate() * (r - p)).imag
    return side(a, b, c) * side(a, b, d) < 0 and side(c, d, a) * side(c, d, b) < 0


def _added(rec: Record, before: int):
    new = rec.items[before:]
    text = [p for p in new if p.kind == "text"]
    leader = [p for p in new if p.kind == "segment" and p.role == "label"]
    return text, leader


def test_a_free_point_gets_its_label_beside_it_without_a_leader():
    rec = Record("free")
    rec.point((0.0, 0.0), role="construction")
    rec.segment((-20.0, -3.0), (20.0, -3.0), role="construction")
    n = len(rec.items)
    how = place_beside(rec, [LabelRequest(0j, "7", 1 + 1j, 2.5)])
    text, leader = _added(rec, n)
    assert how == "beside" and len(text) == 1 and not leader
    assert _box_gap(text[0].ink(), 0j) <= BESIDE_MM
    assert collisions(rec) == []


def test_a_crowded_point_gets_a_leader_off_the_avoided_curve_its_label_nearest_it():
    """The point in a hatch of thin lines 1 mm apart (no room within 4.3 mm); a curve to avoid just
    right of it, a rival point above it: the label ends on a leader, the leader crosses the curve
    nowhere, runs along no hatch line (not level), and its label is nearer its own point than the
    rival."""
    rec = Record("crowded")
    for y in np.arange(-9.0, 9.5, 1.0):
        rec.segment((-9.0, float(y)), (9.0, float(y)), role="projection", layer="construction")
    curve = np.array([complex(6.0, y) for y in np.linspace(-40.0, 40.0, 81)])
    rec.add("polyline", [(z.real, z.imag) for z in curve], role="curve")
    rec.point((0.0, 0.0), role="construction")
    rival = complex(0.0, 14.0)
    rec.point((rival.real, rival.imag), role="construction")
    n = len(rec.items)
    req = LabelRequest(0j, "12", 1 + 1j, 2.5, across=False, rivals=(rival,))
    how = place_beside(rec, [req], avoid=curve)
    text, leader = _added(rec, n)
    assert how == "leader" and len(text) == 1 and len(leader) == 1
    a, b = (complex(*p) for p in leader[0].points)
    assert abs(a) < 2.0                                   # from the point …
    assert _box_gap(text[0].ink(), b) < 1.5               # … to its label
    assert not any(_cross(a, b, p, q) for p, q in zip(curve, curve[1:]))
    assert abs((b - a).imag) > 0.2 * abs(b - a)           # not along a level hatch line
    box = text[0].ink()
    assert _box_gap(box, 0j) < _box_gap(box, rival)
    assert not [c for c in collisions(rec) if c.startswith("'12'")]


def test_nothing_is_drawn_when_sketched():
    rec = Record("sketch")
    rec.point((0.0, 0.0), role="construction")
    n = len(rec.items)
    with sketched():
        assert place_beside(rec, [LabelRequest(0j, "3", 1j, 2.5)]) == ""
    assert len(rec.items) == n
