"""The cam sheet's given data as a table («Вихідні дані»), as coursework sheets carry it (seed 000 puts
its given dimensions in Table 2.1 beside the drawing): the follower, the stroke (swing), the offset (the
arm and the centre distance), the roller, the phase angles, the laws, the allowed pressure angles and
the cam's speed and sense. On the A1 sheet it stands in the room the profile's column leaves between the
profile and Table 1 (CAM50's and CAM52's 239 × 90 mm blank under a 1:1 profile), where it fits at the
sheet's table lettering; it is read first, so it is Table 1 and the table of the divisions Table 2."""
from __future__ import annotations

from graphplan.drawing.labels import collisions
from graphplan.drawing.layout import GAP, Placed
from graphplan.graphic.record import Record
from graphplan.model.cam import Cam
from graphplan.report.cam import WORDS as REPORT
from graphplan.sheets.form import table
from graphplan.util.words import num

WORDS = {
    "uk": {"title": "Таблиця {n}. Вихідні дані", "head": ["Величина", "Позначення", "Значення"],
           "follower": "Штовхач", "kinds": {"translating": "поступальний", "rocking": "коромисловий"},
           "roller": "роликовий", "knife": "із вістрям", "stroke": "Хід штовхача", "swing": "Кут розмаху коромисла",
           "offset": "Ексцентриситет", "auto": "для найменшого R_0", "arm": "Довжина коромисла",
           "centre": "Міжосьова відстань", "radius": "Радіус ролика", "base": "Радіус основної шайби",
           "phases": "Фазові кути",
           "law_rise": "Закон руху на підйомі", "law_return": "Закон руху на опусканні",
           "allowed": "Допустимі кути тиску", "rpm": "Частота обертання кулачка",
           "sense": "Напрям обертання кулачка", "mm": "мм", "rpm_unit": "об/хв",
           "phase_symbols": "φ_п; φ_вв; φ_с; φ_бв", "allowed_symbols": "[ϑ]_п; [ϑ]_с"},
    "en": {"title": "Table {n}. Given data", "head": ["Quantity", "Symbol", "Value"],
           "follower": "Follower", "kinds": {"translating": "translating", "rocking": "rocking"},
           "roller": "roller", "knife": "knife-edge", "stroke": "Stroke", "swing": "Swing of the arm",
           "offset": "Offset", "auto": "for the smallest R_0", "arm": "Arm length",
           "centre": "Centre distance", "radius": "Roller radius", "base": "Base radius",
           "phases": "Phase angles",
           "law_rise": "Law of the rise", "law_return": "Law of the return",
           "allowed": "Allowed pressure angles", "rpm": "Cam speed",
           "sense": "Sense of the cam's turn", "mm": "mm", "rpm_unit": "rpm",
           "phase_symbols": "φ_{rise}; φ_{far}; φ_{return}; φ_{near}", "allowed_symbols": "[ϑ]_{rise}; [ϑ]_{return}"},
}
SIZES = ((3.5, 10.0), (3.5, 9.0), (3.5, 8.0), (3.5, 7.0), (2.5, 8.0), (2.5, 7.0), (2.5, 6.0))   # (lettering, row) mm, largest first
WIDTHS = [60.0, 24.0, 30.0]


def given_rows(cam: Cam, doc: dict, lang: str) -> list[list[str]]:
    """The given data a row each (quantity, symbol with its unit, value), as the scene gives them: the
    offset "auto" said as the rule that chooses it, the base radius only where the scene gives it."""
    w, r = WORDS[lang], REPORT[lang]
    n = lambda x: num(x, lang, 4).replace("-", "−")            # noqa: E731  a true minus
    mm = w["mm"]
    kind = f"{w['kinds'][cam.follower]}, {w['roller'] if cam.roller > 0 else w['knife']}"
    rows = [w["head"], [w["follower"], "—", kind]]
    if cam.rocking:
        rows += [[w["swing"], "ψ_{max}, °", n(doc["swing_deg"])], [w["arm"], f"l, {mm}", n(cam.arm * 1000)],
                 [w["centre"], f"a, {mm}", n(cam.centre_distance * 1000)]]
    else:
        rows += [[w["stroke"], f"h, {mm}", n(cam.stroke * 1000)],
                 [w["offset"], f"e, {mm}", w["auto"] if cam.offset is None else n(cam.offset * 1000)]]
    if cam.roller > 0:
        rows.append([w["radius"], f"r, {mm}", n(cam.roller * 1000)])
    if cam.base_radius is not None:
        rows.append([w["base"], f"R_0, {mm}", n(cam.base_radius * 1000)])
    rows += [[w["phases"], w["phase_symbols"] + ", °", "; ".join(n(p) for p in cam.phases)],
             [w["law_rise"], "—", r["laws"][cam.laws[0]]], [w["law_return"], "—", r["laws"][cam.laws[1]]],
             [w["allowed"], w["allowed_symbols"] + ", °", "; ".join(n(a) for a in cam.allowed)],
             [w["rpm"], f"n, {w['rpm_unit']}", n(cam.omega * 30.0 / 3.141592653589793)],
             [w["sense"], "—", r["sense"][doc["sense"]]]]
    return rows


def given_table(cam: Cam, doc: dict, lang: str, size: float, row_h: float, number: int = 1,
                span: float | None = None) -> Record:
    """The given data ruled as the sheet's tables are (form.table): the quantity's words from the left,
    the symbols centred, the values from the left (words and numbers mixed); ``span``: its columns
    widened in proportion to that width (the width of the table of the divisions under it)."""
    from graphplan.graphic.record import text_width
    rows = given_rows(cam, doc, lang)
    # a left-aligned column a reader's gap wider than its widest cell (a lowered index, «R₀», by the rule)
    widths = [max(w, max(text_width(r[c], size) for r in rows) + 4.0) for c, w in enumerate(WIDTHS)]
    return table(rows, widths, row_h=row_h, size=size,
                 title=WORDS[lang]["title"].format(n=number), align=["start", "middle", "start"], span=span)


def renumbered(rec: Record, lang: str, old: int, new: int) -> Record:
    """``rec`` (a placed table) with its title's number ``old`` written ``new`` (the title's first line,
    same width: one digit for another)."""
    from dataclasses import replace
    head = ("Таблиця {n}." if lang == "uk" else "Table {n}.")
    a, b = head.format(n=old), head.format(n=new)
    items = [replace(p, text=b + p.text[len(a):]) if p.kind == "text" and p.text.startswith(a) else p
             for p in rec.items]
    return Record(rec.title, items, dict(rec.scales))


def references_renumbered(rec: Record, lang: str, old: int, new: int) -> Record:
    """``rec`` (the placed notes) with its references to the table numbered ``old`` — «(табл. 1)»,
    «(Table 1)», the legend of «*» — written ``new``: the given data, read first, take Table 1 and the
    table of the divisions its δ and ϑ cells are starred in becomes Table 2 (stop 62: CAM62's legend
    «* — похибка δ понад 5 % (табл. 1)» pointed at the given data, its starred −7,37* in Table 2)."""
    from dataclasses import replace
    pairs = [(f"табл. {old})", f"табл. {new})"), (f"Table {old})", f"Table {new})")]
    a, b = pairs[0] if lang == "uk" else pairs[1]
    items = [replace(p, text=p.text.replace(a, b)) if p.kind == "text" and a in (p.text or "") else p
             for p in rec.items]
    out = Record(rec.title, items, dict(rec.scales))
    for key, value in vars(rec).items():       # what a notes record carries besides (parts, theta_at)
        if key not in ("title", "items", "scales"):
            setattr(out, key, value)
    return out


def tab_size(rec: Record) -> float:
    """The letter height of a placed table's cells (its body's lettering, under its 3.5-mm title)."""
    sizes = [p.size for p in rec.items if p.kind == "text" and p.layer == "tables"]
    return sorted(sizes)[len(sizes) // 2] if sizes else 3.5


ROWS = (10.0, 9.0, 8.5, 8.0, 7.5, 7.0)     # mm: Table 2's rows tried, tallest first, with the given data's alike


def with_given(page: list[Placed], cam: Cam, doc: dict, lang: str, rebuild=None) -> list[Placed]:
    """The A1 sheet's placed drawings with the given data in the room between the profile and Table 1
    (the profile's box narrowed to its own ink and a GAP), left-aligned with Table 1 and a GAP above
    its title, lettered as the table of the divisions (then Table 2) is: where the room is too low,
    that table's rows made shorter (``rebuild(row_h, size, span)``: it again at those rows, its foot
    where it stood by the title block), both tables in rows alike (ROWS, down to 7 mm); else at the
    largest smaller lettering of SIZES that fits; else both tables at that smaller lettering in rows
    alike (Table 2 rebuilt: the uk sheet's Table 2 larger than the en one's must not drop the given
    data); ``page`` as it is where none fits."""
    prof = next((p for p in page if p.name == "profile"), None)
    tab = next((p for p in page if p.name == "table"), None)
    if prof is None or tab is None:
        return page
    pb, tb = prof.record.bounds(), tab.record.bounds()
    x0, x1 = tb[0], max(prof.box[2], tb[2])
    size = tab_size(tab.record)
    tries = [(None, size, row) for row in ROWS] if rebuild is None else [(row, size, row) for row in ROWS]
    tries += [(None, s, r) for s, r in SIZES if s < size - 1e-9]
    if rebuild is not None:     # then both tables at a smaller lettering, in rows alike (review 57 #6: the
        # uk sheet's Table 2 at 3.5 mm in 7.5-mm rows left 91 mm for the given data's 96 and dropped it,
        # where the en sheet's, at 2.5 mm, kept it: one scene's two languages carry the same tables)
        for s in sorted({s for s, _ in SIZES if s < size - 1e-9}, reverse=True):
            tries += [(row, s, row) for row in sorted(set(ROWS) | {r for t, r in SIZES if t == s}, reverse=True)]
    for row2, s, row in tries:
        table2 = tab.record
        if row2 is not None:
            table2 = rebuild(row2, s, tb[2] - tb[0])
            b2 = table2.bounds()
            if b2[2] - b2[0] > x1 - x0 + 1e-9 or collisions(table2):     # a lowered index on a closer rule
                continue
            table2 = table2.moved(tb[0] - b2[0], tb[1] - b2[1])       # its foot where it stood
        t2 = table2.bounds()
        top, floor = pb[1] - GAP, t2[3] + GAP      # the room: under the profile's ink, over Table 2's title
        # as wide as Table 2 under it (stop 57: 162 mm over a 248-mm Table 2 left 86 × 108 mm blank
        # in the profile's column, over the title block)
        rec = given_table(cam, doc, lang, s, row, span=min(t2[2] - t2[0], x1 - x0))
        b = rec.bounds()
        w, h = b[2] - b[0], b[3] - b[1]
        if w > x1 - x0 + 1e-9 or h > top - floor + 1e-9 or collisions(rec):
            continue
        rec = rec.moved(x0 - b[0], floor - b[1])
        box = (x0, floor - GAP / 2, x0 + w, floor + h + GAP / 2)
        out = []
        for p in page:
            if p is prof:
                out.append(Placed(p.name, p.record, (p.box[0], pb[1] - GAP / 2, p.box[2], p.box[3])))
            elif p is tab:
                out.append(Placed(p.name, renumbered(table2, lang, 1, 2),
                                  (p.box[0], p.box[1], p.box[2], min(p.box[3], t2[3] + GAP / 2))))
            elif p.name == "notes":
                out.append(Placed(p.name, references_renumbered(p.record, lang, 1, 2), p.box))
            else:
                out.append(p)
        return out + [Placed("given", rec, box)]
    return page
