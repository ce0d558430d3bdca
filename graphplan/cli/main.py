"""The command line. Bad input → one line on stderr and exit code 2, never a traceback."""
from __future__ import annotations

import argparse
import json
import os
import sys
from importlib import import_module
from collections.abc import Callable, Sequence
from typing import Any

from graphplan import __version__
from graphplan.util.errors import GraphplanError

Handler = Callable[[argparse.Namespace], int]


class _Parser(argparse.ArgumentParser):
    """argparse that reports a usage error as one line (exit 2)."""

    def error(self, message: str) -> None:  # type: ignore[override]
        raise GraphplanError(f"{self.prog}: {message} (see --help)")


def dumps(doc: Any) -> str:
    """Deterministic JSON for stdout and files."""
    return json.dumps(doc, ensure_ascii=False, indent=1, allow_nan=False) + "\n"


def _scene_arg(p: argparse.ArgumentParser, optional: bool = False) -> None:
    help_ = "scene file (TOML, see docs/scenes.md)"
    if optional:
        p.add_argument("scene", nargs="?", help=help_ + "; the built-in crank-slider when omitted")
    else:
        p.add_argument("scene", help=help_)


def _load(path: str | None):
    from graphplan.exact.positions import study
    from graphplan.model.scene import load
    return study(load(path))


def _angles(st, args) -> tuple[list[float], list[int]]:
    """Crank angles asked for: --phi values, else positions 0 … N−1 from position 0."""
    import numpy as np
    if getattr(args, "phi", None):
        phis = [float(p) % 360.0 for p in args.phi]
        return phis, list(range(len(phis)))
    count = args.positions or st.mech.count
    if not 2 <= count <= 100000:
        raise GraphplanError(f"--positions must be from 2 to 100000, got {count}")
    return [float(v) for v in np.asarray(st.positions(count))], list(range(count))


def cmd_analyze(args: argparse.Namespace) -> int:
    import numpy as np

    from graphplan.report.analysis import analyze_json, analyze_table
    st = _load(args.scene)
    phis, indices = _angles(st, args)
    phi = np.asarray(phis)
    if args.json:
        sys.stdout.write(dumps(analyze_json(st, phi, indices)))
    else:
        sys.stdout.write(analyze_table(st, phi, indices))
    return 0


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(prog="graphplan", description=(
        "Graphical methods of the theory of machines and mechanisms: plans of positions, velocities "
        "and accelerations, kinematic diagrams by chords and force plans, measured like a student "
        "and compared with the exact analytic solution."))
    parser.add_argument("--version", action="version", version=f"graphplan {__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    p = sub.add_parser("analyze", help="exact (analytic) kinematics: positions, velocities, accelerations",
                       description="Exact kinematics of every point, link and sliding pair.")
    _scene_arg(p, optional=True)
    p.add_argument("--positions", type=int, metavar="N", help="number of positions (default: the scene's)")
    p.add_argument("--phi", type=float, nargs="+", metavar="DEG",
                   help="crank angles instead of positions (deg from +x, counter-clockwise)")
    p.add_argument("--json", action="store_true", help="the JSON of the contract instead of tables")
    p.set_defaults(handler=cmd_analyze)
    for module in COMMAND_MODULES:
        import_module(module).register(sub)
    return parser


# Each module registers its subcommand with ``register(subparsers)`` and imports heavy parts lazily.
COMMAND_MODULES: tuple[str, ...] = (
    "graphplan.sheets.sheet",
    "graphplan.report.plans",
    "graphplan.graphic.diagrams",
    "graphplan.cli.forces",
    "graphplan.cli.key",
    "graphplan.bench.run",
)


def main(argv: Sequence[str] | None = None) -> int:
    from graphplan.util.memory import keep_freed_memory
    keep_freed_memory()
    try:
        args = build_parser().parse_args(argv)
        if not getattr(args, "handler", None):
            build_parser().print_help()
            return 2
        return args.handler(args)
    except GraphplanError as exc:
        print(f"graphplan: {exc.line()}", file=sys.stderr)
        return 2
    except BrokenPipeError:
        return 0
    except KeyboardInterrupt:
        print("graphplan: interrupted", file=sys.stderr)
        return 130
    except Exception as exc:  # an internal error is still one line unless debugging
        if os.environ.get("GRAPHPLAN_DEBUG"):
            raise
        print(f"graphplan: internal error: {type(exc).__name__}: {exc} "
              "(set GRAPHPLAN_DEBUG=1 for the traceback)", file=sys.stderr)
        return 1
