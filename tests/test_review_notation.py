"""The teacher's review of the six-bar and the offset press (corrections 4, 5, 8, 10, 11, 17, 18),
each checked against a truth computed here: a tangential component from the moment of the exact
reaction, the crank's turn from position 0 by the scene's geometry, the documented minimum of a
velocity plan, the drawn lines against the links' lines."""
from __future__ import annotations

import math
import re

import pytest

from conftest import scene_study
from review_scenes import OFFSET_SLIDER, SIXBAR


def _cross(a: complex, b: complex) -> float:
    return a.real * b.imag - a.imag * b.real


@pytest.fixture(scope="module")
def sixbar_forces():
    """The six-bar's force sheet plan (A1, the ruler's 0.5 mm), its groups' force plans and tables."""
    from graphplan.sheets import forces as sf
    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.form import form
    from conftest import shared

    def build():
        st = scene_study(SIXBAR)
        p, _, dr = sf.plan(st, form("A1"), SheetOptions(precision=0.5, sheet="forces"))
        return {"st": st, "fp": dr.groups_fp(p.mu), "dr": dr, "mu": p.mu,
                "tables": dict(sf._tables(dr, p.mu, "uk", p.tables))}
    return shared("test_review_notation.sixbar_forces", build)


def _row(rec, first: str) -> list[str]:
    """The cells of a table's row whose first cell reads ``first``, left to right (a table set in
    two tiers: the first tier's, then the second's)."""
    out = []
    for head in sorted((p for p in rec.items if p.kind == "text" and p.text == first), key=lambda p: -p.points[0][1]):
        y = head.points[0][1]
        cells = [p for p in rec.items if p.kind == "text" and abs(p.points[0][1] - y) < 0.05 and p is not head]
        out += [p.text for p in sorted(cells, key=lambda p: p.points[0][0])]
    return out


def _value(text: str) -> float:
    return float(text.replace("−", "-").replace(",", "."))


def test_a_tangential_component_is_tabulated_as_seed_000_does(sixbar_forces):
    """Each group's table prints R^τ as its moment equation solves it, as a magnitude beside the arrow
    drawn in its true sense (seed 000's table 2.4 prints 579,7 Н where its equation solved
    «−R^t = … = 579,7»; review 9 #5 marked a signed cell beside a true-sense arrow). The truth: the
    exact reaction R at its pair X has the moment (X − P) × R about the equation's point P; R^τ =
    that moment over the signed arm, |arm| = |X − P| — for R^τ03 of the six-bar −348 N as solved,
    348 as tabulated."""
    from graphplan.util.words import force_symbol, word
    fp = sixbar_forces["fp"]
    seen = 0
    for gp in fp.groups:
        rec = sixbar_forces["tables"][f"table {gp.label}"]
        heads = _row(rec, word("force", "uk"))
        values = _row(rec, word("force value", "uk"))
        assert len(heads) == len(values), gp.label
        for eq in gp.equations:
            if eq.unknown == "M_b":
                continue
            r = fp.ks.reactions[eq.unknown.replace("τ", "")]
            x = complex(r.at[0])
            p = next(complex(q.at[0]) for q in fp.ks.reactions.values()
                     if q.point == eq.about and q.group == gp.label)
            truth = _cross(x - p, complex(r.force[0])) / (math.copysign(1.0, eq.arm_mm) * abs(x - p))
            printed = _value(values[heads.index(force_symbol(eq.unknown, "uk"))])
            assert printed == pytest.approx(abs(truth), rel=0.03), (eq.unknown, printed, truth)
            seen += 1
    assert seen == 3
    gp = next(g for g in fp.groups if g.label.startswith("II(2-3)"))
    rec = sixbar_forces["tables"][f"table {gp.label}"]
    r03 = _row(rec, word("force value", "uk"))[_row(rec, word("force", "uk")).index(force_symbol("R03τ", "uk"))]
    assert _value(r03) == pytest.approx(347.19, rel=0.01)     # the exact 347,19 read off the drawing


@pytest.fixture(scope="module")
def offset_sheets():
    """The offset press's three A1 sheets in both languages (the crank turning clockwise)."""
    from conftest import scene_sheet
    return {(name, lang): scene_sheet(OFFSET_SLIDER, name, "A1", lang, precision=0.5)
            for lang in ("uk", "en") for name in ("kinematics", "forces", "dynamics")}


def _texts(sheet) -> list:
    return [p for p in sheet.record.items if p.kind == "text"]


def _paragraph(sheet, start: str) -> str:
    """The notes' line that begins with ``start`` with its continued lines (indented 5 mm) joined; a
    line's start may sit up to a letter's side bearing (under 0.8 mm) off the margin, since the notes
    set each line's ink flush (graphic.record: a lower-case letter's bearing taken off)."""
    first = next(p for p in _texts(sheet) if p.text.startswith(start))
    x, y = first.points[0]
    below = sorted((p for p in _texts(sheet) if p.size == first.size and p.points[0][1] < y - 1e-9
                    and abs(p.points[0][0] - x) < 5.8), key=lambda p: -p.points[0][1])
    text = first.text
    for p in below:
        if abs(p.points[0][0] - (x + 5.0)) > 0.8:
            break
        text += " " + p.text
    return text


PHI_SAID = {"uk": "φ — поворот кривошипа від положення 0 у бік його обертання; положення 0: кут кривошипа {phi0}° "
                  "від осі x",
            "en": "φ: the crank's turn from position 0 in its sense of rotation; position 0: crank angle {phi0}° "
                  "from the x axis"}


@pytest.mark.parametrize("lang", ["uk", "en"])
def test_phi_is_the_turn_from_position_0_on_every_sheet(offset_sheets, lang):
    """Correction 5: one φ on the three sheets, the lab's (seed 000's φ_8 = 200°): the crank's turn
    from position 0 in its sense, said once in each sheet's notes in the same words. The truth: the
    offset press (r = 0.09, l = 0.36, e = −0.03, position 0 the outer dead centre) has position 0 at
    the crank angle asin(e/(l + r)) = −3.82° = 356.2°; its table 1 reads φ = 0, 30 … 330 (twelve
    equal turns) and its acceleration plan of position 3 is at φ = 90° — not the crank angles
    356.2°, 326.2° … 266.2° of a clockwise crank."""
    phi0 = math.degrees(math.asin(-0.03 / 0.45)) % 360.0
    sep = "," if lang == "uk" else "."
    said = PHI_SAID[lang].format(phi0=f"{phi0:.1f}".replace(".", sep))
    for name in ("kinematics", "forces", "dynamics"):
        sheet = offset_sheets[name, lang]
        starts = [p for p in _texts(sheet) if p.text.startswith(said[:12])]
        assert len(starts) == 1, (name, [p.text for p in starts])
        assert _paragraph(sheet, said[:12]).replace("\xa0", " ").startswith(said), (name, _paragraph(sheet, said[:12]))
    kin = offset_sheets["kinematics", lang]
    head = next(p for p in _texts(kin) if p.text == "φ, °")
    column = sorted((p for p in _texts(kin) if 0.0 < p.points[0][0] - head.points[0][0] < 12.0
                     and p.points[0][1] < head.points[0][1] and p.points[0][1] > head.points[0][1] - 13 * 8.4
                     and re.fullmatch(r"[0-9]+[.,][0-9]", p.text)), key=lambda p: -p.points[0][1])
    assert [float(p.text.replace(",", ".")) for p in column] == [30.0 * k for k in range(12)]
    caption = next(p.text for p in _texts(kin) if p.text.startswith("μ_a") and "φ" in p.text)
    assert caption.endswith("φ = 90°"), caption


def test_sixbar_velocity_plans_are_legible_on_a1():
    """Correction 8: the six-bar's velocity plans drew p_v a = 37.7 mm (μv = 0.02) in cells twice
    their size; docs/scenes.md asks at least 40 mm. The truth: v_A = ω1·r = (90·2π/60)·0.08 m/s; the
    A1 sheet's μv draws it at least 40 mm and no coarser than before; the plans, the terminal and
    the sheet take this one μv."""
    from graphplan.sheets.kinematics import sheet_scales
    v_a = 90 * 2 * math.pi / 60 * 0.08
    st = scene_study(SIXBAR)
    mu = sheet_scales(st, "A1")["mu_v"]
    assert v_a / mu >= 40.0 and mu < 0.02
    chosen = 5.0 * math.floor(v_a / mu / 5.0 + 1e-9)     # the lab's chosen length, a multiple of 5 mm
    assert chosen <= v_a / mu <= chosen / 0.99            # … μ at 3 figures down (45 mm since the grid's
                                                          # columns each take their own width)


@pytest.mark.parametrize("value, length", [(0.7539822, 40.0), (1.508, 40.0), (37.5, 45.0), (2.0e-4, 40.0)])
def test_a_chosen_length_gives_its_scale_at_three_figures(value, length):
    """The lab's p_v a chosen, μ = v_A/p_v a (REFERENCE §3): three significant figures, rounded down,
    so the vector is drawn at least that long and less than 1 % longer."""
    from graphplan.graphic.scales import chosen_length
    mu = chosen_length(value, length)
    assert length <= value / mu < length * 1.01
    assert float(f"{mu:.3g}") == mu


def _points(p) -> list[complex]:
    return [complex(x, y) for x, y in p.points]


def _near_run(a: complex, b: complex, s: complex, e: complex, tol: float = 0.6) -> float:
    """How long (mm) the arrow a→b runs within ``tol`` mm of the segment s–e (200 samples): an
    arrow drawn over a line, whatever the small angle between them."""
    d, n = b - a, 200
    hits = 0
    for k in range(n + 1):
        z = a + d * k / n
        w = e - s
        t = min(max(((z - s) * w.conjugate()).real / abs(w) ** 2, 0.0), 1.0) if abs(w) > 1e-9 else 0.0
        hits += abs(z - (s + t * w)) <= tol
    return abs(d) * max(0, hits - 1) / n


def test_no_force_lies_on_a_link_on_the_scheme_or_a_line_of_the_lever(sixbar_forces):
    """Correction 10: on the scheme Φ5 lay on the rod CD (it leaves D toward C, the rod coming in at
    3.6° to the guide), on the lever P_D lay along the image d–s4. No arrow now runs more than 1 mm
    within 0.6 mm of a link (a line of the lever) at less than 15° to it."""
    drawings = sixbar_forces["dr"].drawings(sixbar_forces["mu"], "uk")
    for rec, lines in ((drawings["scheme"][0], lambda p: p.role == "link" and p.layer == "mechanism"),
                       (drawings["lever"][0], lambda p: p.role == "relative")):
        segs = [(s, e) for p in rec.items if p.kind in ("segment", "polyline") and lines(p)
                for s, e in zip(_points(p), _points(p)[1:])]
        assert segs
        for v in (p for p in rec.items if p.kind == "vector"):
            a, b = _points(v)
            for s, e in segs:           # a line within 15° of the arrow: one it could hide in
                if abs(e - s) > 1e-9 and abs(((b - a) / abs(b - a) * ((e - s) / abs(e - s)).conjugate()).imag) < 0.26:
                    assert _near_run(a, b, s, e) <= 1.0, (rec.title, v.text, s, e)


def test_the_sliders_guide_is_drawn_with_its_hatching(sixbar_forces):
    """Correction 10: the slider D on the scheme stands on its guide as on the kinematics sheet: a
    solid line of the frame along the guide (y = 0.30 m, horizontal) through the block with short
    hatch strokes on one side — none under the block, none across a line. Its group is drawn freed
    from the frame (review4 #10: the press's II(4–5) kept the guide): no frame line, no hatching."""
    fp, mu = sixbar_forces["fp"], sixbar_forces["mu"]
    drawings = sixbar_forces["dr"].drawings(mu, "uk")
    groups = drawings["groups"]
    gp45 = next(k for k, g in enumerate(fp.groups) if g.label.startswith("II(4-5)"))
    assert not [p for p in groups[gp45].items if p.layer == "frame"], groups[gp45].title
    for rec, m in ((drawings["scheme"][0], mu["scheme"]),):
        d = complex(fp.ks.reactions["R05"].at[0]) / m
        guide = [p for p in rec.items if p.kind == "segment" and p.role == "frame"
                 and all(abs(y - d.imag) < 1e-6 for _, y in p.points)
                 and min(x for x, _ in p.points) < d.real - 10 < d.real + 10 < max(x for x, _ in p.points)]
        assert guide, rec.title
        hatch = [p for p in rec.items if p.kind == "segment" and p.role == "hatch"
                 and all(abs(y - d.imag) <= 3.0 for _, y in p.points) and abs(p.points[0][0] - d.real) <= 26.0]
        assert len(hatch) >= 3, rec.title
        assert all(abs(p.points[0][0] - d.real) > 5.0 for p in hatch), rec.title
        sides = {math.copysign(1.0, p.points[1][1] - d.imag) for p in hatch}
        assert len(sides) == 1, rec.title


def test_chart_axes_are_solid_thin_lines(sixbar_forces):
    """Correction 11 (GOST 2.303): a diagram's axes are solid thin lines — the M_b chart's, the
    R05 chart's, the resistance diagram's, the hodographs' and the cam diagrams' (they were
    dash-dot: the centre lines' type). The truth: each chart's φ (s, x) axis is the line y = 0
    through its origin, its ordinate axis x = 0; neither is dashed."""
    from graphplan.graphic.record import DASHED_ROLES, ROLES
    drawings = sixbar_forces["dr"].drawings(sixbar_forces["mu"], "uk")
    recs = list(drawings["charts"]) + list(drawings["hodographs"])
    from graphplan.drawing.cam import diagrams, phase_diagram
    from graphplan.exact.cam import solve
    from graphplan.graphic.cam import construct
    from graphplan.model.cam import load
    from conftest import ROOT
    sol = solve(load(ROOT / "examples" / "cam_translating.toml"))
    g = construct(sol)
    cams = [diagrams(sol, g, "uk"), phase_diagram(sol, g, "uk")]
    checked = 0
    for rec in recs:
        axes = [p for p in rec.items if p.kind in ("segment", "vector") and len(p.points) == 2
                and ((abs(p.points[0][1]) < 1e-9 and abs(p.points[1][1]) < 1e-9)
                     or (abs(p.points[0][0]) < 1e-9 and abs(p.points[1][0]) < 1e-9))
                and math.dist(*p.points) > 5.0]
        assert len(axes) >= 2, rec.title
        for p in axes:
            assert p.role not in DASHED_ROLES and (p.width or ROLES[p.role]) < 0.5, (rec.title, p.role)
            checked += 1
    for rec in cams:
        axes = [p for p in rec.items if (p.step or "").startswith(("axis ", "ordinate ", "follower axis"))]
        assert axes, rec.title
        for p in axes:
            assert p.role not in DASHED_ROLES, (rec.title, p.step, p.role)
            checked += 1
    assert checked >= 12


def test_english_sheets_are_titled_in_english(offset_sheets):
    """Correction 17: the SVG <title> of the English kinematics, force and dynamics sheets is the
    scene's title_en (it was the Ukrainian title), the Ukrainian sheets' the title."""
    from graphplan.drawing.svg import render
    for (name, lang), sheet in offset_sheets.items():
        want = "Offset crank-slider mechanism of a press" if lang == "en" else \
            "Дезаксіальний кривошипно-повзунний механізм преса"
        svg = render(sheet.record, sheet.form.width, sheet.form.height, sheet.record.title)
        title = re.search(r"<title>(.*?)</title>", svg).group(1)
        assert title.startswith(want + " — "), (name, lang, title)
        assert (re.search("[А-Яа-яІіЇїЄєҐґ]", title) is None) == (lang == "en"), (name, lang, title)


@pytest.mark.parametrize("lang, said", [("uk", "гр.\u00a0МБ-21"), ("en", "group\u00a0MB-21")])   # romanised (stop 55)
def test_the_group_is_one_word_on_every_sheet(lang, said):
    """Correction 17: the title block's organisation field names the student's group in one word on
    the lever, cam and gear sheets ("group МБ-21" beside "gr. МБ-21" before)."""
    from conftest import example
    from graphplan.sheets import cam as cs, gears as gs
    from graphplan.sheets.kintables import fields
    got = {fields(example("shaper"), lang, "")["organisation"],
           cs._fields(example("cam_translating"), lang)["organisation"],
           gs._fields(example("gears"), lang, None)["organisation"]}
    assert len(got) == 1 and next(iter(got)).endswith(said), got


def test_a_symbol_keeps_its_value_on_its_line():
    """Correction 18: the notes never break a line between a symbol and its "= value unit" (the
    force sheet's notes ended a line with "μ_a" and began the next with "= 0,025"). At every width
    from 40 to 200 mm each "X = value unit" of the scales' line stands whole on one line."""
    from graphplan.sheets.compose import NOTE, wrap_markup
    line = ("Масштабні коефіцієнти: μ_l = 0,004 м/мм; μ_l = 0,001 м/мм (група I(0-1)); μ_F = 10 Н/мм; "
            "μ_a = 0,025 (м/с²)/мм; μ_v = 0,01 (м/с)/мм")
    whole = ["μ_l = 0,004 м/мм;", "μ_l = 0,001 м/мм", "μ_F = 10 Н/мм;", "μ_a = 0,025 (м/с²)/мм;", "μ_v = 0,01 (м/с)/мм"]
    for width in range(40, 201, 3):
        lines = wrap_markup(line, float(width), NOTE)
        assert " ".join(lines) == line
        for part in whole:
            assert any(part in x for x in lines), (width, part, lines)
    forces = "Сили, коротші за 10 мм: R^{τ}_{34} 2,5 мм, 2,8 %; Φ_2 3 мм, 3,1 %; G_3 7 мм, 7,2 %"
    for width in range(40, 121, 3):
        for x in wrap_markup(forces, float(width), NOTE):
            assert not x.endswith(("2,5", " 3", " 7", "10")) and not x.startswith("мм"), (width, x)


def test_the_inertia_table_heads_its_moment_as_everywhere(sixbar_forces):
    """Correction 18: Table 2 heads its couple M^Φ, as the scheme, the groups and the lever letter
    it (it read M_Φ)."""
    rec = sixbar_forces["tables"]["inertia table"]
    heads = [p.text for p in rec.items if p.kind == "text"]
    assert any(t.startswith("M^Φ, ") for t in heads) and not any("M_Φ" in t for t in heads), heads


def test_the_planetary_velocity_names_are_lettered_3_5_mm():
    """Correction 18: v_A and v_O2 of the planetary train's velocity picture were lettered 2.5 mm
    (their small v and index about 2 mm high); they are lettered 3.5 mm, the plans' size."""
    from conftest import example_sheet
    sheet = example_sheet("gears", "gears", "A1", "uk")      # the gallery's (shared: conftest)
    sizes = {p.text: p.size for p in sheet.record.items if p.kind == "text" and p.text in ("v_A", "v_{O_2}")}
    assert sizes == {"v_A": 3.5, "v_{O_2}": 3.5}


def test_a_crowded_pivots_letter_breaks_only_thin_lines():
    """The known defect: at a pivot where twelve thin position lines meet (and a thick crank, a
    vector and the crank pin's circle pass) the letter O_1 went 16.9 mm out on a leader. Asked with
    ``breaks`` it stands within 5 mm of its point; the thin lines under it are broken, each piece
    on its own line with the original's role, layer, step and width; the thick link, the vector
    and the frame are left whole; nothing touches the letter."""
    from graphplan.drawing.labels import breakable, collisions, place_labels
    from graphplan.graphic.record import LabelRequest, Record
    rec = Record("pivot")
    for k in range(12):
        u = complex(math.cos(math.pi * k / 6 + 0.1), math.sin(math.pi * k / 6 + 0.1))
        rec.segment((0.0, 0.0), (40 * u.real, 40 * u.imag), role="link", width=0.3, layer="mechanism",
                    step=f"position {k}")
    rec.circle((0.0, 0.0), 20.0, role="trajectory", layer="construction", step="circle")
    rec.segment((0.0, 0.0), (20.0, 3.0), role="link", layer="mechanism", step="thick")
    rec.vector((0.0, 0.0), (-3.0, 25.0), role="absolute", layer="vectors", step="F")
    rec.segment((-4.0, -5.0), (4.0, -5.0), role="frame", layer="frame", step="support")
    before = list(rec.items)
    place_labels(rec, [LabelRequest(0j, "O_1", toward=1 + 1j, size=3.5, breaks=True)])
    letter = next(p for p in rec.items if p.kind == "text")
    x0, y0, x1, y1 = letter.ink()
    assert math.hypot(max(x0, 0.0, -x1), max(y0, 0.0, -y1)) <= 5.0
    assert not any(p.role == "label" and p.kind == "segment" for p in rec.items)     # no leader
    kept = [p for p in before if not breakable(p)]
    assert all(p in rec.items for p in kept)
    pieces = [p for p in rec.items if p not in before and p.kind != "text"]
    assert pieces
    for q in pieces:
        src = [p for p in before if breakable(p) and p.step == q.step]
        assert len(src) == 1 and (q.role, q.layer, q.width) == (src[0].role, src[0].layer, src[0].width)
        if q.kind == "segment":
            (ax, ay), (bx, by) = src[0].points
            for px, py in q.points:           # on the original line
                assert abs((bx - ax) * (py - ay) - (by - ay) * (px - ax)) / math.hypot(bx - ax, by - ay) < 1e-9
    assert collisions(rec) == []
