"""The help in the reader's language: every parser's texts from the catalogue (util.helpwords).

The language is the one the program's messages speak (main.told_lang): --lang wherever it is written
(before or after the command), else the ``lang`` of the scene named on the command line, else
Ukrainian. The environment's LANG/LC_ALL is not read: the tables, sheets and refusals do not read it
either, and a help in another language than the run it explains would mislead.
"""
from __future__ import annotations

import argparse
import shutil
import textwrap

from graphplan.util.helpwords import HELPS, METAVARS, help_text

MOST_COLUMNS = 100       # argparse wraps at the terminal's width, never wider than this


def formatter(lang: str) -> type[argparse.HelpFormatter]:
    """argparse's formatter speaking ``lang``: its "usage:" from the catalogue, lines ≤ MOST_COLUMNS,
    a hyphenated word never broken («кривошипно-повзунний», "crank-slider")."""
    class Formatter(argparse.HelpFormatter):
        def __init__(self, prog: str, indent_increment: int = 2, max_help_position: int = 24,
                     width: int | None = None) -> None:
            width = min(width or shutil.get_terminal_size().columns - 2, MOST_COLUMNS)
            super().__init__(prog, indent_increment, max_help_position, width)

        def _split_lines(self, text: str, width: int) -> list[str]:
            return textwrap.wrap(self._whitespace_matcher.sub(" ", text).strip(), width, break_on_hyphens=False)

        def _fill_text(self, text: str, width: int, indent: str) -> str:
            return textwrap.fill(self._whitespace_matcher.sub(" ", text).strip(), width, initial_indent=indent,
                                 subsequent_indent=indent, break_on_hyphens=False)

        def add_usage(self, usage, actions, groups, prefix=None) -> None:
            super().add_usage(usage, actions, groups, help_text("@ usage", lang) if prefix is None else prefix)
    Formatter.lang = lang
    return Formatter


def speak(parser: argparse.ArgumentParser, lang: str, command: str = "graphplan") -> None:
    """Every text of ``parser`` and its subcommands' parsers in ``lang``: descriptions, option helps,
    the commands' list, argparse's headings and its -h/--version lines, metavars that are words.
    Option names, choices and behaviour stay as they are."""
    parser.formatter_class = formatter(lang)
    if f"{command} desc" in HELPS:
        parser.description = help_text(f"{command} desc", lang)
    parser._positionals.title = help_text("@ positional", lang)
    parser._optionals.title = help_text("@ options", lang)
    for group in parser._action_groups:
        if any(isinstance(a, argparse._SubParsersAction) for a in group._group_actions):
            group.title = help_text("@ commands", lang)
    for action in parser._actions:
        if isinstance(action, argparse._HelpAction):
            action.help = help_text("@ help", lang)
        elif isinstance(action, argparse._VersionAction):
            action.help = help_text("@ version", lang)
        elif isinstance(action, argparse._SubParsersAction):
            action.metavar = _metavar(action.metavar, lang)
            listed_ = {listed.dest for listed in action._choices_actions}
            action._choices_actions.extend(action._ChoicesPseudoAction(name, (), None)
                                           for name in action.choices if name not in listed_)
            for listed in action._choices_actions:
                listed.help = _said(listed.dest, lang, listed.help)
            for name, sub in action.choices.items():
                speak(sub, lang, name)
        elif action.help is not argparse.SUPPRESS:
            key = f"{command} {action.dest}"
            action.help = _said(key if key in HELPS else f"* {action.dest}", lang, action.help)
            shown = action.metavar or (action.dest if not action.option_strings else action.dest.upper())
            if shown in METAVARS:
                action.metavar = _metavar(shown, lang)


def _said(key: str, lang: str, given: str | None) -> str | None:
    """The catalogue's text for ``key``; an option it lacks keeps the help it was given (the test of
    the catalogue, tests/test_help_lang.py, fails on it — a run never does)."""
    return help_text(key, lang) if key in HELPS else given


def _metavar(shown: str | None, lang: str) -> str | None:
    if shown is None or shown not in METAVARS:
        return shown
    uk, en = METAVARS[shown]
    return uk if lang == "uk" else en
