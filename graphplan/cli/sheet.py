"""`graphplan sheet`: the drawing sheet of a scene, written as SVG, PDF, PNG or DXF."""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

from graphplan.cli.common import caution, lang_arg, lang_of, option_error
from graphplan.util.errors import GraphplanError, keyed_error, either


def register(sub) -> None:
    p = sub.add_parser("sheet")
    p.add_argument("scene", nargs="?")
    p.add_argument("-o", "--output", required=True, metavar="FILE")
    p.add_argument("--format", default="A1")
    lang_arg(p)
    p.add_argument("--sheet", default=None, choices=["kinematics", "forces", "dynamics", "cam", "gears"])
    p.add_argument("--positions", type=int, metavar="N")
    p.add_argument("--accel", nargs="+", metavar="AT")
    p.add_argument("--precision", type=float, default=0.5, metavar="MM")
    p.add_argument("--text-as-paths", action="store_true")
    p.add_argument("--dpi", type=float, default=300)
    p.set_defaults(handler=cmd_sheet)


def cmd_sheet(args: argparse.Namespace) -> int:
    from graphplan.exact.positions import study
    from graphplan.model.scene import load
    from graphplan.sheets.form import form
    from graphplan.sheets.sheet import BUILDERS, FORMATS_OUT
    if Path(args.output).suffix.lower() not in FORMATS_OUT:
        raise option_error(f"-o {args.output}", "op out format", formats=either(*FORMATS_OUT))
    if Path(args.output).suffix.lower() in (".pdf", ".png"):
        from graphplan.drawing.raster import require_cairo
        require_cairo()                  # before the work: one line when the cairo library is missing
    gears = _gears_scene(args.scene)
    cam = _cam_scene(args.scene) if gears is None else None
    if gears is not None or args.sheet == "gears":
        if gears is None:
            raise keyed_error(GraphplanError, args.scene, "--sheet gears", "op no gears", None, gears="[gears]", planetary="[planetary]",
                              doc="docs/gears.md")
        if args.sheet not in (None, "gears"):
            raise keyed_error(GraphplanError, args.scene, f"--sheet {args.sheet}", "op gears only", None, sheet="gears")
        from graphplan.util.words import pick
        args.sheet, st = "gears", gears
        args.lang = pick(getattr(args, "lang", None), dict(gears.meta).get("lang"))
    elif cam is not None or args.sheet == "cam":
        if cam is None:
            raise keyed_error(GraphplanError, args.scene, "--sheet cam", "op no cam", None, cam="[cam]", doc="docs/cams.md")
        if args.sheet not in (None, "cam"):
            raise keyed_error(GraphplanError, args.scene, f"--sheet {args.sheet}", "op cam only", None, sheet="cam")
        from graphplan.util.words import pick
        args.sheet, st = "cam", cam
        args.lang = pick(getattr(args, "lang", None), dict(cam.meta).get("lang"))
    else:
        args.sheet = args.sheet or "kinematics"
        mech = load(args.scene)
        caution(mech, getattr(args, "lang", None))
        st = study(mech)
        args.lang = lang_of(args, st)
    f = form(args.format)
    build = BUILDERS.get(args.sheet)
    if build is None:
        raise option_error(f"--sheet {args.sheet}", "op not available")
    from graphplan.sheets.compose import SheetOptions, page_path
    from graphplan.util.words import unit, word
    sheet = build(st, f, SheetOptions(positions=args.positions, accel=args.accel, precision=args.precision,
                                      lang=args.lang, sheet=args.sheet))
    path = sheet.write(args.output, args.text_as_paths, args.dpi)
    dpi = f", {args.dpi:g} dpi" if path.suffix.lower() == ".png" else ""
    size = f"{f.width:g}×{f.height:g} {unit('mm', args.lang)}{dpi}"
    for n, page in enumerate(sheet.pages, 1):
        print(word("sheet page written", args.lang, path=page_path(path, n), form=f.name, size=size,
                   k=page.fields.get("sheet", n), m=page.fields.get("sheets", len(sheet.pages)),
                   n=len(page.placed), blocks=_blocks(len(page.placed), args.lang)),
              file=sys.stderr)      # the sheet's number in its scene's project
    return 0


def _blocks(n: int, lang: str) -> str:
    """The noun of the written-sheet line: «блоків: 4» (uk), "1 block", "4 blocks" (en)."""
    return "блоків" if lang == "uk" else ("block" if n == 1 else "blocks")


def _scene_tree(path: str | None) -> dict | None:
    """The scene file's table, or None where there is no file or it does not read (the lever scene's
    reader then says what is wrong, in one line)."""
    if path is None:
        return None
    from graphplan.model import bounds as B
    from graphplan.util.files import read_bytes
    try:
        return B.parse_toml(read_bytes(path, "scene", B.MAX_SCENE_BYTES).decode("utf-8-sig"), str(path))
    except (UnicodeDecodeError, GraphplanError):
        return None


def _cam_scene(path: str | None):
    """The cam of a [cam] scene, or None for a lever mechanism's scene (read as every scene is)."""
    from graphplan.model.cam import build, is_cam
    data = _scene_tree(path)
    return build(data, str(path)) if data is not None and is_cam(data) else None


def _gears_scene(path: str | None):
    """The gear scene of a [gears]/[planetary] scene, or None for another scene (read as every scene is)."""
    from graphplan.model.gears import build, is_gears
    data = _scene_tree(path)
    return build(data, str(path)) if data is not None and is_gears(data) and "cam" not in data else None
