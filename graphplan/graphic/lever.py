"""The Zhukovsky lever (seed 000 §2.6): the velocity plan built from the measured plan vectors p_v x
(mm at μv, rounded), turned 90° counter-clockwise; each force carried to its point's image (a couple
as a pair M/l at its link's joints); Σ F·h about the pole, with h read off the lever, balances the
force P_b at the crank pin's image: P_b·pa = ΣF·h, M_b = P_b·l_OA."""
from __future__ import annotations

import math
from dataclasses import replace, dataclass

import numpy as np

from graphplan.graphic.draftsman import measure
from graphplan.graphic.scales import at_least as standard_scale
from graphplan.exact.kinematics import cross
from graphplan.exact.kinetostatics import Kinetostatics, Load

PLAN_MM = 120.0        # the fastest point's velocity vector on the lever
# a link's image shorter than this carries its inertia couple as a moment, not as a force pair:
# the pair's two arrows (⊥ xy, at x and y) must stand apart with their two names (M^Φ', M^Φ'':
# 3.5 mm letters with a superscript and a subscript, ~5 mm tall) and the two images' letters
# (3.5 mm) between them, each 1 mm from the next — ~15 mm. Review 10 #6: at φ = 150° the
# six-bar's a, b lie 7 mm apart at μv = 0.01 and 11 mm at the A1 sheet's 0.00628; both drew
# seven forces and their names knotted round a, b, e, s2 and two long dashed arms to the pair
READABLE_MM = 15.0


@dataclass
class LeverTerm:
    name: str
    force: float         # N
    arm_mm: float        # signed: + counter-clockwise about the pole
    moment: float        # N·mm
    image: str           # the point's image it acts at
    vector: complex      # the force (N), for drawing
    pair: tuple[str, str] = ()       # a couple carried as a moment: its link's two points X, Y
    ratio: float = 0.0               # … and l_xy (mm, measured on the lever) / l_XY (m)


@dataclass
class Lever:
    """The Zhukovsky lever: the velocity plan (mm, not yet turned) and the moments about the pole."""
    mu_v: float
    images: dict[str, complex]      # p_v x in mm (measured lengths, exact directions)
    links: list[tuple[str, str]]    # image segments of the links (for drawing)
    terms: list[LeverTerm]
    pa_mm: float
    total: float                    # Σ F·h, N·mm
    balancing_force: float          # P_b (N), + when its moment on the crank is counter-clockwise
    balancing: float                # M_b, N·m


def velocity_scale(ks: Kinetostatics, target_mm: float = PLAN_MM) -> float:
    """μv ((m/s)/mm, standard series) so that the fastest point's vector is ≤ ``target_mm``."""
    fastest = max(float(np.max(np.abs(ks.kin.point(p)[1]))) for p in ks.mech.point_names())
    return standard_scale(max(fastest, 1e-12) / target_mm)


def lever(ks: Kinetostatics, precision: float, mu_v: float | None = None, loads: list[Load] | None = None) -> Lever:
    """The Zhukovsky lever at the (single) angle of ``ks``, loaded by ``loads`` (default ``ks``'s; the
    force plans pass theirs: the inertia loads read off the acceleration plan)."""
    mech, kin = ks.mech, ks.kin
    mu_v = mu_v or velocity_scale(ks)
    images: dict[str, complex] = {}

    def image(link: str, point: str) -> complex:
        """p_v x: the measured length of the plan vector, its exact direction (mm)."""
        if point not in images:
            v = complex(kin.bodies[link].at(mech.links[link].local[point])[1][0])
            images[point] = measure(abs(v) / mu_v, precision) * v / abs(v) if v else 0j
        return images[point]

    terms: list[LeverTerm] = []

    def add(name: str, link: str, point: str, force: complex) -> None:
        if force == 0:
            return
        turned = 1j * image(link, point)
        unit = force / abs(force)
        arm = cross(turned, unit)
        h = math.copysign(measure(abs(arm), precision), arm)
        terms.append(LeverTerm(name, abs(force), h, abs(force) * h, point, force))

    for ld in (ks.loads if loads is None else loads):
        f, c = complex(ld.force[0]), float(ld.couple[0])
        if f != 0:
            add(ld.name, ld.link, ld.point, f)
        if c != 0 and not _couple_pair(ld, c, ks, add, image, precision, terms) \
                and not _couple_pair(replace(ld, link=_guide(mech, ld.link)), c, ks, add, image, precision, terms):
            # a link with a single point on no turning guide: the couple's moment on the lever is
            # −M·ω/μv, the moment of its force pair at the images of any two of its points
            omega = float(ld.omega[0])
            terms.append(LeverTerm(ld.name, abs(c), 0.0, -c * omega / mu_v, ld.point or "", 0j))
    crank = mech.crank
    pa = measure(abs(image(crank.link, crank.pin)), precision)
    for link_name in mech.links:
        image(link_name, next(iter(mech.links[link_name].local)))
    total = sum(t.moment for t in terms)
    p_b = total / pa if pa else float("nan")
    m_b = math.copysign(1.0, mech.omega1) * p_b * crank.length
    segs = []
    for name, link in mech.links.items():
        pts = [p for p in link.local if p in images]
        segs += [(pts[i], pts[i + 1]) for i in range(len(pts) - 1)]
    return Lever(mu_v, images, segs, terms, pa, total, p_b, m_b)


def _guide(mech, link: str) -> str:
    """The link a block slides on, when that guide is a link (a coulisse's slotted lever): the block
    turns with it (ω₄ = ω₅), so its couple is carried as a pair M/l at the guide's points — the
    textbook's rule for a couple on the lever, with the guide's length (review 58: a row «M^Φ₄, F =
    0,042, h = 0» gave the couple as a force). Else the link itself."""
    guide = mech.links[link].slides_on
    return guide if guide in mech.links and guide != link else link


def _couple_pair(ld: Load, c: float, ks: Kinetostatics, add, image, precision: float,
                 terms: list[LeverTerm]) -> bool:
    """A couple M on a link as two forces M/l ⊥ XY at two of its points X, Y (seed 000: P' = M/l);
    where the image xy is shorter than READABLE_MM, as the couple's own moment on the lever,
    M·l_xy/l_XY (the couple's transfer rule: the pair M/l_XY at x, y has the arm l_xy; its sense
    the couple's, −M·ω/μv with ω = v_XY/l_XY = l_xy·μv/l_XY)."""
    link = ks.mech.links[ld.link]
    names = list(link.joints) + [p for p in link.local if p not in link.joints]
    body = ks.kin.bodies[ld.link]
    pos = {p: complex(body.at(link.local[p])[0][0]) for p in names}
    pair = next(((x, y) for i, x in enumerate(names) for y in names[i + 1:]
                 if abs(pos[y] - pos[x]) > 1e-9), None)
    if pair is None:
        return False
    x, y = pair
    length = abs(pos[y] - pos[x])
    shown = image(ld.link, y) - image(ld.link, x)
    if abs(shown) < READABLE_MM:
        # ω's sense from the image: v_Y − v_X ⊥ XY, counter-clockwise when cross(XY, xy) > 0
        sense = math.copysign(1.0, cross(pos[y] - pos[x], shown)) if shown else 0.0
        ratio = measure(abs(shown), precision) / length
        terms.append(LeverTerm(ld.name, abs(c), 0.0, -c * sense * ratio, x, 0j, (x, y), ratio))
        return True
    f = c / length * 1j * (pos[y] - pos[x]) / length       # cross(Y − X, f) = M
    add(f"{ld.name}'", ld.link, y, f)
    add(f"{ld.name}''", ld.link, x, -f)
    return True
