"""Review 55 #1: the A1 force sheet's scheme and groups drawn as large as the composition allows."""
from __future__ import annotations

import pytest

from conftest import scene_study


@pytest.mark.slow
@pytest.mark.parametrize("name", ["BEAM_PUMP55"])
def test_the_a1_scheme_is_not_the_smallest_main_drawing(name):
    """LAYOUT.md's "the scheme left, large", as a property of the one-sheet composition: the scheme
    and the groups (at one scale, never the groups smaller) are not drawn smaller against their
    targets than every other main drawing (the force plans, the acceleration plan, the lever), unless
    they are at their target. The beam pump's A1 sheet drew them at 1:10, 0.25 of their target,
    beside its lever at 0.40, its force plans at 0.62 and its acceleration plan at 1.23 — ~180 × 85 mm
    blank round the scheme, where its A2 set draws it at 1:2 (review 55 #1)."""
    import review_scenes
    from graphplan.sheets import forces as sf
    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.form import form
    st = scene_study(getattr(review_scenes, name))
    p, nat, _ = sf.plan(st, form("A1"), SheetOptions(precision=0.5, sheet="forces"))
    assert p.sheets == 1 and p.mu["groups"] <= p.mu["scheme"] * (1 + 1e-9), p.mu
    rel = {n: nat.families[n].rel(p.mu[n]) for n in sf.MAIN}
    others = min(rel[n] for n in ("forces", "acceleration", "lever"))
    assert rel["scheme"] >= min(others, 1.0) * (1 - 1e-9), rel
