"""What the commands share: the one-line usage error, the scene argument, the study it loads."""
from __future__ import annotations

import argparse
from typing import Any

from graphplan.util.errors import GraphplanError
from graphplan.util.files import json_text


class Parser(argparse.ArgumentParser):
    """argparse that reports a usage error as one line (exit 2)."""

    def error(self, message: str) -> None:  # type: ignore[override]
        raise GraphplanError(f"{self.prog}: {message} (see --help)")


def dumps(doc: Any) -> str:
    """Deterministic JSON for stdout and files (util.files.json_text)."""
    return json_text(doc)


def scene_arg(p: argparse.ArgumentParser, optional: bool = False) -> None:
    """The SCENE positional: a TOML file; optional ones fall back to the built-in crank-slider."""
    help_ = "scene file (TOML, see docs/scenes.md)"
    if optional:
        p.add_argument("scene", nargs="?", help=help_ + "; the built-in crank-slider when omitted")
    else:
        p.add_argument("scene", help=help_)


def lang_arg(p: argparse.ArgumentParser) -> None:
    """--lang uk|en: one option and one default for every command (the scene's ``lang``, else
    Ukrainian)."""
    p.add_argument("--lang", choices=("uk", "en"), default=None,
                   help="language of tables, captions and messages: uk or en (default: the scene's "
                        "lang, else uk)")


def lang_of(args: argparse.Namespace, st=None) -> str:
    """The language a command speaks: --lang, else the scene's ``lang``, else Ukrainian."""
    from graphplan.util.words import pick
    scene = st.mech.task.meta.get("lang") if st is not None else None
    return pick(getattr(args, "lang", None), scene)


def load_study(path: str | None):
    """The scene read and studied (structure, position 0, extremes): what every command starts from."""
    from graphplan.exact.positions import study
    from graphplan.model.scene import load
    return study(load(path))


_load = load_study   # the name the command modules used before the split
_scene_arg = scene_arg
