"""The third sheet, «Динамічний аналіз» (dynamic analysis): the reduced moments with their graphical
integration into the work diagrams, ΔT, I*_m, the energy–mass (Wittenbauer) diagram with the
flywheel read off |kl|, the steady-state speed ω(φ), the tables of the reduced quantities per
position, the flywheel by each method with its error and the motor."""
from __future__ import annotations

from graphplan.drawing.flywheel import records
from graphplan.drawing.layout import Block
from graphplan.exact.dynamics import analyse
from graphplan.exact.positions import Study
from graphplan.graphic.diagrams import LAB_LIMIT
from graphplan.graphic.flywheel import Flywheel, construct
from graphplan.graphic.record import Record
from graphplan.report.dynamics import dynamics_json
from graphplan.report.plans import captioned
from graphplan.sheets.form import TABLES, Form, enlarged, table
from graphplan.sheets.sheet import Options, Sheet, compose, fields, fmt
from graphplan.util.words import column, fixed, num

# the diagrams' abscissa L (mm) and the size of their heights: the largest pair that fits
SIZES = ((330.0, 1.5), (330.0, 1.3), (330.0, 1.15), (330.0, 1.0), (290.0, 1.0), (250.0, 1.0), (210.0, 0.8),
         (170.0, 0.7))

WORDS = {
    "uk": {"subtitle": "Динамічний аналіз", "moments": "Діаграми зведених моментів M^*_с(φ), M^*_д і робіт A_с(φ), "
           "A_д(φ) (графічне інтегрування методом хорд)", "energy": "Діаграма зміни кінетичної енергії ΔT(φ) = A_д − A_с",
           "inertia": "Діаграма зведеного моменту інерції механізму I^*_м(φ)",
           "wittenbauer": "Діаграма енергія–маса (Віттенбауера)", "speed": "Кутова швидкість корби ω(φ) усталеного руху",
           "positions": "Таблиця 1. Зведені величини в положеннях", "flywheel": "Таблиця 2. Момент інерції маховика, кг·м²",
           "motor": "Таблиця 3. Електродвигун і редуктор", "method": "метод", "value": "I_мах", "err": "похибка, %",
           "exact": "точно: рівняння руху (сталий M^*_д)", "graph": "графічно: діаграма Віттенбауера",
           "approx": "наближено: (ΔT_{max}−ΔT_{min})/(ω_m²δ) − I^*_{м сер}", "merk": "наближено: метод Мерцалова",
           "motor_fl": "з двигуном: рівняння руху", "scales": "Масштаби", "given": "δ = {d}, ω_m = {w} рад/с",
           "n": "№", "chosen": "вибраний за правилом", "scene": "заданий у сцені", "warn": "Попередження",
           "achieved": "Досягнуто: δ = {d}; ω(2π) = ω(0) — рух усталений{c}",
           "turn": "φ — поворот кривошипа від положення 0 у бік його обертання (як на діаграмах); положення 0: "
                   "кут кривошипа {phi0}° від осі x; dI^*_м/dφ — похідна за цим φ",
           "none": "Маховик не потрібен: ротор і редуктор (I_рот·i² + I_ред = {c} кг·м²) уже дають δ ≤ {d} "
                   "(потрібно J = {j} кг·м²), тому I_мах = 0",
           "weak": "Двигун {name}: P_н = {p} кВт менша за потрібну за правилом P = M^*_{{с max}}·ω_1/η = {need} кВт",
           "weak_cell": "{p} (< {need})", "mark": "* — ",
           "open": "незамкнення |ω(2π) − ω(0)|/ω_m = {c}",
           "why_graph": "графічно {e} %: похибка побудови ({n} поділок, лінійка {p} мм) — більше поділок зменшить її",
           "why_approx": "наближено {e} %: метод нехтує зміною I^*_м за цикл (похибка методу, а не побудови)",
           "why_merk": "Мерцалов {e} %: метод оцінює енергію ланок за середньої швидкості ω_m (похибка методу, а не побудови)"},
    "en": {"subtitle": "Dynamic analysis", "moments": "Reduced moments M^*_c(φ), M^*_d and the work A_c(φ), A_d(φ) "
           "(graphical integration by chords)", "energy": "Change of kinetic energy ΔT(φ) = A_d − A_c",
           "inertia": "Reduced moment of inertia of the mechanism I^*_m(φ)",
           "wittenbauer": "Energy–mass (Wittenbauer) diagram", "speed": "Crank speed ω(φ) in the steady state",
           "positions": "Table 1. Reduced quantities at the positions", "flywheel": "Table 2. Flywheel moment of inertia, kg·m²",
           "motor": "Table 3. Motor and reducer", "method": "method", "value": "I_fl", "err": "error, %",
           "exact": "exact: equation of motion (constant M^*_d)", "graph": "graphical: Wittenbauer diagram",
           "approx": "approximate: (ΔT_{max}−ΔT_{min})/(ω_m²δ) − I^*_{m mean}", "merk": "approximate: Merkalov's method",
           "motor_fl": "with the motor: equation of motion", "scales": "Scales", "given": "δ = {d}, ω_m = {w} rad/s",
           "n": "No", "chosen": "chosen by the rule", "scene": "given by the scene", "warn": "Warnings",
           "achieved": "Achieved: δ = {d}; ω(2π) = ω(0): a steady state{c}",
           "turn": "φ: the crank's turn from position 0 in its sense of rotation (as on the diagrams); position 0: "
                   "crank angle {phi0}° from the x axis; dI^*_m/dφ: the derivative along this φ",
           "none": "No flywheel is needed: the rotor and the reducer (I_rotor·i² + I_red = {c} kg·m²) already keep "
                   "δ ≤ {d} (J = {j} kg·m² is needed), so I_fl = 0",
           "weak": "Motor {name}: P_n = {p} kW is below the power rule P = M^*_{{c max}}·ω_1/η = {need} kW",
           "weak_cell": "{p} (< {need})", "mark": "* — ",
           "open": "closure |ω(2π) − ω(0)|/ω_m = {c}",
           "why_graph": "graphical {e} %: the construction's error ({n} divisions, a {p} mm ruler); more divisions reduce it",
           "why_approx": "approximate {e} %: the method neglects the change of I^*_m over the cycle (the method's error, "
                         "not the drawing's)",
           "why_merk": "Merkalov {e} %: the method takes the links' energy at the mean speed ω_m (the method's error, "
                       "not the drawing's)"},
}


def positions_table(doc: dict, lang: str) -> Record:
    """I*_m, dI*_m/dφ, M*_c, M*_d, A_c and ΔT (graphical and exact) per position; φ is the crank's
    turn from position 0 (the diagrams' abscissa), so dI*_m/dφ follows the printed φ whatever the
    crank's sense; each column's values below its resolution print 0 (``util.words.column``)."""
    w = WORDS[lang]
    uk = lang == "uk"
    head = [w["n"], "φ, °", "I^*_м, кг·м²" if uk else "I^*_m, kg·m²", "dI^*_м/dφ, кг·м²" if uk else "dI^*_m/dφ, kg·m²",
            "M^*_с, Н·м" if uk else "M^*_c, N·m", "M^*_д, Н·м" if uk else "M^*_d, N·m", "A_с, Дж" if uk else "A_c, J",
            "ΔT гр., Дж" if uk else "ΔT gr., J", "ΔT, Дж" if uk else "ΔT, J"]
    ps = doc["positions"]
    cols = [column([p[k] for p in ps], lang) for k in ("inertia", "d_inertia", "moment_resistance", "moment_driving")]
    cols += [column([p["graphical"][k] for p in ps], lang) for k in ("work_resistance", "energy")]
    cols.append(column([p["energy"] for p in ps], lang))
    rows = [head]
    for k, p in enumerate(ps):
        rows.append([str(p["index"]), fixed(p["turn_deg"], lang, 1)] + [c[k] for c in cols])
    return table(rows, [9.0, 13.0, 22.0, 26.0, 20.0, 20.0, 18.0, 20.0, 18.0], row_h=6.0, size=2.5,
                 title=w["positions"])


def flywheel_table(doc: dict, lang: str) -> Record:
    """The flywheel by each method beside the exact one; 0 (never negative) where no flywheel is
    needed, the notes saying why."""
    w = WORDS[lang]
    fw = doc["flywheel"]

    def pct(v: float | None) -> str:          # over the lab's 5 %: marked, the notes say why
        return "—" if v is None else fmt(v, lang, 3) + ("*" if abs(v) > LAB_LIMIT else "")
    rows = [[w["method"], f"{w['value']}, {'кг·м²' if lang == 'uk' else 'kg·m²'}", w["err"]],
            [w["exact"], fmt(fw["exact"], lang), "0" if fw["exact"] > 0 else "—"],
            [w["graph"], fmt(fw["graphical"], lang), pct(fw["error_pct"])],
            [w["approx"], fmt(fw["approximate"], lang), pct(fw["approximate_error_pct"])],
            [w["merk"], fmt(fw["merkalov"], lang), pct(fw["merkalov_error_pct"])],
            [w["motor_fl"], fmt(fw["motor"], lang), ""]]
    return table(rows, [78.0, 24.0, 18.0], row_h=6.0, size=2.5, title=w["flywheel"])


def motor_table(doc: dict, lang: str) -> Record:
    """The motor's data, its characteristic and the power rule; a motor weaker than the rule asks
    has its power cell marked (*) and the notes say so."""
    w = WORDS[lang]
    m = doc["motor"]
    uk = lang == "uk"
    power = fmt(m["power_kW"], lang)
    if m.get("underpowered"):
        power = w["weak_cell"].format(p=power, need=fmt(m["power_needed_kW"], lang)) + "*"
    rows = [[m["name"], w["chosen"] if m["chosen"] else w["scene"]],
            ["P_н, кВт" if uk else "P_n, kW", power],
            ["n_с / n_н, об/хв" if uk else "n_c / n_n, rpm", f"{num(m['rpm_sync'], lang)} / {num(m['rpm_rated'], lang)}"],
            ["ω_с / ω_н, рад/с" if uk else "ω_c / ω_n, rad/s", f"{fixed(m['omega_sync'], lang, 2)} / {fixed(m['omega_rated'], lang, 2)}"],
            ["M_н / M_{max}, Н·м" if uk else "M_n / M_{max}, N·m", f"{fixed(m['moment_rated'], lang, 3)} / {fixed(m['moment_max'], lang, 3)}"],
            ["M = Aω + B", f"{fmt(m['A'], lang)}·ω + {fmt(m['B'], lang)}"],
            ["P = M^*_{с max}·ω_1/η, кВт" if uk else "P = M^*_{c max}·ω_1/η, kW", fmt(m["power_needed_kW"], lang)],
            ["i, η", f"{num(m['ratio'], lang, 4)}, {num(m['efficiency'], lang)}"],
            ["I_рот·i², кг·м²" if uk else "I_rotor·i², kg·m²", fmt(m["rotor_reduced"], lang)],
            ["ω_m, δ", f"{fixed(m['motion']['omega_mean'], lang, 4)}, {fixed(m['motion']['delta'], lang, 4)}"],
            ["M_{max} циклу, Н·м" if uk else "M_{max} on the cycle, N·m", fmt(m["moment_peak"], lang)]]
    return table(rows, [48.0, 40.0], row_h=6.0, size=2.5, title=w["motor"])


CLOSURE_FLOOR = 1e-9


def closure(c: float, lang: str) -> str:
    """|ω(2π) − ω(0)|/ωm as the sheet says it: below 10⁻⁹ the residual is the integrator's rounding
    (it differs from machine to machine), the motion is periodic and the sheet says nothing more
    (deterministic files, no value printed at 10⁻⁹); above it, the residual itself."""
    return "" if abs(c) < CLOSURE_FLOOR else "; " + WORDS[lang]["open"].format(c=num(c, lang, 2))


def notes(f: Flywheel, doc: dict, lang: str) -> Record:
    """The scales, the construction's numbers with their symbols typeset, the convention of φ, the
    flywheel (0 and why where none is needed), the motor against the power rule and the warnings."""
    w = WORDS[lang]
    uk = lang == "uk"
    mm = "мм" if uk else "mm"
    s = doc["scales"]
    fw = doc["flywheel"]
    rot, red, fl = ("I_рот", "I_ред", "I_мах") if uk else ("I_rotor", "I_red", "I_fl")
    lines = [w["given"].format(d=num(doc["delta"], lang), w=fmt(doc["omega_mean"], lang)),
             f"{w['scales']}: μ_M = {num(s['mu_M'], lang)} {'Н·м' if uk else 'N·m'}/{mm}, μ_φ = 2π/L = "
             f"{num(s['mu_phi'], lang, 5)} {'рад' if uk else 'rad'}/{mm}, H = {num(f.H, lang)} {mm}",
             f"μ_A = μ_T = μ_M·μ_φ·H = {num(s['mu_A'], lang, 5)} {'Дж' if uk else 'J'}/{mm}, μ_I = {num(s['mu_I'], lang)} "
             f"{'кг·м²' if uk else 'kg·m²'}/{mm}",
             f"{'A_с' if uk else 'A_c'} = {num(doc['work_resistance'], lang, 5)} {'Дж' if uk else 'J'}, "
             f"{'M^*_д = A_с/2π' if uk else 'M^*_d = A_c/2π'} = {num(doc['moment_driving'], lang, 5)}; "
             f"{'графічно' if uk else 'graphical'} {num(f.driving, lang, 5)} {'Н·м' if uk else 'N·m'}",
             f"tg ψ = μ_I·ω_m²(1 ± δ)/(2μ_T): ψ_{{max}} = {fixed(fw['psi_max_deg'], lang, 3)}°, "
             f"ψ_{{min}} = {fixed(fw['psi_min_deg'], lang, 3)}°",
             f"J = μ_T·|kl|/(ω_m²δ) = {num(f.mu_A, lang, 5)}·{num(f.kl, lang)}/({num(doc['omega_mean'], lang, 4)}²·"
             f"{num(doc['delta'], lang)}) = {num(f.total, lang, 4)}; {fl} = J − {rot}·i² − {red} = "
             f"{num(f.flywheel, lang, 4)} {'кг·м²' if uk else 'kg·m²'}",
             w["achieved"].format(d=fixed(doc["motion"]["delta"], lang, 6), c=closure(doc["motion"]["closure"], lang)),
             w["turn"].format(phi0=fixed(doc["start_phi_deg"], lang, 1))]
    from graphplan.sheets.form import wrap
    said = []
    if not fw["needed"]:
        said.append(w["none"].format(c=num(fw["rotor_reduced"] + fw["reducer_reduced"], lang, 4),
                                     d=num(doc["delta"], lang), j=num(fw["total_exact"], lang, 4)))
    for key, why in (("error_pct", "why_graph"), ("approximate_error_pct", "why_approx"),
                     ("merkalov_error_pct", "why_merk")):
        if fw[key] is not None and abs(fw[key]) > LAB_LIMIT:
            said.append(w["mark"] + w[why].format(e=fmt(fw[key], lang, 3), n=doc["divisions"],
                                                  p=num(doc["precision_mm"], lang)))
    m = doc["motor"]
    if m.get("underpowered"):
        said.append(w["mark"] + w["weak"].format(name=m["name"], p=fmt(m["power_kW"], lang),
                                                 need=fmt(m["power_needed_kW"], lang)))
    for text in said:
        lines += wrap(text, 250.0, 3.5)
    for en, uk_text in f.dyn.warnings:
        if "no flywheel is needed" in en or "below the power rule" in en:   # said above in full
            continue
        lines += wrap(f"{w['warn']}: {uk_text if uk else en}", 250.0, 3.5)
    rec = Record("notes")
    for k, line in enumerate(lines):
        rec.label((0.0, -6.5 * k), line, size=3.5, layer="labels")
    return rec


def dynamics_blocks(st: Study, args: Options, L: float, dyn=None, size: float = 1.0,
                    tables: float = 1.0) -> tuple[list[Block], Flywheel]:
    lang = args.lang
    w = WORDS[lang]
    dyn = dyn or analyse(st, getattr(args, "delta", None))
    f = construct(dyn, getattr(args, "divisions", None), args.precision, L=L, size=size)
    doc = dynamics_json(f)
    drawn = records(f, lang, speed_height=100.0 * size)
    blocks = [Block(name, lambda _k, r=drawn[name], c=w[name]: captioned(r, c))
              for name in ("moments", "wittenbauer", "energy", "inertia", "speed")]
    blocks.append(Block("positions table", lambda _k: enlarged(positions_table(doc, lang), tables)))
    blocks.append(Block("flywheel table", lambda _k: enlarged(flywheel_table(doc, lang), tables)))
    blocks.append(Block("motor table", lambda _k: enlarged(motor_table(doc, lang), tables)))
    blocks.append(Block("notes", lambda _k: notes(f, doc, lang)))
    return blocks, f


def build_dynamics_sheet(st: Study, f: Form, args: Options) -> Sheet:
    """Sheet 3: the largest abscissa L at which every block fits one sheet (the tables lettered 3.5 mm,
    else 2.5 mm); where none does (a small format), the smallest, carried over to further sheets
    of the set."""
    from graphplan.sheets.compose import fits_one
    dyn = analyse(st, getattr(args, "delta", None))
    for tables in (TABLES, 1.0):         # the tables lettered 3.5 mm unless that costs a further sheet
        for L, size in SIZES:
            blocks, fw = dynamics_blocks(st, args, L, dyn, size, tables)
            if fits_one(f, blocks):
                break
        else:
            continue
        break
    tf = fields(st, args.lang, f"μ_φ = {num(fw.mu_phi, args.lang, 4)}", 3, 3)
    tf["subtitle"] = WORDS[args.lang]["subtitle"]
    return compose(f, blocks, tf, args.lang, f"{st.mech.title} — {tf['subtitle']}")
