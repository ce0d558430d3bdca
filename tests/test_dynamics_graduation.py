"""Every dynamics diagram graduates its ordinate axes in values (review 5 #14, review 3 #3/#12: the
M*_c/M*_d, A, ΔT and I* axes carried no values, only μ in the notes): round values (1, 2, 2,5, 5
×10^k steps) whose ticks stand where value/μ puts them, at least 8 mm apart, at least two values
lettered on each axis as one run (every tick's, or every 2nd, 5th, 10th), none touching a line or
other lettering, in both languages; the energy–mass diagram's ΔT axis ticked at ΔT(φ)'s heights;
values on one side of their axis."""
from __future__ import annotations

import math

import pytest

from conftest import example

ROUND = (1.0, 2.0, 2.5, 5.0)


@pytest.fixture(scope="module")
def flywheel():
    from graphplan.exact.dynamics import analyse
    from graphplan.graphic.flywheel import construct
    return construct(analyse(example("slotter"), None), None, 0.5, L=200.0)


def _records(f, lang):
    from graphplan.drawing.flywheel import (energy_projected, energy_record, inertia_record, inertia_turned,
                                            moments_record, wittenbauer_record)
    return {"moments": moments_record(f, lang), "energy": energy_projected(f, lang, 150.0, 170.0),
            "wittenbauer": wittenbauer_record(f, lang, projections=(-20.0, -10.0)),
            "inertia": inertia_turned(f, lang, 150.0, 10.0),
            "ΔT(φ) alone": energy_record(f, lang), "I*(φ) alone": inertia_record(f, lang)}


def _value(text: str) -> float:
    return float(text.replace(",", ".").replace("−", "-"))


def _axis(rec, step: str, vertical: bool = True):
    """(value lettered, where its tick stands along the axis) of an axis's graduation ``step``."""
    ticks = [p for p in rec.items if p.kind == "segment" and p.step == step]
    texts = [p for p in rec.items if p.kind == "text" and p.step == step]
    along = [(p.points[0][1] if vertical else p.points[0][0]) for p in ticks]
    out = []
    for t in texts:                      # each value beside its own tick (the nearest along the axis)
        x, y = t.points[0]
        c = 0.5 * (t.ink()[1] + t.ink()[3]) if vertical else x
        out.append((_value(t.text), min(along, key=lambda a: abs(a - c))))
    return out, along


def _check(values, along, mu, origin=0.0, least=2):
    assert len(values) >= least, values
    if not values:
        return
    steps = sorted(along)
    assert min(b - a for a, b in zip(steps, steps[1:])) >= 8.0 - 1e-9
    for v, at in values:
        assert v * 1.0 == pytest.approx((at - origin) * mu, rel=1e-9, abs=1e-9)
    step = min(abs(b - a) for a, b in zip(steps, steps[1:])) * mu
    e = 10 ** math.floor(math.log10(step) + 1e-12)
    assert any(abs(step / e - m) < 1e-6 for m in ROUND), step
    for v, _ in values:
        assert abs(v / step - round(v / step)) < 1e-6, (v, step)
    shown = sorted(v for v, _ in values)           # lettered as a draftsman letters major ticks: a run
    gaps = {round(b - a, 9) for a, b in zip(shown, shown[1:])}     # of one step, no value skipped
    assert len(gaps) == 1 and any(abs(min(gaps) / step - m) < 1e-6 for m in (1, 2, 4, 5, 10)), shown
    gap = min(gaps)                                # past every 2nd tick the lettered step is round itself
    ge = 10 ** math.floor(math.log10(gap) + 1e-12)   # (0,1 0,2 over ticks every 0,025, not 0,125 0,25)
    assert gap / step <= 2 + 1e-6 or any(abs(gap / ge - m) < 1e-6 for m in ROUND), shown


@pytest.mark.parametrize("lang", ["uk", "en"])
def test_every_ordinate_axis_is_graduated_in_round_values_where_mu_puts_them(flywheel, lang):
    f = flywheel
    recs = _records(f, lang)
    m = recs["moments"]
    _check(*_axis(m, "M graduation"), f.mu_M)
    a_axis = [p for p in m.items if p.kind == "vector" and p.step == "axes A"
              and abs(p.points[0][1] - p.points[1][1]) < 1e-9][0]      # the work diagram's φ axis
    _check(*_axis(m, "A graduation"), f.mu_A, origin=a_axis.points[0][1])
    _check(*_axis(recs["energy"], "ΔT graduation"), f.mu_T)
    w = recs["wittenbauer"]
    # the energy–mass diagram's axes lettered too (review 8: its I* axis had ticks and no values), among
    # its projections where they crowd it (broken under the values)
    _check(*_axis(w, "I* graduation", vertical=False), f.mu_I)
    # its ΔT axis ticked at ΔT(φ)'s values (the same μ_T, the same heights) and lettered
    lettered, ticks = _axis(w, "ΔT graduation")
    _check(lettered, ticks, f.mu_T)
    beside = [at * f.mu_T for _, at in _axis(recs["energy"], "ΔT graduation")[0]]
    assert len(ticks) >= 2 and {round(t * f.mu_T, 6) for t in ticks} >= {round(v, 6) for v in beside}
    i_values = [(_value(p.text), p.points[0][0]) for p in recs["inertia"].items
                if p.kind == "text" and p.step == "I* graduation"]
    assert len(i_values) >= 2 and all(v == pytest.approx(x * f.mu_I) for v, x in i_values)


@pytest.mark.parametrize("lang", ["uk", "en"])
def test_no_graduation_value_touches_a_line_or_lettering(flywheel, lang):
    from graphplan.drawing.labels import collisions
    for name, rec in _records(flywheel, lang).items():
        hits = [c for c in collisions(rec) if any(
            c.startswith(repr(p.text)) for p in rec.items if p.kind == "text" and p.step.endswith("graduation"))]
        assert hits == [], (name, hits[:3])


def test_the_moment_and_work_axes_carry_their_units(flywheel):
    from graphplan.drawing.flywheel import moments_record
    for lang, nm, j in (("uk", "Н·м", "Дж"), ("en", "N·m", "J")):
        texts = [p.text for p in moments_record(flywheel, lang).items if p.kind == "text"
                 and p.step in ("axes M", "axes A")]
        assert any(t.endswith(", " + nm) for t in texts) and any(t.endswith(", " + j) for t in texts), texts


@pytest.mark.parametrize("lang", ["uk", "en"])
def test_the_speed_extremes_stay_out_of_the_tick_column(flywheel, lang):
    """Stop 49: the slotter's ω_max (at φ ≈ 5°, the steep motor curve on its right) was lettered left
    of the ω axis among the ticks' values, where it reads as one of them. Each extreme's label now
    stands right of the axis — its ink, and its leader's — and the plot still fits the zone it was
    fitted to (the label not pushed out past the values)."""
    from graphplan.drawing.flywheel import speed_fitted
    for w, h in ((312.0, 240.0), (320.0, 250.0), (200.0, 120.0)):
        rec = speed_fitted(flywheel, lang, w, h)
        x0, y0, x1, y1 = rec.bounds()
        assert x1 - x0 <= w + 1e-6 and y1 - y0 <= h + 1e-6
        labels = [p for p in rec.items if p.kind == "text" and p.step.startswith(("ω_max", "ω_min"))]
        assert len(labels) == 4
        for p in labels:
            assert p.ink()[0] > 0.0, (w, h, p.text, p.ink())
        for p in rec.items:
            if p.kind == "segment" and p.role == "label" and p.step.startswith(("ω_max", "ω_min")):
                assert min(x for x, _ in p.points) >= -1e-9, p.points
