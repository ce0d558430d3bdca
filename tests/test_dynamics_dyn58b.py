"""Stop 58, helper dyn58b: the energy–mass diagram's letters k and l beside their own circles. Review 58
(finding 6) on COULISSE_REVIEW58's A1 dynamics sheet: the curve point 12's number took the place under l's
extension line, and l ran into the dimension's text («|kl| = 111,5 мм l»). The letters of the
construction are placed before the points' numbers (drawing.flywheel.energy_mass)."""
from __future__ import annotations

import math

import pytest
from conftest import scene_study
from review_scenes import COULISSE_REVIEW58


def _gap(a, b) -> float:
    """The distance between two boxes (x0, y0, x1, y1), 0 where they meet."""
    dx = max(a[0] - b[2], b[0] - a[2], 0.0)
    dy = max(a[1] - b[3], b[1] - a[3], 0.0)
    return math.hypot(dx, dy)


@pytest.mark.slow
@pytest.mark.parametrize("lang, projections", [("uk", (-46.29205293958472, -132.09147570635702)),
                                               ("en", (-47.49271519279964, -132.19081345802473))])
def test_l_beside_its_circle_clear_of_the_kl_dimension(lang, projections):
    """The construction as the A1 sheet draws it (L = 210 mm, heights × 1,15, the projections from the
    sheet's ΔT(φ) and I*(φ)): k and l each within 5 mm of its point on the ΔT axis, nearer it than the
    |kl| text, and l at least 2 mm clear of that text (it stood 1,5 mm after «мм», read as its last word)."""
    from graphplan.drawing.flywheel import energy_mass
    from graphplan.exact.dynamics import analyse
    from graphplan.graphic.flywheel import redrawn
    from graphplan.util.markup import plain
    f = redrawn(analyse(scene_study(COULISSE_REVIEW58), None), None, 0.5, L=210.0, size=1.15)
    w = energy_mass(f, lang, projections=projections)
    texts = [p for p in w.items if p.kind == "text"]
    kl = [p.ink() for p in texts if plain(p.text).startswith("|kl|")]
    assert len(kl) == 1
    for name in ("k", "l"):
        x, y = next(p.points[0] for p in w.items if p.kind == "point" and p.step == name)
        dot = (x, y, x, y)
        letter = [p.ink() for p in texts if p.step == name and plain(p.text) == name]
        assert len(letter) == 1, name
        assert _gap(letter[0], dot) <= 5.0, (name, letter[0], (x, y))
        assert _gap(letter[0], dot) < _gap(letter[0], kl[0]), (name, letter[0], kl[0])
        assert _gap(letter[0], kl[0]) >= 2.0, (name, letter[0], kl[0])
