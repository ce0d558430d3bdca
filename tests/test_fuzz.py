"""The fuzz suite: random valid mechanisms of every dyad kind, near-singular ones and broken scenes
through every command, in-process. Every run ends in exit 0 or 2, one line on stderr for 2, never
an internal error or a warning, JSON without NaN; a solved mechanism keeps its links' lengths and
its sliders on their guides.

The quick profile (a few hundred runs) is in the default suite; ``-m slow`` runs 10 000 scenes per
command (docs/benchmarks.md records the last run).
"""
from __future__ import annotations

import cmath
import os

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from fuzz_scenes import FULL_TREE, LOADED, MALFORMED, NEAR_SINGULAR, VALID, check_run, mutated, run
from graphplan.model.mechanism import FRAME
from graphplan.model.scene import loads

QUICK = dict(max_examples=int(os.environ.get("GRAPHPLAN_FUZZ_QUICK", "15")), deadline=None, derandomize=True,
             suppress_health_check=list(HealthCheck))
SLOW = dict(max_examples=int(os.environ.get("GRAPHPLAN_FUZZ_SLOW", "10000")), deadline=None,
            suppress_health_check=list(HealthCheck))

# (command, extra options) every scene goes through; {out} is a file in a fresh folder. The solvers
# are fuzzed at their own scales (--format none): laying out a sheet to choose the scales costs about a
# second a run, and the sheets are fuzzed on their own (test_sheets_of_random_mechanisms).
COMMANDS = [
    ("analyze", ["--json"]),
    ("plans", ["--json", "--format", "none"]),
    ("diagrams", ["--json", "--format", "none"]),
    ("forces", ["--json", "--format", "none"]),
]


def _scene(tmp_path_factory, text: str | bytes) -> str:
    folder = tmp_path_factory.mktemp("fuzz")
    path = folder / "scene.toml"
    path.write_bytes(text if isinstance(text, bytes) else text.encode("utf-8", "surrogatepass"))
    return str(path)


def constraints_hold(text: str, doc: dict) -> None:
    """Every link with two joints keeps its length; every slider on a frame guide stays on it
    (to 1e-9 of the mechanism's size)."""
    mech = loads(text, "<fuzz>")
    size = max([mech.crank.length] + [lk.length or 0.0 for lk in mech.links.values()])
    for pos in doc["positions"]:
        pts = {n: complex(p["x"], p["y"]) for n, p in pos["points"].items()}
        for link in mech.links.values():
            if link.slides_on is None and len(link.joints) >= 2 and all(j in pts for j in link.joints[:2]):
                a, b = link.joints[:2]
                want = abs(link.local[b] - link.local[a])
                assert abs(abs(pts[b] - pts[a]) - want) <= 1e-9 * size, (link.name, pos["phi_deg"])
            if link.slides_on is not None:
                guide = mech.guides[link.slides_on]
                if guide.body != FRAME:
                    continue
                p = pts[next(iter(link.local))]
                off = ((p - guide.through) * cmath.exp(-1j * guide.angle)).imag
                assert abs(off) <= 1e-9 * max(size, abs(guide.through)), (link.name, pos["phi_deg"])


def _through_commands(tmp_path_factory, text, commands=COMMANDS, valid: bool = False) -> list[int]:
    path = _scene(tmp_path_factory, text)
    codes = []
    for command, extra in commands:
        argv = [command, path, *extra]
        code, out, err = run(argv)
        doc = check_run(argv, code, out, err)
        if valid and command == "analyze" and doc is not None:
            constraints_hold(text, doc)
        codes.append(code)
    return codes


# -- the quick profile --------------------------------------------------------------------------

@settings(**QUICK)
@given(VALID)
def test_valid_mechanisms(tmp_path_factory, scene):
    text, assemblable = scene
    codes = _through_commands(tmp_path_factory, text, valid=True)
    if assemblable:
        assert codes[0] == 0        # analyze solves every mechanism that assembles over the turn


@settings(**QUICK)
@given(NEAR_SINGULAR)
def test_near_singular_mechanisms(tmp_path_factory, scene):
    _through_commands(tmp_path_factory, scene[0], valid=True)


@settings(**QUICK)
@given(LOADED)
def test_loaded_mechanisms_at_the_bounds(tmp_path_factory, scene):
    _through_commands(tmp_path_factory, scene[0], valid=True)


@settings(**QUICK)
@given(mutated())
def test_mutated_scenes(tmp_path_factory, text):
    _through_commands(tmp_path_factory, text)


@pytest.mark.slow      # a long fuzz run; test_mutated_scenes is the default's quick fuzz of bad input
@settings(**dict(QUICK, max_examples=max(2, QUICK["max_examples"] // 3)))
@given(mutated(FULL_TREE))
def test_every_sections_fields_of_the_wrong_type(tmp_path_factory, text):
    """The shaper with every optional section filled in (a motor by its data, the reducer, the
    diagrams, the output), one to three of its fields swapped for junk of another type: analyze and
    dynamics end in an answer or one line (a motor's ω given as text used to end every command in
    ValueError)."""
    _through_commands(tmp_path_factory, text, commands=[("analyze", ["--json"]), ("dynamics", ["--json"])])


@settings(**QUICK)
@given(MALFORMED)
def test_malformed_files(tmp_path_factory, text):
    codes = _through_commands(tmp_path_factory, text, commands=COMMANDS[:1])
    assert codes == [2]


OPTIONS = st.lists(st.sampled_from([
    "--phi", "--positions", "--precision", "--mu-v", "--mu-l", "--mu-a", "--accel", "--h1", "--h2", "--L",
    "--divisions", "--height", "--tolerance", "--at", "--lang", "--adaptive"]), min_size=1, max_size=3)
VALUES = st.one_of(st.sampled_from(["nan", "inf", "-inf", "0", "-1", "1e-9", "1e9", "1e300", "#3", "#-1",
                                    "2", "360", "1e-300", "0,nan", "x", "5,10,400", "uk"]),
                   st.floats().map(repr), st.integers(-10 ** 6, 10 ** 6).map(str))


@settings(**QUICK)
@given(st.sampled_from(["analyze", "plans", "diagrams", "forces"]), OPTIONS, st.data())
def test_extreme_options(tmp_path_factory, command, options, data):
    argv = [command]
    for opt in options:
        argv.append(opt)
        if opt != "--adaptive":
            argv.append(data.draw(VALUES))
    argv.append("--json")
    code, out, err = run(argv)
    check_run(argv, code, out, err)


SHEET = dict(QUICK, max_examples=max(2, QUICK["max_examples"] // 8))


@settings(**SHEET)
@given(st.one_of(VALID, NEAR_SINGULAR), st.sampled_from(["svg", "dxf"]), st.sampled_from(["kinematics", "forces"]))
def test_sheets_of_random_mechanisms(tmp_path_factory, scene, suffix, kind):
    path = _scene(tmp_path_factory, scene[0])
    out = f"{path[:-5]}.{suffix}"
    argv = ["sheet", path, "-o", out, "--sheet", kind, "--positions", "8"]
    code, _, err = run(argv)
    check_run(argv, code, _, err)
    assert (code == 0) == os.path.exists(out)


@pytest.mark.slow      # a long fuzz run (the brief: marked slow); the explorer of every example runs by default
@settings(**SHEET)
@given(st.one_of(VALID, NEAR_SINGULAR))
def test_the_explorer_of_random_mechanisms(tmp_path_factory, scene):
    path = _scene(tmp_path_factory, scene[0])
    out = f"{path[:-5]}.html"
    argv = ["view", path, "-o", out, "--step", "5"]
    code, _, err = run(argv)
    check_run(argv, code, _, err)
    assert (code == 0) == os.path.exists(out)


@pytest.fixture(scope="module")
def key_folder(crank_slider_keys):
    return crank_slider_keys


CELL = st.one_of(st.sampled_from(["01", "02", "7", "v_B", "omega_AB", "a_B", "#3", "1", "13", "-1",
                                  "7,2", "\"7,2\"", "−52,7", "5 346,1", "7_2", "nan", "inf", "1e400", "\"",
                                  "", "position", "quantity", "value", "variant",
                                  # a decimal comma split across cells (11,09 unquoted), a thousands
                                  # dot or a decimal point, an underflow, line breaks csv does not know
                                  "11", "09", "5.351", "1e-400", "7\u20282", "7\f2", "note"]),
                 st.text(max_size=8), st.floats().map(repr),
                 # numbers in every literal Python accepts (issue 36): radix prefixes, '_', exponents,
                 # signs, points at either end, thousands dots in ';' tables
                 st.integers(-10 ** 6, 10 ** 6).flatmap(lambda n: st.sampled_from(
                     [hex(n), oct(n), bin(n), f"{n:_}", f"{n}.", f"+{n}", f"{n}e-3", f"{n}E+2", f".{abs(n)}"])),
                 st.floats(allow_nan=True).flatmap(lambda x: st.sampled_from([f"{x:e}", f"{x:.3f}", f"{x:g}"])),
                 st.sampled_from(["0x10", "0o7000", "0b101", "2.800", "1_000.5", "1e-400", "-0", "+.5",
                                  "0X1F", "1E5", "Infinity", "-nan"]))
ROW = st.lists(CELL, min_size=1, max_size=6)


@settings(**QUICK)
@given(st.sampled_from([",", ";", "\t"]), st.lists(ROW, min_size=1, max_size=6),
       st.sampled_from(["utf-8", "utf-8-sig", "utf-16", "cp1251"]), st.booleans())
def test_random_student_tables(tmp_path_factory, key_folder, sep, rows, encoding, header):
    """`check` on random student tables: exit 0 or 2, one line, never an internal error."""
    head = "variant,position,quantity,value" + (",note" if len(rows) % 2 else "")    # a spare column
    if len(rows) % 3 == 1:                       # every column order (issue 36): the header rotated
        names = head.split(",")
        k = len(rows[0]) % len(names)
        head = ",".join(names[k:] + names[:k])
    lines = ([head.replace(",", sep)] if header else []) + [sep.join(r) for r in rows]
    path = tmp_path_factory.mktemp("student") / "student.csv"
    path.write_bytes("\n".join(lines).encode(encoding, "replace"))
    for extra in ([], ["--json"], ["--signed", "--json"]):
        argv = ["check", str(key_folder), str(path), *extra]
        code, out, err = run(argv)
        check_run(argv, code, out, err)


@settings(**dict(QUICK, max_examples=max(2, QUICK["max_examples"] // 8)))
@given(st.lists(st.tuples(st.sampled_from(["r", "l", "e", "rpm", "omega", "accel", "count", "K", "crank.length",
                                           "link.AB.length", "frame.points.O", "student", "divisions"]),
                          CELL), min_size=1, max_size=3))
def test_random_variant_tables(tmp_path_factory, cells):
    """`key` on random variant tables over the example: exit 0 or 2, one line, never an internal error."""
    from fuzz_scenes import ROOT
    folder = tmp_path_factory.mktemp("variants")
    names = list(dict.fromkeys(c for c, _ in cells))
    values = dict(cells)
    text = (f"# base = {ROOT / 'examples' / 'crank_slider.toml'}\nvariant,{','.join(names)}\n"
            f"01,{','.join(values[n].replace(',', '.') for n in names)}\n")
    (folder / "v.csv").write_text(text, encoding="utf-8")
    argv = ["key", str(folder / "v.csv"), "-o", str(folder / "keys"), "--quiet", "--no-pdf", "--jobs", "1"]
    code, out, err = run(argv)
    check_run(argv, code, out, err)


@settings(**dict(QUICK, max_examples=max(4, QUICK["max_examples"] // 3)))
@given(st.permutations(["variant", "position", "quantity", "value"]), CELL, st.sampled_from([",", ";", "\t"]))
def test_student_tables_in_every_column_order(tmp_path_factory, key_folder, order, value, sep):
    """A row of known meaning in every column order and separator: graded by name (the variant 01,
    position 1, v_B) with the value read as Python reads it, or refused in one line naming the line."""
    import re
    cells = {"variant": "01", "position": "1", "quantity": "v_B", "value": value}
    path = tmp_path_factory.mktemp("order") / "student.csv"
    path.write_text(sep.join(order) + "\n" + sep.join(cells[c] for c in order) + "\n", encoding="utf-8")
    argv = ["check", str(key_folder), str(path), "--json", "--lang", "en"]
    code, out, err = run(argv)
    doc = check_run(argv, code, out, err)
    if code == 2:
        assert "line " in err, err
        return
    for row in doc["rows"]:
        assert (row["variant"], row["position"], row["quantity"]) == ("01", "1", "v_B"), row
        if row["value"] is not None and re.fullmatch(r"[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?", value.strip()):
            assert row["value"] == float(value), (value, row["value"])


@settings(**dict(QUICK, max_examples=max(2, QUICK["max_examples"] // 8)))
@given(CELL, st.sampled_from(["csv,", "csv;", "csv\t", "toml"]))
def test_variant_tables_read_every_literal_as_check_does(tmp_path_factory, value, form):
    """`key` with a number in any literal in an ``e`` cell of each kind of table: the same value as
    the students' reader gives, or a refusal in one line (never 0x10 as 16, 1e-400 as 0)."""
    from fuzz_scenes import ROOT
    from graphplan.model.bounds import numeric_like, read_number
    folder = tmp_path_factory.mktemp("literal")
    base = ROOT / "examples" / "crank_slider.toml"
    if form == "toml":
        path = folder / "v.toml"
        path.write_text(f'base = "{base}"\n[[variant]]\nvariant = "01"\ne = {value}\n', encoding="utf-8")
    else:
        sep = form[3:]
        path = folder / "v.csv"
        path.write_text(f"# base = {base}\nvariant{sep}e\n01{sep}{value}\n", encoding="utf-8")
    argv = ["key", str(path), "-o", str(folder / "keys"), "--quiet", "--no-pdf", "--jobs", "1", "--json"]
    code, out, err = run(argv)
    check_run(argv, code, out, err)
    if code == 0 and form != "toml" and numeric_like(value) and "\"" not in value:
        import json
        key = json.loads((folder / "keys" / "01" / "key.json").read_text(encoding="utf-8"))
        assert key["overrides"]["e"] == read_number(value, form[3:]), (value, key["overrides"])


@pytest.mark.slow
@settings(**SLOW)
@given(st.one_of(VALID, NEAR_SINGULAR, LOADED, mutated().map(lambda t: (t, None)),
                 MALFORMED.map(lambda t: (t, None))))
def test_fuzz_slow(tmp_path_factory, scene):
    """The release profile: 10 000 scenes through analyze, plans, diagrams and forces."""
    text, assemblable = scene
    _through_commands(tmp_path_factory, text, valid=assemblable is not None)
