"""Hodographs numbered so that each position reads (issue 32 #3, review4 #11, review5 #6): where the
idle stroke's reactions crowd by the pole (points closer than 1.5 mm at the hodograph's μR) the spot
is ringed "I" and drawn again at a finer series μR (GOST 2.305's extension element) — in a free
corner of the hodograph's own field, so that its cell does not grow — each of its points numbered
there; a number is shared ("3–4") only by consecutive points within the ruler's 0.5 mm at the scale
they are drawn. Checked against the exact reactions, not against the drawing's own numbers."""
from __future__ import annotations

import pytest

from conftest import scene_study
from review_scenes import PRESS4


@pytest.fixture(scope="module")
def turn():
    from graphplan.drawing.charts import turn as make
    return make(scene_study(PRESS4))


def _runs(text: str) -> list[int]:
    a, _, b = text.partition("–")
    return list(range(int(a), int(b or a) + 1))


def test_crowded_points_are_numbered_in_a_detail_within_the_field(turn):
    from graphplan.drawing.charts import hodograph_record, series_value
    from graphplan.graphic.record import Record
    rounds = {round(series_value(m, k), 9) for k in range(-2, 6) for m in (1.0, 2.0, 2.5, 4.0, 5.0)}
    idx = {pos: k for k, pos in turn.position_index()}
    details = 0
    for key in ("R34", "R45"):                     # the press4's rocker-side reactions: 0–3, 9–11 by the pole
        # 65 mm: μR 100 N/mm (62 mm); at 60 mm the series without GOST's 150 (review 59 #2) draws them at
        # 200 N/mm, 31 mm, where R45's field has no corner for its detail: its crowded points share "0–2"
        rec = hodograph_record(turn, key, 65.0, lang="en")
        f = turn.ks.reactions[key].force
        mu = rec.scales["mu_R"]
        mu_d = rec.scales.get("mu_R detail")
        assert mu_d is not None and round(mu_d, 9) in rounds and 2 * mu_d <= mu, (key, mu, mu_d)
        details += 1
        texts = [(q.text, q.step.endswith("detail")) for q in rec.items
                 if q.kind == "text" and q.text.replace("–", "").isdigit()]
        assert sorted(n for t, _ in texts for n in _runs(t)) == list(range(turn.count)), texts
        for t, inside in texts:
            run = _runs(t)
            for a, b in zip(run, run[1:]):        # shared only where the ruler cannot tell them apart
                assert abs(f[idx[b]] - f[idx[a]]) / (mu_d if inside else mu) <= 0.5 + 1e-9, (key, t)
        # every position whose point lies within 1.5 mm of another's at μR is numbered in the detail
        pts = {pos: f[k] / mu for k, pos in turn.position_index()}
        crowded = {p for p, w in pts.items() if any(q != p and abs(w - v) < 1.5 for q, v in pts.items())}
        in_detail = {n for t, inside in texts if inside for n in _runs(t)}
        assert crowded <= in_detail, (key, crowded, in_detail)
        # the detail keeps to the room the hodograph takes without it (its field, its lettering)
        rest = Record(items=[q for q in rec.items if not q.step.endswith("detail")]).bounds()
        lines = Record(items=[q for q in rec.items if q.step.endswith("detail") and q.kind != "text"]).bounds()
        assert (rest[0] - 1e-6 <= lines[0] and lines[2] <= rest[2] + 1e-6
                and rest[1] - 1e-6 <= lines[1] and lines[3] <= rest[3] + 1e-6), (key, rest, lines)
    assert details == 2
