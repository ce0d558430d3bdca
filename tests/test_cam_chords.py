"""The cam's graphical integration drawn as the lab draws it (issue 32, item 1 of the cam review):
the poles P1, P2 at whole-millimetre pole distances on the integrated diagrams' axes, a ray from the
pole to each interval's mean ordinate carried to the ordinate axis, each chord of the integral
parallel to its ray; the scales following from H (μ_v = μ_a·μ_φ·H1, μ_s = μ_v·μ_φ·H2); the centre
profile thin and the working profile thick (GOST 2.303); on the sheet the phase diagram's s axis
level with the s diagram's."""
from __future__ import annotations

import math

import numpy as np
import pytest

from conftest import ROOT
from graphplan.drawing.cam import diagrams, profile_drawing
from graphplan.exact.cam import solve
from graphplan.graphic.cam import construct
from graphplan.graphic.record import ROLES
from graphplan.model.cam import build, load

REVIEW = {"title": "Кулачок", "title_en": "A cam", "cam": {   # the review's cam: translating, ccw, e = −8 mm
    "follower": "translating", "stroke": 0.03, "offset": -0.008, "roller_radius": 0.008,
    "phases_deg": {"rise": 100, "dwell_far": 40, "return": 110, "dwell_near": 110},
    "laws": {"rise": "cycloidal", "return": "parabolic"}, "pressure_angle_deg": {"rise": 30, "return": 30},
    "omega": 12, "direction": "ccw", "divisions": 8}}
LINEAR = {"title": "Кулачок", "cam": {
    "follower": "translating", "stroke": 0.02, "roller_radius": 0.006,
    "phases_deg": {"rise": 120, "dwell_far": 60, "return": 120, "dwell_near": 60},
    "laws": {"rise": "linear", "return": "cosine"}, "rpm": 60}}

CAMS = [pytest.param(lambda: build(REVIEW, "<review>"), id="review"),
        pytest.param(lambda: load(ROOT / "examples" / "cam_translating.toml"), id="translating"),
        pytest.param(lambda: load(ROOT / "examples" / "cam_rocking.toml"), id="rocking"),
        pytest.param(lambda: build(LINEAR, "<linear>"), id="linear")]


def _steps(rec, prefix: str) -> dict[str, object]:
    return {p.step: p for p in rec.items if p.step.startswith(prefix)}


def _angle(p) -> float:
    (x0, y0), (x1, y1) = p.points[0], p.points[-1]
    return math.degrees(math.atan2(y1 - y0, x1 - x0))


@pytest.mark.parametrize("cam", CAMS)
@pytest.mark.parametrize("size", [1.0, 1.7])
def test_each_chord_is_parallel_to_its_ray_from_a_whole_millimetre_pole(cam, size):
    c = cam()
    sol = solve(c)
    g = construct(sol, size=size, measure=False)
    assert g.H1 == round(g.H1) and g.H2 == round(g.H2), (g.H1, g.H2)
    assert 15 <= g.H1 <= 50 and 15 <= g.H2 <= 50
    assert g.mu_v == pytest.approx(g.mu_a * g.mu_phi * g.H1, rel=1e-12)
    assert g.mu_s == pytest.approx(g.mu_a * g.mu_phi ** 2 * g.H1 * g.H2, rel=1e-12)
    rec = diagrams(sol, g, "uk")
    n = c.divisions
    axis = {k: _steps(rec, f"axis {k}")[f"axis {k}"].points[0][1] for k in ("a", "v", "s")}
    for index, integrated, integral, H in (("1", "a", "v", g.H1), ("2", "v", "s", g.H2)):
        pole = _steps(rec, f"pole P{index}")[f"pole P{index}"].points[0]
        assert pole == pytest.approx((-H, axis[integrated]))          # on the integrated diagram's axis
        rays = _steps(rec, f"ray P{index} ")
        chords = _steps(rec, f"chord {integral} ")
        assert len(chords) == 2 * n
        linear = [ph for ph in (0, 1) if c.laws[ph] == "linear"] if integrated == "a" else []
        assert len(rays) == n * (2 - len(linear))
        for ph in (0, 1):
            for j in range(n):
                ray = rays.get(f"ray P{index} {ph * n + j}")
                if ph in linear:
                    assert ray is None
                    continue
                assert ray.points[0] == pytest.approx(pole) and abs(ray.points[1][0]) < 1e-9
                chord = chords[f"chord {integral} {ph} {j}"]
                assert abs(_angle(chord) - _angle(ray)) < 0.1, (index, ph, j)
                # the ray ends at the interval's mean ordinate carried across to the ordinate axis
                mean = _steps(rec, f"mean {integrated} {ph * n + j}")
                level = [p for p in mean.values() if p.kind == "point"][0].points[0][1]
                assert ray.points[1][1] == pytest.approx(level)
    # ds/dφ read at the divisions lies on its chords within the ruler's half division
    for k in range(len(g.phi)):
        top = _steps(rec, f"v at {k}")[f"v at {k}"].points[1][1] - axis["v"]
        assert abs(top - g.v_chord[k]) <= g.precision / 2 + 1e-9


@pytest.mark.parametrize("cam", CAMS[:3])
def test_the_centre_profile_is_thin_and_the_working_profile_thick(cam):
    sol = solve(cam())
    g = construct(sol, measure=False)
    rec = profile_drawing(sol, g, "en")
    centre = [p for p in rec.items if p.step == "centre profile"]
    working = [p for p in rec.items if p.step == "working profile"]
    assert len(centre) == len(working) == 1
    assert ROLES[centre[0].role] <= 0.35 < 0.5 <= ROLES[working[0].role]
