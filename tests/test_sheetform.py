"""The sheet's form and renderers: true millimetres, the frame at 20/5 mm, the title block's
geometry (REFERENCE §3), DXF that reads back in mm with Cyrillic, layout without overlaps."""
from __future__ import annotations

import io

import pytest

from graphplan.graphic.record import Record
from graphplan.drawing.labels import collisions
from graphplan.drawing.layout import Grid, Leaf, Row, Stack, arrange, extent, flow
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
    assert collisions(tb) == []


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
    """A column is widened to its widest cell: the lettering keeps its height and stays in its cell,
    clear of the rules."""
    rows = [["No", "φ, °", "v_B, м/с"]] + [[str(k), f"{30 * k:.1f}", f"{k * 1.234:.3f}"] for k in range(12)]
    rows[5][2] = "a very long cell of text"
    t = table(rows, [10, 16, 22], title="Таблиця 1")
    assert collisions(t) == []
    right = max(p.points[0][0] for p in t.items if p.kind == "segment")
    assert right > 48.0
    for p in t.items:
        if p.kind == "text":
            assert p.size == 2.5 or p.text == "Таблиця 1"
            b = p.bounds()
            assert 0 <= b[0] and b[2] <= right + 1e-9


def _square(name: str, w: float, h: float) -> Leaf:
    r = Record(name)
    r.add("polygon", [(0, 0), (w, 0), (w, h), (0, h)])
    return Leaf(name, record=r)


def test_a_composition_gives_each_drawing_its_own_box():
    """Rows, stacks and grids: each leaf's box is at least its size, inside the parent's box, no two
    boxes meet, the spare room shared out; a grid's cells are equal and read row by row."""
    cells = [_square(f"c{k}", 20 + 3 * k, 15) for k in range(7)]
    tree = Stack([Row([_square("a", 100, 60), _square("b", 50, 80)]), Grid(cells, 3)])
    w, h = extent(tree)
    assert (w, h) == pytest.approx((max(156, 3 * 38 + 12), 80 + 6 + 3 * 15 + 12))
    laid = list(arrange(tree, (0.0, 0.0, 300.0, 250.0)))
    boxes = {leaf.name: b for leaf, b in laid}
    for name, (x0, y0, x1, y1) in boxes.items():
        assert 0 <= x0 and x1 <= 300 and 0 <= y0 and y1 <= 250, name
    names = list(boxes)
    for i, a in enumerate(names):
        for b in names[i + 1:]:
            p, q = boxes[a], boxes[b]
            assert not (p[0] < q[2] and q[0] < p[2] and p[1] < q[3] and q[1] < p[3]), (a, b)
    grid = [boxes[f"c{k}"] for k in range(7)]
    assert len({round(b[2] - b[0], 9) for b in grid}) == 1 and len({round(b[3] - b[1], 9) for b in grid}) == 1
    assert grid[0][0] < grid[1][0] < grid[2][0] and grid[3][3] < grid[0][1] and grid[3][0] == grid[0][0]


def test_a_set_flows_in_reading_order_and_keeps_clear_of_the_title_block():
    """Rows wrap and carry over to a further sheet; nothing enters the title block's corner."""
    region, keep = (0.0, 0.0, 400.0, 270.0), (200.0, 0.0, 400.0, 60.0)
    rows = [[_square(f"p{k}", 120, 100) for k in range(7)]]
    pages = flow(rows, region, keep)
    assert len(pages) == 2
    order = [leaf.name for page in pages for leaf, _ in page]
    assert order == [f"p{k}" for k in range(7)]
    for page in pages:
        for _leaf, (x0, y0, x1, y1) in page:
            assert not (x1 > keep[0] and y0 < keep[3])
    assert flow([[_square("huge", 500, 100)]], region, keep) is None


def test_a_region_left_of_a_column_keeps_its_own_edge_by_the_title_block():
    """A set's sheet flows its drawings in the room left of the tables' column (the region ends at
    x = 120) while the title block starts farther right (x = 200): a row near the foot took the room
    up to the title block and ran on under the notes (R01's hodograph on an A2 set's last sheet)."""
    region, keep = (0.0, 0.0, 120.0, 270.0), (200.0, 0.0, 400.0, 60.0)
    rows = [[_square(f"h{k}", 100, 70) for k in range(3)]]
    pages = flow(rows, region, keep)
    assert len(pages) == 1
    for _leaf, (x0, y0, x1, y1) in pages[0]:
        assert region[0] - 1e-9 <= x0 and x1 <= region[2] + 1e-9, (_leaf.name, x0, x1)
