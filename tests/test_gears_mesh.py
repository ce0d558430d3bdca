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
    import numpy as np
    import shapely
    ring, other = a.exterior, b.exterior
    n = 20000
    # the 20000 points interpolated along the outline's vertices at once, the distances measured only
    # where the prepared outline is within ``tol`` (a shapely call a point took 0,5–0,9 s a pair)
    xy = np.asarray(ring.coords)
    along = np.concatenate(([0.0], np.cumsum(np.hypot(*np.diff(xy, axis=0).T))))
    at = along[-1] * np.arange(n) / n
    points = shapely.points(np.interp(at, along, xy[:, 0]), np.interp(at, along, xy[:, 1]))
    shapely.prepare(other)
    near = np.flatnonzero(shapely.dwithin(points, other, tol))
    dist = np.full(n, np.inf)
    dist[near] = shapely.distance(points[near], other)
    runs: list[list[tuple[float, Point]]] = []
    last = -10
    for i in np.flatnonzero(dist < tol):
        if i - last > 2:
            runs.append([])
        runs[-1].append((float(dist[i]), points[i]))
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
    from conftest import example_sheet
    lang = "en" if name == "gears_b" else "uk"
    sheet = example_sheet(name, "gears", "A1", lang)      # shared with the modules that read it
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


# -- what Table 1 reads, drawn; the profiles smooth (review 5, items 18 and 19) -----------------------

def _steps(mesh, name, kind=None):
    return [q for q in mesh.record.items if q.step == name and (kind is None or q.kind == kind)]


@pytest.mark.parametrize("z, x", [PAIRS[1], PAIRS[3], PAIRS[5]])
def test_the_meshing_draws_s_sa_p_pb_and_b1b2_where_table_1_reads_them(z, x):
    """The chord s of each wheel's tooth lies on its pitch circle with the tooth's flanks at its ends
    and is the laid-off chord 2r·sin(s/2r); sa's dimension is the tip chord 2ra·sin(ψa) (ψa from the
    involute function, written here); p is an arc of the pitch circle πm long (drawing mm); pb is laid
    off on N1N2 from B1, pb = πm·cos α long; B1B2 is drawn bold from B1 to B2; each is lettered
    (s_1, s_2, s_a1, s_a2, p, p_b) within 25 mm of its line (a leader's length at most)."""
    from graphplan.graphic.gears import construct_mesh
    sol = solve_pair(Pair(z, 0.004, x))
    mesh = construct_mesh(sol, 0.0)
    k = mesh.module_mm / 4.0                                      # drawing mm per part mm
    O = {1: mesh.points["O1"], 2: mesh.points["O2"]}
    alpha = math.radians(20.0)
    inv = lambda a: math.tan(a) - a                               # noqa: E731
    letters = {q.text: q.bounds() for q in mesh.record.items if q.kind == "text"}
    for w in (1, 2):
        r = 4.0 * sol.pair.z[w - 1] / 2 * k
        s = 4.0 * (math.pi / 2 + 2 * x[w - 1] * math.tan(alpha)) * k
        seg = _steps(mesh, f"s{w}", "segment")
        assert len(seg) == 1
        a, b = (complex(*q) for q in seg[0].points)
        assert abs(abs(a - O[w]) - r) < 1e-6 and abs(abs(b - O[w]) - r) < 1e-6          # on the pitch circle
        assert abs(abs(b - a) - 2 * r * math.sin(s / (2 * r))) < 1e-6                     # the chord of s
        ra = sol.ra[w - 1] * 1000 * k
        aa = math.acos(sol.rb[w - 1] * 1000 * k / ra)
        psi = s / (2 * r) + inv(alpha) - inv(aa)                   # half the tip's angle
        if psi > 0:
            seg = _steps(mesh, f"sa{w}", "segment")
            chord = max(abs(complex(*q.points[1]) - complex(*q.points[0])) for q in seg)
            assert abs(chord - 2 * ra * math.sin(psi)) < 1e-6
        for name in (f"s_{w}",) + ((f"s_a{w}",) if psi > 0 else ()):
            assert name in letters, name
    arc = _steps(mesh, "p", "arc")
    assert len(arc) == 1
    rp = arc[0].radius
    a0, a1 = arc[0].angles
    r1 = 4.0 * sol.pair.z[0] / 2 * k
    assert abs(math.radians(a1 - a0) * r1 - math.pi * 4.0 * k) < 1e-6                  # p = πm on r1
    B1, B2 = mesh.points["B1"], mesh.points["B2"]
    dim = max(_steps(mesh, "pb", "segment"), key=lambda q: math.dist(*q.points))
    assert abs(math.dist(*dim.points) - math.pi * 4.0 * math.cos(alpha) * k) < 1e-6        # pb = πm·cos α
    u = (B2 - B1) / abs(B2 - B1)
    start = complex(*dim.points[0])
    assert abs(((start - B1) / u).real) < 1e-6                                            # from B1
    active = _steps(mesh, "active part B1B2", "segment")
    assert len(active) == 1 and active[0].line_width >= 0.7
    assert {complex(*q) for q in active[0].points} == {B1, B2}
    for name, prim in (("p", arc[0]), ("p_b", dim)):
        box = letters[name]
        pts = [complex(*q) for q in prim.points] if prim.kind != "arc" else \
            [O[1] + rp * complex(math.cos(math.radians(t)), math.sin(math.radians(t))) for t in (a0, a1)]
        mid = sum(pts) / len(pts)
        assert math.hypot(max(box[0] - mid.real, mid.real - box[2], 0), max(box[1] - mid.imag, mid.imag - box[3], 0)) < 25.0 \
            + abs(pts[0] - pts[-1]) / 2


def _sagittas(points):
    """The sagittas of the chords of a polyline on the circle through each three points in a row
    (a turn past 20° is a corner of the outline — tip and flank —, and two chords of lengths more than
    1.3 apart the joint of two curves — a fillet and the root —, not chords of one curve)."""
    pts = [complex(*q) for q in points]
    out = []
    for a, b, c in zip(pts, pts[1:], pts[2:]):
        if min(abs(b - a), abs(c - b)) < 1e-9 or abs(math.degrees(math.atan2(((c - b) / (b - a)).imag,
                                                                             ((c - b) / (b - a)).real))) > 20.0:
            continue
        area = abs(((b - a).conjugate() * (c - a)).imag) / 2
        if area < 1e-12 or max(abs(b - a), abs(c - b)) > 1.3 * min(abs(b - a), abs(c - b)):
            continue
        R = abs(b - a) * abs(c - b) * abs(c - a) / (4 * area)
        L = max(abs(b - a), abs(c - b))
        out.append(R - math.sqrt(max(R * R - L * L / 4, 0.0)))
    return out


@pytest.mark.parametrize("z, x", [PAIRS[1], PAIRS[3]])
def test_the_profiles_show_no_corner_at_the_drawing_scale(z, x):
    """The bold working parts and the teeth's outlines (fillets, involutes, tips, roots) as chords
    that sag at most 0.03 mm off the curve (at 5:1 the 12-point working parts sagged about 0.07 mm and
    showed corners, review 5 item 19)."""
    from graphplan.graphic.gears import construct_mesh
    mesh = construct_mesh(solve_pair(Pair(z, 0.004, x)), 0.5)
    lines = [q for q in mesh.record.items if q.kind == "polyline" and q.step.startswith(("teeth", "working part"))]
    assert len(lines) == 4
    for q in lines:
        assert max(_sagittas(q.points)) <= 0.03, q.step


@pytest.mark.parametrize("z, x", [((17, 34), (0.5, 0.3)), ((12, 31), (0.45, 0.2)), ((20, 40), (0.0, 0.0))])
def test_the_sliding_curves_are_lettered_apart_from_their_crossing(z, x):
    """review 7 #16: λ2 stood at P, where λ1 and λ2 cross (both 0), and the ordinate had no name:
    each λ is lettered beside its own curve, at least 10 mm from P along N1N2, and the axis is λ."""
    from graphplan.graphic.gears import construct_mesh, sliding_diagram
    sol = solve_pair(Pair(z, 0.005, x))
    mesh = construct_mesh(sol, 0.0)
    rec = sliding_diagram(sol, mesh)
    texts = {p.text: complex(*p.points[0]) for p in rec.items if p.kind == "text"}
    assert "λ" in texts
    xP = sol.rho_P / rec.scales["mu_l"]          # (the abscissa at its own scale, review 12 mark 22)
    for name in ("λ_1", "λ_2"):
        assert abs(texts[name].real - xP) > 10.0, (name, texts[name], xP)
