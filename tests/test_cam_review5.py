"""Review 4, items 19–20: the A1 cam sheet composed without the blank room under the phase diagram
(375–570, 335–590 mm from the sheet's left/top was empty: 42 % of the sheet), and Table 1's
graphical values to what the ruler gives (s гр. = 0,3982 from a reading of 1 mm)."""
from __future__ import annotations

import math

import pytest

from conftest import ROOT
from graphplan.model.cam import load
from graphplan.sheets.compose import SheetOptions, defects, field_of, keep_out
from graphplan.sheets.form import form

CELL = 20.0


def _marks(q) -> list[tuple[float, float]]:
    """Points along a primitive's ink about every millimetre (a text: its ink box filled)."""
    if q.kind == "text":
        x0, y0, x1, y1 = q.ink()
        nx, ny = max(2, int((x1 - x0) + 2)), max(2, int((y1 - y0) + 2))
        return [(x0 + (x1 - x0) * i / (nx - 1), y0 + (y1 - y0) * j / (ny - 1)) for i in range(nx) for j in range(ny)]
    if q.kind in ("circle", "arc"):
        (cx, cy), r = q.points[0], q.radius
        a0, sweep = (0.0, 360.0) if q.kind == "circle" else (q.angles[0], (q.angles[1] - q.angles[0]) % 360.0 or 360.0)
        n = max(4, int(math.radians(sweep) * r) + 2)
        return [(cx + r * math.cos(math.radians(a0 + sweep * k / (n - 1))),
                 cy + r * math.sin(math.radians(a0 + sweep * k / (n - 1)))) for k in range(n)]
    pts = list(q.points) + ([q.points[0]] if q.kind == "polygon" else [])
    out = list(pts)
    for (xa, ya), (xb, yb) in zip(pts, pts[1:]):
        n = int(math.hypot(xb - xa, yb - ya)) + 2
        out += [(xa + (xb - xa) * k / n, ya + (yb - ya) * k / n) for k in range(1, n)]
    return out


def empty_share(sheet) -> tuple[float, set]:
    """The share of the field's CELL-mm cells (the title block's left out) where no placed drawing
    puts ink, read off the sheet's records; and the empty cells (column, row)."""
    x0, y0, x1, y1 = field_of(sheet.form)
    kx0, _, _, ky1 = keep_out(sheet.form)
    cols, rows = int(math.ceil((x1 - x0) / CELL)), int(math.ceil((y1 - y0) / CELL))
    inked = set()
    for placed in sheet.placed:
        for q in placed.record.items:
            for x, y in _marks(q):
                inked.add((int((x - x0) // CELL), int((y - y0) // CELL)))
    cells = {(i, j) for i in range(cols) for j in range(rows)
             if not (x0 + (i + 1) * CELL > kx0 and y0 + j * CELL < ky1)}
    empty = cells - inked
    return len(empty) / len(cells), empty


def _sheet(path, lang):
    from graphplan.sheets.cam import build_cam_sheet
    return build_cam_sheet(load(path), form("A1"), SheetOptions(lang=lang, sheet="cam"))


KNIFE = '''title = "Кулачковий механізм з поступальним загостреним штовхачем"
title_en = "Disc cam with a translating knife-edge follower"
designation = "ТММ.КМ.00.000"

[cam]
follower = "translating"
stroke = 0.032
offset = -0.006
roller_radius = 0
phases_deg = { rise = 100, dwell_far = 40, return = 140, dwell_near = 80 }
laws = { rise = "cycloidal", return = "trapezoidal" }
pressure_angle_deg = { rise = 28, return = 35 }
omega = 12
direction = "cw"
divisions = 10
'''


def _largest_blank(empty: set) -> int:
    """The side (in cells) of the largest square of empty cells."""
    best = 0
    for i, j in empty:
        k = best + 1
        while all((i + a, j + b) in empty for a in range(k) for b in range(k)):
            best, k = k, k + 1
    return best


def _laid_sheet(path, lang):
    """The A1 composition at the construction's sizes as cam_sizes finds them for the review's cam
    (2.6, 1.9, 1.5, 1.6; H1 30, H2 42 mm, the series' scales), without the search: the leaves laid
    (sheets.cam._laid) — the pressure angle's diagram under the s–v–a diagrams (with_theta) —, placed."""
    from types import SimpleNamespace
    from graphplan.exact.cam import solve
    from graphplan.graphic.cam import construct
    from graphplan.sheets import cam as sc
    sol = solve(load(path))
    g = construct(sol, None, 0.5, size=2.6, profile_size=1.9, height=1.5, accel=1.6, H1=30.0, H2=42.0,
                  measure=False, series="rad")
    leaves, tab, nts, doc = sc._leaves(sol, g, sol.cam, lang)
    f = form("A1")
    (page,) = sc._laid(f, leaves, tab, nts, sc._notes_at(doc, lang, sol.cam))
    placed = [q for leaf, b in page for q in sc.apart(leaf.name, sc.place(f, leaf, b), b, page,
                                                       getattr(leaf.record, "parts", None),
                                                       getattr(leaf.record, "theta_at", None))]
    return SimpleNamespace(form=f, placed=placed)


@pytest.mark.parametrize("lang", ["uk", "en"])
def test_the_room_under_the_phase_diagram_holds_the_notes(tmp_path, lang):
    """Review 4, item 19: under the phase diagram, beside the ds/dφ and d²s/dφ² diagrams, 195 × 255
    mm stood blank (a square of 9 × 9 empty 20-mm cells). The notes stand there now, under the phase
    diagram they follow, the table by the title block under the profile: no empty square of 8 cells
    (160 mm) on the sheet; no two drawings' boxes meet; the profile larger than the phase diagram."""
    from graphplan.drawing.layout import boxes_apart
    path = tmp_path / "kn.toml"
    path.write_text(KNIFE, encoding="utf-8")
    sheet = _laid_sheet(path, lang)
    box = {p.name: p.box for p in sheet.placed}
    assert set(box) - {"given"} == {"diagrams", "phase", "profile", "table", "notes", "pressure"}, set(box)
    assert not boxes_apart(sheet.placed)
    ink = {p.name: p.record.bounds() for p in sheet.placed}
    assert ink["diagrams"][2] < ink["notes"][0] and ink["notes"][2] < ink["profile"][0]
    assert ink["notes"][3] < ink["phase"][1]
    area = {k: (b[2] - b[0]) * (b[3] - b[1]) for k, b in ink.items()}
    assert area["profile"] > area["phase"]
    share, empty = empty_share(sheet)
    assert _largest_blank(empty) < 8, (_largest_blank(empty), share)


def _figures(text: str) -> int:
    """Significant figures of a number as printed (0,398 → 3; 32,1 → 3; 0 → 1)."""
    digits = text.replace("−", "").replace(",", "").replace(".", "").lstrip("0")
    return max(1, len(digits))


@pytest.mark.parametrize("lang", ["uk", "en"])
def test_table_1_gives_the_rulers_reading_and_the_value_to_three_figures(tmp_path, lang):
    """Review 4, item 20: Table 1 printed s гр. = 0,3982 mm from a 1 mm reading (four figures out
    of a ruler's two). Now each graphical s and ds/dφ has the ordinate read beside it (mm, to the
    ruler's 0.5 mm) and the value to no more decimals than the reading supports (review 8: one
    count of decimals a column, so 0,38 from a 1 mm reading beside 31,98 from 84 mm), within half
    a unit of its last figure of the JSON's value (which keeps every digit)."""
    from graphplan.exact.cam import solve
    from graphplan.graphic.cam import construct
    from graphplan.report.cam import cam_json
    from graphplan.sheets.cam import positions_table
    path = tmp_path / "kn.toml"
    path.write_text(KNIFE, encoding="utf-8")
    sol = solve(load(path))
    doc = cam_json(sol, construct(sol), "")
    rec = positions_table(doc, lang)
    rows: dict[float, list] = {}
    for q in rec.items:
        if q.kind == "text":
            rows.setdefault(round(q.points[0][1], 3), []).append(q)
    body = sorted(([q.text for q in sorted(r, key=lambda q: q.points[0][0])] for r in rows.values() if len(r) == 14),
                  key=lambda r: r[0] != ("№" if lang == "uk" else "No."))
    head = body.pop(0)
    assert len(body) == len(doc["positions"])            # a row per division
    body.sort(key=lambda r: int(r[0]))
    ys, sg = head.index("y_{s}, " + ("мм" if lang == "uk" else "mm")), head.index("s " + ("гр." if lang == "uk" else "gr."))
    assert ys + 1 == sg
    for row, p in zip(body, doc["positions"]):
        read, value = row[ys], row[sg]
        mm = float(read.replace(",", ".").replace("−", "-"))
        assert mm == pytest.approx(p["graphical"]["s_mm"], abs=0.05) and mm * 2 == round(mm * 2)
        v = float(value.replace(",", ".").replace("−", "-"))
        s = p["graphical"]["s_m"] * 1000
        places = len(value.split("," if lang == "uk" else ".")[1]) if value != "0" else 0
        if mm:      # review 8: one count of decimals a column, the last within two places of μ_s × 0.5 mm
            assert 10.0 ** -places > abs(s / mm) * 0.5 / 100, (value, mm)
        assert v == pytest.approx(s, abs=0.5 * 10.0 ** -places + 1e-9), (value, s)


@pytest.mark.parametrize("H1, H2, shortest", [(24.0, 24.0, 15), (24.0, 24.0, 19), (47.0, 47.0, 40), (38.0, 37.0, 30)])
def test_the_poles_grow_ds_dphi_alone_keeping_mu_s(H1, H2, shortest):
    """The ds/dφ diagram alone taller (μ_{ds/dφ} ∝ H1) while μ_s ∝ H1·H2 stays within 2 %, never
    coarser: whole-millimetre pole distances in the lab's 15–50 mm, the shortest H1 that fits."""
    from graphplan.sheets.cam import _poles
    h1, h2 = _poles(H1, H2, lambda p: p[0] >= shortest)
    assert h1 is not None and h1 >= shortest and h1 == int(h1) and h2 == int(h2)
    assert 15 <= h1 < H1 and h2 <= 50
    assert 0.98 * H1 * H2 <= h1 * h2 <= H1 * H2
    better = [h for h in range(shortest, int(h1)) if 0.98 * H1 * H2 <= h * (H1 * H2 // h) <= H1 * H2
              and H1 * H2 // h <= 50]
    assert not better, better
    assert _poles(H1, H2, lambda p: False) == (None, None)


@pytest.mark.slow
@pytest.mark.parametrize("lang", ["uk", "en"])
def test_the_built_sheet_of_the_reviews_cam_is_filled_and_clean(tmp_path, lang):
    """The whole A1 sheet as `graphplan sheet` builds it (sizes searched, Table 1's rows of 8 mm):
    nothing a teacher sends back (compose.defects), the notes under the phase diagram, no empty
    square of 8 cells, and fewer empty cells than the composition review 4 graded (46 % of them
    by this count)."""
    path = tmp_path / "kn.toml"
    path.write_text(KNIFE, encoding="utf-8")
    sheet = _sheet(path, lang)
    assert defects(sheet) == []
    ink = {p.name: p.record.bounds() for p in sheet.placed}
    assert ink["notes"][3] < ink["phase"][1] and ink["diagrams"][2] < ink["notes"][0]
    share, empty = empty_share(sheet)
    assert _largest_blank(empty) < 8 and share < 0.45, (share, _largest_blank(empty))
