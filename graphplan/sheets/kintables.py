"""The kinematics sheet's tables and notes (seeds 000, 002 and 004), numbered 1, 2, 3 … in reading
order: table 1 the plans' velocities at every position, then one table per acceleration plan (2, 3 …),
then the links' dimensions, the lab's s, v, a at its chosen positions and the diagrams read at every
position beside the plans (seed 002, step 11) — each error past the lab's 5 % marked and footnoted with its cause —
and the notes' lines (mobility, structure, scales, precision, the largest errors, the signs). The
composition that places them is sheets/kinematics.py (sheets/kinlayout.py the arithmetic)."""
from __future__ import annotations

import re

from graphplan.exact.positions import Study
from graphplan.graphic.diagrams import judged_pct
from graphplan.graphic.record import Record, text_width
from graphplan.report.plans import acceleration_cells, places, rate_step, step_decimals  # noqa: F401  (the terminal's own, one rule)
from graphplan.sheets.compose import lines_of, number, percent
from graphplan.sheets.form import enlarged, table
from graphplan.util.markup import escape, subscripted
from graphplan.util.words import fixed, num, pair_kind, unit, word

SHORT_MM = 20.0    # the notes' second figure: errors of vectors drawn at least this long

def _symbol(key: str, letter: str = "v", e: dict | None = None) -> str:
    """A JSON key as the lab writes the quantity (markup): B → v_B, BA → v_BA, n_BA → a^n_BA,
    t_BA → a^τ_BA, k_A3A2 → a^k_A3A2, r_A3A2 → a^r_A3A2; omega_O2B → ω_3 by the link's number its
    entry ``e`` carries (``link_number``), as the lab writes ω3, ε3 (else by the name, ω_O2B)."""
    for prefix, sym in (("omega_", "ω"), ("epsilon_", "ε")):
        if key.startswith(prefix):
            n = (e or {}).get("link_number")
            return f"{sym}_{{{n if n is not None else key[len(prefix):]}}}"
    head, _, rest = key.partition("_")
    marks = {"n": "n", "t": "τ", "k": "k", "r": "r"}
    if rest and head in marks:
        return f"{letter}^{marks[head]}_{{{rest}}}"
    return f"{letter}_{{{key}}}"


# -- tables ------------------------------------------------------------------------------------

RELATIVE = re.compile(r"[A-Z][a-z0-9_]*[A-Z][a-z0-9_]*")    # a relative velocity's key: "CB", "A3A2"
CENTRE = re.compile(r"S\d*")      # a centre of mass's key: "S3"


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
        # a relative velocity is kept though its column equals a point's (review 56 #6: a toggle's
        # v_CB = v_B at every position, O2B = BC, was left out while ω4 stood in the table)
        if all(c in ("0", "—") for c in cells) or (cells in seen and not RELATIVE.fullmatch(key)):
            continue
        seen.append(cells)
        kept.append(key)
    return kept


def velocity_twins(doc: dict, precision: float) -> dict[str, list[str]]:
    """The ω columns ``velocity_columns`` leaves out as equal to a kept one, by the kept key: a
    block's ω equals its slotted link's (ω4 = ω5 of a stone in a rocking coulisse, as it turns with
    it), so the kept column is headed by both — the diagrams and Table 2 name the slotted link's
    (ω5, ε5), the table must not drop it for the stone's. So too a centre of mass whose velocity
    equals a kept point's (v_C = v_S3 of a yoke, which translates: review 57 #5 — Tables 2/3 give
    a_S3 and the force sheet uses it, Table 1 must not drop it)."""
    kept = velocity_columns(doc, precision)
    cells = lambda key: tuple(_cell(pos["velocity"].get(key), precision) for pos in doc["positions"])  # noqa: E731
    out: dict[str, list[str]] = {}
    keys = [k for pos in doc["positions"] for k in pos["velocity"]]
    point = lambda k: not k.startswith("omega_") and not RELATIVE.fullmatch(k)   # noqa: E731
    for key in dict.fromkeys(keys):
        if key in kept or not (key.startswith("omega_") or CENTRE.fullmatch(key)):
            continue
        kin = (lambda k: k.startswith("omega_")) if key.startswith("omega_") else point
        twin = next((k for k in kept if kin(k) and cells(k) == cells(key)), None)
        if twin is not None and not all(c in ("0", "—") for c in cells(key)):
            out.setdefault(twin, []).append(key)
    return out


def _cell(e: dict | None, precision: float, lang: str = "en") -> str:
    """A table's graphical value: the plan's reading (a vector read as 0 mm — a dead centre's
    velocity — is the number 0, as the terminal prints it); ω and ε signed by their sense
    (+ counter-clockwise, the tables' headers say so) and written to the figures of the vector they
    are read from (report.plans.figures); "—" only where there is no entry."""
    if not e:
        return "—"
    value = e.get("value")
    if value is not None and e.get("sense") == "cw":
        value = -value
    if e.get("sense") is not None:         # ω, ε: no finer than the vector they are read from
        from graphplan.report.plans import figures
        return number(value, figures(e.get("from_mm"), precision), lang=lang)
    return number(value, lang=lang)


def _signed(e: dict) -> float | None:
    """An entry's graphical value as the tables print it: ω, ε signed by their sense (+ ccw)."""
    value = e.get("value")
    return -value if value is not None and e.get("sense") == "cw" else value


def decimals(entries: list[dict | None], precision: float, most: int = 4) -> int:
    """One count of decimals for a column of values read off drawn lengths (REFERENCE: a length is
    read to the ruler's division, then multiplied by the scale): the figures the longest reading
    supports (report.plans.figures: 38.5 mm → 3, 123.5 mm → 4; ω, ε by the vector they are read
    from) at the column's largest value, and no finer than the ruler's step times the scale (μ_v =
    0.02, 0.5 mm: 0.01, two decimals). So a column writes 0.85, 0.10, 0.50 — never 0.1 beside
    0.85 — and ω2 −3.54, 0.42, −0.50 beside it."""
    values = [_signed(e) for e in entries if e]
    mms = [_length(e) for e in entries if e and _length(e)]
    mus = [abs(e["value"] / e["mm"]) for e in entries if e and e.get("sense") is None and e.get("mm") and e.get("value")]
    step = rate_step([(e.get("value"), e.get("from_mm")) for e in entries if e and e.get("sense") is not None], precision)
    return places(values, max(mms, default=None), precision, mus[0] if mus else None, most, step=step)


def written(value: float | None, d: int, lang: str) -> str:
    """A value to ``d`` decimals, trailing zeros kept, a true minus; "—" for none; a reading of
    0 mm (a dead centre's velocity: no vector drawn) the number 0, as the terminal prints it."""
    if value is not None and value == 0:
        return "0"
    return fixed(value, lang, d).replace("-", "−")


LAB_LIMIT = 5.0    # the lab's limit of an error, % (REFERENCE §1.6): a cell past it is marked
MARK = "*"


def _length(e: dict) -> float | None:
    """The drawn length an entry is read from: its own mm, or for ω, ε the relative vector's."""
    return e.get("mm") if e.get("mm") is not None else e.get("from_mm")


def why(e: dict, sym: str, pos: dict, plan: str, lang: str, precision: float = 0.5) -> str:
    """Why an entry misses the lab's 5 %: a vector drawn shorter than ``SHORT_MM`` (its ±½ division
    is a large share of it; its length as the ruler reads it, 0.5 mm — not 0.529), direction lines
    crossing at a small angle on its plan (the plan's warnings), else the ruler's precision."""
    from graphplan.graphic.draftsman import measure
    w = lambda key, **f: word(f"kin {key}", lang, **f)  # noqa: E731
    mm = _length(e)
    if mm is not None and mm < SHORT_MM:
        read = measure(mm, precision)
        text = written(read, step_decimals(precision), lang) if precision > 0 else num(mm, lang, 3)
        if e.get("mm") is not None:
            return w('why_short', sym=sym, mm=text)
        # ω or ε read from a relative vector: the lab's why — the ruler's half division is a large share
        # of it, and the intersection it is found by closes the errors of the vectors laid before it
        # (SIXBAR12's ε4 = ε5 +11,48 % off a^τ_C5O3 drawn 5.9 mm where the exact is 5.3)
        share = fixed(100.0 * 0.5 * precision / read, lang, 1) if precision > 0 and read > 0 else "—"
        return w('why_short_from', sym=sym, mm=text, share=share)
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
    """Table 1: the plans' velocities (graphical) at every position, like seed 004's table 3 (φ the
    crank's turn from position 0, as on every sheet), with
    the row's largest error; ω signed (+ counter-clockwise); a row's error past the lab's 5 % is
    marked and its footnote says which vector and why."""
    w = lambda key, **f: word(f"kin {key}", lang, **f)  # noqa: E731
    keys = velocity_columns(doc, precision)
    first = {k: next((pos["velocity"][k] for pos in doc["positions"] if k in pos["velocity"]), None) for k in keys}
    twins = velocity_twins(doc, precision)
    firsts = lambda k: next((pos["velocity"][k] for pos in doc["positions"] if k in pos["velocity"]), None)  # noqa: E731
    headed = {k: " = ".join([_symbol(k, "v", first[k])] + [_symbol(t, "v", firsts(t)) for t in twins.get(k, [])])
              for k in keys}       # ω4 = ω5: the stone's and its coulisse's one column
    head = [w('no'), "φ, °"] + [headed[k] for k in keys] + ["δ_{max}, %"]
    rows = [head]
    places = {k: decimals([pos["velocity"].get(k) for pos in doc["positions"]], precision) for k in keys}
    notes = []
    for pos in doc["positions"]:
        err = row_error(pos, keys)
        cell = percent(err, lang=lang)
        if err is not None and err > LAB_LIMIT:
            cell += MARK
            key = worst(pos, keys)
            notes.append(w('mark_row', n=pos["index"], why=why(pos["velocity"][key], _symbol(key, "v", first[key]), pos,
                                                                "velocity", lang, precision)))
        rows.append([str(pos["index"]), fixed(pos.get("turn_deg", pos["phi_deg"]), lang, 1)]
                    + [written(_signed(pos["velocity"][k]), places[k], lang) if pos["velocity"].get(k) else "—"
                       for k in keys] + [cell])
    widths = [8.0, 13.0] + [max(14.0, text_width(headed[k], 2.5) + 3) for k in keys] + [15.0]
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
    """Table n: one acceleration plan (the sheet numbers it after table 1 and the earlier plans): drawn mm, graphical value, analytic value and δ, %; ε
    signed (+ counter-clockwise); a vector read as 0 mm is 0; the graphical and the analytic value to
    the same decimals and δ worked out from them (report.plans ``acceleration_cells``); an error past
    the lab's 5 % is marked, its footnote says why. The force
    position (no index) is named by the crank's turn from position 0, as the scene gives it."""
    w = lambda key, **f: word(f"kin {key}", lang, **f)  # noqa: E731
    rows = [[w('quantity'), unit("mm", lang), w('graphical'), w('analytic'), w('error')]]
    items = list(pos.get("acceleration", {}).items())
    cells = acceleration_cells(pos, lang, precision)    # the terminal's, cell for cell; δ from the printed pair
    notes: dict = {}
    ruler = step_decimals(precision) if precision > 0 else 2
    for key, e in items:
        value, truth, delta = cells[key]
        cell = percent(delta, lang=lang)
        if delta is not None and abs(round(delta, 2)) > LAB_LIMIT:     # the printed δ past 5 %
            cell += MARK
            # one footnote for the quantities one reason covers (ε4 = ε5 of a slider and its slotted
            # lever, read off the one a^τ: "ε₄, ε₅: …", not the reason twice)
            said = why(e, "\x00", pos, "acceleration", lang, precision)
            notes.setdefault(said, []).append(_symbol(key, "a", e))
        rows.append([_symbol(key, "a", e), "—" if e.get("mm") is None else written(e["mm"], ruler, lang),
                     value, truth, cell])
    notes = [w('mark_cell', why=said.replace("\x00", ", ".join(syms))) for said, syms in notes.items()]
    if pos["index"] is not None:
        where = pos["index"]
    else:
        where = w('turn_at', turn=num(pos.get("turn_deg", pos["phi_deg"]), lang, 4),
                  phi=fixed(pos['phi_deg'], lang, 1))
    rec = table(rows, [22.0, 14.0, 20.0, 20.0, 14.0], row_h=6.0, size=2.5,
                title=w('acc_table_signed', n=n, i=where))
    return footnoted(rec, [w('mark_head')] + notes if notes else [])


def link_lengths(st: Study) -> list[tuple[str, float]]:
    """Every link's dimensions as the drawing letters them (markup: O_{1}A): the crank, each pair
    of joints on a floating link (every side of a plate ABC: AB, AC, BC), a pivoted link's arms from its pivot (a bell crank's O2B and
    O2D, not the derived BD), the frame's pivots' distances, and each fixed guide's distance from
    the crank's pivot (e, the offset; e with the guide's name where there are several)."""
    import cmath

    from graphplan.util.markup import indexed
    mech = st.mech

    def named(a: str, b: str) -> str:             # O_{1}A: the subscript closed (O_1A set "1A" low)
        def one(p: str) -> str:
            head = p.rstrip("0123456789")
            return f"{indexed(head)}_{{{p[len(head):]}}}" if head and head != p else indexed(p)
        return one(a) + one(b)
    out: list[tuple[str, float]] = [(named(mech.crank.pivot, mech.crank.pin), mech.crank.length)]
    for name, link in mech.links.items():
        if name == mech.crank.link:
            continue
        pts = [p for p in link.local if p in link.joints or p in mech.frame]
        pivot = next((p for p in pts if p in mech.frame), None)
        if pivot is not None:
            pairs = [(pivot, p) for p in pts if p != pivot]
        elif len(pts) >= 3 and not _collinear([link.local[p] for p in pts]):
            # a plate (the coupler ABC): every side — two do not fix C (review 6 #8: AC was missing)
            pairs = [(a, b) for i, a in enumerate(pts) for b in pts[i + 1:]]
        else:
            pairs = list(zip(pts, pts[1:]))
        end = free_end(link, pivot, pts)
        if end is not None:           # the slotted lever O3E: its end E carries the output, no joint there
            pairs.append((pivot, end))
        for a, b in pairs:
            d = abs(link.local[a] - link.local[b])
            if d > 0:
                out.append((named(a, b), d))
        ref = pivot if pivot is not None else (pts[0] if pts else None)
        other = next((p for p in pts if p != ref), None)
        if link.com is not None and link.com in link.local:   # the centre of mass off its link's middle
            d = abs(link.local[link.com] - link.local[ref]) if ref is not None else 0.0
            if d > 1e-12 and not any(abs(link.local[link.com] - (link.local[a] + link.local[b]) / 2) < 1e-12
                                     for a, b in pairs):
                out.append((named(ref, link.com), d))
                out += _second_side(link, ref, other, link.com, named)
        # a point of the link that is neither a joint nor its centre of mass (a plate's vertex E carrying a
        # force, its path drawn): its distances from the link's joints, two where it lies off their line —
        # what a student constructs it from (review 57 #3: the conveyor's plate ABE gave no AE, BE)
        for p in link.local:
            if p in pts or p == link.com or p == end or ref is None:
                continue
            d = abs(link.local[p] - link.local[ref])
            if d > 1e-12:
                out.append((named(ref, p), d))
                out += _second_side(link, ref, other, p, named)
    frame = [p for p in mech.frame if any(p in l.joints for l in mech.links.values())]
    for a, b in zip(frame, frame[1:]):
        d = abs(mech.frame[a] - mech.frame[b])
        if d > 0:
            out.append((named(a, b), d))
    out.extend(frame_coordinates(st))
    out.extend((label, d) for label, d, _, _ in guide_distances(st))
    return out


def _second_side(link, ref: str, other: str | None, p: str, named) -> list[tuple[str, float]]:
    """The second distance that places point ``p`` of ``link`` where it lies off the line through its
    joints ``ref`` and ``other`` (one distance leaves it on a circle: review 57 #3, AS2 = 0,153 alone
    did not place S2 = (0,15; 0,03) off AB): [(other p, length)], else []."""
    if other is None:
        return []
    a, b, z = link.local[ref], link.local[other], link.local[p]
    if abs(b - a) < 1e-12 or abs(((z - a) * (b - a).conjugate()).imag) / abs(b - a) < 1e-9:
        return []
    return [(named(other, p), abs(z - b))]


def free_end(link, pivot: str | None, pts: list[str]) -> str | None:
    """A pivoted link's free end: its point farthest from the pivot, farther than every joint and not
    its centre of mass (the slotted lever O3E's E, the link's given length), else None."""
    if pivot is None:
        return None
    reach = max((abs(link.local[p] - link.local[pivot]) for p in pts), default=0.0)
    ends = [p for p in link.local if p not in pts and p != link.com
            and abs(link.local[p] - link.local[pivot]) > reach + 1e-12]
    return max(ends, key=lambda p: abs(link.local[p] - link.local[pivot]), default=None)


def frame_coordinates(st: Study) -> list[tuple[str, float]]:
    """The frame pivots the distances alone do not place (review 12: O2 at (0,26; −0,02), O3 at
    (0,52; 0,16)): x and y from the crank's pivot of each other pivot off both axes through it —
    signed, as the scene gives them (a pivot on an axis is placed by its distance and the drawing)."""
    mech = st.mech
    origin = mech.frame.get(mech.crank.pivot)
    if origin is None:
        return []
    out = []
    for p, z in mech.frame.items():
        if p == mech.crank.pivot or not any(p in l.joints for l in mech.links.values()):
            continue
        d = z - origin
        if abs(d.real) > 1e-9 and abs(d.imag) > 1e-9:
            head = p.rstrip("0123456789")
            sub = f"{head}{p[len(head):]}" if head and head != p else p
            out += [(f"x_{{{sub}}}", d.real), (f"y_{{{sub}}}", d.imag)]
    return out


def middle_centres(st: Study) -> list[str]:
    """The centres of mass at the middle of a length Table 4 gives (S2 of AB, S5 of O3E), as the
    table's footnote names them (the others have their own rows: O2S3)."""
    from graphplan.util.markup import indexed
    out = []
    for name, link in st.mech.links.items():
        if link.com is None or link.com not in link.local:
            continue
        pts = [p for p in link.local if p in link.joints or p in st.mech.frame]
        pivot = next((p for p in pts if p in st.mech.frame), None)
        ends = pts + [e for e in [free_end(link, pivot, pts)] if e is not None]
        if any(abs(link.local[link.com] - (link.local[a] + link.local[b]) / 2) < 1e-12 and a != b
               for a in ends for b in ends):
            out.append(indexed(link.com))
    return out


def guide_distances(st: Study) -> list[tuple[str, float, object, str]]:
    """Each fixed guide's distance from a pivot, as the lab gives it: (label, m, guide, pivot). The
    guide of a slider on the crank's own rod: e, the offset from the crank's pivot; a slider driven
    by a rocker's rod (the coulisse's ram, a six-bar's): X from the rocker's pivot, as seed 000 gives
    X from O (the coulisse's Table 4 printed "e = 0,320 м", its ram guide's distance from O1,
    unexplained). With the guide's name where there are several."""
    import cmath

    from graphplan.model.mechanism import FRAME
    mech = st.mech
    if mech.frame.get(mech.crank.pivot) is None:
        return []
    guides = [g for g in mech.guides.values()
              if g.body == FRAME and any(l.slides_on == g.name for l in mech.links.values())]
    out = []
    for g in guides:
        driver = _driver_pivot(mech, g.name)
        pivot = driver or mech.crank.pivot
        u = cmath.exp(1j * g.angle)
        d = abs(((mech.frame[pivot] - g.through) * u.conjugate()).imag)   # the pivot's distance from the line
        if d <= 1e-9 and pivot != mech.crank.pivot:
            # a ram's guide through its rocker's pivot (a toggle press's ram under O2): the line is
            # still an input of the scheme — X from the crank's pivot (review 56 #6)
            pivot = mech.crank.pivot
            d = abs(((mech.frame[pivot] - g.through) * u.conjugate()).imag)
        if d > 1e-9:                                                     # an axial slider: no offset to give
            symbol = "e" if driver is None else "X"
            out.append((symbol if len(guides) == 1 else f"{symbol}_{{{g.name}}}", d, g, pivot))
    return out


def _guide_point(mech, g) -> str | None:
    """The point of the slider on the fixed guide ``g`` (the plunger's D), as the position plan letters
    it; None where only a yoke (no joint of its own) slides on it."""
    for link in mech.links.values():
        if link.slides_on == g.name and link.joints:
            return link.joints[0]
    return None


def _driver_pivot(mech, guide: str) -> str | None:
    """The frame pivot of the rocker whose rod drives the slider on ``guide`` (None: the crank's rod
    drives it, or no rocker does) — or whose own point carries the stone in a yoke's slot on it
    (kin51's own: a rocker's end C in a Scotch yoke's slot, its guide's distance "e" from O1 given
    as X from the rocker's O2)."""
    for yoke in (l for l in mech.links.values() if l.slides_on == guide and not l.joints):
        for stone in (l for l in mech.links.values() if l.slides_on == yoke.name):
            for j in stone.joints:
                for carrier in mech.links.values():
                    if carrier is not stone and j in carrier.joints and carrier.name != mech.crank.link:
                        pivot = next((p for p in carrier.joints if p in mech.frame), None)
                        if pivot is not None:
                            return pivot
    for slider in (l for l in mech.links.values() if l.slides_on == guide):
        rods = [l for j in slider.joints for l in mech.links.values() if l is not slider and j in l.joints]
        if any(mech.crank.pin in rod.joints for rod in rods):
            return None      # the crank's own rod drives it (a crank-slider whose slider drives a further
            #                  group through its pin: review 51's six-bar printed "X від O₂" of the rocker)
        for j in slider.joints:
            for rod in (l for l in mech.links.values() if l is not slider and j in l.joints):
                for k in rod.joints:
                    if k == j or k == mech.crank.pin:
                        continue
                    for carrier in mech.links.values():
                        if carrier is not rod and k in carrier.joints and carrier.name != mech.crank.link:
                            pivot = next((p for p in carrier.joints if p in mech.frame), None)
                            if pivot is not None:
                                return pivot
    return None


def _collinear(zs: list[complex], tol: float = 1e-9) -> bool:
    """Whether the points lie on one line (a bar with a point on its extension, not a plate)."""
    a = zs[0]
    b = max(zs, key=lambda z: abs(z - a))
    if abs(b - a) < tol:
        return True
    u = (b - a) / abs(b - a)
    return all(abs(((z - a) * u.conjugate()).imag) < tol * max(1.0, abs(b - a)) for z in zs)


def dimensions_table(st: Study, mu_l: float, lang: str, n: int = 3, precision: float = 0.5) -> Record:
    """Seed 000's table 2.1 / seed 002's measured dimensions: each length real (to the millimetre:
    three decimals of a metre; four in the whole column where one is given to a tenth of a millimetre — an
    offset of 12.5 mm is 0,0125, not 0,012 beside its drawn 12,5) and drawn at μl, laid off with
    the ruler (its 0.5 mm)."""
    from graphplan.graphic.draftsman import lay_off
    w = lambda key, **f: word(f"kin {key}", lang, **f)  # noqa: E731
    rows = [[w('link'), w('real'), w('drawn')]]
    ruler = step_decimals(precision) if precision > 0 else 2
    lengths = link_lengths(st)
    tenths = [v for _, v in lengths if abs(v * 1e4 - round(v * 1e4)) < 1e-6 < abs(v * 1e3 - round(v * 1e3))]
    real = 4 if tenths else 3        # a given 12.5 mm; a derived 286.36 mm stays to the millimetre
    # a rocker-driven ram's guide: X named with the pivot it is measured from ("X від O"), no footnote
    # (a line more under the table cost a press its full-size diagrams)
    # … and with the slider's point whose guide it is, as the scheme letters it (review 55 #10: a bare
    # "X від O₂" of the beam pump's plunger guide read as an unexplained Latin capital)
    froms = {label: (w('dims from point', symbol=label, pivot=_pivot_name(pivot), point=_pivot_name(point))
                     if (point := _guide_point(st.mech, g)) else w('dims from', symbol=label, pivot=_pivot_name(pivot)))
             for label, _, g, pivot in guide_distances(st) if label.startswith("X")}
    for name, length in lengths:
        rows.append([froms.get(name, name), written(length, real, lang),
                     written(lay_off(length / mu_l, precision), ruler, lang)])
    notes = []
    for label, value, kind in yoke_dimensions(st):     # a yoke's slot and its points (review 11 #2)
        if label in dict(lengths):      # a yoke with a joint: CS3 is already a link's length (review 57)
            continue
        if kind == "angle":
            deg = f"{num(value, lang)}°"
            rows.append([label, deg, deg])
        else:
            rows.append([label, written(value, real, lang), written(lay_off(value / mu_l, precision), ruler, lang)])
    for k, deg in wedge_angles(st):     # a wedge's inclined face: a given of the scheme (review 62)
        rows.append([f"α_{{{k}}}", f"{num(deg, lang)}°", f"{num(deg, lang)}°"])
        notes.append(w('dims wedge angle', n=k))
    for point, deg in guide_angles(st):     # an inclined guide's angle: an input of the scheme as its distance is
        rows.append([w('dims guide angle', point=_pivot_name(point)), f"{num(deg, lang)}°", f"{num(deg, lang)}°"])
    given = {label for label, _, _ in yoke_dimensions(st)}
    for yoke in {label.split("_")[-1] for label, _, kind in yoke_dimensions(st) if kind == "angle"}:
        k = yoke.strip("{}")     # e_k said only where its row is (a slot through D has none: kin51's own)
        # e_k measured from the yoke's own point: D of a yoke with no joint, C of one pinned there (review 57)
        ref = next((next(iter(lk.local)) for lk in st.mech.links.values() if str(lk.number) == k), "D")
        notes.append(w('dims yoke' if f"e_{{{k}}}" in given else 'dims yoke angle', n=k, d=_pivot_name(ref)))
    # the centres at their links' middles said only beside one that has its own row (review 12's O2S3):
    # where every centre is at its middle (the lab's default) the line says nothing a reader needs
    middles = middle_centres(st)
    if middles and any("S" in name for name, _ in lengths):
        notes.append(w('dims middles' if len(middles) > 1 else 'dims middle', names=", ".join(middles)))
    rec = table(rows, [18.0, 18.0, 22.0], row_h=6.0, size=2.5, title=w('dims', n=n))
    return footnoted(rec, notes)


def guide_angles(st: Study) -> list[tuple[str, float]]:
    """Each fixed guide a slider's point slides on that is neither horizontal nor vertical: (that
    point, the guide's angle to the x axis, deg in (0, 180), to 0.01°) — the scheme's input Table 3
    gives beside the guide's distance (review of stop 56: LINK56's 30° guide of D given only by
    its 0,057 m from O₂)."""
    import math

    from graphplan.model.mechanism import FRAME
    out = []
    for g in st.mech.guides.values():
        if g.body != FRAME:
            continue
        point = _guide_point(st.mech, g)
        deg = round(math.degrees(g.angle) % 180.0, 2)
        if point is None or min(deg % 90.0, 90.0 - deg % 90.0) < 1e-6:
            continue
        out.append((point, deg))
    return out


def wedge_angles(st: Study) -> list[tuple[int, float]]:
    """A wedge's given angle: a link sliding on a guide that carries the slot a block slides in and is
    no yoke (``linkshape.yoke_guide``: its slot shallower than a yoke's) — the wedge press's wedge 3,
    its inclined face at α3 to its own guide — as (the link's number, α in degrees, 0 … 90: the
    acute angle between the face and the guide, as the textbook gives a wedge's angle)."""
    import math

    from graphplan.model.linkshape import yoke_guide
    mech = st.mech
    out = []
    for name, link in mech.links.items():
        if link.slides_on is None or yoke_guide(mech, name) is not None:
            continue
        carried = [mech.guides[o.slides_on] for o in mech.links.values()
                   if o.slides_on is not None and mech.guides[o.slides_on].body == name]
        if carried:
            deg = math.degrees(carried[0].angle) % 180.0
            out.append((link.number, round(min(deg, 180.0 - deg), 6)))
    return out


def yoke_dimensions(st: Study) -> list[tuple[str, float, str]]:
    """A yoke's given data (the Scotch yoke's link 3: no joint to measure between): its slot's angle
    to the rod's guide α (deg), the slot's distance e from its point D along the rod (to where the
    slot's line crosses the rod's axis) and each of its other points' distance from D (DS3) — as
    (label, value, "angle" | "length")."""
    import cmath
    import math

    from graphplan.model.linkshape import rod_crossing, yoke_guide
    mech = st.mech
    out = []
    for name, link in mech.links.items():
        g = yoke_guide(mech, name)
        if g is None:
            continue
        n = link.number
        ref = next(iter(link.local))
        d = link.local[ref]
        alpha = math.degrees(g.angle) % 180.0
        out.append((f"α_{{{n}}}", alpha, "angle"))
        x = rod_crossing(d, 1 + 0j, g.through, cmath.exp(1j * g.angle))
        if abs(x - d) > 1e-9:
            out.append((f"e_{{{n}}}", abs(x - d), "length"))
        for p, z in link.local.items():
            if p != ref and abs(z - d) > 1e-9:
                head = p.rstrip("0123456789")
                low = f"{head}_{{{p[len(head):]}}}" if head and head != p else p
                out.append((f"{ref}{low}", abs(z - d), "length"))
    return out


def _pivot_name(p: str) -> str:
    """A pivot as the drawing letters it (markup): O, O_{2}."""
    from graphplan.util.markup import indexed
    head = p.rstrip("0123456789")
    return f"{indexed(head)}_{{{p[len(head):]}}}" if head and head != p else indexed(p)


def lab_table(diag, lang: str, n: int = 4, precision: float = 0.5) -> Record | None:
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
    r, k_ = diag.drawn, drawn_sense(diag)
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

    # a column one count of decimals: the ordinates the ruler's, the values by the longest ordinate
    ruler = step_decimals(precision) if precision > 0 else 2
    d = {key: places([vals[key][k] for k in chosen], float(np.max(np.abs(getattr(r, key)))), precision, mu)
         for key, mu in (("s", diag.mu_s), ("v_at", diag.mu_v), ("a_at", diag.mu_a))}
    for k in chosen:
        rows.append([str(diag.position[k]), fixed(float(diag.turn[k]) % 360.0, lang, 1),
                     written(r.s[k], ruler, lang), written(k_ * vals["s"][k], d["s"], lang),
                     written(r.v_at[k], ruler, lang), written(k_ * vals["v_at"][k], d["v_at"], lang),
                     pct("v_at", ev, k, r.v_at[k], v_),
                     written(r.a_at[k], ruler, lang), written(k_ * vals["a_at"][k], d["a_at"], lang),
                     pct("a_at", ea, k, r.a_at[k], a_)])
    rec = table(rows, [9.0, 13.0, 14.0, 16.0, 14.0, 16.0, 14.0, 14.0, 18.0, 14.0], row_h=6.0, size=2.5,
                title=w('lab', n=n))
    said = [w('mark_head')] + notes if notes else []
    return footnoted(rec, said)


def _plan_value(doc_pos: dict | None, key: str, truth: float) -> float | None:
    """The output's value on a position's plan: a link's ω or ε signed by its sense (+
    counter-clockwise), a point's vector along its guide signed as its direction on the plan (the
    analytic value's: the plan's vector points the same way wherever it is read at all)."""
    e = (doc_pos or {}).get(key)
    if not e or e.get("value") is None:
        return None
    if e.get("sense") is not None:
        return -e["value"] if e["sense"] == "cw" else e["value"]
    return e["value"] if truth >= 0 else -e["value"]


def diagram_readings(diag, doc: dict) -> list[dict]:
    """Seed 002's step 11: s, v, a read off the diagrams at each position of the plans (the
    values the diagrams' ordinates give, as ``Diagrams.values``), beside the plans' v (Table 1) and
    a (the acceleration plans, where drawn), the exact s, v, a (the analytic solver's, the truth δ is
    of) and δ, % of the diagrams' readings against them as the lab's 5 % judges them
    (graphic.diagrams.judged_pct)."""
    vals, errs = diag.values(), diag.position_errors()
    out_kind, name = diag.output.kind, diag.output.name
    vkey, akey = (name, name) if out_kind == "slide" else (f"omega_{name}", f"epsilon_{name}")
    by_index = {pos["index"]: pos for pos in doc["positions"] if pos.get("index") is not None}
    rows = []
    for i, k in enumerate(diag.at_positions):
        n = diag.position[k]
        pos = by_index.get(n, {})
        rows.append({"position": n, "s": float(vals["s"][k]), "v": float(vals["v_at"][k]),
                     "a": float(vals["a_at"][k]),
                     "s_exact": float(diag.truth["s"][k]), "v_exact": float(diag.truth["v_at"][k]),
                     "a_exact": float(diag.truth["a_at"][k]),
                     "v_plan": _plan_value(pos.get("velocity"), vkey, float(diag.truth["v_at"][k])),
                     "a_plan": _plan_value(pos.get("acceleration"), akey, float(diag.truth["a_at"][k])),
                     "delta_s": float(errs["s"][i]), "delta_v": float(errs["v_at"][i]),
                     "delta_a": float(errs["a_at"][i])})
    return rows


def printed_frame(row: dict, k: int, maxima: dict) -> dict:
    """A row of ``diagram_readings`` as Table 4 prints it: s, v, a (the diagram's, the plans', the
    exact) times the diagrams' sense ``k`` (``drawn_sense``), and δ judged again of the printed
    pair (``judged_pct``). δ of its own exact value, 100·(g − e)/e, is the same in either frame;
    δ of |max|, 100·(g − e)/|max|, changes its sign with the pair (review 54 #1: a_E −1,30 vs
    −0,75 was printed +3,68 — the plans' frame's δ beside the diagrams' values)."""
    out = {key: (k * value + 0.0 if key[0] in "sva" and value is not None else value)
           for key, value in row.items()}
    for q, big in (("s", "s"), ("v", "v"), ("a", "a")):
        out[f"delta_{q}"] = float(judged_pct(out[q], out[f"{q}_exact"], maxima[big]))
    return out


READINGS_COLUMNS = 12    # positions a row of the readings table holds (more: the next rows under it)


def printed_readings(diag, doc: dict, lang: str, precision: float = 0.5) -> list[dict]:
    """Table n's columns as printed: a position's cells (keys of ``diagram_readings``, in the
    diagrams' sense, ``printed_frame``) written to their row's decimals, and δ_v, δ_a (floats; None
    where the exact value prints as zero: "—") of the PRINTED pair, as Tables 1–2 give theirs (a
    reader's check, review 54 #1): 100·(g − e)/e, or 100·(g − e)/|max| where |exact| < 10 % of
    the cycle's |max| (``judged_pct``'s choice, of the unrounded exact value)."""
    import numpy as np

    from graphplan.graphic.diagrams import MEANINGFUL
    k_ = drawn_sense(diag)
    read = [printed_frame(row, k_, diag.maxima) for row in diagram_readings(diag, doc)]
    # one count of decimals a row: the diagram's values by its longest ordinate and its scale, the
    # plans' by their vectors (``decimals``)
    out_kind, name = diag.output.kind, diag.output.name
    vkey, akey = (name, name) if out_kind == "slide" else (f"omega_{name}", f"epsilon_{name}")
    d = {key: places([r[key] for r in read], float(np.max(np.abs(getattr(diag.drawn, ordinate)))), precision, mu)
         for key, ordinate, mu in (("s", "s", diag.mu_s), ("v", "v_at", diag.mu_v), ("a", "a_at", diag.mu_a))}
    d["v_plan"] = decimals([pos["velocity"].get(vkey) for pos in doc["positions"]], precision)
    d["a_plan"] = decimals([pos.get("acceleration", {}).get(akey) for pos in doc["positions"]], precision)
    # a plan's row is compared with the diagram's row over it: both to the coarser count (review 7
    # #17: a_D −10,6 over the plan's 2,77 — a column written to one count of decimals)
    for plan, own in (("v_plan", "v"), ("a_plan", "a")):
        if any(r[plan] for r in read):
            d[plan] = d[own] = min(d[plan], d[own])
    for own in ("s", "v", "a"):          # the exact row to its reading's decimals: like with like
        d[f"{own}_exact"] = d[own]

    def cell(r: dict, key: str) -> str:
        """A reading in its row's decimals — a 0 mm ordinate too (0,0 beside −10,6, not a bare 0:
        review 7 #17), no sign on a zero."""
        if r[key] is None:
            return "—"
        if round(r[key], d[key]) == 0:
            return fixed(0.0, lang, d[key])
        return written(r[key], d[key], lang)

    def value(c: str) -> float:
        return float(c.replace(",", ".").replace("−", "-"))

    out = []
    for r in read:
        row = {"position": r["position"]} | {key: cell(r, key) for key in
                                             ("s", "s_exact", "v", "v_plan", "v_exact", "a", "a_plan", "a_exact")}
        for q in ("v", "a"):
            g, e = row[q], row[f"{q}_exact"]
            if e == "—" or value(e) == 0.0:       # δ of a zero is not computed (review 53 #9)
                row[f"delta_{q}"] = None
                continue
            big = float(diag.maxima[q])
            own = abs(r[f"{q}_exact"]) >= MEANINGFUL * big
            ref = value(e) if own else big
            row[f"delta_{q}"] = 100.0 * (value(g) - value(e)) / ref + 0.0
            if not own:       # the |max| it is of, to the row's decimals (the footnote gives it)
                row[f"max_{q}"] = fixed(big, lang, d[q])
        out.append(row)
    return out


def readings_table(diag, doc: dict, lang: str, n: int, precision: float = 0.5) -> Record:
    """Table n: s, v, a read off the diagrams at the positions (``diagram_readings``), the plans'
    v and a under them, the exact values under each quantity (review 13 #17: δ "of the exact value"
    must be checkable from the sheet, as Tables 2–3 print their analytic column), δ, % of the
    printed pair (``printed_readings``); a δ past the lab's 5 % marked (the notes say why). The
    positions run across (as the lab's protocol tables do: short, to stand in the tables' column),
    ``READINGS_COLUMNS`` a block, the blocks one under another."""
    w = lambda key, **f: word(f"kin {key}", lang, **f)  # noqa: E731
    s_, v_, a_ = (f"{sym}_{{{diag.sub}}}" for sym in diag.symbols)
    units = ("m", "m/s", "m/s²") if diag.unit == "m" else ("rad", "rad/s", "rad/s²")
    us, uv, ua = (unit(u, lang) for u in units)
    plans, exact = w('readings_plan'), w('readings_exact')
    # a link drawn + clockwise (``drawn_sense`` −1) against the tables' + counter-clockwise: its rows
    # headed −φ5, −ω5, −ε5, so the table reads right on its own beside Tables 1–3 (review 55 #5: ω5
    # −2,36 in Table 1 and 2,36 here, a note apart)
    # (ψ, the turn from the extreme position, is the diagrams' own — no table of the plans gives it;
    # a link turning round keeps the notes' −φ)
    neg = "−" if drawn_sense(diag) < 0 and diag.output.kind != "slide" else ""
    neg_s = neg if diag.symbols[0] != "ψ" else ""
    heads = [w('no'), f"{neg_s}{s_}, {us}", exact, f"{neg}{v_}, {uv}", plans, exact, f"δ_{{{diag.symbols[1]}}}, %",
             f"{neg}{a_}, {ua}", plans, exact, f"δ_{{{diag.symbols[2]}}}, %"]
    marked = False

    def pct(e: float | None) -> str:
        """δ, % of a reading — "—" where the exact value is printed as zero (the sheet's rule, as
        Tables 1–2: δ of a zero is not computed; an extreme position's v = 0, review 53 #9)."""
        nonlocal marked
        if e is None:
            return "—"
        cell = percent(e, lang=lang)
        if abs(round(e, 2)) > LAB_LIMIT:       # the printed δ past 5 %
            marked = True
            cell += MARK
        return cell
    k_ = drawn_sense(diag)
    out_kind = diag.output.kind
    got = printed_readings(diag, doc, lang, precision)
    cols = [[str(r["position"]), r["s"], r["s_exact"], r["v"], r["v_plan"], r["v_exact"], pct(r["delta_v"]),
             r["a"], r["a_plan"], r["a_exact"], pct(r["delta_a"])] for r in got]
    # the |max| a δ is of where one is (review 54 #1: δ of |max| checkable from the sheet)
    tops = [f"{sym}_{{{diag.sub}}}: {top} {u}" for q, sym, u in (("v", diag.symbols[1], uv), ("a", diag.symbols[2], ua))
            if (top := next((r[f"max_{q}"] for r in got if f"max_{q}" in r), None))]
    rec: Record | None = None
    y = 0.0
    for start in range(0, len(cols), READINGS_COLUMNS):
        block = cols[start:start + READINGS_COLUMNS]
        rows = [[heads[i]] + [c[i] for c in block] for i in range(len(heads))]
        part = table(rows, [20.0] + [11.0] * len(block), row_h=5.0, size=2.5,
                     title=w("readings", n=n) if rec is None else "")
        if rec is None:
            rec = part
        else:
            b, top = rec.bounds(), part.bounds()[3]
            rec.extend(part.moved(0.0, b[1] - 3.0 - top))
    assert rec is not None
    said = [w('readings_delta') + (w('readings_max', tops=", ".join(tops)) if tops else "")
            + (w('readings_mark') if marked else "")]
    if k_ < 0:     # the diagrams' sense against the plans' (review 53 #10: ω5 −1,38 in Table 1, +1,38 here)
        m = sum(1 for pos in doc["positions"] if pos.get("acceleration"))
        t = "1" if m == 0 else "1,\u00a02" if m == 1 else f"1–{1 + m}"
        sym = diag.symbols[0] if diag.symbols[0] == "ψ" else f"−{diag.symbols[0]}"
        said.append(w('readings_signs_back', t=t) if out_kind == "slide"
                    else w('readings_signs_cw', sym=sym, n=diag.sub, t=t))
    return footnoted(rec, said)


def phi_convention(phi0: float, lang: str) -> str:
    """The one meaning of φ on every sheet (the lab's, seed 000's φ_8 = 200°): the crank's turn from
    position 0 in its sense of rotation; the crank angle of position 0 from the x axis beside it."""
    return word("sheet phi", lang, phi0=fixed(phi0 % 360.0, lang, 1))


def notes(st: Study, scales: list[str], extra: list[str], lang: str) -> Record:
    """The structural formula, the mobility, the scale coefficients and what φ means as lines of
    text."""
    w = lambda key, **f: word(f"kin {key}", lang, **f)  # noqa: E731
    s = st.structure
    lines = [f"{w('mobility')}: W = 3n − 2p_5 − p_4 = 3·{s.n} − 2·{s.p5} − {s.p4} = {s.mobility}",
             f"{w('structure')}: "     # each group once, with its kind: I(0-1) → II(2-3) ВВВ
             + s.written(s.crank, lambda d: f"{d.label} {pair_kind(d.kind, lang)}"),
             f"{w('scales')}: " + "; ".join(scales), phi_convention(st.phi0, lang)] + extra
    rec = Record("notes")
    for k, line in enumerate(lines):
        rec.label((0.0, -7.0 * k), line, size=3.5, layer="labels")
    return rec


def title_in(st: Study, lang: str) -> str:
    """The scene's title in the sheet's language: ``title_en`` on an English sheet where the scene
    gives it (the title block and the SVG's <title> alike), else ``title`` (romanised on an English
    sheet: util/romanize.py)."""
    from graphplan.util.romanize import scene_text
    meta = st.mech.task.meta
    if "title" not in meta and "title_en" not in meta:           # a scene without a title: the word in the sheet's language
        return "Механізм" if lang == "uk" else "Mechanism"
    return scene_text(meta, "title", lang, st.mech.title)


def fields(st: Study, lang: str, scale: str, sheet_no: int = 1, sheets: int = 1,
           subtitle: str | None = None) -> dict[str, str]:
    """The title block's fields from the scene's title and [sheet] table: the organisation's field
    carries the organisation and the student's group ("НУБіП України, гр. МБ-21")."""
    meta = st.mech.task.meta
    title = title_in(st, lang)
    from graphplan.sheets.compose import organisation, sheet_field
    org = organisation(meta, lang)
    from graphplan.util.romanize import scene_text
    return {"designation": escape(scene_text(meta, "designation", lang)), "title": escape(title),
            "student": escape(sheet_field(meta, "student", lang)), "teacher": escape(sheet_field(meta, "teacher", lang)),
            "organisation": escape(org),
            "scale": scale, "sheet": str(sheet_no), "sheets": str(sheets),
            "subtitle": subtitle or word("kin subtitle", lang)}


def drawn_sense(diag) -> int:
    """How the sheet writes the diagrams' quantities against the plans' signs: the displacement from
    the extreme position 0 as the diagram draws it, ≥ 0 on the way out (seed 002's s from B_0; a
    rocker's ψ likewise), its v, a (ω, ε) + in the sense it grows — ``Diagrams.sign`` times the
    value signed along the guide (counter-clockwise for an angle), as the diagram's ordinates read
    (mm · μ). +1 where the two agree."""
    return diag.sign


def sign_note(st: Study, diag, lang: str) -> str:
    """One sign convention, said on the sheet: s, v, a are signed along the output's guide
    everywhere, the diagrams drawn so the stroke from position 0 rises (for some outputs mirrored);
    a link's φ (from position 0), ω, ε counter-clockwise, a rocker's diagrams with the tables' sign
    (a link turning clockwise round: mirrored, said with −φ)."""
    w = lambda key, **f: word(f"kin {key}", lang, **f)  # noqa: E731
    out = st.output
    if out.kind == "slide":
        import math
        from graphplan.exact.positions import point_slider
        guide = st.mech.guides[st.mech.links[point_slider(st.mech, out.name)].slides_on]
        said = f"{escape(guide.title(lang))} ({num(math.degrees(guide.angle) % 360, lang)}°)"
        return w('signs_back' if drawn_sense(diag) < 0 else 'signs', guide=said)
    n, s = diag.sub, diag.symbols[0]          # φ, or ψ for a rocker's angle
    return w('signs_link_cw' if drawn_sense(diag) < 0 else 'signs_link', link=subscripted(out.name), n=n, sym=s)


def table_errors(doc: dict, precision: float, shortest: float) -> list[float]:
    """Every |δ| the tables 1 and 2 print (velocities; accelerations the ruler read, δ from the
    printed pair as Table 2 gives it), of vectors at least ``shortest`` mm long — ω and ε by the
    relative vector they are read from."""
    out = []
    keys = velocity_columns(doc, precision)
    for pos in doc["positions"]:
        e = row_error(pos, keys, shortest)
        if e is not None:
            out.append(e)
        cells = acceleration_cells(pos, "en", precision) if pos.get("acceleration") else {}
        for key, a in pos.get("acceleration", {}).items():
            mm = _length(a)
            if not judged(a) or (mm is not None and (mm < precision or mm < shortest)):
                continue
            printed = cells[key][2]      # δ as Table 2 prints it, from the printed pair (a reader's check)
            out.append(abs(printed if printed is not None else a["error_pct"]))
    return out



def sheet_tables(st: Study, plans, diag, lang: str, p: float, factor: float) -> list[tuple[str, Record]]:
    """The sheet's tables in reading order, numbered 1, 2, 3 … consecutively (``table_numbers``):
    the velocities, one table per acceleration plan, the dimensions, the lab's s, v, a (a lab of at
    most 8 positions)."""
    from graphplan.report.plans import plans_json
    doc = plans_json(plans)
    out = [("velocity table", velocity_table(doc, lang, p))]
    n = 0
    for q, pos in zip(plans.positions, doc["positions"]):
        if q.acceleration is not None:
            n += 1
            out.append((f"acceleration table {n}", acceleration_table(pos, 1 + n, lang, p)))
    out.append(("dimensions table", dimensions_table(st, plans.mu_l, lang, 2 + n, p)))
    if st.mech.task.count <= 8:
        lab = lab_table(diag, lang, 3 + n, p)
        if lab is not None:
            out.append(("lab table", lab))
    out.append(("diagram readings table", readings_table(diag, doc, lang, len(out) + 1, p)))
    return [(name, enlarged(rec, factor)) for name, rec in out]


def readings_number(st: Study, plans, diag) -> int:
    """The number of the diagrams' readings table (``sheet_tables``: the last)."""
    m = sum(q.acceleration is not None for q in plans.positions)
    lab = st.mech.task.count <= 8 and any(p in diag.chosen for p in diag.position)
    return 3 + m + int(lab)


def plan_tables(plans) -> str:
    """The numbers of the tables of the plans' errors (velocities 1, accelerations 2 … 1 + m):
    "1", "1, 2" or "1–4", as the notes cite them."""
    m = sum(q.acceleration is not None for q in plans.positions)
    return "1" if m == 0 else "1, 2" if m == 1 else f"1–{1 + m}"


def short_poles(st: Study, doc: dict, lang: str, precision: float) -> list[str]:
    """Where the crank pin's p_v a (π a) is drawn under LEGIBLE_MM because a plan's longest vector is
    already ``kinlayout.PLAN_MM`` long (the plans read by their size: a rocker's end swinging fast
    beside a short crank), the note says so — which plan bounds the scale and how long its vector
    would be at p_v a = 40 mm (review 56 #5: an A3 set drew p_v a = 35 mm, p_v e of plan 10 160 mm,
    where docs/scenes.md promises 40 mm wherever the sheet has the room)."""
    from graphplan.graphic.draftsman import measure
    from graphplan.graphic.scales import LEGIBLE_MM, LEGIBLE_READS
    from graphplan.report.replay import seg
    from graphplan.sheets.kinlayout import PLAN_MM
    from graphplan.util.markup import indexed
    pin = st.mech.crank.pin
    out = []
    for kind, pole, kind_w in (("velocity", "p_v", ("швидкостей", "velocity")),
                               ("acceleration", "π", ("прискорень", "acceleration"))):
        rows = [(pos["index"], pos[kind]) for pos in doc["positions"] if pos.get(kind)]
        pins = [e[pin]["mm"] for _, e in rows if e.get(pin, {}).get("mm")]
        if not pins or pins[0] >= LEGIBLE_MM - LEGIBLE_READS:
            continue
        n, key, longest = max(((i, k, e["mm"]) for i, ents in rows for k, e in ents.items()
                               if e.get("mm") is not None and e.get("sense") is None and not RELATIVE.fullmatch(k)),
                              key=lambda t: t[2])
        if longest < PLAN_MM:
            continue
        at = longest * LEGIBLE_MM / pins[0]
        ruler = step_decimals(precision) if precision > 0 else 1
        out.append(word("kin short_pole", lang, seg=seg(pole, indexed(pin.lower())), mm=fixed(pins[0], lang, ruler),
                        least=num(LEGIBLE_MM, lang), kind=kind_w[lang != "uk"], vec=seg(pole, indexed(key.lower())),
                        n=n, long=fixed(longest, lang, ruler), at=fixed(measure(at, precision), lang, ruler)))
    return out


def phase_shift(st: Study, a: str, b: str, grid: int = 720) -> float | None:
    """The crank turn Δ (deg, in (−180, 180]) with t_b(φ) − t̄_b = ±(t_a(φ + Δ) − t̄_a) over the whole cycle
    (φ counted in the crank's sense): ``b`` slides as ``a`` does, Δ earlier (Δ > 0) or −Δ later — a
    V-twin's second piston (review 58: the diagrams drawn for B only, the sheet silent on C); None
    when no turn on a ``grid``-step circle makes the two strokes one (different rods, offsets)."""
    import numpy as np
    turn = np.arange(grid) * 360.0 / grid
    kin = st.solve(np.mod(st.phi0 + turn * np.sign(st.mech.omega1), 360.0))
    ta, tb = (np.asarray(kin.slides[n].t, dtype=float) for n in (a, b))
    ta, tb = ta - ta.mean(), tb - tb.mean()
    scale = max(float(np.ptp(ta)), float(np.ptp(tb)), 1e-300)
    for k in range(grid):
        shifted = np.roll(ta, -k)                  # shifted[j] = t_a at turn j + k
        if min(np.max(np.abs(tb - shifted)), np.max(np.abs(tb + shifted))) < 1e-7 * scale:
            d = k * 360.0 / grid
            return d - 360.0 if d > 180.0 else d
    return None


def other_outputs(st: Study, plans, lang: str) -> list[str]:
    """A line for each other slider on a frame guide than the diagrams' output: whose diagrams the sheet
    draws, and where the other's motion is read — its diagrams those of the output shifted by the phase
    ``phase_shift`` finds (a V-twin's pistons), else the tables and the plans (review 58)."""
    from graphplan.exact.positions import point_slider
    from graphplan.model.mechanism import FRAME
    out = st.output
    if out.kind != "slide":
        return []
    mech = st.mech
    others = [next(iter(link.local)) for name, link in mech.links.items()
              if link.slides_on is not None and mech.guides[link.slides_on].body == FRAME
              and next(iter(link.local)) != out.name]
    lines = []
    for c in dict.fromkeys(others):
        if point_slider(mech, c) is None:
            continue
        shift = phase_shift(st, out.name, c)
        t = plan_tables(plans)
        if shift is None or abs(shift) < 1e-9:
            lines.append(word("kin other_drawn", lang, b=out.name, c=c, t=t))
        else:
            lines.append(word("kin other_lead" if shift > 0 else "kin other_lag", lang, b=out.name, c=c,
                              deg=fixed(abs(shift), lang, 0 if abs(shift - round(shift)) < 1e-9 else 1), t=t))
    return lines


def notes_lines(st: Study, plans, diag, lang: str, p: float) -> list[str]:
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
        extra.append(f"{w('max_error', t=plan_tables(plans))}: {fixed(max(every), lang, 2)} %"
                     + (f" ({w('max_error_20')}: {fixed(max(long_), lang, 2)} %)" if long_ else ""))
    extra.append(w('dash'))
    extra.append(sign_note(st, diag, lang))
    extra += short_poles(st, doc, lang, p)
    from graphplan.drawing.plans import output_point, primed, swing
    psi = swing(plans)
    if psi is not None:                  # the rocker's swing, dimensioned on the position plan (review 12 #8)
        import math
        out = output_point(plans)
        extra.append(w('swing', link=subscripted(st.output.name), deg=fixed(psi, lang, 2),
                       rad=fixed(math.radians(psi), lang, 4), a=primed(out, 1), b=primed(out, 2)))
    # the study's warnings (a block past its slotted link's end, a group near locking), as `analyze` says them
    extra += [f"{word('warnings', lang)}: {subscripted(text)}" for text in st.says(lang)]   # O₃C, O₃E
    import numpy as np
    rows = printed_readings(diag, doc, lang, p)      # the note names the δ Table n prints
    printed = {f"{q}_at": np.array([np.nan if r[f"delta_{q}"] is None else r[f"delta_{q}"] for r in rows])
               for q in ("v", "a")}
    said = sheet_notes(diag, lang, readings_number(st, plans, diag), printed)
    return lines_of(notes(st, scales, extra + said[:1] + other_outputs(st, plans, lang) + said[1:], lang))
