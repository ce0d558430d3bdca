"""The sheet's form and renderers: true millimetres, the frame at 20/5 mm, the title block's
geometry (REFERENCE §3), DXF that reads back in mm with Cyrillic, layout without overlaps."""
from __future__ import annotations

import io

import pytest

from graphplan.graphic.record import Record
from graphplan.drawing.layout import Block, declutter, overlapping_texts, place
from graphplan.sheets.form import form, frame, table, title_block, title_block_box
from graphplan.drawing.svg import render

FIELDS = {"designation": "ТММ.КП.00.000", "title": "Важільний механізм поперечно-стругального верстата",
          "student": "Студент", "teacher": "Викладач", "organisation": "НУБіП України", "scale": "1:5"}


def a1_sheet(lang="uk") -> tuple[Record, object]:
    f = form("A1")
    rec = Record()
    rec.extend(frame(f))
    rec.extend(title_block(f, FIELDS, lang))
    return rec, f


def test_svg_reads_as_true_millimetres():
    import svgelements
    rec, f = a1_sheet()
    svg = render(rec, f.width, f.height, "sheet")
    doc = svgelements.SVG.parse(io.StringIO(svg), ppi=25.4)  # 1 px = 1 mm
    assert doc.width == pytest.approx(841) and doc.height == pytest.approx(594)
    assert 'viewBox="0 0 841 594"' in svg and "transform" not in svg
    rects = [e for e in doc.elements() if isinstance(e, svgelements.Polygon)]
    frame_box = rects[0].bbox()
    assert frame_box == pytest.approx((20, 5, 836, 589))
    assert 'inkscape:label="frame"' in svg


def test_title_block_geometry():
    rec, f = a1_sheet()
    x0, y0, x1, y1 = title_block_box(f)
    assert (x1 - x0, y1 - y0) == (185, 55) and x1 == 836 and y0 == 5
    tb = title_block(f, FIELDS)
    bx = tb.bounds()
    assert bx[0] == pytest.approx(x0) and bx[2] == pytest.approx(x1)
    assert bx[1] == pytest.approx(y0) and bx[3] <= y1 + 1e-9
    # the verticals of the left part: 7 | 10 | 23 | 15 | 10
    xs = sorted({round(p.points[0][0] - x0, 3) for p in tb.items
                 if p.kind == "segment" and p.points[0][0] == p.points[1][0]})
    for c in (7, 17, 40, 55, 65, 135, 150, 167):
        assert c in xs
    texts = {p.text for p in tb.items if p.kind == "text"}
    assert {"Змн.", "Арк.", "№ докум.", "Підпис", "Дата", "Розроб.", "Перевір.", "Т.контр.",
            "Н.контр.", "Затв.", "Літ.", "Маса", "Масштаб"} <= texts
    assert "ТММ.КП.00.000" in texts
    en = {p.text for p in title_block(f, FIELDS, "en").items if p.kind == "text"}
    assert {"Drawn", "Checked", "Scale", "Mass"} <= en
    # every caption lies inside the block
    for p in tb.items:
        if p.kind == "text":
            b = p.bounds()
            assert x0 <= b[0] and b[2] <= x1 and y0 <= b[1] and b[3] <= y1, p.text
    assert overlapping_texts(tb) == []


def test_dxf_reads_back_in_mm_with_cyrillic(tmp_path):
    import ezdxf
    from graphplan.drawing.dxf import to_dxf
    rec, f = a1_sheet()
    rec.segment((100, 100), (200, 100), role="axis", layer="mechanism")
    data = to_dxf(rec, f.width, f.height)
    assert data == to_dxf(rec, f.width, f.height)          # byte-identical
    path = tmp_path / "s.dxf"
    path.write_bytes(data)
    doc = ezdxf.readfile(path)
    auditor = doc.audit()
    assert not auditor.has_errors
    assert doc.units == ezdxf.units.MM
    texts = [e.dxf.text for e in doc.modelspace().query("TEXT")]
    assert "Розроб." in texts and "ТММ.КП.00.000" in texts
    assert {"frame", "mechanism", "labels"} <= {layer.dxf.name for layer in doc.layers}
    axis = doc.modelspace().query("LINE[layer=='mechanism']").first
    assert axis.dxf.linetype == "GOST_DASHDOT"
    pattern = doc.linetypes.get("GOST_DASHDOT").pattern_tags.tags
    assert any(abs(t.value - 12.0) < 1e-9 for t in pattern if t.code == 49)  # dash length in mm


def test_table_cells_fit_and_do_not_overlap():
    rows = [["No", "φ, °", "v_B, м/с"]] + [[str(k), f"{30 * k:.1f}", f"{k * 1.234:.3f}"] for k in range(12)]
    t = table(rows, [10, 16, 22], title="Таблиця 1")
    assert overlapping_texts(t) == []
    for p in t.items:
        if p.kind == "text" and p.text != "Таблиця 1":
            b = p.bounds()
            assert 0 <= b[0] and b[2] <= 48.0 + 1e-9


def test_layout_places_without_overlap_and_shrinks():
    def square(size):
        def build(k):
            r = Record()
            r.add("polygon", [(0, 0), (size * k, 0), (size * k, size * k), (0, size * k)])
            return r
        return build
    blocks = [Block(f"b{k}", square(150), factors=(1.0, 0.5)) for k in range(6)]
    placed = place(blocks, (25, 10, 831, 584), obstacles=[(651, 5, 836, 60)])
    from shapely.geometry import box
    boxes = [box(*p.box) for p in placed]
    for i in range(len(boxes)):
        for j in range(i + 1, len(boxes)):
            assert boxes[i].intersection(boxes[j]).area == 0
        assert box(25, 10, 831, 584).contains(boxes[i])
        assert boxes[i].intersection(box(651, 5, 836, 60)).area == 0
    big = [Block("huge", square(2000), factors=(1.0,))]
    from graphplan.util.errors import GraphplanError
    with pytest.raises(GraphplanError, match="no room for the huge"):
        place(big, (25, 10, 831, 584))


def test_declutter_separates_colliding_labels():
    r = Record()
    for k in range(5):
        r.label((10.0, 10.0), f"b{k}", size=3.5)
    assert overlapping_texts(r) != []
    assert overlapping_texts(declutter(r)) == []
