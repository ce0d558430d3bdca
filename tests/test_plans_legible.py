"""Plans large enough to read (issue 32, item 4), measured on the records the sheet draws: the crank
pin's velocity p_v a as long as its cell lets it be, no grid of plans narrower than its rows need, the
position plan's letters beside their points, a link's number never beside another number."""
from __future__ import annotations

import pytest

from conftest import example
from graphplan.drawing.labels import LINK_APART, LINK_SIZE, NUMBERS_APART, is_number
from graphplan.drawing.plans import at_position, indexed, joints_at, position_record
from graphplan.sheets.compose import SheetOptions
from graphplan.sheets.form import form
from graphplan.sheets.kinematics import plan
from graphplan.sheets.kinlayout import _grids


def test_a_grid_of_r_rows_takes_the_fewest_columns():
    """12 velocity plans in two rows are 6 a row (the grid was 11 wide: one row of 11 and one of 1,
    too wide to grow, so the plans stayed small)."""
    for n in range(1, 40):
        cols = _grids(n)
        rows = [-(-n // c) for c in cols]
        assert sorted(set(rows)) == sorted(rows) == sorted({-(-n // c) for c in range(1, n + 1)})
        for c, r in zip(cols, rows):
            assert c == -(-n // r)          # no narrower grid has r rows


def _pa_mm(st, mu_v: float) -> float:
    return abs(st.mech.omega1) * st.mech.crank.length / mu_v


# p_v a on the A1 sheet, mm: the lab model and the four-bar drew 42 and 31 mm (a grid of 11 columns)
@pytest.mark.parametrize("name, least", [("lab_crank_slider", 80.0), ("four_bar", 55.0), ("crank_slider", 40.0)])
def test_velocity_plans_fill_their_cells(name, least):
    st = example(name)
    p = plan(st, form("A1"), SheetOptions(sheet="kinematics"))[0]
    assert _pa_mm(st, p.mu["velocity"]) >= least


def _box_gap(a, b) -> float:
    dx = max(a[0] - b[2], b[0] - a[2], 0.0)
    dy = max(a[1] - b[3], b[1] - a[3], 0.0)
    return (dx * dx + dy * dy) ** 0.5


@pytest.mark.parametrize("fmt", ["A1", "A3"])
@pytest.mark.parametrize("name", ["lab_crank_slider", "four_bar", "shaper", "crank_slider"])
def test_position_plan_letters_and_numbers(name, fmt):
    """Each joint's letter is drawn (at the first thick position), every one within 6 mm of its
    point and half of them within 4.5 mm — the crank's pivot, where the twelve crank lines meet,
    and points among the links' twelve thin positions too: the letter is written beside its point
    and the thin lines under it are broken, as a draftsman does (drawing.labels, ``breaks``; they
    took leaders of 7–16.9 mm before, O1 of the shaper 16.9 mm); a
    link's number (5 mm) is ``LINK_APART`` from every other number, position numbers ``NUMBERS_APART``
    from each other — "3" by "1" does not read "31"."""
    st = example(name)
    p, _, dr = plan(st, form(fmt), SheetOptions(sheet="kinematics"))
    pl = dr.plans(p.mu)
    rec = position_record(pl)
    thick = set(pl.accel_keys) or {0}
    lay = next(q.layout for q in pl.positions if q.layout.key == min(thick))
    texts = [q for q in rec.items if q.kind == "text"]
    dist = []
    # since kinmarks, with several thick positions each one's moving joints carry its number, the
    # first's too (A₁, B₁ beside A₅, B₅: review 11 #15); a frame point keeps its plain letter
    mech = pl.scheme.mech
    moving = {j for link in mech.links.values() for j in link.joints} - set(mech.frame)
    several = len(thick) > 1
    for point, X in joints_at(pl.scheme, lay).items():
        letter = at_position(point, lay.index if lay.index is not None else lay.key) \
            if several and point in moving else indexed(point)
        boxes = [q.ink() for q in texts if q.text == letter]
        assert boxes, point
        d = min(_box_gap(b, (X.real, X.imag, X.real, X.imag)) for b in boxes)
        assert d <= 6.0, (point, d)
        dist.append(d)
    assert sorted(dist)[(len(dist) - 1) // 2] <= 4.5, dist
    numbers = [q for q in texts if is_number(q.text)]
    links = [q for q in numbers if q.size >= LINK_SIZE]
    assert sorted(q.text for q in links) == sorted({str(l.number) for l in pl.scheme.mech.links.values()})
    for i, a in enumerate(numbers):
        for b in numbers[i + 1:]:
            need = LINK_APART if max(a.size, b.size) >= LINK_SIZE else NUMBERS_APART
            assert _box_gap(a.ink(), b.ink()) >= need - 1e-6, (a.text, b.text)


@pytest.mark.parametrize("r,ratio,offset", [(0.1, 4.0, 0.3), (0.15, 3.0, -0.4), (0.08, 5.0, 0.0)])
def test_a_slider_stroke_and_offset_are_dimensioned(r, ratio, offset):
    """The position plan dimensions the slider's stroke H and a crank-slider's offset e in real mm:
    H = √((l + r)² − e²) − √((l − r)² − e²) (the closed form, not the drawing's) to the whole mm, e
    the scene's; no e where the guide passes through the crank's pivot."""
    import math
    import re

    from coursework_scenes import crank_slider
    from graphplan.exact.positions import study
    from graphplan.graphic.plans import build_plans
    from graphplan.model.scene import loads
    st = study(loads(crank_slider(r, ratio, offset, 60.0, 50.0, 1000.0, 10.0), "cs"))
    rec = position_record(build_plans(st))
    texts = [p.text for p in rec.items if p.kind == "text"]
    l, e = ratio * r, abs(offset) * r
    H = math.sqrt((l + r) ** 2 - e ** 2) - math.sqrt((l - r) ** 2 - e ** 2)
    def mm(t: str) -> float:
        return float(t.split()[2].replace(",", "."))
    # whole millimetres where the length is whole, else to its tenth (drawing.plans._real_mm)
    found = [t for t in texts if re.fullmatch(r"H = \d+(,\d)? мм", t)]
    assert found and abs(mm(found[0]) - 1000 * H) <= 0.05 + 1e-9, (found, 1000 * H)
    es = [t for t in texts if re.fullmatch(r"e = \d+(,\d)? мм", t)]
    if e:
        assert es and abs(mm(es[0]) - 1000 * e) <= 0.05 + 1e-9, es
    else:
        assert es == []
    dims = [p for p in rec.items if p.step == "dimensions" and p.kind == "vector"]
    assert len(dims) == (4 if e else 2)
