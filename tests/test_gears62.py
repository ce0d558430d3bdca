"""Stop 62's gear scenes against closed forms worked out apart from the code: the lead's GEARS62 (a 10/32
pair with shifts "auto", m = 4 mm: x = 0.6/0.35 by the rule, the geometry by the involute function; a
type-B train synthesised for u1H = 15, K = 3: 17/52/20/89 the smallest within ±4 %, 19/56/20/95 exact
but larger) and gc62's GC62_GEARS (an equal-and-opposite shift pair 14/26, x = ±0.3: αw = α, aw = a; a
type-A train for u1H = 8, K = 3)."""
from __future__ import annotations

import math
import tomllib

import pytest
from scipy.optimize import brentq

from review_scenes import GC62_GEARS, GEARS62


def _solve(text: str, name: str):
    from graphplan.exact.gears import solve
    from graphplan.model.gears import build
    return solve(build(tomllib.loads(text), name))


def _inv(a: float) -> float:
    return math.tan(a) - a


def _pair(z1, z2, m, x1, x2, ha=1.0, c=0.25, alpha=20.0):
    """The pair by the textbook's formulas (mm): inv αw, aw, Δy, the radii, s, sa, εα."""
    al = math.radians(alpha)
    iw = 2 * (x1 + x2) * math.tan(al) / (z1 + z2) + _inv(al)
    aw_ = brentq(lambda a: _inv(a) - iw, 1e-6, 1.5) if abs(x1 + x2) > 1e-15 else al
    a = m * (z1 + z2) / 2
    aw = a * math.cos(al) / math.cos(aw_)
    dy = x1 + x2 - (aw - a) / m
    r = (m * z1 / 2, m * z2 / 2)
    rb = tuple(q * math.cos(al) for q in r)
    ra = tuple(q + m * (ha + x - dy) for q, x in zip(r, (x1, x2)))
    rf = tuple(q - m * (ha + c - x) for q, x in zip(r, (x1, x2)))
    s = tuple(m * (math.pi / 2 + 2 * x * math.tan(al)) for x in (x1, x2))
    sa = tuple(2 * rA * (sk / (2 * rk) + _inv(al) - _inv(math.acos(rB / rA)))
               for rA, rk, rB, sk in zip(ra, r, rb, s))
    g = aw * math.sin(aw_)
    eps = (math.sqrt(ra[0] ** 2 - rb[0] ** 2) + math.sqrt(ra[1] ** 2 - rb[1] ** 2) - g) / (math.pi * m * math.cos(al))
    return {"aw_deg": math.degrees(aw_), "aw": aw, "dy": dy, "ra": ra, "rf": rf, "s": s, "sa": sa, "eps": eps}


@pytest.mark.parametrize("scene, name, z, m, x", [(GEARS62, "GEARS62", (10, 32), 4.0, (0.6, 0.35)),
                                                  (GC62_GEARS, "GC62_GEARS", (14, 26), 6.0, (0.3, -0.3))])
def test_the_pairs_geometry_by_the_textbooks_formulas(scene, name, z, m, x):
    """GEARS62: x1 = 0.6 ≥ x_min = 1 − 10·sin²20°/2 = 0.4151 (z = 10 undercut without a shift), αw = 25.3614°,
    aw = 87.353 mm, εα = 1.2035 ≥ 1.2 — the values the A1 sheet's Table 1 prints; GC62_GEARS: x1 + x2 = 0, so
    αw = 20°, aw = a = 120 mm, Δy = 0, and x2 = −0.3 ≥ 1 − 26·sin²20°/2 = −0.5207 (no undercut)."""
    sol = _solve(scene, name).pair
    want = _pair(*z, m, *x)
    assert sol.x == pytest.approx(x, abs=1e-12)
    assert math.degrees(sol.alpha_w) == pytest.approx(want["aw_deg"], abs=1e-9)
    assert sol.aw * 1000 == pytest.approx(want["aw"], abs=1e-9) and sol.dy == pytest.approx(want["dy"], abs=1e-9)
    for k in (0, 1):
        assert sol.ra[k] * 1000 == pytest.approx(want["ra"][k], abs=1e-9)
        assert sol.rf[k] * 1000 == pytest.approx(want["rf"][k], abs=1e-9)
        assert sol.s[k] * 1000 == pytest.approx(want["s"][k], abs=1e-9)
        assert sol.sa[k] * 1000 == pytest.approx(want["sa"][k], abs=1e-9)
        assert x[k] >= 1 - z[k] * math.sin(math.radians(20)) ** 2 / 2
    assert sol.eps == pytest.approx(want["eps"], abs=1e-9) and sol.eps >= 1.2
    if name == "GEARS62":
        assert want["aw_deg"] == pytest.approx(25.3614, abs=1e-4) and want["eps"] == pytest.approx(1.2035, abs=1e-4)
    else:
        assert want["aw_deg"] == pytest.approx(20.0) and want["aw"] == pytest.approx(120.0)


def _sets(kind: str, u: float, K: int, top: int = 120):
    """Every set meeting coaxiality, assembly, neighbourhood and the no-undercut limits (external z ≥ 17, the
    planet meshing the ring ≥ 20, the ring ≥ 85, ring − planet ≥ 8) with u1H within ±4 %, as
    (D/m, |u1H − u|, z): D/m = z3 (A), max(z1 + 2z2, z3) (B)."""
    out = []
    sK = math.sin(math.pi / K)
    for z1 in range(17, top + 1):
        for z2 in range(17 if kind == "B" else 20, top + 1):
            for zb in (range(20, top + 1) if kind == "B" else (None,)):
                if kind == "A":
                    z3 = z1 + 2 * z2
                    ok = z3 >= 85 and z3 - z2 >= 8 and (z1 + z3) % K == 0 and (z1 + z2) * sK > z2 + 2
                    ratio, d, z = 1 + z3 / z1, z3, (z1, z2, z3)
                else:
                    z3 = z1 + z2 + zb
                    ok = (z3 >= 85 and z3 - zb >= 8 and (z1 * zb + z2 * z3) % (K * math.gcd(z2, zb)) == 0
                          and (z1 + z2) * sK > max(z2, zb) + 2)
                    ratio, d, z = 1 + z2 * z3 / (z1 * zb), max(z1 + 2 * z2, z3), (z1, z2, zb, z3)
                if ok and abs(ratio - u) <= 0.04 * u:
                    out.append((d, abs(ratio - u), z, ratio))
    return out


@pytest.mark.slow
@pytest.mark.parametrize("scene, name, kind, u, chosen, exact", [
    (GEARS62, "GEARS62", "B", 15.0, (17, 52, 20, 89), (19, 56, 20, 95)),
    (GC62_GEARS, "GC62_GEARS", "A", 8.0, (17, 49, 115), (18, 54, 126))])
def test_the_train_the_smallest_within_4_percent_and_the_exact_one_named(scene, name, kind, u, chosen, exact):
    """The brute force's smallest train by D/m within ±4 % is the one chosen (GEARS62: 17/52/20/89, u1H =
    1 + 52·89/(17·20) = 14.61, −2.59 %, D/m = 17 + 104 = 121); the smallest exact one (19/56/20/95, D/m =
    131; type A 18/54/126, D/m = 126) is what the notes name against it, with the rule and D defined."""
    from graphplan.graphic.gears import construct_train
    from graphplan.report.gears import train_json
    from graphplan.sheets.gears import note_parts
    tr = _solve(scene, name).train
    sets = _sets(kind, u, 3)
    best = min(sets, key=lambda t: (t[0], t[1], sum(t[2])))
    near = min((t for t in sets if t[1] < 1e-12), key=lambda t: (t[0], sum(t[2])))
    assert best[2] == chosen == tuple(tr.z) and near[2] == exact and tuple(tr.nearest["z"]) == exact
    vel = construct_train(tr, 0.5, "uk")
    doc = {"planetary": train_json(tr, vel)}
    pct = f"{100 * (best[3] - u) / u:.2f}".replace("-", "−")
    for lang in ("uk", "en"):
        said = " ".join(note_parts(doc, lang, None, vel)[-1])
        z = ", ".join(map(str, exact))
        assert f"z = {z}" in said and f"D/m = {near[0]}" in said and f"D/m = {best[0]}" in said
        assert (pct.replace(".", ",") if lang == "uk" else pct) + " %" in said
        assert ("D = m·z_3" if kind == "A" else "D = m·max(z_1 + 2z_2, z_3)") in said
