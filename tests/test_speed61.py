"""Stop 61's speed of building sheets: the searches made cheaper must find what they found before.

- The kinematics sheet's composition search (``kinlayout.one_sheet_at``) measures each grid pair's
  tree as a function of its tables' column (``tree_sized``: ``extent_with``), the same sums to the
  bit as ``extent(tree(…))``, and skips the grid pairs whose least tree (``least_leaf``, the least
  column of ``floor_of``: the notes one line a paragraph, ``notes_floor``) is past the field — the
  extent only grows with its leaves, so none of their trees fits. Hypothesis checks both facts on
  random drawings' sizes, and (slow) the search with and without the skipping chooses the same
  composition on whole scenes.
- The dynamics construction's search for the larger energy–mass diagram (``larger``) asks ``held``
  only for bands at least as long as the classical composition's (``longer``): ``held`` then looks
  at the shorter ones with 3.5-mm tables only where they decide (a 2.5-mm one holds), never with
  2.5-mm ones — the same construction (slow: with and without it, on whole scenes).
- Benchmarks (slow): the drag-link's A1 kinematics composition and its dynamics construction, cold.
"""
from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st_

from graphplan.drawing.layout import Grid, Leaf, extent
from graphplan.sheets import kinlayout as K

SIZE = st_.floats(0.0, 400.0, allow_nan=False, allow_infinity=False)
LEAF = st_.tuples(SIZE, SIZE).map(lambda s: Leaf("x", *s))


@st_.composite
def _grid(draw):
    """A fitted grid of 1–12 random plans."""
    kids = draw(st_.lists(LEAF, min_size=1, max_size=6))
    return Grid(kids, draw(st_.integers(1, len(kids))), fitted=True)


def _family(most: int):
    """A family's grids (one per column count the search tries), or none (no drawings: [None])."""
    return st_.one_of(st_.just([None]), st_.lists(_grid(), min_size=1, max_size=most))


@settings(max_examples=60, deadline=None, derandomize=True, database=None)
@given(shape=st_.sampled_from(K.SHAPES), P=LEAF, D=LEAF, vg=st_.one_of(st_.none(), _grid()),
       ag=st_.one_of(st_.none(), _grid()),
       columns=st_.lists(st_.tuples(LEAF, LEAF, LEAF), min_size=1, max_size=6))
def test_tree_sized_is_the_trees_extent_to_the_bit(shape, P, D, vg, ag, columns):
    """``tree_sized(shape, P, D, vg, ag)(C, (T, N))`` == ``extent(tree(shape, P, D, vg, ag, C, (T, N)))``
    exactly (==, not approximately: the composition compares these sums with the field's size, and
    the sheet must come out byte-identical), for every shape and every column of a list."""
    sized = K.tree_sized(shape, P, D, vg, ag)
    for C, T, N in columns:
        assert sized(C, (T, N)) == extent(K.tree(shape, P, D, vg, ag, C, (T, N)))


@settings(max_examples=60, deadline=None, derandomize=True, database=None)
@given(shape=st_.sampled_from(K.SHAPES), P=LEAF, D=LEAF,
       vgs=_family(4), ags=_family(3),
       columns=st_.lists(st_.tuples(LEAF, LEAF, LEAF), min_size=1, max_size=5))
def test_the_least_tree_is_no_larger_than_any_it_bounds(shape, P, D, vgs, ags, columns):
    """The pruning's premise: a tree with each leaf replaced by one no wider than the narrowest and
    no higher than the lowest of its alternatives (``least_leaf``) is no wider and no higher than
    the tree of any choice of them — so where it is past the field (``fits_field`` false), every
    choice is, and skipping them changes nothing."""
    lv, la = K.least_leaf(vgs), K.least_leaf(ags)
    lC, lT, lN = (K.least_leaf(c[i] for c in columns) for i in range(3))
    lw, lh = extent(K.tree(shape, P, D, lv, la, lC, (lT, lN)))
    for vg in vgs:
        for ag in ags:
            for C, T, N in columns:
                w, h = extent(K.tree(shape, P, D, vg, ag, C, (T, N)))
                assert lw <= w and lh <= h
                if not K.fits_field(K.tree(shape, P, D, lv, la, lC, (lT, lN)), 500.0, 400.0):
                    assert not (w <= 500.0 + 1e-9 and h <= 400.0 + 1e-9)


WORDS = ["μ_v", "=", "0,02", "(м/с)/мм,", "ω_3", "рад/с", "план", "швидкостей", "побудовано", "для",
         "положення", "12", "кривошипа;", "Table", "4:", "the", "velocity", "of", "point", "D", "by", "similarity"]


@settings(max_examples=30, deadline=None, derandomize=True, database=None)
@given(notes=st_.lists(st_.lists(st_.lists(st_.sampled_from(WORDS), min_size=1, max_size=25).map(" ".join),
                                 min_size=0, max_size=12), min_size=1, max_size=3),
       width=st_.floats(20.0, 800.0))
def test_the_notes_floor_is_no_higher_than_the_notes_at_any_width(notes, width):
    """``notes_floor`` (one line a paragraph) is at most the notes' height wrapped to any width, in
    every language's list — the least column ``floor_of`` builds on it stays under every column."""
    from graphplan.sheets.compose import notes_height
    assert K.notes_floor(notes) <= notes_height(notes, width)


def test_least_leaf_of_a_family_without_drawings_is_none():
    assert K.least_leaf([None]) is None
    assert K.least_leaf([]) is None
    got = K.least_leaf([Leaf("a", 3.0, 9.0), Leaf("b", 7.0, 2.0)])
    assert (got.w, got.h) == (3.0, 2.0)


def _plan_both_ways(monkeypatch, st, fmt):
    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.form import form
    from graphplan.sheets.kinematics import plan
    opts = SheetOptions(sheet="kinematics")
    monkeypatch.setattr(K, "PRUNED", True)
    pruned = plan.__wrapped__(st, form(fmt), opts)[0]
    monkeypatch.setattr(K, "PRUNED", False)
    whole = plan.__wrapped__(st, form(fmt), opts)[0]
    return pruned, whole


@pytest.mark.slow
@pytest.mark.parametrize("name,fmt", [("DRAGLINK_REVIEW59", "A1"), ("LINK61", "A1"), ("shaper", "A2")])
def test_the_skipped_grid_pairs_change_no_composition(monkeypatch, name, fmt):
    """The kinematics sheet's composition with the grid pairs skipped (``PRUNED``) is the one the
    plain search (every tree measured whole) chooses, Plan for Plan: the drag-link and LINK61 on
    A1, the shaper's A2 set (whose first try is one sheet)."""
    import review_scenes
    from conftest import example, scene_study
    st = scene_study(getattr(review_scenes, name)) if name.isupper() else example(name)
    pruned, whole = _plan_both_ways(monkeypatch, st, fmt)
    assert pruned == whole


@pytest.mark.slow
def test_bench_the_draglinks_a1_kinematics_composition(benchmark, monkeypatch):
    """The drag-link's A1 kinematics sheet composed cold (the plan alone, not numbered: the layout
    search this stop cut). Run with ``--benchmark-enable`` (stop 61: 10,0 → 7,0 s of CPU at load 17)."""
    import review_scenes
    from conftest import scene_study

    from graphplan.graphic import redraw as R
    from graphplan.sheets import kinematics as KS
    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.form import form
    st = scene_study(review_scenes.DRAGLINK_REVIEW59)

    def cold():
        KS._REDRAWN.clear()
        R._JUDGED.clear()
        return KS.plan.__wrapped__(st, form("A1"), SheetOptions(sheet="kinematics"))[0]
    p = benchmark.pedantic(cold, rounds=1, iterations=1)
    assert p.sheets == 1


def _construction_cold(st, fmt="A1"):
    """The dynamics construction of ``st`` on ``fmt`` composed from the start (no construction, its
    measures nor its flywheels kept)."""
    from graphplan.sheets import dynamics as D
    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.form import form
    f, args = form(fmt), SheetOptions(None, None, 0.5, "uk", "dynamics")
    dyn = D._analysed(st, None)
    key = D._construction_key(st, dyn, f, args)
    from graphplan.drawing import flywheel as FW
    for memo in (D._CONSTRUCTIONS, D._MEMOS, D._ONE):
        memo.pop(key, None)
    for memo in (D._BUILT, D._BANDS, FW._WITT):
        memo.clear()
    return D.construction(st, dyn, f, args)


@pytest.mark.slow
@pytest.mark.parametrize("name", ["DRAGLINK_REVIEW59", "LINK61", "shaper"])
def test_the_larger_diagrams_search_finds_what_the_plain_one_does(monkeypatch, name):
    """``larger`` with ``held`` asked only for the bands it can take (``dynamics.PRUNED``) builds the
    construction the plain search builds (every band ``held`` reaches drawn), tuple for tuple."""
    import review_scenes
    from conftest import example, scene_study

    from graphplan.sheets import dynamics as D
    st = scene_study(getattr(review_scenes, name)) if name.isupper() else example(name)
    monkeypatch.setattr(D, "PRUNED", True)
    pruned = _construction_cold(st)
    monkeypatch.setattr(D, "PRUNED", False)
    plain = _construction_cold(st)
    assert pruned == plain


@pytest.mark.slow
def test_bench_the_draglinks_a1_dynamics_construction(benchmark):
    """The drag-link's A1 dynamics construction (the classical scales, ``larger``, ``finer_energy``)
    composed cold. Run with ``--benchmark-enable`` (stop 61: 57,8 → 47,3 s of CPU at load 20)."""
    import review_scenes
    from conftest import scene_study
    st = scene_study(review_scenes.DRAGLINK_REVIEW59)
    got = benchmark.pedantic(lambda: _construction_cold(st), rounds=1, iterations=1)
    assert got[3] != "set"
