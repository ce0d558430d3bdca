"""Stop 62, helper wlab62: the energy–mass diagram's point numbers near their points. On DYN62_BALER's uk A1
dynamics sheet the points 11′, 11′′, 12 and 12′ crowd where the force profile ends: their dots overlap (12 is
0,5 mm from 11′′), so no leader could say which dot it pointed at, and point 12's number was set by the
placer's last resort 80 mm away on its own projection line, struck through by it (overprinted, with and
without the font). Now points whose dots overlap take one number between them (``coinciding``), as a student
letters coinciding points («0, 12»), and no number is set farther from its point than the placer's farthest
leader ring (``NUMBER_FARTHEST``): one that finds no place so near is left off."""
from __future__ import annotations

import functools
import math

import pytest
from conftest import scene_study
from review_scenes import DYN62_BALER, LINK61, LINK62

# the construction as each uk A1 sheet draws it (its ruler L, heights ×, ΔT(φ)'s own μ_T; the projections from
# its ΔT(φ) and I*(φ): the sheet's last call), read off the sheets built on this branch
SHEETS = {
    "baler": (DYN62_BALER, dict(L=210.0, size=0.8, energy=5.0), (-44.98245029739998, -93.60058358752937)),
    # LINK62: 6′ (184,4°) on 6 (180°+): «6; 6′» on one leader (two leaders on main, to dots 1,2 mm apart)
    "link62": (LINK62, dict(L=210.0, size=0.8, energy=0.25), (-40.98642381004365, -101.72119204835438)),
}


def _gap(box, z: complex) -> float:
    """The paper between a box (x0, y0, x1, y1) and a point."""
    return math.hypot(max(box[0] - z.real, 0.0, z.real - box[2]), max(box[1] - z.imag, 0.0, z.imag - box[3]))


def _members(text: str) -> list[str]:
    return [t for part in text.split("; ") for t in part.split(", ")]


@functools.cache
def _construction(name: str):
    """The sheet's construction of ``name`` and its energy–mass diagram (once per module)."""
    from graphplan.drawing.flywheel import energy_mass
    from graphplan.exact.dynamics import analyse
    from graphplan.graphic.flywheel import redrawn
    scene, kw, projections = SHEETS[name]
    f = redrawn(analyse(scene_study(scene), None), None, 0.5, **kw)
    return f, energy_mass(f, "uk", projections=projections)


@pytest.fixture(params=sorted(SHEETS))
def drawn(request):
    return (request.param, *_construction(request.param))


def test_coinciding_groups_the_points_whose_dots_overlap():
    """Chained by the dots' overlap (2 × 0,775 mm), each group in its first point's order."""
    from graphplan.drawing.flywheel import COINCIDE, NUMBER_FARTHEST, coinciding
    assert COINCIDE == pytest.approx(1.55) and NUMBER_FARTHEST == pytest.approx(32.0 * math.sqrt(2.0))
    pts = [0j, 5 + 0j, 1.0j, 2.0j, 5.5 + 0j, 10 + 0j, 3.6j]
    # 0 – 1j – 2j chained (1 mm steps), 3.6j 1,6 mm from 2j: apart; 5 and 5.5 together
    assert coinciding(pts) == [[0, 2, 3], [1, 4], [5], [6]]
    assert coinciding([]) == []


def test_every_point_number_of_the_energy_mass_curve_stands_by_its_point(drawn):
    """Every lettered point of the diagram (the divisions, every other where more than 24, and the added
    points) has its number exactly once, in one label with the points whose dots overlap its own, and that
    label within ``NUMBER_FARTHEST`` mm of paper (45,3: the placer's farthest leader ring, 32 mm, along a
    diagonal) of the point; a label of several numbers only where their dots overlap. The labels meet no line and no other label (``collisions``). On main the baler's 12 stood
    ~75–80 mm off, struck through by its projection."""
    _every_number_by_its_point(*drawn)


def _every_number_by_its_point(name, f, rec) -> None:
    from graphplan.drawing.labels import collisions
    farthest = 32.0 * math.sqrt(2.0)      # NUMBER_FARTHEST (on main too)
    coincide = 2.0 * 0.775                # COINCIDE: two dots' ink radii
    n = f.divisions
    every = 1
    while n / every > 24:
        every *= 2
    points = {str(j): complex(float(f.I[j]), float(f.dT[j])) for j in range(0, n, every)}
    points.update({f.added_label(j): complex(float(f.I_all[j]), float(f.dT_all[j])) for j in f.added})
    texts = [p for p in rec.items if p.kind == "text" and p.step.startswith(("point ", "added point number"))]
    seen: dict[str, object] = {}
    for p in texts:
        for m in _members(p.text):
            assert m in points, (name, p.text)
            assert m not in seen, (name, m, p.text)
            seen[m] = p
    assert sorted(seen) == sorted(points), (name, sorted(set(points) - set(seen)))
    for m, p in seen.items():
        assert _gap(p.ink(), points[m]) <= farthest + 1e-6, (name, m, p.text, p.ink(), points[m])
        others = [points[o] for o in _members(p.text) if o != m]
        if others:     # merged only with a point whose dot overlaps (chained)
            assert min(abs(points[m] - z) for z in others) < coincide, (name, p.text)
    assert collisions(rec) == [], name


@pytest.mark.slow
def test_the_balers_numbers_stand_by_their_points_in_the_sheets_band():
    """The band as the A1 sheet composes it (``sheets.dynamics.band``: the energy–mass diagram's side moved
    left while its lettering runs past it, six attempts): on main the baler's 12 went past the side at each
    attempt and ended 77 mm from its point, on its own projection line (~40 s on a loaded machine)."""
    from graphplan.sheets.dynamics import band
    f, _ = _construction("baler")
    parts, _ = band(f, "uk", 210.0)
    _every_number_by_its_point("baler band", f, parts["wittenbauer"])


def test_the_balers_crowded_end_of_stroke_is_one_label():
    """The baler's 11′, 11′′, 12 and 12′ (dots 1,5, 0,5 and 1,0 mm apart) lettered once, as the draftsman does."""
    _, rec = _construction("baler")
    assert "11′; 11′′; 12; 12′" in [p.text for p in rec.items if p.kind == "text"]
