"""Stop 62 (review 62's F1): the wedge press's wedge 3 whose inclined face (35° to its horizontal guide)
runs through its own joint B — drawn as the textbook's triangle resting on its guide (the face from B
to past the block C, the far end's perpendicular down to the guide, the base back along the guide),
one rigid body on the position plan and on the force scheme; not a bar from a pin at B to C (read
"a rod BC pinned at B": RRP + RRP). Table 4 gives the wedge's angle α3 = 35°.
Truths: the scene's angles (the face at 35°, the guide at 0°) and the block C, which rides on the face."""
from __future__ import annotations

import cmath
import math

import pytest

from conftest import scene_force_plans, scene_study
from review_scenes import WEDGE52, WEDGE62_PRESS

FACE, GUIDE = 35.0, 0.0     # the wedge's face and its guide, degrees (the scene's)


def _deg(p: complex, q: complex) -> float:
    return math.degrees(cmath.phase(q - p)) % 180.0


def _on(z: complex, p: complex, q: complex, tol: float = 1e-6) -> bool:
    """z on the segment p–q."""
    d = q - p
    t = ((z - p) * d.conjugate()).real / abs(d) ** 2
    return -1e-9 <= t <= 1 + 1e-9 and abs(z - (p + t * d)) < tol


def _triangle(outline: list[complex], b: complex, c: complex) -> None:
    """A closed triangle: a corner at B, the side from it at the face's angle carrying C, the far
    end's side perpendicular to the guide, the base along the guide back to B."""
    assert len(outline) == 4 and abs(outline[0] - outline[-1]) < 1e-9, outline
    p, far, foot = outline[:3]
    assert abs(p - b) < 1e-6, (p, b)
    assert math.isclose(_deg(p, far), FACE, abs_tol=1e-6)
    assert _on(c, p, far), (c, p, far)
    assert math.isclose(_deg(foot, far), (GUIDE + 90.0) % 180.0, abs_tol=1e-6)
    assert math.isclose(_deg(foot, p), GUIDE, abs_tol=1e-6)


@pytest.fixture(scope="module")
def st():
    return scene_study(WEDGE62_PRESS)


def test_the_position_plan_draws_the_wedge_as_its_triangle(st):
    """At every thick position the segments of the mechanism close a triangle at B: the face at 35°
    through the block C, a side square to the guide, the base along the guide — and no bar runs from
    B to the face's end alone (the old drawing: the face one thick line from the pin at B)."""
    from graphplan.drawing.plans import position_record
    from graphplan.graphic.plans import build_plans
    rec = position_record(build_plans(st))
    segs = [tuple(complex(*p) for p in it.points) for it in rec.items
            if it.kind == "segment" and it.layer == "mechanism" and len(it.points) == 2]
    found = []
    for i, (p, q) in enumerate(segs):
        if abs(p - q) < 1e-9 or not math.isclose(_deg(p, q), FACE, abs_tol=1e-6):
            continue
        for r, s in segs:
            if abs(r - q) < 1e-9 and math.isclose(_deg(r, s), 90.0, abs_tol=1e-6):
                if any(abs(u - s) < 1e-9 and abs(v - p) < 1e-9 and math.isclose(_deg(u, v), GUIDE, abs_tol=1e-6)
                       for u, v in segs):
                    found.append([p, q, s])
    assert len(found) >= 2, found      # the plan's thick positions (accel = [3, 8]) at least
    # the frame's hatching (the ram's guide runs down into the wedge) stops at the wedge's body
    from graphplan.model.linkshape import _inside
    hatch = [tuple(complex(*p) for p in it.points) for it in rec.items if it.kind == "segment" and it.role == "hatch"]
    assert hatch
    inside = [h for h in hatch for t in found if _inside((h[0] + h[1]) / 2, t)]
    assert not inside, inside


def test_the_triangles_corner_is_b_and_its_face_carries_c(st):
    """On a thick position's own joints: the triangle's corner is B, C on its face."""
    from graphplan.drawing.plans import _wedge_sides
    from graphplan.graphic.record import Record
    from graphplan.model.linkshape import slot_line
    b, c = 10 + 5j, 10 + 5j + 60 * cmath.exp(1j * math.radians(FACE))
    u = cmath.exp(1j * math.radians(FACE))
    a, e = slot_line(b, u, [b], [c])
    rec = Record()
    assert _wedge_sides(rec, [b], a, e, 1 + 0j, "link", "")
    pts = [complex(*it.points[0]) for it in rec.items] + [complex(*rec.items[-1].points[1])]
    _triangle(pts, b, c)


def test_the_force_scheme_draws_the_same_triangle():
    """The force scheme's and the groups' outline of the wedge (``forces._link_outline``)."""
    from graphplan.drawing.forces import _link_outline
    fp = scene_force_plans(WEDGE62_PRESS)
    out = _link_outline(fp, "B", fp.mu_l)

    def at(link: str, point: str) -> complex:
        lk = fp.ks.mech.links[link]
        return complex(fp.ks.kin.bodies[link].at(lk.local[point])[0][0]) / fp.mu_l
    _triangle(out, at("B", "B"), at("C", "C"))


def test_table_4_gives_the_wedges_angle(st):
    """α3 = 35° (the face through B); WEDGE52's face at 150° to its guide: α3 = 30°, the acute angle."""
    from graphplan.sheets.kintables import dimensions_table, wedge_angles
    assert wedge_angles(st) == [(3, FACE)]
    assert wedge_angles(scene_study(WEDGE52)) == [(3, 30.0)]
    rec = dimensions_table(st, 0.002, "uk")
    texts = [it.text for it in rec.items if getattr(it, "text", None)]
    row = [i for i, t in enumerate(texts) if t == "α_{3}"]
    assert row and texts[row[0] + 1] == "35°", texts


def test_the_rams_bar_is_drawn_between_c_and_d():
    """Review 62's F2: the ram 5 (a slider at C on the vertical guide, its point D 0,06 m up the guide)
    is drawn on its group as its bar C–D, not as a block with a lone dot D above it."""
    from graphplan.drawing.forces import _link_outline
    fp = scene_force_plans(WEDGE62_PRESS)
    lk = fp.ks.mech.links["D"]
    c = complex(fp.ks.kin.bodies["D"].at(lk.local["C"])[0][0]) / fp.mu_l
    out = _link_outline(fp, "D", fp.mu_l)
    assert len(out) == 2, out
    assert {round(abs(z - c), 6) for z in out} == {0.0, round(0.06 / fp.mu_l, 6)}, (out, c)
    d = next(z for z in out if abs(z - c) > 1e-6)
    assert math.isclose(_deg(c, d), 90.0, abs_tol=1e-6) and d.imag > c.imag


def test_the_rams_point_d_has_no_second_numbered_path(st):
    """Review 62's F6: D (the ram's point 0,06 m up its vertical guide from its block C) runs on C's own
    line, so its path is not drawn and numbered a second time («C″ 2, 10» read as C″ at positions 2, 10);
    the rod's centre S2 keeps its path. The truth: D − C of the scene lies along the guide."""
    from graphplan.graphic.plans import default_trajectories
    lk = st.mech.links["D"]
    assert abs((lk.local["D"] - lk.local["C"]).imag) < 1e-12      # along the ram's guide
    assert default_trajectories(st.mech) == ("S2",)


def test_the_schemes_guide_is_not_hatched_inside_the_wedge():
    """The force scheme's fixed guide (``forces._guide``) leaves out the strokes inside a closed body
    drawn over it — the wedge's triangle the ram's guide runs down into — and keeps the others."""
    from graphplan.drawing.forces import _guide
    from graphplan.graphic.record import Record
    from graphplan.model.linkshape import _inside
    tri = [0j, 40 + 28j, 40 + 0j, 0j]            # a wedge's triangle, its vertical side at x = 40
    z, g = 38 + 20j, 1j                          # a vertical guide 2 mm left of that side
    strokes = {}
    for bodies in ((), [tri]):
        rec = Record()
        _guide(rec, z, g, [], "", bodies)
        strokes[len(bodies)] = [tuple(complex(*p) for p in it.points) for it in rec.items if it.role == "hatch"]
    inside = lambda ss: [s for s in ss if _inside((s[0] + s[1]) / 2, tri)]   # noqa: E731
    assert inside(strokes[0]) and not inside(strokes[1])
    assert len(strokes[1]) == len(strokes[0]) - len(inside(strokes[0])) > 0
