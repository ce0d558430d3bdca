"""Reviews 10 and 11 on the kinematics sheet: three significant figures in the tables, one count of
decimals for the ε rows, a subscript's own index (a^n_{BO₂}), every thick position's letters with its
number, the title block's name broken before its parenthesis, the force position's crank angle as
the kinematics sheet writes position 0's."""
from __future__ import annotations

import math

from conftest import scene_study
from review_scenes import COMPRESSOR11, SIXBAR10
from graphplan.drawing.plans import joints_at, position_record
from graphplan.graphic.plans import build_plans
from graphplan.report.plans import acceleration_cells, places
from graphplan.sheets.form import SLACK, balanced_wrap, wrap
from graphplan.util.markup import plain, runs


def _figures(text: str) -> int:
    """Significant figures of a printed number ("0,125" → 3, "0,080" → 2)."""
    digits = text.replace("−", "").replace("-", "").replace(",", "").replace(".", "").lstrip("0")
    return len(digits)


def test_a_velocity_column_keeps_three_figures_for_its_typical_values():
    """review 10 #9: v_B 0,08 (4 mm × μv 0,02) beside three-figure columns. The column's typical
    values (from its median up) keep three figures; the smaller ones (0,080, a dead centre's 0,004)
    the same decimals with fewer figures, the column one count of decimals."""
    values = [0.08, 0.16, 0.12, 0.1, 0.14, 0.004]
    d = places(values, longest_mm=8.0, precision=0.5, mu=0.02)
    printed = [f"{v:.{d}f}" for v in values]
    assert d == 3 and printed[0] == "0.080"
    assert all(_figures(p) >= 3 for p, v in zip(printed, values) if v >= sorted(values)[(len(values) - 1) // 2])


def test_the_epsilon_rows_share_one_count_of_decimals():
    """review 10 #9: ε2 −62,548 beside ε3 −13,49 and ε4 1,42. One count for the ε rows: the smallest
    keeps three figures, the largest at most four."""
    pos = {"mu_a": 0.0823, "acceleration": {
        "BA": {"mm": 192.0, "value": 15.8016, "analytic": 15.767},
        "eps_AB": {"value": 62.548, "analytic": 62.331, "sense": "cw", "from_mm": 190.0},
        "eps_O2B": {"value": 13.49, "analytic": 13.14, "sense": "cw", "from_mm": 29.5},
        "eps_EF": {"value": 1.42, "analytic": 1.27, "sense": "ccw", "from_mm": 4.5}}}
    cells = acceleration_cells(pos, "uk")
    eps = [cells[k][0] for k in ("eps_AB", "eps_O2B", "eps_EF")]
    decimals = {len(c.split(",")[1]) for c in eps}
    assert len(decimals) == 1, eps
    assert min(_figures(c) for c in eps) >= 3 and max(_figures(c) for c in eps) <= 4, eps


def test_a_subscripts_index_is_set_lower():
    """review 10 #17: a^n_BO2 printed «BO2» on one line; the lab writes a^n_{BO₂}. An all-digit
    subscript (R_05, H_1) stays one subscript."""
    r = runs("a^n_BO2")
    assert [(x.text, x.level) for x in r[2:]] == [("BO", -1), ("2", -2)] and r[2].stacked
    assert [(x.text, x.level) for x in runs("R_05")] == [("R", 0), ("05", -1)]
    assert plain("l_O1A") == "l_O₁A" and plain("v_S2") == "v_S₂"


def test_the_title_block_breaks_before_the_parenthesis():
    """review 10 #20: «… привода сита (рецензія» / «10)». A draftsman breaks before «(рецензія»; the
    same count of lines as the greedy wrap."""
    title = "Шестиланковий важільний механізм привода сита (рецензія 10)"
    for size in (5.0, 3.5, 2.5):
        lines = balanced_wrap(title, 68 / SLACK, size)
        assert len(lines) == len(wrap(title, 68 / SLACK, size))
        assert all(line.count("(") == line.count(")") for line in lines), lines
        assert " ".join(lines) == title


def test_every_thick_position_is_lettered_with_its_number():
    """review 11 #15: position 4's slider a plain «B» beside position 9's A₉, B₉. With two thick
    positions each one's moving joints carry its number."""
    st = scene_study(COMPRESSOR11)
    plans = build_plans(st)
    rec = position_record(plans)
    texts = {q.text for q in rec.items if q.kind == "text"}
    for k in (4, 9):
        assert {f"A_{{{k}}}", f"B_{{{k}}}"} <= texts, sorted(texts)
    assert "B" not in texts and "A" not in texts


def test_the_force_position_gives_the_crank_angle_as_the_kinematics_sheet():
    """review 10 #17: «кут кривошипа 285,50°» on the forces sheet, 75,5° on the kinematics sheet. Both
    are the angle from the x axis (position 0 at 75,5°, the force position 150° clockwise from it:
    75,5 − 150 + 360 = 285,5), written alike: one decimal, «від осі x»."""
    from graphplan.sheets.forces import force_position
    from graphplan.sheets.kintables import phi_convention
    st = scene_study(SIXBAR10)
    phi0 = st.phi0 if hasattr(st, "phi0") else st.positions.phi0
    phi = (phi0 - 150.0) % 360.0
    said, kin = force_position(st, phi, "uk"), phi_convention(phi0, "uk")
    assert f"{phi:.1f}".replace(".", ",") + "° від осі x" in said and "150" in said, said
    assert f"{phi0 % 360:.1f}".replace(".", ",") + "° від осі x" in kin
    assert math.isclose(phi, 285.5, abs_tol=0.06)
