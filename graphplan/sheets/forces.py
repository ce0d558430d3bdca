"""The force sheet (sheet 2 of the coursework, seed 000): the mechanism in the force position with
every load on it, each group with its force plan beside it (a row per group, in the order they are
solved), the acceleration plan of the force position, the Zhukovsky lever, the charts over the turn
(the balancing moment, the frame's reaction on the slider, the resistance over the stroke, the
reactions' hodographs); the tables (accelerations, masses and inertia loads, each group's forces,
the results) in a column by the title block, the notes above it.

Composed by construction like every sheet (docs/composition.md); the scales — μl of the scheme and of
the groups, μF, μa, μv of the lever, the charts' and hodographs' sizes — chosen once per scene and
format by arithmetic (``plan``); ``forces --format`` prints the same numbers (``force_scales``)."""
from __future__ import annotations

import math
import re
from dataclasses import dataclass, replace

import numpy as np

from graphplan.drawing.layout import (GAP, Box, Grid, Leaf, Placed, Row, Stack, arrange, centred, column_size,
                                      extent, extent_with, fits, flow, set_columns, split, top_left)
from graphplan.exact.positions import Study
from graphplan.graphic.record import Record
from graphplan.sheets import forceset
from graphplan.sheets.compose import (Family, Sheet, SheetOptions, captioned, coarser, compose,
                                      drawing_scale, field_of, grown, keep_out, measured_twice, note_block, notes_height,
                                      options_of, remembered)
from graphplan.sheets.form import TABLES, Form, enlarged, form, table
from graphplan.sheets.kinematics import ONE_SHEET, TITLE, acceleration_table, fields, notes
from graphplan.sheets.kintables import title_in
from graphplan.util.errors import GraphplanError, said_error
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


def inertia_table(st: Study, fp, lang: str, table_no: int = 1) -> Record:
    """Seed 000's table 2.3: per link m, I_S, the acceleration of its centre of mass and its ε read
    off the force position's acceleration plan (Table ``table_no``, the sheet's: π s × μa, ε), G = m·g,
    Φ = m·a_S and M^Φ = −I_S·ε from them — the very loads the force plans, the groups' tables and
    the lever take (``fp.inertia``, ``forceplans.plan_inertia``; ε and M^Φ + counter-clockwise) —
    each beside the closed form's with δ, % as the sheet's other tables give it (review 10 #14:
    the exact values alone were not the plan the sheet draws)."""
    from graphplan.graphic.forceplans import error_pct
    from graphplan.util.words import pct
    _pct = lambda v, lang: pct(v, lang).replace("-", "−")  # noqa: E731  (δ as the results table signs it)
    from graphplan.graphic.record import text_width
    w = lambda key, **f: word(f"fs {key}", lang, **f)  # noqa: E731
    mech = st.mech
    exact = word("exact", lang)
    head = [w('link'), f"m, {unit('kg', lang)}", f"I_S, {unit('kg·m²', lang)}", f"a_S, {unit('m/s²', lang)}",
            f"ε, {unit('rad/s²', lang)}", f"G, {unit('N', lang)}", f"Φ, {unit('N', lang)}",
            f"{exact}, {unit('N', lang)}", "δ, %", f"M^Φ, {unit('N·m', lang)}", f"{exact}, {unit('N·m', lang)}", "δ, %"]
    rows = [head]
    forces = [abs(i.exact_force) for i in fp.inertia.values()] + [1.0]
    couples = [abs(i.exact_couple) for i in fp.inertia.values()] + [1e-9]
    fallback = []
    for name, i in fp.inertia.items():
        link = mech.links[name]
        if i.source != "plan":
            fallback.append(str(link.number))
        f, fx = number(abs(i.force), 4, lang), number(abs(i.exact_force), 4, lang)
        m, mx = number(i.couple, 4, lang), number(i.exact_couple, 4, lang)
        # δ of the loads themselves (δΦ = δa_S of Table 1: the 4 figures printed here would move it, 0,18 → 0,22 %)
        df = error_pct(abs(i.force), abs(i.exact_force), max(forces))
        dm = error_pct(i.couple, i.exact_couple, max(couples))
        rows.append([f"{link.number} ({i.point})", number(i.mass, 4, lang), number(i.inertia, 4, lang),
                     number(abs(i.a), 4, lang), number(i.eps, 4, lang), number(i.mass * mech.g, 4, lang),
                     f, fx, _pct(df, lang) if i.mass else "—", m, mx, _pct(dm, lang) if i.inertia else "—"])
    # each column as wide as its widest cell (the head's markup read as set: I_S, M^Φ) and 3 mm
    widths = [max(text_width(str(r[k]).replace("_", "").replace("^", ""), 2.5) for r in rows) + 3.0
              for k in range(len(head))]
    widths = [max(x, 12.0) for x in widths]
    rec = table(rows, widths, row_h=6.0, size=2.5, title=w('inertia'))
    from graphplan.sheets.kinematics import footnoted
    notes = [w('inertia note', n=table_no)]
    if fallback:
        notes.append(w('inertia exact rows', links=", ".join(fallback)))
    return footnoted(rec, notes)


def force_position(st: Study, phi: float, lang: str, short: bool = False) -> str:
    """The force position as the scene assigns it: the crank's turn from position 0
    (``positions.force_phi_deg``, in the crank's sense) with the crank angle from the x axis —
    "φ = 200° від положення 0 (кут кривошипа 45,7° від осі x)": the crank angle as the kinematics
    sheet gives position 0's (``kintables.phi_convention``: from the x axis, one decimal; review 10
    read 285,50° here against 75,5° there as two conventions). ``short``: a caption's form, the
    angle without "crank angle" ("φ = 200° від положення 0 (45,7° від осі x)"), as wide as the
    caption was before the axis was named — the notes say it in full."""
    turn = round(float(st.from_position0(phi)), 9) % 360.0
    text = word("fs force position short" if short else "fs force position", lang, turn=num(turn, lang, 4), phi=fixed(phi % 360.0, lang, 1))
    return text + idle_words(st, phi, lang)


def idle_words(st: Study, phi: float, lang: str) -> str:
    """The stroke-bound loads acting at the force position, by the stroke it lies on (review 11 #17;
    review 53 #1: two moments on one lever, one per stroke, were said "M_3 = 0" on the idle stroke
    while its 260 N·m acted): ", idle stroke: P_D = 0", ", idle stroke: M_3 = 260 N·m". Each
    ``[[force]]``/``[[moment]]`` bound to a stroke is named once by its symbol with the value it
    has at the position (``kinetostatics.loads``: its magnitude on its own stroke, its profile's
    factor, 0 on the other stroke; loads of one symbol summed). Nothing when no load is
    stroke-bound, nor on the working stroke when every stroke-bound load is the working stroke's
    (the tables give it)."""
    import numpy as np

    from graphplan.exact.kinetostatics import force_working, loads, working_stroke
    from graphplan.util.words import force_symbol
    mech = st.mech
    bound = [f"P_{f.point}" for f in mech.forces if f.stroke != "both"]
    bound += [f"M_{mech.links[m.link].number}" for m in mech.moments if m.stroke != "both"]
    if not bound:
        return ""
    at = np.atleast_1d(float(phi))
    working = np.atleast_1d(working_stroke(st, at))
    on_work = bool(working[0])
    # each piston's force on its own stroke (kinetostatics.force_working: a V-twin's P_C may be idle
    # while the output's P_B works)
    forces_work = all(f.stroke == "working" and bool(np.atleast_1d(force_working(st, f.point, at, working))[0])
                      for f in mech.forces if f.stroke != "both")
    if on_work and forces_work and all(m.stroke == "working" for m in mech.moments if m.stroke != "both"):
        return ""
    acting = [ld for ld in loads(st, st.solve(at), working) if ld.kind == "external"]
    said = []
    for name in dict.fromkeys(bound):
        mine = [ld for ld in acting if ld.name == name]
        couple = name.startswith("M_")
        value = abs(sum(float(np.atleast_1d(ld.couple)[0]) for ld in mine)) if couple else \
            abs(sum(complex(np.atleast_1d(ld.force)[0]) for ld in mine))
        sym = force_symbol(name, lang)
        said.append(f"{sym} = 0" if value < 1e-9 else f"{sym} = {num(value, lang, 4)} {unit('N·m' if couple else 'N', lang)}")
    return f", {word('fs working' if on_work else 'fs idle', lang)}: {', '.join(said)}"


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
        # a reaction the ruler reads 0 mm, read off the plan's detail: its reading there too ("R05 0 мм
        # (I: 4,5 мм)")
        from graphplan.drawing.charts import DETAIL_NAME
        detail = {m.name: f" ({DETAIL_NAME}:\u00a0{num(m.mm, lang, 2)}\u00a0{unit('mm', lang)})"
                  for m in gp.reactions.values() if m.detail_mu}
        out += [f"{force_symbol(s.name, lang)} {num(measure(s.mm, fp.precision), lang, 2)} {unit('mm', lang)}"
                f"{detail.get(s.name, '')}, {fixed(100 * s.mm / big, lang, 1)} %"
                for s in sides if s.mm < SHORT_FORCE_MM]
        # a load the ruler reads as 0 mm is no side of the plan (its table says 0): named with its bound
        drawn = {s.name for s in sides}
        out += [f"{force_symbol(f.name, lang)} < {num(fp.precision, lang, 2)} {unit('mm', lang)}"
                for f in gp.forces if f.force != 0 and f.name not in drawn and fp.precision > 0]
    return list(dict.fromkeys(out))


FAMILIES = ("scheme", "groups", "forces", "acceleration", "lever", "charts", "hodographs")
TARGETS = {"scheme": 250.0, "groups": 250.0, "forces": POLYGON_MM, "acceleration": 120.0, "lever": 100.0,
           "charts": 1.0, "hodographs": 1.0}
SMALL_CAPTION = {"hodographs": 3.5}       # the caption's letter height under a small drawing
LEVER_STEP = 1.25     # the lever grown in the composition's rounds by at least this factor a step
LEVER_MM = 150.0      # the lever grown at most this across, forces included (seed 000's: p_v a = 55, p_v c 102 mm),
# in the composition's rounds and into the room the composed sheet leaves it (``_grown_lever``; it grew
# up to 200 mm there for the pump six-bar's 19 loads, review 45 #2, and drew the shaper's 172 mm where the
# lever's row wrapped — the pump's lever is lettered by its arms within 150 mm now)
LETTERING = 10.0      # mm a drawing's lettering is assumed to add across and up before it is placed


GROUP = "group "      # mu["group I(0-1)"]: a group drawn at its own scale


def group_scales(mu: dict[str, float]) -> tuple[tuple[str, float], ...]:
    """The groups the plan draws at their own scales, (label, μl) in order."""
    return tuple(sorted((k[len(GROUP):], v) for k, v in mu.items() if k.startswith(GROUP)))


PLAN = "plan "        # mu["plan II(4-5)"]: a group's force plan drawn at its own μF


def plan_scales(mu: dict[str, float]) -> tuple[tuple[str, float], ...]:
    """The force plans the sheet draws at their own μF, (label, μF) in order."""
    return tuple(sorted((k[len(PLAN):], v) for k, v in mu.items() if k.startswith(PLAN)))


@dataclass
class ForceDrafter:
    """Draws what the force sheet holds at given scales, remembering it."""
    st: Study
    opts: SheetOptions

    def __post_init__(self) -> None:
        from graphplan.drawing import charts as forcecharts
        from graphplan.exact import kinetostatics
        self.phi = float(np.atleast_1d(kinetostatics.at_scene_angle(self.st))[0])
        self.ks = kinetostatics.analyse(self.st, [self.phi])
        self.turn = forcecharts.turn(self.st)
        self.memo: dict = {}
        # μa of the acceleration plan whose readings load the force plans (Φ = m·a_S, M^Φ = −I_S·ε):
        # None while the sheet is composed (the plan at its own μa: a force plan's size then does not
        # move with the acceleration plan's scale as that grows), the sheet's μa once it is (``plan``)
        self.accel_mu: float | None = None

    def _once(self, key, make):
        if key not in self.memo:
            self.memo[key] = make()
        return self.memo[key]

    def _kept(self, key, make) -> list[Record]:
        """``_once`` for a list of records, each handed out as its own copy (its own list of the
        same immutable primitives): one drawing serves several sets of scales."""
        return [Record(r.title, list(r.items), dict(r.scales)) for r in self._once(key, make)]

    def fp(self, mu_l: float | None = None, mu_F: float | None = None, mu_v: float | None = None,
           group_mu: tuple[tuple[str, float], ...] = (), plan_mu: tuple[tuple[str, float], ...] = (),
           mu_a: float | None = None):
        """The force plans at these scales, their inertia loads read off the acceleration plan the
        sheet draws at ``mu_a`` (default ``accel_mu``; ``plans``: its Table 1)."""
        from graphplan.graphic import forceplans
        mu_a = self.accel_mu if mu_a is None else mu_a
        return self._once(("fp", mu_l, mu_F, mu_v, group_mu, plan_mu, mu_a), lambda: forceplans.construct(
            self.st, self.phi, precision=self.opts.precision, mu_l=mu_l, mu_F=mu_F, mu_v=mu_v,
            group_mu=dict(group_mu), group_mu_F=dict(plan_mu), accel=self.plans(mu_a)))

    def group_size(self, mu: dict[str, float], i: int, mu_l: float, caption: tuple[float, float]) -> tuple[float, float]:
        """Group i drawn (lettered, both languages) at its own μl ``mu_l``, the others as ``mu``:
        its cell with the caption. Drawn, not scaled from the family's model: a crank group whose
        force arrows outreach its short crank keeps its size while μl shrinks, until the crank
        outgrows them (the sieve's crank at 1:0.5 was taken for 64 mm, drawn 152 mm, over the frame)."""
        from graphplan.drawing import forces as forcedraw
        from graphplan.util.words import LANGS

        def make():
            base = self.groups_fp(mu)
            label = base.groups[i].label
            own = tuple(sorted({**dict(group_scales(mu)), label: mu_l}.items()))
            fp = self.fp(mu["groups"], mu["forces"], mu["lever"], own, plan_scales(mu))
            wh = [_wh(forcedraw.group_record(fp, fp.groups[i], lang)) for lang in LANGS]
            return max(max(w for w, _ in wh), caption[0]), max(h for _, h in wh) + caption[1]
        return self._once(("group size", i, mu_l, mu["groups"], mu["forces"], mu["lever"], plan_scales(mu),
                           self.accel_mu), make)

    def scheme_size(self, mu: dict[str, float], mu_l: float, caption: tuple[float, float]) -> tuple[float, float]:
        """The scheme drawn (lettered, both languages) at μl ``mu_l``: its cell with the caption —
        drawn, not scaled from the family's model (its loads' arrows keep their length)."""
        from graphplan.drawing import forces as forcedraw
        from graphplan.util.words import LANGS

        def make():
            fp = self.fp(mu_l, mu["forces"], mu["lever"])
            wh = [_wh(forcedraw.mechanism_record(fp, lang)) for lang in LANGS]
            return max(max(w for w, _ in wh), caption[0]), max(h for _, h in wh) + caption[1]
        return self._once(("scheme size", mu_l, mu["forces"], self.accel_mu), make)

    def plan_size(self, mu: dict[str, float], i: int, mu_F: float, caption: tuple[float, float]) -> tuple[float, float]:
        """Group i's force plan drawn (lettered, both languages) at its own μF ``mu_F``: its cell
        with the caption (a plan's lettering and small forces do not scale with it: the six-bar's
        II(4-5) at 5 N/mm came out 188 mm across where the family's model said 149)."""
        from graphplan.drawing import forces as forcedraw
        from graphplan.util.words import LANGS

        def make():
            base = self.groups_fp(mu)
            label = base.groups[i].label
            own = tuple(sorted({**dict(plan_scales(mu)), label: mu_F}.items()))
            fp = self.fp(mu["groups"], mu["forces"], mu["lever"], group_scales(mu), own)
            wh = [_wh(forcedraw.polygon_record(fp, fp.groups[i], lang)) for lang in LANGS]
            return max(max(w for w, _ in wh), caption[0]), max(h for _, h in wh) + caption[1]
        return self._once(("plan size", i, mu_F, mu["groups"], mu["forces"], mu["lever"], group_scales(mu),
                           self.accel_mu), make)

    def hodograph_cells(self, mu_h: float) -> list[tuple[float, float]]:
        """The hodographs drawn (lettered and captioned, both languages) at the size factor
        1/``mu_h``, each cell the largest of them as the sheet sets them (``build_forces_sheet``).
        Drawn, not scaled from the family's model: μR steps along its series and the note under a
        hodograph, not its curve, set the width where it was measured (the compressor's at 1.6
        drawn 94.6 mm wide where the model, fitted at 1 and 0.5, said 99.7 — and kept them at 1.4)."""
        from graphplan.drawing.charts import HODOGRAPH_MM, hodograph_record
        from graphplan.util.words import LANGS

        def make():
            sizes = [_wh(captioned(hodograph_record(self.turn, k, HODOGRAPH_MM / mu_h, lang=lang),
                                   _caption(f"hodograph {k}", lang), size=SMALL_CAPTION["hodographs"]))
                     for lang in LANGS for k in self.turn.revolute]
            if not sizes:
                return []
            cell = (max(w for w, _ in sizes), max(h for _, h in sizes))
            return [cell] * len(self.turn.revolute)
        return self._once(("hodograph cells", round(mu_h, 12)), make)

    def groups_fp(self, mu: dict[str, float]):
        """The groups' force plans at the sheet's scales: μl, μF, μv, a group's own μl where the
        plan draws it larger (``mu["group <label>"]``) and a force plan's own μF
        (``mu["plan <label>"]``); the inertia loads the acceleration plan's at ``accel_mu``."""
        return self.fp(mu["groups"], mu["forces"], mu["lever"], group_scales(mu), plan_scales(mu))

    def plans(self, mu_a: float | None = None):
        from graphplan.graphic.forceplans import acceleration_plan      # only the plans drawn
        return self._once(("plans", mu_a), lambda: acceleration_plan(
            self.st, self.phi, count=self.opts.positions, precision=self.opts.precision, mu_a=mu_a))

    def drawings(self, mu: dict[str, float], lang: str = "uk", lettered: bool = True) -> dict[str, list[Record]]:
        """The drawings at the scales ``mu`` (no captions): family → records in order; sketched
        (labels not placed, drawing.labels.sketched) when not ``lettered``."""
        def make():
            if not lettered:
                from graphplan.drawing.labels import sketched
                with sketched():
                    return draw()
            return draw()

        def draw():
            from graphplan.drawing import charts as forcecharts
            from graphplan.drawing import forces as forcedraw
            from graphplan.drawing.plans import acceleration_records
            fp = self.groups_fp(mu)
            scheme = self.fp(mu["scheme"], mu["forces"], mu["lever"])
            plans = self.plans(mu["acceleration"])
            q = next(x for x in plans.positions if x.acceleration is not None)
            charts = forcecharts.records(self.turn, 1.0 / mu["charts"], lang, 1.0 / mu["hodographs"])
            names = self.names()
            # the scheme, the groups and their force plans read no μv (only the lever does): drawn
            # once for the scales they read, however the lever's scale moves in the rounds
            from graphplan.drawing.labels import _SKETCH
            keep = (lang, lettered, _SKETCH[-1], self.accel_mu, mu["forces"])
            own = (mu["groups"], group_scales(mu), plan_scales(mu))
            return {"scheme": self._kept(("scheme record", mu["scheme"]) + keep,
                                         lambda: [forcedraw.mechanism_record(scheme, lang)]),
                    "groups": self._kept(("group records",) + own + keep,
                                         lambda: [forcedraw.group_record(fp, gp, lang) for gp in fp.groups]),
                    "forces": self._kept(("polygon records",) + own + keep,
                                         lambda: [forcedraw.polygon_record(fp, gp, lang) for gp in fp.groups]),
                    "acceleration": [acceleration_records(plans)[q.key]],
                    "lever": [forcedraw.lever_record(fp, lang)],
                    "charts": [charts[n] for n in names["charts"]],
                    "hodographs": [charts[n] for n in names["hodographs"]]}
        return self._once(("drawings", lang, lettered, self.accel_mu) + tuple(sorted(mu.items())), make)

    def names(self) -> dict[str, list[str]]:
        """The drawings' names per family, in order (for captions and boxes), as
        ``drawing.charts.records`` names the charts."""
        from graphplan.drawing import charts as forcecharts

        def make():
            fp = self.fp()
            ext = any(ld.kind == "external" for ld in self.turn.ks.loads)
            more = [f"resistance {p}" for p in forcecharts.other_pistons(self.turn)] if ext else []
            charts = (["moment"] + (["resistance"] if ext else []) + more
                      + [f"reaction {k}" for k in forcecharts.slider_reactions(self.turn)])
            return {"scheme": ["mechanism"], "groups": [f"group {gp.label}" for gp in fp.groups],
                    "forces": [f"polygon {gp.label}" for gp in fp.groups], "acceleration": ["acceleration plan"],
                    "lever": ["lever"], "charts": charts,
                    "hodographs": [f"hodograph {k}" for k in self.turn.revolute]}
        return self._once(("names",), make)


def _captions(dr: ForceDrafter, mu: dict[str, float], lang: str) -> dict[str, list[tuple[str, str]]]:
    """Each drawing's caption (name, second line) in ``lang``."""
    from graphplan.graphic.scales import format_scale
    w = lambda key: word(f"fs {key}", lang)  # noqa: E731
    names = dr.names()
    # the captions' short form: the full one widened the scheme's and the acceleration plan's cells by
    # ~20 mm, and the sieve's A1 force sheet lost its grown crank group (1:2 → the family's 1:4)
    at = force_position(dr.st, dr.phi, lang, short=True)
    from graphplan.drawing.charts import resistance_loads
    moment_only = resistance_loads(dr.turn)[1]     # the chart's load: the output's own
    out = {"scheme": [(w('mechanism'), f"{format_scale('mu_l', mu['scheme'], lang)},  {at}")],
           "groups": [(_caption(n, lang), format_scale('mu_l', gp.mu_l or mu['groups'], lang))
                      for n, gp in zip(names["groups"], dr.groups_fp(mu).groups)],
           "forces": [(_caption(n, lang), "") for n in names["forces"]],     # μF under the plan itself
           "acceleration": [(f"{w('acceleration')}, {w('position')}",
                             f"{format_scale('mu_a', mu['acceleration'], lang)},  {at}")],
           "lever": [(_caption("lever", lang), "")],                           # μv under the lever itself
           "charts": [(w("resistance moment") if n == "resistance" and moment_only else
                       _resistance_caption(dr, n, lang) or _caption(n, lang), "") for n in names["charts"]],
           "hodographs": [(_caption(n, lang), "") for n in names["hodographs"]]}
    return out


def _resistance_caption(dr: ForceDrafter, name: str, lang: str) -> str | None:
    """A resistance diagram's caption naming its force where there is one per piston (stop 58's
    V-twin: «… P_B за хід», «… P_C за хід»); None otherwise (the one diagram's usual caption)."""
    kind, _, point = name.partition(" ")
    names = dr.names()["charts"]
    if kind != "resistance" or not any(n.startswith("resistance ") for n in names):
        return None
    return word("fs resistance of", lang, p=force_symbol(f"P_{point or dr.st.output.name}", lang))


def _tables(dr: ForceDrafter, mu: dict[str, float], lang: str, factor: float) -> list[tuple[str, Record]]:
    """The sheet's tables in reading order, lettered ``factor`` × 2.5 mm (``_tables_at``)."""
    key = ("tables", lang, mu["acceleration"], mu["groups"], mu["forces"], mu["lever"], group_scales(mu),
           plan_scales(mu), dr.accel_mu)
    return [(name, enlarged(rec, factor)) for name, rec in dr._once(key, lambda: _tables_at(dr, mu, lang))]


def _tables_at(dr: ForceDrafter, mu: dict[str, float], lang: str) -> list[tuple[str, Record]]:
    """The sheet's tables in reading order: the force position's accelerations, the masses and
    inertia loads, each group's forces, the balancing moment and the reactions."""
    from graphplan.drawing import forces as forcedraw
    from graphplan.report.plans import plans_json
    st, p = dr.st, dr.opts.precision
    plans = dr.plans(mu["acceleration"])
    acc_doc = next(d for d in plans_json(plans)["positions"] if "acceleration" in d)
    n = len(st.mech.task.accel) + 1 if st.mech.task.accel else 2   # after the kinematics sheet's 2.1 …
    fp = dr.groups_fp(mu)
    # numbered 1, 2, 3 … in reading order on this sheet (not the kinematics sheet's 2.n, nor a fixed 5)
    out = [("acceleration table", _renumbered(acceleration_table(acc_doc, n, lang, p), 1)),
           ("inertia table", _renumbered(inertia_table(st, fp, lang, 1), 2))]
    for k, gp in enumerate(fp.groups, 3):
        rec = forcedraw.group_table_record(fp, gp, lang)
        title = forcedraw.table_title(k, f"{_caption(f'table {gp.label}', lang)}, {unit('N', lang)}", lang)
        out.append((f"table {gp.label}", _titled(rec, title)))
    out.append(("results", forcedraw.results_record(fp, lang, number=3 + len(fp.groups))))
    return out


_NUMBER = re.compile(r"^(Таблиця|Table) [0-9]+(?:\.[0-9]+)?\.")


def _renumbered(rec: Record, n: int) -> Record:
    """A table whose title carries another sheet's number ("Таблиця 2.2.", "Таблиця 5.") numbered
    ``n`` as this sheet reads it."""
    from dataclasses import replace
    items = [replace(p, text=_NUMBER.sub(lambda m: f"{m.group(1)} {n}.", p.text, count=1))
             if p.kind == "text" and _NUMBER.match(p.text) else p for p in rec.items]
    return Record(rec.title, items, dict(rec.scales))


def _titled(rec: Record, title: str) -> Record:
    """A table record with its title above it, as the sheet's other tables carry theirs."""
    out = Record(rec.title, list(rec.items), dict(rec.scales))
    x0, _, _, y1 = rec.bounds()
    out.label((x0, y1 + 2.2), title, size=3.5, layer="tables")
    return out


def _hodographs_share(dr: ForceDrafter, mu_h: float) -> bool:
    """Whether a hodograph drawn at the size factor 1/``mu_h`` (or its detail) numbers two
    positions as one ("0–2"): drawn unlettered (the shared numbers do not depend on where the
    numbers stand), once per size."""
    def make() -> bool:
        from graphplan.drawing.charts import HODOGRAPH_MM, hodograph_record
        from graphplan.drawing.labels import sketched
        with sketched():
            return any(hodograph_record(dr.turn, k, HODOGRAPH_MM / mu_h, "en").scales.get("shared numbers", 0) > 0
                       for k in dr.turn.revolute)
    return dr._once(("hodographs share", mu_h), make)


def _notes_lines(dr: ForceDrafter, mu: dict[str, float], lang: str) -> list[str]:
    from graphplan.graphic.scales import format_scale
    w = lambda key: word(f"fs {key}", lang)  # noqa: E731
    fp = dr.groups_fp(mu)
    small = small_forces(fp, lang)
    lines = [f"{w('position').capitalize()}: {force_position(dr.st, dr.phi, lang)}"] + ([w('small') + "; ".join(small)] if small else [])
    if _hodographs_share(dr, mu["hodographs"]):      # the hodographs' "0–2", said once
        lines.append(w('coincide'))
    # an inertia couple carried onto the lever as a moment beside others as pairs of forces: why
    # (graphic.lever.READABLE_MM; review 55 #7: the lab's seed 000 writes P' = M/l for every couple)
    from graphplan.graphic.lever import READABLE_MM
    couples = [t for t in dr.fp(mu["scheme"], mu["forces"], mu["lever"]).lever.terms if t.pair and not t.vector]
    if couples:
        lines.append(word("fs couple", lang, what=", ".join(force_symbol(t.name, lang) for t in couples),
                          seg=", ".join(f"{t.pair[0].lower()}{t.pair[1].lower()}" for t in couples),
                          mm=num(READABLE_MM, lang)))
    scales = [format_scale("mu_l", mu["scheme"], lang)]
    by_scale: dict[float, list[str]] = {}
    for gp in fp.groups:                  # each group at its own scale (forceplans.group_scales)
        by_scale.setdefault(gp.mu_l or mu["groups"], []).append(gp.label)
    for m_l, labels in by_scale.items():
        if m_l != mu["scheme"]:
            scales.append(format_scale("mu_l", m_l, lang) + f" ({w('group').lower()} {', '.join(labels)})")
    forces: dict[float, list[str]] = {}
    for gp in fp.groups:                  # each force plan at its own μF (stated under it, too)
        forces.setdefault(gp.mu_F or mu["forces"], []).append(gp.label)
    for m_F, labels in forces.items():
        tail = f" ({w('polygon').lower()} {', '.join(labels)})" if len(forces) > 1 else ""
        scales.append(format_scale("mu_F", m_F, lang) + tail)
    scales += [format_scale(m, mu[k], lang) for m, k in (("mu_a", "acceleration"), ("mu_v", "lever"))]
    from graphplan.sheets.compose import lines_of
    return lines_of(notes(dr.st, scales, lines, lang))


@dataclass
class Natural:
    """The force sheet's drawings measured once (both languages): the families, the tables per
    lettering factor, the notes' lines."""
    families: dict[str, Family]
    tables: dict[float, list[tuple[str, float, float]]]
    notes: list[list[str]]


@dataclass
class Crowded(Family):
    """A family whose drawings' lettering is assumed to stick out no further at a larger drawing
    than at a smaller one: at a scale where drawing i was not drawn, what its lettering added at
    the scales drawing it as large or larger (and as measured first), not the most it added
    anywhere (``Family.lettering``). Labels placed round a small, crowded drawing go out on long
    leaders (the pump six-bar's lever at μv 0.0239: a 48 mm figure lettered 165 × 175 mm); taken
    for every scale, that margin shrank the lever's row and, through it, the scheme and the groups,
    whose own lettering at 1:10 (labels pushed round a 7 mm crank) then barred 1:4 — the sheet
    ended at 1:10 with the A1 field a third empty (review 45 #1)."""

    def lettering(self, mu: float, i: int) -> tuple[float, float]:
        got = self.seen.get((round(mu, 12), i))
        if got is not None:
            return got
        larger = [v for (m, j), v in self.seen.items() if j == i and m <= mu * (1 + 1e-9)]
        lw, lh = self.sizes[i][2:]
        return max([lw] + [v[0] for v in larger]), max([lh] + [v[1] for v in larger])

    def allow(self, mu: float, w: float, h: float, i: int) -> bool:
        """Drawn at μ, drawing i came out w × h (without its caption): what its lettering adds
        there is remembered for that scale and the smaller drawings (``lettering``). Whether the
        assumption held."""
        k = self.mu0 / mu
        gw, gh = self.sizes[i][:2]
        need = (w - gw * (k if self.across else 1.0), h - gh * (k if self.up else 1.0))
        was = self.lettering(mu, i)
        self.seen[(round(mu, 12), i)] = need
        return need[0] <= was[0] + 1e-6 and need[1] <= was[1] + 1e-6


@dataclass
class LeverFamily(Crowded):
    """The lever's family, grown in finer steps than the series' (up to twice as large — seldom
    room for it in the lever's row): the next of the velocity plans' choices (graphic.scales.
    larger_choices: the round values, GOST's 1.5, 7.5 × 10^k between the series' steps, then p_v a
    chosen in 5 mm steps), so that the lever takes its share of a row in turn with the other
    drawings; at most ``LEVER_MM`` across."""
    figure: float = 0.0      # the drawing's figure across at μ = 1 (its lines without the forces), mm
    arrows: float = 0.0      # what the forces' arrows (of one length at any μ) add across, mm

    def lines_across(self, mu: float) -> float:
        """The drawing's lines across at μ, mm."""
        return self.figure / mu + self.arrows

    def choices(self, mu: float, most: float = LEVER_MM) -> list[tuple[float, bool]]:
        """(μ, round?) that draw the lever larger than μ and at most ``most`` mm across, the
        smallest drawing first."""
        from graphplan.graphic.scales import larger_choices
        if self.figure <= 0:
            return []
        return [(m, rnd) for m, rnd in larger_choices(self.principal, mu, self.principal * most / self.figure)
                if self.lines_across(m) <= most + 1e-9]

    def finer(self, mu: float) -> float | None:
        steps = self.steps(mu)
        return steps[0] if steps else None

    def steps(self, mu: float) -> list[float]:
        """The next sizes to try, largest first: a step as large as the other families' (the first
        choice that draws the lever ``LEVER_STEP`` times as large, else the largest there is), then
        one about half as large, then the next choice (p_v a 5 mm longer) — so that the lever takes
        what room its row has left when a whole step no longer fits (``_levels``)."""
        nxt = [m for m, _ in self.choices(mu)]
        if not nxt:
            return []
        big = next((m for m in nxt if mu / m >= LEVER_STEP - 1e-9), nxt[-1])
        mid = next((m for m in nxt if mu / m >= (1 + LEVER_STEP) / 2 - 1e-9), nxt[-1])
        return list(dict.fromkeys(m for m in (big, mid, nxt[0]) if m >= big))


@dataclass
class Floored(Crowded):
    """A family of size factors never started below ``floor`` (the hodographs: a teacher reads one
    whose larger extent is ~60 mm on A1; the sheet's other drawings give way first)."""
    floor: float = 0.0
    cap: float = math.inf

    def start(self, k: float) -> float:
        return super().start(max(k, self.floor))

    def finer(self, mu: float) -> float | None:
        m = super().finer(mu)
        return m if m is not None and self.rel(m) <= self.cap + 1e-9 else None


@dataclass
class Capped(Crowded):
    """The force plans' family: never drawn with the analysis' largest force longer than ``cap``
    times its target (``FORCES_MOST``). A group of the third kind loaded by a moment alone (the
    rocking coulisse's R12 ≈ R03 ≈ 510 N against G, Φ of 14–90 N) grew into the sheet's room to
    μF = 1 N/mm: 510 mm slivers 40 mm wide across the sheet, their short sides squeezed at one
    end (review 49 #2) — seed 000 draws its largest force 162 mm."""
    cap: float = math.inf

    def start(self, k: float) -> float:
        return super().start(min(k, self.cap))

    def finer(self, mu: float) -> float | None:
        m = super().finer(mu)
        return m if m is not None and self.rel(m) <= self.cap + 1e-9 else None


# the longest force of a plan drawn at most this times ``POLYGON_MM`` (225 mm) however much room the sheet has
FORCES_MOST = 1.5


HODOGRAPHS_FLOOR = 1.0    # the hodographs' least size factor on one sheet (drawing.charts.HODOGRAPH_MM)
HODOGRAPHS_CAP = 1.0      # … and the largest they grow to: the room beyond goes to the lever and the charts


def lever_across(lv) -> float:
    """The lever's figure across (the larger of its width and height), mm: the velocity plan
    turned, the pole with the points' images, without the forces (their arrows keep their length
    at any μv)."""
    zs = [1j * z for z in lv.images.values()] + [0j]
    xs, ys = [z.real for z in zs], [z.imag for z in zs]
    return max(max(xs) - min(xs), max(ys) - min(ys))


def measure(dr: ForceDrafter) -> Natural:
    from graphplan.util.words import LANGS
    fp = dr.fp()
    plans = dr.plans()
    mu0 = {"scheme": fp.mu_l, "groups": fp.mu_l, "forces": fp.mu_F, "acceleration": plans.mu_a,
           "lever": fp.lever.mu_v, "charts": 1.0, "hodographs": 1.0}
    mu1 = {fam: (2.0 if fam in ("charts", "hodographs") else coarser(coarser(mu))) for fam, mu in mu0.items()}
    recs, recs1 = dr.drawings(mu0, lettered=False), dr.drawings(mu1, lettered=False)
    biggest = max([float(np.max(np.abs(ld.force))) for ld in dr.ks.loads]
                  + [float(np.max(np.abs(r.force))) for r in dr.ks.reactions.values()] + [1e-9])
    extent = TARGETS["scheme"] * fp.mu_l        # the mechanism's extent the default μl was chosen by
    mech = dr.st.mech
    a_a = mech.crank.length * (mech.omega1 ** 4 + mech.crank.epsilon ** 2) ** 0.5
    v_a = abs(mech.omega1) * mech.crank.length
    principal = {"scheme": extent, "groups": extent, "forces": biggest, "acceleration": a_a, "lever": v_a,
                 "charts": 1.0, "hodographs": 1.0}
    caps = {lang: _captions(dr, mu0, lang) for lang in LANGS}
    families = {}
    for fam, rs in recs.items():
        families[fam] = measured_twice(rs, recs1[fam], mu0[fam], mu1[fam],
                                       [caps[lang][fam][i] for lang in LANGS for i in range(len(rs))],
                                       principal=principal[fam], target=TARGETS[fam],
                                       factors=fam in ("charts", "hodographs"), caption=SMALL_CAPTION.get(fam, 5.0),
                                       lettering=LETTERING)
    families = {fam: Crowded(**vars(x)) for fam, x in families.items()}
    families["forces"] = Capped(**vars(families["forces"]), cap=FORCES_MOST)
    figure = lever_across(fp.lever)
    lines = Record(items=[q for q in recs["lever"][0].items if q.kind != "text"]).bounds()
    # flat hodographs (the press's, 8000 N down and 300 N across: 60 × 15 mm slivers) grow to the
    # area of a round one (charts.hodograph_growth, the flattest's share) — the last to take the
    # room the sheet has left, never a main drawing's or a chart's
    from graphplan.drawing.charts import FLAT_GROWTH, hodograph_growth
    grown = min([hodograph_growth(dr.turn, k) for k in dr.turn.revolute] + [FLAT_GROWTH])
    families["hodographs"] = Floored(**vars(families["hodographs"]), floor=HODOGRAPHS_FLOOR,
                                     cap=HODOGRAPHS_CAP * grown)
    families["lever"] = LeverFamily(**vars(families["lever"]), figure=figure * fp.lever.mu_v,
                                   arrows=max(0.0, max(lines[2] - lines[0], lines[3] - lines[1]) - figure))
    tables = {}
    for factor in (TABLES, 1.0):
        per = [[(name, *_wh(rec)) for name, rec in _tables(dr, mu0, lang, factor)] for lang in LANGS]
        tables[factor] = [(a[0], max(a[1], b[1]), max(a[2], b[2])) for a, b in zip(*per)]
    return Natural(families, tables, [_notes_lines(dr, mu0, lang) for lang in LANGS])


def _wh(rec: Record) -> tuple[float, float]:
    b = rec.bounds()
    return b[2] - b[0], b[3] - b[1]


def _column(f: Form, tables: list[Leaf], parts: int, height, counts: tuple[int, ...] = ()
            ) -> tuple[Leaf, list[list[Leaf]], float]:
    """The tables' column: ``parts`` columns of tables (as ``split`` finds them, or ``counts`` tables
    each as the plan found them), the notes under them, the title block's height kept free."""
    groups = split(tables, parts, counts=counts)
    cw, ch = column_size(groups)
    width = max(cw, TITLE)
    foot = keep_out(f)[3] - field_of(f)[1]
    return Leaf("column", width, ch + GAP + height(width) + GAP + foot), groups, width


ACROSS = " across"
SHAPES = ("column", "bands", "column" + ACROSS, "bands" + ACROSS, "low", "low" + ACROSS, "lever up" + ACROSS)
# the families grown in turn in these orders; the better composition kept (a tight sheet where the
# force plans, grown first, leave the groups at 0.4 of their size has a twin with both at ≥ 0.56)
ORDERS = (("scheme", "forces", "groups", "acceleration", "lever", "charts", "hodographs"),
          ("scheme", "groups", "forces", "acceleration", "lever", "charts", "hodographs"))


SCHEME_FIRST = ("scheme first",)     # ``_one_sheet_at``: the scheme and the groups grown first (``_scheme_first``)
HROWS = (3, 1, 2)     # the rows the hodographs' grid may end (the charts' row first)
CUTS = (-1, 0)        # the charts in the lever's row (``_tree``): the shape's own count, else none (the row
                      # wrapped: ROCKING_BLOCK51's lever 80 × 70 mm beside the M_зр chart over a half-empty row)
SPACE = forceset.SPACE     # mm between two groups, a group and its plan (review 7 #18)
ROWS_GAP = GAP             # … between the one-sheet composition's other drawings


def _groups_node(shape: str, leaves: dict[str, list[Leaf]]):
    """The groups with their force plans: a row per group, or (``… across``) side by side."""
    if shape.endswith(ACROSS):
        return Row([Stack([g, p], SPACE) for g, p in zip(leaves["groups"], leaves["forces"])], SPACE)
    return Stack([Row([g, p], SPACE) for g, p in zip(leaves["groups"], leaves["forces"])], SPACE)


def _chart_rows(charts: list, tail: list, wrap: int = 0) -> list[list]:
    """The charts' row under the lever's (``tail`` at its end: the hodographs, the tables' column),
    wrapped after every ``wrap`` charts (0: one row)."""
    if wrap <= 0 or len(charts) <= wrap:
        return [list(charts) + list(tail)]
    rows = [list(charts[i:i + wrap]) for i in range(0, len(charts), wrap)]
    rows[-1] += list(tail)
    return rows


def _tree(shape: str, leaves: dict[str, list[Leaf]], hcols: int, C: Leaf, hrow: int = 3, groups=None, H=None,
          cut: int = -1, wrap: int = 0):
    """The force sheet's composition: the scheme beside the groups (each group a row: its drawing,
    its force plan), the acceleration plan and the lever, the charts; "column" — the tables' column
    the sheet's full height at the right; "bands" — the column under the groups' band; "low" — the
    scheme and the groups across the full width, the column under them at the right beside the
    acceleration plan, the lever and the charts; "lever up" — so, the lever in the top row; "… across"
    — the groups side by side, each over its force plan (a tall, narrow mechanism's groups: the
    slotter's at 1:5 instead of 1:10). The hodographs' grid ends row ``hrow`` (1, 2 or 3): the
    charts' row, or beside the groups or the lever where those leave the room (the slotter's five
    at 60 mm beside its narrow groups). ``cut``: the charts in the lever's row (the rest in the row
    under it), −1 the shape's own count — the row wraps where the lever would be squeezed by the
    charts beside it while the row under them is half empty (ROCKING_BLOCK51: its lever 80 × 70 mm
    between the acceleration plan and the M_зр chart, P_C's and Φ5's heads 2 mm apart). ``wrap``: at
    most this many charts to a row under the lever's (0: one row; ``_one_sheet``: INCLINED_ROCKER53's
    three charts, each at least 138 mm wide by its lettering, beside the 381 mm tables' column ran
    6 mm over the A1 field at every scale, and the sheet became a set of two A1 sheets)."""
    S = leaves["scheme"][0]
    groups = _groups_node(shape, leaves) if groups is None else groups     # (a leaf of its size: a trial)
    shape = shape.removesuffix(ACROSS)
    A, L = leaves["acceleration"][0], leaves["lever"][0]
    charts = leaves["charts"]
    if H is None:
        H = [Grid(leaves["hodographs"], hcols, ROWS_GAP)] if leaves["hodographs"] else []
    at = {k: H if k == hrow else [] for k in (1, 2, 3)}
    k = (2 if shape == "bands" else 1) if cut < 0 else cut
    if shape == "column":
        rows = [Row([S, groups] + at[1], ROWS_GAP), Row([A, L] + charts[:k] + at[2], ROWS_GAP)] + [
            Row(r, ROWS_GAP) for r in _chart_rows(charts[k:], at[3], wrap)]
        return Row([Stack([r for r in rows if r.children], ROWS_GAP), C], ROWS_GAP, flush=True)
    if shape in ("low", "lever up"):
        # the scheme and the groups across the sheet's full width, the column under them at the
        # right (the tables a short column: the press's two parts 348 mm high left 226 × 346 mm
        # under them blank while its groups were drawn at 1:10 beside a 1:4 scheme); "lever up" —
        # the lever in the top row too, where the row beside the column leaves it no room
        up = [L] if shape == "lever up" else []
        rows = [Row([A] + ([] if up else [L]) + charts[:k] + at[2], ROWS_GAP)] + [
            Row(r, ROWS_GAP) for r in _chart_rows(charts[k:], at[3], wrap)]
        return Stack([Row([S, groups] + up + at[1], ROWS_GAP),
                      Row([Stack([r for r in rows if r.children], ROWS_GAP), C], ROWS_GAP, flush=True)],
                     ROWS_GAP, flush=True)
    low = _chart_rows(charts[k:], at[3] + [C], wrap)
    rows = [Row([S, groups, A] + at[1], ROWS_GAP), Row([L] + charts[:k] + at[2], ROWS_GAP)] + [
        Row(r, ROWS_GAP, flush=r is low[-1]) for r in low]
    return Stack(rows, ROWS_GAP, flush=True)


def _levels(families: dict[str, Family], fits, order, largest=None, start=None,
            led: dict[str, str] | None = None, ruled: bool = False) -> dict[str, float] | None:
    """``compose.choose_levels`` where a family may offer smaller steps when its whole one does not
    fit (``LeverFamily.steps``): the largest common size factor that fits (or ``start``), then the
    families in ``order`` each grown by the first of its steps that still fits, round after round.
    ``led``: a family grown takes another along at least to its scale ({"scheme": "groups"}: the
    groups never at a smaller scale than the scheme, ``_one_sheet``). ``ruled`` (one sheet): an
    auxiliary drawing grown past its target only as ``aux_allowed`` lets it — held back, not given
    up, while the main drawings grow (a later round may let it on)."""
    from graphplan.sheets.compose import FACTORS
    mu = start if start is not None and fits(start) else \
        next((trial for trial in ({name: fam.start(k) for name, fam in families.items()} for k in FACTORS)
              if fits(trial)), None)
    if mu is None:
        return None
    growing = [name for name in order if name in families]
    changed = True
    while growing and changed:
        changed = False
        for name in list(growing):
            fam = families[name]
            steps = fam.steps(mu[name]) if isinstance(fam, LeverFamily) else [fam.finer(mu[name])]
            held = False
            for bigger in steps:
                if bigger is None or (largest is not None and not largest(name, bigger)):
                    continue
                if ruled and not aux_allowed(families, mu, name, bigger):
                    held = True
                    continue
                trial = {**mu, name: bigger}
                other = (led or {}).get(name)
                if other in trial and trial[other] > bigger * (1 + 1e-9):
                    trial[other] = bigger
                if fits(trial):
                    mu, changed = trial, True
                    break
            else:
                if not held:
                    growing.remove(name)
    return mu


def _next_coarser(fam: Family, mu: float) -> float:
    """The family's next smaller drawing's μ: the standard series' step; the lever's by its own
    choices (``LeverFamily``: p_v a in 5 mm steps between the round values)."""
    if isinstance(fam, LeverFamily) and fam.principal > 0:
        from graphplan.graphic.scales import larger_choices
        got = [m for m, _ in larger_choices(fam.principal, mu * 2.5, fam.principal / mu) if m > mu * (1 + 1e-9)]
        if got:
            return min(got)
    return coarser(mu)


# the drawings the force analysis is read from (the scheme, the groups, their force plans, the lever)
# and those that serve it (the acceleration plan the inertia loads are read off, the charts): on one
# sheet an auxiliary drawing grows past its target by the one step that takes it there, further only
# while it stays within ``AUX_OVER`` times the poorest main drawing's size against its target — the
# room goes to the poorest first (LINK61: its acceleration plan at 2.3 times its 120 mm, p a = 276 mm,
# the sheet's largest drawing, beside its scheme and groups at 1:10, a quarter of their target). So
# where one is drawn past that one step, the poorest main drawing is at least 1/``AUX_OVER`` of its
# size against its target. (The hodographs, auxiliary too, keep their own bounds: at most
# ``HODOGRAPHS_CAP`` in the rounds, grown last, into the room no other drawing takes, up to
# ``HODOGRAPHS_ROOM`` times that — ``_grown_hodographs``.)
MAIN_DRAWINGS = ("scheme", "groups", "forces", "lever")
AUXILIARY = ("acceleration", "charts")
AUX_OVER = 2.0


def poorest(families: dict[str, Family], mu: dict[str, float]) -> float:
    """The smallest of the main drawings' sizes against their targets at ``mu`` (a group or a
    force plan at its own scale counted too)."""
    rel = [families[n].rel(mu[n]) for n in MAIN_DRAWINGS if n in families and n in mu]
    rel += [families["groups"].rel(m) for _, m in group_scales(mu) if "groups" in families]
    rel += [families["forces"].rel(m) for _, m in plan_scales(mu) if "forces" in families]
    return min(rel + [math.inf])


def aux_allowed(families: dict[str, Family], mu: dict[str, float], name: str, bigger: float) -> bool:
    """Whether family ``name`` may be drawn at ``bigger`` (from ``mu[name]``) on one sheet: a main
    drawing always; an auxiliary one while it is under its target (the step may take it past: the
    shaper's acceleration plan at 0.72 or 1.45 of its target, no step between), past it up to
    ``AUX_OVER`` times the poorest main drawing's size against its target (``poorest``)."""
    if name not in AUXILIARY:
        return True
    fam = families[name]
    return fam.rel(mu[name]) < 1.0 - 1e-9 or fam.rel(bigger) <= max(1.0, AUX_OVER * poorest(families, mu)) + 1e-9


def _scheme_first(families: dict[str, Family], fits, mu: dict[str, float] | None) -> dict[str, float] | None:
    """The scheme and the groups (at one scale) grown a step at a time from ``mu`` while the sheet
    holds them, each step paid for by the acceleration plan or the lever, whichever is drawn larger
    against its target (a step coarser; the force plans', charts' and hodographs' sizes kept: the
    force plans' lettering is modelled no narrower at a coarser μF, ``Crowded``) while that drawing stays larger against its
    target than the smallest main drawing was before the step — the room taken from the richest for the poorest; then every
    family grown in turn (``_levels``, the auxiliary drawings as ``aux_allowed`` lets them). None where
    the scheme cannot grow so."""
    if mu is None:
        return None
    s = max(mu["scheme"], mu["groups"])
    cur, grew = {**mu, "scheme": s, "groups": s}, False
    while True:
        s1 = families["scheme"].finer(cur["scheme"])
        if s1 is None:
            break
        trial = {**cur, "scheme": s1, "groups": s1}
        need = min(families[n].rel(cur[n]) for n in MAIN)      # the smallest now: it must come out larger
        while not fits(trial):
            payers = [n for n in ("acceleration", "lever")
                      if families[n].rel(_next_coarser(families[n], trial[n])) > need * (1 + 1e-9)]
            if not payers:
                break
            rich = max(payers, key=lambda n: families[n].rel(trial[n]))
            trial = {**trial, rich: _next_coarser(families[rich], trial[rich])}
        if not fits(trial):
            break
        cur, grew = trial, True
    if not grew:
        return None
    return _levels(families, fits, ORDERS[1], start=cur, led={"scheme": "groups"}, ruled=True)


@dataclass
class Plan:
    mu: dict[str, float]
    tables: float
    shape: str = "column"
    hcols: int = 1
    parts: int = 1
    sheets: int = 1
    counts: tuple[int, ...] = ()     # the tables in each of the column's parts, in reading order
    hrow: int = 3                    # the row the hodographs end (``_tree``)
    cut: int = -1                    # the charts in the lever's row (``_tree``; −1 the shape's own)
    wrap: int = 0                    # at most this many charts to a row under the lever's (``_tree``; 0: one row)
    packed: bool = False             # a set: the drawings' rows side by side where they fit (``_packed``)
    where: tuple = ()                # a set: the drawings' names on each sheet (kept as drawings grow)
    plan_first: bool = True          # a set: the acceleration plan before the groups, else after them
    gap: float = SPACE               # a set: mm between its drawings (``SPACE``, else ``GAP`` where that saves a sheet)


def _free_box(inner: Box, others: list[Box], region: Box, keep: Box, gap: float) -> Box | None:
    """The box ``inner`` widened left and right, then up and down, as far as the field goes without
    coming within ``gap`` of another drawing's box or the title block's ``keep``; None where
    ``inner`` itself is not that clear (a set's hodographs beside a chart that stands within their
    cells' bounding box: the shaper's A3 sheet 4)."""
    def clear(b: Box) -> bool:
        return all(b[2] + gap <= o[0] + 1e-9 or o[2] + gap <= b[0] + 1e-9
                   or b[3] + gap <= o[1] + 1e-9 or o[3] + gap <= b[1] + 1e-9 for o in others + [keep])
    if not clear(inner):
        return None
    x0, y0, x1, y1 = inner
    lefts = [o[2] + gap for o in others + [keep] if o[2] <= x0 + 1e-9 and o[1] < y1 and o[3] > y0]
    rights = [o[0] - gap for o in others + [keep] if o[0] >= x1 - 1e-9 and o[1] < y1 and o[3] > y0]
    x0, x1 = min(x0, max(lefts + [region[0]])), max(x1, min(rights + [region[2]]))
    downs = [o[3] + gap for o in others + [keep] if o[3] <= y0 + 1e-9 and o[0] < x1 and o[2] > x0]
    ups = [o[1] - gap for o in others + [keep] if o[1] >= y1 - 1e-9 and o[0] < x1 and o[2] > x0]
    out = (x0, min(y0, max(downs + [region[1]])), x1, max(y1, min(ups + [region[3]])))
    return out if clear(out) else inner


def _hodographs_fitted(dr: ForceDrafter, p: Plan, items: list[Placed], region: Box, keep: Box,
                       lang: str) -> list[Placed]:
    """A set's sheet's hodographs set again, each in its own cell of a grid fitted to them
    (``Grid.fitted``: a column as wide as its widest, a row as tall as its tallest), at the largest
    size factor (up to ``SET_HODOGRAPHS_LARGEST``, never smaller than planned) and column count
    that fit the free room round the equal cells the set planned for them — the sheet's other
    drawings, their sheets and the notes as planned. LINK47's A1 sheet 2: six hodographs in the
    largest one's 150 × 160 mm cell, the flat R12, R23, R01 (a 15 N/mm sliver each) a 160 mm tall
    row, 190 and 170 mm blank either side. Sized in both languages, so that the two sheets agree."""
    from graphplan.drawing.charts import HODOGRAPH_MM, hodograph_record
    from graphplan.sheets.compose import FACTORS
    from graphplan.util.words import LANGS
    hod = [q for q in items if q.name.startswith("hodograph ")]
    if not hod:
        return items
    rest = [q for q in items if not q.name.startswith("hodograph ")]
    inner = (min(q.box[0] for q in hod), min(q.box[1] for q in hod), max(q.box[2] for q in hod),
             max(q.box[3] for q in hod))
    room = _free_box(inner, [q.box for q in rest], region, keep, p.gap)
    if room is None:
        return items
    keys = [q.name.removeprefix("hodograph ") for q in hod]
    mu0 = p.mu["hodographs"]
    shared = _hodographs_share(dr, mu0)

    def drawn(mu_h: float, lg: str) -> list[Record]:
        return dr._once(("fitted hodographs", round(mu_h, 12), lg, tuple(keys)), lambda: [
            captioned(hodograph_record(dr.turn, k, HODOGRAPH_MM / mu_h, lang=lg),
                      _caption(f"hodograph {k}", lg), size=SMALL_CAPTION["hodographs"]) for k in keys])

    def grid(mu_h: float, cols: int) -> Grid:
        sizes = [[_wh(r) for r in drawn(mu_h, lg)] for lg in LANGS]
        cells = [(max(s[i][0] for s in sizes), max(s[i][1] for s in sizes)) for i in range(len(keys))]
        return Grid([Leaf(k, w, h, r) for k, (w, h), r in zip(keys, cells, drawn(mu_h, lang))], cols, p.gap,
                    fitted=True)

    def flaws(mu_h: float) -> int:
        """The lettering touching a line or lettering in the hodographs drawn so (both languages,
        drawing.labels.collisions): a larger drawing may set a number on its own axis."""
        from graphplan.drawing.labels import collisions
        return dr._once(("fitted hodographs' flaws", round(mu_h, 12), tuple(keys)), lambda: sum(
            len(collisions(r)) for lg in LANGS for r in drawn(mu_h, lg)))

    W, H = room[2] - room[0], room[3] - room[1]
    best = None
    factors = sorted({1.0 / mu0} | {k for k in (*FACTORS, *SET_HODOGRAPHS_FACTORS)
                                    if 1.0 / mu0 < k <= SET_HODOGRAPHS_LARGEST + 1e-9})
    for k in factors:
        mu_h = 1.0 / k
        if _hodographs_share(dr, mu_h) != shared:        # the notes say "0–2" as planned
            continue
        if mu_h != mu0 and flaws(mu_h) > flaws(mu0):      # no lettering the planned size had not
            continue
        fitting = [g for g in (grid(mu_h, c) for c in range(1, len(keys) + 1)) if fits(g, W, H)]
        if not fitting:
            continue
        # the fewest rows that fit, then the rows evenly filled (``balanced``: LINK52's eight
        # hodographs as 4 + 4, not 7 + 1 over a 480 × 120 mm hole)
        best = min(fitting, key=lambda g: (g.rows, g.cols))
    if best is None:
        return items
    gw, gh = extent(best)
    cy = (inner[1] + inner[3]) / 2
    # the grid round the planned cells' centre, moved only as far as the room needs; its columns
    # spread over the room's width (``arrange`` shares a fitted grid's spare width evenly)
    by0 = min(max(cy - gh / 2, room[1]), room[3] - gh)
    new = {f"hodograph {leaf.name}": Placed(f"hodograph {leaf.name}", centred(leaf.record, b), b)
           for leaf, b in arrange(best, (room[0], by0, max(room[2], room[0] + gw), by0 + gh))}
    return [new.get(q.name, q) for q in items]       # each where it stood in the sheet's reading order


def _leaves(nat: Natural, mu: dict[str, float]) -> dict[str, list[Leaf]]:
    """The drawings' cells by their families' models at the scales ``mu``; the hodographs each in
    the largest one's cell, as the sheet sets them (``_drawn_leaves``: a PUMP45 A2 set planned its
    six hodographs, 41–97 mm tall, under the charts of sheet 2, drew them in 75 × 96 mm cells that
    did not fit there, and took a fourth sheet for them alone, 80 % blank)."""
    out = {fam: [f.leaf(mu[fam], f"{fam} {i}", i) for i in range(len(f.sizes))] for fam, f in nat.families.items()}
    if out.get("hodographs"):
        cw, ch = max(x.w for x in out["hodographs"]), max(x.h for x in out["hodographs"])
        out["hodographs"] = [Leaf(x.name, cw, ch) for x in out["hodographs"]]
    return out


# ``_one_sheet_at``'s arrangements by the cells' sizes (``plan`` asks the same sizes again in its next
# round and with the hodographs floored or not): the latest ``ARRANGED_KEPT`` kept
_ARRANGED: dict[tuple, tuple | None] = {}
ARRANGED_KEPT = 20000


CHARTS_WRAP = 2     # the charts two to a row where in one row no one-sheet composition fits (``_tree``)


def _one_sheet(nat: Natural, f: Form) -> tuple[tuple, Plan] | None:
    """The best one-sheet composition (``_one_sheet_at``): the charts in one row, else — where none
    fits so, or where a main drawing is left under its target so, and the sheet has more charts than
    ``CHARTS_WRAP`` — wrapped ``CHARTS_WRAP`` to a row where that scores better (A1 is one sheet:
    INCLINED_ROCKER53's three charts in a row beside its tables ran 6 mm over the field; LINK61's
    charts' row, three charts and six hodographs beside the tables' column, ran 10 mm over the field
    at 1:5 and left its scheme and groups at 1:10, a quarter of their target)."""
    best = _one_sheet_at(nat, f)
    if len(nat.families["charts"].sizes) > CHARTS_WRAP and (best is None or best[0][0] < 1.0 - 1e-9):
        wrapped = _one_sheet_at(nat, f, CHARTS_WRAP)
        if best is None or (wrapped is not None and wrapped[0] > best[0]):
            best = wrapped
    return best


def _one_sheet_at(nat: Natural, f: Form, wrap: int = 0) -> tuple[tuple, Plan] | None:
    """The best one-sheet composition (its score: the smallest of the main drawings' sizes against
    their targets first), or None where none fits; ``wrap``: the charts' row wrapped (``_tree``)."""
    x0, y0, x1, y1 = field_of(f)
    W, H = x1 - x0, y1 - y0
    nh = len(nat.families["hodographs"].sizes)
    best = None
    for factor in (TABLES, 1.0):
        tabs = [Leaf(name, w, h) for name, w, h in nat.tables[factor]]
        cols = [_column(f, tabs, parts, lambda w: notes_height(nat.notes, w))[0] for parts in (1, 2, 3)]

        tried: dict[tuple, tuple | None] = {}

        def arranged(mu, shape, first=False):
            """``_arranged``, remembered: the shapes' two orders of growth try the same sizes."""
            key = (shape, first, tuple(sorted(mu.items())))
            if key not in tried:
                tried[key] = _arranged(mu, shape, first)
            return tried[key]

        def _arranged(mu, shape, first=False):
            """(fill, hodographs' columns, the column's parts, the hodographs' row) of the best
            arrangement that fits; ``first``: the first that fits (whether any does)."""
            leaves = _leaves(nat, mu)
            # the same cells arranged again (``plan``'s next round, the hodographs' floor changed or
            # not: the same sizes): once per sizes, as extents add up nothing but the cells' sizes
            key = (W, H, wrap, shape, first, tuple((c.w, c.h) for c in cols),
                   tuple((fam, tuple((x.w, x.h) for x in xs)) for fam, xs in leaves.items()))
            if key not in _ARRANGED:
                if len(_ARRANGED) >= ARRANGED_KEPT:
                    _ARRANGED.pop(next(iter(_ARRANGED)))
                _ARRANGED[key] = _arranged_at(leaves, shape, first)
            return _ARRANGED[key]

        def _arranged_at(leaves, shape, first):
            groups = Leaf("groups", *extent(_groups_node(shape, leaves)))      # sizes only: one extent each
            grids = {hc: [Leaf("hodographs", *extent(Grid(leaves["hodographs"], hc, ROWS_GAP)))] if nh else []
                     for hc in range(1, max(nh, 1) + 1)}
            found = None
            # one tree a cut and a row of the hodographs, its hodographs' grid and tables' column
            # slots of each size in turn (``extent_with``: the sums of each tree, to the bit)
            slots = [Leaf("column", cols[0].w, cols[0].h)] + [Leaf("hodographs", grids[1][0].w, grids[1][0].h)] * bool(nh)
            tries = [(hc, parts) for hc in range(1, max(nh, 1) + 1) for parts in range(1, len(cols) + 1)]
            for cut in CUTS:
                for hrow in HROWS if nh else HROWS[:1]:
                    sized = extent_with(_tree(shape, leaves, 1, slots[0], hrow, groups, slots[1:], cut, wrap), slots)
                    for hc, parts in tries:
                        tw, th = sized([(cols[parts - 1].w, cols[parts - 1].h)] + [(g.w, g.h) for g in grids[hc]])
                        if tw <= W + 1e-9 and th <= H + 1e-9:
                            fill = min(W / tw, H / th)
                            if found is None or fill > found[0] + 1e-9:
                                found = (fill, hc, parts, hrow, cut)
                            if first:
                                return found
            return found

        for shape, order in [(sh, o) for sh in SHAPES for o in (*ORDERS, SCHEME_FIRST)]:
            fits = lambda m, s=shape: arranged(m, s, True) is not None       # noqa: E731
            if order is SCHEME_FIRST:
                # the scheme and the groups with it grown first, paid for by the drawings drawn larger
                # against their targets (LAYOUT.md: the scheme left, large): the families grown in
                # turn from a common start gave the beam pump's lever, lettered 80 mm out on its arms,
                # the top row's room, and its scheme and groups stayed at 1:10 beside ~180 × 85 mm
                # blank where its A2 set draws them at 1:2 (review 55 #1); the score below keeps
                # whichever composition leaves its smallest drawing the larger
                mu = _levels(nat.families, fits, ORDERS[1], ruled=True)
            else:
                mu = _levels(nat.families, fits, order, ruled=True)
            if mu is None:
                continue
            if mu["scheme"] < mu["groups"] * (1 - 1e-9):
                # the groups never at a smaller scale than the scheme on one sheet (review 4 #8: the
                # groups at 1:10 beside a 1:4 scheme; the press's II(2-3) at 1:5 beside its 1:4
                # scheme once its lever's couple took their row's room; the shaper's at 1:4 beside
                # 1:2.5): the scheme at the groups' scale, the room it leaves grown into by the rest
                mu = _levels(nat.families, fits, order, start={**mu, "scheme": mu["groups"]},
                             led={"scheme": "groups"}, ruled=True)
                if mu is None:
                    continue
            if order is SCHEME_FIRST:
                mu = _scheme_first(nat.families, fits, mu)
                if mu is None:
                    continue
            rel = [nat.families[fam].rel(mu[fam]) for fam in ("scheme", "groups", "forces", "acceleration", "lever")]
            # the smallest against its target, then those under their targets as large as may be
            # (a drawing beyond its target gains the sheet less than one under it loses: the
            # shaper's acceleration plan at 1.8 times its target scored its scheme and groups at
            # 1:5 above both at 1:4), then all
            score = (round(min(rel), 6), round(sum(math.log(min(r, 1.0)) for r in rel), 6),
                     round(sum(math.log(r) for r in rel), 6), factor == TABLES, -SHAPES.index(shape))
            _, hc, parts, hrow, cut = arranged(mu, shape)
            counts = tuple(len(g) for g in split(tabs, parts))
            cand = (score, Plan(mu, factor, shape, hc, parts, 1, counts, hrow, cut=cut, wrap=wrap))
            if best is None or cand[0] > best[0]:
                best = cand
    return best


SET_SMALLEST = 1.0     # below A1 the drawings are not drawn smaller than their targets to keep one sheet


# how much larger than its target a family of a set grows while the set needs no more sheets: the
# scheme and the groups, where the crowding is (the coulisse's crank end at 1:4 on an A2 sheet 70 %
# empty), as far as a sheet holds them; the others as before
SET_LARGEST = {"scheme": 4.0, "groups": 4.0, "charts": 2.0, "hodographs": 2.0}
FLOWED_LARGEST = {"scheme": 4.0, "groups": 4.0}      # … as the rows' flow grew them (``_set_flowed``)


def _set_largest(nat: Natural, name: str, largest: dict[str, float] = SET_LARGEST) -> float:
    """How large a family of a set grows (``SET_LARGEST``, else 1.25); flat hodographs to their
    cap, the area of a round one (the press's A3 set drew them 60 × 15 mm on a sheet half empty)."""
    fam = nat.families[name]
    if name == "hodographs" and math.isfinite(getattr(fam, "cap", math.inf)):
        return max(largest.get(name, 1.25), fam.rel(1.0 / fam.cap))
    return largest.get(name, 1.25)


def _set_rows(leaves: dict[str, list[Leaf]], tail: list[Leaf], width: float, packed: bool = False) -> list[list]:
    """A set's rows in reading order: the scheme; each group with its force plan; the acceleration
    plan and the lever; the charts, then the hodographs as one grid (kept together on one sheet —
    R34's stood alone on the coulisse's sheet 3, the other four on sheet 4); the tables and notes
    (``tail``). ``packed``: the drawings' rows side by side while they fit across (``_packed``)."""
    rows = [leaves["scheme"]] + [[g, q] for g, q in zip(leaves["groups"], leaves["forces"])]
    rows.append(leaves["acceleration"] + leaves["lever"])
    hods = leaves["hodographs"]
    if hods:
        cw = max(extent(h)[0] for h in hods)
        cols = max(1, min(len(hods), int((width + GAP) // (cw + GAP))))
        rows.append(leaves["charts"] + [Grid(hods, cols)])
    else:
        rows.append(leaves["charts"])
    if packed:       # a group with its force plan one unit (``_packed``)
        rows = _packed([rows[0]] + [[Row(r)] for r in rows[1:1 + len(leaves["groups"])]]
                       + rows[1 + len(leaves["groups"]):])
    rows.append(tail)
    return rows


def _packed(rows: list[list]) -> list[list]:
    """The drawings' rows run together into one, in order: the sheets' rows then take drawings side
    by side while they fit across, wrapping (``flow``). A tall, narrow mechanism (a press's vertical
    ram) draws its scheme and each group with its force plan about 100 mm wide: one to an A3 sheet's
    row of 390 mm left sheets 84–87 % empty."""
    return [[item for row in rows for item in row]]


def _set_pages(nat: Natural, f: Form, leaves: dict[str, list[Leaf]], factor: float, plan_first: bool = True,
               gap: float = SPACE):
    """The set's sheets at these drawings' sizes (``forceset.pack``, the drawings ``gap`` apart), or
    None where one is larger than a sheet."""
    from graphplan.sheets.compose import later_keep
    from graphplan.sheets.forceset import pack, units_of
    region = field_of(f)
    tables = [Leaf(n, w, h) for n, w, h in nat.tables[factor]]
    notes = Leaf("notes", TITLE, notes_height(nat.notes, TITLE))
    return pack(units_of(leaves, region[2] - region[0], plan_first, gap), tables, notes, region, keep_out(f),
                later_keep(f), gap)


def _lonely(pages, f: Form) -> int:
    """How many of a set's sheets hold one drawing alone (its tables and notes aside) on a field it
    leaves mostly empty (``forceset.FILL_SHARE``): review 12's six-bar drew its scheme alone on sheet
    1 of its A3 set, about half of it blank."""
    x0, y0, x1, y1 = field_of(f)
    out = 0
    for page in pages:
        drawn = [n for s in page for n in _names(s.node)
                 if n.partition(" ")[0] in FAMILIES and not n.endswith("table")]
        if len(drawn) == 1 and sum(s.w * s.h for s in page) < forceset.FILL_SHARE * (x1 - x0) * (y1 - y0):
            out += 1
    return out


def _least_share(pages, f: Form) -> float:
    """The least share of a sheet's field its drawings take (their boxes' areas), of a set's sheets."""
    x0, y0, x1, y1 = field_of(f)
    return min(sum(s.w * s.h for s in page) / ((x1 - x0) * (y1 - y0)) for page in pages)


def _where(pages) -> tuple | None:
    """Which drawings stand on which sheet of a set (``forceset.pack``'s sheets), None for none."""
    return None if pages is None else tuple(tuple(n for s in page for n in _names(s.node)) for page in pages)


def _planned_names(leaves: dict[str, list[Leaf]]) -> dict[str, str]:
    """The drawn leaves' names → the plan's names for them ("hodograph R24" → "hodographs 0")."""
    return {x.name: f"{fam} {i}" for fam, xs in leaves.items() for i, x in enumerate(xs)}


def _as_planned(packed, p: Plan, leaves: dict[str, list[Leaf]]) -> bool:
    """Whether a set's sheets as packed (``forceset.pack``) hold each drawing on the sheet the plan
    put it on (``Plan.where``; the tables and notes aside): True where the plan names none."""
    if not p.where:
        return True
    names = _planned_names(leaves)
    mine = [sorted(names[n] for n in page if n in names) for page in _where(packed)]
    planned = [sorted(n for n in page if n in names.values()) for page in p.where]
    return mine == planned


def _packed_as_planned(p: Plan, leaves: dict[str, list[Leaf]], tables: list[Leaf], notes: Leaf, f: Form):
    """A set's sheets with each drawing, table and the notes on the sheet the plan put it on
    (``Plan.where``), each sheet packed on its own (``forceset.pack``); None where a sheet does not
    hold its share."""
    from graphplan.sheets.compose import later_keep
    from graphplan.sheets.forceset import pack, units_of
    region = field_of(f)
    pages = []
    for k, page in enumerate(p.where or ()):
        mine = {fam: [x for i, x in enumerate(xs) if f"{fam} {i}" in page] for fam, xs in leaves.items()}
        keep = keep_out(f) if k == 0 else later_keep(f)
        out = pack(units_of(mine, region[2] - region[0], p.plan_first, p.gap), [t for t in tables if t.name in page],
                   notes if "notes" in page else None, region, keep, later_keep(f), p.gap)
        if out is None or len(out) != 1:
            return None
        pages.append(out[0])
    return pages or None


def _names(node) -> tuple[str, ...]:
    """The drawings' names in a node of the set's composition."""
    if isinstance(node, Leaf):
        return (node.name,)
    return tuple(n for c in node.children for n in _names(c))


def _set_flowed(nat: Natural, f: Form) -> Plan:
    """The scales a set's drawings took flowing in rows over the sheets (reading order, a row a
    drawing or a group with its plan): every family at least at its target size, then grown
    while the set needed no more sheets — the floor of ``_set``'s scales (a set packed onto fewer
    sheets draws nothing smaller than this did)."""
    region = field_of(f)
    keep = keep_out(f)
    best = None
    for factor, packed in ((TABLES, False), (1.0, False), (TABLES, True), (1.0, True)):
        def pages(mu):
            leaves = _leaves(nat, mu)
            rows = _set_rows(leaves, [Leaf(n, w, h) for n, w, h in nat.tables[factor]]
                             + [Leaf("notes", TITLE, notes_height(nat.notes, TITLE))], region[2] - region[0], packed)
            out = flow(rows, region, keep)
            return None if out is None else len(out)
        mu = None
        for k in (1.0, 0.8, 0.64, 0.5, 0.4, 0.32):
            trial = {name: fam.start(k) for name, fam in nat.families.items()}
            if pages(trial) is not None:
                mu = trial
                break
        if mu is None:
            continue
        count = pages(mu)
        grown = _levels(nat.families, lambda m: pages(m) == count, FAMILIES,
                        lambda name, m: nat.families[name].rel(m) <= _set_largest(nat, name, FLOWED_LARGEST) + 1e-9)
        mu = grown if grown is not None and pages(grown) == count else mu
        if best is None or count < best[0] and (not packed or _no_smaller(nat, mu, best[1].mu)):
            best = (count, Plan(mu, factor, "set", 1, 1, count, packed=packed))
    if best is None:
        raise said_error(GraphplanError, "sh forces fit", None, None, form=f.name, option="--format")
    return best[1]


def _set(nat: Natural, f: Form) -> Plan:
    """A set: the drawings set down over the fewest sheets in reading order (``forceset``), at the
    scales the rows' flow drew them (``_set_flowed``) — the acceleration plan, the lever, the charts
    and the hodographs at their targets where that saves a sheet — then grown while each stays on
    its sheet; of the tables' two letterings and the acceleration plan before or after the groups,
    the fewest sheets, then the tables whole on one, then the emptiest sheet fullest."""
    flowed = _set_flowed(nat, f).mu
    # the scheme no larger than the groups cut from it (review 6 #4: an A2 set's scheme at 1:1 over
    # two-thirds of its sheet, the groups and the kinematic plan at 1:2) — unless that leaves its
    # sheet emptier (a scheme alone on its sheet either way)
    capped = {**flowed, "scheme": max(flowed["scheme"], flowed["groups"])}
    # the drawings after the groups (the acceleration plan, the lever, the charts, the hodographs)
    # may start at their targets where that saves a sheet: the flow grew them on its spare sheets
    # (the six-bar's lever and plan twice their targets, each on a sheet of its own)
    later = ("acceleration", "lever", "charts", "hodographs")
    floors: list[tuple[dict, bool]] = []
    for cap in (True, False):
        for t in (False, True):
            fl = {n: (nat.families[n].start(1.0) if t and n in later else m) for n, m in (capped if cap else flowed).items()}
            if all(fl != f0 for f0, _ in floors):
                floors.append((fl, cap or fl["scheme"] >= fl["groups"] * (1 - 1e-9)))

    def tried(floor: dict, cap: bool, factor: float, plan_first: bool, gap: float):
        """The set from this floor grown while each drawing stays on its sheet: (its key, its
        plan), None where a drawing is larger than a sheet."""
        smallest = floor["groups"] if cap else 0.0
        def sheets_of(mu):
            """Which drawings stand on which sheet: the growth keeps it (a drawing grown until
            the next one moved on to another sheet left the scheme alone on a sheet 77 % empty)."""
            return _where(_set_pages(nat, f, _leaves(nat, mu), factor, plan_first, gap))
        mu = dict(floor)
        where = sheets_of(mu)
        if where is None:
            return None
        tables = {n for n, _, _ in nat.tables[factor]}
        grown = _levels(nat.families, lambda m: sheets_of(m) == where, FAMILIES,
                        lambda name, m: nat.families[name].rel(m) <= _set_largest(nat, name) + 1e-9
                        and (name != "scheme" or m >= smallest * (1 - 1e-9) or _scheme_aside(nat, f, m)),
                        start=mu)
        mu = grown if grown is not None and sheets_of(grown) == where else mu
        # the fewest sheets, then the tables whole on one of them, then the fewest sheets with one
        # drawing alone on them, then the fewest of tables alone (review 61 #5; a sheet's drawings
        # brought forward by ``forceset.pack`` had left the gate's A3 tables alone on sheet 4), then
        # the emptiest sheet fullest
        pages = _set_pages(nat, f, _leaves(nat, mu), factor, plan_first, gap)
        alone = sum(all(n in tables or n == "notes" for n in page) for page in where)
        key = (len(where), len({k for k, page in enumerate(where) if any(n in tables for n in page)}), not cap,
               -gap, _lonely(pages, f), alone, -round(_least_share(pages, f), 3))
        return key, Plan(mu, factor, "set", 1, 1, len(where), packed=True, where=where,
                         plan_first=plan_first, gap=gap)

    best = None
    # the drawings ``SPACE`` apart (review 7 #18), else ``GAP`` where that takes fewer sheets
    for (floor, cap), factor, plan_first, gap in [(fl, fa, pf, g) for g in (SPACE, GAP) for fl in floors
                                                  for pf in (True, False) for fa in (TABLES, 1.0)]:
        got = tried(floor, cap, factor, plan_first, gap)
        if got is not None and (best is None or got[0] < best[0]):
            best = (*got, floor, cap)
    if best is None:
        return _set_flowed(nat, f)
    if best[0][4]:
        # a drawing alone on a mostly empty sheet (the six-bar's scheme, grown to the groups' 1:2 on
        # sheet 1 of its A3 set, 105 mm of acceleration plan wanting room under it where 92 was
        # left): the scheme a step smaller than the groups, so that a drawing that reads on its own
        # joins it (``forceset.pack``), where that takes no more sheets
        key, p = best[:2]
        floor = {**best[2], "scheme": coarser(max(best[2]["scheme"], best[2]["groups"]))}
        for pf in (True, False):
            got = tried(floor, True, p.tables, pf, p.gap)
            if got is not None and got[0][:2] <= key[:2] and got[0][4] < best[0][4]:
                best = (*got, floor, True)
    return _plan_grown(nat, best, tried)


def _plan_grown(nat: Natural, best: tuple, tried) -> Plan:
    """The set's acceleration plan, below its target, started a series step larger in turn (either
    before the groups or after them) while the set keeps its count of sheets, its tables' sheets,
    its scheme's cap and its gap, up to the size a set grows it to (``_set_largest``): growth keeps
    each drawing on its sheet, so a plan the flow's common factor drew at half its target stayed so
    where one step larger went onto the next sheet, the same sheets in all (review 12 #13: the
    six-bar's A3 set drew it at 0.1 (m/s²)/mm, πa 62 mm in a band under its scheme, Table 1 reading
    a^n_BA off a 1 mm vector, +25 %; A1 draws it at 0.05). The larger plan of the two is kept."""
    key, p, floor, cap = best
    fam = nat.families["acceleration"]
    m = floor["acceleration"]
    while fam.rel(m) < 1.0 - 1e-9:
        m = next_series(m)         # the series' next step (review 58 #2: not GOST's 1.5, 7.5 between)
        if m is None or fam.rel(m) > _set_largest(nat, "acceleration") + 1e-9:
            break                  # (no larger than a set grows it: the shaper's 0.75 → 0.5 drew it 1.45 times)
        trials = [tried({**floor, "acceleration": m}, cap, p.tables, pf, p.gap) for pf in (True, False)]
        ok = [t for t in trials if t is not None and t[0][:5] == key[:5]]
        if ok:
            got = min(ok, key=lambda t: t[0])
            if fam.rel(got[1].mu["acceleration"]) > fam.rel(p.mu["acceleration"]) + 1e-9:
                key, p = got
    return p


SCHEME_ROOM = 0.25    # a set's scheme drawn larger than its groups while its cell takes at most this share of a sheet


def _scheme_aside(nat: Natural, f: Form, mu: float, size: tuple[float, float] | None = None) -> bool:
    """Whether a set's scheme at μl ``mu`` (its cell ``size``, else the family's model) takes at most
    ``SCHEME_ROOM`` of a sheet's field, so that it may be drawn larger than the groups cut from it:
    review 6 #4 sent back a scheme at 1:1 over two-thirds of an A2 sheet beside groups at 1:2;
    review 11 #13 one at 1:2 on an A3 sheet (its crank 22 mm, the support's hatching over S1) where
    1:1, the A1 sheet's scale, takes 16 % of the sheet beside the acceleration plan."""
    x0, y0, x1, y1 = field_of(f)
    w, h = size if size is not None else nat.families["scheme"].size(mu)
    return w * h <= SCHEME_ROOM * (x1 - x0) * (y1 - y0) + 1e-9


def _no_smaller(nat: Natural, mu: dict[str, float], than: dict[str, float]) -> bool:
    """Whether the scheme and the groups at ``mu`` are drawn no smaller than at ``than``: a packed
    set takes fewer sheets only so (the coulisse's A2 set packed onto 3 sheets drew its scheme at
    1:4 again, its crank end crowded, where 4 sheets hold it at 1:2)."""
    return all(nat.families[n].rel(mu[n]) >= nat.families[n].rel(than[n]) * (1 - 1e-9) for n in ("scheme", "groups"))


def _checked(dr: ForceDrafter, nat: Natural, p: Plan) -> bool:
    """Whether the drawings and tables at the plan's scales are no larger than measured; where one
    is, its size is taken into ``nat`` for the next trial."""
    from graphplan.util.words import LANGS
    ok = not grown(nat.tables[p.tables], [[(n, *_wh(r)) for n, r in _tables(dr, p.mu, lang, p.tables)]
                                          for lang in LANGS])
    drawn = [_notes_lines(dr, p.mu, lang) for lang in LANGS]
    if notes_height(drawn, TITLE) > notes_height(nat.notes, TITLE) + 1e-6:
        nat.notes += drawn
        ok = False
    for fam, recs in dr.drawings(p.mu).items():
        family = nat.families[fam]
        for i, r in enumerate(recs):
            ok &= family.allow(p.mu[fam], *_wh(r), i)
    return ok


# compositions tried at most, each with the sizes the one before came out drawn at: review 12's six-bar
# took 7 (its lever's arms lettered 40–70 mm out at some μv, not at others); after 4 it kept the 4th,
# drawn 852 × 581 mm on a field of 806 × 574 (Table 3, the notes and a hodograph's caption off the frame)
ROUNDS = 8


def _holds(dr: ForceDrafter, nat: Natural, f: Form, p: Plan) -> bool:
    """Whether the plan's composition holds its drawings at the sizes they came out drawn at
    (``_checked`` took them into ``nat``)."""
    return _fits(nat, f, p, _placed_leaves(dr, nat, p.mu))


def _drawn_leaves(dr: ForceDrafter, mu: dict[str, float], lang: str) -> dict[str, list[Leaf]]:
    """The drawings at the scales ``mu`` as the sheet places them: each captioned, the hodographs in
    equal cells."""
    recs, caps, names = dr.drawings(mu, lang), _captions(dr, mu, lang), dr.names()
    leaves = {fam: [Leaf(names[fam][i], record=captioned(r, *caps[fam][i], size=SMALL_CAPTION.get(fam, 5.0)))
                    for i, r in enumerate(rs)] for fam, rs in recs.items()}
    if leaves.get("hodographs"):
        cw, ch = max(x.w for x in leaves["hodographs"]), max(x.h for x in leaves["hodographs"])
        leaves["hodographs"] = [Leaf(x.name, cw, ch, x.record) for x in leaves["hodographs"]]
    return leaves


def _within(dr: ForceDrafter, f: Form, p: Plan) -> bool:
    """Whether the one-sheet composition holds its drawings, tables and notes as they come out drawn
    at the plan's scales, as ``build_forces_sheet`` sets them: the field's bounds checked, not assumed
    from the families' models. In the plan's language (its drawings are the sheet's, drawn once);
    the tables and notes in both (``measure`` took the larger)."""
    from graphplan.util.words import LANGS
    x0, y0, x1, y1 = field_of(f)
    leaves = _drawn_leaves(dr, p.mu, dr.opts.lang)
    for lang in LANGS:
        tables = [Leaf(name, record=rec) for name, rec in _tables(dr, p.mu, lang, p.tables)]
        lines = _notes_lines(dr, p.mu, lang)
        C = _column(f, tables, p.parts, lambda wd: _wh(note_block(lines, wd))[1], p.counts)[0]
        tw, th = extent(_tree(p.shape, leaves, p.hcols, C, p.hrow, cut=p.cut, wrap=p.wrap))
        if tw > x1 - x0 + 1e-6 or th > y1 - y0 + 1e-6:
            return False
    return True


_ROUNDS: dict[tuple, tuple] = {}


def _rounds_key(st: Study, f: Form, opts: SheetOptions) -> tuple:
    return (repr(st.mech), f.name, repr(opts))


def _rounds_kept(st: Study, f: Form, opts: SheetOptions) -> tuple:
    """``_rounds`` for ``plan``'s arguments, kept for ``plan`` to go on from (``planned_sheets``
    asked first): taken, not copied — ``plan`` grows the drawings in ``nat`` — so it is kept for one
    ``plan`` only, and a plan composed again starts again."""
    key = _rounds_key(st, f, opts)
    if key not in _ROUNDS:
        if len(_ROUNDS) >= 8:
            _ROUNDS.pop(next(iter(_ROUNDS)))
        _ROUNDS[key] = _rounds(st, f, opts)
    return _ROUNDS[key]


_PLANNED: dict[tuple, int] = {}


def planned_sheets(st: Study, f: Form, opts: SheetOptions) -> int | None:
    """``plan(st, f, opts)[0].sheets`` where the composition's rounds end on one sheet (not a set):
    the drawings grown after them (``_grown_groups``, ``_filled_sheets``, ``_grown_lever``,
    ``_grown_hodographs``) change the plan's scales, never its shape nor its sheets, and ``plan``
    then returns one of them — so 1 without growing them (a third of the forces plan: what the
    kinematics sheet's number waited for). None where the rounds end on a set (``plan`` decides)."""
    key = _rounds_key(st, f, opts)
    if key not in _PLANNED:
        p = _rounds_kept(st, f, opts)[2]
        if p.shape == "set":
            return None
        if len(_PLANNED) >= 64:
            _PLANNED.pop(next(iter(_PLANNED)))
        _PLANNED[key] = p.sheets
    return _PLANNED[key]


def _rounds(st: Study, f: Form, opts: SheetOptions) -> tuple[ForceDrafter, Natural, Plan, Plan]:
    """``plan``'s rounds: the composition tried at the sizes the drawings came out drawn at, until
    one comes out as measured: (the drafter, the measures, the plan, the plan before growth)."""
    if not has_loads(st):
        raise GraphplanError(NO_LOADS.format(src=st.mech.source))
    dr = ForceDrafter(st, SheetOptions(opts.positions, opts.accel, opts.precision, "uk", "forces"))
    nat = measure(dr)
    hod = nat.families["hodographs"]
    legible = _legible_factor(dr, hod)
    tried: list[Plan] = []
    for _ in range(ROUNDS):
        hod.floor = 0.0
        free = _one_sheet(nat, f)
        floored = None
        if free is None or hod.rel(free[1].mu["hodographs"]) < legible - 1e-9:
            hod.floor = legible
            floored = _one_sheet(nat, f)
            if floored is None and legible > HODOGRAPHS_FLOOR:
                hod.floor = HODOGRAPHS_FLOOR
                floored = _one_sheet(nat, f)
        # the hodographs at their legible size where that costs no main drawing a step it needs
        one = floored if floored is not None and (free is None or _costs_nothing(nat, floored[1], free[1])) else free
        hod.floor = hod.floor if one is floored and one is not None else 0.0
        one = one[1] if one is not None else None
        fine = one is not None and all(nat.families[n].rel(one.mu[n]) >= SET_SMALLEST - 1e-9
                                       for n in ("scheme", "groups", "forces"))
        if one is None and f.name in ONE_SHEET:
            # A1 is one sheet: a round's drawings that came out larger than measured (a crowded lever
            # lettered on long leaders at a coarse μv) can leave no one-sheet composition at all at
            # the sizes measured since, where an earlier round's holds its drawings as they came out
            # (LINK52: its second round, μF 50 N/mm and μv 0.00942, holds; its fifth found none and
            # the sheet became a set of two A1 sheets) — the latest that holds, as after the last round
            held = next((q for q in reversed(tried) if q.shape != "set" and _holds(dr, nat, f, q)), None)
            if held is not None:
                p = held
                break
        if one is None or not (f.name in ONE_SHEET or fine):
            hod.floor = HODOGRAPHS_FLOOR                 # a set: every drawing at least at its size
            one = _set(nat, f)
        p = one
        if _checked(dr, nat, p):
            break
        tried.append(p)
    else:
        # no composition came out drawn as measured: the latest that holds its drawings as they
        # came out (each measured at its scales by ``_checked``), never one that runs off the field
        p = next((q for q in reversed(tried) if _holds(dr, nat, f, q)), p)
    return dr, nat, p, p


@remembered
def plan(st: Study, f: Form, opts: SheetOptions) -> tuple[Plan, Natural, ForceDrafter]:
    """The force sheet's composition, once per scene, format and options (not the language): one
    sheet where one holds every drawing at least at its target size (on A1 always), else a set."""
    dr, nat, p, base = _rounds_kept(st, f, opts)
    _ROUNDS.pop(_rounds_key(st, f, opts), None)     # grown below: a plan composed again starts again
    p = _grown_groups(dr, nat, f, p)
    room = _filled_sheets(dr, nat, f, p)
    filled = _grown_hodographs(dr, nat, f, _grown_lever(dr, nat, f, room))
    if filled.shape != "set":
        # grown drawings sized by their families' models: the sheet as they come out drawn, else
        # without the lever's growth (its arms' lettering at a new μv is the least foreseeable: the
        # shaper's lever grown into 200 mm of room came out over the field, and the sheet fell back
        # to its plans at the family's μF), else the composition before them (the field's bounds
        # are a hard rule, the growth a nicety)
        tries = (q() for q in (lambda: filled, lambda: _grown_hodographs(dr, nat, f, room), lambda: p))
        return _loaded(next((q for q in tries if _within(dr, f, q)), base), dr), nat, dr
    if filled.mu == p.mu:
        return _loaded(filled, dr), nat, dr
    # the set's sheets as its drawings come out drawn: the fill kept where it takes no more sheets
    # than without it (a six-bar's A2 set grew its plans to 7.5 N/mm and took a third sheet)
    # — and the lever's growth kept where it takes no more sheets than without it, the first of the
    # fewest (SIXBAR12's A2 set grew its lever to 153 × 212 mm where 129 × 189 was planned: the resistance chart went on
    # to sheet 3 with the hodographs, the tables to a fourth sheet)
    plain = _grown_hodographs(dr, nat, f, _grown_lever(dr, nat, f, p))
    tries = [filled, plain, _grown_hodographs(dr, nat, f, room), p]
    counts = [_drawn_sheets(dr, nat, f, q) for q in tries]
    return _loaded(tries[counts.index(min(counts))], dr), nat, dr


def _loaded(p: Plan, dr: ForceDrafter) -> Plan:
    """The composed sheet's force plans, lever and Table 2 loaded with the inertia loads of the
    acceleration plan it draws (at its μa, Table 1); composed with the plan at its own μa, whose
    readings differ from these by the ruler's rounding only (review 10 #14)."""
    dr.accel_mu = p.mu["acceleration"]
    return p


def _legible_factor(dr: ForceDrafter, hod: Family) -> float:
    """The hodographs' least size factor on one sheet: ``HODOGRAPHS_FLOOR``, or the first larger
    one (within their growth's reach) at which no two of a hodograph's points share a number — the
    compressor's at factor 1 merged "0–2" and "10–11" (75 N/mm) once its groups took the room,
    where 1.4 numbers each point by its dot."""
    from graphplan.sheets.compose import FACTORS
    reach = getattr(hod, "cap", math.inf) * HODOGRAPHS_ROOM
    for k in sorted(x for x in FACTORS if HODOGRAPHS_FLOOR - 1e-9 <= x <= reach + 1e-9):
        if not _hodographs_share(dr, 1.0 / k):
            return k
    return HODOGRAPHS_FLOOR


def _drawn_sheets(dr: ForceDrafter, nat: Natural, f: Form, p: Plan) -> int:
    """How many sheets a set takes with its drawings as drawn at the plan's scales (both languages,
    captioned) — as ``build_forces_sheet`` packs them — or a large number where they do not fit."""
    from graphplan.util.words import LANGS
    names = dr.names()
    sizes: dict[str, list[tuple[float, float]]] = {}
    for lang in LANGS:
        recs, caps = dr.drawings(p.mu, lang), _captions(dr, p.mu, lang)
        for fam, rs in recs.items():
            got = [_wh(captioned(r, *caps[fam][i], size=SMALL_CAPTION.get(fam, 5.0))) for i, r in enumerate(rs)]
            sizes[fam] = [(max(a[0], b[0]), max(a[1], b[1])) for a, b in zip(sizes.get(fam, got), got)]
    leaves = {fam: [Leaf(names[fam][i], w, h) for i, (w, h) in enumerate(ws)] for fam, ws in sizes.items()}
    out = _set_pages(nat, f, leaves, p.tables, p.plan_first, p.gap)
    return len(out) if out is not None else 10 ** 6


# a set's sheet whose drawings' cells cover less of its field than this has them grown: cells 60 % of
# the field left a six-bar's group sheet 74 % empty by the reviews' 20 mm cells (thin lines, blank corners)
FILL_SHARE = 0.75
# … its drawings grown at most so (against their targets)
FILL_LARGEST = {"scheme": 4.0, "groups": 4.0, "forces": FORCES_MOST, "acceleration": 2.0, "charts": 2.0, "hodographs": 2.0}


def _sheet_share(leaves: dict[str, list[Leaf]], names: tuple[str, ...], f: Form) -> float:
    """The share of a sheet's field the cells of its drawings ``names`` ("groups 1") cover."""
    x0, y0, x1, y1 = field_of(f)
    cells = {f"{fam} {i}": leaf for fam, ls in leaves.items() for i, leaf in enumerate(ls)}
    return sum(cells[n].w * cells[n].h for n in names if n in cells) / ((x1 - x0) * (y1 - y0))


def next_round(mu: float) -> float | None:
    """The next round coefficient drawing larger than μ: the series' 1, 2, 2.5, 4, 5 or GOST 2.302's
    1.5, 7.5 × 10^k (graphic.scales.on_round) — 10 N/mm → 7.5, not 5 (a plan half again as large)."""
    from graphplan.graphic.scales import larger_choices
    nxt = [m for m, rnd in larger_choices(1.0, mu, 2.01 / mu) if rnd]
    return nxt[0] if nxt else None


def next_series(mu: float) -> float | None:
    """The next coefficient of the standard series 1, 2, 2.5, 4, 5 × 10^k drawing larger than μ
    (2 N/mm → 1, not GOST's 1.5): a set's force plans and acceleration plan grown into their
    sheets' room print a μ of the series, as its A1 sheet's and docs require (review 58 #2: the
    crank-rocker's A2 set drew group II(2-3)'s plan at 1.5 N/mm, its A1 and A3 at 2)."""
    from graphplan.sheets.compose import finer
    return finer(mu) if mu > 0 and math.isfinite(mu) else None


def next_length(mu_l: float) -> float | None:
    """``next_round`` for a length scale (the scheme, a group): the next that is a GOST 2.302
    drawing scale (graphic.scales.gost_length) — 0.001 → 0.0005 (2:1), not 0.00075 (the title
    block's "1.333:1", review 11 #3); 0.02 → 0.015 (1:15)."""
    from graphplan.graphic.scales import gost_length
    nxt = next_round(mu_l)
    while nxt is not None and not gost_length(nxt):
        nxt = next_round(nxt)
    return nxt


def _filled_sheets(dr: ForceDrafter, nat: Natural, f: Form, p: Plan) -> Plan:
    """A set's sheet its drawings leave mostly empty (their cells under ``FILL_SHARE`` of the field:
    the slotter's and the sieve's scheme alone on sheet 1 of an A3 set, 80 % of its cells blank; a
    six-bar's group with its force plan alone, 73–78 %) gets them drawn larger — the scheme, a
    group at its own μl, its force plan at its own μF, each by the standard series' next step in
    turn — while every drawing stays on its sheet, the tables and notes keep their size, and each
    stays within ``FILL_LARGEST`` of its target; the scheme no larger than the groups (review 6 #4).
    One sheet (A1): its scheme, groups, force plans, acceleration plan and charts so grown into the
    room the composition leaves (kinlayout.into_room), the smallest against its target first, before
    the lever and the hodographs take theirs (review 7: A1 force sheets 46–53 % empty; the six-bar's
    II(4-5) plan at 7.5 N/mm, not 10). Each size as drawn, not scaled from the family's model (a
    force plan's lettering and short forces do not scale: 188 mm drawn where the model said 149)."""
    mu = dict(p.mu)
    fp = dr.fp(mu["groups"], mu["forces"], mu["lever"])
    labels = [gp.label for gp in fp.groups]
    fams = nat.families
    one = p.shape != "set" or not p.where
    sheets = [tuple(f"{fam} {i}" for fam, ls in _leaves(nat, mu).items() for i in range(len(ls)))] if one else p.where
    for names in sheets:
        leaves = _placed_leaves(dr, nat, mu)
        if not one and _sheet_share(leaves, names, f) >= FILL_SHARE:
            continue
        steps = [("scheme", 0)] if "scheme 0" in names else []
        for n in names:
            fam, _, i = n.partition(" ")
            if fam in ("groups", "forces"):
                steps.append((fam, int(i)))
            elif fam in ("acceleration", "charts", "hodographs") and (fam, 0) not in steps \
                    and not (one and fam == "hodographs"):       # (one sheet: ``_grown_hodographs``)
                steps.append((fam, 0))          # a family at one scale: grown while all its sheets hold it

        def key_of(fam: str, i: int) -> str:
            return {"groups": GROUP + labels[i], "forces": PLAN + labels[i]}.get(fam, fam)

        growing, changed = list(steps), True
        while growing and changed:
            changed = False
            # the smallest against its target first (kinlayout.into_room)
            for fam, i in sorted(growing, key=lambda s: fams[s[0]].rel(mu.get(key_of(*s), mu[s[0]]))):
                key = key_of(fam, i)
                base = mu.get(key, mu[fam])
                # a force plan's μF and the acceleration plan's μa by the standard series on one
                # sheet too (review 59 #2: the A1 sheet's II(2-3) plan at 1.5 N/mm, μa 0.075)
                nxt = fams[fam].finer(base) if fams[fam].factors else (
                    next_length(base) if fam in ("scheme", "groups") else next_series(base))
                # the scheme never larger than the groups cut from it where it would take much
                # of its sheet (review 6 #4, ``_scheme_aside``)
                if nxt is None or fams[fam].rel(nxt) > FILL_LARGEST[fam] + 1e-9 \
                        or (one and fam == "groups" and not _group_allowed(dr, mu, labels[i], nxt)) \
                        or (fam == "scheme" and nxt < mu["groups"] * (1 - 1e-9)
                            and (one or not _scheme_aside(nat, f, nxt, dr.scheme_size(mu, nxt, fams["scheme"].caption)))):
                    growing.remove((fam, i))
                    continue
                if one and not aux_allowed(fams, mu, fam, nxt):
                    continue        # held while the main drawings grow (``aux_allowed``)
                trial_mu = {**mu, key: nxt}
                trial = {k: list(v) for k, v in leaves.items()}
                if fam == "hodographs":            # as drawn, each in the largest one's cell
                    trial[fam] = [Leaf(x.name, *cell) for x, cell in zip(trial[fam], dr.hodograph_cells(nxt))]
                elif fam in ("acceleration", "charts"):       # one scale: its model's cells
                    trial[fam] = [Leaf(x.name, *(v + GROW_MARGIN * (fam == "acceleration")
                                                 for v in fams[fam].size(nxt, j)))
                                  for j, x in enumerate(trial[fam])]
                else:
                    if fam == "scheme":
                        w, h = dr.scheme_size(trial_mu, nxt, fams["scheme"].caption)
                    elif fam == "groups":
                        w, h = dr.group_size(mu, i, nxt, fams["groups"].caption)
                    else:
                        w, h = dr.plan_size(mu, i, nxt, fams["forces"].caption)
                    trial[fam][i] = Leaf(trial[fam][i].name, *(margined(w, h, trial[fam][i]) if fam == "forces"
                                                               else (w + GROW_MARGIN, h + GROW_MARGIN)))
                # the notes may take a line (the groups' μl apart from the scheme's): then fitted again
                if _fits(nat, f, p, trial) and (_lettering_kept(dr, nat, trial_mu, p) or _fits(nat, f, p, trial)):
                    mu, leaves, changed = trial_mu, trial, True
                else:
                    growing.remove((fam, i))
    return replace(p, mu=mu) if mu != p.mu else p


# a set's sheet the hodographs leave mostly empty draws them past the one-sheet series' largest
# factor (compose.FACTORS' 2.0), by R10's next steps: LINK47's A1 sheet 2 held its six hodographs
# at 127 × 126 mm cells (R12, R23, R01 110 × 25 mm slivers) over 650 × 170 mm left empty beneath them
SET_HODOGRAPHS_FACTORS = (2.5, 3.2, 4.0)
SET_HODOGRAPHS_LARGEST = SET_HODOGRAPHS_FACTORS[-1]


def set_finer(mu: float) -> float | None:
    """The next larger size factor's μ (1/k) of a set's hodographs beyond compose.FACTORS
    (``SET_HODOGRAPHS_FACTORS``), None past the last."""
    bigger = [k for k in SET_HODOGRAPHS_FACTORS if k > 1.0 / mu * (1 + 1e-9)]
    return 1.0 / min(bigger) if bigger else None


HODOGRAPHS_ROOM = 1.6     # a one-sheet composition's hodographs grown into the room left, up to this over their cap


def _grown_hodographs(dr: ForceDrafter, nat: Natural, f: Form, p: Plan) -> Plan:
    """A one-sheet composition's hodographs (or a set's, on a sheet they leave mostly empty) grown,
    every other drawing as planned, while the sheet still holds them (a set: each drawing on its sheet) — at most ``HODOGRAPHS_ROOM`` times their cap (review 7 #9: 16 × 48 mm slivers
    whose numbers merge, in a column of a sheet left with a 600 × 60 mm empty band, review 6 #12)."""
    fam = nat.families["hodographs"]
    if not fam.sizes:
        return p
    leaves = _placed_leaves(dr, nat, p.mu)
    mu = p.mu["hodographs"]
    limit = fam.rel(mu) * HODOGRAPHS_ROOM if not math.isfinite(getattr(fam, "cap", math.inf)) \
        else fam.cap * HODOGRAPHS_ROOM
    if p.shape == "set":
        # a set's sheet the hodographs leave mostly empty (``FILL_SHARE``) draws them larger, every
        # drawing kept on its sheet, the last to take the room (PUMP45's A2 set drew six 40 mm
        # hodographs in a row across an otherwise empty sheet)
        page = next((names for names in p.where if "hodographs 0" in names), ()) if p.where else ()
        if not page or _sheet_share(_placed_leaves(dr, nat, p.mu), page, f) >= FILL_SHARE:
            return p
        limit = SET_HODOGRAPHS_LARGEST
    while True:
        nxt = Family.finer(fam, mu) or (set_finer(mu) if p.shape == "set" else None)
        if nxt is None or fam.rel(nxt) > limit + 1e-9:
            break
        trial = {**leaves, "hodographs": [Leaf(x.name, *cell) for x, cell in
                                          zip(leaves["hodographs"], dr.hodograph_cells(nxt))]}
        if not (_drawings_kept(nat, f, p, trial) if p.shape == "set" else _fits(nat, f, p, trial)):
            break
        mu = nxt
    return replace(p, mu={**p.mu, "hodographs": mu}) if mu != p.mu["hodographs"] else p


def _drawings_kept(nat: Natural, f: Form, p: Plan, leaves: dict[str, list[Leaf]]) -> bool:
    """Whether a set with these drawings' sizes takes no more sheets and keeps every drawing on its
    sheet (the tables and notes may move on: PUMP45's A3 set planned Table 1 beside the hodographs
    and drew it with the other tables on the last sheet, the hodographs alone)."""
    out = _where(_set_pages(nat, f, leaves, p.tables, p.plan_first, p.gap))
    if out is None or len(out) > len(p.where):
        return False
    drawn = lambda where: [tuple(n for n in page if n.partition(" ")[0] in FAMILIES and not n.endswith("table"))
                             for page in where]  # noqa: E731
    return drawn(out) == drawn(p.where)[:len(out)] and all(not page for page in drawn(p.where)[len(out):])


MAIN = ("scheme", "groups", "forces", "acceleration", "lever")


def _costs_nothing(nat: Natural, floored: Plan, free: Plan) -> bool:
    """Whether the hodographs drawn at their legible size (``floored``) leave every main drawing as
    large as without (``free``), or at least at its target size."""
    return all(nat.families[n].rel(floored.mu[n]) >= min(nat.families[n].rel(free.mu[n]), 1.0) * (1 - 1e-9)
               for n in MAIN)


GROW_MARGIN = 3.0     # mm a grown group's cell keeps over its measured size (labels settle differently)


def margined(w: float, h: float, cell: Leaf) -> tuple[float, float]:
    """A grown force plan's cell over its measured size ``w`` × ``h`` (``GROW_MARGIN``) where that is
    larger than its ``cell`` so far; a side the drawing, as measured, does not outgrow keeps the
    cell's (the composition held it already): the toggle press's crank plan, as wide as its 91 mm
    cell at every μF, was barred from 25 N/mm by the margin alone and stayed at 200 N/mm — R21
    8.5 mm long in an empty 100 × 80 mm zone (review56 #1)."""
    return (cell.w if w <= cell.w + 1e-9 else w + GROW_MARGIN), (cell.h if h <= cell.h + 1e-9 else h + GROW_MARGIN)


def _fits(nat: Natural, f: Form, p: Plan, leaves: dict[str, list[Leaf]]) -> bool:
    """Whether the plan's composition, with these drawings' sizes, still fits the sheet (one sheet)
    or needs no more sheets (a set)."""
    if p.shape == "set":
        out = _where(_set_pages(nat, f, leaves, p.tables, p.plan_first, p.gap))
        return out is not None and (out == p.where if p.where else len(out) <= p.sheets)
    x0, y0, x1, y1 = field_of(f)
    tabs = [Leaf(name, w, h) for name, w, h in nat.tables[p.tables]]
    C = _column(f, tabs, p.parts, lambda w: notes_height(nat.notes, w))[0]
    tw, th = extent(_tree(p.shape, leaves, p.hcols, C, p.hrow, cut=p.cut, wrap=p.wrap))
    return tw <= x1 - x0 + 1e-9 and th <= y1 - y0 + 1e-9


def _grown_groups(dr: ForceDrafter, nat: Natural, f: Form, p: Plan) -> Plan:
    """LAYOUT.md's rule for each group and each force plan: the largest standard scale that fits
    its cell, every other drawing as planned. A group smaller than the largest (the crank's, a
    short dyad) is drawn at a finer standard μl than the family's — no larger than the largest
    group's drawing, or up to the scheme's scale, which every group takes where the sheet has room
    (review 4: the groups at 1:10 beside a 1:4 scheme) — the crank group of a long-rocker shaper at
    1:2, not 1:5 with G1 and Φ1 crowding its 20 mm. A force plan whose forces are small beside the
    largest plan's (the coulisse's outer dyad: R34 1740 N against R12 5140 N) is drawn at a finer
    μF, its largest vector no longer than the largest plan's (II(4-5) at 20 N/mm instead of 40:
    R34 87 mm, not 43). Grown a step at a time, the smallest against the largest of its family
    first: the groups grown whole before the plans left the pump six-bar's II(4-5) plan at
    20 N/mm, six of its nine forces under 2 mm, beside its group at 1:2 (review 45 #1). The grown
    scales go into ``mu`` as "group <label>" and "plan <label>", printed under each drawing and in
    the notes. Each size as drawn, not the family's model alone: a plan's lettering and small
    forces do not scale with it (SIEVE's I(0-1) at 2.5 N/mm came out 179 × 33 mm where the model
    said 93 × 39, and the A2 set planned on 2 sheets was drawn on 3)."""
    from graphplan.graphic.forceplans import group_extent
    from graphplan.sheets.compose import finer
    fams = nat.families
    mu = dict(p.mu)
    base_l, base_F = mu["groups"], mu["forces"]
    fp = dr.groups_fp(mu)
    extents = {gf.label: group_extent(dr.ks, gf.links) for gf in dr.ks.groups}
    largest_e = max(list(extents.values()) + [0.0])
    longest = {gp.label: max([s.mm for s in gp.sides] + [0.0]) for gp in fp.groups}
    largest_F = max(list(longest.values()) + [0.0])
    # each plan's shortest load (G, Φ, a resistance: the sides laid as known) at the family's μF
    shortest = {gp.label: min([s.mm for s in gp.sides if s.role == "known" and s.mm > 1e-9] + [math.inf])
                for gp in fp.groups}
    labels = [gp.label for gp in fp.groups]
    leaves = _placed_leaves(dr, nat, mu)

    def key_of(fam: str, i: int) -> str:
        return (GROUP if fam == "groups" else PLAN) + labels[i]

    def share(step: tuple[str, int]) -> float:
        """The drawing against the largest of its family (1: as large)."""
        fam, i = step
        m = mu.get(key_of(fam, i), mu[fam])
        if fam == "groups":
            return extents[labels[i]] / m / (largest_e / base_l)
        return longest[labels[i]] * base_F / m / largest_F

    def allowed(fam: str, i: int, s: float) -> bool:
        if fam == "groups":
            return extents[labels[i]] / s <= largest_e / base_l + 1e-9 or s >= mu["scheme"] * (1 - 1e-9)
        return plan_may_grow(longest[labels[i]] * base_F / s, shortest[labels[i]] * base_F / s, largest_F)

    growing = [("groups", i) for i in range(len(labels)) if largest_e > 0 and extents.get(labels[i], 0.0) > 0]
    growing += [("forces", i) for i in range(len(labels)) if largest_F > 0 and longest[labels[i]] > 0]
    while growing:
        fam, i = step = min(growing, key=share)
        # the next step, a plan's next three: its note of the short forces shortens as they lengthen
        # (the pump's II(4-5) plan drawn 107 mm wide at 15 N/mm, 98 at 10 — its group's cell 104)
        steps, s = [], mu.get(key_of(fam, i), mu[fam])
        while len(steps) < (1 if fam == "groups" else PLAN_TRIES):
            s = finer(s)
            if s is None or not allowed(fam, i, s):
                break
            steps.append(s)
        for s in steps:
            if fam == "groups":
                w, h = dr.group_size(mu, i, s, fams["groups"].caption)
            else:
                w, h = dr.plan_size(mu, i, s, fams["forces"].caption)   # as drawn, in both languages
            trial = {**leaves, fam: [*leaves[fam][:i], Leaf(leaves[fam][i].name, *(margined(w, h, leaves[fam][i]) if fam == "forces" else (w + GROW_MARGIN, h + GROW_MARGIN))),
                                     *leaves[fam][i + 1:]]}
            if _fits(nat, f, p, trial):
                mu[key_of(fam, i)] = s
                leaves = trial
                break
        else:
            growing.remove(step)
    return replace(p, mu=_plan_over_group(dr, nat, f, p, mu, leaves, allowed))


def _plan_over_group(dr: ForceDrafter, nat: Natural, f: Form, p: Plan, mu: dict[str, float],
                     leaves: dict[str, list[Leaf]], allowed) -> dict[str, float]:
    """A force plan left with sides too short to draw (under ``forces.TINY_MM``, named under it)
    that cannot grow in its cell takes the room of its group's drawing: the group one standard step
    coarser (one step only), the plan at the finest step that then fits — taken where it names
    fewer short sides than before, or as many while the plan grows by a larger factor than its group
    shrinks. INCLINED_ROCKER53's II(4-5): its group at 1:2 (169 mm tall over its plan) left the
    plan at 2 N/mm, a 3 × 13 mm polygon with R24τ, R05n and R45 under 3 mm; its group at 1:2.5
    lets it grow to 0.5 N/mm (review 53, frc53b #7). Since a revolute reaction is drawn as
    R^τ + R^n (5b4e801) its R05n stays under 3 mm down to 0.25 N/mm: "fewer" alone kept the plan at
    1 N/mm, a 32 mm polygon with its R24n, R45, Φ4, R05τ knotted in 8 mm, beside 25 mm of its
    group's room (frc59b: 0.5 N/mm, 65 mm, its group at the scheme's 1:2.5)."""
    from graphplan.drawing.forces import TINY_MM
    from graphplan.sheets.compose import coarser, finer
    fams = nat.families
    labels = [gp.label for gp in dr.groups_fp(mu).groups]

    def tiny(m: dict[str, float], i: int) -> int:
        return sum(1e-9 < s.mm < TINY_MM for s in dr.groups_fp(m).groups[i].sides)

    for i, label in enumerate(labels):
        g_key, p_key = GROUP + label, PLAN + label
        short = tiny(mu, i)
        if not short or p.shape == "set":
            continue
        g = coarser(mu.get(g_key, mu["groups"]))
        gw, gh = dr.group_size(mu, i, g, fams["groups"].caption)
        trial_mu = {**mu, g_key: g}
        group_leaf = Leaf(leaves["groups"][i].name, gw + GROW_MARGIN, gh + GROW_MARGIN)
        best, s = None, mu.get(p_key, mu["forces"])
        while True:
            s = finer(s)
            if s is None or not allowed("forces", i, s):
                break
            w, h = dr.plan_size(trial_mu, i, s, fams["forces"].caption)
            trial = {**leaves,
                     "groups": [*leaves["groups"][:i], group_leaf, *leaves["groups"][i + 1:]],
                     "forces": [*leaves["forces"][:i], Leaf(leaves["forces"][i].name, *margined(w, h, leaves["forces"][i])),
                                *leaves["forces"][i + 1:]]}
            if not _fits(nat, f, p, trial):
                break
            best = (s, trial)
        if best is None:
            continue
        now = tiny({**trial_mu, p_key: best[0]}, i)
        # fewer short sides; or as many, the plan grown by more than its group lost (the group a
        # series step coarser, 1:2 → 1:2.5: ×1.25; the plan 1 → 0.5 N/mm: ×2)
        gain = mu.get(p_key, mu["forces"]) / best[0] > g / mu.get(g_key, mu["groups"]) * (1 + 1e-9)
        if now < short or (now <= short and gain):
            mu = {**trial_mu, p_key: best[0]}
            leaves = best[1]
    return mu


PLAN_TRIES = 3     # a force plan's next steps tried in turn where the first does not fit (``_grown_groups``)
# how much longer than the largest plan's longest side a plan whose own loads are short grows (``plan_may_grow``)
PLAN_BEYOND = 1.5


def plan_may_grow(longest_mm: float, shortest_mm: float, largest_mm: float) -> bool:
    """Whether a group's force plan may be drawn with its longest side ``longest_mm`` and its
    shortest load (G, Φ) ``shortest_mm`` long: no longer than the largest plan's longest side
    (``largest_mm``) — or, past it, up to ``PLAN_BEYOND`` times that while the shortest load is
    drawn no longer than ``SHORT_FORCE_MM`` (the step that brings it to read, no step further): a
    group is drawn at a scale where its smallest force reads (issue 32 #3). The rocker six-bar's
    crank group at 4 N/mm — G1 6 mm, Φ1 4.5 mm, the polygon 58 mm beside 100 mm of empty room —
    barred from 2.5 N/mm because its R01 came out 93 mm against II(4-5)'s 91.5. Never longer than
    ``FORCES_MOST`` × ``POLYGON_MM`` (``Capped``)."""
    if longest_mm > FORCES_MOST * POLYGON_MM + 1e-9:      # no sliver across the sheet (``Capped``)
        return False
    if longest_mm <= largest_mm + 1e-9:
        return True
    return shortest_mm <= SHORT_FORCE_MM + 1e-9 and longest_mm <= PLAN_BEYOND * largest_mm + 1e-9


def _group_allowed(dr: ForceDrafter, mu: dict[str, float], label: str, mu_l: float) -> bool:
    """Whether group ``label`` may be drawn at μl ``mu_l`` on one sheet: no larger than the largest
    group's drawing at the groups' scale, or at the scheme's scale (``_grown_groups``' rule, the
    fill's too: the pump six-bar's crank group grew to 2:1, a 140 mm crank beside groups and a
    scheme at 1:4, review 45 #1)."""
    from graphplan.graphic.forceplans import group_extent
    extents = {gf.label: group_extent(dr.ks, gf.links) for gf in dr.ks.groups}
    largest = max(list(extents.values()) + [0.0])
    return (extents.get(label, 0.0) / mu_l <= largest / mu["groups"] + 1e-9
            or mu_l >= mu["scheme"] * (1 - 1e-9))


def _placed_leaves(dr: ForceDrafter, nat: Natural, mu: dict[str, float]) -> dict[str, list[Leaf]]:
    """The drawings' cells at the plan's scales, a group drawn at its own μl (``_grown_groups``)
    in its own cell."""
    leaves = _leaves(nat, mu)
    if leaves.get("hodographs"):
        # the hodographs as drawn at their size (``hodograph_cells``), as the growth took them: the
        # family's model, measured at the sizes drawn so far, read the compressor's grown to 2.0 as
        # 65.4 mm wide where they are drawn 95.1 mm — and the drawings grown after them took their room
        leaves["hodographs"] = [Leaf(x.name, *cell) for x, cell in
                                zip(leaves["hodographs"], dr.hodograph_cells(mu["hodographs"]))]
    own = dict(group_scales(mu))
    if own:
        fam = nat.families["groups"]
        fp = dr.fp(mu["groups"], mu["forces"], mu["lever"])
        leaves["groups"] = [Leaf(leaf.name, *(x + GROW_MARGIN for x in dr.group_size(mu, i, own[gp.label], fam.caption)))
                            if gp.label in own else leaf
                            for i, (leaf, gp) in enumerate(zip(leaves["groups"], fp.groups))]
    drawn = dr.memo.get(("scheme size", mu["scheme"], mu["forces"]))
    if drawn is not None and leaves["scheme"]:     # the scheme as drawn at its scale (``_filled_sheets``)
        s = leaves["scheme"][0]
        leaves["scheme"] = [Leaf(s.name, max(s.w, drawn[0] + GROW_MARGIN), max(s.h, drawn[1] + GROW_MARGIN))]
    plans = dict(plan_scales(mu))
    if plans:                                      # a force plan at its own μF (``_grown_plans``)
        fam = nat.families["forces"]
        fp = dr.fp(mu["groups"], mu["forces"], mu["lever"])
        leaves["forces"] = [Leaf(leaf.name, *margined(*_plan_cell(dr, mu, fam, plans[gp.label], i), leaf))
                            if gp.label in plans else leaf
                            for i, (leaf, gp) in enumerate(zip(leaves["forces"], fp.groups))]
    return leaves


def _plan_cell(dr: ForceDrafter, mu: dict[str, float], fam: Family, mu_F: float, i: int) -> tuple[float, float]:
    """A force plan's cell at its own μF: as drawn where it was (``ForceDrafter.plan_size``, both
    languages, the largest of the drawings at the groups' scales), else the family's model (whose
    lettering, the short forces' note of a coarser plan, overstates a finer one's)."""
    drawn = [d for key, d in dr.memo.items()
             if key[:3] == ("plan size", i, mu_F) and key[3:5] == (mu["groups"], mu["forces"])]    # (not μv's)
    if drawn:
        return max(d[0] for d in drawn), max(d[1] for d in drawn)
    return fam.size(mu_F, i)


def _lettering_kept(dr: ForceDrafter, nat: Natural, mu: dict[str, float], p: Plan) -> bool:
    """Whether the tables and the notes at the scales ``mu`` (the lever's μv is printed in the
    notes, its P_b and M_b in the results) are no larger than the composition allowed for; where
    they are, ``nat`` takes their sizes."""
    from graphplan.util.words import LANGS
    ok = not grown(nat.tables[p.tables], [[(n, *_wh(r)) for n, r in _tables(dr, mu, lang, p.tables)]
                                          for lang in LANGS])
    drawn = [_notes_lines(dr, mu, lang) for lang in LANGS]
    if notes_height(drawn, TITLE) > notes_height(nat.notes, TITLE) + 1e-6:
        nat.notes += drawn
        ok = False
    return ok


def _grown_lever(dr: ForceDrafter, nat: Natural, f: Form, p: Plan) -> Plan:
    """The Zhukovsky lever as large as its cell allows (LAYOUT.md: the largest scale that fits its
    zone), every other drawing as planned — the lever's μv grown in the plans' steps
    (``LeverFamily``) while the composition fits, up to ``LEVER_MM`` across (the room left
    is no other drawing's: the lever and then the hodographs take it last) — then a round μv (the series, GOST's 1.5, 7.5 ×
    10^k) where it draws the lever at least ``ROUND_SHARE`` of that, else p_v a chosen (a multiple of
    5 mm) and μv = v_A / p_v a at three figures, as the kinematics sheet's plans. The arms h are read
    off the lever to the ruler's 0.5 mm, so a larger lever reads P_зр closer to the exact."""
    from graphplan.graphic.scales import ROUND_SHARE, on_round
    fam = nat.families["lever"]
    mu = dict(p.mu)
    if not isinstance(fam, LeverFamily) or fam.figure <= 0 or not fam.sizes:
        return p
    leaves = _placed_leaves(dr, nat, mu)
    name = leaves["lever"][0].name

    def fits(m: float) -> bool:
        w, h = fam.size(m, 0)
        return _fits(nat, f, p, {**leaves, "lever": [Leaf(name, w + GROW_MARGIN, h + GROW_MARGIN)]})

    for _ in range(3):
        fitting = [(mu["lever"], on_round(mu["lever"]))]
        for m, rnd in fam.choices(mu["lever"]):      # the smallest first: stop at the first too large
            if not fits(m):
                break
            fitting.append((m, rnd))
        largest = fitting[-1][0]
        rounds = [r for r, _ in fam.choices(largest * 2.0) if on_round(r) and r >= largest * (1 - 1e-9)]
        m = next((r for r in reversed(rounds) if largest / r >= ROUND_SHARE - 1e-9), largest)
        if m == p.mu["lever"]:
            break
        trial = {**mu, "lever": m}
        if _lettering_kept(dr, nat, trial, p) and fits(m):
            mu = trial
            break
    return replace(p, mu=mu)


def drawing_scales(st: Study, format: str = "A1", precision: float = 0.5) -> dict[str, dict[str, float]]:
    """Every drawing of the force sheet of ``format`` with the scales it is drawn at (the scheme's
    and the groups' μl, μF, μa, μv, the charts' and hodographs' μ) — for ``forces --json``: the
    terminal reports the construction the sheet draws."""
    from graphplan.drawing.forces import polygon_record
    p, _, dr = plan(st, form(format), SheetOptions(precision=precision, sheet="forces"))
    names = dr.names()
    drawn = dr.drawings(p.mu, lettered=False)
    # the force plans as the sheet draws them: a plan's detail ("I (μF = 25 N/mm)") is no sketch's
    fp = dr.groups_fp(p.mu)
    drawn = {**drawn, "forces": [polygon_record(fp, gp, "uk") for gp in fp.groups]}
    return {names[fam][i]: {k: v for k, v in r.scales.items() if k.startswith("mu_")}    # the scales alone
            for fam, recs in drawn.items() for i, r in enumerate(recs)}


def force_scales(st: Study, format: str = "A1", precision: float = 0.5) -> dict[str, float]:
    """μl (of the groups) and μF of the force sheet of ``format`` — for ``forces --format``; no sheet
    is built. With them μa of its acceleration plan, the inertia loads' (``forceplans.construct``)."""
    p, _, _ = plan(st, form(format), SheetOptions(precision=precision, sheet="forces"))
    return {"mu_l": p.mu["groups"], "mu_F": p.mu["forces"], "mu_v": p.mu["lever"],
            "group_mu": dict(group_scales(p.mu)), "group_mu_F": dict(plan_scales(p.mu)),
            "mu_a": p.mu["acceleration"]}


def _arranged(tree, region):
    """``layout.arrange`` of the one-sheet tree, a flush stack of bands giving its spare height to
    its last band (the acceleration plan, the charts and the tables' column spread over it) rather
    than to a blank strip between the bands (review 6 #12: 600 × 60 mm across an A1 sheet)."""
    if not isinstance(tree, Stack) or not tree.flush or len(tree.children) < 2:
        yield from arrange(tree, region)
        return
    x0, y0, x1, y1 = region
    top = y1
    for child in tree.children[:-1]:
        h = extent(child)[1]
        yield from arrange(child, (x0, top - h, x1, top))
        top -= h + tree.gap
    yield from arrange(tree.children[-1], (x0, y0, x1, top))


def count_forces_sheets(st: Study, f: Form, options) -> int:
    """``len(build_forces_sheet(st, f, options).pages)`` without drawing it where ``plan`` makes it one
    sheet (that builder then lays ``pages = [items]``): what the scene's other sheets number by."""
    opts = options_of(options)
    raw = SheetOptions(opts.positions, opts.accel, opts.precision, "uk", "forces")
    if planned_sheets(st, f, raw) == 1 or plan(st, f, raw)[0].sheets == 1:
        return 1
    return len(build_forces_sheet(st, f, options).pages)


def build_forces_sheet(st: Study, f: Form, options) -> Sheet:
    """Sheet 2: the force analysis at the scene's force position, composed in zones (a set of sheets
    where a small format cannot hold it)."""
    opts = options_of(options)
    p, nat, dr = plan(st, f, SheetOptions(opts.positions, opts.accel, opts.precision, "uk", "forces"))
    lang = opts.lang
    w = lambda key: word(f"fs {key}", lang)  # noqa: E731
    leaves = _drawn_leaves(dr, p.mu, lang)
    tables = [Leaf(name, record=rec) for name, rec in _tables(dr, p.mu, lang, p.tables)]
    note_lines = _notes_lines(dr, p.mu, lang)
    region = field_of(f)
    if p.sheets == 1:
        C, groups, width = _column(f, tables, p.parts, lambda wd: _wh(note_block(note_lines, wd))[1], p.counts)
        items, col_box = [], None
        for leaf, b in _arranged(_tree(p.shape, leaves, p.hcols, C, p.hrow, cut=p.cut, wrap=p.wrap), region):
            if leaf is C:
                col_box = b
            elif leaf.record is not None:
                items.append(Placed(leaf.name, centred(leaf.record, b), b))
        nrec = note_block(note_lines, width)
        foot = keep_out(f)[3]
        nb = (col_box[2] - width, foot, col_box[2], foot + _wh(nrec)[1])
        items.append(Placed("notes", top_left(nrec, nb), nb))
        items += set_columns(groups, col_box[2] - column_size(groups)[0], col_box[3])
        pages = [items]
    else:
        from graphplan.sheets.compose import later_keep
        from graphplan.sheets.forceset import laid, pack, spread, units_of
        nrec = note_block(note_lines, TITLE)
        notes_leaf = Leaf("notes", record=nrec)
        packed = pack(units_of(leaves, region[2] - region[0], p.plan_first, p.gap), tables, notes_leaf, region,
                      keep_out(f), later_keep(f), p.gap)
        if packed is not None and not _as_planned(packed, p, leaves):
            # each drawing on the sheet the plan put it on, where each sheet holds its share: LINK53's
            # A2 hodographs packed into sheet 2's bottom row where the plan set them on sheet 3 with
            # the tables (stop 54), which stood there alone, spread across the width
            packed = _packed_as_planned(p, leaves, tables, notes_leaf, f) or packed
        if packed is None or len(packed) > p.sheets:
            # each drawing in the cell the plan sized: the set's sheets as the plan counted them
            planned = _placed_leaves(dr, nat, p.mu)
            leaves = {fam: [Leaf(x.name, max(x.w, q.w), max(x.h, q.h), x.record) for x, q in zip(xs, planned[fam])]
                      for fam, xs in leaves.items()}
            if leaves["hodographs"]:
                cw, ch = max(x.w for x in leaves["hodographs"]), max(x.h for x in leaves["hodographs"])
                leaves["hodographs"] = [Leaf(x.name, cw, ch, x.record) for x in leaves["hodographs"]]
            tables = [Leaf(t.name, max(t.w, w), max(t.h, h), t.record)
                      for t, (_, w, h) in zip(tables, nat.tables[p.tables])]
            notes_leaf = Leaf("notes", TITLE, max(_wh(nrec)[1], notes_height(nat.notes, TITLE)), nrec)
            packed = pack(units_of(leaves, region[2] - region[0], p.plan_first, p.gap), tables, notes_leaf, region,
                          keep_out(f), later_keep(f), p.gap)
        if packed is None:       # each group and its plan set apart, where no sheet holds the two as one box
            packed = pack(units_of(leaves, region[2] - region[0], p.plan_first, p.gap, apart=True), tables,
                          notes_leaf, region, keep_out(f), later_keep(f), p.gap)
        if packed is None:
            raise said_error(GraphplanError, "sh drawing larger", None, None, form=f.name, option="--format")
        pages = []
        for k, spots in enumerate(packed):
            keep = keep_out(f) if k == 0 else later_keep(f)
            corner = {t.name for t in tables} | {"notes"}          # a table at its column's left
            pages.append([Placed(leaf.name, (top_left if leaf.name in corner else centred)(leaf.record, b), b)
                          for leaf, b in laid(spread(spots, region, keep, p.gap), region) if leaf.record is not None])
            pages[-1] = _hodographs_fitted(dr, p, pages[-1], region, keep, lang)
    tf = fields(st, lang, drawing_scale(p.mu["scheme"], lang), subtitle=w('subtitle'))
    return compose(f, pages, tf, lang, f"{title_in(st, lang)} — {w('subtitle')}")
