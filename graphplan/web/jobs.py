"""The work behind the routes, run in a worker process (web/pool.py): each job takes plain data (the
scene's text, the options as strings) and a folder of its own the server made, and returns
``Answer`` — the bytes to send, or the one line the command line would print for the same input.

The computation is graphplan's own: the scene read as ``graphplan sheet``/``view``/``check`` read it
(model.scene, model.cam), the sheets' builders, the explorer, teach.grading. File names here are
fixed ("scene.toml", "student.csv"), never the client's; error lines lose the job's folder so they
read as the command line's for a file of that name."""
from __future__ import annotations

import inspect
import io
import math
import zipfile
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from graphplan.util.errors import GraphplanError, keyed_error, said_error
from graphplan.util.words import word

SCENE = "scene.toml"
KINDS = ("kinematics", "forces", "dynamics", "cam", "gears")
TYPES = {"svg": "image/svg+xml", "pdf": "application/pdf", "png": "image/png", "dxf": "image/vnd.dxf"}
FIXED_DATE = (1980, 1, 1, 0, 0, 0)          # zip entries' date: the same input, the same bytes


@dataclass
class Answer:
    """What a job hands back: ``status`` 200 with ``body`` of ``media``, or an error ``line``."""
    status: int = 200
    body: bytes = b""
    media: str = "application/octet-stream"
    headers: dict[str, str] = field(default_factory=dict)
    line: str = ""


def refused(exc: GraphplanError, folder: Path | None, lang: str | None = None) -> Answer:
    """The command line's one line for ``exc`` (in the request's language, else the scene's, as
    `--lang` and the scene's ``lang`` choose on the command line), without the job's folder."""
    from graphplan.util.words import pick
    text = exc.line(pick(lang, exc.lang))
    if folder is not None:
        text = text.replace(f"{folder}/", "").replace(str(folder), ".")
    return Answer(422, line=text)


def zipped(files: list[tuple[str, bytes]]) -> bytes:
    """A zip of (name, bytes), every entry dated FIXED_DATE (deterministic)."""
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w", zipfile.ZIP_DEFLATED) as z:
        for name, data in files:
            info = zipfile.ZipInfo(name, FIXED_DATE)
            info.compress_type = zipfile.ZIP_DEFLATED
            info.external_attr = 0o644 << 16
            z.writestr(info, data)
    return buf.getvalue()


def file_stem(text: str, *more: str) -> str:
    """The downloads' name for the scene ``text``: its designation (else its title) in Latin letters,
    and the first six hex digits of the text's SHA-256 — the same scene, the same name, another
    variant another name (a template's designation is the same for every variant: two variants'
    sheets overwrote each other in a student's Downloads folder). ASCII only, so it travels in a
    Content-Disposition header and through every file system unchanged. ``more``: other texts the
    file is made of (a teacher's variants table beside the base scene), in the fingerprint too."""
    import hashlib
    import re
    import tomllib
    from graphplan.util.romanize import romanize
    # the top-level keys come before the first [table]: only that head is read (the server calls this
    # in its own process, where a megabyte of TOML would hold every other request)
    head = re.split(r"^[ \t]*\[", text[:65536], maxsplit=1, flags=re.M)[0]
    try:
        tree = tomllib.loads(head)
    except Exception:                          # noqa: BLE001 — a scene that does not read is named "scene"
        tree = {}
    name = next((v for k in ("designation", "designation_en", "title_en", "title")
                 if isinstance(v := tree.get(k), str) and v.strip()), "scene")
    slug = re.sub(r"[^A-Za-z0-9.]+", "-", romanize(name)).strip("-.")[:48].strip("-.") or "scene"
    digest = hashlib.sha256(text.encode("utf-8", "surrogatepass"))
    for part in more:
        digest.update(b"\0" + part.encode("utf-8", "surrogatepass"))
    return f"{slug}-{digest.hexdigest()[:6]}"


def _tree(text: str) -> dict[str, Any]:
    from graphplan.model import bounds as B
    return B.parse_toml(text, SCENE)


def _lang(asked: str | None, tree: Any) -> str:
    """--lang, else the scene's ``lang``, else Ukrainian (cli.common.lang_of)."""
    from graphplan.util.words import pick
    said = tree.get("lang") if isinstance(tree, dict) else None
    return pick(asked, said if said in ("uk", "en") else None)


def _cam_or_study(tree: dict[str, Any]):
    """("gears", Gears) for a [gears]/[planetary] scene, ("cam", Cam) for a [cam] scene, else
    ("lever", Study) — as `graphplan sheet` tells them (cli/sheet.py: a gear scene first)."""
    from graphplan.model.gears import is_gears
    if is_gears(tree) and "cam" not in tree:
        from graphplan.model.gears import build as build_gears
        return "gears", build_gears(tree, SCENE)
    from graphplan.model.cam import build as build_cam
    from graphplan.model.cam import is_cam
    if is_cam(tree):
        return "cam", build_cam(tree, SCENE)
    from graphplan.exact.positions import study
    from graphplan.model.scene import build
    return "lever", study(build(tree, SCENE))


def _gears_solved(gears, precision: float = 0.5, lang: str = "uk"):
    """(solution, mesh, velocities) as `graphplan gears` makes them (sheets.gears.on_sheet: the
    A1 sheet's scales and readings)."""
    from graphplan.exact.gears import solve
    from graphplan.sheets.form import form
    from graphplan.sheets.gears import on_sheet
    sol = solve(gears)
    mesh, vel, _ = on_sheet(gears, sol, form("A1"), precision, lang)
    return sol, mesh, vel


def _gears_doc(gears) -> dict[str, Any]:
    """`graphplan gears scene.toml --json`'s document."""
    from graphplan.report.gears import gears_json
    return gears_json(*_gears_solved(gears), SCENE)


# -- the jobs ------------------------------------------------------------------------------------------

def check(folder: Path, text: str, lang: str | None) -> Answer:
    """{"ok": true, "warnings": [...]} when the scene reads and assembles over the whole turn."""
    import json
    tree = _tree(text)
    kind, obj = _cam_or_study(tree)
    lang = _lang(lang, tree)
    if kind == "cam":
        from graphplan.exact.cam import solve
        sol = solve(obj)
        warnings = [w[1] if lang == "uk" else w[0] for w in sol.warnings]
        doc = {"ok": True, "kind": "cam", "warnings": warnings}
    elif kind == "gears":                     # the pair's and the train's, as gears --json says them
        g = _gears_doc(obj)
        said = "warnings_uk" if lang == "uk" else "warnings"
        doc = {"ok": True, "kind": "gears",
               "warnings": [w for part in ("pair", "planetary") if part in g for w in g[part][said]]}
    else:
        doc = {"ok": True, "kind": "lever", "warnings": list(obj.says(lang)),
               "structure": obj.structure.formula,
               "branches": _branch_keys(obj.mech, obj.structure)}
    return Answer(body=json.dumps(doc, ensure_ascii=False).encode(), media="application/json")


def _branch_keys(mech, structure) -> list[str]:
    """The groups' points whose assembly [branch] chooses (RRR, RRP, RPR have two)."""
    return [d.key for d in structure.dyads if d.kind in ("RRR", "RRP", "RPR")]


def sheet(folder: Path, text: str, kinds: list[str], fmt: str, kind_of_file: str, lang: str | None,
          dpi: float = 300) -> Answer:
    """The sheets of ``kinds`` on ``fmt`` as ``kind_of_file``: one file, or a zip of the set."""
    from graphplan.sheets.compose import SheetOptions, page_path
    from graphplan.sheets.form import form
    from graphplan.sheets.sheet import BUILDERS
    f = form(fmt)
    if kind_of_file in ("pdf", "png"):
        from graphplan.drawing.raster import require_cairo
        require_cairo()
    tree = _tree(text)
    scene_kind, obj = _cam_or_study(tree)
    lang = _lang(lang, tree)
    if not kinds:
        kinds = [scene_kind if scene_kind in ("cam", "gears") else "kinematics"]
    stem = file_stem(text)
    files: list[tuple[str, bytes]] = []
    for kind in kinds:
        build = BUILDERS.get(kind)
        if build is None:
            raise keyed_error(GraphplanError, None, f"--sheet {kind}", "op not available")
        if scene_kind == "gears" and kind != "gears":             # cli/sheet.py's lines
            raise keyed_error(GraphplanError, SCENE, f"--sheet {kind}", "op gears only", None, sheet="gears")
        if scene_kind != "gears" and kind == "gears":
            raise keyed_error(GraphplanError, SCENE, "--sheet gears", "op no gears", None, gears="[gears]", planetary="[planetary]",
                              doc="docs/gears.md")
        if scene_kind == "cam" and kind != "cam":
            raise keyed_error(GraphplanError, SCENE, f"--sheet {kind}", "op cam only", None, sheet="cam")
        if scene_kind != "cam" and kind == "cam":
            raise keyed_error(GraphplanError, SCENE, "--sheet cam", "op no cam", None, cam="[cam]", doc="docs/cams.md")
        made = build(obj, f, SheetOptions(lang=lang, sheet=kind))
        out = folder / f"{kind}-{f.name}.{kind_of_file}"
        made.write(out, False, dpi)
        for n in range(1, len(made.pages) + 1):
            p = page_path(out, n)
            files.append((f"{stem}-{p.name}", p.read_bytes()))
    if len(files) == 1:
        name, data = files[0]
        return Answer(body=data, media=TYPES[kind_of_file],
                      headers={"Content-Disposition": f'attachment; filename="{name}"'})
    what = "-".join(kinds)
    return Answer(body=zipped(files), media="application/zip",
                  headers={"Content-Disposition": f'attachment; filename="{stem}-{what}-{f.name}-{kind_of_file}.zip"'})


def view(folder: Path, text: str, lang: str | None) -> Answer:
    """The explorer page, as `graphplan view` writes it: a lever mechanism's (the plans at the A1
    sheet's scales) or a cam's (cli/view.py view_cam: the construction of `graphplan cam`)."""
    from graphplan import api
    from graphplan.report.explorer import explorer_html
    tree = _tree(text)
    kind, obj = _cam_or_study(tree)
    lang = _lang(lang, tree)
    if kind == "gears":
        raise said_error(GraphplanError, "wb explorer gears", SCENE, lang)
    if kind == "cam":
        from graphplan.exact.cam import solve
        from graphplan.report.camview import cam_html
        from graphplan.sheets.cam import construct_on
        from graphplan.sheets.form import form
        sol = solve(obj)
        page = cam_html(sol, construct_on(sol, form("A1"), None, 0.5), step=1.0, lang=lang, scene=SCENE)
    else:
        st = api.study(obj).value
        plans = api.plans(st, precision=0.5, format="A1").value
        page = explorer_html(st, precision=0.5, step=1.0, lang=lang, plans=plans)
    return Answer(body=page.encode("utf-8"), media="text/html; charset=utf-8",
                  headers={"Content-Disposition": f'attachment; filename="{file_stem(text)}-explorer.html"'})


def tables(folder: Path, text: str, lang: str | None) -> Answer:
    """The tables as CSV in a zip: the exact kinematics at the scene's positions (analyze --json's
    points, links, slides) and the plans' readings (plans --json's velocity and acceleration)."""
    import csv
    from graphplan import api
    tree = _tree(text)
    kind, obj = _cam_or_study(tree)
    files: list[tuple[str, bytes]] = []
    if kind == "cam":
        from graphplan.exact.cam import solve
        from graphplan.sheets.cam import construct_on
        from graphplan.sheets.form import form
        sol = solve(obj)
        g = api.Cam((sol, construct_on(sol, form("A1"), None, 0.5)))     # `graphplan cam`'s construction
        doc = g.to_json()
        buf = io.StringIO()
        w = csv.writer(buf, lineterminator="\n")
        w.writerow(["phi_deg", "quantity", "exact", "graphical", "error_pct"])
        unit = "deg" if doc["follower"] == "rocking" else "m"      # a rocking follower's s is its swing, °
        for p in doc["positions"]:
            for q, e in ((f"s_{unit}", "s"), (f"ds_dphi_{unit}", "ds_dphi"), ("pressure_angle_deg", "pressure_angle")):
                err = p["error_pct"].get(e)
                w.writerow([_clean(p["phi_deg"]), q, _clean(p["exact"][q]), _clean(p["graphical"][q]),
                            "" if err is None else _fixed(float(err), 2)])
        files.append(("cam.csv", buf.getvalue().encode()))
        return Answer(body=zipped(files), media="application/zip",
                      headers={"Content-Disposition": f'attachment; filename="{file_stem(text)}-tables.zip"'})
    if kind == "gears":
        files = gears_tables(_gears_doc(obj))
        return Answer(body=zipped(files), media="application/zip",
                      headers={"Content-Disposition": f'attachment; filename="{file_stem(text)}-tables.zip"'})
    st = obj
    exact = api.study(st).to_json()
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(["position", "phi_deg", "kind", "name", "quantity", "value"])
    for p in exact["positions"]:
        for group in ("points", "links", "slides"):
            for name, values in p[group].items():
                for q, v in values.items():
                    w.writerow([p["index"], p["phi_deg"], group, name, q, v])
    files.append(("analyze.csv", buf.getvalue().encode()))
    try:
        plans = api.plans(st, precision=PLANS_PRECISION).to_json()   # at the A1 sheet's scales, as `plans` prints
    except GraphplanError:                                    # more positions than a sheet holds
        plans = api.plans(st, precision=PLANS_PRECISION, format=None).to_json()
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(["position", "phi_deg", "plan", "quantity", "mm", "value", "analytic", "error_pct"])
    for p in plans["positions"]:
        for plan in ("velocity", "acceleration"):
            entries = p.get(plan, {})
            size = max((abs(float(e["analytic"])) for e in entries.values() if e.get("analytic") is not None),
                       default=0.0)
            for q, e in entries.items():
                w.writerow([p["index"], p["phi_deg"], plan, q, *plan_reading(e, PLANS_PRECISION, size)])
    files.append(("plans.csv", buf.getvalue().encode()))
    return Answer(body=zipped(files), media="application/zip",
                  headers={"Content-Disposition": f'attachment; filename="{file_stem(text)}-tables.zip"'})


PLANS_PRECISION = 0.5      # mm: the ruler of the plans the tables read (`graphplan plans`' default)


def _decimals(quantum: float) -> int:
    """Decimals that resolve a tenth of ``quantum`` (one guard digit below the reading's step), never
    fewer than none: a 0.5 mm ruler → 2 (58.25 mm), μv·0.5 mm = 0.17 m/s → 2, 21 m/s² → 0."""
    return max(0, math.ceil(-math.log10(quantum)) + 1) if quantum > 0 and math.isfinite(quantum) else 0


def _fixed(v: float, decimals: int) -> str:
    text = f"{v:.{decimals}f}"
    return "0" if float(text) == 0 else text                # no "-0.00"


def plan_reading(e: dict[str, Any], precision: float, size: float = 0.0) -> list[str]:
    """One plan entry of ``plans --json`` as plans.csv writes it: mm, value, analytic, error %, each
    to the digits the drawing gives meaning to — the length to a tenth of the ruler's step, the value
    to a tenth of the step times the plan's scale (ω, ε: of their length's reading), the exact value
    to 12 significant figures (0 below 10⁻⁹ of ``size``, the plan's largest: a dead centre's
    1,4·10⁻¹² m/s is round-off), the error to 0.01 % (the sheets' and the terminal's). mm × μ in
    floats carried noise (1.1720000000000002); these are deterministic decimal strings."""
    value = float(e["value"])
    mm = e.get("mm", e.get("from_mm"))
    if mm is not None and float(mm) > 0:
        value_text = _fixed(value, _decimals(precision * abs(value) / float(mm)))
    else:                                                   # 0 read as 0, or no length to read
        value_text = "0" if value == 0 else repr(float(f"{value:.4g}"))
    mm_text = _fixed(float(e["mm"]), _decimals(precision)) if "mm" in e else ""
    analytic = e.get("analytic")
    if analytic is None:
        analytic_text = ""
    elif abs(float(analytic)) <= 1e-9 * size:
        analytic_text = "0"
    else:
        analytic_text = repr(float(f"{float(analytic):.12g}"))
    err = e.get("error_pct")
    return [mm_text, value_text, analytic_text, "" if err is None else _fixed(float(err), 2)]


def _clean(v: Any) -> Any:
    """A float for a CSV without the noise of its arithmetic: 12 significant figures (0.018, not
    0.018000000000000002), and 0 for round-off below 10⁻¹³ (λ = 2.2·10⁻¹⁶ at the pitch point)."""
    if isinstance(v, float) and math.isfinite(v):
        return 0.0 if abs(v) < 1e-13 else float(f"{v:.12g}")
    return v


def _csv(rows: list[list[Any]]) -> bytes:
    import csv
    buf = io.StringIO()
    csv.writer(buf, lineterminator="\n").writerows([[_clean(v) for v in row] for row in rows])
    return buf.getvalue().encode()


def gears_tables(doc: dict[str, Any]) -> list[tuple[str, bytes]]:
    """`gears --json` as CSV: ``pair.csv`` (each quantity of the pair by wheel: exact, graphical, error
    %, and εα with its bound), ``sliding.csv`` (λ1, λ2 along N1N2), ``train.csv`` (the teeth, u1H and
    the angular velocities by member: exact, graphical, error %)."""
    files: list[tuple[str, bytes]] = []
    e = lambda v: "" if v is None else v        # noqa: E731
    p = doc.get("pair")
    if p is not None:
        g = p.get("graphical", {})
        rows: list[list[Any]] = [["quantity", "wheel", "exact", "graphical", "error_pct", "bound"]]
        for q in ("z", "x"):
            rows += [[q, k + 1, p[q][k], "", "", ""] for k in (0, 1)]
        for q in ("r_m", "rb_m", "rw_m", "ra_m", "rf_m", "s_m", "sa_m"):
            for k in (0, 1):
                gr = g.get(q, [None, None])[k] if q in g else None
                er = g.get("error_pct", {}).get(q[:-2], [None, None])[k]
                rows.append([q, k + 1, p[q][k], e(gr), e(er), ""])
        for q in ("module_m", "alpha_deg", "addendum", "clearance", "alpha_w_deg", "a_m", "a_w_m", "y", "delta_y",
                  "pitch_m", "base_pitch_m", "line_of_action_m"):
            rows.append([q, "", p[q], "", "", ""])
        c = p["contact_ratio"]
        rows.append(["contact_ratio", "", c["exact"], e(c["graphical"]), e(c["error_pct"]), e(c["bound"])])
        files.append(("pair.csv", _csv(rows)))
        rows = [["point", "rho1_m", "lambda1", "lambda2"]]
        rows += [[s.get("point", ""), s["rho1_m"], e(s["lambda1"]), e(s["lambda2"])] for s in p["sliding"]]
        files.append(("sliding.csv", _csv(rows)))
    t = doc.get("planetary")
    if t is not None:
        g = t.get("graphical", {})
        rows = [["quantity", "member", "exact", "graphical", "error_pct", "bound"]]
        members = ["1", "2", "3"] if t["type"] == "A" else ["1", "2", "2'", "3"]
        rows += [["z", m, z, "", "", ""] for m, z in zip(members, t["z"])]
        rows += [["planets", "", t["planets"], "", "", ""], ["module_m", "", t["module_m"], "", "", ""]]
        r = t["ratio"]
        rows.append(["u1H", "", r["exact"], e(r["graphical"]), e(r["error_pct"]), e(r["bound"])])
        if t["ratio_required"] is not None:
            rows.append(["u1H_wanted", "", t["ratio_required"], "", e(r.get("required_error_pct")), ""])
        for m, w in t["omega_rad_s"].items():
            rows.append(["omega_rad_s", m, w, e(g.get("omega_rad_s", {}).get(m)),
                         e(g.get("error_pct", {}).get(m)), ""])
        files.append(("train.csv", _csv(rows)))
    return files


def grade(folder: Path, key: bytes, student: bytes, signed: bool, lang: str | None = None) -> Answer:
    """`graphplan check KEY STUDENT.csv --json`: the key a key.json, or the zip /api/key answers."""
    import json
    from graphplan.teach.grading import grade as grade_rows
    from graphplan.teach.grading import load_keys, read_student, report_json
    if key[:4] == b"PK\x03\x04":
        key_path = _unzip_keys(key, folder / "keys")
        key_name = "keys"
    else:
        key_path = folder / "key.json"
        key_path.write_bytes(key)
        key_name = "key.json"
    student_path = folder / "student.csv"
    student_path.write_bytes(student)
    keys = load_keys(key_path)
    try:
        rows = read_student(student_path)
    except GraphplanError as exc:                 # without ?lang=: the keys' scenes' language
        from graphplan.util.errors import speaking
        langs = {k.get("scene", {}).get("lang") for k in keys.values() if isinstance(k.get("scene"), dict)}
        raise speaking(exc, langs.pop() if len(langs) == 1 else None) from None
    graded = grade_rows(keys, rows, signed=signed)
    doc = report_json(graded, key_name, "student.csv", signed)
    for row, g in zip(doc["rows"], graded):        # the note in Ukrainian too, for the Ukrainian page
        row["note_uk"] = g.note_uk
    return Answer(body=json.dumps(doc, ensure_ascii=False, indent=1).encode(), media="application/json")


MAX_KEY_FILES = 5000


def _unzip_keys(data: bytes, into: Path) -> Path:
    """A key folder's zip unpacked: only ``summary.json`` and ``<variant>/key.json`` entries whose names
    are plain (no ``..``, no absolute path, no link), the rest ignored."""
    import re
    plain = re.compile(r"^(?:[A-Za-z0-9][A-Za-z0-9._-]*/)?(?:summary\.json|key\.json)$")
    try:
        z = zipfile.ZipFile(io.BytesIO(data))
        infos = z.infolist()
    except (zipfile.BadZipFile, ValueError) as exc:
        raise said_error(GraphplanError, "wb zip", "key", None, why=str(exc)) from None
    if len(infos) > MAX_KEY_FILES:
        raise said_error(GraphplanError, "wb zip files", "key", None, n=len(infos), most=MAX_KEY_FILES)
    into.mkdir()
    total = 0
    for info in infos:
        name = info.filename
        if not plain.match(name) or ".." in name or info.is_dir():
            continue
        total += info.file_size
        if total > 64 * 1024 * 1024:
            raise said_error(GraphplanError, "wb zip size", "key", None, mb=64)
        target = into / name
        target.parent.mkdir(exist_ok=True)
        target.write_bytes(z.read(info))
    return into


# -- the preview: the mechanism at φ, both assemblies where [branch] leaves them open ---------------

PREVIEW_WIDTH = 150.0        # mm the mechanism spans over its turn in the preview
TURN = 36                    # crank angles the preview's extent is taken over


def preview(folder: Path, text: str, phi: float, lang: str | None, stack: bool = False) -> Answer:
    """image/svg+xml: the mechanism at φ; two drawings side by side (the [branch] +1 and −1 of every
    group the scene leaves open), each with its caption — one above the other with ``stack`` (a
    phone's column: side by side each got half of a 390 px screen, its letters unreadable) —, or the
    cam's profile."""
    import dataclasses
    import itertools
    import json
    from urllib.parse import quote
    tree = _tree(text)
    from graphplan.model.cam import is_cam
    from graphplan.model.gears import is_gears
    if is_gears(tree) and "cam" not in tree:
        return _gears_preview(tree, _lang(lang, tree))
    if is_cam(tree):
        return _cam_preview(tree, _lang(lang, tree))
    from graphplan.exact.positions import study
    from graphplan.model.scene import build
    from graphplan.model.structure import analyse
    mech = build(tree, SCENE)
    lang = _lang(lang, tree)
    structure = analyse(mech)
    open_keys = [k for k in _branch_keys(mech, structure) if k not in mech.branches]
    drawings, first_error, defaults = [], None, []
    for sign in ((+1, -1) if open_keys else (0,)):
        chosen = {open_keys[0]: sign} if sign else {}
        drawn, error, default = None, None, False
        for rest in itertools.islice(itertools.product((1, -1), repeat=max(len(open_keys) - 1, 0)), 8):
            branches = {**mech.branches, **chosen, **dict(zip(open_keys[1:], rest))}
            try:
                st = study(dataclasses.replace(mech, branches=branches))
            except GraphplanError as exc:
                error = error or exc
                continue
            drawn = _at(st, phi, lang)
            # the scene's default: what a sheet draws with no [branch] for the open groups (+1 each)
            default = sign > 0 and all(s > 0 for s in rest)
            break
        if drawn is None:
            first_error = first_error or error
        drawings.append((chosen, drawn, "" if drawn is not None else refused(error, folder, lang).line))
        defaults.append(default)
    if all(d[1] is None for d in drawings):
        raise first_error                                    # type: ignore[misc]
    svg = _side_by_side(drawings, lang, defaults, stack)
    headers = {"X-Scene-Kind": "lever", "X-Sheet-Kinds": ",".join(sheet_kinds(mech)),
               "X-Branch-Keys": quote(json.dumps(open_keys, ensure_ascii=False)),
               "X-Assemblies": quote(json.dumps([{"branch": c, "error": e, "default": f}
                                                 for (c, _, e), f in zip(drawings, defaults)],
                                                ensure_ascii=False))}
    return Answer(body=svg.encode("utf-8"), media="image/svg+xml", headers=headers)


def sheet_kinds(mech) -> list[str]:
    """The sheets a lever mechanism's scene makes, in the project's order (sheets.sheet.kinds_of): the
    kinematics, the forces where it loads a link, the dynamics where it has a [dynamics] table — what
    the page offers to download (the preview's X-Sheet-Kinds)."""
    from types import SimpleNamespace

    from graphplan.sheets.sheet import kinds_of
    return list(kinds_of(SimpleNamespace(mech=mech), "kinematics"))


def _at(st, phi: float, lang: str):
    """The record of the mechanism at φ: the frame, the crank pin's circle, the joints' paths over the
    turn (thin), the links thick, the letters — the position plan's own drawing of one position."""
    import numpy as np

    from graphplan.drawing.labels import LabelRequest, place_labels
    from graphplan.drawing.plans import draw_frame, draw_links, joints_at, catmull_rom
    from graphplan.graphic.plans import Scheme
    from graphplan.graphic.position_plan import construct_position, where
    from graphplan.graphic.record import Record
    from graphplan.util.markup import indexed
    if not math.isfinite(phi):
        raise keyed_error(GraphplanError, None, "--phi", "op angle", lang, got=phi)
    sc = Scheme(st)
    angles = [float(a) for a in np.arange(TURN) * 360.0 / TURN]
    probe = [construct_position(sc, a, 1.0) for a in angles]
    pts = [p for lay in probe for p in joints_at(sc, lay).values()]
    span = max(max(p.real for p in pts) - min(p.real for p in pts),
               max(p.imag for p in pts) - min(p.imag for p in pts), 1e-9)
    mu = span / PREVIEW_WIDTH
    every = [construct_position(sc, a, mu) for a in angles]
    lay = construct_position(sc, float(phi) % 360.0, mu)
    rec = Record(title="mechanism")
    draw_frame(rec, sc, every + [lay])
    moving = [n for n in st.mech.point_names() if not sc.fixed(n)]
    for name in moving:
        path = [where(sc, l, sc.body_of(name), name) for l in every]
        if max(abs(p - path[0]) for p in path) > 1.0:
            rec.add("polyline", [(c.real, c.imag) for c in catmull_rom(path)], role="trajectory",
                    layer="construction")
    draw_links(rec, sc, lay, thick=True)
    here = joints_at(sc, lay)
    centre = sum(here.values(), 0j) / len(here)
    labels = [LabelRequest(X, indexed(n), toward=X - centre if abs(X - centre) > 1e-9 else 1j, size=3.5)
              for n, X in here.items()]
    # the drawing's extent fixed over the turn: an invisible frame of every position's joints
    allp = [p for l in every for p in joints_at(sc, l).values()]
    x0, x1 = min(p.real for p in allp) - 12, max(p.real for p in allp) + 12
    y0, y1 = min(p.imag for p in allp) - 12, max(p.imag for p in allp) + 12
    place_labels(rec, labels)
    return rec, (x0, y0, x1, y1)


def _side_by_side(drawings, lang: str, defaults=(), stack: bool = False) -> str:
    """One SVG: the drawings in equal cells left to right (top to bottom with ``stack``), each
    captioned with its [branch] values, the scene's default (the one a sheet draws when [branch]
    leaves the group open) said so."""
    from graphplan.drawing.svg import render
    from graphplan.util.markup import plain
    from xml.sax.saxutils import escape
    cells = []
    boxes = [d[1][1] for d in drawings if d[1] is not None]
    w = max(b[2] - b[0] for b in boxes)
    h = max(b[3] - b[1] for b in boxes)
    cap = max(9.0, w / 30)
    for k, (chosen, drawn, error) in enumerate(drawings):
        x, y = (0.0, k * (h + cap + 10)) if stack else (k * (w + 10), 0.0)
        said = ", ".join(f"{plain(n)} = {'+1' if v > 0 else '−1'}" for n, v in chosen.items())
        default = k < len(defaults) and defaults[k]
        caption = (f"{word('wb assembly', lang)} {k + 1}: [branch] {said}"
                   + (f" ({word('wb default', lang)})" if default else "")) if said else ""
        parts = [f'<g class="assembly" transform="translate({x:.3f},{y:.3f})">',
                 f'<rect x="0" y="0" width="{w:.3f}" height="{h + cap:.3f}" fill="#fff" stroke="#bbb" '
                 'stroke-width="0.3"/>']
        if caption:
            parts.append(f'<text x="4" y="{cap * 0.7:.3f}" font-size="{cap * 0.5:.3f}" '
                         f'font-family="sans-serif">{escape(caption)}</text>')
        if drawn is not None:
            rec, (x0, y0, x1, y1) = drawn
            moved = rec.moved(-x0, -y0)
            inner = render(moved, x1 - x0, y1 - y0, "", embed_font=False)
            import re
            head, _, body = inner.partition(">")
            head = re.sub(r'(width|height)="([0-9.]+)mm"', r'\1="\2"', head)
            inner = head.replace("<svg ", f'<svg x="0" y="{cap:.3f}" ', 1) + ">" + body
            parts.append(inner)
        else:
            # already in the reader's language (refused); without the server's name for the scene
            # ("scene.toml: …"): the box is the assembly's own, and a student's file has a name of its own
            lines = _wrap(error.removeprefix(f"{SCENE}: "), 60)
            size = max(4.0, w / 60)
            for j, line in enumerate(lines):
                parts.append(f'<text x="4" y="{cap + 2 * size + 1.5 * size * j:.3f}" font-size="{size:.3f}" fill="#a00" '
                             f'font-family="sans-serif">{escape(line)}</text>')
        parts.append("</g>")
        cells.append("".join(parts))
    if stack:
        total_w, total_h = w, len(drawings) * (h + cap + 10) - 10
    else:
        total_w, total_h = len(drawings) * (w + 10) - 10, h + cap
    return (f'<svg xmlns="http://www.w3.org/2000/svg" version="1.1" viewBox="0 0 {total_w:.3f} {total_h:.3f}" '
            f'width="{total_w:.3f}mm" height="{total_h:.3f}mm">' + "".join(cells) + "</svg>")


def _wrap(text: str, width: int) -> list[str]:
    import textwrap
    return textwrap.wrap(text, width) or [""]


def _cam_preview(tree: dict[str, Any], lang: str) -> Answer:
    from graphplan.api import _page
    from graphplan.drawing.cam import profile_drawing
    from graphplan.exact.cam import solve
    from graphplan.graphic.cam import construct
    from graphplan.model.cam import build as build_cam
    sol = solve(build_cam(tree, SCENE))
    svg = _page(profile_drawing(sol, construct(sol, None, 0.5), lang))
    return Answer(body=svg.encode("utf-8"), media="image/svg+xml",
                  headers={"X-Branch-Keys": "%5B%5D", "X-Scene-Kind": "cam", "X-Sheet-Kinds": "cam"})


def _gears_preview(tree: dict[str, Any], lang: str) -> Answer:
    """The meshing and the planetary train's pictures side by side, as `graphplan gears --svg` draws
    them (graphic.gears; the page scales the drawing down)."""
    from graphplan.drawing.svg import page_for, render
    from graphplan.graphic.record import Record
    from graphplan.model.gears import build as build_gears
    gears = build_gears(tree, SCENE)
    _, mesh, vel = _gears_solved(gears, 0.5, lang)
    parts = [c.record for c in (mesh, vel) if c is not None]
    both = Record(title=gears.title_in(lang))
    right = None
    for rec in parts:
        x0, y0, x1, _ = rec.bounds()
        moved = rec if right is None else rec.moved(right + 20.0 - x0, both.bounds()[1] - y0)
        both.extend(moved)
        right = moved.bounds()[2]
    page, w, h = page_for(both)
    svg = render(page, w, h, both.title, embed_font=False)
    return Answer(body=svg.encode("utf-8"), media="image/svg+xml",
                  headers={"X-Branch-Keys": "%5B%5D", "X-Scene-Kind": "gears", "X-Sheet-Kinds": "gears"})


JOBS = {"check": check, "sheet": sheet, "view": view, "tables": tables, "grade": grade, "preview": preview}


def run(name: str, folder: str, *args: Any) -> Answer:
    """Run job ``name`` in ``folder`` (made here, emptied by the caller): an Answer, never a raise."""
    where = Path(folder)
    where.mkdir(parents=True, exist_ok=True)
    job = JOBS[name]
    from graphplan.util.words import pick
    asked = dict(zip(list(inspect.signature(job).parameters)[1:], args)).get("lang")
    try:
        return job(where, *args)
    except GraphplanError as exc:
        return refused(exc, where, asked)
    except RecursionError:
        return Answer(422, line=f"{SCENE}: {word('wb nested', pick(asked))}")
    except MemoryError:
        return Answer(422, line=word("wb memory", pick(asked), gb=4))
    except Exception as exc:   # an internal error is one line too (as the command line says it)
        text = " ".join(str(exc).split())[:300].replace(f"{where}/", "")
        return Answer(500, line=word("wb internal", pick(asked), name=type(exc).__name__, text=text))
