"""`graphplan bench`, section "cam": the graphical cam synthesis against the exact one — the base
radius measured off the phase diagram and the profile's radii read at the divisions, as the divisions
of each phase grow, with the exact ruler (the construction converges) and the lab's 0.5 mm one (the
readings dominate); and where the method fails: the linear law's rigid shocks (its ds/dφ must be drawn
directly), a pressure angle allowed near 90° (the smallest base radius collapses toward the offset), a
roller larger than the profile's curvature (undercut)."""
from __future__ import annotations

import time
from collections.abc import Iterator
from dataclasses import replace
from pathlib import Path
from typing import Any

import numpy as np

Row = dict[str, Any]
DIVISIONS = (4, 6, 8, 12, 16, 24, 32, 64, 128)
QUICK = (4, 8, 16, 32)


def rows(quick: bool, examples: Path) -> Iterator[Row]:
    from graphplan.exact.cam import motion, solve
    from graphplan.graphic.cam import construct
    from graphplan.model.cam import load
    for name in ("cam_translating", "cam_rocking"):
        cam = load(examples / f"{name}.toml")
        t0 = time.perf_counter()
        sol = solve(cam)
        yield {"section": "cam", "method": "exact", "scene": name, "x": 0, "setting": f"{name} exact",
               "time_s": time.perf_counter() - t0, "max_error_pct": None, "R0_min_m": sol.R0_min}
        for precision in (0.0, 0.5):
            for n in QUICK if quick else DIVISIONS:
                t0 = time.perf_counter()
                g = construct(sol, n, precision)
                elapsed = time.perf_counter() - t0
                s, _, _ = motion(cam, g.phi, g.phase)
                radius = sol.at(g.phi, g.phase)["radius"]
                yield {"section": "cam", "method": "graphical", "scene": name, "x": n, "precision_mm": precision,
                       "setting": f"{name} precision={precision:g} mm", "time_s": elapsed,
                       "R0_error_pct": 100.0 * (g.R0_min - sol.R0_min) / sol.R0_min,
                       "profile_error_pct": 100.0 * float(np.max(np.abs(g.radius_mm * g.mu_l - radius) / radius)),
                       "s_error_pct": 100.0 * float(np.max(np.abs(g.s - s))) / cam.stroke,
                       "max_error_pct": abs(100.0 * (g.R0_min - sol.R0_min) / sol.R0_min)}
    # where the method fails
    from graphplan.report.cam import WORDS
    from graphplan.util.words import word
    cam = load(examples / "cam_translating.toml")
    shocks = word("bench law shocks", "en", law=WORDS["en"]["laws"]["linear"])    # the summary says it in uk
    for label, changed in ((shocks, replace(cam, laws=("linear", "linear"))),
                           ("[ϑ] = 85° (near 90°)", replace(cam, allowed=(85.0, 85.0))),
                           ("roller 55.6 mm (undercut)", replace(cam, roller=0.0556, base_radius=0.056))):
        from graphplan.util.errors import GraphplanError
        t0 = time.perf_counter()
        try:
            sol = solve(changed)
            g = construct(sol, 8, 0.5)
        except GraphplanError as exc:            # the method's end, said in one line
            yield {"section": "cam", "method": "failure", "scene": "cam_translating", "x": 8, "setting": label,
                   "time_s": time.perf_counter() - t0, "max_error_pct": None, "status": "refused",
                   "message": exc.line()}
            continue
        yield {"status": "warning" if sol.warnings or g.warnings else "ok","section": "cam", "method": "failure", "scene": "cam_translating", "x": 8, "setting": label,
               "time_s": time.perf_counter() - t0, "max_error_pct": None, "R0_min_m": sol.R0_min,
               "R0_error_pct": 100.0 * (g.R0_min - sol.R0_min) / sol.R0_min,
               "warnings": [en for en, _ in sol.warnings + g.warnings]}


def chart(rows: list[Row], plt):
    """The graphical R0's and the profile's errors against the divisions, exact and 0.5 mm ruler."""
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for ax, key, title in ((axes[0], "R0_error_pct", "|R0 error|, %"), (axes[1], "profile_error_pct",
                                                                         "profile radius error (max), %")):
        for setting in dict.fromkeys(r["setting"] for r in rows if r["method"] == "graphical"):
            sel = [r for r in rows if r["setting"] == setting and r["method"] == "graphical"]
            xs = [r["x"] for r in sel]
            ys = [max(abs(r[key]), 1e-12) for r in sel]
            ax.plot(xs, ys, marker="o", label=setting)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("divisions of each phase")
        ax.set_title(title)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    fig.tight_layout()
    return fig
