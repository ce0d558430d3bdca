"""`graphplan dynamics`: the contract's JSON and the readable tables of the machine's dynamics —
the reduced inertia and moments per position, the flywheel by each method against the exact one,
the steady states and the motor."""
from __future__ import annotations

import re

import math
from typing import Any

import numpy as np

from graphplan.drawing.flywheel import delta_text, motor_delta, motor_omega
from graphplan.exact.dynamics import crank_angle
from graphplan.util.markup import inline
from graphplan.graphic.diagrams import LAB_LIMIT
from graphplan.graphic.chords import read
from graphplan.graphic.flywheel import over, ruler_bound
from graphplan.model.motors import catalogue, latin
from graphplan.util.words import column_decimals, decimals_column, fixed, num
from graphplan.util.romanize import scene_title


def _clean(doc: Any) -> Any:
    """−0.0 → 0.0 and non-finite → null everywhere (byte-stable JSON)."""
    if isinstance(doc, dict):
        return {k: _clean(v) for k, v in doc.items()}
    if isinstance(doc, (list, tuple)):
        return [_clean(v) for v in doc]
    if isinstance(doc, (float, np.floating)):
        v = float(doc)
        return v + 0.0 if math.isfinite(v) else None
    if isinstance(doc, np.integer):
        return int(doc)
    return doc


def _motion(m, every: int) -> dict[str, Any]:
    idx = np.arange(0, len(m.turn), every)
    return {"phi_deg": [float(v) for v in np.degrees(m.turn[idx]).round(9)],
            "omega": [float(v) for v in m.omega[idx]],
            "delta": m.delta, "omega_mean": m.mean, "omega_max": m.omega_max, "omega_min": m.omega_min,
            "closure": m.closure}


def dynamics_json(f) -> dict[str, Any]:
    """The contract's ``dynamics --json`` document (SI units; angles in degrees)."""
    dyn = f.dyn
    st = dyn.study
    c = dyn.cycle
    dr = dyn.drive
    md = c.driving
    positions = []
    exact_dt = md * f.turn - c.resistance_work(f.turn)
    motor_md = dr.moment(np.interp(f.turn, dyn.motor_motion.turn, dyn.motor_motion.omega))
    for k in range(f.divisions):
        positions.append({
            "index": k, "phi_deg": float(crank_angle(st, f.turn[k])), "turn_deg": 360.0 * k / f.divisions,
            "inertia": float(f.inertia_exact[k]), "d_inertia": float(f.d_inertia_exact[k]),
            "moment_resistance": float(f.moment_exact[k]), "moment_driving": md,
            "moment_motor": float(motor_md[k]),
            "work_resistance": float(c.resistance_work(f.turn[k])),
            "graphical": {"inertia": float(f.I[k] * f.mu_I), "moment_resistance": float(f.M[k] * f.mu_M),
                          "work_resistance": float(f.A[k] * f.mu_A), "energy": float(f.dT[k] * f.mu_T)},
            "energy": float(exact_dt[k])})
    exact = dyn.flywheel
    pct = lambda v: 100.0 * (v - exact) / exact if exact > 0 else None  # noqa: E731
    graphical = max(graphical_chain(f)[1], 0.0)   # as the notes' printed arithmetic gives it (stop 46); never < 0
    tg = f.tangent
    every = (len(dyn.motion.turn) - 1) // 360
    m = dr.motor
    a, b = m.line
    doc = {
        "scene": st.mech.title,
        "delta": dyn.delta,
        "omega_mean": dyn.omega_mean,
        "start_phi_deg": st.phi0,
        "divisions": f.divisions, "precision_mm": f.precision, "L_mm": f.L, "H_mm": f.H,
        "scales": {"mu_M": f.mu_M, "mu_phi": f.mu_phi, "mu_A": f.mu_A, "mu_T": f.mu_T, "mu_I": f.mu_I},
        "work_resistance": c.work, "moment_driving": md, "moment_driving_graphical": f.driving,
        "positions": positions,
        "equal_area_intervals": [int(k) for k in f.equal_area],
        "flywheel": {
            "needed": dyn.needs_flywheel,
            "exact": exact, "graphical": graphical, "error_pct": pct(graphical),
            "approximate": f.approximate, "approximate_error_pct": pct(f.approximate),
            "approximate_energy": {k: (v * f.mu_T if k in ("max", "min") else v) for k, v in f.energy_extremes.items()},
            "merkalov": f.merkalov, "merkalov_error_pct": pct(f.merkalov),
            "total_exact": dyn.flywheel_total, "total_graphical": f.total,
            "rotor_reduced": dr.rotor_reduced, "reducer_reduced": dr.reducer_reduced,
            "kl_mm": f.kl, "k_mm": tg["k"], "l_mm": tg["l"], "slopes": f.slopes,
            "tg_psi_max": tg["s_max"], "tg_psi_min": tg["s_min"],
            "redrawn": None if f.redrawn is None else f.redrawn.to_json(),
            "psi_max_deg": math.degrees(math.atan(tg["s_max"])), "psi_min_deg": math.degrees(math.atan(tg["s_min"])),
            "motor": dyn.motor_flywheel},
        "motion": _motion(dyn.motion, every),
        "motor": {"name": m.name, "power_kW": m.power_kW, "rpm_sync": m.rpm_sync, "rpm_rated": m.rpm_rated,
                  "omega_sync": m.omega_sync, "omega_rated": m.omega_rated, "moment_rated": m.moment_rated,
                  "moment_max": m.moment_max, "A": a, "B": b, "rotor_inertia": m.inertia,
                  "rotor_inertia_estimated": m.inertia_estimated,
                  "chosen": dr.chosen, "power_needed_kW": dr.power_needed_kW,
                  "smallest": dr.chosen and smallest_of_line(m),
                  "underpowered": dyn.underpowered,
                  "ratio": dr.ratio, "ratio_given": st.mech.drive.ratio is not None, "efficiency": dr.efficiency, "rotor_reduced": dr.rotor_reduced,
                  "flywheel": dyn.motor_flywheel,
                  "moment_peak": float(np.max(dyn.motor_motion.driving)) / (dr.ratio * dr.efficiency),
                  "motion": _motion(dyn.motor_motion, every)},
        "warnings": [en for en, _ in dyn.warnings],
    }
    # Table 2's approximate row: what the note's printed arithmetic gives (stop 46), as the graphical one
    approx = max(approximate_chain(doc), 0.0) if f.approximate is not None else None
    doc["flywheel"].update(approximate=approx, approximate_error_pct=None if approx is None else pct(approx))
    return _clean(doc)


def table_columns(doc: dict[str, Any], lang: str) -> dict[str, list[str]]:
    """Table 1's columns as the sheet and the terminal both print them, one count of decimals a
    column (``util.words.column_decimals``): φ (the crank's turn from position 0) and the crank
    angle to 0.1°, I*_m, dI*_m/dφ, the moments M*_c and M*_d to the decimals of both (one diagram,
    one μ_M), and the works and energies A_c, A_d, ΔT (graphical) and ΔT (exact) to the decimals of
    all four (one unit, the graphical beside the exact). A_d prints the printed ΔT plus the printed
    A_c (graphic.flywheel reads ΔT = A_d − A_c), so every row checks by subtraction to the digit."""
    ps = doc["positions"]
    out = {"turn": [fixed(p["turn_deg"], lang, 1) for p in ps], "phi": [fixed(p["phi_deg"], lang, 1) for p in ps],
           "inertia": decimals_column([p["inertia"] for p in ps], lang),
           "d_inertia": decimals_column([p["d_inertia"] for p in ps], lang)}
    moments = [[p["moment_resistance"] for p in ps], [p["moment_driving"] for p in ps]]
    d = column_decimals(moments[0] + moments[1])
    out["moment_resistance"], out["moment_driving"] = (decimals_column(m, lang, d) for m in moments)
    a_c = [p["graphical"]["work_resistance"] for p in ps]
    d_t = [p["graphical"]["energy"] for p in ps]
    d = energy_decimals(doc)
    a_d = [round(t, d) + round(a, d) for t, a in zip(d_t, a_c)]
    out.update(work_resistance=decimals_column(a_c, lang, d), work_driving=decimals_column(a_d, lang, d),
               energy_graphical=decimals_column(d_t, lang, d),
               energy=decimals_column([p["energy"] for p in ps], lang, d))
    out["energy_error"] = [fixed(e, lang, 1, plus=e != 0).replace("-", "−") + ("*" if abs(round(e, 1)) > LAB_LIMIT else "")
                           for e in energy_errors(doc)]
    return out


def energy_errors(doc: dict[str, Any]) -> list[float]:
    """Table 1's δ of ΔT гр., %: (ΔT гр. − ΔT)/(ΔT_max − ΔT_min)·100, the printed values (so a reader
    recomputes the printed δ) over the exact ΔT's range — the span the flywheel is sized by (a row's
    own ΔT passes through 0, where its own percent says nothing); past the lab's 5 % marked *."""
    d = energy_decimals(doc)
    ps = doc["positions"]
    gr = [round(p["graphical"]["energy"], d) for p in ps]
    ex = [round(p["energy"], d) for p in ps]
    span = max(ex) - min(ex)
    return [100.0 * (g - e) / span if span > 0 else 0.0 for g, e in zip(gr, ex)]


def chords_note(doc: dict[str, Any], lang: str) -> str:
    """The notes' line on the chords' heights and Table 1's δ of ΔT (markup): the intervals that took
    the equal-area mean ordinate (graphic.flywheel.mean_ordinates: M*_c drops or bends inside, or
    the middle ordinate misses the mean by more than the ruler's division) — those kept at the
    middle ordinate where they are fewer — and what δ is a percent of."""
    ks = list(doc.get("equal_area_intervals") or [])
    n = doc["divisions"]
    uk = lang == "uk"
    spans = lambda idx: ", ".join(f"{k}–{k + 1}" for k in idx)   # noqa: E731
    rest = [k for k in range(n) if k not in ks]
    if not ks:
        where = "ордината в середині кожного інтервалу" if uk else "each interval's middle ordinate"
    elif not rest:
        where = ("середня ордината рівних площ у кожному інтервалі" if uk else
                 "each interval's equal-area mean ordinate")
    elif len(rest) < len(ks):
        where = (f"середня ордината рівних площ, крім {spans(rest)} (там — у середині)" if uk else
                 f"the equal-area mean ordinate, but the middle one in {spans(rest)}")
    else:
        where = (f"ордината в середині, у {spans(ks)} — середня рівних площ" if uk else
                 f"middle ordinates, in {spans(ks)} the equal-area mean")
    hi, lo, span = energy_span(doc, lang)
    # the arithmetic kept on one line (a reader checks it as one): non-breaking spaces
    arith = NB.join(("=", hi, "−", _paren(lo), "=", span, "Дж" if uk else "J"))
    return (f"Висоти хорд: {where}; δ — % від ΔT_{{max}} − ΔT_{{min}} {arith}" if uk else
            f"Chord heights: {where}; δ, % of ΔT_{{max}} − ΔT_{{min}} {arith}")


def _paren(text: str) -> str:
    """A printed negative value in brackets where it is subtracted: − (−43,2)."""
    return f"({text})" if text.startswith(("−", "-")) else text


def energy_span(doc: dict[str, Any], lang: str) -> tuple[str, str, str]:
    """Table 1's δ's denominator as printed: the largest and the smallest exact ΔT of the table's
    column and their difference, to the column's decimals (``energy_errors`` divides by it)."""
    d = energy_decimals(doc)
    ex = [round(p["energy"], d) for p in doc["positions"]]
    return tuple(fixed(v, lang, d).replace("-", "−") for v in (max(ex), min(ex), max(ex) - min(ex)))


FLYWHEEL_METHODS = ("error_pct", "graphical"), ("approximate_error_pct", "approximate"), ("merkalov_error_pct", "merkalov")


def flywheel_decimals(doc: dict[str, Any]) -> int:
    """Table 2's I column to one count of decimals: four figures for its smallest value, no more
    than four for its largest (``util.words.column_decimals``; 328,3 beside 55,0, not 54,99), the
    notes' results of the flywheel's arithmetic the same."""
    fw = doc["flywheel"]
    values = [fw[k] for k in ("graphical", "approximate", "merkalov", "motor") if fw[k] > 0]
    return column_decimals(values + ([fw["exact"]] if fw["needed"] else []), least=4)


def flywheel_text(v: float, lang: str, decimals: int | None) -> str:
    """A flywheel's I as Table 2 prints it: to the column's ``decimals`` (four figures, ``sig``,
    where none is given), trailing zeros kept, a true minus."""
    return sig(v, lang) if decimals is None else fixed(v, lang, decimals).replace("-", "−")


def flywheel_errors(doc: dict[str, Any]) -> dict[str, float | None]:
    """Table 2's δ of each method, % — 100·(I − I_exact)/I_exact worked out from the two printed
    values (``flywheel_text``), so a reader who recomputes δ from the table gets the printed δ
    (84,47 against 82,63: +2,23, where the unrounded values give +2,24; the JSON keeps those). A
    method whose I (or the exact one) prints as none needed keeps its unrounded δ (or none)."""
    fw = doc["flywheel"]
    d = flywheel_decimals(doc)
    out: dict[str, float | None] = {}
    for key, method in FLYWHEEL_METHODS:
        if fw[key] is None or not (fw["needed"] and fw["exact"] > 0 and fw[method] > 0):
            out[key] = fw[key]
            continue
        e, g = (float(flywheel_text(fw[k], "en", d).replace("−", "-")) for k in ("exact", method))
        out[key] = 100.0 * (g - e) / e
    return out


def energy_decimals(doc: dict[str, Any]) -> int:
    """The decimals of Table 1's works and energies (A_c, A_d and ΔT graphical, ΔT exact): one count
    for the four columns, which the approximate flywheel's ΔT_max and ΔT_min are printed to too."""
    ps = doc["positions"]
    a_c = [p["graphical"]["work_resistance"] for p in ps]
    d_t = [p["graphical"]["energy"] for p in ps]
    return column_decimals(a_c + d_t + [t + a for t, a in zip(d_t, a_c)] + [p["energy"] for p in ps])


WORDS = {
    "uk": {"title": "Динаміка машини: {scene}", "pos": "Зведені величини в положеннях (точно; роботи й ΔT графічно, ΔT точно)",
           "res": "Маховик для δ = {delta:g} при ωm = {wm:.4g} рад/с", "method": "метод", "value": "Iм, кг·м²",
           "err": "похибка, %", "exact": "точно (рівняння руху, сталий Mд*)", "graph": "графічно (Віттенбауер)",
           "approx": "наближено (ΔTₘₐₓ гр − ΔTₘᵢₙ гр)/(ωm²δ) − I*сер − Iрот·i²", "merk": "наближено (Мерцалов)",
           "turn": "φ — кут кривошипа від осі x; пов. — поворот від положення 0 у бік обертання кривошипа; "
                   "dI*/dφ — похідна за цим поворотом",
           "motor_fl": "з двигуном (рівняння руху)", "motor": "Двигун", "chosen": "вибрано за правилом",
           "given": "заданий у сцені", "warn": "Попередження", "scales": "Масштаби",
           "u": {"rotor": "Iрот", "Nm": "Н·м", "mm": "мм", "rad": "рад", "J": "Дж", "kgm2": "кг·м²", "kW": "кВт", "rpm": "об/хв",
                 "s": "с", "steady": "усталений рух", "peak": "найбільший момент"}},
    "en": {"title": "Dynamics of the machine: {scene}", "pos": "Reduced quantities at the positions (exact; the works and ΔT graphical, ΔT exact)",
           "res": "Flywheel for δ = {delta:g} at ωm = {wm:.4g} rad/s", "method": "method", "value": "Ifl, kg·m²",
           "err": "error, %", "exact": "exact (equation of motion, constant Md*)", "graph": "graphical (Wittenbauer)",
           "approx": "approximate (ΔTmax gr − ΔTmin gr)/(ωm²δ) − I*mean − Irotor·i²", "merk": "approximate (Mertsalov)",
           "turn": "φ: the crank angle from the x axis; turn: from position 0 in the crank's sense; "
                   "dI*/dφ: the derivative along that turn",
           "motor_fl": "with the motor (equation of motion)", "motor": "Motor", "chosen": "chosen by the rule",
           "given": "given by the scene", "warn": "Warnings", "scales": "Scales",
           "u": {"rotor": "Irotor", "Nm": "N·m", "mm": "mm", "rad": "rad", "J": "J", "kgm2": "kg·m²", "kW": "kW", "rpm": "rpm",
                 "s": "s", "steady": "steady state", "peak": "peak moment"}},
}


def dynamics_table(f, lang: str = "uk") -> str:
    """The readable tables."""
    doc = dynamics_json(f)
    w = WORDS[lang]
    mech = f.dyn.study.mech
    out = [w["title"].format(scene=scene_title(mech.task.meta, mech.title, lang)), ""]
    s = doc["scales"]
    u = w["u"]
    out.append(f"{w['scales']}: μM = {s['mu_M']:g} {u['Nm']}/{u['mm']}, μφ = {s['mu_phi']:.5g} {u['rad']}/{u['mm']}, "
               f"H = {doc['H_mm']:g} {u['mm']}, {energy_scales(s['mu_A'], s['mu_T'])} {u['J']}/{u['mm']}, "
               f"μI = {s['mu_I']:g} {u['kgm2']}/{u['mm']}; Ac = {sig(doc['work_resistance'], 'en')} {u['J']}, "
               f"Md* = {sig(doc['moment_driving'], 'en')} {u['Nm']}")       # four figures, as the sheet's notes
    out += ["", w["pos"]]
    gr = "ΔT гр." if lang == "uk" else "ΔT gr."
    turn = "пов., °" if lang == "uk" else "turn, °"
    out.append(w["turn"])
    cols = table_columns(doc, lang)
    keys = ("phi", "turn", "inertia", "d_inertia", "moment_resistance", "moment_driving", "work_resistance",
            "work_driving", "energy_graphical", "energy", "energy_error")
    names = ("φ, °", turn, "I*m", "dI*/dφ", "M*c", "Md*", "Ac гр." if lang == "uk" else "Ac gr.",
             "Aд гр." if lang == "uk" else "Ad gr.", gr, "ΔT", "δ, %")
    # the sheet's Table 1 cell for cell (table_columns), each column as wide as its widest entry
    widths = [max(len(n), *(len(c) for c in cols[k])) for n, k in zip(names, keys)]
    out.append(f"{'№' if lang == 'uk' else 'No.':>3} " + " ".join(f"{n:>{wd}}" for n, wd in zip(names, widths)))
    for j, p in enumerate(doc["positions"]):
        out.append(f"{p['index']:>3} " + " ".join(f"{cols[k][j]:>{wd}}" for k, wd in zip(keys, widths)))
    out.append(f"  {_term(chords_note(doc, lang))}")
    fw = doc["flywheel"]
    fd = flywheel_decimals(doc)              # Table 2's one count of decimals
    exact = f"{flywheel_text(fw['exact'], 'en', fd):>10}" if fw["needed"] else not_needed(doc["motion"]["delta"], doc["delta"], lang)
    none = "не потрібен" if lang == "uk" else "not needed"
    val = lambda v: f"{flywheel_text(v, 'en', fd):>10}" if v > 0 else f"{none:>10}"   # noqa: E731  (J below rotor + reducer)
    errs = flywheel_errors(doc)          # Table 2's: δ from the printed values
    approx = w["approx"] + ((" − I*ред" if lang == "uk" else " − I*red") if fw["reducer_reduced"] > 0 else "")
    motor = (f"{flywheel_text(fw['motor'], 'en', fd):>10}" if fw["motor"] > 0 else
             not_needed(doc["motor"]["motion"]["delta"], doc["delta"], lang, inline(motor_delta(lang))))
    out += ["", w["res"].format(delta=doc["delta"], wm=doc["omega_mean"]),
            f"  {w['exact']:54} {exact}",
            f"  {w['graph']:54} {val(fw['graphical'])}  {_pct(errs['error_pct'])}  |kl| = {fw['kl_mm']:g} {u['mm']}, "
            f"ψmax = {fw['psi_max_deg']:.3f}°, ψmin = {fw['psi_min_deg']:.3f}°",
            f"  {approx:54} {val(fw['approximate'])}  {_pct(errs['approximate_error_pct'])}",
            f"  {w['merk']:54} {val(fw['merkalov'])}  {_pct(errs['merkalov_error_pct'])}",
            f"  {w['motor_fl']:54} {motor}",
            f"  δ = {doc['motion']['delta']:.9f}, |ω(2π) − ω(0)|/ωm = {doc['motion']['closure']:.1e}"]
    amp = amplified_note(f, lang, error_text(errs["error_pct"], lang)) if errs["error_pct"] is not None else None
    out += [f"  {_term(line)}" for line in (redrawn_note(f, lang), amp, wittenbauer_note(f, lang, fd), reducer_note(f, lang),
                                             tangents_note(f, lang), approximate_note(doc, lang, formula=True),
                                             design_note(doc, lang), motor_note(doc, lang)) if line]
    m = doc["motor"]
    ratio = "i = nн/n₁" if lang == "uk" else "i = nn/n₁"
    out += ["", f"{w['motor']}: {m['name'] if lang == 'uk' else latin(m['name'])} ({w['chosen'] if m['chosen'] else w['given']}), {m['power_kW']:g} {u['kW']}, "
            f"{m['rpm_sync']:g}/{m['rpm_rated']:g} {u['rpm']}, ωc = {m['omega_sync']:.2f}, ωn = {m['omega_rated']:.2f} "
            f"{u['rad']}/{u['s']}, Mn = {m['moment_rated']:.3f} {u['Nm']}, Mmax = {m['moment_max']:.3f} {u['Nm']}, "
            f"M = {m['A']:.4g}·ω + {m['B']:.5g}",
            f"  P = max M*c·ω₁/η = {m['power_needed_kW']:.3f} {u['kW']}; {'i' if m['ratio_given'] else ratio} = {m['ratio']:.4g}, η = {m['efficiency']:g}, "
            f"{u['rotor']}·i² = {m['rotor_reduced']:.4g} {u['kgm2']}; {u['steady']}: {inline(motor_omega(lang))} = {m['motion']['omega_mean']:.4f} "
            f"{u['rad']}/{u['s']}, {inline(motor_delta(lang))} = {m['motion']['delta']:.5f}, {u['peak']} {m['moment_peak']:.3f} {u['Nm']}"]
    said = rotor_estimate_note(doc, lang)
    if said:                                                    # a small motor's rotor: not the handbook's
        out.append(f"  {_term(said)}")
    note = _term(motor_speed_note(doc, lang))
    out.append(f"  {note[0].upper()}{note[1:]}")                # which ω_m serves what: the flywheel's above
    if f.dyn.warnings:
        out += ["", w["warn"] + ":"] + [f"  {_term(uk if lang == 'uk' else en)}" for en, uk in f.dyn.warnings]
    text = "\n".join(out) + "\n"
    # the decimal comma of the Ukrainian tables (the rows above format with Python's point)
    return re.sub(r"(?<=\d)\.(?=\d)", ",", text) if lang == "uk" else text


def _term(text: str) -> str:
    """A note's markup as the terminal prints it: plain text (util.markup.inline), plain spaces."""
    return inline(text).replace(NB, " ")


def _pct(v: float | None) -> str:
    """A method's δ as Table 2 prints it (``error_text``: two decimals, signed)."""
    return "—" if v is None else error_text(v, "en").replace("−", "-") + " %"


# -- the notes the terminal and the sheet share -----------------------------------------------------

NB = "\u00a0"     # a no-break space: a number stays on its line with its unit (the notes are wrapped)


def signed(v: float, lang: str) -> str:
    """A percent with its sign, three significant figures ("+6,71", "−0,376")."""
    return _signed(v, lang)


def _signed(v: float, lang: str) -> str:
    text = num(v, lang, 3)
    return text.replace("-", "−") if text.startswith("-") or text in ("0", "—") else "+" + text


def _errs(e: dict[str, float], lang: str) -> str:
    """"+7,09 % (M^*_д +5,94 %)": the flywheel's error, M*_d's beside it (markup)."""
    md = "M^*_д" if lang == "uk" else "M^*_d"
    parts = []
    if math.isfinite(e.get("flywheel", math.nan)):
        parts.append(f"{_signed(e['flywheel'], lang)}{NB}%")
    if math.isfinite(e.get("driving", math.nan)):
        parts.append(f"{md}{NB}{_signed(e['driving'], lang)}{NB}%")
    if len(parts) == 2:
        return f"{parts[0]} ({parts[1]})"
    return parts[0] if parts else "—"


def redrawn_note(f, lang: str, sheet: bool = False) -> str | None:
    """What graphic.flywheel.redrawn did, in one line (markup), or None where the first drawing was
    within the lab's 5 %: redrawn on more divisions (which, instead of which, the errors before and
    after); the given divisions kept (and which would be right); or nothing within the bound right.
    ``sheet``: the sheet's form states what is drawn and why (the divisions drawn and their error,
    the error the first count would give as the reason), not the search (review 54 #3)."""
    rd = f.redrawn
    if rd is None or not rd.needed or rd.ruler:    # the ruler's: ``amplified_note`` says why
        return None
    uk = lang == "uk"
    e0 = _errs(rd.before, lang)
    if not {"flywheel", "driving"} & set(over(rd.before)):     # the flywheel right, I*'s peak between divisions
        return _inertia_note(f, rd, lang, sheet)
    if rd.divisions != rd.first:
        # M*_d off: the chords' middle ordinates missed how M*_c changes inside an interval (its work);
        # else the curves ΔT(φ), I*(φ) the Wittenbauer diagram joins change inside one
        moment = "driving" in over(rd.before)
        why = (("M^*_с змінюється всередині інтервалу" if moment else "ΔT(φ) та I^*_м(φ) змінюються всередині інтервалу")
               if uk else ("M^*_c changes inside an interval" if moment else
                           "ΔT(φ) and I^*_m(φ) change inside an interval"))
        if sheet:
            n = _divisions(rd.divisions, lang)
            return (f"Діаграми побудовано на {n}: похибка графічного маховика {_errs(rd.after, lang)}; на "
                    f"{_divisions(rd.first, lang)} вона була б {e0} — понад 5{NB}% лабораторної, бо {why}"
                    f"{_short(f, lang)}" if uk else
                    f"Diagrams drawn on {n}: the graphical flywheel's error {_errs(rd.after, lang)}; on "
                    f"{_divisions(rd.first, lang)} it would be {e0}, over the 5{NB}% the lab accepts, as {why}"
                    f"{_short(f, lang)}")
        return (f"Діаграми побудовано заново на {rd.divisions} поділках замість {rd.first}: з {rd.first} графічний "
                f"маховик відхилявся на {e0} — понад 5{NB}% лабораторної, бо {why}; з {rd.divisions} — на "
                f"{_errs(rd.after, lang)}{_short(f, lang)}" if uk else
                f"Diagrams redrawn on {rd.divisions} divisions, not {rd.first}: with {rd.first} the graphical flywheel "
                f"was {e0} off — over the 5{NB}% the lab accepts, as {why}; with {rd.divisions}, {_errs(rd.after, lang)}"
                f"{_short(f, lang)}")
    if rd.given:
        src = ({"scene": "задано в сцені ([dynamics] divisions)", "option": "задано параметром --divisions"}[rd.given]
               if uk else {"scene": "given by the scene ([dynamics] divisions)",
                           "option": "given by --divisions"}[rd.given])
        if rd.better is not None:
            return (f"Кількість поділок ({rd.first}) {src}, тому діаграми не побудовано заново; на {rd.better} поділках "
                    f"графічний маховик відхилявся б на {_errs(rd.better_errors, lang)}" if uk else
                    f"The {rd.first} divisions are {src}, so the diagrams are not redrawn; on {rd.better} divisions "
                    f"the graphical flywheel would be {_errs(rd.better_errors, lang)} off")
        return (f"Кількість поділок ({rd.first}) {src}; жодна більша (до 360) не дає похибки в межах 5{NB}%" if uk else
                f"The {rd.first} divisions are {src}; no more divisions (up to 360) bring the error within 5{NB}%")
    if "flywheel" not in over(rd.before):      # the answer within, M*_d's ordinate too short for the ruler
        mm = NB + ("мм" if uk else "mm")
        h, p, e = num(f.Md, lang, 3), num(f.precision, lang), _signed(rd.before["driving"], lang)
        md = "M^*_д" if uk else "M^*_d"
        return (f"Графічний {md} відхиляється на {e}{NB}%: його ордината H·A_с/L = {h}{mm} закоротка для лінійки "
                f"{p}{mm}; більше поділок (кратних {rd.first}, до 360) цього не виправляє — залишено {rd.first}" if uk
                else f"The graphical {md} is {e}{NB}% off: its ordinate H·A_c/L = {h}{mm} is too short for a {p}{mm} "
                f"ruler; more divisions (multiples of {rd.first}, up to 360) do not help — the {rd.first} stay")
    return (f"Жодна побудова заново на більшій кількості поділок (кратній {rd.first}, до 360) не зводить похибку "
            f"графічного маховика, {e0}, в межі 5{NB}% лабораторної — кількість поділок залишено ({rd.first})" if uk else
            f"No redrawing on more divisions (multiples of {rd.first}, up to 360) brings the graphical flywheel's "
            f"error, {e0}, within the 5{NB}% the lab accepts: the {rd.first} divisions stay")


def rotor_estimate_note(doc: dict[str, Any], lang: str) -> str | None:
    """Where the motor's rotor inertia is the catalogue's estimate (the 4А series' 50–63 frames, whose
    rotors the handbooks do not tabulate: data/motors.toml), one sentence saying so where I_рот·i² is
    used (markup); else None."""
    m = doc["motor"]
    if not m.get("rotor_inertia_estimated"):
        return None
    value = num(m["rotor_inertia"], lang, 2)
    if lang == "uk":
        return (f"I_рот = {value} кг·м² двигуна {m['name']} — оцінка: довідники серії 4А не наводять інерції "
                f"роторів габаритів 50–63; її взято з ротора габариту 71 пропорційно M_н (ротор такого ж "
                f"радіуса, об'єм ~ M_н)")
    return (f"I_rotor = {value} kg·m² of the {latin(m['name'])} is an estimate: the 4A series' handbooks do not "
            f"list the rotors of the 50–63 frames; it is the 71 frame's rotor scaled by M_n (a rotor of a similar "
            f"radius, its volume ~ M_n)")


def amplified(f) -> dict[str, float] | None:
    """Where the flywheel is so small a part of J (rotor, reducer and flywheel together: what the
    energy–mass diagram's |kl| reads) that the ruler's reading of |kl| alone may put it past the
    lab's 5 % (graphic.flywheel ``ruler_bound``), the numbers that say so: I_fl's share of the exact
    J, %, the exact J, the ruler's share of J (precision/|kl|), %, the bound on I_fl, %, and the
    graphical J's error, % (J as the notes print it from |kl|: ``graphical_chain``) — a method's error
    on I_fl is its error on J times J/I_fl. Else None."""
    exact = f.dyn.flywheel
    if exact <= 0 or ruler_bound(f) <= LAB_LIMIT:
        return None
    J = exact + f.dyn.constant
    return {"share": 100.0 * exact / J, "J": J, "ruler": 100.0 * f.precision / abs(f.kl), "bound": ruler_bound(f),
            "graphical": 100.0 * (graphical_chain(f)[0] - J) / J}


def amplified_note(f, lang: str, e: str) -> str | None:
    """Why the graphical flywheel is ``e`` % off where the flywheel is a small part of J
    (``amplified``): its share of J, J's own error beside what the ruler alone may make of it
    (precision/|kl|), and both times J/I_fl in I_fl — the ruler's alone past the lab's 5 %, which no
    more divisions change (markup)."""
    a = amplified(f)
    if a is None:
        return None
    uk = lang == "uk"
    sym, _ = constant_terms(f.dyn.drive.rotor_reduced, f.dyn.drive.reducer_reduced, lang)
    fl, kg, mm = ("I_мах", "кг·м²", "мм") if uk else ("I_fl", "kg·m²", "mm")
    v = {"e": e, "share": num(a["share"], lang, 2), "J": sig(a["J"], lang), "p": num(f.precision, lang),
         "kl": num(abs(f.kl), lang), "r": num(a["ruler"], lang, 2), "b": num(a["bound"], lang, 2),
         "je": _signed(a["graphical"], lang)}
    v["x"] = num(100.0 / a["share"], lang, 2)
    if uk:
        return (f"графічно {v['e']}{NB}%: {fl} = J{sym} — лише {v['share']}{NB}% від J{NB}={NB}{v['J']}{NB}{kg}, "
                f"тож похибка J ({v['je']}{NB}%; сама лінійка {v['p']}{NB}{mm} на |kl|{NB}={NB}{v['kl']}{NB}{mm} — "
                f"до {v['r']}{NB}%) в {fl} помножена на J/{fl}{NB}={NB}{v['x']}: від самої лінійки до ±{v['b']}{NB}%, і більше "
                f"поділок не зведе її в межі 5{NB}%")
    return (f"graphical {v['e']}{NB}%: {fl} = J{sym} is only {v['share']}{NB}% of J{NB}={NB}{v['J']}{NB}{kg}, so "
            f"J's error ({v['je']}{NB}%; a {v['p']}{NB}{mm} ruler on |kl|{NB}={NB}{v['kl']}{NB}{mm} alone up to "
            f"{v['r']}{NB}%) is multiplied by J/{fl}{NB}={NB}{v['x']} in {fl}: up to ±{v['b']}{NB}% from the ruler alone, which no "
            f"more divisions bring within 5{NB}%")


def _divisions(n: int, lang: str) -> str:
    """"24 поділках" / "24 divisions": a count as "на …" / "on …" takes it (markup)."""
    if lang != "uk":
        return f"{n}{NB}divisions"
    from graphplan.util.words import uk_count
    return f"{n}{NB}{uk_count(n, 'поділці', 'поділках', 'поділках')}"


def _inertia_note(f, rd, lang: str, sheet: bool = False) -> str:
    """The drawing redrawn (or not) because the diagram's largest I*_m missed the exact largest by
    more than the lab's 5 % (graphic.flywheel.inertia_miss): its peak lies between two divisions,
    where the French curve through them guesses it wrong (markup)."""
    uk = lang == "uk"
    im = "I^*_м" if uk else "I^*_m"
    e0 = f"{_signed(rd.before['inertia'], lang)}{NB}%"
    exact = num(float(max(f.dyn.cycle.samples.inertia)), lang)
    unit = NB + ("кг·м²" if uk else "kg·m²")
    if rd.divisions != rd.first:
        e1 = f"{_signed(rd.after['inertia'], lang)}{NB}%"
        if sheet:
            return (f"Діаграми побудовано на {_divisions(rd.divisions, lang)}: найбільше {im} діаграми відхиляється "
                    f"від точного {exact}{unit} на {e1}; на {_divisions(rd.first, lang)} — на {e0}, понад 5{NB}% "
                    f"лабораторної (вершина між поділками)" if uk else
                    f"Diagrams drawn on {_divisions(rd.divisions, lang)}: the diagram's largest {im} misses the exact "
                    f"{exact}{unit} by {e1}; on {_divisions(rd.first, lang)}, by {e0}, over the lab's 5{NB}% (the "
                    f"peak lies between divisions)")
        return (f"Діаграми побудовано заново на {rd.divisions} поділках замість {rd.first}: з {rd.first} найбільше "
                f"{im} діаграми відхилялося від точного найбільшого {im} = {exact}{unit} на {e0} (понад 5{NB}% "
                f"лабораторної: вершина між поділками); з {rd.divisions} — на {e1}" if uk else
                f"Diagrams redrawn on {rd.divisions} divisions, not {rd.first}: with {rd.first} the diagram's largest "
                f"{im} missed the exact largest {im} = {exact}{unit} by {e0} (over the lab's 5{NB}%: the peak "
                f"lies between divisions); with {rd.divisions}, {e1}")
    if rd.given and rd.better is not None:
        e1 = f"{_signed(rd.better_errors['inertia'], lang)}{NB}%"
        return (f"Кількість поділок ({rd.first}) задано, тому діаграми не побудовано заново: найбільше {im} діаграми "
                f"відхиляється від точного {exact}{unit} на {e0}, на {rd.better} поділках — {e1}" if uk else
                f"The {rd.first} divisions are given, so the diagrams are not redrawn: the diagram's largest {im} "
                f"misses the exact {exact}{unit} by {e0}; on {rd.better} divisions, {e1}")
    return (f"Найбільше {im} діаграми відхиляється від точного {exact}{unit} на {e0}; жодна більша кількість "
            f"поділок (до 360) не зводить це в межі 5{NB}% — залишено {rd.first}" if uk else
            f"The diagram's largest {im} misses the exact {exact}{unit} by {e0}; no more divisions (up to 360) "
            f"bring it within 5{NB}%: the {rd.first} stay")


def _short(f, lang: str) -> str:
    """Where M*_d stays past the limit on the redrawn drawing: its ordinate, too short for the ruler
    at any number of divisions (markup; empty otherwise)."""
    if "driving" not in over(f.redrawn.after):
        return ""
    mm = NB + ("мм" if lang == "uk" else "mm")
    h, p = num(f.Md, lang, 3), num(f.precision, lang)
    return (f"; M^*_д лишається поза 5{NB}%: його ордината H·A_с/L = {h}{mm} закоротка для лінійки {p}{mm} за будь-якої "
            "кількості поділок" if lang == "uk" else
            f"; M^*_d stays past 5{NB}%: its ordinate H·A_c/L = {h}{mm} is too short for a {p}{mm} ruler at any number "
            "of divisions")


PROTRACTOR_DEG = 5.0      # °: a tangent angle below this is laid off by its slope, not with a protractor
RUN_MM = 100.0            # mm: the run along the I* axis over which the slope's rise is given


def kl_read(f) -> tuple[float, float, float]:
    """k, l and |kl| in mm as one ruler of ``f.precision`` reads them on the ΔT axis: |kl| read whole
    (``f.kl``, what J = μ_T·|kl|/(ω_m²·δ) takes), k read from the I* axis, and l laid off |kl| below
    it — so the printed k − l is the printed |kl| (stop 45's pump printed k = 0,715 and l = −65,1 mm
    with |kl| = 66 mm, each rounded its own way); each within a ruler's step of the drawing's."""
    k = float(read(f.tangent["k"], f.precision))
    return k, k - f.kl, f.kl


def tangents_note(f, lang: str) -> str | None:
    """How the Wittenbauer tangents are drawn where ψ is too small for a protractor (below
    ``PROTRACTOR_DEG``): by their slope tg ψ — the rise over ``RUN_MM`` of the I* axis — moved
    parallel until they touch the curve, and where they cut the ΔT axis: k, l and |kl| in mm (markup)."""
    tg = f.tangent
    if math.degrees(math.atan(abs(tg["s_min"]))) >= PROTRACTOR_DEG:
        return None
    uk = lang == "uk"
    mm = NB + ("мм" if uk else "mm")
    run = num(RUN_MM, lang)
    hi, lo = (num(RUN_MM * tg[key], lang, 3).replace("-", "−") for key in ("s_max", "s_min"))
    k, l, kl = (num(v, lang).replace("-", "−") for v in kl_read(f))
    im = "I^*_м" if uk else "I^*_m"
    if uk:
        return (f"ψ замалі для транспортира: дотичні проводять за tg ψ (на {run}{mm} осі {im} підйом {hi}{mm} при "
                f"ψ_{{max}}, {lo}{mm} при ψ_{{min}}), переносячи паралельно до дотику з кривою; на осі ΔT вони "
                f"відтинають k{NB}={NB}{k}{mm} і l{NB}={NB}{l}{mm}, |kl|{NB}={NB}{kl}{mm}")
    return (f"ψ is too small for a protractor: the tangents are drawn by tan ψ (a rise of {hi}{mm} at ψ_{{max}}, {lo}{mm} "
            f"at ψ_{{min}} over {run}{mm} of the {im} axis), moved parallel to touch the curve; they cut the "
            f"ΔT axis at k{NB}={NB}{k}{mm} and l{NB}={NB}{l}{mm}, |kl|{NB}={NB}{kl}{mm}")


def motor_speed_note(doc: dict, lang: str) -> str:
    """Which ω_m is used where (markup), one line for the sheet's notes after the flywheel's
    ω_m = πn_1/30 (``WORDS`` "given"): with the motor through the reducer (i = n_н/n_1 at the rated
    speed, Table 3) the crank's mean speed is another one, ω_{m дв} — faster where the load is below
    the rated one (less slip) —, which serves only the flywheel «with the motor» and the dashed ω(φ)."""
    uk = lang == "uk"
    m = doc["motor"]
    w1, wm = doc["omega_mean"], m["motion"]["omega_mean"]
    pct = 100.0 * (wm / w1 - 1.0)
    sym, sign = motor_omega(lang), _signed(pct, lang)
    if uk:
        why = "ковзання менше номінального" if pct > 0 else "ковзання більше номінального"
        return f"з двигуном {sym}{NB}={NB}{num(wm, lang, 4)}{NB}рад/с ({sign}{NB}%: {why})"
    why = "less slip than rated" if pct > 0 else "more slip than rated"
    return f"with the motor {sym}{NB}={NB}{num(wm, lang, 4)}{NB}rad/s ({sign}{NB}%: {why})"


def not_needed(delta_without: float, delta: float, lang: str, symbol: str = "δ") -> str:
    """"не потрібен (δ = 0,0236 < 0,03)": a flywheel no method needs, with the δ the machine keeps
    without one against the δ asked for (``symbol``: the motor's δ_{дв})."""
    return (f"не потрібен ({symbol} = {delta_text(delta_without, lang)} < {num(delta, lang)})" if lang == "uk" else
            f"not needed ({symbol} = {delta_text(delta_without, lang)} < {num(delta, lang)})")


def design_note(doc: dict[str, Any], lang: str) -> str | None:
    """One sentence giving the project's answer wherever a flywheel is needed: the flywheel by the
    course's graphical method (REFERENCE §9: Wittenbauer's energy–mass diagram, the tangents at
    ψ_max/ψ_min, I_fl = μ_T·|kl|/(ω_m²·δ) − I_рот·i², the "third sheet"), with the exact one (the
    equation of motion for the same constant M*_d) as its check; the motor's own run (seed 003's
    M = Aω + B through the reducer) only as a remark — its moment falls as the speed rises and takes
    up part of the fluctuation, and its crank turns at the motor's own mean speed (``speed_share``),
    so it may need less (or none: review 11's Scotch yoke, 10,09 kg·m² against none). The remark is
    left out where the motor's flywheel is within the lab's 5 % of the exact. None where no flywheel
    is needed (Table 2 and the notes say why)."""
    fw = doc["flywheel"]
    if not fw["needed"]:
        return None
    uk = lang == "uk"
    J = "кг·м²" if uk else "kg·m²"
    d = flywheel_decimals(doc)
    fl, md = ("I_мах", "M^*_д") if uk else ("I_fl", "M^*_d")
    exact = flywheel_text(fw["exact"], lang, d)
    graphical = fw["graphical"] > 0          # the diagram's reading: the answer (else the exact one)
    value = flywheel_text(fw["graphical"] if graphical else fw["exact"], lang, d)
    if uk:
        how = f"за діаграмою Віттенбауера; точно {exact}" if graphical else f"точно, для сталого {md}"
        answer = f"Відповідь проєкту — маховик {fl}{NB}={NB}{value}{NB}{J} ({how})"
    else:
        how = f"by Wittenbauer's diagram; exact {exact}" if graphical else f"exact, for a constant {md}"
        answer = f"The design's answer is a flywheel {fl}{NB}={NB}{value}{NB}{J} ({how})"
    if fw["motor"] > 0 and abs(fw["motor"] - fw["exact"]) <= LAB_LIMIT / 100 * fw["exact"]:
        return answer                        # the motor's run agrees within the lab's 5 %: no remark
    dm = (f"{motor_delta(lang)}{NB}={NB}{delta_text(doc['motor']['motion']['delta'], lang)}{NB}<{NB}"
          f"{num(doc['delta'], lang)}")         # kept on one line (no-break spaces)
    motor = flywheel_text(fw["motor"], lang, d)
    speed = speed_share(doc, lang)
    if fw["motor"] <= 0:
        with_motor = f"з двигуном не потрібен ({dm})" if uk else f"with the motor none is needed ({dm})"
    elif fw["motor"] < fw["exact"]:
        with_motor = f"з двигуном досить {motor}{NB}{J}" if uk else f"with the motor {motor}{NB}{J} suffices"
    else:
        with_motor = f"з двигуном потрібен {motor}{NB}{J}" if uk else f"with the motor {motor}{NB}{J} is needed"
    if fw["motor"] < fw["exact"]:            # the motor's M(ω) falls with speed: it takes up part of ΔT
        why = "M(ω) спадає зі швидкістю" if uk else "its M(ω) falls with speed"
        return f"{answer}; {'примітка' if uk else 'remark'}: {with_motor}: {why}{speed}"
    return f"{answer}; {'примітка' if uk else 'remark'}: {with_motor}{speed}"


SPEED_SAID = 1.0     # %: ω_m дв off ω_m by more than this — the design note says it as a cause (stop 51)


def speed_share(doc: dict[str, Any], lang: str) -> str:
    """", а ω_{m дв} на 7,02 % більша (J ~ 1/ω_m²)" (markup): the other cause of the motor's flywheel
    differing from the constant-M*_d one — the crank turning at the motor's own mean speed (the
    reducer's i = n_н/n_1 taken at the rated slip), and the flywheel for a δ being inversely as the
    square of the mean speed, (δ ≈ (ΔT_max − ΔT_min)/(J·ω_m²)); LINK51: +7,02 %, J × 0,873 of the
    10,91 → 7,30 kg·m². Nothing where the two speeds agree to ``SPEED_SAID``."""
    w1, wm = doc["omega_mean"], doc["motor"]["motion"]["omega_mean"]
    pct = 100.0 * (wm / w1 - 1.0)
    if abs(pct) <= SPEED_SAID:
        return ""
    sym, size = motor_omega(lang), num(abs(pct), lang, 3)
    if lang == "uk":
        return f", а {sym} на{NB}{size}{NB}% {'більша' if pct > 0 else 'менша'}{NB}(J{NB}~{NB}1/ω_{{m}}^{{2}})"
    return f", and {sym} is{NB}{size}{NB}% {'higher' if pct > 0 else 'lower'}{NB}(J{NB}~{NB}1/ω_{{m}}^{{2}})"


def smallest_of_line(m) -> bool:
    """Whether the motor is the catalogue's smallest of its synchronous speed (model/motors.toml)."""
    line = [c.power_kW for c in catalogue() if c.rpm_sync == m.rpm_sync]
    return bool(line) and m.power_kW <= min(line) + 1e-12


OVERSIZED = 2.0      # P_n over the rule's P past which the note says the line has no smaller motor


def catalogue_floor(doc: dict[str, Any], lang: str) -> str:
    """", the smallest … of the catalogue" after the rule's power where the rule's motor is the
    smallest of its line and still over ``OVERSIZED`` times the power asked (LINK50: 0,55 kW for
    0,094 kW — a teacher asks why so large a motor); else nothing."""
    m = doc["motor"]
    if not m.get("smallest") or m["power_kW"] < OVERSIZED * m["power_needed_kW"]:
        return ""
    name = m["name"] if lang == "uk" else latin(m["name"])
    rpm = f"{m['rpm_sync']:g}"
    if lang == "uk":
        return f"; {name} ({num(m['power_kW'], lang)} кВт) — найменший у каталозі на {rpm} об/хв"
    return f"; {name} ({num(m['power_kW'], lang)} kW) is the catalogue's smallest at {rpm} rpm"


def motor_note(doc: dict[str, Any], lang: str) -> str | None:
    """One sentence on why a flywheel where the motor is sized by the peak (review 13 #18: "why a
    2,65 kg·m² flywheel when the 5,5 kW motor carries the peak anyway?"). Seed 003's power rule,
    P = M*_c max·ω_1/η, lets the motor carry the cycle's peak load (the mean is M*_d·ω_m/η); how
    evenly the crank turns is set by the inertia — on its working branch M = Aω + B (A < 0) the
    motor's moment grows only as ω falls —, so the equation of motion with this motor still asks
    for its flywheel (Table 2's last row), or, where it keeps δ_дв < δ alone, none. None where no
    method needs a flywheel (nothing to ask)."""
    fw, m = doc["flywheel"], doc["motor"]
    if not fw["needed"]:
        return None
    uk = lang == "uk"
    kw = "кВт" if uk else "kW"
    # the mean like the peak, the motor's: through η (stop 49: 0,6187 kW beside a crank's 0,2473 kW)
    peak = sig(m["power_needed_kW"], lang)
    mean = sig(doc["moment_driving"] * doc["omega_mean"] / m["efficiency"] / 1000.0, lang)
    md, mc = ("M^*_д", "M^*_{с max}") if uk else ("M^*_d", "M^*_{c max}")
    rule = f"P = {mc}·ω_1/η = {peak} {kw}"
    # ω_m first: set as plain text "ωm/η" reads as the unit m/ (tests/test_words.py)
    avg = f"({'середня' if uk else 'the mean'} ω_m·{md}/η = {mean} {kw}){catalogue_floor(doc, lang)}"
    d = num(doc["delta"], lang)
    # a statement, not a question (stop 49: «Чому маховик, коли …» read as a heading on the sheet)
    if fw["motor"] > 0:
        J = flywheel_text(fw["motor"], lang, flywheel_decimals(doc))
        if uk:
            return (f"Двигун вибрано за піком навантаження: {rule} {avg}; рівномірність ходу дає не потужність, "
                    f"а інерція (M(ω) двигуна росте лише зі спадом ω): для δ = {d} з цим двигуном потрібен "
                    f"маховик {J} кг·м²")
        return (f"The motor is sized by the peak load: {rule} {avg}; the speed is kept even not by the power but "
                f"by the inertia (the motor's M(ω) grows only as ω falls): δ = {d} with this motor needs a "
                f"{J} kg·m² flywheel")
    dm = f"{motor_delta(lang)} = {delta_text(m['motion']['delta'], lang)} < {d}"
    if uk:
        return (f"Двигун вибрано за піком навантаження: {rule} {avg}; його M(ω) круто росте зі спадом ω, і він "
                f"сам тримає {dm} — з ним маховик не потрібен; маховик таблиці 2 — для сталого {md}")
    return (f"The motor is sized by the peak load: {rule} {avg}; its M(ω) grows steeply as ω falls and it holds "
            f"{dm} alone — no flywheel with it; Table 2's flywheel is for a constant {md}")


# -- the flywheel's arithmetic, every term printed ---------------------------------------------------

def sig(v: float, lang: str, digits: int = 4) -> str:
    """``digits`` significant figures with the trailing zeros kept (12,998 → "13,00" beside 12,65,
    not "13"), the language's decimal sign and a true minus."""
    from graphplan.util.words import fixed
    v = float(v)
    if v == 0 or not math.isfinite(v):
        return num(v, lang)
    rounded = float(f"{v:.{digits - 1}e}")        # the exponent after rounding (9.9996 → 10.00)
    decimals = max(digits - 1 - math.floor(math.log10(abs(rounded))), 0)
    return fixed(rounded, lang, decimals).replace("-", "−")


def constant_terms(rotor: float, reducer: float, lang: str) -> tuple[str, str]:
    """What the flywheel's J holds besides the flywheel, as a method subtracts it (markup): the
    symbols, " − I_рот·i²" and " − I^*_ред" where the scene's reducer has inertia (seed 003's
    I*_ред, its shafts reduced to the crank), and their values the same way (Table 3's I_рот·i²)."""
    uk = lang == "uk"
    sym = f" − {'I_рот' if uk else 'I_rotor'}·i²"
    val = f"{NB}−{NB}{sig(rotor, lang)}"        # the arithmetic kept on one line (no-break spaces)
    if reducer > 0:
        sym += f" − {'I^*_ред' if uk else 'I^*_red'}"
        val += f"{NB}−{NB}{sig(reducer, lang)}"
    return sym, val


def reducer_note(f, lang: str) -> str | None:
    """The reducer's reduced inertia named where the notes subtract it (markup), or None."""
    red = f.dyn.drive.reducer_reduced
    if red <= 0:
        return None
    return (f"I^*_ред{NB}={NB}{sig(red, lang)}{NB}кг·м² — момент інерції редуктора, зведений до кривошипа" if lang == "uk"
            else f"I^*_red{NB}={NB}{sig(red, lang)}{NB}kg·m²: the reducer's moment of inertia reduced to the crank")


def _fl(v: float, lang: str, decimals: int | None = None) -> str:
    """A flywheel's value (markup) ending its arithmetic, to Table 2's ``decimals``: kg·m², or ≤ 0
    and none needed."""
    kgm2 = "кг·м²" if lang == "uk" else "kg·m²"
    if v > 0:
        return f"{flywheel_text(v, lang, decimals)}{NB}{kgm2}"
    return (f"{sig(v, lang)}{NB}{kgm2} ≤ 0: маховик не потрібен" if lang == "uk" else
            f"{sig(v, lang)}{NB}{kgm2} ≤ 0: no flywheel is needed")


def wittenbauer_note(f, lang: str, decimals: int | None = None) -> str:
    """The graphical flywheel's arithmetic (markup), every input printed: J = μ_T·|kl|/(ω_m²·δ)
    with the numbers, then I_мах = J − I_рот·i² (− I*_ред; Table 3 prints I_рот·i²) (REFERENCE §9), the
    result to Table 2's ``decimals`` (``flywheel_decimals``; four figures where none are given)."""
    uk = lang == "uk"
    sym, _ = constant_terms(f.dyn.drive.rotor_reduced, f.dyn.drive.reducer_reduced, lang)
    fl = "I_мах" if uk else "I_fl"
    kgm2 = "кг·м²" if uk else "kg·m²"
    wm, d = f.dyn.omega_mean, f.dyn.delta
    # each "numbers = result unit" on one line (no-break spaces): a result never wrapped off its arithmetic
    total, flywheel = graphical_chain(f)
    return (f"J = μ_T·|kl|/(ω_{{m}}^{{2}}·δ) = {num(f.mu_T, lang)}·{num(f.kl, lang)}/({sig(wm, lang)}²·{num(d, lang)})"
            f"{NB}={NB}{sig(total, lang)}{NB}{kgm2}; {fl} = J{sym}{NB}={NB}{_fl(flywheel, lang, decimals)}")


def energy_scales(mu_A: float, mu_T: float) -> str:
    """The terminal's μA and μT: one value where ΔT is drawn at the work diagrams' scale, else both."""
    if mu_T == mu_A:
        return f"μA = μT = {mu_A:.5g}"
    return f"μA = {mu_A:.5g}, μT = {mu_T:.5g}"


def _read(text: str) -> float:
    """A printed number read back (the reader's value): decimal comma or point, true minus."""
    return float(text.replace("−", "-").replace(",", ".").replace(NB, ""))


def _constant_printed(rotor: float, reducer: float) -> float:
    """I_рот·i² (+ I*_ред) as ``constant_terms`` prints them, read back."""
    return _read(sig(rotor, "en")) + (_read(sig(reducer, "en")) if reducer > 0 else 0.0)


def graphical_chain(f) -> tuple[float, float]:
    """The graphical flywheel as a reader works it out from ``wittenbauer_note``'s printed numbers
    (stop 46: 5,057 − 0,3231 printed = 4,733 where the printed numbers give 4,734): J =
    μ_T·|kl|/(ω_m²·δ) from the printed μ_T, |kl|, ω_m and δ, printed to four figures, and
    I_мах = J − I_рот·i² (− I*_ред) from that printed J; (J, I_мах) — Table 2's graphical row is this I."""
    wm, d = f.dyn.omega_mean, f.dyn.delta
    total = _read(num(f.mu_T, "en")) * _read(num(f.kl, "en")) / (_read(sig(wm, "en")) ** 2 * _read(num(d, "en")))
    total = _read(sig(total, "en"))
    return total, total - _constant_printed(f.dyn.drive.rotor_reduced, f.dyn.drive.reducer_reduced)


def approximate_chain(doc: dict) -> float:
    """The approximate flywheel as a reader works it out from ``approximate_note``'s printed numbers
    (stop 46: (21,9 − (−44,7))/(14,66²·0,06) − 0,05746 − 0,3231 printed = 4,787 where they give
    4,784): ΔT_max, ΔT_min to Table 1's decimals, ω_m and I*_м сер to four figures, δ as given."""
    p = approximate_parts(doc)
    hi, lo = (_read(t) for t in decimals_column([p["dt_max"], p["dt_min"]], "en", energy_decimals(doc)))
    fw = doc["flywheel"]
    return ((hi - lo) / (_read(sig(p["omega_mean"], "en")) ** 2 * _read(num(p["delta"], "en")))
            - _read(sig(p["i_mean"], "en")) - _constant_printed(fw["rotor_reduced"], fw["reducer_reduced"]))


def approximate_parts(doc: dict) -> dict[str, float]:
    """The approximate method's inputs as read (graphic.flywheel ``approximate_total``), from the
    ``dynamics --json`` document: ΔT_max and ΔT_min read off the drawn ΔT(φ) curve at its extremes
    (``approximate_energy``, J, with their φ), I*_m's graphical mean over the divisions, ω_m, δ,
    and J = (ΔT_max − ΔT_min)/(ω_m²·δ) − I*_mean."""
    e = doc["flywheel"]["approximate_energy"]
    mean = float(np.mean([p["graphical"]["inertia"] for p in doc["positions"]]))
    wm, d = doc["omega_mean"], doc["delta"]
    return {"dt_max": e["max"], "dt_min": e["min"], "max_deg": e["max_deg"], "min_deg": e["min_deg"],
            "i_mean": mean, "omega_mean": wm, "delta": d,
            "total": (e["max"] - e["min"]) / (wm ** 2 * d) - mean}


def approximate_note(doc: dict, lang: str, formula: bool = False) -> str:
    """The approximate flywheel's arithmetic (markup), every input printed in the order of Table 2's
    row, I_мах = (ΔT_max − ΔT_min)/(ω_m²·δ) − I*_м сер − I_рот·i² (− I*_ред): ΔT_max,min read off the
    drawn ΔT(φ) curve (where, said after), so the printed numbers give the printed value; ``formula``:
    the symbols first (the terminal, which has no Table 2 row beside it)."""
    uk = lang == "uk"
    p = approximate_parts(doc)
    fw = doc["flywheel"]
    sym, val = constant_terms(fw["rotor_reduced"], fw["reducer_reduced"], lang)
    hi, lo = decimals_column([p["dt_max"], p["dt_min"]], lang, energy_decimals(doc))    # as Table 1's column prints them
    lo = f"({lo})" if p["dt_min"] < 0 else lo
    mean = "I^*_{м сер}" if uk else "I^*_{m mean}"
    gr = "гр" if uk else "gr"       # read off the drawn curve: graphical, as Table 1's «ΔT гр.» (review 61's remark 6)
    symbols = f"(ΔT_{{max {gr}}} − ΔT_{{min {gr}}})/(ω_{{m}}^{{2}}·δ) − {mean}{sym} = " if formula else ""
    return (f"{'наближено' if uk else 'approximate'}: {'I_мах' if uk else 'I_fl'} = {symbols}"
            f"({hi}{NB}−{NB}{lo})/({sig(p['omega_mean'], lang)}²·{num(p['delta'], lang)})"
            f" −{NB}{sig(p['i_mean'], lang)}{val}{NB}={NB}"
            f"{_fl(approximate_chain(doc), lang, flywheel_decimals(doc))}"
            + (f" (ΔT_{{max {gr}}}, ΔT_{{min {gr}}} {'з накресленої кривої ΔT(φ) при' if uk else 'read off the drawn ΔT(φ) curve at'} "
               f"{fixed(p['max_deg'], lang, 0)}°{NB}{'і' if uk else 'and'}{NB}{fixed(p['min_deg'], lang, 0)}°)"))


def error_text(v: float, lang: str) -> str:
    """A method's percent error as Table 2 and the notes print it: two decimals, signed ("+1,31",
    "−0,16"; "0,00" for the exact row), the terminal's to three."""
    from graphplan.util.words import fixed
    return fixed(v, lang, 2) if v == 0 else fixed(v, lang, 2, plus=True).replace("-", "−")
