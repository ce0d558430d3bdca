"""Stop 52's second look at the cam sheet sets and lettering (cam52b), each against measured geometry
or plain arithmetic of the sheet's sizes:

- Table 1 stands beside the profile where the two fit across the field (A2: 559 mm) and the table
  clears the later sheets' title block — it took a sheet of its own, 60 % blank, under a profile
  as tall as the sheet (OWN_CAM52's A2 set, 5 sheets where its A3 set, half the paper, had 4);
- on the phase diagram |OC₀| is lettered with the R₀ taken, and measures it at μ_s (O, 2 mm
  under the region's vertex, was read as drawn at the smallest R₀);
- on the profile R₀ is lettered along its own line, not in one line with ω (read «ω R₀»)."""
from __future__ import annotations

import tomllib

import numpy as np
import pytest

from graphplan.drawing.layout import GAP, Leaf
from graphplan.exact.cam import solve
from graphplan.graphic.cam import construct
from graphplan.model.cam import build
from review_scenes import REVIEW_CAM52


@pytest.fixture(scope="module")
def review():
    sol = solve(build(tomllib.loads(REVIEW_CAM52), "<review52>"))
    return sol, construct(sol, measure=True, series="rad")


@pytest.mark.parametrize("profile_w,beside", [(301.0, True), (361.0, False)])
def test_the_table_stands_beside_the_profile_where_they_fit_across(profile_w, beside):
    """A2's field is 559 mm across: a 301-mm profile (2:1) leaves 252 mm for the 198-mm table and the
    gap — the two on one sheet, the table right of the profile and clear of the title block —; a
    361-mm one (2,5:1) leaves 192 mm, and the table goes on (no overlap either way)."""
    from graphplan.sheets.cam import beside_last, kept_together
    from graphplan.sheets.compose import field_of, keep_out, later_keep, note_block
    from graphplan.sheets.form import form
    f = form("A2")
    region, keep, later = field_of(f), keep_out(f), later_keep(f)
    assert (region[2] - region[0] - profile_w - GAP >= 198.0) is beside      # the arithmetic the test rests on
    lines = ["Поступальний штовхач, хід h = 25 мм."] * 6
    tab = Leaf("table", 198.0, 96.0)
    leaves = [Leaf("phase", 256.0, 315.0), Leaf("profile", profile_w, 322.0)]
    laid = kept_together(leaves, tab, lines, Leaf("notes", record=note_block(lines, 292.0)), region, keep, later, True)
    where = {leaf.name: (n, b) for n, page in enumerate(laid) for leaf, b in page}
    same = where["table"][0] == where["profile"][0]
    assert same is beside
    if beside:
        assert beside_last(leaves, tab, lines, region, keep, later) is not None
        p, t = where["profile"][1], where["table"][1]
        assert t[0] >= p[2] + GAP - 1e-6 and t[2] <= region[2] + 1e-6
        assert t[1] >= later[3] - 1e-6 or t[2] <= later[0] + 1e-6                # clear of the title block
        assert len(laid) == 2


def test_the_phase_diagram_letters_the_R0_taken_and_OC0_measures_it(review):
    """R₀ taken 39 mm over the smallest 38.28 mm: |OC₀| on the diagram is 39 mm at μ_s and lettered
    «R_0 = 39 мм» (en «mm»); O below the region's vertex by (√(39²−e²) − √(R0min²−e²))/μ_s."""
    from graphplan.drawing.cam import phase_diagram
    sol, g = review
    assert sol.geometry.R0 == pytest.approx(0.039) and g.R0_drawn < 0.039
    for lang, unit in (("uk", "мм"), ("en", "mm")):
        rec = phase_diagram(sol, g, lang)
        (seg,) = [q for q in rec.items if q.step == "R0"]
        (a, b) = (complex(*p) for p in seg.points)
        assert abs(b - a) * g.mu_s * 1000.0 == pytest.approx(39.0, abs=1e-6)
        assert f"R_0 = 39 {unit}" in [q.text for q in rec.items if q.kind == "text"]


def test_the_profile_letters_R0_along_its_line_apart_from_omega(review):
    """R₀ and ω stood side by side in one line (read «ω R₀»): now their ink boxes share no line
    (no vertical overlap), and R₀ is within 3 mm of its own radius line."""
    from graphplan.drawing.cam import profile_drawing
    sol, g = review
    rec = profile_drawing(sol, g, "uk")
    (r0,) = [q for q in rec.items if q.kind == "text" and q.text == "R_0"]
    (w,) = [q for q in rec.items if q.kind == "text" and q.text == "ω"]
    a, b = r0.ink(), w.ink()
    assert a[1] > b[3] or b[1] > a[3]
    (seg,) = [q for q in rec.items if q.step == "R0" and q.kind == "segment"]
    p, q = (complex(*z) for z in seg.points)
    corners = [complex(x, y) for x in (a[0], a[2]) for y in (a[1], a[3])]
    t = [min(max(((c - p) * np.conj(q - p)).real / abs(q - p) ** 2, 0.0), 1.0) for c in corners]
    assert min(abs(p + s * (q - p) - c) for c, s in zip(corners, t)) <= 3.0


@pytest.mark.slow
def test_own_cam52s_a2_set_takes_no_more_sheets_than_its_a3_set():
    """An A2 sheet is two A3 sheets' paper: OWN_CAM52's A2 set took 5 sheets where its A3 set took 4
    (Table 1 alone on sheet 5, 60 % blank). Now no more than the A3 set, Table 1 on the profile's sheet,
    and the scale the title block prints is the μ_l `graphplan cam --format A2` prints (construct_on)."""
    from graphplan.sheets.cam import build_cam_sheet, construct_on
    from graphplan.sheets.compose import SheetOptions, defects
    from graphplan.sheets.form import form
    from review_scenes import OWN_CAM52
    cam = build(tomllib.loads(OWN_CAM52), "<own52>")
    count = {}
    for fmt in ("A2", "A3"):
        sheet = build_cam_sheet(cam, form(fmt), SheetOptions(lang="uk", sheet="cam"))
        assert defects(sheet) == []
        count[fmt] = len(sheet.pages)
        if fmt == "A2":
            pages = [{p.name for p in page.placed} for page in sheet.pages]
            assert any({"profile", "table"} <= names for names in pages)
            mu = next(p.record.scales["mu_l"] for page in sheet.pages for p in page.placed if p.name == "profile")
            assert construct_on(solve(cam), form(fmt)).mu_l == pytest.approx(mu)
    assert count["A2"] <= count["A3"]
