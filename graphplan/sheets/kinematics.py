"""The kinematics sheet (sheet 1 of the coursework, seeds 000 and 004; the lab report of seed 002):
the position plan, the velocity plan of every position, the acceleration plans asked for, the s–v–a
diagrams, the tables (velocities; one numbered table per acceleration plan; the links' dimensions;
the lab's s, v, a at the chosen positions) and the notes.

The scales are chosen once per scene and format (``choose``): the largest size factor of the
standard targets at which the whole fits one sheet with legible plans, each family of drawings then
grown to fill the field; when it does not fit, the smallest legible one for a set of sheets. The terminal
commands ask ``sheet_scales`` for the same numbers."""
from __future__ import annotations

from dataclasses import dataclass

from graphplan.drawing.layout import HULL, Block
from graphplan.exact.positions import Study
from graphplan.graphic.record import Record, text_width
from graphplan.report.plans import captioned
from graphplan.sheets.compose import (Sheet, SheetOptions, bare_share, beside, compose, drawing_scale,
                                      fits_one, fits_sheets, number, options_of, paginate, percent, reading, remembered,
                                      sampled)
from graphplan.sheets.form import TABLES, Form, enlarged, form, table
from graphplan.util.errors import GraphplanError
from graphplan.util.markup import escape
from graphplan.util.words import column, fixed, num, pair_kind, unit, word

FACTORS = (2.0, 1.6, 1.4, 1.25, 1.12, 1.0, 0.8, 0.64, 0.5, 0.4, 0.32)
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
    x0, y0, x1, _ = rec.bounds()
    y = y0 - 1.5 * size
    for note in notes:
        for line in wrap(note, max(x1 - x0, 80.0), size):
            rec.label((x0, y), line, size=size, layer="tables")
            y -= 1.6 * size
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


def flow(records: list[Record], width: float, gap: float = 6.0) -> Record:
    """Records left to right in order, wrapping into a new row at ``width`` mm (the velocity plans
    0, 1, 2 … read like a text)."""
    out = Record("flow")
    x = top = 0.0
    row_h = 0.0
    for rec in records:
        b = rec.bounds()
        w, h = b[2] - b[0], b[3] - b[1]
        if x > 0 and x + w > width:
            x, top, row_h = 0.0, top - row_h - gap, 0.0
        out.extend(rec.moved(x - b[0], top - b[3]))
        x += w + gap
        row_h = max(row_h, h)
    return out


# -- the blocks at a size factor -----------------------------------------------------------------

FAMILIES = ("position", "acceleration", "velocity", "diagrams")   # the order they are grown in
DIVISION_MM = 25.0   # the diagrams grow no wider than this many mm per division
SHARE = 0.6          # the v and a diagrams' peaks drawn at about this share of the s diagram's height


@dataclass
class Drawn:
    """Everything the kinematics sheet draws at the size factors ``k`` (one per family of blocks:
    the position plan, the velocity plans, the acceleration plans, the diagrams)."""
    k: dict[str, float]
    plans: object
    diag: object
    blocks: list[Block]


def diagram_options(st: Study, k: float, positions: int | None) -> dict:
    """The diagrams' L, height and pole distances at size factor k: L and the s diagram's height
    from the scene's [diagrams] table scaled by k; H1, H2 the scene's unless its v or a diagram
    would be drawn lower than a third of the s diagram or taller than it — then chosen (whole mm,
    5–80) so that its peak is about ``SHARE`` of the s diagram's height:
    v_mm = v·μt·H1/μs, a_mm = a·μt·H2/μv, μt = T/L (REFERENCE §1.5)."""
    from graphplan.graphic.diagrams import chord_diagrams
    dg = st.mech.task.diagram
    out: dict = {"point": dg.get("point"), "divisions": positions or dg.get("divisions") or st.mech.task.count,
           "L": float(dg.get("L_mm", 240.0)) * k, "H1": float(dg.get("H1_mm", 30.0)),
           "H2": float(dg.get("H2_mm", 30.0)), "height": 70.0 * k}
    probe = chord_diagrams(st, precision=0.0, **out)
    s_mm = probe.maxima["s"] / probe.mu_s

    def pole(given: float, peak: float, mu_before: float) -> float:
        drawn = peak * probe.mu_t * given / mu_before
        if peak <= 0 or s_mm / 3 <= drawn <= 1.2 * s_mm:
            return given
        return float(min(80.0, max(5.0, round(SHARE * s_mm * mu_before / (peak * probe.mu_t)))))
    out["H1"] = pole(out["H1"], probe.maxima["v"], probe.mu_s)
    mu_v = probe.mu_s / (probe.mu_t * out["H1"])
    out["H2"] = pole(out["H2"], probe.maxima["a"], mu_v)
    return out


class Drafter:
    """Draws the kinematics sheet's blocks at given size factors, remembering what it drew."""

    def __init__(self, st: Study, opts: SheetOptions, width: float, tables: float = 1.0):
        self.st, self.opts, self.width, self.tables = st, opts, width, tables
        self.memo: dict = {}

    def _once(self, key, make):
        if key not in self.memo:
            self.memo[key] = make()
        return self.memo[key]

    def plans(self, kp: float, kv: float, ka: float):
        from graphplan.graphic.plans import build_plans
        from graphplan.graphic.scales import Targets
        st, o = self.st, self.opts

        def at(k: float):
            return self._once(("plans", k), lambda: build_plans(
                st, count=o.positions, accel=_accel_arg(o.accel), precision=o.precision,
                targets=Targets().scaled(k)))
        mu = (at(kp).mu_l, at(kv).mu_v, at(ka).mu_a)
        return self._once(("fixed",) + mu, lambda: build_plans(
            st, count=o.positions, accel=_accel_arg(o.accel), precision=o.precision,
            mu_l=mu[0], mu_v=mu[1], mu_a=mu[2]))

    def diagrams(self, kd: float):
        from graphplan.graphic.diagrams import chord_diagrams
        o = self.opts
        return self._once(("diag", kd), lambda: chord_diagrams(
            self.st, precision=o.precision, lang=o.lang, **diagram_options(self.st, kd, o.positions)))

    def widest_diagrams(self) -> float:
        """The diagrams' largest factor: no division wider than ``DIVISION_MM``."""
        o = diagram_options(self.st, 1.0, self.opts.positions)
        n = o["divisions"] if isinstance(o["divisions"], int) else len(o["divisions"])
        return DIVISION_MM * n / o["L"]

    def drawn(self, k: dict[str, float]) -> Drawn:
        key = ("drawn",) + tuple(k[f] for f in FAMILIES)
        return self._once(key, lambda: drawn_at(self, k))


def drawn_at(dr: Drafter, k: dict[str, float]) -> Drawn:
    """The kinematics sheet's blocks at size factors k: the position plan with the links'
    dimensions, the diagrams (with the lab's table), each velocity plan, the velocity table, each
    acceleration plan beside its numbered table, and the notes."""
    from graphplan.drawing.diagrams import draw as draw_diagrams
    from graphplan.drawing.plans import acceleration_records, position_record, velocity_records
    from graphplan.graphic.scales import format_scale
    from graphplan.report.diagrams import sheet_notes
    from graphplan.report.plans import plans_json
    st, opts = dr.st, dr.opts
    lang, p = opts.lang, opts.precision
    w = lambda key, **f: word(f"kin {key}", lang, **f)  # noqa: E731
    plans = dr.plans(k["position"], k["velocity"], k["acceleration"])
    diag = dr.diagrams(k["diagrams"])
    doc = plans_json(plans)
    prec = captioned(position_record(plans), f"{w('positions')}, {format_scale('mu_l', plans.mu_l, lang)}")
    dims = enlarged(dimensions_table(st, plans.mu_l, lang), dr.tables)
    blocks = [Block("position plan", lambda _k: prec), Block("dimensions table", lambda _k: dims)]
    drec = draw_diagrams(diag, lang)
    lab = lab_table(diag, lang) if st.mech.task.count <= 8 else None
    lab = enlarged(lab, dr.tables) if lab is not None else None
    dblock = drec if lab is None else beside([drec], below=lab)
    blocks.append(Block("diagrams", lambda _k: dblock, solid=True))
    vrec = velocity_records(plans)
    cells = [captioned(vrec[q.key], f"{w('velocity')} {q.index if q.index is not None else ''}")
             for q in plans.positions]
    for q, cell in zip(plans.positions, cells):
        blocks.append(Block(f"velocity plan {q.key}", lambda _k, c=cell: c))
    vtab = enlarged(velocity_table(doc, lang, p), dr.tables)
    blocks.append(Block("velocity table", lambda _k: vtab))
    arec = acceleration_records(plans)
    n = 0
    for q, pos in zip(plans.positions, doc["positions"]):
        if q.acceleration is None:
            continue
        n += 1
        caption = (f"{w('acceleration')}, {w('position')} {q.index if q.index is not None else ''} "
                   f"(φ = {fixed(q.phi % 360, lang, 1)}°), {format_scale('mu_a', plans.mu_a, lang)}")
        both = beside([captioned(arec[q.key], caption), enlarged(acceleration_table(pos, n, lang, p), dr.tables)])
        blocks.append(Block(f"acceleration plan {q.key}", lambda _k, r=both: r, solid=HULL))

    def notes_block(_k: float) -> Record:
        scales = [format_scale(m, v, lang) for m, v in (("mu_l", plans.mu_l), ("mu_v", plans.mu_v),
                                                         ("mu_a", plans.mu_a))]
        scales.append(f"μ_t = {num(diag.mu_t, lang)} {unit('s/mm', lang)}")
        extra = [f"{w('precision')}: {num(p, lang)} {unit('mm', lang)}"]
        every = table_errors(doc, p, 0.0)
        long_ = table_errors(doc, p, SHORT_MM)
        if every:
            extra.append(f"{w('max_error')}: {fixed(max(every), lang, 2)} %"
                         + (f" ({w('max_error_20')}: {fixed(max(long_), lang, 2)} %)" if long_ else ""))
        extra.append(w('dash'))
        extra.append(sign_note(st, diag, lang))
        return notes(st, scales, extra + sheet_notes(diag, lang), lang)

    nrec = notes_block(1.0)
    blocks.append(Block("notes", lambda _k: nrec))
    return Drawn(dict(k), plans, diag, blocks)


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


# -- the scale choice, once per scene and format -----------------------------------------------------

def _same(k: float) -> dict[str, float]:
    return {f: k for f in FAMILIES}


LEGIBLE_MM = 60.0    # the crank's vectors p_v a and π a drawn at least this long where the sheet allows


def legible(d: Drawn) -> bool:
    """Whether the plans draw the crank pin's velocity and acceleration at least ``LEGIBLE_MM`` long."""
    pl = d.plans
    mech = pl.study.mech
    v_a = abs(mech.omega1) * mech.crank.length
    a_a = mech.crank.length * (mech.omega1 ** 4 + mech.crank.epsilon ** 2) ** 0.5
    return v_a / pl.mu_v >= LEGIBLE_MM - 1e-9 and (not pl.accel_keys or a_a / pl.mu_a >= LEGIBLE_MM - 1e-9)


SET_LARGEST = 1.25   # a set's drawings grow no larger than this: more sheets, not giant plans
ONE_SHEET = ("A1",)  # the coursework's format: one sheet, the plans smaller if they must be


@remembered
def choose(st: Study, f: Form, opts: SheetOptions) -> tuple[Drawn, bool]:
    """The scales, once per scene and format: the largest common size factor at which the plans
    stay legible (``legible``) and the whole fits one sheet of ``f`` — on A1 (the coursework's one
    sheet) the largest at which it fits at all; then each family grown in turn (position plan,
    acceleration plans, velocity plans, diagrams) while it still fits — the field filled. When no
    such drawing fits one sheet: the smallest legible factor whose blocks each fit a sheet, for a
    set of sheets, grown while the set needs no more sheets. The tables are lettered 3.5 mm
    (``TABLES``) unless that costs the set a further sheet. Returns the drawing and whether it is
    one sheet."""
    x0, y0, x1, y1 = f.frame_box
    big, small = (Drafter(st, opts, x1 - x0 - 10.0, t) for t in (TABLES, 1.0))
    for dr in (big, small):
        one = _one_sheet(dr, f)
        if one is not None:
            return one, True
    starts = [(dr, s) for dr, s in ((dr, _set_start(dr, f)) for dr in (big, small)) if s is not None]
    if not starts:
        return big.drawn(_same(FACTORS[-1])), False
    dr, (d, pages) = min(starts, key=lambda x: x[1][1])       # the fewer sheets; equal: the larger tables
    return grow(dr, d, lambda t: fits_sheets(f, t.blocks, pages), SET_LARGEST), False


def _one_sheet(dr: Drafter, f: Form) -> Drawn | None:
    """The fullest one-sheet drawing (see ``choose``); None when no legible one fits one sheet."""
    x0, y0, x1, y1 = f.frame_box
    free = (x1 - x0) * (y1 - y0) - 190.0 * 60.0
    base = dr.drawn(_same(1.0))
    area = sum((b[2] - b[0] + 8.0) * (b[3] - b[1] + 8.0) for b in (blk.build(1.0).bounds() for blk in base.blocks))
    one = lambda d: fits_one(f, d.blocks)  # noqa: E731
    for k in FACTORS:
        if area * k * k > 1.1 * free:
            continue
        d = dr.drawn(_same(k))
        if not legible(d) and f.name not in ONE_SHEET:
            break
        if one(d):
            path = [d]
            grow(dr, d, one, path=path)
            return min(sampled(path), key=lambda t: bare_share(f, t.blocks))
    return None


def _set_start(dr: Drafter, f: Form) -> tuple[Drawn, int] | None:
    """The smallest legible factor whose blocks each fit a sheet (the fewest sheets; the smallest
    that fits when none is legible), and the sheets it needs."""
    layable = []
    for k in FACTORS:
        d = dr.drawn(_same(k))
        try:
            paginate(f, d.blocks)
        except GraphplanError:
            continue
        layable.append(d)
    readable = [d for d in layable if legible(d)]
    if not layable:
        return None
    d = readable[-1] if readable else layable[0]
    return d, len(paginate(f, d.blocks))


def grow(dr: Drafter, d: Drawn, fits, largest: float = FACTORS[0], path: list | None = None) -> Drawn:
    """Each family in turn drawn at the next larger factors (up to ``largest``) while ``fits`` holds
    (each drawing on the way appended to ``path``)."""
    best = d
    for fam in FAMILIES:
        top = min(largest, dr.widest_diagrams()) if fam == "diagrams" else largest
        for k in sorted(x for x in FACTORS if best.k[fam] < x <= top):
            trial = dr.drawn({**best.k, fam: k})
            if not fits(trial):
                break
            best = trial
            if path is not None:
                path.append(best)
    return best


def sheet_scales(st: Study, format: str = "A1", positions: int | None = None, accel=None,
                 precision: float = 0.5) -> dict[str, float]:
    """The scales the kinematics sheet of ``format`` draws with: μl, μv, μa of the plans and the
    diagrams' L and height — for the terminal's ``plans``/``diagrams`` to print what the sheet draws."""
    d, _ = choose(st, form(format), SheetOptions(positions=positions, accel=accel, precision=precision))
    opts = diagram_options(st, d.k["diagrams"], positions)
    return {"mu_l": d.plans.mu_l, "mu_v": d.plans.mu_v, "mu_a": d.plans.mu_a,
            "L": opts["L"], "height": opts["height"], "H1": opts["H1"], "H2": opts["H2"]}


A1_POSITIONS = 40     # measured: A1 holds 36 velocity plans of the examples, never 48


def check_positions(st: Study, options) -> None:
    """A sheet set holds a bounded number of velocity plans (about 40, what an A1 sheet holds; a
    smaller format spreads them over more sheets): more is refused before any plan is built."""
    count = options_of(options).positions or st.mech.task.count
    if count > A1_POSITIONS:
        raise GraphplanError(f"--positions {count}: a kinematics sheet holds at most {A1_POSITIONS} "
                             "positions' plans; choose fewer positions", st.mech.source)


def build_kinematics_sheet(st: Study, f: Form, options) -> Sheet:
    """Sheet 1: everything of the kinematic analysis at the scales ``choose`` picks; a set of
    sheets when it does not fit one."""
    opts = options_of(options)
    check_positions(st, opts)
    d, _ = choose(st, f, opts)
    return compose(f, d.blocks, fields(st, opts.lang, drawing_scale(d.plans.mu_l, opts.lang)), opts.lang, st.mech.title)


def kinematics_blocks(st: Study, options, k: float, width: float = 780.0) -> tuple[list[Block], str]:
    """The blocks at size factor k and the title block's scale (kept for callers of the old API)."""
    d = Drafter(st, options_of(options), width).drawn(_same(k))
    return d.blocks, drawing_scale(d.plans.mu_l, options_of(options).lang)

