"""Teachers' keys for gear variants (docs/gears.md, docs/keys.md): the exact answers of one gear scene —
the pair's geometry (αw, aw, y, Δy, r, rb, rw, ra, rf, s, sa of both wheels, εα) and the train's
(the z's, u1H, every member's ω) — in the key format `check` grades: one "position" 0 holding every
quantity, so a student's long table (variant, position, quantity, value) of the geometry is graded as a
lever mechanism's is; with an A4 key sheet and a summary row of their own."""
from __future__ import annotations

from typing import Any

from graphplan.exact.gears import Solution
from graphplan.graphic.record import Record
from graphplan.model.variants import tolerance_for
from graphplan.teach.keys import FORMAT, ZERO_FRACTION
from graphplan.util.markup import escape
from graphplan.util.words import num

# the pair's quantities: name → (unit, what, the solution's value)
PAIR = {
    "alpha_w": ("°", "the operating pressure angle αw", lambda p: p.alpha_w_deg),
    "a_w": ("m", "the centre distance aw", lambda p: p.aw),
    "y": ("", "the centre distance's shift y", lambda p: p.y),
    "delta_y": ("", "the tip shortening Δy", lambda p: p.dy),
    **{f"{q}{k + 1}": ("m", f"{what} of wheel {k + 1}", (lambda p, q=q, k=k: getattr(p, q)[k]))
       for q, what in (("r", "the pitch radius r"), ("rb", "the base radius rb"), ("rw", "the rolling radius rw"),
                       ("ra", "the tip radius ra"), ("rf", "the root radius rf"),
                       ("s", "the tooth thickness s"), ("sa", "the tip thickness sa")) for k in (0, 1)},
    "eps": ("", "the contact ratio εα", lambda p: p.eps),
}


def make_gear_key(sol: Solution, *, variant: str = "", student: str = "", base: str = "",
                  overrides: dict[str, Any] | None = None, scene: dict[str, Any] | None = None,
                  tolerances=()) -> dict[str, Any]:
    """The key of one gear variant as a JSON-ready document in the lever keys' layout (``positions``
    with ``values``, ``quantities`` with units and tolerances), plus the headline answers."""
    values: dict[str, float] = {}
    meta: dict[str, tuple[str, str]] = {}
    if sol.pair is not None:
        for name, (unit, text, get) in PAIR.items():
            values[name] = float(get(sol.pair))
            meta[name] = (unit, text)
    if sol.train is not None:
        tr = sol.train
        values["u1H"] = tr.ratio
        meta["u1H"] = ("", "the train's ratio u1H")
        for k in ("2", "H"):
            values[f"omega_{k}"] = tr.omega[k]
            meta[f"omega_{k}"] = ("rad/s", f"the angular velocity of {'the planet' if k == '2' else 'the carrier'}")
    headline: dict[str, Any] = {}
    if sol.pair is not None:
        headline.update(z=list(sol.pair.pair.z), module_m=sol.pair.pair.module, x=list(sol.pair.x),
                        shifts="auto" if sol.pair.pair.shifts is None else "given")
    if sol.train is not None:
        headline.update(train_type=sol.train.train.kind, planets=sol.train.train.planets,
                        train_z=list(sol.train.z), ratio_required=sol.train.train.ratio,
                        conditions=dict(sol.train.conditions))
    warnings = (sol.pair.warnings if sol.pair else []) + (sol.train.warnings if sol.train else [])
    g = sol.gears
    return {
        "format": FORMAT, "kind": "gears", "variant": variant, "student": student, "base": base,
        "overrides": dict(overrides or {}), "title": g.title, "title_en": g.title_in("en"), **headline,
        "warnings": [en for en, _ in warnings], "warnings_uk": [uk for _, uk in warnings],
        "count": 1, "accel": [], "divisions": 0, "zero_fraction": ZERO_FRACTION,
        "quantities": {k: {"unit": u, "family": "velocity", "signed": k.startswith("omega"), "text": t,
                           "scale": abs(values[k]) or 1.0, "tolerance_pct": tolerance_for(k, *tolerances)}
                       for k, (u, t) in meta.items()},
        "positions": [{"index": 0, "phi_deg": 0.0, "turn_deg": 0.0, "values": values}],
        "diagram": [], "scene": scene,
    }


def summary_row(key: dict[str, Any]) -> dict[str, Any]:
    """One line of the group's summary: the variant's inputs and the headline answers."""
    row: dict[str, Any] = {"variant": key["variant"], "student": key["student"], "status": "ok"}
    row.update(key["overrides"])
    v = key["positions"][0]["values"]
    if "x" in key:
        row.update(x1=key["x"][0], x2=key["x"][1], alpha_w=v["alpha_w"], a_w=v["a_w"], eps=v["eps"])
    if "train_z" in key:
        row.update(train_z=" ".join(map(str, key["train_z"])), u1H=v["u1H"])
    return row


def summary_units(key: dict[str, Any]) -> dict[str, str]:
    return {"x1": "", "x2": "", "alpha_w": "°", "a_w": "m", "eps": "", "train_z": "", "u1H": ""}


def key_sheet(key: dict[str, Any], lang: str = "uk") -> Record:
    """The gear variant's A4 key sheet: the data and every quantity's exact value."""
    from graphplan.teach.keysheet import A4_PORTRAIT, EDGE, INSET, LEFT, MEDIUM, SMALL, frame, table, heading
    W, H = A4_PORTRAIT
    uk = lang == "uk"
    rec, x0, y = heading(key, lang)
    lines = []
    if "z" in key:
        lines.append(f"z = {', '.join(map(str, key['z']))}; m = {num(key['module_m'] * 1000, lang)} "
                     f"{'мм' if uk else 'mm'}; x = {', '.join(num(v, lang) for v in key['x'])}")
    if "train_z" in key:
        lines.append((f"планетарна передача типу {key['train_type']}, K = {key['planets']}: z = " if uk else
                      f"planetary train, type {key['train_type']}, K = {key['planets']}: z = ")
                     + ", ".join(map(str, key["train_z"])))
    for line in lines:
        y -= 5.5
        rec.label((x0, y), line, size=SMALL)
    mm = "мм" if uk else "mm"
    names = {"alpha_w": ("α_w", "°"), "a_w": ("a_w", mm), "y": ("y", ""), "delta_y": ("Δy", ""), "eps": ("ε_α", ""),
             "u1H": ("u_{1H}", ""), "omega_2": ("ω_2", "рад/с" if uk else "rad/s"),
             "omega_H": ("ω_H", "рад/с" if uk else "rad/s")}
    rows = []
    for name, value in key["positions"][0]["values"].items():
        if name in names:
            sym, unit = names[name]
        else:
            base, k = name[:-1], name[-1]
            sym, unit = {"r": "r", "rb": "r_b", "rw": "r_w", "ra": "r_a", "rf": "r_f", "s": "s", "sa": "s_a"}[base], mm
            sym = f"{sym}{k}" if "_" in sym else f"{sym}_{k}"
        v = value * 1000 if unit == mm else value
        rows.append([escape(name), sym, num(v, lang, 6).replace("-", "−"), unit,
                     num(key["quantities"][name]["tolerance_pct"], lang)])
    header = [["назва" if uk else "name", "", "значення" if uk else "value", "од." if uk else "unit", "±%"]]
    table(rec, x0, y - 6.0, header, rows, row_h=5.0)
    return rec
