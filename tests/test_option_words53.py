"""The command line's own refusals (files, options, argparse's usage errors) in both languages: one
line, exit 2, no traceback; Ukrainian unless --lang (or the scene's ``lang``) says English. Table-driven,
in-process (cli.main.main), none of them reaches a drawing."""
from __future__ import annotations

import re
from pathlib import Path

import pytest

from conftest import ROOT
from graphplan.cli.main import main

CYRILLIC = re.compile(r"[А-Яа-яІіЇїЄєҐґ]")
EXAMPLE = str(ROOT / "examples" / "crank_slider.toml")
CAM = str(ROOT / "examples" / "cam_translating.toml")


def files(tmp: Path) -> dict[str, str]:
    """The bad files a case names: a folder, a Latin-1 scene, a file where a folder should be."""
    (tmp / "folder").mkdir(exist_ok=True)
    (tmp / "latin1.toml").write_bytes('title = "Кривошип"\n'.encode("cp1251"))
    (tmp / "plain").write_text("x", encoding="utf-8")
    return {"FOLDER": str(tmp / "folder"), "LATIN1": str(tmp / "latin1.toml"), "NOPE": str(tmp / "nope.toml"),
            "UNDER_FILE": str(tmp / "plain" / "x.svg"), "OUT": str(tmp / "x.svg"), "EX": EXAMPLE, "CAM": CAM}


# name → (argv, Ukrainian words, English words)
CASES = {
    "missing scene": (["sheet", "NOPE", "-o", "OUT"], ["NOPE", "не знайдено файлу сцени"], ["NOPE", "no such scene file"]),
    "scene a folder": (["analyze", "FOLDER"], ["FOLDER", "це тека"], ["FOLDER", "is a folder"]),
    "not UTF-8": (["analyze", "LATIN1"], ["LATIN1", "не є текстом UTF-8"], ["LATIN1", "not UTF-8 text"]),
    "output format": (["sheet", "EX", "-o", "x.xyz"], ["-o x.xyz", "невідомий формат", ".svg"],
                      ["-o x.xyz", "unknown format", ".svg"]),
    "output under a file": (["sheet", "EX", "-o", "UNDER_FILE"], ["UNDER_FILE", "не тека"], ["UNDER_FILE", "not a folder"]),
    "sheet kind": (["sheet", "EX", "-o", "OUT", "--sheet", "foo"], ["--sheet", "недопустиме значення 'foo'", "див. --help"],
                   ["--sheet", "invalid choice: 'foo'", "see --help"]),
    "sheet format": (["sheet", "EX", "-o", "OUT", "--format", "A7"], ["--format", "невідомий формат аркуша 'A7'"],
                     ["--format", "unknown sheet format 'A7'"]),
    "cam scene's sheet": (["sheet", "CAM", "-o", "OUT", "--sheet", "forces"], ["--sheet forces", "лише аркуш cam"],
                          ["--sheet forces", "cam sheet only"]),
    "positions range": (["analyze", "EX", "--positions", "1"], ["--positions", "має бути від 2 до 36000, задано 1"],
                        ["--positions", "must be from 2 to 36000, got 1"]),
    "positions not a number": (["analyze", "EX", "--positions", "x"], ["--positions", "'x' — не ціле число"],
                               ["--positions", "invalid int value: 'x'"]),
    "precision range": (["forces", "EX", "--precision", "99"], ["--precision", "від 0 до 10 мм"],
                        ["--precision", "from 0 to 10 mm"]),
    "phi not finite": (["forces", "EX", "--phi", "nan"], ["--phi", "задано nan"], ["--phi", "got nan"]),
    "divisions": (["diagrams", "EX", "--divisions", "x"], ["--divisions", "ціле число або перелік"],
                  ["--divisions", "a whole number or comma-separated"]),
    "delta": (["dynamics", "EX", "--delta", "0.7"], ["--delta", "(0; 0,5)"], ["--delta", "(0, 0.5)"]),
    "required": (["sheet", "EX"], ["бракує аргументів: -o/--output"], ["arguments are required: -o/--output"]),
    "unrecognized": (["analyze", "EX", "--bogus"], ["невідомі аргументи: --bogus"], ["unrecognized arguments: --bogus"]),
    "expected one": (["analyze", "EX", "--positions"], ["--positions: потрібне одне значення"],
                     ["--positions: expected one argument"]),
    "unknown command": (["shet"], ["недопустиме значення 'shet'"], ["invalid choice: 'shet'"]),
}


def refused(argv: list[str], capsys) -> str:
    code = main(argv)
    out, err = capsys.readouterr()
    lines = err.strip().splitlines()
    assert code == 2 and len(lines) == 1 and "Traceback" not in err, (argv, err)
    return lines[0]


@pytest.mark.parametrize("case", sorted(CASES))
def test_each_option_refusal_in_both_languages(case, tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    names = files(tmp_path)
    argv, uk_words, en_words = CASES[case]
    argv = [names.get(a, a) for a in argv]
    for lang, words in (("uk", uk_words), ("en", en_words)):
        line = refused([*argv, "--lang", lang], capsys)
        for w in words:
            assert names.get(w, w) in line, (lang, w, line)
        told = line.split("graphplan: ", 1)[1]
        for path in names.values():          # the files as written
            told = told.replace(path, "")
        assert bool(CYRILLIC.search(told)) == (lang == "uk"), (lang, line)
    if case not in ("unknown command",):
        assert refused(argv, capsys) == refused([*argv, "--lang", "uk"], capsys)     # Ukrainian by default


def test_the_scene_s_lang_speaks_an_option_refusal(tmp_path, capsys):
    """No --lang: a scene with lang = "en" hears its option refusals (and argparse's) in English."""
    scene = tmp_path / "en.toml"
    scene.write_text('lang = "en"\n' + Path(EXAMPLE).read_text(encoding="utf-8"), encoding="utf-8")
    assert "must be from 2 to 36000" in refused(["analyze", str(scene), "--positions", "1"], capsys)
    assert "invalid int value" in refused(["analyze", str(scene), "--positions", "x"], capsys)
    assert "задано 1" in refused(["analyze", str(scene), "--positions", "1", "--lang", "uk"], capsys)


def test_a_bad_lang_is_refused_in_ukrainian(capsys):
    line = refused(["analyze", EXAMPLE, "--lang", "de"], capsys)
    assert "--lang" in line and "недопустиме значення 'de'" in line
