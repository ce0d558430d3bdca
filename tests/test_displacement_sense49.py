"""Stop 49: the diagrams' displacement is the textbook's — measured from the extreme position 0 and
written ≥ 0 on the way out (seed 002: s from B_0; a rocker's ψ likewise), whichever way the output
swings; its ω, ε (v, a) + in the sense it grows. Checked against the closed form of the rocking
coulisse (the line OA through the crank pin: ψ(φ) = |∠(A(φ) − O) − ∠(A_0 − O)|, position 0 where OA
is tangent to the crank circle) and against the drawn diagram."""
from __future__ import annotations

import math

import numpy as np
import pytest

import review_scenes
from conftest import scene_study
from graphplan.graphic.diagrams import chord_diagrams
from graphplan.graphic.plans import build_plans
from graphplan.report.plans import plans_json
from graphplan.sheets.kintables import readings_table, sign_note


@pytest.fixture(scope="module")
def coulisse49():
    st = scene_study(review_scenes.LINK49)
    return st, chord_diagrams(st, divisions=12, L=200.0, H1=25.0, H2=30.0)


def closed_form_psi(k: int) -> float:
    """LINK49: O at the origin, O1 = (0, 0.22), O1A = 0.09, clockwise; position 0 is the extreme
    position where OA ⟂ O1A (cos α = r/d from O1O), the working stroke's start."""
    r, d = 0.09, 0.22
    th0 = math.atan2(-d, 0.0) - math.acos(r / d)     # 204.15°, the sheet prints 204,1°

    def gamma(th: float) -> float:
        return math.atan2(d + r * math.sin(th), r * math.cos(th))
    return abs(gamma(th0 - math.radians(30.0 * k)) - gamma(th0))


def _cells(rec) -> list[list[str]]:
    """The table's rows, its texts by their baselines, left to right."""
    rows: dict[float, list] = {}
    for p in rec.items:
        if p.kind == "text":
            rows.setdefault(round(p.points[0][1], 1), []).append((p.points[0][0], p.text))
    return [[t for _, t in sorted(r)] for _, r in sorted(rows.items(), reverse=True)]


def _value(cell: str) -> float:
    return float(cell.rstrip("*").replace("−", "-").replace(",", "."))


def test_the_coulisse_swinging_clockwise_has_psi_from_its_extreme_position_positive(coulisse49):
    st, d = coulisse49
    pl = build_plans(st)
    rows = _cells(readings_table(d, plans_json(pl), "uk", 4, 0.5))
    psi = next(r for r in rows if r[0].startswith("ψ"))
    exact = rows[rows.index(psi) + 1]
    assert exact[0] == "точно"
    for k in range(12):
        truth = closed_form_psi(k)
        assert _value(exact[k + 1]) == pytest.approx(truth, abs=6e-4), k
        assert _value(psi[k + 1]) >= 0.0
        assert _value(psi[k + 1]) == pytest.approx(truth, abs=0.012), k   # read off a 0.5-mm ruler
    # the diagram drawn rising: its ordinates (mm) ≥ 0, the largest the swing ψ_max = 2·asin(r/d)
    assert np.all(d.drawn.s >= -0.5)
    assert float(np.max(d.drawn.s)) * d.mu_s == pytest.approx(2 * math.asin(0.09 / 0.22), rel=0.02)
    # ω3 on the way out (positions 1–7) is + in the sense ψ3 grows, as the diagram draws it
    omega = next(r for r in rows if r[0].startswith("−ω"))     # −ω3: + clockwise (review 55 #5)
    assert all(_value(c) > 0 for c in omega[2:8])
    # and the notes say which sense that is (clockwise), the plans' tables keeping + counter-clockwise
    for lang, cw, ccw in (("uk", "+ за годинниковою стрілкою", "+ проти годинникової стрілки"),
                          ("en", "+ clockwise", "+ counter-clockwise")):
        said = sign_note(st, d, lang)
        assert cw in said and ccw in said and said.index(ccw) < said.index(cw)


def test_a_rocker_driven_by_a_slider_swings_from_its_extreme_position():
    """kin49's own six-bar (an offset crank-slider O-A-B driving the rocker O2C through BC): the
    rocker stops where the slider does (v_B = 0 ⇒ ω4 = ω5 = 0), so position 0 (B's far dead centre)
    is its extreme too; ψ5 is drawn ≥ 0 from it and peaks at the swing between the two dead
    centres' C — B at √((l ± r)² − e²) on the guide y = e, C the circles' (B, BC) ∩ (O2, O2C)
    intersection left of B→O2 (0.4676 rad; the sheet prints ψmax = 26,79°)."""
    st = scene_study(review_scenes.OWN_SIX49)
    d = chord_diagrams(st, divisions=12, L=200.0, H1=30.0, H2=25.0, precision=0.0)
    r, l, e, bc, oc, o2 = 0.08, 0.3, 0.02, 0.22, 0.15, complex(0.35, 0.25)

    def rocker(xb: float) -> float:
        b = complex(xb, e)
        dist = abs(o2 - b)
        along = (bc ** 2 - oc ** 2 + dist ** 2) / (2 * dist)
        u = (o2 - b) / dist
        c = b + u * along + 1j * u * math.sqrt(bc ** 2 - along ** 2)    # C left of B→O2 (the drawn branch)
        return math.atan2(c.imag - o2.imag, c.real - o2.real)
    swing = abs(rocker(math.sqrt((l + r) ** 2 - e ** 2)) - rocker(math.sqrt((l - r) ** 2 - e ** 2)))
    assert d.sign == -1                       # it swings clockwise: mirrored against Table 1's sign
    assert np.all(d.exact.s >= -1e-6)
    assert float(np.max(d.exact.s)) * d.mu_s == pytest.approx(swing, rel=1e-3)
