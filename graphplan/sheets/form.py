"""The drawing sheet's form: formats, the frame and the title block (REFERENCE §3, GOST 2.104
form 1 and form 2a), and tables — all as construction records in sheet millimetres (y up)."""
from __future__ import annotations

from dataclasses import dataclass

from graphplan.graphic.record import THICK, THIN, Record, line_pitch, text_width
from graphplan.util.words import word as _word

FORMATS = {"A1": (841.0, 594.0), "A2": (594.0, 420.0), "A3": (420.0, 297.0), "A4": (210.0, 297.0)}
LEFT, MARGIN = 20.0, 5.0           # the frame: 20 mm from the left edge, 5 mm from the others
BLOCK_W, BLOCK_H, BLOCK_2A_H = 185.0, 55.0, 15.0

@dataclass(frozen=True)
class Form:
    """A sheet's geometry: paper size and the frame's inner box."""
    name: str
    width: float
    height: float

    @property
    def frame_box(self) -> tuple[float, float, float, float]:
        return LEFT, MARGIN, self.width - MARGIN, self.height - MARGIN


def form(name: str) -> Form:
    from graphplan.util.errors import GraphplanError, either, keyed_error
    key = name.upper()
    if key not in FORMATS:
        raise keyed_error(GraphplanError, None, "--format", "op sheet format", None, got=repr(name),
                          formats=either("A1", "A2", "A3", "A4"))
    w, h = FORMATS[key]
    return Form(key, w, h)


def frame(f: Form) -> Record:
    """The frame: a solid thick rectangle 20 mm from the left edge, 5 mm from the others."""
    rec = Record("frame")
    x0, y0, x1, y1 = f.frame_box
    rec.add("polygon", [(x0, y0), (x1, y0), (x1, y1), (x0, y1)], role="frame", layer="frame")
    return rec


def _line(rec: Record, a, b, thick: bool) -> None:
    rec.segment(a, b, role="frame" if thick else "table", layer="frame", width=THICK if thick else THIN)


def _text(rec: Record, x: float, y: float, text: str, size: float = 2.5, anchor: str = "middle",
          row: bool = False) -> None:
    """A text at baseline y — or, ``row``, centred in the 5 mm row whose bottom is y (its capitals
    and descenders clear of both rules); a centred one centred by its ink (either font's,
    ``Primitive.ink``), so that it stands clear of both sides of its cell as ``_fit`` measured."""
    if text:
        if anchor == "middle":
            from graphplan.graphic.record import Primitive
            b = Primitive("text", ((0.0, 0.0),), text=text, size=size, anchor="middle").ink()
            x -= (b[0] + b[2]) / 2
        rec.label((x, y + 2.5 - 0.35 * size if row else y), text, size=size, anchor=anchor, layer="frame")


SLACK = 1.3     # a field's text measured this much wider than osifont sets it: it stays inside its
                # cell where a viewer letters it with the fallback font (DejaVu Sans: 18–27 % wider)


def _fit(text: str, width: float, sizes=(7.0, 5.0, 3.5, 2.5), slack: float = SLACK) -> float:
    """The largest GOST letter height (2.5 … 7 mm) at which ``text``'s ink, ``slack`` times wider
    (the title block's short words of the form: 1), fits ``width`` mm (the cell less a half millimetre each side) clear of the rules."""
    from graphplan.graphic.record import Primitive
    for s in sizes:
        b = Primitive("text", ((0.0, 0.0),), text=text, size=s).ink()
        if slack * (b[2] - b[0]) <= width - 0.3:
            return s
    return sizes[-1]


def wrap(text: str, width: float, size: float) -> list[str]:
    """Break ``text`` into lines no wider than ``width`` mm at letter height ``size`` (at spaces
    outside the markup's groups: ``M^*_{с max}`` is never broken)."""
    from graphplan.util.markup import split
    lines: list[str] = []
    for word in split(text):
        if lines and text_width(lines[-1] + " " + word, size) <= width:
            lines[-1] += " " + word
        else:
            lines.append(word)
    return lines or [""]


def balanced_wrap(text: str, width: float, size: float) -> list[str]:
    """``wrap``'s count of lines, broken as a draftsman breaks a name: never inside a parenthesis
    where a break outside it fits (review 10 #20: «… сита (рецензія» / «10)» → «… сита» /
    «(рецензія 10)»), before one where it fits, the lines as even in width as these allow."""
    from itertools import combinations

    from graphplan.util.markup import split
    words = split(text)
    greedy = wrap(text, width, size)
    k = len(greedy)
    if k < 2 or len(words) > 24:
        return greedy
    depth, inside = 0, []           # whether a break before each word falls inside a parenthesis
    for w in words:
        inside.append(depth > 0)
        depth = max(0, depth + w.count("(") - w.count(")"))
    best, best_cost = greedy, None
    for cuts in combinations(range(1, len(words)), k - 1):
        bounds = (0,) + cuts + (len(words),)
        lines = [" ".join(words[a:b]) for a, b in zip(bounds, bounds[1:])]
        widths = [text_width(line, size) for line in lines]
        if max(widths) > width:
            continue
        before = any(words[c].startswith("(") for c in cuts)      # «… сита» / «(рецензія 10)»
        cost = (sum(inside[c] for c in cuts), not before and "(" in text, max(widths) - min(widths))
        if best_cost is None or cost < best_cost:
            best, best_cost = lines, cost
    return best


def title_block(f: Form, fields: dict[str, str], lang: str = "uk") -> Record:
    """Title block form 1 (185×55 mm) in the frame's bottom-right corner, filled from ``fields``:
    designation, title, student, teacher, organisation, scale, sheet, sheets, letter, mass."""
    cap = {k: _word("tb " + k.replace("_", " "), lang) for k in (
        "changes", "sheet", "doc", "sign", "date", "drawn", "checked", "tech", "norm", "approved", "letter", "mass",
        "scale", "sheet_no", "sheets")}
    rec = Record("title block")
    _, fy0, fx1, _ = f.frame_box
    x0, y0 = fx1 - BLOCK_W, fy0
    X = lambda dx: x0 + dx  # noqa: E731
    Y = lambda dy: y0 + dy  # noqa: E731  (dy from the block's bottom)
    # outline and the main structure
    rec.add("polygon", [(X(0), Y(0)), (X(185), Y(0)), (X(185), Y(55)), (X(0), Y(55))],
            role="frame", layer="frame")
    _line(rec, (X(65), Y(0)), (X(65), Y(55)), True)
    # left part: 11 rows of 5 mm (row 1 at the top); rows 1–4 thin, the header row 5 between thick lines
    for row in range(1, 11):
        y = Y(55 - 5 * row)
        _line(rec, (X(0), y), (X(65), y), row in (4, 5))
    cols = [0, 7, 17, 40, 55, 65]
    for c in cols[1:-1]:
        x = X(c)
        if c == 7:  # above the header only: the first two columns merge to 17 mm below it
            _line(rec, (x, Y(30)), (x, Y(55)), True)
        else:
            _line(rec, (x, Y(0)), (x, Y(55)), True)
    heads = [cap["changes"], cap["sheet"], cap["doc"], cap["sign"], cap["date"]]
    for (a, b), head in zip(zip(cols, cols[1:]), heads):
        _text(rec, X((a + b) / 2), Y(30), head, size=_fit(head, b - a - 1, (2.5, 2.0), 1.0), row=True)
    roles = [cap["drawn"], cap["checked"], cap["tech"], "", cap["norm"], cap["approved"]]
    names = [fields.get("student", ""), fields.get("teacher", ""), "", "", "", ""]
    for k, (role, name) in enumerate(zip(roles, names)):
        y = Y(30 - 5 * (k + 1))
        _text(rec, X(1), y, role, size=_fit(role, 15.5, (2.5, 2.0), 1.0), anchor="start", row=True)
        # a name too long for 2 mm (a romanised one is longer: «Retsenzent R. R.» 22.4 mm against
        # «Рецензент Р. Р.» 19.6) takes GOST 2.304's smallest height, 1.8 mm, before it meets the rule
        _text(rec, X(18), y, name, size=_fit(name, 21.5, (2.5, 2.0, 1.8), 1.0), anchor="start", row=True)
    # right part: designation 120×15, name 70×25 over 70×15, the 50 mm column
    _line(rec, (X(65), Y(40)), (X(185), Y(40)), True)
    _line(rec, (X(135), Y(0)), (X(135), Y(40)), True)
    _line(rec, (X(65), Y(15)), (X(185), Y(15)), True)
    _line(rec, (X(135), Y(35)), (X(185), Y(35)), True)
    _line(rec, (X(135), Y(20)), (X(185), Y(20)), True)
    for dx in (140, 145):  # three 5 mm letter cells
        _line(rec, (X(dx), Y(20)), (X(dx), Y(35)), False)
    for dx in (150, 167):  # Літ. | Маса | Масштаб
        _line(rec, (X(dx), Y(20)), (X(dx), Y(40)), True)
    _line(rec, (X(155), Y(15)), (X(155), Y(20)), True)   # Аркуш 20 | Аркушів 30
    _text(rec, X(142.5), Y(35), cap["letter"], row=True)
    _text(rec, X(158.5), Y(35), cap["mass"], row=True)
    _text(rec, X(176), Y(35), cap["scale"], size=_fit(cap["scale"], 17, (2.5, 2.0), 1.0), row=True)
    _text(rec, X(137), Y(15), f"{cap['sheet_no']} {fields.get('sheet', '1')}", anchor="start", row=True)
    _text(rec, X(157), Y(15), f"{cap['sheets']} {fields.get('sheets', '1')}", anchor="start", row=True)
    _text(rec, X(142.5), Y(26), fields.get("letter", _word("tb study letter", lang)), size=3.5)
    _text(rec, X(158.5), Y(26), fields.get("mass", ""), size=3.5)
    scale = fields.get("scale", "")
    _text(rec, X(176), Y(26), scale, size=_fit(scale, 17, (3.5, 2.5), 1.0))
    designation = fields.get("designation", "")
    _text(rec, X(125), Y(45.5), designation, size=_fit(designation, 116, (7.0, 5.0, 3.5)))
    _block_text(rec, fields.get("title", ""), X(66), Y(15), 68, 25, (5.0, 3.5, 2.5, 2.0))   # (2.0 as the name
    # fields' last size: a five-line name at 2.5 mm in 5-mm steps touched without its font, stop 52)
    _block_text(rec, fields.get("organisation", ""), X(136), Y(0), 48, 15, (3.5, 2.5))
    _block_text(rec, fields.get("subtitle", ""), X(66), Y(0), 68, 15, (3.5, 2.5))
    return rec


def title_block_2a(f: Form, fields: dict[str, str], lang: str = "uk") -> Record:
    """Title block form 2a (185×15 mm, GOST 2.104) of a document's later sheets, in the frame's
    bottom-right corner: the left part 65 mm (columns 7 | 10 | 23 | 15 | 10, two revision rows over
    the header row), the designation 110×15, the sheet's number in a 10 mm column (the caption
    "Арк." in its upper 7 mm, the number in the lower 8 mm)."""
    cap = {k: _word("tb " + k, lang) for k in ("changes", "sheet", "doc", "sign", "date")}
    rec = Record("title block")
    _, fy0, fx1, _ = f.frame_box
    x0, y0 = fx1 - BLOCK_W, fy0
    X = lambda dx: x0 + dx  # noqa: E731
    Y = lambda dy: y0 + dy  # noqa: E731
    rec.add("polygon", [(X(0), Y(0)), (X(185), Y(0)), (X(185), Y(15)), (X(0), Y(15))],
            role="frame", layer="frame")
    _line(rec, (X(0), Y(10)), (X(65), Y(10)), False)       # the revision rows: thin
    _line(rec, (X(0), Y(5)), (X(65), Y(5)), True)          # the header row under a thick line
    cols = [0, 7, 17, 40, 55, 65]
    for c in cols[1:]:
        _line(rec, (X(c), Y(0)), (X(c), Y(15)), True)
    _line(rec, (X(175), Y(0)), (X(175), Y(15)), True)
    _line(rec, (X(175), Y(8)), (X(185), Y(8)), True)
    heads = [cap["changes"], cap["sheet"], cap["doc"], cap["sign"], cap["date"]]
    for (a, b), head in zip(zip(cols, cols[1:]), heads):
        _text(rec, X((a + b) / 2), Y(0), head, size=_fit(head, b - a - 1, (2.5, 2.0), 1.0), row=True)
    _text(rec, X(180), Y(9.5), cap["sheet"], size=_fit(cap["sheet"], 9, (2.5, 2.0), 1.0))
    _text(rec, X(180), Y(2.25), fields.get("sheet", ""), size=3.5)
    designation = fields.get("designation", "")
    _text(rec, X(120), Y(5), designation, size=_fit(designation, 106, (7.0, 5.0, 3.5)))
    return rec


def _block_text(rec: Record, text: str, x: float, y: float, w: float, h: float, sizes) -> None:
    """Centred, wrapped text in a w×h field whose bottom-left is (x, y): the largest of ``sizes``
    (GOST heights) at which its lines, ``SLACK`` wider than osifont sets them, fit the field; at the
    smallest, lines wrapped to the width and the line step tightened so none leaves the field."""
    if not text:
        return
    for size in sizes:
        lines = balanced_wrap(text, w / SLACK, size)
        if len(lines) * line_pitch(size) <= h and all(SLACK * text_width(s, size) <= w for s in lines):
            break
    step = min(line_pitch(size), h / len(lines))     # (the docstring's tightening: stop 52's own name, five
    top = y + h / 2 + step * len(lines) / 2              # lines at 6 mm, ran 5 mm over the 25-mm cell's rules)
    for k, line in enumerate(lines):
        _text(rec, x + w / 2, top - step * (k + 1) + (step - size) / 2, line, size=size)


def title_block_box(f: Form) -> tuple[float, float, float, float]:
    _, fy0, fx1, _ = f.frame_box
    return fx1 - BLOCK_W, fy0, fx1, fy0 + BLOCK_H


from graphplan.drawing.tables import LETTERING, TABLES, enlarged, table  # noqa: E402,F401  (one ruled-table builder)
