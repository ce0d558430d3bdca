"""Stop 59's gear sheet: the lead's GEARS59 — a pair 15/32 with GIVEN shifts x1 = 0,35, x2 = −0,2 (a negative
shift on the wheel), m = 5 mm, and a type-A train with given teeth 18/27/72, K = 3, 960 rpm — against the
textbook's closed forms written here with numpy (inv αw = 2(x1 + x2)·tg α/(z1 + z2) + inv α solved by
bisection, the radii, the tip thicknesses, εα from the active line, λ at B1, B2; Willis' formula and the
four conditions by hand), and the A1 meshing and planetary pictures read off their records: each circle
at its radius, the line of action tangent to both base circles through P at αw, the velocity picture's
reading of u1H within its bound."""
from __future__ import annotations

import math
import tomllib

import numpy as np
import pytest

from review_scenes import GEARS59

Z1, Z2, M, X1, X2 = 15, 32, 5.0, 0.35, -0.2
ALPHA = math.radians(20.0)


def _inv(a):
    return np.tan(a) - a


def _closed() -> dict:
    """The pair in mm and radians by the closed forms (h*a = 1, c* = 0,25)."""
    target = 2 * (X1 + X2) * math.tan(ALPHA) / (Z1 + Z2) + _inv(ALPHA)
    lo, hi = 0.01, 1.2
    for _ in range(200):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if _inv(mid) < target else (lo, mid)
    aw_ = (lo + hi) / 2
    a = M * (Z1 + Z2) / 2
    aw = a * math.cos(ALPHA) / math.cos(aw_)
    r = np.array([M * Z1 / 2, M * Z2 / 2])
    rb = r * math.cos(ALPHA)
    rw = rb / math.cos(aw_)
    rf = r - M * (1.25 - np.array([X1, X2]))
    ra = aw - rf[::-1] - 0.25 * M
    s = M * (math.pi / 2 + 2 * np.array([X1, X2]) * math.tan(ALPHA))
    aa = np.arccos(rb / ra)
    sa = ra * (s / r - 2 * (_inv(aa) - _inv(ALPHA)))
    line = aw * math.sin(aw_)                                   # N1N2
    g = np.sqrt(ra ** 2 - rb ** 2)
    eps = (g.sum() - line) / (math.pi * M * math.cos(ALPHA))
    b1, b2 = line - g[1], g[0]                                  # B1, B2 from N1 along N1N2
    u = Z2 / Z1
    lam1 = 1 - (line - b1) / (b1 * u)
    lam2 = 1 - b2 * u / (line - b2)
    return dict(alpha_w=aw_, aw=aw, r=r, rb=rb, rw=rw, rf=rf, ra=ra, s=s, sa=sa, eps=eps, lam=(lam1, lam2), line=line)


@pytest.fixture(scope="module")
def s59():
    from graphplan.exact.gears import solve
    from graphplan.model.gears import build
    return solve(build(tomllib.loads(GEARS59), "<gears59>"))


def test_gears59_pair_by_the_closed_forms(s59):
    """αw = 20,9543°, aw = 118,233 mm (a = 117,5; y = 0,1466, Δy = 0,0034), ra 44,233/83,983, rf 33/72,75,
    sa 2,384/3,944 mm (0,477m/0,789m: no pointed tip), εα = 1,4833, λ1(B1) = −2,625, λ2(B2) = −2,669; the
    wheel's negative shift not undercut (x_min2 = 1 − 32·sin²20°/2 = −0,872 < −0,2)."""
    p = s59.pair
    ref = _closed()
    assert math.degrees(p.alpha_w) == pytest.approx(math.degrees(ref["alpha_w"]), abs=1e-7)
    assert math.degrees(ref["alpha_w"]) == pytest.approx(20.95428, abs=1e-5)
    assert p.aw * 1000 == pytest.approx(ref["aw"], abs=1e-7) and ref["aw"] == pytest.approx(118.23310, abs=1e-5)
    assert [x * 1000 for x in p.ra] == pytest.approx(list(ref["ra"]), abs=1e-7)
    assert [x * 1000 for x in p.sa] == pytest.approx(list(ref["sa"]), abs=1e-7)
    assert list(ref["sa"] / M) == pytest.approx([0.47681, 0.78874], abs=1e-5)
    assert p.eps == pytest.approx(ref["eps"], abs=1e-9) and ref["eps"] == pytest.approx(1.483272, abs=1e-6)
    l1, _ = p.sliding(p.rho_B1)
    _, l2 = p.sliding(p.rho_B2)
    assert (float(l1), float(l2)) == pytest.approx(ref["lam"], abs=1e-9)
    assert ref["lam"] == pytest.approx((-2.62463, -2.66873), abs=1e-5)
    assert 1 - Z2 * math.sin(ALPHA) ** 2 / 2 < X2


def test_gears59_train_by_willis_and_the_conditions_by_hand(s59):
    """18/27/72, K = 3: u1H = 1 + z3/z1 = 5; ω1 = 960π/30 = 100,53, ωH = 20,106, ω2 = ωH − (ω1 − ωH)·z1/z2 =
    −33,51 rad/s; coaxial 18 + 2·27 = 72, assembly (18 + 72)/3 = 30, neighbourhood 45·sin 60° = 38,97 > 29;
    the ring's 72 teeth under the lab's 85 flagged."""
    from graphplan.exact.gears import conditions
    t = s59.train
    assert tuple(t.z) == (18, 27, 72)
    w1 = 960 * math.pi / 30
    assert t.ratio == pytest.approx(5.0, rel=1e-12)
    assert t.omega["H"] == pytest.approx(w1 / 5, rel=1e-12)
    assert t.omega["2"] == pytest.approx(w1 / 5 - (w1 - w1 / 5) * 18 / 27, rel=1e-12)
    assert t.omega["2"] == pytest.approx(-33.5103, abs=1e-4)
    assert 18 + 2 * 27 == 72 and (18 + 72) % 3 == 0 and 45 * math.sin(math.pi / 3) > 27 + 2
    assert conditions("A", (18, 27, 72), 3) == {"coaxial": True, "assembly": True, "neighbourhood": True,
                                                 "no_undercut": False}


@pytest.fixture(scope="module")
def a1(s59):
    from graphplan.sheets.form import form
    from graphplan.sheets.gears import construct_on
    return construct_on(s59, form("A1"), 0.5, "uk")


def test_gears59_a1_meshing_draws_its_circles_and_the_line_of_action(a1):
    """Read off the A1 meshing's record (5:1): every circle (r, rb, rw, ra, rf of each wheel) at its closed-
    form radius laid off to the ruler's 0,5 mm (rb1 = 35,238 mm at 5:1 drawn 176 mm), the wheels' centres aw apart; the line of action tangent to both base circles, through
    the pitch point P (rw1 from O1 on O1O2), at αw to the tangent at P."""
    mesh, vel, plan = a1
    ref = _closed()
    mu = mesh.mu_l * 1000                                            # mm of the wheel a drawn mm
    arcs = {p.step: p for p in mesh.record.items if p.kind == "arc" and p.step.startswith("circle ")}
    centre, drawn = {}, {}
    for name in ("r", "rb", "rw", "ra", "rf"):
        for k in (0, 1):
            arc = arcs[f"circle {name}{k + 1}"]          # laid off with the ruler: to its 0,5 mm drawn
            assert arc.radius == pytest.approx(round(2 * ref[name][k] / mu) / 2, abs=1e-9), (name, k)
            drawn[name, k] = arc.radius
            centre.setdefault(k, complex(*arc.points[0]))
            assert complex(*arc.points[0]) == pytest.approx(centre[k])
    o1, o2 = centre[0], centre[1]
    assert abs(o2 - o1) == pytest.approx(round(2 * ref["aw"] / mu) / 2, abs=1e-9)
    a, b = (complex(*q) for q in next(p for p in mesh.record.items if p.step == "line of action N1N2").points)
    d = (b - a) / abs(b - a)

    def dist(z):
        return abs(((z - a) * d.conjugate()).imag)
    assert dist(o1) == pytest.approx(drawn["rb", 0], abs=1e-6)
    assert dist(o2) == pytest.approx(drawn["rb", 1], abs=1e-6)
    P = o1 + (o2 - o1) / abs(o2 - o1) * drawn["rw", 0]
    assert dist(P) == pytest.approx(0.0, abs=0.3)          # (the drawn radii each within the ruler's 0,25 mm)
    t1, t2 = (complex(*q) for q in next(p for p in mesh.record.items if p.step == "tangent at P").points)
    tang = (t2 - t1) / abs(t2 - t1)
    turn = math.degrees(math.acos(min(1.0, abs((d * tang.conjugate()).real))))
    assert turn == pytest.approx(math.degrees(ref["alpha_w"]), abs=0.05)


def test_gears59_a1_velocity_picture_reads_the_ratio_within_its_bound(a1):
    """The A1 planetary pictures (the half-section at 1:1, h ≥ 40 mm): the segments of the plan of angular
    velocities are ω/μω (1 at 100,53/μω …), u1H read 1 + … within the bound the notes state, under the lab's
    5 %, ω1 read within 1 % of 960π/30."""
    mesh, vel, plan = a1
    w1 = 960 * math.pi / 30
    assert vel.h >= 40.0
    assert abs(vel.ratio - 5.0) <= vel.ratio_bound + 1e-9 and 100 * vel.ratio_bound / 5.0 < 5.0
    assert vel.omega["1"] == pytest.approx(w1, rel=0.01)
    assert vel.omega["H"] == pytest.approx(w1 / 5, rel=0.02)
    assert vel.omega["2"] == pytest.approx(w1 / 5 - (w1 - w1 / 5) * 18 / 27, rel=0.02)
    assert vel.omega["3"] == 0.0
