"""Stop 55's gear-sheet check (helper gears55): the lead's pair 14/56 with shifts "auto", m = 6 mm, and a
one-row train chosen for u1H = 7.2 with K = 3 (GEARS55); the helper's pair 16/44 with given shifts and a
two-row train chosen for u1H = 20 (GEARS_OWN55). Checked against the closed forms worked out here (inv αw
inverted by bisection), the "auto" rule and the trains' synthesis re-done by brute force, and the
composed A1 sheet's boxes — not the code's own numbers."""
from __future__ import annotations

import math
import tomllib

import pytest

from review_scenes import GEARS55, GEARS_OWN55

ALPHA = math.radians(20.0)


def _inv(a: float) -> float:
    return math.tan(a) - a


def _pair(z1: int, z2: int, m: float, x1: float, x2: float) -> dict | None:
    """The shifted pair by the textbook's closed forms (h*a = 1, c* = 0.25), inv αw by bisection; None
    where inv αw ≤ 0 or a tip circle lies inside its base circle."""
    target = 2 * (x1 + x2) * math.tan(ALPHA) / (z1 + z2) + _inv(ALPHA)
    if target <= 1e-9:
        return None
    lo, hi = 0.0, 1.5
    for _ in range(100):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if _inv(mid) < target else (lo, mid)
    aw_ = (lo + hi) / 2
    a = m * (z1 + z2) / 2
    aw = a * math.cos(ALPHA) / math.cos(aw_)
    dy = x1 + x2 - (aw - a) / m
    r = [m * z / 2 for z in (z1, z2)]
    rb = [q * math.cos(ALPHA) for q in r]
    ra = [m * (z / 2 + 1 + x - dy) for z, x in ((z1, x1), (z2, x2))]
    if any(p <= b for p, b in zip(ra, rb)):
        return None
    sa = [2 * p * ((math.pi / 2 + 2 * x * math.tan(ALPHA)) / z + _inv(ALPHA) - _inv(math.acos(b / p)))
          for p, b, z, x in zip(ra, rb, (z1, z2), (x1, x2))]
    g = aw * math.sin(aw_)
    e = [math.sqrt(p * p - b * b) for p, b in zip(ra, rb)]
    eps = (e[0] + e[1] - g) / (math.pi * m * math.cos(ALPHA))
    rho_b1, rho_b2 = g - e[1], e[0]                     # from N1
    lam1 = 1 - (g - rho_b1) / rho_b1 * z1 / z2 if rho_b1 > 0 else -math.inf
    lam2 = 1 - rho_b2 / (g - rho_b2) * z2 / z1 if g - rho_b2 > 0 else -math.inf
    lim = [q * math.sin(ALPHA) - (1 - x) * m / math.sin(ALPHA) for q, x in zip(r, (x1, x2))]
    ok = (all(x >= 1 - z * math.sin(ALPHA) ** 2 / 2 for z, x in ((z1, x1), (z2, x2)))
          and all(s >= 0.25 * m for s in sa) and eps >= 1.2
          and rho_b1 >= max(lim[0], 0.0) and g - rho_b2 >= max(lim[1], 0.0))
    return {"alpha_w": aw_, "aw": aw, "eps": eps, "sa": sa, "lam": (lam1, lam2), "ok": ok and min(sa) > 0}


def _scene(text: str, name: str):
    from graphplan.exact.gears import solve
    from graphplan.model.gears import build
    g = build(tomllib.loads(text), name)
    return g, solve(g)


@pytest.fixture(scope="module")
def lead():
    return _scene(GEARS55, "GEARS55")


def test_the_auto_shifts_are_the_rule_redone_by_brute_force(lead):
    """The documented rule over the grid −0.5…1.2 by 0.05: the passing pair whose greater |λ| at B1, B2 is
    least (ties: the larger εα, then the smaller x) — for 14/56 it is x = 0.65, 1.05; αw, aw, εα and the
    sliding there by the closed forms."""
    _, sol = lead
    grid = [round(-0.5 + 0.05 * k, 10) for k in range(35)]
    best = None
    for x1 in grid:
        for x2 in grid:
            p = _pair(14, 56, 6.0, x1, x2)
            if p is None or not p["ok"]:
                continue
            key = (round(max(abs(v) for v in p["lam"]), 12), -round(p["eps"], 12), x1, x2)
            best = min(best, (key, x1, x2)) if best else (key, x1, x2)
    assert best[1:] == (0.65, 1.05)
    p = _pair(14, 56, 6.0, 0.65, 1.05)
    pr = sol.pair
    assert pr.x == pytest.approx((0.65, 1.05))
    assert pr.alpha_w == pytest.approx(p["alpha_w"], abs=1e-12)
    assert pr.aw * 1000 == pytest.approx(p["aw"], rel=1e-12)
    assert pr.eps == pytest.approx(p["eps"], rel=1e-12) and 1.2 <= pr.eps < 1.21
    q = pr.quality()["sliding_max"]
    assert q == pytest.approx([abs(v) for v in p["lam"]], rel=1e-9)


def _type_a(u: float, K: int, top: int = 130) -> list[tuple[int, int, int]]:
    """Every type-A set z1 ≥ 17, z2 ≥ 20, z3 = z1 + 2z2 ≤ ``top``, z3 ≥ 85, z3 − z2 ≥ 8, (z1 + z3)/K whole,
    (z1 + z2)·sin(π/K) > z2 + 2, 1 + z3/z1 within ±4 % of u."""
    out = []
    for z1 in range(17, top):
        for z2 in range(20, top):
            z3 = z1 + 2 * z2
            if z3 > top or z3 < 85 or z3 - z2 < 8 or (z1 + z3) % K:
                continue
            if (z1 + z2) * math.sin(math.pi / K) > z2 + 2 and abs(1 + z3 / z1 - u) <= 0.04 * u:
                out.append((z1, z2, z3))
    return out


def test_the_train_chosen_the_nearest_named_and_why(lead):
    """u1H = 7.2, K = 3: the smallest ring within ±4 % is 17/43/103 (u1H = 120/17 = 7.0588, −1.96 %);
    20/52/124 gives 7.2 exactly (z3/z1 = 6.2 = 31/5 needs z1 a multiple of 5, 15 < 17) and is 124/103 − 1
    = 20 % larger: the notes say both and why the smaller won; Willis' ωH = ω1·17/120 and
    ω2 = ωH − (ω1 − ωH)·17/43 at n1 = 1450 rpm."""
    from graphplan.graphic.gears import construct_mesh, construct_train
    from graphplan.report.gears import gears_json
    from graphplan.sheets.gears import note_parts
    _, sol = lead
    sets = _type_a(7.2, 3)
    smallest = min(sets, key=lambda z: (z[2], abs(1 + z[2] / z[0] - 7.2), sum(z)))
    exact = min((z for z in sets if z[2] * 5 == 31 * z[0]), key=lambda z: z[2])
    assert smallest == (17, 43, 103) and exact == (20, 52, 124)
    tr = sol.train
    assert tuple(tr.z) == smallest and tr.nearest["z"] == list(exact)
    w1 = 1450 * math.pi / 30
    wH = w1 * 17 / 120
    assert tr.omega["H"] == pytest.approx(wH, rel=1e-12)
    assert tr.omega["2"] == pytest.approx(wH - (w1 - wH) * 17 / 43, rel=1e-12)
    vel = construct_train(tr, 0.5, "uk")
    mesh = construct_mesh(sol.pair, 0.5, "uk", module_mm=24.0)
    doc = gears_json(sol, mesh, vel, "")
    # stop 62: D named by what it measures — type A's ring, m·z3 (103 = z3 of the smallest set)
    assert smallest[2] == 103
    for lang, words in (("uk", ("z = 20, 52, 124 дає u_{1H} = 7,2 (точно)", "D/m = 124 проти 103",
                                "на 20 % більший", "−1,96 % у межах ±4 %", "діаметр D = m·z_3, D/m = 103")),
                        ("en", ("z = 20, 52, 124 gives u_{1H} = 7.2 (exactly)", "D/m = 124 against 103",
                                "20 % larger", "−1.96 % being within ±4 %", "diameter D = m·z_3, D/m = 103"))):
        said = " ".join(note_parts(doc, lang, mesh, vel)[-1])
        assert all(x in said for x in words), (lang, said)
        assert " 271 наборів" not in said


def test_own_type_b_train_and_its_exact_rival():
    """GEARS_OWN55: u1H = 20, K = 3, type B: 17/64/20/101 (1 + 64·101/(17·20) = 20.0118, D/m =
    max(17 + 128, 101) = 145) is chosen; 18/72/24/114 gives 20 exactly (72·114 = 19·18·24) at D/m = 162
    and is named; the conditions by hand."""
    _, sol = _scene(GEARS_OWN55, "GEARS_OWN55")
    tr = sol.train
    z1, z2, z2b, z3 = tr.z
    assert (z1, z2, z2b, z3) == (17, 64, 20, 101)
    assert tr.ratio == pytest.approx(1 + 64 * 101 / (17 * 20), rel=1e-15)
    assert z1 + z2 == z3 - z2b and (z1 * z2b + z2 * z3) % (3 * math.gcd(z2, z2b)) == 0
    assert (z1 + z2) * math.sin(math.pi / 3) > max(z2, z2b) + 2
    n = tr.nearest
    assert n["z"] == [18, 72, 24, 114] and n["ratio"] == 20.0 and n["diameter_modules"] == 162
    assert 72 * 114 == 19 * 18 * 24 and 18 + 72 == 114 - 24 and (18 * 24 + 72 * 114) % (3 * 24) == 0
    # stop 62: the notes name D — the planets' envelope z1 + 2·z2 = 145 over the ring's 101 here
    from graphplan.graphic.gears import construct_train
    from graphplan.sheets.gears import note_parts
    d = max(z1 + 2 * z2, z3)
    assert d == 145
    vel = construct_train(tr, 0.5, "uk")
    from graphplan.report.gears import train_json
    doc = {"planetary": train_json(tr, vel)}
    for lang in ("uk", "en"):
        said = " ".join(note_parts(doc, lang, None, vel)[-1])
        assert f"D = m·max(z_1 + 2z_2, z_3), D/m = {d}" in said, said
    p = _pair(16, 44, 4.0, 0.25, 0.1)
    assert sol.pair.eps == pytest.approx(p["eps"], rel=1e-12)
    assert sol.pair.aw * 1000 == pytest.approx(p["aw"], rel=1e-12)


@pytest.mark.slow
def test_the_a1_meshing_in_the_depth_band_where_a_band_scale_fits(lead):
    """Stop 55: the lead's 14/56 was drawn at 2,5:1 (the whole depth 33,75 mm, a warning) because the
    scale rule judged the 4:1 window 621 mm wide in a 611-mm zone; the drawing is 586 mm. Now 4:1 — the
    depth 2.25·6·4 = 54 mm within 40–60 —, the sheet one page, the meshing inside the field clear of every
    other block, the λ diagrams' N1N2 = aw·sin αw at their own scale within 200 mm, no depth warning."""
    from graphplan.sheets.compose import field_of
    from graphplan.sheets.form import form
    from graphplan.sheets.gears import on_sheet
    g, sol = lead
    mesh, _, pages = on_sheet(g, sol, form("A1"), 0.5, "uk")
    assert mesh.module_mm == pytest.approx(24.0) and 40.0 <= 2.25 * mesh.module_mm <= 60.0
    assert not any("depth" in en for en, _ in mesh.warnings)
    assert len(pages) == 1
    x0, y0, x1, y1 = field_of(form("A1"))
    boxes = {p.name: p.record.bounds() for p in pages[0]}
    b = boxes["meshing"]
    assert x0 - 1e-6 <= b[0] and b[2] <= x1 + 1e-6 and y0 - 1e-6 <= b[1] and b[3] <= y1 + 1e-6
    for name, o in boxes.items():
        if name != "meshing":
            assert b[2] <= o[0] or o[2] <= b[0] or b[3] <= o[1] or o[3] <= b[1], name
    p = _pair(14, 56, 6.0, 0.65, 1.05)
    line = p["aw"] * math.sin(p["alpha_w"]) / (mesh.lam.scales["mu_l"] * 1000)
    assert 120.0 <= line <= 200.0
