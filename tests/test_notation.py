"""The kinematics notation (issue 32, item 5): normal-component ends lettered by their link, the
diagrams' scales named apart from the plans', ω and ε no finer than the vector they are read from,
one word for the crank."""
from __future__ import annotations

import re
from pathlib import Path

import pytest

from conftest import ROOT, example
from graphplan.graphic.diagrams import chord_diagrams
from graphplan.graphic.plans import build_plans
from graphplan.drawing.diagrams import scale_lines
from graphplan.report.plans import figures


@pytest.mark.parametrize("name", ["four_bar", "shaper", "slotter", "crank_slider"])
def test_normal_ends_are_lettered_by_their_link(name):
    """Every normal component a^n_CP laid off on an acceleration plan ends at a point lettered n_k, k
    the number of the link it belongs to (the link turning about P) — each one lettered."""
    st = example(name)
    plans = build_plans(st, accel=[1, 4])
    links = {link.number: name_ for name_, link in st.mech.links.items()}
    for q in plans.positions:
        acc = q.acceleration
        if acc is None:
            continue
        normals = [e for e in acc.entries.values() if e.kind == "normal"]
        assert normals
        lettered = [n for label in acc.labels for n in re.findall(r"n_(\d+)", label.text)]
        # one letter a normal component (none for the crank's own when ε1 = 0: π a is it)
        counted = [e for e in normals if not (e.key == f"n_{st.mech.crank.pin}{st.mech.crank.pivot}"
                                               and st.mech.crank.epsilon == 0)]
        assert len(lettered) == len(counted), (lettered, [e.key for e in counted])
        assert all(int(k) in links for k in lettered)
        assert len(set(lettered)) == len(lettered)          # by link: no two ends share a number here


def test_the_diagrams_scales_are_named_apart_from_the_plans():
    d = chord_diagrams(example("lab_crank_slider"), divisions=8, L=240, H1=25, H2=25)
    said = " ".join(scale_lines(d, "en"))
    # lower case as the lab writes μ_t beside them, named apart from the plans' μ_v, μ_a by the point
    assert "μ_{sB} = " in said and "μ_{vB} = μ_{sB}/(μ_t·H_1)" in said and "μ_{aB} = μ_{vB}/(μ_t·H_2)" in said
    assert not re.search(r"μ_\{?[SVA]\b", said)
    assert "μ_v" not in said and "μ_a" not in said
    rocker = chord_diagrams(example("four_bar"), divisions=12)
    assert "μ_ω = μ_ψ/(μ_t·H_1)" in " ".join(scale_lines(rocker, "uk"))      # a rocker's angle ψ


@pytest.mark.parametrize("mm, figs", [(2.0, 2), (23.0, 3), (23.4, 3), (61.5, 3), (123.5, 4), (123.0, 4),
                                      (0.2, 2), (8.0, 2), (None, 4)])
def test_figures_of_a_ruler_reading(mm, figs):
    assert figures(mm, 0.5) == figs


def test_omega_no_finer_than_its_vector(capsys):
    """ω_AB read off a 2-mm vector ab is written 0,11 (two figures), not 0,1143."""
    from graphplan.cli.main import main
    assert main(["plans", str(ROOT / "examples" / "four_bar.toml"), "--mu-v", "0.02"]) == 0
    out = capsys.readouterr().out
    row = next(line for line in out.splitlines() if line.split()[:1] == ["2"])
    assert "0,11" in row.split() and "0,1143" not in row


def test_one_word_for_the_crank():
    """The crank is "кривошип" on every sheet and table (the dynamics charts said "корба")."""
    for path in (ROOT / "graphplan").rglob("*.py"):
        text = Path(path).read_text(encoding="utf-8")
        assert "корб" not in text.lower(), path
