"""`graphplan bench`: speed against accuracy, and stability where the methods fail.

Every row has ``section``, ``method``, ``setting``, ``x`` (the swept quantity), ``time_s`` and
``max_error_pct``; charts (matplotlib, PNG and SVG) are drawn from the rows alone.
"""
from __future__ import annotations

import functools
import math
import re
import time
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import numpy as np

from graphplan.bench import differentiation
from graphplan.bench.examples import example, examples_dir  # noqa: F401  (the sections' scenes)
from graphplan.util.errors import GraphplanError
from graphplan.exact.positions import study
from graphplan.model.scene import loads

Row = dict[str, Any]


def best_time(fn: Callable[[], Any], repeats: int = 3) -> float:
    """The best wall time of ``repeats`` calls (s)."""
    best = math.inf
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t0)
    return best


# -- the analytic solver's speed ------------------------------------------------------------------

def crank_slider_exact(phi_deg: np.ndarray, r: float, l: float, w: float) -> np.ndarray:
    """v_B = −rω·sinφ·(1 + r·cosφ/√(l² − r²·sin²φ)) (centred crank-slider)."""
    p = np.radians(phi_deg)
    return -r * w * np.sin(p) * (1 + r * np.cos(p) / np.sqrt(l ** 2 - r ** 2 * np.sin(p) ** 2))


def solver_speed(quick: bool) -> Iterator[Row]:
    """Positions per second of the analytic solver, 1 … 10^5 positions (10^4 with --quick)."""
    top = 4 if quick else 5
    cs = example("crank_slider")
    shaper = example("shaper")
    for n in [10 ** k for k in range(top + 1)]:
        phi = np.linspace(0.0, 360.0, n, endpoint=False) + 0.123
        for name, st in (("crank_slider", cs), ("shaper", shaper)):
            t = best_time(lambda st=st: st.solve(phi), 3 if n < 10 ** 5 else 1)
            error = None
            if name == "crank_slider":
                v = st.solve(phi).point("B")[1].real
                exact = crank_slider_exact(phi, 0.064, 0.307, 293.07)
                error = float(np.max(np.abs(v - exact)) / np.max(np.abs(exact)) * 100)
            yield {"section": "speed", "method": "analytic", "setting": f"{name} N={n}", "x": n,
                   "time_s": t, "positions_per_s": n / t, "max_error_pct": error}


# -- stability: sweeps toward failure -----------------------------------------------------------

def _scene_four_bar(l3: float) -> str:
    return ("[frame.points]\nO1 = [0, 0]\nO2 = [0.3, 0]\n[crank]\npivot = \"O1\"\npin = \"A\"\n"
            "length = 0.1\nrpm = 60\n[[link]]\nname = \"AB\"\njoints = [\"A\", \"B\"]\nlength = 0.35\n"
            f"[[link]]\nname = \"O2B\"\njoints = [\"O2\", \"B\"]\nlength = {l3}\n[positions]\nstart = 0\n")


def _scene_crank_slider(ratio: float) -> str:
    return ("[frame.points]\nO = [0, 0]\n[frame.guides]\nx = { through = [0, 0], angle_deg = 0 }\n"
            "[crank]\npivot = \"O\"\npin = \"A\"\nlength = 0.1\nrpm = 60\n[[link]]\nname = \"AB\"\n"
            f"joints = [\"A\", \"B\"]\nlength = {0.1 * ratio}\n[[link]]\nname = \"B\"\njoints = [\"B\"]\n"
            "slides_on = \"x\"\n[positions]\nstart = 0\n")


def _scene_slotted(ratio: float) -> str:
    """Crank 0.1 about O, the rocker pivoted at (0.1·ratio, 0): ratio → 1 brings the pivot onto the
    crank circle, where the slot's direction jumps; Q 0.4 m out, past the block's farthest reach
    (0.1·ratio + 0.1 ≤ 0.3 m: no block off the slot's end, which is warned of)."""
    return ("[frame.points]\nO = [0, 0]\nP = [" + f"{0.1 * ratio}" + ", 0]\n[crank]\npivot = \"O\"\n"
            "pin = \"A\"\nlength = 0.1\nrpm = 60\n[[link]]\nname = \"2\"\njoints = [\"A\"]\n"
            "slides_on = \"PQ\"\n[[link]]\nname = \"PQ\"\njoints = [\"P\"]\npoints = { Q = [0.4, 0] }\n"
            "[positions]\nstart = 0\n")


SWEEPS: dict[str, tuple[Callable[[float], str], str, list[float]]] = {
    "four_bar toward its toggle (O2B → 0.15 m)": (_scene_four_bar, "O2B",
                                                        [0.25, 0.2, 0.17, 0.16, 0.155, 0.152, 0.151, 0.1505, 0.15]),
    "crank_slider l/r → 1": (_scene_crank_slider, "AB", [4.0, 2.0, 1.5, 1.2, 1.1, 1.05, 1.01, 1.001, 1.0]),
    "slotted link, rocker pivot → crank circle (c/r → 1)": (
        _scene_slotted, "PQ", [2.0, 1.5, 1.2, 1.1, 1.05, 1.01, 1.001, 1.0]),
}


def stability(quick: bool) -> Iterator[Row]:
    """Sweep each mechanism toward its failure: the smallest angle between the groups' direction
    lines, the analytic velocity's agreement with finite differences of positions, and what the
    program says (ok, warning, refusal)."""
    for title, (make, link, values) in SWEEPS.items():
        for x in values:
            row: Row = {"section": "stability", "method": "analytic", "setting": title, "x": x,
                        "time_s": None, "max_error_pct": None, "min_angle_deg": None, "status": "ok"}
            t0 = time.perf_counter()
            try:
                st = study(loads(make(x), f"<{title}>"))
            except GraphplanError as exc:
                row.update(status="refused", message=exc.line())
                row["time_s"] = time.perf_counter() - t0
                yield row
                continue
            phi = np.linspace(0.0, 360.0, 721)[:-1] + 0.05
            kin = st.solve(phi)
            cond = min(float(np.min(c)) for c in kin.condition.values())
            w = kin.bodies[link].omega
            h = 1e-4
            ang = lambda p: np.unwrap(st.solve(p).bodies[link].theta)  # noqa: E731
            fd = (ang(phi + h) - ang(phi - h)) / (2 * math.radians(h)) * st.mech.omega1
            err = float(np.max(np.abs(w - fd)) / np.max(np.abs(w)) * 100)
            from graphplan.graphic.plans import build_plans
            from graphplan.report.plans import plans_json
            try:
                doc = plans_json(build_plans(st, precision=0.5))
                perr = [abs(e["error_pct"]) for p in doc["positions"] for e in p["velocity"].values()
                        if e.get("error_pct") is not None and (e.get("mm") or 0.0) >= 20.0]
                row["plans_max_error_pct"] = max(perr) if perr else None
                row["plans_warnings"] = sum(len(p["warnings"]) for p in doc["positions"])
            except GraphplanError as exc:
                row["plans_max_error_pct"], row["plans_message"] = None, exc.line()
            row.update(time_s=time.perf_counter() - t0, max_error_pct=err,
                       min_angle_deg=math.degrees(math.asin(min(cond, 1.0))),
                       max_omega=float(np.max(np.abs(w))),
                       status="warning" if st.warnings else "ok", message="; ".join(st.warnings))
            yield row


def chords(quick: bool) -> Iterator[Row]:
    """Accuracy against cost of the method of chords: the largest error of v and a (in % of the
    cycle's maximum, at the chord midpoints) against the number of divisions, for several pole
    distances and drafting precisions."""
    from graphplan.graphic.diagrams import chord_diagrams
    counts = [8, 12, 24, 48, 96] + ([] if quick else [180, 360])
    poles = [20.0, 30.0, 50.0] if not quick else [20.0, 50.0]
    for name in ("crank_slider", "shaper"):
        st = example(name)
        for precision in (0.0, 0.5):
            for h in poles:
                for n in counts:
                    elapsed = best_time(lambda: chord_diagrams(st, divisions=n, H1=h, H2=h,
                                                               precision=precision), 3)
                    d = chord_diagrams(st, divisions=n, H1=h, H2=h, precision=precision)
                    for key, label in (("v_mid", "v"), ("a_mid", "a")):
                        err = float(np.nanmax(np.abs(d.errors_of_max(key))))
                        yield {"section": "chords", "method": f"chords {label}", "x": n,
                               "setting": f"{name} H1=H2={h:g} mm precision={precision:g} mm",
                               "scene": name, "H_mm": h, "precision_mm": precision,
                               "time_s": elapsed, "max_error_pct": err}


def plans(quick: bool) -> Iterator[Row]:
    """The plans' error against the drafting precision (velocities and accelerations of vectors
    drawn at least 20 mm long; all positions, one acceleration plan)."""
    from graphplan.graphic.plans import build_plans
    from graphplan.report.plans import plans_json
    names = ["crank_slider", "shaper"] if quick else ["crank_slider", "four_bar", "shaper", "slotter"]
    for name in names:
        st = example(name)
        for precision in (0.0, 0.1, 0.25, 0.5, 1.0):
            t0 = time.perf_counter()
            doc = plans_json(build_plans(st, precision=precision))
            elapsed = time.perf_counter() - t0
            for kind in ("velocity", "acceleration"):
                errs = [abs(e["error_pct"]) for p in doc["positions"] for e in p.get(kind, {}).values()
                        if e.get("error_pct") is not None and (e.get("mm") or 0.0) >= 20.0]
                yield {"section": "plans", "method": f"plans {kind}", "x": precision,
                       "setting": f"{name} precision={precision:g} mm", "scene": name,
                       "time_s": elapsed, "max_error_pct": max(errs) if errs else None,
                       "mean_error_pct": float(np.mean(errs)) if errs else None}


SHEET_TIMED = (("crank_slider", "kinematics"), ("shaper", "kinematics"), ("shaper", "forces"))

# one sheet built and written as SVG in a fresh interpreter, its processor time from after the imports
# of the sheets' module to the SVG (the compositions, drawings and placements a process remembers are
# its own: a second sheet of the same scene in one process takes a few hundredths of a second)
_SHEET_ONCE = """
import sys, time
from types import SimpleNamespace
from graphplan.bench.examples import example
from graphplan.sheets.form import form
from graphplan.sheets.sheet import BUILDERS
st = example(sys.argv[1])
args = SimpleNamespace(positions=None, accel=None, precision=0.5, lang="uk", sheet=sys.argv[2])
t0 = time.process_time()
BUILDERS[sys.argv[2]](st, form("A1"), args).svg()
print(time.process_time() - t0)
"""


def sheet_time(quick: bool) -> Iterator[Row]:
    """The processor time of one whole A1 sheet (in a fresh process, its imports of the sheets'
    module not counted; the command adds Python's start-up): the best of 1 (quick) or 3 runs."""
    import os
    import subprocess
    import sys
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(Path(__file__).resolve().parents[2])]
                                                         + [p for p in [os.environ.get("PYTHONPATH")] if p])}
    for name, kind in SHEET_TIMED:
        runs = [float(subprocess.run([sys.executable, "-c", _SHEET_ONCE, name, kind], env=env, check=True,
                                     capture_output=True, text=True).stdout.split()[-1])
                for _ in range(1 if quick else 3)]
        setting = f"{name} A1 SVG" if kind == "kinematics" else f"{name} {kind} A1 SVG"
        yield {"section": "sheet", "method": "sheet", "x": 1, "setting": setting,
               "time_s": min(runs), "max_error_pct": None}


def external(quick: bool) -> Iterator[Row]:
    """The same analysis by pylinkage and by `mechanism`, where installed, side by side (ratios)."""
    from graphplan.bench.external import external_rows
    for row in external_rows(n_positions=360, repeats=3 if quick else 5, examples_dir=examples_dir()):
        yield {"section": "external", "x": row.get("n_positions"), **row}


def flywheel(quick: bool) -> Iterator[Row]:
    """The graphical flywheel against the exact one (bench/dynamics.py)."""
    from graphplan.bench.dynamics import flywheel as rows
    return rows(quick, example)


def cam(quick: bool) -> Iterator[Row]:
    """The graphical cam synthesis against the exact one (bench/cam.py)."""
    from graphplan.bench.cam import rows as measured
    return measured(quick, examples_dir())


def gears(quick: bool) -> Iterator[Row]:
    """The graphical εα and u1H against the closed forms (bench/gears.py)."""
    from graphplan.bench.gears import rows as measured
    return measured(quick)


def processes(quick: bool) -> Iterator[Row]:
    """Whole commands as fresh processes against the bare import (bench/processes.py)."""
    from graphplan.bench.processes import rows as measured
    return measured(quick)


SECTIONS: dict[str, Callable[[bool], Iterator[Row]]] = {
    "speed": solver_speed,
    "chords": chords,
    "differentiation": differentiation.rows,
    "plans": plans,
    "stability": stability,
    "sheet": sheet_time,
    "external": external,
    "flywheel": flywheel,
    "cam": cam,
    "gears": gears,
}
ON_REQUEST: dict[str, Callable[[bool], Iterator[Row]]] = {     # not in a plain run: asked for by name
    "processes": processes,
}


def run(out: Path, quick: bool, show_progress: bool | None = None, sections: list[str] | None = None,
        lang: str = "uk") -> list[Row]:
    """Run every section (or the ``sections`` named), write ``out/bench.json`` and the charts;
    return the rows. ``lang`` is the language of the progress bar, the charts and a refusal."""
    from graphplan.util.errors import said_error
    from graphplan.util.files import json_text, write_atomic
    from graphplan.util.progress import progress
    from graphplan.util.words import word

    known = {**SECTIONS, **ON_REQUEST}
    names = list(SECTIONS) if not sections else sections
    for name in names:
        if name not in known:
            raise said_error(GraphplanError, "bench unknown section", None, lang, name=repr(name),
                             known=", ".join(known))
    rows: list[Row] = []
    for name in progress(names, len(names), word("bench progress", lang), show_progress,
                         done=word("bench done", lang)):
        rows.extend(known[name](quick))
    doc = {"quick": quick, "rows": rows}
    write_atomic(out / "bench.json", json_text(_clean(doc)))
    charts(rows, out, lang)
    return rows


def _clean(value: Any) -> Any:
    """JSON-safe: floats that are not finite become null."""
    if isinstance(value, float):
        return value if math.isfinite(value) else None
    if isinstance(value, dict):
        return {k: _clean(v) for k, v in value.items()}
    if isinstance(value, list):
        return [_clean(v) for v in value]
    return value


def charts(rows: list[Row], out: Path, lang: str = "uk") -> list[Path]:
    """Draw each section's chart as PNG and SVG (deterministic files), its words in ``lang``."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from graphplan.util.files import write_atomic
    import io

    plt.rcParams["svg.hashsalt"] = "graphplan"
    written = []
    for name, draw in CHARTS.items():
        section = [r for r in rows if r["section"] == name]
        if not section:
            continue
        fig = draw(section, plt)
        say_figure(fig, lang)
        for fmt in ("png", "svg"):
            buf = io.BytesIO()
            meta = {"Date": None} if fmt == "svg" else {"Software": None}
            fig.savefig(buf, format=fmt, dpi=110, metadata=meta)
            written.append(write_atomic(out / f"{name}.{fmt}", buf.getvalue()))
        plt.close(fig)
    return written


def _chart_speed(rows: list[Row], plt):
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for setting in sorted({r["setting"].split(" N=")[0] for r in rows}):
        pts = [(r["x"], r["positions_per_s"]) for r in rows if r["setting"].startswith(setting + " ")]
        ax.loglog(*zip(*pts), "o-", label=f"analytic solver, {setting}")
    ax.set_xlabel("positions per call")
    ax.set_ylabel("positions per second")
    ax.set_title("Speed of the analytic solver (vectorised numpy)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    return fig


def _chart_stability(rows: list[Row], plt):
    settings = list(dict.fromkeys(r["setting"] for r in rows))
    fig, axes = plt.subplots(1, len(settings), figsize=(5 * len(settings), 4.2))
    for ax, setting in zip(np.atleast_1d(axes), settings):
        sel = [r for r in rows if r["setting"] == setting]
        xs = [r["x"] for r in sel if r["min_angle_deg"] is not None]
        ax.plot(xs, [r["min_angle_deg"] for r in sel if r["min_angle_deg"] is not None], "o-",
                label="smallest angle between direction lines, °")
        ax.set_yscale("log")
        ax2 = ax.twinx()
        ax2.plot(xs, [r["max_omega"] for r in sel if r["min_angle_deg"] is not None], "s--", color="C1",
                 label="max |ω| of the link, rad/s")
        pe = [(r["x"], r.get("plans_max_error_pct")) for r in sel if r.get("plans_max_error_pct") is not None]
        if pe:
            ax2.plot(*zip(*pe), "^:", color="C2", label="plans' max error at 0.5 mm, %")
        ax2.set_yscale("log")
        for r in sel:
            if r["status"] != "ok":
                ax.axvline(r["x"], color="red" if r["status"] == "refused" else "orange", alpha=0.4)
        ax.set_title(setting, fontsize=9)
        ax.set_xlabel("swept parameter (red: refused, orange: warned)")
        ax.invert_xaxis()
        ax.legend(loc="lower left", fontsize=7)
        ax2.legend(loc="upper right", fontsize=7)
    fig.tight_layout()
    return fig


def _chart_chords(rows: list[Row], plt):
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(12, 4.8))
    styles = {}
    for r in rows:
        key = (r["scene"], r["method"], r["H_mm"], r["precision_mm"])
        styles.setdefault(key, []).append(r)
    for (scene, method, h, p), sel in sorted(styles.items()):
        ls = "-" if p == 0 else "--"
        mk = "o" if method.endswith("v") else "s"
        label = f"{scene} {method[-1]} H={h:g} p={p:g}"
        line = ax1.loglog([r["x"] for r in sel], [r["max_error_pct"] for r in sel], ls, marker=mk, ms=3,
                          label=label)[0]
        if h == max(k[2] for k in styles):      # one pole distance on the time chart, to stay legible
            ax2.loglog([r["time_s"] for r in sel], [r["max_error_pct"] for r in sel], ls, marker=mk, ms=3,
                       color=line.get_color(), label=label)
    for ax in (ax1, ax2):
        ax.axhline(5.0, color="red", lw=0.8)
        ax.text(ax.get_xlim()[0], 5.3, " lab's 5 %", color="red", fontsize=7)
        ax.grid(True, which="both", alpha=0.3)
        ax.set_ylabel("max error, % of the cycle's maximum")
    ax1.set_xlabel("divisions of the period")
    ax2.set_xlabel("wall time of one construction, s")
    ax1.set_title("Method of chords: error against divisions (solid: exact ruler, dashed: 0.5 mm)", fontsize=9)
    ax2.set_title("… and against the wall time of one construction (largest H)", fontsize=9)
    ax2.legend(fontsize=5)
    ax1.legend(fontsize=5, ncol=2)
    fig.tight_layout()
    return fig


def _chart_plans(rows: list[Row], plt):
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for scene in sorted({r["scene"] for r in rows}):
        for method, ls in (("plans velocity", "o-"), ("plans acceleration", "s--")):
            sel = [r for r in rows if r["scene"] == scene and r["method"] == method and r["x"] > 0]
            if sel:
                ax.loglog([r["x"] for r in sel], [r["max_error_pct"] for r in sel], ls, label=f"{scene}, {method[6:]}")
    ax.set_xlabel("drafting precision, mm (0: exact, error ~1e-12 %)")
    ax.set_ylabel("max error of vectors ≥ 20 mm, %")
    ax.axhline(5.0, color="red", lw=0.8)
    ax.set_title("Plans: error against the drafting precision", fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    return fig


def _chart_cam(rows: list[Row], plt):
    from graphplan.bench.cam import chart
    return chart(rows, plt)


def _chart_gears(rows: list[Row], plt):
    from graphplan.bench.gears import chart
    return chart(rows, plt)


def _chart_flywheel(rows: list[Row], plt):
    from graphplan.bench.dynamics import chart
    return chart(rows, plt)


CHARTS: dict[str, Callable] = {"speed": _chart_speed, "chords": _chart_chords, "plans": _chart_plans,
                               "stability": _chart_stability, "differentiation": differentiation.chart,
                               "flywheel": _chart_flywheel, "cam": _chart_cam, "gears": _chart_gears}


@functools.lru_cache(maxsize=None)
def _phrases(lang: str) -> tuple[dict[str, str], re.Pattern]:
    """Every English phrase a bench row says → its words in ``lang``: the catalogue's "bench …"
    entries (the laws' names as the cam's tables word them), the cam scenes as the cam's tables name
    their followers, the drawn millimetre."""
    from graphplan.report.cam import WORDS as CAM
    from graphplan.util.words import WORDS, unit, word
    table = {en: (uk if lang == "uk" else en) for key, (uk, en) in WORDS.items()
             if key.startswith("bench ") and "{" not in en}
    for law in CAM["en"]["laws"]:
        table[word("bench law shocks", "en", law=CAM["en"]["laws"][law])] = word(
            "bench law shocks", lang, law=CAM[lang]["laws"][law])
    for follower in ("translating", "rocking"):
        table[f"cam_{follower}"] = f"{word('bench cam', lang)}, {CAM[lang][follower]}"
    table["mm"] = unit("mm", lang)          # (not "m": m is the gears' module there)
    pattern = "|".join(re.escape(p) for p in sorted(table, key=len, reverse=True))
    return table, re.compile(rf"(?<!\w)(?:{pattern})(?!\w)")


def say(text: str, lang: str) -> str:
    """A bench row's English text in ``lang``: each known phrase (the longest first, whole words
    only) in the language's words, decimal commas in Ukrainian; names of libraries, their calls and
    the errors they raise stay as they are."""
    from graphplan.util.words import word
    if lang == "en" or not text:
        return text
    failed = word("bench failed", "en")
    if text.startswith(failed):                  # another package's error, as it said it
        return word("bench failed", lang) + text[len(failed):]
    table, pattern = _phrases(lang)
    text = pattern.sub(lambda m: table[m.group(0)], text)
    return re.sub(r"(?<=\d)\.(?=\d)", ",", text)


def say_figure(fig, lang: str) -> None:
    """Every text a chart holds (titles, axis labels, legends, notes) said in ``lang`` (``say``),
    the ticks' numbers with the decimal comma in Ukrainian."""
    if lang == "en":
        return
    from matplotlib.text import Text
    from matplotlib.ticker import Formatter

    class Comma(Formatter):
        """The axis's own labels, the decimal point a comma."""

        def __init__(self, inner: Formatter):
            self.inner = inner

        def __call__(self, x, pos=None):
            return self.inner(x, pos).replace(".", ",")

        def format_ticks(self, values):
            return [t.replace(".", ",") for t in self.inner.format_ticks(values)]

        def get_offset(self):
            return self.inner.get_offset().replace(".", ",")

    import textwrap
    for t in fig.findobj(Text):
        if t.get_text():
            t.set_text(say(t.get_text(), lang))
    renderer = fig.canvas.get_renderer()
    for ax in fig.axes:
        for axis in (ax.xaxis, ax.yaxis):
            axis.set_major_formatter(Comma(axis.get_major_formatter()))
            axis.set_minor_formatter(Comma(axis.get_minor_formatter()))
        room = ax.get_window_extent(renderer)
        for t, span in ((ax.title, room.width), (ax.xaxis.label, room.width), (ax.yaxis.label, room.height)):
            box = t.get_window_extent(renderer)
            wide = max(box.width, box.height) if t is ax.yaxis.label else box.width
            if wide > span:                  # a longer title or axis label: wrapped to the axes' size
                text = t.get_text()
                t.set_text(textwrap.fill(text, max(int(len(text) * span / wide), 16)))
        legend = ax.get_legend()
        if legend is not None and legend.get_window_extent(renderer).width > room.width:
            texts = legend.get_texts()       # longer entries: one column, where they cover least
            ax.legend(legend.legend_handles, [t.get_text() for t in texts], fontsize=texts[0].get_fontsize(),
                      ncol=1)
    fig.tight_layout()


def setting(r: Row, lang: str) -> str:
    """A row's setting in ``lang`` (a sweep's row adds its swept value x)."""
    from graphplan.util.words import num
    text = say(r["setting"], lang)
    if r["section"] == "stability":
        text += f" x={num(r['x'], lang, 6)}"
    return text


def summary(rows: list[Row], lang: str = "uk") -> str:
    """One line per row, for people, in ``lang``: section, method, setting, time, error, the status
    or the note; columns as wide as their widest cell."""
    from graphplan.util.words import num, word
    table = [word("bench head", lang).split("|")]
    for r in rows:
        t = "" if r.get("time_s") is None else num(r["time_s"], lang, 3)
        e = "" if r.get("max_error_pct") is None else num(r["max_error_pct"], lang, 3)
        status = r.get("status") or r.get("note") or ""
        table.append([say(r["section"], lang), say(r["method"], lang), setting(r, lang), t, e, say(status, lang)])
    widths = [max(len(row[k]) for row in table) for k in range(5)]
    return "\n".join(f"{c[0]:{widths[0]}} {c[1]:{widths[1]}} {c[2]:{widths[2]}} {c[3]:>{widths[3]}} "
                     f"{c[4]:>{widths[4]}}  {c[5]}".rstrip() for c in table)
