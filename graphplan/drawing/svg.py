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

from graphplan.graphic.record import (LAYERS, DASHED_ROLES, Primitive, Record, arrowhead, em, kerned, lettering,
                                      plain_width, run_offsets, sub_kern)
from graphplan.util.markup import SMALL, SUB_SHIFT, SUP_SHIFT, is_plain, runs

FONT = "osifont, 'DejaVu Sans', sans-serif"
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


def render(record: Record, width: float, height: float, title: str = "", text_as_paths: bool = False,
           embed_font: bool = True) -> str:
    """The record as an SVG document of ``width`` × ``height`` mm (y of the record points up).
    ``text_as_paths`` writes lettering as outlines, for importers that drop text; otherwise text stays
    text (searchable, selectable) and ``embed_font`` carries the glyphs it uses (fonts.face_css)."""
    import svgwrite
    from svgwrite.extensions import Inkscape

    dwg = svgwrite.Drawing(size=(f"{_f(width)}mm", f"{_f(height)}mm"), profile="full", debug=False)
    dwg["viewBox"] = f"0 0 {_f(width)} {_f(height)}"
    ink = Inkscape(dwg)
    if title:
        dwg.set_desc(title=title)
    layers = {}
    for name in LAYERS:
        layers[name] = ink.layer(label=name, id=f"layer-{name}")
    for prim in record.items:
        layer = layers.get(prim.layer) or layers.setdefault(prim.layer, ink.layer(label=prim.layer,
                                                                                 id=f"layer-{prim.layer}"))
        if text_as_paths and prim.kind == "text":
            layer.add(dwg.path(d=text_outline(prim, height), fill="black", stroke="none"))
            continue
        for element in _elements(dwg, prim, height):
            layer.add(element)
    for name, layer in layers.items():
        if layer.elements:
            dwg.add(layer)
    chars = _lettered(dwg)
    if embed_font and chars:
        from graphplan.drawing.fonts import face_css
        dwg.defs.add(dwg.style(face_css(chars)))
    return dwg.tostring()


def _lettered(element) -> str:
    """Every character the document letters (text and its spans)."""
    own = getattr(element, "text", None)
    inner = "".join(_lettered(e) for e in getattr(element, "elements", ()))
    return (own if isinstance(own, str) else "") + inner


def _xy(p, height: float) -> tuple[str, str]:
    return _f(p[0]), _f(height - p[1])


def _stroke(prim: Primitive) -> dict:
    style = {"stroke": "black", "stroke_width": _f(prim.line_width), "fill": "none",
             "stroke_linecap": "round", "stroke_linejoin": "round"}
    dash = DASHED_ROLES.get(prim.role)
    if dash:
        style["stroke_dasharray"] = DASHES[dash]
    return style


def _elements(dwg, prim: Primitive, h: float):
    k = prim.kind
    if k == "segment":
        (x1, y1), (x2, y2) = (_xy(p, h) for p in prim.points)
        yield dwg.line((x1, y1), (x2, y2), **_stroke(prim))
    elif k == "vector":
        a, b = prim.points
        tip = arrowhead(a, b, length=3.0 if prim.line_width >= 0.5 else 2.5)
        yield dwg.line(_xy(a, h), _xy(tip[0], h), **_stroke(prim))
        yield dwg.polygon([_xy(p, h) for p in tip], fill="black", stroke="none")
    elif k in ("polyline", "polygon"):
        pts = [_xy(p, h) for p in prim.points]
        yield (dwg.polygon if k == "polygon" else dwg.polyline)(pts, **_stroke(prim))
    elif k == "circle":
        yield dwg.circle(_xy(prim.points[0], h), _f(prim.radius), **_stroke(prim))
    elif k == "arc":
        yield dwg.path(d=arc_path(prim.points[0], prim.radius, *prim.angles, h), **_stroke(prim))
    elif k == "point":
        r = 0.6 if prim.role != "joint" else 1.0
        style = {"fill": "white" if prim.role == "joint" else "black", "stroke": "black",
                 "stroke_width": _f(0.35)}
        yield dwg.circle(_xy(prim.points[0], h), _f(r), **style)
    elif k == "text":
        yield _text(dwg, prim, h)


ARROW_FONT = "'graphplan symbols', 'DejaVu Sans', sans-serif"   # osifont has no → ⊥ ∥ ′ ″ …: those in the
MISSING = "→⊥∥′″…"                                              # package's symbols' font (drawing.fonts)
_MISSING = re.compile(f"([{MISSING}])")


def _text(dwg, prim: Primitive, h: float):
    """A text element; the markup's sub- and superscripts (util.markup) as <tspan>s at 0.7 of the
    size with their baselines shifted by dy (and stacked ones moved back by dx), the arrow → in a
    font that has it."""
    anchor = {"start": "start", "middle": "middle", "end": "end"}[prim.anchor]
    if is_plain(prim.text) and not _MISSING.search(prim.text) and len(kerned(prim.text, prim.size)) == 1:
        return dwg.text(lettering(prim.text), insert=_xy(prim.points[0], h), font_size=_f(em(prim.size)),
                        font_family=FONT, text_anchor=anchor, fill="black")
    # anchored at its start by the font's own advances: cairosvg (PDF, PNG) misplaces the <tspan>s
    # of a centred or right-aligned text
    pieces, total = _set(prim.text, prim.size)
    x_start = prim.points[0][0] - {"start": 0.0, "middle": 0.5, "end": 1.0}[prim.anchor] * total
    el = dwg.text("", insert=_xy((x_start, prim.points[0][1]), h), font_size=_f(em(prim.size)), font_family=FONT,
                  fill="black")
    shift = pen = 0.0    # the baseline shift (mm up) and the pen's x so far
    for piece, small, x0, up, advance in pieces:
        kw = {}
        if up != shift:
            kw["dy"] = [_f(shift - up)]
        if abs(x0 - pen) > 1e-6:
            kw["dx"] = [_f(x0 - pen)]
        if small:
            kw["font_size"] = _f(em(prim.size) * SMALL)
        if piece in MISSING:
            kw["font_family"] = ARROW_FONT
        el.add(dwg.tspan(piece if piece in MISSING else _svg_lettering(piece), **kw))
        shift, pen = up, x0 + advance
    return el


@lru_cache(maxsize=4096)
def _set(text: str, size: float) -> tuple[list[tuple[str, bool, float, float, float]], float]:
    """The markup typeset: (piece, small, x, baseline shift, advance) per piece, x from the text's
    start by the drawing font's advances (stacked scripts start together), and the whole width."""
    out = []
    pen = start = 0.0
    base = ("", size)        # the last letter set on the baseline, and its size
    for run in runs(text):
        s = size * SMALL if run.level else size
        x = start if run.stacked else pen
        if run.level == -1 and not run.stacked and base[0] and run.text:
            x += sub_kern(base[0], base[1], run.text[0], s)      # an index beside a P, Г, Т
        start = x
        if run.level == 0 and run.text:
            base = (run.text[-1], s)
        up = {0: 0.0, -1: -SUB_SHIFT * size, 1: SUP_SHIFT * size}[run.level]
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


def to_pdf(svg_text: str) -> bytes:
    """The SVG as PDF (raster.to_pdf: the packaged font embedded)."""
    from graphplan.drawing.raster import to_pdf as pdf
    return pdf(svg_text)


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
            if len(pts) < 3:
                continue
            parts.append("M" + " L".join(f"{_f(x)},{_f(height - y)}" for x, y in pts) + " Z")
    return " ".join(parts) or "M0,0"
