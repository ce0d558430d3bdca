"""Shared helpers: the examples, a scene builder and finite differences of exact positions."""
from __future__ import annotations

import functools
import math
import os
import sys
from pathlib import Path

import numpy as np
import pytest

from graphplan.exact.positions import study
from graphplan.model.scene import load, loads

# The packaged fonts registered with fontconfig before any test renders: cairo keeps, for the life of a
# process, the face it first matched to a family, so a test that rasterised an SVG lettered "osifont"
# with cairosvg before anything had registered the font left the worker's later PDFs and PNGs in the
# fallback (DejaVu): stop 55's CI, 8 PDF/PNG tests failing by the order xdist dealt them. A browser
# loads the sheet's font before it draws; so do the tests.
from graphplan.drawing.fonts import register as _register_fonts  # noqa: E402

_register_fonts()

ROOT = Path(__file__).resolve().parent.parent

# Property tests draw the same examples on every run (CI: a green main stays green; a failure is
# reproducible); HYPOTHESIS_PROFILE=explore draws new ones each run (hypothesis's default) to search.
from hypothesis import settings  # noqa: E402

settings.register_profile("ci", derandomize=True, database=None)
settings.register_profile("explore")
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "ci"))


# The test modules' rewritten code kept between runs (pytest's assertion rewriting writes it to
# tests/__pycache__ unless bytecode is not to be written): where PYTHONDONTWRITEBYTECODE is set (as on
# CI's machine) every worker of every run rewrote all the modules' asserts afresh — 62 % of collecting
# (7–8 s of CPU a worker). Written while the modules are collected; the setting is back after.
_DONT_WRITE_BYTECODE = sys.dont_write_bytecode
sys.dont_write_bytecode = False


def pytest_collection_finish(session):
    sys.dont_write_bytecode = _DONT_WRITE_BYTECODE


def pytest_collection(session):
    """On a fresh checkout (CI's: no tests/__pycache__) every xdist worker rewrote the asserts of all
    the test modules as it collected them, the two at once — 14 s of CPU a worker against 5.5 s with
    the rewritten modules cached. Worker k of n now first imports the modules from the k-th n-th of
    the list on, wrapping round, while worker 0 collects in the list's order: each rewrites (and
    caches) its share and reads back the others'. A module is imported once either way, and what is
    collected is the same; a run of named files, or without workers, is left as it was."""
    worker, count = os.environ.get("PYTEST_XDIST_WORKER", ""), int(os.environ.get("PYTEST_XDIST_WORKER_COUNT", "1"))
    here = Path(__file__).resolve().parent
    if not worker.startswith("gw") or worker == "gw0" or count < 2 or str(here) not in sys.path:
        return
    start = session.config.invocation_params.dir
    args = [(start / a.split("::")[0]).resolve() for a in session.config.args]
    if not args or not all(a.is_dir() and (a == here or a in here.parents) for a in args):
        return
    import importlib
    names = sorted(p.name for p in here.glob("test_*.py"))
    first = int(worker[2:]) * len(names) // count
    for name in names[first:] + names[:first]:
        try:
            importlib.import_module(name[:-3])
        except (KeyboardInterrupt, SystemExit):
            raise
        except BaseException:       # noqa: BLE001 — collecting imports it again and reports it
            continue


def pytest_configure(config):
    """Tests and benchmarks run with the allocator as the program sets it (graphplan.util.memory),
    and keep the sets' sheet counts (sheets/sheet.py ``pages_of``) in a folder of this run only —
    shared by its workers (they inherit the variable), never a count of an earlier run."""
    from graphplan.util.memory import keep_freed_memory
    keep_freed_memory()
    # the cyclic collector less often, as the program runs it (util.memory): the workers keep the
    # examples' sheets (``example_sheet``) and the placements (drawing.labels), which the default
    # thresholds walk again and again — ~5 % of a sheet test's CPU (test_sheet_content: 1.9 s of 34 s of
    # collecting, 0.4 s so)
    from graphplan.util.memory import collect_less_often
    collect_less_often()
    if not hasattr(config, "workerinput"):
        # the package byte-compiled once, before the workers start: where PYTHONDONTWRITEBYTECODE is set
        # (as on CI's machine) every worker and every command the tests run would otherwise compile it
        # afresh (about 0.5 s of CPU a process); compileall writes the .pyc files regardless
        import compileall
        import graphplan
        compileall.compile_dir(os.path.dirname(graphplan.__file__), quiet=1)
    if "GRAPHPLAN_CACHE" not in os.environ:
        import atexit
        import shutil
        import tempfile
        folder = tempfile.mkdtemp(prefix="graphplan-test-cache-")
        os.environ["GRAPHPLAN_CACHE"] = folder
        atexit.register(shutil.rmtree, folder, True)
    if not hasattr(config, "workerinput"):
        # the examples' sheets shared by the workers of this run (``_shared``): a folder of this run only
        import atexit
        import shutil
        import tempfile
        folder = tempfile.mkdtemp(prefix="graphplan-test-sheets-")
        os.environ[SHARED_SHEETS] = folder
        atexit.register(shutil.rmtree, folder, True)


# Each test's CPU time, where ``GRAPHPLAN_TEST_CPU`` names a file: a line per phase (node id, phase,
# the process's CPU seconds, the worker's pid) appended to it. ``--durations`` gives wall time, which
# on a shared machine is mostly waiting (stop 54: 2 cores, load 15–17; a 7 s composition read 60 s);
# CPU time ranks the suite's costs the same under any load. Sum by file:
#   awk -F'\t' 'NF==4 && $2!="children" {split($1,a,"::"); s[a[1]]+=$3} END {for (k in s) print s[k], k}' FILE | sort -gr
# (and the commands' own CPU, phase "children", with $2=="children")
CPU_LOG = os.environ.get("GRAPHPLAN_TEST_CPU")

import time as _time  # noqa: E402

if CPU_LOG:

    import resource as _resource

    def _children_cpu() -> float:
        got = _resource.getrusage(_resource.RUSAGE_CHILDREN)
        return got.ru_utime + got.ru_stime

    def _cpu_logged(phase: str):
        # … and, on a line of its own (phase "children": costly.py reads only setup, call and teardown),
        # the CPU of the commands, servers and browsers the phase ran and waited for — the two cores'
        # other load, which the worker's own clock does not see
        @pytest.hookimpl(hookwrapper=True)
        def hook(item):
            t, c = _time.process_time(), _children_cpu()
            yield
            with open(CPU_LOG, "a", encoding="utf-8") as out:
                out.write(f"{item.nodeid}\t{phase}\t{_time.process_time() - t:.3f}\t{os.getpid()}\n")
                if _children_cpu() - c >= 0.001:
                    out.write(f"{item.nodeid}\tchildren\t{_children_cpu() - c:.3f}\t{os.getpid()}\n")
        return hook

    pytest_runtest_setup = _cpu_logged("setup")
    pytest_runtest_call = _cpu_logged("call")
    pytest_runtest_teardown = _cpu_logged("teardown")


# Parametrized tests whose every case runs in the slow suite while the default run keeps the first
# few — each case checks the same behaviour on another example or format, the first ones exercise it
# (the default suite stays within 3 minutes on two cores): test → how many cases the default keeps,
# or which (a predicate on the case's id).
THINNED = {
    "test_gallery_sheet_is_current": lambda case: not any(f in case for f in ("-A2", "-A3")),   # sets: slow
    "test_no_word_on_a_gallery_sheet_is_overprinted": 1,
    "test_gallery_sets_are_composed_cleanly": 2,
    "test_the_page_replays_every_plan_in_textbook_order": 1,
    "test_kinematics_tables_numbered_in_reading_order": 3,
    "test_position_plan_letters_and_numbers": 2,
    "test_a_sets_diagrams_are_drawn_readably_high": 1,
    "test_sheet_is_a1_in_mm_with_layers": 2,
    "test_killed_sheet_leaves_no_partial_file": 1,
    "test_no_sheet_of_a_set_holds_only_the_notes": 0,
    "test_the_cam_in_the_explorer": 1,
    "test_new_mechanisms_print_no_word_over_another": 1,
    "test_the_page_reads_well_at_every_width": 1,
    "test_a_few_cams_end_with_an_answer_or_one_line": 1,
    "test_a_set_holds_a_drawing_or_a_table_on_every_sheet_the_tables_whole_and_in_order": 1,
    "test_notes_largest_error_is_the_tables": 1,
    "test_lettering_reads_as_words_wherever_it_stands": 1,
    "test_forces_json_contract": 1,
    "test_a_force_sheet_keeps_every_element_in_its_field": 0,      # 4–15 s each (the shaper's in test_sheet)
    "test_every_force_on_a_group_is_named_from_its_source_to_the_group": 1,
    "test_the_cam_page_is_one_offline_deterministic_file": 0,
    # stop 44 (the default run 199 s > 180 s): the press's module fixture (7.5 s; review 4's rule is
    # also checked in the default run on three scenes by test_the_one_sheet_composition_never_…),
    # an A2 set's tables, the gear A3 set's fixture, the slotter's generated force sheet
    "test_the_press_forces_letters_stand_at_their_own_arrows": 0,
    "test_a_group_freed_from_the_frame_keeps_no_guide": 0,
    "test_the_press_groups_at_least_at_the_schemes_scale": 0,
    "test_an_a2_set_puts_its_tables_in_a_column_by_the_title_block": 0,
    "test_the_task_data_are_printed_as_the_scene_gives_them": lambda case: case != "a3",
    "test_mu_omega_times_the_measured_segment_is_table_3s_omega": lambda case: case != "a3",
    "test_the_a3_sets_train_is_drawn_at_full_size_where_its_sheet_has_room": 0,
    "test_the_force_sheet_draws_the_same_number_of_plans_at_any_count": 0,
    "test_a_tall_narrow_mechanisms_force_set_packs_its_drawings": 0,
    "test_flat_hodographs_grow_where_the_sheet_has_room": 0,
    "test_replay_pictures_for_the_docs": 0,           # the docs' screenshots (GRAPHPLAN_SHOTS)
    "test_sheets_of_random_mechanisms": 0,            # a fuzz run
    "test_forces_table_and_files": 0,                 # the slotter's forces --svg --charts (5.6 s)
    "test_every_result_displays_itself": 0,           # every API result's display (3.4 s)
    # the heaviest single checks (sets and a moment-loaded dynamics sheet, 10–42 s each): slow suite
    "test_every_format_draws_quick": 0,
    "test_the_force_sheet_draws_and_names_the_moment": 0,
    "test_a_centric_crank_slider_with_a_profile_mark_at_its_stroke": 0,
    "test_the_a3_set_reads_the_flywheel_no_worse_than_the_a1_sheet_and_fills_its_sheets": 0,
    "test_no_sheet_of_the_set_holds_only_tables_and_notes": 0,
    "test_the_shapers_a3_set_reads_the_a1_kl_or_its_notes_say_why_not": 0,
    "test_the_energy_caption_stands_apart_from_kl": 0,
    "test_the_phi_of_delta_t_stands_at_its_arrow_clear_of_the_projections": 0,
    "test_the_press_sheet_is_redrawn_and_its_rows_check": 0,
    "test_dynamics_in_english_is_headed_in_english": 0,
    "test_a2_four_bar_set_has_no_sheet_of_notes_alone": 0,
    "test_a3_set_fills_its_sheets_in_order": 0,
    "test_a1_is_one_sheet_and_a3_a_set": 0,
    "test_near_zero_ordinates_are_not_projected_across_the_moments_diagram": 0,
    "test_the_sheet_notes_say_the_method_and_the_spurious_extrema": 0,
    "test_a3_diagrams_fill_the_sheet_they_take": 0,
    "test_sheet_reports_in_its_language": 0,
    "test_plans_json_precision_zero_shaper": 0,
    "test_formats_by_suffix": 0,
    "test_cam_rocking_a3_set_keeps_the_notes_with_the_table": 0,          # 23 s: a rocking cam's A3 set
    # stop 42's merges took the default run from 163 to 205 s: the cases that repeat a behaviour another
    # case of the same test shows (a four-bar and a shaper beside the crank-slider and the slotter; the A2
    # DXF beside the A1; the rocking phase diagram, 5.7 s, beside the two translating ones): slow suite
    # (with stop 44's: the generated slotter's force sheet, 10 s, slow — a second key had dropped it;
    # stop 47: the generated slotter's kinematics sheet, 7 s, slow — the default run keeps the property
    # on a generated crank-slider's kinematics and force sheets, the slotter's kinematics is the gallery's)
    "test_sheets_of_new_mechanisms_have_no_defects": lambda case: case.endswith("crank_slider"),
    "test_dxf_is_cad_ready": 1,
    "test_ukrainian_output_of_every_command": lambda case: case.endswith("-shaper"),     # each command once
    "test_the_phase_diagram_draws_the_printed_pressure_angles": 1,
    # stop 43: the gear sets' cases past the first repeat one behaviour on another pair; the rest as named
    "test_the_set_draws_the_meshing_at_the_largest_band_scale_that_fits_its_first_sheet": 1,
    "test_a_set_carries_form_1_then_form_2a": 1,
    "test_the_terminal_reads_the_sheet_of_its_format": 1,
    "test_the_terminal_reads_the_train_off_the_set_as_grown": 1,      # the A3 set is the fixture's (cached)
    "test_the_meshing_is_the_largest_drawing_of_the_a1_sheet": 3,
    "test_the_gear_sheet_is_composed_and_clean": 1,
    "test_the_lever_is_as_large_as_its_cell_allows": 1,
    "test_shared_divisions_are_numbered_once_and_no_two_numbers_overlap": 4,
    "test_blocks_and_labels_do_not_overlap": 4,
    # stop 56: the six-bar shaper's sheets (the most scales) in both languages; the crank-slider's and the
    # four-bar's English sheets, composed and numbered for this test alone, slow
    "test_one_scale_symbol_one_value": lambda case: case == "shaper",
    # stop 61: speed60's equivalences of a fast search and the old chain of searches, on random drawings
    # (4 s of the default run): the first seeds there, every seed in the slow suite
    "test_far_with_several_checks_is_the_first_search_that_finds": 6,
    "test_a_force_letter_among_arrows_is_placed_as_the_four_searches_placed_it": 8,
}


# The tests measured costliest, left to the slow suite so that the default run keeps within the
# brief's three minutes on two cores (``tests/costly.py`` picks them from a log of each test's cost;
# every module keeps its cheapest test in the default run).
COSTLY = frozenset((Path(__file__).with_name("costly.txt")).read_text(encoding="utf-8").splitlines()) - {""}   # a line an id (ids hold spaces)


@pytest.hookimpl(tryfirst=True)
def pytest_collection_modifyitems(config, items):
    """``THINNED``: the cases past those the default run keeps are marked slow (before ``-m``);
    ``COSTLY``: the measured costliest tests are slow."""
    from collections import Counter
    seen: Counter = Counter()
    for item in items:
        if item.nodeid in COSTLY:
            item.add_marker(pytest.mark.slow)
            continue
        keep = THINNED.get(getattr(item, "originalname", item.name))
        if keep is None:
            continue
        case = item.callspec.id if hasattr(item, "callspec") else ""
        seen[item.originalname] += 1
        if (not keep(case)) if callable(keep) else seen[item.originalname] > keep:
            item.add_marker(pytest.mark.slow)
EXAMPLES = ["crank_slider", "lab_crank_slider", "four_bar", "shaper", "slotter"]


def example(name: str):
    """An example studied — a cam example (cam_*) read as its cam, what the cam sheet takes."""
    if name.startswith("cam_"):
        from graphplan.model.cam import load as load_cam
        return load_cam(ROOT / "examples" / f"{name}.toml")
    if name.startswith("gears"):            # a gear example: the gear sheet takes the scene itself
        from graphplan.model.gears import load as load_gears
        return load_gears(ROOT / "examples" / f"{name}.toml")
    return study(load(ROOT / "examples" / f"{name}.toml"))


def example_sheet(name: str, kind: str = "kinematics", fmt: str = "A1", lang: str = "uk"):
    """An example's sheet (or set) as ``BUILDERS`` makes it (numbered in its project), built once per
    worker and shared by every test module that reads it (an example's sheet costs 3–12 s of CPU and
    a dozen modules read the same ones). Read it, never change it; a test of determinism builds its
    own second copy. (The arguments passed on in full: ``example_sheet("four_bar")`` and
    ``example_sheet(name, kind, fmt, lang)`` are one sheet, one entry of the cache.)"""
    return _example_sheet(name, kind, fmt, lang)


SHARED_SHEETS = "GRAPHPLAN_TEST_SHEETS"


def _clock() -> float:
    return _time.perf_counter()


def _log_shared(tag: str, how: str, waited: float, cpu: float) -> None:
    """Where ``GRAPHPLAN_TEST_CPU`` names a file, a line per shared value asked for: the tag, "built"
    or "read", the CPU seconds of building it, the worker's pid and the seconds it waited for the other
    worker building it — which builds a run makes, and which the workers wait on."""
    if CPU_LOG:
        with open(CPU_LOG, "a", encoding="utf-8") as out:
            out.write(f"{tag}\t{how}\t{cpu:.3f}\t{os.getpid()}\t{waited:.3f}\n")


def _shared(tag: str, build):
    """``build()``, composed once per test run and shared by its workers: the first worker to ask
    composes it (holding a lock: a worker asking meanwhile waits, as composing it itself would take
    as long) and leaves it pickled in this run's folder (``SHARED_SHEETS``, made in
    ``pytest_configure``); the others read it back (a few ms against 3–12 s of CPU: under xdist the
    gallery's modules and the sheet-content modules fall to different workers, and each composed
    the same examples' sheets). A build that raises leaves nothing behind: the next asker builds
    (and raises) again. Outside a run that made the folder, ``build()`` itself."""
    import fcntl
    import hashlib
    import pickle
    folder = os.environ.get(SHARED_SHEETS)
    if not folder or not os.path.isdir(folder):
        return build()
    stem = os.path.join(folder, hashlib.sha1(tag.encode()).hexdigest())
    with open(stem + ".lock", "w") as lock:
        waited = _clock()
        fcntl.flock(lock, fcntl.LOCK_EX)
        waited = _clock() - waited
        try:
            if os.path.exists(stem + ".pickle"):
                with open(stem + ".pickle", "rb") as f:
                    out = pickle.load(f)
                _log_shared(tag, "read", waited, 0.0)
                return out
            cpu = _time.process_time()
            out = build()
            _log_shared(tag, "built", waited, _time.process_time() - cpu)
            try:
                data = pickle.dumps(out, protocol=pickle.HIGHEST_PROTOCOL)
            except Exception:           # noqa: BLE001 — not picklable: each worker builds its own
                return out
            with open(stem + ".part", "wb") as f:
                f.write(data)
            os.replace(stem + ".part", stem + ".pickle")
            return out
        finally:
            fcntl.flock(lock, fcntl.LOCK_UN)


def shared(tag: str, build):
    """``build()`` made once per test run and shared by its workers (``_shared``) — for a module
    fixture's costly value: under ``--dist worksteal`` a file's tests fall to both workers, and each
    built the module's fixtures (a force sheet's plan 3–16 s of CPU). ``tag`` names it in the run:
    the module, the fixture and its parameter. Read it, never change it."""
    return _shared(tag, build)


@functools.lru_cache(maxsize=48)
def _example_sheet(name: str, kind: str, fmt: str, lang: str):
    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.form import form
    from graphplan.sheets.sheet import BUILDERS
    return _shared(f"numbered {name} {kind} {fmt} {lang}",
                   lambda: BUILDERS[kind](example(name), form(fmt), SheetOptions(lang=lang, sheet=kind)))


@functools.lru_cache(maxsize=16)
def example_composed(name: str, kind: str = "kinematics", fmt: str = "A1", lang: str = "uk"):
    """An example's sheet (or set) composed alone (``composed``: not numbered in its project), built
    once per worker and shared read-only — for the tests that read an example's drawings, tables
    and notes but not the title block's sheet numbers, in a language whose other documents no test
    of the default run composes (numbering the slotter's English dynamics sheet counted its
    English kinematics and force sheets: 7 s of CPU). ``example_sheet`` is the numbered one."""
    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.form import form
    return _shared(f"composed {name} {kind} {fmt} {lang}",
                   lambda: composed(kind, example(name), form(fmt), SheetOptions(lang=lang, sheet=kind)))


def scene_sheet(text: str, kind: str = "kinematics", fmt: str = "A1", lang: str = "uk", numbered: bool = False,
                **options):
    """A scene's sheet (or set) given as its text (tests/review_scenes.py), composed once per test run
    and shared by every test and module that asks with the same arguments (in-process, and across the
    workers through ``_shared``): ``composed`` (not numbered) unless ``numbered``, then as ``BUILDERS``
    numbers it. ``options``: the rest of ``SheetOptions`` (positions, accel, precision). The same
    review scenes' sheets were composed again in a dozen files (1–12 s of CPU each). Read it, never
    change it: a test that changes a sheet, or checks the build itself (its time, the warnings it
    emits), builds its own."""
    return _scene_sheet(text, kind, fmt, lang, numbered,
                        tuple(sorted((k, tuple(v) if isinstance(v, list) else v) for k, v in options.items())))


@functools.lru_cache(maxsize=32)
def _scene_sheet(text: str, kind: str, fmt: str, lang: str, numbered: bool, options: tuple):
    import hashlib

    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.form import form
    from graphplan.sheets.sheet import BUILDERS

    def build():
        opts = SheetOptions(lang=lang, sheet=kind,
                            **{k: list(v) if isinstance(v, tuple) else v for k, v in options})
        scene = scene_study(text)
        return (BUILDERS[kind] if numbered else functools.partial(composed, kind))(scene, form(fmt), opts)
    digest = hashlib.sha1(text.encode()).hexdigest()
    return _shared(f"scene {digest} {kind} {fmt} {lang} {numbered} {options!r}", build)


def scene_plan(text: str, kind: str = "kinematics", fmt: str = "A1", lang: str = "uk", **options):
    """A scene's (text's) sheet plan — ``sheets.kinematics.plan`` or ``sheets.forces.plan``: (Plan,
    Natural, Drafter) — made once per test run and shared like ``scene_sheet`` (a force plan is
    2–5 s of CPU, and the same scenes' plans were made again in a dozen files). Read it, never
    change it."""
    return _scene_plan(text, kind, fmt, lang,
                       tuple(sorted((k, tuple(v) if isinstance(v, list) else v) for k, v in options.items())))


@functools.lru_cache(maxsize=32)
def _scene_plan(text: str, kind: str, fmt: str, lang: str, options: tuple):
    import hashlib
    import importlib

    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.form import form
    opts = SheetOptions(lang=lang, sheet=kind, **{k: list(v) if isinstance(v, tuple) else v for k, v in options})
    plan = importlib.import_module(f"graphplan.sheets.{kind}").plan
    digest = hashlib.sha1(text.encode()).hexdigest()
    return _shared(f"plan {digest} {fmt} {opts!r}", lambda: plan(scene_study(text), form(fmt), opts))


def cli(*argv: str) -> tuple[int, str, str]:
    """``fuzz_scenes.run(argv)`` — a command that writes no file, run once per test run and shared
    by the tests that ask for the same command line (``graphplan cam X --json`` repeats the A1 sheet's
    scale search, 2–3 s of CPU): (exit code, stdout, stderr with every warning the run raised).
    A test of what a command writes, or of how long it takes, runs it itself."""
    return _cli(tuple(str(a) for a in argv))


@functools.lru_cache(maxsize=16)
def _cli(argv: tuple[str, ...]) -> tuple[int, str, str]:
    from fuzz_scenes import run
    return _shared("cli " + "\0".join(argv), lambda: run(list(argv)))


def cam_constructed(text: str, tmp_path_factory, name: str = "cam"):
    """A cam scene's text solved (``exact.cam.solve``) and constructed with no ruler: (solution,
    construction)."""
    from graphplan.exact.cam import solve
    from graphplan.graphic.cam import construct
    from graphplan.model.cam import load as load_cam
    path = tmp_path_factory.mktemp(name) / f"{name}.toml"
    path.write_text(text, encoding="utf-8")
    sol = solve(load_cam(path))
    return sol, construct(sol, measure=False)


def scene_study(text: str):
    return study(loads(text, "<test>"))


def scene_force_plans(text: str, **scales):
    """A scene's force plans (``forceplans.construct``) at its force analysis's crank angle, at the
    given scales (mu_l, mu_F, group_mu, group_mu_F)."""
    from graphplan.exact import kinetostatics
    from graphplan.graphic import forceplans
    st = scene_study(text)
    return forceplans.construct(st, float(kinetostatics.at_scene_angle(st)), **scales)


def group_of(fp, label: str):
    """The force plans' group lettered ``label`` ("II(2-3)")."""
    return next(g for g in fp.groups if g.label == label)


def circles(p: complex, rp: float, q: complex, rq: float) -> tuple[complex, complex]:
    """The two points at rp from p and rq from q: p + a·e ± i·h·e, a = (rp² − rq² + d²)/(2d), h = √(rp² − a²)."""
    d = abs(q - p)
    a = (rp * rp - rq * rq + d * d) / (2 * d)
    h = math.sqrt(rp * rp - a * a)
    e = (q - p) / d
    return p + a * e + 1j * h * e, p + a * e - 1j * h * e


def composed(kind: str, scene, f, options):
    """The kind's sheet (or set) as its builder composes it (``sheets.sheet.RAW``), not numbered in the
    scene's project: ``BUILDERS`` numbers it by composing every other document of the scene to count
    its sheets (``pages_of``: a six-bar's force sheet composed for a kinematics sheet's "Аркушів" takes
    20 s of CPU, three quarters of such a test). For tests that read the drawings, tables and notes;
    the numbering itself is checked in test_sheetset.py and test_dynamics_review47.py. The count is
    remembered as ``BUILDERS`` would (a numbered sheet of the scene built later reads it)."""
    from graphplan.sheets import sheet as S
    sheet = S.RAW[kind](scene, f, options)
    S.remember_pages(S._key(kind, scene, f, options), len(sheet.pages))
    return sheet


def derivative(f, phi_deg: np.ndarray, omega: float, order: int = 1, h_deg: float = 0.05):
    """d/dt (order 1) or d²/dt² (order 2) of f(φ) at constant ω, five-point stencils in φ."""
    h = np.radians(h_deg)
    f2, f1, f0, g1, g2 = (f(phi_deg + k * h_deg) for k in (-2, -1, 0, 1, 2))
    if order == 1:
        return (f2 - 8 * f1 + 8 * g1 - g2) / (12 * h) * omega
    return (-f2 + 16 * f1 - 30 * f0 + 16 * g1 - g2) / (12 * h * h) * omega ** 2


@pytest.fixture(params=EXAMPLES)
def any_example(request):
    return example(request.param)


@pytest.fixture(scope="module")
def crank_slider_keys(tmp_path_factory):
    """Keys of two crank-slider variants (examples/crank_slider.toml with r, l changed), for the tests
    that grade students' tables."""
    from fuzz_scenes import run
    folder = tmp_path_factory.mktemp("keys")
    table = folder / "variants.csv"
    table.write_text(f"# base = {ROOT / 'examples' / 'crank_slider.toml'}\nvariant,r,l\n01,0.064,0.307\n"
                     "02,0.05,0.2\n", encoding="utf-8")
    code, _, err = run(["key", str(table), "-o", str(folder / "keys"), "--quiet", "--no-pdf", "--jobs", "1"])
    assert code == 0, err
    return folder / "keys"



# -- one Chromium per worker (stop 59, speed59b) -----------------------------------------------------------
# Each browser module (test_view, test_view_tutor, test_serve_browser, test_serve_browser55, test_serve56)
# launched its own Chromium and chromedriver (≈ 3.5 s of CPU a launch, more under xdist's worksteal, which
# hands a module's tests to both workers): one browser now serves every module of the worker, and each
# test starts clean (``browser_tab``): the module's window size, the cookies, the cache and the logs of
# earlier tests gone, no emulated device left over.
CHROMIUM = "/usr/bin/chromium"
CHROMEDRIVER = "/usr/bin/chromedriver"
_BROWSER = {"launches": 0}


@pytest.fixture(scope="session")
def chromium():
    """The worker's one headless Chromium (started at the first test that needs it, quit at the end).
    The callers check first that chromium, its driver and selenium are there (they skip, or fail in CI)."""
    import shutil
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    opts = webdriver.ChromeOptions()
    opts.binary_location = CHROMIUM if os.path.exists(CHROMIUM) else shutil.which("chromium")
    for arg in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                "--window-size=1400,1800", "--no-first-run", "--disable-extensions",
                "--disable-background-networking", "--disable-component-update"):
        opts.add_argument(arg)
    opts.add_experimental_option("prefs", {"download.prompt_for_download": False})
    opts.set_capability("goog:loggingPrefs", {"browser": "ALL", "performance": "ALL"})
    d = webdriver.Chrome(options=opts, service=Service(
        CHROMEDRIVER if os.path.exists(CHROMEDRIVER) else shutil.which("chromedriver")))
    _BROWSER["launches"] += 1
    if CPU_LOG:
        with open(CPU_LOG, "a", encoding="utf-8") as out:
            out.write(f"chromium\tlaunch\t{_BROWSER['launches']}\t{os.getpid()}\n")
    yield d
    d.quit()


def browser_tab(d, width: int, height: int, downloads: Path | None = None):
    """``d`` (the worker's browser) for a new test at ``width`` × ``height``: what an earlier test left
    (a window it opened, cookies, the cache, console and network logs, an emulated phone) is gone; no
    page of the program keeps web storage (none in graphplan/). Every test opens its own page first: a
    new tab a test (a blank page) passed them all (speed59b), but cost a renderer process each — 0.4 s of
    CPU, an about:blank between tests 0.08 s, a launch 1 s (speed59b-scratch/launch*.py)."""
    for handle in d.window_handles[1:]:        # a test that opened a window of its own
        d.switch_to.window(handle)
        d.close()
    d.switch_to.window(d.window_handles[0])
    d.execute_cdp_cmd("Emulation.clearDeviceMetricsOverride", {})
    d.set_window_size(width, height)
    d.execute_cdp_cmd("Network.clearBrowserCookies", {})
    d.execute_cdp_cmd("Network.clearBrowserCache", {})
    d.execute_cdp_cmd("Browser.setDownloadBehavior", {"behavior": "allow" if downloads else "default",
                                                      **({"downloadPath": str(downloads)} if downloads else {})})
    d.get_log("browser")
    d.get_log("performance")
    return d


@pytest.fixture(scope="session")
def served():
    """The worker's one real ``graphplan serve`` (a process, as a student starts it) for the browser tests
    of test_serve_browser, test_serve_browser55 and test_serve56 — it was one a module, each with its pool
    of two workers importing graphplan. Without chromium, its driver, selenium or pdftotext: skipped (CI:
    failed)."""
    import test_serve_browser as B
    reason = B._browser_missing()
    if reason:
        if os.environ.get("CI"):
            pytest.fail(f"browser tests cannot run in CI: {reason}")
        pytest.skip(reason)
    port = B.free_port()
    proc = B.start_server(port)
    yield f"http://127.0.0.1:{port}"
    proc.terminate()
    proc.wait(10)


@pytest.fixture(scope="session")
def web_client():
    """The web app (one worker in its pool, a job's bound 600 s, host "testserver") in starlette's test
    client, one per xdist worker for test_serve56, test_web57, test_web58 and test_messages54: each module
    started an app of its own, and its pool a worker process importing graphplan (≈ 1 s of CPU each).
    test_serve keeps its own app (two workers; it checks the pool's folders outlive no app)."""
    pytest.importorskip("starlette")
    pytest.importorskip("multipart")
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        from starlette.testclient import TestClient
    from graphplan.web.app import Config, create_app
    with TestClient(create_app(Config(workers=1, timeout=600, allowed_hosts=["testserver"]))) as c:
        yield c


@pytest.fixture
def web(web_client):
    """``web_client`` with no cookie an earlier test left."""
    web_client.cookies.clear()
    return web_client
