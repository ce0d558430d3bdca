"""The command line: the contract's JSON, readable tables, and one clean line for bad input."""
from __future__ import annotations

import json
import os
import subprocess
import sys

import numpy as np
import pytest

from conftest import EXAMPLES, ROOT, derivative, example
from graphplan.cli.main import main


def run(capsys, *argv):
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


@pytest.mark.parametrize("name", EXAMPLES)
def test_analyze_json_all_examples(capsys, name):
    code, out, err = run(capsys, "analyze", str(ROOT / "examples" / f"{name}.toml"), "--positions", "12", "--json")
    assert code == 0 and err == ""
    doc = json.loads(out)
    assert doc["structure"]["mobility"] == 1
    assert len(doc["positions"]) == 12
    st = example(name)
    phis = np.array([p["phi_deg"] for p in doc["positions"]])
    # velocities in the JSON are the derivatives of the exact positions (independent of the loops)
    w = st.mech.omega1
    names = [n for n in st.mech.point_names() if n not in st.mech.frame]
    scale = abs(w) * st.mech.crank.length
    for n in names:
        fd = derivative(lambda p: st.solve(p).point(n)[0], phis, w)
        got = np.array([complex(p["points"][n]["vx"], p["points"][n]["vy"]) for p in doc["positions"]])
        assert np.all(np.abs(got - fd) <= 1e-7 * np.maximum(np.abs(fd), 1e-3 * scale)), n
    for p in doc["positions"]:
        assert set(p["links"]) == set(st.mech.links)
        for s in p["slides"].values():
            assert set(s) == {"s", "v", "a", "coriolis"}
    assert doc["positions"][0]["phi_deg"] == pytest.approx(st.phi0)
    first = doc["positions"][0]["slides"]
    assert all(abs(s["s"]) < 1e-12 for s in first.values())        # displacement from position 0


def test_contract_example_numbers(capsys):
    code, out, _ = run(capsys, "analyze", str(ROOT / "examples" / "crank_slider.toml"), "--json")
    pos = json.loads(out)["positions"]
    assert pos[0]["points"]["B"]["x"] == pytest.approx(0.371)
    assert pos[0]["points"]["B"]["ax"] == pytest.approx(-6642.9, abs=0.1)
    assert pos[0]["links"]["AB"]["omega"] == pytest.approx(-61.1, abs=0.05)
    b = pos[1]["points"]["B"]
    assert np.hypot(b["vx"], b["vy"]) == pytest.approx(11.081, abs=5e-4)


def test_phi_option_and_table(capsys):
    code, out, _ = run(capsys, "analyze", str(ROOT / "examples" / "shaper.toml"), "--phi", "30", "390")
    assert code == 0      # Ukrainian by default: the lab's pair letters, the decimal comma
    assert "I(0-1) → II(2-3) → II(4-5)" in out and "ВПВ" in out and "ВВП" in out and "обчислено довжина кривошипа, м = 0,20826" in out
    assert not any(w in out for w in ("crank", "rocker"))     # the synthesis's names in the scene's language
    code, out, _ = run(capsys, "analyze", str(ROOT / "examples" / "shaper.toml"), "--phi", "30", "390",
                       "--lang", "en")
    assert "I(0-1) → II(2-3) → II(4-5)" in out and "RPR" in out and "RRP" in out
    assert "derived crank length, m = 0.20826" in out and "Coriolis" in out
    rows = [line for line in out.splitlines() if line.strip().startswith(("0 ", "1 "))]
    assert len(rows) >= 2


def test_builtin_scene_is_the_example(capsys):
    from graphplan.model.scene import builtin_path
    assert builtin_path().read_bytes() == (ROOT / "examples" / "crank_slider.toml").read_bytes()
    code, out, _ = run(capsys, "analyze", "--json")
    assert code == 0 and json.loads(out)["scene"] == "Кривошипно-повзунний механізм"


def test_output_is_deterministic(capsys):
    a = run(capsys, "analyze", str(ROOT / "examples" / "slotter.toml"), "--json")[1]
    b = run(capsys, "analyze", str(ROOT / "examples" / "slotter.toml"), "--json")[1]
    assert a == b


BAD = {
    "syntax": ("title = \n", "TOML syntax error", "line 1"),
    "unknown key": ("[frame.points]\nO=[0,0]\n[crank]\npivot='O'\npin='A'\nlength=1\nomega=1\ncolour=3\n",
                    "crank.colour", "unknown key"),
    "missing crank": ("[frame.points]\nO=[0,0]\n", "crank", "missing"),
    "negative length": ("[frame.points]\nO=[0,0]\n[crank]\npivot='O'\npin='A'\nlength=-1\nomega=1\n",
                        "crank.length", "positive"),
    "zero speed": ("[frame.points]\nO=[0,0]\n[crank]\npivot='O'\npin='A'\nlength=1\nrpm=0\n",
                   "crank.rpm", "positive"),
    "unknown guide": ("[frame.points]\nO=[0,0]\n[crank]\npivot='O'\npin='A'\nlength=0.1\nomega=1\n"
                      "[[link]]\njoints=['A','B']\nlength=0.3\n[[link]]\njoints=['B']\nslides_on='y'\n",
                      "slides_on", "no guide named 'y'"),
    "mobility": ("[frame.points]\nO=[0,0]\nO2=[0.3,0]\n[crank]\npivot='O'\npin='A'\nlength=0.1\nomega=1\n"
                 "[[link]]\njoints=['A','B']\nlength=0.3\n[[link]]\njoints=['B','C']\nlength=0.3\n"
                 "[[link]]\njoints=['C','O2']\nlength=0.3\n", "mobility W", "= 2"),
    "dyad inputs unknown": ("[frame.points]\nO=[0,0]\n[crank]\npivot='O'\npin='A'\nlength=0.1\nomega=1\n"
                            "[[link]]\njoints=['B','C']\nlength=0.3\n[[link]]\njoints=['C','B2']\nlength=0.3\n"
                            "[[link]]\njoints=['B','B2']\nlength=0.2\n[[link]]\njoints=['A','D']\nlength=0.2\n",
                            "joint 'D'", "joins nothing"),
    "unknown branch point": ("@[branch]\nB = 1\nZ = 1\n", "branch.Z", "no such point"),
    "assembly": (None, "II(2-3) ВВП", "°–"),      # the scene's language: Ukrainian (util.words "asm …")
}


@pytest.mark.parametrize("case", sorted(BAD))
def test_bad_input_is_one_line_exit_2(tmp_path, case):
    text, part, detail = BAD[case]
    example_text = (ROOT / "examples" / "crank_slider.toml").read_text(encoding="utf-8")
    if text is None:
        text = example_text.replace('l = 0.307', 'l = 0.050')
    elif text.startswith("@"):
        text = example_text.replace("[branch]\nB = 1", text[1:].strip())
    path = tmp_path / "bad.toml"
    path.write_text(text, encoding="utf-8")
    lang = [] if case == "assembly" else ["--lang", "en"]       # the English wording; assembly: the scene's (uk)
    if case == "syntax":       # one real process: the command line's contract itself (exit code, streams)
        proc = subprocess.run([sys.executable, "-m", "graphplan", "analyze", str(path)] + lang,
                              capture_output=True, text=True, cwd=ROOT)
        code, out, err = proc.returncode, proc.stdout, proc.stderr
    else:                      # the others: the same command in the worker (0.45 s of CPU a process)
        from fuzz_scenes import run as in_process
        code, out, err = in_process(["analyze", str(path)] + lang)
    assert code == 2
    assert out == ""
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    assert "Traceback" not in err
    assert str(path) in lines[0] and part in lines[0] and detail in lines[0], lines[0]


def test_assembly_range_is_exact(capsys, tmp_path):
    """r = 0.064, l = 0.05, slider on the x axis: the rod reaches the axis while |r sinφ| ≤ l,
    so it fails for asin(l/r) < φ < 180° − asin(l/r) and the mirror range."""
    text = (ROOT / "examples" / "crank_slider.toml").read_text(encoding="utf-8").replace('l = 0.307', 'l = 0.050')
    path = tmp_path / "short.toml"
    path.write_text(text, encoding="utf-8")
    code, out, err = run(capsys, "analyze", str(path))
    a = np.degrees(np.arcsin(0.05 / 0.064))
    assert code == 2
    uk = lambda t: t.replace(".", ",")  # noqa: E731  (the scene's language: a decimal comma)
    assert uk(f"{a:.1f}°–{180 - a:.1f}°") in err and uk(f"{180 + a:.1f}°–{360 - a:.1f}°") in err


def test_usage_error_is_one_line():
    proc = subprocess.run([sys.executable, "-m", "graphplan", "analyze", "--positions", "x"],
                          capture_output=True, text=True, cwd=ROOT)
    assert proc.returncode == 2 and len(proc.stderr.strip().splitlines()) == 1


def test_help_works():
    """The one subprocess run of --help (the others are in-process, tests/test_help_lang.py): Ukrainian
    without --lang, whatever the environment's LANG."""
    proc = subprocess.run([sys.executable, "-m", "graphplan", "analyze", "--help"],
                          capture_output=True, text=True, cwd=ROOT, env={**os.environ, "LANG": "en_US.UTF-8"})
    assert proc.returncode == 0 and "--positions" in proc.stdout
    assert proc.stdout.startswith("використання: graphplan analyze") and "кількість положень" in proc.stdout
