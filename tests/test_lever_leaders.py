"""The Zhukovsky lever's names read at a glance (issue 32, the six-bars' levers: leaders to 51 mm
across six lines, a teacher could not tell which force is which): each force's name by its arrow,
each arm's h by its own segment, each image's letter by its point — beside it, or on a leader no
longer than a reader follows at a glance, four letter heights and the gap (4 × 3.5 + 1 = 15 mm),
that crosses no arrow and no link's image (a name across an arrow reads as that arrow's) — where
the plan crowds, at most one name in ten past a glance and one in ten across an arrow.

Measured on the drawing itself (the record's leaders against every drawn primitive's ink), on the
examples' six-bars at the sheet's own μv, and, in the default run, on the shaper's lever at the
lab's μv and on generated shapers and slotters (tests/coursework_scenes.py)."""
from __future__ import annotations

import pytest

from conftest import example, scene_study
from coursework_scenes import shaper, slotter
from review_scenes import SIXBAR

LETTER = 3.5
GLANCE_MM = 4 * LETTER + 1.0      # the longest leader a reader follows without searching
THICK_HALF = 0.3                  # half width of a thick line (an arrow, a link's image): labels.THICK_HALF


def _cross(a: complex, b: complex, c: complex, d: complex) -> bool:
    """Whether the segments a–b and c–d cross (a proper intersection)."""
    def side(p, q, r):
        return ((q - p).conjugate() * (r - p)).imag
    return side(c, d, a) * side(c, d, b) < 0 and side(a, b, c) * side(a, b, d) < 0


def leader_report(rec) -> list[tuple[float, int, int]]:
    """Each leader of the drawing: (its length mm, how many thick primitives — arrows, links'
    images — it crosses, how many thin ones — construction, projections, arms, other leaders)."""
    from graphplan.drawing.labels import strokes
    leaders = [p for p in rec.items if p.kind == "segment" and p.role == "label"]
    drawn = [p for p in rec.items if p.kind not in ("text", "point") and p not in leaders]
    out = []
    for lead in leaders:
        a, b = complex(*lead.points[0]), complex(*lead.points[1])
        thick = thin = 0
        for q in drawn + [x for x in leaders if x is not lead]:
            if any(_cross(a, b, complex(*s), complex(*e)) for s, e, _ in strokes(q)):
                if q.line_width / 2 >= THICK_HALF:
                    thick += 1
                else:
                    thin += 1
        out.append((abs(b - a), thick, thin))
    return out


SHARE = 10     # at most one name in this many past a glance, and one across an arrow or a link


def _check(name: str, rec, strict: bool = False) -> None:
    """No more than one name in ``SHARE`` on a leader past a glance, nor across a thick line
    (``strict``: none at all)."""
    rep = leader_report(rec)
    names = sum(1 for q in rec.items if q.kind == "text" and q.layer == "labels")
    allowed = 0 if strict else names // SHARE
    long = [round(r[0], 1) for r in rep if r[0] > GLANCE_MM]
    across = [(round(r[0], 1), r[1]) for r in rep if r[1]]
    assert len(long) <= allowed, (name, names, long)
    assert len(across) <= allowed, (name, names, across)


def _lever(st, mu_v: float | None = None):
    from graphplan.drawing.forces import lever_record
    from graphplan.sheets import forces as sf
    from graphplan.sheets.compose import SheetOptions
    d = sf.ForceDrafter(st, SheetOptions(precision=0.5, sheet="forces"))
    return lever_record(d.fp() if mu_v is None else d.fp(None, None, mu_v), "uk")


def test_the_shapers_lever_names_beside_their_lines():
    """The shaping machine's lever at the lab's μv."""
    _check("shaper", _lever(example("shaper")))


@pytest.mark.parametrize("text", [
    shaper(1.6, 0.4, 0.5, 0.8, 0.6, 90.0, 40.0, 2000.0, 20.0),
    slotter(0.1, 0.35, 0.065, 0.3, 0.1, 120.0, 50.0, 1500.0, 25.0),
], ids=["shaper", "slotter"])
def test_generated_levers_names_beside_their_lines(text):
    """The same on a shaper and a slotter nobody drew (before: the shaper's 6 names of 30 on
    leaders to 30 mm or across arrows)."""
    from graphplan.exact.positions import study
    from graphplan.model.scene import loads
    _check("generated", _lever(study(loads(text, "<generated>"))))


@pytest.mark.slow
@pytest.mark.parametrize("scene", ["shaper", "slotter", "sixbar"])
def test_the_sheets_lever_names_beside_their_lines(scene):
    """On the A1 force sheet, at the μv the composition chose for the lever."""
    from graphplan.sheets import forces as sf
    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.form import form
    st = scene_study(SIXBAR) if scene == "sixbar" else example(scene)
    p, _, dr = sf.plan(st, form("A1"), SheetOptions(precision=0.5, sheet="forces"))
    _check(scene, dr.drawings(p.mu, "uk")["lever"][0])
