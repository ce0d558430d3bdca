"""A sheet set: the frame and the title block of each sheet, the drawings where the sheet's composition
put them (drawing/layout.py: zones by construction), the further sheets of a set (``x.svg``,
``x-2.svg`` …, each titled "sheet N of M"), written as SVG, PDF, PNG or DXF.

The scales of a sheet's families of drawings are chosen by arithmetic (``choose_levels``): the largest
common size at which the composition fits, then each family grown in turn while it still fits —
sums of the drawings' sizes at candidate scales, never a trial layout.

Also the sheets' numbers as the lab writes them (``number``: significant figures, no e-notation,
"—" for what the ruler cannot read) and the drawing's scale for the title block (``drawing_scale``)."""
from __future__ import annotations

import functools
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path

from graphplan.drawing.layout import GAP, Placed
from graphplan.graphic.record import Record, left_bearing, line_pitch, text_width
from graphplan.sheets.form import Form, frame, title_block, title_block_box
from graphplan.util.errors import GraphplanError
from graphplan.util.words import fixed, num

FORMATS_OUT = (".svg", ".pdf", ".png", ".dxf")
INSET = 5.0        # mm between the frame and the drawings


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
    """A composed sheet: its form, the whole construction record and where each drawing went;
    ``more`` holds the further sheets of the same set (sheet 2, 3 … of M)."""
    form: Form
    record: Record
    placed: list[Placed] = field(default_factory=list)
    lang: str = "uk"
    more: list[Sheet] = field(default_factory=list)
    fields: dict[str, str] = field(default_factory=dict)    # the title block's fields as lettered

    def number(self, first: int, total: int, designation: str | None = None) -> Sheet:
        """Letter the set's title blocks as sheets ``first``, ``first + 1`` … of a project of
        ``total`` sheets under ``designation`` (sheets/sheet.py numbers a scene's sheets as one
        project): form 1 on this sheet, form 2a on the later sheets of the set. Returns self."""
        for k, page in enumerate(self.pages):
            tf = dict(page.fields, sheet=str(first + k), sheets=str(total))
            if designation is not None:
                tf["designation"] = designation
            page.record = _lettered(page.form, page.record, tf, page.lang, k == 0)
            page.fields = tf
        return self

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
            raise keyed_error(GraphplanError, None, f"-o {path}", "op out suffix", None, got=repr(suffix or "(none)"),
                              formats=either(*FORMATS_OUT))
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
        if suffix == ".pdf":             # drawn straight from the record (drawing.pdf)
            from graphplan.drawing.pdf import render_pdf
            from graphplan.util.markup import plain
            return write_atomic(path, render_pdf([self.record], self.form.width, self.form.height,
                                                 plain(self.record.title), text_as_paths))
        from graphplan.drawing.fonts import register
        from graphplan.drawing.raster import to_png
        svg = self.svg(text_as_paths or not register())   # no fontconfig: letter with outlines
        return write_atomic(path, to_png(svg, dpi))


def page_path(path: Path, n: int) -> Path:
    """Sheet n of a set: ``x.svg``, ``x-2.svg``, ``x-3.svg`` …"""
    return path if n == 1 else path.with_name(f"{path.stem}-{n}{path.suffix}")


def field_of(f: Form) -> tuple[float, float, float, float]:
    """The field the drawings may use: the frame's inside, ``INSET`` mm clear of its line."""
    x0, y0, x1, y1 = f.frame_box
    return x0 + INSET, y0 + INSET, x1 - INSET, y1 - INSET


def keep_out(f: Form) -> tuple[float, float, float, float]:
    """The title block with the clearance around it that no drawing enters."""
    tb = title_block_box(f)
    return tb[0] - GAP, tb[1], tb[2], tb[3] + GAP


def later_keep(f: Form) -> tuple[float, float, float, float]:
    """``keep_out`` of a set's later sheets: their title block is form 2a (185×15 mm)."""
    from graphplan.sheets.form import BLOCK_2A_H
    tb = title_block_box(f)
    return tb[0] - GAP, tb[1], tb[2], tb[1] + BLOCK_2A_H + GAP


def compose(f: Form, pages: list[list[Placed]], title_fields: dict[str, str], lang: str, title: str) -> Sheet:
    """Each page's frame, title block and placed drawings: the set's sheets, numbered "sheet N of
    M" of the set (form 1 on the first, form 2a on the later ones) until ``Sheet.number`` numbers
    them in their project."""
    sheets = []
    for n, placed in enumerate(pages, 1):
        rec = Record(title if n == 1 else f"{title} ({n})")
        rec.extend(frame(f))
        for p in placed:
            rec.extend(p.record)
        sheets.append(Sheet(f, rec, placed, lang, fields=dict(title_fields)))
    first = sheets[0]
    first.more = sheets[1:]
    return first.number(1, len(pages))


def _lettered(f: Form, rec: Record, tf: dict[str, str], lang: str, first: bool) -> Record:
    """The page's record with its title block (form 1 on a document's first sheet, else form 2a)
    lettered from ``tf`` in place of the one it had: the frame first, the block, the drawings."""
    from graphplan.sheets.form import title_block_2a
    out = Record(rec.title, [p for p in rec.items if not (p.layer == "frame" and p.step == "title block")],
                 dict(rec.scales))
    block = title_block(f, tf, lang) if first else title_block_2a(f, tf, lang)
    n = len(frame(f).items)
    out.items[n:n] = [replace(p, step="title block") for p in block.items]
    return out


def defects(sheet: Sheet) -> list[str]:
    """What a teacher would send back, read off the set's own records: lettering that touches a
    line or other lettering (drawing.labels.collisions), two drawings whose boxes meet or a drawing
    outside its box, anything outside the frame or inside the title block (but the block's own),
    the velocity plans out of position order (row by row, sheet after sheet). Empty when none."""
    import re

    from graphplan.drawing.labels import collisions
    out: list[str] = []
    order: list[int] = []
    for n, page in enumerate(sheet.pages, 1):
        f = page.form
        out += [f"sheet {n}: {c}" for c in collisions(page.record)]
        fx0, fy0, fx1, fy1 = f.frame_box
        tb = title_block_box(f)
        if n > 1:                                   # a set's later sheets carry form 2a (``Sheet.number``)
            from graphplan.sheets.form import BLOCK_2A_H
            tb = (tb[0], tb[1], tb[2], tb[1] + BLOCK_2A_H)
        for p in page.record.items:
            if p.layer == "frame":
                continue
            x0, y0, x1, y1 = p.bounds()
            if x0 < fx0 - 1e-6 or y0 < fy0 - 1e-6 or x1 > fx1 + 1e-6 or y1 > fy1 + 1e-6:
                out.append(f"sheet {n}: {p.kind} {p.text!r} outside the frame")
            elif x1 > tb[0] + 1e-6 and y0 < tb[3] - 1e-6:
                out.append(f"sheet {n}: {p.kind} {p.text!r} in the title block")
        items = page.placed
        for i, a in enumerate(items):
            r = a.record.bounds() if a.record.items else a.box
            if r[0] < a.box[0] - 1e-6 or r[1] < a.box[1] - 1e-6 or r[2] > a.box[2] + 1e-6 or r[3] > a.box[3] + 1e-6:
                out.append(f"sheet {n}: the {a.name} leaves its box")
            for b in items[i + 1:]:
                p_, q = a.box, b.box
                if p_[0] < q[2] and q[0] < p_[2] and p_[1] < q[3] and q[1] < p_[3]:
                    out.append(f"sheet {n}: the {a.name} and the {b.name} meet")
        plans = [(p.box, int(m.group(1))) for p in items if (m := re.fullmatch(r"velocity plan (\d+)", p.name))]
        rows: dict[float, list] = {}
        for b, k in plans:
            top = next((t for t in rows if abs(t - b[3]) < 0.5), b[3])
            rows.setdefault(top, []).append((b[0], k))
        for top in sorted(rows, reverse=True):
            order += [k for _, k in sorted(rows[top])]
    if order != sorted(order):
        out.append(f"velocity plans read {order}")
    return out


# -- captions and notes ------------------------------------------------------------------------------

CAPTION = 5.0        # a drawing's name, mm (GOST 2.304)
CAPTION_2 = 3.5      # its second line (the position's angle, the scale)
CAPTION_GAP = 4.0    # mm between a drawing and its caption


def captioned(rec: Record, title: str, second: str = "", size: float = CAPTION) -> Record:
    """The drawing with its caption centred under it (its name 5 mm — 3.5 mm under a small
    drawing —, a second line 3.5 mm): the caption belongs to the drawing's box."""
    out = Record(rec.title, list(rec.items), dict(rec.scales))
    x0, y0, x1, _ = rec.bounds() if rec.items else (0.0, 0.0, 0.0, 0.0)
    mid = (x0 + x1) / 2
    y = y0 - CAPTION_GAP - size
    out.label((mid, y), title, size=size, anchor="middle", layer="labels", step="caption")
    if second:
        out.label((mid, y - line_pitch(CAPTION_2) - 1.0), second, size=CAPTION_2, anchor="middle", layer="labels",
                  step="caption")
    return out


def caption_size(title: str, second: str = "", size: float = CAPTION) -> tuple[float, float]:
    """The width and height a caption adds under a drawing."""
    w = max(text_width(title, size), text_width(second, CAPTION_2) if second else 0.0)
    h = CAPTION_GAP + size + 1.5 + ((line_pitch(CAPTION_2) + 1.0) if second else 0.0)
    return w, h


def _tokens(text: str) -> list[str]:
    """Words of a line of markup text: split at spaces outside {groups}."""
    out, depth, cur = [], 0, ""
    for c in text:
        if c == "{":
            depth += 1
        elif c == "}":
            depth = max(0, depth - 1)
        if c == " " and depth == 0:
            out.append(cur)
            cur = ""
        else:
            cur += c
    out.append(cur)
    return _bound([t for t in out if t])


RELATIONS = ("=", "≈", "≤", "≥", "<", ">")


def _unit_word(token: str) -> bool:
    """Whether a word is a unit as the sheets write one after a value (мм, Н·м, (м/с)/мм, °/мм, %)."""
    from graphplan.util.words import UNITS
    bare = token.rstrip(",;:.)")
    if not bare or any(c in "0123456789" for c in bare):
        return False
    return bare in {u for pair in UNITS.values() for u in pair} or bare in ("%", "°") or "/" in bare \
        or "·" in bare


def _bound(words: list[str]) -> list[str]:
    """The words a line never breaks between kept together: a symbol, its relation and its value
    with the value's unit — "μ_a = 0,025 (м/с²)/мм," is one word to the wrapping (the reviewer found
    "μ_a" at a line's end, "= 0,025" under it), and any number its unit ("Φ_2 3 мм"). A chain
    "J = a = b" breaks before its second "=" at most (each "= value unit" whole)."""
    out: list[str] = []
    state = None              # "rel": a relation waits for its value; "value": a unit may follow
    for t in words:
        if t in RELATIONS:
            if out and state is None and not out[-1].endswith((",", ";", ":")):
                out[-1] += " " + t
            else:
                out.append(t)
            state = "rel"
        elif state == "rel":
            out[-1] += " " + t
            state = None if t.endswith((",", ";", ":")) else "value"
        elif (state == "value" or (out and out[-1][-1:] in "0123456789")) and _unit_word(t):
            out[-1] += " " + t            # a value keeps its unit: "3 мм", "= 0,025 (м/с²)/мм"
            state = None
        else:
            out.append(t)
            state = None
    return out


@functools.lru_cache(maxsize=4096)
def _wrapped(text: str, width: float, size: float) -> tuple[str, ...]:
    lines: list[str] = []
    for word in _tokens(text):
        if lines and text_width(lines[-1] + " " + word, size) <= width:
            lines[-1] += " " + word
        else:
            lines.append(word)
    return tuple(lines or [""])


def sheet_field(meta: dict, name: str, lang: str) -> str:
    """A [sheet] field (student, teacher, group, organisation …) in the sheet's language: its
    ``NAME_en`` variant on an English sheet where the scene gives one (as ``title_en``), else on an
    English sheet the field romanised (util/romanize.py: «Рецензент Р. Р.» → «Retsenzent R. R.»), on a
    Ukrainian sheet as written; unescaped."""
    from graphplan.util.romanize import scene_text
    return scene_text(meta, f"sheet.{name}", lang)


def organisation(meta: dict, lang: str) -> str:
    """The title block's organisation field: the organisation and the student's group in one word
    on every sheet ("НУБіП України, гр. МБ-21"; "…, group МБ-21"), unescaped."""
    from graphplan.util.words import word
    org, group = sheet_field(meta, "organisation", lang), sheet_field(meta, "group", lang)
    return ", ".join(x for x in (org, word("kin group", lang, g=group) if group else "") if x)


def wrap_markup(text: str, width: float, size: float) -> list[str]:
    """The line broken at spaces (never inside a {group} of the markup) into lines no wider than
    ``width`` mm at letter height ``size``; a single word wider than that stays whole."""
    return list(_wrapped(text, round(width, 6), size))


NOTE = 3.5           # the notes' lettering, mm
NOTE_STEP = line_pitch(NOTE)   # mm from one line's baseline to the next


def note_block(lines: Sequence[str], width: float, title: str = "notes") -> Record:
    """Lines of notes wrapped to ``width`` mm, one under another (a continued line indented), each
    line's ink flush with the margin (its first glyph's side bearing taken off: review 10's «R₀ …»
    line stood 0.7 mm in, osifont's R)."""
    short = [0.0] * len(lines)
    for _ in range(2):
        rec = Record(title)
        y = 0.0
        ends = []
        for j, line in enumerate(lines):
            for k, part in enumerate(wrap_markup(line, width - 5.0 - short[j], NOTE)):
                p = rec.label(((5.0 if k else 0.0) - left_bearing(part, NOTE), y), part, size=NOTE, layer="labels",
                              step="notes")
                b = p.bounds()
                ends.append((j, b[2], b[2] - b[0]))
                y -= NOTE_STEP
        # a line whose first glyph's bearing is taken off stands left of the margin, and the block is placed by
        # its box: a line filling its width then ran that much past the box's right edge (hypothesis, 150/150
        # teeth, English A1: the notes 0.15 mm out of their column) — such lines wrapped again that much shorter
        edge = (rec.bounds()[0] if rec.items else 0.0) + width
        over = [(j, e - edge, w) for j, e, w in ends if e > edge + 1e-9]
        if not over:
            break
        for j, d, w in over:              # its part no wider than it was less the overshoot
            short[j] = max(short[j], width - 5.0 - (w - d) + 1e-6)
    return rec


def notes_height(notes: Sequence[Sequence[str]], width: float) -> float:
    """The height of the tallest of these notes (one list of lines per language) wrapped to
    ``width`` mm, with a line to spare for the final numbers."""
    return max(sum(len(wrap_markup(line, width - 5.0, NOTE)) for line in lines) for lines in notes) * NOTE_STEP \
        + NOTE_STEP


def grown(measured: list[tuple[str, float, float]], drawn: Sequence[Sequence[tuple[str, float, float]]]) -> bool:
    """Whether any table as ``drawn`` (per language: name, width, height) is larger than
    ``measured``; ``measured`` takes the larger sizes (the next composition allows for them)."""
    out = False
    for per in drawn:
        for k, (name, w, h) in enumerate(per):
            if w > measured[k][1] + 1e-6 or h > measured[k][2] + 1e-6:
                measured[k] = (name, max(w, measured[k][1]), max(h, measured[k][2]))
                out = True
    return out


def lines_of(rec: Record) -> list[str]:
    """The text lines of a notes record, top to bottom."""
    return [p.text for p in sorted((p for p in rec.items if p.kind == "text"), key=lambda p: -p.points[0][1])]


# -- scales by arithmetic -------------------------------------------------------------------------

FACTORS = (2.0, 1.6, 1.4, 1.25, 1.12, 1.0, 0.8, 0.64, 0.5, 0.4, 0.32, 0.25, 0.2)


def finer(mu: float) -> float:
    """The next finer coefficient of the standard series (a larger drawing)."""
    from graphplan.graphic.scales import series_around
    return max(m for m in series_around(mu) if m < mu * (1 - 1e-9))


def coarser(mu: float) -> float:
    """The next coarser coefficient of the standard series (a smaller drawing)."""
    from graphplan.graphic.scales import series_around
    return min(m for m in series_around(mu) if m > mu * (1 + 1e-9))


@dataclass
class Family:
    """Drawings that share one scale (the velocity plans, the force plans, the charts), measured once
    at a trial scale ``mu0``: each drawing's lines (w, h) there and what its lettering adds (w, h),
    its caption's (w, h). At a scale μ a drawing's lines are μ0/μ times as large (across and/or up),
    its lettering and caption the same. ``principal``: the real size of the segment the family's
    ``target`` (mm at size factor 1) speaks of — the crank r, v_A, a_A, the largest force. A family
    whose drawings have no standard scale (a chart's length) takes μ = 1/k for the size factors k."""
    mu0: float
    sizes: list[tuple[float, float, float, float]]
    caption: tuple[float, float] = (0.0, 0.0)
    principal: float = 1.0
    target: float = 100.0
    across: bool = True
    up: bool = True
    factors: bool = False
    seen: dict = field(default_factory=dict)   # (μ, i) → what drawing i's lettering added, measured at μ

    def lettering(self, mu: float, i: int) -> tuple[float, float]:
        """What drawing i's lettering adds at μ (w, h): as measured where it was drawn at that μ
        (``allow``), else the most it added anywhere (lettering placed round a smaller drawing sticks
        out further: the slotter's position plan 1.6 mm at 1:2.5, 6.4 mm at 1:4 — so one margin for
        all scales pushed its plan back to 1:4)."""
        return self.seen.get((round(mu, 12), i), self.sizes[i][2:])

    def start(self, k: float) -> float:
        """The family's μ at the common size factor k."""
        from graphplan.graphic.scales import at_least
        return 1.0 / k if self.factors else at_least(self.principal / (self.target * k))

    def finer(self, mu: float) -> float | None:
        """The next larger drawing's μ (None: no larger size factor)."""
        if not self.factors:
            return finer(mu)
        bigger = [k for k in FACTORS if k > 1.0 / mu * (1 + 1e-9)]
        return 1.0 / min(bigger) if bigger else None

    def size(self, mu: float, i: int | None = None) -> tuple[float, float]:
        """Drawing i at μ (the largest of each dimension when i is None), with lettering and caption."""
        k = self.mu0 / mu
        kw, kh = (k if self.across else 1.0), (k if self.up else 1.0)
        which = range(len(self.sizes)) if i is None else [i]
        sizes = [self.sizes[j][:2] + self.lettering(mu, j) for j in which] or [(0.0, 0.0, 0.0, 0.0)]
        w = max(gw * kw + lw for gw, _, lw, _ in sizes)
        h = max(gh * kh + lh for _, gh, _, lh in sizes)
        return max(w, self.caption[0]), h + self.caption[1]

    def leaf(self, mu: float, name: str = "", i: int | None = None):
        from graphplan.drawing.layout import Leaf
        return Leaf(name, *self.size(mu, i))

    def allow(self, mu: float, w: float, h: float, i: int) -> bool:
        """Drawn at μ, drawing i came out w × h (without its caption): where that is more than
        assumed, what its lettering adds is corrected (the next choice allows for it). Whether the
        assumption held."""
        k = self.mu0 / mu
        kw, kh = (k if self.across else 1.0), (k if self.up else 1.0)
        gw, gh, lw, lh = self.sizes[i]
        need_w, need_h = w - gw * kw, h - gh * kh
        was_w, was_h = self.lettering(mu, i)
        self.seen[(round(mu, 12), i)] = (need_w, need_h)
        if need_w <= was_w + 1e-6 and need_h <= was_h + 1e-6:
            return True
        self.sizes[i] = (gw, gh, max(lw, need_w), max(lh, need_h))
        return False

    def drawn(self, mu: float) -> float:
        """The principal segment drawn at μ, mm (a chart: its size factor × target)."""
        return self.target / mu if self.factors else self.principal / mu

    def rel(self, mu: float) -> float:
        """How large the family is drawn against its target (1 = the target)."""
        return self.drawn(mu) / self.target


def measured(records: Sequence[Record], mu0: float, captions: Sequence[tuple[str, str]] = (),
             caption: float = CAPTION, lettering: float | None = None, **kw) -> Family:
    """A family measured from its drawings at ``mu0``: each one's lines and lettering (or, for
    drawings measured before their lettering is placed, ``lettering`` mm assumed), the widest and
    tallest of its captions (both languages' when given; ``caption`` its letter height)."""
    sizes = []
    for r in records:
        lines = Record(items=[p for p in r.items if p.kind != "text"]).bounds()
        full = r.bounds()
        gw, gh = lines[2] - lines[0], lines[3] - lines[1]
        if lettering is not None:
            sizes.append((gw, gh, lettering, lettering))
        else:
            sizes.append((gw, gh, full[2] - full[0] - gw + 1.0, full[3] - full[1] - gh + 1.0))
    cs = [caption_size(*c, size=caption) for c in captions] or [(0.0, 0.0)]
    return Family(mu0, sizes, (max(c[0] for c in cs), max(c[1] for c in cs)), **kw)


def measured_twice(first: Sequence[Record], second: Sequence[Record], mu0: float, mu1: float,
                   captions: Sequence[tuple[str, str]] = (), caption: float = CAPTION, lettering: float = 0.0,
                   **kw) -> Family:
    """A family measured from its drawings at two scales μ0 and μ1: each drawing's size taken as
    a/μ + c across and up (a part drawn to scale, a part that is not — arrows of a fixed length),
    the two unknowns from the two drawings; ``lettering`` mm more for labels not yet placed."""
    sizes = []
    ratio = mu0 / mu1
    for r0, r1 in zip(first, second):
        b0, b1 = r0.bounds(), r1.bounds()
        dims = []
        for s0, s1 in ((b0[2] - b0[0], b1[2] - b1[0]), (b0[3] - b0[1], b1[3] - b1[1])):
            g = max((s0 - s1) / (1.0 - ratio), 0.0) if abs(1.0 - ratio) > 1e-9 else s0
            dims.append((g, max(s0 - g, s1 - g * ratio, 0.0) + 1.0 + lettering))
        (gw, lw), (gh, lh) = dims
        sizes.append((gw, gh, lw, lh))
    cs = [caption_size(*c, size=caption) for c in captions] or [(0.0, 0.0)]
    return Family(mu0, sizes, (max(c[0] for c in cs), max(c[1] for c in cs)), **kw)


def choose_levels(families: dict[str, Family], fits: Callable[[dict[str, float]], bool],
                  order: Sequence[str], largest: Callable[[str, float], bool] | None = None,
                  start: dict[str, float] | None = None) -> dict[str, float] | None:
    """The scales by arithmetic: the largest common size factor k (each family's ``start(k)``) at
    which ``fits`` holds (or the scales ``start``, where given and they fit); then the families in
    ``order``, in turn, each made one step larger while it still fits (and ``largest(name, μ)``
    allows) — round after round, so they grow together. None when even the smallest factor (or
    ``start``) does not fit."""
    mu = None
    for trial in ([start] if start is not None else
                  ({name: fam.start(k) for name, fam in families.items()} for k in FACTORS)):
        if fits(trial):
            mu = dict(trial)
            break
    if mu is None:
        return None
    growing = [name for name in order if name in families]
    while growing:
        for name in list(growing):
            bigger = families[name].finer(mu[name])
            trial = {**mu, name: bigger}
            if bigger is None or (largest is not None and not largest(name, bigger)) or not fits(trial):
                growing.remove(name)
            else:
                mu = trial
    return mu


def remembered(choose):
    """A composition remembered per scene (its whole content, not its file's name), format and
    options: ``plans``, ``diagrams``, the sheet and the explorer of one scene ask for the same
    scales. A few are kept."""
    import functools
    memo: dict[tuple, object] = {}

    @functools.wraps(choose)
    def wrapper(st, f: Form, opts: SheetOptions, *args):
        key = (repr(st.mech), f.name, repr(opts), args)
        if key not in memo:
            if len(memo) >= 8:
                memo.pop(next(iter(memo)))
            memo[key] = choose(st, f, opts, *args)
        return memo[key]
    return wrapper


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
