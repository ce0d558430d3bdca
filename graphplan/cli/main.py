"""The command line. Bad input → one line on stderr and exit code 2, never a traceback."""
from __future__ import annotations

import argparse
import os
import sys
from importlib import import_module
from collections.abc import Callable, Sequence

from graphplan import __version__
from graphplan.cli.common import Parser, _load, _scene_arg, check_options, dumps  # noqa: F401
from graphplan.util.errors import GraphplanError

Handler = Callable[[argparse.Namespace], int]


def build_parser() -> argparse.ArgumentParser:
    parser = Parser(prog="graphplan", description=(
        "Graphical methods of the theory of machines and mechanisms: plans of positions, velocities "
        "and accelerations, kinematic diagrams by chords and force plans, measured like a student "
        "and compared with the exact analytic solution."))
    parser.add_argument("--version", action="version", version=f"graphplan {__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=Parser)
    for module in COMMAND_MODULES:
        import_module(module).register(sub)
    return parser


# Each module registers its subcommand with ``register(subparsers)`` and imports heavy parts lazily.
COMMAND_MODULES: tuple[str, ...] = (
    "graphplan.cli.analyze",
    "graphplan.cli.sheet",
    "graphplan.cli.plans",
    "graphplan.cli.diagrams",
    "graphplan.cli.forces",
    "graphplan.cli.dynamics",
    "graphplan.cli.key",
    "graphplan.cli.bench",
    "graphplan.cli.view",
    "graphplan.cli.cam",
    "graphplan.cli.serve",
    "graphplan.cli.gears",
)


def main(argv: Sequence[str] | None = None) -> int:
    from graphplan.util.memory import collect_less_often, keep_freed_memory
    keep_freed_memory()
    collect_less_often()
    args = None
    try:
        args = build_parser().parse_args(argv)
        if not getattr(args, "handler", None):
            build_parser().print_help()
            return 2
        check_options(args)
        return args.handler(args)
    except GraphplanError as exc:
        from graphplan.util.words import pick     # --lang, else the scene's, else Ukrainian
        print(f"graphplan: {exc.line(pick(getattr(args, 'lang', None), exc.lang))}", file=sys.stderr)
        return 2
    except BrokenPipeError:
        return 0
    except KeyboardInterrupt:
        print("graphplan: interrupted", file=sys.stderr)
        return 130
    except Exception as exc:  # an internal error is still one line unless debugging
        if os.environ.get("GRAPHPLAN_DEBUG"):
            raise
        text = " ".join(str(exc).split())[:300]           # one line, whatever the exception holds
        print(f"graphplan: internal error: {type(exc).__name__}: {text} "
              "(set GRAPHPLAN_DEBUG=1 for the traceback)", file=sys.stderr)
        return 1
