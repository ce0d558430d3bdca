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
