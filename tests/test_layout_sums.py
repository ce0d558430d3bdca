"""The composition's shortcuts add up as the plain sums do, to the bit: ``extent_with`` (a tree's
extent as a function of a few slot leaves' sizes, the rest added once) against ``extent`` of the
same tree with the slots at those sizes; ``split`` (its cuts remembered by the items' heights)
against every way of cutting the items, tried by hand."""
from __future__ import annotations

import itertools

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from graphplan.drawing.layout import Grid, Leaf, Row, Stack, extent, extent_with, split

SIZE = st.floats(0.0, 900.0, allow_nan=False, allow_infinity=False)
GAPS = st.sampled_from([0.0, 3.3, 6.0, 10.0])


@st.composite
def trees(draw, slots, depth=3):
    """A tree of rows and stacks over leaves, grids and the ``slots`` (each leaf a slot or not)."""
    if depth == 0 or draw(st.booleans()):
        pick = draw(st.integers(0, 5))
        if pick < len(slots):
            return slots[pick]
        if pick == 5:
            return Grid([Leaf("g", draw(SIZE), draw(SIZE)) for _ in range(draw(st.integers(1, 5)))],
                        draw(st.integers(1, 3)), draw(GAPS), fitted=draw(st.booleans()))
        return Leaf("x", draw(SIZE), draw(SIZE))
    kind = draw(st.sampled_from([Row, Stack]))
    return kind([draw(trees(slots, depth - 1)) for _ in range(draw(st.integers(1, 4)))], draw(GAPS),
                draw(st.booleans()))


@st.composite
def slotted(draw):
    slots = [Leaf("a"), Leaf("b"), None]
    return slots, draw(trees(slots[:2])), draw(st.lists(st.tuples(st.tuples(SIZE, SIZE), st.tuples(SIZE, SIZE)),
                                                        min_size=1, max_size=4))


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(slotted())
def test_extent_with_slots_is_the_trees_extent_to_the_bit(case):
    slots, tree, sizes = case
    sized = extent_with(tree, slots)
    for a, b in sizes:
        got = sized([a, b, None])
        slots[0].w, slots[0].h = a
        slots[1].w, slots[1].h = b
        assert got == extent(tree)             # the same floats, not nearly


def test_a_slot_inside_a_grid_is_refused():
    s = Leaf("s", 1.0, 1.0)
    try:
        extent_with(Row([Grid([s, Leaf("x", 2.0, 2.0)], 2)]), [s])
    except ValueError:
        return
    raise AssertionError("a slot in a grid taken")


@settings(deadline=None)
@given(st.lists(st.floats(0.5, 300.0), min_size=0, max_size=8), st.integers(1, 4), GAPS)
def test_split_is_the_first_of_the_lowest_cuts(heights, parts, gap):
    """By hand: every way of cutting the items into ``parts`` runs in order, the lowest tallest
    run (ties to the first met, cuts tried from the shortest first run)."""
    items = [Leaf(str(i), 10.0, h) for i, h in enumerate(heights)]
    got = split(items, parts, gap)
    n, k = len(items), max(1, min(parts, len(items)))
    best = None
    for ends in itertools.combinations(range(1, n), k - 1):
        bounds = list(zip((0,) + ends, ends + (n,)))
        tallest = max(sum(t.h for t in items[a:b]) + gap * (b - a - 1) for a, b in bounds)
        if best is None or tallest < best[0] - 1e-9:
            best = (tallest, [items[a:b] for a, b in bounds])
    assert got == (best[1] if n else [[]])
    assert split(items, parts, gap) == got     # remembered: the same groups of the same items again
