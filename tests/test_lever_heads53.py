"""Stop 53: the lever of the articulated-rod compressor (LINK53, the lead's check) drew M^Φ2'' leaving
a and M^Φ4'' leaving k head to head — their two names between them, each nearer the other's arrow.
An arrow whose head would end on another's is drawn pushing, its head at its image. The truths are
the drawn arrows' measured ends."""
from __future__ import annotations

from itertools import combinations

import pytest

from conftest import scene_force_plans


def _to_segment(z: complex, a: complex, b: complex) -> float:
    """The distance from z to the segment ab (by hand: the foot clamped to the segment)."""
    d = b - a
    t = 0.0 if abs(d) == 0 else max(0.0, min(1.0, ((z - a) * d.conjugate()).real / abs(d) ** 2))
    return abs(z - (a + t * d))


def test_arrows_ending_on_arrows_by_hand():
    """An arrow of the image 20j whose head ends 1 mm from another's head, or 0.5 mm from its shaft,
    or 1 mm from another image, ends on it; one leaving the other's image, or parallel 5 mm off, does
    not."""
    from graphplan.drawing.forces import _ends_on
    drawn, images = [(0j, 0j, 10 + 0j)], [0j, 20j, 30 + 30j]
    assert _ends_on(20j, 10 + 20j, 10 + 1j, drawn, images)
    assert _ends_on(20j, 5 + 20j, 5 + 0.5j, drawn, images)
    assert _ends_on(20j, 20j, 29 + 29j, drawn, images)
    assert not _ends_on(0j, 0j, 10j, drawn, images)
    assert not _ends_on(20j, 5j, 10 + 5j, drawn, images)


@pytest.fixture(scope="module")
def lever_arrows():
    import review_scenes
    from graphplan.drawing.forces import lever_record
    fp = scene_force_plans(review_scenes.LINK53)
    rec = lever_record(fp, "uk")
    return [(complex(*q.points[0]), complex(*q.points[1])) for q in rec.items
            if q.kind == "vector" and q.layer == "vectors"]


def test_no_two_lever_arrows_meet_head_to_head(lever_arrows):
    """On LINK53's lever no arrow's head lies within 3 mm of another's head or 1 mm of its shaft
    (but at its image: the arrows pushing into one image)."""
    assert len(lever_arrows) >= 10
    for (a1, b1), (a2, b2) in combinations(lever_arrows, 2):
        assert abs(b1 - b2) >= 3.0, ((a1, b1), (a2, b2))
        assert _to_segment(b1, a2, b2) >= 1.0 or abs(b1 - a2) < 1.0, ((a1, b1), (a2, b2))
        assert _to_segment(b2, a1, b1) >= 1.0 or abs(b2 - a1) < 1.0, ((a1, b1), (a2, b2))
