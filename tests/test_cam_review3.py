"""The third review's corrections of the cam sheet (items 8 and 13): the divisions 0…N numbered on
every diagram's φ axis, one unit for the analogue on the drawing and in the table, a rocking
follower's angle lettered ψ (dψ/dφ, d²ψ/dφ²) — never s — on the diagrams, the table and the notes in
both languages, a translating follower's still s; and the profile's "0" apart from "O_1". Each
checked against what the test works out itself (the divisions' abscissae, the drawn ordinates)."""
from __future__ import annotations

import re

import numpy as np
import pytest

from conftest import ROOT
from graphplan.drawing.cam import diagrams, profile_drawing
from graphplan.exact.cam import solve
from graphplan.graphic.cam import construct
from graphplan.model.cam import load
from graphplan.util.markup import plain
from review_scenes import CAM_TR

ROCKING = '''title = "r"
[cam]
follower = "rocking"
swing_deg = 24
arm = 0.09
centre_distance = 0.11
roller_radius = 0.01
phases_deg = { rise = 120, dwell_far = 30, return = 90, dwell_near = 120 }
laws = { rise = "cosine", return = "parabolic" }
pressure_angle_deg = { rise = 40, return = 50 }
rpm = 90
direction = "cw"
divisions = 10
'''


@pytest.fixture(scope="module")
def cams(tmp_path_factory):
    """The review's clockwise rocking roller cam (10 divisions a phase), the rocking example and a
    translating cam, each solved and constructed."""
    d = tmp_path_factory.mktemp("cam3")
    (d / "rk.toml").write_text(ROCKING, encoding="utf-8")
    (d / "tr.toml").write_text(CAM_TR, encoding="utf-8")
    out = {}
    for name, path in (("rk", d / "rk.toml"), ("ro", ROOT / "examples" / "cam_rocking.toml"), ("tr", d / "tr.toml")):
        sol = solve(load(path))
        out[name] = (sol, construct(sol, measure=False))
    return out


@pytest.mark.parametrize("name", ["rk", "tr"])
def test_every_diagrams_phi_axis_carries_the_division_numbers(cams, name):
    """On each of the three diagrams the numbers 0…N stand by their divisions (x = φ_k/μ_φ), beside
    that diagram's φ axis — not only under s."""
    sol, g = cams[name]
    rec = diagrams(sol, g, "uk")
    x = np.radians(g.phi) / g.mu_phi
    n = len(x) - 1
    axes = {k: next(q for q in rec.items if q.step == f"axis {k}").points[0][1] for k in ("a", "v", "s")}
    numbers = [q for q in rec.items if q.kind == "text" and q.text.isdigit()]
    for key, y in axes.items():     # each number by the axis nearest it, at most 8 mm off (s: under a closing chord)
        near = {int(q.text): q.points[0] for q in numbers
                if min(axes.values(), key=lambda v: abs(v - q.points[0][1])) == y and abs(q.points[0][1] - y) < 8.0}
        assert set(near) == set(range(n + 1)), (key, sorted(near))
        for k, (px, _) in near.items():
            assert abs(px - x[k]) < 3.0, (key, k, px, x[k])


def _letters(rec) -> str:
    return " | ".join(plain(q.text) for q in rec.items if q.kind == "text")


def test_a_rocking_cams_lettering_names_its_angle_psi_never_s(cams):
    """The whole sheet of the review's rocking cam, uk and en: ψ, dψ/dφ, d²ψ/dφ², μ_ψ, δψ — and no
    s, ds/dφ, μ_s as the arm's angle; the translating cam keeps s and has no ψ on its diagrams."""
    from graphplan.model.cam import build
    from graphplan.sheets.cam import build_cam_sheet
    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.form import form
    import tomllib
    cam = build(tomllib.loads(ROCKING), "<scene>")
    for lang in ("uk", "en"):
        text = _letters(build_cam_sheet(cam, form("A1"), SheetOptions(lang=lang, sheet="cam")).record)
        for want in ("dψ/dφ", "d²ψ/dφ²", "μ_ψ", "μ_dψ/dφ", "μ_d²ψ/dφ²", "ψ, °", "δ_ψ", "ψ(dψ/dφ)"):
            assert want in text, (lang, want)
        bad = re.findall(r"ds/dφ|d²s/dφ²|μ_s\b|μ_d²?s|(?<!\w)s, |(?<!\w)s (?:гр|gr)|δ_s\b|(?<!\w)s\(", text)
        assert not bad, (lang, bad)
    sol, g = cams["tr"]
    text = _letters(diagrams(sol, g, "en"))
    assert "ds/dφ" in text and "ψ" not in text


def _unit(text: str) -> tuple[float, str]:
    m = re.search(r"=\s*([0-9]+[.,]?[0-9]*)\s*(.+)$", text)
    return float(m.group(1).replace(",", ".")), m.group(2).strip()


@pytest.mark.parametrize("lang", ["uk", "en"])
def test_the_analogue_has_one_unit_on_the_drawing_and_in_the_table(cams, lang):
    """The rocking cam's dψ/dφ: the table's unit U (°/рад) is the scale's numerator, μ_{dψ/dφ} in
    (U)/мм, and the table's graphical value is the printed μ times the drawn ordinate (to the
    printed μ's four digits) — a scale in 1/мм (rad) beside a table in °/рад fails by 57×."""
    from graphplan.report.cam import cam_json
    from graphplan.sheets.cam import positions_table
    sol, g = cams["ro"]
    doc = cam_json(sol, g, "")
    head = [plain(q.text) for q in positions_table(doc, lang).items if q.kind == "text"]
    (col,) = [h for h in head if h.startswith("dψ/dφ, ")]
    unit = col.split(", ", 1)[1]
    mm = "мм" if lang == "uk" else "mm"
    (scale,) = [plain(q.text) for q in diagrams(sol, g, lang).items
                if q.kind == "text" and plain(q.text).startswith("μ_dψ/dφ")]
    mu, scale_unit = _unit(scale)
    assert scale_unit == f"({unit})/{mm}", (scale_unit, unit)
    for p, drawn in zip(doc["positions"], g.v_mm):
        value = p["graphical"]["ds_dphi_deg"]
        assert value == pytest.approx(mu * drawn, rel=1e-3, abs=1e-3 * abs(mu * 40)), (value, mu, drawn)


def test_the_profiles_zero_stands_apart_from_o1(cams):
    """Division 0 of a rocking cam's profile is lettered at the start's pivot O_1: the two labels'
    inked boxes are not on one line, at least 1 mm apart across it (review 3: side by side they read
    "0O1")."""
    for name in ("rk", "ro"):
        sol, g = cams[name]
        rec = profile_drawing(sol, g, "uk")
        (zero,) = [q for q in rec.items if q.kind == "text" and q.text == "0"]
        (o1,) = [q for q in rec.items if q.kind == "text" and q.text == "O_1"]
        a, b = zero.ink(), o1.ink()
        gap = max(b[1] - a[3], a[1] - b[3])
        assert gap > 1.0, (name, gap, a, b)
