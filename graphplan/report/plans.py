"""`graphplan plans`: the plans' measurements as the contract's JSON, as the seeds' tables, and the
plans themselves as SVG files in true millimetres."""
from __future__ import annotations

import math

from typing import Any

from graphplan.graphic.record import Record
from graphplan.graphic.plans import NEAR_ZERO, SMALL_ANGLE_DEG, VANISH, Entry, Plan, Plans, PositionPlans
from graphplan.graphic.scales import UNITS, format_scale
from graphplan.util.markup import plain
from graphplan.util.words import column_decimals, fixed, num, pct, unit, word
from graphplan.util.romanize import scene_title

KIND_ORDER = {"point": 0, "relative": 1, "normal": 2, "tangential": 3, "coriolis": 4,
              "omega": 5, "epsilon": 6}

def ordered(plan: Plan) -> list[Entry]:
    """The mechanism's points in the scene's order, then the coincident points (A3), relative
    vectors, components (each in drawing order), and ω or ε last by link number: ε2, ε3, ε4, ε5 (review
    12: the block's ε4 = ε5 is found after the slotted link's, but the lab numbers the rows)."""
    names = plan.sc.mech.point_names()
    mech = plan.sc.mech

    def key(e: Entry) -> tuple[int, int]:
        if e.kind == "point":
            return (0, names.index(e.key)) if e.key in names else (1, 0)
        if e.kind in ("omega", "epsilon"):
            n = link_number(mech, e.key)
            return (KIND_ORDER[e.kind] + 1, n if n is not None else 10 ** 6)
        return (KIND_ORDER[e.kind] + 1, 0)
    return sorted(plan.entries.values(), key=key)


def entry_json(e: Entry, mu: float | None = None) -> dict[str, Any]:
    """One entry: mm, value, analytic, error_pct; ω and ε add their sense and ``from_mm``, the
    drawn length of the plan vector they are read from (v_BA for ω_AB, a^τ_BA for ε_AB) — the
    length a short-vector rule judges them by, the one the table's row of that vector reads (a
    closing a^τ drawn 5.9 mm where the exact is 5.3: "6,0 мм", not "5,5")."""
    out: dict[str, Any] = {}
    if e.mm is not None:
        out["mm"] = e.mm
    out["value"] = e.value
    out["analytic"] = e.analytic
    out["error_pct"] = e.error_pct
    if e.kind in ("omega", "epsilon"):
        out["sense"] = e.sense
        if e.drawn is not None:
            out["from_mm"] = e.drawn
        elif mu:
            out["from_mm"] = e.basis / mu
    return out


def position_json(plans: Plans, p: PositionPlans) -> dict[str, Any]:
    """One position: its plans' entries, the crank's turn from position 0 (``turn_deg``, in the
    crank's sense: the scene's convention), the warnings' texts and their angles by plan."""
    st = plans.study
    doc: dict[str, Any] = {"index": p.index, "phi_deg": p.phi % 360.0,
                           "turn_deg": round(float(st.from_position0(p.phi % 360.0)), 9) % 360.0, "mu_v": plans.mu_v,
                           "velocity": {e.key: entry_json(e, plans.mu_v) for e in ordered(p.velocity)}}
    if p.acceleration is not None:
        doc["mu_a"] = plans.mu_a
        doc["acceleration"] = {e.key: entry_json(e, plans.mu_a) for e in ordered(p.acceleration)}
    for plan in ("velocity", "acceleration"):       # ω, ε: the link's number (ω3), as the lab writes
        for key, entry in doc.get(plan, {}).items():
            n = link_number(st.mech, key)
            if n is not None:
                entry["link_number"] = n
    doc["warnings"] = [w.text for w in p.warnings]
    doc["warning_angles"] = [{"plan": w.plan, "group": w.group, "kind": w.kind, "angle_deg": w.angle}
                             for w in p.warnings]
    return doc


def plans_json(plans: Plans) -> dict[str, Any]:
    """The contract's ``plans --json`` document (magnitudes in SI; ω, ε with their sense)."""
    st = plans.study
    return {
        "scene": st.mech.title,
        "mu_l": plans.mu_l,
        "precision_mm": plans.precision,
        "units": dict(UNITS),
        "structure": st.structure.formula,
        "position0_phi_deg": st.phi0,
        "near_zero": {"share_of_largest": NEAR_ZERO,
                      "rule": "error_pct is null where the exact vector an entry comes from (for ω, ε: "
                              "the relative velocity or tangential acceleration) is shorter than this "
                              "share of the plan's largest vector or than one ruler division "
                              "(precision_mm × the plan's scale)"},
        "small_angle_deg": SMALL_ANGLE_DEG,
        "dead_centre_share": VANISH,
        "positions": [position_json(plans, p) for p in plans.positions],
    }


# -- tables -------------------------------------------------------------------------------------

def link_number(mech, key: str) -> int | None:
    """The number of the link an ω or ε key names (omega_O2B → 3): the lab writes ω3, ε3 — by the
    link's number, not its joints' letters; None for any other key."""
    for prefix in ("omega_", "epsilon_"):
        if key.startswith(prefix) and key[len(prefix):] in mech.links:
            return mech.links[key[len(prefix):]].number
    return None


def symbol(e: Entry, kind: str, mech=None) -> str:
    """How a quantity is written in a table: v_B, v_BA, a^n_BA, a^k_A3A2 and, with the mechanism,
    ω and ε by the link's number as the lab writes them (ω_3, ε_2; else by its name, ω_AB)."""
    letter = "v" if kind == "velocity" else "a"
    if e.kind in ("omega", "epsilon"):
        n = link_number(mech, e.key) if mech is not None else None
        sym = "ω" if e.kind == "omega" else "ε"
        return f"{sym}_{n}" if n is not None and n < 10 else f"{sym}_{{{n}}}" if n is not None \
            else sym + "_" + e.key.partition("_")[2]
    head, _, rest = e.key.partition("_")
    marks = {"n": "n", "t": "τ", "k": "k", "r": "r"}
    if rest and head in marks and e.kind in ("normal", "tangential", "coriolis", "relative"):
        return f"{letter}^{marks[head]}_{rest}"
    return f"{letter}_{e.key}"


def figures(mm: float | None, precision: float = 0.5, most: int = 4) -> int:
    """The significant figures a value derived from one drawn length supports — ω = v_BA/l_AB from
    the vector ab, ε from a^τ — the figures of the ruler's reading of that length written to the
    ruler's division (0.5 mm: 2.0 → 2, 23.0 → 3, 61.5 → 3, 123.5 → 4), at least 2 and at most
    ``most`` (what the tables print of every other value): ω is written no finer than the velocity
    it is read from. An exact ruler: ``most``."""
    if mm is None or not math.isfinite(mm) or mm <= 0 or precision <= 0:
        return most
    reading = round(abs(mm) / precision) * precision
    decimals = max(0, -math.floor(math.log10(precision) + 1e-9))     # 0.5 mm: one decimal, 42 → "42.0"
    digits = f"{reading:.{decimals}f}".replace(".", "").lstrip("0")
    return max(2, min(most, len(digits)))


def step_decimals(step: float) -> int:
    """The decimals that write a ruler's step exactly (μ·0.5 mm: 0.01 → 2, 0.0125 → 4), at most 6."""
    for d in range(7):
        if abs(round(step, d) - step) <= 1e-9 * max(1.0, abs(step)):
            return d
    return 6


def places(values, longest_mm: float | None, precision: float, mu: float | None = None, most: int = 4,
           step: float | None = None) -> int:
    """One count of decimals for a column of values read off drawn lengths: the figures of the
    longest drawn length ``longest_mm`` they are read from (``figures``) at the largest |value|, no
    finer than the ruler's step times the scale ``mu``. The sheet's tables (sheets.kintables) and
    the terminal's ω columns write with it: ω3 of the review's six-bar read from a 1 mm vector is
    0,10 ± 0,02 (half a division × μv / l), so both write 0.10, not the sheet's 0.10 beside the
    terminal's 0.096 (review 6 #9)."""
    vals = [abs(float(v)) for v in values if v is not None and math.isfinite(float(v)) and v != 0]
    if not vals:
        return 0
    figs = figures(longest_mm, precision, most) if longest_mm else most
    d = figs - 1 - math.floor(math.log10(max(vals)))
    if mu and precision > 0:
        d = min(d, step_decimals(mu * precision))
    # at least three figures for the column's typical value (review 10: v_B 0,08 beside v_S2 0,126;
    # 4,0 mm × μv 0,02 = 0,080 is as read — the product written out, a trailing figure not invented)
    d = max(0, d, column_decimals(vals, typical=True))
    # a quotient (ω = v_BA/l, ε = a^τ/l) is no product of the ruler's step: written no finer than
    # the place of its step's first figure (review 55 #9: ω4 = 0,22/0,30 printed 0,733 where the
    # ruler's division gives ±0,033 — 0,73, two decimals like ω2, ω3 beside it)
    return min(d, rate_decimals(step)) if step else d


def rate_decimals(step: float) -> int:
    """The decimals of a quotient read off the ruler whose division changes it by ``step``: the place
    of the step's first significant figure (0,033 → 2, 0,05 → 2, 0,2 → 1, 1,5 → 0)."""
    return max(0, -math.floor(math.log10(step) + 1e-12))


def rate_step(values_mm, precision: float) -> float | None:
    """The finest change one ruler division makes to a column of ω (or ε): precision × |ω| / the mm
    of the vector each is read from (ω = v/l: the reading's division is μ·precision/l), the smallest
    over the column's (value, mm) pairs; None where no pair has both."""
    steps = [precision * abs(v) / mm for v, mm in values_mm if v and mm and precision > 0]
    return min(steps) if steps else None


def rate_column(entries: list[Entry], mu: float, lang: str, precision: float = 0.5) -> list[str]:
    """A column of ω (or ε) as the sheet's tables write it: signed, one count of decimals for the
    column (``places``: the figures of its longest vector at its largest value), 0 where the vector
    was read as 0 mm."""
    longest = max((e.basis / mu for e in entries if mu and e.basis), default=None)
    step = rate_step([(signed(e), (e.drawn if e.drawn is not None else e.basis / mu if mu else None)) for e in entries],
                     precision)
    d = places([signed(e) for e in entries], longest, precision, step=step)
    return ["0" if e.value == 0 else fixed(signed(e), lang, d) for e in entries]


def signed(e: Entry) -> float:
    """ω and ε keep their sign in the tables; vectors are magnitudes."""
    return e.vector.real if e.kind in ("omega", "epsilon") else e.value


def _signed_json(e: dict, key: str = "value") -> float | None:
    """An entry's value of the JSON (``value`` or ``analytic``) signed as the tables print it: ω and
    ε + counter-clockwise."""
    v = e.get(key)
    return -v if v is not None and e.get("sense") == "cw" else v


def acceleration_cells(pos: dict[str, Any], lang: str, precision: float = 0.5) -> dict[str, tuple[str, str, float | None]]:
    """An acceleration plan's cells as the sheet's Table 2 (3 …) and the terminal both print them,
    key → (graphical, exact, δ %): the graphical and the exact value of a quantity to the same
    decimals, and δ = 100·(g − e)/e worked out from the two printed numbers, so a reader who
    recomputes δ from the table gets the printed δ (the JSON keeps the unrounded error; None where
    the vector was read as 0 mm or the printed exact value is 0). The vectors' decimals, one count
    for them all: the figures of the longest drawn vector (``places``), one more where the ruler's
    step times μ_a still writes it exactly (69,5 mm × 0,5 = 34,75 beside 34,74, not 34,8 beside
    34,74); the ε rows one count of decimals, three figures for the smallest and at most four for the
    largest (review 10: −62,55 / −13,49 / 1,42, not −62,548 / −13,49 / 1,42)."""
    items = list(pos.get("acceleration", {}).items())
    vectors = [e for _, e in items if e.get("sense") is None]
    mu = pos.get("mu_a")
    longest = max((e["mm"] for e in vectors if e.get("mm")), default=None)
    vec = places([e.get("value") for e in vectors], longest, precision, mu)
    finer = int(bool(mu and precision > 0 and step_decimals(mu * precision) > vec))
    vec += finer
    # the ε rows one count of decimals (review 10: ε2 −62,548 beside ε3 −13,49 beside ε4 1,42):
    # three figures for the smallest, four at most for the largest (util.words.column_decimals)
    rates = [e for _, e in items if e.get("sense") is not None]
    eps = column_decimals([_signed_json(e) for e in rates] + [_signed_json(e, "analytic") for e in rates])

    def text(v: float | None, d: int) -> str:
        if v is None:
            return "—"
        return "0" if round(v, d) == 0 else fixed(v, lang, d).replace("-", "−")
    out = {}
    for key, e in items:
        d = vec if e.get("sense") is None else eps
        g = "0" if e.get("value") == 0 else text(_signed_json(e), d)
        x = text(_signed_json(e, "analytic"), d)
        judged = e.get("error_pct") is not None and e.get("value") not in (0, None)
        ev, gv = (float(c.replace("−", "-").replace(",", ".")) if c != "—" else None for c in (x, g))
        delta = 100.0 * (gv - ev) / ev if judged and ev and gv is not None else None
        out[key] = (g, x, delta)
    return out


def plans_table(plans: Plans, lang: str = "uk") -> str:
    """The seeds' tables: velocities of all points at all positions (and their errors), the
    accelerations at the plan positions, ω and ε, and the warnings; in ``lang``."""
    w = lambda k_, **kw: plain(word(k_, lang, **kw))  # noqa: E731
    n = lambda v: num(v, lang)  # noqa: E731
    st = plans.study
    title = scene_title(st.mech.task.meta, st.mech.title, lang)
    lines = [f"{title} — {w('plans title')}",
             f"{w('structure')}: {st.structure.formula};  {w('ruler')} {n(plans.precision)} {unit('mm', lang)}",
             "; ".join(plain(format_scale(k, v, lang)) for k, v in plans.scales.items()), ""]
    keys = [e.key for e in ordered(plans.positions[0].velocity)]
    heads = [plain(symbol(plans.positions[0].velocity.entries[k], "velocity", st.mech)) for k in keys]
    widths = [max(8, len(h)) for h in heads]

    def row(cells: list[str]) -> str:
        return "  ".join(c.rjust(wd) for c, wd in zip(cells, [4, 7, 7] + widths))

    def turn(phi: float) -> str:
        """The sheets' φ: the crank's turn from position 0 in its sense of rotation."""
        return fixed(float(st.from_position0(phi % 360.0)) % 360.0, lang, 2)

    def label(p: PositionPlans) -> str:
        return str(p.index) if p.index is not None else "*"

    lines += [w("turn note"), "", w("velocities read"), row([w("no"), "φ, °", w("turn col")] + heads)]
    omegas = {k: rate_column([p.velocity.entries[k] for p in plans.positions], plans.mu_v, lang, plans.precision)
              for k in keys if plans.positions[0].velocity.entries[k].kind == "omega"}
    for i, p in enumerate(plans.positions):
        lines.append(row([label(p), fixed(p.phi % 360, lang, 2), turn(p.phi)] +
                         [omegas[k][i] if k in omegas else n(signed(p.velocity.entries[k])) for k in keys]))
    lines += ["", w("errors exact"), row([w("no"), "φ, °", w("turn col")] + heads)]
    for p in plans.positions:
        cells = [pct(p.velocity.entries[k].error_pct, lang) for k in keys]
        lines.append(row([label(p), fixed(p.phi % 360, lang, 2), turn(p.phi)] + cells))
    for p in plans.positions:
        acc = p.acceleration
        if acc is None:
            continue
        where_ = f"{p.index}" if p.index is not None else "*"
        lines += ["", f"{w('accelerations at')} {where_} (φ = {fixed(p.phi % 360, lang, 2)}°, "
                      f"{w('turn col').split(',')[0]} {turn(p.phi)}°), "
                      f"{plain(format_scale('mu_a', plans.mu_a, lang))}; {w('rates')}",
                  f"{w('quantity'):>12}  {unit('mm', lang):>7}  {w('plan'):>10}  {w('exact'):>10}  "
                  f"{w('error'):>9}"]
        cells = acceleration_cells(position_json(plans, p), lang, plans.precision)    # the sheet's, cell for cell
        for e in ordered(acc):
            mm = "" if e.mm is None else fixed(e.mm, lang, 1)
            value, exact, delta = cells[e.key]
            lines.append(f"{plain(symbol(e, 'acceleration', st.mech)):>12}  {mm:>7}  {value.replace('−', '-'):>10}  "
                         f"{exact.replace('−', '-'):>10}  {pct(delta, lang):>9}")
    lines += ["", w("warnings") + ":"]
    warned = False
    for p in plans.positions:
        for wn in p.warnings:
            lines.append(f"  {w('position')} {label(p)}: {plain(wn.say(lang))}")
            warned = True
    if not warned:
        lines.append("  " + w("none"))
    return "\n".join(lines) + "\n"


# -- SVG files ----------------------------------------------------------------------------------

def captioned(rec: Record, caption: str) -> Record:
    """The record with a caption line under it (5 mm lettering)."""
    out = Record(rec.title, list(rec.items), dict(rec.scales))
    x0, y0, _, _ = rec.bounds()
    out.label((x0, y0 - 10.0), caption, size=5.0)
    return out


def svg_documents(plans: Plans, lang: str = "uk") -> dict[str, str]:
    """Each plan as its own SVG in true millimetres: file name → SVG text."""
    from graphplan.drawing.svg import page_for, render
    w = lambda key: word(key, lang)  # noqa: E731
    docs: dict[str, str] = {}

    def put(name: str, rec: Record, caption: str) -> None:
        caption = caption[:1].upper() + caption[1:]
        page, wd, h = page_for(captioned(rec, caption))
        docs[name] = render(page, wd, h, plain(caption))

    from graphplan.drawing.plans import acceleration_records, position_record, velocity_records
    vel, acc = velocity_records(plans), acceleration_records(plans)
    put("positions.svg", position_record(plans),
        f"{w('position plan')}: {format_scale('mu_l', plans.mu_l, lang)}")
    for p in plans.positions:
        tag = f"{p.index:02d}" if p.index is not None else f"phi{p.phi % 360:g}"
        where_ = f"{w('position')} {p.index}" if p.index is not None else ""
        phi = fixed(p.phi % 360, lang, 1)
        put(f"velocity_{tag}.svg", vel[p.key],
            f"{w('velocity plan')}, {where_} (φ = {phi}°): {format_scale('mu_v', plans.mu_v, lang)}")
        if p.acceleration is not None:
            put(f"acceleration_{tag}.svg", acc[p.key],
                f"{w('acceleration plan')}, {where_} (φ = {phi}°): "
                f"{format_scale('mu_a', plans.mu_a, lang)}")
    return docs
