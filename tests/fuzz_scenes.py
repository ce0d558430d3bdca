"""What the fuzz suite shares: running a command in-process, the contract's properties of a run,
scene trees written back as TOML, and hypothesis strategies of valid, near-singular and broken scenes.
"""
from __future__ import annotations

import contextlib
import io
import json
import math
import tomllib
from pathlib import Path

from hypothesis import strategies as st

import random_mechanisms as rm
from graphplan.cli.main import main

ROOT = Path(__file__).resolve().parent.parent
BASE = tomllib.loads((ROOT / "examples" / "crank_slider.toml").read_text(encoding="utf-8"))
EXAMPLE_TREES = [tomllib.loads(p.read_text(encoding="utf-8")) for p in sorted((ROOT / "examples").glob("*.toml"))]


def _full_tree() -> dict:
    """The shaper with every optional section a scene may have filled in — a motor given by its data
    (with the printed ω's), the reducer, the diagrams' settings, the output named, a [sheet] — so that
    mutating its leaves swaps the type of every section's every field (issue 26: the motor's fields)."""
    tree = tomllib.loads((ROOT / "examples" / "shaper.toml").read_text(encoding="utf-8"))
    tree["dynamics"].update({"motor": {"name": "m", "power_kW": 30.0, "rpm_sync": 1500, "rpm_rated": 1460,
                                       "max_ratio": 2.2, "start_ratio": 2.0, "inertia": 0.01,
                                       "omega_sync": 157.08, "omega_rated": 152.89},
                             "ratio": 7.5, "rotor_inertia": 0.01, "reducer_inertia": 0.002,
                             "first_stage_ratio": 3.0, "reducer_shafts": [0.0004, 0.002, 0.05]})
    tree.pop("synchronous_rpm", None)
    tree["dynamics"].pop("synchronous_rpm", None)
    tree["diagrams"] = {"L_mm": 240, "H1_mm": 25, "H2_mm": 25, "divisions": 12, "point": "C"}
    tree["positions"]["output"] = "C"
    return tree


FULL_TREE = _full_tree()


# -- one run ----------------------------------------------------------------------------------

def run(argv: list[str]) -> tuple[int, str, str]:
    """``graphplan argv`` in this process: exit code, stdout, stderr. Every warning raised during the
    run is appended to stderr as the program would print it (each one, not only the first per line
    of code, and also under pytest, which otherwise records warnings away from stderr)."""
    import warnings
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err), \
            warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            code = main(argv)
        except SystemExit as exc:          # argparse's --help/--version
            code = exc.code if isinstance(exc.code, int) else 2
    shown = "".join(warnings.formatwarning(w.message, w.category, w.filename, w.lineno) for w in caught)
    return code, out.getvalue(), err.getvalue() + shown


def _no_constant(name: str):
    raise AssertionError(f"{name} in the JSON")


def check_run(argv: list[str], code: int, out: str, err: str) -> dict | None:
    """The contract of every run: exit 0 or 2; on 2 exactly one line on stderr, never an internal
    error; no warning on stderr; JSON without NaN/Infinity. Returns the JSON document if any."""
    assert code in (0, 2), f"exit {code} for {argv}: {err!r}"
    assert "internal error" not in err and "внутрішня помилка" not in err, f"{argv}: {err!r}"
    assert "Warning" not in err, f"{argv}: {err!r}"
    if code == 2:
        lines = err.splitlines()
        assert len(lines) == 1 and lines[0].startswith("graphplan: "), f"{argv}: {err!r}"
        assert not lines[0].startswith("graphplan: graphplan"), err
        return None
    if "--json" in argv:
        return json.loads(out, parse_constant=_no_constant)
    return None


# -- scene trees as TOML -----------------------------------------------------------------------

def _value(v) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        if math.isnan(v):
            return "nan"
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        return repr(v)
    if isinstance(v, str):
        return json.dumps(v)
    if isinstance(v, list):
        return "[" + ", ".join(_value(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{" + ", ".join(f"{json.dumps(str(k))} = {_value(x)}" for k, x in v.items()) + "}"
    return json.dumps(str(v))


def to_toml(tree: dict) -> str:
    """A scene tree as TOML text: top-level values, then tables, then arrays of tables."""
    lines = []
    tables = []
    for k, v in tree.items():
        if isinstance(v, dict):
            tables.append((k, v, False))
        elif isinstance(v, list) and v and all(isinstance(x, dict) for x in v):
            tables.append((k, v, True))
        else:
            lines.append(f"{json.dumps(str(k))} = {_value(v)}")
    for k, v, many in tables:
        for entry in (v if many else [v]):
            lines.append(f"[[{json.dumps(str(k))}]]" if many else f"[{json.dumps(str(k))}]")
            lines += [f"{json.dumps(str(kk))} = {_value(vv)}" for kk, vv in entry.items()]
    return "\n".join(lines) + "\n"


# -- strategies ----------------------------------------------------------------------------------

def _f(lo: float, hi: float):
    return st.floats(lo, hi, allow_nan=False, allow_infinity=False)


omega = st.one_of(_f(0.5, 400.0), _f(-400.0, -0.5))
branch = st.sampled_from([1, -1])

VALID = st.one_of(
    st.builds(rm.rrr, _f(0.02, 0.1), _f(0.15, 0.4), _f(0.1, 0.5), _f(0.1, 0.5), omega, branch),
    st.builds(rm.rrp, _f(0.02, 0.1), _f(0.05, 0.6), _f(-0.1, 0.1), _f(-180, 180), omega, branch),
    st.builds(rm.rpr, _f(0.02, 0.1), _f(0.05, 0.4), _f(-0.03, 0.03), omega, branch),
    st.builds(rm.prp, _f(0.02, 0.08), _f(0.2, 0.35), _f(0.2, 0.4), _f(0.2, 0.4), _f(-170, 170),
              _f(-170, 170), omega),
    st.builds(rm.rpp, _f(0.02, 0.1), _f(-170, 170), _f(-170, 170), omega),
    st.builds(rm.rrp_moving, _f(0.02, 0.08), _f(0.2, 0.35), _f(0.2, 0.4), _f(0.2, 0.4), _f(0.3, 0.8),
              _f(-170, 170), omega, branch),
    st.builds(rm.rpp_moving, _f(0.02, 0.08), _f(0.2, 0.35), _f(0.2, 0.4), _f(0.2, 0.4), _f(-170, 170),
              _f(-170, 170), omega),
)
"""Random mechanisms of every dyad kind and chain: (scene text, assemblable over the turn?)."""

_eps = _f(1e-9, 1e-4)
NEAR_SINGULAR = st.one_of(
    # a four-bar at the edge of assembly: l2 + l3 = d + r (+ a hair)
    st.builds(lambda r, d, l2, e, w: rm.rrr(r, d, l2, d + r - l2 + e, w, 1),
              _f(0.02, 0.1), _f(0.15, 0.4), _f(0.2, 0.3), _eps, omega),
    # a crank-slider whose rod is a hair longer than crank + offset
    st.builds(lambda r, off, e, w: rm.rrp(r, r + abs(off) + e, off, 0.0, w, 1),
              _f(0.02, 0.1), _f(-0.05, 0.05), _eps, omega),
    # a slotted link whose pivot is a hair off the crank circle
    st.builds(lambda r, e, w: rm.rpr(r, r + e, 0.0, w, 1), _f(0.02, 0.1), _eps, omega),
    # a Scotch yoke whose slot is nearly parallel to its guide
    st.builds(lambda r, a, w: rm.rpp(r, a, 0.0, w), _f(0.02, 0.1), _f(-0.2, 0.2), omega),
    # tiny and huge but physical mechanisms
    st.builds(rm.rrp, _f(1e-5, 1e-4), _f(5e-4, 1e-3), st.just(0.0), st.just(0.0), _f(1e-3, 1e5), branch),
    st.builds(rm.rrp, _f(10.0, 100.0), _f(300.0, 999.0), st.just(0.0), st.just(0.0), _f(1e-3, 1e4), branch),
)

def _loaded(scene, omega, g, q, k):
    """A valid mechanism at the edges of the physical bounds: ω, g, q·l masses, k·m·l² inertias."""
    import re
    text, ok = scene
    text = re.sub(r"omega = [^\n]+", f"omega = {omega!r}", text, count=1)
    return text + f"[loads]\ng = {g!r}\nmass_per_length = {q!r}\ninertia_factor = {k!r}\n", ok


LOADED = st.builds(_loaded, VALID, st.sampled_from([1e-3, 0.1, 300.0, 1e4, 1e5]),
                   st.sampled_from([0.0, 9.81, 1e3]), st.sampled_from([1e-9, 1.0, 1e6]),
                   st.sampled_from([1e-9, 1 / 12, 10.0]))
"""Valid mechanisms loaded at the bounds of bounds.py (forces must stay finite or be refused)."""

_junk_scalar = st.one_of(
    st.none(), st.booleans(), st.integers(), st.integers(min_value=10 ** 20, max_value=10 ** 400),
    st.floats(), st.text(max_size=30), st.sampled_from([
        "1/0", "sqrt(-1)", "10**400", "(-8)**0.5", "r * " * 60 + "1", "-" * 3000 + "1", "7_2",
        "__import__('os')", "l**2**2**2**2", "nan", "inf", "1e400", "0", "-1", "1e-30", "1e30",
        "\x07title", "S1", "0", "A", "B", "x", "", " "]))
_junk = st.recursive(_junk_scalar, lambda inner: st.one_of(
    st.lists(inner, max_size=3), st.dictionaries(st.text(max_size=8), inner, max_size=3)), max_leaves=6)


def _paths(tree, prefix=()):
    """Every (path, value) of a tree, tables and lists included."""
    yield prefix, tree
    if isinstance(tree, dict):
        for k, v in tree.items():
            yield from _paths(v, prefix + (k,))
    elif isinstance(tree, list):
        for i, v in enumerate(tree):
            yield from _paths(v, prefix + (i,))


def _set(tree, path, value, delete=False):
    node = tree
    for p in path[:-1]:
        node = node[p]
    if delete:
        del node[path[-1]]
    else:
        node[path[-1]] = value


@st.composite
def mutated(draw, base=None) -> str:
    """An example scene (or ``base``) with one to three leaves replaced by junk, deleted or joined
    by unknown keys, as TOML text."""
    import copy
    tree = copy.deepcopy(base if base is not None else draw(st.sampled_from(EXAMPLE_TREES)))
    for _ in range(draw(st.integers(1, 3))):
        paths = [p for p, _ in _paths(tree) if p]
        if not paths:
            break
        path = draw(st.sampled_from(paths))
        action = draw(st.sampled_from(["replace", "replace", "replace", "delete", "add"]))
        try:
            if action == "replace":
                _set(tree, path, draw(_junk))
            elif action == "delete":
                _set(tree, path, None, delete=True)
            else:
                parent = tree
                for p in path[:-1]:
                    parent = parent[p]
                if isinstance(parent, dict):
                    parent[draw(st.text(min_size=1, max_size=8))] = draw(_junk)
        except (KeyError, IndexError, TypeError):
            pass
    return to_toml(_drop_none(tree))


def _drop_none(tree):
    if isinstance(tree, dict):
        return {k: _drop_none(v) for k, v in tree.items() if v is not None}
    if isinstance(tree, list):
        return [_drop_none(v) for v in tree if v is not None]
    return tree


MALFORMED = st.one_of(
    st.binary(max_size=300).map(lambda b: b.decode("latin-1")),
    st.text(max_size=300),
    st.sampled_from(["[frame\n", "x = " + "[" * 5000, "a = {" * 3000, "title = \"unclosed\n",
                     "x = 1\nx = 2\n", "[[link]]\n[link]\n", "\ufeff[crank]\n", "k = 9" + "9" * 5000]),
)
"""Text that is not a scene: binary garbage, random text, broken TOML."""


# -- the deterministic families of issue 36: sections removed, the cam's combinations, counts --------

OPTIONAL = ("sheet", "params", "synthesis", "loads", "force", "dynamics", "diagrams", "branch", "positions",
            "title", "title_en", "designation", "frame.guides", "crank.points", "crank.direction",
            "positions.accel", "positions.start", "positions.force_phi_deg", "positions.working_stroke",
            "dynamics.synchronous_rpm", "dynamics.delta", "dynamics.efficiency", "cam.direction",
            "cam.offset", "cam.roller_radius", "cam.pressure_angle_deg", "cam.laws", "cam.divisions")


def _without(tree: dict, dotted: str) -> dict | None:
    """The tree with the section or key ``dotted`` removed (None when the tree has none)."""
    import copy
    parts = dotted.split(".")
    tree = copy.deepcopy(tree)
    node = tree
    for part in parts[:-1]:
        node = node.get(part) if isinstance(node, dict) else None
        if not isinstance(node, dict):
            return None
    if not isinstance(node, dict) or parts[-1] not in node:
        return None
    del node[parts[-1]]
    return tree


def sections_removed() -> list[tuple[str, str]]:
    """Every example (and the full shaper) with one optional section or key removed, one at a time —
    the shaper without [loads] and [[force]] together too (issue 36's bracket error)."""
    out = []
    trees = [(p.stem, tomllib.loads(p.read_text(encoding="utf-8"))) for p in sorted((ROOT / "examples").glob("*.toml"))]
    for name, tree in trees + [("full shaper", FULL_TREE)]:
        for dotted in OPTIONAL:
            cut = _without(tree, dotted)
            if cut is not None:
                out.append((f"{name} without {dotted}", to_toml(cut)))
    both = _without(_without(trees[[n for n, _ in trees].index("shaper")][1], "loads"), "force")
    out.append(("shaper without loads and force", to_toml(both)))
    return out


def cam_combinations() -> list[tuple[str, str]]:
    """Both cam examples in both senses, with the other laws, offsets of both signs and "auto", a
    knife edge, the pressure angles at the ends of their range and the fewest divisions."""
    import copy
    import itertools
    out = []
    for stem in ("cam_translating", "cam_rocking"):
        base = tomllib.loads((ROOT / "examples" / f"{stem}.toml").read_text(encoding="utf-8"))
        laws = ["parabolic", "cosine", "cycloidal", "linear", "trapezoidal"]
        extras = ([{"offset": 0.0}, {"offset": -0.005}, {"offset": "auto"}, {"roller_radius": 0.0}]
                  if base["cam"]["follower"] == "translating" else [{"roller_radius": 0.0}, {"arm": 0.15}])
        extras += [{"pressure_angle_deg": {"rise": 5, "return": 80}}, {"pressure_angle_deg": 80},
                   {"divisions": 2}, {}]
        for sense, law, extra in itertools.product(("cw", "ccw", None), laws, extras):
            tree = copy.deepcopy(base)
            if sense is None:
                tree["cam"].pop("direction", None)
            else:
                tree["cam"]["direction"] = sense
            tree["cam"]["laws"] = {"rise": law, "return": laws[(laws.index(law) + 2) % len(laws)]}
            tree["cam"].update(extra)
            out.append((f"{stem} {sense or 'default sense'} {law} {extra}", to_toml(tree)))
    return out


def counts_at_bounds() -> list[tuple[str, str]]:
    """The examples at the counts the bounds allow: 2 and 3600 positions, 2 and 720 diagram divisions,
    4 and 360 dynamics divisions."""
    import copy
    out = []
    for stem in ("crank_slider", "four_bar", "shaper", "slotter"):
        base = tomllib.loads((ROOT / "examples" / f"{stem}.toml").read_text(encoding="utf-8"))
        for count, divisions, dyn in ((2, 2, 4), (3600, 720, 360), (3600, None, None), (3, None, 4)):
            tree = copy.deepcopy(base)
            tree.setdefault("positions", {})["count"] = count
            tree["positions"]["accel"] = [1] if count > 2 else [0]
            if divisions is not None:
                tree.setdefault("diagrams", {})["divisions"] = divisions
            if dyn is not None and "dynamics" in tree:
                tree["dynamics"]["divisions"] = dyn
            out.append((f"{stem} count {count} divisions {divisions} dynamics {dyn}", to_toml(tree)))
    return out


def extras_census(progress: str | None = None) -> dict:
    """The deterministic families through every command (``cam`` too), tallied as ``census`` does."""
    import os
    import tempfile
    import time
    families = {"sections": sections_removed(), "cam": cam_combinations(), "counts": counts_at_bounds()}
    tally: dict = {"scenes": 0, "runs": 0, "exit0": 0, "exit2": 0, "internal": 0, "multiline": 0,
                   "warnings": 0, "nan_json": 0, "other_exit": 0, "over_30s": 0, "slowest_s": 0.0,
                   "by_family": {}}
    failures: list[str] = []
    folder = tempfile.mkdtemp(prefix="graphplan-fuzz-extra-")
    path = os.path.join(folder, "scene.toml")
    start = time.perf_counter()
    for family, scenes in families.items():
        tally["by_family"][family] = {"scenes": len(scenes), "internal": 0, "exit0": 0, "exit2": 0}
        for name, text in scenes:
            tally["scenes"] += 1
            Path(path).write_text(text, encoding="utf-8")
            commands = ("cam", "analyze") if family == "cam" else COMMANDS
            for command in commands:
                argv = [command, path, "--json"]
                t0 = time.perf_counter()
                code, out, err = run(argv)
                took = time.perf_counter() - t0
                tally["runs"] += 1
                tally["slowest_s"] = round(max(tally["slowest_s"], took), 2)
                problem = None
                if took > 30:
                    tally["over_30s"] += 1
                    problem = f"{took:.0f} s"
                if "internal error" in err or "внутрішня помилка" in err:
                    tally["internal"] += 1
                    tally["by_family"][family]["internal"] += 1
                    problem = "internal"
                elif code not in (0, 2):
                    tally["other_exit"] += 1
                    problem = f"exit {code}"
                elif "Warning" in err:
                    tally["warnings"] += 1
                    problem = "warning"
                elif code == 2 and len(err.splitlines()) != 1:
                    tally["multiline"] += 1
                    problem = "multiline"
                else:
                    tally[f"exit{code}"] += 1
                    tally["by_family"][family][f"exit{code}"] += 1
                    if code == 0:
                        try:
                            json.loads(out, parse_constant=_no_constant)
                        except AssertionError:
                            tally["nan_json"] += 1
                            problem = "NaN in JSON"
                if problem:
                    failures.append(f"{problem}: {command} {name}: {err.strip()[:160]}")
            if progress:
                tally["seconds"] = round(time.perf_counter() - start, 1)
                Path(progress).write_text(json.dumps({"tally": tally, "failures": failures}, indent=1))
    tally["seconds"] = round(time.perf_counter() - start, 1)
    return {"tally": tally, "failures": failures}


# -- the release count (docs/benchmarks.md): python tests/fuzz_scenes.py N ------------------------

COMMANDS = ("analyze", "plans", "diagrams", "forces", "dynamics")
SOMETIMES = ("sheet", "view")       # about a second a run: every tenth scene


def census(count: int, seed: int = 0, progress: str | None = None) -> dict:
    """``count`` scenes (valid, near-singular, mutated, malformed in turn) through every command:
    how the runs ended. A failing run is listed (first 20) instead of stopping the count; with
    ``progress`` the tally so far is written to that file every 250 scenes."""
    import os
    import random
    import tempfile
    import time
    from hypothesis import HealthCheck, given, settings

    tally = {"scenes": 0, "runs": 0, "exit0": 0, "exit2": 0, "internal": 0, "multiline": 0,
             "warnings": 0, "nan_json": 0, "constraint": 0, "other_exit": 0, "over_30s": 0,
             "slowest_s": 0.0, "by_command": {}}
    failures: list[str] = []
    seen: dict[str, int] = {}
    folder = tempfile.mkdtemp(prefix="graphplan-fuzz-")
    path = os.path.join(folder, "scene.toml")
    kinds = st.one_of(VALID.map(lambda s: ("valid", s[0])), NEAR_SINGULAR.map(lambda s: ("near", s[0])),
                      LOADED.map(lambda s: ("loaded", s[0])),
                      mutated().map(lambda t: ("mutated", t)), mutated(FULL_TREE).map(lambda t: ("types", t)),
                      MALFORMED.map(lambda t: ("malformed", t)))
    start = time.perf_counter()

    @settings(max_examples=count, deadline=None, database=None, derandomize=False,
              suppress_health_check=list(HealthCheck))
    @given(kinds)
    def one(item):
        kind, text = item
        tally["scenes"] += 1
        with open(path, "wb") as fh:
            fh.write(text.encode("utf-8", "surrogatepass"))
        commands = COMMANDS + (SOMETIMES if tally["scenes"] % 10 == 0 else ())
        for command in commands:
            argv = [command, path, "--json"] if command not in SOMETIMES else \
                [command, path, "-o", os.path.join(folder, "out." + ("svg" if command == "sheet" else "html"))] \
                + (["--step", "5"] if command == "view" else [])
            t0 = time.perf_counter()
            code, out, err = run(argv)
            took = time.perf_counter() - t0
            tally["runs"] += 1
            tally["by_command"][command] = tally["by_command"].get(command, 0) + 1
            tally["slowest_s"] = round(max(tally["slowest_s"], took), 2)
            problem = None
            if took > 30:
                tally["over_30s"] += 1
                problem = f"{took:.0f} s"
            if "internal error" in err or "внутрішня помилка" in err:
                tally["internal"] += 1
                problem = "internal"
            elif code not in (0, 2):
                tally["other_exit"] += 1
                problem = f"exit {code}"
            elif "Warning" in err:
                tally["warnings"] += 1
                problem = "warning"
            elif code == 2 and len(err.splitlines()) != 1:
                tally["multiline"] += 1
                problem = "multiline"
            else:
                tally[f"exit{code}"] += 1
                if code == 0 and command not in SOMETIMES:
                    try:
                        doc = json.loads(out, parse_constant=_no_constant)
                    except AssertionError:
                        tally["nan_json"] += 1
                        problem = "NaN in JSON"
                    else:
                        if command == "analyze" and kind in ("valid", "near", "loaded"):
                            from test_fuzz import constraints_hold
                            try:
                                constraints_hold(text, doc)
                            except AssertionError as exc:
                                tally["constraint"] += 1
                                problem = f"constraint {exc}"
            if problem:                    # up to 3 scenes of each kind of failure, whole
                said = f"{problem}: {command} {err.strip()[:100]}"
                seen[said] = seen.get(said, 0) + 1
                if seen[said] <= 3 and len(failures) < 60:
                    failures.append(f"{said} [{kind}] :: {text[:4000]!r}")
        if progress and tally["scenes"] % 250 == 0:
            tally["seconds"] = round(time.perf_counter() - start, 1)
            Path(progress).write_text(json.dumps({"tally": tally, "kinds": seen, "failures": failures}, indent=1))

    random.seed(seed)
    one()
    tally["seconds"] = round(time.perf_counter() - start, 1)
    return {"tally": tally, "kinds": seen, "failures": failures}


if __name__ == "__main__":
    import sys
    sys.path.insert(0, str(Path(__file__).resolve().parent))
    if len(sys.argv) > 1 and sys.argv[1] == "extras":     # python tests/fuzz_scenes.py extras [PROGRESS.json]
        print(json.dumps(extras_census(sys.argv[2] if len(sys.argv) > 2 else None), ensure_ascii=False, indent=1))
        sys.exit(0)
    result = census(int(sys.argv[1]) if len(sys.argv) > 1 else 1000,
                    progress=sys.argv[2] if len(sys.argv) > 2 else None)
    print(json.dumps(result, ensure_ascii=False, indent=1))
