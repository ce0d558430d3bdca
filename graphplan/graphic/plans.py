"""The graphical plans, constructed as a draftsman draws them and measured like a student.

* **Position plan** — the crank circle divided into N parts from position 0; each position of each
  Assur group found with the compass and ruler in drawing millimetres: two arcs ("засічки",
  circle ∩ circle) for RRR, an arc and the guide (circle ∩ line) for RRP, the rocker's line through
  the block (a line through a pivot) for RPR, two lines (line ∩ line) for PRP and RPP.
* **Velocity plan** — from the pole p_v: v_A = ω1·l_OA ⊥ OA laid off as p_v a; every group's two
  vector equations are solved by drawing their known direction lines (∥ a guide, ⊥ a link) through
  the known plan points and intersecting them, e.g. v_B = v_A + v_BA (⊥ AB) with v_B ∥ the guide;
  the slotted link: v_A3 = v_A2 + v_A3A2 (∥ the rocker) with v_A3 ⊥ O A. Further points of a link by
  the similarity theorem (the link's figure on the plan is similar to the link, turned 90°).
* **Acceleration plan** — from the pole π: a_A, then for each group normal components
  a^n = v²/l laid off ∥ the link toward its centre (n ends), Coriolis a^k = 2·ω·v_rel laid off along
  v_rel turned 90° in the sense of ω (k ends), and the lines of the unknown tangential/relative
  components intersected.

Every length read off a plan is rounded to the drafting precision (a ruler: 0.5 mm; 0 = exact) and
multiplied by the scale; lengths computed from measured values (normal and Coriolis components) are
laid off with the same ruler. The analytic solver is used only for the comparison (and to choose the
scales' sizes); nothing of its velocities or accelerations enters a plan.
"""
from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from graphplan.util.words import fixed, num, word
from graphplan.util.errors import GraphplanError
from graphplan.exact.kinematics import Kinematics
from graphplan.model.mechanism import FRAME, Mechanism
from graphplan.exact.positions import Study
from graphplan.graphic.scales import Targets, standard_scale
from graphplan.graphic.position_plan import Layout, Scheme, construct_position
from graphplan.graphic.plan import Exact, PlanWarning, SMALL_ANGLE_DEG
from graphplan.graphic.velocity import VelocityPlan
from graphplan.graphic.acceleration import AccelerationPlan
# what the rooms above read from the plans, in one place:
from graphplan.graphic.draftsman import measure  # noqa: F401
from graphplan.graphic.plan import NEAR_ZERO, VANISH, Entry, Plan  # noqa: F401
from graphplan.graphic.position_plan import where  # noqa: F401


# -- all the plans of a mechanism ----------------------------------------------------------------

@dataclass
class PositionPlans:
    """One position: its layout on the position plan, its velocity plan and maybe its
    acceleration plan. ``key`` is the position's index, or N, N+1, … for extra crank angles."""
    key: int
    index: int | None
    phi: float
    layout: Layout
    velocity: VelocityPlan
    acceleration: AccelerationPlan | None
    warnings: list[PlanWarning]


@dataclass
class Plans:
    """Every plan of a mechanism, measured. Records are in drawing mm with their own origin: the
    crank's pivot on the position plan, the pole on the velocity and acceleration plans."""
    study: Study
    scheme: Scheme
    count: int
    precision: float
    mu_l: float
    mu_v: float
    mu_a: float
    targets: Targets
    positions: list[PositionPlans]
    extremes: list[Layout]
    trajectories: tuple[str, ...]

    @property
    def scales(self) -> dict[str, float]:
        return {"mu_l": self.mu_l, "mu_v": self.mu_v, "mu_a": self.mu_a}

    def at(self, key: int) -> PositionPlans:
        return next(p for p in self.positions if p.key == key)

    @property
    def accel_keys(self) -> list[int]:
        return [p.key for p in self.positions if p.acceleration is not None]


def resolve_accel(st: Study, phis: np.ndarray, accel: Sequence[str | int | float] | None
                  ) -> tuple[list[int], list[float]]:
    """Positions with acceleration plans: indices (an int, or "#3") and crank angles (a float, or
    "200" degrees; an angle on a position is that position). Default: the scene's, else position 1."""
    specs = list(accel) if accel else (list(st.mech.task.accel) or [1])
    n = len(phis)
    indices: list[int] = []
    extra: list[float] = []
    for spec in specs:
        index, phi = None, None
        if isinstance(spec, (int, np.integer)) and not isinstance(spec, bool):
            index = int(spec)
        elif isinstance(spec, (float, np.floating)):
            phi = float(spec)
        else:
            text = str(spec).strip()
            try:
                if text.startswith("#"):
                    index = int(text[1:])
                else:
                    phi = float(text.rstrip("°"))
            except ValueError:
                raise GraphplanError(f"--accel {text!r}: give a crank angle in degrees or a position "
                                     "index like #3") from None
            if phi is not None and not math.isfinite(phi):
                raise GraphplanError(f"--accel {text!r}: the angle must be finite")
        if index is not None:
            if not 0 <= index < n:
                raise GraphplanError(f"--accel #{index}: there are {n} positions (#0–#{n - 1})")
            indices.append(index)
            continue
        phi %= 360.0
        gaps = np.abs((phis - phi + 180.0) % 360.0 - 180.0)
        if np.min(gaps) < 1e-9:
            indices.append(int(np.argmin(gaps)))
        elif not any(abs((phi - e + 180.0) % 360.0 - 180.0) < 1e-9 for e in extra):
            extra.append(phi)
    extra.sort(key=lambda p: float(st.from_position0(p)))
    return sorted(set(indices)), extra


def choose_scales(st: Study, kin: Kinematics, phis: np.ndarray, accel_at: list[int], targets: Targets,
                  mu_l: float | None, mu_v: float | None, mu_a: float | None) -> tuple[float, float, float]:
    """μl from the crank (and the whole mechanism's extent), μv from p_v a, μa from π a — each
    the standard value that fills its target and keeps every figure within its limit. The sizes
    come from the exact solution: a draftsman sketches before choosing a scale."""
    mech = st.mech
    names = [n for n in mech.point_names()]
    xs = np.concatenate([np.atleast_1d(kin.point(n)[0]) for n in names])
    extent = max(np.ptp(xs.real), np.ptp(xs.imag))
    r = mech.crank.length
    ml = standard_scale(r, targets.crank, mu_l, extent, targets.layout)
    moving = [n for n in names if n not in mech.frame]
    v = max(float(np.max(np.abs(kin.point(n)[1]))) for n in moving)
    mv = standard_scale(abs(mech.omega1) * r, targets.velocity, mu_v, v, targets.figure)
    a_a = r * math.hypot(mech.omega1 ** 2, mech.crank.epsilon)
    a = max([float(np.max(np.abs(kin.point(n)[2][accel_at]))) for n in moving] + [a_a]) if accel_at else a_a
    ma = standard_scale(a_a, targets.acceleration, mu_a, a, targets.figure)
    return ml, mv, ma


def default_trajectories(mech: Mechanism) -> tuple[str, ...]:
    """Points whose paths are worth drawing: the extra points (centres of mass, coupler points) of
    the links after the crank."""
    joints = {j for link in mech.links.values() for j in link.joints}
    out = []
    for name, link in mech.links.items():
        if name == mech.crank.link:
            continue
        first = next(iter(link.local))
        # a point of a slider on a frame guide along the guide's line through its own point (the ram's
        # D above its block C): its path is that line, numbered already — its numbers stood beside
        # C's extreme letters («C″ 2, 10», review 62 F6)
        # (a centre of mass keeps its path: the lab draws the S's; a yoke's rod too, its own drawing)
        along = link.slides_on is not None and mech.guides[link.slides_on].body == FRAME and bool(link.joints)
        out += [p for p in link.local if p not in joints and p not in mech.frame and p not in out
                and p != first and not (along and p != link.com and not p.startswith("S")
                                        and abs((link.local[p] - link.local[first]).imag) < 1e-9)]
    return tuple(out)


def build_plans(st: Study, count: int | None = None, accel: Sequence[str | int | float] | None = None,
                precision: float = 0.5, mu_l: float | None = None, mu_v: float | None = None,
                mu_a: float | None = None, targets: Targets | None = None,
                trajectories: Sequence[str] | None = None) -> Plans:
    """The position plan of ``count`` positions (default: the scene's), the velocity plan of every
    position and acceleration plans at ``accel`` (indices / "#3" / crank angles in degrees; default:
    the scene's, else position 1), drawn with the scales given or chosen for ``targets``, read with
    a ruler of ``precision`` mm (0 = exact)."""
    if not (isinstance(precision, (int, float)) and math.isfinite(precision) and 0 <= precision <= 10):
        raise GraphplanError(f"--precision must be from 0 to 10 mm, got {precision!r}")
    n = count or st.mech.task.count
    if not 2 <= n <= 3600:
        raise GraphplanError(f"--positions must be from 2 to 3600, got {n}")
    targets = targets or Targets()
    phis = np.asarray(st.positions(n), dtype=float)
    accel_idx, extra = resolve_accel(st, phis, accel)
    all_phi = np.concatenate([phis, np.asarray(extra, dtype=float)])
    kin = st.solve(all_phi)
    acc_keys = accel_idx + list(range(n, n + len(extra)))
    ml, mv, ma = choose_scales(st, kin, all_phi, acc_keys, targets, mu_l, mu_v, mu_a)
    sc = Scheme(st)
    trajectories = tuple(trajectories) if trajectories is not None else default_trajectories(st.mech)
    for name in trajectories:
        if name not in st.mech.point_names():
            raise GraphplanError(f"trajectory: no point named {name!r}")
    results = []
    for key, phi in enumerate(all_phi):
        index = key if key < n else None
        lay = construct_position(sc, float(phi), ml, key, index)
        exact = Exact(kin, key)
        vel = VelocityPlan(sc, lay, exact, mv, precision)
        vel.crank()
        for d in st.structure.dyads:
            vel.group(d)
        vel.finish()
        acc = None
        if key in acc_keys:
            acc = AccelerationPlan(sc, lay, exact, ma, precision, vel)
            acc.crank()
            for d in st.structure.dyads:
                acc.group(d)
            acc.finish()
        warnings = [PlanWarning("position", c.group, c.kind, c.angle,
                                *(word("warn position", lang, group=c.group, what=c.what, angle=fixed(c.angle, lang, 1),
                                       limit=num(SMALL_ANGLE_DEG, lang),
                                       how=word("nearly tangent" if c.kind == "arcs" else "nearly parallel", lang))
                                  for lang in ("en", "uk")))
                    for c in lay.angles if c.angle < SMALL_ANGLE_DEG]
        warnings += vel.warnings + (acc.warnings if acc else [])
        results.append(PositionPlans(key, index, float(phi), lay, vel, acc, warnings))
    extremes = [construct_position(sc, float(e), ml, -1 - j) for j, e in enumerate(st.extremes)]
    return Plans(st, sc, n, float(precision), ml, mv, ma, targets, results, extremes, trajectories)
