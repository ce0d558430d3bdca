"""The third sheet, «Динамічний аналіз» (dynamic analysis): the reduced moments with their graphical
integration into the work diagrams, ΔT, I*_m, the energy–mass (Wittenbauer) diagram with the
flywheel read off |kl|, the steady-state speed ω(φ), the tables of the reduced quantities per
position, the flywheel by each method with its error and the motor."""
from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from graphplan.drawing.flywheel import (BREAK_CLEAR, _cleared, achieved, energy_projected, inertia_turned, moments_least,
                                        turned_length,
                                       moments_record, records, speed_fitted, wittenbauer_record, SPEED_ASPECT, SPEED_TALLEST,
                                       PSI_DECIMALS)
from graphplan.drawing.layout import (GAP, Leaf, Placed, Row, Stack, arrange, centred, column_size, extent, flow,
                                      set_columns, split, top_left)
from graphplan.exact.dynamics import analyse
from graphplan.exact.positions import Study
from graphplan.graphic.diagrams import LAB_LIMIT
from graphplan.graphic.flywheel import A_HEIGHT, Flywheel, redrawn
from graphplan.graphic.scales import series_choices
from graphplan.graphic.record import Record, line_pitch, text_width
from graphplan.model.motors import latin
from graphplan.report.dynamics import (amplified, amplified_note, approximate_note, chords_note, design_note, motor_note, dynamics_json, error_text, flywheel_decimals, flywheel_errors,
                                       flywheel_text, motor_delta, motor_omega, motor_speed_note, not_needed,
                                       redrawn_note, reducer_note, rotor_estimate_note, sig, signed, table_columns, tangents_note, wittenbauer_note)
from graphplan.sheets.compose import (CAPTION, CAPTION_GAP, Sheet, SheetOptions, captioned, compose, field_of, keep_out, lines_of,
                                      note_block, notes_height, wrap_markup)
from graphplan.sheets.form import TABLES, Form, enlarged, form, table
from graphplan.sheets.kinematics import TITLE, fields
from graphplan.sheets.kintables import phi_convention, title_in
from graphplan.util.errors import GraphplanError, said_error
from graphplan.util.words import LANGS, fixed, num


def fmt(v: float | None, lang: str, digits: int = 4) -> str:
    """Numbers for tables (util.words.num): 4 significant digits, the language's decimal sign, a
    true minus, '—' for none."""
    return num(v, lang, digits).replace("-", "−")


Options = SheetOptions

# the diagrams' abscissa L (mm) and the size of their heights: the largest pair that fits
SIZES = ((330.0, 1.5), (330.0, 1.3), (330.0, 1.15), (330.0, 1.0), (290.0, 1.0), (250.0, 1.0), (210.0, 0.8),
         (170.0, 0.7), (170.0, 0.55), (150.0, 0.45), (130.0, 0.35), (120.0, 0.3))

WORDS = {
    "uk": {"subtitle": "Динамічний аналіз", "moments": "Діаграми зведених моментів M^*_с(φ), M^*_д і робіт A_с(φ), "
           "A_д(φ) (графічне інтегрування методом хорд)", "energy": "Діаграма зміни кінетичної енергії ΔT(φ) = A_д − A_с",
           "inertia": "Діаграма зведеного моменту інерції механізму I^*_м(φ)",
           "wittenbauer": "Діаграма енергія–маса (Віттенбауера)", "speed": "Кутова швидкість кривошипа ω(φ) усталеного руху",
           "positions": "Таблиця 1. Зведені величини в положеннях", "flywheel": "Таблиця 2. Момент інерції маховика, кг·м²",
           "motor": "Таблиця 3. Електродвигун і редуктор", "method": "метод", "value": "I_мах", "err": "δ, %",
           "exact": "точно: рівняння руху (сталий M^*_д)", "graph": "графічно: діаграма Віттенбауера",
           "approx": "наближ.: (ΔT_{max гр}−ΔT_{min гр})/(ω_{m}^{2}·δ) − I^*_{м сер}", "merk": "наближ.: метод Мерцалова",
           "motor_fl": "з двигуном (ω_{m дв}): рівняння руху", "scales": "Масштаби", "given": "δ = {d}; для маховика ω_m = πn_1/30 = {w} рад/с (n_1 = {n} об/хв), {motor}",
           "n": "№", "chosen": "вибраний за правилом", "scene": "заданий у сцені", "warn": "Попередження",
           "achieved": "Досягнуто: δ = {d}; ω(2π) = ω(0) — рух усталений{c}",
           "turn": "dI^*_м/dφ — похідна за цим φ",
           "added": "{one} {pts} додано між поділками, де M^*_с стрибає чи ламається (ΔT(φ) там має злам)",
           "none": "Маховик не потрібен: ротор і редуктор (I_рот·i² + I^*_ред = {c} кг·м²) уже дають δ ≤ {d} "
                   "(потрібно J = {j} кг·м²), тому I_мах = 0",
           "weak": "Двигун {name}: P_н = {p} кВт менша за потрібну за правилом P = M^*_{{с max}}·ω_1/η = {need} кВт",
           "weak_cell": "{p} (< {need})", "mark": "* — ",
           "open": "незамкнення |ω(2π) − ω(0)|/ω_m = {c}",
           "why_graph": "графічно {e} %: похибка побудови ({n} поділок, лінійка {p} мм)",
           "not": "не потрібен",
           "why_approx": "наближено {e} %: метод нехтує зміною I^*_м за цикл (похибка методу, а не побудови)",
           "why_approx_small": "наближено {e} %: J {j} %, помножена на J/I_мах = {x} (метод нехтує зміною I^*_м "
                               "за цикл, а ΔT_{{max гр}} − ΔT_{{min гр}} та I^*_{{м сер}} прочитано лінійкою)",
           "why_merk": "Мерцалов {e} %: метод оцінює енергію ланок за середньої швидкості ω_m (похибка методу, а не побудови)",
           "short": "|kl| = {kl} мм (на аркуші A1 — {a1} мм): ",
           "short_tall": "з |kl| = {a1} мм діаграма енергія–маса з I^*_м(φ) під нею мала б ≥ {need} мм заввишки, "
                         "а аркуш {fmt} вміщує {room} мм",
           "short_none": "жоден масштаб (L = {low}…{top} мм), що вміщується на аркуші {fmt}, не дає |kl| ≥ {a1} мм",
           "short_first": "у порядку роботи (M^*(φ) на першому аркуші) жоден масштаб (L = {low}…{top} мм) аркуша {fmt} "
                          "не дає |kl| ≥ {a1} мм"},
    "en": {"subtitle": "Dynamic analysis", "moments": "Reduced moments M^*_c(φ), M^*_d and the work A_c(φ), A_d(φ) "
           "(graphical integration by chords)", "energy": "Change of kinetic energy ΔT(φ) = A_d − A_c",
           "inertia": "Reduced moment of inertia of the mechanism I^*_m(φ)",
           "wittenbauer": "Energy–mass (Wittenbauer) diagram", "speed": "Crank speed ω(φ) in the steady state",
           "positions": "Table 1. Reduced quantities at the positions", "flywheel": "Table 2. Flywheel moment of inertia, kg·m²",
           "motor": "Table 3. Motor and reducer", "method": "method", "value": "I_fl", "err": "δ, %",
           "exact": "exact: equation of motion (constant M^*_d)", "graph": "graphical: Wittenbauer diagram",
           "approx": "approx.: (ΔT_{max gr}−ΔT_{min gr})/(ω_{m}^{2}·δ) − I^*_{m mean}", "merk": "approx.: Mertsalov's method",
           "motor_fl": "with the motor (ω_{m mot}): equation of motion", "scales": "Scales", "given": "δ = {d}; for the flywheel ω_m = πn_1/30 = {w} rad/s (n_1 = {n} rpm), {motor}",
           "n": "No.", "chosen": "chosen by the rule", "scene": "given by the scene", "warn": "Warnings",
           "achieved": "Achieved: δ = {d}; ω(2π) = ω(0): a steady state{c}",
           "turn": "dI^*_m/dφ: the derivative along this φ",
           "added": "{one} {pts} added between the divisions where M^*_c jumps or bends (ΔT(φ) has a corner there)",
           "none": "No flywheel is needed: the rotor and the reducer (I_rotor·i² + I^*_red = {c} kg·m²) already keep "
                   "δ ≤ {d} (J = {j} kg·m² is needed), so I_fl = 0",
           "weak": "Motor {name}: P_n = {p} kW is below the power rule P = M^*_{{c max}}·ω_1/η = {need} kW",
           "weak_cell": "{p} (< {need})", "mark": "* — ",
           "open": "closure |ω(2π) − ω(0)|/ω_m = {c}",
           "why_graph": "graphical {e} %: the construction's error ({n} divisions, a {p} mm ruler)",
           "not": "not needed",
           "why_approx_small": "approximate {e} %: J {j} %, multiplied by J/I_fl = {x} (the method neglects the "
                               "change of I^*_m over the cycle, and ΔT_{{max gr}} − ΔT_{{min gr}} and I^*_{{m mean}} are read "
                               "with the ruler)",
           "why_approx": "approximate {e} %: the method neglects the change of I^*_m over the cycle (the method's error, "
                         "not the drawing's)",
           "why_merk": "Mertsalov {e} %: the method takes the links' energy at the mean speed ω_m (the method's error, "
                       "not the drawing's)",
           "short": "|kl| = {kl} mm ({a1} mm on the A1 sheet): ",
           "short_tall": "at |kl| = {a1} mm the energy–mass diagram with I^*_m(φ) under it would be ≥ {need} mm tall, "
                         "an {fmt} sheet holds {room} mm",
           "short_none": "no scale (L = {low}…{top} mm) that fits an {fmt} sheet gives |kl| ≥ {a1} mm",
           "short_first": "in the order of the work (M^*(φ) on the first sheet) no scale (L = {low}…{top} mm) of an "
                          "{fmt} sheet gives |kl| ≥ {a1} mm"},
}


ROW = 6.0     # mm: a row of the tables


def note_under(rec: Record, span: tuple[float, float], top: float, text: str, step: str) -> int:
    """``text`` under a table ``rec`` whose body spans ``span`` = (x0, x1) (its bounds before any
    note: a note never widens the next one), wrapped to that width less the indent, its first line
    from ``top`` (mm, the baseline) at x0, the lines it wraps to indented 4 mm (the tables' notes: the
    chords, the approximate arithmetic, the marks' legend, the design answer, the rotor's estimate);
    the count of lines written."""
    x0, x1 = span
    parts = wrap_markup(text, x1 - x0 - 4.0, 2.5)
    for k, part in enumerate(parts):
        rec.label((x0 + (4.0 if k else 0.0), top - k * line_pitch(2.5)), part, size=2.5, layer="tables", step=step)
    return len(parts)


def positions_table(doc: dict, lang: str, extra: list[str] | tuple[str, ...] = ()) -> Record:
    """I*_m, dI*_m/dφ, M*_c, M*_d, A_c and ΔT (graphical and exact) per position; φ is the crank's
    turn from position 0 (the diagrams' abscissa), so dI*_m/dφ follows the printed φ whatever the
    crank's sense; one count of decimals a column, the terminal's cells (report.dynamics
    ``table_columns``)."""
    w = WORDS[lang]
    uk = lang == "uk"
    head = [w["n"], "φ, °", "I^*_м, кг·м²" if uk else "I^*_m, kg·m²", "dI^*_м/dφ, кг·м²" if uk else "dI^*_m/dφ, kg·m²",
            "M^*_с, Н·м" if uk else "M^*_c, N·m", "M^*_д, Н·м" if uk else "M^*_d, N·m",
            "A_с гр., Дж" if uk else "A_c gr., J", "A_д гр., Дж" if uk else "A_d gr., J",
            "ΔT гр., Дж" if uk else "ΔT gr., J", "ΔT, Дж" if uk else "ΔT, J", "δ, %"]
    cols = table_columns(doc, lang)         # the terminal's Table 1, cell for cell
    keys = ("inertia", "d_inertia", "moment_resistance", "moment_driving", "work_resistance", "work_driving",
            "energy_graphical", "energy", "energy_error")
    rows = [head]
    for k, p in enumerate(doc["positions"]):
        rows.append([str(p["index"]), cols["turn"][k]] + [cols[c][k] for c in keys])
    rec = table(rows, [9.0, 13.0, 22.0, 26.0, 20.0, 20.0, 19.0, 19.0, 20.0, 18.0, 11.0], row_h=ROW, size=2.5,
                title=w["positions"])
    x0, y0, x1, _ = rec.bounds()            # under the table: the chords' heights and what δ is of
    top = y0 - 4.2
    for line, step in ((chords_note(doc, lang), "chord heights"), *((t, "added points") for t in extra)):
        top -= note_under(rec, (x0, x1), top, line, step) * line_pitch(2.5)
    return rec


def flywheel_table(doc: dict, lang: str, why: list[str] | tuple[str, ...] = ()) -> Record:
    """The flywheel by each method beside the exact one; 0 (never negative) where no flywheel is
    needed, the notes saying why. Under it the approximate row's arithmetic and ``why`` (``marked``:
    the legend of the rows marked * past the lab's 5 %), then the project's answer."""
    w = WORDS[lang]
    fw = doc["flywheel"]

    def pct(v: float | None) -> str:          # over the lab's 5 %: marked, the notes say why
        return "—" if v is None else error_text(v, lang) + ("*" if abs(round(v, 2)) > LAB_LIMIT else "")
    d = flywheel_decimals(doc)                # one count of decimals for the column, the notes' results too

    def value(v: float) -> str:               # a method's J no larger than rotor and reducer: none needed
        return flywheel_text(v, lang, d) if v > 0 else w["not"]
    exact = (flywheel_text(fw["exact"], lang, d) if fw["needed"] else not_needed(doc["motion"]["delta"], doc["delta"], lang))
    motor = (flywheel_text(fw["motor"], lang, d) if fw["motor"] > 0 else
             not_needed(doc["motor"]["motion"]["delta"], doc["delta"], lang, motor_delta(lang)))
    # the approximate row names every term its value subtracts (the rotor, the reducer: notes' arithmetic); its ΔT
    # extremes marked graphical (гр/gr, stop 62) and «наближ.»/«approx.» shortened so that the column keeps its
    # width (78 / 84,5 mm: the en row at full length made Table 2 7 mm wider and LINK61's results left the nook)
    approx = w["approx"] + (" − I_рот·i²" if lang == "uk" else " − I_rotor·i²") + (
        (" − I^*_ред" if lang == "uk" else " − I^*_red") if fw["reducer_reduced"] > 0 else "")
    errs = flywheel_errors(doc)              # δ worked out from the printed values, as the terminal's
    rows = [[w["method"], f"{w['value']}, {'кг·м²' if lang == 'uk' else 'kg·m²'}", w["err"]],
            [w["exact"], exact, error_text(0.0, lang) if fw["exact"] > 0 else "—"],
            [w["graph"], value(fw["graphical"]), pct(errs["error_pct"])],
            [approx, value(fw["approximate"]), pct(errs["approximate_error_pct"])],
            [w["merk"], value(fw["merkalov"]), pct(errs["merkalov_error_pct"])],
            [w["motor_fl"], motor, ""]]
    rec = table(rows, [78.0, 24.0, 18.0], row_h=6.0, size=2.5, title=w["flywheel"])
    # under the table, the approximate row's arithmetic: its printed numbers give its printed value
    x0, y0, x1, _ = rec.bounds()
    n = note_under(rec, (x0, x1), y0 - 4.2, approximate_note(doc, lang), "approximate arithmetic")
    top = y0 - 4.2 - (n + 0.3) * line_pitch(2.5)
    for line in why:                        # the marks' legend, each line indented where it wraps
        top -= (note_under(rec, (x0, x1), top, line, "marks legend") + 0.3) * line_pitch(2.5)
    said = design_note(doc, lang)           # which of the two answers the design fits (review 11)
    if said:
        note_under(rec, (x0, x1), top, said, "design answer")
    return rec


def motor_table(doc: dict, lang: str, mean: bool = False) -> Record:
    """The motor's data, its characteristic and the power rule; a motor weaker than the rule asks
    has its power cell marked (*) and the notes say so. ``mean``: the mean power ω_m·M*_д/η in a row
    under the rule's peak — where the notes cannot hold the motor's sentence (report.dynamics
    ``motor_note``, which compares the two: ``_mean_row``)."""
    w = WORDS[lang]
    m = doc["motor"]
    uk = lang == "uk"
    power = fmt(m["power_kW"], lang)
    if m.get("underpowered"):
        power = w["weak_cell"].format(p=power, need=fmt(m["power_needed_kW"], lang)) + "*"
    rows = [[m["name"] if uk else latin(m["name"]), w["chosen"] if m["chosen"] else w["scene"]],
            ["P_н, кВт" if uk else "P_n, kW", power],
            ["n_с / n_н, об/хв" if uk else "n_c / n_n, rpm", f"{num(m['rpm_sync'], lang)} / {num(m['rpm_rated'], lang)}"],
            ["ω_с / ω_н, рад/с" if uk else "ω_c / ω_n, rad/s", f"{fmt(m['omega_sync'], lang)} / {fmt(m['omega_rated'], lang)}"],
            ["M_н / M_{max}, Н·м" if uk else "M_n / M_{max}, N·m", f"{fmt(m['moment_rated'], lang)} / {fmt(m['moment_max'], lang)}"],
            ["M = Aω + B, Н·м" if uk else "M = Aω + B, N·m", f"{fmt(m['A'], lang)}·ω + {fmt(m['B'], lang)}"],
            ["P = M^*_{с max}·ω_1/η, кВт" if uk else "P = M^*_{c max}·ω_1/η, kW", fmt(m["power_needed_kW"], lang)],
            *([["середня ω_m·M^*_д/η, кВт" if uk else "mean ω_m·M^*_d/η, kW",
                fmt(doc["moment_driving"] * doc["omega_mean"] / m["efficiency"] / 1000.0, lang)]] if mean else []),
            ["i; η" if m.get("ratio_given") else f"i = n_{'н' if uk else 'n'}/n_1; η",
             f"{num(m['ratio'], lang, 4)}; {num(m['efficiency'], lang)}"],
            ["I_рот·i², кг·м²" if uk else "I_rotor·i², kg·m²", fmt(m["rotor_reduced"], lang)],
            [f"{motor_omega(lang)}, {'рад/с' if uk else 'rad/s'}; {motor_delta(lang)}",
             f"{fmt(m['motion']['omega_mean'], lang)}; {achieved(m['motion']['delta'], doc['delta'], lang)}"],
            # the motor shaft's (review 13 #18: "on the cycle" did not say which shaft)
            # (not M_max: that is the catalogue's, two rows up — stop 46)
            ["M_{дв} найбільший у циклі, Н·м" if uk else "M_{mot} peak in the cycle, N·m", fmt(m["moment_peak"], lang)]]
    # every value right-aligned, pairs and the characteristic too (stop 46: 1,5 at the right under
    # 750 / 698 centred read as two columns)
    rec = table(rows, [48.0, 40.0], row_h=6.0, size=2.5, title=w["motor"], align=["middle", "end"])
    # why a flywheel beside a motor sized by the peak (review 13 #18) is said in the notes where the
    # band's nook holds it (``with_motor``), not under this table: its 4–6 lines here cost the
    # shaper's A1 dynamics its one sheet
    # a small motor's rotor inertia, not tabulated by the handbooks, is the catalogue's estimate: said under
    # the table whose I_рот·i² row uses it (stop 57), in the table's width
    said = rotor_estimate_note(doc, lang)
    if said:
        x0, y0, x1, _ = rec.bounds()
        note_under(rec, (x0, x1), y0 - 4.2, said, "rotor estimated")
    return rec


MOTOR_NOTE_W = 116.0    # mm: the motor's note wrapped as wide as Table 2's over it (its 120 mm less the indent)


CLOSURE_FLOOR = 1e-9


def closure(c: float, lang: str) -> str:
    """|ω(2π) − ω(0)|/ωm as the sheet says it: below 10⁻⁹ the residual is the integrator's rounding
    (it differs from machine to machine), the motion is periodic and the sheet says nothing more
    (deterministic files, no value printed at 10⁻⁹); above it, the residual itself."""
    return "" if abs(c) < CLOSURE_FLOOR else "; " + WORDS[lang]["open"].format(c=num(c, lang, 2))


def notes(f: Flywheel, doc: dict, lang: str, short: Shortfall | None = None, motor: bool = False) -> Record:
    """The scales, the construction's numbers with their symbols typeset, the convention of φ, the
    flywheel (0 and why where none is needed), the motor against the power rule and the warnings;
    in a set whose energy–mass diagram reads |kl| short of the A1 sheet's, why (``short``); with
    ``motor``, why a flywheel beside a motor sized by the peak (report.dynamics ``motor_note``: the
    sheet says it where the band's nook holds it, ``with_motor``; the terminal always)."""
    w = WORDS[lang]
    uk = lang == "uk"
    mm = "мм" if uk else "mm"
    s = doc["scales"]
    fw = doc["flywheel"]
    J, Nm, kgm2 = ("Дж", "Н·м", "кг·м²") if uk else ("J", "N·m", "kg·m²")
    lines = [w["given"].format(d=num(doc["delta"], lang), w=fmt(doc["omega_mean"], lang),
                               n=num(doc["omega_mean"] * 30.0 / math.pi, lang), motor=motor_speed_note(doc, lang)),
             # L named with its length: "2π/L" alone left a teacher asking which L (stop 50)
             f"{w['scales']}: μ_M = {num(s['mu_M'], lang)} {Nm}/{mm}, L = {num(doc['L_mm'], lang)} {mm}, μ_φ = 2π/L = "
             f"{num(s['mu_phi'], lang)} {'рад' if uk else 'rad'}/{mm}, H = {num(f.H, lang)} {mm}",
             energy_scales_note(s, lang) + f", μ_I = {num(s['mu_I'], lang)} {kgm2}/{mm}",
             f"{'A_с' if uk else 'A_c'} = {sig(doc['work_resistance'], lang)} {J}, "     # four figures, the terminal's
             f"{'M^*_д = A_с/2π' if uk else 'M^*_d = A_c/2π'} = {sig(doc['moment_driving'], lang)} {Nm}; "
             f"{'графічно' if uk else 'graphical'} {num(f.driving, lang)} {Nm}",
             f"{'tg' if uk else 'tan'} ψ = μ_I·ω_{{m}}^{{2}}(1 ± δ)/(2μ_T): ψ_{{max}} = {fixed(fw['psi_max_deg'], lang, PSI_DECIMALS)}°, "
             f"ψ_{{min}} = {fixed(fw['psi_min_deg'], lang, PSI_DECIMALS)}°",
             wittenbauer_note(f, lang, flywheel_decimals(doc)),
             *[line for line in (reducer_note(f, lang), tangents_note(f, lang)) if line],
             w["achieved"].format(d=achieved(doc["motion"]["delta"], doc["delta"], lang),
                                  c=closure(doc["motion"]["closure"], lang)),
             f"{phi_convention(doc['start_phi_deg'], lang)}; {w['turn']}"]
    said = []
    if not fw["needed"]:
        said.append(w["none"].format(c=num(fw["rotor_reduced"] + fw["reducer_reduced"], lang, 4),
                                     d=num(doc["delta"], lang), j=num(fw["total_exact"], lang, 4)))
    # Table 2's rows marked * past the lab's 5 % are explained here (``marked``). Under Table 2, where the
    # teacher reads the mark, they were tried (stop 57): the legend wrapped to the table's width made the
    # column so tall that the shaper's A1 lost its enlarged tables (3.5 → 2.5 mm, ~150 × 80 mm bare)
    said += marked(f, doc, lang)
    said += [line for line in (redrawn_note(f, lang, sheet=True),) if line]     # redrawn on more divisions, or why not
    if short is not None:
        said.append(short_note(short, lang))
    m = doc["motor"]
    if m.get("underpowered"):
        said.append(w["mark"] + w["weak"].format(name=m["name"] if uk else latin(m["name"]), p=fmt(m["power_kW"], lang),
                                                 need=fmt(m["power_needed_kW"], lang)))
    if motor:                              # why a flywheel beside a motor sized by the peak
        said += [line for line in (motor_note(doc, lang),) if line]
    lines += said                          # each a line the note block wraps to the column (once)
    for en, uk_text in f.dyn.warnings:
        if "no flywheel is needed" in en or "below the power rule" in en:   # said above in full
            continue
        lines.append(f"{w['warn']}: {uk_text if uk else en}")
    rec = Record("notes")
    for k, line in enumerate(lines):
        rec.label((0.0, -6.5 * k), line, size=3.5, layer="labels")
    return rec


def added_note(f: Flywheel, lang: str) -> str:
    """The notes' line on the points added between the divisions (graphic.flywheel ``division_points``):
    each by its name as drawn (6′) and its turn from position 0, and why the lab adds them."""
    uk = lang == "uk"
    pts = ", ".join(f"{f.added_label(j)} (φ = {num(math.degrees(float(f.turn_all[j])), lang, 4)}°)" for j in f.added)
    many = len(f.added) > 1
    one = ("Точки" if many else "Точку") if uk else ("Points" if many else "Point")
    if not uk:
        pts += " are" if many else " is"
    return WORDS[lang]["added"].format(one=one, pts=pts)


def marked(f: Flywheel, doc: dict, lang: str) -> list[str]:
    """Why each of Table 2's rows past the lab's 5 % (marked *) is off (markup, «* — наближено
    −9,82 %: метод нехтує …»): the construction's error, the method's, or — where the flywheel is a
    small part of J — J's error times J/I_fl (report.dynamics ``amplified``). Printed under Table 2,
    the marks' legend under the table that carries them."""
    w = WORDS[lang]
    out = []
    errs = flywheel_errors(doc)              # Table 2's δ
    amp = amplified(f)                       # the flywheel a small part of J: each error J's times J/I_fl
    for key, why in (("error_pct", "why_graph"), ("approximate_error_pct", "why_approx"),
                     ("merkalov_error_pct", "why_merk")):
        if errs[key] is not None and abs(round(errs[key], 2)) > LAB_LIMIT:
            e = error_text(errs[key], lang)
            line = amplified_note(f, lang, e) if key == "error_pct" else None
            if line is None:
                line = w[why].format(e=e, n=doc["divisions"], p=num(doc["precision_mm"], lang))
                j = None if amp is None else errs[key] * amp["share"] / 100.0    # J's error: I_fl's × I_fl/J
                if amp is not None and key == "approximate_error_pct":
                    # its J read off ΔT(φ) and I*(φ) by the same ruler: not the method's error alone
                    line = w["why_approx_small"].format(e=e, j=signed(j, lang), x=num(100.0 / amp["share"], lang, 2))
                elif amp is not None:        # the method's own error is J's: said beside I_fl's
                    line = line.replace(" %:", f" % (J {signed(j, lang)} %):", 1)
            out.append(w["mark"] + line)
    return out


def energy_scales_note(s: dict, lang: str) -> str:
    """μ_A = μ_M·μ_φ·H, and ΔT's μ_T: the same, or its own where ΔT(φ) is redrawn larger
    (graphic.flywheel ``own_energy_scale``: a small ΔT read between the work diagrams)."""
    J, mm = ("Дж", "мм") if lang == "uk" else ("J", "mm")
    if s["mu_T"] == s["mu_A"]:
        return f"μ_A = μ_T = μ_M·μ_φ·H = {num(s['mu_A'], lang)} {J}/{mm}"
    own = "ΔT(φ) перенесено у власному масштабі" if lang == "uk" else "ΔT(φ) redrawn at its own scale"
    return (f"μ_A = μ_M·μ_φ·H = {num(s['mu_A'], lang)} {J}/{mm}, μ_T = {num(s['mu_T'], lang)} {J}/{mm} "
            f"({own})")


def short_note(short: Shortfall, lang: str) -> str:
    """The notes' line on a set's |kl| short of the A1 sheet's: both |kl| and why (``Shortfall``).
    The A1 sheet's |kl| is the one it draws (``Shortfall.a1``: ΔT at its own finer μ_T, or its larger
    diagram, where it has room), not the search's classical target; the reason is taken at it."""
    w = WORDS[lang]
    fmt = {"kl": num(short.kl, lang), "a1": num(short.a1, lang), "fmt": short.format,
           "need": num(math.floor(short.need), lang),
           "room": num(short.room, lang), "low": num(short.low, lang), "top": num(short.top, lang)}
    return w["short"].format(**fmt) + w["short_" + short.kind].format(**fmt)


DRAWINGS = ("moments", "energy", "inertia", "wittenbauer", "speed")
BAND = ("energy", "wittenbauer", "inertia")
# the φ axis of ΔT(φ) and of the turned I*(φ) (free: their ordinates' μ_T and μ_I are the
# construction's), as a share of L, largest first, no shorter than PROJECTED_MIN mm
PROJECTED = (1.0, 0.85, 0.7, 0.6, 0.5, 0.42, 0.35)
PROJECTED_MIN = 80.0
PROJECTED_LEAST = 50.0      # … but on a set's page too small for that (5 mm a division at 10)


def _body(rec: Record) -> tuple[float, float, float, float]:
    """The drawing's box without its projection lines (they run to the neighbour's side)."""
    return Record(items=[p for p in rec.items if p.role != "projection"]).bounds()


def _caption(rec: Record, title: str, above: bool = False, left: float | None = None,
             scale: str | None = None) -> Record:
    """``captioned``, centred on the drawing without its projection lines; ``above`` it for the
    energy–mass diagram, whose foot the I* projections cross (and no further left than ``left``,
    ΔT(φ)'s side); ``scale``: a line under the caption stating the drawing's own scale (ΔT(φ)'s
    μ_φ, drawn over the band's length, not the moments' L: review 13 #11)."""
    x0, y0, x1, y1 = _body(rec)
    out = Record(rec.title, list(rec.items), dict(rec.scales))
    y = y1 + CAPTION_GAP if above else y0 - CAPTION_GAP - CAPTION
    mid = (x0 + x1) / 2
    if left is not None:
        mid = max(mid, left + text_width(title, CAPTION) / 2 + 1.0)
    out.label((mid, y), title, size=CAPTION, anchor="middle", layer="labels", step="caption")
    if scale:
        out.label((mid, y - CAPTION - 2.0), scale, size=2.5, anchor="middle", layer="labels", step="caption scale")
    return out


BAND_PRIME = "′"      # ΔT(φ)'s φ scale μ′_φ (and the turned I*(φ)'s where it shares ΔT(φ)'s axis) …
TURNED_PRIME = "″"    # … the turned I*(φ)'s μ″_φ where its axis is shorter (``widened``): the moments' μ_φ = 2π/L
#                       is the notes'; three scales of φ on one sheet, three names (a teacher marks one name for two)


def band_scale(length: float, lang: str, prime: str = BAND_PRIME) -> str:
    """ΔT(φ)'s (or the turned I*(φ)'s) φ scale: one turn over the band's ``length`` mm, named
    apart from the moments' μ_φ by its ``prime`` (μ′_φ = 2π/260 = 0,02417 рад/мм)."""
    return (f"μ{prime}_φ = 2π/{num(length, lang)} = {num(2 * math.pi / length, lang)} "
            f"{'рад/мм' if lang == 'uk' else 'rad/mm'}")


CAPTION_APART = 8.0    # mm: ΔT(φ)'s caption from the energy–mass diagram's lettering on its line (|kl|)
CAPTION_SHIFT = 12.0   # mm: … moved left at most this far past ΔT(φ)'s left side (or its own start), else under it


def _caption_apart(energy: Record, witt: Record) -> Record:
    """ΔT(φ) with its caption clear of the energy–mass diagram's lettering that stands on the
    caption's line (|kl| = … lettered under l, left of the ΔT axis: 3 mm after the caption it read
    as the caption's end): the caption moved left, at most ``CAPTION_SHIFT`` past ΔT(φ)'s left side
    (or its own start, the wider), until ``CAPTION_APART`` mm of paper lie between them; else under
    that lettering, a caption's gap below."""
    cap = next((p for p in energy.items if p.kind == "text" and p.step == "caption"), None)
    if cap is None:
        return energy
    cx0, cy0, cx1, cy1 = cap.ink()
    row = [b for b in (p.ink() for p in witt.items if p.kind == "text")
           if b[1] < cy1 + CAPTION_GAP and b[3] > cy0 - CAPTION_GAP and b[2] > cx0 - CAPTION_APART
           and b[0] < cx1 + CAPTION_APART]
    if not row:
        return energy
    left = min(_body(energy)[0], cx0) - CAPTION_SHIFT
    dx = min(b[0] for b in row) - CAPTION_APART - cx1           # ≤ 0: leftward
    if cx0 + dx >= left - 1e-9 and all(b[2] + CAPTION_APART <= cx0 + dx or b[0] - CAPTION_APART >= cx1 + dx
                                        for b in row):
        shift = (dx, 0.0)
    else:
        shift = (0.0, min(b[1] for b in row) - CAPTION_GAP - cy1)
    # the caption and its scale's line under it move together
    return Record(energy.title, [p.moved(*shift) if p.kind == "text" and p.step in ("caption", "caption scale") else p
                                 for p in energy.items], dict(energy.scales))


# mm: the energy–mass diagram's lettering keeps this far above the foot, where the turned I*(φ)'s
# projections end — a projection broken under a value (drawing.flywheel.BREAK_CLEAR) must not run on up to
# 0.4 mm under it from the drawing below (the shaper's «2,5», «10,0», stop 56), plus the line's half width
FOOT_CLEAR = BREAK_CLEAR + 0.2


def lettering_foot(witt: Record, side: float) -> float:
    """The lowest ink of the energy–mass diagram's lettering right of its side (where the turned I*(φ)'s
    vertical projections come up to the foot); +inf where none."""
    inks = [p.ink() for p in witt.items if p.kind == "text" and p.text.strip()]
    return min((b[1] for b in inks if b[2] > side), default=float("inf"))


_BANDS: dict[tuple, tuple] = {}


def band(f: Flywheel, lang: str, length: float,
         energy_length: float | None = None) -> tuple[dict[str, Record], dict[str, tuple]]:
    """``_band`` once per flywheel (the very object), language, φ axes and sketching (a copy each
    time): the composition's search asks for the band at each φ axis in both languages, and the
    sheet then draws one of them again."""
    from graphplan.drawing import labels as lb
    key = (id(f), lang, length, energy_length, lb._SKETCH[-1])
    hit = _BANDS.get(key)
    if hit is None or hit[0] is not f:
        if len(_BANDS) >= 64:
            _BANDS.pop(next(iter(_BANDS)))
        hit = _BANDS[key] = (f, _band(f, lang, length, energy_length))
    parts, boxes = hit[1]
    return {name: Record(r.title, list(r.items), dict(r.scales)) for name, r in parts.items()}, dict(boxes)


def _band(f: Flywheel, lang: str, length: float,
          energy_length: float | None = None) -> tuple[dict[str, Record], dict[str, tuple]]:
    """The textbook's elimination of φ (REFERENCE §9): ΔT(φ) to the left of the energy–mass
    diagram, its ΔT zero line the diagram's I* axis (the same μ_T), I*(φ) turned by 90° under it,
    its I* axis the diagram's (the same μ_I), φ running down ``length`` mm; a thin horizontal
    projection from each ΔT(φ) point and a thin vertical one from each turned I*(φ) point meet at
    the diagram's point of that division. ``energy_length``: ΔT(φ)'s own φ axis where it is longer
    than I*(φ)'s (the elimination of φ pairs the divisions by number, so each diagram of the
    projection has its own φ scale — ``widened``), each diagram's μ_φ then stated beside it. Records in one frame (the ΔT axis of the energy–mass
    diagram at x = 0, its I* axis at y = 0), captioned, and the boxes they own (touching where the
    projections cross from one to the other)."""
    from graphplan.drawing.labels import sketched
    w = WORDS[lang]
    with sketched():                                   # its lines' extent: the numbers are placed once, below
        probe = wittenbauer_record(f, lang, projections=(0.0, 0.0))
    px0, py0, _, _ = probe.bounds()
    side = px0 - 3.0                                   # the energy–mass diagram's left side …
    foot = py0 - 2.0                                   # … and its foot
    el = length if energy_length is None else energy_length
    turned = _caption(inertia_turned(f, lang, length, 0.0), w["inertia"])
    reached: dict[float, Record] = {}

    def projected_to(reach_: float) -> Record:        # ΔT(φ) captioned, drawn once per reach (the
        if reach_ not in reached:                      # attempts below ask for the same again)
            reached[reach_] = _caption(energy_projected(f, lang, el, reach_), w["energy"], scale=band_scale(el, lang))
        return reached[reach_]
    for attempt in range(6):                           # the lettering keeps off the lines: where it moves
        reach = el + 24.0                              # past the side or the foot, they go farther
        energy = projected_to(reach)
        if energy.bounds()[2] > reach:                 # ΔT(φ)'s lines run past its φ and its caption
            reach = energy.bounds()[2]
            energy = projected_to(reach)
        energy = energy.moved(side - reach, 0.0)
        if turned.bounds()[0] < side:                  # the turned I*(φ) reaches under ΔT(φ) too
            foot = min(foot, energy.bounds()[1] - 2.0)
        # captioned under the drawing, as every other (review 56 #8: above it the caption stood close under
        # A(φ)'s and read as its second line); the I* projections that run down past it broken under it
        witt = _caption(wittenbauer_record(f, lang, projections=(side, foot)), w["wittenbauer"], left=side)
        wx0, wy0, _, _ = witt.bounds()
        low = lettering_foot(witt, side)
        if (wx0 >= side - 1e-9 and wy0 >= foot - 1e-9 and low >= foot + FOOT_CLEAR - 1e-9) or attempt == 5:
            break
        side, foot = min(side, wx0 - 1.0), min(foot, wy0 - 1.0, low - FOOT_CLEAR)
    witt = _cleared(witt, "caption", w["wittenbauer"])
    energy = _caption_apart(energy, witt)
    ex0, ey0, _, ey1 = energy.bounds()
    dy = foot - 3.0 - turned.bounds()[3]
    inertia = _caption(inertia_turned(f, lang, length, foot - dy), w["inertia"]).moved(0.0, dy)
    if abs(el - length) > 1e-9:                        # I*(φ)'s own φ scale, under its μ_I
        mu = next(p for p in inertia.items if p.kind == "text" and p.text.startswith("μ_I ="))
        inertia.label((mu.points[0][0], mu.points[0][1] - line_pitch(mu.size)),
                      band_scale(turned_length(f, length), lang, TURNED_PRIME), size=mu.size, layer=mu.layer, step="axes I*_m")
    wx0, wy0, wx1, wy1 = witt.bounds()
    ix0, iy0, ix1, _ = inertia.bounds()
    boxes = {"energy": (ex0, ey0, side, ey1), "wittenbauer": (side, foot, wx1, wy1),
             "inertia": (ix0, iy0, ix1, foot)}
    return {"energy": energy, "wittenbauer": witt, "inertia": inertia}, boxes


def band_least(f: Flywheel, length: float) -> tuple[float, float]:
    """The least box (w, h mm) ``band`` can take at the φ axis ``length``, its lettering left out:
    the energy–mass diagram's ΔT axis (6 mm under the lowest of the curve, ΔT_k, k and l, 10 mm
    over the highest) over the turned I*(φ) (its φ axis ``length`` + 10 mm long, ≥ 14 mm under that
    axis's foot), and from ΔT(φ)'s axis (≥ ``length`` + 40.5 mm left of the I* axis) to the I*
    axis's end (14 mm right of the largest I*) — a band composed where this box does not fit need
    not be drawn to know it does not."""
    w, h = wittenbauer_least(f)
    return w + length + 37.5, h + turned_length(f, length) + 16.0


def wittenbauer_least(f: Flywheel) -> tuple[float, float]:
    """The least box (w, h mm) the energy–mass diagram (``wittenbauer_record``) can take, its
    lettering left out: its I* axis from −3 mm to 14 mm past the largest I* (or the curve's
    abscissa), its ΔT axis from 6 mm under the lowest of the curve, ΔT_k, k and l (and 0) to 10 mm
    over the highest."""
    X, Y = f.curve()
    v = np.concatenate([Y, f.dT, [f.tangent["k"], f.tangent["l"], 0.0]])
    return float(max(np.max(X), np.max(f.I))) + 17.0, float(v.max() - v.min()) + 16.0


def _union(parts: dict[str, Record]) -> Record:
    """The band as one drawing for the composition (its parts' items)."""
    rec = Record("band")
    for name in BAND:
        rec.extend(parts[name])
    return rec


def _band_shift(boxes: dict[str, tuple], box: tuple) -> tuple[float, float]:
    """How far the band moves to stand centred in ``box``."""
    x0 = min(b[0] for b in boxes.values())
    y0 = min(b[1] for b in boxes.values())
    x1 = max(b[2] for b in boxes.values())
    y1 = max(b[3] for b in boxes.values())
    return (box[0] + box[2]) / 2 - (x0 + x1) / 2, (box[1] + box[3]) / 2 - (y0 + y1) / 2


def nooks(boxes: dict[str, tuple]) -> list[tuple[float, float, float, float]]:
    """The room the band leaves at its lower left (its frame): ΔT(φ) stands left of the energy–mass
    diagram, the turned I*(φ) under the diagram only, so under ΔT(φ) and left of I*(φ) the band's
    box is empty — from the band's left side to GAP short of the turned I*(φ), from its foot to GAP
    under ΔT(φ)'s caption: that whole height where it clears the energy–mass diagram's side too
    (narrower), else from GAP under the diagram's foot (lower, as wide as to I*(φ)). None (an empty
    list) where I*(φ) reaches under ΔT(φ)."""
    x0 = min(b[0] for b in boxes.values())
    y0 = min(b[1] for b in boxes.values())
    ey0, (wx0, wy0), ix0 = boxes["energy"][1], boxes["wittenbauer"][:2], boxes["inertia"][0]
    out = [(x0, y0, min(ix0, wx0 if ey0 - GAP > wy0 else ix0) - GAP, ey0 - GAP),
           (x0, y0, ix0 - GAP, min(ey0, wy0) - GAP)]
    return [n for k, n in enumerate(out) if n[2] > x0 and n[3] > y0 and n not in out[:k]]


def with_motor(lines: list[str], fuller: list[str], height: float, width: float) -> list[str]:
    """The notes' lines with the motor's sentence (``fuller``: ``notes(…, motor=True)``) where they
    still fit the nook the notes stand in (``height`` × ``width`` mm: the construction chose it for
    the notes without that sentence, so the sheet keeps its composition), else ``lines`` — the
    sentence said where there is room (stop 47's six-bar: ~200 × 75 mm empty under the notes), as
    the terminal's ``dynamics`` always says it."""
    return fuller if notes_height([fuller], width) <= height + 1e-9 else lines


def nook_for(boxes: dict[str, tuple], lines: list[str], slack: float = 0.0):
    """The nook (``nooks``) that holds the notes' ``lines``, the first (the highest) that does, with
    the width they are set in — ``slack`` mm more at the left, where the band stands centred in a
    wider box —, or None."""
    for n in nooks(boxes):
        w = n[2] - n[0] + slack
        if w >= NOOK_NOTES and notes_height([lines], w) <= n[3] - n[1] + 1e-9:
            return n, w
    return None


def speed_nook(boxes: dict[str, tuple], speed: Leaf, lines: list[str]) -> tuple[tuple, float] | None:
    """The band's nook (``nooks``, its frame) that "nook" sets ω(φ) in with the notes' ``lines``
    under it, and its width: the largest by area that holds ``speed`` (ω(φ) at its smallest, no
    narrower than ``NOOK_SPEED``) over the notes set in its width — under a tall energy–mass
    diagram (the shaper's: l 330 mm under its I* axis) the room under ΔT(φ) was ~210 × 470 mm of
    paper while ω(φ) and the notes stood squeezed beside the tables — or None."""
    fit = []
    for n in nooks(boxes):
        w, h = n[2] - n[0], n[3] - n[1]
        if w >= max(NOOK_SPEED, speed.w) - 1e-9 and h >= speed.h + GAP + notes_height([lines], w) - 1e-9:
            fit.append((n, w))
    return max(fit, key=lambda m: (m[0][2] - m[0][0]) * (m[0][3] - m[0][1])) if fit else None


def speed_in_nook(per_lang, speed: Leaf, lines: list[list[str]]) -> bool:
    """Each language's band (``per_lang``: (boxes, width) pairs) has a nook that holds ω(φ) over
    that language's notes (``lines``, in the same order)."""
    return all(speed_nook(b, speed, ls) is not None for (b, _), ls in zip(per_lang, lines))


NOOK_NOTES = 120.0       # mm: the least width the notes are set in under ΔT(φ) (the column's: TITLE)


def _band_placed(parts: dict[str, Record], boxes: dict[str, tuple], box: tuple) -> list[Placed]:
    """The band's parts moved as one into ``box`` (centred), each with its own box."""
    dx, dy = _band_shift(boxes, box)
    return [Placed(name, parts[name].moved(dx, dy),
                   (boxes[name][0] + dx, boxes[name][1] + dy, boxes[name][2] + dx, boxes[name][3] + dy))
            for name in BAND]


def _band_size(boxes: dict[str, tuple]) -> tuple[float, float]:
    return (max(b[2] for b in boxes.values()) - min(b[0] for b in boxes.values()),
            max(b[3] for b in boxes.values()) - min(b[1] for b in boxes.values()))


def _tables(doc: dict, lang: str, factor: float, f: Flywheel) -> list[tuple[str, Record]]:
    """The three tables (``enlarged`` by ``factor``): Table 1 with the points added between its positions
    (``added_note``: not rows of it, so said under it), Table 2 (its marks' legend in the notes: ``marked``)."""
    return [(name, enlarged(make(doc, lang), factor)) for name, make in
            (("positions table", lambda d, l: positions_table(d, l, [added_note(f, l)] if f.added else [])),
             ("flywheel table", flywheel_table), ("motor table", motor_table))]


_BUILT: dict[tuple, tuple] = {}


def _built(dyn, args, L: float, size: float, energy: float | None = None) -> Flywheel:
    """The construction at (L, size): redrawn on more divisions where the first drawing's flywheel
    or M*_d is past the lab's 5 % (graphic.flywheel.redrawn; divisions the scene or the command
    gives are kept). Remembered per analysis (the very object), divisions, ruler and scales: the
    sheet draws the construction its search (``construction``) built already — the same object, so
    the drawings remembered per flywheel (``wittenbauer_record``, ``band``) are not drawn again.
    ``energy``: ΔT(φ)'s own μ_T (``finer_energy``), else the construction's rule."""
    divisions = getattr(args, "divisions", None)
    key = (id(dyn), divisions, args.precision, L, size, energy)
    hit = _BUILT.get(key)
    if hit is None or hit[0] is not dyn:
        if len(_BUILT) >= 64:
            _BUILT.pop(next(iter(_BUILT)))
        hit = _BUILT[key] = (dyn, redrawn(dyn, divisions, args.precision, L=L, size=size,
                                          given="option" if divisions is not None else None, energy=energy))
    return hit[1]


def _drawn(dyn, args, L: float, size: float, lang: str, f: Flywheel | None = None,
           energy: float | None = None) -> tuple[Flywheel, dict[str, Record]]:
    """The construction at (L, size) (``_built``, or ``f``) and its drawings captioned, ω(φ) at its
    smallest (``_speed`` grows it into its zone once the composition is chosen)."""
    f = f if f is not None else _built(dyn, args, L, size, energy)
    drawn = records(f, lang, speed_zone=(0.0, 0.0))
    return f, {name: captioned(drawn[name], WORDS[lang][name]) for name in DRAWINGS}


def _speed(f: Flywheel, lang: str, zone: tuple[float, float], aspect: float = SPEED_ASPECT,
           tallest: float = SPEED_TALLEST) -> Record:
    """ω(φ) captioned, as large as ``zone`` (w, h mm, the caption included) holds, no taller than
    ``aspect`` of its abscissa nor ``tallest`` (``speed_fitted``)."""
    w, h = zone
    probe = speed_fitted(f, lang, w, 0.0)
    h -= _wh(captioned(probe, WORDS[lang]["speed"]))[1] - _wh(probe)[1]   # the caption's height comes off
    return captioned(speed_fitted(f, lang, w, h, aspect, tallest), WORDS[lang]["speed"])


def speed_zone(shape: str, d: dict[str, Leaf], C: Leaf, W: float, H: float) -> tuple[float, float]:
    """The room ω(φ) owns once the other zones have theirs (LAYOUT.md: each zone's drawing as large
    as fits it): over the tables' column beside the left bands ("speed"), under the bands beside
    the column ("bands", "column"), beside the column under the moments ("side")."""
    middle = extent(d["band"])
    if shape == "speed":
        left = max(d["moments"].w, middle[0])
        return W - left - GAP, H - C.h - GAP
    if shape == "side":
        return W - middle[0] - C.w - 2 * GAP, H - d["moments"].h - GAP
    return W - C.w - GAP, H - d["moments"].h - middle[1] - 2 * GAP


CLASSICAL = ("bands", "column", "speed")


def _classical(shape: str, d: dict[str, Leaf], C: Leaf):
    """The classical composition (ΔT(φ) over I*(φ) on one φ axis beside the energy–mass diagram)
    that sets the construction's scales (L, size): the band of the projections drawn in its place
    keeps them, so the numbers do not depend on how the band is laid out."""
    middle = Row([Stack([d["energy"], d["inertia"]]), d["wittenbauer"]])
    if shape == "bands":
        return Stack([Row([d["moments"]]), middle, Row([d["speed"], C], flush=True)], flush=True)
    if shape == "speed":
        return Row([Stack([d["moments"], middle]), Stack([d["speed"], C], flush=True)], flush=True)
    return Row([Stack([d["moments"], middle, d["speed"]]), C], flush=True)


SHAPES = ("bands", "column", "speed", "nook", "side")
UPWARD = 2                    # the larger sizes tried for the energy–mass diagram (``larger``) …
UPWARD_L = 3                  # … each at the classical L and the next shorter ones of the series
UPWARD_SPARE = 60.0           # mm of the field's height left bare under the moments that a larger diagram may cost
NOOKED = ("nook", "side")     # the band at the right over the title block, the column at the left under the moments
NOOK_SPEED = 160.0            # mm: the least width of the nook "nook" sets ω(φ) and the notes in
NOOK_ASPECT = 1.0             # ω(φ) there as tall as its abscissa (the nook is narrow and tall: at ¾ the
#                               shaper's left ~90 mm of it empty between ω(φ) and the notes)


def _tree(shape: str, d: dict[str, Leaf], C: Leaf, foot: float = 0.0):
    """The dynamics sheet's composition: the moments and the work on one φ axis; the band of the
    energy–mass diagram (ΔT(φ) beside it, the turned I*(φ) under it: ``band``); ω(φ); the tables'
    column with the notes over the title block. "bands": those one under another, the column beside
    ω(φ); "column": the column the sheet's full height; "speed": ω(φ) over the column, beside the
    moments and the band; "side": the band at the right over the title block (``foot`` mm kept
    for it), the column and ω(φ) under the moments; "nook": as "side", ω(φ) in the band's nook
    under ΔT(φ) (``speed_nook``), the column alone under the moments."""
    middle = d["band"]
    if shape == "bands":
        return Stack([Row([d["moments"]]), middle, Row([d["speed"], C], flush=True)], flush=True)
    if shape == "speed":
        return Row([Stack([d["moments"], middle]), Stack([d["speed"], C], flush=True)], flush=True)
    if shape == "side":
        return Row([Stack([d["moments"], Row([C, d["speed"]])], flush=True),
                    Stack([middle, Leaf("title block", 0.0, foot)], flush=True)], flush=True)
    if shape == "nook":
        return Row([Stack([d["moments"], C], flush=True),
                    Stack([middle, Leaf("title block", 0.0, foot)], flush=True)], flush=True)
    return Row([Stack([d["moments"], middle, d["speed"]]), C], flush=True)


ROWED = 0     # ``parts``: the table of the positions over the results' tables side by side


def _tables_size(groups: list[list[Leaf]], parts: int) -> tuple[float, float]:
    """The tables' size: in columns (``column_size``), or ``ROWED`` the first group over the second's
    tables side by side."""
    if parts != ROWED:
        return column_size(groups)
    (first,), rest = groups
    return (max(first.w, column_size([[t] for t in rest])[0]),
            first.h + GAP + max(t.h for t in rest))


def _set_tables(groups: list[list[Leaf]], parts: int, right: float, top: float) -> list[Placed]:
    """The tables placed, their block's right side at ``right`` and top at ``top`` (``set_columns``;
    ``ROWED``: the first table at the block's left over the others in a row)."""
    if parts != ROWED:
        return set_columns(groups, right - column_size(groups)[0], top)
    left = right - _tables_size(groups, parts)[0]
    (first,), rest = groups
    return (set_columns([[first]], left, top)
            + set_columns([[t] for t in rest], left, top - first.h - GAP))


def _column(f: Form, tables: list[Leaf], parts: int, height, shape: str = "") -> tuple[Leaf, list[list[Leaf]], float]:
    """The tables over the notes, over the title block but in "side" (the column at the left);
    ``height`` None: the notes stand elsewhere (in the band's ``nook``). ``parts``: the tables in
    that many columns, or ``ROWED``."""
    groups = [tables[:1], tables[1:]] if parts == ROWED else split(tables, parts)
    cw, ch = _tables_size(groups, parts)
    width = max(cw, TITLE)
    foot = 0.0 if shape in NOOKED else GAP + keep_out(f)[3] - field_of(f)[1]
    return Leaf("column", width, ch + (0.0 if height is None else GAP + height(width)) + foot), groups, width


def _sizes(st: Study):
    """The (L, size) pairs tried, largest first: the scene's L where it gives one."""
    given = st.mech.task.flywheel.get("L_mm")
    if given:
        return tuple(dict.fromkeys((float(given), k) for _, k in SIZES))
    return SIZES


_CONSTRUCTIONS: dict[tuple, tuple] = {}
PRUNED = True      # ``larger`` asks ``held`` only for the bands it can take (``longer``); False: the plain search
ENERGY_MOST = A_HEIGHT        # mm (× size): ΔT's span drawn at its own finer scale no taller than A(φ)'s height
ENERGY_AXIS = 1               # … with the band's φ axis at most this many steps (``_lengths``) shorter than the one found
ENERGY_GAIN = 1.25            # … and ΔT drawn at least this much taller (the series' least step, 2 → 2.5)


def construction(st: Study, dyn, f: Form, args) -> tuple[float, float, float, str, int, float, bool, float | None]:
    """The flywheel construction the dynamics sheet of ``f`` draws and how: the largest abscissa L
    and heights' size at which the classical composition (``_classical``) fits one sheet (both
    languages measured) — the scales, hence every number, do not depend on the band's layout —;
    then the band of the projections (``band``) at the longest φ axis (``_lengths``) at which a
    composition (``SHAPES``) holds it on that sheet, the tables lettered 3.5 mm where that costs
    nothing, the notes in the band's ``nook`` where they fit it (the column then the tables' alone):
    (L, size, tables' factor, shape, table columns, the band's φ axis, notes in the nook, ΔT's own μ_T
    where the sheet holds it finer — ``finer_energy`` — else None); a set of sheets at
    those scales where none does (at the smallest where not even the classical one fits). The
    terminal's ``dynamics`` reports the same construction. The sizes are tried by halving the list
    (a larger size never fits where a smaller does not); each try draws the diagrams (a few ms).
    Remembered per mechanism, δ, format, divisions and precision (the language changes no
    construction: every size is measured in both): a scene's sheets each count the dynamics
    document's sheets (sheets/sheet.py ``pages_of``), and the A2/A3 set's search takes the A1
    sheet's |kl| (``_a1_kl``)."""
    if _table_overflow(st, dyn, f, args):          # no composition holds the table: the smallest scales
        L, size = _sizes(st)[-1]                   # (what the search would end at), nothing drawn
        return L, size, 1.0, "set", 1, _lengths(L)[-1], False, None
    key = _construction_key(st, dyn, f, args)
    if key not in _CONSTRUCTIONS:
        if len(_CONSTRUCTIONS) >= 64:
            _CONSTRUCTIONS.pop(next(iter(_CONSTRUCTIONS)))
        _CONSTRUCTIONS[key] = _construction(st, dyn, f, args)
    return _CONSTRUCTIONS[key]


_SCALES: dict[tuple, tuple[float, float]] = {}


def construction_scales(st: Study, dyn, f: Form, args) -> tuple[float, float]:
    """(L, size) of ``construction`` alone — what the A2/A3 set's search needs of the A1 sheet
    (``_a1_kl``): the classical composition's scales stand once the band holds at its shortest φ
    axis in some composition, whichever longer one the sheet then draws (not sought here)."""
    if _table_overflow(st, dyn, f, args):
        return _sizes(st)[-1]
    key = _construction_key(st, dyn, f, args)
    if key in _CONSTRUCTIONS:
        return _CONSTRUCTIONS[key][:2]
    if key not in _SCALES:
        if len(_SCALES) >= 64:
            _SCALES.pop(next(iter(_SCALES)))
        _SCALES[key] = _construction(st, dyn, f, args, scales_only=True)[:2]
    return _SCALES[key]


def _construction_key(st: Study, dyn, f: Form, args) -> tuple:
    """What a construction depends on: the mechanism, δ, the format, the divisions and the ruler
    (not the language: every drawing is measured in both)."""
    return (repr(st.mech), dyn.delta, f.name, f.width, f.height, getattr(args, "divisions", None), args.precision)


_MEMOS: dict[tuple, tuple] = {}


def _memo(st: Study, dyn, f: Form, args) -> dict:
    """What ``_construction`` measured per size (the drawings' and the bands' boxes in both languages,
    the tables' content, the notes), kept per construction key and analysis (the very object): the
    scene's other sheets count the dynamics document by a search that stops once one sheet is known
    to hold it (``one_sheet``), and the dynamics sheet's own search (``construction``) in the same
    process then measures nothing twice (stop 59: the shaper's kinematics sheet, numbered, took 14 s
    cold, the dynamics count half of it)."""
    key = _construction_key(st, dyn, f, args)
    hit = _MEMOS.get(key)
    if hit is None or hit[0] is not dyn:
        if len(_MEMOS) >= 8:
            _MEMOS.pop(next(iter(_MEMOS)))
        hit = _MEMOS[key] = (dyn, {})
    return hit[1]


def _construction(st: Study, dyn, f: Form, args, scales_only: bool = False, upward: bool = True,
                  count_only: bool = False) -> tuple | None:
    """``construction`` computed (its table of the positions known to fit a sheet); ``scales_only``:
    (L, size) as soon as they are known to stand (``construction_scales``); ``count_only``: the first
    one-sheet composition the search finds (``held``; not yet the larger diagram, ``larger``, nor ΔT's
    finer scale, ``finer_energy``: neither changes whether one sheet holds it), None where a set of
    sheets is drawn (``one_sheet``)."""
    x0, y0, x1, y1 = field_of(f)
    W, H = x1 - x0, y1 - y0
    sizes = _sizes(st)

    memo = _memo(st, dyn, f, args)
    drawn_at: dict = memo.setdefault("drawn_at", {})
    banded: dict = memo.setdefault("banded", {})
    built_at: dict = memo.setdefault("built_at", {})
    mu_T: list = [None]          # ΔT(φ)'s own scale the search tries (``finer_energy``); None: the rule's

    def built(L: float, size: float) -> Flywheel:      # the construction once for both languages
        if (L, size, mu_T[0]) not in built_at:
            built_at[(L, size, mu_T[0])] = _built(dyn, args, L, size, mu_T[0])
        return built_at[(L, size, mu_T[0])]

    def measured(L: float, size: float, factor: float):
        if (L, size, mu_T[0]) not in drawn_at:    # the drawings and the tables' content once per size
            per = []
            built_ = built(L, size)
            for lang in LANGS:
                fw, drawn = _drawn(dyn, args, L, size, lang, built_)
                doc = dynamics_json(fw)
                per.append((lang, {n: _wh(r) for n, r in drawn.items()}, doc, lines_of(notes(fw, doc, lang)), fw))
            drawn_at[(L, size, mu_T[0])] = per
        per = drawn_at[(L, size, mu_T[0])]
        leaves = {name: Leaf(name, max(p[1][name][0] for p in per), max(p[1][name][1] for p in per))
                  for name in per[0][1]}
        tabs = [[(name, *_wh(rec)) for name, rec in _tables(doc, lang, factor, fw_)] for lang, _, doc, _, fw_ in per]
        tables = [Leaf(a[0], max(a[1], b[1]), max(a[2], b[2])) for a, b in zip(*tabs)]
        return leaves, tables, [p[3] for p in per], per

    def band_leaf(L: float, size: float, length: float) -> Leaf:
        return band_and_nooks(L, size, length)[0]

    def band_and_nooks(L: float, size: float, length: float):
        """The band's leaf (both languages) and each language's band: its boxes and width (``nooks``)."""
        if (L, size, length, mu_T[0]) not in banded:    # the band in both languages (its captions differ)
            bx = [band(built(L, size), lang, length)[1] for lang in LANGS]
            wh = [_band_size(b) for b in bx]
            banded[(L, size, length, mu_T[0])] = (Leaf("band", max(a[0] for a in wh), max(a[1] for a in wh)),
                                                  [(b, w) for b, (w, _) in zip(bx, wh)])
        return banded[(L, size, length, mu_T[0])]

    def notes_in_nook(boxes_, per, shape: str, C: Leaf, leaves: dict[str, Leaf]) -> bool:
        """Each language's notes in its band's nook, the band centred in the box the composition
        gives it with that language's drawings (ω(φ) at its smallest: the box only grows)."""
        for (b, bw), p in zip(boxes_, per):
            own = {name: Leaf(name, *wh) for name, wh in p[1].items()}
            own["band"] = leaves["band"]
            if nook_for(b, p[3], (band_room(_tree(shape, own, C, foot)) - bw) / 2) is None:
                return False
        return True

    def band_room(tree) -> float:              # the width of the box the composition gives the band
        return next(b[2] - b[0] for leaf, b in arrange(tree, (0.0, 0.0, W, H)) if leaf.name == "band")

    drawn_bands: dict = memo.setdefault("drawn_bands", {})

    def notes_in_widened(L: float, size: float, length: float, shape: str, C: Leaf, leaves: dict[str, Leaf],
                         per) -> bool:
        """Each language's notes in the nook of the band the sheet draws with ΔT(φ) widened
        (``widened``: under the longer ΔT(φ) the nook is wider — stop 49's sieve drive: the notes
        then leave the tables' column, ~335 × 100 mm empty under ΔT(φ) before)."""
        fw_ = built(L, size)

        def make(lang: str, el: float):
            if (L, size, length, lang, el, mu_T[0]) not in drawn_bands:
                drawn_bands[(L, size, length, lang, el, mu_T[0])] = band(fw_, lang, length, el)
            return drawn_bands[(L, size, length, lang, el, mu_T[0])]
        zones = [({**{name: Leaf(name, *wh) for name, wh in p[1].items()}, "band": leaves["band"]}, C) for p in per]
        got = widened(fw_, length, zones, shape, foot, (0.0, 0.0, W, H), make)
        if got is None:
            return False
        for p in per:
            boxes_ = got[1][p[0]][1]
            own = {**{name: Leaf(name, *wh) for name, wh in p[1].items()}, "band": got[2]}
            slack = (band_room(_tree(shape, own, C, foot)) - _band_size(boxes_)[0]) / 2
            if nook_for(boxes_, p[3], slack) is None:
                return False
        return True

    foot = keep_out(f)[3] - y0

    def fit(k: int):                      # the scales: as the classical composition sets them
        L, size = sizes[k]
        fw = built(L, size)                # every one stacks the energy–mass diagram under the moments:
        (mw, mh), (ww, wh) = moments_least(fw), wittenbauer_least(fw)     # where their least boxes
        if max(mw, ww) > W + 1e-9 or mh + wh > H + 1e-9:                  # do not fit, none is drawn
            return None
        for factor in (TABLES, 1.0):
            leaves, tables, notes_, _ = measured(L, size, factor)
            for shape in CLASSICAL:
                for parts in (1, 2, 3):
                    C = _column(f, tables, parts, lambda w: notes_height(notes_, w))[0]
                    tw, th = extent(_classical(shape, leaves, C))
                    if tw <= W + 1e-9 and th <= H + 1e-9:
                        return L, size
        return None
    lo, hi, found = 0, len(sizes) - 1, None
    while lo <= hi:                      # the first (largest) size that fits
        k = (lo + hi) // 2
        got = fit(k)
        if got is not None:
            found, hi = got, k - 1
        else:
            lo = k + 1
    L, size = found if found is not None else sizes[-1]

    def least_holds(leaves, tables, notes_, least: Leaf) -> bool:
        """Some composition ``held`` tries fits the field with the band at its least box (``band_least``):
        arithmetic alone — a drawn band is never smaller, and the compositions' extents grow with their
        leaves, so where this fails no band drawn at that φ axis would be held (the tests left out
        here, the notes' and ω(φ)'s nooks, only take compositions away)."""
        trial = {**leaves, "band": least}
        for in_nook in (True, False):
            for shape in SHAPES:
                if in_nook and shape in NOOKED:
                    continue
                for parts in (1, 2, 3):
                    C = _column(f, tables, parts, None if in_nook or shape == "nook"
                                else lambda w: notes_height(notes_, w), shape)[0]
                    tw, th = extent(_tree(shape, trial, C, foot))
                    if tw <= W + 1e-9 and th <= H + 1e-9:
                        return True
        return False

    def held(L: float, size: float, quick: bool = scales_only, least: float = 0.0, longer: float | None = None):
        """The band at its longest φ axis some composition holds at (L, size) (the notes in the band's
        nook where they fit it), or None; ``quick``: (L, size) where it holds at its shortest;
        ``least``: no φ axis shorter than this tried; ``longer``: the same answer where its φ axis is
        at least this long, else None (``larger`` takes no other: the bands it cannot take are not
        drawn where they decide nothing — the drag-link's dynamics sheet drew 128 bands)."""
        if quick:                         # the band at its shortest φ axis (the notes in the column)
            shortest = _lengths(L)[-1]
            for factor in (TABLES, 1.0):
                leaves, tables, notes_, _ = measured(L, size, factor)
                leaves["band"] = band_leaf(L, size, shortest)
                for shape in SHAPES:
                    if shape == "nook" and not speed_in_nook(band_and_nooks(L, size, shortest)[1], leaves["speed"],
                                                             notes_):
                        continue
                    for parts in (1, 2, 3):
                        C = _column(f, tables, parts, None if shape == "nook" else lambda w: notes_height(notes_, w),
                                    shape)[0]
                        tw, th = extent(_tree(shape, leaves, C, foot))
                        if tw <= W + 1e-9 and th <= H + 1e-9:
                            return L, size
            return None
        if longer is None:
            for factor in (TABLES, 1.0):
                got = scanned(L, size, factor, least)
                if got is not None:
                    return got
            return None
        # only a band at least ``longer`` long counts (``larger``): the search's answer is the first
        # found in the order (3.5-mm tables, φ axes ≥ longer), (3.5 mm, shorter), (2.5 mm, ≥ longer),
        # (2.5 mm, shorter) and counts only from the first or the third; the second is looked at
        # (its bands drawn) only where the third finds one, the fourth never — the same answer
        got = scanned(L, size, TABLES, max(least, longer))
        if got is not None:
            return got
        got = scanned(L, size, 1.0, max(least, longer))
        if got is None or scanned(L, size, TABLES, least, longer) is not None:
            return None
        return got

    def scanned(L: float, size: float, factor: float, least: float, below: float | None = None):
        """``held``'s search with the tables' lettering ``factor``: the first composition that holds
        the band, its φ axes from the longest down to ``least`` (only those shorter than ``below``,
        where given), or None."""
        leaves, tables, notes_, per = measured(L, size, factor)
        for length in _lengths(L):
            if below is not None and length >= below - 1e-9:
                continue
            if length < least - 1e-9:
                break
            box = band_least(built(L, size), length)        # no composition holds a band wider or
            if box[0] > W + 1e-9 or box[1] > H + 1e-9:       # taller than the field: not drawn
                continue
            if not least_holds(leaves, tables, notes_, Leaf("band", *box)):   # nor where no composition
                continue                     # holds even its least box (stop 58: LINK57 drew 152 bands)
            leaves["band"], nooks = band_and_nooks(L, size, length)
            # the notes in the band's nook where they fit it (the column then holds the tables alone)
            for in_nook in (True, False):
                for shape in SHAPES:
                    if in_nook and shape in NOOKED:     # the band at the right: no nook under ΔT(φ)
                        continue                        # for the notes (or ω(φ) holds it: "nook")
                    if shape == "nook" and not speed_in_nook(nooks, leaves["speed"], notes_):
                        continue                        # ω(φ) over the notes in the band's nook
                    for parts in (1, 2, 3):
                        C = _column(f, tables, parts, None if in_nook or shape == "nook"
                                    else lambda w: notes_height(notes_, w), shape)[0]
                        tree = _tree(shape, leaves, C, foot)
                        tw, th = extent(tree)
                        if tw <= W + 1e-9 and th <= H + 1e-9 and (
                                not in_nook or notes_in_nook(nooks, per, shape, C, leaves)
                                or notes_in_widened(L, size, length, shape, C, leaves, per)):
                            if shape == "speed" and parts == 1 and rowed(leaves, tables, shape, foot, in_nook,
                                                                        notes_):
                                parts = ROWED
                            return L, size, factor, shape, parts, length, in_nook
        return None

    def larger(found_: tuple[float, float]):
        """The sheet's main construction first (LAYOUT.md): the energy–mass diagram (its scales μ_I, μ_T
        set by ``size`` alone) at the next larger sizes (``UPWARD``), the moments' abscissa L as long as
        the classical composition's or shorter (``UPWARD_L`` steps of the series), where a composition
        holds the band there with a φ axis no shorter than at the classical scales at the right beside the
        moments ("nook", "side": ω(φ), a secondary chart, in the room that remains under ΔT(φ) or the
        moments — in "speed" it would take the whole room right of them again: s1_cylinder at 1.15,
        ~430 × 250 mm) and leaves no more than ``UPWARD_SPARE`` mm bare under the moments (``adrift``). The classical composition stacks the diagram under the moments
        and ends height-bound at L 330 (the crusher: the diagram ~100 × 190 mm, ω(φ) ~380 × 260 beside
        it; review 54 #15), where the band at the right beside shorter moments holds it larger."""
        base = held(*found_, quick=False)
        if base is None:
            return None
        ups = sorted({k for _, k in sizes if k > found_[1] + 1e-9})[:UPWARD]
        Ls = sorted({L_ for L_, _ in sizes if L_ <= found_[0] + 1e-9}, reverse=True)[:UPWARD_L]
        for size_ in reversed(ups):
            for L_ in Ls:
                if may_hold(L_, size_):
                    got = held(L_, size_, quick=False, longer=base[5] if PRUNED else None)
                    if got is not None and got[3] in NOOKED and got[5] >= base[5] - 1e-9 and not adrift(got):
                        return got
        return base

    def adrift(got) -> bool:
        """The band at the right ("nook", "side") leaves more than ``UPWARD_SPARE`` mm of the field's
        height empty under the moments and the column there (s1_cylinder at 1.5: the tables 2.5 mm
        high ~150 mm under the short moments, ~600 × 150 mm of bare paper): the larger diagram then
        costs the sheet more than it gains."""
        L_, size_, factor, shape, parts, _, in_nook = got
        if shape not in NOOKED:
            return False
        leaves, tables, notes_, _ = measured(L_, size_, factor)
        C = _column(f, tables, parts, None if in_nook or shape == "nook" else lambda w: notes_height(notes_, w),
                    shape)[0]
        under = C.h if shape == "nook" else max(C.h, leaves["speed"].h)
        return H - (leaves["moments"].h + GAP + under) > UPWARD_SPARE + 1e-9

    def may_hold(L: float, size: float) -> bool:
        """The moments' and the band's least boxes (at its shortest φ axis) fit the field in some
        composition: the band under the moments, or at the right beside them over the title block —
        nothing drawn where they do not (``held`` draws every drawing in both languages)."""
        fw = built(L, size)
        (mw, mh), (bw, bh) = moments_least(fw), band_least(fw, _lengths(L)[-1])
        return ((max(mw, bw) <= W + 1e-9 and mh + bh <= H + 1e-9)
                or (mw + bw <= W + 1e-9 and bh + foot <= H + 1e-9))

    def rowed(leaves, tables, shape: str, foot_: float, in_nook: bool, notes_) -> bool:
        """ω(φ) over the column beside the moments and the band ("speed") spans the room right of
        them, the one column of tables only its width: the results' tables side by side under the
        positions' (``ROWED``) where the sheet still holds it — the column shorter, ω(φ) taller, no
        strip of paper left of the tables (the compressor: ~140 × 400 mm); so too the column alone
        under the moments ("nook": the shaper's Tables 2 and 3 left ~150 × 200 mm beside them)."""
        C = _column(f, tables, ROWED, None if in_nook or shape == "nook" else lambda w: notes_height(notes_, w),
                    shape)[0]
        tw, th = extent(_tree(shape, leaves, C, foot_))
        return tw <= W + 1e-9 and th <= H + 1e-9

    def finer_energy(got: tuple) -> tuple:
        """``got`` (a one-sheet composition) with ΔT(φ) and the energy–mass diagram at ΔT's own finer
        scale where the sheet has room for it (LAYOUT.md: each drawing at the largest standard scale
        that fits its zone; the agitator's ΔT(φ) 38 mm tall beside ~340 × 150 mm of bare paper): the
        series' values finer than the construction's μ_T by a step at least (``ENERGY_GAIN``: μ_A = 1,047 J/mm is
        not redrawn at 1 J/mm; ``series_choices``) that draw ΔT's span no
        taller than ``ENERGY_MOST`` (A(φ)'s, whose ordinates it is read from), tried from the smallest
        step up while a composition still holds the band at the same scales L, size with a φ axis at
        most ``ENERGY_AXIS`` steps of ``_lengths`` shorter than the one found (the φ axes are free: no
        number depends on them; ΔT's scale sets |kl|) — the last that holds is drawn (a finer μ_T draws
        every ΔT taller, so where one does not hold no finer one does). The flywheel's J = μ_T·|kl|/(ω_m²·δ)
        is read off a longer |kl|: the ruler's 0.5 mm a smaller share of it. ``got`` with μ_T appended
        (None: the rule's own, ``own_energy_scale``)."""
        L_, size_, length = got[0], got[1], got[5]
        axes = _lengths(L_)
        at = next((k for k, g_ in enumerate(axes) if g_ <= length + 1e-9), len(axes) - 1)
        least = axes[min(at + ENERGY_AXIS, len(axes) - 1)]
        fw = built(L_, size_)
        span = float(np.ptp(fw.dT)) * fw.mu_T
        best = got + (None,)
        for m in reversed(series_choices(span, fw.mu_T, ENERGY_MOST * size_)):   # the smallest step first
            if m > fw.mu_T / ENERGY_GAIN * (1 + 1e-9):      # not a step: μ_A 1,047 → 1 J/mm drew ΔT 5 % taller
                continue
            mu_T[0] = m
            try:
                g = held(L_, size_, quick=False, least=least)
            finally:
                mu_T[0] = None
            if g is None or g[:2] != (L_, size_):
                break
            best = g + (m,)
        return best

    floor = one_sheet_floor(st, dyn, f, args)
    if found is not None:                 # the band: the largest scales from the classical ones down at
        start = sizes.index(found)        # which a composition holds it on one sheet (the compressor's
        got = None                        # moments 348 mm tall at 1.5 left no room for any band there:
        if upward and abs(built(*found).kl) >= floor - 1e-9:      # its one A1 sheet came out as three)
            # the energy–mass diagram first (``larger``: None exactly where ``held`` at ``found`` is)
            got = held(*found, quick=False) if count_only else larger(found)
        if got is not None:
            return got[:2] if scales_only else got if count_only else finer_energy(got)
        for k in range(start, len(sizes)):
            if k > start and fit(k) is None:
                continue
            if abs(built(*sizes[k]).kl) < floor - 1e-9:   # shrunk below reading: a set of sheets instead
                break
            got = held(*sizes[k])
            if got is not None:
                return got[:2] if scales_only else got if count_only else finer_energy(got)
    if count_only:
        return None
    # else a set of sheets: each drawing at the scales a sheet of its own holds

    def on_a_page(b: Leaf) -> bool:       # over a later sheet's title block, or beside it
        return _fits_later(f, b)

    moments_at: dict = memo.setdefault("moments_at", {})

    def moments_leaf(L: float, size: float) -> Leaf:      # the moments and the work alone, both languages
        if (L, size) in drawn_at:
            return measured(L, size, 1.0)[0]["moments"]
        if (L, size) not in moments_at:      # once per size: both searches (``_set_scales``) ask for it
            fw = built(L, size)
            wh = [_wh(captioned(moments_record(fw, lang), WORDS[lang]["moments"])) for lang in LANGS]
            moments_at[(L, size)] = (max(a[0] for a in wh), max(a[1] for a in wh))
        return Leaf("moments", *moments_at[(L, size)])

    def fits(L: float, size: float, first: bool = False) -> bool:   # the moments, then the band: only
        fw, length = built(L, size), _lengths(L)[-1]   # what decides, each drawn only where its least box fits
        fit_m = _fits_first if first else _fits_later  # the moments on the first sheet (form 1) or a later one
        return (fit_m(f, Leaf("moments", *moments_least(fw))) and fit_m(f, moments_leaf(L, size))
                and _fits_later(f, Leaf("band", *band_least(fw, length))) and _fits_later(f, band_leaf(L, size, length)))

    def kl(L: float, size: float) -> float:       # read off the construction: nothing drawn
        return abs(built(L, size).kl)
    classical = _a1_kl(st, dyn, f, args)
    # the search aims at the |kl| the A1 sheet draws (ΔT at its own finer μ_T, or its larger diagram:
    # ``a1_drawn_kl``), the one the set's note compares with — stop 60's note said 113 mm where the
    # search had aimed at LINK53's classical 74; the order of the work is left (the tables first) only
    # where it does not read the flywheel to ``ORDERED_READ`` by the ruler (review 61 #4; before, where
    # it did not read the classical composition's |kl|)
    target = None if classical is None else max(classical, a1_drawn_kl(st, dyn, args))
    # the moments on the first sheet (the set in the order of the work) where that reads the flywheel
    # to ``ORDERED_READ``; else at the scales a later sheet holds (the tables then go first)
    first_fits = lambda L_, s_: fits(L_, s_, True)      # noqa: E731
    ordered = _set_scales(sizes, first_fits, kl, target, (L, size))
    in_order = first_fits(*ordered) and kl(*ordered) >= args.precision / ORDERED_READ - 1e-9
    if target is not None and in_order and kl(*ordered) < target - 1e-9:
        # in the order of the work the flywheel is read (to ``ORDERED_READ`` by the ruler): the A1
        # sheet's |kl| sought in that order alone, else the note says how far short — a set is read
        # from its form 1 on, the construction before the results (review 61 #4: b_gate's A3 set
        # put Tables 1–3 and ω(φ) on its first sheet, M*(φ) and the band after them, for the
        # classical |kl| the order of the work fell short of)
        L, size, why = _reach(sizes, first_fits, kl, target, args.precision, f, ordered)
        why = _on_first(why)
        if why is not None:
            if len(_SHORT) >= 64:
                _SHORT.pop(next(iter(_SHORT)))
            why = _too_tall(sizes, target, args.precision, f) or why
            _SHORT[_construction_key(st, dyn, f, args)] = Shortfall(kl(L, size), target, f.name, *why,
                                                                    drawn=target)
    elif target is None or kl(*ordered) >= target - 1e-9:
        L, size = ordered
    else:
        L, size = _set_scales(sizes, fits, kl, target, (L, size))
        if kl(L, size) < target - 1e-9:      # the search's steps may pass a scale that reads it: any?
            L, size, why = _reach(sizes, fits, kl, target, args.precision, f, (L, size))
            out = why is not None
            if out and target > classical + 1e-9:
                # the drawn |kl| out of reach: the classical one where a later sheet reads it (only
                # where the order of the work reads less than ``ORDERED_READ``: see ``in_order``)
                Lc, sc = _set_scales(sizes, fits, kl, classical, (L, size))
                if kl(Lc, sc) < classical - 1e-9:
                    Lc, sc, gone = _reach(sizes, fits, kl, classical, args.precision, f, (Lc, sc))
                    out = gone is not None
                else:
                    out = False
                if kl(Lc, sc) > kl(L, size) + 1e-9:
                    L, size = Lc, sc
            if out and kl(*ordered) >= args.precision / ORDERED_READ - 1e-9:
                # the A1 sheet's |kl| out of reach either way: the set in the order of the work (review 7
                # #12: its first sheet the tables), the flywheel still read to ORDERED_READ by the ruler
                (L, size), why = ordered, _on_first(_reach(sizes, lambda L_, s_: fits(L_, s_, True), kl, target,
                                                           args.precision, f, ordered)[2])
            if why is not None:
                if len(_SHORT) >= 64:
                    _SHORT.pop(next(iter(_SHORT)))
                drawn = max(a1_drawn_kl(st, dyn, args), target)      # what the note compares with; at it
                why = _too_tall(sizes, drawn, args.precision, f) or why   # the band may be past any sheet
                _SHORT[_construction_key(st, dyn, f, args)] = Shortfall(kl(L, size), target, f.name, *why,
                                                                        drawn=drawn)
    def band_length(L_: float, size_: float) -> float:     # the band's longest φ axis a later sheet holds
        return next((g for g in _lengths(L_) if on_a_page(Leaf("band", *band_least(built(L_, size_), g)))
                     and on_a_page(band_leaf(L_, size_, g))), _lengths(L_)[-1])

    def sheets(L_: float, size_: float) -> tuple[int, int]:
        """The set laid out at (L_, size_) as the sheet lays it (``_set_laid``), the worse language:
        its sheets that hold no drawing (tables and notes only), then its count of sheets."""
        fw_, g = built(L_, size_), band_length(L_, size_)
        short_ = _SHORT.get(key)
        short_ = replace(short_, kl=kl(L_, size_)) if short_ is not None else None
        bw = [_band_size(band(fw_, other, g)[1]) for other in LANGS]
        worst = (0, 0)
        for lang in LANGS:
            _, drawn = _drawn(dyn, args, L_, size_, lang, fw_)
            doc = dynamics_json(fw_)
            leaves_ = {"moments": Leaf("moments", record=drawn["moments"]),
                       "band": Leaf("band", max(a[0] for a in bw), max(a[1] for a in bw),
                                    record=_union(band(fw_, lang, g)[0]))}
            tables_ = [Leaf(name, record=rec) for name, rec in _tables(doc, lang, 1.0, fw_)]
            laid = _set_laid(f, fw_, doc, lang, leaves_, tables_, 1.0, g, lines_of(notes(fw_, doc, lang, short_)))[0]
            if laid is None:
                return (10 ** 6, 10 ** 6)
            bare = sum(1 for page in laid if not {leaf.name for leaf, _ in page if leaf.record is not None} & SET_DRAWN)
            worst = max(worst, (bare, len(laid)))
        return worst
    # judged by its sheets: where the set leaves a sheet with only tables and notes (the compressor's
    # A3 set at L 300: the English notes no longer fit under the band, Tables 2–3 and the notes alone
    # on a fourth sheet), the next shorter L (``SET_PATIENCE`` of them) at the same size that every
    # sheet of the set holds as the search required and that reads the flywheel as the search did
    # (|kl| the A1 sheet's where it reached it, else to ``ORDERED_READ``) and lays no such sheet
    key = _construction_key(st, dyn, f, args)
    at = sheets(L, size)
    if at[0] > 0:
        first = fits(L, size, True)
        floor = (target if target is not None and kl(L, size) >= target - 1e-9
                 else classical if classical is not None and kl(L, size) >= classical - 1e-9   # as it reads
                 else args.precision / ORDERED_READ)
        low = min(L_ for L_, _ in sizes)
        for step in range(1, SET_PATIENCE + 1):
            L_ = L - SET_L_STEP * step
            if L_ < low - 1e-9 or kl(L_, size) < floor - 1e-9 or not fits(L_, size, first):
                continue
            got = sheets(L_, size)
            if got[0] == 0 and got[1] <= at[1]:
                L = L_
                if key in _SHORT:
                    _SHORT[key] = replace(_SHORT[key], kl=kl(L, size))
                break
    return L, size, 1.0, "set", 1, band_length(L, size), False, None


ORDERED_READ = 0.02      # a set out of the order of the work (its tables first) only where in order |kl| would
#                          be so short that the ruler's precision is more than this share of it (0.5 mm of 25 mm:
#                          I_fl ∝ |kl| read to 2 %, well within the lab's 5 %; review 3's set had 2.9 %)
SET_SIZES = (1.5, 1.3, 1.2, 1.15, 1.1, 1.05, 1.0, 0.9, 0.8, 0.7, 0.6, 0.55, 0.5, 0.45, 0.4, 0.35, 0.3)
SET_L_STEP = 10.0        # mm: the set's abscissae L tried, from the longest down
SET_PATIENCE = 3         # L tried past the largest |kl| found before a set settles for it
SET_DRAWN = {"moments", "band", "speed"}    # a set's drawings: each of its sheets holds one


def _later_keep(f: Form) -> tuple[float, float, float, float]:
    """The title block form 2a (185×15 mm) of a set's later sheets with its clearance (``keep_out``)."""
    from graphplan.sheets.form import BLOCK_2A_H, BLOCK_W
    _, fy0, fx1, _ = f.frame_box
    return fx1 - BLOCK_W - GAP, fy0, fx1, fy0 + BLOCK_2A_H + GAP


def _fits_later(f: Form, b: Leaf) -> bool:
    """``b`` fits a set's later sheet: over its title block form 2a, or beside it."""
    x0, y0, x1, y1 = field_of(f)
    k = _later_keep(f)
    return b.w <= x1 - x0 + 1e-9 and (b.h <= y1 - k[3] + 1e-9 or (b.w <= k[0] - x0 + 1e-9 and b.h <= y1 - y0 + 1e-9))


def _fits_first(f: Form, b: Leaf) -> bool:
    """``b`` fits a set's first sheet: over its title block (form 1), or beside it — where the set's
    first drawing, the moments, goes (a set reads in the order of the work)."""
    x0, y0, x1, y1 = field_of(f)
    k = keep_out(f)
    return b.w <= x1 - x0 + 1e-9 and (b.h <= y1 - k[3] + 1e-9 or (b.w <= k[0] - x0 + 1e-9 and b.h <= y1 - y0 + 1e-9))


def one_sheet_floor(st: Study, dyn, f: Form, args) -> float:
    """The least |kl| (mm) a sheet smaller than A1 may read the flywheel off where it holds the whole
    analysis on one sheet: a set's floor (the ruler's ``precision`` over ``ORDERED_READ``: I_fl ∝ |kl|
    read to 2 %), never more than the A1 sheet's own |kl|; 0 on A1. LAYOUT.md: "a drawing shrunk below
    its legibility minimum to fit is not (use a set of sheets then)" — LINK53's one A2 sheet read
    |kl| = 18 mm, its energy–mass diagram 11 mm wide, against 74 mm on A1."""
    target = _a1_kl(st, dyn, f, args)
    if target is None:
        return 0.0
    return min(target, args.precision / ORDERED_READ)


def _a1_kl(st: Study, dyn, f: Form, args) -> float | None:
    """|kl| of the energy–mass diagram on the A1 sheet (the reading error a set must not make worse:
    the ruler's 0.5 mm over |kl|), or None on A1 itself."""
    if f.name == "A1":
        return None
    L, size = _classical_scales(st, dyn, form("A1"), args)
    return abs(_built(dyn, args, L, size).kl)


def a1_drawn_kl(st: Study, dyn, args) -> float:
    """|kl| of the energy–mass diagram as the A1 sheet draws it: at its construction's scales and
    ΔT's own finer μ_T where it has one (``construction``, ``finer_energy``) — what a set's note
    compares with (``short_note``) and since stop 61 what the set's search aims at (``_a1_kl``, the
    classical composition's scales, only bounds where the set may leave the order of the work: the
    slotter's A2 set aimed at the larger diagram lost its order). The A1 sheet draws ΔT finer since
    stop 59, or the larger diagram, and the note understated its |kl| (LINK53's A3 set: 74 mm against
    the 113 drawn; the shaper's: 171.5 against 217.5). The whole A1 search runs (remembered per
    process)."""
    A1 = form("A1")
    c = construction(st, dyn, A1, args)
    return abs(_built(dyn, args, c[0], c[1], c[7]).kl)


def _classical_scales(st: Study, dyn, f: Form, args) -> tuple[float, float]:
    """``construction_scales`` without the larger energy–mass diagram (``larger``): the scales the set's
    target |kl| is read at (the slotter's A2 set aimed at the A1 sheet's |kl| at 1.5 no longer held
    its moments on the first sheet: its tables came first)."""
    if _table_overflow(st, dyn, f, args):
        return _sizes(st)[-1]
    key = ("classical",) + _construction_key(st, dyn, f, args)
    if key not in _SCALES:
        if len(_SCALES) >= 64:
            _SCALES.pop(next(iter(_SCALES)))
        _SCALES[key] = _construction(st, dyn, f, args, scales_only=True, upward=False)[:2]
    return _SCALES[key]


def _on_first(why: tuple | None) -> tuple | None:
    """``_reach``'s "none" where the search kept the moments on the first sheet (the order of the work):
    the note says no scale reads |kl| *in that order* ("first") — a later sheet may hold a scale that
    would, with the tables before the construction (review 61 #4: the gate's A3 note said no scale that
    fits an A3 sheet reads 60,5 mm, while 63,5 mm fitted a later sheet)."""
    return ("first", *why[1:]) if why is not None and why[0] == "none" else why


@dataclass(frozen=True)
class Shortfall:
    """Why a set's energy–mass diagram reads |kl| short of the A1 sheet's (``_reach``): ``kind``
    "tall" — at the A1 sheet's |kl| the diagram with I*(φ) turned under it would be at least
    ``need`` mm tall where a sheet of the set holds ``room`` mm —, "none" — no scale of the
    set's grid (L from ``low`` to ``top`` mm) that a sheet holds reads it —, or "first" — none does
    with the moments on the first sheet, the order of the work the set keeps (``_on_first``)."""
    kl: float
    target: float
    format: str
    kind: str
    need: float = 0.0
    room: float = 0.0
    low: float = 0.0
    top: float = 0.0
    drawn: float | None = None      # |kl| the A1 sheet draws (``a1_drawn_kl``), where it is not ``target``

    @property
    def a1(self) -> float:
        """|kl| on the A1 sheet as it is drawn: ``drawn``, else the search's ``target``."""
        return self.target if self.drawn is None else max(self.drawn, self.target)


_SHORT: dict[tuple, Shortfall] = {}


def shortfall(st: Study, dyn, f: Form, args) -> Shortfall | None:
    """Where the set of ``f`` draws the energy–mass diagram at a |kl| short of the A1 sheet's, why
    (``Shortfall``, for the notes); else None."""
    if _table_overflow(st, dyn, f, args) or construction(st, dyn, f, args)[3] != "set":
        return None
    return _SHORT.get(_construction_key(st, dyn, f, args))


def _set_grid(sizes) -> list[float]:
    """The abscissae L a set tries, the longest first, ``SET_L_STEP`` apart."""
    Ls = sorted({L for L, _ in sizes}, reverse=True)
    if len(Ls) > 1:
        top, low = Ls[0], Ls[-1]
        Ls = [top - SET_L_STEP * k for k in range(int((top - low) / SET_L_STEP) + 1)]
    return Ls


def _reach(sizes, fits, kl, target: float, precision: float, f: Form, found: tuple[float, float]):
    """The set's scales where ``_set_scales`` stopped short of ``target``: the first pair of the grid
    (L the longest first, then the size the largest) whose |kl| reaches it and whose drawings fit a
    sheet, with None; else ``found`` and why none does (``Shortfall``'s kind and numbers). The
    energy–mass diagram's ΔT axis spans k and l, so at |kl| ≥ target the band is at least target −
    precision/2 + its shortest φ axis + 32 mm tall (``band_least``): where no sheet of ``f`` is that
    tall, no pair is tried."""
    Ls = _set_grid(sizes)
    tall = _too_tall(sizes, target, precision, f)
    if tall is not None:
        return (*found, tall)
    for L in Ls:
        for size in SET_SIZES:
            if kl(L, size) >= target - 1e-9 and fits(L, size):
                return L, size, None
    return (*found, ("none", 0.0, 0.0, Ls[-1], Ls[0]))


def _too_tall(sizes, target: float, precision: float, f: Form) -> tuple[str, float, float] | None:
    """("tall", need, room) where at |kl| ≥ ``target`` the band (ΔT's axis spans k and l: at least target −
    precision/2 + its shortest φ axis + 32 mm, ``band_least``) is taller than a sheet of ``f``; else None."""
    x0, y0, x1, y1 = field_of(f)
    need = target - precision / 2 + min(_lengths(_set_grid(sizes)[-1])) + 32.0
    return ("tall", need, y1 - y0) if need > y1 - y0 + 1e-9 else None


def _set_scales(sizes, fits, kl, target: float | None, fallback: tuple[float, float]) -> tuple[float, float]:
    """A set's construction (L, size): for each L from the longest down (``SET_L_STEP``) the largest
    size (``SET_SIZES``) at which the moments and the band each fit a sheet; the first whose |kl| is
    at least ``target`` (the A1 sheet's: the flywheel read no worse), else the one of the largest |kl|
    (the search ends after ``SET_PATIENCE`` L without a larger one). ``fits`` is taken to hold for
    every smaller size where it holds for one (the drawings grow with it): each L's size is sought
    from the last L's (a shorter L holds at least as large a size), upward while it fits, else by
    halving below it."""
    Ls = _set_grid(sizes)
    best, last, idle = None, None, 0
    for L in Ls:
        if last is not None and fits(L, SET_SIZES[last]):
            got = last
            while got > 0 and fits(L, SET_SIZES[got - 1]):
                got -= 1
        else:
            lo, hi, got = 0 if last is None else last + 1, len(SET_SIZES) - 1, None
            while lo <= hi:
                k = (lo + hi) // 2
                if fits(L, SET_SIZES[k]):
                    got, hi = k, k - 1
                else:
                    lo = k + 1
            if got is None:
                continue
        last = got
        pair = (L, SET_SIZES[got])
        value = kl(*pair)
        if target is None or value >= target - 1e-9:
            return pair
        if best is None or value > best[0] + 1e-9:
            best, idle = (value, pair), 0
        else:
            idle += 1
            if idle >= SET_PATIENCE:
                break
    return best[1] if best is not None else fallback


ROUND_LENGTH = 10.0    # mm: the band's φ axes a multiple of this (2π/115,5 is no scale a student picks: 2π/110)


def round_length(length: float, L: float) -> float:
    """``length`` down to a multiple of ``ROUND_LENGTH`` (L itself, the moments' axis, as it is)."""
    return length if length >= L - 1e-9 else max(ROUND_LENGTH, math.floor(length / ROUND_LENGTH + 1e-9) * ROUND_LENGTH)


def _lengths(L: float) -> tuple[float, ...]:
    """The φ axes tried for the band's ΔT(φ) and turned I*(φ), longest first (``PROJECTED``),
    each a round length (``round_length``)."""
    return tuple(dict.fromkeys([*(round_length(max(k * L, min(L, PROJECTED_MIN)), L) for k in PROJECTED),
                                *(round_length(min(L, g), L) for g in (70.0, 60.0, PROJECTED_LEAST))]))


def _wh(rec: Record) -> tuple[float, float]:
    b = rec.bounds()
    return b[2] - b[0], b[3] - b[1]


def dynamics_scales(st: Study, dyn, format: str = "A1", divisions: int | None = None,
                    precision: float = 0.5) -> dict[str, float]:
    """L, size and ΔT's own μ_T (``finer_energy``; None: the construction's rule) of the flywheel
    construction the dynamics sheet of ``format`` draws — for
    ``graphplan dynamics`` to report the construction the sheet draws."""
    L, size, *_, energy = construction(st, dyn, form(format), SheetOptions(precision=precision, sheet="dynamics")
                                       if divisions is None else _Args(divisions, precision))
    return {"L": L, "size": size, "energy": energy}


class _Args:
    def __init__(self, divisions, precision):
        self.divisions, self.precision, self.lang = divisions, precision, "uk"


SPEED_WIDTHS = (1.0, 0.8, 0.65, 0.5, 0.4)     # ω(φ) in a set: its width a share of the field's, largest first


def _set_speed(f: Form, fw: Flywheel, lang: str, lay) -> tuple[Leaf, list]:
    """ω(φ) in a set grown while the set's count of sheets holds (``lay(speed)`` lays the set out):
    the widest of ``SPEED_WIDTHS`` of the field at 0.45 of its width high."""
    x0, y0, x1, _ = field_of(f)
    small = Leaf("speed", record=_speed(fw, lang, (0.0, 0.0)))
    base = lay(small)
    if base is None:
        return small, base
    for share in SPEED_WIDTHS:
        w = share * (x1 - x0)
        leaf = Leaf("speed", record=_speed(fw, lang, (w, 0.45 * w)))
        laid = lay(leaf)
        if laid is not None and len(laid) <= len(base):
            return leaf, laid
    return small, base


def _set_flow(rows: list[list[Leaf]], tables: list[Leaf], notes: Leaf, region, keep, later=None,
              lead: Leaf | None = None, rewrapped=None):
    """A set's sheets (drawing.layout.flow, the later sheets kept clear of their form 2a ``later``):
    the drawings' ``rows``, then the tables and the notes in one row — the last drawing (ω) in its
    row or leading the tables' —, in the order of the work; where the first drawing does not fit
    beside the first sheet's title block, the table of the positions (the reduced M*c and I* the
    diagrams are plotted from) alone on the first sheet, the results' tables still last (review 5
    #15: a set read backwards, its results before the constructions) — unless the tables' rows
    first (ω(φ) beside them) take fewer sheets. Where that leaves the
    notes alone on the last sheet, the last table goes with them (over them, else beside them) —
    every sheet of a set carries a drawing or a table. The fewest sheets of those — where the last
    table and the notes share a row, the one keeping them together (the notes beside the table, a
    GAP apart: ``flow`` shares a row's spare width out between its items and sets them far apart).
    ``lead``: the table of the positions lettered larger, tried first where it leads alone (its sheet
    not three-quarters empty)."""
    tried = []
    for rank, order in enumerate(("drawings", "data", "tables")):
        if order != "drawings" and tried and tried[0][1] == 0:
            break                          # the order of the work lays out: taken as before
        ends = tables if order in ("drawings", "tables") else tables[1:]
        # the notes beside the last table also set as wide as the rest of its row (``rewrapped``):
        # fewer lines, so that ω(φ) still goes under them with the tables (the compressor's notes at
        # the title block's width, 81 mm high, left ω 0.8 mm short of its sheet: it took one alone)
        wide = region[2] - region[0] - ends[-1].w - GAP
        beside = ([[ends[:-1] + [Row([ends[-1], rewrapped(wide)])]]]
                  if rewrapped is not None and ends and wide > notes.w + 1e-9 else [])
        for tail in [[ends + [notes]], [ends[:-1] + [Stack([ends[-1], notes])]],
                     [ends[:-1] + [Row([ends[-1], notes])]]] + beside:     # the last drawing (ω) goes with the tables
            if order == "drawings":        # in the order of the work: ω beside the band, or leading the tables' row
                ways = [rows + tail, rows[:-1] + [rows[-1][:-1]] + [rows[-1][-1:] + tail[0]]]
            elif order == "data":          # the table of the positions first, the results' tables last
                ways = [[[t1]] + rows + tail for t1 in ([lead] if lead else []) + tables[:1]]
                ways += [[[t1]] + rows[:-1] + [rows[-1][:-1]] + [rows[-1][-1:] + tail[0]]
                         for t1 in ([lead] if lead else []) + tables[:1]]
            else:
                # the constructions in their order after the tables (ω(φ) last, as it is derived), where that
                # takes no more sheets than ω(φ) beside the tables (stop 48's compressor: tables, ω(φ), then
                # the moments and the band)
                ways = [[tail[0]] + rows, [tail[0] + rows[-1][-1:]] + rows[:-1] + [rows[-1][:-1]]]
            for first in ways:
                laid = flow([r for r in first if r], region, keep, later=later)
                if laid is not None and not _notes_alone(laid[-1]):
                    spread = len(tail[0]) == len(ends) + 1 and any(_one_row(pg, tables[-1], notes) for pg in laid)
                    tried.append((len(laid), rank, spread, len(tried), laid))
    if tried:                              # the fewest sheets, then the order of the work
        return min(tried)[4]
    return flow(rows + [tables + [notes]], region, keep, later=later)


def _one_row(page, table: Leaf, notes: Leaf) -> bool:
    """Whether ``table`` and ``notes`` stand side by side in one row of a set's sheet (``flow``
    gives a row's items boxes of one top)."""
    tops = [b[3] for leaf, b in page if leaf is table or leaf is notes]
    return len(tops) == 2 and abs(tops[0] - tops[1]) < 1e-6


def _top_aligned(page: list[tuple[Leaf, tuple]]) -> set[str]:
    """The names on a set's sheet drawn at the top of their boxes, not centred: the last table and
    the notes side by side in one row (a row of text read from its first line, the table's title
    and the notes' first line on one level)."""
    boxes = {leaf.name: b for leaf, b in page if leaf.record is not None}
    pair = ("motor table", "notes")
    if all(n in boxes for n in pair) and abs(boxes[pair[0]][3] - boxes[pair[1]][3]) < 1e-6:
        return set(pair)
    return set()


def _notes_alone(page) -> bool:
    """A sheet of a set that holds the notes and nothing else drawn."""
    return [leaf.name for leaf, _ in page if leaf.record is not None] == ["notes"]


def _table_overflow(st: Study, dyn, f: Form, args) -> str | None:
    """Why no sheet of ``f`` holds the table of the positions, or None where one does: it has a row
    per division and no sheet of a set splits it, so where the fewest divisions the sheet can draw
    (the first construction's: ``redrawn`` only adds) make it taller or wider than the field,
    neither the sheet nor any set can be laid out (the line says how many divisions fit)."""
    from graphplan.graphic.flywheel import construct
    L, size = _sizes(st)[-1]
    first = construct(dyn, getattr(args, "divisions", None), args.precision, L=L, size=size)
    x0, y0, x1, y1 = field_of(f)
    w, h = _wh(positions_table(dynamics_json(first), getattr(args, "lang", "uk")))
    if w <= x1 - x0 + 1e-9 and h <= y1 - y0 + 1e-9:
        return None
    most = first.divisions - math.ceil((h - (y1 - y0)) / ROW)       # a row a division
    return (f"the dynamics sheet's table of the positions, a row for each of {first.divisions} divisions, is "
            f"{h:.0f} mm tall: more than a whole {f.name} sheet holds; give at most {most} divisions (the scene's "
            "[dynamics] divisions, or --positions)")


def _refuse_a_table_taller_than(st: Study, dyn, f: Form, args) -> None:
    """``_table_overflow`` refused in one line, before any drawing is laid out."""
    why = _table_overflow(st, dyn, f, args)
    if why:
        raise GraphplanError(why)


_ANALYSED: dict[tuple, object] = {}


def _analysed(st: Study, delta: float | None):
    """exact.dynamics ``analyse`` remembered per mechanism and δ: a scene's sheets each count the
    dynamics document's sheets (sheets/sheet.py ``pages_of``), in both languages and formats."""
    key = (repr(st.mech), delta)
    if key not in _ANALYSED:
        if len(_ANALYSED) >= 8:
            _ANALYSED.pop(next(iter(_ANALYSED)))
        _ANALYSED[key] = analyse(st, delta)
    return _ANALYSED[key]


def set_energy_length(fw: Flywheel, length: float, f: Form) -> float | None:
    """ΔT(φ)'s φ axis in a set's band sheet longer than the turned I*(φ)'s (``band``'s
    ``energy_length``, as ``widened`` does on one sheet): as long as a later sheet holds the band in
    both languages, no longer than the moments' L, in whole ``WIDEN_STEP``; None where that gains
    less than ``WIDEN_LEAST`` (the crusher's A3 set drew ΔT(φ) over 70 mm, 12 divisions 5.8 mm
    apart, with ~70 mm of its sheet empty beside it)."""
    if fw.L - length < WIDEN_LEAST - 1e-9:
        return None
    x0, _, x1, y1 = field_of(f)
    k = _later_keep(f)

    def size(el: float | None) -> tuple[float, float]:
        wh = [_band_size(band(fw, other, length, el)[1]) for other in LANGS]
        return max(a[0] for a in wh), max(a[1] for a in wh)
    bw, bh = size(None)
    room = (x1 - x0) if bh <= y1 - k[3] + 1e-9 else (k[0] - x0)
    el = length + math.floor(min(room - bw, fw.L - length) / WIDEN_STEP) * WIDEN_STEP
    for _ in range(4):
        if el - length < WIDEN_LEAST - 1e-9:
            return None
        w, h = size(el)
        if _fits_later(f, Leaf("band", w, h)) and h <= bh + 1e-9:
            return el
        el -= max(WIDEN_STEP, math.ceil((w - room) / WIDEN_STEP) * WIDEN_STEP)
    return None


def _set_laid(f: Form, fw: Flywheel, doc: dict, lang: str, leaves: dict[str, Leaf], tables: list[Leaf],
              factor: float, length: float, note_lines: list[str]):
    """``_set_laid_at`` with the band as given, or with ΔT(φ) widened (``set_energy_length``) where
    that lays the set on no more sheets and leaves no more of them without a drawing. Returns
    ``_set_laid_at``'s three and ΔT(φ)'s φ axis (None: the band as given)."""
    base = _set_laid_at(f, fw, doc, lang, leaves, tables, factor, length, note_lines, None)
    el = set_energy_length(fw, length, f) if base[0] is not None else None
    if el is None:
        return (*base, None)
    wh = [_band_size(band(fw, other, length, el)[1]) for other in LANGS]
    wide = {**leaves, "band": Leaf("band", max(a[0] for a in wh), max(a[1] for a in wh),
                                   record=_union(band(fw, lang, length, el)[0]))}
    got = _set_laid_at(f, fw, doc, lang, wide, tables, factor, length, note_lines, el)

    def bare(laid) -> int:
        return sum(1 for page in laid if not {leaf.name for leaf, _ in page if leaf.record is not None} & SET_DRAWN)
    if got[0] is not None and (len(got[0]), bare(got[0])) <= (len(base[0]), bare(base[0])):
        return (*got, el)
    return (*base, None)


def _set_laid_at(f: Form, fw: Flywheel, doc: dict, lang: str, leaves: dict[str, Leaf], tables: list[Leaf],
                 factor: float, length: float, note_lines: list[str], el: float | None):
    """A set's sheets in ``lang`` (``_set_flow``, ω(φ) grown by ``_set_speed``): the notes in the
    band's nook where they fit it in both languages (the same sheets in either), else with the
    tables. Returns the laid sheets (None where a drawing is larger than a sheet), the nook (or
    None) and ω(φ)'s leaf. ``leaves``: the moments and the band (with records; ΔT(φ) over ``el``)."""
    boxes = band(fw, lang, length, el)[1]
    nook = nook_for(boxes, note_lines)
    if nook is not None and any(nook_for(band(fw, other, length, el)[1], lines_of(notes(fw, doc, other))) is None
                                for other in LANGS if other != lang):
        nook = None                      # the same sheets in either language
    nleaf = (Leaf("notes", 0.0, 0.0) if nook is not None else Leaf("notes", record=note_block(note_lines, TITLE)))
    lead = Leaf(tables[0].name, record=enlarged(tables[0].record, TABLES)) if factor == 1.0 else None
    speed, laid = _set_speed(f, fw, lang, lambda speed: _set_flow(
        [[leaves["moments"]], [leaves["band"], speed]], tables, nleaf, field_of(f), keep_out(f), _later_keep(f),
        lead=lead, rewrapped=None if nook is not None else (lambda w: Leaf("notes", record=note_block(note_lines, w)))))
    return laid, nook, speed


WIDEN_STEP = ROUND_LENGTH      # mm: ΔT(φ)'s widened φ axis a multiple of this (the same in either language)
WIDEN_LEAST = 20.0    # mm: … and widened only by this much or more


def widened(fw: Flywheel, length: float, zones: list[tuple[dict[str, Leaf], Leaf]], shape: str, foot: float,
            region: tuple, make=None) -> tuple[float, dict[str, tuple], Leaf] | None:
    """The band with ΔT(φ)'s φ axis longer than I*(φ)'s (``band``'s ``energy_length``) as far as the
    composition holds it in both languages (``zones``: each language's drawings and column; the band
    as wide as the field lets it beside the others, ω(φ) then grown into what is left) — its height
    unchanged: the band's φ axis is bounded by the turned I*(φ)'s height, and where the moments over
    it are wider the band stood centred with paper either side (stop 49's coulisse: ~120 × 280 mm
    between I*(φ) and the tables, ~70 × 100 left of ΔT(φ)); ΔT(φ) no longer than the moments' L.
    (ΔT(φ)'s φ axis, each language's (parts, boxes), the band's leaf), or None where it gains less
    than ``WIDEN_LEAST``. ``make(lang, el)``: the band drawn (``band``; a search passes its memo)."""
    make = make or (lambda lang, el: band(fw, lang, length, el))
    W, H = region[2] - region[0], region[3] - region[1]
    base = zones[0][0]["band"]

    def holds(width: float) -> bool:      # the composition with the band this wide still fits the field,
        for leaves, C in zones:           # each language's
            tw, th = extent(_tree(shape, {**leaves, "band": Leaf("band", width, base.h)}, C, foot))
            if tw > W + 1e-9 or th > H + 1e-9:
                return False
        return True
    if not holds(base.w):
        return None
    room, hi = base.w, W                  # the widest band the composition holds (ω(φ) at its smallest:
    for _ in range(24):                   # it then grows into what is left, ``speed_zone``)
        mid = (room + hi) / 2
        room, hi = (mid, hi) if holds(mid) else (room, mid)
    more = min(room - base.w, fw.L - length)
    el = length + math.floor(more / WIDEN_STEP) * WIDEN_STEP
    for _ in range(4):                    # the lettering's overhang may differ: shorter until it holds
        if el - length < WIDEN_LEAST - 1e-9:
            return None
        got = {other: make(other, el) for other in LANGS}
        wh = [_band_size(b) for _, b in got.values()]
        bw, bh = max(a[0] for a in wh), max(a[1] for a in wh)
        if bw <= room + 1e-9 and bh <= base.h + 1e-9:
            return el, got, Leaf("band", bw, bh)
        el -= max(WIDEN_STEP, math.ceil((bw - room) / WIDEN_STEP) * WIDEN_STEP)
    return None


def _speed_widened(fw: Flywheel, lang: str, items: list[Placed], boxes: dict[str, tuple],
                   region: tuple) -> list[Placed]:
    """ω(φ) in "speed" stands over the tables' column right of the moments and of the band below them;
    where it ends above the band's top (its zone is as tall as the room over the column, the band
    starts lower) the strip between the moments' right side and the band's right side over the band
    is its too — drawn across it, wider (stop 51's own mechanism: a 90 × 230 mm strip left empty
    beside the moments, ω(φ) 260 mm wide). The same height: nothing else moves."""
    placed = next((p for p in items if p.name == "speed"), None)
    if placed is None or "moments" not in boxes or "band" not in boxes:
        return items
    rx0, ry0, rx1, ry1 = placed.record.bounds()
    moments = next(p for p in items if p.name == "moments")
    right = moments.record.bounds()[2]          # the moments' box narrowed to its drawing: the boxes
    left = right + GAP                          # of two drawings never meet (compose.defects)
    band_top = max(max(p.box[3], p.record.bounds()[3]) for p in items if p.name not in ("moments", "speed")
                   and p.box[0] < rx0 - 1e-6)
    if ry0 < band_top + GAP - 1e-6 or left >= rx0 - 1e-6:
        return items
    zone = (region[2] - left, ry1 - ry0)
    wider = _speed(fw, lang, zone)
    w, h = _wh(wider)
    if w <= rx1 - rx0 + 1e-6 or w > zone[0] + 1e-6 or h > zone[1] + 1e-6:
        return items
    box = (left, ry0, region[2], ry1)
    mb = moments.box
    narrowed = Placed("moments", moments.record, (mb[0], mb[1], min(mb[2], right), mb[3]))
    return ([narrowed if p is moments else p for p in items if p.name != "speed"]
            + [Placed("speed", centred(wider, box), box)])


def _speed_nooked(fw: Flywheel, lang: str, boxes: dict[str, tuple], band_box: tuple, small: Leaf,
                  lines: list[str], fuller: list[str], region: tuple, keep: tuple) -> list[Placed]:
    """ω(φ) over the notes in the band's nook (``speed_nook``; the band stands centred in
    ``band_box``), the nook down to the field's foot where it ends left of the title block
    (``keep``: the band stands over the title block, the paper under the nook is no one's — the
    shaper's ~235 × 100 mm): ω(φ) grown into what the notes leave of it, the two one under another
    with the spare height in three equal parts over, between and under them; the motor's sentence
    with the notes where it still fits. Where the nook reaches past the title block's left side, that
    nook narrowed to the side and run down to the field's foot too, whichever draws ω(φ) larger."""
    dx, dy = _band_shift(boxes, band_box)
    got = speed_nook(boxes, small, lines)
    n, w = got if got is not None else (nooks(boxes)[0], nooks(boxes)[0][2] - nooks(boxes)[0][0])
    box = (n[0] + dx, n[1] + dy, n[0] + dx + w, n[3] + dy)
    boxes_ = [(box[0], region[1], box[2], box[3]) if box[2] <= keep[0] + 1e-9 else box]
    if box[2] > keep[0] + 1e-9 and keep[0] - box[0] >= max(NOOK_SPEED, small.w) - 1e-9:
        # the nook reaches past the title block's left side (LINK60: by 19 mm, and ~300 × 170 mm of paper
        # stood bare under it, beside the tables): narrowed to that side it runs down to the field's foot
        boxes_.append((box[0], region[1], keep[0], box[3]))
    best = None
    for b in boxes_:
        w_, room = b[2] - b[0], b[3] - b[1] - GAP
        lines_ = with_motor(lines, fuller, room - small.h, w_)
        nrec_ = note_block(lines_, w_)
        if best is not None and _wh(nrec_)[1] + GAP + small.h > room + 1e-9:
            continue
        rec_ = _speed(fw, lang, (w_, room - _wh(nrec_)[1]), NOOK_ASPECT)
        if _wh(rec_)[0] > w_ + 1e-6 or _wh(rec_)[1] > room - _wh(nrec_)[1] + 1e-6:
            rec_ = small.record
        area = _wh(rec_)[0] * _wh(rec_)[1]
        if best is None or area > best[0] * (1 + 1e-6):     # ω(φ) the larger (LAYOUT.md), else as it was
            best = (area, b, rec_, nrec_)
    _, box, rec, nrec = best
    sh, nh = _wh(rec)[1], _wh(nrec)[1]
    third = max(0.0, box[3] - box[1] - sh - nh) / 3        # the spare height: over, between and under them
    sb = (box[0], box[3] - third - sh, box[2], box[3] - third)
    nb = (box[0], sb[1] - third - nh, box[2], sb[1] - third)
    return [Placed("speed", centred(rec, sb), sb), Placed("notes", top_left(nrec, nb), nb)]


def _results_nooked(f: Form, fw: Flywheel, per: dict[str, tuple], parts: int, region: tuple,
                    foot: float) -> bool:
    """The results' tables (Table 2, Table 3) go side by side under the notes in the band's nook (the
    "speed" composition, the notes in the nook) where every language's nook holds them there (the
    notes' own width, ``GAP`` between; down to the field's foot, the nook ending left of the title
    block) — the tables' column then holds Table 1 alone and ω(φ) over it grows into the height they
    leave, as tall as its abscissa (``NOOK_ASPECT``): under the notes stood ~320 × 115 mm of bare
    paper (LINK61), the column ω(φ) stands over being as tall as the field. Only where the height ω(φ)
    does not grow into (its abscissa bounds it) is less than what the notes alone leave bare in the
    nook (else the hole only moves to the column). ``per``: each language's (leaves, tables, the
    notes' lines, the band's boxes)."""
    W, H = region[2] - region[0], region[3] - region[1]
    for lang, (leaves, tables, lines, boxes) in per.items():
        if len(tables) < 3:
            return False
        C = _column(f, tables, parts, None, "speed")[0]
        band_box = next(b for leaf, b in arrange(_tree("speed", leaves, C, foot - region[1]), region)
                        if leaf.name == "band")
        slack = (band_box[2] - band_box[0] - _band_size(boxes)[0]) / 2
        got = nook_for(boxes, lines, slack)
        if got is None:
            return False
        (_, n0, n1, n3), nw = got
        dy = _band_shift(boxes, band_box)[1]
        if n1 + _band_shift(boxes, band_box)[0] > keep_out(f)[0] - 1e-9:
            return False
        n0 = min(n0, region[1] - dy)               # the paper under the band's foot is no one's
        tw, th = _tables_size([[t] for t in tables[1:]], 2)
        nh = _wh(note_block(lines, nw))[1]
        if tw > nw + 1e-9 or nh + GAP + th > n3 - n0 + 1e-9:
            return False
        before = _wh(_speed(fw, lang, speed_zone("speed", leaves, C, W, H)))[1]
        C1 = _column(f, tables[:1], 1, None, "speed")[0]
        after = _wh(_speed(fw, lang, speed_zone("speed", leaves, C1, W, H), NOOK_ASPECT, math.inf))[1]
        if th - (after - before) > n3 - n0 - nh - 1e-9:     # the column's bare height past the nook's
            return False
    return True


def _mean_row(nooked: list[Leaf], doc: dict, lang: str, factor: float, room: float) -> list[Leaf]:
    """The results' tables under the notes in the band's nook (Table 2, Table 3 side by side) with the mean
    power ω_m·M*_д/η in a row of Table 3 under the rule's peak, where the notes lost the motor's sentence
    (``with_motor``: LINK61's, once the tables moved under them at stop 61 — a teacher read P = 0,6796 kW
    with nothing to say the cycle's mean is 0,2383 kW; Table 2's design note already says why a flywheel
    beside the motor) and Table 3 so grown still stands in the nook's ``room`` under the notes (mm, to
    the field's foot) no taller than Table 2 beside it (the row takes the paper under Table 3, the
    composition unchanged). Else the tables as they were (the terminal says it always)."""
    if len(nooked) != 2 or not motor_note(doc, lang):
        return nooked
    t3 = Leaf(nooked[1].name, record=enlarged(motor_table(doc, lang, mean=True), factor))
    return [nooked[0], t3] if t3.h <= min(room, max(nooked[0].h, nooked[1].h)) + 1e-9 else nooked


def count_dynamics_sheets(st: Study, f: Form, args: Options) -> int:
    """``len(build_dynamics_sheet(st, f, args).pages)`` without drawing it where ``construction``
    chose one sheet's composition (that builder then lays ``pages = [items]``): what the scene's
    other sheets number by — the analysis and the construction only (the drawing in both
    languages, the band and the tables were half the time)."""
    dyn = _analysed(st, getattr(args, "delta", None))
    _refuse_a_table_taller_than(st, dyn, f, args)
    if one_sheet(st, dyn, f, args):
        return 1
    return len(build_dynamics_sheet(st, f, args).pages)


_ONE: dict[tuple, bool] = {}


def one_sheet(st: Study, dyn, f: Form, args) -> bool:
    """Whether ``construction`` draws the document on one sheet (its shape not "set"), known from its
    search's first one-sheet composition (``_construction``'s ``count_only``): the larger diagram
    and ΔT's finer scale it then seeks only change how that sheet is drawn. Remembered as
    ``construction`` is, and read off it where it was made."""
    if _table_overflow(st, dyn, f, args):
        return False
    key = _construction_key(st, dyn, f, args)
    if key in _CONSTRUCTIONS:
        return _CONSTRUCTIONS[key][3] != "set"
    if key not in _ONE:
        if len(_ONE) >= 64:
            _ONE.pop(next(iter(_ONE)))
        _ONE[key] = _construction(st, dyn, f, args, count_only=True) is not None
    return _ONE[key]


def build_dynamics_sheet(st: Study, f: Form, args: Options) -> Sheet:
    """Sheet 3: the flywheel construction at the scales ``construction`` chooses, in zones: the
    moments and the work; the band of the energy–mass diagram built by projection (ΔT(φ) to its
    left, I*(φ) turned under it: ``band``); ω(φ); the tables' column with the notes."""
    dyn = _analysed(st, getattr(args, "delta", None))
    _refuse_a_table_taller_than(st, dyn, f, args)
    L, size, factor, shape, parts, length, in_nook, energy = construction(st, dyn, f, args)
    lang = args.lang
    fw, drawn = _drawn(dyn, args, L, size, lang, energy=energy)
    doc = dynamics_json(fw)
    short = shortfall(st, dyn, f, args) if shape == "set" else None
    leaves = {name: Leaf(name, record=drawn[name]) for name in ("moments", "speed")}
    parts_, boxes = band(fw, lang, length)
    bw = [_band_size(boxes if other == lang else band(fw, other, length)[1]) for other in LANGS]   # the same
    # room in either language (this language's band drawn once)
    leaves["band"] = Leaf("band", max(a[0] for a in bw), max(a[1] for a in bw), record=_union(parts_))
    tables = [Leaf(name, record=rec) for name, rec in _tables(doc, lang, factor, fw)]
    note_lines = lines_of(notes(fw, doc, lang, short))
    region = field_of(f)
    foot = keep_out(f)[3]

    def placed(leaf: Leaf, b, top: bool = False) -> list[Placed]:
        if leaf.name == "band":
            return _band_placed(parts_, boxes, b)
        rec = centred(leaf.record, b)
        if top:                                  # at the top of its box (``_top_aligned``)
            rec = rec.moved(0.0, b[3] - rec.bounds()[3])
        return [Placed(leaf.name, rec, b)]
    height = (None if in_nook or shape == "nook"                  # the notes in the column
              else (lambda w: _wh(note_block(note_lines, w))[1]))
    nooked: list[Leaf] = []                  # the results' tables under the notes in the band's nook
    if shape != "set":                       # ΔT(φ) across the band's box where I*(φ)'s height bounds the band
        zones = []                           # each language's drawings and column: the same band in either
        per = {}                             # … its leaves, tables and notes (``_results_nooked``)
        for other in LANGS:
            if other == lang:
                zones.append((leaves, _column(f, tables, parts, height, shape)[0]))
                per[other] = (leaves, tables, note_lines)
                continue
            _, drawn_ = _drawn(dyn, args, L, size, other, fw)
            doc_ = dynamics_json(fw)
            lines_ = lines_of(notes(fw, doc_, other, short))
            tables_ = [Leaf(n, record=r) for n, r in _tables(doc_, other, factor, fw)]
            zones.append(({"moments": Leaf("moments", record=drawn_["moments"]),
                           "speed": Leaf("speed", record=drawn_["speed"]), "band": leaves["band"]},
                          _column(f, tables_, parts, None if in_nook or shape == "nook"
                                  else (lambda w, ls=lines_: _wh(note_block(ls, w))[1]), shape)[0]))
            per[other] = (zones[-1][0], tables_, lines_)
        got = widened(fw, length, zones, shape, foot - region[1], region)
        others = {other: band(fw, other, length)[1] for other in LANGS}
        if got is not None and (not in_nook or nook_for(got[1][lang][1], note_lines) is not None
                                or nook_for(boxes, note_lines) is None):     # the notes' nook kept
            parts_, boxes = got[1][lang]
            leaves["band"] = Leaf("band", got[2].w, got[2].h, record=_union(parts_))
            others = {other: got[1][other][1] for other in LANGS}
        if shape == "speed" and in_nook and _results_nooked(
                f, fw, {o: ({**per[o][0], "band": leaves["band"]}, per[o][1], per[o][2], others[o]) for o in LANGS},
                parts, region, foot):
            nooked, tables, parts = tables[1:], tables[:1], 1
    if shape not in ("set", "nook"):         # ω(φ) grows into the room the other zones leave it
        C = _column(f, tables, parts, height, shape)[0]
        zone = speed_zone(shape, leaves, C, region[2] - region[0], region[3] - region[1])
        speed = _speed(fw, lang, zone, NOOK_ASPECT, math.inf) if nooked else _speed(fw, lang, zone)
        if _wh(speed)[0] <= zone[0] + 1e-6 and _wh(speed)[1] <= zone[1] + 1e-6:
            leaves["speed"] = Leaf("speed", record=speed)
    if shape == "set":
        # the notes in the band's nook where they fit it, as on the A1 sheet (the band's sheet not half
        # empty); else with the tables. The set reads in the order of the work: the moments on the
        # first sheet, the band, ω(φ), the tables by the last sheet's title block (``_set_laid``)
        laid, nook, leaves["speed"], el = _set_laid(f, fw, doc, lang, leaves, tables, factor, length, note_lines)
        if el is not None:                   # ΔT(φ) widened on the band's sheet
            parts_, boxes = band(fw, lang, length, el)
        if laid is None:
            raise said_error(GraphplanError, "sh drawing larger", None, None, form=f.name, option="--format")
        pages = [[q for leaf, b in page if leaf.record is not None
                  for q in placed(leaf, b, leaf.name in _top_aligned(page))] for page in laid]
        if nook is not None:
            at = next(k for k, page in enumerate(laid) if any(leaf.name == "band" for leaf, _ in page))
            band_box = next(b for leaf, b in laid[at] if leaf.name == "band")
            dx, dy = _band_shift(boxes, band_box)
            (_, n0, n1, n3), nw = nook
            note_lines = with_motor(note_lines, lines_of(notes(fw, doc, lang, short, motor=True)), n3 - n0, nw)
            nrec = note_block(note_lines, nw)
            nb = (n1 + dx - nw, n3 + dy - _wh(nrec)[1], n1 + dx, n3 + dy)
            pages[at].append(Placed("notes", top_left(nrec, nb), nb))
    else:
        C, groups, width = _column(f, tables, parts, height, shape)
        items, col_box, band_box = [], None, None
        boxes_at = {}
        for leaf, b in arrange(_tree(shape, leaves, C, foot - region[1]), region):
            if leaf is C:
                col_box = b
            elif leaf.record is not None:
                items += placed(leaf, b)
                band_box = b if leaf.name == "band" else band_box
                boxes_at[leaf.name] = b
        if shape == "speed":                 # ω(φ) over the band's reach: across to the moments' side
            items = _speed_widened(fw, lang, items, boxes_at, region)
        if shape == "nook":                  # ω(φ) over the notes in the band's nook under ΔT(φ)
            items += _speed_nooked(fw, lang, boxes, band_box, leaves["speed"], note_lines,
                                   lines_of(notes(fw, doc, lang, short, motor=True)), region, keep_out(f))
        elif in_nook:                          # under ΔT(φ), left of the turned I*(φ): the band's nook
            dx, dy = _band_shift(boxes, band_box)
            slack = (band_box[2] - band_box[0] - _band_size(boxes)[0]) / 2    # the band centred in its box
            got = nook_for(boxes, note_lines, slack)
            if got is None:                          # (``construction`` found it holds them) the lowest
                got = (nooks(boxes)[-1], nooks(boxes)[-1][2] - nooks(boxes)[-1][0] + max(slack, 0.0))
            (_, n0, n1, n3), nw = got
            under = 0.0
            if nooked:                                 # the results' tables under the notes, the nook run
                n0 = min(n0, region[1] - dy)           # down to the field's foot (``_results_nooked``)
                under = _tables_size([[t] for t in nooked], 2)[1] + GAP
            fuller = lines_of(notes(fw, doc, lang, short, motor=True))
            note_lines = with_motor(note_lines, fuller, n3 - n0 - under, nw)
            nrec = note_block(note_lines, nw)          # from the left side of the band's box
            if nooked and note_lines is not fuller:    # the motor's mean power in Table 3 where it stays
                nooked = _mean_row(nooked, doc, lang, factor, n3 - n0 - _wh(nrec)[1] - GAP)   # in the nook
            nb = (n1 + dx - nw, n3 + dy - _wh(nrec)[1], n1 + dx, n3 + dy)
            if nooked:                                 # side by side under the notes, from the nook's left
                items += set_columns([[t] for t in nooked], nb[0], nb[1] - GAP)
        else:
            nrec = note_block(note_lines, width)
            bottom = col_box[1] if shape in NOOKED else foot      # over the title block, or the column's foot
            nb = (col_box[2] - width, bottom, col_box[2], bottom + _wh(nrec)[1])
        if shape != "nook":
            items.append(Placed("notes", top_left(nrec, nb), nb))
        right = col_box[2]
        if shape == "nook":                  # the tables alone under the moments: centred under them, the
            spare = col_box[2] - col_box[0] - _tables_size(groups, parts)[0]   # spare width either side (the
            right -= max(spare, 0.0) / 2     # shaper's ~90 × 350 mm strip left of them, right-aligned)
        items += _set_tables(groups, parts, right, col_box[3])
        pages = [items]
    from graphplan.util.words import word
    tf = fields(st, lang, word("tb no scale", lang))   # diagrams: no drawing scale (their μ are in the notes)
    tf["subtitle"] = WORDS[lang]["subtitle"]
    return compose(f, pages, tf, lang, f"{title_in(st, lang)} — {tf['subtitle']}")
