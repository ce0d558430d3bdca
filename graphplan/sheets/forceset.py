"""A force set's drawings laid over its sheets (reviews 6 #2 and 7 #1: eight A3 sheets, each 56–84 %
empty — one tall scheme alone on a sheet, a group with its plan alone on the next, the tables split
over two sheets with room left on both).

The drawings are set down in reading order — the scheme, each group beside its own force plan, the
acceleration plan, the lever, the charts, the hodographs (one grid), the tables and the notes — each
at the highest free place of the sheet that holds it (a skyline: the room under the drawings set so
far), the further left the better: a drawing goes beside the last one where the width holds it, or
under it, or starts a column to its right (a tall scheme with the groups in a column beside it, as
the A1 sheet draws them). A drawing never goes back to an earlier sheet nor above-left of the one
before it — except that a sheet the next drawing would leave mostly empty (a tall scheme alone: 80 %
of its 20 mm cells blank, review 7 #1) takes later drawings that read on their own first, the
acceleration plan, the lever, the charts over the turn: those that fit and leave it fullest.
Drawings stand ``SPACE`` apart (review 7 #18), or the layout's ``GAP`` where only that keeps a sheet (sheets/forces.py chooses). The tables, each whole, go together in one to three columns under the drawings at the
sheet's right, the notes right over the title block; a new sheet only where they do not fit. Each
sheet's spare room is then shared out between its drawings (their corners' distances from the field's
top-left corner stretched alike: boxes that did not meet still do not)."""
from __future__ import annotations

import copy
from collections.abc import Sequence
from dataclasses import dataclass, replace

from graphplan.drawing.layout import GAP, Grid, Leaf, Node, Row, Stack, arrange, extent, split

Box = tuple[float, float, float, float]
# mm between two drawings (review 7 #18: group II(2-3)'s "R₀₃" stood 7 mm before group I(0-1)'s "A"
# across a 5 mm gap and read as one label): a label nearer its own drawing than another's lettering
SPACE = 10.0
FILL_SHARE = 0.5      # a sheet whose drawings' cells take less of its field than this is mostly empty


@dataclass
class Spot:
    """A unit set down on a sheet: its node, its top-left corner (x from the field's left, d down
    from its top, mm), its size; ``fixed``: kept where it is when the sheet's spare room is shared
    out (the tables' column and the notes by the title block)."""
    node: Node
    x: float
    d: float
    w: float
    h: float
    fixed: bool = False
    alts: tuple = ()        # the unit's alternatives it was chosen from (``pack``: set again on another sheet)


class Skyline:
    """The room left on one sheet: for each stretch of the field's width, the depth from its top
    down to which drawings (with their gap) are set; the title block's corner kept clear."""

    def __init__(self, width: float, height: float, keep_x: float, keep_d: float, gap: float = GAP):
        self.W, self.H, self.kx, self.kd, self.gap = width, height, keep_x, keep_d, gap
        self.segs: list[tuple[float, float, float]] = [(0.0, width + gap, 0.0)]    # (x0, x1, depth)
        self.spots: list[Spot] = []
        self.left = 0.0          # nothing set left of this (the tables' column right of the drawings)
        self.top = 0.0           # … nor above this (the tables under the drawings)

    def __deepcopy__(self, memo) -> Skyline:
        """A trial copy: its own stretches and spots, the spots' drawings shared (a set's search
        only reads them; ``copy.deepcopy`` copied every record of them, some 20 % of the shaper's
        A3 force set)."""
        new = Skyline.__new__(Skyline)
        new.__dict__.update(self.__dict__)
        new.segs = list(self.segs)
        new.spots = [Spot(s.node, s.x, s.d, s.w, s.h, s.fixed, s.alts) for s in self.spots]
        return new

    def depth(self, x: float, w: float) -> float:
        """How deep the drawings already reach over [x, x + w)."""
        return max((d for a, b, d in self.segs if a < x + w - 1e-9 and b > x + 1e-9), default=0.0)

    def floor(self, x: float, w: float) -> float:
        """How deep a drawing over [x, x + w) may reach: the field's foot, or the title block's top."""
        return self.kd if x + w > self.kx + 1e-9 else self.H

    def ordered(self, x: float, d: float) -> bool:
        """Reading order: a drawing not above the last one's top unless wholly to its right."""
        if not self.spots:
            return True
        p = self.spots[-1]
        return d >= p.d - 1e-9 or x >= p.x + p.w + self.gap - 1e-9

    def after(self, x: float, d: float, spot: Spot | None) -> bool:
        """Read after ``spot``: wholly to its right or wholly under it (a group's drawing after the
        group before it — the outer group first, the crank's last, seed 000 §2.5)."""
        return (spot is None or x >= spot.x + spot.w + self.gap - 1e-9
                or d >= spot.d + spot.h + self.gap - 1e-9)

    def where(self, w: float, h: float, right: bool = False, min_x: float = 0.0,
              follows: Spot | None = None) -> tuple[float, float] | None:
        """The highest place for a w × h drawing (then the leftmost, or ``right``: the rightmost),
        not left of ``min_x``, read after ``follows`` (``after``)."""
        at = self.places(w, h, right, min_x, follows)
        return at[0] if at else None

    def places(self, w: float, h: float, right: bool = False, min_x: float = 0.0,
               follows: Spot | None = None) -> list[tuple[float, float]]:
        """Every place for a w × h drawing (``where``'s), the highest first."""
        if w > self.W + 1e-9:
            return []
        min_x = max(min_x, self.left)
        xs = {a for a, _, _ in self.segs} | {b - self.gap - w for _, b, _ in self.segs} | {self.W - w, min_x}
        found = {}
        for x in xs:
            if x < min_x - 1e-9 or x + w > self.W + 1e-9:
                continue
            x = max(0.0, x)
            d = max(self.depth(x, w), self.top)
            if not self.after(x, d, follows):
                # lowered to read after ``follows`` (LINK52's group II(4-5) had a place under the
                # scheme 6 mm too high for that, and went right of it over a 200 × 400 mm blank)
                d = max(d, follows.d + follows.h + self.gap)
            if d + h > self.floor(x, w) + 1e-9 or not self.ordered(x, d) or not self.after(x, d, follows):
                continue
            found[(round(d, 6), -x if right else x)] = (x, d)
        return [found[k] for k in sorted(found)]

    def put(self, spot: Spot) -> None:
        """Take the spot's room (its width and height with the gap after it)."""
        a, b, depth = spot.x, spot.x + spot.w + self.gap, spot.d + spot.h + self.gap
        out = []
        for x0, x1, d in self.segs:
            if x1 <= a + 1e-9 or x0 >= b - 1e-9:
                out.append((x0, x1, d))
                continue
            if x0 < a:
                out.append((x0, a, d))
            if x1 > b:
                out.append((b, x1, d))
        out.append((a, b, max(depth, self.depth(a, b - a))))
        self.segs = sorted(out)
        self.spots.append(spot)


def pack(units: Sequence[Sequence[Node]], tables: Sequence[Leaf], notes: Leaf | None, region: Box,
         first_keep: Box, later_keep: Box, gap: float = GAP) -> list[list[Spot]] | None:
    """The set's sheets: each unit (its alternatives — the hodographs' grid at several widths — the
    one set highest wins) at the highest free place of the current sheet, else on a new one; then the
    tables in a block of one to three columns and the notes over the title block, together on one
    sheet where they fit. None where a drawing is larger than a sheet."""
    rx0, ry0, rx1, ry1 = region
    W, H = rx1 - rx0, ry1 - ry0

    def sheet(n: int) -> Skyline:
        k = first_keep if n == 0 else later_keep
        return Skyline(W, H, k[0] - rx0, ry1 - k[3], gap)

    pages: list[Skyline] = [sheet(0)]

    def follows(alts: Sequence[Node], page: Skyline) -> Spot | None:
        """The group's drawing a group's unit is read after on the page (``Skyline.after``)."""
        return next((s for s in reversed(page.spots) if _is_group(s.node)), None) if _is_group(alts[0]) else None

    def place(alts: Sequence[Node], page: Skyline) -> Spot | None:
        """The alternative set highest on the page (then the one ending higher, then the first); a
        group's drawing read after the group before it on the page (``Skyline.after``)."""
        best = None
        for node in alts:
            w, h = extent(node)
            at = page.where(w, h, follows=follows(alts, page))
            if at is not None and (best is None or (round(at[1], 6), round(at[1] + h, 6)) < best[0]):
                best = ((round(at[1], 6), round(at[1] + h, 6)), Spot(node, at[0], at[1], w, h, alts=tuple(alts)))
        return None if best is None else best[1]

    def other_places(alts: Sequence[Node], page: Skyline, taken: Spot) -> list[Spot]:
        """A group's other places on the page than the highest (``GROUP_TRIES`` of them, one an x):
        the outer group set highest at the right left the crank's group no place after it."""
        out, xs = [], {round(taken.x, 3)}
        for node in alts:
            w, h = extent(node)
            for x, d in page.places(w, h, follows=follows(alts, page)):
                if round(x, 3) not in xs:
                    xs.add(round(x, 3))
                    out.append(Spot(node, x, d, w, h))
        return sorted(out, key=lambda s: (round(s.d, 6), s.x))[:GROUP_TRIES]

    def grids(children: list, page: Skyline) -> list[Grid]:
        return [g for g in (Grid(children, c, page.gap) for c in range(1, len(children) + 1))
                if extent(g)[0] <= page.W + 1e-9]

    def tables_on(pages: list[Skyline]) -> bool:
        """The tables whole on one sheet: the last, else a new one; only where no sheet holds them
        all, table after table over the sheets; the notes after them. False where a table is
        larger than a sheet."""
        if _put_tables(pages[-1], tables, notes):
            return True
        fresh = sheet(len(pages))
        if pages[-1].spots and _put_tables(fresh, tables, notes):
            pages[-1:] = joined(pages[-1], len(pages) - 1, fresh)
            return True
        rest = list(tables)
        while rest:
            n = _put_tables(pages[-1], rest, None, partial=True)
            if n == 0 and not pages[-1].spots:
                return False
            rest = rest[n:]
            if rest:
                pages.append(sheet(len(pages)))
        if notes is not None and not _put_notes(pages[-1], notes):
            # not a sheet for the notes alone (LINK47's A3 set: sheet 6 of 6 held twelve lines by
            # its title block): on the latest sheet before that has room for them
            if any(_put_notes(page, notes) for page in reversed(pages[:-1])):
                return True
            pages.append(sheet(len(pages)))
            return _put_notes(pages[-1], notes)
        return True

    def joined(last: Skyline, n: int, fresh: Skyline) -> list[Skyline]:
        """The tables' own new sheet (``fresh``, sheet ``n + 1``) with the last drawings of sheet ``n``
        (``last``) set before them in reading order — the fewest that the tables still fit beside,
        where sheet ``n`` keeps two drawings at least and the emptier of the two sheets is no emptier
        than ``TABLES_ALONE`` of what it was: no sheet of tables alone (review 61 #5; LINK62's A2 sheet 3
        held Tables 1–7 alone, 279 × 194 mm bare, while its five hodographs stood 40 mm small on sheet
        2). The room left on sheet ``n`` is then grown into by its drawings (sheets/forces.py)."""
        least = min(share(last), share(fresh))
        drawn = [s for s in last.spots if not s.fixed]
        for k in range(1, len(drawn) - 1):
            split_grid = isinstance(drawn[-k - 1].node, Grid) and isinstance(drawn[-k].node, Grid)
            if split_grid or not all(s.alts for s in drawn[-k:]):
                break          # (the hodographs' grid split in two parts by its own rule: kept on one sheet)
            kept = sheet(n)
            for s in drawn[:-k]:
                kept.put(Spot(s.node, s.x, s.d, s.w, s.h, s.fixed, s.alts))
            new = sheet(n + 1)
            for s in drawn[-k:]:
                spot = place(s.alts, new)
                if spot is None:
                    return [last, fresh]
                new.put(spot)
            if not _put_tables(new, tables, notes):
                return [last, fresh]
            if min(share(kept), share(new)) >= TABLES_ALONE * least - 1e-9:
                return [kept, new]
        return [last, fresh]

    def run(queue: list, pages: list[Skyline]) -> list[Skyline] | None:
        """The rest of the units, then the tables, set down from the last of ``pages``."""
        while queue:
            alts = queue.pop(0)
            spot = place(alts, pages[-1])
            if spot is None and isinstance(alts[0], Grid) and pages[-1].spots:
                # the hodographs: as many as the sheet holds here (two at least, two left at least),
                # the rest where they then fit — where that saves a sheet
                kids = alts[0].children
                for k in range(len(kids) - 2, 1, -1):
                    part = place(grids(kids[:k], pages[-1]), pages[-1])
                    if part is not None:
                        split_pages = copy.deepcopy(pages)
                        split_pages[-1].put(part)
                        split = run([grids(kids[k:], split_pages[-1])] + [list(q) for q in queue], split_pages)
                        whole = run([alts] + [list(q) for q in queue], copy.deepcopy(pages) + [sheet(len(pages))])
                        if whole is None or (split is not None and len(split) < len(whole)):
                            return split
                        return whole
            if spot is None and pages[-1].spots and share(pages[-1]) < FILL_SHARE:
                # the sheet would be left mostly empty (the slotter's and the sieve's scheme alone on
                # sheet 1, 80 % of its cells blank): later drawings that read on their own — the
                # acceleration plan the inertia loads come from, the Zhukovsky lever, the charts over
                # the turn — set here first
                # (of the later drawings that read on their own, those that leave the sheet fullest)
                moved = _brought_forward(queue, pages[-1], place)
                if moved:
                    for j in reversed(moved):
                        queue.pop(j)
                    spot = place(alts, pages[-1])
            if spot is not None and _is_group(alts[0]) and any(_is_group(q[0]) for q in queue):
                # a group with another after it: of its places, the one that needs fewest sheets
                # (the first of those), the groups kept in the analysis' order
                trials = []
                for k, s_ in enumerate([spot] + other_places(alts, pages[-1], spot)):
                    tried = copy.deepcopy(pages)
                    tried[-1].put(s_)
                    done = run([list(q) for q in queue], tried)
                    if done is not None:
                        trials.append((len(done), k, done))
                    if k == 0 and done is not None and not _later_group_moved(done, len(pages)):
                        break            # the highest place keeps the next group on this sheet
                if trials:
                    return min(trials, key=lambda t: t[:2])[2]
                return None
            if spot is None:
                if not pages[-1].spots:
                    return None                   # larger than an empty sheet
                pages.append(sheet(len(pages)))
                spot = place(alts, pages[-1])
                if spot is None:
                    return None
            pages[-1].put(spot)
        if (tables or notes is not None) and not tables_on(pages):
            return None
        return pages

    out = run([list(alts) for alts in units], pages)
    return None if out is None else [p.spots for p in out]


GROUP_TRIES = 3    # a group's places tried besides the highest (``pack``)
# a sheet of tables alone takes the last drawings of the sheet before where the emptier of the two
# sheets keeps this much of the share of its field it had (``pack``'s ``joined``): LINK62's A2 set,
# 0.46 (the tables alone) and 0.61, became 0.62 and 0.41 with the hodographs by the tables
TABLES_ALONE = 0.8


def _later_group_moved(pages: list[Skyline], n: int) -> bool:
    """Whether a set packed from ``n`` sheets set a group on a later sheet than the ``n``-th."""
    return any(_is_group(s.node) for p in pages[n:] for s in p.spots)


def _is_group(node: Node) -> bool:
    """Whether a unit holds a group's drawing (a leaf "group II(2-3)" as drawn, "groups 0" as
    planned), beside its force plan."""
    if isinstance(node, Leaf):
        return node.name.startswith(("group ", "groups "))
    return any(_is_group(c) for c in getattr(node, "children", ()))


def share(page: Skyline) -> float:
    """The share of the sheet's field its drawings' cells take."""
    return sum(s.w * s.h for s in page.spots) / (page.W * page.H)


def _brought_forward(queue: list, page: Skyline, place) -> list[int]:
    """The later units (their places in ``queue``) set on a mostly empty ``page`` first, in their
    reading order: the first of the acceleration plan and the lever that fits — or, where the page
    holds one drawing that reads on its own (the scheme, the acceleration plan, the lever: ``lone``),
    of the drawings that read on their own, the charts over the turn too (``movable``), those that
    leave the page fullest, the fewest then the earliest of those. The slotter's A3 sheet 1 took the
    first that fit, its lever, and held it alone beside the tall scheme, 69 % empty by the reviews'
    20 mm cells, where the M_b and resistance charts one under the other take the room. A sheet
    that holds a group, or two drawings already, keeps the reading order but for that one drawing
    (the shaper's A3 sheet 1 held the scheme and the acceleration plan: the M_b chart beside them
    read before the groups). The page takes them; [] where none fits."""
    from itertools import combinations
    many = lone(page)
    movables = [j for j, later in enumerate(queue) if movable(later, charts=many)][:MOVABLE_TRIES]
    best: tuple | None = None
    for n in range(1, (len(movables) if many else 1) + 1):
        for js in combinations(movables, n):
            trial = copy.deepcopy(page)
            for j in js:
                spot = place(queue[j], trial)
                if spot is None:
                    break
                trial.put(spot)
            else:
                key = (round(share(trial), 6) if many else 0.0, -n, [-j for j in js])
                if best is None or key > best[0]:
                    best = (key, js, trial)
    if best is None:
        return []
    page.segs, page.spots = best[2].segs, best[2].spots
    return list(best[1])


def lone(page: Skyline) -> bool:
    """Whether the page holds one drawing, one that reads on its own: the scheme ("scheme 0" as
    planned, "mechanism" as drawn), the acceleration plan, the lever."""
    nodes = [s.node for s in page.spots]
    return len(nodes) == 1 and isinstance(nodes[0], Leaf) and (
        nodes[0].name.startswith(("scheme", "mechanism")) or movable(nodes[0:1]))


MOVABLE_TRIES = 6      # the later drawings that read on their own ``pack`` tries on a mostly empty sheet


def movable(alts: Sequence[Node], charts: bool = False) -> bool:
    """Whether a unit reads on its own, out of the reading order: the acceleration plan, the lever;
    ``charts``: a chart over the turn too (each of one drawing, named so by ``units_of``'s callers:
    "charts 1" as planned, "moment", "resistance", "reaction R05" as drawn)."""
    names = ("acceleration", "lever") + (("charts ", "moment", "resistance", "reaction") if charts else ())
    return len(alts) == 1 and isinstance(alts[0], Leaf) and alts[0].name.startswith(names)


def _put_notes(page: Skyline, notes: Leaf) -> bool:
    """The notes right over the title block where that is free, else at the highest free place."""
    x, d = page.W - notes.w, page.kd - notes.h
    if x >= -1e-9 and page.depth(x, notes.w) <= d + 1e-9 and page.ordered(x, d):
        page.put(Spot(notes, x, d, notes.w, notes.h, fixed=True))
        return True
    at = page.where(notes.w, notes.h, right=True)
    if at is None:
        return False
    page.put(Spot(notes, at[0], at[1], notes.w, notes.h, fixed=True))
    return True


def _put_tables(page: Skyline, tables: Sequence[Leaf], notes: Leaf | None, partial: bool = False):
    """The tables in reading order in columns, as a newspaper sets them: each under the one before
    where the sheet holds it there, else at the top of a new column to the right of the last; then
    the notes over the title block. Whether all (and the notes) fit — the page unchanged where not —
    or, ``partial``, how many tables fit (those taken)."""
    # the tables' column right of the sheet's drawings (LAYOUT.md: by the title block), else the
    # tables under every drawing (a row of hodographs over them): never beside a drawing's left
    drawn = [s for s in page.spots if not s.fixed]
    for left, top in ((max([s.x + s.w + page.gap for s in drawn] + [0.0]), 0.0),
                      (0.0, max([s.d + s.h + page.gap for s in drawn] + [0.0]))):
        page.left, page.top = left, top
        try:
            out = _tables_right(page, tables, notes, partial)
        finally:
            page.left = page.top = 0.0
        if out or not drawn:
            return out
    return out


def _tables_right(page: Skyline, tables: Sequence[Leaf], notes: Leaf | None, partial: bool):
    if partial:
        return _newspaper(page, tables, None, True, False)
    if _newspaper(page, tables, notes, False, notes is not None):
        return True
    for with_notes in (False, True):
        items = list(tables) + ([notes] if with_notes and notes is not None else [])
        for parts in range(1, min(4, len(items)) + 1):
            for right in (True, False):
                if _block(page, split(items, parts, page.gap), None if with_notes else notes, right):
                    return True
    return (_newspaper(page, tables, notes, False, False) or _rows(page, tables, notes, columns=True)
            or _rows(page, tables, notes))


def _next_in_column(placed: list[Spot], x: float, d: float, w: float, gap: float) -> bool:
    """Whether a table at (x, d), w wide, reads next after the tables ``placed`` as a newspaper's
    columns read (left to right, each from its top): under the last one, in its column (not
    reaching back left of it), or at the top of a new column wholly to the right of every one of
    them."""
    if not placed:
        return True
    last = placed[-1]
    under = d >= last.d + last.h + gap - 1e-9 and last.x - 1e-9 <= x < last.x + last.w - 1e-9
    return under or x >= max(s.x + s.w for s in placed) + gap - 1e-9


def _rows(page: Skyline, tables: Sequence[Leaf], notes: Leaf | None, columns: bool = False) -> bool:
    """The tables each at the highest free place in turn (side by side where the width holds two,
    as a row of text), the notes over the title block; whether they fit (taken then). ``columns``:
    each where it reads next as a newspaper's columns read (``_next_in_column``) — LINK48's A2
    sheet 3 set Table 5 under Table 1, left of Tables 2–4, and Tables 6 and 7 at the top right."""
    trial = copy.deepcopy(page)
    kd = trial.kd
    for keep_notes in ((True, False) if notes is not None else (False,)):
        trial = copy.deepcopy(page)
        if keep_notes:
            trial.kd = kd - notes.h - trial.gap
        mine: list[Spot] = []
        for t in tables:
            if columns:
                at = next((q for q in trial.places(t.w, t.h)
                           if _next_in_column(mine, q[0], q[1], t.w, trial.gap)), None)
            else:
                at = trial.where(t.w, t.h)
            if at is None:
                break
            mine.append(Spot(t, at[0], at[1], t.w, t.h, fixed=True))
            trial.put(Spot(t, at[0], at[1], t.w, t.h, fixed=True))
        else:
            trial.kd = kd
            if notes is None or _put_notes(trial, notes):
                page.segs, page.spots = trial.segs, trial.spots
                return True
    return False


def _block(page: Skyline, columns: list[list[Leaf]], notes: Leaf | None, right: bool) -> bool:
    """The tables in these columns side by side (each column's tables one under another, from its
    top) in one block as high on the sheet as it is free (at the right, or the left), the notes
    over the title block (or at the highest free place); whether they fit (taken then)."""
    columns = [c for c in columns if c]
    w = sum(max(t.w for t in c) for c in columns) + page.gap * (len(columns) - 1)
    h = max(sum(t.h for t in c) + page.gap * (len(c) - 1) for c in columns)
    at = page.where(w, h, right=right)
    if at is None:
        return False
    trial = copy.deepcopy(page)
    x = at[0]
    for c in columns:
        d = at[1]
        for t in c:
            trial.spots.append(Spot(t, x, d, t.w, t.h, fixed=True))
            d += t.h + trial.gap
        x += max(t.w for t in c) + trial.gap
    trial.spots, spots = trial.spots[:len(page.spots)], trial.spots[len(page.spots):]
    trial.put(Spot(Leaf("tables", w, h), at[0], at[1], w, h, fixed=True))
    trial.spots = trial.spots[:-1] + spots
    if notes is not None and not _put_notes(trial, notes):
        return False
    page.segs, page.spots = trial.segs, trial.spots
    return True


def _newspaper(page: Skyline, tables: Sequence[Leaf], notes: Leaf | None, partial: bool, keep_notes: bool):
    """``_put_tables`` with the notes' room over the title block kept free for them
    (``keep_notes``) or the notes set at the highest free place after the tables."""
    trial = copy.deepcopy(page)
    if keep_notes:
        trial.kd -= notes.h + trial.gap
    done = 0
    col_x = None            # the current column's left edge and right edge
    col_r = 0.0
    for t in tables:
        at = None
        if col_x is not None:
            last = trial.spots[-1]
            d = last.d + last.h + trial.gap
            if col_x + t.w <= trial.W + 1e-9 and trial.depth(col_x, t.w) <= d + 1e-9 \
                    and d + t.h <= trial.floor(col_x, t.w) + 1e-9:
                at = (col_x, d)
            else:
                at = trial.where(t.w, t.h, min_x=col_r + trial.gap)
        else:
            at = trial.where(t.w, t.h)
        if at is None:
            break
        if col_x is None or at[0] != col_x:
            col_x, col_r = at[0], at[0] + t.w
        col_r = max(col_r, at[0] + t.w)
        trial.put(Spot(t, at[0], at[1], t.w, t.h, fixed=True))
        done += 1
    if partial:
        if done:
            page.segs, page.spots = trial.segs, trial.spots
        return done
    trial.kd = page.kd
    if done < len(tables) or (notes is not None and not _put_notes(trial, notes)):
        return False
    page.segs, page.spots = trial.segs, trial.spots
    return True


def spread(spots: list[Spot], region: Box, keep: Box, gap: float = GAP) -> list[Spot]:
    """The sheet's spare room shared out: the loose drawings' corners moved away from the field's
    top-left corner by one factor across and one down, the largest that keeps every drawing in the
    field, clear of the title block and of the fixed ones (``x' = s·x``: two boxes apart by at least
    the gap stay so for any s ≥ 1)."""
    rx0, ry0, rx1, ry1 = region
    W, H = rx1 - rx0, ry1 - ry0
    kx, kd = keep[0] - rx0, ry1 - keep[3]
    fixed = [s for s in spots if s.fixed]
    loose = [s for s in spots if not s.fixed]
    if not loose:
        return _columns_spread(spots, W, kx, kd, gap)

    def ok(trial: list[Spot]) -> bool:
        for s in trial:
            if s.x < -1e-9 or s.x + s.w > W + 1e-9 or s.d + s.h > H + 1e-9:
                return False
            if s.x + s.w > kx + 1e-9 and s.d + s.h > kd + 1e-9:
                return False
            if any(_overlap(s, f, gap) for f in fixed):
                return False
        return True

    def stretched(sx: float, sy: float) -> list[Spot]:
        return [replace(s, x=s.x * sx, d=s.d * sy) for s in loose]

    def largest(make) -> float:
        lo, hi = 1.0, 4.0
        if not ok(make(lo)):
            return 1.0
        for _ in range(30):
            mid = (lo + hi) / 2
            lo, hi = (mid, hi) if ok(make(mid)) else (lo, mid)
        return lo

    sy = largest(lambda s: stretched(1.0, s))
    sx = largest(lambda s: stretched(s, sy))
    moved = stretched(sx, sy)
    # what the stretch leaves at the right and the foot, shared: half of it before the first drawings
    dx = (W - max(s.x + s.w for s in moved)) / 2
    dy = (H - max(s.d + s.h for s in moved)) / 2
    for ddx, ddy in ((dx, dy), (dx, 0.0), (0.0, dy)):
        trial = [replace(s, x=s.x + ddx, d=s.d + ddy) for s in moved]
        if ok(trial):
            moved = trial
            break
    at = iter(moved)
    out = [s if s.fixed else next(at) for s in spots]
    return _columns_spread(out, W, kx, kd, gap)


def _overlap(s: Spot, o: Spot, gap: float) -> bool:
    """Two spots closer than ``gap`` in both directions (their rectangles grown by the gap meet)."""
    return (s.x < o.x + o.w + gap - 1e-9 and o.x < s.x + s.w + gap - 1e-9
            and s.d < o.d + o.h + gap - 1e-9 and o.d < s.d + s.h + gap - 1e-9)


def _columns_spread(spots: list[Spot], W: float, kx: float, kd: float, gap: float) -> list[Spot]:
    """The tables' columns set evenly over the width the sheet leaves them, as a newspaper spaces
    its columns: each column's left moved from the block's left by one factor (``x' = x₀ + s·(x −
    x₀)``, the largest s that keeps every table in the field, clear of the title block, the notes
    and the drawings) — LINK52's A1 sheet 2 set its three columns of tables 10 mm apart at the
    left, a 270 × 150 mm blank between them and the notes."""
    tables = [s for s in spots if s.fixed and getattr(s.node, "name", "") != "notes"]
    if len({round(s.x, 6) for s in tables}) < 2:
        return spots
    others = [s for s in spots if s not in tables]
    x0 = min(s.x for s in tables)

    def ok(trial: list[Spot]) -> bool:
        for s in trial:
            if s.x + s.w > W + 1e-9 or (s.x + s.w > kx + 1e-9 and s.d + s.h > kd + 1e-9):
                return False
            if any(_overlap(s, o, gap) for o in others):
                return False
        return True

    def stretched(k: float) -> list[Spot]:
        return [replace(s, x=x0 + (s.x - x0) * k) for s in tables]

    lo, hi = 1.0, 4.0
    if not ok(stretched(lo)):
        return spots
    for _ in range(30):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if ok(stretched(mid)) else (lo, mid)
    moved = dict(zip(map(id, tables), stretched(lo)))
    return [moved.get(id(s), s) for s in spots]


def laid(spots: list[Spot], region: Box) -> list[tuple[Leaf, Box]]:
    """Each drawing of the sheet with its box in sheet mm (y up), in reading order: a unit's nodes
    arranged in its box (a table, the notes: its own box)."""
    rx0, ry0, rx1, ry1 = region
    out: list[tuple[Leaf, Box]] = []
    for s in spots:
        box = (rx0 + s.x, ry1 - s.d - s.h, rx0 + s.x + s.w, ry1 - s.d)
        out.extend(arrange(s.node, box))
    return out


def units_of(leaves: dict[str, list[Leaf]], width: float, plan_first: bool = True,
             gap: float = SPACE, apart: bool = False) -> list[list[Node]]:
    """The set's drawings in reading order as units (alternatives each): the scheme; the
    acceleration plan; each group beside (or over) its own force plan; the lever; each chart; the hodographs as one
    grid (kept together), of any width the sheet holds. ``apart``: each group and its force plan
    two units, the plan set after its group (beside its top where there is room) — where no sheet
    holds the two as one box (LINK49's A3 set: the coulisse's group 265 mm tall beside its 212 mm
    plan, a 302 × 265 mm box 3 mm taller than form 2a leaves beside the title block)."""
    # the accelerations the inertia loads come from first, as Tables 1 and 2 give them (and the wide
    # scheme of a six-bar has room under it for the plan, not for a group with its force plan)
    # (``plan_first``; else after the groups, by the lever it is turned into)
    acc = [[a] for a in leaves["acceleration"]]
    units: list[list[Node]] = [[s] for s in leaves["scheme"]] + (acc if plan_first else [])
    # a group beside its force plan, or over it where the sheet's room beside the last drawing is
    # narrow (a tall scheme's)
    for g, q in zip(leaves["groups"], leaves["forces"]):
        units += [[g], [q]] if apart else [[Row([g, q], gap), Stack([g, q], gap)]]
    units += ([] if plan_first else acc) + [[lv] for lv in leaves["lever"]]
    units += [[c] for c in leaves["charts"]]
    hods = leaves["hodographs"]
    if hods:
        grids = [Grid(hods, cols, gap) for cols in range(1, len(hods) + 1)]
        units.append([g for g in grids if extent(g)[0] <= width + 1e-9] or grids[:1])
    return units
