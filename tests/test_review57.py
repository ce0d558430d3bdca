"""Stop 57's blind review, its own scenes checked against its own code (numpy/scipy, no graphplan):
the English walking-beam conveyor's balancing moment by the power balance (−59.1464 N·m at 100° of
crank turn from the start of the working swing; the force plans and the lever within the lab's 5 %),
and the 15/28 "auto" pair with the type-B train 17/40/20/77 by the textbook's closed forms (the rule's
shifts 0.6/0.65 reproduced by the reviewer; αw 26.4991°, aw 112.876 mm, εα 1.2033; Willis)."""
from __future__ import annotations

import math
import tomllib

import pytest

from conftest import scene_force_plans
from review_scenes import CONVEYOR_EN57, GEARS_REVIEW57
from test_gears_review55 import _pair

LAB_LIMIT = 5.0


def test_the_conveyors_balancing_moment_is_the_reviewers_power_balance():
    fp = scene_force_plans(CONVEYOR_EN57, mu_l=0.004, mu_F=10.0)
    assert fp.analytic == pytest.approx(-59.1464, abs=2e-4)
    for value in (fp.balancing, fp.lever.balancing):
        assert abs(100 * (value + 59.1464) / 59.1464) < LAB_LIMIT, value


def test_the_review_pair_and_train_agree_with_the_closed_forms():
    from graphplan.exact.gears import solve
    from graphplan.model.gears import build
    sol = solve(build(tomllib.loads(GEARS_REVIEW57), "review57"))
    p, ref = sol.pair, _pair(15, 28, 5.0, 0.6, 0.65)
    assert math.degrees(p.alpha_w) == pytest.approx(math.degrees(ref["alpha_w"]), abs=1e-6)
    assert math.degrees(p.alpha_w) == pytest.approx(26.4991, abs=1e-4)          # the reviewer's
    assert p.aw * 1000 == pytest.approx(ref["aw"], abs=1e-6) and ref["aw"] == pytest.approx(112.876, abs=1e-3)
    assert p.eps == pytest.approx(ref["eps"], abs=1e-9) and ref["eps"] == pytest.approx(1.2033, abs=1e-4)
    t, w1 = sol.train, 960 * math.pi / 30
    u = 1 + 40 * 77 / (17 * 20)                                                  # Willis, type B
    assert t.ratio == pytest.approx(u, rel=1e-12)
    assert t.omega["H"] == pytest.approx(w1 / u, rel=1e-12)
    assert t.omega["2"] == pytest.approx(w1 / u - (w1 - w1 / u) * 17 / 40, rel=1e-12)   # −28.484 rad/s
