"""Ten scenes a student gets wrong, each told in one line (exit 2, no traceback) in both languages,
naming the file, the key and what is wrong (the crank angles where a group will not assemble); the
lengths in millimetres are read but warned of (a mechanism may be large)."""
from __future__ import annotations

import re

import pytest

from conftest import ROOT
from graphplan.cli.main import main

CYRILLIC = re.compile(r"[А-Яа-яІіЇїЄєҐґ]")
LEVER = (ROOT / "examples" / "crank_slider.toml").read_text(encoding="utf-8")


def _line(text: str, what: str) -> int:
    """The 1-based line of ``text`` holding ``what`` (where TOML's parser stops on a bare word)."""
    return text[:text.index(what)].count("\n") + 1

CAM = (ROOT / "examples" / "cam_translating.toml").read_text(encoding="utf-8")
FORCE = '\n[[force]]\npoint = "Z"\nmagnitude = 1000\nstroke = "working"\ndirection = "oppose"\n'
SECOND_CRANK = '[crank]\npivot = "O"\npin = "C"\nlength = 0.1\nomega = 10\n\n[[link]]\nname = "AB"'

# name → (scene, old, new, command, the key or table named, [Ukrainian words], [English words])
CASES = {
    "typo in a key": (LEVER, 'length = "l"', 'lenght = "l"', "analyze", "link[0].lenght",
                      ["невідомий ключ", "length"], ["unknown key", "length"]),
    "no crank": (LEVER, LEVER[LEVER.index("[crank]"):LEVER.index("[[link]]")], "", "analyze", "crank",
                 ["відсутній", "кривошип"], ["missing", "crank"]),
    "cannot assemble": (LEVER, "l = 0.307 ", "l = 0.03 ", "analyze", "II(2-3)",
                        ["не складається", "кутів кривошипа", "°"], ["cannot be assembled", "crank angles", "°"]),
    "phases not 360": (CAM, "dwell_near = 90", "dwell_near = 80", "cam", "cam.phases_deg", ["360°", "350°"],
                       ["360°", "350°"]),
    "negative length": (LEVER, "l = 0.307 ", "l = -0.307 ", "analyze", "link AB.length", ["додатним", "-0,307"],
                        ["positive", "-0.307"]),
    "guide angle as text": (LEVER, "angle_deg = 0 }", 'angle_deg = "horizontal" }', "analyze",
                            "frame.guides.x.angle_deg", ["не число", "'horizontal'"], ["not a number", "'horizontal'"]),
    "angle without quotes": (LEVER, "angle_deg = 0 }", "angle_deg = horizontal }", "analyze", "TOML",
                             [f"рядок {_line(LEVER, 'angle_deg = 0 }')}", "лапках"],
                             [f"line {_line(LEVER, 'angle_deg = 0 }')}", "quotes"]),
    "two cranks": (LEVER, '[[link]]\nname = "AB"', SECOND_CRANK, "analyze", "[crank]", ["двічі", "рядок"],
                   ["twice", "line"]),
    "force on an unknown point": (LEVER, "accel = [1]", "accel = [1]" + FORCE, "analyze", "force.point",
                                  ["'Z'"], ["'Z'"]),
    "rpm and omega": (LEVER, "omega = 293.07 ", "omega = 293.07\nrpm = 2800 ", "analyze", "crank",
                      ["omega", "rpm", "одним"], ["omega", "rpm", "one of"]),
}


def refusal(capsys, tmp_path, text: str, command: str, lang: str) -> str:
    path = tmp_path / "bad.toml"
    path.write_text(text, encoding="utf-8")
    code = main([command, str(path), "--lang", lang])
    out, err = capsys.readouterr()
    lines = err.strip().splitlines()
    assert code == 2 and out == "" and len(lines) == 1 and "Traceback" not in err, (code, err)
    assert str(path) in lines[0], lines[0]
    return lines[0].split(str(path), 1)[1]


@pytest.mark.parametrize("case", sorted(CASES))
def test_a_student_s_bad_scene_is_one_clear_line(case, tmp_path, capsys):
    scene, old, new, command, key, uk_words, en_words = CASES[case]
    assert old in scene
    text = scene.replace(old, new, 1)
    for lang, words in (("uk", uk_words), ("en", en_words)):
        line = refusal(capsys, tmp_path, text, command, lang)
        assert key in line and all(w in line for w in words), (lang, line)
        rest = line.split(key, 1)[1]
        for w in ("omega", "rpm", "length", "'horizontal'", "'Z'", "TOML"):
            rest = rest.replace(w, "")
        assert bool(CYRILLIC.search(rest)) == (lang == "uk"), (lang, line)


def test_lengths_in_millimetres_are_warned(tmp_path, capsys):
    path = tmp_path / "mm.toml"
    path.write_text(LEVER.replace("l = 0.307 ", "l = 307 ", 1), encoding="utf-8")
    for lang, words in (("uk", ["попередження", "AB", "307 м", "0,064 м", "міліметрах"]),
                        ("en", ["warning", "AB", "307 m", "0.064 m", "millimetres"])):
        code = main(["analyze", str(path), "--json", "--lang", lang])
        err = capsys.readouterr().err.strip().splitlines()
        assert code == 0 and len(err) == 1 and all(w in err[0] for w in words), err


@pytest.mark.parametrize("command, scene, uk, en", [
    ("gears", CAM, "кулачкового", "cam scene"),         # not "a lever mechanism" (the blind review, stop 53)
    ("gears", LEVER, "важільний", "lever"),
    ("cam", LEVER, "важільний", "lever"),
])
def test_the_wrong_command_names_the_scene_s_kind(command, scene, uk, en, tmp_path, capsys):
    """A scene given to the command of another kind says what the scene is, in both languages."""
    assert uk in refusal(capsys, tmp_path, scene, command, "uk")
    assert en in refusal(capsys, tmp_path, scene, command, "en")
