"""Stop 50's gear-sheet review (helper gear50): the lead's pair 15/45 with given shifts 0.5/0.2 and a type-B
train for u = 12, K = 3, n1 = 960 rpm (GEARS50), and the helper's own 12/33 (x = 0.4/−0.15) with a type-B
train of given teeth 21/42/22/85, K = 4 (GEARS_OWN50) — checked against the closed forms (written out
here, not the code's) and measured on the drawn records."""
from __future__ import annotations

import cmath
import math
import tomllib

import pytest

from review_scenes import GEARS47, GEARS50, GEARS_OWN50

ALPHA = math.radians(20.0)


def inv(t: float) -> float:
    return math.tan(t) - t


def alpha_w_of(inv_w: float) -> float:
    """inv αw = given → αw by Newton's method (d inv/dα = tan²α)."""
    a = 0.4
    for _ in range(50):
        a -= (inv(a) - inv_w) / math.tan(a) ** 2
    return a


def pair_closed(z1: int, z2: int, m: float, x1: float, x2: float) -> dict:
    """The textbook's shifted pair (REFERENCE §12), α = 20°, h*a = 1, c* = 0.25, lengths in m."""
    aw_ = alpha_w_of(2 * (x1 + x2) * math.tan(ALPHA) / (z1 + z2) + inv(ALPHA))
    a = m * (z1 + z2) / 2
    aw = a * math.cos(ALPHA) / math.cos(aw_)
    y = (aw - a) / m
    dy = x1 + x2 - y
    out = {"alpha_w": aw_, "a": a, "aw": aw, "y": y, "dy": dy, "r": [], "rb": [], "ra": [], "rf": [], "s": [], "sa": []}
    for z, x in ((z1, x1), (z2, x2)):
        r = m * z / 2
        rb = r * math.cos(ALPHA)
        ra = m * (z / 2 + 1 + x - dy)
        s = m * (math.pi / 2 + 2 * x * math.tan(ALPHA))
        sa = 2 * ra * (s / (2 * r) + inv(ALPHA) - inv(math.acos(rb / ra)))
        for k, v in (("r", r), ("rb", rb), ("ra", ra), ("rf", m * (z / 2 - 1.25 + x)), ("s", s), ("sa", sa)):
            out[k].append(v)
    pb = math.pi * m * math.cos(ALPHA)
    e1, e2 = (math.sqrt(out["ra"][k] ** 2 - out["rb"][k] ** 2) for k in (0, 1))
    g = aw * math.sin(aw_)
    out.update(pb=pb, g=g, eps=(e1 + e2 - g) / pb, rho_B1=g - e2, rho_B2=e1)
    # the specific slidings at the ends of the working part: λ1 = 1 − (ρ2/ρ1)(z1/z2), λ2 = 1 − (ρ1/ρ2)(z2/z1)
    out["lam1_B1"] = 1 - (g - out["rho_B1"]) / out["rho_B1"] * z1 / z2
    out["lam2_B2"] = 1 - out["rho_B2"] / (g - out["rho_B2"]) * z2 / z1
    return out


def _solved(text: str, name: str):
    from graphplan.exact.gears import solve
    from graphplan.model.gears import build
    g = build(tomllib.loads(text), name)
    return g, solve(g)


@pytest.fixture(scope="module")
def sheet50():
    """GEARS50's A1 sheet in Ukrainian as build_gears_sheet composes it (about 4 s): (solution, mesh,
    velocities, sheet)."""
    from graphplan.sheets.compose import compose
    from graphplan.sheets.form import form
    from graphplan.sheets.gears import _fields, on_sheet
    g, sol = _solved(GEARS50, "GEARS50")
    mesh, vel, pages = on_sheet(g, sol, form("A1"), 0.5, "uk")
    return sol, mesh, vel, compose(form("A1"), pages, _fields(g, "uk", mesh.mu_l), "uk", g.title_in("uk"))


@pytest.mark.parametrize("text, name, z, m, x", [(GEARS50, "GEARS50", (15, 45), 0.005, (0.5, 0.2)),
                                                 (GEARS_OWN50, "GEARS_OWN50", (12, 33), 0.006, (0.4, -0.15))],
                         ids=["GEARS50", "GEARS_OWN50"])
def test_the_pair_is_the_closed_forms(text, name, z, m, x):
    """inv αw = 2(x1+x2)tgα/(z1+z2) + inv α; aw, y, Δy, ra, rf, s, sa and εα by the textbook's formulas;
    the slidings λ1 at B1 and λ2 at B2 (the worst on the working part). GEARS50: αw = 23,110°, aw =
    153,252 mm, εα = 1,3836, λ1 = −1,466, λ2 = −1,541."""
    _, sol = _solved(text, name)
    c = pair_closed(*z, m, *x)
    p = sol.pair
    assert abs(p.alpha_w - c["alpha_w"]) < 1e-9 and c["alpha_w"] > ALPHA
    for key in ("a", "aw", "y", "dy", "pb", "g", "eps", "rho_B1", "rho_B2"):
        assert getattr(p, key) == pytest.approx(c[key], rel=1e-9, abs=1e-12), key
    for key in ("r", "rb", "ra", "rf", "s", "sa"):
        assert getattr(p, key) == pytest.approx(tuple(c[key]), rel=1e-9), key
    l1, _ = p.sliding(p.rho_B1)
    _, l2 = p.sliding(p.rho_B2)
    assert (l1, l2) == pytest.approx((c["lam1_B1"], c["lam2_B2"]), rel=1e-9)
    if name == "GEARS50":
        assert math.degrees(c["alpha_w"]) == pytest.approx(23.1101, abs=1e-4)
        assert (c["aw"] * 1000, c["eps"], c["lam1_B1"], c["lam2_B2"]) == pytest.approx(
            (153.252, 1.3836, -1.466, -1.541), abs=1e-3)


@pytest.mark.parametrize("text, name, K, rpm, omega", [(GEARS50, "GEARS50", 3, 960.0, None),
                                                       (GEARS_OWN50, "GEARS_OWN50", 4, None, 150.0)],
                         ids=["GEARS50", "GEARS_OWN50"])
def test_the_type_b_train_is_willis_and_its_conditions(text, name, K, rpm, omega):
    """Type B: u1H = 1 + z2·z3/(z1·z2') (Willis with the ring fixed); coaxiality z1 + z2 = z3 − z2';
    assembly (z1·z2' + z2·z3)/(K·gcd(z2, z2')) whole; neighbourhood (z1 + z2)·sin(π/K) > max(z2, z2') + 2;
    ωH = ω1/u1H, ω2 = ωH − (ω1 − ωH)·z1/z2. GEARS50's 17/47/22/86: u1H 11,807 (−1,60 % of 12); the
    own 21/42/22/85 with K = 4: 44,55 > 44 — the neighbourhood met within 1,3 %."""
    _, sol = _solved(text, name)
    z1, z2, z2b, z3 = sol.train.z
    u = 1 + z2 * z3 / (z1 * z2b)
    w1 = rpm * math.pi / 30 if rpm else omega
    wH = w1 / u
    assert sol.train.ratio == pytest.approx(u, rel=1e-12)
    assert sol.train.omega["H"] == pytest.approx(wH, rel=1e-9)
    assert sol.train.omega["2"] == pytest.approx(wH - (w1 - wH) * z1 / z2, rel=1e-9)
    assert z1 + z2 == z3 - z2b
    assert (z1 * z2b + z2 * z3) % (K * math.gcd(z2, z2b)) == 0
    assert (z1 + z2) * math.sin(math.pi / K) > max(z2, z2b) + 2
    assert all(sol.train.conditions.values())
    if name == "GEARS50":
        assert sol.train.z == (17, 47, 22, 86) and abs(u - 12) / 12 <= 0.04
        assert u == pytest.approx(11.807, abs=1e-3)
    else:
        assert (z1 + z2) * math.sin(math.pi / K) / (max(z2, z2b) + 2) < 1.013


def _alpha_w_ok(mesh, aw_: float) -> tuple[bool, str]:
    """Whether the letter α_w lies inside the angle of mesh at P (between the tangent at P, the
    horizontal, and the line of action P–N2 left of P, or the vertically opposite angle) and the αw
    arc runs from one side of the angle to the other, centred on P."""
    P, N2 = mesh.points["P"], mesh.points["N2"]
    up = (N2 - P) / abs(N2 - P)
    drawn = math.pi - cmath.phase(up)               # the angle as drawn (its radii laid off to 0,5 mm)
    assert abs(drawn - aw_) < 2e-3                  # the line of action at αw to the tangent
    aw_ = drawn
    t = [q for q in mesh.record.items if q.kind == "text" and q.text == "α_w"]
    arcs = [q for q in mesh.record.items if q.kind == "arc" and q.step == "αw"]
    if len(t) != 1 or len(arcs) != 1:
        return False, f"{len(t)} letters, {len(arcs)} arcs"
    x0, y0, x1, y1 = t[0].bounds()
    arc = arcs[0]
    if abs(complex(*arc.points[0]) - P) > 1e-6 or abs((arc.angles[1] - arc.angles[0]) - math.degrees(aw_)) > 1e-6:
        return False, "the arc is not the angle's"
    side = 1 if arc.angles[0] < 180.0 else -1
    for q in (complex(x0, y0), complex(x0, y1), complex(x1, y0), complex(x1, y1)):
        v = side * (q - P)
        if not (v.real < 0 and v.imag > 0 and (up.conjugate() * v).imag > 0):
            return False, f"corner {q - P} outside"
    return True, ""


def test_alpha_w_is_lettered_inside_its_angle_on_the_sheet(sheet50):
    """Stop 49's mark: αw's letter stood above the line of action, outside its angle (p_b's dimension
    crossed every spot inside). Now its box lies between the tangent at P and the line of action (on
    the sheet's meshing of GEARS50), the arc of αw centred on P and spanning αw."""
    sol, mesh, _, _ = sheet50
    ok, why = _alpha_w_ok(mesh, sol.pair.alpha_w)
    assert ok, why


@pytest.mark.parametrize("text, name, md", [(GEARS47, "GEARS47", 20.0), (GEARS_OWN50, "GEARS_OWN50", 24.0)],
                         ids=["GEARS47", "GEARS_OWN50"])
def test_alpha_w_inside_and_b2_beside_its_point_on_other_meshings(text, name, md):
    """The same on GEARS47's meshing (αw 22,5°, a narrower angle) and the own 12/33; GEARS47's B2 —
    lettered 16,5 mm off on a leader at stop 49 — now within 7 mm of its point (a 2,5-mm letter
    beside it where a 3,5-mm one does not fit)."""
    from graphplan.graphic.gears import construct_mesh
    _, sol = _solved(text, name)
    mesh = construct_mesh(sol.pair, 0.5, "en", module_mm=md)
    ok, why = _alpha_w_ok(mesh, sol.pair.alpha_w)
    assert ok, why
    B2 = mesh.points["B2"]
    box = next(q.bounds() for q in mesh.record.items if q.kind == "text" and q.text == "B_2")
    near = complex(min(max(B2.real, box[0]), box[2]), min(max(B2.imag, box[1]), box[3]))
    assert abs(near - B2) <= 7.0, abs(near - B2)


def test_the_lambda_diagrams_fill_the_row_and_read_the_closed_forms(sheet50):
    """Stop 50's first look: the λ diagrams at 2,5:1 (N1N2 150 mm) left a 245 × 108-mm blank under them
    and 89 mm of the row unused. Now N1N2 is drawn at a GOST 2.302 scale no larger than the meshing's,
    the λ diagrams and the planetary pictures together take at least 90 % of the drawings' zone width
    (the field less the tables' column), and the heavy working part's ends read λ1(B1), λ2(B2) of the
    closed form within 0,5 mm of the ordinate."""
    from graphplan.sheets.compose import field_of
    from graphplan.sheets.form import form
    sol, mesh, _, s = sheet50
    c = pair_closed(15, 45, 0.005, 0.5, 0.2)
    lam = mesh.lam
    mu_x, unit = lam.scales["mu_l"], 1.0 / lam.scales["mu_lambda"]
    assert round(0.001 / mu_x, 6) in (1.0, 2.0, 2.5, 4.0, 5.0, 10.0) and mu_x >= mesh.mu_l - 1e-12
    box = {p.name: p.record.bounds() for p in s.placed}
    x0, _, x1, _ = field_of(form("A1"))
    zone = min(box[t][0] for t in ("geometry", "quality", "train")) - x0
    used = (box["sliding"][2] - box["sliding"][0]) + (box["planetary"][2] - box["planetary"][0])
    assert used >= 0.9 * zone, (used, zone)
    heavy = {q.step: q for q in lam.items if q.step in ("λ_1 on B1B2", "λ_2 on B1B2")}
    l1_at_B1 = heavy["λ_1 on B1B2"].points[0][1] / unit
    l2_at_B2 = heavy["λ_2 on B1B2"].points[-1][1] / unit
    assert abs(l1_at_B1 - c["lam1_B1"]) * unit <= 0.5 and abs(l2_at_B2 - c["lam2_B2"]) * unit <= 0.5
    xs = [q.points[0][0] for q in lam.items if q.step == "λ_1 on B1B2"]
    assert xs[0] == pytest.approx(c["rho_B1"] / mu_x, abs=0.05)


def test_table_3_shows_the_trains_conditions_with_their_numbers(sheet50):
    """Stop 50: Table 3 printed the train's conditions as «викон.» alone where Table 2 shows the pair's
    with their numbers. Now each row shows its check: coaxiality z1 + z2 = z3 − z2', assembly
    (z1·z2' + z2·z3)/(K·gcd(z2, z2')) whole, neighbourhood (z1 + z2)·sin(π/K) > max(z2, z2') + 2 — the
    numbers computed here from the chosen teeth."""
    from test_sheet_content import texts
    sol, _, _, s = sheet50
    z1, z2, z2b, z3 = sol.train.z
    K = 3
    words = texts(s)
    num, den = z1 * z2b + z2 * z3, K * math.gcd(z2, z2b)
    near = (z1 + z2) * math.sin(math.pi / K)
    assert f"{z1} + {z2} = {z3} − {z2b}: викон." in words
    g = math.gcd(z2, z2b)                 # (stop 52: the products and K·gcd written out)
    asm = f"({z1}·{z2b} + {z2}·{z3})/" + (f"({K}·{g})" if g > 1 else f"{K}")
    assert f"{asm} = {num // den}: викон." in words and num % den == 0
    # (stop 51: the neighbourhood's formula written out, (z1 + z2)·sin(180°/K) = … > …)
    assert f"({z1} + {z2})·sin 60° = " + f"{near:.2f}".replace(".", ",") + f" > {max(z2, z2b) + 2}: викон." in words
