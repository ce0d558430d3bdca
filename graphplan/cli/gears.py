"""`graphplan gears`: the involute pair drawn in mesh and the planetary train by velocity pictures —
measured with the ruler and compared with the closed forms (docs/gears.md); tables, the contract's
JSON, and the constructions as SVG on request."""
from __future__ import annotations

import argparse
import math
import sys

from graphplan.cli.common import lang_arg, option_error, range_fields
from graphplan.util.errors import GraphplanError, said_error


def register(sub) -> None:
    p = sub.add_parser("gears")
    p.add_argument("scene")
    p.add_argument("--precision", type=float, default=0.5, metavar="MM")
    p.add_argument("--json", action="store_true")
    p.add_argument("--svg", metavar="DIR")
    p.add_argument("--format", default="A1", metavar="A1|A2|A3")
    lang_arg(p)
    p.set_defaults(handler=cmd_gears)


def cmd_gears(args: argparse.Namespace) -> int:
    from graphplan.cli.common import dumps
    from graphplan.report.gears import gears_json, gears_table
    from graphplan.util.words import pick
    if not math.isfinite(args.precision) or not 0 <= args.precision <= 10:
        raise option_error("--precision", "op range", **range_fields(0, 10, "mm", False, args.precision))
    from graphplan.exact.gears import solve
    from graphplan.model.gears import load
    from graphplan.sheets.form import form
    from graphplan.sheets.gears import on_sheet
    gears = load(args.scene)
    lang = pick(getattr(args, "lang", None), dict(gears.meta).get("lang"))
    sol = solve(gears)
    mesh, vel, _ = on_sheet(gears, sol, form(args.format), args.precision, lang)    # that sheet's (set's) readings
    if args.svg:
        write_svg(mesh, vel, args.svg)
    doc = gears_json(sol, mesh, vel, args.scene)
    sys.stdout.write(dumps(doc) if args.json else gears_table(doc, lang, gears.title_in(lang)))
    return 0


def records(mesh, vel) -> dict:
    out = {}
    if mesh is not None:
        out["meshing"], out["sliding"] = mesh.record, mesh.lam
    if vel is not None:
        out["planetary"] = vel.record
    return out


def write_svg(mesh, vel, folder: str) -> None:
    from pathlib import Path

    from graphplan.drawing import svg
    from graphplan.util.files import write_atomic
    if Path(folder).exists() and not Path(folder).is_dir():
        raise said_error(GraphplanError, "op svg folder", str(folder), None)
    for name, rec in records(mesh, vel).items():
        page, w, h = svg.page_for(rec)
        write_atomic(Path(folder) / f"{name}.svg", svg.render(page, w, h, rec.title))
