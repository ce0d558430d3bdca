"""Stop 58's cam sheet: the lead's CAM58 (a ROCKING roller follower, the cam counter-clockwise, NO far dwell:
a trapezoidal rise of 150° straight into a cycloidal return of 150°, a near dwell of 60°, ψ_max = 25°,
l = 90 mm, a = 110 mm, r = 10 mm, [ϑ] 40°/45°, 10 divisions) against a brute force written apart from the
code: the laws integrated numerically, the roller centre C on its arc about the pivot A = (a, 0), the
pressure angle the angle between the centre profile's normal (the relative velocity C′ − iC turned by 90°)
and C's velocity (square to the arm), the centre profile turned point by point for its curvature; and the
phase diagram read off its record (the drawn O, the drawn points K and the arms)."""
from __future__ import annotations

import math
import re

import numpy as np
import pytest

from camfixtures import cam_fixture
from review_scenes import CAM58, OWN_CAM58

cam58 = cam_fixture("cam58", CAM58, 10)
own58 = cam_fixture("own58", OWN_CAM58, 8)

A, L, R = 0.11, 0.09, 0.01                  # a, l, r (m)
PSI = math.radians(25.0)
RISE, RET = 150.0, 150.0                     # no far dwell, the near dwell 60°


def _trapezoidal(u):
    """The trapezoidal-acceleration law's s/h on u ∈ [0, 1]: the acceleration's trapezoids (ramps over the
    first and last eighths and the middle quarter) integrated twice numerically, scaled to 1 at u = 1."""
    grid = np.linspace(0.0, 1.0, 100001)
    a = np.interp(grid, [0, 1 / 8, 3 / 8, 5 / 8, 7 / 8, 1], [0, 1, 1, -1, -1, 0])
    v = np.concatenate([[0.0], np.cumsum((a[1:] + a[:-1]) / 2 * np.diff(grid))])
    s = np.concatenate([[0.0], np.cumsum((v[1:] + v[:-1]) / 2 * np.diff(grid))])
    return np.interp(u, grid, s / s[-1])


def _psi(phi):
    """ψ (rad) at the cam's turns ``phi`` (deg): the rise, then at once the return, then the near dwell."""
    phi = np.asarray(phi, float)
    out = np.zeros_like(phi)
    m = phi <= RISE
    out[m] = PSI * _trapezoidal(phi[m] / RISE)
    m = (phi > RISE) & (phi <= RISE + RET)
    u = (phi[m] - RISE) / RET
    out[m] = PSI * (1.0 - (u - np.sin(2 * np.pi * u) / (2 * np.pi)))
    return out


PHI = np.linspace(0.0, 360.0, 36001)
_D = 1e-4
PSI_OF = _psi(PHI)
DPSI = (_psi(PHI + _D) - _psi(PHI - _D)) / math.radians(2 * _D)
ON_RISE, ON_RETURN = PHI <= RISE, (PHI >= RISE) & (PHI <= RISE + RET)


def _theta(R0: float, k=slice(None)):
    """(ϑ in degrees, C) at the base radius R0 for the cam turning counter-clockwise (σ = +1): the arm's
    start angle ψ0 from the triangle O A C0 (|C0| = R0), C = A + l·e^{i(π − ψ0 − ψ)}."""
    psi0 = math.acos((A * A + L * L - R0 * R0) / (2 * A * L))
    turn = np.exp(1j * (math.pi - psi0 - PSI_OF[k]))
    C = A + L * turn
    dC = -1j * L * turn                       # ∂C/∂ψ: square to the arm
    t = dC * DPSI[k] - 1j * C                 # the roller centre's velocity relative to the cam, per ω
    return np.degrees(np.arcsin((np.conj(t) * dC / L).real / np.abs(t))), C


def _worst(R0: float) -> float:
    th, _ = _theta(R0)
    return max(np.max(np.abs(th[ON_RISE])) / 40.0, np.max(np.abs(th[ON_RETURN])) / 45.0)



def _least(worst, top: float) -> float:
    """The least base radius (m) whose worst pressure angle is within its allowed one (``worst`` ≤ 1):
    a 0.5-mm scan from 20.5 mm up to ``top`` (allowed from the first one on, none below), then bisection."""
    scan = np.arange(0.0205, top, 0.0005)
    ok = np.array([worst(r) <= 1.0 for r in scan])
    first = int(np.argmax(ok))
    assert first > 0 and ok[first:].all()
    lo, hi = scan[first - 1], scan[first]
    for _ in range(30):
        mid = (lo + hi) / 2
        lo, hi = (lo, mid) if worst(mid) <= 1.0 else (mid, hi)
    return hi

def test_cam58_base_radius_angles_and_curvature_by_brute_force(cam58):
    """R0 min: the first radius of a 0.5-mm scan of the arm's reach that allows [ϑ], bisected, to 0.01 mm
    (and every scanned radius above it allowed: no band); at R0 = 33 mm ψ0, each division's exact ϑ to
    0.05°, each phase's largest |ϑ| (the rise's at its start, −29.35°, the arm at rest) and its turn;
    the smallest radius of curvature of the convex centre profile — the near dwell's arc, R0 — and no
    concave part tighter than the roller."""
    cam, sol, g, doc = cam58
    assert doc["base_radius_min_m"] == pytest.approx(_least(_worst, 0.08), abs=1e-5)
    assert doc["base_radius_m"] == pytest.approx(0.033) and doc["arm_angle_deg"] == pytest.approx(
        math.degrees(math.acos((A * A + L * L - 0.033 ** 2) / (2 * A * L))), abs=1e-9)
    th, C = _theta(0.033)
    for p in doc["positions"]:
        j = int(round(p["phi_deg"] * 100))
        assert p["exact"]["pressure_angle_deg"] == pytest.approx(th[j], abs=0.05), p["number"]
        assert p["exact"]["radius_m"] == pytest.approx(abs(C[j]), abs=1e-6)
    for name, m in (("rise", ON_RISE), ("return", ON_RETURN)):
        k = int(np.argmax(np.abs(th[m])))
        assert doc["pressure_angle_extreme_deg"][name] == pytest.approx(th[m][k], abs=0.02)
        assert doc["pressure_angle_extreme_phi_deg"][name] == pytest.approx(PHI[m][k], abs=0.1)
    assert doc["pressure_angle_extreme_phi_deg"]["rise"] == pytest.approx(0.0, abs=0.1)
    # the centre profile P = C·e^{−iφ} (the cam counter-clockwise) traversed clockwise: convex where P′ × P″ < 0
    P = C * np.exp(-1j * np.radians(PHI))
    d1 = np.gradient(P, PHI)
    d2 = np.gradient(d1, PHI)
    rho = -np.abs(d1) ** 3 / (np.conj(d1) * d2).imag
    inner = rho[5:-5]
    convex = float(np.min(inner[inner > 0]))
    assert convex == pytest.approx(0.033, abs=2e-5)
    assert doc["curvature_min_m"] == pytest.approx(convex, abs=2e-5) and convex > R
    assert np.all(np.abs(inner[inner < 0]) > R)
    assert doc["shocks"] == [] and doc["profile_corners"] == []


def test_cam58_phase_diagram_draws_the_angles_with_o_on_its_side(cam58):
    """The phase diagram read off its record: at the drawn O the angle between the line to each drawn K
    and the roller's motion there (square to the drawn arm) is the brute force's |ϑ| within 1°, and
    its side of the motion keeps one relation to ϑ's sign at every division (an O mirrored to the
    other side of the arms' lines reads the angles on the wrong hand: issue 32 item 1's sent-back cam);
    O lies on its locus, the arc of radius a about the pivot, at R0 from C0."""
    from graphplan.drawing.cam import phase_diagram
    cam, sol, g, doc = cam58
    rec = phase_diagram(sol, g, "uk")

    def one(step):
        return next(p for p in rec.items if p.step == step)
    O = complex(*one("O").points[0])
    th, _ = _theta(0.033)
    sides = set()
    for k, p in enumerate(doc["positions"]):
        K = complex(*one(f"K {k}").points[0])
        a, b = (complex(*q) for q in one(f"arm {k}").points)
        u = (b - a) * 1j
        line = K - O
        cos = abs((line * u.conjugate()).real) / (abs(line) * abs(u))
        want = th[int(round(p["phi_deg"] * 100))]
        assert math.degrees(math.acos(min(1.0, cos))) == pytest.approx(abs(want), abs=1.0), k
        if abs(want) > 2.0:
            sides.add(np.sign((line * u.conjugate()).real * (line * u.conjugate()).imag) * np.sign(want))
    assert len(sides) == 1
    # the drawn geometry: the arms' lines meet at the pivot O_1, a from O; C_0 (K 0, dψ/dφ = 0) at R0
    # from O, and R0 drawn from O to it; O's locus an arc of radius a about O_1 (the phase diagram's μ)
    mu = rec.scales["mu_phase"]
    (p0, q0), (p1, q1) = ((complex(*q) for q in one(f"arm {k}").points) for k in (0, 5))
    d0, d1 = q0 - p0, q1 - p1
    t = ((p1 - p0).conjugate() * d1).imag / (d0.conjugate() * d1).imag
    pivot = p0 + t * d0
    assert abs(pivot - O) * mu == pytest.approx(A, abs=1e-6)
    C0 = complex(*one("K 0").points[0])
    assert abs(C0 - O) * mu == pytest.approx(0.033, abs=1e-6)
    assert abs(C0 - pivot) * mu == pytest.approx(L, abs=1e-6)
    ends = [complex(*q) for q in one("R0").points]
    assert min(abs(e - O) for e in ends) < 1e-6 and min(abs(e - C0) for e in ends) < 1e-6
    locus = next(p for p in rec.items if p.step == "O locus" and p.kind == "polyline")
    assert all(abs(complex(*q) - pivot) * mu == pytest.approx(A, abs=1e-6) for q in locus.points)


NUMBER = re.compile(r"^\d+(; \d+)*$")


def _numbers(rec) -> list[str]:
    return [q.text for q in rec.items if q.kind == "text" and q.text and NUMBER.match(q.text)]


def test_cam58_no_far_dwell_one_point_one_number(cam58):
    """No far dwell: the rise's end and the return's start are one point, numbered 10 once on the phase
    diagram and the profile, three times under ψ, dψ/dφ and d²ψ/dφ² (never «10; 11»); every number
    0…20 on the φ axes; the profile's phase arcs and the s diagram's phase spans name the rise, the
    return (and the profile the near dwell) — no φ_вв, no «0°»; Table 2 one row a point, 0…20."""
    from graphplan.drawing.cam import diagrams, phase_diagram, profile_drawing
    from graphplan.sheets.cam import positions_table
    cam, sol, g, doc = cam58
    dia, phase, prof = diagrams(sol, g, "uk"), phase_diagram(sol, g, "uk"), profile_drawing(sol, g, "uk")
    for rec in (dia, phase, prof):
        assert not any(t.startswith("10; ") or t.endswith("; 11") for t in _numbers(rec))
    assert {int(x) for t in _numbers(dia) for x in t.split("; ")} == set(range(21))
    assert _numbers(dia).count("10") == 3
    assert _numbers(phase).count("10") == 1 and _numbers(prof).count("10") == 1
    assert "0; 20" in _numbers(phase)              # the near dwell's ends: ψ = 0 and dψ/dφ = 0 at both
    for lang, names in (("uk", ("φ_п", "φ_с", "φ_бв")), ("en", ("φ_{rise}", "φ_{return}", "φ_{near}"))):
        texts = [q.text for rec in (profile_drawing(sol, g, lang), diagrams(sol, g, lang, ("s",)))
                 for q in rec.items if getattr(q, "text", None)]
        assert not any(("φ_вв" if lang == "uk" else "φ_{far}") in t for t in texts)
        assert not any(t.strip().endswith(" 0°") for t in texts)
        assert all(any(t.startswith(n) for t in texts) for n in names)
    table = positions_table(doc, "uk")
    cells = [q for q in table.items if q.kind == "text"]
    first = min(q.points[0][0] for q in cells if q.text == "0")
    rows = [q.text for q in sorted(cells, key=lambda q: -q.points[0][1])
            if abs(q.points[0][0] - first) < 1e-6 and q.text.isdigit()]
    assert rows == [str(k) for k in range(21)]


# -- stop 57's leftover: the A1 sheet's top-left blank (the diagrams centred in their column) ------------------

def test_the_diagrams_stand_at_their_columns_left_and_the_room_under_the_phase_diagram_takes_the_rest(cam58):
    """The A1 columns (sheets.cam.place, hole): the diagrams with the phase diagram beside them at the top
    LEFT of their column — no strip left of the poles (stop 57: CAM57's 49 mm, CAM55's 36) —, the room
    under the phase diagram (the notes and ϑ(φ)) from a GAP right of the diagrams' placed ink to the
    column's right edge, under the phase diagram; apart() puts the phase diagram in the middle of the
    room right of the diagrams (the spare width either side of it, not at the sheet's edge). Where a
    record is not marked flush (the sizing's first trials) the room is the centred record's, as before."""
    from graphplan.drawing.cam import diagrams, phase_diagram
    from graphplan.drawing.layout import GAP, Leaf
    from graphplan.sheets import cam as sc
    from graphplan.sheets.form import form
    cam, sol, g, doc = cam58
    rec = sc.beside(diagrams(sol, g, "uk"), phase_diagram(sol, g, "uk"), sc._captions(g, cam, "uk"), True)
    assert rec.flush
    b = rec.bounds()
    box = (25.0, 10.0, 25.0 + (b[2] - b[0]) + 120.0, 584.0)          # 120 mm to spare across the column
    dia = Leaf("diagrams", record=rec)
    placed = sc.place(form("A1"), dia, box)
    pb = placed.bounds()
    assert pb[0] == pytest.approx(box[0]) and pb[3] == pytest.approx(box[3])
    room = sc.hole(dia, box)
    left = _bounds_of(placed, rec.parts)
    assert room[0] == pytest.approx(left[2] + 2 * GAP) and room[2] == box[2]
    notes = (room[0], room[1], room[2], room[1] + 50.0)                # a leaf in the room (the notes)
    parts = {p.name: p for p in sc.apart("diagrams", placed, box, [(dia, box), (Leaf("notes", 1.0, 1.0), notes)],
                                         rec.parts)}
    ph = parts["phase"].record.bounds()
    assert ph[0] - (left[2] + 2 * GAP) == pytest.approx(box[2] - ph[2], abs=1e-6)    # in the middle of its room
    assert ph[0] >= left[2] + 2 * GAP - 1e-9
    rec.flush = False
    try:
        was = sc.hole(dia, box)
        assert was[0] == pytest.approx(room[0] + 60.0)                 # half the spare: the centred record's
    finally:
        rec.flush = True


def _bounds_of(rec, n):
    """The bounds of a record's first ``n`` items (the s, ds/dφ, d²s/dφ² diagrams of beside's record)."""
    from graphplan.graphic.record import Record
    return Record(rec.title, rec.items[:n], {}).bounds()


@pytest.mark.slow
@pytest.mark.parametrize("name", ["CAM57", "CAM55"])
def test_stop_57s_a1_sheets_lose_their_top_left_strip(name):
    """CAM57 and CAM55 on A1 (uk): the s–ds/dφ–d²s/dφ² diagrams' ink from the field's left edge (they stood
    49 and 36 mm off it); the phase diagram in the middle of the room between them and the profile's
    column; the sheet's composition sound (no two boxes meet, nothing overprinted)."""
    import tomllib

    import review_scenes
    from graphplan.drawing.layout import boxes_apart
    from graphplan.model.cam import build
    from graphplan.sheets import cam as sc
    from graphplan.sheets.compose import SheetOptions, field_of
    from graphplan.sheets.form import form
    seen = {}
    real = sc.compose

    def grab(f, pages, *a, **k):
        seen["pages"] = pages
        return real(f, pages, *a, **k)
    cam = build(tomllib.loads(getattr(review_scenes, name)), f"<{name}>")
    try:
        sc.compose = grab
        sc.build_cam_sheet(cam, form("A1"), SheetOptions(lang="uk", sheet="cam"))
    finally:
        sc.compose = real
    (page,) = seen["pages"]
    got = {p.name: p for p in page}
    x0 = field_of(form("A1"))[0]
    dia, phase = got["diagrams"], got["phase"]
    assert dia.record.bounds()[0] == pytest.approx(x0, abs=1.0)
    ph = phase.record.bounds()
    room = (dia.box[2], got["profile"].box[0])
    assert (ph[0] - room[0]) == pytest.approx(room[1] - ph[2], abs=8.0)   # the GAPs either side within 8 mm
    assert not boxes_apart(page)


# -- cam58's own look: OWN_CAM58, a rocking roller follower, the cam CLOCKWISE, parabolic rise, LINEAR return ------

def test_own58_clockwise_rocking_cam_by_brute_force(own58):
    """OWN_CAM58 (ψ_max = 20°, l = 100 mm, a = 120 mm; a parabolic rise of 120°, a far dwell of 40°, a linear
    return of 100°; [ϑ] 40°/45°; the cam clockwise, σ = −1) by the brute force above with the clockwise
    relative velocity C′ + iC and the arm on the side of O–O1 a clockwise cam lays it (stop 60: the
    counter-clockwise layout mirrored about O–O1): R0 min to 0.01 mm, 37.86 mm as the counter-clockwise cam's
    with its own arm (the mirror), and not the 36.15 mm of the arm on the other side, each phase's largest ϑ at the R0 taken and its turn (the return's at its start, one-sided
    after the jump of dψ/dφ), the two corners at the return's ends (convex at 160°, concave at 260°) and the
    shocks: rigid there, soft at the parabolic rise's start, middle and end."""
    cam, sol, g, doc = own58
    a, l, psi_max = 0.12, 0.10, math.radians(20.0)
    phi = np.linspace(0.0, 360.0, 36001)

    def psi_of(p):
        p = np.asarray(p, float)
        out = np.zeros_like(p)
        m = p <= 120.0
        u = p[m] / 120.0
        out[m] = psi_max * np.where(u <= 0.5, 2 * u * u, 1 - 2 * (1 - u) ** 2)
        out[(p > 120.0) & (p <= 160.0)] = psi_max
        m = (p > 160.0) & (p <= 260.0)
        out[m] = psi_max * (1 - (p[m] - 160.0) / 100.0)
        return out
    psi = psi_of(phi)
    dpsi = (psi_of(phi + 1e-4) - psi_of(phi - 1e-4)) / math.radians(2e-4)
    rise, ret = phi <= 120.0, (phi > 160.0 + 1e-3) & (phi < 260.0 - 1e-3)

    def theta(R0, sigma, side=None):
        # side: +1 the arm over O–O1 (the counter-clockwise layout), −1 under it (the clockwise one's mirror)
        psi0 = math.acos((a * a + l * l - R0 * R0) / (2 * a * l))
        turn = np.exp(1j * (math.pi - psi0 - psi))
        C, dC = a + l * turn, -1j * l * turn
        if (sigma if side is None else side) < 0:
            C, dC = C.conjugate(), dC.conjugate()
        t = dC * dpsi - 1j * sigma * C
        return np.degrees(np.arcsin((np.conj(t) * dC / l).real / np.abs(t)))

    def r0_min(sigma, side=None):
        def worst(R):
            th = theta(R, sigma, side)
            return max(np.max(np.abs(th[rise])) / 40.0, np.max(np.abs(th[ret])) / 45.0)
        return _least(worst, 0.09)
    assert doc["sense"] == "cw"
    assert doc["base_radius_min_m"] == pytest.approx(r0_min(-1), abs=1e-5)
    assert doc["base_radius_min_m"] == pytest.approx(r0_min(+1), abs=1e-5)
    assert doc["base_radius_min_m"] == pytest.approx(0.03786, abs=1e-5)
    assert abs(doc["base_radius_min_m"] - r0_min(-1, side=+1)) > 1e-3
    R0 = doc["base_radius_m"]
    th = theta(R0, -1)
    for name, m in (("rise", rise), ("return", ret)):
        k = int(np.argmax(np.abs(th[m])))
        assert doc["pressure_angle_extreme_deg"][name] == pytest.approx(th[m][k], abs=0.05)
        assert doc["pressure_angle_extreme_phi_deg"][name] == pytest.approx(phi[m][k], abs=0.2)
    # the corners: the centre profile P = C·e^{iφ} (σ = −1) turns there by the angle between its tangents just
    # before and just after; convex where that turn has the sense the whole profile winds in
    psi0 = math.acos((a * a + l * l - R0 ** 2) / (2 * a * l))
    P = (a + l * np.exp(1j * (math.pi - psi0 - psi))).conjugate() * np.exp(1j * np.radians(phi))
    winding = np.sign(np.sum((np.conj(P) * np.roll(P, -1)).imag))
    want = []
    for at in (160.0, 260.0):
        j = int(round(at * 100))
        before, after = P[j] - P[j - 5], P[j + 5] - P[j]
        want.append((at, bool(np.sign((np.conj(before) * after).imag) == winding)))
    corners = [(c["phi_deg"], c["convex"]) for c in doc["profile_corners"]]
    assert corners == [(pytest.approx(w[0]), w[1]) for w in want]
    assert [w[1] for w in want] == [True, False]
    shocks = {(round(x["phi_deg"], 6), x["kind"]) for x in doc["shocks"]}
    assert shocks == {(160.0, "rigid"), (260.0, "rigid"), (0.0, "soft"), (60.0, "soft"), (120.0, "soft")}
