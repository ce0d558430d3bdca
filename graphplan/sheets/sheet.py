"""`graphplan sheet`: the drawing sheet — frame and title block, the position plan, the velocity and
acceleration plans, the s–v–a diagrams and the tables, laid out so nothing overlaps (REFERENCE §3).
The output's suffix picks SVG, PDF, PNG or DXF; every format views the same construction record."""
from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

import numpy as np

from graphplan.graphic.record import Record, text_width
from graphplan.util.errors import GraphplanError
from graphplan.drawing.layout import Block, Placed, declutter, place
from graphplan.exact.positions import Study
from graphplan.report.plans import captioned
from graphplan.sheets.form import Form, form, frame, table, title_block, title_block_box

WORDS = {
    "uk": {"positions": "План положень", "velocity": "План швидкостей", "acceleration": "План прискорень",
           "position": "положення", "diagrams": "Кінематичні діаграми", "vel_table": "Таблиця 1. Швидкості, м/с; ω, рад/с",
           "acc_table": "Таблиця 2. Прискорення, м/с²; ε, рад/с², положення", "graphical": "графічно",
           "analytic": "аналітично", "error": "δ, %", "quantity": "величина", "structure": "Структурна формула",
           "mobility": "Ступінь рухомості", "scales": "Масштабні коефіцієнти", "precision": "Точність креслення",
           "forces": "Силовий аналіз", "max_error": "Найбільша похибка планів швидкостей (вектори від 20 мм)",
           "subtitle": "Кінематичний аналіз"},
    "en": {"positions": "Position plan", "velocity": "Velocity plan", "acceleration": "Acceleration plan",
           "position": "position", "diagrams": "Kinematic diagrams", "vel_table": "Table 1. Velocities, m/s; ω, rad/s",
           "acc_table": "Table 2. Accelerations, m/s²; ε, rad/s², position", "graphical": "graphical",
           "analytic": "analytic", "error": "δ, %", "quantity": "quantity", "structure": "Structural formula",
           "mobility": "Mobility", "scales": "Scale coefficients", "precision": "Drafting precision",
           "forces": "Force analysis", "max_error": "Largest error of the velocity plans (vectors from 20 mm)",
           "subtitle": "Kinematic analysis"},
}
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


def fmt(v: float | None, digits: int = 4) -> str:
    """Numbers for tables: 4 significant digits, a true minus, '—' for none."""
    if v is None or (isinstance(v, float) and not math.isfinite(v)):
        return "—"
    text = f"{v:.{digits}g}"
    if "e" in text:
        text = f"{v:.2e}"
    return text.replace("-", "−")


def velocity_table(doc: dict, lang: str) -> Record:
    """Table 1: the plans' velocities (graphical) at every position, like seed 004's table 3."""
    w = WORDS[lang]
    keys: list[str] = []
    for pos in doc["positions"]:
        for key in pos["velocity"]:
            if key not in keys:
                keys.append(key)
    head = ["№", "φ, °"] + [_symbol(k) for k in keys] + ["δmax, %"]
    rows = [head]
    for pos in doc["positions"]:
        errs = [abs(e["error_pct"]) for e in pos["velocity"].values() if e.get("error_pct") is not None]
        rows.append([str(pos["index"]), f"{pos['phi_deg']:.1f}"]
                    + [fmt(pos["velocity"].get(k, {}).get("value")) for k in keys]
                    + [fmt(max(errs) if errs else None, 2)])
    widths = [8.0, 13.0] + [max(14.0, text_width(_symbol(k), 2.5) + 3) for k in keys] + [15.0]
    return table(rows, widths, row_h=6.0, size=2.5, title=w["vel_table"])


def acceleration_table(doc: dict, pos: dict, lang: str) -> Record:
    """Table 2: one acceleration plan: drawn mm, graphical value, analytic value and δ, %."""
    w = WORDS[lang]
    rows = [[w["quantity"], "мм" if lang == "uk" else "mm", w["graphical"], w["analytic"], w["error"]]]
    for key, e in list(pos.get("acceleration", {}).items()):
        rows.append([_symbol(key), fmt(e.get("mm")), fmt(e.get("value")), fmt(e.get("analytic")),
                     fmt(e.get("error_pct"), 2)])
    return table(rows, [22.0, 14.0, 20.0, 20.0, 14.0], row_h=6.0, size=2.5,
                 title=f"{w['acc_table']} {pos['index']}")


def _symbol(key: str) -> str:
    """'B' → 'v_B'-style headers kept short: omega_AB → ωAB, epsilon_AB → εAB, k_A → aᵏA."""
    for prefix, sym in (("omega_", "ω"), ("epsilon_", "ε"), ("k_", "k ")):
        if key.startswith(prefix):
            return sym + key[len(prefix):]
    return key


def notes(st: Study, scales: list[str], extra: list[str], lang: str) -> Record:
    """The structural formula, the mobility and the scale coefficients as lines of text."""
    w = WORDS[lang]
    s = st.structure
    lines = [f"{w['mobility']}: W = 3n − 2p5 − p4 = 3·{s.n} − 2·{s.p5} − {s.p4} = {s.mobility}",
             f"{w['structure']}: {s.formula}  ("
             + ", ".join(f"{d.label} {d.kind}" for d in s.dyads) + ")",
             f"{w['scales']}: " + "; ".join(scales)] + extra
    rec = Record("notes")
    for k, line in enumerate(lines):
        rec.label((0.0, -7.0 * k), line, size=3.5, layer="labels")
    return rec


def fields(st: Study, lang: str, scale: str, sheet_no: int = 1, sheets: int = 1) -> dict[str, str]:
    meta = st.mech.task.meta
    title = meta.get("title_en", meta.get("title", st.mech.title)) if lang == "en" else \
        meta.get("title", st.mech.title)
    return {"designation": meta.get("designation", ""), "title": title,
            "student": meta.get("sheet.student", ""), "teacher": meta.get("sheet.teacher", ""),
            "organisation": meta.get("sheet.organisation", meta.get("sheet.group", "")),
            "scale": scale, "sheet": str(sheet_no), "sheets": str(sheets),
            "subtitle": WORDS[lang]["subtitle"]}


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

FORCE_WORDS = {
    "uk": {"group": "Група", "polygon": "План сил групи", "table": "Реакції групи", "lever": "Важіль Жуковського",
           "results": "Зрівноважувальний момент", "moment": "Зрівноважувальний момент за оберт",
           "hodograph": "Годограф реакції", "subtitle": "Силовий аналіз", "at": "φ ="},
    "en": {"group": "Group", "polygon": "Force plan of group", "table": "Reactions of group",
           "lever": "Zhukovsky lever", "results": "Balancing moment", "moment": "Balancing moment over a turn",
           "hodograph": "Hodograph of reaction", "subtitle": "Force analysis", "at": "φ ="},
}


def _force_caption(name: str, lang: str) -> str:
    w = FORCE_WORDS[lang]
    kind, _, rest = name.partition(" ")
    return {"group": f"{w['group']} {rest}", "polygon": f"{w['polygon']} {rest}",
            "table": f"{w['table']} {rest}", "lever": w["lever"], "results": w["results"],
            "moment": w["moment"], "hodograph": f"{w['hodograph']} {rest}"}.get(kind, name)


def build_forces_sheet(st: Study, f: Form, args: Options) -> Sheet:
    """Sheet 2: every group with its force plan and reactions table, the lever, the results and the
    balancing moment and reaction hodographs over a turn."""
    from graphplan.drawing import charts as forcecharts
    from graphplan.drawing import forces as forcedraw
    from graphplan.graphic import forceplans
    from graphplan.exact import kinetostatics
    lang = args.lang
    phi = kinetostatics.at_scene_angle(st)
    fp = forceplans.construct(st, phi, precision=args.precision)
    drawn = forcedraw.records(fp)
    turn = forcecharts.turn(st)
    charts = forcecharts.records(turn)
    order = [k for k in drawn if not k.startswith("table")] + [k for k in drawn if k.startswith("table")]
    blocks = [Block(name, (lambda k, r=rec, n=name: captioned(r, _force_caption(n, lang))))
              for name, rec in list((k, drawn[k]) for k in order) + list(charts.items())]
    w = FORCE_WORDS[lang]
    head = notes(st, [f"μl = {fp.mu_l:g} m/mm" if lang == "en" else f"μl = {fp.mu_l:g} м/мм",
                      f"μF = {fp.mu_F:g} N/mm" if lang == "en" else f"μF = {fp.mu_F:g} Н/мм"],
                 [f"{w['at']} {float(np.atleast_1d(phi)[0]):.2f}°"], lang)
    blocks.insert(0, Block("notes", lambda k, r=head: r))
    tf = fields(st, lang, f"μl = {fp.mu_l:g}", 2, 2)
    tf["subtitle"] = w["subtitle"]
    return compose(f, blocks, tf, lang, f"{st.mech.title} — {w['subtitle']}")


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
    w = WORDS[lang]
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
        cells = [captioned(records[p.key], f"{w['velocity']} {p.index if p.index is not None else ''}")
                 for p in vp.positions]
        return flow(cells, width)

    def notes_block(_k: float) -> Record:
        vp = state["plans"]
        vdoc = plans_json(vp)
        scales = [format_scale("mu_l", plans.mu_l), format_scale("mu_v", vp.mu_v), format_scale("mu_a", plans.mu_a)]
        scales.append(f"μt = {diag.mu_t:.4g}")
        errs = [abs(e["error_pct"]) for p in vdoc["positions"] for e in p["velocity"].values()
                if e.get("error_pct") is not None and (e.get("mm") or 0) >= 20.0]
        extra = [f"{w['precision']}: {args.precision:g} " + ("мм" if lang == "uk" else "mm")]
        if errs:
            extra.append(f"{w['max_error']}: {max(errs):.2f} %")
        return notes(st, scales, extra + sheet_notes(diag, lang), lang)

    blocks = [Block("position plan", lambda _k: captioned(
        position_record(plans), f"{w['positions']}, {format_scale('mu_l', plans.mu_l)}"))]
    blocks.append(Block("diagrams", lambda _k: draw_diagrams(diag, lang)))
    blocks.append(Block("velocity plans", velocity_plans, factors=(1.0, 0.8, 0.64, 0.5)))
    for p in plans.positions:
        if p.acceleration is not None:
            blocks.append(Block(f"acceleration plan {p.key}", lambda _k, p=p: captioned(
                acceleration_records(plans)[p.key],
                f"{w['acceleration']}, {w['position']} {p.index if p.index is not None else ''} "
                f"(φ = {p.phi % 360:.1f}°), {format_scale('mu_a', plans.mu_a)}")))
    blocks.append(Block("velocity table", lambda _k: velocity_table(plans_json(state["plans"]), lang)))
    for pos in doc["positions"]:
        if "acceleration" in pos:
            blocks.append(Block(f"acceleration table {pos['index']}",
                                lambda _k, pos=pos: acceleration_table(doc, pos, lang)))
    blocks.append(Block("notes", notes_block))
    return blocks, f"μl = {plans.mu_l:g}"


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
