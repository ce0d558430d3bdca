"""The lettering font that comes with the package: osifont, an ISO 3098 / GOST 2.304 type B font
(GPL-3 with the font exception; graphplan/data/fonts/osifont-LICENSE.txt).

Every output letters with this one file, so a sheet looks the same on a fresh machine as in the
gallery: SVG embeds the glyphs it uses (``face_css``), PDF and PNG find it through fontconfig
(``register``), outlines (``--text-as-paths``) are cut from it, and the DXF text style names it.
"""
from __future__ import annotations

import base64
import io
from functools import lru_cache
from importlib import resources
from pathlib import Path

FAMILY = "osifont"
FONT_FILE = "osifont.ttf"
SYMBOLS_FAMILY = "graphplan symbols"      # → ⊥ ∥ ′ ″ …, which osifont lacks: a subset of DejaVu Sans,
SYMBOLS_FILE = "graphplan-symbols.ttf"    # renamed as its licence asks (graphplan-symbols-LICENSE.txt)


def font_path(name: str = FONT_FILE) -> Path:
    """A packaged TTF (graphplan/data/fonts/): osifont, or the symbols' font."""
    return Path(str(resources.files("graphplan") / "data" / "fonts" / name))


def symbols_path() -> Path:
    """The packaged symbols' font (→ ⊥ ∥ ′ ″ …)."""
    return font_path(SYMBOLS_FILE)


SYMBOLS = "→⊥∥′″…"      # what the symbols' font draws


@lru_cache(maxsize=64)
def _woff_subset(chars: str, name: str = FONT_FILE) -> bytes:
    """The font cut down to ``chars`` (glyph outlines and hinting unaltered), as WOFF; the same
    characters give the same bytes (no timestamps)."""
    from fontTools import subset
    from fontTools.ttLib import TTFont

    options = subset.Options()
    options.layout_features = ["kern"]
    options.name_IDs = [0, 1, 2, 13, 14]          # copyright, family, style, licence, its address
    options.drop_tables += ["FFTM"]
    font = TTFont(str(font_path(name)), recalcTimestamp=False)
    cutter = subset.Subsetter(options)
    cutter.populate(text=chars)
    cutter.subset(font)
    font.flavor = "woff"
    out = io.BytesIO()
    font.save(out, reorderTables=True)
    return out.getvalue()


def face_css(chars: str) -> str:
    """A CSS ``@font-face`` rule carrying the glyphs of ``chars`` as a data URI, so a browser letters
    the SVG with osifont even where it is not installed (about 10 KB for a whole sheet)."""
    chars = "".join(sorted(set(chars) - set("\n\t")))
    faces = [(FAMILY, FONT_FILE, chars)]
    symbols = "".join(c for c in chars if c in SYMBOLS)
    if symbols:
        faces.append((SYMBOLS_FAMILY, SYMBOLS_FILE, symbols))
    css = []
    for family, name, text in faces:
        data = base64.b64encode(_woff_subset(text, name)).decode("ascii")
        css.append(f"@font-face{{font-family:'{family}';font-style:normal;font-weight:normal;"
                   f"src:url(data:font/woff;base64,{data}) format('woff')}}")
    return "".join(css)


@lru_cache(maxsize=1)
def register() -> bool:
    """Add the packaged font to fontconfig's current configuration (the one cairo uses), so cairo
    finds ``osifont`` by name even on a machine without any system fonts. Works before or after
    cairo has loaded; False where fontconfig is not to be found (then letter with outlines)."""
    import ctypes
    import ctypes.util

    name = ctypes.util.find_library("fontconfig")
    if not name:
        return False
    try:
        fc = ctypes.CDLL(name)
    except OSError:
        return False
    fc.FcConfigAppFontAddFile.argtypes = [ctypes.c_void_p, ctypes.c_char_p]
    fc.FcConfigAppFontAddFile.restype = ctypes.c_int
    return all([bool(fc.FcConfigAppFontAddFile(None, str(p).encode())) for p in (font_path(), symbols_path())])
