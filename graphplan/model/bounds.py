"""What a scene may ask for: the physical and practical bounds of every number, name and text.

A scene describes a lever mechanism a student draws and a machine runs: links from 10 µm to 1 km,
crank speeds a machine reaches, masses and forces a machine carries. Anything outside is a typo
(``1e16`` for ``1.6``) or a fuzzer, and refusing it where the scene is read — one line naming the
key and the allowed range — keeps every later computation finite. The same module bounds the
reading itself: the file's size, the TOML's nesting, an expression's length and depth, integers'
size, and the text that ends up in a drawing (no control characters: an SVG must stay XML).
"""
from __future__ import annotations

import math
import re
import tomllib
import unicodedata
from dataclasses import dataclass
from typing import Any

from graphplan.util.errors import SaidValueError, SceneError, keyed_error, reason

MAX_SCENE_BYTES = 1024 * 1024        # the largest example is 3 kB
MAX_TOML_DEPTH = 12                  # tables in tables in arrays … (a scene needs 4)
MAX_INT = 10 ** 15                   # integers beyond this are typos, and float() of 400 digits overflows
MAX_EXPRESSION = 200                 # characters of one expression such as "0.7 * rocker"
MAX_EXPRESSION_DEPTH = 24            # nested operations and calls in one expression
MAX_NAME = 40                        # characters of a point's, link's or guide's name
MAX_TEXT = 200                       # characters of a title or a title-block field


@dataclass(frozen=True)
class Range:
    """A closed (or, at ``lo``, open) interval of a physical quantity, with its unit for the message."""
    lo: float
    hi: float
    unit: str
    lo_open: bool = False
    floor: float = 0.0      # a physical floor: 0 < value < floor is refused (5e-324 kg is no mass)

    def holds(self, value: float) -> bool:
        above = value > self.lo if self.lo_open else value >= self.lo
        return math.isfinite(value) and above and value <= self.hi and not 0.0 < abs(value) < self.floor

    def text(self, lang: str = "en") -> str:
        """The interval as a person reads it, in ``lang`` (the unit too; a decimal comma in Ukrainian)."""
        uk = lang == "uk"
        unit = f" {_unit(self.unit, lang)}" if self.unit else ""

        def g(v: float) -> str:
            return _plain(v, lang)
        if self.floor:
            zero = ("0 або " if uk else "0 or ") if not self.lo_open else ""
            return f"{zero}{'від' if uk else 'from'} {g(self.floor)} {'до' if uk else 'to'} {g(self.hi)}{unit}"
        if self.lo == -self.hi:
            return f"|{'значення' if uk else 'value'}| ≤ {g(self.hi)}{unit}"
        excl = (" (не включно)" if uk else " (exclusive)") if self.lo_open else ""
        low = g(self.lo)
        if self.unit == "m" and 0 < self.lo < 1e-3:      # 10 µm as a draftsman writes it: 0,01 мм
            low = f"{g(self.lo * 1e3)} {_unit('mm', lang)}"
        return f"{'від' if uk else 'from'} {low}{excl} {'до' if uk else 'to'} {g(self.hi)}{unit}"


def _unit(key: str, lang: str) -> str:
    """A range's unit in ``lang`` (kg/m is not among the sheets' units)."""
    from graphplan.util.words import UNITS
    uk, en = UNITS.get(key, ("кг/м", "kg/m") if key == "kg/m" else (key, key))
    return uk if lang == "uk" else en


LENGTH = Range(1e-5, 1e3, "m")                 # a link, a stroke, a centre distance
COORDINATE = Range(-1e3, 1e3, "m")             # a frame point, a guide's point, a link's local point
OMEGA = Range(1e-3, 1e5, "rad/s")              # 0.01 … 955 000 rpm
RPM = Range(0.01, 1e6, "rpm")
EPSILON = Range(-1e8, 1e8, "rad/s²")
MASS = Range(0.0, 1e6, "kg", floor=1e-6)                   # 0 (massless) or from 1 mg
INERTIA = Range(0.0, 1e6, "kg·m²", floor=1e-12)
MASS_PER_LENGTH = Range(0.0, 1e6, "kg/m", lo_open=True, floor=1e-6)
INERTIA_FACTOR = Range(0.0, 10.0, "", lo_open=True)   # I = k·m·l², a rod's k = 1/12
FORCE = Range(0.0, 1e9, "N", lo_open=True, floor=1e-6)
MOMENT = Range(0.0, 1e9, "N·m", lo_open=True, floor=1e-6)
GRAVITY = Range(0.0, 1e3, "m/s²")
ANGLE = Range(-1e6, 1e6, "deg")
TIME_RATIO = Range(1.0, 100.0, "", lo_open=True)      # K of the quick-return synthesis
PARAMETER = Range(-1e12, 1e12, "")
PROFILE_DISTANCE = Range(-1e6, 1e6, "")
PROFILE_FACTOR = Range(-1e3, 1e3, "")
ABSCISSA_MM = Range(10.0, 2000.0, "mm")              # the diagrams' L
POLE_MM = Range(1.0, 1000.0, "mm")                   # H1, H2
COUNT = (2, 3600)                                    # positions of a turn
DIVISIONS = (2, 720)                                 # the diagrams' intervals
DYNAMICS_DIVISIONS = (4, 360)                        # the flywheel construction's divisions: 1° each at
                                                     # most (L ≈ 250 mm: 0.7 mm a division, the ruler's 0.5 mm)


def check(value: float, bounds: Range, key: str, where: str) -> float:
    """``value`` when it lies within ``bounds``; else the one-line refusal naming the key and range."""
    if not bounds.holds(value):
        raise keyed_error(SceneError, where, key, "bad range", range=lambda lang: bounds.text(lang), got=_g(value))
    return value


def check_count(value: Any, bounds: tuple[int, int], key: str, where: str) -> int:
    """A whole number within ``bounds`` (booleans are not numbers)."""
    lo, hi = bounds
    if isinstance(value, bool) or not isinstance(value, int) or not lo <= value <= hi:
        raise keyed_error(SceneError, where, key, "bad count", lo=lo, hi=hi, got=short(repr(value)))
    return value


def to_float(value: int | float, key: str, where: str) -> float:
    """A TOML number as a float; integers beyond ±10¹⁵ are refused (they are typos, and 400 digits
    overflow a float)."""
    if isinstance(value, int) and abs(value) > MAX_INT:
        raise keyed_error(SceneError, where, key, "bad large integer", most=f"{MAX_INT:.0e}")
    return float(value)


def _g(value: float) -> object:
    """A value for a refusal: written "%g" in each language (a decimal comma in Ukrainian), never in
    e-notation (``_plain``)."""
    return lambda lang: _plain(value, lang)


def _plain(value: float, lang: str = "en") -> str:
    """A number for a person: "%g" where that has no exponent (0,04; 2800), else the float's
    shortest digits written out (0.00001 as the scene most likely wrote it, 1000000 for 1e6), and
    the lab's ·10ⁿ only where that would run past 12 digits (1·10⁻¹²). A decimal comma in Ukrainian."""
    text = f"{value:g}"
    if "e" in text and math.isfinite(value):
        from decimal import Decimal
        out = format(Decimal(repr(float(value))), "f")
        out = out.rstrip("0").rstrip(".") if "." in out else out
        if len(out.lstrip("-").replace(".", "")) <= 12:
            text = out
        else:                                    # from the decimal digits: 5e-324 has no 10⁻³²⁴ float
            from graphplan.util.words import SUPER
            sign, digits, exp = Decimal(repr(float(value))).normalize().as_tuple()
            figures = "".join(map(str, digits))
            mantissa = figures[0] + ("." + figures[1:] if len(figures) > 1 else "")
            power = str(len(figures) - 1 + exp).translate(SUPER)
            text = f"{'-' if sign else ''}{mantissa}·10{power}"
    return text.replace(".", ",") if lang == "uk" else text


def short(text: str, limit: int = 40) -> str:
    """A text cut for an error message (a message stays one short line)."""
    text = " ".join(str(text).split())
    return text if len(text) <= limit else text[: limit - 1] + "…"


def clean_text(value: Any) -> str:
    """A title or title-block field as drawable text: control and format characters become spaces
    (a U+0007 in an SVG makes it ill-formed XML), runs of spaces one, at most MAX_TEXT characters."""
    text = "".join(" " if unicodedata.category(c) in ("Cc", "Cf", "Cs", "Co", "Cn") else c
                   for c in str(value))
    return " ".join(text.split())[:MAX_TEXT]


def name_problem(name: str) -> str | None:
    """Why a point's, link's or guide's name cannot be used (the catalogue's word), or None when it can."""
    if len(name) > MAX_NAME:
        return "bad name long"
    if any(unicodedata.category(c).startswith(("C", "Z")) for c in name):
        return "bad name spaces"
    return None


# tomllib's commonest complaints, said in the reader's language (the rest stay as tomllib words them)
_TOML_WHY = ((re.compile(r"^Cannot declare \((?P<t>[^)]*)\) twice \(at line (?P<line>\d+), column \d+\)$"), "bad toml twice"),
             (re.compile(r"^Cannot overwrite a value \(at line (?P<line>\d+), column \d+\)$"), "bad toml overwrite"),
             (re.compile(r"^Invalid value \(at line (?P<line>\d+), column \d+\)$"), "bad toml invalid"),
             (re.compile(r"^Expected '=' after a key in a key/value pair \(at line (?P<line>\d+), column \d+\)$"),
              "bad toml equals"),
             (re.compile(r"^.* \(at end of document\)$"), "bad toml end"),
             (re.compile(r"^(?P<what>.+) \(at line (?P<line>\d+), column (?P<col>\d+)\)$"), "bad toml at"))


def toml_why(message: str):
    """tomllib's message as the refusal says it: a table declared twice ("[crank] twice, line 31"), a
    key given twice, a value that is not TOML (text without quotes), a key without '=' — in either
    language; any other message as tomllib words it (shortened)."""
    from graphplan.util.words import word
    for pattern, key in _TOML_WHY:
        m = pattern.match(message)
        if m:
            fields = {k: v for k, v in m.groupdict().items()}
            if "t" in fields:
                fields["t"] = "[" + ".".join(x.strip().strip("'\"") for x in fields["t"].split(",") if x.strip()) + "]"
            if "what" in fields:          # tomllib's words, in Ukrainian where the catalogue has them
                from graphplan.util.words import TOML_SAID
                what = fields.pop("what")
                said = TOML_SAID.get(what) or (what.replace("Illegal character", "недопустимий символ", 1)
                                               if what.startswith("Illegal character") else short(what, 100))
                return lambda lang: word(key, lang, what=said if lang == "uk" else short(what, 100), **fields)
            return lambda lang: word(key, lang, **fields)
    return short(message, 120)


def parse_toml(text: str, where: str) -> dict[str, Any]:
    """The TOML tree of a scene, bounded: size, nesting depth, integers' size."""
    if len(text.encode("utf-8", "surrogatepass")) > MAX_SCENE_BYTES:
        raise keyed_error(SceneError, where, "", "bad scene size", kb=MAX_SCENE_BYTES // 1024)
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise keyed_error(SceneError, where, "", "bad toml syntax", toml="TOML", why=toml_why(str(exc))) from None
    except RecursionError:
        raise keyed_error(SceneError, where, "", "bad toml depth", toml="TOML", most=MAX_TOML_DEPTH) from None
    except ValueError as exc:          # e.g. an integer of more than 4300 digits
        raise keyed_error(SceneError, where, "", "bad toml value", toml="TOML", why=short(str(exc), 80)) from None
    check_tree(data, where)
    return data


def check_tree(data: Any, where: str) -> None:
    """Nesting at most MAX_TOML_DEPTH levels (checked without recursion)."""
    stack = [(data, 0)]
    while stack:
        node, depth = stack.pop()
        if depth > MAX_TOML_DEPTH:
            raise keyed_error(SceneError, where, "", "bad toml depth", toml="TOML", most=MAX_TOML_DEPTH)
        if isinstance(node, dict):
            stack.extend((v, depth + 1) for v in node.values())
        elif isinstance(node, list):
            stack.extend((v, depth + 1) for v in node)


# -- numbers in tables: one reader for variant tables (key) and students' tables (check) --------------

MAX_CELL_VALUE = 1e12                 # no number of a lab's table is larger (SI units)
_GROUPING = "\u0020\u00a0\u202f\u2009"   # spaces between thousands: space, no-break, narrow no-break, thin
_MINUSES = "\u2212\u2012\u2013\ufe63\uff0d"   # minus sign, figure dash, en dash, small/full-width
_PLAIN = re.compile(r"^[+-]?(\d+(\.\d*)?|\.\d+)([eE][+-]?\d+)?$")
_GROUPED = re.compile(r"^[+-]?\d{1,3}([ ]\d{3})+([.,]\d*)?$")
_THOUSANDS_COMMA = re.compile(r"^[+-]?[1-9]\d{0,2}(,\d{3})+$")   # 1,234: a decimal comma or thousands?
_THOUSANDS_DOT = re.compile(r"^[+-]?[1-9]\d{0,2}(\.\d{3})+$")   # 5.351: a decimal point or thousands?
_RADIX = re.compile(r"^[+-]?0[xXoObB]")
_WORDS = re.compile(r"^[+-]?(inf|infinity|nan)$", re.IGNORECASE)
_NUMERIC = re.compile(r"^[+-]?[.,]?\d[\w.,+-]*$")
_TOKEN = re.compile(r"(?<![\w.])\.?\d(?:[\w.]|(?<=[eE])[+-])*")
_QUOTED = re.compile(r"\"(?:[^\"\\]|\\.)*\"|'[^']*'")


def _normal(text: str) -> str:
    s = text.strip()
    for m in _MINUSES:
        s = s.replace(m, "-")
    return s


def numeric_like(text: str) -> bool:
    """Whether a table's cell is meant as a number (then ``read_number`` reads it or says why not):
    digits with signs, points, commas, exponents, letters (0x10, 2r), thousands spaces (5 346,1),
    inf and nan — not an expression (0.7 * rocker), a list or a word."""
    s = _normal(text)
    if _WORDS.match(s) or _NUMERIC.match(s):
        return True
    return any(c in s for c in _GROUPING) and bool(_GROUPED.match(re.sub(f"[{_GROUPING}]", " ", s)))


def read_number(text: str, delimiter: str) -> int | float:
    """A table's number as a person writes it — "−52.7", "5 346,1", "7,2" (where the comma is not
    the separator, or the cell was quoted), "1e-3" — by one rule for every table (variants, students'):
    an integer's text gives an int. ValueError with the reason for what cannot be read unambiguously:
    hexadecimal, octal and binary literals (0x10), '_' (7_2), inf and nan, "1,234" in a ','
    table, "5.351" in a ';' or tab table (a decimal point or thousands?), both a point and a comma,
    |value| > 10¹², and a value that underflows to 0 (1e-400)."""
    s = _normal(text)
    if _RADIX.match(s):
        raise SaidValueError("nb radix")
    if "_" in s:
        raise SaidValueError("nb underscore")
    if _WORDS.match(s):
        raise SaidValueError("nb not finite")
    if any(c in s for c in _GROUPING):
        s = re.sub(f"[{_GROUPING}]", " ", s)
        if not _GROUPED.match(s):
            raise SaidValueError("nb spaces")
        s = s.replace(" ", "")
    if "," in s:
        if "." in s:
            raise SaidValueError("nb point and comma")
        if delimiter == "," and _THOUSANDS_COMMA.match(s):
            raise SaidValueError("nb comma thousands")
        if s.count(",") > 1:
            raise SaidValueError("nb two commas")
        s = s.replace(",", ".")
    elif delimiter in (";", "\t") and _THOUSANDS_DOT.match(s):
        raise SaidValueError("nb dot thousands")
    if not _PLAIN.match(s):
        raise SaidValueError("nb not number")
    value = float(s)
    if not abs(value) <= MAX_CELL_VALUE:
        raise SaidValueError("nb too large", most=f"{MAX_CELL_VALUE:g}")
    if value == 0.0 and re.search(r"[1-9]", s.split("e")[0].split("E")[0]):
        raise SaidValueError("nb underflow")
    return int(s) if re.fullmatch(r"[+-]?\d+", s) else value


def check_numbers_in(text: str, delimiter: str) -> None:
    """Every number written inside a cell that is not itself a number (an expression such as
    ``0.7 * rocker``, a list ``[0, 0.5]``), outside its quoted strings, read by ``read_number``'s
    rule: ValueError for 0x10, 7_2, 1e-400 … there too."""
    for token in _TOKEN.findall(_QUOTED.sub(" ", text)):
        try:
            read_number(token, ",")           # the cell's own commas separate its items
        except ValueError as exc:
            raise SaidValueError("nb in cell", text=repr(token[:30]), why=reason(exc)) from None
