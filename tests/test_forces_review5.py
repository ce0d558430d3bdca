"""The fifth review's force sheet of an offset crank-slider press (review5, items 7, 8, 11): the
Zhukovsky lever's letters at their own arrows, the outer reaction's components R^τ12 and R^n12 drawn
at A and listed as seed 000's table 2.4 lists them, the charts over the turn closed by the division
"12" and the resistance chart's force axis graduated at a round step."""
from __future__ import annotations

import math

import pytest

from conftest import example, scene_study
from review_scenes import PRESS_EN
from test_forces_press import PRESS


@pytest.fixture(scope="module")
def press_fp():
    from graphplan.sheets import forces as sf
    from graphplan.sheets.compose import SheetOptions
    return sf.ForceDrafter(scene_study(PRESS_EN), SheetOptions(precision=0.5, sheet="forces")).fp()


@pytest.fixture(scope="module")
def press_turn():
    from graphplan.drawing.charts import turn
    return turn(scene_study(PRESS_EN))


def _lever_strays(rec, lang: str) -> list:
    """The lever's force letters that do not read as their own arrow's: another arrow nearer the
    letter's box — unless the letter stands on a leader from its own arrow (its end or its shaft), ≥ 1.5 mm clear of
    every other arrow (the lever's vectors carry "G2: h = … mm"; the name is before the colon)."""
    from graphplan.drawing.labels import box_to_segment
    from graphplan.util.words import force_symbol
    arrows = {q.text.split(":")[0]: (complex(*q.points[0]), complex(*q.points[1]))
              for q in rec.items if q.kind == "vector" and q.text}
    by_letter = {force_symbol(n, lang): n for n in arrows}
    leaders = [(complex(*q.points[0]), complex(*q.points[1])) for q in rec.items
               if q.kind == "segment" and q.role == "label"]
    out = []
    for q in rec.items:
        if q.kind != "text" or q.layer != "labels" or q.text not in by_letter:
            continue
        name, box = by_letter[q.text], q.bounds()
        gaps = sorted((box_to_segment(box, a, b), n) for n, (a, b) in arrows.items())
        if gaps[0][1] == name:
            continue
        a, b = arrows[name]
        led = any(min(box_to_segment(box, z, z) for z in ld) < 1.5
                  and min(box_to_segment((z.real, z.imag, z.real, z.imag), a, b) for z in ld) < 2.0
                  for ld in leaders)
        if not (led and all(g >= 1.5 for g, n in gaps if n != name)):
            out.append((q.text, gaps[:2]))
    return out


def test_the_press_levers_letters_stand_at_their_own_arrows(press_fp):
    """Review5 #8: "G2" sat on Φ2's arrowhead and "Φ2" beside G2's arrow. Every force's letter on
    the lever (both languages) is nearer its own arrow than any other, or on a leader from it."""
    from graphplan.drawing.forces import lever_record
    for lang in ("en", "uk"):
        rec = lever_record(press_fp, lang)
        assert len([q for q in rec.items if q.kind == "vector"]) >= 6
        assert not _lever_strays(rec, lang), lang


@pytest.mark.parametrize("scene", ["shaper", "slotter", "press4"])
def test_the_examples_levers_letters_stand_at_their_own_arrows(scene):
    """The same on the examples' levers and on review4's six-bar press."""
    from graphplan.drawing.forces import lever_record
    from graphplan.sheets import forces as sf
    from graphplan.sheets.compose import SheetOptions
    st = scene_study(PRESS) if scene == "press4" else example(scene)
    fp = sf.ForceDrafter(st, SheetOptions(precision=0.5, sheet="forces")).fp()
    assert not _lever_strays(lever_record(fp, "uk"), "uk")


def test_the_outer_reaction_is_drawn_and_listed_with_its_components(press_fp):
    """Review5 #7: group II(2–3) drew only the whole R12 at A. Seed 000 draws R^τ (from the moment
    equation about B) and R^n (along AB, from the plan) and lists R^τ, R^n and R. Both are drawn
    from A — R^τ across AB, R^n along it — and the table's values equal the exact reaction's
    components across and along AB within the ruler's half-millimetre at μF (and 1 %)."""
    from graphplan.drawing.forces import group_record, group_table_record
    fp = press_fp
    gp = next(g for g in fp.groups if "2-3" in g.label)
    a, b = gp.points["A"], gp.points["B"]
    u = (b - a) / abs(b - a)
    exact = complex(fp.ks.reactions["R12"].force[0])           # on AB from the crank
    along, across = (exact * u.conjugate()).real, (exact * u.conjugate()).imag
    for lang in ("en", "uk"):
        rec = group_record(fp, gp, lang)
        vec = {q.text: (complex(*q.points[0]), complex(*q.points[1])) for q in rec.items if q.kind == "vector"}
        for name, parallel in (("R12τ", False), ("R12n", True)):
            t, h = vec[name]
            d = (h - t) / abs(h - t)
            cos = abs((d * u.conjugate()).real)
            assert (cos > 0.999) if parallel else (cos < 0.02), (name, cos)
            ends = [w for w in vec["R12"]]
            assert min(abs(e - w) for e in (t, h) for w in ends) < 6.0, name    # at A, by R12
        texts = {q.text for q in rec.items if q.kind == "text"}
        assert {"R^{τ}_{12}", "R^{n}_{12}", "R_{12}"} <= texts, texts
        table = group_table_record(fp, gp, lang)
        cells = [q.text for q in table.items if q.kind == "text"]
        head = cells[cells.index("R^{τ}_{12}"):]
        assert head[1] == "R^{n}_{12}" and "R_{12}" in head
    tol = 0.5 * gp.mu_F
    cells = [q.text for q in group_table_record(fp, gp, "en").items if q.kind == "text"]
    width = cells.index("value, N (N·m)")          # the header row's cells, then the values' row

    def value(symbol: str) -> float:
        return float(cells[width + cells.index(symbol)].replace("−", "-"))
    n_val, t_val = abs(value("R^{n}_{12}")), abs(value("R^{τ}_{12}"))
    assert n_val == pytest.approx(abs(along), abs=tol + 0.01 * abs(along))
    assert t_val == pytest.approx(abs(across), abs=tol)
    assert math.hypot(n_val, t_val) == pytest.approx(abs(exact), rel=0.01)


def _numbers_on_axis(rec) -> dict[str, float]:
    return {q.text: q.points[0][0] for q in rec.items if q.kind == "text" and q.text.isdigit()
            and q.anchor != "end"}


def test_the_charts_over_the_turn_close_at_12(press_turn):
    """Review5 #11: the M_b and R03 charts had no "12" at the right end. The turn closes at position
    0 again: its end, 360°/μφ from the origin, carries the tick and the number 12, near its end."""
    from graphplan.drawing.charts import moment_record, reaction_record
    for rec in (moment_record(press_turn, lang="en"), reaction_record(press_turn, "R03", lang="en")):
        end = 360.0 / rec.scales["mu_phi"]
        nums = _numbers_on_axis(rec)
        assert set(map(str, range(13))) <= set(nums), sorted(nums)
        ticks = [q for q in rec.items if q.kind == "segment" and q.points[0][0] == pytest.approx(end)
                 and q.points[1][0] == pytest.approx(end) and abs(q.points[0][1]) == pytest.approx(1.5)]
        assert ticks, rec.title
        assert abs(nums["12"] - end) < 5.0 and nums["12"] > nums["11"]


def test_the_resistance_charts_force_axis_is_graduated(press_turn):
    """Review5 #11: the P_B axis carried only "8000". Its values stand at one round step (1, 2 or 5 ×
    10ⁿ), each at its tick's height times μP, from 0 to the peak, at least three of them; the path
    closes at position 12, the path's end."""
    from graphplan.drawing.charts import path_travelled, resistance_record
    rec = resistance_record(press_turn, lang="en")
    mu = rec.scales["mu_P"]
    values = sorted((float(q.text), q.points[0][1] + 1.2) for q in rec.items
                    if q.kind == "text" and q.anchor == "end")
    assert len(values) >= 3, values
    for v, y in values:
        assert y * mu == pytest.approx(v, abs=1e-9)
    steps = {round(b[0] - a[0], 9) for a, b in zip(values, values[1:])}
    assert len(steps) == 1
    s = steps.pop()
    assert round(s / 10.0 ** math.floor(math.log10(s)), 9) in {1.0, 2.0, 5.0}
    top = max(abs(sum(ld.force for ld in press_turn.ks.loads if ld.kind == "external")))
    assert values[0][0] == 0 and top - s < values[-1][0] <= top + 1e-9
    end = path_travelled(press_turn)[-1] / rec.scales["mu_s"]
    twelve = [q for q in rec.items if q.kind == "text" and q.text == "12"]
    # at its tick, or set aside from it on a leader where 11 crowds it (one row, review 12 #18)
    led = [a[0] for a, b in (q.points for q in rec.items if q.kind == "segment" and q.layer == "labels")
           if twelve and abs(b[0] - twelve[0].points[0][0]) < 2.0 and 0 < b[1] - twelve[0].points[0][1] < 4.5]
    assert twelve and (led or [twelve[0].points[0][0]])[0] == pytest.approx(end)


def test_flat_hodographs_grow_where_the_sheet_has_room(press_turn):
    """Review5 #6: the press's hodographs were 60 × 15 mm slivers at 150 N/mm in a 125 mm wide
    column, their idle-stroke numbers merged "7–11". A hodograph's growth is 1/√(its aspect), at
    most 2 (checked against its own extents); on the A1 sheet the press's are drawn at least 1.6
    times the round size — μR finer than 150 N/mm — every position numbered, a number shared only
    where the points lie within the ruler's 0.5 mm — the main drawings' scales unchanged."""
    import numpy as np
    from graphplan.drawing.charts import FLAT_GROWTH, hodograph_growth
    from graphplan.sheets import forces as sf
    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.form import form
    for key in press_turn.revolute:
        f = press_turn.ks.reactions[key].force
        w = np.ptp(np.r_[f.real, 0.0])
        h = np.ptp(np.r_[f.imag, 0.0])
        assert hodograph_growth(press_turn, key) == pytest.approx(min(FLAT_GROWTH, math.sqrt(max(w, h) / min(w, h))))
    p, nat, dr = sf.plan(scene_study(PRESS_EN), form("A1"), SheetOptions(precision=0.5, sheet="forces"))
    assert 1.0 / p.mu["hodographs"] >= 1.6
    hods = dr.drawings(p.mu, "en")["hodographs"]
    assert hods and all(rec.scales["mu_R"] < 150.0 for rec in hods)
    # every position numbered; a number shared only by points within the ruler's 0.5 mm at the scale
    # they are drawn (the hodograph's, or its detail's "I" where one has room)
    count = press_turn.count
    for rec in hods:
        key = rec.title.split()[-1]
        f = press_turn.ks.reactions[key].force
        idx = dict((pos, k) for k, pos in press_turn.position_index())
        mu_d = rec.scales.get("mu_R detail")
        assert mu_d is None or mu_d * 2 <= rec.scales["mu_R"], rec.title
        texts = [(q.text, q.step.endswith("detail")) for q in rec.items
                 if q.kind == "text" and q.text.replace("–", "").isdigit()]
        assert sorted(n for t, _ in texts for n in _runs(t)) == list(range(count)), texts
        for t, in_detail in texts:
            run = _runs(t)
            mu = mu_d if in_detail else rec.scales["mu_R"]
            for a, b in zip(run, run[1:]):
                assert abs(f[idx[b]] - f[idx[a]]) / mu <= 0.5 + 1e-9, (rec.title, t)
    v_A = 0.09 * 90 * math.pi / 30                  # r·ω1 of the press
    assert p.mu["scheme"] == pytest.approx(0.002) and v_A / p.mu["lever"] >= 75.0   # the lever's pa no shorter


def _runs(text: str) -> list[int]:
    a, _, b = text.partition("–")
    return list(range(int(a), int(b or a) + 1))


def test_a_wide_group_table_is_set_in_two_tiers():
    """The components widened review4's press II(2-3) table to 226 mm (the column grew, the group
    II(4-5) lost a step): a table wider than 200 mm is set in two tiers, each narrower, together
    every force once — R^τ and R^n for each outer joint's R^τ."""
    from graphplan.drawing.forces import TABLE_WIDEST_MM, group_table_record
    from graphplan.sheets import forces as sf
    from graphplan.sheets.compose import SheetOptions
    fp = sf.ForceDrafter(scene_study(PRESS), SheetOptions(precision=0.5, sheet="forces")).fp()
    gp = next(g for g in fp.groups if "2-3" in g.label)
    rec = group_table_record(fp, gp, "en")
    heads = [q for q in rec.items if q.kind == "text" and q.text == "force"]
    assert len(heads) == 2
    x0, _, x1, _ = rec.bounds()
    assert x1 - x0 <= TABLE_WIDEST_MM
    names = [q.text for q in rec.items if q.kind == "text" and q.text.startswith(("R", "G", "Φ", "M", "P"))]
    assert len(names) == len(set(names))
    taus = {eq.unknown for eq in gp.equations if eq.unknown.endswith("τ")}
    assert len(taus) == 2
    for t in taus:
        index = t[1:-1]
        assert {f"R^{{τ}}_{{{index}}}", f"R^{{n}}_{{{index}}}", f"R_{{{index}}}"} <= set(names)
