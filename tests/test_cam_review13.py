"""Reviews 12 and 13 on the cam sheet: no unlettered ray from O beside each [ϑ] line on the phase
diagram (review 12 #16, review 13 #15: the region of O hatched along the lines instead), no two division numbers on an axis within 1 mm of each
other (review 13 #5: "24" moved left off a jump line onto "23"), and the s chords of a phase that
missed its closing dashed (review 13 #16: kept solid 2 mm over ψ_max)."""
from __future__ import annotations

import itertools
import math
import tomllib

import numpy as np
import pytest

from graphplan.model.cam import build

# review 12's scene b: a knife-edge, trapezoidal rise, cosine return, clockwise
KNIFE_REV12 = '''
[cam]
follower = "translating"
stroke = 0.025
offset = 0.0073              # "auto" in the review: the exact optimum 7.304 mm rounded to 0.1 mm
roller_radius = 0
phases_deg = { rise = 100, dwell_far = 40, return = 130, dwell_near = 90 }
laws = { rise = "trapezoidal", return = "cosine" }
pressure_angle_deg = { rise = 30, return = 35 }
omega = 12
direction = "cw"
divisions = 8
'''

# review 13's scene b: a rocking roller, clockwise, trapezoidal rise 150°, parabolic return 75°
ROCKING_REV13 = '''
[cam]
follower = "rocking"
swing_deg = 24
arm = 0.11
centre_distance = 0.14
roller_radius = 0.012
phases_deg = { rise = 150, dwell_far = 30, return = 75, dwell_near = 105 }
laws = { rise = "trapezoidal", return = "parabolic" }
pressure_angle_deg = { rise = 40, return = 50 }
rpm = 90
direction = "cw"
divisions = 10
'''


@pytest.fixture(scope="module")
def knife():
    from graphplan.exact.cam import solve
    from graphplan.graphic.cam import construct
    sol = solve(build(tomllib.loads(KNIFE_REV12), "<rev12>"))
    return sol, construct(sol, 8, 0.5, measure=False)


def _step(rec, name):
    return next(q for q in rec.items if q.step == name)


def test_the_phase_diagram_has_no_ray_from_O_beside_its_lines_and_hatches_the_region(knife):
    """Only R₀ and e leave O (no unlettered ray to the points the [ϑ] lines pass, 1–2 mm beside
    them); the region of O is hatched along both [ϑ] lines below their crossing, each stroke on O's
    side of its line."""
    from graphplan.drawing.cam import phase_diagram
    sol, g = knife
    rec = phase_diagram(sol, g, "en")
    O = complex(*_step(rec, "O").points[0])
    from_O = {q.step for q in rec.items if q.kind in ("segment", "vector", "polyline")
              and any(abs(complex(*p) - O) < 1e-6 for p in q.points)}
    assert from_O <= {"R0", "offset e"}, from_O
    lines = [(complex(*_step(rec, f"[ϑ] line {ph}").points[0]), complex(*_step(rec, f"[ϑ] line {ph}").points[1]))
             for ph in (0, 1)]
    for j, (a, b) in enumerate(lines):
        strokes = [q for q in rec.items if q.step == f"region {j}"]
        assert len(strokes) >= 3
        d = (b - a) / abs(b - a)
        side = ((O - a) * d.conjugate()).imag
        for q in strokes:
            p, r = (complex(*z) for z in q.points)
            assert abs(((p - a) * d.conjugate()).imag) < 1e-9           # it starts on the line
            assert ((r - a) * d.conjugate()).imag * side > 0             # and goes to O's side
            # and below the other line's crossing: on O's side of the other line too
            oa, ob = lines[1 - j]
            od = (ob - oa) / abs(ob - oa)
            assert ((p - oa) * od.conjugate()).imag * ((O - oa) * od.conjugate()).imag > 0


def _close_numbers(rec) -> list:
    """Pairs of division numbers on one row whose ink comes within 1 mm."""
    nums = [q for q in rec.items if q.kind == "text" and q.step.startswith("division")]
    out = []
    for a, b in itertools.combinations(nums, 2):
        A, B = a.ink(), b.ink()
        if max(A[1] - B[3], B[1] - A[3]) < 1.0 and max(A[0] - B[2], B[0] - A[2]) < 1.0:
            out.append((a.step, a.text, b.text))
    return out


def test_no_two_division_numbers_closer_than_a_millimetre():
    """Review 13's rocking cam at its A3 set's sizes, redrawn with 16 divisions (the return's are
    4.69 mm apart at 1 °/mm): "24", moved left off the jump line at 25, stood 0.8 mm from "23" on
    the d²ψ/dφ² axis (and "24", "25" 0.97 mm apart under ψ) — no two numbers now within 1 mm, nor
    one on the jump's vertical."""
    from graphplan.drawing.cam import diagrams
    from graphplan.exact.cam import solve
    from graphplan.graphic.cam import construct
    sol = solve(build(tomllib.loads(ROCKING_REV13), "<rev13>"))
    g = construct(sol, 16, 0.5, size=2.8, profile_size=0.9, height=1.1, accel=0.55, measure=False, series=True)
    assert g.mu_phi == pytest.approx(math.radians(1.0))
    rec = diagrams(sol, g, "en")
    assert _close_numbers(rec) == []
    numbers = [q for q in rec.items if q.kind == "text" and q.step.startswith("division a")]
    assert {"0", "24", "33"} <= {q.text for q in numbers} and "32" not in {q.text for q in numbers}
    # nor on a jump of the curve: "24" (4.46 mm of ink right of its division) touched the vertical at 25
    curve = np.array(next(q for q in rec.items if q.step == "a(φ) exact").points)
    for q in numbers:
        x0, y0, x1, y1 = q.ink()
        for (ax, ay), (bx, by) in zip(curve[:-1], curve[1:]):
            if abs(ax - bx) < 1e-6 and x0 - 0.3 < ax < x1 + 0.3:
                assert max(ay, by) < y0 - 0.3 or min(ay, by) > y1 + 0.3, (q.text, ax)


def test_the_chords_of_a_phase_that_missed_its_closing_are_dashed_and_thinner(knife):
    """The first traverse of s (the chords before the closing error is laid back) dashed and
    thinner than every solid line of the diagram; a phase that closed keeps its chords' weight."""
    from graphplan.drawing.cam import diagrams
    from graphplan.graphic.record import DASHED_ROLES, ROLES
    sol, g = knife
    rec = diagrams(sol, g, "en")
    for ph in (0, 1):
        chords = [q for q in rec.items if q.step.startswith(f"chord s {ph} ")]
        assert chords
        if abs(g.closing[ph]) > 0:
            solid = min(q.line_width for q in rec.items if q.kind in ("segment", "polyline")
                        and q.role not in DASHED_ROLES and not q.step.startswith("chord s"))
            assert all(DASHED_ROLES.get(q.role) == "dashed" and q.line_width < solid for q in chords)
        else:
            assert all(q.line_width == ROLES["chord"] for q in chords)
    assert any(abs(c) > 0 for c in g.closing)
