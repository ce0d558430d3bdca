"""The interactive explorer: one offline HTML page with the mechanism moving, its plans at every
angle, each construction replayed step by step, and the s–v–a diagrams.

Python computes everything the page shows and writes it into the page as one JSON object; the
page's small hand-written script only draws it (inline SVG) — there is no second solver in it:

* the exact solution on a fine grid of crank angles (every ``step`` degrees plus the lab's
  positions): points' positions, velocities and accelerations, links' ω and ε, the slides, and the
  crossing angle of each group's direction lines (where it is small the plans are ill-conditioned);
* the graphical plans at the lab's positions (graphic.plans.build_plans): every velocity plan and
  the acceleration plans the scene asks for, as their construction records, each primitive with a
  caption of the draftsman's step ("v_A ⊥ O1A", "line ⊥ CB through b", "c at the intersection",
  the Coriolis component …) in Ukrainian and English, and the values read off them;
* the s–v–a diagrams by chords (graphic.diagrams.chord_diagrams) beside the exact curves;
* the warnings: extreme (dead-centre) positions, plan warnings, small crossing angles.

No network request of any kind: script, style and data are inline; the only URIs are the SVG and
XHTML namespaces. The bytes depend only on the scene and the options (deterministic).
"""
from __future__ import annotations

import html
import json
import math
from importlib import resources
from typing import Any

import numpy as np

from graphplan.report.replay import mm, plan_records, same_point
from graphplan.exact.positions import Study
from graphplan.graphic.plan import SMALL_ANGLE_DEG
from graphplan.graphic.plans import Plans, build_plans
from graphplan.model.mechanism import FRAME
from graphplan.util.errors import GraphplanError
from graphplan.util.markup import indexed
from graphplan.util.words import LANGS
from graphplan.util.romanize import scene_title

DIGITS = 9          # significant digits kept of every exact value (the page shows 4)

# -- numbers -------------------------------------------------------------------------------------


def sig(x: float, digits: int = DIGITS) -> float:
    """``x`` rounded to ``digits`` significant digits (0 for round-off below 1e-12)."""
    x = float(x)
    if not math.isfinite(x):
        raise GraphplanError(f"the explorer got a non-finite value {x!r}")
    return 0.0 if abs(x) < 1e-12 else float(f"{x:.{digits}g}")


def column(values, digits: int = DIGITS, floor: float = 0.0) -> list[float]:
    """The values rounded; those below ``floor`` (round-off of a vanishing quantity) become 0."""
    return [0.0 if abs(v) <= floor else sig(v, digits) for v in np.asarray(values, dtype=float)]


ROUND_OFF = 1e-10   # of the largest value of its kind, as `graphplan analyze` zeroes round-off



# -- the crank-angle grid --------------------------------------------------------------------------


def angle_grid(step: float, lab: list[float], phi0: float = 0.0, sense: float = 1.0) -> np.ndarray:
    """Crank angles φ (deg, [0, 360)) every ``step`` degrees of the crank's turn from position 0
    (φ0, turning in its own ``sense``: the slider's and the diagrams' convention), with the lab's
    positions, ascending in φ."""
    if not (math.isfinite(step) and 0.05 <= step <= 30.0):
        raise GraphplanError(f"--step must be from 0.05 to 30 degrees, got {step!r}")
    n = int(round(360.0 / step))
    fine = np.mod(phi0 + math.copysign(1.0, sense) * np.arange(n) * (360.0 / n), 360.0)
    every = np.concatenate([fine, np.mod(np.asarray(lab, dtype=float), 360.0)])
    every = np.round(np.sort(every), 9) % 360.0
    every = np.sort(every)
    keep = np.concatenate([[True], np.diff(every) > 1e-6])
    return every[keep]


def coincident_motion(kin, body: str, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """v and a of ``body``'s point that is at ``x`` now: v_O + ω×r, a_O + ε×r − ω²r (r = x − O)."""
    return kin.bodies[body].coincident(x)


def grid_data(st: Study, plans: Plans, phi: np.ndarray) -> dict[str, Any]:
    """The exact solution on the grid: points (m, m/s, m/s²), links, slides, crossing angles."""
    mech = st.mech
    kin = st.solve(phi)
    motion: dict[str, tuple[np.ndarray, np.ndarray, np.ndarray]] = {}
    for name in mech.point_names():
        if name not in mech.frame:
            motion[name] = kin.point(name)
    for (point, body), name in sorted(plans.scheme.coincident.items(), key=lambda kv: kv[1]):
        if body != FRAME and name not in motion:
            x = kin.point(point)[0]
            motion[name] = (x, *coincident_motion(kin, body, x))
    fx, fv, fa = (ROUND_OFF * max(float(np.max(np.abs(m[k]))) for m in motion.values()) for k in range(3))
    points = {name: {"x": column(x.real, floor=fx), "y": column(x.imag, floor=fx),
                     "vx": column(v.real, floor=fv), "vy": column(v.imag, floor=fv),
                     "ax": column(a.real, floor=fa), "ay": column(a.imag, floor=fa)}
              for name, (x, v, a) in motion.items()}
    bodies = [kin.bodies[name] for name in mech.links]
    fw = ROUND_OFF * max(float(np.max(np.abs(b.omega))) for b in bodies)
    fe = ROUND_OFF * max(float(np.max(np.abs(b.eps))) for b in bodies)
    links = {name: {"theta": column(np.degrees(kin.bodies[name].theta), 7),
                    "omega": column(kin.bodies[name].omega, floor=fw),
                    "epsilon": column(kin.bodies[name].eps, floor=fe)} for name in mech.links}
    slides = {key: {"point": s.point, "fixed": s.carrier == FRAME,
                    "s": column(s.t - st.t0[key], floor=fx), "v": column(s.v, floor=fv),
                    "a": column(s.a, floor=fa), "k": column(s.coriolis_magnitude, floor=fa)}
              for key, s in kin.slides.items()}
    slots = slot_lines(st, plans, kin)
    crossing = {label: [round(math.degrees(math.asin(min(1.0, abs(float(c))))), 1) for c in cond]
                for label, cond in kin.condition.items()}
    return {"phi": [round(float(p), 6) for p in phi], "points": points, "links": links,
            "slides": slides, "crossing": crossing, "slots": slots}


def slot_lines(st: Study, plans: Plans, kin) -> dict[str, list[list[list[float]]]]:
    """Each slotted link (a coulisse) drawn at every angle of the grid as the sheets draw it
    (model.linkshape.slot_line: along its guide, through its own points and its blocks, 4 mm
    beyond): per carrier, per block sliding in it, per angle [x0, y0, x1, y1] in drawing mm."""
    from graphplan.model.linkshape import extra_points, slot_line
    mech, k = st.mech, 1.0 / plans.mu_l
    out: dict[str, list[list[list[float]]]] = {}
    for slider, link in mech.links.items():
        if link.slides_on is None or mech.guides[link.slides_on].body == FRAME:
            continue
        g = mech.guides[link.slides_on]
        carrier = mech.links[g.body]
        body = kin.bodies[g.body]
        own = [body.at(carrier.local[p])[0] * k for p in list(carrier.joints) + extra_points(carrier)]
        blocks = [kin.bodies[slider].at(z)[0] * k for z in link.local.values()]
        a, b = slot_line(body.at(g.through)[0] * k, body.turn * np.exp(1j * g.angle), own, blocks)
        out.setdefault(g.body, []).append([[mm(p.real), mm(p.imag), mm(q.real), mm(q.imag)] for p, q in zip(a, b)])
    return out


# -- the mechanism's scheme for the drawing --------------------------------------------------------


def scheme_data(st: Study, plans: Plans) -> dict[str, Any]:
    """What the page needs to draw the mechanism: frame points, links (bars, blocks, slotted
    links), guides on the frame, the trajectories worth drawing. Each link's ``outline`` is the
    sheets' own (model.linkshape: the bar to its outermost point, a plate round a point off its
    joints' line) as the names of the points it runs through, taken at position 0 (a rigid motion
    keeps it), and ``points`` its named points beyond the joints (D, E), drawn and lettered."""
    from graphplan.model.linkshape import extra_points, outline_names
    from graphplan.drawing.plans import joints_at
    mech = st.mech
    at0 = joints_at(plans.scheme, plans.positions[0].layout)
    carriers: dict[str, list[str]] = {}
    for name, link in mech.links.items():
        if link.slides_on is not None:
            carriers.setdefault(mech.guides[link.slides_on].body, []).append(next(iter(link.local)))
    links = []
    for name, link in mech.links.items():
        links.append({"name": name, "number": link.number, "joints": list(link.joints),
                      "block": next(iter(link.local)) if link.slides_on is not None and len(link.joints) <= 1 else None,
                      "slot": carriers.get(name, []) if name != FRAME else [],
                      "outline": outline_names(link, at0) if len(link.joints) >= 2 else coulisse_outline(link, at0),
                      "points": [p for p in extra_points(link) if p in at0 and p not in mech.frame]})
    guides = [{"point": next(iter(mech.links[s].local)),
               "angle": math.degrees(g.angle),
               "through": [mm(g.through.real / plans.mu_l), mm(g.through.imag / plans.mu_l)]}
              for s, link in mech.links.items() if link.slides_on is not None
              for g in [mech.guides[link.slides_on]] if g.body == FRAME]
    pivots = sorted({j for link in mech.links.values() for j in link.joints if j in mech.frame})
    frame = {name: [mm(z.real / plans.mu_l), mm(z.imag / plans.mu_l)] for name, z in mech.frame.items()}
    out = st.output
    from graphplan.drawing.plans import output_point as marked
    output_point = marked(plans)        # the sheets' own: a slotted lever O3E's end E, not its name
    paths = list(dict.fromkeys([mech.crank.pin, output_point] + list(plans.trajectories)))
    return {"frame": frame, "pivots": pivots, "links": links, "guides": guides,
            "crank": {"link": mech.crank.link, "pivot": mech.crank.pivot, "pin": mech.crank.pin},
            "trajectories": paths, "output": {"kind": out.kind, "name": out.name, "point": output_point}}


def coulisse_outline(link, at0: dict[str, complex]) -> list[str]:
    """A link pivoted at its only joint (a coulisse O2 … B): its points' outline through the joint and
    its own points (["O2", "B"]), for its similar figure on the plans (the mechanism draws it along
    its guide); none for a block."""
    from graphplan.model.linkshape import extra_points, outline_order
    names = list(link.joints) + [p for p in extra_points(link) if p in at0]
    if link.slides_on is not None or len(names) < 2:
        return []
    return [names[k] for k in outline_order([at0[n] for n in names[:2]], [at0[n] for n in names[2:]])]


# -- the values' table -----------------------------------------------------------------------------


def table_rows(st: Study, plans: Plans, grid: dict[str, Any]) -> list[dict[str, Any]]:
    """The rows of the values' table: |v| and |a| of every moving point, ω and ε of the turning
    links, the slides' relative velocity and the Coriolis acceleration. ``q`` names the row."""
    mech = st.mech
    rows: list[dict[str, Any]] = []
    pts = [p for p in grid["points"]]
    # every turning link but the crank and the blocks (a block turns with its coulisse: ω2 = ω3) — a
    # coulisse pivoted at its only joint included (its ω3 is the lab's very question)
    rot = [n for n in mech.links if n != mech.crank.link and plans.scheme.rotating.get(n)
           and (len(mech.links[n].joints) >= 2 or mech.links[n].slides_on is None)]
    for p in pts:
        rows.append({"q": f"v_{p}", "plan": "velocity", "source": "point", "name": p, "unit": "m/s", "entry": p})
    for n in rot:
        rows.append({"q": f"omega_{n}", "plan": "velocity", "source": "omega", "name": n, "unit": "rad/s",
                     "entry": f"omega_{n}"})
    for key, s in sorted(grid["slides"].items()):
        if s["fixed"] and s["point"] in pts:
            continue        # a slider on the frame's guide: its velocity is the point's own row (v_D twice)
        rows.append({"q": f"vrel_{key}", "plan": "velocity", "source": "slide_v", "name": key, "unit": "m/s",
                     "entry": s["point"] if s["fixed"] else None, "point": s["point"]})
    for p in pts:
        rows.append({"q": f"a_{p}", "plan": "acceleration", "source": "point", "name": p, "unit": "m/s²", "entry": p})
    for n in rot:
        rows.append({"q": f"epsilon_{n}", "plan": "acceleration", "source": "epsilon", "name": n,
                     "unit": "rad/s²", "entry": f"epsilon_{n}"})
    for key, s in sorted(grid["slides"].items()):
        if max(s["k"]) > 0:
            rows.append({"q": f"k_{key}", "plan": "acceleration", "source": "slide_k", "name": key,
                         "unit": "m/s²", "entry": None, "point": s["point"]})
    # each row written as the sheets' tables write it (report.plans.symbol): ω_3, v_A3A2, a^k_A3A2
    from graphplan.report.plans import symbol
    for row in rows:
        for p in plans.positions:
            plan = p.velocity if row["plan"] == "velocity" else p.acceleration
            e = plan_entry(plan, row) if plan is not None else None
            if e is not None:
                row["symbol"] = symbol(e, plan.kind, mech)
                break
    return rows


def plan_entry(plan, row: dict[str, Any]):
    """The plan's entry a row of the values' table reads (None where the plan has none)."""
    e = plan.entries.get(row["entry"]) if row["entry"] else None
    if e is None and row["source"] in ("slide_v", "slide_k"):
        e = relative_entry(plan.entries, row["point"], "k_" if row["source"] == "slide_k" else "")
    return e


def readings(plans: Plans, rows: list[dict[str, Any]]) -> dict[str, dict[str, list]]:
    """What the plans of each lab position read, per row: [mm or null, value, error % or null];
    ω and ε signed (+ counter-clockwise) as the exact column shows them; a slide's relative
    velocity negative where the drawn vector points against the exact one (the page gives it the
    exact value's sign along the guide)."""
    out: dict[str, dict[str, list]] = {}
    for p in plans.positions:
        got: dict[str, list] = {}
        for plan in (p.velocity, p.acceleration):
            if plan is None:
                continue
            for row in rows:
                if row["plan"] != plan.kind:
                    continue
                e = plan_entry(plan, row)
                if e is None:
                    continue
                value = e.vector.real if row["source"] in ("omega", "epsilon") else e.value
                if row["source"] == "slide_v" and (e.vector * e.exact.conjugate()).real < 0:
                    value = -value      # drawn against the exact sense: the page shows the opposite sign
                got[row["q"]] = [None if e.mm is None else mm(e.mm), sig(value, 6),
                                 None if e.error_pct is None else sig(e.error_pct, 7)]
        out[str(p.key)] = got
    return out


def relative_entry(entries: dict, point: str, prefix: str = ""):
    """The plan's entry of a sliding pair's relative motion at ``point``: "A3A2" (v_A3A2), or with
    ``prefix="k_"`` its Coriolis component "k_A3A2"."""
    for key, e in entries.items():
        rest = key.removeprefix(prefix) if key.startswith(prefix) else None
        if rest and not rest.startswith("k_") and rest.startswith(point) and same_point(rest):
            return e
    return None


def check_data(plans: Plans) -> dict[str, list[list[Any]]]:
    """The self-check of each lab position: every segment a student reads off the plans (the
    points' vectors, the relative and tangential components; not the normal and Coriolis ones,
    which are laid off from computed values), as [plan, entry, symbol (util.markup), μ, exact
    magnitude, graphplan's mm, graphplan's error %]. The page computes value = mm × μ and
    δ = 100·(value − exact)/exact from the student's mm with these very numbers (full precision),
    as `graphplan plans` does from its own reading."""
    from graphplan.report.plans import ordered, symbol
    out: dict[str, list[list[Any]]] = {}
    for p in plans.positions:
        rows: list[list[Any]] = []
        for plan in (p.velocity, p.acceleration):
            if plan is None:
                continue
            floor = ROUND_OFF * max([abs(float(e.analytic)) for e in plan.entries.values()] + [0.0])
            for e in ordered(plan):
                if e.mm is None or e.kind in ("normal", "coriolis"):
                    continue
                rows.append([plan.kind, e.key, symbol(e, plan.kind, plans.study.mech), plan.mu,
                             0.0 if abs(float(e.analytic)) <= floor else float(e.analytic), float(e.mm),
                             None if e.error_pct is None else float(e.error_pct)])
        out[str(p.key)] = rows
    return out


# -- warnings, diagrams ---------------------------------------------------------------------------

def warnings_data(st: Study, plans: Plans) -> dict[str, Any]:
    """The warnings in both languages: extreme positions (angles), each lab position's plan
    warnings, the cycle's (near-locking groups)."""
    return {"extremes": [round(e, 6) for e in st.extremes],
            "plans": {str(p.key): {lang: [w.say(lang) for w in p.warnings] for lang in LANGS}
                      for p in plans.positions if p.warnings},
            "study": {lang: list(st.says(lang)) for lang in LANGS},
            "small": SMALL_ANGLE_DEG}


def diagrams_data(st: Study, precision: float, phi: np.ndarray) -> dict[str, Any] | None:
    """The s–v–a diagrams by chords (the scene's settings) and the exact curves on the grid."""
    from graphplan.graphic.diagrams import chord_diagrams, exact_motion
    from graphplan.report.diagrams import diagrams_json
    task = st.mech.task.diagram
    d = chord_diagrams(st, point=task.get("point"), divisions=task.get("divisions"),
                       L=task.get("L_mm", 240.0), H1=task.get("H1_mm", 30.0), H2=task.get("H2_mm", 30.0),
                       precision=precision)
    doc = diagrams_json(d)
    turn = st.from_position0(phi)
    s, v, a = exact_motion(st, d.output, turn)
    pick = lambda rows: [[round(r["phi_deg"], 6), sig(r["value"], 6), sig(r["analytic"], 6)] for r in rows]  # noqa: E731
    return {"symbols": list(d.symbols), "sub": d.sub, "unit": d.unit, "point": d.point,
            "L": d.L, "H1": d.H1, "H2": d.H2, "divisions": d.divisions,
            "mu": {"s": d.mu_s, "t": d.mu_t, "v": d.mu_v, "a": d.mu_a},
            "exact": {"s": column(s, 7), "v": column(v, 7), "a": column(a, 7)},
            "chords": {"s": pick(doc["s"]), "v": pick(doc["v"]), "a": pick(doc["a"])}}


# -- the page -------------------------------------------------------------------------------------

def explorer_data(st: Study, precision: float = 0.5, step: float = 1.0, lang: str = "uk",
                  plans: Plans | None = None, sheet: str | None = None) -> dict[str, Any]:
    """Everything the page shows, computed here (SI units; drawing mm where said), the words in
    both languages (``lang`` is the one the page opens in); ``sheet``: the format whose kinematics
    sheet chose the plans' scales (step 0 of each replay says so), None for the plans' own."""
    if lang not in LANGS:
        raise GraphplanError(f"--lang must be uk or en, got {lang!r}")
    plans = plans or build_plans(st, precision=precision)
    phi = angle_grid(step, [p.phi for p in plans.positions], st.phi0, st.mech.omega1)
    grid = grid_data(st, plans, phi)
    rows = table_rows(st, plans, grid)
    mech = st.mech
    meta = mech.task.meta
    scheme = scheme_data(st, plans)
    scheme["labels"] = {name: indexed(name) for name in list(grid["points"]) + list(scheme["frame"])}
    # a rocker pivoted at its only joint (a slotted link) has no moving joint: its path is its points'
    scheme["trajectories"] = [name for name in scheme["trajectories"] if name in grid["points"]]
    return {
        "title": {"uk": mech.title, "en": scene_title(meta, mech.title, "en")}, "lang": lang,
        "precision": plans.precision, "step": step,
        "omega1": mech.omega1,
        "structure": st.structure.formula,
        "scales": {"mu_l": plans.mu_l, "mu_v": plans.mu_v, "mu_a": plans.mu_a},
        "phi0": round(st.phi0, 6),
        "open": opening(st, plans),
        "positions": [{"key": p.key, "index": p.index, "phi": round(p.phi, 6),
                       "accel": p.acceleration is not None} for p in plans.positions],
        "scheme": scheme,
        "grid": grid,
        "rows": rows,
        "readings": readings(plans, rows),
        "check": check_data(plans),
        "records": plan_records(plans, sheet),
        "diagrams": diagrams_data(st, plans.precision, phi),
        "warnings": warnings_data(st, plans),
    }


def opening(st: Study, plans: Plans) -> dict[str, Any]:
    """Where the page opens: the first position with an acceleration plan (the scene's ``accel``,
    whose plans the sheet draws and reads), else position 1 when position 0 is an extreme position
    (the output stands still there: most velocities are 0 — a six-bar's dead position shows a plan
    shrunk to a point), else position 0. ``why``: "accel", "still" or "" (position 0); ``still0``:
    whether position 0 is an extreme position (the page says so)."""
    still0 = any(abs((st.phi0 - e + 180.0) % 360.0 - 180.0) < 1e-6 for e in st.extremes)
    first = plans.positions[0]
    pick, why = first, ""
    accel = [p for p in plans.positions if p.acceleration is not None]
    if accel and accel[0].key != first.key:
        pick, why = accel[0], "accel"
    elif not accel and still0 and len(plans.positions) > 1:
        pick, why = plans.positions[1], "still"
    return {"key": pick.key, "index": pick.index, "phi": round(pick.phi, 6), "why": why, "still0": still0}


def _asset(name: str) -> str:
    return resources.files("graphplan.report").joinpath("explorer_assets", name).read_text(encoding="utf-8")


def explorer_html(st: Study, precision: float = 0.5, step: float = 1.0, lang: str = "uk",
                  plans: Plans | None = None, sheet: str | None = None) -> str:
    """The explorer as one self-contained HTML page (inline style, script and data)."""
    data = explorer_data(st, precision, step, lang, plans, sheet)
    payload = json.dumps(data, ensure_ascii=False, separators=(",", ":"), allow_nan=False)
    payload = payload.replace("</", "<\\/")     # a "</script>" inside a caption cannot end the script
    page = _asset("explorer.html")
    return (page.replace("{{lang}}", lang)
                .replace("{{title}}", html.escape(data["title"][lang]))
                .replace("{{style}}", _asset("explorer.css"))
                .replace("{{data}}", payload)
                .replace("{{script}}", _asset("explorer.js")))


def explorer_iframe(st: Study, height: int = 1400, **options) -> str:
    """The explorer for a notebook's ``_repr_html_``: the page in an ``<iframe srcdoc>``, because
    JupyterLab does not run scripts written straight into an output cell. ``options`` as
    ``explorer_html``."""
    page = html.escape(explorer_html(st, **options), quote=True)
    return (f'<iframe srcdoc="{page}" style="width:100%;height:{int(height)}px;border:0;background:#fff" '
            'sandbox="allow-scripts"></iframe>')
