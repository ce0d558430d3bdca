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

from graphplan.drawing.layout import Block
from graphplan.exact.positions import Study
from graphplan.graphic.record import Record, text_width
from graphplan.report.plans import captioned
from graphplan.sheets.compose import (Sheet, SheetOptions, beside, compose, drawing_scale, fits_one, number,
                                      options_of, paginate, percent, reading)
from graphplan.sheets.form import Form, form, table
from graphplan.util.errors import GraphplanError

WORDS = {
    "uk": {"positions": "План положень", "velocity": "План швидкостей", "acceleration": "План прискорень",
           "position": "положення", "diagrams": "Кінематичні діаграми", "vel_table": "Таблиця 1. Швидкості, м/с; ω, рад/с",
           "acc_table": "Таблиця 2.{n}. Прискорення, м/с²; ε, рад/с², положення {i}", "graphical": "графічно",
           "analytic": "аналітично", "error": "δ, %", "quantity": "величина", "structure": "Структурна формула",
           "mobility": "Ступінь рухомості", "scales": "Масштабні коефіцієнти", "precision": "Точність креслення",
           "forces": "Силовий аналіз", "max_error": "Найбільша похибка в таблицях",
           "max_error_20": "векторів від 20 мм", "subtitle": "Кінематичний аналіз",
           "dims": "Таблиця 3. Розміри ланок", "link": "ланка", "real": "l, м", "drawn": "l, мм (μl)",
           "lab": "Таблиця 4. s, v, a у заданих положеннях", "no": "№", "dash": "— : коротше за поділку лінійки",
           "signs": "Знаки s, v, a (таблиці, analyze, ключі): + у напрямку напрямної {guide}",
           "flipped": "; діаграми s, v, a побудовано дзеркально (вгору −s)",
           "signs_link": "Знаки φ, ω, ε ланки {link} (таблиці, analyze, ключі): + проти годинникової стрілки"},
    "en": {"positions": "Position plan", "velocity": "Velocity plan", "acceleration": "Acceleration plan",
           "position": "position", "diagrams": "Kinematic diagrams", "vel_table": "Table 1. Velocities, m/s; ω, rad/s",
           "acc_table": "Table 2.{n}. Accelerations, m/s²; ε, rad/s², position {i}", "graphical": "graphical",
           "analytic": "analytic", "error": "δ, %", "quantity": "quantity", "structure": "Structural formula",
           "mobility": "Mobility", "scales": "Scale coefficients", "precision": "Drafting precision",
           "forces": "Force analysis", "max_error": "Largest error in the tables",
           "max_error_20": "vectors from 20 mm", "subtitle": "Kinematic analysis",
           "dims": "Table 3. Dimensions of the links", "link": "link", "real": "l, m", "drawn": "l, mm (μl)",
           "lab": "Table 4. s, v, a at the given positions", "no": "No.", "dash": "— : shorter than a ruler division",
           "signs": "Signs of s, v, a (tables, analyze, keys): + along the guide {guide}",
           "flipped": "; the s, v, a diagrams are drawn mirrored (up = −s)",
           "signs_link": "Signs of φ, ω, ε of link {link} (tables, analyze, keys): + counter-clockwise"},
}

FACTORS = (2.0, 1.6, 1.4, 1.25, 1.12, 1.0, 0.8, 0.64, 0.5, 0.4, 0.32)
SHORT_MM = 20.0    # the notes' second figure: errors of vectors drawn at least this long


def _accel_arg(values) -> list | None:
    """The acceleration plans asked for, as build_plans reads them ("#3", "200", 200.0)."""
    return list(values) if values else None


def _symbol(key: str) -> str:
    """Table headers kept short: omega_AB → ωAB, epsilon_AB → εAB, k_A → k A."""
    for prefix, sym in (("omega_", "ω"), ("epsilon_", "ε"), ("k_", "k ")):
        if key.startswith(prefix):
            return sym + key[len(prefix):]
    return key


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


def _cell(e: dict | None, precision: float) -> str:
    if not e:
        return "—"
    return reading(e.get("value"), e.get("mm"), precision)


def velocity_table(doc: dict, lang: str, precision: float = 0.5) -> Record:
    """Table 1: the plans' velocities (graphical) at every position, like seed 004's table 3, with
    the row's largest error."""
    w = WORDS[lang]
    keys = velocity_columns(doc, precision)
    head = ["№", "φ, °"] + [_symbol(k) for k in keys] + ["δmax, %"]
    rows = [head]
    for pos in doc["positions"]:
        rows.append([str(pos["index"]), f"{pos['phi_deg']:.1f}"]
                    + [_cell(pos["velocity"].get(k), precision) for k in keys]
                    + [percent(row_error(pos, keys))])
    widths = [8.0, 13.0] + [max(14.0, text_width(_symbol(k), 2.5) + 3) for k in keys] + [15.0]
    return table(rows, widths, row_h=6.0, size=2.5, title=w["vel_table"])


def row_error(pos: dict, keys: list[str] | None = None, shortest: float = 0.0) -> float | None:
    """The largest |δ| of a position's velocities (of vectors at least ``shortest`` mm long)."""
    errs = [abs(e["error_pct"]) for k, e in pos["velocity"].items()
            if (keys is None or k in keys) and e.get("error_pct") is not None
            and (e.get("mm") is None or e["mm"] >= shortest)]
    return max(errs) if errs else None


def acceleration_table(pos: dict, n: int, lang: str, precision: float = 0.5) -> Record:
    """Table 2.n: one acceleration plan: drawn mm, graphical value, analytic value and δ, %."""
    w = WORDS[lang]
    rows = [[w["quantity"], "мм" if lang == "uk" else "mm", w["graphical"], w["analytic"], w["error"]]]
    for key, e in pos.get("acceleration", {}).items():
        short = e.get("mm") is not None and precision > 0 and abs(e["mm"]) < precision
        rows.append([_symbol(key), "—" if e.get("mm") is None or short else number(e["mm"], 4),
                     reading(e.get("value"), e.get("mm"), precision), number(e.get("analytic")),
                     "—" if short else percent(e.get("error_pct"))])
    return table(rows, [22.0, 14.0, 20.0, 20.0, 14.0], row_h=6.0, size=2.5,
                 title=w["acc_table"].format(n=n, i=pos["index"] if pos["index"] is not None
                                             else f"φ = {pos['phi_deg']:.1f}°"))


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
    w = WORDS[lang]
    rows = [[w["link"], w["real"], w["drawn"]]]
    for name, length in link_lengths(st):
        rows.append([name, number(length, 4), number(length / mu_l, 4)])
    return table(rows, [18.0, 18.0, 22.0], row_h=6.0, size=2.5, title=w["dims"])


def lab_table(diag, lang: str) -> Record | None:
    """Seed 002's table: s, v, a of the output at the lab's given positions — drawn, graphical, exact."""
    w = WORDS[lang]
    chosen = [k for k in range(len(diag.position)) if diag.position[k] in diag.chosen]
    if not chosen:
        return None
    vals = diag.values()
    s_, v_, a_ = diag.symbols
    mm = "мм" if lang == "uk" else "mm"
    rows = [[w["no"], "φ, °", f"{s_}, {mm}", s_, f"{v_}, {mm}", v_, f"{v_} {w['error']}",
             f"{a_}, {mm}", a_, f"{a_} {w['error']}"]]
    ev, ea = diag.errors_pct("v_at"), diag.errors_pct("a_at")
    for k in chosen:
        r = diag.drawn
        rows.append([str(diag.position[k]), f"{diag.phi[k]:.1f}", number(r.s[k], 3), number(vals["s"][k]),
                     number(r.v_at[k], 3), number(vals["v_at"][k]), percent(ev[k]),
                     number(r.a_at[k], 3), number(vals["a_at"][k]), percent(ea[k])])
    return table(rows, [9.0, 13.0, 14.0, 16.0, 14.0, 16.0, 14.0, 14.0, 16.0, 14.0], row_h=6.0, size=2.5,
                 title=w["lab"])


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


def fields(st: Study, lang: str, scale: str, sheet_no: int = 1, sheets: int = 1,
           subtitle: str | None = None) -> dict[str, str]:
    """The title block's fields from the scene's title and [sheet] table."""
    meta = st.mech.task.meta
    title = meta.get("title_en", meta.get("title", st.mech.title)) if lang == "en" else \
        meta.get("title", st.mech.title)
    return {"designation": meta.get("designation", ""), "title": title,
            "student": meta.get("sheet.student", ""), "teacher": meta.get("sheet.teacher", ""),
            "organisation": meta.get("sheet.organisation", meta.get("sheet.group", "")),
            "scale": scale, "sheet": str(sheet_no), "sheets": str(sheets),
            "subtitle": subtitle or WORDS[lang]["subtitle"]}


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

    def __init__(self, st: Study, opts: SheetOptions, width: float):
        self.st, self.opts, self.width = st, opts, width
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
    from graphplan.report.plans import plans_json
    st, opts = dr.st, dr.opts
    lang, p = opts.lang, opts.precision
    w = WORDS[lang]
    plans = dr.plans(k["position"], k["velocity"], k["acceleration"])
    diag = dr.diagrams(k["diagrams"])
    doc = plans_json(plans)
    prec = captioned(position_record(plans), f"{w['positions']}, {format_scale('mu_l', plans.mu_l)}")
    dims = dimensions_table(st, plans.mu_l, lang)
    blocks = [Block("position plan", lambda _k: prec), Block("dimensions table", lambda _k: dims)]
    drec = draw_diagrams(diag, lang)
    lab = lab_table(diag, lang) if st.mech.task.count <= 8 else None
    dblock = drec if lab is None else beside([drec], below=lab)
    blocks.append(Block("diagrams", lambda _k: dblock, solid=True))
    vrec = velocity_records(plans)
    cells = [captioned(vrec[q.key], f"{w['velocity']} {q.index if q.index is not None else ''}")
             for q in plans.positions]
    for q, cell in zip(plans.positions, cells):
        blocks.append(Block(f"velocity plan {q.key}", lambda _k, c=cell: c))
    vtab = velocity_table(doc, lang, p)
    blocks.append(Block("velocity table", lambda _k: vtab))
    arec = acceleration_records(plans)
    n = 0
    for q, pos in zip(plans.positions, doc["positions"]):
        if q.acceleration is None:
            continue
        n += 1
        caption = (f"{w['acceleration']}, {w['position']} {q.index if q.index is not None else ''} "
                   f"(φ = {q.phi % 360:.1f}°), {format_scale('mu_a', plans.mu_a)}")
        both = beside([captioned(arec[q.key], caption), acceleration_table(pos, n, lang, p)])
        blocks.append(Block(f"acceleration plan {q.key}", lambda _k, r=both: r, solid=True))

    def notes_block(_k: float) -> Record:
        scales = [format_scale("mu_l", plans.mu_l), format_scale("mu_v", plans.mu_v),
                  format_scale("mu_a", plans.mu_a),
                  f"μt = {number(diag.mu_t, 4)} " + ("с/мм" if lang == "uk" else "s/mm")]
        extra = [f"{w['precision']}: {p:g} " + ("мм" if lang == "uk" else "mm")]
        every = table_errors(doc, p, 0.0)
        long_ = table_errors(doc, p, SHORT_MM)
        if every:
            extra.append(f"{w['max_error']}: {max(every):.2f} %"
                         + (f" ({w['max_error_20']}: {max(long_):.2f} %)" if long_ else ""))
        extra.append(w["dash"])
        extra.append(sign_note(st, diag, lang))
        return notes(st, scales, extra, lang)

    nrec = notes_block(1.0)
    blocks.append(Block("notes", lambda _k: nrec))
    return Drawn(dict(k), plans, diag, blocks)


def sign_note(st: Study, diag, lang: str) -> str:
    """One sign convention, said on the sheet: s, v, a are signed along the output's guide (a
    rocker: counter-clockwise) everywhere; the diagrams are drawn so the stroke from position 0
    rises, which for some outputs mirrors them."""
    w = WORDS[lang]
    out = st.output
    if out.kind == "slide":
        import math
        guide = st.mech.guides[st.mech.links[out.name].slides_on]
        said = w["signs"].format(guide=f"{st.mech.links[out.name].slides_on} ({math.degrees(guide.angle) % 360:g}°)")
    else:
        said = w["signs_link"].format(link=out.name)
    return said + (w["flipped"] if diag.sign < 0 else "")


def table_errors(doc: dict, precision: float, shortest: float) -> list[float]:
    """Every |δ| the tables print (velocities; accelerations read longer than the ruler's division),
    of vectors at least ``shortest`` mm long."""
    out = []
    keys = velocity_columns(doc, precision)
    for pos in doc["positions"]:
        e = row_error(pos, keys, shortest)
        if e is not None:
            out.append(e)
        for a in pos.get("acceleration", {}).values():
            mm = a.get("mm")
            if a.get("error_pct") is None or (mm is not None and (mm < precision or mm < shortest)):
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


def choose(st: Study, f: Form, opts: SheetOptions) -> tuple[Drawn, bool]:
    """The scales, once per scene and format: the largest common size factor at which the plans
    stay legible (``legible``) and the whole fits one sheet of ``f`` — on A1 (the coursework's one
    sheet) the largest at which it fits at all; then each family grown in turn (position plan,
    acceleration plans, velocity plans, diagrams) while it still fits — the field filled. When no
    such drawing fits one sheet: the smallest legible factor whose blocks each fit a sheet, for a
    set of sheets, grown while the set needs no more sheets. Returns the drawing and whether it
    is one sheet."""
    x0, y0, x1, y1 = f.frame_box
    dr = Drafter(st, opts, x1 - x0 - 10.0)
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
            return grow(dr, d, one), True
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
        return dr.drawn(_same(FACTORS[-1])), False
    d = readable[-1] if readable else layable[0]     # the smallest legible: the fewest sheets
    pages = len(paginate(f, d.blocks))
    return grow(dr, d, lambda t: _pages(f, t) <= pages, SET_LARGEST), False


def _pages(f: Form, d: Drawn) -> int:
    try:
        return len(paginate(f, d.blocks))
    except GraphplanError:
        return 10 ** 6


def grow(dr: Drafter, d: Drawn, fits, largest: float = FACTORS[0]) -> Drawn:
    """Each family in turn drawn at the next larger factors (up to ``largest``) while ``fits`` holds."""
    best = d
    for fam in FAMILIES:
        top = min(largest, dr.widest_diagrams()) if fam == "diagrams" else largest
        for k in sorted(x for x in FACTORS if best.k[fam] < x <= top):
            trial = dr.drawn({**best.k, fam: k})
            if not fits(trial):
                break
            best = trial
    return best


def sheet_scales(st: Study, format: str = "A1", positions: int | None = None, accel=None,
                 precision: float = 0.5) -> dict[str, float]:
    """The scales the kinematics sheet of ``format`` draws with: μl, μv, μa of the plans and the
    diagrams' L and height — for the terminal's ``plans``/``diagrams`` to print what the sheet draws."""
    d, _ = choose(st, form(format), SheetOptions(positions=positions, accel=accel, precision=precision))
    opts = diagram_options(st, d.k["diagrams"], positions)
    return {"mu_l": d.plans.mu_l, "mu_v": d.plans.mu_v, "mu_a": d.plans.mu_a,
            "L": opts["L"], "height": opts["height"], "H1": opts["H1"], "H2": opts["H2"]}


def build_kinematics_sheet(st: Study, f: Form, options) -> Sheet:
    """Sheet 1: everything of the kinematic analysis at the scales ``choose`` picks; a set of
    sheets when it does not fit one."""
    opts = options_of(options)
    d, _ = choose(st, f, opts)
    return compose(f, d.blocks, fields(st, opts.lang, drawing_scale(d.plans.mu_l)), opts.lang, st.mech.title)


def kinematics_blocks(st: Study, options, k: float, width: float = 780.0) -> tuple[list[Block], str]:
    """The blocks at size factor k and the title block's scale (kept for callers of the old API)."""
    d = Drafter(st, options_of(options), width).drawn(_same(k))
    return d.blocks, drawing_scale(d.plans.mu_l)

