"""Stop 50's speed work: the program's short cuts give the answers of the long ways they replace."""
from __future__ import annotations

import pytest

from graphplan.exact import cam as C
from graphplan.model import cam as MC
from graphplan.model.bounds import parse_toml
from review_scenes import CAM47, CAM49


def _cam(text: str, name: str):
    return MC.build(parse_toml(text, name), name)


@pytest.mark.parametrize("text", [CAM49, CAM47], ids=["CAM49", "CAM47"])
def test_the_best_offset_is_the_least_radius_that_bracketing_the_pressure_angle_finds(text):
    """The closed form's offset e* (tg ϑ = (ds/dφ − e)/(s0 + s)): ``min_base_radius`` — ϑ itself
    bracketed, independent of the closed form — gives the same R0 there, and a larger one 0.1 mm
    either side."""
    cam = _cam(text, "cam")
    e, r0 = C.best_offset(cam)
    assert C.min_base_radius(cam, e) == pytest.approx(r0, rel=1e-9)
    for step in (-1e-4, 1e-4):
        assert C.min_base_radius(cam, e + step) > r0 * (1 + 1e-7)


@pytest.mark.slow
@pytest.mark.parametrize("law", ["parabolic", "cosine", "cycloidal", "linear", "trapezoidal"])
def test_the_best_offset_is_the_brute_searchs(law):
    """The closed form against the search it replaced (min_base_radius at every trial offset)."""
    cam = _cam(CAM49.replace('laws = { rise = "cosine"', f'laws = {{ rise = "{law}"'), law)
    e, r0 = C.best_offset(cam)
    e_b, r0_b = C.best_offset_searched(cam)
    assert abs(e - e_b) < 1e-9 and round(e, 4) == round(e_b, 4)
    assert r0 == pytest.approx(r0_b, rel=1e-9)
