"""Stop 52 (a teacher's blind grading): a wedge press — an offset crank-slider drives a wedge 3 along the
frame; a block 4 in the wedge's slot at 150° is pinned at C to the ram 5 on a vertical frame guide
(I(0-1) → II(2-3) ВВП → II(4-5) ПВП).

The point C slides twice: the block along the moving wedge and the ram along its fixed guide. The
output "C" (and the force's point C) means the ram's absolute motion — what the press does — not
the block's slide along the wedge, which is twice as long and points another way.
Truth: the offset crank-slider x_B = r·cos φ + √(l² − (r·sin φ + e)²) and the wedge's slot line
through B + (0,14; 0) at 150°, which the ram's vertical line x = 0,40 cuts at y_C.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from conftest import scene_study
from review_scenes import WEDGE52

R, L, E = 0.05, 0.22, 0.03      # the crank, the rod, the wedge guide's offset below O, m
U, SLOT, X_RAM = 0.14, math.radians(150.0), 0.40


@pytest.fixture(scope="module")
def st():
    return scene_study(WEDGE52)


def _y_c(phi_deg: np.ndarray) -> np.ndarray:
    """The ram's height: the slot line through (x_B + u, −e) at 150° cut by x = 0,40."""
    phi = np.radians(phi_deg)
    x_b = R * np.cos(phi) + np.sqrt(L ** 2 - (R * np.sin(phi) + E) ** 2)
    return -E + (X_RAM - x_b - U) * math.tan(SLOT)


def test_the_output_c_is_the_ram_on_its_fixed_guide(st):
    """The slide keyed by the point's own name is the ram's, along the frame guide."""
    phi = np.linspace(0.0, 360.0, 73)
    slide = st.solve(phi).slides[st.output.name]
    assert (st.output.kind, st.output.name) == ("slide", "C")
    assert st.mech.links[slide.slider].number == 5
    from graphplan.exact.positions import point_slider
    assert point_slider(st.mech, "C") == slide.slider          # the sheet's sign note names its guide
    # its travel is the ram's: y_C from the closed form, up to the guide's origin
    t = st.output.value(st.solve(phi))
    y = _y_c(phi)
    assert np.ptp(t) == pytest.approx(np.ptp(y), abs=1e-9)
    assert np.allclose(t - t[0], y - y[0], atol=1e-9)


def test_the_stroke_is_the_rams(st):
    """H = (√((l + r)² − e²) − √((l − r)² − e²))·tg 30° = 58,31 mm, not the slot's 116,6 mm."""
    h = (math.sqrt((L + R) ** 2 - E ** 2) - math.sqrt((L - R) ** 2 - E ** 2)) * math.tan(math.radians(30))
    t = st.output.value(st.solve(np.linspace(0.0, 360.0, 1441)))
    assert np.ptp(t) == pytest.approx(h, rel=1e-5)
    assert h == pytest.approx(0.05831, abs=1e-5)


def test_position_0_and_the_extremes_are_the_rams(st):
    """Position 0 is the ram's lowest point (``start = "min"``): dy_C/dφ = 0 there, y_C least."""
    ys = _y_c(np.linspace(0.0, 360.0, 14401))
    assert _y_c(np.array([st.phi0]))[0] == pytest.approx(ys.min(), abs=1e-8)


def test_the_block_keeps_its_slide_along_the_wedge(st):
    """The relative slide of the block 4 along the slot is still there for the Coriolis term and the
    plans — under its own key: v_C = v_B + v_C4C3 with v_C vertical, v_B horizontal and v_C4C3 along
    the slot at 150° gives v_C = v_C4C3·sin 150°, so |v_C4C3| = |v_C| / sin 30°."""
    kin = st.solve(np.array([st.phi0 + 90.0]))
    rel = next(s for s in kin.slides.values() if st.mech.links[s.slider].number == 4)
    ram = kin.slides["C"]
    assert rel.point == "C" and rel.carrier == "B"
    assert abs(rel.v[0]) == pytest.approx(abs(ram.v[0]) / math.sin(math.radians(30)), rel=1e-9)


def test_the_wedge_is_drawn_as_one_body(st):
    """On the drawn (thick) position the wedge 3 is one rigid body: its block's joint B joined to both
    ends of its slot, which runs at the slot's angle (150°) — not a slot floating apart from its block."""
    from graphplan.drawing.plans import position_record
    from graphplan.graphic.plans import build_plans
    pos = position_record(build_plans(st))
    segs = [tuple(complex(*p) for p in it.points) for it in pos.items
            if it.kind == "segment" and it.layer == "mechanism"]
    ends = {frozenset(s) for s in segs}
    bodies = []
    for i, (x, p) in enumerate(segs):
        for x2, q in segs[i + 1:]:
            if abs(x - x2) < 1e-9 and frozenset((p, q)) in ends and abs(q - p) > 20.0:
                bodies.append(math.degrees(math.atan2((q - p).imag, (q - p).real)) % 180.0)
    assert any(abs(a - 150.0) < 1e-6 for a in bodies), bodies
