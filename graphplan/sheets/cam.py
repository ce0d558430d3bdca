"""The fourth sheet, «Синтез кулачкового механізму» (cam synthesis): the law's diagrams integrated by
chords, the phase diagram with the smallest base radius, the profile by inversion, the table of the
divisions (graphical beside exact, with the percent errors) and the notes — composed in zones like the
other sheets: the drawings in a row in reading order, the table and the notes beside the title block;
a format too small carries the rest to further sheets of the set."""
from __future__ import annotations

from graphplan.drawing.cam import records
from graphplan.drawing.layout import Leaf, Placed, centred, flow
from graphplan.exact.cam import solve
from graphplan.graphic.cam import construct
from graphplan.graphic.diagrams import LAB_LIMIT
from graphplan.graphic.record import Record
from graphplan.model.cam import Cam
from graphplan.report.cam import cam_json
from graphplan.sheets.compose import Sheet, SheetOptions, captioned, compose, field_of, keep_out, note_block
from graphplan.sheets.form import Form, table
from graphplan.sheets.kinematics import TITLE
from graphplan.util.errors import GraphplanError
from graphplan.util.markup import escape
from graphplan.util.words import fixed, num

WORDS = {
    "uk": {"subtitle": "Синтез кулачкового механізму", "diagrams": "Діаграми d^2s/dφ^2, ds/dφ, s (графічне "
           "інтегрування методом хорд)", "phase": "Фазова діаграма s(ds/dφ) і найменший радіус R_0",
           "profile": "Профіль кулачка (метод обернення руху)", "table": "Таблиця 1. Переміщення, аналог "
           "швидкості й кут тиску в точках поділу", "n": "№", "group": "гр."},
    "en": {"subtitle": "Cam synthesis", "diagrams": "Diagrams d^2s/dφ^2, ds/dφ, s (graphical integration by "
           "chords)", "phase": "Phase diagram s(ds/dφ) and the smallest base radius R_0",
           "profile": "Cam profile (by inversion)", "table": "Table 1. Displacement, velocity analogue and "
           "pressure angle at the divisions", "n": "No", "group": "gr."},
}


def _fields(cam: Cam, lang: str) -> dict[str, str]:
    meta = dict(cam.meta)
    org, group = meta.get("sheet.organisation", ""), meta.get("sheet.group", "")
    if group:
        org = ", ".join(x for x in (org, f"{WORDS[lang]['group']} {group}") if x)
    return {"designation": escape(meta.get("designation", "")), "title": escape(cam.title_in(lang)),
            "student": escape(meta.get("sheet.student", "")), "teacher": escape(meta.get("sheet.teacher", "")),
            "organisation": escape(org), "scale": "", "sheet": "1", "sheets": "1",
            "subtitle": WORDS[lang]["subtitle"]}


def _pct(v) -> str:
    return "—" if v is None else num(v, "uk", 3).replace("-", "−") + ("*" if abs(v) > LAB_LIMIT else "")


def positions_table(doc: dict, lang: str) -> Record:
    """Per division: φ, s and ds/dφ exact and graphical with δ, ϑ exact and measured, R exact and
    measured (mm)."""
    rocking = doc["follower"] == "rocking"
    key = "_deg" if rocking else "_m"
    k = 1.0 if rocking else 1000.0                      # a translating follower's s in mm
    unit = "°" if rocking else ("мм" if lang == "uk" else "mm")
    gr = "гр." if lang == "uk" else "gr."
    head = [WORDS[lang]["n"], "φ, °", f"s, {unit}", f"s {gr}", "δ_s, %", f"ds/dφ, {unit}", f"ds/dφ {gr}", "δ, %",
            "ϑ, °", f"ϑ {gr}", "R, " + ("мм" if lang == "uk" else "mm"), f"R {gr}"]
    rows = [head]
    mu_l = doc["scales"]["mu_l_m_mm"]
    for j, p in enumerate(doc["positions"]):
        e, g, err = p["exact"], p["graphical"], p["error_pct"]
        def v(x, d=4):
            return num(x, lang, d).replace("-", "−")
        rows.append([str(j), fixed(p["phi_deg"], lang, 1), v(e["s" + key] * k), v(g["s" + key] * k),
                     _pct(err["s"]).replace(".", "," if lang == "uk" else "."), v(e["ds_dphi" + key] * k),
                     v(g["ds_dphi" + key] * k), _pct(err["ds_dphi"]).replace(".", "," if lang == "uk" else "."),
                     fixed(e["pressure_angle_deg"], lang, 1).replace("-", "−"),
                     fixed(g["pressure_angle_deg"], lang, 1).replace("-", "−"),
                     fixed(e["radius_m"] * 1000, lang, 2), fixed(g["radius_mm"] * mu_l * 1000, lang, 1)])
    widths = [8.0, 13.0, 17.0, 17.0, 14.0, 19.0, 19.0, 14.0, 13.0, 13.0, 16.0, 15.0]
    return table(rows, widths, row_h=6.0, size=2.5, title=WORDS[lang]["table"])


def notes(doc: dict, lang: str, cam: Cam) -> list[str]:
    """The data, the base radius exact and measured, the largest pressure angles, the curvature, the
    scales and the warnings, as the terminal says them (report.cam)."""
    from graphplan.report.cam import cam_table
    text = cam_table(doc, lang, cam.title_in(lang))
    lines = text.split("\n\n")[0].splitlines()[1:]
    w = doc["warnings_uk"] if lang == "uk" else doc["warnings"]
    lines += [("Попередження: " if lang == "uk" else "Warning: ") + x for x in w]
    marked = any(v is not None and abs(v) > LAB_LIMIT for p in doc["positions"] for v in p["error_pct"].values())
    if marked:
        lines.append("* — " + ("похибка понад 5 %: коротка ордината (кілька мм) або мало поділок"
                               if lang == "uk" else "an error past 5 %: a short ordinate (a few mm) or few "
                               "divisions"))
    return [escape(x) for x in lines]


def build_cam_sheet(cam: Cam, f: Form, args: SheetOptions) -> Sheet:
    """The cam sheet: the three constructions captioned, the table and the notes, flowed over the
    sheet (and further sheets of the set when the format is small) in reading order."""
    lang = args.lang
    sol = solve(cam)
    g = construct(sol, None, args.precision)
    doc = cam_json(sol, g, cam.source or "")
    drawn = records(sol, g, lang)
    w = WORDS[lang]
    leaves = [Leaf(name, record=captioned(drawn[name], w[name])) for name in ("diagrams", "phase", "profile")]
    tab = Leaf("table", record=positions_table(doc, lang))
    width = max(TITLE, tab.record.bounds()[2] - tab.record.bounds()[0])
    nts = Leaf("notes", record=note_block(notes(doc, lang, cam), width))
    region = field_of(f)
    laid = flow([leaves, [tab, nts]], region, keep_out(f))
    if laid is None:
        raise GraphplanError(f"a cam drawing is larger than a whole {f.name} sheet; choose a larger --format")
    pages = [[Placed(leaf.name, centred(leaf.record, b), b) for leaf, b in page if leaf.record is not None]
             for page in laid]
    from graphplan.sheets.compose import drawing_scale
    tf = dict(_fields(cam, lang), scale=drawing_scale(doc["scales"]["mu_l_m_mm"], lang))   # the profile's scale
    return compose(f, pages, tf, lang, f"{cam.title_in(lang)} — {w['subtitle']}")
