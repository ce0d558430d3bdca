"""Review 56 (kinematics, items 3–6): the plans' tables against their sign note, a coulisse's
position letters, a short p_v a said in the notes, the toggle press's missing inputs."""
from __future__ import annotations

import cmath
import math

import numpy as np
import pytest

from conftest import example, scene_study
from review_scenes import SLOTTED_LEVER_EN56, TOGGLE_PRESS56


def _doc(st, **kw):
    from graphplan.graphic.plans import build_plans
    from graphplan.report.plans import plans_json
    plans = build_plans(st, **kw)
    return plans, plans_json(plans)


@pytest.mark.slow
@pytest.mark.parametrize("name", ["TOGGLE_PRESS56", "crank_slider", "shaper"])
def test_plans_tables_give_magnitudes_the_exact_solver_agrees(name):
    """Review 56 #3: Table 1 printed v_C = 0,160 while the ram moved down (−0,1605 along its 90°
    guide) under a note «+ у напрямку напрямної». The tables give |v|, |a| (the vector's length × μ)
    and say so; every vector entry equals the exact solver's |v| of its point at the position's
    crank angle (a slider's: |its projection on the guide|), to the ruler's precision."""
    from graphplan.exact.positions import point_slider
    from graphplan.model.mechanism import FRAME
    st = scene_study(TOGGLE_PRESS56) if name == "TOGGLE_PRESS56" else example(name)
    plans, doc = _doc(st)
    phis = np.array([pos["phi_deg"] for pos in doc["positions"]])
    kin = st.solve(phis)
    slider = point_slider(st.mech, st.output.name) if st.output.kind == "slide" else None
    checked = 0
    for i, pos in enumerate(doc["positions"]):
        for key, e in pos["velocity"].items():
            if e.get("sense") is not None or e.get("mm") is None or not key.isalnum() or len(key) > 2 \
                    or key not in {p for link in st.mech.links.values() for p in link.local}:
                continue
            v = complex(kin.point(key)[1][i])
            if slider is not None and key == st.output.name:
                g = st.mech.guides[st.mech.links[slider].slides_on]
                assert g.body == FRAME
                v = (v * cmath.exp(-1j * g.angle)).real            # along the guide, signed
            assert e["value"] >= 0.0                                  # a magnitude, as the title says
            tol = max(0.5 * plans.mu_v + 1e-9, 0.002 * abs(v))      # half a ruler division
            assert abs(e["value"] - abs(v)) <= tol, (name, pos["index"], key, e["value"], v)
            checked += 1
    assert checked >= len(doc["positions"])
    from graphplan.util.words import word
    for lang in ("uk", "en"):
        assert "|v|" in word("kin vel_table_signed", lang)
        assert "|a|" in word("kin acc_table_signed", lang, n=2, i=4)
        for key in ("kin signs", "kin signs_back"):
            text = word(key, lang, guide="X")
            assert "|v|, |a|" in text
            assert "таблицях планів: +" not in text and "plans' tables: +" not in text


def test_toggle_press_ram_moves_down_at_position_1():
    """The reviewer's case, independently: at position 1 the ram C moves down its 90° guide
    (v along it ≈ −0,1605 m/s) while Table 1 prints 0,160 — now headed |v|."""
    st = scene_study(TOGGLE_PRESS56)
    _, doc = _doc(st)
    pos = doc["positions"][1]
    v = complex(st.solve(np.array([pos["phi_deg"]])).point("C")[1][0])
    assert v.imag == pytest.approx(-0.1605, abs=5e-4) and abs(v.real) < 1e-9
    assert pos["velocity"]["C"]["value"] == pytest.approx(0.160, abs=0.002)


def test_coulisse_positions_are_numbered_not_lettered_A2_A8():
    """Review 56 #4: the slotted lever's crank pin at the acceleration plans' positions 2 and 8 was
    lettered A₂, A₈ — on a sheet where A₂, A₃ are the block's and the lever's point A (v_A3A2).
    Now the pin there carries the plain A (at the first) and the positions' numbers, 2 and 8; a
    mechanism without a coulisse keeps its B₈ (review 6 #11)."""
    from graphplan.drawing.plans import coulisse_points, position_record
    from graphplan.graphic.plans import build_plans
    st = scene_study(SLOTTED_LEVER_EN56)
    assert coulisse_points(st.mech) == {"A"}
    plans = build_plans(st)
    texts = [p.text for p in position_record(plans, lang="en").items if p.kind == "text"]
    assert not any(t.startswith("A_{") and not t.startswith("A_{3") for t in texts), texts
    numbers = {n for t in texts for n in t.split(", ")}
    assert {"2", "8"} <= numbers
    assert coulisse_points(example("crank_slider").mech) == set()


def test_toggle_press_tables_carry_the_guide_and_v_CB():
    """Review 56 #6: Table 3 gave O2 from O1 but not the ram's guide (x = 0, through O2, so its
    distance from O2 is 0): X is given from O1, 0.28 m (O1 = (0.28, 0.22)); Table 1 left v_CB out
    as a column equal to v_B (O2B = BC: the toggle's kite), while ω4 stood there."""
    from graphplan.sheets.kintables import guide_distances, velocity_columns
    st = scene_study(TOGGLE_PRESS56)
    (label, d, g, pivot), = guide_distances(st)
    assert (label, pivot) == ("X", "O1") and d == pytest.approx(0.28, abs=1e-12)
    _, doc = _doc(st)
    cols = velocity_columns(doc, 0.5)
    assert "CB" in cols and "BA" in cols and "B" in cols
    # v_CB = v_B at every position, independently: ω4·BC = ω3·O2B with BC = O2B
    kin = st.solve(np.array([p["phi_deg"] for p in doc["positions"]]))
    vb, vc = kin.point("B")[1], kin.point("C")[1]
    assert np.allclose(np.abs(vc - vb), np.abs(vb), atol=1e-9)


def test_a_short_p_v_a_is_said_with_the_plan_that_bounds_it():
    """Review 56 #5: the slotted lever's A3 set drew p_v a = 35 mm (docs/scenes.md: 40 mm where
    the sheet has the room) — plan 10's p_v e is 160 mm there, so the plans read by their size
    (kinlayout.readable). The notes say which plan bounds the scale and its length at 40 mm:
    v_E/v_A times 40, from the exact solver."""
    from graphplan.sheets.kintables import short_poles
    st = scene_study(SLOTTED_LEVER_EN56)
    _, doc = _doc(st, mu_v=0.0239, mu_a=0.5)
    (uk,), (en,) = short_poles(st, doc, "uk", 0.5), short_poles(st, doc, "en", 0.5)
    pos = doc["positions"][10]
    kin = st.solve(np.array([pos["phi_deg"]]))
    ve, va = abs(kin.point("E")[1][0]), abs(kin.point("A")[1][0])
    at = 40.0 * ve / va
    assert "p_{v}e" in en and "plan 10" in en and "плану 10" in uk
    said = float(en.rsplit("be ", 1)[1].split(" mm")[0])
    assert abs(said - at) <= 1.0
    _, doc40 = _doc(st)                    # μv 0.02: p_v a 40 mm or more, nothing to say
    assert short_poles(st, doc40, "en", 0.5) == []
    assert math.isfinite(at)
