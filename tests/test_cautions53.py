"""A scene's likely slips are warned, not refused (model.cautions): a centre of mass outside its link's
joints (S2 = [0.5, 0] on a 0.307 m rod: metres where a fraction was meant), a point far beyond the link;
not an extension point (the rocker O2–B–D, D = 1.3), nor a crank's counterweight behind its pivot, nor
any example. The command line tells each one line on stderr, once, in the scene's language."""
from __future__ import annotations

from pathlib import Path

import pytest

from conftest import ROOT
from graphplan.model.cautions import cautions
from graphplan.model.scene import load, loads

EXAMPLE = (ROOT / "examples" / "crank_slider.toml").read_text(encoding="utf-8")


def with_points(crank: str = "S1 = 0.4", rod: str = "S2 = 0.35") -> str:
    text = EXAMPLE.replace("points = { S1 = 0.4 }", f"points = {{ {crank} }}", 1)
    return text.replace("points = { S2 = 0.35 }", f"points = {{ {rod} }}", 1)


@pytest.mark.parametrize("crank, rod, said", [
    ("S1 = 0.4", "S2 = 0.35", None),
    ("S1 = 0.4", "S2 = [0.5, 0]", "S2"),                 # metres: 0.193 m past B
    ("S1 = 0.4", "S2 = 1.92", "S2"),                     # a fraction over 1
    ("S1 = 0.4", "S2 = [0.15, 0.2]", "S2"),              # far off the rod's line
    ("S1 = 0.4", "S2 = 0.35, D = 1.3", None),            # an extension point O2–B–D is legitimate
    ("S1 = 0.4", "S2 = 0.35, E = [2.0, 0.0]", "E"),      # 1.69 m past B on a 0.307 m rod
    ("S1 = -0.3", "S2 = 0.35", None),                    # a crank's counterweight behind its pivot
    ("S1 = -1.5", "S2 = 0.35", "S1"),
])
def test_which_points_are_warned(crank, rod, said):
    told = cautions(loads(with_points(crank, rod)))
    assert len(told) == (said is not None)
    if said:
        assert f" {said} " in told[0]["en"] and f" {said} " in told[0]["uk"]


def test_no_example_is_warned():
    for path in sorted((ROOT / "examples").glob("*.toml")):
        text = path.read_text(encoding="utf-8")
        if "[crank]" in text:
            assert cautions(load(path)) == [], path.name


def test_the_command_line_warns_once_in_the_scene_s_language(tmp_path, capsys):
    from graphplan.cli.main import main
    path = tmp_path / "s2.toml"
    path.write_text(with_points(rod="S2 = [0.5, 0]"), encoding="utf-8")
    for lang, words in ((None, ["попередження", "центр мас S2", "0,193 м", "шарніра B"]),
                        ("en", ["warning", "centre of mass S2", "0.193 m", "joint B"])):
        code = main(["analyze", str(path), "--json", *(["--lang", lang] if lang else [])])
        err = capsys.readouterr().err.strip().splitlines()
        assert code == 0 and len(err) == 1 and str(path) in err[0], err
        assert all(w in err[0] for w in words), err[0]
    Path(path).write_text('lang = "en"\n' + with_points(rod="S2 = [0.5, 0]"), encoding="utf-8")
    main(["analyze", str(path), "--json"])
    assert "centre of mass S2" in capsys.readouterr().err


def test_a_refused_run_stays_one_line(tmp_path, capsys):
    """A scene with a slip that is then refused (its rod too short to assemble) prints the refusal only."""
    from graphplan.cli.main import main
    path = tmp_path / "bad.toml"
    path.write_text(with_points(rod="S2 = [0.5, 0]").replace("l = 0.307 ", "l = 0.03 ", 1), encoding="utf-8")
    assert main(["analyze", str(path), "--lang", "en"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "cannot be assembled" in err[0], err
