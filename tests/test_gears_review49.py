"""Stop 49's gear-sheet review (helper gear49): the lead's pair 9/40 "auto" + type A u = 5.2, K = 4,
n1 = 1450 rpm (GEARS49) — checked against the closed forms and the drawn sheet's boxes, not the code's
own numbers."""
from __future__ import annotations

import math
import tomllib

import pytest

from review_scenes import GEARS49


@pytest.fixture(scope="module")
def sheet49():
    """GEARS49's A1 sheet in English as build_gears_sheet composes it (about 4 s): (solution,
    velocities, sheet)."""
    from graphplan.exact.gears import solve
    from graphplan.model.gears import build
    from graphplan.sheets.compose import compose
    from graphplan.sheets.form import form
    from graphplan.sheets.gears import _fields, on_sheet
    g = build(tomllib.loads(GEARS49), "GEARS49")
    sol = solve(g)
    mesh, vel, pages = on_sheet(g, sol, form("A1"), 0.5, "en")
    return sol, vel, compose(form("A1"), pages, _fields(g, "en", mesh.mu_l), "en", g.title_in("en"))


def test_the_drawings_fill_the_field_with_no_empty_band_over_or_under_them(sheet49):
    """The planetary pictures were capped by the meshing's size: 270 × 190 mm in a 616 × 372-mm row, a
    61-mm band empty over the meshing and under the pictures. Now the row under the meshing holds them
    as large as it takes: no band over 35 mm over the meshing or under the pictures, the pictures under
    the meshing and left of the tables' column."""
    from graphplan.sheets.compose import field_of
    from graphplan.sheets.form import form
    _, _, s = sheet49
    x0, y0, x1, y1 = field_of(form("A1"))
    box = {p.name: p.record.bounds() for p in s.placed}
    m, p = box["meshing"], box["planetary"]
    assert y1 - m[3] <= 35.0 and p[1] - y0 <= 35.0, (m, p)
    assert p[3] <= m[1] and p[2] <= min(box[t][0] for t in ("geometry", "quality", "train"))


def test_u1h_is_read_within_its_bound_of_willis_and_omega1_is_the_given_speed(sheet49):
    """Willis for type A: u1H = 1 + z3/z1 (z3 = z1 + 2·z2, coaxial), here from the chosen teeth; the plan
    reads it within the stated bound, the bound under 3 % of u1H on the grown pictures. Table 3's ω1
    row is the given speed, πn/30 = 151,8 rad/s, and says so (its reading off the plan a check, as the
    notes say), where it read «ω_1, rad/s: 151,8 | 150» as though the given speed were a result."""
    from test_sheet_content import texts
    sol, vel, s = sheet49
    z1, z2, z3 = sol.train.z
    assert z3 == z1 + 2 * z2 and (z1 + z3) % 4 == 0
    u = 1 + z3 / z1
    assert abs(u - 5.2) / 5.2 <= 0.04
    assert abs(vel.ratio - u) <= vel.ratio_bound <= 0.03 * u
    words = texts(s)
    assert "ω_1 (given), rad/s" in words
    assert f"{math.pi * 1450 / 30:.1f}" in words
    assert any(t.startswith("ω_1 is given") for t in words)


def _rw1(z1: int, z2: int, x1: float, x2: float, m: float) -> float:
    """The pinion's rolling radius, m: inv αw = 2(x1 + x2)·tg α/(z1 + z2) + inv α (Newton), rw = r·cos α/cos αw."""
    a = math.radians(20.0)
    inv = 2 * (x1 + x2) * math.tan(a) / (z1 + z2) + math.tan(a) - a
    w = a
    for _ in range(50):
        w -= (math.tan(w) - w - inv) / math.tan(w) ** 2
    return m * z1 / 2 * math.cos(a) / math.cos(w)


@pytest.mark.parametrize("name, md, teeth", [("GEARS49", 20.0, 3), ("GEARS48", 25.0, 5)])   # (their A1 sheets')
def test_the_pinions_centre_in_reach_is_drawn_not_broken_off(name, md, teeth):
    """The broken meshing (the wheel's centre O2 far off the drawing) broke the centre line under the
    window too, with «↓ O_1», though O1 stood 9,5 mm under that break (stop 49's 9/40) or on it (stop 48's
    12/31). O1 is now drawn: a point rw1/μl under P (rw1 from inv αw, written here), lettered within
    6 mm, the radius O1N1 drawn to it, and no break mark under P — the one over P stays (O2 off)."""
    import review_scenes
    from graphplan.exact.gears import solve
    from graphplan.graphic.gears import construct_mesh
    from graphplan.model.gears import build
    sol = solve(build(tomllib.loads(getattr(review_scenes, name)), name)).pair
    mesh = construct_mesh(sol, 0.5, "en", module_mm=md, teeth=teeth)
    rec, mu = mesh.record, mesh.mu_l
    pts = [q.points[0] for q in rec.items if q.kind == "point" and q.role == "pole"]
    P = mesh.points["P"]
    z1, z2 = sol.pair.z
    rw1 = _rw1(z1, z2, *sol.x, sol.pair.module) / mu
    o1 = [p for p in pts if abs(p[0]) < 1e-9 and abs(P.imag - p[1] - rw1) <= 0.5]
    assert o1, (rw1, P, pts)
    (x, y), = o1[:1]
    letter = next(q for q in rec.items if q.kind == "text" and q.text == "O_1").bounds()
    assert math.hypot(max(letter[0] - x, x - letter[2], 0), max(letter[1] - y, y - letter[3], 0)) <= 6.0
    breaks = [q.points[0][1] for q in rec.items if q.step == "break"]
    assert breaks and all(b > P.imag for b in breaks)
    N1 = mesh.points["N1"]
    assert any(q.kind == "segment" and {tuple(map(lambda v: round(v, 6), e)) for e in q.points}
               == {(round(N1.real, 6), round(N1.imag, 6)), (round(x, 6), round(y, 6))} for q in rec.items)


def test_a_height_corrected_pair_reads_its_contact_ratio_within_the_bound_of_the_closed_form():
    """Stop 49's own scene (GEARS_OWN49): 13/52 with x1 = −x2 = 0,3, m = 2,5 mm — a height correction,
    so αw = α, aw = a = m(z1 + z2)/2, rw = r. Drawn at 10:1 (the whole depth 56,25 mm), rw1 and rw2 are
    read as r1, r2 within the ruler's half millimetre, O1 is drawn (not broken off), and εα read off the
    drawing is within its stated bound of the closed form [√(ra1² − rb1²) + √(ra2² − rb2²) − aw·sin α]/pb,
    ra = m(z/2 + 1 + x), written here."""
    from graphplan.exact.gears import solve
    from graphplan.graphic.gears import construct_mesh
    from graphplan.model.gears import build
    import review_scenes
    sol = solve(build(tomllib.loads(review_scenes.GEARS_OWN49), "GEARS_OWN49")).pair
    mesh = construct_mesh(sol, 0.5, "en", module_mm=25.0, teeth=5)
    m, z, x, a = 2.5, (13, 52), (0.3, -0.3), math.radians(20.0)
    r = [m * k / 2 for k in z]
    rb = [v * math.cos(a) for v in r]
    ra = [m * (k / 2 + 1 + s) for k, s in zip(z, x)]
    aw = r[0] + r[1]
    eps = (sum(math.sqrt(p * p - q * q) for p, q in zip(ra, rb)) - aw * math.sin(a)) / (math.pi * m * math.cos(a))
    assert abs(mesh.eps - eps) <= mesh.eps_bound
    for k in (0, 1):
        assert abs(mesh.rw[k] * 1000 - r[k]) <= 0.25 * mesh.mu_l * 1000 + 1e-9
    assert not [q for q in mesh.record.items if q.step == "break" and q.points[0][1] < mesh.points["P"].imag]


@pytest.mark.slow
def test_the_pinions_centre_costs_a_set_no_sheet():
    """Drawing O1 made GEARS49's meshing 10 mm taller: its English A3 set took a fourth sheet holding
    Table 3 and a few notes (80 % empty). A set draws O1 only where that costs no sheet: three sheets,
    as with the centre line broken, each holding a drawing or a table (about 20 s)."""
    from graphplan.exact.gears import solve
    from graphplan.model.gears import build
    from graphplan.sheets.form import form
    from graphplan.sheets.gears import on_sheet
    g = build(tomllib.loads(GEARS49), "GEARS49")
    mesh, _, pages = on_sheet(g, solve(g), form("A3"), 0.5, "en")
    assert len(pages) == 3
    assert all(any(p.name in ("meshing", "sliding", "planetary", "geometry", "quality", "train") for p in page)
               for page in pages)
