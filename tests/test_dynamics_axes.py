"""Review 8 of the dynamics sheets: every axis of every diagram graduated with values (the energy–mass
diagram's I* axis had ticks and no values), the values of an axis all on one side of it (the
shaper's M axis lettered 500 and 750 on opposite sides), none skipped within the run lettered, and
none touching a line or other lettering — on the press, the shaper and the slotter, at the A1
sheet's construction (L = 330 mm), the diagrams drawn as the sheet draws them."""
from __future__ import annotations

import pytest

from conftest import example, scene_study

AXES = {"moments": [("M graduation", True), ("A graduation", True)], "energy": [("ΔT graduation", True)],
        "wittenbauer": [("I* graduation", False), ("ΔT graduation", True)],
        "inertia": [("I* graduation", False)], "ΔT(φ)": [("ΔT graduation", True)],
        "I*(φ)": [("I*_m graduation", True)]}


@pytest.fixture(scope="module", params=["press", "shaper", "slotter"])
def drawn(request):
    from graphplan.drawing.flywheel import (energy_projected, energy_record, inertia_record, inertia_turned,
                                            moments_record, wittenbauer_record)
    from graphplan.exact.dynamics import analyse
    from graphplan.graphic.flywheel import redrawn
    from review_scenes import PRESS4
    st = scene_study(PRESS4) if request.param == "press" else example(request.param)
    f = redrawn(analyse(st, None), None, 0.5, L=330.0, size=1.0, given=None)
    return f, {"moments": moments_record(f, "uk"), "energy": energy_projected(f, "uk", 150.0, 170.0),
               "wittenbauer": wittenbauer_record(f, "uk", projections=(-20.0, -10.0)),
               "inertia": inertia_turned(f, "uk", 150.0, 10.0),
               "ΔT(φ)": energy_record(f, "uk"), "I*(φ)": inertia_record(f, "uk")}


def _value(text: str) -> float:
    return float(text.replace(",", ".").replace("−", "-"))


def test_every_axis_carries_values_on_one_side_of_it(drawn):
    f, recs = drawn
    for name, axes in AXES.items():
        rec = recs[name]
        for step, vertical in axes:
            texts = [p for p in rec.items if p.kind == "text" and p.step == step]
            ticks = [p for p in rec.items if p.kind == "segment" and p.step == step]
            assert len(texts) >= 2, (name, step, [p.text for p in texts])
            # the axis: the line the ticks start from (x = 0 for an ordinate axis, y of the I* axis)
            axis = {round(p.points[0][0 if vertical else 1], 6) for p in ticks}
            assert len(axis) == 1, (name, step, axis)
            at = axis.pop()
            sides = {(0.5 * (t.ink()[0] + t.ink()[2]) if vertical else 0.5 * (t.ink()[1] + t.ink()[3])) > at
                     for t in texts}
            assert len(sides) == 1, (name, step, "values on both sides of the axis")
            values = sorted(_value(t.text) for t in texts)
            gaps = {round(b - a, 9) for a, b in zip(values, values[1:]) if a * b > 0}   # 0 is the origin's
            assert len(gaps) <= 1, (name, step, values)


def test_no_value_touches_a_line_or_other_lettering(drawn):
    from graphplan.drawing.labels import collisions
    f, recs = drawn
    for name, rec in recs.items():
        values = {p.text for p in rec.items if p.kind == "text" and p.step.endswith("graduation")}
        hits = [c for c in collisions(rec) if any(c.startswith(repr(v)) for v in values)]
        assert hits == [], (name, hits[:3])
