"""Review 58 #2: a block sliding in a slotted lever (a coulisse, RPR) turns with it (ω₄ = ω₅), so its
inertia couple M^Φ₄ goes onto the Zhukovsky lever as the textbook carries any couple: a pair M/l at two
points of a link turning with it — the slotted lever's o₃ and e — never as a row «F = M, h = 0» whose
F·h is not F×h. Checked against the couple's virtual power M^Φ₄·ω₄ computed here from the exact
kinematics, and the lever's balancing moment against the kinetostatics'."""
from __future__ import annotations

import numpy as np
import pytest

from conftest import scene_study
from review_scenes import COULISSE_REVIEW58


@pytest.fixture(scope="module")
def fp():
    from graphplan.exact import kinetostatics
    from graphplan.graphic import forceplans
    st = scene_study(COULISSE_REVIEW58)
    phi = float(np.atleast_1d(kinetostatics.at_scene_angle(st))[0])
    return forceplans.construct(st, phi, precision=0.0)


def test_every_lever_row_is_a_force_times_its_arm(fp):
    rows = [t for t in fp.lever.terms if not t.pair]
    assert rows
    for t in rows:
        assert t.moment == pytest.approx(t.force * t.arm_mm, rel=1e-9, abs=1e-9), t.name


def test_the_blocks_couple_is_a_pair_on_the_slotted_levers_points(fp):
    """The pair M/l_O3E at e and o3 (ω₄ = ω₅): its moment about the pole is −M·ω₄/μv, the couple's
    virtual power over ω₁ in lever units."""
    ks = fp.ks
    block = next(ld for ld in ks.loads if ld.link == "4" and float(ld.couple[0]) != 0)
    pair = [t for t in fp.lever.terms if t.name in (block.name + "'", block.name + "''")]
    assert sorted(t.image for t in pair) == ["E", "O3"]
    l = abs(complex(ks.mech.links["O3E"].local["E"]) - complex(ks.mech.links["O3E"].local["O3"]))
    assert all(t.force == pytest.approx(abs(float(block.couple[0])) / l) for t in pair)
    omega4 = float(block.omega[0])
    assert omega4 == pytest.approx(float(np.atleast_1d(ks.kin.bodies["O3E"].omega)[0]))
    moment = sum(t.moment for t in pair)
    assert moment == pytest.approx(-float(block.couple[0]) * omega4 / fp.lever.mu_v, rel=1e-6)


def test_the_lever_balances_as_the_kinetostatics(fp):
    assert fp.lever.balancing == pytest.approx(float(np.atleast_1d(fp.ks.balancing)[0]), rel=1e-6)
