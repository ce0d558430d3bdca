"""A kinematics set's trial layouts remembered: ``kinlayout.set_of_sheets`` lays the set out some
12 000 times on the shaper's A3 (each family's scale grown step by step, each diagrams' size, both
orders, three widths of the notes, and the whole search once more after the drawings are measured),
half of them the same rows again. A trial's answer depends only on the rows' sizes and names, the
sheet's field and title blocks and the plans' own sizes: keyed on those, each distinct trial is laid
out once — the same answers, so the same sets byte for byte."""
from __future__ import annotations

from graphplan.drawing.layout import Box, Leaf, flow

_TRIALS: dict[tuple, tuple[int, int, float] | None] = {}
LIMIT = 200_000          # trials kept (a few tens of MB); past it the memo starts afresh


def _signature(node) -> tuple:
    """What ``flow`` reads of a node: a leaf's name, size and whether it holds a record; a grid's
    columns, gap, fitting and cells."""
    if node.__class__ is Leaf:
        return node.name, node.w, node.h, node.record is None
    return (node.__class__.__name__, getattr(node, "cols", None), node.gap, getattr(node, "fitted", None),
            getattr(node, "flush", None), tuple(_signature(c) for c in node.children))


def _key(rows) -> tuple:
    """The rows' signature (``_signature``; a leaf's written out in place: most cells are leaves, and a
    call per cell cost the lab crank-slider's A3 set a quarter of its time)."""
    return tuple((row.__class__.__name__,) + tuple((n.name, n.w, n.h, n.record is None) if n.__class__ is Leaf
                                                   else _signature(n) for n in row) for row in rows)


def _leaves(node):
    """The node's leaves in the order ``arrange`` places them."""
    if node.__class__ is Leaf:
        yield node
        return
    for c in node.children:
        yield from _leaves(c)


_COUNTS: dict[tuple, tuple[int, int] | None] = {}


def counted(rows, region: Box, keep: Box | None, later: Box | None) -> tuple[int, int] | None:
    """``trial``'s first two answers — (sheets, 1 where the last holds the notes alone else 0), or
    None where a drawing is larger than a sheet — from the rows as ``flow`` breaks them over the
    sheets (``lines``), no drawing placed: the set's search asks only the count of nearly every
    trial, the emptiest sheet's fill only of the few it keeps. The same answers as ``trial``."""
    key = (_key(rows), region, keep, later)
    if key in _COUNTS:
        return _COUNTS[key]
    pages = flow(rows, region, keep, later=later, ragged=True, lines=True)
    got = None if pages is None else (len(pages), int(all(leaf.name in ("notes", "") for _, _, items in pages[-1]
                                                          for item in items for leaf in _leaves(item))))
    if len(_COUNTS) >= LIMIT:
        _COUNTS.clear()
    _COUNTS[key] = got
    return got


def trial(rows, region: Box, keep: Box | None, later: Box | None,
          sizes: dict[str, tuple[float, float]]) -> tuple[int, int, float] | None:
    """The rows laid over a set of sheets (``flow``): (sheets, 1 where the last holds the notes alone
    else 0, the emptiest sheet's share drawn on — ``kinlayout.page_fill`` with ``sizes``), or None
    where a drawing is larger than a sheet."""
    from graphplan.sheets.kinlayout import page_fill
    key = (_key(rows), region, keep, later, tuple(sizes.items()))     # the sizes in the order ``own`` made them
    if key in _TRIALS:
        return _TRIALS[key]
    out = flow(rows, region, keep, later=later, ragged=True)
    got = None if out is None else (len(out), int(all(leaf.name in ("notes", "") for leaf, _ in out[-1])),
                                    min(page_fill(page, region, sizes) for page in out))
    if len(_TRIALS) >= LIMIT:
        _TRIALS.clear()
    _TRIALS[key] = got
    return got
