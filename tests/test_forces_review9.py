"""The ninth review's force sheets (review 9 #5, #6, #8; review 8 #3): a tangential component the
moment equation gives negative is tabulated as its magnitude beside an arrow drawn in its true
sense (seed 000: "−R^t = … = 579,7 Н", the table 579,7), and the terminal says the minus; an arm
is never drawn along a drawn force's shaft; a set reads the groups in the analysis' order (the
outer first, the crank's last); M_зр's arc on the scheme clear of ω1's and of the arrows by the
pivot."""
from __future__ import annotations

import cmath
import math

import pytest

from conftest import scene_study
from review_scenes import ROCKER9

# review 9's pump (m1: a vertical offset crank-slider, crank clockwise) and loom (m2: a crank-rocker
# with a resistance moment on the rocker), their [sheet] and [dynamics] left out
PUMP = '''title = "Кривошипно-повзунний механізм насоса з вертикальною напрямною (рецензія 9)"
title_en = "Vertical offset crank-slider of a pump (review 9)"
lang = "en"
[params]
r = 0.055
l = 0.21
e = -0.018
[frame.points]
O = [0, 0]
[frame.guides]
y = { through = ["e", 0], angle_deg = 90, title_uk = "поршня", title_en = "of the piston" }
[crank]
name = "OA"
pivot = "O"
pin = "A"
length = "r"
rpm = 240
direction = "cw"
points = { S1 = 0.3 }
mass = 3.0
inertia = 0.004
[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = "l"
points = { S2 = 0.3 }
mass = 2.2
inertia = 0.011
[[link]]
name = "B"
number = 3
joints = ["B"]
slides_on = "y"
mass = 4.5
[branch]
B = 1
[positions]
count = 12
start = "working"
accel = [2, 7]
force_phi_deg = 75
working_stroke = "to_max"
[loads]
g = 9.81
[[force]]
point = "B"
magnitude = 2600
stroke = "working"
direction = "oppose"
profile = [[0, 0.1], [0.02, 1], [0.085, 1], [0.11, 0.1]]
'''

LOOM = ROCKER9      # review 9's crank-rocker loaded by a moment on its rocker (tests/review_scenes.py)


def _fp(text: str):
    from graphplan.sheets import forces as sf
    from graphplan.sheets.compose import SheetOptions
    return sf.ForceDrafter(scene_study(text), SheetOptions(precision=0.5, sheet="forces")).fp()


@pytest.fixture(scope="module")
def pump():
    return _fp(PUMP)


@pytest.fixture(scope="module")
def loom():
    return _fp(LOOM)


def _true_tangential(fp, gp, eq) -> complex:
    """The exact reaction found by ``eq`` (R12 on AB at A, R03 on O2B at O2) resolved across the
    link from its joint to the point the moments are taken about: its component perpendicular to
    that line, in N as a vector (the closed-form kinetostatics, not the plan)."""
    r = fp.ks.reactions[eq.unknown[:-1]]
    force = complex(r.force[0])
    at = complex(r.at[0]) / gp.mu_l
    u = (gp.points[eq.about] - at) / abs(gp.points[eq.about] - at)
    return force - u * (force * u.conjugate()).real


@pytest.mark.parametrize("scene", ["pump", "loom"])
def test_tangential_components_tabulated_as_magnitudes_arrows_in_their_true_sense(scene, request):
    """Review 9 #5: R^τ12 = −36,65 N (pump) and R^τ03 = −502,2 N (loom) were printed signed beside
    arrows drawn in their true sense. The table gives |R^τ| = the exact component across the link
    (within the ruler's ½ mm at μF); the drawn R^τ arrow points as the true component does; the
    terminal's equation keeps the solved sign and says what the minus means, its table |R^τ|."""
    from graphplan.drawing.forces import group_record, group_table_record
    from graphplan.report.forces import forces_table
    fp = request.getfixturevalue(scene)
    negatives = 0
    for gp in fp.groups:
        for eq in gp.equations:
            if not eq.unknown.endswith("τ"):
                continue
            key = eq.unknown[:-1]
            truth = _true_tangential(fp, gp, eq)
            negatives += eq.result < 0
            tol = 0.5 * gp.mu_F + 1e-6
            cells = [q.text for q in group_table_record(fp, gp, "en").items if q.kind == "text"]
            sym = "R^{τ}_{" + key[1:] + "}"
            width = cells.index("value, N (N·m)")
            value = cells[width + cells.index(sym)]
            assert "−" not in value and "-" not in value, value
            assert float(value) == pytest.approx(abs(truth), abs=tol)
            rec = group_record(fp, gp, "en")
            (t, h), = [(complex(*q.points[0]), complex(*q.points[1])) for q in rec.items
                       if q.kind == "vector" and q.text == eq.unknown]
            # drawn y up like the sheet's mm (the record's y axis is the model's): same sense
            assert ((h - t) * truth.conjugate()).real > 0.99 * abs(h - t) * abs(truth), (key, h - t, truth)
    assert negatives >= 1            # the review's case: the assumed sense came out reversed
    text = forces_table(fp, "en")
    assert "the minus:" in text and "acts opposite to the sense assumed" in text
    uk = forces_table(fp, "uk")
    assert "знак «−»" in uk and "спрямована протилежно прийнятому" in uk


def _run_on(a: complex, b: complex, c: complex, d: complex, tol: float = 0.6) -> float:
    """How long (mm) segment a→b runs within ``tol`` of segment c→d, nearly parallel (12°)."""
    u = (b - a) / abs(b - a)
    v = (d - c) / abs(d - c)
    if abs((u.conjugate() * v).imag) > math.sin(math.radians(12.0)):
        return 0.0
    n, hits = 60, 0
    for k in range(n + 1):
        z = a + (b - a) * k / n
        s = min(max(((z - c) * v.conjugate()).real, 0.0), abs(d - c))
        hits += abs(z - (c + s * v)) <= tol
    return abs(b - a) * max(0, hits - 1) / n


@pytest.mark.parametrize("scene", ["pump", "loom"])
def test_no_arm_is_drawn_along_a_drawn_force(scene, request):
    """Review 9 #6: the arm h_G2 ran from B along R03's arrow (its right-angle mark on R03's
    shaft). Every arm of every group and of the scheme runs less than 1 mm along any force's
    arrow drawn there, keeps its length and ends perpendicular on its force's line."""
    from graphplan.drawing.forces import group_record, mechanism_record
    fp = request.getfixturevalue(scene)
    recs = [group_record(fp, gp, "en") for gp in fp.groups] + [mechanism_record(fp, "en")]
    for rec in recs:
        arrows = [(complex(*q.points[0]), complex(*q.points[1]), q.text) for q in rec.items
                  if q.kind == "vector" and q.role != "head" and abs(complex(*q.points[1]) - complex(*q.points[0])) > 1.0]
        arms = [q for q in rec.items if q.kind == "segment" and q.text.startswith("h_{")]
        for arm in arms:
            a, b = (complex(*p) for p in arm.points)
            h = float(arm.text.split(" = ")[1].split(" mm")[0])
            assert abs(abs(b - a) - h) <= 0.25 + 1e-9        # as the ruler reads it
            for t, hd, name in arrows:
                assert _run_on(a, b, t, hd) < 1.0, (rec.title, arm.text, name)


def test_a_set_places_the_groups_in_the_analysis_order():
    """Review 9 #8: the pump's A2 set drew group I(0-1) left of group II(2-3) (the tall outer group
    set at the top right, the crank's under the plan in the middle). ``forceset.pack`` sets each
    group's unit wholly right of or under the group before it — and, here, on no more sheets."""
    from graphplan.drawing.layout import Leaf, Row
    from graphplan.sheets.forceset import pack
    region = (0.0, 0.0, 560.0, 400.0)
    units = [[Leaf("scheme 0", 150, 160)], [Leaf("acceleration 0", 170, 100)],
             [Row([Leaf("groups 0", 120, 270), Leaf("forces 0", 75, 270)])],
             [Row([Leaf("groups 1", 100, 160), Leaf("forces 1", 70, 160)])],
             [Leaf("lever 0", 150, 120)]]
    pages = pack(units, [], None, region, (560.0, 400.0, 560.0, 400.0), (560.0, 400.0, 560.0, 400.0))
    assert pages is not None and len(pages) == 1
    spots = {n.name: s for s in pages[0] for n in ([s.node] if isinstance(s.node, Leaf) else s.node.children)}
    outer, crank = spots["groups 0"], spots["groups 1"]
    assert crank.x >= outer.x + outer.w or crank.d >= outer.d + outer.h, (outer, crank)


def test_the_schemes_balancing_moment_reads_beside_omega(loom):
    """Review 8 #3: M_зр on the scheme was a 5 mm arc under G1's arrowhead. Drawn as on the crank's
    group: an arc of at least 9 mm about the crank's pivot, in M_b's sense, no arrow passing within
    1 mm of its arc, apart from ω1's arc (not one arc read as the other's continuation)."""
    from graphplan.drawing.forces import mechanism_record
    rec = mechanism_record(loom, "en")
    head, = [q for q in rec.items if q.kind == "vector" and q.text == "M_b"]
    tip_ = complex(*head.points[1])
    arc = next(q for q in rec.items if q.kind == "arc" and abs(abs(tip_ - complex(*q.points[0])) - q.radius) < 1e-6)
    centre = complex(*arc.points[0])
    r = arc.radius
    assert r >= 8.5
    tail, tip = complex(*head.points[0]), complex(*head.points[1])
    turning = ((tip - tail) * (tip - centre).conjugate()).imag          # > 0: counter-clockwise
    assert math.copysign(1.0, turning) == math.copysign(1.0, loom.balancing)
    m_mid = cmath.phase(0.5 * (tail + tip) - centre)
    omega = [q for q in rec.items if q.kind == "arc" and "ω1" in q.step]
    assert omega
    for q in omega:
        if abs(q.radius - r) < 2.0:       # at one radius: their spans apart, not one arc
            mid = math.radians(0.5 * (q.angles[0] + q.angles[1]))
            assert abs((mid - m_mid + math.pi) % (2 * math.pi) - math.pi) > math.radians(90.0)
    others = [(complex(*q.points[0]), complex(*q.points[1])) for q in rec.items
              if q.kind == "vector" and q.text and q.text != "M_b" and q.role != "head"]
    for a, b in others:
        for k in range(41):
            z = a + (b - a) * k / 40
            if abs(z - centre) > 1.0:
                off = abs((cmath.phase(z - centre) - m_mid + math.pi) % (2 * math.pi) - math.pi)
                assert abs(abs(z - centre) - r) > 1.0 or off > math.radians(45.0)
