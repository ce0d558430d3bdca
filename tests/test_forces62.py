"""Stop 62 (frc62): LINK62's group II(4-5) graded as a teacher would — the pin B inside the block of the
slotted lever and S5's dot 9 mm down the lever: «B» stood nearer S5's dot than B's circle (a reader took
the dot for B); G4 from B showed a 7-mm stub under the block, its name on a 25-mm leader; on the scheme G4
and Φ4 arrived at B with their heads hidden inside the two blocks there.

Measured on the drawings (the records' own geometry): each point's letter stands nearer its own point than
any other lettered point of the drawing; each arrow leaving a block's centre shows at least ``SHOWN_MM`` out
of the block; no arrow's head (its tip) lies inside a block.
"""
from __future__ import annotations

import pytest

from conftest import scene_force_plans


def _blocks(rec) -> list[list[complex]]:
    """The sliders' blocks drawn (8 × 5 mm rectangles: ``drawing.forces._block``)."""
    out = []
    for q in rec.items:
        if q.kind == "polygon" and q.role == "link" and len(q.points) == 4:
            zs = [complex(*p) for p in q.points]
            sides = sorted(abs(zs[(k + 1) % 4] - zs[k]) for k in range(4))
            if abs(sides[0] - 5.0) < 1e-6 and abs(sides[-1] - 8.0) < 1e-6:
                out.append(zs)
    return out


def _inside(z: complex, box: list[complex], tol: float = 0.05) -> bool:
    """Whether z lies inside the rectangle (by more than ``tol`` from its edges)."""
    c = sum(box) / 4
    u, v = box[1] - box[0], box[3] - box[0]
    w = z - c
    return (abs((w * u.conjugate()).real) / abs(u) < abs(u) / 2 - tol
            and abs((w * v.conjugate()).real) / abs(v) < abs(v) / 2 - tol)


def _out_of(a: complex, b: complex, box: list[complex], n: int = 400) -> float:
    """How much of the segment a→b lies outside the rectangle, mm (sampled)."""
    return abs(b - a) * sum(not _inside(a + (b - a) * (k + 0.5) / n, box, 0.0) for k in range(n)) / n


def _records(scene: str, **scales):
    from graphplan.drawing.forces import group_record, mechanism_record
    fp = scene_force_plans(scene, **scales)
    return fp, [group_record(fp, gp, "uk") for gp in fp.groups] + [mechanism_record(fp)]


@pytest.fixture(scope="module")
def link62():
    from review_scenes import LINK62
    return _records(LINK62, mu_l=0.0025)      # its A1 sheet's scheme and II(4-5)


def test_link62s_b_is_lettered_by_its_pin_not_by_s5(link62):
    from graphplan.drawing.labels import _box_gap
    _, recs = link62
    g45 = next(r for r in recs if r.title.startswith("II(4-5)"))
    points = [complex(*q.points[0]) for q in g45.items if q.kind == "point"]
    texts = {q.text: q for q in g45.items if q.kind == "text" and q.layer == "labels"}
    b_box = texts["B"].ink()
    # B is the joint drawn inside a block; S5 the dot nearest it
    block = _blocks(g45)
    assert block, "the block 4 at B is drawn"
    b = next(z for z in points if _inside(z, block[0]))
    s5 = min((z for z in points if abs(z - b) > 0.5), key=lambda z: abs(z - b))
    assert abs(s5 - b) < 15.0
    assert _box_gap(b_box, b) < _box_gap(b_box, s5), (_box_gap(b_box, b), _box_gap(b_box, s5))


def test_link62s_arrows_at_blocks_show_out_of_them(link62):
    from graphplan.drawing.forces import SHOWN_MM
    _, recs = link62
    seen_leaving = seen_arriving = 0
    for rec in recs:
        blocks = _blocks(rec)
        for q in rec.items:
            if q.kind != "vector" or q.role not in ("absolute", "result", "relative"):
                continue
            a, b = complex(*q.points[0]), complex(*q.points[1])
            for box in blocks:
                c = sum(box) / 4
                assert not _inside(b, box), (rec.title, q.text, "its head inside a block")
                if abs(a - c) < 0.5:
                    seen_leaving += 1
                    assert _out_of(a, b, box) >= SHOWN_MM - 0.05, (rec.title, q.text, _out_of(a, b, box))
                if abs(b - c) < 12.0 and abs(((b - a) * (c - b).conjugate()).imag) < 1e-6 * abs(b - a) * abs(c - b) \
                        and ((b - a) * (c - b).conjugate()).real > 0:
                    seen_arriving += 1          # pushing toward the block's centre along its own line
    assert seen_leaving >= 5 and seen_arriving >= 1, (seen_leaving, seen_arriving)
