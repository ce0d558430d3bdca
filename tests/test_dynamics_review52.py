"""Stop 52's dynamics sheet: LINK52 (tests/review_scenes.py), the eight-bar whose coulisse drives a
slider against 1200 N on its working stroke. What grading marked: the band's φ scales printed as
"μ_φ = 2π/260,5" and "μ_φ = 2π/115,5" beside the notes' "μ_φ = 2π/L" (three values under one name,
two of them over axes no student would rule), and the energy–mass diagram's |kl| dimension line
drawn without its value. Checked against the drawing itself: each printed scale is 2π over the span
its division points are drawn over, |kl| the distance between the drawn points k and l."""
from __future__ import annotations

import math
import re

import pytest
from conftest import scene_study
from review_scenes import DYN_OWN52, LINK52


@pytest.fixture(scope="module")
def link52():
    """LINK52's construction at L = 330 mm, heights × 1 (one of the scales its A1 sheet tries)."""
    from graphplan.exact.dynamics import analyse
    from graphplan.graphic.flywheel import redrawn
    dyn = analyse(scene_study(LINK52), None)
    return redrawn(dyn, None, 0.5, L=330.0, size=1.0)


def _texts(rec, start: str) -> list[str]:
    from graphplan.util.markup import plain
    return [plain(p.text).replace("\u00a0", " ") for p in rec.items if p.kind == "text"
            and plain(p.text).startswith(start)]


@pytest.mark.parametrize("L", [330.0, 290.0, 250.0, 210.0, 170.0, 150.0, 130.0, 120.0, 333.3])
def test_the_bands_phi_axes_are_round_lengths(L):
    """Every φ axis the band is tried at is L itself or a whole multiple of 10 mm, no longer than L."""
    from graphplan.sheets.dynamics import _lengths
    got = _lengths(L)
    assert got and got[0] == L
    for g in got[1:]:
        assert g < L and g % 10.0 == pytest.approx(0.0, abs=1e-9), got


@pytest.fixture(scope="module")
def own52():
    """DYN_OWN52 (dyn52's own six-bar lifting table, 16 divisions) as its A1 sheet draws it (L = 210
    mm, heights × 0.8)."""
    from graphplan.exact.dynamics import analyse
    from graphplan.graphic.flywheel import redrawn
    return redrawn(analyse(scene_study(DYN_OWN52), None), None, 0.5, L=210.0, size=0.8)


@pytest.mark.parametrize("lang", ["uk", "en"])
@pytest.mark.parametrize("which, length, el", [("link52", 110.0, 260.0), ("own52", 80.0, 210.0)])
def test_each_phi_scale_of_the_band_has_its_own_name_and_is_two_pi_over_its_drawn_axis(request, which, length,
                                                                                      el, lang):
    """ΔT(φ) widened over the turned I*(φ) (LINK52: 260 over 110 mm; the own six-bar's 16 divisions:
    210 over 80): ΔT(φ) states μ′_φ, I*(φ) μ″_φ, neither the moments' unprimed μ_φ; each value 2π
    over the span its points are drawn over."""
    from graphplan.sheets.dynamics import band
    parts, _ = band(request.getfixturevalue(which), lang, length, el)
    for name, step, axis, prime in (("energy", "ΔT read", 0, "′"), ("inertia", "I*_m read", 1, "″")):
        rec = parts[name]
        at = [p.points[0][axis] for p in rec.items if p.kind == "point" and p.step == step]
        span = max(at) - min(at)
        said = _texts(rec, f"μ{prime}_φ = 2π/")
        assert len(said) == 1, (name, said)
        m = re.fullmatch(r"μ.?_φ = 2π/(\d+) = (\d+[.,]\d+) (?:рад|rad)/(?:мм|mm)", said[0])
        assert m, said[0]
        assert float(m.group(1)) == pytest.approx(span, abs=1e-6)
        assert float(m.group(2).replace(",", ".")) == pytest.approx(2 * math.pi / span, rel=5e-4)
        assert not _texts(rec, "μ_φ"), name          # the notes' μ_φ = 2π/L is the moments' alone


@pytest.mark.parametrize("lang", ["uk", "en"])
def test_the_energy_mass_diagram_in_the_band_letters_kl_as_drawn(link52, lang):
    """The band's energy–mass diagram (projections drawn, its I* axis graduated on a scale line)
    letters |kl| = … mm: the distance between its drawn points k and l, as the notes read it."""
    from graphplan.sheets.dynamics import band
    witt = band(link52, lang, 110.0, 260.0)[0]["wittenbauer"]
    k, l_ = ([p.points[0][1] for p in witt.items if p.kind == "point" and p.step == s] for s in ("k", "l"))
    said = _texts(witt, "|kl| = ")
    assert len(said) == 1, said
    value = float(re.search(r"(\d+(?:[.,]\d+)?)", said[0]).group(1).replace(",", "."))
    assert value == pytest.approx(abs(k[0] - l_[0]), abs=0.5)      # read with the ruler to 0,5 mm
    assert value == pytest.approx(link52.kl, abs=1e-9)


@pytest.mark.parametrize("lang", ["uk", "en"])
def test_each_axis_letters_its_values_to_one_count_of_decimals(link52, lang):
    """A scale's numbers to one count of decimals: "0,02 … 0,10 0,12" (it lettered 0,1), "12,8
    13,0 13,2" (it lettered 13) — on every graduated axis of the sheet's diagrams."""
    from graphplan.drawing.flywheel import moments_record, speed_record
    from graphplan.sheets.dynamics import band
    from graphplan.util.markup import plain
    recs = [moments_record(link52, lang), speed_record(link52, lang), *band(link52, lang, 110.0, 260.0)[0].values()]
    axes = 0
    for rec in recs:
        by_axis: dict[tuple[str, float], list[str]] = {}
        for p in rec.items:
            if p.kind == "text" and (p.step.endswith("graduation") or p.step == "ω ticks") and plain(p.text) != "0":
                x, y = p.points[0]
                horizontal = p.step.startswith("I*")          # I* runs along x: its numbers share a row
                key = (p.step, round(y if horizontal else p.ink()[2], 1))
                by_axis.setdefault(key, []).append(plain(p.text))
        for key, texts in by_axis.items():
            if len(texts) < 2:
                continue
            axes += 1
            decimals = {len(t.split("," if lang == "uk" else ".")[1]) if ("," if lang == "uk" else ".") in t else 0
                        for t in texts}
            assert len(decimals) == 1, (key, texts)
    assert axes >= 5
