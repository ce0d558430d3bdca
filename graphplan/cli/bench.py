"""`graphplan bench`: speed against accuracy and stability toward failure."""
from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

from graphplan.cli.common import lang_arg, lang_of


def cmd_bench(args: argparse.Namespace) -> int:
    from graphplan.bench.run import run, summary
    out = Path(args.out)
    lang = lang_of(args)
    t0 = time.perf_counter()
    rows = run(out, args.quick, sections=args.section, lang=lang)
    from graphplan.util.words import fixed, word
    sys.stdout.write(summary(rows, lang) + "\n" + word("rows in", lang, n=len(rows), t=fixed(time.perf_counter() - t0, lang),
                                                       path=out / "bench.json") + "\n")
    return 0


def register(sub) -> None:
    p = sub.add_parser("bench")
    p.add_argument("-o", "--out", default="bench", metavar="DIR")
    p.add_argument("--quick", action="store_true")
    p.add_argument("--section", action="append", metavar="NAME")
    lang_arg(p)
    p.set_defaults(handler=cmd_bench)
