"""Composing a sheet set: the frame and the title block of each sheet, the blocks placed in the free
field in order, and whatever does not fit carried to the next sheet of the same set (``x.svg``,
``x-2.svg`` …, each titled "sheet N of M") — a drawing never fails for want of room.

Also the sheets' numbers as the lab writes them (``number``: significant figures, no e-notation,
"—" for what the ruler cannot read) and the drawing's scale for the title block (``drawing_scale``)."""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path

from graphplan.drawing.layout import (GRID, Block, Cells, Placed, bare_cells, cover_some, declutter, footprint,
                                      improve, nest_some, spread_nested)
from graphplan.graphic.record import Record
from graphplan.sheets.form import Form, frame, title_block, title_block_box
from graphplan.util.errors import GraphplanError
from graphplan.util.words import fixed, num

FORMATS_OUT = (".svg", ".pdf", ".png", ".dxf")
GAP = 6.0          # mm between blocks
INSET = 5.0        # mm between the frame and the blocks


@dataclass
class SheetOptions:
    """What a sheet is asked for (the command line's options, or an API call's keywords)."""
    positions: int | None = None
    accel: list[str] | None = None
    precision: float = 0.5
    lang: str = "uk"
    sheet: str = "kinematics"


def options_of(obj) -> SheetOptions:
    """SheetOptions from any object with those attributes (an argparse namespace, a SimpleNamespace)."""
    if isinstance(obj, SheetOptions):
        return obj
    return SheetOptions(**{k: getattr(obj, k) for k in SheetOptions.__dataclass_fields__ if hasattr(obj, k)})


@dataclass
class Sheet:
    """A laid-out sheet: its form, the whole construction record and where each block went;
    ``more`` holds the further sheets of the same set (sheet 2, 3 … of M)."""
    form: Form
    record: Record
    placed: list[Placed] = field(default_factory=list)
    lang: str = "uk"
    more: list[Sheet] = field(default_factory=list)

    @property
    def pages(self) -> list[Sheet]:
        """Every sheet of the set, this one first."""
        return [self] + self.more

    def svg(self, text_as_paths: bool = False) -> str:
        from graphplan.drawing.svg import render
        return render(self.record, self.form.width, self.form.height, self.record.title, text_as_paths)

    def write(self, path: str | Path, text_as_paths: bool = False, dpi: float = 300) -> Path:
        """Write the set: this sheet to ``path``, sheet N to ``stem-N.suffix``; the suffix picks the
        format (PNG at ``dpi``). Whole files only. Returns the first file's path."""
        path = Path(path)
        suffix = path.suffix.lower()
        if suffix not in FORMATS_OUT:
            raise GraphplanError(f"-o {path}: unknown format {suffix or '(none)'!r}; use "
                                 + ", ".join(FORMATS_OUT))
        for n, page in enumerate(self.pages, 1):
            page._write_one(page_path(path, n), suffix, text_as_paths, dpi)
        return path

    def _write_one(self, path: Path, suffix: str, text_as_paths: bool, dpi: float) -> Path:
        from graphplan.util.files import write_atomic
        if suffix == ".dxf":
            from graphplan.drawing.dxf import to_dxf
            return write_atomic(path, to_dxf(self.record, self.form.width, self.form.height))
        if suffix == ".svg":
            return write_atomic(path, self.svg(text_as_paths))
        from graphplan.drawing.fonts import register
        from graphplan.drawing.raster import to_pdf, to_png
        svg = self.svg(text_as_paths or not register())   # no fontconfig: letter with outlines
        return write_atomic(path, to_pdf(svg) if suffix == ".pdf" else to_png(svg, dpi))


def page_path(path: Path, n: int) -> Path:
    """Sheet n of a set: ``x.svg``, ``x-2.svg``, ``x-3.svg`` …"""
    return path if n == 1 else path.with_name(f"{path.stem}-{n}{path.suffix}")


def field_region(f: Form) -> tuple[tuple[float, float, float, float], tuple[float, float, float, float]]:
    """The free field inside the frame and the title block's keep-out box. The field's lower-left
    corner is moved (by under one raster cell) onto the raster of the 25 mm judging cells, so that
    no raster cell of the layout straddles a judging cell's edge: the count the layout makes is the
    count the sheet is judged by."""
    x0, y0, x1, y1 = f.frame_box
    tb = title_block_box(f)
    cells = judging_cells(f)
    wx0, _, _, wy1 = cells.within
    bottom = wy1 - ((wy1 - cells.within[1]) // cells.size) * cells.size     # the lowest whole row's edge
    rx0 = wx0 + math.ceil((x0 + INSET - wx0) / GRID - 1e-9) * GRID
    ry0 = bottom + math.ceil((y0 + INSET - bottom) / GRID - 1e-9) * GRID
    return ((rx0, ry0, x1 - INSET, y1 - INSET),
            (tb[0] - INSET, tb[1], tb[2], tb[3] + INSET))


ORDERS = ("given", "area", "height", "width")


def _ordered(blocks: list[Block], how: str) -> list[Block]:
    """The blocks in one of the packing orders: as given, or largest (area, height, width) first —
    bottom-left fill packs big pieces first best."""
    if how == "given":
        return list(blocks)
    size = {}
    for b in blocks:
        x0, y0, x1, y1 = b.build(b.factors[0]).bounds()
        size[b.name] = {"area": (x1 - x0) * (y1 - y0), "height": y1 - y0, "width": x1 - x0}[how]
    return sorted(blocks, key=lambda b: -size[b.name])


def _cached(blocks: list[Block]) -> list[Block]:
    """The same blocks, each drawn once per factor."""
    out = []
    for b in blocks:
        memo: dict[float, Record] = {}

        def build(k: float, b=b, memo=memo) -> Record:
            if k not in memo:
                memo[k] = b.build(k)
            return memo[k]
        out.append(Block(b.name, build, b.factors, b.solid))
    return out


def paginate(f: Form, blocks: list[Block]) -> list[list[Placed]]:
    """The blocks placed sheet after sheet: first-fit finds how many sheets the set needs (a sheet
    fewer is tried), then the blocks (largest first) are shared out, each to the emptiest sheet that
    still takes it, so the last sheet is not left with one drawing; the sheet with the earliest block comes first. A block
    that does not fit even an empty sheet is refused."""
    region, keep_out = field_region(f)
    greedy = _first_fit(f, blocks)
    if len(greedy) == 1:
        return greedy
    return (_balanced(blocks, len(greedy) - 1, region, keep_out)
            or _balanced(blocks, len(greedy), region, keep_out) or greedy)


def _first_fit(f: Form, blocks: list[Block]) -> list[list[Placed]]:
    """Sheet after sheet filled with what still fits (in the best of the packing orders)."""
    region, keep_out = field_region(f)
    rest = _cached(blocks)
    greedy: list[list[Placed]] = []
    while rest:
        for how in ORDERS:
            placed, left = nest_some(_ordered(rest, how), region, obstacles=[keep_out], gap=GAP)
            if not left:
                break
        else:
            placed, left = nest_some(rest, region, obstacles=[keep_out], gap=GAP)
        if not placed:
            raise GraphplanError(f"the {rest[0].name} is larger than a whole {f.name} sheet; "
                                 "choose a larger --format")
        greedy.append(placed)
        rest = left
    return greedy


def fits_sheets(f: Form, blocks: list[Block], n: int) -> bool:
    """Whether the blocks fit ``n`` sheets of ``f`` (as ``paginate`` shares them out), checked without
    sharing them out when first-fit already needs no more."""
    try:
        greedy = _first_fit(f, blocks)
    except GraphplanError:
        return False
    if len(greedy) <= n:
        return True
    region, keep_out = field_region(f)
    return len(greedy) == n + 1 and _balanced(blocks, n, region, keep_out) is not None


def _area(b: Block) -> float:
    x0, y0, x1, y1 = b.build(b.factors[0]).bounds()
    return (x1 - x0) * (y1 - y0)


def _balanced(blocks: list[Block], count: int, region, keep_out) -> list[list[Placed]] | None:
    """``count`` sheets with the blocks shared out largest first, each to the emptiest sheet that
    takes it; None when some block fits none."""
    cached = _cached(blocks)
    order = {b.name: k for k, b in enumerate(cached)}
    sheets: list[list[Block]] = [[] for _ in range(count)]
    load = [0.0] * count

    def cover(b: Block) -> float:       # the paper a block really takes: its footprint
        return float(footprint(b.build(b.factors[0]), GAP / 2, b.solid).mask.sum())
    for b in sorted(cached, key=lambda b: -_area(b)):
        for n in sorted(range(count), key=lambda n: load[n]):
            trial = sorted(sheets[n] + [b], key=lambda x: -_area(x))
            if not nest_some(trial, region, obstacles=[keep_out], gap=GAP)[1]:
                sheets[n].append(b)
                load[n] += cover(b)
                break
        else:
            return None
    sheets.sort(key=lambda s: min(order[b.name] for b in s) if s else len(order))
    return [nest_some(sorted(s, key=lambda x: -_area(x)), region, obstacles=[keep_out], gap=GAP)[0]
            for s in sheets if s]


def fits_one(f: Form, blocks: list[Block]) -> bool:
    """Whether every block fits one sheet of form ``f`` in one of the packing orders."""
    return _packed(f, blocks) is not None


def _packed(f: Form, blocks: list[Block]) -> list[Placed] | None:
    """The blocks packed on one sheet in the first of the packing orders that holds them all."""
    region, keep_out = field_region(f)
    blocks = _cached(blocks)
    for how in ORDERS:
        placed, left = nest_some(_ordered(blocks, how), region, obstacles=[keep_out], gap=GAP)
        if not left:
            return placed
    return None


def beside(records: list[Record], gap: float = 10.0, below: Record | None = None) -> Record:
    """Records side by side, tops aligned, and ``below`` under them, left-aligned: a drawing with its
    table next to it."""
    out = Record(" | ".join(r.title for r in records))
    x = 0.0
    bottom = 0.0
    for r in records:
        x0, y0, x1, y1 = r.bounds()
        out.extend(r.moved(x - x0, -y1))
        x += x1 - x0 + gap
        bottom = min(bottom, -(y1 - y0))
    if below is not None:
        x0, y0, x1, y1 = below.bounds()
        out.extend(below.moved(-x0, bottom - gap - y1))
    return out


def remembered(choose):
    """A scale choice remembered per scene (its whole content, not its file's name), format and
    options: ``plans``, ``diagrams``, the sheet and the explorer of one scene ask for the same
    layout, and each layout costs seconds. A few are kept."""
    import functools
    memo: dict[tuple, object] = {}

    @functools.wraps(choose)
    def wrapper(st, f: Form, opts: SheetOptions):
        key = (repr(st.mech), f.name, repr(opts))
        if key not in memo:
            if len(memo) >= 8:
                memo.pop(next(iter(memo)))
            memo[key] = choose(st, f, opts)
        return memo[key]
    return wrapper


def judging_cells(f: Form) -> Cells:
    """The 25 mm cells a sheet is judged by: whole cells inside the frame (1 mm off its line), the
    title block's left out."""
    x0, y0, x1, y1 = f.frame_box
    return Cells((x0 + 1.0, y0 + 1.0, x1 - 1.0, y1 - 1.0), 25.0, [title_block_box(f)])


SLACKS = (0, 0, 1, 2)    # the cells of slack each try of the cover layout allows


def covered(f: Form, blocks: list[Block]) -> list[Placed] | None:
    """The blocks (largest first) each put where its ink reaches the most bare 25 mm cells; what
    finds no room is tried first next time, then with a little slack for a tighter packing. None
    when no try places them all."""
    region, keep_out = field_region(f)
    cells = judging_cells(f)
    mine = sorted(_cached(blocks), key=lambda b: -_area(b))
    for slack in SLACKS:
        out, left = cover_some(mine, region, cells, obstacles=[keep_out], gap=GAP, slack=slack)
        if not left:
            return out
        mine = left + [b for b in mine if b not in left]     # what found no room goes first
    return None


def fill(f: Form, blocks: list[Block], placed: list[Placed]) -> list[Placed]:
    """One sheet's blocks laid out to use the field (``covered``); when that never places them all,
    the packing ``placed`` spread over the sheet. (Measured on the gallery: the cover layout leaves
    15–43 % of the cells bare where the spread packing left 20–53 %; spreading the cover layout
    afterwards only loses cells.)"""
    region, keep_out = field_region(f)
    names = {p.name for p in placed}
    out = covered(f, [b for b in blocks if b.name in names])
    return out if out is not None else spread_nested(placed, region, [keep_out], GAP)


_LAID: dict[tuple, tuple[list[Block], list[list[Placed]]]] = {}


def laid_out(f: Form, blocks: list[Block]) -> list[list[Placed]]:
    """The sheets of the set as ``compose`` draws them: one sheet when the cover layout holds
    everything, else the packing's sheets each filled (``fill``); then each bettered (``improve``).
    Remembered for the same blocks, since the scale choice lays out the drawing it then composes."""
    key = (f.name, tuple(id(b) for b in blocks))
    hit = _LAID.get(key)
    if hit is not None and all(a is b for a, b in zip(hit[0], blocks)):
        return hit[1]
    if len(_LAID) > 64:
        _LAID.clear()
    region, keep_out = field_region(f)
    whole = covered(f, blocks)
    if whole is not None:
        pages = [whole]
    else:
        packed = paginate(f, blocks)
        pages = ([spread_nested(packed[0], region, [keep_out], GAP)] if len(packed) == 1
                 else shared_out(f, blocks, [fill(f, blocks, placed) for placed in packed]))
    pages = [improve(placed, region, judging_cells(f), [keep_out], GAP) for placed in pages]
    _LAID[key] = (list(blocks), pages)
    return pages


MOVES, TRIED = 2, 6


def _page(f: Form, blocks: list[Block]) -> list[Placed] | None:
    """One sheet of these blocks as ``fill`` lays it out (the cover layout, else a packing spread
    over the sheet); None when they do not fit one sheet."""
    out = covered(f, blocks)
    if out is not None:
        return out
    placed = _packed(f, blocks)
    if placed is None:
        return None
    region, keep_out = field_region(f)
    return spread_nested(placed, region, [keep_out], GAP)


def shared_out(f: Form, blocks: list[Block], pages: list[list[Placed]]) -> list[list[Placed]]:
    """A set's drawings shared out so that no sheet stays sparse: a drawing of the fullest sheet
    (the smaller ones tried first) moves to the sparsest when both still hold theirs and the
    sparser of the two leaves fewer cells bare (the rest of the fuller sheet keep their places) — a
    few moves at most, each trying a few drawings (each try lays out the sparser sheet again)."""
    region, _ = field_region(f)
    cells = judging_cells(f)
    by_name = {b.name: b for b in blocks}
    share = lambda placed: bare_cells(placed, region, cells, GAP)  # noqa: E731
    pages = list(pages)
    for _ in range(MOVES):
        shares = [share(p) for p in pages]
        full, sparse = shares.index(min(shares)), shares.index(max(shares))
        if full == sparse:
            break
        worst = shares[sparse]
        best = None
        names = sorted((p.name for p in pages[full]), key=lambda n: _area(by_name[n]))
        for name in names[:TRIED]:
            a = [p for p in pages[full] if p.name != name]       # the rest keep their places
            b = _page(f, [by_name[p.name] for p in pages[sparse]] + [by_name[name]])
            if b is None:
                continue
            score = max(share(a), share(b))
            if score < worst - 1e-9 and (best is None or score < best[0]):
                best = (score, a, b)
        if best is None:
            break
        pages[full], pages[sparse] = best[1], best[2]
    order = {b.name: k for k, b in enumerate(blocks)}
    return sorted(pages, key=lambda p: min(order[x.name] for x in p))


def bare_share(f: Form, blocks: list[Block]) -> float:
    """The estimated share of bare 25 mm cells of the set's sparsest sheet as ``compose`` lays them
    out (each sheet of a set is judged on its own)."""
    region, _ = field_region(f)
    return max(bare_cells(p, region, judging_cells(f), GAP) for p in laid_out(f, blocks))


def sampled(path: list, most: int = 4) -> list:
    """At most ``most`` drawings of a growth path, evenly, its first and last among them: the
    candidates whose layouts are compared (each costs a whole layout, ~0.6 s)."""
    if len(path) <= most:
        return list(path)
    return [path[k] for k in sorted({round(k * (len(path) - 1) / (most - 1)) for k in range(most)})]


def compose(f: Form, blocks: list[Block], title_fields: dict[str, str], lang: str, title: str) -> Sheet:
    """Frame + title block + the blocks placed in the free field, labels decluttered; what does not
    fit goes to further sheets of the set (title block "sheet N of M")."""
    pages = laid_out(f, blocks)
    sheets = []
    for n, placed in enumerate(pages, 1):
        tf = dict(title_fields, sheet=str(n), sheets=str(len(pages)))
        rec = Record(title if n == 1 else f"{title} ({n})")
        rec.extend(frame(f))
        rec.extend(title_block(f, tf, lang))
        for p in placed:
            rec.extend(p.record)
        sheets.append(Sheet(f, declutter(rec), placed, lang))
    first = sheets[0]
    first.more = sheets[1:]
    return first


# -- numbers as the lab writes them -------------------------------------------------------------

def number(v: float | None, sig: int = 4, lang: str = "uk") -> str:
    """A value as the lab writes it (util.words.num): ``sig`` significant figures, the language's
    decimal sign, a true minus, no e-notation, "—" for none."""
    return num(v, lang, sig).replace("-", "−")


def reading(value: float | None, mm: float | None, precision: float, sig: int = 4, lang: str = "uk") -> str:
    """A value read off a drawn length: "—" where the length is below the ruler's resolution."""
    if mm is not None and precision > 0 and abs(mm) < precision:
        return "—"
    return number(value, sig, lang)


def percent(v: float | None, lang: str = "uk") -> str:
    """δ, %: two decimals, a true minus, "—" for none."""
    if v is None or not math.isfinite(v):
        return "—"
    return fixed(v, lang, 2).replace("-", "−")


def drawing_scale(mu_l: float, lang: str = "uk") -> str:
    """The title block's "Масштаб": μl (m/mm) as a drawing scale: 0.0025 → 1:2.5 (1:2,5 in
    Ukrainian), 0.0004 → 2.5:1."""
    ratio = mu_l * 1000.0
    if ratio >= 1.0:
        return f"1:{num(ratio, lang)}"
    return f"{num(1.0 / ratio, lang)}:1"
