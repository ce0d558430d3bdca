"""A scene's likely slips that are not errors: a point placed where a student rarely means it. Told as
one line each (warned, not refused): a centre of mass outside the span of its link's joints, and an
extra point far beyond the link (metres written where a fraction of the length was meant, or the
other way round). An extension point — the rocker O2–B–D with D = 1.3 — is not one of them."""
from __future__ import annotations

from graphplan.model.mechanism import Link, Mechanism
from graphplan.util.words import said

COM_ALONG = 0.02     # a centre of mass past its link's end joints by more than this share of the span …
COM_ACROSS = 0.3     # … or off their band by more than this share of it (a lug, a plate: a little) is outside the link
FAR = 2.0            # an extra point farther than this many spans from the nearest joint is "far beyond"
RATIO = 100.0        # links whose lengths differ more than this many times: some in millimetres?
LONG = 20.0          # m: a lever mechanism of a machine is smaller; a length above it was meant in mm


def _joints(mech: Mechanism, link: Link) -> list[str]:
    """The link's joints: its own, and its points another link pins to (a plate's third vertex)."""
    others = {j for other in mech.links.values() if other.name != link.name for j in other.joints}
    return [p for p in link.local if p in link.joints or p in others]


def _span(link: Link, joints: list[str]) -> float:
    """The largest distance between two of the link's joints (its length for a bar)."""
    pts = [link.local[j] for j in joints]
    return max((abs(a - b) for a in pts for b in pts), default=0.0)


def cautions(mech: Mechanism) -> list[dict[str, str]]:
    """Each likely slip of the scene's points, in both languages (util.words.said)."""
    out: list[dict[str, str]] = _units(mech)
    for link in mech.links.values():
        joints = _joints(mech, link)
        if len(joints) < 2 or link.slides_on is not None:
            continue
        span = _span(link, joints)
        if span <= 0:
            continue
        for name, p in link.local.items():
            if name in joints:
                continue
            nearest = min(joints, key=lambda j: abs(link.local[j] - p))
            dist = abs(link.local[nearest] - p)
            if name == link.com and _outside(link, joints, p, span, crank=link.number == 1):
                out.append(said("caution com outside", link=link.name, point=name, dist=float(dist), joint=nearest,
                                span=float(span)))
            elif name != link.com and dist > FAR * span:
                out.append(said("caution far point", link=link.name, point=name, dist=float(dist), joint=nearest,
                                span=float(span)))
    return out


def _outside(link: Link, joints: list[str], p: complex, span: float, crank: bool) -> bool:
    """``p`` outside the band of the joints in the link's own frame (along its first two joints' line):
    past the end joints along it, or well off it across. A crank's centre of mass may lie behind its
    pivot (a counterweight), up to the crank's length."""
    o, x = link.local[joints[0]], link.local[joints[1]]
    axis = (x - o) / abs(x - o)
    local = [(link.local[j] - o) / axis for j in joints]
    q = (p - o) / axis
    lo, hi = min(z.real for z in local), max(z.real for z in local)
    if crank:
        lo -= span
    off_lo, off_hi = min(z.imag for z in local), max(z.imag for z in local)
    return (q.real < lo - COM_ALONG * span or q.real > hi + COM_ALONG * span
            or q.imag < off_lo - COM_ACROSS * span or q.imag > off_hi + COM_ACROSS * span)


def _units(mech: Mechanism) -> list[dict[str, str]]:
    """Lengths written in millimetres where the scene wants metres: a link longer than LONG, or the
    longest more than RATIO times the shortest (l = 307 beside r = 0.064)."""
    lengths = {link.name: float(link.length) for link in mech.links.values() if link.length}
    if len(lengths) < 1:
        return []
    big = max(lengths, key=lengths.get)
    small = min(lengths, key=lengths.get)
    if lengths[big] > LONG or lengths[big] > RATIO * lengths[small]:
        return [said("caution units", long=big, big=lengths[big], short=small, small=lengths[small])]
    return []
