"""Stop 53 (the lead's LINK53: a two-cylinder compressor with an articulated rod, the crank O1A
clockwise, pistons B and C on fixed guides at 60° and 120° through O1): the terminal's ω, ε tables
without the pistons (a slider on a fixed guide does not turn), and the tables' block with the first
table over and the last under the columns of those between."""
from __future__ import annotations

import math

import numpy as np
import pytest

from conftest import scene_study
from review_scenes import LINK53


@pytest.fixture(scope="module")
def link53():
    return scene_study(LINK53)


def _table(text: str, head: str) -> list[str]:
    """The lines of the terminal's table titled ``head`` (up to the next blank line)."""
    lines = text.splitlines()
    k = next(i for i, ln in enumerate(lines) if ln.startswith(head))
    out = []
    for ln in lines[k + 1:]:
        if not ln.strip():
            break
        out.append(ln)
    return out


def test_analyze_prints_no_omega_or_epsilon_of_the_pistons(link53):
    """``analyze``'s ω and ε tables name the rods AB and KC only — the pistons B and C slide on
    guides the frame carries, their ω, ε are 0 by the pair (they printed columns of zeros) — and ω of
    the master rod is the crank-slider's closed form (guide through O1 at 60°, θ = φ − 60°):
    sin ψ = −r sin θ / L, ω₂ = −ω₁ r cos θ / (L cos ψ)."""
    from graphplan.report.analysis import analyze_table
    phi = np.array([0.0, 300.0])
    text = analyze_table(link53, phi, [0, 1], lang="en")
    omega = _table(text, "Angular velocities")
    eps = _table(text, "Angular accelerations")
    assert omega[0].split()[-2:] == ["ω_AB", "ω_KC"] and eps[0].split()[-2:] == ["ε_AB", "ε_KC"]
    assert "ω_B" not in omega[0] and "ω_C" not in omega[0] and "ε_B" not in eps[0] and "ε_C" not in eps[0]
    w1, r, L = -2 * math.pi * 360 / 60, 0.055, 0.22
    for row, p in zip(omega[1:], phi):
        th = math.radians(p - 60.0)
        psi = math.asin(-r * math.sin(th) / L)
        expected = -w1 * r * math.cos(th) / (L * math.cos(psi))
        assert float(row.split()[2]) == pytest.approx(expected, rel=1e-3)


def test_only_the_links_on_the_frames_guides_count_as_translating():
    """The links left out of the ω, ε tables: the pistons B, C (on the frame's guides b, c); the rods
    AB, KC, which turn, stay."""
    from graphplan.report.analysis import _translates
    st = scene_study(LINK53)
    assert [n for n in st.mech.links if _translates(st.mech, n)] == ["B", "C"]


def test_the_first_table_over_and_the_last_under_the_columns_between():
    """The compressor's tables (T1 190 × 95, T2 90 × 110, T3 58 × 53, T4 175 × 66 mm): T1 across the
    top, T2 | T3 side by side under it, T4 across under them, in reading order, none meeting another,
    all in the block — 58 mm lower than T1 over the one column T2, T3, T4 (which left 100 × 178 mm
    blank beside T2, T3)."""
    from graphplan.drawing.layout import GAP, Leaf
    from graphplan.sheets.kinlayout import place_tables, table_groups, tables_size
    tabs = [Leaf(f"T{i}", w, h) for i, (w, h) in enumerate(((190, 95), (90, 110), (58, 53), (175, 66)), 1)]
    groups = table_groups(tabs, 2, (), True, True)
    w, h = tables_size(groups, True, True)
    assert (w, h) == (190, 95 + GAP + 110 + GAP + 66)
    boxes = {p.name: p.box for p in place_tables(groups, w, 0.0, True, True)}
    from test_kin_review46 import inside_and_apart
    inside_and_apart([t.name for t in tabs], boxes, w, h)
    assert boxes["T1"][1] >= boxes["T2"][3] and boxes["T3"][0] >= boxes["T2"][2]          # T1 over, T2 | T3
    assert boxes["T4"][3] <= min(boxes["T2"][1], boxes["T3"][1])                           # T4 under both
    assert boxes["T1"][0] == boxes["T2"][0] == boxes["T4"][0] == 0.0                        # one left edge
    one = tables_size(table_groups(tabs, 1), False, False)
    assert one[1] - h == pytest.approx(53 + GAP)


# -- SLOTTED_CRANK53 (kin53's own): the block 2 slides in the slot of the crank 1 -----------------------

@pytest.fixture(scope="module")
def slotted_plans():
    from graphplan.graphic.plans import build_plans
    from review_scenes import SLOTTED_CRANK53
    return build_plans(scene_study(SLOTTED_CRANK53), accel=[3])


def _arm_angle(phi: float) -> float:
    """The arm O2B's angle where the crank's slot (the line through O1 at φ) meets the circle
    |B − O2| = 0.10 (the scene's numbers): B = λ·e^{iφ}, λ = O2·e + √((O2·e)² − |O2|² + R²)."""
    O2, R = complex(0.04, -0.03), 0.10
    e = complex(math.cos(phi), math.sin(phi))
    p = (O2.conjugate() * e).real
    lam = p + math.sqrt(p * p - abs(O2) ** 2 + R * R)
    return math.atan2((lam * e - O2).imag, (lam * e - O2).real)


def test_a_block_in_the_cranks_slot_has_no_omega_or_epsilon_entry(slotted_plans):
    """The block turns with the crank (ω2 = ω1, ε2 = ε1 = 0: given, not read off a plan): the plans
    carry no ω2, ε2 of it (Table 1 printed −10,5 at every position, Table 2 ε2 = 0); the arm's ω3 is
    the closed form's dψ/dφ · ω1 (ψ by ``_arm_angle``, central difference), its ε3 the same of ω3."""
    w1 = -2 * math.pi * 100 / 60
    for p in slotted_plans.positions:
        keys = set(p.velocity.entries)
        assert "omega_2" not in keys and "omega_O2B" in keys
        phi, h = math.radians(p.phi), 1e-5
        dpsi = (_arm_angle(phi + h) - _arm_angle(phi - h)) / (2 * h)
        omega3 = p.velocity.entries["omega_O2B"].exact.real
        assert omega3 == pytest.approx(dpsi * w1, rel=1e-5)
        if p.acceleration is not None:
            assert "epsilon_2" not in p.acceleration.entries
            d2 = (_arm_angle(phi + h) - 2 * _arm_angle(phi) + _arm_angle(phi - h)) / h ** 2
            eps3 = p.acceleration.entries["epsilon_O2B"].exact.real
            assert eps3 == pytest.approx(d2 * w1 ** 2, rel=1e-3)


def test_one_centre_at_its_middle_is_said_in_the_singular(link53):
    """Table 3's footnote: the one centre S4 at its link's middle — "S₄: at the middle of its link",
    "S₄ — посередині ланки" (it said "at the middles of their links" of the one point)."""
    from graphplan.sheets.kintables import dimensions_table
    for lang, one, many in (("en", "at the middle of its link", "middles"), ("uk", "посередині ланки", "посередині ланок")):
        texts = " ".join(q.text for q in dimensions_table(link53, 0.001, lang).items if q.kind == "text")
        assert one in texts and many not in texts
