"""`graphplan cam`: a cam mechanism synthesised by the graphical method — the law's diagrams
integrated by chords, the phase diagram's smallest base radius, the profile by inversion — measured
with the ruler and compared with the exact solution (docs/cams.md); tables, the contract's JSON, and
the constructions as SVG on request."""
from __future__ import annotations

import argparse
import math
import sys

from graphplan.cli.common import lang_arg, option_error, range_fields
from graphplan.util.errors import GraphplanError, said_error


def register(sub) -> None:
    p = sub.add_parser("cam")
    p.add_argument("scene")
    p.add_argument("--divisions", type=int, metavar="N")
    p.add_argument("--precision", type=float, default=0.5, metavar="MM")
    p.add_argument("--json", action="store_true")
    p.add_argument("--svg", metavar="DIR")
    p.add_argument("--format", default="A1", metavar="A1|A2|A3")
    lang_arg(p)
    p.set_defaults(handler=cmd_cam)


def cmd_cam(args: argparse.Namespace) -> int:
    from graphplan.cli.common import dumps
    from graphplan.exact.cam import solve
    from graphplan.model.cam import load
    from graphplan.report.cam import cam_json, cam_table
    from graphplan.util.words import pick
    if not math.isfinite(args.precision) or not 0 <= args.precision <= 10:
        raise option_error("--precision", "op range", **range_fields(0, 10, "mm", False, args.precision))
    if args.divisions is not None and not 2 <= args.divisions <= 360:
        raise option_error("--divisions", "op whole", lo=2, hi=360, got=args.divisions)
    from graphplan.sheets.cam import construct_on
    from graphplan.sheets.form import form
    cam = load(args.scene)
    f = form(args.format)
    lang = pick(getattr(args, "lang", None), dict(cam.meta).get("lang"))
    try:
        sol = solve(cam)
        g = construct_on(sol, f, args.divisions, args.precision, lang)     # the sheet's in that language
    except GraphplanError as exc:
        raise GraphplanError(str(exc), exc.where or args.scene, exc.said, exc.lang) from None
    if args.svg:
        write_svg(sol, g, args.svg, lang)
    doc = cam_json(sol, g, args.scene)
    sys.stdout.write(dumps(doc) if args.json else cam_table(doc, lang, cam.title_in(lang)))
    return 0


def write_svg(sol, g, folder: str, lang: str) -> None:
    from pathlib import Path

    from graphplan.drawing import svg
    from graphplan.drawing.cam import records
    from graphplan.util.files import write_atomic
    if Path(folder).exists() and not Path(folder).is_dir():
        raise said_error(GraphplanError, "op svg folder", str(folder), None)
    for name, rec in records(sol, g, lang).items():
        page, w, h = svg.page_for(rec)
        write_atomic(Path(folder) / f"{name}.svg", svg.render(page, w, h, rec.title))
