"""2, 3. What a velocity or acceleration plan is: the pole, vectors laid off with the ruler, direction
lines intersected, points by similarity, every segment read and compared with the exact solution."""
from __future__ import annotations

import math
from dataclasses import dataclass, field


from graphplan.util.words import LANGS, fixed, num, word
from graphplan.graphic.record import LabelRequest, Record
from graphplan.util.errors import GraphplanError
from graphplan.exact.kinematics import Kinematics
from graphplan.model.linkshape import extra_points, rigid_outline
from graphplan.model.mechanism import FRAME
from graphplan.graphic.draftsman import cross, crossing_angle, dot, lay_off, line_line, measure, unit
from graphplan.graphic.position_plan import Image, Layout, Scheme, sub, where


NEAR_ZERO = 1e-3        # exact vectors below this share of the plan's largest (or below one ruler
                        # division) get no percent error
VANISH = 1e-3           # a constructed velocity this short (share of the plan's largest) = a dead centre
SMALL_ANGLE_DEG = 15.0  # direction lines / arcs crossing at less than this are ill-conditioned


@dataclass
class Entry:
    """One measured quantity: the plan's magnitude (``mm`` × scale, or ω, ε from them) beside
    the exact one. ``vector``/``exact`` keep the directions (plan vector × scale in SI; for ω, ε the
    signed values) so the sense can be checked too; ``basis`` is the analytic size of the vector the
    entry derives from (for the near-zero rule)."""
    key: str
    kind: str
    mm: float | None
    value: float
    analytic: float
    vector: complex
    exact: complex
    basis: float
    sense: str | None = None
    error_pct: float | None = None
    drawn: float | None = None    # ω, ε: the drawn length (mm) of the relative vector read (the ruler's)


@dataclass
class PlanWarning:
    """An ill-conditioned construction, with the angle that makes it so (for a dead centre: how
    far the crank is from the extreme position)."""
    plan: str        # "position", "velocity", "acceleration"
    group: str
    kind: str        # "lines", "arcs", "dead centre"
    angle: float
    text: str        # English (the JSON's)
    text_uk: str = ""

    def say(self, lang: str) -> str:
        """The warning in ``lang`` (util.words)."""
        return self.text_uk if lang == "uk" and self.text_uk else self.text


@dataclass
class Equation:
    """One vector equation drawn on a plan: from the known plan point ``base`` the known components
    ``chain`` (vector mm, role, end label, entry key) are laid off; the unknown component lies on
    the line through the chain's end along ``direction``.

    For the words of a replay (nothing here changes the drawing): ``name`` is the base's plan name
    (util.markup, "" for the pole), ``term`` the unknown component ("a^τ_CB"), ``rule`` how its
    line runs: ("perp", "CB") perpendicular to CB, ("link", "OB") along the link OB (a slotted
    link), ("guide", "C") along the fixed guide of the slider C."""
    base: complex
    direction: complex
    unknown_role: str
    chain: list[tuple[complex, str, str, str]] = field(default_factory=list)
    name: str = ""
    term: str = ""
    rule: tuple[str, str] = ("", "")

    @property
    def end(self) -> complex:
        return self.base + sum((v for v, *_ in self.chain), 0j)


@dataclass
class Side:
    """One equation as it was drawn, for a replay in the textbook's order: the record's indices of
    its known components (None where one was too short to draw), of its direction line and of its
    unknown component up to the intersection (None when too short)."""
    equation: Equation
    chain: list[int | None]
    line: int
    unknown: int | None


@dataclass
class Solved:
    """One group's two equations solved on the plan: the point found (its plan name, util.markup)
    where the direction lines cross, and what each equation drew."""
    group: str
    step: str
    found: str
    at: complex
    sides: tuple[Side, Side]


# -- 2, 3. velocity and acceleration plans --------------------------------------------------------

CRANK_STEP = 0.1    # mm: the crank's own vector laid to a tenth of a millimetre (``Plan.scaled``)

class Exact:
    """The analytic solution at one crank angle — used only for the comparison."""

    def __init__(self, kin: Kinematics, k: int):
        self.kin, self.k = kin, k

    def point(self, name: str) -> tuple[complex, complex, complex]:
        x, v, a = self.kin.point(name)
        return complex(x[self.k]), complex(v[self.k]), complex(a[self.k])

    def at(self, body: str, point: str) -> tuple[complex, complex]:
        """Velocity and acceleration of ``body``'s point that is at ``point``'s place now."""
        if body == FRAME:
            return 0j, 0j
        b, k = self.kin.bodies[body], self.k
        r = self.point(point)[0] - complex(b.origin[k])
        w, e = float(b.omega[k]), float(b.eps[k])
        return complex(b.vo[k]) + 1j * w * r, complex(b.ao[k]) + (1j * e - w * w) * r

    def omega(self, body: str) -> float:
        return 0.0 if body == FRAME else float(self.kin.bodies[body].omega[self.k])

    def eps(self, body: str) -> float:
        return 0.0 if body == FRAME else float(self.kin.bodies[body].eps[self.k])


class Plan:
    """A velocity or acceleration plan being drawn: plan points, body images, the record, entries.

    ``rates`` holds the measured ω (velocity plan) or ε (acceleration plan) of each body, signed
    (+ counter-clockwise); ``basis`` the analytic size of the relative vector each was read from."""

    kind = ""
    pole = ""
    rate_kind = ""
    index = 1          # 1: velocities, 2: accelerations in Kinematics.point(); 0/1 in Exact.at()

    def __init__(self, sc: Scheme, lay: Layout, exact: Exact, mu: float, precision: float):
        self.sc, self.lay, self.exact = sc, lay, exact
        self.mu, self.precision = mu, precision
        self.images: dict[str, Image] = {FRAME: Image(0j, 0j, 0j)}
        self.rates: dict[str, float] = {FRAME: 0.0}
        self.basis: dict[str, float] = {FRAME: 0.0}
        self.read_mm: dict[str, float | None] = {FRAME: None}   # each body's ``Entry.drawn``
        self.entries: dict[str, Entry] = {}
        self.record = Record()
        self.labels: list[LabelRequest] = []
        self.named: dict[str, complex] = {}
        self.warnings: list[PlanWarning] = []
        self.found: list[tuple[str, str, complex]] = []   # (group, point, constructed plan point)
        self.ends = {"n": 0, "k": 0}
        self.segments: list[tuple[complex, complex]] = []
        # what a replay needs, in the order drawn (the record's indices; nothing read from them):
        self.solved: list[Solved] = []                      # each group's construction
        self.crank_items: list[int] = []                    # a_A's components when ε1 ≠ 0
        self.absolute_items: dict[str, int | None] = {}     # point → its vector from the pole
        self.figure_items: dict[str, list[int]] = {}        # link → its similar figure's lines

    # the ruler -------------------------------------------------------------------------------------
    def read(self, vec_mm: complex) -> tuple[float, float]:
        """(mm, value): a plan segment read with the ruler and multiplied by the scale."""
        mm = measure(abs(vec_mm), self.precision)
        return mm, mm * self.mu

    def laid(self, value: float, direction: complex) -> complex:
        """A computed magnitude laid off with the ruler along ``direction`` (a plan vector, mm)."""
        return lay_off(abs(value) / self.mu, self.precision) * unit(direction)

    @property
    def crank_step(self) -> float:
        """The step the crank's own vector is laid and written to: a tenth of a millimetre (seed 000
        lays π a = a_A / μa = 113,6 mm), or the ruler's division where that is finer (0 = exact)."""
        return min(self.precision, CRANK_STEP) if self.precision > 0 else 0.0

    def scaled(self, value: float, direction: complex) -> complex:
        """The crank's own vector, p_v a = v_A / μ_v (π a = a_A / μ_a), laid off to ``crank_step``
        as the lab lays a computed length — read back (``entries``) it is what the tables print, mm ×
        μ = value: Table 2 printed π a 99,5 mm beside a_A 24,871 m/s² at μa 0,25 (99,5 × 0,25 =
        24,875; drawn at the computed 99,48 mm, its value ω1²·l, not the drawing's). Laid with the
        ruler's 0.5 mm it would read v_A 1,06 where ω1·l = 1,07 (review 8: the coulisse's p_v a 42,7
        mm at μ_v 0,025 laid 42,5). A vector shorter than the ruler's division is laid with the
        ruler as any other (0 mm — the scale draws no plan; a Scotch yoke a hair off its guide at
        μ_v = 0.5 would draw p_v a = 0.125 mm)."""
        length = abs(value) / self.mu
        if self.precision > 0 and length < self.precision:
            return self.laid(value, direction)
        return lay_off(length, self.crank_step) * unit(direction)

    # what is measured --------------------------------------------------------------------------------
    def entry(self, key: str, kind: str, vec_mm: complex, exact: complex, laid: bool = False,
              step: float | None = None) -> None:
        """A segment of the plan: read off (or, for a laid-off component, its laid length; ``step``:
        read to that step, the crank pin's vector laid to it — ``scaled``)."""
        if step is not None and abs(vec_mm) >= self.precision:
            mm = measure(abs(vec_mm), step)
            value = mm * self.mu
        else:
            mm, value = (abs(vec_mm), abs(vec_mm) * self.mu) if laid else self.read(vec_mm)
        if (laid or step is not None) and math.isclose(value, abs(exact), rel_tol=1e-9):
            value = abs(exact)          # laid off as computed: its round-off is no error (not "−0,00 %")
        self.entries[key] = Entry(key, kind, mm, value, abs(exact), vec_mm * self.mu, exact, abs(exact))

    def rate(self, link: str, value: float, exact: float, basis: float, drawn: float | None = None) -> None:
        """ω (or ε) of a link: its measured signed value beside the exact one; ``drawn`` the length
        (mm) of the plan's relative vector it was read from, as drawn."""
        self.rates[link], self.basis[link], self.read_mm[link] = value, basis, drawn
        if self.sc.rotating.get(link) and link != self.sc.mech.crank.link:
            sense = None if value == 0 else ("ccw" if value > 0 else "cw")
            key = f"{self.rate_kind}_{link}"
            self.entries[key] = Entry(key, self.rate_kind, None, abs(value), abs(exact), value, exact,
                                      basis, sense, drawn=drawn)

    def inherit(self, link: str, carrier: str) -> None:
        """A slider turns with the body that carries its guide: the same ω and ε. On the crank's
        guide (a slotted crank) that is ω1, ε1, given, not read off the plan: kept for the plan's
        later steps, no entry of its own (the table's column of −10,5 at every position, struck out)."""
        exact = self.exact.omega(link) if self.kind == "velocity" else self.exact.eps(link)
        if carrier == self.sc.mech.crank.link:
            self.rates[link], self.basis[link] = self.rates[carrier], self.basis[carrier]
            self.read_mm[link] = self.read_mm.get(carrier)
            return
        self.rate(link, self.rates[carrier], exact, self.basis[carrier], self.read_mm.get(carrier))

    def turn_rate(self, link: str, X: complex, C: complex, rel_mm: complex, length: float,
                  exact_rel: complex) -> None:
        """ω = v_CX / l (or ε = a^τ_CX / l) with its sense, the sign of (C − X) × the plan segment."""
        _, value = self.read(rel_mm)
        signed = math.copysign(value / length, cross(C - X, rel_mm)) if value else 0.0
        exact = self.exact.omega(link) if self.kind == "velocity" else self.exact.eps(link)
        self.rate(link, signed, exact, abs(exact_rel), abs(rel_mm))

    # drawing -----------------------------------------------------------------------------------------
    def vector(self, a: complex, b: complex, role: str, step: str) -> int | None:
        """An arrow from a to b unless shorter than 0.3 mm; its index in the record (or None)."""
        if abs(b - a) > 0.3:
            self.record.vector((a.real, a.imag), (b.real, b.imag), role=role, layer="vectors", step=step)
            self.segments.append((a, b))
            return len(self.record.items) - 1
        return None

    def drawn(self, a: complex, b: complex) -> bool:
        """Is the segment ab (either way) already drawn as a vector?"""
        return any(min(abs(a - p) + abs(b - q), abs(a - q) + abs(b - p)) < 1e-6 for p, q in self.segments)

    def link_figures(self) -> None:
        """The similar figure of every link on the plan, drawn thin as the link is drawn on the
        position plan (``rigid_outline``): the line ab on which s2 lies, extended to a point on the
        link's extension; the triangle abc of a plate — the similarity theorem's figure, by which c
        is found (Δabc ∼ ΔABC)."""
        sc = self.sc
        for name, link in sc.mech.links.items():
            if name == sc.mech.crank.link or name not in self.images:
                continue
            outline = rigid_outline([self.plan_point(name, j) for j in link.joints],
                                    [self.plan_point(name, p) for p in extra_points(link)])
            pairs = list(zip(outline, outline[1:]))
            for a, b in pairs:
                if abs(b - a) > 0.3 and not self.drawn(a, b):
                    self.record.segment((a.real, a.imag), (b.real, b.imag), role="construction",
                                        layer="construction", step=f"similarity: link {name}")
                    self.figure_items.setdefault(name, []).append(len(self.record.items) - 1)

    def known(self, point: str) -> str:
        """A known point's plan name for a replay's words: "" (the pole) for a fixed point."""
        return "" if self.sc.fixed(point) else sub(point)

    def name_point(self, label: str, at: complex) -> None:
        self.named.setdefault(label, at)

    def end_label(self, letter: str, link: str | None = None) -> str:
        """The letter of a component's end on the plan: by the link it belongs to (n2: the normal
        component of link 2's rotation; a second one of the same link n2′), else numbered in the
        order of drawing — but the Coriolis end is k as the lab letters it (REFERENCE §1: "Coriolis
        k"), a second one k′."""
        if link is None and letter == "k":
            seen = self.ends[letter]
            self.ends[letter] += 1
            return letter + "′" * seen
        if link is None:
            self.ends[letter] += 1
            return sub(f"{letter}{self.ends[letter]}")
        number = self.sc.mech.links[link].number
        key = f"{letter}{number}"
        seen = self.ends.setdefault(key, 0)
        self.ends[key] = seen + 1
        return sub(key) + "′" * seen

    def direction_line(self, through: complex, found: complex, direction: complex, step: str) -> int:
        """A thin line along ``direction`` through the known end, reaching past the intersection;
        its index in the record."""
        u = unit(direction)
        t = dot(u, found - through)
        lo, hi = min(0.0, t) - 6.0, max(0.0, t) + 6.0
        a, b = through + lo * u, through + hi * u
        self.record.segment((a.real, a.imag), (b.real, b.imag), role="direction", layer="construction",
                            step=step)
        return len(self.record.items) - 1

    def solve(self, group: str, what: str, e1: Equation, e2: Equation, step: str) -> complex:
        """Lay off both equations' known components, draw their direction lines; the unknown plan
        point is where the lines cross. A warning when they cross at a small angle."""
        angle = crossing_angle(e1.direction, e2.direction)
        if angle < 1e-9:
            raise GraphplanError(f"{self.kind} plan at φ = {self.lay.phi:.4g}°, {group}: the direction "
                                 f"lines of {step} are parallel (a toggle position); the plan has no "
                                 "intersection there", self.sc.mech.source)
        x = line_line(e1.end, e1.direction, e2.end, e2.direction)
        sides = []
        for eq in (e1, e2):
            at = eq.base
            chain = []
            for vec, role, label, _key in eq.chain:
                chain.append(self.vector(at, at + vec, role, step))
                if label:                 # a short one shares its start's label ("b, n3")
                    self.name_point(label, at + vec)
                at = at + vec
            line = self.direction_line(eq.end, x, eq.direction, step)
            sides.append(Side(eq, chain, line, self.vector(eq.end, x, eq.unknown_role, step)))
        self.solved.append(Solved(group, step, what, x, (sides[0], sides[1])))
        if angle < SMALL_ANGLE_DEG:
            slip = 0.5 / math.sin(math.radians(max(angle, 1e-9)))
            said = {lang: word("warn lines", lang, plan=word(f"{self.kind} plan lower", lang), group=group,
                               step=step, angle=fixed(angle, lang, 1), limit=num(SMALL_ANGLE_DEG, lang),
                               what=what, slip=fixed(slip, lang, 1)) for lang in LANGS}
            self.warnings.append(PlanWarning(self.kind, group, "lines", angle, said["en"], said["uk"]))
        return x

    def is_crank_pin(self, name: str) -> bool:
        """Whether ``name`` is the crank's pin, whose plan vector the scale is chosen by."""
        cr = self.sc.mech.crank
        return name == cr.pin and self.sc.body_of(name) == cr.link

    # images -------------------------------------------------------------------------------------------
    def plan_point(self, body: str, point: str) -> complex:
        return self.images[body].at(where(self.sc, self.lay, body, point))

    def finish(self) -> None:
        """Every point by similarity; absolute vectors from the pole; labels; percent errors."""
        sc, lay = self.sc, self.lay
        for name in sc.mech.point_names():
            if sc.fixed(name):
                continue
            p = self.plan_point(sc.body_of(name), name)
            # the crank pin's vector, laid to ``crank_step`` (``scaled``), read to it: mm × μ = value
            self.entry(name, "point", p, self.exact.point(name)[self.index],
                       step=self.crank_step if self.is_crank_pin(name) else None)
            self.name_point(sub(name), p)
        for (point, body), name in sc.coincident.items():
            if body in self.images:
                X = where(sc, lay, sc.body_of(point), point)
                p = self.images[body].at(X)
                if name not in self.entries:
                    self.entry(name, "point", p, self.exact.at(body, point)[self.index - 1])
                self.name_point(sub(name), p)
        drawn: list[complex] = []
        for e in self.entries.values():
            p = e.vector / self.mu
            if e.kind == "point" and all(abs(p - q) > 1e-6 for q in drawn):
                self.absolute_items[e.key] = self.vector(
                    0j, p, "absolute", "similarity" if e.key in sc.mech.point_names() else "")
                drawn.append(p)
        self.link_figures()
        self.record.point((0.0, 0.0), role="pole", layer="vectors")
        self.group_labels()
        self.percent_errors()

    def group_labels(self) -> None:
        """One label per place: plan points closer than 1.5 mm share it ("pv, b")."""
        groups: list[tuple[complex, list[str]]] = [(0j, [self.pole])]
        for label, p in self.named.items():
            for at, names in groups:
                if abs(at - p) < 1.5:
                    if label not in names:
                        names.append(label)
                    break
            else:
                groups.append((p, [label]))
        centre = sum((p for p, _ in groups), 0j) / len(groups)
        for at, names in groups:
            toward = at - centre if abs(at - centre) > 1e-9 else -1j
            # in sight of its point: s1 at 0.3 of p_v a, set across the line p_v s2 beside it, read
            # as that line's (stop 48's V-compressor): no line between a letter and its point
            self.labels.append(LabelRequest(at, ", ".join(names), toward=toward, size=3.5, sight=True))

    def percent_errors(self) -> None:
        """error % = 100·(value − analytic)/analytic, left out (None) where the exact vector the
        entry derives from is shorter than NEAR_ZERO of the plan's largest vector or than one
        division of the ruler (``precision`` mm on the plan): no percent means anything there."""
        largest = max((e.basis for e in self.entries.values()), default=0.0)
        floor = max(NEAR_ZERO * largest, self.precision * self.mu)
        for e in self.entries.values():
            if e.basis > floor and e.analytic > 0:
                e.error_pct = 100.0 * (e.value - e.analytic) / e.analytic
