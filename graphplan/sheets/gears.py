"""The third sheet, «Синтез зубчастих механізмів» (gear synthesis): the involute pair drawn in mesh,
the specific sliding diagrams, the planetary train's scheme with its velocity picture and plan of
angular velocities, the tables (the geometry exact / graphical / δ %, the quality indices, the train's
teeth, conditions and angular velocities) and the notes — composed in zones like the other sheets:
the drawings in a row in reading order, the tables and the notes beside the title block; a format
too small carries the rest to further sheets of the set (docs/gears.md)."""
from __future__ import annotations

import math

from graphplan.drawing.layout import GAP, Leaf, Placed, centred
from graphplan.exact.gears import POINTED, solve, undercut_limits
from graphplan.graphic.diagrams import LAB_LIMIT
from graphplan.graphic.gears import (H_CARRIER, MORE_TEETH, SEGMENT_MIN, TEETH, TEETH_SPAN, construct_mesh, construct_train,
                                     lambda_mu, most_teeth, pole_distances, sliding_diagram)
from graphplan.graphic.record import Record, line_pitch, text_width
from graphplan.graphic.scales import at_least
from graphplan.model.gears import Gears
from graphplan.report.gears import (agreeing, alike, bare, contact_ratio_text, delta_text, eps_read_verdict, gears_json,
                                    length_decimals, sig_decimals, table_decimals)
from graphplan.sheets.compose import (CAPTION_2, Sheet, SheetOptions, captioned, compose, drawing_scale, field_of, keep_out,
                                      note_block)
from graphplan.sheets.form import TABLES, Form, enlarged, table
from graphplan.drawing.tables import baseline_in_row
from graphplan.sheets.kinematics import TITLE
from graphplan.util.errors import GraphplanError, said_error
from graphplan.util.markup import escape
from graphplan.util.words import fixed, num

WORDS = {
    "uk": {"subtitle": "Синтез зубчастих механізмів",
           "meshing": "Евольвентне зачеплення, М {scale} (μ_l = {mu} м/мм)",
           "sliding": "Питоме ковзання λ_1, λ_2", "sliding2": "абсциса ρ уздовж N_{{1}}N_{{2}}, М {scale} (μ_l = {mul} м/мм); B_{{1}}B_{{2}} робоча (потовщено); "
                       "μ_λ = {mu} 1/мм",
           "planetary": "Планетарна передача", "planetary2": "схема, картина швидкостей, план кутових швидкостей",
           "plan_scales": "μ_l = {l} м/мм, μ_v = {v} (м/с)/мм, h = {h} мм", "plan_h_H": ", h_H = {h} мм",
           "t1": "Таблиця 1. Геометрія передачі: точно, графічно, δ", "t2": "Таблиця 2. Показники якості",
           "t3": "Таблиця 3. Планетарна передача: z, умови, ω",
           "qty": "величина", "ex": "точно", "gr": "графічно", "w1": "колесо 1", "w2": "колесо 2",
           "cond": "умова", "bound": "висновок", "yes": "так", "no": "ні", "ok": "викон.", "fail": "не викон.",
           "under": "без підрізання: x ≥ x_{min}", "point": "без загострення: s_a/m ≥ 0,25",
           "interf": "без заклинювання: ρ(B) ≥ ρ_l, мм", "eps": "ε_α ≥ 1,2 за формулою",
           "eps_both": "ε_α ≥ 1,2: формула / креслення", "within": "у межах", "lam": "найбільше |λ|",
           "z": "числа зубців", "u": "u_{1H}: потрібно / точно / графічно", "coax": "співвісність",
           "asm": "складання", "nb": "сусідство", "nu": "без підрізання", "omega": "ω_{n}, рад/с",
           "member": "ланка", "mm": "мм", "given": "(задано)",
           "check": "ω_1 задано; відрізок 1 плану кутових швидкостей ({s} мм при μ_ω = {mu} (рад/с)/мм, тобто {g} рад/с) — "
                    "перевірка лінії 1 картини швидкостей; δ — похибка побудови, що входить і в ω_2, ω_H",
           "rule": "Зміщення x_1 = {x1}, x_2 = {x2} вибрано за правилом: {rule} (сітка x від {a} до {b} з кроком "
                   "{s}; пар, що задовольняють умови таблиці 2: {n})",
           "data": "Вихідні дані пари: z_1 = {z1}, z_2 = {z2}, m = {m} мм, α = {a}°, h^*_a = {h}, c^* = {c}{x}",
           "data_x": ", x_1 = {x1}, x_2 = {x2}",
           "train_data": "Вихідні дані планетарної передачі: тип {t}, {u}, K = {k}, m = {m} мм, {w}",
           "train_u": "u_{{1H}} = {u}", "train_z": "{z}",
           "rpm": "n_1 = {n} об/хв (ω_1 = {w} рад/с)", "omega1": "ω_1 = {w} рад/с",
           "scale": "Зачеплення: модуль на кресленні {md} мм, висота зуба 2,25·m = {h} мм; точність креслення {p} мм",
           "res": "Довжини таблиці 1 (прочитані r_w, s, s_a і їхні точні значення) — до {d} мм, на розряд точніше "
                  "за роздільність лінійки на деталі: {p} мм · {mu} м/мм = {r} мм",
           "bound_eps": "Межа похибки ε_α від точності креслення (відкладені a_w, радіуси основних і вершинних кіл, "
                        "p_b і прочитане "
                        "B_{{1}}B_{{2}} — кожне в межах половини точності): ±{b} абсолютна (ε_α без одиниці), "
                        "±{bp} % від ε_α",
           "train": "Планетарна передача: u_{{1H}} = {u} (за Віллісом); масштаби μ_l = {l} м/мм, "
                    "μ_v = {v} (м/с)/мм, полюсна відстань h = {h} мм; межа похибки u_{{1H}} від точності креслення (r_1, a_w, r_3 відкладені з округленням лінійки, відрізки прочитані в межах половини точності): ±{b} "
                    "(абсолютна, u_{{1H}} без одиниці; ±{bp} % від u_{{1H}})",
           "own_pole": "Відрізок ω_H на плані з полюсом p_ω був би {s} мм (ω_H = ω_1/{u}): водило має свій полюс p'_ω "
                       "на продовженні h, h_H = {hH} мм, його відрізок {sH} мм; ω_H = відрізок·μ'_ω, "
                       "u_{{1H}} = (відрізок 1/h)/(відрізок H/h_H)",
           "short": "Відрізок ω_H на плані лише {s} мм (ω_H = ω_1/{u}): півподілки лінійки — {e} % від нього; "
                    "звідси межа похибки u_{{1H}}",
           "synth": "Числа зубців вибрано з наборів, що задовольняють умови співвісності, складання, "
                    "сусідства й непідрізання при u_{{1H}} у межах ±4 % від потрібного (їх {n}): найменший зовнішній "
                    "діаметр D = {Dd}, D/m = {D0}",
           "nearer": "Набір z = {z} дає u_{{1H}} = {u} ({d}), але D/m = {D} проти {D0} (редуктор на {g} % більший); "
                     "за правилом узято менший: його відхилення {d0} % у межах ±4 %",
           "exactly": "точно",
           "tip": "; s_{{a{k}}} з хорди {c} мм: межа похибки від точності креслення ±{b} % {v}",
           "tip_in": "(у межах)", "tip_out": "(поза межею)",
           "x_min": "Таблиця 2: x_{{min}} = h^*_a − z·sin²α/2 = h^*_a·(z_{{min}} − z)/z_{{min}}, "
                    "z_{{min}} = 2h^*_a/sin²α = {zm}{r}",
           "x_min17": " (наближена формула (17 − z)/17 дала б для z_1 = {z} значення {x})",
           "judged": "Умови таблиці 2 — за формулами; ε_α з креслення {g} < 1,2 {v}",
           "judged_in": "у межах похибки ±{b}", "judged_out": "поза межею похибки ±{b}",
           "warn": "Попередження: ", "mark": "* — похибка понад 5 %",
           "past": "! — прочитане поза межею похибки від точності креслення"},
    "en": {"subtitle": "Gear synthesis",
           "meshing": "Involute meshing, scale {scale} (μ_l = {mu} m/mm)",
           "sliding": "Specific sliding λ_1, λ_2", "sliding2": "abscissa ρ along N_{{1}}N_{{2}}, scale {scale} (μ_l = {mul} m/mm); B_{{1}}B_{{2}} working "
                       "(heavy); μ_λ = {mu} 1/mm",
           "planetary": "Planetary train", "planetary2": "scheme, velocity picture, plan of angular velocities",
           "plan_scales": "μ_l = {l} m/mm, μ_v = {v} (m/s)/mm, h = {h} mm", "plan_h_H": ", h_H = {h} mm",
           "t1": "Table 1. Pair geometry: exact, graphical, δ", "t2": "Table 2. Quality indices",
           "t3": "Table 3. Planetary train: z, conditions, ω",
           "qty": "quantity", "ex": "exact", "gr": "graphical", "w1": "wheel 1", "w2": "wheel 2",
           "cond": "condition", "bound": "verdict", "yes": "yes", "no": "no", "ok": "met", "fail": "not met",
           "under": "no undercut: x ≥ x_{min}", "point": "not pointed: s_a/m ≥ 0.25",
           "interf": "no interference: ρ(B) ≥ ρ_l, mm", "eps": "ε_α ≥ 1.2 by the formula",
           "eps_both": "ε_α ≥ 1.2: formula / drawing", "within": "within", "lam": "largest |λ|",
           "z": "teeth", "u": "u_{1H}: wanted / exact / graphical", "coax": "coaxial",
           "asm": "assembly", "nb": "neighbourhood", "nu": "no undercut", "omega": "ω_{n}, rad/s",
           "member": "member", "mm": "mm", "given": "(given)",
           "check": "ω_1 is given; the plan's segment 1 ({s} mm at μ_ω = {mu} (rad/s)/mm, i.e. {g} rad/s) checks the "
                    "velocity picture's line 1; δ is the construction's error, in ω_2, ω_H too",
           "rule": "Shifts x_1 = {x1}, x_2 = {x2} chosen by the rule: {rule} (a grid of x from {a} to {b} by {s}; "
                   "{n} pairs meet the conditions of Table 2)",
           "data": "The pair's data: z_1 = {z1}, z_2 = {z2}, m = {m} mm, α = {a}°, h^*_a = {h}, c^* = {c}{x}",
           "data_x": ", x_1 = {x1}, x_2 = {x2}",
           "train_data": "Data of the planetary train: type {t}, {u}, K = {k}, m = {m} mm, {w}",
           "train_u": "u_{{1H}} = {u}", "train_z": "{z}",
           "rpm": "n_1 = {n} rpm (ω_1 = {w} rad/s)", "omega1": "ω_1 = {w} rad/s",
           "scale": "Meshing: the module drawn {md} mm, the whole depth 2.25·m = {h} mm; drafting precision {p} mm",
           "res": "Table 1's lengths (r_w, s, s_a read off and their exact values) to {d} mm, a digit finer than the "
                  "ruler's resolution on the part: {p} mm · {mu} m/mm = {r} mm",
           "bound_eps": "Bound of the error of ε_α from the drafting precision (a_w, the base and tip radii, p_b "
                        "laid off and "
                        "B_{{1}}B_{{2}} read, each within half the precision): ±{b} absolute (ε_α has no unit), "
                        "±{bp} % of ε_α",
           "train": "Planetary train: u_{{1H}} = {u} (Willis); scales μ_l = {l} m/mm, μ_v = {v} (m/s)/mm, "
                    "pole distance h = {h} mm; bound of the error of u_{{1H}} from the drafting precision (r_1, a_w, r_3 laid off as the ruler rounds them, the segments read within half the precision): ±{b} (absolute, "
                    "u_{{1H}} has no unit; ±{bp} % of u_{{1H}})",
           "own_pole": "The segment of ω_H off the pole p_ω would be {s} mm (ω_H = ω_1/{u}): the carrier has a pole "
                       "p'_ω of its own on h produced, h_H = {hH} mm, its segment {sH} mm; ω_H = segment·μ'_ω, "
                       "u_{{1H}} = (segment 1/h)/(segment H/h_H)",
           "short": "The segment of ω_H on the plan is only {s} mm (ω_H = ω_1/{u}): the ruler's half division is {e} % "
                    "of it; hence the bound of u_{{1H}}",
           "synth": "The teeth chosen from the sets meeting coaxiality, assembly, neighbourhood and no undercut "
                    "with u_{{1H}} within ±4 % of the wanted ({n} sets): the smallest outer diameter D = {Dd}, D/m = {D0}",
           "nearer": "The set z = {z} gives u_{{1H}} = {u} ({d}) but D/m = {D} against {D0} (a train {g} % larger); "
                     "the rule takes the smaller, its error {d0} % being within ±4 %",
           "exactly": "exactly",
           "tip": "; s_{{a{k}}} read off a chord of {c} mm: its bound from the drafting precision ±{b} % {v}",
           "tip_in": "(within)", "tip_out": "(outside)",
           "x_min": "Table 2: x_{{min}} = h^*_a − z·sin²α/2 = h^*_a·(z_{{min}} − z)/z_{{min}}, "
                    "z_{{min}} = 2h^*_a/sin²α = {zm}{r}",
           "x_min17": " (the approximate (17 − z)/17 would give {x} for z_1 = {z})",
           "judged": "Table 2's conditions are judged by the formulas; ε_α off the drawing {g} < 1.2 {v}",
           "judged_in": "within its bound ±{b}", "judged_out": "outside its bound ±{b}",
           "warn": "Warning: ", "mark": "* — an error past 5 %",
           "past": "! — a reading outside its bound from the drafting precision"},
}


def _n(v, lang: str, d: int = 4) -> str:
    return "—" if v is None else num(v, lang, d).replace("-", "−")


def _pct(v, suffix: str = "") -> tuple:
    """A δ % cell, set when its whole column is known (``_pct_cells``)."""
    return ("δ", v, suffix)


def _pct_cells(rows: list[list], lang: str) -> list[list[str]]:
    """The table's δ % cells (``report.gears.delta_text``: one count of decimals down the column —
    not 2,5 beside −0,869 and 0,144, review 10 mark 19 — and as the terminal prints them); past the
    lab's 5 % marked *, "—" where nothing was read."""
    def text(c) -> str:
        _, v, suffix = c
        return delta_text(v, lang) + ("*" if v is not None and abs(v) > LAB_LIMIT else "") + suffix
    return [[text(c) if isinstance(c, tuple) else c for c in r] for r in rows]


def geometry_table(doc: dict, lang: str) -> Record:
    """Per wheel: r, rb, rw, ra, rf, s, sa exact and graphical (mm) with δ; then αw, aw, y, Δy, p,
    pb, εα."""
    w = WORDS[lang]
    p = doc["pair"]
    g = p.get("graphical", {})
    rows = [[w["qty"], f"{w['ex']} 1", f"{w['gr']} 1", "δ, %", f"{w['ex']} 2", f"{w['gr']} 2", "δ, %"]]
    names = {"r": "r", "rb": "r_b", "rw": "r_w", "ra": "r_a", "rf": "r_f", "s": "s", "sa": "s_a"}
    # the lengths to one decimal past the ruler's resolution on the part, δ from the printed values
    # (report.gears.agreeing): the column and its δ agree for a reader who recomputes it
    dec = table_decimals(g) if g else 4
    for key, sym in names.items():
        row = [f"{sym}, {w['mm']}"]
        for k in (0, 1):
            gr = g.get(f"{key}_m")
            te, tg, e = agreeing(p[f"{key}_m"][k] * 1000, gr[k] * 1000 if gr else None, dec, lang)
            past = key == "sa" and gr and abs(gr[k] - p["sa_m"][k]) > g["sa_bound_m"][k] + 1e-12
            row += [te, tg, _pct(e, "!" if past else "")] if gr else [te, "", ""]   # one count of decimals down the column
        rows.append(row)
    c = p["contact_ratio"]
    te, tg, e = contact_ratio_text(c["exact"], c["graphical"], lang)
    rows.append(["ε_α", te, tg, _pct(e, "!" if c["outside_bound"] else "") if tg else "", "", "", ""])
    # the terminal's figures (report.gears.pair_lines): αw to six significant figures, y and Δy to
    # four, the lengths to the column's decimals and at least 0,01 mm (the lab prints aw so: the centre
    # distance is machined; review 12 had «110» for 109,977)
    ld = length_decimals(dec)
    for sym, v, k in (("α_w, °", p["alpha_w_deg"], 6), (f"a_w, {w['mm']}", p["a_w_m"] * 1000, -ld),
                      (f"a, {w['mm']}", p["a_m"] * 1000, -ld), ("y", p["y"], 4), ("Δy", p["delta_y"], 4),
                      (f"p, {w['mm']}", p["pitch_m"] * 1000, -ld), (f"p_b, {w['mm']}", p["base_pitch_m"] * 1000, -ld)):
        rows.append([sym, _n(v, lang, k) if k > 0 else fixed(v, lang, -k).replace("-", "−"), "", "", "", "", ""])
    return table(_pct_cells(rows, lang), [22.0, 17.0, 17.0, 13.0, 17.0, 17.0, 13.0], row_h=6.0, size=2.5, title=w["t1"])


def quality_table(doc: dict, lang: str) -> Record:
    w = WORDS[lang]
    p = doc["pair"]
    q = p["quality"]
    m = p["module_m"]
    yes = lambda b: w["ok"] if b else w["fail"]                           # noqa: E731
    rows = [[w["cond"], w["w1"], w["w2"], w["bound"]]]      # (the verdicts, wheel 1 / wheel 2: stop 49 headed them «межа»)
    # each cell its value beside its bound with the relation that holds — «≥» where met, «<» where not (a
    # failed condition printed «0,1 ≥ 0,3566» beside «не викон.»); sa/m beside 0,25 too (stop 52: alone)
    ge = lambda ok: "≥" if ok else "<"                                   # noqa: E731
    rows.append([w["under"], *(f"{_n(p['x'][k], lang)} {ge(not q['undercut'][k])} {_n(q['x_min'][k], lang)}"
                               for k in (0, 1)),
                 " / ".join(yes(not v) for v in q["undercut"])])
    rows.append([w["point"], *(f"{_n(p['sa_m'][k] / m, lang)} {ge(not q['pointed'][k])} {_n(POINTED, lang)}"
                               for k in (0, 1)),
                 " / ".join(yes(not v) for v in q["pointed"])])
    rho = [p["rho_m"]["B1"], p["line_of_action_m"] - p["rho_m"]["B2"]]
    lim = [max(v, 0.0) for v in q["involute_start_rho_m"]]
    # (millimetres to Table 1's decimals, both sides alike: «13,94 ≥ 9,80», not «13,94 ≥ 9,797» — stop 51)
    dec = table_decimals(p["graphical"]) if p.get("graphical") else 2
    mm = lambda v: fixed(v * 1000, lang, dec).replace("-", "−")           # noqa: E731
    rows.append([w["interf"], *(f"{mm(rho[k])} {ge(not q['interference'][k])} {mm(lim[k])}" for k in (0, 1)),
                 " / ".join(yes(not v) for v in q["interference"])])
    # εα judged by the formula, as the pair is designed, and apart from it on the value read off the
    # drawing against its bound (review 12, mark 12: 1,2033 by the formula «met» beside 1,196 read)
    c = p["contact_ratio"]
    te, tg, _ = contact_ratio_text(c["exact"], c["graphical"], lang)
    if tg:                                # by the formula / off the drawing, each judged
        v = eps_read_verdict(c)
        rows.append([w["eps_both"], f"{te} / {tg}", "",
                     f"{yes(q['contact_ratio_ok'])} / " + (w["within"] if v == "within" else yes(v == "ok"))])
    else:
        rows.append([w["eps"], te, "", yes(q["contact_ratio_ok"])])
    rows.append([w["lam"], *alike(q["sliding_max"], lang), ""])    # (one count of decimals: 1,351 / 1,420)
    # (the verdicts' column as wide as its cells: its ruled 30 mm, 42 at 3,5-mm letters, kept GEARS52's
    # A3 Table 2 off the λ diagrams' sheet by 3 mm — 2,5-mm letters there, stop 52)
    return table(rows, [50.0, 24.0, 24.0, 24.0], row_h=6.0, size=2.5, title=w["t2"])


NARROW_CELL = 32.0   # mm at 2,5-mm letters: a value cell of the narrow Table 3 broken onto two lines past this


def broken(cell: str, room: float = NARROW_CELL, size: float = 2.5) -> str:
    """A value cell broken as a drafter breaks it onto two lines where it is wider than ``room``: a
    condition before its verdict («18 + 45 = 85 − 22:» / «викон.»), else a formula at its last «=»,
    the sign repeated on the new line («(18·22 + 45·85)/3 =» / «= 1407: викон.»), else a list after the
    comma nearest its middle («z₁ = 18, z₂ = 45,» / «z′₂ = 22, z₃ = 85»); the cell as it was where no
    break makes both lines fit."""
    if text_width(cell, size) <= room:
        return cell
    tries = []
    head, sep, tail = cell.rpartition(": ")
    if sep:
        tries.append((head + ":", tail))
    head, sep, tail = cell.rpartition(" = ")
    if sep:
        tries.append((head + " =", "= " + tail))
    commas = [k for k in range(len(cell)) if cell.startswith(", ", k)]
    for k in sorted(commas, key=lambda k: abs(k - len(cell) / 2)):
        tries.append((cell[:k + 1], cell[k + 2:]))
    for a, b in tries:
        if text_width(a, size) <= room and text_width(b, size) <= room:
            return a + "\n" + b
    return cell


def train_table(doc: dict, lang: str, narrow: bool = False) -> Record:
    """Table 3: the teeth, u1H (exact, read, δ) and the wanted u1H, ω1, ω2, ωH, the conditions with
    their numbers. ``narrow``: its long values broken onto two lines (``broken``): 133–135 mm wide at
    the sets' 3,5-mm letters, not 177–182 (stop 56). Not yet taken by a set: GEARS55's A3 still ends
    with Table 3 alone with it — its third sheet holds the pictures (≥ 234 mm wide) and the pair's notes
    across the field, leaving no 135 × 134-mm place (measured; the pictures would have to shrink)."""
    w = WORDS[lang]
    t = doc["planetary"]
    ok = lambda b: w["ok"] if b else w["fail"]                            # noqa: E731
    names = ["z_1", "z_2", "z_3"] if t["type"] == "A" else ["z_1", "z_2", "z'_2", "z_3"]
    r = t["ratio"]
    g = t.get("graphical", {})
    # the values to five significant figures, δ from the printed values (report.gears.agreeing)
    ue, ug, ud = agreeing(r["exact"], r["graphical"], sig_decimals(r["exact"]), lang)
    rows = [[w["qty"], w["ex"], w["gr"], "δ, %"],
            [w["z"], ", ".join(f"{a} = {b}" for a, b in zip(names, t["z"])), "", ""],
            [w["u"].split(":")[0], bare(ue), bare(ug) if ug else "—",
             _pct(ud, "!" if r["outside_bound"] else "")]]
    if t["ratio_required"] is not None:
        # the chosen train's deviation from the task's ratio, a design quantity of the synthesis (not a
        # reading): from the unrounded ratios, as the terminal's list of sets and the notes give it
        # (review 54, item 22: 5,474 printed gave −0,47 where 104/19 against 5,5 is −0,4785 %)
        req = t["ratio_required"]
        d_ = r.get("required_error_pct", 100.0 * (r["exact"] - req) / req)
        rows.append([w["u"].split(":")[0] + (" потрібне" if lang == "uk" else " wanted"),
                     _n(req, lang), "", _pct(d_)])
    for key in ("1", "2", "H"):
        name = key if not (key == "2" and t["type"] == "B") else "2"
        te, tg, e = agreeing(t["omega_rad_s"][key], g.get("omega_rad_s", {}).get(key),
                             sig_decimals(t["omega_rad_s"][key]), lang)
        label = w["omega"].replace("{n}", name)
        if key == "1":                    # the given speed: its reading off the plan a check (stop 49)
            label = label.replace(",", " " + w["given"] + ",", 1)
        rows.append([label, bare(te), bare(tg) if tg else "—", _pct(e)])
    c = t["conditions"]
    shown = condition_numbers(t, lang)
    # (a condition's numbers within the teeth's cell, or as wide as keeps the table within the title
    # block's width at the sheets' size: the neighbourhood's formula, stop 51)
    room = max(text_width(rows[1][1], 2.5), TITLE / TABLES - (34.0 + 20.0 + 14.0) - 3.0)
    for key, name in (("coaxial", "coax"), ("assembly", "asm"), ("neighbourhood", "nb"), ("no_undercut", "nu")):
        cell = f"{shown[key]}: {ok(c[key])}" if key in shown else ok(c[key])
        if narrow:
            cell = broken(cell)
            rows.append([w[name], cell if max(text_width(q, 2.5) for q in cell.split("\n")) <= NARROW_CELL
                         else ok(c[key]), "", ""])
        else:
            rows.append([w[name], cell if text_width(cell, 2.5) <= room else ok(c[key]), "", ""])
    if narrow:
        rows[1][1] = broken(rows[1][1])
        return table(_pct_cells(rows, lang), [24.0, 30.0, 14.0, 10.0], row_h=6.0, size=2.5, title=w["t3"])
    return table(_pct_cells(rows, lang), [34.0, 40.0, 20.0, 14.0], row_h=6.0, size=2.5, title=w["t3"])


def condition_numbers(t: dict, lang: str) -> dict[str, str]:
    """The train's conditions as Table 3 shows them checked — with the numbers, as Table 2 shows the
    pair's (stop 50: «викон.» alone): coaxiality A z1 + 2·z2 = z3, B z1 + z2 = z3 − z2'; assembly A
    (z1 + z3)/K, B (z1·z2' + z2·z3)/(K·gcd(z2, z2')), each product written out, gcd = 1 left off — whole
    where met —; neighbourhood
    (z1 + z2)·sin(180°/K), the sine's argument written in degrees, against the planet's tip,
    max(z2, z2') + 2 (h*a = 1)."""
    z, K = t["z"], t["planets"]
    rel = lambda a, b: "=" if a == b else "≠"                            # noqa: E731
    if t["type"] == "A":
        z1, z2, z3 = z
        coax = f"{z1} + 2·{z2} {rel(z1 + 2 * z2, z3)} {z3}"
        num_, den = z1 + z3, K
        asm = f"({z1} + {z3})/{K} = {_n(num_ / den, lang, 4)}"
        tip = z2 + 2
    else:
        z1, z2, z2b, z3 = z
        coax = f"{z1} + {z2} {rel(z1 + z2, z3 - z2b)} {z3} − {z2b}"
        g = math.gcd(z2, z2b)             # written out as the neighbourhood is (stop 52: «5400/15 = 360»
        num_, den = z1 * z2b + z2 * z3, K * g     # left the reader to find where 5400 and 15 came from)
        asm = f"({z1}·{z2b} + {z2}·{z3})/{f'({K}·{g})' if g > 1 else K} = {_n(num_ / den, lang, 4)}"
        tip = max(z2, z2b) + 2
    out = {"coaxial": coax, "assembly": asm, "no_undercut": undercut_cell(t["type"], z)}
    if K > 1:
        near = (z1 + z2) * math.sin(math.pi / K)     # (z1 + z2)·sin(180°/K) written out (stop 51: «36,77 > 35»)
        out["neighbourhood"] = (f"({z1} + {z2})·sin {_n(180.0 / K, lang, 4)}° = {_n(near, lang, 4)} "
                                f"{'>' if near > tip else '≤'} {tip}")
    return out


MARKED = {"z1": "z_1", "z2": "z_2", "z2'": "z'_2", "z3": "z_3", "z3 − z2": "z_3 − z_2", "z3 − z2'": "z_3 − z'_2"}


def undercut_cell(kind: str, z) -> str:
    """Table 3's no-undercut condition with its numbers (``exact.gears.undercut_limits``): where missed,
    each missed limit with its value — «z_3 = 74 < 85», which wheel and by how much (stop 54: «не викон.»
    alone for z = 18/36/20/74) —; where met, the limits themselves (A «z_1 ≥ 17, z_2 ≥ 20, z_3 ≥ 85,
    z_3 − z_2 ≥ 8»), the teeth being in the row above."""
    limits = undercut_limits(kind, z)
    missed = [(n, v, lo) for n, v, lo in limits if v < lo]
    if missed:
        return ", ".join(f"{MARKED[n]} = {v} < {lo}" for n, v, lo in missed)
    if kind == "B":                       # (z1 and z2 share their limit)
        return f"z_1, z_2 ≥ {limits[0][2]}, " + ", ".join(f"{MARKED[n]} ≥ {lo}" for n, _, lo in limits[2:])
    return ", ".join(f"{MARKED[n]} ≥ {lo}" for n, _, lo in limits)


_SYMBOLS = ((r"\bB1B2/pb\b", r"B_1B_2/p_b"), (r"\bz([123])'", r"z'_\1"), (r"\b([xz])([123])\b", r"\1_\2"), (r"\bsa([12])\b", r"s_{a\1}"),
            (r"h\*a", r"h^*_a"), (r"ρ([12])", r"ρ_\1"), (r"\bB([12])\b", r"B_\1"), (r"εα", r"ε_α"),
            (r"αw", r"α_w"), (r"\bu1H\b", r"u_{1H}"), (r"ω([12H])\b", r"ω_\1"))


def typeset(text: str) -> str:
    """A warning of the solution (plain text, as the terminal and the JSON say it: «x1 = 0.1», «z3 = 74
    < 85», «h*a») in the sheet's markup, its symbols lettered as the tables letter them (x_1, z_3, z'_2,
    s_{a1}, h^*_a, ρ_1, B_1, ε_α, u_{1H}) — stop 54: the notes printed z3 and h*a under Table 3's z₃."""
    import re
    out = escape(text)
    for pattern, repl in _SYMBOLS:
        out = re.sub(pattern, repl, out)
    return out


def notes(doc: dict, lang: str, mesh, vel) -> list[str]:
    """The sheet's notes: the pair's, then the train's (``note_parts``)."""
    return [x for part in note_parts(doc, lang, mesh, vel) for x in part]


def note_parts(doc: dict, lang: str, mesh, vel) -> list[list[str]]:
    """The notes in two parts — the pair's (the shifts' rule, the scale, the readings' decimals, the
    bound of εα, its warnings) and the train's (the scales, the bound of u1H, the synthesis, its
    warnings) —, the legends of the tables' marks closing the last; a part a scene lacks is left out.
    A set puts each part by its tables (sheets/gearset.py)."""
    w = WORDS[lang]
    key = "warnings_uk" if lang == "uk" else "warnings"
    parts = []
    out: list[str] = []
    if "pair" in doc:
        p = doc["pair"]
        if p["shifts"] == "auto":
            a = p["auto"]
            out.append(w["rule"].format(rule=a["rule_uk" if lang == "uk" else "rule"], x1=_n(p["x"][0], lang),
                                        x2=_n(p["x"][1], lang), a=_n(a["grid"][0], lang),
                                        b=_n(a["grid"][1], lang), s=_n(a["grid"][2], lang), n=a["passing"]))
        out.append(w["scale"].format(md=_n(mesh.module_mm, lang), h=_n(2.25 * mesh.module_mm, lang),
                                     p=_n(mesh.precision, lang)))
        g = p.get("graphical")
        if g and mesh.precision > 0:
            out.append(w["res"].format(d=num(10.0 ** -table_decimals(g), lang), p=_n(mesh.precision, lang),
                                       mu=_n(mesh.mu_l, lang),
                                       r=_n(mesh.precision * mesh.mu_l * 1000.0, lang)))
        out.append(w["bound_eps"].format(b=_n(mesh.eps_bound, lang, 2),
                                         bp=_n(100 * mesh.eps_bound / p["contact_ratio"]["exact"], lang, 2)))
        out.append(x_min_note(p, lang))
        c = p["contact_ratio"]
        v = eps_read_verdict(c) if c["graphical"] is not None and mesh.precision > 0 else "ok"
        if v != "ok":                     # (review 12: 1,203 by the formula, 1,196 read)
            out.append(w["judged"].format(g=contact_ratio_text(c["exact"], c["graphical"], lang)[1], v=w[
                "judged_in" if v == "within" else "judged_out"].format(b=_n(c["bound"], lang, 2))))
        out += [w["warn"] + typeset(x) for x in p[key]]
        parts.append(out)
        out = []
    if "planetary" in doc:
        t = doc["planetary"]
        out.append(w["train"].format(t=t["type"], k=t["planets"], u=_n(t["ratio"]["exact"], lang), l=_n(vel.mu_l, lang),
                                     v=_n(vel.mu_v, lang), h=_n(vel.h, lang), b=_n(vel.ratio_bound, lang, 2),
                                     bp=_n(100 * vel.ratio_bound / t["ratio"]["exact"], lang, 2)))
        w1g = t.get("graphical", {}).get("omega_rad_s", {}).get("1")
        if w1g is not None:               # what Table 3's ω1 row reads, and how
            g1 = agreeing(t["omega_rad_s"]["1"], w1g, sig_decimals(t["omega_rad_s"]["1"]), lang)[1]
            out.append(w["check"].format(s=_n(abs(vel.segments["1"]), lang), g=bare(g1),
                                         mu=_n(vel.mu_v / (vel.mu_l * vel.h), lang)))
        if vel.h_carrier:                 # the carrier's own pole (review 13 #9)
            sH = abs(vel.segments["H"])
            out.append(w["own_pole"].format(s=_n(sH * vel.h / vel.h_carrier, lang, 2), u=_n(t["ratio"]["exact"], lang),
                                            hH=_n(vel.h_carrier, lang), sH=_n(sH, lang)))
        elif vel.precision > 0 and 0 < abs(vel.segments["H"]) < SEGMENT_MIN / 2:   # the half division past 2,5 %
            sH = abs(vel.segments["H"])
            out.append(w["short"].format(s=_n(sH, lang), u=_n(t["ratio"]["exact"], lang),
                                         e=_n(100 * vel.precision / 2 / sH, lang, 2)))
        if t["candidates"]:
            chosen = next((c for c in t["candidates"] if list(c["z"]) == list(t["z"])), t["candidates"][0])
            # D named by what it measures (stop 62: «найменший зовнішній діаметр, D/m = 121» left a teacher
            # asking which diameter — the planets' 17 + 2·52 over the ring's 89; exact.gears.overall)
            out.append(w["synth"].format(n=t["candidates_passing"], D0=chosen["diameter_modules"],
                                         Dd="m·z_3" if t["type"] == "A" else "m·max(z_1 + 2z_2, z_3)"))
            pair = nearer_candidate(t)
            if pair:
                near, chosen = pair
                pct = lambda e: fixed(e, lang, 2, plus=True).replace("-", "−")     # noqa: E731
                exact = abs(near["error_pct"]) < 0.005          # (not «+0,00 %»: stop 55, «точно»)
                out.append(w["nearer"].format(z=", ".join(map(str, near["z"])), u=_n(near["ratio"], lang),
                                              d=w["exactly"] if exact else pct(near["error_pct"]) + " %",
                                              D=near["diameter_modules"], D0=chosen["diameter_modules"],
                                              g=_n(round(100.0 * (near["diameter_modules"] / chosen["diameter_modules"]
                                                                  - 1.0)), lang),
                                              d0=pct(chosen["error_pct"])))
        out += [w["warn"] + typeset(x) for x in t[key]]
        parts.append(out)
    last = parts[-1] if parts else out
    if starred(doc, lang):                # (stop 46: the legend stood under tables with no * in them)
        last.append(w["mark"] + "".join(tips(doc, lang, mesh)))
    g = doc.get("pair", {}).get("graphical")
    tip_out = bool(g) and any(abs(g["sa_m"][k] - doc["pair"]["sa_m"][k]) > g["sa_bound_m"][k] + 1e-12 for k in (0, 1))
    if tip_out or any(doc[k][c]["outside_bound"] for k, c in (("pair", "contact_ratio"), ("planetary", "ratio"))
                      if k in doc):
        last.append(w["past"])
    return [[escape(x) if "_" not in x else x for x in part] for part in (parts or [out])]


def x_min_note(p: dict, lang: str) -> str:
    """Table 2's x_min named with its formula (stop 56: the sheet printed x_min = 0,4151 for z = 10, the
    exact h*a − z·sin²α/2 of REFERENCE §12, where a teacher who reckons (17 − z)/17 gets 0,4118 and asks
    where it comes from): z_min = 2h*a/sin²α is 17,1 at α = 20°, h*a = 1, and the textbook's 17 rounds it;
    where wheel 1's two values differ in the printed decimals the rounded one is given beside."""
    w = WORDS[lang]
    ha, a = p["addendum"], math.radians(p["alpha_deg"])
    zm = 2 * ha / math.sin(a) ** 2
    z1 = p["z"][0]
    r = ""
    if abs(ha - 1.0) < 1e-9 and abs(p["alpha_deg"] - 20.0) < 1e-9 and z1 < 17:
        approx = (17 - z1) / 17
        if _n(approx, lang) != _n(p["quality"]["x_min"][0], lang):
            r = w["x_min17"].format(x=_n(approx, lang), z=z1)
    return w["x_min"].format(zm=_n(zm, lang, 3), r=r)


def starred(doc: dict, lang: str) -> bool:
    """Whether Table 1 or Table 3 marks a δ past the lab's 5 % with * (the marks' legend is then due)."""
    recs = ([geometry_table(doc, lang)] if "pair" in doc else []) + ([train_table(doc, lang)] if "planetary" in doc
                                                                    else [])
    return any(q.kind == "text" and q.text.rstrip("!").endswith("*") for r in recs for q in r.items)


def tips(doc: dict, lang: str, mesh) -> list[str]:
    """The starred sa of Table 1 explained in the marks' legend by its bound from the drafting
    precision (``graphic.gears.sa_bound``: a thin tip of few teeth — review 45's 11-tooth pinion with
    x = 0,6 read sa +9,76 % within ±18 %), each "; s_a1 …" (none where no sa is starred)."""
    w = WORDS[lang]
    p = doc.get("pair")
    g = p.get("graphical") if p else None
    out = []
    if not g or mesh is None or mesh.precision <= 0:
        return out
    for k in (0, 1):
        e = agreeing(p["sa_m"][k] * 1000, g["sa_m"][k] * 1000, table_decimals(g), lang)[2]   # Table 1's δ
        if e is not None and abs(e) > LAB_LIMIT:
            b = g["sa_bound_m"][k]
            out.append(w["tip"].format(k=k + 1, c=_n(mesh.read[f"sa{k + 1}"], lang), b=_n(100 * b / p["sa_m"][k], lang, 2),
                                       v=w["tip_in" if abs(g["sa_m"][k] - p["sa_m"][k]) <= b + 1e-12 else "tip_out"]))
    return out


def data_lines(doc: dict, lang: str) -> list[str]:
    """The task data as the scene gives them (review 10, mark 2: a teacher checks Table 1 against
    z and m): the pair's, then the train's; at the head of the A1 sheet's notes, a block of their
    own by the meshing in a set (``_set``)."""
    return ([pair_data(doc["pair"], lang)] if "pair" in doc else []) + \
        ([train_data(doc["planetary"], lang)] if "planetary" in doc else [])


def pair_data(p: dict, lang: str) -> str:
    """The pair's task data as the scene gives them, heading the notes (review 10, mark 2): z1, z2,
    m, α, h*a, c* and the shifts (or that they are to be chosen)."""
    w = WORDS[lang]
    x = (w["data_x"].format(x1=_n(p["x"][0], lang), x2=_n(p["x"][1], lang)) if p["shifts"] == "given"
         else "")                         # (the next line names the rule that chose them)
    return w["data"].format(z1=p["z"][0], z2=p["z"][1], m=_n(p["module_m"] * 1000, lang), a=_n(p["alpha_deg"], lang),
                            h=_n(p["addendum"], lang), c=_n(p["clearance"], lang), x=x)


def train_data(t: dict, lang: str) -> str:
    """The planetary train's task data: its type, u1H wanted (or the teeth given), K, m and n1 (or ω1)
    as the scene gives them."""
    w = WORDS[lang]
    names = ["z_1", "z_2", "z_3"] if t["type"] == "A" else ["z_1", "z_2", "z'_2", "z_3"]
    u = (w["train_u"].format(u=_n(t["ratio_required"], lang)) if t["ratio_required"] is not None
         else w["train_z"].format(z=", ".join(f"{a} = {b}" for a, b in zip(names, t["z"]))))
    w1 = t["omega_rad_s"]["1"]
    speed = (w["rpm"].format(n=_n(t["rpm"], lang), w=_n(w1, lang)) if t.get("rpm") is not None
             else w["omega1"].format(w=_n(w1, lang)))
    return w["train_data"].format(t=t["type"], u=u, k=t["planets"], m=_n(t["module_m"] * 1000, lang), w=speed)


def nearer_candidate(t: dict) -> tuple[dict, dict] | None:
    """Of every train weighed, the one whose u1H is nearest the wanted (``exact.gears.synthesise``, the
    JSON's ``nearest``; else the nearest of the candidates listed), when it is not the one chosen (the rule takes the smallest diameter within ±4 %): what the notes say
    lost and why, with the chosen. None when the chosen train is also the nearest."""
    cands = t.get("candidates") or []
    if not cands or t.get("ratio_required") is None:
        return None
    near = t.get("nearest") or min(cands, key=lambda c: (abs(c["error_pct"]), c["diameter_modules"]))
    chosen = next((c for c in cands if list(c["z"]) == list(t["z"])), cands[0])
    return None if near["z"] == chosen["z"] or abs(near["error_pct"]) >= abs(chosen["error_pct"]) else (near, chosen)


def _fields(g: Gears, lang: str, mu_l: float | None) -> dict[str, str]:
    meta = dict(g.meta)
    from graphplan.sheets.compose import organisation, sheet_field
    org = organisation(meta, lang)
    from graphplan.util.romanize import scene_text
    return {"designation": escape(scene_text(meta, "designation", lang)), "title": escape(g.title_in(lang)),
            "student": escape(sheet_field(meta, "student", lang)), "teacher": escape(sheet_field(meta, "teacher", lang)),
            "organisation": escape(org), "scale": drawing_scale(mu_l, lang) if mu_l else "", "sheet": "1",
            "sheets": "1", "subtitle": WORDS[lang]["subtitle"]}


def _plan(vel, lang: str) -> Record:
    """The planetary pictures captioned: the name, what they are, their scales μl, μv and h."""
    w = WORDS[lang]
    return captioned(vel.record, w["planetary"], w["planetary2"] + "; " + w["plan_scales"].format(
        l=_n(vel.mu_l, lang), v=_n(vel.mu_v, lang), h=_n(vel.h, lang)) + (
        w["plan_h_H"].format(h=_n(vel.h_carrier, lang)) if vel.h_carrier else ""))


SHARES = ((1.0, 1.5), (1.0, 1.25), (1.0, 1.0), (1.0, 0.85), (0.8, 0.85), (0.8, 0.7), (0.65, 0.7), (0.65, 0.6),
          (0.5, 0.6), (0.5, 0.5))   # (vA, the sun's segment and h) × their sizes: the segment longer where the
#                                   row is wide, vA and it shorter where too wide
GROW = (4.0, 3.5, 3.0, 2.5, 2.2, 2.0, 1.8, 1.6, 1.5, 1.4, 1.3, 1.2, 1.1, 1.0)   # the planetary pictures' sizes tried, × (80, 60, 100) mm
# (the ring's radius, vA, the sun's segment): a set's (``_set_grown``); the A1 sheet takes the scheme's scales
# they give (``_grown``)
H_MIN = 40.0             # mm: the pole distance of a grown plan of angular velocities at least this


def _size(r: Record) -> tuple[float, float]:
    b = r.bounds()
    return b[2] - b[0], b[3] - b[1]


SCHEME_SHARES = (1.4, 1.0, 0.65)   # vA × its size tried with each scale of the scheme, the longest first
#                                       (vA and h cancel in every ω: a longer vA makes the plan no taller for its S)
ALONE_SHARES = (4.0, 3.0, 2.0)     # and before them where the pictures have the row under the meshing alone (the λ
#                                   diagrams beside the meshing): stop 61, GEARS60's pictures at 1.4 stood 360 mm
#                                   wide centred in a 620-mm row, 150 × 340 mm blank each side; at 4 the velocity
#                                   picture and the plan take the row (ω1's segment 190 → 380 mm, u1H within ±0,43 %
#                                   for ±0,86 %) — where the λ diagrams share the row, their growth takes its room
#                                   (``_lambda_filling``)


def filled(tr, precision: float, lang: str, ring_mm: float, va_mm: float, room_w: float, room_h: float,
           h_min: float, memo: dict | None = None, full: bool = False):
    """The planetary pictures with the scheme at the scale ``ring_mm`` gives and vA about ``va_mm``, the
    plan of angular velocities as large as the zone ``room_w`` × ``room_h`` (the pictures with their
    caption) takes — by arithmetic on the zone's size (review 12 mark 11, review 13 mark 9: ωH read off
    a 3,8–9 mm segment while the zone was two thirds empty): every segment of the plan is the sun's S
    times ωi/ω1 and h = S·yA/vA, so the plan's span grows as S·(1 + |ω2|/ω1) and its height as
    S·yA/vA; S is the largest the zone's spare width and height allow, measured on the pictures drawn
    at a first S, then checked on the pictures drawn (a few per cent less while labels push them out).
    (velocities, captioned record), or None when none fits or h would be under ``h_min``. ``memo``: the
    pictures drawn, kept across calls for the same train (a set tries several heights). ``full``: the
    scheme over and under the axis (``construct_train``)."""
    om = tr.omega
    span = 1.0 + max((abs(om[k]) for k in om if k != "1" and om[k] < 0), default=0.0) / abs(om["1"])

    memo = {} if memo is None else memo

    def at(S: float):
        key = (round(ring_mm, 6), round(va_mm, 6), round(S, 3), full)
        if key not in memo:
            try:
                v = construct_train(tr, precision, lang, ring_mm=ring_mm, va_mm=va_mm, sun_segment_mm=S, full=full)
                memo[key] = v, _plan(v, lang)
            except GraphplanError:
                memo[key] = None
        return memo[key]

    def at_h(hH: float, k: float = 1.0):  # the pictures at k × the last S with the carrier's own pole h_H
        try:
            c = construct_train(tr, precision, lang, ring_mm=ring_mm, va_mm=va_mm, sun_segment_mm=k * S,
                                h_carrier=hH, full=full)
        except GraphplanError:
            return None
        return (c, _plan(c, lang)) if c.h >= h_min else None

    def fits(d) -> bool:
        w_, h_ = _size(d[1])
        return w_ <= room_w and h_ <= room_h and d[0].h >= h_min

    S = 100.0
    d = at(S)
    if d is None:
        return None
    got = d if fits(d) else None
    for _ in range(3):                    # from the pictures at S, the S that fills the zone; again from it
        w_, h_ = _size(d[1])
        tall = d[0].heights["A"] / d[0].va_mm     # h per mm of the sun's segment
        # the plan grows from under the scheme: its right end, not the pictures', meets the zone's
        line = next(q for q in d[0].record.items if q.step == "plan of ω")
        reach = max(q[0] for q in line.points) - d[1].bounds()[0]
        wide = (room_w - max(w_, reach)) / span + (max(w_, reach) - reach) / span
        target = min(S + min(wide, (room_h - h_) / tall), 150.0 / tall)   # h ≤ 150 mm
        if abs(target - S) < 0.5:
            break
        for _ in range(5):                # labels may push the pictures out: a little less
            e = at(target)
            if e is not None and fits(e):
                break
            target = S + 0.8 * (target - S)
        else:
            break
        S, d, got = target, e, e
    return carried(got, at_h, room_w, room_h) if got is not None else None


def carried(got, at_h, room_w: float, room_h: float):
    """The pictures ``got`` (velocities, captioned record) with the carrier's ray from a pole of its own
    (``construct_train``'s ``h_carrier``) where its segment on the plan is shorter than
    ``SEGMENT_MIN`` — review 13 #9: ωH read off 3,8 mm, +5,54 %; u = 26…40 leave it 5–9 mm on A1 and
    2,5–8 mm on A3 whatever the sun's segment, the width taken —: h_H the one that makes it
    ``SEGMENT_MIN`` (at most 200 mm), or the longest the zone's spare height ``room_h`` holds, when
    that is at least 1,5·h — else the plan's h halved of the longest h_H the zone holds (the sun's
    segment shorter, still the longest) — either taken where the carrier's segment is 1,5 times as
    long and u1H's bound no wider; ``got`` else (the notes then say the segment's length).
    ``at_h(h_H, k)``: the pictures drawn with it at k times the sun's segment. An h_H whose μ'ω =
    μv/(μl·h_H) is round (``pole_distances``) is tried first where one reaches ``SEGMENT_MIN``, and
    last where none does; a whole millimetre between (μ'ω then as it falls: stop 13's 26,5-mm
    segment needs h_H = 87 mm, the round ones 62,5 and 100 mm)."""
    v, rec = got
    if abs(v.segments["H"]) >= SEGMENT_MIN or not v.segments["H"]:
        return got
    slope = abs(v.segments["H"]) / v.h                       # (about: the segment as read)
    _, h_ = _size(rec)
    tallest = v.h + room_h - h_ - 2.0                        # h_H the zone's spare height holds
    need = SEGMENT_MIN / slope
    hs = [q for q in pole_distances(v.mu_v / v.mu_l, 0.0, min(H_CARRIER, tallest)) if q >= 1.5 * v.h]
    want = min(H_CARRIER, math.ceil(need), tallest)
    tries = [(1.0, q, True) for q in hs if q >= need][:1] + [(1.0, want, False)]   # μ'ω round first (review 48)
    if want < 1.5 * v.h:                  # too little spare height: the plan's h (and the sun's segment)
        tries.append((0.5 * tallest / v.h, tallest, False))  # halved of h_H — the carrier's the longest
    tries += [(1.0, q, True) for q in hs[-1:] if q < need]    # a round μ'ω short of SEGMENT_MIN, last
    for k, hH, rnd in tries:
        for _ in range(6):                # the labels may push the pictures out: a little shorter
            if hH < 1.5 * k * v.h or k < 0.4:
                break
            e = at_h(hH, k)
            if e is not None and _size(e[1])[0] <= room_w and _size(e[1])[1] <= room_h:
                if e[0].ratio_bound <= v.ratio_bound and abs(e[0].segments["H"]) >= 1.5 * abs(v.segments["H"]):
                    return e      # (u1H no worse bounded: s1 shorter and h, h_H laid off weigh in too)
                break
            lower = [q for q in hs if q < hH]
            if rnd and not lower:
                break
            hH = lower[-1] if rnd else k * v.h + 0.8 * (hH - k * v.h)
    return got


def _grown(tr, precision: float, lang: str, f: Form, mesh, plan: Record, vel, pair=None):
    """The planetary pictures as large as their place in the row under the meshing takes (beside the
    λ diagrams, the meshing's height and the tables' column off the field): for each scale of the
    scheme (GOST 2.302, the ring's radius at most ``GROW``'s largest × 80 mm) whose scheme leaves the
    plan its height, and vA (``SCHEME_SHARES``), the plan of angular velocities filling the zone
    (``filled``); of those, the pictures that read u1H within the narrowest bound (the heights r1, aw,
    r3 laid off longer and the segments read longer both lower it: review 12's 1:1 reads within ±0,94
    where 1:2 with a 1 mm longer ωH reads within ±1,53; stop 49's 9/40 + type A, 2:1 ±0,16 with
    h = 25 mm, 1:1 ±0,13, 1:2 ±0,25). No longer capped by the meshing's size (stop 49: capped, the
    pictures stood 270 × 190 mm in a 616 × 372 row, a 61-mm band empty over the meshing and under
    them). The pictures as they were when none fits. (Stop 50: ``longer`` — vA twice as long and the
    sun's segment with it where the zone's height held the pictures — removed: with μω round (``pole_distance``)
    the plan's segments are ω/μω whatever vA, the height never held them, and on no scene did it change
    the pictures.)"""
    mesh_w, mesh_h = _size(meshing_leaf(mesh, lang))               # the meshing with its caption
    lam_w = 0.0 if beside(f, mesh, lang) else _size(sliding_leaf(mesh.lam, lang))[0] + GAP   # with its caption
    region = field_of(f)
    room_w = drawings_room(f) - lam_w - 2 * GAP
    room_h = region[3] - region[1] - mesh_h - 3 * GAP
    r = tr.radii
    r3 = r["3"]
    top = max(r3, r["H"] + max(r["2"], r.get("2'", 0.0)))      # the scheme's top: the ring or the planet over it
    scales = sorted({at_least(r3 / (80.0 * k)) for k in GROW})     # the scheme's scales, the largest drawing first
    best = None
    for mu in scales:
        ring = r3 / mu * (1 + 1e-9)                              # (``construct_train`` takes μl = this scale)
        if top / mu + 26.0 + min(H_MIN, vel.h) + 20.0 > room_h:   # the scheme, the plan under it, its labels
            continue
        for va_share in (() if lam_w else ALONE_SHARES) + SCHEME_SHARES:   # the longer vA where it fits (the plan
            #                                                             then no taller for its S)
            d = filled(tr, precision, lang, ring, 60.0 * ring / 80.0 * va_share, room_w, room_h, min(H_MIN, vel.h))
            if d is not None:
                if best is None or _rank(d[0], tr.ratio) < _rank(best[0], tr.ratio):   # (a tie: the larger)
                    best = d
                if d[0].h >= H_MIN - 1e-9:
                    break         # (else a shorter vA may still give h ≥ H_MIN: stop 55, the lead's 14/56 in
                #                   English at 1:1 was 1 mm too wide with h = 50 mm — μω is round, so the pictures'
                #                   width jumps — and fell to h = 25 mm, which ranked under 1:2 read within ±7,1 %)
    if best is None:
        return vel, plan
    # the scheme over and under the axis (``_whole``) only where the λ diagrams in the row already stand at
    # the meshing's scale: elsewhere they grow into the room the pictures leave (``_lambda_filling``), and the
    # whole scheme, a scale smaller and filling the row, left them at theirs (11/53's stood at 5:1 beside the
    # half at 2:1, at 2,5:1 beside the whole at 1:1; drawn no wider than the half, the whole left review 13's
    # row 40 mm short and its λ did not grow)
    if lam_w and pair is not None and mesh.lam is not None and mesh.lam.scales["mu_l"] > mesh.mu_l * (1 + 1e-9):
        return best
    wide = room_w
    whole = None
    for mu in (best[0].mu_l,):            # the half's scale alone (``_whole``)
        ring = r3 / mu * (1 + 1e-9)
        if 2.0 * top / mu + 13.0 + 20.0 > room_h:                # both halves of the scheme, its caption
            continue
        for va_share in (() if lam_w else ALONE_SHARES) + SCHEME_SHARES:
            d = filled(tr, precision, lang, ring, 60.0 * ring / 80.0 * va_share, wide, room_h, min(H_MIN, vel.h),
                       full=True)
            if d is not None and (whole is None or _rank(d[0]) < _rank(whole[0])):
                whole = d
    return _whole(best, whole, tr.ratio)


def _whole(best, whole, u: float):
    """The planetary pictures: ``whole`` — the scheme over and under the central axis, both planets, the
    carrier across them, the ring's frame on both sides, as the textbook draws a 2K-H train (stop 57: the
    lead found the half over the axis sparse), the plan of angular velocities under the velocity picture —
    where it keeps what ``_rank`` asks first (h, the carrier's segment) and reads u1H within a bound under
    the lab's 5 % (a reading then within the lab's limit whatever the ruler does), drawn at the half's
    scale; else ``best``, the half-section. The whole scheme is as tall again under the axis: the lead's
    57 and review 10 (ring 127,5 mm) were whole at 1:2, u1H within ±3,7 % and ω1 read +2,2 %, where the
    half stands at 1:1 within ±0,86 % and reads ω1 −0,16 % (stop 58: review 10 mark 19 had sent back ω1
    read +2,5 % off a train at 1:2 where 1:1 fits; the whole is taken at the half's scale only: GEARS56)."""
    if whole is None or _rank(whole[0])[:2] > _rank(best[0])[:2] or 100.0 * whole[0].ratio_bound / u > LAB_LIMIT \
            or not math.isclose(whole[0].mu_l, best[0].mu_l, rel_tol=1e-9):
        return best
    return whole


def _rank(v, u: float | None = None) -> tuple:
    """The planetary pictures' order of preference on the A1 sheet: h at least ``H_MIN`` and the carrier's
    segment at least ``SEGMENT_MIN`` (what a teacher reads with the ruler: review 13's ωH off 3,8 mm), then
    the narrowest bound of u1H — with ``u`` (the exact u1H) as the notes print it, in % of u1H to 0,01, so
    that pictures the notes give the same bound tie and ``_grown`` keeps the larger scheme (stop 58: a
    13/30 pair's 20/31/82 train stood at 1:2, 273 × 165 mm, ±0,805 %, over a 50-mm blank in a 257-mm row,
    where 1:1 — 272 × 196 mm — reads within ±0,808 %: both «±0,81 %»)."""
    b = v.ratio_bound if u is None else round(100.0 * v.ratio_bound / abs(u), 2)
    return (v.h < H_MIN - 1e-9, abs(v.segments["H"]) < SEGMENT_MIN - 1e-9, b)


def construct_on(sol, f: Form, precision: float = 0.5, lang: str = "uk"):
    """The meshing and the planetary pictures at the scales of the gear sheet on ``f``: (mesh, vel,
    plan). What `graphplan gears`, graphplan.gears(), the web page and the sheet measure, so that all
    print the same readings."""
    region = field_of(f)
    vel = construct_train(sol.train, precision, lang, ring_mm=110.0 if f.name == "A1" else 80.0) \
        if sol.train else None
    plan = _plan(vel, lang) if vel else None
    mesh = None
    if sol.pair:
        # the meshing's zone: the field less the tables' column and the row under it where the λ diagrams
        # (N1N2 long, at the meshing's scale) stand beside the planetary pictures
        side_w = max(TITLE, 150.0)
        plan_w, plan_h = ((plan.bounds()[2] - plan.bounds()[0], plan.bounds()[3] - plan.bounds()[1]) if plan
                          else (0.0, 0.0))
        zone_w = region[2] - region[0] - side_w - GAP
        zone_h = region[3] - region[1] - max(SLIDING_H, plan_h) - GAP
        line = zone_w - (plan_w + GAP if plan else 0.0) - 30.0
        if zone_w < 150.0 or zone_h < 150.0 or line < 100.0:   # a small format: the meshing heads a set
            mesh = set_mesh(sol.pair, f, precision, lang)
        else:
            mesh = construct_mesh(sol.pair, precision, lang, height_mm=zone_h, width_mm=zone_w, line_mm=line)
            mesh = _into_band(sol.pair, mesh, zone_w, zone_h, line, precision, lang)
            teeth = most_teeth(sol.pair, mesh.module_mm, zone_h, zone_w)     # more teeth where the zone holds them
            if teeth != TEETH:
                mesh = construct_mesh(sol.pair, precision, lang, module_mm=mesh.module_mm, teeth=teeth)
    if mesh is not None and sol.pair and f.name == "A1":
        _beside_smaller(sol, mesh, f, lang)
    if vel is not None and mesh is not None and f.name == "A1":
        vel, plan = _grown(sol.train, precision, lang, f, mesh, plan, vel, sol.pair)
    if mesh is not None and sol.pair:
        _slide(sol, mesh, f, plan, lang)
    return mesh, vel, plan


def _into_band(pair, mesh, zone_w: float, zone_h: float, line: float, precision: float, lang: str):
    """The A1 meshing drawn at the largest GOST 2.302 scale whose whole depth is 40–60 mm where
    ``mesh_scale`` (which judges a window a few mm wider and taller than the drawing) kept a smaller one
    outside the band: each such scale built and its drawing with its caption measured against the zone
    ``zone_w`` × ``zone_h``, the λ diagrams' N1N2 (at their own scale, ``lambda_mu``) within ``line``.
    Stop 55: the lead's 14/56, m = 6 mm, was drawn at 2,5:1, the teeth 33,75 mm deep with a warning, its
    window at 4:1 judged 621 mm wide in a 611-mm zone — the drawing is 586 mm; ``mesh`` as it was where no
    scale in the band fits."""
    from graphplan.graphic.gears import DEPTH_MM, ENLARGE, REDUCE, lambda_mu
    m = pair.pair.module * 1000.0
    if DEPTH_MM[0] <= 2.25 * mesh.module_mm <= DEPTH_MM[1]:
        return mesh
    for k in sorted(ENLARGE + REDUCE, reverse=True):
        md = m * k
        if not DEPTH_MM[0] <= 2.25 * md <= DEPTH_MM[1] or md <= mesh.module_mm * (1 + 1e-9):
            continue
        if pair.g / lambda_mu(pair, pair.pair.module / md) > line + 1e-9:
            continue
        got = construct_mesh(pair, precision, lang, module_mm=md)
        w, h = _size(meshing_leaf(got, lang))
        if w <= zone_w + 1e-9 and h <= zone_h + 1e-9:
            return got
    return mesh


LAMBDA_BESIDE_MIN = 120.0   # mm: N1N2 drawn at least this long where the λ diagrams go beside the meshing smaller


def _beside_smaller(sol, mesh, f: Form, lang: str) -> None:
    """The λ diagrams (``mesh.lam``) at the next GOST 2.302 scale below their own where that one step
    takes them beside the meshing, N1N2 still ``LAMBDA_BESIDE_MIN`` long — the row under the meshing then
    the planetary pictures' alone, across it. GEARS51 (stop 51/52): N1N2 at the meshing's 2,5:1 made the
    λ diagrams 205 mm wide, 6 mm too wide to stand beside the 434-mm meshing; the meshing stood centred
    between two 88-mm blank strips, the λ diagrams in the row beside the pictures; at 2:1 (N1N2 150 mm)
    they are 167 mm and fill the strips. ``mesh.lam`` as it was where no such step does."""
    from graphplan.graphic.gears import ENLARGE, REDUCE
    if beside(f, mesh, lang):
        return
    now = mesh.lam.scales["mu_l"]
    smaller = [0.001 / k for k in ENLARGE + REDUCE if 0.001 / k > now * (1 + 1e-9)]
    if not smaller:
        return
    mu_x = min(smaller)                   # one step down
    if sol.pair.g / mu_x < LAMBDA_BESIDE_MIN - 1e-9:
        return
    old = mesh.lam
    mesh.lam = sliding_diagram(sol.pair, mesh, 1.0 / old.scales["mu_lambda"], mu_x)
    if not beside(f, mesh, lang):
        mesh.lam = old


def _slide(sol, mesh, f: Form, plan: Record | None, lang: str) -> None:
    """The meshing's λ diagrams (``mesh.lam``) with the unit their place takes: beside the meshing, as
    tall as it with its caption; on A1 in the row under it beside the planetary pictures, as tall as the
    row's room under the meshing; in a set, as tall as the planetary pictures."""
    region = field_of(f)
    if beside(f, mesh, lang):
        row_h = mesh.record.bounds()[3] - mesh.record.bounds()[1] + 12.0
    elif f.name == "A1":                  # the row's whole room under the meshing (review 54, item 23: capped
        top = meshing_leaf(mesh, lang).bounds()     # at the meshing's 223 mm, 11/53's λ stood at 40 mm a unit
        row_h = max(SLIDING_H, region[3] - region[1] - (top[3] - top[1]) - 2 * GAP)   # over a 320 × 130-mm
        #                                           blank; ``lambda_unit`` keeps four units within 0.75 N1N2)
    else:
        row_h = max(SLIDING_H, plan.bounds()[3] - plan.bounds()[1] if plan else 0.0)
    mu_x = mesh.lam.scales["mu_l"] if mesh.lam is not None else lambda_mu(sol.pair, mesh.mu_l)   # (its own:
    mesh.lam = sliding_diagram(sol.pair, mesh, lambda_unit(row_h, sol.pair.g / mu_x), mu_x)   # ``_beside_smaller``)


def meshing_leaf(mesh, lang: str) -> Record:
    """The meshing with its caption: the name, the scale and μl."""
    return captioned(mesh.record, WORDS[lang]["meshing"].format(mu=_n(mesh.mu_l, lang),
                                                               scale=drawing_scale(mesh.mu_l, lang)))


def set_mesh(pair, f: Form, precision: float, lang: str, o1: bool = True):
    """The meshing at the head of an A2/A3 set: the largest GOST 2.302 scale whose whole depth 2.25m
    is 40–60 mm and whose drawing, caption included, fits the first sheet over its title block (or
    beside it); when none in that band does, the fitting one whose depth comes nearest the band (as
    ``mesh_scale`` takes it); the drawings built and measured, not estimated (``mesh_scale``'s window
    is a few mm wider than the drawing)."""
    from graphplan.graphic.gears import DEPTH_MM, ENLARGE, REDUCE
    x0, y0, x1, y1 = field_of(f)
    keep = keep_out(f)
    m = pair.pair.module * 1000.0
    series = sorted(ENLARGE + REDUCE, reverse=True)
    far = lambda k: max(DEPTH_MM[0] / (2.25 * m * k), 2.25 * m * k / DEPTH_MM[1])     # noqa: E731
    for k in sorted(series, key=lambda k: (round(far(k), 9) if far(k) > 1.0 else 0.0, -k)):
        mesh = construct_mesh(pair, precision, lang, module_mm=m * k, o1=o1)
        b = meshing_leaf(mesh, lang).bounds()
        w, h = b[2] - b[0], b[3] - b[1]
        if (w <= x1 - x0 and h <= y1 - keep[3]) or (w <= keep[0] - x0 and h <= y1 - y0):
            return mesh
    return construct_mesh(pair, precision, lang, module_mm=m * series[-1], o1=o1)


def _more_teeth(pair, mesh, f: Form, precision: float, lang: str, o1: bool = True):
    """The set's meshing at its scale with more teeth of each wheel (the most of ``MORE_TEETH`` whose
    outer teeth stay within ``TEETH_SPAN``) whose drawing with its caption still fits the first sheet
    over its title block; else None."""
    x0, y0, x1, y1 = field_of(f)
    room_w, room_h = x1 - x0, y1 - keep_out(f)[3]
    for k in MORE_TEETH:                  # (the drawing measured, not its window estimated)
        if any((k / 2 + 0.3) * 2 * math.pi / z > TEETH_SPAN for z in pair.pair.z):
            continue
        more = construct_mesh(pair, precision, lang, module_mm=mesh.module_mm, teeth=k, o1=o1)
        b = meshing_leaf(more, lang).bounds()
        if b[2] - b[0] <= room_w and b[3] - b[1] <= room_h:
            more.lam = mesh.lam
            return more
    return None


def beside(f: Form, mesh, lang: str) -> bool:
    """Whether the λ diagrams stand beside the meshing (the zone under it then the planetary
    pictures' alone): when the two, captioned as ``zones`` sets them, fit across the drawings' zone,
    the field less the tables' column. (Measured bare, the λ diagrams of z = 10/25 were 127 mm wide
    where their caption with the abscissa's scale makes them 212: the planetary pictures were sized
    for the row under the meshing alone, the λ diagrams came into that row and the A1 sheet became
    two.)"""
    mesh_w = _size(meshing_leaf(mesh, lang))[0]
    lam_w = _size(sliding_leaf(mesh.lam, lang))[0]
    return mesh_w + GAP + lam_w <= drawings_room(f)


def drawings_room(f: Form, width: float = TITLE) -> float:
    """The drawings' width on one sheet ``f``: the field less the tables' column (``width``, at least
    the title block's reach with its clearance, ``keep_out``) and a gap — what ``zones`` lays the
    meshing and the λ diagrams across. (``beside`` asked the field less TITLE, 1 mm more than ``zones``
    gave: GEARS12's λ diagrams were judged beside its 434-mm meshing, ``zones`` put them under it with
    the planetary pictures grown for the whole row, and the A1 sheet became two.)"""
    x0, _, x1, _ = field_of(f)
    return x1 - x0 - max(width, x1 - keep_out(f)[0]) - GAP


LAMBDA_UNITS = (20.0, 25.0, 40.0, 50.0)    # mm a unit of λ (μλ = 0.05, 0.04, 0.025, 0.02 1/mm)


def lambda_unit(row_h: float, line_mm: float | None = None) -> float:
    """The λ diagrams' unit, mm: the largest of ``LAMBDA_UNITS`` whose diagram (λ from −3 to 1 and
    the margins, with its two-line caption, about 4.3 units and 40 mm) stands in the row ``row_h``
    mm tall beside the planetary pictures, and — sized to its content, two curves (review 10, mark
    15: 240 × 190 mm for them) — whose four units of λ are no taller than 0.75 of N1N2 drawn
    (``line_mm``)."""
    fits = [u for u in LAMBDA_UNITS if 4.3 * u + 40.0 <= row_h]
    if line_mm is not None:
        fits = [u for u in fits if 4.0 * u <= 0.75 * line_mm] or fits[:1]
    return max(fits or [LAMBDA_UNITS[0]])


def build_gears_sheet(g: Gears, f: Form, args: SheetOptions) -> Sheet:
    """The gear sheet: the meshing with the λ diagrams under it, the planetary pictures, the three
    tables and the notes, in zones (the meshing at the largest standard scale its zone takes); a
    format too small flows them over further sheets of the set in reading order (sheets/gearset.py),
    the planetary pictures there grown while the set keeps its count of sheets (``on_sheet``)."""
    lang = args.lang
    sol = solve(g)
    mesh, vel, pages = on_sheet(g, sol, f, args.precision, lang)
    w = WORDS[lang]
    return compose(f, pages, _fields(g, lang, mesh.mu_l if mesh else (vel.mu_l if vel else None)), lang,
                   f"{g.title_in(lang)} — {w['subtitle']}")


def on_sheet(g: Gears, sol, f: Form, precision: float = 0.5, lang: str = "uk"):
    """The gear sheet's constructions as the sheet (or the set) on ``f`` ends up drawing and reading
    them, and its pages: (mesh, velocities, pages). What `graphplan gears --format F`, graphplan.gears()
    and the web page print, so that the terminal's readings are the sheet's tables' (an A3 set grows
    its planetary pictures after composing: ``construct_on`` alone gave the first, smaller pictures —
    u1H read off h = 33 mm where the set's sheet drew h = 69 mm)."""
    mesh, vel, plan = construct_on(sol, f, precision, lang)
    drawings, tables, parts = _blocks(g, sol, mesh, vel, plan, lang)
    lines = [x for part in parts for x in part]
    pages = None
    for k in SIZES:                       # the tables as the other sheets draw theirs, in 7-mm rows, else ruled
        pages = _composed(drawings, tables, parts, f, k)
        if pages is not None:
            break
    if pages is not None and mesh is not None and plan is not None:
        pages = _lambda_filling(g, sol, mesh, vel, plan, f, lang, pages, k)
    if pages is None:                     # a set of sheets (sheets/gearset.py)
        one = mesh
        kept_ = (vel,)

        def cut(o1: bool):
            """The set with the meshing drawn with O1 where in reach (``o1``) or its centre line broken."""
            m_, d_, t_, p_ = one, drawings, tables, parts
            if m_ is not None:            # its meshing at the set's scale (``set_mesh``), not at the one the
                head = set_mesh(sol.pair, f, precision, lang, o1)   # one-sheet zones took (stop 47: A2 drew
                if head.module_mm != m_.module_mm or not o1:    # 14/35 at 2,5:1, the depth 22,5 mm, s_a2
                    m_ = head                                    # +5,96 %, while 5:1 fits the set's first sheet)
                # the λ diagrams weighed in the set's cut at the least unit (they stand under the meshing where
                # its sheet holds them so: stop 47, 11/29 on A2 left its first sheet 45 % empty, 151 mm of λ
                # diagrams for 145 mm under the meshing); the sheet that holds them takes ``lam``'s longer unit
                m_.lam = sliding_diagram(sol.pair, m_, LAMBDA_UNITS[0])
                d_, t_, p_ = _blocks(g, sol, m_, vel, plan, lang)
            more_ = _more_teeth(sol.pair, m_, f, precision, lang, o1) if m_ is not None else None
            lam_ = _set_lambda(sol, m_, f, lang) if m_ is not None else None
            return m_, more_, lam_, _set(d_, t_, p_, f, more_, lang, lam_)

        mesh, more, lam, pages = cut(True)
        o1 = True
        if mesh is not None and mesh.o1_shown and pages is not None:    # O1 drawn where it costs no sheet
            flat = cut(False)             # (stop 49: 9/40's en A3 set took a 4th sheet, 80 % empty, for it)
            if flat[3] is not None and len(flat[3]) < len(pages):
                mesh, more, lam, pages = flat
                o1 = False
        if pages is None:
            raise said_error(GraphplanError, "sh drawing larger", g.source, None, form=f.name, option="--format")
        if vel is not None and len(pages) > 1 and {q.name for q in pages[-1]} <= TRAIN_ALONE:
            # Table 3 and its notes alone on the last sheet: the set cut again from smaller first pictures
            # (``FIRST_SMALLER``) where that saves the sheet — the pictures then grow back on their sheet
            # (``_set_grown``) as far as the count allows, a sheet more where they read u1H past 5 % (below).
            # Stop 58: the lead's 9/35 A3 set ended with Table 3 alone on a fourth sheet, as five before it.
            kept_ = vel, plan, drawings, tables, parts
            undone = vel, mesh, more, lam, pages
            for k in FIRST_SMALLER:
                try:
                    v = construct_train(sol.train, precision, lang, ring_mm=80.0 * k, va_mm=60.0 * k,
                                        sun_segment_mm=100.0 * k)
                except GraphplanError:
                    continue
                vel, plan = v, _plan(v, lang)
                drawings, tables, parts = _blocks(g, sol, one, vel, plan, lang)
                got = cut(o1)
                if got[3] is not None and len(got[3]) < len(pages):
                    mesh, more, lam, pages = got
                    break
            else:
                vel, plan, drawings, tables, parts = kept_
        if vel is not None:
            first = pages
            vel0 = vel
            vel, pages = _set_grown(g, sol, mesh, more, vel0, f, precision, lang, first, lam)
            if vel0 is not kept_[0] and vel.h < min(H_MIN, kept_[0].h) - 1e-9:
                # the sheet saved with the smaller first pictures only where they grow back to the pole distance
                # the first would have had (h at least H_MIN, or theirs): GEARS_B47's pictures stood at 1:4 with
                # h = 25 mm on three sheets, where four keep 1:2 and h = 62,5 mm (u1H within ±0,93 %)
                vel0, mesh, more, lam, first = undone
                vel, pages = _set_grown(g, sol, mesh, more, vel0, f, precision, lang, first, lam)
            short = abs(vel.segments["H"])
            if precision > 0 and 0 < short < SEGMENT_MIN / 2:      # one more sheet where it reads ωH
                v1, p1 = _set_grown(g, sol, mesh, more, vel0, f, precision, lang, first, lam, extra=1)
                if abs(v1.segments["H"]) >= 2 * short:                   # (it doubles: review 13 #9's 3,8 mm)
                    vel, pages = v1, p1
            exact = sol.train.ratio
            off = lambda v: 100.0 * abs(v.ratio - exact) / exact      # noqa: E731  (u1H's δ %, as Table 3)
            if precision > 0 and off(vel) > LAB_LIMIT and len(pages) == len(first):
                # one more sheet where the pictures grown on it read u1H within the lab's 5 % (stop 54: the
                # lead's A3 set of three drew the train at 1:2 beside Table 3, u1H read +7,36 %)
                v1, p1 = _set_grown(g, sol, mesh, more, vel0, f, precision, lang, first, lam, extra=1)
                if off(v1) <= LAB_LIMIT:
                    vel, pages = v1, p1
    return mesh, vel, pages


TRAIN_ALONE = {"train", "train notes"}    # a set's last sheet that holds Table 3 and its notes alone
FIRST_SMALLER = (0.8, 0.64, 0.5)          # a set's first planetary pictures, × (80, 60, 100) mm, tried smaller
#                                           where Table 3 stands alone on the last sheet


def _lambda_filling(g: Gears, sol, mesh, vel, plan, f: Form, lang: str, pages, k):
    """The one-sheet pages with the λ diagrams in the row under the meshing drawn at the largest GOST
    2.302 scale of N1N2 — no larger than the meshing's — with which the row (the λ diagrams, then the
    planetary pictures) still fits the drawings' zone, λ's unit grown with it (``lambda_unit``); the
    sheet composed again and measured (``zones``), ``pages`` as they were where no larger scale fits.
    Stop 49/50: the planetary pictures' plan of angular velocities is as wide as its round μω allows
    (the ω1 segment is ω1/μω), and the λ diagrams at 2,5:1 (N1N2 150 mm, 190 × 165 mm) left the row a
    245 × 108-mm blank under them and 89 mm unused beside the pictures on GEARS50's A1; at 4:1 they
    take the row's width (N1N2 240 mm, λ 40 mm a unit). ``k``: the tables' size the pages were
    composed with."""
    region = field_of(f)
    if f.name != "A1" or beside(f, mesh, lang):
        return pages
    from graphplan.graphic.gears import ENLARGE, REDUCE
    now = mesh.lam.scales["mu_l"]
    top = meshing_leaf(mesh, lang).bounds()
    row_h = max(SLIDING_H, region[3] - region[1] - (top[3] - top[1]) - 2 * GAP)     # (as ``_slide``)
    old = mesh.lam
    for scale in sorted(ENLARGE + REDUCE, reverse=True):
        mu_x = 0.001 / scale
        if mu_x < mesh.mu_l - 1e-12 or mu_x >= now - 1e-12:
            continue
        mesh.lam = sliding_diagram(sol.pair, mesh, lambda_unit(row_h, sol.pair.g / mu_x), mu_x)
        drawings, tables, parts = _blocks(g, sol, mesh, vel, plan, lang)
        # at the tables' size ``k``, else the next but the ruled (stop 61: with the pair's notes under the λ
        # diagrams the column holds the 8,4-mm rows, where the notes whole in it had 7-mm rows — the λ
        # diagrams of 11/53 grow to 5:1 with the 7-mm rows, the notes whole, as before)
        for size in SIZES[SIZES.index(k):-1] or [k]:
            got = _composed(drawings, tables, parts, f, size)
            if got is not None:
                return got
    mesh.lam = old
    return pages


def _blocks(g: Gears, sol, mesh, vel, plan, lang: str) -> tuple[list[Leaf], list[Leaf], list[list[str]]]:
    """The sheet's drawings (the meshing, the λ diagrams, the planetary pictures), its tables and the
    lines of its notes in their parts: the task data (``data_lines``), then ``note_parts``, from the
    constructions."""
    w = WORDS[lang]
    doc = gears_json(sol, mesh, vel, g.source or "")
    drawings: list[Leaf] = []
    tables: list[Leaf] = []
    if mesh is not None:
        drawings.append(Leaf("meshing", record=meshing_leaf(mesh, lang)))
        drawings.append(Leaf("sliding", record=sliding_leaf(mesh.lam, lang)))
        tables += [Leaf("geometry", record=geometry_table(doc, lang)), Leaf("quality", record=quality_table(doc, lang))]
    if plan is not None:
        drawings.append(Leaf("planetary", record=plan))
        tables.append(Leaf("train", record=train_table(doc, lang)))
    return drawings, tables, [data_lines(doc, lang)] + note_parts(doc, lang, mesh, vel)


def _set(drawings: list[Leaf], tables: list[Leaf], parts: list[list[str]], f: Form, more, lang: str,
         lam: Leaf | None = None):
    """The set's sheets: the fewest with the tables as the other sheets draw theirs (at the ruled
    size only where no set holds those), the meshing with ``more`` teeth or its three — the larger tables, then more teeth, where
    that costs no sheet —, each part of the notes by its tables (the pair's, the train's), ``lam``
    (the λ diagrams with a longer unit) where their sheet holds it. None when a drawing is larger
    than a sheet."""
    from graphplan.sheets.gearset import set_pages
    data, parts = parts[0], parts[1:]
    names = ["notes", "train notes"] if len(parts) == 2 else (["notes"] if any(t.name == "geometry" for t in tables)
                                                               else ["train notes"])
    lines = dict(zip(names, parts))
    lines["data"] = data
    names = ["data"] + names
    # the tables as the other sheets draw theirs (3,5-mm letters in 8,4- or 7-mm rows), the ruled 2,5-mm
    # letters only where no set holds those: a set one sheet longer with readable tables rather (stop 52:
    # the set knew only 8,4-mm rows or the ruled size — GEARS52's A2 and A3 tables 2,5 mm beside 3,5-mm
    # notes; stop 53: the fewest sheets still took the ruled tables for GEARS53's A3, GEARS52's A2 and
    # GEARS51's A3 sets, one sheet saved)
    tried = []
    for k in SIZES:
        if k == 1.0 and any(t is not None for t in tried):
            break
        grown = [Leaf(t.name, record=_sized(t.record, k)) for t in tables]
        width = max([TITLE] + [t.w for t in grown])
        side = grown + [Leaf(n, record=note_block(lines[n], width)) for n in names]
        for m in ([more] if more is not None else []) + [None]:
            d = [Leaf("meshing", record=meshing_leaf(m, lang)) if (m is not None and t.name == "meshing") else t
                 for t in drawings]
            larger = [{t.name: Leaf(t.name, record=_sized(t.record, b)) for t in tables}
                      for b in SIZES[:SIZES.index(k)]] or [{}]  # each sheet's tables larger where it holds them
            for big in larger:
                if lam is not None:
                    big["sliding"] = lam
            tried.append(set_pages(d + side, f, lambda n, w: Leaf(n, record=note_block(lines[n], w)), larger))
    tried = [t for t in tried if t is not None]
    # the fewest sheets, then the notes on the sheet of the tables they explain (review 54: the 11/53 A3 set
    # took the 8,4-mm rows and sent the pair's notes to the planetary sheet, under the train's pictures,
    # where the 7-mm rows keep them by Tables 1 and 2 — the same count of sheets), then the larger tables
    return min(tried, key=lambda t: (len(t), _notes_apart(t))) if tried else None


def _notes_apart(pages) -> int:
    """How many parts of a set's notes stand on a sheet without a table they explain (gearset ``OWN``)."""
    from graphplan.sheets.gearset import OWN
    out = 0
    for page in pages:
        names = {p.name for p in page}
        out += sum(1 for n, own in OWN.items() if n in names and not names & set(own))
    return out


SET_GROW = (3.0, 2.5, 2.0, 1.8, 1.6, 1.4, 1.3, 1.2, 1.1)    # a set's planetary pictures, × (80, 60, 100) mm, tried


def _set_lambda(sol, mesh, f: Form, lang: str) -> Leaf:
    """The λ diagrams of a set with the longest unit of ``LAMBDA_UNITS`` a later sheet's field takes
    in height (over its title block form 2a), captioned."""
    from graphplan.sheets.gearset import later_keep
    x0, y0, x1, y1 = field_of(f)
    rec = sliding_diagram(sol.pair, mesh, lambda_unit(y1 - later_keep(f)[3] - GAP,
                                                    sol.pair.g / lambda_mu(sol.pair, mesh.mu_l)))
    return Leaf("sliding", record=sliding_leaf(rec, lang))


def sliding_leaf(rec: Record, lang: str) -> Record:
    """The λ diagrams captioned: the name, then the abscissa's scale — a length along N1N2 of the part,
    as GOST 2.302's scale and μl (review 12, mark 22: only «уздовж N1N2» was printed) —, the working
    part heavy, and μλ."""
    w = WORDS[lang]
    mu = rec.scales["mu_l"]
    second = w["sliding2"].format(mu=_n(rec.scales["mu_lambda"], lang), mul=_n(mu, lang), scale=drawing_scale(mu, lang))
    b = rec.bounds()
    head, _, rest = second.partition("; ")
    if not rest or text_width(second, CAPTION_2) <= b[2] - b[0]:
        return captioned(rec, w["sliding"], second)
    # a caption wider than the diagrams in two lines, the abscissa's scale, then the working part and
    # μλ (stop 46: the one line made the leaf 214 mm for a 196-mm diagram, 6 mm too wide to stand
    # beside a 5:1 meshing of 11/29 — the A1 sheet then left a third of its drawings' zone empty)
    out = captioned(rec, w["sliding"], head + ";")
    y = min(q.points[0][1] for q in out.items if q.kind == "text" and q.step == "caption")
    out.label(((b[0] + b[2]) / 2, y - line_pitch(CAPTION_2) - 1.0), rest, size=CAPTION_2, anchor="middle",
              layer="labels", step="caption")
    return out


def _set_grown(g: Gears, sol, mesh, more, vel, f: Form, precision: float, lang: str, pages, lam=None,
               extra: int = 0):
    """A set's planetary pictures grown (the ring's radius, vA and the sun's segment together,
    ``SET_GROW``) to the largest that keeps the set's count of sheets (on a later sheet than the
    meshing they are that sheet's main drawing): the pictures read with a longer h and segments.
    (velocities, pages): ``vel`` and ``pages`` as they were when none does. The sizes are tried by halving (a larger picture never
    takes fewer sheets). ``extra``: sheets the set may take beyond its count (review 13 #9: a set whose
    plan reads ωH off 2,5–4 mm takes one more sheet where the plan grows to read it off twice that)."""
    def drawn(k: float, va_share: float, share: float):
        try:
            v = construct_train(sol.train, precision, lang, ring_mm=80.0 * k, va_mm=60.0 * k * va_share,
                                sun_segment_mm=100.0 * k * share)
        except GraphplanError:
            return None
        return v, _plan(v, lang)

    def good(v) -> bool:                  # no smaller than the set's first pictures, h as long as A1's least
        return v.mu_l <= vel.mu_l and v.h >= min(H_MIN, vel.h) and (v.mu_l, -v.h) < (vel.mu_l, -vel.h)

    def kept(v, p):                       # the set with these pictures, when it keeps the count of sheets
        drawings, tables, parts = _blocks(g, sol, mesh, v, p, lang)
        got = _set(drawings, tables, parts, f, more, lang, lam)
        return got if got is not None and len(got) <= len(pages) + extra else None

    # the largest size (halving SET_GROW: a larger picture never takes fewer sheets) whose narrowest
    # variant keeps the count, then at it the widest variant that does — the ring's scale the one that
    # reads best (review 10: A3's train at 1:2 read ω1 +2,5 % where 1:1 fits beside Table 3)
    # (halving over the sizes whose pictures are good: h is not monotonic in the size — μv rounded —, and a
    # size left out for its h sent the halving to the smaller ones; stop 47: A2's 14/35 train drawn at
    # 1:2, u1H within ±0,33, where 1:1 kept the set's two sheets and reads it within ±0,18)
    sizes = [(k, d) for k in SET_GROW for d in [drawn(k, *SHARES[-1])] if d is not None and good(d[0])]
    lo, hi, got = 0, len(sizes) - 1, None
    while lo <= hi:
        mid = (lo + hi) // 2
        out = kept(*sizes[mid][1])
        if out is not None:
            got, hi = (sizes[mid][0], out, sizes[mid][1]), mid - 1
        else:
            lo = mid + 1
    if got is None:
        chosen = (vel, pages)
    else:
        chosen = (got[2][0], got[1])
        for va_share, share in SHARES[:-1]:
            d = drawn(got[0], va_share, share)
            if d is not None and good(d[0]):
                out = kept(*d)
                if out is not None:
                    chosen = (d[0], out)
                    break
    return _set_filled(sol, f, precision, lang, chosen, vel, kept)


def _set_filled(sol, f: Form, precision: float, lang: str, chosen, vel, kept):
    """A set's planetary pictures at their scheme's scale with the plan of angular velocities filling
    the sheet's width at the pictures' height (``filled``; review 12 mark 11: the A3 set's ωH was a
    6-mm segment on a sheet two thirds empty), where that keeps the set's count of sheets and reads
    u1H better (its bound smaller): (velocities, pages), ``chosen`` else. Where the pictures so read u1H
    within a bound wider than half the lab's 5 %, the scheme one and two GOST 2.302 steps smaller is
    tried too, and the narrowest bound taken: the bound is mostly the radii r1, aw, r3 rounded to the
    ruler as laid off, which a smaller scale may put on its marks (stop 57: GEARS56's A3 drew 22,5, 78,75 and
    106,25 mm at 1:2 as 11, 39,5 and 53 mm, u1H read +4,78 % within ±6,1 % whatever the plan's size —
    S 128 → 257 mm took the bound only from ±7,4 to ±6,1 % —; at 1:2,5 they are 9, 31,5 and 42,5 mm, on
    the marks)."""
    from graphplan.graphic.gears import ENLARGE, REDUCE
    from graphplan.sheets.gearset import later_keep
    v0, pages = chosen
    x0, y0, x1, y1 = field_of(f)
    h0 = _size(_plan(v0, lang))[1]
    full = y1 - later_keep(f)[3] - GAP
    memo: dict = {}
    tried = set()

    def at(mu: float, bound: float):      # the first pictures at the scheme's scale ``mu`` reading u1H within
        ring = sol.train.radii["3"] / mu * (1 + 1e-9)                     # a narrower bound that keep the count
        for room_h in (full, 0.5 * (full + h0), h0):      # the sheet's height, then less
            for va_share in (4.0, 3.0, 2.0, 1.0):   # (the longest vA first: at a given height the longest plan —
                #                                   stop 54: with 2 the longest, GEARS_OWN54's A3 plan kept h = 25 mm
                #                                   and a 76-mm segment 1 over a sheet a third empty; 4 draws it 190 mm)
                d = filled(sol.train, precision, lang, ring, 60.0 * ring / 80.0 * va_share, x1 - x0, room_h,
                           min(H_MIN, vel.h), memo)
                if d is not None and d[0].ratio_bound < bound - 1e-12:
                    if id(d) not in tried:    # (a set tried once)
                        tried.add(id(d))
                        out = kept(*d)
                        if out is not None:
                            return d[0], out
                    break                     # (a shorter vA only makes it taller)
        return None

    best = at(v0.mu_l, v0.ratio_bound) or (v0, pages)
    if 100.0 * best[0].ratio_bound / sol.train.ratio > LAB_LIMIT / 2:
        for mu in sorted(0.001 / q for q in ENLARGE + REDUCE if 0.001 / q > v0.mu_l * (1 + 1e-9))[:2]:
            got = at(mu, best[0].ratio_bound)
            best = got or best
    return best


RULED_ROW = 6.0          # the gear tables' ruled rows, mm (``table(..., row_h=6.0)``)
TIGHT = 7.0 / 6.0        # the A1 column's tables at 3.5 mm letters in 7-mm rows (``tight``), × the ruled 6 mm
SIZES = (TABLES, (TABLES, TIGHT), 1.0)   # the A1 column's tables tried: 3.5 mm letters and 8.4-mm rows, 7-mm rows, ruled


def tight(rec: Record, k: float = TABLES, rows: float = TIGHT) -> Record:
    """A ruled table drawn ``k`` times wider with its letters ``k`` times taller (GOST 2.304's 3.5 mm
    from the ruled 2.5) and its rows only ``rows`` times taller: 7-mm rows for 3.5-mm letters — a
    letter 1 mm under its top rule, a descender 1.3 mm over its bottom one, as GOST 2.104's title block
    sets 3.5 mm in 5-mm rows. Stop 51: the 8.4-mm rows of ``enlarged`` left gears.toml's three tables and
    notes 19 mm (en 28) taller than the column over the title block; they fell back to 2.5-mm letters
    with 35-mm gaps between them."""
    from graphplan.graphic.record import Primitive
    big = enlarged(rec, k)
    f = rows / k
    row_h = RULED_ROW * rows

    def row_of(p: Primitive) -> int | None:       # a cell's lettering: the row it stands in (None: not a cell)
        return math.floor(-p.points[0][1] * f / row_h) if p.kind == "text" and p.points[0][1] < 0.0 else None

    # each row's one baseline: the lowest its cells need to keep their ink clear of the rules (the prime
    # of z′₂ raised onto the row's top rule in the 7-mm rows, review 51)
    lines: dict[int, float] = {}
    for p in big.items:
        r = row_of(p)
        if r is not None:
            y = baseline_in_row(p.text, p.size, p.points[0][1] * f, -r * row_h, row_h)
            lines[r] = min(lines.get(r, y), y)

    def placed(p: Primitive) -> Primitive:
        r = row_of(p)
        pts = ((p.points[0][0], lines[r]),) if r is not None else tuple((x, y * f) for x, y in p.points)
        return Primitive(p.kind, pts, p.role, p.layer, p.step, p.text, p.size, p.radius, p.angles, p.anchor,
                         p.width, p.turn)
    return Record(big.title, [placed(p) for p in big.items], dict(big.scales))


def _sized(rec: Record, k) -> Record:
    """A table at one of ``SIZES``: ``k`` times its ruled size, or (k, rows) ``tight``."""
    rec = _title_rewrapped(rec, k[0] if isinstance(k, tuple) else k)
    return tight(rec, *k) if isinstance(k, tuple) else enlarged(rec, k)


def _title_rewrapped(rec: Record, k: float) -> Record:
    """The ruled table's title (3.5-mm lines over its top rule, ``table``) wrapped anew for its drawing
    ``k`` times larger: its letters then take the nearest GOST 2.304 height (3.5·1.4 = 4.9 → 5 mm), wider
    than ``k`` times, so the lines are wrapped to the table's width × 3.5k/that height (stop 52/53: the en
    Table 1's title, wrapped for the ruled table, overhung the enlarged one by 3 mm)."""
    from graphplan.drawing.tables import LETTERING, TITLE_MM, title_lines
    from graphplan.graphic.record import line_pitch
    titles = [p for p in rec.items if p.kind == "text" and p.size == 3.5 and p.points[0][1] > 0.0]
    if k == 1.0 or not titles or not rec.title:
        return rec
    snap = min(LETTERING, key=lambda h: abs(h - 3.5 * k))
    width = max(x for p in rec.items if p.kind == "segment" for x, _ in p.points)
    lines = title_lines(rec.title, max(width, TITLE_MM) * 3.5 * k / snap)
    kept = [p for p in rec.items if not any(p is t for t in titles)]
    out = Record(rec.title, kept, dict(rec.scales))
    for i, line in enumerate(lines):
        out.label((0.0, 2.2 + line_pitch(3.5) * (len(lines) - 1 - i)), line, size=3.5, layer="tables")
    return out


def _column(tables: list[Leaf], lines: list[str], k) -> tuple[list[Leaf], float]:
    """The tables drawn ``k`` times their ruled size (``TABLES``: as the other sheets draw theirs,
    3.5 mm letters and 8.4 mm rows; ``(TABLES, TIGHT)``: the letters so in 7-mm rows, ``tight``) and
    the notes under them, wrapped to the column's width (the title block's or the widest table's):
    (the leaves, the width)."""
    grown = [Leaf(t.name, record=_sized(t.record, k)) for t in tables]
    width = max([TITLE] + [t.record.bounds()[2] - t.record.bounds()[0] for t in grown])
    return grown + [Leaf("notes", record=note_block(lines, width))], width


def _composed(drawings: list[Leaf], tables: list[Leaf], parts: list[list[str]], f: Form, k) -> list[list[Placed]] | None:
    """The A1 sheet in zones (``zones``) with its tables at size ``k``, the notes in one of two places: all in
    the column under the tables (as before stop 61), or — where the λ diagrams stand in the row under the
    meshing beside the planetary pictures — the pair's part (its task data and notes) under the λ diagrams it
    follows, wrapped to their width, the train's part (its data, notes and the marks' legends) at the column's
    foot under Table 3. Of the two the one whose largest blank (``blank``) is smaller, the column's on a tie.
    Stop 61: the λ diagrams (λ from −3 to 1, four units no taller than 0,75·N1N2) are shorter than the planetary
    pictures beside them, and the row left a 300 × 120-mm blank under them (GEARS57; GEARS59 245 × 143) while
    the column ran down to the title block; a teacher reads the pair's drawings, then what the pair's notes say
    of them, then the train's, the tables in their column."""
    side, width = _column(tables, [x for part in parts for x in part], k)
    tried = [zones(drawings, side, f, width)]
    data, own = parts[0], parts[1:]
    lam = next((d for d in drawings if d.name == "sliding"), None)
    if lam is not None and len(data) == 2 and len(own) == 2:       # a pair and a train
        side, width = _column(tables, [data[1]] + own[1], k)
        side[-1] = Leaf("train notes", record=side[-1].record)
        under = Leaf("notes", record=note_block([data[0]] + own[0], lam.w))
        tried.append(zones(drawings, side, f, width, under))
    tried = [t for t in tried if t is not None]
    return min(tried, key=lambda t: blank(t[0], f)) if tried else None


def blank(placed: list[Placed], f: Form) -> float:
    """The largest blank rectangle (mm²) one sheet's ``placed`` leave in its field off the title block
    (``kinlayout._empty_rect``: on a 5-mm grid, a blank counted where both its sides reach 50 mm)."""
    from graphplan.sheets.kinlayout import _empty_rect
    return _empty_rect(field_of(f), [keep_out(f)] + [p.record.bounds() for p in placed])


SLIDING_H = 125.0        # the λ diagrams' height with their caption, mm (λ from −3 to 1 at 20 mm, labels)


def zones(drawings: list[Leaf], side: list[Leaf], f: Form, width: float, under: Leaf | None = None
          ) -> list[list[Placed]] | None:
    """One sheet in zones (LAYOUT.md): the meshing on top (the largest drawing), under it the λ
    diagrams beside the planetary pictures, the tables and the notes in the title block's column on
    the right, above the block (the column's last part, its notes, on the block). ``under``: notes
    that stand under the λ diagrams in the row, at their left (``_composed``) — None where the λ
    diagrams stand beside the meshing. None when the field cannot hold them (the caller flows them
    over a set)."""
    x0, y0, x1, y1 = field_of(f)
    keep = keep_out(f)
    right = max(width, x1 - keep[0])
    tall = sum(t.h for t in side)
    apart = (len(side) - 1) or 1
    # the column's parts GAP apart, closer (to COLUMN_GAP) where that keeps its tables' size: stop 57's x_min
    # note took one line more and GEARS51's English column needed 513 mm for 512, its tables fell to 2,5 mm
    gap = max(COLUMN_GAP, min(GAP, (y1 - keep[3] - GAP - tall) / apart))
    need = tall + gap * (len(side) - 1)
    if need > y1 - keep[3] - GAP + 1e-9:
        return None
    room = drawings_room(f, width)
    mesh_w = sum(d.w for d in drawings if d.name == "meshing")
    up = ("meshing", "sliding") if any(d.name == "sliding" and mesh_w + GAP + d.w <= room for d in drawings) \
        else ("meshing",)                 # the λ diagrams beside the meshing where the two fit across
    top = [d for d in drawings if d.name in up]
    row = [d for d in drawings if d.name not in up]
    if under is not None:
        lam = next((d for d in row if d.name == "sliding"), None)
        if lam is None:
            return None
        row = [Leaf(d.name, max(d.w, under.w), d.h + GAP + under.h, d.record) if d is lam else d for d in row]
    row_w = sum(d.w for d in row) + GAP * max(len(row) - 1, 0)
    row_h = max((d.h for d in row), default=0.0)
    top_h = max((d.h for d in top), default=0.0)
    top_w = sum(d.w for d in top) + GAP * max(len(top) - 1, 0)
    if row_w > room or top_w > room or top_h + row_h + (GAP if top and row else 0.0) > y1 - y0:
        return None
    out: list[Placed] = []
    spare_y = (y1 - y0 - top_h - row_h - (GAP if top and row else 0.0)) / (1 + len([z for z in (top, row) if z]))
    y = y1 - spare_y
    if top:
        spare_x = (room - top_w) / (len(top) + 1)
        x = x0 + spare_x
        for d in top:
            box = (x, y - top_h, x + d.w, y)
            out.append(Placed(d.name, centred(d.record, box), box))
            x = box[2] + spare_x + GAP
        y = y - top_h - GAP - spare_y
    if row:
        spare_x = (room - row_w) / (len(row) + 1)
        x = x0 + spare_x
        for d in row:
            box = (x, y - row_h, x + d.w, y)
            rec = centred(d.record, box)
            if d.name == "sliding":       # the λ diagrams, shorter than the planetary pictures, at the row's
                rec = rec.moved(0.0, box[3] - rec.bounds()[3])   # top under the meshing they are read off
                if under is not None:     # (stop 46: centred, they left a hole over them), the notes under them
                    b = rec.bounds()
                    rec = rec.moved(box[0] - b[0], 0.0)
                    nb = (box[0], box[1], box[2], b[1] - GAP)
                    out.append(Placed(under.name, top_left_of(under.record, nb), nb))
                    box = (box[0], b[1], box[2], box[3])
            out.append(Placed(d.name, rec, box))
            x = box[2] + spare_x + GAP
    y = y1
    tabs = [t for t in side if t.name not in ("notes", "train notes")]
    spare = (y1 - keep[3] - GAP - need) / max(len(tabs), 1)      # the column's spare height between its parts
    for t in side:
        if t.name in ("notes", "train notes"):                     # the notes stand on the title block
            y = keep[3] + GAP + t.h
        box = (x1 - right, y - t.h, x1, y)
        out.append(Placed(t.name, top_left_of(t.record, box), box))
        y = box[1] - gap - (spare if t is not tabs[-1] else 0.0)
    return [out]


COLUMN_GAP = 4.0         # the least gap between the column's tables and notes, mm (``zones``; GAP where it fits)


def top_left_of(rec: Record, box) -> Record:
    """The record with its top-left corner at the box's."""
    b = rec.bounds()
    return rec.moved(box[0] - b[0], box[3] - b[3])
