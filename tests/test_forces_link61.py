"""Stop 61 (frc61): LINK61's force analysis against an independent model (numpy alone).

The bell crank O2BD (a plate: D at [-0.06, -0.11] m in O2B's own frame) drives the slider E on the vertical
guide x = 0.44 m through the rod DE; a 900 N force opposes E over the working (slow) stroke. Here: the
positions by circle intersections, a_S and ε by central differences in φ at ω1 = −4π rad/s (the crank
clockwise), the loads by m = q·l and I_S = 0.1·m·l², the force angle found from the slider's extremes
(position 0 the top, starting the slow stroke down; 75° of clockwise turn from it) — then M_b by virtual
power and the reactions by each group's own statics (linear solves), compared with the closed form.
"""
from __future__ import annotations

import numpy as np
import pytest

from conftest import scene_study

G, Q, KI = 9.81, 20.0, 0.1
O1, O2, XG = np.array([0.0, 0.0]), np.array([0.28, 0.0]), 0.44
R1, L2, L3, L4 = 0.07, 0.26, 0.16, 0.22
D_LOCAL = np.array([-0.06, -0.11])
W1 = -120 * 2 * np.pi / 60


def _circles(p, rp, c, rc):
    d = np.linalg.norm(c - p)
    a = (rp ** 2 - rc ** 2 + d ** 2) / (2 * d)
    e = (c - p) / d
    return p + a * e + np.sqrt(rp ** 2 - a ** 2) * np.array([-e[1], e[0]])      # the branch B = 1


def _pos(phi: float) -> dict:
    a = O1 + R1 * np.array([np.cos(phi), np.sin(phi)])
    b = _circles(a, L2, O2, L3)
    ex = (b - O2) / L3
    d = O2 + D_LOCAL[0] * ex + D_LOCAL[1] * np.array([-ex[1], ex[0]])
    e = np.array([XG, d[1] + np.sqrt(L4 ** 2 - (XG - d[0]) ** 2)])                # E above D
    ang = lambda v: np.arctan2(v[1], v[0])
    return dict(A=a, B=b, D=d, E=e, S1=O1.copy(), S2=(a + b) / 2, S3=O2 + 0.4 * (b - O2), S4=(d + e) / 2, S5=e,
                th2=ang(b - a), th3=ang(b - O2), th4=ang(e - d))


def _cross(a, b) -> float:
    return float(a[0] * b[1] - a[1] * b[0])


def _force_angle() -> float:
    from scipy.optimize import minimize_scalar
    top = minimize_scalar(lambda p: -_pos(p)["E"][1], bracket=(3.6, 3.7, 3.8), tol=1e-12).x
    bottom = minimize_scalar(lambda p: _pos(p)["E"][1], bracket=(0.4, 0.5, 0.6), tol=1e-12).x
    down = (top - bottom) % (2 * np.pi)            # the clockwise turn from the top to the bottom
    assert down > np.pi                            # the slow stroke is the way down: position 0 at the top
    return top - np.radians(75.0)


def _model():
    phi, h = _force_angle(), 1e-4

    def d(key, k):
        f = [np.asarray(_pos(phi + s * h)[key], float) for s in (-1, 0, 1)]
        if key.startswith("th"):
            f = [f[1] + (x - f[1] + np.pi) % (2 * np.pi) - np.pi for x in f]
        return (f[2] - f[0]) / (2 * h) * W1 if k == 1 else (f[2] - 2 * f[1] + f[0]) / h ** 2 * W1 ** 2
    x = _pos(phi)
    m = {1: Q * R1, 2: Q * L2, 3: Q * L3, 4: Q * L4, 5: 6.0}
    inertia = {2: KI * m[2] * L2 ** 2, 3: KI * m[3] * L3 ** 2, 4: KI * m[4] * L4 ** 2}
    f = {i: np.array([0.0, -m[i] * G]) - m[i] * d(f"S{i}", 2) for i in m}       # G + Φ at S_i
    mphi = {i: -inertia[i] * d(f"th{i}", 2) for i in inertia}
    v_e = d("E", 1)
    p = np.array([0.0, -900.0 * np.sign(v_e[1])])
    power = sum(f[i] @ d(f"S{i}", 1) for i in m) + sum(mphi[i] * d(f"th{i}", 1) for i in inertia) + p @ v_e
    mb_power = -power / W1
    # II(4-5): R34 (on 4 at D), R54 (on 4 at E), R05 along x (on 5, normal to the vertical guide)
    a = np.zeros((5, 5)); b = np.zeros(5)
    f5 = f[5] + p
    a[0, [0, 2]] = 1; b[0] = -f[4][0]
    a[1, [1, 3]] = 1; b[1] = -f[4][1]
    ed = x["E"] - x["D"]
    a[2, 2], a[2, 3] = -ed[1], ed[0]; b[2] = -(_cross(x["S4"] - x["D"], f[4]) + mphi[4])
    a[3, 2], a[3, 4] = -1, 1; b[3] = -f5[0]
    a[4, 3] = -1; b[4] = -f5[1]
    s = np.linalg.solve(a, b)
    r34, r05 = s[:2], np.array([s[4], 0.0])
    # II(2-3): R12 (on 2 at A), R32 (on 2 at B), R03 (on 3 at O2); R43 = −R34 at D
    a = np.zeros((6, 6)); b = np.zeros(6)
    r43 = -r34
    ba, bo = x["B"] - x["A"], x["B"] - O2
    a[0, [0, 2]] = 1; b[0] = -f[2][0]
    a[1, [1, 3]] = 1; b[1] = -f[2][1]
    a[2, 2], a[2, 3] = -ba[1], ba[0]; b[2] = -(_cross(x["S2"] - x["A"], f[2]) + mphi[2])
    a[3, 2], a[3, 4] = -1, 1; b[3] = -(f[3][0] + r43[0])
    a[4, 3], a[4, 5] = -1, 1; b[4] = -(f[3][1] + r43[1])
    a[5, 2], a[5, 3] = bo[1], -bo[0]
    b[5] = -(_cross(x["S3"] - O2, f[3]) + _cross(x["D"] - O2, r43) + mphi[3])
    s = np.linalg.solve(a, b)
    r12, r03 = s[:2], s[4:6]
    mb_statics = _cross(x["A"] - O1, r12)            # M_b + (A − O1) × R21 = 0, R21 = −R12
    return dict(phi=np.degrees(phi) % 360, mb_power=mb_power, mb_statics=mb_statics,
                R05=r05, R34=r34, R12=r12, R03=r03)


@pytest.fixture(scope="module")
def both():
    from review_scenes import LINK61
    from graphplan.exact import kinetostatics
    st = scene_study(LINK61)
    phi = float(kinetostatics.at_scene_angle(st))
    return _model(), phi, kinetostatics.analyse(st, [phi])


def test_the_force_angle_and_m_b_by_virtual_power(both):
    mine, phi, ks = both
    assert mine["phi"] == pytest.approx(phi, abs=1e-3)                    # 138.329°
    assert mine["mb_power"] == pytest.approx(mine["mb_statics"], rel=1e-6)
    assert float(ks.balancing[0]) == pytest.approx(mine["mb_power"], rel=1e-5)      # −44.497 N·m


@pytest.mark.parametrize("key", ["R05", "R34", "R12", "R03"])
def test_reactions_by_each_groups_statics(both, key):
    mine, _, ks = both
    got = {k: complex(r.force[0]) for k, r in ks.reactions.items()}
    # the closed form's pair reactions are named by the link acted on (R05 on 5, R34 on 4 …)
    want = complex(*mine[key])
    assert got[key] == pytest.approx(want, rel=1e-5, abs=1e-6), (key, got[key], want)
