"""Stop 53: the wedge press's wedge (WEDGE52's link B: a block on the frame's guide x, its inclined
face at 150° the slot the ram's block C rides in) drawn on the force scheme and its group as the
kinematics sheet draws it — the triangle of its joint B and the slot's ends — not as a bar from B to
C with its face missing. The truths are the scene's guide angle and the points' positions."""
from __future__ import annotations

import cmath
import math

import pytest

from conftest import scene_force_plans


@pytest.fixture(scope="module")
def fp():
    import review_scenes
    return scene_force_plans(review_scenes.WEDGE52)


def _at(fp, link: str, point: str) -> complex:
    lk = fp.ks.mech.links[link]
    return complex(fp.ks.kin.bodies[link].at(lk.local[point])[0][0]) / fp.mu_l


def _to_segment(z: complex, a: complex, b: complex) -> float:
    d = b - a
    t = max(0.0, min(1.0, ((z - a) * d.conjugate()).real / abs(d) ** 2))
    return abs(z - (a + t * d))


def test_the_wedge_is_its_joint_and_its_inclined_face(fp):
    """The outline is closed, B one of its corners, the side opposite B along 150° (the scene's
    guide on the wedge, which slides without turning) with C's block on it."""
    from graphplan.drawing.forces import _link_outline
    out = _link_outline(fp, "B", fp.mu_l)
    assert len(out) == 4 and abs(out[0] - out[-1]) < 1e-9, out
    b, c = _at(fp, "B", "B"), _at(fp, "C", "C")
    assert abs(out[1] - b) < 1e-6, (out, b)
    face = out[2] - out[0]
    assert math.isclose(math.degrees(cmath.phase(face)) % 180.0, 150.0, abs_tol=1e-6)
    assert _to_segment(c, out[0], out[2]) < 1e-6


def test_a_plain_link_keeps_its_bar(fp):
    """The rod AB (no guide on it) is drawn from A to B as before."""
    from graphplan.drawing.forces import _link_outline
    out = _link_outline(fp, "AB", fp.mu_l)
    a, b = _at(fp, "AB", "A"), _at(fp, "AB", "B")
    assert min(abs(out[0] - a), abs(out[-1] - a)) < 1e-6 and min(abs(out[0] - b), abs(out[-1] - b)) < 1e-6
