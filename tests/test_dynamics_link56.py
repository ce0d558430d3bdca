"""Stop 56: LINK_DYN56 (the lead's six-bar pusher: a crank-rocker four-bar O1ABO2, the rocker's point C
driving the rod CD and the slider D on a guide at 30°, crank clockwise at 120 rpm, 2000 N against the
slider on its working stroke, masses 20 kg/m, I_S = 0,1·m·l²; δ = 0,04, η = 0,8, a 1500-rpm motor).
Everything reduced to the crank is computed here from the geometry alone — two circles for B, a circle
and the guide's line for D, each dS/dφ and dθ/dφ by central differences —, the flywheel by the energy
form of the equation of motion (ω = √(2(T0 + ΔT)/(I*_m + J)), T0 and J solved for ω_m = πn/30 and δ),
the motor by seed 003's rule over the catalogue's 1500-rpm line, and its own steady state by shooting
on dT/dφ = i·η·(A·i·ω + B) − M*_c."""
from __future__ import annotations

import json
import math

import numpy as np
import pytest
from scipy.integrate import cumulative_trapezoid, solve_ivp
from scipy.interpolate import CubicSpline
from scipy.optimize import brentq

from review_scenes import LINK_DYN56

O1, O2 = np.array([0.0, 0.0]), np.array([0.25, 0.0])
R1, L2, L3, LC, L4 = 0.06, 0.22, 0.15, 0.105, 0.25
P0, E = np.array([0.45, 0.05]), np.array([math.cos(math.pi / 6), math.sin(math.pi / 6)])
MASS = {1: 1.2, 2: 4.4, 3: 3.0, 4: 5.0, 5: 15.0}
INERTIA = {1: 0.1 * 1.2 * 0.06 ** 2, 2: 0.1 * 4.4 * 0.22 ** 2, 3: 0.1 * 3.0 * 0.15 ** 2, 4: 0.1 * 5.0 * 0.25 ** 2}
G, F, DELTA, ETA = 9.81, 2000.0, 0.04, 0.8
W1 = 120 * math.pi / 30


def pose(phi: float) -> dict:
    a = O1 + R1 * np.array([math.cos(phi), math.sin(phi)])
    d = O2 - a
    dist = math.hypot(*d)
    along = (L2 * L2 - L3 * L3 + dist * dist) / (2 * dist)
    b = a + along * d / dist + math.sqrt(L2 * L2 - along * along) * np.array([-d[1], d[0]]) / dist
    u = (b - O2) / L3
    c = O2 + LC * u
    w = c - P0
    t = w @ E + math.sqrt(L4 * L4 - (w @ w - (w @ E) ** 2))
    dd = P0 + t * E
    return {"S1": O1, "S2": (a + b) / 2, "S3": O2 + 0.5 * L3 * u, "S4": (c + dd) / 2, "S5": dd, "s": t,
            "t1": phi, "t2": math.atan2(*(b - a)[::-1]), "t3": math.atan2(u[1], u[0]), "t4": math.atan2(*(dd - c)[::-1])}


def rates(phi: float, h: float = 1e-6) -> dict:
    p, q = pose(phi + h), pose(phi - h)
    out = {}
    for k in p:
        d = np.asarray(p[k]) - np.asarray(q[k])
        if k.startswith("t"):
            d = (d + math.pi) % (2 * math.pi) - math.pi
        out[k] = d / (2 * h)
    return out


def inertia(phi: float) -> float:
    d = rates(phi)
    return (sum(m * float(d[f"S{i}"] @ d[f"S{i}"]) for i, m in MASS.items())
            + sum(j * d[f"t{i}"] ** 2 for i, j in INERTIA.items()))


@pytest.fixture(scope="module")
def doc(tmp_path_factory):
    from graphplan.cli.main import main
    import contextlib
    import io
    path = tmp_path_factory.mktemp("link56") / "link56.toml"
    path.write_text(LINK_DYN56, encoding="utf-8")
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        assert main(["dynamics", str(path), "--json"]) == 0
    return json.loads(out.getvalue())


@pytest.mark.slow                     # the program's analysis and the independent integration: ~15 s
def test_link56s_flywheel_and_motor_are_the_equation_of_motions(doc):
    phi0 = math.radians(doc["start_phi_deg"])
    turn = np.linspace(0.0, 2 * math.pi, 7201)
    phis = phi0 - turn                                           # clockwise
    s = np.array([pose(p)["s"] for p in phis])
    end = int(np.argmax(np.abs(s - s[0])))                       # the working stroke: position 0 to the far end

    def resistance(k: int) -> float:
        d = rates(phis[k])
        gravity = -G * sum(m * -d[f"S{i}"][1] for i, m in MASS.items())     # gravity's power over |ω1|
        return -(gravity - (F * abs(d["s"]) if k <= end else 0.0))
    mc = np.array([resistance(k) for k in range(len(turn))])
    md = np.trapezoid(mc, turn) / (2 * math.pi)
    assert doc["moment_driving"] == pytest.approx(md, rel=1e-4)
    for p in doc["positions"]:
        assert p["inertia"] == pytest.approx(inertia(math.radians(p["phi_deg"])), rel=1e-5)
    energy = md * turn - cumulative_trapezoid(mc, turn, initial=0.0)
    im = np.array([inertia(p) for p in phis[::20]])
    de = energy[::20]

    def spread(J: float) -> float:
        def mean(T0):
            w = np.sqrt(2 * (T0 + de) / (im + J))
            return (w.max() + w.min()) / 2 - W1
        T0 = brentq(mean, -de.min() + 1e-9, 1e7)
        w = np.sqrt(2 * (T0 + de) / (im + J))
        return (w.max() - w.min()) / W1 - DELTA
    J = brentq(spread, 1.0, 1e3)
    # seed 003's rule: P = max M*_c·ω1/η → the 1500-rpm line's 4АМ90L4 (2,2 kW: the 1,5 kW below it is short)
    need = mc.max() * W1 / ETA / 1000.0
    assert 1.5 < need < 2.2 and doc["motor"]["power_needed_kW"] == pytest.approx(need, rel=1e-3)
    assert doc["motor"]["name"] == "4АМ90L4"
    i = 1425 / 120
    rotor = 0.0056 * i * i
    fw = doc["flywheel"]
    assert fw["rotor_reduced"] == pytest.approx(rotor, rel=1e-9)
    assert fw["exact"] == pytest.approx(J - rotor, rel=2e-4)
    assert abs(fw["error_pct"]) < 5.0 and fw["graphical"] == pytest.approx(J - rotor, rel=0.05)
    # the motor's own steady state without a flywheel: M*_d(ω) = i·η·(A·i·ω + B), A = M_n/(ω_n − ω_c)
    wn, wc = 1425 * math.pi / 30, 1500 * math.pi / 30
    a = (2200 / wn) / (wn - wc)
    b = -a * wc
    imr = im + rotor
    imr[-1] = imr[0]                                   # the grid's last point is 2π: the turn closes
    spline = CubicSpline(turn[::20], imr, bc_type="periodic")

    def run(T0):
        f = lambda t, T: [i * ETA * (a * i * math.sqrt(2 * T[0] / spline(t)) + b) - np.interp(t, turn, mc)]
        return solve_ivp(f, (0, 2 * math.pi), [T0], rtol=1e-10, atol=1e-10, max_step=0.004, dense_output=True)
    T0 = brentq(lambda T0: run(T0).y[0, -1] - T0, 50.0, 200.0)
    grid = np.linspace(0, 2 * math.pi, 3601)
    w = np.sqrt(2 * run(T0).sol(grid)[0] / spline(grid))
    mean = (w.max() + w.min()) / 2
    motion = doc["motor"]["motion"]
    assert motion["omega_mean"] == pytest.approx(mean, rel=1e-5)
    assert motion["delta"] == pytest.approx((w.max() - w.min()) / mean, rel=1e-3)
    assert motion["delta"] < DELTA and doc["motor"]["flywheel"] == 0.0     # the motor alone keeps δ: none needed
