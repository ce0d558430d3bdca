"""Stop 52's kinematics sheet, graded as a teacher grades it.

The eight-bar LINK52 (a four-bar whose rocker's end C carries a block in the coulisse O3D, whose end D
drives the rod DE to the slider E): the coulisse's end D is constructed at every position (on the
coulisse's line through C, |O3D| from O3) and the rod's arc starts from it, yet its twelve dots were
bare — only the crank pin, the output, the groups' inner joints and the blocks' pins were numbered. The
same cause left LINK51's coulisse end B and FORCE_COUPLER51's coupler point E unnumbered. Every moving
joint's positions are numbered now, each number read (the drawn point nearest its ink, or its leader's
far end) as its own point at its own position."""
from __future__ import annotations

import cmath

import pytest

import review_scenes
from conftest import scene_study
from graphplan.drawing.plans import position_record
from graphplan.graphic.plans import build_plans, where
from test_position_numbers import _gap, _numbered


def _readings(rec, plans, names):
    """{(point, position)} that the record's position numbers are read as: a number with a leader
    at the numbered point nearest the leader's far end, one without at the numbered point nearest
    its ink (a group "5, 7" read as that point at each position it names)."""
    sc = plans.scheme
    at = {(n, str(p.index)): where(sc, p.layout, sc.body_of(n), n) for p in plans.positions for n in names}
    leaders = [[complex(*e) for e in q.points] for q in rec.items if q.kind == "segment" and q.role == "label"]
    read, wrong = set(), []
    for q in rec.items:
        if q.kind != "text" or q.size > 3.0:
            continue
        parts = q.text.split(", ")
        if not all(t.isdigit() for t in parts):
            continue
        box = q.ink()
        ends = [e for a, b in leaders for e, f in ((a, b), (b, a)) if _gap(box, f) < 1.2 and _gap(box, e) >= 1.2]
        spot = (lambda z: abs(z - ends[0])) if ends else (lambda z: _gap(box, z))      # noqa: E731
        name, k = min(at, key=lambda key: spot(at[key]))
        if k not in parts and not any(abs(at[name, t] - at[name, k]) < 1e-6 for t in parts if (name, t) in at):
            wrong.append((q.text, name, k))
        read |= {(name, t) for t in parts}
    return read, wrong


@pytest.fixture(scope="module")
def link52():
    st = scene_study(review_scenes.LINK52)
    plans = build_plans(st, mu_l=0.0025)        # the A1 sheet's scale
    return st, plans, position_record(plans)


def test_link52_coulisse_end_d_lies_where_the_closed_form_puts_it(link52):
    """D on the coulisse's line O3C at |O3D| = 0.38 m from O3, C at |O2C| = 1.8·0.14 m from O2 on the
    rocker's line O2B, and B on the circles (A, 0.24) ∩ (O2, 0.14): measured on the drawn plan."""
    _, plans, _ = link52
    sc, mu = plans.scheme, plans.mu_l
    for p in plans.positions:
        z = {n: where(sc, p.layout, sc.body_of(n), n) for n in ("O1", "O2", "O3", "A", "B", "C", "D")}
        assert abs(z["A"] - z["O1"]) * mu == pytest.approx(0.06, abs=1e-6)
        assert abs(z["B"] - z["A"]) * mu == pytest.approx(0.24, abs=1e-6)
        assert abs(z["B"] - z["O2"]) * mu == pytest.approx(0.14, abs=1e-6)
        assert z["C"] - z["O2"] == pytest.approx((z["B"] - z["O2"]) * 1.8, abs=1e-6)
        assert abs(z["D"] - z["O3"]) * mu == pytest.approx(0.38, abs=1e-6)
        across = (z["D"] - z["O3"]) / (z["C"] - z["O3"])
        assert abs(cmath.phase(across)) < 1e-9           # D on the ray O3 → C (the block slides on O3D)


def test_link52_every_moving_joint_numbered_at_every_position(link52):
    """A, B, C, D and E at each of the 12 positions carry their number (the thick position 3's
    joints their letters, its number beside), each read as its own point's."""
    _, plans, rec = link52
    names = ["A", "B", "C", "D", "E"]
    read, wrong = _readings(rec, plans, names)
    assert not wrong, wrong
    missing = [(n, str(p.index)) for p in plans.positions for n in names if (n, str(p.index)) not in read]
    assert not missing, missing


@pytest.mark.parametrize("scene, point", [("LINK51", "B"), ("FORCE_COUPLER51", "E")])
def test_outer_joints_numbered(scene, point):
    """Stop 51's leftovers, the same cause: LINK51's coulisse end B (the rod BD's start) and
    FORCE_COUPLER51's coupler point E (the rod EF's start) numbered at every position."""
    st = scene_study(getattr(review_scenes, scene))
    plans = build_plans(st, mu_l=0.0025 if scene == "LINK51" else None)
    rec = position_record(plans)
    read, wrong = _readings(rec, plans, _numbered(plans))
    assert not wrong, wrong
    thick = {str(p.index) for p in plans.positions if p.layout.key in (set(plans.accel_keys) or {0})}
    missing = [str(p.index) for p in plans.positions if (point, str(p.index)) not in read and str(p.index) not in thick]
    assert not missing, missing
