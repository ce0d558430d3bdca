"""Stop 59 (frc59c): review 59 #2 and a force's label in a knot of parallel arrows.

1. Every μF of the force sheet on the standard series 1, 2, 2.5, 4, 5 × 10^k (LAYOUT.md): the Watt-II's A1
   sheet drew group II(2-3)'s plan and the inset of II(4-5) at GOST's 1.5 N/mm, the hodographs of R12
   and R01 at 7.5 N/mm, its acceleration plan at 0.075 (m/s²)/mm. Checked against the series written
   out here, and the hodograph's size against the reaction's exact extent.
2. M_b by the force plans −15 %: the note says which reading carries it — R21 taken over from group
   II(2-3)'s plan, its line 1.3° off, its arm 18 mm for 19.4 — checked against the closed form (the
   exact R21 and point A: its exact moment about O1, and M_b = −ΣM of the plan's terms).
3. A force's label nearer its own arrow than any other (FRC56_PUSHER's II(2-3): «R43» 11.8 mm from its
   arrow, 8.3 from G2's, on a leader the old rule let stand 2 mm clear of every other arrow however far
   from its own) — measured on the drawing: the label's ink box to every arrow's segment.
"""
from __future__ import annotations

import math

import pytest
from hypothesis import HealthCheck, given, settings, strategies as st

from conftest import scene_force_plans, scene_study

MANTISSAS = (1.0, 2.0, 2.5, 4.0, 5.0)


def _series(mu: float) -> bool:
    """The mantissa of μ is one of 1, 2, 2.5, 4, 5 (independent of graphic.scales)."""
    k = math.floor(math.log10(mu) + 1e-12)
    return any(abs(mu / 10.0 ** k - m) <= 1e-9 for m in MANTISSAS)


@settings(suppress_health_check=[HealthCheck.too_slow], deadline=None)
@given(st.floats(1.0, 1e6), st.floats(20.0, 200.0))
def test_a_hodographs_scale_is_the_finest_series_value_that_fits(span, size):
    from graphplan.drawing.charts import hodograph_scale
    mu = hodograph_scale(span, size)
    assert _series(mu)
    assert span / mu <= size * (1 + 1e-9)
    assert span / mu >= size / 2.0 * (1 - 1e-9)          # the series' widest step: 5 → 10


@settings(suppress_health_check=[HealthCheck.too_slow], deadline=None)
@given(st.floats(0.02, 30.0), st.sampled_from([m * 10.0 ** k for m in MANTISSAS for k in range(-1, 3)]))
def test_a_plans_detail_scale_is_of_the_series(side_mm, mu_F):
    from graphplan.graphic.forceplans import DETAIL_GAIN_MOST, detail_scale
    mu = detail_scale(side_mm, mu_F)
    assert _series(mu)
    assert mu <= mu_F / 2.0 * (1 + 1e-9)
    assert mu >= mu_F / DETAIL_GAIN_MOST / 2.5 * (1 - 1e-9)


@pytest.mark.slow
def test_the_watt_a1_sheets_force_plans_and_acceleration_plan_are_on_the_series():
    from review_scenes import FRC59C_WATT_EN
    from graphplan.sheets import forces
    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.form import form
    study = scene_study(FRC59C_WATT_EN)
    q, _, _ = forces.plan(study, form("A1"), SheetOptions(sheet="forces", lang="en"))
    plans = {k: v for k, v in q.mu.items() if k == "forces" or k.startswith(forces.PLAN) or k == "acceleration"}
    assert any(k.startswith(forces.PLAN) for k in plans), q.mu
    for k, v in plans.items():
        assert _series(v), (k, q.mu)


# the Watt-II's force plans as its A1 sheet draws them (the branch's scales: μl 0.004, the crank 0.001;
# μF 4, 2, 0.5; μa 0.1)
WATT_SCALES = dict(mu_l=0.004, group_mu={"I(0-1)": 0.001}, group_mu_F={"II(4-5)": 4.0, "II(2-3)": 2.0, "I(0-1)": 0.5},
                   mu_a=0.1)


@pytest.mark.slow
def test_the_note_says_which_reading_carries_m_b_by_the_plans_off():
    import re
    from review_scenes import FRC59C_WATT_EN
    from graphplan.drawing.forces import _carried_why
    fp = scene_force_plans(FRC59C_WATT_EN, **WATT_SCALES)
    assert abs(fp.balancing / fp.analytic - 1) > 0.05                 # the reviewer's −15 %
    crank = fp.groups[-1]
    terms = {t.name: t for t in crank.equations[0].terms}
    assert fp.balancing == pytest.approx(-sum(t.value for t in terms.values()))
    # the exact R21 on the crank at A, about O1, from the closed form alone
    kin = fp.ks.kin
    o, a = complex(kin.point("O1")[0][0]), complex(kin.point("A")[0][0])
    r12 = complex(fp.ks.reactions["R12"].force[0])
    moment = abs(((a - o) * r12.conjugate()).imag)                      # |r × F|, N·m
    arm_mm = moment / abs(r12) / crank.mu_l
    text = _carried_why(fp, "en", "M_b (force plans)")
    assert text and "R_{21}" in text and "II(2-3)" in text, text
    nums = [float(x) for x in re.findall(r"-?\d+\.?\d*", text.split(":", 1)[1])]
    assert any(abs(x - abs(r12)) < 0.006 for x in nums), (text, abs(r12))          # exact 24.92
    assert any(abs(x - arm_mm) < 0.06 for x in nums), (text, arm_mm)              # exact arm 19.4 mm
    assert any(abs(x - moment) < 6e-5 for x in nums), (text, moment)              # exact moment 0.4839
    assert any(abs(x - abs(terms["R21"].value)) < 6e-5 for x in nums), text        # as the plans read it
    # the plans' miss is R21's moment's: the rest of the crank's moments are read within 1 %
    rest = sum(t.value for n, t in terms.items() if n != "R21")
    exact_rest = -fp.analytic - moment * math.copysign(1.0, terms["R21"].value)
    assert rest == pytest.approx(exact_rest, rel=0.01)


def _labels_and_arrows(scene: str, label: str):
    from shapely.geometry import LineString, box
    from graphplan.drawing.forces import group_record
    from graphplan.util.words import force_symbol
    fp = scene_force_plans(scene)
    gp = next(g for g in fp.groups if g.label == label)
    rec = group_record(fp, gp)
    arrows = {q.text: LineString([q.points[0], q.points[1]]) for q in rec.items
              if q.kind == "vector" and q.role in ("absolute", "result")}
    names = {force_symbol(n, "uk"): n for n in arrows}
    out = []
    for q in rec.items:
        if q.kind == "text" and q.layer == "labels" and q.text in names:
            b = box(*q.ink())
            own = b.distance(arrows[names[q.text]])
            other = min((b.distance(ln), n) for n, ln in arrows.items() if n != names[q.text])
            out.append((names[q.text], own, other))
    return arrows, out


def _nearest_own(scene: str, label: str, names: tuple[str, ...]):
    arrows, labels = _labels_and_arrows(scene, label)
    got = {n for n, _, _ in labels}
    assert set(names) <= got, (names, got)                              # every force named
    for name, own, (other, who) in labels:
        assert own < other, (label, name, round(own, 2), who, round(other, 2))


@pytest.mark.slow
def test_frc56_pushers_r43_stands_by_its_own_arrow():
    """II(2-3): «R43» was set on a leader 11.8 mm from its arrow, 8.3 mm from G2's."""
    from review_scenes import FRC56_PUSHER
    _nearest_own(FRC56_PUSHER, "II(2-3)", ("R43", "G2", "Φ2", "G3", "Φ3", "R03", "R12"))


# stop 59 left these two strict xfails: a knot of parallel arrows 2–3.5 mm apart (lanes set aside from the
# links and from P_D), the force's own the shortest between two others, its ink box wider than the strip
# its arrow owns. Stop 61 (frc61) draws every force on its own line through its point (test_forces_own_line61):
# the lanes are gone and each name stands nearer its own arrow.
@pytest.mark.slow
@pytest.mark.parametrize("scene,label,name", [
    ("FRC56_PUSHER", "II(4-5)", "Φ5"),
    ("LINK59", "II(4-5)", "G4"),
])
def test_a_label_in_a_knot_of_parallel_arrows(scene, label, name):
    import review_scenes
    _, labels = _labels_and_arrows(getattr(review_scenes, scene), label)
    own, (other, who) = next((o, w) for n, o, w in labels if n == name)
    assert own < other, (name, own, who, other)
    # … and so does every other force's name of the group
    assert [(n, o, w) for n, o, w in labels if o >= w[0]] == []


@pytest.mark.slow
@pytest.mark.parametrize("mu_F", [10.0, 20.0, 25.0, 50.0])
def test_link59s_crank_reads_r01_within_the_rulers_reach(mu_F):
    """LINK59's crank (A1 uk: μF 20 N/mm, 1:1): R01 closes the sliver G1 + R21 (R21 ≈ 1950 N, G1 17 N);
    frc59's report saw it at −19 %. Read at any of the crank plan's series μF it is within half a ruler
    division of the closed form plus what R21 carries in from group II(2-3)'s plan."""
    from review_scenes import LINK59
    fp = scene_force_plans(LINK59, mu_l=0.0025, group_mu={"II(4-5)": 0.0005, "I(0-1)": 0.001},
                           group_mu_F={"II(4-5)": 20.0, "II(2-3)": 20.0, "I(0-1)": mu_F}, mu_a=0.05)
    got = fp.reactions()
    r01, r12 = got["R01"], got["R12"]
    exact = abs(complex(fp.ks.reactions["R01"].force[0]))
    assert r01.analytic == pytest.approx(exact)
    carried = abs(r12.value - r12.analytic)
    assert abs(r01.value - exact) <= carried + 0.5 * fp.precision * mu_F + 1.0, (r01.value, exact, carried)
    assert abs(r01.value / exact - 1) < 0.02
