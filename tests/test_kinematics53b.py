"""Stop 53 (kin53b), the blind review's marks on the diagrams' table (Table 4 on a rocker's sheet):

- #9: δ of a reading whose exact value is zero (the extreme position 0: ω = 0) is "—", the sheet's
  own rule ("δ not computed where the exact value is ≈ 0"), not "0,00";
- #10: the same plan reading of ω signed both ways on one sheet (Table 1 + counter-clockwise, Table 4
  + clockwise as the diagrams draw the rocker's turn from position 0): Table 4 says its convention
  under itself, and both signs agree with the closed form's sense of the rocker's turn;
- #11: "No." (not "№") heads the English tables' position column.

The rocking coulisse LINK49 (its closed form in test_displacement_sense49): the line O A through the
crank pin turns by γ(θ) = atan2(d + r sin θ, r cos θ), the crank θ = θ0 − 30°·k clockwise."""
from __future__ import annotations

import math

import pytest

from graphplan.report.plans import plans_json
from graphplan.sheets.kintables import readings_table, velocity_table
from test_displacement_sense49 import _cells, _value, coulisse49  # noqa: F401  (the module's fixture)


def _gamma_rate_sign(k: int) -> int:
    """The sense of the coulisse's turn at position k, + counter-clockwise: dγ/dt = dγ/dθ·dθ/dt with
    dθ/dt < 0 (the crank turns clockwise)."""
    r, d = 0.09, 0.22
    th = math.atan2(-d, 0.0) - math.acos(r / d) - math.radians(30.0 * k)
    h = 1e-6
    gamma = lambda t: math.atan2(d + r * math.sin(t), r * math.cos(t))   # noqa: E731
    return -1 if (gamma(th + h) - gamma(th - h)) > 0 else 1


def _titled(rows: list[list[str]]) -> list[list[str]]:
    """A table's title as one row where it wraps under a narrow table (Table 1's "|v|" title, review 56)."""
    rows = [list(r) for r in rows]
    while len(rows) > 1 and len(rows[0]) == 1 and len(rows[1]) == 1:
        rows[0] = [rows[0][0] + " " + rows.pop(1)[0]]
    return rows


@pytest.fixture(scope="module")
def tables(coulisse49):
    from graphplan.graphic.plans import build_plans
    st, d = coulisse49
    doc = plans_json(build_plans(st))
    return {lang: (_titled(_cells(velocity_table(doc, lang, 0.5))), _cells(readings_table(d, doc, lang, 4, 0.5)))
            for lang in ("uk", "en")}


def test_no_delta_of_a_zero_exact_value(tables):
    _, t4 = tables["en"]
    omega = next(i for i, r in enumerate(t4) if r[0].lstrip("−").startswith("ω"))
    exact, delta = t4[omega + 2], t4[omega + 3]
    assert exact[0] == "exact" and delta[0].startswith("δ")
    assert _value(exact[1]) == 0.0 and delta[1] == "—"          # position 0, the coulisse's extreme
    assert all(c != "—" for c in delta[2:])                    # elsewhere δ is computed


def test_one_sign_convention_said_per_table_and_both_agree_with_the_closed_form(tables):
    for lang, cw, ccw in (("uk", "+ за годинниковою стрілкою", "+ проти годинникової стрілки"),
                          ("en", "+ clockwise", "+ counter-clockwise")):
        t1, t4 = tables[lang]
        title = t1[0][0].replace("\xa0", " ")
        assert ("+ проти" if lang == "uk" else ccw) in title    # Table 1's title: ω + counter-clockwise
        col = next(j for j, h in enumerate(t1[1]) if h.startswith("ω"))
        plan = next(r for r in t4 if r[0] in ("план", "plan"))
        for k in range(1, 12):
            truth = _gamma_rate_sign(k)
            assert math.copysign(1, _value(t1[k + 2][col])) == truth, (lang, k)
            assert math.copysign(1, _value(plan[k + 1])) == -truth, (lang, k)     # Table 4: + clockwise
        said = " ".join(r[0] for r in t4 if len(r) == 1).replace("\xa0", " ")
        assert cw in said and ccw in said, said                # … and says so under itself


def test_english_tables_head_their_position_column_no(tables):
    assert tables["en"][0][1][0] == "No." and tables["en"][1][1][0] == "No."
    assert tables["uk"][0][1][0] == "№" and tables["uk"][1][1][0] == "№"


def test_a_slider_drawn_against_its_guide_says_so_under_table_4():
    """COMPRESSOR11: the piston's diagrams drawn + away from position 0, i.e. against its guide
    (``drawn_sense`` −1): Table 4 says so under itself, and its "plan" and "exact" rows carry that
    sign."""
    import review_scenes

    from conftest import scene_study
    from graphplan.graphic.diagrams import chord_diagrams
    from graphplan.graphic.plans import build_plans
    st = scene_study(review_scenes.COMPRESSOR11)
    d = chord_diagrams(st, divisions=12, L=200.0, H1=25.0, H2=30.0)
    assert d.sign == -1
    doc = plans_json(build_plans(st))
    t4 = _cells(readings_table(d, doc, "en", 4, 0.5))
    said = " ".join(r[0] for r in t4 if len(r) == 1).replace("\xa0", " ")
    assert "+ away from position 0, against the guide" in said and "give the magnitudes |v|, |a|" in said
    plan = next(r for r in t4 if r[0] == "plan")
    exact = t4[t4.index(plan) + 1]
    assert exact[0] == "exact"
    for k, (p_, e_) in enumerate(zip(plan[1:], exact[1:])):      # the plan's v in the table's own sign
        if p_ != "—" and abs(_value(e_)) > 0.05:
            assert math.copysign(1, _value(p_)) == math.copysign(1, _value(e_)), k
            # … which is the diagram's: + against the guide (the solver's v along it, turned)
            assert math.copysign(1, _value(e_)) == -math.copysign(1, float(d.truth["v_at"][d.at_positions[k]])), k
