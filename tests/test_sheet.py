"""The drawing sheets of every example: A1 in true mm with named layers, the frame at 20/5 mm and
the title block in place; no two labels and no two blocks overlap, nothing crosses the frame or
the title block; DXF, PDF and PNG outputs; one clean line for bad requests."""
from __future__ import annotations

import argparse
import io
import re
import subprocess
import sys

import pytest
from shapely.geometry import box

from conftest import EXAMPLES, ROOT, example, example_composed, example_sheet
from graphplan.sheets.compose import defects
from graphplan.sheets.sheet import BUILDERS
from graphplan.sheets.form import form, title_block_box

ARGS = dict(positions=None, accel=None, precision=0.5, sheet="kinematics")


def build(name: str, kind: str = "kinematics", lang: str = "uk", fmt: str = "A1"):
    """The example's sheet, shared with the other modules that read it (``conftest.example_sheet``)."""
    return example_sheet(name, kind, fmt, lang)


def build_anew(name: str, kind: str = "kinematics", lang: str = "uk", fmt: str = "A1"):
    return BUILDERS[kind](example(name), form(fmt), argparse.Namespace(**{**ARGS, "lang": lang, "sheet": kind}))


@pytest.fixture(scope="module", params=EXAMPLES)
def sheet(request):
    return build(request.param)


def test_sheet_is_a1_in_mm_with_layers(sheet):
    import svgelements
    svg = sheet.svg()
    doc = svgelements.SVG.parse(io.StringIO(svg), ppi=25.4)
    assert (doc.width, doc.height) == (pytest.approx(841), pytest.approx(594))
    assert 'viewBox="0 0 841 594"' in svg
    assert "transform=" not in svg
    for layer in ("frame", "mechanism", "vectors", "labels", "diagrams", "tables"):
        assert f'inkscape:label="{layer}"' in svg, layer
    assert re.search(r'<polygon[^>]*points="20,589 836,589 836,5 20,5"', svg)
    from svgboxes import off_field
    assert off_field(svg, sheet.form) == []        # every element in the field, read off the SVG


def test_blocks_and_labels_do_not_overlap(sheet):
    """Every drawing in its own box, no two boxes meeting, no lettering on a line or on lettering,
    everything inside the frame and clear of the title block (sheets.compose.defects)."""
    assert defects(sheet) == []
    frame_in = box(*sheet.form.frame_box)
    tb = box(*title_block_box(sheet.form))
    for p in sheet.placed:
        assert frame_in.contains(box(*p.box)) and box(*p.box).intersection(tb).area == 0, p.name


def test_sheet_content_and_language():
    uk = build("shaper")
    texts = " ".join(p.text for p in uk.record.items if p.kind == "text")
    assert "План положень" in texts and "План швидкостей 11" in texts and "План прискорень" in texts
    assert "I(0-1) → II(2-3) ВПВ → II(4-5) ВВП" in texts and "μ_l = " in texts and "Розроб." in texts
    en = example_composed("shaper", "kinematics", "A1", "en")    # composed alone: its numbering is not read
    texts = " ".join(p.text for p in en.record.items if p.kind == "text")
    assert "Position plan" in texts and "Velocity plan 11" in texts and "Drawn" in texts
    assert "Lever mechanism of a shaping machine" in texts


def test_deterministic_bytes():
    assert build("four_bar").svg() == build_anew("four_bar").svg()


def test_formats_by_suffix(tmp_path):
    import ezdxf
    s = build("crank_slider")
    pdf = s.write(tmp_path / "s.pdf").read_bytes()
    assert pdf == s.write(tmp_path / "again.pdf").read_bytes()      # no creation date in the bytes
    box_ = re.search(rb"/MediaBox \[ ?0 0 ([\d.]+) ([\d.]+) ?\]", pdf)
    assert box_ and float(box_.group(1)) == pytest.approx(841 / 25.4 * 72, abs=1) \
        and float(box_.group(2)) == pytest.approx(594 / 25.4 * 72, abs=1)
    png = s.write(tmp_path / "s.png", dpi=96).read_bytes()
    assert png[:8] == b"\x89PNG\r\n\x1a\n"
    from PIL import Image
    assert Image.open(io.BytesIO(png)).size == (round(841 / 25.4 * 96), round(594 / 25.4 * 96))
    dxf = s.write(tmp_path / "s.dxf")
    doc = ezdxf.readfile(dxf)
    assert not doc.audit().has_errors and doc.units == ezdxf.units.MM
    texts = [e.dxf.text for e in doc.modelspace().query("TEXT")]
    assert any(t.startswith("План положень") for t in texts)
    assert {"frame", "mechanism", "vectors", "labels", "diagrams", "tables"} <= {l.dxf.name for l in doc.layers}
    outlined = s.svg(text_as_paths=True)
    assert "<text" not in outlined and outlined.count("<path") > 100


def test_force_sheet_renders():
    s = build("shaper", kind="forces")
    assert defects(s) == []
    from svgboxes import off_field
    assert off_field(s.svg(), s.form) == []          # every element in the field, read off the SVG
    texts = " ".join(p.text for p in s.record.items if p.kind == "text")
    assert "Важіль Жуковського" in texts and "План сил групи II(4-5)" in texts


def test_cli_sheet_builtin_and_errors(tmp_path):
    out = tmp_path / "x.svg"
    proc = subprocess.run([sys.executable, "-m", "graphplan", "sheet", "-o", str(out)],
                          capture_output=True, text=True, cwd=ROOT)
    assert proc.returncode == 0 and out.read_text().startswith("<svg")
    bad = subprocess.run([sys.executable, "-m", "graphplan", "sheet", "-o", str(tmp_path / "x.doc")],
                         capture_output=True, text=True, cwd=ROOT)
    assert bad.returncode == 2 and len(bad.stderr.strip().splitlines()) == 1
    assert not (tmp_path / "x.doc").exists()
    small = subprocess.run([sys.executable, "-m", "graphplan", "sheet", "examples/shaper.toml", "--format",
                            "A9", "-o", str(tmp_path / "y.svg")], capture_output=True, text=True, cwd=ROOT)
    assert small.returncode == 2 and "A9" in small.stderr and not (tmp_path / "y.svg").exists()
