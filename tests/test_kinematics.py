"""The analytic solver against independent truth: published numbers, closed forms and
finite differences of its own exact positions (a different computation from its velocity loops)."""
from __future__ import annotations

import math

import numpy as np
import pytest

from conftest import derivative, example, scene_study

ANGLES = np.linspace(0.0, 360.0, 73)[:-1] + 1.7  # many angles, none on a grid line


def close(value, truth, scale, rel=1e-7):
    """|value − truth| ≤ rel·max(|truth|, 1e-3·scale): relative, with a floor near zero."""
    err = np.abs(np.asarray(value) - np.asarray(truth))
    return np.all(err <= rel * np.maximum(np.abs(truth), 1e-3 * scale))


def test_crank_slider_published_values():
    st = example("crank_slider")
    assert st.phi0 == pytest.approx(0.0, abs=1e-9)           # outer dead centre
    kin = st.solve(st.positions())
    x, v, a = kin.point("B")
    assert abs(v[1]) == pytest.approx(11.081, abs=5e-4)       # REFERENCE §2, 30° from the ODC
    assert abs(kin.bodies["AB"].omega[1]) == pytest.approx(53.20, abs=5e-3)
    assert abs(kin.point("A")[1][0]) == pytest.approx(293.07 * 0.064)   # v_A = ω1·r = 18.76
    assert x[0].real == pytest.approx(0.064 + 0.307)


def test_crank_slider_closed_form():
    """x_B = r cosφ + √(l² − r² sin²φ) and its exact derivatives."""
    st = example("crank_slider")
    r, l, w = 0.064, 0.307, 293.07
    phi = np.radians(ANGLES)
    kin = st.solve(ANGLES)
    x, v, a = kin.point("B")
    root = np.sqrt(l ** 2 - r ** 2 * np.sin(phi) ** 2)
    xb = r * np.cos(phi) + root
    vb = -r * w * np.sin(phi) - r ** 2 * w * np.sin(phi) * np.cos(phi) / root
    assert np.allclose(x.real, xb, rtol=1e-13)
    assert close(v.real, vb, 20.0, 1e-10)
    # ω_AB = −r ω1 cosφ / (l cosβ), sinβ = r sinφ / l
    w2 = -r * w * np.cos(phi) / root
    assert close(kin.bodies["AB"].omega, w2, 60.0, 1e-10)


def test_shaper_synthesis_and_stroke():
    st = example("shaper")
    d = st.mech.derived
    assert d["theta_deg"] == pytest.approx(180 * 0.8 / 2.8)
    assert d["crank"] == pytest.approx(0.48 * math.sin(math.radians(d["theta_deg"] / 2)))
    assert d["crank"] == pytest.approx(0.20826, abs=1e-5)
    assert d["rocker"] == pytest.approx(0.57619, abs=1e-5)
    # extremes: the crank ⟂ rocker; the two strokes take 180° ∓ θ of crank turn
    e1, e2 = st.extremes
    assert (e2 - e1) % 360 == pytest.approx(180 - d["theta_deg"], abs=1e-8)
    kin = st.solve(list(st.extremes))
    c = kin.point("C")[0].real
    assert abs(c[1] - c[0]) == pytest.approx(0.5, rel=1e-9)   # the ram's stroke H
    # position 0 starts the idle (fast) stroke: the next extreme comes after 180° − θ
    nxt = [e for e in st.extremes if e != st.phi0][0]
    assert (nxt - st.phi0) % 360 == pytest.approx(180 - d["theta_deg"], abs=1e-8)


def test_four_bar_dead_centres_are_crank_and_coupler_in_line():
    st = example("four_bar")
    kin = st.solve(list(st.extremes))
    a = kin.point("A")[0]
    b = kin.point("B")[0]
    o1 = 0j
    for k in range(2):  # O1, A, B collinear at the rocker's extremes
        u, w = a[k] - o1, b[k] - a[k]
        assert abs((np.conj(u) * w).imag) < 1e-12
    assert np.all(kin.point("B")[0].imag > 0)                # B above O1O2 (branch +1)


@pytest.mark.parametrize("name", ["crank_slider", "lab_crank_slider", "four_bar", "shaper", "slotter"])
def test_velocity_and_acceleration_are_derivatives(name):
    st = example(name)
    omega = st.mech.omega1
    kin = st.solve(ANGLES)
    for point in st.mech.point_names():
        if point in st.mech.frame:
            continue
        x, v, a = kin.point(point)
        v_a = abs(omega) * st.mech.crank.length  # the mechanism's scale: v_A, a_A
        vmax = max(np.max(np.abs(v)), v_a)
        amax = max(np.max(np.abs(a)), v_a * abs(omega))
        fd_v = derivative(lambda p: st.solve(p).point(point)[0], ANGLES, omega)
        fd_a = derivative(lambda p: st.solve(p).point(point)[1], ANGLES, omega)
        fd_a2 = derivative(lambda p: st.solve(p).point(point)[0], ANGLES, omega, order=2, h_deg=0.2)
        assert close(v, fd_v, vmax), point
        assert close(a, fd_a, amax), point
        assert close(a, fd_a2, amax, rel=1e-6), point
    for link, body in kin.bodies.items():
        if link == "0":
            continue
        theta = lambda p, link=link: np.unwrap(st.solve(p).bodies[link].theta)  # noqa: E731
        assert close(body.omega, derivative(theta, ANGLES, omega), abs(omega) * 5), link
        omg = lambda p, link=link: st.solve(p).bodies[link].omega  # noqa: E731
        assert close(body.eps, derivative(omg, ANGLES, omega), omega ** 2 * 5), link


@pytest.mark.parametrize("name", ["shaper", "slotter"])
def test_coriolis_of_the_slotted_link(name):
    """a_k = 2·ω3·v_rel: ω3 and v_rel from finite differences of the rocker angle and the slide."""
    st = example(name)
    omega = st.mech.omega1
    kin = st.solve(ANGLES)
    slide = kin.slides["A"]
    w3 = derivative(lambda p: np.unwrap(st.solve(p).bodies[slide.carrier].theta), ANGLES, omega)
    vrel = derivative(lambda p: st.solve(p).slides["A"].t, ANGLES, omega)
    ak = 2 * np.abs(w3 * vrel)
    assert close(slide.coriolis_magnitude, ak, np.max(ak))
    # direction: v_rel turned 90° in the sense of ω3
    turned = 1j * np.sign(w3) * slide.direction * np.sign(vrel)
    unit = slide.coriolis / np.maximum(np.abs(slide.coriolis), 1e-300)
    big = ak > 1e-3 * np.max(ak)
    assert np.allclose(unit[big], turned[big], atol=1e-9)
    # and the kinematic identity a_A(block) = a_A(rocker's point) + a_rel + a_k
    _, _, a_block = kin.point("A")
    _, acoinc = kin.bodies[slide.carrier].coincident(kin.point("A")[0])
    assert np.allclose(a_block, acoinc + slide.a * slide.direction + slide.coriolis, rtol=1e-10, atol=1e-9)


def test_crank_epsilon_enters_the_accelerations():
    """With ε1 ≠ 0 at one position: a = a(ε1 = 0) + (v/ω1)·ε1 for every point."""
    text = (example_text("crank_slider").replace("omega = 293.07", "omega = 293.07\nepsilon = 500.0"))
    st_e = scene_study(text)
    st_0 = example("crank_slider")
    kin_e, kin_0 = st_e.solve(ANGLES), st_0.solve(ANGLES)
    for p in ("A", "B", "S2"):
        _, v, a0 = kin_0.point(p)
        _, _, ae = kin_e.point(p)
        assert np.allclose(ae, a0 + v / 293.07 * 500.0, rtol=1e-12, atol=1e-9)


def test_slides_and_positions_follow_the_crank():
    st = example("crank_slider")
    phis = st.positions()
    assert len(phis) == 12 and phis[1] == pytest.approx(30.0)
    cw = scene_study(example_text("crank_slider").replace('omega = 293.07', 'omega = 293.07\ndirection = "cw"'))
    assert cw.positions()[1] == pytest.approx(330.0)           # the crank's own sense
    kin = cw.solve(cw.positions())
    assert kin.point("B")[1][1].real < 0                        # moving back toward O after the ODC


def example_text(name: str) -> str:
    from conftest import ROOT
    return (ROOT / "examples" / f"{name}.toml").read_text(encoding="utf-8")


def test_a_group_that_locks_is_refused_and_one_near_locking_is_warned():
    """Four-bar O1A = 0.1, O1O2 = 0.3, AB = 0.35: with O2B = 0.15 the coupler and rocker come into
    line at φ = 0 (|AO2| = 0.2 = AB − O2B): refused; with 0.151 they nearly do: a warning."""
    import random_mechanisms as rm
    from graphplan.util.errors import AssemblyError
    text, _ = rm.rrr(0.1, 0.3, 0.35, 0.15, 6.28, 1)
    with pytest.raises(AssemblyError, match=r"locks at crank angle 0\.00°"):
        scene_study(text)
    text, _ = rm.rrr(0.1, 0.3, 0.35, 0.151, 6.28, 1)
    st = scene_study(text)
    assert len(st.warnings) == 1 and "near crank angle 0.00°" in st.warnings[0]
    # the true angle between coupler and rocker at φ = 0: law of cosines in triangle A–B–O2
    cos_mu = (0.35 ** 2 + 0.151 ** 2 - 0.2 ** 2) / (2 * 0.35 * 0.151)
    mu = math.degrees(math.acos(cos_mu))
    assert f"{mu:.2f}°" in st.warnings[0]
    for name in ("crank_slider", "four_bar", "shaper", "slotter"):
        assert example(name).warnings == []
