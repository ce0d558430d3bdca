"""Stop 56 (misc56): the explorer (`graphplan view`) opened on the lead's six-bar, as a student
learning the method would read it."""
from __future__ import annotations

import functools

from conftest import scene_study
from review_scenes import MISC56


@functools.lru_cache(maxsize=None)
def _data(text: str):
    from graphplan.graphic.plans import build_plans
    from graphplan.report.explorer import explorer_data
    st = scene_study(text)
    plans = build_plans(st, precision=0.5)
    return st, plans, explorer_data(st, step=10.0, plans=plans)


def test_each_quantity_is_one_row_of_the_values_table():
    """The slider D on the frame's guide was a row v_D and again a row «v_D» (its slide along the
    fixed guide, the same velocity, signed): a student saw v_D twice."""
    st, plans, data = _data(MISC56)
    symbols = [r.get("symbol") or r["q"] for r in data["rows"]]
    assert len(symbols) == len(set(symbols)), symbols
    assert "v_D" in symbols and "a_D" in symbols
    assert not any(r["q"].startswith("vrel_") for r in data["rows"])      # no slide in a moving slot here


def test_the_crank_s_step_writes_omega_l_as_computed():
    """The step «p_va = v_A = ω_1·l_{O1A} = …» and «πa = a_A = ω_1^2·l_{O1A} = …» wrote the plan's reading
    (70,5 mm × μ_v = 0,7543; 115,1 mm × μ_a = 9,473) as if it were ω_1·l (0,754) and ω_1²·l (9,475), one
    step after the scale's step had written a_A = 9,475: the formula's own value now."""
    import math

    from graphplan.report.replay import num
    st, plans, data = _data(MISC56)
    omega, l = 120 * 2 * math.pi / 60, 0.06          # the scene: 120 rpm, l_O1A = 0.06 m
    steps = [s["caption"]["en"] for r in data["records"] for s in r["steps"]]
    v = [c for c in steps if "= ω_1·l_{O1A} = " in c]
    a = [c for c in steps if "= ω_1^2·l_{O1A} = " in c]
    assert v and a
    assert all(f"= ω_1·l_{{O1A}} = {num(omega * l, 'en')} m/s" in c for c in v), v[0]
    assert all(f"= ω_1^2·l_{{O1A}} = {num(omega ** 2 * l, 'en')} m/s²" in c for c in a), a[0]
