"""The gear sheet's A2/A3 set (``--format A2``/``A3``): the drawings, the tables and the notes in the
A1 sheet's reading order — the meshing, the task data (review 10, mark 2), the λ diagrams, Tables 1 and 2 and the pair's notes, the
planetary pictures, Table 3 and the train's notes — cut into consecutive sheets, each composed in zones
as the A1 sheet is: its drawings on the left (or across the top), its tables and notes in a column by
the title block (or in a row under the drawings). The fewest sheets win; every sheet holds a drawing
or a table (never the notes alone), a table is never cut, the meshing — the main drawing — stands
first at the largest GOST 2.302 scale whose whole depth 2.25m is 40–60 mm and which fits the first
sheet over its title block. The later sheets carry form 2a (``Sheet.number``), kept clear of here."""
from __future__ import annotations

import math
from itertools import combinations

from graphplan.drawing.layout import GAP, Leaf, Placed, Row, Stack, arrange, extent
from graphplan.sheets.compose import field_of, keep_out
from graphplan.sheets.form import BLOCK_2A_H, BLOCK_W, Form

Box = tuple[float, float, float, float]

ORDER = ("meshing", "data", "sliding", "geometry", "quality", "notes", "planetary", "train", "train notes")   # reading order
NOTES = ("data", "notes", "train notes")      # the task data, the pair's notes, the train's
DRAWINGS = ("meshing", "sliding", "planetary")


def later_keep(f: Form) -> Box:
    """The title block form 2a (185×15 mm) of a set's later sheets with its clearance (``keep_out``)."""
    _, fy0, fx1, _ = f.frame_box
    return fx1 - BLOCK_W - GAP, fy0, fx1, fy0 + BLOCK_2A_H + GAP


def _fits(node, w: float, h: float) -> bool:
    nw, nh = _extent(node)
    return nw <= w + 1e-9 and nh <= h + 1e-9


_SIZES: dict[int, tuple[object, tuple[float, float]]] = {}


def _extent(node) -> tuple[float, float]:
    """``extent`` remembered per node (a set weighs the same groupings many times)."""
    got = _SIZES.get(id(node))
    if got is None or got[0] is not node:
        if len(_SIZES) > 4096:
            _SIZES.clear()
        got = _SIZES[id(node)] = (node, extent(node))
    return got[1]


def _placed(node, box: Box, top: set[str] = frozenset()) -> list[Placed]:
    """Each leaf of ``node`` centred in the box ``arrange`` gives it (a table or the notes at its box's
    top-left: read from their first line)."""
    out = []
    for leaf, b in arrange(node, box):
        if leaf.record is None:
            continue
        r = leaf.record.bounds()
        if leaf.name in top:
            dx, dy = b[0] - r[0], b[3] - r[3]
        else:
            dx, dy = (b[0] + b[2] - r[0] - r[2]) / 2, (b[1] + b[3] - r[1] - r[3]) / 2
        # its left edge and top on whole millimetres, as the A1 sheet's column stands (a raster of a
        # few pixels a millimetre then draws a table's subscripts as on the A1 sheet), inside the box
        fx, fy = math.ceil(r[0] + dx) - r[0], math.floor(r[3] + dy) - r[3]
        rec = leaf.record.moved(fx if r[2] + fx <= b[2] + 1e-9 else dx, fy if r[1] + fy >= b[1] - 1e-9 else dy)
        out.append(Placed(leaf.name, rec, b))
    return out


OWN = {"notes": ("geometry", "quality"), "train notes": ("train",)}    # the tables each part of the notes explains


def _foreign(last: Leaf, others: list[Leaf]) -> bool:
    """Whether the notes ``last``, set beside the column of ``others`` at its top, would stand by a table
    they do not explain (stop 54: GEARS_OWN53's A2 sheet 2 put the train's notes at the top right, beside
    Tables 1 and 2 and read before Table 3 at the foot of the column)."""
    own = OWN.get(last.name)
    return own is not None and any(t.name not in own and t.name not in NOTES + DRAWINGS for t in others)


def _at_foot(notes: Leaf, height: float):
    """The notes at the foot of a column ``height`` tall (a blank over them), beside the foot of the
    column of tables left of them — by the table they explain, its last."""
    blank = height - notes.h - GAP
    return Stack([Leaf("blank", w=notes.w, h=blank), notes], flush=True) if blank > 0 else notes


def _groupings(items: list[Leaf]) -> list:
    """The ways a sheet's drawings (or its tables) stand together: side by side, one under another,
    and (three or more) the first over the others side by side, or in two columns — the first i one
    under another, the rest beside them — where the second column's head is not notes beside tables
    they do not explain (stop 54: only the last beside the others was tried, so Table 1 could not stand
    beside Table 2 with the pair's notes under it — the lead's A3 set sent those notes to the planetary
    sheet —, and GEARS_OWN53's A2 sheet 2 put the train's notes at the top right, by Tables 1 and 2,
    Table 3 at the foot of the column)."""
    if not items:
        return []
    if len(items) == 1:
        return [items[0]]
    out = [Row(list(items)), Stack(list(items))]
    if len(items) == 2 and items[1].name in OWN and items[0].name in OWN[items[1].name]:
        # a table and the notes that explain it one under another: kept together, the spare room round
        # them (review 54: GEARS53/54's A3 last sheet stood Table 3 at its top, its notes 80 mm lower)
        out[1] = Stack([Stack(list(items), flush=True)])
    if len(items) >= 3:
        out.append(Stack([items[0], Row(list(items[1:]))]))
        for i in range(1, len(items)):    # two columns: the first i, then the rest
            left, right = items[:i], items[i:]
            first = left[0] if i == 1 else Stack(list(left))
            if len(right) == 1 and right[0].name in OWN and left[-1].name in OWN[right[0].name]:
                out.append(Row([first, _at_foot(right[0], _extent(first)[1])]))   # by its table, at the foot
            elif not _foreign(right[0], left):
                out.append(Row([first, right[0] if len(right) == 1 else Stack(list(right))]))
    return out


NOTE_WIDTHS = (130.0, 150.0, 240.0, 300.0, 380.0)   # mm: the notes wrapped to another width where that fits


def page(leaves: list[Leaf], f: Form, first: bool, notes=None):
    """One sheet of the set in zones: its drawings on the left and its tables and notes in a column by
    the title block, or the drawings across the top and the tables and notes in a row under them; the
    spare room shared out (the arrangement whose least spare is largest). None when no arrangement
    fits the field (the title block kept clear of: form 1 on the first sheet, form 2a on the later
    ones). ``notes(name, width)``: the notes ``name`` (of ``NOTES``) wrapped to another width, tried
    where they are on the sheet.
    Returns a function that places them (a set weighs many runs of its leaves and places one)."""
    tried = [_page(leaves, f, first)]
    if notes is not None and any(t.name in NOTES for t in leaves):
        tried += [_page([notes(t.name, w) if t.name in NOTES else t for t in leaves], f, first) for w in NOTE_WIDTHS]
    tried = [t for t in tried if t is not None]
    return max(tried, key=lambda t: t[0])[1] if tried else None     # (placed when the set is chosen)


def _cached(notes):
    """``notes(name, width)`` remembered per name and width."""
    if notes is None:
        return None
    seen: dict[tuple[str, float], Leaf] = {}
    return lambda n, w: seen[(n, w)] if (n, w) in seen else seen.setdefault((n, w), notes(n, w))


def _page(leaves: list[Leaf], f: Form, first: bool):
    x0, y0, x1, y1 = field_of(f)
    keep = keep_out(f) if first else later_keep(f)
    drawings = [t for t in leaves if t.name in DRAWINGS]
    side = [t for t in leaves if t.name not in DRAWINGS]
    texts = {t.name for t in side}
    best: tuple[float, list[Placed]] | None = None

    def take(score: float, placed) -> None:          # placed: a thunk, called for the best only
        nonlocal best
        if best is None or score > best[0] + 1e-9:
            best = (score, placed)

    low = keep[3]                       # the foot of anything that reaches over the title block
    lefts = []                          # the drawings, and the first tables under them, with the rest
    for k in range(len(side) + (1 if drawings else 0)):
        under, rest = side[:k], side[k:]
        if k and any(t.name not in NOTES for t in rest):
            continue                    # (Table 1 low on the left, Table 2 high on the right: out of order)
        for dg in _groupings(drawings) or [None]:
            for ug in _groupings(under) or [None]:
                node = dg if ug is None else (ug if dg is None else Stack([dg, ug]))
                lefts += [(node, c) for c in _groupings(rest) or [None]]
    tabs = [t for t in side if t.name not in NOTES]
    tail = side[len(tabs):]
    if len(drawings) == 1 and tabs and tail and side[:len(tabs)] == tabs and all(t.name in NOTES for t in tail):
        # the drawing and its tables side by side, the notes under them (review 54: the 11/53 A3 set's λ
        # diagrams, Tables 1 and 2 in a column and the pair's notes did not share a sheet one under
        # another; the notes went under the planetary pictures, a sheet away from the tables they explain)
        lefts += [(Row([drawings[0], tg]), c) for tg in _groupings(tabs) for c in _groupings(tail)]
    if len(drawings) >= 2 and side:       # the first drawing across the top, the others with the tables and
        top, under = drawings[0], Row(list(drawings[1:]) + side)      # notes beside them under it, left of
        tw, th = _extent(top)                                         # the title block (stop 47: 11/29's
        uw, uh = _extent(under)                                       # A2 set left its first sheet 45 %
        spare = y1 - y0 - th - GAP - uh                               # empty, the λ diagrams on the next)
        split = y1 - th - spare / 2                                   # the top's foot
        if tw <= x1 - x0 + 1e-9 and uw <= keep[0] - x0 + 1e-9 and spare >= -1e-9 and \
                (split >= low - 1e-9 or tw <= keep[0] - x0 + 1e-9):
            take(min(spare / 2, x1 - x0 - tw, keep[0] - x0 - uw),
                 lambda top=top, under=under, a=(x0, split, x1, y1), b=(x0, y0, keep[0], split - GAP):
                 _placed(top, a, texts) + _placed(under, b, texts))
    for d, c in lefts:
        dw, dh = _extent(d) if d is not None else (0.0, 0.0)
        cw, ch = _extent(c) if c is not None else (0.0, 0.0)
        if d is None or c is None:              # one zone alone: the field over (or beside) the block
            node, (w, h) = (d, (dw, dh)) if c is None else (c, (cw, ch))
            for box in ((x0, low, x1, y1), (x0, y0, keep[0], y1)):
                if _fits(node, box[2] - box[0], box[3] - box[1]):
                    take(min(box[2] - box[0] - w, box[3] - box[1] - h),
                         lambda node=node, box=box: _placed(node, box, texts))
                    break
            continue
        # the column: the tables and notes on the right, over the title block; the drawings left
        col = (x1 - cw, low, x1, y1)
        if ch <= y1 - low + 1e-9:
            for dbox in ((x0, y0, x1 - cw - GAP, y1), (x0, low, x1 - cw - GAP, y1)):
                if dbox[2] > keep[0] + 1e-9 and dbox[1] < low - 1e-9:
                    continue
                if _fits(d, dbox[2] - dbox[0], dbox[3] - dbox[1]):
                    take(min(dbox[2] - dbox[0] - dw, dbox[3] - dbox[1] - dh),
                         lambda d=d, dbox=dbox, c=c, col=col: _placed(d, dbox, texts) + _placed(c, col, texts))
                    break
        # the row: the drawings across the top, the tables and notes under them
        if dw <= x1 - x0 + 1e-9:
            for foot, right in ((y0, keep[0]), (low, x1)):
                spare = y1 - foot - dh - GAP - ch
                if cw > right - x0 + 1e-9 or spare < -1e-9:
                    continue
                split = y1 - dh - spare / 2                # the drawings' zone over the row's
                if split < low - 1e-9 <= y1 - dh and low - GAP - foot >= ch - 1e-9:
                    split = low     # the drawings risen over the title block, the row beside it under them
                dright = x1 if split >= low - 1e-9 else keep[0]     # (stop 52: GEARS52's A3 meshing, 212 mm
                if dw > dright - x0 + 1e-9:                         # tall, left its task data to the next
                    continue                                        # sheet: split midway fell 3 mm below it)
                take(min(y1 - dh - split, split - GAP - foot - ch, dright - x0 - dw, right - x0 - cw),
                     lambda d=d, c=c, a=(x0, split, dright, y1), b=(x0, foot, right, split - GAP):
                     _placed(d, a, texts) + _placed(c, b, texts))
                break
    return best


def set_pages(leaves: list[Leaf], f: Form, notes=None,
              larger: dict[str, Leaf] | list[dict[str, Leaf]] | None = None) -> list[list[Placed]] | None:
    """The set's sheets: ``leaves`` (in ``ORDER``) cut into consecutive runs, each composed by
    ``page``; the fewest sheets, then the first sheets the fullest (the reading order kept), no sheet
    with the notes alone. None when one of them does not fit a whole sheet. ``notes``: as ``page``'s.
    ``larger``: leaves drawn larger (the tables as the other sheets draw theirs, the λ diagrams with a
    longer unit) — or several such, the largest first (the tables' 8,4-mm rows, then 7-mm rows with
    the same 3,5-mm letters) —, taken on each sheet of the chosen cut that still holds them: all of
    one, else its tables, for each in turn, else the drawings alone."""
    leaves = sorted(leaves, key=lambda t: ORDER.index(t.name))
    notes = _cached(notes)
    n = len(leaves)
    memo: dict[tuple[int, int, bool], object] = {}

    def one(i: int, j: int):
        key = (i, j, i == 0)
        if key not in memo:
            run = leaves[i:j]
            memo[key] = None if all(t.name in NOTES for t in run) else page(run, f, i == 0, notes)
        return memo[key]

    for k in range(1, n + 1):                     # k sheets: the cuts between them
        found = []
        for cuts in combinations(range(1, n), k - 1):
            bounds = (0, *cuts, n)
            pages = [one(a, b) for a, b in zip(bounds, bounds[1:])]
            if all(p is not None for p in pages):
                found.append(([-(b - a) for a, b in zip(bounds, bounds[1:])], pages, bounds))
        if found:
            _, pages, bounds = min(found, key=lambda t: t[0])
            out = []
            options = [x for x in (larger if isinstance(larger, list) else [larger]) if x]
            for (a, b), place in zip(zip(bounds, bounds[1:]), pages):
                big = None
                run = leaves[a:b]
                tries = []                # all larger, else the tables larger (each size in turn), else the
                for opt in options:       # drawings: the first this sheet holds
                    names = [t.name for t in run if t.name in opt]
                    tries += [(opt, names), (opt, [n for n in names if n not in DRAWINGS])]
                if options:
                    tries.append((options[0], [t.name for t in run if t.name in options[0] and t.name in DRAWINGS]))
                for opt, some in tries:
                    if some and big is None:
                        big = page([opt[t.name] if t.name in some else t for t in run], f, a == 0, notes)
                out.append((big or place)())
            return out
    return None
