"""Stop 46's gear sheet (an 11/29 pair with shifts "auto" at 5:1 and a type-B train for u1H = 9, A1 en),
graded as a teacher grades it: the drawings fill their zone (the λ diagrams beside the meshing where
the two fit across), the lab's notation (z2′, the planetary labels), the dimension a_w as Table 1
prints it — each checked on the drawn sheet against the closed forms or the sheet's own zones."""
from __future__ import annotations

import math

import pytest

from review_scenes import GEARS46


@pytest.fixture(scope="module")
def sheet46(tmp_path_factory):
    from graphplan.exact.gears import solve
    from graphplan.model.gears import load
    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.form import form
    from graphplan.sheets.gears import build_gears_sheet
    path = tmp_path_factory.mktemp("g46") / "gears.toml"
    path.write_text(GEARS46, encoding="utf-8")
    g = load(path)
    return g, solve(g), build_gears_sheet(g, form("A1"), SheetOptions(lang="en"))


def _placed(sheet, name: str):
    return next(p for page in sheet.pages for p in page.placed if p.name == name)


def test_the_sliding_diagrams_stand_beside_the_meshing_with_a_caption_no_wider_than_them(sheet46):
    """The lead's first glance: a third of the drawings' zone empty left of the λ diagrams, which stood
    in the row under the 5:1 meshing only because their one-line caption made them 214 mm for a 196-mm
    diagram. The caption now runs in two lines no wider than the diagrams, and the diagrams stand
    beside the meshing (its row, the same top) when the two fit across the field less the tables'
    column; the drawn N1N2 is the closed form's g = aw·sin αw over the abscissa's scale."""
    g, sol, sheet = sheet46
    mesh, lam = _placed(sheet, "meshing"), _placed(sheet, "sliding")
    drawn = [q.bounds() for q in lam.record.items if q.step != "caption"]
    x0, x1 = min(b[0] for b in drawn), max(b[2] for b in drawn)
    caption = [q.bounds() for q in lam.record.items if q.step == "caption"]
    assert len(caption) == 3 and all(b[0] >= x0 - 1e-6 and b[2] <= x1 + 1e-6 for b in caption)
    assert lam.box[3] == pytest.approx(mesh.box[3]) and lam.box[0] >= mesh.box[2]      # one row, side by side
    # the drawn N1N2 (the axis from N1 − 4 to N2 + 8) against the closed form
    aw, a_w = _centre_distance(sol)
    axis = next(q for q in lam.record.items if q.step == "λ axis").points
    assert (axis[1][0] - axis[0][0] - 12.0) * lam.record.scales["mu_l"] == pytest.approx(aw * math.sin(a_w), rel=1e-9)


def _centre_distance(sol) -> tuple[float, float]:
    """aw, m, and αw, rad, of the pair with the shifts "auto" chose: inv αw = 2(x1 + x2)·tg α/(z1 + z2)
    + inv α solved here by bisection; aw = a·cos α/cos αw."""
    from scipy.optimize import brentq
    (z1, z2), (x1, x2), m = sol.pair.pair.z, sol.pair.x, sol.pair.pair.module
    al = math.radians(20.0)
    inv = lambda t: math.tan(t) - t                                           # noqa: E731
    a_w = brentq(lambda t: inv(t) - (2 * (x1 + x2) * math.tan(al) / (z1 + z2) + inv(al)), 0.05, 1.2, xtol=1e-14)
    return m * (z1 + z2) / 2 * math.cos(al) / math.cos(a_w), a_w
