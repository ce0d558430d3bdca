"""Stop 56's gear-sheet check (helper gears56): the lead's pair 10/31 "auto" with a type-B train chosen
for u1H = 11 (GEARS56), the helper's 13/27 "auto" with a type-A train for 5.6, K = 4 (GEARS_OWN56); the
bound of u1H read off the plan from what the construction laid off (GEARS_OWN55's radii fall on the
ruler's marks); the field check reading a turned dimension's number where it is drawn. Checked against
the textbook's closed forms worked out here (test_gears_review55's), hand sums, an SVG written here."""
from __future__ import annotations

import math
import tomllib

import pytest

from review_scenes import GEARS56, GEARS_OWN55, GEARS_OWN56
from test_gears_review55 import _pair


def _scene(text: str, name: str):
    from graphplan.exact.gears import solve
    from graphplan.model.gears import build
    g = build(tomllib.loads(text), name)
    return g, solve(g)


@pytest.mark.parametrize("text, z, m, x, teeth, u", [
    (GEARS56, (10, 31), 5.0, (0.6, 0.3), (18, 45, 22, 85), 1 + 45 * 85 / (18 * 22)),
    (GEARS_OWN56, (13, 27), 6.0, (0.6, 0.5), (19, 33, 85), 1 + 85 / 19)], ids=["GEARS56", "GEARS_OWN56"])
def test_the_pair_and_the_train_agree_with_the_closed_forms(text, z, m, x, teeth, u):
    """αw, aw, εα, sa by the closed forms (inv αw by bisection), the shifts clear of undercut
    (x ≥ h*a − z·sin²α/2, ≈ (17 − z)/17), sa ≥ 0.25m, εα ≥ 1.2; the train's u1H by Willis, coaxiality,
    assembly and neighbourhood by hand."""
    _, sol = _scene(text, "s56")
    p = sol.pair
    assert tuple(p.x) == pytest.approx(x)                    # the "auto" rule's choice, the sheet's
    ref = _pair(*z, m, *x)
    assert math.degrees(p.alpha_w) == pytest.approx(math.degrees(ref["alpha_w"]), abs=1e-6)
    assert p.aw * 1000 == pytest.approx(ref["aw"], abs=1e-6)
    assert p.eps == pytest.approx(ref["eps"], abs=1e-9) and ref["eps"] >= 1.2
    assert [s * 1000 for s in p.sa] == pytest.approx(ref["sa"], abs=1e-9)
    assert min(ref["sa"]) >= 0.25 * m and ref["ok"]
    for zk, xk in zip(z, x):
        assert xk >= 1 - zk * math.sin(math.radians(20)) ** 2 / 2 > (17 - zk) / 17 - 0.01
    tr = sol.train
    assert tuple(tr.z) == teeth and tr.ratio == pytest.approx(u, rel=1e-12)
    if len(teeth) == 4:                                        # type B: 1–2, 2'–3
        z1, z2, z2p, z3 = teeth
        assert z1 + z2 == z3 - z2p and (z1 * z2p + z2 * z3) % 3 == 0
        assert (z1 + z2) * math.sin(math.pi / 3) > z2 + 2
    else:                                                      # type A, K = 4
        z1, z2, z3 = teeth
        assert z1 + 2 * z2 == z3 and (z1 + z3) % 4 == 0
        assert (z1 + z2) * math.sin(math.pi / 4) > z2 + 2


def test_the_ratio_bound_takes_the_heights_as_laid_off():
    """GEARS_OWN55 at 1:1: r1, aw, r3 = 17, 81, 101 mm fall on the ruler's marks and are laid off
    exactly, so the bound is the segments' alone, (s1 + p/2)/(sH − p/2) − u by hand (the stop-55 bound
    took p/2 on each height too: ±6,7 % where the reading was +0,55 %); a height off the marks adds its
    rounding, and the reading stays within."""
    from graphplan.graphic.gears import construct_train, ratio_bound
    _, sol = _scene(GEARS_OWN55, "own55")
    tr = sol.train
    v = construct_train(tr, 0.5, ring_mm=101.0)
    assert v.mu_l == pytest.approx(0.001) and v.h_carrier is None
    assert [v.heights[k] for k in ("A", "O2", "C")] == [17.0, 81.0, 101.0]
    s1 = v.h * v.va_mm / 17.0
    sH = s1 / tr.ratio
    assert v.ratio_bound == pytest.approx((s1 + 0.25) / (sH - 0.25) - tr.ratio, rel=1e-9)
    assert abs(v.ratio - tr.ratio) <= v.ratio_bound
    # the same train at 1:2.5 (μl = 0.0025): 6.8, 32.4, 40.4 mm — every height off the marks by 0.2 mm
    far = ratio_bound(tr, 0.0025, v.h, v.va_mm, 0.5)
    near = ratio_bound(tr, 0.001, v.h, v.va_mm, 0.5)
    y = [17 / 2.5, 81 / 2.5, 101 / 2.5]
    s1f = v.h * v.va_mm / y[0]
    assert far >= (s1f + 0.25) / (s1f / tr.ratio - 0.25) - tr.ratio + 0.2 * tr.ratio * (1 / y[0] + 1 / (y[2] - y[0]))
    assert near < far


@pytest.mark.slow
def test_the_own55_sheet_states_a_bound_under_the_labs_five_percent():
    """The A1 sheet of GEARS_OWN55 states u1H's bound under 5 % (it said ±6,7 %) and reads within it."""
    from graphplan.sheets.form import form
    from graphplan.sheets.gears import construct_on
    _, sol = _scene(GEARS_OWN55, "own55")
    _, vel, _ = construct_on(sol, form("A1"), 0.5, "uk")
    assert vel.ratio_bound / sol.train.ratio < 0.05
    assert abs(vel.ratio - sol.train.ratio) <= vel.ratio_bound


def test_the_field_check_reads_a_turned_number_where_it_is_drawn():
    """A vertical dimension's number (``rotate(-90 cx cy)``, as drawing.svg writes it) is boxed where the
    viewer draws it: an SVG written here whose unturned line would stand left of the frame."""
    from svgboxes import elements
    svg = ('<svg xmlns="http://www.w3.org/2000/svg" xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape">'
           '<g inkscape:label="gears"><text transform="rotate(-90 30 100)" font-size="5" x="10" y="100" '
           'text-anchor="start">llll</text></g></svg>')
    (_, _, (x0, y0, x1, y1)), = elements(svg)
    # turned a quarter counter-clockwise about (30, 100), read upward: the line's x = 10 … ≈17 stands at
    # y = 120 … ≈113 (its start lowest), the glyphs' height (baseline y = 100, ink above) at x ≈ 26.5 … 30
    assert 25.0 < x0 < x1 < 30.5 and 110.0 < y0 < y1 < 120.5


def test_a_broken_cell_takes_two_lines_in_a_taller_row_inside_its_rules():
    """The shared table builder with a cell broken onto two lines: that row one line pitch taller, both
    lines inside the cell's rules and one pitch apart; the rows of one-line cells as tall as before."""
    from graphplan.drawing.tables import table
    from graphplan.graphic.record import line_pitch
    one = table([["a", "b"], ["x", "1,5"], ["y", "2,5"]], [20.0, 20.0], row_h=6.0, size=2.5)
    two = table([["a", "b"], ["x", "first line\nsecond"], ["y", "2,5"]], [20.0, 20.0], row_h=6.0, size=2.5)
    rules = lambda rec: sorted({round(q.points[0][1], 6) for q in rec.items      # noqa: E731
                                if q.kind != "text" and q.points[0][1] == q.points[-1][1]})
    assert rules(one) == [-18.0, -12.0, -6.0, 0.0]
    assert rules(two) == [-18.0 - line_pitch(2.5), -12.0 - line_pitch(2.5), -6.0, 0.0]
    texts = {q.text: q.points[0][1] for q in two.items if q.kind == "text"}
    assert texts["first line"] - texts["second"] == pytest.approx(line_pitch(2.5))
    assert -12.0 - line_pitch(2.5) < texts["second"] < texts["first line"] + 2.5 < -6.0
    assert [q.text for q in one.items if q.kind == "text"] == ["a", "b", "x", "1,5", "y", "2,5"]


@pytest.mark.parametrize("lang", ["uk", "en"])
def test_the_narrow_table_3_is_under_141_mm_and_says_the_same(lang):
    """Table 3 with its long values broken (a set's): at most 141 mm at the sets' 1.4 × (beside the
    smallest pictures on an A3 field, LEFT55), every line within its column, and the same words as the
    one-line table (a formula broken at «=» repeats the sign on the new line)."""
    from graphplan.drawing.tables import enlarged
    from graphplan.report.gears import gears_json
    from graphplan.sheets.form import form
    from graphplan.sheets.gears import construct_on, train_table
    g, sol = _scene(GEARS56, "s56")
    mesh, vel, _ = construct_on(sol, form("A3"), 0.5, lang)
    doc = gears_json(sol, mesh, vel, "")
    wide, narrow = train_table(doc, lang), enlarged(train_table(doc, lang, narrow=True))
    x0, _, x1, _ = narrow.bounds()
    assert x1 - x0 <= 141.0
    words = lambda rec: [q.text for q in rec.items if q.kind == "text"]          # noqa: E731
    joined = " ".join(words(narrow)).replace("= = ", "= ").replace(":  ", ": ")
    assert joined == " ".join(words(wide))
    assert any("=" == q.text.split()[0] for q in narrow.items if q.kind == "text")   # «= 1407: …»
