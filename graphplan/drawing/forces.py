"""Drawings of the force analysis as construction records (mm, y up): each group's scheme with its
forces and measured arms, its force polygon, the Zhukovsky lever and the results tables.

Labels are placed by a small search (``Labeler``): around the thing they name, in the preferred
direction first, the first spot that overlaps neither another label nor a drawn line.
"""
from __future__ import annotations

import cmath
from dataclasses import dataclass
import math
from dataclasses import dataclass

from graphplan.drawing.labels import place_along, place_labels
from graphplan.model.linkshape import extra_points, rigid_outline
from graphplan.drawing.tables import table
from graphplan.graphic.record import LabelRequest, Record, arc_head, line_pitch, text_width
from graphplan.graphic.forceplans import ForcePlans, GForce, GroupPlan
from graphplan.exact.kinematics import dot
from graphplan.model.mechanism import FRAME
from graphplan.util.markup import indexed
from graphplan.util.words import fixed, force_symbol, num, pair_kind, pct, unit, word

Box = tuple[float, float, float, float]

GROUP_NOTE = True     # a component below the ruler named under its group too (review 7 #10)
NOTE_ROWS = (0.1, 0.3, 0.5, 0.7, 0.9)    # … at a free spot: these fractions of its height, lowest first
NOTE_COLUMNS = (0.25, 0.5, 0.75)         # … and of its width
LETTER = 3.5    # mm: a force's, an arm's name — the sheet's lettering height (GOST 2.304 on A1, LAYOUT.md)


def _pt(z: complex) -> tuple[float, float]:
    return (float(z.real), float(z.imag))


def _unit(z: complex) -> complex:
    return z / abs(z) if abs(z) > 0 else 1 + 0j


def _arrow_length(force: float, biggest: float) -> float:
    """Arrows on a scheme or on the lever: 8–30 mm, growing with the force (not to scale)."""
    return 8.0 + 22.0 * math.sqrt(max(force, 0.0) / biggest) if biggest > 0 else 8.0


# -- labels ------------------------------------------------------------------------------------

class Labeler:
    """Letters a record by the one label placer (drawing.labels): the labels asked for (``place``),
    then set all at once (``done``), each clear of the lines and of the labels set before it,
    beside its point or on a short leader."""

    def __init__(self, rec: Record):
        self.rec = rec
        self.asked: list[LabelRequest] = []

    def place(self, anchor: complex, text: str, size: float = 2.5, prefer: complex = 1j,
              step: str = "", rivals: tuple = ()) -> None:
        self.asked.append(LabelRequest(anchor, text, prefer, size, step=step, rivals=rivals))

    def done(self) -> Record:
        place_labels(self.rec, self.asked, layer="labels")
        self.asked = []
        return self.rec


# -- a group's scheme --------------------------------------------------------------------------

def _mu(fp: ForcePlans, gp: GroupPlan | None) -> float:
    """The scale a group is drawn at (its own, else the plans')."""
    return gp.mu_l if gp is not None and gp.mu_l else fp.mu_l


def _mu_F(fp: ForcePlans, gp: GroupPlan) -> float:
    """The scale a group's force plan is drawn at (its own, else the plans')."""
    return gp.mu_F or fp.mu_F


def _wedge_outline(fp: ForcePlans, link: str, mu: float) -> list[complex]:
    """A slider that carries a guide — the wedge press's wedge B on the frame's guide, its inclined
    face the slot the ram's block C rides in — drawn as the kinematics sheet draws it
    (``plans._wedge_sides``): the slot along its guide through the blocks riding in it
    (``linkshape.slot_line``) and, off its joint, the triangle of the joint and the slot's ends; through
    it, the triangle resting on its guide (``linkshape.wedge_body``) — one rigid body (mm);
    none for any other link (review 52: the wedge drawn as a bar from B to C, its face missing)."""
    import numpy as np
    from graphplan.drawing.plans import WEDGE_OFF_MM
    from graphplan.model.linkshape import slot_line, wedge_body
    mech, kin = fp.ks.mech, fp.ks.kin
    lk = mech.links[link]
    riders = [r for r, other in mech.links.items()
              if other.slides_on is not None and mech.guides[other.slides_on].body == link]
    if lk.slides_on is None or len(lk.joints) != 1 or not riders:
        return []
    body = kin.bodies[link]
    g = mech.guides[mech.links[riders[0]].slides_on]
    base = complex(body.at(g.through)[0][0]) / mu
    u = complex(np.exp(1j * (body.theta[0] + g.angle)))
    x = complex(body.at(lk.local[lk.joints[0]])[0][0]) / mu
    blocks = [complex(kin.bodies[r].at(z)[0][0]) / mu for r in riders for z in mech.links[r].local.values()]
    # the face over the blocks' whole travel along it, as the position plan draws it (review 62: the
    # textbook's wedge covers the block's travel; over the force position's block alone its back stood
    # on the ram's axis, the ram's arrows along it)
    blocks += [base + t / mu * u for t in _wedge_travel(fp, link, riders)]
    a, b = (complex(z) for z in slot_line(base, u, [x], blocks))
    if abs(((x - a) * u.conjugate()).imag) <= WEDGE_OFF_MM:     # the face through B: the textbook's triangle
        return wedge_body(a, b, x, complex(np.exp(1j * body.theta[0]))) or [a, b]   # on its guide (review 62)
    return [a, x, b, a]


_TRAVEL: dict[tuple[int, str], tuple[object, list[float]]] = {}


def _wedge_travel(fp: ForcePlans, link: str, riders: list[str]) -> list[float]:
    """The wedge's blocks' farthest places along its face over the turn (m from the slot guide's
    point; ``YOKE_TURN`` steps), once per analysis: the outline is asked for some forty times a sheet."""
    import weakref

    import numpy as np
    hit = _TRAVEL.get((id(fp.ks), link))
    if hit is not None and hit[0]() is fp.ks:
        return hit[1]
    mech = fp.ks.mech
    g = mech.guides[mech.links[riders[0]].slides_on]
    turn = fp.ks.st.solve(np.linspace(0.0, 360.0, YOKE_TURN, endpoint=False))
    tb = turn.bodies[link]
    along = [((complex(turn.bodies[r].at(z)[0][i]) - complex(tb.at(g.through)[0][i]))
              * complex(np.exp(-1j * (tb.theta[i] + g.angle)))).real
             for i in range(YOKE_TURN) for r in riders for z in mech.links[r].local.values()]
    out = [min(along), max(along)]
    _TRAVEL[(id(fp.ks), link)] = (weakref.ref(fp.ks), out)
    return out


def _link_outline(fp: ForcePlans, link: str, mu: float | None = None, framed: bool = True) -> list[complex]:
    """The drawn line of a link (mm): its joints, stretched along its axis to any block riding on it
    (a yoke: its slot and rod, ``framed``: the rod reaching its bushing)."""
    mech, kin = fp.ks.mech, fp.ks.kin
    mu = mu or fp.mu_l
    from graphplan.model.linkshape import yoke_guide
    if yoke_guide(mech, link) is not None:
        return yoke_lines(fp, link, mu, framed)
    wedge = _wedge_outline(fp, link, mu)
    if wedge:
        return wedge
    lk = mech.links[link]
    body = kin.bodies[link]
    pos = {p: complex(body.at(lk.local[p])[0][0]) / mu for p in lk.joints}
    riders = [name for name, other in mech.links.items() if other.slides_on == link]
    for r in riders:
        pos[f"~{r}"] = complex(kin.bodies[r].at(mech.links[r].local[next(iter(mech.links[r].local))])[0][0]) / mu
    pts = list(pos.values())
    extras = [complex(body.at(lk.local[p])[0][0]) / mu for p in extra_points(lk)]
    if extras and len(lk.joints) >= 2:       # one rigid link through all its points (O2–B–D)
        return rigid_outline([pos[p] for p in lk.joints],
                             extras + [z for k, z in pos.items() if k.startswith("~")])
    if len(lk.joints) >= 3:
        return [pos[p] for p in lk.joints] + [pos[lk.joints[0]]]
    if len(pts) == 1 and any(abs(z - pts[0]) > 1e-6 for z in extras):
        # a slider's own bar past its block: the ram 5's C–D (review 62 F2: D a lone dot over C)
        far = max(extras, key=lambda z: abs(z - pts[0]))
        return rigid_outline(pts + [far], [z for z in extras if z is not far])
    if len(pts) < 2:
        return pts
    if extras:          # a slotted lever's own points past its block (review 12: O3E's end E drawn apart)
        pts += extras
    axis = _unit(pts[1] - pts[0])
    proj = sorted(pts, key=lambda z: dot(z - pts[0], axis))
    return [proj[0], proj[-1]]


def _point_name(fp: ForcePlans, link: str, z: complex, mu: float) -> str:
    """The name of the link's point drawn at ``z`` (mm): the point itself (S3, D; the centre of
    mass is always one of them — the scene's ``com``, else the link's first point), else "": a
    force's own point of application, not lettered (WEDGE52: the wedge's R03 and R43 act where the
    slot's line meets the guide's, lettered "S3" though the wedge's centre of mass is B)."""
    lk = fp.ks.mech.links[link]
    body = fp.ks.kin.bodies[link]
    near = [(abs(complex(body.at(lk.local[p])[0][0]) / mu - z), p) for p in lk.local]
    hit = min(near, default=(1e9, ""))
    if hit[0] >= 0.5:
        # … or the point of another link's pair there: the block C riding in the link's slot, where
        # the block's reaction R43 acts on the slotted rocker (LINK59's II(2-3): an unlettered dot
        # on O2E between B and E)
        mech, kin = fp.ks.mech, fp.ks.kin
        others = [(abs(complex(kin.bodies[name].at(other.local[p])[0][0]) / mu - z), p)
                  for name, other in mech.links.items() if name != link and other.slides_on == link
                  for p in other.joints]
        hit = min(others + [hit])
    return hit[1] if hit[0] < 0.5 else ""


def _pairs(points: list[complex]) -> list[tuple[complex, complex]]:
    return list(zip(points, points[1:]))


ALONG_DEG = 12.0   # a force within this angle of a link through its point lies on the link's line
PAST_MM = 5.0      # such a force's arrow reaches this far past the link's end, to read


SIDE_MM = 1.8      # a force set aside from a link's line or from another force's line, parallel (the lever)
LANE_MM = 2.5      # … on a group's drawing: clear of the link's line and of the next lane's 2 mm arrowheads
NEAR_DEG = 8.0     # two arrows leaving one point this near in direction read as one shaft
OVER_LANE_MM = 4.5  # … beside another arrow of its point on the same line: the two heads clear apart
COMPONENT_MM = 10.0   # a reaction's component across its link drawn at most this long (its value in the table)


def arm_symbol(name: str) -> str:
    """The arm of a force as the lab letters it (markup): h with the force's name below —
    G2 → h_{G2}, Φ2 → h_{Φ2}, R43 → h_{R43}, a couple's pair force on the lever M^Φ_2' → h_{MΦ2'};
    the terminal writes the same pair as G₂·h. A load named by its point keeps its own index one
    level lower, P_B → h_{P_B} (h with P_B below, B an index's index: markup.runs), not h_{PB} with
    B flat beside P as if it were a second letter (stop 47: the lever's "h_{Φ3,PB}")."""
    flat = "".join(c for c in name if c not in "_^{}\\")
    if name.startswith("P_") and name != "P_b" and flat[1:].isalnum():
        return "h_{P_" + flat[1:] + "}"
    return "h_{" + flat + "}"


def _along_links(z: complex, u: complex, links: list[tuple[complex, complex]]) -> tuple[float, float]:
    """How far (mm) a drawn link whose line the force's line follows (within ``ALONG_DEG``) runs on
    from ``z`` ahead along ``u`` and behind it."""
    ahead = behind = 0.0
    for a, b in links:
        d = b - a
        if abs(d) < 1e-9 or not _on_segment(z, a, b):
            continue
        if abs((u.conjugate() * d / abs(d)).imag) > math.sin(math.radians(ALONG_DEG)):
            continue
        ends = [dot(e - z, u) for e in (a, b)]
        ahead, behind = max(ahead, max(ends)), max(behind, -min(ends))
    return ahead, behind


SLIDE_MM = 12.0    # how far an arrow hidden by its link's line at its point may slide along its own line:
                   # farther, its stroke from the point hides in the link and the arrow reads as applied
                   # elsewhere (the slotter's G4, 3° off its link, slid 25 mm from S4 toward C)
CLEAR_MM = 1.2     # … and keep this far (centre to centre) from every drawn link along its whole length:
                   # two 0.7 mm lines with half a millimetre of paper between them
HEAD_HALF_MM = 1.0  # a thick arrow's head: 4 mm long, 2 mm wide (graphic.record.vector_arrow)
HEAD_LONG_MM = 4.0
SHAFT_HALF_MM = 0.35


def _clearance(a: complex, b: complex, segments: list[tuple[complex, complex]], n: int = 40) -> float:
    """How far the arrow a→b's ink stays from the drawn lines ``segments`` (centre lines, mm), less
    the clearance asked (``CLEAR_MM``): sampled at ``n + 1`` points along its whole length, its head
    (wider than its shaft toward its base) asking as much more as it is wider — ≥ 0 where the arrow
    reads apart from every line, < 0 where it runs on or by one (the slotter's G4 slid down its link
    3° off its line ran 0.6–1 mm from the link's stroke: a thickened link, not a force)."""
    import numpy as np
    d = b - a
    if abs(d) < 1e-9 or not segments:
        return math.inf
    t = np.linspace(0.0, 1.0, n + 1)
    z = a + d * t                                              # samples along the arrow
    back = (1.0 - t) * abs(d)                                  # how far each is back from the tip
    wider = np.clip(np.minimum(back, HEAD_LONG_MM) / HEAD_LONG_MM * HEAD_HALF_MM - SHAFT_HALF_MM, 0.0, None)
    wider[back > HEAD_LONG_MM] = 0.0
    s = np.array([p for p, _ in segments], dtype=complex)[:, None]
    e = np.array([q for _, q in segments], dtype=complex)[:, None]
    w = e - s
    ww = np.where(np.abs(w) < 1e-12, 1.0, np.abs(w) ** 2)
    k = np.clip(((z[None, :] - s) * np.conj(w)).real / ww, 0.0, 1.0)
    dist = np.abs(z[None, :] - (s + k * w)).min(axis=0)
    return float((dist - CLEAR_MM - wider).min())


def _on_line(z: complex, u: complex, length: float, links: list[tuple[complex, complex]],
             drawn: list[tuple[complex, complex, complex]], outlines: list[tuple[complex, complex]] = (),
             points: list[complex] = ()) -> tuple[complex, complex] | None:
    """The nearest place ON the force's line of action through ``z`` (leaving the point along ``u``
    or arriving at it, slid up to ``SLIDE_MM`` along the line by 1 mm steps) where its arrow crosses
    no link, no block's outline and no arrow drawn, keeps ``CLEAR_MM`` from every one of those lines
    over its whole length (``_clearance``: the slotter's G4 slid down its link 3° off its line ran
    0.6–1 mm from it, a thickened link), runs by no arrow (``LANE_MM``), and neither it nor its stroke
    from ``z`` passes within ``LANE_MM`` of another point (``points``, loaded or jointed: G5 slid up
    from S5 ran over the block's C; G4 down from C ran 1.6 mm by S5, its name nearer G5), its head
    ends ``HEAD_CLEAR_MM`` from them and it lies nearer its own point than any other (COULISSE8's G1
    slid up from S1 began by the crank's A) — or None where the link hides every such place."""
    arrows = [(t, h) for _, t, h in drawn]
    for k in range(int(SLIDE_MM) + 1):
        s = float(k)
        for a, b in ((z + s * u, z + (s + length) * u), (z - (s + length) * u, z - s * u)):
            if _crosses(a, b, links) or _crosses(a, b, arrows) or _crosses(a, b, list(outlines)) \
                    or _clearance(a, b, list(links) + list(outlines)) < 0.0:
                continue
            far = a if abs(a - z) > abs(b - z) else b
            if any(abs(w - z) > 0.5 and _to_segment(w, z, far) < LANE_MM for w in points):
                continue
            if abs(b - z) > abs(a - z) and any(abs(w - z) > 0.5 and abs(w - b) < HEAD_CLEAR_MM for w in points):
                continue        # its head by another point reads as applied there (COULISSE8's G1 down to O1)
            if any(abs(w - z) > 0.5 and _to_segment(w, a, b) < s for w in points):
                continue        # nearer another point than its own: read as that one's (G1 by the crank's A)
            if any(_one_arrow(a, b, t, h, LANE_MM) or _one_shaft(a, b, t, h) for t, h in arrows):
                continue
            return a, b
    return None


OWN_LEAST_MM = 6.0   # an arrow drawn over its own link's line at least this long (its 4 mm head and a shaft)
OWN_TIP_MM = 3.0     # … its whole length this far at least from any other point (a joint's ring, S, E)
OWN_GAP_MM = 3.0     # a force drawn on the line of another arrow of its point: this far past that arrow's end
OWN_BLOCK_MM = 5.0   # the edges of a slider's block this near its point are its own block's (crossed by its arrows)


def _on_own_line(z: complex, u: complex, length: float, links: list[tuple[complex, complex]],
                 drawn: list[tuple[complex, complex, complex]], outlines: list[tuple[complex, complex]] = (),
                 points: list[complex] = ()) -> tuple[complex, complex] | None:
    """A force lying on a link's line through its point (Φ1 along the crank at S1, the jaw's G2 at S2 6°
    off it) or on the line of an arrow already drawn at its point (Φ5 and P_D at the slider's D) drawn
    ON its line of action through the point, as the textbook draws it (review 60 #3: set a lane aside,
    parallel, it contradicted the arm h drawn to the true line): first from the point, over its link's
    line if need be — leaving it along ``u``, else arriving at it — at its length, else shorter down to
    ``OWN_LEAST_MM``, its tip ``OWN_TIP_MM`` clear of every other point (a joint's ring at the link's
    end); then, where another arrow of the point takes the line, one after the other along the line,
    ``OWN_GAP_MM`` past that arrow's far end. Every place crosses no other link, no arrow and no block
    but the point's own, keeps ``CLEAR_MM`` from the links not through the point, and reads as no
    other arrow (``_one_arrow``, ``_one_shaft``) — or None where none does."""
    arrows = [(t, h) for _, t, h in drawn]
    mine = [(p, q) for p, q in links if _on_segment(z, p, q)]          # the point's own links' lines
    off = [(p, q) for p, q in links if not _on_segment(z, p, q)]
    # the bars that END at the point (the ram's C–D at C): its line runs on free past the point, so an
    # arrow laid over such a bar, only its head showing (review 62: Φ4, G5, Φ5 up the ram from C), gives
    # way to the free stretch, one after the other (``past``), else to a place slid along the line
    ending = [(p, q) for p, q in mine if abs(q - p) > 1.0 and min(abs(z - p), abs(z - q)) < 0.5]
    walls = [(p, q) for p, q in outlines if _to_segment(z, p, q) > OWN_BLOCK_MM]
    block = len(walls) < len(outlines) and any(_to_segment(z, p, q) <= OWN_BLOCK_MM for p, q in outlines)
    others = [w for w in points if abs(w - z) > 0.5]
    sizes = [length] + [k * length for k in (0.8, 0.65, 0.5) if k * length >= OWN_LEAST_MM]
    if length > OWN_LEAST_MM:
        sizes.append(OWN_LEAST_MM)
    # how far out along either half of the line the arrows of the point already lying on it reach
    reach = {1.0: 0.0, -1.0: 0.0}
    for w, t, h in drawn:
        if abs(w - z) < 0.5 and abs(((t - z).conjugate() * u).imag) < 0.5 and abs(((h - z).conjugate() * u).imag) < 0.5:
            for e in (t, h):
                side = 1.0 if dot(e - z, u) >= 0 else -1.0
                reach[side] = max(reach[side], abs(dot(e - z, u)))

    def fits(a: complex, b: complex, head: float = HEAD_CLEAR_MM) -> bool:
        if _crosses(a, b, off) or _crosses(a, b, arrows) or _crosses(a, b, walls):
            return False
        if off and _clearance(a, b, off) < 0.0:
            return False
        for t, h in arrows:
            if _one_shaft(a, b, t, h) or _overlap(a, b, t, h, LANE_MM):
                return False
            # end to end on one line reads as one double-headed arrow — but at the point itself, its
            # dot between them, two forces leaving it (or arriving) on either side (G3 down from S3,
            # Φ3 up) read as the textbook's two
            ends = [(p, q) for p in (a, b) for q in (t, h) if abs(p - q) <= LANE_MM]
            if _one_arrow(a, b, t, h, LANE_MM) and any(abs(p - z) > 0.5 or abs(q - z) > 0.5 for p, q in ends):
                return False
        # its head ``HEAD_CLEAR_MM`` from any other point (FRC56_PUSHER's Φ3 up the rocker from S3 ended
        # 3 mm short of C, where R43 leaves: its name went by R43), its whole length ``OWN_TIP_MM``
        tip = b if abs(b - z) > abs(a - z) else None
        return all(_to_segment(w, a, b) >= OWN_TIP_MM for w in others) and \
            (tip is None or all(abs(w - tip) >= head for w in others))

    def at_point(over: bool, head: float = HEAD_CLEAR_MM):
        # from the point: leaving it (tail at the point), else arriving (head at the point) — clear of
        # its own link's line first, then over it; over it, leaving at any length first (its head out
        # along the bar, clear of the joint, SIXBAR6's Φ1 at S1: arriving from O1, its name went 15 mm
        # out) — but at a slider's block each length either way (FORCE_COUPLER51's P_F left F down the
        # rod 8° off it, its name nearer Φ4; arriving, its head lies in the block: left for the next stop)
        tries = [(z, z + ln * u) for ln in sizes] + [(z - ln * u, z) for ln in sizes] if over and not block else \
            [c for ln in sizes for c in ((z, z + ln * u), (z - ln * u, z))]
        for a, b in tries:
            side = 1.0 if dot((a + b) / 2 - z, u) > 0 else -1.0
            if reach[side] > 0.5:
                continue                 # another arrow of the point lies on that half of the line
            if over and _run_along(a, b, ending) > 0.5 * abs(b - a):
                continue                 # mostly over a bar ending at the point: its free side instead
            if (_run_along(a, b, mine) > 1.0) == over and fits(a, b, head):
                return a, b
        return None

    def past():
        for ln in sizes:
            # past the arrow of the point on its line: one after the other (P_D leaving D, Φ5 beyond it)
            for side in (1.0, -1.0):
                if reach[side] <= 0.5:
                    continue
                s = reach[side] + OWN_GAP_MM
                a, b = (z + s * u, z + (s + ln) * u) if side > 0 else (z - (s + ln) * u, z - s * u)
                if fits(a, b) and not any(_one_arrow(a, b, t, h, OWN_GAP_MM - 0.5) for t, h in arrows):
                    return a, b
        return None
    # clear of its link at its point; past another arrow of the point on its line (rather than down
    # the slider's rod 10° off the guide: a_incline's Φ5); over its own link's line (Φ1 at S1)
    # — its head by another point only where nothing else is free, ``OWN_TIP_MM`` from it
    return at_point(False) or at_point(True) or past() or at_point(True, OWN_TIP_MM)


def _run_along(a: complex, b: complex, links: list[tuple[complex, complex]], tol: float = 0.6) -> float:
    """How much (mm) of the arrow a→b lies on a drawn line — within ``tol`` mm of a segment of
    ``links`` that runs within ``ALONG_DEG`` of it (Φ5 at the slider's joint along the rod CD, P_D
    on the lever along the image d–s4): sampled at 40 points."""
    d = b - a
    if abs(d) < 1e-9:
        return 0.0
    u = d / abs(d)
    near = [(s, e) for s, e in links if abs(e - s) > 1e-9
            and abs((u.conjugate() * (e - s) / abs(e - s)).imag) <= math.sin(math.radians(ALONG_DEG))]
    if not near:
        return 0.0
    n = 40
    hits = sum(1 for k in range(n + 1) if any(_on_segment(a + d * k / n, s, e, tol) for s, e in near))
    return abs(d) * max(0, hits - 1) / n


def _overlap(a: complex, b: complex, c: complex, d: complex, tol: float = 0.5) -> bool:
    """Two arrows a→b and c→d on one line (within ``tol`` mm) sharing more than ``tol`` of it."""
    u = _unit(b - a)
    if abs(((c - a).conjugate() * u).imag) > tol or abs(((d - a).conjugate() * u).imag) > tol:
        return False
    lo, hi = sorted((dot(c - a, u), dot(d - a, u)))
    return min(hi, abs(b - a)) - max(lo, 0.0) > tol


def _one_arrow(a: complex, b: complex, c: complex, d: complex, tol: float = 0.5) -> bool:
    """Whether two arrows a→b and c→d read as one: on one line (within ``tol`` mm), sharing more
    than ``tol`` of it (``_overlap``) or meeting end to end (review 11 #12: Φ3 and P_B left the same
    point above B in opposite senses, one double-headed arrow; the seeds draw such forces apart)."""
    if _overlap(a, b, c, d, tol):
        return True
    u = _unit(b - a)
    if abs(((c - a).conjugate() * u).imag) > tol or abs(((d - a).conjugate() * u).imag) > tol:
        return False
    return any(abs(p - q) <= tol for p in (a, b) for q in (c, d))


def _one_shaft(a: complex, b: complex, c: complex, d: complex, tol: float = 0.5) -> bool:
    """Whether two arrows a→b and c→d leave one point (or arrive at one) within ``NEAR_DEG`` of each
    other's direction: their shafts merge into one near it."""
    if abs(b - a) < 1e-9 or abs(d - c) < 1e-9:
        return False
    same_end = abs(a - c) <= tol or abs(b - d) <= tol
    return same_end and dot(_unit(b - a), _unit(d - c)) > math.cos(math.radians(NEAR_DEG))


def _crosses(a: complex, b: complex, links: list[tuple[complex, complex]]) -> bool:
    """Whether the arrow a→b crosses a drawn link's line (their segments meet, not just touch at an
    end within 0.3 mm)."""
    def cross(p: complex, q: complex) -> float:
        return p.real * q.imag - p.imag * q.real
    d = b - a
    for s, e in links:
        w = e - s
        den = cross(d, w)
        if abs(den) < 1e-12:
            continue
        t, v = cross(s - a, w) / den, cross(s - a, d) / den
        if 0.3 / abs(d) < t < 1 - 0.3 / abs(d) and 0.0 <= v <= 1.0:
            return True
    return False


def _apart_mm(p: tuple[complex, complex], q: tuple[complex, complex]) -> float:
    """The least distance between two segments that do not cross, mm (an end's to the other)."""
    return min(_to_segment(p[0], *q), _to_segment(p[1], *q), _to_segment(q[0], *p), _to_segment(q[1], *p))


def _on_segment(z: complex, a: complex, b: complex, tol: float = 0.5) -> bool:
    d = b - a
    if abs(d) < 1e-9:
        return abs(z - a) <= tol
    t = min(max(dot(z - a, d) / abs(d) ** 2, 0.0), 1.0)
    return abs(z - (a + t * d)) <= tol


HEADS_MM = 3.0     # two arrows' heads nearer than this read as one point (the lever's forces)


def _ends_on(z: complex, tail: complex, tip: complex, drawn: list[tuple[complex, complex, complex]],
             images: list[complex]) -> bool:
    """Whether the lever's arrow tail → tip of the image ``z`` ends on another's: its head within
    ``HEADS_MM`` of another drawn arrow's head (``drawn``: image, tail, head), or — the arrow of
    another image — 1 mm of its shaft or its head within 1 mm of this one's shaft away from its own
    image, or its head within ``HEADS_MM`` of another image (it reads as applied there)."""
    for w, a, b in drawn:
        if abs(tip - b) < HEADS_MM:
            return True
        if abs(w - z) < 0.5:          # of the same image: its lines are the lanes' (set aside below)
            continue
        if _to_segment(tip, a, b) < 1.0 or (abs(b - z) > 1.0 and _to_segment(b, tail, tip) < 1.0):
            return True
    return any(abs(w - z) > 0.5 and abs(tip - w) < HEADS_MM for w in images)


def _to_segment(z: complex, a: complex, b: complex) -> float:
    """The distance from ``z`` to the segment ab, mm."""
    d = b - a
    if abs(d) < 1e-9:
        return abs(z - a)
    t = min(max(dot(z - a, d) / abs(d) ** 2, 0.0), 1.0)
    return abs(z - (a + t * d))


COUPLE_CROWD_MM = 12.0   # a couple's arc drawn elsewhere on its link where its point has less room than this
COUPLE_GAIN_MM = 0.5     # … and the spot found has more, by a ruler step at least
COUPLE_STEP_MM = 1.0     # … the spots tried along the link this far apart


def couple_spot(at: complex, own: list[tuple[complex, complex]], points: list[complex],
                arrows: list[tuple[complex, complex, complex]], lines: list[tuple[complex, complex]]) -> complex:
    """Where a couple's arc goes on its link: at its point ``at`` (S3), whose own arrows it dodges
    by its side — unless the other points, the arrows of other points (``arrows``: point, tail,
    head) and the ``lines`` (other links, supports) leave it less than ``COUPLE_CROWD_MM``; then at the spot
    of the link's lines ``own`` with the most room, where that has ``COUPLE_GAIN_MM`` more (a couple
    is a free vector: any point of its link carries it). The rocking coulisse's scheme at 1:2.5 put
    M3's and M^Φ3's arcs round S3, 8 mm from O1 and 10 mm from S1, under M_зр's and ω1's arcs: a
    dozen names in a few mm; a Whitworth coulisse's M^Φ3 round S3 5.9 mm from S1 was named on a
    39 mm leader (review 49 #1)."""
    if not own:
        return at

    def room(z: complex, home: bool = False) -> float:
        pts = [abs(z - p) for p in points if not (home and abs(p - at) < 0.5)]
        ars = [_to_segment(z, a, b) for w, a, b in arrows if not (home and abs(w - at) < 0.5)]
        return min(pts + ars + [_to_segment(z, a, b) for a, b in lines] + [math.inf])

    here = room(at, home=True)
    if here >= COUPLE_CROWD_MM:
        return at
    spots = [a + (b - a) * k / n for a, b in own
             for n in [max(1, int(abs(b - a) / COUPLE_STEP_MM))] for k in range(n + 1)]
    # the nearest spot to its point with the room, else the roomiest: the slotted lever's M3 and
    # M^Φ3 went to the roomiest, 0.06 m from the pivot O2 with S3 at 0.16 m, and read as the
    # pivot's (review56 #7)
    near = [z for z in spots if room(z) >= COUPLE_CROWD_MM]
    best = min(near, key=lambda z: abs(z - at)) if near else \
        max(spots, key=lambda z: (round(room(z), 6), -abs(z - at)))
    return best if room(best) >= here + COUPLE_GAIN_MM else at


HEAD_CLEAR_MM = 5.0   # two arrowheads of different points at least this far apart (tip to tip)


def _heads_meet(z: complex, head: complex, drawn: list[tuple[complex, complex, complex]]) -> bool:
    """Whether an arrow of the point ``z`` ending at ``head`` ends by the head of an arrow drawn at
    another point (``drawn``: point, tail, head) — the two tips within ``HEAD_CLEAR_MM`` read as one
    arrowhead and the name by it as either's (review51: the coupler's P_F, laid along the guide from
    F, ended on Φ4's head from S4, "Φ4" beside the shared tip)."""
    return any(abs(w - z) >= 0.5 and abs(h - head) < HEAD_CLEAR_MM for w, _, h in drawn)


def _head_clear(z: complex, u: complex, a: complex, b: complex, drawn: list[tuple[complex, complex, complex]],
                links: list[tuple[complex, complex]], busy: list[tuple[complex, complex]]) -> tuple[complex, complex]:
    """The arrow a→b of the point ``z`` (direction ``u``) whose head meets another point's
    (``_heads_meet``) laid again, as the seeds draw two forces that would meet: first the other way
    along its line — arriving at its point where it left it, or leaving it where it arrived — where
    that side is free (no link crossed, no force of its point lying that way, no arrow drawn over);
    else shorter (its length grows with the force, not to scale: 0.8, then 0.65 of it), its end at
    the point kept; else as it was."""
    d = b - a
    at_point = abs(dot(a - z, u)) < 0.5          # leaving its point (its tail at the point's level)
    flipped = (a - d, a) if at_point else (b, b + d)
    cos_near = math.cos(math.radians(NEAR_DEG))
    side = -u if at_point else u                 # the side of the point the flipped arrow lies on
    arrows = [(t, h) for _, t, h in drawn]
    cands = []
    if not _crosses(*flipped, links) and not _crosses(*flipped, arrows) \
            and not any(abs(w - z) < 0.5 and dot(v, side) > cos_near for w, v in busy) \
            and not any(_one_arrow(*flipped, t, h) for t, h in arrows):
        cands.append(flipped)
    for k in (0.8, 0.65):
        cands.append((a, a + k * d) if at_point else (b - k * d, b))
    return next((c for c in cands if not _heads_meet(z, c[1], drawn)), (a, b))


def _clear_of_links(z: complex, u: complex, length: float, links: list[tuple[complex, complex]],
                    busy: list[tuple[complex, complex]] = ()) -> tuple[complex, complex]:
    """Where a force's arrow is drawn (tail, head) on its line of action through ``z``: from ``z``
    along ``u``, ``length`` long; where the force lies along a drawn link through its point, so
    that it does not hide in the link's line: at the link's end (R03 up the rocker from O2) it is
    drawn pushing, its head at the point and its tail outside the link — unless another force of
    ``busy`` (point, direction) leaves the point that way (the slotter's G5 at D under P_D and Φ5);
    inside the link (Φ1 at S1) it reaches ``PAST_MM`` past the link's end."""
    ahead = behind = 0.0
    for a, b in links:
        d = b - a
        if abs(d) < 1e-9 or not _on_segment(z, a, b):
            continue
        if abs((u.conjugate() * d / abs(d)).imag) > math.sin(math.radians(ALONG_DEG)):
            continue
        ends = [dot(e - z, u) for e in (a, b)]
        ahead, behind = max(ahead, max(ends)), max(behind, -min(ends))
    if ahead <= 0.5:
        return z, z + length * u
    cos_along = math.cos(math.radians(ALONG_DEG))
    taken = any(abs(w - z) < 0.5 and dot(v, -u) > cos_along for w, v in busy)
    if behind <= 0.5 and not taken:
        return z - length * u, z
    if behind <= 0.5:
        return z, z + length * u
    return z, z + max(length, ahead + PAST_MM) * u


def _name_side(z: complex, arrows: list[tuple[complex, complex]], links: list[tuple[complex, complex]]
               ) -> complex:
    """The side a point's letter is asked on: lower left (the seeds'), unless two of the point's
    force arrows bound that sector — their letters go beside their shafts there (LINK51's stone A:
    G2 down and Φ2 up-left, "A" between them left "G2" a 14 mm leader) — then the middle of the
    widest sector between the point's arrows and links bounded by at most one arrow."""
    rays = [(cmath.phase((h if abs(h - z) > abs(t - z) else t) - z), True) for t, h in arrows
            if max(abs(h - z), abs(t - z)) > 0.5]
    rays += [(cmath.phase(e - z), False) for a, b in links for e in (a, b)
             if abs(e - z) > 0.5 and _on_segment(z, a, b)]
    if len(rays) < 2:
        return -1 - 1j
    rays.sort()
    sectors = [(rays[k][0], (rays[(k + 1) % len(rays)][0] - rays[k][0]) % (2 * math.pi),
                int(rays[k][1]) + int(rays[(k + 1) % len(rays)][1])) for k in range(len(rays))]
    home = cmath.phase(-1 - 1j)
    own = next((s_ for s_ in sectors if (home - s_[0]) % (2 * math.pi) < s_[1]), None)
    if own is None or own[2] < 2:
        return -1 - 1j
    free = [s_ for s_ in sectors if s_[2] < 2 and s_[1] > math.radians(60.0)]
    if not free:
        return -1 - 1j
    start, width, _ = max(free, key=lambda s_: s_[1])
    return cmath.exp(1j * (start + width / 2))


BLOCK_HALF = 2.5   # a slider's block: 8 × 5 mm
SHOWN_MM = 10.0    # an arrow from a slider's block's centre: at least this much of it out of the block


def _block(rec: Record, z: complex, g: complex, step: str) -> None:
    """A slider drawn as a 8 × 5 mm rectangle along its guide."""
    u, n = _unit(g) * 4.0, _unit(g) * BLOCK_HALF * 1j
    rec.add("polygon", [_pt(z - u - n), _pt(z + u - n), _pt(z + u + n), _pt(z - u + n)],
            role="link", layer="mechanism", step=step)


GUIDE_MM = 25.0    # a slider's fixed guide drawn this far either side of the block
HATCH_BAND_MM = BLOCK_HALF + 1.0 + LANE_MM + 0.5   # the guide's hatching on the side with fewer lines this near


def _guide(rec: Record, z: complex, g: complex, lines: list[tuple[complex, complex]], step: str,
           bodies: list[list[complex]] = ()) -> None:
    """A slider's fixed guide as the kinematics sheet draws it (drawing.plans.draw_frame): a line of
    the frame along the guide with short hatch strokes every 4 mm on one side, left clear under
    the block — on the side where fewer of the drawn ``lines`` (links, arrows) pass near it; a
    stroke that would still cross one is left out, and one inside a closed body drawn over the
    guide (``bodies``: a wedge's triangle, review 62 — the ram's guide running down into it)."""
    from graphplan.model.linkshape import _inside
    u = _unit(g)

    def ink(n: complex) -> int:          # samples of the lines inside the hatching's band on side n
        return sum(1 for a, b in lines for k in range(41)           # (and the arrows' lanes by the block)
                   if 0.1 <= dot(a + (b - a) * k / 40 - z, n) <= HATCH_BAND_MM
                   and 6.0 <= abs(dot(a + (b - a) * k / 40 - z, u)) <= GUIDE_MM)
    normal = -1j * u
    if ink(normal) > ink(-normal):
        normal = -normal
    rec.segment(_pt(z - GUIDE_MM * u), _pt(z + GUIDE_MM * u), role="frame", layer="frame", step=step)
    t = -GUIDE_MM
    while t <= GUIDE_MM + 1e-9:
        base = z + t * u
        p, q = base + 0.35 * normal, base + 2.5 * normal - 2.0 * u
        # the block (8 mm long) and a millimetre either side clear; a stroke that would cross a
        # line (the rod coming in at a small angle) or an arrow left out, as a draftsman breaks it
        if abs(t) > 6.0 and not any(_on_segment(p + (q - p) * k / 4, a, b, 0.4) for k in range(1, 5)
                                    for a, b in lines) and not any(_inside((p + q) / 2, w) for w in bodies):
            rec.segment(_pt(p), _pt(q), role="hatch", layer="frame", step=step)
        t += 4.0


SUPPORT_SPARE_DEG = 10.0  # a support's side this much more than the kinematics sheet's 5° off a link at its pivot
SUPPORT_CLEAR_MM = 0.8   # a support's strokes this far at least from any link (but its own at the pivot) or arrow


def support_strokes(z: complex, direction: float) -> list[tuple[complex, complex]]:
    """The strokes (mm) of a frame pivot's support as ``drawing.plans.support`` draws it at ``z``
    along ``direction`` (degrees): the triangle's two sides, the bar, the five hatch strokes."""
    r = cmath.exp(1j * math.radians(direction + 90.0))
    a, b = complex(-3.5, -5.0), complex(3.5, -5.0)
    out = [(z, z + a * r), (z, z + b * r), (z + (a - 1.5) * r, z + (b + 1.5) * r)]
    for k in range(5):
        s_ = a + complex(-1.5 + 2.5 * k, 0)
        out.append((z + s_ * r, z + (s_ + complex(-1.8, -1.8)) * r))
    return out


def _gap_deg(a: float, b: float) -> float:
    return abs((a - b + 180.0) % 360.0 - 180.0)


def _support_direction(z: complex, links: list[tuple[complex, complex]],
                       arrows: list[tuple[complex, complex]], omega: bool = False) -> tuple[float, float | None]:
    """Where a frame pivot's support stands on the force scheme (degrees from the pivot), as the
    kinematics sheet puts it (``drawing.plans.support_direction``: below where that is free, else
    the next of ``SUPPORT_DIRS``), and further: none of its strokes within ``SUPPORT_CLEAR_MM`` of
    a link not leaving the pivot or of a force's arrow (G1 at S1 beside the crank's pivot). For the
    crank's pivot (``omega``) also the middle of ω1's 90° arc (degrees), clear of the links and the
    support. Returns (direction, ω1's middle or None)."""
    from graphplan.drawing.plans import (CLEAR_DEG, OMEGA_HALF_DEG, SUPPORT_DIRS, SUPPORT_HALF_DEG)
    leaving = [math.degrees(cmath.phase(e - z)) for a, b in links for e in (a, b)
               if abs(e - z) > 0.5 and _on_segment(z, a, b)]
    leaving += [math.degrees(cmath.phase(b - a)) for a, b in arrows if abs(a - z) < 0.5]
    leaving += [math.degrees(cmath.phase(a - b)) for a, b in arrows if abs(b - z) < 0.5]
    others = [(a, b) for a, b in links if not _on_segment(z, a, b)] + \
             [(a, b) for a, b in arrows if abs(a - z) >= 0.5 and abs(b - z) >= 0.5]

    def free(d: float, half: float) -> float:
        return min([_gap_deg(d, a) for a in leaving] + [180.0]) - half

    import numpy as np
    near_all = others + [(a, b) for a, b in links if (a, b) not in others]

    def segments(pairs: list[tuple[complex, complex]]) -> tuple:
        return np.array([a for a, _ in pairs], dtype=complex), np.array([b for _, b in pairs], dtype=complex)
    sides, every = segments(others), segments(near_all)

    def near(w: np.ndarray, seg: tuple, tol: float) -> bool:
        """Whether any point of ``w`` lies within ``tol`` of a segment (``_on_segment``, at once)."""
        a, b = seg
        if not len(w) or not len(a):
            return False
        d = b - a
        l2 = np.abs(d) ** 2
        t = np.clip(((w[:, None] - a[None, :]) * np.conj(d)[None, :]).real / np.where(l2 < 1e-18, 1.0, l2), 0.0, 1.0)
        t = np.where(l2 < 1e-18, 0.0, t)
        return bool(np.any(np.abs(w[:, None] - (a + t * d)[None, :]) <= tol))

    samples = np.arange(9) / 8.0
    memo: dict[float, bool] = {}

    def touches(d: float) -> bool:
        if d in memo:
            return memo[d]
        strokes = support_strokes(z, d)
        # the triangle's sides leave the pivot with the links (kept apart by angle, ``free``);
        # the bar and the hatching clear of every line, those leaving the pivot too
        out = False
        for group, seg in ((strokes[:2], sides), (strokes[2:], every)):
            w = np.concatenate([p + (q - p) * samples for p, q in group])
            w = w[np.abs(w - z) > 1.0]
            if near(w, seg, SUPPORT_CLEAR_MM):
                out = True
                break
        memo[d] = out
        return out

    def arc_touches(m: float) -> bool:
        """ω1's arc (r = ``OMEGA_R_MM``, 90° about ``m``, its head 2 mm wide) near a line not at the pivot."""
        for k in range(13):
            w = z + OMEGA_R_MM * cmath.exp(1j * math.radians(m - 50.0 + 100.0 * k / 12))
            if any(_on_segment(w, a, b, 1.0) for a, b in others):
                return True
        return False

    best = (-1e9, -90.0, None)
    # a direction whose strokes an arrow or another link runs through is taken only where none is
    # clear (review 12 #17: G1 ran down from S1 through O1's bar and hatching, the support below
    # having 110° of room)
    order = sorted(SUPPORT_DIRS, key=touches)
    for d in order:
        # the bar's ends stand 45° off the axis, 7 mm out: 15° more keeps them 1.8 mm off a link
        room = free(d, SUPPORT_HALF_DEG) - SUPPORT_SPARE_DEG - (20.0 if touches(d) else 0.0)
        arc = None
        if omega:
            arcs = [m for m in range(0, 360, 5) if free(m, OMEGA_HALF_DEG) >= CLEAR_DEG
                    and _gap_deg(m, d) >= SUPPORT_HALF_DEG + OMEGA_HALF_DEG + 5.0]
            arc = min(arcs, key=lambda m: (arc_touches(m), _gap_deg(m, 245.0))) if arcs else None
        if room >= CLEAR_DEG and (not omega or arc is not None):
            return d, arc
        score = room + (0.0 if not omega or arc is not None else -90.0)
        if score > best[0]:
            best = (score, d, arc)
    return best[1], best[2]


def _longest_first(forces: list, biggest: float) -> list:
    """The forces in their order, but of those on one line at one point the longest arrow first:
    it takes the lane by the point, the shorter one the next lane out, its letter clear of the
    longer's shaft (Φ3 laid first, P_B over it, left Φ3's letter on a leader)."""
    def line(f) -> tuple:
        d = _unit(f.force)
        if d.real < -1e-9 or (abs(d.real) <= 1e-9 and d.imag < 0):
            d = -d
        return (round(f.at.real, 6), round(f.at.imag, 6), round(d.real, 6), round(d.imag, 6))
    first = {}
    for k, f in enumerate(forces):
        first.setdefault(line(f), k)
    return sorted(forces, key=lambda f: (first[line(f)], -_arrow_length(abs(f.force), biggest)))


def group_record(fp: ForcePlans, gp: GroupPlan, lang: str = "uk", omega_at: complex | None = None) -> Record:
    """A group drawn at μl: its links, every force acting on it (loads, the reactions handed over by
    the later groups, the reactions found here) and the arms of the moment equations; with
    ``omega_at`` (mm) the crank's sense of rotation there, drawn before any label is set."""
    mech, kin = fp.ks.mech, fp.ks.kin
    mu = _mu(fp, gp)
    title = f"{gp.label} {pair_kind(gp.kind, lang)}" if gp.kind not in ("crank", "mechanism") else gp.label
    rec = Record(title, scales={"mu_l": mu})
    step = f"{gp.label}: ΣM = 0, ΣF = 0"
    names: list[tuple[complex, str]] = []
    supports: list[complex] = []
    guides: list[tuple[complex, complex]] = []      # a slider's fixed guide: (the block's centre, direction)
    blocks: list[tuple[complex, complex]] = []      # the sliders' blocks' edges
    block_at: list[tuple[complex, complex]] = []    # … their centres and guides' directions
    bushings: list[tuple[complex, complex]] = []    # a yoke's rod's bushing: (middle, unit)
    from graphplan.model.linkshape import yoke_guide
    for link in gp.links:
        lk = mech.links[link]
        yoke = yoke_guide(mech, link) is not None
        outline = _link_outline(fp, link, mu, gp.kind == "mechanism")
        if yoke:          # the slotted crosshead and its rod, one body (no block at D: its rod slides)
            draw_yoke(rec, fp, link, mu, step, framed=gp.kind == "mechanism")
        elif len(outline) >= 2:
            rec.add("polyline", [_pt(z) for z in outline], role="link", layer="mechanism", step=step)
        if yoke:
            # the scheme keeps the rod's bushing as the position plan draws it (clear of the crank)
            bush = yoke_at(fp, link, mu)[4]
            if bush is not None and gp.kind == "mechanism":
                bushings.append(bush)
        elif lk.slides_on is not None:
            guide = mech.guides[lk.slides_on]
            origin = next(iter(lk.local))
            z = complex(kin.bodies[link].at(lk.local[origin])[0][0]) / mu
            import numpy as np
            g = complex(np.exp(1j * (kin.bodies[guide.body].theta[0] + guide.angle)))
            _block(rec, z, g, step)
            u_, n_ = _unit(g) * 4.0, _unit(g) * BLOCK_HALF * 1j     # its edges, kept clear by the arms
            corners = [z - u_ - n_, z + u_ - n_, z + u_ + n_, z - u_ + n_]
            blocks += list(zip(corners, corners[1:] + corners[:1]))
            block_at.append((z, _unit(g)))
            if guide.body == FRAME:
                guides.append((z, g))
        for p in lk.joints:
            z = complex(kin.bodies[link].at(lk.local[p])[0][0]) / mu
            rec.point(_pt(z), role="joint", layer="mechanism", step=step)
            if p in mech.frame and gp.kind == "mechanism":
                # the scheme keeps its supports (drawn once the arrows are laid, away from the
                # links and arrows); a group is drawn freed from the frame, the pivot a circle, its
                # support replaced by the reaction (R03, R01)
                if all(abs(w - z) > 0.5 for w in supports):
                    supports.append(z)
            if all(n != p for _, n in names):
                names.append((z, p))
        for p in extra_points(lk):          # its other points (D where P_D acts), each by its name:
            z = complex(kin.bodies[link].at(lk.local[p])[0][0]) / mu     # a dot, not a hinge's ring
            hinge = any(p in other.joints for other in mech.links.values())   # another link's pair there
            rec.point(_pt(z), role="joint" if hinge else "dot", layer="mechanism", step=step)
            if all(n != p for _, n in names):
                names.append((z, p))
    forces = [f for f in gp.forces if f.force != 0]
    outer = [m for m in gp.reactions.values()
             if {fp.ks.reactions[m.key].frm, fp.ks.reactions[m.key].on} - set(gp.links)]
    biggest = max([abs(f.force) for f in forces] + [m.value for m in outer] + [1e-9])
    labels: list[tuple[complex, str, complex]] = []
    centres: list[tuple[complex, str]] = []
    drawn_links = [(a, b) for link in gp.links
                   for a, b in _pairs(_link_outline(fp, link, mu, gp.kind == "mechanism"))]
    drawn_links += [pair for link in gp.links if yoke_guide(mech, link) is not None     # a slot's sides
                    for pair in _pairs(_slot_sides(fp, link, mu))]
    from graphplan.model.linkshape import BUSH_GAP_MM, BUSH_HALF_MM
    drawn_links += [(m + BUSH_GAP_MM * s * 1j * u - BUSH_HALF_MM * u, m + BUSH_GAP_MM * s * 1j * u + BUSH_HALF_MM * u)
                    for m, u in bushings for s in (1.0, -1.0)]      # its walls
    span: dict[str, tuple[complex, complex]] = {}
    clear: dict[complex, complex] = {}     # a point with a moment's arc: its letter's side
    busy = [(f.at / mu, _unit(f.force)) for f in forces]       # every force leaving its point
    for m in outer:
        truth = fp.ks.reactions[m.key]
        at = truth.line_point()[0] if truth.on in gp.links else truth.at[0]
        if truth.on in gp.links and m.line is not None:
            at = m.line
        if m.acting:
            busy.append((complex(at) / mu, _unit(m.acting)))
    armed = {t.name for eq in gp.equations for t in eq.terms if abs(t.arm_mm) >= 1.0 and not t.couple}
    drawn: list[tuple[complex, complex, complex]] = []     # (point, tail, head) of each arrow drawn
    guide_lines = [(z - GUIDE_MM * _unit(g), z + GUIDE_MM * _unit(g)) for z, g in guides]   # drawn below
    lanes: dict[str, complex] = {}     # a force set aside from its line of action: by how much (mm)
    set_aside: list[tuple[complex, complex, complex, complex]] = []   # … (its point, that, its direction, middle)
    slid: set[str] = set()             # a force slid along its own line past its link (``_on_line``)

    def on_its_line(z: complex, u: complex, pair: tuple[complex, complex], name: str | None = None) -> tuple[complex, complex]:
        """A place found on the force's own line: its head cleared of a head already there
        (``_head_clear``), recorded as drawn (``slid`` where ``name`` is given: slid past its link)."""
        a, b = pair
        if name is not None:
            slid.add(name)
        if _heads_meet(z, b, drawn):
            a, b = _head_clear(z, u, a, b, drawn, drawn_links, busy)
        drawn.append((z, a, b))
        return a, b

    def lay(name: str, z: complex, u: complex, length: float) -> tuple[complex, complex]:
        """Where a force's arrow goes: clear of the links (``_clear_of_links``); one lying inside a
        link's line (Φ1 at S1 on the crank), along a link or a slider's guide (Φ5 along the rod CD,
        P_B along the guide) or on the line of an arrow already drawn at its point (Φ5 over P_D
        at D) is set ``SIDE_MM`` aside, parallel, on the side free of the others (a lane farther
        where that is taken) — unless an arm is drawn to its line (the arm ends on the line)."""
        a, b = _clear_of_links(z, u, length, drawn_links, busy)
        cos_near = math.cos(math.radians(NEAR_DEG))
        if abs(a - z) < 0.5 and any(abs(w - z) < 0.5 and abs(t - z) < 0.5 and abs(h - t) > 1e-9
                                    and dot(_unit(h - t), u) > cos_near for w, t, h in drawn):
            # an arrow of its point already leaves it a few degrees off this one's line (G4 down
            # from the stone's C, R34 4° from vertical): the two shafts merge into one — this one
            # drawn arriving at the point instead, where that side is free (the seeds' pushing arrow)
            a2, b2 = z - length * u, z
            free = not _crosses(a2, b2, drawn_links) and not _crosses(a2, b2, [(t, h) for _, t, h in drawn]) \
                and not any(abs(w - z) < 0.5 and dot(v, -u) > cos_near for w, v in busy) \
                and not any(_one_arrow(a2, b2, t, h) for _, t, h in drawn) \
                and _run_along(a2, b2, drawn_links + guide_lines) <= 1.0
            if free:
                a, b = a2, b2
        ahead, behind = _along_links(z, u, drawn_links)
        # inside a link's line, or along one from its end (Φ5 at D along the rod CD where P_D
        # leaves D the other way): either hides in the link
        inside = (ahead > 0.5 and behind > 0.5) or _run_along(a, b, drawn_links + guide_lines) > 1.0
        over = any(abs(w - z) < 0.5 and _one_arrow(a, b, t, h) for w, t, h in drawn)
        if inside and name in armed:
            # an arm is drawn to its line: first the arrow ON its line (the line the arm ends on,
            # drawn thin through the point), slid along it past where the link hides it — leaving
            # the point, or arriving at it (the seeds' pushing arrow), a thin stroke from the point
            # to it — wherever it keeps ``CLEAR_MM`` from every drawn line over its whole length
            # (review 58 #1: G4 at C and G5 at S5 on the slotted lever 7° off vertical were set
            # 2.5 and 4.8 mm aside, off the lines their arms end on). Not where no arm is drawn
            # (the scheme): there no line of action leads the eye to a slid arrow — LINK59's G3
            # hung 9 mm below S3 on a stroke the rocker hid, read as a load lower down — the lane
            # with its stroke across to the point reads better
            on_line = _on_line(z, u, length, drawn_links + guide_lines, drawn, blocks,
                               [w for w, _ in busy] + [w for w, _ in names])
            if on_line is not None:
                return on_its_line(z, u, on_line, name)
            a, b = z, z + length * u
        if inside or over:
            # on its line through its point, over its link's line if need be, or one after the
            # other along the line with the arrow of its point lying there (``_on_own_line``):
            # review 60 #3 — Φ1 set a lane aside from the crank, Φ5 beside P_D, the jaw's G2 and
            # P_E beside the jaw while their arms h ended on the true lines
            own = _on_own_line(z, u, length, drawn_links + guide_lines, drawn, blocks,
                               [w for w, _ in busy] + [w for w, _ in names])
            if own is not None:
                return on_its_line(z, u, own)
            if inside and name not in armed:
                # slid along its line past the link, a thin stroke from the point to it
                on_line = _on_line(z, u, length, drawn_links + guide_lines, drawn, blocks,
                                   [w for w, _ in busy] + [w for w, _ in names])
                if on_line is not None:
                    return on_its_line(z, u, on_line, name)
        # only where no place on the line is free, beside the link in a lane, its own length (G2,
        # G3 on the coulisse's rocker ran 70 mm down it to O), the arm ending on its line of action
        # drawn thin through the point (``lanes``)
        if inside or (over and name not in armed):
            others = [v for w, v in busy if abs(w - z) < 0.5 and abs((v.conjugate() * u).imag) > 1e-6]
            others += [_unit(e - z) for s, e in drawn_links for e in (s, e)
                       if abs(e - z) > 0.5 and _on_segment(z, s, e)
                       and abs((_unit(e - z).conjugate() * u).imag) > math.sin(math.radians(ALONG_DEG))]
            n = 1j * u
            here, there = sum(max(0.0, dot(n, v)) for v in others), sum(max(0.0, dot(-n, v)) for v in others)
            if abs(here - there) <= 1e-9:
                # either side as free: the side away from the arrows already drawn at the point
                # (G3 down from B, R03 up not yet set: Φ3 and P_B above the block, not over G3;
                # R03 then beside the block away from them)
                laid = [_unit((t + h) / 2 - z) for w, t, h in drawn if abs(w - z) < 0.5 and abs(h - t) > 1e-9
                        and abs((t + h) / 2 - z) > 1e-9]
                here, there = sum(max(0.0, dot(n, v)) for v in laid), sum(max(0.0, dot(-n, v)) for v in laid)
            # a force on the line of one already set aside at its point (Φ3 and P_B at B): its lane
            # on the same side, where the others leave either free — the two parallel, a lane
            # apart, the other side left to the guide's hatching (review 11 #12)
            mate, mid = next(((v, m) for w, v, d, m in set_aside
                              if abs(w - z) < 0.5 and abs((d.conjugate() * u).imag) < 1e-6), (None, None))
            if here > there + 1e-9 or (abs(here - there) <= 1e-9 and mate is not None and dot(n, mate) < 0):
                n = -n
            # a force a few degrees off its link's line (G3 at S3, the rocker 8° from vertical) on
            # the side it turns away to, so that its head does not come back onto the link
            away = False
            sin_along = math.sin(math.radians(ALONG_DEG))
            near = [_unit(e - s_) for s_, e in drawn_links if abs(e - s_) > 1e-9 and _on_segment(z, s_, e)
                    and abs((u.conjugate() * _unit(e - s_)).imag) <= sin_along]
            if near:
                d = near[0] if dot(near[0], u) >= 0 else -near[0]
                dev = u - d * dot(u, d)
                if abs(dev) > math.sin(math.radians(1.0)):
                    n = 1j * u if dot(1j * u, dev) > 0 else -1j * u
                    away = True
            # a lane farther where the first is taken (P_B and Φ3 at B); at a slider's block the
            # lanes start clear of the block (its half height and a millimetre)
            block = any(abs(w - z) < 0.5 for w, _ in guides)
            # beside another arrow of its point (G5 and Φ5 both down from S5: two 2 mm heads
            # 2.5 mm apart read as one arrow, review 47 #3) a lane wide enough to part the heads
            first = BLOCK_HALF + 1.0 if block else (LANE_MM if inside else OVER_LANE_MM)
            offs = ((first, first + LANE_MM, first + 2 * LANE_MM, -first, -first - LANE_MM) if away else
                    (first, -first, first + LANE_MM, -first - LANE_MM, first + 2 * LANE_MM))
            if block and mate is not None:      # at a slider's block: the mate's side, the next lane out
                side = 1.0 if dot(n, mate) > 0 else -1.0
                offs = tuple(side * o for o in (first, first + LANE_MM, first + 2 * LANE_MM)) + \
                    tuple(-side * o for o in (first, first + LANE_MM))
            # … and over the same stretch of the line as it, pushing toward the point where the
            # mate pulls from it (the seeds' pair: P_B arriving at B's level beside Φ3 leaving it)
            back = length * u if mid is not None and dot(mid - z, u) < 0 else 0.0
            cands = [(z + off * n - back, z + off * n + length * u - back, off) for off in offs]
            # (nor from the tail of an arrow set there a few degrees off: the stone's R42 set aside
            # above the slider's block, 5° off its guide, and Φ3 in the same lane left one tail)
            free = [c for c in cands if not any(_one_arrow(c[0], c[1], t, h, LANE_MM / 2) or _one_shaft(c[0], c[1], t, h)
                                                for _, t, h in drawn)]
            if not block:
                # a lane whose arrow neither crosses another link nor runs by another arrow from
                # the point first (review 12 #17: Φ1 beside the crank crossed the rod AB at A, the
                # two lines and the rod read as one knot; the V-twin's G1 then ran by Φ1)
                mine = [(t, h) for w, t, h in drawn if abs(w - z) < 0.5]

                def by(c) -> bool:
                    return any(_on_segment(c[0] + (c[1] - c[0]) * k / 10, t, h, 0.8 * LANE_MM)
                               for k in range(3, 11) for t, h in mine)
                free.sort(key=lambda c: int(_crosses(c[0], c[1], drawn_links)) + int(by(c)))
            a, b, off = free[0] if free else cands[-1]
            if block and _crosses(a, b, drawn_links):
                # beside a slider's block, a lane across no link: leaving the block's level, else
                # arriving at it, head by the block (Φ5 at C crossed the rod BC coming down to C)
                ends = [(z + o * n + k * length * u, z + o * n + (k + 1) * length * u, o)
                        for o in offs for k in (0, -1)]
                a, b, off = next((c for c in ends if not _crosses(c[0], c[1], drawn_links)
                                  and not any(_one_arrow(c[0], c[1], t, h, LANE_MM / 2) for _, t, h in drawn)),
                                 (a, b, off))
            lanes[name] = off * n
            set_aside.append((z, off * n, u, (a + b) / 2))
        if _heads_meet(z, b, drawn):
            a, b = _head_clear(z, u, a, b, drawn, drawn_links, busy)
        drawn.append((z, a, b))
        return a, b

    def along_link(name: str, z: complex, u: complex, length: float) -> tuple[complex, complex]:
        """A component along its link (R^n12 along AB): drawn inside the link's span, from the
        joint or to it, ``LANE_MM`` aside on the side no arrow takes — so that it adds nothing to
        the group's extent (laid from the joint outward it made the six-bar press's II(4-5) a
        step smaller); a component across its link (R^τ12) as any force (``lay``)."""
        runs = [(a_, b_) for a_, b_ in drawn_links if abs(b_ - a_) > 1.0 and _on_segment(z, a_, b_)
                and abs((u.conjugate() * _unit(b_ - a_)).imag) <= math.sin(math.radians(ALONG_DEG))]
        if not runs:          # across: short, the group's extent kept (the value is in the table)
            return lay(name, z, u, min(length, COMPONENT_MM))
        a_, b_ = max(runs, key=lambda r: abs(r[1] - r[0]))
        far = a_ if abs(a_ - z) > abs(b_ - z) else b_
        d = _unit(far - z)
        length = min(length, 0.6 * abs(far - z))
        n = 1j * d
        arrows = [(t, h) for _, t, h in drawn]
        cands = []
        # its own length first, then shorter (not to scale here: the value is in the table), down
        # to the shortest arrow a group draws — one that crosses no arrow drawn before it: LINK50's
        # R^n03, 27 mm up the rocker O2B from O2, ran through Φ3's head at S3 and its name went out
        # on a 49 mm leader
        for lanes_ in ((LANE_MM, -LANE_MM), (2 * LANE_MM, -2 * LANE_MM)):     # the near lanes first
            for k_len in (1.0, 0.75, 0.5):
                ln = max(min(length, 8.0), k_len * length)
                t0, t1 = (z, z + ln * u) if dot(u, d) > 0 else (z - ln * u, z)
                cands += [(t0 + k * n, t1 + k * n) for k in lanes_]
        # … and passes by no other loaded point (S3 with its G3, Φ3 and M^Φ3's arc and names), nor
        # within ``LANE_MM`` of another arrow — a lane's width by the ruler, not by the float: PRESS4's
        # R^n03 from O2 outward, R^τ03's head a lane (2.49999… mm) from O2, was refused and R^n03 went
        # up the rocker in a lane 1.7 mm by G3's head, where "G3" then found no spot of its own
        loaded = {w for w, _, _ in drawn if abs(w - z) > 0.5}

        def clear(c, strict: int) -> bool:
            if any(_one_arrow(c[0], c[1], t, h, LANE_MM / 2) for t, h in arrows) or _crosses(c[0], c[1], drawn_links):
                return False
            return strict < 1 or (not _crosses(c[0], c[1], arrows)
                                  and (strict < 2 or (all(_to_segment(w, c[0], c[1]) > 2 * LANE_MM for w in loaded)
                                                      and all(_apart_mm(c, (t, h)) >= LANE_MM - 1e-6 for t, h in arrows
                                                              if abs(t - z) > 0.5 and abs(h - z) > 0.5))))
        # where none inside the link's span is clear, from the joint outward along the link's line
        # (the textbook's picture: R^n and R^τ at the joint, R their diagonal) — LINK50's R^n03 at O2
        out = []
        for k_len in (1.0, 0.75, 0.5):
            ln = max(min(length, 8.0), k_len * length)
            out.append((z, z + ln * u) if dot(u, d) < 0 else (z - ln * u, z))
        ca, cb = next((c for strict in (2, 1) for c in cands + out if clear(c, strict)),
                      next((c for c in cands if clear(c, 0)), cands[0]))
        drawn.append((z, ca, cb))
        return ca, cb

    def out_of_block(z: complex, u: complex, length: float) -> float:
        """An arrow leaving a slider's block from its centre: at least ``SHOWN_MM`` of it out of the
        block (a 4 mm head and a shaft behind it longer than the head) — LINK62's G4, 11 mm from the
        block's pin B, showed a 7 mm stub below the block, 3 mm of shaft behind its head, and its
        name went out on a 25 mm leader; its Φ3 showed 5 mm past the block's end, mostly head. An
        arrow at a pushing end (arriving at the point) is laid by ``lay`` as before."""
        inside = in_block(z, u)
        return length if inside is None else max(length, inside + SHOWN_MM)

    def lay_at(name: str, z: complex, u: complex, length: float) -> tuple[complex, complex]:
        """``lay``, an arrow leaving a block's centre then lengthened (``out_of_block``) where the
        longer one still leaves the point on its own line (not set a lane aside); an arrow laid
        arriving at the centre is drawn back to the block's edge instead (``to_block``)."""
        def state():
            return list(drawn), dict(lanes), list(set_aside), set(slid)

        def restore(st) -> None:
            drawn[:] = st[0]
            lanes.clear()
            lanes.update(st[1])
            set_aside[:] = st[2]
            slid.clear()
            slid.update(st[3])
        before = state()
        a, b = lay(name, z, u, length)
        longer = out_of_block(z, u, length)
        if longer > length + 1e-9 and abs(a - z) < 0.5 and name not in lanes:
            kept, after = (a, b), state()
            restore(before)
            a, b = lay(name, z, u, longer)
            if name in lanes or abs(a - z) >= 0.5:
                restore(after)
                a, b = kept
        return to_block(z, u, a, b)

    def in_block(z: complex, u: complex) -> float | None:
        """How far the line from ``z`` along ``u`` runs inside the blocks drawn round ``z`` (None: no
        block there; at a pin of two blocks, the slider's and the rocker's, the farther edge)."""
        ins = [min(4.0 / abs(dot(u, g)) if abs(dot(u, g)) > 1e-9 else math.inf,
                   BLOCK_HALF / abs(dot(u, 1j * g)) if abs(dot(u, 1j * g)) > 1e-9 else math.inf)
               for w, g in block_at if abs(w - z) < 0.5]
        return max(ins) if ins else None

    def to_block(z: complex, u: complex, a: complex, b: complex) -> tuple[complex, complex]:
        """An arrow laid arriving at a slider's block's centre (the pushing arrow): drawn back along
        its line until its head touches the block's edge — its head inside the block was hidden by
        the block's outline (LINK62's scheme: G4 down onto B, Φ4 along the guide onto it)."""
        inside = in_block(z, u)
        if inside is None or abs(b - z) > 0.5 or abs(a - z) < 0.5:
            return a, b
        back = (inside + 0.3) * u
        a, b = a - back, b - back
        drawn[-1] = (z, a, b)
        return a, b

    for f in _longest_first(forces, biggest):
        z = f.at / mu
        u = _unit(f.force)
        a, b = span[f.name] = lay_at(f.name, z, u, _arrow_length(abs(f.force), biggest))
        rec.vector(_pt(a), _pt(b), role="absolute", layer="vectors", step=step, text=f.name)
        near_end = a if abs(a - z) < abs(b - z) else b
        if f.name in slid and abs(near_end - z) > 0.5:
            # slid along its line (``_on_line``): a thin stroke from the point to the arrow
            rec.segment(_pt(z), _pt(near_end), role="projection", layer="construction", step=step)
        if f.name in lanes and f.name not in armed:
            # set a lane aside from its point (Φ1 inside the crank): a thin stroke across from the
            # point to its arrow's end there, so that it reads as applied at the point and not as a
            # second line of the link (review 12 #17)
            end = next((e for e in (a, b) if abs(dot(e - z, u)) < 0.5), None)
            if end is not None:
                rec.segment(_pt(z), _pt(end), role="projection", layer="construction", step=step)
        labels.append((a, f.name, -u) if dot(b - z, u) < 0.5 else (b, f.name, u))   # an arrow ending at its point: named at its tail
        if all(abs(w - z) > 0.5 for w, _ in names) and all(abs(w - z) > 0.5 for w, _ in centres):
            lk = mech.links[f.link]            # a load at the link's centre of mass: S_i marked
            centres.append((z, _point_name(fp, f.link, z, mu)))
            # a dot as the position plan draws it (review 13 #13: S1, S2, S4 drawn as hinges' rings)
            rec.point(_pt(z), role="dot", layer="mechanism", step=step)
    # each frame pivot's support on the side free of the links and the arrows (as the kinematics
    # sheet puts it), the crank's leaving room for ω1's arc
    support_at: dict[complex, float] = {}
    omega_mid: float | None = None
    for z in supports:
        crank_pivot = omega_at is not None and abs(omega_at - z) < 0.5
        others = [(a, b) for w, d_ in support_at.items() for a, b in support_strokes(w, d_)]   # clear of those set
        d, mid_ = _support_direction(z, drawn_links + guide_lines, [(a, b) for _, a, b in drawn] + others,
                                     omega=crank_pivot)
        from graphplan.drawing.plans import support as draw_support
        draw_support(rec, z, d, step)
        support_at[z] = d
        if crank_pivot and mid_ is not None:
            omega_mid = math.radians(mid_)

    def support_dirs(z: complex) -> list[float]:
        """The directions (rad) a support at ``z`` takes: its axis and its triangle's sides."""
        return [math.radians(d + e) for w, d in support_at.items() if abs(w - z) < 0.5
                for e in (-40.0, 0.0, 40.0)]
    arcs: dict[complex, list[complex]] = {}      # the couples' arcs drawn at a point (their middles)
    spots: dict[str, complex] = {}               # where a link's couples are drawn (``couple_spot``)
    for f in gp.forces:
        if f.couple and not f.force and f.kind == "balancing":
            # M_зр at the crank's pivot: an arc arrow in its sense, on the side away from the crank
            ck = mech.crank
            pin = complex(kin.bodies[ck.link].at(mech.links[ck.link].local[ck.pin])[0][0]) / mu
            z = f.at / mu
            taken = [cmath.phase(pin - z)] + support_dirs(z)          # the crank, the support
            if omega_at is not None and abs(omega_at - z) < 0.5:     # ω1's arc (r = 9 mm as this one)
                w1 = omega_mid if omega_mid is not None else cmath.phase(z - pin)
                taken += [w1 + math.radians(e) for e in (-45.0, 0.0, 45.0)]
            taken += [cmath.phase(m.acting) for m in outer if m.acting]   # R01 from the pivot
            taken += [cmath.phase(t.foot - z) for eq in gp.equations for t in eq.terms   # the arms
                      if abs(t.arm_mm) >= 1.0 and not t.couple]
            # … and clear of the other pivots' supports (the slotter's at 1:4: the other pivot's
            # hatching 10 mm off, M_зр's arc 0.24 mm from it)
            lines_by = [(p, q) for _, p, q in drawn] + drawn_links
            propped = [ab for w, d_ in support_at.items() if abs(w - z) >= 0.5 for ab in support_strokes(w, d_)]
            # … and from another link passing where its letter goes, beyond the arc (the gate's scheme:
            # «M_b» set past its arc across the coupler AB 17 mm above O1 read as the coupler's)
            beyond = [(p, q) for p, q in drawn_links if _to_segment(z, p, q) > 0.5]

            def lettered(r_: float) -> list[float]:
                return _near_arrows(z, beyond, r_ + LETTER / 2 + 1.0, LETTER / 2 + 2.5)
            taken += lettered(BALANCING_R_MM)
            away = _free_direction_clear(taken + _near_arrows(z, lines_by, BALANCING_R_MM), z,
                                         BALANCING_R_MM, 80.0, propped)
            r = BALANCING_R_MM
            ends = [e for _, p, q in drawn for e in (p, q) if abs(e - z) > 1.0]     # the arrows' ends by it
            if omega_at is not None and abs(omega_at - z) < 0.5 and (
                    abs((away - w1 + math.pi) % (2 * math.pi) - math.pi) < math.radians(150.0)
                    or _arc_near(z, r, away, 80.0, ends) < ARC_CLEAR_MM):
                r = OMEGA_R_MM + 5.0     # beside ω1's arc: wider, so that the two do not read as one
                away = _free_direction_clear(taken + lettered(r) + _near_arrows(z, lines_by, r), z, r, 80.0, propped)
            mid = _moment_arc(rec, z, f.couple, away, step, r=r, span=80.0)
            labels.append((mid, f.name, mid - z))
            clear[z] = z - mid          # the pivot's letter on the side away from the arc
        elif f.couple and not f.force:
            # a couple's arc on the side of its point free of the links and forces there — at a
            # free spot of its link where its point is crowded by others (``couple_spot``)
            own = _pairs(_link_outline(fp, f.link, mu, gp.kind == "mechanism"))
            others = [(a, b) for link in gp.links if link != f.link
                      for a, b in _pairs(_link_outline(fp, link, mu, gp.kind == "mechanism"))]
            z = spots.get(f.link) or couple_spot(
                f.at / mu, own, [w for w, _ in names] + [w for w, _ in centres], drawn,
                others + [ab for w, d_ in support_at.items() for ab in support_strokes(w, d_)]
                + [(m_, m_) for ms in arcs.values() for m_ in ms])
            spots[f.link] = z            # M3 and M^Φ3 on one link: two arcs at one spot
            taken = [cmath.phase(e - z) for a, b in drawn_links for e in (a, b)
                     if abs(e - z) > 0.5 and _on_segment(z, a, b)]
            taken += [cmath.phase(g.force) for g in forces if abs(g.at / mu - z) < 0.5]
            taken += [cmath.phase(-g.force) for g in forces if abs(g.at / mu - z) < 0.5]
            # an arrow set a lane aside at the point (Φ5 beside G5 at S5): where it runs, not its
            # line through the point (the arc came down between the two, its head on Φ5's tail)
            taken += [cmath.phase((p + q) / 2 - z) for w, p, q in drawn
                      if abs(w - z) < 0.5 and abs((p + q) / 2 - z) > 0.5]
            taken += support_dirs(z)                              # the support at a frame pivot
            if omega_at is not None and abs(omega_at - z) < 0.5:  # ω1's arc, away from the crank
                ck = mech.crank
                pin = complex(kin.bodies[ck.link].at(mech.links[ck.link].local[ck.pin])[0][0]) / mu
                taken.append(omega_mid if omega_mid is not None else cmath.phase(z - pin))
            key = next((w for w in arcs if abs(w - z) < 0.5), z)     # M^Φ3 and M3 on one link: two arcs
            taken += [cmath.phase(m_ - z) for m_ in arcs.get(key, [])]     # apart, the second wider
            away = _free_direction(taken or [-math.pi / 2])
            # as wide as the free sector lets it, 15° clear of the lines bounding it (G2 drawn down
            # from S2 on its own line beside the jaw left the jaw's couple 90° between Φ2 and the
            # jaw: a 110° arc's head lay on the jaw), from 60° to 110°
            room = 2.0 * min((abs((away - t + math.pi) % (2 * math.pi) - math.pi) for t in taken), default=math.pi)
            mid = _moment_arc(rec, z, f.couple, away, step, r=5.0 + 4.0 * len(arcs.get(key, [])),
                              span=min(110.0, max(60.0, math.degrees(room) - 30.0)), name="")
            arcs.setdefault(key, []).append(mid)
            labels.append((mid, f.name, mid - z))
            clear[z] = z - mid
    slide_arms: list = []
    for m in outer:
        # the reaction found here acts on the group's link: drawn and named so, R<from><to> (R03, R12)
        truth = fp.ks.reactions[m.key]
        inward = truth.on in gp.links
        z = complex(truth.line_point()[0] if inward else truth.at[0]) / mu
        if inward and m.line is not None:      # a sliding pair's: on the line its ΣM = 0 found (measured)
            z = m.line / mu
        v = m.acting
        if not v:
            continue
        u = _unit(v)
        a, b = span[m.name] = lay_at(m.name, z, u, _arrow_length(m.value, biggest))
        rec.vector(_pt(a), _pt(b), role="result", layer="vectors", step=step, text=m.name)
        labels.append((a, m.name, -u) if abs(dot(b - z, u)) < 0.5 else (b, m.name, u))
        if inward and m.line is not None:
            # a sliding pair's reaction off its pair's point (the yoke's R03 from ΣM = 0 of link 3):
            # its arm h from the point along the guide, drawn aside on the side away from the arrow
            slide_arms.append(_slide_arm(rec, complex(truth.at[0]) / mu, m.line / mu, u, m.name, step))
        # its components at the same point, as the textbook draws them (seed 000, group 12–11):
        # R^τ from the moment equation about the inner joint, R^n along the link from the plan
        for c in _components(gp, m.name):
            cv = (c.end - c.start) * _mu_F(fp, gp)
            cu = _unit(cv)
            ca, cb = span[c.name] = along_link(c.name, z, cu, _arrow_length(abs(cv), biggest))
            rec.vector(_pt(ca), _pt(cb), role="relative", layer="vectors", step=step, text=c.name)
            labels.append((ca, c.name, -cu) if abs(dot(cb - z, cu)) < 0.5 else (cb, c.name, cu))
    arms = []
    for eq in gp.equations:
        about = _about(fp, eq.about, gp)
        if about is None:
            continue
        for t in eq.terms:
            # an arm is drawn to the line of a force drawn on the group (not to a component's)
            f = next((g for g in forces if g.name == t.name), None)
            if abs(t.arm_mm) < 1.0 or t.couple or f is None:
                continue
            arms.append((about, t, f))
    shifts: list[complex] = []
    # the longer arms first: a short arm along a longer one's line (LINK50's h_R43 from B within
    # h_G2, R43 and G2 both near vertical) is set aside from it, so that each has its own line and
    # name — its name went out 30 mm along h_G2's line
    arms.sort(key=lambda x: -abs(x[1].foot - x[0]))
    arm_lines: list[tuple[complex, complex]] = []
    for about, t, f in arms:
        a, b = span[f.name]
        off = lanes.get(f.name, 0j)
        # an arm lying on a drawn arrow or link (h_G2 from B along R03) drawn aside (``arm_aside``)
        # … or on an arm drawn (not one the ruler cannot set apart from it: those are one line, one name)
        mates = [(p, q) for p, q in arm_lines if abs(p - about) > 1e-6 or abs(q - t.foot) > ONE_ARM_MM]
        shift = arm_aside(about, t.foot, _unit(f.force), [(p, q) for _, p, q in drawn] + drawn_links + mates,
                          toward=0.5 * (a + b) - off, outlines=blocks)
        shifts.append(shift)
        arm_lines.append((about + shift, t.foot + shift))
        s0, foot = about + shift, t.foot + shift
        rec.segment(_pt(s0), _pt(foot), role="construction", layer="construction", step=step,
                    text=f"{arm_symbol(t.name)} = {abs(t.arm_mm):g} mm to {t.name}")
        if shift:                        # the extension line from the point the moments are taken about
            rec.segment(_pt(about), _pt(s0 + 1.0 * _unit(shift)), role="projection", layer="construction",
                        step=step)
        # the right-angle mark at the foot: the arm is perpendicular to this force's line
        back, along = _unit(about - t.foot) * 1.5, _unit(f.force) * 1.5
        if dot(f.at / mu - foot, along) < 0:
            along = -along
        rec.add("polyline", [_pt(foot + back), _pt(foot + back + along), _pt(foot + along)],
                role="construction", layer="construction", step=step)
        a, b = a - off, b - off          # the force's line of action (a laned arrow runs beside it)
        if dot(foot - a, b - a) < 0 or dot(foot - b, a - b) < 0:      # past the arrow: its line extended
            near = a if abs(foot - a) < abs(foot - b) else b
            rec.segment(_pt(near), _pt(foot), role="projection", layer="construction", step=step)
        if off:                          # the line itself along the arrow, where the arm ends
            rec.segment(_pt(a), _pt(b), role="projection", layer="construction", step=step)
    if bushings:
        from graphplan.drawing.plans import draw_bushing
        for m, u in bushings:
            draw_bushing(rec, m, u, step=step)
    for z, g in guides if gp.kind == "mechanism" else ():
        # the scheme keeps its guides; a group freed from the frame shows the reaction (R05) in
        # the guide's place — its block's arrows still laid clear of the guide's line
        _guide(rec, z, g, [(a, b) for _, a, b in drawn] + drawn_links, step,
               [w for link in gp.links if len(w := _wedge_outline(fp, link, mu)) >= 4])
    lab = Labeler(rec)
    if omega_at is not None:
        ck = mech.crank
        pin = complex(kin.bodies[ck.link].at(mech.links[ck.link].local[ck.pin])[0][0]) / mu
        _omega(rec, lab, omega_at, mech.omega1,
               omega_mid if omega_mid is not None else cmath.phase(omega_at - pin))
    # a point's letter reads as its own: nearer it than any other point lettered near it (LINK62's
    # II(4-5): «B», pushed off the pin by the block round it, stood nearer S5's dot 9 mm down the
    # lever than B's circle, and a reader took the dot for B)
    lettered = [z for z, _ in names] + [z for z, name in centres if name]

    def rivals(z: complex) -> tuple:
        return tuple(w for w in lettered if 0.5 < abs(w - z) < RIVAL_MM)
    for z, name in names:
        side = next((v for c, v in clear.items() if abs(c - z) < 0.5), None)
        if side is None:
            side = _name_side(z, [(t, h) for w, t, h in drawn if abs(w - z) < 0.5], drawn_links)
        lab.place(z, indexed(name), 3.5, side, step, rivals(z))
    for z, name in centres:
        if name:
            lab.place(z, indexed(name), 3.5, -1 - 1j, step, rivals(z))
    # the arms' letters by their arms first, then the forces' names — each read as its own arrow's
    # (``place_owned_line``), none on a leader across a link: named after the arms, a couple's name
    # took the only leader out of a crowded S2 and h_Φ2's crossed it (an X)
    first_arm = len(lab.asked)
    for mid, text, side in arm_names(arms, shifts):
        lab.place(mid, text, LETTER, side, step)
    for mark in slide_arms:
        if mark is not None:
            lab.place(mark[0], arm_symbol(mark[1]), LETTER, mark[2], step)
    owned: dict[int, tuple[tuple[complex, complex], list[LabelRequest]]] = {}
    # a couple's name before the forces' (it has only its arc's spot; a force's letter may stand
    # anywhere along its shaft): set after Φ4's and G4's, M^Φ4 hung on a 25 mm leader across the rod
    labels.sort(key=lambda lb: lb[1] in span)
    first_force = len(lab.asked)
    for tip, name, u in labels:
        if name in span:       # a force's letter: read as its own arrow's, not a neighbour's
            a, b = span[name]
            mid = 0.5 * (a + b)
            owned[len(lab.asked)] = ((a, b), [LabelRequest(mid, force_symbol(name, lang), side, LETTER, step=step)
                                              for side in (1j * _unit(b - a), -1j * _unit(b - a))])
        lab.place(tip, force_symbol(name, lang), LETTER, u, step)
    # each label fenced by its height while the rest are placed: two arms on one line at B (h_Φ3,
    # h_G3 on the loom's rocker) had their names stacked against each other; no leader across a link
    # … nor nearer an arc's arrowhead (M_зр, ω1, M^Φ) than its own arrow: "G1" by M_зр's head on the
    # press's scheme read as the moment's
    heads = [(complex(*q.points[0]), complex(*q.points[1])) for q in rec.items if q.kind == "vector" and q.role == "head"]
    n0 = len(rec.items)
    _apart(rec, lab.asked, owned, list(span.values()) + heads, across=False)
    joints = [complex(*q.points[0]) for q in rec.items[:n0] if q.kind == "point"]
    if _leaders_badly(rec.items[n0:], joints) > 0.0 and first_force > first_arm:
        # a name on a long leader: the forces' names set before the arms' instead (the arms' in
        # turn, or the other way round), kept where their leaders are shorter and pass no joint
        # (LINK50's II(2-3): the 2 mm arm h_Φ3's name took the spot beside Φ3's short arrow, and
        # "Φ3" went out 30 mm across the rocker)
        best, score = rec.items[n0:], _leaders_badly(rec.items[n0:], joints)
        arms_ = list(range(first_arm, first_force))
        for tail in (arms_, arms_[::-1]):
            del rec.items[n0:]
            order = list(range(first_arm)) + list(range(first_force, len(lab.asked))) + tail
            again = {order.index(i): v for i, v in owned.items()}
            _apart(rec, [lab.asked[i] for i in order], again, list(span.values()) + heads, across=False)
            if _leaders_badly(rec.items[n0:], joints) < score - 1e-9:
                best, score = rec.items[n0:], _leaders_badly(rec.items[n0:], joints)
        del rec.items[n0:]
        rec.items.extend(best)
    lost = lost_components(fp, gp, lang, bound=False) if GROUP_NOTE else ""
    if lost:
        # a component the ruler reads as 0 mm is neither drawn here nor on the plan: named on the
        # group with its value, as its plan's note names it (review 7 #10: R^τ24 = −1.99 N went
        # unaccounted for) — a note at a free spot within the drawing's own extent, lowest first, on
        # no leader (a line under the drawing recomposed the sheet: SIXBAR7's groups went from 1:4
        # to 1:10; set by a point, it read as that point's: "… Н B"); where none has room, only the
        # plan's note names it
        x0, y0, x1, y1 = rec.bounds()
        n = len(rec.items)
        for fy in NOTE_ROWS:
            for fx in NOTE_COLUMNS:
                at = complex(x0 + fx * (x1 - x0), y0 + fy * (y1 - y0))
                place_labels(rec, [LabelRequest(at, lost, 1 + 0j, 3.5, step=step, across=False)], layer="labels")
                placed = rec.items[n:]
                if placed and all(q.kind == "text" for q in placed):
                    bx = Record(items=placed).bounds()
                    if bx[0] >= x0 and bx[1] >= y0 and bx[2] <= x1 and bx[3] <= y1:
                        break
                del rec.items[n:]
            else:
                continue
            break
    return rec


RIVAL_MM = 15.0     # a point's letter on a group stands nearer its point than any other lettered point this near


ONE_ARM_MM = 1.0    # two arms from one point whose feet lie this near (two ruler steps) are drawn as one line


def arm_names(arms: list, shifts: list[complex]) -> list[tuple[complex, str, complex]]:
    """Each arm's name on a group (where, text, side): h_{G2} by the middle of its arm — two arms
    from one point whose feet the ruler cannot set apart (``ONE_ARM_MM``: the rocker's G5 and Φ5,
    both at S5, their lines 1.4° apart, arms 29.0 mm about D, feet 0.7 mm apart) read as one line and
    get one name, both forces in it (h_{G5,Φ5}, as the lever names two forces on one line) — not
    two names fighting for the room by one line (stop 47: "h_{Φ5}" 34 mm off on a leader)."""
    out: list[tuple[complex, str, complex, list[complex]]] = []
    for (about, t, _), shift in zip(arms, shifts):
        foot = t.foot + shift
        same = next((k for k, (_, _, _, key) in enumerate(out)
                     if abs(key[0] - (about + shift)) < 1e-6 and abs(key[1] - foot) <= ONE_ARM_MM), None)
        if same is None:
            out.append((0.5 * (about + t.foot) + shift, arm_symbol(t.name), 1j * _unit(t.foot - about),
                        [about + shift, foot]))
        else:
            mid, text, side, key = out[same]
            out[same] = (mid, text[:-1] + "," + arm_symbol(t.name)[3:], side, key)
    # a name by the middle of its arm where no other arm ends there; else farther along it, where
    # the feet of the others are farthest (own mechanism 50: "h_Φ4" by the middle of its 70 mm arm
    # from O3 stood at h_Φ5's foot, the two arms 2° apart — read as h_Φ5's name)
    feet = [key[1] for _, _, _, key in out]
    placed = []
    for mid, text, side, (s0, foot) in out:
        # (a foot on this arm's own line is a collinear arm's, h_G5 within h_G4: the two lettered as before)
        others = [f for f in feet if abs(f - foot) > 1e-9 and _to_segment(f, s0, foot) > 1.0]

        def room(t: float, s0=s0, foot=foot, others=others) -> float:
            return min((abs(s0 + t * (foot - s0) - f) for f in others), default=math.inf)
        if room(0.5) < ARM_FOOT_MM:
            t = max((0.5, 0.4, 0.6, 0.3, 0.7), key=lambda t: (min(room(t), ARM_FOOT_MM), -abs(t - 0.5)))
            mid = s0 + t * (foot - s0)
        placed.append((mid, text, side))
    return placed


ARM_FOOT_MM = 8.0    # an arm's name kept this far from the foot of another arm (its right-angle mark)


ARM_ASIDE_MM = (4.0, -4.0, 7.0, -7.0, 10.0, -10.0)   # an arm on an arrow's line drawn this far aside


def arm_aside(about: complex, foot: complex, u: complex, lines: list[tuple[complex, complex]],
              toward: complex | None = None, outlines: list[tuple[complex, complex]] = ()) -> complex:
    """Where an arm (``about`` → ``foot``, perpendicular to its force's line along ``u``) is drawn:
    0 where it runs along no drawn arrow or link; else moved along its force's line — its foot stays
    on that line, its length and right angle kept — by the first of ``ARM_ASIDE_MM`` (first toward
    ``toward``, the force's arrow) that runs along nothing drawn, an extension line from ``about``
    to it, as a dimension line is drawn (review 9 #6: h_G2 lay on R03's shaft at B); nor along a
    slider's block's edge (``outlines``, which its extension line may cross)."""
    if abs(foot - about) < 1e-9 or _run_along(about, foot, lines) <= 1.0:
        return 0j
    v = _unit(u)
    if toward is not None and dot(toward - foot, v) < 0:
        v = -v
    every = list(lines) + list(outlines)
    for k in ARM_ASIDE_MM:
        shift = k * v
        if _run_along(about + shift, foot + shift, every) <= 0.5 and not _crosses(about, about + shift, lines):
            return shift
    return ARM_ASIDE_MM[0] * v


def lost_components(fp: ForcePlans, gp: GroupPlan, lang: str = "uk", values: bool = True,
                    bound: bool = True) -> str:
    """The tangential components found by a group's moment equations that the ruler reads as 0 mm
    on its force plan (no side drawn), with their values and the bound: "R^τ24 = −1,99 Н < 0,5 мм";
    "" where there are none."""
    ruler = fp.precision if fp.precision > 0 else 0.5
    lost = {eq.unknown: eq.result for eq in gp.equations if eq.unknown.endswith("τ") and eq.result != 0
            and all(s.name != eq.unknown or s.mm <= 1e-9 for s in gp.sides)}
    if not lost:
        return ""
    named = ", ".join(f"{force_symbol(n, lang)} = {num(v, lang, 3)} {unit('N', lang)}" if values
                      else force_symbol(n, lang) for n, v in lost.items())
    return f"{named} < {num(ruler, lang)} {unit('mm', lang)}" if bound else named


def _components(gp: GroupPlan, name: str) -> list:
    """The sides of the group's force plan that are the reaction ``name``'s tangential and normal
    components (R12τ, R12n: R̄12 = R̄^τ12 + R̄^n12), τ first; none where the plan lays it whole."""
    return [s for mark in ("τ", "n") for s in gp.sides
            if s.name == name + mark and s.role == "component" and s.mm > 1e-9][:2]


def mechanism_record(fp: ForcePlans, lang: str = "uk") -> Record:
    """The whole mechanism at the force position, at μl, with every load the groups carry (weights,
    inertia forces and couples, the resistance) and the balancing moment on the crank: the scheme
    the groups are taken apart from ("схема механізму з прикладеними силами")."""
    loads = [f for gp in fp.groups for f in gp.forces if f.kind == "load"]
    crank = fp.groups[-1].links[0]
    pivot = next(r.at for r in fp.ks.reactions.values() if r.on == crank and r.frm == FRAME)
    # M_зр drawn as on the crank's group: a 9 mm arc clear of ω1's, of the crank and of the arrows
    # passing by (review 8 #3: a 5 mm arc under G1's arrowhead, its sense unreadable)
    loads.append(GForce("M_b", crank, complex(pivot[0]), 0j, couple=fp.balancing, kind="balancing"))
    links = tuple(link for gp in reversed(fp.groups) for link in gp.links)
    whole = GroupPlan("0", "mechanism", links, loads, [], [], [], {}, {}, [], fp.mu_l)
    rec = group_record(fp, whole, lang, omega_at=complex(pivot[0]) / fp.mu_l)
    rec.title = "mechanism with its loads"
    return rec


OMEGA_R_MM = 9.0   # ω1's arc on the scheme
BALANCING_R_MM = 9.0   # M_зр's arc at the crank's pivot (on the scheme and the crank's group)


ARC_CLEAR_MM = 7.0   # M_зр's arc on the scheme at least this far from an arrow's end (its letter's room)


def _arc_near(z: complex, r: float, away: float, span: float, points: list[complex]) -> float:
    """The least distance (mm) from an arc of radius ``r`` about ``z``, ``span``° centred on
    ``away`` (rad), to ``points`` (sampled every 5°)."""
    n = max(2, int(span / 5.0))
    arc = [z + r * cmath.exp(1j * (away + math.radians(-span / 2 + span * k / n))) for k in range(n + 1)]
    return min((abs(a - p) for a in arc for p in points), default=math.inf)


def _near_arrows(z: complex, lines: list[tuple[complex, complex]], r: float, band: float = 3.5) -> list[float]:
    """The directions (rad) from ``z`` to the points of ``lines`` (sampled every 0.5 mm) within
    ``band`` mm of the circle of radius ``r`` about ``z``: where an arc of radius ``r`` about ``z``
    would run over (or its head onto) an arrow passing by (G1 down past O1, Φ1 along the crank)."""
    out = []
    for a, b in lines:
        n = max(2, int(abs(b - a) / 0.5))
        for k in range(n + 1):
            w = a + (b - a) * k / n
            if abs(abs(w - z) - r) < band:
                out.append(cmath.phase(w - z))
    return out


def _omega(rec: Record, lab: Labeler, z: complex, omega: float, away: float, r: float = OMEGA_R_MM) -> None:
    """The crank's sense of rotation at its pivot: a 90° arc with an arrowhead, labelled ω₁ (as on
    the position plan), on the side of the pivot away from the crank (``away``, rad) so that it
    crosses neither the crank nor the balancing moment's arc (r = 5 mm)."""
    step = "the crank's rotation ω1"
    c = math.degrees(away)
    start, end = (c - 45.0, c + 45.0) if omega > 0 else (c + 45.0, c - 45.0)
    rec.arc(_pt(z), r, min(start, end) % 360.0, min(start, end) % 360.0 + 90.0, role="relative",
            layer="mechanism", step=step)
    tail, tip = arc_head(z, r, end, 1 if omega > 0 else -1)
    rec.vector(tail, tip, role="head", layer="mechanism", step=step)
    mid = z + r * complex(math.cos(away), math.sin(away))
    lab.place(mid, "ω_1", 3.5, mid - z, step)


def _about(fp: ForcePlans, name: str, gp: GroupPlan) -> complex | None:
    mech, kin = fp.ks.mech, fp.ks.kin
    mu = _mu(fp, gp)
    for link in gp.links:
        lk = mech.links[link]
        if name in lk.local:
            return complex(kin.bodies[link].at(lk.local[name])[0][0]) / mu
    return complex(kin.point(name)[0][0]) / mu if name in mech.point_names() else None


def _free_direction(taken: list[float]) -> float:
    """The direction (rad, of 24 around) farthest in angle from every direction in ``taken``."""
    def gap(a: float) -> float:
        return min(abs((a - t + math.pi) % (2 * math.pi) - math.pi) for t in taken) if taken else math.pi
    return max((math.radians(15.0 * k) for k in range(24)), key=gap)


def _free_direction_clear(taken: list[float], z: complex, r: float, span: float,
                          lines: list[tuple[complex, complex]], clear: float = 1.0) -> float:
    """``_free_direction``, but of the 24 directions (farthest from ``taken`` first) the first whose
    arc of radius ``r`` and ``span``° about ``z`` (its head included) keeps ``clear`` mm off
    ``lines`` (another pivot's support); none: ``_free_direction``'s."""
    def gap(a: float) -> float:
        return min(abs((a - t + math.pi) % (2 * math.pi) - math.pi) for t in taken) if taken else math.pi
    ink = [a + (b - a) * k / n for a, b in lines for n in [max(2, int(abs(b - a) / 0.5))] for k in range(n + 1)]
    dirs = sorted((math.radians(15.0 * k) for k in range(24)), key=gap, reverse=True)
    return next((a for a in dirs if _arc_near(z, r, a, span + 10.0, ink) >= clear), dirs[0])


def _moment_arc(rec: Record, z: complex, couple: float, away: float, step: str, r: float = 6.0,
                span: float = 120.0, name: str = "M_b") -> complex:
    """A moment drawn at ``z`` as an arc of ``span``° centred on the direction ``away`` (rad) with an
    arrowhead in its sense (+ counter-clockwise), the arrowhead's record text ``name`` (M_b; a couple
    of inertia none: a record's named vectors are its forces); returns the arc's middle."""
    c = math.degrees(away)
    a0, a1 = c - span / 2, c + span / 2
    rec.arc(_pt(z), r, a0 % 360.0, a0 % 360.0 + span, role="relative", layer="vectors", step=step,
            width=0.5)
    tail, tip = arc_head(z, r, a1 if couple > 0 else a0, 1 if couple > 0 else -1)
    rec.vector(tail, tip, role="head", layer="vectors", step=step, text=name, width=0.5)
    return z + r * complex(math.cos(away), math.sin(away))


# -- a force polygon ---------------------------------------------------------------------------

def polygon_record(fp: ForcePlans, gp: GroupPlan, lang: str = "uk") -> Record:
    """The group's force polygon at μF: known forces head to tail, the reactions closing it; its
    sides too short to carry their names drawn again in a detail (``plan_detail``) — in a corner of
    the plan's room (as wide as the sheet's caption under it) where one is free, else, on the crank
    group's plan (a sliver where R21 ≈ R01, its G1 and Φ1 at the tip), beside it. Sketched (the
    composition's first measure) without it: the finished drawing is measured again."""
    from graphplan.drawing.labels import _SKETCH
    plain = _polygon(fp, gp, lang, detail=False)
    if _SKETCH[-1] or plan_detail([s for s in gp.sides if s.mm > 1e-9], _mu_F(fp, gp), _read_in_detail(gp)) is None:
        return plain
    # the detail in a free corner of the plan's room (``_polygon_detail``, within the plan's lettered
    # extent widened to its caption: the rocker six-bar's II(2-3) knot, whose room measured off the
    # unlettered plan refused it by a hair), or, the crank's, under its sliver
    out = _polygon(fp, gp, lang, detail=True, beside=gp.kind == "crank" or bool(_read_in_detail(gp)))
    return out if "mu_F detail" in out.scales else plain


def _read_in_detail(gp: GroupPlan) -> dict[str, float]:
    """The group's reactions the ruler reads 0 mm on its plan, read off its detail: side's name → μF_I
    (``forceplans.detail_scale``)."""
    return {m.name: m.detail_mu for m in gp.reactions.values() if m.detail_mu}


def _polygon(fp: ForcePlans, gp: GroupPlan, lang: str, detail: bool, beside: bool = False) -> Record:
    """``polygon_record``, with its detail where ``detail`` and the plan's room holds one (or
    ``beside`` it)."""
    mu_F = _mu_F(fp, gp)
    rec = Record(f"{word('force plan of group', lang)} {gp.label}", scales={"mu_F": mu_F})
    step = f"{gp.label}: ΣF = 0"
    for a, b in gp.lines:
        rec.segment(_pt(a), _pt(b), role="direction", layer="construction", step=step)
    role = {"known": "absolute", "reaction": "result", "component": "relative"}
    sides = [s for s in gp.sides if s.mm > 1e-9]
    for s in sides:
        rec.vector(_pt(s.start), _pt(s.end), role=role[s.role], layer="vectors", step=step,
                   text=f"{s.name} = {s.mm:.4g} mm")
    rec.point((0.0, 0.0), layer="vectors", step=step)
    tiny = [s for s in sides if s.mm < TINY_MM]
    same = _coinciding(sides)
    rings = _detail_rings(rec, sides, mu_F, step, _read_in_detail(gp)) if detail else []
    detail = rings[0][0] if rings else None
    read = next(iter(_read_in_detail(gp)), "")
    if detail is not None and read and gp.detail_sides and any(q.name == read for q in gp.detail_sides):
        from dataclasses import replace
        detail = replace(detail, fine=tuple(q for q in gp.detail_sides if q.mm > 1e-9), read=read)
        rings[0] = (detail, rings[0][1])
    # a side wholly within a ring is named in its detail (the crank's G1 and Φ1 by R21's tail)
    lettered = [s for s in sides if s.mm >= TINY_MM and s.name not in same
                and not any(_within(s, d.box) for d, _ in rings)]
    anchors = _plan_anchors(lettered)
    # of two sides along one line the shorter letter is set second, on the line's other side
    pairs = {}
    for _, s, side in anchors:
        o = _along_lettered(s, anchors)
        if o is not None:
            short, long_ = sorted((s, o), key=lambda q: len(_plan_letter(q, same, lang)))
            pairs[id(short)] = (long_, side if short is s else -side)
    from graphplan.drawing.labels import box_to_segment
    asked, choices = [], {}
    for at, s, side in anchors:
        if id(s) in pairs:
            # along a side lettered already: on the other side of their one line, wherever along
            # it there is room (by R45's upper end, where P_D stands off), so that each reads as its own
            o, side = pairs[id(s)]
            d = s.end - s.start

            def beyond(box, o=o, s=s, side=side) -> bool:
                twin = next((q for q in rec.items if q.kind == "text" and q.text == _plan_letter(o, same, lang)), None)
                if twin is not None:          # the other side of where the long letter landed
                    t0, t1, t2, t3 = twin.ink()
                    n_ = 1j * _unit(o.end - o.start)
                    side = -n_ if dot(complex(0.5 * (t0 + t2), 0.5 * (t1 + t3)) - o.start, n_) > 0 else n_
                mine = box_to_segment(box, s.start, s.end)
                return (all(dot(complex(x, y) - o.start, side) > 0.5 for x in (box[0], box[2]) for y in (box[1], box[3]))
                        and mine < 2.0 and all(box_to_segment(box, q.start, q.end) > mine + 1.0
                                               for q in sides if q is not s and q is not o
                                               and same.get(q.name) not in (s.name, o.name)))
            choices[len(asked)] = ([LabelRequest(s.start + t * d, _plan_letter(s, same, lang), side, LETTER, step=step)
                                    for t in (0.5, 0.35, 0.65, 0.2, 0.8, 0.1, 0.9)], beyond)
        asked.append(LabelRequest(at, _plan_letter(s, same, lang), side, LETTER, step=step))
    # the long letter first, its twin after it on the line's other side
    order = sorted(range(len(asked)), key=lambda k: k in choices)
    _apart(rec, [asked[k] for k in order], choices={j: choices[k] for j, k in enumerate(order) if k in choices})
    # a sliver's several spots (LINK59's II(4-5): no corner of its 21 mm tall room holds a detail)
    # under it in a row where its room has none
    row = [] if len(rings) > 1 else None
    beside = beside or row is not None
    if detail is not None and not _polygon_detail(rec, detail, sides, same, mu_F, lang, step, gp.label, beside,
                                                  row=row):
        return _polygon(fp, gp, lang, detail=False)      # no room for it: the plan as it was
    # the further spots' details, "II", "III" in turn where the plan's room holds them (LINK59's
    # II(4-5): G4 and Φ5 at P_C's tail, R05 at its head); a ring without room loses its ring
    named = 1
    for d, ring in rings[1:]:
        if named < len(DETAIL_NAMES) and _polygon_detail(rec, d, sides, same, mu_F, lang, step, gp.label, beside,
                                                         name=DETAIL_NAMES[named], row=row):
            named += 1
        else:
            rec.items[:] = [q for q in rec.items if q is not ring]
    x0, y0, _, _ = rec.bounds()
    caption = f"μ_F = {num(mu_F, lang)} {unit('N/mm', lang)}"
    # a load the ruler reads as 0 mm is no side at all (G1 on the crank's plan): named with the tiny
    unseen = [f.name for f in gp.forces if f.force != 0 and all(s.name != f.name for s in sides)]
    if tiny or unseen:     # vectors too short to carry a label: named under the plan with their bound
        names = ", ".join(dict.fromkeys([force_symbol(s.name, lang) for s in tiny]
                                        + [force_symbol(n, lang) for n in unseen]))
        # (a side laid off 1 mm long measures 0.9999… mm along its exact direction: its bound is 2 mm,
        # not "< 1 мм" beside the notes' «Φ1 1 мм», review 60 #2)
        bound = math.floor(round(max(s.mm for s in tiny), 6)) + 1 if tiny else 1
        caption += f"; {names} < {num(bound, lang)} {unit('mm', lang)}"
    # a tangential component the ruler reads as 0 mm (R^τ24 = −1.99 N at 25 N/mm: 0.08 mm) is no
    # side at all: named with its bound, the ruler's division, so that none goes unaccounted for
    lost = lost_components(fp, gp, lang, values=False)
    if lost:
        caption += f"; {lost}"
    rec.label((x0, y0 - 6.0), caption, size=3.5, step=step)
    return rec


DETAIL_SHORT_MM = 5.0    # a force plan's side drawn shorter than this is drawn again in the plan's detail
DETAIL_LEAST_MM = (6.0, 5.0, 4.0, 3.0)    # … the shortest of them drawn at least so long, the first with room
SPECK_SHARE = 0.02       # … or (short) under this share of the plan's longest side: it reads as a speck
DETAIL_MOST_MM = 30.0    # … and the detail's window at most this across
DETAIL_PAD = 1.5         # mm round the short sides' spot on the plan (the ring's room)
DETAIL_CLEAR = 2.0       # mm a detail set within the plan's room keeps off its letters
DETAIL_GAP = 8.0         # mm between the crank group's plan and its detail set beside it
CAPTION_MM = 5.0         # the sheet's caption under a plan (sheets.compose.CAPTION)


def _caption_across(label: str) -> float:
    """How wide the sheet's caption under group ``label``'s force plan is (5 mm lettering,
    centred) in the wider of its languages ("Force plan of group I(0-1)", not "План сил групи
    I(0-1)"): the plan's cell is sized for both (``sheets.forces.ForceDrafter.plan_size``), so the
    Ukrainian drawing has that room too (measured by its own caption, the slotter's crank detail
    found no corner and went under the sliver, 36 mm down: its A3 set took a sixth sheet)."""
    from graphplan.util.words import LANGS
    return max(text_width(f"{word('force plan of group', lang)} {label}", CAPTION_MM) for lang in LANGS)


@dataclass
class PlanDetail:
    """Where a force plan's short sides crowd (the crank group's G1 and Φ1 at the tip of a sliver
    where R21 and R01 nearly cancel): the window (plan mm) and the detail's μF values to try, the
    finest first (``plan_detail``)."""
    box: tuple[float, float, float, float]
    choices: tuple[float, ...]
    fine: tuple = ()          # a reaction read off the detail: the polygon laid again at μF_I (its sides, mm
    read: str = ""            # there: ``GroupPlan.detail_sides``) and that reaction's name, drawn instead
                              # of the plan's sides enlarged


def plan_detail(sides: list, mu_F: float, read: dict[str, float] | None = None) -> PlanDetail | None:
    """The detail of a force plan's short sides (those under ``DETAIL_SHORT_MM``, drawn with the
    sides they meet), GOST 2.305's extension element: the window round them and the μF_I to try —
    for each of ``DETAIL_LEAST_MM``'s lengths ℓ the largest value of the series (1, 2, 2.5, 4, 5 ×
    10^k) at which the shortest side s_min is drawn at least ℓ long (μF_I ≤ μF·s_min/ℓ), no
    finer than draws the window ``DETAIL_MOST_MM`` across, and at least twice the plan's size (μF_I
    ≤ μF/2); None where no side is too short to carry its name (``TINY_MM``: named only under the
    plan, "G1, Φ1 < 3 mm"), or no value is left. The first of ``plan_details``."""
    got = plan_details(sides, mu_F, read)
    return got[0] if got else None


def plan_details(sides: list, mu_F: float, read: dict[str, float] | None = None) -> list[PlanDetail]:
    """Every detail a force plan's short sides need (``plan_detail``'s rule for each knot of them,
    ``_knots``), the knot with the most sides too short to carry their names first: a sliver's short
    sides at both its ends (LINK59's II(4-5) at 20 N/mm: G4 0.5 mm and Φ5 1 mm at P_C's tail, 9 mm
    apart along G5, R05 1.5 mm at its head, 75 mm off) each in their own — one window round G4, G5
    and Φ5 could be enlarged only twice within 30 mm, G4 drawn 1 mm there."""
    from graphplan.drawing.charts import _series_below, hodograph_scale
    for s in sides:
        if read and s.name in read:
            # a reaction the ruler reads 0 mm here (FRC56_PUMP's R05, 0.23 mm at 5 N/mm) is read off
            # the detail at its μF_I (``forceplans.detail_scale``): the window round it no wider than
            # ``DETAIL_MOST_MM`` at that μF_I
            mu = read[s.name]
            span = max(abs(s.end.real - s.start.real), abs(s.end.imag - s.start.imag))
            pad = max(0.1, min(DETAIL_PAD, 0.5 * (DETAIL_MOST_MM * mu / mu_F - span)))
            return [PlanDetail((min(s.start.real, s.end.real) - pad, min(s.start.imag, s.end.imag) - pad,
                                max(s.start.real, s.end.real) + pad, max(s.start.imag, s.end.imag) + pad), (mu,))]
    longest = max((s.mm for s in sides), default=0.0)
    out = []
    for short in _knots([s for s in sides if 1e-9 < s.mm < DETAIL_SHORT_MM]):
        # each side long enough to carry its name, and none a mere speck beside the plan's longest: none
        # (LINK47's crank plan: G1 4 mm and Φ1 4.5 mm at the tip of R21's 271 mm sliver, review 47 #2)
        if not any(s.mm < TINY_MM or s.mm < SPECK_SHARE * longest for s in short):
            continue
        x0, y0, x1, y1 = _window(short)
        smallest = min(s.mm for s in short)
        cap = hodograph_scale(mu_F * max(x1 - x0, y1 - y0), DETAIL_MOST_MM)
        choices = dict.fromkeys(m for m in (max(_series_below(mu_F * smallest / least), cap) for least in DETAIL_LEAST_MM)
                                if mu_F / m >= 2.0 - 1e-9)
        if choices:
            out.append(PlanDetail((x0, y0, x1, y1), tuple(choices)))
    return out


def _window(short: list) -> tuple[float, float, float, float]:
    """The short sides' spot on the plan, padded by ``DETAIL_PAD``."""
    zs = [z for s in short for z in (s.start, s.end)]
    return (min(z.real for z in zs) - DETAIL_PAD, min(z.imag for z in zs) - DETAIL_PAD,
            max(z.real for z in zs) + DETAIL_PAD, max(z.imag for z in zs) + DETAIL_PAD)


def _chained(short: list, near: float) -> list[list]:
    """The short sides chained into knots: ends within ``near`` of each other."""
    knots: list[list] = []
    for s in short:
        joined = [k for k in knots if any(min(abs(p - q) for p in (s.start, s.end) for q in (o.start, o.end)) <= near
                                          for o in k)]
        merged = [s] + [o for k in joined for o in k]
        knots = [k for k in knots if all(k is not j for j in joined)] + [merged]
    return knots


def _knots(short: list) -> list[list]:
    """A plan's short sides in the spots they crowd: the sides within ``DETAIL_MOST_MM`` / 2 of each
    other (end to end, chained) — the knot with the most sides too short to carry their names
    (``TINY_MM``), then the most sides, first. A short side at the plan's other end is no part of a
    knot (the rocker six-bar's II(2-3): R^τ03 3.5 mm at R43's head, 90 mm from the knot of R^τ12,
    G2, Φ2, Φ3 at its foot, made the window 90 mm tall and left the knot without a detail). A knot
    whose window, enlarged until its shortest side is drawn ``DETAIL_LEAST_MM``'s least length,
    would be wider than ``DETAIL_MOST_MM`` is split into the sides that meet end to end (LINK59's
    II(4-5): G4 0.5 mm and Φ5 1 mm 9 mm apart along G5 — a 12.5 mm window, enlarged 6 times 75 mm)."""
    knots = []
    for k in _chained(short, DETAIL_MOST_MM / 2):
        x0, y0, x1, y1 = _window(k)
        grow = DETAIL_LEAST_MM[-1] / max(min(s.mm for s in k), 1e-9)
        knots += _chained(k, 0.05) if max(x1 - x0, y1 - y0) * grow > DETAIL_MOST_MM + 1e-9 else [k]
    # ties in the polygon's order (the details read I, II, III along it)
    first = [min(j for j, s in enumerate(short) if any(s is o for o in k)) for k in knots]
    order = sorted(range(len(knots)), key=lambda i: (-sum(o.mm < TINY_MM for o in knots[i]), -len(knots[i]), first[i]))
    return [[s for s in short if any(s is o for o in knots[i])] for i in order]


def _inside(a: complex, b: complex, box) -> tuple[float, float] | None:
    """The part of segment ab inside ``box`` as (t0, t1) along it (Liang–Barsky), None outside."""
    x0, y0, x1, y1 = box
    t0, t1 = 0.0, 1.0
    d = b - a
    for p, q in ((-d.real, a.real - x0), (d.real, x1 - a.real), (-d.imag, a.imag - y0), (d.imag, y1 - a.imag)):
        if abs(p) < 1e-12:
            if q < 0:
                return None
            continue
        t = q / p
        if p < 0:
            t0 = max(t0, t)
        else:
            t1 = min(t1, t)
    return (t0, t1) if t1 - t0 > 1e-9 else None


def _within(s, box) -> bool:
    """Whether a side lies wholly within ``box``."""
    x0, y0, x1, y1 = box
    return all(x0 - 1e-9 <= z.real <= x1 + 1e-9 and y0 - 1e-9 <= z.imag <= y1 + 1e-9 for z in (s.start, s.end))


def _detail_rings(rec: Record, sides: list, mu_F: float, step: str,
                  read: dict[str, float] | None = None) -> list[tuple[PlanDetail, object]]:
    """Every detail's spot ringed on the plan (GOST 2.305, as the hodographs' details) before the
    plan's letters are set, so that they keep clear of them (``plan_details``): (the detail, its
    ring's item)."""
    out = []
    for d in plan_details(sides, mu_F, read):
        x0, y0, x1, y1 = d.box
        rec.circle(_pt(complex(x0 + x1, y0 + y1) / 2), abs(complex(x1 - x0, y1 - y0)) / 2, role="construction",
                   layer="construction", step=f"{step}: detail")
        out.append((d, rec.items[-1]))
    return out


DETAIL_NAMES = ("I", "II", "III", "IV")     # a plan's details in turn (GOST 2.305's extension elements)


def _polygon_detail(rec: Record, d: PlanDetail, sides: list, same: dict[str, str], mu_F: float, lang: str,
                    step: str, gp_label: str = "", beside: bool = False, name: str = "I",
                    row: list[float] | None = None) -> bool:
    """The ringed spot (``_detail_rings``) drawn again at the detail's μF, every side through the
    window named there, "I (μ_F = 1 N/mm)" over it — the drawn plan enlarged (its lengths as the
    ruler read them, times μF/μF_I), as the hodographs' details — in a corner of the plan's room
    free of its lines and letters (the sheet's composition undisturbed), at the finest of the
    detail's μF that has room there, its ring marked "I" on a shelf; False where none has. ``row``: a
    plan's several details set under it (``beside``) in a row from its left, [x, y] of the next one's
    top-left (filled by the first so set), not each at its middle over the one before."""
    from shapely.geometry import box as shapely_box
    from shapely.ops import unary_union

    from graphplan.drawing.charts import SHELF_LEAD, _corner, _detail_mark, _ink_of
    x0, y0, x1, y1 = d.box
    c = complex(x0 + x1, y0 + y1) / 2
    r = abs(complex(x1 - x0, y1 - y0)) / 2
    ink = unary_union([_ink_of(rec)] + [shapely_box(*q.ink()).buffer(DETAIL_CLEAR)
                                        for q in rec.items if q.kind == "text"])
    rb = rec.bounds()
    # the plan's room: as wide as the sheet's caption under it (``_caption_across``), which a
    # sliver's cell takes anyway
    half = max(rb[2] - rb[0], _caption_across(gp_label)) / 2
    mid = (rb[0] + rb[2]) / 2
    tries = [(mu, False) for mu in d.choices] + ([(d.choices[0], True)] if beside else [])
    if row:                 # a row begun under the plan: the next detail in it (I, II, III in order)
        tries = [(mu, True) for mu in d.choices]
    # every side it draws named first (review 60 #2: the crank's Φ1, 2.5 mm in the detail, drawn
    # unnamed), at every μF_I and place; where no such detail has room, the sides under ``TINY_MM``
    # unnamed as before (named so, FRC56_PUSHER's I and II and LINK59's I–III found no room at all)
    tries = [(mu, out, True) for mu, out in tries] + [(mu, out, False) for mu, out in tries]
    for mu, out, every in tries:
        det = _detail_drawing(d, mu, sides, same, mu_F, lang, step, name, every=every)
        if out and row is not None:         # under the plan, in a row from its left
            if not row:
                row[:] = [rb[0], rb[1] - DETAIL_GAP]
            e0, _, _, e3 = det.bounds()
            moved = det.moved(row[0] - e0, row[1] - e3)
        elif out:               # under the plan, at its middle
            e0, _, e2, e3 = det.bounds()
            moved = det.moved((rb[0] + rb[2]) / 2 - (e0 + e2) / 2, rb[1] - DETAIL_GAP - e3)
        else:
            moved = _corner(ink, det, (c, r), (mid - half, rb[1], mid + half, rb[3]))
        if moved is None:
            continue
        n0 = len(rec.items)
        rec.extend(moved)
        # the ring's mark "I" on a shelf, within the plan's extent where it finds room there
        if not (_detail_mark(rec, c, r, f"{step}: detail mark", name=name)
                or _detail_mark(rec, c, r, f"{step}: detail mark", within=False, name=name)
                # a reaction's spot where the plan's closing lines meet (FRC56_PUMP's R05 at 20 N/mm):
                # on a longer leader, out past them
                or (out and _detail_mark(rec, c, r, f"{step}: detail mark", within=False,
                                         leads=tuple(SHELF_LEAD * k for k in (2, 3, 4)), name=name))):
            del rec.items[n0:]
            continue
        rec.scales["mu_F detail" if name == "I" else f"mu_F detail {name}"] = mu
        if out and row is not None:
            row[0] = moved.bounds()[2] + DETAIL_GAP
        return True
    return False


DETAIL_MID_MM = 8.0     # a detail's side shorter than this is named at its middle


def _detail_drawing(d: PlanDetail, mu: float, sides: list, same: dict[str, str], mu_F: float, lang: str,
                    step: str, name: str = "I", every: bool = False) -> Record:
    """The detail at μF_I = ``mu``: every side through the window, enlarged μF/μF_I times about its
    middle (a side's head out of the window drawn as its line), named (``every``: however short
    there, else from ``TINY_MM``); its name over it."""
    from graphplan.graphic.forceplans import Side
    k = mu_F / mu
    x0, y0, x1, y1 = d.box
    c = complex(x0 + x1, y0 + y1) / 2
    if d.fine:
        # a reaction read off the detail (FRC56_PUMP's R05): the polygon laid again at μF_I, as it
        # was read (``forceplans._Plans.group``), its window as large as the plan's ring enlarged,
        # round that reaction's side there
        r = next(q for q in d.fine if q.name == d.read)
        c = (r.start + r.end) / 2
        w, h = (x1 - x0) * k / 2, (y1 - y0) * k / 2
        sides, k = list(d.fine), 1.0
        x0, y0, x1, y1 = c.real - w, c.imag - h, c.real + w, c.imag + h
        d = PlanDetail((x0, y0, x1, y1), d.choices, read=d.read)
    dstep = f"{step}: detail" if name == "I" else f"{step}: detail {name}"
    det = Record(dstep)
    role = {"known": "absolute", "reaction": "result", "component": "relative"}
    drawn = []
    for s in sides:
        t = _inside(s.start, s.end, d.box)
        if t is None:
            continue
        a, b = s.start + t[0] * (s.end - s.start), s.start + t[1] * (s.end - s.start)
        A, B = (a - c) * k, (b - c) * k
        if abs(B - A) < 1.0:
            continue
        if t[1] >= 1.0 - 1e-9:          # its head within the window: the arrow
            det.vector(_pt(A), _pt(B), role=role[s.role], layer="vectors", step=dstep, text=s.name)
        else:                           # a long side's part: its line, its head out of the window
            det.segment(_pt(A), _pt(B), role=role[s.role], layer="vectors", step=dstep, text=s.name)
        drawn.append(Side(s.name, A, B, s.role))
    if x0 <= 0.0 <= x1 and y0 <= 0.0 <= y1:
        det.point(_pt(-c * k), layer="vectors", step=dstep)
    # (the reaction read here named however short: its reading is what the detail is for)
    lettered = [s for s in drawn if (every or s.mm >= TINY_MM or s.name == d.read) and s.name not in same]
    # each name nearer its own side than any other (labels.place_owned_line), tried along the side
    # on either hand: LINK50's detail of the stone's corner had "R54" by R05's line and Φ4's
    # leader across G5
    anchors = _plan_anchors(lettered)
    owned = {}
    for i, (at, s, side) in enumerate(anchors):
        n = 1j * _unit(s.end - s.start)
        owned[i] = ((s.start, s.end), [LabelRequest(s.start + t * (s.end - s.start), _plan_letter(s, same, lang),
                                                    hand, LETTER, step=dstep)
                                       for t in (0.5, 0.3, 0.7) for hand in (n, -n)])
    # (a short side's leader, where it needs one, to its middle: not to an end another side shares)
    _apart(det, [LabelRequest(at if s.mm > DETAIL_MID_MM else 0.5 * (s.start + s.end), _plan_letter(s, same, lang),
                              side, LETTER, step=dstep) for at, s, side in anchors],
           owned, [(q.start, q.end) for q in drawn])
    b = det.bounds()
    det.label((b[0], b[3] + 4.0), f"{name} (μ_F = {num(mu, lang)} {unit('N/mm', lang)})",
              size=2.5, step=dstep)
    return det


def _coinciding(sides: list) -> dict[str, str]:
    """The components that coincide with their whole reaction on the plan (R^n24 = R24 where R^τ24
    is below the ruler): component's name → the reaction's — one line, one letter "R24 = R^n24"."""
    out = {}
    for c in sides:
        if c.role != "component":
            continue
        whole = next((r for r in sides if r.role == "reaction" and c.name[:-1] == r.name
                      and abs(r.start - c.start) < 0.3 and abs(r.end - c.end) < 0.3), None)
        if whole is not None:
            out[c.name] = whole.name
    return out


def _plan_letter(s, same: dict[str, str], lang: str) -> str:
    """A side's letter: its symbol, joined by its coinciding components' ("R_24 = R^n_24")."""
    return " = ".join([force_symbol(s.name, lang)] + [force_symbol(c, lang) for c, r in same.items() if r == s.name])


_FENCE = "a label's fence (removed once the labels are set)"


def _unfenced_again(rec: Record, n: int, put) -> tuple[list, list, list]:
    """A label set again with only the drawing's lines and letters in the way: its first setting
    (``rec.items[n:]``) and the fences of the labels before taken out, ``put`` called again; returns
    (first, again, fences) with neither setting nor the fences left in ``rec`` — the caller keeps the
    better setting and puts the fences back."""
    first = rec.items[n:]
    del rec.items[n:]
    kept = [p for p in rec.items if p.step == _FENCE]
    rec.items[:] = [p for p in rec.items if p.step != _FENCE]
    m = len(rec.items)
    put()
    again = rec.items[m:]
    del rec.items[m:]
    return first, again, kept


def _apart(rec: Record, asked: list[LabelRequest],
           owned: dict[int, tuple[tuple[complex, complex], list[LabelRequest]]] | None = None,
           arrows: list[tuple[complex, complex]] = (), across: bool = True,
           choices: dict | None = None) -> Record:
    """The labels placed one by one (drawing.labels), each fenced while the rest are placed by a
    ring its letter height out, so that no two stand closer than their height; the rings go.
    A force's letter (``owned``: the request's index → its arrow, tail and head, and further
    anchors along its shaft) is set only where it stands nearer its own arrow than any other of
    the ``arrows`` (labels.place_owned_line): at the ram the press's "P_E" stood by the head of
    Φ4's short arrow and "Φ4" beside the shaft of P_E's. Not ``across``: no leader crosses a link
    or an arrow (on a group a force's name there reads as the other side's)."""
    from dataclasses import replace

    from graphplan.drawing.labels import place_first, place_labels, place_owned_line
    owned = owned or {}
    rings = []
    for i, req in enumerate(asked):
        n = len(rec.items)

        def put(i=i, req=req) -> None:
            if i in owned:
                mine, more = owned[i]
                others = [ab for ab in arrows if ab is not mine and ab != mine]
                place_owned_line(rec, [replace(r, across=across) for r in (req, *more)], mine, others, layer="labels")
            else:
                place_labels(rec, [replace(req, across=across)], layer="labels")
        if choices and i in choices:
            # asked at several anchors, where ``accept`` holds (a side along another's line: on
            # the line's other side); else as any label
            alts, accept = choices[i]
            place_first(rec, [replace(r, across=across) for r in alts], layer="labels", accept=accept)
            new = [p for p in rec.items[n:] if p.kind == "text"]
            if not new or not accept(new[0].ink()):
                del rec.items[n:]
                place_labels(rec, [replace(req, across=across)], layer="labels")
        else:
            put()
        if not across and _led_badly(rec.items[n:], rec.items[:n], req.at):
            # the fences of the labels set before drove it far out (M^Φ4 on the six-bar's scheme on
            # a 25 mm leader across the coupler) or its leader through a joint: set again with only
            # the drawing's lines and letters in the way, kept where that leads it better
            first, again, kept = _unfenced_again(rec, n, put)
            better = (not _led_badly(again, rec.items, req.at, long=max(LONG_LEADER_MM, _leader_mm(first) - 1.0))
                      and _apart_from_labels(again, rec.items, req.size))
            rec.items.extend(kept)
            n = len(rec.items)
            rec.items.extend(again if better else first)
        if i in owned and not _owns(rec.items[n:], owned[i][0], arrows):
            # no spot by its own arrow the fences of the labels set before left (FRC56_PUSHER's
            # II(4-5): "Φ5" set as any label 6.3 mm from its arrow, 2.2 mm from P_D's beside it):
            # set again with only the drawing's lines and letters in the way, kept where it then
            # stands nearer its own arrow than any other, led no worse and apart from the labels
            first, again, kept = _unfenced_again(rec, n, put)
            better = (_owns(again, owned[i][0], arrows)
                      and not (not across and _led_badly(again, rec.items, req.at,
                                                         long=max(LONG_LEADER_MM, _leader_mm(first))))
                      and _apart_from_labels(again, rec.items, req.size))
            rec.items.extend(kept)
            n = len(rec.items)
            rec.items.extend(again if better else first)
        for p in rec.items[n:]:
            if p.kind != "text":
                continue
            x0, y0, x1, y1 = p.bounds()
            g = req.size
            rings.append(rec.add("polyline", [(x0 - g, y0 - g), (x1 + g, y0 - g), (x1 + g, y1 + g),
                                              (x0 - g, y1 + g), (x0 - g, y0 - g)],
                                 role="label", layer="construction", step=_FENCE))   # not breakable
    # by their step: a letter set over thin lines (``breaks``) breaks a ring into pieces too
    rec.items[:] = [p for p in rec.items if p.step != _FENCE]
    return rec


LONG_LEADER_MM = 12.0   # a label's leader longer than this is set again without the fences


def _owns(items: list, mine: tuple[complex, complex], arrows: list[tuple[complex, complex]]) -> bool:
    """Whether the force's letter among ``items`` stands nearer its own arrow ``mine`` than any other
    of the ``arrows`` (its ink's box to each segment; True where none is set or no other is near)."""
    from graphplan.drawing.labels import box_to_segment
    texts = [p for p in items if p.kind == "text"]
    if not texts:
        return True
    box = texts[0].ink()
    d = box_to_segment(box, *mine)
    return all(box_to_segment(box, *o) > d for o in arrows if o is not mine and o != mine)


def _long_leaders(items: list, long: float = LONG_LEADER_MM) -> float:
    """How far the labels' leaders among ``items`` run past ``long`` mm, summed (0: none is long)."""
    return sum(max(0.0, abs(complex(*p.points[1]) - complex(*p.points[0])) - long) for p in items
               if p.kind == "segment" and p.role == "label")


THROUGH_JOINT_MM = 25.0   # a leader through a joint counts as this much leader too long (it reads as the joint's)


def _leaders_badly(items: list, joints: list[complex]) -> float:
    """How badly the labels among ``items`` are led: their leaders' length past ``LONG_LEADER_MM``
    (``_long_leaders``) and ``THROUGH_JOINT_MM`` for each that passes within 0.9 mm of a joint
    between its ends."""
    bad = _long_leaders(items)
    for p in items:
        if p.kind == "segment" and p.role == "label":
            a, b = complex(*p.points[0]), complex(*p.points[1])
            if abs(b - a) > 1e-9 and any(0.05 < dot(z - a, b - a) / abs(b - a) ** 2 < 0.95
                                         and _to_segment(z, a, b) < 0.9 for z in joints):
                bad += THROUGH_JOINT_MM
    return bad


def _leader_mm(items: list) -> float:
    """The length of the label's leader among ``items`` (0 where it stands beside its point)."""
    return sum(abs(complex(*p.points[1]) - complex(*p.points[0])) for p in items
               if p.kind == "segment" and p.role == "label")


def _apart_from_labels(items: list, drawn: list, gap: float) -> bool:
    """Whether the label's letters (``items``) stand at least ``gap`` from every letter drawn."""
    from graphplan.drawing.labels import _meets
    mine = [q.ink() for q in items if q.kind == "text"]
    return not any(_meets(a, q.ink(), gap - 0.05) for a in mine for q in drawn
                   if q.kind == "text" and q.layer == "labels" and q.step != _FENCE)


def _led_badly(items: list, drawn: list, at: complex, long: float = LONG_LEADER_MM) -> bool:
    """Whether a label (its ``items``) hangs on a leader longer than ``long`` or one that passes
    through a joint of the drawing (within 0.9 mm of a point, not its own) or through a letter."""
    from graphplan.drawing.labels import box_to_segment
    for p in items:
        if p.kind != "segment" or p.role != "label":
            continue
        a, b = complex(*p.points[0]), complex(*p.points[1])
        if abs(b - a) > long:
            return True
        d = b - a
        for q in drawn:
            if q.kind == "point":
                z = complex(*q.points[0])
                t = dot(z - a, d) / abs(d) ** 2 if abs(d) > 1e-9 else 0.0
                if abs(z - at) > 1.5 and 0.0 < t < 1.0 and abs(z - (a + t * d)) < 0.9:
                    return True
            elif q.kind == "text" and q.layer == "labels" and q.step != _FENCE:
                if box_to_segment(q.ink(), a + 0.1 * d, a + 0.9 * d) < 0.2:
                    return True
    return False


TINY_MM = 3.0      # a force plan's vector shorter than this gets no label of its own (named under the plan)
SPREAD_MM = 8.0    # labels' anchors on a force plan kept at least this far apart where the sides allow


def _plan_anchors(sides: list) -> list[tuple[complex, object, complex]]:
    """Where each side of a force plan is labelled: at its middle, else the point along it (of
    0.5, 0.35, 0.65 … of its length) farthest from the anchors already taken, so that sides on
    near-parallel lines (R23, R12, Rⁿ12) are named apart; on the side away from the plan's middle."""
    if not sides:
        return []
    centre = sum(0.5 * (s.start + s.end) for s in sides) / len(sides)
    taken: list[complex] = []
    out = []
    for s in sorted(sides, key=lambda s: -s.mm):
        d = s.end - s.start
        best, score = None, -1.0
        for t in (0.5, 0.35, 0.65, 0.25, 0.75, 0.15, 0.85):
            z = s.start + t * d
            gap = min((abs(z - w) for w in taken), default=math.inf)
            if gap >= SPREAD_MM:
                best = z
                break
            if gap > score:
                best, score = z, gap
        taken.append(best)
        n = 1j * _unit(d)
        if dot(n, best - centre) < 0:
            n = -n
        # a side along one already lettered (R45 by R24 on the slider group's plan, the two all
        # but one line): lettered on the other side of the line, so that each letter has its own
        o = _along_lettered(s, out)
        if o is not None:
            m = next(m for _, q, m in out if q is o)
            n = -m if dot(n, m) > 0 else n
        out.append((best, s, n))
    return out


def _along_lettered(s, anchors: list):
    """The side lettered before ``s`` (``anchors`` in order) that runs along s's line, if any."""
    d = s.end - s.start
    for _, o, _ in anchors:
        if o is s:
            return None
        e = o.end - o.start
        mid = 0.5 * (s.start + s.end)
        ts = sorted(dot(z - o.start, _unit(e)) for z in (s.start, s.end))
        if (abs((_unit(d).conjugate() * _unit(e)).imag) < COLLINEAR_SIN
                and abs(((mid - o.start) * _unit(e).conjugate()).imag) < COLLINEAR_MM
                and min(ts[1], abs(e)) - max(ts[0], 0.0) > 1.0):       # overlapping, not end to end
            return o
    return None


COLLINEAR_SIN = 0.1   # two sides of a plan within ~6° …
COLLINEAR_MM = 3.0    # … and this near one line read as one line: lettered on its two sides


# -- the lever ---------------------------------------------------------------------------------

@dataclass
class _Name:
    """A name of the lever to set by its own line (``mine``), not read as any of ``others``."""
    req: LabelRequest
    mine: tuple[complex, complex]
    others: list[tuple[complex, complex]]
    fractions: tuple[float, ...]
    accept: object = None
    owned: tuple | None = None       # a force's arrow and its shaft's anchors, for the last resort


def _name_all(rec: Record, jobs: list[_Name], arrows: list[tuple[complex, complex]]) -> None:
    """The lever's names set by their own lines (labels.place_along) in rounds, each round for the
    names the rounds before did not set: beside its line, owning it; beside it, merely nearer it
    than any other line (where the plan crowds); on a leader to a glance (15 mm) across nothing; on
    one to 25 mm; on one across thin lines only; last as any label (``_apart``) — so that a name that fits beside its line is not
    driven off by one that would need a leader anyway. No name nearer another than its height."""
    from graphplan.drawing.labels import APART
    gap = LETTER - APART + 0.9    # box to box (review 3: names 1.5 mm apart at a, s2, b)
    rounds = ({"longest": 0.0}, {"longest": 0.0, "loose": True}, {}, {"loose": True}, {"longest": FAR_ALONG_MM},
              {"longest": FAR_ALONG_MM, "loose": True}, {"loose": True, "thin": True},
              {"longest": FAR_ALONG_MM, "loose": True, "thin": True}, {"longest": 40.0, "loose": True, "thin": True})
    left = list(jobs)
    for kw in rounds:
        # a force's name only where it owns its arrow (review 5: "Φ3" by P_B's shaft read as P_B's)
        left = [j for j in left if (j.owned and kw.get("loose"))
                or not place_along(rec, j.req, j.mine, j.others, j.fractions, apart=gap, accept=j.accept, **kw)]
    if not left:
        return
    # the rest as any label, each fenced off by the names set (``_apart``'s rings)
    for p in [q for q in rec.items if q.kind == "text" and q.layer == "labels"]:
        x0, y0, x1, y1 = p.bounds()
        g = LETTER
        rec.add("polyline", [(x0 - g, y0 - g), (x1 + g, y0 - g), (x1 + g, y1 + g), (x0 - g, y1 + g), (x0 - g, y0 - g)],
                role="label", layer="construction", step=_FENCE)
    _apart(rec, [j.req for j in left], {i: j.owned for i, j in enumerate(left) if j.owned}, arrows)
    rec.items[:] = [p for p in rec.items if p.step != _FENCE]


FAR_ALONG_MM = 25.0
ONE_RAY_SIN = 0.1     # two arms within ~6° of one ray from the pole read as one line (a name between them is either's)


def _one_ray(f: complex, g: complex) -> bool:
    """Whether two arms' feet lie on one ray from the pole."""
    return dot(g, f) > 0 and abs((f.conjugate() * g).imag) <= ONE_RAY_SIN * abs(f) * abs(g)


def _over(a: complex, b: complex, past: float = 0.0):
    """Whether a name's box stands over the stretch a–b of a line it shares with other arms: its
    middle's projection inside it, 1 mm in from either end — or up to ``past`` mm beyond b, where
    no arm runs on past it (the outermost foot of the weights' line)."""
    d = b - a
    def accept(box) -> bool:
        t = dot(complex(0.5 * (box[0] + box[2]), 0.5 * (box[1] + box[3])) - a, d) / abs(d)
        return 1.0 <= t <= abs(d) - 1.0 + (past + 1.0 if past else 0.0)
    return accept


def _arm_pieces(feet: list[complex]) -> dict[complex, tuple[complex, complex]]:
    """Each arm's own piece (mm): from the pole to its foot, or, where arms run on one ray from the
    pole (the weights' arms of a lever all horizontal), from the next foot nearer the pole — the
    stretch of that line a name reads as this arm's."""
    out = {}
    for f in feet:
        inner = [g for g in feet if 0.3 < abs(f) - abs(g) and _one_ray(f, g)]
        out[f] = (max(inner, key=abs) if inner else 0j, f)
    return out


ARM_LETTER_MM = 5.0   # a lever arm's letter anchored this far from its foot, back toward the pole
ARM_PAST_MM = 4.0     # … or this far past its foot, where no other arm runs on beyond it


_LEVERS: dict[tuple, Record] = {}
_LEVERS_KEPT = 32


def lever_record(fp: ForcePlans, lang: str = "uk") -> Record:
    """The Zhukovsky lever: the velocity plan turned 90° counter-clockwise, each force at its point's
    image, the arms from the pole, the balancing force P_b at the crank pin's image. Remembered by
    what it reads (the lever's value, the crank's pin, the language, whether sketched): a force
    sheet's composition draws the same lever at the same μv again in its rounds."""
    from graphplan.drawing.labels import _SKETCH
    key = (repr(fp.lever), fp.ks.mech.crank.pin, lang, _SKETCH[-1])
    hit = _LEVERS.get(key)
    if hit is None:
        hit = _lever_record(fp, lang)
        if len(_LEVERS) >= _LEVERS_KEPT:
            _LEVERS.pop(next(iter(_LEVERS)))
        _LEVERS[key] = hit
    return Record(hit.title, list(hit.items), dict(hit.scales))


SAME_IMAGE_MM = 1.5    # two of the lever's images this near are one spot, lettered together (as the plan of
                       # velocities letters its points, ``graphic.plan.group_labels``)


def _coincident_images(turned: dict[str, complex]) -> list[tuple[complex, list[str]]]:
    """The lever's images off the pole grouped by spot (within ``SAME_IMAGE_MM``): each spot (the
    first image's place) with the names there — the joints' first, then the centres of mass
    ("a, b, s₂") — the spots farthest from the pole first (the order they are lettered in)."""
    spots: list[tuple[complex, list[str]]] = []
    for name, z in turned.items():
        if abs(z) <= 0.1:
            continue
        spot = next((s for s in spots if abs(s[0] - z) < SAME_IMAGE_MM), None)
        if spot is None:
            spots.append((z, [name]))
        else:
            spot[1].append(name)
    for _, names in spots:
        names.sort(key=lambda n: (n[:1] == "S" and n[1:].isdigit(), n))
    return sorted(spots, key=lambda s: -abs(s[0]))


def _lever_record(fp: ForcePlans, lang: str) -> Record:
    """``lever_record`` drawn."""
    from dataclasses import replace
    lv = fp.lever
    rec = Record(word("lever", lang), scales={"mu_v": lv.mu_v})
    step = "ΣM_p = 0 (Zhukovsky lever)"
    turned = {k: 1j * v for k, v in lv.images.items()}
    for a, b in lv.links:
        if abs(turned[a] - turned[b]) > 0.1:
            rec.segment(_pt(turned[a]), _pt(turned[b]), role="relative", layer="vectors", step=step)
    for name, z in turned.items():
        if abs(z) > 0.1:
            rec.segment((0.0, 0.0), _pt(z), role="construction", layer="construction", step=step)
            rec.point(_pt(z), layer="vectors", step=step)
    rec.point((0.0, 0.0), role="joint", layer="vectors", step=step)
    biggest = max([t.force for t in lv.terms] + [abs(lv.balancing_force), 1e-9])
    labels = []
    arm_feet: dict[complex, list[str]] = {}      # each arm's foot: the forces on that line (one arm serves them)
    span: dict[str, tuple[complex, complex]] = {}      # each force's arrow, tail → head
    drawn: list[tuple[complex, complex, complex]] = []
    lines = [(turned[a], turned[b]) for a, b in lv.links] + [(0j, z) for z in turned.values()]
    images = list(turned.values()) + [0j]
    for t in lv.terms:
        if not t.vector:
            continue
        z = turned[t.image]
        u = _unit(t.vector)
        length = _arrow_length(t.force, biggest)
        tail, tip = z, z + length * u
        ahead, behind = _along_links(z, u, lines)
        if abs(t.arm_mm) >= 1.0 and ahead > 0.5 and behind <= 0.5:
            # along a line of the lever that runs on from its image (P_D at d along d–s4): drawn
            # on its own line pushing, its head at the image, so that the arm still ends on it
            tail, tip = z - length * u, z
        elif (_ends_on(z, tail, tip, drawn, images)
              and not _ends_on(z, z - length * u, z, drawn, images)):
            # its head on another force's head or shaft, or on another image (LINK53's lever:
            # M^Φ2'' leaving a and M^Φ4'' leaving k met head to head, their two names between
            # them for either): drawn pushing, its head at its image
            tail, tip = z - length * u, z
        if (any(abs(w - z) < 0.5 and _one_arrow(tail, tip, a, b) for w, a, b in drawn)
                or (max(ahead, behind) > 0.5 and abs(t.arm_mm) < 1.0)
                or _run_along(tail, tip, lines) > 1.0):
            # on the line of a force drawn at the same image (Φ5 with P_D at d; Φ3 and P_B leaving
            # b in opposite senses read as one double-headed arrow, review 11 #12), along a line of
            # the lever through its point (Φ1 along p_v s1; P_D along d–s4 where Φ5 shares its
            # line): set aside, parallel, away from the pole — a lane farther where the first is
            # taken; the arm to their one line serves both
            n = 1j * u if dot(1j * u, z) >= 0 else -1j * u
            for k in (1, 2, -1, 3, -2):
                a_, b_ = tail + k * SIDE_MM * n, tip + k * SIDE_MM * n
                if not any(_overlap(a_, b_, a, b) for _, a, b in drawn):
                    break
            tail, tip = a_, b_
        drawn.append((z, tail, tip))
        span[t.name] = (tail, tip)
        rec.vector(_pt(tail), _pt(tip), role="absolute", layer="vectors", step=step,
                   text=f"{t.name}: h = {t.arm_mm:g} mm")
        labels.append((tip, t.name, u) if abs(tip - z) >= abs(tail - z) else (tail, t.name, -u))
        if abs(t.arm_mm) >= 1.0:
            foot = z - dot(z, u) * u
            # the arm h from the pole to the force's line, lettered as on the groups (h_{G2})
            rec.segment((0.0, 0.0), _pt(foot), role="construction", layer="construction", step=step,
                        text=f"{arm_symbol(t.name)} = {abs(t.arm_mm):g} mm to {t.name}")
            key = next((k for k in arm_feet if abs(k - foot) < ONE_ARM_MM), foot)   # one line to the ruler
            arm_feet.setdefault(key, []).append(t.name)
            lo, hi = sorted((dot(tail - z, u), dot(tip - z, u)))
            at = dot(foot - z, u)
            if at < lo - 1e-9 or at > hi + 1e-9:      # past the arrow: its line extended to the foot
                near = z + (lo if at < lo else hi) * u
                rec.segment(_pt(near), _pt(foot), role="projection", layer="construction", step=step)
    crank = fp.ks.mech.crank
    a = turned.get(crank.pin, 0j)
    if lv.balancing_force and abs(a) > 0:
        u = -1j * _unit(a) * math.copysign(1.0, lv.balancing_force)
        length = _arrow_length(abs(lv.balancing_force), biggest)
        # pushing from a (its tail there) or pulling into a (its head there), whichever runs along
        # no line of the lever and meets no arrow there (review 12: at ab ∥ P_зр its shaft ran along
        # a–s2–b, its head past b: it read as applied at b)
        # … and where either way runs on a force's line at a (the six-bar's Φ3 leaving a along
        # P_зр's line, its head on P_зр's shaft: review51), set aside, parallel, a lane or two off
        # a (SIDE_MM, as the forces on one line), the lane nearest a line free of them
        n = 1j * u if dot(1j * u, a) >= 0 else -1j * u
        ways = [(t + k * SIDE_MM * n, h + k * SIDE_MM * n, k) for k in (0, 1, -1, 2, -2)
                for t, h in ((a, a + length * u), (a - length * u, a))]
        # … and where one way passes over another image (LINK53 at φ 240°: P_зр up from a through
        # k, k's and s2's arrows ending on its shaft), the other
        others = [w for w in images if abs(w - a) > 0.5]
        tail, tip, _ = min(ways, key=lambda w: (_run_along(w[0], w[1], lines) > 1.0,
                                                sum(_one_arrow(w[0], w[1], c, d) for _, c, d in drawn),
                                                any(_to_segment(z, w[0], w[1]) < HEADS_MM for z in others),
                                                abs(w[2]), abs(w[0] - w[2] * SIDE_MM * n - a) > 1e-9))
        rec.vector(_pt(tail), _pt(tip), role="result", layer="vectors", step=step, text="P_b")
        span["P_b"] = (tail, tip)
        # named beside its shaft, on the side away from the pole: at the head it met the letters
        # of the images the arrow points at (s3 on the coulisse's lever)
        side = 1j * u if dot(1j * u, a) >= 0 else -1j * u
        labels.append((tail + 0.55 * (tip - tail), "P_b", side))
    lab = Labeler(rec)
    _lever_couples(rec, lab, lv, turned, lines + list(span.values()), step, lang)
    # the pole lettered with the images it is, as the lab does: "p_v, o1, o2" — the fixed pivots
    # have no velocity, and the couples' forces at o2 act there
    still = sorted(indexed(name.lower()) for name, z in turned.items() if abs(z) <= 0.1)
    lab.place(0j, ", ".join(["p_v"] + still), 3.5, -1 + 1j, step)
    _apart(rec, lab.asked)
    # the names asked for — each image's letter, each force's, each arm's — each with its own
    # line, the others it must not read as, and where along its line it is anchored
    jobs: list[_Name] = []
    for z, names in _coincident_images(turned):
        # each image lettered beside it, nearer it than any other image (the six-bar's "b" stood
        # on a leader across three arrows); images at one spot lettered together, "a, b, s₂", as
        # the plan of velocities letters them (review51: only "s2" where a, b and s2 coincide)
        req = LabelRequest(z, ", ".join(indexed(n.lower()) for n in names), _unit(z), 3.5, step=step)
        jobs.append(_Name(req, (z, z), [(w, w) for w in turned.values() if abs(w - z) >= SAME_IMAGE_MM], (0.0,)))
    arrows = list(span.values())
    for tip, name, u in labels:
        # a force's name by its own arrow (the press's lever set "G2" on Φ2's head and "Φ2" by
        # G2's shaft: the two read swapped): beside its head or its shaft, either side, else on
        # a short leader from it across nothing (review: leaders to 51 mm across six lines)
        a_, b_ = span[name]
        mine = (a_, b_) if abs(b_ - tip) < abs(a_ - tip) else (b_, a_)     # … from its image to its free end
        fractions = (0.55, 0.75, 0.35, 1.0) if name == "P_b" else (1.0, 0.75, 0.5, 0.25)
        req = LabelRequest(tip, force_symbol(name, lang), u, LETTER, step=step)
        side = 1j * _unit(b_ - a_)
        jobs.append(_Name(req, mine, [ab for ab in arrows if ab != span[name]], fractions,
                          owned=((a_, b_), [replace(req, at=0.5 * (a_ + b_), toward=t) for t in (side, -side)])))
    middle = sum(turned.values()) / max(len(turned), 1)
    arms = _arm_pieces(list(arm_feet))
    # the arms with the least room first — the shortest pieces (LINK58: h_G5's 8 mm of the weights'
    # line between G2's and G4's feet, left after h_G2 took the end of its 28 mm by G5's foot, went
    # out on a leader across the lever); each tried by its foot too, and past it where no arm runs
    # on beyond it (its piece's free end: a dimension's name at its end)
    for foot, names in sorted(arm_feet.items(), key=lambda item: abs(arms[item[0]][1] - arms[item[0]][0])):
        # each arm named by its own segment from the pole, toward its foot (G1's and G2's arms run
        # on one line from the pole: over its own stretch of it), on the side toward the plan's
        # middle first; two forces on one line: one arm, both names (h_{G3,G4})
        at = foot - min(ARM_LETTER_MM, 0.5 * abs(foot)) * _unit(foot)
        side = 1j * _unit(foot) if dot(1j * _unit(foot), middle - at) >= 0 else -1j * _unit(foot)
        text = arm_symbol(names[0]) if len(names) == 1 else "h_{" + ",".join(arm_symbol(n)[3:-1] for n in names) + "}"
        g, _ = arms[foot]
        ray = [f for f in arms if f != foot and _one_ray(f, foot)]
        outer = not any(abs(f) > abs(foot) for f in ray)
        piece = abs(foot - g)
        past = (1.0, 1.0 + ARM_PAST_MM / piece) if outer and piece > 1e-9 else (1.0,)
        jobs.append(_Name(LabelRequest(at, text, side, LETTER, step=step), arms[foot],
                          [s for f, s in arms.items() if f != foot and f not in ray],
                          (0.8, 0.65, 0.5, 0.9, 0.35) + past,
                          accept=_over(g, foot, ARM_PAST_MM + LETTER if outer else 0.0) if ray else None))
    # the forces' names first: an arrow has the fewest spots its name reads as its own
    # the images' letters, then the forces' names one by one, each before the next (review 5: at
    # the ram), then the arms'
    _name_all(rec, [j for j in jobs if j.mine[0] == j.mine[1]], arrows)
    for j in jobs:
        if j.owned:
            _name_all(rec, [j], arrows)
    _name_all(rec, [j for j in jobs if not j.owned and j.mine[0] != j.mine[1]], arrows)
    x0, y0, _, _ = rec.bounds()
    rec.label((x0, y0 - 6.0), f"μ_v = {num(lv.mu_v, lang)} {unit('(m/s)/mm', lang)}", size=3.5, step=step)
    return rec


COUPLE_R_MM = (7.0, 9.0, 11.0)     # a couple's arc on the lever: round its link's short image
COUPLE_SPANS = (120.0, 90.0, 60.0)  # … as long as the lines round it leave free (clear by 2 mm)


def _circle_near(z: complex, r: float, ink):
    """The least distance (mm) from each point of the circle of radius ``r`` about ``z`` at every
    5° (72, from 0°) to the points ``ink`` (a numpy array): ``_arc_near`` for every arc at once."""
    import numpy as np
    circle = z + r * np.exp(1j * np.radians(5.0 * np.arange(72)))
    return np.abs(circle[:, None] - ink[None, :]).min(axis=1)


def _freest_sector(near, span: float) -> tuple[int, float]:
    """The arc of ``span``° (a multiple of 10°) centred on 5°·k whose points (every 5°, as
    ``_arc_near`` samples them) stand farthest from the ink: (k, that least distance), the first
    such k."""
    import numpy as np
    half = int(round(span / 10.0))
    worst = np.min([np.roll(near, -m) for m in range(-half, half + 1)], axis=0)
    k = int(np.argmax(worst))
    return k, float(worst[k])


def _lever_couples(rec: Record, lab: Labeler, lv, turned: dict[str, complex],
                   lines: list[tuple[complex, complex]], step: str, lang: str) -> None:
    """Each inertia couple carried onto the lever as a moment (its link's image shorter than
    READABLE_MM: M·l_xy/l_XY, review 10 #6) drawn as a 120° arc round the image's middle, in the
    moment's sense, where the fewest lines pass, named with its value in N·mm."""
    for t in lv.terms:
        if t.vector or not t.moment:
            continue
        pts = [turned[p] for p in (t.pair or (t.image,)) if p in turned]
        if not pts:
            continue
        z = sum(pts) / len(pts)
        knot = max(abs(p - z) for p in pts)
        import numpy as np
        ink = np.array([a + (b - a) * k / n for a, b in lines for n in [max(2, int(abs(b - a) / 0.5))]
                        for k in range(n + 1)] or [complex(math.inf)])
        best = None
        for r in COUPLE_R_MM:
            r = max(r, knot + 4.0)
            near = _circle_near(z, r, ink)
            for span in COUPLE_SPANS:
                # the sector freest of the lines: the arc (its head included) clear of every arrow
                k, far = _freest_sector(near, span + 10.0)
                away = math.radians(5.0 * k)
                clear = min(far, 2.0)
                if best is None or clear > best[0] + 1e-9:
                    best = (clear, r, span, away)
        _, r, span, away = best
        mid = _moment_arc(rec, z, t.moment, away, step, r=r, span=span, name="")
        if t.pair:
            x, y = t.pair
            text = (f"{force_symbol(t.name, lang)}·l_{{{x.lower()}{y.lower()}}}/l_{{{x}{y}}}"
                    f" = {num(abs(t.moment), lang)} {unit('N·mm', lang)}")
        else:
            text = f"{force_symbol(t.name, lang)}: {num(abs(t.moment), lang)} {unit('N·mm', lang)}"
        lab.place(mid, text, LETTER, mid - z, step)


# -- tables ------------------------------------------------------------------------------------

def _table(rec: Record, x: float, y: float, head: list[str], rows: list[list[str]],
           widths: list[float], step: str, size: float = 2.5, row_h: float = 6.0) -> float:
    """A ruled table (drawing.tables) with its top-left corner at (x, y) added to ``rec``; returns
    its bottom y."""
    t = table([head] + rows, widths, row_h=row_h, size=size).moved(x, y)
    rec.extend(t)
    return t.bounds()[1]


def group_table_record(fp: ForcePlans, gp: GroupPlan, lang: str = "uk") -> Record:
    """Seed 000's tables 2.4–2.5: every force of the group, its value (N) and its drawn length (mm).
    A tangential component found by a moment equation is tabulated as its magnitude, as seed 000
    solves "−R^t = … = 579,7 Н" and lists 579,7: its arrow is drawn in the true sense, and the
    minus (the assumed sense reversed) stays with the moment equation (``forces`` prints it)."""
    rec = Record(f"{word('reactions of group', lang)} {gp.label}")
    step = f"table {gp.label}"
    from graphplan.graphic.draftsman import measure
    cells = []
    for f in gp.forces:       # "on the drawing, mm": each length as laid off with the ruler
        if f.force:
            cells.append((f.name, abs(f.force), measure(abs(f.force) / _mu_F(fp, gp), fp.precision)))
        if f.couple:
            cells.append((f.name, f.couple, None))
    for eq in gp.equations:
        if eq.unknown != "M_b":
            cells.append((eq.unknown, abs(eq.result), measure(abs(eq.result) / _mu_F(fp, gp), fp.precision)))
        if eq.unknown.endswith("τ"):     # its normal component, read off the force plan (seed 000's R^n)
            for c in _components(gp, eq.unknown[:-1]):
                if c.name.endswith("n"):
                    mm = measure(c.mm, fp.precision)
                    cells.append((c.name, mm * _mu_F(fp, gp), mm))
    for m in gp.reactions.values():     # one read off the plan's detail marked so: "4,5 (I)"
        cells.append((m.name, m.value, _reading(m, lang)))
    widths = [max(14.0, text_width(force_symbol(c[0], lang), 2.5) + 4) for c in cells]
    tiers = [cells]
    if 30.0 + sum(widths) > TABLE_WIDEST_MM and len(cells) > 1:
        # two tiers, one under the other, each with its header: a group's table grown by the
        # components (R^τ, R^n at two joints) no wider than the sheet's column already was
        k = len(cells) - len(cells) // 2
        tiers = [cells[:k], cells[k:]]
    y = 0.0
    for tier in tiers:
        head = [word("force", lang)] + [force_symbol(c[0], lang) for c in tier]
        rows = [[word("force value", lang)] + [num(c[1], lang).replace("-", "−") for c in tier],
                [word("drawn mm", lang)] + [c[2] if isinstance(c[2], str) else num(c[2], lang) for c in tier]]
        y = _table(rec, 0.0, y, head, rows, [30.0] + [max(14.0, text_width(h, 2.5) + 4) for h in head[1:]],
                   step) - TIER_GAP_MM
    return rec


TABLE_WIDEST_MM = 200.0   # a group's table wider than this is set in two tiers
TIER_GAP_MM = 3.0         # between the tiers


def _reading(m, lang: str) -> str:
    """A reaction's drawn length as its tables print it; one read off the plan's detail at μF_I
    (the ruler read its side 0 mm at the plan's μF) marked with the detail's name: "4,5 (I)"."""
    from graphplan.drawing.charts import DETAIL_NAME
    return f"{num(m.mm, lang)} ({DETAIL_NAME})" if m.detail_mu else num(m.mm, lang)


LAB_LIMIT = 5.0    # the lab's limit of an error, % (REFERENCE §1.6): a result past it is marked
SHORT_MM = 20.0    # a vector shorter than this reads with a large relative error (±½ division)


def _pct(v: float | None, lang: str) -> str:
    """δ, % signed, with a true minus; "—" for none."""
    return pct(v, lang).replace("-", "−")


def reaction_why(fp: ForcePlans, key: str, lang: str) -> str:
    """Why a reaction read off its force plan misses the lab's 5 %: drawn short, or the closing
    lines of its polygon crossing at a small angle, else the ruler."""
    from graphplan.graphic.draftsman import crossing_angle
    from graphplan.graphic.plan import SMALL_ANGLE_DEG
    sym = force_symbol(key, lang)
    gp = next(g for g in fp.groups if key in g.reactions)
    m = gp.reactions[key]
    from graphplan.graphic.draftsman import measure
    if m.detail_mu:      # read off the detail, where the polygon is laid again at μF_I: its knowns rounded there miss
        side = next((s for s in gp.sides if s.name == m.name), None)
        known = sum(1 for s in gp.sides if s.role == "known")
        # … and a tangential component laid there as its moment equation found it, arms measured at
        # μl (FRC56_PUMP's R^τ24 12.54 N for 12.77 at 1:2.5: 0.23 N of R05's 1.18)
        tau = [force_symbol(s.name, lang) for s in gp.sides
               if s.role == "component" and s.name.endswith("τ")]
        return word("fs why detail tau" if tau else "fs why detail", lang, sym=sym,
                    mm=num(measure(side.mm, fp.precision) if side else 0.0, lang),
                    n=known, half=num(fp.precision / 2, lang), mu=num(m.detail_mu, lang), tau=", ".join(tau))
    if m.mm < SHORT_MM:
        # what a short side misses by, said as the kinematics sheet says it (stop 58: FRC56_PUMP's R03
        # flagged "a short vector" alone): half a division's share of it and the rounded knowns it closes
        known = sum(1 for s in gp.sides if s.role == "known")
        share = fixed(100.0 * fp.precision / 2 / m.mm, lang, 0) if m.mm > 0 else "—"
        return word("fs why short", lang, sym=sym, mm=num(m.mm, lang), share=share, n=known,
                    half=num(fp.precision / 2, lang))
    if len(gp.lines) >= 2:
        (a1, b1), (a2, b2) = gp.lines[-2:]
        angle = crossing_angle(b1 - a1, b2 - a2)
        if angle < SMALL_ANGLE_DEG:
            return word("fs why angle", lang, sym=sym, angle=fixed(angle, lang, 1))
    return word("kin why_ruler", lang, sym=sym)


TABLE_WORD = {"uk": "Таблиця", "en": "Table"}
REACTIONS_TITLE = {"uk": "Реакції: з планів сил і точні", "en": "Reactions: by the force plans and exact"}


def table_title(n: int, title: str, lang: str) -> str:
    """A table's numbered title as the sheets write it: "Таблиця 3. Сили групи II(4-5)"."""
    return f"{TABLE_WORD.get(lang, 'Table')} {n}. {title}"


def _title_above(rec: Record, y_top: float, title: str, step: str) -> None:
    """A table's title over its top edge at ``y_top`` (wrapped to the tables' width)."""
    from graphplan.drawing.tables import TITLE_MM, title_lines
    lines = title_lines(title, TITLE_MM)
    for k, line in enumerate(lines):
        rec.label((0.0, y_top + 2.2 + line_pitch(3.5) * (len(lines) - 1 - k)), line, size=3.5,
                  layer="tables", step=step)


def _carried_why(fp: ForcePlans, lang: str, sym: str) -> str | None:
    """Why M_b by the force plans misses: the reaction the crank takes over from the next group's
    plan (R21), its value and line as read there against the exact, its arm on the crank's drawing
    and its moment; and how much the crank's other moments take off it (review 59 #2: the Watt-II's
    M_b −0.33 N·m = R21's 0.43 − G1's 0.15: R21 read 24.12 N for 24.92, its line 1.3° off from
    R^τ12 found with arms read at 1:4, its arm 18.0 mm for 19.4 — 0.05 N·m, 15 % of M_b). None
    where no single carried reaction accounts for most of the miss."""
    crank = fp.groups[-1] if fp.groups else None
    if crank is None or not crank.equations or fp.analytic == 0:
        return None
    terms = [t for t in crank.equations[0].terms if not t.couple]
    byname = {m.name: m for m in fp.reactions().values()}
    carried = [(t, byname.get(t.name[0] + t.name[1:][::-1])) for t in terms if t.name.startswith("R")]
    carried = [(t, m) for t, m in carried if m is not None]
    if len(carried) != 1 or len(crank.points) < 2:
        return None
    t, m = carried[0]
    o, a = list(crank.points.values())[:2]
    exact = complex(fp.ks.reactions[m.key].force[0])
    if exact == 0 or crank.mu_l <= 0:
        return None
    he = abs((((a - o) * (exact / abs(exact)).conjugate())).imag)
    me = abs(exact) * he * crank.mu_l
    miss = abs(fp.balancing - fp.analytic)
    if abs(abs(t.value) - me) < 0.5 * miss:            # not this moment's miss
        return None
    rest = sum(x.value for x in crank.equations[0].terms if x is not t)
    da = abs((m.angle_deg - m.analytic_angle_deg + 180.0) % 360.0 - 180.0)
    group = next((g.label for g in fp.groups if m.key in g.reactions), "")
    ml = next((g.mu_l for g in fp.groups if m.key in g.reactions), crank.mu_l)
    return word("fs why carried", lang, sym=sym, r=force_symbol(t.name, lang), f=num(t.force, lang),
                fe=num(abs(exact), lang), g=group, da=fixed(da, lang, 1), ml=num(ml, lang),
                h=num(abs(t.arm_mm), lang), he=fixed(he, lang, 1), m=num(abs(t.value), lang), me=num(me, lang),
                rest=num(abs(rest), lang), k=fixed(max(abs(t.value), me) / abs(fp.analytic), lang, 1))


def results_record(fp: ForcePlans, lang: str = "uk", number: int | None = None) -> Record:
    """The balancing moment found four ways and each reaction against its closed form; a result
    past the lab's 5 % is marked (*) and the lines under the tables say why (a short vector, a small
    angle between the polygon's closing lines, a short pa on the lever, the arms' ruler). With
    ``number`` the two tables are titled "Table n." and "Table n+1." (the sheet's numbering)."""
    rec = Record(word("balancing moment", lang))
    step = "results"
    a = fp.analytic
    rows, why = [], []
    for name, value in (("closed form short", a), ("by force plans", fp.balancing),
                        ("by lever", fp.lever.balancing), ("by power", fp.power)):
        e = None if name == "closed form short" or a == 0 else 100 * (value - a) / a
        err = "" if e is None else _pct(e, lang)
        if e is not None and abs(e) > LAB_LIMIT and name != "by power":
            err += "*"
            sym = f"{word('M_b', lang)} ({word(name, lang)})"
            carried = _carried_why(fp, lang, sym) if name == "by force plans" else None
            if name == "by lever" and fp.lever.pa_mm < SHORT_MM:
                why.append(word("fs why pa", lang, sym=sym, mm=num(fp.lever.pa_mm, lang)))
            elif carried:
                why.append(carried)
            else:
                why.append(word("fs why arms", lang, sym=sym, p=num(fp.precision, lang)))
        rows.append([word(name, lang), num(value, lang).replace("-", "−"), err])
    if number is not None:
        _title_above(rec, 0.0, table_title(number, word("fs results", lang), lang), step)
    bottom = _table(rec, 0.0, 0.0, [word("M_b", lang), unit("N·m", lang), "δ, %"], rows, [34.0, 22.0, 18.0], step)
    top = bottom
    if number is not None:
        # the next table's title as far under this table as the sheet's tables stand apart
        # (layout.GAP to its capitals' top; Tables 6 and 7 stood 2.3 mm apart)
        from graphplan.drawing.layout import GAP
        from graphplan.drawing.tables import TITLE_MM, title_lines
        title = table_title(number + 1, REACTIONS_TITLE.get(lang, REACTIONS_TITLE["en"]), lang)
        top = bottom - GAP - 3.5 - 2.2 - line_pitch(3.5) * (len(title_lines(title, TITLE_MM)) - 1)
        _title_above(rec, top, title, step)
    rows = []
    for m in fp.reactions().values():
        err = _pct(m.error_pct, lang)
        if m.error_pct is not None and abs(m.error_pct) > LAB_LIMIT:
            err += "*"
            why.append(reaction_why(fp, m.key, lang))
        # the exact direction beside the drawn one, as ``forces`` prints it: a reaction's angle read
        # off its polygon is where an error of M_b by the plans starts (review 56 #1: R12 read 1.6°
        # off put M_b at +4.4 % while its magnitude was within 0.05 %)
        rows.append([force_symbol(m.key, lang), _reading(m, lang), num(m.value, lang), fixed(m.angle_deg, lang, 1),
                     num(m.analytic, lang), fixed(m.analytic_angle_deg, lang, 1), err])
    bottom = _table(rec, 0.0, top if number is not None else bottom - 8.0, ["R", unit("mm", lang), unit("N", lang), word("angle deg", lang),
                                             word("exact N", lang), word("exact deg", lang), "δ, %"], rows,
                    [12.0, 12.0, 16.0, 14.0, 16.0, 14.0, 12.0], step)
    from graphplan.graphic.forceplans import slide_arms
    arms = [slide_arm_text(a, lang) for a in slide_arms(fp)]
    if why or arms:
        from graphplan.util.markup import split
        y = bottom - 4.5
        for text in arms + ([word("kin mark_head", lang)] + why if why else []):
            line = ""
            for piece in split(text):        # wrapped to the tables' width
                if line and text_width(line + " " + piece, 2.5) > 94.0:
                    rec.label((0.0, y), line, size=2.5, step=step)
                    y -= line_pitch(2.5)
                    line = piece
                else:
                    line = f"{line} {piece}".strip()
            rec.label((0.0, y), line, size=2.5, step=step)
            y -= line_pitch(2.5)
    return rec


# -- layout ------------------------------------------------------------------------------------

def arrange(records: list[Record], gap: float = 15.0, across: bool = True,
            titles: bool = True) -> Record:
    """Records side by side (or one under another, left-aligned), each titled above it."""
    out = Record(" | ".join(r.title for r in records))
    x = y = 0.0
    for r in records:
        x0, y0, x1, y1 = r.bounds()
        top = 8.0 if titles else 0.0
        if across:
            moved = r.moved(x - x0, -y1 - top)
            if titles:
                out.label((x, -4.0), r.title, size=3.5, step=r.title)
            x += (x1 - x0) + gap
        else:
            moved = r.moved(-x0, y - y1 - top)
            if titles:
                out.label((0.0, y - 4.0), r.title, size=3.5, step=r.title)
            y -= (y1 - y0) + gap + top
        out.extend(moved)
        out.scales.update(r.scales)
    return out


def records(fp: ForcePlans, lang: str = "uk") -> dict[str, Record]:
    """Every drawing of the force analysis by name, for the force sheet:
    "group II(4-5)", "polygon II(4-5)", "table II(4-5)", …, "group I(0-1)", …, "lever", "results"."""
    out: dict[str, Record] = {}
    for gp in fp.groups:
        out[f"group {gp.label}"] = group_record(fp, gp, lang)
        out[f"polygon {gp.label}"] = polygon_record(fp, gp, lang)
        out[f"table {gp.label}"] = group_table_record(fp, gp, lang)
    out["lever"] = lever_record(fp, lang)
    out["mechanism"] = mechanism_record(fp, lang)
    out["results"] = results_record(fp, lang)
    return out


def drawing(fp: ForcePlans, lang: str = "uk") -> Record:
    """All of it on one page: each group beside its force plan, one group under another, then the
    lever beside the results."""
    rows = [arrange([group_record(fp, gp, lang), polygon_record(fp, gp, lang)]) for gp in fp.groups]
    rows.append(arrange([lever_record(fp, lang), results_record(fp, lang)]))
    return arrange(rows, across=False, titles=False)


# -- a yoke (a slotted crosshead on a rod) drawn as one rigid body --------------------------------

YOKE_TURN = 72    # the block's travel in the slot taken over this many steps of the turn


def yoke_at(fp: ForcePlans, link: str, mu: float, framed: bool = True):
    """A yoke at the force position (mm at ``mu``) as the position plan draws it
    (``linkshape.yoke_body`` over the whole turn): its slot over the block's travel in it, its rod
    from the slot through D to its farthest point and through its bushing, the bushing (middle,
    unit; None on a moving guide). Not ``framed`` (a group freed from the frame): the rod from the
    slot to its farthest point only, no bushing. Returns (slot's ends, rod's ends, bushing)."""
    import numpy as np

    from graphplan.model.linkshape import yoke_body, yoke_guide, yoke_shape
    mech, kin = fp.ks.mech, fp.ks.kin
    lk = mech.links[link]
    g = yoke_guide(mech, link)
    ref_local = lk.local[next(iter(lk.local))]
    turn = fp.ks.st.solve(np.linspace(0.0, 360.0, YOKE_TURN, endpoint=False))
    sliders = [s for s, other in mech.links.items() if other.slides_on == g.name]

    def at(k, body, z, i):
        return complex(k.bodies[body].at(z)[0][i]) / mu

    def frame(k, i):
        ur = complex(k.bodies[link].turn[i])
        return at(k, link, ref_local, i), ur, at(k, link, g.through, i), ur * np.exp(1j * g.angle)
    every = [(turn, i) for i in range(YOKE_TURN)] + [(kin, 0)]
    frames = [frame(k, i) for k, i in every]
    blocks = [[at(k, s, z, i) for s in sliders for z in mech.links[s].local.values()] for k, i in every]
    own = [[at(k, link, z, i) for z in lk.local.values()] for k, i in every]
    guide = mech.guides[lk.slides_on]
    line = O = None
    if guide.body == FRAME and framed:
        line = (guide.through / mu, complex(np.exp(1j * guide.angle)))
        O = mech.frame[mech.crank.pivot] / mu
    # the frame's reaction on the rod (R03) acts where ΣM = 0 puts it: the rod is drawn on past it
    # (the exact line and the one the group's construction drew)
    keys = [k for k, r in fp.ks.reactions.items() if r.guide is not None and {r.on, r.frm} == {link, FRAME}]
    reach = [complex(fp.ks.reactions[k].line_point()[0]) / mu for k in keys]
    reach += [complex(m.line) / mu for g in fp.groups for k, m in g.reactions.items()
              if k in keys and m.line is not None]
    slot, rod, bushing = yoke_body(frames, blocks, own, line, O, mech.crank.length / mu, reach)
    return (*yoke_shape(*frames[-1], slot, rod), bushing)


def yoke_mm(fp: ForcePlans, link: str, mu: float, framed: bool = True) -> tuple[complex, complex, complex, complex]:
    """A yoke at the force position (mm at ``mu``): its slot's ends and its rod's ends (``yoke_at``)."""
    return yoke_at(fp, link, mu, framed)[:4]


def yoke_lines(fp: ForcePlans, link: str, mu: float, framed: bool = True) -> list[complex]:
    """A yoke's drawn lines as one polyline for the arrows to keep clear of: along its slot, back
    to the rod's crossing, along the rod to its far end."""
    from graphplan.model.linkshape import rod_crossing
    a, b, p, q = yoke_mm(fp, link, mu, framed)
    x = rod_crossing(p, _unit(q - p), a, _unit(b - a))
    return [a, b, x, q if abs(q - x) >= abs(p - x) else p]


def draw_yoke(rec: Record, fp: ForcePlans, link: str, mu: float, step: str, framed: bool = True) -> None:
    """The yoke as one body: its slot (its two sides, closed) and its rod from the slot through D."""
    from graphplan.model.linkshape import rod_from_slot, rod_stubs, slot_outline
    a, b, p, q = yoke_mm(fp, link, mu, framed)
    rec.add("polyline", [_pt(z) for z in slot_outline(a, b)], role="link", layer="mechanism", step=step)
    rec.segment(*(_pt(z) for z in rod_from_slot(a, b, p, q)), role="link", layer="mechanism", step=step)
    body = fp.ks.kin.bodies[link]
    own = [complex(body.at(w)[0][0]) / mu for w in fp.ks.mech.links[link].local.values()]
    for f, z in rod_stubs(p, _unit(q - p), own):
        rec.segment(_pt(f), _pt(z), role="link", layer="mechanism", step=step)


SLIDE_ARM_ASIDE_MM = 4.0   # a sliding pair's reaction's arm drawn this far beside the guide's line


def _slide_arm(rec: Record, at: complex, line: complex, u: complex, name: str, step: str):
    """The arm h of a sliding pair's reaction (mm): from the pair's point ``at`` along the guide to
    the reaction's line through ``line`` (its direction ``u``), drawn ``SLIDE_ARM_ASIDE_MM`` aside
    on the side away from the arrow with extension lines from both ends (it lies on the rod). The
    spot and side for its letter, or None where it is shorter than a millimetre (on the point)."""
    if abs(line - at) < 1.0:
        return None
    side = -u * SLIDE_ARM_ASIDE_MM
    rec.segment(_pt(at + side), _pt(line + side), role="construction", layer="construction", step=step,
                text=f"{arm_symbol(name)} = {abs(line - at):.1f} mm to {name}")
    for z in (at, line):
        rec.segment(_pt(z), _pt(z + side * 1.25), role="projection", layer="construction", step=step)
    return 0.5 * (at + line) + side, name, side


def slide_arm_text(a, lang: str = "uk", h: str | None = None) -> str:
    """One line (markup) for a sliding pair's reaction's arm (``forceplans.SlideArm``): h_{R03} (or
    ``h``) in mm and m from its point along the guide, the closed form's and δ — the sheet's and the
    terminal's words."""
    return word("fs slide arm", lang, h=h or arm_symbol(a.key), mm=num(abs(a.h_mm), lang), m=num(a.value, lang),
                p=a.point, e=num(a.analytic, lang), d=_pct(a.error_pct, lang), r=force_symbol(a.key, lang),
                g=a.group, n=a.link)


def _slot_sides(fp: ForcePlans, link: str, mu: float) -> list[complex]:
    """A yoke's slot as drawn (its closed outline, mm): the arrows are laid clear of its sides."""
    from graphplan.model.linkshape import slot_outline
    a, b, _, _ = yoke_mm(fp, link, mu)
    return slot_outline(a, b)
