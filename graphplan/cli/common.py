"""What the commands share: the one-line usage error, the scene argument, the study it loads."""
from __future__ import annotations

import argparse
import math
import re
from typing import Any

from graphplan.util.errors import GraphplanError
from graphplan.util.files import json_text


# argparse's own usage errors (Python's wording) → the catalogue's keys: translated, fields kept
_ARGPARSE: tuple[tuple[re.Pattern[str], str], ...] = tuple((re.compile(p), k) for p, k in (
    (r"^the following arguments are required: (?P<names>.+)$", "ap required"),
    (r"^unrecognized arguments: (?P<names>.+)$", "ap unrecognized"),
    (r"^argument (?P<arg>\S+): invalid choice: (?P<got>.+?) \(choose from (?P<choices>.+)\)$", "ap choice"),
    (r"^argument (?P<arg>\S+): invalid (?P<kind>\w+) value: (?P<got>.+)$", "ap invalid"),
    (r"^argument (?P<arg>\S+): expected one argument$", "ap one"),
    (r"^argument (?P<arg>\S+): expected at least one argument$", "ap some"),
    (r"^argument (?P<arg>\S+): not allowed with argument (?P<other>\S+)$", "ap not allowed"),
    (r"^ambiguous option: (?P<got>\S+) could match (?P<names>.+)$", "ap ambiguous"),
))


def usage_said(message: str) -> dict[str, str]:
    """An argparse usage error in every language: a message argparse words (``_ARGPARSE``) through the
    catalogue, its fields (options, values) as given; any other one in English in both."""
    from graphplan.util.words import WORDS, said
    for pattern, key in _ARGPARSE:
        m = pattern.match(message)
        if m:
            fields: dict[str, object] = dict(m.groupdict())
            kind = fields.get("kind")
            if kind is not None and f"ap kind {kind}" in WORDS:
                fields["kind"] = lambda lang, k=f"ap kind {kind}": WORDS[k][0 if lang == "uk" else 1]
            return said(key, **fields)
    return said("ap other", text=message)


class Parser(argparse.ArgumentParser):
    """argparse that reports a usage error as one line (exit 2), in either language (the line main
    prints speaks --lang, else the scene's, else Ukrainian)."""

    def error(self, message: str) -> None:  # type: ignore[override]
        from graphplan.util.words import word
        command = self.prog.partition(" ")[2]       # "graphplan analyze" → "analyze"; main adds "graphplan: "
        texts = {lang: (f"{command}: " if command else "") + word("op usage", lang, text=text)
                 for lang, text in usage_said(message).items()}
        raise GraphplanError(texts["en"], None, texts)


def option_error(option: str | None, key: str, /, **fields: object) -> GraphplanError:
    """A bad command-line option, worded by the catalogue: "--option: text" (``option`` as typed)."""
    from graphplan.util.errors import keyed_error
    return keyed_error(GraphplanError, None, option or "", key, None, **fields)


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
            raise option_error(f"--{dest}", "op many values", most=MAX_VALUES, got=len(given))
    for dest, (lo, hi, unit, lo_open) in OPTION_BOUNDS.items():
        given = getattr(args, dest, None)
        values = given if isinstance(given, list) else [given]
        for v in values:
            if not isinstance(v, (int, float)) or isinstance(v, bool):
                continue
            low_ok = v > lo if lo_open else v >= lo
            if not (math.isfinite(v) and low_ok and v <= hi):
                raise option_error("--" + dest.replace("_", "-"), "op range", **range_fields(lo, hi, unit, lo_open, v))


def range_fields(lo: float, hi: float, unit: str, lo_open: bool, got: object) -> dict:
    """The fields of "op range": bounds and value as numbers in each language, the unit in it."""
    from graphplan.util.words import UNITS, word

    def said_unit(lang: str) -> str:
        text = UNITS[unit][0 if lang == "uk" else 1] if unit in UNITS else unit
        return text if text in ("", "°") else " " + text          # 30°, 10 mm
    number = isinstance(got, (int, float)) and not isinstance(got, bool)   # as typed: 1e-08, 0.05, nan
    return {"lo": f"{lo:g}", "hi": f"{hi:g}", "unit": said_unit, "got": f"{got:g}" if number else str(got),
            "open": (lambda lang: word("op exclusive", lang)) if lo_open else ""}


def dumps(doc: Any) -> str:
    """Deterministic JSON for stdout and files (util.files.json_text)."""
    return json_text(doc)


def scene_arg(p: argparse.ArgumentParser, optional: bool = False) -> None:
    """The SCENE positional: a TOML file; optional ones fall back to the built-in crank-slider (the help:
    util.helpwords "* scene")."""
    if optional:
        p.add_argument("scene", nargs="?")
    else:
        p.add_argument("scene")


def lang_arg(p: argparse.ArgumentParser) -> None:
    """--lang uk|en: one option and one default for every command (the scene's ``lang``, else
    Ukrainian)."""
    p.add_argument("--lang", choices=("uk", "en"), default=None)


def lang_of(args: argparse.Namespace, st=None) -> str:
    """The language a command speaks: --lang, else the scene's ``lang``, else Ukrainian."""
    from graphplan.util.words import pick
    scene = st.mech.task.meta.get("lang") if st is not None else None
    return pick(getattr(args, "lang", None), scene)


def load_study(path: str | None, lang: str | None = None):
    """The scene read and studied (structure, position 0, extremes): what every command starts from.
    The scene's likely slips (model.cautions) are told on stderr first, one line each, in ``lang``
    (--lang), else the scene's."""
    from graphplan.exact.positions import study
    from graphplan.model.scene import load
    mech = load(path)
    caution(mech, lang)
    return study(mech)


CAUTIONS: list[str] = []     # the run's cautions, told (main) once the command has succeeded


def caution(mech, lang: str | None = None) -> None:
    """The scene's likely slips (a centre of mass outside its link, a point far beyond it, lengths in
    millimetres) kept for stderr: "graphplan: warning: <file>: <what>", one line each, in --lang, else
    the scene's language. main prints them when the command succeeds — a refused run stays one line."""
    from graphplan.model.cautions import cautions
    from graphplan.util.words import pick, word
    said_ = pick(lang, mech.task.meta.get("lang"))
    for texts in cautions(mech):
        line = f"graphplan: {word('caution', said_)}: {mech.source}: {texts[said_]}"
        if line not in CAUTIONS:
            CAUTIONS.append(line)


def tell_cautions(told: bool) -> None:
    """The run's cautions on stderr (``told``: the command succeeded), then forgotten."""
    import sys
    if told:
        for line in CAUTIONS:
            print(line, file=sys.stderr)
    CAUTIONS.clear()


_load = load_study   # the name the command modules used before the split
_scene_arg = scene_arg
