"""Stop 59 (review 58 #1, frc58c's rule tightened): a force with an arm drawn to its line, hidden by its
link's line at its point, is drawn ON its line of action — the line its arm ends on — slid along it
past the link, where its arrow keeps 1.2 mm (centre to centre: two 0.7 mm lines and half a millimetre
of paper) from every drawn link over its whole length; else beside the link in a lane.

Checked against the drawing's own geometry: each arrow's line, extended, through the force's point;
every arrow drawn off its point (slid or set aside) sampled along its whole length against every link
segment of the record. On main the coulisses' weights stood in lanes 2.5 mm off the lines their arms
end on; frc58c's slide (≤ 1 mm of the link's line allowed) laid the slotter's G4 0.6–1 mm from its
link 3° off vertical — a thickened link, not a force."""
from __future__ import annotations

import math
from pathlib import Path

import pytest

from conftest import scene_force_plans
from graphplan.drawing.forces import _mu, group_record
from review_scenes import COULISSE, COULISSE_REVIEW58, LINK59, SLIDER_COULISSE50

pytestmark = pytest.mark.slow

SLOTTER = (Path(__file__).parents[1] / "examples" / "slotter.toml").read_text(encoding="utf-8")

CLEAR_MM = 1.2


def _to_line(p: complex, a: complex, b: complex) -> float:
    u = (b - a) / abs(b - a)
    return abs(((p - a) * u.conjugate()).imag)


def _to_segment(p: complex, a: complex, b: complex) -> float:
    d = b - a
    if abs(d) < 1e-9:
        return abs(p - a)
    t = max(0.0, min(1.0, ((p - a) * d.conjugate()).real / abs(d) ** 2))
    return abs(p - (a + t * d))


def _drawing(scene: str, label: str):
    fp = scene_force_plans(scene)
    gp = next(g for g in fp.groups if g.label == label)
    rec = group_record(fp, gp)
    mu = _mu(fp, gp)
    at = {f.name: f.at / mu for f in gp.forces if f.force != 0}
    armed = {t.name for eq in gp.equations for t in eq.terms if abs(t.arm_mm) >= 1.0 and not t.couple}
    arrows = {q.text: (complex(*q.points[0]), complex(*q.points[1])) for q in rec.items
              if q.kind == "vector" and q.role == "absolute" and q.text in at}
    links = []
    for q in rec.items:
        if q.role == "link" and q.kind in ("polyline", "segment"):
            pts = [complex(*p) for p in q.points]
            links += list(zip(pts, pts[1:]))
    return at, armed, arrows, links


CASES = [  # (scene, group, the forces that must lie on their own lines there)
    (COULISSE_REVIEW58, "II(4-5)", ("G4", "G5")),     # the slotted lever 7° off vertical (review 58 #1)
    (COULISSE, "II(2-3)", ("G2", "G3")),              # the stone's G2 and the rocker's G3 at S3
    (SLIDER_COULISSE50, "II(4-5)", ("G4", "G5")),
    (LINK59, "II(2-3)", ("G3",)),                     # the slotted rocker O2E at S3
    (SLOTTER, "II(4-5)", ()),                         # G4, 3° off its link: a lane, not its stroke
]


@pytest.mark.parametrize("scene,label,on_line", CASES,
                         ids=["coulisse58", "coulisse", "slider_coulisse50", "link59", "slotter"])
def test_an_armed_force_lies_on_its_line_or_clear_of_every_link(scene, label, on_line):
    at, armed, arrows, links = _drawing(scene, label)
    assert links and armed
    for name in on_line:
        a, b = arrows[name]
        assert _to_line(at[name], a, b) < 0.05, (label, name)            # on the line its arm ends on
    detached = 0
    for name, (a, b) in arrows.items():
        z = at[name]
        if min(abs(a - z), abs(b - z)) < 0.5 and _to_line(z, a, b) < 0.05:
            continue                     # drawn from its point (or to it): the point's links meet it there
        detached += 1
        least = min(_to_segment(a + (b - a) * k / 40, s, e) for k in range(41) for s, e in links)
        assert least >= CLEAR_MM - 1e-6, (label, name, round(least, 2))
    assert detached >= 1


def test_the_slotters_g4_keeps_its_lane_and_its_name():
    """Its link 3° off its line, a place on the line clear by 1.2 mm lay 23 mm and more down from S4:
    the arrow stays beside the link (2.5 mm), its line of action through S4, parallel."""
    at, armed, arrows, links = _drawing(SLOTTER, "II(4-5)")
    a, b = arrows["G4"]
    assert "G4" in armed
    assert 2.0 < _to_line(at["G4"], a, b) < 3.0
    assert abs(((b - a) / abs(b - a)).imag + 1.0) < 1e-6                 # down, parallel to its line


def test_a_reaction_read_off_the_detail_is_read_where_the_detail_lays_the_polygon_again():
    """FRC56_PUMP's II(4-5): R05 = 1.18 N (exact) is 0.12 mm at the plan's 10 N/mm, under the knowns'
    rounding there (0.25 mm each, 2.5 N): the plan's side enlarged read 3.75 N (+217 %). Laid again at
    the detail's μF_I, each known rounded there, it reads within the rounding of the sides laid at μF_I
    (half the ruler's step per side, the reading's own half step) of the exact value; the detail drawn
    at that μF_I shows the side the table reads, and says its scale."""
    from graphplan.drawing.forces import polygon_record
    from review_scenes import FRC56_PUMP
    fp = scene_force_plans(FRC56_PUMP)
    gp = next(g for g in fp.groups if g.label == "II(4-5)")
    m = gp.reactions["R05"]
    assert m.detail_mu > 0 and m.detail_mu <= gp.mu_F / 2
    knowns = [f for f in gp.forces if f.force != 0] + [s for s in gp.sides if s.role == "component"]
    bound = (len(knowns) + 1) * fp.precision / 2 * m.detail_mu
    assert abs(m.value - m.analytic) <= bound, (m.value, m.analytic, bound)
    assert abs(m.analytic - 1.1814) < 1e-3                      # the closed form's R05 (N)
    assert abs(m.value - m.mm * m.detail_mu) < 1e-9             # read off the detail's side, at its μF_I
    rec = polygon_record(fp, gp)
    assert rec.scales.get("mu_F detail") == m.detail_mu
    side = [q for q in rec.items if q.kind == "vector" and q.role == "result" and q.text == "R05"
            and q.step.endswith(": detail")]
    assert side, "R05 drawn in the detail"
    (x0, y0), (x1, y1) = side[0].points[:2]
    assert abs(math.hypot(x1 - x0, y1 - y0) - m.mm) <= fp.precision / 2 + 1e-9


def test_the_weights_arm_names_on_the_lever_each_stand_over_its_own_stretch_of_their_line():
    """LINK58's lever: the weights' arms all run left from the pole along one horizontal line (feet at
    G3 47, G2 76, G5 84, G4 89 mm). Each arm's name reads as its own where it stands over its own
    stretch of that line (from the next foot nearer the pole to its own; the outermost's also past
    its foot, where nothing runs on), beside it or on a leader read at a glance (15 mm) — «h_G5»
    went out on a leader over h_G2's stretch, after h_G2 took the end of its own stretch."""
    from graphplan.drawing.forces import lever_record
    from review_scenes import LINK58
    fp = scene_force_plans(LINK58)
    rec = lever_record(fp)
    feet = {q.text.split(" =")[0]: complex(*q.points[1]) for q in rec.items
            if q.role == "construction" and q.kind == "segment" and (q.text or "").startswith("h_{G")}
    ray = {n: f for n, f in feet.items() if abs(f.imag) < 1e-6 and f.real < 0}
    assert len(ray) >= 4
    order = sorted(ray, key=lambda n: -ray[n].real)          # nearest the pole first
    names = {q.text: q.bounds() for q in rec.items if q.kind == "text" and q.text in ray}
    for k, n in enumerate(order):
        inner = -ray[order[k - 1]].real if k else 0.0
        outer = -ray[n].real
        x0, y0, x1, y1 = names[n]
        mid = -(x0 + x1) / 2
        last = k == len(order) - 1
        assert inner < mid < outer + (4.0 + 3.5 + 1.0 if last else 0.0), (n, inner, mid, outer)
        assert min(abs(y0), abs(y1)) < 15.0, (n, y0, y1)         # beside it, or on a leader read at a glance


def test_the_point_a_block_presses_its_slotted_link_at_is_lettered_by_the_blocks_point():
    """LINK59's II(2-3): R43, the block C's reaction on the slotted rocker O2E, acts where the block
    rides — C, the point of the pair; it was an unlettered dot on the rocker between B and E."""
    from review_scenes import LINK59
    fp = scene_force_plans(LINK59)
    gp = next(g for g in fp.groups if g.label == "II(2-3)")
    rec = group_record(fp, gp)
    mu = _mu(fp, gp)
    c = next(f.at / mu for f in gp.forces if f.name == "R43")
    kin, mech = fp.ks.kin, fp.ks.mech
    block = next(n for n, lk in mech.links.items() if lk.slides_on is not None and "C" in lk.joints
                 and mech.links[lk.slides_on].joints and lk.slides_on in gp.links)
    assert abs(complex(kin.bodies[block].at(mech.links[block].local["C"])[0][0]) / mu - c) < 0.5
    letters = [complex(*q.points[0]) for q in rec.items if q.kind == "text" and q.role == "label" and q.text == "C"]
    assert letters and min(abs(z - c) for z in letters) < 8.0
