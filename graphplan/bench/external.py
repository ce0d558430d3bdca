"""graphplan's analytic solver side by side with two other open packages, where installed.

* ``pylinkage`` (PyPI 1.3.0): a crank stepped by a fixed angle per step, each dyad solved in closed
  form (circle ∩ circle, circle ∩ line) and the root nearest the joint's previous position kept;
  velocities and accelerations by the closed-form derivatives (``Linkage.step_with_derivatives``).
* ``mechanism`` (PyPI 1.1.10): the vector loop r_a + r_b − r_c − r_d = 0 solved by
  ``scipy.optimize.fsolve`` at every crank angle, each solve started from the previous root; the
  velocity and acceleration loops (linear in the unknowns) by fsolve too.

Both model the same N crank angles as ``positions.study(...).positions(N)`` (position 0 onward,
in the crank's sense) on the assembly the scene's ``[branch]`` chooses: the other packages only
take a starting point, so both are started from the inner joint's position 0 on that assembly
(``Case.start``, by the textbook construction). Started from a rough point merely on the right
side, fsolve landed on the other assembly for 3 of 82 random crank-rockers; pylinkage's
nearest-root rule jumped to the other assembly in one of them at N = 36 (10° steps), where the
two roots come close. A row whose results disagree says so in its note.

``external_rows`` returns one row per method and setting with the best-of-``repeats`` wall
time (model built outside the timer, one untimed warm-up run first), the disagreement with
graphplan, and the time as a ratio to graphplan's ``Study.solve`` of the same angles (which
always computes positions, velocities and accelerations together). A package that is absent
gives rows whose note is "not installed". The packages are imported lazily: neither is a
dependency of graphplan.
"""
from __future__ import annotations

import importlib
import math
import time
import warnings
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from graphplan.exact import positions
from graphplan.model import scene
from graphplan.model.mechanism import FRAME

EXAMPLES_DIR = Path(__file__).resolve().parents[2] / "examples"
PACKAGES = ("pylinkage", "mechanism")
POSITIONS = "positions"
ALL = "positions+velocities+accelerations"
MISMATCH_PCT = 1e-3  # above this a row is flagged: another branch, or a solver that failed


@dataclass(frozen=True)
class Case:
    """A crank with one class-II dyad (RRR to a frame pivot, or RRP on a frame guide), as the
    other packages model it. Points are complex x + iy in metres; angles in degrees."""
    example: str
    kind: str                  # "RRR" or "RRP"
    pivot: complex             # the crank's frame pivot O
    r: float                   # crank length OA
    omega: float               # ω1, rad/s, + counter-clockwise
    epsilon: float             # ε1, rad/s²
    la: float                  # A–B (connecting rod / coupler)
    ground: complex            # RRR: the rocker's frame pivot; RRP: a point of the guide
    lb: float                  # RRR: the rocker O2–B; RRP: unused (0)
    guide_angle: float         # RRP: the guide's direction, rad; RRR: unused (0)
    branch: int                # +1 / −1 as the scene's [branch] means it
    pin: str                   # the crank pin's name ("A")
    inner: str                 # the dyad's inner joint ("B")
    phi_deg: np.ndarray        # the N crank angles, position 0 first

    @property
    def step(self) -> float:
        """Crank turn between consecutive positions, rad, signed like ω1."""
        return math.copysign(2 * math.pi / len(self.phi_deg), self.omega)

    def pin_at(self, phi_deg: float) -> complex:
        return self.pivot + self.r * np.exp(1j * math.radians(phi_deg))

    def start(self) -> complex:
        """The inner joint at position 0 on the scene's assembly, by the textbook construction —
        the starting point handed to the other packages (they only keep the root nearest to it,
        or start their iteration from it). RRR: circle (A, la) ∩ circle (O2, lb), left of A→O2
        for branch +1; RRP: circle (A, la) ∩ the guide, ahead of A's foot for branch +1."""
        a = self.pin_at(float(self.phi_deg[0]))
        if self.kind == "RRR":
            span = self.ground - a
            dist = abs(span)
            along = (dist ** 2 + self.la ** 2 - self.lb ** 2) / (2 * dist)
            height = math.sqrt(max(self.la ** 2 - along ** 2, 0.0))
            return a + (along + 1j * self.branch * height) * span / dist
        g = np.exp(1j * self.guide_angle)
        foot = float(np.real((a - self.ground) * np.conj(g)))
        across = float(np.imag((a - self.ground) * np.conj(g)))
        return self.ground + (foot + self.branch * math.sqrt(max(self.la ** 2 - across ** 2, 0.0))) * g


class Unsupported(ValueError):
    """A mechanism this comparison does not translate (more than one dyad, other kinds)."""


def case_of(study: positions.Study, example: str, n_positions: int) -> Case:
    """Reduce a graphplan study to a Case; Unsupported unless it is crank + one RRR or RRP."""
    mech, dyads = study.mech, study.structure.dyads
    if len(dyads) != 1 or dyads[0].kind not in ("RRR", "RRP"):
        raise Unsupported(f"{example}: only a crank with one RRR or RRP dyad is compared")
    d, crank = dyads[0], mech.crank
    if d.outer_a.point != crank.pin or crank.link not in d.outer_a.bodies:
        raise Unsupported(f"{example}: the dyad is not driven by the crank pin")
    link_a = mech.links[d.a]
    la = abs(link_a.local[d.inner.point] - link_a.local[crank.pin])
    branch = mech.branches.get(d.key, 1)
    common = dict(example=example, kind=d.kind, pivot=mech.frame[crank.pivot], r=crank.length,
                  omega=crank.omega, epsilon=crank.epsilon, la=la, branch=branch, pin=crank.pin,
                  inner=d.inner.point, phi_deg=study.positions(n_positions))
    if d.kind == "RRR":
        if FRAME not in d.outer_b.bodies:
            raise Unsupported(f"{example}: the rocker is not pinned to the frame")
        link_b = mech.links[d.b]
        lb = abs(link_b.local[d.inner.point] - link_b.local[d.outer_b.point])
        return Case(ground=mech.frame[d.outer_b.point], lb=lb, guide_angle=0.0, **common)
    guide = mech.guides[d.outer_b.guide]
    if guide.body != FRAME or d.outer_b.slider != d.b or d.outer_b.point != d.inner.point:
        raise Unsupported(f"{example}: the slider's guide is not on the frame")
    return Case(ground=guide.through, lb=0.0, guide_angle=guide.angle, **common)


@dataclass(frozen=True)
class Motion:
    """Positions (and, maybe, velocities, accelerations) of the pin and the inner joint: (2, N) complex."""
    pos: np.ndarray
    vel: np.ndarray | None = None
    acc: np.ndarray | None = None
    note: str = ""


# -- graphplan -----------------------------------------------------------------------------------

def graphplan_motion(study: positions.Study, case: Case) -> Motion:
    kin = study.solve(case.phi_deg)
    pv = [kin.point(name) for name in (case.pin, case.inner)]
    return Motion(*(np.array([p[k] for p in pv]) for k in range(3)))


# -- pylinkage -----------------------------------------------------------------------------------

def pylinkage_model(case: Case):
    """Ground, crank and dyad; the crank starts one step before position 0 (step() moves first)."""
    import pylinkage as pl
    o = pl.Ground(case.pivot.real, case.pivot.imag, name="O")
    crank = pl.Crank(anchor=o, radius=case.r, angular_velocity=case.step,
                     initial_angle=math.radians(float(case.phi_deg[0])) - case.step, name=case.pin)
    h = case.start()
    if case.kind == "RRR":
        o2 = pl.Ground(case.ground.real, case.ground.imag, name="O2")
        dyad = pl.RRRDyad(crank.output, o2, distance1=case.la, distance2=case.lb,
                          x=h.real, y=h.imag, name=case.inner)
        parts = [o, o2, crank, dyad]
    else:
        g = case.ground + np.exp(1j * case.guide_angle)
        l1 = pl.Ground(case.ground.real, case.ground.imag, name="G1")
        l2 = pl.Ground(g.real, g.imag, name="G2")
        dyad = pl.RRPDyad(crank.output, l1, l2, distance=case.la, x=h.real, y=h.imag, name=case.inner)
        parts = [o, l1, l2, crank, dyad]
    linkage = pl.Linkage(parts, name=case.example)
    linkage.set_input_velocity(crank, omega=case.omega, alpha=case.epsilon)
    return linkage, (parts.index(crank), parts.index(dyad))


def _pairs(rows, idx) -> np.ndarray:
    """[(x, y) per component] per step → (2, N) complex for the components idx."""
    xy = np.array([[row[i] for i in idx] for row in rows], dtype=float)  # (N, 2, 2)
    return (xy[..., 0] + 1j * xy[..., 1]).T


def pylinkage_step(model, n: int) -> Motion:
    linkage, idx = model
    return Motion(_pairs(list(linkage.step(iterations=n)), idx))


def pylinkage_step_fast(model, n: int) -> Motion:
    linkage, idx = model
    xy = linkage.step_fast(iterations=n)[:, list(idx), :]
    return Motion((xy[..., 0] + 1j * xy[..., 1]).T)


def pylinkage_derivatives(model, n: int) -> Motion:
    linkage, idx = model
    out = list(linkage.step_with_derivatives(iterations=n))
    return Motion(*(_pairs([o[k] for o in out], idx) for k in range(3)))


# -- mechanism (vector loops and fsolve) ---------------------------------------------------------

def mechanism_model(case: Case, derivatives: bool):
    """Vectors a = OA (input angle), b = AB (unknown angle), c = O2B (unknown angle) or GB (unknown
    length along the guide), d = OO2 / OG fixed; loop a + b − c − d = 0. The package puts its
    origin joint at (0, 0), so the frame is shifted by O."""
    from mechanism import Mechanism, Vector, get_joints
    o, a, b, g = get_joints(f"O {case.pin} {case.inner} G")
    d_vec = case.ground - case.pivot
    va = Vector((o, a), r=case.r)
    vb = Vector((a, b), r=case.la)
    vd = Vector((o, g), r=abs(d_vec), theta=float(np.angle(d_vec)), show=False)
    h = case.start() - case.pivot
    a0 = case.pin_at(float(case.phi_deg[0])) - case.pivot
    if case.kind == "RRR":
        vc = Vector((g, b), r=case.lb)
        guess = [np.angle(h - a0), np.angle(h - d_vec)]
    else:
        vc = Vector((g, b), theta=case.guide_angle)
        guess = [np.angle(h - a0), float(np.real((h - d_vec) * np.exp(-1j * case.guide_angle)))]

    def loops(x, inp):
        return va(inp) + vb(x[0]) - vc(x[1]) - vd()

    n = len(case.phi_deg)
    phi = math.radians(float(case.phi_deg[0])) + case.step * np.arange(n)
    kw = dict(vectors=(va, vb, vc, vd), origin=o, loops=loops, pos=phi)
    if derivatives:
        kw.update(vel=np.full(n, case.omega), acc=np.full(n, case.epsilon),
                  guess=(np.array(guess), np.zeros(2), np.zeros(2)))
    else:
        kw.update(guess=(np.array(guess),))
    return Mechanism(**kw), (a, b), case.pivot


def mechanism_run(model, n: int) -> Motion:
    mech, joints, shift = model
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", RuntimeWarning)
        mech.iterate()
    stalled = sum(1 for w in caught if "iteration" in str(w.message) or "calls to function" in str(w.message))
    note = f"fsolve did not converge (×{stalled})" if stalled else ""
    pos = np.array([j.x_positions + 1j * j.y_positions for j in joints]) + shift
    if mech.vel is None:
        return Motion(pos, note=note)
    vel = np.array([j.x_velocities + 1j * j.y_velocities for j in joints])
    acc = np.array([j.x_accelerations + 1j * j.y_accelerations for j in joints])
    return Motion(pos, vel, acc, note)


# -- measuring -----------------------------------------------------------------------------------

def disagreement(ext: Motion, ref: Motion, crank: float) -> dict[str, float | None]:
    """Max |Δ| over the pin and the inner joint: positions in % of the crank length; velocities
    and accelerations in % of that joint's largest magnitude over the N positions."""
    def pct(x, y, scale) -> float:
        err = np.abs(x - y).max(axis=1) / scale * 100.0
        return float(err.max()) if np.all(np.isfinite(err)) else math.inf

    out: dict[str, float | None] = {"pos_error_pct": pct(ext.pos, ref.pos, crank),
                                    "vel_error_pct": None, "acc_error_pct": None}
    if ext.vel is not None:
        out["vel_error_pct"] = pct(ext.vel, ref.vel, np.abs(ref.vel).max(axis=1))
        out["acc_error_pct"] = pct(ext.acc, ref.acc, np.abs(ref.acc).max(axis=1))
    return out


def best_time(build: Callable[[], object], run: Callable[[object], Motion],
              repeats: int) -> tuple[float, float, Motion]:
    """(best, first, result): a warm-up run (its time is ``first``), then the best of ``repeats``
    timed runs, each on a freshly built model; building is outside the timer."""
    times, result = [], None
    for _ in range(repeats + 1):
        model = build()
        t0 = time.perf_counter()
        result = run(model)
        times.append(time.perf_counter() - t0)
    return min(times[1:]), times[0], result


def installed(package: str) -> tuple[bool, str]:
    """(available, version) — ``mechanism`` must be the vector-loop package (Vector, Mechanism)."""
    try:
        mod = importlib.import_module(package)
    except Exception:  # noqa: BLE001 — a broken install counts as absent
        return False, ""
    if package == "mechanism" and not all(hasattr(mod, n) for n in ("Vector", "Mechanism")):
        return False, ""
    from importlib.metadata import PackageNotFoundError, version
    try:
        return True, version(package)
    except PackageNotFoundError:
        return True, getattr(mod, "__version__", "")


@dataclass(frozen=True)
class Method:
    package: str
    label: str          # how the package is driven
    quantities: str     # POSITIONS or ALL
    build: Callable[[Case], object]
    run: Callable[[object, int], Motion]


def methods() -> list[Method]:
    return [
        Method("pylinkage", "Linkage.step", POSITIONS, pylinkage_model, pylinkage_step),
        Method("pylinkage", "Linkage.step_fast", POSITIONS, pylinkage_model, pylinkage_step_fast),
        Method("pylinkage", "Linkage.step_with_derivatives", ALL, pylinkage_model, pylinkage_derivatives),
        Method("mechanism", "Mechanism.iterate, fsolve", POSITIONS,
               lambda c: mechanism_model(c, False), mechanism_run),
        Method("mechanism", "Mechanism.iterate, fsolve", ALL,
               lambda c: mechanism_model(c, True), mechanism_run),
    ]


def _row(method: str, example: str, quantities: str, n: int, how: str, **fields) -> dict:
    row = {"method": method, "setting": f"{example} {quantities} N={n} ({how})", "example": example,
           "quantities": quantities, "n_positions": n, "time_s": None, "max_error_pct": None,
           "ratio_to_graphplan": None, "note": "", "first_call_s": None, "pos_error_pct": None,
           "vel_error_pct": None, "acc_error_pct": None, "version": ""}
    row.update(fields)
    return row


def _quirks(package: str, label: str) -> str:
    if package == "pylinkage":
        from pylinkage._numba_compat import HAS_NUMBA
        jit = "numba" if HAS_NUMBA else "pure Python (numba absent)"
        return f"{label}, {jit}; keeps the root nearest the previous position"
    return f"{label}; each solve started from the previous root"


def compare(study: positions.Study, example: str, n_positions: int = 360, repeats: int = 5,
            packages: Sequence[str] = PACKAGES) -> list[dict]:
    """The rows of one study: graphplan's, then each way of driving each package."""
    try:
        case = case_of(study, example, n_positions)
    except Unsupported as exc:
        return [_row("graphplan", example, ALL, n_positions, "Study.solve", note=f"not compared: {exc}")]
    best, first, ref = best_time(lambda: None, lambda _: graphplan_motion(study, case), repeats)
    rows = [_row("graphplan", example, ALL, n_positions, "Study.solve", time_s=best, first_call_s=first,
                 max_error_pct=0.0, ratio_to_graphplan=1.0, pos_error_pct=0.0, vel_error_pct=0.0,
                 acc_error_pct=0.0, version="",
                 note="closed-form dyads, vectorised over the angles (the reference)")]
    have = {p: installed(p) for p in packages}
    for m in methods():
        if m.package not in have:
            continue
        ok, ver = have[m.package]
        if not ok:
            rows.append(_row(m.package, example, m.quantities, n_positions, m.label, note="not installed"))
            continue
        try:
            t, t1, motion = best_time(lambda: m.build(case), lambda mod: m.run(mod, n_positions), repeats)
        except Exception as exc:  # noqa: BLE001 — another package's failure is a result, not a crash
            rows.append(_row(m.package, example, m.quantities, n_positions, m.label, version=ver,
                             note=f"failed: {type(exc).__name__}: {' '.join(str(exc).split())}"))
            continue
        err = {k: (None if v is None or math.isinf(v) else v)
               for k, v in disagreement(motion, ref, case.r).items()}
        finite = [v for v in err.values() if v is not None]
        worst = max(finite) if len(finite) == (1 if m.quantities == POSITIONS else 3) else None
        note = _quirks(m.package, m.label) + (f"; {motion.note}" if motion.note else "")
        if worst is None or worst > MISMATCH_PCT:
            note += "; DISAGREES with graphplan: another branch, or a failed solve (NaN)"
        rows.append(_row(m.package, example, m.quantities, n_positions, m.label, time_s=t,
                         first_call_s=t1, max_error_pct=worst, ratio_to_graphplan=t / best,
                         version=ver, note=note, **err))
    return rows


def external_rows(n_positions: int = 360, repeats: int = 5,
                  examples: Sequence[str] = ("four_bar", "crank_slider"),
                  examples_dir: Path | None = None,
                  packages: Sequence[str] = PACKAGES) -> list[dict]:
    """Rows {method, setting, time_s, max_error_pct, ratio_to_graphplan, note, …}: per example,
    graphplan's solver and every way of driving pylinkage and mechanism ("not installed" rows
    when absent). max_error_pct: positions in % of the crank length; for the rows with
    derivatives, the largest of the position, velocity and acceleration disagreements (those in
    % of the joint's largest magnitude over the cycle), also given apart as pos_/vel_/acc_error_pct.
    ratio_to_graphplan = time_s / graphplan's time_s for the same angles (> 1: slower)."""
    folder = Path(examples_dir) if examples_dir else EXAMPLES_DIR
    rows: list[dict] = []
    for example in examples:
        st = positions.study(scene.load(folder / f"{example}.toml"))
        rows += compare(st, example, n_positions, repeats, packages)
    return rows
