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
import functools

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


@functools.lru_cache(maxsize=None)
def _drawn(scene: str, mu_l: float | None):
    """A review scene's study, plans and position plan at ``mu_l`` — built once for the module."""
    st = scene_study(getattr(review_scenes, scene))
    plans = build_plans(st, mu_l=mu_l)
    return st, plans, position_record(plans)


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


@pytest.mark.parametrize("scene, point", [("LINK51", "B"), ("FORCE_COUPLER51", "E"), ("SIX_BELL52", "C")])
def test_outer_joints_numbered(scene, point):
    """Stop 51's leftovers, the same cause: LINK51's coulisse end B (the rod BD's start) and
    FORCE_COUPLER51's coupler point E (the rod EF's start) numbered at every position; and kin52's own
    Watt six-bar's bell-crank arm C (the plate O2BC's third vertex, the rod CD's start)."""
    st, plans, rec = _drawn(scene, {"LINK51": 0.0025, "FORCE_COUPLER51": 0.0025, "SIX_BELL52": 0.002}[scene])
    read, wrong = _readings(rec, plans, _numbered(plans))
    assert not wrong, wrong
    thick = {str(p.index) for p in plans.positions if p.layout.key in (set(plans.accel_keys) or {0})}
    missing = [str(p.index) for p in plans.positions if (point, str(p.index)) not in read and str(p.index) not in thick]
    assert not missing, missing


def _watt(phi: float, branch_b: int = 1, branch_d: int = 1):
    """kin52's own Watt six-bar in closed form: B on the circles (A, 0.20) ∩ (O2, 0.12), the bell
    crank's C = O2 + (0.02 − 0.11i)·(B − O2)/|B − O2|, D on (C, 0.22) ∩ (O3, 0.14); None where a
    group does not assemble. The branch as the scene's B = 1, D = 1 (left of P→Q)."""
    def meet(P, a, Q, b, br):
        d = abs(Q - P)
        x = (a * a - b * b + d * d) / (2 * d)
        h2 = a * a - x * x
        if h2 < 0:
            return None
        u = (Q - P) / d
        return P + u * x + br * 1j * u * h2 ** 0.5
    O2, O3 = complex(0.18, 0.08), complex(0.36, 0.38)
    A = 0.05 * cmath.exp(1j * phi)
    B = meet(A, 0.20, O2, 0.12, branch_b)
    C = O2 + (B - O2) / abs(B - O2) * complex(0.02, -0.11)
    return A, B, C, meet(C, 0.22, O3, 0.14, branch_d), O3


def test_own_watt_sixbar_drawn_as_the_closed_form_and_its_swing():
    """kin52's own mechanism: every position's A, B, C, D on the plan are the closed form's (at μl,
    from O1), and the rocker O3D's extreme positions D′, D″ span the swing ψmax the closed form gives
    (a 0.01° search), to 0.05°."""
    import math
    _, plans, _ = _drawn("SIX_BELL52", 0.002)
    sc, mu = plans.scheme, plans.mu_l
    # the scene's branch signs against the drawing's: each joint at one position picks the sign
    first = plans.positions[0]
    o1 = where(sc, first.layout, sc.body_of("O1"), "O1")
    phi0 = math.radians(first.phi)
    signs = []
    for sb in (1, -1):
        for sd in (1, -1):
            pts = _watt(phi0, sb, sd)
            if pts[3] is not None and abs((where(sc, first.layout, sc.body_of("D"), "D") - o1) * mu - pts[3]) < 1e-6:
                signs.append((sb, sd))
    assert len(signs) == 1, signs
    sb, sd = signs[0]
    for p in plans.positions:
        A, B, C, D, _ = _watt(math.radians(p.phi), sb, sd)
        for name, z in zip("ABCD", (A, B, C, D)):
            drawn = (where(sc, p.layout, sc.body_of(name), name) - o1) * mu
            assert abs(drawn - z) < 1e-6, (p.index, name)
    ref = _watt(0.0, sb, sd)[3] - complex(0.36, 0.38)          # angles from one position: no ±180° wrap
    angles = [cmath.phase((_watt(math.radians(k / 100), sb, sd)[3] - complex(0.36, 0.38)) / ref) for k in range(36000)]
    swing = math.degrees(max(angles) - min(angles))
    from graphplan.drawing.plans import stroke_ends
    e1, e2 = ((where(sc, lay, sc.body_of("D"), "D") - where(sc, lay, sc.body_of("O3"), "O3")) for lay in stroke_ends(plans))
    assert math.degrees(abs(cmath.phase(e2 / e1))) == pytest.approx(swing, abs=0.05)


def test_a_sets_notes_go_under_the_last_tables_rather_than_alone():
    """LINK52's A3 set (stop 52): sheet 5 held Table 2 (a column 195 mm high) beside Tables 3 and 4,
    and the notes, 125 mm high, found no line on it — a shelf's line is as high as its tallest item —
    so they took sheet 6 alone. Set over the last two tables (``set_tail``), they stand on sheet 5
    under Tables 3 and 4, in reading order, inside the field and clear of the title block; one
    sheet fewer. (The sizes are that set's, mm.)"""
    from graphplan.drawing.layout import Leaf, Shelf, flow
    from graphplan.sheets.compose import field_of, keep_out, later_keep
    from graphplan.sheets.form import form
    from graphplan.sheets.kinlayout import set_tail
    f = form("A3")
    region, keep, later = field_of(f), keep_out(f), later_keep(f)
    tables = [Leaf("velocity table", 300.0, 100.0), Leaf("acceleration table 1", 120.0, 195.0),
              Leaf("dimensions table", 65.0, 75.0), Leaf("diagram readings table", 160.0, 55.0)]
    notes = Leaf("notes", 185.0, 125.0)
    first = [[Leaf("acceleration plan", 300.0, 150.0)]]
    alone = flow(first + [Shelf(set_tail(tables, notes, 0))], region, keep, later=later, ragged=True)
    # the defect was the notes alone on a sheet 4; since stop 59 a shelf's line of columns sets them
    # under Table 4 unstacked too (``layout._columns``): as many sheets either way
    assert len(alone) == 3 and [leaf.name for leaf, _ in alone[-1]] == [t.name for t in tables[1:]] + ["notes"]
    t4, n = (dict((leaf.name, b) for leaf, b in alone[-1])[k] for k in ("diagram readings table", "notes"))
    assert n[3] <= t4[1] + 1e-9 and n[0] == pytest.approx(t4[0])     # in Table 4's column, under it
    under = flow(first + [Shelf(set_tail(tables, notes, 2))], region, keep, later=later, ragged=True)
    assert len(under) == len(alone)
    last = dict((leaf.name, b) for leaf, b in under[-1])
    assert set(last) == {"acceleration table 1", "dimensions table", "diagram readings table", "notes"}
    n, t3, t4 = last["notes"], last["dimensions table"], last["diagram readings table"]
    assert n[3] <= min(t3[1], t4[1]) + 1e-9                             # under both tables
    assert t3[2] <= t4[0] + 1e-9                                        # Table 3, then Table 4
    x0, y0, x1, y1 = region
    for b in last.values():
        assert x0 - 1e-9 <= b[0] and b[2] <= x1 + 1e-9 and b[3] <= y1 + 1e-9
        assert b[1] >= later[3] - 1e-9 or b[2] <= later[0] + 1e-9      # clear of the title block
    # no two boxes overlap
    bs = list(last.values())
    assert not any(a[0] < b[2] - 1e-9 and b[0] < a[2] - 1e-9 and a[1] < b[3] - 1e-9 and b[1] < a[3] - 1e-9
                   for i, a in enumerate(bs) for b in bs[i + 1:])


def test_position_numbers_stand_apart_from_each_other_lists_too():
    """FORCE_COUPLER51's E₅ "5" stood 2 mm before B's "1, 9" and read "5 1, 9": a list of positions
    numbered at one spot is a number too (``labels.is_number``), kept as far from other numbers as
    any — no two position numbers' inks nearer than 2.5 mm, where they would read as one."""
    def is_number(text: str) -> bool:
        return all(part.isdigit() for part in text.split(", "))
    _, _, rec = _drawn("FORCE_COUPLER51", 0.0025)
    boxes = [q.ink() for q in rec.items if q.kind == "text" and q.size <= 3.0 and is_number(q.text)]
    assert any("," in q.text for q in rec.items if q.kind == "text" and is_number(q.text))
    def gap(a, b):
        return abs(complex(max(a[0] - b[2], b[0] - a[2], 0.0), max(a[1] - b[3], b[1] - a[3], 0.0)))
    near = min(gap(a, b) for i, a in enumerate(boxes) for b in boxes[i + 1:])
    assert near >= 2.5, near
