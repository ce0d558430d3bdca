"""Stop 58's gear-sheet check (helper gears58): the lead's pair 9/35 with shifts "auto" (a 9-tooth pinion:
a large shift against undercut, the tip's thickness near its bound) and a two-row type-B train chosen for
u1H = 14, K = 3 (GEARS58). Checked against the textbook's closed forms (test_gears_review55's ``_pair``),
a search of the "auto" grid written here, Willis' formula and the four conditions summed by hand."""
from __future__ import annotations

import math
import tomllib
from math import gcd

import pytest

from review_scenes import GEARS58
from test_gears_review55 import _pair


def _scene(text: str = GEARS58, name: str = "s58"):
    from graphplan.exact.gears import solve
    from graphplan.model.gears import build
    g = build(tomllib.loads(text), name)
    return g, solve(g)


def test_the_lead_s_58_pair_is_the_least_sliding_of_the_blocking_contour_and_agrees_with_the_closed_forms():
    """Every (x1, x2) on the 0,05 grid −0,5…1,2 weighed by the closed forms: of the pairs with no undercut,
    sa ≥ 0,25m, εα ≥ 1,2 and no interference, the least max(|λ1(B1)|, |λ2(B2)|) is x = 0,55/0,4 — a
    narrow zone (x1 only 0,5 or 0,55: x_min = 1 − 9·sin²20°/2 = 0,4736 and sa1 ≥ 0,25m close it) — and
    the pair's αw, aw, εα, sa, λ are the closed forms': εα = 1,2040 ≥ 1,2, sa1 = 1,2217 mm = 0,3054m,
    inside the 0,25…0,4m a 9-tooth pinion's tip is held to."""
    _, sol = _scene()
    p = sol.pair
    grid = [round(-0.5 + 0.05 * k, 10) for k in range(35)]
    ok = []
    for x1 in grid:
        for x2 in grid:
            r = _pair(9, 35, 4.0, x1, x2)
            if r is not None and r["ok"]:
                ok.append((max(abs(r["lam"][0]), abs(r["lam"][1])), -r["eps"], x1, x2))
    assert 5 <= len(ok) <= 20 and {x1 for *_, x1, _ in ok} == {0.5, 0.55}
    assert min(ok)[2:] == (0.55, 0.4) == tuple(p.x)
    ref = _pair(9, 35, 4.0, 0.55, 0.4)
    assert math.degrees(p.alpha_w) == pytest.approx(math.degrees(ref["alpha_w"]), abs=1e-6)
    assert math.degrees(ref["alpha_w"]) == pytest.approx(25.16890, abs=1e-5)
    assert p.aw * 1000 == pytest.approx(ref["aw"], abs=1e-6) and ref["aw"] == pytest.approx(91.36757, abs=1e-5)
    assert p.eps == pytest.approx(ref["eps"], abs=1e-9) and 1.2 <= ref["eps"] == pytest.approx(1.204015, abs=1e-6)
    assert [s * 1000 for s in p.sa] == pytest.approx(ref["sa"], abs=1e-9)
    assert 0.25 <= ref["sa"][0] / 4.0 <= 0.4 and ref["sa"][0] / 4.0 == pytest.approx(0.30542, abs=1e-5)
    l1, _ = p.sliding(p.rho_B1)
    _, l2 = p.sliding(p.rho_B2)
    assert (float(l1), float(l2)) == pytest.approx(ref["lam"], abs=1e-9)
    assert ref["lam"] == pytest.approx((-2.77251, -1.93018), abs=1e-5)


def test_the_lead_s_58_train_by_willis_and_the_conditions_by_hand():
    """The type-B train chosen (the smallest D/m = z3 + 2 of the sets within 4 % of u1H = 14): 17/51/21/89,
    u1H = 1 + z2·z3/(z1·z2′) = 13,714 (−2,04 %); coaxial 17 + 51 = 89 − 21; assembly (z1·z2′ + z2·z3)/
    (K·gcd(z2, z2′)) = 4896/9 = 544; neighbourhood (z1 + z2)·sin(π/K) = 58,89 > z2 + 2 = 53; ω by Willis."""
    _, sol = _scene()
    t = sol.train
    z1, z2, z2b, z3 = t.z
    assert (z1, z2, z2b, z3) == (17, 51, 21, 89)
    assert z1 + z2 == z3 - z2b == 68
    assert (z1 * z2b + z2 * z3) % (3 * gcd(z2, z2b)) == 0 and (z1 * z2b + z2 * z3) // 9 == 544
    assert (z1 + z2) * math.sin(math.pi / 3) > max(z2, z2b) + 2
    u = 1 + z2 * z3 / (z1 * z2b)
    assert t.ratio == pytest.approx(u, rel=1e-12) and 100 * (u / 14 - 1) == pytest.approx(-2.0408, abs=1e-4)
    w1 = 1450 * math.pi / 30
    assert t.omega["H"] == pytest.approx(w1 / u, rel=1e-12)
    assert t.omega["2"] == pytest.approx(w1 / u - (w1 - w1 / u) * z1 / z2, rel=1e-12)
    assert 1 + 52 * 90 / (18 * 20) == 14                  # the exact set the notes name, D/m 122 against 119


@pytest.mark.parametrize("lang, comma", [("uk", ","), ("en", ".")])
def test_table_2_prints_the_tip_thickness_and_the_contact_ratio_against_their_bounds(lang, comma):
    """Table 2 prints sa1/m = 0,3054 ≥ 0,25 and εα = 1,204 against 1,2 — the two bounds a 9-tooth pinion's
    shift runs into — with the verdicts; the terminal's quality line says the same."""
    from graphplan.report.gears import gears_json
    from graphplan.sheets.gears import quality_table
    _, sol = _scene()
    doc = gears_json(sol, None, None, "s58")
    cells = [q.text for q in quality_table(doc, lang).items if q.kind == "text"]
    ref = _pair(9, 35, 4.0, 0.55, 0.4)
    sa = f"{ref['sa'][0] / 4.0:.4f}".replace(".", comma)
    assert any(c.startswith(f"{sa} ≥ 0{comma}25") for c in cells), cells
    assert any(c.startswith(f"{ref['eps']:.3f}".replace(".", comma)) for c in cells), cells
