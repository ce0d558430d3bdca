"""The cam sheet as a teacher reads it (issue 32, item 1): no raw markup in any lettering, nothing
overprinted (on the rendered sheet), the drawings filling the field above the table — for the
translating example and a generated rocking cam turning counter-clockwise."""
from __future__ import annotations

import re

import pytest

from conftest import ROOT
from graphplan.graphic.record import Record
from graphplan.model.cam import build, load
from graphplan.sheets.cam import build_cam_sheet
from graphplan.sheets.compose import SheetOptions, defects, field_of
from graphplan.sheets.form import form

ROCKING_CCW = {"title": "Кулачок", "title_en": "A cam", "cam": {
    "follower": "rocking", "swing_deg": 25, "arm": 0.09, "centre_distance": 0.11, "roller_radius": 0.007,
    "phases_deg": {"rise": 120, "dwell_far": 30, "return": 90, "dwell_near": 120},
    "laws": {"rise": "parabolic", "return": "cycloidal"}, "rpm": 100}}


def lettering(svg: str) -> list[str]:
    """Every text element's characters as drawn (its tspans joined; entities decoded)."""
    import html
    out = []
    for m in re.finditer(r"<text\b[^>]*>(.*?)</text>", svg, flags=re.S):
        out.append(html.unescape(re.sub(r"<[^>]+>", "", m.group(1))))
    return out


@pytest.mark.parametrize("cam, lang", [
    pytest.param(lambda: load(ROOT / "examples" / "cam_translating.toml"), "uk", id="translating-uk"),
    pytest.param(lambda: build(ROCKING_CCW, "<rocking ccw>"), "en", id="rocking-ccw-en", marks=pytest.mark.slow)])
def test_the_cam_sheet_reads_as_lettered(cam, lang, request):
    from inkcheck import overprinted
    if request.node.callspec.id == "translating-uk":
        # the example's: the gallery's shared sheet (a cam alone is numbered 1 of 1: its SVG is this
        # builder's, byte for byte — stop 56 compared them), not composed a second time
        from conftest import example_sheet
        sheet = example_sheet("cam_translating", "cam", "A1", "uk")
    else:
        sheet = build_cam_sheet(cam(), form("A1"), SheetOptions(lang=lang, sheet="cam"))
    svg = sheet.svg()
    words = lettering(svg)
    assert len(words) > 200
    raw = [w for w in words if any(c in w for c in "_^{}")]
    assert not raw, raw[:5]
    for must in ("ω", "O", "R", "φ", "d", "μ"):
        assert any(must in w for w in words), must
    assert not defects(sheet)
    assert overprinted(svg) == []
    from svgboxes import off_field
    assert off_field(svg, sheet.form) == []        # every element in the field, read off the SVG
    # the drawings fill the field: their boxes span its width and more than half its height
    x0, y0, x1, y1 = field_of(sheet.form)
    # (the phase diagram placed apart from the s–v–a diagrams when the notes stand under it)
    boxes = [p.record.bounds() for p in sheet.placed if p.name in ("diagrams", "phase", "profile")]
    assert len(boxes) in (2, 3)
    width = sum(b[2] - b[0] for b in boxes)
    height = max(b[3] - b[1] for b in boxes)
    assert width > 0.85 * (x1 - x0) and height > 0.6 * (y1 - y0), (width, height)
    # the phase diagram stands beside the s diagram at μ_s, its s axis level with the s diagram's: the
    # point of each division on it (K k) at the height of that division's ordinate on the s diagram
    if lang == "uk":          # the translating follower (its s axis straight)
        rec = Record("diagrams", [q for p in sheet.placed if p.name in ("diagrams", "phase") for q in p.record.items])
        tops = {p.step: p.points[1][1] for p in rec.items if p.step.startswith("s at ")}
        ks = {p.step: p.points[0][1] for p in rec.items if p.kind == "point" and p.step.startswith("K ")}
        assert len(tops) == len(ks) > 10
        for k in range(len(ks)):
            assert abs(ks[f"K {k}"] - tops[f"s at {k}"]) < 0.5, k
