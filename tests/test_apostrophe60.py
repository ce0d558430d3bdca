"""The English apostrophe after b, h, k (stop 60): tucked over the letter's open right (stop 58), the letter
after it was tucked under it too, and the apostrophe hung over that letter's shoulder — «crank's» read
«crankś». A letter after such a tucked apostrophe now stands clear of it; after a prime's full advance
(«pair's», «train's»: an apostrophe after r, n, a digit is set as a prime) the s stays tucked as before
(stop 59 moved every letter after an English apostrophe and the English type-B gear sheet read 2 overprinted
words). Measured on where the SVG sets each glyph (drawing.svg.glyph_xs) and the font's own ink boxes."""
from __future__ import annotations

import pytest


def _inks(word: str, size: float) -> list[tuple[float, float] | None]:
    """Each drawn character's ink (x from, x to; mm) as the SVG sets it: its x and the font's box (None:
    a blank)."""
    from graphplan.drawing.svg import glyph_xs
    from graphplan.graphic.record import _metrics, em, lettering
    m, e = _metrics(), em(size)
    drawn = lettering(word)
    return [None if m["boxes"][c] is None else (x + m["boxes"][c][0] * e, x + m["boxes"][c][2] * e)
            for c, x in zip(drawn, glyph_xs(drawn, size, 0.0))]


@pytest.mark.parametrize("size", [2.5, 3.5, 4.747])
@pytest.mark.parametrize("word", ["crank's", "lab's", "link's", "the bench's", "Hook's"])
def test_the_letter_after_an_apostrophe_tucked_over_b_h_k_stands_clear_of_it(word, size):
    """The apostrophe stands over the b, h or k's open right (its ink begins left of that letter's ink's
    end), and the s after it begins at least 0.12 em right of the apostrophe's ink: not under it."""
    from graphplan.graphic.record import em
    ink = _inks(word, size)
    i = word.index("'")
    assert ink[i][0] < ink[i - 1][1]                                  # tucked over k's arm (stop 58)
    assert ink[i + 1][0] - ink[i][1] >= 0.12 * em(size)                # the s clear of it


@pytest.mark.parametrize("size", [2.5, 3.5, 4.747])
@pytest.mark.parametrize("word", ["pair's", "train's", "Table 1's"])
def test_after_a_prime_the_s_stays_tucked_under_it(word, size):
    """After r, n or a digit the ASCII ' is a prime set at its full advance (not tucked), and the s after it
    begins APOSTROPHE_GAP (0.03 em) across from its ink — as before stop 60 (stop 59's untucked s read as a
    word of its own)."""
    from graphplan.graphic.record import APOSTROPHE_GAP, em
    ink = _inks(word, size)
    i = word.index("'")
    assert ink[i][0] > ink[i - 1][1]                                   # the prime: not over its letter
    assert ink[i + 1][0] - ink[i][1] == pytest.approx(APOSTROPHE_GAP * em(size), abs=1e-9)


@pytest.mark.parametrize("size", [2.5, 3.5, 4.747])
def test_the_words_with_apostrophes_read_as_one_word_each(size):
    """Rendered and grouped into words as overprint.py groups ink (the 0.8-mm closing at 4 px/mm), wherever
    the text falls on the pixel grid: «crank's», «lab's», «bench's» one word each, «pair's» too at the notes'
    3.5 mm and under; unclosed, «k's» is three pieces of ink (the apostrophe touches neither letter). (At 4.7-mm letters «pair's» and «train's» already read as two
    pieces before stop 60: the prime after r, n at its full advance, 0.10–0.11 em across; not changed.)"""
    from test_cam56 import _words
    for word in ("crank's", "lab's", "bench's") + (("pair's",) if size <= 3.5 else ()):
        for dx in (0.0, 0.1, 0.2):
            for dy in (0.0, 0.2):
                assert _words(word, size, dx, dy) == 1, (word, dx, dy)
    assert _words("k's", size, 0.0, 0.0, closing=False) == 3
