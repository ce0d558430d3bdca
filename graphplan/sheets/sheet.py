"""`graphplan sheet`: the drawing sheet — frame and title block, the position plan, the velocity and
acceleration plans, the s–v–a diagrams and the tables, laid out so nothing overlaps (REFERENCE §3).
The output's suffix picks SVG, PDF, PNG or DXF; every format views the same construction record."""
from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

import numpy as np

from graphplan.graphic.record import Record, text_width
from graphplan.util.errors import GraphplanError
from graphplan.util.markup import escape
from graphplan.util.words import fixed, force_symbol, num, pair_kind, pct, unit, word
from graphplan.drawing.layout import Block, Placed, declutter, place
from graphplan.exact.positions import Study
from graphplan.report.plans import captioned
from graphplan.sheets.form import Form, form, frame, table, title_block, title_block_box

FORMATS_OUT = (".svg", ".pdf", ".png", ".dxf")

# What a sheet is asked for: positions, accel (degrees or "#3"), precision (mm), lang, sheet (kind);
# the command line's namespace or any object with those attributes.
Options = Any


@dataclass
class Sheet:
    """A laid-out sheet: its form, the whole construction record and where each block went."""
    form: Form
    record: Record
    placed: list[Placed] = field(default_factory=list)
    lang: str = "uk"

    def svg(self, text_as_paths: bool = False) -> str:
        from graphplan.drawing.svg import render
        return render(self.record, self.form.width, self.form.height, self.record.title, text_as_paths)

    def write(self, path: str | Path, text_as_paths: bool = False, dpi: float = 300) -> Path:
        """Write the sheet; the suffix picks the format (PNG at ``dpi``). Whole files only."""
        from graphplan.util.files import write_atomic
        path = Path(path)
        suffix = path.suffix.lower()
        if suffix not in FORMATS_OUT:
            raise GraphplanError(f"-o {path}: unknown format {suffix or '(none)'!r}; use "
                                 + ", ".join(FORMATS_OUT))
        if suffix == ".dxf":
            from graphplan.drawing.dxf import to_dxf
            return write_atomic(path, to_dxf(self.record, self.form.width, self.form.height))
        if suffix == ".svg":
            return write_atomic(path, self.svg(text_as_paths))
        from graphplan.drawing.fonts import register
        from graphplan.drawing.raster import to_pdf, to_png
        svg = self.svg(text_as_paths or not register())   # no fontconfig: letter with outlines
        return write_atomic(path, to_pdf(svg) if suffix == ".pdf" else to_png(svg, dpi))


def fmt(v: float | None, lang: str, digits: int = 4) -> str:
    """Numbers for tables (util.words.num): 4 significant digits, the language's decimal sign, a
    true minus, '—' for none."""
    return num(v, lang, digits).replace("-", "−")


def velocity_table(doc: dict, lang: str) -> Record:
    """Table 1: the plans' velocities (graphical) at every position, like seed 004's table 3."""
    keys: list[str] = []
    for pos in doc["positions"]:
        for key in pos["velocity"]:
            if key not in keys:
                keys.append(key)
    head = ["№", "φ, °"] + [_symbol(k, "v") for k in keys] + ["δ_max, %"]
    rows = [head]
    for pos in doc["positions"]:
        errs = [abs(e["error_pct"]) for e in pos["velocity"].values() if e.get("error_pct") is not None]
        rows.append([str(pos["index"]), fixed(pos['phi_deg'], lang, 1)]
                    + [fmt(pos["velocity"].get(k, {}).get("value"), lang) for k in keys]
                    + [fixed(max(errs) if errs else None, lang, 2)])
    widths = [8.0, 13.0] + [max(14.0, text_width(_symbol(k, "v"), 2.5) + 3) for k in keys] + [15.0]
    return table(rows, widths, row_h=6.0, size=2.5, title=word("velocity table", lang))


def acceleration_table(doc: dict, pos: dict, lang: str) -> Record:
    """Table 2: one acceleration plan: drawn mm, graphical value, analytic value and δ, %."""
    rows = [[word("quantity", lang), unit("mm", lang), word("graphical", lang), word("analytic", lang),
             word("error pct", lang)]]
    for key, e in list(pos.get("acceleration", {}).items()):
        rows.append([_symbol(key, "a"), fmt(e.get("mm"), lang), fmt(e.get("value"), lang),
                     fmt(e.get("analytic"), lang), pct(e.get("error_pct"), lang).replace("-", "−")])
    return table(rows, [22.0, 14.0, 20.0, 20.0, 14.0], row_h=6.0, size=2.5,
                 title=f"{word('acceleration table', lang)} {pos['index']}")


def _symbol(key: str, letter: str) -> str:
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


def notes(st: Study, scales: list[str], extra: list[str], lang: str) -> Record:
    """The structural formula, the mobility and the scale coefficients as lines of text."""
    s = st.structure
    lines = [f"{word('mobility', lang)}: W = 3n − 2p_5 − p_4 = 3·{s.n} − 2·{s.p5} − {s.p4} = {s.mobility}",
             f"{word('structure formula', lang)}: {s.formula}  ("
             + ", ".join(f"{d.label} {pair_kind(d.kind, lang)}" for d in s.dyads) + ")",
             f"{word('scales', lang)}: " + "; ".join(scales)] + extra
    rec = Record("notes")
    for k, line in enumerate(lines):
        rec.label((0.0, -7.0 * k), line, size=3.5, layer="labels")
    return rec


def fields(st: Study, lang: str, scale: str, sheet_no: int = 1, sheets: int = 1) -> dict[str, str]:
    meta = st.mech.task.meta
    title = meta.get("title_en", meta.get("title", st.mech.title)) if lang == "en" else \
        meta.get("title", st.mech.title)
    return {"designation": escape(meta.get("designation", "")), "title": escape(title),
            "student": escape(meta.get("sheet.student", "")), "teacher": escape(meta.get("sheet.teacher", "")),
            "organisation": escape(meta.get("sheet.organisation", meta.get("sheet.group", ""))),
            "scale": scale, "sheet": str(sheet_no), "sheets": str(sheets),
            "subtitle": word("kinematics subtitle", lang)}


def compose(f: Form, blocks: list[Block], title_fields: dict[str, str], lang: str, title: str) -> Sheet:
    """Frame + title block + the blocks placed in the free field, labels decluttered."""
    x0, y0, x1, y1 = f.frame_box
    region = (x0 + 5.0, y0 + 5.0, x1 - 5.0, y1 - 5.0)
    tb = title_block_box(f)
    placed = place(blocks, region, obstacles=[(tb[0] - 5.0, tb[1], tb[2], tb[3] + 5.0)], gap=8.0)
    rec = Record(title)
    rec.extend(frame(f))
    rec.extend(title_block(f, title_fields, lang))
    for p in placed:
        rec.extend(p.record)
    return Sheet(f, declutter(rec), placed, lang)


BUILDERS: dict[str, Callable[..., Sheet]] = {}


# -- the force sheet (issue 8): groups with their force plans, the lever, the results, the turn --------

def _force_caption(name: str, lang: str) -> str:
    kind, _, rest = name.partition(" ")
    w = lambda key: word(key, lang)  # noqa: E731
    return {"group": f"{w('group')} {rest}", "polygon": f"{w('force plan of group')} {rest}",
            "table": f"{w('reactions of group')} {rest}", "lever": w("lever"), "results": w("balancing moment"),
            "moment": w("balancing moment turn"),
            "hodograph": f"{w('hodograph')} {force_symbol(rest, lang)}"}.get(kind, name)


def build_forces_sheet(st: Study, f: Form, args: Options) -> Sheet:
    """Sheet 2: every group with its force plan and reactions table, the lever, the results and the
    balancing moment and reaction hodographs over a turn."""
    from graphplan.drawing import charts as forcecharts
    from graphplan.drawing import forces as forcedraw
    from graphplan.graphic import forceplans
    from graphplan.exact import kinetostatics
    from graphplan.graphic.scales import format_scale
    lang = args.lang
    phi = kinetostatics.at_scene_angle(st)
    fp = forceplans.construct(st, phi, precision=args.precision)
    drawn = forcedraw.records(fp, lang)
    turn = forcecharts.turn(st)
    charts = forcecharts.records(turn, lang)
    order = [k for k in drawn if not k.startswith("table")] + [k for k in drawn if k.startswith("table")]
    blocks = [Block(name, (lambda k, r=rec, n=name: captioned(r, _force_caption(n, lang))))
              for name, rec in list((k, drawn[k]) for k in order) + list(charts.items())]
    head = notes(st, [format_scale("mu_l", fp.mu_l, lang), format_scale("mu_F", fp.mu_F, lang)],
                 [f"φ = {fixed(float(np.atleast_1d(phi)[0]), lang, 2)}°"], lang)
    blocks.insert(0, Block("notes", lambda k, r=head: r))
    tf = fields(st, lang, f"μ_l = {num(fp.mu_l, lang)}", 2, 2)
    tf["subtitle"] = word("forces subtitle", lang)
    return compose(f, blocks, tf, lang, f"{st.mech.title} — {tf['subtitle']}")


BUILDERS["forces"] = build_forces_sheet


# -- the kinematics sheet (the main job) -------------------------------------------------------------

FACTORS = (1.6, 1.4, 1.25, 1.12, 1.0, 0.8, 0.64, 0.5, 0.4, 0.32)
FILL = 1.25  # blocks covering more than this share of the free field (at their largest) are not tried


def _accel_arg(values: list[str] | None):
    return None if not values else [v if v.startswith("#") else float(v) for v in values]


def kinematics_blocks(st: Study, args: Options, k: float,
                      width: float = 780.0) -> tuple[list[Block], str]:
    """The kinematics sheet's blocks at size factor k: notes, the position plan, the diagrams,
    the acceleration plans, the tables and the velocity plans; and the sheet's length scale."""
    from graphplan.graphic.diagrams import chord_diagrams
    from graphplan.drawing.diagrams import draw as draw_diagrams
    from graphplan.drawing.plans import acceleration_records, position_record, velocity_records
    from graphplan.graphic.plans import build_plans
    from graphplan.report.diagrams import sheet_notes
    from graphplan.report.plans import plans_json
    from graphplan.graphic.scales import Targets, format_scale
    lang = args.lang
    w = lambda key: word(key, lang)  # noqa: E731
    plans = build_plans(st, count=args.positions, accel=_accel_arg(args.accel), precision=args.precision,
                        targets=Targets().scaled(k))
    doc = plans_json(plans)
    dg = st.mech.task.diagram
    diag = chord_diagrams(st, point=dg.get("point"), divisions=args.positions or dg.get("divisions") or st.mech.task.count,
                          L=float(dg.get("L_mm", 240.0)) * k, H1=float(dg.get("H1_mm", 30.0)),
                          H2=float(dg.get("H2_mm", 30.0)), precision=args.precision, lang=lang, height=70.0 * k,
                          method=dg.get("method", "chords"))
    state = {"plans": plans}

    def velocity_plans(kv: float) -> Record:
        """The velocity plans, at a coarser μv (kv < 1) when they do not fit at the sheet's."""
        vp = plans
        if kv != 1.0:
            t = Targets().scaled(k)
            t = replace(t, velocity=(t.velocity[0] * kv, t.velocity[1] * kv), figure=t.figure * kv)
            vp = build_plans(st, count=args.positions, accel=_accel_arg(args.accel), precision=args.precision,
                             targets=t, mu_l=plans.mu_l, mu_a=plans.mu_a)
        state["plans"] = vp
        records = velocity_records(vp)
        cells = [captioned(records[p.key], f"{w('velocity plan')} {p.index if p.index is not None else ''}")
                 for p in vp.positions]
        return flow(cells, width)

    def notes_block(_k: float) -> Record:
        vp = state["plans"]
        vdoc = plans_json(vp)
        scales = [format_scale(m, v, lang) for m, v in (("mu_l", plans.mu_l), ("mu_v", vp.mu_v), ("mu_a", plans.mu_a))]
        scales.append(f"μ_t = {num(diag.mu_t, lang)} {unit('s/mm', lang)}")
        errs = [abs(e["error_pct"]) for p in vdoc["positions"] for e in p["velocity"].values()
                if e.get("error_pct") is not None and (e.get("mm") or 0) >= 20.0]
        extra = [f"{w('precision')}: {num(args.precision, lang)} {unit('mm', lang)}"]
        if errs:
            extra.append(f"{w('max error')}: {fixed(max(errs), lang, 2)} %")
        return notes(st, scales, extra + sheet_notes(diag, lang), lang)

    blocks = [Block("position plan", lambda _k: captioned(
        position_record(plans), f"{w('position plan')}, {format_scale('mu_l', plans.mu_l, lang)}"))]
    blocks.append(Block("diagrams", lambda _k: draw_diagrams(diag, lang)))
    blocks.append(Block("velocity plans", velocity_plans, factors=(1.0, 0.8, 0.64, 0.5)))
    for p in plans.positions:
        if p.acceleration is not None:
            blocks.append(Block(f"acceleration plan {p.key}", lambda _k, p=p: captioned(
                acceleration_records(plans)[p.key],
                f"{w('acceleration plan')}, {w('position')} {p.index if p.index is not None else ''} "
                f"(φ = {fixed(p.phi % 360, lang, 1)}°), {format_scale('mu_a', plans.mu_a, lang)}")))
    blocks.append(Block("velocity table", lambda _k: velocity_table(plans_json(state["plans"]), lang)))
    for pos in doc["positions"]:
        if "acceleration" in pos:
            blocks.append(Block(f"acceleration table {pos['index']}",
                                lambda _k, pos=pos: acceleration_table(doc, pos, lang)))
    blocks.append(Block("notes", notes_block))
    return blocks, f"μ_l = {num(plans.mu_l, lang)}"


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


def build_kinematics_sheet(st: Study, f: Form, args: Options) -> Sheet:
    """Sheet 1: everything of the kinematic analysis; the plans' scales are coarsened (factor k)
    until the whole set fits the sheet. The blocks' area at k = 1 (it grows about as k²) picks the
    first factor worth trying."""
    check_positions(st, f, args)
    last: GraphplanError | None = None
    x0, y0, x1, y1 = f.frame_box
    free = (x1 - x0) * (y1 - y0) - 185.0 * 55.0
    width = x1 - x0 - 10.0
    first, scale = kinematics_blocks(st, args, 1.0, width=width)
    area = sum((b[2] - b[0] + 8.0) * (b[3] - b[1] + 8.0) for b in (blk.build(1.0).bounds() for blk in first))
    for k in FACTORS:
        if area * k * k > FILL * free and k != FACTORS[-1]:
            continue
        blocks, scale = (first, scale) if k == 1.0 else kinematics_blocks(st, args, k, width=width)
        try:
            return compose(f, blocks, fields(st, args.lang, scale, 1, 2), args.lang, st.mech.title)
        except GraphplanError as exc:
            last = exc
    raise GraphplanError(f"the sheet {f.name} is too small: {last}", st.mech.source)


A1_POSITIONS = 40     # measured: A1 holds 36 velocity plans of the examples, never 48


def check_positions(st: Study, f: Form, args: Options) -> None:
    """A sheet holds a bounded number of velocity plans (about 40 on A1, in proportion to the paper's
    area): more is refused before the plans are built, not after a minute of packing."""
    count = args.positions or st.mech.task.count
    most = max(4, int(A1_POSITIONS * f.width * f.height / (841.0 * 594.0)))
    if count > most:
        raise GraphplanError(f"--positions {count}: the sheet {f.name} holds at most {most} "
                             "positions' plans; choose a larger --format or fewer positions",
                             st.mech.source)


BUILDERS["kinematics"] = build_kinematics_sheet


def build_dynamics_sheet(st: Study, f: Form, args: Options) -> Sheet:
    """Sheet 3 (sheets/dynamics.py): the flywheel by the Wittenbauer construction and the motor."""
    from graphplan.sheets.dynamics import build_dynamics_sheet as build
    return build(st, f, args)


BUILDERS["dynamics"] = build_dynamics_sheet
