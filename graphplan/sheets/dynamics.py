"""The third sheet, «Динамічний аналіз» (dynamic analysis): the reduced moments with their graphical
integration into the work diagrams, ΔT, I*_m, the energy–mass (Wittenbauer) diagram with the
flywheel read off |kl|, the steady-state speed ω(φ), the tables of the reduced quantities per
position, the flywheel by each method with its error and the motor."""
from __future__ import annotations

from graphplan.drawing.flywheel import records
from graphplan.drawing.layout import Block
from graphplan.exact.dynamics import analyse
from graphplan.exact.positions import Study
from graphplan.graphic.flywheel import Flywheel, construct
from graphplan.graphic.record import Record
from graphplan.report.dynamics import dynamics_json
from graphplan.report.plans import captioned
from graphplan.sheets.form import TABLES, Form, enlarged, table
from graphplan.sheets.sheet import Options, Sheet, compose, fields, fmt
from graphplan.util.words import fixed, num

# the diagrams' abscissa L (mm) and the size of their heights: the largest pair that fits
SIZES = ((330.0, 1.5), (330.0, 1.3), (330.0, 1.15), (330.0, 1.0), (290.0, 1.0), (250.0, 1.0), (210.0, 0.8),
         (170.0, 0.7))

WORDS = {
    "uk": {"subtitle": "Динамічний аналіз", "moments": "Діаграми зведених моментів Mс*(φ), Mд* і робіт Aс(φ), Aд(φ) "
           "(графічне інтегрування методом хорд)", "energy": "Діаграма зміни кінетичної енергії ΔT(φ) = Aд − Aс",
           "inertia": "Діаграма зведеного моменту інерції механізму I*м(φ)",
           "wittenbauer": "Діаграма енергія–маса (Віттенбауера)", "speed": "Кутова швидкість корби ω(φ) усталеного руху",
           "positions": "Таблиця 1. Зведені величини в положеннях", "flywheel": "Таблиця 2. Момент інерції маховика, кг·м²",
           "motor": "Таблиця 3. Електродвигун і редуктор", "method": "метод", "value": "Iм", "err": "похибка, %",
           "exact": "точно: рівняння руху (сталий Mд*)", "graph": "графічно: діаграма Віттенбауера",
           "approx": "наближено: (ΔT_{max}−ΔT_{min})/(ωm²δ) − I*сер", "merk": "наближено: метод Мерцалова",
           "motor_fl": "з двигуном: рівняння руху", "scales": "Масштаби", "given": "δ = {d}, ωm = {w} рад/с",
           "n": "№", "chosen": "вибраний за правилом", "scene": "заданий у сцені", "warn": "Попередження",
           "achieved": "Досягнуто: δ = {d}, |ω(2π) − ω(0)|/ωm {c}"},
    "en": {"subtitle": "Dynamic analysis", "moments": "Reduced moments M_c*(φ), M_d* and the work A_c(φ), A_d(φ) "
           "(graphical integration by chords)", "energy": "Change of kinetic energy ΔT(φ) = A_d − A_c",
           "inertia": "Reduced moment of inertia of the mechanism I*_m(φ)",
           "wittenbauer": "Energy–mass (Wittenbauer) diagram", "speed": "Crank speed ω(φ) in the steady state",
           "positions": "Table 1. Reduced quantities at the positions", "flywheel": "Table 2. Flywheel moment of inertia, kg·m²",
           "motor": "Table 3. Motor and reducer", "method": "method", "value": "I_fl", "err": "error, %",
           "exact": "exact: equation of motion (constant M_d*)", "graph": "graphical: Wittenbauer diagram",
           "approx": "approximate: (ΔT_{max}−ΔT_{min})/(ωm²δ) − I*mean", "merk": "approximate: Merkalov's method",
           "motor_fl": "with the motor: equation of motion", "scales": "Scales", "given": "δ = {d}, ωm = {w} rad/s",
           "n": "No", "chosen": "chosen by the rule", "scene": "given by the scene", "warn": "Warnings",
           "achieved": "Achieved: δ = {d}, |ω(2π) − ω(0)|/ωm {c}"},
}


def positions_table(doc: dict, lang: str) -> Record:
    """I*_m, dI*/dφ, M*_c, M*_d, A_c and ΔT (graphical and exact) per position."""
    w = WORDS[lang]
    uk = lang == "uk"
    head = [w["n"], "φ, °", "I*м, кг·м²" if uk else "I*_m, kg·m²", "dI*/dφ", "Mс*, Н·м" if uk else "M_c*, N·m",
            "Mд*, Н·м" if uk else "M_d*, N·m", "Aс, Дж" if uk else "A_c, J", "ΔT гр., Дж" if uk else "ΔT gr., J",
            "ΔT, Дж" if uk else "ΔT, J"]
    rows = [head]
    for p in doc["positions"]:
        g = p["graphical"]
        rows.append([str(p["index"]), f"{fixed(p['phi_deg'], lang, 1)}", fmt(p["inertia"], lang), fmt(p["d_inertia"], lang),
                     fmt(p["moment_resistance"], lang), fmt(p["moment_driving"], lang), fmt(g["work_resistance"], lang),
                     fmt(g["energy"], lang), fmt(p["energy"], lang)])
    return table(rows, [9.0, 13.0, 22.0, 17.0, 20.0, 20.0, 18.0, 20.0, 18.0], row_h=6.0, size=2.5,
                 title=w["positions"])


def flywheel_table(doc: dict, lang: str) -> Record:
    w = WORDS[lang]
    fw = doc["flywheel"]
    rows = [[w["method"], w["value"], w["err"]],
            [w["exact"], fmt(fw["exact"], lang), "0"],
            [w["graph"], fmt(fw["graphical"], lang), fmt(fw["error_pct"], lang, 3)],
            [w["approx"], fmt(fw["approximate"], lang), fmt(fw["approximate_error_pct"], lang, 3)],
            [w["merk"], fmt(fw["merkalov"], lang), fmt(fw["merkalov_error_pct"], lang, 3)],
            [w["motor_fl"], fmt(fw["motor"], lang), ""]]
    return table(rows, [78.0, 22.0, 18.0], row_h=6.0, size=2.5, title=w["flywheel"])


def motor_table(doc: dict, lang: str) -> Record:
    w = WORDS[lang]
    m = doc["motor"]
    uk = lang == "uk"
    rows = [["", ""],
            [m["name"], w["chosen"] if m["chosen"] else w["scene"]],
            ["Pн, кВт" if uk else "P_n, kW", fmt(m["power_kW"], lang)],
            ["nc / nн, об/хв" if uk else "n_c / n_n, rpm", f"{num(m['rpm_sync'], lang)} / {num(m['rpm_rated'], lang)}"],
            ["ωc / ωн, рад/с" if uk else "ω_c / ω_n, rad/s", f"{fixed(m['omega_sync'], lang, 2)} / {fixed(m['omega_rated'], lang, 2)}"],
            ["M_н / M_{max}, Н·м" if uk else "M_n / M_max, N·m", f"{fixed(m['moment_rated'], lang, 3)} / {fixed(m['moment_max'], lang, 3)}"],
            ["M = Aω + B", f"{fmt(m['A'], lang)}·ω + {fmt(m['B'], lang)}"],
            ["P = M^*_{с max}·ω_1/η, кВт" if uk else "P = M^*_{c max}·ω_1/η, kW", fmt(m["power_needed_kW"], lang)],
            ["i, η", f"{num(m['ratio'], lang, 4)}, {num(m['efficiency'], lang)}"],
            ["Iрот·i², кг·м²" if uk else "I_rotor·i², kg·m²", fmt(m["rotor_reduced"], lang)],
            ["ω_m, δ" , f"{fixed(m['motion']['omega_mean'], lang, 4)}, {fixed(m['motion']['delta'], lang, 4)}"],
            ["M_{max} циклу, Н·м" if uk else "peak M on the cycle, N·m", fmt(m["moment_peak"], lang)]]
    return table(rows[1:], [48.0, 40.0], row_h=6.0, size=2.5, title=w["motor"])


CLOSURE_FLOOR = 1e-9


def closure(c: float, lang: str) -> str:
    """|ω(2π) − ω(0)|/ωm as the sheet says it: a residual below 10⁻⁹ is the integrator's rounding and
    differs from machine to machine, so the sheet says "< 10⁻⁹" (deterministic files)."""
    return "< 10⁻⁹" if abs(c) < CLOSURE_FLOOR else f"= {num(c, lang, 2)}"


def notes(f: Flywheel, doc: dict, lang: str) -> Record:
    w = WORDS[lang]
    uk = lang == "uk"
    mm = "мм" if uk else "mm"
    s = doc["scales"]
    fw = doc["flywheel"]
    lines = [w["given"].format(d=num(doc["delta"], lang), w=fmt(doc["omega_mean"], lang)),
             f"{w['scales']}: μM = {num(s['mu_M'], lang)} {'Н·м' if uk else 'N·m'}/{mm}, μφ = 2π/L = {num(s['mu_phi'], lang, 5)} "
             f"{'рад' if uk else 'rad'}/{mm}, H = {num(f.H, lang)} {mm}",
             f"μA = μT = μM·μφ·H = {num(s['mu_A'], lang, 5)} {'Дж' if uk else 'J'}/{mm}, μI = {num(s['mu_I'], lang)} "
             f"{'кг·м²' if uk else 'kg·m²'}/{mm}",
             f"Aс = {num(doc['work_resistance'], lang, 5)} {'Дж' if uk else 'J'}, Mд* = Aс/2π = {num(doc['moment_driving'], lang, 5)}; "
             f"{'графічно' if uk else 'graphical'} {num(f.driving, lang, 5)} {'Н·м' if uk else 'N·m'}",
             f"tg ψ = μI·ωm²(1 ± δ)/(2μT): ψ_{{max}} = {fixed(fw['psi_max_deg'], lang, 3)}°, ψ_{{min}} = {fixed(fw['psi_min_deg'], lang, 3)}°",
             f"J = μT·|kl|/(ωm²δ) = {num(f.mu_A, lang, 5)}·{num(f.kl, lang)}/({num(doc['omega_mean'], lang, 4)}²·{num(doc['delta'], lang)}) = {num(f.total, lang, 4)}; "
             f"Iм = J − Iрот·i² − Iред = {num(f.flywheel, lang, 4)} {'кг·м²' if uk else 'kg·m²'}",
             w["achieved"].format(d=fixed(doc["motion"]["delta"], lang, 6), c=closure(doc["motion"]["closure"], lang))]
    from graphplan.sheets.form import wrap
    for en, uk_text in f.dyn.warnings:
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
