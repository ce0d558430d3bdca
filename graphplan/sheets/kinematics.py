"""The kinematics sheet (sheet 1 of the coursework, seeds 000 and 004; the lab report of seed 002):
the position plan, the velocity plan of every position, the acceleration plans asked for, the s–v–a
diagrams, the tables (velocities; one numbered table per acceleration plan; the links' dimensions;
the lab's s, v, a at the chosen positions) and the notes.

Composed by construction (docs/composition.md): the tables in a column by the title block, the notes
above it; in the rest of the field the position plan and the diagrams, the velocity plans in a grid of
equal cells in position order, the acceleration plans together. The scales are chosen once per scene
and format by arithmetic on the drawings' natural sizes (``plan``): the largest standard scales at
which the composition fits; the terminal's ``plans``/``diagrams``, the API and the explorer ask
``sheet_scales`` for the same numbers. Where one sheet cannot hold the plans legibly (a small
format), the drawings flow over a set of sheets in reading order."""
from __future__ import annotations

import math
from dataclasses import dataclass

from graphplan.drawing.layout import (GAP, Grid, Leaf, Placed, Row, Stack, arrange, cells, centred, column_size, extent,
                                      flow, set_columns, split, top_left)
from graphplan.exact.positions import Study
from graphplan.graphic.record import Record, text_width
from graphplan.sheets.compose import (Family, Sheet, SheetOptions, captioned, choose_levels, coarser,
                                      compose, drawing_scale, field_of, finer, grown, lines_of, measured, note_block, notes_height,
                                      number, options_of, percent, reading, remembered)
from graphplan.sheets.form import TABLES, Form, enlarged, form, table
from graphplan.util.errors import GraphplanError
from graphplan.util.markup import escape
from graphplan.util.words import column, fixed, num, pair_kind, unit, word

SHORT_MM = 20.0    # the notes' second figure: errors of vectors drawn at least this long


def _accel_arg(values) -> list | None:
    """The acceleration plans asked for, as build_plans reads them ("#3", "200", 200.0)."""
    return list(values) if values else None


def _symbol(key: str, letter: str = "v") -> str:
    """A JSON key as the lab writes the quantity (markup): B → v_B, BA → v_BA, omega_AB → ω_AB,
    n_BA → a^n_BA, t_BA → a^τ_BA, k_A3A2 → a^k_A3A2, r_A3A2 → a^r_A3A2."""
    for prefix, sym in (("omega_", "ω"), ("epsilon_", "ε")):
        if key.startswith(prefix):
            return f"{sym}_{{{key[len(prefix):]}}}"
    head, _, rest = key.partition("_")
    marks = {"n": "n", "t": "τ", "k": "k", "r": "r"}
    if rest and head in marks:
        return f"{letter}^{marks[head]}_{{{rest}}}"
    return f"{letter}_{{{key}}}"


# -- tables ------------------------------------------------------------------------------------

def velocity_columns(doc: dict, precision: float) -> list[str]:
    """The velocity table's columns: every quantity once — a column equal to an earlier one (ω of a
    block riding its rocker: ω2 = ωOB) or zero at every position (a centre of mass on a fixed
    pivot) is left out."""
    keys: list[str] = []
    for pos in doc["positions"]:
        for key in pos["velocity"]:
            if key not in keys:
                keys.append(key)
    kept: list[str] = []
    seen: list[tuple[str, ...]] = []
    for key in keys:
        cells = tuple(_cell(pos["velocity"].get(key), precision) for pos in doc["positions"])
        if all(c in ("0", "—") for c in cells) or cells in seen:
            continue
        seen.append(cells)
        kept.append(key)
    return kept


def _cell(e: dict | None, precision: float, lang: str = "en") -> str:
    """A table's graphical value: the plan's reading (a vector read as 0 mm — a dead centre's
    velocity — is the number 0, as the terminal prints it); ω and ε signed by their sense
    (+ counter-clockwise, the tables' headers say so); "—" only where there is no entry."""
    if not e:
        return "—"
    value = e.get("value")
    if value is not None and e.get("sense") == "cw":
        value = -value
    return number(value, lang=lang)


LAB_LIMIT = 5.0    # the lab's limit of an error, % (REFERENCE §1.6): a cell past it is marked
MARK = "*"


def _length(e: dict) -> float | None:
    """The drawn length an entry is read from: its own mm, or for ω, ε the relative vector's."""
    return e.get("mm") if e.get("mm") is not None else e.get("from_mm")


def why(e: dict, sym: str, pos: dict, plan: str, lang: str) -> str:
    """Why an entry misses the lab's 5 %: a vector drawn shorter than ``SHORT_MM`` (its ±½ division
    is a large share of it), direction lines crossing at a small angle on its plan (the plan's
    warnings), else the ruler's precision."""
    w = lambda key, **f: word(f"kin {key}", lang, **f)  # noqa: E731
    mm = _length(e)
    if mm is not None and mm < SHORT_MM:
        return w('why_short' if e.get("mm") is not None else 'why_short_from', sym=sym, mm=num(mm, lang, 3))
    angles = [a["angle_deg"] for a in pos.get("warning_angles", []) if a["plan"] == plan and a["kind"] == "lines"]
    if angles:
        return w('why_angle', sym=sym, angle=fixed(min(angles), lang, 1))
    return w('why_ruler', sym=sym)


def footnoted(rec: Record, notes: list[str], size: float = 2.5) -> Record:
    """A table with its footnotes under it (wrapped to the table's width): what its marks mean."""
    if not notes:
        return rec
    from graphplan.sheets.form import wrap
    from graphplan.graphic.record import line_pitch
    x0, y0, x1, _ = rec.bounds()
    y = y0 - 2.0 - size                        # the first line's capitals 2 mm under the table's rule
    for note in notes:
        for line in wrap(note, max(x1 - x0, 80.0), size):
            rec.label((x0, y), line, size=size, layer="tables")
            y -= line_pitch(size)
    return rec


def velocity_table(doc: dict, lang: str, precision: float = 0.5) -> Record:
    """Table 1: the plans' velocities (graphical) at every position, like seed 004's table 3, with
    the row's largest error; ω signed (+ counter-clockwise); a row's error past the lab's 5 % is
    marked and its footnote says which vector and why."""
    w = lambda key, **f: word(f"kin {key}", lang, **f)  # noqa: E731
    keys = velocity_columns(doc, precision)
    head = ["№", "φ, °"] + [_symbol(k, "v") for k in keys] + ["δ_{max}, %"]
    rows = [head]
    notes = []
    for pos in doc["positions"]:
        err = row_error(pos, keys)
        cell = percent(err, lang=lang)
        if err is not None and err > LAB_LIMIT:
            cell += MARK
            key = worst(pos, keys)
            notes.append(w('mark_row', n=pos["index"], why=why(pos["velocity"][key], _symbol(key, "v"), pos,
                                                                "velocity", lang)))
        rows.append([str(pos["index"]), fixed(pos['phi_deg'], lang, 1)]
                    + [_cell(pos["velocity"].get(k), precision, lang) for k in keys] + [cell])
    widths = [8.0, 13.0] + [max(14.0, text_width(_symbol(k, "v"), 2.5) + 3) for k in keys] + [15.0]
    rec = table(rows, widths, row_h=6.0, size=2.5, title=w('vel_table_signed'))
    return footnoted(rec, [w('mark_head')] + notes if notes else [])


def worst(pos: dict, keys: list[str] | None = None, kind: str = "velocity") -> str:
    """The key of a position's largest |δ| (velocities, or ``kind``)."""
    errs = {k: abs(e["error_pct"]) for k, e in pos[kind].items() if (keys is None or k in keys) and judged(e)}
    return max(errs, key=errs.get)


def row_error(pos: dict, keys: list[str] | None = None, shortest: float = 0.0) -> float | None:
    """The largest |δ| of a position's velocities (of vectors at least ``shortest`` mm long; ω by
    the relative velocity it is read from)."""
    errs = [abs(e["error_pct"]) for k, e in pos["velocity"].items()
            if (keys is None or k in keys) and judged(e) and (_length(e) is None or _length(e) >= shortest)]
    return max(errs) if errs else None


def judged(e: dict) -> bool:
    """Whether an entry's δ means anything: it has one, and the ruler read the vector (a vector
    read as 0 mm, shorter than half a division, has no percent error — "—")."""
    return e.get("error_pct") is not None and e.get("value") != 0


def acceleration_table(pos: dict, n: int, lang: str, precision: float = 0.5) -> Record:
    """Table 2.n: one acceleration plan: drawn mm, graphical value, analytic value and δ, %; ε
    signed (+ counter-clockwise); a vector read as 0 mm is 0; an analytic value below its column's
    resolution is 0; an error past the lab's 5 % is marked, its footnote says why. The force
    position (no index) is named by the crank's turn from position 0, as the scene gives it."""
    w = lambda key, **f: word(f"kin {key}", lang, **f)  # noqa: E731
    rows = [[w('quantity'), unit("mm", lang), w('graphical'), w('analytic'), w('error')]]
    items = list(pos.get("acceleration", {}).items())
    exact = column([(-1.0 if e.get("sense") == "cw" else 1.0) * e["analytic"] if e.get("analytic") is not None
                    else None for _, e in items], lang)
    notes = []
    for (key, e), analytic in zip(items, exact):
        cell = percent(e.get("error_pct") if judged(e) else None, lang=lang)
        if judged(e) and abs(e["error_pct"]) > LAB_LIMIT:
            cell += MARK
            notes.append(w('mark_cell', why=why(e, _symbol(key, "a"), pos, "acceleration", lang)))
        rows.append([_symbol(key, "a"), "—" if e.get("mm") is None else number(e["mm"], 4, lang=lang),
                     _cell(e, precision, lang), analytic, cell])
    if pos["index"] is not None:
        where = pos["index"]
    else:
        where = w('turn_at', turn=num(pos.get("turn_deg", pos["phi_deg"]), lang, 4),
                  phi=fixed(pos['phi_deg'], lang, 1))
    rec = table(rows, [22.0, 14.0, 20.0, 20.0, 14.0], row_h=6.0, size=2.5,
                title=w('acc_table_signed', n=n, i=where))
    return footnoted(rec, [w('mark_head')] + notes if notes else [])


def link_lengths(st: Study) -> list[tuple[str, float]]:
    """Every link's dimensions: the crank, each pair of joints on a link, the frame's pivots' distances."""
    mech = st.mech
    out: list[tuple[str, float]] = [(mech.crank.pivot + mech.crank.pin, mech.crank.length)]
    for name, link in mech.links.items():
        if name == mech.crank.link:
            continue
        pts = [p for p in link.local if p in link.joints or p in mech.frame]
        for a, b in zip(pts, pts[1:]):
            d = abs(link.local[a] - link.local[b])
            if d > 0:
                out.append((a + b, d))
    frame = [p for p in mech.frame if any(p in l.joints for l in mech.links.values())]
    for a, b in zip(frame, frame[1:]):
        d = abs(mech.frame[a] - mech.frame[b])
        if d > 0:
            out.append((a + b, d))
    return out


def dimensions_table(st: Study, mu_l: float, lang: str) -> Record:
    """Seed 000's table 2.1 / seed 002's measured dimensions: each length real and drawn at μl."""
    w = lambda key, **f: word(f"kin {key}", lang, **f)  # noqa: E731
    rows = [[w('link'), w('real'), w('drawn')]]
    for name, length in link_lengths(st):
        rows.append([name, number(length, 4, lang=lang), number(length / mu_l, 4, lang=lang)])
    return table(rows, [18.0, 18.0, 22.0], row_h=6.0, size=2.5, title=w('dims'))


def lab_table(diag, lang: str) -> Record | None:
    """Seed 002's table: s, v, a of the output at the lab's given positions — the diagrams'
    ordinates (mm), the graphical and the exact values' errors — one sign convention (the values'
    along the guide, the ordinates too: a mirrored diagram's ordinate is written with the value's
    sign) and the units in the header; an error past the lab's 5 % is marked, its footnote says why
    (the chords' own error of coarse divisions, a short ordinate, or the ruler)."""
    import numpy as np
    w = lambda key, **f: word(f"kin {key}", lang, **f)  # noqa: E731
    chosen = [k for k in range(len(diag.position)) if diag.position[k] in diag.chosen]
    if not chosen:
        return None
    vals = diag.values()
    s_, v_, a_ = diag.symbols
    mm = unit("mm", lang)
    units = ("m", "m/s", "m/s²") if diag.unit == "m" else ("rad", "rad/s", "rad/s²")
    us, uv, ua = (unit(u, lang) for u in units)
    rows = [[w('no'), "φ, °", f"{s_}, {mm}", f"{s_}, {us}", f"{v_}, {mm}", f"{v_}, {uv}", f"δ_{v_}, %",
             f"{a_}, {mm}", f"{a_}, {ua}", f"δ_{a_}, %"]]
    ev, ea = diag.errors_pct("v_at"), diag.errors_pct("a_at")
    own = {"v_at": diag.errors_pct("v_at", diag.exact), "a_at": diag.errors_pct("a_at", diag.exact)}
    r, k_ = diag.drawn, diag.sign
    notes = []

    def pct(key: str, errs, k: int, ordinate: float, sym: str) -> str:
        e = None if not np.isfinite(errs[k]) else float(errs[k])
        cell = percent(e, lang=lang)
        if e is not None and abs(e) > LAB_LIMIT:
            o = float(own[key][k])
            if np.isfinite(o) and abs(o) > LAB_LIMIT:
                reason = w('why_chords', sym=sym, e=fixed(o, lang, 1).replace("-", "−"), n=diag.divisions)
            elif abs(ordinate) < SHORT_MM:
                reason = w('why_ordinate', sym=sym, mm=num(abs(ordinate), lang, 3))
            else:
                reason = w('why_ruler', sym=sym)
            notes.append(w('mark_row', n=diag.position[k], why=reason))
            cell += MARK
        return cell

    for k in chosen:
        rows.append([str(diag.position[k]), fixed(diag.phi[k], lang, 1),
                     number(k_ * r.s[k], 3, lang=lang), number(vals["s"][k], lang=lang),
                     number(k_ * r.v_at[k], 3, lang=lang), number(vals["v_at"][k], lang=lang),
                     pct("v_at", ev, k, r.v_at[k], v_),
                     number(k_ * r.a_at[k], 3, lang=lang), number(vals["a_at"][k], lang=lang),
                     pct("a_at", ea, k, r.a_at[k], a_)])
    rec = table(rows, [9.0, 13.0, 14.0, 16.0, 14.0, 16.0, 14.0, 14.0, 18.0, 14.0], row_h=6.0, size=2.5,
                title=w('lab'))
    said = ([w('mark_head')] + notes if notes else []) + ([w('lab_mirrored')] if k_ < 0 else [])
    return footnoted(rec, said)


def notes(st: Study, scales: list[str], extra: list[str], lang: str) -> Record:
    """The structural formula, the mobility and the scale coefficients as lines of text."""
    w = lambda key, **f: word(f"kin {key}", lang, **f)  # noqa: E731
    s = st.structure
    lines = [f"{w('mobility')}: W = 3n − 2p_5 − p_4 = 3·{s.n} − 2·{s.p5} − {s.p4} = {s.mobility}",
             f"{w('structure')}: {s.formula}  ("
             + ", ".join(f"{d.label} {pair_kind(d.kind, lang)}" for d in s.dyads) + ")",
             f"{w('scales')}: " + "; ".join(scales)] + extra
    rec = Record("notes")
    for k, line in enumerate(lines):
        rec.label((0.0, -7.0 * k), line, size=3.5, layer="labels")
    return rec


def fields(st: Study, lang: str, scale: str, sheet_no: int = 1, sheets: int = 1,
           subtitle: str | None = None) -> dict[str, str]:
    """The title block's fields from the scene's title and [sheet] table: the organisation's field
    carries the organisation and the student's group ("НУБіП України, гр. МБ-21")."""
    meta = st.mech.task.meta
    title = meta.get("title_en", meta.get("title", st.mech.title)) if lang == "en" else \
        meta.get("title", st.mech.title)
    org, group = meta.get("sheet.organisation", ""), meta.get("sheet.group", "")
    if group:
        org = ", ".join(x for x in (org, word("kin group", lang, g=group)) if x)
    return {"designation": escape(meta.get("designation", "")), "title": escape(title),
            "student": escape(meta.get("sheet.student", "")), "teacher": escape(meta.get("sheet.teacher", "")),
            "organisation": escape(org),
            "scale": scale, "sheet": str(sheet_no), "sheets": str(sheets),
            "subtitle": subtitle or word("kin subtitle", lang)}


def sign_note(st: Study, diag, lang: str) -> str:
    """One sign convention, said on the sheet: s, v, a are signed along the output's guide (a
    rocker: counter-clockwise) everywhere; the diagrams are drawn so the stroke from position 0
    rises, which for some outputs mirrors them."""
    w = lambda key, **f: word(f"kin {key}", lang, **f)  # noqa: E731
    out = st.output
    if out.kind == "slide":
        import math
        slider = next(link for link in st.mech.links.values()
                      if link.slides_on is not None and next(iter(link.local)) == out.name)
        guide = st.mech.guides[slider.slides_on]
        said = w('signs', guide=f"{escape(guide.title(lang))} ({num(math.degrees(guide.angle) % 360, lang)}°)")
    else:
        said = w('signs_link', link=escape(out.name))
    return said + (w('flipped') if diag.sign < 0 else "")


def table_errors(doc: dict, precision: float, shortest: float) -> list[float]:
    """Every |δ| the tables 1 and 2 print (velocities; accelerations the ruler read), of vectors at
    least ``shortest`` mm long — ω and ε by the relative vector they are read from."""
    out = []
    keys = velocity_columns(doc, precision)
    for pos in doc["positions"]:
        e = row_error(pos, keys, shortest)
        if e is not None:
            out.append(e)
        for a in pos.get("acceleration", {}).values():
            mm = _length(a)
            if not judged(a) or (mm is not None and (mm < precision or mm < shortest)):
                continue
            out.append(abs(a["error_pct"]))
    return out


# -- the composition: zones by construction, scales by arithmetic (docs/composition.md) -------------

FAMILIES = ("position", "velocity", "acceleration")
LEGIBLE_MM = 40.0      # a set's plans: the crank pin's vectors p_v a and π a drawn at least this long
ONE_SHEET = ("A1",)    # the coursework's format: one sheet, the plans smaller if they must be
SET_LARGEST = 1.25     # a set's principal segments grow to at most this times the targets' upper end
DIAGRAM_SIZES = (1.0, 0.8, 0.64, 0.5)   # the diagrams drawn smaller only where a sheet cannot hold them
S_HEIGHT = 80.0        # mm: the s diagram drawn at most this high (μs from the standard series)
POLES = (15.0, 50.0)   # the lab manual's pole distances H1, H2, mm
SHARE = 0.6            # an unset pole distance draws the v or a peak about this share of the s diagram's
TARGETS = {"position": 70.0, "velocity": 100.0, "acceleration": 120.0}   # principal segments at factor 1, mm


def diagram_options(st: Study, k: float = 1.0, positions: int | None = None) -> dict:
    """The diagrams' L, s height and pole distances: the scene's L (× k where a small sheet needs it),
    the s diagram at most ``S_HEIGHT`` × k high; H1, H2 the scene's where it gives them, else chosen
    (whole mm, within the lab's 15–50 mm) so the v or a peak is about ``SHARE`` of the s diagram:
    v_mm = v·μt·H1/μs, a_mm = a·μt·H2/μv, μt = T/L (REFERENCE §1.5). No language enters."""
    from graphplan.graphic.diagrams import chord_diagrams
    dg = st.mech.task.diagram
    out: dict = {"point": dg.get("point"), "divisions": positions or dg.get("divisions") or st.mech.task.count,
                 "L": float(dg.get("L_mm", 240.0)) * k, "H1": float(dg.get("H1_mm", 30.0)),
                 "H2": float(dg.get("H2_mm", 30.0)), "height": S_HEIGHT * k}
    if "H1_mm" in dg and "H2_mm" in dg:
        return out
    probe = chord_diagrams(st, precision=0.0, **out)
    s_mm = float(max(abs(probe.exact.s.max() - probe.exact.s.min()), 1e-9))

    def pole(peak: float, mu_before: float) -> float:
        if peak <= 0:
            return POLES[0]
        return float(min(POLES[1], max(POLES[0], round(SHARE * s_mm * mu_before / (peak * probe.mu_t)))))
    if "H1_mm" not in dg:
        out["H1"] = pole(probe.maxima["v"], probe.mu_s)
    if "H2_mm" not in dg:
        out["H2"] = pole(probe.maxima["a"], probe.mu_s / (probe.mu_t * out["H1"]))
    return out


def _geometry(rec: Record) -> tuple[float, float]:
    """The size of a drawing's lines (its lettering left out), mm."""
    b = Record(items=[p for p in rec.items if p.kind != "text"]).bounds()
    return b[2] - b[0], b[3] - b[1]


def _size(rec: Record) -> tuple[float, float]:
    b = rec.bounds()
    return b[2] - b[0], b[3] - b[1]


@dataclass
class Natural:
    """The drawings' natural sizes, measured once at trial scales — what the arithmetic needs: the
    plans' families (position, velocity, acceleration; sheets.compose.Family), the diagrams' size
    per size factor, the tables' sizes per lettering factor (in order) and the notes' lines — each
    the larger of the two languages, so no scale depends on the language."""
    families: dict[str, Family]
    diagrams: dict[float, tuple[float, float]]
    tables: dict[float, list[tuple[str, float, float]]]
    notes: list[list[str]]

    @property
    def count(self) -> dict[str, int]:
        return {name: len(fam.sizes) for name, fam in self.families.items()}

    def leaf(self, family: str, mu: float, name: str = "") -> Leaf:
        """The family's cell at μ: its largest drawing with lettering and caption."""
        return self.families[family].leaf(mu, name or family)

    def drawn(self, family: str, mu: float) -> float:
        """The principal segment drawn at μ, mm."""
        return self.families[family].drawn(mu)

    def notes_height(self, width: float) -> float:
        return notes_height(self.notes, width)


def _captions(st: Study, plans, lang: str, mu: dict[str, float]) -> dict[str, list[tuple[str, str]]]:
    """Each drawing's caption (name, second line) in ``lang``."""
    from graphplan.graphic.scales import format_scale
    w = lambda key, **f: word(f"kin {key}", lang, **f)  # noqa: E731
    out: dict[str, list[tuple[str, str]]] = {"position": [(w('positions'), format_scale('mu_l', mu["position"], lang))]}
    out["velocity"] = [(f"{w('velocity')} {q.index if q.index is not None else ''}".rstrip(), "")
                       for q in plans.positions]
    out["acceleration"] = [
        (f"{w('acceleration')}, {w('position')} {q.index}" if q.index is not None else w('acceleration'),
         f"{format_scale('mu_a', mu['acceleration'], lang)},  φ = {fixed(q.phi % 360, lang, 1)}°")
        for q in plans.positions if q.acceleration is not None]
    return out


def _tables(st: Study, plans, diag, lang: str, p: float, factor: float) -> list[tuple[str, Record]]:
    """The sheet's tables in reading order: 1 velocities, 2.n accelerations, 3 dimensions, 4 the
    lab's s, v, a (a lab of at most 8 positions)."""
    from graphplan.report.plans import plans_json
    doc = plans_json(plans)
    out = [("velocity table", velocity_table(doc, lang, p))]
    n = 0
    for q, pos in zip(plans.positions, doc["positions"]):
        if q.acceleration is not None:
            n += 1
            out.append((f"acceleration table {n}", acceleration_table(pos, n, lang, p)))
    out.append(("dimensions table", dimensions_table(st, plans.mu_l, lang)))
    if st.mech.task.count <= 8:
        lab = lab_table(diag, lang)
        if lab is not None:
            out.append(("lab table", lab))
    return [(name, enlarged(rec, factor)) for name, rec in out]


def _notes_lines(st: Study, plans, diag, lang: str, p: float) -> list[str]:
    """The notes' lines: mobility, structure, scales, precision, the largest errors, the signs."""
    from graphplan.graphic.scales import format_scale
    from graphplan.report.diagrams import sheet_notes
    from graphplan.report.plans import plans_json
    w = lambda key, **f: word(f"kin {key}", lang, **f)  # noqa: E731
    doc = plans_json(plans)
    scales = [format_scale(m, v, lang) for m, v in (("mu_l", plans.mu_l), ("mu_v", plans.mu_v), ("mu_a", plans.mu_a))]
    scales.append(f"μ_t = {num(diag.mu_t, lang)} {unit('s/mm', lang)}")
    extra = [f"{w('precision')}: {num(p, lang)} {unit('mm', lang)}"]
    every = table_errors(doc, p, 0.0)
    long_ = table_errors(doc, p, SHORT_MM)
    if every:
        extra.append(f"{w('max_error')}: {fixed(max(every), lang, 2)} %"
                     + (f" ({w('max_error_20')}: {fixed(max(long_), lang, 2)} %)" if long_ else ""))
    extra.append(w('dash'))
    extra.append(sign_note(st, diag, lang))
    return lines_of(notes(st, scales, extra + sheet_notes(diag, lang), lang))


@dataclass
class Drafter:
    """Draws what the kinematics sheet holds, remembering it: the plans at given scales, the
    diagrams at a size factor."""
    st: Study
    opts: SheetOptions

    def __post_init__(self) -> None:
        self.memo: dict = {}

    def _once(self, key, make):
        if key not in self.memo:
            self.memo[key] = make()
        return self.memo[key]

    def plans(self, mu: dict[str, float] | None = None):
        from graphplan.graphic.plans import build_plans
        o = self.opts
        kw = {} if mu is None else {"mu_l": mu["position"], "mu_v": mu["velocity"], "mu_a": mu["acceleration"]}
        key = ("plans",) + tuple(sorted(kw.items()))
        return self._once(key, lambda: build_plans(self.st, count=o.positions, accel=_accel_arg(o.accel),
                                                   precision=o.precision, **kw))

    def diagrams(self, k: float, lang: str = "uk"):
        from graphplan.graphic.diagrams import chord_diagrams
        o = self.opts
        return self._once(("diag", k, lang), lambda: chord_diagrams(
            self.st, precision=o.precision, lang=lang, **diagram_options(self.st, k, o.positions)))

    def lines(self, mu: dict[str, float]) -> dict[str, list[Record]]:
        """The plans at the scales ``mu``, their lines only (no lettering): family → records."""
        from graphplan.drawing.plans import position_record
        pl = self.plans(mu)
        return {"position": [position_record(pl, lettered=False)],
                "velocity": [q.velocity.record for q in pl.positions if q.velocity is not None],
                "acceleration": [q.acceleration.record for q in pl.positions if q.acceleration is not None]}

    def records(self, mu: dict[str, float]) -> dict[str, list[Record]]:
        """The plans at the scales ``mu``, drawn and lettered (no captions): family → records."""
        from graphplan.drawing.plans import acceleration_records, position_record, velocity_records
        key = ("records",) + tuple(sorted(mu.items()))

        def make():
            pl = self.plans(mu)
            return {"position": [position_record(pl)], "velocity": list(velocity_records(pl).values()),
                    "acceleration": list(acceleration_records(pl).values())}
        return self._once(key, make)

    def diagram_record(self, k: float, lang: str) -> Record:
        from graphplan.drawing.diagrams import draw
        return self._once(("drec", k, lang), lambda: captioned(draw(self.diagrams(k, lang), lang),
                                                                word("kin diagrams", lang)))


def measure(dr: Drafter) -> Natural:
    """The natural sizes (``Natural``): the plans drawn once at their own scales, the diagrams, the
    tables and the notes in both languages."""
    from graphplan.util.words import LANGS
    st = dr.st
    pl = dr.plans()
    mech = st.mech
    mu0 = {"position": pl.mu_l, "velocity": pl.mu_v, "acceleration": pl.mu_a}
    recs = dr.lines(mu0)          # the lettering is allowed for (LETTERING) and checked once drawn
    v_a = abs(mech.omega1) * mech.crank.length
    a_a = mech.crank.length * (mech.omega1 ** 4 + mech.crank.epsilon ** 2) ** 0.5
    principal = {"position": mech.crank.length, "velocity": v_a, "acceleration": a_a}
    families = {fam: measured(rs, mu0[fam], [c for lang in LANGS for c in _captions(st, pl, lang, mu0)[fam]],
                              principal=principal[fam], target=TARGETS[fam], lettering=LETTERING)
                for fam, rs in recs.items()}
    diag = dr.diagrams(1.0)
    tables = {}
    for factor in (TABLES, 1.0):
        per = [[(name, *_size(rec)) for name, rec in _tables(st, pl, diag, lang, dr.opts.precision, factor)]
               for lang in LANGS]
        tables[factor] = [(a[0], max(a[1], b[1]), max(a[2], b[2])) for a, b in zip(*per)]
    notes_ = [_notes_lines(st, pl, dr.diagrams(1.0, lang), lang, dr.opts.precision) for lang in LANGS]
    return Natural(families, {}, tables, notes_)


def diagrams_size(dr: Drafter, nat: Natural, k: float) -> tuple[float, float]:
    """The diagrams' block at size factor k (the larger of the two languages)."""
    from graphplan.util.words import LANGS
    if k not in nat.diagrams:
        sizes = [_size(dr.diagram_record(k, lang)) for lang in LANGS]
        nat.diagrams[k] = (max(s[0] for s in sizes), max(s[1] for s in sizes))
    return nat.diagrams[k]


def _tree(shape: str, P, D, vgrid: Grid | None, agrid: Grid | None, C):
    """The sheet's composition (C: the tables' column with the notes over the title block, in the
    bottom-right corner): "bands" — position plan and diagrams across the top, under them the
    velocity plans, the acceleration plans and the column; "column" — the column the sheet's full
    height, the rest in those two bands; "accel" — the acceleration plans beside the position plan
    and the diagrams, the velocity plans beside the column; "sides" — the position plan over the
    velocity plans, beside them the diagrams over the acceleration plans over the column."""
    vg = [vgrid] if vgrid is not None else []
    ag = [agrid] if agrid is not None else []
    if shape == "bands":
        return Stack([Row([P, D]), Row(vg + ag + [C], flush=True)], flush=True)
    if shape == "column":
        return Row([Stack([Row([P, D]), Row(vg + ag)]), C], flush=True)
    if shape == "accel":
        return Stack([Row([P, D] + ag), Row(vg + [C], flush=True)], flush=True)
    return Row([Stack([P] + vg), Stack([D] + ag + [C], flush=True)], flush=True)


SHAPES = ("bands", "column", "accel", "sides")
LETTERING = 14.0     # mm a plan's lettering is assumed to add across and up before it is placed


@dataclass
class Plan:
    """The kinematics sheet as composed by arithmetic: the scales (μ per family), the diagrams'
    size factor, the tables' lettering factor, the composition's shape, grid columns and table
    columns, and the number of sheets (a set: more than 1)."""
    mu: dict[str, float]
    diagrams: float
    tables: float
    shape: str = "bands"
    vcols: int = 1
    acols: int = 1
    parts: int = 1
    sheets: int = 1
    counts: tuple[int, ...] = ()     # the tables in each of the column's parts, in reading order


TITLE = 185.0     # the title block's width: the column is at least this wide


def column_leaf(f: Form, tables: list[Leaf], parts: int, notes_height, counts: tuple[int, ...] = ()
                ) -> tuple[Leaf, list[list[Leaf]], float]:
    """The tables in ``parts`` columns (``counts`` tables each, where the plan found them) with the
    notes under them and the title block's room at the foot, as one leaf for the composition; its
    table groups and its width."""
    from graphplan.sheets.compose import keep_out
    groups = split(tables, parts, counts=counts)
    cw, ch = column_size(groups)
    width = max(cw, TITLE)
    foot = keep_out(f)[3] - field_of(f)[1]
    return Leaf("column", width, ch + GAP + notes_height(width) + GAP + foot), groups, width


def _grids(n: int) -> list[int]:
    """Column counts of a grid of n cells that give different row counts."""
    out, seen = [], set()
    for c in range(n, 0, -1):
        r = -(-n // c)
        if r not in seen:
            seen.add(r)
            out.append(c)
    return out or [1]


def _one_sheet(dr: Drafter, nat: Natural, f: Form) -> Plan | None:
    """The best one-sheet composition: for each lettering of the tables, each shape and each order
    of growth, the scales by ``choose_levels``; the one whose plans are drawn largest (the product
    of the principal segments), 3.5 mm tables where they cost no drawing a step."""
    x0, y0, x1, y1 = field_of(f)
    W, H = x1 - x0, y1 - y0
    has_a = nat.count["acceleration"] > 0
    D = Leaf("diagrams", *diagrams_size(dr, nat, 1.0))
    nv, na = nat.count["velocity"], nat.count["acceleration"]
    best = None
    for factor in (TABLES, 1.0):
        tabs = [Leaf(name, w, h) for name, w, h in nat.tables[factor]]
        cols = [column_leaf(f, tabs, parts, nat.notes_height)[0] for parts in (1, 2, 3)][:max(1, len(tabs))]

        def arranged(mu, shape, best_fill=False):
            P = nat.leaf("position", mu["position"])
            V = [nat.leaf("velocity", mu["velocity"])] * nv
            A = [nat.leaf("acceleration", mu["acceleration"])] * na
            vgrids = {vc: Grid(V, vc) for vc in _grids(nv)} if V else {1: None}
            agrids = {ac: Grid(A, ac) for ac in _grids(na)} if A else {1: None}
            found = None
            for vc, vg in vgrids.items():
                for ac, ag in agrids.items():
                    for parts, C in enumerate(cols, 1):
                        tw, th = extent(_tree(shape, P, D, vg, ag, C))
                        if tw <= W + 1e-9 and th <= H + 1e-9:
                            if not best_fill:
                                return (0.0, vc, ac, parts)
                            fill = min(W / tw, H / th)
                            if found is None or fill > found[0] + 1e-9:
                                found = (fill, vc, ac, parts)
            return found

        for shape in SHAPES:
            mu = choose_levels(nat.families, lambda m, s=shape: arranged(m, s) is not None,
                               ("velocity", "position", "acceleration"))
            if mu is None:
                continue
            rel = [nat.families[fam].rel(mu[fam]) for fam in FAMILIES if fam != "acceleration" or has_a]
            score = (round(min(rel), 6), round(sum(math.log(r) for r in rel), 6), factor == TABLES,
                     -SHAPES.index(shape))
            _, vc, ac, parts = arranged(mu, shape, best_fill=True)
            counts = tuple(len(g) for g in split(tabs, parts))
            cand = (score, Plan(mu, 1.0, factor, shape, vc, ac, parts, 1, counts))
            if best is None or cand[0] > best[0]:
                best = cand
    return best[1] if best else None


def legible(nat: Natural, mu: dict[str, float]) -> bool:
    """Whether the plans draw the crank pin's velocity and acceleration at least ``LEGIBLE_MM`` long."""
    return nat.drawn("velocity", mu["velocity"]) >= LEGIBLE_MM - 1e-9 and (
        nat.count["acceleration"] == 0 or nat.drawn("acceleration", mu["acceleration"]) >= LEGIBLE_MM - 1e-9)


def _set_rows(nat: Natural, mu: dict[str, float], dsize, factor: float, width: float) -> list[list[Leaf]]:
    """A set's drawings and tables as rows in reading order: the position plan and the diagrams,
    the velocity plans as many equal cells to a row as the sheet's width holds, the acceleration
    plans likewise, the tables and the notes (rows wrap where too wide)."""
    rows: list[list[Leaf]] = [[nat.leaf("position", mu["position"]), Leaf("diagrams", *dsize)]]
    for fam in ("velocity", "acceleration"):
        cell = nat.leaf(fam, mu[fam])
        k = max(1, int((width + GAP) // (cell.w + GAP)))
        n = nat.count[fam]
        rows += _grid_rows([Leaf(f"{fam} {i}", cell.w, cell.h) for i in range(n)], k)
    rows.append([Leaf(name, w, h) for name, w, h in nat.tables[factor]]
                + [Leaf("notes", TITLE, nat.notes_height(TITLE))])
    return rows


def _grid_rows(cells_: list[Leaf], k: int) -> list[list[Leaf]]:
    """Equal cells k to a row, the last row filled up with empty cells so the columns line up."""
    rows = [cells_[j:j + k] for j in range(0, len(cells_), k)]
    if rows and len(rows) > 1 and len(rows[-1]) < k:
        c = rows[-1][0]
        rows[-1] = rows[-1] + [Leaf("", c.w, c.h) for _ in range(k - len(rows[-1]))]
    return rows


def _legible(fam: Family) -> float:
    """The coarsest standard μ at which the family's principal segment is drawn ``LEGIBLE_MM`` long."""
    mu = fam.start(1.0)
    while fam.drawn(mu) < LEGIBLE_MM - 1e-9:
        mu = finer(mu)
    while fam.drawn(coarser(mu)) >= LEGIBLE_MM - 1e-9:
        mu = coarser(mu)
    return mu


def _set(dr: Drafter, nat: Natural, f: Form) -> Plan:
    """A set of sheets: the velocity and acceleration plans just legible, the position plan as large
    as a sheet holds (or a step or two smaller where that saves a sheet), the drawings and tables
    flowing over the sheets in reading order — the fewest sheets; then each family grown while the
    set needs no more sheets (up to ``SET_LARGEST`` times its target)."""
    from graphplan.sheets.compose import keep_out
    region = field_of(f)
    width, height = region[2] - region[0], region[3] - region[1]
    keep = keep_out(f)

    def alone(size) -> bool:              # fits an empty sheet beside or over the title block
        w, h = size
        return (w <= width and h <= keep[1] + height - keep[3]) or (w <= keep[0] - region[0] and h <= height)
    fams = nat.families
    floor = {fam: _legible(fams[fam]) for fam in ("velocity", "acceleration")}
    def fitted(fam: str, mu: float) -> float:
        """The finest μ from ``mu`` on at which the family fits an empty sheet; a family no μ fits
        (a size that does not shrink: lettering alone, or no finite size) is refused in one line."""
        for _ in range(90):                     # 30 decades of the standard series
            if alone(fams[fam].size(mu)):
                return mu
            mu = coarser(mu)
        raise PlansUndrawable(f"the {fam} plans cannot be drawn on a {f.name} sheet at any scale (a plan of "
                             "directions nearly parallel?); the terminal's commands take --format none",
                             dr.st.mech.source if hasattr(dr, "st") else None)
    for fam in floor:                       # … unless a plan that large fits no sheet
        floor[fam] = fitted(fam, floor[fam])
    top = fitted("position", fams["position"].start(2.0))
    best = None
    for k in [k for k in DIAGRAM_SIZES if alone(diagrams_size(dr, nat, k))] or DIAGRAM_SIZES[-1:]:
        dsize = diagrams_size(dr, nat, k)
        for factor in (TABLES, 1.0):
            def pages(mu):
                out = flow(_set_rows(nat, mu, dsize, factor, width), region, keep)
                return None if out is None else len(out)
            for mu_l in (top, coarser(top), coarser(coarser(top))):
                mu = {"position": mu_l, **floor}
                count = pages(mu)
                if count is None:
                    continue
                for fam in ("velocity", "acceleration", "position"):
                    while True:
                        bigger = finer(mu[fam])
                        if fams[fam].rel(bigger) > SET_LARGEST or pages({**mu, fam: bigger}) != count:
                            break
                        mu = {**mu, fam: bigger}
                rel = sum(math.log(fams[fam].rel(mu[fam])) for fam in FAMILIES) + math.log(k)
                key = (count, -(factor == TABLES), -rel)
                if best is None or key < best[0]:
                    best = (key, Plan(mu, k, factor, "set", 1, 1, 1, count))
    if best is None:
        raise GraphplanError(f"the drawings do not fit a {f.name} sheet even at the smallest scales; "
                             "choose a larger --format")
    return best[1]


def _checked(dr: Drafter, nat: Natural, p: Plan) -> bool:
    """Whether the drawings at the plan's scales are no larger than the arithmetic assumed; where one
    is, ``nat`` is corrected (the next choice allows for it). So are the tables and the notes
    (their millimetres and scales are the plan's)."""
    from graphplan.util.words import LANGS
    plans = dr.plans(p.mu)
    prec = dr.opts.precision
    ok = not grown(nat.tables[p.tables], [[(n, *_size(r)) for n, r in _tables(
        dr.st, plans, dr.diagrams(p.diagrams, lang), lang, prec, p.tables)] for lang in LANGS])
    drawn = [_notes_lines(dr.st, plans, dr.diagrams(p.diagrams, lang), lang, prec) for lang in LANGS]
    if notes_height(drawn, TITLE) > notes_height(nat.notes, TITLE) + 1e-6:
        nat.notes += drawn
        ok = False
    for fam, recs in dr.records(p.mu).items():
        family = nat.families[fam]
        for i, r in enumerate(recs):
            ok &= family.allow(p.mu[fam], *_size(r), i)
    return ok


@remembered
def plan(st: Study, f: Form, opts: SheetOptions) -> tuple[Plan, Natural, Drafter]:
    """The kinematics sheet's composition, once per scene, format and options (the language does
    not enter): one sheet where one holds the plans legibly (on A1 always), else a set. The plans
    are then drawn at the chosen scales and, where one came out larger than assumed, the choice is
    made again allowing for it (the sheet, the terminal and the explorer all get this result)."""
    dr = Drafter(st, SheetOptions(opts.positions, opts.accel, opts.precision, "uk", "kinematics"))
    nat = measure(dr)
    for _ in range(4):
        one = _one_sheet(dr, nat, f)
        p = one if one is not None and (f.name in ONE_SHEET or legible(nat, one.mu)) else _set(dr, nat, f)
        if _checked(dr, nat, p):
            break
    return p, nat, dr


def _options(opts: SheetOptions) -> SheetOptions:
    return SheetOptions(opts.positions, opts.accel, opts.precision, "uk", "kinematics")


def sheet_scales(st: Study, format: str = "A1", positions: int | None = None, accel=None,
                 precision: float = 0.5) -> dict[str, float]:
    """The scales the kinematics sheet of ``format`` draws with — μl, μv, μa of the plans and the
    diagrams' L, height, H1, H2 — for the terminal's ``plans``/``diagrams``, the API and the explorer
    to print what the sheet draws. Arithmetic on the drawings' sizes: no sheet is built. More
    positions than a sheet holds are refused first (the layout of 3600 plans would take minutes)."""
    check_positions(st, SheetOptions(positions=positions, accel=accel, precision=precision))
    p, _, _ = plan(st, form(format), SheetOptions(positions=positions, accel=accel, precision=precision))
    opts = diagram_options(st, p.diagrams, positions)
    return {"mu_l": p.mu["position"], "mu_v": p.mu["velocity"], "mu_a": p.mu["acceleration"],
            "L": opts["L"], "height": opts["height"], "H1": opts["H1"], "H2": opts["H2"]}


class PlansUndrawable(GraphplanError):
    """No standard scale draws a family of plans on the sheet (a size that does not shrink)."""


A1_POSITIONS = 40     # an A1 sheet holds about 40 velocity plans at a legible scale


def check_positions(st: Study, options) -> None:
    """A sheet set holds a bounded number of velocity plans (about 40, what an A1 sheet holds; a
    smaller format spreads them over more sheets): more is refused before any plan is built."""
    given = options_of(options).positions
    count = given or st.mech.task.count
    if count > A1_POSITIONS:
        key = f"--positions {count}" if given else f"positions.count = {count}"
        raise GraphplanError(f"{key}: a kinematics sheet holds at most {A1_POSITIONS} positions' plans "
                             "(one velocity plan a position); choose fewer positions, or --format none "
                             "for the plans at their own scales", st.mech.source)


def drawings(st: Study, p: Plan, dr: Drafter, lang: str) -> dict:
    """Everything the sheet draws at the plan's scales, in ``lang``: the position plan, the
    diagrams, each velocity plan and acceleration plan with its caption, the tables in order."""
    plans = dr.plans(p.mu)
    caps = _captions(st, plans, lang, p.mu)
    recs = dr.records(p.mu)
    diag = dr.diagrams(p.diagrams, lang)
    return {
        "plans": plans, "diag": diag,
        "position": captioned(recs["position"][0], *caps["position"][0]),
        "diagrams": dr.diagram_record(p.diagrams, lang),
        "velocity": [captioned(r, *c) for r, c in zip(recs["velocity"], caps["velocity"])],
        "acceleration": [captioned(r, *c) for r, c in zip(recs["acceleration"], caps["acceleration"])],
        "tables": _tables(st, plans, diag, lang, dr.opts.precision, p.tables),
        "notes": _notes_lines(st, plans, diag, lang, dr.opts.precision),
    }


def build_kinematics_sheet(st: Study, f: Form, options) -> Sheet:
    """Sheet 1: everything of the kinematic analysis at the scales ``plan`` chose, in the zones of the
    composition (one sheet), or flowing over a set of sheets."""
    from graphplan.sheets.compose import keep_out
    opts = options_of(options)
    check_positions(st, opts)
    p, nat, dr = plan(st, f, _options(opts))
    d = drawings(st, p, dr, opts.lang)
    region = field_of(f)
    P = Leaf("position plan", record=d["position"])
    D = Leaf("diagrams", record=d["diagrams"])
    V = cells([Leaf(f"velocity plan {q.key}", record=r) for q, r in zip(d["plans"].positions, d["velocity"])])
    A = cells([Leaf(f"acceleration plan {i + 1}", record=r) for i, r in enumerate(d["acceleration"])])
    tables = [Leaf(name, record=rec) for name, rec in d["tables"]]
    pages: list[list[Placed]]
    if p.sheets == 1:
        C, groups, width = column_leaf(f, tables, p.parts, lambda w: note_block(d["notes"], w).bounds()[3]
                                       - note_block(d["notes"], w).bounds()[1], p.counts)
        tree = _tree(p.shape, P, D, Grid(V, p.vcols) if V else None, Grid(A, p.acols) if A else None, C)
        items, col_box = [], None
        for leaf, b in arrange(tree, region):
            if leaf is C:
                col_box = b
            elif leaf.record is not None:
                items.append(Placed(leaf.name, centred(leaf.record, b), b))
        notes_rec = note_block(d["notes"], width)
        nb = notes_rec.bounds()
        foot = keep_out(f)[3]
        notes_box = (col_box[2] - width, foot, col_box[2], foot + nb[3] - nb[1])
        items.append(Placed("notes", top_left(notes_rec, notes_box), notes_box))
        items += set_columns(groups, col_box[2] - column_size(groups)[0], col_box[3])
        pages = [items]
    else:
        notes_rec = note_block(d["notes"], TITLE)
        rows: list[list[Leaf]] = [[P, D]]
        width = region[2] - region[0]
        for cells_ in (V, A):
            if cells_:
                rows += _grid_rows(cells_, max(1, int((width + GAP) // (cells_[0].w + GAP))))
        rows.append(tables + [Leaf("notes", record=notes_rec)])
        laid = flow(rows, region, keep_out(f))
        if laid is None:
            raise GraphplanError(f"a drawing is larger than a whole {f.name} sheet; choose a larger --format")
        pages = [[Placed(leaf.name, centred(leaf.record, b), b) for leaf, b in page if leaf.record is not None]
                 for page in laid]
    return compose(f, pages, fields(st, opts.lang, drawing_scale(p.mu["position"], opts.lang)), opts.lang,
                   st.mech.title)
