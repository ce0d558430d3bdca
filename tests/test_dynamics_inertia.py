"""One I* on the dynamics sheet (review 8 #6): the turned I*(φ) diagram, ΔT(φ) beside the
energy–mass diagram and the energy–mass (Wittenbauer) curve are drawn by one French curve, so the
point (I*(φ), ΔT(φ)) read off the two φ diagrams lies on the Wittenbauer curve within the ruler's
0,5 mm at every φ — the pchip I*(φ) peaked at 4,78 kg·m² where the spline's Wittenbauer curve bulged
to 5,1. And where the diagram's largest I* misses the exact largest by more than the lab's 5 % (the
peak between two divisions), the drawing is redrawn on more divisions and the notes say so. The exact largest I* is sampled here from the solver's I*."""
from __future__ import annotations

import math

import numpy as np
import pytest

from conftest import example, scene_study
from review_scenes import COULISSE8   # review 8's coulisse (cw, the 1000 rpm motor line)
from graphplan.exact.dynamics import analyse
from graphplan.graphic.flywheel import construct, redrawn
from graphplan.util.markup import plain

RULER = 0.5    # mm



@pytest.fixture(scope="module", params=["coulisse", "shaper"])
def dyn(request):
    return analyse(scene_study(COULISSE8) if request.param == "coulisse" else example("shaper"))


def _curve(rec, step):
    found = [p.points for p in rec.items if p.kind == "polyline" and p.step == step]
    assert len(found) == 1, step
    return np.asarray(found[0], dtype=float)


@pytest.mark.parametrize("n", [12, 24])
def test_the_i_phi_diagram_and_the_wittenbauer_curve_draw_one_i_star(dyn, n):
    from shapely import LineString, Point
    from graphplan.drawing.flywheel import energy_mass, energy_projected, inertia_turned
    f = construct(dyn, n, 0.5, L=240.0)
    length = 150.0
    turned = _curve(inertia_turned(f, "uk", length, 10.0), "I*_m(φ)")          # (I*, −φ·length/L)
    energy = _curve(energy_projected(f, "uk", length, 10.0), "ΔT(φ)")          # (φ·length/L, ΔT)
    witt = LineString(_curve(energy_mass(f, "uk"), "ΔT(I*): φ eliminated"))
    phi = np.linspace(0.0, length, 600)
    i_at = np.interp(phi, -turned[:, 1], turned[:, 0])
    dt_at = np.interp(phi, energy[:, 0], energy[:, 1])
    far = max(witt.distance(Point(i, t)) for i, t in zip(i_at, dt_at))
    assert far <= RULER, f"the I*(φ) and ΔT(φ) diagrams' point lies {far:.2f} mm off the Wittenbauer curve"
    assert float(np.min(turned[:, 0])) >= 0.0        # never I* < 0 drawn
    values = sorted(float(p.text.replace(",", ".")) for p in inertia_turned(f, "uk", length, 10.0).items
                    if p.kind == "text" and p.step == "I* graduation")
    step = min(b - a for a, b in zip(values, values[1:]))
    assert values[-1] >= float(np.max(turned[:, 0])) * f.mu_I - step      # its values span the drawn peak


def _drawn_peak_miss(f, top: float) -> float:
    """The I*(φ) diagram's largest I* (its drawn polyline, read at μ_I) against the exact largest, %."""
    from graphplan.drawing.flywheel import inertia_turned
    turned = _curve(inertia_turned(f, "uk", 150.0, 10.0), "I*_m(φ)")
    return 100.0 * (float(np.max(turned[:, 0])) * f.mu_I - top) / top


def test_the_i_star_peak_is_drawn_within_the_lab_or_redrawn():
    """The coulisse's exact I* peaks at 5,293 kg·m² between positions 9 and 10. At 12 divisions its
    ordinates give 4,78 (−9,7 %), the French curve through them 5,06 (−4,45 %: the lab's 5 % holds,
    not redrawn); at 8 divisions the curve misses by −20 %: redrawn on 16, said in the notes."""
    dyn = analyse(scene_study(COULISSE8))
    t = np.linspace(0.0, 2 * math.pi, 20001)
    top = float(np.max(dyn.cycle.inertia(t)))                      # 5,29 kg·m² at position 9,65
    twelve = redrawn(dyn, None, 0.5, L=240.0)
    assert twelve.divisions == 12 and abs(_drawn_peak_miss(twelve, top)) <= 5.0
    assert abs(100.0 * (float(np.max(twelve.I)) * twelve.mu_I - top) / top) > 5.0     # the ordinates alone miss
    coarse = construct(dyn, 8, 0.5, L=240.0)
    assert _drawn_peak_miss(coarse, top) < -5.0
    f = redrawn(dyn, 8, 0.5, L=240.0)
    assert f.divisions > 8 and f.divisions % 8 == 0 and abs(_drawn_peak_miss(f, top)) <= 5.0
    from graphplan.report.dynamics import redrawn_note
    uk, en = plain(redrawn_note(f, "uk")), plain(redrawn_note(f, "en"))
    assert f"на {f.divisions} поділках замість 8" in uk and "найбільше I" in uk and "5,293" in uk
    assert f"redrawn on {f.divisions} divisions, not 8" in en and "largest I" in en
    # the sheet states what it drew and why (review 54 #3): no "instead of", no "— −"
    uk, en = plain(redrawn_note(f, "uk", sheet=True)), plain(redrawn_note(f, "en", sheet=True))
    assert uk.startswith(f"Діаграми побудовано на {f.divisions}") and "замість" not in uk and "— −" not in uk
    assert en.startswith(f"Diagrams drawn on {f.divisions}") and "not 8" not in en and "— −" not in en


@pytest.mark.slow
def test_every_axis_of_the_coulisse_sheet_is_lettered_across_its_curve():
    """Review 8 #13: the M* axis was lettered only to 300 N·m where M*_c reaches 443 (the 350/400
    ticks bare). On the sheet, each axis's lettered values reach within one lettered step of its
    diagram's largest and smallest ordinate (the exact M*_c, the read ΔT, I* — computed here)."""
    from types import SimpleNamespace
    from graphplan.sheets.form import form
    from graphplan.sheets.sheet import BUILDERS
    args = SimpleNamespace(positions=None, accel=None, precision=0.5, lang="uk", sheet="dynamics")
    st = scene_study(COULISSE8)
    out = BUILDERS["dynamics"](st, form("A1"), args)
    dyn = analyse(st)
    m = dyn.cycle.samples.moment
    wanted = {("moments", "M graduation"): (float(np.min(m)), float(np.max(m))),
              ("moments", "A graduation"): (0.0, float(dyn.cycle.work))}
    for (name, step), (lo, hi) in wanted.items():
        rec = next(p.record for p in out.placed if p.name == name)
        shown = sorted(float(p.text.replace(",", ".").replace("−", "-")) for p in rec.items
                       if p.kind == "text" and p.step == step)
        assert len(shown) >= 2, (step, shown)
        every = min(b - a for a, b in zip(shown, shown[1:]))
        assert shown[-1] >= hi - every - 1e-9, (step, shown, hi)      # 400 of 443 at a 50 step: read across
        assert shown[0] <= max(lo, 0.0) + every + 1e-9, (step, shown, lo)


def test_a_constant_i_star_is_drawn_compactly_and_said():
    """A moment-loaded four-bar whose only mass is its crank's: I* is the crank's own, the same at
    every position — the energy–mass curve a vertical line, the turned I*(φ) a line in a 250 mm
    panel, point 0's number on the I* axis after its values read as one. Drawn on a short φ axis
    with the value said beside the line, the energy–mass I* axis ticked only."""
    from graphplan.drawing.flywheel import energy_mass, inertia_turned
    from test_moment_load import scene
    text = scene().replace("omega = ", "mass = 4.0\ninertia = 0.02\nomega = ", 1) + "\n[dynamics]\ndelta = 0.05\n"
    dyn = analyse(scene_study(text))
    i_star = dyn.cycle.inertia(np.linspace(0.0, 2 * math.pi, 361))
    assert float(np.ptp(i_star)) < 1e-12 * float(np.max(i_star))
    f = construct(dyn, None, 0.5, L=240.0)
    rec = inertia_turned(f, "uk", 250.0, 10.0)
    x0, y0, x1, y1 = rec.bounds()
    assert y1 - y0 < 100.0                               # not a 250 mm panel around one line
    said = [p.text for p in rec.items if p.kind == "text" and "стала" in (p.text or "")]
    assert said and "0,02" in said[0]
    en = [p.text for p in inertia_turned(f, "en", 250.0, 10.0).items if p.kind == "text" and "constant" in (p.text or "")]
    assert en
    w = energy_mass(f, "uk", projections=(-20.0, -10.0))
    assert not [p for p in w.items if p.kind == "text" and p.step == "I* graduation"]
    assert [p for p in w.items if p.kind == "segment" and p.step == "I* graduation"]     # the ticks stay
