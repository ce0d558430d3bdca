"""Review51 (the coupler's force sheet, group II(4-5) at the A1 sheet's 1:4): the slider's resistance
P_F, laid from F along the inclined guide, ended with its head on the head of the rod's inertia force
Φ4 laid from S4 — two arrowheads at one spot, "Φ4" beside the shared tip, read as either's. The truth
here is the drawn geometry measured: two arrows of different points end with their tips apart, and
each force's name stands nearest its own arrow."""
from __future__ import annotations

import pytest

from conftest import scene_study
from review_scenes import FORCE_COUPLER51

MU_L = 0.004          # the A1 sheet's groups (1:4)
TIPS_MM = 5.0         # two 2-3 mm arrowheads read as two when their tips are this far apart


@pytest.fixture(scope="module")
def groups():
    from graphplan.drawing.forces import group_record
    from graphplan.exact import kinetostatics
    from graphplan.graphic import forceplans
    st = scene_study(FORCE_COUPLER51)
    fp = forceplans.construct(st, float(kinetostatics.at_scene_angle(st)), mu_l=MU_L)
    return {gp.label: (gp, group_record(fp, gp, "en")) for gp in fp.groups}


def _arrows(rec) -> dict[str, tuple[complex, complex]]:
    return {q.text: (complex(*q.points[0]), complex(*q.points[-1])) for q in rec.items
            if q.kind == "vector" and q.text}


def _to_segment(z: complex, a: complex, b: complex) -> float:
    d = b - a
    t = 0.0 if abs(d) < 1e-12 else min(1.0, max(0.0, ((z - a) * d.conjugate()).real / abs(d) ** 2))
    return abs(z - (a + t * d))


def test_the_slider_force_and_the_rods_inertia_force_end_apart(groups):
    gp, rec = groups["II(4-5)"]
    at = {f.name: f.at / MU_L for f in gp.forces}
    assert abs(at["P_F"] - at["Φ4"]) > 10.0          # two points (F and S4)
    arrows = _arrows(rec)
    assert abs(arrows["P_F"][1] - arrows["Φ4"][1]) >= TIPS_MM


def test_no_two_points_arrows_share_a_tip(groups):
    for label, (gp, rec) in groups.items():
        at = {f.name: f.at / MU_L for f in gp.forces}
        tips = [(at[n], b) for n, (_, b) in _arrows(rec).items() if n in at]
        for i, (p, b) in enumerate(tips):
            for q, c in tips[i + 1:]:
                if abs(p - q) > 0.5:
                    assert abs(b - c) >= TIPS_MM, (label, b, c)


@pytest.mark.parametrize("name, text", [("P_F", "P_{F}"), ("Φ4", "Φ_{4}")])
def test_each_name_stands_nearest_its_own_arrow(groups, name, text):
    _, rec = groups["II(4-5)"]
    arrows = _arrows(rec)
    q = next(q for q in rec.items if q.kind == "text" and q.text == text)
    x0, y0, x1, y1 = q.ink()
    centre = complex((x0 + x1) / 2, (y0 + y1) / 2)
    own = _to_segment(centre, *arrows[name])
    assert all(own < _to_segment(centre, a, b) for n, (a, b) in arrows.items() if n != name), name
