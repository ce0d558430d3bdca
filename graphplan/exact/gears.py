"""The gear mechanism's exact solution (REFERENCE §12; docs/gears.md): the closed forms every graphical
reading is compared with.

The involute pair (shifted, external): inv αw = 2(x1 + x2)·tg α/(z1 + z2) + inv α solved for αw by
Newton's method; a = m(z1 + z2)/2, aw = a·cos α/cos αw, y = (aw − a)/m, Δy = x1 + x2 − y; r = mz/2,
rb = r·cos α, rw = rb/cos αw, rf = m(z/2 − h*a − c* + x), ra = m(z/2 + h*a + x − Δy);
s = m(π/2 + 2x·tg α), sa = 2ra(s/(2r) + inv α − inv αa) with cos αa = rb/ra; p = πm, pb = p·cos α;
εα = [√(ra1² − rb1²) + √(ra2² − rb2²) − aw·sin αw]/pb.

Along the line of action N1N2 (length g = aw·sin αw), ρ1 measured from N1 and ρ2 = g − ρ1 from N2:
the contact begins at B1 where wheel 2's tip circle cuts it (ρ1 = g − √(ra2² − rb2²)) and ends at B2
on wheel 1's tip circle (ρ1 = √(ra1² − rb1²)), wheel 1 driving; P at ρ1 = rw1·sin αw. The specific
sliding λ1 = 1 − (ρ2/ρ1)(z1/z2), λ2 = 1 − (ρ1/ρ2)(z2/z1).

Quality: undercut when x < h*a − z·sin²α/2; a pointed tip when sa < 0.25m; interference when the
active profile of a wheel reaches below where the rack cut its involute: the rack's tip line meets
its line of action at ρl = r·sin α − (h*a − x)m/sin α from N (ρl < 0 is the undercut), so wheel 1
interferes when ρ1(B1) < max(ρl1, 0) — the tip of wheel 2 past N1 (ρ1(B1) < 0) included — and wheel 2
when ρ2(B2) < max(ρl2, 0).

The planetary train 2K-H by Willis' formula: type A u1H = 1 + z3/z1, type B u1H = 1 + z2·z3/(z1·z2');
with the ring fixed ωH = ω1/u1H and the planet (the block 2–2') ω2 = ωH − (ω1 − ωH)·z1/z2.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from itertools import product

import numpy as np

from graphplan.model.gears import Gears, Pair, Train
from graphplan.util.errors import GraphplanError, said_error

POINTED = 0.25              # sa ≥ 0.25·m
CONTACT_MIN = 1.2           # εα ≥ 1.2
RATIO_TOLERANCE = 0.04      # the train's ratio within ±4 %
AUTO_GRID = (-0.5, 1.2, 0.05)   # the "auto" rule's shifts: from, to, step
AUTO_RULE = "blocking-contour zone, the smallest maximum specific sliding"
AUTO_RULE_UK = "зона блокувального контуру, найменше з найбільших питомих ковзань"
Z_EXTERNAL_MIN = 17         # an external wheel of a train cut without shift (2h*a/sin²α = 17.1 at 20°)
Z_PLANET_INTERNAL_MIN = 20  # a planet meshing with the ring
Z_RING_MIN = 85             # the ring (internal) wheel cut by a shaper cutter without interference
RING_PLANET_DIFF = 8        # z3 − z2 ≥ 8: no interference of the internal pair's tips


def inv(a):
    """The involute function inv θ = tg θ − θ."""
    return np.tan(a) - a


def inv_inverse(value, tol: float = 1e-12):
    """θ with inv θ = value (value > 0) by Newton's method, d inv/dθ = tg²θ, from θ0 = ∛(3v): inv θ ≥ θ³/3
    and inv is convex, so the steps fall monotonically onto the root; iterated until a step is below
    ``tol`` rad (quadratic convergence: a handful of steps), then one more."""
    v = np.asarray(value, dtype=float)
    if np.any(~(v > 0)):
        raise said_error(GraphplanError, "gr inv", None, None, inv="inv αw")
    a = np.minimum(np.cbrt(3.0 * v), 1.55)
    for _ in range(100):
        step = (inv(a) - v) / np.tan(a) ** 2
        a = a - step
        if np.all(np.abs(step) < tol):
            break
    return a - (inv(a) - v) / np.tan(a) ** 2


@dataclass
class PairSolution:
    """The pair's geometry and quality, SI units (radians inside, degrees in ``alpha_w_deg``)."""
    pair: Pair
    x: tuple[float, float]
    alpha_w: float
    a: float
    aw: float
    y: float
    dy: float
    r: tuple[float, float]
    rb: tuple[float, float]
    rw: tuple[float, float]
    ra: tuple[float, float]
    rf: tuple[float, float]
    s: tuple[float, float]
    sa: tuple[float, float]
    p: float
    pb: float
    g: float                      # N1N2
    rho_B1: float                 # from N1
    rho_P: float
    rho_B2: float
    rho_limit: tuple[float, float]   # where the rack's cut involute begins, from N1 (wheel 1) and N2 (wheel 2)
    eps: float
    auto: dict | None = None      # the "auto" rule's record (rule, grid, the conditions' values)
    warnings: list[tuple[str, str]] = field(default_factory=list)

    @property
    def alpha_w_deg(self) -> float:
        return math.degrees(self.alpha_w)

    def sliding(self, rho1):
        """λ1, λ2 at ρ1 from N1 (NaN where a ρ is 0: ±∞)."""
        z1, z2 = self.pair.z
        r1 = np.asarray(rho1, dtype=float)
        r2 = self.g - r1
        with np.errstate(divide="ignore", invalid="ignore"):
            l1 = np.where(r1 > 1e-15 * self.g, 1.0 - (r2 / r1) * (z1 / z2), np.nan)
            l2 = np.where(r2 > 1e-15 * self.g, 1.0 - (r1 / r2) * (z2 / z1), np.nan)
        return l1, l2

    def quality(self) -> dict:
        """Each quality condition's value, its bound and whether it holds."""
        m, (z1, z2) = self.pair.module, self.pair.z
        lim = [self.pair.addendum - z * math.sin(self.pair.alpha) ** 2 / 2 for z in (z1, z2)]
        l1, _ = self.sliding(self.rho_B1)
        _, l2 = self.sliding(self.rho_B2)
        return {
            "undercut": [bool(self.x[k] < lim[k]) for k in (0, 1)], "x_min": lim,
            "pointed": [bool(self.sa[k] < POINTED * m) for k in (0, 1)],
            "interference": [bool(self.rho_B1 < max(self.rho_limit[0], 0.0)),
                             bool(self.g - self.rho_B2 < max(self.rho_limit[1], 0.0))],
            "contact_ratio_ok": bool(self.eps >= CONTACT_MIN),
            "sliding_max": [float(abs(l1)) if math.isfinite(l1) else None,
                            float(abs(l2)) if math.isfinite(l2) else None]}


def _error(en: str, uk: str) -> GraphplanError:
    """A gear scene's geometry error in both languages (``solve`` gives it the scene's language; issue
    32 item 8: a Ukrainian scene's refusal was English)."""
    return GraphplanError(en, said={"en": en, "uk": uk})


def _uk(v: float, fmt: str = "g") -> str:
    """A number as the Ukrainian text writes it (a decimal comma, a true minus)."""
    return format(v, fmt).replace(".", ",").replace("-", "−")


def pair_geometry(pair: Pair, x: tuple[float, float]) -> PairSolution:
    """The closed forms of the module docstring for the shifts ``x``."""
    (z1, z2), m, al = pair.z, pair.module, pair.alpha
    ha, c = pair.addendum, pair.clearance
    target = 2 * (x[0] + x[1]) * math.tan(al) / (z1 + z2) + float(inv(al))
    if not target > 1e-9:
        raise _error(f"gears.shifts: x1 + x2 = {x[0] + x[1]:g} is too negative for z1 + z2 = {z1 + z2}: "
                     "inv αw ≤ 0, the wheels cannot mesh",
                     f"gears.shifts: x1 + x2 = {_uk(x[0] + x[1])} надто від'ємне для z1 + z2 = {z1 + z2}: "
                     "inv αw ≤ 0, колеса не можуть зачепитися")
    aw_ = float(inv_inverse(target))
    a = m * (z1 + z2) / 2
    aw = a * math.cos(al) / math.cos(aw_)
    y = (aw - a) / m
    dy = x[0] + x[1] - y
    r = (m * z1 / 2, m * z2 / 2)
    rb = (r[0] * math.cos(al), r[1] * math.cos(al))
    rw = (rb[0] / math.cos(aw_), rb[1] / math.cos(aw_))
    rf = tuple(m * (z / 2 - ha - c + xk) for z, xk in zip((z1, z2), x))
    ra = tuple(m * (z / 2 + ha + xk - dy) for z, xk in zip((z1, z2), x))
    for k in (0, 1):
        if ra[k] <= rb[k]:
            raise _error(f"gears.shifts[{k}]: the tip circle of wheel {k + 1} (ra = {ra[k]:.6g} m) lies inside "
                         f"its base circle (rb = {rb[k]:.6g} m): no involute to mesh with",
                         f"gears.shifts[{k}]: коло вершин колеса {k + 1} (ra = {_uk(ra[k], '.6g')} м) лежить усередині "
                         f"його основного кола (rb = {_uk(rb[k], '.6g')} м): немає евольвенти для зачеплення")
    s = tuple(m * (math.pi / 2 + 2 * xk * math.tan(al)) for xk in x)
    sa = []
    for k in (0, 1):
        aa = math.acos(rb[k] / ra[k])
        sa.append(2 * ra[k] * (s[k] / (2 * r[k]) + float(inv(al)) - float(inv(aa))))
    for k in (0, 1):
        if sa[k] <= 0:
            raise _error(f"gears.shifts[{k}]: x{k + 1} = {x[k]:g} points the tooth of wheel {k + 1} below its "
                         f"tip circle (sa = {sa[k] * 1000:.3g} mm ≤ 0)",
                         f"gears.shifts[{k}]: x{k + 1} = {_uk(x[k])} загострює зуб колеса {k + 1} нижче його кола "
                         f"вершин (sa = {_uk(sa[k] * 1000, '.3g')} мм ≤ 0)")
    p = math.pi * m
    pb = p * math.cos(al)
    g = aw * math.sin(aw_)
    e1 = math.sqrt(ra[0] ** 2 - rb[0] ** 2)
    e2 = math.sqrt(ra[1] ** 2 - rb[1] ** 2)
    rho_B1, rho_B2 = g - e2, e1
    rho_P = rw[0] * math.sin(aw_)
    limit = tuple(rk * math.sin(al) - (ha - xk) * m / math.sin(al) for rk, xk in zip(r, x))
    eps = (e1 + e2 - g) / pb
    sol = PairSolution(pair, (x[0], x[1]), aw_, a, aw, y, dy, r, rb, rw, (ra[0], ra[1]), (rf[0], rf[1]),
                       (s[0], s[1]), (sa[0], sa[1]), p, pb, g, rho_B1, rho_P, rho_B2, (limit[0], limit[1]), eps)
    sol.warnings = pair_warnings(sol)
    return sol


def pair_warnings(sol: PairSolution) -> list[tuple[str, str]]:
    """What the quality conditions say, in English and Ukrainian — each number with a true minus, the
    Ukrainian with a decimal comma (``_uk``; stop 54: «x1 = -0.15», «0.2981» in the Ukrainian notes)."""
    q = sol.quality()
    out = []
    m = sol.pair.module
    en = lambda v, fmt: format(v, fmt).replace("-", "−")                  # noqa: E731
    for k in (0, 1):
        if q["undercut"][k]:
            x, lim = sol.x[k], q["x_min"][k]
            out.append((f"wheel {k + 1} is undercut: x{k + 1} = {en(x, '.4g')} < h*a − z·sin²α/2 = {en(lim, '.4g')}",
                        f"колесо {k + 1} підрізане: x{k + 1} = {_uk(x, '.4g')} < h*a − z·sin²α/2 = {_uk(lim, '.4g')}"))
        if q["pointed"][k]:
            v = sol.sa[k] / m
            out.append((f"the tooth of wheel {k + 1} is near pointed: sa{k + 1} = {en(v, '.3g')}·m < 0.25·m",
                        f"зуб колеса {k + 1} майже загострений: sa{k + 1} = {_uk(v, '.3g')}·m < 0,25·m"))
    if q["interference"][0]:
        a, b = sol.rho_B1 * 1000, max(sol.rho_limit[0], 0.0) * 1000
        out.append(("interference: the tip of wheel 2 reaches below where wheel 1's involute begins "
                    f"(ρ1 at B1 = {en(a, '.4g')} mm < {en(b, '.4g')} mm)",
                    "заклинювання: вершина колеса 2 заходить нижче початку евольвенти колеса 1 "
                    f"(ρ1 у B1 = {_uk(a, '.4g')} мм < {_uk(b, '.4g')} мм)"))
    if q["interference"][1]:
        a, b = (sol.g - sol.rho_B2) * 1000, max(sol.rho_limit[1], 0.0) * 1000
        out.append(("interference: the tip of wheel 1 reaches below where wheel 2's involute begins "
                    f"(ρ2 at B2 = {en(a, '.4g')} mm < {en(b, '.4g')} mm)",
                    "заклинювання: вершина колеса 1 заходить нижче початку евольвенти колеса 2 "
                    f"(ρ2 у B2 = {_uk(a, '.4g')} мм < {_uk(b, '.4g')} мм)"))
    if not q["contact_ratio_ok"]:
        out.append((f"the contact ratio εα = {en(sol.eps, '.4g')} is below 1.2",
                    f"коефіцієнт перекриття εα = {_uk(sol.eps, '.4g')} менший за 1,2"))
    return out


def passes(sol: PairSolution) -> bool:
    """No undercut, sa ≥ 0.25m, εα ≥ 1.2, no interference."""
    q = sol.quality()
    return not any(q["undercut"]) and not any(q["pointed"]) and not any(q["interference"]) and q["contact_ratio_ok"]


def auto_shifts(pair: Pair) -> PairSolution:
    """The "auto" rule: the blocking contour's zone of the pair — every (x1, x2) on a 0.05 grid from
    −0.5 to 1.2 where there is no undercut, sa ≥ 0.25m, εα ≥ 1.2 and no interference — and in it the
    shifts with the smallest maximum specific sliding max(|λ1(B1)|, |λ2(B2)|) (the sliding made as
    equal as the zone allows); ties to the larger εα, then the smaller x1, x2. One line naming the
    conditions that close the zone when no grid point passes."""
    lo, hi, step = AUTO_GRID
    grid = [round(lo + k * step, 10) for k in range(int(round((hi - lo) / step)) + 1)]
    best, key_best = None, None
    failing: dict[str, int] = {}
    names = ("no undercut", "sa ≥ 0.25m", "εα ≥ 1.2", "no interference")
    names_uk = dict(zip(names, ("без підрізання", "sa ≥ 0,25m", "εα ≥ 1,2", "без заклинювання")))
    tried = passing = 0
    for x1, x2 in product(grid, grid):
        try:
            sol = pair_geometry(pair, (x1, x2))
        except GraphplanError:
            continue
        tried += 1
        q = sol.quality()
        fails = [any(q["undercut"]), any(q["pointed"]), not q["contact_ratio_ok"], any(q["interference"])]
        if any(fails):
            if sum(fails) == 1:
                failing[names[fails.index(True)]] = failing.get(names[fails.index(True)], 0) + 1
            continue
        passing += 1
        smax = max(v if v is not None else math.inf for v in q["sliding_max"])
        key = (round(smax, 12), -round(sol.eps, 12), x1, x2)
        if key_best is None or key < key_best:
            best, key_best = sol, key
    if best is None:
        blocking = sorted(failing, key=lambda k: -failing[k]) or list(names)
        raise _error(f'gears.shifts: "auto" found no shifts x1, x2 from {lo:g} to {hi:g} (step {step:g}) '
                     f"for z = [{pair.z[0]}, {pair.z[1]}]: the zone is closed by {' and '.join(blocking)}",
                     f'gears.shifts: "auto" не знайшло зміщень x1, x2 від {_uk(lo)} до {_uk(hi)} (крок {_uk(step)}) '
                     f"для z = [{pair.z[0]}, {pair.z[1]}]: зону закривають умови "
                     f"{' і '.join(names_uk[b] for b in blocking)}")
    q = best.quality()
    best.auto = {"rule": AUTO_RULE, "rule_uk": AUTO_RULE_UK, "grid": [lo, hi, step], "tried": tried, "passing": passing,
                 "sliding_max": q["sliding_max"]}
    return best


def solve_pair(pair: Pair) -> PairSolution:
    """The pair with its shifts (given, or by the "auto" rule)."""
    if pair.shifts is None:
        return auto_shifts(pair)
    return pair_geometry(pair, pair.shifts)


# -- the planetary train ---------------------------------------------------------------------------

@dataclass
class TrainSolution:
    """The train's teeth, ratio, angular velocities (rad/s, + as ω1) and conditions."""
    train: Train
    z: tuple[int, ...]
    ratio: float
    omega: dict[str, float]
    conditions: dict[str, bool]
    candidates: list[dict] = field(default_factory=list)
    warnings: list[tuple[str, str]] = field(default_factory=list)
    weighed: int = 0              # how many sets met every condition (the candidates are the first of them)
    nearest: dict | None = None   # of those, the one nearest the wanted u1H (``synthesise``), when not the chosen

    @property
    def radii(self) -> dict[str, float]:
        """Pitch radii, m: 1, 2, (2'), 3, and the planets' axis (the carrier's arm) "H"."""
        m = self.train.module
        if self.train.kind == "A":
            z1, z2, z3 = self.z
            return {"1": m * z1 / 2, "2": m * z2 / 2, "3": m * z3 / 2, "H": m * (z1 + z2) / 2}
        z1, z2, z2b, z3 = self.z
        return {"1": m * z1 / 2, "2": m * z2 / 2, "2'": m * z2b / 2, "3": m * z3 / 2, "H": m * (z1 + z2) / 2}


def ratio_of(kind: str, z) -> float:
    """Willis with the ring fixed: A 1 + z3/z1, B 1 + z2·z3/(z1·z2')."""
    if kind == "A":
        return 1.0 + z[2] / z[0]
    return 1.0 + z[1] * z[3] / (z[0] * z[2])


def undercut_limits(kind: str, z) -> list[tuple[str, int, int]]:
    """The train's limits against undercut and interference (docs/gears.md, h*a = 1, α = 20°) as
    (the quantity, its value, its least): A z1 ≥ 17, z2 ≥ 20, z3 ≥ 85, z3 − z2 ≥ 8; B z1, z2 ≥ 17,
    z2' ≥ 20, z3 ≥ 85, z3 − z2' ≥ 8 — each one checked, so that a failure names the wheel (stop 54: the
    notes said only «a wheel has fewer teeth than the limits», z = [18, 36, 20, 74] printed as a list)."""
    if kind == "A":
        z1, z2, z3 = z
        return [("z1", z1, Z_EXTERNAL_MIN), ("z2", z2, Z_PLANET_INTERNAL_MIN), ("z3", z3, Z_RING_MIN),
                ("z3 − z2", z3 - z2, RING_PLANET_DIFF)]
    z1, z2, z2b, z3 = z
    return [("z1", z1, Z_EXTERNAL_MIN), ("z2", z2, Z_EXTERNAL_MIN), ("z2'", z2b, Z_PLANET_INTERNAL_MIN),
            ("z3", z3, Z_RING_MIN), ("z3 − z2'", z3 - z2b, RING_PLANET_DIFF)]


# why each limit of ``undercut_limits`` is there, (en, uk), a missed one's warning
LIMIT_WHY = {
    "z1": ("the sun 1 (external teeth) is undercut when cut without shift: 2h*a/sin²α = 17.1",
           "центральне колесо 1 (зовнішні зубці), нарізане без зміщення, підрізається: 2h*a/sin²α = 17,1"),
    "z2 B": ("the planet 2 (external teeth) is undercut when cut without shift: 2h*a/sin²α = 17.1",
             "сателіт 2 (зовнішні зубці), нарізаний без зміщення, підрізається: 2h*a/sin²α = 17,1"),
    "planet": ("the planet {p} meshes the ring: with fewer teeth the internal pair interferes",
               "сателіт {p} зачіплюється з коронним колесом: з меншим числом зубців внутрішнє зачеплення "
               "заклинюється"),
    "z3": ("the ring 3 (internal teeth) is cut by a shaper cutter without undercut and interference only "
           "from 85 teeth (h*a = 1, α = 20°)",
           "коронне колесо 3 (внутрішні зубці) довбяк нарізає без підрізання й заклинювання лише від 85 зубців "
           "(h*a = 1, α = 20°)"),
    "diff": ("the tips of the internal pair {p}–3 interfere",
             "вершини зубців внутрішньої пари {p}–3 заклинюються"),
}


def limit_warning(kind: str, name: str, value: int, least: int) -> tuple[str, str]:
    """A missed limit of ``undercut_limits`` said in English and Ukrainian: the quantity, its value
    and its least, then why (``LIMIT_WHY``)."""
    planet = "2" if kind == "A" else "2'"
    key = ("z1" if name == "z1" else "z2 B" if name == "z2" and kind == "B" else "z3" if name == "z3"
           else "diff" if "−" in name else "planet")
    en, uk = LIMIT_WHY[key]
    return (f"the no-undercut condition is not met: {name} = {value} < {least} — " + en.format(p=planet),
            f"умову без підрізання не виконано: {name} = {value} < {least} — " + uk.format(p=planet))


def teeth_text(kind: str, z, K: int) -> str:
    """The train's teeth and planets as the notes name them: «z1 = 18, z2 = 36, z2' = 20, z3 = 74, K = 3»."""
    names = ("z1", "z2", "z3") if kind == "A" else ("z1", "z2", "z2'", "z3")
    return ", ".join(f"{a} = {b}" for a, b in zip(names, z)) + f", K = {K}"


def conditions(kind: str, z, K: int, ha: float = 1.0) -> dict[str, bool]:
    """Coaxiality, assembly, neighbourhood and no undercut (docs/gears.md):
    A: z3 = z1 + 2z2; (z1 + z3)/K whole; (z1 + z2)·sin(π/K) > z2 + 2h*a;
    B: z1 + z2 = z3 − z2'; (z1·z2' + z2·z3)/(K·gcd(z2, z2')) whole; (z1 + z2)·sin(π/K) > max(z2, z2') + 2h*a;
    no undercut: the external wheels z ≥ 17, the planet meshing the ring z ≥ 20, the ring z ≥ 85, z3 − z(planet) ≥ 8."""
    if kind == "A":
        z1, z2, z3 = z
        coax = z3 == z1 + 2 * z2
        assembly = (z1 + z3) % K == 0
        neigh = (z1 + z2) * math.sin(math.pi / K) > z2 + 2 * ha if K > 1 else True
    else:
        z1, z2, z2b, z3 = z
        coax = z1 + z2 == z3 - z2b
        assembly = (z1 * z2b + z2 * z3) % (K * math.gcd(z2, z2b)) == 0
        neigh = (z1 + z2) * math.sin(math.pi / K) > max(z2, z2b) + 2 * ha if K > 1 else True
    under = all(v >= least for _, v, least in undercut_limits(kind, z))
    return {"coaxial": bool(coax), "assembly": bool(assembly), "neighbourhood": bool(neigh), "no_undercut": bool(under)}


def overall(kind: str, z) -> int:
    """The train's outer diameter in modules (the criterion): A z3; B max(z1 + 2z2, z3)."""
    return z[2] if kind == "A" else max(z[0] + 2 * z[1], z[3])


Z_SEARCH = 200      # the largest number of teeth the synthesis tries for a sun or a planet


def _ranked(kind: str, zs: np.ndarray, u: float) -> list[tuple]:
    """The sets (rows of zs) ordered by the criterion: the outer diameter in modules, then the ratio's
    distance from u, then the fewest teeth; as (diameter, distance, teeth, z) tuples."""
    if len(zs) == 0:
        return []
    zf = zs.astype(float)
    if kind == "A":
        dia = zs[:, 2]
        ratio = 1.0 + zf[:, 2] / zf[:, 0]
    else:
        dia = np.maximum(zs[:, 0] + 2 * zs[:, 1], zs[:, 3])
        ratio = 1.0 + zf[:, 1] * zf[:, 3] / (zf[:, 0] * zf[:, 2])
    dist = np.round(np.abs(ratio - u), 12)
    teeth = zs.sum(axis=1)
    order = np.lexsort(tuple(zs[:, c] for c in range(zs.shape[1] - 1, -1, -1)) + (teeth, dist, dia))
    return [(int(dia[o]), float(dist[o]), int(teeth[o]), tuple(int(v) for v in zs[o])) for o in order]


def synthesise(kind: str, u: float, K: int, ha: float = 1.0, keep: int = 8) -> tuple[tuple[int, ...], list[dict], int]:
    """The z's for the ratio ``u`` with K planets: every set meeting coaxiality, assembly, neighbourhood
    and no undercut with the ratio within ±4 %, the smallest train by its outer diameter (in modules;
    ties: the ratio nearest, then the fewest teeth). Returns the chosen z's, the first ``keep``
    candidates weighed, how many passed, and the passing set nearest ``u`` — u exactly where some set
    gives it —, the smallest of those by D/m: what the sheet names beside the chosen smallest train (stop
    55: u1H = 7,2 with K = 3 took 17, 43, 103, −1,96 %, D/m = 103; 20, 52, 124 gives 7,2 exactly, D/m = 124 —
    the notes named it only because it was among the first eight by D/m). One line naming the condition
    that fails when none passes."""
    sK = math.sin(math.pi / K) if K > 1 else 1.0
    found: list[tuple] = []
    blocked = {"ratio": 0, "assembly": 0, "neighbourhood": 0}
    if kind == "A":
        z1 = np.arange(Z_EXTERNAL_MIN, Z_SEARCH + 1)[:, None]
        z2 = np.arange(Z_PLANET_INTERNAL_MIN, Z_SEARCH + 1)[None, :]
        z3 = z1 + 2 * z2
        ratio = 1.0 + z3 / z1
        ok_r = np.abs(ratio - u) <= RATIO_TOLERANCE * u
        ok_u = (z3 >= Z_RING_MIN) & (z3 - z2 >= RING_PLANET_DIFF)
        ok_a = (z1 + z3) % K == 0
        ok_n = ((z1 + z2) * sK > z2 + 2 * ha) if K > 1 else np.ones_like(ok_r)
        ok = ok_r & ok_u & ok_a & ok_n
        blocked["ratio"] = int(np.sum(ok_r & ok_u))
        blocked["assembly"] = int(np.sum(ok_r & ok_u & ok_a))
        blocked["neighbourhood"] = int(np.sum(ok_r & ok_u & ok_n))
        i, j = np.nonzero(ok)
        zs = np.stack([z1[i, 0], z2[0, j], z3[i, j]], axis=1)
        found = _ranked(kind, zs, u)
    else:
        top = 120
        a = np.arange(Z_EXTERNAL_MIN, top + 1, dtype=np.int64)
        b = np.arange(Z_PLANET_INTERNAL_MIN, top + 1, dtype=np.int64)
        # the ratio first (one pass over the grid), the other conditions on the sets it leaves
        r3 = 1.0 + (a[None, :, None] * (a[:, None, None] + a[None, :, None] + b[None, None, :])
                    / (a[:, None, None] * b[None, None, :]).astype(float))
        i, j, k = np.nonzero(np.abs(r3 - u) <= RATIO_TOLERANCE * u)
        z1, z2, z2b = a[i], a[j], b[k]
        z3 = z1 + z2 + z2b
        ok_u = (z3 >= Z_RING_MIN) & (z3 - z2b >= RING_PLANET_DIFF)
        ok_a = (z1 * z2b + z2 * z3) % (K * np.gcd(z2, z2b)) == 0
        ok_n = ((z1 + z2) * sK > np.maximum(z2, z2b) + 2 * ha) if K > 1 else np.ones_like(ok_u)
        ok = ok_u & ok_a & ok_n
        blocked["ratio"] = int(np.sum(ok_u))
        blocked["assembly"] = int(np.sum(ok_u & ok_a))
        blocked["neighbourhood"] = int(np.sum(ok_u & ok_n))
        zs = np.stack([z1[ok], z2[ok], z2b[ok], z3[ok]], axis=1)
        found = _ranked(kind, zs, u)
    if not found:
        if blocked["ratio"] == 0:
            why = f"no teeth without undercut reach u1H = {u:g} within ±4 %"
            why_uk = f"жоден набір зубців без підрізання не дає u1H = {_uk(u)} у межах ±4 %"
        elif blocked["neighbourhood"] == 0:
            why = f"the neighbourhood condition fails for K = {K} planets on every set within ±4 % of u1H = {u:g}"
            why_uk = f"умова сусідства для K = {K} сателітів не виконується на жодному наборі в межах ±4 % від " \
                     f"u1H = {_uk(u)}"
        elif blocked["assembly"] == 0:
            why = f"the assembly condition fails for K = {K} planets on every set within ±4 % of u1H = {u:g}"
            why_uk = f"умова складання для K = {K} сателітів не виконується на жодному наборі в межах ±4 % від " \
                     f"u1H = {_uk(u)}"
        else:
            why = (f"no set within ±4 % of u1H = {u:g} meets both the assembly and the neighbourhood conditions "
                   f"for K = {K} planets")
            why_uk = (f"жоден набір у межах ±4 % від u1H = {_uk(u)} не задовольняє водночас умов складання й "
                      f"сусідства для K = {K} сателітів")
        top = Z_SEARCH if kind == "A" else 120
        raise _error(f"planetary.ratio: type {kind}: {why} (teeth tried up to {top})",
                     f"planetary.ratio: тип {kind}: {why_uk} (перебрано зубці до {top})")
    cands = [_candidate(kind, z, d, u) for d, _, _, z in found[:keep]]
    d, _, _, z = min(found, key=lambda t: (t[1], t[0], t[2], t[3]))     # the nearest u, then the smallest
    return found[0][3], cands, len(found), _candidate(kind, z, d, u)


def _candidate(kind: str, z, d: int, u: float) -> dict:
    """One weighed set as the JSON and the notes name it: its z's, D/m, u1H and its error from ``u``, %."""
    return {"z": list(z), "diameter_modules": d, "ratio": ratio_of(kind, z),
            "error_pct": 100.0 * (ratio_of(kind, z) - u) / u}


def solve_train(train: Train) -> TrainSolution:
    """The train: its z's (given, or synthesised from the ratio), u1H and every member's ω by Willis."""
    cands: list[dict] = []
    count = 0
    if train.z is None:
        assert train.ratio is not None
        z, cands, count, near = synthesise(train.kind, train.ratio, train.planets)
    else:
        z = train.z
        cond = conditions(train.kind, z, train.planets)
        if not cond["coaxial"]:
            want = (f"z3 = z1 + 2·z2 = {z[0] + 2 * z[1]}, got {z[2]}" if train.kind == "A" else
                    f"z1 + z2 = z3 − z2' needs z3 = {z[0] + z[1] + z[2]}, got {z[3]}")
            raise _error(f"planetary.z: the wheels are not coaxial (equal modules): {want}",
                         f"planetary.z: колеса не співвісні (модулі рівні): {want.replace('got', 'задано')}"
                         .replace("needs", "потребує"))
    u = ratio_of(train.kind, z)
    w1 = train.omega
    wH = w1 / u
    w2 = wH - (w1 - wH) * z[0] / z[1]
    omega = {"1": w1, "2": w2, "3": 0.0, "H": wH}
    cond = conditions(train.kind, z, train.planets)
    sol = TrainSolution(train, tuple(z), u, omega, cond, cands, weighed=count)
    if train.z is None and near["z"] != list(z) and abs(near["error_pct"]) < abs(100.0 * (u - train.ratio)
                                                                                  / train.ratio) - 1e-9:
        sol.nearest = near
    names = {"coaxial": ("the coaxiality condition fails", "не виконано умову співвісності"),
             "assembly": ("the assembly condition fails", "не виконано умову складання"),
             "neighbourhood": ("the neighbourhood condition fails", "не виконано умову сусідства")}
    teeth = teeth_text(train.kind, z, train.planets)
    for key, ok in cond.items():
        if not ok and key in names:
            en, uk = names[key]
            sol.warnings.append((f"{en} ({teeth})", f"{uk} ({teeth})"))
    sol.warnings += [limit_warning(train.kind, name, v, least) for name, v, least in undercut_limits(train.kind, z)
                     if v < least]
    if train.ratio is not None and abs(u - train.ratio) > RATIO_TOLERANCE * train.ratio:
        sol.warnings.append((f"u1H = {u:.4g} is more than 4 % from {train.ratio:g}",
                             f"u1H = {_uk(u, '.4g')} відрізняється від {_uk(train.ratio)} більш як на 4 %"))
    return sol


@dataclass
class Solution:
    """The scene's solution: the pair's and the train's (either may be None)."""
    gears: Gears
    pair: PairSolution | None
    train: TrainSolution | None


def solve(gears: Gears) -> Solution:
    """The whole scene solved; a failure is one line naming the scene."""
    try:
        pair = solve_pair(gears.pair) if gears.pair is not None else None
        train = solve_train(gears.train) if gears.train is not None else None
    except GraphplanError as exc:                    # in the scene's language where it says itself in both
        raise GraphplanError(str(exc), exc.where or gears.source, exc.said, dict(gears.meta).get("lang")) from None
    return Solution(gears, pair, train)
