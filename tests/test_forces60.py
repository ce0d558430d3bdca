"""Stop 60 (frc60): LINK60, a plunger B on a vertical offset guide whose slider drives a rocker O2C through
the rod BC — its balancing moment against virtual power computed here with numpy alone.

The truth is independent of graphplan: the positions solved by hand (B on the guide x = 0.03 m from the
crank pin, C where the circles round B and O2 cross, the branch of the scene's C), velocities and
accelerations by central differences in the crank angle, the loads G = m·g, Φ = −m·a_S, M^Φ = −I_S·ε
(m = 22 kg/m × length, the slider 8 kg, I_S = 0.1·m·l²) and the 60 N·m moment against the rocker's
turn on the working stroke; M_b = −(ΣF·v + ΣM·ω)/ω1. Position 0 (the working stroke's start) is an
extreme of the rocker found here by bisection on dθ5/dφ."""
from __future__ import annotations

import math

import numpy as np
import pytest

from conftest import scene_force_plans, scene_study

R, L2, L4, L5, XG = 0.065, 0.24, 0.20, 0.13, 0.03
O2 = np.array([0.22, 0.30])
W1 = 150 * 2 * math.pi / 60            # counter-clockwise
MASS = {2: 22 * L2, 3: 8.0, 4: 22 * L4, 5: 22 * L5}
INERTIA = {2: 0.1 * MASS[2] * L2 ** 2, 4: 0.1 * MASS[4] * L4 ** 2, 5: 0.1 * MASS[5] * L5 ** 2}


def _points(phi: float) -> dict[str, np.ndarray]:
    """A, B, C, the centres of mass and the links' angles at crank angle φ (rad from +x)."""
    a = R * np.array([math.cos(phi), math.sin(phi)])
    b = np.array([XG, a[1] + math.sqrt(L2 ** 2 - (XG - a[0]) ** 2)])      # the plunger above the crank
    d = O2 - b
    dist = float(np.hypot(*d))
    along = (L4 ** 2 - L5 ** 2 + dist ** 2) / (2 * dist)
    c = b + along * d / dist + math.sqrt(L4 ** 2 - along ** 2) * np.array([-d[1], d[0]]) / dist   # the scene's C (up-left of BO2)
    ang = lambda p, q: math.atan2(q[1] - p[1], q[0] - p[0])               # noqa: E731
    return {"A": a, "B": b, "C": c, "S2": a + 0.35 * (b - a), "S3": b, "S4": b + 0.5 * (c - b),
            "S5": O2 + 0.5 * (c - O2), "t2": np.array(ang(a, b)), "t4": np.array(ang(b, c)), "t5": np.array(ang(O2, c))}


def _motion(phi: float, h: float = 1e-4):
    """Positions, velocities and accelerations (points, and the links' ω, ε) at φ."""
    p0, pp, pm = _points(phi), _points(phi + h), _points(phi - h)
    wrap = lambda x: (x + math.pi) % (2 * math.pi) - math.pi              # noqa: E731
    v, acc = {}, {}
    for k in p0:
        if k.startswith("t"):
            v[k] = wrap(float(pp[k] - pm[k])) / (2 * h) * W1
            acc[k] = (wrap(float(pp[k] - p0[k])) - wrap(float(p0[k] - pm[k]))) / h ** 2 * W1 ** 2
        else:
            v[k] = (pp[k] - pm[k]) / (2 * h) * W1
            acc[k] = (pp[k] - 2 * p0[k] + pm[k]) / h ** 2 * W1 ** 2
    return p0, v, acc


def _rocker_rate(phi: float, h: float = 1e-5) -> float:
    """dθ5/dφ by a central difference."""
    return math.remainder(float(_points(phi + h)["t5"] - _points(phi - h)["t5"]), 2 * math.pi) / (2 * h)


def _extremes() -> list[float]:
    """The crank angles (deg) where the rocker stands still: dθ5/dφ changes sign, bisected."""
    step = 5.0
    grid = np.radians(np.arange(0.0, 360.0, step))
    rates = [_rocker_rate(float(x)) for x in grid]
    out = []
    for i in range(len(grid)):
        lo, hi = float(grid[i]), float(grid[i]) + math.radians(step)
        if rates[i] * rates[(i + 1) % len(grid)] < 0:
            for _ in range(45):
                mid = 0.5 * (lo + hi)
                lo, hi = (mid, hi) if _rocker_rate(lo) * _rocker_rate(mid) > 0 else (lo, mid)
            out.append(math.degrees(0.5 * (lo + hi)) % 360.0)
    return out


def _balancing(phi_deg: float) -> float:
    """M_b (N·m, + counter-clockwise) by virtual power at φ on the working stroke."""
    p, v, acc = _motion(math.radians(phi_deg))
    power = 0.0
    for i in (2, 3, 4, 5):
        s = f"S{i}"
        force = np.array([0.0, -MASS[i] * 9.81]) - MASS[i] * acc[s]
        power += float(force @ v[s])
    for i in (2, 4, 5):
        power += -INERTIA[i] * acc[f"t{i}"] * v[f"t{i}"]
    power += -60.0 * abs(v["t5"])                         # the resistance against the rocker's turn
    return -power / W1


@pytest.fixture(scope="module")
def link60():
    from review_scenes import LINK60
    return LINK60


def test_link60s_force_position_is_60_degrees_from_the_working_strokes_start(link60):
    from graphplan.exact import kinetostatics
    st = scene_study(link60)
    ext = _extremes()
    assert len(ext) == 2
    assert min(abs((st.phi0 - e + 180) % 360 - 180) for e in ext) < 1e-6, (st.phi0, ext)
    assert kinetostatics.at_scene_angle(st) == pytest.approx((st.phi0 + 60.0) % 360.0)


def test_link60s_balancing_moment_is_the_virtual_powers(link60):
    """The closed form's M_b at the force position against virtual power (34.756 N·m)."""
    from graphplan.exact import kinetostatics
    st = scene_study(link60)
    phi = kinetostatics.at_scene_angle(st)
    ks = kinetostatics.analyse(st, np.array([phi]))
    truth = _balancing(phi)
    assert truth == pytest.approx(34.756, abs=0.01)
    assert float(ks.balancing[0]) == pytest.approx(truth, rel=1e-6)


def test_link60s_plans_and_lever_read_m_b_within_their_rulers(link60):
    """The force plans (A1 uk scales: μl 0.0025, the crank 1:1; μF 5, 10, 10 N/mm) and the lever (μv
    0.0075) read M_b within 1 % of virtual power (the sheet's Table 6: 34.73 and 34.76 N·m)."""
    fp = scene_force_plans(link60, mu_l=0.0025, group_mu={"I(0-1)": 0.001},
                           group_mu_F={"II(4-5)": 5.0, "II(2-3)": 10.0, "I(0-1)": 10.0}, mu_a=0.1)
    truth = _balancing(fp.phi_deg)
    assert fp.balancing == pytest.approx(truth, rel=0.01)
    assert fp.lever.balancing == pytest.approx(truth, rel=0.01)


# -- frc60 #3: a sliver's short sides at both its ends, each in a detail of its own ------------------

def test_short_sides_apart_along_a_longer_one_are_split_into_their_own_knots():
    """LINK59's II(4-5) at 20 N/mm, written out: G4 0.5 mm, G5 9 mm, Φ5 1 mm, P_C 75 mm, R05 1.5 mm. One
    window round G4 and Φ5 (4 × 12.5 mm) enlarged until G4 reads 3 mm would be 75 mm across, over the
    30 mm a detail may take: G4 and Φ5 each get their own knot, R05 its own — three details, in the
    polygon's order; each enlarged so that its shortest side reads at least 3 mm within 30 mm."""
    from graphplan.drawing.forces import DETAIL_MOST_MM, TINY_MM, plan_details
    from graphplan.graphic.forceplans import Side
    sides = [Side("G4", 0j, -0.5j, "known"), Side("G5", -0.5j, -9.5j, "known"), Side("Φ5", -9.5j, 1 - 9.5j, "known"),
             Side("P_C", 1 - 9.5j, -74 - 9.5j, "known"), Side("R05", -74 - 9.5j, -74 - 11j, "reaction"),
             Side("R34", -74 - 11j, 0j, "reaction")]
    details = plan_details(sides, 20.0)
    inside = [[s.name for s in sides if s.mm < TINY_MM and all(d.box[0] <= z.real <= d.box[2] and d.box[1] <= z.imag <= d.box[3]
                                                               for z in (s.start, s.end))] for d in details]
    assert inside == [["G4"], ["Φ5"], ["R05"]]
    for d, names in zip(details, inside):
        side = next(s for s in sides if s.name == names[0])
        mu = d.choices[0]
        assert side.mm * 20.0 / mu >= 3.0 - 1e-9                        # legible in its detail
        assert max(d.box[2] - d.box[0], d.box[3] - d.box[1]) * 20.0 / mu <= DETAIL_MOST_MM + 1e-9


def test_sides_meeting_end_to_end_stay_one_knot():
    """Four short loads meeting end to end at a sliver's foot (test_forces_rocker46's) stay one knot,
    whatever their window: only sides apart are split."""
    from graphplan.drawing.forces import _knots
    from graphplan.graphic.forceplans import Side
    foot = [Side("R12τ", 0j, 0.5j, "component"), Side("G2", 0.5j, 0.5j - 4j, "known"),
            Side("Φ2", -3.5j, -3.5j + 4.5, "known"), Side("Φ3", 4.5 - 3.5j, 7.0 - 3.5j, "known")]
    assert [[s.name for s in k] for k in _knots(foot)] == [["R12τ", "G2", "Φ2", "Φ3"]]


@pytest.mark.slow
def test_link59s_sliver_draws_every_short_force_legibly_in_a_detail():
    """LINK59's II(4-5) force plan at its A1 scales (μl 0.0005, μF 20 N/mm): G4, Φ5 and R05 under 2 mm
    were only named under a 100 × 20 mm sliver. Each is drawn now in a detail (I, II, III) at least
    3 mm long, its drawn length × the detail's μF_I its plan's reading — within the plan's ruler's half
    division (0.25 mm × μF) of the force itself: the loads G = m·g, Φ5 = m5·a_S5 from the closed form,
    R05 the closed form's reaction plus what the plan carries in."""
    from review_scenes import LINK59
    from graphplan.drawing.forces import TINY_MM, polygon_record
    from graphplan.util.words import force_symbol
    mu_F = 20.0
    fp = scene_force_plans(LINK59, mu_l=0.0025, group_mu={"II(4-5)": 0.0005, "I(0-1)": 0.001},
                           group_mu_F={"II(4-5)": mu_F, "II(2-3)": 20.0, "I(0-1)": 20.0}, mu_a=0.05)
    gp = next(g for g in fp.groups if g.label == "II(4-5)")
    rec = polygon_record(fp, gp, "uk")
    tiny = [s for s in gp.sides if 1e-9 < s.mm < TINY_MM]
    assert {s.name for s in tiny} == {"G4", "Φ5", "R05"}
    marks = [q.text for q in rec.items if q.kind == "text" and q.step.endswith("detail mark")]
    assert marks == ["I", "II", "III"]
    exact = {"G4": abs(complex(next(ld for ld in fp.ks.loads if ld.name == "G4").force[0])),
             "Φ5": abs(complex(next(ld for ld in fp.ks.loads if ld.name == "Φ5").force[0])),
             "R05": abs(complex(fp.ks.reactions["R05"].force[0]))}
    for s in tiny:
        drawn = [(q, rec.scales["mu_F detail" + ("" if q.step.endswith(": detail") else " " + q.step.rsplit(" ", 1)[1])])
                 for q in rec.items if q.text == s.name and q.layer == "vectors" and ": detail" in q.step]
        assert drawn, s.name
        q, mu_I = drawn[0]
        (x0, y0), (x1, y1) = q.points[0], q.points[1]
        length = math.hypot(x1 - x0, y1 - y0)
        assert length >= 3.0 - 1e-9, (s.name, length)
        assert length * mu_I == pytest.approx(s.mm * mu_F, rel=1e-6)       # the plan's reading, enlarged
        carried = abs(gp.reactions[s.name].value - gp.reactions[s.name].analytic) if s.name in gp.reactions else 0.0
        assert abs(length * mu_I - exact[s.name]) <= 0.25 * mu_F + carried + 1e-6, (s.name, length * mu_I, exact[s.name])
    # the caption still names them as under 2 mm on the plan
    assert any(force_symbol("R05", "uk") in q.text for q in rec.items if q.kind == "text" and q.text.startswith("μ_F"))


# -- the slider-attached group: the pin B the plunger's (FRC60_PLUNGER: LINK60 with the plunger listed first) -----

def _cross(r: np.ndarray, f: np.ndarray) -> float:
    return float(r[0] * f[1] - r[1] * f[0])


def _reactions(phi_deg: float, pin_on_plunger: bool) -> dict[str, np.ndarray]:
    """Every pair's reaction by the links' own equilibrium (numpy's linear solve, no graphplan): the
    rod BC and rocker O2C (R34 or R24 at B, R45 at C, R05 at O2), then the rod AB and the plunger (R12 at
    A, R23 the rod AB's on the plunger at B — or the plunger's on the rod, the pin being the rod's —,
    R03 normal to the vertical guide), the crank's R01; Rij is link i's force on link j."""
    p, v, acc = _motion(math.radians(phi_deg))
    g = np.array([0.0, -9.81])
    load = {i: MASS[i] * g - MASS[i] * acc[f"S{i}"] for i in (2, 3, 4, 5)}
    couple = {i: -INERTIA[i] * acc[f"t{i}"] for i in (2, 4, 5)}
    couple[5] += -60.0 * math.copysign(1.0, v["t5"])
    b, c, a = p["B"], p["C"], p["A"]
    # unknowns x = [Rb (on 4 at B), R54... ] — link 4: Rb + R54 + load4 = 0, moments about S4; link 5: R05 + R45 + load5
    # with R45 = −R54: unknowns Rb(2), R54(2), R05(2)
    m = np.zeros((6, 6))
    rhs = np.zeros(6)
    m[0:2, 0:2] = np.eye(2); m[0:2, 2:4] = np.eye(2); rhs[0:2] = -load[4]
    s4 = p["S4"]
    m[2, 0:2] = [-(b - s4)[1], (b - s4)[0]]; m[2, 2:4] = [-(c - s4)[1], (c - s4)[0]]; rhs[2] = -couple[4]
    m[3:5, 4:6] = np.eye(2); m[3:5, 2:4] = -np.eye(2); rhs[3:5] = -load[5]
    s5 = p["S5"]
    m[5, 4:6] = [-(O2 - s5)[1], (O2 - s5)[0]]; m[5, 2:4] = [(c - s5)[1], -(c - s5)[0]]; rhs[5] = -couple[5]
    x = np.linalg.solve(m, rhs)
    rb, r54, r05 = x[0:2], x[2:4], x[4:6]
    # link 2 (AB) and the plunger 3: unknowns R12(2), R32 (the plunger's on the rod, 2), R03x
    on2 = np.zeros(2) if pin_on_plunger else -rb             # the rod BC's force on the rod AB at B
    on3 = -rb if pin_on_plunger else np.zeros(2)             # … or on the plunger
    m = np.zeros((5, 5))
    rhs = np.zeros(5)
    s2 = p["S2"]
    m[0:2, 0:2] = np.eye(2); m[0:2, 2:4] = np.eye(2); rhs[0:2] = -load[2] - on2
    m[2, 0:2] = [-(a - s2)[1], (a - s2)[0]]; m[2, 2:4] = [-(b - s2)[1], (b - s2)[0]]
    rhs[2] = -couple[2] - _cross(b - s2, on2)
    m[3:5, 2:4] = -np.eye(2); m[3, 4] = 1.0; rhs[3:5] = -load[3] - on3
    y = np.linalg.solve(m, rhs)
    g1 = np.array([0.0, -9.81 * 22 * R])                     # the crank's weight at O (S1 = O: no inertia)
    return {"R01": y[0:2] - g1, "R12": y[0:2], "R23": -y[2:4], "R03": np.array([y[4], 0.0]), "R05": r05, "R45": -r54,
            ("R34" if pin_on_plunger else "R24"): rb}


@pytest.mark.parametrize("scene, pin_on_plunger", [("LINK60", False), ("FRC60_PLUNGER", True)])
def test_link60s_reactions_with_the_pin_on_the_rod_or_the_plunger(scene, pin_on_plunger):
    """The closed form's reactions against the links' own equilibrium solved here: the same R at B on the
    rod BC either way (564.7 N), R12, R03, R05, R45 alike; only the rod AB's force on the plunger differs
    — 321.7 N where the pin is the rod's (LINK60: R24, R42), 671.3 N where it is the plunger's
    (FRC60_PLUNGER: R34, R43) — and M_b is the same."""
    import review_scenes
    from graphplan.exact import kinetostatics
    st = scene_study(getattr(review_scenes, scene))
    phi = kinetostatics.at_scene_angle(st)
    ks = kinetostatics.analyse(st, np.array([phi]))
    truth = _reactions(phi, pin_on_plunger)
    got = {k: complex(r.force[0]) for k, r in ks.reactions.items()}
    assert set(got) == set(truth)
    for k, f in truth.items():
        assert abs(got[k] - complex(*f)) <= 1e-4 * max(1.0, abs(complex(*f))), (k, got[k], f)
    assert abs(complex(*truth["R23"])) == pytest.approx(671.31 if pin_on_plunger else 321.74, abs=0.01)
    assert float(ks.balancing[0]) == pytest.approx(_balancing(phi), rel=1e-6)
