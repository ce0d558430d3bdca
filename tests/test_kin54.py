"""Stop 54 (kinematics): the jaw crusher (LINK54) — the tables' column leaves no blank zone where a
composition drawing no smaller has none (LAYOUT.md: no big empty areas), and the diagrams' advice
names a sharp bend only where the chords' own error is what misses the lab's 5 %."""
from __future__ import annotations

import pytest

import review_scenes
from conftest import scene_study
from graphplan.graphic.diagrams import LAB_LIMIT, chord_diagrams, why_not


@pytest.mark.parametrize("name, kw", [
    ("INCLINED_ROCKER53", dict(L=240.0, H1=42.0, H2=34.0, height=80.0, correct=True)),
    ("INCLINED_ROCKER53", dict(L=240.0, H1=42.0, H2=34.0, height=80.0, correct=True, divisions=8)),
])
def test_a_sharp_bend_is_named_only_where_the_chords_own_error_misses_the_limit(name, kw):
    """The exact drawing's largest |δ| at the positions (the chords' own error, ruler 0) decides:
    the inclined crank-slider's a reads 8.3 % at 12 divisions with the 0.5-mm ruler, 1.0 % exact —
    the ruler's, not a bend's; at 8 divisions (45° steps) its chords alone read 7.8 %."""
    d = chord_diagrams(scene_study(getattr(review_scenes, name)), precision=0.5, lang="en", **kw)
    own = d.worst_pct(d.exact)
    text = why_not(d, "en")
    assert "own error" in text          # more divisions read worse here: the advice says why
    assert ("a bend sharp" in text) == (own > LAB_LIMIT)
    assert ("згин, крутий" in why_not(d, "uk")) == (own > LAB_LIMIT)
