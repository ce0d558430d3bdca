"""A sheet set: the frame and the title block of each sheet, the drawings where the sheet's composition
put them (drawing/layout.py: zones by construction), the further sheets of a set (``x.svg``,
``x-2.svg`` …, each titled "sheet N of M"), written as SVG, PDF, PNG or DXF.

The scales of a sheet's families of drawings are chosen by arithmetic (``choose_levels``): the largest
common size at which the composition fits, then each family grown in turn while it still fits —
sums of the drawings' sizes at candidate scales, never a trial layout.

Also the sheets' numbers as the lab writes them (``number``: significant figures, no e-notation,
"—" for what the ruler cannot read) and the drawing's scale for the title block (``drawing_scale``)."""
from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from pathlib import Path

from graphplan.drawing.layout import GAP, Placed
from graphplan.graphic.record import Record, line_pitch, text_width
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


def field_of(f: Form) -> tuple[float, float, float, float]:
    """The field the drawings may use: the frame's inside, ``INSET`` mm clear of its line."""
    x0, y0, x1, y1 = f.frame_box
    return x0 + INSET, y0 + INSET, x1 - INSET, y1 - INSET


def keep_out(f: Form) -> tuple[float, float, float, float]:
    """The title block with the clearance around it that no drawing enters."""
    tb = title_block_box(f)
    return tb[0] - GAP, tb[1], tb[2], tb[3] + GAP


def compose(f: Form, pages: list[list[Placed]], title_fields: dict[str, str], lang: str, title: str) -> Sheet:
    """Each page's frame, title block ("sheet N of M") and placed drawings: the set's sheets."""
    sheets = []
    for n, placed in enumerate(pages, 1):
        tf = dict(title_fields, sheet=str(n), sheets=str(len(pages)))
        rec = Record(title if n == 1 else f"{title} ({n})")
        rec.extend(frame(f))
        rec.extend(title_block(f, tf, lang))
        for p in placed:
            rec.extend(p.record)
        sheets.append(Sheet(f, rec, placed, lang))
    first = sheets[0]
    first.more = sheets[1:]
    return first


# -- captions and notes ------------------------------------------------------------------------------

CAPTION = 5.0        # a drawing's name, mm (GOST 2.304)
CAPTION_2 = 3.5      # its second line (the position's angle, the scale)
CAPTION_GAP = 4.0    # mm between a drawing and its caption


def captioned(rec: Record, title: str, second: str = "") -> Record:
    """The drawing with its caption centred under it (its name 5 mm, a second line 3.5 mm): the
    caption belongs to the drawing's box."""
    out = Record(rec.title, list(rec.items), dict(rec.scales))
    x0, y0, x1, _ = rec.bounds() if rec.items else (0.0, 0.0, 0.0, 0.0)
    mid = (x0 + x1) / 2
    y = y0 - CAPTION_GAP - CAPTION
    out.label((mid, y), title, size=CAPTION, anchor="middle", layer="labels", step="caption")
    if second:
        out.label((mid, y - line_pitch(CAPTION_2) - 1.0), second, size=CAPTION_2, anchor="middle", layer="labels",
                  step="caption")
    return out


def caption_size(title: str, second: str = "") -> tuple[float, float]:
    """The width and height a caption adds under a drawing."""
    w = max(text_width(title, CAPTION), text_width(second, CAPTION_2) if second else 0.0)
    h = CAPTION_GAP + CAPTION + 1.5 + ((line_pitch(CAPTION_2) + 1.0) if second else 0.0)
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
    return [t for t in out if t]


def wrap_markup(text: str, width: float, size: float) -> list[str]:
    """The line broken at spaces (never inside a {group} of the markup) into lines no wider than
    ``width`` mm at letter height ``size``; a single word wider than that stays whole."""
    lines: list[str] = []
    for word in _tokens(text):
        if lines and text_width(lines[-1] + " " + word, size) <= width:
            lines[-1] += " " + word
        else:
            lines.append(word)
    return lines or [""]


NOTE = 3.5           # the notes' lettering, mm
NOTE_STEP = line_pitch(NOTE)   # mm from one line's baseline to the next


def note_block(lines: Sequence[str], width: float, title: str = "notes") -> Record:
    """Lines of notes wrapped to ``width`` mm, one under another (a continued line indented)."""
    rec = Record(title)
    y = 0.0
    for line in lines:
        for k, part in enumerate(wrap_markup(line, width - 5.0, NOTE)):
            rec.label((5.0 if k else 0.0, y), part, size=NOTE, layer="labels", step="notes")
            y -= NOTE_STEP
    return rec


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


def choose_levels(start: Callable[[float], dict[str, float]], fits: Callable[[dict[str, float]], bool],
                  order: Sequence[str], largest: Callable[[str, float], bool] | None = None
                  ) -> dict[str, float] | None:
    """The scales by arithmetic: the largest common size factor k (``start(k)`` gives each family's
    standard μ for it) at which ``fits`` holds; then the families in ``order``, in turn, each made one
    standard step finer while it still fits (and ``largest(name, μ)`` allows) — round after round,
    so they grow together. None when even the smallest factor does not fit."""
    mu = None
    for k in FACTORS:
        trial = start(k)
        if fits(trial):
            mu = trial
            break
    if mu is None:
        return None
    growing = list(order)
    while growing:
        for name in list(growing):
            bigger = finer(mu[name])
            trial = {**mu, name: bigger}
            if (largest is not None and not largest(name, bigger)) or not fits(trial):
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
