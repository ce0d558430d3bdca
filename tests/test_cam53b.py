"""Stop 53 (cam53b): Table 1 prints each column to one count of decimals. Stop 54: its zeros the bare
number 0, as the seeds' tables write a zero (seed 000's Tables 2.2–2.3, seed 004's Table 3) and the
kinematics and dynamics tables do. Checked against the exact law: a dwell's s and ds/dφ are zero by the
law itself."""
from __future__ import annotations

import re
import tomllib

import pytest

from graphplan.exact.cam import solve
from graphplan.graphic.cam import construct
from graphplan.model.cam import build
from graphplan.report.cam import cam_json, table_columns
from review_scenes import CAM52

NUMBER = re.compile(r"^−?\d+(?:,(\d+))?\*?$")


@pytest.fixture(scope="module")
def cam52_doc():
    sol = solve(build(tomllib.loads(CAM52), "<cam52>"))
    g = construct(sol, measure=True, series="rad")
    return cam_json(sol, g, "")


def _places(cell: str) -> int:
    m = NUMBER.match(cell)
    assert m, cell
    return len(m.group(1) or "")


@pytest.mark.parametrize("column", ["s", "s_gr", "v", "v_gr", "R", "R_gr"])
def test_table_zeros_are_the_bare_0(cam52_doc, column):
    cells = table_columns(cam52_doc, "uk")[column]
    plain = [c for c in cells if "→" not in c and c not in ("—", "0")]
    assert len({_places(c) for c in plain}) == 1, plain
    # the law's zeros: s at the near dwell (0°, 290°…360°), ds/dφ on the far dwell (150°…190°)
    where = {"s": lambda phi: phi < 1e-9 or phi > 290.0 - 1e-9, "v": lambda phi: 150.0 - 1e-9 < phi < 190.0 + 1e-9}
    if column in where:
        zero = [c for c, p in zip(cells, cam52_doc["positions"]) if where[column](p["phi_deg"])]
        assert zero and all(c == "0" for c in zero), zero


def _sheet(scene: str, fmt: str, lang: str):
    from graphplan.sheets.cam import build_cam_sheet
    from graphplan.sheets.compose import SheetOptions, defects
    from graphplan.sheets.form import form
    sheet = build_cam_sheet(build(tomllib.loads(scene), "<scene>"), form(fmt), SheetOptions(lang=lang, sheet="cam"))
    assert defects(sheet) == []
    return sheet


def _height(rec) -> float:
    b = rec.bounds()
    return b[3] - b[1]


@pytest.mark.slow
@pytest.mark.parametrize("name,fmt,lang,sheets,tall", [("REVIEW_CAM52", "A2", "uk", 3, 120.0),
                                                       ("CAM48", "A3", "en", 4, 60.0)])
def test_a_sets_pressure_angle_takes_its_tallest_placement(name, fmt, lang, sheets, tall):
    """Of the placements of ϑ(φ) at the diagrams' μ_φ that take no sheet more, the one that draws it
    tallest (stop 53): review 52's A2 set drew it at 10 °/мм (about 7 mm over ±35°) under the phase
    diagram where the table's sheet takes 0.4 °/мм; CAM48's A3 set at 5 °/мм under ψ where the profile's
    sheet takes 2 °/мм. The drawn diagram measured, the set's sheets counted."""
    import review_scenes
    sheet = _sheet(getattr(review_scenes, name), fmt, lang)
    assert len(sheet.pages) == sheets
    theta = [p.record for page in sheet.pages for p in page.placed if p.name == "pressure"]
    assert len(theta) == 1 and _height(theta[0]) >= tall, [_height(t) for t in theta]


@pytest.mark.slow
def test_cam53s_a1_table_spans_the_profiles_column():
    """CAM53's A1 sheet: the profile (1:1, 344 mm) leaves Table 1 no room for closer rows; at its own size
    it stood 196 mm wide in that column, 147 × 162 mm blank beside it — now its columns widened to span
    it (at most 1.5 times): the blank beside it under 60 mm."""
    from review_scenes import CAM53
    sheet = _sheet(CAM53, "A1", "uk")
    boxes = {p.name: p.box for p in sheet.pages[0].placed}
    tab = next(p.record for p in sheet.pages[0].placed if p.name == "table").bounds()
    assert boxes["profile"][2] - tab[2] < 60.0, (boxes["profile"], tab)
