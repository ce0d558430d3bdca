"""Structural analysis: mobility W = 3n − 2p5 − p4 and the Assur decomposition into class-II dyads.

Pairs come from the scene: a point shared by two bodies is a revolute pair R, a link that
``slides_on`` another body's guide forms a prismatic pair P. Dyads are found from the input
mechanism I(0-1) outward; each is named by its pairs in order outer–inner–outer (RRR, RRP,
RPR, PRP, RPP; PRR and PPR are the same kinds read the other way round).
"""
from __future__ import annotations

from dataclasses import dataclass

from graphplan.util.errors import SceneError, keyed_error
from graphplan.model.mechanism import FRAME, Mechanism


@dataclass(frozen=True)
class Pair:
    """A lower pair between two bodies. R: ``point`` is the joint. P: ``slider`` slides on
    the guide ``guide`` carried by the other body; ``point`` is the slider's point on that line."""
    kind: str
    bodies: tuple[str, str]
    point: str
    slider: str | None = None
    guide: str | None = None

    def other(self, body: str) -> str:
        return self.bodies[1] if self.bodies[0] == body else self.bodies[0]


@dataclass(frozen=True)
class Dyad:
    """A class-II Assur group: links ``a`` and ``b``; ``outer_a`` joins a to a known body,
    ``inner`` joins a and b, ``outer_b`` joins b to a known body."""
    kind: str
    a: str
    b: str
    outer_a: Pair
    inner: Pair
    outer_b: Pair
    numbers: tuple[int, int]

    @property
    def key(self) -> str:
        """The point whose assembly branch the scene chooses ([branch] table)."""
        if self.kind == "RPR":
            return self.outer_a.point if self.inner.slider == self.a else self.outer_b.point
        return self.inner.point

    @property
    def block_parts(self) -> tuple[str, str, Pair, Pair]:
        """A slotted-link (RPR) group's parts: the block, the rocker carrying its guide, the
        block's outer pair and the rocker's outer pair."""
        slider = self.inner.slider
        if slider == self.a:
            return self.a, self.b, self.outer_a, self.outer_b
        return self.b, self.a, self.outer_b, self.outer_a

    @property
    def label(self) -> str:
        return f"II({self.numbers[0]}-{self.numbers[1]})"

    @property
    def title(self) -> str:
        return f"dyad {self.label} {self.kind} (links {self.a}, {self.b})"


@dataclass(frozen=True)
class Structure:
    n: int
    p5: int
    p4: int
    dyads: tuple[Dyad, ...]
    crank: str = ""

    @property
    def formula(self) -> str:
        return self.written(self.crank)

    @property
    def mobility(self) -> int:
        """Chebyshev: W = 3n − 2p5 − p4."""
        return 3 * self.n - 2 * self.p5 - self.p4

    def parents(self, crank: str) -> list[int]:
        """For each dyad, the group it is attached to: the latest of the groups holding the links
        its outer pairs join (−1: the input mechanism I(0-1); the frame attaches nothing)."""
        owner = {crank: -1}
        out: list[int] = []
        for k, d in enumerate(self.dyads):
            joined = {d.outer_a.other(d.a), d.outer_b.other(d.b)}
            out.append(max((owner[b] for b in joined if b in owner), default=-1))
            owner[d.a] = owner[d.b] = k
        return out

    def paths(self, crank: str) -> list[list[int]]:
        """The formula's chains: each group with no group attached to it, traced back to I(0-1)
        through the group it hangs on — one chain for a serial mechanism, one per branch where
        groups hang on the crank side by side (a V-engine's two pistons)."""
        parent = self.parents(crank)
        leaves = [k for k in range(len(self.dyads)) if k not in parent]
        chains = []
        for leaf in leaves:
            chain, k = [], leaf
            while k >= 0:
                chain.append(k)
                k = parent[k]
            chains.append(chain[::-1])
        return chains or [[]]

    def written(self, crank: str, name=lambda d: d.label) -> str:
        """The structural formula as the textbook writes it: I(0-1) → II(2-3) → II(4-5), branches
        separated by "; " (I(0-1) → II(2-3); I(0-1) → II(4-5))."""
        return "; ".join(" → ".join(["I(0-1)"] + [name(self.dyads[k]) for k in chain])
                         for chain in self.paths(crank))


def pairs_of(mech: Mechanism) -> list[Pair]:
    """All lower pairs: R where bodies share a joint (k bodies → k−1 pairs), P for each slide."""
    pairs: list[Pair] = []
    holders: dict[str, list[str]] = {}
    for name, link in mech.links.items():
        for j in link.joints:
            holders.setdefault(j, []).append(name)
    for point, bodies in holders.items():
        if point in mech.frame:
            bodies = [FRAME] + bodies
        for other in bodies[1:]:
            # a joint shared by several links: chain them to the first holder
            pairs.append(Pair("R", (other, bodies[0]), point))
    for name, link in mech.links.items():
        if link.slides_on is not None:
            guide = mech.guides[link.slides_on]
            origin = next(iter(link.local))
            pairs.append(Pair("P", (name, guide.body), origin, slider=name, guide=guide.name))
    return pairs


def _lang(mech: Mechanism) -> str | None:
    """The scene's language (its ``lang``), what its refusals speak unless --lang says otherwise."""
    return mech.task.meta.get("lang")


def analyse(mech: Mechanism) -> Structure:
    """Mobility and the Assur decomposition; SceneError if W ≠ 1 or no class-II chain exists."""
    pairs = pairs_of(mech)
    n = len(mech.links)
    structure_p5 = len(pairs)
    w = 3 * n - 2 * structure_p5
    where = mech.source
    crank = mech.crank.link
    crank_pairs = [p for p in pairs if crank in p.bodies and FRAME in p.bodies]
    if not any(p.kind == "R" and p.point == mech.crank.pivot for p in crank_pairs):
        raise keyed_error(SceneError, where, "", "st crank pivot", _lang(mech), crank=crank, pivot=mech.crank.pivot)
    if w != 1:
        raise keyed_error(SceneError, where, "", "st mobility", _lang(mech), n=n, p5=structure_p5, w=w,
                          joints="joints", slides_on="slides_on")
    known = {FRAME, crank}
    todo = [name for name in mech.links if name != crank]
    dyads: list[Dyad] = []
    while todo:
        found = _next_dyad(mech, pairs, known, todo)
        if found is None:
            raise keyed_error(SceneError, where, "", "st no groups", _lang(mech), links=", ".join(todo))
        dyads.append(found)
        known |= {found.a, found.b}
        todo = [t for t in todo if t not in (found.a, found.b)]
    return Structure(n=n, p5=structure_p5, p4=0, dyads=tuple(dyads), crank=crank)


def _next_dyad(mech: Mechanism, pairs: list[Pair], known: set[str], todo: list[str]) -> Dyad | None:
    for i, x in enumerate(todo):
        for y in todo[i + 1:]:
            inner = [p for p in pairs if set(p.bodies) == {x, y}]
            out_x = [p for p in pairs if x in p.bodies and p.other(x) in known]
            out_y = [p for p in pairs if y in p.bodies and p.other(y) in known]
            if len(inner) != 1 or len(out_x) != 1 or len(out_y) != 1:
                continue
            return _canonical(mech, x, y, out_x[0], inner[0], out_y[0])
    return None


def _canonical(mech: Mechanism, x: str, y: str, ox: Pair, inner: Pair, oy: Pair) -> Dyad:
    kind = ox.kind + inner.kind + oy.kind
    if kind in ("PRR", "PPR"):
        x, y, ox, oy = y, x, oy, ox
        kind = kind[::-1]
    if kind == "PPP":
        raise keyed_error(SceneError, mech.source, "", "st ppp", _lang(mech), x=x, y=y)
    numbers = sorted((mech.links[x].number, mech.links[y].number))
    return Dyad(kind=kind, a=x, b=y, outer_a=ox, inner=inner, outer_b=oy,
                numbers=(numbers[0], numbers[1]))
