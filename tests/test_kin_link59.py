"""Stop 59's lead's mechanism LINK59 checked as a teacher checks it: a crank-rocker four-bar
O1A–AB–O2B whose rocker carries a slot; a block C (4) in it is pinned to a ram (5) on a horizontal
guide 0.22 m above the pivots — a PRP group whose block slides on a ROTATING link. The plans' exact
values against an independent solution: the four-bar by two circles, C where the slot's line meets
the guide, every rate by central differences in time. v_C5 = v_C4 = v_C3 + v_C4C3 (along the slot),
a_C = a_C3 + a^k_C4C3 + a^r_C4C3 with the Coriolis term 2·ω3·v_C4C3, its direction v_rel turned 90°
in ω3's sense."""
from __future__ import annotations

import math

import numpy as np
import pytest

from conftest import scene_study
from graphplan.graphic.plans import build_plans
from review_scenes import LINK59

R, AB, O2B, D, E = 0.07, 0.26, 0.18, 0.24, 0.22        # crank, rod, rocker, O1O2, the guide's height
W1 = 95 * 2 * math.pi / 60                              # clockwise
DT = 1e-5


def _at(theta: float):
    """(C, the slot's angle, C's distance from O2 along the slot) with the crank at ``theta`` rad."""
    A = R * np.exp(1j * theta)
    O2 = complex(D, 0.0)
    d = abs(O2 - A)
    a = (AB ** 2 - O2B ** 2 + d ** 2) / (2 * d)
    h = math.sqrt(AB ** 2 - a ** 2)
    u = (O2 - A) / d
    B = max((A + a * u + s * h * 1j * u for s in (1, -1)), key=lambda z: z.imag)    # B above the pivots
    psi = np.angle(B - O2)
    t = E / math.sin(psi)
    return O2 + t * np.exp(1j * psi), psi, t


def _rates(theta0: float):
    """v_C, a_C (complex), ω3, ε3, v_rel, a_rel, the slot's unit vector, t — the crank at θ0 turning clockwise."""
    got = [_at(theta0 - W1 * k * DT) for k in (-1, 0, 1)]
    C = np.array([g[0] for g in got])
    psi = np.unwrap([g[1] for g in got])
    t = np.array([g[2] for g in got])
    d1 = lambda x: (x[2] - x[0]) / (2 * DT)                     # noqa: E731
    d2 = lambda x: (x[2] - 2 * x[1] + x[0]) / DT ** 2           # noqa: E731
    return d1(C), d2(C), d1(psi), d2(psi), d1(t), d2(t), np.exp(1j * psi[1]), t[1]


@pytest.fixture(scope="module")
def plans():
    st = scene_study(LINK59.replace("accel = [4]", "accel = [4, 10]"))
    return st, build_plans(st)


@pytest.mark.parametrize("k", [4, 10])
def test_the_ram_the_slot_and_coriolis_against_an_independent_solution(plans, k):
    st, pl = plans
    p = pl.at(k)
    theta = math.radians(p.phi)
    vC, aC, w3, e3, vr, ar, u, t = _rates(theta)
    assert abs(vC.imag) < 1e-6 and abs(aC.imag) < 1e-4            # the ram: along its horizontal guide
    vel, acc = p.velocity.entries, p.acceleration.entries
    assert vel["C"].exact == pytest.approx(vC, abs=1e-6)
    assert vel["C4C3"].exact == pytest.approx(vr * u, abs=1e-6)                    # along the slot
    assert vel["C3"].exact == pytest.approx(1j * w3 * t * u, abs=1e-6)             # ω3 × O2C
    assert vel["C"].exact == pytest.approx(vel["C3"].exact + vel["C4C3"].exact, abs=1e-9)
    assert acc["C"].exact == pytest.approx(aC, abs=2e-4)
    cor = 2 * w3 * 1j * (vr * u)                  # v_rel turned 90° in ω3's sense, 2·|ω3|·|v_rel| long
    assert acc["k_C4C3"].exact == pytest.approx(cor, abs=1e-5)
    assert acc["k_C4C3"].analytic == pytest.approx(2 * abs(w3 * vr), rel=1e-5)
    assert acc["r_C4C3"].exact == pytest.approx(ar * u, abs=2e-4)
    a_c3 = (1j * e3 - w3 ** 2) * t * u
    assert acc["C3"].exact == pytest.approx(a_c3, abs=2e-4)
    assert acc["C"].exact == pytest.approx(acc["C3"].exact + acc["k_C4C3"].exact + acc["r_C4C3"].exact, abs=1e-9)
    # the drawn Coriolis vector points the way the exact one does (within the drawing's precision)
    drawn = acc["k_C4C3"].vector
    assert abs(np.angle(drawn / cor)) < math.radians(3.0)


def test_the_rams_stroke_and_its_extremes():
    """Position 0 is where the working stroke starts (v_C = 0); the ram's stroke between the two
    stops, 224.9 mm, the working stroke 195.6° of the crank's turn."""
    st = scene_study(LINK59)
    grid = np.radians(st.phi0 - np.arange(0.0, 360.0, 0.01))
    x = np.array([_at(th)[0].real for th in grid])
    assert (x.max() - x.min()) * 1000 == pytest.approx(224.93, abs=0.01)
    assert x.argmin() == 0
    assert np.arange(0.0, 360.0, 0.01)[x.argmax()] == pytest.approx(195.61, abs=0.02)
    kin = st.solve(np.array([st.phi0]))
    assert abs(kin.slides["C"].v[0]) < 1e-9
