"""A cam with no far dwell (or no near dwell): the end of the rise and the start of the return are one
division turn, and on the profile the last division meets division 0 again. Their numbers were drawn
one over the other ("6" over "7") on the diagrams and the profile. With no far dwell the rise's end
and the return's start are one point of the cam and carry one number (stop 49: "6; 7" on one point
read as two; the return is numbered on from it, graphic.cam.division_numbers); on the profile the
last division meeting 0 (no near dwell) is lettered once with both numbers ("0; 12", "0, 12" in
English); no two division numbers' ink boxes come within the label check's 0.3 mm of each other, on
any drawing, for translating and rocking followers, knife-edge and roller, both senses; and each
diagram still numbers every division 0…N."""
from __future__ import annotations

import itertools
import re

import pytest

from graphplan.drawing.cam import diagrams, phase_diagram, pressure_diagram, pressure_scales, profile_drawing
from graphplan.exact.cam import solve
from graphplan.graphic.cam import construct
from graphplan.model.cam import build

NUMBER = re.compile(r"^\d+(?:[;,] \d+)*$")
GAP = 0.3        # mm: the label check's least paper between two letterings (drawing.labels.CHECK)


def _cam(follower: str, roller: float, sense: str, far: float, near: float, n: int = 6):
    rise, ret = (360.0 - far - near) * 0.55, (360.0 - far - near) * 0.45
    cam = {"follower": follower, "roller_radius": roller, "direction": sense, "divisions": n,
           "phases_deg": {"rise": rise, "dwell_far": far, "return": ret, "dwell_near": near},
           "laws": {"rise": "cosine", "return": "parabolic"}, "pressure_angle_deg": {"rise": 30, "return": 30},
           "omega": 10}
    if follower == "rocking":
        cam |= {"swing_deg": 20, "arm": 0.1, "centre_distance": 0.12,
                "pressure_angle_deg": {"rise": 40, "return": 45}}
    else:
        cam |= {"stroke": 0.03, "offset": -0.005 if sense == "ccw" else "auto"}
    return build({"title": "t", "cam": cam}, "<shared divisions>")


CASES = [("translating", 0.008, "ccw", 0.0, 120.0), ("translating", 0.0, "cw", 60.0, 0.0),
         ("translating", 0.0, "ccw", 0.0, 0.0), ("rocking", 0.01, "ccw", 0.0, 120.0),
         ("rocking", 0.0, "cw", 0.0, 0.0), ("rocking", 0.01, "cw", 40.0, 0.0)]


def _numbers(rec):
    """The division numbers (the ϑ axis's graduation values are numbers too, not divisions)."""
    return [q for q in rec.items if q.kind == "text" and NUMBER.match(q.text) and q.step != "ϑ graduation"]


def _divisions(texts) -> set[int]:
    return {int(t) for q in texts for t in re.split(r"[;,] ", q.text)}


@pytest.mark.parametrize("lang", ["uk", "en"])
@pytest.mark.parametrize("case", CASES, ids=lambda c: f"{c[0]}-{'roller' if c[1] else 'knife'}-{c[2]}-far{c[3]:g}-near{c[4]:g}")
def test_shared_divisions_are_numbered_once_and_no_two_numbers_overlap(case, lang):
    sol = solve(_cam(*case))
    g = construct(sol, measure=False)
    far, near = case[3], case[4]
    n_last = len(g.phi) - 1 - (far == 0.0)          # the points' last number
    mu_phi, mu_t = pressure_scales(sol, 240.0, 100.0)
    drawn = {"diagrams": diagrams(sol, g, lang), "phase": phase_diagram(sol, g, lang),
             "profile": profile_drawing(sol, g, lang), "pressure": pressure_diagram(sol, g, lang, mu_phi, mu_t)}
    sep = "; " if lang == "uk" else ", "
    for name, rec in drawn.items():
        texts = _numbers(rec)
        for a, b in itertools.combinations(texts, 2):
            A, B = a.ink(), b.ink()
            apart = A[2] + GAP <= B[0] or B[2] + GAP <= A[0] or A[3] + GAP <= B[1] or B[3] + GAP <= A[1]
            assert apart, (name, a.text, b.text, A, B)
        # no number is drawn twice on one drawing (a shared spot carries both numbers, once)
        seen = [int(t) for q in texts for t in re.split(r"[;,] ", q.text)]
        if name != "diagrams":          # the diagrams number each of their three φ axes
            assert len(seen) == len(set(seen)), (name, sorted(seen))
    # every division on each diagram's φ axis; with no far dwell the rise's end one number, once a φ axis
    rise_end = (len(g.phi) - 1) // 2
    assert _divisions(_numbers(drawn["diagrams"])) == set(range(n_last + 1))
    if far == 0.0:
        assert not any(sep in q.text for q in _numbers(drawn["diagrams"]))
        assert sum(q.text == str(rise_end) for q in _numbers(drawn["diagrams"])) == 3    # s, ds/dφ, d²s/dφ²
        assert sum(q.text == str(rise_end) for q in _numbers(drawn["phase"])) == 1
    if near == 0.0:    # the profile closes on itself: the last division meets 0 there
        assert any(q.text == f"0{sep}{n_last}" for q in _numbers(drawn["profile"]))
    else:
        assert not any(sep in q.text and q.text.startswith("0" + sep) for q in _numbers(drawn["profile"]))


# -- the rocking cam's A1 sheet and the A3 set filled (the camfix round) ----------------------------------

@pytest.mark.slow
@pytest.mark.parametrize("lang", ["uk", "en"])
def test_the_rocking_phase_diagram_stands_at_the_top_and_its_room_goes_to_the_pressure_diagram(lang):
    """examples/cam_rocking.toml on A1: the phase diagram (nothing reads across from ψ) level with the
    ψ diagram's top — it hung from the ψ axis over a blank 100 mm high —, the pressure angle's diagram under the diagrams
    at their μ_φ and 2 °/mm or finer, the sheet under 37 % empty (35.3 / 34.3 % before; 32.0 / 29.7 %
    with ϑ(φ) under the notes; 35.4 % (uk) since ϑ(φ) takes the diagrams' μ_φ, review 11 #16, and
    36.1 / 35.6 % since the phase diagram draws no unlettered ray from O, review 12 #16)."""
    from conftest import example_sheet
    from graphplan.sheets.compose import defects
    from sheetfill import empty_share
    sheet = example_sheet("cam_rocking", "cam", "A1", lang)     # the gallery's (shared: conftest)
    assert defects(sheet) == []
    placed = {p.name: p for p in sheet.placed}
    dia, phase = placed["diagrams"].record, placed["phase"].record
    assert abs(dia.bounds()[3] - phase.bounds()[3]) < 1.0
    assert placed["pressure"].record.scales["mu_theta"] <= 2.0
    assert placed["pressure"].record.scales["mu_phi"] == dia.scales["mu_phi"]
    assert empty_share(sheet) < 0.37


@pytest.mark.slow
def test_an_a3_set_carries_the_pressure_diagram_beside_the_profile():
    """examples/cam_translating.toml on A3: the third sheet (Table 1 and the notes) stood half blank,
    then the profile's (61 %, issue 32): the pressure angle's diagram goes on a drawing's sheet at
    the diagrams' μ_φ (review 11, mark 16) and 2 °/mm or finer — under s, which has a sheet of its
    own (review 13 #7: one sheet drew a phase's ds/dφ under LEGIBLE_MM) —, no fifth sheet."""
    from conftest import example
    from graphplan.sheets.cam import build_cam_sheet
    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.form import form
    sheet = build_cam_sheet(example("cam_translating"), form("A3"), SheetOptions(lang="uk", sheet="cam"))
    pages = [{p.name: p for p in page.placed} for page in sheet.pages]
    assert len(pages) == 4
    assert {"phase", "profile"} <= set(pages[2]) and {"table", "notes"} <= set(pages[-1])
    (pressure,) = [page["pressure"] for page in pages[1:] if "pressure" in page]
    assert pressure.record.scales["mu_theta"] <= 2.0
    assert pressure.record.scales["mu_phi"] == pages[0]["diagrams"].record.scales["mu_phi"]
