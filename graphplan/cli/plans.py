"""`graphplan plans`: the position, velocity and acceleration plans, measured and compared."""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

from graphplan.cli.common import lang_arg, lang_of, load_study, option_error
from graphplan.util.errors import GraphplanError, said_error, either
from graphplan.util.files import json_text, write_atomic

def _format_arg(text: str) -> str | None:
    """A sheet format (A1 … A4) or "none"."""
    if text.lower() == "none":
        return None
    if text.upper() not in ("A1", "A2", "A3", "A4"):
        raise option_error("--format", "op sheet format", got=repr(text), formats=either("A1", "A2", "A3", "A4", "none"))
    return text.upper()


def cmd_plans(args: argparse.Namespace) -> int:
    from graphplan.graphic.plans import build_plans
    from graphplan.report.plans import plans_json, plans_table, svg_documents
    st = load_study(args.scene, getattr(args, "lang", None))
    lang = lang_of(args, st)
    if args.positions is not None and not 2 <= args.positions <= 3600:
        raise option_error("--positions", "op whole", lo=2, hi=3600, got=args.positions)
    mu = {"mu_l": args.mu_l, "mu_v": args.mu_v, "mu_a": args.mu_a}
    if args.format and None in mu.values():      # the sheet's scales, unless the user gives them
        from graphplan.sheets.kinematics import sheet_scales
        drawn = sheet_scales(st, args.format, args.positions, args.accel, args.precision)
        mu = {k: v if v is not None else drawn[k] for k, v in mu.items()}
    plans = build_plans(st, count=args.positions, accel=args.accel, precision=args.precision, **mu)
    if args.svg:
        folder = Path(args.svg)
        if folder.exists() and not folder.is_dir():
            raise said_error(GraphplanError, "op svg folder", str(folder), None)
        for name, text in svg_documents(plans, lang).items():
            write_atomic(folder / name, text)
    if args.json:
        sys.stdout.write(json_text(plans_json(plans)))
    else:
        sys.stdout.write(plans_table(plans, lang))
    return 0


def register(sub) -> None:
    p = sub.add_parser("plans")
    p.add_argument("scene", nargs="?")
    p.add_argument("--positions", type=int, metavar="N")
    p.add_argument("--accel", nargs="+", metavar="AT")
    p.add_argument("--precision", type=float, default=0.5, metavar="MM")
    p.add_argument("--mu-l", type=float, metavar="M_PER_MM")
    p.add_argument("--mu-v", type=float, metavar="V_PER_MM")
    p.add_argument("--mu-a", type=float, metavar="A_PER_MM")
    p.add_argument("--format", default="A1", type=_format_arg, metavar="A1")
    p.add_argument("--json", action="store_true")
    p.add_argument("--svg", metavar="DIR")
    lang_arg(p)
    p.set_defaults(handler=cmd_plans)
