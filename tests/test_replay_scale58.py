"""Stop 58, kin58b: the explorer's step 0 where the kinematics sheet's room grew a plan to a chosen
π a under 40 mm (sheets.kinlayout.into_room: its plans read by their size, docs/scenes.md) — it
says so, not "not shorter than 40 mm" beside a 35 mm length (the generated RRP-moving six-bar:
a_A = 10 m/s², μa 0.285 (m/s²)/mm, π a = 35.1 mm)."""
from __future__ import annotations

import math

import pytest

ARGS = (0.1, 0.4, 0.35, 0.3, 0.6, 30, 10, 1)      # tests/test_view_tutor.py's "RRP moving"


@pytest.fixture(scope="module")
def st():
    import random_mechanisms as R
    from conftest import scene_study
    text, ok = R.rrp_moving(*ARGS)
    assert ok
    return scene_study(text)


def step0(st, mu_a: float) -> dict:
    from graphplan.graphic.plans import build_plans
    from graphplan.report.explorer import explorer_data
    plans = build_plans(st, count=2, mu_l=0.004, mu_v=0.05, mu_a=mu_a)
    rec = next(r for r in explorer_data(st, step=30.0, lang="en", plans=plans, sheet="A1")["records"]
               if r["kind"] == "acceleration")
    return rec["steps"][0]


@pytest.mark.parametrize("mu_a, trial, short", [(0.285, 35, True), (0.248, 40, False)])
def test_a_chosen_length_says_why_it_may_be_short(st, mu_a, trial, short):
    """a_A = l_OA·ω² (ε = 0) = 0.1·10² = 10 m/s²: μa 0.285 draws 35.09 mm, the trial 35 mm, a plan
    read by its size; 0.248 draws 40.3 mm, trial 40, "not shorter than 40 mm"."""
    s = step0(st, mu_a)
    a_A = 0.1 * 10 ** 2
    assert s["scale"]["value"] == pytest.approx(a_A)
    assert s["scale"]["trial"] == trial == math.floor(a_A / mu_a)
    en = s["caption"]["en"]
    assert ("shorter than 40 mm: the plan reads by its size" in en) == short
    assert ("not shorter than 40 mm" in en) == (not short)
    assert f"{a_A:g}/{trial} " in en and f"= {a_A / mu_a:.1f} mm".replace("-", "−") in en
    assert ("коротше 40 мм: план читається за розміром" in s["caption"]["uk"]) == short
