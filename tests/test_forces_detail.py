"""Issue 32 #3: the crank group's force plan is a sliver where R21 ≈ R01 (nearly equal and opposite),
its G1 and Φ1 shorter than the ruler can letter at the sliver's tip ("G1, Φ1 < 3 mm" under it). The
spot is ringed and marked "I", and drawn again as a detail (GOST 2.305's extension element) at a
series μF_I: every side through the window named there, its lengths the drawn plan's times μF/μF_I."""
from __future__ import annotations

import math

import pytest

from conftest import scene_study
from review_scenes import SIXBAR

# the standard series every μF takes (LAYOUT.md; review 59 #2: no GOST 1.5, 7.5): 1, 2, 2.5, 4, 5 × 10^k
SERIES = sorted(m * 10.0 ** k for m in (1.0, 2.0, 2.5, 4.0, 5.0) for k in range(-3, 5))


def test_the_detail_scale_is_the_largest_series_value_that_draws_the_shortest_side_long_enough():
    """plan_detail's first μF_I is the largest series value at which the shortest side is drawn at
    least 6 mm (and the window at most 30 mm across: the smallest value that does), and at least
    twice the plan's size — computed here from the series written out."""
    from graphplan.drawing.forces import DETAIL_LEAST_MM, DETAIL_MOST_MM, DETAIL_PAD, plan_detail
    from graphplan.graphic.forceplans import Side
    for mu_F, g, phi in ((10.0, 3.0, 1.0), (40.0, 2.5, 0.5), (75.0, 2.0, 1.5), (7.5, 4.0, 2.5)):
        sides = [Side("G1", 0j, -g * 1j, "known"), Side("Φ1", -g * 1j, -g * 1j - phi, "known"),
                 Side("R21", -g * 1j - phi, 80 + 40j, "known"), Side("R01", 80 + 40j, 0j, "reaction")]
        d = plan_detail(sides, mu_F)
        assert d is not None
        window = max(phi, g) + 2 * DETAIL_PAD
        least = max(m for m in SERIES if mu_F * min(g, phi) / m >= DETAIL_LEAST_MM[0] - 1e-9)
        cap = min(m for m in SERIES if mu_F * window / m <= DETAIL_MOST_MM + 1e-9)
        assert d.choices[0] == pytest.approx(max(least, cap)), (mu_F, d)
        assert all(mu_F / m >= 2.0 - 1e-9 for m in d.choices)
        assert list(d.choices) == sorted(d.choices)                   # the finest (largest drawing) first


def test_no_detail_where_every_side_carries_its_name():
    from graphplan.drawing.forces import TINY_MM, plan_detail
    from graphplan.graphic.forceplans import Side
    sides = [Side("G1", 0j, -TINY_MM * 1j - 1j, "known"), Side("Φ1", -4j, -4j - 4, "known"),
             Side("R21", -4 - 4j, 80 + 40j, "known"), Side("R01", 80 + 40j, 0j, "reaction")]
    assert plan_detail(sides, 10.0) is None



def test_a_detail_where_short_sides_are_specks_beside_the_plans_longest():
    """Review 47 #2: LINK47's crank plan drew G1 (4 mm) and Φ1 (4.5 mm) at the tip of R21's 271 mm
    sliver — each named, yet 1.5 % of the plan: a speck. Short sides (under 5 mm) under 2 % of the
    longest side are drawn again in a detail; the same short sides beside a 95 mm side are not."""
    from graphplan.drawing.forces import plan_detail
    from graphplan.graphic.forceplans import Side
    tip = -4j - 4.5
    sides = [Side("G1", 0j, -4j, "known"), Side("Φ1", -4j, tip, "known"),
             Side("R21", tip, tip + 271 * complex(math.cos(0.05), math.sin(0.05)), "known")]
    sides.append(Side("R01", sides[-1].end, 0j, "reaction"))
    d = plan_detail(sides, 5.0)
    assert d is not None
    # the window rings G1 and Φ1 (their spot, 4.5 × 4 mm, padded), not the long sides
    assert d.box[2] - d.box[0] < 10 and d.box[3] - d.box[1] < 10
    short = [Side("G1", 0j, -4j, "known"), Side("Φ1", -4j, tip, "known"),
             Side("R21", tip, 90 + 30j, "known"), Side("R01", 90 + 30j, 0j, "reaction")]
    assert plan_detail(short, 5.0) is None


@pytest.fixture(scope="module")
def crank_plan():
    from graphplan.drawing.forces import polygon_record
    from graphplan.sheets import forces as sf
    from graphplan.sheets.compose import SheetOptions
    fp = sf.ForceDrafter(scene_study(SIXBAR), SheetOptions(precision=0.5, sheet="forces")).fp()
    gp = next(g for g in fp.groups if g.kind == "crank")
    return fp, gp, {lang: polygon_record(fp, gp, lang) for lang in ("uk", "en")}


def test_the_crank_plan_sliver_gets_a_detail_naming_every_force(crank_plan):
    """SIXBAR's crank plan (R21 ≈ R01, G1 and Φ1 under 3 mm): a ring and its mark "I", and a detail
    whose arrows are the drawn sides through the window enlarged μF/μF_I times, every one of G1, Φ1,
    R21, R01 named in it; no letter of the plan or its detail on a line or on another letter."""
    from graphplan.drawing.labels import collisions
    from graphplan.util.words import force_symbol
    fp, gp, recs = crank_plan
    mu_F = gp.mu_F or fp.mu_F
    short = [s for s in gp.sides if 1e-9 < s.mm < 3.0]
    assert {s.name for s in short} >= {"Φ1"}                       # the case: a side too short to letter
    for lang, rec in recs.items():
        mu_I = rec.scales["mu_F detail"]
        k = mu_F / mu_I
        assert k >= 2.0 and any(abs(mu_I - m) < 1e-9 * m for m in SERIES)
        assert sum(1 for q in rec.items if q.kind == "circle" and q.step.endswith("detail")) == 1
        assert any(q.kind == "text" and q.text == "I" for q in rec.items)          # the ring's mark
        names = {q.text for q in rec.items if q.kind == "text" and q.step.endswith("detail")}
        assert {force_symbol(n, lang) for n in ("G1", "Φ1", "R21", "R01")} <= names
        assert any(t.startswith("I (μ_F = ") for t in names)
        # the short sides' arrows in the detail: their drawn lengths times k
        arrows = sorted(math.dist(*q.points) for q in rec.items if q.kind == "vector" and q.step.endswith("detail"))
        for s in short + [s for s in gp.sides if s.name == "G1"]:
            assert any(abs(a - s.mm * k) < 1e-6 for a in arrows), (s.name, s.mm * k, arrows)
        assert collisions(rec) == []
