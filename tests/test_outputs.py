"""Outputs as a print shop and a CAD program take them: the packaged GOST lettering in SVG, PDF and
PNG on a machine without fonts; PNG at 300 dpi, opaque white, with pHYs; PDF with the font embedded
and Cyrillic text; DXF with the sheet's limits, extents and paper-space layout, two text styles and
the same bytes under every PYTHONHASHSEED; LibreCAD printing it on its own format."""
from __future__ import annotations

import base64
import html
import io
import os
import re
import shutil
import struct
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from conftest import ROOT, example_sheet
from graphplan.drawing.fonts import FAMILY, font_path

BARE_FONTCONFIG = """<?xml version="1.0"?>
<!DOCTYPE fontconfig SYSTEM "urn:fontconfig:fonts.dtd">
<fontconfig><cachedir>{cache}</cachedir></fontconfig>
"""


def sheet(name: str = "crank_slider", fmt: str = "A1", lang: str = "uk"):
    """The example's kinematics sheet, shared with the other modules that read it (``conftest.example_sheet``)."""
    return example_sheet(name, "kinematics", fmt, lang)


@pytest.fixture(scope="module")
def a1():
    """The built-in crank-slider on A1, Ukrainian."""
    return sheet()


def run(code: str, env: dict | None = None, cwd: Path = ROOT) -> subprocess.CompletedProcess:
    """``code`` in a fresh interpreter that imports this checkout's graphplan."""
    full = {**os.environ, "PYTHONPATH": str(ROOT), **(env or {})}
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=full,
                          cwd=cwd, timeout=300)


def grey(png: bytes) -> np.ndarray:
    from PIL import Image
    return np.asarray(Image.open(io.BytesIO(png)).convert("L"), dtype=float)


def chunks(png: bytes) -> dict[bytes, bytes]:
    """The PNG's chunks by type (the last of each), read by the specification's layout."""
    out, at = {}, 8
    while at < len(png):
        (n,) = struct.unpack(">I", png[at:at + 4])
        out[png[at + 4:at + 8]] = png[at + 8:at + 8 + n]
        at += 12 + n
    return out


# -- lettering ------------------------------------------------------------------------------------

def test_the_font_and_its_licence_ship_in_the_package():
    from fontTools.ttLib import TTFont
    folder = font_path().parent
    font = TTFont(str(font_path()))
    assert font["name"].getDebugName(1) == FAMILY
    cmap = font.getBestCmap()
    assert all(ord(c) in cmap for c in "План швидкостей μl ωε°²·№ ABCabc0123456789")
    licence = (folder / "osifont-LICENSE.txt").read_text(encoding="utf-8")
    assert "special exception" in licence and "GPL-3.txt" in licence
    assert "GNU GENERAL PUBLIC LICENSE" in (folder / "GPL-3.txt").read_text(encoding="utf-8")
    pyproject = (ROOT / "pyproject.toml").read_text(encoding="utf-8")
    assert '"data/fonts/*"' in pyproject


def test_svg_keeps_real_text_and_embeds_the_glyphs_it_uses(a1):
    from fontTools.ttLib import TTFont
    from graphplan.drawing.svg import render
    from graphplan.graphic.record import Record
    svg = a1.svg()
    texts = re.findall(r"<text\b[^>]*>(.*?)</text>", svg, re.S)
    assert any("План швидкостей" in t for t in texts)          # searchable, selectable
    found = re.search(r"@font-face\{font-family:'osifont'[^}]*base64,([A-Za-z0-9+/=]+)\)", svg)
    assert found, "no embedded font"
    data = base64.b64decode(found.group(1))
    assert len(data) < 20_000                                     # a subset, not the 116 KB font
    face = TTFont(io.BytesIO(data))
    assert face["name"].getDebugName(1) == FAMILY
    lettered = set(html.unescape("".join(re.sub(r"<[^>]+>", "", t) for t in texts))) - {" "}
    missing = {c for c in lettered if ord(c) not in face.getBestCmap()}
    whole = {c for c in missing if ord(c) in TTFont(str(font_path())).getBestCmap()}
    assert not whole, f"characters the font has but the subset lacks: {sorted(whole)}"
    small = Record("t")
    small.label((10, 10), "План швидкостей")
    outlined = render(small, 100, 30, text_as_paths=True)
    assert "@font-face" not in outlined and "<text" not in outlined and "<path" in outlined


def test_sheet_without_system_fonts_matches_the_gallery(tmp_path):
    """The committed gallery sheet rasterised here and in a process whose fontconfig knows no font
    at all: the same pixels (and the bare process's PDF embeds osifont). The same bare process with
    plain cairosvg letters boxes instead: the test sees a missing font."""
    from graphplan.drawing.raster import to_png
    gallery = ROOT / "drawings" / "shaper.svg"
    conf = tmp_path / "fonts.conf"
    conf.write_text(BARE_FONTCONFIG.format(cache=tmp_path / "cache"), encoding="utf-8")
    env = {"FONTCONFIG_FILE": str(conf)}
    here = grey(to_png(gallery.read_text(encoding="utf-8"), dpi=60))
    out = tmp_path / "bare.png"
    pdf = tmp_path / "bare.pdf"
    done = run(f"from graphplan.drawing.raster import to_pdf, to_png\n"
               f"svg = open({str(gallery)!r}, encoding='utf-8').read()\n"
               f"open({str(out)!r}, 'wb').write(to_png(svg, dpi=60))\n"
               f"open({str(pdf)!r}, 'wb').write(to_pdf(svg))", env=env)
    assert done.returncode == 0, done.stderr
    assert b"+osifont" in pdf.read_bytes() and b"/FontFile2" in pdf.read_bytes()
    there = grey(out.read_bytes())
    assert there.shape == here.shape
    assert np.abs(there - here).mean() < 0.05 and (there != here).mean() < 0.001
    plain = tmp_path / "plain.png"
    control = run(f"import cairosvg\ncairosvg.svg2png(url={str(gallery)!r}, write_to={str(plain)!r}, dpi=60,"
                  f" background_color='white')", env=env)
    assert control.returncode == 0, control.stderr
    assert np.abs(grey(plain.read_bytes()) - here).mean() > 10 * max(np.abs(there - here).mean(), 0.01)


def test_pdf_embeds_the_font_and_keeps_cyrillic_text(tmp_path, a1):
    path = a1.write(tmp_path / "s.pdf")
    data = path.read_bytes()
    assert b"/FontFile2" in data and b"+osifont" in data                # a TrueType subset embedded
    if not (shutil.which("pdffonts") and shutil.which("pdftotext")):
        pytest.skip("poppler-utils (pdffonts, pdftotext) not installed: checked the PDF's bytes only")
    fonts = subprocess.run(["pdffonts", str(path)], capture_output=True, text=True, check=True).stdout
    rows = [line.split() for line in fonts.splitlines()[2:] if line.strip()]
    assert rows and all(r[0].split("+")[-1] in ("osifont", "graphplan-symbols") for r in rows), fonts  # ours only
    assert all(r[-5] == "yes" for r in rows), fonts                      # the "emb" column
    text = subprocess.run(["pdftotext", str(path), "-"], capture_output=True, text=True, check=True).stdout
    assert "План швидкостей" in text and "План положень" in text


# -- PNG ------------------------------------------------------------------------------------------

def test_png_encoder_round_trips_through_an_independent_decoder():
    from PIL import Image
    from graphplan.drawing.raster import png_bytes
    rgb = np.random.default_rng(7).integers(0, 256, (301, 123, 3), dtype=np.uint8)
    png = png_bytes(rgb, 300, strip=64)
    image = Image.open(io.BytesIO(png))
    assert image.mode == "RGB" and np.array_equal(np.asarray(image), rgb)
    assert image.info["dpi"] == pytest.approx((300, 300), abs=0.01)


def test_png_sheet_is_print_ready(tmp_path):
    """The command's default: 300 dpi in the pHYs chunk, A1 in pixels, RGB without alpha, white."""
    out = tmp_path / "four_bar.png"
    done = run(f"import sys; from graphplan.cli.main import main\n"
               f"sys.exit(main(['sheet', 'examples/four_bar.toml', '-o', {str(out)!r}]))")
    assert done.returncode == 0, done.stderr
    png = out.read_bytes()
    head = chunks(png)
    w, h, depth, colour = struct.unpack(">IIBB", head[b"IHDR"][:10])
    assert (depth, colour) == (8, 2)                                    # 8-bit RGB: no alpha at all
    assert (w, h) == (round(841 / 25.4 * 300), round(594 / 25.4 * 300))
    ppx, ppy, unit = struct.unpack(">IIB", head[b"pHYs"])
    assert unit == 1 and ppx == ppy == round(300 / 0.0254)              # 11811 px/m
    from PIL import Image
    Image.MAX_IMAGE_PIXELS = None
    small = np.asarray(Image.open(io.BytesIO(png)).convert("L").reduce(8))
    margin = small[:, round(10 / 25.4 * 300 / 8)]                       # 10 mm from the left edge
    assert (margin == 255).all()                                        # white paper outside the frame
    assert (small == 255).mean() > 0.8


@pytest.mark.slow              # a second PNG of the A1 sheet (6 s); test_png_sheet_is_print_ready draws the first
def test_png_dpi_option(tmp_path):
    out = tmp_path / "a2.png"
    done = run(f"import sys; from graphplan.cli.main import main\n"
               f"sys.exit(main(['sheet', '--format', 'A2', '--dpi', '150', '-o', {str(out)!r}]))")
    assert done.returncode == 0, done.stderr
    head = chunks(out.read_bytes())
    assert struct.unpack(">II", head[b"IHDR"][:8]) == (round(594 / 25.4 * 150), round(420 / 25.4 * 150))
    assert struct.unpack(">I", head[b"pHYs"][:4])[0] == round(150 / 0.0254)
    bad = run(f"import sys; from graphplan.cli.main import main\n"
              f"sys.exit(main(['sheet', '--dpi', '5', '-o', {str(tmp_path / 'x.png')!r}]))")
    assert bad.returncode == 2 and len(bad.stderr.strip().splitlines()) == 1 and "--dpi" in bad.stderr
    assert not (tmp_path / "x.png").exists()


def test_missing_cairo_is_one_clear_line(tmp_path):
    """Without the cairo library (its Python binding fails to load) PDF and PNG stop with one line
    naming the library, before any work; SVG still works."""
    hide = "import sys; sys.modules['cairocffi'] = None; sys.modules['cairosvg'] = None\n"
    for suffix in (".png", ".pdf"):
        out = tmp_path / f"s{suffix}"
        done = run(hide + f"from graphplan.cli.main import main\nsys.exit(main(['sheet', '-o', {str(out)!r}]))")
        assert done.returncode == 2 and "Traceback" not in done.stderr
        assert len(done.stderr.strip().splitlines()) == 1 and "libcairo2" in done.stderr, done.stderr
        assert not out.exists()
    for suffix in (".svg",):
        out = tmp_path / f"s{suffix}"
        done = run(hide + f"from graphplan.cli.main import main\nsys.exit(main(['sheet', '-o', {str(out)!r}]))")
        assert done.returncode == 0 and out.stat().st_size > 10_000, done.stderr


# -- DXF ------------------------------------------------------------------------------------------

@pytest.mark.parametrize("fmt,width,height", [("A1", 841, 594), ("A2", 594, 420)])
def test_dxf_is_cad_ready(tmp_path, fmt, width, height):
    import ezdxf
    doc = ezdxf.readfile(sheet(fmt=fmt).write(tmp_path / "s.dxf"))
    assert not doc.audit().has_errors
    head = doc.header
    for name in ("$LIMMIN", "$PLIMMIN", "$EXTMIN"):
        assert tuple(head[name])[:2] == (0, 0), name
    for name in ("$LIMMAX", "$PLIMMAX", "$EXTMAX"):
        assert tuple(head[name])[:2] == pytest.approx((width, height)), name
    layout = doc.paperspace(fmt)
    plot = layout.dxf_layout.dxf
    assert (plot.paper_width, plot.paper_height) == pytest.approx((width, height))
    assert plot.plot_paper_units == 1 and plot.scale_numerator == plot.scale_denominator == 1
    assert f"({width:.2f}_x_{height:.2f}_MM)" in plot.paper_size
    assert (plot.left_margin, plot.right_margin, plot.top_margin, plot.bottom_margin) == (0, 0, 0, 0)
    views = [v for v in layout.viewports() if v.dxf.id != 1]            # id 1 is paper space itself
    assert len(views) == 1 and views[0].dxf.view_height == pytest.approx(height)   # 1:1
    assert views[0].dxf.height == pytest.approx(height)
    styles = {s.dxf.name for s in doc.styles}
    assert styles == {"Standard", "GOST"}
    assert {t.dxf.style for t in doc.modelspace().query("TEXT")} == {"GOST"}
    assert doc.styles.get("GOST").dxf.font == "osifont.ttf"


def test_dxf_bytes_do_not_depend_on_the_hash_seed(tmp_path):
    """ezdxf lists CLASS entries in a set's order; the file fixes it (seed 4 reordered it before)."""
    code = ("import sys; from graphplan.drawing.dxf import to_dxf; from graphplan.graphic.record import Record\n"
            "r = Record('t'); r.segment((0, 0), (100, 50), role='link', layer='mechanism')\n"
            "r.label((10, 10), 'План швидкостей'); r.circle((50, 50), 5)\n"
            "sys.stdout.write(to_dxf(r, 420, 297).decode('utf-8'))")
    outs = []
    for seed in ("0", "1", "4", "7"):
        done = run(code, env={"PYTHONHASHSEED": seed})
        assert done.returncode == 0, done.stderr
        outs.append(done.stdout)
    classes = [re.search(r"\nCLASSES\n(.*?)\nENDSEC\n", o, re.S).group(1) for o in outs]
    assert len(set(classes)) == 1 and "LAYOUT" in classes[0]
    assert len(set(outs)) == 1


def test_librecad_prints_the_sheet_on_its_own_format(tmp_path, a1):
    """LibreCAD's dxf2pdf (headless, Qt offscreen) without -a/--fit: an A1 page, the frame 20 mm from
    the left edge and 5 mm from the others, i.e. 1:1 (before, it printed onto A3 and cut the sheet)."""
    librecad = shutil.which("librecad")
    if not librecad:
        pytest.skip("LibreCAD is not installed (Debian: apt install librecad): dxf2pdf not checked")
    a1.write(tmp_path / "sheet.dxf")
    env = {**os.environ, "QT_QPA_PLATFORM": "offscreen", "XDG_RUNTIME_DIR": str(tmp_path)}
    subprocess.run([librecad, "dxf2pdf", "-t", str(tmp_path / "out"), str(tmp_path / "sheet.dxf")],
                   capture_output=True, env=env, timeout=120, check=True)
    pdf = (tmp_path / "out" / "sheet.pdf").read_bytes()
    box = re.search(rb"/MediaBox \[ ?0 0 ([\d.]+) ([\d.]+) ?\]", pdf)
    assert box, "no page size in LibreCAD's PDF"
    mm = [float(v) / 72 * 25.4 for v in box.groups()]
    assert mm == pytest.approx([841, 594], abs=0.5)
    if not shutil.which("pdftoppm"):
        pytest.skip("poppler-utils not installed: the page size is checked, the 1:1 frame is not")
    subprocess.run(["pdftoppm", "-r", "25.4", "-gray", str(tmp_path / "out" / "sheet.pdf"),
                    str(tmp_path / "page")], check=True, capture_output=True)
    from PIL import Image
    page = np.asarray(Image.open(next(tmp_path.glob("page*.pgm")))) < 128   # one pixel per mm
    columns = [x for x in range(page.shape[1]) if page[:, x].mean() > 0.8]
    rows = [y for y in range(page.shape[0]) if page[y].mean() > 0.8]
    assert columns and rows
    assert min(columns) == pytest.approx(20, abs=1) and max(columns) == pytest.approx(836, abs=1)
    assert min(rows) == pytest.approx(5, abs=1) and max(rows) == pytest.approx(589, abs=1)


@pytest.mark.slow             # 18 s: the sheet drawn twice; test_sheet_without_system_fonts_matches_the_gallery stays quick
def test_without_fontconfig_the_lettering_goes_in_as_outlines(tmp_path, a1, monkeypatch):
    """Where cairo cannot be told about the packaged font, PDF and PNG letter with its outlines
    rather than with whatever font the machine has: no font in the PDF, the captions still drawn."""
    from graphplan.drawing import fonts
    monkeypatch.setattr(fonts, "register", lambda: False)
    data = a1.write(tmp_path / "outlined.pdf").read_bytes()
    assert b"/FontFile" not in data and b"/Font" not in data
    outlined = grey(a1.write(tmp_path / "outlined.png", dpi=40).read_bytes())
    monkeypatch.undo()
    text = grey(a1.write(tmp_path / "text.png", dpi=40).read_bytes())
    from graphplan.drawing.raster import to_png
    from graphplan.drawing.svg import render
    from graphplan.graphic.record import Record
    bare = Record(a1.record.title, [p for p in a1.record.items if p.kind != "text"])
    lines = grey(to_png(render(bare, a1.form.width, a1.form.height), dpi=40))

    def ink(image):
        return float((255 - image).sum() - (255 - lines).sum())   # the lettering's ink alone
    assert ink(text) > 0 and ink(outlined) / ink(text) == pytest.approx(1, abs=0.05)
