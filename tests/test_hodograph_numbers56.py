"""Review55 #14: a hodograph's position number stood 6 mm from its point with no leader (the beam
pump's R34 "4"; the stop-56 six-bar's R12/R01 "5", R23 "9" 5.5–6 mm off) — read as no point's, or as
a neighbour's. Each number now stands as a diagram's (``labels.place_beside``): beside its own point
within 2.5 mm (``charts.LEAD_FROM_MM``), no other position's point much nearer, or at the end of a leader
that starts at its own point.

The points are found independently of the drawing: the reaction at each position (the study's
kinetostatics) divided by the hodograph's μR, matched to the number's text."""
from __future__ import annotations

import pytest

from conftest import scene_study
from review_scenes import BEAM_PUMP55, FRC56_PUSHER

NEARER_MM = 1.0       # … and no other point nearer it by more than this (two points 2 mm apart share its spot)
OWN_MM = 2.5 + 0.05     # charts.LEAD_FROM_MM: farther, a number gets a leader to its point


def _gap(box, z: complex) -> float:
    dx = max(box[0] - z.real, 0.0, z.real - box[2])
    dy = max(box[1] - z.imag, 0.0, z.imag - box[3])
    return (dx * dx + dy * dy) ** 0.5


@pytest.mark.slow
@pytest.mark.parametrize("text", [FRC56_PUSHER, BEAM_PUMP55], ids=["pusher56", "beam_pump55"])
def test_each_hodograph_number_stands_by_its_own_point(text):
    from graphplan.drawing.charts import hodograph_record, turn
    t = turn(scene_study(text))
    for key in t.ks.reactions:
        f = t.ks.reactions[key].force
        rec = hodograph_record(t, key, 60.0, lang="uk")
        mu = rec.scales["mu_R"]
        where = {pos: complex(f[k]) / mu for k, pos in t.position_index()}
        leaders = [[complex(*p) for p in q.points] for q in rec.items
                   if q.kind == "segment" and q.role == "label" and not q.step.endswith("detail")]
        numbers = [q for q in rec.items if q.kind == "text" and q.size < 3.0 and not q.step.endswith("detail")
                   and q.text.replace("–", "").isdigit()]
        assert len(numbers) >= 6, key
        for q in numbers:
            first = int(q.text.split("–")[0])
            own = where[first]
            box = q.ink()
            others = [z for p, z in where.items() if abs(z - own) > 0.6]
            beside = _gap(box, own) <= OWN_MM and all(_gap(box, z) > _gap(box, own) - NEARER_MM for z in others)
            led = any(min(abs(e - own) for e in ld) < 1.3 and min(_gap(box, e) for e in ld) < 1.5 for ld in leaders)
            assert beside or led, (key, q.text, round(_gap(box, own), 2))
