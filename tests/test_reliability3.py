"""The third round of reliability reproducers, the scene side (issue 26): each ends in exit 0 with the
right answer, or exit 2 with one line naming the file and the key — within 30 s, never an internal
error, a warning, an infinity in JSON or a quietly wrong reading. The students' tables and the keys
have their own tests (test_reliability.py, test_keys.py)."""
from __future__ import annotations

import json
import math
import time
from pathlib import Path

import pytest

from conftest import ROOT
from fuzz_scenes import check_run, run

CRANK_SLIDER = (ROOT / "examples" / "crank_slider.toml").read_text(encoding="utf-8")
SHAPER = (ROOT / "examples" / "shaper.toml").read_text(encoding="utf-8")
LAB = (ROOT / "examples" / "lab_crank_slider.toml").read_text(encoding="utf-8")
MOTOR_AT = "synchronous_rpm = 1500 # the motor"


def scene(tmp_path: Path, text: str, name: str = "scene.toml") -> Path:
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def ends(argv, code: int, *words) -> tuple[str, str]:
    """The run's exit code is ``code``, a refusal is one line holding every word and the file's name,
    an answer has no warning and (as JSON) no NaN or infinity. (No bound in seconds: CPU or wall time
    measured the machine's load — 57 s on two cores shared by a dozen runs, stop 47, where the same
    run takes a few seconds alone; the speed goals are docs/benchmarks.md's.)"""
    argv = [str(a) for a in argv]
    got, out, err = run(argv)
    check_run(argv, got, out, err)
    assert got == code, (argv, got, err[-300:])
    if code == 2:
        assert len(err.strip().splitlines()) == 1 and "internal error" not in err, err
        scene_file = next((a for a in argv if a.endswith(".toml")), None)
        if scene_file:
            assert scene_file in err, err
    for w in words:
        assert w in (err if code == 2 else out), (w, err, out[:300])
    return out, err


def with_motor(extra: str) -> str:
    return SHAPER.replace(MOTOR_AT, f"motor = {{ name = \"m\", power_kW = 3, rpm_sync = 1500, rpm_rated = 1430{extra} }}\n"
                          + MOTOR_AT)


# -- internal errors, now one line naming the key ----------------------------------------------------

@pytest.mark.parametrize("command", ["analyze", "plans", "forces"])
def test_a_crank_named_like_the_frame_is_refused(tmp_path, command):
    path = scene(tmp_path, CRANK_SLIDER.replace('name = "OA"', 'name = "0"'))
    ends([command, path, "--lang", "en"], 2, "crank.name", "frame")


@pytest.mark.parametrize("extra, key", [(', omega_sync = "x"', "omega_sync"), (", omega_rated = [1, 2]", "omega_rated"),
                                        (", omega_rated = { a = 1 }", "omega_rated"),
                                        (", power_kW = 1e308", "power_kW"), (', max_ratio = "2"', "max_ratio")])
def test_motor_fields_of_the_wrong_type_or_size_name_the_key(tmp_path, extra, key):
    text = with_motor(extra).replace("power_kW = 3, ", "") if "power_kW = 1e308" in extra else with_motor(extra)
    path = scene(tmp_path, text)
    for command in ("analyze", "dynamics"):
        ends([command, path], 2, f"dynamics.motor.{key}")


def test_an_oversized_motor_is_integrated_as_a_stiff_system(tmp_path):
    """A 99 999 kW motor on the shaper: its characteristic is so steep against the machine's inertia
    that the explicit integrator would take millions of steps; integrated as stiff, the crank then runs
    at the motor's own speed through the reducer, ω_m ≈ ω_rated/i (the motor holds it)."""
    text = with_motor("").replace("power_kW = 3", "power_kW = 99999")
    out, _ = ends(["dynamics", scene(tmp_path, text), "--json"], 0)
    doc = json.loads(out)
    motion = doc["motor"]["motion"]
    i = doc["motor"]["ratio"]
    w_rated = 1430 * math.pi / 30
    assert motion["omega_mean"] == pytest.approx(w_rated / i, rel=0.05)
    assert motion["delta"] < 1e-2


@pytest.mark.parametrize("command", ["forces", "dynamics"])
def test_a_subnormal_mass_is_refused(tmp_path, command):
    path = scene(tmp_path, SHAPER.replace("mass = 40", "mass = 5e-324"))
    ends([command, path, "--lang", "en"], 2, "link C.mass", "0 or from 0.000001")


def test_tangents_at_precision_0_give_null_not_infinity(tmp_path):
    """The tangents with the exact ruler: s is drawn exactly, so the first differentiation amplifies
    nothing — null in JSON, and the table says why."""
    path = ROOT / "examples" / "crank_slider.toml"
    out, _ = ends(["diagrams", path, "--method", "tangents", "--precision", "0", "--json"], 0)
    ruler = json.loads(out)["ruler"]
    assert ruler["first"] is None and ruler["s_rms_pct"] == 0 and ruler["second"] > 0
    out, _ = ends(["diagrams", path, "--method", "tangents", "--precision", "0", "--lang", "en"], 0)
    assert "starts from an exact curve" in out


# -- quietly wrong, now right --------------------------------------------------------------------------

def test_output_naming_the_slider_link_and_its_point_means_the_point(tmp_path):
    """``output = "B"`` on the crank-slider whose slider link is also called B: the point B slides,
    and every command answers as with the default output (it used to pick the link, which never turns,
    and end in ZeroDivisionError)."""
    path = scene(tmp_path, CRANK_SLIDER.replace("accel = [1]", 'accel = [1]\noutput = "B"'))
    base = ROOT / "examples" / "crank_slider.toml"
    for command in ("analyze", "plans", "diagrams"):
        out, _ = ends([command, path, "--json"], 0)
        ref, _ = ends([command, base, "--json"], 0)
        assert json.loads(out) == json.loads(ref), command


def test_a_link_that_never_turns_is_no_output(tmp_path):
    text = CRANK_SLIDER.replace('name = "B"', 'name = "slider"').replace("accel = [1]", 'accel = [1]\noutput = "slider"')
    ends(["analyze", scene(tmp_path, text), "--lang", "en"], 2, "positions.output", "never turns")


def test_a_crank_slider_with_l_equal_r_is_refused_naming_the_angle(tmp_path):
    text = CRANK_SLIDER.replace("l = 0.307", "l = 0.064")
    ends(["analyze", scene(tmp_path, text), "--lang", "en"], 2, "locks at crank angle 90.00°")


RPR = """title = "slotted link"
[frame.points]
O = [0, 0]
O1 = [0, 0.2]
[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = {r}
omega = 10
[[link]]
name = "2"
number = 2
joints = ["A"]
slides_on = "OB"
[[link]]
name = "OB"
number = 3
joints = ["O"]
points = {{ B = [0.5, 0] }}
[positions]
start = 0
"""


@pytest.mark.parametrize("r", ["0.2", "0.2000001", "0.1999999"])
def test_a_slotted_link_whose_pivot_lies_on_the_crank_circle_is_refused(tmp_path, r):
    """The rocker's pivot O on the crank pin's circle (O1O = r): the block passes through the pivot at
    270°, where the slotted link's direction is undefined (ω was 1.5·10¹⁴ rad/s)."""
    ends(["analyze", scene(tmp_path, RPR.format(r=r)), "--lang", "en"], 2, "passes through the pivot O", "270.00°")


def test_a_slotted_link_passing_near_its_pivot_is_answered_with_a_warning(tmp_path):
    """10 mm off the pivot the mechanism runs (ω of the slotted link ω1·r/(r − O1O)... = 190 rad/s):
    answered, and the study says where the block passes close."""
    out, _ = ends(["analyze", scene(tmp_path, RPR.format(r="0.19")), "--lang", "en"], 0)
    assert "passes within 10 mm of the pivot O" in out


# -- bounded work ----------------------------------------------------------------------------------------

def lab_3600(tmp_path: Path, divisions: bool = True) -> Path:
    text = LAB.replace("count = 8", "count = 3600").replace("accel = [1, 5]", "accel = [1]")
    return scene(tmp_path, text + ("divisions = 12\n" if divisions else ""), "lab_3600.toml")


@pytest.mark.parametrize("command", ["plans", "sheet", "view"])
def test_3600_positions_are_refused_before_the_sheets_work(tmp_path, command, monkeypatch):
    """Refused before any plan is constructed (was: within 5 s of CPU, a bound that measured the
    machine): a velocity plan finished before the refusal fails the test."""
    from graphplan.graphic.velocity import VelocityPlan

    def no_plan(self):
        raise AssertionError("a velocity plan was constructed before the refusal")
    monkeypatch.setattr(VelocityPlan, "finish", no_plan)
    path = lab_3600(tmp_path)
    argv = [command, path] + (["-o", tmp_path / ("x.svg" if command == "sheet" else "x.html")] if command != "plans" else [])
    ends(argv, 2, "positions.count = 3600", "at most 40")
    assert not list(tmp_path.glob("x.*"))


def test_3600_positions_plans_at_their_own_scales_and_diagrams_of_12_divisions(tmp_path):
    path = lab_3600(tmp_path)
    out, _ = ends(["plans", path, "--format", "none", "--json"], 0)
    assert len(json.loads(out)["positions"]) == 3600
    out, _ = ends(["diagrams", path, "--json"], 0)
    assert len(json.loads(out)["s"]) == 13 and json.loads(out)["divisions"] == 12


def test_too_many_divisions_name_the_file_and_the_key(tmp_path):
    ends(["diagrams", lab_3600(tmp_path, divisions=False)], 2, "positions.count", "from 4 to 720")


def test_a_yoke_whose_slot_is_a_hair_off_its_guide_is_refused_at_a_sheets_scales(tmp_path):
    """The Scotch yoke's slot 0.0625° off its guide (the fuzz census): no standard scale draws its
    velocity plans on a sheet — the search for one used to run off to an infinite μ (OverflowError);
    now one line, and the terminal's own scales still answer."""
    import random_mechanisms as rm
    text, _ = rm.rpp(0.0625, 0.0625, 0.0, 1.0)
    path = scene(tmp_path, text)
    ends(["plans", path], 2, "cannot be drawn on a A1 sheet at any scale")
    ends(["plans", path, "--format", "none", "--json"], 0)
    ends(["diagrams", path, "--json"], 0)          # the diagrams need no plan: drawn at their own scales


# -- students' tables ------------------------------------------------------------------------------------

@pytest.fixture(scope="module")
def keys(crank_slider_keys) -> Path:
    return crank_slider_keys


def exact_vb(keys: Path, position: int = 1) -> float:
    doc = json.loads((keys / "01" / "key.json").read_text(encoding="utf-8"))
    return doc["positions"][position]["values"]["v_B"]


def student(tmp_path: Path, text: str, name: str = "student.csv") -> Path:
    path = tmp_path / name
    path.write_bytes(text.encode("utf-8"))
    return path


@pytest.mark.parametrize("text, words", [
    # a spare column: "11,09" unquoted lands 09 in the note column (was read as 11 and passed)
    ("variant,position,quantity,value,note\n01,1,v_B,11,09\n", ["line 2", "'11' and then '09'", "decimal comma"]),
    # the key.csv layout a student fills in: "7,2" spills into the unit column (was 7, "fits position 5")
    ("variant,position,quantity,value,unit,tolerance_pct,phi_deg\n01,1,v_B,7,2\n", ["line 2", "'7' and then '2'"]),
    # a wide table's value spilling into an unnamed column
    ("position,v_B,\n1,11,08\n", ["line 2", "'11' and then '08'"]),
    # a thousands dot or a decimal point?
    ("variant;position;quantity;value\n01;1;a_B;5.351\n", ["line 2", "5.351", "thousands"]),
    # an underflow, refused like an overflow
    ("variant,position,quantity,value\n01,1,v_B,1e-400\n", ["line 2", "1e-400", "underflows"]),
])
def test_student_tables_that_cannot_be_read_for_sure_are_refused(tmp_path, keys, text, words):
    path = student(tmp_path, text)
    code, out, err = run(["check", str(keys), str(path), "--lang", "en"])
    check_run(["check"], code, out, err)
    assert code == 2, out
    for w in words:
        assert w in err, (w, err)


def test_a_decimal_comma_in_a_semicolon_table_and_a_spare_empty_note_are_read(tmp_path, keys):
    vb = exact_vb(keys)
    text = f"variant;position;quantity;value;note\n01;1;v_B;{vb:.2f}".replace(".", ",") + ";\n"
    code, out, err = run(["check", str(keys), str(student(tmp_path, text)), "--json"])
    assert code == 0, err
    row = json.loads(out)["rows"][0]
    assert row["pass"] and row["value"] == pytest.approx(round(vb, 2))


def test_line_numbers_are_the_files_lines_whatever_the_unicode_breaks(tmp_path, keys):
    """U+2028 and a form feed are no line ends for a CSV file: the rows keep their real line numbers
    (they used to be numbered past the file's end)."""
    vb = exact_vb(keys)
    text = f"variant,position,quantity,value\n01,1,v_B,{vb:.3f}\u2028\n01,1,v_B,{vb:.3f}\f\n01,1,v_B,oops\n"
    code, _, err = run(["check", str(keys), str(student(tmp_path, text)), "--lang", "en"])
    assert code == 2 and "line 4:" in err, err
    assert text.count("\n") == 4


def big_table(n: int, seed: int = 3) -> str:
    import random
    rnd = random.Random(seed)
    names = ["v_B", "a_B", "v_S2", "omega_AB", "a_S2", "epsilon_AB"]
    rows = [f"0{1 + k % 2},{k % 12},{names[k % 6]},{rnd.uniform(1, 100):.3f}" for k in range(n)]
    return "variant,position,quantity,value\n" + "\n".join(rows) + "\n"


def test_batched_search_finds_the_angles_one_search_finds(tmp_path, keys):
    """The failed rows' searches run batched per variant and quantity: each row's fit (position,
    crank angles) is what a search of that row alone finds."""
    from graphplan.teach.grading import grade, load_keys, read_student
    path = student(tmp_path, big_table(300))
    loaded = load_keys(keys)
    rows = read_student(path)
    together = grade(loaded, rows)
    for k in range(0, 300, 37):
        alone = grade(load_keys(keys), [rows[k]])[0]
        assert alone.status == together[k].status and alone.note == together[k].note
        if alone.fits:
            assert alone.fits["angles_deg"] == pytest.approx(together[k].fits["angles_deg"], abs=1e-7)


@pytest.mark.slow
def test_a_faculty_table_of_100000_rows_is_graded_in_time_linear_in_its_rows(tmp_path, keys):
    """A faculty's table of 100 000 rows is graded whole, and the check's work grows as the table:
    100 000 rows take at most 20 times the processor time of their first 12 500 (8 times as many rows:
    linear is 8, a search of each row against every other 64) and at most 40 times the reading of the
    same table (grading.read_student; about 10: a search per failed row is hundreds). All is measured
    in this process one after the other (after a small run has paid the imports; the small table before
    and after the big one, the larger time kept), so the machine's other load weighs on both sides: a
    bound in seconds measured that load instead (37.9 s of CPU beside a second pytest worker where the
    run alone takes 7–10 s, stop 57; 40 s of wall time, stop 45). The speed: docs/benchmarks.md."""
    from graphplan.teach.grading import read_student

    def graded(n: int) -> float:
        path = student(tmp_path, big_table(n), f"student{n}.csv")
        t = time.process_time()
        code, out, err = run(["check", str(keys), str(path), "--json"])
        took = time.process_time() - t
        assert code == 0, err
        assert len(json.loads(out)["rows"]) == n
        return took
    graded(500)
    small = graded(12_500)
    big = graded(100_000)
    small = max(small, graded(12_500))
    t = time.process_time()
    assert len(read_student(tmp_path / "student100000.csv")) == 100_000
    read = time.process_time() - t
    print(f"\ngrading 12 500 rows: {small:.2f} s of CPU, 100 000 rows: {big:.2f} s ({big / small:.1f}×), "
          f"reading them {read:.2f} s ({big / read:.1f}×)")
    assert big < 20 * small, (small, big)
    assert big < 40 * read, (read, big)


# -- keys written whole ----------------------------------------------------------------------------------

def test_a_key_set_appears_under_its_name_only_when_whole(tmp_path):
    """The run writes into a hidden folder beside the target and renames it when done: a new target
    appears whole (summary included) and nothing else is left; a second run into the same folder
    replaces the variants and the summary and keeps the teacher's own files; a run that builds no
    variant leaves no folder at all. (A killed run: tests/test_reliability.py.)"""
    table = tmp_path / "v.csv"
    table.write_text(f"# base = {ROOT / 'examples' / 'crank_slider.toml'}\nvariant,r,l\n01,0.064,0.307\n",
                     encoding="utf-8")
    out = tmp_path / "keys"
    code, _, err = run(["key", str(table), "-o", str(out), "--quiet", "--no-pdf", "--jobs", "1"])
    assert code == 0, err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["keys", "v.csv"]
    assert (out / "summary.json").exists() and (out / "01" / "key.json").exists()
    (out / "students.csv").write_text("mine\n", encoding="utf-8")
    (out / "01" / "stale.txt").write_text("old\n", encoding="utf-8")
    code, _, err = run(["key", str(table), "-o", str(out), "--quiet", "--no-pdf", "--jobs", "1"])
    assert code == 0, err
    assert (out / "students.csv").read_text(encoding="utf-8") == "mine\n"
    assert not (out / "01" / "stale.txt").exists()          # the variant's folder is the new one
    bad = tmp_path / "bad.csv"
    bad.write_text(f"# base = {ROOT / 'examples' / 'crank_slider.toml'}\nvariant,r,l\n01,0.5,0.1\n",
                   encoding="utf-8")
    code, _, err = run(["key", str(bad), "-o", str(tmp_path / "none"), "--quiet", "--no-pdf", "--jobs", "1", "--lang", "en"])
    assert code == 2 and "nothing written" in err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bad.csv", "keys", "v.csv"]
