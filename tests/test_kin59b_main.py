"""The A1 kinematics sheet's position plan, its main drawing (LAYOUT.md: the largest drawing, μl by
its zone), drawn at the largest standard scale its zone allows — the blind review of stop 59 (finding
1): the drag-link six-bar (uk) and the Watt-II chain (en) drew it at 1:5 in a corner (cranks 20 and
12 mm, twelve positions' labels piled on leaders), smaller than either acceleration plan's cell
(158 × 101 mm against 114 × 169; 131 × 121 against the Watt chain's), beside full-length diagrams.
``main_larger`` drew the diagrams shorter only for a position plan twice as large with every other
plan kept at 0.9: the drag-link's L × 0.9 gave 1:4 (1.25 times), the Watt chain's L × 0.8 gave 1:2
with π a 55.1 → 45.1 mm (0.82, still legible). Now, where no length does that, a standard step
larger with every plan legible (``STEP``: the composition's score's own order).

Cases: the review's two scenes and mechanisms generated from them (the whole geometry scaled, the
speed changed), each composed by arithmetic (no sheet drawn; 20–40 s of CPU each: slow)."""
from __future__ import annotations

import re
from dataclasses import replace

import pytest

import review_scenes
from conftest import scene_study
from graphplan.drawing.layout import Leaf
from graphplan.sheets.compose import SheetOptions
from graphplan.sheets.form import form
from graphplan.sheets.kinematics import plan
from graphplan.sheets.kinlayout import MAIN, composed_fits, diagrams_size


def generated(text: str, scale: float, rpm: float) -> str:
    """A mechanism made from a scene: every length and frame point times ``scale``, the crank at
    ``rpm`` (the same chain, another size and speed)."""
    def times(m: re.Match) -> str:
        return f"{float(m.group(0)) * scale:.6g}"
    out = []
    for line in text.splitlines():
        if re.match(r"\s*(length|O\d|shape|x = \{ through)\s*=?", line) and "mass" not in line:
            line = re.sub(r"-?\d+\.\d+|(?<![\w.])-?\d+(?![\w.])", times, line.split("#")[0])
        elif re.match(r"\s*rpm\s*=", line):
            line = f"rpm = {rpm:g}"
        out.append(line)
    return "\n".join(out) + "\n"


CASES = {
    "DRAGLINK_REVIEW59": review_scenes.DRAGLINK_REVIEW59,
    "WATT_EN_REVIEW59": review_scenes.WATT_EN_REVIEW59,
    "draglink x1.4, 60 rpm": generated(review_scenes.DRAGLINK_REVIEW59, 1.4, 60),
    "watt x0.75, 150 rpm": generated(review_scenes.WATT_EN_REVIEW59, 0.75, 150),
}


def test_a_generated_mechanism_is_the_scene_scaled():
    """The generator scales what it says and nothing else (the crank 0.10 m → 0.14 m, O2 0.06 → 0.084,
    the slider's mass kept)."""
    st = scene_study(CASES["draglink x1.4, 60 rpm"])
    base = scene_study(review_scenes.DRAGLINK_REVIEW59)
    assert st.mech.crank.length == pytest.approx(1.4 * base.mech.crank.length)
    assert abs(st.mech.omega1) == pytest.approx(60 * 2 * 3.141592653589793 / 60)
    assert "mass = 8" in CASES["draglink x1.4, 60 rpm"]


@pytest.mark.slow
@pytest.mark.parametrize("name", list(CASES))
def test_the_a1_position_plan_takes_its_zones_largest_standard_scale(name):
    """On the A1 kinematics sheet the position plan is drawn at the largest standard scale its zone
    allows: one step larger (the series' next, 1:5 → 1:4 → 1:2.5 → 1:2) the composition as chosen
    (its shape, grids, table columns, the other drawings' scales) no longer fits the field — or it is
    at its target already; and it is not the smallest drawing: its box (lettering and caption
    included) is larger than any velocity or acceleration plan's cell."""
    st = scene_study(CASES[name])
    f = form("A1")
    p, nat, dr = plan(st, f, SheetOptions(sheet="kinematics"))
    pos = nat.families["position"]
    mu_l = p.mu["position"]
    bigger = pos.finer(mu_l)
    D = Leaf("diagrams", *diagrams_size(dr, nat, p.diagrams))
    assert composed_fits(nat, f, p, D), (name, p)            # the check's own arithmetic holds the plan
    assert bigger is None or pos.rel(bigger) > MAIN + 1e-9 or not composed_fits(
        nat, f, replace(p, mu={**p.mu, "position": bigger}), D), (name, mu_l, bigger, p)
    area = lambda w, h: w * h  # noqa: E731
    main = area(*pos.size(mu_l))
    for fam in ("velocity", "acceleration"):
        if nat.count[fam]:
            assert main > area(*nat.families[fam].size(p.mu[fam])), (name, fam, p.mu)
