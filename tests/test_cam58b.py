"""Review 58 #5 on the cam sheet, a translating roller follower with a GIVEN R0 = 40 mm below the
smallest (45,88 mm; e = −6 mm, the cam clockwise):

- the phase diagram's caption says «найменший і заданий R₀»: both centres are drawn — the given O,
  its |OC₀| lettered with its value, and O_min on O's offset line where the binding [ϑ] line crosses
  it, below O (O outside the allowed region), lettered once;
- «*» marks both an error past 5 % (Table 2) and a pressure angle past [ϑ] (32,81°* in the notes and on
  ϑ(φ)): the notes' legend says each meaning that occurs, in uk and en."""
from __future__ import annotations

import math

import pytest

from graphplan.drawing.cam import phase_diagram
from graphplan.exact.cam import solve
from graphplan.graphic.cam import construct
from graphplan.model.cam import load
from graphplan.report.cam import cam_json
from graphplan.sheets.cam import notes
from review_scenes import CAM58B_SMALL_R0


@pytest.fixture(scope="module")
def small(tmp_path_factory):
    path = tmp_path_factory.mktemp("cam58b") / "cam58b.toml"
    path.write_text(CAM58B_SMALL_R0, encoding="utf-8")
    sol = solve(load(path))
    return sol, construct(sol, series="rad")


def test_o_min_is_marked_below_the_given_o(small):
    sol, g = small
    rec = phase_diagram(sol, g, "uk")
    mu = rec.scales["mu_phase"]
    (o,) = [complex(*q.points[0]) for q in rec.items if q.step == "O" and q.kind == "point"]
    (om,) = [complex(*q.points[0]) for q in rec.items if q.step == "O min" and q.kind == "point"]
    assert sum(1 for q in rec.items if q.kind == "text" and q.text == "O_{min}") == 1
    assert any(q.kind == "text" and q.text == "R_0 = 40 мм" for q in rec.items)
    # on O's offset line (parallel to the follower's axis), below O by the two radii's legs over μ
    assert abs(om.real - o.real) < 1e-9 and om.imag < o.imag - 6.0
    e = 0.006
    assert (o.imag - om.imag) * mu == pytest.approx(math.sqrt(g.R0_drawn ** 2 - e ** 2) - math.sqrt(0.04 ** 2 - e ** 2),
                                                    rel=1e-6)
    # O_min on the binding [ϑ] line (0 mm from it), O outside the region (past that line, beyond it)
    gaps = []
    for ph in (0, 1):
        (x0, y0), (x1, y1) = next(q for q in rec.items if q.step == f"[ϑ] line {ph}").points
        p, d = complex(x0, y0), complex(x1 - x0, y1 - y0) / abs(complex(x1 - x0, y1 - y0))
        gaps.append(abs(((om - p) * d.conjugate()).imag))
    assert min(gaps) == pytest.approx(0.0, abs=0.3)
    # the smallest R0 drawn is the exact one to the ruler (independent: the notes' exact 45,883 mm)
    assert g.R0_drawn * 1000 == pytest.approx(45.88, abs=0.25)


def test_the_legend_says_both_meanings_of_the_star(small):
    sol, g = small
    doc = cam_json(sol, g, "")
    uk, en = notes(doc, "uk", sol.cam), notes(doc, "en", sol.cam)
    assert any("32,81°*" in x for x in uk)          # the rise's ϑ over [ϑ] = 30°, marked
    (luk,) = [x for x in uk if x.startswith("* — ")]
    (len_,) = [x for x in en if x.startswith("* — ")]
    assert "кут тиску понад допустимий" in luk and "pressure angle past the allowed" in len_
    # Table 2's δ past 5 % here too (5,26* at position 1): both meanings in one legend
    assert "понад 5 %" in luk and "past 5 %" in len_
