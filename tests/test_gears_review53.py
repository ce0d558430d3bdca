"""Stop 53's gear-sheet review (helper gear53): the lead's pair 16/21 with m = 10 mm and the shifts "auto", a
type-A train for u = 4,2 with K = 5 (GEARS53, a tight neighbourhood); the helper's own 32/41 with m = 5 mm and a
type-A train for u = 3,6 with K = 6 (GEARS_OWN53) — the closed forms written out here, not the code's — and the
a_w dimension's number written along its dimension line (GOST 2.307), measured on the drawn record."""
from __future__ import annotations

import dataclasses
import functools
import math
import tomllib

import pytest

from review_scenes import GEARS53, GEARS_OWN53
from test_gears_review50 import pair_closed


@functools.lru_cache(maxsize=None)
def _solved(text: str, name: str, train: bool = True):
    """The scene solved once for the module (the shifts' rule "auto" weighs ~1000 pairs); ``train``
    False: the same solution without its train (what the meshing's zone is sized by alone)."""
    from graphplan.exact.gears import solve
    from graphplan.model.gears import build
    if not train:
        g, sol = _solved(text, name)
        return g, dataclasses.replace(sol, train=None)
    g = build(tomllib.loads(text), name)
    return g, solve(g)


@pytest.mark.parametrize("text, name, z, m, published", [
    # GEARS53 by hand with the rule's x = 0,55/0,55: inv αw = 2·1,1·tg 20°/37 + inv 20° → αw = 26,6093°,
    # aw = 185·cos 20°/cos αw = 194,438 mm, ra = 93,938/118,938 mm, sa = 5,985/6,687 mm, εα = 1,2077
    (GEARS53, "GEARS53", (16, 21), 0.010, ((0.55, 0.55), 26.6093, 194.438, 1.2077)),
    # GEARS_OWN53 with x = 0,95/1,1: αw = 26,3322°, aw = 191,349 mm, εα = 1,2127 (just over 1,2: the rule's
    # zone of the blocking contour keeps εα ≥ 1,2)
    (GEARS_OWN53, "GEARS_OWN53", (32, 41), 0.005, ((0.95, 1.1), 26.3322, 191.349, 1.2127)),
], ids=["GEARS53", "GEARS_OWN53"])
def test_the_pairs_are_the_closed_forms(text, name, z, m, published):
    _, sol = _solved(text, name)
    p = sol.pair
    x, a_w, aw_mm, eps = published
    assert tuple(p.x) == pytest.approx(x, abs=1e-12)
    c = pair_closed(*z, m, *x)
    assert math.degrees(c["alpha_w"]) == pytest.approx(a_w, abs=5e-5)
    assert c["aw"] * 1000 == pytest.approx(aw_mm, abs=5e-4) and round(c["eps"], 4) == eps
    assert p.aw == pytest.approx(c["aw"], rel=1e-12) and p.eps == pytest.approx(c["eps"], rel=1e-12)
    for k in (0, 1):
        assert p.ra[k] == pytest.approx(c["ra"][k], rel=1e-12) and p.sa[k] == pytest.approx(c["sa"][k], rel=1e-9)
        # no undercut (x ≥ 1 − z·sin²α/2), not pointed (sa ≥ 0,25m), εα ≥ 1,2: Table 2's verdicts
        assert x[k] >= 1 - z[k] * math.sin(math.radians(20)) ** 2 / 2 and c["sa"][k] >= 0.25 * m
    assert c["eps"] >= 1.2


@pytest.mark.parametrize("text, name, z, rpm", [
    (GEARS53, "GEARS53", (29, 31, 91), 1450),     # u1H 4,138 (−1,48 %); (29 + 31)·sin 36° = 35,27 > 33
    (GEARS_OWN53, "GEARS_OWN53", (34, 26, 86), 960),   # u1H 3,529 (−1,96 %); (34 + 26)·sin 30° = 30 > 28
], ids=["GEARS53", "GEARS_OWN53"])
def test_the_type_a_trains_meet_the_conditions_and_willis(text, name, z, rpm):
    """u1H = 1 + z3/z1 within ±4 % of the wanted u; coaxial z3 = z1 + 2z2; assembled (z1 + z3)/K whole;
    neighbours (z1 + z2)·sin(π/K) > z2 + 2; Willis with the ring fixed: (ω1 − ωH)/(0 − ωH) = −z3/z1, and the
    planet's ω2 = ωH − (ω1 − ωH)·z1/z2."""
    _, sol = _solved(text, name)
    t = sol.train
    scene = tomllib.loads(text)["planetary"]
    K, u_wanted = scene["planets"], scene["ratio"]
    assert tuple(t.z) == z
    z1, z2, z3 = z
    assert z3 == z1 + 2 * z2 and (z1 + z3) % K == 0 and (z1 + z2) * math.sin(math.pi / K) > z2 + 2
    u = 1 + z3 / z1
    assert abs(u - u_wanted) / u_wanted <= 0.04
    w1 = rpm * math.pi / 30
    assert t.ratio == pytest.approx(u, rel=1e-12) and t.omega["H"] == pytest.approx(w1 / u, rel=1e-12)
    assert (t.omega["1"] - t.omega["H"]) / (0 - t.omega["H"]) == pytest.approx(-z3 / z1, rel=1e-12)
    assert t.omega["2"] == pytest.approx(w1 / u - (w1 - w1 / u) * z1 / z2, rel=1e-12)


@pytest.fixture(scope="module")
def meshed53():
    """GEARS53's pair (no train) solved and drawn as the A1 sheet draws it: (sol, mesh)."""
    from graphplan.sheets.form import form
    from graphplan.sheets.gears import construct_on
    _, sol = _solved(GEARS53, "GEARS53", train=False)
    mesh, _, _ = construct_on(sol, form("A1"), 0.5, "uk")
    return sol, mesh


def test_the_aw_dimension_reads_along_its_unbroken_line(meshed53):
    """GOST 2.307: a linear dimension's number stands over its dimension line (left of a vertical one), parallel
    to it, read from the right, near its middle; the line is not broken for it. Measured on the drawn meshing
    of GEARS53 (its centres off the drawing: the a_w dimension drawn): the number turned 90°, its ink left of
    the line and clear of it, centred on the line's middle; the two arrows start at that middle (no gap); in
    the SVG the lettering is turned about its anchor."""
    from graphplan.drawing.svg import render
    from graphplan.graphic.record import Record
    sol, mesh = meshed53
    items = mesh.record.items
    (num,) = [q for q in items if q.kind == "text" and q.text.startswith("a_w = ")]
    arrows = [q for q in items if q.kind == "vector" and q.step == "aw"]
    assert len(arrows) == 2 and arrows[0].points[0] == arrows[1].points[0]          # from the middle: unbroken
    (xd, mid), ends = arrows[0].points[0], sorted(a.points[1][1] for a in arrows)
    assert all(a.points[1][0] == xd for a in arrows) and mid == pytest.approx(sum(ends) / 2)
    assert num.text == f"a_w = {sol.pair.aw * 1000:.2f}".replace(".", ",") and num.turn == 90.0
    x0, y0, x1, y1 = num.ink()
    assert x1 <= xd - 0.5 and xd - x0 <= 8.0                 # over (left of) the line, clear of it, close to it
    assert (y0 + y1) / 2 == pytest.approx(mid, abs=1.5) and y1 - y0 > 4 * (x1 - x0)     # along it, at its middle
    svg = render(Record("aw", [num]), 841.0, 594.0)
    assert 'transform="rotate(-90 ' in svg


@pytest.mark.parametrize("lang", ["en", "uk"])
def test_an_enlarged_tables_title_stays_over_the_table(meshed53, lang):
    """The gear tables are ruled with 2,5-mm cells and a 3,5-mm title, then drawn 1,4 times larger for the
    A1 column: the title's letters take GOST's 5 mm (not 4,9), so a title wrapped for the ruled table ran
    past the enlarged table's right rule (the en Table 1, by 3 mm). At every size the column tries, every
    title line's ink ends within the table's outer rule and the lines read the whole title in order."""
    from graphplan.report.gears import gears_json
    from graphplan.sheets.gears import SIZES, _sized, geometry_table
    sol, mesh = meshed53
    rec = geometry_table(gears_json(sol, mesh, None, ""), lang)
    for k in SIZES:
        big = _sized(rec, k)
        right = max(x for q in big.items if q.kind == "segment" for x, _ in q.points)
        top = max(y for q in big.items if q.kind == "segment" for _, y in q.points)
        title = sorted((q for q in big.items if q.kind == "text" and q.points[0][1] > top), key=lambda q: -q.points[0][1])
        assert title and " ".join(q.text for q in title) == rec.title
        assert all(q.ink()[2] <= right + 1e-6 for q in title), (k, [q.ink()[2] for q in title], right)
