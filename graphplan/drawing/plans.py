"""The position plan as a record: the frame, every position (the ones with acceleration plans
thick), the compass arcs of each construction, the trajectories of chosen points, the extreme
positions (dashed) and the labels. Drawing millimetres, the crank's pivot at (0, 0)."""
from __future__ import annotations

import cmath
import math
from dataclasses import dataclass

from graphplan.util.markup import escape, indexed
from graphplan.graphic.record import Record, arc_head, text_width
from graphplan.drawing.labels import LabelRequest, place_first, place_labels, place_owned
from graphplan.model.linkshape import (BUSH_GAP_MM, BUSH_HALF_MM, extra_points, outline_names, rod_crossing,
                                        rod_from_slot, rod_stubs, slot_line, slot_outline, wedge_body, yoke_body, _inside,
                                        yoke_guide, yoke_shape)
from graphplan.model.mechanism import FRAME
from graphplan.graphic.plans import Layout, Plan, Plans, Scheme, where
from graphplan.graphic.position_plan import Arc

ARC_HALF = 5.0       # mm of arc drawn each side of a construction point (a "засічка")
BLOCK = (9.0, 5.0)   # slider block drawn on the thick positions, mm
BLOCK_CLEAR = 0.5    # mm the guide's hatching stops short of a block on it


def _pt(z: complex) -> tuple[float, float]:
    return (z.real, z.imag)


def joints_at(sc: Scheme, lay: Layout) -> dict[str, complex]:
    """Every named point at this position, drawn."""
    return {name: where(sc, lay, sc.body_of(name), name) for name in sc.mech.point_names()}


def guide_carriers(sc: Scheme) -> dict[str, list[str]]:
    """Bodies carrying a guide someone slides on → the sliders on it."""
    out: dict[str, list[str]] = {}
    for name, link in sc.mech.links.items():
        if link.slides_on is not None:
            out.setdefault(sc.mech.guides[link.slides_on].body, []).append(name)
    return out


def draw_links(rec: Record, sc: Scheme, lay: Layout, thick: bool, role: str = "link",
               step: str = "", yokes: dict[str, YokeSpans] | None = None,
               travel: dict[tuple[str, str], list[float]] | None = None) -> None:
    """The links of one position: bars between joints, slotted links along their guides, blocks;
    a yoke as one body (``draw_yoke``: its slot and rod, its spans ``yokes`` kept over the turn); a
    wedge's face at a thick position over its block's whole ``travel`` along it (``wedge_travel``)."""
    mech = sc.mech
    pts = joints_at(sc, lay)
    width = None if thick else 0.3
    carriers = guide_carriers(sc)
    for name, link in mech.links.items():
        joints = list(link.joints)
        if yoke_guide(mech, name) is not None:
            draw_yoke(rec, sc, lay, name, (yokes or {}).get(name) or yoke_spans(sc, [lay], name), thick,
                      role, step)
            continue
        if name in carriers:
            # a slotted link: its guide line over its joints and the blocks sliding in it
            # (through all its own points: the coulisse O2A3 runs to its end B)
            own = [pts[p] for p in joints + [q for q in extra_points(link) if q in pts]]
            for slider in carriers[name]:
                g = mech.guides[mech.links[slider].slides_on]
                base, ug = lay.poses[name].at(g.through), lay.poses[name].direction(g.angle)
                # a wedge at a thick position: its face over the block's whole travel (a thin
                # position's face line, one of twelve, to just past its block)
                a, b = slot_line(base, ug, own, [pts[p] for p in mech.links[slider].local]
                                 + [base + t * ug for t in (travel or {}).get((name, slider), ()) if thick])
                if thick and link.slides_on is not None and _wedge_sides(
                        rec, [pts[p] for p in joints], complex(a), complex(b), lay.poses[name].direction(0.0),
                        role, step):
                    continue
                rec.segment(_pt(complex(a)), _pt(complex(b)), role=role, width=width, layer="mechanism", step=step)
        if link.slides_on is not None and len(joints) <= 1:
            if thick:
                corners = block_corners(sc, lay, name)
                front = [block_corners(sc, lay, o) for o in pinned_blocks(sc, name)]
                if not front:
                    rec.add("polygon", [_pt(c) for c in corners], role=role, layer="mechanism", step=step)
                for a, b in _behind(corners + corners[:1], front):
                    rec.segment(_pt(a), _pt(b), role=role, layer="mechanism", step=step)
            continue
        # one rigid link through all its points: the rocker O2–B–D to D, a plate round E off its line
        shape = [pts[p] for p in outline_names(link, pts)]
        for p, q in zip(shape, shape[1:]):
            rec.segment(_pt(p), _pt(q), role=role, width=width, layer="mechanism", step=step)
    for name, link in mech.links.items():
        for j in link.joints:
            rec.point(_pt(pts[j]), role="joint" if thick else "dot", layer="mechanism")
        if thick:
            for p in link.local:
                if p not in link.joints and p in pts and not sc.fixed(p) and (
                        p != next(iter(link.local)) or yoke_guide(mech, name) is not None):
                    rec.point(_pt(pts[p]), role="dot", layer="mechanism")


CARRIAGE = (12.0, 6.0)   # a slider on a frame guide that carries another's block on its pin, mm …
STONE = (8.0, 4.0)       # … and that block (the stone in a moving link's slot), drawn in front of it


def pinned_blocks(sc: Scheme, name: str) -> list[str]:
    """The blocks drawn in front of the block ``name``: where a slider on a frame guide carries on its
    pin the block of a moving link's slot (LINK62: the slider 3 on its inclined guide, the block 4
    in the lever's slot, both at B), the block in the slot — the lever's plane — is in front and
    the slider's edges under it are hidden, as a drawing hides them (the two 9 × 5 blocks drawn
    over each other read as one eight-pointed knot). Empty for any other block."""
    mech = sc.mech
    link = mech.links[name]
    if link.slides_on is None or len(link.joints) > 1 or mech.guides[link.slides_on].body != FRAME:
        return []
    pin = next(iter(link.local))
    return [o for o, l in mech.links.items() if o != name and l.slides_on is not None and len(l.joints) <= 1
            and next(iter(l.local)) == pin and mech.guides[l.slides_on].body != FRAME]


def block_size(sc: Scheme, name: str) -> tuple[float, float]:
    """A slider's block, mm (length along its guide, height): ``BLOCK``; where two blocks share one
    pin (``pinned_blocks``) the carriage on the frame guide longer and taller (``CARRIAGE``), the
    stone in front of it smaller (``STONE``) — which is which reads at a glance."""
    mech = sc.mech
    if pinned_blocks(sc, name):
        return CARRIAGE
    link = mech.links[name]
    if link.slides_on is not None and len(link.joints) <= 1 and any(
            name in pinned_blocks(sc, o) for o in mech.links if o != name):
        return STONE
    return BLOCK


def block_corners(sc: Scheme, lay: Layout, name: str) -> list[complex]:
    """The four corners of a slider's block at a position: centred on its own point (its first
    joint), along its guide, ``block_size``."""
    pin = next(iter(sc.mech.links[name].local))
    centre = where(sc, lay, sc.body_of(pin), pin)
    u = lay.poses[name].direction(0.0)
    w, h = block_size(sc, name)
    return [centre + u * complex(sx * w / 2, sy * h / 2) for sx, sy in ((-1, -1), (1, -1), (1, 1), (-1, 1))]


def _behind(outline: list[complex], fronts: list[list[complex]]) -> list[tuple[complex, complex]]:
    """The pieces of a closed ``outline`` (its points, the first repeated) outside every polygon of
    ``fronts`` — the edges a block drawn in front leaves in sight (all of it where none)."""
    if not fronts:
        return []
    from shapely.geometry import LineString, Polygon
    from shapely.ops import unary_union
    seen = LineString([_pt(z) for z in outline]).difference(unary_union([Polygon([_pt(z) for z in f]) for f in fronts]))
    parts = getattr(seen, "geoms", [seen])
    out = []
    for part in parts:
        xy = list(part.coords) if not part.is_empty else []
        out += [(complex(*a), complex(*b)) for a, b in zip(xy, xy[1:]) if abs(complex(*a) - complex(*b)) > 1e-6]
    return out


WEDGE_OFF_MM = 1.0   # a sliding carrier's joint this far off its slot's line is joined to the slot


def _wedge_sides(rec: Record, joints: list[complex], a: complex, b: complex, u_slide: complex, role: str,
                 step: str) -> bool:
    """A slider that carries a slot (a wedge: the block B on the frame's guide, its inclined face the
    slot the ram's block C rides in) drawn as one rigid body: off its own joint, the triangle of its
    joint and the slot's ends (review 52), the face ``a``–``b`` then drawn by the caller; through its
    joint, the textbook's triangle resting on its guide (``linkshape.wedge_body``: the face, its far
    end's perpendicular to the guide's line along ``u_slide`` and the base along it, review 62: not a
    bar from a pin at B to C) drawn here, face and all — True when so."""
    u = (b - a) / abs(b - a)
    off = [X for X in joints if abs(((X - a) * u.conjugate()).imag) > WEDGE_OFF_MM]
    for X in off:
        rec.segment(_pt(X), _pt(a), role=role, layer="mechanism", step=step)
        rec.segment(_pt(X), _pt(b), role=role, layer="mechanism", step=step)
    if off or not joints:
        return False
    body = wedge_body(a, b, joints[0], u_slide)
    if not body:
        return False
    for p, q in zip(body, body[1:]):
        rec.segment(_pt(p), _pt(q), role=role, layer="mechanism", step=step)
    return True


def wedge_travel(sc: Scheme, layouts: list[Layout]) -> dict[tuple[str, str], list[float]]:
    """A wedge's (a sliding link carrying a slot, not a yoke) blocks' farthest places along its face
    over the ``layouts`` drawn (mm from the slot guide's point): the face is drawn over the block's whole
    travel, as the textbook's wedge covers it (review 62: over the block's place at each position alone,
    the triangle's back stood on the ram's axis at every position)."""
    mech = sc.mech
    out: dict[tuple[str, str], list[float]] = {}
    for name, carried in guide_carriers(sc).items():
        link = mech.links.get(name)
        if link is None or link.slides_on is None or yoke_guide(mech, name) is not None:
            continue
        for slider in carried:
            g = mech.guides[mech.links[slider].slides_on]
            along = [((lay.poses[slider].at(z) - lay.poses[name].at(g.through))
                      * lay.poses[name].direction(g.angle).conjugate()).real
                     for lay in layouts for z in mech.links[slider].local.values()]
            if along:
                out[(name, slider)] = [min(along), max(along)]
    return out


def wedge_bodies(sc: Scheme, lay: Layout, travel: dict[tuple[str, str], list[float]] | None = None) -> list[list[complex]]:
    """The wedges drawn as their triangles on their guides at this position (``_wedge_sides``,
    ``linkshape.wedge_body``: a sliding link whose carried slot runs through its own joint), mm — the
    frame's hatching stops at them (the ram's guide of review 62's press runs down into the wedge)."""
    mech = sc.mech
    pts = joints_at(sc, lay)
    out = []
    for name, carried in guide_carriers(sc).items():
        link = mech.links.get(name)
        if link is None or link.slides_on is None or yoke_guide(mech, name) is not None or not link.joints:
            continue
        own = [pts[p] for p in list(link.joints) + [q for q in extra_points(link) if q in pts]]
        for slider in carried:
            g = mech.guides[mech.links[slider].slides_on]
            base, ug = lay.poses[name].at(g.through), lay.poses[name].direction(g.angle)
            a, b = (complex(z) for z in slot_line(base, ug, own, [pts[p] for p in mech.links[slider].local]
                                                  + [base + t * ug for t in (travel or {}).get((name, slider), ())]))
            u = (b - a) / abs(b - a)
            X = pts[link.joints[0]]
            if all(abs(((pts[j] - a) * u.conjugate()).imag) <= WEDGE_OFF_MM for j in link.joints):
                body = wedge_body(a, b, X, lay.poses[name].direction(0.0))
                if body:
                    out.append(body)
    return out


SUPPORT_HALF_DEG = 45.0   # the support's triangle and hatched bar, seen from its pivot: ±45° about its axis
SUPPORT_DIRS = (-90.0, -60.0, -120.0, -30.0, -150.0, 0.0, 180.0, 30.0, 150.0, 60.0, 120.0, 90.0)   # the force scheme tries, down first
OMEGA_HALF_DEG = 45.0     # ω1's arc: 90° about its middle
CLEAR_DEG = 5.0           # and this much clear of a link leaving the pivot


def _gap(a: float, b: float) -> float:
    """The angle between two directions, degrees (0 … 180)."""
    return abs((a - b + 180.0) % 360.0 - 180.0)


def leaving(sc: Scheme, layouts: list[Layout], name: str) -> list[float]:
    """The directions (degrees) of the links leaving the frame pivot ``name`` at the drawn (thick)
    positions: toward each other point of each link jointed there."""
    out = []
    for lay in layouts:
        pts = joints_at(sc, lay)
        X = pts[name]
        for link in sc.mech.links.values():
            if name in link.joints:
                out += [math.degrees(cmath.phase(pts[p] - X)) for p in list(link.joints) + extra_points(link)
                        if p in pts and abs(pts[p] - X) > 1e-6]
    return out


def support_direction(links: list[float], omega: bool = False) -> tuple[float, float | None]:
    """Where a frame pivot's support stands (degrees from the pivot: below, −90°, where that is
    free) — the side away from the links leaving it at the drawn position — and, for the crank's
    pivot (``omega``), the middle of ω1's 90° arc clear of both (nearest 245°, lower left, as
    before): the support is not drawn across the crank, nor ω1's arrow across the support."""
    def free(d: float, half: float) -> float:
        return min([_gap(d, a) for a in links] + [180.0]) - half
    best = (-1e9, -90.0, None)
    for d in FINE_DIRS:                  # nearest straight down first
        room = free(d, SUPPORT_HALF_DEG)
        arc = None
        if omega:
            arcs = [m for m in range(0, 360, 5) if free(m, OMEGA_HALF_DEG) >= CLEAR_DEG
                    and _gap(m, d) >= SUPPORT_HALF_DEG + OMEGA_HALF_DEG + 5.0]
            arc = min(arcs, key=lambda m: _gap(m, 245.0)) if arcs else None
        if room >= CLEAR_DEG and (not omega or arc is not None):
            return d, arc
        score = room + (0.0 if not omega or arc is not None else -90.0)
        if score > best[0]:
            best = (score, d, arc)
    return best[1], best[2]


FINE_DIRS = sorted(range(-180, 180, 5), key=lambda d: (_gap(d, -90.0), d))   # straight down first


def frame_support(sc: Scheme, drawn: list[Layout], thick: list[Layout], name: str,
                  omega: bool = False) -> tuple[float, float | None]:
    """Where the frame pivot ``name``'s support stands (and, for the crank's pivot, ω1's arc):
    where no link line of any ``drawn`` position passes (nearest straight down) — else as
    ``support_direction`` puts it clear of the ``thick`` positions' links (straight down where
    they leave it free), the thin lines then broken under it (``break_under_supports``)."""
    every = leaving(sc, drawn, name)
    bold = leaving(sc, thick, name)
    if every:
        upright = upright_support(every, bold, omega)
        if upright is not None and upright[2] == 0:
            return upright[0], upright[1]
        for d in FINE_DIRS:
            if min(_gap(d, a) for a in every) - SUPPORT_HALF_DEG < CLEAR_DEG:
                continue
            if not omega:
                return float(d), None
            arcs = [m for m in range(0, 360, 5)
                    if min([_gap(m, a) for a in bold] + [180.0]) - OMEGA_HALF_DEG >= CLEAR_DEG
                    and _gap(m, d) >= SUPPORT_HALF_DEG + OMEGA_HALF_DEG + 5.0]
            if arcs:
                return float(d), min(arcs, key=lambda m: _gap(m, 245.0))
        if upright is not None:
            return upright[0], upright[1]
    return support_direction(bold, omega=omega)


UPRIGHT_DIRS = (-90.0, 0.0, 180.0, 90.0)   # the support upright: below, beside (a wall), above — in turn


def _omega_arc(bold: list[float], d: float) -> float | None:
    """ω1's arc's middle (degrees) clear of the thick links and of a support toward ``d``: nearest 245°."""
    arcs = [m for m in range(0, 360, 5)
            if min([_gap(m, a) for a in bold] + [180.0]) - OMEGA_HALF_DEG >= CLEAR_DEG
            and _gap(m, d) >= SUPPORT_HALF_DEG + OMEGA_HALF_DEG + 5.0]
    return min(arcs, key=lambda m: _gap(m, 245.0)) if arcs else None


def upright_support(every: list[float], bold: list[float], omega: bool = False
                    ) -> tuple[float, float | None, int] | None:
    """The support set upright (its bar level or plumb, GOST 2.770 as a textbook draws it) where
    that is clear of the thick positions' links (and leaves ω1's arc room at the crank's pivot):
    the one of ``UPRIGHT_DIRS`` that the fewest thin lines leaving the pivot (``every``) cross —
    these are broken under it — in turn on a tie. (direction, ω1's arc, thin lines crossed); None
    where no upright support clears the thick links (review 7 #6: the crank's O1 stood tilted 13°
    among its twelve lines)."""
    best = None
    for k, d in enumerate(UPRIGHT_DIRS):
        if min([_gap(d, a) for a in bold] + [180.0]) - SUPPORT_HALF_DEG < CLEAR_DEG:
            continue
        arc = _omega_arc(bold, d) if omega else None
        if omega and arc is None:
            continue
        crossed = sum(1 for a in every if _gap(d, a) - SUPPORT_HALF_DEG < CLEAR_DEG)
        if best is None or (crossed, k) < best[0]:
            best = ((crossed, k), d, arc)
    return None if best is None else (best[1], best[2], best[0][0])


def support_outline(X: complex, direction: float) -> list[complex]:
    """The ink of ``support``'s symbol as a convex outline: the pivot, the bar's ends, the
    hatching's far corners."""
    r = cmath.exp(1j * math.radians(direction + 90.0))
    return [X + c * r for c in (0j, complex(5.0, -5.0), complex(3.2, -6.8), complex(-6.8, -6.8), complex(-5.0, -5.0))]


SUPPORT_CLEAR = 1.0   # mm of white round a support's symbol (review 10 #16: at 0,4 mm the crank's O1
                     # read as a bare bar among its twelve thin lines, its 0,35-mm legs like theirs)


def break_under_supports(rec: Record, outlines: list[list[complex]], clear: float = SUPPORT_CLEAR) -> None:
    """The thin lines (``labels.breakable``: the thin positions, trajectories, construction)
    interrupted where they pass under a support's symbol and ``clear`` round it, as a draftsman
    draws the support over them: the crank's twelve lines leave its pivot clear of its frame symbol."""
    if not outlines:
        return
    from dataclasses import replace

    from shapely.geometry import LineString, Polygon
    from shapely.ops import unary_union

    from graphplan.drawing.labels import breakable
    cover = unary_union([Polygon([(z.real, z.imag) for z in o]).buffer(clear) for o in outlines])
    out = []
    for p in rec.items:
        if p.kind not in ("segment", "polyline") or not breakable(p) or len(p.points) < 2:
            out.append(p)
            continue
        line = LineString(p.points)
        if not line.intersects(cover):
            out.append(p)
            continue
        rest = line.difference(cover)
        parts = [rest] if rest.geom_type == "LineString" else list(getattr(rest, "geoms", []))
        for g in parts:
            if g.geom_type == "LineString" and g.length > 0.05:
                pts = tuple((float(x), float(y)) for x, y in g.coords)
                out.append(replace(p, points=pts if p.kind == "polyline" else (pts[0], pts[-1])))
    rec.items[:] = out


def support(rec: Record, X: complex, direction: float, step: str = "") -> None:
    """A fixed pivot's support (GOST 2.770): a triangle from the pivot to a bar 5 mm away along
    ``direction`` (degrees), the bar hatched on its far side."""
    r = cmath.exp(1j * math.radians(direction + 90.0))        # (0, −1), straight down, → direction

    def at(c: complex) -> tuple[float, float]:
        return _pt(X + c * r)
    a, b = complex(-3.5, -5.0), complex(3.5, -5.0)
    rec.segment(_pt(X), at(a), role="frame", width=0.35, layer="frame", step=step)
    rec.segment(_pt(X), at(b), role="frame", width=0.35, layer="frame", step=step)
    rec.segment(at(a + complex(-1.5, 0)), at(b + complex(1.5, 0)), role="frame", layer="frame", step=step)
    for k in range(5):
        s = a + complex(-1.5 + 2.5 * k, 0)
        rec.segment(at(s), at(s + complex(-1.8, -1.8)), role="hatch", layer="frame", step=step)
    rec.point(_pt(X), role="joint", layer="frame", step=step)


def draw_frame(rec: Record, sc: Scheme, layouts: list[Layout], thick: list[Layout] | None = None,
               drawn: list[Layout] | None = None, yokes: dict[str, YokeSpans] | None = None) -> list[list[complex]]:
    """Fixed pivots with their supports (each where no link of the ``drawn`` positions passes,
    else on the side away from the links leaving it at the ``thick`` positions, below where that
    is free: ``frame_support``), fixed guides with hatching over the slider's travel. Returns the
    supports' outlines (``support_outline``: the thin lines drawn later are broken under them)."""
    mech = sc.mech
    lay0 = layouts[0]
    outlines = []
    for name in mech.frame:
        if not any(name in link.joints for link in mech.links.values()):
            continue
        X = where(sc, lay0, FRAME, name)
        d, _ = frame_support(sc, drawn or [], thick or [], name, omega=name == mech.crank.pivot)
        support(rec, X, d, step=f"support {name}")
        outlines.append(support_outline(X, d))
    for gname, g in mech.guides.items():
        if g.body != FRAME:
            continue
        sliders = [n for n, l in mech.links.items() if l.slides_on == gname]
        if not sliders:
            continue
        bushings = [(yokes or {}).get(n) for n in sliders]
        if all(b is not None and b.bushing is not None for b in bushings):
            for b in bushings:          # a yoke's rod: its bushing beside the crank, not a wall through it
                draw_bushing(rec, *b.bushing, step=f"guide {gname}")
            continue
        base = where_frame(sc, lay0, g.through)
        u = cmath.exp(1j * g.angle)
        along = []
        for lay in layouts:
            for s in sliders:
                for p in mech.links[s].local:
                    along.append(((lay.poses[s].at(mech.links[s].local[p]) - base) * u.conjugate()).real)
        lo, hi = min(along) - 12.0, max(along) + 12.0
        rec.segment(_pt(base + lo * u), _pt(base + hi * u), role="frame", layer="frame", step=f"guide {gname}")
        normal = -1j * u
        # the hatching stops at a block drawn on the guide (a thick position's, BLOCK wide): the
        # block sits on the guide's hatched side, and strokes through it read as drawn over it
        blocks = [(((lay.poses[s].at(mech.links[s].local[next(iter(mech.links[s].local))]) - base)
                    * u.conjugate()).real, block_size(sc, s)[0] / 2) for lay in (thick or []) for s in sliders]
        # … and at a wedge's triangle drawn over it (review 62: the ram's guide run down into the wedge,
        # its strokes across the wedge's side): the guide's line goes on, its hatching stops
        travel = wedge_travel(sc, drawn or layouts)
        wedges = [w for lay in (thick or []) for w in wedge_bodies(sc, lay, travel)]
        t = lo
        while t <= hi:
            s = base + t * u + normal * 2.5
            if not any(t - 2.0 < c + half + BLOCK_CLEAR and t > c - half - BLOCK_CLEAR for c, half in blocks) \
                    and not any(_inside(z, w) for w in wedges for z in (base + t * u + normal * 0.35, s - u * 2.0)):
                rec.segment(_pt(base + t * u + normal * 0.35), _pt(s - u * 2.0), role="hatch", layer="frame")
            t += 4.0
    return outlines


def where_frame(sc: Scheme, lay: Layout, p: complex) -> complex:
    return lay.poses[FRAME].at(p)


def draw_construction(rec: Record, lay: Layout) -> None:
    """The compass arcs that found each group's point (a short arc each side of it)."""
    for mark in lay.drawn:
        if not isinstance(mark, Arc):
            continue
        mid = math.degrees(cmath.phase(mark.at - mark.centre))
        half = math.degrees(ARC_HALF / mark.radius) if mark.radius > 0 else 0.0
        rec.arc(_pt(mark.centre), mark.radius, mid - half, mid + half, role="arc", layer="construction",
                step=f"position {lay.index if lay.index is not None else lay.key}: {mark.group} arcs")


def catmull_rom(points: list[complex], closed: bool = True, per: int = 12) -> list[complex]:
    """A centripetal Catmull–Rom curve through the points (the French curve of the drawing)."""
    if len(points) < 3:
        return points
    pts = points + points[:3] if closed else [points[0]] + points + [points[-1]]
    out: list[complex] = []
    spans = len(points) if closed else len(points) - 1
    for i in range(spans):
        p0, p1, p2, p3 = pts[i], pts[i + 1], pts[i + 2], pts[i + 3]
        if closed:
            p0, p1, p2, p3 = points[i - 1], points[i], points[(i + 1) % len(points)], points[(i + 2) % len(points)]
        t0 = 0.0
        t1 = t0 + max(abs(p1 - p0), 1e-9) ** 0.5
        t2 = t1 + max(abs(p2 - p1), 1e-9) ** 0.5
        t3 = t2 + max(abs(p3 - p2), 1e-9) ** 0.5
        for k in range(per):
            t = t1 + (t2 - t1) * k / per
            a1 = (t1 - t) / (t1 - t0) * p0 + (t - t0) / (t1 - t0) * p1
            a2 = (t2 - t) / (t2 - t1) * p1 + (t - t1) / (t2 - t1) * p2
            a3 = (t3 - t) / (t3 - t2) * p2 + (t - t2) / (t3 - t2) * p3
            b1 = (t2 - t) / (t2 - t0) * a1 + (t - t0) / (t2 - t0) * a2
            b2 = (t3 - t) / (t3 - t1) * a2 + (t - t1) / (t3 - t1) * a3
            out.append((t2 - t) / (t2 - t1) * b1 + (t - t1) / (t2 - t1) * b2)
    out.append(out[0] if closed else points[-1])
    return out


def output_point(plans: Plans) -> str:
    """The point whose extreme positions are marked: the output slide's point, or the output
    rocker's far joint — a slotted lever pivoted at its only joint (O3E) its farthest point from the
    pivot, the end E (review 12: E′, E″ and the position numbers were lettered at the pivot O3)."""
    st = plans.study
    if st.output.kind == "slide":
        return st.output.name
    link = st.mech.links[st.output.name]
    moving = [j for j in link.joints if j not in st.mech.frame]
    if moving:
        return moving[-1]
    pivot = link.joints[-1]
    ends = [p for p in link.local if p != link.com and abs(link.local[p] - link.local[pivot]) > 1e-9]
    return max(ends, key=lambda p: abs(link.local[p] - link.local[pivot]), default=pivot)


def stroke_ends(plans: Plans) -> list[Layout]:
    """The output's two extreme positions that bound its stroke (or swing): where it stops at its
    largest and its smallest value, in the study's order. An output may stop more than twice a
    turn (a six-bar's slider driven through its rod's dead centre: 355.7°, 18.6°, 42.9°, 201.5°,
    the middle two a 0.3-mm dip), and the stroke H is between the largest and the smallest, not the
    first two stops (review 46: it dimensioned H = 1 between 355.7° and 18.6°)."""
    lays = list(plans.extremes)
    if len(lays) <= 2:
        return lays
    values = plans.study.output.value(plans.study.solve([lay.phi for lay in lays]))
    hi, lo = int(max(range(len(lays)), key=lambda i: values[i])), int(min(range(len(lays)), key=lambda i: values[i]))
    return [lays[i] for i in sorted({hi, lo})]


def other_slides(plans: Plans) -> list[str]:
    """The points of the sliders on frame guides other than the output slide — a V-twin's second
    piston C — as the notes name them (``sheets.kintables.other_outputs``): each has its own extreme
    positions and stroke on the position plan (review 59: B′, B″ and H were drawn, C had none); where
    the output is a rocker, a slider whose extreme positions are the rocker's — a plunger the rocker
    follows (stop 60: LINK60's plunger B had neither B′, B″ nor its stroke H beside the rocker's C′,
    C″ and ψ_max); not one that stops elsewhere (LINK57's piston B: its primes and stroke crowded the
    rocker's dwell number 12.6 mm off its points)."""
    from graphplan.exact.positions import point_slider
    st = plans.study
    if st.output.kind not in ("slide", "link"):
        return []
    mech = st.mech
    names = [next(iter(link.local)) for link in mech.links.values()
             if link.slides_on is not None and mech.guides[link.slides_on].body == FRAME
             and next(iter(link.local)) != st.output.name]
    out = [c for c in dict.fromkeys(names) if point_slider(mech, c) is not None]
    if st.output.kind == "link":
        ends = sorted(lay.phi % 360.0 for lay in stroke_ends(plans))

        def same(c: str) -> bool:
            own = sorted(lay.phi % 360.0 for lay in slide_ends(plans, c))
            return len(own) == len(ends) == 2 and all(abs(a - b) < 0.01 for a, b in zip(own, ends))
        out = [c for c in out if same(c)]
    return out


def slide_ends(plans: Plans, name: str) -> list[Layout]:
    """The extreme positions that bound the stroke of the slider at point ``name``: the output's
    ``stroke_ends``; another slider's where its own velocity changes sign (``find_extremes``), the
    largest and the smallest of its coordinate, in the crank's angle order (keys −100, −101)."""
    st = plans.study
    if st.output.kind == "slide" and name == st.output.name:
        return stroke_ends(plans)
    from graphplan.exact.positions import Output, find_extremes
    from graphplan.graphic.position_plan import construct_position
    memo = ("slide ends", name)
    if memo not in st.memo:
        out = Output("slide", name)
        found = find_extremes(st.mech, st.structure, out)
        ends: list[float] = []
        if len(found) >= 2:
            values = out.value(st.solve(list(found)))
            hi, lo = int(max(range(len(found)), key=lambda i: values[i])), int(min(range(len(found)), key=lambda i: values[i]))
            ends = [float(found[i]) for i in sorted({hi, lo})]
        st.memo[memo] = ends
    return [construct_position(plans.scheme, phi, plans.mu_l, -100 - k) for k, phi in enumerate(st.memo[memo])]


def swing(plans: Plans) -> float | None:
    """The output rocker's swing ψ_max between its extreme positions, degrees (None for a slider, a
    link turning round or fewer than two extremes)."""
    st = plans.study
    ends = stroke_ends(plans)
    if st.output.kind != "link" or len(ends) < 2:
        return None
    sc = plans.scheme
    link = st.mech.links[st.output.name]
    pivot = next((j for j in link.joints if j in st.mech.frame), None)
    out = output_point(plans)
    if pivot is None or out == pivot:
        return None
    P = where(sc, ends[0], FRAME, pivot)
    a, b = (where(sc, lay, sc.body_of(out), out) - P for lay in ends)
    return abs(math.degrees(cmath.phase(b / a)))


def position_record(plans: Plans, lettered: bool = True, lang: str = "uk", joined: tuple = ()) -> Record:
    """The position plan of all positions, with arcs, trajectories, extremes and labels (only the
    lines when not ``lettered``: what a layout measures before the lettering is placed). ``joined``:
    (point, position, position) — a position numbered with another's spot (``far_numbers``)."""
    sc = plans.scheme
    mech = sc.mech
    rec = Record(title="position plan", scales={"mu_l": plans.mu_l})
    regular = [p.layout for p in plans.positions if p.index is not None]
    every = [p.layout for p in plans.positions]
    thick_keys = set(plans.accel_keys) or {0}
    thick_lays = [l for l in every if l.key in thick_keys]
    crank = mech.crank
    O = where(sc, regular[0], FRAME, crank.pivot)
    r = crank.length / plans.mu_l
    # the other sliders' extreme positions (a V-twin's second piston): drawn, their points lettered
    # C′, C″ and their strokes dimensioned, as the output's are
    others = [lay for c in other_slides(plans) for lay in slide_ends(plans, c)
              if all(abs(lay.phi - e.phi) > 1e-4 for e in plans.extremes)]     # not drawn twice (a rocker's
    # extremes where its plunger's are the same: LINK60's rocker moves with B alone)
    yokes = {n: yoke_spans(sc, every + plans.extremes + others, n, O, r) for n in mech.links if yoke_guide(mech, n)}
    travel = wedge_travel(sc, every + plans.extremes + others)
    outlines = draw_frame(rec, sc, every + plans.extremes + others, thick_lays, drawn=every + plans.extremes + others,
                          yokes=yokes)
    rec.circle(_pt(O), r, role="trajectory", layer="construction", step="the crank pin's circle")
    for lay in every:
        draw_construction(rec, lay)
    for name in plans.trajectories:
        path = [where(sc, lay, sc.body_of(name), name) for lay in regular]
        if max(abs(p - path[0]) for p in path) > 1.0:
            curve = catmull_rom(path)
            rec.add("polyline", [_pt(c) for c in curve], role="trajectory", layer="construction",
                    step=f"trajectory of {name}")
    # a coupler point's path (not a centre of mass's) is read position by position, as the joints'
    # are: a dot at each, numbered (``_numbered``) — the four-bar's E drew a bare loop under its
    # twelve thin coupler triangles, none of its corners marked, while Table 1 gives v_E at each
    for name in coupler_points(plans):
        for lay in regular:
            rec.point(_pt(where(sc, lay, sc.body_of(name), name)), role="dot", layer="mechanism",
                      step=f"trajectory of {name}")
    traced = set(plans.trajectories)
    for name in sheet_points(plans):
        if name in traced:
            continue
        path = [where(sc, lay, sc.body_of(name), name) for lay in regular]
        if max(abs(p - path[0]) for p in path) > 1.0 and not _on_circle_or_line(path):
            rec.add("polyline", [_pt(c) for c in catmull_rom(path)], role="trajectory",
                    layer="construction", step=f"trajectory of {name}")
    out = output_point(plans)
    extremes = [lay for lay in stroke_ends(plans) + others
                if all(abs((lay.phi - p.phi + 180.0) % 360.0 - 180.0) > 1e-6 for p in plans.positions)]
    extremes = [lay for k, lay in enumerate(extremes)          # one drawing where two sliders stop at once
                if all(abs((lay.phi - e.phi + 180.0) % 360.0 - 180.0) > 1e-6 for e in extremes[:k])]
    for lay in extremes:
        draw_links(rec, sc, lay, thick=False, role="projection", step="extreme position", yokes=yokes, travel=travel)
    for lay in every:
        if lay.key not in thick_keys:
            draw_links(rec, sc, lay, thick=False, step=f"position {lay.key}", yokes=yokes, travel=travel)
    for lay in every:
        if lay.key in thick_keys:
            draw_links(rec, sc, lay, thick=True, step=f"position {lay.key}", yokes=yokes, travel=travel)
    break_under_supports(rec, outlines)
    # every line first (the extreme points, the stroke's dimension, ω1's arc), then the lettering
    late: list[LabelRequest] = []
    late += extreme_letters(rec, plans, O)
    late += stroke_dimensions(rec, plans, O, lang)
    labels: list[LabelRequest] = []
    # letters at the first thick position, placed first: each beside its point (a link's number,
    # placed after them, by its bar)
    lay = next(l for l in every if l.key in sorted(thick_keys)[0:1] or l.key == min(thick_keys))
    pts = joints_at(sc, lay)
    centre = sum(pts.values(), 0j) / len(pts)
    dots = [complex(*q.points[0]) for q in rec.items if q.kind == "point"]
    joints = {j for link in mech.links.values() for j in link.joints}
    pins = [joints_at(sc, l).get(crank.pin) for l in every]
    pins = [z for z in pins if z is not None]
    # with several thick positions each one's moving joints carry its number (as thick_letters'; a
    # centre of mass, lettered at the first only, keeps its S₂), the first's too (review
    # 11 #15: position 4's slider a plain B beside position 9's A₉, B₉); one thick position is the plan
    together = coinciding(pts)
    paired = coulisse_points(mech)
    for name, X in pts.items():
        if name not in together:
            continue                      # lettered with the point it coincides with (O₁, S₁)
        # crowded by thin positions: beside it, the lines broken; nearer it than the point's other
        # positions drawn as dots (a centre of mass is dotted at the thick positions only)
        rivals = tuple(z for z in (joints_at(sc, l).get(name) for l in every) if z is not None and abs(z - X) > 1e-6
                       and any(abs(z - d) < 1e-6 for d in dots))
        if name in mech.frame:
            # a pivot's letter read as none of the crank pin's positions, which are numbered after
            # it: a four-bar's crank circle 12 mm across had its O₁ set 1.3 mm from the pin's
            # position 8, whose number then found no spot but on a leader through that O₁
            rivals = tuple(z for z in pins if SAME_DOT < abs(z - X) < PIVOT_RIVALS)
        text = ", ".join(indexed(n) if len(thick_lays) < 2 or n in mech.frame or n not in joints or n in paired else
                         at_position(n, lay.index if lay.index is not None else lay.key) for n in together[name])
        labels.append(LabelRequest(X, text, toward=X - centre if abs(X - centre) > 1e-9 else 1j, size=3.5,
                                   breaks=True, rivals=rivals))
    for other in thick_lays:
        if other.key != lay.key:
            labels += thick_letters(sc, other, every, dots)
    d, middle = frame_support(sc, every + plans.extremes, thick_lays, crank.pivot, omega=True)
    if middle is not None:
        middle = roomiest_arc(rec, O, r, leaving(sc, thick_lays, crank.pivot), d, middle)
    labels = omega_arrow(rec, O, r, mech.omega1, 245.0 if middle is None else middle) + labels   # by its arc, first
    if not lettered:
        return rec
    lines = rec.bounds()          # every line drawn: the swing's lettering stays within them
    place_labels(rec, labels)
    owners = number_owner(sc, thick_lays, rec)
    for alternatives in link_numbers(sc, lay, pts, along=True):     # each beside its own bar
        place_first(rec, alternatives, accept=owners.get(alternatives[0].step))
    dots = [complex(*q.points[0]) for q in rec.items if q.kind == "point"]     # with the extremes'
    lettered_at = {(other.key, name) for other in thick_lays if other.key != lay.key or len(thick_lays) > 1
                   for name in joints_at(sc, other) if name not in mech.frame
                   and name not in paired}          # B₈ says 8 there (a coulisse's A: its number beside it)
    numbers = position_numbers(plans, O, dots, skip=lettered_at, joined=joined)
    placed = place_labels(rec, numbers + [q for q in late if q.step != SWING_STEP])
    placed = place_swing(placed, [q for q in late if q.step == SWING_STEP], lines)
    more = () if joined else far_numbers(plans, placed, numbers)
    return position_record(plans, lettered, lang, joined=more) if more else placed


LONG_LEADER = 12.0    # mm: a position's number this far from its point is read on a long leader …
JOIN_SPOT = 2.5       # … and is numbered with another spot of its point this near (a number's height) instead


def far_numbers(plans: Plans, rec: Record, numbers: list[LabelRequest]) -> tuple:
    """The positions whose number stands ``LONG_LEADER`` mm or more from its point (no spot nearer
    was free) while another numbered spot of the same point lies within ``JOIN_SPOT`` — the height
    of a number, nearer than two numbers can each stand beside their own — as (point, position,
    the other spot's first position): numbered there together, as a student numbers a rocker's
    dwell "0, 1, 2, 3, 11" (stop 57: LINK57's D₃, 2.1 mm from D₂, stood on a 30-mm leader across
    the swing's arc and the rocker's positions, no free spot nearer among its lines)."""
    sc = plans.scheme
    texts = [q for q in rec.items if q.kind == "text"]
    out = []
    for name, _ in _numbered(plans):
        path = [where(sc, p.layout, sc.body_of(name), name) for p in plans.positions]
        for req in numbers:
            ks = [k for k, z in enumerate(path) if abs(z - req.at) < 1e-9]
            if not ks:
                continue
            same = [q.ink() for q in texts if q.text == req.text]
            if not same:                       # not placed (sketched, or optional and dropped)
                continue
            gap = min(abs(complex(max(b[0] - req.at.real, 0.0, req.at.real - b[2]),
                                  max(b[1] - req.at.imag, 0.0, req.at.imag - b[3]))) for b in same)
            if gap < LONG_LEADER:
                continue
            k = ks[0]
            mine = {int(t) for t in req.text.split(", ") if t.isdigit()}
            near = [j for j, z in enumerate(path) if j not in mine and abs(z - path[k]) < JOIN_SPOT]
            if near:
                j = min(near, key=lambda j: abs(path[j] - path[k]))
                out.append((name, k, j))
    return tuple(out)


SAME_POINT = 0.05     # mm drawn: two named points this near are one point (a centre of mass on its pivot, S₁ = 0)


def coinciding(pts: dict[str, complex]) -> dict[str, list[str]]:
    """The named points grouped where they coincide, each group keyed by the name that letters it:
    a frame pivot first, then a joint, then a centre of mass (``pts``' order within each). One
    label for the group ("O₁, S₁", as the velocity plan letters the points at its pole "p_v, s₁"):
    review 54 #12 — the crank's S₁ = 0 was lettered up and left of O₁ on the crank's line, as if a
    point of its own."""
    def rank(name: str) -> int:
        return 0 if not name.startswith("S") or name[1:2].isalpha() else 1
    order = sorted(pts, key=lambda n: (rank(n), list(pts).index(n)))
    out: dict[str, list[str]] = {}
    for name in order:
        host = next((h for h in out if abs(pts[h] - pts[name]) <= SAME_POINT), None)
        if host is None:
            out[name] = [name]
        else:
            out[host].append(name)
    return out


def at_position(name: str, k: int | str) -> str:
    """A point's letter at a further thick position: its number as a subscript, B₈; a name with a
    number of its own takes both, A_{3,8}."""
    head = name.rstrip("0123456789")
    if head and head != name:
        return f"{escape(head)}_{{{name[len(head):]},{k}}}"
    return f"{escape(name)}_{{{k}}}"


def coulisse_points(mech) -> set[str]:
    """The joints a block carries along a moving link's guide (a coulisse's A): the sheet writes
    A₂, A₃ for that point of the block and of the slotted link (v_A3A2, a^k_A3A2), so a further
    thick position's A₈ (or the first's A₂) would read as a link's point (review 56 #4) — there
    the position is said by its number only, as at every thin position, and the letter stays
    plain."""
    return {j for link in mech.links.values() if link.slides_on is not None
            and mech.guides[link.slides_on].body != FRAME for j in link.joints}


def thick_letters(sc: Scheme, lay: Layout, every: list[Layout], dots: list[complex]) -> list[LabelRequest]:
    """The moving joints of a thick (acceleration) position other than the first, lettered with the
    position's number (B₈, C₈, D₈: review 6 #11 — position 8's hollow joints had no letters while
    position 3's had), each beside its point rather than the same point's other positions'."""
    mech = sc.mech
    pts = joints_at(sc, lay)
    joints = {j for link in mech.links.values() for j in link.joints}
    centre = sum(pts.values(), 0j) / len(pts)
    out = []
    paired = coulisse_points(mech)
    for name, X in pts.items():
        if name in mech.frame or name not in joints or name in paired:
            continue
        rivals = tuple(z for z in (joints_at(sc, l).get(name) for l in every) if z is not None
                       and abs(z - X) > 1e-6 and any(abs(z - d) < 1e-6 for d in dots))
        out.append(LabelRequest(X, at_position(name, lay.index if lay.index is not None else lay.key),
                                toward=X - centre if abs(X - centre) > 1e-9 else 1j, size=3.5, breaks=True,
                                rivals=rivals, step=f"position {lay.key}"))
    return out


def primed(name: str, k: int) -> str:
    """A point's letter at an extreme position: B′, B″ (the prime after the subscript: S₄′)."""
    mark = {1: "′", 2: "″"}.get(k, f"({k})")
    head = name.rstrip("0123456789")
    return f"{escape(head)}_{{{name[len(head):]}}}{mark}" if head and head != name else escape(name) + mark


def extreme_order(plans: Plans, name: str | None = None) -> list[Layout]:
    """The extreme positions (of the output, or of the slider at point ``name``) in the order the crank
    reaches them from position 0 (the first ′, the second ″): position 0 itself first where it is one."""
    st = plans.study
    ends = stroke_ends(plans) if name is None else slide_ends(plans, name)
    turn = [float(st.from_position0(lay.phi)) for lay in ends]
    turn = [0.0 if t > 360.0 - 1e-6 else t for t in turn]
    return [lay for _, lay in sorted(zip(turn, ends), key=lambda t: t[0])]


def extreme_letters(rec: Record, plans: Plans, O: complex) -> list[LabelRequest]:
    """The extreme positions lettered as the textbook letters them: the output point (the slider's
    B′, B″, a rocker's far joint) and the crank pin (A′, A″) at each, marked by a point — both
    extremes, the one on a numbered position (position 0 at a dead centre) too, each letter
    beside its own point rather than a neighbouring position's (review 7 #6: the second dead centre
    of A was an unlabelled dot 2.6 mm from A6)."""
    sc = plans.scheme
    out = output_point(plans)
    names = list(dict.fromkeys([out, sc.mech.crank.pin]))
    paths = {n: [where(sc, p.layout, sc.body_of(n), n) for p in plans.positions] for n in names}
    labels = []
    sets = [(extreme_order(plans), names)]
    other = other_slides(plans)
    for c in other:               # a second piston: its own C′, C″ (the crank pin's A′, A″ are the output's)
        paths[c] = [where(sc, p.layout, sc.body_of(c), c) for p in plans.positions]
        sets.append((extreme_order(plans, c), [c]))
    for order, who in sets:
        for k, lay in enumerate(order[:2], 1):
            for name in who:
                X = where(sc, lay, sc.body_of(name), name)
                rec.point(_pt(X), role="joint" if name in (out, *other) else "dot", layer="mechanism",
                          step="extreme position")
                path = paths[name]
                mid = sum(path, 0j) / len(path)
                toward = X - O if name == sc.mech.crank.pin else (X - mid if abs(X - mid) > 1e-6 else 1j)
                rivals = tuple(z for z in path if SAME_DOT < abs(z - X) < RIVALS_WITHIN)
                labels.append(LabelRequest(X, primed(name, k), toward=toward, size=3.0, optional=True,
                                           rivals=rivals, step="extreme position"))
    return labels


def coupler_points(plans: Plans) -> list[str]:
    """The traced points that are neither a joint nor a centre of mass: a coupler point (the
    four-bar's E off its coupler AB), whose path is the construction's own result."""
    mech = plans.scheme.mech
    coms = {link.com for link in mech.links.values()}
    joints = {j for link in mech.links.values() for j in link.joints}
    return [n for n in plans.trajectories if n not in coms and n not in joints and n not in mech.frame]


def _numbered(plans: Plans) -> list[tuple[str, bool]]:
    """The points whose positions are numbered: the crank pin (always lettered) and the output
    point, the groups' inner joints and the coupler points (``coupler_points``; left out where no
    room is)."""
    crank = plans.scheme.mech.crank
    inner = [d.inner.point for d in plans.study.structure.dyads if d.kind in ("RRR", "RRP", "PRP")]
    # a slotted link's block pinned to a moving link (LINK50's stone 4 on the rocker's C, not the
    # crank pin): its pin's positions traced as the joints' are, numbered as theirs (stop 50)
    frame = plans.scheme.mech.frame
    blocks = [d.block_parts[2].point for d in plans.study.structure.dyads if d.kind == "RPR"]
    inner += [n for n in blocks if n not in frame]
    # every other moving joint too: a group's outer joint on a moving link is constructed at each
    # position as the inner ones are (stop 52: the coulisse's end D, whose arc the rod DE starts
    # from, carried twelve bare dots; LINK51's B, FORCE_COUPLER51's coupler point E likewise)
    joints = [j for link in plans.scheme.mech.links.values() for j in link.joints if j not in frame]
    return [(crank.pin, False)] + [(n, True) for n in dict.fromkeys([output_point(plans)] + inner + joints
                                                                    + coupler_points(plans))
                                   if n != crank.pin]


def _beside(path: list[complex], i: int, O: complex) -> complex:
    """The side a position number takes at the path's i-th point: across the path (its chord
    through the neighbours), on its convex side — away from the path's middle; a straight path
    (a slider's guide) away from the crank's pivot O."""
    n = len(path)
    t = path[(i + 1) % n] - path[(i - 1) % n]
    if abs(t) < 1e-6:
        t = path[(i + 1) % n] - path[i] if abs(path[(i + 1) % n] - path[i]) > 1e-6 else 1.0 + 0j
    normal = 1j * t / abs(t)
    middle = sum(path, 0j) / n
    away = path[i] - middle
    if abs((away * normal.conjugate()).real) < 0.05 * max(abs(away), 1e-9) or abs(away) < 1e-6:
        away = path[i] - O
    return normal if (away * normal.conjugate()).real >= 0 else -normal


PIVOT_RIVALS = 12.0    # mm: the drawn points a fixed pivot's letter is kept from (``position_record``)
RIVALS_WITHIN = 30.0   # mm: the other points a position number is kept from (farther ones cannot be confused)
SAME_DOT = 1.0         # mm: a drawn point this near a position's point is that point (an extreme on a dead centre)


def position_numbers(plans: Plans, O: complex, dots: list[complex] = (),
                     skip: set[tuple] = frozenset(), joined: tuple = ()) -> list[LabelRequest]:
    """The numbers of the positions at the crank pin, the output point and the groups' inner
    joints: each across its path beside its own point, read as nobody else's — nearer its point
    than any other numbered point of another position or any other drawn point (``dots``: a
    centre of mass, a joint of the thick position) — ``rivals`` — else on a leader to it. None at
    the points ``skip`` names, (position key, point): a further thick position's joints, lettered
    with the position's number (B₈ — not "B₈ 8")."""
    sc = plans.scheme
    named = _numbered(plans)
    rows = []
    for name, optional in named:
        path = [where(sc, p.layout, sc.body_of(name), name) for p in plans.positions]
        rows.append((name, optional, path))
    labels = [str(p.index) if p.index is not None else f"{p.phi:g}°" for p in plans.positions]
    groups = {name: {g[0]: g for g in same_spots(path, [k for k, p in enumerate(plans.positions)
                                                         if (p.key, name) not in skip],
                                                  [(k, j) for n, k, j in joined if n == name])}
              for name, _, path in rows}
    out = []
    for k, p in enumerate(plans.positions):      # in the positions' order (the placing's priority)
        for name, optional, path in rows:
            group = groups[name].get(k)
            if group is None:                     # skipped, or numbered with an earlier position
                continue
            X = path[k]
            # the group's own positions' points are no rivals of its number: "5, 7" at D₅ is
            # D₇'s too (stop 52: D₇'s dot 1.1 mm off barred half the leaders, and the number was lost)
            mine = [q[j] for _, _, q in rows for j in group]
            others = [q[j] for _, _, q in rows for j in range(len(q)) if j not in group]
            rivals = tuple(z for z in others + [d for d in dots if abs(d - X) > SAME_DOT]
                           if abs(z - X) < RIVALS_WITHIN and min(abs(z - m) for m in mine) > 1e-6)
            toward = X - O if name == sc.mech.crank.pin else _beside(path, k, O)
            out.append(LabelRequest(X, ", ".join(labels[j] for j in group), toward=toward, size=2.5,
                                    optional=optional, rivals=rivals))
    return out


SAME_SPOT = 1.2    # mm: a point's positions nearer each other than this are numbered together ("4, 7, 8")


def same_spots(path: list[complex], keys: list[int], joined: list[tuple[int, int]] = ()) -> list[list[int]]:
    """The positions ``keys`` of one point grouped where its points lie within ``SAME_SPOT`` of
    each other (chained), each group in the positions' order: a rocker dwelling near its extreme
    puts three positions within 1 mm, where three numbers cannot each sit beside its own point —
    the drawing numbers the spot once, "4, 7, 8", as a student does (stop 51: D's positions 5 and 7
    were left unnumbered). ``joined``: pairs of positions numbered together however far apart
    (``far_numbers``)."""
    groups: list[list[int]] = []
    pairs = {frozenset(p) for p in joined}
    for k in keys:
        near = [g for g in groups if any(abs(path[k] - path[j]) < SAME_SPOT or frozenset((k, j)) in pairs for j in g)]
        merged = [k] + [j for g in near for j in g]
        groups = [g for g in groups if g not in near] + [sorted(merged)]
    return sorted(groups)


DIM_OFF = 12.0    # mm from the slider's path to the stroke's dimension line (clear of the block)
DIM_PAST = 7.0    # … and at least this far past the drawing's last line on that side, over the stroke
DIM_SIDE = 10.0   # mm: the side toward the crank is taken where it is clear this much nearer the path


def _strokes(rec: Record) -> list[tuple[complex, complex]]:
    """Every drawn line of the record as straight pieces (arcs and circles as 5° chords)."""
    out = []
    for p in rec.items:
        if p.kind in ("circle", "arc"):
            c = complex(*p.points[0])
            lo, hi = p.angles if p.kind == "arc" else (0.0, 360.0)
            sweep = (hi - lo) % 360.0 or 360.0
            zs = [c + p.radius * cmath.exp(1j * math.radians(lo + sweep * k / 72)) for k in range(73)]
        elif p.kind in ("segment", "vector", "polyline", "polygon"):
            zs = [complex(x, y) for x, y in p.points] + ([complex(*p.points[0])] if p.kind == "polygon" else [])
        else:
            continue
        out += list(zip(zs, zs[1:]))
    return out


def dimension_place(rec: Record, X1: complex, u: complex, away: complex, span: float) -> tuple[complex, float]:
    """Where the stroke's dimension line goes: the side of the slider's path (``away`` from the
    crank first) and the offset (from ``DIM_OFF`` out, 1 mm steps, to ``DIM_PAST`` past the
    drawing's last line on that side over the stroke) at which it crosses the fewest lines — the
    nearest such, the side toward the crank counted ``DIM_SIDE`` mm farther (away from the crank on
    a tie). The slotter's H = 350 ran 12 mm above its guide through its rods; it now runs above
    them, clear. Stop 62: LINK62's slider B under a slotted lever's fan, its H clear 111 mm below
    the guide past the lever's end C″ (read as C′C″'s stroke), is clear 48 mm above it."""
    import numpy as np
    pieces = _strokes(rec)
    if not pieces:
        return away, DIM_OFF
    P = np.array([[((a - X1) * u.conjugate()).real, ((a - X1) * u.conjugate()).imag,
                   ((b - X1) * u.conjugate()).real, ((b - X1) * u.conjugate()).imag] for a, b in pieces])
    best = None
    for sign, side in ((1.0, away), (-1.0, -away)):
        # in the path's frame (x along u, y across, + toward n = 1j·u): the side's y sign
        ys = (side * u.conjugate()).imag
        x0, y0, x1, y1 = P[:, 0], P[:, 1] * ys, P[:, 2], P[:, 3] * ys
        over = ((np.maximum(x0, x1) >= -5.0) & (np.minimum(x0, x1) <= span + 5.0))
        reach = float(np.max(np.where(over, np.maximum(y0, y1), 0.0), initial=0.0))
        for off in np.arange(DIM_OFF, max(DIM_OFF, reach + DIM_PAST) + 0.5, 1.0):
            dy = y1 - y0
            with np.errstate(all="ignore"):
                t = (off - y0) / dy
                x = x0 + t * (x1 - x0)
            hits = int(np.sum((np.abs(dy) > 1e-12) & (t >= 0) & (t <= 1) & (x >= 0) & (x <= span)))
            key = (hits, float(off) + (DIM_SIDE if sign < 0 else 0.0), sign < 0)
            if best is None or key < best[0]:
                best = (key, side, float(off))
            if hits == 0:
                break
    return best[1], best[2]


def stroke_dimensions(rec: Record, plans: Plans, O: complex, lang: str = "uk") -> list[LabelRequest]:
    """The output slider's stroke H between its extreme positions, dimensioned on the side of its
    path away from the crank (extension lines, a dimension line with arrows at both ends, GOST
    2.307), and a crank-slider's offset e from the crank's pivot to the path — each lettered with its
    real size in mm (``H = 250``, ``e = 30``), as a kinematic scheme gives them. None for a rocker."""
    st = plans.study
    if st.output.kind == "link":
        # a rocker driven through a slider on a frame guide: the slider's stroke too (LINK60's plunger)
        other = other_slides(plans)
        return swing_dimension(rec, plans, lang) + [
            label for name in other
            for label in _stroke_dimension(rec, plans, O, name, "H" if len(other) == 1 else f"H_{{{escape(name)}}}",
                                           lang)]
    if st.output.kind != "slide":
        return []
    sc = plans.scheme
    out = output_point(plans)
    other = other_slides(plans)
    labels: list[LabelRequest] = []
    for name in [out, *other]:
        # two sliders' strokes lettered apart, each by its point (H_B, H_C: a V-twin's pistons)
        labels += _stroke_dimension(rec, plans, O, name, "H" if not other else f"H_{{{escape(name)}}}", lang)
    ends = stroke_ends(plans)
    if len(ends) < 2:
        return labels
    X1, X2 = (where(sc, lay, sc.body_of(out), out) for lay in ends)
    if abs(X2 - X1) < 1e-6:
        return labels
    u = (X2 - X1) / abs(X2 - X1)
    n = 1j * u
    side = ((O - X1) * n.conjugate()).real          # O's side of the path (+ along n)
    step = "dimensions"
    mm = 1000.0 * plans.mu_l
    if len(st.structure.dyads) == 1 and abs(side) * mm >= 0.5:      # a crank-slider's offset
        # beside the crank's circle, on the side away from the slider: O's line and the path carried
        # there parallel to the path, the dimension line across them
        F = X1 + ((O - X1) * u.conjugate()).real * u                # the foot of O on the path
        back = -u if ((0.5 * (X1 + X2) - O) * u.conjugate()).real > 0 else u
        r = st.mech.crank.length / plans.mu_l
        near = min((X1, X2), key=lambda z: abs(z - F))
        for start, end in ((O, O + back * (r + 10.0)), (near, F + back * (r + 10.0))):
            rec.segment(_pt(start), _pt(end), role="construction", layer="construction", step=step)
        a, b = O + back * (r + 8.0), F + back * (r + 8.0)
        c = 0.5 * (a + b)
        rec.vector(_pt(c), _pt(a), role="construction", layer="construction", step=step)
        rec.vector(_pt(c), _pt(b), role="construction", layer="construction", step=step)
        labels.append(LabelRequest(c, f"e = {_real_mm(abs(side) * mm, lang)} {_MM.get(lang, 'mm')}", toward=back, size=3.5, step=step))
    return labels


def _stroke_dimension(rec: Record, plans: Plans, O: complex, name: str, letter: str,
                      lang: str = "uk") -> list[LabelRequest]:
    """The stroke of the slider at point ``name`` between its extreme positions (``slide_ends``),
    dimensioned on the side of its path away from the crank where the dimension line crosses the
    fewest lines (``dimension_place``) and lettered ``letter`` = its real size in mm."""
    sc = plans.scheme
    ends = slide_ends(plans, name)
    if len(ends) < 2:
        return []
    X1, X2 = (where(sc, lay, sc.body_of(name), name) for lay in ends)
    if abs(X2 - X1) < 1e-6:
        return []
    u = (X2 - X1) / abs(X2 - X1)
    n = 1j * u
    side = ((O - X1) * n.conjugate()).real          # O's side of the path (+ along n)
    away = -n if side > 0 else n
    step = "dimensions"
    away, off = dimension_place(rec, X1, u, away, abs(X2 - X1))
    a, b = X1 + away * off, X2 + away * off
    for X, Y in ((X1, a), (X2, b)):
        rec.segment(_pt(X + away * 1.5), _pt(Y + away * 2.0), role="construction", layer="construction", step=step)
    mid = 0.5 * (a + b)
    rec.vector(_pt(mid), _pt(a), role="construction", layer="construction", step=step)
    rec.vector(_pt(mid), _pt(b), role="construction", layer="construction", step=step)
    mm = 1000.0 * plans.mu_l
    return [LabelRequest(mid, f"{letter} = {_real_mm(abs(X2 - X1) * mm, lang)} {_MM.get(lang, 'mm')}", toward=away,
                         size=3.5, step=step)]


SWING_PAST = 8.0    # mm: the swing's dimension arc this far beyond the rocker's end point (E′, E″)


def swing_dimension(rec: Record, plans: Plans, lang: str = "uk") -> list[LabelRequest]:
    """The output rocker's swing between its extreme positions (E′, E″) dimensioned as an angle
    (GOST 2.307): extension lines from the pivot's rays past E′ and E″, an arc about the pivot
    ``SWING_PAST`` mm beyond them with arrows at both ends, lettered ψ_max = 16,47° (review 12 #8)."""
    from graphplan.util.words import fixed
    psi = swing(plans)
    if psi is None or psi < 0.5:
        return []
    st, sc = plans.study, plans.scheme
    link = st.mech.links[st.output.name]
    pivot = next(j for j in link.joints if j in st.mech.frame)
    out = output_point(plans)
    ends = stroke_ends(plans)
    P = where(sc, ends[0], FRAME, pivot)
    X1, X2 = (where(sc, lay, sc.body_of(out), out) for lay in ends)
    R = max(abs(X1 - P), abs(X2 - P)) + SWING_PAST
    step = "dimensions"
    for X in (X1, X2):
        u = (X - P) / abs(X - P)
        rec.segment(_pt(X + u * 1.5), _pt(P + u * (R + 2.0)), role="construction", layer="construction", step=step)
    a1, a2 = (math.degrees(cmath.phase(X - P)) for X in (X1, X2))
    if (a2 - a1) % 360.0 > 180.0:                  # a1 → a2 counter-clockwise, the short way
        a1, a2 = a2, a1
    a2 = a1 + (a2 - a1) % 360.0
    rec.arc(_pt(P), R, a1, a2, role="construction", layer="construction", step=step)
    for end, sense in ((a1, -1), (a2, 1)):          # the arrows at both ends, pointing outward along the arc
        tail, tip = arc_head(P, R, end, sense)
        rec.vector(tail, tip, role="construction", layer="construction", step=step)
    others = [where(sc, ends[0], FRAME, j) for j in st.mech.frame if j != pivot]
    text = f"ψ_max = {fixed(psi, lang, 2)}°"
    # the lettering may stand its whole width either way of its anchor: clear by that and SWING_CLEAR
    need = text_width(text, 3.5) + SWING_CLEAR
    t = swing_label_at(P, R, a1, a2, others, need)
    mid = P + R * cmath.exp(1j * math.radians(a1 + t * (a2 - a1)))
    # where no spot beside the arc's middle is free (the swing's arc among the rocker's numbered
    # positions), the other shares that clear the pivots, either side of the arc, then beyond its
    # ends: ``place_swing`` takes the first within the plan's lines
    def at(u: float) -> complex:
        return P + R * cmath.exp(1j * math.radians(a1 + u * (a2 - a1)))

    def clear(z: complex) -> bool:
        return all(abs(z - o) >= need for o in others)
    shares = [t] + [u for u in sorted(SWING_TRIES, key=lambda u: abs(u - t)) if u != t and clear(at(u))]
    first = [LabelRequest(mid, text, toward=mid - P, size=3.5, step=SWING_STEP)]
    more = [LabelRequest(at(u), text, toward=side * (at(u) - P), size=3.5, step=SWING_STEP)
            for u in shares for side in (1, -1)][1:]
    # … else beside the outer side's extension line, inside the arc, the side away from the sweep
    # (under the rocker's lowest line, beside B″), a share ``k`` of the radius from the pivot
    ends_ = [LabelRequest(P + k * (at(u) - P), text, toward=(at(u) - P) * (1j if u > 0.5 else -1j),
                          size=3.5, step=SWING_STEP) for u in (1.0, 0.0) for k in SWING_ALONG if clear(at(u))]
    return first + more + ends_


SWING_ALONG = (0.85, 0.7, 0.55)   # shares of the arc's radius along an extension line, tried for the lettering


SWING_STEP = "dimensions: swing"    # the swing's lettering asked at several spots (``place_swing``)


def place_swing(rec: Record, alternatives: list[LabelRequest], frame: tuple[float, float, float, float]) -> Record:
    """The swing's «ψ_max = …» at the first of its ``alternatives`` (``swing_dimension``) with a free
    spot beside it within ``frame`` (the plan's lines' box) grown by ``SWING_OUT`` (a line of
    lettering over the arc, where it is the plan's edge, as the four-bar's stands): else at the
    first on a leader within it; else as any label (the first, farther out, on a leader). Stop 62: at 1:2,5 the crusher's
    «ψ_max = 23,63°» found no spot by its arc among the rocker's twelve numbered positions and
    stood on a 40-mm leader below B″, 20 mm past the plan's lines — the A3 plan measured too tall
    for its sheet fell to 1:4. Beside the arc's end, under the rocker's lowest line, it does not
    grow the plan."""
    from graphplan.drawing.labels import CLEAR as _CLEAR, FAR, _far, beside_first, obstacles
    from graphplan.graphic.record import Primitive
    if not alternatives:
        return rec
    x0, y0, x1, y1 = frame[0] - SWING_OUT, frame[1] - SWING_OUT, frame[2] + SWING_OUT, frame[3] + SWING_OUT

    def inside(box) -> bool:
        return box[0] >= x0 and box[1] >= y0 and box[2] <= x1 and box[3] <= y1
    if beside_first(rec, alternatives, inside):
        return rec
    ob = obstacles(rec.items)
    for req in alternatives:
        ink = Primitive("text", ((0.0, 0.0),), text=req.text, size=req.size).ink()
        size = (ink[2] - ink[0]) + (ink[3] - ink[1]) + _CLEAR + 2.0
        spot = _far(ob.near(req.at, FAR[-1] + size), req, ink, inside)
        if spot is not None and abs(spot[2][1] - spot[2][0]) <= SWING_LEADER:
            (a, b) = spot[2]
            rec.segment((a.real, a.imag), (b.real, b.imag), role="label", layer="labels", step=req.step)
            rec.label((spot[1].real, spot[1].imag), req.text, size=req.size, anchor="start", step=req.step,
                      layer="labels")
            return rec
    return place_labels(rec, alternatives[:1])


SWING_OUT = 6.0       # mm: the swing's lettering may stand this far out of the plan's lines (``place_swing``)
SWING_LEADER = 12.0   # mm: the swing's lettering on a leader at most about this long (``place_swing``)


SWING_CLEAR = 10.0   # mm: the swing's lettering (its anchor: this and the text's width) this far from any other pivot
SWING_TRIES = (0.5, 0.4, 0.6, 0.3, 0.7, 0.2, 0.8)    # where along the arc (a share of its sweep), the middle first


def swing_label_at(P: complex, R: float, a1: float, a2: float, others: list[complex],
                   clear: float = SWING_CLEAR) -> float:
    """Where along the swing's dimension arc (about ``P``, radius ``R`` mm, from ``a1`` to ``a2``
    degrees) its ψ_max is lettered, as a share of the sweep: the middle, unless another fixed pivot
    (``others``: the frame's other points, a support drawn at each) stands within ``clear`` mm of it
    (the sheet passes the lettering's width and ``SWING_CLEAR``) — there a teacher reads the angle
    as that pivot's rocker's (review 58: the slotted lever's ψ_max = 57,75° beside O2, the other
    rocker's pivot) — then the nearest share to the middle that clears them all, else the one
    farthest from them."""
    def clearance(t: float) -> float:
        at = P + R * cmath.exp(1j * math.radians(a1 + t * (a2 - a1)))
        return min((abs(at - o) for o in others), default=math.inf)
    good = next((t for t in SWING_TRIES if clearance(t) >= clear), None)
    return good if good is not None else max(SWING_TRIES, key=clearance)


_MM = {"uk": "мм", "en": "mm"}     # a scheme's dimension with its unit (review 56 #6: "H = 42,2" read bare)


def _real_mm(v: float, lang: str = "uk") -> str:
    """A real length in millimetres, as a scheme's dimensions read: whole millimetres where the
    length is whole, else to 0.1 mm in the language's decimal sign (an offset of 12.5 mm reads
    "12,5", not a rounded "12" beside Table 4's 12,5)."""
    from graphplan.util.words import fixed
    v = max(v, 1.0)
    return f"{v:.0f}" if abs(v - round(v)) < 0.05 else fixed(v, lang, 1)


def sheet_points(plans: Plans) -> list[str]:
    """The moving points the sheet's plans and diagrams use: every joint off the frame and the
    centres of mass — their trajectories are traced on the position plan."""
    mech = plans.scheme.mech
    names = []
    for link in mech.links.values():
        for p in list(link.joints) + ([link.com] if link.com else []):
            if p and p not in mech.frame and p not in names and p != mech.crank.pin:
                names.append(p)
    return names


def _on_circle_or_line(path: list[complex]) -> bool:
    """A path already drawn another way: a straight guide (a slider's travel)."""
    a, b = path[0], max(path, key=lambda z: abs(z - path[0]))
    if abs(b - a) < 1e-9:
        return True
    u = (b - a) / abs(b - a)
    return all(abs(((z - a) * u.conjugate()).imag) < 0.3 for z in path)


ALONG = (0.5, 0.35, 0.65, 0.25, 0.75)    # where along its bar a link's number is tried, in turn


def link_numbers(sc: Scheme, lay: Layout, pts: dict[str, complex], along: bool = False):
    """Each link's number beside the middle of its bar (the frame's pivots are 0); with ``along``,
    each link's list of requests at ``ALONG`` of its bar (``labels.place_first``: the first with
    room beside it) — the rod BC's "4" by the rod, not 15 mm off at the guide's end."""
    mech = sc.mech
    out = []
    for name, link in mech.links.items():
        joints = [pts[j] for j in link.joints if j in pts]
        if len(joints) == 1 and link.slides_on is None:
            # a bar with one joint and its own points (a slotted lever O3E pivoted at O3 with E at its
            # end): from the joint to its farthest point — at the pivot alone "5" stood by O₃ and read
            # "O₃5" (stop 55's dosing drive)
            far = max((pts[q] for q in link.local if q in pts), key=lambda z: abs(z - joints[0]), default=joints[0])
            if abs(far - joints[0]) > 1e-9:
                joints = [joints[0], far]
        if len(joints) >= 2:
            d = joints[1] - joints[0]
            normal = 1j * d / abs(d) if abs(d) > 1e-9 else 1j
            spots = [joints[0] + t * d for t in (ALONG if along else ALONG[:1])]
        elif block_size(sc, name) != BLOCK:
            # a carriage and the stone on its pin (``pinned_blocks``): each numbered beyond its own
            # block's ends or sides, where it stands out of the other — not both at the shared pin
            corners = block_corners(sc, lay, name)
            u = (corners[1] - corners[0]) / abs(corners[1] - corners[0])
            n = 1j * u
            c = pts[next(iter(link.local))]
            w, h = block_size(sc, name)
            ends = [(c + u * w / 2, u), (c - u * w / 2, -u), (c + n * h / 2, n), (c - n * h / 2, -n)]
            asked = [LabelRequest(z, str(link.number), toward=d, size=5.0, optional=True, step=f"number of {name}")
                     for z, d in (ends if along else ends[:1])]
            out.append(asked if along else asked[0])
            continue
        else:
            spots = [pts[next(iter(link.local))]]
            normal = 1j
        asked = [LabelRequest(z, str(link.number), toward=normal, size=5.0, optional=True,
                              breaks=len(joints) >= 2, step=f"number of {name}") for z in spots]     # by a bar: its lines may break
        out.append(asked if along else asked[0])
    return out


def link_shapes(sc: Scheme, lay: Layout) -> dict[str, list[complex]]:
    """Each link's outline at a position, as drawn (``draw_links``): the bar or the plate's closed
    outline through its points, a slider's block."""
    pts = joints_at(sc, lay)
    out = {}
    for name, link in sc.mech.links.items():
        if yoke_guide(sc.mech, name) is not None:
            a, b, p, q = yoke_parts(sc, lay, name, yoke_spans(sc, [lay], name))
            # the rod's own unit: its span is 0 where the slot runs through D and S (a yoke whose
            # rod starts at the slot: 0/0 before, stop 51)
            x = rod_crossing(p, _yoke_frame(sc, lay, name)[1], a, (b - a) / abs(b - a))
            out[name] = [a, b, x, q if abs(q - x) >= abs(p - x) else p]
        elif link.slides_on is not None and len(link.joints) <= 1:
            corners = block_corners(sc, lay, name)
            out[name] = corners + corners[:1]
        else:
            out[name] = [pts[p] for p in outline_names(link, pts)]
    return out


LETTER_APART = 2.5   # mm between a link's number and any other lettering (not "1O₁", "4S₄" read as one)


def number_owner(sc: Scheme, thick: list[Layout], rec: Record | None = None):
    """For each link (by the step ``link_numbers`` gives its number, "number of NAME") the spots its
    number may take on the position plan: nearer its own link (at the thick positions) than any
    other's — at most half as far, less ``OWN_MARGIN``, or 1.5 mm nearer — and outside every other
    link's outline (a plate's triangle): a number stands by its own link (review 6 #8: the rod's
    "4" between the plate's edge CB and the rod, 3 mm from each, read as the plate's); and
    ``LETTER_APART`` from the lettering already in ``rec``."""
    from shapely.geometry import LineString, Point, Polygon, box as rect
    from shapely.ops import unary_union

    from graphplan.drawing.labels import OWN_MARGIN, RIVAL_FARTHER
    shapes: dict[str, list] = {name: [] for name in sc.mech.links}
    plates: dict[str, list] = {name: [] for name in sc.mech.links}
    for lay in thick:
        for name, zs in link_shapes(sc, lay).items():
            xy = [(z.real, z.imag) for z in zs]
            if len(xy) >= 2:
                shapes[name].append(LineString(xy))
            if len(xy) >= 4 and abs(zs[0] - zs[-1]) < 1e-9:
                poly = Polygon(xy)
                if poly.is_valid and poly.area > 1.0:
                    plates[name].append(poly)

    def rule(name: str):
        own = unary_union(shapes[name]) if shapes[name] else None
        rest = [g for other, gs in shapes.items() if other != name for g in gs]
        others = unary_union(rest) if rest else None
        inside = [p for other, ps in plates.items() if other != name for p in ps]
        if own is None or others is None:
            return None

        def accept(box) -> bool:
            if rec is not None:
                g = LETTER_APART
                for q in rec.items:
                    if q.kind == "text":
                        x0, y0, x1, y1 = q.ink()
                        if x0 < box[2] + g and box[0] - g < x1 and y0 < box[3] + g and box[1] - g < y1:
                            return False
            r = rect(*box)
            centre = Point(0.5 * (box[0] + box[2]), 0.5 * (box[1] + box[3]))
            if any(p.contains(centre) for p in inside):
                return False
            mine = r.distance(own)
            return r.distance(others) >= min(2.0 * mine + OWN_MARGIN, mine + RIVAL_FARTHER)
        return accept
    return {f"number of {name}": rule(name) for name in sc.mech.links}


def roomiest_arc(rec: Record, O: complex, r: float, bold: list[float], support_deg: float,
                 middle: float) -> float:
    """ω1's arc's middle among those clear of the thick links and the support (``_omega_arc``'s
    rule): where its letter has the most room — the fewest drawn lines within 3 mm of the spot
    beside the arc's middle — ``middle`` (nearest 245°) on a tie. With the crank's support set
    upright at the side, the arc at 245° put ω₁ 8 mm off it among the crank's lines 5–7."""
    import numpy as np
    rr = max(6.0, 0.25 * r)
    pieces = _strokes(rec)
    if not pieces:
        return middle
    P = np.array([[a.real, a.imag, b.real, b.imag] for a, b in pieces])

    def crowd(m: float) -> int:
        z = O + (rr + 3.5) * cmath.exp(1j * math.radians(m))
        d = P[:, 2:] - P[:, :2]
        L2 = np.maximum((d ** 2).sum(axis=1), 1e-12)
        t = np.clip(((z.real - P[:, 0]) * d[:, 0] + (z.imag - P[:, 1]) * d[:, 1]) / L2, 0.0, 1.0)
        dist = np.hypot(P[:, 0] + t * d[:, 0] - z.real, P[:, 1] + t * d[:, 1] - z.imag)
        return int(np.sum(dist < 3.0))
    allowed = [m for m in range(0, 360, 5)
               if min([_gap(m, a) for a in bold] + [180.0]) - OMEGA_HALF_DEG >= CLEAR_DEG
               and _gap(m, support_deg) >= SUPPORT_HALF_DEG + OMEGA_HALF_DEG + 5.0]
    if not allowed:
        return middle
    return float(min(allowed, key=lambda m: (crowd(m), _gap(m, middle))))


def omega_arrow(rec: Record, O: complex, r: float, omega: float, middle: float = 245.0) -> list[LabelRequest]:
    """The crank's sense of rotation: a 90° arc around the pivot about ``middle`` (degrees) with an
    arrowhead, labelled ω₁ (ω_1)."""
    rr = max(6.0, 0.25 * r)
    start, end = (middle - 45.0, middle + 45.0) if omega > 0 else (middle + 45.0, middle - 45.0)
    rec.arc(_pt(O), rr, min(start, end), max(start, end), role="relative", layer="mechanism",
            step="the crank's rotation ω1")
    tail, tip = arc_head(O, rr, end, 1 if omega > 0 else -1)
    rec.vector(tail, tip, role="head", layer="mechanism", step="the crank's rotation ω1")
    mid = O + rr * cmath.exp(1j * math.radians(middle))
    return [LabelRequest(mid, "ω_1", toward=mid - O, size=3.5, optional=False, breaks=True)]   # thin lines broken under it


def labelled(plan: Plan) -> Record:
    """A velocity or acceleration plan's record with its labels placed (the pole at (0, 0))."""
    rec = Record(plan.record.title, list(plan.record.items), dict(plan.record.scales))
    return place_owned(rec, plan.labels)      # crowded points: each letter nearest its own point


def plan_records(plans: Plans, kind: str) -> dict[int, Record]:
    """The velocity (``kind="velocity"``, pole p_v at (0, 0)) or acceleration plans (pole π),
    labelled, keyed by position."""
    out = {}
    for p in plans.positions:
        plan = p.velocity if kind == "velocity" else p.acceleration
        if plan is not None:
            rec = labelled(plan)
            rec.title = f"{kind} plan, position {p.index if p.index is not None else f'φ = {p.phi:g}°'}"
            rec.scales = {"mu_v" if kind == "velocity" else "mu_a": plan.mu}
            out[p.key] = rec
    return out


def velocity_records(plans: Plans) -> dict[int, Record]:
    """The velocity plan of every position, keyed by position, the pole p_v at (0, 0)."""
    return plan_records(plans, "velocity")


def acceleration_records(plans: Plans) -> dict[int, Record]:
    """The acceleration plans, keyed by position, the pole π at (0, 0)."""
    return plan_records(plans, "acceleration")


# -- a yoke (a slotted crosshead on a rod, no revolute joint of its own) drawn as one rigid body ----

@dataclass(frozen=True)
class YokeSpans:
    """A yoke's drawn spans in its own frame (mm), the same at every position (one rigid body):
    the slot along its guide from the guide's point, the rod along its axis from its point D; and
    the frame's bushing on the rod's axis (its middle, unit direction; None: no bushing)."""
    slot: tuple[float, float]
    rod: tuple[float, float]
    bushing: tuple[complex, complex] | None = None


def _yoke_frame(sc: Scheme, lay: Layout, name: str):
    """A yoke's drawing frame at a position: (D, rod's unit, slot guide's point, slot's unit)."""
    mech = sc.mech
    link = mech.links[name]
    g = yoke_guide(mech, name)
    pose = lay.poses[name]
    return pose.at(link.local[next(iter(link.local))]), pose.direction(0.0), pose.at(g.through), pose.direction(g.angle)


def yoke_spans(sc: Scheme, layouts: list[Layout], name: str, O: complex | None = None,
               r: float = 0.0) -> YokeSpans:
    """The yoke's spans over the drawn positions (``linkshape.yoke_body``): the slot over the
    block's travel (and the rod's crossing), the rod from the slot to its farthest point and through
    its bushing, which stands on the rod's axis clear of the crank pin's circle (about ``O``, radius
    ``r`` mm) and of the slot's sweep (the textbook's Scotch yoke: its rod's guide beside the crank,
    not a wall through it)."""
    mech = sc.mech
    link = mech.links[name]
    g = yoke_guide(mech, name)
    sliders = [s for s, other in mech.links.items() if other.slides_on == g.name]
    frames = [_yoke_frame(sc, lay, name) for lay in layouts]
    blocks = [[lay.poses[s].at(z) for s in sliders for z in mech.links[s].local.values()] for lay in layouts]
    own = [[lay.poses[name].at(z) for z in link.local.values()] for lay in layouts]
    guide = mech.guides[link.slides_on]
    line = None
    if guide.body == FRAME:
        lay0 = layouts[0]
        line = (where_frame(sc, lay0, guide.through), lay0.poses[FRAME].direction(guide.angle))
    slot, rod, bushing = yoke_body(frames, blocks, own, line, O, r)
    return YokeSpans(slot, rod, bushing)


def yoke_parts(sc: Scheme, lay: Layout, name: str, spans: YokeSpans) -> tuple[complex, complex, complex, complex]:
    """The yoke at a position (mm): its slot's ends and its rod's ends (``linkshape.yoke_shape``)."""
    ref, ur, base, us = _yoke_frame(sc, lay, name)
    return yoke_shape(ref, ur, base, us, spans.slot, spans.rod)


def draw_yoke(rec: Record, sc: Scheme, lay: Layout, name: str, spans: YokeSpans, thick: bool,
              role: str = "link", step: str = "") -> None:
    """A yoke as one rigid body: its slot (drawn as a slot, its two sides, on a thick position; its
    line on a thin one) and its rod from the slot through D to its end."""
    a, b, p, q = yoke_parts(sc, lay, name, spans)
    width = None if thick else 0.3
    if thick:
        rec.add("polyline", [_pt(z) for z in slot_outline(a, b)], role=role, layer="mechanism", step=step)
        p_, q_ = rod_from_slot(a, b, p, q)       # the rod from the slot's side, not across its inside
    else:
        rec.segment(_pt(a), _pt(b), role=role, width=width, layer="mechanism", step=step)
        p_, q_ = p, q
    rec.segment(_pt(p_), _pt(q_), role=role, width=width, layer="mechanism", step=step)
    pose = lay.poses[name]
    for f, z in rod_stubs(p, _yoke_frame(sc, lay, name)[1], [pose.at(w) for w in sc.mech.links[name].local.values()]):
        rec.segment(_pt(f), _pt(z), role=role, width=width, layer="mechanism", step=step)


def draw_bushing(rec: Record, mid: complex, u: complex, step: str = "") -> None:
    """The frame's bushing a rod slides in: its two walls ``BUSH_GAP_MM`` either side of the rod's
    axis, ``2·BUSH_HALF_MM`` long, hatched on their outer sides (GOST 2.770's fixed guide)."""
    for s in (1.0, -1.0):
        n = 1j * u * s
        a, b = mid - BUSH_HALF_MM * u + BUSH_GAP_MM * n, mid + BUSH_HALF_MM * u + BUSH_GAP_MM * n
        rec.segment(_pt(a), _pt(b), role="frame", layer="frame", step=step)
        t = -BUSH_HALF_MM
        while t <= BUSH_HALF_MM - 2.0 + 1e-9:
            z = mid + t * u + BUSH_GAP_MM * n
            rec.segment(_pt(z + 0.35 * n), _pt(z + 2.5 * n + 2.0 * u), role="hatch", layer="frame", step=step)
            t += 4.0
