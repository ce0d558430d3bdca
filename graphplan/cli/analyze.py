"""`graphplan analyze`: the exact kinematics of every point, link and sliding pair."""
from __future__ import annotations

import argparse
import sys

from graphplan.cli.common import lang_arg, lang_of, load_study, scene_arg, option_error
from graphplan.util.errors import GraphplanError
from graphplan.util.files import json_text


def _angles(st, args) -> tuple[list[float], list[int]]:
    """Crank angles asked for: --phi values, else positions 0 … N−1 from position 0."""
    import numpy as np
    if getattr(args, "phi", None):
        phis = [float(p) % 360.0 for p in args.phi]
        return phis, list(range(len(phis)))
    count = args.positions or st.mech.task.count
    if not 2 <= count <= 36000:
        raise option_error("--positions", "op whole", lo=2, hi=36000, got=count)
    return [float(v) for v in np.asarray(st.positions(count))], list(range(count))


def cmd_analyze(args: argparse.Namespace) -> int:
    import numpy as np

    from graphplan.report.analysis import analyze_json, analyze_table
    st = load_study(args.scene, getattr(args, "lang", None))
    phis, indices = _angles(st, args)
    phi = np.asarray(phis)
    if args.json:
        sys.stdout.write(json_text(analyze_json(st, phi, indices)))
    else:
        sys.stdout.write(analyze_table(st, phi, indices, lang_of(args, st)))
    return 0


def register(sub) -> None:
    p = sub.add_parser("analyze")
    scene_arg(p, optional=True)
    p.add_argument("--positions", type=int, metavar="N")
    p.add_argument("--phi", type=float, nargs="+", metavar="DEG")
    p.add_argument("--json", action="store_true")
    lang_arg(p)
    p.set_defaults(handler=cmd_analyze)
