"""Stop 45's teacher look at a mechanism nobody had drawn: an offset compressor (crank-slider, e = 18 mm,
the crank clockwise at 480 rpm, gas pressure on the piston over the compression stroke as a profile),
forces at φ = 130° from the outer dead centre. The balancing moment by the closed form written here
(virtual power, the positions by the triangle OAB, derivatives by central differences), and on the
crank's group as drawn: R21 at A, R01 at O, M_зр's arc turning in its sense, each arm ending on its
own force's line and square to it."""
import math

import numpy as np

from conftest import scene_study
from review_scenes import COMPRESSOR45

R, L, E = 0.05, 0.2, 0.018          # OA, AB, the guide's offset (m)
OMEGA = -480 * math.pi / 30         # clockwise
M1, M2, M3, I2, G = 4.2, 2.4, 3.1, 0.011, 9.81
PROFILE = np.array([[0, 0.04], [0.03, 0.1], [0.06, 0.3], [0.08, 0.65], [0.09, 1], [0.103, 1]])
PMAX = 3200.0


def _points(th: float):
    """A, B, S1, S2 (m) at the crank angle th (rad from x): B on the guide y = e, |AB| = l."""
    a = R * np.array([math.cos(th), math.sin(th)])
    b = np.array([a[0] + math.sqrt(L ** 2 - (E - a[1]) ** 2), E])
    return a, b, 0.35 * a, a + 0.32 * (b - a)


def _crank_angle() -> float:
    """130° clockwise from the outer dead centre, where O, A, B lie on one line: asin(e/(r + l))."""
    return math.asin(E / (R + L)) - math.radians(130.0)


def _balancing() -> float:
    """M_зр·ω1 + Σ F·v + Σ M·ω = 0 with the weights, Φ = −m·a_S, M^Φ = −I_S·ε and the gas force
    opposing the piston (its share of 3200 N at the piston's travel from the outer dead centre)."""
    th, h = _crank_angle(), 1e-5

    def d(k: int, order: int):
        f = [np.append(_points(th + j * h)[k], 0.0) if k < 4 else np.array([0.0])
             for j in (-1, 0, 1)]
        return (f[2] - f[0]) / (2 * h) if order == 1 else (f[2] - 2 * f[1] + f[0]) / h ** 2

    def phi2(t: float) -> float:
        a, b, _, _ = _points(t)
        return math.atan2(b[1] - a[1], b[0] - a[0])
    v = {k: d(k, 1)[:2] * OMEGA for k in (1, 2, 3)}
    acc = {k: d(k, 2)[:2] * OMEGA ** 2 for k in (1, 2, 3)}
    w2 = (phi2(th + h) - phi2(th - h)) / (2 * h) * OMEGA
    e2 = (phi2(th + h) - 2 * phi2(th) + phi2(th - h)) / h ** 2 * OMEGA ** 2
    s = _points(math.asin(E / (R + L)))[1][0] - _points(th)[1][0]
    gas = PMAX * float(np.interp(s, PROFILE[:, 0], PROFILE[:, 1])) * -math.copysign(1.0, v[1][0])
    power = sum(float(np.dot(-m * acc[k] + [0.0, -m * G], v[k])) for k, m in ((2, M1), (3, M2)))
    power += float(np.dot(-M3 * acc[1] + [gas, -M3 * G], v[1])) + (-I2 * e2) * w2
    return -power / OMEGA


def _plans():
    from graphplan.sheets import forces as sf
    from graphplan.sheets.compose import SheetOptions
    return sf.ForceDrafter(scene_study(COMPRESSOR45), SheetOptions(precision=0.5, sheet="forces")).fp()


def test_the_balancing_moment_by_the_closed_form_and_the_crank_group_as_drawn():
    fp = _plans()
    exact = _balancing()
    assert abs(exact - (-80.549)) < 0.01                       # the sheet's Table 5 row, written down
    assert abs(fp.analytic - exact) < 1e-6 * abs(exact)
    assert abs(fp.balancing - exact) < 0.01 * abs(exact)       # the force plans, at the ruler's 0.5 mm
    from graphplan.drawing.forces import group_record
    crank = fp.groups[-1]
    mu = crank.mu_l or fp.mu_l
    rec = group_record(fp, crank, "en")
    arrows = {q.text: (complex(*q.points[0]), complex(*q.points[1])) for q in rec.items
              if q.kind == "vector" and q.role != "head" and q.text}
    a_mm = complex(*_points(_crank_angle())[0]) / mu
    assert set(arrows) >= {"G1", "Φ1", "R21", "R01"} and "R12" not in arrows
    assert min(abs(e - a_mm) for e in arrows["R21"]) < 1e-6     # the rod's force on the crank, at A
    assert abs(arrows["R01"][0]) < 1e-6                         # the frame's, at O
    head = next(q for q in rec.items if q.kind == "vector" and q.role == "head" and q.text == "M_b")
    tail, tip = (complex(*p) for p in head.points)
    turn = (tail.conjugate() * (tip - tail)).imag                # > 0 counter-clockwise about O
    assert turn < 0 < -exact                                     # M_зр clockwise, as its sign
    arms = [q for q in rec.items if q.kind == "segment" and q.text.startswith("h_{")]
    assert {q.text.split("}")[0][3:] for q in arms} == {"G1", "R21"}
    for q in arms:
        name = q.text.split("}")[0][3:]
        t, h = arrows[name]
        u = (h - t) / abs(h - t)
        p, foot = (complex(*c) for c in q.points)
        assert abs(((foot - t) * u.conjugate()).imag) < 0.05, name        # the foot on its own line
        assert abs(((foot - p) * u.conjugate()).real) < 0.05, name        # square to it
