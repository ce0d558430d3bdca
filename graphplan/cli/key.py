"""`graphplan key VARIANTS -o DIR` and `graphplan check KEY STUDENT.csv`: teachers' keys and grading.

Per variant DIR/<id>/ gets key.json (everything, with the resolved scene), key.csv (the long format a
student fills in, with the exact values), key.svg and key.pdf (the A4 key sheet); the group gets
DIR/summary.json, summary.csv, summary.txt and summary.svg/.pdf. Every file is written whole or not
at all; the same input gives the same bytes.
"""
from __future__ import annotations

import argparse
import os
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Any, TextIO

from graphplan.cli.common import lang_arg, lang_of, option_error
from graphplan.util.markup import escape, plain
from graphplan.util.progress import Progress
from graphplan.util.errors import GraphplanError, said_error, speaking
from graphplan.util.words import word
from graphplan.util.files import write_atomic

SUMMARY_FORMAT = "graphplan-keys/1"


def pdf_bytes(pages, size: tuple[float, float], title: str) -> bytes:
    """Key or summary sheets (construction records) as one PDF, drawn straight on a cairo surface
    (drawing.pdf: the font embedded, fixed metadata)."""
    from graphplan.drawing.pdf import render_pdf
    return render_pdf(pages, *size, title=title)


def _parse_tol(items: list[str], tolerance: float | None) -> dict[str, float]:
    out: dict[str, float] = {}
    for item in items:
        name, sep, value = item.partition("=")
        try:
            pct = float(value)
        except ValueError:
            pct = -1.0
        if not sep or not name.strip() or not 0 < pct <= 100:
            raise option_error("--tol", "op tol", item=repr(item))
        out[name.strip()] = pct
    if tolerance is not None:
        if not 0 < tolerance <= 100:
            raise option_error("--tolerance", "op tolerance", got=float(tolerance))
        out["*"] = tolerance
    return out


def write_key(folder: Path, key: dict[str, Any], pdf: bool = True, lang: str = "uk") -> list[Path]:
    """The variant's files: key.json, key.csv, key.svg and key.pdf."""
    from graphplan.cli.main import dumps
    from graphplan.teach.keys import key_csv
    from graphplan.teach.keysheet import A4_PORTRAIT, key_sheet
    from graphplan.drawing.svg import render
    if key.get("kind") == "cam":
        from graphplan.teach.camkeys import key_sheet
    if key.get("kind") == "gears":
        from graphplan.teach.gearkeys import key_sheet
    sheet = key_sheet(key, lang)
    svg = render(sheet, *A4_PORTRAIT, title=plain(sheet.title))
    files = [write_atomic(folder / "key.json", dumps(key)),
             write_atomic(folder / "key.csv", key_csv(key)),
             write_atomic(folder / "key.svg", svg)]
    if pdf:
        files.append(write_atomic(folder / "key.pdf", pdf_bytes([sheet], A4_PORTRAIT, plain(sheet.title))))
    return files


def summary_columns(rows: list[dict[str, Any]]) -> list[str]:
    """The union of the rows' keys, first seen first, without columns empty in every row; the note last."""
    cols: list[str] = []
    for r in rows:
        cols += [c for c in r if c not in cols and c != "note"]
    cols = [c for c in cols if any(r.get(c) not in (None, "") for r in rows)]
    if any("note" in r for r in rows):
        cols.append("note")
    return cols


def summary_csv(columns: list[str], rows: list[dict[str, Any]]) -> str:
    import csv
    import io
    buf = io.StringIO()
    writer = csv.writer(buf, lineterminator="\n")
    writer.writerow(columns)
    for r in rows:
        writer.writerow([_csv_value(r.get(c)) for c in columns])
    return buf.getvalue()


def _csv_value(v: Any) -> str:
    from graphplan.teach.keys import fmt
    if v is None:
        return ""
    if isinstance(v, float):
        return fmt(v, 10)
    return str(v)


def summary_text(title: str, columns: list[str], rows: list[dict[str, Any]], units: dict[str, str],
                 overrides: set[str] = frozenset(), lang: str = "uk") -> str:
    """The summary as a fixed-width table for printing (the variants' data as given), in ``lang``."""
    from graphplan.teach.keysheet import cell, display, unit_text
    from graphplan.util.markup import plain
    table_cols = [c for c in columns if c != "note"]
    cells = [[cell(r.get(c), c in overrides, lang) for c in table_cols] for r in rows]
    head = [plain(display(c, lang)) for c in table_cols]
    unit_row = [unit_text(units.get(c, ""), lang) for c in table_cols]
    widths = [max(len(x) for x in col) for col in zip(head, unit_row, *cells)]
    left = {i for i, c in enumerate(table_cols) if c in ("variant", "student", "status")}
    lines = [title, ""]
    for r in [head, unit_row] + cells:
        lines.append("  ".join(x.ljust(w) if i in left else x.rjust(w)
                               for i, (x, w) in enumerate(zip(r, widths))).rstrip())
    from graphplan.teach.keysheet import summary_note
    from graphplan.util.words import word
    if "phi0_deg" in columns:            # the lever mechanisms' columns explained (not a cam's)
        lines += ["", plain(summary_note(lang))]
    notes = [r for r in rows if r.get("note")]
    if notes:
        lines.append("")
        lines += [word("variant note", lang, v=r["variant"], note=r["note"]) for r in notes]
    return "\n".join(lines) + "\n"


@dataclass(frozen=True)
class KeyOptions:
    """What every variant's job needs besides its row."""
    out: Path
    tolerances: dict[str, float]
    divisions: int | None
    pdf: bool
    lang: str = "uk"


_JOB: dict[str, Any] = {}


def _init_job(table, options: KeyOptions, parent: int | None = None) -> None:
    _JOB["table"], _JOB["options"] = table, options
    if parent is not None:
        import signal
        # a worker ends at once on the pool's SIGTERM: the command's SystemExit handler, inherited by
        # the fork, once left an idle worker blocked on the task queue's lock while the pool waited
        # for it forever (files are written whole or as a stray .part, never half)
        signal.signal(signal.SIGTERM, signal.SIG_DFL)
        _die_with(parent)


def _die_with(parent: int) -> None:
    """A worker ends when the command ends, even by SIGKILL: Linux's PR_SET_PDEATHSIG sends the
    worker SIGKILL when its parent dies (a pool's workers otherwise wait for work forever)."""
    import signal
    try:
        import ctypes
        libc = ctypes.CDLL(None, use_errno=True)
        libc.prctl(1, int(signal.SIGKILL), 0, 0, 0)          # PR_SET_PDEATHSIG = 1
    except (OSError, AttributeError):                         # not Linux: the pool's own cleanup
        pass
    if os.getppid() != parent:                                # the parent died before prctl
        os._exit(1)


def _variant_job(index: int) -> dict[str, Any]:
    """Build, key and write one variant (in a worker process or inline). Returns its summary."""
    from graphplan.model import variants as vt
    from graphplan.teach.keys import make_key, summary_row, summary_units
    from graphplan.exact.positions import study
    from graphplan.model.scene import build
    table, opt = _JOB["table"], _JOB["options"]
    v = table.variants[index]
    from graphplan.model.cam import is_cam
    try:
        tree = vt.scene_tree(table, v)
        from graphplan.model.gears import is_gears
        if is_gears(tree) and "cam" not in tree:     # a gear variant: its own key (teach/gearkeys.py)
            from graphplan.exact.gears import solve as solve_gears
            from graphplan.model.gears import build as build_gears
            from graphplan.teach import gearkeys
            key = gearkeys.make_gear_key(solve_gears(build_gears(tree, v.where(table.path))), variant=v.id,
                                         student=v.student, base=v.base.name, overrides=v.overrides, scene=tree,
                                         tolerances=[v.tolerances, opt.tolerances, table.tolerances])
            summary_row, summary_units = gearkeys.summary_row, gearkeys.summary_units
        elif is_cam(tree):                  # a cam variant: its own key (teach/camkeys.py)
            from graphplan.exact.cam import solve
            from graphplan.model.cam import build as build_cam
            from graphplan.teach import camkeys
            key = camkeys.make_cam_key(solve(build_cam(tree, v.where(table.path))), variant=v.id,
                                       student=v.student, base=v.base.name, overrides=v.overrides, scene=tree,
                                       divisions=v.divisions or opt.divisions,
                                       tolerances=[v.tolerances, opt.tolerances, table.tolerances])
            summary_row, summary_units = camkeys.summary_row, camkeys.summary_units
        else:
            st = study(build(tree, v.where(table.path)))
            key = make_key(st, variant=v.id, student=v.student, base=v.base.name, overrides=v.overrides,
                           scene=tree, divisions=v.divisions or opt.divisions,
                           tolerances=[v.tolerances, opt.tolerances, table.tolerances])
    except GraphplanError as exc:
        said_note = _note(exc, v.where(table.path), opt.lang)     # in the run's language, as the rows'
        where = v.where(table.path)
        return {"entry": {"variant": v.id, "status": "skipped", "key": None, "note": said_note}, "units": {},
                "row": {"variant": v.id, "student": v.student, "status": "skipped", **v.overrides, "note": said_note},
                "message": "graphplan: " + word("ky skipped", opt.lang, where=where.said.get(opt.lang, where)
                                                if hasattr(where, "said") else where, note=said_note)}
    write_key(opt.out / v.id, key, pdf=opt.pdf, lang=opt.lang)
    return {"entry": {"variant": v.id, "status": "ok", "key": f"{v.id}/key.json", "note": ""},
            "row": summary_row(key), "units": summary_units(key), "message": None}


def _note(exc: GraphplanError, where: str, lang: str) -> str:
    """Why a variant was skipped, in ``lang``, without its place (the variant) in front."""
    note = exc.line(lang)
    for prefix in {where, *getattr(where, "said", {}).values()}:
        if note.startswith(prefix):
            return note[len(prefix):].lstrip(": ")
    return note


def run_jobs(table, options: KeyOptions, jobs: int, progress: Progress) -> list[dict[str, Any]]:
    """Every variant's job, in the table's order; ``jobs`` > 1 spreads them over processes
    (the files do not depend on it: each variant's are its own)."""
    n = len(table.variants)
    results = []
    if jobs <= 1 or n <= 1:
        _init_job(table, options)
        for k in range(n):
            progress.step(f"{word('variant', options.lang)} {table.variants[k].id}")
            results.append(_variant_job(k))
            _report(results[-1], progress)
        return results
    import multiprocessing
    method = "fork" if "fork" in multiprocessing.get_all_start_methods() else "spawn"
    if method == "fork":
        _preload(options.pdf)
    # a Pool is terminated when the block ends, by an error or a signal too (SIGTERM becomes
    # SystemExit in cmd_key): no worker outlives the command
    previous = _terminate_cleanly()
    try:
        with multiprocessing.get_context(method).Pool(jobs, initializer=_init_job,
                                                      initargs=(table, options, os.getpid())) as pool:
            progress.step(f"{word('variant', options.lang)} {table.variants[0].id}")
            for k, result in enumerate(pool.imap(_variant_job, range(n), chunksize=1 if n < 64 else 4)):
                results.append(result)
                _report(result, progress)
                if k + 1 < n:
                    progress.step(f"{word('variant', options.lang)} {table.variants[k + 1].id}")
    finally:
        if previous is not None:
            import signal
            signal.signal(signal.SIGTERM, previous)
    return results


def _preload(pdf: bool) -> None:
    """Import what every variant's job uses once, before the workers fork (they share it instead of
    each importing numpy, the solver, the sheet and cairo again; the summary needs them here too)."""
    import graphplan.exact.positions  # noqa: F401
    import graphplan.model.scene  # noqa: F401
    import graphplan.teach.keys  # noqa: F401
    import graphplan.teach.keysheet  # noqa: F401
    import graphplan.drawing.svg  # noqa: F401
    if pdf:
        from graphplan.drawing.pdf import preload
        preload()


def _report(result: dict[str, Any], progress: Progress) -> None:
    progress.advance()


def cmd_key(args: argparse.Namespace) -> int:
    from graphplan.model import variants as vt
    from graphplan.cli.main import dumps

    table = vt.read(args.variants)
    vt.check_columns(table)
    cli_tol = _parse_tol(args.tol, args.tolerance)
    if args.divisions is not None and not 2 <= args.divisions <= 720:
        raise option_error("--divisions", "op whole", lo=2, hi=720, got=args.divisions)
    if args.jobs is not None and args.jobs < 1:
        raise option_error("--jobs", "op at least", lo=1, got=args.jobs)
    out = Path(args.output)
    if out.exists() and not out.is_dir():
        raise said_error(GraphplanError, "op output folder", str(out), None)
    jobs = args.jobs or min(os.cpu_count() or 1, 8, len(table.variants))
    progress = Progress(len(table.variants), enabled=not args.quiet and sys.stderr.isatty())
    lang = lang_of(args) if args.lang else _table_lang(table)
    final, out = out, staging(out)
    try:
        results = run_jobs(table, KeyOptions(out, cli_tol, args.divisions, not args.no_pdf, lang), jobs, progress)
        progress.close()
        text, doc = _summary(args, table, results, out, lang)
    except BaseException:
        import shutil
        if not isinstance(sys.exc_info()[1], (KeyboardInterrupt, SystemExit)):
            shutil.rmtree(out, ignore_errors=True)      # an error: nothing written, nothing left
        raise                                           # a kill leaves the hidden staging folder only
    publish(out, final)
    sys.stdout.write(dumps(doc) if args.json else text)
    return 0


def staging(out: Path) -> Path:
    """The hidden folder beside the target where a run writes (``.keys.part`` for ``keys``): a key set
    appears under its name only when whole — a run killed midway leaves this folder, never a
    half-made set under the target's name; the next run starts it afresh."""
    import shutil
    tmp = out.parent / f".{out.name}.part"
    shutil.rmtree(tmp, ignore_errors=True)
    tmp.mkdir(parents=True)
    return tmp


def publish(tmp: Path, out: Path) -> None:
    """The finished set under the target's name: renamed there when the target is new; into an
    existing folder each variant's folder and the summary files replace theirs (other files stay),
    the summary last."""
    import shutil
    if not out.exists():
        os.replace(tmp, out)
        return
    items = sorted(tmp.iterdir(), key=lambda p: (p.name.startswith("summary"), p.name))
    for old in out.glob("summary-*.svg"):            # a longer summary's pages from an earlier run
        if old.stem.removeprefix("summary-").isdigit() and not (tmp / old.name).exists():
            old.unlink()
    for item in items:
        target = out / item.name
        if target.is_dir() and not target.is_symlink():
            shutil.rmtree(target)
        os.replace(item, target)
    tmp.rmdir()


def _summary(args, table, results, out: Path, lang: str) -> tuple[str, dict]:
    """The summary files of a finished run (in ``out``), and the text and document printed."""
    from graphplan.cli.main import dumps
    from graphplan.teach.keysheet import A4_LANDSCAPE, summary_pages
    from graphplan.drawing.svg import render
    entries = [r["entry"] for r in results]
    skipped = [r["message"] for r in results if r["message"]]
    if skipped and not any(e["status"] == "ok" for e in entries):
        from graphplan.util.words import word as said_word
        more = (lambda lang: said_word("ky more", lang, n=len(skipped) - 1)) if len(skipped) > 1 else ""
        raise said_error(GraphplanError, "ky none built", None, lang, first=skipped[0].removeprefix("graphplan: "),
                         more=more)
    for line in skipped:                  # written keys and skipped variants: a line for each skip
        print(line, file=sys.stderr)
    rows = [r["row"] for r in results]
    written = sum(e["status"] == "ok" for e in entries)
    from graphplan.util.words import word
    title = (word("keys title", lang, table=table.path.name, n=len(entries), written=written)
             + (word("keys skipped", lang, k=len(entries) - written) if written < len(entries) else ""))
    columns = summary_columns(rows)
    units: dict[str, str] = {}
    for r in results:
        units.update({c: u for c, u in r["units"].items() if c in columns and c not in units})
    doc = {"format": SUMMARY_FORMAT, "table": table.path.name, "variants": entries,
           "columns": columns, "units": units, "rows": rows}
    text = summary_text(title, columns, rows, units, overrides=_override_columns(table), lang=lang)
    if written:
        write_atomic(out / "summary.json", dumps(doc))
        write_atomic(out / "summary.csv", summary_csv(columns, rows))
        write_atomic(out / "summary.txt", text)
        pages = summary_pages(escape(title), [c for c in columns if c != "note"], rows, units,
                              _override_columns(table), lang)
        for n, page in enumerate(pages, 1):          # summary.svg, summary-2.svg … (as a sheet set)
            write_atomic(out / ("summary.svg" if n == 1 else f"summary-{n}.svg"),
                         render(page, *A4_LANDSCAPE, title=plain(page.title)))
        if not args.no_pdf:                          # every page in one PDF, to print
            write_atomic(out / "summary.pdf", pdf_bytes(pages, A4_LANDSCAPE, title))
    return text, doc


def _terminate_cleanly():
    """While the pool works, SIGTERM ends `key` like an error (SystemExit): the pool is terminated,
    files written so far are whole (util.files.write_atomic), the summary is not written. Returns
    the handler to restore (None off the main thread, where signals cannot be handled)."""
    import signal
    import threading
    if threading.current_thread() is not threading.main_thread():
        return None
    return signal.signal(signal.SIGTERM, lambda signum, frame: sys.exit(128 + signum))


def _override_columns(table) -> set[str]:
    return {c for v in table.variants for c in v.overrides}


def cmd_check(args: argparse.Namespace) -> int:
    from graphplan.teach.grading import grade, load_keys, read_student, write_json, write_table
    keys = load_keys(args.key)
    try:
        rows = read_student(args.student)
    except GraphplanError as exc:                 # without --lang: the keys' scenes' language
        raise speaking(exc, keys_lang(keys)) from None
    graded = grade(keys, rows, signed=args.signed)
    if args.json:
        write_json(sys.stdout, graded, args.key, args.student, args.signed)
    else:
        from graphplan.util.words import pick
        write_table(sys.stdout, graded, args.key, args.student, pick(args.lang, keys_lang(keys)))
    return 0


def _table_lang(table) -> str:
    """The language of a run without --lang: its first variant's base scene's ``lang``, else Ukrainian."""
    from graphplan.util.words import pick
    lang = table.base_tree(table.variants[0].base).get("lang") if table.variants else None
    return pick(None, lang if lang in ("uk", "en") else None)


def keys_lang(keys: dict[str, dict[str, Any]]) -> str | None:
    """The ``lang`` of the keys' scenes, where they agree on one."""
    langs = {k.get("scene", {}).get("lang") for k in keys.values() if isinstance(k.get("scene"), dict)}
    return langs.pop() if len(langs) == 1 and langs <= {"uk", "en"} else None


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("key")
    p.add_argument("variants")
    p.add_argument("-o", "--output", required=True, metavar="DIR")
    p.add_argument("--tolerance", type=float, metavar="PCT")
    p.add_argument("--tol", action="append", default=[], metavar="QUANTITY=PCT")
    p.add_argument("--divisions", type=int, metavar="N")
    p.add_argument("--no-pdf", action="store_true")
    p.add_argument("--jobs", type=int, metavar="N")
    p.add_argument("--quiet", action="store_true")
    p.add_argument("--json", action="store_true")
    lang_arg(p)
    p.set_defaults(handler=cmd_key)

    c = sub.add_parser("check")
    c.add_argument("key")
    c.add_argument("student")
    c.add_argument("--json", action="store_true")
    lang_arg(c)
    c.add_argument("--signed", action="store_true")
    c.set_defaults(handler=cmd_check)
