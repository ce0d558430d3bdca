"""Ruled tables as construction records — the one table builder of every sheet, key sheet and
drawing (GOST 2.104-style: a thick outline and header line, thin rules, numbers right-aligned)."""
from __future__ import annotations

from graphplan.graphic.record import THICK, THIN, Record, ink_boxes, line_pitch, text_width

LETTERING = (1.8, 2.5, 3.5, 5.0, 7.0, 10.0, 14.0)   # GOST 2.304 letter heights, mm
TABLES = 1.4      # the sheets' tables: ruled at 2.5 mm lettering, drawn 1.4 × (3.5 mm letters, 8.4 mm rows)


def enlarged(rec: Record, k: float = TABLES) -> Record:
    """A table (or any record) drawn ``k`` times larger about its origin, its lettering at the
    nearest letter height of the GOST series (a cell's letters shrunk to fit stay in proportion)."""
    from dataclasses import replace

    if k == 1.0:
        return rec

    def grown(p):
        q = p.moved(0.0, 0.0, k)
        if p.kind != "text":
            return q
        size = min(LETTERING, key=lambda h: abs(h - p.size * k)) if p.size in LETTERING else p.size * k
        return replace(q, size=size)
    return Record(rec.title, [grown(p) for p in rec.items], dict(rec.scales))


PAD = 1.0        # mm between a cell's text and its rules
TITLE_MM = 100.0  # a table's title wraps to the table's width, or to this where the table is narrower


def title_lines(title: str, width: float, size: float = 3.5) -> list[str]:
    """A table's title wrapped at its spaces (never inside a {group} of the markup) to ``width`` mm."""
    from graphplan.util.markup import split
    lines, line = [], ""
    for word in split(title):
        if line and text_width(f"{line} {word}", size) > width:
            lines.append(line)
            line = word
        else:
            line = f"{line} {word}".strip()
    return lines + [line] if line else lines


def table(rows: list[list[str]], widths: list[float], row_h: float = 6.0, size: float = 2.5,
          title: str = "", header: int = 1, align: list[str] | None = None, span: float | None = None,
          clear_header: bool = False) -> Record:
    """A ruled table; its top-left corner at (0, 0), growing downward (y < 0), its title above it.
    The first ``header`` rows are the header (centred, a thick line under them); in the body numbers
    are right-aligned and text centred, or each column as ``align`` says ("start", "middle",
    "end"). A column is widened to its widest cell: the lettering keeps its height (never under
    2.5 mm) and stays in its cell, clear of the rules. ``span``: the columns widened in proportion to
    that width where they are narrower (a table across the column of the sheet it stands in).
    A cell may hold lines broken as a drafter breaks a long value or header («\\n» between them): its
    row grows by a line pitch for each line past the first, its lines centred in the row one under
    another; a table of one-line cells is ruled as before. ``clear_header``: a header row of one-line cells
    whose lettering (capitals to a subscript's tail) cannot keep ``RULE_CLEAR`` from both its rules in
    ``row_h`` grows to hold it, its ink centred (a table set in rows close for its letters)."""
    rec = Record(title)
    lines_of = lambda cell: cell.split("\n")                      # noqa: E731
    widths = [max(w, max((text_width(q, size) for row in rows if c < len(row) and row[c] for q in lines_of(row[c])),
                         default=0.0) + 2 * PAD + 0.5) for c, w in enumerate(widths)]
    if span is not None and span > sum(widths):
        widths = [w * span / sum(widths) for w in widths]
    x_edges = [0.0]
    for w in widths:
        x_edges.append(x_edges[-1] + w)
    top = 0.0
    if title:
        lines = title_lines(title, max(x_edges[-1], TITLE_MM))
        for k, line in enumerate(lines):
            rec.label((0.0, 2.2 + line_pitch(3.5) * (len(lines) - 1 - k)), line, size=3.5, layer="tables")
    n = len(rows)
    pitch = line_pitch(size)
    heights = [row_h + pitch * (max((len(lines_of(c)) for c in row if c), default=1) - 1) for row in rows]
    # (clear_header) a header row of one-line cells whose lettering, capitals to a subscript's tail, cannot keep
    # RULE_CLEAR from both its rules in row_h grows to hold it (stop 60: the cam set's 3.5-mm Table 1 in 7-mm rows — the
    # header's «y_{ds/dφ}, мм» reached 0.49 mm from the thick rule under it, a composition defect)
    ink = [_row_ink(row, size) if clear_header and h_ == row_h and r < header else None
           for r, (row, h_) in enumerate(zip(rows, heights))]
    grown = [b is not None and b[1] - b[0] + 2 * RULE_CLEAR > row_h for b in ink]
    heights = [b[1] - b[0] + 2 * RULE_CLEAR if g else h_ for b, g, h_ in zip(ink, grown, heights)]
    tops = [top]
    for h_ in heights:
        tops.append(tops[-1] - h_)
    for k in range(n + 1):
        y = tops[k]
        rec.segment((0.0, y), (x_edges[-1], y), role="table", layer="tables",
                    width=THICK if k in (0, header, n) else THIN)
    for k, x in enumerate(x_edges):
        rec.segment((x, top), (x, tops[n]), role="table", layer="tables",
                    width=THICK if k in (0, len(x_edges) - 1) else THIN)
    for r, row in enumerate(rows):
        y_row = tops[r + 1] + (row_h - size) / 2 + 0.15 * size
        # one baseline a row: the lowest any of its cells needs (a raised prime's cell lowers its row)
        y = min((baseline_in_row(q, size, y_row, tops[r] - (len(lines_of(cell)) - 1) * 0.0, row_h)
                 for cell in row if cell for q in lines_of(cell)[:1]), default=y_row)
        if grown[r]:                     # the row's ink RULE_CLEAR under its top rule, as far over its bottom one
            y = tops[r] - RULE_CLEAR - ink[r][1]
        for c, cell in enumerate(row):
            if not cell:
                continue
            parts = lines_of(cell)
            how = "middle" if r < header else (align[c] if align else ("end" if _is_number(parts[-1]) else "middle"))
            x = {"start": x_edges[c] + PAD + 0.3, "middle": (x_edges[c] + x_edges[c + 1]) / 2,
                 "end": x_edges[c + 1] - PAD - 0.3}[how]
            if len(parts) == 1 and (heights[r] == row_h or grown[r]):
                rec.label((x, y), cell, size=size, anchor=how, layer="tables")
                continue
            # lines one pitch apart, the block centred in the row (the one-line cell's place shifted)
            first = y + (heights[r] - row_h) / 2 + pitch * (len(parts) - 1) / 2
            for k, q in enumerate(parts):
                rec.label((x, first - k * pitch), q, size=size, anchor=how, layer="tables")
    return rec


RULE_CLEAR = 0.8     # mm from a rule's centre line to a cell's ink: its half width and a reader's gap


def baseline_in_row(cell: str, size: float, y: float, row_top: float, row_h: float) -> float:
    """The cell's baseline: ``y`` (letters of ``size`` centred in the row) unless its ink reaches
    within ``RULE_CLEAR`` of the row's top rule — a prime or index raised high (z′₂ of a type-B
    train), a Й, in a row only twice the letters' height — then lowered to keep that clearance, or,
    where that would bring its descenders as near the bottom rule, its ink centred in the row."""
    boxes = ink_boxes(cell, size)
    if not boxes:
        return y
    hi, lo = max(b[3] for b in boxes), min(b[1] for b in boxes)
    if row_top - (y + hi) >= RULE_CLEAR:
        return y
    lowered = row_top - RULE_CLEAR - hi
    if lowered + lo - (row_top - row_h) >= RULE_CLEAR:
        return lowered
    return row_top - row_h / 2 - (hi + lo) / 2


def _row_ink(row: list[str], size: float) -> tuple[float, float] | None:
    """The lowest and highest ink (mm from the baseline) of a row's cells' lettering (None: no ink)."""
    boxes = [b for cell in row if cell for b in ink_boxes(cell, size)]
    if not boxes:
        return None
    return min(b[1] for b in boxes), max(b[3] for b in boxes)


def _is_number(text: str) -> bool:
    """A number as the tables write it: a true minus, a decimal comma, maybe marked * (over 5 %);
    or a jump's two sides, «0 → 20,37» (right-aligned as its column's numbers)."""
    if " → " in text:
        return all(_is_number(t) for t in text.split(" → "))
    try:
        float(text.removesuffix("*").replace("−", "-").replace(",", "."))
        return True
    except ValueError:
        return False
