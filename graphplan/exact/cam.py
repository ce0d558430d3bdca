"""The cam mechanism solved exactly: the follower's law, the pressure angle, the smallest base radius
the allowed pressure angles permit, the centre and working profiles and their curvature
(REFERENCE §11; docs/cams.md).

Conventions. φ is the cam's turn from the start of the rise, in degrees. s(φ) is the follower's
displacement from its nearest position: metres (translating) or radians (rocking, the arm's swing);
its analogues ds/dφ and d²s/dφ² are per radian of φ. In the fixed frame the cam's centre O is the
origin; a translating follower's axis is vertical at x = σ·e (σ = +1 when the cam turns counter-
clockwise), its roller centre at C = (σe, s0 + s) with s0 = √(R0² − e²); a rocking follower's arm of
length l turns about A = (a, 0) and its roller centre is C = A + l·e^{iσ(π − ψ0 − s)}, |C| = R0 at s = 0: a
clockwise cam's whole layout is the counter-clockwise one's mirrored about the line O–O1 (the arm on the side
the phase diagram ψ–dψ/dφ finds favourable for the turn: stop 60, CAM60's R0min 54.44 mm with the arm
above O–O1, 49.44 mm mirrored), so ϑ, ρ and R0min are the ccw cam's and the profile its mirror image.
The centre (theoretical) profile is the path of C in the cam's own frame (the inversion: the frame
turned back by the cam's turn), P(φ) = C(φ)·e^{−iσφ}; the working profile is its inner offset by the
roller radius (the envelope of the roller circles). The pressure angle ϑ is the angle between the
profile's normal at the contact (the force's line, friction neglected) and the velocity of the roller
centre: sin ϑ = Re(t̄·u)/|t|, t = dP/dφ·e^{iσφ} = C′ − iσC, u the unit direction of ∂C/∂s — for a
translating follower tg ϑ = (ds/dφ − e)/(s0 + s) for either sense (σ enters through C and t alike).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from graphplan.model.cam import Cam
from graphplan.util.errors import GraphplanError, keyed_error, said_error
from graphplan.util.words import Fixed


def _refusal(cam: Cam, key: str, word: str, /, **fields: object) -> GraphplanError:
    """A cam that cannot be built, worded by the catalogue (util.words) in the scene's language."""
    return keyed_error(GraphplanError, cam.source, key, word, dict(cam.meta).get("lang"), **fields)

Array = np.ndarray


# -- the laws: f(u), f′(u), f″(u) on u ∈ [0, 1], f(0) = 0, f(1) = 1 -------------------------------------

def _trapezoid_knots() -> tuple[Array, Array, Array, Array, float]:
    """The trapezoidal acceleration: a(u) ramps 0 → A over the first eighth, holds A to 3/8, falls to −A
    by 5/8, holds to 7/8 and ramps back to 0; A such that f(1) = 1. Integrated exactly piece by piece
    (a piecewise-linear a gives cubic pieces): the knots and, at each, a, f′ and f for A = 1."""
    u = np.array([0, 1, 3, 5, 7, 8]) / 8.0
    a = np.array([0.0, 1.0, 1.0, -1.0, -1.0, 0.0])
    v = np.zeros(6)
    f = np.zeros(6)
    for k in range(5):
        h = u[k + 1] - u[k]
        j = (a[k + 1] - a[k]) / h
        v[k + 1] = v[k] + a[k] * h + j * h * h / 2
        f[k + 1] = f[k] + v[k] * h + a[k] * h * h / 2 + j * h ** 3 / 6
    return u, a, v, f, 1.0 / f[-1]


_TRAP = _trapezoid_knots()


EXACT_U = 1e-12     # a phase's share u this close to 0, ½ or 1 is that point (φ/Φ of a division is off by an ulp)


def _snapped(u: Array) -> Array:
    """u with the phase's start, middle and end made exact (within ``EXACT_U``): where the laws' values
    are exact numbers (0, ½, 1) the law gives them, not the turn's rounding."""
    half = np.round(2 * u) / 2
    return np.where(np.abs(u - half) <= EXACT_U, half, u)


def _sinpi(x: Array) -> Array:
    """sin πx, exact where 2x is a whole number (sin π is 1.2·10⁻¹⁶ in floating point, not 0)."""
    k = np.round(2 * x)
    exact = k == 2 * x                                   # False for a NaN: it stays NaN
    quarter = np.mod(np.where(exact, k, 0.0), 4).astype(int)
    return np.where(exact, np.array([0.0, 1.0, 0.0, -1.0])[quarter], np.sin(np.pi * x))


def _cospi(x: Array) -> Array:
    """cos πx, exact where 2x is a whole number (cos π/2 is 6.1·10⁻¹⁷ in floating point, not 0)."""
    return _sinpi(x + 0.5)


def law(name: str, u: Array) -> tuple[Array, Array, Array]:
    """The normalised law f(u) and its derivatives f′, f″ (u = φ/Φ of the phase):
    parabolic f = 2u² (u ≤ ½), 1 − 2(1 − u)²; cosine f = (1 − cos πu)/2; cycloidal f = u − sin(2πu)/2π;
    linear f = u; trapezoidal: the acceleration above. At the phase's start, middle and end (u = 0, ½,
    1 within ``EXACT_U``) the values are the law's exact ones: a cosine's f′(1) = (π/2)·sin π is 0, not
    1.9·10⁻¹⁶ — a zero of the law prints 0 wherever it is printed (stop 55)."""
    u = _snapped(np.clip(np.asarray(u, dtype=float), 0.0, 1.0))
    if name == "parabolic":
        first = u <= 0.5
        f = np.where(first, 2 * u * u, 1 - 2 * (1 - u) ** 2)
        return f, np.where(first, 4 * u, 4 * (1 - u)), np.where(first, 4.0, -4.0)
    if name == "cosine":
        return (1 - _cospi(u)) / 2, np.pi / 2 * _sinpi(u), np.pi ** 2 / 2 * _cospi(u)
    if name == "cycloidal":
        return u - _sinpi(2 * u) / (2 * np.pi), 1 - _cospi(2 * u), 2 * np.pi * _sinpi(2 * u)
    if name == "linear":
        return u.copy(), np.ones_like(u), np.zeros_like(u)
    if name == "trapezoidal":
        knots, a, v, f, A = _TRAP
        k = np.clip(np.searchsorted(knots, u, side="right") - 1, 0, 4)
        t = u - knots[k]
        j = (a[k + 1] - a[k]) / (knots[k + 1] - knots[k])
        return (A * (f[k] + v[k] * t + a[k] * t * t / 2 + j * t ** 3 / 6), A * (v[k] + a[k] * t + j * t * t / 2),
                A * (a[k] + j * t))
    raise said_error(GraphplanError, "ec unknown law", None, None, name=repr(name))


def motion(cam: Cam, phi_deg: Array, phase: Array | None = None) -> tuple[Array, Array, Array]:
    """s, ds/dφ, d²s/dφ² (per radian) at the cam turns ``phi_deg`` from the start of the rise: the rise's
    law, the far dwell at h, the return's law mirrored, the near dwell at 0. ``phase`` (0 rise, 1
    return, per turn) says which phase a turn on the boundary of two belongs to — the rise's end is the
    return's start when there is no far dwell —; without it the later phase takes a shared turn."""
    raw = np.asarray(phi_deg, dtype=float)
    phi = np.mod(raw, 360.0)
    rise, far, ret, _ = cam.phases
    h = cam.stroke
    s, v, a = np.zeros_like(phi), np.zeros_like(phi), np.zeros_like(phi)
    R, T = math.radians(rise), math.radians(ret)
    if phase is not None:
        phase = np.asarray(phase)
        phi = np.where(phase == 1, raw, phi)            # the return's end stays at its own turn
    up = phi <= rise
    if phase is not None:
        up = up & (phase != 1)
    f, f1, f2 = law(cam.laws[0], phi[up] / rise)
    s[up], v[up], a[up] = h * f, h * f1 / R, h * f2 / R ** 2
    dwell = (phi > rise) & (phi < rise + far)
    s[dwell] = h
    down = (phi >= rise + far) & (phi <= rise + far + ret)
    if phase is not None:
        down = down & (phase != 0)
    f, f1, f2 = law(cam.laws[1], (phi[down] - rise - far) / ret)
    s[down], v[down], a[down] = h * (1 - f), -h * f1 / T, -h * f2 / T ** 2
    return s, v, a


def sides(cam: Cam, phi_deg: float) -> tuple[tuple[float, float, float], tuple[float, float, float]]:
    """s, ds/dφ, d²s/dφ² just before and just after the turn ``phi_deg``: the phase that ends there at
    its own end (u = 1) and the phase that starts there at its start (u = 0), by the law — its exact
    values, not the law a hair either side (stop 55: a parabolic rise's ds/dφ at its end printed
    4,584·10⁻¹⁰ mm/rad where it is 0). Inside a phase both are that phase's value."""
    rise, far, ret, near = cam.phases
    h = cam.stroke
    R, T = math.radians(rise), math.radians(ret)
    spans = [(0.0, rise, 0), (rise, far, -2), (rise + far, ret, 1), (rise + far + ret, near, -1)]
    spans = [sp for sp in spans if sp[1] > 0]
    tol = 1e-9
    phi = float(phi_deg) % 360.0

    def value(start: float, length: float, kind: int, at: float) -> tuple[float, float, float]:
        if kind == -2:
            return h, 0.0, 0.0
        if kind == -1:
            return 0.0, 0.0, 0.0
        f, f1, f2 = (float(x[0]) for x in law(cam.laws[kind], np.array([(at - start) / length])))
        if kind == 0:
            return h * f, h * f1 / R, h * f2 / R ** 2
        return h * (1 - f), -h * f1 / T, -h * f2 / T ** 2

    def side(after: bool) -> tuple[float, float, float]:
        for at in (phi, phi + 360.0):          # the near dwell's end is 360°, the rise's start 0°
            for start, length, kind in spans:
                end = start + length
                if (start - tol <= at < end - tol) if after else (start + tol < at <= end + tol):
                    return value(start, length, kind, min(max(at, start), end))
        return value(*spans[0], 0.0)
    return side(False), side(True)


def phase_of(cam: Cam, phi_deg: Array) -> Array:
    """0 on the rise, 1 on the return, −1 on the dwells (φ from the start of the rise)."""
    phi = np.mod(np.asarray(phi_deg, dtype=float), 360.0)
    rise, far, ret, _ = cam.phases
    return np.where(phi <= rise, 0, np.where((phi >= rise + far) & (phi <= rise + far + ret), 1, -1))


# -- the geometry ---------------------------------------------------------------------------------------

@dataclass(frozen=True)
class Geometry:
    """Where the follower stands: the base radius R0, the offset e (translating) or the arm's angle ψ0
    to the line of centres at the nearest position (rocking)."""
    R0: float
    e: float = 0.0
    psi0: float = 0.0


def _g(value: float) -> object:
    """A value for a refusal written "%g" in each language (a decimal comma in Ukrainian)."""
    return lambda lang: f"{value:g}".replace(".", ",") if lang == "uk" else f"{value:g}"


def geometry(cam: Cam, R0: float, e: float | None = None) -> Geometry:
    e = cam.offset if e is None else e
    if cam.rocking:
        a, l = cam.centre_distance, cam.arm
        c = (a * a + l * l - R0 * R0) / (2 * a * l)
        if not -1 < c < 1:
            raise _refusal(cam, "", "ec arm reach", arm=_g(l), centre=_g(a), base=_g(R0))
        return Geometry(R0, 0.0, math.acos(c))
    e = e or 0.0
    if abs(e) >= R0:
        raise _refusal(cam, "", "ec offset base", e=_g(abs(e)), base=_g(R0))
    return Geometry(R0, e)


def centre_path(cam: Cam, g: Geometry, s: Array, v: Array, a: Array) -> tuple[Array, Array, Array, Array]:
    """The roller centre C in the fixed frame and its derivatives by φ (C′, C″), and the unit direction
    u of ∂C/∂s (the follower's velocity as s grows) — complex numbers, m."""
    sig = 1 if cam.sense > 0 else -1
    if cam.rocking:
        l = cam.arm
        w = np.exp(1j * (np.pi - g.psi0 - s))
        C = cam.centre_distance + l * w
        C1 = -1j * l * v * w
        C2 = l * (-v * v - 1j * a) * w
        u = -1j * w
        if sig < 0:     # a clockwise cam: the counter-clockwise layout mirrored about the line O–O1
            return C.conjugate(), C1.conjugate(), C2.conjugate(), u.conjugate()
        return C, C1, C2, u
    s0 = math.sqrt(g.R0 ** 2 - g.e ** 2)
    C = sig * g.e + 1j * (s0 + s)
    return C, 1j * v, 1j * a, np.full(np.shape(s), 1j, dtype=complex)


def profile(cam: Cam, g: Geometry, phi_deg: Array, s=None, v=None, a=None) -> dict[str, Array]:
    """The centre profile P(φ) in the cam's frame (complex, m), its radius, the pressure angle (deg,
    signed: + where it opposes the follower's rise), the radius of curvature ρ (m, + where the profile
    is convex) and the working profile (the centre profile's inner offset by the roller)."""
    phi = np.asarray(phi_deg, dtype=float)
    if s is None:
        s, v, a = motion(cam, phi)
    sig = 1 if cam.sense > 0 else -1
    C, C1, C2, u = centre_path(cam, g, s, v, a)
    turn = np.exp(-1j * sig * np.radians(phi))
    P = C * turn
    t = C1 - 1j * sig * C                                 # dP/dφ turned back to the fixed frame
    t2 = C2 - 2j * sig * C1 - C                           # d²P/dφ² likewise
    speed = np.abs(t)
    theta = np.degrees(np.arcsin(np.clip(np.real(np.conj(t) * u) / speed, -1.0, 1.0)))
    cross = np.imag(np.conj(t) * t2)                      # t × t″: + where P turns left
    with np.errstate(divide="ignore", invalid="ignore"):
        rho = -sig * speed ** 3 / cross                   # P runs against the cam's turn: + where convex
    normal = 1j * (t / speed) * sig * turn                # the outward normal in the cam's frame
    working = P - cam.roller * normal
    return {"P": P, "radius": np.abs(P), "theta": theta, "rho": rho, "working": working}


# -- the smallest base radius ------------------------------------------------------------------------------

def _grid(cam: Cam, n: int = 7200) -> Array:
    rise, far, ret, _ = cam.phases
    a = np.linspace(0.0, rise, n // 2 + 1)
    b = np.linspace(rise + far, rise + far + ret, n // 2 + 1)
    return np.concatenate([a, b])


def phase_maxima(cam: Cam, g: Geometry) -> tuple[float, float]:
    """Each active phase's largest |ϑ| (deg) over the continuous phase (phase_extremes' magnitudes)."""
    rise, ret = phase_extremes(cam, g)
    return abs(rise), abs(ret)


def phase_extremes(cam: Cam, g: Geometry) -> tuple[float, float]:
    """Each active phase's pressure angle of largest magnitude (deg), signed as Table 1 signs ϑ: the
    0.05° grid's largest |ϑ|, refined by a bounded search between its neighbours (the divisions'
    values may lie below it)."""
    (_, rise), (_, ret) = phase_extreme_points(cam, g)
    return rise, ret


def phase_extreme_points(cam: Cam, g: Geometry) -> tuple[tuple[float, float], tuple[float, float]]:
    """``phase_extremes`` with where each falls: ((φ°, ϑ°) of the rise, (φ°, ϑ°) of the return). A
    rocking follower's largest |ϑ| may fall at a phase's end, where the arm still rests (stop 56: the
    rise's −27,04° at φ = 0°): the notes say where."""
    from scipy.optimize import minimize_scalar
    grid = _grid(cam)
    out = []
    for k in (0, 1):
        sel = grid[phase_of(cam, grid) == k]
        signed = profile(cam, g, sel)["theta"]
        th = np.abs(signed)
        j = int(np.argmax(th))
        lo, hi = sel[max(j - 1, 0)], sel[min(j + 1, len(sel) - 1)]
        best, at = float(signed[j]), float(sel[j])
        if hi > lo:
            r = minimize_scalar(lambda x: -abs(float(profile(cam, g, np.array([x]))["theta"][0])),
                                bounds=(lo, hi), method="bounded", options={"xatol": 1e-12})
            if -float(r.fun) > abs(best):
                best, at = float(profile(cam, g, np.array([float(r.x)]))["theta"][0]), float(r.x)
        out.append((at, best))
    return out[0], out[1]


def _refined_worst(cam: Cam, R0: float, e: float | None) -> float:
    """|ϑ|max/[ϑ] with each phase's largest |ϑ| refined about the grid's largest (bounded search)."""
    rise, ret = phase_maxima(cam, geometry(cam, R0, e))
    return max(rise / cam.allowed[0], ret / cam.allowed[1])


def min_base_radius(cam: Cam, e: float | None = None) -> float:
    """The smallest R0 at which no pressure angle exceeds its allowed value (brentq on the refined
    largest |ϑ|/[ϑ] − 1, which falls as R0 grows)."""
    e = cam.offset if e is None else e
    if cam.rocking:
        lo = abs(cam.centre_distance - cam.arm) * (1 + 1e-9) + 1e-9
        hi = (cam.centre_distance + cam.arm) * (1 - 1e-9)
    else:
        lo = abs(e or 0.0) * (1 + 1e-9) + 1e-9 + cam.stroke * 1e-6
        hi = max(lo * 2, cam.stroke * 2)
        while _refined_worst(cam, hi, e) > 1:
            hi *= 2
            if hi > 1e4:
                raise _refusal(cam, "", "ec no base")
    f = lambda R0: _refined_worst(cam, R0, e) - 1.0          # noqa: E731
    if cam.rocking:
        # the arm's angle changes with R0 and |ϑ| is not monotone in it: the allowed radii are a band;
        # the first allowed one on a scan of the reach, then bracketed. The coarse grid's largest |ϑ|
        # never exceeds the refined one, so a scan point whose coarse ratio is over 1 is not allowed;
        # the others are decided by f itself — the bracket's ends then differ in sign by construction.
        scan = np.linspace(lo, hi, 241)
        coarse = _grid(cam, 720)
        phases = phase_of(cam, coarse)

        def quick(R: float) -> float:
            th = np.abs(profile(cam, geometry(cam, R, e), coarse)["theta"])
            return max(float(np.max(th[phases == k])) / cam.allowed[k] for k in (0, 1))
        ratios = [quick(R) for R in scan]
        first = next((k for k, R in enumerate(scan) if ratios[k] <= 1.0 and f(R) <= 0), None)
        if first is None:
            first, scan = _narrow_band(cam, e, scan, ratios, quick, f)
        if first == 0:
            return float(lo)
        lo, hi = scan[first - 1], scan[first]
    elif f(lo) <= 0:
        return float(lo)
    return bracketed_root(f, lo, hi)


def _narrow_band(cam: Cam, e, scan: Array, ratios: list[float], quick, f) -> tuple[int, Array]:
    """Where no scan point of the rocking follower's reach is allowed: the coarse ratio's least value
    searched between the best scan point's neighbours (a band narrower than the scan's step); found
    allowed, the scan is cut there (index 1: its left neighbour is not allowed, so f changes sign on
    the bracket). Else one line naming the phase and the least pressure angle it can have."""
    from scipy.optimize import minimize_scalar
    j = int(np.nanargmin(np.where(np.isfinite(ratios), ratios, np.inf)))
    a, b = scan[max(j - 1, 0)], scan[min(j + 1, len(scan) - 1)]
    r = minimize_scalar(quick, bounds=(a, b), method="bounded", options={"xatol": 1e-12})
    R = float(r.x) if r.fun < ratios[j] else float(scan[j])
    if quick(R) <= 1.0 and f(R) <= 0 and R > scan[0]:
        return 1, np.array([a if f(a) > 0 else scan[0], R])
    rise, ret = phase_maxima(cam, geometry(cam, R, e))
    k = 0 if rise / cam.allowed[0] >= ret / cam.allowed[1] else 1
    name, least = ("rise", rise) if k == 0 else ("return", ret)
    raise _refusal(cam, "", "ec rise pressure" if k == 0 else "ec return pressure", allowed=_g(cam.allowed[k]),
                   least=Fixed(least, 2), R0=Fixed(R * 1000, 3))


def bracketed_root(f, lo: float, hi: float) -> float:
    """The root of ``f`` between ``lo`` (f > 0) and ``hi`` (f ≤ 0) by brentq; where f(hi) is exactly
    0 that end is the answer (brentq needs opposite signs)."""
    from scipy.optimize import brentq
    f_hi = f(hi)
    if f_hi == 0:
        return float(hi)
    if not f(lo) > 0 or not f_hi < 0:
        raise said_error(GraphplanError, "ec no bracket", None, None, lo=Fixed(lo * 1000, 3), hi=Fixed(hi * 1000, 3))
    return float(brentq(f, lo, hi, xtol=1e-15, rtol=1e-15, maxiter=200))


def best_offset(cam: Cam) -> tuple[float, float]:
    """The offset e that allows the smallest base radius, and that radius (translating follower): the
    cam centre at the corner of the phase diagram's allowed region nearest the follower's origin.

    By the closed form of the translating follower's pressure angle, tg ϑ = (ds/dφ − e)/(s0 + s)
    (the module's conventions), |ϑ| ≤ [ϑ] on a phase is s0 ≥ |ds/dφ − e|/tg[ϑ] − s at each of its
    turns: the least s0 at an offset e is the largest of these (``_least_s0``, each phase's largest
    refined about its grid's largest as ``phase_extremes`` refines ϑ), and R0 = √(e² + s0²) — what
    ``min_base_radius`` finds by bracketing ϑ itself, without solving for R0 at every trial offset
    (4.5 s of CPU for stop 49's cam, half its sheet). Minimised over e by the same bounded search."""
    from scipy.optimize import minimize_scalar
    h = cam.stroke
    terms = _offset_terms(cam)
    r = minimize_scalar(lambda e: _least_radius(cam, terms, e), bounds=(-2 * h, 2 * h), method="bounded",
                        options={"xatol": 1e-9 * h})
    return float(r.x), float(r.fun)


def _offset_terms(cam: Cam) -> list[tuple[Array, Array, Array, float]]:
    """Each active phase's 0.05° grid (``_grid``): its turns, s and ds/dφ there, and tg[ϑ]."""
    grid = _grid(cam)
    out = []
    for k in (0, 1):
        sel = grid[phase_of(cam, grid) == k]
        s, v, _ = motion(cam, sel)
        out.append((sel, s, v, math.tan(math.radians(cam.allowed[k]))))
    return out


def _least_s0(cam: Cam, terms, e: float) -> float:
    """The least s0 = √(R0² − e²) at which no pressure angle of the translating follower at offset
    ``e`` exceeds its allowed one: max over each phase of |ds/dφ − e|/tg[ϑ] − s, the grid's largest
    refined by a bounded search between its neighbours (as ``phase_extremes``)."""
    from scipy.optimize import minimize_scalar
    best = -math.inf
    for sel, s, v, tg in terms:
        need = np.abs(v - e) / tg - s
        j = int(np.argmax(need))
        top = float(need[j])
        lo, hi = sel[max(j - 1, 0)], sel[min(j + 1, len(sel) - 1)]
        if hi > lo:
            def minus(x: float) -> float:
                sx, vx, _ = motion(cam, np.array([x]))
                return -(abs(float(vx[0]) - e) / tg - float(sx[0]))
            r = minimize_scalar(minus, bounds=(lo, hi), method="bounded", options={"xatol": 1e-12})
            top = max(top, -float(r.fun))
        best = max(best, top)
    return best


def _least_radius(cam: Cam, terms, e: float) -> float:
    """``min_base_radius(cam, e)`` of a translating follower by the closed form (``_least_s0``): √(e² + s0²),
    and never below the search's least radius ``lo`` (a cam whose angles hold at any radius)."""
    lo = abs(e) * (1 + 1e-9) + 1e-9 + cam.stroke * 1e-6
    return max(lo, math.hypot(e, max(_least_s0(cam, terms, e), 0.0)))


def best_offset_searched(cam: Cam) -> tuple[float, float]:
    """``best_offset`` by brute force: ``min_base_radius`` (ϑ bracketed at every trial offset) minimised
    over e — the check of the closed form (tests), ~50 times slower."""
    from scipy.optimize import minimize_scalar
    h = cam.stroke
    r = minimize_scalar(lambda e: min_base_radius(cam, e), bounds=(-2 * h, 2 * h), method="bounded",
                        options={"xatol": 1e-9 * h})
    return float(r.x), float(r.fun)


@dataclass
class Solution:
    """The cam solved: the geometry chosen, the smallest base radius, the profile's tabulation and its
    curvature, and what the sheet and the terminal must say."""
    cam: Cam
    geometry: Geometry
    R0_min: float
    warnings: list[tuple[str, str]]
    cache: dict = field(default_factory=dict, repr=False, compare=False)

    def pressure_maxima(self) -> tuple[float, float]:
        """Each active phase's largest |ϑ| over the continuous phase (phase_maxima), once."""
        rise, ret = self.pressure_extremes()
        return abs(rise), abs(ret)

    def pressure_extremes(self) -> tuple[float, float]:
        """Each active phase's pressure angle of largest magnitude, signed (phase_extremes), once."""
        (_, rise), (_, ret) = self.pressure_extreme_points()
        return rise, ret

    def pressure_extreme_points(self) -> tuple[tuple[float, float], tuple[float, float]]:
        """(φ°, ϑ°) of each active phase's largest |ϑ| (phase_extreme_points), once."""
        if "extremes" not in self.cache:
            self.cache["extremes"] = phase_extreme_points(self.cam, self.geometry)
        return self.cache["extremes"]

    def at(self, phi_deg: Array, phase: Array | None = None) -> dict[str, Array]:
        s, v, a = motion(self.cam, phi_deg, phase)
        out = profile(self.cam, self.geometry, phi_deg, s, v, a)
        out.update(s=s, v=v, a=a)
        return out

    def corners(self) -> list[Corner]:
        """The centre profile's corners (profile_corners): ρ = 0 there, outside curvature_min."""
        if "corners" not in self.cache:
            self.cache["corners"] = profile_corners(self.cam, self.geometry)
        return self.cache["corners"]

    def shocks(self) -> list["Shock"]:
        return shocks(self.cam)

    def curvature_min(self) -> float:
        """The smallest radius of curvature of the centre profile where it is convex, m: a 0.025° grid's
        smallest refined by a bounded search, and at every point where d²s/dφ² (or ds/dφ) jumps — the
        phases' ends, the parabolic law's middle, the trapezoidal law's knots — both one-sided limits
        (the grid sees one side of a jump only)."""
        if "rho" not in self.cache:
            self.cache["rho"] = self._curvature_min()
        return self.cache["rho"]

    def concave(self) -> list[tuple[float, float, float]]:
        """The centre profile's concave stretches, each (from φ°, to φ°, the least |ρ| there, m): the runs
        of ρ < 0 on the 0.025° grid of ``curvature_min``, a run up to 360° joined to the one from 0° (then
        from > to: «350…25°» crosses φ = 0); a run
        whose least |ρ| is over a thousand base radii is a straight stretch's rounding noise and left out.
        (Stop 62: CAM61's profile is faintly concave over φ = 272,5…281,3°, |ρ| ≥ 601,6 mm, which the
        notes' «ρ_min = 26 мм» left a teacher to find on the drawing.)"""
        if "concave" not in self.cache:
            phi = np.linspace(0.0, 360.0, 14401)[:-1]          # (360° is 0° again)
            rho = self.at(phi)["rho"]
            neg = np.isfinite(rho) & (rho < 0)
            runs, j = [], 0
            while j < len(phi):
                if not neg[j]:
                    j += 1
                    continue
                k = j
                while k + 1 < len(phi) and neg[k + 1]:
                    k += 1
                runs.append([float(phi[j]), float(phi[k]), float(np.min(-rho[j:k + 1]))])
                j = k + 1
            if len(runs) > 1 and runs[0][0] == 0.0 and runs[-1][1] == float(phi[-1]):   # one run across φ = 0,
                last = runs.pop()                                  # from its start before 360° to its end after 0°
                runs[0] = [last[0], runs[0][1], min(last[2], runs[0][2])]
            big = 1000.0 * self.geometry.R0
            self.cache["concave"] = [tuple(r) for r in runs if r[2] <= big]
        return self.cache["concave"]

    def _curvature_min(self) -> float:
        from scipy.optimize import minimize_scalar
        phi = np.linspace(0.0, 360.0, 14401)
        rho = self.at(phi)["rho"]
        ok = np.isfinite(rho) & (rho > 0)
        best = float(np.min(rho[ok])) if ok.any() else math.inf
        if ok.any():
            j = int(np.argmin(np.where(ok, rho, np.inf)))
            lo, hi = phi[max(j - 1, 0)], phi[min(j + 1, len(phi) - 1)]

            def r(x: float) -> float:
                v = float(self.at(np.array([x]))["rho"][0])
                return v if math.isfinite(v) and v > 0 else math.inf
            best = min(best, float(minimize_scalar(r, bounds=(lo, hi), method="bounded",
                                                   options={"xatol": 1e-10}).fun))
        knots = jump_points(self.cam)
        s, _, _ = motion(self.cam, knots)
        for side in (-1.0, 1.0):
            _, v, a = motion(self.cam, knots + side * 1e-9)
            rho = profile(self.cam, self.geometry, knots, s, v, a)["rho"]
            ok = np.isfinite(rho) & (rho > 0)
            if ok.any():
                best = min(best, float(np.min(rho[ok])))
        return best


@dataclass(frozen=True)
class Corner:
    """A corner of the centre profile: where ds/dφ jumps (the linear law's ends) the profile's tangent
    turns at once — ρ = 0 there. ``convex``: it points out of the cam (the working profile has a sharp
    edge there, which the roller rolls over: its centre rounds the corner by an arc of radius r about
    that edge, off the law); else the working profile is an arc of the roller's radius about it."""
    phi_deg: float
    v_before: float        # ds/dφ just before and just after (per radian; rocking: dψ/dφ in rad/rad)
    v_after: float
    convex: bool


def profile_corners(cam: Cam, g: Geometry) -> list[Corner]:
    """The centre profile's corners: the phases' ends where ds/dφ jumps by more than 1e-9 of the largest
    |ds/dφ| (the linear law's rigid shocks). Convex when the tangent turns there the way the profile
    runs round the cam: Im(conj(t₋)·t₊) of the same sign as the profile's signed area."""
    rise, far, ret, _ = cam.phases
    ends = sorted({e % 360.0 for e in (0.0, rise, rise + far, rise + far + ret)})      # no near dwell: 360° is 0°
    fine = np.linspace(0.0, 360.0, 3601)
    big = float(np.max(np.abs(motion(cam, fine)[1]))) or 1.0
    P = profile(cam, g, fine)["P"]
    area = float(np.sum((np.conj(P[:-1]) * P[1:]).imag))       # twice the signed area
    out = []
    for phi in ends:
        (_, vb, _), (_, va, _) = sides(cam, phi)        # the law's own values at the phase's ends
        if abs(va - vb) <= 1e-9 * big:
            continue
        d = 1e-3
        q = profile(cam, g, np.array([phi - d, phi, phi + d]))["P"]
        turn = float((np.conj(q[1] - q[0]) * (q[2] - q[1])).imag)
        out.append(Corner(float(phi % 360.0), float(vb), float(va), turn * area > 0))
    return out


_LAW_KNOTS = {"parabolic": (0.5,), "trapezoidal": (0.125, 0.375, 0.625, 0.875)}


def jump_points(cam: Cam) -> Array:
    """The cam turns (deg) where d²s/dφ² or ds/dφ may jump: the phases' ends and the laws' knots."""
    rise, far, ret, _ = cam.phases
    pts = [0.0, rise, rise + far, rise + far + ret]
    pts += [rise * u for u in _LAW_KNOTS.get(cam.laws[0], ())]
    pts += [rise + far + ret * u for u in _LAW_KNOTS.get(cam.laws[1], ())]
    return np.array(sorted(set(pts)))


@dataclass(frozen=True)
class Shock:
    """A jump of the follower's motion at the cam turn ``phi_deg``: "rigid" where ds/dφ jumps (the
    acceleration is infinite), "soft" where only d²s/dφ² jumps (a finite jump of acceleration)."""
    phi_deg: float
    kind: str


def _law_sides(name: str, u: float) -> tuple[tuple[float, float], tuple[float, float]]:
    """f′, f″ of a law just before and just after a knot ``u`` inside its phase (a hair either side:
    the laws are polynomials or trigonometric between their knots, so the hair's error is ~1e-9·f‴)."""
    d = 1e-9
    lo, hi = (law(name, np.array([x])) for x in (u - d, u + d))
    return (float(lo[1][0]), float(lo[2][0])), (float(hi[1][0]), float(hi[2][0]))


def shocks(cam: Cam) -> list[Shock]:
    """The shocks of the cycle, by the one-sided values of ds/dφ and d²s/dφ² at the phases' ends
    (``sides``: where two phases meet without a dwell both are judged) and at the laws' knots inside a
    phase (the parabolic law's middle, the trapezoidal's ramps): a jump of ds/dφ is a rigid shock, one
    of d²s/dφ² alone a soft one — from the values, not the law's name (a cosine rise into a cosine
    return of the same angle has none at the join)."""
    rise, far, ret, _ = cam.phases
    h = cam.stroke
    spans = [(0.0, rise), (rise + far, ret)]
    v_big = max(h / math.radians(x) for _, x in spans)
    a_big = max(h / math.radians(x) ** 2 for _, x in spans)
    tol = 1e-6
    out = []
    for phi in sorted({e % 360.0 for e in (0.0, rise, rise + far, rise + far + ret)}):
        (_, vb, ab), (_, va, aa) = sides(cam, phi)
        if abs(va - vb) > tol * v_big:
            out.append(Shock(float(phi), "rigid"))
        elif abs(aa - ab) > tol * a_big:
            out.append(Shock(float(phi), "soft"))
    for k, (start, length) in enumerate(spans):
        scale = h / math.radians(length)
        for u in _LAW_KNOTS.get(cam.laws[k], ()):
            (vb, ab), (va, aa) = _law_sides(cam.laws[k], u)
            if abs(va - vb) * scale > tol * v_big:
                out.append(Shock(float(start + length * u), "rigid"))
            elif abs(aa - ab) * scale / math.radians(length) > tol * a_big:
                out.append(Shock(float(start + length * u), "soft"))
    return sorted(out, key=lambda x: x.phi_deg)


def solve(cam: Cam) -> Solution:
    """The exact solution: the offset (given or the best), the smallest base radius, the base radius
    taken (the scene's, else the smallest rounded up to a whole millimetre), and the warnings: the linear
    law's rigid shocks, an undercut working profile, a base radius below the smallest."""
    e = cam.offset
    if e is None:
        e, r_min = best_offset(cam)
        e = round(e, 4)                      # a draftsman's offset: a tenth of a millimetre
        r_min = min_base_radius(cam, e)
    else:
        r_min = min_base_radius(cam, e)
    R0 = cam.base_radius if cam.base_radius is not None else math.ceil(r_min * 1000 - 1e-9) / 1000
    if cam.rocking:
        R0 = min(max(R0, abs(cam.centre_distance - cam.arm) * 1.0001), (cam.centre_distance + cam.arm) * 0.9999)
    elif abs(e) >= R0:
        R0 = math.ceil(abs(e) * 1000 + 1) / 1000
    if cam.roller >= R0:
        raise _refusal(cam, "cam.roller_radius", "cm roller base", roller=_g(cam.roller), base=_g(R0))
    sol = Solution(cam, geometry(cam, R0, e), r_min, [])
    for k, name in enumerate(("rise", "return")):
        if cam.laws[k] == "linear":
            v = "dψ/dφ" if cam.rocking else "ds/dφ"        # a rocking follower's angle is ψ, not s
            sol.warnings.append((f"the linear law of the {name}: rigid shocks at its ends (the acceleration is "
                                 f"infinite there); its {v} is drawn directly, not integrated",
                                 f"лінійний закон {'підйому' if k == 0 else 'опускання'}: жорсткі удари на "
                                 f"кінцях фази (прискорення там нескінченне); {v} будується прямо, без "
                                 "інтегрування"))
    comma = lambda x: x.replace(".", ",")          # noqa: E731  the Ukrainian decimal comma (review 57)
    if R0 < r_min * (1 - 1e-9):
        take = math.ceil(r_min * 1000 - 1e-9)           # the whole millimetre the program itself would take
        sol.warnings.append((f"the base radius {R0 * 1000:.1f} mm is below the smallest allowed "
                             f"{r_min * 1000:.2f} mm: the pressure angle exceeds the allowed one; take R₀ ≥ {take} mm",
                             f"радіус основної шайби {comma(f'{R0 * 1000:.1f}')} мм менший за найменший допустимий "
                             f"{comma(f'{r_min * 1000:.2f}')} мм: кут тиску перевищує допустимий; слід прийняти "
                             f"R₀ ≥ {take} мм"))
    if cam.roller > 0:
        rho = sol.curvature_min()
        if rho <= cam.roller:
            sol.warnings.append((f"undercut: the centre profile's smallest convex radius of curvature "
                                 f"{rho * 1000:.2f} mm is not larger than the roller's {cam.roller * 1000:g} mm; "
                                 "take a smaller roller or a larger base circle",
                                 f"підрізання: найменший радіус кривини опуклої ділянки центрового профілю "
                                 f"{comma(f'{rho * 1000:.2f}')} мм не більший за радіус ролика "
                                 f"{comma(f'{cam.roller * 1000:g}')} мм; "
                                 "візьміть менший ролик або більшу основну шайбу"))
    return sol
