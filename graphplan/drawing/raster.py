"""PNG (and, for SVG text from elsewhere, PDF) from the SVG renderer's text (cairosvg on the cairo
library), ready to print. Sheets and key sheets are written to PDF by drawing.pdf, straight from
their records; ``to_pdf`` stays for an SVG document only.

- Lettering: the packaged osifont, found by cairo through fontconfig (fonts.register), with the
  font options fixed (no hinting, grey antialiasing) so the glyphs do not follow the machine's
  fontconfig settings: the same sheet gives the same pixels on every machine.
- PDF: the font embedded (a subset, with its Unicode map: the Cyrillic text is selectable) and the
  creation date fixed, so the bytes depend on the input only.
- PNG: 300 dpi by default, opaque white RGB (no alpha), the resolution in the pHYs chunk (PNG
  specification §11.3.5.3), written row strip by row strip from cairo's buffer (an A1 sheet at
  300 dpi is 9933 × 7016 px).
"""
from __future__ import annotations

import re
import struct
import sys
import zlib

from graphplan.util.errors import GraphplanError

DPI = 300                 # print quality (PNG default)
MAX_PIXELS = 32767        # cairo's largest image side
INCH = 0.0254             # m


def require_cairo():
    """cairosvg, or one clear line when the cairo library is missing."""
    try:
        import cairosvg
        import cairosvg.surface
    except (ImportError, OSError) as err:
        raise GraphplanError("PDF and PNG output need the cairo library, which is not installed "
                             "(Debian/Ubuntu: apt install libcairo2; macOS: brew install cairo); "
                             "SVG and DXF output work without it") from err
    return cairosvg


def _fixed_font_options(context) -> None:
    """Make every font-options change on this cairo context keep: no hinting, no hinted metrics,
    grey antialiasing (cairosvg sets the options at each node; fontconfig would add its own)."""
    import cairocffi as cairo

    plain = context.set_font_options

    def set_font_options(options):
        options.set_hint_style(cairo.HINT_STYLE_NONE)
        options.set_hint_metrics(cairo.HINT_METRICS_OFF)
        options.set_antialias(cairo.ANTIALIAS_GRAY)
        plain(options)

    context.set_font_options = set_font_options


def _surfaces():
    """cairosvg's PDF and PNG surfaces with the lettering fixed (PNG: RGB, written by png_bytes)."""
    require_cairo()
    import cairocffi as cairo
    from cairosvg.surface import PDFSurface, PNGSurface, Surface

    class Lettered:
        def draw(self, node):
            if not getattr(self.context, "_gost", False):
                _fixed_font_options(self.context)
                self.context._gost = True
            super().draw(node)

    class PDF(Lettered, PDFSurface):
        pass

    class PNG(Lettered, PNGSurface):
        def _create_surface(self, width, height):
            w, h = int(round(width)), int(round(height))
            if not 0 < max(w, h) <= MAX_PIXELS:
                raise GraphplanError(f"--dpi {self.dpi:g}: the image would be {w}×{h} px; cairo draws "
                                     f"at most {MAX_PIXELS} px a side")
            surface = cairo.ImageSurface(cairo.FORMAT_RGB24, w, h)
            paper = cairo.Context(surface)     # white to the last pixel row (the sheet may end inside it)
            paper.set_source_rgb(1, 1, 1)
            paper.paint()
            return surface, w, h

        def finish(self):
            self.cairo.flush()
            self.output.write(png_bytes(_rgb(self.cairo), self.dpi))
            return Surface.finish(self)

    return PDF, PNG


def _rgb(surface):
    """cairo's RGB24 buffer (32-bit native-endian 0x00RRGGBB per pixel) as an H×W×3 view."""
    import numpy as np

    w, h, stride = surface.get_width(), surface.get_height(), surface.get_stride()
    px = np.frombuffer(surface.get_data(), np.uint8).reshape(h, stride)[:, :4 * w].reshape(h, w, 4)
    return px[..., 2::-1] if sys.byteorder == "little" else px[..., 1:4]


def _chunk(kind: bytes, data: bytes) -> bytes:
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))


def png_bytes(rgb, dpi: float, strip: int = 256) -> bytes:
    """An 8-bit RGB PNG of the H×W×3 array ``rgb`` with its resolution: pHYs in pixels per metre
    (dpi / 0.0254, unit 1), each row filtered 'None', deflated strip by strip."""
    import numpy as np

    h, w = rgb.shape[:2]
    ppm = round(dpi / INCH)
    head = struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0)
    deflate = zlib.compressobj(6)
    parts = [b"\x89PNG\r\n\x1a\n", _chunk(b"IHDR", head), _chunk(b"pHYs", struct.pack(">IIB", ppm, ppm, 1))]
    data = []
    for top in range(0, h, strip):
        rows = np.ascontiguousarray(rgb[top:top + strip]).reshape(-1, 3 * w)
        lines = np.zeros((rows.shape[0], 3 * w + 1), np.uint8)   # filter byte 0: None
        lines[:, 1:] = rows
        data.append(deflate.compress(lines.tobytes()))
    data.append(deflate.flush())
    parts.append(_chunk(b"IDAT", b"".join(data)))
    parts.append(_chunk(b"IEND", b""))
    return b"".join(parts)


def _prepare(svg_text: str) -> bytes:
    from graphplan.drawing.fonts import register
    register()
    return svg_text.encode("utf-8")


def to_pdf(svg_text: str) -> bytes:
    """The SVG as PDF with the lettering font embedded and cairo's creation date fixed (fixed_date)."""
    pdf, _ = _surfaces()
    return fixed_date(pdf.convert(bytestring=_prepare(svg_text)))


def fixed_date(data: bytes) -> bytes:
    """A PDF with cairo's creation date replaced by one of the same length, 2000-01-01, so the bytes
    depend on the input only (the cross-reference offsets stay right)."""
    return re.sub(rb"/CreationDate \(D:\d{14}[^)]*\)",
                  lambda m: b"/CreationDate (D:20000101000000Z" + b" " * (len(m.group(0)) - 33) + b")",
                  data)


def to_png(svg_text: str, dpi: float = DPI) -> bytes:
    """The SVG as an opaque white RGB PNG at ``dpi`` (recorded in the file)."""
    if not 10 <= dpi <= 2400:
        raise GraphplanError(f"--dpi {dpi:g}: use 10 to 2400 dots per inch (300 to print)")
    _, png = _surfaces()
    return png.convert(bytestring=_prepare(svg_text), dpi=dpi, background_color="white")
