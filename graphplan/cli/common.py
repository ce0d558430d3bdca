"""What the commands share: the one-line usage error, the scene argument, the study it loads."""
from __future__ import annotations

import argparse
import math
from typing import Any

from graphplan.util.errors import GraphplanError
from graphplan.util.files import json_text


class Parser(argparse.ArgumentParser):
    """argparse that reports a usage error as one line (exit 2)."""

    def error(self, message: str) -> None:  # type: ignore[override]
        command = self.prog.partition(" ")[2]       # "graphplan analyze" → "analyze"; main adds "graphplan: "
        raise GraphplanError(f"{command}: {message} (see --help)" if command else f"{message} (see --help)")


# Every numeric option's meaningful range, checked once before any command runs (main.check_options):
# dest → (low, high, unit, low excluded). A value outside is one line naming the option.
OPTION_BOUNDS: dict[str, tuple[float, float, str, bool]] = {
    "phi": (-1e6, 1e6, "deg", False),
    "precision": (0.0, 10.0, "mm", False),
    "mu_l": (1e-8, 10.0, "m/mm", False),
    "mu_v": (1e-8, 1e8, "(m/s)/mm", False),
    "mu_a": (1e-6, 1e14, "(m/s²)/mm", False),
    "h1": (1.0, 1000.0, "mm", False),
    "h2": (1.0, 1000.0, "mm", False),
    "L": (10.0, 2000.0, "mm", False),
    "height": (1.0, 2000.0, "mm", False),
    "tolerance": (0.0, 100.0, "", True),
    "positions": (2, 36000, "", False),      # 0.01° steps; analyze's JSON of 36 000 positions is ~50 MB
    "at": (0, 3600, "", False),
    "jobs": (1, 64, "", False),
}


MAX_VALUES = 3600        # values of one list option (--phi, --accel, --at): a turn in 0.1° steps


def check_options(args: argparse.Namespace) -> None:
    """Every numeric option within its range (OPTION_BOUNDS), before any work: one line naming it."""
    for dest in ("phi", "accel", "at", "tol"):
        given = getattr(args, dest, None)
        if isinstance(given, list) and len(given) > MAX_VALUES:
            raise GraphplanError(f"--{dest}: at most {MAX_VALUES} values, got {len(given)}")
    for dest, (lo, hi, unit, lo_open) in OPTION_BOUNDS.items():
        given = getattr(args, dest, None)
        values = given if isinstance(given, list) else [given]
        for v in values:
            if not isinstance(v, (int, float)) or isinstance(v, bool):
                continue
            low_ok = v > lo if lo_open else v >= lo
            if not (math.isfinite(v) and low_ok and v <= hi):
                option = "--" + dest.replace("_", "-") + (" (a scale)" if dest.startswith("mu_") else "")
                unit_text = f" {unit}" if unit else ""
                raise GraphplanError(f"{option} must be from {lo:g}{' (exclusive)' if lo_open else ''} "
                                     f"to {hi:g}{unit_text}, got {v:g}")


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
