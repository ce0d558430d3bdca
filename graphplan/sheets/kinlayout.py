"""The kinematics sheet composed by arithmetic (docs/composition.md, LAYOUT.md): the drawings' natural
sizes measured once at trial scales (``Natural``), then the largest standard scales at which the
position plan, the diagrams, the velocity and acceleration plans and the tables' column fit the zones
of one sheet (``one_sheet``: four shapes of zones, the grids' columns, the tables' parts), or, where one
sheet cannot hold the plans legibly, the fewest sheets of a set (``set_of_sheets``). Nothing is drawn
here: the drawings come from sheets/kinematics.py's Drafter."""
from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

from graphplan.drawing.layout import GAP, SHELF_MOST, Grid, Leaf, Row, Shelf, Stack, column_size, extent, extent_with, flow, split
from graphplan.graphic.record import Record
from graphplan.graphic.scales import LEGIBLE_MM, LEGIBLE_READS, PLAN_MM, series_choices   # the plans read: p_v a and π a at least this long,
from graphplan.sheets.compose import FACTORS, NOTE_STEP, Family, choose_levels, coarser, field_of, finer, keep_out, notes_height
from graphplan.sheets.form import TABLES, Form
from graphplan.util.errors import GraphplanError, said_error

if TYPE_CHECKING:
    from graphplan.sheets.kinematics import Drafter

FAMILIES = ("position", "velocity", "acceleration")
# PLAN_MM (graphic.scales): … or its largest plan drawn at least this across
CRANK_MM = 30.0        # a set's position plan: the crank drawn at least this long (else its twelve
                       # positions crowd the letters off their points: 1:4 drew OA 20 mm, S1 23 mm away)
ONE_SHEET = ("A1",)    # the coursework's format: one sheet, the plans smaller if they must be
SET_LARGEST = 1.25     # a set's principal segments grow to at most this times the targets' upper end
DIAGRAM_SIZES = (1.0, 0.8, 0.64, 0.5)   # the diagrams drawn smaller only where a sheet cannot hold them
HEIGHTS = (1.25, 0.5)    # a set's diagrams' height factors: from s at most 100 mm high down to 40 mm …
HEIGHT_STEP = 0.05       # … in these steps (4 mm of s's allowance)
# One sheet's s diagram drawn taller (``finer_s``) also at the series' next finer μs past the 100-mm allowance,
# s then up to this many times the allowance (the series' largest step, 5 → 10), where the composition holds
# it and it reads closer (graphic.diagrams.fitted_scale, review 61 #2's rule): review 62 F4, the offset pump
# drew its 121-mm stroke 60.5 mm high at μs 0,002 (the allowance's finest) in a 290-mm block, a_B 10.2 % off
PAST_ALLOWANCE = 2.0
LEAST_TALLER = 4         # a flat one-factor drawing: this many steps taller tried for one that is not
TARGETS = {"position": 70.0, "velocity": 100.0, "acceleration": 120.0}   # principal segments at factor 1, mm


class PlansUndrawable(GraphplanError):
    """No standard scale draws a family of plans on the sheet (a size that does not shrink)."""


def size_of(rec: Record) -> tuple[float, float]:
    b = rec.bounds()
    return b[2] - b[0], b[3] - b[1]


@dataclass
class Natural:
    """The drawings' natural sizes, measured once at trial scales — what the arithmetic needs: the
    plans' families (position, velocity, acceleration; sheets.compose.Family), the diagrams' size
    per size factor, the tables' sizes per lettering factor (in order) and the notes' lines — each
    the larger of the two languages, so no scale depends on the language."""
    families: dict[str, Family]
    diagrams: dict[float, tuple[float, float]]
    tables: dict[float, list[tuple[str, float, float]]]
    notes: list[list[str]]

    @property
    def count(self) -> dict[str, int]:
        return {name: len(fam.sizes) for name, fam in self.families.items()}

    def leaf(self, family: str, mu: float, name: str = "") -> Leaf:
        """The family's cell at μ: its largest drawing with lettering and caption."""
        return self.families[family].leaf(mu, name or family)

    def drawn(self, family: str, mu: float) -> float:
        """The principal segment drawn at μ, mm."""
        return self.families[family].drawn(mu)

    def notes_height(self, width: float) -> float:
        """The notes' height wrapped to ``width`` (remembered while the notes are the same: a
        composition's search asks it for each width a column is widened to)."""
        seen, memo = self.__dict__.get("_notes_memo", (None, {}))
        if seen != self.notes:
            seen, memo = [list(lines) for lines in self.notes], {}
            self.__dict__["_notes_memo"] = (seen, memo)
        if width not in memo:
            memo[width] = notes_height(self.notes, width)
        return memo[width]


def factors(k: float | tuple[float, float]) -> tuple[float, float]:
    """A diagrams' size as (length factor, height factor): one factor for both, or the pair."""
    return (float(k), float(k)) if isinstance(k, (int, float)) else (float(k[0]), float(k[1]))


def diagrams_size(dr: Drafter, nat: Natural, k: float | tuple[float, float]) -> tuple[float, float]:
    """The diagrams' block at size factor k (or length and height factors; the larger of the two
    languages)."""
    from graphplan.util.words import LANGS
    if k not in nat.diagrams:
        sizes = [size_of(dr.diagram_record(k, lang)) for lang in LANGS]
        nat.diagrams[k] = (max(s[0] for s in sizes), max(s[1] for s in sizes))
    return nat.diagrams[k]


def tree(shape: str, P, D, vgrid: Grid | None, agrid: Grid | None, C, split_column: tuple | None = None):
    """The sheet's composition (C: the tables' column with the notes over the title block, in the
    bottom-right corner): "bands" — position plan and diagrams across the top, under them the
    velocity plans, the acceleration plans and the column; "column" — the column the sheet's full
    height, the rest in those two bands; "accel" — the acceleration plans beside the position plan
    and the diagrams, the velocity plans beside the column; "sides" — the position plan over the
    velocity plans, beside them the diagrams over the acceleration plans over the column; "stacked" —
    the position plan over the diagrams, beside them the velocity plans over the acceleration plans,
    then the column; "stacked-bands" — the position plan over the diagrams, beside them the velocity
    plans over the acceleration plans and the column (a long or tall position plan: it and the
    diagrams need not share a row's width); "split" — the column split (``split_column``: the tables,
    the notes over the title block's room): the position plan, the diagrams and the tables across
    the top, under them the velocity plans, the acceleration plans and the notes over the title
    block (the coulisse's tables, 258 mm high in two columns 361 mm wide, left a full-height column
    150 mm empty under them while its velocity plans were drawn at p_v a 26.7 mm); "tables-accel" —
    the position plan over the diagrams, beside them the velocity plans the sheet's full height, then
    the column split (``split_column``): the tables over the acceleration plans beside the notes over
    the title block's room (stop 47's six-bar: "stacked" left 290 × 170 mm blank under its four tables, its column 554 mm
    high for 385 mm of tables, notes and title block, while the acceleration plan under the
    velocity plans held them at p_v a 40 mm); "accel-column" — the position plan over the diagrams,
    beside them the velocity plans the sheet's full height, then the column split (``split_column``)
    in reading order: the acceleration plans, the tables, the notes over the title block's room (the
    jaw crusher's "stacked" column left 250 × 92 mm blank between its tables and its notes)."""
    vg = [vgrid] if vgrid is not None else []
    ag = [agrid] if agrid is not None else []
    if shape == "split":
        T, N = split_column
        return Stack([Row([P, D, T], flush=True), Row(vg + ag + [N], flush=True)], flush=True)
    if shape == "tables-accel":
        T, N = split_column
        return Row([Stack([P, D])] + vg + [Stack([T, Row(ag + [N], flush=True)], flush=True)], flush=True)
    if shape == "accel-column":
        T, N = split_column
        return Row([Stack([P, D])] + vg + [Stack(ag + [T, N], flush=True)], flush=True)
    if shape == "bands":
        return Stack([Row([P, D]), Row(vg + ag + [C], flush=True)], flush=True)
    if shape == "column":
        return Row([Stack([Row([P, D]), Row(vg + ag)]), C], flush=True)
    if shape == "accel":
        return Stack([Row([P, D] + ag), Row(vg + [C], flush=True)], flush=True)
    if shape == "stacked":
        return Row([Stack([P, D]), Stack(vg + ag), C], flush=True)
    if shape == "stacked-bands":
        return Row([Stack([P, D]), Stack(vg + [Row(ag + [C], flush=True)], flush=True)], flush=True)
    return Row([Stack([P] + vg), Stack([D] + ag + [C], flush=True)], flush=True)


# (the order breaks ties of the scales: "tables-accel" before "stacked", whose acceleration plans under
# the velocity plans leave the column's blank under its tables in one piece)
SHAPES = ("bands", "column", "accel", "sides", "tables-accel", "stacked", "stacked-bands", "split", "accel-column")
SPLIT = ("split", "tables-accel", "accel-column")     # the shapes whose column is split (``split_leaves``)
BALANCE = 2.0      # a family drawn past its target at most this times the least-grown one's share
LETTERING = 14.0     # mm a plan's lettering is assumed to add across and up before it is placed


@dataclass
class Plan:
    """The kinematics sheet as composed by arithmetic: the scales (μ per family), the diagrams'
    size factor, the tables' lettering factor, the composition's shape, grid columns and table
    columns, and the number of sheets (a set: more than 1)."""
    mu: dict[str, float]
    diagrams: float | tuple[float, float]     # the diagrams' size factor (or length and height factors)
    tables: float
    shape: str = "bands"
    vcols: int = 1
    acols: int = 1
    parts: int = 1
    sheets: int = 1
    counts: tuple[int, ...] = ()     # the tables in each of the column's parts, in reading order
    after: bool = False              # a set: the diagrams after the acceleration plans (else before)
    notes: float = 185.0             # the notes' width, mm (the title block's, ``TITLE``, or wider: ``widened``)
    under: bool = False              # one sheet: the last table across under the columns of the others
    over: bool = False               # one sheet: the first table across over the columns of the others
    stacked: int = 0                 # a set: the last tables this many, side by side, over the notes (``set_tail``)
    beside: tuple[int, ...] = ()     # a set: the first tables as one block beside the last plan, lines of these counts (``set_tail``)


TITLE = 185.0     # the title block's width: the column is at least this wide
TWO_COLUMNS = 2 * TITLE + GAP    # a set's notes this wide stand in two columns of the title block's width


def note_halves(lines: list[str], width: float = TITLE) -> tuple[list[str], list[str]]:
    """A set's notes in two columns (``TWO_COLUMNS``): the lines split, whole, where the taller
    column (lines wrapped to ``width``) is lowest — the six-bar's A3 notes, 160 mm high at the title
    block's width, took a sixth sheet of their own; in two columns they stand under the last tables."""
    from graphplan.sheets.compose import NOTE, wrap_markup
    counts = [len(wrap_markup(line, width - 5.0, NOTE)) for line in lines]
    total = sum(counts)
    cut = min(range(len(lines) + 1), key=lambda i: (max(sum(counts[:i]), total - sum(counts[:i])), -i))
    return lines[:cut], lines[cut:]


def set_notes_height(notes: list[list[str]], width: float) -> float:
    """The height of a set's notes (one list of lines per language) at ``width``: one column, or
    two where ``width`` is ``TWO_COLUMNS`` (``note_halves``)."""
    if width < TWO_COLUMNS - 1e-9:
        return notes_height(notes, width)
    return max(notes_height([half], TITLE) for lines in notes for half in note_halves(lines))


def table_groups(tables: list, parts: int, counts: tuple[int, ...] = (), under: bool = False,
                 over: bool = False) -> list[list]:
    """The tables in ``parts`` columns (``counts`` tables each, where the plan found them); ``under``:
    the last one set across under the columns of the others, its own group last (``tables_size``,
    ``place_tables``); ``over``: the first one across over the columns of the others, its own group
    first; both: the first over and the last under the columns of those between (the compressor's
    Table 1 over Tables 2 | 3, Table 4 under them: in one column Table 3 stood under Table 2 beside
    a 100 × 178 mm blank)."""
    if over and under and len(tables) > parts + 1:
        return [[tables[0]]] + split(tables[1:-1], parts, counts=counts) + [[tables[-1]]]
    if over and len(tables) > parts:
        return [[tables[0]]] + split(tables[1:], parts, counts=counts)
    if under and len(tables) > parts:
        return split(tables[:-1], parts, counts=counts) + [[tables[-1]]]
    return split(tables, parts, counts=counts)


def tables_size(groups: list[list], under: bool = False, over: bool = False) -> tuple[float, float]:
    """The tables' block (``table_groups``): columns side by side, the last group under them where
    ``under``, the first over them where ``over`` (both: the first over, the last under them)."""
    if over and under and len(groups) >= 3:
        cw, ch = column_size(groups[1:-1])
        first, last = groups[0][0], groups[-1][0]
        return max(cw, first.w, last.w), first.h + GAP + ch + GAP + last.h
    if over and len(groups) >= 2:
        cw, ch = column_size(groups[1:])
        first = groups[0][0]
        return max(cw, first.w), first.h + GAP + ch
    if not under or len(groups) < 2:
        return column_size(groups)
    cw, ch = column_size(groups[:-1])
    last = groups[-1][0]
    return max(cw, last.w), ch + GAP + last.h


def place_tables(groups: list[list], right: float, top: float, under: bool = False, over: bool = False) -> list:
    """The tables placed from the block's top right corner (``set_columns``): in reading order, down
    each column, then the next; the last group under them, at the block's right, where ``under`` —
    wider than the last column, it runs on under the one before: read after them all."""
    from graphplan.drawing.layout import Placed, set_columns, top_left
    w, _ = tables_size(groups, under, over)
    if over and under and len(groups) >= 3:
        t, u = groups[0][0], groups[-1][0]
        _, ch = column_size(groups[1:-1])
        b = (right - w, top - t.h, right - w + t.w, top)
        # the last at the block's left, as the first and the columns' first: one left edge
        bu = (right - w, top - t.h - GAP - ch - GAP - u.h, right - w + u.w, top - t.h - GAP - ch - GAP)
        return ([Placed(t.name, top_left(t.record, b) if t.record is not None else Record(), b)]
                + set_columns(groups[1:-1], right - w, top - t.h - GAP)
                + [Placed(u.name, top_left(u.record, bu) if u.record is not None else Record(), bu)])
    if over and len(groups) >= 2:
        # the first across the block's top at its left (read first), the others' columns under it
        t = groups[0][0]
        b = (right - w, top - t.h, right - w + t.w, top)
        return [Placed(t.name, top_left(t.record, b) if t.record is not None else Record(), b)] + set_columns(
            groups[1:], right - w, top - t.h - GAP)
    if not under or len(groups) < 2:
        return set_columns(groups, right - w, top)
    _, ch = column_size(groups[:-1])
    t = groups[-1][0]
    b = (right - t.w, top - ch - GAP - t.h, right, top - ch - GAP)
    return set_columns(groups[:-1], right - w, top) + [
        Placed(t.name, top_left(t.record, b) if t.record is not None else Record(), b)]


def tables_blank(tables: list, parts: int, under: bool = False, over: bool = False) -> float:
    """The blank (mm²) the tables leave in their block arranged as ``table_groups`` sets them: the
    block's area less the tables' own."""
    size = tables_size(table_groups(tables, parts, (), under, over), under, over)
    return math.prod(size) - sum(t.w * t.h for t in tables)


def column_leaf(f: Form, tables: list[Leaf], parts: int, notes_height, counts: tuple[int, ...] = (),
                under: bool = False, notes: float = TITLE, over: bool = False) -> tuple[Leaf, list[list[Leaf]], float]:
    """The tables in ``parts`` columns (``counts`` tables each, where the plan found them; ``under``:
    the last across under the others) with the notes under them — wrapped to the column's width, or
    to ``notes`` mm where that is wider (``widened``) — and the title block's room at the foot, as
    one leaf for the composition; its table groups and its width."""
    from graphplan.sheets.compose import keep_out
    groups = table_groups(tables, parts, counts, under, over)
    cw, ch = tables_size(groups, under, over)
    width = max(cw, TITLE, notes)
    foot = keep_out(f)[3] - field_of(f)[1]
    return Leaf("column", width, ch + GAP + notes_height(width) + GAP + foot), groups, width


def split_leaves(f: Form, tables: list[Leaf], parts: int, notes_height, counts: tuple[int, ...] = (),
                 under: bool = False, notes: float = TITLE, over: bool = False) -> tuple[Leaf, Leaf, list[list[Leaf]]]:
    """The column split in two (``tree``'s "split"): the tables in ``parts`` columns (``under``: the
    last across under the others), and the notes at the title block's width (or ``notes`` mm where
    wider: ``widened``) over the title block's room; and the tables' groups."""
    from graphplan.sheets.compose import keep_out
    groups = table_groups(tables, parts, counts, under, over)
    foot = keep_out(f)[3] - field_of(f)[1]
    width = max(TITLE, notes)
    return Leaf("tables", *tables_size(groups, under, over)), Leaf("notes", width, notes_height(width) + GAP + foot), groups


NOTES_STEP = 5.0    # mm: a column widened for its notes in these steps (``widened``)


def widened(width: float, spare: float) -> float | None:
    """The notes' width where a composition is too tall by its column (or its notes' leaf) and has
    ``spare`` mm across: the column ``width`` mm wide widened by the spare room, in whole
    ``NOTES_STEP`` — its notes wrapped wider, fewer lines. The notes are the one block of a sheet
    whose size is not a scale's step: a line more of them (the coulisse's Table 4 footnote, 4 mm)
    made its stacked composition 1.1 mm too tall beside 37.7 mm spare across, and the position plan
    went from 1:2.5 to 1:5. None where there is not a step to spare."""
    wide = width + math.floor(spare / NOTES_STEP + 1e-9) * NOTES_STEP
    return wide if wide > width + 1e-9 else None


PRUNED = True       # ``one_sheet_at`` skips the grid pairs whose least tree is past the field (``floor_of``);
                    # False: every tree measured whole (the plain search, for the tests)
FLOOR_SLACK = 1e-6  # mm: a tree counted past the field only by more than this (``fits_field``)


def notes_floor(notes: list[list[str]]) -> float:
    """The least height the notes (one list of lines per language) take at any width: one line a
    paragraph (``notes_height`` wraps each into one line or more), and the line it adds."""
    return max((len(lines) for lines in notes), default=0) * NOTE_STEP + NOTE_STEP


def least_leaf(nodes) -> Leaf | None:
    """A leaf as narrow as the narrowest of ``nodes`` and as low as the lowest (None where any is
    None: the family has no drawings): a tree with it in place of any of them is no larger."""
    nodes = list(nodes)
    if not nodes or any(n is None for n in nodes):
        return None
    sizes = [extent(n) for n in nodes]
    return Leaf("least", min(w for w, _ in sizes), min(h for _, h in sizes))


def fits_field(node, W: float, H: float) -> bool:
    """Whether a lower bound of trees (``floor_of``) may still fit the field W × H: where it does not
    (past it by more than ``FLOOR_SLACK``), no tree it bounds does."""
    w, h = extent(node)
    return w <= W + FLOOR_SLACK and h <= H + FLOOR_SLACK


def tree_sized(shape: str, P, D, vg, ag):
    """``extent(tree(shape, P, D, vg, ag, C, (T, N)))`` as a function ``f(C, (T, N))`` of the column
    and the split halves: the same sums and maxima to the bit (``extent_with``), the position plan,
    the diagrams and the grids added up once (a sheet's search tries each grid pair with every
    arrangement of its tables)."""
    slots = [Leaf("column"), Leaf("tables"), Leaf("notes")]
    sized = extent_with(tree(shape, P, D, vg, ag, slots[0], (slots[1], slots[2])), slots)

    def size_with(C, half) -> tuple[float, float]:
        return sized(((C.w, C.h), (half[0].w, half[0].h), (half[1].w, half[1].h)))
    return size_with


def _grids(n: int) -> list[int]:
    """Column counts of a grid of n cells, one for each row count: the fewest columns that give it
    (the narrowest grid of r rows has ⌈n/r⌉ columns — 12 plans in two rows are 6 a row, not 11)."""
    out: list[int] = []
    for r in range(1, n + 1):
        c = -(-n // r)
        if -(-n // c) == r and c not in out:
            out.append(c)
    return out or [1]



DIAGRAMS_SHRUNK = (1.0, 0.8, 0.64, 0.5)   # the diagrams' size factors a sheet tries, largest first


def one_sheet(dr: Drafter, nat: Natural, f: Form) -> Plan | None:
    """The best one-sheet composition (``composed``) with the notes at the column's width; where
    wrapping them wider (``widened``) would have made the room for an arrangement that did not fit,
    composed so too, and that one where it draws the plans larger (``plan_score``): a line more of
    notes (the coulisse's Table 4 footnote, 4 mm) took its A1 position plan from 1:2.5 to 1:5. Not
    always wider: the series' steps grow the families greedily, and more room at one trial can end
    in a sheet worse by the same measure (a sieve's velocity plans grown 40.4 → 45.2 mm into the
    notes' room left its acceleration plan 40 mm, not 71)."""
    near: list[dict[str, float]] = []
    first = composed(dr, nat, f, False, near)
    if not near or first is not None and not any(trial_score(nat, mu) > plan_score(nat, first)[:3] for mu in near):
        return first         # no trial the wider notes hold would draw the plans larger
    wider = composed(dr, nat, f, True)
    if wider is not None and (first is None or plan_score(nat, wider) > plan_score(nat, first)):
        return wider
    return first


def trial_score(nat: Natural, mu: dict[str, float]) -> tuple:
    """``plan_score``'s first three: (legible, the position plan's share, the smallest family's)."""
    fams = [fam for fam in FAMILIES if fam != "acceleration" or nat.count["acceleration"] > 0]
    return legible(nat, mu), main_rel(nat, mu), round(min(nat.families[fam].rel(mu[fam]) for fam in fams), 6)


def plan_score(nat: Natural, p: Plan) -> tuple:
    """How large a one-sheet composition draws: (legible, the position plan against its target up to
    ``MAIN``, the smallest family's, the families' log sizes counted per drawing, the diagrams' size
    factor) — ``one_sheet_at``'s order."""
    fams = [fam for fam in FAMILIES if fam != "acceleration" or nat.count["acceleration"] > 0]
    rel = [nat.families[fam].rel(p.mu[fam]) for fam in fams]
    weight = [max(1, nat.count[fam]) for fam in fams]
    return (legible(nat, p.mu), main_rel(nat, p.mu), round(min(rel), 6),
            round(sum(w * math.log(r) for w, r in zip(weight, rel)), 6), min(factors(p.diagrams)))


def composed(dr: Drafter, nat: Natural, f: Form, wide: bool = False, near: list | None = None) -> Plan | None:
    """The best one-sheet composition (``one_sheet_at``; ``wide``, ``near``: its notes wrapped wider)
    with the diagrams at their full size, else at the smaller factor of ``DIAGRAMS_SHRUNK`` whose
    plans come out largest: a six-bar press's twelve tall velocity plans, 347 × 268 mm of diagrams
    and four tables hold no A1 sheet at full size, and A1 is one sheet. None where none holds even
    then."""
    full = one_sheet_at(dr, nat, f, DIAGRAMS_SHRUNK[0], wide=wide, near=near)
    if full is not None and f.name in ONE_SHEET:
        main = main_larger(dr, nat, f, full[1], wide, near)
        if main is not None:
            return main
        smaller = main_in_smaller(dr, nat, f, full[1], wide, near)
        if smaller is not None:
            return smaller
    if full is not None or f.name not in ONE_SHEET:       # a smaller format makes a set instead
        return full[1] if full is not None else None
    shrunk = [got for k in DIAGRAMS_SHRUNK[1:]
              if (got := one_sheet_at(dr, nat, f, k, True, wide=wide, near=near)) is not None]
    return max(shrunk, key=lambda c: c[0])[1] if shrunk else None


def main_in_smaller(dr: Drafter, nat: Natural, f: Form, p: Plan, wide: bool = False, near: list | None = None
                    ) -> Plan | None:
    """Where the full-size diagrams leave the position plan crowded (its crank under ``CRANK_MM``):
    the first smaller size factor of ``DIAGRAMS_SHRUNK`` (right, ``diagrams_right``) whose
    composition draws the position plan larger and every other plan no smaller — the diagrams'
    size is ``plan_score``'s last criterion, the main drawing's its first after legibility. Review
    46: the six-bar's A1 kept its diagrams at 0.8 with the position plan at 1:2.5 (crank 26 mm),
    p_v a 40 mm and π a 80 mm, where at 0.64 another arrangement draws 1:2, 55 mm and 115 mm. None
    where no smaller size does."""
    if nat.drawn("position", p.mu["position"]) >= CRANK_MM - 1e-9:
        return None
    was = sizes_of(nat, p.mu, p.diagrams)
    for k in DIAGRAMS_SHRUNK[1:]:
        if k >= min(factors(p.diagrams)) - 1e-9 or not dr.diagrams_right(k):
            continue
        got = one_sheet_at(dr, nat, f, k, True, wide=wide, near=near)
        if got is None:
            continue
        now = sizes_of(nat, got[1].mu, got[1].diagrams)
        if now[0] > was[0] + 1e-9 and all(a >= b - 1e-9 for a, b in zip(now[1:len(FAMILIES)], was[1:len(FAMILIES)])):
            return got[1]
    return None


def composed_fits(nat: Natural, f: Form, p: Plan, D: Leaf) -> bool:
    """Whether one sheet's composition ``p`` (its scales, shape, grids and table columns as chosen)
    holds the diagrams' leaf ``D`` (``one_sheet_at``'s arithmetic)."""
    x0, y0, x1, y1 = field_of(f)
    tabs = [Leaf(name, w, h) for name, w, h in nat.tables[p.tables]]
    C = column_leaf(f, tabs, p.parts, nat.notes_height, p.counts, p.under, p.notes, p.over)[0]
    halves = split_leaves(f, tabs, p.parts, nat.notes_height, p.counts, p.under, p.notes, p.over)[:2]
    P = nat.leaf("position", p.mu["position"])
    V = [nat.families["velocity"].leaf(p.mu["velocity"], "", i) for i in range(nat.count["velocity"])]
    A = [nat.families["acceleration"].leaf(p.mu["acceleration"], "", i) for i in range(nat.count["acceleration"])]
    vg = Grid(V, p.vcols, fitted=True) if V else None
    ag = Grid(A, p.acols, fitted=True) if A else None
    tw, th = extent(tree(p.shape, P, D, vg, ag, C, halves))
    return tw <= x1 - x0 + 1e-9 and th <= y1 - y0 + 1e-9


def taller_in_place(dr: Drafter, nat: Natural, f: Form, p: Plan) -> Plan:
    """One sheet's diagrams, drawn shorter for the room across, given back their height where the
    composition has it (the same scales, shape and columns): of the height factors up to 1 in
    ``HEIGHT_STEP`` that still fit, are right (graphic.redraw) and no flatter, the one read closest
    to the exact values at the positions (redraw's largest |δ|, what Table 5 prints), then drawn
    largest — as a set's diagrams are grown (``taller``); kept where none reads better. Review 12:
    the A1 drew φ5 29 mm high (L 120 mm, μφ 0,01 рад/мм) beside a 301-mm column of tables; there
    the chords' own error rules ε5 (17.5 % at 0.5, 22.7–38 % at the taller heights), so it stays.
    Also the s diagram alone taller at a finer μs (``finer_s``), the v and a diagrams as high — on
    diagrams already at their full size too: review 60 #1, the jaw crusher's ψ3 drawn 41 mm high
    (μψ 0,01, its 80-mm allowance) with 45 mm empty above it, ε3 read 17 % off at a position; at
    0,005 (82.5 mm, within the 100-mm allowance a set's diagrams have) 6.3 %."""
    from graphplan.sheets.kinematics import diagram_options
    long_, tall = factors(p.diagrams)
    full = tall >= 1.0 - 1e-9 and long_ >= 1.0 - 1e-9
    if full and not finer_s(dr, p.diagrams):
        return p
    o = dr.opts

    def judged(k) -> tuple[float, float]:
        r = diagram_options(dr.st, k, o.positions, o.precision, dr.room, dr.floor)["redrawn"]
        return (round(r.off_after, 1) if r.off_after is not None else math.inf, -round(drawn_share(dr, k), 6))
    best, score = p.diagrams, judged(p.diagrams)
    # not by bisection: a pair's poles follow its height allowance (``first_options``), so its
    # block's height is not monotonic in the factor (0.6 drew 239 mm, 0.7 232 mm here). Longer too
    # where the zone is wider than the diagrams (a stacked position plan 300 mm across over them):
    # the lengths of ``DIAGRAMS_SHRUNK`` above the chosen one, their heights in steps of 0.1
    heights = {long_: [round(tall + j * HEIGHT_STEP, 6) for j in range(int(round((1.0 - tall) / HEIGHT_STEP)), 0, -1)]}
    for length in (x for x in DIAGRAMS_SHRUNK if x > long_ + 1e-9):
        heights[length] = [round(1.0 - 0.1 * j, 6) for j in range(int(round((1.0 - length) / 0.1)) + 1)]
    scales = finer_s(dr, p.diagrams)
    ks = [(length, t) for length, ts in heights.items() for t in ts] + scales
    tried = {dr.diagrams(p.diagrams).mu_s: score[0]}     # μs → its largest |δ| (or why not drawn), for the notes
    for k in ks:
        mu = dr.diagrams(k).mu_s if k in scales else None
        if not dr.diagrams_right(k):
            if mu is not None:
                tried.setdefault(mu, "wrong")
            continue
        got = judged(k)        # no better read: not drawn in both languages to be measured
        if mu is not None and not isinstance(tried.get(mu), float):
            tried[mu] = ("room" if not composed_fits(nat, f, p, Leaf("diagrams", *diagrams_size(dr, nat, k)))
                         else "flat" if flat(dr, k) > flat(dr, p.diagrams) else got[0])
        # past the 100-mm allowance only where it reads closer, not for its size at the same |δ| (the lab
        # crank-slider's given poles drew s 200 mm and v, a twice as tall at 0,0005 for 9.59 % beside 9.6 %)
        closer = got < score if mu is None or k[1] <= HEIGHTS[0] + 1e-9 else got[0] < score[0]
        if closer and composed_fits(nat, f, p, Leaf("diagrams", *diagrams_size(dr, nat, k))) \
                and flat(dr, k) <= flat(dr, p.diagrams):
            best, score = k, got
    # the notes say the other s scales tried (review 62 F4: a diagram past 5 % and no word of a larger s)
    chosen = dr.diagrams(best).mu_s
    dr.s_tried[best] = tuple(sorted(((mu, why) for mu, why in tried.items() if mu != chosen), reverse=True))
    from dataclasses import replace
    return p if best == p.diagrams else replace(p, diagrams=best)


def finer_s(dr: Drafter, k) -> list[tuple[float, float, float]]:
    """One sheet's diagrams at size ``k`` with their s diagram drawn taller at each finer standard μs
    the height allowance up to ``HEIGHTS[0]`` × ``S_HEIGHT`` (100 mm, a set's tallest) holds, the v
    and a diagrams as high as at ``k`` (``first_options``' triple: the poles lower in proportion; for
    one factor ``k``, as high as the pair (length, ``k``) draws them, from its whole allowance — the
    jaw crusher's v, a 53.5, 45 → 74.5, 70.5 mm read ε3 6.3 % off, kept at k's heights 10.1 %):
    (length, the smallest height factor in ``HEIGHT_STEP`` that draws at that μs, ``k``'s height)
    — ``taller_in_place`` takes one where
    the composition's band holds it and it reads closer to the exact values. The short s ordinates
    are what the ruler's half millimetre amplifies in v and a: review 55 #3's beam pump drew its
    stroke 44 mm high (μs 0,004) in an 85-mm band, a_D 32.8 % off at a position; at 0,0025 it is
    71 mm high. Then the series' one next finer μs past that allowance (the stroke up to
    ``PAST_ALLOWANCE`` times it: taller than 100 mm by less than the series' step), where the sheet
    holds it — review 62 F4: the offset pump's 120.9-mm stroke 60.5 mm high at 0,002 (the allowance's
    finest), a_B 10.2 % off; at 0,001 (121 mm) 5.1 %."""
    from graphplan.sheets.kinematics import first_options, _drawn, S_HEIGHT
    long_, tall = factors(k)
    if tall >= PAST_ALLOWANCE * HEIGHTS[0] - 1e-9:
        return []
    o = dr.opts
    d = dr.diagrams(k)
    mu = d.mu_s
    out, seen = [], {mu}
    for j in range(1, int(round((HEIGHTS[0] - tall) / HEIGHT_STEP)) + 1):
        t = round(min(HEIGHTS[0], tall + j * HEIGHT_STEP), 6)
        k3 = (long_, t, tall)
        mu_t = _drawn(dr.st, first_options(dr.st, k3, o.positions), 0.0).mu_s
        if mu_t < mu - 1e-12 and mu_t not in seen:
            seen.add(mu_t)
            out.append(k3)
    # past the allowance: the series' one next finer value, s taller than 100 mm by less than its step
    import numpy as np
    from graphplan.exact.positions import exact_motion
    from graphplan.graphic.diagrams import CYCLE
    from graphplan.graphic.scales import at_most
    span = float(np.ptp(exact_motion(d.study, d.output, np.arange(CYCLE + 1) * 360.0 / CYCLE)[0]))
    finest = min(seen)
    nxt = at_most(finest * (1 - 1e-6))
    t = max(tall, HEIGHTS[0]) + HEIGHT_STEP * max(1, math.ceil(
        (span / nxt / S_HEIGHT - max(tall, HEIGHTS[0])) / HEIGHT_STEP - 1e-6))
    t = round(t, 6)
    if t <= PAST_ALLOWANCE * HEIGHTS[0] + 1e-9:
        k3 = (long_, t, tall)
        if _drawn(dr.st, first_options(dr.st, k3, o.positions), 0.0).mu_s < finest - 1e-12:
            out.append(k3)
    return out


SHORTER = (0.9, 0.8, 0.7, 0.64)   # the diagrams' length factors an A1 tries for a larger position plan
KEPT = 0.9        # … where every other plan keeps at least this share of its size
GAIN = 2.0        # … and the position plan is drawn at least this many times as large
STEP = 1.25       # … else, where no length does, a standard step larger (1:5 → 1:4, 1:2.5 → 1:2) with every
                  # plan still legible (``plan_score``'s order: legible, then the main drawing): the blind
                  # review of stop 59's Watt-II chain kept 1:5 (crank 12 mm, its twelve positions' labels
                  # piled on leaders) beside full-length diagrams, where L × 0.8 draws it at 1:2 (p_v a
                  # 40.1 mm kept, π a 55.1 → 45.1 mm, still legible; KEPT asked 49.6)


def main_larger(dr: Drafter, nat: Natural, f: Form, p: Plan, wide: bool = False, near: list | None = None
                ) -> Plan | None:
    """Where the sheet's main drawing, the position plan, is drawn with its crank under ``CRANK_MM``
    (LAYOUT.md: the largest drawing, μl by its zone): the diagrams drawn shorter (``SHORTER``, their
    height kept): of those whose composition draws the position plan at least ``GAIN`` times as
    large and every other plan at least ``KEPT`` as large (or legible and no smaller against its
    target than the position plan) — where none does, a standard ``STEP`` larger, every plan
    legible —, the one drawing the position plan largest, then the longest (the first whose crank
    reaches ``CRANK_MM``) — the coulisse's 0.55 × 0.66 m plan sat at 1:10 (crank 9.3 mm, its
    letters 14–27 mm off their points) in the 77 mm the full-length diagrams left it; L × 0.7
    gives it 1:4 (p_v a 26.7 → 25.0 mm, π a 61.5 → 60.0 mm). None where no shorter length does."""
    if nat.drawn("position", p.mu["position"]) >= CRANK_MM - 1e-9:
        return None
    was = sizes_of(nat, p.mu, p.diagrams)[:len(FAMILIES)]
    gots: dict[float, tuple | None] = {}
    for gain in (GAIN, STEP):
        best: tuple[float, Plan] | None = None
        for k in SHORTER:
            if k not in gots:
                gots[k] = one_sheet_at(dr, nat, f, (k, 1.0), wide=wide, near=near)
            got = gots[k]
            if got is None:
                continue
            now = sizes_of(nat, got[1].mu, got[1].diagrams)[:len(FAMILIES)]
            main = nat.families["position"].rel(got[1].mu["position"])

            def kept(fam: str, a: float, b: float, got=got, main=main) -> bool:
                """A plan keeps ``KEPT`` of its size, or yields room to the main drawing while it still
                reads and is drawn, against its target, no smaller than the position plan now is (the
                coulisse's acceleration plans π a 82 → 55 mm for its position plan 1:10 → 1:4)."""
                if gain < GAIN:         # a step larger: the score's own order, legible first, then the main drawing
                    return legible(nat, got[1].mu)
                return a >= KEPT * b - 1e-9 or (legible(nat, got[1].mu) and a / nat.families[fam].target >= main - 1e-9)
            if now[0] >= gain * was[0] - 1e-9 and all(kept(fam, a, b) for fam, a, b in zip(FAMILIES[1:], now[1:], was[1:])):
                if best is None or now[0] > best[0] + 1e-9:
                    best = (now[0], got[1])
                if now[0] >= CRANK_MM - 1e-9:
                    break
        if best is not None:
            return best[1]
    return None


def one_sheet_at(dr: Drafter, nat: Natural, f: Form, k_diagrams: float, even: bool = False,
                 wide: bool = False, near: list | None = None) -> tuple[tuple, Plan] | None:
    """The best one-sheet composition with the diagrams at size factor ``k_diagrams``: for each
    lettering of the tables, each shape and each order of growth, the scales by ``choose_levels``
    (all families grown together, and ``position_first``); the legible one whose position plan is
    drawn largest (up to ``MAIN`` of its target), then whose plans are drawn largest (the smallest,
    then the product of the principal segments), 3.5 mm tables where they cost no drawing a step —
    with its score. ``even``: where no arrangement is legible (the diagrams already shrunk), the
    smallest plan drawn largest first, the position plan after it — a press's position plan grown
    first left its twelve velocity plans at p_v a = 19 mm, their letters crowding. ``wide``: an
    arrangement too tall by its column with room across has the notes wrapped wider (``widened``);
    else the scales of each trial that would then fit are noted in ``near``."""
    near = [] if near is None else near
    x0, y0, x1, y1 = field_of(f)
    W, H = x1 - x0, y1 - y0
    has_a = nat.count["acceleration"] > 0
    D = Leaf("diagrams", *diagrams_size(dr, nat, k_diagrams))
    nv, na = nat.count["velocity"], nat.count["acceleration"]
    cands: list[tuple] = []     # (score as chosen, sizes as chosen, score with the room given out, plan)

    def score_of(mu, k_d, factor, shape, weighed: bool = False, plain: bool = True) -> tuple:
        """(legible, main, smallest, product of the principal segments, …); ``weighed``: each
        family's log counted once a drawing (twelve velocity plans weigh more than two
        acceleration plans: the drawn area); ``plain``: not the over-and-under tables, which win
        no tie (the slotter's "column" held by them, at the scales "split" drew too, opened a
        66 × 328 mm strip beside its position plan)."""
        fams = [fam for fam in FAMILIES if fam != "acceleration" or has_a]
        rel = [nat.families[fam].rel(mu[fam]) for fam in fams]
        weight = [max(1, nat.count[fam]) if weighed else 1 for fam in fams]
        return (legible(nat, mu), main_rel(nat, mu), round(min(rel), 6),
                round(sum(w * math.log(r) for w, r in zip(weight, rel)), 6), k_d, factor == TABLES,
                plain, -SHAPES.index(shape))
    for factor in (TABLES, 1.0):
        tabs = [Leaf(name, w, h) for name, w, h in nat.tables[factor]]
        # the tables in 1–3 columns; or the last (the diagrams' readings, 12 positions across: review
        # 12's 175 mm) across under 2–3 columns of the others — the six-bar's columns T1, T2 | T3,
        # T4, T5 drew 413 mm wide beside a 1:5 position plan; T5 under them, 328
        ways = [(parts, False, False) for parts in (1, 2, 3)][:max(1, len(tabs))]
        # (only where it is wider than the last column: set at the block's right it then runs on under
        # the column before — read after them all, not as the foot of one column)
        ways += [(parts, True, False) for parts in (2, 3) if len(tabs) > parts + 1
                 and tabs[-1].w > max(t.w for t in split(tabs[:-1], parts)[-1]) + GAP]
        # or the first (the velocities, 12 positions' columns) across over 2–3 columns of the others:
        # the six-bar's T1 alone in a column beside T2, T3 left 218 × 127 mm blank under it; over
        # [T2 | T3, T4] the block is narrower and lower, read in order (review 46)
        ways += [(parts, False, True) for parts in (2, 3) if len(tabs) > parts
                 and tabs[0].w > max(t.w for t in split(tabs[1:], parts)[0]) + GAP]
        # or both: the first over and the last under the columns of those between (the compressor's
        # T1 over T2 | T3, T4 under: in one column T3 stood under T2 beside 100 × 178 mm blank)
        ways += [(parts, True, True) for parts in (2, 3) if len(tabs) > parts + 1
                 and tabs[0].w > max(t.w for t in split(tabs[1:-1], parts)[0]) + GAP
                 and tabs[-1].w > max(t.w for t in split(tabs[1:-1], parts)[-1]) + GAP]
        cols = [column_leaf(f, tabs, parts, nat.notes_height, under=under, over=over)[0] for parts, under, over in ways]
        halves = [split_leaves(f, tabs, parts, nat.notes_height, under=under, over=over)[:2]
                  for parts, under, over in ways]
        # the blank a table arrangement leaves in its block (a tie between arrangements goes to the
        # one leaving less: its columns' heights alike)
        waste = [tables_blank(tabs, parts, under, over) for parts, under, over in ways]

        tried: dict[tuple, tuple | None] = {}

        def arranged(mu, shape, best_fill=False, D=D):
            """``_arranged``, remembered: the shapes' growths and searches try the same sizes
            (the shaper's sheet: 716 trials, 294 distinct)."""
            key = (shape, best_fill, D.w, D.h, tuple(sorted(mu.items())))
            if key not in tried:
                tried[key] = _arranged(mu, shape, best_fill, D)
            return tried[key]

        def _arranged(mu, shape, best_fill=False, D=D):
            P = nat.leaf("position", mu["position"])
            V = [nat.families["velocity"].leaf(mu["velocity"], "", i) for i in range(nv)]
            A = [nat.families["acceleration"].leaf(mu["acceleration"], "", i) for i in range(na)]
            vgrids = {vc: Grid(V, vc, fitted=True) for vc in _grids(nv)} if V else {1: None}
            agrids = {ac: Grid(A, ac, fitted=True) for ac in _grids(na)} if A else {1: None}
            found = None
            # the over-and-under ways only where no other arrangement holds these scales: their block
            # is lower, but a column's freed height is blank all the same (the crank-slider's column
            # held 194 × 160 mm blank under its tables where in one column the blank was a 58-mm band)
            for both in (False, True):
                if found is not None:
                    break
                found = _arranged_ways(mu, shape, best_fill, D, P, vgrids, agrids, both)
            return found

        floors: dict[tuple[str, bool], tuple[Leaf, tuple[Leaf, Leaf]] | None] = {}

        def floor_of(shape: str, both: bool) -> tuple[Leaf, tuple[Leaf, Leaf]] | None:
            """The least column (and split halves) any table arrangement of this pass can take in
            ``shape``, its notes wrapped to any width (remembered; None: no arrangement): each
            leaf the least width and a height no more than any arrangement's, its notes one line a
            paragraph (``notes_height`` wraps each into one line or more). The tree's extent only
            grows with its leaves' sizes (sums and maxima), so where the tree with these leaves
            does not fit, no arrangement of a grid pair fits, nor does one with its notes wrapped
            wider (``widened``: never narrower): the pair is skipped, as its trials would all
            fail — the drag-link's sheet tried 400 000 trees, most of them too large."""
            if (shape, both) not in floors:
                least = notes_floor(nat.notes)
                foot = keep_out(f)[3] - field_of(f)[1]
                got = []
                for way, C in enumerate(cols):
                    if (ways[way][1] and ways[way][2]) != both:
                        continue
                    half = halves[way]
                    if shape == "accel-column" and half[0].w > TITLE + NOTES_STEP:
                        C, half = widen(way, math.floor(half[0].w / NOTES_STEP) * NOTES_STEP)
                    T, N = half
                    got.append((C.w, T.h + GAP + least + GAP + foot, T.w, T.h, N.w, least + GAP + foot))
                floors[shape, both] = None if not got else (
                    Leaf("column", min(g[0] for g in got), min(g[1] for g in got)),
                    (Leaf("tables", min(g[2] for g in got), min(g[3] for g in got)),
                     Leaf("notes", min(g[4] for g in got), min(g[5] for g in got))))
            return floors[shape, both]

        def _arranged_ways(mu, shape, best_fill, D, P, vgrids, agrids, both):
            found = None
            low = floor_of(shape, both)
            if low is None:
                return None
            # where even the least grids of either family leave no room (each grid's columns against
            # its rows), no pair does
            if PRUNED and not fits_field(tree(shape, P, D, least_leaf(vgrids.values()), least_leaf(agrids.values()),
                                              *low), W, H):
                return None
            for vc, vg in vgrids.items():
                for ac, ag in agrids.items():
                    if not PRUNED:
                        def size_with(C, half, vg=vg, ag=ag):
                            return extent(tree(shape, P, D, vg, ag, C, half))
                    elif not fits_field(tree(shape, P, D, vg, ag, *low), W, H):
                        continue            # no arrangement of this pair fits (``floor_of``)
                    else:
                        size_with = tree_sized(shape, P, D, vg, ag)
                    for way, C in enumerate(cols):
                        if (ways[way][1] and ways[way][2]) != both:
                            continue
                        half = halves[way]
                        notes_w = TITLE
                        if shape == "accel-column" and half[0].w > TITLE + NOTES_STEP:
                            # the notes under the tables as wide as they are (the column's width)
                            notes_w = math.floor(half[0].w / NOTES_STEP) * NOTES_STEP
                            C, half = widen(way, notes_w)
                        tw, th = size_with(C, half)
                        if th > H + 1e-9 and tw < W - NOTES_STEP:
                            # too tall, room across: the notes wrapped wider (``widened``) — or,
                            # not ``wide``, only noted where that would make the room
                            w_ = widened(half[1].w if shape in SPLIT else C.w, W - tw)
                            # the tree no lower than by what its column (notes' leaf) loses: first
                            # at the field's width (once a table arrangement), then at ``w_``
                            C_, half_ = widen(way, W)
                            if w_ is not None and th - lowered(shape, C, half, C_, half_) <= H + 1e-9:
                                C_, half_ = widen(way, w_)
                            if w_ is not None and th - lowered(shape, C, half, C_, half_) <= H + 1e-9:
                                tw_, th_ = size_with(C_, half_)
                                if not wide:
                                    if th_ <= H + 1e-9:
                                        near.append(dict(mu))
                                else:
                                    C, half, tw, th, notes_w = C_, half_, tw_, th_, w_
                        if tw <= W + 1e-9 and th <= H + 1e-9:
                            if not best_fill:
                                return (0.0, vc, ac, way, notes_w)
                            fill = min(W / tw, H / th)
                            if found is None or fill > found[0] + 1e-9 or (
                                    fill > found[0] - 1e-9 and waste[way] < waste[found[3]] - 1.0):
                                found = (fill, vc, ac, way, notes_w)
            return found

        widths: dict[tuple, tuple] = {}

        def lowered(shape: str, C: Leaf, half, C_: Leaf, half_) -> float:
            """How much lower the column (the split's notes) is widened."""
            return (half[1].h - half_[1].h) if shape in SPLIT else C.h - C_.h

        def widen(way: int, wide: float) -> tuple[Leaf, tuple[Leaf, Leaf]]:
            """The column and the split's halves of table arrangement ``way`` with the notes
            ``wide`` mm wide (remembered)."""
            if (way, wide) not in widths:
                parts, under, over = ways[way]
                widths[way, wide] = (column_leaf(f, tabs, parts, nat.notes_height, under=under, notes=wide, over=over)[0],
                                     split_leaves(f, tabs, parts, nat.notes_height, under=under, notes=wide, over=over)[:2])
            return widths[way, wide]

        for shape in SHAPES:
            current: dict[str, float] = {}

            def fits(m, s=shape, current=current) -> bool:
                ok = arranged(m, s) is not None
                if ok:                      # choose_levels takes every trial that fits: the scales now
                    current.update(m)
                return ok

            def balanced(name: str, bigger: float, current=current) -> bool:
                """A family grows past its target only up to ``BALANCE`` times the smallest of the
                others (an acceleration plan twice its target beside 25-mm velocity plans takes the
                room they could grow into)."""
                others = [nat.families[fam].rel(current[fam]) for fam in FAMILIES
                          if fam != name and (fam != "acceleration" or has_a)]
                return not others or nat.families[name].rel(bigger) <= max(1.0, BALANCE * min(others)) + 1e-9
            balanced_mu = choose_levels(nat.families, fits, ("velocity", "position", "acceleration"), balanced)
            for mu in (balanced_mu, position_first(nat, fits, balanced)):
                if mu is None:
                    continue
                k_d, D_k = k_diagrams, D
                if not legible(nat, mu) and k_diagrams == 1.0:
                    found = legible_where_room(dr, nat, mu, lambda m, d, s=shape: arranged(m, s, D=d) is not None)
                    if found is not None:
                        mu, k_d = found
                        D_k = Leaf("diagrams", *diagrams_size(dr, nat, k_d))
                first = score_of(mu, k_d, factor, shape)
                before = sizes_of(nat, mu, k_d)
                mu = into_room(nat, mu, lambda m, s=shape, d=D_k: arranged(m, s, D=d) is not None)
                _, vc, ac, way, notes_w = arranged(mu, shape, best_fill=True, D=D_k)
                parts, under, over = ways[way]
                counts = tuple(len(g) for g in split(tabs[1:-1] if under and over else tabs[:-1] if under
                                                     else tabs[1:] if over else tabs, parts))
                cands.append((first, before, score_of(mu, k_d, factor, shape, True, not (under and over)),
                              Plan(mu, k_d, factor, shape, vc, ac, parts, 1, counts, notes=notes_w, under=under,
                                   over=over)))
    if not cands:
        return None
    # the composition chosen by the series' steps; then, the room given out (``into_room``), the best
    # of those whose every drawing is at least as large as it drew them (the shaper's velocity plans
    # grown to 50 mm in another shape by an acceleration plan shrunk from 87 to 58 mm are not better)
    least = max(cands, key=lambda c: _order(c[0], even))[1]
    better = [(c[2], -i, c[3]) for i, c in enumerate(cands)
              if all(a >= b - 1e-9 for a, b in zip(sizes_of(nat, c[3].mu, c[3].diagrams), least))]
    score, _, plan_ = max(better, key=lambda c: (_order(c[0], even), c[1]))
    # LAYOUT.md: no big empty areas. Where the chosen composition leaves a blank in its tables'
    # column (``largest_blank``: the jaw crusher's "stacked" column, 250 × 92 mm between its tables
    # and its notes), another whose blank there is smaller by a 50-mm square or more wins where it
    # draws the position plan, the smallest family and the drawings counted per drawing no smaller
    # (the series' guard above, every drawing at least as large, still holds for the others)
    D_of = lambda p_: Leaf("diagrams", *diagrams_size(dr, nat, p_.diagrams))    # noqa: E731
    blank = largest_blank(nat, f, plan_, D_of(plan_))
    if blank > 0.0:
        roomier = [(c[2], -i, c[3]) for i, c in enumerate(cands)
                   if all(a >= b - 1e-9 for a, b in zip(c[2][:4], score[:4]))
                   and largest_blank(nat, f, c[3], D_of(c[3])) < blank - BLANK_MM ** 2]
        if roomier:
            score, _, plan_ = max(roomier, key=lambda c: (_order(c[0], even), c[1]))
    return score, plan_


BLANK_MM = 50.0       # a zone's blank counts where both its sides are at least this long (a teacher sees it)


def _blank_rect(w: float, h: float) -> float:
    """The area of a blank rectangle w × h mm, counted where both its sides reach ``BLANK_MM``."""
    return w * h if min(w, h) >= BLANK_MM - 1e-9 else 0.0


def largest_blank(nat: Natural, f: Form, p: Plan, D: Leaf) -> float:
    """The largest blank rectangle (mm², ``_blank_rect``) one sheet's composition ``p`` leaves in the
    region of its tables' column (the boxes of the column, or of the split column's tables and
    notes), by the arithmetic of ``tree``, ``arrange`` and ``place_tables``: the region less the
    tables as placed, the notes over the title block, the title block and any drawing centred in a
    box there — so a blank that runs from under a shorter column of tables into the room over the
    notes counts whole (the eight-bar's 202 × 104 mm beside its acceleration plan). The column is
    the one zone with no scale to grow into its room; a drawing's box beyond the drawing elsewhere
    is the series' step (LAYOUT.md: fine) and is not counted."""
    from graphplan.drawing.layout import arrange
    from graphplan.sheets.compose import keep_out
    tabs = [Leaf(name, w, h) for name, w, h in nat.tables[p.tables]]
    C, groups, width = column_leaf(f, tabs, p.parts, nat.notes_height, p.counts, p.under, p.notes, p.over)
    T, N, groups_ = split_leaves(f, tabs, p.parts, nat.notes_height, p.counts, p.under, p.notes, p.over)
    split_ = p.shape in SPLIT
    if split_:
        groups, width = groups_, N.w
    P = nat.leaf("position", p.mu["position"])
    V = [nat.families["velocity"].leaf(p.mu["velocity"], "", i) for i in range(nat.count["velocity"])]
    A = [nat.families["acceleration"].leaf(p.mu["acceleration"], "", i) for i in range(nat.count["acceleration"])]
    vg = Grid(V, p.vcols, fitted=True) if V else None
    ag = Grid(A, p.acols, fitted=True) if A else None
    boxes = list(arrange(tree(p.shape, P, D, vg, ag, C, (T, N)), field_of(f)))
    own = [b for leaf, b in boxes if leaf is C or leaf is T or leaf is N]
    if not own:
        return 0.0
    region = (min(b[0] for b in own), min(b[1] for b in own), max(b[2] for b in own), max(b[3] for b in own))
    tab_box = next(b for leaf, b in boxes if leaf is (T if split_ else C))
    notes_at = next(b for leaf, b in boxes if leaf is (N if split_ else C))[2]
    foot = keep_out(f)
    ink = [q.box for q in place_tables(groups, tab_box[2], tab_box[3], p.under, p.over)]
    ink += [(notes_at - width, foot[3], notes_at, foot[3] + nat.notes_height(width)), foot]
    for leaf, (x0, y0, x1, y1) in boxes:         # drawings in the region (an acceleration plan beside the notes)
        if leaf not in (C, T, N):
            cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
            ink.append((cx - leaf.w / 2, cy - leaf.h / 2, cx + leaf.w / 2, cy + leaf.h / 2))
    return _empty_rect(region, ink)


BLANK_CELL = 5.0      # mm: the grid a blank is measured on


def _empty_rect(region, ink) -> float:
    """The largest rectangle (mm², ``_blank_rect``) of ``region`` that meets none of the ``ink``
    boxes, on a ``BLANK_CELL`` grid (the histogram method: each row's run of free cells above)."""
    x0, y0, x1, y1 = region
    nx, ny = int((x1 - x0) // BLANK_CELL), int((y1 - y0) // BLANK_CELL)
    if nx <= 0 or ny <= 0:
        return 0.0
    free = [[True] * nx for _ in range(ny)]
    for b in ink:
        i0, i1 = max(0, int((b[0] - x0) // BLANK_CELL)), min(nx, int(math.ceil((b[2] - x0) / BLANK_CELL)))
        j0, j1 = max(0, int((b[1] - y0) // BLANK_CELL)), min(ny, int(math.ceil((b[3] - y0) / BLANK_CELL)))
        if i1 <= i0:
            continue
        for j in range(j0, j1):
            free[j][i0:i1] = [False] * (i1 - i0)
    best, h = 0.0, [0] * nx
    for row in free:
        h = [hh + 1 if f_ else 0 for hh, f_ in zip(h, row)]
        stack: list[tuple[int, int]] = []
        for i in range(nx + 1):
            cur, start = (h[i] if i < nx else 0), i
            while stack and stack[-1][1] >= cur:
                s0, hh = stack.pop()
                best = max(best, _blank_rect((i - s0) * BLANK_CELL, hh * BLANK_CELL))
                start = s0
            stack.append((start, cur))
    return best


def sizes_of(nat: Natural, mu: dict[str, float], k_diagrams) -> tuple[float, ...]:
    """What a candidate draws: its families' principal segments and the diagrams' size factor."""
    return tuple(nat.drawn(fam, mu[fam]) for fam in FAMILIES) + (min(factors(k_diagrams)),)


def into_room(nat: Natural, mu: dict[str, float], fits) -> dict[str, float]:
    """The room the series' steps leave given to the velocity and acceleration plans (LAYOUT.md: each
    drawing as large as its zone holds): the series doubles a plan from 0.02 to 0.01, so a press's
    velocity plans stayed at p_v a = 42 mm beside a third of the sheet empty where seed 000 draws
    55 mm. The smaller family (against its target) is grown first, a step at a time, to the next of
    ``larger_choices`` (GOST 2.302's 1.5, 7.5 × 10^k between the series' steps, or the lab's own:
    p_v a chosen 5 mm longer, μ = v_A / p_v a) while ``fits(μ)`` and up to ``BALANCE`` times the
    least-grown family's share (at least the target); then a round coefficient where it draws at
    least ``ROUND_SHARE`` of the grown one (the force sheet's lever likewise)."""
    from graphplan.graphic.scales import ROUND_SHARE, larger_choices, on_round
    fams = nat.families
    grown_ = [fam for fam in ("velocity", "acceleration") if nat.count[fam] > 0]
    mu = dict(mu)
    live = list(grown_)
    while live:
        fam = min(live, key=lambda name: fams[name].rel(mu[name]))
        others = [fams[o].rel(mu[o]) for o in FAMILIES if o != fam and (o == "position" or nat.count[o] > 0)]
        cap = fams[fam].target * max(1.0, BALANCE * min(others, default=1.0))
        nxt = larger_choices(fams[fam].principal, mu[fam], cap)
        if nxt and fits({**mu, fam: nxt[0][0]}):
            mu[fam] = nxt[0][0]
        else:
            live.remove(fam)
    for fam in grown_:
        if not on_round(mu[fam]):
            fam_ = fams[fam]
            rounds = [m for m, rnd in larger_choices(fam_.principal, mu[fam] * 2.0, fam_.drawn(mu[fam])) if rnd]
            good = [m for m in rounds if fam_.drawn(m) >= ROUND_SHARE * fam_.drawn(mu[fam]) - 1e-9 and m >= mu[fam]]
            if good and readable(fam_, min(good)):
                mu[fam] = min(good)
    return mu


def _order(score: tuple, even: bool) -> tuple:
    """A candidate's score as compared: (legible, main, smallest, product, …), or with ``even`` and
    nothing legible the smallest plan's size before the position plan's."""
    return score[:1] + score[2:3] + score[1:2] + score[3:] if even and not score[0] else score


MAIN = 1.0     # the position plan, the sheet's main drawing, grows first up to this share of its target


def main_rel(nat: Natural, mu: dict[str, float]) -> float:
    """How large the position plan is drawn against its target, up to ``MAIN`` (the composition
    prefers a larger one before any other drawing grows)."""
    return round(min(nat.families["position"].rel(mu["position"]), MAIN), 6)


def position_first(nat: Natural, fits, balanced) -> dict[str, float] | None:
    """The scales where the position plan, the sheet's main drawing (LAYOUT.md), is given its room
    first: the velocity and acceleration plans just legible (``_legible``), the position plan grown
    from the smallest common size while the composition fits, up to ``MAIN`` of its target; then
    every family grown in turn as ``choose_levels`` does. None where the legible plans leave no room."""
    fams = nat.families
    mu = {fam: just_legible(fams[fam]) if fam != "position" else fams[fam].start(FACTORS[-1]) for fam in fams}
    if not fits(mu):
        return None
    while True:
        bigger = finer(mu["position"])
        if fams["position"].rel(bigger) > MAIN + 1e-9 or not fits({**mu, "position": bigger}):
            break
        mu["position"] = bigger
    return choose_levels(fams, fits, ("velocity", "position", "acceleration"), balanced, start=mu)


def legible_where_room(dr: Drafter, nat: Natural, mu: dict[str, float], fits
                       ) -> tuple[dict[str, float], float] | None:
    """The plans made legible where the sheet has the room (docs/scenes.md: the crank pin's p_v a
    and π a at least ``LEGIBLE_MM``; ``readable``): each family of plans drawn shorter is given a
    scale that draws it legibly and still ``fits(μ, diagrams' leaf)``, the other families as they
    are — first a round one, GOST 2.302's 1:15 and 1:75 between the series' steps or the series'
    next; else the lab's own (REFERENCE §3, seed 004): p_v a chosen, the longest multiple of 5 mm
    from ``LEGIBLE_MM`` up that fits, μ = v_A / p_v a (the six-bar's μv 0.02 drew p_v a 37.7 mm in
    cells twice as large; the series' next, 0.01, would need twice the room). The diagrams keep
    their size, or give a step (0.8) where only that makes the room. The scales and the diagrams'
    size factor, or None where none fits (one sheet then holds the plans smaller: LAYOUT.md's
    last resort)."""
    from graphplan.graphic.scales import chosen_length, legible_values
    for k in DIAGRAM_SIZES[:2]:
        if k != 1.0 and not dr.diagrams_right(k):
            continue
        D = Leaf("diagrams", *diagrams_size(dr, nat, k))
        out = dict(mu)
        for name in ("velocity", "acceleration"):
            fam = nat.families[name]
            if nat.count[name] == 0 or readable(fam, out[name]):
                continue
            nxt = finer(out[name])
            found = next((v for v in legible_values(out[name], nxt)
                          if readable(fam, v) and fits({**out, name: v}, D)), None)
            if found is None:
                lengths = [LEGIBLE_MM + 5.0 * j for j in range(int((fam.drawn(nxt) - LEGIBLE_MM) // 5.0) + 1)]
                fitting = [m for m in (chosen_length(fam.principal, n, LEGIBLE_READS) for n in lengths)
                           if m < out[name] and fits({**out, name: m}, D)]
                found = min(fitting) if fitting else None
            if found is None:
                break
            out[name] = found
        else:
            return out, k
    return None


def readable(fam: Family, mu: float) -> bool:
    """Whether a family of plans reads at μ: its principal segment (p_v a, π a) at least
    ``LEGIBLE_MM`` long, or its largest plan at least ``PLAN_MM`` across — where the crank pin's
    vector is the plan's short one (a rocker swinging fast beside a short crank), p_v a that long
    would draw every plan a sheet wide, one plan a sheet."""
    if fam.drawn(mu) >= LEGIBLE_MM - LEGIBLE_READS - 1e-9:      # reads 40.0 on the ruler
        return True
    k = fam.mu0 / mu
    return max((max(gw, gh) * k for gw, gh, _, _ in fam.sizes), default=0.0) >= PLAN_MM - 1e-9


def legible(nat: Natural, mu: dict[str, float]) -> bool:
    """Whether the plans read (``readable``) at the scales ``mu``."""
    return readable(nat.families["velocity"], mu["velocity"]) and (
        nat.count["acceleration"] == 0 or readable(nat.families["acceleration"], mu["acceleration"]))


STACKED = (1, 2)    # a set's last tables tried over the notes where the notes would take a sheet alone


def set_tail(tables: list[Leaf], notes: Leaf, stacked: int = 0, beside: tuple[int, ...] = ()) -> list:
    """A set's tables and notes in reading order (``set_rows``' tail): one after another, or the
    last ``stacked`` tables side by side over the notes as one block — a shelf sets its items in
    lines each as high as its tallest, so the notes, 125 mm high, found no room under Tables 3 and 4
    beside Table 2 on the eight-bar's A3 sheet 5 (stop 52) and took sheet 6 alone — and the first
    tables as one block in lines of ``beside``'s counts, one line over another (``(1, 1)``: Table 1
    over Table 2), which stands beside the last acceleration plan as one item of its row: the row
    is as high as the plan or the block, so Table 2 goes under Table 1 beside the plan, not on the
    next sheet (the blind review's A3 coupler-slider set: sheet 4 held its plan and Table 1 over an
    empty lower half; ``beside_tables`` decides). The order is kept: the block's lines read left to
    right, top to bottom, and the rest follows it."""
    from graphplan.drawing.layout import Row, Stack
    out = list(tables) + [notes]
    free = len(tables)
    if 0 < stacked <= len(tables):
        last = tables[-stacked:]
        out = list(tables[:-stacked]) + [Stack([Row(last) if len(last) > 1 else last[0], notes])]
        free -= stacked
    if len(beside) > 1 and all(k > 0 for k in beside) and sum(beside) <= free:
        lines, at = [], 0
        for k in beside:
            lines.append(Row(list(out[at:at + k])) if k > 1 else out[at])
            at += k
        block = Stack(lines)
        block.beside = True          # ``set_rows`` opens it again where the tail is a shelf of its own
        out = [block] + out[at:]
    return out


def _opened(tail: list) -> list:
    """The tail with ``set_tail``'s block beside the plan opened into its tables: a shelf breaks a
    row of its own into lines itself, and the block is for the last plan's row only."""
    out = []
    for item in tail:
        if getattr(item, "beside", False):
            for line in item.children:
                out.extend(line.children if isinstance(line, Row) else [line])
        else:
            out.append(item)
    return out


def _set_rows(nat: Natural, mu: dict[str, float], dsize, factor: float, width: float, after: bool = False,
              notes: float = TITLE, sized=None, stacked: int = 0, beside: tuple[int, ...] = ()) -> list[list[Leaf]]:
    """A set's drawings and tables as rows in reading order: the position plan and the diagrams,
    the velocity plans as many equal cells to a row as the sheet's width holds, the acceleration
    plans likewise, the tables and the notes (rows wrap where too wide). ``sized``: where given,
    (family, μ) → the cell's (w, h) and width → the notes' height, remembered by the caller (the
    same answers as ``nat``'s; ``set_of_sheets`` asks them some 10 000 times)."""
    cell_of, notes_of = sized[:2] if sized else ((lambda fam, m: nat.families[fam].size(m)),
                                                  (lambda w: set_notes_height(nat.notes, w)))
    own_of = sized[2] if sized and len(sized) > 2 else (
        lambda fam, m: tuple(nat.families[fam].size(m, i) for i in range(nat.count[fam])))
    grids = {}
    for fam in ("velocity", "acceleration"):
        # each plan its own size: in cells as large as the largest (p_v b 106 × 94 mm where most are
        # 62–79 mm across and 24–85 high) LINK59's and the Watt's A3 sets put 3–4 velocity plans on
        # a sheet, the four-bar's sheet 3 four plans 17 % drawn on (stop 60)
        grids[fam] = [Leaf(f"{fam} {i}", w, h) for i, (w, h) in enumerate(own_of(fam, mu[fam]))]
    return set_rows(Leaf("position", *cell_of("position", mu["position"])), Leaf("diagrams", *dsize), grids["velocity"],
                    grids["acceleration"], set_tail([Leaf(name, w, h) for name, w, h in nat.tables[factor]],
                                                    Leaf("notes", notes, notes_of(notes)), stacked, beside), width,
                    after)


def set_rows(P: Leaf, D: Leaf, V: list[Leaf], A: list[Leaf], tail: list[Leaf], width: float,
             after: bool = False) -> list[list[Leaf]]:
    """A set's drawings and tables as rows in reading order: the position plan and the diagrams
    side by side where the sheet's width holds both (else the position plan, the velocity plans
    under it, then the diagrams: no sheet holds a position plan alone), the velocity plans as many
    equal cells to a row as the width holds, the acceleration plans likewise, their last row
    (unpadded) followed by the tables and the notes — a lone acceleration plan shares its sheet
    with the tables instead of taking one for itself; or, where the diagrams stand in a row of
    their own, the acceleration plans beside them where that row holds them."""
    def grid(cells_: list[Leaf]) -> list[list[Leaf]]:
        """The plans as one row that ``flow`` wraps where the room ends (a row cut short by the title
        block or a sheet's foot goes on in the next line, not as a line of its own: the six-bar's A3
        set put two velocity plans beside the title block and the other two of that row alone atop
        the next sheet) — each plan its own size, a line as high as its tallest (equal cells as
        large as the largest plan left LINK59's A3 sheets 2–4 three or four plans each, 27–39 %
        drawn on); equal cells padded so the last line's columns line up with the full lines'."""
        if not cells_:
            return []
        if any((c.w, c.h) != (cells_[0].w, cells_[0].h) for c in cells_):
            return [list(cells_)]
        k = max(1, int((width + GAP) // (cells_[0].w + GAP)))
        c = cells_[0]
        return [list(cells_) + [Leaf("", c.w, c.h) for _ in range(k - 1)]]
    if P.w + GAP + D.w <= width + 1e-9:
        rows = [[P, D]] + grid(V)
    else:
        # the first velocity plans beside the position plan where its row has room for them (the
        # six-bar's A3 plan 245 mm wide left 134 mm of its 163-mm row empty): a grid as many
        # columns as fit across and rows as fit its height, read on in the rows under it
        first: list[list[Leaf | Grid]] = [[P]]
        if V:
            k, c = _beside(P, V, width)
            if k:
                first, V = [[P, Grid(V[:k], c, fitted=True)]], V[k:]
        if after:                   # the plans first, the diagrams on a sheet of their own before the tables
            return first + grid(V) + grid(A) + [[D], Shelf(_opened(tail))]
        if A and D.w + sum(GAP + a.w for a in A) <= width + 1e-9 and max(a.h for a in A) <= D.h + 1e-9:
            # the acceleration plans beside the diagrams where the row holds them, no taller (the
            # V-compressor's A2 left 230 × 280 mm beside its diagrams empty, the plan on the next sheet)
            return first + grid(V) + [[D] + list(A), Shelf(_opened(tail))]
        rows = first + grid(V) + [[D]]
    rows += grid(A)
    if A:
        # a shelf (``flow`` breaks it into the lines, or a line of columns, that put the most on the
        # sheet): row by row, the last line's Table 4 and notes took a sheet of their own (stop 59)
        last = [c for c in rows[-1] if c.name] + tail
        rows[-1] = Shelf(last) if len(last) <= SHELF_MOST else last
    else:
        rows.append(Shelf(_opened(tail)))     # the tables and notes a row of their own: broken to fill the sheet
    return rows


_BESIDE: dict[tuple, tuple[int, int]] = {}


def _beside(P: Leaf, V: list[Leaf], width: float) -> tuple[int, int]:
    """How many of the first velocity plans stand beside the position plan, and in how many columns:
    the most whose grid (each column as wide as its widest plan, each row as high as its tallest:
    ``Grid.fitted``) fits the room across beside the plan and its height, read row by row (once per
    sizes: a set's search lays its rows out thousands of times)."""
    key = (P.w, P.h, width, tuple((v.w, v.h) for v in V))
    if key in _BESIDE:
        return _BESIDE[key]
    room = width - P.w - GAP + 1e-9
    best = (0, 0)
    for c in range(1, len(V) + 1):
        most = 0
        for k in range(c, len(V) + 1):        # a plan more never makes the grid smaller
            w, h = extent(Grid(V[:k], c, fitted=True))
            if w > room or h > P.h + 1e-9:
                break
            most = k
        if most > best[0]:
            best = (most, c)
        if not most:
            break                             # c plans do not fit across: more columns do not either
    if len(_BESIDE) > 10_000:
        _BESIDE.clear()
    _BESIDE[key] = best
    return best


def grid_rows(cells_: list[Leaf], k: int) -> list[list[Leaf]]:
    """Equal cells k to a row, the last row filled up with empty cells so the columns line up."""
    rows = [cells_[j:j + k] for j in range(0, len(cells_), k)]
    if rows and len(rows) > 1 and len(rows[-1]) < k:
        c = rows[-1][0]
        rows[-1] = rows[-1] + [Leaf("", c.w, c.h) for _ in range(k - len(rows[-1]))]
    return rows


def just_legible(fam: Family) -> float:
    """The coarsest μ at which the family's plans read: the series' (``_legible``) or the lab's own,
    p_v a (π a) chosen ``LEGIBLE_MM`` long (``legible_where_room``), whichever draws them smaller."""
    from graphplan.graphic.scales import chosen_length
    own = chosen_length(fam.principal, LEGIBLE_MM, LEGIBLE_READS)
    return max(_legible(fam), own if readable(fam, own) else 0.0)


def _legible(fam: Family) -> float:
    """The coarsest standard μ at which the family's plans read (``readable``)."""
    mu = fam.start(1.0)
    while not readable(fam, mu):
        mu = finer(mu)
    while readable(fam, coarser(mu)):
        mu = coarser(mu)
    return mu


def room(f: Form, later: bool = False) -> tuple[float, ...]:
    """Where one drawing fits an empty sheet of the format: (the field's width, its height over the
    title block, the width beside the title block, the field's height), mm — ``later``: a set's
    later sheet, whose title block is form 2a (15 mm high, not 55)."""
    from graphplan.sheets.compose import keep_out, later_keep
    region = field_of(f)
    keep = later_keep(f) if later else keep_out(f)
    height = region[3] - region[1]
    return (region[2] - region[0], keep[1] + height - keep[3], keep[0] - region[0], height)


def room_fits(r: tuple[float, ...], w: float, h: float) -> bool:
    """Whether a w × h drawing fits the room ``r`` (``room``): across the field over the title
    block, or beside the title block the field's full height."""
    return (w <= r[0] and h <= r[1]) or (w <= r[2] and h <= r[3])


def set_diagrams(dr: Drafter, nat: Natural, r: tuple[float, ...]) -> list[float | tuple[float, float]]:
    """The diagrams' sizes a set tries: each length factor of ``DIAGRAM_SIZES`` whose block fits an
    empty sheet (``room_fits`` the room ``r``) drawn with its one factor (the block may then share a
    sheet), and the longest that the sheet's width holds drawn as tall as an empty sheet holds it —
    the height factor the largest from ``HEIGHTS`` (the A3 set's diagrams at one factor 0.5 drew
    s 32 mm high and L 120 mm over a sheet half empty; length and height grown together, 0.8 missed
    the sheet by 10 mm). The next length is tried where that drawing is qualitatively wrong. μs
    stays a standard value, H1, H2 whole mm within the lab's (``first_options``)."""
    out: list[float | tuple[float, float]] = []
    tall_found = False
    for k in DIAGRAM_SIZES:
        w, h = diagrams_size(dr, nat, k)
        if w > r[0] + 1e-9:
            continue                        # too long for the sheet whatever its height
        if room_fits(r, w, h):
            out.append(k)
        if tall_found:
            continue
        # the height chosen on the first drawing (a redrawing keeps near it: graphic.redraw); where
        # that one is redrawn, also the tallest as finally drawn (a taller first drawing may be
        # redrawn with the lab's smallest poles to fit, flat — the crank-slider's v 15 mm high —;
        # ``drawn_share`` weighs them)
        talls = [tallest(lambda t, k=k: room_fits(r, *dr.first_size((k, t))))]
        if talls[0] is None or dr.redrawn((k, talls[0])):
            talls.append(tallest(lambda t, k=k: room_fits(r, *diagrams_size(dr, nat, (k, t)))))
            if talls[0] is not None:
                # … and the tallest under it drawn as first chosen, within ``LEAST_TALLER`` steps (the
                # long rocker's A2 s allowance 100 mm was redrawn with H1 20 mm, v 54 mm high; 88 mm
                # draws s, v, a 78, 98, 79 mm as first chosen)
                talls += next(([t] for t in (round(talls[0] - j * HEIGHT_STEP, 6) for j in range(1, LEAST_TALLER + 1))
                               if t > k + 1e-9 and not dr.redrawn((k, t))), [])
        for tall in dict.fromkeys(talls):
            if tall is not None and room_fits(r, *diagrams_size(dr, nat, (k, tall))):
                out.append((k, tall))
                tall_found = tall_found or dr.diagrams_right((k, tall))
        if k in out and flat(dr, k) and tall_found:
            # the one factor draws a diagram flat (the shaper's A2 v 38 mm): the least taller one that
            # does not, where it is lower than the tallest (a block that may still share its sheet)
            for t in (round(k + j * HEIGHT_STEP, 6) for j in range(1, LEAST_TALLER + 1)):
                if t >= max(x[1] for x in out if isinstance(x, tuple)) - 1e-9:
                    break
                if room_fits(r, *diagrams_size(dr, nat, (k, t))) and not flat(dr, (k, t)):
                    out.append((k, t))
                    break
    return out or list(DIAGRAM_SIZES[-1:])


def tallest(fits, low: float = HEIGHTS[-1], high: float = HEIGHTS[0], step: float = HEIGHT_STEP) -> float | None:
    """The largest height factor from ``low`` to ``high`` in steps of ``step`` that ``fits`` (bisection:
    a block's height grows with its factor), or None where not even ``low`` does."""
    n = int(round((high - low) / step))
    if not fits(low):
        return None
    lo, hi = 0, n + 1                       # fits(low + lo·step); not known to fit from hi on
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if fits(round(low + mid * step, 6)):
            lo = mid
        else:
            hi = mid
    return round(low + lo * step, 6)


def page_fill(page, region, sizes: dict[str, tuple[float, float]] | None = None) -> float:
    """The share of the field a laid-out sheet's drawings take: their own sizes within their boxes
    (``sizes``: name → each plan's own size, where its cell is the family's largest plan's; a row's
    spare width shared out is not drawn on)."""
    sizes = sizes or {}
    area = 0.0
    for leaf, b in page:
        if leaf.name:
            w, h = sizes.get(leaf.name, (leaf.w or b[2] - b[0], leaf.h or b[3] - b[1]))
            area += min(w, b[2] - b[0]) * min(h, b[3] - b[1])      # drawn, not the spare shared out
    return area / ((region[2] - region[0]) * (region[3] - region[1]))


def drawn_share(dr: Drafter, k) -> float:
    """How large the diagrams of size ``k`` are drawn: half the log of L × the geometric mean of the
    s, v, a diagrams' heights over the same at factor 1 (k's log where length and height grow
    together; a flat diagram counts: v 15 mm high under s 32 mm reads worse than both at 25)."""
    def size(k) -> float:
        L, *heights = dr.drawn(k)
        return L * math.prod(max(h, 1.0) for h in heights) ** (1 / 3)
    return math.log(size(k) / size(1.0)) / 2


def flat(dr: Drafter, k) -> int:
    """1 where a diagram of size ``k`` is drawn lower than ``DIAGRAM_MM`` (with its axis): a set,
    which has a sheet for its diagrams, weighs that like one more sheet (the crank-slider's A3 set
    drew v 26 mm and a 22 mm high under s 64 mm; the lab's model, whose poles are given, a 15.5 mm
    at L 240 mm where L 154 mm draws it 38 mm)."""
    from graphplan.sheets.kinematics import DIAGRAM_MM
    return int(min(dr.drawn(k)[1:]) < DIAGRAM_MM - 1e-6)


SPARSE = 0.25      # of as many sheets, a set none of whose sheets is drawn on less than this share of its
                   # field (the crank-slider's A3 acceleration plan, 145 mm, moved to the tables' sheet and
                   # left five velocity plans on 16 % of sheet 2; at 130 mm it shares their sheet; the
                   # shaper's A2 velocity plans at p_v a 75 mm, the acceleration plan on the tables' sheet,
                   # drew sheet 2 on 23 % where 0.2 let them: at 85 mm with it, 54 %)
SHORT_MM = 3.0     # a table's value read off a vector shorter than this reads poorly (0.5 mm of 2.5 is 20 %)


def short_vectors(dr: Drafter) -> dict[str, tuple[float, list[float]]]:
    """The vectors the tables 1–3 read their values from, as drawn at the plans' own scales: family
    → (that μ, the lengths, mm) — a value the ruler read at all (``kintables.judged``)."""
    from graphplan.report.plans import plans_json
    from graphplan.sheets.kintables import _length, judged, velocity_columns
    pl = dr.plans()
    doc = plans_json(pl)
    keys = velocity_columns(doc, dr.opts.precision)
    v = [_length(e) for pos in doc["positions"] for k in keys if (e := pos["velocity"].get(k)) and judged(e)]
    a = [_length(e) for pos in doc["positions"] for e in pos.get("acceleration", {}).values() if judged(e)]
    return {"velocity": (pl.mu_v, [x for x in v if x]), "acceleration": (pl.mu_a, [x for x in a if x])}


def lifted(nat: Natural, short: dict[str, tuple[float, list[float]]], mu: dict[str, float]) -> int:
    """1 where a table's value is read off a vector under ``SHORT_MM`` at ``mu`` that the family's
    largest set scale (``SET_LARGEST`` of its target) would draw at least that long — review 7: the
    four-bar's A3 set saved a sheet with its velocity plans at p_v a 40 mm, ω_AB read off 2.8 mm
    7.8 % wrong, where 50 mm on one more sheet reads it off 3.5 mm. A set weighs that like a sheet."""
    for fam, (mu0, lengths) in short.items():
        family = nat.families[fam]
        if not lengths or nat.count[fam] == 0:
            continue
        top = mu[fam] * family.rel(mu[fam]) / SET_LARGEST        # the μ that draws SET_LARGEST of the target
        now, most = mu0 / mu[fam], mu0 / min(top, mu[fam])
        if any(x * now < SHORT_MM - 1e-9 and x * most >= SHORT_MM - 1e-9 for x in lengths):
            return 1
    return 0


def set_of_sheets(dr: Drafter, nat: Natural, f: Form) -> Plan:
    """A set of sheets: the velocity and acceleration plans just legible, the position plan as large
    as a sheet holds (or a step or two smaller where that saves a sheet and its crank is still drawn
    ``CRANK_MM`` long: never crowded for fewer sheets), the drawings and tables
    flowing over the sheets in reading order — the fewest sheets (qualitatively wrong diagrams
    counted as one more: their larger size factor is taken where it is right; so is a sheet of the
    notes alone, the notes first wrapped wider to avoid it); then each family grown while the set
    needs no more sheets (up to ``SET_LARGEST`` times its target). The diagrams' sizes are
    ``set_diagrams``'; where they do not fit beside the position plan, both orders are tried (the
    diagrams before the acceleration plans, or after them on a sheet of their own); of as many
    sheets, the set whose drawings are larger, then whose emptiest sheet is fuller."""
    from graphplan.sheets.compose import keep_out, later_keep
    from graphplan.sheets.kintrial import counted, trial        # each distinct trial layout once
    region = field_of(f)
    width, height = region[2] - region[0], region[3] - region[1]
    keep, later = keep_out(f), later_keep(f)

    def alone(size) -> bool:              # fits an empty sheet beside or over the title block
        return room_fits(room(f), *size)
    fams = nat.families
    # the plans just legible as the lab chooses (``just_legible``: p_v a, π a 40 mm at μ = v_A / 40,
    # not only the series' next, twice the drawing: the six-bar's A3 velocity plans at 0.01 drew
    # p_v a 69 mm, four cells a row, three rows missing a sheet by 7 mm — sheets 27 % filled), then
    # grown in the steps ``larger_choices`` gives while the set needs no more sheets
    # … at the standard series' scales (review 58 #2): the coarsest of the series that reads (``_legible``)
    floor = {fam: _legible(fams[fam]) for fam in ("velocity", "acceleration")}
    def fitted(fam: str, mu: float) -> float:
        """The finest μ from ``mu`` on at which the family fits an empty sheet; a family no μ fits
        (a size that does not shrink: lettering alone, or no finite size) is refused in one line."""
        for _ in range(90):                     # 30 decades of the standard series
            if alone(fams[fam].size(mu)):
                return mu
            mu = coarser(mu)
        raise PlansUndrawable(f"the {fam} plans cannot be drawn on a {f.name} sheet at any scale (a plan of "
                             "directions nearly parallel?); the terminal's commands take --format none",
                             dr.st.mech.source if hasattr(dr, "st") else None)
    for fam in floor:                       # … unless a plan that large fits no sheet
        floor[fam] = fitted(fam, floor[fam])
    top = fitted("position", fams["position"].start(2.0))

    def grown(fam: str, mu: float) -> list[float]:
        """The velocity or acceleration plans' larger scales, smallest drawing first: the standard
        series' (``series_choices``; review 58 #2: the crank-rocker's A2 and A3 sets drew π a 145 mm
        at the lab's own 0.0272 (m/s²)/mm where the A1 draws 0.025)."""
        return set_steps(fams[fam].principal, mu, fams[fam].target)
    best = None
    short = short_vectors(dr)
    r = room(f, later=True)      # the diagrams go on a later sheet where they do not fit beside the plan
    # the notes' widths: the title block's, the room beside it, two columns of the title block's
    wide = tuple(sorted({TITLE, max(TITLE, r[2])})) + ((TWO_COLUMNS,) if TWO_COLUMNS <= width + 1e-9 else ())
    # each layout's answer once per call (the scene's sizes do not change within it: ``_checked``
    # corrects them between calls), keyed on the few numbers it is laid from — the shaper's A3 set
    # asked for the same layout again in about half of its 16 000 ``laid`` calls
    laid_memo: dict[tuple, tuple | None] = {}
    cells_memo: dict[tuple, tuple[float, float]] = {}
    notes_memo: dict[float, float] = {}

    def cell_of(fam: str, mu: float) -> tuple[float, float]:
        if (fam, mu) not in cells_memo:
            cells_memo[fam, mu] = fams[fam].size(mu)
        return cells_memo[fam, mu]

    own_memo: dict[tuple, dict[str, tuple[float, float]]] = {}
    counts = nat.count

    def own(mu) -> dict[str, tuple[float, float]]:
        """Each velocity and acceleration plan's own size at ``mu`` (its cell is the largest's)."""
        key = (mu["velocity"], mu["acceleration"])
        if key not in own_memo:
            own_memo[key] = {f"{fam} {i}": fams[fam].size(mu[fam], i) for fam in ("velocity", "acceleration")
                             for i in range(counts[fam])}
        return own_memo[key]

    def notes_of(w: float) -> float:
        if w not in notes_memo:
            notes_memo[w] = set_notes_height(nat.notes, w)
        return notes_memo[w]
    plans_memo: dict[tuple, tuple] = {}

    def own_of(fam: str, mu: float) -> tuple:
        if (fam, mu) not in plans_memo:
            plans_memo[fam, mu] = tuple(fams[fam].size(mu, i) for i in range(counts[fam]))
        return plans_memo[fam, mu]
    sizes = set_diagrams(dr, nat, r)
    read_off = {k: dr.diagrams(k).worst_pct() for k in sizes}
    for k in sizes:
        dsize = diagrams_size(dr, nat, k)
        misread = misread_diagrams(read_off, k)
        for factor, after in ((fa, af) for fa in (TABLES, 1.0) for af in (False, True)):
            def laid(mu, factor=factor, after=after, dsize=dsize):
                key = (mu["position"], mu["velocity"], mu["acceleration"], dsize, factor, after)
                if key not in laid_memo:
                    laid_memo[key] = _laid(mu, factor, after, dsize)
                return laid_memo[key]

            def _laid(mu, factor, after, dsize):
                """The set's pages at ``mu``: (count, notes alone on the last sheet, the notes'
                width, the tables stacked over them) — the notes wider where at the title block's
                width they would take a sheet of their own; where every width still leaves them
                alone, the last tables set over them (``set_tail``)."""
                found = None
                for stacked in (0,) + STACKED:
                    for nw in wide:
                        tried = counted(_set_rows(nat, mu, dsize, factor, width, after, nw, (cell_of, notes_of, own_of),
                                                  stacked), region, keep, later)
                        if tried is None:     # a drawing larger than a sheet: none; a stacked block too large:
                            if not stacked:   # the notes wrapped wider, which are lower (LINK57's A3 at 1:2:
                                return None   # Table 4 over the 198-mm notes is too tall for a sheet, over
                            continue          # the notes two columns wide it is not — they stood alone)
                        got = (*tried, nw, stacked)
                        orphan = got[1]
                        # the narrowest notes that take no more sheets (a sheet of the notes alone counted)
                        if found is None or got[0] + got[1] < found[0] + found[1]:
                            found = got
                        if not orphan and nw == wide[0]:
                            break
                    if not found[1]:
                        break
                return found

            def pages(mu):
                got = laid(mu)
                return None if got is None else got[0]
            if after and (fams["position"].size(top)[0] + GAP + dsize[0] <= width + 1e-9):
                continue                    # the diagrams beside the position plan: one order only
            for mu_l in (top, coarser(top), coarser(coarser(top))):
                mu = {"position": mu_l, **floor}
                count = pages(mu)
                if count is None:
                    continue
                for fam in ("velocity", "acceleration"):
                    # the largest of the steps that keeps the count: a step's cells may wrap a row onto
                    # another sheet where a larger one's fewer columns do not (the six-bar's velocity
                    # plans stopped at p_v a 55 mm, a 1.5-mm v_B read 30 % off, where 69 mm kept 6 sheets)
                    for bigger in grown(fam, mu[fam]):
                        if (got := pages({**mu, fam: bigger})) is not None and got <= count:
                            mu = {**mu, fam: bigger}
                while True:
                    bigger = finer(mu["position"])
                    if fams["position"].rel(bigger) > SET_LARGEST or pages({**mu, "position": bigger}) != count:
                        break
                    mu = {**mu, "position": bigger}
                _, orphan, nw, stacked = laid(mu)
                fill = trial(_set_rows(nat, mu, dsize, factor, width, after, nw, (cell_of, notes_of, own_of), stacked), region,
                             keep, later, own(mu))[2]      # the emptiest sheet's fill: laid out in full for the kept
                rel = sum(math.log(fams[fam].rel(mu[fam])) for fam in FAMILIES) + drawn_share(dr, k)
                # the first sheet keeps its main drawing (LAYOUT.md; the A1's ``main_larger``): a
                # crowded position plan — its crank shorter than CRANK_MM where a sheet holds a
                # larger plan — is never traded for fewer sheets (it weighed one sheet: LINK57's A3
                # set took 1:4, its twelve positions' labels piled up, for a sheet fewer than 1:2;
                # the A3 coulisse, whose crank is 28 mm at the largest, had been drawn at 1:10, 11 mm).
                # Then qualitatively wrong diagrams weigh like one more sheet: a larger drawing that
                # is right is taken where it costs a sheet at most; so do a diagram lower than
                # DIAGRAM_MM (``flat``) and a sheet holding the notes alone; of as many, the larger
                # drawings (then the fuller emptiest sheet); and a value read off a vector shorter
                # than SHORT_MM that larger plans would lift (``lifted``)
                wrong = 0 if dr.diagrams_right(k) else 1
                small = int(fams["position"].drawn(mu["position"]) < CRANK_MM - 1e-9 and mu["position"] > top)
                low = flat(dr, k)
                # of as many, no sheet of the notes alone: a shelf's columns fill a sheet with the
                # tables and can leave the notes to the next (LINK57's A3 sheet 5, stop 59)
                key = (small, count + wrong + orphan + low + misread + lifted(nat, short, mu), orphan, wrong,
                       low, int(fill < SPARSE), -(factor == TABLES), -round(rel, 6),
                       -round(fill, 1))
                if best is None or key < best[0]:
                    best = (key, Plan(mu, k, factor, "set", 1, 1, 1, count, after=after, notes=nw, stacked=stacked))
    if best is None:
        raise said_error(GraphplanError, "sh kin fit", None, None, form=f.name, option="--format")
    chosen = best[1]
    b = beside_tables(nat, chosen, diagrams_size(dr, nat, chosen.diagrams), f, own(chosen.mu))
    if b:
        chosen = replace(chosen, beside=b)
    return taller(dr, nat, chosen, lambda k: _laid_again(nat, chosen, diagrams_size(dr, nat, k), f))


MISREAD = 2.0      # a set's diagrams read this many times worse than at its best size tried …


def misread_diagrams(read_off: dict, k) -> int:
    """1 where the diagrams of size ``k`` read off worse than the lab's 5 % and ``MISREAD`` times worse
    than at the best size the set tries (``read_off``: size → the largest |δ|, % at the positions,
    ``Diagrams.worst_pct``): a set weighs that like one more sheet — a student given a sheet of
    their own for the diagrams draws them there, closer (the gate's A2 set, review 61, drew them
    12,8 % off at μψ 0,02 beside the plans where another size reads 5,65 %). Not where the best
    size itself reads off more than ``MISREAD`` times the lab's 5 %: there the method's own error
    dominates and no size reads close (the shaper's A2 set reads 13 % at best, 26 % at the size
    that keeps it on 2 sheets; the crusher's A3 11,9 % at best, 20,6 % at 0,5)."""
    from graphplan.graphic.diagrams import LAB_LIMIT
    best = min(read_off.values(), default=0.0)
    mine = read_off.get(k, 0.0)
    return int(mine > LAB_LIMIT and mine > MISREAD * best and best <= MISREAD * LAB_LIMIT)


def set_steps(principal: float, mu: float, target: float) -> list[float]:
    """The scales a set's velocity or acceleration plans grow to from ``mu``, the smallest drawing
    first: the standard series' (``series_choices``) that draw the principal segment at most
    ``SET_LARGEST`` times its ``target`` — and where the largest of them still draws it shorter than
    its target, the series' next value past them too. The series steps by 1.25 to 2 times: the
    agitator's A2 set drew π a 98.7 mm at 0.04 (m/s²)/mm, its target 120, because 0.025 draws
    158 mm, 6 mm past the cap — a sheet 46 % empty under its acceleration plan (stop 59)."""
    steps = series_choices(principal, mu, target * SET_LARGEST)
    last = steps[-1] if steps else mu
    if principal / last < target - 1e-9:
        past = [m for m in series_choices(principal, last, math.inf)]
        steps += past[:1]
    return steps


BESIDE_MOST = 4      # a set's first tables tried as one column beside the last acceleration plan: 2 … this many


def set_pages(nat: Natural, p: Plan, dsize, f: Form, beside: tuple[int, ...] | None = None) -> list | None:
    """The set's sheets as ``flow`` lays them at the plan's scales with diagrams of ``dsize`` (each a
    list of (leaf, box)); ``beside``: the plan's own unless given."""
    from graphplan.sheets.compose import keep_out, later_keep
    region = field_of(f)
    return flow(_set_rows(nat, p.mu, dsize, p.tables, region[2] - region[0], p.after, p.notes, stacked=p.stacked,
                          beside=p.beside if beside is None else beside),
                region, keep_out(f), later=later_keep(f), ragged=True)


def page_blank(page, region, keep, sizes: dict[str, tuple[float, float]] | None = None) -> float:
    """The largest blank rectangle (mm², ``_empty_rect``: both sides at least ``BLANK_MM``) of a laid
    sheet's field: off each drawing's and table's own size centred in its box (``sizes``: a plan's own
    size where its cell is the family's largest) and off the title block (``keep``)."""
    sizes = sizes or {}
    ink = [keep]
    for leaf, (x0, y0, x1, y1) in page:
        if not leaf.name:
            continue
        w, h = sizes.get(leaf.name, (leaf.w, leaf.h))
        w, h = min(w, x1 - x0), min(h, y1 - y0)
        cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
        ink.append((cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2))
    return _empty_rect(region, ink)


def set_blanks(pages, f: Form, sizes: dict[str, tuple[float, float]] | None = None) -> list[float]:
    """``page_blank`` of each sheet of a laid set (form 1's title block on the first, 2a's on the
    later ones)."""
    from graphplan.sheets.compose import keep_out, later_keep
    return [page_blank(page, field_of(f), keep_out(f) if n == 0 else later_keep(f), sizes)
            for n, page in enumerate(pages)]


def _lines(n: int, most: int):
    """The ways to set the first 2 … ``most`` of ``n`` items in two or more lines, in order: the
    lines' counts (``(1, 1)``, ``(2, 1)``, ``(1, 2)``, ``(1, 1, 1)`` …)."""
    def parts(m: int):
        if m == 0:
            yield ()
            return
        for k in range(1, m + 1):
            for rest in parts(m - k):
                yield (k,) + rest
    for m in range(2, min(most, n) + 1):
        yield from (c for c in parts(m) if len(c) > 1)


def beside_tables(nat: Natural, p: Plan, dsize, f: Form, sizes: dict[str, tuple[float, float]] | None = None
                  ) -> tuple[int, ...]:
    """The set's first tables as one block beside the last acceleration plan (``set_tail``): none
    (each an item of the row, as before), or the lines whose sheets — as many, no sheet of the notes
    alone — leave the smallest largest blank on a sheet before the last: the last sheet holds what
    is left, an earlier one half empty is room a table could have taken (the blind review's A3
    coupler-slider: sheet 4 held its acceleration plan and Table 1 over an empty lower half, Table 2
    on sheet 5; the crusher's A2 sheet 3 a 380 × 80 mm band). Taken where that blank is smaller by
    a ``BLANK_MM`` square or more; of as good, the fewest tables in the block."""
    n = len(nat.tables[p.tables]) - (p.stacked if 0 < p.stacked <= len(nat.tables[p.tables]) else 0)
    if not nat.count["acceleration"]:
        return ()

    def judged(b: tuple[int, ...]):
        pages = set_pages(nat, p, dsize, f, b)
        if pages is None:
            return None
        orphan = int(all(leaf.name in ("notes", "") for leaf, _ in pages[-1]))
        blanks = set_blanks(pages, f, sizes)
        return len(pages), orphan, max(blanks[:-1], default=0.0)
    first = judged(())
    if first is None or first[0] < 2:
        return ()
    best, got = (), first
    for b in _lines(n, BESIDE_MOST):
        tried = judged(b)
        if tried is None or tried[0] > first[0] or tried[1] > first[1]:
            continue
        if tried[2] <= got[2] - (BLANK_MM ** 2 if not best else 1.0):
            best, got = b, tried
    return best


def _laid_again(nat: Natural, p: Plan, dsize, f: Form) -> tuple[int, int] | None:
    """A set's pages at the plan's scales with diagrams of ``dsize``: (count, notes alone on the last)."""
    from graphplan.sheets.compose import keep_out, later_keep
    region = field_of(f)
    out = flow(_set_rows(nat, p.mu, dsize, p.tables, region[2] - region[0], p.after, p.notes, stacked=p.stacked,
                         beside=p.beside), region,
               keep_out(f), later=later_keep(f), ragged=True)
    return None if out is None else (len(out), int(all(leaf.name in ("notes", "") for leaf, _ in out[-1])))


def taller(dr: Drafter, nat: Natural, p: Plan, laid) -> Plan:
    """The set's diagrams drawn taller where its sheets hold them (``laid(k)``: the same count, no
    sheet of notes alone): each height factor from the chosen one up to ``HEIGHTS[0]`` in
    ``HEIGHT_STEP``, right, no flatter and drawn no smaller (or brought within the lab's 5 %), the
    one read closest to the exact values at the positions (graphic.redraw's largest |δ|), then drawn
    largest — review 5: the press's A2 set drew its
    diagrams at 0.8, a_B off by up to 11.9 % where its A1 sheet is off 6.7 %, sheet 2 34 % empty;
    s ≤ 80 mm at L 192 draws s, v, a 74, 103, 74 mm, off 4.2 %."""
    from graphplan.sheets.kinematics import diagram_options
    long_, tall = factors(p.diagrams)
    o = dr.opts

    def judged(k) -> tuple[float, float]:
        r = diagram_options(dr.st, k, o.positions, o.precision, dr.room, dr.floor)["redrawn"]
        return (round(r.off_after, 1) if r.off_after is not None else math.inf, -round(drawn_share(dr, k), 6))
    from graphplan.graphic.redraw import LAB_LIMIT
    best, score = p.diagrams, judged(p.diagrams)
    first_score = score
    if not dr.diagrams_right(p.diagrams):
        return p
    first = laid(p.diagrams)
    for j in range(1, int(round((HEIGHTS[0] - tall) / HEIGHT_STEP)) + 1):
        k = (long_, round(tall + j * HEIGHT_STEP, 6))
        if not dr.diagrams_right(k):
            continue
        got = judged(k)
        # drawn no smaller, or brought within the lab's 5 % (the crank-slider's A3 set: 5.5 → 4.8 %);
        # judged before the set is laid out again with it (none better: not laid)
        if got < score and (got[1] <= first_score[1] + 1e-9 or got[0] <= LAB_LIMIT < first_score[0]) \
                and flat(dr, k) <= flat(dr, p.diagrams) and laid(k) == first:
            best, score = k, got
    return p if best == p.diagrams else Plan(p.mu, best, p.tables, p.shape, p.vcols, p.acols, p.parts, p.sheets,
                                             p.counts, p.after, p.notes, stacked=p.stacked, beside=p.beside)
