"""The invariant a teacher checks first (review 12 #1–3): every element of a sheet inside its drawing
field — the frame's inside, clear of the title block — read off the SVG alone (tests/svgboxes.py:
each word's ink from the font file's outlines at its glyphs' x, each line from its coordinates).
Review 12's six-bar drew its A1 force sheet 852 × 581 mm on a field of 806 × 574: Table 3's last
column beyond the paper's edge, two note lines through the frame, a hodograph's caption on it."""
from __future__ import annotations

import pytest

import review_scenes
from conftest import scene_study
from svgboxes import off_field

SVG = ('<svg xmlns="http://www.w3.org/2000/svg" xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape" '
       'width="841mm" height="594mm" viewBox="0 0 841 594">'
       '<g inkscape:label="frame"><polygon points="20,589 836,589 836,5 20,5" /></g>'
       '<g inkscape:label="tables">{}</g></svg>')
WORD = '<text font-size="3.5" text-anchor="start" x="{x}" y="{y}">{text}</text>'


def test_the_check_reads_words_and_lines_past_the_field_off_the_svg():
    """A word whose last glyphs pass the field's right edge (x 831 mm) or sit on the title block, a
    table's rule past the paper: each named; the same word inside: none. The font's own outlines
    set a word's extent: «R54» starting at 827 mm ends past 831, at 820 it does not."""
    from graphplan.sheets.form import form
    f = form("A1")
    inside = WORD.format(x=820, y=20, text="R54") + '<line x1="700" y1="16" x2="830" y2="16" />'
    assert off_field(SVG.format(inside), f) == []
    past = [WORD.format(x=827, y=20, text="R54"), '<line x1="700" y1="16" x2="856" y2="16" />',
            WORD.format(x=700, y=570, text="Таблиця"), WORD.format(x=400, y=588, text="Годограф")]
    out = off_field(SVG.format("".join(past)), f)
    assert len(out) == 4, out
    assert "'R54'" in out[0] and "outside the field" in out[0]
    assert "on the title block" in out[2]
    # the glyphs' x as the SVG writes them, one per glyph: the last one's outline ends the word
    glyphs = '<text font-size="3.5" text-anchor="start" x="826.0 828.3 830.6" y="20">R54</text>'
    assert off_field(SVG.format(glyphs), f) != []


# review 12's scene (the overflow's regression) and two earlier reviews' mechanisms; slow (4–15 s each):
# the default run reads the shaper's force sheet so (test_sheet.test_force_sheet_renders)
FORCE_SCENES = ["SIXBAR12_SHORT", "SIXBAR12", "COMPRESSOR11", "COULISSE8"]   # SHORT: O3E 0.42 as the review drew it


@pytest.mark.parametrize("name", FORCE_SCENES)
def test_a_force_sheet_keeps_every_element_in_its_field(name):
    """The A1 force sheet of review 12's six-bar (whose composition ran out of the frame after four
    trials) and of two earlier reviews' mechanisms: every word, table rule and line inside the field,
    none on the title block — read off the SVG — and the records' own check (``defects``) clean."""
    from graphplan.sheets.compose import SheetOptions, defects
    from graphplan.sheets.forces import build_forces_sheet
    from graphplan.sheets.form import form
    sheet = build_forces_sheet(scene_study(getattr(review_scenes, name)), form("A1"),
                               SheetOptions(precision=0.5, lang="uk", sheet="forces"))
    assert off_field(sheet.svg(), sheet.form) == []
    assert defects(sheet) == []
