"""The fast writers of the key sheets: the SVG put together as text (the same bytes svgwrite's objects
write), the PDF drawn straight from the records on a cairo surface (the same drawing cairosvg makes
of the SVG, the lettering where the record puts it, the font embedded, the text searchable), and
the group's summary over as many A4 pages as its rows need."""
from __future__ import annotations

import json
import re
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from graphplan.graphic.record import lettering

from conftest import ROOT
from svgwrite_reference import reference_render
from graphplan.cli.main import main
from graphplan.drawing.svg import render
from graphplan.graphic.record import Record, text_width
from graphplan.teach.keysheet import A4_LANDSCAPE, A4_PORTRAIT, EDGE, LEFT, key_sheet, summary_pages

EXAMPLES = ROOT / "examples"
POPPLER = shutil.which("pdftoppm") and shutil.which("pdftotext") and shutil.which("pdfinfo")
MM = 72.0 / 25.4


@pytest.fixture(scope="module")
def keyset(tmp_path_factory):
    """The crank-slider table's first six variants keyed (with their PDF sheets)."""
    tmp = tmp_path_factory.mktemp("keys")
    lines = (EXAMPLES / "crank_slider_variants.csv").read_text(encoding="utf-8").splitlines()
    head = [ln for ln in lines if ln.startswith("#") or ln.startswith("variant")]
    rows = [ln for ln in lines if ln not in head][:6]
    text = "\n".join(head + rows).replace("base = crank_slider.toml", f"base = {EXAMPLES / 'crank_slider.toml'}")
    (tmp / "v.csv").write_text(text + "\n", encoding="utf-8")
    assert main(["key", str(tmp / "v.csv"), "-o", str(tmp / "k"), "--quiet", "--jobs", "1"]) == 0
    return tmp / "k"


def every_kind() -> Record:
    """One primitive of every kind, lettering with markup, the symbols' font, XML's special
    characters, an empty text, a comma set apart and a layer of its own."""
    rec = Record("a <title> & \"quotes\"")
    rec.add("segment", [(10, 10), (60, 20)], role="axis", layer="mechanism")
    rec.add("vector", [(10, 30), (50, 45)], role="vector", layer="vectors")
    rec.add("polyline", [(5, 5), (20, 8), (30, 2)], role="projection")
    rec.add("polygon", [(70, 5), (90, 5), (90, 25)], role="frame", layer="frame")
    rec.add("circle", [(100, 40)], radius=7.5, role="trajectory")
    rec.add("arc", [(100, 40)], radius=4.0, angles=(300.0, 45.0))
    rec.add("arc", [(120, 40)], radius=4.0, angles=(0.0, 360.0))
    rec.point((30, 30), role="joint", layer="mechanism")
    rec.point((40, 30), layer="custom layer & more")
    for k, (text, anchor) in enumerate([("a^τ_BA = ω_2^2·l_AB", "start"), ("P → Q ⊥ AB ∥ CD′", "middle"),
                                        ("<&> \"x\"", "end"), ("", "start"), ("v_B, м/с", "end"),
                                        ("205,7", "end"), ("Швидкості\\_точок", "start")]):
        rec.label((60 + 10 * (k % 2), 60 + 6 * k), text, size=(2.5, 3.5, 5.0)[k % 3], anchor=anchor)
    return rec


# -- SVG ------------------------------------------------------------------------------------------

@pytest.mark.parametrize("paths", [False, True])
def test_svg_text_is_byte_for_byte_what_svgwrite_writes(keyset, paths):
    key = json.loads((keyset / "01" / "key.json").read_text(encoding="utf-8"))
    records = [(every_kind(), 150.0, 110.0)]
    if not paths:           # (outlines are cut by matplotlib: a key sheet's 350 texts take 10 s)
        records += [(key_sheet(key, "uk"), *A4_PORTRAIT), (key_sheet(key, "en"), *A4_PORTRAIT)]
    for rec, w, h in records:
        for title, embed in ((rec.title, True), ("", False)):
            ours = render(rec, w, h, title=title, text_as_paths=paths, embed_font=embed)
            assert ours == reference_render(rec, w, h, title=title, text_as_paths=paths, embed_font=embed)


def test_svg_of_a_gallery_sheet_is_what_svgwrite_writes():
    from conftest import example_sheet
    sheet = example_sheet("crank_slider", "kinematics", "A3")     # shared with the modules that read it
    f = sheet.form
    assert render(sheet.record, f.width, f.height, sheet.record.title) == \
        reference_render(sheet.record, f.width, f.height, sheet.record.title)


# -- PDF ------------------------------------------------------------------------------------------

def _pdf(rec: Record, w: float, h: float) -> bytes:
    from graphplan.drawing.pdf import render_pdf
    return render_pdf([rec], w, h, title=rec.title)


def _grey(pdf: Path, dpi: int) -> np.ndarray:
    from PIL import Image
    subprocess.run(["pdftoppm", "-r", str(dpi), "-gray", "-singlefile", str(pdf), str(pdf.with_suffix(""))],
                   check=True)
    return np.asarray(Image.open(pdf.with_suffix(".pgm")), dtype=float)


@pytest.mark.skipif(not POPPLER, reason="poppler-utils (pdftoppm, pdftotext, pdfinfo) not installed")
def test_pdf_draws_what_cairosvg_draws_of_the_svg(tmp_path, keyset):
    """Rasterised at 50 dpi, the direct PDF and cairosvg's PDF of the same sheet's SVG differ by
    less than a grey level on average, with the same amount of ink: nothing lost, mirrored or moved
    (the lettering of right-aligned text sits up to 0.2 mm apart: cairosvg measures it its own way)."""
    from graphplan.drawing.raster import to_pdf
    key = json.loads((keyset / "02" / "key.json").read_text(encoding="utf-8"))
    drawings = {"kind": (every_kind(), 150.0, 110.0), "key": (key_sheet(key, "uk"), *A4_PORTRAIT)}
    for name, (rec, w, h) in drawings.items():
        direct, via = tmp_path / f"{name}-direct.pdf", tmp_path / f"{name}-svg.pdf"
        direct.write_bytes(_pdf(rec, w, h))
        via.write_bytes(to_pdf(render(rec, w, h)))
        a, b = _grey(direct, 50), _grey(via, 50)
        assert a.shape == b.shape
        assert np.abs(a - b).mean() < 2.5, name
        ink_a, ink_b = (255 - a).sum(), (255 - b).sum()
        assert abs(ink_a - ink_b) < 0.03 * ink_b, name


@pytest.mark.skipif(not POPPLER, reason="poppler-utils (pdftoppm, pdftotext, pdfinfo) not installed")
def test_sheet_pdf_draws_what_cairosvg_draws_of_its_svg(tmp_path):
    """`graphplan sheet -o x.pdf` (the direct PDF) against cairosvg's PDF of the sheet's own SVG: a
    whole A3 sheet of plans, diagrams and tables rasterised at 40 dpi differs by less than a grey level
    on average, with the same ink to 1 %."""
    from graphplan.drawing.raster import to_pdf
    assert main(["sheet", str(EXAMPLES / "crank_slider.toml"), "--format", "A3", "-o", str(tmp_path / "s.pdf")]) == 0
    assert main(["sheet", str(EXAMPLES / "crank_slider.toml"), "--format", "A3", "-o", str(tmp_path / "s.svg")]) == 0
    (tmp_path / "via.pdf").write_bytes(to_pdf((tmp_path / "s.svg").read_text(encoding="utf-8")))
    a, b = _grey(tmp_path / "s.pdf", 40), _grey(tmp_path / "via.pdf", 40)
    assert a.shape == b.shape
    assert np.abs(a - b).mean() < 1.0
    assert abs((255 - a).sum() / (255 - b).sum() - 1) < 0.01


@pytest.mark.skipif(not POPPLER, reason="poppler-utils (pdftoppm, pdftotext, pdfinfo) not installed")
def test_pdf_letters_each_word_where_the_record_puts_it(tmp_path, keyset):
    """pdftotext's word boxes against the record: every plain text of the key sheet (no markup, no
    decimal comma set apart) begins (left-aligned) or ends (right-aligned) within 0.15 mm of its
    anchor, its word's box standing on the text's baseline."""
    key = json.loads((keyset / "01" / "key.json").read_text(encoding="utf-8"))
    rec = key_sheet(key, "uk")
    path = tmp_path / "k.pdf"
    path.write_bytes(_pdf(rec, *A4_PORTRAIT))
    html = subprocess.run(["pdftotext", "-bbox", str(path), "-"], capture_output=True, text=True, check=True).stdout
    boxes: dict[str, list[tuple[float, ...]]] = {}
    for m in re.finditer(r'xMin="([\d.]+)" yMin="([\d.]+)" xMax="([\d.]+)" yMax="([\d.]+)">([^<]*)</word>', html):
        boxes.setdefault(m.group(5), []).append(tuple(float(v) / MM for v in m.groups()[:4]))
    checked = {"start": 0, "end": 0}
    for p in rec.items:
        words = p.text.split()
        if p.kind != "text" or p.anchor == "middle" or not words or re.search(r"[_^\\,→⊥∥′″…&<>]", p.text):
            continue
        x, y = p.points[0]
        word, side = (words[0], 0) if p.anchor == "start" else (words[-1], 2)
        word = lettering(word)                     # as drawn: a sign's hyphen the minus (the en dash)
        baseline = A4_PORTRAIT[1] - y
        near = [b for b in boxes.get(word, []) if abs(b[side] - x) < 1.0 and b[1] < baseline < b[3] + 0.5]
        assert near, p.text
        assert min(abs(b[side] - x) for b in near) < 0.15, p.text
        checked[p.anchor] += 1
    assert checked["start"] >= 5 and checked["end"] >= 50, checked


@pytest.mark.skipif(not POPPLER, reason="poppler-utils (pdftoppm, pdftotext, pdfinfo) not installed")
def test_key_pdf_is_a4_embeds_the_font_and_keeps_the_answers_searchable(keyset):
    path = keyset / "01" / "key.pdf"
    info = subprocess.run(["pdfinfo", str(path)], capture_output=True, text=True, check=True).stdout
    assert "595.276 x 841.89 pts (A4)" in info and re.search(r"Pages:\s+1\n", info)
    assert "Ключ відповідей" in info and "2000" in info                # the title; the fixed date
    fonts = subprocess.run(["pdffonts", str(path)], capture_output=True, text=True, check=True).stdout
    rows = [ln.split() for ln in fonts.splitlines()[2:] if ln.strip()]
    assert rows and all(r[0].split("+")[-1] in ("osifont", "graphplan-symbols") for r in rows), fonts
    assert all(r[-5] == "yes" and r[-3] == "yes" for r in rows), fonts    # embedded, with its Unicode map
    text = subprocess.run(["pdftotext", str(path), "-"], capture_output=True, text=True, check=True).stdout
    key = json.loads((keyset / "01" / "key.json").read_text(encoding="utf-8"))
    v_b = key["positions"][1]["values"]["v_B"]
    assert f"{v_b:.4g}".replace(".", ",") in text                       # an answer, as the sheet prints it
    assert "Швидкості в положеннях" in text and "ω" in text


def test_pdf_bytes_depend_on_the_input_only(keyset):
    key = json.loads((keyset / "03" / "key.json").read_text(encoding="utf-8"))
    rec = key_sheet(key, "en")
    first = _pdf(rec, *A4_PORTRAIT)
    assert first == _pdf(rec, *A4_PORTRAIT)
    assert b"/CreationDate (D:20000101000000Z" in first
    assert (keyset / "03" / "key.pdf").read_bytes() == _pdf(key_sheet(key, "uk"), *A4_PORTRAIT)


def test_pdf_without_system_fonts_embeds_osifont(tmp_path, keyset):
    """In a process whose fontconfig knows no font at all the direct PDF still letters with the
    packaged osifont (fonts.register adds it to cairo's fontconfig)."""
    from test_outputs import BARE_FONTCONFIG
    conf = tmp_path / "fonts.conf"
    conf.write_text(BARE_FONTCONFIG.format(cache=tmp_path / "cache"), encoding="utf-8")
    out = tmp_path / "bare.pdf"
    code = ("import json\nfrom graphplan.teach.keysheet import key_sheet, A4_PORTRAIT\n"
            "from graphplan.cli.key import pdf_bytes\nfrom graphplan.util.markup import plain\n"
            f"key = json.load(open({str(keyset / '01' / 'key.json')!r}, encoding='utf-8'))\n"
            "sheet = key_sheet(key, 'uk')\n"
            f"open({str(out)!r}, 'wb').write(pdf_bytes([sheet], A4_PORTRAIT, plain(sheet.title)))\n")
    done = subprocess.run([sys.executable, "-c", code], env={"FONTCONFIG_FILE": str(conf), "PATH": "/usr/bin:/bin"},
                          cwd=ROOT, capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    data = out.read_bytes()
    assert b"+osifont" in data and b"/FontFile2" in data
    assert data == (keyset / "01" / "key.pdf").read_bytes()


# -- the summary's pages ------------------------------------------------------------------------------

def _rows(n: int, skipped: int = 0) -> list[dict]:
    rows = [{"variant": f"v{k + 1:04d}", "student": f"Студент {k + 1}", "status": "ok", "r": 0.05 + k * 1e-4,
             "phi0_deg": 12.5 + k, "H": 0.1 + k * 1e-3, "v_max": 3.3 + k * 0.01} for k in range(n)]
    for r in rows[:skipped]:
        r.update(status="skipped", note="the rod is shorter than the crank")
    return rows


def _inside_frame(page: Record, width: float, height: float) -> bool:
    x0, y0, x1, y1 = page.bounds()
    return x0 >= LEFT - 1e-6 and y0 >= EDGE - 1e-6 and x1 <= width - EDGE + 1e-6 and y1 <= height - EDGE + 1e-6


@pytest.mark.parametrize("n,skipped,fewest,most", [(5, 0, 1, 1), (30, 2, 1, 1), (60, 0, 2, 2), (1000, 40, 23, 25)])
def test_summary_runs_over_pages_and_never_past_the_frame(n, skipped, fewest, most):
    """One page while the rows fit it at 3 mm; beyond that pages of 4 mm rows (185 mm under the
    title: 44 rows and the column heads a page), the notes (6 mm a line) after the last row."""
    cols = ["variant", "student", "status", "r", "phi0_deg", "H", "v_max"]
    units = {"r": "m", "phi0_deg": "°", "H": "m", "v_max": "m/s"}
    out = summary_pages("Ключі відповідей", cols, _rows(n, skipped), units, {"r"}, "uk")
    pages = len(out)
    assert fewest <= pages <= most
    for page in out:
        assert _inside_frame(page, *A4_LANDSCAPE)
    listed = [p.text for page in out for p in page.items if p.kind == "text" and re.fullmatch(r"v\d{4}", p.text)]
    assert listed == [f"v{k + 1:04d}" for k in range(n)]                 # every variant once, in order
    with_rows = [page for page in out if any(re.fullmatch(r"v\d{4}", p.text) for p in page.items)]
    heads = [[p.text for p in page.items if p.kind == "text" and p.text.startswith("Ключі")][0] for page in out]
    if pages > 1:
        assert heads == [f"Ключі відповідей (аркуш {k} з {pages})" for k in range(1, pages + 1)]
        assert all(any(p.text == "варіант" for p in page.items) for page in with_rows)   # heads on each
    notes = [p for page in out for p in page.items if p.kind == "text" and "shorter" in p.text]
    assert len(notes) == skipped
    last = with_rows[-1]
    rows_y = min(p.points[0][1] for p in last.items if p.kind == "text" and re.fullmatch(r"v\d{4}", p.text))
    assert all(p.points[0][1] < rows_y for p in notes if p in last.items)     # the notes under the rows
    for page in out[out.index(last) + 1:]:                                     # then pages of notes only
        assert all(p in notes or p.text.startswith("Ключі") for p in page.items if p.kind == "text")


def test_summary_cell_widths_fit_their_text():
    cols = ["variant", "student", "status", "r", "phi0_deg", "H", "v_max"]
    page = summary_pages("T", cols, _rows(3), {}, set(), "en")[0]
    for p in page.items:
        if p.kind == "text" and p.text.startswith("Студент"):
            assert text_width(p.text, p.size) < 60


@pytest.mark.skipif(not POPPLER, reason="poppler-utils (pdftoppm, pdftotext, pdfinfo) not installed")
def test_key_writes_every_summary_page_and_one_pdf(tmp_path):
    lines = (EXAMPLES / "crank_slider_variants.csv").read_text(encoding="utf-8").splitlines()
    head = [ln for ln in lines if ln.startswith("#") or ln.startswith("variant")]
    rows = [ln for ln in lines if ln not in head]
    more = [",".join([f"x{k:03d}"] + rows[k % len(rows)].split(",")[1:]) for k in range(70)]
    text = "\n".join(head + more).replace("base = crank_slider.toml", f"base = {EXAMPLES / 'crank_slider.toml'}")
    (tmp_path / "v.csv").write_text(text + "\n", encoding="utf-8")
    assert main(["key", str(tmp_path / "v.csv"), "-o", str(tmp_path / "k"), "--quiet"]) == 0
    out = tmp_path / "k"
    assert (out / "summary.svg").exists() and (out / "summary-2.svg").exists()
    assert not (out / "summary-3.svg").exists()
    info = subprocess.run(["pdfinfo", str(out / "summary.pdf")], capture_output=True, text=True, check=True).stdout
    assert re.search(r"Pages:\s+2\n", info)
    words = subprocess.run(["pdftotext", str(out / "summary.pdf"), "-"], capture_output=True, text=True,
                           check=True).stdout
    assert all(f"x{k:03d}" in words for k in range(70))
    # a shorter run into the same folder: the second page of the earlier summary goes
    short = "\n".join(head + more[:4]).replace("base = crank_slider.toml",
                                              f"base = {EXAMPLES / 'crank_slider.toml'}")
    (tmp_path / "v.csv").write_text(short + "\n", encoding="utf-8")
    assert main(["key", str(tmp_path / "v.csv"), "-o", str(out), "--quiet", "--jobs", "1"]) == 0
    assert (out / "summary.svg").exists() and not (out / "summary-2.svg").exists()
    assert (out / "x050" / "key.json").exists()          # the teacher's other files stay


@pytest.mark.parametrize("lang", ["uk", "en"])
def test_key_sheet_letters_inside_the_frame_and_clear_of_each_other(keyset, lang):
    """Every word of the key sheets inside the frame (the acceleration heading beside the velocity
    table once ran through the frame's right edge on the crank-slider's variant 01), and no two
    lettered boxes of different sections overlapping: a long heading beside a table wraps."""
    for v in ("01", "02", "03", "04", "05", "06"):
        rec = key_sheet(json.loads((keyset / v / "key.json").read_text(encoding="utf-8")), lang)
        texts = [p for p in rec.items if p.kind == "text"]
        for p in texts:
            x0, y0, x1, y1 = p.ink()
            assert LEFT < x0 and x1 < A4_PORTRAIT[0] - EDGE and EDGE < y0 and y1 < A4_PORTRAIT[1] - EDGE, p.text
        heads = [p for p in texts if p.size == 3.5 and re.match(r"\d\. ", p.text)]
        for p in heads:                      # a heading's ink clear of every other text's
            a = p.ink()
            for q in texts:
                if q is not p:
                    b = q.ink()
                    assert a[2] <= b[0] or b[2] <= a[0] or a[3] <= b[1] or b[3] <= a[1], (p.text, q.text)


def test_arrowheads_read_at_a_glance():
    """A thick vector's head is about three times its line wide (2 mm on 0.7 mm, 4 mm long) and its
    shaft ends inside the head (the point sharp, no round cap past it); an arc's arrow (ω₁, the
    balancing moment) a head 3 mm long on the arc, its tip at the arc's end — measured off the
    rendered primitives."""
    import math

    from graphplan.graphic.record import arc_head, vector_arrow
    a, b = (0.0, 0.0), (30.0, 40.0)
    tip, end = vector_arrow(a, b, 0.7)
    wide = math.dist(tip[1], tip[2])
    assert wide >= 3 * 0.7 * 0.95 and tip[0] == b
    base = ((tip[1][0] + tip[2][0]) / 2, (tip[1][1] + tip[2][1]) / 2)
    assert math.isclose(math.dist(base, b), 4.0)
    # the shaft's round cap (0.35 mm) ends inside the head, where the head is wider than the line
    assert math.dist(end, b) - 0.35 > 0 and (math.dist(end, b) - 0.35) / 4.0 * wide > 0.7
    tail, tip_ = arc_head(complex(0, 0), 9.0, 90.0, +1)
    assert math.isclose(math.hypot(*tip_), 9.0) and math.isclose(tip_[1], 9.0)
    assert math.isclose(math.hypot(*tail), 9.0) and tail[0] > 0       # back against the sense (ccw)
    head, _ = vector_arrow(tail, tip_, 0.25, head=True)
    assert math.dist(*head[1:]) >= 1.2 - 1e-9 and 2.9 < math.dist(tail, tip_) <= 3.0
