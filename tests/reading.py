"""The order a reader takes a sheet's blocks in, from their boxes alone (not from the layout that
placed them). Two blocks side by side — their boxes sharing some height — are read left one first;
two one over the other — sharing some width — the upper one first. Blocks that share neither (one
lower-left, the other upper-right) may be read either way: a sheet read in rows takes the upper,
one read down its columns the left (a drawing over Table 1 beside Table 2 at the top of the next
column). A numbering is in reading order where no block precedes, so, one numbered before it.
Boxes are (x0, y0, x1, y1), y up (mm)."""
from __future__ import annotations

from typing import Sequence

Box = tuple[float, float, float, float]
TOL = 1e-6


def precedes(a: Box, b: Box) -> bool:
    """Whether every reader takes block ``a`` before block ``b``: ``a`` left of ``b`` in a band of
    height they share, or above it in a strip of width they share."""
    share_h = a[1] < b[3] - TOL and b[1] < a[3] - TOL
    share_w = a[0] < b[2] - TOL and b[0] < a[2] - TOL
    return (share_h and a[2] <= b[0] + TOL) or (share_w and a[1] >= b[3] - TOL)


def in_reading_order(boxes: Sequence[Box]) -> list[int]:
    """The blocks' indices as a reader may take them, keeping to the given order wherever no
    block precedes (``precedes``) the next one given: the given order itself exactly where it is a
    reading order (each step the first given of the blocks no other left precedes)."""
    left = list(range(len(boxes)))
    out = []
    while left:
        free = [i for i in left if not any(precedes(boxes[j], boxes[i]) for j in left if j != i)]
        k = free[0] if free else left[0]
        out.append(k)
        left.remove(k)
    return out
