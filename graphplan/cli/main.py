"""The command line. Bad input → one line on stderr and exit code 2, never a traceback."""
from __future__ import annotations

import argparse
import os
import sys
from importlib import import_module
from collections.abc import Callable, Sequence

from graphplan import __version__
from graphplan.cli.common import Parser, _load, _scene_arg, check_options, dumps, tell_cautions  # noqa: F401
from graphplan.util.errors import GraphplanError

Handler = Callable[[argparse.Namespace], int]


def build_parser(lang: str = "uk") -> argparse.ArgumentParser:
    """The command line, its help in ``lang`` (the catalogue's, cli.helps)."""
    from graphplan.cli.helps import speak
    parser = Parser(prog="graphplan")
    parser.add_argument("--version", action="version", version=f"graphplan {__version__}")
    parser.add_argument("--lang", dest="lang_before", choices=("uk", "en"), default=None)
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=Parser, title="commands")
    for module in COMMAND_MODULES:
        import_module(module).register(sub)
    speak(parser, lang)
    return parser


def help_lang(argv: Sequence[str] | None) -> str:
    """The language the parser (its help, its usage errors' names) speaks: --lang as written, else — when
    the help is asked for — the scene's ``lang`` (main.told_lang), else Ukrainian."""
    words = list(sys.argv[1:] if argv is None else argv)
    if not words or "-h" in words or "--help" in words:
        return told_lang(words, None)
    for k, item in enumerate(words):
        if item == "--lang" and k + 1 < len(words) and words[k + 1] in ("uk", "en"):
            return words[k + 1]
        if item in ("--lang=uk", "--lang=en"):
            return item[7:]
    return "uk"


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
        lang = help_lang(argv)
        args = build_parser(lang).parse_args(argv)
        if getattr(args, "lang", None) is None and getattr(args, "lang_before", None):
            args.lang = args.lang_before                  # graphplan --lang en COMMAND …
        if not getattr(args, "handler", None):
            build_parser(lang).print_help()
            return 2
        check_options(args)
        code = args.handler(args)
        tell_cautions(code == 0)
        return code
    except GraphplanError as exc:
        print(f"graphplan: {exc.line(told_lang(argv, args, exc))}", file=sys.stderr)
        return 2
    except BrokenPipeError:
        return 0
    except KeyboardInterrupt:
        from graphplan.util.words import word
        print(f"graphplan: {word('op interrupted', told_lang(argv, args))}", file=sys.stderr)
        return 130
    except Exception as exc:  # an internal error is still one line unless debugging
        if os.environ.get("GRAPHPLAN_DEBUG"):
            raise
        from graphplan.util.words import word
        text = " ".join(str(exc).split())[:300]           # one line, whatever the exception holds
        print(f"graphplan: {word('op internal', told_lang(argv, args), name=type(exc).__name__, text=text)}",
              file=sys.stderr)
        return 1
    finally:
        tell_cautions(False)             # a run that did not succeed keeps its one line


def told_lang(argv: Sequence[str] | None, args: argparse.Namespace | None, exc: GraphplanError | None = None) -> str:
    """The language a refusal speaks: --lang (as parsed, or as written when the parse itself failed),
    else the scene's ``lang`` (the error's, or read from the scene named on the command line), else
    Ukrainian."""
    from graphplan.util.words import LANGS, pick
    words = list(sys.argv[1:] if argv is None else argv)
    told = getattr(args, "lang", None)
    for k, item in enumerate(words):
        if told is None and item == "--lang" and k + 1 < len(words) and words[k + 1] in LANGS:
            told = words[k + 1]
        elif told is None and item.startswith("--lang=") and item[7:] in LANGS:
            told = item[7:]
    scene = exc.lang if exc is not None else None
    if told is None and scene is None:
        path = getattr(args, "scene", None) or next((w for w in words if w.endswith(".toml")), None)
        scene = _scene_lang(path)
    return pick(told if told in LANGS else None, scene if scene in LANGS else None)


def _scene_lang(path: object) -> str | None:
    """The ``lang`` of the scene file at ``path``, or None where there is none or it does not read."""
    if not isinstance(path, str):
        return None
    try:
        from graphplan.model import bounds as B
        from graphplan.util.files import read_bytes
        data = B.parse_toml(read_bytes(path, "scene", B.MAX_SCENE_BYTES).decode("utf-8-sig"), path)
    except (GraphplanError, UnicodeDecodeError, ValueError):
        return None
    lang = data.get("lang") if isinstance(data, dict) else None
    return lang if isinstance(lang, str) else None
