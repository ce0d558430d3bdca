"""Every command's --help in the reader's language (stop 54): Ukrainian by default, English with
--lang en (before or after the command) or a scene whose lang is "en"; the texts from the catalogue
(util.helpwords), argparse's own words included. The scans reuse test_words' (a Ukrainian text keeps
Latin only as the program's names: options, the values they take, formats, files; an English one no
Cyrillic); the options are the public contract's, copied below as the contract writes them."""
from __future__ import annotations

import argparse
import re

import pytest

from conftest import ROOT
from test_words import CYRILLIC, latin_words
from graphplan.cli.main import build_parser, main
from graphplan.util.helpwords import HELPS, METAVARS

# the contract's command lines (CONTRACT.md, "Command line"): every option there is in the help
CONTRACT = """
graphplan analyze SCENE [--positions N] [--phi DEG ...] [--json]
graphplan plans SCENE [--positions N] [--accel AT ...] [--precision MM] [--json] [--svg DIR]
graphplan diagrams SCENE [--point P] [--divisions N] [--h1 MM] [--h2 MM] [--precision MM] [--json] [--svg FILE]
graphplan sheet [SCENE] -o FILE [--format A1/A3] [--lang uk/en]
graphplan bench [-o DIR] [--quick]
graphplan key VARIANTS -o DIR
graphplan check KEY STUDENT.csv [--json]
graphplan forces SCENE [--phi DEG] [--precision MM] [--json] [--svg DIR]
graphplan dynamics SCENE [--delta D] [--precision MM] [--json] [--svg DIR]
graphplan view SCENE -o FILE.html
graphplan diagrams ... --method chords/tangents
graphplan cam SCENE [--divisions N] [--precision MM] [--json] [--svg DIR]
graphplan sheet SCENE --sheet cam
graphplan gears SCENE [--precision MM] [--json] [--svg DIR]
graphplan serve [--host H] [--port P]
"""
COMMANDS = ["analyze", "sheet", "plans", "diagrams", "forces", "dynamics", "key", "check", "bench", "view",
            "cam", "serve", "gears"]


def contract_options() -> dict[str, set[str]]:
    """command → the options the contract names for it ("Every command takes --lang" included)."""
    found: dict[str, set[str]] = {c: {"--lang"} for c in COMMANDS}
    for line in CONTRACT.strip().splitlines():
        command = line.split()[1]
        found[command] |= set(re.findall(r"(?<![\w-])(-o|--[a-z][a-z0-9-]*)", line))
    return found


# the program's names a Ukrainian help writes as one types them: formats, the scene's tables and keys,
# the files a command writes, the student table's columns, the bench's sections, the libraries it times
NAMES = {"SVG", "PDF", "PNG", "DXF", "TOML", "JSON", "CSV", "HTML", "DPI", "auto", "none", "lang", "delta",
         "divisions", "planetary", "position", "quantity", "value", "variant", "moments", "energy",
         "inertia", "wittenbauer", "speed", "meshing", "sliding", "phase", "profile", "stability",
         "differentiation", "external", "flywheel", "processes", "numpy", "shapely", "svgwrite"}


def program_names(parser: argparse.ArgumentParser) -> set[str]:
    """The values the options take (choices) and the commands' names: a user types them as they are."""
    names = set(NAMES)
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            names |= set(action.choices)
            for sub in action.choices.values():
                names |= program_names(sub)
        elif action.choices:
            names |= {str(c) for c in action.choices}
    return names


def help_of(capsys, *argv: str) -> str:
    """``graphplan ARGV`` run in-process: its help (exit 0) as printed."""
    with pytest.raises(SystemExit) as done:
        main(list(argv))
    out, err = capsys.readouterr()
    assert done.value.code == 0 and not err, err
    return out


@pytest.fixture
def columns(monkeypatch):
    monkeypatch.setenv("COLUMNS", "100")


def bare(text: str) -> str:
    """``text`` without the program's paths and dotted names (docs/cams.md, ТЕКА/bench.json, key.json,
    positions.force_phi_deg, a_*=8): names, not words."""
    return re.sub(r"\S*[\w\]]/\S*|\w+(?:\.\w+)+|'[^']*'", " ", text)


@pytest.mark.parametrize("command", [None, *COMMANDS])
def test_ukrainian_help_has_no_english_and_the_english_no_cyrillic(capsys, columns, command):
    head = [command] if command else []
    names = program_names(build_parser("uk"))
    uk = help_of(capsys, *head, "--help")
    assert uk.startswith("використання: graphplan") and "параметри:" in uk
    assert ("\nкоманди:\n" in uk) == (command is None)
    for line in uk.splitlines():
        assert not latin_words(bare(line), names), f"{command}: English in {line!r}"
        assert not re.search(r"\w-$", line), f"{command}: a hyphenated word broken at {line!r}"
    assert uk == help_of(capsys, *head, "--lang", "uk", "--help")
    en = help_of(capsys, *head, "--lang", "en", "--help")
    assert en.startswith("usage: graphplan") and "options:" in en
    assert not CYRILLIC.search(en), f"{command}: Cyrillic in {en!r}"
    assert not re.search(r"\w-$", en, re.M), f"{command}: a hyphenated word broken"


@pytest.mark.parametrize("command", COMMANDS)
def test_every_contract_option_is_in_both_helps_within_100_columns(capsys, columns, command):
    for lang in ("uk", "en"):
        text = help_of(capsys, "--lang", lang, command, "--help")
        listed = set(re.findall(r"(?<![\w-])(-o|--[a-z][a-z0-9-]*)", text))
        assert contract_options()[command] <= listed, (lang, contract_options()[command] - listed)
        assert max(len(line) for line in text.splitlines()) <= 100


def test_a_wide_terminal_still_gets_100_columns(capsys, monkeypatch):
    monkeypatch.setenv("COLUMNS", "250")
    text = help_of(capsys, "diagrams", "--help")
    assert 90 < max(len(line) for line in text.splitlines()) <= 100


def test_the_help_speaks_as_the_messages_do(capsys, columns, tmp_path, monkeypatch):
    """--lang before or after the command, else the named scene's lang, else Ukrainian — the
    environment's LANG is not read (docs/language.md)."""
    monkeypatch.setenv("LANG", "en_US.UTF-8")
    monkeypatch.setenv("LC_ALL", "en_US.UTF-8")
    assert help_of(capsys, "sheet", "--help").startswith("використання:")
    assert help_of(capsys, "--lang", "en", "sheet", "--help").startswith("usage:")
    assert help_of(capsys, "sheet", "--lang=en", "--help").startswith("usage:")
    scene = tmp_path / "four_bar_en.toml"
    scene.write_text('lang = "en"\n' + (ROOT / "examples" / "four_bar.toml").read_text(encoding="utf-8"),
                     encoding="utf-8")
    assert help_of(capsys, "plans", str(scene), "--help").startswith("usage:")
    assert help_of(capsys, "plans", str(scene), "--lang", "uk", "--help").startswith("використання:")


def test_lang_before_the_command_speaks_for_the_run(capsys):
    code = main(["--lang", "en", "analyze", str(ROOT / "examples" / "four_bar.toml"), "--positions", "2"])
    out, _ = capsys.readouterr()
    assert code == 0 and out and not CYRILLIC.search(out)
    code = main(["--lang", "en", "analyze", "--positions", "x"])
    _, err = capsys.readouterr()
    assert code == 2 and "invalid int value" in err and err.count("\n") == 1


def test_every_text_of_every_parser_is_in_the_catalogue():
    """No option, command or description keeps a text outside the catalogue; both languages, the
    same %-fields (argparse fills %%)."""
    used: set[str] = set()

    def walk(parser: argparse.ArgumentParser, command: str) -> None:
        if command != "graphplan" or parser.description:
            assert f"{command} desc" in HELPS, command
            used.add(f"{command} desc")
        for action in parser._actions:
            if isinstance(action, (argparse._HelpAction, argparse._VersionAction)):
                continue
            if isinstance(action, argparse._SubParsersAction):
                for name, sub in action.choices.items():
                    assert name in HELPS, name
                    used.add(name)
                    walk(sub, name)
                continue
            key = f"{command} {action.dest}" if f"{command} {action.dest}" in HELPS else f"* {action.dest}"
            assert key in HELPS, key
            used.add(key)
    walk(build_parser("en"), "graphplan")
    assert set(HELPS) - used - {k for k in HELPS if k.startswith("@")} == set()      # nothing stale
    for key, (uk, en) in HELPS.items():
        assert uk.strip() and en.strip() and re.findall(r"%.", uk) == re.findall(r"%.", en), key
    for uk, en in METAVARS.values():
        assert not re.search(r"[A-Za-z]{2,}", uk.replace(".html", "")) and not CYRILLIC.search(en)
