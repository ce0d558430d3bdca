"""`graphplan bench`, section "gears": the graphical εα and u1H against the closed forms as the drafting
precision and the drawing's scale change — the meshing with the module drawn 10, 20 and 40 mm, the
train's scheme with the ring's radius drawn 50, 100 and 200 mm (the sun's segment on the plan of
angular velocities about 100 mm), each at the exact ruler (the
construction is exact: errors at round-off) and at 0.1 … 1 mm — beside the stated first-order bound;
and where the method fails: near-pointed teeth (sa read as a short chord), a small wheel (undercut and
interference), a ratio near 1 (no type B train reaches it), a large ratio (the carrier's segment a few
millimetres long)."""
from __future__ import annotations

import time
from collections.abc import Iterator
from typing import Any

Row = dict[str, Any]
PRECISIONS = (0.0, 0.1, 0.25, 0.5, 1.0)
QUICK = (0.0, 0.5)
PAIRS = (((12, 30), (0.5, 0.3)), ((17, 60), (0.0, 0.0)), ((14, 35), (0.65, 0.65)), ((25, 40), (0.3, -0.2)))
TRAINS = (("A", 6.0), ("A", 9.5), ("B", 12.0), ("B", 7.0))


def rows(quick: bool) -> Iterator[Row]:
    from graphplan.exact.gears import solve_pair, solve_train
    from graphplan.graphic.gears import construct_mesh, construct_train
    from graphplan.model.gears import Pair, Train
    from graphplan.util.errors import GraphplanError
    precisions = QUICK if quick else PRECISIONS
    for module_mm in ((20.0,) if quick else (10.0, 20.0, 40.0)):
        for p in precisions:
            worst, bound, t = 0.0, 0.0, 0.0
            for z, x in PAIRS:
                sol = solve_pair(Pair(z, 0.004, x))
                t0 = time.perf_counter()
                m = construct_mesh(sol, p, module_mm=module_mm)
                t += time.perf_counter() - t0
                err = 100.0 * abs(m.eps - sol.eps) / sol.eps
                if err >= worst:
                    worst, bound = err, 100.0 * m.eps_bound / sol.eps
            yield {"section": "gears", "method": "contact ratio", "x": p, "precision_mm": p, "module_mm": module_mm,
                   "setting": f"εα, m = {module_mm:g} mm, precision={p:g} mm", "time_s": t / len(PAIRS),
                   "max_error_pct": worst, "bound_pct": bound}
    for ring in ((80.0,) if quick else (50.0, 100.0, 200.0)):
        for p in precisions:
            worst, bound, t = 0.0, 0.0, 0.0
            for kind, u in TRAINS:
                tr = solve_train(Train(kind, 3, 0.003, 100.0, ratio=u))
                t0 = time.perf_counter()
                v = construct_train(tr, p, ring_mm=ring)
                t += time.perf_counter() - t0
                err = 100.0 * abs(v.ratio - tr.ratio) / tr.ratio
                if err >= worst:
                    worst, bound = err, 100.0 * v.ratio_bound / tr.ratio
            yield {"section": "gears", "method": "ratio u1H", "x": p, "precision_mm": p, "ring_mm": ring,
                   "setting": f"u1H, r3 = {ring:g} mm, precision={p:g} mm", "time_s": t / len(TRAINS),
                   "max_error_pct": worst, "bound_pct": bound}
    # where the method fails
    cases = [("sa → 0: z = 12, 30; x = 1.05, 0.3", lambda: _pair(Pair((12, 30), 0.004, (1.05, 0.3)))),
             ("z = 8, 30; x = 0, 0", lambda: _pair(Pair((8, 30), 0.004, (0.0, 0.0)))),
             ("u1H = 1.3, B", lambda: _train(Train("B", 3, 0.003, 100.0, ratio=1.3))),
             ("u1H = 40, B", lambda: _train(Train("B", 3, 0.003, 100.0, ratio=40.0)))]
    for label, fn in cases:
        t0 = time.perf_counter()
        try:
            out = fn()
        except GraphplanError as exc:
            yield {"section": "gears", "method": "failure", "x": 0.5, "setting": label, "status": "refused",
                   "time_s": time.perf_counter() - t0, "max_error_pct": None, "message": exc.line()}
            continue
        yield {"section": "gears", "method": "failure", "x": 0.5, "setting": label,
               "status": "warning" if out["warnings"] else "ok", "time_s": time.perf_counter() - t0, **out}


def _pair(pair) -> dict:
    from graphplan.exact.gears import solve_pair
    from graphplan.graphic.gears import construct_mesh
    sol = solve_pair(pair)
    m = construct_mesh(sol, 0.5)
    errs = [100.0 * abs(m.sa[k] - sol.sa[k]) / sol.sa[k] for k in (0, 1)]
    return {"max_error_pct": max(errs + [100.0 * abs(m.eps - sol.eps) / sol.eps]),
            "sa_error_pct": errs, "eps_error_pct": 100.0 * (m.eps - sol.eps) / sol.eps,
            "warnings": [en for en, _ in sol.warnings + m.warnings]}


def _train(train) -> dict:
    from graphplan.exact.gears import solve_train
    from graphplan.graphic.gears import construct_train
    tr = solve_train(train)
    v = construct_train(tr, 0.5)
    return {"max_error_pct": 100.0 * abs(v.ratio - tr.ratio) / tr.ratio, "carrier_segment_mm": v.segments["H"],
            "warnings": [en for en, _ in tr.warnings] + ([f"the carrier's segment is {v.segments['H']:g} mm"]
                                                          if abs(v.segments["H"]) < 10 else [])}


def chart(rows: list[Row], plt):
    """|εα error| and |u1H error| against the precision, per drawn module and per sun segment, with
    the stated bounds dashed."""
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for ax, method, key, title in ((axes[0], "contact ratio", "module_mm", "εα error, % (module drawn, mm)"),
                                   (axes[1], "ratio u1H", "ring_mm", "u1H error, % (ring's radius drawn, mm)")):
        sel = [r for r in rows if r["method"] == method and r["x"] > 0]
        for v in sorted({r[key] for r in sel}):
            pts = [r for r in sel if r[key] == v]
            line, = ax.plot([r["x"] for r in pts], [max(r["max_error_pct"], 1e-12) for r in pts], marker="o",
                            label=f"{v:g}")
            ax.plot([r["x"] for r in pts], [r["bound_pct"] for r in pts], ls="--", color=line.get_color())
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("drafting precision, mm")
        ax.set_title(title)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    fig.tight_layout()
    return fig
