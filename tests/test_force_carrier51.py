"""Stop 51 (a teacher's grading of a generated six-bar): a useful force on a slider whose pin is shared
by the rod before it, the slider and the rod of the next group (SLIDER_ROCKER51: the crank-slider's
slider B drives a rocker through the rod BC).

The force acts on the slider — the working member — so it is carried by the group of the slider,
II(2-3), not hung on the next group's rod; and the slider is the output the positions, the working
stroke and the useful-resistance diagram are counted on (its path s, not the rocker's angle).
Truth: the closed-form central crank-slider x_B = r·cos φ + √(l² − r²·sin² φ).
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from conftest import scene_study
from review_scenes import SLIDER_ROCKER51

R, L = 0.06, 0.25               # the crank O1A and the rod AB, m (guide through O1, no offset)


@pytest.fixture(scope="module")
def st():
    return scene_study(SLIDER_ROCKER51)


def _x_b(phi_deg: np.ndarray) -> np.ndarray:
    """x_B = r·cos φ + √(l² − r²·sin² φ), m."""
    phi = np.radians(phi_deg)
    return R * np.cos(phi) + np.sqrt(L ** 2 - (R * np.sin(phi)) ** 2)


def test_the_force_on_the_shared_pin_acts_on_the_slider(st):
    from graphplan.exact.kinetostatics import force_link
    holders = st.mech.bodies_of("B")
    assert {st.mech.links[h].number for h in holders} == {2, 3, 4}
    carrier = st.mech.links[force_link(st.mech, "B")]
    assert carrier.number == 3 and carrier.slides_on is not None


def test_the_slider_is_carried_by_its_own_group(st):
    """The group of links 2 and 3 holds the slider that carries P_B (not II(4-5))."""
    from graphplan.exact.kinetostatics import force_link
    name = force_link(st.mech, "B")
    dyad = next(d for d in st.structure.dyads if name in (d.a, d.b))
    assert {st.mech.links[d].number for d in (dyad.a, dyad.b)} == {2, 3}


def test_the_output_is_the_slide_and_position_0_its_extreme(st):
    """Position 0 at an extreme of the slider (x_B = l ± r), not of the rocker."""
    assert (st.output.kind, st.output.name) == ("slide", "B")
    x0 = float(_x_b(np.array([st.phi0]))[0])
    assert min(abs(x0 - (L + R)), abs(x0 - (L - R))) <= 1e-9


def test_the_force_works_over_one_whole_stroke_of_the_slider(st):
    """P_B is on (opposing the motion) over one stroke of the slider — one sign of ẋ_B, a travel of
    2r — and off over the other."""
    from graphplan.exact.kinetostatics import loads, working_stroke
    phi = (st.phi0 + np.arange(0.5, 360.0, 1.0)) % 360.0
    kin = st.solve(phi)
    p_b = next(ld for ld in loads(st, kin, working_stroke(st, phi)) if ld.name == "P_B")
    on = np.abs(p_b.force) > 1e-9
    x = _x_b(phi)
    xdot = np.gradient(x) * math.copysign(1.0, st.mech.omega1)     # along the crank's turn
    assert 170 <= int(on.sum()) <= 190
    assert np.all(np.sign(xdot[on][5:-5]) == np.sign(xdot[on][len(xdot[on]) // 2]))
    assert np.ptp(x[on]) == pytest.approx(2 * R, rel=0.02)
    # along the horizontal guide, against the closed form's motion wherever it acts
    assert np.all(np.abs(p_b.force[on].imag) <= 1e-9 * np.abs(p_b.force[on]))
    assert np.all(p_b.force[on].real[3:-3] * xdot[on][3:-3] < 0)


@pytest.mark.parametrize("name, offset", [("SLIDER_ROCKER51", 0.0), ("OWN_SIX49", None)])
def test_a_slider_on_the_cranks_rod_gives_its_guide_from_the_crank(name, offset):
    """Table 3 gives a guide's distance as the lab does: e from the crank's pivot where the crank's
    own rod drives the slider — even when the slider's pin drives a further group (the rod BC to a
    rocker); "X від O₂" of that rocker read as a crank-slider's offset from the wrong pivot. The
    distance is the crank pivot's from the guide line (the scene's geometry); an axial guide has no row."""
    import cmath

    import review_scenes
    from graphplan.sheets.kintables import guide_distances
    st = scene_study(getattr(review_scenes, name))
    rows = guide_distances(st)
    slider = next(link for link in st.mech.links.values() if link.slides_on in st.mech.guides
                  and any(st.mech.crank.pin in r.joints for r in st.mech.links.values() if link.joints[0] in r.joints))
    g = st.mech.guides[slider.slides_on]
    e = abs(((st.mech.frame[st.mech.crank.pivot] - g.through) * cmath.exp(-1j * g.angle)).imag)
    if offset is not None:
        assert e == pytest.approx(offset, abs=1e-12)
    if e < 1e-9:
        assert rows == []
    else:
        assert [(label, pivot) for label, _, _, pivot in rows] == [("e", st.mech.crank.pivot)]
        assert rows[0][1] == pytest.approx(e, rel=1e-12)
