"""The third review's force sheet of a loom's four-bar with a resistance moment on the rocker
(review3, items 2, 5, 7, 10, 11): the rocker's angle named φ3 on the resistance chart, the balancing
moment's chart at a round μφ with its ordinate valued up to the peak, the lever's pole lettered with
the fixed pivots' images, the group drawn freed from the frame, the hodographs' jump marked."""
from __future__ import annotations

import math

import numpy as np
import pytest

from conftest import example, scene_study
from test_moment_load import scene


LOOM = '''# review3's loom: a four-bar driving a batten, a resistance moment on the rocker
title = "Шарнірний чотириланковий механізм батана"
title_en = "Four-bar linkage of a loom batten"
designation = "ТММ.КП.08.000"
lang = "uk"

[sheet]
student = "Рецензент"
teacher = "Викладач"
group = "МБ-41"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]
O2 = [0.42, 0.05]

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.12
rpm = 150
points = { S1 = 0.5 }

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.40
points = { S2 = 0.5 }

[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = 0.28
points = { S3 = 0.5 }

[branch]
B = 1

[positions]
count = 12
start = "max"
accel = [2]
force_phi_deg = 240

[loads]
g = 9.81
mass_per_length = 40
inertia_factor = 0.1

[[moment]]
link = 3
magnitude = 150
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.05
synchronous_rpm = 1000
'''


@pytest.fixture(scope="module")
def loom_a1():
    """The loom's A1 force sheet: its plan and drawings."""
    from conftest import scene_plan, shared
    p, nat, dr = scene_plan(LOOM, "forces", "A1", precision=0.5)
    return scene_study(LOOM), p, dr, shared("test_forces_review3.loom_a1", lambda: dr.drawings(p.mu, "uk"))


@pytest.fixture(scope="module")
def rocker():
    return scene_study(scene("3", "oppose").replace('stroke = "both"', 'stroke = "working"'))


@pytest.fixture(scope="module")
def rocker_turn(rocker):
    from graphplan.drawing.charts import turn
    return turn(rocker)


def _texts(rec) -> list[str]:
    return [p.text for p in rec.items if p.kind == "text"]


def test_the_resistance_charts_positions_read_in_one_row(rocker_turn):
    """Review 12 #18: by a rocker's extremes the path hardly grows, and 0/1, 6/7, 11/12 were split
    over two rows above the degree scale. Now one row: every position's number at one height, each
    3 mm of paper from the next (the font's ink), at its tick or set aside on a leader from that
    very tick, within 4 mm of it."""
    from graphplan.drawing.charts import resistance_record
    from graphplan.graphic.record import Primitive
    t = rocker_turn
    rec = resistance_record(t, lang="uk")
    count = t.ks.st.mech.task.count
    nums = [q for q in rec.items if q.kind == "text" and q.text.isdigit() and q.points[0][1] < 0
            and q.anchor == "middle" and int(q.text) <= count]
    rows = sorted({round(q.points[0][1], 6) for q in nums})
    top = [q for q in nums if round(q.points[0][1], 6) == rows[-1]]
    assert sorted(int(q.text) for q in top) == list(range(count + 1))        # 0 … 12 in the top row
    ticks = {x for q in rec.items if q.kind == "segment" and q.layer == "diagrams"
             for (x, y0), (_, y1) in [q.points] if y0 == -1.5 and y1 == 1.5}
    leaders = [q.points for q in rec.items if q.kind == "segment" and q.layer == "labels"]
    boxes = []
    for q in sorted(top, key=lambda q: q.points[0][0]):
        x = q.points[0][0]
        ink = Primitive("text", ((x, 0.0),), text=q.text, size=q.size, anchor="middle").ink()
        boxes.append((ink[0], ink[2]))
        tick = next((a[0] for a, b in leaders if abs(b[0] - x) < 2.0 and 0 < b[1] - q.points[0][1] < 4.5), x)
        assert min(abs(tick - s) for s in ticks) < 1e-6 and abs(tick - x) < 4.0, q.text   # at its tick, or led
    # 3 mm of paper between two numbers (labels.NUMBERS_APART: "11 12" closer reads "1112")
    assert all(b[0] - a[1] >= 3.0 - 1e-6 for a, b in zip(boxes, boxes[1:])), boxes
    assert leaders                      # this rocker's 11 and 12 (and 0, 1) crowd: some set aside


@pytest.mark.parametrize("xs, halves", [([0.0, 0.9, 5.0, 10.0, 10.5, 30.0, 30.3], [0.7] * 7),
                                        ([3.0, 1.0, 2.0], [1.5, 0.5, 0.5]), ([0.0, 20.0], [1.0, 1.0])])
def test_numbers_crowding_in_a_row_are_set_apart_about_their_places(xs, halves):
    """Each number as near its place as its neighbours leave it: apart by 1 mm of paper at least,
    in their order, a run of crowding numbers centred on their places' mean; alone, at its place."""
    from graphplan.drawing.charts import spread_apart
    at = spread_apart(xs, halves, 1.0)
    order = sorted(range(len(xs)), key=lambda i: xs[i])
    for i, j in zip(order, order[1:]):
        assert at[j] - at[i] >= halves[i] + halves[j] + 1.0 - 1e-9
    for i in order:
        alone = all(abs(xs[i] - xs[j]) >= halves[i] + halves[j] + 1.0 for j in order if j != i)
        assert not alone or at[i] == pytest.approx(xs[i])


def test_a_rockers_resistance_chart_names_its_angle_psi3(rocker_turn):
    """"s, °" and μ_s named the rocker's angle: a rocking output's path is ψ3 with μ_ψ, the
    textbook's letter for a rocker's angle as the kinematics sheet writes it (review 12 #18: φ5); a
    slider's stays s with μ_s."""
    from graphplan.drawing.charts import resistance_record, turn
    texts = _texts(resistance_record(rocker_turn, lang="en"))
    assert "ψ_{3}, °" in texts
    assert not any(t.startswith("s,") or "μ_s" in t or "φ" in t for t in texts), texts
    assert any("μ_ψ = " in t and "ψ_{3}" in t for t in texts), texts
    slider = _texts(resistance_record(turn(example("shaper")), lang="en"))
    assert any(t.startswith("s, ") for t in slider) and any("μ_s = " in t for t in slider)
    assert not any("μ_ψ" in t for t in slider)


ROUND = {1.0, 1.5, 2.0, 2.5, 4.0, 5.0, 7.5}


def _mantissa(v: float) -> float:
    return round(v / 10.0 ** math.floor(math.log10(v) + 1e-12), 9)


@pytest.mark.parametrize("width", [252.0, 180.0, 160.0, 300.0, 110.0, 115.0, 130.0])
def test_the_balancing_moment_chart_takes_a_round_mu_phi_and_values_its_axis(rocker_turn, width):
    """μφ = 1.786 °/mm was no series value and the M axis read only 0 and 40 under a peak of 83:
    μφ is the finest round value whose turn fits the length (the crusher's 3.273 °/mm = 360°/110 mm,
    stop 54, was none: 4 °/mm, 90 mm), and the ordinate's values at one round step, each at its
    tick's height times μM, reach past the exact peak and below the trough."""
    from graphplan.drawing.charts import moment_record
    rec = moment_record(rocker_turn, width, 70.0, "en")
    mu_phi, mu = rec.scales["mu_phi"], rec.scales["mu_M"]
    assert _mantissa(mu_phi) in ROUND, mu_phi
    assert 360.0 / mu_phi <= width + 1e-9
    finer = max(m * 10.0 ** k for m in ROUND for k in range(-2, 3) if m * 10.0 ** k < mu_phi - 1e-9)
    assert 360.0 / finer > width, (mu_phi, finer)          # the finest that fits
    curve = next(p for p in rec.items if p.kind == "polyline")
    assert max(x for x, _ in curve.points) == pytest.approx(360.0 / mu_phi)
    values = sorted((float(p.text.replace("−", "-")), p.points[0][1] + 1.2) for p in rec.items
                    if p.kind == "text" and p.anchor == "end")
    assert len(values) >= 4, values
    for v, y in values:
        assert y * mu == pytest.approx(v, abs=1e-9)
    steps = {round(b[0] - a[0], 9) for a, b in zip(values, values[1:])}
    assert len(steps) == 1 and _mantissa(steps.pop()) in {1.0, 2.0, 5.0}
    m = rocker_turn.ks.balancing
    assert values[-1][0] >= m.max() - 1e-9 and values[0][0] <= min(0.0, m.min()) + 1e-9


def _gap(a, b) -> float:
    (ax0, ay0, ax1, ay1), (bx0, by0, bx1, by1) = a.bounds(), b.bounds()
    return max(ax0 - bx1, bx0 - ax1, ay0 - by1, by0 - ay1, 0.0)


def test_the_levers_pole_names_the_fixed_pivots_and_its_labels_stand_apart(loom_a1):
    """The pole read p_v alone though o1 and o2 (where M3'' acts) are there; the names of the
    forces at a, s2 and b stood 1.5 mm apart: the pole is "p_v, o1, o2" — every image drawn at
    the pole, the pivots' images having no velocity — and no two labels closer than the force's
    lettering."""
    from graphplan.drawing.forces import LETTER
    st, p, dr, drawings = loom_a1
    rec = drawings["lever"][0]
    labels = [q for q in rec.items if q.kind == "text" and q.layer == "labels"]
    fp = dr.groups_fp(p.mu)
    at_pole = {n for n, z in fp.lever.images.items() if abs(z) <= 0.1}
    assert {"O1", "O2"} <= at_pole
    pole = [q.text for q in labels if q.text.startswith("p_v")]
    assert pole == ["p_v, " + ", ".join(sorted(f"{n[0].lower()}_{n[1:]}" for n in at_pole))], pole
    for i, a in enumerate(labels):
        for b in labels[i + 1:]:
            assert _gap(a, b) >= LETTER - 0.05, (a.text, b.text, _gap(a, b))


def test_a_group_is_drawn_freed_from_the_frame_its_arms_named_apart(loom_a1):
    """Group II(2–3) kept the frame's hatched support at O2, and h_Φ3, h_G3 on one line at B had
    their names 2 mm apart: a group's pivot on the frame is a joint circle with no support (R03
    replaces it) while the scheme keeps its supports; no two labels of a group closer than 3.5 mm."""
    from graphplan.drawing.forces import LETTER
    st, p, dr, drawings = loom_a1
    mech = st.mech
    for rec in drawings["groups"]:
        assert not [q for q in rec.items if q.layer == "frame"], rec.title
        labels = [q for q in rec.items if q.kind == "text" and q.layer == "labels"]
        assert {"O_2"} <= {q.text for q in labels} or "II" not in rec.title
        for i, a in enumerate(labels):
            for b in labels[i + 1:]:
                assert _gap(a, b) >= LETTER - 0.05, (rec.title, a.text, b.text, _gap(a, b))
    texts = [q.text for q in drawings["groups"][0].items if q.kind == "text"]
    assert {"h_{Φ3}", "h_{G3}", "R_{03}"} <= set(texts), texts
    scheme = drawings["scheme"][0]
    hatches = [q for q in scheme.items if q.role == "hatch" and q.layer == "frame"]
    assert len(hatches) == 5 * len(mech.frame)      # the scheme's supports: five strokes a pivot


def test_a_hodographs_jump_is_joined_where_the_moment_switches(rocker_turn):
    """R23 and R03 jump where M3 switches on (and off), and the sheet left the gap unexplained:
    each jump's two ends — the reaction just before and just after the switch, from the exact
    analysis — are joined by one thin dashed line."""
    from graphplan.drawing.charts import hodograph_record
    from graphplan.graphic.record import DASHED_ROLES, ROLES, THIN
    work = np.asarray(rocker_turn.ks.working, dtype=bool)
    cuts = [k for k in range(len(work)) if work[k] != work[k - 1]]
    assert len(cuts) == 2
    for key in rocker_turn.revolute:
        rec = hodograph_record(rocker_turn, key, lang="en")
        mu = rec.scales["mu_R"]
        f = rocker_turn.ks.reactions[key].force / mu
        jumps = [q for q in rec.items if q.kind == "segment" and q.step.endswith("the jump")]
        assert len(jumps) == sum(1 for k in cuts if abs(f[k] - f[k - 1]) > 0.5), key
        for k in cuts:
            if abs(f[k] - f[k - 1]) <= 0.5:
                continue
            ends = {(round(f[k - 1].real, 6), round(f[k - 1].imag, 6)), (round(f[k].real, 6), round(f[k].imag, 6))}
            assert any({tuple(round(c, 6) for c in pt) for pt in q.points} == ends for q in jumps), (key, k)
        for q in jumps:
            assert ROLES[q.role] == THIN and q.role in DASHED_ROLES

    # each hodograph that draws a jump says what the dashed line is (review4 #11: said under one of
    # four, the other three left to guess)
    from graphplan.drawing.charts import records
    for name, rec in records(rocker_turn, lang="en").items():
        if name.startswith("hodograph"):
            said = [q.text for q in rec.items if q.kind == "text" and "dashed" in q.text]
            drawn = any(q.step.endswith("the jump") for q in rec.items)
            assert said == (["dashed: the jump due to M_{3}"] if drawn else []), (name, said)
