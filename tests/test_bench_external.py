"""graphplan against pylinkage and mechanism (each skipped when absent): the other packages are
exact methods too, so the joints' positions, velocities and accelerations must agree to rounding
(pylinkage, closed forms) or to fsolve's tolerance (mechanism) — an independent check of both.
Without the packages the rows still come, saying "not installed"."""
from __future__ import annotations

import dataclasses
import math
import sys

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from conftest import ROOT, example, scene_study
from graphplan.bench import external as be

CLOSED_FORM_PCT = 1e-9   # pylinkage: rounding only (observed ~3e-12 %)
FSOLVE_PCT = 1e-6        # mechanism: fsolve's xtol 1.49e-8 on the angles (observed ~2e-8 %)

FOUR_BAR = (ROOT / "examples" / "four_bar.toml").read_text(encoding="utf-8")


def motions(name_or_study, n: int, build, run):
    study = example(name_or_study) if isinstance(name_or_study, str) else name_or_study
    case = be.case_of(study, "t", n)
    return case, be.graphplan_motion(study, case), run(build(case), n)


def test_case_reads_the_scene():
    case = be.case_of(example("four_bar"), "four_bar", 360)
    assert (case.kind, case.r, case.la, case.lb, case.branch) == ("RRR", 0.1, 0.35, 0.25, 1)
    assert case.pivot == 0 and case.ground == 0.3 and case.omega == pytest.approx(2 * math.pi)
    slider = be.case_of(example("crank_slider"), "crank_slider", 12)
    assert (slider.kind, slider.r, slider.la, slider.guide_angle) == ("RRP", 0.064, 0.307, 0.0)
    assert len(slider.phi_deg) == 12


def test_start_is_on_the_scenes_assembly():
    """Position 0 by the textbook construction: the right lengths, on the scene's side."""
    for branch in (1, -1):
        st_ = scene_study(FOUR_BAR.replace("B = 1 ", f"B = {branch} "))
        case = be.case_of(st_, "four_bar", 360)
        a, b = case.pin_at(case.phi_deg[0]), case.start()
        assert abs(b - a) == pytest.approx(0.35) and abs(b - 0.3) == pytest.approx(0.25)
        assert np.sign(np.imag(np.conj(0.3 - a) * (b - a))) == branch  # left of A→O2 for +1
    slider = be.case_of(example("crank_slider"), "crank_slider", 360)
    b = slider.start()
    assert b.imag == 0 and abs(b - slider.pin_at(slider.phi_deg[0])) == pytest.approx(0.307)
    assert b.real > 0


def test_rows_say_not_installed_when_absent(monkeypatch):
    for name in be.PACKAGES:
        monkeypatch.setitem(sys.modules, name, None)   # import → ImportError
    rows = be.external_rows(n_positions=36, repeats=1)
    assert [r["method"] for r in rows] == (["graphplan"] + ["pylinkage"] * 3 + ["mechanism"] * 2) * 2
    for r in rows:
        assert {"method", "setting", "time_s", "max_error_pct", "ratio_to_graphplan", "note"} <= set(r)
        if r["method"] == "graphplan":
            assert r["time_s"] > 0 and r["ratio_to_graphplan"] == 1.0 and "N=36" in r["setting"]
        else:
            assert r["note"] == "not installed" and r["time_s"] is None and r["max_error_pct"] is None


@pytest.mark.parametrize("name", ["four_bar", "crank_slider"])
def test_pylinkage_agrees(name):
    pytest.importorskip("pylinkage")
    case, ref, ext = motions(name, 360, be.pylinkage_model, be.pylinkage_derivatives)
    # the crank pin is where the angle puts it: both solvers step the same positions
    assert np.abs(ext.pos[0] - (case.pivot + case.r * np.exp(1j * np.radians(case.phi_deg)))).max() < 1e-14
    err = be.disagreement(ext, ref, case.r)
    assert max(err.values()) < CLOSED_FORM_PCT, err
    fast = be.pylinkage_step_fast(be.pylinkage_model(case), 360)
    assert be.disagreement(fast, ref, case.r)["pos_error_pct"] < CLOSED_FORM_PCT


@pytest.mark.parametrize("name", ["four_bar", "crank_slider"])
def test_mechanism_agrees(name):
    pytest.importorskip("mechanism")
    pytest.importorskip("mechanism.vectors")   # the vector-loop package, not another "mechanism"
    case, ref, ext = motions(name, 360, lambda c: be.mechanism_model(c, True), be.mechanism_run)
    err = be.disagreement(ext, ref, case.r)
    assert max(err.values()) < FSOLVE_PCT, err
    assert ext.note == ""   # fsolve converged everywhere


@pytest.mark.parametrize("branch", [1, -1])
def test_both_assemblies_agree_and_differ(branch):
    """The other assembly of the four-bar: still agreement, and the two assemblies are far apart
    (so agreement is no accident of the branch)."""
    pytest.importorskip("pylinkage")
    st_ = scene_study(FOUR_BAR.replace("B = 1 ", f"B = {branch} "))
    case, ref, ext = motions(st_, 90, be.pylinkage_model, be.pylinkage_derivatives)
    assert max(be.disagreement(ext, ref, case.r).values()) < CLOSED_FORM_PCT
    flipped = dataclasses.replace(case, branch=-branch)
    other = be.pylinkage_derivatives(be.pylinkage_model(flipped), 90)
    assert be.disagreement(other, ref, case.r)["pos_error_pct"] > 100.0


def test_a_wrong_assembly_is_flagged(monkeypatch):
    """Start the other packages on the other assembly: the rows must say they disagree."""
    pytest.importorskip("pylinkage")
    real = be.case_of
    monkeypatch.setattr(be, "case_of", lambda s, e, n: dataclasses.replace(real(s, e, n), branch=-1))
    rows = be.compare(example("four_bar"), "four_bar", 36, 1, packages=("pylinkage",))
    assert len(rows) == 4
    for r in rows[1:]:
        assert r["max_error_pct"] > 100.0 and "DISAGREES" in r["note"]


def test_rows_with_the_packages():
    pytest.importorskip("pylinkage")
    pytest.importorskip("mechanism.vectors")
    rows = be.external_rows(n_positions=36, repeats=1)
    assert len(rows) == 12
    for r in rows:
        assert r["time_s"] > 0 and r["ratio_to_graphplan"] > 0
        assert r["max_error_pct"] < FSOLVE_PCT and "DISAGREES" not in r["note"], r
        assert (r["version"] != "") == (r["method"] != "graphplan")


def four_bar_text(d: float, e: float, a: float, u: float, branch: int, direction: str) -> str:
    """A crank-rocker (crank 0.1) with |a − b| ≤ D − r and a + b ≥ D + r: b a fraction u
    of the way through the interval where the dyad assembles over the whole turn."""
    r, dist = 0.1, math.hypot(d, e)
    lo, hi = max(dist + r - a, a - dist + r), a + dist - r
    b = lo + u * (hi - lo)
    return f"""
[frame.points]
O1 = [0, 0]
O2 = [{d!r}, {e!r}]
[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = {r}
rpm = 60
direction = "{direction}"
[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = {a!r}
[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = {b!r}
[branch]
B = {branch}
"""


@settings(max_examples=25, deadline=None)
@given(d=st.floats(0.2, 0.5), e=st.floats(-0.1, 0.1), a=st.floats(0.15, 0.6), u=st.floats(0.05, 0.95),
       branch=st.sampled_from([1, -1]), direction=st.sampled_from(["ccw", "cw"]))
def test_random_crank_rockers_agree(d, e, a, u, branch, direction):
    """Any crank-rocker, either assembly, either sense: graphplan, pylinkage and mechanism agree."""
    pytest.importorskip("pylinkage")
    pytest.importorskip("mechanism.vectors")
    st_ = scene_study(four_bar_text(d, e, a, u, branch, direction))
    case, ref, ext = motions(st_, 360, be.pylinkage_model, be.pylinkage_derivatives)
    assert max(be.disagreement(ext, ref, case.r).values()) < CLOSED_FORM_PCT
    loops = be.mechanism_run(be.mechanism_model(case, False), 360)
    assert be.disagreement(loops, ref, case.r)["pos_error_pct"] < FSOLVE_PCT
