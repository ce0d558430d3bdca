"""Composing a sheet by construction (../docs/composition.md): zones that tile the field, each owning
its drawings, so nothing can overlap — no search, a few sums.

A composition is a tree. A ``Leaf`` is one drawing (a record with its caption and lettering, or just
its size while the scales are being chosen); a ``Row`` sets its children side by side, a ``Stack``
one under another, a ``Grid`` sets equal cells in reading order (row by row). ``extent`` adds sizes
up the tree; ``arrange`` hands each child a box inside its parent's and puts every drawing in its
own box (centred), the spare room shared out evenly between the drawings instead of left in a strip.
A drawing never leaves its box, and boxes of one parent never meet: by construction no drawing
nests in another and no lettering of one runs into another.
"""
from __future__ import annotations

import functools
import math
from collections.abc import Iterator, Sequence
from dataclasses import dataclass

from graphplan.graphic.record import Record

Box = tuple[float, float, float, float]
GAP = 6.0        # mm between neighbouring drawings


@dataclass
class Leaf:
    """One drawing: its ``record`` (any origin) and its size (w, h) — the record's own unless given
    (a grid's cell is as large as the largest drawing of the grid) — or only the size while the
    scales are being chosen."""
    name: str
    w: float = 0.0
    h: float = 0.0
    record: Record | None = None

    def __post_init__(self) -> None:
        if self.record is not None and not (self.w or self.h):
            x0, y0, x1, y1 = self.record.bounds()
            self.w, self.h = x1 - x0, y1 - y0


def cells(children: list[Leaf]) -> list[Leaf]:
    """The drawings as equal cells, each as large as the largest (width and height apart)."""
    if not children:
        return []
    w, h = max(c.w for c in children), max(c.h for c in children)
    return [Leaf(c.name, w, h, c.record) for c in children]


@dataclass
class Row:
    """Children side by side, in order from the left; the spare width shared out evenly between and
    around them, or, ``flush``, only between them (the first and last touch the box's sides)."""
    children: list
    gap: float = GAP
    flush: bool = False


@dataclass
class Stack:
    """Children one under another, in order from the top; the spare height shared out evenly
    between and around them, or, ``flush``, only between them."""
    children: list
    gap: float = GAP
    flush: bool = False


@dataclass
class Grid:
    """Equal cells, ``cols`` to a row, filled row by row (cell i holds child i): the velocity plans
    0, 1, 2 … read like a text. A cell is as large as the largest child — or, ``fitted``, each
    column as wide as its widest child (the columns line up) and each row as tall as its tallest
    (a slotter's twelve velocity plans 36–162 mm tall: three rows of the tallest took 43 mm more
    than the sheet had beside its position plan at 1:2.5; the coulisse's plans 9 and 10, 2.7 times
    as wide as the others, made every column theirs)."""
    children: list
    cols: int
    gap: float = GAP
    fitted: bool = False

    @property
    def rows(self) -> int:
        return -(-len(self.children) // max(self.cols, 1))

    def heights(self) -> list[float]:
        """Each row's height: the cell's, or (``fitted``) its tallest child's (once: a grid's
        children and columns are not changed once it is made — a six-bar's A1 composition asked
        its velocity grids 200 000 times)."""
        if "_heights" not in self.__dict__:
            self._heights = self._heights_of()
        return list(self._heights)

    def widths(self) -> list[float]:
        """Each column's width: the cell's, or (``fitted``) its widest child's (once, as ``heights``)."""
        if "_widths" not in self.__dict__:
            self._widths = self._widths_of()
        return list(self._widths)

    def _heights_of(self) -> list[float]:
        if not self.fitted:
            return [self.cell()[1]] * self.rows
        hs = [extent(c)[1] for c in self.children]
        k = max(self.cols, 1)
        return [max(hs[j:j + k]) for j in range(0, len(hs), k)]

    def _widths_of(self) -> list[float]:
        k = max(self.cols, 1)
        if not self.fitted:
            return [self.cell()[0]] * k
        ws = [extent(c)[0] for c in self.children]
        return [max(ws[j::k], default=0.0) for j in range(k)]

    def cell(self) -> tuple[float, float]:
        """The cell's size: the largest child's width and height."""
        if not hasattr(self, "_cell"):
            sizes = [extent(c) for c in self.children] or [(0.0, 0.0)]
            self._cell = (max(w for w, _ in sizes), max(h for _, h in sizes))
        return self._cell


Node = Leaf | Row | Stack | Grid


def extent(node: Node) -> tuple[float, float]:
    """The least (width, height) the node needs, gaps included."""
    cls = node.__class__
    if cls is Leaf:                  # a composition's search asks ~10⁶ times a sheet: the leaves inline
        return node.w, node.h
    if cls is not Row and cls is not Stack:
        if isinstance(node, Leaf):
            return node.w, node.h
        if not node.children:
            return 0.0, 0.0
        if isinstance(node, Grid):
            # once a grid (its children and columns are not changed once it is made: ``heights``);
            # a kinematics sheet's search asks the same grid under every table arrangement
            got = node.__dict__.get("_extent")
            if got is None:
                width = sum(node.widths()) if node.fitted else node.cell()[0] * node.cols
                got = node._extent = (width + node.gap * (node.cols - 1), sum(node.heights()) + node.gap * (node.rows - 1))
            return got
    children = node.children
    if not children:
        return 0.0, 0.0
    ws: list[float] = []
    hs: list[float] = []
    for c in children:
        if c.__class__ is Leaf:
            ws.append(c.w)
            hs.append(c.h)
        else:
            w, h = extent(c)
            ws.append(w)
            hs.append(h)
    # summed and maxed by the builtins over the lists, as before: the same sums to the last bit
    if cls is Row or (cls is not Stack and isinstance(node, Row)):
        return sum(ws) + node.gap * (len(ws) - 1), max(hs)
    return max(ws), sum(hs) + node.gap * (len(hs) - 1)


def extent_with(node: Node, slots: Sequence[Leaf | None]):
    """``extent(node)`` as a function of the sizes of the leaves ``slots`` (each in the tree as
    itself, in no ``Grid``; None: none): ``f(sizes)`` — a (w, h) a slot, or None for a None slot —
    is the same sums and maxima, to the bit, as ``extent`` of the tree with those leaves of those
    sizes, the subtrees that hold no slot added up once (a composition's search tries one tree with
    each of its tables' columns and its plans' grids: the one-sheet force sheet ~70 trees a trial)."""
    at = {id(s): k for k, s in enumerate(slots) if s is not None}
    # the rows and stacks on a path from a slot to the root, children before parents: each its
    # children's sizes with the constant ones filled in, and where a slot's or such a node's go
    program: list[tuple[bool, float, list[float], list[float], list[tuple[int, bool, int]]]] = []

    def compiled(n) -> tuple[bool, int] | None:
        """(a slot?, its index) — a slot, or a node on a slot's path — or None: constant."""
        if id(n) in at:
            return True, at[id(n)]
        kids = getattr(n, "children", None)
        if not kids:
            return None
        refs = [compiled(c) for c in kids]
        if all(r is None for r in refs):
            return None
        if not isinstance(n, (Row, Stack)):
            raise ValueError("a slot inside a grid")
        ws: list[float] = []
        hs: list[float] = []
        subs = []
        for j, (c, r) in enumerate(zip(kids, refs)):
            w, h = extent(c) if r is None else (0.0, 0.0)
            ws.append(w)
            hs.append(h)
            if r is not None:
                subs.append((j, *r))
        row = n.__class__ is Row or (n.__class__ is not Stack and isinstance(n, Row))
        program.append((row, n.gap, ws, hs, subs))
        return False, len(program) - 1
    root = compiled(node)
    whole = extent(node) if root is None else None

    def sized(sizes: Sequence[tuple[float, float] | None]) -> tuple[float, float]:
        if root is None:
            return whole
        if root[0]:
            return tuple(sizes[root[1]])
        vals: list[tuple[float, float]] = []
        for row, gap, ws0, hs0, subs in program:
            ws, hs = ws0[:], hs0[:]
            for j, slot, k in subs:
                ws[j], hs[j] = sizes[k] if slot else vals[k]
            vals.append((sum(ws) + gap * (len(ws) - 1), max(hs)) if row
                        else (max(ws), sum(hs) + gap * (len(hs) - 1)))
        return vals[-1]
    return sized


def fits(node: Node, w: float, h: float) -> bool:
    """Whether the node's extent fits a box w × h (mm)."""
    nw, nh = extent(node)
    return nw <= w + 1e-9 and nh <= h + 1e-9


def _shares(sizes: list[float], room: float, gap: float, flush: bool = False) -> list[tuple[float, float]]:
    """Spans (start, length) along an axis: each child its size, the spare room shared out evenly
    as wider gaps between the children and half as much at either end (``flush``: none at the
    ends; a single child then keeps to the start)."""
    n = len(sizes)
    spare = max(0.0, room - sum(sizes) - gap * (n - 1))
    if flush:
        extra, at = (spare / (n - 1) if n > 1 else 0.0), 0.0
    else:
        extra = spare / n
        at = extra / 2
    out = []
    for s in sizes:
        out.append((at, s))
        at += s + gap + extra
    return out


def arrange(node: Node, box: Box) -> Iterator[tuple[Leaf, Box]]:
    """Every leaf with the box it owns inside ``box`` (x0, y0, x1, y1; y up)."""
    x0, y0, x1, y1 = box
    if isinstance(node, Leaf):
        yield node, box
        return
    if isinstance(node, Row):
        spans = _shares([extent(c)[0] for c in node.children], x1 - x0, node.gap, node.flush)
        for c, (at, w) in zip(node.children, spans):
            yield from arrange(c, (x0 + at, y0, x0 + at + w, y1))
        return
    if isinstance(node, Stack):
        spans = _shares([extent(c)[1] for c in node.children], y1 - y0, node.gap, node.flush)
        for c, (at, hgt) in zip(node.children, spans):
            yield from arrange(c, (x0, y1 - at - hgt, x1, y1 - at))
        return
    cols, rows = node.cols, node.rows
    if node.fitted:                 # each column its own width, the spare width shared evenly
        ws = node.widths()
        wider = max(0.0, x1 - x0 - node.gap * (cols - 1) - sum(ws)) / cols
        ws = [w + wider for w in ws]
        lefts = [x0 + sum(ws[:k]) + k * node.gap for k in range(cols)]
    else:
        cw = (x1 - x0 - node.gap * (cols - 1)) / cols
        ws, lefts = [cw] * cols, [x0 + k * (cw + node.gap) for k in range(cols)]
    hs = node.heights()
    extra = max(0.0, y1 - y0 - node.gap * (rows - 1) - sum(hs)) / rows     # the spare height shared evenly
    tops = [y1 - sum(hs[:r]) - r * (extra + node.gap) for r in range(rows)]
    for i, c in enumerate(node.children):
        r, k = divmod(i, cols)
        yield from arrange(c, (lefts[k], tops[r] - hs[r] - extra, lefts[k] + ws[k], tops[r]))


def centred(rec: Record, box: Box) -> Record:
    """The record moved to the middle of ``box``."""
    x0, y0, x1, y1 = rec.bounds()
    bx0, by0, bx1, by1 = box
    return rec.moved((bx0 + bx1) / 2 - (x0 + x1) / 2, (by0 + by1) / 2 - (y0 + y1) / 2)


def top_left(rec: Record, box: Box) -> Record:
    """The record moved to the top-left corner of ``box``."""
    x0, _, _, y1 = rec.bounds()
    return rec.moved(box[0] - x0, box[3] - y1)


@dataclass
class Placed:
    """A drawing on the sheet: its name, its record in sheet mm and the box it owns."""
    name: str
    record: Record
    box: Box


def placed(node: Node, box: Box) -> list[Placed]:
    """Each drawing of the tree moved into the box it owns (centred in it)."""
    out = []
    for leaf, b in arrange(node, box):
        if leaf.record is not None:
            out.append(Placed(leaf.name, centred(leaf.record, b), b))
    return out


def best_grid(children: list, w: float, h: float, gap: float = GAP) -> Grid | None:
    """The grid of these children that fits w × h with cells most like the room's shape (the most
    of the zone filled); None when no column count fits."""
    best = None
    for cols in range(1, len(children) + 1):
        g = Grid(children, cols, gap)
        gw, gh = extent(g)
        if gw > w + 1e-9 or gh > h + 1e-9:
            continue
        fill = min(w / gw if gw else math.inf, h / gh if gh else math.inf)   # how much the cells could grow
        key = (round(fill, 9), cols)
        if best is None or key > best[0]:
            best = (key, g)
    return best[1] if best else None


def split(items: Sequence[Leaf], parts: int, gap: float = GAP, counts: Sequence[int] = ()) -> list[list[Leaf]]:
    """The items in ``parts`` consecutive groups (their order kept) whose tallest stack of items is
    as short as it can be: tables set in that many columns — or, given ``counts``, that many items
    in each group (the grouping a plan found, kept when the items are redrawn)."""
    n = len(items)
    if counts and sum(counts) == n:
        ends = [0]
        for c in counts:
            ends.append(ends[-1] + c)
        return [list(items[a:b]) for a, b in zip(ends[:-1], ends[1:])]
    parts = max(1, min(parts, n))
    return [list(items[a:b]) for a, b in _split_bounds(tuple(t.h for t in items), parts, gap)]


@functools.lru_cache(maxsize=4096)
def _split_bounds(heights: tuple[float, ...], parts: int, gap: float) -> tuple[tuple[int, int], ...]:
    """``split``'s groups as (start, end) of each, by the items' heights alone (the search tries
    every way to cut them — once per heights: a force set's search asked the same tables' column
    ~30 000 times, a fifth of its CPU)."""
    n = len(heights)
    best = None

    def height(a: int, b: int) -> float:
        return sum(heights[a:b]) + gap * (b - a - 1)

    def cuts(start: int, left: int):
        if left == 1:
            yield [(start, n)]
            return
        for end in range(start + 1, n - left + 2):
            for rest in cuts(end, left - 1):
                yield [(start, end)] + rest
    for groups in cuts(0, parts):
        tallest = max(height(a, b) for a, b in groups)
        if best is None or tallest < best[0] - 1e-9:
            best = (tallest, groups)
    return tuple(best[1]) if best else ((0, 0),)


def column_size(groups: list[list[Leaf]], gap: float = GAP) -> tuple[float, float]:
    """The width and height of tables set in columns, one group a column, side by side."""
    if not groups or not any(groups):
        return 0.0, 0.0
    ws = [max(t.w for t in g) for g in groups if g]
    hs = [sum(t.h for t in g) + gap * (len(g) - 1) for g in groups if g]
    return sum(ws) + gap * (len(ws) - 1), max(hs)


def set_columns(groups: list[list[Leaf]], left: float, top: float, gap: float = GAP) -> list[Placed]:
    """Tables set in columns from (``left``, ``top``): a group a column, in reading order — down
    each column, then the next column to the right; each table at its column's left."""
    out = []
    x = left
    for g in groups:
        if not g:
            continue
        y = top
        for t in g:
            b = (x, y - t.h, x + t.w, y)
            out.append(Placed(t.name, top_left(t.record, b) if t.record is not None else Record(), b))
            y -= t.h + gap
        x += max(t.w for t in g) + gap
    return out


def boxes_apart(items: Sequence[Placed], gap: float = 0.0) -> list[tuple[str, str]]:
    """Pairs of placed drawings whose boxes meet (a check: by construction there are none)."""
    out = []
    for i, a in enumerate(items):
        for b in items[i + 1:]:
            p, q = a.box, b.box
            if p[0] < q[2] + gap and q[0] < p[2] + gap and p[1] < q[3] + gap and q[1] < p[3] + gap:
                out.append((a.name, b.name))
    return out


def _prefix(items: list[Node], y: float, bottom: float, room, width, over=None) -> tuple[list[Node], float]:
    """The longest run of ``items`` from the first that fits side by side under ``y`` (above
    ``bottom``, within ``room``, or where ``over(items, y, h)`` is false), and its height: what of a
    row fills the rest of a sheet."""
    fit: list[Node] = []
    height = 0.0
    for item in items:
        h = max(height, extent(item)[1])
        if y - h < bottom - 1e-9 or (over(fit + [item], y, h) if over is not None
                                     else width(fit + [item]) > room(y, h) + 1e-9):
            break
        fit.append(item)
        height = h
    return fit, height


class Shelf(list):
    """A row of ``flow`` whose items (a set's tables and notes, in order) are broken into lines
    where that puts the most of them on the sheet being filled, not wherever the next one no longer
    fits across: the six-bar's A3 set put Tables 1 and 2 side by side (a row 187 mm high) with the
    top 40 % of its sheet blank and Tables 3–5 on the next; Table 1 alone over Tables 2, 3, 4 fills
    it."""


SHELF_MOST = 8     # a shelf of more items than this is broken as any row (2^7 ways to break 8)


def _shelf_lines(items: list, y: float, bottom: float, gap: float, over) -> tuple[list, float]:
    """``Shelf``'s lines on the sheet from ``y`` down: the lines any row is broken into where they
    hold every item above ``bottom`` (not ``over`` the room); else, of the ways to break ``items``
    into lines in order, one that puts the most of them on the sheet, in the least height (lines
    ``L[j]`` ending before item j, in O(n²)); ((top, height, line) of each, the next line's top)."""
    n = len(items)
    heights = [extent(t)[1] for t in items]

    def laid(breaks: list[int]) -> tuple[list, float]:
        used, top = [], y
        for a, b in zip(breaks, breaks[1:]):
            h = max(heights[a:b])
            used.append((top, h, items[a:b]))
            top -= h + gap
        return used, top
    greedy, start, top = [0], 0, y      # first as any row breaks them: kept where they hold all
    for i in range(1, n + 1):
        h = max(heights[start:i])
        if i < n and not over(items[start:i + 1], top, max(h, heights[i])):
            continue
        if top - h < bottom - 1e-9 or over(items[start:i], top, h):
            break
        greedy.append(i)
        top -= h + gap
        start = i
    if greedy[-1] == n:
        return laid(greedy)
    inf = math.inf
    least = [0.0] + [inf] * n           # the least height that lays items[:j] in lines
    before = [0] * (n + 1)
    shape: list[list | None] = [None] * (n + 1)     # a line of columns ending before item j, or None: a row
    for j in range(1, n + 1):
        for i in range(j):
            if least[i] == inf:
                continue
            top = y - least[i] - (gap if i else 0.0)
            h = max(heights[i:j])
            line = None
            if top - h < bottom - 1e-9 or over(items[i:j], top, h):
                line, h = _columns(items[i:j], top, bottom, gap, over)
                if line is None:
                    continue
            if top - h > y - least[j] + 1e-9:
                least[j] = y - (top - h)
                before[j] = i
                shape[j] = line
    j = max(k for k in range(n + 1) if least[k] < inf)
    breaks = [j]
    while breaks[-1] > 0:
        breaks.append(before[breaks[-1]])
    if not j:
        return [], y
    breaks = breaks[::-1]
    if not any(shape[b] for b in breaks[1:]):
        return laid(breaks)
    used, top = [], y
    for a, b in zip(breaks, breaks[1:]):
        line = shape[b] or items[a:b]
        h = max(extent(t)[1] for t in line)
        used.append((top, h, line))
        top -= h + gap
    return used, top


def _held(node) -> int:
    """How many of a shelf's items a node of its lines holds: a column (``_columns``' ``Stack``) its
    items, an item one."""
    return len(node.children) if getattr(node, "column", False) else 1


def _column(items: list) -> Stack:
    """A column of a shelf's line (``_columns``): its items one under another."""
    col = Stack(list(items))
    col.column = True
    return col


def _columns(items: list, top: float, bottom: float, gap: float, over) -> tuple[list | None, float]:
    """``items`` as one line of columns, in reading order — down each column, then the next to the
    right, as the A1's tables' column reads — where no line of them side by side fits: the lowest
    such line that stands above ``bottom`` and is not ``over`` the room, as (its columns, each a
    ``Stack`` of two or more items or an item alone; its height), else (None, 0). A set's tables and
    notes took a row each over two sheets: LINK59's A3 sheet 6 held Tables 1–3 in its middle third,
    sheet 7 Table 4 and the notes in its top third (stop 59)."""
    n = len(items)
    best, least = None, math.inf
    for mask in range(1 << (n - 1)):            # a break after item k where bit k is set
        groups, start = [], 0
        for k in range(n - 1):
            if mask >> k & 1:
                groups.append(items[start:k + 1])
                start = k + 1
        groups.append(items[start:])
        if len(groups) == n:                    # one item a column: the row itself
            continue
        line = [_column(g) if len(g) > 1 else g[0] for g in groups]
        h = max(extent(t)[1] for t in line)
        if h >= least - 1e-9 or top - h < bottom - 1e-9 or over(line, top, h):
            continue
        best, least = line, h
    return best, (least if best is not None else 0.0)


def flow(rows: Sequence[Sequence[Node]], region: Box, keep: Box | None = None, gap: float = GAP,
         later: Box | None = None, ragged: bool = False, lines: bool = False) -> list | None:
    """Rows of drawings set down a set of sheets in reading order: each row's items side by side
    while they fit across (the rest wrap to the next row), rows one under another, a new sheet when
    the next row does not fit below. Near the foot a row keeps clear of ``keep`` (the title block).
    The spare room of each row is shared out across it, a sheet's spare height between its rows
    (where no row then meets the title block). None when one item is larger than a sheet. ``later``:
    the title block kept clear of on the sheets after the first (a set's smaller form 2a), else ``keep``.
    ``ragged``: the room beside the title block is judged item by item, not by the row's tallest —
    an item whose own foot clears the title block may stand above it (the six-bar's A3 position plan,
    224.6 mm tall, reached 3.6 mm below the title block's top, so its row held 199 mm, not the 385 mm
    across, and the four velocity plans beside it went to the next sheet, leaving sheet 1 half blank).
    ``lines``: only the sheets as broken into rows — per sheet the (top, height, items) of each row,
    before any spare room is shared out and any drawing placed (what counting the sheets needs: a
    set's search lays out thousands of trials)."""
    rx0, ry0, rx1, ry1 = region
    pages: list[list[tuple[float, float, list[Node]]]] = []      # per sheet: (top, height, items) of each row
    page: list[tuple[float, float, list[Node]]] = []
    y = ry1
    sheet = [0]                                                  # the sheet being filled (0: the first)

    def room(top: float, h: float) -> float:
        k = keep if (sheet[0] == 0 or later is None) else later
        if k is not None and top - h < k[3] + 1e-9:
            # the room left of the title block, never past the region's own edge (a set's sheet
            # flows its drawings left of the tables' column: R01's hodograph ran on under the notes)
            return min(k[0], rx1) - rx0
        return rx1 - rx0

    def width(items: list[Node]) -> float:
        # a leaf's width read in place (a set's search asks ~10⁵ rows of a dozen plans a sheet)
        return sum(t.w if t.__class__ is Leaf else extent(t)[0] for t in items) + gap * (len(items) - 1)

    def _packed(items: list[Node], top: float) -> float:
        """``ragged``: the room items packed from the left need — their width where each item that
        reaches below the title block's top ends left of it, else more than any sheet has (the
        widths summed as ``width`` sums them: the same sum to the bit)."""
        k = keep if (sheet[0] == 0 or later is None) else later
        at = rx0
        if k is None:
            return width(items)
        ws = []
        low, right = k[3] + 1e-9, min(k[0], rx1) + 1e-9
        for t in items:
            w, h = (t.w, t.h) if t.__class__ is Leaf else extent(t)
            ws.append(w)
            at += w
            if top - h < low and at > right:
                return math.inf
            at += gap
        return sum(ws) + gap * (len(items) - 1)

    if ragged:
        def over(items: list[Node], top: float, h: float) -> bool:
            return _packed(items, top) > rx1 - rx0 + 1e-9
    else:
        def over(items: list[Node], top: float, h: float) -> bool:
            return width(items) > room(top, h) + 1e-9

    def spans_of(items: list[Node], top: float, h: float) -> list[tuple[float, float]]:
        """Each item's span across: the row's spare width shared out, or (``ragged``, where that
        would push an item reaching below the title block's top over it) packed from the left."""
        sizes = [extent(t)[0] for t in items]
        if not ragged:
            return _shares(sizes, room(top, h), gap)
        k = keep if (sheet[0] == 0 or later is None) else later
        for spans in (_shares(sizes, rx1 - rx0, gap), _shares(sizes, rx1 - rx0, gap, flush=True)):
            if k is None or all(not (top - extent(t)[1] < k[3] + 1e-9 and rx0 + at + w > min(k[0], rx1) + 1e-9)
                                for t, (at, w) in zip(items, spans)):
                return spans
        out, at = [], 0.0
        for w in sizes:
            out.append((at, w))
            at += w + gap
        return out

    def _run(queue: list[Node], top: float) -> tuple[list[Node], float]:
        """The items from the first that stand side by side in the row at ``top`` (the first
        always), and the row's height."""
        taken: list[Node] = []
        height = 0.0
        for item in queue:
            w, h = extent(item)
            if taken and over(taken + [item], top, max(height, h)):
                break
            taken.append(item)
            height = max(height, h)
        return taken, height

    def _ragged_run(queue: list[Node], top: float) -> tuple[list[Node], float]:
        """``_run`` with ``ragged``'s ``over`` judged item by item as ``_packed`` judges a whole
        run — the run packed so far kept (its left edge ``at`` summed as ``_packed`` sums it), each
        next item checked alone against the title block and the run's width summed anew: the same
        runs as ``_run``, without packing every run again from its first item."""
        k = keep if (sheet[0] == 0 or later is None) else later
        low, right = (k[3] + 1e-9, min(k[0], rx1) + 1e-9) if k is not None else (0.0, 0.0)
        across = rx1 - rx0 + 1e-9
        taken: list[Node] = []
        ws: list[float] = []
        height, at, blocked = 0.0, rx0, False
        for item in queue:
            w, h = (item.w, item.h) if item.__class__ is Leaf else extent(item)
            at_ = at + w
            tall = k is not None and top - h < low and at_ > right
            if taken and (blocked or tall or sum(ws + [w]) + gap * len(ws) > across):
                break
            blocked = blocked or tall
            taken.append(item)
            ws.append(w)
            at = at_ + gap
            height = max(height, h)
        return taken, height

    def box_of(item: Node, x0: float, w: float, top: float, h: float) -> Box:
        """The item's box in its row: the row's height, or (``ragged``) its own where the row's
        would take it into the title block."""
        k = keep if (sheet[0] == 0 or later is None) else later
        if ragged and k is not None and top - h < k[3] + 1e-9 and x0 + w > k[0] + 1e-9:
            h = extent(item)[1]
        return (x0, top - h, x0 + w, top)

    for row in rows:
        queue = list(row)
        while isinstance(row, Shelf) and 1 < len(queue) <= SHELF_MOST:
            used, top = _shelf_lines(queue, y, ry0, gap, over)
            if used:
                page.extend(used)
                y = top
                queue = queue[sum(_held(t) for u in used for t in u[2]):]
            if not queue:
                break
            if not page:                       # alone on an empty sheet and still too large
                return None
            pages.append(page)
            page, y = [], ry1
            sheet[0] += 1
        while queue:
            taken, height = (_ragged_run if ragged else _run)(queue, y)
            if over(taken, y, height) or y - height < ry0 - 1e-9:
                fit, low = _prefix(taken, y, ry0, room, width, over if ragged else None) if page else ([], 0.0)
                if fit:                        # the first items fit below: the sheet is filled first
                    page.append((y, low, fit))
                    y -= low + gap
                    queue = queue[len(fit):]
                    continue
                if not page:                   # alone on an empty sheet and still too large
                    return None
                pages.append(page)
                page, y = [], ry1
                sheet[0] += 1
                continue
            page.append((y, height, taken))
            y -= height + gap
            queue = queue[len(taken):]
            if all(isinstance(q, Leaf) and not q.name and q.record is None for q in queue):
                queue = []                     # a grid's padding cells do not start a row of their own
    if page:
        pages.append(page)
    if lines:
        return pages
    out = []
    for n, rows_ in enumerate(pages):
        sheet[0] = n
        spare = (rows_[-1][0] - rows_[-1][1]) - ry0
        extra = spare / len(rows_) if rows_ else 0.0
        shifted = [(top - extra * (k + 0.5), h, items) for k, (top, h, items) in enumerate(rows_)]
        if any(over(items, top, h) for top, h, items in shifted):
            shifted = rows_                    # spreading would push a row into the title block
        placed_ = []
        for top, h, items in shifted:
            spans = spans_of(items, top, h)
            for item, (at, w) in zip(items, spans):
                placed_.extend(arrange(item, box_of(item, rx0 + at, w, top, h)))
        out.append(placed_)
    return out
