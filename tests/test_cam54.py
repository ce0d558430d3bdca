"""Stop 54 (cam54): the lead's CAM54 (a translating roller follower, the cam clockwise, the offset
negative — the follower's axis 8 mm to the right of O, which raises the rise's pressure angle —, a
trapezoidal rise of 100°, a cycloidal return of 140°, 10 divisions) checked against a brute force of its
own: the laws integrated numerically from their acceleration, the centre profile by the inversion
turned point by point, the pressure angle from that profile's finite-difference normal, R0 by
bisection. And the sheet's given-data table («Вихідні дані») in the room under a 1:1 profile."""
from __future__ import annotations

import math
import tomllib

import numpy as np
import pytest

from camfixtures import cam_fixture
from graphplan.model.cam import build
from review_scenes import CAM52, CAM54

H, PHASES, AXIS_X = 0.032, (100.0, 20.0, 140.0, 100.0), 0.008     # the axis 8 mm right of O (cw, e = −8 mm)


def _trapezoid(u):
    """The trapezoidal acceleration (ramps over the eighths, flats between) integrated twice by the
    trapezoid rule on a fine grid, scaled so that f(1) = 1."""
    U = np.linspace(0.0, 1.0, 40001)
    A = np.interp(U, [0, 1 / 8, 3 / 8, 5 / 8, 7 / 8, 1], [0, 1, 1, -1, -1, 0])
    V = np.concatenate([[0.0], np.cumsum((A[1:] + A[:-1]) / 2 * np.diff(U))])
    S = np.concatenate([[0.0], np.cumsum((V[1:] + V[:-1]) / 2 * np.diff(U))])
    return np.interp(u, U, S / S[-1])


def _s(phi):
    rise, far, ret, _ = PHASES
    phi = np.asarray(phi, float)
    u = np.clip((phi - rise - far) / ret, 0, 1)
    return np.where(phi <= rise, H * _trapezoid(np.clip(phi / rise, 0, 1)),
                    np.where(phi < rise + far, H, H * (1 - (u - np.sin(2 * np.pi * u) / (2 * np.pi)))))


def _pitch(phi, R0):
    """The roller centre in the cam's frame: the fixed-frame point (x, s0 + s) turned by +φ (the cam
    turns clockwise, the follower is carried round it counter-clockwise)."""
    s0 = math.sqrt(R0 * R0 - AXIS_X ** 2)
    t = np.radians(phi)
    x, y = AXIS_X, s0 + _s(phi)
    return x * np.cos(t) - y * np.sin(t), x * np.sin(t) + y * np.cos(t)


def _theta(phi, R0, d=1e-3):
    """The angle (deg, signed + against the rise) between the profile's normal and the follower's
    axis: the tangent by central differences, turned back to the fixed frame."""
    (xa, ya), (xb, yb) = _pitch(phi - d, R0), _pitch(phi + d, R0)
    t = -np.radians(phi)
    tx, ty = (xb - xa) * np.cos(t) - (yb - ya) * np.sin(t), (xb - xa) * np.sin(t) + (yb - ya) * np.cos(t)
    return np.degrees(np.arctan(-ty / tx))


RISE = np.linspace(0.01, 99.99, 4001)
RETURN = np.linspace(120.01, 259.99, 4001)


def _brute_R0() -> float:
    lo, hi = AXIS_X * 1.001, 0.2
    for _ in range(45):
        mid = (lo + hi) / 2
        ok = np.abs(_theta(RISE, mid)).max() <= 28.0 and np.abs(_theta(RETURN, mid)).max() <= 35.0
        lo, hi = (lo, mid) if ok else (mid, hi)
    return hi


cam54 = cam_fixture("cam54", CAM54, 10)


def test_cam54_base_radius_phase_maxima_and_curvature_by_brute_force(cam54):
    """R0 (69.844 mm), each phase's largest pressure angle at the R0 taken (70 mm: +27.96° on the rise,
    −12.12° on the return) and ρ_min of the centre profile (61.83 mm) as the brute force finds them;
    the axis on O's right for the clockwise cam with e < 0 (the rise's angle raised)."""
    cam, sol, g, doc = cam54
    assert doc["base_radius_min_m"] * 1000 == pytest.approx(_brute_R0() * 1000, abs=0.02)
    R0 = doc["base_radius_m"]
    assert R0 == pytest.approx(0.070)
    fine = np.linspace(0.01, 99.99, 40001), np.linspace(120.01, 259.99, 40001)
    rise, ret = (_theta(p, R0) for p in fine)
    signed = doc.get("pressure_angle_extreme_deg") or {}
    for k, th in (("rise", rise), ("return", ret)):
        assert doc["pressure_angle_max_deg"][k] == pytest.approx(np.abs(th).max(), abs=0.01)
        if k in signed:
            assert signed[k] == pytest.approx(th[np.argmax(np.abs(th))], abs=0.01)
    phi = np.linspace(0.0, 360.0, 72001)[:-1]
    x, y = _pitch(phi, R0)
    dp = math.radians(phi[1] - phi[0])
    x1, y1 = np.gradient(x, dp), np.gradient(y, dp)
    x2, y2 = np.gradient(x1, dp), np.gradient(y1, dp)
    rho = (x1 * x1 + y1 * y1) ** 1.5 / (x1 * y2 - y1 * x2)
    assert (rho > 0).all()                                # convex all round (counter-clockwise: +)
    assert doc["curvature_min_m"] * 1000 == pytest.approx(rho.min() * 1000, abs=0.05)


def test_cam54_phase_diagram_draws_the_printed_angles(cam54):
    """The angles at the drawn O (left of the s axis: the axis right of O) between its lines to the
    drawn points and the follower's axis are Table 2's graphical ϑ within 1°."""
    from graphplan.drawing.cam import phase_diagram
    from test_cam_robust import drawn_angles
    cam, sol, g, doc = cam54
    rec = phase_diagram(sol, g, "uk")
    angles = drawn_angles(rec, False)
    assert len(angles) == len(doc["positions"])
    for k, p in enumerate(doc["positions"]):
        assert abs(angles[k] - abs(p["graphical"]["pressure_angle_deg"])) < 1.0, (k, angles[k])
    O = next(p for p in rec.items if p.step == "O").points[0]
    axis = next(p for p in rec.items if p.step == "follower axis").points[0]
    assert O[0] < axis[0]


@pytest.mark.parametrize("lang", ["uk", "en"])
def test_given_rows_say_the_scene(lang):
    """The given data's rows carry the scene's numbers: h, e, r, the four phase angles, the allowed
    angles, the speed; the offset "auto" as the rule that chooses it (CAM52)."""
    from graphplan.sheets.camgiven import given_rows
    for scene, e in ((CAM54, "−8"), (CAM52, None)):
        cam = build(tomllib.loads(scene), "<scene>")
        rows = given_rows(cam, {"sense": "cw"}, lang)
        cell = {r[1].split(",")[0]: r[2] for r in rows[1:]}
        assert cell["h"] == "32"
        assert cell["e"] == (e if e else ("для найменшого R_0" if lang == "uk" else "for the smallest R_0"))
        assert cell["r"] == ("8" if scene is CAM54 else "9")
        phases = next(r[2] for r in rows if r[1].startswith("φ"))
        assert [float(x) for x in phases.split("; ")] == list(build(tomllib.loads(scene)).phases)
        assert cell["n"] == ("120" if scene is CAM54 else "200")


def test_the_given_table_takes_the_room_under_the_profile():
    """with_given on a page whose profile stands 120 mm over Table 1: the given data between them, a GAP
    clear of both, as wide as Table 1 (renumbered 2) under it, the profile's box narrowed to its ink; with no room
    (the profile down to the table) the page as it was."""
    from graphplan.drawing.layout import GAP, Placed
    from graphplan.graphic.record import Record
    from graphplan.sheets.camgiven import with_given
    cam = build(tomllib.loads(CAM54), "<cam54>")
    doc = {"sense": "cw"}
    prof = Record("profile")
    prof.segment((560.0, 300.0), (800.0, 560.0))
    tab = Record("table", [], {})
    tab.label((560.0, 200.0), "Таблиця 1. Переміщення", size=3.5, layer="tables")
    tab.segment((560.0, 60.0), (800.0, 196.0), layer="tables")
    page = [Placed("profile", prof, (555.0, 206.0, 836.0, 589.0)), Placed("table", tab, (560.0, 60.0, 800.0, 205.0))]
    out = with_given(page, cam, doc, "uk", None)
    names = {p.name: p for p in out}
    assert set(names) == {"profile", "table", "given"}
    gb, tb, pb = (names[k].record.bounds() for k in ("given", "table", "profile"))
    assert gb[1] >= tb[3] + GAP - 1e-6 and gb[3] <= pb[1] - GAP + 1e-6
    assert names["profile"].box[1] >= names["given"].box[3] - 1e-9
    # as wide as Table 2 under it (stop 57: 162 mm over 248 left a blank over the title block)
    assert gb[2] - gb[0] == pytest.approx(tb[2] - tb[0], abs=0.5) and gb[0] == pytest.approx(tb[0], abs=0.5)
    texts = [p.text for p in names["table"].record.items if p.kind == "text"]
    assert texts[0].startswith("Таблиця 2.")
    assert any(p.text == "Таблиця 1. Вихідні дані" for p in names["given"].record.items if p.kind == "text")
    low = [Placed("profile", prof, (555.0, 206.0, 836.0, 589.0)),
           Placed("table", tab.moved(0.0, 90.0), (560.0, 150.0, 800.0, 295.0))]
    assert with_given(low, cam, doc, "uk", None) is low


@pytest.mark.parametrize("lang", ["uk", "en"])
def test_the_notes_legend_follows_the_table_of_the_divisions_renumbered(lang):
    """Stop 62 (CAM62): the given data, read first, take Table 1 and the table of the divisions becomes
    Table 2 — the notes' legend of «*» (an error δ past 5 %, starred in that table's δ columns) must point
    at Table 2, not at the given data; the other notes' lettering untouched, and with no room for the
    given data (the table stays 1) the legend stays «табл. 1»."""
    from graphplan.drawing.layout import Placed
    from graphplan.graphic.record import Record
    from graphplan.sheets.camgiven import with_given
    cam = build(tomllib.loads(CAM54), "<cam54>")
    head = "Таблиця 1. Переміщення" if lang == "uk" else "Table 1. Displacement"
    legend = ("* — похибка δ понад 5 % (табл. 1): коротка ордината" if lang == "uk"
              else "* — an error δ past 5 % (Table 1): a short ordinate")
    other = "R_0 = 48 мм (табл. 1 — ні)" if lang == "uk" else "R_0 = 48 mm (Table 1 - no)"
    prof = Record("profile")
    prof.segment((560.0, 300.0), (800.0, 560.0))
    tab = Record("table", [], {})
    tab.label((560.0, 200.0), head, size=3.5, layer="tables")
    tab.segment((560.0, 60.0), (800.0, 196.0), layer="tables")
    nts = Record("notes")
    nts.label((300.0, 100.0), other, size=3.5)
    nts.label((300.0, 90.0), legend, size=3.5)
    page = [Placed("profile", prof, (555.0, 206.0, 836.0, 589.0)), Placed("table", tab, (560.0, 60.0, 800.0, 205.0)),
            Placed("notes", nts, (295.0, 85.0, 540.0, 105.0))]
    out = {p.name: p for p in with_given(page, cam, {"sense": "cw"}, lang, None)}
    title = next(p.text for p in out["table"].record.items if p.kind == "text")
    number = title.split(".")[0].split()[-1]
    texts = [p.text for p in out["notes"].record.items if p.kind == "text"]
    said = texts[1].split("(табл. " if lang == "uk" else "(Table ")[1][0]
    assert number == said == "2"
    assert texts[0] == other and out["notes"].box == page[2].box
    low = [page[0], Placed("table", tab.moved(0.0, 90.0), (560.0, 150.0, 800.0, 295.0)), page[2]]
    assert with_given(low, cam, {"sense": "cw"}, lang, None) is low


# -- cam54's own: a rocking knife-edge follower turned by a clockwise cam -----------------------------

def _rocking_theta(phi, R0, a=0.11, l=0.09, swing=math.radians(18.0), d=1e-3):
    """OWN_CAM54's pressure angle (deg, signed as Table 1) by brute force: the arm's angle at the
    nearest position from the triangle O O1 C (|OC| = R0), the tip carried round the clockwise cam's
    centre by +φ, the tangent of that path by central differences, sin ϑ = the tip's velocity
    (square to the arm) along the tangent. The arm under the line O–O1 (a clockwise cam's layout: the
    counter-clockwise one mirrored, stop 60)."""
    rise, far, ret = 90.0, 30.0, 120.0

    def psi(p):
        p = np.asarray(p, float)
        u = np.clip(p / rise, 0, 1)
        v = np.clip((p - rise - far) / ret, 0, 1)
        par = np.where(v <= 0.5, 2 * v * v, 1 - 2 * (1 - v) ** 2)
        return swing * np.where(p <= rise, _trapezoid(u), np.where(p < rise + far, 1.0, 1 - par))

    psi0 = math.acos((a * a + l * l - R0 * R0) / (2 * a * l))

    def tip(p):
        ang = math.pi - psi0 - psi(p)
        x, y, t = a + l * np.cos(ang), -l * np.sin(ang), np.radians(p)
        return x * np.cos(t) - y * np.sin(t), x * np.sin(t) + y * np.cos(t), ang
    (xa, ya, _), (xb, yb, _), (_, _, ang) = tip(phi - d), tip(phi + d), tip(phi)
    t = -np.radians(phi)
    tx, ty = (xb - xa) * np.cos(t) - (yb - ya) * np.sin(t), (xb - xa) * np.sin(t) + (yb - ya) * np.cos(t)
    return np.degrees(np.arcsin((tx * np.sin(ang) + ty * np.cos(ang)) / np.hypot(tx, ty)))


def test_own_cam54_rocking_knife_edge_by_brute_force():
    """OWN_CAM54 ([ϑ] 40°/45°): at the R0 the program finds the brute force's largest angle is its phase's
    allowed one (the bound reached: the return's 45° with the arm under O–O1), 1 % under R0 it is past it; at the R0 taken each phase's largest
    angle and the dwells' (|∠OCO1 − 90°| of the triangle OO1C at |OC| = R0 and R_max) as the JSON says;
    the drawn phase diagram's angles from O the printed ones within 1°."""
    from graphplan.drawing.cam import phase_diagram
    from graphplan.exact.cam import solve
    from graphplan.graphic.cam import construct
    from graphplan.report.cam import cam_json
    from review_scenes import OWN_CAM54
    from test_cam_robust import drawn_angles
    cam = build(tomllib.loads(OWN_CAM54), "<own54>")
    sol = solve(cam)
    g = construct(sol, 12, 0.5)
    doc = cam_json(sol, g, "")
    rise, ret = np.linspace(0.01, 89.99, 8001), np.linspace(120.01, 239.99, 8001)
    R0 = doc["base_radius_min_m"]
    def worst(R):          # the larger of each phase's largest |ϑ| over its allowed one
        return max(np.abs(_rocking_theta(rise, R)).max() / 40.0, np.abs(_rocking_theta(ret, R)).max() / 45.0)
    assert worst(R0) == pytest.approx(1.0, abs=0.01 / 45.0)
    assert worst(R0 * 0.99) > 1.004
    taken = doc["base_radius_m"]
    signed = doc["pressure_angle_extreme_deg"]
    for k, grid in (("rise", rise), ("return", ret)):
        th = _rocking_theta(grid, taken)
        assert signed[k] == pytest.approx(th[np.argmax(np.abs(th))], abs=0.01)
    near, far = _rocking_theta(np.array([300.0, 105.0]), taken)
    dwell = doc["dwell_pressure_angle_deg"]
    assert near == pytest.approx(dwell["near"], abs=0.01) and far == pytest.approx(dwell["far"], abs=0.01)
    a, l = 0.11, 0.09
    psi0 = math.acos((a * a + l * l - taken * taken) / (2 * a * l))
    far_r = abs(a + l * np.exp(1j * (math.pi - psi0 - math.radians(18.0))))
    for th, r in ((near, taken), (far, far_r)):
        gamma = math.degrees(math.acos((r * r + l * l - a * a) / (2 * r * l)))
        assert abs(th) == pytest.approx(abs(gamma - 90.0), abs=0.01)
    angles = drawn_angles(phase_diagram(sol, g, "uk"), True)
    assert max(abs(angles[k] - abs(p["graphical"]["pressure_angle_deg"])) for k, p in enumerate(doc["positions"])) < 1.0


def test_a_sets_sheet_of_table_1_alone_draws_it_large(cam54):
    """_table_alone on a set's sheet that holds Table 1 alone (CAM54's table of 10 divisions on an A3
    continuation sheet): lettered 3.5 mm (its body's median letter height), centred in the field over
    form 2a; a sheet holding the table and the notes stays as it is. (Stop 57: OWN_CAM54's A3 set, which
    this test built, no longer has such a sheet — its notes now share the table's sheet, a better use
    of it —, so the rule is tested on the page itself.)"""
    from graphplan.drawing.layout import Placed
    from graphplan.sheets.cam import _table_alone, positions_table
    from graphplan.sheets.camgiven import tab_size
    from graphplan.sheets.compose import field_of, later_keep
    from graphplan.sheets.form import form
    doc = cam54[3]
    f = form("A3")
    small = positions_table(doc, "uk")                          # 2.5-mm letters in 6-mm rows
    page = [Placed("table", small, small.bounds())]
    out = _table_alone(page, doc, "uk", f, 1)
    assert [p.name for p in out] == ["table"] and tab_size(small) == pytest.approx(2.5)
    assert tab_size(out[0].record) == pytest.approx(3.5)
    b, (x0, _, x1, y1), floor = out[0].record.bounds(), field_of(f), later_keep(f)[3]
    assert x0 - 1e-6 <= b[0] and b[2] <= x1 + 1e-6 and floor <= b[1] and b[3] <= y1 + 1e-6
    assert (b[0] + b[2]) / 2 == pytest.approx((x0 + x1) / 2, abs=0.01)
    shared = page + [Placed("notes", small.moved(0.0, -100.0), small.bounds())]
    assert _table_alone(shared, doc, "uk", f, 1) is shared


@pytest.mark.slow
def test_own_cam54s_a3_set_keeps_table_1_with_the_notes_at_most():
    """OWN_CAM54's A3 set: no defects; Table 1 on a sheet of its own (then lettered 3.5 mm) or with the
    notes alone, within the field."""
    from graphplan.sheets.cam import build_cam_sheet
    from graphplan.sheets.camgiven import tab_size
    from graphplan.sheets.compose import SheetOptions, defects, field_of
    from graphplan.sheets.form import form
    from review_scenes import OWN_CAM54
    sheet = build_cam_sheet(build(tomllib.loads(OWN_CAM54), "<own54>"), form("A3"), SheetOptions(lang="uk", sheet="cam"))
    assert not defects(sheet)
    holding = [page for page in sheet.pages if any(p.name == "table" for p in page.placed)]
    assert len(holding) == 1
    names = [p.name for p in holding[0].placed]
    assert sorted(names) in (["table"], ["notes", "table"])
    tab = next(p for p in holding[0].placed if p.name == "table")
    if names == ["table"]:
        assert tab_size(tab.record) == pytest.approx(3.5)
    b, (x0, y0, x1, y1) = tab.record.bounds(), field_of(sheet.form)
    assert x0 - 1e-6 <= b[0] and b[2] <= x1 + 1e-6 and y0 - 1e-6 <= b[1] and b[3] <= y1 + 1e-6
