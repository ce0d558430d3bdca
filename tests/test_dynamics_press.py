"""The fourth review's dynamics sheet of a six-bar press (items 13, 15): the M*_c diagram's dashed
projections drew a striped band over the φ axis (the idle stroke's small ordinates each carried
across the width, a millimetre apart); the energy–mass diagram's I* axis had no values and point
0's number stood across a projection line from its point. Read off the drawings' records on the
press and the examples, at one construction (L = 330 mm, size 1: the A1 sheet's order)."""
from __future__ import annotations

import pytest
from conftest import example, scene_study

SPACING = 1.0      # mm: two parallel dashed lines closer than this over a common stretch read as one band


def _construction(st):
    from graphplan.exact.dynamics import analyse
    from graphplan.graphic.flywheel import redrawn
    return redrawn(analyse(st, None), None, 0.5, L=330.0, size=1.0, given=None)


@pytest.fixture(scope="module", params=["press", "shaper", "slotter"])
def built(request):
    from review_scenes import PRESS4
    return _construction(scene_study(PRESS4) if request.param == "press" else example(request.param))


def test_the_moments_projections_keep_apart_and_off_the_axis(built):
    """Each dashed projection runs from its middle's point to the M axis (x = 0), so any two share
    the stretch from the axis to the nearer point: none closer than SPACING to another, to the φ
    axis or to the line of M*_d; every ordinate a millimetre or longer still has its ray from P to
    its height on the M axis (the reading the chord needs), and the largest is projected."""
    from graphplan.drawing.flywheel import moments_record
    f = built
    rec = moments_record(f, "uk")
    proj = [p.points for p in rec.items if p.role == "projection" and p.step.startswith("M at the middle")]
    heights = sorted(a[1] for a, _ in proj)
    for (a, b) in proj:
        assert a[1] == pytest.approx(b[1]) and min(a[0], b[0]) == pytest.approx(0.0, abs=1e-9) or \
            max(a[0], b[0]) == pytest.approx(0.0, abs=1e-9)
    assert all(abs(y) >= SPACING for y in heights), heights
    assert all(b - a >= SPACING for a, b in zip(heights, heights[1:])), heights
    assert all(abs(y - f.Md) >= SPACING for y in heights), (heights, f.Md)
    rays = {round(p.points[1][1], 6) for p in rec.items if p.role == "ray"}
    assert all(round(float(y), 6) in rays for y in f.M_mid if abs(y) >= 1.0)
    top = max(f.M_mid, key=abs)
    assert any(y == pytest.approx(float(top)) for y in heights)


def test_the_press_band_is_gone(built):
    """On the press the idle stroke's ordinates (a few mm) were projected a millimetre apart across
    the diagram: of its ≥ 1 mm ordinates between the φ axis and M*_d at most one in PROJECTION
    spacing is drawn — fewer lines than ordinates there."""
    from graphplan.drawing.flywheel import PROJECTION_SPACING, moments_record
    f = built
    rec = moments_record(f, "uk")
    low = [float(y) for y in f.M_mid if 1.0 <= abs(y) < abs(f.Md)]
    drawn = [p.points[0][1] for p in rec.items if p.role == "projection" and abs(p.points[0][1]) < abs(f.Md)]
    span = abs(f.Md)
    assert len(drawn) <= 2 * span / PROJECTION_SPACING + 1
    if len(low) > span / PROJECTION_SPACING:        # crowded (the press): some carried by their rays alone
        assert len(drawn) < len(low)


def _value(text: str) -> float:
    return float(text.replace(",", ".").replace("−", "-"))


def test_the_inertia_axis_is_graduated_at_its_scale(built):
    """The turned I*(φ)'s foot carries I* values at μ_I: each value's text stands at x = value/μ_I
    from the φ axis (the energy–mass diagram's I* abscissa), round steps ≥ 8 mm apart, up to the
    largest I* (computed: the exact inertia's maximum)."""
    import numpy as np
    from graphplan.drawing.flywheel import inertia_turned
    f = built
    rec = inertia_turned(f, "en", 120.0, 0.0)
    marks = [(p.points[0][0], _value(p.text)) for p in rec.items if p.kind == "text" and p.step == "I* graduation"]
    assert len(marks) >= 2
    for x, v in marks:
        assert x == pytest.approx(v / f.mu_I, abs=1e-6)
    steps = np.diff([v for _, v in marks])
    assert np.allclose(steps, steps[0]) and steps[0] / f.mu_I >= 8.0 - 1e-9
    assert marks[0][1] == pytest.approx(steps[0])
    top = float(np.max(f.dyn.cycle.samples.inertia))   # the exact largest, between divisions too (the press's
    #                                                   12 divisions read 0,467 of its 0,532)
    assert marks[-1][1] <= top * (1 + 1e-9) + f.precision * f.mu_I and marks[-1][1] + steps[0] > top - f.precision * f.mu_I
    assert any(p.kind == "text" and p.text.startswith("μ_I = ") for p in rec.items)


def test_point_zero_is_numbered_at_its_point(built):
    """Point 0 lies on the I* axis (ΔT = 0), the line its own projection runs along: its number
    stands beside it (≤ 3 mm of paper between) with no projection line crossing between them, or on
    a leader from it — not 5.5 mm off across a projection (review 4)."""
    from shapely.geometry import LineString, Point, box
    from shapely.ops import nearest_points
    from graphplan.drawing.flywheel import wittenbauer_record
    f = built
    rec = wittenbauer_record(f, "uk", projections=(-20.0, -20.0))
    at = Point(float(f.I[0]), float(f.dT[0]))
    text = [p for p in rec.items if p.kind == "text" and p.step == "point 0"]
    assert len(text) == 1
    leader = [LineString(p.points) for p in rec.items if p.kind == "segment" and p.step == "point 0"]
    if leader:
        assert min(s.distance(at) for s in leader) <= 1.5
        return
    ink = box(*text[0].ink())
    assert ink.distance(at) <= 3.0 + 1e-9
    sight = LineString([at, nearest_points(at, ink)[1]])
    for p in rec.items:
        if p.kind == "segment" and p.role == "projection":
            line = LineString(p.points)
            if line.distance(at) > 0.9:       # not a line through the point (within its dot, 0.9 mm)
                assert not line.intersects(sight), p.step


@pytest.mark.slow
def test_the_press_a2_set_reads_in_the_order_of_the_work():
    """Review 4, item 16: the press's A2 set gave Tables 1–3, the notes and ω(φ) on its first sheet and
    the construction after, its band's sheet half empty. Now: the moments on sheet 1, the band on
    sheet 2 with the notes in its nook under ΔT(φ) (as the A1 sheet sets them), ω(φ) and the tables
    on the last sheet; the notes clear of the band's drawings; no overprinted word."""
    from types import SimpleNamespace
    from shapely.geometry import box
    from graphplan.sheets.form import form
    from graphplan.sheets.sheet import BUILDERS
    from review_scenes import PRESS4
    args = SimpleNamespace(positions=None, accel=None, precision=0.5, lang="uk", sheet="dynamics")
    sheet = BUILDERS["dynamics"](scene_study(PRESS4), form("A2"), args)
    names = [[p.name for p in page.placed] for page in sheet.pages]
    assert names[0] == ["moments"], names
    assert {"energy", "wittenbauer", "inertia", "notes"} <= set(names[1]), names
    assert {"speed", "positions table", "flywheel table", "motor table"} <= set(names[-1]), names
    from graphplan.sheets.compose import defects
    band = {p.name: p for p in sheet.pages[1].placed}
    notes = box(*band["notes"].record.bounds())
    for name in ("energy", "inertia"):              # under ΔT(φ), left of the turned I*(φ)
        assert not notes.intersects(box(*band[name].record.bounds())), name
    assert defects(sheet) == []


@pytest.mark.parametrize("top, mu, expected", [(26.0, 1.0, [10.0, 20.0]), (107.0, 0.005, [0.1, 0.2, 0.3, 0.4, 0.5]),
                                               (5.0, 1.0, []), (30.0, 0.004, [0.05, 0.1])])
def test_graduation_steps_are_round_and_apart(top, mu, expected):
    """Round steps 12 mm apart or more (0,1 kg·m² at μ_I = 0,005: 20 mm), closer down to 8 mm
    where that alone gives two values (the shaper's 26 mm I*: 10 and 20, not 20 alone)."""
    from graphplan.drawing.flywheel import graduation
    assert graduation(top, mu) == pytest.approx(expected)
