"""Stop 55 (cam55): the lead's CAM55 (a translating roller follower, the cam clockwise, offset "auto", a
parabolic rise of 150° straight into a LINEAR return of 90°, no far dwell) and cam55's own OWN_CAM55 (a
rocking roller follower, the cam counter-clockwise, a cosine rise and a cycloidal return), checked against
brute forces of their own: the laws written out, the centre profile by the inversion turned point by
point, the pressure angle from that profile's finite-difference tangent, R0 by bisection, the offset by a
scan. And a law's exact zeros printed 0 wherever the cam prints numbers (the terminal printed
«ds/dφ 4,584·10⁻¹⁰ → −28,65 мм/рад» at φ = 150°: the law a hair before the phase's end, not at it)."""
from __future__ import annotations

import itertools
import math
import re
import tomllib

import numpy as np
import pytest

from camfixtures import cam_fixture
from graphplan.model.cam import build
from review_scenes import CAM55, OWN_CAM55

LAWS = ("parabolic", "cosine", "cycloidal", "linear", "trapezoidal")


# -- a law's zeros are zeros -------------------------------------------------------------------------------

def test_the_laws_exact_values_at_the_phase_start_middle_and_end():
    """f(0) = 0, f(1) = 1, and the closed forms' zeros: f′(0) = f′(1) = 0 of every law but the linear,
    f″(½) = 0 of the cosine and the cycloidal, f″(0) = f″(1) = 0 of the cycloidal and the trapezoidal —
    exactly, also where u comes from a division's turn over the phase (an ulp off ½ or 1)."""
    from graphplan.exact.cam import law
    shares = [np.linspace(0.0, phase, n + 1) / phase for phase in (77.0, 100.0, 110.0, 150.0, 163.3)
              for n in (4, 6, 8, 10, 12)]
    for name in LAWS:
        for u in shares:
            f, f1, f2 = law(name, u)
            assert f[0] == 0.0 and f[-1] == 1.0
            if name != "linear":
                assert f1[0] == 0.0 and f1[-1] == 0.0, name
            mid = len(u) // 2
            if len(u) % 2 and name in ("cosine", "cycloidal"):
                assert f2[mid] == 0.0, name
            if name in ("cycloidal", "trapezoidal", "linear"):
                assert f2[0] == 0.0 and f2[-1] == 0.0, name
        # away from the exact points the law is the closed form (the snap is only ulps wide)
        u = np.array([0.1, 0.37, 0.5 + 1e-6, 0.93])
        f, f1, f2 = law(name, u)
        if name == "cosine":
            assert np.allclose(f1, np.pi / 2 * np.sin(np.pi * u), rtol=1e-14, atol=0)
            assert np.allclose(f2, np.pi ** 2 / 2 * np.cos(np.pi * u), rtol=1e-9, atol=0)
        if name == "cycloidal":
            assert np.allclose(f1, 1 - np.cos(2 * np.pi * u), rtol=1e-14, atol=0)


def _scene(rise_law: str, ret_law: str, follower: str, far: int, sense: str) -> str:
    geometry = 'stroke = 0.045\noffset = "auto"' if follower == "translating" else \
        "swing_deg = 20\narm = 0.1\ncentre_distance = 0.12"
    near = 120
    ret = 360 - 150 - far - near
    return f"""title = "t"
[cam]
follower = "{follower}"
{geometry}
roller_radius = 0.008
phases_deg = {{ rise = 150, dwell_far = {far}, return = {ret}, dwell_near = {near} }}
laws = {{ rise = "{rise_law}", return = "{ret_law}" }}
pressure_angle_deg = {{ rise = 45, return = 45 }}
rpm = 90
direction = "{sense}"
divisions = 6
"""


@pytest.mark.slow
@pytest.mark.parametrize("rise_law,ret_law", [(a, b) for a, b in itertools.product(LAWS, LAWS)
                                               if "linear" in (a, b) and a != b])
def test_a_corners_sides_are_the_laws_own_values(rise_law, ret_law):
    """At a corner of the centre profile (a linear law's end) each side of ds/dφ is the law's value at
    the phase's end: exactly 0 beside a dwell or a law whose f′ vanishes there, exactly ±h/Φ on the
    linear side — and the corner's sides as the JSON, the terminal and the notes print them carry no
    ·10ⁿ of round-off (a parabolic rise into a linear return printed 4,584·10⁻¹⁰)."""
    from graphplan.exact.cam import solve
    from graphplan.graphic.cam import construct
    from graphplan.report.cam import cam_json, cam_table
    for follower, far, sense in (("translating", 0, "cw"), ("rocking", 0, "ccw"), ("translating", 20, "ccw")):
        cam = build(tomllib.loads(_scene(rise_law, ret_law, follower, far, sense)), "<corner>")
        sol = solve(cam)
        h = cam.stroke
        R, T = math.radians(cam.phases[0]), math.radians(cam.phases[2])
        linear = {0: h / R, 1: -h / T}
        for c in sol.corners():
            for side, value in (("before", c.v_before), ("after", c.v_after)):
                # which phase is on this side of the corner: the rise ends at 150°, the return starts at 150 + far
                if c.phi_deg == 0.0:
                    k = None if side == "before" else 0
                elif c.phi_deg == 150.0:
                    k = 0 if side == "before" else (1 if far == 0 else None)
                elif c.phi_deg == 150.0 + far:
                    k = None if side == "before" else 1
                else:
                    k = 1 if side == "before" else None
                want = 0.0 if k is None or cam.laws[k] != "linear" else linear[k]
                assert value == pytest.approx(want, rel=1e-12, abs=0.0), (follower, c, side)
        doc = cam_json(sol, construct(sol, 6, 0.5), "")
        said = cam_table(doc, "uk", "t") + cam_table(doc, "en", "t")
        assert "·10" not in said


# -- CAM55 against its own brute force -----------------------------------------------------------------------

H, RISE, RET, NEAR, ALLOWED = 45.0, 150.0, 90.0, 120.0, (30.0, 40.0)     # mm, deg; the cam clockwise


def _s55(phi):
    phi = np.asarray(phi, float)
    u = np.clip(phi / RISE, 0, 1)
    w = np.clip((phi - RISE) / RET, 0, 1)
    return np.where(phi <= RISE, H * np.where(u <= 0.5, 2 * u * u, 1 - 2 * (1 - u) ** 2), H * (1 - w))


def _pitch55(phi, R0, x):
    """The roller centre in the cam's frame: the fixed-frame point (x, s0 + s) turned by +φ (the cam
    turns clockwise, the follower is carried round it counter-clockwise); x the axis's abscissa."""
    s0 = math.sqrt(R0 * R0 - x * x)
    t = np.radians(phi)
    y = s0 + _s55(phi)
    return x * np.cos(t) - y * np.sin(t), x * np.sin(t) + y * np.cos(t)


def _theta55(phi, R0, x, d=1e-4):
    """|ϑ| (deg): the tangent by central differences against the follower's axis turned with the frame."""
    (xa, ya), (xb, yb) = _pitch55(phi - d, R0, x), _pitch55(phi + d, R0, x)
    t = np.radians(phi)
    ux, uy = -np.sin(t), np.cos(t)                      # the axis's direction in the cam's frame
    tx, ty = xb - xa, yb - ya
    return np.degrees(np.arcsin(np.abs(tx * ux + ty * uy) / np.hypot(tx, ty)))


UP, DOWN = np.linspace(0.001, RISE - 0.001, 3001), np.linspace(RISE + 0.001, RISE + RET - 0.001, 2001)


def _brute_R0(x: float) -> float:
    lo, hi = abs(x) + 1e-6, 200.0
    for _ in range(40):
        mid = (lo + hi) / 2
        ok = _theta55(UP, mid, x).max() <= ALLOWED[0] and _theta55(DOWN, mid, x).max() <= ALLOWED[1]
        lo, hi = (lo, mid) if ok else (mid, hi)
    return hi


cam55 = cam_fixture("cam55", CAM55, 8)


@pytest.mark.slow
def test_cam55_offset_base_radius_angles_and_curvature_by_brute_force(cam55):
    """The offset "auto" is the brute force's best (the follower's axis ~0.99 mm LEFT of O, which lowers
    the rise's angle for this clockwise cam; taken to 0.1 mm: 1 mm), R0 at it (35.347 mm), the phases'
    largest angles at the R0 taken (36 mm: 29.71°, 39.48°) and ρ_min of the smooth parts (33.53 mm)."""
    cam, sol, g, doc = cam55
    xs = np.arange(-4.0, 4.01, 0.5)
    radii = [_brute_R0(x) for x in xs]
    j = int(np.argmin(radii))
    fine = np.arange(xs[j] - 0.5, xs[j] + 0.501, 0.05)
    radii = [_brute_R0(x) for x in fine]
    best = fine[int(np.argmin(radii))]
    axis = -doc["offset_m"] * 1000                       # clockwise: the axis at x = −e
    assert axis == pytest.approx(best, abs=0.06) and axis < 0
    assert doc["base_radius_min_m"] * 1000 == pytest.approx(_brute_R0(axis), abs=0.01)
    assert min(radii) <= doc["base_radius_min_m"] * 1000 + 0.01
    R0 = doc["base_radius_m"] * 1000
    assert R0 == pytest.approx(36.0)
    up, down = (np.linspace(a, b, 40001) for a, b in ((0.001, RISE - 0.001), (RISE + 0.001, RISE + RET - 0.001)))
    assert doc["pressure_angle_max_deg"]["rise"] == pytest.approx(_theta55(up, R0, axis).max(), abs=0.01)
    assert doc["pressure_angle_max_deg"]["return"] == pytest.approx(_theta55(down, R0, axis).max(), abs=0.01)
    # ρ of the smooth pieces (the corners at 150° and 240° are ρ = 0, left out)
    least = math.inf
    for a, b in ((0.0, RISE), (RISE, RISE + RET), (RISE + RET, 360.0)):
        phi = np.linspace(a + 1e-3, b - 1e-3, 40001)
        x, y = _pitch55(phi, R0, axis)
        dp = math.radians(phi[1] - phi[0])
        x1, y1 = np.gradient(x, dp), np.gradient(y, dp)
        x2, y2 = np.gradient(x1, dp), np.gradient(y1, dp)
        rho = (x1 * x1 + y1 * y1) ** 1.5 / (x1 * y2 - y1 * x2)
        assert (rho[2:-2] > 0).all()                    # convex between the corners (counter-clockwise: +)
        least = min(least, rho[2:-2].min())
    assert doc["curvature_min_m"] * 1000 == pytest.approx(least, abs=0.05)
    # the corners: convex at the rise's end (the parabolic rise's ds/dφ 0 → the return's −h/Φ), concave at 240°
    corners = doc["profile_corners"]
    assert [c["phi_deg"] for c in corners] == [150.0, 240.0]
    assert corners[0]["ds_dphi_before_m"] == 0.0 and corners[1]["ds_dphi_after_m"] == 0.0
    assert corners[0]["ds_dphi_after_m"] == pytest.approx(-H / 1000 / math.radians(RET), rel=1e-12)
    assert corners[0]["convex"] and not corners[1]["convex"]


def test_cam55_prints_the_laws_zeros_as_0(cam55):
    """The terminal, the notes and Table 1 say the corner at 150° as «0 → −28,65»: no ·10ⁿ anywhere; the
    jump row's ruler ordinate and graphical value carry both sides too (row 8 printed a bare 0 in both
    while its exact cell said «0 → −28,65»: its own side's ordinate is 0, so μ came from no row)."""
    from graphplan.report.cam import cam_lines, cam_table, table_columns
    cam, sol, g, doc = cam55
    for lang in ("uk", "en"):
        text = cam_table(doc, lang, "t") + "\n".join(cam_lines(doc, lang))
        assert "·10" not in text
        comma = "," if lang == "uk" else "."
        assert f"φ = 150° (0 → −28{comma}65" in text
        cols = table_columns(doc, lang)
        j = next(k for k, p in enumerate(doc["positions"]) if p["phi_deg"] == 150.0)
        for c in ("v", "v_mm", "v_gr"):
            a, b = cols[c][j].split(" → ")
            assert a == "0" and b.startswith("−"), (c, cols[c][j])
        mu = doc["scales"]["mu_v_mm"] * 1000
        y = float(cols["v_mm"][j].split(" → ")[1].replace("−", "-").replace(",", "."))
        v = float(cols["v_gr"][j].split(" → ")[1].replace("−", "-").replace(",", "."))
        assert v == pytest.approx(y * mu, abs=0.006)
        assert abs(y * mu - (-28.648)) <= doc["precision_mm"] / 2 * mu + 1e-9


def test_cam55_phase_diagram_draws_the_printed_angles(cam55):
    """The angles at the drawn O between its lines to the drawn points and the follower's axis are the
    table's graphical ϑ within 1° (the clockwise cam's O right of the s axis: the axis left of O)."""
    from graphplan.drawing.cam import phase_diagram
    from test_cam_robust import drawn_angles
    cam, sol, g, doc = cam55
    rec = phase_diagram(sol, g, "uk")
    angles = drawn_angles(rec, False)
    assert len(angles) == len(doc["positions"])
    for k, p in enumerate(doc["positions"]):
        assert abs(angles[k] - abs(p["graphical"]["pressure_angle_deg"])) < 1.0, (k, angles[k])
        assert abs(angles[k] - abs(p["exact"]["pressure_angle_deg"])) < 1.0, (k, angles[k])
    O = next(p for p in rec.items if p.step == "O").points[0]
    axis = next(p for p in rec.items if p.step == "follower axis").points[0]
    assert O[0] > axis[0]


# -- OWN_CAM55: a rocking roller follower, the cam counter-clockwise ----------------------------------------

SWING, ARM, DIST = math.radians(22.0), 110.0, 130.0
PH = (110.0, 30.0, 120.0, 100.0)


def _psi(phi):
    rise, far, ret, _ = PH
    phi = np.asarray(phi, float)
    u = np.clip(phi / rise, 0, 1)
    w = np.clip((phi - rise - far) / ret, 0, 1)
    up = SWING * (1 - np.cos(np.pi * u)) / 2
    down = SWING * (1 - (w - np.sin(2 * np.pi * w) / (2 * np.pi)))
    return np.where(phi <= rise, up, np.where(phi < rise + far, SWING, np.where(phi <= rise + far + ret, down, 0.0)))


def _rocker(phi, R0):
    """The roller centre: the pivot A = (a, 0), the arm at ψ0 + ψ from the line A→O (|OC| = R0 at ψ = 0,
    growing with ψ), C above the line; in the cam's frame turned back by −φ (the cam counter-clockwise)."""
    psi0 = math.acos((DIST ** 2 + ARM ** 2 - R0 ** 2) / (2 * DIST * ARM))
    ang = np.pi - psi0 - _psi(phi)
    cx, cy = DIST + ARM * np.cos(ang), ARM * np.sin(ang)
    t = -np.radians(phi)
    return cx * np.cos(t) - cy * np.sin(t), cx * np.sin(t) + cy * np.cos(t), ang


def _theta_rocker(phi, R0, d=1e-4):
    (xa, ya, _), (xb, yb, _) = _rocker(phi - d, R0), _rocker(phi + d, R0)
    _, _, ang = _rocker(phi, R0)
    t = -np.radians(phi)
    vx, vy = -np.sin(ang), np.cos(ang)                  # C's velocity as ψ grows: square to the arm
    ux, uy = vx * np.cos(t) - vy * np.sin(t), vx * np.sin(t) + vy * np.cos(t)
    tx, ty = xb - xa, yb - ya
    return np.degrees(np.arcsin(np.abs(tx * ux + ty * uy) / np.hypot(tx, ty)))


@pytest.mark.slow
def test_own_cam55_rocking_by_brute_force():
    """R0 (the smallest with |ϑ| ≤ 40° on both phases), the phases' largest angles at the R0 taken and
    ρ_min as the brute force finds them; the near dwell's ϑ the triangle OO₁C's."""
    from graphplan.exact.cam import solve
    from graphplan.graphic.cam import construct
    from graphplan.report.cam import cam_json
    cam = build(tomllib.loads(OWN_CAM55), "<own55>")
    sol = solve(cam)
    doc = cam_json(sol, construct(sol, 10, 0.5), "")
    up = np.linspace(0.001, 109.999, 4001)
    down = np.linspace(140.001, 259.999, 4001)

    def worst(R0):
        return max(_theta_rocker(up, R0).max() / 40.0, _theta_rocker(down, R0).max() / 40.0)
    # the allowed radii from the reach's low end: the first allowed one on a scan, then bisection
    scan = np.linspace(DIST - ARM + 0.01, 100.0, 400)
    first = next(k for k, R in enumerate(scan) if worst(R) <= 1.0)
    lo, hi = scan[first - 1], scan[first]
    for _ in range(40):
        mid = (lo + hi) / 2
        lo, hi = (lo, mid) if worst(mid) <= 1.0 else (mid, hi)
    assert doc["base_radius_min_m"] * 1000 == pytest.approx(hi, abs=0.02)
    R0 = doc["base_radius_m"] * 1000
    assert R0 == pytest.approx(math.ceil(hi))
    assert doc["pressure_angle_max_deg"]["rise"] == pytest.approx(_theta_rocker(up, R0).max(), abs=0.01)
    assert doc["pressure_angle_max_deg"]["return"] == pytest.approx(_theta_rocker(down, R0).max(), abs=0.01)
    phi = np.linspace(0.0, 360.0, 72001)[:-1]
    x, y, _ = _rocker(phi, R0)
    dp = math.radians(phi[1] - phi[0])
    x1, y1 = np.gradient(x, dp), np.gradient(y, dp)
    x2, y2 = np.gradient(x1, dp), np.gradient(y1, dp)
    rho = (x1 * x1 + y1 * y1) ** 1.5 / (x1 * y2 - y1 * x2)
    convex = rho < 0                                    # the profile runs clockwise in the cam's frame
    assert doc["curvature_min_m"] * 1000 == pytest.approx(np.abs(rho[convex]).min(), abs=0.05)
    near = doc["dwell_pressure_angle_deg"]["near"]
    gamma = math.degrees(math.acos((ARM ** 2 + R0 ** 2 - DIST ** 2) / (2 * ARM * R0)))
    assert abs(near) == pytest.approx(abs(90.0 - gamma), abs=0.01)
    assert not doc["profile_corners"]
    assert re.search("·10", "\n".join(str(v) for v in doc["warnings_uk"])) is None


# -- the short-ordinate rule at its bound (LEFT54: OWN_CAM54's δψ = −20,00*) ------------------------------------

@pytest.mark.slow
def test_short_ordinate_rule_judges_by_the_exact_ordinate_at_its_bound():
    """errors_pct leaves δ out below SHORT_DIVISIONS ruler divisions of the EXACT ordinate and judges it
    at the bound and above; OWN_CAM54's ψ = 0,25° (μ_ψ = 0,2 °/мм: 1.25 mm, read 1,0 mm) keeps δ = −20,00*
    — half a division of 1.25 mm — and every «—» of its Table 1 is a zero, under 1 % of the largest, or
    an exact ordinate under 1 mm, as the note now says."""
    from graphplan.exact.cam import solve
    from graphplan.graphic.cam import SHORT_DIVISIONS, construct, errors_pct
    from graphplan.report.cam import short_note, table_columns
    from review_scenes import OWN_CAM54
    least = SHORT_DIVISIONS * 0.5 * 0.2                  # 2 divisions of 0.5 mm at 0.2 °/mm: 0.2°
    at, under = errors_pct(np.array([0.15, 0.15]), np.array([least, least * 0.999]), 20.0, least)
    assert at == pytest.approx(-25.0) and under is None
    cam = build(tomllib.loads(OWN_CAM54), "<own54>")
    sol = solve(cam)
    from graphplan.report.cam import cam_json
    from graphplan.sheets.cam import construct_on
    from graphplan.sheets.form import form
    for g in (construct(sol, 10, 0.5), construct_on(sol, form("A1"), None, 0.5, "uk")):   # any scales; the sheet's last
        doc = cam_json(sol, g, "")
        _dashes_as_said(cam, doc)
    cols = table_columns(doc, "uk")
    row = next(j for j, p in enumerate(doc["positions"]) if abs(p["phi_deg"] - 230.0) < 1e-9)
    assert doc["positions"][row]["exact"]["s_deg"] / math.degrees(doc["scales"]["mu_s_mm"]) == pytest.approx(1.25)
    assert cols["ds"][row] == "−20,00*"
    assert "точна ордината" in short_note(doc, "uk") and "exact ordinate" in short_note(doc, "en")


def _dashes_as_said(cam, doc) -> None:
    from graphplan.report.cam import table_columns
    cols = table_columns(doc, "uk")
    mu = {"s": doc["scales"]["mu_s_mm"], "ds_dphi": doc["scales"]["mu_v_mm"]}
    big = {q: max(abs(p["exact"][q + "_deg"]) for p in doc["positions"]) for q in mu}
    for j, p in enumerate(doc["positions"]):
        for q, c in (("s", "ds"), ("ds_dphi", "dv")):
            value = math.radians(p["exact"][q + "_deg"])
            ordinate = abs(value) / mu[q]
            dash = cols[c][j] == "—"
            small = value == 0 or ordinate < 1.0 - 1e-9 or abs(p["exact"][q + "_deg"]) < 0.01 * (
                math.degrees(cam.stroke) if q == "s" else big[q]) * (1 - 1e-12)
            assert dash == small, (j, q, ordinate, cols[c][j])


def test_own_cam55_phase_diagram_draws_the_printed_angles():
    """The rocking follower's phase diagram: the angles at the drawn O between its lines to the drawn
    points and the perpendiculars of the drawn arms are the table's graphical ϑ within 1°."""
    from graphplan.drawing.cam import phase_diagram
    from graphplan.exact.cam import solve
    from graphplan.graphic.cam import construct
    from graphplan.report.cam import cam_json
    from test_cam_robust import drawn_angles
    cam = build(tomllib.loads(OWN_CAM55), "<own55>")
    sol = solve(cam)
    g = construct(sol, 10, 0.5)
    doc = cam_json(sol, g, "")
    angles = drawn_angles(phase_diagram(sol, g, "uk"), True)
    assert len(angles) == len(doc["positions"])
    for k, p in enumerate(doc["positions"]):
        assert abs(angles[k] - abs(p["graphical"]["pressure_angle_deg"])) < 1.0, (k, angles[k])
