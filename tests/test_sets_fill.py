"""A2/A3 sets of sheets as a teacher reads them (issue 32): no sheet mostly empty, none holding only
notes (every sheet of a set carries a drawing or a table; the notes follow the last table), the
kinematic diagrams as large as the sheet they take holds — and drawn that large at the lab's scales,
their values the same as at any other size (heights are ordinates at a scale)."""
from __future__ import annotations

import math

import numpy as np
import pytest

from conftest import example, scene_study
from graphplan.sheets.compose import SheetOptions, field_of, keep_out
from graphplan.sheets.form import form
from graphplan.sheets.sheet import BUILDERS

LONG_ROCKER = """
title = "Чотириланковий механізм з довгим коромислом"
title_en = "Four-bar linkage with a long rocker"
designation = "ТММ.05.00.000"
[frame.points]
O1 = [0, 0]
O2 = [0.45, 0.05]
[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.08
rpm = 90
[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.30
points = { S2 = 0.5 }
[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = 0.42
[branch]
B = 1
[positions]
count = 12
start = "max"
accel = [2]
"""

OFFSET_SLIDER = """
title = "Кривошипно-повзунний механізм з ексцентриситетом"
title_en = "Offset crank-slider mechanism"
designation = "ТММ.06.00.000"
[params]
r = 0.05
l = 0.18
e = 0.03
[frame.points]
O = [0, 0]
[frame.guides]
x = { through = [0, "e"], angle_deg = 0 }
[crank]
name = "OA"
pivot = "O"
pin = "A"
length = "r"
omega = 120.0
points = { S1 = 0.5 }
[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = "l"
points = { S2 = 0.3 }
[[link]]
name = "B"
number = 3
joints = ["B"]
slides_on = "x"
[branch]
B = 1
[positions]
count = 12
start = "max"
accel = [3]
"""

OWN = {"long_rocker": LONG_ROCKER, "offset_slider": OFFSET_SLIDER}
LEAST_FILL = 0.25       # no sheet of a set with less of its field drawn on (A2 four-bar's notes-only sheet: 0.08;
                        # 0.18 until the plans were floored at the lab's legible size: the four-bar's A3 0.22)
DIAGRAMS_ALONE = 0.7    # a sheet the diagrams take alone: their block covers this much of the field over the
                        # title block


def study_of(name: str):
    return scene_study(OWN[name]) if name in OWN else example(name)


def build(name: str, kind: str, fmt: str):
    scene = study_of(name) if kind == "kinematics" else example(name)
    return BUILDERS[kind](scene, form(fmt), SheetOptions(sheet=kind))


def fill(page) -> float:
    """The share of the page's field its drawings' extents cover (their union, not their sum)."""
    from shapely.geometry import box
    from shapely.ops import unary_union
    field = box(*field_of(page.form))
    drawn = unary_union([box(*p.record.bounds()) for p in page.placed if p.record.items])
    return drawn.intersection(field).area / field.area


def check_no_orphan(sheet) -> None:
    """Every sheet of the set carries a drawing or a table; the notes are on the last table's sheet."""
    pages = [[p.name for p in page.placed] for page in sheet.pages]
    for n, names in enumerate(pages, 1):
        assert any(name != "notes" for name in names), f"sheet {n} of {len(pages)} holds only {names}"
    with_notes = [n for n, names in enumerate(pages) if "notes" in names]
    with_tables = [n for n, names in enumerate(pages) if any("table" in name for name in names)]
    assert with_notes and with_tables and with_notes[-1] == with_tables[-1], pages


def diagrams_block_share(page) -> float | None:
    """Where a sheet holds the diagrams and nothing else: their block's area over the field's area
    above the title block."""
    if [p.name for p in page.placed] != ["diagrams"]:
        return None
    x0, y0, x1, y1 = field_of(page.form)
    over = (x1 - x0) * (y1 - keep_out(page.form)[3])
    b = page.placed[0].record.bounds()
    return (b[2] - b[0]) * (b[3] - b[1]) / over


def test_a2_four_bar_set_has_no_sheet_of_notes_alone():
    """The A2 four-bar set gave its third sheet to the notes alone (filled 8 %): the notes go with
    the tables (wider beside the title block), two sheets, none mostly empty."""
    sheet = build("four_bar", "kinematics", "A2")
    check_no_orphan(sheet)
    assert min(fill(page) for page in sheet.pages) >= LEAST_FILL


def test_a3_diagrams_fill_the_sheet_they_take():
    """The offset crank-slider's A3 set drew its diagrams 219 × 169 mm on a sheet of their own (L
    120 mm, s 25.5, a 23 mm high): length and height now chosen apart, the block covers most of the
    field over the title block, every diagram at least 30 mm high, at the lab's scales. Since the
    acceleration plans stand beside the diagrams where the diagrams' row holds them and they are no
    taller (c94dbc0: LINK48's A2 left 230 × 280 mm beside its diagrams empty), this set's sheet 3
    holds the diagrams and acceleration plan 1 (stop 58: L 153.6 mm, s, v, a 50.5, 53, 43 mm, the
    sheet 73 % covered): the diagrams with their plans then cover as much, the plans no taller than
    the diagrams, and the s diagram still reads 12.5 mm or more a division of its 12."""
    st = study_of("offset_slider")
    sheet = build("offset_slider", "kinematics", "A3")
    pages = [page for page in sheet.pages if "diagrams" in [p.name for p in page.placed]]
    assert len(pages) == 1
    page, = pages
    names = [p.name for p in page.placed]
    assert all(n == "diagrams" or n.startswith("acceleration plan") for n in names), names
    alone = diagrams_block_share(page)
    from graphplan.sheets.kinematics import _options, plan
    p, _, dr = plan(st, form("A3"), _options(SheetOptions(sheet="kinematics")))
    d = dr.diagrams(p.diagrams)
    if alone is not None:
        assert alone >= DIAGRAMS_ALONE, alone
        assert d.L >= 192.0 - 1e-9
    else:
        assert fill(page) >= DIAGRAMS_ALONE, fill(page)
        block = next(q.record.bounds() for q in page.placed if q.name == "diagrams")
        for q in page.placed:
            if q.name != "diagrams":
                b = q.record.bounds()
                assert b[3] - b[1] <= block[3] - block[1] + 1e-6, (q.name, b, block)
        assert d.L >= 12.5 * d.divisions - 1e-9, d.L
    heights = [float(np.ptp(np.append(x, 0.0))) for x in (d.drawn.s, d.drawn.v, d.drawn.a)]
    r = d.redrawn
    if r is not None and r.changed:
        # redrawn for its errors at the positions (other poles: v's ordinates ∝ H1, a's ∝ H1·H2) —
        # the size the set chose is the first drawing's, and the redrawing must pay for its height
        h1, h2 = r.first.get("H1", d.H1), r.first.get("H2", d.H2)
        heights = [heights[0], heights[1] * h1 / d.H1, heights[2] * h1 * h2 / (d.H1 * d.H2)]
        assert r.off_after < r.off_before
    assert min(heights) >= 30.0, heights
    assert standard(d.mu_s) and 15 <= d.H1 <= 50 and 15 <= d.H2 <= 50 and d.H1 == round(d.H1) and d.H2 == round(d.H2)


def standard(mu: float) -> bool:
    """Whether μ is of the standard series 1, 2, 2.5, 4, 5 × 10^k."""
    e = math.floor(math.log10(mu) + 1e-12)
    return any(math.isclose(mu, m * 10.0 ** e, rel_tol=1e-9) for m in (1, 2, 2.5, 4, 5))


@pytest.mark.parametrize("tall", [0.5, 0.75, 1.2])
def test_taller_diagrams_read_the_same_values(tall):
    """A set's diagrams drawn taller (the height factor apart from the length) are the same
    construction at other scales: drawn exactly (precision 0) every v and a read off them in SI
    equals the one-factor drawing's to 1e-9 of the maximum — the chords' slopes and the poles'
    rays do not depend on μs or H — while μs stays standard and H1, H2 whole mm within 15–50."""
    from graphplan.graphic.diagrams import chord_diagrams
    from graphplan.sheets.kinematics import first_options
    st = example("four_bar")
    one = chord_diagrams(st, precision=0.0, **first_options(st, 1.0))
    other = chord_diagrams(st, precision=0.0, **first_options(st, (1.0, tall)))
    assert other.L == one.L and standard(other.mu_s)
    assert all(15 <= h <= 50 and h == round(h) for h in (other.H1, other.H2))
    for key in ("s", "v_mid", "v_at", "a_mid"):
        a, b = one.values()[key], other.values()[key]
        assert np.max(np.abs(a - b)) <= 1e-9 * np.max(np.abs(a)), key
    s_mm = other.drawn.s.max() - other.drawn.s.min()
    assert s_mm <= 80.0 * tall + 1e-9 and s_mm >= 0.4 * 80.0 * tall - 1e-9


def test_cam_rocking_a3_set_keeps_the_notes_with_the_table():
    """The rocking cam's A3 set gave its fourth sheet to ten lines of notes: they follow the table on
    its sheet now."""
    check_no_orphan(build("cam_rocking", "cam", "A3"))


@pytest.mark.slow
@pytest.mark.parametrize("fmt", ["A3", "A2"])
@pytest.mark.parametrize("name", ["crank_slider", "four_bar", "shaper", "long_rocker", "offset_slider"])
def test_kinematics_sets_are_filled(name, fmt):
    """No sheet of a kinematics set with less than ``LEAST_FILL`` of its field drawn on, none of
    notes alone, and a sheet the diagrams take alone covered by them — or, where the sheet has
    more room than the lab's scales fill (an A2 sheet), the diagrams as large as they allow: the
    scene's L and the s diagram's largest allowance (100 mm) — or drawn larger than that allowance
    draws them (redrawn right, the long rocker's tallest draws v 54 mm high where s 88 mm draws
    it 98 mm)."""
    from graphplan.sheets.kinematics import _options, plan
    from graphplan.sheets.kinlayout import HEIGHTS, drawn_share, factors
    sheet = build(name, "kinematics", fmt)
    check_no_orphan(sheet)
    fills = [round(fill(page), 3) for page in sheet.pages]
    assert min(fills) >= LEAST_FILL, fills
    shares = [s for s in map(diagrams_block_share, sheet.pages) if s is not None]
    if any(s < DIAGRAMS_ALONE for s in shares):
        p, _, dr = plan(study_of(name), form(fmt), _options(SheetOptions(sheet="kinematics")))
        tallest = (1.0, HEIGHTS[0])
        assert factors(p.diagrams) == tallest or drawn_share(dr, p.diagrams) > drawn_share(dr, tallest), (
            shares, p.diagrams)


@pytest.mark.slow
@pytest.mark.parametrize("name,fmt", [("cam_translating", "A3"), ("cam_translating", "A2"), ("cam_rocking", "A2")])
def test_cam_sets_keep_the_notes_with_the_table(name, fmt):
    check_no_orphan(build(name, "cam", fmt))

