"""Review 60 #5 and #6 (cam60b).

#5: the cam sheet's «*» legend pointed at «табл. 2» / "Table 2", a table no cam sheet has (its only table is Table 1),
and Table 1's ϑ cells past [ϑ] (review 60's scene c: row 5, 30,8° > 30°) carried no «*» where the notes star the
phase's largest (30,85°*). Each «*» has its meaning in the legend, the legend names only Table 1, and a ϑ cell is
starred exactly when its printed value is past its phase's allowed [ϑ].

#6 (overprint.py's 1 word at «rise's» on the English cam sheet): cam60b tucked an ASCII ' between letters over a round
top, which read «phasés» at the A1 notes' 4.7-mm letters; the lead reverted it and the cam's notes say «the pressure
angle of the rise», «the end of the phase» instead (no possessive where the overprint was found)."""
from __future__ import annotations

import re

import pytest

from review_scenes import CAM60B_REVIEW_C


def _number(cell: str) -> float:
    return float(cell.rstrip("*").replace(",", ".").replace("−", "-"))


@pytest.fixture(scope="module")
def review_c(tmp_path_factory):
    from graphplan.exact.cam import solve
    from graphplan.graphic.cam import construct
    from graphplan.model.cam import load
    from graphplan.report.cam import cam_json
    path = tmp_path_factory.mktemp("cam60b") / "c.toml"
    path.write_text(CAM60B_REVIEW_C, encoding="utf-8")
    sol = solve(load(path))
    g = construct(sol, series="rad")
    return sol, cam_json(sol, g, "")


@pytest.mark.parametrize("lang", ["uk", "en"])
def test_every_theta_past_its_allowed_is_starred_and_the_legend_names_only_table_1(review_c, lang):
    from graphplan.report.cam import table_columns, table_rows
    from graphplan.sheets.cam import notes, positions_table
    sol, doc = review_c
    cols = table_columns(doc, lang)
    allowed = doc["pressure_angle_allowed_deg"]
    starred = 0
    for j in table_rows(doc):
        limit = allowed[doc["positions"][j]["phase"]]
        for c in ("theta", "theta_gr"):
            cell = cols[c][j]
            assert cell.endswith("*") == (abs(_number(cell)) > limit), (j, cell, limit)
            starred += cell.endswith("*")
    assert starred >= 2                       # row 5: 30,8 and 31,0 over [ϑ] = 30° (the review's reading)
    lines = notes(doc, lang, sol.cam)
    (legend,) = [x for x in lines if x.startswith("* — ")]
    named = {int(n) for n in re.findall(r"(?:табл\.|Table)\s*(\d+)", legend)}
    title = next(q.text for q in positions_table(doc, lang).items if q.kind == "text" and
                 re.match(r"(Таблиця|Table) \d", q.text or ""))
    assert named == {int(re.match(r"\D+(\d+)", title).group(1))} == {1}
    assert ("кут тиску понад допустимий" if lang == "uk" else "pressure angle past the allowed") in legend


def test_the_english_cam_notes_name_the_phases_without_a_possessive():
    """Where overprint.py found «rise's» (review 60's scene c, e = −6 mm): the offset's note says «the pressure angle
    of the rise … that of the return», and a phase's end is «the end of the phase» — no ' in those notes."""
    from graphplan.report.cam import WORDS as CW
    en = CW["en"]
    for k in ("offset_side", "angle_end", "closing_one"):
        assert all("'" not in x for x in ((en[k],) if isinstance(en[k], str) else en[k])), k
