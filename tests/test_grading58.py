"""Stop 58 (web58): what a graded row says to a student — a zero graded by an absolute tolerance in
the quantity's unit, a cam key's wrong row said as a cam's (its division, the cam's angle; a cam has
no crank), and a refusal's bound written without e-notation."""
from __future__ import annotations

import math
import re
import tomllib
from pathlib import Path

import pytest

from graphplan.exact.positions import study
from graphplan.model.scene import build
from graphplan.teach.grading import Row, grade
from graphplan.teach.keys import make_key

ROOT = Path(__file__).resolve().parents[1]


@pytest.fixture(scope="module")
def slider_key():
    """The crank-slider of seed 004 with S1 at the crank's pivot: v_S1 and a_S1 are 0 at every angle."""
    text = (ROOT / "examples" / "crank_slider.toml").read_text().replace("points = { S1 = 0.4 }",
                                                                          "points = { S1 = 0.0 }")
    tree = tomllib.loads(text)
    key = make_key(study(build(tree, "cs.toml")), variant="01", scene=tree)
    key["_path"] = "key.json"
    return key


def _bound(note: str) -> tuple[float, str]:
    m = re.search(r"±([0-9.,]+)\u00a0?(\S+?)[ )]", note)
    assert m, note
    return float(m.group(1).replace(",", ".")), m.group(2)


def test_a_quantity_zero_at_every_angle_is_graded_by_an_absolute_bound_in_its_unit(slider_key):
    v_crank_pin = 293.07 * 0.064                 # ω1·OA: the largest |v| is at least this
    quantities = slider_key["quantities"]
    assert quantities["v_S1"]["scale"] == 0.0
    rows = [Row(1, "01", "1", "v_S1", 0.0), Row(2, "01", "1", "v_S1", 0.3), Row(3, "01", "1", "a_S1", 0.0)]
    g = grade({"01": slider_key}, rows)
    for lang in ("en", "uk"):
        note = g[0].says(lang)
        assert "1·10" not in note and "e-" not in note, note
        bound, unit = _bound(note)
        assert unit == ("m/s" if lang == "en" else "м/с"), note
        # 5 % (the tolerance) of 5 % (the near-zero fraction) of the largest |v| over the turn
        assert bound >= 0.05 * 0.05 * v_crank_pin * (1 - 1e-3), note
        assert bound <= 0.05 * 0.05 * v_crank_pin * (1 + 0.064 / 0.307) * 1.01, note
    assert "every crank angle" in g[0].note and "кожному куті кривошипа" in g[0].note_uk
    assert _bound(g[2].note)[1] == "m/s²"
    bound = _bound(g[0].note)[0]
    near = grade({"01": slider_key}, [Row(1, "01", "1", "v_S1", 0.9 * bound), Row(2, "01", "1", "v_S1", 1.2 * bound)])
    assert [r.status for r in near] == ["pass", "fail"]
    assert g[1].status == "fail" and g[0].status == "pass" and g[2].status == "pass"


def test_near_zero_at_a_dead_centre_says_its_bound_in_the_unit(slider_key):
    """v_B at position 0 (a dead centre) is 0; its bound is 5 % of 5 % of v_B's own largest |value|."""
    g = grade({"01": slider_key}, [Row(1, "01", "0", "v_B", 0.0)])[0]
    bound, unit = _bound(g.note)
    scale = slider_key["quantities"]["v_B"]["scale"]
    assert unit == "m/s" and bound == pytest.approx(0.0025 * scale, rel=1e-3)
    assert g.status == "pass" and g.error_pct is None


@pytest.fixture(scope="module")
def cam_key():
    from graphplan.exact.cam import solve
    from graphplan.model.cam import build as build_cam
    from graphplan.teach.camkeys import make_cam_key
    tree = tomllib.loads((ROOT / "examples" / "cam_translating.toml").read_text())
    key = make_cam_key(solve(build_cam(tree, "cam.toml")), variant="01", scene=tree)
    key["_path"] = "key.json"
    return key


def test_a_cam_keys_wrong_row_names_its_division_and_the_cams_angle_not_a_crank(cam_key):
    k = 2
    at = cam_key["positions"][k]
    g = grade({"01": cam_key}, [Row(1, "01", str(k), "s", at["values"]["s"] * 1.5 + 1e-3)])[0]
    assert g.status == "fail"
    for text in (g.note, g.note_uk):
        assert "crank" not in text and "кривошип" not in text, text
    assert f"division {k}" in g.note and f"поділці {k}" in g.note_uk
    turn = re.search(r"([0-9.]+)°", g.note)
    assert turn and float(turn.group(1)) == pytest.approx(at["turn_deg"], abs=0.05)
    assert "rise" in g.note


@pytest.mark.parametrize("lang", ["en", "uk"])
def test_a_negative_stroke_is_refused_without_e_notation(tmp_path, lang):
    from graphplan.cli.main import main
    text = (ROOT / "examples" / "cam_translating.toml").read_text()
    text = re.sub(r"(?m)^stroke = [0-9.]+", "stroke = -0.04", text)
    path = tmp_path / "cam.toml"
    path.write_text(text)
    import contextlib
    import io
    err = io.StringIO()
    with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
        code = main(["cam", str(path), "--lang", lang])
    line = err.getvalue().strip()
    assert code == 2 and len(line.splitlines()) == 1, line
    assert not re.search(r"\de[-+]?\d", line), line               # no 1e-05
    assert ("0.01 mm" if lang == "en" else "0,01 мм") in line and ("-0.04" if lang == "en" else "-0,04") in line


def test_plain_numbers_of_refusals():
    from graphplan.model.bounds import _plain
    assert _plain(1e-5) == "0.00001" and _plain(1e-5, "uk") == "0,00001" and _plain(1e6) == "1000000"
    assert _plain(5e-324) == "5·10⁻³²⁴" and _plain(-1.25e-300, "uk") == "-1,25·10⁻³⁰⁰"
    for v in (1e-5, 2.5e-7, 1e6, 123456789.0, 0.04, 7.0):
        assert float(_plain(v)) == v
