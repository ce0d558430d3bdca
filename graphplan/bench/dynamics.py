"""`graphplan bench`, section "flywheel": the graphical (Wittenbauer) flywheel's error against the
exact one as the divisions of the turn grow — with the exact ruler (precision 0: the construction
converges; with the course's tangents tg ψ = μ_I·ω_m²(1 ± δ)/(2μ_T) to the δ²/4 those drop, with
the exact (1 ± δ/2)² to zero) and with the 0.5 mm ruler (the reading of |kl| dominates)."""
from __future__ import annotations

import time
from collections.abc import Iterator
from typing import Any

Row = dict[str, Any]
DIVISIONS = (8, 12, 24, 48, 96, 192, 384)
QUICK = (8, 12, 24, 48, 96)


def flywheel(quick: bool, example) -> Iterator[Row]:
    """Rows: scene, divisions, precision, slopes; the flywheel's error in % of the exact one and
    the approximate methods' errors; ``example(name)`` gives a study."""
    from graphplan.exact.dynamics import analyse
    from graphplan.graphic.flywheel import construct
    for name in ("slotter", "shaper"):
        st = example(name)
        t0 = time.perf_counter()
        dyn = analyse(st)
        exact_time = time.perf_counter() - t0
        yield {"section": "flywheel", "method": "exact", "setting": f"{name} equation of motion + brentq",
               "scene": name, "x": 0, "time_s": exact_time, "max_error_pct": None,
               "flywheel": dyn.flywheel, "motor_flywheel": dyn.motor_flywheel, "delta": dyn.delta}
        for precision, slopes in ((0.0, "exact"), (0.0, "course"), (0.5, "course")):
            for n in QUICK if quick else DIVISIONS:
                t0 = time.perf_counter()
                f = construct(dyn, n, precision, slopes=slopes)
                elapsed = time.perf_counter() - t0
                yield {"section": "flywheel", "method": "wittenbauer", "scene": name, "x": n,
                       "setting": f"{name} precision={precision:g} mm tangents={slopes}",
                       "precision_mm": precision, "slopes": slopes, "time_s": elapsed,
                       "max_error_pct": abs(f.error_pct(f.flywheel)), "error_pct": f.error_pct(f.flywheel),
                       "approximate_error_pct": f.error_pct(f.approximate),
                       "merkalov_error_pct": f.error_pct(f.merkalov), "kl_mm": f.kl}


def chart(rows: list[Row], plt):
    """|error| of the graphical flywheel against the divisions, log–log, one line per setting."""
    fig, ax = plt.subplots(figsize=(7.5, 4.8))
    sel = [r for r in rows if r["method"] == "wittenbauer"]
    for setting in dict.fromkeys(r["setting"] for r in sel):
        pts = [(r["x"], max(r["max_error_pct"], 1e-6)) for r in sel if r["setting"] == setting]
        style = "-" if "precision=0 " in setting else "--"
        marker = "o" if "tangents=exact" in setting else "s"
        ax.loglog(*zip(*pts), style, marker=marker, ms=3, label=setting)
    ax.axhline(5.0, color="red", lw=0.8)
    ax.set_xlabel("divisions of the turn")
    ax.set_ylabel("|flywheel error|, % of the exact one")
    ax.set_title("Wittenbauer flywheel against the equation of motion (solid: exact ruler, dashed: 0.5 mm)",
                 fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=6)
    fig.tight_layout()
    return fig
