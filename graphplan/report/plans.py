"""`graphplan plans`: the plans' measurements as the contract's JSON, as the seeds' tables, and the
plans themselves as SVG files in true millimetres."""
from __future__ import annotations

from typing import Any

from graphplan.graphic.record import Record
from graphplan.graphic.plans import NEAR_ZERO, SMALL_ANGLE_DEG, VANISH, Entry, Plan, Plans, PositionPlans
from graphplan.graphic.scales import UNITS, format_scale

KIND_ORDER = {"point": 0, "relative": 1, "normal": 2, "tangential": 3, "coriolis": 4,
              "omega": 5, "epsilon": 6}

TEXT = {
    "en": {
        "title": "graphical plans", "ruler": "ruler", "exact": "exact",
        "structure": "structure", "velocities": "Velocities read off the velocity plans, m/s "
        "(ω, rad/s, + counter-clockwise)", "errors": "Errors against the exact solution, % "
        "(— where the exact value is ~0)", "accel": "Accelerations at position",
        "quantity": "quantity", "plan": "plan", "error": "error, %", "warnings": "Warnings",
        "none": "none", "position": "position", "velocity plan": "velocity plan",
        "acceleration plan": "acceleration plan", "position plan": "position plan",
        "rates": "ε, rad/s², + counter-clockwise",
    },
    "uk": {
        "title": "графічні плани", "ruler": "лінійка", "exact": "точно",
        "structure": "будова", "velocities": "Швидкості, виміряні на планах швидкостей, м/с "
        "(ω, рад/с, + проти годинникової стрілки)", "errors": "Похибки відносно точного розв'язку, % "
        "(— де точне значення ≈ 0)", "accel": "Прискорення в положенні",
        "quantity": "величина", "plan": "план", "error": "похибка, %", "warnings": "Попередження",
        "none": "немає", "position": "положення", "velocity plan": "план швидкостей",
        "acceleration plan": "план прискорень", "position plan": "план положень",
        "rates": "ε, рад/с², + проти годинникової стрілки",
    },
}


def ordered(plan: Plan) -> list[Entry]:
    """The mechanism's points in the scene's order, then the coincident points (A3), relative
    vectors, components, and ω or ε last (each in drawing order)."""
    names = plan.sc.mech.point_names()

    def key(e: Entry) -> tuple[int, int]:
        if e.kind == "point":
            return (0, names.index(e.key)) if e.key in names else (1, 0)
        return (KIND_ORDER[e.kind] + 1, 0)
    return sorted(plan.entries.values(), key=key)


def entry_json(e: Entry) -> dict[str, Any]:
    out: dict[str, Any] = {}
    if e.mm is not None:
        out["mm"] = e.mm
    out["value"] = e.value
    out["analytic"] = e.analytic
    out["error_pct"] = e.error_pct
    if e.kind in ("omega", "epsilon"):
        out["sense"] = e.sense
    return out


def position_json(plans: Plans, p: PositionPlans) -> dict[str, Any]:
    doc: dict[str, Any] = {"index": p.index, "phi_deg": p.phi % 360.0, "mu_v": plans.mu_v,
                           "velocity": {e.key: entry_json(e) for e in ordered(p.velocity)}}
    if p.acceleration is not None:
        doc["mu_a"] = plans.mu_a
        doc["acceleration"] = {e.key: entry_json(e) for e in ordered(p.acceleration)}
    doc["warnings"] = [w.text for w in p.warnings]
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

def symbol(e: Entry, kind: str) -> str:
    """How a quantity is written in a table: v_B, v_BA, ω_AB, a^n_BA, a^k_A3A2, ε_AB."""
    letter = "v" if kind == "velocity" else "a"
    if e.kind == "omega":
        return "ω_" + e.key[len("omega_"):]
    if e.kind == "epsilon":
        return "ε_" + e.key[len("epsilon_"):]
    head, _, rest = e.key.partition("_")
    marks = {"n": "n", "t": "τ", "k": "k", "r": "r"}
    if rest and head in marks and e.kind in ("normal", "tangential", "coriolis", "relative"):
        return f"{letter}^{marks[head]}_{rest}"
    return f"{letter}_{e.key}"


def signed(e: Entry) -> float:
    """ω and ε keep their sign in the tables; vectors are magnitudes."""
    return e.vector.real if e.kind in ("omega", "epsilon") else e.value


def _num(v: float) -> str:
    return f"{v:.4g}" if v != 0 else "0"


def plans_table(plans: Plans, lang: str = "en") -> str:
    """The seeds' tables: velocities of all points at all positions (and their errors), the
    accelerations at the plan positions, ω and ε, and the warnings."""
    t = TEXT.get(lang, TEXT["en"])
    st = plans.study
    title = st.mech.task.meta.get("title_en", st.mech.title) if lang == "en" else st.mech.title
    lines = [f"{title} — {t['title']}",
             f"{t['structure']}: {st.structure.formula};  {t['ruler']} {plans.precision:g} mm",
             "; ".join(format_scale(k, v) for k, v in plans.scales.items()), ""]
    keys = [e.key for e in ordered(plans.positions[0].velocity)]
    heads = [symbol(plans.positions[0].velocity.entries[k], "velocity") for k in keys]
    widths = [max(8, len(h)) for h in heads]

    def row(cells: list[str]) -> str:
        return "  ".join(c.rjust(w) for c, w in zip(cells, [4, 7] + widths))

    def label(p: PositionPlans) -> str:
        return str(p.index) if p.index is not None else "*"

    lines += [t["velocities"], row(["No", "φ, °"] + heads)]
    for p in plans.positions:
        lines.append(row([label(p), f"{p.phi % 360:.2f}"] +
                         [_num(signed(p.velocity.entries[k])) for k in keys]))
    lines += ["", t["errors"], row(["No", "φ, °"] + heads)]
    for p in plans.positions:
        cells = []
        for k in keys:
            err = p.velocity.entries[k].error_pct
            cells.append("—" if err is None else f"{err:+.2f}")
        lines.append(row([label(p), f"{p.phi % 360:.2f}"] + cells))
    for p in plans.positions:
        acc = p.acceleration
        if acc is None:
            continue
        where_ = f"{p.index}" if p.index is not None else "*"
        lines += ["", f"{t['accel']} {where_} (φ = {p.phi % 360:.2f}°), {format_scale('mu_a', plans.mu_a)}; "
                      f"{t['rates']}",
                  f"{t['quantity']:>12}  {'mm':>7}  {t['plan']:>10}  {t['exact']:>10}  {t['error']:>9}"]
        for e in ordered(acc):
            mm = "" if e.mm is None else f"{e.mm:.1f}"
            exact = e.exact.real if e.kind in ("omega", "epsilon") else e.analytic
            err = "—" if e.error_pct is None else f"{e.error_pct:+.2f}"
            lines.append(f"{symbol(e, 'acceleration'):>12}  {mm:>7}  {_num(signed(e)):>10}  "
                         f"{_num(exact):>10}  {err:>9}")
    lines += ["", t["warnings"] + ":"]
    warned = False
    for p in plans.positions:
        for w in p.warnings:
            lines.append(f"  {t['position']} {label(p)}: {w.text}")
            warned = True
    if not warned:
        lines.append("  " + t["none"])
    return "\n".join(lines) + "\n"


# -- SVG files ----------------------------------------------------------------------------------

def captioned(rec: Record, caption: str) -> Record:
    """The record with a caption line under it (5 mm lettering)."""
    out = Record(rec.title, list(rec.items), dict(rec.scales))
    x0, y0, _, _ = rec.bounds()
    out.label((x0, y0 - 10.0), caption, size=5.0)
    return out


def svg_documents(plans: Plans, lang: str = "en") -> dict[str, str]:
    """Each plan as its own SVG in true millimetres: file name → SVG text."""
    from graphplan.drawing.svg import page_for, render
    t = TEXT.get(lang, TEXT["en"])
    docs: dict[str, str] = {}

    def put(name: str, rec: Record, caption: str) -> None:
        caption = caption[:1].upper() + caption[1:]
        page, w, h = page_for(captioned(rec, caption))
        docs[name] = render(page, w, h, caption)

    from graphplan.drawing.plans import acceleration_records, position_record, velocity_records
    vel, acc = velocity_records(plans), acceleration_records(plans)
    put("positions.svg", position_record(plans),
        f"{t['position plan']}: {format_scale('mu_l', plans.mu_l)}")
    for p in plans.positions:
        tag = f"{p.index:02d}" if p.index is not None else f"phi{p.phi % 360:g}"
        where_ = f"{t['position']} {p.index}" if p.index is not None else ""
        put(f"velocity_{tag}.svg", vel[p.key],
            f"{t['velocity plan']}, {where_} (φ = {p.phi % 360:.1f}°): {format_scale('mu_v', plans.mu_v)}")
        if p.acceleration is not None:
            put(f"acceleration_{tag}.svg", acc[p.key],
                f"{t['acceleration plan']}, {where_} (φ = {p.phi % 360:.1f}°): "
                f"{format_scale('mu_a', plans.mu_a)}")
    return docs
