"""The meshing as drawn (graphic/gears.py), checked on its own record with shapely: the drawn teeth of the
two wheels do not overlap (at precision 0 not at all, else by less than the drafting precision), they
touch only on the line of action N1N2 — or, the mesh being backlash-free (αw from the involute
function), on its mirror about O1O2, where the back flanks touch —, each tooth is s thick on the pitch
circle, three teeth each wheel with wheel 1's middle one in mesh at P; and the scale is a standard one
(GOST 2.302) with the whole depth 40–60 mm where one gives that and fits."""
from __future__ import annotations

import math

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from shapely.geometry import LineString, Point, Polygon

from graphplan.exact.gears import solve_pair
from graphplan.model.gears import Pair
from graphplan.util.errors import GraphplanError

# GOST 2.302: the reductions 1:2 … 1:10 and the enlargements 1:1 … 100:1 (drawing mm per mm)
GOST = (0.1, 0.2, 0.25, 0.4, 0.5, 1.0, 2.0, 2.5, 4.0, 5.0, 10.0, 20.0, 40.0, 50.0, 100.0)
PAIRS = [((14, 35), (0.65, 0.65)), ((12, 30), (0.5, 0.3)), ((40, 80), (0.0, 0.0)), ((10, 25), (0.6, 0.3)),
         ((17, 60), (0.0, 0.0)), ((25, 40), (0.3, -0.2))]


def wheels(mesh):
    """Each wheel's three teeth as one polygon: the drawn outline closed through its centre."""
    out = {}
    for p in mesh.record.items:
        if p.step.startswith("teeth "):
            k = int(p.step[-1])
            c = mesh.points[f"O{k}"]
            out[k] = (Polygon(list(p.points) + [(c.real, c.imag)]), list(p.points))
    return out


def contacts(a: Polygon, b: Polygon, tol: float = 0.02) -> list[Point]:
    """The nearest point to b's outline on each stretch of a's outline within ``tol`` mm of it."""
    ring, other = a.exterior, b.exterior
    n = 20000
    runs: list[list[tuple[float, Point]]] = []
    last = -10
    for i in range(n):
        q = ring.interpolate(ring.length * i / n)
        d = q.distance(other)
        if d < tol:
            if i - last > 2:
                runs.append([])
            runs[-1].append((d, q))
            last = i
    return [min(r, key=lambda t: t[0])[1] for r in runs]


@pytest.mark.parametrize("z, x", PAIRS)
def test_the_drawn_teeth_touch_on_the_line_of_action_and_are_s_thick(z, x):
    from graphplan.graphic.gears import construct_mesh
    sol = solve_pair(Pair(z, 0.004, x))
    mesh = construct_mesh(sol, 0.0)
    w = wheels(mesh)
    assert w[1][0].is_valid and w[2][0].is_valid
    assert w[1][0].intersection(w[2][0]).area < 1e-6                   # no overlap
    N1, N2, P = mesh.points["N1"], mesh.points["N2"], mesh.points["P"]
    lines = [LineString([(N1.real, N1.imag), (N2.real, N2.imag)]),       # N1N2 and its mirror about O1O2
             LineString([(-N1.real, N1.imag), (-N2.real, N2.imag)])]
    found = [q for q in contacts(w[1][0], w[2][0]) if q.distance(w[2][0].exterior) < 0.005]   # touching
    assert found
    on_line = 0
    for q in found:
        # where the two outlines cross the nearer line: one point, within 0.1 mm — they touch on it
        line = min(lines, key=q.distance)
        near = []
        for k in (1, 2):
            cut = w[k][0].exterior.intersection(line)
            near.append(min(getattr(cut, "geoms", [cut]), key=q.distance))
        assert near[0].distance(near[1]) < 0.1 and near[0].distance(q) < 1.0, (q, near)
        on_line += q.distance(lines[0]) < 0.5
    assert on_line >= 1 and any(q.distance(Point(P.real, P.imag)) < 0.5 for q in found)   # the pair at P
    s_mm = [v / mesh.mu_l for v in sol.s]
    for k in (1, 2):                                   # three teeth, each s thick on the pitch circle
        c = mesh.points[f"O{k}"]
        pitch = Point(c.real, c.imag).buffer(mesh.drawn[f"r{k}"], quad_segs=4096).exterior
        cut = w[k][0].intersection(pitch)
        arcs = [g for g in getattr(cut, "geoms", [cut]) if g.length > 0.2 * s_mm[k - 1]]
        assert len(arcs) == 3
        for g in arcs:
            assert g.length == pytest.approx(s_mm[k - 1], abs=0.05)
    # wheel 1's middle tooth is the one at P: P lies on its outline
    poly1, pts1 = w[1]
    third = len(pts1) // 3
    middle = LineString(pts1[third:2 * third])
    assert middle.distance(Point(P.real, P.imag)) < 0.05


@pytest.mark.parametrize("z, x", PAIRS[:4])
@pytest.mark.parametrize("p", [0.25, 0.5, 1.0])
def test_the_teeth_overlap_by_less_than_the_drafting_precision(z, x, p):
    from graphplan.graphic.gears import construct_mesh
    mesh = construct_mesh(solve_pair(Pair(z, 0.004, x)), p)
    w = wheels(mesh)
    both = w[1][0].intersection(w[2][0])
    for g in getattr(both, "geoms", [both]):
        if g.area > 0:
            assert 2 * g.area / g.length < p                # a sliver's width: twice its area over its outline


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.integers(8, 150), st.integers(8, 150), st.sampled_from([0.0005, 0.001, 0.003, 0.004, 0.005, 0.01, 0.02]),
       st.floats(-0.3, 0.8), st.floats(-0.3, 0.8), st.floats(150.0, 560.0), st.floats(200.0, 800.0))
def test_the_meshing_scale_is_standard(z1, z2, m, x1, x2, height, width):
    """μl is a GOST 2.302 scale; the whole depth 40–60 mm unless no standard scale that draws it so
    fits the zone (then the drawing at that scale is indeed larger than the zone)."""
    from graphplan.graphic.gears import construct_mesh, mesh_scale
    try:
        sol = solve_pair(Pair((z1, z2), m, (x1, x2)))
        mesh = construct_mesh(sol, 0.0, height_mm=height, width_mm=width)
    except GraphplanError:
        return
    k = 1e-3 / mesh.mu_l
    assert any(abs(k - g) < 1e-9 * g for g in GOST), k
    depth = 2.25 * m * 1000.0 * k
    if not 40.0 <= depth <= 60.0:
        for g in GOST:
            if 40.0 <= 2.25 * m * 1000.0 * g <= 60.0 and g > k:
                # the band's scale does not fit: the meshing drawn at it is taller or wider than the zone
                big = construct_mesh(sol, 0.0, module_mm=m * 1000.0 * g).record.bounds()
                assert big[3] - big[1] > height - 40.0 or big[2] - big[0] > width - 20.0
    assert mesh_scale(sol, height, width) == mesh.module_mm


@pytest.mark.parametrize("name", ["gears", "gears_b"])
def test_the_sheet_says_its_standard_scale(name):
    from conftest import ROOT
    from graphplan.model.gears import load
    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.form import form
    from graphplan.sheets.sheet import BUILDERS
    g = load(ROOT / "examples" / f"{name}.toml")
    lang = "en" if name == "gears_b" else "uk"
    sheet = BUILDERS["gears"](g, form("A1"), SheetOptions(lang=lang, sheet="gears"))
    texts = [p.text for p in sheet.record.items if p.kind == "text"]
    m_mm = 4.0 if name == "gears_b" else 5.0
    shown = [g for g in GOST if g >= 1 and 40.0 <= 2.25 * m_mm * g <= 60.0 and f"{g:g}:1" in texts]
    assert len(shown) == 1                                  # the title block's box says it: 4:1 or 5:1 here
    caption = [t for t in texts if t.startswith("Евольвентне зачеплення" if lang == "uk" else "Involute meshing")]
    assert len(caption) == 1 and f"{shown[0]:g}:1" in caption[0]


@pytest.mark.parametrize("z, x", PAIRS)
def test_no_involute_mark_lies_past_its_wheels_tip_circle(z, x):
    """The draftsman's marks on each involute (the ends of the unrolled tangents) stop at the tip: none
    is left as a dot without a tooth beside the meshing's teeth (the review's stray dot)."""
    from graphplan.graphic.gears import construct_mesh
    m = construct_mesh(solve_pair(Pair(z, 0.004, x)), 0.5)
    centre = {"1": 0j, "2": 1j * m.drawn["aw"]}
    marks = [p for p in m.record.items if p.kind == "point" and p.step.startswith("involute ")]
    assert len(marks) >= 6
    for p in marks:
        k = p.step.split()[1].rstrip(":")
        assert abs(complex(*p.points[0]) - centre[k]) <= m.drawn[f"ra{k}"] + 1e-9, p.step
