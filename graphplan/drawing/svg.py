"""SVG renderer of construction records, in true millimetres (REFERENCE §3).

Root ``width="Wmm" height="Hmm" viewBox="0 0 W H"``, unitless coordinates, stroke widths in user
units (= mm), ``fill="none"`` on strokes, no transforms, one Inkscape layer per kind, deterministic.
Lettering stays text (searchable) in osifont, whose glyphs the document carries (drawing.fonts), or,
with ``text_as_paths``, outlines cut from the same font.
"""
from __future__ import annotations

import math
import re
from functools import lru_cache

from graphplan.graphic.record import (LAYERS, DASHED_ROLES, SIGNS, Primitive, Record, em, kern, kerned,
                                      lettering, plain_width, run_offsets, script_space, sub_kern, vector_arrow)
from graphplan.util.markup import SMALL, baseline_shift, is_plain, runs

FONT = "osifont, 'DejaVu Sans', sans-serif"
# a sign touching a letter (+5, =–0,23): drawn by a text of its own centred on its osifont advance
# (graphic.record.sign_gap), the lettering's own copy of it unpainted (still read and searched)
_SIGN = re.compile(f"(?<=[^\\s])([{re.escape(SIGNS)}])|([{re.escape(SIGNS)}])(?=[^\\s])")
DASHES = {"dashdot": "12,3,1.5,3", "dashed": "4,2"}


def _f(v: float) -> str:
    """Numbers as short, stable text (0.001 mm is far below any plotter)."""
    s = f"{v:.3f}".rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


def page_for(record: Record, margin: float = 10.0) -> tuple[Record, float, float]:
    """Move a record so it sits on a page ``margin`` mm from its bounds; returns (record, W, H)."""
    x0, y0, x1, y1 = record.bounds()
    w, h = math.ceil(x1 - x0 + 2 * margin), math.ceil(y1 - y0 + 2 * margin)
    return record.moved(margin - x0, margin - y0), float(w), float(h)


NAMESPACES = ('xmlns="http://www.w3.org/2000/svg" xmlns:ev="http://www.w3.org/2001/xml-events" '
              'xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape" '
              'xmlns:sodipodi="http://sodipodi.sourceforge.net/DTD/sodipodi-0.dtd" '
              'xmlns:xlink="http://www.w3.org/1999/xlink"')


def render(record: Record, width: float, height: float, title: str = "", text_as_paths: bool = False,
           embed_font: bool = True) -> str:
    """The record as an SVG document of ``width`` × ``height`` mm (y of the record points up).
    ``text_as_paths`` writes lettering as outlines, for importers that drop text; otherwise text stays
    text (searchable, selectable) and ``embed_font`` carries the glyphs it uses (fonts.face_css).

    The document is the one svgwrite writes for these elements (its "full" profile with the
    Inkscape extension's layers: attributes in sorted order, ElementTree's escaping), put together
    here as text: a key sheet's 500 elements through svgwrite's objects and ElementTree took 25 ms,
    this about a tenth of that (tests/test_outputs.py compares the two documents byte for byte)."""
    layers: dict[str, list[str]] = {name: [] for name in LAYERS}
    chars: list[str] = []
    for prim in record.items:
        out = layers.setdefault(prim.layer, [])
        if text_as_paths and prim.kind == "text":
            out.append(_tag("path", {"d": text_outline(prim, height), "fill": "black", "stroke": "none"}))
            continue
        out.extend(_elements(prim, height, chars))
    w, h = _f(width), _f(height)
    parts = [f'<svg baseProfile="full" height="{h}mm" version="1.1" viewBox="0 0 {w} {h}" width="{w}mm" '
             f'{NAMESPACES}>']
    if title:
        parts.append(f"<title>{_text_escape(title)}</title>")
    lettered = "".join(chars)
    if embed_font and lettered:
        from graphplan.drawing.fonts import face_css
        parts.append(f'<defs><style type="text/css"><![CDATA[{face_css(lettered)}]]></style></defs>')
    else:
        parts.append("<defs />")
    for name, elements in layers.items():
        if elements:
            parts.append(f'<g id="layer-{_attr_escape(name)}" inkscape:groupmode="layer" '
                         f'inkscape:label="{_attr_escape(name)}">')
            parts.extend(elements)
            parts.append("</g>")
    parts.append("</svg>")
    return "".join(parts)


def _text_escape(text: str) -> str:
    """Character data as ElementTree escapes it."""
    return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")


_ESCAPED = re.compile('[&<>"\r\n\t]')


def _attr_escape(text: str) -> str:
    """An attribute value as ElementTree escapes it (Python 3.11)."""
    if not _ESCAPED.search(text):
        return text
    return (text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace('"', "&quot;")
            .replace("\r", "&#13;").replace("\n", "&#10;").replace("\t", "&#09;"))


def _tag(name: str, attrs: dict[str, str], inner: str | None = None) -> str:
    """One element: its attributes sorted by name (as svgwrite writes them), empty ones closed."""
    head = "".join(f' {k}="{_attr_escape(v)}"' for k, v in sorted(attrs.items()))
    return f"<{name}{head}>{inner}</{name}>" if inner else f"<{name}{head} />"


def _xy(p, height: float) -> tuple[str, str]:
    return _f(p[0]), _f(height - p[1])


@lru_cache(maxsize=64)
def _stroke(width: float, role: str) -> str:
    """A stroke's attributes after ``fill="none"`` (and a polygon's points), in sorted order:
    black, round caps and joins, the width and the role's dashes."""
    dash = DASHED_ROLES.get(role)
    dashes = f' stroke-dasharray="{DASHES[dash]}"' if dash else ""
    return (f' stroke="black"{dashes} stroke-linecap="round" stroke-linejoin="round" '
            f'stroke-width="{_f(width)}"')


def _points(points, h: float) -> str:
    return " ".join(",".join(_xy(p, h)) for p in points)


def _elements(prim: Primitive, h: float, chars: list[str]) -> list[str]:
    """The SVG elements of one primitive (``chars`` collects the lettering's characters); each
    element's attributes in sorted order, as svgwrite writes them."""
    k = prim.kind
    if k == "text":
        return [_turned_text(_text(prim, h, chars), prim, h)]
    stroke = _stroke(prim.line_width, prim.role)
    if k == "segment":
        (x1, y1), (x2, y2) = (_xy(p, h) for p in prim.points)
        return [f'<line fill="none"{stroke} x1="{x1}" x2="{x2}" y1="{y1}" y2="{y2}" />']
    if k == "vector":
        a, b = prim.points
        tip, end = vector_arrow(a, b, prim.line_width, prim.role == "head")
        (x1, y1), (x2, y2) = _xy(a, h), _xy(end, h)
        return [f'<line fill="none"{stroke} x1="{x1}" x2="{x2}" y1="{y1}" y2="{y2}" />',
                f'<polygon fill="black" points="{_points(tip, h)}" stroke="none" />']
    if k in ("polyline", "polygon"):
        return [f'<{k} fill="none" points="{_points(prim.points, h)}"{stroke} />']
    if k == "circle":
        cx, cy = _xy(prim.points[0], h)
        return [f'<circle cx="{cx}" cy="{cy}" fill="none" r="{_f(prim.radius)}"{stroke} />']
    if k == "arc":
        return [f'<path d="{arc_path(prim.points[0], prim.radius, *prim.angles, h)}" fill="none"{stroke} />']
    if k == "point":
        cx, cy = _xy(prim.points[0], h)
        joint = prim.role == "joint"
        return [f'<circle cx="{cx}" cy="{cy}" fill="{"white" if joint else "black"}" '
                f'r="{"1" if joint else "0.6"}" stroke="black" stroke-width="0.35" />']
    return []


ARROW_FONT = "'graphplan symbols', 'DejaVu Sans', sans-serif"   # osifont has no → ⊥ ∥ ′ ″ …: those in the
MISSING = "→⊥∥′″…"                                              # package's symbols' font (drawing.fonts)
_MISSING = re.compile(f"([{MISSING}])")


@lru_cache(maxsize=65536)
def _plain_set(text: str, size: float) -> str | None:
    """The lettering of a text set in one piece (no markup, no character from the symbols' font),
    else None."""
    if is_plain(text) and not _MISSING.search(text):
        return lettering(text)
    return None


@lru_cache(maxsize=256)
def _em_text(size: float) -> str:
    return _f(em(size))


_FONT_ATTR = _attr_escape(FONT)


def glyph_xs(drawn: str, size: float, x0: float) -> list[float]:
    """Where each character of ``drawn`` (lettering) starts, mm: from ``x0`` by the packaged font's
    advances × the em and the pairs ``kern`` sets apart or tucks in (graphic.record.plain_width,
    metrics.json)."""
    advance, box = _advances_em()
    k = em(size)
    out, x, before, prev = [], x0, "", ""
    for c in drawn:
        if prev:
            x += kern(prev, c, size, before)
        out.append(x)
        x += k * advance.get(c, box)
        before, prev = prev, c
    return out


@lru_cache(maxsize=1)
def _advances_em():
    from graphplan.graphic.record import _advances
    return _advances()


def _xs_attr(xs: list[float]) -> str:
    return " ".join(_f(v) for v in xs)


def _kept_spaces(drawn: str) -> str:
    """The spaces SVG would collapse or strip (at the ends, the second of two) as no-break spaces:
    every character keeps its own x."""
    out = []
    for i, c in enumerate(drawn):
        if c == " " and (i == 0 or i == len(drawn) - 1 or drawn[i - 1] in " \u00a0"):
            c = "\u00a0"
        out.append(c)
    return "".join(out)


def _turned_text(element: str, prim: Primitive, h: float) -> str:
    """A text element turned ``prim.turn`` degrees counter-clockwise about its anchor (SVG's y runs
    down: rotate by minus the angle)."""
    if not prim.turn:
        return element
    x, y = _xy(prim.points[0], h)
    return element.replace("<text ", f'<text transform="rotate({_f(-prim.turn)} {x} {y})" ')


def _text(prim: Primitive, h: float, chars: list[str]) -> str:
    """A text element; the markup's sub- and superscripts (util.markup) as <tspan>s at 0.7 of the
    size with their baselines shifted by dy, the arrow → in a font that has it.

    Every character of a lettering is placed at its own x, where the packaged font's advances put
    it (``glyph_xs``), the text anchored at its start: a viewer that letters with another font —
    Inkscape, rsvg, cairosvg, ImageMagick ignore the embedded @font-face and fall back to a wider
    sans — still sets each letter where it was measured, so nothing laid out clear of lettering
    runs into it, and a caption keeps its measured width; the layout keeps lines clear of the
    union of both fonts' glyph boxes (graphic.record.ink_boxes, fallback.json). (A ``textLength``
    would not do: cairosvg ignores it.)"""
    drawn = _plain_set(prim.text, prim.size)
    if drawn is not None:         # the attributes in svgwrite's (sorted) order
        chars.append(drawn)
        x0 = prim.points[0][0] - {"start": 0.0, "middle": 0.5, "end": 1.0}[prim.anchor] * \
            plain_width(prim.text, prim.size)
        _, y = _xy(prim.points[0], h)
        xs = glyph_xs(drawn, prim.size, x0)
        if _SIGN.search(drawn):
            return _signed_text(drawn, xs, prim.size, y)
        inner = _text_escape(_kept_spaces(drawn))
        head = (f'<text fill="black" font-family="{_FONT_ATTR}" font-size="{_em_text(prim.size)}" '
                f'text-anchor="start" x="{_xs_attr(xs) or _f(x0)}" y="{y}"')
        return f"{head}>{inner}</text>" if inner else f"{head} />"
    # anchored at its start by the font's own advances: cairosvg (PDF, PNG) misplaces the <tspan>s
    # of a centred or right-aligned text
    pieces, x_start = placed(prim)
    x, y = _xy((x_start, prim.points[0][1]), h)
    spans = []
    shift = 0.0    # the baseline shift (mm up) so far
    for piece, small, x0, up, advance in pieces:
        kw = {}
        if up != shift:
            kw["dy"] = _f(shift - up)
        if small:
            kw["font-size"] = _f(em(prim.size) * SMALL)
        if piece in MISSING:
            kw["font-family"] = ARROW_FONT
        drawn = piece if piece in MISSING else lettering(piece)
        kw["x"] = _xs_attr(glyph_xs(drawn, prim.size * SMALL if small else prim.size, x_start + x0))
        drawn = _kept_spaces(drawn)
        chars.append(drawn)
        spans.append(_tag("tspan", kw, _text_escape(drawn)))
        shift = up
    return _tag("text", {"x": x, "y": y, "font-size": _f(em(prim.size)), "font-family": FONT, "fill": "black"},
                "".join(spans))


def _signed_text(drawn: str, xs: list[float], size: float, y: str) -> str:
    """A plain lettering with a sign touching a letter: the lettering in tspans at its letters' own
    x, each such sign unpainted in it, and painted by a text of its own centred on its osifont
    advance — with osifont exactly where it stood; in a viewer without it DejaVu Sans' wider sign
    overhangs both sides alike, into the space ``kern`` keeps (graphic.record.sign_gap)."""
    drawn = _kept_spaces(drawn)
    advance, box = _advances_em()
    spans, signs, start = [], [], 0
    for i in (m.start() for m in _SIGN.finditer(drawn)):
        if i > start:
            spans.append(_tag("tspan", {"x": _xs_attr(xs[start:i])}, _text_escape(drawn[start:i])))
        spans.append(_tag("tspan", {"fill": "none", "x": _f(xs[i])}, _text_escape(drawn[i])))
        mid = xs[i] + em(size) * advance.get(drawn[i], box) / 2
        signs.append(f'<text fill="black" font-family="{_FONT_ATTR}" font-size="{_em_text(size)}" '
                     f'text-anchor="middle" x="{_f(mid)}" y="{y}">{_text_escape(drawn[i])}</text>')
        start = i + 1
    if start < len(drawn):
        spans.append(_tag("tspan", {"x": _xs_attr(xs[start:])}, _text_escape(drawn[start:])))
    return (f'<text fill="black" font-family="{_FONT_ATTR}" font-size="{_em_text(size)}" text-anchor="start" '
            f'x="{_f(xs[0])}" y="{y}">' + "".join(spans) + "</text>" + "".join(signs))


def placed(prim: Primitive) -> tuple[list[tuple[str, bool, float, float, float]], float]:
    """A text primitive typeset (``typeset``) and the x its first piece starts at: the anchor moved
    back by the whole advance for centred and right-aligned text."""
    pieces, total = typeset(prim.text, prim.size)
    return pieces, prim.points[0][0] - {"start": 0.0, "middle": 0.5, "end": 1.0}[prim.anchor] * total


@lru_cache(maxsize=4096)
def typeset(text: str, size: float) -> tuple[list[tuple[str, bool, float, float, float]], float]:
    """The markup typeset: (piece, small, x, baseline shift, advance) per piece, x from the text's
    start by the drawing font's advances (stacked scripts start together), and the whole width."""
    out = []
    pen = start = 0.0
    base = ("", size)        # the last letter set on the baseline, and its size
    level = 0
    for run in runs(text):
        s = size * SMALL if run.level else size
        x = start if run.stacked else pen
        if not run.stacked and run.level == 0:
            x += script_space(level, run.text, size)    # the base letters clear of the index before them
        if run.level == -1 and level == 0 and not run.stacked and base[0] and run.text:
            x += sub_kern(base[0], base[1], run.text[0], s)      # an index beside a P, Г, Т
        level = run.level
        start = x
        if run.level == 0 and run.text:
            base = (run.text[-1], s)
        up = baseline_shift(run.level, size)
        for part in (p for p in _MISSING.split(run.text) if p):
            pieces = [(part, 0.0)] if part in MISSING else kerned(part, round(s, 6))   # a comma set apart
            for piece, extra in pieces:
                x += extra
                adv = _advance(piece, round(s, 6))
                out.append((piece, bool(run.level), x, up, adv))
                x += adv
        pen = max(pen, x)
    return out, pen


def _advance(piece: str, size: float) -> float:
    """How far the pen moves over ``piece`` at letter height ``size`` (mm): the advances of the font
    that draws it, as cairo and browsers set text (graphic.record.plain_width)."""
    return plain_width(piece, size)


def _svg_lettering(text: str) -> str:
    """lettering() keeping the spaces SVG would collapse at a tspan's edges as no-break spaces."""
    out = lettering(text)
    return out.replace(" ", "\u00a0") if out.startswith(" ") or out.endswith(" ") else out


def arc_path(centre, r: float, start: float, end: float, h: float) -> str:
    """An SVG path for a counter-clockwise arc (the y axis flips, so the sweep flag is 0)."""
    sweep = (end - start) % 360.0 or 360.0
    if sweep >= 359.999:
        end = start + 359.99
        sweep = 359.99
    a0, a1 = math.radians(start), math.radians(start + sweep)
    p0 = (centre[0] + r * math.cos(a0), centre[1] + r * math.sin(a0))
    p1 = (centre[0] + r * math.cos(a1), centre[1] + r * math.sin(a1))
    large = 1 if sweep > 180 else 0
    (x0, y0), (x1, y1) = _xy(p0, h), _xy(p1, h)
    return f"M{x0},{y0} A{_f(r)},{_f(r)} 0 {large} 0 {x1},{y1}"


def to_png(svg_text: str, dpi: int = 300) -> bytes:
    """The SVG as PNG (raster.to_png: opaque white, ``dpi`` recorded)."""
    from graphplan.drawing.raster import to_png as png
    return png(svg_text, dpi)


@lru_cache(maxsize=1)
def _font(symbols: bool = False):
    from matplotlib.font_manager import FontProperties

    from graphplan.drawing.fonts import font_path, symbols_path
    return FontProperties(fname=str(symbols_path() if symbols else font_path()))


def text_outline(prim: Primitive, height: float) -> str:
    """The lettering of a text primitive as one SVG path (matplotlib TextPath), in sheet mm."""
    from matplotlib.textpath import TextPath

    pieces = []   # (TextPath, x offset, baseline shift) per run of the markup, by the glyphs' advances
    pen = start = 0.0
    base = ("", prim.size)
    for run, _x, size, up in run_offsets(prim.text, prim.size):
        x_run = start if run.stacked else pen
        if run.level == -1 and not run.stacked and base[0] and run.text:
            x_run += sub_kern(base[0], base[1], run.text[0], size)
        if run.level == 0 and run.text:
            base = (run.text[-1], size)
        start = x = x_run
        for piece in (p for p in _MISSING.split(run.text) if p):     # → ⊥ ∥ … from the symbols' font
            tp = TextPath((0, 0), lettering(piece), size=em(size), prop=_font(symbols=piece in MISSING))
            pieces.append((tp, x, up))
            ext = tp.get_extents()
            x += (ext.x0 + ext.width if len(tp.vertices) else 0.0) + 0.25 * size * piece.endswith(" ")
        pen = max(pen, x)
    boxes = [(tp.get_extents(), dx) for tp, dx, _ in pieces]
    left = min((e.x0 + dx for e, dx in boxes), default=0.0)
    right = max((e.x0 + e.width + dx for e, dx in boxes), default=0.0)
    shift = {"start": 0.0, "middle": -(left + right) / 2, "end": -right}[prim.anchor]
    x0, y0 = prim.points[0]
    parts = []
    for tp, dx, up in pieces:
        for poly in tp.to_polygons(closed_only=True):
            pts = [(x0 + x + dx + shift, y0 + y + up) for x, y in poly]
            if prim.turn:        # turned about the anchor, counter-clockwise
                c, sn = math.cos(math.radians(prim.turn)), math.sin(math.radians(prim.turn))
                pts = [(x0 + c * (x - x0) - sn * (y - y0), y0 + sn * (x - x0) + c * (y - y0)) for x, y in pts]
            if len(pts) < 3:
                continue
            parts.append("M" + " L".join(f"{_f(x)},{_f(height - y)}" for x, y in pts) + " Z")
    return " ".join(parts) or "M0,0"
