"""Stop 47 (the lead's six-bar LINK47: an offset crank-slider O-A-B whose rod's point C drives a
rocker O2D; I(0-1) -> II(2-3) RRP -> II(4-5) RRR, P_B on the working stroke). The truth here is the
physics, not the drawing: the outer group II(4-5) is solved before the slider's group, so its
reactions cannot depend on P_B at all — computed again with P_B three times as large."""
from __future__ import annotations

import numpy as np
import pytest

from conftest import scene_study
from review_scenes import LINK47


SHEET_MM = 110.0    # about the A1 sheet's top row of hodographs (R24 at μR = 1 N/mm)


@pytest.fixture(scope="module")
def turns():
    from graphplan.drawing import charts
    heavy = LINK47.replace("magnitude = 1500", "magnitude = 4500", 1)
    assert heavy != LINK47
    return charts.turn(scene_study(LINK47)), charts.turn(scene_study(heavy))


def _dependence(turns, key: str) -> float:
    """How far (N, over the turn) the reaction moves when P_B is tripled."""
    a, b = turns
    return float(np.max(np.abs(a.ks.reactions[key].force - b.ks.reactions[key].force)))


@pytest.mark.parametrize("key", ["R24", "R45", "R05"])
def test_no_jump_drawn_or_said_where_the_reaction_does_not_carry_pb(turns, key):
    """R24, R45, R05 do not change with P_B (the physics); their hodographs then draw no dashed
    "jump" and say none ("пунктир — стрибок від P_B" stood under all three, their ordinary
    0.4–0.9 N step at the stroke's change drawn dashed), in either language."""
    from graphplan.drawing import charts
    assert _dependence(turns, key) < 1e-6
    for lang in ("uk", "en"):
        rec = charts.hodograph_record(turns[0], key, size=SHEET_MM, lang=lang)
        assert not [q for q in rec.items if "jump" in (q.step or "")], (key, lang)
        words = " ".join(q.text or "" for q in rec.items if q.kind == "text")
        assert "стрибок" not in words and "jump" not in words, (key, lang, words)


@pytest.mark.parametrize("key", ["R12", "R23", "R01"])
def test_the_jump_drawn_and_said_where_the_reaction_carries_pb(turns, key):
    """R12, R23, R01 move by P_B's own size where it switches (the physics: tripling P_B moves
    them by 2 × 1500 N on the working stroke); their hodographs draw the jump dashed and name P_B."""
    from graphplan.drawing import charts
    assert _dependence(turns, key) == pytest.approx(3000.0, rel=0.05)
    rec = charts.hodograph_record(turns[0], key, lang="uk")
    assert [q for q in rec.items if "jump" in (q.step or "")], key
    words = " ".join(q.text or "" for q in rec.items if q.kind == "text")
    assert "стрибок від P_{B}" in words or "стрибок від P_B" in words, words


@pytest.fixture(scope="module")
def lever():
    from graphplan.drawing.forces import lever_record
    from graphplan.sheets import forces as sf
    from graphplan.sheets.compose import SheetOptions
    fp = sf.ForceDrafter(scene_study(LINK47), SheetOptions(precision=0.5, sheet="forces")).fp()
    return fp, lever_record(fp, "uk")


def test_the_slider_loads_arm_keeps_p_bs_index_below_p(lever):
    """Φ3 and P_B act at b along one line (the slider's guide: both horizontal — the exact
    directions, read off the lever's terms), so the lever draws one arm for both; its name sets
    P_B's B as an index of P (a level below P, as Φ3's 3 is below Φ), not flat beside it ("h_{Φ3,PB}"
    read as a force named PB)."""
    from graphplan.util.markup import runs
    fp, rec = lever
    terms = {t.name: t for t in fp.lever.terms}
    assert {"Φ3", "P_B"} <= set(terms)
    names = [q.text for q in rec.items if q.kind == "text" and q.text.startswith("h_{") and "P" in q.text]
    assert len(names) == 1, names
    levels = [(r.text, r.level) for r in runs(names[0])]
    p_at = next(k for k, (t, lv) in enumerate(levels) if t.endswith("P"))
    assert levels[p_at][1] == -1 and levels[p_at + 1] == ("B", -2), levels
    if "Φ" in names[0]:
        phi = next(k for k, (t, _) in enumerate(levels) if t.endswith("Φ"))
        assert levels[phi + 1] == ("3", -2), levels


def test_two_arms_the_ruler_cannot_part_get_one_name(lever):
    """Group II(4-5): G5 and Φ5 both act at S5 (G5 vertical, Φ5 against a_S5), their lines 1–2°
    apart, so their arms about D — computed here from the points and the loads' directions — are
    one line to the ruler (feet < 1 mm apart); the group names that line once, with both forces
    (h_{G5,Φ5}), not twice ("h_{Φ5}" stood 34 mm off on a leader) — and every other arm once."""
    from graphplan.drawing.forces import group_record
    fp, _ = lever
    gp = next(g for g in fp.groups if g.label == "II(4-5)")
    mu = gp.mu_l
    d = gp.points["D"]
    loads = {f.name: f for f in gp.forces if f.name in ("G5", "Φ5")}
    feet = []
    for f in loads.values():
        u = f.force / abs(f.force)
        s = f.at / mu
        feet.append(s + ((d - s) * u.conjugate()).real * u)        # the foot of the perpendicular from D
    assert abs(feet[0] - feet[1]) < 1.0, feet
    rec = group_record(fp, gp, "uk")
    names = [q.text for q in rec.items if q.kind == "text" and q.text.startswith("h_{")]
    parts = [n for q in names for n in q[3:-1].split(",")]
    assert sorted(parts) == sorted(set(parts)), names                  # each force's arm named once
    both = [q for q in names if {"G5", "Φ5"} <= set(q[3:-1].split(","))]
    assert len(both) == 1, names


def test_the_lever_names_g5_and_phi5s_one_arm_once(lever):
    """On the lever G5 and Φ5 (turned with the plan) again leave s5 along lines ~1.4° apart: their
    arms from the pole end under 1 mm apart (measured on the drawn arm segments), one line to the
    ruler, named once with both forces."""
    fp, rec = lever
    feet = {p.text.rsplit(" to ", 1)[1]: complex(*p.points[1]) for p in rec.items
            if p.kind == "segment" and p.text.startswith("h_{") and " mm to " in p.text}
    assert abs(feet["G5"] - feet["Φ5"]) < 1.0, feet
    names = [q.text for q in rec.items if q.kind == "text" and q.text.startswith("h_{")]
    assert len([q for q in names if {"G5", "Φ5"} <= set(q[3:-1].split(","))]) == 1, names


def test_no_sheet_for_the_notes_alone():
    """The set's packer (forceset.pack): where the tables fill their sheet and the notes find no
    room by its title block, the notes go to an earlier sheet with room for them — not to a sheet
    of their own (LINK47's A3 set ended with a sheet holding twelve lines of notes and nothing
    else). Sizes here are boxes (mm), the sheet a real A3 with its title blocks."""
    from graphplan.drawing.layout import Leaf
    from graphplan.sheets.compose import field_of, keep_out, later_keep
    from graphplan.sheets.form import form
    from graphplan.sheets.forceset import pack
    f = form("A3")
    x0, y0, x1, y1 = field_of(f)
    W, H = x1 - x0, y1 - y0
    units = [[Leaf("scheme 0", 0.5 * W, 0.4 * H)]]                  # a small drawing: sheet 1 mostly free
    tables = [Leaf("table 1", W - 1.0, H - 40.0)]                   # the tables fill sheet 2
    notes = Leaf("notes", 150.0, 60.0)
    pages = pack(units, tables, notes, field_of(f), keep_out(f), later_keep(f))
    assert pages is not None and len(pages) == 2, pages
    where = {s.node.name: k for k, page in enumerate(pages) for s in page}
    assert where["table 1"] == 1 and where["notes"] == 0, where
    for page in pages:                                                # nothing overlaps on a sheet
        for i, a in enumerate(page):
            for b in page[i + 1:]:
                assert (a.x + a.w <= b.x + 1e-6 or b.x + b.w <= a.x + 1e-6
                        or a.d + a.h <= b.d + 1e-6 or b.d + b.h <= a.d + 1e-6), (a.node.name, b.node.name)


@pytest.mark.parametrize("key", ["R34", "R05", "R12", "R01"])
def test_watt_reactions_jump_with_m5_and_say_so(key):
    """WATT47 (frc47's own check: a Watt six-bar, two RRR dyads, no slider; M5 = 60 N·m against
    the output rocker on its working stroke). M5 acts on the last group, so every reaction carries
    it (the physics: tripling M5 moves each reaction); each hodograph draws the jump dashed and
    names M_5 — and no P, there being no force load."""
    from graphplan.drawing import charts
    a, b = _watt_turns()
    moved = float(np.max(np.abs(a.ks.reactions[key].force - b.ks.reactions[key].force)))
    assert moved > 10.0, moved
    rec = charts.hodograph_record(a, key, size=SHEET_MM, lang="en")
    assert [q for q in rec.items if "jump" in (q.step or "")], key
    words = " ".join(q.text or "" for q in rec.items if q.kind == "text")
    assert "jump due to M_{5}" in words or "jump due to M_5" in words, words
    assert "P_" not in words, words


_WATT: list = []


def _watt_turns():
    """WATT47's turn, and again with M5 three times as large (computed once per module)."""
    if not _WATT:
        from graphplan.drawing import charts
        from review_scenes import WATT47
        heavy = WATT47.replace("magnitude = 60", "magnitude = 180", 1)
        assert heavy != WATT47
        _WATT.extend([charts.turn(scene_study(WATT47)), charts.turn(scene_study(heavy))])
    return _WATT


def _overlap(a, b) -> float:
    """The area (mm²) two boxes (x0, y0, x1, y1) share."""
    return max(0.0, min(a[2], b[2]) - max(a[0], b[0])) * max(0.0, min(a[3], b[3]) - max(a[1], b[1]))


@pytest.mark.slow
def test_a1_forces_are_one_sheet_its_hodographs_legible():
    """LINK47's A1 forces are one sheet (``plan``: A1 one sheet where one holds every drawing at least
    at its target size). Stop 47 drew two, the hodographs alone on sheet 2 — then grown into its
    room (review 47 #1); the one sheet has held since before stop 53, and the two tests that asked
    for sheet 2 failed from then to stop 59. frc59b looked at the six hodographs in their 135 mm
    strip beside the lever: the curves 40–60 mm across, R12, R23, R01 flat, every position's number
    apart and readable. Measured on the drawn sheet: each hodograph no smaller than at the size
    factor one step under the one-sheet floor (``HODOGRAPHS_FLOOR``: ``plan`` drops the floor where
    it would cost a main drawing a step — R05 is drawn 63.4 mm wide where the floor's is 64.9);
    each drawing inside the field and off the title block, no two overlapping."""
    from graphplan.drawing import charts
    from graphplan.drawing.charts import HODOGRAPH_MM, hodograph_record
    from graphplan.sheets.compose import FACTORS, SheetOptions, field_of, keep_out
    from graphplan.sheets.forces import HODOGRAPHS_FLOOR, build_forces_sheet
    from graphplan.sheets.form import form
    st = scene_study(LINK47)
    f = form("A1")
    sheet = build_forces_sheet(st, f, SheetOptions(precision=0.5, lang="en", sheet="forces"))
    assert len(sheet.pages) == 1
    hods = {pl.name.removeprefix("hodograph "): pl for pl in sheet.pages[0].placed if pl.name.startswith("hodograph")}
    turn = charts.turn(st)
    assert sorted(hods) == sorted(turn.revolute) and len(hods) == 6
    under = max(k for k in FACTORS if k < HODOGRAPHS_FLOOR - 1e-9)        # 0.8
    for key, pl in hods.items():
        least = hodograph_record(turn, key, HODOGRAPH_MM * under, lang="en").bounds()
        got = pl.record.bounds()
        assert got[2] - got[0] >= least[2] - least[0] - 1e-6, (key, got, least)
    x0, y0, x1, y1 = field_of(f)
    keep = keep_out(f)
    boxes = [pl.record.bounds() for pl in sheet.pages[0].placed]
    for b in boxes:
        assert x0 - 1e-6 <= b[0] and b[2] <= x1 + 1e-6 and y0 - 1e-6 <= b[1] and b[3] <= y1 + 1e-6, b
        assert _overlap(b, keep) < 1e-6, (b, keep)
    for i, a in enumerate(boxes):
        for b in boxes[i + 1:]:
            assert _overlap(a, b) < 1e-6, (a, b)


def test_free_box_widens_a_box_to_its_neighbours_and_the_field():
    """The free room round a drawing's box (``forces._free_box``): measured by hand on a 100 × 100
    field with a drawing at its left (x 0–20) and the title block at its bottom right: the box
    (40, 40, 60, 60) widens to x 26–100 (6 mm clear of the drawing), then up to the field's top
    and down to 6 mm over the block."""
    from graphplan.sheets.forces import _free_box
    got = _free_box((40, 40, 60, 60), [(0, 0, 20, 100)], (0, 0, 100, 100), (70, 0, 100, 10), 6.0)
    assert got == pytest.approx((26, 16, 100, 100))
    # a box already closer than the gap to another drawing (2 mm): none
    assert _free_box((0, 0, 10, 10), [(0, 12, 10, 20), (12, 0, 20, 10)], (0, 0, 20, 20), (30, 30, 40, 40),
                     6.0) is None
    # nothing to widen into: the box itself
    assert _free_box((0, 0, 10, 10), [(0, 16, 20, 20), (16, 0, 20, 16)], (0, 0, 20, 20), (30, 30, 40, 40),
                     6.0) == pytest.approx((0, 0, 10, 10))


def _to_segment(z: complex, a: complex, b: complex) -> float:
    """The distance (mm) from z to the segment ab."""
    d = b - a
    t = 0.0 if abs(d) < 1e-12 else min(1.0, max(0.0, ((z - a) * d.conjugate()).real / abs(d) ** 2))
    return abs(z - (a + t * d))


def test_the_scheme_parts_g5_and_phi5_and_keeps_m5s_arc_off_them(lever):
    """Review 47 #3: on the scheme G5 and Φ5 both run down from S5 (G5 vertical, Φ5 against a_S5
    — 1.3° apart), their arrows 2.3 mm apart: the two 2 mm heads read as one arrow, and M^Φ5's
    arc came down between them. Measured on the drawn scheme: the two shafts at least 4 mm apart
    along their length; the arc centred at S5 nowhere within 0.5 mm of either shaft."""
    import cmath
    import math
    from graphplan.drawing.forces import mechanism_record
    fp, _ = lever
    rec = mechanism_record(fp, "uk")
    vec = {q.text: [complex(*p) for p in q.points] for q in rec.items if q.kind == "vector" and q.text in ("G5", "Φ5")}
    g, f = vec["G5"], vec["Φ5"]
    # stop 61 (review 60 #3: every force ON its line through its point): the two drawn one after the
    # other along their common line through S5 (Φ5 reaching S5, G5 leaving it) — their heads at least
    # 4 mm apart, neither shaft running over the other (they were set 4 mm apart in lanes, off S5)
    assert abs(g[1] - f[1]) >= 4.0, (g, f)
    assert min(_to_segment(z, *g) for z in (f[0], 0.5 * (f[0] + f[1]))) >= 4.0, (g, f)
    assert min(_to_segment(z, *f) for z in (g[1], 0.5 * (g[0] + g[1]))) >= 4.0, (g, f)
    s5 = next(complex(*q.points[0]) for q in rec.items if q.kind == "point"
              and min(abs(complex(*q.points[0]) - e) for e in (*g, *f)) < 0.5)
    arcs = [q for q in rec.items if q.kind == "arc" and abs(complex(*q.points[0]) - s5) < 0.5]
    assert len(arcs) == 1
    q = arcs[0]
    a0, a1 = q.angles
    for k in range(41):
        z = s5 + q.radius * cmath.exp(1j * math.radians(a0 + (a1 - a0) * k / 40))
        assert _to_segment(z, *g) > 0.5 and _to_segment(z, *f) > 0.5, (k, z)
