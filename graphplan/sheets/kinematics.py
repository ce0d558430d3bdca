"""The kinematics sheet (sheet 1 of the coursework, seeds 000 and 004; the lab report of seed 002):
the position plan, the velocity plan of every position, the acceleration plans asked for, the s–v–a
diagrams, the tables (sheets/kintables.py: velocities; one numbered table per acceleration plan; the
links' dimensions; the lab's s, v, a at the chosen positions; the diagrams read at every position
beside the plans) and the notes.

Composed by construction (docs/composition.md): the tables in a column by the title block, the notes
above it; in the rest of the field the position plan and the diagrams, the velocity plans in a grid of
cells in position order, the acceleration plans together. The scales are chosen once per scene
and format by arithmetic on the drawings' natural sizes (``plan``; the arithmetic is
sheets/kinlayout.py): the largest standard scales at which the composition fits; the terminal's
``plans``/``diagrams``, the API and the explorer ask ``sheet_scales`` for the same numbers. Where one
sheet cannot hold the plans legibly (a small format), the drawings flow over a set of sheets in
reading order. This module draws (``Drafter``), measures, chooses and places."""
from __future__ import annotations

from dataclasses import dataclass

from graphplan.drawing.layout import GAP, Grid, Leaf, Placed, arrange, centred, flow, top_left
from graphplan.exact.positions import Study
from graphplan.graphic.record import Record
from graphplan.sheets.compose import (Sheet, SheetOptions, captioned, compose, drawing_scale, field_of, grown,
                                      measured, note_block, notes_height, options_of, remembered)
from graphplan.sheets.form import TABLES, Form, form
# the tables and the title block's fields (the force, dynamics and cam sheets import them from here too)
from graphplan.sheets.kintables import (acceleration_table, fields, footnoted, lab_table, notes,  # noqa: F401
                                        notes_lines, sheet_tables, title_in, velocity_columns)
from graphplan.sheets.kinlayout import (ONE_SHEET, TARGETS, TITLE, LETTERING, Plan, Natural,  # noqa: F401
                                        PlansUndrawable, SPLIT, factors, column_leaf, grid_rows, legible, one_sheet, room,
                                        place_tables, room_fits, set_of_sheets, set_rows, set_tail, size_of, split_leaves,
                                        taller_in_place,
                                        tree)
from graphplan.util.errors import GraphplanError, said_error
from graphplan.util.words import fixed, num, word


def _accel_arg(values) -> list | None:
    """The acceleration plans asked for, as build_plans reads them ("#3", "200", 200.0)."""
    return list(values) if values else None


S_HEIGHT = 80.0        # mm: the s diagram drawn at most this high (μs from the standard series)
POLES = (15.0, 50.0)   # the lab manual's pole distances H1, H2, mm
SHARE = 0.6            # an unset pole distance draws the v or a peak about this share of the s diagram's


_REDRAWN: dict[tuple, dict] = {}


def diagram_options(st: Study, k: float | tuple[float, float] = 1.0, positions: int | None = None,
                    precision: float = 0.5, room: tuple[float, ...] | None = None, floor: float = 0.0) -> dict:
    """The options the sheet draws the diagrams with (``chord_diagrams`` keywords): ``first_options``
    where that drawing is qualitatively right, else as graphic.redraw changes it until it is (the
    area correction, other poles within the lab's 15–50 mm, smaller intervals where the curve bends;
    the scene's own H1, H2 kept; a longer L, up to the scene's, where ``room`` is given) — ``redrawn``
    says what. A redrawn block is at most ``GROWTH`` times the first one's width and height and fits
    ``room`` (the sheet's: ``kinlayout.room``) and leaves the v and a diagrams at least ``floor``
    mm high (or as high as first drawn; a set's ``DIAGRAM_MM``: a lower drawing reads worse than
    one off 5 % at a position), else the next right candidate is taken. The s height
    is the size factor's: a larger one is the composition's choice (``kinlayout.set_of_sheets``
    takes a size whose diagrams are right where that costs a sheet at most). Once per
    scene, size factor, positions and ruler: the sheet of either language, ``sheet_scales`` and
    the terminal get the same."""
    from graphplan.graphic.redraw import redraw
    key = (repr(st.mech), k, positions, precision, room, floor)
    if key not in _REDRAWN:
        if len(_REDRAWN) >= 128:       # a set searches some 35 sizes (the A3 gate: 34, two of them redrawn twice at 32)
            _REDRAWN.pop(next(iter(_REDRAWN)))
        first = first_options(st, k, positions)
        dg = st.mech.task.diagram
        fixed = frozenset(name for name in ("H1", "H2") if f"{name}_mm" in dg)
        longest = float(dg.get("L_mm", 240.0)) if room is not None else None
        sizes: dict = {}

        def fits(options: dict, grow: bool = True) -> bool:
            if "first" not in sizes:            # the first drawing measured once (not at every candidate)
                sizes["first"] = _block_size(st, first, precision)
            w0, h0 = sizes["first"]
            w, h = _block_size(st, options, precision)
            g = GROWTH if grow else SAME
            if not (w <= g * w0 + 1e-6 and h <= g * h0 + 1e-6 and (room is None or room_fits(room, w, h))):
                return False
            if floor <= 0:
                return True
            if "first spans" not in sizes:
                sizes["first spans"] = _spans(st, first, precision)
            low = sizes["first spans"]
            return all(got >= min(floor, was) - 1e-6 for got, was in zip(_spans(st, options, precision), low))
        chosen, done = redraw(st, first, precision, POLES, fixed=fixed, longest=longest, fits=fits, menu=floor > 0)
        _REDRAWN[key] = {**chosen, "redrawn": done}
    return dict(_REDRAWN[key])


DIAGRAM_MM = 40.0   # a set's redrawing leaves the v and a diagrams at least this high (or as high as first
                    # drawn): the crank-slider's A3 set took H1 15 mm for 5 % at the positions, v 26 mm high
GROWTH = 1.25     # a redrawn diagrams' block at most this times the first one's width and height
SAME = 1.05       # … redrawn for its errors at the positions alone (the first was right): about its size


_LAST: list = []      # the last (key, diagrams) drawn for a candidate's size (``_drawn``)
_S_RANGE: dict[tuple, tuple] = {}     # (id(st), point) → (a weak reference to st, unit, s_range): what μs is chosen from
_MEASURED: dict[tuple, tuple] = {}    # (what, the drawing's key) → (a weak reference to st, a block's size or the
_MEASURED_KEPT = 4096                 # spans: ``_measured``) — a study's id is its own while it lives
_PLAIN = (int, float, str, bool, type(None))


def _drawing_key(st: Study, options: dict, precision: float) -> tuple | None:
    """What a drawing with ``options`` is made of: its options with the s height as the μs it chooses
    (``choose_mu_s``: ``chord_diagrams`` reads ``height`` through μs alone — the same construction, the
    same block, to the last bit), or None where an option is not a plain value. A set's heights are
    searched in 0.05 steps (``kinlayout.tallest``), and each height's redrawing measures the same
    candidates over the few μs of the series they choose (review 61: the A3 gate's set spent 70 % of
    its CPU measuring candidates, most of them measured before at another height)."""
    if not all(isinstance(v, _PLAIN) or (isinstance(v, tuple) and all(isinstance(x, _PLAIN) for x in v))
               for v in options.values()):
        return None
    opts = dict(options)
    height = opts.get("height")
    if height is not None:
        from graphplan.graphic.diagrams import choose_mu_s
        rk = (id(st), opts.get("point"))
        hit = _S_RANGE.get(rk)
        if hit is None or hit[0]() is not st:
            import weakref

            import numpy as np

            from graphplan.graphic.diagrams import CYCLE, exact_motion, resolve_output
            out, _, _, _, unit = resolve_output(st, opts.get("point"))
            s_c = exact_motion(st, out, np.arange(CYCLE + 1) * 360.0 / CYCLE)[0]
            if len(_S_RANGE) >= 64:
                _S_RANGE.pop(next(iter(_S_RANGE)))
            hit = _S_RANGE[rk] = (weakref.ref(st), unit, float(np.ptp(s_c)))
        _, unit, s_range = hit
        opts["height"] = ("mu_s", choose_mu_s(st, unit, s_range, height, bool(opts.get("fit", False))))
    return (id(st), tuple(sorted((k, repr(v)) for k, v in opts.items())), precision)


def _drawn(st: Study, options: dict, precision: float):
    """``chord_diagrams(st, precision, **options)`` (Ukrainian), remembered for the last options of
    plain values: a candidate's block (``_block_size``) and its spans (``_spans``) are measured off
    one construction, not two (redraw measures some 300 candidates on the shaper's A3 set)."""
    from graphplan.graphic.diagrams import chord_diagrams
    key = _drawing_key(st, options, precision)
    if key is None:
        return chord_diagrams(st, precision=precision, **options)
    if not _LAST or _LAST[0][0] != key:
        _LAST[:] = [(key, chord_diagrams(st, precision=precision, **options))]     # holds st: its id stays its
    return _LAST[0][1]


def _measured(what: str, st: Study, options: dict, precision: float, make):
    """``make()`` once per drawing (``_drawing_key``): its block's size, its spans."""
    key = _drawing_key(st, options, precision)
    if key is None:
        return make()
    key = (what,) + key
    hit = _MEASURED.get(key)
    if hit is None or hit[0]() is not st:
        import weakref
        if len(_MEASURED) >= _MEASURED_KEPT:
            _MEASURED.pop(next(iter(_MEASURED)))
        hit = _MEASURED[key] = (weakref.ref(st), make())
    return hit[1]


def _spans(st: Study, options: dict, precision: float) -> tuple[float, float]:
    """The v and a diagrams drawn with ``options``: each one's height with its axis, mm."""
    import numpy as np

    def make():
        r = _drawn(st, options, precision).drawn
        return tuple(float(np.ptp(np.append(x, 0.0))) for x in (r.v, r.a))
    return _measured("spans", st, options, precision, make)


def _block_size(st: Study, options: dict, precision: float) -> tuple[float, float]:
    """The diagrams' block drawn with ``options`` (the larger of the two languages), mm. The
    construction is the language's own in nothing but its ``lang`` (graphic.diagrams): built once,
    lettered in each language."""
    from dataclasses import replace

    from graphplan.drawing.diagrams import draw
    from graphplan.util.words import LANGS

    def make():
        d = _drawn(st, options, precision)
        sizes = []
        for lang in LANGS:
            b = captioned(draw(d if d.lang == lang else replace(d, lang=lang), lang),
                          word("kin diagrams", lang)).bounds()
            sizes.append((b[2] - b[0], b[3] - b[1]))
        return max(w for w, _ in sizes), max(h for _, h in sizes)
    return _measured("block", st, options, precision, make)


def first_options(st: Study, k: float | tuple[float, ...] = 1.0, positions: int | None = None) -> dict:
    """The diagrams' first L, s height and pole distances: the scene's L (× k where a small sheet needs it),
    the s diagram at most ``S_HEIGHT`` × k high (k a pair: L × its first, the height × its second —
    a set's diagrams as tall as their sheet holds, ``kinlayout.set_of_sheets``; a triple: the poles
    as the pair of its first and third chose them, so only s is taller); H1, H2 the scene's
    where it gives them, else chosen (whole mm, within the lab's 15–50 mm) so the v or a peak is
    about ``SHARE`` of the s diagram — of the height allowed it, for a pair: μs is a standard value,
    so s takes 0.4–1 of its allowance and the v and a diagrams take up the rest (heights are
    ordinates at a scale: the construction is the same) —: v_mm = v·μt·H1/μs, a_mm = a·μt·H2/μv,
    μt = T/L (REFERENCE §1.5). No language enters."""
    from graphplan.graphic.diagrams import chord_diagrams
    dg = st.mech.task.diagram
    long, tall = factors(k)
    out: dict = {"point": dg.get("point"), "divisions": positions or dg.get("divisions") or st.mech.task.count,
                 "L": float(dg.get("L_mm", 240.0)) * long, "H1": float(dg.get("H1_mm", 30.0)),
                 "H2": float(dg.get("H2_mm", 30.0)), "height": S_HEIGHT * tall}
    if "H1_mm" in dg and "H2_mm" in dg:
        return out
    probe = chord_diagrams(st, precision=0.0, **out)
    s_mm = float(max(abs(probe.exact.s.max() - probe.exact.s.min()), 1e-9))
    if not isinstance(k, (int, float)):
        s_mm = max(s_mm, out["height"])
    if not isinstance(k, (int, float)) and len(k) > 2:
        # a triple (length, height, poles' height): the s diagram as tall as the second factor's μs
        # draws it, the poles chosen as the pair (length, third) chose them — so the v and a peaks
        # stay as high as that pair's (v_mm = SHARE·s_mm: the poles scale with μs) and only the s
        # diagram grows, at a finer μs (``kinlayout.taller_in_place``: review 55 #3, the beam pump's
        # stroke 44 mm high at μs 0,004 in an 85-mm band; at 0,0025 it is 71 mm)
        base = chord_diagrams(st, precision=0.0, **{**out, "height": S_HEIGHT * float(k[2])})
        s_mm = max(float(max(abs(base.exact.s.max() - base.exact.s.min()), 1e-9)), S_HEIGHT * float(k[2]))

    def pole(peak: float, mu_before: float) -> float:
        if peak <= 0:
            return POLES[0]
        return float(min(POLES[1], max(POLES[0], round(SHARE * s_mm * mu_before / (peak * probe.mu_t)))))
    if "H1_mm" not in dg:
        out["H1"] = pole(probe.maxima["v"], probe.mu_s)
    if "H2_mm" not in dg:
        out["H2"] = pole(probe.maxima["a"], probe.mu_s / (probe.mu_t * out["H1"]))
    return out


def _captions(st: Study, plans, lang: str, mu: dict[str, float]) -> dict[str, list[tuple[str, str]]]:
    """Each drawing's caption (name, second line) in ``lang``."""
    from graphplan.graphic.scales import format_scale
    w = lambda key, **f: word(f"kin {key}", lang, **f)  # noqa: E731
    out: dict[str, list[tuple[str, str]]] = {"position": [(w('positions'), format_scale('mu_l', mu["position"], lang))]}
    out["velocity"] = [(f"{w('velocity')} {q.index if q.index is not None else ''}".rstrip(), "")
                       for q in plans.positions]
    out["acceleration"] = [
        (f"{w('acceleration')}, {w('position')} {q.index}" if q.index is not None else w('acceleration'),
         f"{format_scale('mu_a', mu['acceleration'], lang)},  "
         f"φ = {num(float(st.from_position0(q.phi % 360)), lang, 4)}°")
        for q in plans.positions if q.acceleration is not None]
    return out


@dataclass
class Drafter:
    """Draws what the kinematics sheet holds, remembering it: the plans at given scales, the
    diagrams at a size factor."""
    st: Study
    opts: SheetOptions
    room: tuple[float, ...] | None = None    # kinlayout.room: where a redrawn diagrams' block must fit
    floor: float = 0.0       # … and how high its v and a diagrams stay (a set's: ``DIAGRAM_MM``)

    def __post_init__(self) -> None:
        self.memo: dict = {}
        self.s_tried: dict = {}     # size → the other s scales tried for it (kinlayout.taller_in_place)

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
        """The diagrams at size ``k`` in ``lang``: constructed once (Ukrainian), the other language
        the same construction with its ``lang`` (graphic.diagrams: a Diagrams is the language's own in
        nothing else, its warnings carry both; ``_block_size`` measures so too)."""
        from dataclasses import replace

        from graphplan.graphic.diagrams import chord_diagrams
        o = self.opts
        if lang != "uk":
            d = self._once(("diag", k, lang), lambda: replace(self.diagrams(k, "uk"), lang=lang))
        else:
            d = self._once(("diag", k, lang), lambda: chord_diagrams(
                self.st, precision=o.precision, lang=lang, **diagram_options(self.st, k, o.positions, o.precision,
                                                                             self.room, self.floor)))
        tried = self.s_tried.get(k, ())
        return d if d.s_tried == tried else replace(d, s_tried=tried)

    def lines(self, mu: dict[str, float]) -> dict[str, list[Record]]:
        """The plans at the scales ``mu``, their lines only (no lettering): family → records."""
        from graphplan.drawing.plans import position_record
        pl = self.plans(mu)
        return {"position": [position_record(pl, lettered=False)],
                "velocity": [q.velocity.record for q in pl.positions if q.velocity is not None],
                "acceleration": [q.acceleration.record for q in pl.positions if q.acceleration is not None]}

    def records(self, mu: dict[str, float], lang: str = "uk") -> dict[str, list[Record]]:
        """The plans at the scales ``mu``, drawn and lettered (no captions) in ``lang`` (the position
        plan's dimensions carry its decimal sign): family → records."""
        from graphplan.drawing.plans import acceleration_records, position_record, velocity_records
        key = ("records", lang) + tuple(sorted(mu.items()))

        def make():
            pl = self.plans(mu)
            return {"position": [position_record(pl, lang=lang)], "velocity": list(velocity_records(pl).values()),
                    "acceleration": list(acceleration_records(pl).values())}
        return self._once(key, make)

    def diagrams_right(self, k: float) -> bool:
        """Whether the diagrams at size factor k are qualitatively right (graphic.redraw found a drawing)."""
        o = self.opts
        return diagram_options(self.st, k, o.positions, o.precision, self.room, self.floor)["redrawn"].right

    def redrawn(self, k) -> bool:
        """Whether the diagrams at size ``k`` are drawn otherwise than first (graphic.redraw)."""
        o = self.opts
        r = diagram_options(self.st, k, o.positions, o.precision, self.room, self.floor)["redrawn"]
        return bool(r.changed or r.wrong_after)

    def drawn(self, k) -> tuple[float, float, float, float]:
        """The diagrams at size ``k`` as drawn: L and the s, v, a diagrams' heights (with their
        axis), mm."""
        import numpy as np
        d = self.diagrams(k)
        r = d.drawn
        return d.L, *(float(np.ptp(np.append(x, 0.0))) for x in (r.s, r.v, r.a))

    def first_size(self, k) -> tuple[float, float]:
        """The diagrams' block as first drawn at size ``k`` (``first_options``, before any redrawing), mm."""
        o = self.opts
        return self._once(("first size", k), lambda: _block_size(self.st, first_options(self.st, k, o.positions),
                                                                 o.precision))

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
    recs = dr.records(mu0)        # lettered: what the lettering adds is measured (and checked once drawn)
    v_a = abs(mech.omega1) * mech.crank.length
    a_a = mech.crank.length * (mech.omega1 ** 4 + mech.crank.epsilon ** 2) ** 0.5
    principal = {"position": mech.crank.length, "velocity": v_a, "acceleration": a_a}
    families = {fam: measured(rs, mu0[fam], [c for lang in LANGS for c in _captions(st, pl, lang, mu0)[fam]],
                              principal=principal[fam], target=TARGETS[fam])
                for fam, rs in recs.items()}
    diag = dr.diagrams(1.0)
    tables = {}
    for factor in (TABLES, 1.0):
        per = [[(name, *size_of(rec)) for name, rec in sheet_tables(st, pl, diag, lang, dr.opts.precision, factor)]
               for lang in LANGS]
        tables[factor] = [(a[0], max(a[1], b[1]), max(a[2], b[2])) for a, b in zip(*per)]
    notes_ = [notes_lines(st, pl, dr.diagrams(1.0, lang), lang, dr.opts.precision) for lang in LANGS]
    return Natural(families, {}, tables, notes_)


def _checked(dr: Drafter, nat: Natural, p: Plan) -> bool:
    """Whether the drawings at the plan's scales are no larger than the arithmetic assumed; where one
    is, ``nat`` is corrected (the next choice allows for it). So are the tables and the notes
    (their millimetres and scales are the plan's)."""
    from graphplan.util.words import LANGS
    plans = dr.plans(p.mu)
    prec = dr.opts.precision
    ok = not grown(nat.tables[p.tables], [[(n, *size_of(r)) for n, r in sheet_tables(
        dr.st, plans, dr.diagrams(p.diagrams, lang), lang, prec, p.tables)] for lang in LANGS])
    drawn = [notes_lines(dr.st, plans, dr.diagrams(p.diagrams, lang), lang, prec) for lang in LANGS]
    if any(notes_height(drawn, w) > notes_height(nat.notes, w) + 1e-6 for w in {TITLE, p.notes}):
        nat.notes += drawn
        ok = False
    for fam, recs in dr.records(p.mu).items():
        family = nat.families[fam]
        for i, r in enumerate(recs):
            ok &= family.allow(p.mu[fam], *size_of(r), i)
    return ok


@remembered
def plan(st: Study, f: Form, opts: SheetOptions) -> tuple[Plan, Natural, Drafter]:
    """The kinematics sheet's composition, once per scene, format and options (the language does
    not enter): one sheet where one holds the plans legibly (on A1 always), else a set. The plans
    are then drawn at the chosen scales and, where one came out larger than assumed, the choice is
    made again allowing for it (the sheet, the terminal and the explorer all get this result)."""
    dr = Drafter(st, SheetOptions(opts.positions, opts.accel, opts.precision, "uk", "kinematics"),
                 room(f, later=f.name not in ONE_SHEET), 0.0 if f.name in ONE_SHEET else DIAGRAM_MM)
    nat = measure(dr)

    def choose() -> Plan:
        one = one_sheet(dr, nat, f)
        return one if one is not None and (f.name in ONE_SHEET or legible(nat, one.mu)) else set_of_sheets(dr, nat, f)
    for _ in range(4):
        p = choose()
        if _checked(dr, nat, p):
            break
    # the lettering is now measured at the chosen scales (``Family.lettering``), where the choice
    # assumed the most any scale needed: chosen once more, the drawings' true sizes may hold a
    # better one (the long rocker's A2 set was laid out with nine velocity plans on its second
    # sheet; drawn, five went on the first and seven sat alone on the second, 17 % drawn on). A set
    # only: an A1 sheet's zones stretch, no drawing moves to another sheet
    if f.name not in ONE_SHEET:
        again = choose()
        if again != p and _checked(dr, nat, again):
            p = again
    else:       # one sheet's diagrams drawn shorter for the room across get their height back where it is
        # — tried again where the check corrected ``nat`` (the taller drawing's notes longer than
        # assumed): the coulisse of stop 8 kept its diagrams at 0.64 (s 36 mm high, 23.5 % off at a
        # position) though, its notes allowed for, (0.8, 0.9) holds and reads closer
        for _ in range(3):
            tall = taller_in_place(dr, nat, f, p)
            notes_were = list(nat.notes)
            if _checked(dr, nat, tall):       # kept too: its notes now say the s scales tried (longer)
                p = tall
                break
            if tall != p and dr.s_tried.get(tall.diagrams):
                # the closer drawing before the sentence on the other s scales tried: the jaw crusher's
                # ψ3 at 0,005 (ε3 6.3 %) lost its room to that sentence and fell back to 0,01 (17 %)
                dr.s_tried[tall.diagrams] = ()
                nat.notes[:] = notes_were
                if _checked(dr, nat, tall):
                    p = tall
                    break
            if tall == p:                      # … measured anew: chosen again allowing for them
                p = choose()
    return p, nat, dr


def _options(opts: SheetOptions) -> SheetOptions:
    return SheetOptions(opts.positions, opts.accel, opts.precision, "uk", "kinematics")


def sheet_scales(st: Study, format: str = "A1", positions: int | None = None, accel=None,
                 precision: float = 0.5) -> dict[str, float]:
    """The scales the kinematics sheet of ``format`` draws with — μl, μv, μa of the plans and the
    diagrams' L, height, H1, H2 (and under "diagrams" all the options its diagrams are drawn with,
    ``diagram_options``) — for the terminal's ``plans``/``diagrams``, the API and the explorer
    to print what the sheet draws. Arithmetic on the drawings' sizes: no sheet is built. More
    positions than a sheet holds are refused first (the layout of 3600 plans would take minutes)."""
    check_positions(st, SheetOptions(positions=positions, accel=accel, precision=precision))
    p, _, dr = plan(st, form(format), SheetOptions(positions=positions, accel=accel, precision=precision))
    opts = diagram_options(st, p.diagrams, positions, precision, dr.room, dr.floor)
    return {"mu_l": p.mu["position"], "mu_v": p.mu["velocity"], "mu_a": p.mu["acceleration"],
            "L": opts["L"], "height": opts["height"], "H1": opts["H1"], "H2": opts["H2"],
            "diagrams": opts}


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
    recs = dr.records(p.mu, lang)
    diag = dr.diagrams(p.diagrams, lang)
    return {
        "plans": plans, "diag": diag,
        "position": captioned(recs["position"][0], *caps["position"][0]),
        "diagrams": dr.diagram_record(p.diagrams, lang),
        "velocity": [captioned(r, *c) for r, c in zip(recs["velocity"], caps["velocity"])],
        "acceleration": [captioned(r, *c) for r, c in zip(recs["acceleration"], caps["acceleration"])],
        "tables": sheet_tables(st, plans, diag, lang, dr.opts.precision, p.tables),
        "notes": notes_lines(st, plans, diag, lang, dr.opts.precision),
    }


def set_notes(lines: list[str], width: float) -> Record:
    """A set's notes at ``width``: one column, or two of the title block's width side by side where
    ``width`` is ``TWO_COLUMNS`` (``kinlayout.note_halves``)."""
    from graphplan.sheets.kinlayout import TWO_COLUMNS, note_halves
    if width < TWO_COLUMNS - 1e-9:
        return note_block(lines, width)
    left, right = note_halves(lines)
    rec = note_block(left, TITLE)
    rec.extend(note_block(right, TITLE).moved(TITLE + GAP, 0.0))
    return rec


def count_kinematics_sheets(st: Study, f: Form, options) -> int:
    """``len(build_kinematics_sheet(st, f, options).pages)`` without drawing it where ``plan`` makes it
    one sheet (that builder then lays ``pages = [items]``): what the scene's other sheets number by."""
    opts = options_of(options)
    check_positions(st, opts)
    if plan(st, f, _options(opts))[0].sheets == 1:
        return 1
    return len(build_kinematics_sheet(st, f, options).pages)


def build_kinematics_sheet(st: Study, f: Form, options) -> Sheet:
    """Sheet 1: everything of the kinematic analysis at the scales ``plan`` chose, in the zones of the
    composition (one sheet), or flowing over a set of sheets."""
    from graphplan.sheets.compose import keep_out, later_keep
    opts = options_of(options)
    check_positions(st, opts)
    p, nat, dr = plan(st, f, _options(opts))
    d = drawings(st, p, dr, opts.lang)
    region = field_of(f)
    P = Leaf("position plan", record=d["position"])
    D = Leaf("diagrams", record=d["diagrams"])
    V = [Leaf(f"velocity plan {q.key}", record=r) for q, r in zip(d["plans"].positions, d["velocity"])]
    A = [Leaf(f"acceleration plan {i + 1}", record=r) for i, r in enumerate(d["acceleration"])]
    tables = [Leaf(name, record=rec) for name, rec in d["tables"]]
    pages: list[list[Placed]]
    if p.sheets == 1:
        def high(w: float) -> float:
            b = note_block(d["notes"], w).bounds()
            return b[3] - b[1]
        C, groups, width = column_leaf(f, tables, p.parts, high, p.counts, p.under, p.notes, p.over)
        T, N, groups_ = split_leaves(f, tables, p.parts, high, p.counts, p.under, p.notes, p.over)
        if p.shape in SPLIT:
            groups, width = groups_, N.w
        layout = tree(p.shape, P, D, Grid(V, p.vcols, fitted=True) if V else None,
                      Grid(A, p.acols, fitted=True) if A else None, C, (T, N))
        items, tab_box, notes_at = [], None, None
        for leaf, b in arrange(layout, region):
            if leaf is C or leaf is T:          # the tables at its top right
                tab_box = b
            if leaf is C or leaf is N:          # the notes over the title block at its right
                notes_at = b[2]
            if leaf.record is not None:
                items.append(Placed(leaf.name, centred(leaf.record, b), b))
        notes_rec = note_block(d["notes"], width)
        nb = notes_rec.bounds()
        foot = keep_out(f)[3]
        notes_box = (notes_at - width, foot, notes_at, foot + nb[3] - nb[1])
        items.append(Placed("notes", top_left(notes_rec, notes_box), notes_box))
        items += place_tables(groups, tab_box[2], tab_box[3], p.under, p.over)
        pages = [items]
    else:
        notes_rec = set_notes(d["notes"], p.notes)
        rows = set_rows(P, D, V, A, set_tail(tables, Leaf("notes", record=notes_rec), p.stacked, p.beside),
                        region[2] - region[0], p.after)
        laid = flow(rows, region, keep_out(f), later=later_keep(f), ragged=True)
        if laid is None:
            raise said_error(GraphplanError, "sh drawing larger", None, None, form=f.name, option="--format")
        pages = [[Placed(leaf.name, centred(leaf.record, b), b) for leaf, b in page if leaf.record is not None]
                 for page in laid]
    tf = fields(st, opts.lang, drawing_scale(p.mu["position"], opts.lang))
    return compose(f, pages, tf, opts.lang, f"{title_in(st, opts.lang)} — {tf['subtitle']}")
