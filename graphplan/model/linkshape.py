"""The drawn shape of one rigid link through all its points, as the textbook draws it: a bar
from its farthest point to its farthest point when every point lies on the line of its joints
(the rocker O2–B–D with D on BO2's extension), else a plate — the outline around all its points
(the coupler ABE a triangle). Pure geometry in drawing mm."""
from __future__ import annotations

from graphplan.model.mechanism import Link

ON_LINE_MM = 0.3    # a point this close to the joints' line lies on the bar
SLOT_MARGIN_MM = 4.0  # a slotted link's line runs this far beyond its outermost point or block
COLLINEAR = 1e-5    # mm²: |cross| this small (a point ~1e-7 mm off a 100 mm edge) is no corner: round-off cannot make one


def extra_points(link: Link) -> list[str]:
    """The link's named points beyond its joints that its outline must reach (D, E …): every
    local point except the joints and the centre of mass (a centre of mass is not a pair or a
    point of application the link is shaped for; it lies on the bar in the lab's schemes)."""
    return [p for p in link.local if p not in link.joints and p != link.com]


def _hull(points: list[complex]) -> list[int]:
    """The convex hull, counter-clockwise (Andrew's monotone chain), as indices into ``points``
    (of coincident points the first)."""
    first: dict[tuple[float, float], int] = {}
    for k, z in enumerate(points):
        first.setdefault((round(z.real, 9), round(z.imag, 9)), k)
    pts = sorted(first)
    if len(pts) <= 2:
        return [first[p] for p in pts]

    def cross(o, a, b) -> float:
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    lower: list = []
    for p in pts:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], p) <= COLLINEAR:
            lower.pop()
        lower.append(p)
    upper: list = []
    for p in reversed(pts):
        while len(upper) >= 2 and cross(upper[-2], upper[-1], p) <= COLLINEAR:
            upper.pop()
        upper.append(p)
    return [first[p] for p in lower[:-1] + upper[:-1]]


def outline_order(joints: list[complex], extras: list[complex]) -> list[int]:
    """The order in which a link's outline runs through its points, as indices into
    ``joints + extras`` (a closed outline repeats its first index at the end). Two joints and every
    point on their line: the bar between the two outermost points. Three or more joints and no point
    outside their polygon: the polygon in the joints' order. Otherwise the outline around all the
    points (a rigid plate). A rigid motion keeps the order, so one position gives it for the turn
    (the explorer draws every angle from it: the sheets' shape, not a second one)."""
    if len(joints) < 2:
        return list(range(len(joints)))
    a, b = joints[0], joints[1]
    d = b - a
    if abs(d) < 1e-9:
        d = next((z - a for z in joints + extras if abs(z - a) > 1e-9), 1 + 0j)
    u = d / abs(d)
    every = joints + extras
    if all(abs(((z - a) * u.conjugate()).imag) <= ON_LINE_MM for z in every):
        along = sorted(range(len(every)), key=lambda k: ((every[k] - a) * u.conjugate()).real)
        return [along[0], along[-1]]
    if len(joints) >= 3 and all(_inside(z, joints) for z in extras):
        return list(range(len(joints))) + [0]
    hull = _hull(every)
    return hull + [hull[0]]


def outline_names(link: Link, pts: dict[str, complex]) -> list[str]:
    """The names of the points a link's outline runs through, in order (``outline_order`` over its
    joints and its ``extra_points`` drawn in ``pts``): ["O2", "D"] for the rocker O2–B–D, ["A", "B",
    "E", "A"] for a coupler plate ABE."""
    joints = list(link.joints)
    extras = [p for p in extra_points(link) if p in pts]
    names = joints + extras
    return [names[k] for k in outline_order([pts[p] for p in joints], [pts[p] for p in extras])]


def rigid_outline(joints: list[complex], extras: list[complex]) -> list[complex]:
    """One polyline (mm) drawing a link through its joints and its other points, in the order of
    ``outline_order``: the bar between its outermost points, the joints' polygon, or the closed
    outline around all its points (a rigid plate)."""
    every = joints + extras
    return [every[k] for k in outline_order(joints, extras)]


def slot_line(base, u, own: list, blocks: list, margin: float = SLOT_MARGIN_MM):
    """A slotted link (a coulisse) drawn along its guide: the line through ``base`` in the direction
    ``u`` (a unit complex) from its farthest point to its farthest point, its own (joints, D …) and
    its blocks' alike, ``margin`` mm beyond each end — the coulisse O2A3 reaching its end B. Works on
    complex numbers or on numpy arrays of them (every angle of a turn at once); returns both ends."""
    import numpy as np
    along = [((z - base) * np.conj(u)).real for z in list(own) + list(blocks)]
    lo, hi = np.min(along, axis=0) - margin, np.max(along, axis=0) + margin
    return base + lo * u, base + hi * u


def _inside(z: complex, polygon: list[complex]) -> bool:
    """A point inside or on a polygon (the even–odd rule, the edges counted in)."""
    n = len(polygon)
    for i in range(n):
        p, q = polygon[i], polygon[(i + 1) % n]
        if abs(q - p) > 1e-9 and abs(((z - p) * (q - p).conjugate()).imag) / abs(q - p) <= ON_LINE_MM \
                and -ON_LINE_MM <= ((z - p) * ((q - p) / abs(q - p)).conjugate()).real <= abs(q - p) + ON_LINE_MM:
            return True
    inside = False
    for i in range(n):
        p, q = polygon[i], polygon[(i + 1) % n]
        if (p.imag > z.imag) != (q.imag > z.imag):
            x = p.real + (z.imag - p.imag) * (q.real - p.real) / (q.imag - p.imag)
            if x > z.real:
                inside = not inside
    return inside


SLOT_HALF_MM = 3.5    # a yoke's slot drawn as its two sides this far either side of its line (the 5 mm block inside)
SLOT_END_MM = 7.0     # … running this far beyond the block's centre at either end of its travel


YOKE_SLOT_MIN_DEG = 45.0   # a slider's slot this steep to its rod or steeper: a yoke; shallower: a wedge's face


def yoke_guide(mech, name: str):
    """A yoke: a link that slides along a guide (the rod in its bushings) and carries a guide a
    block slides in (its slot) — the Scotch yoke's slotted crosshead. With no revolute joint of its
    own, or with joints (the rod's end C pinned to a further rod, review 57) and its slot at
    ``YOKE_SLOT_MIN_DEG`` or more to the rod: a slot at a shallow angle is a wedge's inclined face
    (``drawing.plans._wedge_sides``), not a yoke. Its carried guide (model.mechanism.Guide), or
    None for any other link."""
    import math
    link = mech.links[name]
    if link.slides_on is None:
        return None
    for other in mech.links.values():
        if other.slides_on is not None:
            g = mech.guides[other.slides_on]
            if g.body == name:
                steep = abs(math.sin(g.angle)) >= math.sin(math.radians(YOKE_SLOT_MIN_DEG)) - 1e-9
                return g if not link.joints or steep else None
    return None


def wedge_body(a: complex, b: complex, ref: complex, u_slide: complex) -> list[complex]:
    """A wedge whose inclined face (its slot, from ``a`` to ``b``) runs through its own joint (the
    wedge press's wedge 3: the face through B, review 62) drawn as the textbook's triangle resting on
    its guide (the line through ``ref`` along ``u_slide``, the wedge's joint on it): the face from
    where it meets that line to its end farther from it, that end's perpendicular down to the line and
    the base back along it — a closed outline (mm), [P, far, foot, P]; a face not crossing the line
    between its ends is closed by both ends' perpendiculars (a plate). [] for a face along the line."""
    u = (b - a) / abs(b - a)

    def off(z: complex) -> float:
        return ((z - ref) * u_slide.conjugate()).imag

    def foot(z: complex) -> complex:
        return ref + ((z - ref) * u_slide.conjugate()).real * u_slide

    if abs((u * u_slide.conjugate()).imag) < 1e-9:
        return []
    far, near = (b, a) if abs(off(b)) >= abs(off(a)) else (a, b)
    if off(far) * off(near) <= 0.0:          # the face crosses the guide's line: a triangle
        p = rod_crossing(ref, u_slide, a, u)
        return [p, far, foot(far), p]
    return [near, far, foot(far), foot(near), near]


def rod_crossing(ref: complex, u_rod: complex, base: complex, u_slot: complex) -> complex:
    """Where a yoke's slot line (through ``base`` along ``u_slot``) crosses its rod's axis (through
    ``ref`` along ``u_rod``): base + t·u_slot with (base + t·u_slot − ref) × u_rod = 0,
    t = −(base − ref) × u_rod / (u_slot × u_rod); a slot parallel to the rod: base's foot on it."""
    def cr(a: complex, b: complex) -> float:
        return a.real * b.imag - a.imag * b.real
    den = cr(u_slot, u_rod)
    if abs(den) < 1e-9:
        return ref + ((base - ref) * u_rod.conjugate()).real * u_rod
    return base - cr(base - ref, u_rod) / den * u_slot


def yoke_shape(ref: complex, u_rod: complex, base: complex, u_slot: complex, slot: tuple[float, float],
               rod: tuple[float, float]) -> tuple[complex, complex, complex, complex]:
    """A yoke drawn as one rigid body (mm): its slot from ``slot`` = (lo, hi) along ``u_slot`` from
    ``base`` (the guide's point), and its rod along ``u_rod`` from ``rod`` = (lo, hi) off ``ref``
    (the link's own point D). Returns (slot's ends, rod's ends)."""
    return (base + slot[0] * u_slot, base + slot[1] * u_slot, ref + rod[0] * u_rod, ref + rod[1] * u_rod)


def yoke_spans(along_blocks: list[float], along_crossing: float, along_own: list[float],
               rod_reach: list[float] = ()) -> tuple[tuple[float, float], tuple[float, float]]:
    """The yoke's constant spans (mm, in its own frame): the slot over every block position drawn
    and the rod's crossing with it (``along_blocks``: along the slot from its guide's point),
    ``SLOT_END_MM`` beyond the outermost; the rod from the crossing (``along_crossing``, along the rod
    from D) to its farthest own point and to every ``rod_reach`` (a bushing it must pass through)."""
    slot = (min(along_blocks) - SLOT_END_MM, max(along_blocks) + SLOT_END_MM)
    every = [along_crossing] + list(along_own) + list(rod_reach)
    return slot, (min(every), max(every))


def slot_outline(a: complex, b: complex, half: float = SLOT_HALF_MM) -> list[complex]:
    """A slot from ``a`` to ``b`` drawn as its two sides ``half`` mm off its line, closed at the
    ends (a closed polyline)."""
    u = (b - a) / abs(b - a) if abs(b - a) > 1e-12 else 1 + 0j
    n = 1j * u * half
    return [a - n, b - n, b + n, a + n, a - n]


def rod_from_slot(a: complex, b: complex, p: complex, q: complex,
                  half: float = SLOT_HALF_MM) -> tuple[complex, complex]:
    """A yoke's rod ``p``–``q`` as drawn beside its slot ``a``–``b`` drawn as its two sides: an end of
    the rod on the slot's line starts at the slot's side instead (``half`` mm off the line, along the
    rod), not across the block's path inside the slot (review 57)."""
    if abs(q - p) < 1e-9 or abs(b - a) < 1e-9:
        return p, q
    ur, us = (q - p) / abs(q - p), (b - a) / abs(b - a)
    sin = abs((us.conjugate() * ur).imag)
    if sin < 0.05:
        return p, q
    x = rod_crossing(p, ur, a, us)
    step = half / sin
    if abs(p - x) < 1e-6 and abs(q - p) > step:
        return p + step * ur, q
    if abs(q - x) < 1e-6 and abs(q - p) > step:
        return p, q - step * ur
    return p, q


def rod_stubs(ref: complex, u_rod: complex, points: list[complex]) -> list[tuple[complex, complex]]:
    """A yoke's points off its rod's axis (a centre of mass set aside) joined to the rod: from each
    one's foot on the axis to it — so that the body stays one piece."""
    out = []
    for z in points:
        d = (z - ref) * u_rod.conjugate()
        if abs(d.imag) > ON_LINE_MM:
            out.append((ref + d.real * u_rod, z))
    return out


BUSH_HALF_MM = 8.0     # a yoke's rod bushing (the frame's guide) this long either side of its middle
BUSH_GAP_MM = 2.0      # … its two walls this far either side of the rod's axis
BUSH_CLEAR_MM = 4.0    # … this far clear of the crank pin's circle and of the slot's sweep
ROD_PAST_MM = 3.0      # the rod reaches this far past its bushing's far end


def yoke_body(frames: list[tuple[complex, complex, complex, complex]], blocks: list[list[complex]],
              own: list[list[complex]], guide: tuple[complex, complex] | None = None,
              O: complex | None = None, r: float = 0.0, reach: list[complex] = ()):
    """A yoke's constant spans over the positions it is drawn at (mm), one rigid body: at each
    position its frame ``frames[i]`` = (D, the rod's unit, the slot guide's point, the slot's unit),
    the blocks' points in its slot ``blocks[i]`` and its own points ``own[i]``. The slot over every
    block position and the rod's crossing (``yoke_spans``); with the frame's ``guide`` line (point,
    unit) its rod's bushing on that line on the side of its own points, clear of the crank pin's
    circle (about ``O``, radius ``r``), of the slot's sweep and of a point off the rod, the rod long
    enough to stay in it at every position; the rod drawn on ``ROD_PAST_MM`` past every point of
    ``reach`` at the last frame (where the frame's reaction R03 acts on it at the force position,
    review 57 #4: not in empty space beyond the rod's end). Returns (slot span, rod span, bushing
    (middle, unit) or None)."""
    import math

    def along(z: complex, base: complex, u: complex) -> float:
        return ((z - base) * u.conjugate()).real
    slot_at, own_at, feet, cross_rod = [], [], [], 0.0
    for (ref, ur, base, us), bl, ow in zip(frames, blocks, own):
        x = rod_crossing(ref, ur, base, us)
        cross_rod = along(x, ref, ur)
        slot_at += [along(x, base, us)] + [along(z, base, us) for z in bl]
        own_at += [along(z, ref, ur) for z in ow]
        feet.append((x, abs((us.conjugate() * ur).imag)))
    last_ref, last_ur = frames[-1][0], frames[-1][1]
    past = [along(z, last_ref, last_ur) for z in reach]

    def on_past(span: tuple[float, float]) -> tuple[float, float]:
        lo, hi = span
        for t in past:
            lo, hi = min(lo, t - ROD_PAST_MM), max(hi, t + ROD_PAST_MM)
        return lo, hi
    slot, rod = yoke_spans(slot_at, cross_rod, own_at)
    if guide is None or O is None:
        return slot, on_past(rod), None
    gb, ug = guide
    ur0 = frames[0][1]
    side = 1.0 if (max(own_at) - cross_rod) * along(gb + ur0, gb, ug) >= 0 else -1.0
    t_o, off = along(O, gb, ug), abs(((O - gb) * ug.conjugate()).imag)
    clear_r = r + BUSH_GAP_MM + 2.5          # the circle and the bushing's hatching
    reach = [side * t_o + math.sqrt(clear_r * clear_r - off * off)] if off < clear_r else []
    reach += [side * along(x, gb, ug) + (SLOT_HALF_MM + BUSH_GAP_MM) / max(sin, 0.05) for x, sin in feet]
    for (ref, ur, _, _), ow in zip(frames, own):     # a point set off the rod never runs into it
        reach += [side * along(z, gb, ug) for _, z in rod_stubs(ref, ur, ow)]
    near = max(reach) + BUSH_CLEAR_MM
    mid = gb + side * (near + BUSH_HALF_MM) * ug
    far = mid + side * (BUSH_HALF_MM + ROD_PAST_MM) * ug
    _, rod = yoke_spans(slot_at, cross_rod, own_at, [along(far, ref, ur) for ref, ur, _, _ in frames])
    return slot, on_past(rod), (mid, ug)
