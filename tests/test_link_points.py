"""A point on a link's extension (the review's correction 1): the four-bar's rocker O2B carries
D = 1.3·O2B, where P_D acts. The textbook draws O2–B–D as one rigid link and letters the point D;
the sheets drew the rocker only to B and lettered D "S3" (a second S3 on one drawing). Checked
against D placed by hand, O2 + 1.3·(B − O2), on the position plan, the scheme and the group."""
from __future__ import annotations

import math

import pytest

from conftest import scene_study
from graphplan.model.linkshape import rigid_outline
from review_scenes import FOURBAR   # the second review's four-bar: P_D at D = 1.3·O2B on the rocker
from review_scenes import SIEVE     # the lead's review: a cw crank, the coupler a plate ABC, P_C at C


def _points(p) -> list[complex]:
    return [complex(x, y) for x, y in p.points]


def _reaches(rec, a: complex, d: complex, tol: float = 0.3) -> bool:
    """A drawn line of a link runs from ``a`` (the joint O2 or B) to ``d``: one segment's ends, or a
    polyline's consecutive points, at both."""
    for p in rec.items:
        if p.kind in ("segment", "polyline") and p.role == "link":
            pts = _points(p)
            for s, e in zip(pts, pts[1:]):
                if {min(abs(s - a), abs(e - a)) <= tol, min(abs(s - d), abs(e - d)) <= tol} == {True}:
                    return True
    return False


def _gap(text, z: complex) -> float:
    """How far (mm) a text's box stands from the point ``z``."""
    x0, y0, x1, y1 = text.bounds()
    return abs(complex(max(x0 - z.real, 0.0, z.real - x1), max(y0 - z.imag, 0.0, z.imag - y1)))


@pytest.fixture(scope="module")
def force_drawings():
    from conftest import scene_plan, shared
    p, _, dr = scene_plan(FOURBAR, "forces", "A1", precision=0.5)
    return shared("test_link_points.force_drawings", lambda: (dr.groups_fp(p.mu), dr.drawings(p.mu, "uk")))


@pytest.mark.parametrize("which", ["scheme", "groups"])
def test_the_point_d_is_lettered_d_on_its_link(force_drawings, which):
    fp, drawings = force_drawings
    rec = next(r for r in drawings[which] if "B" in [q.text for q in r.items if q.kind == "text"])
    mu = rec.scales["mu_l"]
    kin = fp.ks.kin
    O2 = complex(kin.point("O2")[0][0]) / mu
    B = complex(kin.point("B")[0][0]) / mu
    D = O2 + 1.3 * (B - O2)                       # the scene's D, placed by hand
    texts = [q for q in rec.items if q.kind == "text"]
    names = [q.text for q in texts]
    assert names.count("S_3") == 1 and names.count("D") == 1, names
    letter = next(q for q in texts if q.text == "D")
    assert _gap(letter, D) < 3.0, "D lettered away from D"
    assert any(q.kind == "circle" or abs(complex(*q.points[0]) - D) < 0.3 for q in rec.items
               if q.kind in ("point", "circle") and q.points)
    assert _reaches(rec, B, D) or _reaches(rec, O2, D), "no line of link 3 reaches D"


def test_the_position_plan_draws_the_rocker_to_d():
    from graphplan.drawing.plans import position_record
    from graphplan.graphic.plans import build_plans, where
    st = scene_study(FOURBAR)
    plans = build_plans(st, precision=0)
    rec = position_record(plans)
    sc = plans.scheme
    thick = [p.layout for p in plans.positions if p.key in (set(plans.accel_keys) or {0})]
    for lay in thick:
        O2 = where(sc, lay, sc.body_of("O2"), "O2")
        B = where(sc, lay, "O2B", "B")
        D = O2 + 1.3 * (B - O2)
        assert abs(where(sc, lay, "O2B", "D") - D) < 1e-6
        assert _reaches(rec, O2, D), f"position {lay.key}: the rocker stops short of D"
    texts = [q for q in rec.items if q.kind == "text"]
    assert [q.text for q in texts].count("D") == 1 and [q.text for q in texts].count("S_3") == 1


def test_outline_of_a_bar_and_a_plate():
    # three points on a line: the bar between the outer two, whatever their order
    assert rigid_outline([0j, 10 + 0j], [13 + 0j, 5 + 0j]) == [0j, 13 + 0j]
    assert rigid_outline([0j, 10 + 0j], [-4 + 0j]) == [-4 + 0j, 10 + 0j]
    # a point off the line: a closed triangle through all three
    tri = rigid_outline([0j, 10 + 0j], [5 + 6j])
    assert tri[0] == tri[-1] and set(tri) == {0j, 10 + 0j, 5 + 6j}
    # a point inside a triangle of joints: the joints' triangle, as before
    assert rigid_outline([0j, 10 + 0j, 5 + 8j], [5 + 2j]) == [0j, 10 + 0j, 5 + 8j, 0j]


def test_a_plates_point_is_found_by_its_similar_triangle_on_both_plans():
    """A coupler point C off the line AB (a plate): the textbook finds c on the velocity and the
    acceleration plan by the similarity theorem, Δabc ∼ ΔABC, and draws that triangle — c joined
    to a and to b (a point read off a bare vector from the pole would not show how it was found).
    Checked against c placed by hand: c = a + (b − a)·(C − A)/(B − A) in complex numbers."""
    from graphplan.graphic.plans import build_plans
    from graphplan.graphic.position_plan import where
    st = scene_study(SIEVE)
    plans = build_plans(st, precision=0)
    checked = 0
    for pos in plans.positions:
        for plan in (pos.velocity, pos.acceleration):
            if plan is None:
                continue
            a, b, c = (plan.plan_point("AB", n) for n in ("A", "B", "C"))
            lay = pos.layout
            A, B, C = (where(plans.scheme, lay, "AB", n) for n in ("A", "B", "C"))
            if abs(b - a) < 5:          # a near-degenerate figure: nothing to read the triangle by
                continue
            assert abs(c - (a + (b - a) * (C - A) / (B - A))) < 1e-6
            segs = [(complex(*q.points[0]), complex(*q.points[-1])) for q in plan.record.items
                    if q.kind == "segment"] + [(complex(*q.points[0]), complex(*q.points[-1]))
                                               for q in plan.record.items if q.kind == "vector"]
            for end in (a, b):
                assert any(min(abs(s - c) + abs(e - end), abs(s - end) + abs(e - c)) < 1e-6
                           for s, e in segs), f"position {pos.key}: c not joined to its link's points"
            checked += 1
    assert checked >= 10


def test_a_grown_crank_group_is_measured_as_drawn_and_the_sheet_holds_it():
    """The sieve's force sheet (A1): the crank group, drawn at a finer μl of its own, took its size
    from the family's model — arrows longer than its 23 mm crank measured as lettering, so its size
    seemed not to grow — and went to 1:0.5, 152 mm where 64 mm was allowed, pushing the bottom row
    off the sheet. The group's cell at a finer μl is its drawing's: at 1:0.5 at least the crank's
    own extent at that scale (O1A's larger projection / 0.0005: 127 mm at φ = 45.1°);
    and the sheet keeps every drawing inside the frame and its box, nothing overprinted (``defects``).

    (It asserted the crank group drawn finer than the family's 1:4 as well — a composition's outcome,
    not the rule: since the charts and hodographs took the sheet's room, the group at 1:2.5 is
    12.5 mm taller than its row holds, and stays at 1:4 — the same before stop 56's margin change.)"""
    from graphplan.sheets.compose import SheetOptions, defects
    from graphplan.sheets.forces import build_forces_sheet, plan
    from graphplan.sheets.form import form
    st = scene_study(SIEVE)
    p, nat, dr = plan(st, form("A1"), SheetOptions(precision=0.5, sheet="forces"))
    i = [gp.label for gp in dr.groups_fp(p.mu).groups].index("I(0-1)")
    crank = complex(dr.ks.kin.point("A")[0][0]) - complex(dr.ks.kin.point("O1")[0][0])   # O1A at the force position
    assert abs(crank) == pytest.approx(0.09)
    w, h = dr.group_size(p.mu, i, 0.0005, nat.families["groups"].caption)
    assert max(w, h) >= max(abs(crank.real), abs(crank.imag)) / 0.0005 - 1e-6, (w, h)
    sheet = build_forces_sheet(st, form("A1"), SheetOptions(precision=0.5, lang="uk", sheet="forces"))
    assert defects(sheet) == []
