"""Students' tables as they really come: the text's encoding, the separator and numbers as a
person writes them.

A Ukrainian Excel saves CSV in cp1251 or UTF-16 (with a BOM), separates with ``;`` and writes the
decimal comma, the Unicode minus "−52.7" and thousands with a (no-break) space "5 346,1". All of
that is read. What cannot be read unambiguously is refused with one line, never misread: a decimal
comma in a comma-separated table splits the value into two cells ("7,2" → "7" and "2"), so a row
with more cells than the header is refused; "1,234" in a comma-separated table could be 1.234 or
1234 and is refused; "7_2" is not 72.
"""
from __future__ import annotations

import codecs
import csv
import re
from pathlib import Path

from graphplan.util.errors import GraphplanError, said_error
from graphplan.util.files import read_bytes, what_said
from graphplan.util.words import word

MAX_TABLE_BYTES = 8 * 1024 * 1024     # ~300 000 rows
MAX_ROWS = 100_000                    # a group's tables are a few thousand rows

_INTEGER = re.compile(r"^[+-]?\d+$")
_DIGITS = re.compile(r"^\d+$")
_LINES = re.compile(r"\r\n|\r|\n")


def decode(data: bytes, where: str) -> str:
    """Bytes → text: a BOM decides (UTF-8, UTF-16 LE/BE); without one UTF-16 is recognised by its
    zero bytes, then UTF-8 is tried, then cp1251 (what a Ukrainian Windows writes)."""
    if data.startswith(codecs.BOM_UTF8):
        return _decode(data[3:], "utf-8", where)
    if data.startswith((codecs.BOM_UTF16_LE, codecs.BOM_UTF16_BE)):
        return _decode(data, "utf-16", where)
    if len(data) >= 4 and data.count(0) >= len(data) // 4:
        return _decode(data, "utf-16-le" if data[1] == 0 else "utf-16-be", where)
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError:
        return _decode(data, "cp1251", where)


def _decode(data: bytes, encoding: str, where: str) -> str:
    try:
        return data.decode(encoding)
    except UnicodeDecodeError as exc:
        raise said_error(GraphplanError, "st encoding", where, None, encoding=encoding, byte=exc.start) from None


def read_rows(path: str | Path, what: str = "student table") -> tuple[Records, str]:
    """The table's non-empty, non-comment lines as (line number, cells), and the separator.

    The separator is the header's: ``;``, else a tab, else ``,``. Quotes must close; every row has
    at most as many cells as the header (the first unclosed quote is named, else the first row too
    wide). The rows are checked here and split into cells again as they are read (``Records``)."""
    data = read_bytes(path, what, MAX_TABLE_BYTES)
    where = str(path)
    text = decode(data, where)
    if "\x00" in text:
        raise said_error(GraphplanError, "st zero bytes", where, None, what=what_said(what))
    # lines end as a file's lines do (\n, \r\n, \r): str.splitlines would also break at U+2028, a
    # form feed or U+0085 and number the lines past the file's end; those stay in their cells
    lines = _LINES.split(text)
    del data, text
    kept = [n for n, line in enumerate(lines) if line.strip() and not line.lstrip().startswith("#")]
    if not kept:
        raise said_error(GraphplanError, "st empty", where, None, what=what_said(what))
    if len(kept) > MAX_ROWS + 1:
        raise said_error(GraphplanError, "st too many rows", where, None, what=what_said(what), n=len(kept) - 1,
                         most=MAX_ROWS)
    header = lines[kept[0]]
    delimiter = ";" if ";" in header else "\t" if "\t" in header else ","
    records = Records(lines, kept, delimiter)
    width, wide = None, None
    for k in range(len(kept)):
        try:
            count = len(records[k][1])
        except csv.Error:
            raise said_error(GraphplanError, "st quote", where, None, line=kept[k] + 1) from None
        if width is None:
            width = count
        elif count > width and wide is None:
            wide = (kept[k] + 1, count)
    if wide is not None:
        hint = (lambda lang: word("st comma hint", lang)) if delimiter == "," else ""
        raise said_error(GraphplanError, "vt cells", where, None, line=wide[0], n=wide[1], width=width, hint=hint)
    return records, delimiter


class Records:
    """A table's kept lines as (line number, cells), split into cells when read: 100 000 rows held
    as their lines (~10 MB), not as lists of cells besides (~40 MB)."""

    def __init__(self, lines: list[str], kept: list[int], delimiter: str) -> None:
        self._lines, self._kept, self.delimiter = lines, kept, delimiter

    def __len__(self) -> int:
        return len(self._kept)

    def __getitem__(self, k: int) -> tuple[int, list[str]]:
        n = self._kept[k]
        return n + 1, next(csv.reader([self._lines[n]], delimiter=self.delimiter, strict=True))

    def __iter__(self):
        return (self[k] for k in range(len(self._kept)))


def number(text: str, delimiter: str) -> float:
    """A number as a person writes it — model.bounds.read_number, the one reader of every table's
    numbers (variants tables too) — as a float. ValueError with the reason otherwise."""
    from graphplan.model.bounds import read_number
    return float(read_number(text, delimiter))


def split_comma(cells: list[str], k: int, delimiter: str) -> bool:
    """Whether the value in cell ``k`` looks like a decimal comma split across cells: a comma-separated
    table, an integer there and a cell of digits only right after it ("11,09" → "11" | "09")."""
    return (delimiter == "," and k + 1 < len(cells) and bool(_INTEGER.match(cells[k].strip()))
            and bool(_DIGITS.match(cells[k + 1].strip())))
