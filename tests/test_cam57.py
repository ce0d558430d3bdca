"""Stop 57's cam sheet: the lead's CAM57 (a translating roller follower, offset "auto", the cam clockwise,
a trapezoidal rise, a cosine return) against a brute force written apart from the code (the laws integrated
numerically, tg ϑ = (ds/dφ − e)/(s0 + s), the centre profile turned point by point); and the blind
reviewer's CAM57_SMALL_R0 (R0 GIVEN below the smallest): the notes say so with the radius to take, the
phase's largest angle over [ϑ] flagged «*» there and on ϑ(φ), the phase diagram's caption names the given
R0, the Ukrainian warning in decimal commas."""
from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from camfixtures import cam_fixture
from review_scenes import CAM57, CAM57_SMALL_R0

cam57 = cam_fixture("cam57", CAM57, 8)
small = cam_fixture("small", CAM57_SMALL_R0, 9)


def _trapezoidal(u):
    """The trapezoidal-acceleration law's s/h on ``u`` ∈ [0, 1]: the acceleration's trapezoids (ramps over
    the first and last eighths and the middle quarter) integrated twice numerically, scaled to 1 at u = 1."""
    grid = np.linspace(0.0, 1.0, 200001)
    a = np.interp(grid, [0, 1 / 8, 3 / 8, 5 / 8, 7 / 8, 1], [0, 1, 1, -1, -1, 0])
    v = np.concatenate([[0.0], np.cumsum((a[1:] + a[:-1]) / 2 * np.diff(grid))])
    s = np.concatenate([[0.0], np.cumsum((v[1:] + v[:-1]) / 2 * np.diff(grid))])
    return np.interp(u, grid, s / s[-1])


def _laws(phi, h, rise, far, ret, f_rise, f_ret):
    """s(φ) (m) over a whole turn, φ in degrees: the rise by f_rise(u), the far dwell, the return by
    1 − f_ret(u), the near dwell; ds/dφ by central differences of 1e-4°."""
    def s_of(p):
        p = np.asarray(p, float)
        out = np.zeros_like(p)
        m = p <= rise
        out[m] = h * f_rise(p[m] / rise)
        out[(p > rise) & (p <= rise + far)] = h
        m = (p > rise + far) & (p <= rise + far + ret)
        out[m] = h * (1.0 - f_ret((p[m] - rise - far) / ret))
        return out
    d = 1e-4
    v = (s_of(phi + d) - s_of(phi - d)) / math.radians(2 * d)
    return s_of(phi), v


def _theta(s, v, e, R0):
    """The pressure angle (deg) of a translating follower offset by e: tg ϑ = (ds/dφ − e)/(s0 + s)."""
    s0 = math.sqrt(R0 ** 2 - e ** 2)
    return np.degrees(np.arctan((v - e) / (s0 + s)))


def _r0_min(s, v, e, phases, allowed):
    """The smallest R0 at offset e: s0 ≥ |ds/dφ − e|/tg[ϑ] − s over each phase."""
    s0 = max(float(np.max(np.abs(v[m] - e) / math.tan(math.radians(a)) - s[m])) for m, a in zip(phases, allowed))
    return math.hypot(e, s0)


@pytest.mark.slow
def test_cam57_offset_base_radius_angles_and_curvature_by_brute_force(cam57):
    """CAM57: e «auto» within 0.05 mm of the offset that minimises R0 by a scan; R0 min at the program's
    e to 0.01 mm; each phase's largest |ϑ| at R0 = 32 mm to 0.02° and its φ to 0.2°; ρ_min of the convex
    centre profile (the cam clockwise: P = C·e^{iφ}) to 0.02 mm."""
    cam, sol, g, doc = cam57
    phi = np.linspace(0.0, 360.0, 72001)
    s, v = _laws(phi, 0.032, 100.0, 40.0, 130.0, _trapezoidal, lambda u: (1 - np.cos(np.pi * u)) / 2)
    phases = [phi <= 100.0, (phi >= 140.0) & (phi <= 270.0)]
    coarse = np.linspace(0.0, 0.03, 301)
    fine = np.linspace(-0.0002, 0.0002, 401) + coarse[np.argmin([_r0_min(s, v, e, phases, (30, 40)) for e in coarse])]
    e_best = fine[np.argmin([_r0_min(s, v, e, phases, (30, 40)) for e in fine])]
    e = sol.geometry.e
    assert abs(e - e_best) < 5e-5
    assert sol.R0_min == pytest.approx(_r0_min(s, v, e, phases, (30, 40)), abs=1e-5)
    assert sol.geometry.R0 == pytest.approx(0.032)
    theta = _theta(s, v, e, 0.032)
    for (p_deg, t_deg), m in zip(sol.pressure_extreme_points(), phases):
        k = int(np.argmax(np.abs(theta[m])))
        assert t_deg == pytest.approx(theta[m][k], abs=0.02) and p_deg == pytest.approx(phi[m][k], abs=0.2)
    # the centre profile turned point by point: C = (σe, s0 + s) in the fixed frame, σ = −1 (clockwise)
    s0 = math.sqrt(0.032 ** 2 - e ** 2)
    P = (-e + 1j * (s0 + s)) * np.exp(1j * np.radians(phi))
    d1, d2 = np.gradient(P, phi), np.gradient(np.gradient(P, phi), phi)
    cross = (np.conj(d1) * d2).imag
    rho = np.abs(d1) ** 3 / cross                   # traversed counter-clockwise: convex where > 0
    inner = slice(10, -10)
    assert sol.curvature_min() == pytest.approx(float(np.min(rho[inner][rho[inner] > 0])), abs=2e-5)


def test_a_given_base_radius_below_the_smallest_is_said_plainly(small):
    """CAM57_SMALL_R0 (e = 8 mm, R0 = 50 mm given): the brute force's smallest R0 (50.40 mm) is over the
    given, its largest rise angle at R0 = 50 mm over 25°. The notes' R0 line says the given radius is
    below the smallest and to take the next whole millimetre; the rise's angle printed with «*», the
    return's (under 35°) without; the Ukrainian warning in decimal commas and said once on the sheet."""
    from graphplan.report.cam import cam_lines
    from graphplan.sheets.cam import notes
    cam, sol, g, doc = small
    phi = np.linspace(0.0, 360.0, 72001)
    s, v = _laws(phi, 0.03, 90.0, 60.0, 110.0, lambda u: np.where(u <= 0.5, 2 * u ** 2, 1 - 2 * (1 - u) ** 2),
                 lambda u: u - np.sin(2 * np.pi * u) / (2 * np.pi))
    phases = [phi <= 90.0, (phi >= 150.0) & (phi <= 260.0)]
    r0 = _r0_min(s, v, 0.008, phases, (25, 35))
    assert 0.05 < r0 < 0.051 and sol.R0_min == pytest.approx(r0, abs=1e-5)
    theta = _theta(s, v, 0.008, 0.05)
    rise = float(np.max(np.abs(theta[phases[0]])))
    ret = float(np.max(np.abs(theta[phases[1]])))
    assert rise > 25.0 and ret < 35.0
    take = math.ceil(r0 * 1000)
    uk, en = cam_lines(doc, "uk"), cam_lines(doc, "en")
    assert any("задано R_0 = 50 мм — менший за найменший" in x and f"R_0 ≥ {take} мм" in x for x in uk)
    assert any("R_0 given = 50 mm — below the smallest" in x and f"take R_0 ≥ {take} mm" in x for x in en)
    angles = next(x for x in uk if x.startswith("Найбільший кут тиску"))
    assert f"підйом {rise:.2f}°*".replace(".", ",") in angles
    assert f"−{ret:.2f}° при".replace(".", ",") in angles
    warning = next(x for x in doc["warnings_uk"] if x.startswith("радіус основної шайби"))
    assert "50,0 мм" in warning and f"{r0 * 1000:.2f}".replace(".", ",") in warning and "." not in warning
    lines = notes(doc, "uk", cam)
    assert sum("менший за найменший" in x for x in lines) == 1


@pytest.mark.parametrize("lang", ["uk", "en"])
def test_a_taken_radius_under_the_graphical_smallest_says_why(small, lang):
    """Stop 62 (CAM62: the exact smallest 47,889 mm rounded up to 48, read 48,12 mm off the phase diagram): a
    base radius taken — the brute force's smallest rounded up to a whole mm — under the one read off the
    diagram is said to be the exact one rounded up, the drawn one over it by the construction's error;
    taken over the graphical one, the line says only what it takes. (CAM57_SMALL_R0's document with its R0
    taken, not given.)"""
    from graphplan.report.cam import cam_lines
    cam, sol, g, doc = small
    phi = np.linspace(0.0, 360.0, 72001)
    s, v = _laws(phi, 0.03, 90.0, 60.0, 110.0, lambda u: np.where(u <= 0.5, 2 * u ** 2, 1 - 2 * (1 - u) ** 2),
                 lambda u: u - np.sin(2 * np.pi * u) / (2 * np.pi))
    r0 = _r0_min(s, v, 0.008, [phi <= 90.0, (phi >= 150.0) & (phi <= 260.0)], (25, 35))
    take = math.ceil(r0 * 1000)
    why = "округлений угору" if lang == "uk" else "rounded up"
    taken = f"прийнято R_0 = {take} мм" if lang == "uk" else f"R_0 taken = {take} mm"
    for drawn, said in ((take + 0.12, True), (take - 0.3, False), (float(take), False)):
        d = dict(doc, base_radius_given=False, base_radius_m=take / 1000, base_radius_graphical_m=drawn / 1000)
        line = next(x for x in cam_lines(d, lang) if taken in x)
        assert (why in line) is said and "менший за" not in line and "below the" not in line


def test_the_excess_is_marked_on_the_pressure_angle_diagram(small):
    """ϑ(φ) of CAM57_SMALL_R0: a point at the rise's largest ϑ (φ, ϑ as the solution's extreme) lettered
    with it and «*»; none on the return (within [ϑ])."""
    from graphplan.drawing.cam import pressure_diagram
    cam, sol, g, doc = small
    rec = pressure_diagram(sol, g, "uk", g.mu_phi, 1.0)
    marks = [p for p in rec.items if p.kind == "point" and p.step.startswith("ϑ over [ϑ]")]
    (p_deg, t_deg), _ = sol.pressure_extreme_points()
    assert [p.step for p in marks] == ["ϑ over [ϑ] 0"]
    assert marks[0].points[0] == pytest.approx((math.radians(p_deg) / g.mu_phi, t_deg))
    assert any(p.kind == "text" and p.text == f"{t_deg:.2f}°*".replace(".", ",") for p in rec.items)


def test_the_phase_diagrams_caption_names_a_given_radius(small):
    """A given R0: the phase diagram's caption names the smallest and the given R0 (O is drawn at the
    given one); a chosen R0 keeps «найменший R_0» where O is drawn at the smallest read, else names both
    («найменший і прийнятий R_0»: review 59 #4, O drawn at the rounded-up R0, O_min beside it)."""
    from graphplan.sheets.cam import _captions
    assert _captions(small[2], small[0], "uk")["phase"][0].endswith("найменший і заданий R_0")
    assert _captions(small[2], small[0], "en")["phase"][0].endswith("smallest and given R_0")
    chosen = dataclasses.replace(small[0], base_radius=None)
    assert _captions(small[2], chosen, "uk")["phase"][0].endswith("), найменший і прийнятий R_0")
    at_smallest = dataclasses.replace(small[2], R0=small[2].R0_drawn)
    assert _captions(at_smallest, chosen, "uk")["phase"][0].endswith("), найменший R_0")


# -- review 57 finding 6: the uk sheet of c_cam dropped «Таблиця 1. Вихідні дані» that its en sheet carried ------

def _page_of(doc, lang: str, profile_foot: float):
    """A page as c_cam's uk A1 sheet had it: the table of the divisions at 3.5-mm letters in 10-mm rows,
    245.3 mm wide, its foot at y = 66 mm over the title block; the profile's ink from ``profile_foot`` up."""
    from graphplan.drawing.layout import Placed
    from graphplan.graphic.record import Record
    from graphplan.sheets.cam import positions_table
    tab = positions_table(doc, lang, 10.0, 3.5, span=245.3)
    b = tab.bounds()
    tab = tab.moved(585.7 - b[0], 66.0 - b[1])
    prof = Record("profile")
    prof.segment((598.5, profile_foot), (818.2, 584.0))
    return [Placed("profile", prof, (585.7, tab.bounds()[3] + 6.0, 831.0, 584.0)),
            Placed("table", tab, tab.bounds())]


@pytest.mark.parametrize("lang", ["uk", "en"])
def test_the_given_data_kept_by_both_tables_at_smaller_letters(small, lang):
    """c_cam's uk page (Table 2 at 3.5 mm, the profile's ink from y = 330.6 mm): at 3.5-mm letters the
    closest rows that kept Table 2's lowered indices clear (7.5 mm) left 91 mm for the given data's 96 and
    both tables fell to 2.5 mm in rows alike (7 mm); since stop 60 the header row holds the indices' tails
    and 7-mm rows are clear: both tables at 3.5 mm in rows alike, the given data between them and as wide —
    not the page without it (the en sheet, whose Table 2 was at 2.5 mm already, kept it)."""
    from graphplan.drawing.labels import collisions
    from graphplan.drawing.layout import GAP
    from graphplan.sheets.cam import positions_table
    from graphplan.sheets.camgiven import tab_size, with_given
    doc = small[3]
    page = _page_of(doc, lang, 330.6)
    out = with_given(page, small[0], doc, lang, lambda row, size, span: positions_table(doc, lang, row, size, span=span))
    names = {p.name: p for p in out}
    assert set(names) == {"profile", "table", "given"}
    gb, tb = names["given"].record.bounds(), names["table"].record.bounds()
    assert tb[1] == pytest.approx(66.0, abs=1e-6)                              # its foot where it stood
    assert gb[1] >= tb[3] + GAP - 1e-6 and gb[3] <= 330.6 - GAP + 1e-6          # between the table and the profile
    assert gb[2] - gb[0] == pytest.approx(tb[2] - tb[0], abs=0.5)
    # both tables at one lettering: 3.5 mm since stop 60 — Table 2's header row grows to hold a lowered
    # index's tail (drawing.tables, clear_header), so its 7-mm rows are clear and leave the given data its
    # 96 mm at 3.5 mm; before, only 7.5-mm rows were, and both tables fell to 2.5 mm
    assert tab_size(names["table"].record) == tab_size(names["given"].record) == 3.5
    assert not collisions(names["table"].record) and not collisions(names["given"].record)
    # the rows alike: the two tables' ruled rows the same height (21 rows of Table 2 over 13 of the given data)
    h2 = (tb[3] - tb[1]) / 21
    hg = (gb[3] - gb[1]) / 13
    assert h2 == pytest.approx(hg, abs=0.6)
    # where the room holds the given data at 3.5 mm, the larger lettering is kept
    high = with_given(_page_of(doc, lang, 345.0), small[0], doc, lang,
                      lambda row, size, span: positions_table(doc, lang, row, size, span=span))
    assert tab_size(next(p for p in high if p.name == "given").record) == 3.5


@pytest.mark.slow
def test_c_cams_a1_sheets_carry_the_same_tables_in_both_languages():
    """The reviewer's c_cam (CAM57_SMALL_R0) on A1 in uk and en: the same two tables, the given data
    (with n = 150 rpm) and the divisions."""
    import tomllib

    from graphplan.model.cam import build
    from graphplan.sheets.cam import build_cam_sheet
    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.form import form
    titles = {}
    for lang in ("uk", "en"):
        sheet = build_cam_sheet(build(tomllib.loads(CAM57_SMALL_R0), "<c_cam>"), form("A1"),
                                SheetOptions(lang=lang, sheet="cam"))
        assert not sheet.more
        texts = [p.text for p in sheet.record.items if p.kind == "text"]
        titles[lang] = sorted(t[:16] for t in texts if t.startswith(("Таблиця ", "Table ")))
        assert ("Частота обертання кулачка" if lang == "uk" else "Cam speed") in texts
        assert "150" in texts
    assert titles["uk"] == ["Таблиця 1. Вихід", "Таблиця 2. Перем"]
    assert titles["en"] == ["Table 1. Given d", "Table 2. Displac"]
