"""DXF renderer of construction records (ezdxf): millimetres, one layer per kind, GOST 2.303 line
types defined in millimetres, line weights by role, one text style (GOST) on osifont; Cyrillic kept.

Ready for CAD programs (docs/cad.md): model-space limits and extents and the paper-space limits are
the sheet's format ($LIMMAX = $PLIMMAX = $EXTMAX = 841, 594 for A1), so a program that prints by the
limits (LibreCAD) prints the sheet on its own format; a paper-space layout named after the format
(page setup in mm, 1:1, no margins) shows the model through one viewport at 1:1; the text styles
are Standard (required) and GOST, nothing else; the bytes do not depend on PYTHONHASHSEED."""
from __future__ import annotations

import io
import math

from graphplan.graphic.record import (DASHED_ROLES, LAYERS, Primitive, Record, vector_arrow, lettering, run_offsets,
                                      text_width)
from graphplan.util.markup import is_plain

# GOST 2.303 patterns in mm: (total length, dash, −gap, dot, −gap …)
LINETYPES = {
    "GOST_DASHDOT": ("Dash-dot thin (GOST 2.303) __ . __ .", [18.0, 12.0, -3.0, 0.0, -3.0]),
    "GOST_DASHED": ("Dashed (GOST 2.303) __ __", [6.0, 4.0, -2.0]),
}
LAYER_STYLE = {  # layer → (ACI colour, lineweight in 1/100 mm)
    "frame": (7, 70), "mechanism": (7, 70), "construction": (8, 25), "vectors": (5, 50),
    "labels": (7, 25), "diagrams": (3, 35), "tables": (7, 25),
}
FONT_FILE = "osifont.ttf"   # the packaged font (drawing.fonts); CAD programs find it by this name
STYLE = "GOST"
ISO_A = {(841.0, 1189.0): "A0", (594.0, 841.0): "A1", (420.0, 594.0): "A2", (297.0, 420.0): "A3",
         (210.0, 297.0): "A4"}    # (short side, long side) → format


def _weight(prim: Primitive) -> int:
    """A valid DXF lineweight (1/100 mm) nearest to the primitive's width."""
    valid = (0, 5, 9, 13, 15, 18, 20, 25, 30, 35, 40, 50, 53, 60, 70, 80, 90, 100, 106, 120, 140)
    target = prim.line_width * 100
    return min(valid, key=lambda v: abs(v - target))


def to_dxf(record: Record, width: float, height: float) -> bytes:
    """The record as a DXF R2010 document in millimetres; text stays text (TEXT entities)."""
    import ezdxf
    fixed = ezdxf.options.write_fixed_meta_data_for_testing
    ezdxf.options.write_fixed_meta_data_for_testing = True  # no dates or random GUIDs: equal bytes
    try:
        return _to_dxf(record, width, height)
    finally:
        ezdxf.options.write_fixed_meta_data_for_testing = fixed


def _to_dxf(record: Record, width: float, height: float) -> bytes:
    import ezdxf
    from ezdxf import units
    from ezdxf.enums import TextEntityAlignment

    doc = ezdxf.new("R2010", setup=False)   # no stock styles, line types or dimension styles
    doc.units = units.MM
    doc.header["$INSUNITS"] = units.MM
    doc.header["$MEASUREMENT"] = 1
    for name, (desc, pattern) in LINETYPES.items():
        doc.linetypes.add(name, pattern=pattern, description=desc)
    doc.styles.get("Standard").dxf.font = FONT_FILE
    doc.styles.add(STYLE, font=FONT_FILE)
    for name in LAYERS:
        colour, weight = LAYER_STYLE.get(name, (7, 25))
        doc.layers.add(name, color=colour, lineweight=weight)
    msp = doc.modelspace()
    align = {"start": TextEntityAlignment.LEFT, "middle": TextEntityAlignment.CENTER,
             "end": TextEntityAlignment.RIGHT}
    for prim in record.items:
        if prim.layer not in doc.layers:
            doc.layers.add(prim.layer)
        attribs = {"layer": prim.layer, "lineweight": _weight(prim)}
        dash = DASHED_ROLES.get(prim.role)
        if dash:
            attribs["linetype"] = "GOST_DASHDOT" if dash == "dashdot" else "GOST_DASHED"
        k = prim.kind
        if k == "segment":
            msp.add_line(prim.points[0], prim.points[1], dxfattribs=attribs)
        elif k == "vector":
            a, b = prim.points
            tip, end = vector_arrow(a, b, prim.line_width, prim.role == "head")
            msp.add_line(a, end, dxfattribs=attribs)
            msp.add_solid([tip[0], tip[1], tip[2]], dxfattribs={"layer": prim.layer})
        elif k in ("polyline", "polygon"):
            msp.add_lwpolyline(prim.points, close=(k == "polygon"), dxfattribs=attribs)
        elif k == "circle":
            msp.add_circle(prim.points[0], prim.radius, dxfattribs=attribs)
        elif k == "arc":
            start, end = prim.angles
            if (end - start) % 360.0 == 0.0:
                msp.add_circle(prim.points[0], prim.radius, dxfattribs=attribs)
            else:
                msp.add_arc(prim.points[0], prim.radius, start, end, dxfattribs=attribs)
        elif k == "point":
            msp.add_circle(prim.points[0], 1.0 if prim.role == "joint" else 0.6, dxfattribs=attribs)
        elif k == "text":
            if is_plain(prim.text):
                text = msp.add_text(lettering(prim.text), height=prim.size,
                                    dxfattribs={"layer": prim.layer, "style": STYLE, "rotation": prim.turn})
                text.set_placement(prim.points[0], align=align[prim.anchor])
            else:
                _scripted(msp, prim)
    _sheet_size(doc, width, height)
    _stable_classes(doc)
    stream = io.StringIO()
    doc.write(stream)
    return stream.getvalue().encode("utf-8")


def paper_name(width: float, height: float) -> str:
    """The format's name (A1 …) for an ISO A size in either orientation, else "Sheet"."""
    return ISO_A.get((min(width, height), max(width, height)), "Sheet")


def _sheet_size(doc, width: float, height: float) -> None:
    """Limits and extents of model and paper space at the sheet (ezdxf writes the header's $LIMMAX,
    $PLIMMAX, $EXTMAX … from the layouts), the opening view on the whole sheet, and a paper-space
    layout of the sheet's format printing the model at 1:1 (AutoCAD's media name for DWG to PDF)."""
    msp = doc.modelspace()
    msp.reset_limits((0, 0), (width, height))
    msp.reset_extents((0, 0, 0), (width, height, 0))
    doc.header["$EXTMIN"] = (0, 0, 0)        # ezdxf copies the layout's extents only when not (0, 0, 0)
    doc.header["$EXTMAX"] = (width, height, 0)
    doc.set_modelspace_vport(height=height, center=(width / 2, height / 2))
    name = paper_name(width, height)
    doc.layouts.rename("Layout1", name)
    psp = doc.paperspace(name)
    psp.page_setup(size=(width, height), margins=(0, 0, 0, 0), units="mm", scale=(1, 1),
                   name=f"ISO_full_bleed_{name}" if name != "Sheet" else "graphplan")
    psp.reset_limits((0, 0), (width, height))
    psp.reset_extents((0, 0, 0), (width, height, 0))
    psp.add_viewport(center=(width / 2, height / 2), size=(width, height),
                     view_center_point=(width / 2, height / 2), view_height=height)
    doc.header["$PSVPSCALE"] = 1.0


def _stable_classes(doc) -> None:
    """The CLASSES section in a fixed order: ezdxf adds the classes of the entity types in use in
    the order of a set of names, which changes with PYTHONHASHSEED."""
    from collections import OrderedDict
    doc.classes.add_required_classes(doc.dxfversion)
    doc.classes.classes = OrderedDict(sorted(doc.classes.classes.items()))


def _scripted(msp, prim: Primitive) -> None:
    """Text with sub- and superscripts (util.markup) as one TEXT entity per run, left-aligned at the
    run's estimated x, the scripts 0.7 high on shifted baselines: every CAD program shows TEXT the
    same way, whereas MTEXT's stacking codes (\\S) are ignored by some (LibreCAD) and written out
    raw by others."""
    placed = run_offsets(prim.text, prim.size)
    width = text_width(prim.text, prim.size)
    x0 = prim.points[0][0] - {"start": 0.0, "middle": width / 2, "end": width}[prim.anchor]
    y0 = prim.points[0][1]
    ax, ay = prim.points[0]
    c, s = math.cos(math.radians(prim.turn)), math.sin(math.radians(prim.turn))
    for run, dx, size, up in placed:
        if run.text.strip():          # each run's start turned about the anchor with the text
            px, py = x0 + dx - ax, y0 + up - ay
            msp.add_text(lettering(run.text), height=size,
                         dxfattribs={"layer": prim.layer, "style": STYLE, "rotation": prim.turn,
                                     "insert": (ax + c * px - s * py, ay + s * px + c * py)})
