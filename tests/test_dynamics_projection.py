"""The energy–mass diagram built as the textbook builds it (REFERENCE §9: φ eliminated between
ΔT(φ) and I*(φ)), read off the dynamics sheet's own record: ΔT(φ) stands to the left of the
energy–mass diagram on one ΔT zero line, I*(φ) is turned under it on one I* axis, and thin
projection lines carry each division point across and up to the curve's point of that division."""
from __future__ import annotations

from types import SimpleNamespace

import pytest

from conftest import example

TOL = 0.1      # mm


# the slotter in English: slow (its English dynamics sheet, 7 s of CPU, no other test of the default run
# composes; the default run draws the same projections on the shaper's Ukrainian sheet)
@pytest.fixture(scope="module", params=[("shaper", "uk"), pytest.param(("slotter", "en"), marks=pytest.mark.slow)])
def sheet(request):
    from dataclasses import replace

    from conftest import example_composed, example_sheet
    name, lang = request.param
    # a copy of the shared sheet, named (the English one composed alone: its numbering is not read
    # here, and would count the English kinematics and force sheets no other test composes)
    out = replace((example_composed if lang == "en" else example_sheet)(name, "dynamics", "A1", lang))
    out.name = name
    return out


def _placed(sheet, name):
    found = [p for p in sheet.placed if p.name == name]
    assert len(found) == 1, name
    return found[0].record


def _points(rec, step):
    return [p.points[0] for p in rec.items if p.kind == "point" and p.step == step]


def _projections(rec):
    return [p.points for p in rec.items if p.kind == "segment" and p.role == "projection"]


BROKEN = 2.0      # mm: a projection broken under lettering stops this near its ink (BREAK_CLEAR, PHI_CLEAR)


def _carried(segments, texts, a, b) -> bool:
    """a and b joined along one horizontal or vertical line by projection segments, the line broken
    only under lettering (an axis's value, a point's number: a draftsman breaks his construction
    lines under them) — each gap within a word's ink grown by BROKEN."""
    k = 1 if abs(a[1] - b[1]) <= TOL else 0          # the coordinate the line keeps (y of a horizontal)
    if abs(a[k] - b[k]) > TOL:
        return False
    lo, hi = sorted((a[1 - k], b[1 - k]))
    runs = sorted(sorted((p[1 - k], q[1 - k])) for p, q in segments
                  if abs(p[k] - a[k]) <= TOL and abs(q[k] - a[k]) <= TOL)
    at = lo
    for r0, r1 in runs:
        if r0 > at + TOL:                             # a gap from at to r0: under some word?
            if r0 > hi or not any(t[k] - BROKEN <= a[k] <= t[k + 2] + BROKEN and t[1 - k] - BROKEN <= at
                                  and r0 <= t[3 - k] + BROKEN for t in texts):
                break
        at = max(at, r1)
        if at >= hi - TOL:
            return True
    return at >= hi - TOL


CROWDED = 2.0     # mm: parallel projections nearer than this read as a striped band (review SIXBAR7)


def _stubbed(segments, a, b, neighbours) -> bool:
    """a and b on one horizontal or vertical line, each the end of a projection segment on it — the
    line drawn short at both ends (the ruler carries it between) — and only where another point's
    projection of that kind runs within ``CROWDED`` of it (``neighbours``: their coordinates)."""
    k = 1 if abs(a[1] - b[1]) <= TOL else 0
    if abs(a[k] - b[k]) > TOL or not any(abs(v - a[k]) < CROWDED for v in neighbours):
        return False
    on = [(p, q) for p, q in segments if abs(p[k] - a[k]) <= TOL and abs(q[k] - a[k]) <= TOL]
    ends = lambda z: any(abs(e[1 - k] - z[1 - k]) <= TOL for pq in on for e in pq)  # noqa: E731
    return ends(a) and ends(b)


def test_each_point_is_where_its_two_projections_meet(sheet):
    energy, inertia, witt = (_placed(sheet, n) for n in ("energy", "inertia", "wittenbauer"))
    dT = _points(energy, "ΔT read")
    inert = _points(inertia, "I*_m read")
    n = len(dT) - 1
    curve = [_points(witt, f"point {j}")[0] for j in range(n)]
    assert n >= 8 and len(inert) == n + 1
    segments = _projections(energy) + _projections(inertia) + _projections(witt)
    texts = [p.ink() for r in (energy, inertia, witt) for p in r.items if p.kind == "text" and p.text.strip()]
    for j, c in enumerate(curve):
        assert dT[j][1] == pytest.approx(c[1], abs=TOL), f"ΔT of {j} not carried across on one horizontal"
        assert dT[j][0] < c[0]                                  # ΔT(φ) to the left
        assert inert[j][0] == pytest.approx(c[0], abs=TOL), f"I* of {j} not carried up on one vertical"
        assert inert[j][1] < c[1]                               # I*(φ) under the diagram
        others_t = [p[1] for i, p in enumerate(curve) if i != j]
        others_i = [p[0] for i, p in enumerate(curve) if i != j]
        assert _carried(segments, texts, dT[j], c) or _stubbed(segments, dT[j], c, others_t), \
            f"no horizontal projection joins ΔT(φ)'s point {j} to the curve"
        assert _carried(segments, texts, inert[j], c) or _stubbed(segments, inert[j], c, others_i), \
            f"no vertical projection joins I*(φ)'s point {j} to the curve"
    # the turned I*(φ): φ runs downward, the divisions equally spaced
    ys = [p[1] for p in inert]
    steps = [a - b for a, b in zip(ys, ys[1:])]
    assert min(steps) > 0 and max(steps) - min(steps) < 1e-6
    # ΔT(φ) over φ to the right, equally spaced, with its zero line the diagram's I* axis: point 0 (ΔT = 0)
    xs = [p[0] for p in dT]
    gaps = [b - a for a, b in zip(xs, xs[1:])]
    assert min(gaps) > 0 and max(gaps) - min(gaps) < 1e-6
    axis = [p.points for p in witt.items if p.kind == "vector" and p.step == "I* axis"][0]
    assert dT[0][1] == pytest.approx(axis[0][1], abs=TOL) == pytest.approx(axis[1][1], abs=TOL)


def test_the_projections_carry_the_constructions_ordinates(sheet):
    """The ΔT(φ) ordinates (from its zero line) and the turned I*(φ) abscissae (from the ΔT axis
    of the energy–mass diagram) are the construction's ΔT_k and I_k in mm at the sheet's μ_T and μ_I:
    the band's φ axis is free, its ordinates are not."""
    from graphplan.exact.dynamics import analyse
    from graphplan.sheets.dynamics import _built, construction
    from graphplan.sheets.form import form
    st = example(sheet.name)
    dyn = analyse(st, None)
    args = SimpleNamespace(positions=None, accel=None, precision=0.5, lang="uk", sheet="dynamics")
    L, size, *_, energy = construction(st, dyn, form("A1"), args)
    f = _built(dyn, args, L, size, energy)
    energy, inertia, witt = (_placed(sheet, n) for n in ("energy", "inertia", "wittenbauer"))
    assert energy.scales["mu_T"] == witt.scales["mu_T"] == f.mu_T and inertia.scales["mu_I"] == witt.scales["mu_I"]
    axis = [p.points for p in witt.items if p.kind == "vector" and p.step == "ΔT axis"][0]
    dT, inert = _points(energy, "ΔT read"), _points(inertia, "I*_m read")
    for j in range(f.divisions):
        assert dT[j][1] - dT[0][1] == pytest.approx(f.dT[j] - f.dT[0], abs=1e-6)
        assert inert[j][0] - axis[0][0] == pytest.approx(f.I[j], abs=1e-6)


def test_the_phi_of_delta_t_stands_at_its_arrow_clear_of_the_projections():
    """The fifth review's item 4: on its desaxial press (24 divisions, the ΔT projections a dense
    band) the φ of ΔT(φ) went on a 28 mm leader into the dashes, overprinted. A draftsman letters φ
    at the axis' arrow and breaks the thin projections under it: within 8 mm of the tip, no line
    through its box."""
    from shapely.geometry import LineString, box

    from conftest import composed, scene_study
    from graphplan.sheets.form import form
    from review_scenes import PRESS_EN
    args = SimpleNamespace(positions=None, accel=None, precision=0.5, lang="en", sheet="dynamics")
    out = composed("dynamics", scene_study(PRESS_EN), form("A1"), args)      # not numbered: not read here
    rec = next(p.record for p in out.placed
               if any(q.step == "axes ΔT" and q.kind == "text" and q.text == "φ" for q in p.record.items))
    phi = next(q for q in rec.items if q.step == "axes ΔT" and q.kind == "text" and q.text == "φ")
    tip = max((q.points[-1] for q in rec.items if q.step == "axes ΔT" and q.kind == "vector"), key=lambda p: p[0])
    b = box(*phi.ink())                            # the letter's ink (its box reaches the axis' line)
    assert b.distance(box(tip[0], tip[1], tip[0], tip[1])) < 8.0
    lines = [q for q in rec.items if q.kind in ("segment", "polyline", "vector") and len(q.points) >= 2]
    assert not [q.step for q in lines if LineString(q.points).intersects(b)]


def test_close_projections_draw_no_striped_band():
    """SIXBAR7's ΔT of positions 16–22 lie 0,4–1,7 mm apart: their dashed projections across the gap
    made a striped band. The lines drawn through (from ΔT(φ)'s point to the curve's, or I*(φ)'s up to
    it) stand ≥ CROWDED apart; each other point keeps its short projection at both ends."""
    from conftest import composed, scene_study
    from graphplan.sheets.form import form
    from review_scenes import SIXBAR7
    args = SimpleNamespace(positions=None, accel=None, precision=0.5, lang="uk", sheet="dynamics")
    out = composed("dynamics", scene_study(SIXBAR7), form("A1"), args)       # not numbered: not read here
    energy, inertia, witt = (_placed(out, n) for n in ("energy", "inertia", "wittenbauer"))
    dT = _points(energy, "ΔT read")
    n = len(dT) - 1
    curve = [_points(witt, f"point {j}")[0] for j in range(n)]
    segments = _projections(energy) + _projections(inertia) + _projections(witt)
    texts = [p.ink() for r in (energy, inertia, witt) for p in r.items if p.kind == "text" and p.text.strip()]
    through: list[float] = []        # the heights drawn through (two points at one height: one line)
    for j, c in enumerate(curve):
        if _carried(segments, texts, dT[j], c) and all(abs(c[1] - y) > TOL for y in through):
            through.append(c[1])
    assert len(through) >= n // 2
    gaps = [abs(a - b) for i, a in enumerate(through) for b in through[i + 1:]]
    assert min(gaps) >= CROWDED - 1e-9, f"projections drawn through {min(gaps):.2f} mm apart"
    close = [j for j, c in enumerate(curve) if any(abs(c[1] - d[1]) < CROWDED for i, d in enumerate(curve) if i != j)]
    assert len(close) >= 4          # the band there was: 16–22 (4 close since the chords integrate equal-area means)



def test_the_band_states_its_own_phi_scale(sheet):
    """Review 13 #11: ΔT(φ) spans a turn over the band's length (88 mm on the V-twin), not the
    moments' L, and printed no μ_φ. The line under its caption states μ_φ = 2π/l, l the span the
    ΔT(φ) points are drawn over (position 0 to position N)."""
    import math
    import re
    from graphplan.util.markup import plain
    rec = _placed(sheet, "energy")
    xs = [p[0] for p in _points(rec, "ΔT read")]
    said = [plain(p.text) for p in rec.items if p.kind == "text" and p.step == "caption scale"]
    assert len(said) == 1, said
    m = re.fullmatch(r"μ′_?φ = 2π/([0-9.,]+) = ([0-9.,]+) (?:rad|рад)/(?:mm|мм)", said[0].replace(",", "."))
    assert m, said
    span = max(xs) - min(xs)
    assert float(m.group(1)) == pytest.approx(span, abs=0.06)
    assert float(m.group(2)) == pytest.approx(2 * math.pi / span, rel=6e-4)
