"""The force sheet's lettering read as a teacher reads it (review6 #7, review7 #10, #18): a force
plan's sides along one line lettered on its two sides, a component the ruler cannot draw named
with its bound."""
from __future__ import annotations

import pytest

from conftest import scene_study
from review_scenes import SIXBAR7


@pytest.fixture(scope="module")
def sixbar_fp():
    from graphplan.sheets import forces as sf
    from graphplan.sheets.compose import SheetOptions
    return sf.ForceDrafter(scene_study(SIXBAR7), SheetOptions(precision=0.5, sheet="forces")).fp()


def _side(a: complex, b: complex, z: complex) -> float:
    return ((b - a).conjugate() * (z - a)).imag


def test_sides_along_one_line_are_lettered_on_its_two_sides(sixbar_fp):
    """Review7 #10: on group II(4-5)'s plan R24, R^n24 and R45 run along one line and were lettered
    in one column on one side. R^n24 coincides with R24 (R^τ24 is 0.08 mm): one letter names both,
    and R45's letter stands on the other side of the line."""
    from graphplan.drawing.forces import polygon_record
    gp = next(g for g in sixbar_fp.groups if g.label == "II(4-5)")
    r24 = next(s for s in gp.sides if s.name == "R24")
    r45 = next(s for s in gp.sides if s.name == "R45")
    assert abs(_side(r24.start, r24.end, r45.end)) / abs(r24.end - r24.start) < 0.1   # one line, truly
    rec = polygon_record(sixbar_fp, gp, "uk")
    texts = {q.text: q for q in rec.items if q.kind == "text"}
    both = next(t for t in texts if "R_{24}" in t and "R^{n}_{24}" in t)
    assert "R^{n}_{24}" not in [t for t in texts if t != both]      # not lettered twice
    centre = {t: complex(0.5 * (q.bounds()[0] + q.bounds()[2]), 0.5 * (q.bounds()[1] + q.bounds()[3]))
              for t, q in texts.items()}
    s1, s2 = (_side(r24.start, r24.end, centre[t]) for t in (both, "R_{45}"))
    assert s1 * s2 < 0


def test_a_component_below_the_ruler_is_named_with_its_bound(sixbar_fp):
    """Review7 #10: R^τ24 = −1.99 N is 0.08 mm at μF = 25 N/mm — no side — and the plan's note named
    only G4, Φ4. The note now names it below the ruler's 0.5 mm, in both languages."""
    from graphplan.drawing.forces import polygon_record
    gp = next(g for g in sixbar_fp.groups if g.label == "II(4-5)")
    eq = next(e for e in gp.equations if e.unknown == "R24τ")
    mu_F = gp.mu_F or sixbar_fp.mu_F
    assert 0 < abs(eq.result) / mu_F < 0.25            # the ruler reads it as 0 mm
    assert all(s.name != "R24τ" for s in gp.sides)
    for lang, mm in (("uk", "0,5 мм"), ("en", "0.5 mm")):
        caption = [q.text for q in polygon_record(sixbar_fp, gp, lang).items if q.kind == "text" and "μ_F" in q.text][0]
        assert f"R^{{τ}}_{{24}} < {mm}" in caption
