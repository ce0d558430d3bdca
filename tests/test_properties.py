"""Hypothesis: random mechanisms of every dyad kind. Loop closure holds, velocity is the derivative
of position and acceleration of velocity, no branch jumps; impossible ones give one clean line."""
from __future__ import annotations

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st_

import random_mechanisms as rm
from conftest import derivative, scene_study
from graphplan.cli.main import main
from graphplan.util.errors import AssemblyError

ANGLES = np.linspace(0, 360, 25)[:-1] + 0.9
FAST = settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
length = st_.floats(0.02, 0.5)
omega = st_.sampled_from([-30.0, -5.0, 7.5, 100.0])
branch = st_.sampled_from([1, -1])


def check_motion(st, margin: float = 1e-6):
    """Closure, derivatives and continuity over the turn."""
    w = st.mech.omega1
    kin = st.solve(ANGLES)
    mech = st.mech
    # loop closure: a joint computed from each body holding it is the same point
    for name in mech.point_names():
        holders = [b for b in mech.bodies_of(name) if b != "0"]
        places = [kin.bodies[b].at(mech.links[b].local[name])[0] for b in holders]
        if name in mech.frame:
            places.append(np.full(len(ANGLES), mech.frame[name]))
        for p in places[1:]:
            assert np.allclose(p, places[0], atol=1e-12)
    # every slider point lies on its guide line
    for key, sl in kin.slides.items():
        pt = kin.point(sl.point)[0]
        guide = mech.guides[mech.links[sl.slider].slides_on]
        carrier = kin.bodies[sl.carrier] if sl.carrier != "0" else None
        if carrier is None:
            base, g = guide.through, np.exp(1j * guide.angle)
        else:
            base = carrier.at(guide.through)[0]
            g = np.exp(1j * (carrier.theta + guide.angle))
        offset = mech.links[sl.slider].local[sl.point] * np.exp(1j * guide.angle)
        rel = (pt - base) - (offset * (g / np.exp(1j * guide.angle)))
        assert np.allclose(np.imag(np.conj(g) * rel), 0, atol=1e-12)
    scale_v = abs(w) * mech.crank.length
    for name in mech.point_names():
        _, v, a = kin.point(name)
        fd_v = derivative(lambda p: st.solve(p).point(name)[0], ANGLES, w, h_deg=0.02)
        fd_a = derivative(lambda p: st.solve(p).point(name)[1], ANGLES, w, h_deg=0.02)
        vs = max(np.max(np.abs(v)), scale_v)
        assert np.all(np.abs(v - fd_v) <= 1e-6 * vs), name
        asc = max(np.max(np.abs(a)), scale_v * abs(w))
        assert np.all(np.abs(a - fd_a) <= 1e-5 * asc), name
    # no branch jumps: over a fine turn every point moves no farther than |v|max·Δt allows
    fine = np.linspace(0, 360, 2881)
    kf = st.solve(fine)
    dt = np.radians(360 / 2880) / abs(w)
    for name in mech.point_names():
        x, v, _ = kf.point(name)
        step = np.abs(np.diff(x))
        assert np.all(step <= 1.05 * np.max(np.abs(v)) * dt + 1e-12), name


@FAST
@given(r=st_.floats(0.02, 0.1), d=st_.floats(0.15, 0.4), l2=length, l3=length, w=omega, b=branch)
def test_rrr(r, d, l2, l3, w, b):
    text, ok = rm.rrr(r, d, l2, l3, w, b)
    margin = 0.01
    assume(l2 + l3 > d + r + margin and abs(l2 - l3) < d - r - margin)
    st = scene_study(text)
    assert st.structure.dyads[0].kind == "RRR"
    check_motion(st)


@FAST
@given(r=st_.floats(0.02, 0.1), l=st_.floats(0.05, 0.5), e=st_.floats(-0.05, 0.05),
       ang=st_.floats(-180, 180), w=omega, b=branch)
def test_rrp(r, l, e, ang, w, b):
    text, ok = rm.rrp(r, l, e, ang, w, b)
    assume(l > r + abs(e) + 0.01)
    st = scene_study(text)
    assert st.structure.dyads[0].kind == "RRP"
    check_motion(st)


@FAST
@given(r=st_.floats(0.03, 0.15), c=st_.floats(0.0, 0.3), e=st_.floats(-0.02, 0.02), w=omega, b=branch)
def test_rpr(r, c, e, w, b):
    text, ok = rm.rpr(r, c, e, w, b)
    assume(abs(c - r) > abs(e) + 0.01)
    st = scene_study(text)
    assert st.structure.dyads[0].kind == "RPR"
    check_motion(st)
    kin = st.solve(ANGLES)
    sl = kin.slides["A"]
    # the Coriolis term: 2·ω_rocker·v_rel, on a rotating guide
    assert np.allclose(sl.coriolis_magnitude, 2 * np.abs(kin.bodies["PQ"].omega * sl.v))


@FAST
@given(r=st_.floats(0.02, 0.06), d=st_.floats(0.2, 0.3), l2=st_.floats(0.2, 0.35), l3=st_.floats(0.15, 0.3),
       alpha=st_.floats(-60, 60), beta=st_.floats(0, 180), w=omega)
def test_prp(r, d, l2, l3, alpha, beta, w):
    text, ok = rm.prp(r, d, l2, l3, alpha, beta, w)
    assume(l2 + l3 > d + r + 0.02 and abs(l2 - l3) < d - r - 0.02)
    base = scene_study(rm.rrr(r, d, l2, l3, w, 1)[0]).solve(np.linspace(0, 360, 721))
    rocker = np.degrees(base.bodies["O2B"].theta) + alpha
    sines = np.abs(np.sin(np.radians(rocker - beta)))
    assume(np.min(sines) > 0.2)                               # the two guides never near-parallel
    st = scene_study(text)
    assert [d_.kind for d_ in st.structure.dyads] == ["RRR", "PRP"]
    check_motion(st)
    from graphplan.model.mechanism import FRAME
    kin = st.solve(ANGLES)
    # the point's own name keys its slide along the frame's guide (no Coriolis term) …
    assert kin.slides["C"].carrier == FRAME and np.max(np.abs(kin.slides["C"].coriolis)) == 0
    # … and the block's slide along the rocker's guide has one: the rocker's guide turns
    rel = next(s for s in kin.slides.values() if s.point == "C" and s.carrier != FRAME)
    assert np.max(np.abs(rel.coriolis)) > 0


@FAST
@given(r=st_.floats(0.02, 0.2), alpha=st_.floats(20, 160), beta=st_.floats(-90, 90), w=omega)
def test_rpp(r, alpha, beta, w):
    text, ok = rm.rpp(r, alpha, beta, w)
    st = scene_study(text)
    assert st.structure.dyads[0].kind == "RPP"
    check_motion(st)


@settings(max_examples=20, deadline=None)
@given(r=st_.floats(0.05, 0.1), l=st_.floats(0.01, 0.2), e=st_.floats(-0.05, 0.05), b=branch)
def test_impossible_crank_slider_gives_one_line(tmp_path_factory, r, l, e, b):
    text, ok = rm.rrp(r, l, e, 0.0, 10.0, b)
    assume(l < r + abs(e) - 1e-3)
    path = tmp_path_factory.mktemp("bad") / "bad.toml"
    path.write_text(text, encoding="utf-8")
    with pytest.raises(AssemblyError) as info:
        scene_study(text)
    line = info.value.line()
    assert "II(2-3) RRP" in line and "°" in line and "\n" not in line


@settings(max_examples=15, deadline=None)
@given(r=st_.floats(0.06, 0.1), d=st_.floats(0.15, 0.2), l2=st_.floats(0.02, 0.05), l3=st_.floats(0.02, 0.05))
def test_impossible_four_bar_never_nan(r, d, l2, l3):
    text, ok = rm.rrr(r, d, l2, l3, 5.0, 1)
    with pytest.raises(AssemblyError) as info:
        scene_study(text)
    assert "RRR" in info.value.line()
