"""``[positions] start = "working"`` / ``"idle"`` follow the scene's ``working_stroke`` rule (issue 32,
stop 51): position 0 is the extreme that begins the stroke the force analysis and the sheets call the
working one ("idle": the extreme that ends it), not always the slow stroke's. Checked on an offset
crank-slider against its closed form x_B = r·cos φ + √(l² − (r·sin φ − e)²): its extremes are the
stretched and folded dead centres, sin φ_max = e/(l + r) and sin φ_min = −e/(l − r) (φ_min in the
crank's left half), so the two strokes take different crank turns."""
from __future__ import annotations

import math

import numpy as np
import pytest

from conftest import scene_study

R, L, E = 0.05, 0.2, 0.04          # m: an offset large enough for 186,3° against 173,7°

SCENE = '''title = "Зміщений кривошипно-повзунний механізм (перевірка 51)"
title_en = "Offset crank-slider (check 51)"
[frame.points]
O = [0, 0]
[frame.guides]
x = {{ through = [0, {e}], angle_deg = 0 }}
[crank]
name = "OA"
pivot = "O"
pin = "A"
length = {r}
rpm = 120
direction = "{sense}"
[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = {l}
[[link]]
name = "B"
number = 3
joints = ["B"]
slides_on = "x"
[branch]
B = 1
[positions]
count = 12
start = "{start}"
working_stroke = "{rule}"
'''


def x_b(phi_deg: float) -> float:
    """The slider's closed-form position along the guide."""
    phi = math.radians(phi_deg)
    return R * math.cos(phi) + math.sqrt(L ** 2 - (R * math.sin(phi) - E) ** 2)


PHI_MAX = math.degrees(math.asin(E / (L + R))) % 360.0            # stretched: x_B = √((l + r)² − e²)
PHI_MIN = (180.0 + math.degrees(math.asin(E / (L - R)))) % 360.0  # folded: x_B = √((l − r)² − e²)


def truth(rule: str, sense: int) -> tuple[float, float, int]:
    """The working stroke's first extreme, its crank turn and the slider's direction along it
    (+1 toward x_max), from the closed-form dead centres: from max to min the crank turns
    (φ_min − φ_max)·sense mod 360°."""
    down = ((PHI_MIN - PHI_MAX) * sense) % 360.0
    to_min = {"to_min": True, "to_max": False, "slow": down > 180.0, "fast": down < 180.0}[rule]
    return (PHI_MAX, down, -1) if to_min else (PHI_MIN, 360.0 - down, +1)


def _close(a: float, b: float) -> float:
    return abs((a - b + 180.0) % 360.0 - 180.0)


@pytest.mark.parametrize("sense", ["ccw", "cw"])
@pytest.mark.parametrize("rule", ["slow", "fast", "to_min", "to_max"])
def test_position_0_begins_the_working_stroke_by_the_scenes_rule(rule, sense):
    from graphplan.exact.kinetostatics import working_stroke
    s = 1 if sense == "ccw" else -1
    start, turn, direction = truth(rule, s)
    assert abs(turn - 180.0) > 5.0                   # the strokes differ: the rule decides
    st = scene_study(SCENE.format(r=R, l=L, e=E, sense=sense, start="working", rule=rule))
    assert _close(st.phi0, start) < 1e-6
    # from position 0 the slider moves in the working direction until the other extreme, a crank
    # turn equal to the working stroke's, which the force analysis calls working throughout
    ahead = st.phi0 + s * np.array([1.0, turn / 2, turn - 1.0])
    assert all(direction * (x_b(p) - x_b(st.phi0)) > 0 for p in ahead)
    assert _close(st.phi0 + s * turn, PHI_MIN if direction < 0 else PHI_MAX) < 1e-6
    assert working_stroke(st, np.concatenate([[st.phi0], ahead])).all()
    assert not working_stroke(st, st.phi0 + s * np.array([turn + 1.0, 359.0])).any()
    # "idle": the other extreme, which the working stroke ends at
    idle = scene_study(SCENE.format(r=R, l=L, e=E, sense=sense, start="idle", rule=rule))
    assert _close(idle.phi0, start + s * turn) < 1e-6
