"""`graphplan dynamics`: the machine's dynamics reduced to the crank — the reduced inertia and
moments, the flywheel by the graphical (Wittenbauer) construction and the approximate methods
against the exact one from the equation of motion, and the motor — as the contract's JSON or as
tables; the drawings on request."""
from __future__ import annotations

import argparse
import math
import sys

from graphplan.cli.common import lang_arg, option_error
from graphplan.util.errors import GraphplanError


def register(sub) -> None:
    p = sub.add_parser("dynamics")
    p.add_argument("scene")
    p.add_argument("--delta", type=float, metavar="D")
    p.add_argument("--precision", type=float, default=0.5, metavar="MM")
    p.add_argument("--divisions", type=int, metavar="N")
    p.add_argument("--format", default="A1", metavar="A1")
    p.add_argument("--json", action="store_true")
    p.add_argument("--svg", metavar="DIR")
    lang_arg(p)
    p.set_defaults(handler=cmd_dynamics)


def cmd_dynamics(args: argparse.Namespace) -> int:
    from graphplan.cli.common import dumps, lang_arg, lang_of, load_study
    from graphplan.exact.dynamics import analyse, check_delta, check_divisions
    from graphplan.graphic.flywheel import redrawn
    from graphplan.report.dynamics import dynamics_json, dynamics_table
    if not math.isfinite(args.precision) or args.precision < 0:
        raise option_error("--precision", "op precision", got=float(args.precision))
    if args.delta is not None:
        check_delta(args.delta)
    if args.divisions is not None:
        check_divisions(args.divisions)
    st = load_study(args.scene, getattr(args, "lang", None))
    try:
        dyn = analyse(st, args.delta)
    except GraphplanError as exc:
        raise GraphplanError(str(exc), exc.where or args.scene, exc.said, exc.lang) from None
    from graphplan.sheets.dynamics import dynamics_scales     # the construction the sheet draws
    # as the sheet draws it: redrawn on more divisions where the first drawing is past the lab's 5 %
    # (graphic.flywheel.redrawn), unless --divisions (or the scene) gives them
    f = redrawn(dyn, args.divisions, args.precision, given="option" if args.divisions is not None else None,
                **dynamics_scales(st, dyn, args.format or "A1", args.divisions, args.precision))
    args.lang = lang_of(args, st)
    if args.svg:
        write_svg(f, args.svg, args.lang)
    sys.stdout.write(dumps(dynamics_json(f)) if args.json else dynamics_table(f, args.lang))
    return 0


def write_svg(f, folder: str, lang: str) -> None:
    from pathlib import Path

    from graphplan.drawing import svg
    from graphplan.drawing.flywheel import records
    from graphplan.util.files import write_atomic
    for name, rec in records(f, lang).items():
        page, w, h = svg.page_for(rec)
        write_atomic(Path(folder) / f"{name}.svg", svg.render(page, w, h, rec.title))
