"""`graphplan view`: the offline interactive explorer, one self-contained HTML file."""
from __future__ import annotations

import argparse
from pathlib import Path

from graphplan.cli.common import lang_arg, lang_of, load_study, scene_arg
from graphplan.util.errors import GraphplanError
from graphplan.util.files import write_atomic


def cmd_view(args: argparse.Namespace) -> int:
    from graphplan.report.explorer import explorer_html
    out = Path(args.output)
    if out.suffix.lower() not in (".html", ".htm"):
        raise GraphplanError(f"-o {out}: the explorer is an HTML file, give a name ending in .html")
    if out.exists() and out.is_dir():
        raise GraphplanError("-o needs a file name, this is a folder", str(out))
    st = load_study(args.scene)
    write_atomic(out, explorer_html(st, precision=args.precision, step=args.step, lang=lang_of(args, st)))
    return 0


def register(sub) -> None:
    p = sub.add_parser(
        "view", help="the offline interactive explorer (one HTML file)",
        description="One self-contained HTML page: the mechanism moving with a crank-angle slider, "
                    "the velocity and acceleration plans of the current angle with the table of "
                    "values (graphical at the lab's positions, exact, percent error), each "
                    "construction replayed step by step, the s–v–a diagrams and the warnings. "
                    "Open it in any browser; it makes no network request.")
    scene_arg(p, optional=True)
    p.add_argument("-o", "--output", required=True, metavar="FILE.html", help="the page to write")
    lang_arg(p)
    p.add_argument("--precision", type=float, default=0.5, metavar="MM",
                   help="drafting precision of the plans' readings, mm (default 0.5; 0 = exact)")
    p.add_argument("--step", type=float, default=1.0, metavar="DEG",
                   help="the crank-angle grid of the exact solution, degrees (default 1)")
    p.set_defaults(handler=cmd_view)
