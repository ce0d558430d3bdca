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

from graphplan.util.errors import GraphplanError
from graphplan.util.files import read_bytes

MAX_TABLE_BYTES = 8 * 1024 * 1024     # ~300 000 rows
MAX_VALUE = 1e12                      # no answer of a lab is larger (SI units)
MAX_ROWS = 100_000                    # a group's tables are a few thousand rows

# spaces a person (or Excel) puts between thousands: space, no-break, narrow no-break, thin
_GROUPING = "\u0020\u00a0\u202f\u2009"
_MINUSES = "\u2212\u2012\u2013\ufe63\uff0d"       # minus sign, figure dash, en dash, small/full-width
_PLAIN = re.compile(r"^[+-]?(\d+(\.\d*)?|\.\d+)([eE][+-]?\d+)?$")
_GROUPED = re.compile(r"^[+-]?\d{1,3}([ ]\d{3})+([.,]\d*)?$")
_THOUSANDS_COMMA = re.compile(r"^[+-]?\d{1,3}(,\d{3})+$")
_THOUSANDS_DOT = re.compile(r"^[+-]?[1-9]\d{0,2}(\.\d{3})+$")      # 5.351: a decimal point or thousands?
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
        raise GraphplanError(f"cannot read the table as {encoding} text (byte {exc.start}); "
                             "save it as CSV UTF-8", where) from None


def read_rows(path: str | Path, what: str = "student table") -> tuple[list[tuple[int, list[str]]], str]:
    """The table's non-empty, non-comment lines as (line number, cells), and the separator.

    The separator is the header's: ``;``, else a tab, else ``,``. Quotes must close; every row has
    at most as many cells as the header."""
    data = read_bytes(path, what, MAX_TABLE_BYTES)
    where = str(path)
    text = decode(data, where)
    if "\x00" in text:
        raise GraphplanError(f"the {what} is not text (it holds zero bytes)", where)
    # lines end as a file's lines do (\n, \r\n, \r): str.splitlines would also break at U+2028, a
    # form feed or U+0085 and number the lines past the file's end; those stay in their cells
    numbered = [(n + 1, line) for n, line in enumerate(_LINES.split(text))
                if line.strip() and not line.lstrip().startswith("#")]
    if not numbered:
        raise GraphplanError(f"the {what} is empty", where)
    if len(numbered) > MAX_ROWS + 1:
        raise GraphplanError(f"the {what} has {len(numbered) - 1} rows; at most {MAX_ROWS} are graded "
                             "at once (split the table)", where)
    header = numbered[0][1]
    delimiter = ";" if ";" in header else "\t" if "\t" in header else ","
    rows = []
    for line_no, line in numbered:
        try:
            cells = next(csv.reader([line], delimiter=delimiter, strict=True))
        except csv.Error:
            raise GraphplanError(f"line {line_no}: a quote is not closed", where) from None
        rows.append((line_no, cells))
    width = len(rows[0][1])
    for line_no, cells in rows[1:]:
        if len(cells) > width:
            hint = (" — a decimal comma in a comma-separated table? Separate with ';' or write 7.2"
                    if delimiter == "," else "")
            raise GraphplanError(f"line {line_no}: {len(cells)} cells for {width} columns{hint}", where)
    return rows, delimiter


def number(text: str, delimiter: str) -> float:
    """A number as a person writes it: "−52.7", "5 346,1", "7,2" (where the comma is not the
    separator, or the cell was quoted), "1e-3". ValueError with the reason otherwise."""
    s = text.strip()
    for m in _MINUSES:
        s = s.replace(m, "-")
    if "_" in s:
        raise ValueError("write numbers without '_' (7_2 is not 72)")
    if any(c in s for c in _GROUPING):
        s = re.sub(f"[{_GROUPING}]", " ", s)
        if not _GROUPED.match(s):
            raise ValueError("spaces only between groups of three digits (5 346,1)")
        s = s.replace(" ", "")
    if "," in s:
        if "." in s:
            raise ValueError("both a decimal point and a comma: write 5346.1 or 5346,1")
        if delimiter == "," and _THOUSANDS_COMMA.match(s):
            raise ValueError("is the comma a decimal comma or between thousands? write 1.234 or 1234")
        if s.count(",") > 1:
            raise ValueError("more than one decimal comma")
        s = s.replace(",", ".")
    elif delimiter == ";" and _THOUSANDS_DOT.match(s):
        raise ValueError("is the dot a decimal point or between thousands? in a ';' table write 5,351 or 5351")
    if not _PLAIN.match(s):
        raise ValueError("not a number")
    value = float(s)
    if not abs(value) <= MAX_VALUE:
        raise ValueError(f"|value| ≤ {MAX_VALUE:g}")
    if value == 0.0 and re.search(r"[1-9]", s.split("e")[0].split("E")[0]):
        raise ValueError("too small: it underflows to 0")
    return value


def split_comma(cells: list[str], k: int, delimiter: str) -> bool:
    """Whether the value in cell ``k`` looks like a decimal comma split across cells: a comma-separated
    table, an integer there and a cell of digits only right after it ("11,09" → "11" | "09")."""
    return (delimiter == "," and k + 1 < len(cells) and bool(_INTEGER.match(cells[k].strip()))
            and bool(_DIGITS.match(cells[k + 1].strip())))
