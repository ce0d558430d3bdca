"""Whole commands as a user runs them: each a fresh Python process, timed from the outside against
the bare import of numpy, shapely and svgwrite run in turn with it (a pair at a time, so a drift of
the machine's speed cancels out), with the command's peak memory — `graphplan bench --section
processes`, the figures docs/benchmarks.md quotes."""
from __future__ import annotations

import os
import statistics
import subprocess
import sys
import tempfile
import time
from collections.abc import Iterator
from pathlib import Path
from typing import Any

from graphplan.bench.examples import examples_dir

Row = dict[str, Any]
BARE = "import numpy, shapely, svgwrite"


def commands(folder: Path) -> list[tuple[str, list[str]]]:
    """The measured commands: the sheets, a set, the terminal's plans, diagrams and forces, the
    explorer — what a student runs."""
    ex = examples_dir()
    g = [sys.executable, "-m", "graphplan"]
    out = str(folder / "x.svg")
    return [
        ("sheet shaper A1", g + ["sheet", str(ex / "shaper.toml"), "-o", out]),
        ("sheet shaper forces A1", g + ["sheet", str(ex / "shaper.toml"), "--sheet", "forces", "-o", out]),
        ("sheet shaper dynamics A1", g + ["sheet", str(ex / "shaper.toml"), "--sheet", "dynamics", "-o", out]),
        ("sheet lab A3 set", g + ["sheet", str(ex / "lab_crank_slider.toml"), "--format", "A3", "-o", out]),
        ("plans shaper", g + ["plans", str(ex / "shaper.toml")]),
        ("diagrams shaper", g + ["diagrams", str(ex / "shaper.toml")]),
        ("forces shaper", g + ["forces", str(ex / "shaper.toml")]),
        ("view shaper", g + ["view", str(ex / "shaper.toml"), "-o", str(folder / "x.html")]),
    ]


def _run(argv: list[str]) -> tuple[float, float]:
    """One run: wall seconds and the process's peak memory (MB, ru_maxrss)."""
    t0 = time.perf_counter()
    p = subprocess.Popen(argv, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, status, usage = os.wait4(p.pid, 0)
    wall = time.perf_counter() - t0
    p.returncode = os.waitstatus_to_exitcode(status)
    if p.returncode != 0:
        raise RuntimeError(f"{' '.join(argv)} ended with {p.returncode}")
    return wall, usage.ru_maxrss / 1024.0


def measure(argv: list[str], runs: int) -> dict[str, float]:
    """The command and the bare import in turn, ``runs`` pairs after a warm-up of each: the medians
    of the command's wall time, of its ratio to the bare import's (pair by pair) and of its peak
    memory."""
    bare = [sys.executable, "-c", BARE]
    _run(bare)
    _run(argv)
    times, ratios, peaks, bares = [], [], [], []
    for _ in range(runs):
        b, _ = _run(bare)
        t, mb = _run(argv)
        times.append(t)
        bares.append(b)
        ratios.append(t / b)
        peaks.append(mb)
    return {"time_s": statistics.median(times), "bare_s": statistics.median(bares),
            "ratio": statistics.median(ratios), "ratio_max": max(ratios), "peak_mb": statistics.median(peaks)}


def compiled() -> None:
    """The package's bytecode written, as ``pip install`` writes it for a regular install (an
    editable checkout run with PYTHONDONTWRITEBYTECODE=1, as this machine's shells are, would
    otherwise compile every module of graphplan on every run: 0.05–0.1 s a command)."""
    import compileall

    import graphplan
    compileall.compile_dir(str(Path(graphplan.__file__).parent), quiet=1)


def rows(quick: bool) -> Iterator[Row]:
    """A row per command: medians over 3 pairs (quick) or 7, the package's bytecode compiled."""
    compiled()
    with tempfile.TemporaryDirectory() as tmp:
        for name, argv in commands(Path(tmp)):
            m = measure(argv, 3 if quick else 7)
            yield {"section": "processes", "method": name, "x": 1, "setting": "whole process",
                   "max_error_pct": None, "note": f"× {m['ratio']:.1f} bare import, {m['peak_mb']:.0f} MB", **m}


def markdown_table(rows_: list[Row]) -> str:
    """The rows as docs/benchmarks.md shows them."""
    lines = ["| command | wall, s (median) | bare import, s | × bare import (median, max) | peak memory, MB |",
             "|---|---|---|---|---|"]
    for r in rows_:
        if r.get("section") == "processes":
            lines.append(f"| `{r['method']}` | {r['time_s']:.2f} | {r['bare_s']:.3f} | "
                         f"{r['ratio']:.1f} ({r['ratio_max']:.1f}) | {r['peak_mb']:.0f} |")
    return "\n".join(lines) + "\n"


def main() -> None:
    sys.stdout.write(markdown_table(list(rows(quick="--quick" in sys.argv))))


if __name__ == "__main__":
    main()
