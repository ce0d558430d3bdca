"""The gallery: `python -m graphplan.cli.gallery` redraws drawings/ from examples/ (the test
tests/test_gallery.py checks the committed sheets are current)."""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]

# (scene, sheet kind, language, file name, format); a set's further sheets are name-2.svg, name-3.svg …
SHEETS = [
    ("crank_slider", "kinematics", "uk", "crank_slider.svg", "A1"),
    ("lab_crank_slider", "kinematics", "uk", "lab_crank_slider.svg", "A1"),
    ("lab_crank_slider", "kinematics", "uk", "lab_crank_slider_a3.svg", "A3"),
    ("four_bar", "kinematics", "uk", "four_bar.svg", "A1"),
    ("shaper", "kinematics", "uk", "shaper.svg", "A1"),
    ("shaper", "kinematics", "en", "shaper_en.svg", "A1"),
    ("shaper", "kinematics", "uk", "shaper_a2.svg", "A2"),
    ("slotter", "kinematics", "uk", "slotter.svg", "A1"),
    ("shaper", "forces", "uk", "shaper_forces.svg", "A1"),
    ("shaper", "forces", "uk", "shaper_forces_a2.svg", "A2"),
    ("slotter", "forces", "uk", "slotter_forces.svg", "A1"),
    ("shaper", "dynamics", "uk", "shaper_dynamics.svg", "A1"),
    ("slotter", "dynamics", "uk", "slotter_dynamics.svg", "A1"),
    ("cam_translating", "cam", "uk", "cam_translating.svg", "A1"),
    ("cam_rocking", "cam", "en", "cam_rocking_en.svg", "A1"),
    ("gears", "gears", "uk", "gears.svg", "A1"),
    ("gears_b", "gears", "en", "gears_b_en.svg", "A1"),
]


def build_set(scene: str, kind: str, lang: str, fmt: str = "A1") -> list[str]:
    """One gallery sheet set as SVG texts, sheet 1 first (default precision)."""
    from graphplan.exact.positions import study
    from graphplan.model.scene import load
    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.sheet import BUILDERS
    from graphplan.sheets.form import form
    if kind == "cam":                       # a cam scene: the sheet takes the cam itself
        from graphplan.model.cam import load as load_cam
        st = load_cam(ROOT / "examples" / f"{scene}.toml")
    elif kind == "gears":                   # a gear scene: the sheet takes the gears themselves
        from graphplan.model.gears import load as load_gears
        st = load_gears(ROOT / "examples" / f"{scene}.toml")
    else:
        st = study(load(ROOT / "examples" / f"{scene}.toml"))
    sheet = BUILDERS[kind](st, form(fmt), SheetOptions(lang=lang, sheet=kind))
    return [page.svg() for page in sheet.pages]


# the interactive explorer of each example (graphplan view), on a 2° grid to keep each page small
EXPLORERS = ["crank_slider", "lab_crank_slider", "four_bar", "shaper", "slotter"]
EXPLORER_STEP = 2.0


def explorer(scene: str, lang: str = "uk") -> str:
    """One example's offline explorer page (HTML text)."""
    from graphplan.exact.positions import study
    from graphplan.model.scene import load
    from graphplan.report.explorer import explorer_html
    from graphplan.cli.view import sheet_plans
    st = study(load(ROOT / "examples" / f"{scene}.toml"))
    return explorer_html(st, precision=0.5, step=EXPLORER_STEP, lang=lang, plans=sheet_plans(st, "A1", 0.5))


# the cam examples' constructions (graphplan cam --svg): drawings/<scene>_<part>.svg
CAMS = ["cam_translating", "cam_rocking"]


def cam_drawings(scene: str, lang: str = "uk") -> dict[str, str]:
    """One cam example's constructions as SVG texts by file name (the diagrams, the phase diagram,
    the profile), at the default precision."""
    from graphplan.drawing import svg
    from graphplan.drawing.cam import records
    from graphplan.exact.cam import solve
    from graphplan.graphic.cam import construct
    from graphplan.model.cam import load
    sol = solve(load(ROOT / "examples" / f"{scene}.toml"))
    out = {}
    for part, rec in records(sol, construct(sol), lang).items():
        page, w, h = svg.page_for(rec)
        out[f"{scene}_{part}.svg"] = svg.render(page, w, h, rec.title)
    return out


def build(scene: str, kind: str, lang: str, fmt: str = "A1") -> str:
    """The first sheet of a gallery set as SVG text."""
    return build_set(scene, kind, lang, fmt)[0]


def file_names(name: str, count: int) -> list[str]:
    """name.svg, name-2.svg, … for a set of ``count`` sheets."""
    stem = name[:-len(".svg")]
    return [name] + [f"{stem}-{n}.svg" for n in range(2, count + 1)]


def available() -> list[tuple[str, str, str, str, str]]:
    from graphplan.sheets.sheet import BUILDERS
    return [s for s in SHEETS if s[1] in BUILDERS]


ZONES = ("shaper", "kinematics", "uk", "A1")     # the sheet docs/composition.md shows with its zones


def zones_svg() -> str:
    """docs/composition/zones.svg: the shaper's A1 kinematics sheet with the box each drawing owns
    tinted and named — the composition a teacher reads (docs/composition.md)."""
    from graphplan.drawing.svg import render
    from graphplan.exact.positions import study
    from graphplan.graphic.record import Record
    from graphplan.model.scene import load
    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.form import form
    from graphplan.sheets.sheet import BUILDERS
    scene, kind, lang, fmt = ZONES
    sheet = BUILDERS[kind](study(load(ROOT / "examples" / f"{scene}.toml")), form(fmt), SheetOptions(lang=lang, sheet=kind))
    rec = Record(sheet.record.title, list(sheet.record.items))
    for p in sheet.placed:
        x0, y0, x1, y1 = p.box
        rec.add("polygon", [(x0, y0), (x1, y0), (x1, y1), (x0, y1)], role="projection", layer="zones", width=0.5)
        rec.label((x0 + 1.0, y1 + 1.0), p.name, size=2.5, layer="zones")
    import re
    svg = render(rec, sheet.form.width, sheet.form.height, "zones", embed_font=True)
    head, sep, rest = svg.partition('inkscape:label="zones"')        # the zones in blue, over the black sheet
    layer, end, tail = rest.partition("</g>")
    return head + sep + re.sub(r'(stroke|fill)="black"', r'\1="#1f5fbf"', layer) + end + tail


def write_metrics() -> Path:
    """graphplan/data/fonts/metrics.json from the packaged fonts (graphic.record.metrics_from_fonts), and
    fallback.json from the fallback font when installed (graphic.record.fallback_from_font)."""
    import json

    from graphplan.graphic.record import METRICS, metrics_from_fonts
    from graphplan.util.files import write_atomic
    from graphplan.graphic.record import FALLBACK, fallback_font, fallback_from_font
    text = json.dumps(metrics_from_fonts(), ensure_ascii=False, sort_keys=True, separators=(",", ":"))
    out = write_atomic(ROOT / "graphplan" / "data" / "fonts" / METRICS, text)
    font = fallback_font()          # kept as committed on a machine without the fallback font
    if font:
        text = json.dumps(fallback_from_font(font), ensure_ascii=False, sort_keys=True, separators=(",", ":"))
        write_atomic(ROOT / "graphplan" / "data" / "fonts" / FALLBACK, text)
    return out


def main(argv: list[str] | None = None) -> int:
    from graphplan.util.files import write_atomic
    from graphplan.util.memory import collect_less_often
    collect_less_often()
    parser = argparse.ArgumentParser(prog="python -m graphplan.cli.gallery", description=__doc__)
    parser.add_argument("-o", "--out", default=str(ROOT / "drawings"), help="folder (default: drawings/)")
    args = parser.parse_args(argv)
    print(write_metrics(), file=sys.stderr)
    for scene, kind, lang, name, fmt in available():
        pages = build_set(scene, kind, lang, fmt)
        for stale in Path(args.out).glob(f"{name[:-len('.svg')]}-*.svg"):     # a set that got shorter
            stale.unlink()
        for file, text in zip(file_names(name, len(pages)), pages):
            print(write_atomic(Path(args.out) / file, text), file=sys.stderr)
    for scene in CAMS:
        for file, text in cam_drawings(scene).items():
            print(write_atomic(Path(args.out) / file, text), file=sys.stderr)
    for scene in EXPLORERS:
        print(write_atomic(Path(args.out) / f"{scene}.html", explorer(scene)), file=sys.stderr)
    print(write_atomic(ROOT / "docs" / "composition" / "zones.svg", zones_svg()), file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
