"""Stop 55 (misc55): a scene's TOML syntax error said in the scene's language — the web page showed
"синтаксична помилка TOML: Expected ']' at the end of a table declaration (at line 2, column 7)",
tomllib's English inside a Ukrainian line. Each broken scene below makes one of tomllib's messages."""
from __future__ import annotations

import re

import pytest

from graphplan.model.bounds import parse_toml
from graphplan.util.errors import GraphplanError

BROKEN = {
    "table": ('title = "x"\n[crank\nlength = 0.1\n', 2),
    "array of tables": ('[[link\nname = "AB"\n', 1),
    "after a value": ("a = 1 b = 2\n", 1),
    "array": ("a = [1, 2\nb = 3\n", 2),
    "inline table": ("a = {b = 1\n", 1),
    "string": ('title = "x\n', 1),
    "key": ("= 3\n", 1),
    "statement": ("a = 1\n]\n", 2),
}


@pytest.mark.parametrize("case", sorted(BROKEN))
def test_a_toml_syntax_error_speaks_one_language_and_names_its_line(case):
    text, line = BROKEN[case]
    with pytest.raises(GraphplanError) as got:
        parse_toml(text, "scene.toml")
    uk, en = got.value.line("uk"), got.value.line("en")
    assert f"рядок {line}" in uk and f"line {line}" in en, (uk, en)
    latin = re.sub(r"scene\.toml|TOML|'\\n'", "", uk)
    assert not re.search(r"[A-Za-z]{3,}", latin), uk
    assert not re.search("[А-Яа-яІіЇїЄє]", en), en
