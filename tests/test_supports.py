"""A fixed pivot's support on the position plan (review5 #3: the crank's pivot O drawn tilted ~60°,
its bar and hatching among the crank's twelve lines, its legs hidden). The support stands where no
link line of any position passes, else straight down (or as near it as the thick positions' links
leave free) with the thin lines interrupted under it: no drawn link line crosses its bar or hatching."""
from __future__ import annotations

from pathlib import Path

import pytest
from shapely.geometry import LineString

from conftest import scene_study
from graphplan.drawing.plans import position_record
from graphplan.graphic.plans import build_plans
from review_scenes import PRESS4 as SIXBAR_PRESS  # the reviews' presses: the fourth's six-bar,
from review_scenes import PRESS_EN as OFFSET_PRESS  # the fifth's desaxial crank-slider

EXAMPLES = Path(__file__).resolve().parent.parent / "examples"


def _support_crossings(text: str, mu_l=None, accel=None) -> tuple[list, list]:
    plans = build_plans(scene_study(text), accel=accel, mu_l=mu_l)
    rec = position_record(plans, lettered=False)
    symbol = [q for q in rec.items if q.kind == "segment" and q.step.startswith("support ") and q.role == "hatch"]
    bars = [q for q in rec.items if q.kind == "segment" and q.step.startswith("support ") and q.role == "frame"
            and abs(complex(*q.points[0]) - complex(*q.points[1])) > 9.0]     # the 10 mm bar, not the legs
    links = [LineString(q.points) for q in rec.items
             if q.kind in ("segment", "polyline") and q.role in ("link", "projection") and len(q.points) > 1]
    crossed = [(q.step, q.points) for q in symbol + bars if any(LineString(q.points).intersects(k) for k in links)]
    return symbol, crossed


@pytest.mark.parametrize("text, mu_l, accel", [(OFFSET_PRESS, 0.002, [2, 7]), (SIXBAR_PRESS, 0.004, [5])],
                         ids=["offset press", "six-bar press"])
def test_reviewed_supports_cross_no_link(text, mu_l, accel):
    symbol, crossed = _support_crossings(text, mu_l, accel)
    assert symbol, "no support drawn"
    assert not crossed, crossed


@pytest.mark.parametrize("name", ["crank_slider", "four_bar", "shaper"])
def test_example_supports_cross_no_link(name):
    symbol, crossed = _support_crossings((EXAMPLES / f"{name}.toml").read_text(encoding="utf-8"))
    assert symbol and not crossed, crossed


def test_a_rocker_pivot_with_room_stands_straight_down():
    """The six-bar's O2: its rocker swings over the upper half only, so its support stands straight
    down (the bar level) — where no line of any position passes."""
    plans = build_plans(scene_study(SIXBAR_PRESS), accel=[5], mu_l=0.004)
    rec = position_record(plans, lettered=False)
    bar = [q for q in rec.items if q.step == "support O2" and q.role == "frame" and q.kind == "segment"
           and abs(complex(*q.points[0]) - complex(*q.points[1])) > 9.0]
    assert bar and abs(bar[0].points[0][1] - bar[0].points[1][1]) < 1e-6
