"""Scenes written in the textbook's words: dead centres named inner/outer, a triangular link's vertex
given once in its shape, a slider in a slot of the crank."""
from __future__ import annotations

import math

import numpy as np
import pytest

from graphplan.exact.positions import study
from graphplan.model.scene import loads
from graphplan.util.errors import GraphplanError

CRANK_SLIDER = """
[frame.points]
O = [0, 0]
[frame.guides]
x = {{ through = [0, {e}], angle_deg = 0 }}
[crank]
pivot = "O"
pin = "A"
length = 0.064
omega = 293.07
[[link]]
joints = ["A", "B"]
length = 0.307
[[link]]
name = "slider"
joints = ["B"]
slides_on = "x"
[branch]
B = {branch}
[positions]
start = "{start}"
"""


@pytest.mark.parametrize("branch", [1, -1])
@pytest.mark.parametrize("e", [0.0, 0.02])
def test_inner_dead_centre_is_the_slider_nearest_the_crank_pivot(branch, e):
    """Inner: |OB| = l − r (crank and rod folded); outer: |OB| = l + r (stretched) — with an offset e
    the same, measured from O: √((l ∓ r)² − e²) along the guide."""
    r, l = 0.064, 0.307
    for start, reach in (("inner", l - r), ("outer", l + r)):
        st = study(loads(CRANK_SLIDER.format(e=e, branch=branch, start=start)))
        kin = st.solve([st.phi0])
        B = complex(kin.point("B")[0][0])
        assert abs(B) == pytest.approx(math.hypot(math.sqrt(reach ** 2 - e ** 2), e), rel=1e-9)
        assert abs(complex(kin.point("B")[1][0])) < 1e-6 * 293.07 * r     # a dead centre: v_B = 0


def test_inner_outer_need_a_slider():
    text = CRANK_SLIDER.format(e=0, branch=1, start="max").replace(
        '[positions]\nstart = "max"', '[positions]\nstart = "inner"\noutput = "AB"')
    with pytest.raises(GraphplanError, match="inner and outer dead centres belong to a slider"):
        study(loads(text))


TRIANGLE = """
[frame.points]
O1 = [0, 0]
O2 = [0.3, 0]
[frame.guides]
x = { through = [0, -0.1], angle_deg = 0 }
[crank]
pivot = "O1"
pin = "A"
length = 0.1
rpm = 60
[[link]]
name = "ABE"
joints = ["A", "B"]
length = 0.35
shape = { E = [0.15, 0.1] }
[[link]]
name = "O2B"
joints = ["O2", "B"]
length = 0.25
[[link]]
name = "EF"
joints = ["E", "F"]
length = 0.5
[[link]]
name = "F"
joints = ["F"]
slides_on = "x"
[positions]
start = 0
"""


def test_a_shape_vertex_is_a_joint_without_a_second_listing():
    st = study(loads(TRIANGLE))
    assert st.structure.formula == "I(0-1) → II(2-3) → II(4-5)" and st.structure.mobility == 1
    kin = st.solve(np.arange(0.0, 360.0, 30.0))
    A, B, E = (kin.point(p)[0] for p in ("A", "B", "E"))
    # E rides on the coupler: fixed distances to A and B; EF keeps its length
    assert np.allclose(np.abs(E - A), abs(complex(0.15, 0.1)), atol=1e-12)
    assert np.allclose(np.abs(E - B), abs(complex(0.15 - 0.35, 0.1)), atol=1e-12)
    assert np.allclose(np.abs(kin.point("F")[0] - E), 0.5, atol=1e-12)


SLOTTED_CRANK = """
[frame.points]
O = [0, 0]
C = [0.3, 0.0]
[crank]
pivot = "O"
pin = "A"
length = 0.1
rpm = 60
guide = { through = [0, 0], angle_deg = 0 }
[[link]]
name = "2"
joints = ["B"]
slides_on = "OA"
[[link]]
name = "BC"
joints = ["B", "C"]
length = 0.35
[positions]
start = 0
"""


def test_a_slider_in_the_cranks_slot_with_nothing_at_the_pin():
    st = study(loads(SLOTTED_CRANK))
    assert st.structure.mobility == 1 and st.structure.dyads[0].kind in ("RRP", "RPR")
    phi = np.arange(0.0, 360.0, 15.0)
    kin = st.solve(phi)
    B = kin.point("B")[0]
    # B stays on the crank's line through O and at 0.35 from C
    assert np.allclose(np.abs(np.imag(B * np.exp(-1j * np.radians(phi)))), 0, atol=1e-12)
    assert np.allclose(np.abs(B - 0.3), 0.35, atol=1e-12)


def test_a_pin_that_joins_nothing_is_still_refused_elsewhere():
    text = TRIANGLE.replace('shape = { E = [0.15, 0.1] }\n', '')
    with pytest.raises(GraphplanError, match="joint 'E' joins nothing"):
        loads(text)
