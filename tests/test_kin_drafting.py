"""Drafting on the position plan and the force scheme (the second review's corrections 12, 13):
the crank's support stands clear of the crank and of ω1's arc; the stroke's dimension H runs past
the drawing, not through the rods; a link's number stands by its bar; the Coriolis end is lettered
k; a scale of two figures where it draws p_v a 40 mm on the ruler; a slider's force set beside its
guide crosses no link. Checked by plain geometry written here (segments meeting, distances)."""
from __future__ import annotations

import cmath
import math

import pytest

from conftest import example, scene_study

SLOTTER = '''
[synthesis]
type = "quick_return"
K = 1.5
stroke = 0.35
centre_distance = 0.36

[params]
X = 0.50
lambda1 = 0.5
rod = "lambda1 * rocker"

[frame.points]
O = [0, 0]
O1 = [0, "centre_distance"]

[frame.guides]
ram = { through = [0, "X"], angle_deg = 0 }

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = "crank"
rpm = 120
direction = "cw"
points = { S1 = 0.5 }

[[link]]
name = "2"
number = 2
joints = ["A"]
slides_on = "OB"
mass = 3

[[link]]
name = "OB"
number = 3
joints = ["O", "B"]
length = "rocker"
points = { S3 = 0.5 }

[[link]]
name = "BC"
number = 4
joints = ["B", "C"]
length = "rod"
points = { S4 = 0.5 }

[[link]]
name = "C"
number = 5
joints = ["C"]
slides_on = "ram"
mass = 25

[branch]
A = 1
C = 1

[positions]
count = 12
start = "idle"
accel = [3]
force_phi_deg = 90

[loads]
g = 9.81
mass_per_length = 100
inertia_factor = 0.1

[[force]]
point = "C"
magnitude = 3200
stroke = "working"
direction = "oppose"
profile = [[0, 0], [0.03, 1], [0.32, 1], [0.35, 0]]
'''


def _cross(p: complex, q: complex) -> float:
    return p.real * q.imag - p.imag * q.real


def meet(a: complex, b: complex, c: complex, d: complex, spare: float = 0.3) -> bool:
    """Whether the segments a–b and c–d cross, not counting a touch within ``spare`` mm of a–b's ends."""
    u, w = b - a, d - c
    den = _cross(u, w)
    if abs(den) < 1e-12 or abs(u) < 1e-9:
        return False
    t, v = _cross(c - a, w) / den, _cross(c - a, u) / den
    return spare / abs(u) < t < 1 - spare / abs(u) and 0.0 <= v <= 1.0


def dist(z: complex, a: complex, b: complex) -> float:
    d = b - a
    t = 0.0 if abs(d) < 1e-12 else min(max(((z - a) * d.conjugate()).real / abs(d) ** 2, 0.0), 1.0)
    return abs(z - (a + t * d))


def segments(rec, keep):
    out = []
    for p in rec.items:
        if p.kind in ("segment", "polyline", "vector") and keep(p):
            pts = [complex(x, y) for x, y in p.points]
            out += list(zip(pts, pts[1:]))
    return out


def _position(st):
    from graphplan.drawing.plans import position_record
    from graphplan.graphic.plans import build_plans
    plans = build_plans(st, precision=0.5)
    return plans, position_record(plans)


@pytest.mark.parametrize("scene", ["review four-bar", "crank_slider", "shaper"])
def test_the_cranks_support_clear_of_the_crank_and_omega(scene):
    """The O1 support's bar and hatching were drawn across the crank (the review's four-bar) and ω1's
    arc across the support (the crank-slider's 200°–290° arc over a support standing straight down)."""
    from graphplan.graphic.plans import where
    from test_link_points import FOURBAR
    st = scene_study(FOURBAR) if scene == "review four-bar" else example(scene)
    plans, rec = _position(st)
    sc = plans.scheme
    from graphplan.model.mechanism import FRAME
    O = where(sc, plans.positions[0].layout, FRAME, st.mech.crank.pivot)
    thick = set(plans.accel_keys) or {0}
    cranks = [(O, where(sc, p.layout, st.mech.crank.link, st.mech.crank.pin)) for p in plans.positions if p.key in thick]
    support = [(a, b) for a, b in segments(rec, lambda p: p.layer == "frame" and p.role in ("frame", "hatch"))
               if abs(a - O) < 12 and abs(b - O) < 12]
    assert len(support) >= 8
    for a, b in support:
        for c, d in cranks:                    # the leg from the pivot itself touches the crank at O1
            assert not meet(c, d, a, b, spare=0.6), (scene, a, b)
    arc = next(p for p in rec.items if p.kind == "arc" and "ω1" in p.step)
    (cx, cy), r = arc.points[0], arc.radius
    samples = [complex(cx, cy) + r * cmath.exp(1j * math.radians(arc.angles[0] + (arc.angles[1] - arc.angles[0]) * k / 40))
               for k in range(41)]
    for a, b in support:
        assert min(dist(z, a, b) for z in samples) > 0.5, (scene, "ω1 over the support")
    for c, d in cranks:
        assert min(dist(z, c, d) for z in samples) > 0.5, (scene, "ω1 over the crank")


@pytest.fixture(scope="module")
def slotter():
    st = scene_study(SLOTTER)
    plans, rec = _position(st)
    return st, plans, rec


def test_the_stroke_dimension_runs_clear_of_the_drawing(slotter):
    """H = 350 ran through the rods' lines above the guide: now its dimension line crosses no line
    of the mechanism's positions, their trajectories or arcs, and it measures the stroke."""
    st, plans, rec = slotter
    dim = [(a, b) for a, b in segments(rec, lambda p: p.step == "dimensions" and p.kind == "vector")]
    assert len(dim) == 2
    (m, a), (_, b) = dim
    assert abs(abs(b - a) * plans.mu_l - 0.35) < 1e-6          # the stroke H = 0.35 m, drawn
    lines = segments(rec, lambda p: p.layer in ("mechanism", "construction") and p.step != "dimensions")
    for s, e in lines:
        assert not meet(a, b, s, e, spare=0.0), (s, e)


def test_a_links_number_stands_by_its_bar(slotter):
    """The rod BC's "4" stood 9 mm below the rod, at the guide's end beside position number 5."""
    from graphplan.graphic.plans import where
    st, plans, rec = slotter
    lay = next(p.layout for p in plans.positions if p.key in (set(plans.accel_keys) or {0}))
    sc = plans.scheme
    B, C = where(sc, lay, "BC", "B"), where(sc, lay, "BC", "C")
    four = [p for p in rec.items if p.kind == "text" and p.text == "4" and p.size >= 5.0]
    assert len(four) == 1
    x0, y0, x1, y1 = four[0].ink()
    gap = min(abs(complex(max(x0 - z.real, 0.0, z.real - x1), max(y0 - z.imag, 0.0, z.imag - y1)))
              for z in (B + (C - B) * k / 200 for k in range(201)))
    assert gap < 5.0, gap


def test_the_coriolis_end_is_k():
    """REFERENCE §1: the Coriolis end is lettered k (the sheets wrote k1)."""
    from graphplan.drawing.plans import acceleration_records
    from graphplan.graphic.plans import build_plans
    recs = acceleration_records(build_plans(example("shaper"), precision=0.5, count=4))
    for rec in recs.values():
        texts = [p.text for p in rec.items if p.kind == "text"]
        assert "k" in texts and not any(t.startswith("k_") for t in texts), texts


@pytest.mark.parametrize("value, length, mu", [(1.3979599, 40.0, 0.035), (0.7539822, 40.0, 0.0188),
                                               (2.4, 60.0, 0.04), (0.9, 40.0, 0.0225)])
def test_a_two_figure_scale_where_the_ruler_reads_the_length(value, length, mu):
    """v_A = 1.398 m/s at 40 mm: 0.035 draws 39.94 mm, read 40.0 on the 0.5-mm ruler — the lab's μv,
    not 0.0349; the six-bar's 0.754 m/s keeps 0.0188 (0.019 draws 39.68, read 39.5)."""
    from graphplan.graphic.scales import LEGIBLE_READS, chosen_length
    got = chosen_length(value, length, LEGIBLE_READS)
    assert got == mu
    assert length - 0.25 <= value / got < length * 1.01
    assert round(value / got / 0.5) * 0.5 >= length          # what the ruler reads


@pytest.mark.slow
def test_a_sliders_force_beside_its_guide_crosses_no_link():
    """Φ5 at the slider C, set beside its guide, ran across the rod BC coming down to C."""
    from graphplan.sheets import forces as sf
    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.form import form
    st = scene_study(SLOTTER)
    p, _, dr = sf.plan(st, form("A1"), SheetOptions(precision=0.5, sheet="forces"))
    scheme = dr.drawings(p.mu, "uk")["scheme"][0]
    links = segments(scheme, lambda q: q.role == "link" and q.layer == "mechanism")
    arrows = [q for q in scheme.items if q.kind == "vector" and q.text == "Φ5"]
    assert len(arrows) == 1
    a, b = (complex(x, y) for x, y in arrows[0].points)
    for s, e in links:
        assert not meet(a, b, s, e), (s, e)


def test_crowded_plan_points_are_lettered_unambiguously():
    """The four-bar's velocity plan 8 put a, b and s2 within 4 mm, "b" nearer a than b. Now every
    letter of a point with another within 4 mm stands at most half as far from its own point as
    from any other, or hangs on a leader starting at its own point."""
    from graphplan.drawing.plans import velocity_records
    from graphplan.graphic.plans import build_plans
    from test_link_points import FOURBAR
    plans = build_plans(scene_study(FOURBAR), precision=0.5, mu_l=0.002, mu_v=0.015)
    recs = velocity_records(plans)
    crowded = 0
    for p in plans.positions:
        rec = recs[p.key]
        asked = p.velocity.labels
        leaders = [complex(*q.points[0]) for q in rec.items if q.kind == "segment" and q.role == "label"]
        for req in asked:
            others = [r.at for r in asked if abs(r.at - req.at) > 1e-9]
            if not any(abs(z - req.at) < 4.0 for z in others):
                continue
            crowded += 1
            text = next(q for q in rec.items if q.kind == "text" and q.text == req.text)
            box = text.ink()

            def gap(z: complex) -> float:
                return abs(complex(max(box[0] - z.real, 0.0, z.real - box[2]), max(box[1] - z.imag, 0.0, z.imag - box[3])))
            hung = any(abs(s - req.at) < 1.5 for s in leaders)
            assert hung or all(gap(z) >= 2.0 * gap(req.at) for z in others), (p.index, req.text)
    assert crowded >= 3                                   # plan 8's a, b, s2 at least


INCLINED = """
title = "Кривошипно-повзунний механізм з похилою напрямною"
[params]
r = 0.065
l = 0.26
[frame.points]
O = [0, 0]
[frame.guides]
piston = { through = [-0.025, 0], angle_deg = 150 }
[crank]
name = "OA"
pivot = "O"
pin = "A"
length = "r"
rpm = 240
direction = "ccw"
[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = "l"
[[link]]
name = "B"
number = 3
joints = ["B"]
slides_on = "piston"
[branch]
B = 1
[positions]
count = 12
"""


@pytest.mark.parametrize("lang, text", [("uk", "e = 12,5 мм"), ("en", "e = 12.5 mm")])
def test_the_offset_is_lettered_with_its_real_size(lang, text):
    """A guide through (−25, 0) mm at 150° passes 25·sin 30° = 12.5 mm from O: the scheme letters
    e = 12,5 (Table 4's value), not a rounded "12"; a whole stroke keeps whole millimetres."""
    from graphplan.drawing.plans import position_record
    from graphplan.graphic.plans import build_plans
    st = scene_study(INCLINED)
    plans = build_plans(st, mu_l=0.001)
    words = [p.text for p in position_record(plans, lang=lang).items if p.kind == "text"]
    assert text in words
    H = float(next(w for w in words if w.startswith("H = ")).split()[2].replace(",", "."))
    r, l, e = 65.0, 260.0, 12.5                   # mm at μl = 0.001 m/mm
    assert abs(H - (math.sqrt((l + r) ** 2 - e ** 2) - math.sqrt((l - r) ** 2 - e ** 2))) <= 0.05
