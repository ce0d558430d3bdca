"""Stop 52's gear-sheet review (helper gear52): the lead's pair 11/23 with m = 6 mm and x = 0,5/0,3 given, a
type-B train for u = 16, K = 3, n1 = 960 rpm (GEARS52); the helper's own 15/37 with x2 < 0 and a type-B train
with its teeth given, K = 2 (GEARS_OWN52) — the closed forms written out here (not the code's) — and the set's
composition on synthetic leaves of known sizes (the drawings over the title block, the tables' 7-mm rows) and
the title block's long name."""
from __future__ import annotations

import math
import tomllib

import pytest

from review_scenes import GEARS52, GEARS_OWN52
from test_gears_review50 import pair_closed


def _solved(text: str, name: str):
    from graphplan.exact.gears import solve
    from graphplan.model.gears import build
    g = build(tomllib.loads(text), name)
    return g, solve(g)


@pytest.mark.parametrize("text, name, z, x, m, published", [
    # GEARS52 by hand: inv αw = 2·0,8·tg 20°/34 + inv 20° → αw = 25,5291°, aw = 102·cos 20°/cos αw = 106,219 mm,
    # ra = 41,419/76,219 mm, sa = 2,490/4,308 mm, εα = 1,2278, λ1(B1) = −2,355, λ2(B2) = −2,134
    (GEARS52, "GEARS52", (11, 23), (0.5, 0.3), 0.006, (25.5291, 106.219, 1.2278, -2.355, -2.134)),
    # GEARS_OWN52: x1 + x2 = 0,2 → αw = 21,1387°, aw = 104,779 mm, εα = 1,4621, λ1(B1) = −1,808, λ2(B2) = −2,449
    (GEARS_OWN52, "GEARS_OWN52", (15, 37), (0.45, -0.25), 0.004, (21.1387, 104.779, 1.4621, -1.808, -2.449)),
], ids=["GEARS52", "GEARS_OWN52"])
def test_the_pairs_are_the_closed_forms(text, name, z, x, m, published):
    _, sol = _solved(text, name)
    p = sol.pair
    c = pair_closed(*z, m, *x)
    a_w, aw_mm, eps, lam1, lam2 = published
    assert math.degrees(c["alpha_w"]) == pytest.approx(a_w, abs=5e-5)
    assert c["aw"] * 1000 == pytest.approx(aw_mm, abs=5e-4)
    assert round(c["eps"], 4) == eps and round(c["lam1_B1"], 3) == lam1 and round(c["lam2_B2"], 3) == lam2
    assert math.degrees(p.alpha_w) == pytest.approx(math.degrees(c["alpha_w"]), abs=1e-9)
    assert p.aw == pytest.approx(c["aw"], rel=1e-12) and p.eps == pytest.approx(c["eps"], rel=1e-12)
    for k in (0, 1):
        assert p.ra[k] == pytest.approx(c["ra"][k], rel=1e-12) and p.rf[k] == pytest.approx(c["rf"][k], rel=1e-12)
        assert p.sa[k] == pytest.approx(c["sa"][k], rel=1e-9) and p.s[k] == pytest.approx(c["s"][k], rel=1e-12)
        # no undercut (x ≥ 1 − z·sin²α/2), not pointed (sa ≥ 0,25m): as the sheet's Table 2 says
        assert x[k] >= 1 - z[k] * math.sin(math.radians(20)) ** 2 / 2 and c["sa"][k] >= 0.25 * m


@pytest.mark.parametrize("text, name, z, rpm", [
    (GEARS52, "GEARS52", (17, 55, 20, 92), 960),       # the rule's choice for u = 16, K = 3: D/m = 127
    (GEARS_OWN52, "GEARS_OWN52", (21, 45, 22, 88), 1450),
], ids=["GEARS52", "GEARS_OWN52"])
def test_the_type_b_trains_are_willis(text, name, z, rpm):
    """u1H = 1 + z2·z3/(z1·z2') (15,882 and 9,5714); ωH = ω1/u1H, the block's ω2 = ωH − (ω1 − ωH)·z1/z2 (Willis
    with the ring fixed); coaxial z1 + z2 = z3 − z2', assembled (z1·z2' + z2·z3)/(K·gcd(z2, z2')) whole."""
    _, sol = _solved(text, name)
    t = sol.train
    assert tuple(t.z) == z
    z1, z2, z2b, z3 = z
    K = tomllib.loads(text)["planetary"]["planets"]
    assert z1 + z2 == z3 - z2b and (z1 * z2b + z2 * z3) % (K * math.gcd(z2, z2b)) == 0
    assert (z1 + z2) * math.sin(math.pi / K) > max(z2, z2b) + 2
    u = 1 + z2 * z3 / (z1 * z2b)
    w1 = rpm * math.pi / 30
    assert t.ratio == pytest.approx(u, rel=1e-12)
    assert t.omega["H"] == pytest.approx(w1 / u, rel=1e-12)
    assert t.omega["2"] == pytest.approx(w1 / u - (w1 - w1 / u) * z1 / z2, rel=1e-12)
    # Willis for the block 2–2′ and the fixed ring: (ω1 − ωH)/(0 − ωH) = −(z2·z3)/(z1·z2′)
    assert (t.omega["1"] - t.omega["H"]) / (0 - t.omega["H"]) == pytest.approx(-z2 * z3 / (z1 * z2b), rel=1e-12)


def _box(name: str, w: float, h: float):
    """A leaf of a known size: a rectangle ``w`` × ``h`` mm."""
    from graphplan.drawing.layout import Leaf
    from graphplan.graphic.record import Record
    rec = Record(name)
    rec.add("polygon", [(0.0, 0.0), (w, 0.0), (w, h), (0.0, h)], role="thin", layer="drawing")
    return Leaf(name, record=rec)


def test_a_sets_first_sheet_rises_its_drawing_over_the_title_block_for_the_data_under_it():
    """GEARS52's A3 meshing with its caption is 382 × 212 mm; the first sheet's field 385 × 277 mm over a
    61-mm title block. The task data (190 × 30 mm) fit under it left of the block only where the meshing
    stands over the block: split midway the spare height, its foot fell 3 mm into the block's reach and the
    data went to the next sheet (stop 52)."""
    from graphplan.sheets.compose import keep_out
    from graphplan.sheets.form import form
    from graphplan.sheets.gearset import page
    f = form("A3")
    placed = page([_box("meshing", 382.0, 212.0), _box("data", 190.0, 30.0)], f, True)
    assert placed is not None
    got = {p.name: p.record.bounds() for p in placed()}
    keep = keep_out(f)
    assert got["meshing"][1] >= keep[3] - 1e-6                 # over the title block
    assert got["data"][2] <= keep[0] + 1e-6 and got["data"][3] <= got["meshing"][1]   # beside it, under the meshing


def test_a_set_takes_the_tables_second_larger_size_where_its_sheet_holds_only_that():
    """The tables tried larger in turn on each sheet of the chosen cut (stop 52: the set knew only the
    8,4-mm rows, which GEARS52's A3 sheet 2 could not hold, and drew its tables with 2,5-mm letters beside
    3,5-mm notes): a 201-mm diagram with a table 119 mm wide ruled, 250 mm at the first larger size (no room
    beside the diagram in 385 mm) and 168 mm at the second (room)."""
    from graphplan.sheets.form import form
    from graphplan.sheets.gearset import set_pages
    f = form("A3")
    leaves = [_box("sliding", 201.0, 137.0), _box("geometry", 119.0, 102.0)]
    larger = [{"geometry": _box("geometry", 250.0, 150.0)}, {"geometry": _box("geometry", 168.0, 120.0)}]
    pages = set_pages(leaves, f, None, larger)
    assert pages is not None and len(pages) == 1
    got = {p.name: p.record.bounds() for p in pages[0]}
    assert got["geometry"][2] - got["geometry"][0] == pytest.approx(168.0)


def test_a_long_name_stays_inside_the_title_blocks_cell():
    """GEARS_OWN52's name takes five lines of 2,5-mm letters in the 70 × 25-mm cell (68 mm lettered): at the
    6-mm pitch they ran 5 mm over its rules (6 words overprinted). Now the name takes the name fields'
    last size, 2 mm (four lines at 5,2 mm), and the step is tightened to the cell only past it: every line
    inside the cell, the lines apart by 1,6 h + 2 mm, the English name too."""
    from graphplan.graphic.record import line_pitch
    from graphplan.sheets.form import form, title_block, title_block_box
    f = form("A1")
    x0, y0, _, _ = title_block_box(f)
    for key in ("title", "title_en"):
        title = tomllib.loads(GEARS_OWN52)[key]
        rec = title_block(f, {"title": title, "designation": "ТММ.ЗП.52.100"})
        words = set(title.split())
        lines = sorted((p for p in rec.items if p.kind == "text" and p.text and set(p.text.split()) <= words),
                       key=lambda p: -p.points[0][1])
        assert " ".join(p.text for p in lines).split() == title.split()      # the whole name, in order
        for p in lines:
            y = p.points[0][1]
            assert y - 0.3 * p.size >= y0 + 15.0 - 1e-6 and y + p.size <= y0 + 40.0 + 1e-6
            assert p.size >= 2.0
        for a, b in zip(lines, lines[1:]):
            assert a.points[0][1] - b.points[0][1] >= line_pitch(a.size) - 1e-6


@pytest.mark.slow
def test_the_a3_set_letters_its_tables_at_3_5_mm():
    """GEARS52's A3 set (four sheets at stop 52, three since stop 57 saved one; about 8 s): every table's
    lettering 3,5 mm — the λ diagrams' sheet holds Tables 1 and 2 in 7-mm rows once the task data stand
    under the meshing on the first sheet."""
    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.form import form
    from graphplan.sheets.sheet import BUILDERS
    from graphplan.model.gears import build
    g = build(tomllib.loads(GEARS52), "GEARS52")
    s = BUILDERS["gears"](g, form("A3"), SheetOptions(lang="uk", sheet="gears"))
    assert len(s.pages) in (3, 4)
    sizes = {p.size for page in s.pages for pl in page.placed if pl.name in ("geometry", "quality", "train")
             for p in pl.record.items if p.kind == "text"}
    assert sizes and min(sizes) >= 3.5 - 1e-9
    assert [pl.name for pl in s.pages[0].placed] == ["meshing", "data"]


@pytest.mark.parametrize("z, K, gcd", [((17, 55, 20, 92), 3, 5), ((21, 45, 22, 88), 2, 1)], ids=["GEARS52", "GEARS_OWN52"])
def test_table_3_writes_the_type_b_assembly_condition_out(z, K, gcd):
    """Table 3 printed «5400/15 = 360» (where from?); now (z1·z2′ + z2·z3)/(K·gcd(z2, z2′)) with its numbers,
    the gcd left off where it is 1, and the quotient whole: (17·20 + 55·92)/(3·5) = 360, (21·22 + 45·88)/2 = 2211."""
    from graphplan.sheets.gears import condition_numbers
    z1, z2, z2b, z3 = z
    assert math.gcd(z2, z2b) == gcd and (z1 * z2b + z2 * z3) % (K * gcd) == 0
    den = f"({K}·{gcd})" if gcd > 1 else f"{K}"
    got = condition_numbers({"z": list(z), "planets": K, "type": "B"}, "uk")["assembly"]
    assert got == f"({z1}·{z2b} + {z2}·{z3})/{den} = {(z1 * z2b + z2 * z3) // (K * gcd)}"


def test_the_lambda_diagrams_go_beside_the_meshing_one_gost_step_smaller():
    """GEARS51's A1 (stop 51's leftover, «the strip beside the meshing, 2 × 88 mm»): the meshing at 2,5:1 was
    434 mm wide with its caption (412 since stop 53: the a_w dimension's number along its line, GOST 2.307), the λ diagrams at its scale 205 mm (N1N2 = aw·sin αw = 74,8 mm of the part,
    187 mm drawn) — 6 mm too wide for the 615-mm drawings' zone, so the meshing stood centred between two
    88-mm blank strips. At the next GOST 2.302 scale, 2:1, N1N2 is 150 mm drawn and they stand beside it."""
    from review_scenes import GEARS51
    from graphplan.drawing.layout import GAP
    from graphplan.sheets.compose import field_of
    from graphplan.sheets.form import form
    from graphplan.sheets.gears import TITLE, beside, construct_on, meshing_leaf, sliding_diagram, sliding_leaf
    from graphplan.exact.gears import solve
    from graphplan.model.gears import build
    scene = tomllib.loads(GEARS51)
    del scene["planetary"]                # (the pair alone: the same 434-mm meshing, without growing the train)
    sol = solve(build(scene, "GEARS51"))
    f = form("A1")
    mesh, _, _ = construct_on(sol, f, 0.5, "uk")
    region = field_of(f)
    zone = region[2] - region[0] - max(TITLE, 150.0) - GAP
    w = lambda r: r.bounds()[2] - r.bounds()[0]                 # noqa: E731
    assert mesh.mu_l == pytest.approx(0.0004) and w(meshing_leaf(mesh, "uk")) == pytest.approx(412.0, abs=0.5)
    own = sliding_leaf(sliding_diagram(sol.pair, mesh, 25.0, mesh.mu_l), "uk")
    assert w(meshing_leaf(mesh, "uk")) + GAP + w(own) > zone      # at the meshing's scale: no room beside it
    assert mesh.lam.scales["mu_l"] == pytest.approx(0.0005) and beside(f, mesh, "uk")
    g = sol.pair.aw * math.sin(sol.pair.alpha_w)                  # N1N2 of the part, m
    assert g / 0.0005 == pytest.approx(149.6, abs=0.1) and g / 0.0005 >= 120.0


def test_table_2_writes_each_value_beside_its_bound_with_the_relation_that_holds():
    """Table 2 printed «x ≥ x_min» whatever held («0 ≥ 0,2981» beside «не викон.» for an undercut pinion)
    and sa/m alone; now each cell is value, relation, bound: GEARS52's sa/m = 2,490/6 = 0,415 ≥ 0,25 (the
    closed form), and an unshifted 12/30 pinion 0 < 1 − 12·sin²20°/2 = 0,2981, its contact past N1."""
    from graphplan.exact.gears import solve
    from graphplan.model.gears import build
    from graphplan.report.gears import gears_json
    from graphplan.sheets.gears import quality_table

    def cells(z, shifts):
        scene = tomllib.loads(GEARS52)
        del scene["planetary"]
        scene["gears"].update(z=list(z), shifts=list(shifts))
        rec = quality_table(gears_json(solve(build(scene, "q52")), None, None, ""), "uk")
        return [p.text for p in rec.items if p.kind == "text"]

    c = pair_closed(11, 23, 0.006, 0.5, 0.3)
    got = cells((11, 23), (0.5, 0.3))
    assert f"{c['sa'][0] / 0.006:.3f} ≥ 0,25".replace(".", ",") in got and "0,5 ≥ 0,3566" in got
    x_min = 1 - 12 * math.sin(math.radians(20)) ** 2 / 2
    got = cells((12, 30), (0.0, 0.0))
    assert f"0 < {x_min:.4f}".replace(".", ",") in got and "не викон. / викон." in got
    assert f"0 ≥ {x_min:.4f}".replace(".", ",") not in got and "0 ≥ −0,7547" in got   # (wheel 2's holds)
