"""The SVG renderer as it was written with svgwrite's objects (svgwrite.Drawing, its Inkscape
extension, ElementTree's serializer): the oracle drawing.svg.render's text must equal byte for byte.

One intended difference from the renderer svgwrite once drove: every letter of a text of two or more
lower than 5 mm (or not centred) carries its own x (the packaged font's advances summed here from ``plain_width`` of each prefix), the
text anchored at its start, so that a viewer without the embedded font sets each word where it was measured (issue 32)."""
from __future__ import annotations

import re

from graphplan.drawing.svg import (ARROW_FONT, DASHES, FONT, MISSING, _f, arc_path, text_outline,
                                   typeset as _set)
from graphplan.graphic.record import (LAYERS, DASHED_ROLES, Primitive, Record, em, kerned, lettering,
                                      plain_width, vector_arrow)
from graphplan.util.markup import SMALL, is_plain

_MISSING = re.compile(f"([{MISSING}])")
SIGNS = "+=±×"
# a sign touching a letter (no blank beside it): painted by a text of its own centred on its advance,
# unpainted in the lettering (drawing.svg's _signed_text, graphic.record.sign_gap)
_SIGN = re.compile(r"(?<=\S)([+=±×])|([+=±×])(?=\S)")


def reference_render(record: Record, width: float, height: float, title: str = "", text_as_paths: bool = False,
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
        tip, end = vector_arrow(a, b, prim.line_width, prim.role == "head")
        yield dwg.line(_xy(a, h), _xy(end, h), **_stroke(prim))
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
        yield from _text(dwg, prim, h)




def _text(dwg, prim: Primitive, h: float):
    """A text element; the markup's sub- and superscripts (util.markup) as <tspan>s at 0.7 of the
    size with their baselines shifted by dy (and stacked ones moved back by dx), the arrow → in a
    font that has it."""
    if is_plain(prim.text) and not _MISSING.search(prim.text):
        drawn = lettering(prim.text)
        x0 = prim.points[0][0] - {"start": 0.0, "middle": 0.5, "end": 1.0}[prim.anchor] * \
            plain_width(prim.text, prim.size)
        y = _xy(prim.points[0], h)[1]
        if _SIGN.search(drawn):
            kept = _nbsp(drawn)
            xs = _xs(drawn, prim.size, x0).split()
            el = dwg.text("", x=[xs[0]], y=[y], font_size=_f(em(prim.size)), font_family=FONT,
                          text_anchor="start", fill="black")
            signs, start = [], 0
            for i in (m.start() for m in _SIGN.finditer(kept)):
                if i > start:
                    el.add(dwg.tspan(kept[start:i], x=[" ".join(xs[start:i])]))
                el.add(dwg.tspan(kept[i], x=[xs[i]], fill="none"))
                left = x0 + plain_width(drawn[:i + 1], prim.size) - plain_width(drawn[i], prim.size)
                signs.append(dwg.text(kept[i], x=[_f(left + plain_width(drawn[i], prim.size) / 2)], y=[y],
                                      font_size=_f(em(prim.size)), font_family=FONT, text_anchor="middle",
                                      fill="black"))
                start = i + 1
            if start < len(kept):
                el.add(dwg.tspan(kept[start:], x=[" ".join(xs[start:])]))
            return [el] + signs
        el = dwg.text(_nbsp(drawn), x=[_xs(drawn, prim.size, x0) or _f(x0)], y=[y],
                      font_size=_f(em(prim.size)), font_family=FONT, text_anchor="start", fill="black")
        return [el]
    # anchored at its start by the font's own advances: cairosvg (PDF, PNG) misplaces the <tspan>s
    # of a centred or right-aligned text
    pieces, total = _set(prim.text, prim.size)
    x_start = prim.points[0][0] - {"start": 0.0, "middle": 0.5, "end": 1.0}[prim.anchor] * total
    el = dwg.text("", insert=_xy((x_start, prim.points[0][1]), h), font_size=_f(em(prim.size)), font_family=FONT,
                  fill="black")
    shift = 0.0    # the baseline shift (mm up)
    for piece, small, x0, up, advance in pieces:
        kw = {}
        if up != shift:
            kw["dy"] = [_f(shift - up)]
        if small:
            kw["font_size"] = _f(em(prim.size) * SMALL)
        if piece in MISSING:
            kw["font_family"] = ARROW_FONT
        drawn = piece if piece in MISSING else lettering(piece)
        kw["x"] = [_xs(drawn, prim.size * SMALL if small else prim.size, x_start + x0)]
        el.add(dwg.tspan(_nbsp(drawn), **kw))
        shift = up
    return [el]


def _xs(drawn: str, size: float, x0: float) -> str:
    """Each letter's x: ``x0`` plus the width of the letters up to it and its own kern, less its own
    advance."""
    return " ".join(_f(x0 + plain_width(drawn[:i + 1], size) - plain_width(drawn[i], size))
                    for i in range(len(drawn)))


def _nbsp(drawn: str) -> str:
    """Spaces SVG would strip or collapse (at the ends, after a space) as no-break spaces."""
    return "".join("\u00a0" if c == " " and (i in (0, len(drawn) - 1) or drawn[i - 1] in " \u00a0") else c
                   for i, c in enumerate(drawn))
