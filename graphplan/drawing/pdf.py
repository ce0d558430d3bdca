"""PDF straight from construction records: each record drawn on a page of a cairo PDF surface
(cairocffi), the way the SVG renderer (drawing.svg) writes it and cairosvg would draw that SVG —
without the round trip through SVG text, which cairosvg parses again and letters glyph by glyph
(0.1–0.4 s a key sheet; this takes about a tenth of that).

- Page: ``width`` × ``height`` mm (1 mm = 72/25.4 pt); the record's y points up, so y is flipped
  here point by point (the lettering is never mirrored).
- Lines: black, the role's width, round caps and joins, the roles' dash patterns (svg.DASHES); a
  vector's arrowhead filled; a joint an open circle, a point a dot.
- Lettering: osifont (drawing.fonts, found by cairo through fontconfig) at the em that gives
  capitals ``size`` mm high, the markup's sub- and superscripts set by ``svg.typeset`` (the same
  pieces and advances as the SVG), → ⊥ ∥ ′ ″ … from the package's symbols' font; the font options
  fixed (no hinting) so a sheet has the same glyph positions on every machine. The font is
  embedded as a subset with its Unicode map (the text is selectable and searchable). Where
  fontconfig is not to be found, the lettering is drawn as the font's outlines (svg.text_outline).
- Several records give a document of several pages (a long summary).
- The creation date is fixed and the title set, so the bytes depend on the input only.
"""
from __future__ import annotations

import io
import math
from collections.abc import Sequence

from graphplan.graphic.record import DASHED_ROLES, Primitive, Record, em, lettering, vector_arrow
from graphplan.drawing.svg import ARROW_FONT, DASHES, FONT, MISSING, placed
from graphplan.util.markup import SMALL

MM = 72.0 / 25.4                      # points per millimetre
_FAMILY = FONT.split(",")[0].strip(" '")             # osifont
_SYMBOLS = ARROW_FONT.split(",")[0].strip(" '")      # the package's symbols' font


def preload() -> None:
    """cairo loaded and the packaged fonts registered with fontconfig (a process that forks
    workers does it once for them all)."""
    from graphplan.drawing.raster import require_cairo
    from graphplan.drawing.fonts import register
    require_cairo()
    import cairocffi  # noqa: F401
    register()


def render_pdf(pages: Sequence[Record], width: float, height: float, title: str = "",
               text_as_paths: bool = False) -> bytes:
    """The records as a PDF of ``width`` × ``height`` mm pages, one record a page; ``text_as_paths``
    letters with the font's outlines instead of text."""
    from graphplan.drawing.raster import fixed_date, require_cairo
    from graphplan.drawing.fonts import register
    require_cairo()
    import cairocffi as cairo
    outlines = not register() or text_as_paths
    out = io.BytesIO()
    surface = cairo.PDFSurface(out, width * MM, height * MM)
    if title:
        surface.set_metadata(cairo.PDF_METADATA_TITLE, title)
    ctx = cairo.Context(surface)
    options = cairo.FontOptions()
    options.set_hint_style(cairo.HINT_STYLE_NONE)
    options.set_hint_metrics(cairo.HINT_METRICS_OFF)
    options.set_antialias(cairo.ANTIALIAS_GRAY)
    ctx.set_font_options(options)
    ctx.scale(MM, MM)
    ctx.set_line_cap(cairo.LINE_CAP_ROUND)
    ctx.set_line_join(cairo.LINE_JOIN_ROUND)
    pen = _Pen(ctx, height, cairo, outlines)
    for k, record in enumerate(pages):
        if k:
            ctx.show_page()
        for prim in record.items:
            pen.draw(prim)
    surface.finish()
    return fixed_date(out.getvalue())    # (cairo 1.16's own metadata date leaves out PDF's "D:")


class _Pen:
    """Draws primitives on a cairo context scaled to mm, flipping y (page y = height − y)."""

    def __init__(self, ctx, height: float, cairo, outlines: bool = False) -> None:
        self.ctx, self.h, self.cairo, self.outlines = ctx, height, cairo, outlines
        self.font: tuple[str, float] | None = None
        self.line: tuple[float, str | None] | None = None     # the width and dashes set last
        ctx.set_source_rgb(0, 0, 0)        # black throughout (a joint's white fill restores it)

    def xy(self, p) -> tuple[float, float]:
        return p[0], self.h - p[1]

    def stroke(self, prim: Primitive) -> None:
        self.pen(prim.line_width, DASHED_ROLES.get(prim.role))
        self.ctx.stroke()

    def pen(self, width: float, dash: str | None) -> None:
        """The line's width and dash pattern, set only when they change."""
        if self.line != (width, dash):
            self.ctx.set_line_width(width)
            self.ctx.set_dash([float(v) for v in DASHES[dash].split(",")] if dash else [])
            self.line = (width, dash)

    def draw(self, prim: Primitive) -> None:
        ctx, k = self.ctx, prim.kind
        if k == "text":
            self.text(prim)
            return
        ctx.new_path()
        if k == "segment":
            ctx.move_to(*self.xy(prim.points[0]))
            ctx.line_to(*self.xy(prim.points[1]))
            self.stroke(prim)
        elif k == "vector":
            a, b = prim.points
            tip, end = vector_arrow(a, b, prim.line_width, prim.role == "head")
            ctx.move_to(*self.xy(a))
            ctx.line_to(*self.xy(end))
            self.stroke(prim)
            self.polygon(tip)
            ctx.fill()
        elif k in ("polyline", "polygon"):
            self.polygon(prim.points, closed=k == "polygon")
            self.stroke(prim)
        elif k == "circle":
            ctx.arc(*self.xy(prim.points[0]), prim.radius, 0.0, 2 * math.pi)
            ctx.close_path()
            self.stroke(prim)
        elif k == "arc":
            self.arc(prim)
            self.stroke(prim)
        elif k == "point":
            joint = prim.role == "joint"
            ctx.arc(*self.xy(prim.points[0]), 1.0 if joint else 0.6, 0.0, 2 * math.pi)
            ctx.close_path()
            if joint:
                ctx.set_source_rgb(1, 1, 1)
            ctx.fill_preserve()
            ctx.set_source_rgb(0, 0, 0)
            self.pen(0.35, None)
            ctx.stroke()

    def polygon(self, points, closed: bool = True) -> None:
        ctx = self.ctx
        ctx.move_to(*self.xy(points[0]))
        for p in points[1:]:
            ctx.line_to(*self.xy(p))
        if closed:
            ctx.close_path()

    def arc(self, prim: Primitive) -> None:
        """Counter-clockwise from the start angle to the end (svg.arc_path's sweep; y flipped, so
        cairo draws it with decreasing angles)."""
        start, end = prim.angles
        sweep = (end - start) % 360.0 or 360.0
        sweep = min(sweep, 359.99)
        (cx, cy), r = self.xy(prim.points[0]), prim.radius
        self.ctx.arc_negative(cx, cy, r, -math.radians(start), -math.radians(start + sweep))

    def use_font(self, family: str, size: float) -> None:
        if self.font != (family, size):
            self.ctx.select_font_face(family, self.cairo.FONT_SLANT_NORMAL, self.cairo.FONT_WEIGHT_NORMAL)
            self.ctx.set_font_size(size)
            self.font = (family, size)

    def text(self, prim: Primitive) -> None:
        """The lettering set as svg.typeset sets it: each piece at its x and baseline, from the
        text's start (the anchor moved back by the whole advance)."""
        ctx = self.ctx
        if self.outlines:
            self.outline(prim)
            return
        pieces, x_start = placed(prim)
        size = em(prim.size)
        if prim.turn:                     # turned about the anchor (the page's y runs down)
            ctx.save()
            ax, ay = self.xy(prim.points[0])
            ctx.translate(ax, ay)
            ctx.rotate(-math.radians(prim.turn))
            ctx.translate(-ax, -ay)
        for piece, small, x0, up, _advance in pieces:
            missing = piece in MISSING
            self.use_font(_SYMBOLS if missing else _FAMILY, size * SMALL if small else size)
            ctx.move_to(*self.xy((x_start + x0, prim.points[0][1] + up)))
            ctx.show_text(piece if missing else lettering(piece))
        if prim.turn:
            ctx.restore()

    def outline(self, prim: Primitive) -> None:
        """The lettering as filled outlines of the font's glyphs (svg.text_outline's polygons,
        already in page coordinates)."""
        from graphplan.drawing.svg import text_outline
        ctx = self.ctx
        ctx.new_path()
        for part in text_outline(prim, self.h).split("M")[1:]:
            points = [tuple(map(float, xy.split(","))) for xy in part.replace("Z", "").split(" L")]
            ctx.move_to(*points[0])
            for x, y in points[1:]:
                ctx.line_to(x, y)
            ctx.close_path()
        ctx.fill()
