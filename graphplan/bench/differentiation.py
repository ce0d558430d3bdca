"""`graphplan bench`, section "differentiation": the method of chords, chords with the lab's area
correction and the method of tangents, one against the other, for v and a on the crank-slider and
the shaper (L = 240 mm, H1 = H2 = 30 mm).

Three sweeps, each row one method, one diagram (v or a), one setting:
- ``divisions``: 8 … 96 equal intervals, drawn exactly (ruler 0, tangents exact) and as the lab
  draws (ruler 0.5 mm, tangents ±1° by the mirror);
- ``precision``: the ruler's division 0 … 1 mm at 12 and 24 divisions (tangents at ±1°);
- ``angle``: the tangents' angular error bound 0 … 4° at 12 and 24 divisions, ruler exact and 0.5 mm.
``max_error_pct`` is the largest error at the method's own ordinates (chords: the middles of the
intervals; tangents: the division ordinates) in percent of the cycle's maximum; ``at_error_pct`` the
same at the division ordinates (the lab's table); ``qualitative`` whether the diagram has spurious or
missed extrema or zero crossings. The tangents' errors are the mean over ``SEEDS`` draws of the
drafting error (their largest in ``worst_seed_pct``); the chords have no random part.

``python -m graphplan.bench.differentiation`` prints the Markdown table of docs/diagrams.md.
"""
from __future__ import annotations

import time
from collections.abc import Iterator
from typing import Any

import numpy as np

Row = dict[str, Any]

SCENES = ("crank_slider", "shaper")
METHODS: dict[str, dict[str, Any]] = {"chords": {}, "chords+correction": {"correct": True},
                                      "tangents": {"method": "tangents"}}
LAB = {"precision": 0.5, "angle_error_deg": 1.0}          # how the lab draws
EXACT = {"precision": 0.0, "angle_error_deg": 0.0}
SEEDS = 5
DIVISIONS = (8, 12, 16, 24, 36, 48, 72, 96)
PRECISIONS = (0.0, 0.1, 0.25, 0.5, 1.0)
ANGLES = (0.0, 0.25, 0.5, 1.0, 2.0, 4.0)


def _measure(st, n: int, method: str, precision: float, angle: float, seeds: int) -> dict[str, dict[str, float]]:
    """The v and a errors of one method at one setting (tangents: mean and worst over the seeds)."""
    from graphplan.graphic.diagrams import chord_diagrams
    from graphplan.graphic.tangents import SEED
    kw = dict(METHODS[method])
    runs = seeds if method == "tangents" and angle > 0 else 1
    found: dict[str, list[tuple[float, float, float, bool]]] = {"v": [], "a": []}
    t0 = time.perf_counter()
    for i in range(runs):
        d = chord_diagrams(st, divisions=n, precision=precision, angle_error_deg=angle, seed=SEED + i, **kw)
        wrong = {w["diagram"] for w in d.warnings if w["kind"] == "qualitative"}
        for q, sym in (("v", d.symbols[1]), ("a", d.symbols[2])):
            own = np.abs(d.errors_of_max(f"{q}_mid"))
            at = np.abs(d.errors_of_max(f"{q}_at"))
            found[q].append((float(np.max(own)), float(np.max(at)), float(np.sqrt(np.mean(own ** 2))), sym in wrong))
    elapsed = (time.perf_counter() - t0) / runs
    out = {}
    for q, vals in found.items():
        arr = np.array([v[:3] for v in vals])
        out[q] = {"max_error_pct": float(arr[:, 0].mean()), "at_error_pct": float(arr[:, 1].mean()),
                  "rms_error_pct": float(arr[:, 2].mean()), "worst_seed_pct": float(arr[:, 0].max()),
                  "qualitative": sum(v[3] for v in vals) / len(vals), "time_s": elapsed, "runs": runs}
    return out


def rows(quick: bool) -> Iterator[Row]:
    """Every row of the three sweeps (fewer divisions and seeds with ``quick``)."""
    from graphplan.bench.examples import example
    divisions = (8, 12, 24, 48) if quick else DIVISIONS
    seeds = 2 if quick else SEEDS
    for name in SCENES:
        st = example(name)

        def emit(sweep: str, x: float, n: int, method: str, precision: float, angle: float) -> Iterator[Row]:
            for q, m in _measure(st, n, method, precision, angle, seeds).items():
                shown_angle = angle if method == "tangents" else 0.0
                yield {"section": "differentiation", "method": method, "quantity": q, "scene": name,
                       "sweep": sweep, "x": x, "divisions": n, "precision_mm": precision,
                       "angle_error_deg": shown_angle,
                       "setting": f"{name} {q} N={n} ruler {precision:g} mm"
                                  + (f" tangents ±{shown_angle:g}°" if method == "tangents" else ""),
                       **m}

        for n in divisions:
            for drafting in (EXACT, LAB):
                for method in METHODS:
                    yield from emit("divisions", n, n, method, drafting["precision"], drafting["angle_error_deg"])
        for n in (12, 24):
            for p in PRECISIONS:
                for method in METHODS:
                    yield from emit("precision", p, n, method, p, LAB["angle_error_deg"])
            for p in (0.0, LAB["precision"]):
                for angle in ANGLES:
                    yield from emit("angle", angle, n, "tangents", p, angle)


# -- the chart --------------------------------------------------------------------------------------

STYLE = {"chords": ("C0", "o"), "chords+correction": ("C2", "s"), "tangents": ("C3", "^")}


def chart(rows_: list[Row], plt):
    """Error against divisions (exact and lab drafting), against the ruler, against the tangents'
    angle: v on the top row, a below; solid crank_slider, dashed shaper."""
    fig, axes = plt.subplots(2, 3, figsize=(15, 8.5))
    for r_i, q in enumerate(("v", "a")):
        sel = [r for r in rows_ if r["quantity"] == q]
        ax = axes[r_i][0]
        for (scene, ls) in (("crank_slider", "-"), ("shaper", "--")):
            for method, (color, mk) in STYLE.items():
                for drafting, alpha in ((EXACT, 0.45), (LAB, 1.0)):
                    pts = [(r["x"], r["max_error_pct"]) for r in sel
                           if r["sweep"] == "divisions" and r["scene"] == scene and r["method"] == method
                           and r["precision_mm"] == drafting["precision"]]
                    if pts:
                        lab = "lab" if drafting is LAB else "exact"
                        ax.loglog(*zip(*pts), ls, color=color, marker=mk, ms=3, alpha=alpha,
                                  label=f"{scene} {method} ({lab})")
        ax.set_xlabel("divisions of the period")
        ax.set_title(f"{q}: error against divisions (faint: exact drawing; bold: ruler 0.5 mm, tangents ±1°)",
                     fontsize=8)
        ax = axes[r_i][1]
        for (scene, ls) in (("crank_slider", "-"), ("shaper", "--")):
            for method, (color, mk) in STYLE.items():
                for n, alpha in ((12, 1.0), (24, 0.5)):
                    pts = [(max(r["x"], 0.02), r["max_error_pct"]) for r in sel
                           if r["sweep"] == "precision" and r["scene"] == scene and r["method"] == method
                           and r["divisions"] == n]
                    if pts:
                        ax.loglog(*zip(*pts), ls, color=color, marker=mk, ms=3, alpha=alpha,
                                  label=f"{scene} {method} N={n}")
        ax.set_xlabel("ruler's division, mm (0 drawn at 0.02; tangents ±1°)")
        ax.set_title(f"{q}: error against the drafting precision (bold N = 12, faint N = 24)", fontsize=8)
        ax = axes[r_i][2]
        for (scene, ls) in (("crank_slider", "-"), ("shaper", "--")):
            for p, color in ((0.0, "C3"), (0.5, "C1")):
                for n, alpha in ((12, 1.0), (24, 0.5)):
                    pts = [(max(r["x"], 0.1), r["max_error_pct"]) for r in sel
                           if r["sweep"] == "angle" and r["scene"] == scene and r["precision_mm"] == p
                           and r["divisions"] == n]
                    if pts:
                        ax.loglog(*zip(*pts), ls, color=color, marker="^", ms=3, alpha=alpha,
                                  label=f"{scene} ruler {p:g} mm N={n}")
        ax.set_xlabel("tangents' angular error bound, ° (0 drawn at 0.1)")
        ax.set_title(f"{q}: method of tangents against its angular error", fontsize=8)
    for ax in axes.flat:
        ax.axhline(5.0, color="red", lw=0.8)
        ax.grid(True, which="both", alpha=0.3)
        ax.set_ylabel("max error, % of the cycle's maximum")
        ax.legend(fontsize=4.5, ncol=2)
    fig.tight_layout()
    return fig


# -- the table of docs/diagrams.md -------------------------------------------------------------------

NAMES = {"chords": "chords", "chords+correction": "chords + correction", "tangents": "tangents"}


def errors(rows_: list[Row], scene: str, n: int, q: str, drafting: dict[str, float],
           key: str = "max_error_pct") -> dict[str, float]:
    """Every method's error of ``q`` at ``n`` divisions drawn with ``drafting``."""
    return {r["method"]: r[key] for r in rows_
            if r["sweep"] == "divisions" and r["scene"] == scene and r["divisions"] == n
            and r["quantity"] == q and r["precision_mm"] == drafting["precision"]}


def markdown_table(rows_: list[Row]) -> str:
    """Rows → two Markdown tables (the methods' own ordinates, lab and exact drawing; the division
    ordinates of the lab's table) and, per division count, the method to prefer as the lab draws."""
    counts = sorted({r["divisions"] for r in rows_ if r["sweep"] == "divisions"})
    head = ("| scene | N | {what} | v: chords | v: chords + corr. | v: tangents | a: chords | a: chords + corr. "
            "| a: tangents | best for v | best for a |")
    rule = "|---|---|---|---|---|---|---|---|---|---|---|"
    wins: dict[int, list[str]] = {n: [] for n in counts}
    out = []
    for key, what, draftings in (("max_error_pct", "drawing", ((LAB, "lab"), (EXACT, "exact"))),
                                 ("at_error_pct", "at", ((LAB, "ordinates"),))):
        out += [head.format(what=what), rule]
        for scene in SCENES:
            for n in counts:
                for drafting, label in draftings:
                    ev, ea = (errors(rows_, scene, n, q, drafting, key) for q in ("v", "a"))
                    bv, ba = min(ev, key=ev.get), min(ea, key=ea.get)
                    cells = [f"{ev[m]:.2f}" for m in METHODS] + [f"{ea[m]:.2f}" for m in METHODS]
                    out.append(f"| {scene} | {n} | {label} | " + " | ".join(cells)
                               + f" | {NAMES[bv]} | {NAMES[ba]} |")
                    if drafting is LAB:
                        wins[n] += [bv, ba]
        out.append("")
    out.append("The method to prefer as the lab draws (ruler 0.5 mm, tangents ±1°): wins out of eight "
               "(v and a of both scenes, at the methods' own ordinates and at the division ordinates; a tie "
               "goes to the simpler method, listed first):")
    out.append("")
    for n in counts:
        count = {m: wins[n].count(m) for m in METHODS}
        top = max(count.values())
        out.append(f"- N = {n}: **{' or '.join(NAMES[m] for m in METHODS if count[m] == top)}** ("
                   + ", ".join(f"{NAMES[m]} {count[m]}" for m in METHODS) + ")")
    return "\n".join(out) + "\n"


def main() -> None:
    import sys
    sys.stdout.write(markdown_table(list(rows(quick=False))))


if __name__ == "__main__":
    main()
