"""Review 11, mark 16, of the cam sheets: the pressure angle's diagram ϑ(φ) at the diagrams' μ_φ (it
had its own 2.5 °/mm beside their 0.79 °/mm), and the rocking cam's phase diagram large enough that
its numbers, R₀ and [ϑ] do not crowd by O (all within 15 mm of O at 1:1 on A1, about 45 mm across at
1:2 on the A3 set) — read off the drawn records, not off the code's own numbers."""
from __future__ import annotations

import tomllib

import pytest

from graphplan.exact.cam import solve
from graphplan.model.cam import build
from review_scenes import CAM_REV11


def _ordinate_x(rec, step: str) -> float:
    return next(q for q in rec.items if q.step == step).points[0][0]


def test_theta_under_the_diagrams_shares_their_phi_axis():
    """Where ϑ(φ) stands under the d²s/dφ² diagram (with_theta; apart places it as its own drawing):
    its φ origin on the diagrams' ordinate axes, its abscissa as long, under all three, in a box of
    its own clear of theirs, at their μ_φ."""
    from graphplan.drawing.cam import diagrams, phase_diagram
    from graphplan.graphic.cam import construct
    from graphplan.sheets import cam as sc
    sol = solve(build(tomllib.loads(CAM_REV11), "<rev11>"))
    g = construct(sol, None, 0.5, measure=False, series="rad")
    caps = sc._captions(g, sol.cam, "en")
    rec = sc.beside(diagrams(sol, g, "en"), phase_diagram(sol, g, "en"), caps, True, sc.pressure_below(sol, g, "en"))
    box = rec.bounds()
    placed = {p.name: p for p in sc.apart("diagrams", rec, box, [], rec.parts, rec.theta_at)}
    assert set(placed) == {"diagrams", "pressure"}
    dia, theta = placed["diagrams"].record, placed["pressure"].record
    x0 = _ordinate_x(theta, "ordinate ϑ")
    for key in "sva":
        assert _ordinate_x(dia, f"ordinate {key}") == pytest.approx(x0, abs=1e-9)
        end = next(q for q in dia.items if q.step == f"axis {key}").points[1][0]
        assert end == pytest.approx(next(q for q in theta.items if q.step == "axis ϑ").points[1][0], abs=1e-9)
    assert theta.scales["mu_phi"] == g.mu_phi
    low = min(y for q in dia.items if q.step.startswith("ordinate") for _, y in q.points)
    assert theta.bounds()[3] < low
    a, b = placed["diagrams"].box, placed["pressure"].box
    assert b[3] <= a[1] + 1e-9                    # the boxes apart, ϑ(φ)'s under the diagrams'


def _labels_by_O(rec) -> dict[str, float]:
    """Each lettering of the phase diagram with its distance (mm) from the drawn O."""
    O = complex(*next(q for q in rec.items if q.step == "O").points[0])
    out = {}
    for q in rec.items:
        if q.kind == "text" and q.text:
            x0, y0, x1, y1 = q.ink()
            out[q.text] = abs(complex(min(max(O.real, x0), x1), min(max(O.imag, y0), y1)) - O)
    return out


@pytest.mark.slow
@pytest.mark.parametrize("fmt", ["A1", "A3"])
def test_review_11s_rocking_cam_phase_diagram_and_theta(fmt):
    """Review 11's rocking knife-edge cam (ccw): the phase diagram at an enlarging scale finer than
    the profile's, its division numbers 0, 17 and 8, 9 and R₀ at least 15 mm from O; ϑ(φ) at the
    diagrams' μ_φ on the A1 sheet and on the A3 set; no sheet with a defect."""
    from graphplan.sheets.cam import build_cam_sheet
    from graphplan.sheets.compose import SheetOptions, defects
    from graphplan.sheets.form import form
    sheet = build_cam_sheet(build(tomllib.loads(CAM_REV11), "<rev11>"), form(fmt), SheetOptions(lang="en", sheet="cam"))
    assert defects(sheet) == []
    placed = {p.name: p.record for page in sheet.pages for p in page.placed}
    assert {"diagrams", "phase", "profile", "pressure", "table", "notes"} <= set(placed)
    assert placed["pressure"].scales["mu_phi"] == placed["diagrams"].scales["mu_phi"]
    mu_phase = placed["phase"].scales.get("mu_phase") or placed["diagrams"].scales["mu_phase"]
    assert mu_phase < 0.999 * placed["profile"].scales["mu_l"]
    near = _labels_by_O(placed["phase"])
    # |OC₀| lettered «R_0» or, where the R0 taken is over the smallest read, «R_0 = … mm» (stop 60)
    r0 = next(text for text in near if text == "R_0" or text.startswith("R_0 = "))
    for text in ("0, 17", "8, 9", r0):
        assert near[text] >= 15.0, (text, near[text])
