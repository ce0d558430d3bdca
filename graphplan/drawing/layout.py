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
    solid: bool | str = False  # nested by its whole box (True), each figure's hull (HULL) or its ink


@dataclass
class Placed:
    name: str
    record: Record
    box: Box
    factor: float
    solid: bool | str = False


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


# -- nesting by footprints ----------------------------------------------------------------------
# A drawing's bounding box is mostly paper (a position plan's fan, a diagram's corner): blocks are
# nested by their footprints instead — the ink on a GRID-mm raster, grown by half the gap and with
# its enclosed holes filled — so a velocity plan may sit in the bare corner beside a position plan
# but never inside a figure or nearer than ``gap`` to another block's ink.

GRID = 2.5   # mm per raster cell


def _marks(prim: Primitive, step: float) -> list[tuple[float, float]]:
    """Points along a primitive's ink, ``step`` mm apart (text: its whole box)."""
    import math
    if prim.kind == "text":                   # each letter's own ink (its glyph's box), not the line's box
        from graphplan.graphic.record import ink_boxes
        x0, y0, _, _ = prim.bounds()
        out = []
        for a, b, c, d in ink_boxes(prim.text, prim.size):
            nx, ny = max(1, int((c - a) / step) + 1), max(1, int((d - b) / step) + 1)
            out += [(x0 + a + (c - a) * i / nx, y0 + b + (d - b) * j / ny)
                    for i in range(nx + 1) for j in range(ny + 1)]
        return out
    if prim.kind in ("circle", "arc"):
        (cx, cy), r = prim.points[0], prim.radius
        a0, a1 = prim.angles if prim.kind == "arc" else (0.0, 360.0)
        sweep = (a1 - a0) % 360.0 or 360.0
        n = max(2, int(math.radians(sweep) * r / step) + 1)
        return [(cx + r * math.cos(math.radians(a0 + sweep * k / n)),
                 cy + r * math.sin(math.radians(a0 + sweep * k / n))) for k in range(n + 1)]
    pts = list(prim.points)
    if prim.kind == "polygon":
        pts = pts + pts[:1]
    out = list(pts)
    for (xa, ya), (xb, yb) in zip(pts, pts[1:]):
        n = int(math.hypot(xb - xa, yb - ya) / step) + 1
        out += [(xa + (xb - xa) * k / n, ya + (yb - ya) * k / n) for k in range(1, n)]
    return out


@dataclass
class Footprint:
    """A record's footprint: ``mask[row, col]`` covers the cell whose lower-left corner is
    (x0 + col·GRID, y0 + row·GRID) in the record's coordinates (rows grow upward)."""
    mask: "object"
    x0: float
    y0: float


_FOOTPRINTS: dict[tuple, tuple[Record, Footprint]] = {}


HULL = "hull"     # a block's ``solid``: each figure's convex hull kept clear (a vector plan's fan)


def footprint(rec: Record, pad: float, solid: bool | str = False) -> Footprint:
    """The record's ink on the raster, grown by ``pad`` mm, its enclosed holes filled — or its
    whole box when ``solid`` is True, or each connected figure's convex hull when it is ``HULL``
    (nothing is nested among a plan's rays, while the notch beside its table stays free);
    remembered per record: a layout tries the same drawings many times."""
    key = (id(rec), pad, solid)
    hit = _FOOTPRINTS.get(key)
    if hit is not None and hit[0] is rec:
        return hit[1]
    if len(_FOOTPRINTS) > 4096:
        _FOOTPRINTS.clear()
    fp = _footprint(rec, pad)
    if solid == HULL:
        fp = Footprint(_hulls(fp.mask), fp.x0, fp.y0)
    elif solid:
        fp = Footprint(fp.mask | True, fp.x0, fp.y0)
    _FOOTPRINTS[key] = (rec, fp)
    return fp


def _hulls(mask):
    """The mask with each connected figure replaced by its filled convex hull."""
    import numpy as np
    import shapely
    from scipy import ndimage
    labels, n = ndimage.label(mask, structure=np.ones((3, 3)))
    out = mask.copy()
    rows, cols = np.mgrid[0:mask.shape[0], 0:mask.shape[1]]
    for k in range(1, n + 1):
        r, c = np.nonzero(labels == k)
        corners = np.concatenate([np.c_[c + dx, r + dy] for dx in (0, 1) for dy in (0, 1)])
        hull = shapely.MultiPoint(corners).convex_hull
        r0, r1, c0, c1 = r.min(), r.max() + 1, c.min(), c.max() + 1
        out[r0:r1, c0:c1] |= shapely.contains_xy(hull, cols[r0:r1, c0:c1] + 0.5, rows[r0:r1, c0:c1] + 0.5)
    return out


def ink(rec: Record, pad: float) -> Footprint:
    """The record's bare ink on the same raster as ``footprint(rec, pad)`` (not grown, holes kept):
    what a reader's eye — and a count of inked cells — sees of the block."""
    key = (id(rec), pad, "ink")
    hit = _FOOTPRINTS.get(key)
    if hit is not None and hit[0] is rec:
        return hit[1]
    fp = _footprint(rec, 0.0, margin_for=pad, fill=False)
    _FOOTPRINTS[key] = (rec, fp)
    return fp


def _footprint(rec: Record, pad: float, margin_for: float | None = None, fill: bool = True) -> Footprint:
    import numpy as np
    from scipy import ndimage
    bx0, by0, bx1, by1 = rec.bounds()
    margin = int(np.ceil((pad if margin_for is None else margin_for) / GRID)) + 1
    x0, y0 = bx0 - margin * GRID, by0 - margin * GRID
    w = int(np.ceil((bx1 - bx0) / GRID)) + 2 * margin + 1
    h = int(np.ceil((by1 - by0) / GRID)) + 2 * margin + 1
    mask = np.zeros((h, w), dtype=bool)
    pts = np.array([p for prim in rec.items for p in _marks(prim, GRID / 2)], dtype=float).reshape(-1, 2)
    if len(pts):
        cols = np.clip(((pts[:, 0] - x0) / GRID).astype(int), 0, w - 1)
        rows = np.clip(((pts[:, 1] - y0) / GRID).astype(int), 0, h - 1)
        mask[rows, cols] = True
    r = int(round(pad / GRID))
    if r > 0:
        yy, xx = np.mgrid[-r:r + 1, -r:r + 1]
        mask = ndimage.binary_dilation(mask, structure=(xx ** 2 + yy ** 2) <= r * r)
    return Footprint(ndimage.binary_fill_holes(mask) if fill else mask, x0, y0)


def _field(region: Box, obstacles: Sequence[Box]):
    """The region's raster with the obstacles' cells taken."""
    import numpy as np
    rx0, ry0, rx1, ry1 = region
    W, H = int((rx1 - rx0) / GRID), int((ry1 - ry0) / GRID)
    taken = np.zeros((H, W), dtype=bool)
    for ob in obstacles:
        c0, c1 = int(np.floor((ob[0] - rx0) / GRID)), int(np.ceil((ob[2] - rx0) / GRID))
        r0, r1 = int(np.floor((ob[1] - ry0) / GRID)), int(np.ceil((ob[3] - ry0) / GRID))
        taken[max(r0, 0):max(min(r1, H), 0), max(c0, 0):max(min(c1, W), 0)] = True
    return taken


def spread_nested(placed: list[Placed], region: Box, obstacles: Sequence[Box] = (), gap: float = 6.0,
                  rounds: int = 3) -> list[Placed]:
    """The nested blocks spread over the field: each moved (by whole raster cells) to the middle of
    the free run through its place, up and down, then across, a few rounds — the bare band a
    top-first packing leaves shared out between the drawings."""
    import numpy as np
    rx0, ry0, _, _ = region
    taken = _field(region, obstacles)
    H, W = taken.shape
    prints = [footprint(p.record, gap / 2, p.solid) for p in placed]
    at = []                                    # (row, col) of each footprint's lower-left cell
    for p, fp in zip(placed, prints):
        col = int(round((fp.x0 - rx0) / GRID))
        row = int(round((fp.y0 - ry0) / GRID))
        at.append([row, col])
    def stamp(i: int, on: bool) -> None:
        h, w = prints[i].mask.shape
        r, c = at[i]
        r0, c0 = max(r, 0), max(c, 0)
        sub = prints[i].mask[r0 - r:min(h, H - r), c0 - c:min(w, W - c)]
        if on:
            taken[r0:r0 + sub.shape[0], c0:c0 + sub.shape[1]] |= sub
        else:
            taken[r0:r0 + sub.shape[0], c0:c0 + sub.shape[1]] &= ~sub
    for i in range(len(placed)):
        stamp(i, True)
    for _ in range(rounds):
        for axis in (0, 1):
            for i in range(len(placed)):
                h, w = prints[i].mask.shape
                if h > H or w > W:
                    continue
                stamp(i, False)
                free = _overlaps(taken, prints[i].mask) < 0.5
                r, c = at[i]
                if 0 <= r < free.shape[0] and 0 <= c < free.shape[1] and free[r, c]:
                    line = free[:, c] if axis == 0 else free[r, :]
                    here = r if axis == 0 else c
                    lo = here
                    while lo - 1 >= 0 and line[lo - 1]:
                        lo -= 1
                    hi = here
                    while hi + 1 < len(line) and line[hi + 1]:
                        hi += 1
                    at[i][axis] = (lo + hi) // 2
                stamp(i, True)
    out = []
    for p, fp, (r, c) in zip(placed, prints, at):
        dx, dy = rx0 + c * GRID - fp.x0, ry0 + r * GRID - fp.y0
        moved = p.record.moved(dx, dy)
        out.append(Placed(p.name, moved, moved.bounds(), p.factor, p.solid))
    return out


def _overlaps(taken, mask):
    """For every offset (row, col) with the mask inside ``taken``: how many of its cells are taken
    (a correlation by FFT)."""
    import numpy as np
    H, W = taken.shape
    h, w = mask.shape
    shape = (-(-(H + h) // 32) * 32, -(-(W + w) // 32) * 32)
    key = (id(mask), shape)
    hit = _SPECTRA.get(key)
    if hit is None or hit[0] is not mask:          # a footprint is tried at many places: its spectrum once
        if len(_SPECTRA) > 512:
            _SPECTRA.clear()
        hit = _SPECTRA[key] = (mask, np.conj(np.fft.rfft2(mask.astype(float), shape)))
    full = np.fft.irfft2(np.fft.rfft2(taken.astype(float), shape) * hit[1], shape)
    return full[:H - h + 1, :W - w + 1]


_SPECTRA: dict = {}


def nest_some(blocks: Sequence[Block], region: Box, obstacles: Sequence[Box] = (),
              gap: float = 6.0, cells: "Cells | None" = None,
              slack: float = 0.0) -> tuple[list[Placed], list[Block]]:
    """Each block at the highest, then leftmost place where its footprint (grown by gap/2) meets
    no other's and stays in the region clear of the obstacles; the blocks that fit nowhere are
    handed back in order: (placed, the rest). With ``cells`` (the judging grid), among the free
    places only those where the block's ink reaches the most cells still bare (less ``slack``
    cells) are taken — see ``cover_some``."""
    import numpy as np
    rx0, ry0, rx1, ry1 = region
    taken = _field(region, obstacles)
    H, W = taken.shape
    grid = _cell_grid(region, cells) if cells is not None else None
    placed: list[Placed] = []
    rest: list[Block] = []
    for block in blocks:
        for factor in block.factors:
            rec = block.build(factor)
            fp = footprint(rec, gap / 2, block.solid)
            h, w = fp.mask.shape
            if h > H or w > W:
                continue
            free = _overlaps(taken, fp.mask) < 0.5      # at (row, col) of the footprint's lower-left cell
            if not free.any():
                continue
            if grid is not None:
                bare, origin, step = grid
                seen = ink(rec, gap / 2).mask
                score = np.where(free, _cover_scores(bare, seen, origin, step, free.shape), -np.inf)
                free &= score >= score.max() - slack - 1e-9
            rows, cols = np.nonzero(free)
            row = rows.max()
            col = cols[rows == row].min()
            taken[row:row + h, col:col + w] |= fp.mask
            if grid is not None:
                _mark(bare, seen, row, col, origin, step)
            dx, dy = rx0 + col * GRID - fp.x0, ry0 + row * GRID - fp.y0
            moved = rec.moved(dx, dy)
            placed.append(Placed(block.name, moved, moved.bounds(), factor, block.solid))
            break
        else:
            rest.append(block)
    return placed, rest


# -- using the field: the 25 mm cells a sheet is judged by ---------------------------------------------
# A sheet is judged by how many of its 25 mm cells hold some ink. ``cover_some`` nests like
# ``nest_some`` but puts each block where its ink reaches the most cells still bare (ties: highest,
# then leftmost), so the smaller drawings go to the bare parts of the sheet instead of piling up
# beside the first ones.

@dataclass
class Cells:
    """The judging grid: the whole cells of ``size`` mm inside ``within`` (mm, y up), counted from its
    top-left corner as a reader's ruler would; cells whose middle lies in a ``skip`` box (the title
    block) are not counted."""
    within: Box
    size: float = 25.0
    skip: Sequence[Box] = ()


def _cell_grid(region: Box, cells: Cells):
    """(counted, origin, step): a boolean grid of cells, rows upward, True where a cell counts; the
    raster row/col (relative to the region's corner) of its first cell's lower-left corner; the
    cell's size in raster cells."""
    import numpy as np
    rx0, ry0, _, _ = region
    step = int(round(cells.size / GRID))
    wx0, wy0, wx1, wy1 = cells.within
    nc, nr = int((wx1 - wx0) // cells.size), int((wy1 - wy0) // cells.size)
    bottom = wy1 - nr * cells.size                       # the lowest whole row's lower edge
    origin = (int(round((bottom - ry0) / GRID)), int(round((wx0 - rx0) / GRID)))
    counted = np.ones((nr, nc), dtype=bool)
    for i in range(nr):
        for j in range(nc):
            mx, my = wx0 + (j + 0.5) * cells.size, bottom + (i + 0.5) * cells.size
            x0, y0 = mx - cells.size / 2, my - cells.size / 2
            if any(x0 + cells.size > b[0] and y0 < b[3] and x0 < b[2] and y0 + cells.size > b[1]
                   for b in cells.skip):
                counted[i, j] = False
    return counted, origin, step


def _coarse(mask, pr: int, pc: int, step: int):
    """Which cells a fine mask touches when its first row/col lies ``pr``/``pc`` raster cells into a cell."""
    import numpy as np
    h, w = mask.shape
    H, W = -(-(h + pr) // step) * step, -(-(w + pc) // step) * step
    big = np.zeros((H, W), dtype=bool)
    big[pr:pr + h, pc:pc + w] = mask
    return big.reshape(H // step, step, W // step, step).any(axis=(1, 3))


PHASE = 2   # the cover search tries every 2nd raster offset within a cell (5 mm steps)


def _cover_scores(bare, mask, origin, step: int, shape):
    """For every raster offset (row, col) of a block's lower-left cell within ``shape``: how many
    still-bare cells its ink would reach."""
    import numpy as np
    from scipy.signal import correlate2d
    r0, c0 = origin
    Hf, Wf = shape
    out = np.full((Hf, Wf), -0.5)      # offsets off the tried phases: only where no tried one is free
    for pr in range(0, step, PHASE):
        rows = np.arange(Hf)
        rows = rows[(rows - r0) % step == pr]
        if not len(rows):
            continue
        for pc in range(0, step, PHASE):
            cols = np.arange(Wf)
            cols = cols[(cols - c0) % step == pc]
            if not len(cols):
                continue
            m = _coarse(mask, pr, pc, step).astype(float)
            pad_r, pad_c = m.shape
            padded = np.zeros((bare.shape[0] + 2 * pad_r, bare.shape[1] + 2 * pad_c))
            padded[pad_r:pad_r + bare.shape[0], pad_c:pad_c + bare.shape[1]] = bare
            full = correlate2d(padded, m, mode="valid")
            R = (rows - r0) // step + pad_r
            C = (cols - c0) // step + pad_c
            okr = (R >= 0) & (R < full.shape[0])
            okc = (C >= 0) & (C < full.shape[1])
            out[np.ix_(rows[okr], cols[okc])] = full[np.ix_(R[okr], C[okc])]
    return out


def _mark(bare, mask, row: int, col: int, origin, step: int) -> None:
    """The cells a block's ink reaches, placed at raster (row, col), are no longer bare."""
    for cell in _reach(mask, row, col, origin, step, bare.shape):
        bare[cell] = False


def cover_some(blocks: Sequence[Block], region: Box, cells: Cells, obstacles: Sequence[Box] = (),
               gap: float = 6.0, slack: float = 0.0) -> tuple[list[Placed], list[Block]]:
    """As ``nest_some`` (each block at its first factor that fits), but each block goes where its ink
    reaches the most cells still bare (less ``slack`` cells: the packing kept tighter); of those
    places the highest, then leftmost."""
    return nest_some(blocks, region, obstacles, gap, cells=cells, slack=slack)


def bare_cells(placed: Sequence[Placed], region: Box, cells: Cells, gap: float = 6.0) -> float:
    """The share of the counted cells that no placed block's ink reaches (an estimate on the raster
    of what the sheet's test counts on the rendered page)."""
    bare, origin, step = _cell_grid(region, cells)
    counted = int(bare.sum())
    rx0, ry0, _, _ = region
    for p in placed:
        fp = ink(p.record, gap / 2)
        row, col = int(round((fp.y0 - ry0) / GRID)), int(round((fp.x0 - rx0) / GRID))
        _mark(bare, fp.mask, row, col, origin, step)
    return float(bare.sum()) / max(counted, 1)


def _reach(mask, row: int, col: int, origin, step: int, shape) -> list[tuple[int, int]]:
    """The cells (i, j) of the judging grid a block's ink reaches when placed at raster (row, col)."""
    r0, c0 = origin
    m = _coarse(mask, (row - r0) % step, (col - c0) % step, step)
    R, C = (row - r0) // step, (col - c0) // step
    return [(R + i, C + j) for i, j in zip(*m.nonzero())
            if 0 <= R + i < shape[0] and 0 <= C + j < shape[1]]


def improve(placed: list[Placed], region: Box, cells: Cells, obstacles: Sequence[Box] = (),
            gap: float = 6.0, rounds: int = 2) -> list[Placed]:
    """The layout bettered block by block: each drawing lifted off and put back where its ink
    reaches the most cells the others leave bare, if that is more than where it was (a local
    search on the count the sheet is judged by; it never inks fewer cells)."""
    import numpy as np
    rx0, ry0, _, _ = region
    taken = _field(region, obstacles)
    H, W = taken.shape
    counted, origin, step = _cell_grid(region, cells)
    hits = np.zeros(counted.shape, dtype=int)          # how many blocks ink each cell
    prints = [footprint(p.record, gap / 2, p.solid) for p in placed]
    inks = [ink(p.record, gap / 2) for p in placed]
    at = [[int(round((fp.y0 - ry0) / GRID)), int(round((fp.x0 - rx0) / GRID))] for fp in prints]

    def stamp(i: int, sign: int) -> None:
        r, c = at[i]
        h, w = prints[i].mask.shape
        if r < 0 or c < 0 or r + h > H or c + w > W:
            raise ValueError("outside")
        if sign > 0:
            taken[r:r + h, c:c + w] |= prints[i].mask
        else:
            taken[r:r + h, c:c + w] &= ~prints[i].mask
        for cell in _reach(inks[i].mask, r, c, origin, step, counted.shape):
            hits[cell] += sign
    try:
        for i in range(len(placed)):
            stamp(i, +1)
    except ValueError:                                  # a block off the raster: leave the layout
        return placed
    for _ in range(rounds):
        moved_any = False
        for i in range(len(placed)):
            stamp(i, -1)
            bare = counted & (hits == 0)
            here = sum(bare[cell] for cell in _reach(inks[i].mask, *at[i], origin, step, counted.shape))
            free = _overlaps(taken, prints[i].mask) < 0.5
            score = np.where(free, _cover_scores(bare, inks[i].mask, origin, step, free.shape), -np.inf)
            if score.max() > here + 0.5:
                rows, cols = np.nonzero(free & (score >= score.max() - 1e-9))
                at[i] = [int(rows.max()), int(cols[rows == rows.max()].min())]
                moved_any = True
            stamp(i, +1)
        if not moved_any:
            break
    out = []
    for p, fp, (r, c) in zip(placed, prints, at):
        moved = p.record.moved(rx0 + c * GRID - fp.x0, ry0 + r * GRID - fp.y0)
        out.append(Placed(p.name, moved, moved.bounds(), p.factor, p.solid))
    return out
