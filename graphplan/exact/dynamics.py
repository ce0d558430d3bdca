"""Dynamics of the machine reduced to the crank (seed 003, REFERENCE §1.8–1.9): the reduced moment
of inertia and its derivative, the reduced moment of the resistance forces, the equation of motion
with a constant driving moment or a real induction motor, its periodic steady state and the
flywheel that gives a requested coefficient of unevenness δ.

* Reduced moment of inertia (the kinetic-energy definition, seed 003 eq. 3), φ the crank's turn:
      I*_m(φ) = Σ m_i·(v_Si/ω1)² + I_Si·(ω_i/ω1)²,
      dI*_m/dφ = 2·Σ [m_i·v_Si·a_Si + I_Si·ω_i·ε_i] / (ω1²·|ω1|)
  with the velocities and accelerations of the crank turning uniformly (ε1 = 0).
* Reduced moment of the resistance forces: M*_c(φ) = −(P_G + P_F)/|ω1| — gravity and the scene's
  external forces (their stroke and profile) from kinetostatics.loads, positive where they resist.
* Equation of motion (seed 003 eq. 2), in the energy form used here:
      I*(φ)·dω/dt + ½·dI*/dφ·ω² = M*_d − M*_c   ⇔   dT/dφ = M*_d(ω) − M*_c(φ),  T = ½·I*(φ)·ω²,
  I* = I*_m + I_rotor·i² + I*_reducer + I_fl. The classical course's driving moment is constant,
  M*_d = A_c/2π (A_d = A_c over a cycle); a motor's is M*_d = i·η·(A·i·ω + B) on its working branch.
* δ = (ω_max − ω_min)/ω_m with ω_m = (ω_max + ω_min)/2.

The cycle is tabulated once (exact values, cubic splines between the output's extreme positions,
where the loads may switch), then integrated with scipy's solve_ivp (DOP853, rtol 1e-11); the
motor's steady state is found by shooting (brentq on ω(2π) − ω(0)) and each flywheel by brentq on
the simulated δ.
"""
from __future__ import annotations

import math
from bisect import bisect_right
from dataclasses import dataclass, field, replace
from functools import cached_property

import numpy as np

from graphplan.exact.kinematics import Kinematics, dot, solve
from graphplan.exact.kinetostatics import loads, output_distance, working_stroke
from graphplan.exact.positions import Study
from graphplan.model.motors import Motor, choose, latin
from graphplan.util.errors import GraphplanError, keyed_error, speaking
from graphplan.util.words import num

Array = np.ndarray
STEP_DEG = 0.25        # the cycle's table: at most this far between exact samples
STIFF = 30.0           # relaxation per radian a/(I*·ω) beyond which the motor ODE is integrated as stiff
RTOL = 1e-11           # solve_ivp's tolerances
PERIODIC = 1e-11       # the shooting's tolerance on ω(2π) − ω(0), relative
SETTLED = 1e-9         # Newton's shooting has settled once a step moves ω(0) no more than this, relative
FINE = 7200            # samples per turn for ω_max, ω_min (refined by a parabola)
DELTA_RANGE = (0.0, 0.5)


# -- the reduced quantities at given crank turns -----------------------------------------------

@dataclass
class Reduced:
    """The mechanism reduced to the crank at crank turns ``turn`` (rad from position 0, in the
    crank's sense): I*_m, dI*_m/dφ (kg·m², kg·m²/rad) and M*_c (N·m, + resisting)."""
    turn: Array
    phi_deg: Array
    inertia: Array
    d_inertia: Array
    moment: Array
    working: Array


def uniform(st: Study) -> Study:
    """The same study with the crank turning uniformly (ε1 = 0): the reduction's kinematics."""
    mech = st.mech
    if mech.crank.epsilon == 0.0:
        return st
    return replace(st, mech=replace(mech, crank=replace(mech.crank, epsilon=0.0)))


def crank_angle(st: Study, turn_rad) -> Array:
    """Crank angle φ (deg, [0, 360)) after turning ``turn_rad`` from position 0 in the crank's sense."""
    return np.mod(st.phi0 + np.sign(st.mech.omega1) * np.degrees(np.asarray(turn_rad, dtype=float)), 360.0)


def masses(st: Study) -> list[tuple[str, complex, float, float]]:
    """(link, local point of its centre of mass, m, I_S) of every link with a mass or an inertia."""
    out = []
    for name, link in st.mech.links.items():
        m, i_s = link.mass or 0.0, link.inertia or 0.0
        if m or i_s:
            com = link.com or next(iter(link.local))
            out.append((name, link.local[com], m, i_s))
    if not out:
        raise keyed_error(GraphplanError, st.mech.source, "dynamics", "dy no masses", st.mech.task.meta.get("lang"),
                          keys="mass, inertia", crank="[crank]", link="[[link]]", loads="[loads] mass_per_length")
    return out


def inertia_terms(st: Study, kin: Kinematics) -> tuple[Array, Array]:
    """I*_m = Σ m(v_S/ω1)² + I_S(ω/ω1)²  and  dI*_m/dφ = 2Σ[m v_S·a_S + I_S ω ε]/(ω1²|ω1|)."""
    w1 = st.mech.omega1
    inertia = np.zeros(kin.phi_deg.shape)
    rate = np.zeros(kin.phi_deg.shape)
    for name, local, m, i_s in masses(st):
        body = kin.bodies[name]
        _, v, a = body.at(local)
        inertia = inertia + m * np.abs(v) ** 2 / w1 ** 2 + i_s * (body.omega / w1) ** 2
        rate = rate + 2.0 * (m * dot(v, a) + i_s * body.omega * body.eps)
    return inertia, rate / (w1 ** 2 * abs(w1))


def resistance(st: Study, kin: Kinematics, working: Array) -> Array:
    """M*_c = −(P_G + P_F)/|ω1|: the power of gravity and of the external forces (kinetostatics'
    loads, their strokes and profiles) reduced to the crank; positive where it resists."""
    acting = [ld for ld in loads(st, kin, working) if ld.kind in ("gravity", "external")]
    power = sum((ld.power for ld in acting), np.zeros(kin.phi_deg.shape))
    # the loads' gross power Σ|F|·|v| + |M|·|ω| is the scale of the sum: a weight on a level guide
    # gives F·v ~ 1e-16 of it, round-off, not a resistance (it made A_c ~ 1e-17 J and a bracket error)
    gross = sum((np.abs(ld.force) * np.abs(ld.velocity) + np.abs(ld.couple * ld.omega) for ld in acting),
                np.zeros(kin.phi_deg.shape))
    power = np.where(np.abs(power) <= 1e-12 * float(np.max(gross, initial=0.0)), 0.0, power)
    return -power / abs(st.mech.omega1)


def reduce(st: Study, turn_rad, working: Array | None = None) -> Reduced:
    """I*_m, dI*_m/dφ and M*_c at the crank turns (rad from position 0). ``working`` overrides the
    stroke (at a boundary between strokes each side takes its own)."""
    su = uniform(st)
    turn = np.atleast_1d(np.asarray(turn_rad, dtype=float))
    phi = crank_angle(st, turn)
    kin = su.solve(phi)
    work = working_stroke(su, phi) if working is None else np.broadcast_to(working, phi.shape)
    inertia, rate = inertia_terms(su, kin)
    return Reduced(turn, phi, inertia, rate, resistance(su, kin, work), np.asarray(work, dtype=bool))


# -- the cycle as smooth pieces ----------------------------------------------------------------

@dataclass
class Cycle:
    """One turn tabulated exactly between ``breaks`` (rad: 0, the output's extreme positions, 2π)
    and interpolated by cubic splines inside each piece: I*_m(φ), M*_c(φ) and the resistance work
    A_c(φ) = ∫₀^φ M*_c dφ (the splines' antiderivatives)."""
    breaks: Array
    pieces: list[tuple]            # per piece: (spline I*_m, spline M*_c, A_c(φ) = its antiderivative + offset)
    work: float                    # A_c over the turn, J
    samples: Reduced               # the exact samples the splines pass through

    def _piece(self, turn: Array) -> Array:
        return np.clip(np.searchsorted(self.breaks, turn, side="right") - 1, 0, len(self.pieces) - 1)

    def _eval(self, turn, which: int) -> Array:
        if isinstance(turn, float):                 # the integrator's scalar calls: no array work
            if which < 2:
                return self.scalar(turn, which)
            k = min(max(bisect_right(self.breaks_list, turn) - 1, 0), len(self.pieces) - 1)
            return float(self.pieces[k][which](turn))
        turn = np.asarray(turn, dtype=float)
        flat = np.atleast_1d(turn).ravel()
        out = np.empty(flat.shape)
        idx = self._piece(flat)
        for k in np.unique(idx):
            sel = idx == k
            piece = self.pieces[k]
            out[sel] = piece[which](flat[sel])
        return out.reshape(np.shape(turn)) if np.ndim(turn) else float(out[0])

    @cached_property
    def breaks_list(self) -> list[float]:
        return [float(b) for b in self.breaks]

    @cached_property
    def _cubics(self) -> list[tuple[list[float], list[list[tuple[float, float, float, float]]]]]:
        """Per piece: the splines' knots and, for I*_m and M*_c, each interval's cubic coefficients
        (highest power first) — what a scalar evaluation needs, as plain floats."""
        out = []
        for si, sm, _ in self.pieces:
            knots = [float(x) for x in si.x]
            out.append((knots, [[tuple(float(v) for v in sp.c[:, j]) for j in range(sp.c.shape[1])]
                                for sp in (si, sm)]))
        return out

    def scalar(self, turn: float, which: int) -> float:
        """I*_m (``which`` 0) or M*_c (1) at one turn: the spline's cubic by Horner's rule (the
        integrator calls this some thousand times a turn)."""
        k = min(max(bisect_right(self.breaks_list, turn) - 1, 0), len(self.pieces) - 1)
        knots, coefs = self._cubics[k]
        j = min(max(bisect_right(knots, turn) - 1, 0), len(knots) - 2)
        a, b, c, d = coefs[which][j]
        x = turn - knots[j]
        return ((a * x + b) * x + c) * x + d

    def inertia(self, turn):
        return self._eval(turn, 0)

    def moment(self, turn):
        return self._eval(turn, 1)

    def resistance_work(self, turn):
        """A_c(φ) = ∫₀^φ M*_c dφ, J."""
        return self._eval(turn, 2)

    @property
    def driving(self) -> float:
        """The classical constant driving moment M*_d = A_c/2π (A_d = A_c over a cycle)."""
        return self.work / (2 * math.pi)


def breaks(st: Study) -> Array:
    """0, the output's extreme positions (where a load may switch or turn), the turns where a
    force's profile bends (the output passes one of its distances) and 2π, as crank turns."""
    turns = list(np.radians(st.from_position0(np.asarray(st.extremes, dtype=float))))
    marks = sorted({x for f in st.mech.forces for x, _ in f.profile})
    if marks:
        from scipy.optimize import brentq
        su = uniform(st)
        dist = lambda t: output_distance(su, su.solve(crank_angle(st, t)))  # noqa: E731
        grid = np.linspace(0.0, 2 * math.pi, 1441)
        values = dist(grid)
        for x in marks:
            g = values - x
            for k in np.nonzero(g[:-1] * g[1:] < 0)[0]:
                turns.append(brentq(lambda t: float(dist(np.array([t]))[0]) - x, grid[k], grid[k + 1],
                                    xtol=1e-14, rtol=1e-15))
    inner = sorted({round(float(t), 12) for t in turns if 1e-9 < t < 2 * math.pi - 1e-9})
    return np.array([0.0] + inner + [2 * math.pi])


def cycle(st: Study, step_deg: float = STEP_DEG) -> Cycle:
    """Tabulate the turn exactly and join the samples by cubic splines piece by piece."""
    from scipy.interpolate import CubicSpline
    b = breaks(st)
    pieces, all_turns, parts, start = [], [], [], 0.0
    for lo, hi in zip(b[:-1], b[1:]):
        n = max(16, int(math.ceil(math.degrees(hi - lo) / step_deg)))
        t = np.linspace(lo, hi, n + 1)
        probe = reduce(st, [0.5 * (lo + hi)])            # the stroke of this piece, at its middle
        r = reduce(st, t, working=probe.working[0])
        si, sm = CubicSpline(t, r.inertia), CubicSpline(t, r.moment)
        sa = sm.antiderivative()
        offset = start - float(sa(lo))
        pieces.append((si, sm, lambda x, sa=sa, off=offset: sa(x) + off))
        start = float(sa(hi)) + offset
        all_turns.append(t)
        parts.append(r)
    samples = Reduced(np.concatenate(all_turns), np.concatenate([p.phi_deg for p in parts]),
                      np.concatenate([p.inertia for p in parts]), np.concatenate([p.d_inertia for p in parts]),
                      np.concatenate([p.moment for p in parts]), np.concatenate([p.working for p in parts]))
    if not start > 1e-9 * 2 * math.pi * max(float(np.max(np.abs(samples.moment))), 1e-300):
        raise keyed_error(GraphplanError, st.mech.source, "dynamics", "dy no work", st.mech.task.meta.get("lang"),
                          work=float(start), force="[[force]]")
    return Cycle(b, pieces, start, samples)


# -- the steady state ------------------------------------------------------------------------------

@dataclass
class Motion:
    """A periodic steady state: ω(φ) over one turn and what it achieves."""
    turn: Array           # rad, FINE + 1 samples 0 … 2π
    omega: Array          # rad/s
    omega_max: float
    omega_min: float
    closure: float        # |ω(2π) − ω(0)|/ω_m
    inertia_constant: float   # the constant part of I* (rotor, reducer, flywheel), kg·m²
    driving: Array | None = None   # M*_d(φ) of a motor along the motion, N·m

    @property
    def mean(self) -> float:
        return 0.5 * (self.omega_max + self.omega_min)

    @property
    def delta(self) -> float:
        return (self.omega_max - self.omega_min) / self.mean


def extremes(turn: Array, values: Array) -> tuple[float, float]:
    """The largest and the smallest value of a sampled smooth periodic curve, each refined by
    the parabola through its sample and the two neighbours."""
    def refine(k: int) -> float:
        n = len(values) - 1                           # the last sample repeats the first
        y0, y1, y2 = values[(k - 1) % n], values[k], values[(k + 1) % n]
        den = y0 - 2 * y1 + y2
        if den == 0:
            return float(y1)
        s = 0.5 * (y0 - y2) / den
        return float(y1 - 0.25 * (y0 - y2) * s)
    return refine(int(np.argmax(values[:-1]))), refine(int(np.argmin(values[:-1])))


def _integrate(c: Cycle, rhs, y0, dense: bool = True, stiff: bool = False):
    """dT/dφ = rhs(φ, T) piece by piece (the loads may bend at the breaks): the end value and the
    dense solutions. ``y0`` a number (the end a number) or a list (the end a list: the state with
    its sensitivities). ``stiff``: a motor whose characteristic is steep against the machine's
    inertia (dω/dφ relaxes faster than STIFF per radian) is integrated by LSODA, which switches to
    an implicit method where it must — the explicit DOP853 would take millions of steps."""
    from scipy.integrate import solve_ivp
    sols = []
    scalar = not isinstance(y0, (list, tuple))
    y = [float(y0)] if scalar else [float(v) for v in y0]
    for lo, hi in zip(c.breaks_list[:-1], c.breaks_list[1:]):
        sol = solve_ivp(rhs, (lo, hi), y, method="LSODA" if stiff else "DOP853", rtol=RTOL, atol=RTOL * max(abs(y[0]), 1.0),
                        dense_output=dense)
        if sol.status != 0:
            return None, sols
        y = [float(v) for v in sol.y[:, -1]]
        sols.append(sol)
    return (y[0] if scalar else y), sols


def _sample(c: Cycle, sols) -> tuple[Array, Array]:
    """The dense solutions at FINE + 1 turns 0 … 2π."""
    turn = np.linspace(0.0, 2 * math.pi, FINE + 1)
    values = np.empty_like(turn)
    idx = np.clip(np.searchsorted(c.breaks, turn, side="right") - 1, 0, len(sols) - 1)
    for k, sol in enumerate(sols):
        sel = idx == k
        if np.any(sel):            # a piece shorter than a sample step holds none (scipy fails on none)
            values[sel] = sol.sol(turn[sel])[0]
    return turn, values


def energy_change(c: Cycle) -> tuple[Array, Array]:
    """ΔT(φ) = A_d − A_c = M*_d·φ − ∫M*_c dφ with the constant driving moment: the splines'
    antiderivative, FINE + 1 samples over the turn."""
    turn = np.linspace(0.0, 2 * math.pi, FINE + 1)
    return turn, c.driving * turn - c.resistance_work(turn)


def classical(c: Cycle, inertia_constant: float, omega_mean: float) -> Motion:
    """The steady state with the constant driving moment at the mean speed ω_m: every start is
    periodic (A_d = A_c), the kinetic energy at position 0 is chosen so (ω_max + ω_min)/2 = ω_m;
    ω² = 2(T0 + ΔT)/(I*_m + I_const)."""
    from scipy.optimize import brentq
    turn, dt = energy_change(c)
    total = c.inertia(turn) + inertia_constant

    def omegas(t0: float) -> Array:
        return np.sqrt(np.maximum(2 * (t0 + dt) / total, 0.0))

    def gap(t0: float) -> float:
        hi, lo = extremes(turn, omegas(t0))
        return 0.5 * (hi + lo) - omega_mean
    low = -float(np.min(dt)) + 1e-12
    high = low + float(np.max(total)) * omega_mean ** 2 * 4 + float(np.ptp(dt))
    t0 = brentq(gap, low, high, xtol=1e-14, rtol=1e-15, maxiter=200)
    w = omegas(t0)
    hi, lo = extremes(turn, w)
    return Motion(turn, w, hi, lo, abs(w[-1] - w[0]) / omega_mean, inertia_constant)


def flywheel_classical(c: Cycle, delta: float, omega_mean: float) -> float:
    """The constant reduced inertia J (rotor, reducer and flywheel together) whose steady state
    with the constant driving moment has exactly the coefficient of unevenness δ at ω_m: brentq
    on the simulated δ(J), which falls as J grows."""
    from scipy.optimize import brentq
    check_delta(delta)
    turn, dt = energy_change(c)
    span = float(np.ptp(dt))
    guess = span / (omega_mean ** 2 * delta)
    f = lambda j: classical(c, j, omega_mean).delta - delta  # noqa: E731
    lo, hi = guess * 0.25, guess * 4.0
    while f(lo) < 0:
        lo *= 0.25
    while f(hi) > 0:
        hi *= 4.0
    return brentq(f, lo, hi, xtol=1e-13 * guess, rtol=1e-14, maxiter=200)


def check_divisions(n, key: str = "--divisions", where: str | None = None) -> int:
    """The flywheel construction's divisions asked for explicitly: a whole number within
    bounds.DYNAMICS_DIVISIONS (the construction's cost grows with them; a drawing resolves no more)."""
    from graphplan.model.bounds import DYNAMICS_DIVISIONS
    lo, hi = DYNAMICS_DIVISIONS
    if isinstance(n, bool) or not isinstance(n, int) or not lo <= n <= hi:
        raise keyed_error(GraphplanError, where, key, "dy divisions", None, lo=lo, hi=hi, got=repr(n))
    return n


def bounded(st: Study) -> tuple[Study, list[tuple[str, str]]]:
    """The study the dynamics works on, and its note: the scene's [dynamics] divisions must lie
    within bounds.DYNAMICS_DIVISIONS (refused before any work); without them the construction
    divides the turn at the positions — a positions.count above the bound (the kinematics takes up
    to 3600) is clamped to it with a note, as the exact integration needs no positions at all."""
    from graphplan.model.bounds import DYNAMICS_DIVISIONS
    task = st.mech.task
    if "divisions" in task.flywheel:
        check_divisions(task.flywheel["divisions"], "dynamics.divisions", st.mech.source)
        return st, []
    hi = DYNAMICS_DIVISIONS[1]
    if task.count <= hi:
        return st, []
    task = replace(task, flywheel={**task.flywheel, "divisions": hi})
    note = (f"positions.count = {st.mech.task.count}: the flywheel construction divides the turn into {hi} "
            f"parts (1° each; a drawing resolves no finer) — set [dynamics] divisions for fewer",
            f"positions.count = {st.mech.task.count}: побудова маховика ділить оберт на {hi} частин (по 1°; "
            f"креслення тонше не розрізняє) — менше задайте в [dynamics] divisions")
    return replace(st, mech=replace(st.mech, task=task)), [note]


def check_delta(delta: float) -> None:
    if not (isinstance(delta, (int, float)) and DELTA_RANGE[0] < delta < DELTA_RANGE[1]):
        raise keyed_error(GraphplanError, None, "--delta", "dy delta", None, got=repr(delta))


# -- the motor -----------------------------------------------------------------------------------

@dataclass
class Drive:
    """A motor reduced to the crank through a reducer: M*_d(ω) = i·η·(A·i·ω + B)."""
    motor: Motor
    ratio: float                    # i = ω_motor/ω_crank
    efficiency: float
    rotor_reduced: float            # I_rotor·i², kg·m²
    reducer_reduced: float          # kg·m²
    chosen: bool                    # True: chosen by the rule, False: the scene's
    power_needed_kW: float          # P = max M*_c·ω1 / η, the rule's power
    warnings: list[tuple[str, str]] = field(default_factory=list)   # (English, Ukrainian)

    def moment(self, omega):
        """M*_d at the crank's speed ω."""
        return self.ratio * self.efficiency * self.motor.moment(self.ratio * np.asarray(omega))

    def moment_scalar(self, omega: float) -> float:
        """M*_d at one crank speed, in plain floats (the integrator's calls)."""
        a, b = self._line
        return a * omega + b

    @cached_property
    def _line(self) -> tuple[float, float]:
        """M*_d = a·ω + b on the crank: the motor's line through the reducer."""
        a, b = self.motor.line
        k = self.ratio * self.efficiency
        return k * a * self.ratio, k * b

    @property
    def moment_max(self) -> float:
        return self.ratio * self.efficiency * self.motor.moment_max

    @property
    def omega_breakdown(self) -> float:
        """The crank speed where the motor leaves its working branch."""
        return self.motor.omega_breakdown / self.ratio

    @property
    def omega_sync(self) -> float:
        return self.motor.omega_sync / self.ratio


def drive(st: Study, c: Cycle) -> Drive:
    """The scene's motor, or the catalogue's by seed 003's rule: P1 = max M*_c·ω1 on the crank,
    P1/η on the motor's shaft, the next size up of the line; the reducer's ratio i from the
    motor's rated speed and the crank's (unless the scene gives it)."""
    d = st.mech.drive
    w1 = abs(st.mech.omega1)
    needed = float(np.max(c.samples.moment)) * w1 / d.efficiency / 1000.0
    try:
        motor = d.motor or choose(needed, d.rpm_sync, st.mech.source)
    except GraphplanError as exc:
        raise speaking(exc, st.mech.task.meta.get("lang"))
    ratio = d.ratio or motor.omega_rated / w1
    rotor = motor.inertia if d.rotor_inertia is None else d.rotor_inertia
    return Drive(motor, ratio, d.efficiency, rotor * ratio ** 2, d.reducer_inertia + reducer_shafts(d, ratio),
                 d.motor is None, needed, list(d.warnings))


def reducer_shafts(d, ratio: float) -> float:
    """Seed 003 eq. 4, a reducer with one intermediate shaft reduced to the crank by its kinetic
    energy: I*_red = I_1p·(ω_motor/ω1)² + I_2p·(ω_2p/ω1)² + I_3p, ω_motor/ω1 = i, ω_2p/ω1 = i/i1."""
    i1, i2, i3 = d.shafts
    return i1 * ratio ** 2 + (i2 * (ratio / d.first_stage) ** 2 if i2 else 0.0) + i3


def _stiff(c: Cycle, dr: Drive, const: float) -> bool:
    """Whether the motor ODE is stiff: the relaxation of ω per radian, a/(I*·ω), with the
    characteristic's slope a on the crank, the smallest reduced inertia and the synchronous speed."""
    a = dr.ratio * dr.efficiency * abs(dr.motor.line[0]) * dr.ratio
    smallest = float(np.min(c.inertia(np.linspace(0.0, 2 * math.pi, 361)))) + const
    return a / (smallest * dr.omega_sync) > STIFF


def _periodic_start(c: Cycle, dr: Drive, const: float, guess: float | None) -> float | None:
    """ω(0) of the motor's periodic steady state by Newton's method on T(2π) − T(0) = 0, the
    derivative ∂T(2π)/∂T(0) integrated alongside (dS/dφ = a·S/(I*·ω), M*_d = a·ω + b): a few
    integrations. None when it does not settle (then the bracketing search decides). It has settled
    once a step moves ω(0) by no more than SETTLED of it: Newton's next error is about the square of
    that step, below the integration's own noise (rtol 1e-11: the steps then jitter by 1e-11…4e-11 of
    ω). The stop at 1e-12 waited for a lucky jitter — LINK57's flywheel search fell back to the
    bracketing (~20 integrations instead of 2–3) in 12 of its 16 steady states (stop 58)."""
    a = dr.ratio * dr.efficiency * dr.motor.line[0] * dr.ratio        # dM*_d/dω on the crank
    i0 = c.inertia(0.0) + const

    def rhs(t, y):
        inertia = c.scalar(t, 0) + const
        w = math.sqrt(max(2 * y[0] / inertia, 1e-300))
        return [dr.moment_scalar(w) - c.scalar(t, 1), a * y[1] / (inertia * w)]
    w0 = guess if guess and guess > 0 else dr.omega_sync * 0.98
    stiff = _stiff(c, dr, const)
    for _ in range(12):
        t0 = 0.5 * i0 * w0 * w0
        end, _ = _integrate(c, rhs, [t0, 1.0], dense=False, stiff=stiff)
        if end is None or end[0] <= 0 or not all(math.isfinite(v) for v in end):
            return None
        gap = end[0] - t0
        slope = end[1] - 1.0
        if slope == 0:
            return None
        t_new = t0 - gap / slope
        if t_new <= 0:
            return None
        w_new = math.sqrt(2 * t_new / i0)
        if abs(w_new - w0) <= SETTLED * w0:
            return w_new
        w0 = w_new
    return None


def motor_motion(c: Cycle, dr: Drive, flywheel: float, guess: float | None = None) -> Motion:
    """The periodic steady state with the motor: ω(0) such that ω(2π) = ω(0) to 1e-11 relative —
    by Newton's method from ``guess`` (or the motor's working speed), else by bracketing (brentq on
    ω(2π) − ω(0)) — of dT/dφ = M*_d(ω) − M*_c(φ), ω = √(2T/I*)."""
    from scipy.optimize import brentq
    const = dr.rotor_reduced + dr.reducer_reduced + flywheel

    def rhs(t, y):
        w = math.sqrt(max(2 * y[0] / (c.scalar(t, 0) + const), 0.0))
        return [dr.moment_scalar(w) - c.scalar(t, 1)]

    i0 = c.inertia(0.0) + const
    stiff = _stiff(c, dr, const)

    def ret(w0: float) -> float:
        end, _ = _integrate(c, rhs, 0.5 * i0 * w0 ** 2, dense=False, stiff=stiff)
        if end is None or end <= 0:
            return -w0
        return math.sqrt(2 * end / i0) - w0
    hi = dr.omega_sync
    lo = max(dr.omega_breakdown, 1e-3 * hi)
    w0 = _periodic_start(c, dr, const, guess)
    if w0 is None or not lo < w0:
        if ret(lo) <= 0:
            raise keyed_error(GraphplanError, None, "dynamics", "dy motor slows", None, name=latin(dr.motor.name),
                              power=float(dr.motor.power_kW), ratio=float(dr.ratio))
        while ret(hi) > 0:                # above ω_c at position 0: the motor brakes there (generator)
            hi *= 1.05
        w0 = brentq(ret, lo, hi, xtol=PERIODIC * hi, rtol=1e-15, maxiter=200)
    end, sols = _integrate(c, rhs, 0.5 * i0 * w0 ** 2, stiff=stiff)
    turn, energy = _sample(c, sols)
    w = np.sqrt(2 * energy / (c.inertia(turn) + const))
    hi_w, lo_w = extremes(turn, w)
    return Motion(turn, w, hi_w, lo_w, abs(w[-1] - w[0]) / (0.5 * (hi_w + lo_w)), const, dr.moment(w))


def flywheel_motor(c: Cycle, dr: Drive, delta: float, guess: float) -> float:
    """The flywheel (beyond rotor and reducer) that gives δ with the motor; 0 when the motor's
    own slope and the rotor already keep δ below the request. Brent's method on the simulated δ(J),
    which falls as J grows, in a bracket found by steps out from the classical flywheel (each
    steady state started from the last one's ω(0))."""
    return _flywheel_motor(c, dr, delta, guess)[0]


def _flywheel_motor(c: Cycle, dr: Drive, delta: float, guess: float) -> tuple[float, dict[float, Motion]]:
    """``flywheel_motor`` and the steady states it simulated, by J (each J once: the bracket's
    ends were simulated again by brentq before, stop 58)."""
    from scipy.optimize import brentq
    last: dict[str, float | None] = {"w0": None}
    seen: dict[float, Motion] = {}

    def f(j: float) -> float:
        if j not in seen:
            seen[j] = motor_motion(c, dr, j, last["w0"])
            last["w0"] = float(seen[j].omega[0])
        return seen[j].delta - delta
    if f(0.0) <= 0:
        return 0.0, seen
    g = max(guess, 1e-6)
    fg = f(g)
    step = 0.05 * g
    if fg > 0:                                   # the root is above the guess
        a, b = g, g + step
        while f(b) > 0:
            a, step = b, step * 2.0
            b = a + step
    else:                                        # … or below it
        a, b = max(g - step, 0.0), g
        while a > 0 and f(a) < 0:
            b, step = a, step * 2.0
            a = max(a - step, 0.0)
    # to 1e-8 of the guess: δ(J) is simulated to ~1e-10 (ω's extremes off 7200 samples), so J to ~3e-9
    # of itself at best — the search's last steps to 1e-10 wandered in that noise (LINK57: 6 of its 16
    # steady states, stop 58); the sheets print J to 4 digits
    return brentq(f, a, b, xtol=1e-8 * g, rtol=1e-12, maxiter=200), seen


def carries(dr: Drive, m: Motion) -> None:
    """The motor carries the cycle: its moment stays below M_max and its speed on the working
    branch (above ω_k) all the turn; otherwise one line, exit 2."""
    peak = float(np.max(dr.moment(m.omega)))
    if peak > dr.moment_max or m.omega_min < dr.omega_breakdown:
        raise keyed_error(GraphplanError, None, "dynamics", "dy motor moment", None, name=latin(dr.motor.name),
                          moment=float(peak / (dr.ratio * dr.efficiency)), max=float(dr.motor.moment_max))


# -- the whole exact part ----------------------------------------------------------------------------

@dataclass
class Dynamics:
    """Everything exact: the cycle, the flywheel for δ (classical), its motion, and the motor's."""
    study: Study
    cycle: Cycle
    delta: float
    omega_mean: float
    drive: Drive
    flywheel_total: float          # J that gives δ (classical), kg·m²: I_rotor·i² + I_reducer + I_fl when ≥ them
    motion: Motion                 # classical steady state with J
    motor_flywheel: float          # I_fl with the motor, kg·m²
    motor_motion: Motion
    warnings: list[tuple[str, str]] = field(default_factory=list)   # (English, Ukrainian)

    @property
    def constant(self) -> float:
        """The constant reduced inertia without a flywheel: rotor and reducer."""
        return self.drive.rotor_reduced + self.drive.reducer_reduced

    @property
    def flywheel(self) -> float:
        """The flywheel's own moment of inertia (classical): J − rotor − reducer, or 0 when the
        rotor and the reducer alone keep δ below the request (``needs_flywheel`` is False) — a
        moment of inertia is never negative."""
        return max(self.flywheel_total - self.constant, 0.0)

    @property
    def needs_flywheel(self) -> bool:
        """Whether δ asks for more inertia than the rotor and the reducer give."""
        return self.flywheel_total > self.constant

    @property
    def underpowered(self) -> bool:
        """The scene's motor is weaker than the power rule asks (P_n < max M*_c·ω1/η)."""
        return self.drive.motor.power_kW < self.drive.power_needed_kW


def analyse(st: Study, delta: float | None = None) -> Dynamics:
    """The exact dynamics of the scene: δ from the argument, else the scene's [dynamics] delta,
    else 0.04."""
    delta = float(st.mech.task.flywheel.get("delta", 0.04)) if delta is None else delta
    check_delta(delta)
    st, notes = bounded(st)
    c = cycle(st)
    wm = abs(st.mech.omega1)
    dr = drive(st, c)
    total = flywheel_classical(c, delta, wm)
    # the steady state with the exact flywheel: I_fl = 0 where rotor and reducer already exceed J
    motion = classical(c, max(total, dr.rotor_reduced + dr.reducer_reduced), wm)
    fm, seen = _flywheel_motor(c, dr, delta, max(total - dr.rotor_reduced - dr.reducer_reduced, 0.0))
    # the steady state at the root: the search's own where it simulated the root, else from its ω(0) nearest
    near = min(seen, key=lambda j: abs(j - fm)) if seen else None
    mm = seen[fm] if fm in seen else motor_motion(c, dr, fm, float(seen[near].omega[0]) if near is not None else None)
    carries(dr, mm)
    warnings = list(dr.warnings) + notes
    const = dr.rotor_reduced + dr.reducer_reduced
    if total <= const:
        warnings.append((f"the rotor and the reducer ({const:.4g} kg·m²) exceed the inertia δ = {delta:g} needs "
                         f"({total:.4g} kg·m²): no flywheel is needed, I_fl = 0",
                         f"ротор і редуктор ({num(const, 'uk')} кг·м²) більші за момент інерції, потрібний для "
                         f"δ = {num(delta, 'uk')} ({num(total, 'uk')} кг·м²): маховик не потрібен, I_мах = 0"))
    if dr.motor.power_kW < dr.power_needed_kW:
        warnings.append((f"the motor {latin(dr.motor.name)} ({dr.motor.power_kW:g} kW) is below the power rule "
                         f"P = max M*_c·ω1/η = {dr.power_needed_kW:.4g} kW",
                         f"двигун {dr.motor.name} ({num(dr.motor.power_kW, 'uk')} кВт) слабший, ніж вимагає "
                         f"правило потужності P = M^*_{{с max}}·ω_1/η = {num(dr.power_needed_kW, 'uk')} кВт"))
    mean_moment = float(np.mean(mm.driving[:-1])) / (dr.ratio * dr.efficiency)
    if mean_moment > dr.motor.moment_rated:
        warnings.append((f"the motor {latin(dr.motor.name)} works above its rated moment on average "
                         f"({mean_moment:.3g} > {dr.motor.moment_rated:.3g} N·m): it will overheat",
                         f"двигун {dr.motor.name} у середньому працює з моментом, більшим за номінальний "
                         f"({num(mean_moment, 'uk', 3)} > {num(dr.motor.moment_rated, 'uk', 3)} Н·м): "
                         "він перегріватиметься"))
    return Dynamics(st, c, delta, wm, dr, total, motion, fm, mm, warnings)
