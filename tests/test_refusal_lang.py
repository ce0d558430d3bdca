"""A bad scene is refused in one language: the scene's ``lang`` (Ukrainian when it has none) unless
--lang says otherwise — the frame, the crank, the cam, the gears and the range checks as much as the
assembly (docs/language.md). Each refusal is one line, exit 2, naming the file and the key; and every
catalogue word a refusal is raised with exists in both languages."""
from __future__ import annotations

import ast
import re
from pathlib import Path

import pytest

from conftest import ROOT
from graphplan.util.words import WORDS

CYRILLIC = re.compile(r"[А-Яа-яІіЇїЄєҐґ]")
LETTERS = re.compile(r"[A-Za-zА-Яа-яІіЇїЄєҐґ]")
EXAMPLES = ROOT / "examples"

# name → (example, old text, new text, command, the key the line names)
BAD = {
    "crank both speeds": ("crank_slider.toml", "omega = 293.07", "omega = 293.07\nrpm = 2800", "analyze", "crank"),
    "unknown guide": ("crank_slider.toml", 'slides_on = "x"', 'slides_on = "nowhere"', "analyze",
                      "slides_on"),
    "length out of range": ("crank_slider.toml", "omega = 293.07", "omega = 1e300", "analyze", "crank.omega"),
    "cam phases": ("cam_translating.toml", "dwell_near = 90", "dwell_near = 80", "cam", "cam.phases_deg"),
    "gear shift": ("gears.toml", "shifts = [0.5, 0.3]", 'shifts = [0.5, "x"]', "gears", "gears.shifts[1]"),
}
NO_FRAME = 'title = "x"\n[crank]\npivot = "O"\n'


def refusal(capsys, tmp_path: Path, text: str, command: str, *extra: str) -> str:
    """The one line a command prints for ``text``: exit 2, nothing on stdout, no traceback."""
    from graphplan.cli.main import main
    path = tmp_path / "bad.toml"
    path.write_text(text, encoding="utf-8")
    code = main([command, str(path), *extra])
    out, err = capsys.readouterr()
    lines = err.strip().splitlines()
    assert code == 2 and out == "" and len(lines) == 1 and "Traceback" not in err, err
    assert str(path) in lines[0], lines[0]
    return lines[0]


def cyrillic_share(line: str, key: str) -> float:
    """The share of Cyrillic among the letters after the key (the file and the key are as written)."""
    text = line.split(key, 1)[1]
    letters = LETTERS.findall(text)
    return len(CYRILLIC.findall(text)) / max(len(letters), 1)


def scene_text(case: str) -> str:
    if case == "no frame":
        return NO_FRAME
    example, old, new, _, _ = BAD[case]
    text = (EXAMPLES / example).read_text(encoding="utf-8")
    assert old in text
    return text.replace(old, new, 1)


@pytest.mark.parametrize("case", sorted(BAD) + ["no frame"])
def test_a_refusal_speaks_the_scene_s_language(capsys, tmp_path, case):
    command, key = (BAD[case][3], BAD[case][4]) if case in BAD else ("analyze", "frame")
    text = scene_text(case)
    uk = refusal(capsys, tmp_path, text, command)                       # no lang: Ukrainian
    assert key in uk and cyrillic_share(uk, key) > 0.6, uk
    en = refusal(capsys, tmp_path, text, command, "--lang", "en")
    assert key in en and not CYRILLIC.search(en.split(key, 1)[1]), en
    if not text.startswith("title = \"x\""):
        scene_en = refusal(capsys, tmp_path, 'lang = "en"\n' + text, command)   # the scene's own lang
        assert scene_en == en
        back = refusal(capsys, tmp_path, 'lang = "en"\n' + text, command, "--lang", "uk")   # --lang wins
        assert back == uk


# -- every word a refusal is raised with is in the catalogue, in both languages ----------------------------

RAISERS = {"keyed_error": 3, "said_error": 1, "fail": 1, "_refusal": 2, "option_error": 1}    # the word's argument


def refusal_words() -> set[str]:
    """The catalogue keys given (as literals) to the raisers in the package's sources."""
    found: set[str] = set()
    for path in (ROOT / "graphplan").rglob("*.py"):
        source = path.read_text(encoding="utf-8")
        if not any(f"{name}(" in source for name in RAISERS):
            continue
        for node in ast.walk(ast.parse(source)):
            if not isinstance(node, ast.Call):
                continue
            name = node.func.attr if isinstance(node.func, ast.Attribute) else getattr(node.func, "id", "")
            k = RAISERS.get(name)
            if k is None or len(node.args) <= k:
                continue
            arg = node.args[k]
            options = [arg.body, arg.orelse] if isinstance(arg, ast.IfExp) else [arg]
            found.update(o.value for o in options if isinstance(o, ast.Constant) and isinstance(o.value, str))
    return found


def test_every_refusal_word_is_in_both_languages():
    words = refusal_words()
    assert len(words) > 100, len(words)              # the scene, cam, gear loaders' refusals are found
    missing = sorted(w for w in words if w not in WORDS)
    assert not missing, missing
    for w in words:
        uk, en = WORDS[w]
        assert uk.strip() and en.strip() and CYRILLIC.search(uk) and not CYRILLIC.search(en), w
