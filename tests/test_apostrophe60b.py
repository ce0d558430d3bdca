"""Review 60 #5 and #6 (cam60b).

#5: the cam sheet's «*» legend pointed at «табл. 2» / "Table 2", a table no cam sheet has (its only table is Table 1),
and Table 1's ϑ cells past [ϑ] (review 60's scene c: row 5, 30,8° > 30°) carried no «*» where the notes star the
phase's largest (30,85°*). Each «*» has its meaning in the legend, the legend names only Table 1, and a ϑ cell is
starred exactly when its printed value is past its phase's allowed [ϑ].

#6: an ASCII ' between two letters («rise's», «plan's») was set as a prime (at its full advance, 0.10–0.11 em across
and 0.15 em above the letter before): overprint.py's 0.8-mm closing took it for a mark of its own inside the word's
box on the English cam and forces sheets. Between letters it is now an apostrophe, tucked as the Ukrainian one
(over a round top, a bowl or shoulder, OPEN_TUCK further); after a digit or at a word's end it stays a prime."""
from __future__ import annotations

import re

import pytest

from review_scenes import CAM60B_REVIEW_C

# ' after every class of letter: round tops (e, n, m, a, o, p, s, g, c), square ones (r, t, x, w, u, y), tall (d, l, k, b, h)
WORDS = ("rise's", "plan's", "cam's", "one's", "group's", "axis's", "pair's", "set's", "Box's", "law's",
         "menu's", "family's", "field's", "wheel's", "crank's", "lab's", "drawing's", "disc's")


@pytest.mark.parametrize("size", [3.5, 4.747])
def test_a_word_with_an_apostrophe_reads_as_one_word(size):
    """Rendered and grouped as overprint.py groups ink (the 0.8-mm closing at 4 px/mm) at three placings on the
    pixel grid: each word as many words as without its apostrophe (before: «rise's», «cam's», «one's», «axis's» one
    more at the A1 notes' 4.7 mm; «plan» itself is two there, its l and a 0.8 mm apart)."""
    from test_cam56 import _words
    for word in WORDS:
        for dx in (0.0, 0.1, 0.2):
            assert _words(word, size, dx, 0.1) == _words(word.replace("'", ""), size, dx, 0.1), (word, dx)


@pytest.mark.parametrize("size", [2.5, 4.747])
def test_between_letters_the_ascii_quote_is_tucked_and_after_a_digit_it_is_a_prime(size):
    """Measured on the SVG's glyph positions and the font's ink boxes: in «rise's» the apostrophe's ink begins
    within APOSTROPHE_GAP of the e's box (tucked; as a prime it began 0.11 em right of it), the s's ink no more
    than APOSTROPHE_GAP right of the apostrophe's; «Table 1's» and «z'» keep the prime at its full advance."""
    from test_apostrophe60 import _inks
    from graphplan.graphic.record import APOSTROPHE_GAP, em
    e = em(size)
    for word in ("rise's", "plan's", "pair's", "group's"):
        ink = _inks(word, size)
        i = word.index("'")
        assert ink[i][0] - ink[i - 1][1] <= APOSTROPHE_GAP * e + 1e-9, word
        assert ink[i + 1][0] - ink[i][1] <= APOSTROPHE_GAP * e + 1e-9, word
    for word in ("Table 1's", "z'"):
        ink = _inks(word, size)
        i = word.index("'")
        assert ink[i][0] - ink[i - 1][1] > 0.09 * e, word             # the prime stands after its letter


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
