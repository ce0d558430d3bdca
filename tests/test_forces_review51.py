"""Stop 51 (the lead's LINK51: a rocking coulisse driving a rocker — the crank O1A turns clockwise, its
stone 2 slides in the coulisse O3B; the coulisse's end B drives the rod BD to the rocker O4D under a
90 N·m resistance moment — I(0-1) -> II(2-3) ВПВ -> II(4-5) ВВВ). The truth here: the closed-form
mechanism (the coulisse through A, D by intersecting two circles), its power balance, a frictionless
sliding pair's reaction normal to the coulisse, and the drawn geometry measured."""
from __future__ import annotations

import cmath
import math

import pytest

from conftest import circles, group_of, scene_force_plans, scene_study
from review_scenes import LINK51

MU_L, MU_F = 0.004, 7.5          # the A1 sheet's groups and force plans (1:4, 7.5 N/mm)
CRANK = {"I(0-1)": 0.001}        # … its crank group at 1:1, 5 N/mm
CRANK_F = {"I(0-1)": 5.0}
O1, O3, O4 = 0.20j, 0j, 0.25 + 0.55j
R1, L3, L4, L5 = 0.08, 0.40, 0.30, 0.16
W1 = -90 * 2 * math.pi / 60      # clockwise
MASS = {"S1": 3.0, "A": 1.0, "S3": 8.0, "S4": 4.0, "S5": 5.0}
INERTIA = {"phi3": 0.11, "phi4": 0.025, "phi5": 0.02}     # the crank turns uniformly: its I·ε = 0


@pytest.fixture(scope="module")
def fp():
    return scene_force_plans(LINK51, mu_l=MU_L, mu_F=MU_F, group_mu=CRANK, group_mu_F=CRANK_F)


def _closed_form(fp):
    """θ1 as drawn (group I(0-1)), D on the branch drawn (group II(4-5)): the points and angles as
    functions of t, the crank turning at ω1."""
    pts = group_of(fp, "I(0-1)").points
    theta0 = cmath.phase(pts["A"] - pts["O1"])
    g45 = group_of(fp, "II(4-5)").points
    d_drawn = (g45["D"] - g45["O4"]) * MU_L + O4

    def at(theta: float, sign: int | None = None):
        a = O1 + R1 * cmath.exp(1j * theta)
        u3 = (a - O3) / abs(a - O3)
        b = O3 + L3 * u3
        return a, u3, b, circles(b, L4, O4, L5)
    a0, _, _, ds = at(theta0)
    sign = min((0, 1), key=lambda k: abs(ds[k] - d_drawn))

    def pos(t: float) -> dict[str, complex | float]:
        a, u3, b, ds = at(theta0 + W1 * t)
        d = ds[sign]
        return {"S1": (O1 + a) / 2, "A": a, "S3": O3 + 0.5 * L3 * u3, "S4": (b + d) / 2, "S5": (O4 + d) / 2,
                "phi3": cmath.phase(u3), "phi4": cmath.phase(d - b), "phi5": cmath.phase(d - O4)}
    return pos


def _d(pos, key: str, order: int, h: float = 1e-4) -> complex:
    f = [complex(pos(k * h)[key]) for k in (-2, -1, 0, 1, 2)]
    if order == 1:
        return (f[0] - 8 * f[1] + 8 * f[3] - f[4]) / (12 * h)
    return (-f[0] + 16 * f[1] - 30 * f[2] + 16 * f[3] - f[4]) / (12 * h * h)


def test_balancing_moment_agrees_with_the_closed_form_power_balance(fp):
    """M_зр = −ΣP/ω1 of the closed-form mechanism (90 N·m opposing the rocker's turning): the exact
    kinetostatics within 0.1 %, the plans and the lever within 1 % (the ruler's 0.5 mm); clockwise,
    as the crank turns (the driving moment)."""
    pos = _closed_form(fp)
    power = 0.0
    for key, m in MASS.items():
        power += ((-1j * m * 9.81 - m * _d(pos, key, 2)).conjugate() * _d(pos, key, 1)).real
    for key, inertia in INERTIA.items():
        power += -inertia * _d(pos, key, 2).real * _d(pos, key, 1).real
    w5 = _d(pos, "phi5", 1).real
    power += -90.0 * math.copysign(1.0, w5) * w5
    closed = -power / W1
    assert closed < 0                                 # clockwise (+ counter-clockwise), as the crank turns
    assert fp.ks.balancing[0] == pytest.approx(closed, rel=1e-3)
    assert fp.balancing == pytest.approx(closed, rel=0.01)
    assert fp.lever.balancing == pytest.approx(closed, rel=0.01)


def test_the_coulisse_acts_on_the_stone_normal_to_it(fp):
    """R32 (the coulisse on the stone, frictionless) is drawn at 90° to the coulisse O3A within the
    ruler's 0.5 mm over its length; R12 + G2 + Φ2 + R32 = 0 closes the stone's polygon."""
    p = _closed_form(fp)(0.0)
    u3 = cmath.exp(1j * p["phi3"])
    s = {x.name: x.end - x.start for x in group_of(fp, "II(2-3)").sides}
    assert abs((s["R32"] / u3).real) <= 0.5
    assert abs(s["R32"]) > 50.0
    stone = s["R12"] + s.get("G2", 0) + s.get("Φ2", 0) + s["R32"]
    assert abs(stone) <= 1.0


def test_the_reactions_are_named_from_to(fp):
    """R_ij is link i's force on link j: the crank group is loaded at A by R21 (the stone on the
    crank), the coulisse's group at B by R43 (the rod on the coulisse), which the rod's group
    found as R34 — equal and opposite."""
    names = {gp.label: {x.name for x in gp.sides} for gp in fp.groups}
    assert "R21" in names["I(0-1)"] and "R12" not in names["I(0-1)"]
    assert "R43" in names["II(2-3)"] and "R12" in names["II(2-3)"]
    assert "R34" in names["II(4-5)"]
    s23 = {x.name: x.end - x.start for x in group_of(fp, "II(2-3)").sides}
    s45 = {x.name: x.end - x.start for x in group_of(fp, "II(4-5)").sides}
    assert abs(s23["R43"] + s45["R34"]) <= 1.0


def _arrows_and_labels(rec):
    arrows = {q.text: (complex(*q.points[0]), complex(*q.points[1])) for q in rec.items
              if q.kind == "vector" and q.role != "head" and q.text}
    texts = [q for q in rec.items if q.kind == "text" and q.layer == "labels"]
    leaders = [(complex(*q.points[0]), complex(*q.points[1])) for q in rec.items
               if q.kind == "segment" and q.role == "label"]
    return arrows, texts, leaders


def test_the_stones_letters_read_as_their_own(fp):
    """On II(2-3) at 1:4 the stone A carries G2 and Φ2 and the coulisse's S3 (G3, Φ3) lies 14 mm
    below it: the letter "A" stands on no side between two of A's arrows (it took G2's spot and
    "G2" went out on a leader along Φ3's head, reading as Φ3's name); no force's leader passes
    within 1 mm of another arrow; each force's letter (or its leader's end) is nearer its own
    arrow than any other."""
    from graphplan.drawing import forces as fd
    from graphplan.drawing.labels import box_to_segment, segment_gap
    rec = fd.group_record(fp, group_of(fp, "II(2-3)"), "uk")
    arrows, texts, leaders = _arrows_and_labels(rec)
    label_a = next(q for q in texts if q.text == "A")
    box = label_a.ink()
    centre = complex((box[0] + box[2]) / 2, (box[1] + box[3]) / 2)
    g2, phi2 = arrows["G2"], arrows["Φ2"]
    a = g2[0]
    start = cmath.phase(phi2[1] - a)                    # Φ2 up-left, G2 down: the sector between
    span = (cmath.phase(g2[1] - a) - start) % (2 * math.pi)
    assert span < math.pi
    assert not (cmath.phase(centre - a) - start) % (2 * math.pi) < span, "the letter A between Φ2 and G2"
    for q in texts:
        name = q.text.replace("_{", "").replace("}", "").replace("^{", "")
        if name not in arrows:
            continue
        box = q.ink()
        lead = [ld for ld in leaders if min(box_to_segment(box, p, p) for p in ld) < 1.0]
        if lead:
            p, r = lead[0]
            tip = p if box_to_segment(box, p, p) > box_to_segment(box, r, r) else r
            for other, seg in arrows.items():
                if other != name:
                    assert segment_gap(p, r, *seg) >= 1.0, (name, other)
            near = lambda seg, tip=tip: fd._to_segment(tip, *seg)         # noqa: E731
        else:
            near = lambda seg, box=box: box_to_segment(box, *seg)         # noqa: E731
        own = near(arrows[name])
        assert all(own < near(seg) for other, seg in arrows.items() if other != name), (name, own)


# -- own mechanism 51: a rocking block at the frame pivot O2 guiding the rod AB, whose end B drives a slider --

P1, P2 = 0j, 0.30 + 0j                  # the crank's pivot O1, the block's pivot O2
RA, LAB, LBC, YC = 0.10, 0.55, 0.32, 0.05
W_OWN = 120 * 2 * math.pi / 60          # counter-clockwise


@pytest.fixture(scope="module")
def own():
    from graphplan.exact import kinetostatics
    from graphplan.graphic import forceplans
    from review_scenes import ROCKING_BLOCK51
    st = scene_study(ROCKING_BLOCK51)
    return forceplans.construct(st, float(kinetostatics.at_scene_angle(st)), mu_l=0.004, mu_F=10.0,
                                group_mu={"I(0-1)": 0.002})


def _own_closed_form(own):
    """θ1 as drawn; the rod along A→O2 (through the block), B at 0.55 m from A, C on the guide y = 0.05
    to the right of B at 0.32 m from it."""
    pts = group_of(own, "I(0-1)").points
    theta0 = cmath.phase(pts["A"] - pts["O1"])

    def pos(t: float) -> dict[str, complex | float]:
        a = P1 + RA * cmath.exp(1j * (theta0 + W_OWN * t))
        u = (P2 - a) / abs(P2 - a)
        b = a + LAB * u
        c = complex(b.real + math.sqrt(LBC ** 2 - (YC - b.imag) ** 2), YC)
        return {"S1": a / 2, "S2": a + 0.5 * LAB * u, "O2": P2, "S4": (b + c) / 2, "C": c,
                "phi2": cmath.phase(u), "phi4": cmath.phase(c - b)}
    return pos


def test_own_balancing_moment_agrees_with_the_power_balance(own):
    """M_зр = −ΣP/ω1 of the closed form (the block turns with the rod: I3·ε2; 1500 N against the
    slider's motion on the working stroke): the exact within 0.1 %, the plans and the lever within 1.5 %."""
    pos = _own_closed_form(own)
    power = 0.0
    for key, m in {"S1": 2.5, "S2": 6.0, "S4": 3.0, "C": 8.0}.items():
        power += ((-1j * m * 9.81 - m * _d(pos, key, 2)).conjugate() * _d(pos, key, 1)).real
    for key, inertia in {"phi2": 0.15 + 0.002, "phi4": 0.03}.items():
        power += -inertia * _d(pos, key, 2).real * _d(pos, key, 1).real
    vc = _d(pos, "C", 1).real
    power += -1500.0 * math.copysign(1.0, vc) * vc
    closed = -power / W_OWN
    assert own.ks.balancing[0] == pytest.approx(closed, rel=1e-3)
    assert own.balancing == pytest.approx(closed, rel=0.015)
    assert own.lever.balancing == pytest.approx(closed, rel=0.015)


def test_own_block_acts_on_the_rod_normal_to_it_and_names_by_the_rule(own):
    """The block 3 (pivoted at O2) on the rod 2: normal to the rod within the ruler's 0.5 mm; the crank
    group loaded by R21, the rod's group by R42 (the connecting rod 4 on the rod 2 at B), equal and
    opposite to the outer group's R24."""
    p = _own_closed_form(own)(0.0)
    u = cmath.exp(1j * p["phi2"])
    s = {x.name: x.end - x.start for x in group_of(own, "II(2-3)").sides}
    inner = next(n for n in ("R32", "R23") if n in s)
    assert abs((s[inner] / u).real) <= 0.5 and abs(s[inner]) > 20.0
    names = {gp.label: {x.name for x in gp.sides} for gp in own.groups}
    assert "R21" in names["I(0-1)"] and "R42" in names["II(2-3)"] and "R24" in names["II(4-5)"]
    s45 = {x.name: x.end - x.start for x in group_of(own, "II(4-5)").sides}
    assert abs(s["R42"] + s45["R24"]) <= 1.0


def _lever_arms_checked(fp) -> int:
    """Each arm h drawn on the lever (a segment 'h_X = … mm to X' from the pole) ends on the line of
    X's own arrow, at right angles to it, its length the printed one (to the ruler's 0.5 mm)."""
    import re

    from graphplan.drawing import forces as fd
    rec = fd.lever_record(fp, "uk")
    arrows = {}
    for q in rec.items:
        if q.kind == "vector" and q.text and ": h = " in q.text:
            arrows[q.text.split(": h = ")[0]] = (complex(*q.points[0]), complex(*q.points[1]))
    pole = 0j                                   # the lever is drawn about its pole at the origin
    projections = [q for q in rec.items if q.kind == "segment" and q.role == "projection"]
    n = 0
    for q in rec.items:
        m = re.fullmatch(r"h_\{(.+)\} = ([0-9.]+) mm to (.+)", q.text or "")
        if q.kind != "segment" or m is None:
            continue
        name = m.group(3)
        a, b = complex(*q.points[0]), complex(*q.points[1])
        t, h = arrows[name]
        u = (h - t) / abs(h - t)
        foot = b if abs(b - pole) > abs(a - pole) else a
        off = abs(((foot - t) * u.conjugate()).imag)
        # on its line — or, an arrow set a lane aside from its point (M5' beside MΦ5' at d, the two on
        # one line; Φ4 beside the lever's line b–c), its line of action drawn thin to the foot
        drawn_line = any(abs(complex(*p.points[k]) - foot) < 0.3
                         and abs(((complex(*p.points[1 - k]) - foot) * u.conjugate()).imag) < 0.3
                         for p in projections for k in (0, 1))
        assert off < 0.3 or (off <= 2.6 and (drawn_line or min(abs(t - foot), abs(h - foot)) <= 2.6)), name
        assert abs(((foot - pole) * u.conjugate()).real) < 0.3, (name, "not at right angles")
        assert abs(abs(foot - pole) - float(m.group(2))) <= 0.5, name
        n += 1
    return n


@pytest.mark.slow
@pytest.mark.parametrize("which", ["fp", "own"])
def test_each_lever_arm_is_drawn_to_its_own_forces_line(which, request):
    """LINK51's lever and the own one's: every arm to its own force's line (one sheet drew h1 on Φ5's).
    Slow: drawing a lever takes about 2.5 s."""
    assert _lever_arms_checked(request.getfixturevalue(which)) >= 6
