"""The fourth sheet, «Синтез кулачкового механізму» (cam synthesis): the law's diagrams integrated by
chords, the phase diagram with the smallest base radius, the profile by inversion, the table of the
divisions (graphical beside exact, with the percent errors) and the notes — composed in zones like the
other sheets: the drawings in a row in reading order, the table and the notes beside the title block;
a format too small carries the rest to further sheets of the set."""
from __future__ import annotations

import math

from graphplan.drawing.cam import records, scale_text, symbols
from graphplan.drawing.layout import GAP, Box, Leaf, Placed, Stack, centred, extent, flow
from graphplan.exact.cam import solve
from graphplan.graphic.cam import POLE_MM, closing_warning, construct, phase_drawn_at
from graphplan.graphic.record import Record
from graphplan.model.cam import Cam
from graphplan.report.cam import cam_json, short_note, short_ordinates, table_columns, table_rows
from graphplan.sheets.compose import (Sheet, SheetOptions, captioned, compose, drawing_scale, field_of, keep_out,
                                      later_keep, note_block)
from graphplan.sheets.form import Form, table
from graphplan.sheets.kinematics import TITLE
from graphplan.util.errors import GraphplanError, said_error
from graphplan.util.markup import escape
from graphplan.util.words import num

WORDS = {
    "uk": {"subtitle": "Синтез кулачкового механізму", "diagrams": "Діаграми {a}, {v}, {s} (графічне "
           "інтегрування методом хорд)", "phase": "Фазова діаграма {s}({v}), найменший R_0",
           "phase_given": "Фазова діаграма {s}({v}), найменший і заданий R_0",
           "phase_taken": "Фазова діаграма {s}({v}), найменший і прийнятий R_0",
           "profile": "Профіль кулачка (метод обернення руху)",
           "av": "Діаграми {a}, {v} (графічне інтегрування методом хорд)",
           "s": "Діаграма {s} (хорди паралельні променям з полюса P_2 діаграми {v})", "table": "Таблиця 1. Переміщення, аналог "
           "швидкості й кут тиску в точках поділу", "n": "№"},
    "en": {"subtitle": "Cam synthesis", "diagrams": "Diagrams {a}, {v}, {s} (graphical integration by "
           "chords)", "phase": "Phase diagram {s}({v}), smallest R_0",
           "phase_given": "Phase diagram {s}({v}), smallest and given R_0",
           "phase_taken": "Phase diagram {s}({v}), smallest and taken R_0",
           "profile": "Cam profile (by inversion)",
           "av": "Diagrams {a}, {v} (graphical integration by chords)",
           "s": "Diagram {s} (its chords parallel to the rays from the pole P_2 of {v})", "table": "Table 1. Displacement, velocity analogue and "
           "pressure angle at the divisions", "n": "No."},
}


def _fields(cam: Cam, lang: str) -> dict[str, str]:
    meta = dict(cam.meta)
    from graphplan.sheets.compose import organisation, sheet_field
    org = organisation(meta, lang)
    from graphplan.util.romanize import scene_text
    return {"designation": escape(scene_text(meta, "designation", lang)), "title": escape(cam.title_in(lang)),
            "student": escape(sheet_field(meta, "student", lang)), "teacher": escape(sheet_field(meta, "teacher", lang)),
            "organisation": escape(org), "scale": "", "sheet": "1", "sheets": "1",
            "subtitle": WORDS[lang]["subtitle"]}


def positions_table(doc: dict, lang: str, row_h: float = 6.0, size: float = 2.5, span: float | None = None
                    ) -> Record:
    """Per division: φ, s and ds/dφ exact, their ordinates y as the ruler reads them (mm) and the
    graphical values from them, each to its exact value's decimals, with δ worked out from the two
    printed numbers (report.cam ``table_columns``), ϑ exact and measured, R exact and measured (mm); ds/dφ per radian of the cam's turn (мм/рад; rocking ψ in ° and dψ/dφ in °/рад, the
    unit of its scale μ_{dψ/dφ} in (°/рад)/мм)."""
    rocking = doc["follower"] == "rocking"
    key = "_deg" if rocking else "_m"
    k = 1.0 if rocking else 1000.0                      # a translating follower's s in mm
    unit = "°" if rocking else ("мм" if lang == "uk" else "mm")
    per = unit + "/" + ("рад" if lang == "uk" else "rad")     # the analogue: per radian of the cam's turn
    gr = "гр." if lang == "uk" else "gr."
    q = symbols(rocking)                               # rocking: ψ, dψ/dφ (an angle is not s)
    mm = "мм" if lang == "uk" else "mm"
    head = [WORDS[lang]["n"], "φ, °", f"{q['s']}, {unit}", f"y_{{{q['s']}}}, {mm}", f"{q['s']} {gr}", f"δ_{q['s']}, %",
            f"{q['v']}, {per}", f"y_{{{q['v']}}}, {mm}", f"{q['v']} {gr}", f"δ_{{{q['v']}}}, %",   # stop 51: δ_ψ beside a bare δ
            "ϑ, °", f"ϑ {gr}", "R, " + mm, f"R {gr}"]
    cols = table_columns(doc, lang)          # the terminal's table cell for cell (report.cam)
    keys = ("phi", "s", "s_mm", "s_gr", "ds", "v", "v_mm", "v_gr", "dv", "theta", "theta_gr", "R", "R_gr")
    ps = doc["positions"]
    rows = [head] + [[str(ps[j].get("number", j))] + [cols[c][j] for c in keys] for j in table_rows(doc)]
    widths = [7.0, 11.0, 15.0, 11.0, 13.0, 13.0, 21.0, 12.0, 16.0, 13.0, 11.0, 11.0, 14.0, 13.0]
    return table(rows, widths, row_h=row_h, size=size, title=WORDS[lang]["table"], span=span, clear_header=True)


def notes(doc: dict, lang: str, cam: Cam) -> list[str]:
    """The data, the base radius exact and measured, the largest pressure angles, the curvature, the
    scales, the closing of s and the warnings, as the terminal says them (report.cam), typeset."""
    from graphplan.report.cam import angles_over, cam_lines
    lines = cam_lines(doc, lang)
    w = doc["warnings_uk"] if lang == "uk" else doc["warnings"]
    # a given R0 below the smallest: the R0 line says it with the radius to take (radius_small), not twice
    w = [x for x in w if not (doc.get("base_radius_given") and x.startswith(("радіус основної шайби", "the base radius")))]
    lines += [("Попередження: " if lang == "uk" else "Warning: ") + escape(x) for x in w]
    cols = table_columns(doc, lang)          # a "*" in Table 1 (δ worked out from its printed values)
    marked = any(c.endswith("*") for c in cols["ds"] + cols["dv"])
    if short_ordinates(doc):
        lines.append(short_note(doc, lang))
    # «*» means two things on this sheet: an error δ past 5 % (Table 1's δ columns) and a pressure angle past
    # its allowed one (the notes' angles, ϑ(φ)'s peak letter, Table 1's ϑ cells): the legend says each meaning
    # that occurs (review 58 #5: only the 5 % was said, under «32,81°*»), pointing at Table 1 — the sheet's only
    # table (review 60 #5: «(табл. 2)» pointed at a table no cam sheet has)
    said = []
    if marked:
        said.append("похибка δ понад 5 % (табл. 1): коротка ордината (кілька мм) або мало поділок"
                    if lang == "uk" else "an error δ past 5 % (Table 1): a short ordinate (a few mm) or few divisions")
    if angles_over(doc):
        rows = any(c.endswith("*") for c in cols["theta"] + cols["theta_gr"])      # Table 1 named where it stars one
        said.append(("кут тиску понад допустимий [ϑ]" if lang == "uk" else "a pressure angle past the allowed [ϑ]")
                    + ((" (табл. 1)" if lang == "uk" else " (Table 1)") if rows else ""))
    if said:
        lines.append("* — " + "; ".join(said))
    return lines


FIELD_W = 816.0          # an A1 field's width (841 − 20 − 5 mm); smaller formats wrap the notes the same
SIZES = (1.0, 1.1, 1.2, 1.3, 1.4, 1.5, 1.6, 1.7, 1.8, 1.9, 2.0, 2.2, 2.4, 2.6, 2.8, 3.0, 3.3, 3.6, 4.0)


def _captions(g, cam: Cam, lang: str) -> dict[str, tuple[str, str]]:
    """Each drawing's caption and its second line, the drawing's scales."""
    w = WORDS[lang]
    mm = "мм" if lang == "uk" else "mm"
    num_ = lambda x: num(x, lang, 4)                                             # noqa: E731
    first = f"{scale_text('mu_phi', g.mu_phi, cam.rocking, lang)}; H_1 = {num_(g.H1)} {mm}, H_2 = {num_(g.H2)} {mm}"
    if cam.rocking:
        mu_ph = g.mu_phase or g.mu_l
        phase = (f"{scale_text('mu_l', mu_ph, True, lang)} "
                 + ("(коромисло і дуги l·ψ" if lang == "uk" else "(the arm and the arcs l·ψ")
                 + (f", M {drawing_scale(mu_ph, lang)})" if g.mu_phase else ")"))
    else:
        phase = scale_text("mu_s", g.mu_s, False, lang)
    profile = f"{scale_text('mu_l', g.mu_l, cam.rocking, lang)} (M {drawing_scale(g.mu_l, lang)})"
    q = symbols(cam.rocking)
    second = f"{scale_text('mu_phi', g.mu_phi, cam.rocking, lang)}; H_2 = {num_(g.H2)} {mm}"
    # a given R0: O is drawn at it, not at the smallest (review 57: the caption named the smallest alone)
    # R0 taken over the smallest read (rounded up): O and O_min both drawn (review 59 #4: «найменший R₀» alone
    # under O drawn at the taken 34 mm, O_min unlettered 3 mm above it)
    taken = math.isfinite(g.R0_drawn) and abs(g.R0 - g.R0_drawn) > 1e-9
    phase_cap = w["phase_given" if cam.base_radius is not None else "phase_taken" if taken else "phase"].format(**q)
    return {"diagrams": (w["diagrams"].format(**q), first), "phase": (phase_cap, phase),
            "profile": (w["profile"], profile), "av": (w["av"].format(**q), first), "s": (w["s"].format(**q), second)}


PRESSURE_PART = 0.6     # ϑ(φ)'s span (its curve and the bands ±[ϑ]) at most this part of the stroke drawn


def pressure_below(sol, g, lang: str, mu_theta: float | None = None) -> Record:
    """The pressure angle's diagram ϑ(φ) captioned, at the diagrams' μ_φ (review 11, mark 16: drawn
    at its own 2.5 °/mm beside the diagrams' 0.79 °/mm, its divisions did not line up with theirs),
    its φ origin at theirs (x = 0 in both records), ϑ at the finest standard μ_ϑ whose span is at most
    PRESSURE_PART of the stroke drawn (so it grows and shrinks with the diagrams the sizing tries), or
    at ``mu_theta`` (°/mm)."""
    import numpy as np

    from graphplan.drawing.cam import PRESSURE_NAMES, pressure_diagram, pressure_scales
    mm = "мм" if lang == "uk" else "mm"
    stroke = float(np.max(np.abs(g.s_mm))) if len(g.s_mm) else 40.0
    _, mu_t = pressure_scales(sol, 240.0, PRESSURE_PART * stroke + 18.0)     # 18 mm: pressure_scales' letters
    mu_t = mu_theta or mu_t
    second = f"{scale_text('mu_phi', g.mu_phi, sol.cam.rocking, lang)}; μ_ϑ = {num(mu_t, lang, 4)} °/{mm}"
    return captioned(pressure_diagram(sol, g, lang, g.mu_phi, mu_t), PRESSURE_NAMES[lang], second)


def with_theta(diagrams: Record, pressure: Record | None, flush: bool = False) -> Record:
    """The captioned diagrams with ϑ(φ) (pressure_below, captioned) under them, a GAP clear, their φ
    origins on one vertical (the same μ_φ: a division reads straight down); ``flush``: ϑ(φ)'s left
    edge at the record's (the notes with ϑ(φ) under them); ``theta_at``: the index of ϑ(φ)'s first
    item (apart places it as its own drawing)."""
    if pressure is None:
        return diagrams
    dy = diagrams.bounds()[1] - GAP - pressure.bounds()[3]
    dx = diagrams.bounds()[0] - pressure.bounds()[0] if flush else 0.0
    out = Record(diagrams.title, list(diagrams.items) + pressure.moved(dx, dy).items, dict(diagrams.scales))
    out.scales.update({k: v for k, v in pressure.scales.items() if k not in out.scales})   # the same μ_φ
    out.theta_at = len(diagrams.items)
    return out


def beside(diagrams: Record, phase: Record, caps: dict, rocking: bool = False, pressure: Record | None = None
           ) -> Record:
    """The diagrams and, to their right, the phase diagram at the same height — its s axis lined up
    with the s diagram's (both at μ_s: the point C0 of s = 0 level with the s diagram's φ axis, so a
    value of s reads straight across) —, each with its caption: one drawing on the sheet. A rocking
    follower's phase diagram is drawn at the profile's μ_l (drawing.cam.phase_scale), not at μ_ψ: no
    value reads across, and it stands level with the diagrams' top, the room under it (hole) to the
    notes and the pressure angle's diagram (it hung from the ψ axis over a blank 100 mm high)."""
    left = with_theta(captioned(diagrams, *caps["diagrams"]), pressure)
    right = captioned(phase, *caps["phase"])
    axis = next(q for q in diagrams.items if q.step == "axis s")
    start = next(q for q in phase.items if q.step == "R0")
    dy = axis.points[0][1] - start.points[1][1]
    if rocking:
        dy = left.bounds()[3] - right.bounds()[3]
    dx = left.bounds()[2] + 2 * GAP - right.bounds()[0]
    out = Record("cam diagrams", list(left.items) + right.moved(dx, dy).items, dict(left.scales))
    out.scales.update(phase.scales)
    out.hole = (left.bounds()[2] + 2 * GAP, right.bounds()[1] + dy)     # see hole()
    out.parts = len(left.items)                                          # see apart()
    out.theta_at = getattr(left, "theta_at", None)
    out.flush = True            # placed at the top left of its column (hole, place; cam_sizes sizes it centred first)
    return out


def apart(name: str, rec: Record, box: Box, page, n: int | None = None, theta_at: int | None = None
          ) -> list[Placed]:
    """A placed leaf; the diagrams with a leaf laid in the room under their phase diagram (hole) as
    two drawings — the s, ds/dφ, d²s/dφ² diagrams and the phase diagram — each in its own box, the
    boxes a GAP apart and clear of the room's leaf (no box holds another drawing); ``n``: how many of
    ``rec``'s items are the diagrams' (beside)."""
    if name in ("diagrams", "notes", "displacement") and theta_at is not None:   # ϑ(φ) under them (with_theta): its own box
        end = len(rec.items) if n is None else n
        theta = Record("pressure angle", rec.items[theta_at:end],
                       {k: rec.scales[k] for k in ("mu_phi", "mu_theta") if k in rec.scales})
        rest = Record(rec.title, rec.items[:theta_at] + rec.items[end:], dict(rec.scales))
        tb = theta.bounds()
        below = (tb[0] - GAP / 2, tb[1] - GAP / 2, tb[2] + GAP / 2, tb[3] + GAP / 2)
        parts = apart(name, rest, box, page, None if n is None else theta_at)
        b0 = parts[0].box
        parts[0] = Placed(name, parts[0].record, (b0[0], max(b0[1], below[3]), b0[2], b0[3]))
        return parts + [Placed("pressure", theta, below)]
    inside = [b for other, b in page if other.name != name and box[0] <= b[0] and b[2] <= box[2]
              and box[1] <= b[1] and b[3] <= box[3]]
    if name != "diagrams" or n is None or not inside:
        return [Placed(name, rec, box)]
    left = Record(rec.title, rec.items[:n], dict(rec.scales))
    right = Record("phase diagram", rec.items[n:], {})
    lb, pb = left.bounds(), right.bounds()
    xm = lb[2] + GAP
    # the phase diagram in the middle of the room right of the diagrams (at_top_left: the spare width there)
    right = right.moved(max(0.0, (xm + GAP + box[2]) / 2 - (pb[0] + pb[2]) / 2), 0.0)
    return [Placed(name, left, (box[0], box[1], xm, box[3])),
            Placed("phase", right, (xm, pb[1] - GAP / 2, box[2], box[3]))]


def at_top(rec: Record, box: Box) -> Record:
    """The record at the top of ``box``, in the middle across it (the A1 sheet's profile: the
    room its column leaves under it goes to Table 1, not to a band over it)."""
    x0, _, x1, y1 = rec.bounds()
    return rec.moved((box[0] + box[2]) / 2 - (x0 + x1) / 2, box[3] - y1)


def at_top_left(rec: Record, box: Box) -> Record:
    """The record at the top left of ``box`` (the A1 sheet's diagrams with the phase diagram beside them:
    the column's spare width goes to the room under the phase diagram — the notes and ϑ(φ) at the
    diagrams' μ_φ, so a finer μ_φ fits there —, not half of it to a blank strip left of the poles:
    stop 57's CAM57 49 mm, CAM55 36 mm; apart() centres the phase diagram over that room)."""
    x0, _, _, y1 = rec.bounds()
    return rec.moved(box[0] - x0, box[3] - y1)


def place(f: Form, leaf: Leaf, box: Box) -> Record:
    """A leaf's record in its box: on A1 the diagrams at the top left of their column (at_top_left, as
    hole() takes them), the profile at the top of its column (no band over it); else centred."""
    if f.name == "A1" and leaf.name == "diagrams" and getattr(leaf.record, "flush", False):
        return at_top_left(leaf.record, box)
    return (at_top if f.name == "A1" and leaf.name == "profile" else centred)(leaf.record, box)


def hole(dia: Leaf, box: Box) -> Box | None:
    """The room under the phase diagram beside the ds/dφ and d²s/dφ² diagrams (review 4, item 19:
    (375–570, 335–590) mm of the A1 sheet was blank) when the diagrams' leaf stands at the top of
    ``box`` (the column's spare height goes to that room, the notes and the pressure angle's diagram):
    from the diagrams' right edge to the box's, from the box's foot to a GAP under the phase diagram."""
    at = getattr(dia.record, "hole", None)
    if at is None:
        return None
    x0, y0, x1, y1 = dia.record.bounds()
    dx, dy = (box[0] - x0 if getattr(dia.record, "flush", False) else (box[0] + box[2]) / 2 - (x0 + x1) / 2,
              box[3] - y1)          # at the top (left: at_top_left, else at_top): the room under it
    return at[0] + dx, box[1], box[2], at[1] + dy - GAP


def own_sheet(leaf: Leaf, room: tuple[float, float] | None) -> Leaf:
    """``leaf`` as large as ``region`` (a set's field, above a later sheet's title block): nothing is
    flowed beside or under it — s keeps its sheet for ϑ(φ) and the phase diagram goes to the
    profile's (beside s it stood at 1:2, 40 mm, the profile alone on the next sheet)."""
    if room is None:
        return leaf
    return Leaf(leaf.name, max(room[0], leaf.w), max(room[1], leaf.h), leaf.record)


def sheet_room(region: Box, keep: Box) -> tuple[float, float]:
    """A set's field across and above the first sheet's title block (own_sheet), less a GAP."""
    return region[2] - region[0], region[3] - keep[3] - GAP


def _leaves(sol, g, cam: Cam, lang: str, drawn: dict | None = None, split: bool = False, column: bool = True,
            row: tuple[float, float] | None = None) -> tuple[list[Leaf], Leaf, Leaf, dict]:
    """The captioned drawings (none when ``drawn`` is {}): the diagrams with the phase diagram beside
    them (``split``, a set of sheets: each on its own) — ``column``: ϑ(φ) under the diagrams —, the
    profile; the table and the notes."""
    doc = cam_json(sol, g, cam.source or "")
    if drawn is None and split and g.split:     # s on a sheet of its own, after d²s/dφ² and ds/dφ (set_sizes)
        from graphplan.drawing.cam import diagrams, phase_diagram, profile_drawing
        drawn = {"av": diagrams(sol, g, lang, ("a", "v")), "s": diagrams(sol, g, lang, ("s",)),
                 "phase": phase_diagram(sol, g, lang), "profile": profile_drawing(sol, g, lang)}
    drawn = records(sol, g, lang) if drawn is None else drawn
    caps = _captions(g, cam, lang)
    leaves = []
    if drawn and split and "av" in drawn:
        leaves = [Leaf("diagrams", record=captioned(drawn["av"], *caps["av"])),
                  own_sheet(Leaf("displacement", record=captioned(drawn["s"], *caps["s"])), row)] + [
                  Leaf(name, record=captioned(drawn[name], *caps[name])) for name in ("phase", "profile")]
    elif drawn and split:
        leaves = [Leaf(name, record=captioned(drawn[name], *caps[name])) for name in ("diagrams", "phase", "profile")]
    elif drawn:
        leaves = [Leaf("diagrams", record=beside(drawn["diagrams"], drawn["phase"], caps, cam.rocking,
                                                 pressure_below(sol, g, lang) if column else None)),
                  Leaf("profile", record=captioned(drawn["profile"], *caps["profile"]))]
    tab = Leaf("table", record=positions_table(doc, lang))
    table_w = tab.record.bounds()[2] - tab.record.bounds()[0]
    # the notes between the table and the title block, their lines not longer than about 300 mm
    width = max(TITLE, min(300.0, FIELD_W - table_w - TITLE - 4 * GAP))
    nts = Leaf("notes", record=note_block(notes(doc, lang, cam), width))
    return leaves, tab, nts, doc


def columns(dia: Leaf, prof: Leaf, tab: Leaf, notes_at, region, keep) -> list[list[tuple[Leaf, Box]]] | None:
    """The A1 sheet's composition (review 2, item 11: a row of drawings over a band with only the
    table left half the sheet bare): the diagrams with the phase diagram beside them at the left over
    the field's whole height; at the right, in a column over the title block, the profile and under
    it Table 1 and the notes, by the title block — the notes, when the column has no room for them,
    at the foot of the left column beside the title block. ``notes_at(width)``: the notes' leaf
    wrapped to ``width`` mm. One sheet's leaves with their boxes, or None when they do not fit."""
    rx0, ry0, rx1, ry1 = region
    wr = max(prof.w, tab.w)
    xr = rx1 - wr                       # the right column's left edge
    xl = xr - GAP                       # the left column's right edge
    if xl - rx0 < dia.w - 1e-9:
        return None
    floor = keep[3] if xl > keep[0] else ry0        # the left column clear of the title block
    under = _notes_under(dia, prof, tab, notes_at, (rx0, floor, xl, ry1), (xr, keep[3], rx1, ry1))
    if under is not None:
        return under
    nr = notes_at(wr)
    if prof.h + tab.h + nr.h + 2 * GAP <= ry1 - keep[3] + 1e-9:
        nb = (xr, keep[3], xr + nr.w, keep[3] + nr.h)
        low = keep[3] + nr.h + GAP
        left_floor, nl = floor, nr
    else:
        nl = notes_at(xl - rx0)
        nb = (rx0, floor, rx0 + nl.w, floor + nl.h)
        low = keep[3]
        left_floor = floor + nl.h + GAP
    tb = (xr, low, xr + tab.w, low + tab.h)
    if tb[3] + GAP + prof.h > ry1 + 1e-9 or ry1 - left_floor < dia.h - 1e-9:
        return None
    return [[(dia, (rx0, left_floor, xl, ry1)), (prof, (xr, tb[3] + GAP, rx1, ry1)), (tab, tb), (nl, nb)]]


def _notes_under(dia: Leaf, prof: Leaf, tab: Leaf, notes_at, left: Box, right: Box):
    """The notes in the room under the phase diagram (hole) when they fit it, Table 1 then by the
    title block under the profile in the right column: the notes read under the phase diagram they
    follow, and neither the middle nor the right column keeps a blank as large as the notes."""
    room = hole(dia, left) if left[3] - left[1] >= dia.h - 1e-9 else None
    if room is None or room[2] - room[0] < 120.0:
        return None
    nts = notes_at(room[2] - room[0])
    if nts.h > room[3] - room[1] + 1e-9 or nts.w > room[2] - room[0] + 1e-9 or tab.h + GAP + prof.h > right[3] - right[1] + 1e-9:
        return None
    tb = (right[0], right[1], right[0] + tab.w, right[1] + tab.h)
    nb = (room[0], room[3] - nts.h, room[0] + nts.w, room[3])
    return [[(dia, left), (prof, (right[0], tb[3] + GAP, right[2], right[3])), (tab, tb), (nts, nb)]]


def _notes_at(doc: dict, lang: str, cam: Cam, memo: dict | None = None, theta: Record | None = None):
    """The notes' leaf wrapped to a width (columns), remembered by the width to 1 mm; with ``theta``
    (pressure_below) ϑ(φ) under them (with_theta: one leaf, placed as two drawings)."""
    memo = {} if memo is None else memo
    lines = notes(doc, lang, cam)

    def at(width: float) -> Leaf:
        key = (lang, math.floor(width + 1e-9), id(theta))      # never wider than asked (the box holds it)
        if key not in memo:
            memo[key] = Leaf("notes", record=with_theta(note_block(lines, float(key[1])), theta, flush=True))
        return memo[key]
    return at


def _theta_in_hole(laid) -> bool:
    """Whether a laid-out A1 sheet has ϑ(φ) with the notes in the room under the phase diagram."""
    if not _one_sheet(laid):
        return False
    boxes = {leaf.name: b for leaf, b in laid[0]}
    notes_ = next((leaf for leaf, _ in laid[0] if leaf.name == "notes"), None)
    return (notes_ is not None and getattr(notes_.record, "theta_at", None) is not None
            and {"diagrams", "notes"} <= set(boxes) and _in_hole(boxes))


def _arranged(sol, g, cam: Cam, lang: str, f: Form, hole: bool = True) -> tuple:
    """(leaves, table, notes, doc, layout, notes_at) of the sheet: on A1 ϑ(φ) at the diagrams' μ_φ
    under the notes in the room under the phase diagram where it fits there (``hole``; the room stood
    blank with ϑ(φ) under the diagrams: review 11's A1 46 % empty); else under the diagrams, their φ
    origins on one vertical (with_theta)."""
    if hole and f.name == "A1":
        leaves, tab, nts, doc = _leaves(sol, g, cam, lang, column=False)
        notes_at = _notes_at(doc, lang, cam, theta=pressure_below(sol, g, lang))
        laid = _laid(f, leaves, tab, nts, notes_at)
        if _theta_in_hole(laid):
            return leaves, tab, nts, doc, laid, notes_at
    leaves, tab, nts, doc = _leaves(sol, g, cam, lang)
    notes_at = _notes_at(doc, lang, cam)
    return leaves, tab, nts, doc, _laid(f, leaves, tab, nts, notes_at), notes_at


def _laid(f: Form, leaves: list[Leaf], tab: Leaf, nts: Leaf, notes_at=None):
    """The leaves laid on sheets of ``f``: on A1 in columns when they fit so, else (and on the
    smaller formats) flowed in rows — the drawings in a row, the table and the notes under them."""
    region, keep = field_of(f), keep_out(f)
    if f.name == "A1" and notes_at is not None and [leaf.name for leaf in leaves] == ["diagrams", "profile"]:
        laid = columns(leaves[0], leaves[1], tab, notes_at, region, keep)
        if laid is not None:
            return laid
    return flow([leaves, [tab, nts]], region, keep)


def _one_sheet(laid) -> bool:
    """The drawings on one sheet and in one row (the reading order of LAYOUT.md's cam sheet)."""
    if laid is None or len(laid) != 1:
        return False
    tops = {round(b[3], 6) for leaf, b in laid[0] if leaf.name in ("diagrams", "profile")}
    return len(tops) == 1


def cam_sizes(sol, f: Form, n: int | None = None, precision: float = 0.5
              ) -> tuple:
    """The construction's sizes on ``f`` (construct's ``size``, ``profile_size``, ``height``,
    ``accel``): the largest common size whose drawings (at the standard scales that size asks) fit the
    sheet in one row above the table and the notes — in both languages —, then the profile, the main
    drawing, then the diagrams' ordinates grown while they fit, then the d²s/dφ² and ds/dφ
    diagrams alone (μ_s kept) into the height left. The scales of the series, as a set's (construct's
    ``series``; issue 32: the A1 sheet printed μ_s = 0,0002511 м/мм, μ_φ = 0,02014 рад/мм), μ_φ in
    °/mm or rad/mm (graphic.cam.series_phi: 0,02 рад/мм where 1 °/mm is too long and 2 °/mm half
    the zone); the tuple's seventh item says so. When nothing fits one sheet: a set of sheets, each
    drawing on its own (set_sizes)."""
    region = field_of(f)

    from graphplan.drawing.cam import diagrams, phase_diagram, profile_drawing
    memo: dict = {}
    fixed_: dict = {}                      # the table's and the notes' sizes: the same at every size
    wrapped: dict = {}                     # the notes wrapped to a column's width (A1), by language
    tables: dict = {}                      # Table 1's larger sizes (_rows_of_8), by language

    def drawing(name, draw, key, g):
        if (name, key) not in memo:        # each drawing depends on its own scales only
            memo[(name, key)] = draw(sol, g, "en")   # the longer phase names
        return memo[(name, key)]

    hole = [f.name == "A1"]                # ϑ(φ) under the notes (_arranged) while the sizes allow it
    flush = [False]                        # the diagrams centred in their column while the sizes are chosen,
    # then at its left (as the sheet places them): the spare width to the room under the phase diagram

    def theta(g, lang):
        if ("pressure", g.mu_phi, g.mu_s, lang) not in memo:
            memo[("pressure", g.mu_phi, g.mu_s, lang)] = pressure_below(sol, g, lang)
        return memo[("pressure", g.mu_phi, g.mu_s, lang)]

    def leaf(name, key, g, lang):
        column = not hole[0]
        if (name, key, lang, column, flush[0]) not in memo:
            caps = _captions(g, sol.cam, lang)
            if name == "diagrams":
                rec = beside(drawing("diagrams", diagrams, key[:5], g), drawing("phase", phase_diagram, (key[2], key[5]), g),
                             caps, sol.cam.rocking, theta(g, lang) if column else None)
                rec.flush = flush[0]
            else:
                rec = captioned(drawing(name, profile_drawing, key, g), *caps[name])
            memo[(name, key, lang, column, flush[0])] = Leaf(name, record=rec)
        return memo[(name, key, lang, column, flush[0])]

    def notes_at(g, lang):
        if not hole[0]:
            return wrapped[lang]
        if ("notes", g.mu_phi, g.mu_s, lang) not in memo:
            memo[("notes", g.mu_phi, g.mu_s, lang)] = _notes_at(docs[lang], lang, sol.cam, theta=theta(g, lang))
        return memo[("notes", g.mu_phi, g.mu_s, lang)]

    def fits(size: float, prof: float, height: float, accel: float | None = None, largest: bool = False,
             poles: tuple = (None, None)) -> bool:
        g = construct(sol, n, precision, size=size, profile_size=prof, height=height, measure=False, accel=accel,
                      H1=poles[0], H2=poles[1], series="rad")
        for lang in ("uk", "en"):
            leaves = [leaf("diagrams", (g.mu_phi, g.mu_a, g.mu_s, g.H1, g.H2, g.mu_l), g, lang),
                      leaf("profile", (g.mu_l,), g, lang)]
            laid = _laid(f, leaves, *fixed_[lang], notes_at(g, lang))
            if not (_theta_in_hole(laid) if hole[0] else _one_sheet(laid)):
                return False
        if largest and f.name == "A1":     # the columns give the phase diagram room to outgrow the profile: it may not
            return _profile_largest(drawing("profile", profile_drawing, (g.mu_l,), g).bounds(),
                                    drawing("phase", phase_diagram, (g.mu_s, g.mu_l), g).bounds())
        return True
    g0 = construct(sol, n, precision, measure=False, series="rad")
    docs: dict = {}
    for lang in ("uk", "en"):              # the table and the notes alone higher than the field: a set
        _, tab, nts, doc = _leaves(sol, g0, sol.cam, lang, {})
        fixed_[lang] = [Leaf("table", *extent(tab)), Leaf("notes", *extent(nts))]
        tables[lang] = [Leaf("table", *extent(Leaf("table", record=positions_table(doc, lang, row, size))))
                        for size, row in TABLE_SIZES]
        wrapped[lang] = _notes_at(doc, lang, sol.cam)
        docs[lang] = doc
        if max(leaf.h for leaf in fixed_[lang]) > region[3] - region[1]:
            return set_sizes(sol, f, n, precision)
    if hole[0] and not fits(1.0, 1.0, 1.0):
        hole[0] = False                    # no room for ϑ(φ) under the notes: under the diagrams
    if not fits(1.0, 1.0, 1.0):
        return set_sizes(sol, f, n, precision)
    k = _largest(lambda x: fits(x, x, x), list(SIZES)) or 1.0
    rest = [x for x in SIZES if x > k]
    kp = (_largest(lambda x: fits(k, x, k), rest) if rest else None) or k      # the main drawing first
    # the ordinates grown (μ_s: the profile kept the largest drawing, the columns would let the phase
    # diagram outgrow it), then d²s/dφ² alone (μ_s kept, the phase diagram as it is)
    kh = (_largest(lambda x: fits(k, kp, x, None, True), rest) if rest else None) or k
    up = [x for x in SIZES if x > kh]
    ka = (_largest(lambda x: fits(k, kp, kh, x), up) if up else None) or kh
    if f.name == "A1":       # the columns leave the diagrams the field's height: a step less along φ
        k, kh, ka = _taller(k, kp, kh, ka, fits, lambda *sz: _area(leaf, sol, n, precision, *sz))
        # then the abscissa alone longer (the ordinates' scales as they are) while the drawings fit:
        # drawn over the working angle only, the diagrams leave their column's width part blank
        longer = [x for x in SIZES if x > k]
        k = (_largest(lambda x: fits(x, kp, kh, ka, True), longer) if longer else None) or k
    g = construct(sol, n, precision, size=k, profile_size=kp, height=kh, measure=False, accel=ka, series="rad")
    h1, h2 = _poles(g.H1, g.H2, lambda p: fits(k, kp, kh, ka, False, p)) if f.name == "A1" else (None, None)
    if f.name == "A1":
        # the diagrams at the left of their column, as the sheet places them (at_top_left; stop 57:
        # centred, CAM57's left 49 mm blank left of the poles, CAM55's 36): the room under the phase
        # diagram, where the notes and ϑ(φ) at the diagrams' μ_φ stand, takes the column's spare width —
        # the abscissa longer once more where it then fits, kept where the s, ds/dφ, d²s/dφ² diagrams
        # (with their poles found again) cover WIDER more (the rule _taller keeps for a coarser μ_φ:
        # CAM57's 0,02 рад/мм drew them 10 % larger but its ds/dφ 37 % shorter, H_1 25 → 40 mm)
        flush[0] = True
        longer = [x for x in SIZES if x > k]
        k2 = (_largest(lambda x: fits(x, kp, kh, ka, True), longer) if longer else None) or k
        if k2 > k:
            g2 = construct(sol, n, precision, size=k2, profile_size=kp, height=kh, measure=False, accel=ka,
                           series="rad")
            p2 = _poles(g2.H1, g2.H2, lambda p: fits(k2, kp, kh, ka, False, p))
            if _drawn_area(leaf, sol, n, precision, k2, kp, kh, ka, p2) > WIDER * _drawn_area(
                    leaf, sol, n, precision, k, kp, kh, ka, (h1, h2)):
                k, (h1, h2) = k2, p2
    # (a rocking follower's ψ diagram is not made taller by a shorter H_2: at series scales μ_ψ is
    # the series' (kh), and a shorter H_2 would only coarsen μ_{dψ/dφ} and μ_{d²ψ/dφ²})
    # the trials reuse a drawing per scale; the finished drawings (their own points and letters, the
    # sheet's language) are measured once more, and the smallest size taken if they do not fit
    g = construct(sol, n, precision, size=k, profile_size=kp, height=kh, measure=False, accel=ka, H1=h1, H2=h2,
                  series="rad")
    for lang in ("uk", "en"):
        if not _one_sheet(_arranged(sol, g, sol.cam, lang, f, hole[0])[4]):
            return set_sizes(sol, f, n, precision)
    return k, kp, kh, ka, h1, h2, "rad"


def _poles(H1: float, H2: float, fits) -> tuple[float | None, float | None]:
    """The ds/dφ diagram alone taller where the field's height has room for it (review 4, item 19:
    the A1 column of diagrams 404 mm high in a field of 574): μ_{ds/dφ} = μ_{d²s/dφ²}·μ_φ·H_1 finer by
    a shorter pole distance H_1, H_2 longer by as much, so that μ_s = μ_{d²s/dφ²}·μ_φ²·H_1·H_2 stays
    (H_2 a whole millimetre, both within the lab's 15–50 mm: μ_s at most 2 % finer, never coarser). The
    shortest H_1 at which the drawings still fit (``fits((H1, H2))``); (None, None) when none does."""
    lo, hi = POLE_MM
    trials = []
    for h1 in range(int(H1) - 1, int(lo) - 1, -1):     # v grows as H_1 shortens
        h2 = float(math.floor(H1 * H2 / h1))            # μ_s not coarser… nor finer: the phase diagram as it is
        if h2 > hi or h1 * h2 < 0.98 * H1 * H2:
            continue
        trials.append((float(h1), h2))
    best = _largest(lambda t: fits(trials[int(t)]), list(range(len(trials))))
    return trials[best] if best is not None else (None, None)


def _profile_largest(p: Box, q: Box) -> bool:
    """Whether the profile (box ``p``) stays the sheet's largest drawing beside the phase diagram
    (``q``): larger in area (LAYOUT.md's cam sheet). Not also longer in its longest side, nor half as
    large again: the phase diagram, tall and narrow by nature (R_0 under the stroke at μ_s), was
    held under the profile's height, and the s–ds/dφ–d²s/dφ² diagrams tied to it by μ_s with it —
    a sheet 45 % empty (issue 32, item 1)."""
    pw, ph, qw, qh = p[2] - p[0], p[3] - p[1], q[2] - q[0], q[3] - q[1]
    return pw * ph > qw * qh


def _taller(k, kp, kh, ka, fits, area) -> tuple[float, float, float]:
    """The diagrams' abscissa one or two standard steps shorter (μ_φ coarser) when their ordinates
    then grow enough (μ_s, μ_{d²s/dφ²} finer) that the diagrams with the phase diagram cover more of
    the sheet: in the A1 columns they have the field's whole height but not its width (the profile's
    column beside them), and the ordinates alone widen them only by their poles."""
    best, best_area = (k, kh, ka), area(k, kp, kh, ka)
    lower = [x for x in SIZES if x < k][-2:]
    for k2 in reversed(lower):
        up = [x for x in SIZES if x > k2]
        kh2 = _largest(lambda x: fits(k2, kp, x, None, True), up) or k2
        more = [x for x in SIZES if x > kh2]
        ka2 = (_largest(lambda x: fits(k2, kp, kh2, x), more) if more else None) or kh2
        a2 = area(k2, kp, kh2, ka2)
        if fits(k2, kp, kh2, ka2) and a2 > 1.15 * best_area:     # worth a coarser μ_φ: 15 % more drawing
            best, best_area = (k2, kh2, ka2), a2
    return best


def _drawn_area(leaf, sol, n, precision, k, kp, kh, ka, poles) -> float:
    """The area (mm²) of the s, ds/dφ, d²s/dφ² diagrams alone (beside's first ``parts`` items) at these
    sizes and pole distances."""
    g = construct(sol, n, precision, size=k, profile_size=kp, height=kh, measure=False, accel=ka, H1=poles[0],
                  H2=poles[1], series="rad")
    rec = leaf("diagrams", (g.mu_phi, g.mu_a, g.mu_s, g.H1, g.H2, g.mu_l), g, "en").record
    b = Record(rec.title, rec.items[:rec.parts], {}).bounds()
    return (b[2] - b[0]) * (b[3] - b[1])


def _area(leaf, sol, n, precision, k, kp, kh, ka) -> float:
    """The area (mm²) of the diagrams with the phase diagram beside them at these sizes."""
    g = construct(sol, n, precision, size=k, profile_size=kp, height=kh, measure=False, accel=ka, series="rad")
    d = leaf("diagrams", (g.mu_phi, g.mu_a, g.mu_s, g.H1, g.H2, g.mu_l), g, "en")
    return d.w * d.h


# a set's μ_φ of the series in °/mm or rad/mm, the finer (graphic.cam.series_phi), as the A1 sheet's: in
# °/mm alone the A2 set's diagrams drew 240° at 1 °/mm, 240 mm of a 564 mm field, a third of their sheet
# blank beside them, where 0,01 рад/мм draws 419 mm (stop 49)
SET_SERIES = "rad"
SET_SIZES = (0.5, 0.55, 0.6, 0.65, 0.7, 0.75, 0.8, 0.85, 0.9, 0.95) + SIZES


LEGIBLE_MM = 25.0    # mm: the least tallest ordinate of s and of each phase's ds/dφ on a set's sheets


def _smallest_peak(sol, n: int | None, precision: float, sz: tuple) -> float:
    """The shortest of the read diagrams' tallest ordinates at the sizes ``sz`` (mm): the stroke drawn
    on s and each phase's extreme of ds/dφ — the ordinates Table 1 reads to half a ruler division."""
    import numpy as np
    g = construct(sol, n, precision, size=sz[0], profile_size=sz[1], height=sz[2], accel=sz[3], H1=sz[4],
                  H2=sz[5], measure=False, series=sz[6])
    return min(float(np.max(np.abs(g.s_mm))),
               *(float(np.max(np.abs(g.v_mm[g.phase == ph]))) for ph in (0, 1)))


def set_sizes(sol, f: Form, n: int | None = None, precision: float = 0.5) -> tuple:
    """A set's sizes (_set_sizes): the three diagrams on one sheet, or — where that draws s or a
    phase's ds/dφ under LEGIBLE_MM (50 ruler divisions: half a division 1 % of it; review 13 #7: the
    A3 set's rise of dψ/dφ 12.5 mm tall beside the A1's 52, Table 1 starring five errors the A1 sheet
    has not, while a set has sheets to spare) — d²s/dφ² and ds/dφ on one sheet and s on the next,
    where that draws them taller; the tuple's eighth item says which (True: apart)."""
    return _fewer_sheets(sol, f, n, precision, _set_choice(sol, f, n, precision))


def _set_choice(sol, f: Form, n: int | None, precision: float) -> tuple:
    """set_sizes' choice of the joint or the apart sizes, the profile at its largest scale."""
    joint = _set_sizes(sol, f, n, precision)
    together = _diagrams_fit_alone(sol, f, n, precision, joint)
    least = _smallest_peak(sol, n, precision, joint)
    if least >= LEGIBLE_MM and together:
        return joint + (False,)
    apart_ = _set_sizes(sol, f, n, precision, split=True)
    # the joint sizes where even the smallest left the three diagrams taller than a sheet (the rocking
    # cam's A3 set: 406 mm at the smallest size, the sheet refused) are no choice: apart
    return apart_ + (True,) if not together or _smallest_peak(sol, n, precision, apart_) > least else joint + (False,)


def set_sheets(sol, f: Form, n: int | None, precision: float, sz: tuple) -> int:
    """The number of sheets of ``f`` a set at the sizes ``sz`` (set_sizes) takes — the drawings each
    on its own, then Table 1 with the notes (kept_together, as _sheet_layout lays them before ϑ(φ),
    which never adds a sheet) —, the larger of the two languages; a large number where none lays out."""
    g = construct(sol, n, precision, size=sz[0], profile_size=sz[1], height=sz[2], accel=sz[3], H1=sz[4],
                  H2=sz[5], measure=False, series=sz[6])
    g.split = len(sz) > 7 and bool(sz[7])
    region, keep = field_of(f), keep_out(f)
    most = 0
    for lang in ("uk", "en"):
        leaves, tab, nts, doc = _leaves(sol, g, sol.cam, lang, split=True, row=sheet_room(region, keep))
        laid = kept_together(leaves, tab, notes(doc, lang, sol.cam), nts, region, keep, later_keep(f), g.split)
        if laid is None:
            return 1000
        most = max(most, len(laid))
    return most


def _fewer_sheets(sol, f: Form, n: int | None, precision: float, sz: tuple) -> tuple:
    """``sz`` with the profile at the next coarser standard μ_l where that takes the set a sheet fewer
    (set_sheets) — Table 1 and the notes then beside the profile, not on a sheet of their own: at
    2,5:1 OWN_CAM52's A2 profile left 190 mm beside it where the table needs 202, and the table took
    sheet 5 alone, 60 % blank (stop 52) —; else ``sz`` as it is. One step only: the profile, the main
    drawing, stays at the largest scale but one that fits its sheet alone."""
    if not (len(sz) > 7 and sz[7]):
        # ϑ(φ) not under s: its place is the table's sheet, and a sheet saved there lost it (stop 44's knife
        # cam's A2 set: two sheets, no ϑ(φ))
        return sz
    mu = construct(sol, n, precision, size=sz[0], profile_size=sz[1], height=sz[2], accel=sz[3],
                   measure=False, series=sz[6]).mu_l
    smaller = [x for x in SET_SIZES if x < sz[1]]
    coarser = [x for x in smaller
               if construct(sol, n, precision, size=sz[0], profile_size=x, height=sz[2], accel=sz[3],
                            measure=False, series=sz[6]).mu_l > mu * (1 + 1e-9)]
    if not coarser:
        return sz
    other = (sz[0], max(coarser), *sz[2:])
    # the profile still the largest drawing (LAYOUT.md's cam sheet; _profile_largest): CAM52's A3 set
    # saved its sheet with the profile at 1:2, 95 mm across beside a phase diagram of several times its area
    from graphplan.drawing.cam import phase_diagram, profile_drawing
    g = construct(sol, n, precision, size=other[0], profile_size=other[1], height=other[2], accel=other[3],
                  H1=other[4], H2=other[5], measure=False, series=other[6])
    if not _profile_largest(profile_drawing(sol, g, "en").bounds(), phase_diagram(sol, g, "en").bounds()):
        return sz
    return other if set_sheets(sol, f, n, precision, other) < set_sheets(sol, f, n, precision, sz) else sz


def _diagrams_fit_alone(sol, f: Form, n: int | None, precision: float, sz: tuple) -> bool:
    """Whether the three diagrams at the sizes ``sz`` (_set_sizes) stand on one sheet of ``f`` by
    themselves, in both languages."""
    g = construct(sol, n, precision, size=sz[0], profile_size=sz[1], height=sz[2], accel=sz[3], H1=sz[4],
                  H2=sz[5], measure=False, series=sz[6])
    return _stands_alone(sol, g, f, "diagrams")


def _stands_alone(sol, g, f: Form, name: str) -> bool:
    """Whether the drawing ``name`` of ``g`` ("diagrams", "phase", "profile"; "av": d²s/dφ² and ds/dφ,
    "s"), captioned, stands on one sheet of ``f`` by itself, clear of the title block, in both languages:
    the phase diagram and the profile stand on a later sheet, clear of its form 2a (stop 51: judged under
    form 1, CAM50's A3 profile was drawn at 1:2 where 1:1 stands on its sheet); the diagrams under form 1
    (s, on sheet 2, too: grown to that sheet's whole height it left ϑ(φ) no room under it, and ϑ went at
    4 °/мм under the profile)."""
    from graphplan.drawing.cam import diagrams, phase_diagram, profile_drawing
    draw = {"diagrams": diagrams, "phase": phase_diagram, "profile": profile_drawing,
            "av": lambda *a: diagrams(*a, ("a", "v")), "s": lambda *a: diagrams(*a, ("s",))}[name]
    region, keep = field_of(f), (later_keep(f) if name in ("phase", "profile") else keep_out(f))
    if name == "s":     # on its later sheet over ϑ(φ) at least PRESSURE_ROOM tall (pressure_by_displacement;
        # stop 53: with its own pole P2's ordinates under its axis, s judged under form 1 took the sheet
        # and ϑ(φ) went at 4 °/мм to the table's sheet)
        low = later_keep(f)
        keep = (low[0], low[1], low[2], max(keep[3], low[3] + _theta_room(sol) + 2 * GAP))
    for lang in ("uk", "en"):
        rec = captioned(draw(sol, g, lang), *_captions(g, sol.cam, lang)[name])
        laid = flow([[Leaf(name, *extent(Leaf(name, record=rec)))]], region, keep)
        if laid is None or len(laid) != 1:
            return False
    return True


UNDER_S_MU = 2.0      # °/mm: the μ_ϑ a set's s sheet leaves ϑ(φ) room for under s (the table's sheet's, CAM48 A3)
THETA_LETTERS = 32.0  # mm: ϑ(φ)'s letters above and below its range (pressure_scales' 18) and its two-line caption


def _theta_room(sol) -> float:
    """The height (mm) ϑ(φ) takes at UNDER_S_MU over its range and the bands ±[ϑ] (pressure_scales), at
    least PRESSURE_ROOM's."""
    import numpy as np
    cam = sol.cam
    rise, far, ret, _ = cam.phases
    theta = sol.at(np.linspace(0.0, rise + far + ret, 721))["theta"]
    span = max(float(np.max(theta)), max(cam.allowed)) - min(float(np.min(theta)), -max(cam.allowed))
    return max(PRESSURE_ROOM[1], span / UNDER_S_MU + THETA_LETTERS)


def _set_sizes(sol, f: Form, n: int | None = None, precision: float = 0.5, split: bool = False) -> tuple:
    """The construction's sizes when its drawings do not share one sheet of ``f`` (a set of sheets,
    the drawings each on its own — build_cam_sheet): the largest common size at which the diagrams and
    the phase diagram each fit a sheet's field by themselves (clear of the title block), then their
    ordinates, then d²s/dφ² alone, then the abscissa alone, and the profile, the main drawing, at the largest standard scale at
    which it fits a sheet alone — in both languages. (0.5, 0.5, 0.5, 0.5) when even that is too large.
    The scales of the series (construct's ``series``: μ_φ in °/mm or rad/mm, the finer — SET_SERIES —,
    μ_s standard, the poles whole millimetres); the tuple's seventh item says which."""
    from graphplan.drawing.cam import phase_diagram, profile_drawing
    region = field_of(f)
    memo: dict = {}

    def alone(name: str, g) -> bool:
        key = {"phase": (g.mu_s, g.mu_l), "profile": (g.mu_l,)}.get(name, (g.mu_phi, g.mu_a, g.mu_s, g.H1, g.H2))
        if (name, key) not in memo:
            memo[(name, key)] = _stands_alone(sol, g, f, name)
        return memo[(name, key)]

    def fits(size: float, prof: float, height: float, accel: float | None, names: tuple[str, ...],
             poles: tuple = (None, None)) -> bool:
        g = construct(sol, n, precision, size=size, profile_size=prof, height=height, measure=False, accel=accel,
                      series=SET_SERIES, H1=poles[0], H2=poles[1])
        return all(alone(name, g) for name in names)
    both = ("av", "s", "phase") if split else ("diagrams", "phase")
    sizes = list(SET_SIZES)
    k = _largest(lambda x: fits(x, x, x, None, both), sizes) or sizes[0]
    # then s (and ds/dφ) alone taller, d²s/dφ² as it is: the s ordinates, the ones the table's δ_s
    # reads, as large as the sheet allows (review 8, finding 11: 0.5 mm at division 1, δ_s +24.8 %,
    # where d²s/dφ² took the sheet's height); then d²s/dφ² into what is left
    # (at the abscissa the sheet allows: a short one asks short poles, d²s/dφ² the taller)
    up = [x for x in sizes if x > k]
    kl = (_largest(lambda x: fits(x, k, k, k, both), up) if up else None) or k
    ks = (_largest(lambda x: fits(kl, k, x, sizes[0], both), up) if up else None) or k
    ka = _largest(lambda x: fits(kl, k, ks, x, both), sizes) or sizes[0]
    up = [x for x in sizes if x > kl]        # the abscissa alone longer (the ordinates as they are)
    kl = (_largest(lambda x: fits(x, k, ks, ka, both), up) if up else None) or kl
    if not split:
        kl, ks, ka = _wider(sol, n, precision, sizes, (kl, k, ks, ka),
                            lambda x, h, a: fits(x, k, h, a, both))
    kp = _largest(lambda x: fits(kl, x, ks, ka, ("profile", "phase")), sizes) or sizes[0]

    def shared(size: float, prof: float, height: float, accel: float) -> bool:
        """Whether the phase diagram (a translating follower's at μ_s) and the profile share a sheet."""
        g = construct(sol, n, precision, size=size, profile_size=prof, height=height, measure=False,
                      accel=accel, series=SET_SERIES)
        for lang in ("uk", "en"):
            pair = [Leaf(name, *extent(Leaf(name, record=captioned(draw(sol, g, lang),
                                                                    *_captions(g, sol.cam, lang)[name]))))
                    for name, draw in (("phase", phase_diagram), ("profile", profile_drawing))]
            laid = flow([pair], region, later_keep(f))      # a later sheet's (the diagrams take the first)
            if laid is None or len(laid) != 1:
                return False
        return True
    if ks > k and not shared(kl, kp, ks, ka) and shared(kl, kp, k, ka):
        # a finer μ_s would give the phase diagram a sheet of its own, and the set a sheet more, half
        # blank: s as tall as keeps the two on one sheet (on a later sheet, under its form 2a — judged
        # under the first's title block, the two never shared one: review 44's knife cam's A2 set drew
        # its phase diagram alone on sheet 2, 78 % blank, 4 sheets)
        ks = next(x for x in reversed([x for x in sizes if k <= x < ks]) if shared(kl, kp, x, ka))
        ka = _largest(lambda x: fits(kl, k, ks, x, both), sizes) or sizes[0]
    h1, h2 = _legible_poles(sol, n, precision, (kl, kp, ks, ka), lambda p: fits(kl, kp, ks, ka, ("av",), p)) \
        if split else (None, None)
    return kl, kp, ks, ka, h1, h2, SET_SERIES


WIDER = 1.15      # the diagrams' drawn area a longer abscissa must gain over the taller ordinates (_wider)


def _wider(sol, n, precision: float, sizes: list[float], sz: tuple, fits) -> tuple[float, float, float]:
    """(abscissa, s, d²s/dφ²) sizes of a set's sheet of the three diagrams: as grown (ordinates first,
    then the abscissa: ``sz`` = (kl, k, ks, ka)), or — where the next finer standard μ_φ draws them
    larger by WIDER in area with the ordinates shortened to fit (``fits(size, height, accel)``) — that
    (stop 49: the own rocking cam's A2 set drew 210° at 1 °/mm over 268 of its 564 mm, s grown to the
    sheet's height first, a third of sheet 1 blank beside it)."""
    from graphplan.drawing.cam import diagrams
    kl, k, ks, ka = sz

    def drawn(size: float, height: float, accel: float) -> tuple[float, float]:
        g = construct(sol, n, precision, size=size, profile_size=k, height=height, accel=accel, measure=False,
                      series=SET_SERIES)
        b = diagrams(sol, g, "en").bounds()
        return (b[2] - b[0]) * (b[3] - b[1]), g.mu_phi
    area, mu = drawn(kl, ks, ka)
    for x in (s for s in sizes if s > kl):
        if construct(sol, n, precision, size=x, profile_size=k, height=ks, accel=ka, measure=False,
                     series=SET_SERIES).mu_phi >= mu * (1 - 1e-9):
            continue                       # the same μ_φ: no longer
        h = _largest(lambda y: fits(x, y, sizes[0]), [s for s in sizes if s <= ks])
        if h is None:
            return kl, ks, ka
        a = _largest(lambda y: fits(x, h, y), [s for s in sizes if s <= ka]) or sizes[0]
        return (x, h, a) if drawn(x, h, a)[0] > WIDER * area else (kl, ks, ka)
    return kl, ks, ka


def _legible_poles(sol, n, precision: float, sz: tuple, fits) -> tuple[float | None, float | None]:
    """d²s/dφ² and ds/dφ on a sheet of their own: where a phase's ds/dφ is drawn under LEGIBLE_MM, the
    shortest whole-millimetre H_2 that draws it so tall (its ordinates grow as H_2, μ_s kept), with
    the longest H_1 at which the two still fit their sheet (``fits((H1, H2))``; d²s/dφ², which Table 1
    does not read, gives up the height: μ_{d²s/dφ²} = μ_s/(μ_φ²·H_1·H_2)). (None, None): as they are."""
    import numpy as np
    g = construct(sol, n, precision, size=sz[0], profile_size=sz[1], height=sz[2], accel=sz[3], measure=False,
                  series=SET_SERIES)
    peak = min(float(np.max(np.abs(g.v_mm[g.phase == ph]))) for ph in (0, 1))
    if peak >= LEGIBLE_MM or peak <= 0:
        return None, None
    lo, hi = POLE_MM
    h2 = float(math.ceil(g.H2 * LEGIBLE_MM / peak - 1e-9))
    if h2 > hi:
        return None, None
    h1 = _largest(lambda h: fits((h, h2)), [float(h) for h in range(int(lo), int(hi) + 1)])
    return (h1, h2) if h1 is not None else (None, None)


def _largest(ok, sizes: list[float]) -> float | None:
    """The largest size for which ``ok`` holds, by bisection (fitting falls off as the size grows)."""
    lo, hi, best = 0, len(sizes) - 1, None
    while lo <= hi:
        mid = (lo + hi) // 2
        if ok(sizes[mid]):
            best, lo = sizes[mid], mid + 1
        else:
            hi = mid - 1
    return best


MOST_DIVISIONS = 48      # the most intervals a phase a redrawing tries (four times the scene's, at most)


def construct_on(sol, f: Form, n: int | None = None, precision: float = 0.5, lang: str = "uk"):
    """The construction at the scales of the cam sheet on ``f`` (_construct_on), a rocking follower's
    phase diagram at the scale the sheet in ``lang`` draws it at and R0 read there (_sheet_layout's
    choice, the sheet's own: stop 51 found the terminal reading R0 = 52.4 mm at 2.5:1 where the A1 sheet,
    whose layout had no room for the diagram at 2.5:1, drew it at 1:1 and printed 52.5 mm)."""
    g = _construct_on(sol, f, n, precision)
    if not sol.cam.rocking:
        return g
    return _sheet_layout(sol, g, sol.cam, f, lang)[0]


def _construct_on(sol, f: Form, n: int | None = None, precision: float = 0.5):
    """The construction at the scales of the cam sheet on ``f`` (cam_sizes): what `graphplan cam`,
    the explorer, graphplan.cam() and the sheet itself measure, so that they print the same numbers.

    Redrawn until it closes, as the s–v–a diagrams are (graphic.redraw): where the s diagram misses
    its closing by more than 2 % of the stroke drawn and the ruler's half division
    (graphic.cam.closing_bound), the diagrams are drawn again with more divisions — the fewest that
    close within it, up to four times as many (MOST_DIVISIONS at most) —, the notes saying so
    (``redrawn``; where the scene named the first divisions, the notes say it named them and why the
    drawing takes others: issue 32 item 2, the sheet chooses what makes the diagram right and says
    so). Divisions ``n`` names (`--divisions` on the command line) are kept and a warning says how
    many would do; where none tried helps, the first drawing stays with its warning."""
    first_n = n or sol.cam.divisions
    given = n is not None
    sizes = cam_sizes(sol, f, first_n, precision)

    def make(m: int, sz, measure: bool = False):      # measured (R0 off the phase diagram) once, at the end
        g = construct(sol, m, precision, size=sz[0], profile_size=sz[1], height=sz[2], accel=sz[3],
                      H1=sz[4], H2=sz[5], measure=measure, series=sz[6] if len(sz) > 6 else False)
        g.split = len(sz) > 7 and bool(sz[7])           # s on a sheet of its own (set_sizes)
        return g

    def kept(better: int | None):
        g = make(first_n, sizes, True)
        g.warnings = [w for w in g.warnings if w != closing_warning(g)] + [closing_warning(g, better, True)]
        return g
    first = make(first_n, sizes)
    if first.closes:
        return make(first_n, sizes, True)
    top = min(MOST_DIVISIONS, 360, 4 * first_n)
    for m in range(first_n + 1, top + 1):
        if not make(m, sizes).closes:
            continue
        if given:
            return kept(m)
        sz = sizes if _one_sheet_still(sol, f, make(m, sizes)) else cam_sizes(sol, f, m, precision)
        if make(m, sz).closes:                 # the taller table may have changed the scales
            redrawn = make(m, sz, True)
            redrawn.redrawn = (first_n, *first.closing, first.closing_bound, bool(sol.cam.divisions_given))
            return redrawn
    return kept(None)


def _one_sheet_still(sol, f: Form, g) -> bool:
    """Whether the drawings at ``g``'s scales with the table of ``g``'s divisions still share one sheet
    of ``f`` in both languages (a redrawing's longer table may not leave them room)."""
    for lang in ("uk", "en"):
        if not _one_sheet(_arranged(sol, g, sol.cam, lang, f)[4]):
            return False
    return True


def notes_alone(page) -> bool:
    """Whether a laid-out sheet holds the notes and nothing else."""
    return all(leaf.name == "notes" for leaf, _ in page)


def kept_together(leaves: list[Leaf], tab: Leaf, lines: list[str], nts: Leaf, region, keep, later=None,
                  side: bool = False):
    """A set's sheets: the drawings, then the table with the notes after it — on one sheet (every
    sheet of a set carries a drawing or a table: the rocking cam's A3 set gave its last sheet to
    ten lines of notes). The notes as laid out where they do not take a sheet alone; else wrapped
    to the width the sheet leaves beside the table (at least the title block's); else under the
    table, the two one block. ``later``: the title block of the sheets after the first (flow)."""
    laid = flow([leaves, [tab, nts]], region, keep, later=later)
    # ``side``: the table beside the profile where that saves a sheet — only where ϑ(φ) already stands
    # with s on its sheet (pressure_by_displacement; else the table's sheet is ϑ(φ)'s: the knife cam's
    # A2 set and review 13's A3 set lost ϑ(φ) to a sheet saved)
    by = beside_last(leaves, tab, lines, region, keep, later) if side else None
    if by is not None and (laid is None or len(by) < len(laid)):
        return by
    if laid is None or not notes_alone(laid[-1]):
        return laid
    tw = extent(tab)[0]
    width = min(300.0, region[2] - region[0] - tw - GAP)
    if width >= TITLE:
        beside_ = Leaf("notes", record=note_block(lines, width))
        again = flow([leaves, [tab, beside_]], region, keep, later=later)
        if again is not None and not notes_alone(again[-1]) and len(again) <= len(laid):
            return again
    # under the table at its width; else wider, up to the sheet's field (review 10's A3 set: at the
    # table's 195 mm its notes took one line more than the sheet had under it, and went alone)
    for wide in sorted({max(TITLE, tw), max(TITLE, tw, min(300.0, region[2] - region[0])),
                        max(TITLE, tw, region[2] - region[0])}):
        under = Leaf("notes", record=note_block(lines, wide))
        again = flow([leaves, [Stack([tab, under], flush=True)]], region, keep, later=later)
        if again is not None and not notes_alone(again[-1]):
            return again
    return laid


def beside_last(leaves: list[Leaf], tab: Leaf, lines: list[str], region, keep, later=None):
    """A set's sheets with Table 1 and the notes under it (wrapped to the table's width) in the last
    drawing's row, beside the profile where the two fit across and the table clears the title block
    (flow's ``ragged``): as a row of its own under a profile as tall as the sheet they took a sheet
    alone, 60 % blank (stop 52: OWN_CAM52's A2 set). None where that lays out nothing."""
    under = Leaf("notes", record=note_block(lines, max(TITLE, extent(tab)[0])))
    laid = flow([leaves + [Stack([tab, under], flush=True)]], region, keep, later=later, ragged=True)
    return None if laid is None or notes_alone(laid[-1]) else laid


TABLE_ROW = 8.0      # mm: GOST 2.105's least height of a table's row, where the sheet has room for it
# Table 1 as large as the room under the profile takes (GOST 2.304 letters 3.5 mm, rows of 10 or 8
# mm; else the 2.5 mm letters in rows of 8): the first of these that leaves the drawings where they were
# — the 2.5-mm letters in rows of 10 or 9 mm before those of 8 where the 3.5-mm table is wider than the
# profile's column (stop 50: CAM50's 2.5-mm table in rows of 8 left 230 × 120 mm blank over it)
TABLE_SIZES = ((3.5, 10.0), (3.5, 9.0), (3.5, TABLE_ROW), (2.5, 10.0), (2.5, 9.0), (2.5, TABLE_ROW))


# where rows of TABLE_ROW are too many for the room under the profile (a cam of 10 divisions and no far
# dwell: 22 rows want 182 mm where it has 160), the lettering still 3.5 mm in closer rows — wider than
# the 2.5 mm table in 6 mm rows, whose 115 mm beside it and 20 mm over it stood blank (stop 49); its header
# row grown to hold a subscript's tail clear of the rule under it (positions_table: clear_header)
CLOSER_ROWS = ((3.5, 7.0), (3.5, 6.5))
# a set's Table 1: the 3.5-mm letters in closer rows before the 2.5-mm ones in wider rows, then the table's own
# size (stop 60: the A2 sets took 2.5-mm letters in 8-mm rows where 3.5 mm in 7-mm rows fitted — the closer
# rows were left out of the sets while their header's subscript tail touched the rule under it; the header
# row now grows to hold it, drawing.tables)
SET_TABLE_SIZES = (tuple(t for t in TABLE_SIZES if t[0] == 3.5) + CLOSER_ROWS
                   + tuple(t for t in TABLE_SIZES if t[0] != 3.5) + ((2.5, 6.0),))
STRETCH = 1.5        # a table's columns widened at most this much to span its column
# last, the table's own size (positions_table: 2.5-mm letters in 6-mm rows) across the profile's column: a
# profile tall enough to leave no room for closer rows kept it 196 mm wide in a column of 344, a blank of
# 147 × 162 mm beside it over the title block (stop 53: CAM53's A1 sheet)
BASE_TABLE = (2.5, 6.0)


def _in_hole(boxes: dict) -> bool:
    """Whether the notes (box) stand in the diagrams' box, under the phase diagram."""
    d, nb = boxes["diagrams"], boxes["notes"]
    return d[0] < nb[0] and nb[2] <= d[2] + 1e-9 and d[1] <= nb[1]


def _rows_of_8(laid, leaves: list[Leaf], doc: dict, lang: str, cam: Cam, f: Form, notes_at=None):
    """The A1 sheet's layout with Table 1 drawn larger (TABLE_SIZES: its lettering 3.5 mm, its rows
    10 mm, down to 2.5 mm letters in rows of TABLE_ROW mm) when that leaves the drawings and the notes
    where they were and the profile its room — the column under the profile otherwise stands part
    blank (the A1 sheet 45 % empty, issue 32 item 1) —; else ``laid`` as it is."""
    nts = next(leaf for leaf, _ in laid[0] if leaf.name == "notes")
    before = {leaf.name: b for leaf, b in laid[0] if leaf.name in ("diagrams", "notes")}
    profile = next(leaf for leaf, _ in laid[0] if leaf.name == "profile")
    for size, row in TABLE_SIZES + CLOSER_ROWS + (BASE_TABLE,):
        tall = Leaf("table", record=positions_table(doc, lang, row, size))
        # across the profile's column (stop 49: 70 mm of it stood blank beside the table, over the title
        # block), its columns widened by at most STRETCH
        wide = min(profile.w, STRETCH * tall.w)
        if wide > tall.w + 1.0:
            tall = Leaf("table", record=positions_table(doc, lang, row, size, span=wide))
        again = _laid(f, leaves, tall, nts, notes_at or _notes_at(doc, lang, cam))
        if not _one_sheet(again):
            continue
        after = {leaf.name: b for leaf, b in again[0] if leaf.name in ("diagrams", "notes")}
        room = next(b for leaf, b in again[0] if leaf.name == "profile")
        # the drawings where they were, or the column under the profile wider for the table and the
        # notes still in the room under the phase diagram (the diagrams' box narrower, still theirs)
        held = before == after or (_in_hole(before) and _in_hole(after))
        if held and room[3] - room[1] >= profile.h - 1e-9 and room[2] - room[0] >= profile.w - 1e-9:
            return again
    return laid


PRESSURE_ROOM = (120.0, 50.0)    # mm: the least room (width, height) the pressure angle's diagram takes (ϑ at 2.5 °/mm at most over ±50°)


def pressure_leaf(sol, g, lang: str, w: float, h: float, same: bool = True) -> Leaf | None:
    """The pressure angle's diagram captioned, at the finest standard μ_ϑ that puts it in ``w`` × ``h``
    mm (None when none of the trials does): ``same``, at the diagrams' μ_φ (review 11, mark 16: its
    divisions line up with theirs); else at the standard μ_φ that fits ``w`` (a set whose sheets have
    no room as wide as the diagrams' abscissa)."""
    from graphplan.drawing.cam import PRESSURE_NAMES, pressure_diagram, pressure_scales
    mm = "мм" if lang == "uk" else "mm"
    for shrink in (1.0, 0.9, 0.8, 0.7):
        mu_phi, mu_t = pressure_scales(sol, w * shrink, h * shrink)
        if same:
            mu_phi = g.mu_phi
        second = (f"{scale_text('mu_phi', mu_phi, sol.cam.rocking, lang)}; "
                  f"μ_ϑ = {num(mu_t, lang, 4)} °/{mm}")
        leaf = Leaf("pressure", record=captioned(pressure_diagram(sol, g, lang, mu_phi, mu_t),
                                                PRESSURE_NAMES[lang], second))
        if leaf.w <= w + 1e-9 and leaf.h <= h + 1e-9:
            return leaf
    return None


SET_PRESSURE = (240.0, 130.0)     # mm: the pressure angle's diagram on a set's sheet of the table


PRESSURE_SHARE = 0.6      # of the field's height: the tallest ϑ(φ) tried on a set's sheet of the table


def _pressure_cap(region) -> float:
    """The tallest ϑ(φ) a set's sheet of the table is tried with: PRESSURE_SHARE of the field's height,
    at least SET_PRESSURE's 130 mm (stop 48: capped at 130 mm on A2, ϑ(φ) took 1 °/mm, 100 mm over ±40°,
    and the sheet of the table stood half blank — at 0.5 °/mm it is 195 mm, beside the table in
    8 mm rows; stop 52: at half the A2 field, 205 mm, CAM51's ϑ(φ) over ±45° missed 0.5 °/mm — 210 mm
    with its letters and caption — by 5 mm and took 1 °/mm, its sheet 30 % blank). The flow still
    refuses a ϑ(φ) that would take a sheet more."""
    return max(SET_PRESSURE[1], (region[3] - region[1]) * PRESSURE_SHARE)


def set_with_pressure(laid, leaves, tab: Leaf, nts: Leaf, sol, g, lang: str, region, keep, later=None,
                      same: bool = True):
    """A set's sheets with the pressure angle's diagram after the table and the notes, when it goes
    on the sheets there are (no further sheet for it): the table's sheet of an A2 or A3 set stands
    mostly blank. Else ``laid`` as it is."""
    if laid is None:
        return laid
    # the table and the notes as kept_together laid them (the notes may be wrapped to the table's width)
    # (from every sheet: where the notes took a sheet after the table's, the table is not on the last —
    # taken from the last alone, it was dropped: the reviewer's knife-edge cam's A3 set had no Table 1)
    last = [leaf for page in laid for leaf, _ in page if leaf.name in ("table", "notes")] or [tab, nts]
    # as tall as the room the table and the notes leave (an A3 set: 70 mm under them; review 9,
    # finding 2 — the trials stopped at 70 % of 130 mm, and ϑ(φ) went nowhere), as wide as the sheet
    # — of the widths tried, the one that draws it tallest (a fine μ_ϑ at a coarse μ_φ over a flat ϑ)
    best, area = laid, (0.0, 0.0)
    for w in (region[2] - region[0] - 2 * GAP, SET_PRESSURE[0], 180.0, 150.0):
        for part in (1.0, 0.95, 0.9, 0.85, 0.8, 0.75, 0.7, 0.65, 0.6, 0.55, 0.5, 0.45, 0.4):
            h = _pressure_cap(region) * part
            leaf = pressure_leaf(sol, g, lang, w, h, same)
            if leaf is None or (round(leaf.h), leaf.w) <= area:
                continue
            again = flow([leaves, last + [leaf]], region, keep, later=later)
            if again is not None and len(again) <= len(laid) and not notes_alone(again[-1]):
                best, area = again, (round(leaf.h), leaf.w)
                break
    return best


def pressure_by_table(laid, leaves: list[Leaf], doc: dict, sol, g, cam: Cam, lang: str, region, keep,
                      later=None, most: int | None = None) -> list | None:
    """A set's sheets with ϑ(φ) at the diagrams' μ_φ across the sheet under the phase diagram and the
    profile, else after Table 1 and the notes on the table's sheet, the table's rows as low as
    TABLE_SIZES and 6 mm allow (review 11, mark 16: beside the profile ϑ(φ) had room only at 2 °/mm,
    beside the diagrams' 1 °/mm). None where it would take more sheets than ``most`` (the set's own)."""
    if laid is None:
        return None
    lines = notes(doc, lang, cam)
    w = region[2] - region[0] - 2 * GAP
    for part in (1.0, 0.9, 0.8, 0.7, 0.6, 0.5, 0.4):
        leaf = pressure_leaf(sol, g, lang, w, _pressure_cap(region) * part, True)
        if leaf is None:
            continue
        for size, row in SET_TABLE_SIZES:
            tab = Leaf("table", record=positions_table(doc, lang, row, size))
            nts = Leaf("notes", record=note_block(lines, max(TITLE, min(300.0, region[2] - region[0] - tab.w - GAP))))
            for again in (kept_together(leaves + [leaf], tab, lines, nts, region, keep, later),  # under the profile
                          flow([leaves, [tab, nts, leaf]], region, keep, later=later)):          # after the table
                if again is not None and len(again) <= (most or len(laid)) and not notes_alone(again[-1]):
                    return again
    return None


def pressure_by_displacement(laid, leaves: list[Leaf], doc: dict, sol, g, cam: Cam, lang: str, region, keep,
                             later=None) -> list | None:
    """A set whose s diagram has a sheet of its own (set_sizes): ϑ(φ) under it at its μ_φ, each
    division's ϑ straight under its s (review 11, mark 16), as tall as that sheet leaves, and Table 1
    as large as its sheet takes (TABLE_SIZES). None where that takes more sheets than ``laid``."""
    names = [leaf.name for leaf in leaves]
    if laid is None or "displacement" not in names:
        return None
    at = names.index("displacement")
    disp = leaves[at]
    lines = notes(doc, lang, cam)
    w = region[2] - region[0] - 2 * GAP
    b = disp.record.bounds()
    h = region[3] - (later or keep)[3] - (b[3] - b[1]) - 3 * GAP      # above the later sheets' title block
    if h < PRESSURE_ROOM[1]:
        return None
    for part in (1.0, 0.9, 0.8, 0.7, 0.6):
        leaf = pressure_leaf(sol, g, lang, w, min(h, SET_PRESSURE[1]) * part, True)
        if leaf is None:
            continue
        # one leaf, their φ origins on one vertical (with_theta; apart places them as two drawings)
        both = own_sheet(Leaf("displacement", record=with_theta(disp.record, leaf.record)), sheet_room(region, keep))
        drawings = leaves[:at] + [both] + leaves[at + 1:]
        for again in _with_table(drawings, doc, lang, lines, region, keep, later, laid, True):
            return again
    return None


def _with_table(drawings: list, doc: dict, lang: str, lines: list[str], region, keep, later, laid,
                side: bool = False):
    """The set's sheets with ``drawings``, Table 1 at each of its sizes (TABLE_SIZES, the largest
    first) and the notes kept with it — each arrangement taking no more sheets than ``laid`` and
    leaving no sheet to the notes alone, in that order."""
    for size, row in SET_TABLE_SIZES:
        tab = Leaf("table", record=positions_table(doc, lang, row, size))
        nts = Leaf("notes", record=note_block(lines, max(TITLE, min(300.0, region[2] - region[0] - tab.w - GAP))))
        again = kept_together(drawings, tab, lines, nts, region, keep, later, side)
        if again is not None and len(again) <= len(laid) and not notes_alone(again[-1]):
            yield again


def pressure_by_phase(laid, leaves: list[Leaf], doc: dict, sol, g, cam: Cam, lang: str, region, keep, later=None,
                      same: bool = True):
    """A set's sheets with the pressure angle's diagram ϑ(φ) under the phase diagram, beside the
    profile, and Table 1 drawn as large as the sheet after them takes (TABLE_SIZES) with the notes:
    the phase diagram and the profile — the profile at the largest standard scale that fits the
    sheet alone, the next (1:1 after 1:2) too large — left the profile's sheet 61–65 % empty. The
    pressure angle read off the phase diagram (R_0 from [ϑ]) is checked over the turn beside it, and
    the set reads in order: the law's diagrams, the phase diagram with ϑ(φ), the profile, the table.
    None where that sheet has no room for ϑ(φ) or the set would take a sheet more."""
    names = [leaf.name for leaf in leaves]
    if laid is None or not {"phase", "profile"} <= set(names):
        return None
    page = next((pg for pg in laid if {"phase", "profile"} <= {leaf.name for leaf, _ in pg}), None)
    if page is None:
        return None
    at = names.index("phase")           # a split set's too (s on a sheet of its own: four leaves; stop 53's A3 set)
    phase, profile = leaves[at], leaves[names.index("profile")]
    w = region[2] - region[0] - profile.w - 2 * GAP
    h = region[3] - region[1] - phase.h - 3 * GAP
    if w < PRESSURE_ROOM[0] or h < PRESSURE_ROOM[1]:
        return None
    lines = notes(doc, lang, cam)
    for part in (1.0, 0.9, 0.8, 0.7, 0.6):
        leaf = pressure_leaf(sol, g, lang, w, h * part, same)
        if leaf is None:
            continue
        drawings = leaves[:at] + [Stack([phase, leaf])] + leaves[at + 1:]
        for again in _with_table(drawings, doc, lang, lines, region, keep, later, laid):
            where = [{lf.name for lf, _ in pg} for pg in again]
            if any({"phase", "pressure", "profile"} <= names for names in where):
                return again
    return None


PHASE_SCALES = (0.0002, 0.00025, 0.0004, 0.0005, 0.001, 0.002, 0.0025, 0.004)   # m/mm: GOST 2.302's 5:1 … 1:4


def _phase_scales(sol, g, lang: str):
    """The rocking phase diagram's scales finer than the profile's μ_l, the finest first, at which the
    profile stays the sheet's largest drawing (LAYOUT.md's cam sheet; _profile_largest)."""
    from graphplan.drawing.cam import phase_diagram, profile_drawing
    if not sol.cam.rocking:
        return
    prof = profile_drawing(sol, g, lang).bounds()
    for mu in PHASE_SCALES:
        if mu < g.mu_l * (1 - 1e-9):
            g2 = phase_drawn_at(g, mu)              # R0 read at the scale it is drawn at
            if _profile_largest(prof, phase_diagram(sol, g2, lang).bounds()):
                yield g2


def phase_scale_of(sol, g):
    """``g`` with a rocking follower's phase diagram at the scale the sheet first tries for it — the
    finest standard one at which the profile stays the largest drawing (_phase_scales, by the drawings'
    extents alone) — and R0 read there: what `graphplan cam`, graphplan.cam() and the JSON print, so
    that they agree with the sheet, which draws the diagram there where its layout keeps (_phase_enlarged;
    else at μ_l, R0 then read at μ_l on the sheet). A translating follower's ``g`` as it is."""
    return next(_phase_scales(sol, g, "uk"), g)


def _phase_enlarged(sol, g, f: Form, lang: str, as_is: tuple) -> tuple:
    """A rocking follower's phase diagram (drawn at the profile's μ_l) at the finest standard scale
    (_phase_scales) that keeps the A1 sheet's layout — one sheet, the notes under the phase diagram (review 11, mark
    16: at 1:1 it was 120 × 65 mm beside 300 mm of blank, its numbers, R_0 and [ϑ] crowded by O).
    ``as_is``: the leaves, table, notes, doc and layout at μ_l, returned with ``g`` where none fits."""
    hole = _theta_in_hole(as_is[4])
    for g2 in _phase_scales(sol, g, lang):
        again = _arranged(sol, g2, sol.cam, lang, f, hole)
        if _one_sheet(again[4]) and _in_hole({leaf.name: b for leaf, b in again[4][0]}) and (
                not hole or _theta_in_hole(again[4])):
            return (g2, *again)
    return (g, *as_is)


def _set_phase_enlarged(sol, g, lang: str, region, keep, as_is: tuple, later=None) -> tuple:
    """A set's rocking phase diagram at the finest standard scale (_phase_scales) that keeps the set's sheets and
    leaves it on the profile's sheet (review 11: ≈ 45 mm at 1:2 on the A3 set, illegible)."""
    laid = as_is[-1]
    if laid is None:
        return (g, *as_is)
    for g2 in _phase_scales(sol, g, lang):
        leaves, tab, nts, doc = _leaves(sol, g2, sol.cam, lang, split=True, row=sheet_room(region, keep))
        again = kept_together(leaves, tab, notes(doc, lang, sol.cam), nts, region, keep, later)
        if (again is not None and len(again) == len(laid)
                and any({"phase", "profile"} <= {leaf.name for leaf, _ in page} for page in again)):
            return g2, leaves, tab, nts, doc, again
    return (g, *as_is)


THETA_SCALES = (0.25, 0.4, 0.5, 1.0, 2.0)     # °/mm: μ_ϑ finer than the stroke's rule, the finest first


def _theta_grown(sol, g, f: Form, lang: str, as_is: tuple) -> tuple:
    """ϑ(φ) under the notes (_arranged) at the finest standard μ_ϑ at which it still stands in the room
    under the phase diagram, the rest of the layout as it was (the room under it stood blank)."""
    leaves, tab, nts, doc, laid, notes_at = as_is
    if not _theta_in_hole(laid):
        return as_is
    boxes = {leaf.name: b for leaf, b in laid[0] if leaf.name != "notes"}
    now = next(leaf for leaf, _ in laid[0] if leaf.name == "notes").record.scales.get("mu_theta", 0.0)
    for mu in (m for m in THETA_SCALES if m < now - 1e-12):
        at = _notes_at(doc, lang, sol.cam, theta=pressure_below(sol, g, lang, mu))
        again = _laid(f, leaves, tab, nts, at)
        if _theta_in_hole(again) and {leaf.name: b for leaf, b in again[0] if leaf.name != "notes"} == boxes:
            return leaves, tab, nts, doc, again, at
    return as_is


def _theta_mu(laid) -> float:
    """μ_ϑ (°/mm) of the pressure angle's diagram on a set's sheets — the finer, the taller ϑ(φ) reads
    —; infinity where none is drawn."""
    def records(node):
        kids = getattr(node, "children", None)
        return [r for k in kids for r in records(k)] if kids is not None else [getattr(node, "record", None)]
    mus = [rec.scales["mu_theta"] for page in laid for node, _ in page for rec in records(node)
           if rec is not None and "mu_theta" in rec.scales]
    return min(mus, default=math.inf)


def _names(node) -> set[str]:
    """The names of the leaves in a layout node (a Leaf, or a Stack of them)."""
    kids = getattr(node, "children", None)
    return set().union(*map(_names, kids)) if kids is not None else {getattr(node, "name", "")}


def _sheet_layout(sol, g, cam: Cam, f: Form, lang: str) -> tuple:
    """(g, leaves, table, notes, doc, layout, notes_at) of the cam sheet on ``f``: the A1 sheet in
    columns, its rocking phase diagram enlarged where the layout keeps (_phase_enlarged), ϑ(φ) grown,
    Table 1 larger; else a set, each drawing on its own (set_sizes), the phase diagram enlarged where
    the set keeps (_set_phase_enlarged). ``g`` with the phase diagram's scale chosen here — the one
    construction the sheet and `graphplan cam` (construct_on) both read R0 from."""
    region, keep = field_of(f), keep_out(f)
    leaves, tab, nts, doc, laid, notes_at = _arranged(sol, g, cam, lang, f)
    if f.name == "A1" and _one_sheet(laid):
        g, leaves, tab, nts, doc, laid, notes_at = _phase_enlarged(sol, g, f, lang,
                                                                    (leaves, tab, nts, doc, laid, notes_at))
        leaves, tab, nts, doc, laid, notes_at = _theta_grown(sol, g, f, lang, (leaves, tab, nts, doc, laid, notes_at))
        laid = _rows_of_8(laid, leaves, doc, lang, cam, f, notes_at)
    if not _one_sheet(laid):            # a set of sheets: each drawing on its own (set_sizes)
        leaves, tab, nts, doc = _leaves(sol, g, cam, lang, split=True, row=sheet_room(region, keep))
        # the later sheets clear of their form 2a (stop 51: judged under form 1, as the drawings' sizes were)
        laid = kept_together(leaves, tab, notes(doc, lang, cam), nts, region, keep, later_keep(f))
        g, leaves, tab, nts, doc, laid = _set_phase_enlarged(sol, g, lang, region, keep, (leaves, tab, nts, doc, laid),
                                                             later_keep(f))
    return g, leaves, tab, nts, doc, laid, notes_at


def _table_alone(page: list[Placed], doc: dict, lang: str, f: Form, k: int) -> list[Placed]:
    """A set's sheet that holds Table 1 alone: the table as large as the sheet's field takes it (the
    first of TABLE_SIZES and CLOSER_ROWS that fits, centred) — at 2.5-mm letters in 6-mm rows it stood
    198 × 168 mm on an A3 sheet of 385 × 255 (stop 54: the rocking knife-edge cam's set)."""
    if [p.name for p in page] != ["table"]:
        return page
    x0, y0, x1, y1 = field_of(f)
    floor = (later_keep(f) if k else keep_out(f))[3] + GAP / 2
    for size, row in TABLE_SIZES + CLOSER_ROWS:
        rec = positions_table(doc, lang, row, size)
        b = rec.bounds()
        if b[2] - b[0] <= x1 - x0 + 1e-9 and b[3] - b[1] <= y1 - floor + 1e-9:
            rec = rec.moved((x0 + x1) / 2 - (b[0] + b[2]) / 2, (floor + y1) / 2 - (b[1] + b[3]) / 2)
            return [Placed("table", rec, rec.bounds())]
    return page


def build_cam_sheet(cam: Cam, f: Form, args: SheetOptions) -> Sheet:
    """The cam sheet: the three constructions captioned with their scales, the table and the notes,
    flowed over the sheet (and further sheets of the set when the format is small) in reading order,
    each drawing at the largest standard scale that fits its zone (cam_sizes)."""
    lang = args.lang
    sol = solve(cam)
    # laid out with the phase diagram at the profile's μ_l; enlarged where the layout keeps (_phase_enlarged)
    g = _construct_on(sol, f, None, args.precision)
    region, keep = field_of(f), keep_out(f)
    g, leaves, tab, nts, doc, laid, notes_at = _sheet_layout(sol, g, cam, f, lang)
    if not _one_sheet(laid):            # a set of sheets: each drawing on its own (set_sizes)
        # ϑ(φ) at the diagrams' μ_φ where the set has room for it without a sheet more than at its own
        def placed(t) -> bool:
            return t is not None and any("pressure" in _names(leaf) or getattr(getattr(leaf, "record", None), "theta_at", None)
                                         is not None for pg in t for leaf, _ in pg)
        own = (pressure_by_phase(laid, leaves, doc, sol, g, cam, lang, region, keep, later_keep(f), False)
               or set_with_pressure(laid, leaves, tab, nts, sol, g, lang, region, keep, later_keep(f), False))
        most = len(own) if placed(own) else len(laid or [])
        same = [] if laid is None else [t for t in (pressure_by_displacement(laid, leaves, doc, sol, g, cam, lang, region, keep, later_keep(f)),
                            pressure_by_phase(laid, leaves, doc, sol, g, cam, lang, region, keep, later_keep(f)),
                            pressure_by_table(laid, leaves, doc, sol, g, cam, lang, region, keep, later_keep(f), most),
                            set_with_pressure(laid, leaves, tab, nts, sol, g, lang, region, keep, later_keep(f)))
                if placed(t) and len(t) <= most]
        # of those, the one that reads ϑ finest (μ_ϑ: the tallest ϑ(φ)) on no more sheets than the first
        # (stop 53: CAM48's A3 set drew ϑ(φ) at 5 °/мм under s where the table's sheet takes it at 2 °/мм);
        # at the diagrams' μ_φ still (review 11, mark 16), not at its own
        laid = min(((_theta_mu(t), k, t) for k, t in enumerate(same) if len(t) <= len(same[0])),
                   key=lambda c: c[:2])[2] if same else (own if placed(own) else laid)
    if laid is None:
        raise said_error(GraphplanError, "sh cam larger", None, None, form=f.name, option="--format")
    pages = [[q for leaf, b in page if leaf.record is not None
              for q in apart(leaf.name, place(f, leaf, b), b, page, getattr(leaf.record, "parts", None),
                             getattr(leaf.record, "theta_at", None))]
             for page in laid]
    if len(pages) > 1:
        pages = [_table_alone(page, doc, lang, f, k) for k, page in enumerate(pages)]
    if f.name == "A1" and len(pages) == 1:          # the given data in the room under the profile (camgiven)
        from graphplan.sheets.camgiven import with_given
        pages[0] = with_given(pages[0], cam, doc, lang,
                              lambda row, size, span: positions_table(doc, lang, row, size, span=span))
    fields = _fields(cam, lang)
    fields["scale"] = drawing_scale(g.mu_l, lang)
    return compose(f, pages, fields, lang, f"{cam.title_in(lang)} — {WORDS[lang]['subtitle']}")
