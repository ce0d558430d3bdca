"""Stop 46 on the cam sheet, checked on the drawing itself: the phase diagram's region of O (hatched
along the [ϑ] lines) holds only places from which no drawn point is seen at more than its phase's
[ϑ] — the angles measured off the record (the points K, the follower's axis or the arms' lines), not
taken from the code that chose the lines; the notes' closing of s says what was laid back."""
from __future__ import annotations

import functools
import math
import tomllib

import numpy as np
import pytest

from graphplan.model.cam import build
from graphplan.util.words import num
from tests.review_scenes import CAM_ROCKING46, CAM_TRANSLATING46
from tests.test_cam_review13 import KNIFE_REV12, ROCKING_REV13


@functools.lru_cache(maxsize=None)
def _construct(text: str):
    """The scene solved and constructed at the default scales (measure=False), once a module."""
    from graphplan.exact.cam import solve
    from graphplan.graphic.cam import construct
    sol = solve(build(tomllib.loads(text), "<scene>"))
    return sol, construct(sol, None, 0.5, measure=False)


def _steps(rec, prefix: str) -> list:
    return [q for q in rec.items if q.step and q.step.startswith(prefix)]


def _O(rec) -> complex:
    """The cam's centre O as the phase diagram draws it (its dot)."""
    return complex(*next(q for q in rec.items if q.step == "O" and q.kind == "point").points[0])


def _motion_lines(rec, n: int) -> list[complex]:
    """The line of each division's follower motion, read off the drawing: a translating follower's
    axis; a rocking follower's square to its arm's line (the velocity of the roller's centre)."""
    axis = _steps(rec, "follower axis")
    if axis:
        a, b = (complex(*p) for p in axis[0].points)
        return [(b - a) / abs(b - a)] * n
    out = []
    for k in range(n):
        a, b = (complex(*p) for p in next(q for q in rec.items if q.step == f"arm {k}").points)
        out.append(1j * (b - a) / abs(b - a))
    return out


def _acute(z: complex, w: complex) -> float:
    """The acute angle (°) between the lines along z and w."""
    t = abs(math.degrees(np.angle(z / w)))
    return min(t, 180.0 - t)


@pytest.mark.parametrize("scene", [CAM_TRANSLATING46, CAM_ROCKING46, KNIFE_REV12, ROCKING_REV13],
                         ids=["translating46", "rocking46", "knife_rev12", "rocking_rev13"])
def test_every_hatched_place_of_O_sees_no_point_past_the_allowed_angle(scene):
    from graphplan.drawing.cam import phase_diagram
    sol, g = _construct(scene)
    rec = phase_diagram(sol, g, "en")
    K = {int(q.step.split()[1]): complex(*q.points[0]) for q in _steps(rec, "K ")}
    n = len(K)
    motion = _motion_lines(rec, n)
    O = _O(rec)
    # O itself sees each point at its printed (protractor) angle's size
    for k in range(n):
        assert _acute(K[k] - O, motion[k]) == pytest.approx(abs(g.theta[k]), abs=0.5)
    strokes = _steps(rec, "region ")
    assert len(strokes) >= 6
    worst = 0.0
    for q in strokes:
        tip = complex(*q.points[1])            # a place of O inside the hatched region
        for k in range(n):
            worst = max(worst, _acute(K[k] - tip, motion[k]) - sol.cam.allowed[int(g.phase[k])])
    assert worst <= 0.3, worst


@pytest.mark.parametrize("lang", ["uk", "en"])
def test_the_closing_note_lays_back_only_the_errors_there_are(lang):
    """Review of stop 46: «похибку замикання підйому Δ = 0 мм … розподілено» — a zero error laid
    back. The note names each phase's non-zero Δ as laid back and a phase with Δ = 0 as closed."""
    from graphplan.report.cam import WORDS, closing_line
    from graphplan.util.words import num
    n = lambda x, d=4: num(x, lang, d)          # noqa: E731
    w = WORDS[lang]
    rise, ret = ("підйом", "опускан") if lang == "uk" else ("rise", "return")
    one = closing_line(w, "ψ", 0.0, 1.0, n)
    assert "Δ = 1 " in one and one.count("Δ = 0)") == 1
    laid, closed = one.split(";")                 # what was laid back; what closed as drawn
    assert ret in laid and rise not in laid and rise in closed and "Δ = 0)" in closed
    both = closing_line(w, "s", -1.0, 0.5, n)
    assert "Δ = −1 " in both.replace("-", "−") and "Δ = 0)" not in both and rise in both and ret in both
    none = closing_line(w, "s", 0.0, 0.0, n)
    assert "Δ·k/n" not in none and "Δ = 0 " in none


def test_the_smallest_base_radius_is_read_where_it_is_drawn():
    """R0 is measured as |OC₀| on the phase diagram — a translating follower's drawn at μ_s — so its
    reading is the drawn value to the ruler's half division there (0.5 mm at μ_s), not at the
    profile's coarser μ_l (stop 46: 65.897 mm printed «графічно 65,5», −0.6 %, of a drawn 65.6)."""
    from graphplan.drawing.cam import phase_scale
    from graphplan.exact.cam import solve
    from graphplan.graphic.cam import _phase_diagram_radius, construct
    sol = solve(build(tomllib.loads(CAM_TRANSLATING46), "<scene>"))
    g = construct(sol, None, 0.5)
    mu = phase_scale(sol, g)
    assert mu == g.mu_s < g.mu_l
    drawn = _phase_diagram_radius(sol, g.phi, g.phase, g.s, g.v)       # the drawn points' own R0
    assert abs(g.R0_min - drawn) <= 0.25 * mu + 1e-12
    assert (g.R0_min / mu / 0.5) == pytest.approx(round(g.R0_min / mu / 0.5), abs=1e-6)


@pytest.mark.parametrize("scene", [CAM_ROCKING46, ROCKING_REV13], ids=["rocking46", "rocking_rev13"])
def test_a_rocking_phase_diagram_draws_O_on_its_arc_about_the_pivot(scene):
    """With a given, O is chosen on the arc of radius a about the arm's pivot: the arc drawn through O
    is centred where the drawn arms' lines meet (the pivot, off the drawing), its radius |O₁O| = a at
    the diagram's scale."""
    from graphplan.drawing.cam import phase_diagram
    sol, g = _construct(scene)
    rec = phase_diagram(sol, g, "en")
    (a0, a1), (b0, b1) = ([complex(*p) for p in next(q for q in rec.items if q.step == f"arm {k}").points] for k in (1, len(g.phi) - 3))
    da, db = a1 - a0, b1 - b0
    t = ((b0 - a0).conjugate() * db).imag / (da.conjugate() * db).imag
    pivot = a0 + t * da                                     # the arms' lines meet at the pivot
    O = _O(rec)
    arc = [complex(*p) for p in _steps(rec, "O locus")[0].points]
    mu = rec.scales["mu_phase"]
    assert abs(O - pivot) == pytest.approx(sol.cam.centre_distance / mu, rel=1e-3)
    assert min(abs(z - O) for z in arc) < 0.5
    assert max(abs(abs(z - pivot) - abs(O - pivot)) for z in arc) < 0.1


@pytest.mark.parametrize("scene", [CAM_TRANSLATING46, KNIFE_REV12], ids=["translating46", "knife_rev12"])
def test_the_offset_is_noted_with_the_side_it_is_drawn_on_and_its_effect(scene):
    """«e = −6 мм» said neither side nor sense: the note now names the side of O the follower's axis
    stands on — as the profile draws the offset line e from O — and whether e lowers or raises the
    rise's pressure angle, against the same cam without an offset."""
    from graphplan.drawing.cam import profile_drawing
    from graphplan.exact.cam import solve
    from graphplan.report.cam import cam_json, cam_lines
    sol, g = _construct(scene)
    line = next(x for x in cam_lines(cam_json(sol, g, "x"), "en") if x.startswith("Offset"))
    rec = profile_drawing(sol, g, "en")
    x = complex(*_steps(rec, "offset e")[0].points[1]).real      # the axis' foot, from O at 0
    assert ("right of O" if x > 0 else "left of O") in line
    data = tomllib.loads(scene)
    data["cam"].update(offset=0.0, base_radius=sol.geometry.R0)       # the same R0, no offset
    plain = solve(build(data, "<e = 0>"))
    lower = sol.pressure_maxima()[0] < plain.pressure_maxima()[0]
    assert ("lowering" if lower else "raising") in line


@pytest.mark.parametrize("lang", ["uk", "en"])
def test_a_rocking_followers_pressure_angle_on_the_dwell_is_explained_and_is_the_triangles(lang):
    """Table 1's ϑ = −29,3° at division 0 of the lead's rocking cam is no error: on the dwell the
    profile is an arc about O, the normal is CO, the roller centre moves square to the arm O₁C, so
    |ϑ| = |∠OCO₁ − 90°| of the triangle with sides a, l, R0 (law of cosines); the notes say so."""
    from graphplan.report.cam import cam_json, cam_lines
    sol, g = _construct(CAM_ROCKING46)
    doc = cam_json(sol, g, "x")
    a, l, R0 = sol.cam.centre_distance, sol.cam.arm, sol.geometry.R0
    at_C = math.degrees(math.acos((l * l + R0 * R0 - a * a) / (2 * l * R0)))
    for p in (doc["positions"][0], doc["positions"][-1]):
        assert abs(p["exact"]["pressure_angle_deg"]) == pytest.approx(abs(at_C - 90.0), abs=1e-6)
    line = [x for x in cam_lines(doc, lang) if "O_{1}C" in x]
    assert len(line) == 1 and num(abs(doc["positions"][0]["exact"]["pressure_angle_deg"]), lang, 4) in line[0]
