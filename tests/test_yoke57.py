"""Review 57 (the blind reviewer's scene a, YOKE_REVIEW57): a Scotch yoke whose rod end C — the
yoke's joint — drives a rocker O3E through a rod CE; its slot does NOT pass through its joint
(the slot vertical, 0.25 m from C along the rod). #1 the yoke is one rigid body (a slot, its two
sides, over the block's whole travel, at 90° to the rod, joined to the rod that runs along the
frame's guide to C) at every position — not a triangle A–slot's foot–C changing shape; #2 Table 4
gives α3 and e3; #4 R03 acts on the drawn rod; #5 Table 1 keeps v_S3 (= v_C: the yoke translates).

Truth: the scene's numbers — the crank r = 0.08 m, the slot through (−0.25, 0) of the yoke's frame
at 90°, S3 0.11 m from C — and the closed forms of a Scotch yoke (C.x = A.x + 0.25, v_C = ω·r·|sin φ|,
a_C = −ω²·A.x)."""
from __future__ import annotations

import math

import pytest

from conftest import scene_study
from review_scenes import OWN_YOKE51, WEDGE52, YOKE11, YOKE_REVIEW57, YOKE_ROCKER51

R, E3, CS3, MU = 0.08, 0.25, 0.11, 0.002          # the crank, the slot from C, C to S3 (m); the plan's μl
OMEGA = 90 * 2 * math.pi / 60


@pytest.fixture(scope="module")
def st():
    return scene_study(YOKE_REVIEW57)


@pytest.fixture(scope="module")
def plans(st):
    from graphplan.graphic.plans import build_plans
    return build_plans(st, count=12, accel=[2, 8], precision=0.5)


def test_a_yoke_with_a_joint_is_a_yoke_and_a_wedge_stays_a_wedge():
    """A slider that carries a slot steep to its rod (≥ 45°) is a yoke, with or without a joint of
    its own (review 57's link 3: joint C, slot at 90°); the wedge press's block B (its slot the
    wedge's face at 150°, 30° to its rod) keeps its wedge drawing."""
    from graphplan.model.linkshape import yoke_guide
    from graphplan.model.scene import loads
    for text, link, deg in ((YOKE_REVIEW57, "3", 90.0), (YOKE11, "yoke", 75.0), (YOKE_ROCKER51, "yoke", 90.0),
                            (OWN_YOKE51, "yoke", 90.0)):
        g = yoke_guide(loads(text, "<test>"), link)
        assert g is not None and math.degrees(g.angle) % 180.0 == pytest.approx(deg)
    assert yoke_guide(loads(WEDGE52, "<test>"), "B") is None


def test_the_position_plan_draws_one_rigid_yoke_at_every_thick_position(st, plans):
    """At the thick positions 2 and 8 (the accelerations' plans): the slot drawn as its two sides,
    parallel, of one length, at 90° to the rod's guide (the x axis), the block A between them, covering
    the block's whole travel ±r; the rod along the guide from the slot's line to C = A + e3 (the
    slot e3 = 0.25 m from C); no other line of the yoke (no triangle from the slot's ends to C)."""
    from graphplan.drawing.plans import position_record
    from graphplan.graphic.position_plan import where
    sc = plans.scheme
    rec = position_record(plans)
    lays = {p.layout.key: p.layout for p in plans.positions}
    lengths, rods = [], []
    for k in (2, 8):
        A = where(sc, lays[k], "2", "A")
        C = where(sc, lays[k], "3", "C")
        assert C.imag == pytest.approx(0.0, abs=1e-9) and C.real == pytest.approx(A.real + E3 / MU, abs=1e-6)
        slot, = [i.points for i in rec.items if i.kind == "polyline" and i.role == "link" and i.step == f"position {k}"]
        z = [complex(*p) for p in slot]
        assert abs(z[0] - z[-1]) < 1e-9            # closed
        s1, s2 = (z[0], z[1]), (z[2], z[3])
        for a, b in (s1, s2):
            assert abs(a.real - b.real) < 1e-9      # each side at 90° to the x axis (α3)
        assert abs(abs(s1[1] - s1[0]) - abs(s2[1] - s2[0])) < 1e-9
        lengths.append(abs(s1[1] - s1[0]))
        # A between the sides, the sides at one distance from C along the rod (e3 ∓ the half width)
        assert min(s1[0].real, s2[0].real) < A.real < max(s1[0].real, s2[0].real)
        assert (C.real - s1[0].real) + (C.real - s2[0].real) == pytest.approx(2 * E3 / MU, abs=1e-6)
        # the block's whole travel ±r in the slot
        lo, hi = min(s1[0].imag, s1[1].imag), max(s1[0].imag, s1[1].imag)
        assert lo < -R / MU and hi > R / MU
        segs = [(complex(*i.points[0]), complex(*i.points[1])) for i in rec.items
                if i.kind == "segment" and i.role == "link" and i.step == f"position {k}"]
        on_rod = [s for s in segs if abs(s[0].imag) < 1e-9 and abs(s[1].imag) < 1e-9]
        rod, = on_rod
        # … from the slot's side nearer C (not across the block's path inside the slot) to C
        side = max(s1[0].real, s2[0].real)
        assert sorted((rod[0].real, rod[1].real)) == pytest.approx([side, C.real], abs=1e-6)
        rods.append(abs(rod[1] - rod[0]))
        # the other lines: the crank O–A, the rod C–E, the rocker O3–E — none from the slot's ends
        ends = [s1[0], s1[1], s2[0], s2[1]]
        assert not [s for s in segs if s not in on_rod and any(min(abs(s[0] - e), abs(s[1] - e)) < 1.0 for e in ends)]
        assert len(segs) == 4
    assert lengths[0] == pytest.approx(lengths[1]) and rods[0] == pytest.approx(rods[1])


def test_table_4_gives_the_slots_angle_and_distance_from_c(st):
    """Table 4 (sizes of the links): α3 = 90° and e3 = 0,250 m (125,0 mm at μl 0.002), CS3 once."""
    from graphplan.sheets.kintables import dimensions_table
    from graphplan.util.markup import plain
    rec = dimensions_table(st, MU, "uk", n=4)
    texts = [plain(i.text) for i in rec.items if i.kind == "text"]
    at = {t: k for k, t in enumerate(texts)}
    assert "α₃" in at and "e₃" in at
    assert texts[at["α₃"] + 1] == "90°" and texts[at["α₃"] + 2] == "90°"
    assert texts[at["e₃"] + 1] == "0,250" and texts[at["e₃"] + 2] == "125,0"
    assert texts.count("CS₃") == 1 and texts[at["CS₃"] + 1] == f"{CS3:.3f}".replace(".", ",")
    # e3 said measured from the yoke's joint C (its own point; a yoke with no joint says D)
    assert "від C до осі паза" in " ".join(texts) and "від D" not in " ".join(texts)


def test_r03_acts_on_the_drawn_rod(st):
    """The group II(2-3) draws R03 on the line the yoke's ΣM_C = 0 finds, written here: the slot is
    vertical, so the block's force on the yoke R23 is horizontal through A; ΣF_x of the yoke gives
    it (Φ3 = −m3·a_C, a_C = −ω²·A.x, R43 handed over from II(4-5)), ΣF_y gives N03, and
    h·N03 + (A − C) × R23 + (S3 − C) × G3 = 0. The drawn rod runs ROD_PAST_MM past that line: the
    reaction's arrow meets the rod (review 57 #4: it stood 62 mm past the rod's drawn end)."""
    from graphplan.drawing.forces import group_record, yoke_at
    from graphplan.exact.kinetostatics import at_scene_angle
    from graphplan.graphic.forceplans import construct
    from graphplan.model.linkshape import ROD_PAST_MM
    fp = construct(st, at_scene_angle(st), 0.5)
    kin, mech = fp.ks.kin, st.mech
    A = complex(kin.bodies["2"].at(mech.links["2"].local["A"])[0][0])
    C = complex(kin.bodies["3"].at(mech.links["3"].local["C"])[0][0])
    assert C == pytest.approx(A.real + E3, abs=1e-12)
    r34 = complex(fp.ks.reactions["R34"].force[0])
    R43 = -r34
    phi3 = 6.0 * OMEGA ** 2 * A.real                  # −m3·a_C along x
    r23x = -(phi3 + R43.real)
    n03 = 6.0 * 9.81 - R43.imag
    cross = lambda a, b: a.real * b.imag - a.imag * b.real   # noqa: E731
    h = -(cross(A - C, complex(r23x, 0.0)) + cross(complex(-CS3, 0.0), complex(0.0, -6.0 * 9.81))) / n03
    line = complex(fp.ks.reactions["R03"].line_point()[0])
    assert line.real - C.real == pytest.approx(h, rel=1e-9)
    assert h > 0.03               # the scene's case: R03 well beyond C, past the rod's joint
    gp = next(g for g in fp.groups if "3" in g.links)
    mu = gp.mu_l or fp.mu_l
    rec = group_record(fp, gp, "uk")
    (t, hd), = [v.points for v in rec.items if v.kind == "vector" and v.text == "R03"]
    x = complex(*t).real
    assert complex(*hd).real == pytest.approx(x, abs=1e-9)
    assert x == pytest.approx(complex(gp.reactions["R03"].line).real / mu, abs=1e-6)    # on its found line
    assert abs(x - line.real / mu) < 1.0                 # … the exact one's within the ruler's reading
    rods = [(complex(*s.points[0]), complex(*s.points[1])) for s in rec.items
            if s.kind == "segment" and s.role == "link" and abs(s.points[0][1] - C.imag / mu) < 1e-6
            and abs(s.points[1][1] - C.imag / mu) < 1e-6]
    assert any(min(a.real, b.real) < x - ROD_PAST_MM + 1e-6 and max(a.real, b.real) >= x + ROD_PAST_MM - 1e-6
               for a, b in rods)
    # the scheme's rod too (framed: through its bushing) reaches past R03's point
    _, _, p, q, bush = yoke_at(fp, "3", fp.mu_l)
    assert bush is not None and max(p.real, q.real) >= line.real / fp.mu_l + ROD_PAST_MM - 1e-6


def test_table_1_keeps_v_s3_beside_v_c(plans):
    """v_S3 = v_C (the yoke translates): Table 1 heads the one column v_C = v_S3, its values the
    closed form ω·r·|sin φ| to the table's figures (the plan's reading: half a ruler's division)."""
    from graphplan.report.plans import plans_json
    from graphplan.sheets.kintables import velocity_table, velocity_twins
    from graphplan.util.markup import plain
    doc = plans_json(plans)
    assert velocity_twins(doc, 0.5) == {"C": ["S3"]}
    rec = velocity_table(doc, "uk")
    heads = [plain(i.text) for i in rec.items if i.kind == "text"]
    assert "v_C = v_S₃" in heads, heads
    for pos in doc["positions"]:
        e = pos["velocity"]["C"]
        assert (e["value"] or 0.0) == pytest.approx(OMEGA * R * abs(math.sin(math.radians(pos["phi_deg"]))),
                                                    abs=0.5 * plans.mu_v + 1e-3)
