"""Stop 60's speed of building sheets: the searches made cheaper must find what they found before.

- ``labels._far`` with several checks (``place_owned_line``'s four leader searches) is the first of the
  searches, each on its own, that finds a spot — the candidates counted once for all, the check asked
  last; ``place_owned_line`` places the label where the old four searches did (a reference copy of
  them below, written from their definition).
- The scene's other sheets count the forces document by ``forces.planned_sheets`` (the plan's rounds
  alone; the plan goes on from them) where they end on one sheet: the whole plan's count.
- The scene's other sheets count the dynamics document by ``dynamics.one_sheet`` (the search stopped
  at its first one-sheet composition): the same answer as the whole construction's shape.
- A benchmark (slow): a generated mechanism's numbered A1 kinematics sheet, composed cold.
"""
from __future__ import annotations

import random

import numpy as np
import pytest

from graphplan.drawing import labels as L
from graphplan.graphic.record import LabelRequest, Primitive, Record


def _scene(seed: int) -> tuple[Record, list[tuple[complex, complex]]]:
    """A random drawing of arrows (thick segments) and a few letters around the origin."""
    rng = random.Random(seed)
    rec = Record()
    arrows = []
    for _ in range(rng.randint(3, 9)):
        a = complex(rng.uniform(-25, 25), rng.uniform(-25, 25))
        b = a + complex(rng.uniform(-30, 30), rng.uniform(-30, 30))
        rec.segment((a.real, a.imag), (b.real, b.imag), width=rng.choice((0.25, 0.5, 0.7)))
        arrows.append((a, b))
    for _ in range(rng.randint(0, 4)):
        rec.label((rng.uniform(-20, 20), rng.uniform(-20, 20)), rng.choice(("A", "Φ_2", "G_3", "12")), size=3.5)
    return rec, arrows


@pytest.mark.parametrize("seed", range(12))
def test_far_with_several_checks_is_the_first_search_that_finds(seed):
    """``_far(ob, req, ink, p, q, r)`` = ``_far(ob, req, ink, p) or _far(…, q) or _far(…, r)`` (the
    old chain of searches), for checks that reject most spots, on random drawings."""
    rec, arrows = _scene(seed)
    ob = L.obstacles(rec.items)
    rng = random.Random(100 + seed)
    for across in (True, False):
        req = LabelRequest(complex(rng.uniform(-5, 5), rng.uniform(-5, 5)), "P_E", toward=1j, across=across)
        ink = Primitive("text", ((0.0, 0.0),), text=req.text, size=req.size).ink()
        # spots to the right and above, then far out, then anywhere: each rejects most of the rings
        checks = [lambda b: b[0] > req.at.real + 14.0 and b[1] > req.at.imag,
                  lambda b: abs(complex((b[0] + b[2]) / 2, (b[1] + b[3]) / 2) - req.at) > 24.0,
                  lambda b: b[3] < req.at.imag - 10.0, None]
        for k in range(len(checks)):
            chained = None
            for c in checks[k:]:
                chained = chained or L._far(ob, req, ink, c)
            assert L._far(ob, req, ink, *checks[k:]) == chained


def _led_reference(req, mine, near, box, clear=L.LEADER_CLEAR, nearer=True) -> bool:
    """``place_owned_line``'s leader check as stop 59 wrote it (each distance measured when asked)."""
    a, b = L._leader(req.at, box)
    d = L.box_to_segment(box, *mine) + L.OWN_LINE_MM if nearer else 0.0
    return ((L.owns_line(box, mine, near)
             or all(L.box_to_segment(box, *o) >= max(L.LED_CLEAR, d) for o in near))
            and not any(L._segments_cross(a, b, *o) for o in near)
            and all(L.segment_gap(a, b, *o) >= clear for o in near))


def _owned_line_reference(record: Record, alternatives, mine, others) -> Record:
    """``place_owned_line`` as stop 59 wrote it: the same first pass, then the four leader searches
    one after another (``_far`` each with its check)."""
    ob = L.obstacles(record.items)
    near = [o for o in others if min(abs(o[0] - mine[0]), abs(o[0] - mine[1]), abs(o[1] - mine[0]),
                                     abs(o[1] - mine[1])) < 200.0]
    for req in alternatives:
        ink = Primitive("text", ((0.0, 0.0),), text=req.text, size=req.size).ink()
        size = (ink[2] - ink[0]) + (ink[3] - ink[1]) + L.CLEAR + 2.0
        gaps = (max(req.gap, L.NEAR[0]),) + tuple(g for g in L.NEAR[1:] if g > req.gap)
        local = ob.near(req.at, L.NEAR[-1] + size)
        boxes, starts = L._candidates(req, ink, gaps, 2 * L.DIRECTIONS)
        k = next((k for k in np.nonzero(L._counts(local, boxes, number=L._number(req)) == 0)[0]
                  if L.owns_line(tuple(boxes[k]), mine, near) and L._in_sight(local, req.at, boxes[k])), None)
        if k is not None:
            record.label((starts[k].real, starts[k].imag), req.text, size=req.size, anchor="start", layer="labels")
            return record
    req = alternatives[0]
    ink = Primitive("text", ((0.0, 0.0),), text=req.text, size=req.size).ink()
    size = (ink[2] - ink[0]) + (ink[3] - ink[1]) + L.CLEAR + 2.0
    local = ob.near(req.at, L.FAR[-1] + size)
    spot = None
    for clear, nearer in ((L.LEADER_CLEAR, True), (0.0, True), (L.LEADER_CLEAR, False), (0.0, False)):
        spot = spot or L._far(local, req, ink, lambda box: _led_reference(req, mine, near, box, clear, nearer))
    if spot is None:
        return L.place_labels(record, [req], "labels")
    box, start, (a, b) = spot
    record.segment((a.real, a.imag), (b.real, b.imag), role="label", layer="labels")
    record.label((start.real, start.imag), req.text, size=req.size, anchor="start", layer="labels")
    return record


@pytest.mark.parametrize("seed", range(16))
def test_a_force_letter_among_arrows_is_placed_as_the_four_searches_placed_it(seed):
    """A force's letter at the head of its arrow in a knot of random arrows (the arrows' letters in
    the way): the same primitives as the old chain of four leader searches (a reference copy)."""
    rec, arrows = _scene(seed)
    rng = random.Random(200 + seed)
    mine = arrows[0]
    # a knot: the other arrows pass near its head, most spots beside it lie nearer them
    for _ in range(4):
        a = mine[1] + complex(rng.uniform(-4, 4), rng.uniform(-4, 4))
        b = a + (mine[1] - mine[0]) * rng.uniform(-0.8, 0.8) + complex(rng.uniform(-3, 3), rng.uniform(-3, 3))
        rec.segment((a.real, a.imag), (b.real, b.imag), width=0.5)
        arrows.append((a, b))
    req = LabelRequest(mine[1], "Φ_4", toward=mine[1] - mine[0], across=rng.random() < 0.5)
    others = arrows[1:]
    ours = Record()
    ours.items[:] = list(rec.items)
    theirs = Record()
    theirs.items[:] = list(rec.items)
    L.place_owned_line(ours, [req], mine, others, layer="labels")
    _owned_line_reference(theirs, [req], mine, others)
    assert ours.items == theirs.items


def _one_sheet_cases():
    import review_scenes
    return [("shaper", "A1"), ("LINK60", "A1"), ("shaper", "A3")], review_scenes


@pytest.mark.slow
@pytest.mark.parametrize("case", range(3))
def test_the_dynamics_count_stops_where_one_sheet_is_known(case):
    """``one_sheet`` (the search stopped at its first one-sheet composition) answers as the whole
    construction's shape (not "set") on the gallery's shaper and the stop's plunger-rocker, on one
    sheet and on sets of sheets; asked after the construction it reads that."""
    from conftest import example, scene_study
    from graphplan.sheets import dynamics as D
    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.form import form
    cases, review_scenes = _one_sheet_cases()
    name, fmt = cases[case]
    st = scene_study(getattr(review_scenes, name)) if name.isupper() else example(name)
    f = form(fmt)
    args = SheetOptions(None, None, 0.5, "uk", "dynamics")
    dyn = D._analysed(st, None)
    key = D._construction_key(st, dyn, f, args)
    D._CONSTRUCTIONS.pop(key, None)
    D._ONE.pop(key, None)
    D._MEMOS.pop(key, None)
    first = D.one_sheet(st, dyn, f, args)
    whole = D.construction(st, dyn, f, args)
    assert first == (whole[3] != "set")
    # and the construction after the count is the construction made alone (its measures shared)
    D._CONSTRUCTIONS.pop(key, None)
    D._MEMOS.pop(key, None)
    assert D.construction(st, dyn, f, args) == whole
    assert D.one_sheet(st, dyn, f, args) == first


@pytest.mark.slow
@pytest.mark.parametrize("name,fmt", [("shaper", "A1"), ("LINK60", "A1"), ("shaper", "A3")])
def test_the_forces_count_stops_after_the_rounds(name, fmt):
    """``forces.planned_sheets`` (the plan's rounds alone, before the drawings grow) is the whole
    plan's count of sheets wherever it answers — on A1 always (1) —, and the plan that goes on from
    the rounds it kept is the plan composed from the start."""
    import review_scenes
    from conftest import example, scene_study
    from graphplan.sheets import forces as F
    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.form import form
    st = scene_study(getattr(review_scenes, name)) if name.isupper() else example(name)
    f, opts = form(fmt), SheetOptions(None, None, 0.5, "uk", "forces")
    key = F._rounds_key(st, f, opts)
    F._ROUNDS.pop(key, None)
    F._PLANNED.pop(key, None)
    counted = F.planned_sheets(st, f, opts)
    went_on = F.plan.__wrapped__(st, f, opts)          # from the kept rounds (taken), not remembered
    assert key not in F._ROUNDS
    alone = F.plan.__wrapped__(st, f, opts)            # from the start
    assert went_on[0] == alone[0]
    assert counted is None or counted == alone[0].sheets
    if fmt == "A1":
        assert counted == 1


@pytest.mark.slow
def test_bench_a_generated_mechanisms_numbered_a1_kinematics_sheet(benchmark, tmp_path, monkeypatch):
    """A student's wait: a mechanism generated from the stop's plunger-rocker (every length × 1.2,
    the crank at 120 rpm), its A1 kinematics sheet numbered in the project (the forces and dynamics
    documents counted), composed cold — no count kept on disk or in the process. Run with
    ``--benchmark-enable`` to time it (stop 60: LINK60's took 23.8 s idle)."""
    import review_scenes
    from test_kin59b_main import generated

    from graphplan.cli.main import main
    from graphplan.sheets import sheet as S
    monkeypatch.setenv("GRAPHPLAN_CACHE", "off")
    scene = tmp_path / "generated.toml"
    scene.write_text(generated(review_scenes.LINK60, 1.2, 120), encoding="utf-8")

    def cold() -> int:
        S._PAGES.clear()
        return main(["sheet", str(scene), "--sheet", "kinematics", "-o", str(tmp_path / "k.svg")])
    assert benchmark.pedantic(cold, rounds=1, iterations=1) == 0
    text = (tmp_path / "k.svg").read_text(encoding="utf-8")
    assert text.startswith("<?xml") or text.startswith("<svg")

