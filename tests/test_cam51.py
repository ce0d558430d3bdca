"""Stop 51's look at the cam sheet (the lead's CAM51: a rocking roller follower, the cam counter-clockwise,
ψ_max = 25°, l = 120 mm, a = 150 mm, a parabolic rise of 120°, a far dwell of 20°, a cosine return of
90°). Each number against the test's own brute force of the inversion — the roller centre C on its arc
about O₁, the cam turned about O, the pressure angle the angle between the profile's normal and C's
velocity — or read off what the sheet prints:

- R0, ψ(φ), ϑ(φ) at the divisions and ρ_min of the centre profile are the brute force's;
- the notes explain ϑ ≠ 0 on both dwells (Table 1 printed 6.4° on the far dwell unexplained) with the
  triangle OO₁C's values;
- the A1 sheet and `graphplan cam` print one graphical R0 (the terminal read it at 2.5:1, 52.4 mm, where
  the sheet, with no room for the phase diagram at 2.5:1, drew it at 1:1 and printed 52.5 mm)."""
from __future__ import annotations

import math

import numpy as np
import pytest

from graphplan.exact.cam import solve
from graphplan.graphic.cam import construct
from graphplan.model.cam import load
from review_scenes import CAM51

A, L, PSI = 0.150, 0.120, math.radians(25.0)
RISE, FAR, RET = (math.radians(d) for d in (120.0, 20.0, 90.0))
ALLOWED = (40.0, 45.0)


def _psi(phi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """ψ and dψ/dφ of the scene's laws in closed form: parabolic rise f = 2u², 1 − 2(1 − u)²; cosine
    return ψ = Ψ(1 + cos πu)/2."""
    p, d = np.zeros_like(phi), np.zeros_like(phi)
    r = phi <= RISE
    u = phi[r] / RISE
    p[r] = PSI * np.where(u < 0.5, 2 * u * u, 1 - 2 * (1 - u) ** 2)
    d[r] = PSI / RISE * np.where(u < 0.5, 4 * u, 4 * (1 - u))
    f = (phi > RISE) & (phi < RISE + FAR)
    p[f] = PSI
    t = (phi >= RISE + FAR) & (phi <= RISE + FAR + RET)
    u = (phi[t] - RISE - FAR) / RET
    p[t] = PSI * (1 + np.cos(math.pi * u)) / 2
    d[t] = -PSI * math.pi / (2 * RET) * np.sin(math.pi * u)
    return p, d


def _theta(R0: float, phi: np.ndarray) -> np.ndarray:
    """The pressure angle by inversion: C = O₁ + l·e^{i(π − ψ0 − ψ)} with O₁ = (a, 0), the profile
    C·e^{−iφ} (ccw), its tangent turned back to the fixed frame t = C′ − iC, C's velocity along
    u = ∂C/∂ψ / |∂C/∂ψ|; sin ϑ = Re(t̄u)/|t|, in degrees."""
    psi0 = math.acos((A * A + L * L - R0 * R0) / (2 * A * L))
    p, d = _psi(phi)
    e = np.exp(1j * (math.pi - psi0 - p))
    C = A + L * e
    t = -1j * L * e * d - 1j * C
    return np.degrees(np.arcsin(np.real(np.conj(t) * (-1j * e)) / np.abs(t)))


def _allowed(R0: float, n: int) -> bool:
    rise = np.linspace(0, RISE, n)[1:-1]
    ret = np.linspace(RISE + FAR, RISE + FAR + RET, n)[1:-1]
    return np.abs(_theta(R0, rise)).max() <= ALLOWED[0] and np.abs(_theta(R0, ret)).max() <= ALLOWED[1]


def _smallest_R0() -> float:
    """The first allowed radius of a 1 mm scan of the arm's reach, refined by bisection on fine grids."""
    first = next(R for R in np.arange(A - L + 0.001, A + L, 0.001) if _allowed(R, 1201))
    lo, hi = first - 0.001, first
    for _ in range(30):
        mid = 0.5 * (lo + hi)
        lo, hi = (lo, mid) if _allowed(mid, 12001) else (mid, hi)
    return hi


@pytest.fixture(scope="module")
def cam51(tmp_path_factory):
    path = tmp_path_factory.mktemp("cam51") / "cam51.toml"
    path.write_text(CAM51, encoding="utf-8")
    sol = solve(load(path))
    return path, sol, construct(sol, series="rad")


def test_r0_psi_theta_and_rho_are_the_brute_force_inversions(cam51):
    from graphplan.report.cam import cam_json
    _, sol, g = cam51
    doc = cam_json(sol, g, "x")
    assert doc["base_radius_min_m"] == pytest.approx(_smallest_R0(), abs=2e-6)
    R0 = doc["base_radius_m"]
    assert R0 == pytest.approx(0.053)
    phi = np.radians([p["phi_deg"] for p in doc["positions"]])
    psi, _ = _psi(phi)
    assert [p["exact"]["s_deg"] for p in doc["positions"]] == pytest.approx(np.degrees(psi), abs=1e-9)
    assert [p["exact"]["pressure_angle_deg"] for p in doc["positions"]] == pytest.approx(_theta(R0, phi), abs=1e-6)
    fine_rise = np.linspace(0, RISE, 40001)
    fine_ret = np.linspace(RISE + FAR, RISE + FAR + RET, 40001)
    assert doc["pressure_angle_max_deg"]["rise"] == pytest.approx(np.abs(_theta(R0, fine_rise)).max(), abs=1e-3)
    assert doc["pressure_angle_max_deg"]["return"] == pytest.approx(np.abs(_theta(R0, fine_ret)).max(), abs=1e-3)
    # ρ of the centre profile P = C·e^{−iφ} by differences on a fine grid: the smallest of its convex
    # part (P′ × P″ < 0 on a clockwise traversal) — at the parabolic rise's middle, d²ψ/dφ²'s jump
    phi = np.linspace(0, 2 * math.pi, 400001)[:-1]
    psi0 = math.acos((A * A + L * L - R0 * R0) / (2 * A * L))
    p, _ = _psi(phi)
    P = (A + L * np.exp(1j * (math.pi - psi0 - p))) * np.exp(-1j * phi)
    d1 = np.gradient(P, phi)
    d2 = np.gradient(d1, phi)
    cross = np.imag(np.conj(d1) * d2)
    rho = np.abs(d1) ** 3 / np.abs(cross)
    assert doc["curvature_min_m"] == pytest.approx(rho[cross < 0].min(), rel=2e-4)


@pytest.mark.parametrize("lang", ["uk", "en"])
def test_the_notes_explain_both_dwells_pressure_angles_by_the_triangle(cam51, lang):
    """Table 1 prints ϑ = 6.4° on the far dwell and −24.6° on the near one: the notes give both, each the
    brute force's at a point of its dwell, with R_max = |OC| at ψ_max."""
    from graphplan.report.cam import cam_json, cam_lines
    from graphplan.util.words import fixed
    _, sol, g = cam51
    doc = cam_json(sol, g, "x")
    R0 = doc["base_radius_m"]
    near, far = _theta(R0, np.radians([300.0, 130.0]))
    (line,) = [x for x in cam_lines(doc, lang) if "O_{1}C" in x]
    for want in (near, far):
        assert fixed(want, lang, 2).replace("-", "−") + "°" in line
    psi0 = math.acos((A * A + L * L - R0 * R0) / (2 * A * L))
    r_max = abs(A + L * np.exp(1j * (math.pi - psi0 - PSI)))
    assert fixed(r_max * 1000, lang, 2) + (" мм" if lang == "uk" else " mm") in line


@pytest.mark.slow
@pytest.mark.parametrize("fmt", ["A1", "A2"])
def test_the_sheet_and_the_terminal_print_one_graphical_r0(cam51, fmt):
    """The sheet's notes and `graphplan cam --format F` (construct_on) give the same graphical R0, and
    it is the drawn |OC₀| at the phase diagram's stated scale to the ruler's half millimetre."""
    import re

    from graphplan.drawing.cam import phase_diagram
    from graphplan.sheets.cam import build_cam_sheet, construct_on
    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.form import form
    path, sol, _ = cam51
    sheet = build_cam_sheet(load(path), form(fmt), SheetOptions(lang="en", sheet="cam"))
    printed = [float(x) for page in sheet.pages for x in re.findall(r"graphically ([0-9.]+) mm", page.svg())]
    g = construct_on(sol, form(fmt), lang="en")
    assert printed and all(x == pytest.approx(g.R0_min * 1000, abs=1e-9) for x in printed)
    mu = phase_diagram(sol, g, "en").scales["mu_phase"]
    assert g.R0_min / mu / 0.5 == pytest.approx(round(g.R0_min / mu / 0.5), abs=1e-9)
    assert abs(g.R0_min - g.R0_drawn) <= 0.25 * mu + 1e-12


# cam51's own scene: a rocking roller follower, the cam clockwise, a LINEAR rise of 100° (dψ/dφ and ϑ jump
# at its ends), a far dwell of 40°, a cycloidal return of 110° (OWN_CAM51).
A2_, L2, PSI2 = 0.140, 0.110, math.radians(20.0)


def _theta_own(R0: float, phi_deg: float, side: float) -> float:
    """The own scene's ϑ by inversion at ``phi_deg`` approached from ``side`` (±1), the cam clockwise:
    the profile C·e^{+iφ}, its tangent in the fixed frame t = C′ + iC; the linear rise ψ = Ψφ/Φ; the arm under
    the line O–O1, C = A + l·e^{−i(π − ψ0 − ψ)} (a clockwise cam's layout: the counter-clockwise one mirrored,
    stop 60)."""
    rise, far = 100.0, 40.0
    phi = phi_deg + side * 1e-7
    if 0 < phi < rise:
        p, d = PSI2 * phi / rise, PSI2 / math.radians(rise)
    elif rise <= phi <= rise + far:
        p, d = PSI2, 0.0
    elif phi < 0 or phi > 250.0:
        p, d = 0.0, 0.0
    else:
        raise ValueError(phi)
    psi0 = math.acos((A2_ * A2_ + L2 * L2 - R0 * R0) / (2 * A2_ * L2))
    e = np.exp(-1j * (math.pi - psi0 - p))
    C = A2_ + L2 * e
    t = 1j * L2 * e * d + 1j * C
    return math.degrees(math.asin(float(np.real(np.conj(t) * (1j * e))) / abs(t)))


@pytest.fixture(scope="module")
def own51_built(tmp_path_factory):
    """The own scene solved and constructed (the sheet's series, in rad) and its JSON."""
    from graphplan.report.cam import cam_json
    from review_scenes import OWN_CAM51
    path = tmp_path_factory.mktemp("own51") / "own51.toml"
    path.write_text(OWN_CAM51, encoding="utf-8")
    sol = solve(load(path))
    g = construct(sol, series="rad")
    return sol, g, cam_json(sol, g, "x")


@pytest.fixture(scope="module")
def own51(own51_built):
    return own51_built[2]


@pytest.mark.parametrize("lang", ["uk", "en"])
def test_table_1_gives_both_sides_of_the_linear_rises_pressure_angle_jumps(own51, lang):
    """At the linear rise's ends dψ/dφ jumps and ϑ with it: Table 1's ϑ cells there give both sides,
    «dwell → rise» at 0° and «rise → dwell» at the rise's end, each the brute force's; the graphical
    cells the same to a protractor's ½°."""
    from graphplan.report.cam import table_columns
    from graphplan.util.words import fixed
    cols = table_columns(own51, lang)
    R0 = own51["base_radius_m"]
    rows = {round(p["phi_deg"], 6): j for j, p in enumerate(own51["positions"])}

    def cell(x: float) -> str:
        return fixed(x, lang, 1).replace("-", "−")
    for phi in (0.0, 100.0):
        before, after = _theta_own(R0, phi, -1), _theta_own(R0, phi, +1)
        assert abs(before - after) > 5.0            # a real jump
        j = rows[phi]
        assert cols["theta"][j] == f"{cell(before)} → {cell(after)}"
        assert cols["theta_gr"][j] == f"{cell(round(before * 2) / 2)} → {cell(round(after * 2) / 2)}"


@pytest.mark.parametrize("lang", ["uk", "en"])
def test_the_near_dwells_pressure_angle_is_the_dwells_not_the_rises_side(own51, lang):
    """The note's near-dwell ϑ is the dwell's (the brute force in its middle), not the rise's 34.72° the
    row at 0° gives after the jump; the far dwell's likewise."""
    from graphplan.report.cam import cam_lines
    from graphplan.util.words import fixed
    R0 = own51["base_radius_m"]
    near, far = _theta_own(R0, 300.0, 0), _theta_own(R0, 120.0, 0)
    (line,) = [x for x in cam_lines(own51, lang) if "O_{1}C" in x]
    assert fixed(near, lang, 2).replace("-", "−") + "°" in line
    assert fixed(far, lang, 2).replace("-", "−") + "°" in line
    assert fixed(own51["pressure_angle_max_deg"]["rise"], lang, 2) + "°" not in line


@pytest.mark.parametrize("which, mu", [("lead", 0.001), ("own", 0.001), ("own", 0.0005)])
def test_every_number_of_the_phase_diagram_stands_by_its_own_point(cam51, own51_built, which, mu):
    """Each division's number on the rocking phase diagram (at the scales the A1 sheets draw them: the
    lead's 1:1, the own 2:1) nearer its point K than any other numbered point, and a dwell's number
    (dψ/dφ = 0: K = C, where R0, the [ϑ] lines and the arm's line meet; no other point within 2 mm) within 5 mm of it — «0; 13»
    stood 6–10 mm off C₀ inside the diagram among the arc's ticks."""
    from graphplan.drawing.cam import phase_diagram
    from graphplan.drawing.labels import _box_gap
    from graphplan.graphic.cam import phase_drawn_at
    sol, g = cam51[1:] if which == "lead" else own51_built[:2]
    rec = phase_diagram(sol, g if mu == g.mu_l else phase_drawn_at(g, mu), "uk")
    K = {q.step.split()[1]: complex(*q.points[0]) for q in rec.items if q.kind == "point" and q.step.startswith("K ")}
    numbers = [q for q in rec.items if q.kind == "text" and q.step.startswith("number ")]
    assert len(numbers) >= 12
    for q in numbers:
        k = q.step.split()[1]
        own = _box_gap(q.ink(), K[k])
        alone = all(abs(K[j] - K[k]) > 2.0 for j in K if j != k and abs(K[j] - K[k]) > 1e-6)
        assert g.v[int(k)] != 0 or not alone or own <= 5.0, (q.text, own)    # two dots 0.7 mm apart share room
        named = {j for q2 in numbers for j in [q2.step.split()[1]]}
        assert all(_box_gap(q.ink(), K[j]) > own for j in named if j != k and abs(K[j] - K[k]) > 1e-6), q.text


@pytest.mark.parametrize("which", ["lead", "own"])
def test_the_dwell_notes_formula_gives_the_printed_signs(cam51, own51, which):
    """The note's formula (90° − ∠OCO₁ or ∠OCO₁ − 90°), evaluated with ∠OCO₁ of the triangle OO₁C by
    the law of cosines (a, l and |OC| = R0 on the near dwell, R_max on the far), gives both printed
    values with their signs — for the counter-clockwise lead's cam and the clockwise own one (whose
    note printed +17.18° beside 90° − 107.18°)."""
    import re

    from graphplan.report.cam import cam_json, cam_lines
    doc = cam_json(cam51[1], cam51[2], "x") if which == "lead" else own51
    a, l = doc["centre_distance_m"], doc["arm_m"]
    (line,) = [x for x in cam_lines(doc, "en") if "O_{1}C" in x]
    near, far = (float(x.replace("−", "-")) for x in re.search(r"near (\S+)°, far (\S+)°", line).groups())
    psi0 = math.radians(doc["arm_angle_deg"])
    for value, psi in ((near, psi0), (far, psi0 + math.radians(doc["swing_deg"]))):
        r = math.sqrt(a * a + l * l - 2 * a * l * math.cos(psi))         # |OC| with the arm at ψ0 + ψ
        gamma = math.degrees(math.acos((l * l + r * r - a * a) / (2 * l * r)))
        want = 90.0 - gamma if "ϑ = 90° − ∠OCO_{1}" in line else gamma - 90.0
        assert "ϑ = 90° − ∠OCO_{1}" in line or "ϑ = ∠OCO_{1} − 90°" in line
        assert value == pytest.approx(want, abs=0.006)


@pytest.mark.slow
def test_cam50s_a3_profile_is_drawn_at_1_1_on_its_later_sheet(tmp_path):
    """CAM50's profile (≈ 250 mm across at 1:1) stands on an A3 sheet's field — 420 × 297 mm less the
    frame (20 mm left, 5 mm elsewhere) — above the later sheets' form 2a (15 mm high): the set draws it
    at 1:1, not at 1:2 as sized under the first sheet's 55 mm form 1; the drawing, measured, fits."""
    from graphplan.drawing.cam import profile_drawing
    from graphplan.sheets.cam import build_cam_sheet, construct_on
    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.form import form
    from review_scenes import CAM50
    path = tmp_path / "cam50.toml"
    path.write_text(CAM50, encoding="utf-8")
    cam = load(path)
    sheet = build_cam_sheet(cam, form("A3"), SheetOptions(lang="en", sheet="cam"))
    pages = [p.svg() for p in sheet.pages]
    (profile_page,) = [p for p in pages if "Cam profile" in p]
    assert "(M 1:1)" in profile_page
    g = construct_on(solve(cam), form("A3"), lang="en")
    x0, y0, x1, y1 = profile_drawing(solve(cam), g, "en").bounds()
    assert g.mu_l == pytest.approx(0.001)
    assert x1 - x0 < 420 - 25 and y1 - y0 + 15 < 297 - 10 - 15       # its caption's two lines ≈ 15 mm
