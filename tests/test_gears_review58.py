"""Stop 58's gear-sheet check (helper gears58): the lead's pair 9/35 with shifts "auto" (a 9-tooth pinion:
a large shift against undercut, the tip's thickness near its bound) and a two-row type-B train chosen for
u1H = 14, K = 3 (GEARS58); gears58's own 12/18 "auto", m = 10 mm, and the type-A 24/24/72 (GEARS_OWN58),
whose A3 set no longer ends with Table 3 and its notes alone. Checked against the textbook's closed forms (test_gears_review55's ``_pair``),
a search of the "auto" grid written here, Willis' formula and the four conditions summed by hand."""
from __future__ import annotations

import math
import tomllib
from math import gcd

import pytest

from review_scenes import GEARS58, GEARS_OWN58
from test_gears_review55 import _pair


def _scene(text: str = GEARS58, name: str = "s58"):
    from graphplan.exact.gears import solve
    from graphplan.model.gears import build
    g = build(tomllib.loads(text), name)
    return g, solve(g)


@pytest.fixture(scope="module")
def s58():
    return _scene()[1]


@pytest.fixture(scope="module")
def own58():
    return _scene(GEARS_OWN58, "own58")[1]


def test_the_lead_s_58_pair_is_the_least_sliding_of_the_blocking_contour_and_agrees_with_the_closed_forms(s58):
    """Every (x1, x2) on the 0,05 grid −0,5…1,2 weighed by the closed forms: of the pairs with no undercut,
    sa ≥ 0,25m, εα ≥ 1,2 and no interference, the least max(|λ1(B1)|, |λ2(B2)|) is x = 0,55/0,4 — a
    narrow zone (x1 only 0,5 or 0,55: x_min = 1 − 9·sin²20°/2 = 0,4736 and sa1 ≥ 0,25m close it) — and
    the pair's αw, aw, εα, sa, λ are the closed forms': εα = 1,2040 ≥ 1,2, sa1 = 1,2217 mm = 0,3054m,
    inside the 0,25…0,4m a 9-tooth pinion's tip is held to."""
    sol = s58
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


def test_the_lead_s_58_train_by_willis_and_the_conditions_by_hand(s58):
    """The type-B train chosen (the smallest D/m = z3 + 2 of the sets within 4 % of u1H = 14): 17/51/21/89,
    u1H = 1 + z2·z3/(z1·z2′) = 13,714 (−2,04 %); coaxial 17 + 51 = 89 − 21; assembly (z1·z2′ + z2·z3)/
    (K·gcd(z2, z2′)) = 4896/9 = 544; neighbourhood (z1 + z2)·sin(π/K) = 58,89 > z2 + 2 = 53; ω by Willis."""
    sol = s58
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
def test_table_2_prints_the_tip_thickness_and_the_contact_ratio_against_their_bounds(lang, comma, s58):
    """Table 2 prints sa1/m = 0,3054 ≥ 0,25 and εα = 1,204 against 1,2 — the two bounds a 9-tooth pinion's
    shift runs into — with the verdicts; the terminal's quality line says the same."""
    from graphplan.report.gears import gears_json
    from graphplan.sheets.gears import quality_table
    sol = s58
    doc = gears_json(sol, None, None, "s58")
    cells = [q.text for q in quality_table(doc, lang).items if q.kind == "text"]
    ref = _pair(9, 35, 4.0, 0.55, 0.4)
    sa = f"{ref['sa'][0] / 4.0:.4f}".replace(".", comma)
    assert any(c.startswith(f"{sa} ≥ 0{comma}25") for c in cells), cells
    assert any(c.startswith(f"{ref['eps']:.3f}".replace(".", comma)) for c in cells), cells


def test_gears58_s_own_pair_and_train_by_the_closed_forms(own58):
    """GEARS_OWN58: the "auto" shifts 0,5/0,3 are the least-sliding point of the zone searched here; αw =
    26,0886°, aw = 156,944 mm, εα = 1,2109; the train 24/24/72 by Willis (u1H = 4, ωH = ω1/4, ω2 = ωH −
    (ω1 − ωH)·z1/z2 = −ω1/2) and by hand: coaxial 24 + 2·24 = 72, assembly (24 + 72)/3 = 32, neighbourhood
    48·sin 60° = 41,57 > 26; the ring's 72 teeth under the lab's 85 (internal teeth cut without undercut and
    interference only from 85 at h*a = 1) flagged «not met»."""
    from graphplan.exact.gears import conditions
    sol = own58
    grid = [round(-0.5 + 0.05 * k, 10) for k in range(35)]
    ok = [(max(abs(r["lam"][0]), abs(r["lam"][1])), -r["eps"], x1, x2) for x1 in grid for x2 in grid
          for r in [_pair(12, 18, 10.0, x1, x2)] if r is not None and r["ok"]]
    assert min(ok)[2:] == (0.5, 0.3) == tuple(sol.pair.x)
    ref = _pair(12, 18, 10.0, 0.5, 0.3)
    assert math.degrees(ref["alpha_w"]) == pytest.approx(26.08856, abs=1e-5) == math.degrees(sol.pair.alpha_w)
    assert ref["aw"] == pytest.approx(156.94408, abs=1e-5) == sol.pair.aw * 1000
    assert ref["eps"] == pytest.approx(1.210861, abs=1e-6) == sol.pair.eps
    t = sol.train
    w1 = 1500 * math.pi / 30
    assert t.ratio == pytest.approx(1 + 72 / 24) and t.omega["H"] == pytest.approx(w1 / 4)
    assert t.omega["2"] == pytest.approx(w1 / 4 - (w1 - w1 / 4) * 24 / 24) == pytest.approx(-w1 / 2)
    assert 24 + 2 * 24 == 72 and (24 + 72) % 3 == 0 and 48 * math.sin(math.pi / 3) > 26
    got = conditions("A", (24, 24, 72), 3)
    assert got == {"coaxial": True, "assembly": True, "neighbourhood": True, "no_undercut": False}


@pytest.mark.slow
def test_gears58_s_own_a3_set_ends_with_the_pictures_and_table_3_on_one_sheet():
    """The A3 set of GEARS_OWN58 drew its planetary pictures alone on a third sheet and Table 3 with its
    notes alone on a fourth (the first pictures too large to share a sheet with them). Cut again from
    smaller first pictures it is three sheets, the last holding the pictures, Table 3 and the train's
    notes — and the pictures, grown back on it, read u1H = 4 within their stated bound, under the lab's
    5 %, and ω1 within 1 % of π·1500/30 (about 80 s)."""
    from graphplan.sheets.form import form
    from graphplan.sheets.gears import on_sheet
    g, sol = _scene(GEARS_OWN58, "own58")
    _, vel, pages = on_sheet(g, sol, form("A3"), 0.5, "en")
    names = [{p.name for p in page} for page in pages]
    assert len(pages) == 3 and {"planetary", "train", "train notes"} <= names[-1], names
    assert not any(n <= {"train", "train notes"} for n in names)
    assert abs(vel.ratio - 4.0) <= vel.ratio_bound + 1e-9 and vel.ratio_bound / 4.0 < 0.05
    assert vel.omega["1"] == pytest.approx(1500 * math.pi / 30, rel=0.01)
