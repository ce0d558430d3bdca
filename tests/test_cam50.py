"""Stop 50's look at the cam sheet (the lead's CAM50: a translating roller follower with a given offset
e = 8 mm, the cam counter-clockwise, a linear rise of 90° — rigid shocks at its ends —, a far dwell of
30°, a cycloidal return of 110°). Each checked against what the test works out itself — the laws'
closed forms and the cam turned about O by brute force — or read off the drawn primitives:

- the phase diagram's [ϑ] lines touch the curve (REFERENCE §11: "lines at the allowed pressure angle
  tangent to its branches"), never cut it between two divisions (the return's line through point 14
  cut it between 13 and 14: R0 read 35.8 mm of the brute force's 36.70, a cam past [ϑ] = 40°);
- the offset's printed side (right of O) is the one that lowers the rise's pressure angle of a ccw cam;
- the working profile is the roller's inner envelope: every drawn point r from the centre profile, an
  arc of radius r about the concave corner at the rise's start, a sharp edge at the convex one at its
  end — as the notes say;
- the rigid shocks: d²s/dφ² drawn to +∞ at the rise's start and to −∞ at its end, lettered ∞."""
from __future__ import annotations

import math

import numpy as np
import pytest

from graphplan.drawing.cam import diagrams, phase_diagram, profile_drawing
from graphplan.exact.cam import solve
from graphplan.graphic.cam import construct
from graphplan.model.cam import load
from graphplan.report.cam import WORDS, offset_line
from review_scenes import CAM50

H, E, R = 0.032, 0.008, 0.010
RISE, FAR, RET = (math.radians(d) for d in (90.0, 30.0, 110.0))


def _constructed(tmp_path_factory, name: str, text: str):
    """The scene's cam solved and constructed (the sheet's own series, in rad)."""
    path = tmp_path_factory.mktemp(name) / f"{name}.toml"
    path.write_text(text, encoding="utf-8")
    sol = solve(load(path))
    return sol, construct(sol, series="rad")


@pytest.fixture(scope="module")
def cam50(tmp_path_factory):
    return _constructed(tmp_path_factory, "cam50", CAM50)


def _law(phi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """s and ds/dφ of CAM50 at the turns φ (rad, taken mod 2π): the rise h·φ/Φ, the far dwell, the
    cycloidal return mirrored, the near dwell."""
    phi = np.mod(np.asarray(phi, dtype=float), 2 * math.pi)
    w = np.clip((phi - RISE - FAR) / RET, 0.0, 1.0)
    back = phi >= RISE + FAR
    s = np.where(phi <= RISE, H * phi / RISE,
                 np.where(~back, H, H * (1 - (w - np.sin(2 * np.pi * w) / (2 * np.pi)))))
    v = np.where(phi <= RISE, H / RISE, np.where(~back, 0.0, -H / RET * (1 - np.cos(2 * np.pi * w))))
    far = phi > RISE + FAR + RET
    return np.where(far, 0.0, s), np.where(far, 0.0, v)


def _inverted(R0: float, x: float, phi: np.ndarray) -> np.ndarray:
    """The roller centre in the cam's frame (complex): the follower's axis the vertical x, the cam turned
    counter-clockwise by φ about O (its frame: the fixed one turned back by φ)."""
    s, _ = _law(phi)
    s0 = math.sqrt(R0 ** 2 - E ** 2)
    return (x + 1j * (s0 + s)) * np.exp(-1j * phi)


def _largest(R0: float, x: float) -> tuple[float, float]:
    """Each phase's largest |ϑ| (deg): the angle between the centre profile's normal and the axis."""
    phi = np.linspace(0.0, RISE + FAR + RET, 23001)
    P = _inverted(R0, x, phi)
    t = np.gradient(P, phi)
    axis = 1j * np.exp(-1j * phi)
    th = np.degrees(np.arcsin(np.clip(np.abs((t * axis.conjugate()).real) / np.abs(t), 0.0, 1.0)))
    return float(th[phi < RISE - 1e-6].max()), float(th[phi > RISE + FAR + 1e-6].max())


def test_the_offset_right_of_O_lowers_the_rise_and_R0_is_the_brute_force_smallest(cam50):
    """The notes put the axis right of O («праворуч»); turned ccw by brute force, the rise's largest
    |ϑ| there is the printed one and under the other side's (38.1° > [ϑ] = 30°); the smallest R0 with
    both phases within [ϑ] (30°, 40°) found by bisection is the printed exact one, and the phase
    diagram's reading within the ruler's quarter millimetre at μ_s of it."""
    from scipy.optimize import brentq
    sol, g = cam50
    line = offset_line(WORDS["uk"], {"offset_m": sol.geometry.e, "sense": "ccw"}, lambda v: f"{v:g}")
    assert "праворуч" in line
    rise, ret = _largest(sol.geometry.R0, E)
    assert (rise, ret) == pytest.approx(tuple(abs(x) for x in sol.pressure_maxima()), abs=0.05)
    assert _largest(sol.geometry.R0, -E)[0] > 30.0 > rise
    worst = lambda R0: max(_largest(R0, E)[0] / 30.0, _largest(R0, E)[1] / 40.0) - 1.0
    R0_min = brentq(worst, 0.02, 0.08, xtol=1e-7)
    assert sol.R0_min == pytest.approx(R0_min, abs=2e-5)
    assert abs(g.R0_min - R0_min) <= 0.25 * g.mu_s + 2e-5


def test_the_allowed_lines_touch_the_phase_curve_and_never_cut_it(cam50):
    """The phase curve worked out here — ds/dφ laid off from the roller's centre (σe, s0 + s) square to
    the axis, turned 90° with ω (ccw: to −x): K = (e − ds/dφ, s0 + s)/μ_s — lies wholly on the far side
    of each drawn [ϑ] line from O (not a point past it by more than 0.05 mm) and touches it (within
    0.1 mm)."""
    sol, g = cam50
    rec = phase_diagram(sol, g, "uk")
    mu = rec.scales["mu_phase"]
    s0 = math.sqrt(sol.geometry.R0 ** 2 - E ** 2)
    for ph, (a, b) in enumerate(((0.0, RISE), (RISE + FAR, RISE + FAR + RET))):
        phi = np.linspace(a, b, 4001)
        s, v = _law(phi)
        K = ((E - v) + 1j * (s0 + s)) / mu
        (x0, y0), (x1, y1) = next(q for q in rec.items if q.step == f"[ϑ] line {ph}").points
        p, d = complex(x0, y0), complex(x1 - x0, y1 - y0) / abs(complex(x1 - x0, y1 - y0))
        side = ((0j - p) * d.conjugate()).imag             # O's side of the line
        dist = ((K - p) * d.conjugate()).imag * -np.sign(side)  # + on the far side
        assert dist.min() >= -0.05, (ph, dist.min())
        assert dist.min() <= 0.1


def test_the_working_profile_is_the_rollers_envelope_with_its_arc_and_its_edge(cam50):
    """Every point of the drawn working profile lies r from the brute-force centre profile (the nearest
    of 36 000 inverted roller centres) and inside it; at the rise's start (a concave corner: the tangent
    turns outward by the angle κ0 between the dwell's and the rise's directions) the drawn points on
    the circle of radius r about the corner span κ0 about it; at the rise's end (convex) the drawn profile
    has a vertex where the rise's inner offset meets the far dwell's and turns there by the angle
    between their tangents — the sharp edge."""
    sol, g = cam50
    rec = profile_drawing(sol, g, "uk")
    mu = g.mu_l
    W = np.array([complex(*p) for p in next(q for q in rec.items if q.step == "working profile").points]) * mu
    R0 = sol.geometry.R0
    P = _inverted(R0, E, np.linspace(0.0, 2 * math.pi, 36001))
    near = np.array([np.min(np.abs(P - w)) for w in W])
    assert np.allclose(near, R, atol=0.05e-3)
    order = np.argsort(np.angle(P))
    assert np.all(np.abs(W) < np.interp(np.angle(W), np.angle(P)[order], np.abs(P)[order]))

    def kink(at: float) -> tuple[complex, float]:
        """The corner of the centre profile at the turn ``at`` and its tangent's turn there (rad)."""
        a, C, b = _inverted(R0, E, np.array([at - 1e-7, at, at + 1e-7]))
        return C, abs(np.angle((b - C) / (C - a)))
    C0, k0 = kink(0.0)
    on = W[np.abs(np.abs(W - C0) - R) < 1e-7]            # on the circle (its polygon's vertices)
    span = np.ptp(np.unwrap(np.angle(on - C0)))
    assert span == pytest.approx(k0, abs=math.radians(1.5))
    # the edge: where the rise's inner offset (P − r·n, the centre profile run clockwise, the cam on its
    # right) meets the far dwell's (a circle of radius |C8| − r about O), turning from the one's
    # tangent to the other's
    C8, _ = kink(RISE)
    phi = np.linspace(RISE - 0.4, RISE, 40001)
    Q = _inverted(R0, E, phi)
    tq = np.gradient(Q, phi)
    off = Q - 1j * R * tq / np.abs(tq)
    k = int(np.argmin(np.abs(np.abs(off) - (abs(C8) - R))))
    edge = off[k]
    want = abs(np.angle((-1j * edge / abs(edge)) / tq[k]))
    seg = np.diff(W)
    turn = np.abs(np.angle(seg[1:] / seg[:-1]))
    j = int(np.argmin(np.abs(W[1:-1] - edge)))
    assert abs(W[j + 1] - edge) < 0.05e-3
    assert abs(edge - C8) > R          # the centre's arc r about the edge cuts the corner off (the notes)
    assert turn[j] == pytest.approx(want, abs=math.radians(1.0)) and turn[j] > math.radians(10.0)


def test_the_linear_rise_draws_its_rigid_shocks_up_at_the_start_and_down_at_the_end(cam50):
    """ds/dφ jumps 0 → h/Φ at φ = 0 and h/Φ → 0 at φ = Φ: d²s/dφ² an impulse up at the first, down at the
    second, each an arrow off the axis at its abscissa Φ/μ_φ, lettered ∞ at its tip."""
    sol, g = cam50
    rec = diagrams(sol, g, "uk", ("a",))
    y0 = next(q for q in rec.items if q.step == "axis a").points[0][1]
    shocks = sorted((q.points for q in rec.items if q.kind == "vector" and q.step.startswith("shock")),
                    key=lambda p: p[0][0])
    assert len(shocks) == 2
    (a0, a1), (b0, b1) = shocks
    assert a0 == pytest.approx((0.0, y0)) and a1[0] == pytest.approx(0.0) and a1[1] > y0
    assert b0 == pytest.approx((RISE / g.mu_phi, y0)) and b1[0] == pytest.approx(RISE / g.mu_phi) and b1[1] < y0
    assert sum(1 for q in rec.items if q.kind == "text" and q.text == "∞") == 2


@pytest.fixture(scope="module")
def own50(tmp_path_factory):
    from review_scenes import OWN_CAM50
    return _constructed(tmp_path_factory, "own50", OWN_CAM50)


def test_a_given_base_radius_is_printed_given_and_the_smallest_is_marked_O_min(own50):
    """OWN_CAM50 gives R0 = 60 mm over a central follower, the cam clockwise. The notes print it as given
    («задано», "given"), not taken, and e = 0 as the central follower; the phase diagram marks O_min on O's line (the s axis, e = 0) where
    the region of the cam's centre begins: on one drawn [ϑ] line, on O's side of the other, and
    |O_min C₀| the smallest R0 the brute force gives — the cam turned clockwise about O (its frame the
    fixed one turned on by φ), the roller's centre at s0 + s(φ) on the axis (s, ds/dφ of the program's
    laws), ϑ the angle between the centre profile's normal and the axis, R0 bisected until both
    phases' largest |ϑ| reach [ϑ] (30°, 35°)."""
    from scipy.optimize import brentq
    from graphplan.exact.cam import motion
    from graphplan.report.cam import cam_json, cam_lines
    sol, g = own50
    doc = cam_json(sol, g, "")
    assert doc["base_radius_m"] == pytest.approx(0.060)
    uk, en = "\n".join(cam_lines(doc, "uk")), "\n".join(cam_lines(doc, "en"))
    assert "задано R_0 = 60 мм" in uk and "прийнято" not in uk and "R_0 given = 60 mm" in en
    assert sol.geometry.e == 0.0 and "центральний штовхач" in uk and "a central follower" in en
    rise, far, ret, _ = sol.cam.phases
    turns = np.concatenate([np.linspace(0.0, rise, 6001), rise + far + np.linspace(0.0, ret, 6001)])
    phase = np.repeat([0, 1], 6001)
    s, _, _ = motion(sol.cam, turns, phase)
    phi = np.radians(turns)

    def worst(R0: float) -> float:
        P = 1j * (R0 + s) * np.exp(1j * phi)
        t = np.stack([np.gradient(P[phase == k], phi[phase == k]) for k in (0, 1)]).ravel()
        axis = 1j * np.exp(1j * phi)
        th = np.degrees(np.arcsin(np.clip(np.abs((t * axis.conjugate()).real) / np.abs(t), 0.0, 1.0)))
        return max(th[phase == 0].max() / 30.0, th[phase == 1].max() / 35.0) - 1.0
    R0_min = brentq(worst, 0.02, 0.06, xtol=1e-7)
    rec = phase_diagram(sol, g, "uk")
    mu = rec.scales["mu_phase"]
    (om,) = [complex(*q.points[0]) for q in rec.items if q.step == "O min" and q.kind == "point"]
    C0 = 1j * 0.060 / mu
    assert abs(om.real) < 1e-9
    assert abs(C0 - om) * mu == pytest.approx(R0_min, abs=0.25 * mu + 2e-5)
    gaps = []
    for ph in (0, 1):
        (x0, y0), (x1, y1) = next(q for q in rec.items if q.step == f"[ϑ] line {ph}").points
        p, d = complex(x0, y0), complex(x1 - x0, y1 - y0) / abs(complex(x1 - x0, y1 - y0))
        o_side = np.sign(((0j - p) * d.conjugate()).imag)
        gaps.append(((om - p) * d.conjugate()).imag * o_side)      # + on O's side
    assert min(gaps) == pytest.approx(0.0, abs=0.3) and max(gaps) > -0.3
    assert sum(1 for q in rec.items if q.kind == "text" and q.text == "O_{min}") == 1


def test_the_pressure_angle_curve_is_the_brute_force_one(cam50):
    """ϑ(φ) as drawn (its curve's ordinates times μ_ϑ, at its abscissae over μ_φ) against the cam turned
    counter-clockwise by brute force — the angle between the centre profile's normal and the axis —
    to 0.05° away from the jumps of ds/dφ (0°, 90°): positive over the rise (the axis' offset keeps it
    under [ϑ] = 30°), negative over the return down to the printed −39.82°."""
    from graphplan.drawing.cam import pressure_diagram
    sol, g = cam50
    mu_phi, mu_theta = g.mu_phi, 0.5
    rec = pressure_diagram(sol, g, "uk", mu_phi, mu_theta)
    xy = np.array(next(q for q in rec.items if q.step == "ϑ(φ) exact").points)
    phi, drawn = xy[:, 0] * mu_phi, xy[:, 1] * mu_theta
    keep = (np.abs(phi - RISE) > math.radians(0.5)) & (phi > math.radians(0.5))
    phi, drawn = phi[keep], drawn[keep]
    dP = (_inverted(sol.geometry.R0, E, phi + 1e-7) - _inverted(sol.geometry.R0, E, phi - 1e-7)) / 2e-7
    axis = 1j * np.exp(-1j * phi)
    brute = np.degrees(np.arcsin(np.clip(np.abs((dP * axis.conjugate()).real) / np.abs(dP), 0.0, 1.0)))
    assert np.allclose(np.abs(drawn), brute, atol=0.05)
    assert np.all(drawn[phi < RISE] > 0) and np.all(drawn[(phi > RISE + FAR + 0.05) & (phi < RISE + FAR + RET - 0.05)] < 0)
    assert float(drawn.min()) == pytest.approx(-39.82, abs=0.05) and float(drawn[phi < RISE].max()) < 30.0


@pytest.mark.slow
def test_the_a1_table_takes_rows_of_10_mm_where_its_column_has_room(tmp_path):
    """CAM50's A1: Table 1 stands under the profile, in its column (the 3.5-mm letters make it wider
    than the column); in rows of 8 mm it left 120 mm of the column blank over it — now its rows, the
    rule lines measured on the sheet, 10 mm apart, its foot still over the title block, and the column
    between the profile's ink and the table's under 90 mm."""
    from graphplan.sheets.cam import build_cam_sheet
    from graphplan.sheets.compose import SheetOptions, defects, keep_out
    from graphplan.sheets.form import form
    path = tmp_path / "cam50.toml"
    path.write_text(CAM50, encoding="utf-8")
    f = form("A1")
    sheet = build_cam_sheet(load(path), f, SheetOptions(lang="uk", sheet="cam"))
    assert not defects(sheet)
    placed = {p.name: p.record for p in sheet.placed}
    box = {k: r.bounds() for k, r in placed.items()}
    rules = sorted({round(q.points[0][1], 3) for q in placed["table"].items
                    if q.kind == "segment" and abs(q.points[0][1] - q.points[1][1]) < 1e-9})
    steps = np.diff(rules)
    # stop 54: the given data (camgiven) stand over it in the room the 10-mm rows left, both tables in
    # rows alike (7 … 10 mm), the column between the profile's ink and the given data's under a GAP and a half
    assert 7.0 - 0.05 <= np.median(steps) <= 10.0 + 0.05
    assert box["table"][1] >= keep_out(f)[3] - 1e-6
    assert box["given"][1] > box["table"][3] and box["profile"][1] - box["given"][3] < 20.0


@pytest.mark.parametrize("lang", ["uk", "en"])
def test_table_1_gives_both_sides_of_the_jumps_of_ds_dphi(cam50, lang):
    """At the linear rise's ends ds/dφ jumps 0 → h/Φ (φ = 0) and h/Φ → 0 (φ = Φ): Table 1's rows there
    give both sides in the exact, ruler-ordinate and graphical columns, as the notes write a jump
    («0 → 20,37»), right-aligned as the column's numbers; the rows between give h/Φ alone."""
    from graphplan.report.cam import cam_json
    from graphplan.sheets.cam import positions_table
    from graphplan.util.markup import plain
    sol, g = cam50
    doc = cam_json(sol, g, "cam50")
    comma = (lambda t: t.replace(".", ",")) if lang == "uk" else (lambda t: t)      # noqa: E731
    v = H / RISE * 1000                                     # 20.372 mm/rad, the law's closed form
    y = round(v / 1000 / g.mu_v / 0.5) * 0.5                # the ruler's ordinate, to its 0.5 mm
    exact, ruler, graphical = (comma(f"{x:.{d}f}") for x, d in ((v, 2), (y, 1), (y * g.mu_v * 1000, 2)))
    rec = positions_table(doc, lang)
    rows: dict[float, list] = {}
    for it in rec.items:
        if it.kind == "text" and it.size < 3.0:
            rows.setdefault(round(it.points[0][1], 1), []).append(it)
    body = [sorted(r, key=lambda i: i.points[0][0]) for _, r in sorted(rows.items(), reverse=True)][1:]
    by_number = {plain(r[0].text): r for r in body}
    # a zero side the bare 0 in every column, the ruler's too (stop 55: «0,0 → 26,5» beside the column's «0»)
    for number, want in (("0", (f"0 → {exact}", f"0 → {ruler}", f"0 → {graphical}")),
                         ("8", (f"{exact} → 0", f"{ruler} → 0", f"{graphical} → 0")),
                         ("4", (exact, ruler, graphical))):
        cells = by_number[number]
        assert tuple(plain(c.text) for c in cells[6:9]) == want
        assert all(c.anchor == "end" for c in cells[6:9])
