"""SVG renderer of construction records, in true millimetres (REFERENCE §3).

Root ``width="Wmm" height="Hmm" viewBox="0 0 W H"``, unitless coordinates, stroke widths in user
units (= mm), ``fill="none"`` on strokes, no transforms, one Inkscape layer per kind, deterministic.
Lettering stays text (searchable) in osifont, whose glyphs the document carries (drawing.fonts), or,
with ``text_as_paths``, outlines cut from the same font.
"""
from __future__ import annotations

import math
from functools import lru_cache

from graphplan.graphic.record import LAYERS, DASHED_ROLES, Primitive, Record, arrowhead, lettering

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
        anchor = {"start": "start", "middle": "middle", "end": "end"}[prim.anchor]
        yield dwg.text(lettering(prim.text), insert=_xy(prim.points[0], h), font_size=_f(prim.size),
                       font_family=FONT, text_anchor=anchor, fill="black")


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
def _font():
    from matplotlib.font_manager import FontProperties

    from graphplan.drawing.fonts import font_path
    return FontProperties(fname=str(font_path()))


def text_outline(prim: Primitive, height: float) -> str:
    """The lettering of a text primitive as one SVG path (matplotlib TextPath), in sheet mm."""
    from matplotlib.textpath import TextPath

    tp = TextPath((0, 0), lettering(prim.text), size=prim.size, prop=_font())
    ext = tp.get_extents()
    shift = {"start": 0.0, "middle": -ext.width / 2 - ext.x0, "end": -ext.width - ext.x0}[prim.anchor]
    x0, y0 = prim.points[0]
    parts = []
    for poly in tp.to_polygons(closed_only=True):
        pts = [(x0 + x + shift, y0 + y) for x, y in poly]
        if len(pts) < 3:
            continue
        parts.append("M" + " L".join(f"{_f(x)},{_f(height - y)}" for x, y in pts) + " Z")
    return " ".join(parts) or "M0,0"
