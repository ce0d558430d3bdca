"""Review 11 #1, #2, #17: the Scotch yoke (link 3, a slotted crosshead on a rod, no revolute joint
of its own) drawn as one rigid body, and R03's arm on it from ΣM = 0 of link 3 against a closed
form written here."""
from __future__ import annotations

import cmath
import math

import numpy as np
import pytest

from conftest import scene_study
from review_scenes import YOKE11


@pytest.fixture(scope="module")
def st():
    return scene_study(YOKE11)


def _dist_to_segment(z: complex, a: complex, b: complex) -> float:
    u = (b - a) / abs(b - a)
    t = min(max(((z - a) * u.conjugate()).real, 0.0), abs(b - a))
    return abs(z - (a + t * u))


def test_the_position_plan_draws_the_yoke_as_one_body(st):
    from graphplan.drawing.plans import yoke_parts, yoke_spans
    from graphplan.graphic.plans import build_plans
    from graphplan.graphic.position_plan import where
    from graphplan.model.linkshape import rod_crossing
    plans = build_plans(st)
    sc = plans.scheme
    every = [p.layout for p in plans.positions] + plans.extremes
    O = where(sc, every[0], "0", "O")
    r = 0.08 / plans.mu_l
    spans = yoke_spans(sc, every, "yoke", O, r)
    slot_len = spans.slot[1] - spans.slot[0]
    rod_len = spans.rod[1] - spans.rod[0]
    mid, u = spans.bushing
    for lay in every:
        a, b, p, q = yoke_parts(sc, lay, "yoke", spans)
        A, D, S3 = (where(sc, lay, body, name) for body, name in (("2", "A"), ("yoke", "D"), ("yoke", "S3")))
        # rigid: the same slot and rod at every position
        assert abs(abs(b - a) - slot_len) < 1e-9 and abs(abs(q - p) - rod_len) < 1e-9
        # the slot passes through the block at every drawn position, inclined 75° to the rod
        assert _dist_to_segment(A, a, b) < 1e-6
        assert abs(abs(math.degrees(cmath.phase((b - a) / (q - p)))) % 180 - 75.0) < 1e-6
        # the rod joins the slot (its end on the slot's line) and runs through D and S3
        x = rod_crossing(p, (q - p) / abs(q - p), a, (b - a) / abs(b - a))
        assert min(abs(x - p), abs(x - q)) < 1e-6 and _dist_to_segment(x, a, b) < 1e-6
        assert _dist_to_segment(D, p, q) < 1e-6 and _dist_to_segment(S3, p, q) < 1e-6
        # the rod passes through its bushing, which stands clear of the crank pin's circle
        assert _dist_to_segment(mid, p, q) < 1e-6
    assert abs(mid - O) > r + 8.0


def test_r03_arm_agrees_with_the_yokes_moment_equation(st):
    """ΣM_D = 0 of the yoke written here: the block's forces all pass through A, so the slot's force
    on the yoke R23 = N23·n_slot acts through A; ΣF along the rod gives N23, ΣF across it R03 = N·j,
    and h·N + (A − D) × R23 + (S3 − D) × (G3 + Φ3) = 0 (P_D = 0: φ = 60° is on the idle stroke)."""
    from graphplan.exact.kinetostatics import at_scene_angle
    from graphplan.graphic.forceplans import construct, slide_arms
    phi = at_scene_angle(st)
    r, w, alpha = 0.08, 150 * 2 * math.pi / 60, math.radians(75.0)
    f = math.radians(phi)
    A = r * cmath.exp(1j * f)
    D = complex(A.real - A.imag / math.tan(alpha) + 0.02, 0.0)
    S3 = D + 0.06
    a_D = -w * w * (r * math.cos(f) - r * math.sin(f) / math.tan(alpha))
    F3 = -6.0 * a_D - 1j * 6.0 * 9.81             # Φ3 + G3 at S3
    cr = lambda a, b: a.real * b.imag - a.imag * b.real   # noqa: E731
    n_slot = 1j * cmath.exp(1j * alpha)
    N23 = -F3.real / n_slot.real
    R23 = N23 * n_slot
    N = -(R23 + F3).imag
    h = -(cr(A - D, R23) + cr(S3 - D, F3)) / N
    exact_fp = construct(st, phi, 0.0)
    arm = next(a for a in slide_arms(exact_fp) if a.key == "R03")
    assert arm.analytic == pytest.approx(h, rel=1e-9, abs=1e-12)
    assert arm.value == pytest.approx(h, rel=1e-9, abs=1e-12)       # precision 0: the construction is exact
    drawn = next(a for a in slide_arms(construct(st, phi, 0.5)) if a.key == "R03")
    assert abs(drawn.value - h) < 0.5 * 1.5 * drawn.value / drawn.h_mm + 1e-12   # within the ruler's reading


def test_the_terminal_and_the_sheet_name_r03s_arm_and_the_idle_stroke(st):
    from graphplan.exact.kinetostatics import at_scene_angle
    from graphplan.graphic.forceplans import construct
    from graphplan.report.forces import forces_table
    from graphplan.sheets.forces import force_position
    phi = at_scene_angle(st)
    text = forces_table(construct(st, phi, 0.5), "en")
    assert "h(R₀₃) = " in text and "from D along the guide" in text
    assert force_position(st, phi, "en").endswith("idle stroke: P_{D} = 0")
    assert "робочий" not in force_position(st, (phi + 180.0) % 360.0, "uk")
    # the working stroke's position ends with its crank angle, no idle words; since kinmarks the
    # angle is said from the x axis as the kinematics sheet writes position 0's ("225.0° from the x axis)")
    assert force_position(st, (phi + 180.0) % 360.0, "en").endswith("° from the x axis)")


def test_a_force_sheets_length_scale_grows_only_through_gost_2302_scales():
    """Review 11 #3: the b A2 set's scheme at μl 0.00075 ("1.333:1" in the title block). The length
    families grow by GOST 2.302's drawing scales only: from each, the next is finer, is one, and no
    GOST scale lies between them."""
    from graphplan.graphic.scales import gost_length
    from graphplan.sheets.forces import next_length
    gost = sorted({m * 10.0 ** k / 1000.0 for k in range(-3, 3) for m in (1, 2, 2.5, 4, 5)} | {0.015, 0.075})
    assert not gost_length(0.00075) and not gost_length(0.0015) and gost_length(0.015)
    for mu in gost[3:-3]:
        nxt = next_length(mu)
        assert nxt < mu and gost_length(nxt)
        assert not [g for g in gost if nxt * (1 + 1e-9) < g < mu * (1 - 1e-9)], (mu, nxt)


def test_the_force_sheet_draws_the_same_body_and_r03_on_its_found_line(st):
    """The scheme's and the group's yoke: the slot through the block A, the rod from the slot's line
    through D and S3; the group draws R03 on the line its ΣM = 0 found, its arm h_R03 from D to it."""
    from graphplan.drawing.forces import group_record, yoke_mm
    from graphplan.exact.kinetostatics import at_scene_angle
    from graphplan.graphic.forceplans import construct
    from graphplan.model.linkshape import rod_crossing
    fp = construct(st, at_scene_angle(st), 0.5)
    mu = fp.mu_l
    kin, mech = fp.ks.kin, st.mech
    at = {p: complex(kin.bodies[b].at(mech.links[b].local[p])[0][0]) / mu for b, p in (("2", "A"), ("yoke", "D"), ("yoke", "S3"))}
    a, b, p, q = yoke_mm(fp, "yoke", mu)
    assert _dist_to_segment(at["A"], a, b) < 1e-6
    x = rod_crossing(p, (q - p) / abs(q - p), a, (b - a) / abs(b - a))
    assert min(abs(x - p), abs(x - q)) < 1e-6
    assert _dist_to_segment(at["D"], p, q) < 1e-6 and _dist_to_segment(at["S3"], p, q) < 1e-6
    gp = next(g for g in fp.groups if "yoke" in g.links)
    rec = group_record(fp, gp, "en")
    (t, h), = [v.points for v in rec.items if v.kind == "vector" and v.text == "R03"]
    line = gp.reactions["R03"].line / gp.mu_l
    u = complex(*h) - complex(*t)
    assert abs(((line - complex(*t)) * u.conjugate()).imag) / abs(u) < 1e-6      # R03 on its line
    arm, = [s for s in rec.items if s.kind == "segment" and s.text.startswith("h_{R03}")]
    (ax, ay), (bx, by) = arm.points
    assert abs(math.hypot(bx - ax, by - ay) - abs(line - at["D"] * mu / gp.mu_l)) < 1e-6


def test_the_schemes_rod_runs_in_a_bushing_clear_of_the_crank(st):
    """Review 11 #2 on the force sheet's scheme: at both a working and an idle position the rod's
    bushing stands on the rod's axis outside the crank pin's circle, the rod through it; a group
    freed from the frame draws no bushing and the rod only from the slot to S3."""
    from graphplan.drawing.forces import yoke_at
    from graphplan.graphic.forceplans import construct
    for phi in (45.0, 225.0):
        fp = construct(st, phi, 0.5)
        mu = fp.mu_l
        a, b, p, q, (mid, u) = yoke_at(fp, "yoke", mu)
        assert abs(mid) > 0.08 / mu + 2.0 and abs(mid.imag) < 1e-9 and abs(abs(u) - 1) < 1e-12
        assert _dist_to_segment(mid, p, q) < 1e-9
        *_, p2, q2, none = yoke_at(fp, "yoke", mu, framed=False)
        s3 = complex(fp.ks.kin.bodies["yoke"].at(st.mech.links["yoke"].local["S3"])[0][0]) / mu
        assert none is None and abs(max(p2.real, q2.real) - s3.real) < 1e-9
