"""Stop 60's cam sheet: the lead's CAM60 (a ROCKING roller follower, the cam CLOCKWISE, a cycloidal rise of
120°, a far dwell of 60°, a cosine return of 100°, a swing of 20°, arm l = 100 mm at a = 130 mm, r = 12 mm,
[ϑ] 35°/40°, 12 divisions) against a pressure angle computed here another way than the program's: the
force's line (the profile's normal) passes through the instant centre P of the cam and the arm on the line
of centres OA (ω_cam·OP = ω_arm·AP), and ϑ is its angle to the roller centre's velocity (square to AC);
R0 by bisection, the centre profile's curvature by finite differences of its inversion; and the phase
diagram's |OC₀| lettered with the R0 taken (stop 60: it read «R_0» alone). The arm stands under the line
O–O1, the counter-clockwise layout mirrored for the clockwise cam (stop 60, cam60c: over it, the side that
raises the rise's pressure angle, R0 min was 54,44 mm; under it 49,44)."""
from __future__ import annotations

import math

import numpy as np
import pytest

from camfixtures import cam_fixture
from review_scenes import CAM60, CG60_CAM_NO_DWELL

cam60 = cam_fixture("cam60", CAM60, 12)
nodwell = cam_fixture("nodwell", CG60_CAM_NO_DWELL, 10)

A, L, SWING = 130.0, 100.0, math.radians(20.0)       # mm, mm, rad
RISE, FAR, RET = (math.radians(x) for x in (120.0, 60.0, 100.0))
ALLOWED = (35.0, 40.0)
SIGMA = -1                                             # clockwise


def _psi(phi):
    """ψ and dψ/dφ (rad, rad/rad) at the cam's turns ``phi`` (rad): cycloidal rise, far dwell, cosine return."""
    phi = np.asarray(phi, float)
    psi, d1 = np.zeros_like(phi), np.zeros_like(phi)
    m = phi <= RISE
    u = phi[m] / RISE
    psi[m] = SWING * (u - np.sin(2 * np.pi * u) / (2 * np.pi))
    d1[m] = SWING / RISE * (1 - np.cos(2 * np.pi * u))
    psi[(phi > RISE) & (phi <= RISE + FAR)] = SWING
    m = (phi > RISE + FAR) & (phi <= RISE + FAR + RET)
    u = (phi[m] - RISE - FAR) / RET
    psi[m] = SWING * (1 + np.cos(np.pi * u)) / 2
    d1[m] = -SWING * np.pi / (2 * RET) * np.sin(np.pi * u)
    return psi, d1


def _theta(R0, phi, side=-1):
    """ϑ (deg) at base radius R0 (mm): O at 0, the pivot A at (a, 0), the roller centre C = A + l·e^{−i(π − β)}
    under O–O1 (``side`` −1; +1: C = A + l·e^{i(π − β)} over it), β = ψ0 + ψ; P on OA where the cam (ω = σ) and
    the arm (ω = ∓dψ/dφ) have one velocity; the angle from C's velocity as ψ grows to the line CP, + where it
    opposes the rise (the program's sign)."""
    psi, d1 = _psi(phi)
    beta = math.acos((A * A + L * L - R0 * R0) / (2 * A * L)) + psi
    C = A + L * np.exp(1j * side * (np.pi - beta))
    wa = -side * d1
    p = wa * A / (wa - SIGMA)
    ang = np.angle((p - C) / (side * 1j * (C - A)))
    return -np.degrees((ang + np.pi / 2) % np.pi - np.pi / 2)


PHI = np.linspace(0.0, RISE + FAR + RET, 56001)
ON = (PHI <= RISE, PHI >= RISE + FAR)


def _least(side: int = -1) -> float:
    def worst(R0):
        th = np.abs(_theta(R0, PHI, side))
        return max(th[ON[0]].max() / ALLOWED[0], th[ON[1]].max() / ALLOWED[1])
    lo, hi = A - L + 1e-6, A + L - 1e-6
    scan = np.linspace(lo, hi, 120)
    k = next(i for i, R in enumerate(scan) if worst(R) <= 1.0)
    lo, hi = scan[k - 1], scan[k]
    for _ in range(60):
        mid = (lo + hi) / 2
        lo, hi = (lo, mid) if worst(mid) <= 1.0 else (mid, hi)
    return hi


def test_cam60_base_radius_pressure_angles_and_curvature_by_the_instant_centre(cam60):
    """R0 min 49,441 mm with the arm under O–O1 (the return binds: 40° at φ ≈ 252°; over it 54,444 mm, the rise
    binding); at the taken 50 mm ψ0 = 20,21° (the law of cosines), the rise's largest |ϑ| 26,10° at its start —
    the near dwell's own angle ∠OCA − 90° —, the return's 39,39°, ϑ at the 26 divisions; the centre profile's
    least radius of curvature 48,90 mm."""
    cam, sol, g, doc = cam60
    least = _least()
    assert least == pytest.approx(49.4411, abs=1e-3)
    assert _least(+1) == pytest.approx(54.4437, abs=1e-3)            # the arm on the other side: larger
    assert doc["base_radius_min_m"] * 1000 == pytest.approx(least, abs=1e-3)
    assert doc["base_radius_m"] == pytest.approx(0.050)
    assert doc["arm_angle_deg"] == pytest.approx(math.degrees(math.acos((A * A + L * L - 50.0 ** 2) / (2 * A * L))))
    th = _theta(50.0, PHI)
    for name, m in zip(("rise", "return"), ON):
        k = int(np.argmax(np.abs(th[m])))
        assert doc["pressure_angle_extreme_deg"][name] == pytest.approx(th[m][k], abs=0.01)
        assert doc["pressure_angle_extreme_phi_deg"][name] == pytest.approx(math.degrees(PHI[m][k]), abs=0.05)
    assert doc["pressure_angle_extreme_deg"]["return"] == pytest.approx(-39.39, abs=0.01)
    gamma = math.acos((50.0 ** 2 + L * L - A * A) / (2 * 50.0 * L))       # ∠OCA at the near dwell
    assert abs(doc["pressure_angle_extreme_deg"]["rise"]) == pytest.approx(math.degrees(gamma) - 90.0, abs=0.01)
    assert doc["pressure_angle_extreme_phi_deg"]["rise"] == pytest.approx(0.0, abs=0.05)
    for p in doc["positions"]:
        want = float(_theta(50.0, [math.radians(p["phi_deg"])])[0])
        assert p["exact"]["pressure_angle_deg"] == pytest.approx(want, abs=0.01), p["number"]
    # the centre profile P(φ) = C(φ)·e^{−iσφ}: its least radius of curvature where it is convex
    ph = np.linspace(0.0, 2 * np.pi, 360001)[:-1]
    psi, _ = _psi(ph)
    beta = math.acos((A * A + L * L - 50.0 ** 2) / (2 * A * L)) + psi
    P = (A + L * np.exp(-1j * (np.pi - beta))) * np.exp(-1j * SIGMA * ph)
    h = ph[1] - ph[0]
    P1, P2 = (np.roll(P, -1) - np.roll(P, 1)) / (2 * h), (np.roll(P, -1) - 2 * P + np.roll(P, 1)) / h ** 2
    k = (P1.conjugate() * P2).imag / np.abs(P1) ** 3
    convex = k * np.sign(np.median(k)) > 0
    assert doc["curvature_min_m"] * 1000 == pytest.approx(float(np.min(1 / np.abs(k[convex]))), abs=0.01)
    assert doc["curvature_min_m"] * 1000 == pytest.approx(48.90, abs=0.01)


@pytest.mark.parametrize("lang", ["uk", "en"])
def test_cam60_phase_diagram_letters_r0_with_the_radius_taken(cam60, lang):
    """The rocking phase diagram's |OC₀| (O on its arc about the pivot at the R0 taken, O_min off it at the
    smallest) is lettered «R_0 = 50 мм» (en «mm»), the length drawn times μ, not «R_0» alone."""
    from graphplan.drawing.cam import phase_diagram
    cam, sol, g, doc = cam60
    rec = phase_diagram(sol, g, lang)
    mu = rec.scales["mu_phase"] * 1000                                     # mm of the cam a drawn mm
    (seg,) = [q for q in rec.items if q.step == "R0" and q.kind == "segment"]
    p, q = (complex(*z) for z in seg.points)
    assert abs(q - p) * mu == pytest.approx(50.0, abs=1e-6)
    texts = [q.text for q in rec.items if q.kind == "text"]
    assert f"R_0 = 50 {'мм' if lang == 'uk' else 'mm'}" in texts and "R_0" not in texts


@pytest.mark.parametrize("row", [7.0, 6.5])
def test_cam60_table_at_closer_rows_keeps_its_header_clear(cam60, row):
    """Table 1 at 3.5-mm letters in the closer rows the sets now take (stop 60): the header's «y_{dψ/dφ}, мм»,
    its subscript's φ tail 1.79 mm under the baseline, at least RULE_CLEAR (0.8 mm) over the thick rule under
    the header — measured off the record — and no collision by the sheets' own check."""
    from graphplan.drawing.labels import collisions
    from graphplan.drawing.tables import RULE_CLEAR
    from graphplan.sheets.cam import positions_table
    cam, sol, g, doc = cam60
    rec = positions_table(doc, "uk", row, 3.5)
    ys = sorted({p.points[0][1] for p in rec.items if p.kind == "segment" and p.points[0][1] == p.points[1][1]},
                reverse=True)
    (tail,) = [p.ink() for p in rec.items if p.kind == "text" and p.text == "y_{dψ/dφ}, мм"]
    assert tail[1] - ys[1] >= RULE_CLEAR - 1e-9 and ys[0] - tail[3] >= RULE_CLEAR - 1e-9
    assert collisions(rec) == []


def test_cg60_no_dwell_cam_auto_offset_and_base_radius_by_closed_forms(nodwell):
    """cg60's own cam (a cycloidal rise of 150° straight into a parabolic return of 120°, h = 40 mm, [ϑ] 30°/35°,
    "auto" offset, counter-clockwise): tg ϑ = (ds/dφ − e)/(s0 + s) on a 0.005° grid, R0 by bisection at each
    offset; the smallest R0 over e lies at e* = 0.437 mm (35.179 mm), the program's e is the draftsman's tenth
    of a millimetre nearest it, 0.4 mm, where the least R0 is 35.243 mm (the return binds at its middle,
    −35° at φ = 210°); taken 36 mm: the rise's largest ϑ 29.62° at φ = 63.89°, the return's −34.58° at 210°."""
    cam, sol, g, doc = nodwell
    H, rise, ret = 40.0, math.radians(150.0), math.radians(120.0)
    phi = np.linspace(0.0, rise + ret, 54001)
    up = phi <= rise
    u = np.where(up, phi / rise, (phi - rise) / ret)
    s = np.where(up, H * (u - np.sin(2 * np.pi * u) / (2 * np.pi)), np.where(u < 0.5, H * (1 - 2 * u * u), 2 * H * (1 - u) ** 2))
    v = np.where(up, H / rise * (1 - np.cos(2 * np.pi * u)), np.where(u < 0.5, -4 * H * u, -4 * H * (1 - u)) / ret)

    def theta(R0, e):
        return np.degrees(np.arctan((v - e) / (np.sqrt(R0 * R0 - e * e) + s)))

    def least(e):
        lo, hi = abs(e) + 1e-6, 300.0
        for _ in range(36):
            mid = (lo + hi) / 2
            th = np.abs(theta(mid, e))
            lo, hi = (lo, mid) if max(th[up].max() / 30.0, th[~up].max() / 35.0) <= 1.0 else (mid, hi)
        return hi
    grid = {round(e, 1): least(e) for e in np.arange(-0.5, 1.51, 0.1)}    # R0(e) has one least
    best = min(grid, key=grid.get)
    assert doc["offset_m"] * 1000 == pytest.approx(best, abs=1e-9) == pytest.approx(0.4)
    assert doc["base_radius_min_m"] * 1000 == pytest.approx(grid[best], abs=2e-3)
    assert doc["base_radius_min_m"] * 1000 == pytest.approx(35.243, abs=2e-3)
    assert doc["base_radius_m"] == pytest.approx(0.036)
    th = theta(36.0, 0.4)
    for name, m in (("rise", up), ("return", ~up)):
        k = int(np.argmax(np.abs(th[m])))
        assert doc["pressure_angle_extreme_deg"][name] == pytest.approx(th[m][k], abs=0.01)
        assert doc["pressure_angle_extreme_phi_deg"][name] == pytest.approx(math.degrees(phi[m][k]), abs=0.05)


@pytest.mark.parametrize("which", ["nodwell", "cam60"])
def test_omegas_arc_stands_inside_the_working_profile(which, request):
    """ω's arrow on the profile: an arc about O at least 5 mm inside the working profile (measured off the
    record: the working profile's nearest point to O, R_0 − r = 21 mm drawn for cg60's cam, its 15-mm roller on
    a 36-mm base circle) — at 0.6 R_0 = 21.6 mm it ran along that profile's line (stop 60); CAM60's (R_0 − r =
    38 mm) stays at 0.6 R_0 = 30 mm."""
    from graphplan.drawing.cam import profile_drawing
    cam, sol, g, doc = request.getfixturevalue(which)
    rec = profile_drawing(sol, g, "uk")
    mu = g.mu_l * 1000
    (work,) = [q for q in rec.items if q.step == "working profile"]
    nearest = min(abs(complex(*z)) for z in work.points)
    R0, r = doc["base_radius_m"] * 1000 / mu, doc["roller_radius_m"] * 1000 / mu
    assert nearest == pytest.approx(R0 - r, abs=0.05)
    arcs = [q for q in rec.items if q.step == "ω" and q.kind == "arc"]
    assert len(arcs) == 1
    assert nearest - arcs[0].radius >= 5.0 - 1e-9
    assert arcs[0].radius == pytest.approx(min(0.6 * R0, R0 - r - 5.0))
