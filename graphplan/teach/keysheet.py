"""The key sheet (A4 portrait) and the group's summary sheet (A4 landscape) as construction records.

Both are tables drawn like a sheet: the frame 20 mm from the left edge and 5 mm from the others,
GOST type-B lettering 2.5 / 3.5 / 5 mm, thick outlines and thin rules (REFERENCE §3).
"""
from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from graphplan.util.markup import escape
from graphplan.util.romanize import in_latin, romanize
from graphplan.util.words import UNITS, fixed, num, unit, word
from graphplan.graphic.record import Record, line_pitch, text_width
from graphplan.teach.keys import fmt

A4_PORTRAIT = (210.0, 297.0)
A4_LANDSCAPE = (297.0, 210.0)
LEFT, EDGE = 20.0, 5.0           # the frame's distance from the left edge / the other edges
INSET = 5.0                      # text and tables start this far inside the frame
SMALL, MEDIUM, LARGE = 2.5, 3.5, 5.0


NAMES = {"phi0_deg": ("φ_0", "φ_0"), "pos_a": ("пол. a", "pos. a"), "K_calc": ("K розр.", "K calc"),
         "v_max": ("|v|_max", "|v|_max"), "a_max": ("|a|_max", "|a|_max"), "variant": ("варіант", "variant"),
         "student": ("студент", "student"), "status": ("стан", "status"),
         # a cam's summary (teach/camkeys.py)
         "R0_min": ("R_0 min", "R_0 min"), "R0": ("R_0", "R_0"), "theta_rise": ("ϑ підйому", "ϑ rise"),
         "theta_return": ("ϑ опускання", "ϑ return"), "rho_min": ("ρ min", "ρ min")}


def summary_note(lang: str) -> str:
    """What the summary's computed columns mean."""
    return word("summary note", lang)


def _fmt(value: float | None, lang: str) -> str:
    """keys.fmt with the language's decimal sign."""
    text = fmt(value)
    return text.replace(".", ",") if lang == "uk" else text


def _unit(name: str, lang: str, key: dict[str, Any]) -> str:
    """The unit of the key's quantity ``name`` in ``lang`` (the key itself stores SI symbols)."""
    return unit_text(key["quantities"][name]["unit"], lang)


def unit_text(symbol: str, lang: str) -> str:
    """An SI unit symbol as written in ``lang`` ("m/s" → "м/с"); unknown ones as they are."""
    return unit(symbol, lang) if symbol in UNITS else symbol


def display(name: str, lang: str = "en") -> str:
    """A quantity's name as printed: ω and ε for omega and eps, the rest as in the long table."""
    if name in NAMES:
        return NAMES[name][0 if lang == "uk" else 1]
    return re.sub(r"^omega_", "ω_", re.sub(r"^eps_", "ε_", name))


def heading(key: dict[str, Any], lang: str = "uk") -> tuple[Record, float, float]:
    """A cam or gear variant's A4 key sheet begun: the frame, the base's name, «Ключ відповідей,
    варіант …», the title and the student; (record, x of the text, y of the last line)."""
    W, H = A4_PORTRAIT
    uk = lang == "uk"
    rec = Record(("Ключ: варіант " if uk else "Key: variant ") + escape(key["variant"]))
    frame(rec, W, H)
    x0, y = LEFT + INSET, H - EDGE - 3.0
    rec.label((W - EDGE - INSET, y - SMALL), f"graphplan · {escape(key['base'])}", size=SMALL, anchor="end")
    y -= 7.0
    rec.label((x0, y), ("Ключ відповідей, варіант " if uk else "Answer key, variant ") + escape(key["variant"]),
              size=5.0)
    y -= 7.0
    rec.label((x0, y), escape(key["title"] if uk else (key.get("title_en") or romanize(key["title"]))), size=MEDIUM)
    if key.get("student"):
        y -= 5.5
        rec.label((x0, y), ("студент: " if uk else "student: ") + escape(in_latin(key["student"], "uk" if uk else "en")),
                  size=MEDIUM)
    return rec, x0, y


def frame(rec: Record, width: float, height: float) -> None:
    rec.add("polygon", [(LEFT, EDGE), (width - EDGE, EDGE), (width - EDGE, height - EDGE), (LEFT, height - EDGE)],
            role="frame", layer="frame")


def table(rec: Record, x: float, top: float, header: Sequence[Sequence[str]], rows: Sequence[Sequence[str]],
          *, size: float = SMALL, row_h: float = 4.5, align: Sequence[str] | None = None,
          widths: Sequence[float] | None = None) -> tuple[float, float]:
    """A ruled table (drawing.tables, the one table builder) with its top-left corner at (x, top);
    ``header`` is a list of header rows. Returns (the table's bottom y, its width)."""
    from graphplan.drawing.tables import table as ruled
    cells = [list(r) for r in header] + [list(r) for r in rows]
    if widths is None:
        widths = column_widths(cells, size)
    t = ruled(cells, list(widths), row_h=row_h, size=size, header=len(header),
              align=list(align) if align else ["end"] * len(header[0])).moved(x, top)
    rec.extend(t)
    x0, y0, x1, _ = Record(items=[p for p in t.items if p.kind != "text"]).bounds()
    return y0, x1 - x0


def _heading(rec: Record, x: float, y: float, text: str, size: float = MEDIUM) -> float:
    rec.label((x, y - size), text, size=size)
    return y - size - 2.0


def _words(text: str) -> list[str]:
    """The text's words as a line may break between them: a parenthesis kept whole ("(φ = 30,0°)"),
    a number kept with the word before it ("position 10", "положеннях 0–11")."""
    out: list[str] = []
    depth = 0
    for w in text.split(" "):
        if out and (depth > 0 or (w[:1].isdigit() and not out[-1].endswith((",", ";", ":", ".")))):
            out[-1] += " " + w
        else:
            out.append(w)
        depth = max(0, depth + w.count("(") - w.count(")"))
    return out


def _wrap(text: str, size: float, width: float, heading: bool = False) -> list[str]:
    """The text in lines no wider than ``width``, broken at spaces (a heading not inside a
    parenthesis nor before a number: ``_words``)."""
    words, lines, line = (_words(text) if heading else text.split(" ")), [], ""
    for w in words:
        trial = f"{line} {w}".strip()
        if line and text_width(trial, size) > width:
            lines.append(line)
            line = w
        else:
            line = trial
    return lines + ([line] if line else [])


def _paragraph(rec: Record, x: float, y: float, text: str, size: float, width: float) -> float:
    for line in _wrap(text, size, width):
        rec.label((x, y - size), line, size=size)
        y -= line_pitch(size)
    return y - 0.5


def _value_text(key: dict[str, Any], value: Any, lang: str = "en") -> str:
    return cell(value, as_given=True, lang=lang)


# -- the key sheet -------------------------------------------------------------------------------

def _columns_split(columns: list[str], cells: dict[str, list[str]], fixed: list[tuple[str, str, list[str]]],
                   size: float, room: float) -> list[list[str]]:
    """Split value columns into groups so each table (with the fixed columns repeated) fits ``room``."""
    def width(col_texts: list[str]) -> float:
        return max(text_width(t, size) for t in col_texts) + 2.5
    base = sum(width([h, u] + c) for h, u, c in fixed)
    groups, group, used = [], [], base
    for col in columns:
        w = width(cells[col])
        if group and used + w > room:
            groups.append(group)
            group, used = [], base
        group.append(col)
        used += w
    return groups + ([group] if group else [])


def key_sheet(key: dict[str, Any], lang: str = "uk") -> Record:
    """The compact key sheet of one variant on A4 portrait: header, velocities at every position,
    accelerations at the acceleration-plan positions, the output's diagram values; in ``lang``."""
    W, H = A4_PORTRAIT
    f_ = lambda v: _fmt(v, lang)  # noqa: E731
    w = lambda k_, **kw: word(k_, lang, **kw)  # noqa: E731
    u = lambda name: _unit(name, lang, key)  # noqa: E731
    rec = Record(w("key title", variant=escape(key["variant"])))
    frame(rec, W, H)
    x0, room = LEFT + INSET, W - EDGE - LEFT - 2 * INSET
    y = H - EDGE - 3.0
    rec.label((W - EDGE - INSET, y - SMALL), f"graphplan · {escape(key['base'])}", size=SMALL, anchor="end")
    y = _heading(rec, x0, y, w("key heading", variant=escape(key["variant"])), LARGE) - 0.5
    title = key.get("title_en") or romanize(key.get("title", ""))
    if lang == "uk":
        title = key.get("title") or title
    elif key.get("title") and key.get("title_en"):
        title = f"{key['title_en']} ({key['title']})"
    y = _paragraph(rec, x0, y, escape(title), MEDIUM, room)
    if key.get("student"):
        y = _paragraph(rec, x0, y, f"{w('student cap')}: {escape(in_latin(key['student'], lang))}", MEDIUM, room)
    quantities = key["quantities"]
    if key["overrides"]:
        data = ", ".join(f"{escape(k)} = {_value_text(key, v, lang)}" for k, v in key["overrides"].items())
        y = _paragraph(rec, x0, y, f"{w('variant data')}: {data}", SMALL, room)
    w1 = key["omega1"]
    out = key["output"]["name"]
    parts = [f"ω_1 = {f_(abs(w1))} {unit('rad/s', lang)} ({f_(abs(w1) * 30 / 3.141592653589793)} {unit('rpm', lang)}, "
             f"{w('ccw') if w1 > 0 else w('cw')})",
             f"T = {f_(key['period'])} {unit('s', lang)}", key["formula"],
             w("key output", name=out, phi=fixed(key['position0_phi_deg'], lang, 2))]
    if key["stroke"] is not None:
        parts.append(f"H = {f_(key['stroke'])} {u('s')}, K = {fixed(key['K'], lang, 3)}")
    y = _paragraph(rec, x0, y, "; ".join(parts) + ".", SMALL, room)
    tols = sorted({q["tolerance_pct"] for q in quantities.values()})
    default = max(tols, key=lambda t: sum(q["tolerance_pct"] == t for q in quantities.values()))
    special = [f"{display(n)} ±{num(q['tolerance_pct'], lang)} %" for n, q in quantities.items()
               if q["tolerance_pct"] != default]
    tol_text = w("key tolerance", tol=num(default, lang), special=f" ({', '.join(special)})" if special else "",
                 zero=num(key['zero_fraction'] * 100, lang))
    y = _paragraph(rec, x0, y, tol_text, SMALL, room) - 1.5

    velocity = [n for n, q in quantities.items() if q["family"] == "velocity"]
    acceleration = [n for n, q in quantities.items() if q["family"] == "acceleration"]
    positions = key["positions"]
    accel = key["accel"]

    # table 1: velocities, split into column groups when too wide
    vel_groups = _columns_split(velocity, {n: [f_(p["values"][n]) for p in positions] + [display(n),
                                quantities[n]["unit"]] for n in velocity},
                                [(w("no"), "", [str(p["index"]) for p in positions]),
                                 ("φ", "°", [fixed(p['phi_deg'], lang, 1) for p in positions])], SMALL, room)
    t1 = [Block([[w("no"), "φ"] + [display(n) for n in group], ["", "°"] + [u(n) for n in group]],
                [[str(p["index"]), fixed(p['phi_deg'], lang, 1)] + [f_(p["values"][n]) for n in group]
                 for p in positions]) for group in vel_groups]
    # table 2: accelerations, in two blocks side by side when long
    t2: list[Block] = []
    if accel:
        split = 2 if len(acceleration) > 9 else 1
        chunk = -(-len(acceleration) // split)
        for part in range(split):
            names = acceleration[part * chunk:(part + 1) * chunk]
            t2.append(Block([[w("quantity"), w("unit")] + [f"{w('position')} {p}" for p in accel]],
                            [[display(n), u(n)] + [f_(positions[p]["values"][n]) for p in accel]
                             for n in names], ["start", "start"] + ["end"] * len(accel)))
    # table 3: the output's diagram
    t3 = [_diagram_block(key, lang)]

    numbers = iter(range(1, 4))
    sections = [(w("key velocities", n=next(numbers), last=len(positions) - 1), "", t1, False)]
    if accel:
        where = ", ".join(f"{p} (φ = {fixed(positions[p]['phi_deg'], lang, 1)}°)" for p in accel)
        sections.append((w("key accelerations" if len(accel) > 1 else "key acceleration", n=next(numbers),
                           where=where), "", t2, True))
    sections.append((w("key diagrams", n=next(numbers), name=key['output']['name'], k=key['divisions']),
                     w("key diagrams note", half=fixed(0.5, lang, 1)), t3, False))
    y = _place(rec, x0, y, room, sections)
    if "curves" in key and y - EDGE - 4.0 >= CHART_MIN:
        _curves(rec, key, x0, y - 2.0, room, EDGE + 4.0, lang)
    return rec


@dataclass
class Block:
    """A table to place: header rows, body rows and the body's alignment."""
    header: list[list[str]]
    rows: list[list[str]]
    align: list[str] | None = None

    def width(self, size: float = SMALL) -> float:
        return sum(column_widths(self.header + self.rows, size))


def column_widths(cells: Sequence[Sequence[str]], size: float) -> list[float]:
    return [max(text_width(r[i], size) for r in cells if i < len(r)) + 2.5 for i in range(len(cells[0]))]


GAP = 6.0        # between blocks side by side
ROW_MIN = 2.7    # mm: the smallest row height (with 1.8 mm lettering) before a sheet overflows
SECTION = 4.0    # below a section
HEAD_GAP = 2.0   # mm: a heading's baseline to its tables (or note)
NOTE_GAP = 0.5   # mm: more between a heading and its note (the heading's д, у, φ hang below it)
NOTE_UP = 2.5    # mm: a note's baseline over its tables (a comma's tail clear of the head row)
HEAD_PITCH = line_pitch(MEDIUM) + 0.5    # mm: baseline to baseline of a heading wrapped in two lines


def _diagram_block(key: dict[str, Any], lang: str = "uk") -> Block:
    diagram = key["diagram"]
    f_ = lambda v: _fmt(v, lang)  # noqa: E731
    header = [["k", "φ", "t", "s", f"v (k + {fixed(0.5, lang, 1)})", "a"],
              ["", "°", unit("s", lang), _unit("s", lang, key), _unit("v", lang, key), _unit("a", lang, key)]]
    rows = []
    for k in range(key["divisions"] + 1):
        point = diagram[2 * k]
        mid = diagram[2 * k + 1]["values"]["v"] if 2 * k + 1 < len(diagram) else None
        rows.append([str(k), fixed(point['phi_deg'], lang, 1), f_(point["t"]), f_(point["values"]["s"]),
                     f_(mid) if mid is not None else "", f_(point["values"]["a"])])
    return Block(header, rows)


Section = tuple[str, str, list["Block"], bool]   # title, note, blocks, blocks side by side


def _pair(sections: list[Section], room: float, size: float) -> list[list[Section]]:
    """Rows of the page: two consecutive sections side by side when both fit the width — their
    tables, their notes, and their headings in at most two lines each (the second section starts
    2·GAP after the first's tables; its heading must end inside the frame)."""
    rows, k = [], 0
    while k < len(sections):
        first = sections[k]
        if k + 1 < len(sections):
            second = sections[k + 1]
            x2 = _width(first, size) + 2 * GAP
            widths = (x2 - GAP, room - x2)
            if (_width(second, size) <= widths[1]
                    and all(len(_wrap(s[0], MEDIUM, w, heading=True)) <= 2 and text_width(s[1], SMALL) <= w
                            for s, w in zip((first, second), widths))):
                rows.append([first, second])
                k += 2
                continue
        rows.append([first])
        k += 1
    return rows


def _head_widths(row: list[Section], room: float, size: float) -> list[float]:
    """How wide each section's heading may run: to the next section, or to the frame."""
    if len(row) == 1:
        return [room]
    x2 = _width(row[0], size) + 2 * GAP
    return [x2 - GAP, room - x2]


def _head_height(row: list[Section], room: float, size: float) -> float:
    """The height of a page row's headings (the tallest, each wrapped to its width) and notes."""
    lines = max(len(_wrap(s[0], MEDIUM, w, heading=True)) for s, w in zip(row, _head_widths(row, room, size)))
    return (MEDIUM + HEAD_GAP + (lines - 1) * HEAD_PITCH
            + (SMALL + NOTE_GAP + NOTE_UP if any(s[1] for s in row) else 0.0))


def _width(section: Section, size: float) -> float:
    ws = [b.width(size) for b in section[2]]
    return sum(ws) + GAP * (len(ws) - 1) if section[3] else max(ws)


def _lines(section: Section) -> int:
    ls = [len(b.header) + len(b.rows) for b in section[2]]
    return max(ls) if section[3] else sum(ls)


def _row_height(page_rows: list[list[Section]], height: float, room: float, size: float) -> float:
    """The row height that makes the page rows fill ``height`` (not clamped)."""
    need = sum(max(_lines(s) for s in row) for row in page_rows)
    fixed = sum(_head_height(row, room, size) + SECTION
                + max(0 if s[3] else 3.0 * (len(s[2]) - 1) for s in row) for row in page_rows)
    return (height - fixed) / need


def _lettering(row_h: float) -> float:
    return SMALL if row_h >= 3.4 else max(1.8, row_h - 0.9)


def _fold(section: Section) -> Section:
    """A one-block section's rows in two halves side by side."""
    (block,) = section[2]
    half = -(-len(block.rows) // 2)
    return (section[0], section[1], [Block(block.header, block.rows[:half], block.align),
                                     Block(block.header, block.rows[half:], block.align)], True)


def _place(rec: Record, x0: float, y: float, room: float, sections: list[Section]) -> float:
    """Lay the sections out down the sheet: a section's blocks side by side when it says so (else
    stacked); two consecutive sections side by side when both fit the width. Row heights shrink
    (4.5 → 3.4 mm, then with smaller lettering to 2.7 mm) so that everything fits above the frame;
    when even that is too tall, the longest one-block tables are folded into two halves side by side.
    Returns the y below the last section."""
    height = y - EDGE - 4.0
    sections = list(sections)
    size = SMALL
    page_rows = _pair(sections, room, size)
    row_h = _row_height(page_rows, height, room, size)
    while row_h < ROW_MIN:
        size = _lettering(max(row_h, ROW_MIN))
        foldable = [k for k, s in enumerate(sections) if len(s[2]) == 1 and len(s[2][0].rows) > 8
                    and 2 * s[2][0].width(size) + GAP <= room]
        if not foldable:
            break
        k = max(foldable, key=lambda k: _lines(sections[k]))
        sections[k] = _fold(sections[k])
        page_rows = _pair(sections, room, size)
        row_h = _row_height(page_rows, height, room, size)
    row_h = max(ROW_MIN, min(4.5, row_h))
    size = _lettering(row_h)
    for row in page_rows:
        x, bottom = x0, y
        top = y - _head_height(row, room, size)          # the row's tables start level
        for (title, note, blocks, beside), width in zip(row, _head_widths(row, room, size)):
            for k, line in enumerate(_wrap(title, MEDIUM, width, heading=True)):
                _heading(rec, x, y - k * HEAD_PITCH, line)
            if note:
                rec.label((x, top + NOTE_UP), note, size=SMALL)
            bx, by = x, top
            for b in blocks:
                b_bottom, w = table(rec, bx, by, b.header, b.rows, size=size, row_h=row_h, align=b.align)
                bottom = min(bottom, b_bottom)
                if beside:
                    bx += w + GAP
                else:
                    by = b_bottom - 3.0
            x += _width((title, note, blocks, beside), size) + 2 * GAP
        y = bottom - SECTION
    return y


CHART_MIN = 50.0     # the s–v–a curves are drawn when this much height is left
CHART_MAX = 34.0     # at most this tall per quantity


def _curves(rec: Record, key: dict[str, Any], x0: float, top: float, width: float, bottom: float,
            lang: str = "uk") -> None:
    """The exact s, v, a of the output over one turn from position 0, with the key's ordinates
    marked (s and a at the divisions, v at the chord midpoints) and the divisions ruled."""
    curves, n = key["curves"], key["divisions"]
    turn = curves["turn_deg"]
    f_ = lambda v: _fmt(v, lang)  # noqa: E731
    y = _heading(rec, x0, top, word("key curves", lang, n=_section_count(key) + 1, name=key['output']['name']))
    label_w, tick_w = 12.0, 14.0
    px, pw = x0 + label_w + tick_w, width - label_w - tick_w - 2.0
    gap = 3.0
    h = min(CHART_MAX, (y - bottom - 6.0 - 2 * gap) / 3)
    marks = {"s": [2 * k for k in range(n + 1)], "v": [2 * k + 1 for k in range(n)],
             "a": [2 * k for k in range(n + 1)]}
    for row, name in enumerate(("s", "v", "a")):
        values = curves[name]
        lo, hi = min(min(values), 0.0), max(max(values), 0.0)
        if hi - lo <= 0:
            hi = lo + 1.0
        y1 = y - row * (h + gap)
        y0 = y1 - h

        def X(t: float) -> float:
            return px + t / 360.0 * pw

        def Y(v: float) -> float:
            return y0 + (v - lo) / (hi - lo) * h

        rec.add("polygon", [(px, y0), (px + pw, y0), (px + pw, y1), (px, y1)], role="table", layer="diagrams")
        for k in range(1, n):
            rec.segment((X(k * 360.0 / n), y0), (X(k * 360.0 / n), y1), role="grid", layer="diagrams")
        if lo < 0 < hi:
            rec.segment((px, Y(0.0)), (px + pw, Y(0.0)), role="construction", layer="diagrams")   # solid (GOST 2.303)
        rec.add("polyline", [(X(t), Y(v)) for t, v in zip(turn, values)], role="curve", layer="diagrams")
        for j in marks[name]:
            point = key["diagram"][j]
            t = point["abscissa"] * 360.0 / n
            rec.point((X(t), Y(point["values"][name])), layer="diagrams")
        rec.label((x0, (y0 + y1) / 2 - SMALL / 2), f"{name}, {_unit(name, lang, key)}", size=SMALL)
        rec.label((px - 1.0, y1 - SMALL), f_(hi), size=SMALL, anchor="end")
        rec.label((px - 1.0, y0), f_(lo), size=SMALL, anchor="end")
    y_axis = y - 3 * h - 2 * gap
    for k in range(n + 1):
        if n <= 24 or k % 2 == 0:
            rec.label((X(k * 360.0 / n), y_axis - SMALL - 1.0), str(k), size=SMALL, anchor="middle")
    rec.label((px + pw, y_axis - 2 * SMALL - 2.5), word("key axis note", lang),
              size=SMALL, anchor="end")


def _section_count(key: dict[str, Any]) -> int:
    return 3 if key["accel"] else 2


# -- the group's summary sheet ---------------------------------------------------------------------

SUMMARY_ROW_MIN = 3.0    # mm: the smallest row of a one-page summary
SUMMARY_ROW = 4.0        # mm: the rows of a summary that runs over several pages


def summary_pages(title: str, columns: list[str], rows: list[dict[str, Any]], units: dict[str, str],
                  overrides: set[str] = frozenset(), lang: str = "uk") -> list[Record]:
    """The group's summary on A4 landscape pages: one line per variant with its data and headline
    answers, then what the columns mean and a note for each skipped variant. A group whose rows fit
    one page at 3 mm or more a row (about 45 variants) gets one page; a larger one (a faculty's
    hundreds of variants) runs over pages of 4 mm rows, the column heads repeated on each, the pages
    numbered in their titles ("аркуш 2 з 23") and the notes after the last row."""
    W, H = A4_LANDSCAPE
    x0, room = LEFT + INSET, W - EDGE - LEFT - 2 * INSET
    header = [[display(c, lang) for c in columns], [unit_text(units.get(c, ""), lang) for c in columns]]
    cells = [[cell(r.get(c), c in overrides, lang) for c in columns] for r in rows]
    size = SMALL
    while size > 1.8 and sum(max(text_width(t, size) for t in col) + 2.5
                             for col in zip(*(header + cells))) > room:
        size = round(size - 0.1, 2)
    widths = column_widths(header + cells, size)        # the same columns on every page
    align = ["start" if c in ("variant", "student", "status") else "end" for c in columns]
    notes = ([summary_note(lang)] if "phi0_deg" in columns else []) + [     # not a cam's columns
        word("variant note", lang, v=escape(str(r['variant'])), note=escape(r.get('note', '')))
        for r in rows if r.get("status") != "ok"]
    lines = [line for note in notes for line in _wrap(note, SMALL, room)]
    top = H - EDGE - 3.0 - LARGE - 2.0 - 1.0            # below the title
    bottom = EDGE + 4.0
    pitch = line_pitch(SMALL)
    notes_h = len(lines) * pitch + (1.5 if lines else 0.0)
    one_page = (len(rows) + 2) * SUMMARY_ROW_MIN <= top - bottom - notes_h
    if one_page:
        row_h = max(SUMMARY_ROW_MIN, min(5.0, (top - bottom - notes_h - 3 * 4.0) / (len(rows) + 2)))
        chunks = [cells]
    else:
        row_h = SUMMARY_ROW
        per = max(1, int((top - bottom) / row_h) - 2)
        chunks = [cells[k:k + per] for k in range(0, len(cells), per)]
    pages: list[tuple[Record, float]] = []
    for chunk in chunks:
        rec = Record(title)
        frame(rec, W, H)
        y, _ = table(rec, x0, top, header, chunk, size=size, row_h=row_h, align=align, widths=widths)
        pages.append((rec, y - 1.5))
    rec, y = pages[-1]
    for line in lines:                   # the notes under the last rows, on pages of their own if need be
        if y - pitch < bottom:
            rec = Record(title)
            frame(rec, W, H)
            y = top
            pages.append((rec, y))
        rec.label((x0, y - SMALL), line, size=SMALL)
        y -= pitch
        pages[-1] = (rec, y)
    count = len(pages)
    for k, (rec, _) in enumerate(pages, 1):
        heading = title if count == 1 else f"{title} ({word('page of', lang, k=k, n=count)})"
        _heading(rec, x0, H - EDGE - 3.0, heading, LARGE)
    return [rec for rec, _ in pages]


def cell(value: Any, as_given: bool = False, lang: str = "en") -> str:
    """A summary cell: answers to 4 significant digits, a variant's data as given (``as_given``),
    in the language's decimal sign; the status word in ``lang``."""
    if value is None:
        return ""
    if isinstance(value, float):
        text = f"{value:g}" if as_given else fmt(value, 4)
        return text.replace(".", ",") if lang == "uk" else text
    if value in ("ok", "skipped"):
        return word(value, lang)
    return str(value)
