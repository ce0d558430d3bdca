"""Laying out a sheet: blocks (plans, diagrams, tables) placed in the free field of the frame so that
nothing overlaps and nothing crosses the frame or the title block (shapely regions), and labels
moved apart where they would collide."""
from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass

from shapely.geometry import Polygon, box
from shapely.strtree import STRtree

from graphplan.graphic.record import Primitive, Record
from graphplan.util.errors import GraphplanError

Box = tuple[float, float, float, float]


@dataclass
class Block:
    """Something to place: ``build(k)`` draws it at size factor k (1 = preferred; smaller factors
    mean a coarser standard scale), with its own origin anywhere."""
    name: str
    build: Callable[[float], Record]
    factors: Sequence[float] = (1.0,)


@dataclass
class Placed:
    name: str
    record: Record
    box: Box
    factor: float


def place(blocks: Sequence[Block], region: Box, obstacles: Sequence[Box] = (), gap: float = 6.0) -> list[Placed]:
    """Bottom-left-fill placement: each block goes to the highest, then leftmost free spot (candidate
    corners next to the blocks already placed); if it fits nowhere, the next smaller factor is tried."""
    placed, rest = place_some(blocks, region, obstacles, gap)
    if rest:
        raise GraphplanError(f"the sheet has no room for the {rest[0].name}; choose a larger --format "
                             "or fewer positions")
    return placed


def place_some(blocks: Sequence[Block], region: Box, obstacles: Sequence[Box] = (),
               gap: float = 6.0) -> tuple[list[Placed], list[Block]]:
    """As ``place``, but the blocks that fit nowhere are handed back (in order) instead of refused:
    (placed, the rest) — the rest go to the next sheet of a set."""
    field = box(*region)
    for ob in obstacles:
        field = field.difference(box(*ob))
    placed: list[Placed] = []
    rest: list[Block] = []
    taken: list[Box] = [tuple(ob) for ob in obstacles]
    for block in blocks:
        for factor in block.factors:
            rec = block.build(factor)
            x0, y0, x1, y1 = rec.bounds()
            w, h = x1 - x0, y1 - y0
            spot = _spot(w, h, region, taken, field, gap)
            if spot is not None:
                x, top = spot
                moved = rec.moved(x - x0, top - y1)
                placed.append(Placed(block.name, moved, (x, top - h, x + w, top), factor))
                taken.append((x, top - h, x + w, top))
                break
        else:
            rest.append(block)
    return placed, rest


def _spot(w: float, h: float, region: Box, taken: list[Box], field: Polygon, gap: float):
    rx0, ry0, rx1, ry1 = region
    xs = sorted({rx0} | {b[2] + gap for b in taken if b[2] + gap + w <= rx1})
    tops = sorted({ry1} | {b[1] - gap for b in taken if b[1] - gap - h >= ry0}, reverse=True)
    for top in tops:
        for x in xs:
            if x + w > rx1 + 1e-9 or top - h < ry0 - 1e-9:
                continue
            cand = (x, top - h, x + w, top)
            if any(_overlap(cand, b, gap) for b in taken):
                continue
            if field.contains(box(*cand)):
                return x, top
    return None


def _overlap(a: Box, b: Box, gap: float) -> bool:
    return not (a[2] + gap <= b[0] + 1e-9 or b[2] + gap <= a[0] + 1e-9
                or a[3] + gap <= b[1] + 1e-9 or b[3] + gap <= a[1] + 1e-9)


def text_boxes(record: Record) -> list[tuple[Primitive, Polygon]]:
    return [(p, box(*p.bounds())) for p in record.items if p.kind == "text"]


def declutter(record: Record, pad: float = 0.3, max_shift: float = 9.0) -> Record:
    """Move labels that would overlap a label already placed to the nearest free spot around
    their anchor (8 directions, growing radius). Labels in tables and the frame stay put."""
    fixed_layers = {"frame", "tables"}
    grid = _Grid()
    items = list(record.items)
    order = sorted(range(len(items)), key=lambda k: items[k].layer not in fixed_layers)
    for k in order:
        prim = items[k]
        if prim.kind != "text":
            continue
        rect = _grow(prim.bounds(), pad)
        if prim.layer in fixed_layers or not grid.hits(rect):
            grid.add(rect)
            continue
        r = 1.0
        while r <= max_shift:
            for dx, dy in ((0, 1), (1, 0), (0, -1), (-1, 0), (1, 1), (-1, 1), (1, -1), (-1, -1)):
                cand = prim.moved(dx * r, dy * r)
                crect = _grow(cand.bounds(), pad)
                if not grid.hits(crect):
                    items[k], rect = cand, crect
                    r = max_shift + 1
                    break
            r += 1.0
        grid.add(rect)
    return Record(record.title, items, dict(record.scales))


def _grow(b: Box, pad: float) -> Box:
    return b[0] - pad, b[1] - pad, b[2] + pad, b[3] + pad


class _Grid:
    """Rectangles bucketed in 10 mm cells for quick overlap queries."""

    def __init__(self, cell: float = 10.0):
        self.cell = cell
        self.cells: dict[tuple[int, int], list[Box]] = {}

    def _keys(self, b: Box):
        c = self.cell
        for i in range(int(b[0] // c), int(b[2] // c) + 1):
            for j in range(int(b[1] // c), int(b[3] // c) + 1):
                yield i, j

    def hits(self, b: Box) -> bool:
        return any(_overlap(b, o, 0.0) for key in self._keys(b) for o in self.cells.get(key, ()))

    def add(self, b: Box) -> None:
        for key in self._keys(b):
            self.cells.setdefault(key, []).append(b)


def overlapping_texts(record: Record) -> list[tuple[str, str]]:
    """Pairs of labels whose boxes overlap (used by the tests and as a final check)."""
    boxes = text_boxes(record)
    if not boxes:
        return []
    tree = STRtree([b for _, b in boxes])
    pairs = []
    for i, (p, b) in enumerate(boxes):
        for j in tree.query(b):
            if j > i and b.intersection(boxes[j][1]).area > 1e-6:
                pairs.append((p.text, boxes[j][0].text))
    return pairs




def spread(placed: list[Placed], region: Box, obstacles: Sequence[Box] = (), gap: float = 6.0,
           rounds: int = 6) -> list[Placed]:
    """The free field shared out: each block moved to the middle of the free span beside it, across
    then up and down, a few rounds — the draftsman spreading the drawings evenly over the sheet
    instead of leaving a bare strip at one side. No block comes closer than ``gap`` to another, to
    an obstacle or to the region's edge."""
    boxes = [list(p.box) for p in placed]
    fixed = [tuple(ob) for ob in obstacles]
    rx0, ry0, rx1, ry1 = region

    def span(i: int, axis: int) -> tuple[float, float]:
        b = boxes[i]
        lo, hi = (rx0, rx1) if axis == 0 else (ry0, ry1)
        other = 1 - axis
        for j, o in enumerate([tuple(x) for x in boxes] + fixed):
            if j == i:
                continue
            if o[other] >= b[other + 2] + gap - 1e-9 or b[other] >= o[other + 2] + gap - 1e-9:
                continue                       # no overlap across: not in the way
            if o[axis + 2] <= b[axis] + 1e-9:
                lo = max(lo, o[axis + 2] + gap)
            elif o[axis] >= b[axis + 2] - 1e-9:
                hi = min(hi, o[axis] - gap)
        return lo, hi

    for _ in range(rounds):
        for axis in (0, 1):
            for i in range(len(boxes)):
                lo, hi = span(i, axis)
                size = boxes[i][axis + 2] - boxes[i][axis]
                if hi - lo < size - 1e-9:
                    continue
                start = (lo + hi - size) / 2
                boxes[i][axis], boxes[i][axis + 2] = start, start + size
    out = []
    for p, b in zip(placed, boxes):
        dx, dy = b[0] - p.box[0], b[1] - p.box[1]
        out.append(Placed(p.name, p.record.moved(dx, dy), tuple(b), p.factor))
    return out
