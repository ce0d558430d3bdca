"""Stop 61 (frc61b, issue 32): on the one-sheet A1 force sheet no main drawing (the scheme, the
groups, their force plans, the Zhukovsky lever) is left far under its target while an auxiliary one
(the acceleration plan, the charts, the hodographs) is grown past its own — LINK61's sheet drew its
scheme and groups at 1:10, a quarter of their 250 mm target, beside an acceleration plan at 2.3 times
its 120 mm (p a = 276 mm, the sheet's largest drawing).

The rule (``forces.aux_allowed``): an auxiliary drawing grows past its target by the one step that
takes it there, and further only while it stays within ``AUX_OVER`` = 2 times the poorest main
drawing's size against its target. So on the composed sheet an auxiliary drawing at r > 1 of its
target is either at that first step (the step before it under the target) or the poorest main
drawing is at least r / 2 of its own. The acceleration plan's size is taken from the drawing's own
numbers (p a = a_A / μa against 120 mm, a_A = ω1² · l_OA for a crank turning evenly), not from the
composition's model.

Checked on an offset crank-slider of a long stroke made here from its dimensions and on a crank-rocker
driving a slider through a rod off the rocker (tests/review_scenes.py FRC61B_ROCKER_SLIDER), not on LINK61."""
from __future__ import annotations

import pytest

from conftest import scene_plan
from review_scenes import FRC61B_ROCKER_SLIDER

FRACTION = 0.5      # 1 / AUX_OVER: the poorest main drawing against an auxiliary one grown past its first step


def crank_slider(r: float, lam: float, e: float, rpm: float, force: float) -> str:
    return f'''
title = "Кривошипно-повзунний механізм"
title_en = "Crank-slider mechanism"
designation = "ТММ.61.01.000"

[frame.points]
O = [0, 0]

[frame.guides]
x = {{ through = [0, {e}], angle_deg = 0 }}

[crank]
name = "OA"
pivot = "O"
pin = "A"
length = {r}
rpm = {rpm}
points = {{ S1 = 0.0 }}

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = {r * lam}
points = {{ S2 = 0.35 }}

[[link]]
name = "B"
number = 3
joints = ["B"]
slides_on = "x"
mass = 8

[branch]
B = 1

[positions]
count = 12
start = "max"
accel = [2]
force_phi_deg = 60

[loads]
g = 9.81
mass_per_length = 25
inertia_factor = 0.1

[[force]]
point = "B"
magnitude = {force}
stroke = "working"
direction = "oppose"
'''


SCENES = {
    "crank-slider": crank_slider(r=0.12, lam=3.6, e=0.03, rpm=150, force=1500),
    "rocker-slider": FRC61B_ROCKER_SLIDER,    # a 60-mm crank, rocker 0.15 m extended to C, rod 0.3 m, 100 rpm, 700 N
}


@pytest.mark.slow
@pytest.mark.parametrize("name", sorted(SCENES))
def test_no_auxiliary_drawing_grows_past_its_target_over_a_poor_main_one(name):
    from graphplan.sheets import forces as sf
    from graphplan.sheets.compose import FACTORS, coarser
    text = SCENES[name]
    p, nat, dr = scene_plan(text, "forces", "A1", precision=0.5)
    assert p.shape != "set" and p.sheets == 1            # A1 is one sheet
    fams = nat.families
    mech = dr.st.mech
    # the acceleration plan's size from its own numbers: p a = ω1² l_OA / μa against its 120 mm
    assert mech.crank.epsilon == 0
    pa = mech.omega1 ** 2 * mech.crank.length / p.mu["acceleration"]
    r_acc = pa / sf.TARGETS["acceleration"]
    assert r_acc == pytest.approx(fams["acceleration"].rel(p.mu["acceleration"]), rel=1e-6)
    # the poorest main drawing: the scheme, the groups and force plans (each at its own scale too),
    # the lever — every scale the sheet prints
    mains = [fams[n].rel(p.mu[n]) for n in ("scheme", "groups", "forces", "lever")]
    mains += [fams["groups"].rel(m) for _, m in sf.group_scales(p.mu)]
    mains += [fams["forces"].rel(m) for _, m in sf.plan_scales(p.mu)]
    low = min(mains)
    for fam in ("acceleration", "charts"):
        r = fams[fam].rel(p.mu[fam])
        if r <= 1.0 + 1e-9:
            continue
        # the step before: the series' next coarser μa; the charts' next smaller size factor (1 is one)
        if fam == "acceleration":
            before = coarser(p.mu[fam])
        else:
            before = 1.0 / max(k for k in FACTORS if k < 1.0 / p.mu[fam] * (1 - 1e-9))
        first = fams[fam].rel(before) < 1.0 - 1e-9       # the one step that took it past its target
        assert first or low >= FRACTION * r * (1 - 1e-9), (fam, r, low, p.mu)
