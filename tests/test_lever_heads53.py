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


def test_the_balancing_force_passes_over_no_other_image():
    """LINK53 at φ = 240° (the working stroke, P_B = 1800 N): a and k lie on one vertical of the
    lever and P_зр, ⊥ p_v a, ran up from a through k (the arrows at k and s2 ending on its shaft).
    It is drawn the other way, into a: no image but a within 3 mm of its arrow."""
    import review_scenes
    from graphplan.drawing.forces import lever_record
    text = review_scenes.LINK53.replace("force_phi_deg = 60", "force_phi_deg = 240")
    assert text != review_scenes.LINK53
    fp = scene_force_plans(text)
    lv = fp.lever
    rec = lever_record(fp, "uk")
    tail, tip = next((complex(*q.points[0]), complex(*q.points[1])) for q in rec.items
                     if q.kind == "vector" and q.role == "result")
    a = 1j * lv.images[fp.ks.mech.crank.pin]
    assert min(abs(tail - a), abs(tip - a)) < 2.0 * 1.8 + 1e-6        # at a (or a lane or two off)
    others = [1j * z for name, z in lv.images.items() if abs(1j * z - a) > 0.5 and abs(z) > 0.1]
    assert all(_to_segment(z, tail, tip) >= 3.0 for z in others), (tail, tip, others)
