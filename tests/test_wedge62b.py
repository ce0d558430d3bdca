"""Stop 62 (wedge62b): the wedge press's ram group and the wedge's size.
1. The forces at the ram's C (P_C, G4, G5, Φ4, Φ5, all on the ram's vertical axis) are not laid over
   its drawn bar C–D, where only their heads showed. On group II(4-5) they go one after the other on
   the free stretch of the line below C, as the textbook draws them.
2. The wedge's inclined face covers C's whole travel along it, as the textbook's wedge covers the
   block's travel. Its back side is not drawn on the ram's axis.
Truths: the scene's geometry. C stays on x = 0.34 m. B moves on the guide y = −0.02 m, driven by the
crank r = 0.05 m and the rod l = 0.22 m from O = (0, 0). So B's extreme x are √((l ± r)² − e²), and C's
horizontal reach from B is 0.34 − x_B,min."""
from __future__ import annotations

import math

import pytest

from conftest import group_of, scene_force_plans, scene_study
from review_scenes import WEDGE62_PRESS

HEAD_MM = 4.0        # a force arrow's head (thick vector: 4 mm)
SEEN_MM = 3.0        # each arrow of the ram group shows at least this much of its shaft off every drawn bar
OFF_MM = 1.0         # … "off": farther than this from any link, block or the wedge
X_C, E, R, L = 0.34, 0.02, 0.05, 0.22
XB_MIN = math.sqrt((L - R) ** 2 - E ** 2)
XB_MAX = math.sqrt((L + R) ** 2 - E ** 2)


def _dist(z: complex, a: complex, b: complex) -> float:
    d = b - a
    if abs(d) < 1e-12:
        return abs(z - a)
    t = max(0.0, min(1.0, ((z - a) * d.conjugate()).real / abs(d) ** 2))
    return abs(z - (a + t * d))


def _lines(rec) -> list[tuple[complex, complex]]:
    """Every drawn bar of the mechanism (links, the wedge's triangle, blocks). The frame's thin guide
    lines are left out: a thick arrow along one still shows (P_C down the ram's guide)."""
    out = []
    for it in rec.items:
        if it.layer == "mechanism" and it.kind in ("polyline", "polygon", "segment"):
            ps = [complex(*p) for p in it.points]
            if it.kind == "polygon":
                ps = ps + ps[:1]
            out += list(zip(ps, ps[1:]))
    return out


def _seen(a: complex, b: complex, lines, n: int = 200) -> float:
    """How much of the arrow's shaft (tail to its head's base) lies farther than ``OFF_MM`` from
    every drawn bar (mm)."""
    shaft = abs(b - a) - HEAD_MM
    if shaft <= 0.0:
        return 0.0
    u = (b - a) / abs(b - a)
    k = sum(1 for i in range(n) if min(_dist(a + u * shaft * (i + 0.5) / n, p, q) for p, q in lines) > OFF_MM)
    return shaft * k / n


def _arrows(rec) -> list[tuple[complex, complex]]:
    return [tuple(complex(*p) for p in it.points) for it in rec.items if it.kind == "vector" and it.layer == "vectors"]


@pytest.fixture(scope="module")
def fp():
    return scene_force_plans(WEDGE62_PRESS)


def _c(fp) -> complex:
    lk = fp.ks.mech.links["C"]
    return complex(fp.ks.kin.bodies["C"].at(lk.local["C"])[0][0]) / fp.mu_l


def test_the_ram_groups_arrows_show_their_shafts(fp):
    """On group II(4-5) every arrow shows ≥ 3 mm of its shaft off every drawn bar. The vertical ones
    (P_C, G4, G5, Φ4, Φ5) lie on the ram's axis through C, below C, one after the other, not over the
    bar C–D (main: G5, Φ4, Φ5 lay along the bar, 0 mm of shaft seen)."""
    from graphplan.drawing.forces import group_record
    rec = group_record(fp, group_of(fp, "II(4-5)"))
    lines, arrows = _lines(rec), _arrows(rec)
    assert len(arrows) == 7, arrows         # P_C, G4, G5, Φ4, Φ5, R05, R34
    seen = [round(_seen(a, b, lines), 1) for a, b in arrows]
    assert min(seen) >= SEEN_MM, list(zip(arrows, seen))
    # the group's C: where R05 (horizontal) and R34 start
    c = next(a for a, b in arrows if abs((b - a).imag) < 1e-6)
    vertical = sorted([(a, b) for a, b in arrows if abs((b - a).real) < 1e-6], key=lambda ab: -max(ab[0].imag, ab[1].imag))
    assert len(vertical) == 5, vertical
    for a, b in vertical:
        assert abs(a.real - c.real) < 1e-6 and abs(b.real - c.real) < 1e-6      # on the ram's axis
        assert max(a.imag, b.imag) <= c.imag + 1e-6                              # below C: off the bar
    for (a, b), (p, q) in zip(vertical, vertical[1:]):
        assert min(p.imag, q.imag) < max(p.imag, q.imag) < min(a.imag, b.imag)  # one after the other


def test_the_schemes_arrows_at_c_show_their_shafts(fp):
    """On the force scheme every vertical arrow at C (within 10 mm of the ram's axis, 40 mm of C) shows ≥ 3 mm of its
    shaft. The wedge's triangle lies under C and the line below P_C is taken, so some of them are set
    beside the ram. Main: G4 and G5 along the bar, 0 mm seen."""
    from graphplan.drawing.forces import mechanism_record
    rec = mechanism_record(fp)
    c = _c(fp)
    lines = _lines(rec)
    near = [(a, b) for a, b in _arrows(rec) if abs((b - a).real) < 1e-6 and abs(a.real - c.real) < 10.0
            and _dist(c, a, b) < 40.0]
    assert len(near) >= 5, near            # P_C, G4, G5, Φ4, Φ5
    seen = [round(_seen(a, b, lines), 1) for a, b in near]
    assert min(seen) >= SEEN_MM, list(zip(near, seen))


def test_the_wedges_face_covers_cs_travel_on_the_force_scheme(fp):
    """The wedge's triangle (``forces._link_outline``) reaches past C's farthest place on its face. Its
    vertical back stands at B + (0.34 − x_B,min) + the slot margin, not on C's line."""
    from graphplan.drawing.forces import _link_outline
    out = _link_outline(fp, "B", fp.mu_l)
    lk = fp.ks.mech.links["B"]
    b = complex(fp.ks.kin.bodies["B"].at(lk.local["B"])[0][0]) / fp.mu_l
    back = max(z.real for z in out)
    reach = (X_C - XB_MIN) / fp.mu_l
    assert back - b.real >= reach - 1e-6, (back - b.real, reach)
    assert back - b.real <= reach + 4.0 + 1e-6          # the slot's margin (4 mm along the face) at most
    assert back - _c(fp).real >= (b.real * fp.mu_l - XB_MIN) / fp.mu_l - 1e-6


def test_the_wedges_face_covers_cs_travel_on_the_position_plan():
    """On the position plan every thick position's triangle has its back at least C's farthest
    horizontal reach from B, (0.34 − x_B,min)/μl: one wedge, the same size at each position."""
    from graphplan.drawing.plans import position_record
    from graphplan.graphic.plans import build_plans
    plans = build_plans(scene_study(WEDGE62_PRESS))
    rec = position_record(plans)
    segs = [tuple(complex(*p) for p in it.points) for it in rec.items
            if it.kind == "segment" and it.layer == "mechanism" and len(it.points) == 2 and it.width is None]
    backs = [(p, q) for p, q in segs if abs((q - p).real) < 1e-6 and abs(q - p) > 1.0]
    faces = [(p, q) for p, q in segs if abs(math.degrees(math.atan2((q - p).imag, (q - p).real)) % 180.0 - 35.0) < 1e-6]
    assert len(backs) >= 2 and len(faces) >= 2, (backs, faces)
    reach = (X_C - XB_MIN) / plans.mu_l
    widths = []
    for p, q in faces:
        lo = p if p.real < q.real else q
        back = next(s for s in backs if any(abs(z - (q if lo is p else p)) < 1e-6 for z in s))
        widths.append(back[0].real - lo.real)
    assert all(w >= reach - 1e-6 for w in widths), (widths, reach)
    assert max(widths) - min(widths) < 1e-6, widths      # one rigid wedge
