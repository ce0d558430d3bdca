"""Review 12 #17: on the force sheet's scheme of the six-bar (1:5, the crank O1A 14 mm) Φ1, the
crank's centrifugal force, ran beside the crank across the rod AB and read as a double line; G1 ran
down from S1 through O1's hatched support. Read off the drawn scheme: every support clear of every
force's arrow; a force along its link drawn parallel to it a lane aside, across no other link, joined
to its point by a thin stroke."""
import math

from conftest import scene_study

MU_L = 0.005        # the A1 sheet's scheme (m/mm)
CRANK_M = 0.07      # O1A of SIXBAR12 (m)


def _segment_gap(a: complex, b: complex, c: complex, d: complex) -> float:
    """The least distance (mm) between two segments, sampled along each every 0.1 mm."""
    def to(z, p, q):
        e = q - p
        t = 0.0 if abs(e) < 1e-12 else min(max(((z - p) * e.conjugate()).real / abs(e) ** 2, 0.0), 1.0)
        return abs(z - (p + t * e))
    n, m = max(2, int(abs(b - a) / 0.1)), max(2, int(abs(d - c) / 0.1))
    return min(min(to(a + (b - a) * k / n, c, d) for k in range(n + 1)),
               min(to(c + (d - c) * k / m, a, b) for k in range(m + 1)))


def _crosses(a: complex, b: complex, c: complex, d: complex) -> bool:
    def cross(p, q):
        return p.real * q.imag - p.imag * q.real
    r, s = b - a, d - c
    den = cross(r, s)
    if abs(den) < 1e-12:
        return False
    t, u = cross(c - a, s) / den, cross(c - a, r) / den
    return 0.0 < t < 1.0 and 0.0 < u < 1.0


def _scheme():
    from graphplan.drawing.forces import mechanism_record
    from graphplan.sheets import forces as sf
    from graphplan.sheets.compose import SheetOptions
    from review_scenes import SIXBAR12
    fp = sf.ForceDrafter(scene_study(SIXBAR12), SheetOptions(precision=0.5, sheet="forces")).fp(MU_L)
    return mechanism_record(fp, "uk")


def test_the_cranks_forces_clear_its_support_and_its_line():
    rec = _scheme()
    arrows = {q.text: (complex(*q.points[0]), complex(*q.points[1])) for q in rec.items
              if q.kind == "vector" and q.role != "head" and q.text}
    strokes = [(complex(*q.points[0]), complex(*q.points[1])) for q in rec.items
               if q.kind == "segment" and q.layer == "frame"]
    assert len(strokes) >= 3 * 8                       # three pivots' supports: triangle, bar, hatching
    for name, (a, b) in arrows.items():               # no arrow through a support's strokes
        gap = min(_segment_gap(a, b, p, q) for p, q in strokes)
        assert gap >= 0.3, (name, gap)
    # the crank by the closed form: O1 at the origin, A the ring O1A/μl = 14 mm from it
    rings = [complex(*q.points[0]) for q in rec.items if q.kind == "point" and q.role == "joint"]
    o1 = min(rings, key=abs)
    assert abs(o1) < 1e-6
    a_ = min(rings, key=lambda z: abs(abs(z - o1) - CRANK_M / MU_L))
    assert abs(abs(a_ - o1) - CRANK_M / MU_L) < 1e-6
    axis = (a_ - o1) / abs(a_ - o1)
    t, h = arrows["Φ_{1}"] if "Φ_{1}" in arrows else arrows["Φ1"]
    along = (h - t) / abs(h - t)
    assert abs(math.degrees(math.asin(max(-1.0, min(1.0, (along * axis.conjugate()).imag))))) < 1.0
    assert (along * axis.conjugate()).real > 0            # outward, O1 → A (ε1 = 0: centrifugal)
    side = ((t - o1) * axis.conjugate()).imag
    assert abs(side) >= 2.0, side                           # a lane aside, not on the crank's line
    links = [(complex(*p), complex(*r)) for q in rec.items if q.layer == "mechanism" and q.role == "link"
             and q.kind in ("segment", "polyline") for p, r in zip(q.points, q.points[1:])]
    others = [(p, r) for p, r in links if min(abs(p - o1), abs(r - o1)) > 1e-6 or
              max(abs(p - a_), abs(r - a_)) > 1e-6]
    others = [(p, r) for p, r in others if not ({round(p.real, 6), round(r.real, 6)} ==
                                                {round(o1.real, 6), round(a_.real, 6)})]
    assert not any(_crosses(t, h, p, r) for p, r in others)
    s1 = o1 + 0.5 * (a_ - o1)                              # S1 at the crank's middle (the scene)
    thin = [(complex(*q.points[0]), complex(*q.points[1])) for q in rec.items
            if q.kind == "segment" and q.role == "projection"]
    assert any(abs(p - s1) < 1e-6 and abs(r - t) < 1e-6 for p, r in thin)   # joined to S1
