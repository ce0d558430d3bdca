"""Where a sheet's elements stand, read off its SVG alone (independent of the records' geometry):
each word's ink box from its glyphs' x positions, its baseline and the glyphs' outlines in the font
file (fontTools), each line's, circle's and polygon's box from its coordinates — and which of them
leave the drawing field (the frame's inside, the title block kept clear). The invariant a teacher holds first: every element
inside the frame, none on the title block but the block's own."""
from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from functools import lru_cache

NS = "{http://www.w3.org/2000/svg}"
LABEL = "{http://www.inkscape.org/namespaces/inkscape}label"
NUMBER = re.compile(r"-?\d+(?:\.\d+)?(?:e-?\d+)?")


def _floats(text: str | None) -> list[float]:
    return [float(v) for v in NUMBER.findall(text or "")]


@lru_cache(maxsize=1)
def _faces():
    """The packaged fonts' glyphs (osifont, then the symbols' font): char → (advance, xMin, yMin,
    xMax, yMax) per em, read with fontTools from the TTF files."""
    from fontTools.ttLib import TTFont

    from graphplan.drawing.fonts import SYMBOLS_FILE, font_path
    out: dict[str, tuple[float, float, float, float, float]] = {}
    for name in (SYMBOLS_FILE, "osifont.ttf"):         # osifont's own glyphs last: they win
        font = TTFont(str(font_path(name)))
        upm = font["head"].unitsPerEm
        glyf, hmtx = font["glyf"], font["hmtx"]
        for code, g in font.getBestCmap().items():
            gl = glyf[g]
            adv = hmtx[g][0] / upm
            box = (gl.xMin / upm, gl.yMin / upm, gl.xMax / upm, gl.yMax / upm) if hasattr(gl, "xMin") \
                else (0.0, 0.0, 0.0, 0.0)
            out[chr(code)] = (adv, *box)
    return out


FALLBACK = (0.6, 0.0, -0.2, 0.6, 0.8)      # a glyph neither font has (the viewer's fallback), per em


def _text_box(el) -> tuple[float, float, float, float] | None:
    """A text element's ink box (x0, y0, x1, y1), mm, y down: each glyph's outline box from the font
    file at its x (the text's and its tspans' x lists; else one after another by their advances), its
    baseline (a tspan's dy) and its font size; None for an empty text."""
    faces = _faces()
    anchor = el.get("text-anchor", "start")
    boxes: list[tuple[float, float, float, float]] = []

    def take(node, size: float, y: float, text: str) -> None:
        xs = _floats(node.get("x"))
        glyphs = [faces.get(c, FALLBACK) for c in text]
        if not glyphs:
            return
        if len(xs) < len(glyphs):                 # one x: the glyphs one after another
            x = xs[0] if xs else 0.0
            width = sum(g[0] for g in glyphs) * size
            x -= width / 2 if anchor == "middle" else width if anchor == "end" else 0.0
            xs = []
            for g in glyphs:
                xs.append(x)
                x += g[0] * size
        for x, (c, g) in zip(xs, zip(text, glyphs)):
            if c.isspace():
                continue
            _, gx0, gy0, gx1, gy1 = g
            boxes.append((x + gx0 * size, y - gy1 * size, x + gx1 * size, y - gy0 * size))

    size = float(el.get("font-size", "3.5"))
    y = (_floats(el.get("y")) or [0.0])[0]
    take(el, size, y, el.text or "")
    for sp in el.iter(f"{NS}tspan"):
        y += (_floats(sp.get("dy")) or [0.0])[0]
        take(sp, float(sp.get("font-size", size)), y, sp.text or "")
    if not boxes:
        return None
    return (min(b[0] for b in boxes), min(b[1] for b in boxes), max(b[2] for b in boxes), max(b[3] for b in boxes))


def _shape_box(el) -> tuple[float, float, float, float] | None:
    tag = el.tag.removeprefix(NS)
    if tag == "line":
        xs = [float(el.get("x1", 0)), float(el.get("x2", 0))]
        ys = [float(el.get("y1", 0)), float(el.get("y2", 0))]
    elif tag in ("polyline", "polygon"):
        v = _floats(el.get("points"))
        xs, ys = v[0::2], v[1::2]
    elif tag == "circle":
        cx, cy, r = (float(el.get(k, 0)) for k in ("cx", "cy", "r"))
        xs, ys = [cx - r, cx + r], [cy - r, cy + r]
    elif tag == "path":                # the lines' paths: M/L/A/C numbers, absolute (drawing.svg)
        v = _floats(re.sub(r"[Aa]\s*([^A-Za-z]*)", lambda m: " ".join(_arc_end(m.group(1))), el.get("d", "")))
        xs, ys = v[0::2], v[1::2]
    else:
        return None
    if not xs or not ys:
        return None
    return min(xs), min(ys), max(xs), max(ys)


def _arc_end(args: str) -> list[str]:
    """An arc's end points only (its radii, rotation and flags are not coordinates)."""
    v = NUMBER.findall(args)
    return [f"{v[k + 5]} {v[k + 6]}" for k in range(0, len(v) - 6, 7)]


def _turned(box, transform: str | None):
    """A text's ink box turned as its ``transform="rotate(a cx cy)"`` turns it (drawing.svg writes
    no other transform on lettering: a vertical dimension's number): the box of the turned corners,
    the viewer's, not the unturned line's (the aw dimension on an A3 read 1.2 mm past the frame
    while its turned number stood 13 mm inside)."""
    if box is None or not transform:
        return box
    m = re.fullmatch(r"\s*rotate\(([^)]*)\)\s*", transform)
    assert m, f"a transform the checker does not read: {transform!r}"
    v = _floats(m.group(1))
    import math
    a = math.radians(v[0])
    cx, cy = (v[1], v[2]) if len(v) == 3 else (0.0, 0.0)
    c, s = math.cos(a), math.sin(a)
    pts = [(cx + (x - cx) * c - (y - cy) * s, cy + (x - cx) * s + (y - cy) * c)
           for x in (box[0], box[2]) for y in (box[1], box[3])]
    return (min(p[0] for p in pts), min(p[1] for p in pts), max(p[0] for p in pts), max(p[1] for p in pts))


def elements(svg: str) -> list[tuple[str, str, tuple[float, float, float, float]]]:
    """(layer, what, box) of every drawn element outside the layer ``frame``: a text's words or a
    shape's tag, its box in mm, y down (the SVG's own)."""
    root = ET.fromstring(svg)
    out = []
    for layer in root.iter(f"{NS}g"):
        name = layer.get(LABEL, "")
        if name == "frame":
            continue
        for el in layer:
            tag = el.tag.removeprefix(NS)
            if tag == "text":
                b = _turned(_text_box(el), el.get("transform"))
                if b is not None:
                    out.append((name, "".join(el.itertext()), b))
            else:
                b = _shape_box(el)
                if b is not None:
                    out.append((name, tag, b))
    return out


def off_field(svg: str, form, tolerance: float = 0.3, later: bool = False) -> list[str]:
    """The elements of a sheet (its SVG) that leave the drawing field (the frame's inside, clear of
    its line by ``compose.INSET``) or stand on the title block (``later``: a set's later sheet,
    form 2a): ``"tables 'R54' at (846.5, 17.2, 852.2, 21.3) outside
    the field"``; empty when none. ``tolerance`` mm (half a stroke)."""
    from graphplan.sheets.compose import field_of
    from graphplan.sheets.form import BLOCK_2A_H, title_block_box
    h = form.height
    fx0, fy0, fx1, fy1 = field_of(form)
    bx0, by0, bx1, by1 = title_block_box(form)
    by1 = by0 + BLOCK_2A_H if later else by1
    field = (fx0, h - fy1, fx1, h - fy0)          # y down, as the SVG's
    block = (bx0, h - by1, bx1, h - by0)
    out = []
    for layer, what, (x0, y0, x1, y1) in elements(svg):
        outside = x0 < field[0] - tolerance or y0 < field[1] - tolerance or x1 > field[2] + tolerance \
            or y1 > field[3] + tolerance
        on_block = x1 > block[0] + tolerance and y1 > block[1] + tolerance
        if outside or on_block:
            out.append(f"{layer} {what!r} at ({x0:.1f}, {y0:.1f}, {x1:.1f}, {y1:.1f})"
                       + (" outside the field" if outside else " on the title block"))
    return out
