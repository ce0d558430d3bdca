"""The public API: the documented calls, their views, the notebook's display, and the rooms' layers."""
from __future__ import annotations

import doctest
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

import graphplan

ROOT = Path(__file__).resolve().parents[1]


def test_docs_api_examples_run(monkeypatch):
    monkeypatch.chdir(ROOT)
    result = doctest.testfile(str(ROOT / "docs" / "api.md"), module_relative=False,
                              optionflags=doctest.ELLIPSIS)
    assert result.attempted > 15 and result.failed == 0


def test_import_is_light():
    """`import graphplan` loads no numpy, matplotlib or drawing room until a call needs it."""
    code = ("import sys, graphplan; heavy = [m for m in ('numpy', 'matplotlib', 'graphplan.drawing', "
            "'graphplan.api') if m in sys.modules]; print(heavy)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT)
    assert out.stdout.strip() == "[]"


@pytest.fixture(scope="module")
def shaper():
    return graphplan.load(ROOT / "examples" / "shaper.toml")


def _shows(view) -> None:
    """A view draws itself as SVG in true millimetres, on white for a notebook, and has JSON and text."""
    svg = view._repr_svg_()
    assert svg.startswith("<svg") and 'mm"' in svg
    html = view._repr_html_()
    assert "background:#fff" in html and svg in html
    assert isinstance(view.to_json(), dict)
    assert view.table().strip() and str(view) == view.table()


def test_every_result_displays_itself(shaper):
    p = graphplan.plans(shaper)
    f = graphplan.forces(shaper)
    views = [shaper, graphplan.study(shaper), p, p.velocity(0), p.velocity(7), p.acceleration(),
             graphplan.diagrams(shaper, divisions=12), f, f.plans, f.lever,
             graphplan.sheet(shaper, format="A1")]
    for view in views:
        _shows(view)


def test_views_carry_the_numbers_of_their_rooms(shaper):
    """A plan view's JSON is its position's entry of the whole plans' JSON; the fields pass through."""
    p = graphplan.plans(shaper, precision=0)
    whole = p.to_json()
    one = p.velocity(4).to_json()
    assert one == whole["positions"][4]
    assert p.mu_v == whole["positions"][4]["mu_v"]
    for e in one["velocity"].values():
        assert e["error_pct"] is None or abs(e["error_pct"]) < 1e-7
    with pytest.raises(graphplan.api.GraphplanError if hasattr(graphplan.api, "GraphplanError")
                       else Exception, match="no velocity plan at position 99"):
        p.velocity(99)


def test_the_builtin_scene_without_a_path():
    s = graphplan.load()
    assert graphplan.study(s).structure.formula == "I(0-1) → II(2-3)"


def test_sheet_saves_whole_files(tmp_path, monkeypatch):
    # the shaper as docs/api.md loads it (its source "examples/shaper.toml"): the A1 sheet its doctest
    # composes (test_docs_api_examples_run), which this worker then holds composed (7 s of CPU)
    monkeypatch.chdir(ROOT)
    out = graphplan.sheet(graphplan.load("examples/shaper.toml"), format="A1").save(tmp_path / "s.svg")
    assert out.read_text(encoding="utf-8").startswith("<svg")


def test_the_rooms_keep_their_layers():
    """import-linter: each room imports only rooms below it; argparse only in the command line."""
    exe = shutil.which("lint-imports") or str(Path(sys.executable).with_name("lint-imports"))
    if not os.path.exists(exe):
        pytest.fail("lint-imports (import-linter) is part of the test extra and must be installed")
    out = subprocess.run([exe, "--no-cache"], capture_output=True, text=True, cwd=ROOT)
    assert out.returncode == 0, out.stdout[-3000:]
    assert "BROKEN" not in out.stdout.upper().replace("0 BROKEN", "")


@pytest.mark.parametrize("name", ["shaper", "four_bar"])
def test_api_terminal_and_sheet_use_one_set_of_scales(name, capsys):
    """graphplan.plans(), `graphplan plans --json` and the A1 sheet: the same μl, μv, μa (one
    function gives them: sheets.kinematics.sheet_scales); the language changes none of them."""
    import json

    from graphplan.cli.main import main
    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.form import form
    from graphplan.sheets.kinematics import plan
    path = str(ROOT / "examples" / f"{name}.toml")
    api = graphplan.plans(path)
    assert main(["plans", path, "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert main(["plans", path, "--json", "--lang", "en"]) == 0
    en = json.loads(capsys.readouterr().out)
    st = graphplan.study(path).value
    sheet = plan(st, form("A1"), SheetOptions())[0].mu
    mu_a = next(p["mu_a"] for p in doc["positions"] if "mu_a" in p)
    assert (api.mu_l, api.mu_v, api.mu_a) == (doc["mu_l"], doc["positions"][0]["mu_v"], mu_a) \
        == (sheet["position"], sheet["velocity"], sheet["acceleration"])
    assert en["mu_l"] == doc["mu_l"] and en["positions"][0]["mu_v"] == doc["positions"][0]["mu_v"]


def test_the_structural_formula_branches_where_groups_hang_side_by_side():
    """A V-engine's two dyads both hang on the crank: the formula writes two chains from I(0-1), not
    one chain through both (review 13 #8); a shaper's rod-and-ram group hangs on the rocker's group:
    one chain."""
    from conftest import scene_study
    from review_scenes import VTWIN13
    assert scene_study(VTWIN13).structure.formula == "I(0-1) → II(2-3); I(0-1) → II(4-5)"
    shaper = Path(__file__).parent.parent / "examples" / "shaper.toml"
    assert graphplan.study(graphplan.load(shaper)).structure.formula == "I(0-1) → II(2-3) → II(4-5)"
