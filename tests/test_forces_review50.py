"""Stop 50 (the lead's LINK50: a crank-rocker four-bar O1ABO2 whose rocker carries a pin C; the stone 4
on C slides in the coulisse O3D rocking about O3 under a 120 N·m resistance moment — I(0-1) -> II(2-3)
ВВВ -> II(4-5) ВПВ). The truth here: the closed-form mechanism (B by intersecting two circles, C on the
rocker's line, the coulisse along O3C), its power balance, a frictionless sliding pair's reaction normal
to the guide, and the drawn geometry measured."""
from __future__ import annotations

import cmath
import math

import pytest

from conftest import circles, group_of, scene_force_plans, scene_study
from review_scenes import LINK50

MU_L, MU_F = 0.004, 4.0          # the A1 sheet's groups and force plans (1:4, 4 N/mm)
CRANK = {"I(0-1)": 0.001}        # … its crank group at 1:1, 2 N/mm
CRANK_F = {"I(0-1)": 2.0}
O1, O2, O3 = 0j, 0.30 + 0.03j, 0.52 + 0.26j
R1, L2, L3, LC, L5 = 0.07, 0.28, 0.16, 0.24, 0.46
W1 = 75 * 2 * math.pi / 60      # counter-clockwise


@pytest.fixture(scope="module")
def fp():
    return scene_force_plans(LINK50, mu_l=MU_L, mu_F=MU_F, group_mu=CRANK, group_mu_F=CRANK_F)


_RECORDS: dict = {}


def _record(fp, gp):
    """A group's drawing, drawn once for the module (group_record is the slow part of these tests)."""
    from graphplan.drawing import forces as fd
    key = (id(fp), gp.label)
    if key not in _RECORDS:
        _RECORDS[key] = fd.group_record(fp, gp, "uk")
    return _RECORDS[key]


def _closed_form(fp):
    """θ1 as drawn (group I(0-1)), B on the branch drawn (group II(2-3)): the positions of the centres
    of mass and the links' angles as functions of t (the crank turning at ω1)."""
    pts = group_of(fp, "I(0-1)").points
    theta0 = cmath.phase(pts["A"] - pts["O1"])
    g23 = group_of(fp, "II(2-3)").points
    b_drawn = (g23["B"] - g23["O2"]) * MU_L + O2
    a0 = R1 * cmath.exp(1j * theta0)
    sign = min((0, 1), key=lambda k: abs(circles(a0, L2, O2, L3)[k] - b_drawn))

    def pos(t: float) -> dict[str, complex | float]:
        a = R1 * cmath.exp(1j * (theta0 + W1 * t))
        b = circles(a, L2, O2, L3)[sign]
        c = O2 + LC * (b - O2) / L3
        u5 = (c - O3) / abs(c - O3)
        return {"S1": a / 2, "S2": (a + b) / 2, "S3": (O2 + b) / 2, "C": c, "S5": O3 + 0.23 * u5,
                "phi2": cmath.phase(b - a), "phi3": cmath.phase(b - O2), "phi5": cmath.phase(u5)}
    return pos


def _d(pos, key: str, order: int, h: float = 1e-4) -> complex:
    f = [complex(pos(k * h)[key]) for k in (-2, -1, 0, 1, 2)]
    if order == 1:
        return (f[0] - 8 * f[1] + 8 * f[3] - f[4]) / (12 * h)
    return (-f[0] + 16 * f[1] - 30 * f[2] + 16 * f[3] - f[4]) / (12 * h * h)


def test_balancing_moment_agrees_with_the_closed_form_power_balance(fp):
    """M_зр from the plans equals −ΣP/ω1 of the closed-form six-bar within 2.5 % (the plans' ruler
    and the acceleration plan's reading), the 120 N·m opposing the coulisse's turning. (R12 is the
    textbook's R^τ12 + R^n12 since review56 #1: its direction 0.05° off, its R^n12 read 37.5 mm at
    4 N/mm where the closing side read 38.5 — a ruler's step of 2.6 % either way, −2.1 % here.)"""
    pos = _closed_form(fp)
    g = 9.81
    power = 0.0
    for key, m in {"S1": 3.0, "S2": 5.0, "S3": 6.0, "C": 1.2, "S5": 7.0}.items():
        force = -1j * m * g - m * _d(pos, key, 2)
        power += (force.conjugate() * _d(pos, key, 1)).real
    for key, inertia in {"phi2": 0.04, "phi3": 0.05, "phi5": 0.07}.items():
        power += -inertia * _d(pos, key, 2).real * _d(pos, key, 1).real
    w5 = _d(pos, "phi5", 1).real
    power += -120.0 * math.copysign(1.0, w5) * w5
    closed = -power / W1
    assert fp.balancing == pytest.approx(closed, rel=0.025)
    assert fp.ks.balancing[0] == pytest.approx(closed, rel=1e-3)


def test_the_coulisse_acts_on_the_stone_normal_to_it(fp):
    """R54 (the coulisse on the stone, a frictionless sliding pair) is drawn on the plan at 90° to the
    coulisse O3C within the ruler's 0.5 mm over its 77 mm; its size is the closed form's: the
    coulisse's ΣM about O3 = 0 (its G5, Φ5, M^Φ5 and the 120 N·m) over |O3C|."""
    pos = _closed_form(fp)
    p = pos(0.0)
    u5 = cmath.exp(1j * p["phi5"])
    s = {x.name: x.end - x.start for x in group_of(fp, "II(4-5)").sides}
    r54 = s["R54"]
    assert abs((r54 / u5).real) <= 0.5
    a5, e5, w5 = _d(pos, "S5", 2), _d(pos, "phi5", 2).real, _d(pos, "phi5", 1).real
    f5 = -1j * 7.0 * 9.81 - 7.0 * a5
    moment = ((p["S5"] - O3).conjugate() * f5).imag - 0.07 * e5 - 120.0 * math.copysign(1.0, w5)
    r45 = -moment / abs(p["C"] - O3)                       # R45 on the coulisse along i·u5
    assert abs(r54) * MU_F == pytest.approx(abs(r45), rel=0.02)
    assert ((r54 / u5).imag > 0) == (r45 < 0)               # R54 = −R45


def _vectors(rec) -> dict[str, tuple[complex, complex]]:
    out = {}
    for q in rec.items:
        if q.kind == "vector" and q.role != "head" and q.text:
            (ax, ay), (bx, by) = q.points[:2]
            out[q.text] = (complex(ax, ay), complex(bx, by))
    return out


def _cross(a: complex, b: complex, c: complex, d: complex) -> bool:
    def x(p: complex, q: complex) -> float:
        return p.real * q.imag - p.imag * q.real
    den = x(b - a, d - c)
    if abs(den) < 1e-12:
        return False
    t, v = x(c - a, d - c) / den, x(c - a, b - a) / den
    return 0.02 < t < 0.98 and 0.02 < v < 0.98


def test_a_component_along_the_rocker_crosses_no_other_arrow(fp):
    """On group II(2-3) the components of the reactions along their links (R^n03 up the rocker O2B, R^n12
    along AB) cross no other force's arrow (R^n03 ran through Φ3's head at S3, its name 49 mm away)
    and pass no other loaded point nearer than a lane (2.5 mm)."""
    from graphplan.drawing import forces as fd
    gp = group_of(fp, "II(2-3)")
    vec = _vectors(_record(fp, gp))
    own = {"R03n": ("R03", "R03τ"), "R12n": ("R12", "R12τ")}
    for name, mates in own.items():
        a, b = vec[name]
        for other, (c, d) in vec.items():
            if other != name and other not in mates:
                assert not _cross(a, b, c, d), (name, other)
        for w in (vec["G2"][0], vec["G3"][0]):            # S2, S3: where G2 and G3 are applied
            t = max(0.0, min(1.0, ((w - a) / (b - a)).real))
            assert abs(w - a - (b - a) * t) > 2.5 + 1e-6, (name, w)


def test_no_two_arrows_of_one_point_merge_into_one_shaft(fp):
    """On every group of LINK50 two arrows with an end at one point leave it as rays at least 8° apart
    (R34, 4° from vertical, left the stone's C beside G4 — two shafts read as one; it now arrives
    at C from above, as the seeds draw a pushing force)."""
    from graphplan.drawing import forces as fd
    for gp in fp.groups:
        vec = _vectors(_record(fp, gp))
        rays = []
        for name, (a, b) in vec.items():
            for end, other in ((a, b), (b, a)):
                rays.append((name, end, other - end))
        for i, (n1, p1, r1) in enumerate(rays):
            for n2, p2, r2 in rays[i + 1:]:
                if n1 != n2 and abs(p1 - p2) < 0.5:
                    angle = abs(cmath.phase(r2 / r1))
                    assert angle >= math.radians(8.0) - 1e-9, (gp.label, n1, n2, math.degrees(angle))


def test_the_plans_detail_names_each_side_by_its_own_line(fp):
    """In detail I of II(4-5)'s plan (the stone's corner at 1 N/mm) each name is nearer its own side
    than any other — its letters, or the end of its leader ("R54" stood by R05's line, "Φ4" led
    across G5)."""
    from graphplan.drawing import forces as fd
    from graphplan.drawing.labels import box_to_segment
    rec = fd.polygon_record(fp, group_of(fp, "II(4-5)"), "uk")
    det = [q for q in rec.items if q.step.endswith(": detail")]
    lines = {q.text: (complex(*q.points[0]), complex(*q.points[1])) for q in det
             if q.kind in ("vector", "segment") and q.layer == "vectors" and q.text}
    assert {"R54", "R05", "G5"} <= set(lines)
    leaders = [(complex(*q.points[0]), complex(*q.points[1])) for q in det if q.kind == "segment" and q.role == "label"]
    for q in det:
        if q.kind != "text" or q.layer != "labels":
            continue
        name = q.text.replace("_{", "").replace("}", "")
        if name not in lines:
            continue
        box = q.ink()
        near = lambda seg: box_to_segment(box, *seg)                      # noqa: E731
        lead = [ld for ld in leaders if min(box_to_segment(box, p, p) for p in ld) < 1.0]
        if lead:
            a, b = lead[0]
            tip = a if box_to_segment(box, a, a) > box_to_segment(box, b, b) else b
            near = lambda seg, tip=tip: fd._to_segment(tip, *seg)         # noqa: E731
        own = near(lines[name])
        assert all(own < near(seg) for other, seg in lines.items() if other != name), (name, own)


# -- own mechanism 50: a crank-slider whose slider's pin B carries the stone of a rocking coulisse O3D --

@pytest.fixture(scope="module")
def own():
    from graphplan.exact import kinetostatics
    from graphplan.graphic import forceplans
    from review_scenes import SLIDER_COULISSE50
    st = scene_study(SLIDER_COULISSE50)
    return forceplans.construct(st, float(kinetostatics.at_scene_angle(st)), mu_l=0.0025, mu_F=2.5,
                                group_mu={"II(2-3)": 0.002, "I(0-1)": 0.0005},
                                group_mu_F={"II(2-3)": 2.0, "I(0-1)": 2.0})


def _arms(rec) -> list[tuple[str, complex, complex]]:
    """The arms drawn on a group: (force name, from, foot), read off the construction strokes."""
    out = []
    for q in rec.items:
        if q.kind == "segment" and q.role == "construction" and " mm to " in (q.text or ""):
            out.append((q.text.split(" mm to ")[1], complex(*q.points[0]), complex(*q.points[1])))
    return out


def test_an_arms_name_stands_by_its_own_arm_not_at_anothers_foot(own):
    """On II(4-5) of the slider-driven coulisse the arms h_Φ4 and h_Φ5 leave O3 2° apart: each name is
    nearer its own arm than the other's, and farther than 5 mm from the other's foot (its right-angle
    mark) — "h_Φ4" stood at h_Φ5's foot."""
    from graphplan.drawing import forces as fd
    from graphplan.drawing.labels import box_to_segment
    rec = _record(own, group_of(own, "II(4-5)"))
    arms = {n: (a, b) for n, a, b in _arms(rec)}
    assert {"Φ4", "Φ5"} <= set(arms)
    for name in ("Φ4", "Φ5"):
        text = next(q for q in rec.items if q.kind == "text" and q.text == f"h_{{{name}}}")
        box = text.ink()
        other = "Φ5" if name == "Φ4" else "Φ4"
        assert box_to_segment(box, *arms[name]) < box_to_segment(box, *arms[other])
        assert box_to_segment(box, arms[other][1], arms[other][1]) > 5.0


def test_own_no_two_arrows_of_one_point_merge(own):
    """On every group of the slider-driven coulisse no two arrows leave (or reach) one point within 8°
    of each other: Φ3 set aside over the slider's block shared a tail with R42, 5° off the guide."""
    from graphplan.drawing import forces as fd
    for gp in own.groups:
        vec = _vectors(_record(own, gp))
        ends = [(n, e, o - e) for n, (a, b) in vec.items() for e, o in ((a, b), (b, a))]
        for i, (n1, p1, r1) in enumerate(ends):
            for n2, p2, r2 in ends[i + 1:]:
                if n1 != n2 and abs(p1 - p2) < 0.5:
                    assert abs(cmath.phase(r2 / r1)) >= math.radians(8.0) - 1e-9, (gp.label, n1, n2)


def test_own_balancing_moment_agrees_with_the_closed_form(own):
    """M_зр of the slider-driven coulisse from the plans equals −ΣP/ω1 of its closed form (B = A + the
    rod's reach to the guide y = −0.02 m, the coulisse along O3B) within 1.5 %."""
    pts = group_of(own, "I(0-1)").points
    theta0 = cmath.phase(pts["A"] - pts["O"])
    w1, o3, g = 120 * 2 * math.pi / 60, 0.26 + 0.30j, 9.81

    def pos(t: float) -> dict[str, complex | float]:
        a = 0.07 * cmath.exp(1j * (theta0 + w1 * t))
        b = complex(a.real + math.sqrt(0.26 ** 2 - (-0.02 - a.imag) ** 2), -0.02)
        u5 = (b - o3) / abs(b - o3)
        return {"S1": a / 2, "S2": a + 0.35 * (b - a), "B": b, "S5": o3 + 0.4 * 0.42 * u5,
                "phi2": cmath.phase(b - a), "phi5": cmath.phase(u5)}
    power = 0.0
    for key, m in {"S1": 2.5, "S2": 4.0, "B": 3.0 + 0.8, "S5": 6.0}.items():
        force = -1j * m * g - m * _d(pos, key, 2)
        power += (force.conjugate() * _d(pos, key, 1)).real
    for key, inertia in {"phi2": 0.025, "phi5": 0.06}.items():
        power += -inertia * _d(pos, key, 2).real * _d(pos, key, 1).real
    w5 = _d(pos, "phi5", 1).real
    power += -80.0 * math.copysign(1.0, w5) * w5
    closed = -power / w1
    assert own.balancing == pytest.approx(closed, rel=0.015)


def test_no_arm_lies_along_another(fp):
    """On LINK50's groups no arm runs along another arm's line for more than a millimetre (h_R43 from
    B lay within h_G2, R43 and G2 both near vertical: its name went out 30 mm along h_G2's line) —
    each arm drawn perpendicular to its own force's line, its foot on that line."""
    from graphplan.drawing import forces as fd
    for gp in fp.groups:
        rec = _record(fp, gp)
        arms = _arms(rec)
        vec = _vectors(rec)
        for i, (n1, a1, b1) in enumerate(arms):
            if n1 in vec:                               # perpendicular to its force's line
                t, h = vec[n1]
                assert abs(((b1 - a1) / (h - t)).real) <= 1e-6 * abs(b1 - a1) * abs(h - t) + 1e-6
            for n2, a2, b2 in arms[i + 1:]:
                u = (b1 - a1) / abs(b1 - a1)
                off = max(abs(((p - a1) / u).imag) for p in (a2, b2))
                if off < 0.3:                           # on one line: how much they share
                    lo, hi = sorted(((p - a1) / u).real for p in (a2, b2))
                    assert min(hi, abs(b1 - a1)) - max(lo, 0.0) <= 1.0, (gp.label, n1, n2)


def test_the_reactions_are_named_from_to_as_seed_000(fp):
    """Seed 000 names R_{10-11} the action of link 10 on link 11 (R<from><to>): the plan's R34 is link 3's
    force on the stone 4 — the closed form's −(G4 + Φ4 + R54), R54 normal to the coulisse from its ΣM
    about O3 — within 2 % and 1°; R05, the frame's on the coulisse, balances R45 + G5 + Φ5."""
    pos = _closed_form(fp)
    p = pos(0.0)
    u5 = cmath.exp(1j * p["phi5"])
    a5, a4 = _d(pos, "S5", 2), _d(pos, "C", 2)
    e5, w5 = _d(pos, "phi5", 2).real, _d(pos, "phi5", 1).real
    f5, f4 = -1j * 7.0 * 9.81 - 7.0 * a5, -1j * 1.2 * 9.81 - 1.2 * a4
    moment = ((p["S5"] - O3).conjugate() * f5).imag - 0.07 * e5 - 120.0 * math.copysign(1.0, w5)
    r45 = -moment / abs(p["C"] - O3) * 1j * u5           # the stone on the coulisse, normal to it
    r34 = -(f4 - r45)                                    # the stone: R34 + G4 + Φ4 + R54 = 0, R54 = −R45
    r05 = -(r45 + f5)
    s = {x.name: (x.end - x.start) * MU_F for x in group_of(fp, "II(4-5)").sides}
    for name, truth in (("R34", r34), ("R05", r05)):
        assert abs(s[name]) == pytest.approx(abs(truth), rel=0.02), name
        assert abs(cmath.phase(s[name] / truth)) < math.radians(1.0), name
