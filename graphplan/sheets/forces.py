"""The force sheet (sheet 2 of the coursework, seed 000): the acceleration plan of the force position
with its table, the table of masses, moments of inertia and inertia loads, every group with its
force plan and its forces' table, the Zhukovsky lever, the results, the balancing moment over a turn,
the diagram of the resistance force over the stroke and the reactions' hodographs.

The force plans' μF is chosen once per scene and format (``force_scales``): the largest force drawn
as long as the sheet allows; ``forces --format`` prints the same numbers."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from graphplan.drawing.layout import HULL, Block
from graphplan.exact.positions import Study
from graphplan.graphic.record import Record
from graphplan.report.plans import captioned
from graphplan.sheets.compose import (Sheet, SheetOptions, bare_share, beside, compose, drawing_scale,
                                      fits_one, fits_sheets, options_of, paginate, remembered, sampled)
from graphplan.sheets.form import TABLES, Form, enlarged, form, table
from graphplan.sheets.kinematics import FACTORS, ONE_SHEET, acceleration_table, fields, notes
from graphplan.util.errors import GraphplanError
from graphplan.sheets.compose import number
from graphplan.util.words import fixed, force_symbol, num, unit, word

POLYGON_MM = 150.0     # the largest force of the position drawn this long at size factor 1
NO_LOADS = ("{src}: a force sheet needs loads — add [loads] (g, mass_per_length, inertia_factor) or a "
            "link's mass/inertia, and a [[force]] (point, magnitude, stroke)")


def _caption(name: str, lang: str) -> str:
    w = lambda key: word(f"fs {key}", lang)  # noqa: E731
    kind, _, rest = name.partition(" ")
    return {"group": f"{w('group')} {rest}", "polygon": f"{w('polygon')} {rest}",
            "table": f"{w('table')} {rest}", "lever": w('lever'), "results": w('results'),
            "moment": w('moment'), "hodograph": f"{w('hodograph')} {force_symbol(rest, lang)}",
            "resistance": w('resistance'),
            "reaction": f"{w('reaction')} {force_symbol(rest, lang)}"}.get(kind, name)


def has_loads(st: Study) -> bool:
    """Whether the scene loads any link: a mass, a moment of inertia or an external force."""
    mech = st.mech
    return bool(mech.forces) or any((l.mass or 0) > 0 or (l.inertia or 0) > 0 for l in mech.links.values())


def inertia_table(st: Study, ks, acc_doc: dict | None, lang: str) -> Record:
    """Seed 000's table 2.3: per link m, I_S, the acceleration of its centre of mass and its ε, G = m·g,
    Φ = m·a_S and M_Φ = −I_S·ε — one computation and one sign convention with the force plans, the
    groups' tables, the lever and ``forces``: the inertia loads of the exact kinetostatics (``ks``;
    ε and M_Φ + counter-clockwise); the plan's own a_S beside the exact ones is Table 2's business.
    ``acc_doc`` is not read (kept for the callers)."""
    w = lambda key: word(f"fs {key}", lang)  # noqa: E731
    uk = lang == "uk"
    mech = st.mech
    kin = ks.kin
    rows = [[w('link'), f"m, {unit('kg', lang)}", f"I_S, {unit('kg·m²', lang)}", f"a_S, {unit('m/s²', lang)}",
             f"ε, {unit('rad/s²', lang)}", f"G, {unit('N', lang)}", f"Φ, {unit('N', lang)}",
             f"M_Φ, {unit('N·m', lang)}"]]
    loads = {(ld.link, ld.kind): ld for ld in ks.loads}
    for name, link in mech.links.items():
        m, inertia = link.mass or 0.0, link.inertia or 0.0
        if not m and not inertia:
            continue
        com = link.com or next(iter(link.local))
        body = kin.bodies[name]
        a_s = float(abs(body.at(link.local[com])[2][0]))
        eps = float(body.eps[0])
        force = loads.get((name, "inertia"))
        couple = loads.get((name, "couple"))
        rows.append([f"{link.number} ({com})", number(m, 4, lang), number(inertia, 4, lang), number(a_s, 4, lang),
                     number(eps, 4, lang), number(m * mech.g, 4, lang),
                     number(float(abs(force.force[0])) if force else 0.0, 4, lang),
                     number(float(couple.couple[0]) if couple else 0.0, 4, lang)])
    rec = table(rows, [20.0, 14.0, 20.0, 18.0, 18.0, 16.0, 18.0, 18.0], row_h=6.0, size=2.5,
                title=w('inertia'))
    from graphplan.sheets.kinematics import footnoted
    return footnoted(rec, [w('inertia note')])


def force_position(st: Study, phi: float, lang: str) -> str:
    """The force position as the scene assigns it: the crank's turn from position 0
    (``positions.force_phi_deg``, in the crank's sense) with the crank angle from the x axis —
    "φ = 200° від положення 0 (кут кривошипа 45,71°)"."""
    turn = round(float(st.from_position0(phi)), 9) % 360.0
    return word("fs force position", lang, turn=num(turn, lang, 4), phi=fixed(phi, lang, 2))


SHORT_FORCE_MM = 10.0


def small_forces(fp, lang: str = "uk") -> list[str]:
    """Forces drawn shorter than 10 mm on their group's force plan, each with its length as the
    ruler reads it (the reactions' table's mm) and its share of the plan's largest ("R34τ 4 мм,
    2.4 %"): the sheet says which are short."""
    from graphplan.graphic.draftsman import measure
    out = []
    for gp in fp.groups:
        sides = [s for s in gp.sides if s.mm > 1e-9]
        if not sides:
            continue
        big = max(s.mm for s in sides)
        out += [f"{force_symbol(s.name, lang)} {num(measure(s.mm, fp.precision), lang, 2)} {unit('mm', lang)}, "
                f"{fixed(100 * s.mm / big, lang, 1)} %" for s in sides if s.mm < SHORT_FORCE_MM]
    return list(dict.fromkeys(out))


FORCE_FAMILIES = ("forces", "groups", "acceleration", "charts", "hodographs")


@dataclass
class ForceDrawn:
    k: dict[str, float]
    fp: object
    blocks: list[Block]


class ForceDrafter:
    """Draws the force sheet's blocks at given size factors, remembering what it drew."""

    def __init__(self, st: Study, opts: SheetOptions, tables: float = 1.0):
        from graphplan.drawing import charts as forcecharts
        from graphplan.exact import kinetostatics
        self.st, self.opts, self.tables = st, opts, tables
        self.phi = float(np.atleast_1d(kinetostatics.at_scene_angle(st))[0])
        self.ks = kinetostatics.analyse(st, [self.phi])
        self.turn = forcecharts.turn(st)
        self.memo: dict = {}

    def drawn(self, k: dict[str, float]) -> ForceDrawn:
        key = tuple(k[f] for f in FORCE_FAMILIES)
        if key not in self.memo:
            self.memo[key] = force_blocks(self, k)
        return self.memo[key]


def force_blocks(dr: ForceDrafter, k: dict[str, float]) -> ForceDrawn:
    """The force sheet's blocks at size factors k: "forces" sets μF, "groups" μl of the groups'
    drawings, "acceleration" μa of the force position's plan, "charts" the charts' size, "hodographs" the hodographs'."""
    from graphplan.drawing import charts as forcecharts
    from graphplan.drawing import forces as forcedraw
    from graphplan.drawing.plans import acceleration_records
    from graphplan.graphic import forceplans
    from graphplan.graphic.plans import build_plans
    from graphplan.graphic.scales import Targets, format_scale
    from graphplan.report.plans import plans_json
    st, opts, phi, ks = dr.st, dr.opts, dr.phi, dr.ks
    lang, p = opts.lang, opts.precision
    w = lambda key: word(f"fs {key}", lang)  # noqa: E731
    mu_l = forceplans.mechanism_scale(st, forceplans.MECHANISM_MM * k["groups"])
    mu_F = forceplans.force_scale(ks, POLYGON_MM * k["forces"])
    fp = forceplans.construct(st, phi, precision=p, mu_l=mu_l, mu_F=mu_F)
    plans = build_plans(st, count=opts.positions, accel=[phi], precision=p,
                        targets=Targets().scaled(k["acceleration"]))
    q = next(x for x in plans.positions if x.acceleration is not None)
    acc_doc = next(d for d in plans_json(plans)["positions"] if "acceleration" in d)
    blocks: list[Block] = []
    small = small_forces(fp, lang)
    lines = [f"{w('at')} {fixed(phi, lang, 2)}°"] + ([w('small') + "; ".join(small)] if small else [])
    head = notes(st, [format_scale(m, v, lang) for m, v in (("mu_l", fp.mu_l), ("mu_F", fp.mu_F),
                                                              ("mu_a", plans.mu_a))], lines, lang)
    blocks.append(Block("notes", lambda _k, r=head: r))
    label = q.index if q.index is not None else f"φ = {fixed(q.phi % 360, lang, 1)}°"
    caption = f"{w('acceleration')}, {w('position')} {label}, {format_scale('mu_a', plans.mu_a, lang)}"
    arec = captioned(acceleration_records(plans)[q.key], caption)
    n = len(st.mech.task.accel) + 1 if st.mech.task.accel else 2   # after the kinematics sheet's 2.1 …
    atab = enlarged(acceleration_table(acc_doc, n, lang, p), dr.tables)
    both = beside([arec, atab])
    blocks.append(Block("acceleration plan", lambda _k: both, solid=HULL))
    itab = enlarged(inertia_table(st, ks, acc_doc, lang), dr.tables)
    blocks.append(Block("inertia table", lambda _k: itab))
    drawn = forcedraw.records(fp, lang)
    for gp in fp.groups:
        parts = [captioned(drawn[f"group {gp.label}"], _caption(f"group {gp.label}", lang)),
                 captioned(drawn[f"polygon {gp.label}"], _caption(f"polygon {gp.label}", lang)),
                 captioned(enlarged(drawn[f"table {gp.label}"], dr.tables), _caption(f"table {gp.label}", lang))]
        group = beside([parts[0], beside([parts[1]], below=parts[2])])
        blocks.append(Block(f"group {gp.label}", lambda _k, r=group: r))
    scheme = captioned(drawn["mechanism"], f"{w('mechanism')}, {w('at')} {fixed(phi, lang, 2)}°")
    blocks.append(Block("mechanism", lambda _k: scheme))
    lever = beside([captioned(drawn["lever"], _caption("lever", lang)),
                    captioned(enlarged(drawn["results"], dr.tables), _caption("results", lang))])
    blocks.append(Block("lever", lambda _k: lever, solid=HULL))
    for name, rec in forcecharts.records(dr.turn, k["charts"], lang, k["hodographs"]).items():
        chart = captioned(rec, _caption(name, lang))
        blocks.append(Block(name, lambda _k, r=chart: r, solid=True))   # a chart keeps its axes' field
    return ForceDrawn(dict(k), fp, blocks)


def growth(dr: ForceDrafter, d: ForceDrawn, fits) -> list[ForceDrawn]:
    """Each family in turn drawn at the next larger factors while ``fits`` holds: every drawing on
    the way, ``d`` first; a factor that draws the same (the standard scales step coarser than the
    factors) is passed over without a second entry."""
    path = [d]
    for fam in FORCE_FAMILIES:
        for bigger in sorted(x for x in FACTORS if x > d.k[fam]):
            trial = dr.drawn({**d.k, fam: bigger})
            if not fits(trial):
                break
            d = trial
            if _looks(d) != _looks(path[-1]):
                path.append(d)
    return path


def _looks(d: ForceDrawn) -> tuple:
    """What a drawing looks like, for telling two apart: its blocks' sizes."""
    return tuple(tuple(round(v, 3) for v in b.build(1.0).bounds()) for b in d.blocks)


def sheet_count(f: Form, d: ForceDrawn) -> int | None:
    """How many sheets of ``f`` the packing needs for ``d``; None when a block fits no sheet."""
    try:
        return len(paginate(f, d.blocks))
    except GraphplanError:
        return None


SAMPLED = 6         # the drawings of the growth path whose layouts are compared
SET_SMALLEST = 1.0   # below A1 the plans are not drawn smaller than this to keep one sheet: a set instead


@remembered
def choose_forces(st: Study, f: Form, opts: SheetOptions) -> ForceDrawn:
    """The largest common size factor at which the force sheet fits one sheet, then every family
    grown while it fits — of the drawings on that way, the one that leaves the fewest 25 mm cells
    bare (a larger force plan is mostly bare paper inside its polygon). Below
    A1 not smaller than ``SET_SMALLEST``; when nothing fits one sheet, the largest factor (≤ 1) at
    which every block fits a sheet, for a set, grown while the set needs no more sheets. The tables
    are lettered 3.5 mm (``TABLES``) unless that costs a further sheet."""
    if not has_loads(st):
        raise GraphplanError(NO_LOADS.format(src=st.mech.source))
    big, small = ForceDrafter(st, opts, TABLES), ForceDrafter(st, opts, 1.0)
    for dr in (big, small):
        one = _one_sheet(dr, f)
        if one is not None:
            return one
    starts = [(dr, _set_start(dr, f)) for dr in (big, small)]
    starts = [(dr, s) for dr, s in starts if s is not None]
    if not starts:
        return big.drawn({fam: FACTORS[-1] for fam in FORCE_FAMILIES})
    dr, (d, pages) = min(starts, key=lambda x: x[1][1])       # the fewer sheets; equal: the larger tables
    # a set's drawings grown while the set needs no more sheets
    path = growth(dr, d, lambda t: fits_sheets(f, t.blocks, pages))
    return min(sampled(path, SAMPLED), key=lambda t: bare_share(f, t.blocks))


def _one_sheet(dr: ForceDrafter, f: Form) -> ForceDrawn | None:
    """The fullest one-sheet drawing (see ``choose_forces``); None when none fits one sheet."""
    smallest = 0.5 if f.name in ONE_SHEET else SET_SMALLEST
    for k in FACTORS:
        if k < smallest:
            return None
        d = dr.drawn({fam: k for fam in FORCE_FAMILIES})
        if fits_one(f, d.blocks):
            path = growth(dr, d, lambda t: fits_one(f, t.blocks))
            return min(sampled(path, SAMPLED), key=lambda t: bare_share(f, t.blocks))
    return None


def _set_start(dr: ForceDrafter, f: Form) -> tuple[ForceDrawn, int] | None:
    """The largest common factor (≤ 1) at which every block fits a sheet, and the sheets it needs."""
    for k in FACTORS:
        if k > 1.0:
            continue
        d = dr.drawn({fam: k for fam in FORCE_FAMILIES})
        pages = sheet_count(f, d)
        if pages is not None:
            return d, pages
    return None


def force_scales(st: Study, format: str = "A1", precision: float = 0.5) -> dict[str, float]:
    """μl and μF of the force sheet of ``format`` — for ``forces --format``."""
    d = choose_forces(st, form(format), SheetOptions(precision=precision, sheet="forces"))
    return {"mu_l": d.fp.mu_l, "mu_F": d.fp.mu_F}


def build_forces_sheet(st: Study, f: Form, options) -> Sheet:
    """Sheet 2: the force analysis at the scene's force position (a set when it does not fit)."""
    opts = options_of(options)
    d = choose_forces(st, f, opts)
    w = lambda key: word(f"fs {key}", opts.lang)  # noqa: E731
    tf = fields(st, opts.lang, drawing_scale(d.fp.mu_l, opts.lang), subtitle=w('subtitle'))
    return compose(f, d.blocks, tf, opts.lang, f"{st.mech.title} — {w('subtitle')}")

