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


def ends(argv, code: int, *words) -> tuple[str, str, float]:
    """The run's exit code is ``code`` within 30 s, a refusal is one line holding every word and the
    file's name, an answer has no warning and (as JSON) no NaN or infinity."""
    argv = [str(a) for a in argv]
    t = time.perf_counter()
    got, out, err = run(argv)
    took = time.perf_counter() - t
    check_run(argv, got, out, err)
    assert got == code, (argv, got, err[-300:])
    assert took < 30, (argv, took)
    if code == 2:
        assert len(err.strip().splitlines()) == 1 and "internal error" not in err, err
        scene_file = next((a for a in argv if a.endswith(".toml")), None)
        if scene_file:
            assert scene_file in err, err
    for w in words:
        assert w in (err if code == 2 else out), (w, err, out[:300])
    return out, err, took


def with_motor(extra: str) -> str:
    return SHAPER.replace(MOTOR_AT, f"motor = {{ name = \"m\", power_kW = 3, rpm_sync = 1500, rpm_rated = 1430{extra} }}\n"
                          + MOTOR_AT)


# -- internal errors, now one line naming the key ----------------------------------------------------

@pytest.mark.parametrize("command", ["analyze", "plans", "forces"])
def test_a_crank_named_like_the_frame_is_refused(tmp_path, command):
    path = scene(tmp_path, CRANK_SLIDER.replace('name = "OA"', 'name = "0"'))
    ends([command, path], 2, "crank.name", "frame")


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
    out, _, _ = ends(["dynamics", scene(tmp_path, text), "--json"], 0)
    doc = json.loads(out)
    motion = doc["motor"]["motion"]
    i = doc["motor"]["ratio"]
    w_rated = 1430 * math.pi / 30
    assert motion["omega_mean"] == pytest.approx(w_rated / i, rel=0.05)
    assert motion["delta"] < 1e-2


@pytest.mark.parametrize("command", ["forces", "dynamics"])
def test_a_subnormal_mass_is_refused(tmp_path, command):
    path = scene(tmp_path, SHAPER.replace("mass = 40", "mass = 5e-324"))
    ends([command, path], 2, "link C.mass", "0 or from 1e-06")


def test_tangents_at_precision_0_give_null_not_infinity(tmp_path):
    """The tangents with the exact ruler: s is drawn exactly, so the first differentiation amplifies
    nothing — null in JSON, and the table says why."""
    path = ROOT / "examples" / "crank_slider.toml"
    out, _, _ = ends(["diagrams", path, "--method", "tangents", "--precision", "0", "--json"], 0)
    ruler = json.loads(out)["ruler"]
    assert ruler["first"] is None and ruler["s_rms_pct"] == 0 and ruler["second"] > 0
    out, _, _ = ends(["diagrams", path, "--method", "tangents", "--precision", "0", "--lang", "en"], 0)
    assert "starts from an exact curve" in out


# -- quietly wrong, now right --------------------------------------------------------------------------

def test_output_naming_the_slider_link_and_its_point_means_the_point(tmp_path):
    """``output = "B"`` on the crank-slider whose slider link is also called B: the point B slides,
    and every command answers as with the default output (it used to pick the link, which never turns,
    and end in ZeroDivisionError)."""
    path = scene(tmp_path, CRANK_SLIDER.replace("accel = [1]", 'accel = [1]\noutput = "B"'))
    base = ROOT / "examples" / "crank_slider.toml"
    for command in ("analyze", "plans", "diagrams"):
        out, _, _ = ends([command, path, "--json"], 0)
        ref, _, _ = ends([command, base, "--json"], 0)
        assert json.loads(out) == json.loads(ref), command


def test_a_link_that_never_turns_is_no_output(tmp_path):
    text = CRANK_SLIDER.replace('name = "B"', 'name = "slider"').replace("accel = [1]", 'accel = [1]\noutput = "slider"')
    ends(["analyze", scene(tmp_path, text)], 2, "positions.output", "never turns")


def test_a_crank_slider_with_l_equal_r_is_refused_naming_the_angle(tmp_path):
    text = CRANK_SLIDER.replace("l = 0.307", "l = 0.064")
    ends(["analyze", scene(tmp_path, text)], 2, "locks at crank angle 90.00°")


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
    ends(["analyze", scene(tmp_path, RPR.format(r=r))], 2, "passes through the pivot O", "270.00°")


def test_a_slotted_link_passing_near_its_pivot_is_answered_with_a_warning(tmp_path):
    """10 mm off the pivot the mechanism runs (ω of the slotted link ω1·r/(r − O1O)... = 190 rad/s):
    answered, and the study says where the block passes close."""
    out, _, _ = ends(["analyze", scene(tmp_path, RPR.format(r="0.19")), "--lang", "en"], 0)
    assert "passes within 10 mm of the pivot O" in out


# -- bounded work ----------------------------------------------------------------------------------------

def lab_3600(tmp_path: Path, divisions: bool = True) -> Path:
    text = LAB.replace("count = 8", "count = 3600").replace("accel = [1, 5]", "accel = [1]")
    return scene(tmp_path, text + ("divisions = 12\n" if divisions else ""), "lab_3600.toml")


@pytest.mark.parametrize("command", ["plans", "sheet", "view"])
def test_3600_positions_are_refused_before_the_sheets_work(tmp_path, command):
    path = lab_3600(tmp_path)
    argv = [command, path] + (["-o", tmp_path / ("x.svg" if command == "sheet" else "x.html")] if command != "plans" else [])
    _, _, took = ends(argv, 2, "positions.count = 3600", "at most 40")
    assert took < 5
    assert not list(tmp_path.glob("x.*"))


def test_3600_positions_plans_at_their_own_scales_and_diagrams_of_12_divisions(tmp_path):
    path = lab_3600(tmp_path)
    out, _, _ = ends(["plans", path, "--format", "none", "--json"], 0)
    assert len(json.loads(out)["positions"]) == 3600
    out, _, _ = ends(["diagrams", path, "--json"], 0)
    assert len(json.loads(out)["s"]) == 13 and json.loads(out)["divisions"] == 12


def test_too_many_divisions_name_the_file_and_the_key(tmp_path):
    ends(["diagrams", lab_3600(tmp_path, divisions=False)], 2, "positions.count", "from 4 to 720")
