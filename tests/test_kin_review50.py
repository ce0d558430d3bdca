"""Stop 50 (the lead's LINK50: a crank-rocker four-bar O1ABO2 whose rocker carries a pin C, at 0,24 m
along O2B; a stone 4 on C slides in the coulisse O3D rocking about O3 — I(0-1) → II(2-3) ВВВ →
II(4-5) ВПВ, the third kind driven by a rocker). The truth here is the closed-form mechanism, worked
out in this file alone: B the intersection of two circles, C = O2 + 0,24·(B − O2)/|B − O2|, the
coulisse's angle arg(C − O3) and s = |C − O3|, differentiated numerically; the rocker's extreme
positions where O1A and AB are collinear (O1B = l2 ± l1)."""
from __future__ import annotations

import cmath
import math

import pytest

from conftest import scene_study
from review_scenes import LINK50

O1, O2, O3 = 0j, 0.30 + 0.03j, 0.52 + 0.26j
L1, L2, L3, LC, L5 = 0.07, 0.28, 0.16, 0.24, 0.46
W1 = 75 * 2 * math.pi / 60                  # counter-clockwise


def _meet(p: complex, r1: float, q: complex, r2: float) -> complex:
    """The intersection of circles (p, r1), (q, r2) on the left of p → q (the scene's branch B = 1:
    B above the line O1O2... chosen so B lies above, as drawn)."""
    d = abs(q - p)
    a = (r1 * r1 - r2 * r2 + d * d) / (2 * d)
    h = math.sqrt(max(r1 * r1 - a * a, 0.0))
    e = (q - p) / d
    return p + a * e + 1j * e * h


def _state(th: float) -> dict[str, float | complex]:
    """The closed-form position at the crank's angle θ (from the x axis)."""
    a = O1 + L1 * cmath.exp(1j * th)
    b = _meet(a, L2, O2, L3)
    c = O2 + LC * (b - O2) / L3
    return {"A": a, "B": b, "C": c, "th5": cmath.phase(c - O3), "s": abs(c - O3),
            "th2": cmath.phase(b - a), "th3": cmath.phase(b - O2)}


def _rates(th: float, h: float = 1e-5) -> dict[str, float]:
    """ω2, ω3, ω5 (+ ccw), ds/dt of the stone along the coulisse, and their time derivatives."""
    f = {k: [_state(th + j * h)[k] for j in (-1, 0, 1)] for k in ("th2", "th3", "th5", "s")}
    out = {}
    for k, (m, z, p) in f.items():
        out["d" + k] = (p - m) / (2 * h) * W1
        out["dd" + k] = (p - 2 * z + m) / (h * h) * W1 * W1
    return out


def _start() -> float:
    """Position 0: the crank's angle where O1B = l1 + l2 (the rocker's extreme at the start of the
    working stroke — the coulisse at its smallest angle, as checked below)."""
    b = _meet(O1, L1 + L2, O2, L3)
    return cmath.phase(b - O1)


@pytest.fixture(scope="module")
def plans():
    from graphplan.graphic.plans import build_plans
    return build_plans(scene_study(LINK50), count=12, accel=[3], precision=0.5)


@pytest.fixture(scope="module")
def doc(plans):
    from graphplan.report.plans import plans_json
    return plans_json(plans)


def test_table_1_names_the_coulisse_omega_beside_the_stones(doc):
    """Table 1 held one column ω4 (the stone's) and dropped ω5 as its equal, while the diagrams and
    Table 4 read ω5 of the coulisse O3D: the column is headed ω4 = ω5, and its values are the
    closed-form ω5 within the plans' accuracy (the ruler's half division on the vector read)."""
    from graphplan.sheets.kintables import velocity_table, velocity_twins
    from graphplan.util.markup import plain
    twins = velocity_twins(doc, 0.5)
    assert twins == {"omega_4": ["omega_O3D"]}
    rec = velocity_table(doc, "uk")
    heads = [plain(i.text) for i in rec.items if i.kind == "text"]
    assert "ω₄ = ω₅" in heads, heads
    th0 = _start()
    for pos in doc["positions"]:
        e = pos["velocity"]["omega_4"]
        value = (e["value"] or 0.0) * (-1 if e.get("sense") == "cw" else 1)
        w5 = _rates(th0 + math.radians(30 * pos["index"]))["dth5"]
        # ω5 = v_C5 / l_O3C: half a division (0.5 mm × μv 0.01) on the vector it is read from
        tol = 0.5 * 0.01 / _state(th0 + math.radians(30 * pos["index"]))["s"] + 0.01
        assert value == pytest.approx(w5, abs=tol), pos["index"]


def test_the_swing_and_position_0_agree_with_the_collinear_extremes(plans):
    """ψ_max between D′ and D″ equals the closed-form angle between the coulisse's directions at
    the rocker's two extremes (O1B = l2 + l1 and l2 − l1): 14,71°; position 0 is the first, the crank
    at 32,9°; the coulisse's angle over a fine turn has no extreme elsewhere."""
    from graphplan.drawing.plans import swing
    th_a = _start()
    b = _meet(O1, L2 - L1, O2, L3)
    th_b = cmath.phase(b - O1) + math.pi
    turn = lambda th: cmath.phase((_state(th)["C"] - O3) / (_state(th_a)["C"] - O3))   # noqa: E731  (ψ5, no wrap)
    psi = abs(math.degrees(turn(th_b)))
    assert swing(plans) == pytest.approx(psi, abs=0.01)
    assert psi == pytest.approx(14.705, abs=0.005)
    assert plans.positions[0].phi % 360 == pytest.approx(math.degrees(th_a) % 360, abs=0.05)
    fine = [turn(th_a + math.radians(k / 4)) for k in range(0, 1441)]
    assert min(fine) == pytest.approx(0.0, abs=1e-9)
    assert max(fine) == pytest.approx(turn(th_b), abs=1e-5)


def test_coriolis_of_the_coulisse_on_the_stone(plans):
    """a^k_C5C4 = 2·ω4·v_C5C4 (ω4 = ω5), drawn as v_C5C4 turned 90° in ω5's sense (the rule): at
    position 3 the closed form gives ω5 = +1,066 rad/s (ccw), v_C5C4 = −ds/dt = 0,734 m/s from C
    toward O3's side, |a^k| = 1,564 m/s²; the plan's vector within the ruler's half division × μa and
    within 2° of that direction. a^r_C5C4 lies along the coulisse, a_C5 = ε5·l ⊥ + ω5²·l toward O3."""
    q = plans.positions[3]
    th = _start() + math.radians(90)
    st, r = _state(th), _rates(th)
    u = (st["C"] - O3) / st["s"]                 # along the coulisse, O3 → C
    v_rel = -r["ds"] * u                         # v_C5C4 = v_C5 − v_C4: minus the stone's slide
    cor = 2 * r["dth5"] * 1j * v_rel             # 2 ω × v, ω ccw: +90°
    e = q.acceleration.entries["k_C5C4"]
    mu = plans.mu_a
    assert abs(e.vector) == pytest.approx(abs(cor), abs=0.5 * mu + 0.01)
    assert abs(math.degrees(cmath.phase(e.vector / cor))) < 2.0
    rel = q.acceleration.entries["r_C5C4"]
    assert abs(math.sin(cmath.phase(rel.vector / u))) < 0.03
    assert abs(rel.vector) == pytest.approx(abs(r["dds"]), abs=0.5 * mu + 0.02)    # s̈: the slide's own
    eps5 = q.acceleration.entries["epsilon_O3D"]
    assert eps5.value * (1 if eps5.sense == "ccw" else -1) == pytest.approx(r["ddth5"], abs=0.1)


# -- LINK48's A1: the s diagram at the series' finer μs ----------------------------------------------

def test_a_low_s_diagram_is_fitted_to_its_allowance_not_drawn_flat():
    """LINK48 (a V-compressor, crank r = 0.05 m, rods 0.2 m, the left piston on a 45° guide through
    O): the standard μs 0,002 drew its 0.1-m stroke 50 mm high under an 80-mm allowance, its first
    a diagram wrong, and the redrawing took H1 15 mm: v and a 10 and 12 mm high. Then μs = s_max/h
    to two figures, 0,0013 m/mm; now (kin61b, review 61 #2: a student takes a series value) the
    series' next finer value 0,001 m/mm (0.1/80 = 0.00125), the s diagram 100 mm high, the v and a
    diagrams at least 20 mm high, and the drawn v at the middles and s at
    the ordinates within the lab's 5 % (of the cycle's largest) of the closed-form piston:
    x(θ) = r·cos(θ−45°) + √(l² − r²·sin²(θ−45°)) along the guide, s = x_max − x."""
    from graphplan.graphic.diagrams import chord_diagrams
    from graphplan.sheets.form import form
    from graphplan.sheets.kinematics import diagram_options
    from graphplan.sheets.kinlayout import room
    from review_scenes import LINK48
    st = scene_study(LINK48)
    opts = diagram_options(st, 1.0, None, 0.5, room(form("A1")), 0.0)
    assert opts.get("fit") is True and opts["redrawn"].right
    d = chord_diagrams(st, precision=0.5, **opts)
    r, ln, w = 0.05, 0.2, 960 * 2 * math.pi / 60
    stroke = 2 * r
    assert d.mu_s == pytest.approx(0.001)         # the series 1, 2, 2.5, 4, 5 × 10^k: 0,002 draws 50 mm
    assert opts["height"] < stroke / d.mu_s < 2 * opts["height"]
    assert min(abs(d.drawn.v).max(), abs(d.drawn.a).max()) >= 20.0

    def x(th):
        u = th - math.pi / 4
        return r * math.cos(u) + math.sqrt(ln * ln - (r * math.sin(u)) ** 2)
    phi = [math.radians(p) for p in d.phi]
    s_true = [abs(x(math.pi / 4) - x(p)) for p in phi]          # from the outer dead centre
    assert max(abs(abs(s) * d.mu_s - t) for s, t in zip(d.drawn.s, s_true)) <= 0.05 * stroke
    h = 1e-6
    v_true = [abs((x(math.radians(p) + h) - x(math.radians(p) - h)) / (2 * h) * w) for p in d.phi_mid]
    v_max = max(abs((x(k * math.pi / 180 + h) - x(k * math.pi / 180 - h)) / (2 * h) * w) for k in range(360))
    assert max(abs(abs(v) * d.mu_v - t) for v, t in zip(d.drawn.v, v_true)) <= 0.05 * v_max


# -- kin50's own: a slider on a 30° guide driven through a rod from a coupler point ---------------

G0, GD = 0.10 + 0.30j, cmath.exp(1j * math.radians(30))
E_LOCAL = 0.15 + 0.10j


def _own(th: float) -> dict[str, complex]:
    """The closed form of OWN_SLIDER50: B from two circles (O1A 0.08, AB 0.30, O2B 0.20), E fixed on
    the coupler (0.15 along AB, 0.10 to its left), F on the guide G0 + t·GD with |F − E| = 0.26 (the
    root farther along the guide, as the scene's branch F = 1 draws it)."""
    o2 = 0.32 - 0.04j
    a = 0.08 * cmath.exp(1j * th)
    b = _meet(a, 0.30, o2, 0.20)
    e = a + E_LOCAL * (b - a) / 0.30
    d = e - G0
    k = (d * GD.conjugate()).real
    t = k + math.sqrt(k * k - abs(d) ** 2 + 0.26 ** 2)
    return {"A": a, "B": b, "E": e, "F": G0 + t * GD, "t": t}


@pytest.fixture(scope="module")
def own_plans():
    from graphplan.graphic.plans import build_plans
    from review_scenes import OWN_SLIDER50
    return build_plans(scene_study(OWN_SLIDER50), count=12, accel=[4], precision=0.5)


def test_own_stroke_and_coupler_point_acceleration(own_plans):
    """The slider's extreme positions F′, F″ are the closed form's: the stroke along the guide
    0,1863 m (the sheet's H = 186,3); on the acceleration plan of position 4 the coupler point's
    a_E is the rigid body's a_A + (a_B − a_A)·(E − A)/(B − A) (the similar triangle abe), and a_F the
    closed form's second derivative — each within a few ruler halves × μa."""
    from graphplan.drawing.plans import stroke_ends
    w1 = -120 * 2 * math.pi / 60
    ts = [_own(math.radians(k / 10))["t"] for k in range(3600)]
    stroke = max(ts) - min(ts)
    assert stroke == pytest.approx(0.18631, abs=2e-5)
    sc = own_plans.scheme
    from graphplan.graphic.position_plan import where as at
    ends = stroke_ends(own_plans)
    f1, f2 = (at(sc, lay, sc.body_of("F"), "F") for lay in ends)
    assert abs(f2 - f1) * own_plans.mu_l == pytest.approx(stroke, abs=1e-4)    # drawn mm × μl
    q = own_plans.positions[4]
    th = math.radians(q.phi)
    h = 1e-5
    acc = {k: (_own(th + h)[k] - 2 * _own(th)[k] + _own(th - h)[k]) / (h * h) * w1 * w1 for k in "ABEF"}
    got = {k: q.acceleration.entries[k].vector for k in "ABEF"}
    mu = own_plans.mu_a
    z = _own(th)
    rigid = got["A"] + (got["B"] - got["A"]) * (z["E"] - z["A"]) / (z["B"] - z["A"])
    assert abs(got["E"] - rigid) <= 1.0 * mu          # the similar triangle, to a ruler division
    for k in "ABEF":
        assert abs(got[k] - acc[k]) <= 3 * 0.5 * mu + 0.01 * abs(acc[k]), k


def test_the_stones_pin_c_is_numbered_at_every_position(plans):
    """Stone 4 rides on the rocker's pin C (not the crank pin): its positions on C's arc (the closed
    form's circle of radius l_O2C about O2) are dotted and, as every traced joint's, numbered — a
    number read as a reader reads it, the numbered point nearest its ink or its leader's end, is C at
    its own position (stop 50: the arc's twelve dots bare)."""
    from test_position_numbers import _gap
    from graphplan.drawing.plans import position_record
    from graphplan.graphic.plans import where
    sc = plans.scheme
    rec = position_record(plans)
    at = {(str(p.index), n): where(sc, p.layout, sc.body_of(n), n) for p in plans.positions for n in "ABCD"}
    o2 = where(sc, plans.positions[0].layout, sc.body_of("O2"), "O2")
    for p in plans.positions:                               # C on its arc: |O2C| = 0.24 m at μ_l
        assert abs(at[str(p.index), "C"] - o2) == pytest.approx(LC / plans.mu_l, abs=0.05)
    leaders = [[complex(*e) for e in q.points] for q in rec.items if q.kind == "segment" and q.role == "label"]
    read = set()
    for q in rec.items:
        if q.kind != "text" or q.size > 3.0 or not q.text.isdigit():
            continue
        box = q.ink()
        ends = [e for a, b in leaders for e, f in ((a, b), (b, a)) if _gap(box, f) < 1.2 and _gap(box, e) >= 1.2]
        spot = (lambda z: abs(z - ends[0])) if ends else (lambda z: _gap(box, z))      # noqa: E731
        read.add(min(at, key=lambda k: spot(at[k])))
    thick = {str(p.index) for p in plans.positions if p.layout.key in (set(plans.accel_keys) or {0})}
    missing = [str(p.index) for p in plans.positions if (str(p.index), "C") not in read and str(p.index) not in thick]
    assert not missing, missing                             # the thick position's C is lettered, its 3 beside
