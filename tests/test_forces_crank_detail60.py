"""Review 60 #2: the inclined-guide feeder's crank plan (μF = 5 N/mm) is a sliver where R21 ≈ R01, its
Φ1 (5,4 N) laid off 1 mm at G1's tip. Its detail drew R01, G1, R21 and left Φ1 unnamed (2.5 mm there,
under the plan's 3-mm lettering bound), and the caption said «Φ1 < 1 мм» of a side the notes read 1 мм.
Checked against independent truth: the polygon closes with every force the group carries in it, Φ1's
side is −m1·a_S1 at μF within the ruler, the detail names each side, the caption's bound exceeds each
short side's reading."""
from __future__ import annotations

import math
import re

import pytest

from conftest import scene_study
from review_scenes import FRC60B_INCLINE


@pytest.fixture(scope="module")
def crank():
    from graphplan.drawing.forces import polygon_record
    from graphplan.sheets import forces as sf
    from graphplan.sheets.compose import SheetOptions
    fp = sf.ForceDrafter(scene_study(FRC60B_INCLINE), SheetOptions(precision=0.5, sheet="forces")).fp()
    gp = next(g for g in fp.groups if g.kind == "crank")
    return fp, gp, {lang: polygon_record(fp, gp, lang) for lang in ("uk", "en")}


def test_the_crank_polygon_closes_with_every_force_in_it(crank):
    fp, gp, _ = crank
    mu_F = gp.mu_F or fp.mu_F
    sides = [s for s in gp.sides if s.mm > 1e-9]
    names = {s.name for s in sides}
    assert {f.name for f in gp.forces if abs(f.force) > 0 and f.kind != "balancing"} <= names
    assert "Φ1" in names and "R01" in names
    # closed: head to tail, back to the pole
    assert abs(sum((s.end - s.start) for s in sides)) < 1e-6
    # Φ1 = −m1·a_S1 (the closed form's) at μF, within the ruler's division and the plan's reading
    phi = next(i.exact_force for i in fp.inertia.values() if i.point == "S1")
    s = next(s for s in sides if s.name == "Φ1")
    assert abs(s.mm - abs(phi) / mu_F) <= fp.precision
    v = s.end - s.start
    assert abs(math.atan2((v / phi).imag, (v / phi).real)) < math.radians(2.0)    # the plan's y is the sheet's


def test_the_detail_names_every_force_and_the_caption_bounds_the_short_ones(crank):
    from graphplan.drawing.labels import collisions
    from graphplan.graphic.draftsman import measure
    from graphplan.util.words import force_symbol
    fp, gp, recs = crank
    short = [s for s in gp.sides if 1e-9 < s.mm < 3.0]
    assert "Φ1" in {s.name for s in short}
    for lang, rec in recs.items():
        assert "mu_F detail" in rec.scales
        names = {q.text for q in rec.items if q.kind == "text" and q.step.endswith("detail")}
        assert {force_symbol(n, lang) for n in ("G1", "Φ1", "R21", "R01")} <= names, (lang, names)   # frc61: Φ1 too
        caption = next(q.text for q in rec.items if q.kind == "text" and q.text.startswith("μ_F = "))
        bound = re.search(r"< (\d+)", caption)
        assert bound is not None and force_symbol("Φ1", lang) in caption
        assert all(measure(s.mm, fp.precision) < int(bound.group(1)) for s in short), caption
        assert collisions(rec) == []
