"""Crank positions: the assembly check over a full turn, the output's extreme (dead-centre)
positions found exactly, and the N positions numbered from position 0 in the crank's sense."""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from graphplan.util.words import Fixed, pair_kind, said, word
from graphplan.util.errors import AssemblyError, SceneError, keyed_error, said_error
from graphplan.exact.kinematics import REACH, Kinematics, solve
from graphplan.model.mechanism import FRAME, Mechanism
from graphplan.model.structure import Structure, analyse

GRID = 1440      # the assembly check and the extreme search sample every 0.25°
LOCK_SIN = 1e-9  # a group whose direction lines cross at less than this sine locks
WARN_DEG = 10.0  # warn when a group's direction lines cross at less than this angle


@dataclass(frozen=True)
class Output:
    """The output the positions are counted from: a slide (coordinate along its guide) or a link's angle."""
    kind: str   # "slide" or "link"
    name: str

    def value(self, kin: Kinematics) -> np.ndarray:
        if self.kind == "slide":
            return kin.slides[self.name].t
        return np.unwrap(kin.bodies[self.name].theta)

    def rate(self, kin: Kinematics) -> np.ndarray:
        if self.kind == "slide":
            return kin.slides[self.name].v
        return kin.bodies[self.name].omega

    def accel(self, kin: Kinematics) -> np.ndarray:
        if self.kind == "slide":
            return kin.slides[self.name].a
        return kin.bodies[self.name].eps


@dataclass
class Study:
    """A mechanism with its structure, output and position 0: what every command starts from."""
    mech: Mechanism
    structure: Structure
    output: Output
    phi0: float                     # crank angle of position 0, deg
    extremes: tuple[float, ...]     # crank angles where the output stops, deg
    t0: dict[str, float]            # slide coordinates at position 0
    warnings: list[str] = field(default_factory=list)   # cycle-level warnings (near-locking groups)
    warnings_uk: list[str] = field(default_factory=list)  # the same in Ukrainian
    memo: dict = field(default_factory=dict, repr=False, compare=False)   # kinetostatics.own_stroke's

    def says(self, lang: str) -> list[str]:
        """The warnings in ``lang`` (util.words)."""
        return self.warnings_uk if lang == "uk" else self.warnings

    def positions(self, count: int | None = None) -> np.ndarray:
        """Crank angles of positions 0 … N−1, in the order the crank passes them (deg, [0, 360))."""
        n = count or self.mech.task.count
        step = 360.0 / n * np.sign(self.mech.omega1)
        return np.mod(self.phi0 + step * np.arange(n), 360.0)

    def solve(self, phi_deg) -> Kinematics:
        kin = solve(self.mech, self.structure, phi_deg)
        for label, ok in kin.valid.items():
            if not np.all(ok):
                bad = np.asarray(kin.phi_deg)[~ok]
                raise said_error(AssemblyError, "asm group at", self.mech.source, _lang(self.mech), label=label,
                                 phi=Fixed(float(bad[0]), 2))
        return kin

    def from_position0(self, phi_deg) -> np.ndarray:
        """Crank turn since position 0 in the crank's sense (deg, [0, 360))."""
        return np.mod((np.asarray(phi_deg) - self.phi0) * np.sign(self.mech.omega1), 360.0)


def turns(mech: Mechanism, link: str) -> bool:
    """Whether a link can turn: not a block that slides along a guide of the frame (it translates)."""
    body = mech.links[link]
    return not (body.slides_on is not None and len(body.joints) <= 1
                and mech.guides[body.slides_on].body == FRAME)


def point_slider(mech: Mechanism, point: str) -> str | None:
    """The link whose slide the point ``point`` names: one sliding on a frame guide first (a wedge
    press's ram, not the block sliding along the moving wedge — the slide the point's own name keys,
    ``exact.kinematics._prp``), else the first sliding link carrying it; None when none slides."""
    sliding = [name for name, link in mech.links.items()
               if link.slides_on is not None and next(iter(link.local)) == point]
    framed = [name for name in sliding if mech.guides[mech.links[name].slides_on].body == FRAME]
    return (framed or sliding or [None])[0]


def default_output(mech: Mechanism, structure: Structure) -> Output:
    """The scene's ``output``, else the slide a resistance force acts on (the working member, e.g. a
    slider that drives a further group), else the last group's slide on the frame, else its link
    pinned to the frame."""
    if mech.output is not None:
        # a sliding point first: a crank-slider's slider is often named after its point (link "B"
        # carrying the point B), and ``output = "B"`` means the point that slides
        for name, link in mech.links.items():
            if link.slides_on is not None and next(iter(link.local)) == mech.output:
                return Output("slide", mech.output)
        if mech.output in mech.links:
            if not turns(mech, mech.output):
                raise keyed_error(SceneError, mech.source, "positions.output", "ps output slides", _lang(mech),
                                  name=repr(mech.output))
            return Output("link", mech.output)
        raise keyed_error(SceneError, mech.source, "positions.output", "ps output neither", _lang(mech),
                          name=repr(mech.output))
    for force in mech.forces:          # the useful resistance's slide: the working member
        for link in mech.links.values():
            if (link.slides_on is not None and mech.guides[link.slides_on].body == FRAME
                    and next(iter(link.local)) == force.point):
                return Output("slide", force.point)
    for dyad in reversed(structure.dyads):
        for pair in (dyad.outer_b, dyad.outer_a):
            if pair.kind == "P" and FRAME in pair.bodies:
                return Output("slide", pair.point)
        for pair, link in ((dyad.outer_b, dyad.b), (dyad.outer_a, dyad.a)):
            if pair.kind == "R" and FRAME in pair.bodies:
                return Output("link", link)
    return Output("link", mech.crank.link)


def study(mech: Mechanism) -> Study:
    """Structure, assembly check over the full turn, extremes and position 0."""
    structure = analyse(mech)
    grid = solve(mech, structure, np.arange(GRID) * 360.0 / GRID)     # every 0.25°, for both searches
    said_ = check_assembly(mech, structure, grid)
    output = default_output(mech, structure)
    still(mech, output, grid)
    extremes = find_extremes(mech, structure, output, grid)
    phi0 = choose_start(mech, structure, output, extremes)
    kin0 = solve(mech, structure, [phi0])
    said_ += past_slot_end(mech, structure, grid, phi0)
    return Study(mech, structure, output, phi0, extremes, {k: float(s.t[0]) for k, s in kin0.slides.items()},
                 [s["en"] for s in said_], [s["uk"] for s in said_])


SLOT_MM = 0.05   # a block whose centre runs past its slotted link's drawn end by more than this (mm) is warned of


def slot_extent(mech: Mechanism, slider: str) -> tuple[str, float, str, float] | None:
    """The drawn extent of the slot a block ``slider`` slides in, when a moving link carries it: the
    link's points projected on the guide line u = Re((p − through)·e^(−iα)) in the carrier's frame, as
    (the nearest end's point, its u, the farthest end's point, its u); None for a frame guide, a
    yoke (no joint of its own) or a carrier drawn with no length along its guide (a single point)."""
    link = mech.links[slider]
    if link.slides_on is None:
        return None
    guide = mech.guides[link.slides_on]
    carrier = mech.links.get(guide.body)
    if carrier is None or not carrier.joints:        # the frame's guide; a yoke (its slot spans its block's travel)
        return None
    turn = complex(math.cos(guide.angle), -math.sin(guide.angle))
    u = {name: ((p - guide.through) * turn).real for name, p in carrier.local.items()}
    lo, hi = min(u, key=u.get), max(u, key=u.get)
    if u[hi] - u[lo] < 1e-9:
        return None
    return lo, u[lo], hi, u[hi]


def past_slot_end(mech: Mechanism, structure: Structure, kin: Kinematics, phi0: float) -> list[dict[str, str]]:
    """A block that runs past the free end of its slotted link (a rocking slotted lever O3E, E its
    end point, shorter than the block's greatest distance from O3): the mechanism still moves
    kinematically (the slot's line goes on), but the block leaves the link the scene gives — warned
    of in one line naming the link, how far (mm, with the block's greatest distance from the pivot),
    the crank angles (the grid's, 0.25°) and the positions 0 … N−1 it happens at. An end that is a
    joint is not a free end: a slot runs on through its pivot (the slotter's rotating coulisse) or past
    the rod's pin (the shaper's coulisse O…B, drawn by ``linkshape.slot_line`` out to its block).
    ``kin``: the mechanism on the GRID."""
    out = []
    grid = np.asarray(kin.phi_deg)
    n = mech.task.count
    angles = np.mod(phi0 + 360.0 / n * np.sign(mech.omega1) * np.arange(n), 360.0)
    for dyad in structure.dyads:
        for name in (dyad.a, dyad.b):
            ext = slot_extent(mech, name)
            if ext is None:
                continue
            lo_name, lo, hi_name, hi = ext
            u = _along(kin, mech, name)
            joints = mech.links[mech.guides[mech.links[name].slides_on].body].joints
            past_hi = (u - hi) * 1000.0 if hi_name not in joints else np.full(u.shape, -np.inf)
            past_lo = (lo - u) * 1000.0 if lo_name not in joints else np.full(u.shape, -np.inf)
            beyond = np.maximum(past_hi, past_lo)          # mm past a free end (E), never past a joint
            if not np.any(beyond > SLOT_MM):
                continue
            k = int(np.nanargmax(beyond))
            end, end_u = (hi_name, hi) if u[k] > hi else (lo_name, lo)
            guide = mech.guides[mech.links[name].slides_on]
            carrier = mech.links[guide.body]
            pivot = carrier.joints[0]          # O3: what |O3C| is measured from
            u0 = ((carrier.local[pivot] - guide.through) * complex(math.cos(guide.angle), -math.sin(guide.angle))).real
            reach, length = abs(u[k] - u0) * 1000.0, abs(end_u - u0) * 1000.0
            ua = _along(solve(mech, structure, angles), mech, name)
            positions = [i for i in range(n) if (ua[i] - end_u) * (1 if end == hi_name else -1) * 1000.0 > SLOT_MM]
            ranges = _runs(grid, beyond > SLOT_MM)
            out.append(said("warn past slot end", dyad=_named(dyad), block=next(iter(mech.links[name].local)),
                            link=guide.body, end=end, mm=Fixed(float(beyond[k]), 1), pivot=pivot,
                            reach=Fixed(reach, 1), length=Fixed(length, 1),
                            ranges=lambda lang, r=ranges: ", ".join(f"{deg(a, 1, lang)}–{deg(b, 1, lang)}"
                                                                    for a, b in r),
                            positions=lambda lang, q=positions: _positions_said(q, lang)))
    return out


def _positions_said(q: list[int], lang: str) -> str:
    """The lab positions a warning names: "position 0", "positions 11, 0, 1", "no lab position"."""
    if not q:
        return "жодне з положень" if lang == "uk" else "at no lab position"
    return ("положення " if lang == "uk" else "position " if len(q) == 1 else "positions ") + ", ".join(map(str, q))


def _along(kin: Kinematics, mech: Mechanism, slider: str) -> np.ndarray:
    """The block's point on its guide line, u in the carrier's frame (m; ``slot_extent``'s measure)."""
    link = mech.links[slider]
    guide = mech.guides[link.slides_on]
    body = kin.bodies[guide.body]
    x = kin.point(next(iter(link.local)))[0]
    with np.errstate(all="ignore"):
        return (((x - body.origin) / body.turn - guide.through)
                * complex(math.cos(guide.angle), -math.sin(guide.angle))).real


def _runs(grid: np.ndarray, bad: np.ndarray) -> list[tuple[float, float]]:
    """The runs of ``bad`` grid angles (wrapping round 360°) as (first, last) crank angles, deg."""
    n = len(grid)
    if np.all(bad):
        return [(0.0, float(grid[-1]))]
    start = int(np.argmin(bad))          # a good angle: every bad run is whole from here
    runs, k = [], 0
    while k < n:
        i = (start + k) % n
        if bad[i]:
            j = k
            while j < n and bad[(start + j) % n]:
                j += 1
            runs.append((float(grid[i]), float(grid[(start + j - 1) % n])))
            k = j
        k += 1
    return runs


def check_assembly(mech: Mechanism, structure: Structure, kin: Kinematics | None = None) -> list[dict[str, str]]:
    """Raise AssemblyError naming the first dyad that fails and the crank-angle ranges where it does,
    or that locks (its direction lines coincide) at some angle; return warnings for groups whose
    direction lines cross at less than ``WARN_DEG`` somewhere in the turn (each in every language).
    ``kin``: the mechanism solved at the GRID angles, if already at hand."""
    grid = np.arange(GRID) * 360.0 / GRID
    if kin is None:
        kin = solve(mech, structure, grid)
    worst_of = _worst_conditions(mech, structure, grid, kin,
                                 [d.label for d in structure.dyads if np.all(kin.valid[d.label])])
    warnings = []
    for dyad in structure.dyads:
        ok = kin.valid[dyad.label]
        if np.all(ok):
            phi, worst = worst_of[dyad.label]
            if worst < LOCK_SIN:
                raise said_error(AssemblyError, "asm locks direction", mech.source, _lang(mech), dyad=_named(dyad),
                                 phi=_angle(phi, 2))
            if dyad.kind == "RPR":
                warnings += _block_near_pivot(mech, structure, kin, dyad, grid)
            angle = math.degrees(math.asin(min(worst, 1.0)))
            if angle < WARN_DEG:
                warnings.append(said("warn near locking", dyad=_named(dyad), angle=Fixed(angle, 2),
                                     phi=Fixed(float(round(phi % 360.0, 2) % 360.0), 2)))
            continue
        far = _beyond_reach(kin, dyad)
        if np.any(far):
            raise said_error(AssemblyError, "asm beyond", mech.source, _lang(mech), dyad=_named(dyad),
                             km=f"{REACH / 1000:g}", phi=_angle(float(grid[far][0]), 2))
        if not np.any(ok):
            raise said_error(AssemblyError, "asm never", mech.source, _lang(mech), dyad=_named(dyad))
        ranges = _bad_ranges(mech, structure, dyad.label, grid, ok)
        if all((b - a) % 360.0 < 1e-3 or (a - b) % 360.0 < 1e-3 for a, b in ranges):
            raise said_error(AssemblyError, "asm locks line", mech.source, _lang(mech), dyad=_named(dyad),
                             where=lambda lang: ", ".join(deg(a, 2, lang) for a, _ in ranges))
        raise said_error(AssemblyError, "asm ranges", mech.source, _lang(mech), dyad=_named(dyad),
                         ranges=lambda lang: ", ".join(f"{deg(a, 1, lang)}–{deg(b, 1, lang)}" for a, b in ranges))
    return warnings


def _beyond_reach(kin: Kinematics, dyad) -> np.ndarray:
    """Crank angles where a group's body runs finitely beyond REACH (see kinematics._finite)."""
    far = np.zeros(kin.phi_deg.shape, dtype=bool)
    for name in (dyad.a, dyad.b):
        body = kin.bodies.get(name)
        if body is not None:
            with np.errstate(all="ignore"):
                far |= np.isfinite(body.origin) & (np.abs(body.origin) > REACH)
    return far


def _block_near_pivot(mech: Mechanism, structure: Structure, kin: Kinematics, dyad, grid) -> list[dict[str, str]]:
    """A slotted link whose block passes close to the rocker's pivot turns violently there
    (ω = v_⊥/ρ): warn when ρ falls below 5 % of its largest value. When the block passes through
    the pivot (ρ below 0.01 % of its largest value, found by refining the grid's closest angle twice,
    each time on 2001 angles about it) the slotted link's direction is undefined there and its ω
    unbounded: the mechanism locks, and the scene is refused naming the angle."""
    slider, carrier, outer_s, outer_c = dyad.block_parts

    def rho_of(k_kin):
        return np.abs(k_kin.point(outer_s.point)[0] - k_kin.point(outer_c.point)[0])

    rho = rho_of(kin)
    k = int(np.argmin(rho))
    largest = float(np.max(rho))
    if rho[k] >= 0.05 * largest:
        return []
    phi, near, step = float(grid[k]), float(rho[k]), 360.0 / len(grid)
    for _ in range(2):
        fine = phi + np.linspace(-step, step, 2001)
        fine_rho = rho_of(solve(mech, structure, fine))
        j = int(np.nanargmin(fine_rho))
        if fine_rho[j] < near:
            phi, near = float(fine[j]), float(fine_rho[j])
        step /= 1000.0
    if near < 1e-4 * largest:
        raise said_error(AssemblyError, "asm through pivot", mech.source, _lang(mech), dyad=_named(dyad),
                         block=outer_s.point, pivot=outer_c.point, phi=_angle(phi, 2),
                         mm=lambda lang: f"{near * 1000:.2g}".replace(".", "," if lang == "uk" else "."))
    w = float(np.max(np.abs(kin.bodies[carrier].omega)))
    return [said("warn block near pivot", dyad=_named(dyad), block=outer_s.point, mm=float(rho[k] * 1000),
                 pivot=outer_c.point, phi=Fixed(float(round(grid[k] % 360.0, 1) % 360.0), 1), w=w)]


def _named(dyad):
    """The dyad as a message names it, in the language asked for."""
    return lambda lang: word("dyad title", lang, label=dyad.label, kind=pair_kind(dyad.kind, lang), a=dyad.a,
                             b=dyad.b)


def deg(angle: float, digits: int = 1, lang: str = "en") -> str:
    """A crank angle as text in [0, 360): 359.99 rounds to 0.0°, never to 360.0° (a decimal comma in
    Ukrainian)."""
    text = f"{round(angle % 360.0, digits) % 360.0:.{digits}f}°"
    return text.replace(".", ",") if lang == "uk" else text


def _angle(angle: float, digits: int):
    """A crank angle for a message in either language, without its degree sign (the words add it)."""
    return lambda lang: deg(angle, digits, lang)[:-1]


def _lang(mech: Mechanism) -> str | None:
    """The scene's language (its ``lang``), what its errors speak unless --lang says otherwise."""
    return mech.task.meta.get("lang")


ZOOM = 20        # the worst transmission angle: each round samples a bracket at 2·ZOOM + 1 angles …
ROUNDS = 7       # … and narrows it ZOOM times about the least: 0.25°/20⁷ ≈ 2·10⁻¹⁰° in the end


def _worst_conditions(mech, structure, grid, kin: Kinematics, labels: list[str]) -> dict[str, tuple[float, float]]:
    """For each group in ``labels``: the crank angle and value of the smallest |sin| between its
    direction lines, refined about the grid's four lowest local minima by zooming in: each round
    samples every bracket at 2·ZOOM + 1 angles across it and narrows it ZOOM times about the least
    (a golden-section search's 40 steps narrow it 0.618⁴⁰ ≈ 4·10⁻⁹ times; ROUNDS zooms narrow it
    20⁷ ≈ 10⁹ times). Every bracket of every group at once: one solve of the mechanism a round."""
    step = grid[1] - grid[0]
    out: dict[str, tuple[float, float]] = {}
    owner, centres = [], []
    for label in labels:
        cond = kin.condition[label]
        out[label] = float(grid[int(np.argmin(cond))]), float(np.min(cond))
        lower = (cond <= np.roll(cond, 1)) & (cond <= np.roll(cond, -1))
        minima = np.flatnonzero(lower)
        minima = minima[np.argsort(cond[minima], kind="stable")][:4]
        owner += [label] * len(minima)
        centres += [float(grid[k]) for k in minima]
    if not centres:
        return out
    owner_ = np.array(owner)
    phi, value = np.array(centres), np.full(len(centres), np.inf)
    across = np.linspace(-1.0, 1.0, 2 * ZOOM + 1)
    half = step
    for _ in range(ROUNDS):
        samples = phi[:, None] + half * across[None, :]
        sampled = solve(mech, structure, samples.ravel())
        values = np.zeros(samples.shape)
        for label in dict.fromkeys(owner):
            mine = owner_ == label
            cond = np.where(sampled.valid[label], sampled.condition[label], 0.0).reshape(samples.shape)
            values[mine] = cond[mine]
        least = np.argmin(values, axis=1)
        rows = np.arange(len(phi))
        phi, value = samples[rows, least], values[rows, least]
        half /= ZOOM
    for label in out:
        mine = np.flatnonzero(owner_ == label)
        if not len(mine):
            continue
        k = mine[int(np.argmin(value[mine]))]
        if value[k] < out[label][1]:
            out[label] = float(phi[k]) % 360.0, float(value[k])
    return out


def _bad_ranges(mech, structure, label, grid, ok) -> list[tuple[float, float]]:
    """Failing intervals with their ends refined by bisection to 1e-6°."""
    def good(phi: float) -> bool:
        return bool(solve(mech, structure, [phi]).valid[label][0])

    def edge(lo: float, hi: float) -> float:  # good(lo) != good(hi)
        g_lo = good(lo)
        for _ in range(40):
            mid = 0.5 * (lo + hi)
            if good(mid) == g_lo:
                lo = mid
            else:
                hi = mid
        return 0.5 * (lo + hi)

    step = grid[1] - grid[0]
    n = len(grid)
    start = int(np.argmax(ok))  # begin the scan at a good angle so every bad run is whole
    ranges, k = [], 0
    while k < n:
        i = (start + k) % n
        if not ok[i]:
            j = k
            while j < n and not ok[(start + j) % n]:
                j += 1
            a = edge(grid[(start + k - 1) % n], grid[(start + k - 1) % n] + step)
            b = edge(grid[(start + j - 1) % n], grid[(start + j - 1) % n] + step)
            ranges.append((a % 360.0, b % 360.0))
            k = j
        k += 1
    return ranges


STILL = 1e-6    # an output travelling less than this over a turn (of the crank's length; radians) stands still


def still(mech: Mechanism, output: Output, kin: Kinematics) -> None:
    """Refuse, in one line, an output that does not move over the crank's turn (``kin``: the
    mechanism on the GRID): a slide whose travel is under ``STILL`` of the crank's length, a link
    turning through less than ``STILL`` rad — a group assembled the other way round (a knee press's
    ram put on the toggle's fixed pivot O2 by the other branch of C), whose positions, extremes and
    force charts would be noise (the path axis of a 4e-14 m stroke ran the forces sheet out of memory)."""
    travel = float(np.ptp(output.value(kin)))
    slide = output.kind == "slide"
    if travel >= (STILL * mech.crank.length if slide else STILL):
        return
    reach = f"{travel * 1000 if slide else math.degrees(travel):.1e}"
    raise keyed_error(SceneError, mech.source, "", "ps output still" if slide else "ps output still turn",
                      _lang(mech), name=output.name, table="branch",
                      reach=lambda lang: reach.replace(".", ",") if lang == "uk" else reach)


def find_extremes(mech: Mechanism, structure: Structure, output: Output,
                  kin: Kinematics | None = None) -> tuple[float, ...]:
    """Crank angles where the output's velocity changes sign, refined to the last digit (~1e-12°)
    by Newton's method kept inside each sign-change bracket of the 0.25° grid (a bisection step
    wherever Newton's would leave it): every bracket at once, one solve of the mechanism a step.
    ``kin``: the mechanism solved at the GRID angles, if already at hand (360° is 0° again)."""
    grid = np.arange(GRID + 1) * 360.0 / GRID
    if kin is None:
        kin = solve(mech, structure, grid[:-1])
    rate = output.rate(kin)
    rate = np.append(rate, rate[0])
    scale = np.max(np.abs(rate)) or 1.0
    sign = np.sign(np.where(np.abs(rate) < 1e-12 * scale, 0.0, rate))
    brackets = [(grid[k], grid[k + 1]) for k in range(GRID) if sign[k] * sign[k + 1] < 0]
    brackets += [(grid[k] - 1e-9, grid[k] + 1e-9) for k in range(GRID) if sign[k] == 0]
    if not brackets:
        return ()
    lo = np.array([b[0] for b in brackets])
    hi = np.array([b[1] for b in brackets])
    roots = _rate_roots(mech, structure, output, lo, hi)
    return tuple(sorted({round(float(r), 10) % 360.0 for r in np.mod(roots, 360.0)}))


def _rate_roots(mech: Mechanism, structure: Structure, output: Output, lo: np.ndarray, hi: np.ndarray,
                steps: int = 60) -> np.ndarray:
    """The zero of the output's rate v(φ) in each bracket [lo, hi] (a sign change): Newton's step
    φ − v/(dv/dφ), with dv/dφ = (a − v·ε₁/ω₁)/ω₁ per radian (a = dv/dt = dv/dφ·ω₁ + ∂v/∂ω₁·ε₁ and
    v ∝ ω₁), taken where it lands strictly inside the bracket, else the bracket's midpoint; the
    bracket shrinks to the side that keeps the sign change. Stops when every step or bracket is
    below 1e-12° (a Newton step that small leaves an error at the float's last digit; the angles are
    kept to 1e-10°), or after ``steps`` solves."""
    w1, e1 = mech.crank.omega, mech.crank.epsilon
    kin = solve(mech, structure, np.concatenate([lo, hi]))
    f_lo = np.split(output.rate(kin), 2)[0]
    x = 0.5 * (lo + hi)
    done = np.zeros(x.shape, dtype=bool)
    for _ in range(steps):
        kin = solve(mech, structure, x)
        v, a = output.rate(kin), output.accel(kin)
        same = np.sign(v) == np.sign(f_lo)
        lo, f_lo = np.where(same, x, lo), np.where(same, v, f_lo)
        hi = np.where(same, hi, x)
        with np.errstate(all="ignore"):
            slope = (a - v * e1 / w1) / w1 * (math.pi / 180.0)    # dv/dφ per degree
            newton = np.where(v == 0, x, x - v / slope)
        inside = np.isfinite(newton) & (newton >= lo) & (newton <= hi)
        done |= (hi - lo < 1e-12) | (np.isfinite(newton) & (np.abs(newton - x) < 1e-12))
        x = np.where(done, np.where(np.isfinite(newton) & (np.abs(newton - x) < 1e-12), newton, x),
                     np.where(inside, newton, 0.5 * (lo + hi)))
        if np.all(done):
            break
    return x


def dead_centre(mech: Mechanism, output: Output, kin: Kinematics, extremes: tuple[float, ...],
                which: str) -> float:
    """The textbook's dead centres of a slider: the inner one has the slider nearest the crank's
    pivot, the outer one farthest from it."""
    if output.kind != "slide":
        raise keyed_error(SceneError, mech.source, f"positions.start = {which!r}", "ps start inner", _lang(mech),
                          name=output.name, use='"max"/"min"')
    reach = np.abs(kin.point(output.name)[0] - mech.frame[mech.crank.pivot])   # the slider's point
    pick = np.argmin(reach) if which == "inner" else np.argmax(reach)
    return float(extremes[int(pick)])


def choose_start(mech: Mechanism, structure: Structure, output: Output,
                 extremes: tuple[float, ...]) -> float:
    """Position 0: an angle from the scene, or the extreme named by ``start``."""
    if not isinstance(mech.start, str):
        return float(mech.start)
    if len(extremes) < 2:
        raise keyed_error(SceneError, mech.source, f"positions.start = {mech.start!r}", "ps start no extremes",
                          _lang(mech), name=output.name)
    kin = solve(mech, structure, list(extremes))
    values = output.value(kin)
    hi = float(extremes[int(np.argmax(values))])
    lo = float(extremes[int(np.argmin(values))])
    if mech.start == "max":
        return hi
    if mech.start == "min":
        return lo
    if mech.start in ("inner", "outer"):
        return dead_centre(mech, output, kin, extremes, mech.start)
    start, length = working_start(mech, extremes, output.value(kin))
    if mech.start == "working":
        return start
    end = start + np.sign(mech.omega1) * length          # the working stroke's last extreme: starts the idle one
    return min(extremes, key=lambda e: abs((e - end + 180.0) % 360.0 - 180.0))


def working_start(mech: Mechanism, extremes: tuple[float, ...],
                  values) -> tuple[float, float]:
    """The crank angle of the extreme that begins the working stroke and the stroke's crank turn (°,
    in the crank's sense). The extremes split the turn into two strokes; ``positions.working_stroke``
    names the working one: "slow" (the longer crank turn), "fast", "to_min" or "to_max" (the output
    moving toward its smallest / largest value: from its largest / smallest). ``values`` are the
    output's values at ``extremes``. An extreme value reached twice (a rocker driven past its toggle
    by a coulisse swinging further: LINK51's O4D at 124,6° at φ = 42,2° and 291,5°, equal to 1 ulp)
    leaves two ways to split the turn; every tied pair is tried: "fast" takes the shortest working
    turn, the others the longest (the slow swing with the wobble between the two visits)."""
    values = np.asarray(values, dtype=float)
    tol = 1e-9 * max(1.0, float(np.ptp(values)))
    his = [float(e) for e, v in zip(extremes, values) if v >= values.max() - tol]
    los = [float(e) for e, v in zip(extremes, values) if v <= values.min() + tol]
    sense = np.sign(mech.omega1)
    rule = mech.working_stroke
    best: tuple[float, float] | None = None
    for hi in his:
        for lo in los:
            turn = float(((lo - hi) * sense) % 360.0)
            first_works = {"slow": turn >= 180.0 - 1e-9, "fast": turn < 180.0 - 1e-9,
                           "to_min": True, "to_max": False}[rule]
            start, length = (hi, turn) if first_works else (lo, 360.0 - turn)
            if best is None or (length < best[1] - 1e-9 if rule == "fast" else length > best[1] + 1e-9):
                best = (start, length)
    assert best is not None
    return best


# -- the output's motion over the turn ------------------------------------------------------------

UNWRAP = 720      # a turning link's angle is unwrapped along this fine a grid of the turn


def exact_motion(st: Study, out: Output, turn_deg: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Analytic s (from position 0), v, a of the output at the crank turns since position 0.
    A link's angle is unwrapped along the crank's turn over a fine grid as well, so a turning link
    keeps counting however coarse the divisions."""
    turn_deg = np.asarray(turn_deg, dtype=float)
    grid = np.arange(UNWRAP + 1) * 360.0 / UNWRAP if out.kind == "link" else np.empty(0)
    turns = np.concatenate(([0.0], turn_deg, grid))
    kin = st.solve(crank_angle(st, turns))
    value = out.value(kin)
    if out.kind == "link":
        order = np.argsort(turns, kind="stable")
        unwrapped = np.empty_like(value)
        unwrapped[order] = np.unwrap(value[order])
        value = unwrapped
    m = 1 + len(turn_deg)
    return value[1:m] - value[0], out.rate(kin)[1:m], out.accel(kin)[1:m]


def crank_angle(st: Study, turn_deg) -> np.ndarray:
    """Crank angle φ (deg, [0, 360)) after turning ``turn_deg`` from position 0 in the crank's sense."""
    return np.mod(st.phi0 + np.sign(st.mech.omega1) * np.asarray(turn_deg, dtype=float), 360.0)
