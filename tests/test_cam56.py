"""Stop 56 (cam56): the lead's CAM56 (a ROCKING roller follower, the cam counter-clockwise, a parabolic rise
into a cycloidal return) checked against a brute force of its own — the arm's angle written out from the
triangle OO₁C, the centre profile turned point by point, the pressure angle between the finite-difference
profile's normal and the roller centre's velocity (square to the arm) —; the phase's largest pressure angle
said with the turn it falls at (the rise's −27,04° is the start's, where the arm still rests); the corners of
the centre profile marked and lettered on the drawn profile where the drawn profile turns; the Ukrainian
apostrophe of «м’які» one word with its letters in the rendered lettering."""
from __future__ import annotations

import math
import re
import tomllib

import numpy as np
import pytest

from camfixtures import cam_fixture
from review_scenes import CAM55, CAM56, OWN_CAM56

cam56 = cam_fixture("cam56", CAM56, 9)

# -- the brute force: CAM56's data written out ------------------------------------------------------------
A, L, SWING = 0.14, 0.11, math.radians(24.0)
RISE, FAR, RET = math.radians(120.0), math.radians(30.0), math.radians(110.0)


def _psi(phi: np.ndarray) -> np.ndarray:
    """The arm's swing (rad) at the cam's turn ``phi`` (rad from the rise's start): parabolic rise,
    far dwell, cycloidal return, near dwell — the laws' closed forms."""
    phi = np.mod(phi, 2 * math.pi)
    out = np.zeros_like(phi)
    m = phi < RISE
    u = phi[m] / RISE
    out[m] = SWING * np.where(u < 0.5, 2 * u * u, 1 - 2 * (1 - u) ** 2)
    out[(phi >= RISE) & (phi < RISE + FAR)] = SWING
    m = (phi >= RISE + FAR) & (phi < RISE + FAR + RET)
    u = (phi[m] - RISE - FAR) / RET
    out[m] = SWING * (1 - (u - np.sin(2 * math.pi * u) / (2 * math.pi)))
    return out


def _centre(phi: np.ndarray, R0: float) -> np.ndarray:
    """The roller centre C in the fixed frame (O at 0, the pivot O₁ at (a, 0), the arm up to the left):
    the start angle ψ₀ from |C| = R0 by the cosine rule."""
    psi0 = math.acos((A * A + L * L - R0 * R0) / (2 * A * L))
    return A + L * np.exp(1j * (math.pi - psi0 - _psi(phi)))


def _theta(phi: np.ndarray, R0: float, h: float = 1e-6) -> np.ndarray:
    """|ϑ| (deg): the angle between the centre profile's normal (the profile P = C·e^{−iφ} differenced,
    turned back into the fixed frame) and the roller centre's velocity (square to the arm O₁C)."""
    def P(x):
        return _centre(x, R0) * np.exp(-1j * x)
    t = (P(phi + h) - P(phi - h)) / (2 * h) * np.exp(1j * phi)
    n, v = 1j * t, -1j * (_centre(phi, R0) - A)
    c = np.abs((np.conj(n) * v).real) / (np.abs(n) * np.abs(v))
    return np.degrees(np.arccos(np.clip(c, -1.0, 1.0)))


def _worst(R0: float, step: int = 1) -> tuple[float, float]:
    phi = np.radians(np.arange(0.0, 260.0001, 0.01 * step))
    th = _theta(phi, R0)
    deg = np.degrees(phi)
    return float(th[deg <= 120.0].max()), float(th[deg >= 150.0].max())


def test_cam56_radius_angles_and_curvature_by_brute_force(cam56):
    """R0 (49.743 mm: the first radius of a 0.01-mm scan at which both phases keep their [ϑ]), the
    phases' largest |ϑ| at the R0 taken (50 mm: 27.04° on the rise at φ = 0, 44.75° on the return at
    φ ≈ 221.5°) and ρ_min of the (all convex) centre profile, 43.27 mm at the parabolic law's middle."""
    cam, sol, g, doc = cam56
    R0_min = doc["base_radius_min_m"]
    ok = [r for r in np.arange(0.0490, 0.0505, 0.00001)
          if (lambda w: w[0] <= 40.0 and w[1] <= 45.0)(_worst(r, 5))]
    assert R0_min == pytest.approx(ok[0], abs=1.2e-5)
    R0 = doc["base_radius_m"]
    assert R0 == pytest.approx(0.050)
    phi = np.radians(np.arange(0.0, 260.0001, 0.005))
    th, deg = _theta(phi, R0), np.degrees(phi)
    for k, (lo, hi) in (("rise", (0.0, 120.0)), ("return", (150.0, 260.0))):
        m = (deg >= lo) & (deg <= hi)
        j = int(np.argmax(th[m]))
        assert doc["pressure_angle_max_deg"][k] == pytest.approx(th[m][j], abs=0.01)
        assert abs(doc["pressure_angle_extreme_deg"][k]) == pytest.approx(th[m][j], abs=0.01)
        assert doc["pressure_angle_extreme_phi_deg"][k] == pytest.approx(deg[m][j], abs=0.05)
    assert doc["pressure_angle_extreme_phi_deg"]["rise"] == pytest.approx(0.0, abs=1e-6)
    x = np.linspace(0.0, 2 * math.pi, 1_440_001)[:-1]
    P = _centre(x, R0) * np.exp(-1j * x)
    d = x[1] - x[0]
    P1 = (np.roll(P, -1) - np.roll(P, 1)) / (2 * d)
    P2 = (np.roll(P, -1) - 2 * P + np.roll(P, 1)) / d ** 2
    rho = -np.abs(P1) ** 3 / (np.conj(P1) * P2).imag        # + convex (the profile runs clockwise)
    assert (rho > 0).all()
    assert doc["curvature_min_m"] == pytest.approx(float(rho.min()), abs=2e-5)


def test_the_largest_pressure_angle_is_said_with_where_it_falls(cam56):
    """The notes print each phase's largest ϑ with its turn, and a phase's end as its end: the rise's
    largest |ϑ| of a rocking arm falls where it starts from rest (φ = 0), which a teacher reads against
    Table 1's first row, not as an angle inside the rise."""
    from graphplan.report.cam import cam_lines
    _, _, _, doc = cam56
    uk = next(x for x in cam_lines(doc, "uk") if x.startswith("Найбільший кут тиску"))
    assert "підйом −27,04° при φ = 0° (на початку фази)" in uk
    assert "опускання −44,75° при φ = 221,5° (допустимо" in uk
    en = next(x for x in cam_lines(doc, "en") if x.startswith("Largest pressure angle"))
    assert "rise −27.04° at φ = 0° (the start of the phase)" in en
    # the first row of Table 1 (φ = 0) carries the same angle
    assert doc["positions"][0]["exact"]["pressure_angle_deg"] == pytest.approx(doc["pressure_angle_extreme_deg"]["rise"], abs=1e-6)


# -- the corners on the profile ---------------------------------------------------------------------------

@pytest.mark.parametrize("text, n", [(CAM55, 2), (OWN_CAM56, 0)], ids=["cam55-linear-return", "own56-smooth"])
def test_the_corners_are_marked_and_lettered_where_the_drawn_profile_turns(text, n):
    """Each place where the drawn centre profile's polyline turns sharply (more than 5° between its
    neighbouring segments, the rest turning by a fraction of a degree) carries a corner's ring, lettered
    K_1, K_2 … by it in the order of φ, as many as the notes name; a smooth profile carries none."""
    from camfixtures import built
    from graphplan.drawing.cam import profile_drawing
    from graphplan.report.cam import cam_lines
    cam, sol, g, doc = built(text, "<corners>", 8)
    rec = profile_drawing(sol, g, "uk")
    poly = next(p for p in rec.items if p.step == "centre profile")
    z = np.array([complex(x, y) for x, y in poly.points])
    d = np.diff(z)
    d = d[np.abs(d) > 1e-9]
    turn = np.degrees(np.abs(np.angle(np.roll(d, -1) / d)))
    sharp = [z[1:][k] for k in np.flatnonzero(turn > 5.0)]
    rings = [p for p in rec.items if p.step.startswith("corner ")]
    assert len(rings) == len(sharp) == n
    for q in sharp:
        assert min(abs(complex(*r.points[0]) - q) for r in rings) < 0.05
    texts = {p.text: complex(*p.points[0]) for p in rec.items if p.kind == "text"}
    for j, r in enumerate(sorted(rings, key=lambda r: r.step), 1):
        assert f"K_{j}" in texts
        assert abs(texts[f"K_{j}"] - complex(*r.points[0])) < 12.0
    notes = " ".join(cam_lines(doc, "uk"))
    assert all(f"K_{{{j}}}" in notes or f"K_{j}" in notes for j in range(1, n + 1))
    assert ("K_" in notes) == bool(n)


# -- the apostrophe --------------------------------------------------------------------------------------

def _words(text: str, size: float, dx: float, dy: float, closing: bool = True) -> int:
    """How many words (``closing``: ink joined over the 0.8-mm closing tests/inkcheck and overprint.py
    use; else the bare pieces of ink) ``text`` at ``size`` renders to at 4 px/mm, set ``dx``, ``dy`` mm
    off the pixel grid, in the packaged font (registered by conftest)."""
    from scipy import ndimage
    from inkcheck import _mask
    from graphplan.drawing.fonts import register
    from graphplan.drawing.svg import render
    from graphplan.graphic.record import Record
    register()
    rec = Record("words")
    rec.label((5.0 + dx, 5.0 + dy), text, size=size)
    ink = _mask(render(rec, 60.0, 15.0), 60.0, 15.0, 4.0)
    return ndimage.label(ndimage.binary_dilation(ink, iterations=3) if closing else ink)[1]


@pytest.mark.parametrize("size", [2.5, 3.5, 5.0])
def test_the_apostrophe_reads_as_part_of_its_word(size):
    """«м’які», «п’ять» rendered and grouped into words as tests/inkcheck and overprint.py group ink: as
    many words as without the apostrophes, wherever the text falls on the pixel grid — untucked, the
    apostrophe (high over small letters, osifont's bearings 0.13 and 0.08 em) stood 1.3 mm across the
    diagonal from both letters and read as a word of its own at 35 of these 75 placings —, while its
    ink, unclosed, still stands apart from both letters (tucked in, not touching)."""
    for dx in (0.0, 0.05, 0.1, 0.15, 0.2):
        for dy in (0.0, 0.05, 0.1, 0.15, 0.2):
            assert _words("м’які п’ять", size, dx, dy) == _words("мякі пять", size, dx, dy), (dx, dy)
    assert _words("м’я", size, 0.0, 0.0, closing=False) == 3


@pytest.mark.slow
def test_cam56_sheet_reads_as_lettered():
    """CAM56's A1 sheet: nothing overprinted on the rendered sheet (tests/inkcheck), «м’які» in its notes."""
    from inkcheck import overprinted
    from graphplan.model.cam import build
    from graphplan.sheets.cam import build_cam_sheet
    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.form import form
    sheet = build_cam_sheet(build(tomllib.loads(CAM56), "<cam56>"), form("A1"), SheetOptions(lang="uk", sheet="cam"))
    svg = sheet.svg()
    assert "м’які" in re.sub(r"<[^>]+>", "", svg)      # the lettering's text, its pieces (tspans) joined
    assert overprinted(svg) == []
