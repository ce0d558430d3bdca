"""Review 45 #1: the pump six-bar's A1 force sheet (PUMP45 at φ = 120°, the lead's check) drew its
scheme and group II(2-3) at 1:10 — a 7 mm crank with 20 labels round O — with a third of the field
empty. The composition measured the lever once at a μv where its 48 mm figure is lettered 165 mm
across (the arms' labels on long leaders), took that margin for every μv, and the lever's row left
the scheme and the groups 1:10; measured there, their crowded lettering then barred 1:4 for good."""
from __future__ import annotations

import pytest

from conftest import scene_study
from review_scenes import PUMP45


def _family(**kw):
    from graphplan.sheets.compose import Family
    from graphplan.sheets.forces import Crowded
    # lines 40 × 30 mm at μ0 = 0.01, lettering 10 × 8 mm as first measured
    return Crowded(**vars(Family(0.01, [(40.0, 30.0, 10.0, 8.0)], (20.0, 6.0), **kw)))


def test_lettering_seen_round_a_small_drawing_is_not_assumed_round_a_larger_one():
    """Drawn at μ = 0.02 (half size: lines 20 × 15 mm) it came out 80 × 60 mm — 60 × 45 mm of
    lettering on leaders. A larger drawing (μ 0.005) is assumed to letter as first measured, a
    smaller one (μ 0.04) at least as far out as seen; drawn at 0.005 as 90 × 66 mm, its 10 × 6 mm
    is what 0.005 and every smaller drawing down to 0.02 take."""
    fam = _family()
    assert fam.allow(0.02, 80.0, 60.0, 0) is False
    assert fam.size(0.005, 0) == (80.0 + 10.0, 60.0 + 8.0 + 6.0)         # 2 × lines + the first lettering + caption
    assert fam.size(0.02, 0) == (20.0 + 60.0, 15.0 + 45.0 + 6.0)
    assert fam.size(0.04, 0) == (10.0 + 60.0, 7.5 + 45.0 + 6.0)
    assert fam.allow(0.005, 90.0, 66.0, 0) is True                       # 10 × 6 mm: as assumed, or less
    assert fam.size(0.01, 0) == (40.0 + 10.0, 30.0 + 8.0 + 6.0)          # the most of 0.005's and the first


def test_the_base_family_keeps_the_most_it_saw_anywhere():
    """The kinematics sheet's ``Family`` (unchanged): the largest lettering seen, at every scale."""
    from graphplan.sheets.compose import Family
    fam = Family(0.01, [(40.0, 30.0, 10.0, 8.0)], (20.0, 6.0))
    fam.allow(0.02, 80.0, 60.0, 0)
    assert fam.size(0.005, 0) == (80.0 + 60.0, 60.0 + 45.0 + 6.0)


@pytest.mark.slow
def test_the_pump_sheet_draws_its_scheme_and_groups_at_readable_scales():
    """At φ = 120° (the lead's check): the scheme at 1:4 or larger (its 70 mm crank ≥ 17 mm, the
    kinematics sheet's 1:2 within two steps), every group at the scheme's scale or larger (review
    4), and each force plan's largest vector at least 50 mm (II(4-5)'s 140 N at 20 N/mm was 7 mm,
    six of its nine forces under 2 mm) — read off the plans the sheet draws."""
    from graphplan.sheets import forces as sf
    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.form import form
    assert "force_phi_deg = 210" in PUMP45
    st = scene_study(PUMP45.replace("force_phi_deg = 210", "force_phi_deg = 120"))
    p, _, dr = sf.plan(st, form("A1"), SheetOptions(precision=0.5, sheet="forces"))
    crank = st.mech.crank.length
    assert crank / p.mu["scheme"] >= 17.0 - 1e-9, p.mu
    fp = dr.groups_fp(p.mu)
    exact = {g.label: max(abs(complex(dr.ks.reactions[k].force[0])) for k in g.reactions) for g in dr.ks.groups}
    for gp in fp.groups:
        assert (gp.mu_l or p.mu["groups"]) <= p.mu["scheme"] * (1 + 1e-9), (gp.label, gp.mu_l, p.mu)
        biggest = exact[gp.label] / (gp.mu_F or p.mu["forces"])      # the exact solver's reactions, mm
        assert biggest >= 50.0, (gp.label, biggest, gp.mu_F)
    # the crank group no larger than the largest other group (its 70 mm crank was drawn 140 mm at 2:1
    # beside groups at 1:4): its crank drawn no longer than their longest link drawn
    own = {gp.label: gp.mu_l or p.mu["groups"] for gp in fp.groups}
    others = [(st.mech.links[n].length or 0.0) / own[g.label] for g in dr.ks.groups if g.label != "I(0-1)"
              for n in g.links]
    assert crank / own["I(0-1)"] <= max(others) + 1e-6, (own, max(others))
    # review 45 #2: the lever (19 loads, their arms lettered) grown into the room left — p_v a = ω1·r / μv
    # at least 120 mm (the lead's sheet drew it at μv 0.0175: 75 mm, its arms' labels on long leaders)
    assert abs(st.mech.omega1) * crank / p.mu["lever"] >= 120.0, p.mu["lever"]
