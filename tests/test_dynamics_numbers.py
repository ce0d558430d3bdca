"""The dynamics sheet's division numbers and sets read as a teacher reads them: no number touched by
a curve (a generated shaper whose French curve of I*(φ) dips past its φ axis ran through the
turned diagram's "4"), a set's last sheet never holding the notes alone, and a table of positions
that no sheet holds refused at once in one line that says how many divisions fit."""
from __future__ import annotations

import functools
import math
from types import SimpleNamespace

import numpy as np
import pytest
from shapely.geometry import LineString, Point, box

from conftest import example, scene_study
from coursework_scenes import shaper

CHECK = 0.3      # mm: the least paper a reader needs between a number's ink and a line's ink

# the falsifying shaper of test_composition_properties' many_new_mechanisms (dynamics, A1): I*_m
# 0.038 kg·m² at positions 0 and 4 between 1.1 and 6.5 — the French curve swings 2 mm past the axis
DIPPING = shaper(2.0, 0.29826407280599715, 0.3, 0.75, 0.9, 204.1166895861926, 32.4540087809624, 8000.0, 60.0)


def _args(lang: str = "uk"):
    return SimpleNamespace(positions=None, accel=None, precision=0.5, lang=lang, sheet="dynamics")


@pytest.fixture(scope="module")
def dipping():
    """Composed alone (``conftest.composed``: no test here reads the project's numbering)."""
    from conftest import scene_sheet
    return scene_sheet(DIPPING, "dynamics", "A1", _args().lang)


def _numbers(rec):
    return [p for p in rec.items if p.kind == "text" and p.step == "division numbers"]


def _curves(rec):
    return [LineString(p.points) for p in rec.items if p.kind == "polyline" and p.role == "curve"]


def _turned(dipping):
    """The turned I*(φ) on the sheet: its φ axis's abscissa, the division points (I*_k, φ_k) and
    the drawn curve's vertices."""
    inertia = next(p.record for p in dipping.placed if p.name == "inertia")
    axis = [p.points for p in inertia.items if p.kind == "vector" and p.step == "axes I*_m"][0]
    points = sorted((p.points[0] for p in inertia.items if p.step == "I*_m read"), key=lambda q: -q[1])
    return axis[0][0], np.array(points), [xy for c in _curves(inertia) for xy in c.coords]


def test_the_french_curve_through_the_scenes_points_dips_past_the_axis(dipping):
    """The scene is the one that needs the fix: scipy's periodic cubic spline (the French curve)
    through its turned I*(φ) points runs left of the φ axis (I* < 0) by more than 1.5 mm."""
    from scipy.interpolate import CubicSpline
    x_axis, pts, _ = _turned(dipping)
    phi = pts[0, 1] - pts[:, 1]                      # φ runs downward
    spline = CubicSpline(phi, pts[:, 0] - x_axis, bc_type="periodic")
    assert np.min(spline(np.linspace(0.0, phi[-1], 4001))) < -1.5


def test_the_drawn_inertia_never_runs_below_zero(dipping):
    """I* > 0: the turned I*(φ) curve is drawn shape-preserving, never left of its φ axis (0.05 mm
    of drawing tolerance), and through every division point."""
    x_axis, pts, curve = _turned(dipping)
    assert min(x for x, _ in curve) >= x_axis - 0.05
    drawn_ = LineString(curve)
    assert max(drawn_.distance(Point(*p)) for p in pts) < 0.02


@pytest.mark.parametrize("name", ["energy", "inertia", "moments"])
def test_no_division_number_is_touched_by_a_curve(dipping, name):
    """Every division number's ink keeps CHECK mm of paper from every curve on the sheet (the
    distance by shapely, from the curve's centre line less half its width), and the numbers of a
    diagram stand on one line (one baseline under ΔT(φ) and the moments; one right edge beside the
    turned I*(φ))."""
    rec = next(p.record for p in dipping.placed if p.name == name)
    curves = [(LineString(p.points), p.line_width / 2) for q in dipping.placed for p in q.record.items
              if p.kind == "polyline" and p.role == "curve"]
    numbers = _numbers(rec)
    assert len(numbers) >= 13
    for t in numbers:
        ink = box(*t.ink())
        gap = min(c.distance(ink) - half for c, half in curves)
        assert gap >= CHECK, (name, t.text, round(gap, 2))
    if name == "inertia":                      # beside the φ axis running down: one right edge
        assert len({round(t.points[0][0], 6) for t in numbers}) == 1 and {t.anchor for t in numbers} == {"end"}
    else:                                      # under the φ axis: one baseline (the moments' and the work's)
        assert len({round(t.points[0][1], 6) for t in numbers}) == (2 if name == "moments" else 1)


def test_the_sheet_has_no_defect(dipping):
    from graphplan.sheets.compose import defects
    assert defects(dipping) == []


def test_a_row_moves_as_one_by_the_least_step_that_clears_it():
    """labels.row_clear: a line through a row of numbers' ink, 0.5 mm under its top, moves the row
    down 0.5 mm at a time until CLEAR (0.5 mm) + the line's half width lies between them: 1.175 mm,
    so by 3 steps (1.5 mm), not 2."""
    from graphplan.drawing.labels import CLEAR, ROW_STEP, row_clear
    from graphplan.graphic.record import Primitive, Record
    rec = Record("t")
    row = [Primitive("text", ((x, 0.0),), text=str(k), size=2.5, anchor="middle") for k, x in enumerate((0.0, 10.0))]
    top = max(p.ink()[3] for p in row)
    half = 0.35 / 2
    rec.segment((-5.0, top - 0.5), (15.0, top - 0.5), width=0.35)
    moved = row_clear(rec, row, (0.0, -1.0))
    shift = row[0].points[0][1] - moved[0].points[0][1]
    assert shift == pytest.approx(math.ceil((0.5 + CLEAR + half) / ROW_STEP) * ROW_STEP) == pytest.approx(1.5)
    assert [p.points[0][0] for p in moved] == [0.0, 10.0] and moved[0].points[0][1] == moved[1].points[0][1]


@pytest.mark.parametrize("name, fmt", [("shaper", "A3"), pytest.param("slotter", "A3", marks=pytest.mark.slow)])
def test_no_sheet_of_a_set_holds_only_the_notes(name, fmt):
    """Every sheet of a dynamics set carries a drawing or a table; the notes share a sheet with the
    last table, or stand in the band's nook under ΔT(φ) as on the A1 sheet (shaper and slotter at
    A3 left them alone on a fourth sheet)."""
    from graphplan.sheets.compose import defects
    from graphplan.sheets.form import form
    from graphplan.sheets.sheet import BUILDERS
    sheet = BUILDERS["dynamics"](example(name), form(fmt), _args("en"))
    pages = [[p.name for p in page.placed] for page in sheet.pages]
    assert len(pages) > 1
    assert all(set(names) - {"notes"} for names in pages), pages
    last = pages[-1]
    assert "motor table" in last and ("notes" in last or any({"notes", "wittenbauer"} <= set(p) for p in pages)), pages
    assert defects(sheet) == []


@functools.lru_cache(maxsize=None)
def _slotter(divisions: int):
    """examples/slotter.toml with [dynamics] divisions, studied and analysed (once per count)."""
    from conftest import ROOT
    from graphplan.exact.dynamics import analyse
    base = (ROOT / "examples" / "slotter.toml").read_text(encoding="utf-8")
    st = scene_study(base.replace("[dynamics]", f"[dynamics]\ndivisions = {divisions}"))
    return st, analyse(st, None)


def test_a_table_of_positions_no_sheet_holds_is_refused_at_once():
    """The table of the positions takes a 6 mm row a division, and under it a line of the chords'
    heights and what δ is of: at A1 (574 mm of field) 92 divisions are the most; 93 are refused
    before any drawing is laid out, the line naming 92."""
    import time

    from graphplan.sheets.dynamics import _refuse_a_table_taller_than
    from graphplan.sheets.form import form
    from graphplan.util.errors import GraphplanError
    for n, refused in ((92, False), (93, True)):
        st, dyn = _slotter(n)
        t = time.perf_counter()
        if refused:
            with pytest.raises(GraphplanError) as e:
                _refuse_a_table_taller_than(st, dyn, form("A1"), _args())
            assert "93 divisions" in str(e.value) and "at most 92" in str(e.value) and "A1" in str(e.value)
            assert "\n" not in str(e.value)
        else:
            _refuse_a_table_taller_than(st, dyn, form("A1"), _args())
        assert time.perf_counter() - t < 2.0


def test_numbers_by_twos_do_not_run_into_the_last():
    """93 divisions on a 250 mm φ axis are numbered by twos: 0, 2 … 90 and 93 — not 92 beside 93
    (their ink overlapped); every diagram of the construction is then free of collisions."""
    from graphplan.drawing.flywheel import energy_projected, inertia_turned, moments_record
    from graphplan.drawing.labels import collisions
    from graphplan.graphic.flywheel import construct
    st, dyn = _slotter(93)
    f = construct(dyn, 93, 0.5, L=250.0)
    for rec in (moments_record(f, "uk"), energy_projected(f, "uk", 250.0, 280.0), inertia_turned(f, "uk", 250.0, 10.0)):
        numbers = [int(t.text) for t in _numbers(rec)]
        assert 93 in numbers and 92 not in numbers and 90 in numbers, numbers
        assert collisions(rec) == [], collisions(rec)[:3]


def test_the_last_table_and_the_notes_in_one_row_stay_together():
    """A set's last table and its notes stay together (``_set_flow``): where the plain flow would set
    them in one row with the row's spare width shared out between them (here 100–200 mm apart), the
    notes go under the table or beside it a normal gap (GAP) away, both then drawn from the top of the
    row (``_top_aligned``), on no more sheets. (The examples' sets no longer end so since the notes
    went to the band's nook and the sets into the order of the work — the slotter's A3 set, the case
    checked before, ends with its notes under the tables — so the flow is given the sheets' sizes.)"""
    from graphplan.drawing.layout import GAP, Leaf, flow
    from graphplan.graphic.record import Record
    from graphplan.sheets.compose import field_of, keep_out
    from graphplan.sheets.dynamics import _later_keep, _set_flow, _top_aligned
    from graphplan.sheets.form import form

    def leaf(name: str, w: float, h: float) -> Leaf:
        rec = Record()
        rec.segment((0.0, 0.0), (w, h))
        return Leaf(name, record=rec)

    f = form("A3")
    region, keep, later = field_of(f), keep_out(f), _later_keep(f)
    rows = [[leaf("moments", 380, 220)], [leaf("band", 250, 160), leaf("speed", 380, 150)]]
    tables = [leaf("positions table", 200, 90), leaf("flywheel table", 120, 80), leaf("motor table", 90, 72)]
    ways = set()
    for w, h in ((80, 60), (170, 140), (100, 215)):              # the last: too tall to stand under it
        notes = leaf("notes", w, h)
        plain = flow(rows + [tables + [notes]], region, keep, later=later)
        last = {leaf_.name: b for leaf_, b in plain[-1]}
        table, text = last["motor table"], last["notes"]
        assert abs(table[3] - text[3]) < 1e-6 and text[0] - table[2] > 3 * GAP, (w, h, table, text)
        laid = _set_flow(rows, tables, notes, region, keep, later)
        assert laid is not None and len(laid) <= len(plain)
        page = next(pg for pg in laid if any(leaf_ is notes for leaf_, _ in pg))
        boxes = {leaf_.name: b for leaf_, b in page}
        table, text = boxes["motor table"], boxes["notes"]
        if abs(table[3] - text[3]) < 1e-6:                       # in one row: a GAP apart, read from the top
            assert 0.0 < text[0] - table[2] <= GAP + 0.5, (w, h, table, text)
            assert _top_aligned(page) == {"motor table", "notes"}
            ways.add("beside")
        else:                                                    # under the table, a GAP below it
            assert text[3] <= table[1] and table[1] - text[3] <= GAP + 0.5, (w, h, table, text)
            assert text[0] < table[2] and table[0] < text[2]
            ways.add("under")
    assert ways == {"beside", "under"}
