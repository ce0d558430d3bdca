"""A teacher's corrections of the cam sheet (the review's items 2, 3, 7 and 14): the s diagram redrawn
with more divisions until it closes within the stated bound, the profile the largest drawing, A3
drawn as a set of sheets each within its frame, and the phase angles dimensioned with their values —
each checked against what the test computes itself (the scene's numbers, the drawn chords, the
records' arcs and boxes)."""
from __future__ import annotations

import math
import re

import pytest

from conftest import ROOT
from graphplan.exact.cam import solve
from graphplan.graphic.cam import construct
from graphplan.model.cam import build, load

TRANSLATING = ROOT / "examples" / "cam_translating.toml"
ROCKING = ROOT / "examples" / "cam_rocking.toml"
# the reviewer's rocking scene (cam_rock_ccw.toml): parabolic rise, trapezoidal return, six divisions
# review 9's rocking scene (m3.toml) without a `divisions` line: at the A1 sheet's series scales its
# default 8 miss the closing (cam_rocking.toml's 8 did at the scales before, and now close within it)
M3_TOML = """title = "Кулачок"
[cam]
follower = "rocking"
swing_deg = 22
arm = 0.095
centre_distance = 0.125
roller_radius = 0.009
phases_deg = { rise = 120, dwell_far = 25, return = 95, dwell_near = 120 }
laws = { rise = "cosine", return = "cycloidal" }
pressure_angle_deg = { rise = 40, return = 50 }
rpm = 100
direction = "ccw"
"""
ROCK_CCW = {"title": "Кулачковий механізм з коромисловим штовхачем", "title_en": "Disc cam with a rocking follower",
            "cam": {"follower": "rocking", "swing_deg": 25, "arm": 0.12, "centre_distance": 0.15,
                    "roller_radius": 0.01, "phases_deg": {"rise": 120, "dwell_far": 20, "return": 90, "dwell_near": 130},
                    "laws": {"rise": "parabolic", "return": "trapezoidal"},
                    "pressure_angle_deg": {"rise": 40, "return": 45}, "omega": 15, "direction": "ccw"}}
# the reviewer's translating scene (cam_cw.toml): offset −8 mm, the cam turning clockwise
CAM_CW = {"title": "Кулачок", "title_en": "A cam", "cam": {
    "follower": "translating", "stroke": 0.03, "offset": -0.008, "roller_radius": 0.008,
    "phases_deg": {"rise": 100, "dwell_far": 40, "return": 110, "dwell_near": 110},
    "laws": {"rise": "cycloidal", "return": "cosine"}, "pressure_angle_deg": {"rise": 30, "return": 35},
    "rpm": 200, "direction": "cw", "divisions": 8}}


@pytest.fixture
def trapezoid(monkeypatch):
    """The s diagram integrated over the chords' middles of ds/dφ (the trapezoid rule: the lab's
    equal-area correction skipped) — how the sheet drew it before stop 48, and a drawing that misses
    its closing at few divisions: since the steps of equal area it closes within the ruler's readings
    at any count, and the redrawing these tests look at needs a drawing that does not."""
    import numpy as np
    from graphplan.graphic import cam as G
    monkeypatch.setattr(G, "equal_area_shift", lambda s, v, phi: np.zeros(len(s) - 1))


def closing_errors(sol, g) -> list[float]:
    """Each phase's closing error read off the drawn chords (mm): the rise's last chord vertex of s
    against the stroke drawn, the return's against zero."""
    stroke = sol.cam.stroke / g.mu_s
    ends = [int(k) for k in range(len(g.phase) - 1) if g.phase[k] != g.phase[k + 1]] + [len(g.phase) - 1]
    return [float(g.s_chord[ends[0]] - stroke), float(g.s_chord[ends[1]])]


def allowed_mm(sol, g) -> float:
    """2 % of the stroke drawn and the ruler's half division (the bound the notes state), plus the
    half division the vertex's reading may add."""
    return 0.02 * sol.cam.stroke / g.mu_s + g.precision


def test_a_phase_that_misses_its_closing_is_redrawn_with_more_divisions(trapezoid):
    """Review 9's rocking cam (no `divisions` line), its default taken as 4: there its ψ misses the
    closing by more than the bound; the sheet's construction takes more and closes within it, and the
    notes say so. (At the default 8 it closes since the chords take each interval's step of equal
    area, stop 47.)"""
    import dataclasses
    import tomllib
    from graphplan.report.cam import cam_json, cam_lines
    from graphplan.sheets.cam import cam_sizes, construct_on
    from graphplan.sheets.form import form
    data = tomllib.loads(M3_TOML)
    cam = build(data, "<review 9's rocking cam, no divisions>")
    assert not cam.divisions_given and cam.divisions == 8
    cam = dataclasses.replace(cam, divisions=4)
    sol = solve(cam)
    size, prof, height, accel, h1, h2, series = cam_sizes(sol, form("A1"), 4)
    first = construct(sol, 4, 0.5, size=size, profile_size=prof, height=height, accel=accel, H1=h1, H2=h2,
                      measure=False, series=series)
    assert max(abs(x) for x in closing_errors(sol, first)) > 0.02 * cam.stroke / first.mu_s + 0.25
    g = construct_on(sol, form("A1"))
    n = len(g.phi) // 2 - 1
    assert n > 4
    assert max(abs(x) for x in closing_errors(sol, g)) <= allowed_mm(sol, g)
    doc = cam_json(sol, g, "x")
    assert doc["divisions"] == n and doc["redrawn"]["divisions_first"] == 4
    said = " ".join(cam_lines(doc, "en")).replace("\u00a0", " ")
    assert f"redrawn with {n} divisions instead of 4" in said and "2 % of the stroke" in said
    assert not any("closing" in w for w in doc["warnings"])


def test_divisions_the_command_line_names_are_kept_and_warned_with_how_many_would_do(trapezoid):
    """`--divisions 5` on the reviewer's scene: kept, and the warning's number of divisions closes
    within the bound at the same scales where 5 do not (6 close since stop 47's steps of equal area)."""
    from graphplan.sheets.cam import cam_sizes, construct_on
    from graphplan.sheets.form import form
    cam = build(ROCK_CCW, "<rock ccw>")
    sol = solve(cam)
    g = construct_on(sol, form("A1"), 5)
    assert len(g.phi) // 2 - 1 == 5
    assert max(abs(x) for x in closing_errors(sol, g)) > 0.02 * cam.stroke / g.mu_s + 0.25
    (warning,) = [w for w, _ in g.warnings if "closing" in w]
    better = int(re.search(r"(\d+) divisions would close", warning).group(1))
    assert better > 5
    sizes = cam_sizes(sol, form("A1"), 5)
    h = construct(sol, better, 0.5, size=sizes[0], profile_size=sizes[1], height=sizes[2], accel=sizes[3],
                  H1=sizes[4], H2=sizes[5], measure=False, series=sizes[6])
    assert max(abs(x) for x in closing_errors(sol, h)) <= allowed_mm(sol, h)


def test_divisions_the_scene_names_that_do_not_close_are_redrawn_and_the_notes_say_why(trapezoid):
    """Issue 32 item 2 (review 8, finding 10): the scene names 5 divisions at which s does not close
    within the bound: the sheet's construction (and `graphplan cam`'s) takes the fewest that close,
    and the notes say that 6 were given, what was drawn, and the first closing error against the
    bound — no warning against itself."""
    from graphplan.report.cam import cam_json, cam_lines
    from graphplan.sheets.form import form
    from graphplan.sheets.cam import construct_on
    cam = build(ROCK_CCW | {"cam": ROCK_CCW["cam"] | {"divisions": 5}}, "<rock ccw>")
    sol = solve(cam)
    g = construct_on(sol, form("A1"))
    n = len(g.phi) // 2 - 1
    assert n > 5
    assert max(abs(x) for x in closing_errors(sol, g)) <= allowed_mm(sol, g)
    doc = cam_json(sol, g, "x")
    first = doc["redrawn"]
    assert first["divisions_first"] == 5 and first["divisions_first_given"]
    worst = max(abs(first["closing_mm_first"]["rise"]), abs(first["closing_mm_first"]["return"]))
    assert worst > first["closing_bound_mm_first"]
    en = " ".join(cam_lines(doc, "en"))
    assert f"5 divisions given; the ψ diagram drawn with {n}, as at 5 it does not close" in en
    uk = " ".join(cam_lines(doc, "uk"))
    assert f"5 поділок задано; графік ψ побудовано при {n}, бо при 5 він не замикається" in uk
    assert not any("closing" in w for w in doc["warnings"])


def test_the_profile_is_the_largest_drawing():
    """The reviewer's rocking scene on A1: the profile (1:1) larger in area than the phase diagram
    and at the scale the teacher expects; the translating example's likewise."""
    from graphplan.drawing.cam import phase_diagram, profile_drawing
    from graphplan.sheets.cam import construct_on
    from graphplan.sheets.form import form
    for cam in (build(ROCK_CCW, "<rock ccw>"), load(TRANSLATING)):
        sol = solve(cam)
        g = construct_on(sol, form("A1"))
        px0, py0, px1, py1 = profile_drawing(sol, g, "en").bounds()
        qx0, qy0, qx1, qy1 = phase_diagram(sol, g, "en").bounds()
        assert g.mu_l == pytest.approx(0.001)                  # M 1:1
        # the largest by area (issue 32, item 1: held also under the profile's height, the phase
        # diagram tied the s–ds/dφ–d²s/dφ² diagrams to a μ_s that left the sheet 45 % empty)
        assert (px1 - px0) * (py1 - py0) > (qx1 - qx0) * (qy1 - qy0)


def test_a3_draws_the_cam_as_a_set_every_page_within_its_frame():
    """examples/cam_translating.toml on A3: a set of numbered sheets, every drawing inside its sheet's
    field and clear of the title block, the profile at a GOST scale coarser than on A1, and
    `graphplan cam --format A3` measuring at those very scales."""
    from graphplan.sheets.cam import build_cam_sheet, construct_on
    from graphplan.sheets.compose import SheetOptions, defects, field_of
    from graphplan.sheets.form import form
    cam = load(TRANSLATING)
    sheet = build_cam_sheet(cam, form("A3"), SheetOptions(lang="uk", sheet="cam"))
    pages = [sheet] + list(sheet.more)
    assert len(pages) >= 2
    x0, y0, x1, y1 = field_of(form("A3"))
    names = []
    for page in pages:
        for p in page.placed:
            b = p.record.bounds()
            assert x0 - 1e-6 <= b[0] and b[2] <= x1 + 1e-6 and y0 - 1e-6 <= b[1] and b[3] <= y1 + 1e-6, (p.name, b)
            names.append(p.name)
    assert {"diagrams", "phase", "profile", "table", "notes"} <= set(names)
    assert not defects(sheet)
    g = construct_on(solve(cam), form("A3"))
    assert g.mu_l in (0.002, 0.0025, 0.004, 0.005)          # 1:2, 1:2.5, 1:4, 1:5
    profile = next(p.record for page in pages for p in page.placed if p.name == "profile")
    caption = " ".join(q.text for q in profile.items if q.kind == "text" and q.step == "caption")
    assert f"1:{round(g.mu_l * 1000, 1):g}".replace(".", ",") in caption


@pytest.mark.parametrize("scene", [pytest.param(CAM_CW, id="cw-translating"),
                                   pytest.param(ROCK_CCW, id="ccw-rocking")])
def test_the_phase_arcs_are_drawn_to_the_values_they_print(scene):
    """On the profile each phase is an arc about O between its extension lines, lettered «φ = N°»: the
    arc's drawn angle equals the printed value within 1°, and that value is the scene's; the allowed
    pressure angles on the phase diagram carry the scene's values; ds/dφ is lettered at its axis."""
    from graphplan.drawing.cam import phase_diagram, profile_drawing
    from graphplan.graphic.cam import construct as make
    cam = build(scene, "<scene>")
    sol = solve(cam)
    g = make(sol, 8, 0.5, measure=False)
    rec = profile_drawing(sol, g, "uk")
    phases = scene["cam"]["phases_deg"]
    want = [phases["rise"], phases["dwell_far"], phases["return"], phases["dwell_near"]]
    for j in range(4):
        (arc,) = [q for q in rec.items if q.kind == "arc" and q.step == f"phase {j}"]
        drawn = arc.angles[1] - arc.angles[0]
        text = " ".join(q.text for q in rec.items if q.kind == "text" and q.step == f"phase {j}")
        printed = float(re.search(r"=\s*([\d,.]+)°", text).group(1).replace(",", "."))
        assert abs(drawn - printed) < 1.0 and printed == want[j], (j, drawn, text)
        assert len([q for q in rec.items if q.kind == "vector" and q.step == f"phase {j} arrow"]) == 2
    ph = phase_diagram(sol, g, "uk")
    texts = [q.text for q in ph.items if q.kind == "text"]
    for k, key in enumerate(("rise", "return")):
        assert any(t.replace(" ", "") == f"[ϑ]={scene['cam']['pressure_angle_deg'][key]}°" for t in texts), texts
    # a rocking follower's analogue is laid off along the arm as the arc l·dψ/dφ (an angle is not s)
    (label,) = [q for q in ph.items if q.kind == "text" and q.text == ("l·dψ/dφ" if cam.rocking else "ds/dφ")]
    if not cam.rocking:      # at the end of its axis (through C0, square to the follower's)
        (axis,) = [q for q in ph.items if q.kind == "segment" and q.step == "axis ds/dφ"]
        end = max(axis.points, key=lambda p: p[0])
        assert math.dist(label.points[0], end) < 12.0
        assert abs(axis.points[0][1] - axis.points[1][1]) < 1e-9
