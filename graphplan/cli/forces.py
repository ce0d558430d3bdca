"""`graphplan forces`: kinetostatics at one crank angle — the reactions by force plans against the
closed form, the balancing moment four ways (closed form, force plans, Zhukovsky lever, power
balance) — as the contract's JSON or as readable tables; drawings and full-turn charts on request."""
from __future__ import annotations

import argparse
import math
import sys

from graphplan.cli.common import lang_arg, lang_of, option_error
from graphplan.util.errors import GraphplanError
from graphplan.util.romanize import scene_title

def register(sub) -> None:
    p = sub.add_parser("forces")
    p.add_argument("scene")
    p.add_argument("--phi", type=float, metavar="DEG")
    p.add_argument("--precision", type=float, default=0.5, metavar="MM")
    p.add_argument("--format", default="A1", type=_format_arg, metavar="A1")
    p.add_argument("--json", action="store_true")
    lang_arg(p)
    p.add_argument("--svg", metavar="DIR")
    p.add_argument("--charts", metavar="DIR")
    p.set_defaults(handler=cmd_forces)


def _format_arg(text: str) -> str | None:
    from graphplan.cli.plans import _format_arg as sheet_format
    return sheet_format(text)


def cmd_forces(args: argparse.Namespace) -> int:
    from graphplan.cli.common import load_study as _load
    from graphplan.report.forces import forces_json, forces_table
    from graphplan.util.files import json_text as dumps
    from graphplan.graphic.forceplans import construct
    from graphplan.exact.kinetostatics import at_scene_angle
    if not math.isfinite(args.precision) or args.precision < 0:
        raise option_error("--precision", "op precision", got=float(args.precision))
    if args.phi is not None and not math.isfinite(args.phi):
        raise option_error("--phi", "op angle", got=args.phi)
    st = _load(args.scene, getattr(args, "lang", None))
    lang = lang_of(args, st)
    phi = at_scene_angle(st) if args.phi is None else args.phi % 360.0
    scales, sheet = {}, None
    if args.format and args.phi is None:       # the force sheet's μl and μF at its force position
        from graphplan.sheets.forces import drawing_scales, force_scales, has_loads
        if has_loads(st):
            scales = force_scales(st, args.format, args.precision)
            if args.json:
                sheet = {"format": args.format, "drawings": drawing_scales(st, args.format, args.precision)}
    fp = construct(st, phi, args.precision, **scales)
    if args.svg:
        write_svg(fp, args.svg, lang)
    if args.charts:
        from graphplan.drawing.charts import turn, write_charts
        write_charts(turn(st), args.charts, scene_title(st.mech.task.meta, st.mech.title, lang), lang)
    if args.json:
        doc = forces_json(fp)
        if sheet is not None:
            doc["sheet"] = sheet
        sys.stdout.write(dumps(doc))
    else:
        sys.stdout.write(forces_table(fp, lang))
    return 0


def write_svg(fp, folder: str, lang: str = "uk") -> None:
    from pathlib import Path

    from graphplan.drawing import svg
    from graphplan.drawing.forces import drawing, lever_record
    from graphplan.util.files import write_atomic
    for name, rec in (("forces.svg", drawing(fp, lang)), ("lever.svg", lever_record(fp, lang))):
        page, w, h = svg.page_for(rec)
        write_atomic(Path(folder) / name, svg.render(page, w, h, rec.title))
