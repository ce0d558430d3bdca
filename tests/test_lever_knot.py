"""Review 10 #6 and review 11 #12 on the Zhukovsky lever: where a link's image is shorter than a
readable length (the six-bar's a, b, e, s2 within 5 mm at φ = 150°) its inertia couple is carried
as the couple's own moment M·l_ab/l_AB (drawn as an arc with its value), not as a force pair M/l
stacked on a 5-mm segment, and the balancing moment is unchanged: checked against the couples'
virtual powers Σ M_i·ω_i written here. Two forces at one image on one line in opposite senses
(the compressor's Φ3 and P_B at b) are drawn a lane apart, never as one double-headed arrow."""
from __future__ import annotations

import math

import numpy as np
import pytest

from conftest import scene_study
from review_scenes import REV11_A, SIXBAR10
from test_forces_review11 import _read_as_one  # two arrows on one line read as one


def _fp(text: str, precision: float):
    from graphplan.exact import kinetostatics
    from graphplan.graphic import forceplans
    st = scene_study(text)
    phi = float(np.atleast_1d(kinetostatics.at_scene_angle(st))[0])
    return forceplans.construct(st, phi, precision=precision)


@pytest.fixture(scope="module")
def sixbar():
    return _fp(SIXBAR10, 0.5)


def _image_mm(fp, link: str, x: str, y: str, mu_v: float) -> float:
    """|v_Y − v_X| / μv from the exact kinematics (mm on the lever)."""
    mech, kin = fp.ks.mech, fp.ks.kin
    v = [complex(kin.bodies[link].at(mech.links[link].local[p])[1][0]) for p in (x, y)]
    return abs(v[1] - v[0]) / mu_v


def test_a_short_images_couple_is_a_moment_and_the_rest_are_pairs(sixbar):
    """The coupler plate's couple MΦ2 (ab ≈ 5 mm) is one moment term, no pair MΦ2', MΦ2''; the
    rocker's and the connecting rod's (images ≥ 10 mm) stay pairs at their joints."""
    from graphplan.graphic.lever import READABLE_MM
    lv = sixbar.lever
    moments = {t.name: t for t in lv.terms if not t.vector and t.pair}
    assert set(moments) == {"MΦ2"}
    x, y = moments["MΦ2"].pair
    link = next(ld.link for ld in sixbar.ks.loads if ld.name == "MΦ2")
    assert _image_mm(sixbar, link, x, y, lv.mu_v) < READABLE_MM
    assert not any(t.name.startswith("MΦ2'") for t in lv.terms)
    assert {"MΦ3'", "MΦ4'", "MΦ4''"} <= {t.name for t in lv.terms}


@pytest.mark.parametrize("precision", [0.0, 0.5])
def test_the_couples_on_the_lever_sum_to_their_virtual_powers(precision):
    """Σ over the couples of their lever moments (pairs F·h and moment terms) = −Σ M_i·ω_i / μv
    (the lever's moment is −power/μv), exactly at precision 0, and within what the ruler explains
    at 0.5 mm (each arm or l_ab ± 0.25 mm: |M|/l per reading); the balancing moment read off the
    lever equals the virtual-power one at precision 0."""
    fp = sixbar_fp = _fp(SIXBAR10, precision)
    lv, ks = fp.lever, sixbar_fp.ks
    couples = [ld for ld in ks.loads if float(ld.couple[0]) != 0]
    assert couples
    power = sum(float(ld.couple[0]) * float(ld.omega[0]) for ld in couples)   # Σ M_i·ω_i, W
    on_lever = sum(t.moment for t in lv.terms if t.name.startswith("MΦ"))
    want = -power / lv.mu_v
    if precision == 0.0:
        assert on_lever == pytest.approx(want, rel=1e-9, abs=1e-9)
        total = sum(float(ld.power[0]) for ld in ks.loads)       # Σ F·v + M·ω
        m_b = -total / ks.mech.omega1
        assert lv.balancing == pytest.approx(m_b, rel=1e-9)
    else:
        mech = ks.mech
        # the pair's (or the moment's) l_XY: the link's shortest distance between its joints
        lengths = {ld.name: min(abs(mech.links[ld.link].local[p] - mech.links[ld.link].local[q])
                                for p in mech.links[ld.link].joints for q in mech.links[ld.link].joints if p != q)
                   for ld in couples}
        slack = sum(2 * abs(float(ld.couple[0])) / lengths[ld.name] * precision for ld in couples)
        assert abs(on_lever - want) <= slack


def test_the_moment_is_drawn_as_an_arc_named_with_its_value(sixbar):
    """The lever's drawing: an arc round ab with a head, named M^Φ_2·l_ab/l_AB = … N·mm with the
    term's value; no arrow of MΦ2's pair; no lever word overprinted."""
    from graphplan.drawing.forces import lever_record
    from graphplan.util.words import num
    rec = lever_record(sixbar, "en")
    t = next(t for t in sixbar.lever.terms if t.name == "MΦ2")
    names = [p.text for p in rec.items if p.kind == "text"]
    said = [s for s in names if "l_{ab}/l_{AB}" in s or "l_{ba}/l_{BA}" in s]
    assert len(said) == 1 and said[0].endswith(f"= {num(abs(t.moment), 'en')} N·mm"), names
    assert any(p.kind == "arc" for p in rec.items)
    assert not any(p.kind == "vector" and p.text.startswith("MΦ2") for p in rec.items)



def test_the_compressors_lever_draws_phi3_and_p_b_apart():
    """REV11_A: Φ3 and P_B at b are collinear and opposite; on the lever no two arrows read as
    one, and both keep their one arm h_{Φ3,P_B} (its foot on their common line)."""
    from graphplan.drawing.forces import lever_record
    fp = _fp(REV11_A, 0.5)
    rec = lever_record(fp, "en")
    vs = [(p.text.split(":")[0], complex(*p.points[0]), complex(*p.points[1])) for p in rec.items
          if p.kind == "vector" and p.text]
    for i, (n1, a, b) in enumerate(vs):
        for n2, c, d in vs[i + 1:]:
            assert not _read_as_one(a, b, c, d), (n1, n2)
    arrows = {n: (a, b) for n, a, b in vs}
    (a1, b1), (a2, b2) = arrows["Φ3"], arrows["P_B"]
    u = (b1 - a1) / abs(b1 - a1)
    assert abs(((b2 - a2) / abs(b2 - a2)) + u) < 1e-6            # opposite senses, parallel
    assert abs(((a2 - a1) * u.conjugate()).imag) >= 1.5           # a lane apart
    feet = {p.text.rsplit(" to ", 1)[1]: complex(*p.points[1]) for p in rec.items
            if p.kind == "segment" and p.text.startswith("h_{") and " mm to " in p.text}
    assert abs(feet["Φ3"] - feet["P_B"]) < 1e-6
    assert math.isfinite(fp.lever.balancing)
