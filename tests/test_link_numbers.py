"""ω and ε by the link's number, as the lab writes them (the review's correction 8): the four-bar's
coupler AB is link 2 and its rocker O2B link 3, so the tables read ω2, ω3, ε2, ε3 — not ω_AB,
ω_O2B — on the sheet and in the terminal alike; the JSON keeps its keys (omega_AB) and adds the
number. The structural formula names each group once, with its kind."""
from __future__ import annotations

import re

import pytest

from conftest import example, scene_study
from test_link_points import FOURBAR


@pytest.fixture(scope="module")
def fourbar_plans():
    from graphplan.graphic.plans import build_plans
    st = scene_study(FOURBAR)
    return st, build_plans(st, precision=0.5)


def _texts(rec) -> list[str]:
    return [p.text for p in rec.items if p.kind == "text"]


def test_tables_write_omega_and_epsilon_by_the_links_number(fourbar_plans):
    from graphplan.report.plans import plans_json, plans_table
    from graphplan.sheets.kintables import acceleration_table, velocity_table
    st, plans = fourbar_plans
    numbers = {name: link.number for name, link in st.mech.links.items()}
    assert numbers["AB"] == 2 and numbers["O2B"] == 3          # the scene's own numbers
    doc = plans_json(plans)
    first = doc["positions"][0]
    assert {"omega_AB", "omega_O2B"} <= set(first["velocity"])                 # the keys kept
    assert first["velocity"]["omega_O2B"]["link_number"] == 3
    head = _texts(velocity_table(doc, "uk"))
    assert "ω_{2}" in head and "ω_{3}" in head, head
    pos = next(p for p in doc["positions"] if "acceleration" in p)
    rows = _texts(acceleration_table(pos, 2, "uk"))
    assert "ε_{2}" in rows and "ε_{3}" in rows, rows
    for text in head + rows:
        assert not re.search(r"[ωε]_\{?(AB|O2B)", text), text
    term = plans_table(plans, "uk")
    assert "ω₂" in term and "ω₃" in term and "ε₃" in term and "ω_AB" not in term and "ωAB" not in term


@pytest.mark.parametrize("name", ["shaper"])
def test_the_shapers_columns_are_all_numbers(name):
    """The shaper mixed ω_OB, ω₂, ω_BC: every ω and ε now by its link's number (a stone and the
    coulisse it slides in turn together: one column headed by both numbers, «ω₂ = ω₃»)."""
    from graphplan.graphic.plans import build_plans
    from graphplan.report.plans import plans_json
    from graphplan.sheets.kintables import velocity_table
    st = example(name)
    doc = plans_json(build_plans(st, precision=0.5, count=4))
    head = [t for t in _texts(velocity_table(doc, "en")) if t.startswith(("ω", "ε"))]
    numbers = {str(link.number) for link in st.mech.links.values()}
    named = [re.findall(r"[ωε]_\{(\d+)\}", t) for t in head]
    assert head and all(re.fullmatch(r"[ωε]_\{\d+\}( = [ωε]_\{\d+\})?", t) for t in head), head
    assert all(n in numbers for ns in named for n in ns), head
    assert ["2", "3"] in named, head        # the stone 2 in the coulisse 3


def test_the_structural_formula_names_each_group_once(fourbar_plans):
    from graphplan.sheets.kintables import notes
    st, _ = fourbar_plans
    line = next(t for t in _texts(notes(st, [], [], "uk")) if t.startswith("Структурна"))
    assert line.count("II(2-3)") == 1 and line.endswith("I(0-1) → II(2-3) ВВВ"), line
