"""Stop 49 (the lead's LINK49: a rocking coulisse — the crank O1A clockwise, the stone 2 on the
coulisse OB, a 160 N·m resistance moment on link 3; I(0-1) -> II(2-3) of the third kind alone).
The truth here: the closed-form mechanism (A = O1 + r·e^{iθ}, the coulisse along OA), its power
balance, a frictionless sliding pair's reaction normal to the guide, and the drawn geometry measured."""
from __future__ import annotations

import cmath
import math

import pytest

from conftest import scene_study
from review_scenes import LINK49

MU_L, MU_F = 0.0025, 2.5     # the A1 sheet's scheme and force plans (1:2.5, 2.5 N/mm)


@pytest.fixture(scope="module")
def fp():
    from graphplan.exact import kinetostatics
    from graphplan.graphic import forceplans
    st = scene_study(LINK49)
    return forceplans.construct(st, float(kinetostatics.at_scene_angle(st)), mu_l=MU_L, mu_F=MU_F)


def _sides(fp, label: str) -> dict[str, complex]:
    gp = next(g for g in fp.groups if g.label == label)
    return {s.name: s.end - s.start for s in gp.sides}


def _coulisse(fp) -> complex:
    """The coulisse's direction as drawn: O → A on group II(2-3)."""
    pts = next(g for g in fp.groups if g.label == "II(2-3)").points
    return (pts["A"] - pts["O"]) / abs(pts["A"] - pts["O"])


def test_the_coulisse_acts_on_the_stone_normal_to_it(fp):
    """R32 (the coulisse on the stone, a frictionless sliding pair) is drawn on the plan at 90° to
    the coulisse within the ruler's 0.5 mm over its ~200 mm; R12 (the crank on the stone, a
    revolute) carries along the coulisse what the stone's own loads G2 + Φ2 put there, no more."""
    s, g = _sides(fp, "II(2-3)"), _coulisse(fp)
    r32 = s["R32"]
    assert abs((r32 / g).real) / abs(r32) < 0.5 / abs(r32) + 1e-3
    along = (s["R12"] / g).real + ((s["G2"] + s["Φ2"]) / g).real
    assert abs(along) <= 1.0      # mm: two sides' ruler roundings


def test_balancing_moment_agrees_with_the_closed_form_power_balance(fp):
    """M_зр from the plans equals −ΣP/ω1 of the closed-form mechanism (velocities and accelerations
    by differentiating A = O1 + r·e^{iθ}, ψ = arg A) within 1 % — and is clockwise, against ω1."""
    pts = next(g for g in fp.groups if g.label == "I(0-1)").points
    theta0 = cmath.phase(pts["A"] - pts["O1"])
    r, o1, g = 0.09, 0.22j, 9.81
    w1 = -110 * 2 * math.pi / 60           # clockwise

    def pos(t: float) -> dict[str, complex]:
        th = theta0 + w1 * t
        a = o1 + r * cmath.exp(1j * th)
        psi = cmath.phase(a)
        return {"S1": o1 + 0.5 * r * cmath.exp(1j * th), "A": a, "S3": 0.24 * cmath.exp(1j * psi), "psi": psi}

    h = 1e-4

    def d(key: str, order: int) -> complex:
        f = [pos(k * h)[key] for k in (-2, -1, 0, 1, 2)]
        if order == 1:
            return (f[0] - 8 * f[1] + 8 * f[3] - f[4]) / (12 * h)
        return (-f[0] + 16 * f[1] - 30 * f[2] + 16 * f[3] - f[4]) / (12 * h * h)

    masses = {"S1": 4.0, "A": 1.5, "S3": 9.0}
    power = 0.0
    for k, m in masses.items():
        force = -1j * m * g - m * d(k, 2)
        power += (force.conjugate() * d(k, 1)).real
    w3, e3 = d("psi", 1).real, d("psi", 2).real
    m3 = -160.0 * math.copysign(1.0, w3)              # opposing the coulisse on the working stroke
    power += (m3 - 0.18 * e3) * w3
    closed = -power / w1
    assert fp.balancing == pytest.approx(closed, rel=0.01)
    assert closed < 0                                 # clockwise (+ counter-clockwise), as ω1


def test_the_couples_leave_the_crowded_centre_for_a_free_stretch_of_their_link(fp):
    """S3 lies 8 mm from O1 and 10 mm from S1 on the scheme at 1:2.5 (OB's middle is level with
    O1): M3's and M^Φ3's arcs are drawn on the coulisse itself (within 0.5 mm of its line) and at
    least 15 mm from every point the scheme names, M_зр's and ω1's arcs stay at O1."""
    from graphplan.drawing.forces import mechanism_record
    rec = mechanism_record(fp)
    centres = [complex(*q.points[0]) for q in rec.items if q.kind == "arc"]
    o1 = 0.22j / MU_L
    a = next(g for g in fp.groups if g.label == "II(2-3)").points["A"]
    named = {"O": 0j, "O1": o1, "A": a, "S1": (o1 + a) / 2, "S3": 0.24 / MU_L * _coulisse(fp)}
    away = [c for c in centres if abs(c - o1) > 0.5]
    at_o1 = [c for c in centres if abs(c - o1) <= 0.5]
    assert len(away) == 2 and len(at_o1) == 2
    g = _coulisse(fp)
    for c in away:
        assert abs((c / g).imag) < 0.5
        assert min(abs(c - p) for p in named.values()) >= 15.0


def test_couple_spot_keeps_a_free_point_and_moves_from_a_crowded_one():
    """On a 100 mm link along x with points at 0, 100 and a couple's point at 50: kept there (50 mm
    of room, the couple's own arrows aside); with two more points at 40 and 58 (8 mm of room),
    moved to the nearest spot with the room a free point has (12 mm: 70 mm, 12 mm past the point at
    58 — not the farthest from every point, 79 mm, which sent the slotted lever's M3 to its pivot,
    review56 #7); an arrow of another point across that stretch sends it to the other side (28 mm)."""
    from graphplan.drawing.forces import couple_spot
    own = [(0j, 100 + 0j)]
    mine = [(50 + 0j, 50 + 0j, 50 - 30j)]             # the couple's own G at S: no crowd
    assert couple_spot(50 + 0j, own, [0j, 100 + 0j, 50 + 0j], mine, []) == 50
    pts = [0j, 100 + 0j, 50 + 0j, 40 + 0j, 58 + 0j]
    assert abs(couple_spot(50 + 0j, own, pts, mine, []) - 70) <= 1.0
    across = [(58 + 0j, 79 + 10j, 79 - 10j)]
    assert abs(couple_spot(50 + 0j, own, pts, mine + across, []) - 28) <= 1.0


def test_no_force_plan_longer_than_225_mm():
    """A plan may grow past the largest plan's size for its short loads, never past 1.5 × 150 mm
    (the coulisse's 510 N drawn 510 mm at 1 N/mm, its own loads 14–90 N)."""
    from graphplan.sheets.forces import plan_may_grow
    assert plan_may_grow(204.0, 5.9, 204.0)
    assert not plan_may_grow(255.0, 7.4, 204.0)
    assert not plan_may_grow(510.0, 14.7, 510.0)


@pytest.mark.slow
def test_link49_a1_force_plans_read_without_slivers():
    """The A1 sheet's force plans: the longest side at most 225 mm, every load at least 5 mm."""
    from graphplan.sheets.forces import drawing_scales
    st = scene_study(LINK49)
    sc = drawing_scales(st, "A1")
    for key in ("polygon II(2-3)", "polygon I(0-1)"):
        mu = sc[key]["mu_F"]
        assert 510.0 / mu <= 225.0
        assert 14.7 / mu >= 5.0         # G2 = 1.5 · 9.81 N, the shortest load


def test_a_tall_group_and_its_plan_set_apart_where_no_sheet_holds_them_as_one_box():
    """LINK49's A3 set: the coulisse's group 81 × 265 mm and its plan 212 × 61 mm make a 302 × 265
    box no A3 sheet holds beside form 2a (the field 277 mm tall, 262 mm beside the block): the set
    was refused. Set apart, the group stands at the field's left and its plan beside its top, right
    of it and clear of the title block's corner — the two drawings measured, not the code's boxes."""
    from graphplan.drawing.layout import Leaf
    from graphplan.sheets.compose import field_of, keep_out, later_keep
    from graphplan.sheets.forceset import pack, units_of
    from graphplan.sheets.form import form
    f = form("A3")
    region = field_of(f)
    leaves = {"scheme": [], "acceleration": [], "groups": [Leaf("group II(2-3)", 80.6, 264.8)],
              "forces": [Leaf("polygon II(2-3)", 211.6, 61.4)], "lever": [], "charts": [], "hodographs": []}
    width = region[2] - region[0]
    args = ([], None, region, keep_out(f), later_keep(f), 10.0)
    assert pack(units_of(leaves, width), *args) is None
    pages = pack(units_of(leaves, width, apart=True), *args)
    assert pages is not None and len(pages) == 1
    g, q = pages[0]
    assert g.d + g.h <= region[3] - region[1] + 1e-9
    assert q.x >= g.x + g.w and q.d + q.h <= g.d + g.h      # beside the group, not under it
    kx = keep_out(f)[0] - region[0]
    assert g.x + g.w <= kx or g.d + g.h <= region[3] - keep_out(f)[3]


def test_whitworth_inertia_couple_drawn_and_named_on_its_coulisse_clear_of_the_crank():
    """frc49's own Whitworth drive at 1:4: S3 lies 5.9 mm from S1 (the crank crosses the coulisse),
    where M^Φ3's arc was named on a 39 mm leader. Its arc is drawn on OB (centre within 0.5 mm of
    the line) at least 5.5 mm from every point, and its name stands within 8 mm of the arc's centre."""
    from graphplan.drawing.forces import mechanism_record
    from graphplan.exact import kinetostatics
    from graphplan.graphic import forceplans
    from review_scenes import WHITWORTH49
    st = scene_study(WHITWORTH49)
    mu = 0.004
    fp = forceplans.construct(st, float(kinetostatics.at_scene_angle(st)), mu_l=mu, mu_F=15.0)
    rec = mechanism_record(fp)
    pts = [complex(*q.points[0]) for q in rec.items if q.kind == "point"]
    b_name = next(complex(*q.points[0]) for q in rec.items if q.kind == "text" and q.text == "B")
    b = min(pts, key=lambda p: abs(p - b_name))           # the joint its letter names; O at the origin
    g = b / abs(b)
    arcs = [complex(*q.points[0]) for q in rec.items if q.kind == "arc" and q.radius < 6.0]
    o1 = 0.07j / mu
    couple = [c for c in arcs if abs(c - o1) > 0.5 and abs((c / g).imag) < 0.5]
    assert len(couple) == 1
    c = couple[0]
    assert min(abs(c - p) for p in pts) >= 5.5
    name = next(complex(*q.points[0]) for q in rec.items if q.kind == "text" and q.text == "M^{Φ}_{3}")
    assert abs(name - c) <= 8.0
