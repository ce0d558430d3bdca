"""Stop 57, the lead's kneading-machine six-bar (LINK57: an offset crank-slider whose triangular rod ABC
swings a rocker O3D through CD; 70 N·m on the rocker's working swing, 300 N on the slider on both
strokes). The truth: the balancing moment by virtual power from this file's own loop closure (numpy,
finite differences — nothing of graphplan's kinematics), and the resistance diagram's load read off the
scene: the rocker is the output, so its own working moment is the useful resistance drawn over its
swing — not the slider's constant 300 N over the rocker's angle (a hatched rectangle with no stroke)."""
from __future__ import annotations

import math

import numpy as np
import pytest

from conftest import scene_force_plans, scene_study
from review_scenes import LINK57

LAB_LIMIT = 5.0          # % the lab allows M_b by the plans and the lever off the analytic one

# the scene's data, as the toml gives them
R, L, E, O3 = 0.07, 0.28, -0.025, np.array([0.26, 0.24])
CD, O3D, Q, K = 0.17, 0.13, 25.0, 0.1
W1 = 160 * 2 * math.pi / 60


def _rot(v):
    return np.array([-v[1], v[0]])


def _pose(phi: float) -> dict[str, np.ndarray | float]:
    """The six-bar's points at crank angle ``phi`` (rad): B right of A on the guide y = −0.025, the rod's
    C and S2 at (0.14, 0.09) and (0.14, 0.03) in its frame (x along AB, y to its left), D the circles'
    intersection on the left of C→O3 (the scene's assembly)."""
    A = R * np.array([math.cos(phi), math.sin(phi)])
    B = np.array([A[0] + math.sqrt(L ** 2 - (A[1] - E) ** 2), E])
    u = (B - A) / L
    C, S2 = A + 0.14 * u + 0.09 * _rot(u), A + 0.14 * u + 0.03 * _rot(u)
    d = O3 - C
    dd = np.linalg.norm(d)
    a = (CD ** 2 - O3D ** 2 + dd ** 2) / (2 * dd)
    D = C + a * d / dd + math.sqrt(CD ** 2 - a ** 2) * _rot(d / dd)
    ang = lambda v: math.atan2(v[1], v[0])  # noqa: E731
    return {"A": A, "B": B, "S2": S2, "S4": (C + D) / 2, "S5": (O3 + D) / 2,
            "t2": ang(u), "t4": ang(D - C), "t5": ang(D - O3)}


def _derivatives(phi: float, h: float = 1e-4):
    """Velocities and accelerations (per unit ω1, ω1²) by central differences."""
    p1, p, p0 = _pose(phi + h), _pose(phi), _pose(phi - h)
    wrap = lambda x: (x + math.pi) % (2 * math.pi) - math.pi  # noqa: E731
    v, a = {}, {}
    for k in p:
        fwd, back = np.asarray(p1[k]) - np.asarray(p[k]), np.asarray(p[k]) - np.asarray(p0[k])
        if k.startswith("t"):
            fwd, back = wrap(fwd), wrap(back)
        v[k], a[k] = (fwd + back) / (2 * h) * W1, (fwd - back) / h ** 2 * W1 ** 2
    return v, a


def _extreme(phi: float, sign: float) -> float:
    """The crank angle of the rocker's extreme near ``phi`` (a largest angle for sign +1), by a
    golden-section search over ±1°."""
    f = lambda x: -sign * _pose(x)["t5"]  # noqa: E731
    a, b, g = phi - math.radians(1), phi + math.radians(1), (math.sqrt(5) - 1) / 2
    while b - a > 1e-10:
        c, d = b - g * (b - a), a + g * (b - a)
        a, b = (a, d) if f(c) < f(d) else (c, b)
    return 0.5 * (a + b)


def _virtual_power_mb() -> tuple[float, float]:
    """M_b at 130° of crank turn from position 0 (the rocker's extreme that starts its slow swing):
    M_b·ω1 + Σ(G + Φ)·v_S + Σ M^Φ·ω + P_B·v_B + M5·ω5 = 0. Returns (M_b, the crank angle in degrees)."""
    phis = np.linspace(0, 2 * math.pi, 721)[:-1]
    t5 = np.unwrap([_pose(p)["t5"] for p in phis])
    up, down = (_extreme(phis[np.argmax(t5)], 1.0), _extreme(phis[np.argmin(t5)], -1.0))
    # the ccw crank from the rocker's largest angle to its smallest: the longer turn is the slow swing
    start, work = (up, -1.0) if (down - up) % (2 * math.pi) > math.pi else (down, 1.0)
    phi = start + math.radians(130)
    v, a = _derivatives(phi)
    m = {"S2": L * Q, "B": 4.0, "S4": CD * Q, "S5": O3D * Q}           # the crank's S1 at O1: no power
    inertia = {"t2": K * L * Q * L ** 2, "t4": K * CD * Q * CD ** 2, "t5": K * O3D * Q * O3D ** 2}
    power = sum((np.array([0.0, -9.81 * mi]) - mi * a[k]) @ v[k] for k, mi in m.items())
    power += sum(-inertia[k] * a[k] * v[k] for k in inertia)
    power += -300.0 * np.linalg.norm(v["B"])                           # against v_B on both strokes
    if np.sign(v["t5"]) == work:                                       # the rocker's working swing
        power += -70.0 * abs(v["t5"])
    return -power / W1, math.degrees(phi) % 360


@pytest.fixture(scope="module")
def plans():
    # the A1 sheet's scales: the groups at 1:250 (0.004 m/mm), the plans at 10 N/mm
    return scene_force_plans(LINK57, mu_l=0.004, mu_F=10.0)


def test_the_force_position_and_the_exact_balancing_moment_agree_with_virtual_power(plans):
    mb, phi = _virtual_power_mb()
    assert plans.phi_deg % 360 == pytest.approx(phi, abs=0.1)           # 25.81°
    assert plans.analytic == pytest.approx(mb, rel=1e-4)                 # 44.381 N·m


def test_the_plans_and_the_lever_within_the_labs_limit(plans):
    mb, _ = _virtual_power_mb()
    for value in (plans.balancing, plans.lever.balancing):
        assert abs(100 * (value - mb) / mb) < LAB_LIMIT, value


def test_the_resistance_diagram_draws_the_rockers_moment_over_its_swing():
    """The output is the rocker O3D: the diagram is M5 = 70 N·m over ψ5, hatched over the working swing
    only (its span the rocker's swing, found here by the loop closure), the idle swing on the axis —
    not P_B = 300 N, the slider's load on both strokes, over the rocker's angle."""
    from graphplan.drawing.charts import resistance_loads, resistance_record, turn
    t = turn(scene_study(LINK57))
    loads, couple = resistance_loads(t)
    assert couple and [ld.name for ld in loads] == ["M_5"]
    rec = resistance_record(t, lang="uk")
    mu_s, mu_m = rec.scales["mu_s"], rec.scales["mu_P"]
    t5 = np.unwrap([_pose(p)["t5"] for p in np.linspace(0, 2 * math.pi, 7201)[:-1]])
    swing = math.degrees(t5.max() - t5.min())                            # 29.25°
    hatch = [q for q in rec.items if q.role == "hatch"]
    xs = [q.points[0][0] for q in hatch]
    assert hatch and max(xs) <= swing / mu_s + 1e-6 and max(xs) > swing / mu_s - 2.5
    assert all(q.points[1][1] == pytest.approx(70.0 / mu_m) for q in hatch)
    texts = [q.text for q in rec.items if q.kind == "text"]
    assert "M_{5}, Н·м" in texts and not any(s.startswith("P_") for s in texts)
