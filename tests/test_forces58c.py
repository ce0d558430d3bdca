"""Stop 58c (review 58 #1): a force is drawn ON its line of action — its arrow's line, extended, passes
through the point it acts at — or, where a link hides every place on that line and it is set aside in a
lane, its name stands nearest its own arrow. On COULISSE_REVIEW58's II(4-5) the weights G4 (at the
block's C) and G5 (at S5, 7 mm down the slotted lever 2° off vertical) were set 2.5 and 4.8 mm aside,
off the lines their arms h_G4, h_G5 end on, and «G4» stood nearer G5's arrow than its own."""
from __future__ import annotations

import pytest

from conftest import scene_force_plans
from graphplan.drawing.forces import _mu, group_record
from review_scenes import COULISSE_REVIEW58

pytestmark = pytest.mark.slow


def _to_line(p: complex, a: complex, b: complex) -> float:
    u = (b - a) / abs(b - a)
    return abs(((p - a) * u.conjugate()).imag)


def _to_segment(p: complex, a: complex, b: complex) -> float:
    d = b - a
    t = max(0.0, min(1.0, ((p - a) * d.conjugate()).real / abs(d) ** 2))
    return abs(p - (a + t * d))


def _name(text: str) -> str:
    return "".join(c for c in text if c not in "_{}^")


@pytest.mark.parametrize("scene", [COULISSE_REVIEW58], ids=["coulisse58"])
def test_every_force_is_drawn_on_its_line_or_named_nearest_its_own_arrow(scene):
    fp = scene_force_plans(scene)
    checked = 0
    for gp in fp.groups:
        rec = group_record(fp, gp)
        mu = _mu(fp, gp)
        at = {f.name: f.at / mu for f in gp.forces if f.force != 0}
        arrows = {q.text: (complex(*q.points[0]), complex(*q.points[1])) for q in rec.items
                  if q.kind == "vector" and q.role == "absolute" and q.text}
        labels = {_name(q.text): complex(*q.points[0]) for q in rec.items if q.kind == "text" and q.role == "label"}
        for name, (a, b) in arrows.items():
            if name not in at:
                continue
            checked += 1
            if _to_line(at[name], a, b) < 0.3:
                continue
            # set aside: its name nearest its own arrow of all the arrows drawn
            assert _name(name) in labels, (gp.label, name)
            mine = _to_segment(labels[_name(name)], a, b)
            others = {n: _to_segment(labels[_name(name)], *ab) for n, ab in arrows.items() if n != name}
            assert all(mine < d for d in others.values()), (gp.label, name, mine, others)
    assert checked >= 4


def test_the_coulisse_weights_lie_on_the_lines_their_arms_end_on():
    fp = scene_force_plans(COULISSE_REVIEW58)
    gp = next(g for g in fp.groups if g.label == "II(4-5)")
    rec = group_record(fp, gp)
    mu = _mu(fp, gp)
    arrows = {q.text: (complex(*q.points[0]), complex(*q.points[1])) for q in rec.items
              if q.kind == "vector" and q.role == "absolute" and q.text}
    for f in gp.forces:
        if f.name in ("G4", "G5"):
            a, b = arrows[f.name]
            assert _to_line(f.at / mu, a, b) < 0.05          # on its own (vertical) line of action
            assert ((b - a) / abs(b - a)).imag < -0.99        # still pointing down
