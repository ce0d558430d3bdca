"""Reviews 8 and 9 of the cam sheets: the A3 set's diagrams at scales of the standard series
(review 8, finding 11: μ_s = 0.0009951 m/mm, μ_φ = 0.01454 rad/mm), and every division number of the
phase diagram read as its own dot's (review 9, finding 1: "18" and "0, 19" at each other's dots) —
each checked against what the test computes itself (the series, the drawn dots and lettering)."""
from __future__ import annotations

import math
import re

import pytest

from conftest import ROOT
from graphplan.exact.cam import solve
from graphplan.model.cam import build, load

# the reviewer's rocking scene (review 9, m3.toml): cosine rise, cycloidal return, the cam ccw
M3 = {"title": "Кулачок", "title_en": "Disc cam with a rocking roller follower (review 9)",
      "cam": {"follower": "rocking", "swing_deg": 22, "arm": 0.095, "centre_distance": 0.125,
              "roller_radius": 0.009, "phases_deg": {"rise": 120, "dwell_far": 25, "return": 95, "dwell_near": 120},
              "laws": {"rise": "cosine", "return": "cycloidal"}, "pressure_angle_deg": {"rise": 40, "return": 50},
              "rpm": 100, "direction": "ccw"}}
# review 8's translating scene: e = −6 mm, the cam ccw, 8 divisions named
CAM8 = {"title": "Кулачок", "title_en": "Disc cam", "cam": {
    "follower": "translating", "stroke": 0.032, "offset": -0.006, "roller_radius": 0.011,
    "phases_deg": {"rise": 110, "dwell_far": 40, "return": 90, "dwell_near": 120},
    "laws": {"rise": "cycloidal", "return": "cosine"}, "pressure_angle_deg": {"rise": 28, "return": 35},
    "omega": 12, "direction": "ccw", "divisions": 8}}


def in_series(value: float) -> bool:
    """Whether ``value`` is 1, 2, 2.5, 4 or 5 times a power of ten (GOST 2.302, the lab's scales)."""
    mantissa = value / 10 ** math.floor(math.log10(value) + 1e-9)
    return any(abs(mantissa - m) < 1e-6 for m in (1.0, 2.0, 2.5, 4.0, 5.0))


@pytest.mark.slow
@pytest.mark.parametrize("scene", [CAM8, M3], ids=["translating", "rocking"])
def test_the_a3_sets_diagrams_are_drawn_at_series_scales(scene):
    """The A3 set's μ_φ (in °/mm) and μ_s (m/mm; a rocking follower's μ_ψ in °/mm) are of the
    series, the poles whole millimetres, and the lab's formula μ_s = μ_a·μ_φ²·H1·H2 holds."""
    from graphplan.sheets.cam import construct_on
    from graphplan.sheets.form import form
    cam = build(scene, "<scene>")
    g = construct_on(solve(cam), form("A3"))
    assert in_series(math.degrees(g.mu_phi))
    assert in_series(math.degrees(g.mu_s) if cam.rocking else g.mu_s)
    assert g.H1 == round(g.H1) and g.H2 == round(g.H2) and 15 <= g.H1 <= 50 and 15 <= g.H2 <= 50
    assert g.mu_s == pytest.approx(g.mu_a * g.mu_phi ** 2 * g.H1 * g.H2, rel=1e-12)


def test_series_check_itself():
    """in_series tells the series from what review 8 found on the A3 set."""
    assert in_series(0.0005) and in_series(0.4) and in_series(math.degrees(math.pi / 180)) and in_series(25)
    assert not in_series(0.0009951) and not in_series(math.degrees(0.01454)) and not in_series(0.573)


def _labels_and_dots(scene_or_path):
    from graphplan.drawing.cam import phase_diagram, phase_points, phase_scale
    from graphplan.sheets.cam import construct_on
    from graphplan.sheets.form import form
    cam = load(scene_or_path) if not isinstance(scene_or_path, dict) else build(scene_or_path, "<scene>")
    sol = solve(cam)
    g = construct_on(sol, form("A1"))
    rec = phase_diagram(sol, g, "en")
    _, _, K = phase_points(sol, g)
    return rec, K / phase_scale(sol, g)


def _gap(box, z: complex) -> float:
    dx = max(box[0] - z.real, 0.0, z.real - box[2])
    dy = max(box[1] - z.imag, 0.0, z.imag - box[3])
    return math.hypot(dx, dy)


@pytest.mark.slow
@pytest.mark.parametrize("scene", [M3, ROOT / "examples" / "cam_rocking.toml", CAM8],
                         ids=["m3", "cam_rocking", "translating"])
def test_each_phase_diagram_number_reads_as_its_own_dot(scene):
    """Every division number of the phase diagram is nearer its own dot than any other dot, or
    stands on a leader that starts at its own dot (within 1.5 mm) — never beside another's."""
    rec, K = _labels_and_dots(scene)
    leaders = [p.points for p in rec.items if p.role == "label" and p.kind == "segment"]
    numbers = [p for p in rec.items if p.kind == "text" and re.fullmatch(r"\d+([,;] \d+)*", p.text)]
    assert len(numbers) >= len(K) // 2
    for p in numbers:
        k = int(re.split(r"[,;]", p.text)[0])
        box = p.ink()
        own = _gap(box, complex(K[k]))
        others = [_gap(box, complex(z)) for z in K if abs(z - K[k]) > 0.5]
        led = any(abs(complex(*a) - K[k]) < 1.5 and _gap(box, complex(*b)) < 1.5 for a, b in leaders)
        assert own < min(others) or led, (p.text, own, min(others))


@pytest.mark.slow
def test_the_rocking_a3_set_draws_the_pressure_angle_beside_the_profile(tmp_path):
    """Review 9, finding 2: the A3 set of the reviewer's rocking cam carries ϑ(φ) as the A1 does, in
    four sheets — under ψ, which has a sheet of its own (review 13 #7: on one sheet with d²ψ/dφ² and
    dψ/dφ a phase's dψ/dφ was drawn under LEGIBLE_MM; before, ϑ(φ) stood under the phase diagram
    beside the profile), the phase diagram with the profile, Table 1 and the notes on the last."""
    from graphplan.cli.main import main
    scene = tmp_path / "m3.toml"
    scene.write_text("\n".join([f'title = "{M3["title"]}"', f'title_en = "{M3["title_en"]}"', 'lang = "en"', "[cam]",
                                'follower = "rocking"', "swing_deg = 22", "arm = 0.095", "centre_distance = 0.125",
                                "roller_radius = 0.009",
                                "phases_deg = { rise = 120, dwell_far = 25, return = 95, dwell_near = 120 }",
                                'laws = { rise = "cosine", return = "cycloidal" }',
                                "pressure_angle_deg = { rise = 40, return = 50 }", "rpm = 100", 'direction = "ccw"']),
                     encoding="utf-8")
    assert main(["sheet", str(scene), "--format", "A3", "-o", str(tmp_path / "s.svg")]) == 0
    sheets = [tmp_path / name for name in ("s.svg", "s-2.svg", "s-3.svg", "s-4.svg")]
    assert sorted(tmp_path.glob("s*.svg")) == sorted(sheets)
    texts = [p.read_text(encoding="utf-8") for p in sheets]
    holding = [k for k, t in enumerate(texts) if "Pressure angle" in t]
    assert "Diagram ψ" in texts[1] and "Phase diagram" in texts[2] and "Cam profile" in texts[2]
    assert "Table 1" in texts[3] and "Table 1" not in texts[2]
    # ϑ(φ) once, never on the sheet of d²ψ/dφ² and dψ/dφ (review 13 #7), at their μ_φ (review 11, mark 16),
    # under ψ or beside the profile — where it reads finest (stop 53's rule): stop 57, ψ's sheet leaves
    # 4 °/mm under it, the profile's sheet 2.5 °/mm
    import re
    assert holding in ([1], [2])
    mu_phi = re.findall(r'">\s*=\s*([\d.]+ rad/mm)', texts[1])          # ψ's caption: μ_φ = 0.01745 rad/mm …
    mu_theta = re.findall(r'>ϑ</tspan><tspan[^>]*>\s*=\s*([\d.]+) °/mm<', texts[holding[0]])  # … μ_ϑ = 2.5 °/mm
    assert mu_phi and mu_phi[0] in texts[holding[0]] and mu_theta and float(mu_theta[0]) <= 2.5
