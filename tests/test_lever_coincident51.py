"""Review51 #4 (six.toml's force sheet, the Zhukovsky lever at position 3): a, b and s2 coincide there
(ω2 = 0) and the lever lettered the spot "s2" only — P_зр applied at a with no "a" drawn. The truth:
a central crank-slider at φ = 90° has ω2 = ω1·r·cos φ / (l·cos β) = 0, so a and b (and every point of
the rod) have one velocity image; every image off the pole is lettered, those at one spot in one
label by it ("a, b", as the plan of velocities does)."""
from __future__ import annotations

import pytest

from conftest import example


@pytest.fixture(scope="module")
def lever():
    from graphplan.drawing.forces import lever_record
    from graphplan.graphic import forceplans
    fp = forceplans.construct(example("crank_slider"), 90.0)
    return fp.lever, lever_record(fp, "en")


def test_the_coinciding_images_are_lettered_together(lever):
    lv, rec = lever
    a, b = lv.images["A"], lv.images["B"]
    assert abs(a) > 10.0 and abs(a - b) < 0.05         # ω2 = 0: one spot, off the pole
    spot = 1j * a                                       # the lever is the plan turned by 90°
    texts = [q for q in rec.items if q.kind == "text"]
    names = {t.strip() for q in texts for t in q.text.split(",")}
    assert {"a", "b"} <= names
    q = next(q for q in texts if {t.strip() for t in q.text.split(",")} == {"a", "b"})
    x0, y0, x1, y1 = q.ink()
    gap = abs(complex(max(x0 - spot.real, 0.0, spot.real - x1), max(y0 - spot.imag, 0.0, spot.imag - y1)))
    assert gap < 4.0, gap                               # beside its spot


@pytest.fixture(scope="module")
def six_lever():
    from graphplan.drawing.forces import lever_record
    from graphplan.exact import kinetostatics
    from graphplan.graphic import forceplans
    from conftest import scene_study
    from review_scenes import SIX_LEVER51
    st = scene_study(SIX_LEVER51)
    fp = forceplans.construct(st, float(kinetostatics.at_scene_angle(st)))
    return fp.lever, lever_record(fp, "uk")


def _on_one_line(p: tuple[complex, complex], q: tuple[complex, complex], tol: float = 0.5) -> bool:
    """Two segments on one line (each end of q within ``tol`` of p's line) sharing more than ``tol``."""
    (a, b), (c, d) = p, q
    u = (b - a) / abs(b - a)
    if any(abs(((e - a) * u.conjugate()).imag) > tol for e in (c, d)):
        return False
    s = sorted(((e - a) * u.conjugate()).real for e in (c, d))
    return min(abs(b - a), s[1]) - max(0.0, s[0]) > tol


def test_the_six_bars_coinciding_images_and_the_balancing_force_read_apart(six_lever):
    """At the sheet's position a, b and s2 coincide: lettered "a, b, s₂"; P_зр applied at a lies
    on no other force's line there (Φ3 left a along it, its head on P_зр's shaft)."""
    lv, rec = six_lever
    a = lv.images["A"]
    assert abs(lv.images["B"] - a) < 0.05 and abs(lv.images["S2"] - a) < 0.05
    texts = [q.text for q in rec.items if q.kind == "text"]
    assert any({t.strip() for t in x.split(",")} == {"a", "b", "s_2"} for x in texts), texts
    vectors = [q for q in rec.items if q.kind == "vector"]
    pb = next(q for q in vectors if q.text == "P_b")
    p = (complex(*pb.points[0]), complex(*pb.points[-1]))
    assert min(abs(e - 1j * a) for e in p) < 4.0           # applied at a (a lane at most off it)
    assert not any(_on_one_line(p, (complex(*q.points[0]), complex(*q.points[-1])))
                   for q in vectors if q is not pb)
