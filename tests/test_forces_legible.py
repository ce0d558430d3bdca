"""The second review's force sheet of a slotted-lever coulisse (tests/review_scenes.COULISSE), items
5, 10, 14 and 18: each force plan at a μF from its own room, forces lying along a link drawn their
own length beside it, lettering at the sheet's 3.5 mm with an index clear of the P's bowl, the
resistance axis in metres, the tables of an A2 set in a column by the title block."""
from __future__ import annotations

import math

import pytest

from graphplan.exact.positions import study
from graphplan.model.scene import loads
from graphplan.sheets.compose import SheetOptions
from graphplan.sheets.form import form
from review_scenes import COULISSE


@pytest.fixture(scope="module")
def coulisse():
    return study(loads(COULISSE, "coulisse.toml"))


@pytest.fixture(scope="module")
def a1(coulisse):
    from conftest import shared
    from graphplan.sheets import forces

    def build():
        p, nat, dr = forces.plan(coulisse, form("A1"), SheetOptions(sheet="forces"))
        return p, dr, dr.drawings(p.mu, "en")
    return shared("test_forces_legible.a1", build)


def _arrows(rec):
    return {p.text: p for p in rec.items if p.kind == "vector" and p.text}


def _length(p) -> float:
    (x0, y0), (x1, y1) = p.points[:2]
    return math.hypot(x1 - x0, y1 - y0)


def test_a_force_plan_with_small_forces_gets_its_own_finer_scale(a1):
    """II(4-5)'s forces are a third of the crank's (R34 1760 N, R01 5240 N): at the sheet's one μF
    its plan was 44 mm long beside 131 mm. Now every plan's longest vector is at least half the
    longest plan's, and the μF written under each plan is the one its lengths are drawn at."""
    p, dr, recs = a1
    fp = dr.groups_fp(p.mu)
    longest = {gp.label: max(s.mm for s in gp.sides) for gp in fp.groups}
    assert min(longest.values()) >= 0.5 * max(longest.values()), longest
    for gp, rec in zip(fp.groups, recs["forces"]):
        mu_F = gp.mu_F or fp.mu_F
        caption = next(t.text for t in rec.items if t.kind == "text" and t.text.startswith("μ_F"))
        assert caption.startswith(f"μ_F = {mu_F:g} N/mm"), caption
        for s in gp.sides:                              # each side laid off at the plan's own μF
            force = next((abs(f.force) for f in gp.forces if f.name == s.name and f.force), None)
            if force is not None and s.role == "known":
                assert abs(s.mm - force / mu_F) <= 0.5 + 1e-9, (gp.label, s.name, s.mm, force, mu_F)


def test_forces_along_the_rocker_are_drawn_their_own_length_beside_it(a1):
    """G2 and G3 (vertical; the rocker 8° from vertical) ran as 70 mm arrows down the rocker to O.
    An arrow on a group's drawing is 8–30 mm long (drawing.forces._arrow_length) unless it is a
    reaction or reaches past a link's end; G2, G3 keep to that and stand clear of the rocker's line.
    Since stop 61 a force is drawn ON its own line of action through its point (review 60 #3: set a
    lane aside, it contradicted its arm h drawn to the true line), so "clear of the rocker" is no
    longer its head's tip 1.5 mm off the rocker's centre line (a lane's rule: G3 slid 10 mm up its
    line from S3 has its tip 1.34 mm off, and the 2-mm-wide head's base, 4 mm farther up, is the
    part nearest the rocker anyway) but the head's ink: its filled triangle, as
    graphic.record.vector_arrow draws it, on one side of the rocker with at least half a millimetre
    of paper between it and the rocker's stroke — a head a teacher sees beside the link, not on it."""
    from graphplan.graphic.record import vector_arrow
    p, dr, recs = a1
    rec = next(r for r in recs["groups"] if r.title.startswith("II(2-3)"))
    arrows = _arrows(rec)
    for name in ("G2", "G3"):
        assert 8.0 - 1e-6 <= _length(arrows[name]) <= 30.0 + 1e-6, (name, _length(arrows[name]))
    rocker = max((q for q in rec.items if q.kind == "polyline" and q.role == "link"),
                 key=lambda q: math.dist(q.points[0], q.points[-1]))
    (ax, ay), (bx, by) = rocker.points[0], rocker.points[-1]
    n = math.hypot(bx - ax, by - ay)
    for name in ("G2", "G3"):
        (tx, ty), (hx, hy) = arrows[name].points[:2]
        assert abs(hx - tx) < 1e-6, (name, tx, hx)           # vertical: on the weight's own line
        head, _ = vector_arrow((tx, ty), (hx, hy), arrows[name].line_width)
        sides = [((x - ax) * (by - ay) - (y - ay) * (bx - ax)) / n for x, y in head]
        assert min(sides) > 0 or max(sides) < 0, (name, sides)   # the head does not cross the rocker
        paper = min(abs(d) for d in sides) - 0.5 * rocker.line_width
        assert paper >= 0.5, (name, paper, rocker.line_width)


def test_force_lettering_is_the_sheets_35_mm(a1):
    """Force, arm and plan labels were 2.5 mm; the sheet's lettering is 3.5 mm (GOST 2.304 on A1)."""
    from graphplan.util.words import force_symbol
    p, dr, recs = a1
    names = {force_symbol(a.text, "en") for fam in ("groups", "forces", "scheme") for r in recs[fam]
             for a in r.items if a.kind == "vector" and a.text and not a.text.startswith("M_b")}
    for fam in ("groups", "forces", "scheme", "lever"):
        for r in recs[fam]:
            labels = [t for t in r.items if t.kind == "text" and (t.text in names or t.text.startswith("h_{"))]
            assert labels, (fam, r.title)
            assert min(t.size for t in labels) >= 3.5, (fam, r.title, min(labels, key=lambda t: t.size).text)


def _outline_mm(path: str, ch: str, size: float, x: float, y: float):
    """The outline of ``ch`` in the font file ``path`` lettered ``size`` mm high (our capitals'
    height, record.em) at (x, y) on its baseline, as points (mm): curves sampled."""
    import numpy as np
    from fontTools.ttLib import TTFont

    from graphplan.graphic.record import _outline, em
    with TTFont(path) as font:
        gl, glyf = font["glyf"][font.getBestCmap()[ord(ch)]], font["glyf"]
        pts = np.array(_outline(gl, glyf, 16)) / font["head"].unitsPerEm
    return pts * em(size) + np.array([x, y])


@pytest.mark.parametrize("text", ["P_D", "P_C", "P_B", "Р_D", "F_C", "P_O", "P_G", "P_S", "P_A", "F_A"])
def test_a_capital_index_keeps_clear_of_the_bowl(text):
    """The D of P_D touched the P's bowl (tucked 0.15 h inside the P's box): a capital index keeps
    paper from the letter's ink — and stays near enough to read as its index, one word with it: the
    round C of P_C set by its box stood 0.89 mm off (D's flat side 0.59) and, in a viewer without our
    font, read as a word of its own under the P (stop 54). Measured on the glyphs' outlines, in our
    font and in the fallback a viewer letters with (each glyph at our x); a low index (P_зр's з)
    still tucks in."""
    from importlib import resources

    import numpy as np

    from graphplan.drawing.svg import typeset
    from graphplan.graphic.record import fallback_font
    size = 3.5
    pieces, _ = typeset(text, size)
    (p, _, x_p, _, _), (d, small, x_d, y_d, _) = pieces[:2]
    ours = str(resources.files("graphplan") / "data" / "fonts" / "osifont.ttf")
    for path in [ours] + ([fallback_font()] if fallback_font() else []):
        a = _outline_mm(path, p, size, x_p, 0.0)
        b = _outline_mm(path, d[0], size * 0.7, x_d, y_d)
        gap = float(np.sqrt(((a[:, None, :] - b[None, :, :]) ** 2).sum(-1)).min())
        assert gap >= 0.05 * size, (text, path, gap)
        assert gap <= 0.24 * size, (text, path, gap)          # one word with its letter (0.84 mm)
    # the low index tucks in under the bowl, farther than a flat capital's (D) may
    (_, _, x_p2, _, _), (_, _, x_z, _, _) = typeset("P_{зр}", size)[0][:2]
    (_, _, x_p3, _, _), (_, _, x_dd, _, _) = typeset("P_D", size)[0][:2]
    assert x_z - x_p2 < x_dd - x_p3


def test_the_resistance_axis_reads_in_metres(coulisse):
    """The axis "s, m" carried only position numbers: now a row of values at round steps, each at
    its tick, the value the tick's distance times μs."""
    from graphplan.drawing import charts
    rec = charts.records(charts.turn(coulisse), 1.0, "en")["resistance"]
    mu_s = rec.scales["mu_s"]
    values = [(t.points[0][0], float(t.text)) for t in rec.items
              if t.kind == "text" and "." in t.text and t.text.replace(".", "").isdigit()]
    values += [(t.points[0][0], 0.0) for t in rec.items if t.kind == "text" and t.text == "0"]
    assert len({v for _, v in values}) >= 3, values
    for x, v in values:
        assert abs(x * mu_s - v) < 1e-9 or v == 0.0, (x, v)
    steps = sorted({v for _, v in values})
    assert all(abs((b - a) - (steps[1] - steps[0])) < 1e-9 for a, b in zip(steps, steps[1:]))


def test_the_tables_stand_apart_as_elsewhere(a1):
    """Tables 6 and 7 (balancing moment, reactions) stood 2.3 mm apart; the column's gap is 6 mm."""
    from graphplan.drawing.forces import results_record
    from graphplan.drawing.layout import GAP
    p, dr, recs = a1
    rec = results_record(dr.groups_fp(p.mu), "en", number=6)
    titles = [t for t in rec.items if t.kind == "text" and t.text.startswith("Table 7")]
    rules = [q for q in rec.items if q.kind in ("segment", "polyline", "polygon") and q.layer != "labels"]
    title_top = titles[0].points[0][1] + 3.5
    first_bottom = min(y for q in rules for _, y in q.points if y > title_top)
    assert first_bottom - title_top >= GAP - 0.2, first_bottom - title_top


def test_an_a2_set_puts_its_tables_in_a_column_by_the_title_block(coulisse):
    """Sheet 4 of the A2 set scattered its tables over the sheet in rows, with R34's hodograph
    alone on sheet 3: now all the hodographs stand on one sheet, and on the last sheet every table
    lies to the right of every drawing or under every drawing, the notes over the title block; the scheme, 1:4 on a
    sheet 70 % empty, is drawn larger."""
    from graphplan.sheets.forces import build_forces_sheet
    from graphplan.sheets import forces
    from graphplan.drawing.layout import GAP
    sheet = build_forces_sheet(coulisse, form("A2"), SheetOptions(sheet="forces"))
    pages = [page.placed for page in sheet.pages]
    hods = [n for n, page in enumerate(pages) for it in page if it.name.startswith("hodograph")]
    assert len(hods) == 5 and len(set(hods)) == 1, hods
    last = pages[-1]
    tables = [it for it in last if "table" in it.name or it.name == "results"]
    drawings = [it for it in last if it not in tables and it.name != "notes"]
    assert len(tables) >= 5
    # the tables together: right of every drawing (the column by the title block), or under every
    # drawing (a row of hodographs over them) — never a drawing beside a table's left or under it
    right = min(t.box[0] for t in tables) >= max([d.box[2] for d in drawings] + [0.0]) + GAP - 1e-6
    under = max(t.box[3] for t in tables) <= min([d.box[1] for d in drawings] + [1e9]) - GAP + 1e-6
    assert right or under
    p, _, _ = forces.plan(coulisse, form("A2"), SheetOptions(sheet="forces"))
    assert p.mu["scheme"] < 0.004 - 1e-12, p.mu["scheme"]
