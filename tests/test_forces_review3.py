"""The third review's force sheet of a loom's four-bar with a resistance moment on the rocker
(review3, items 2, 5, 7, 10, 11): the rocker's angle named φ3 on the resistance chart, the balancing
moment's chart at a round μφ with its ordinate valued up to the peak, the lever's pole lettered with
the fixed pivots' images, the group drawn freed from the frame, the hodographs' jump marked."""
from __future__ import annotations

import math

import numpy as np
import pytest

from conftest import example, scene_study
from test_moment_load import scene


@pytest.fixture(scope="module")
def rocker():
    return scene_study(scene("3", "oppose").replace('stroke = "both"', 'stroke = "working"'))


@pytest.fixture(scope="module")
def rocker_turn(rocker):
    from graphplan.drawing.charts import turn
    return turn(rocker)


def _texts(rec) -> list[str]:
    return [p.text for p in rec.items if p.kind == "text"]


def test_a_rockers_resistance_chart_names_its_angle_phi3(rocker_turn):
    """"s, °" and μ_s named the rocker's angle: a rocking output's path is φ3 with μ_φ; a slider's
    stays s with μ_s."""
    from graphplan.drawing.charts import resistance_record, turn
    texts = _texts(resistance_record(rocker_turn, lang="en"))
    assert "φ_{3}, °" in texts
    assert not any(t.startswith("s,") or "μ_s" in t for t in texts), texts
    assert any("μ_φ = " in t and "φ_{3}" in t for t in texts), texts
    slider = _texts(resistance_record(turn(example("shaper")), lang="en"))
    assert any(t.startswith("s, ") for t in slider) and any("μ_s = " in t for t in slider)
    assert not any("μ_φ" in t for t in slider)


ROUND = {1.0, 1.5, 2.0, 2.5, 4.0, 5.0, 7.5}


def _mantissa(v: float) -> float:
    return round(v / 10.0 ** math.floor(math.log10(v) + 1e-12), 9)


@pytest.mark.parametrize("width", [252.0, 180.0, 160.0, 300.0])
def test_the_balancing_moment_chart_takes_a_round_mu_phi_and_values_its_axis(rocker_turn, width):
    """μφ = 1.786 °/mm was no series value and the M axis read only 0 and 40 under a peak of 83:
    μφ is a round value whose turn fills 80–100 % of the length, and the ordinate's values at one
    round step, each at its tick's height times μM, reach past the exact peak and below the trough."""
    from graphplan.drawing.charts import moment_record
    rec = moment_record(rocker_turn, width, 70.0, "en")
    mu_phi, mu = rec.scales["mu_phi"], rec.scales["mu_M"]
    assert _mantissa(mu_phi) in ROUND, mu_phi
    assert 0.8 * width - 1e-9 <= 360.0 / mu_phi <= width + 1e-9
    curve = next(p for p in rec.items if p.kind == "polyline")
    assert max(x for x, _ in curve.points) == pytest.approx(360.0 / mu_phi)
    values = sorted((float(p.text.replace("−", "-")), p.points[0][1] + 1.2) for p in rec.items
                    if p.kind == "text" and p.anchor == "end")
    assert len(values) >= 4, values
    for v, y in values:
        assert y * mu == pytest.approx(v, abs=1e-9)
    steps = {round(b[0] - a[0], 9) for a, b in zip(values, values[1:])}
    assert len(steps) == 1 and _mantissa(steps.pop()) in {1.0, 2.0, 5.0}
    m = rocker_turn.ks.balancing
    assert values[-1][0] >= m.max() - 1e-9 and values[0][0] <= min(0.0, m.min()) + 1e-9
