"""`graphplan sheet`: the drawing sheet of a scene, written as SVG, PDF, PNG or DXF."""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

from graphplan.util.errors import GraphplanError


def register(sub) -> None:
    p = sub.add_parser("sheet", help="the drawing sheet (SVG, PDF, PNG or DXF by the suffix)",
                       description="Lay out the drawing sheet: frame, title block, plans, diagrams and "
                                   "tables. Without SCENE the built-in crank-slider is drawn.")
    p.add_argument("scene", nargs="?", help="scene file (TOML); the built-in crank-slider when omitted")
    p.add_argument("-o", "--output", required=True, metavar="FILE",
                   help="output file: .svg, .pdf, .png or .dxf")
    p.add_argument("--format", default="A1", help="sheet format: A1 (default), A2, A3; what does not fit "
                   "goes to further sheets of the set (FILE-2, FILE-3 …)")
    p.add_argument("--lang", default="uk", choices=["uk", "en"], help="labels: Ukrainian (default) or English")
    p.add_argument("--sheet", default="kinematics", choices=["kinematics", "forces"],
                   help="which sheet: kinematics (default) or forces")
    p.add_argument("--positions", type=int, metavar="N", help="number of positions (default: the scene's)")
    p.add_argument("--accel", nargs="+", metavar="AT", help="acceleration plans: degrees or #index")
    p.add_argument("--precision", type=float, default=0.5, metavar="MM", help="drafting precision (0 = exact)")
    p.add_argument("--text-as-paths", action="store_true", help="write lettering as outlines (SVG/PDF/PNG)")
    p.set_defaults(handler=cmd_sheet)


def cmd_sheet(args: argparse.Namespace) -> int:
    from graphplan.exact.positions import study
    from graphplan.model.scene import load
    from graphplan.sheets.form import form
    from graphplan.sheets.sheet import BUILDERS, FORMATS_OUT
    if Path(args.output).suffix.lower() not in FORMATS_OUT:
        raise GraphplanError(f"-o {args.output}: unknown format; use " + ", ".join(FORMATS_OUT))
    st = study(load(args.scene))
    f = form(args.format)
    build = BUILDERS.get(args.sheet)
    if build is None:
        raise GraphplanError(f"--sheet {args.sheet}: not available")
    from graphplan.sheets.compose import SheetOptions, page_path
    sheet = build(st, f, SheetOptions(positions=args.positions, accel=args.accel, precision=args.precision,
                                      lang=args.lang, sheet=args.sheet))
    path = sheet.write(args.output, args.text_as_paths)
    for n, page in enumerate(sheet.pages, 1):
        print(f"{page_path(path, n)} ({f.name} {f.width:g}×{f.height:g} mm, sheet {n} of {len(sheet.pages)}, "
              f"{len(page.placed)} blocks)", file=sys.stderr)
    return 0
