"""`graphplan bench`: speed against accuracy and stability toward failure."""
from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path


def cmd_bench(args: argparse.Namespace) -> int:
    from graphplan.bench.run import run, summary
    out = Path(args.out)
    t0 = time.perf_counter()
    rows = run(out, args.quick)
    sys.stdout.write(summary(rows) + f"\n{len(rows)} rows in {time.perf_counter() - t0:.1f} s → "
                     f"{out / 'bench.json'}\n")
    return 0


def register(sub) -> None:
    p = sub.add_parser("bench", help="speed–accuracy–stability study: DIR/bench.json plus charts",
                       description="Times and errors of the analytic solver, the graphical plans and the "
                                   "chord diagrams; sweeps toward the mechanisms' failures.")
    p.add_argument("-o", "--out", default="bench", metavar="DIR", help="output folder (default: bench)")
    p.add_argument("--quick", action="store_true", help="a short run (under a minute)")
    p.set_defaults(handler=cmd_bench)
