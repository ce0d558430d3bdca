"""The cam synthesised as the coursework draws it (REFERENCE §11; docs/cams.md), in drawing millimetres,
every length read with the ruler of the drafting precision:

1. the analogue-acceleration diagram d²s/dφ² over the rise and the return, divided into ``n`` equal
   intervals each (abscissa: φ at μ_φ = 2π/L rad/mm);
2. its graphical integration by chords with the pole distance H1 — each interval's mean ordinate (the
   step of equal area, mean_ordinates; its middle ordinate where the curve is smooth over it) carried
   to the ordinate axis and joined to the pole gives its chord's slope — to ds/dφ, then with
   H2 to s (μ_v = μ_a·μ_φ·H1, μ_s = μ_v·μ_φ·H2; a phase of the linear law has no finite acceleration:
   its ds/dφ, a constant, is drawn directly and integrated once);
3. the phase diagram: ds/dφ laid off along the follower's normal at the scale of s; the lines at the
   allowed pressure angle through its extreme points bound the region of the cam's centre; the
   smallest base radius R0 is measured off it (computed here as the smallest R0 at which no drawn point
   exceeds the allowed angle — what the tangent lines give);
4. the profile by inversion: at each division the follower turned about the cam's centre against ω,
   the drawn s laid off from the base circle: the centre profile's points, and its radii measured.

Every graphical value stands beside the exact one with the lab's percent error.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from graphplan.exact.cam import Solution, geometry, motion, profile
from graphplan.graphic.chords import integrate_by_chords
from graphplan.graphic.scales import series_around

HEIGHT_MM = 40.0       # the tallest ordinate of the analogue-acceleration diagram
STROKE_MM = 80.0       # the stroke (swing) drawn on the s diagram, about
PROFILE_MM = 100.0     # the centre profile's largest radius, drawn, about
L_MM = 240.0           # the abscissa a whole turn would take (μ_φ = 2π/L); the diagrams draw its working angle only
POLE_MM = (15.0, 50.0)  # the lab's range of pole distances, set with a ruler in whole millimetres


def read(mm: np.ndarray, precision: float) -> np.ndarray:
    """A length read with a ruler of ``precision`` mm (0: exact)."""
    mm = np.asarray(mm, dtype=float)
    return mm if precision <= 0 else np.round(mm / precision) * precision


def nice(mu: float) -> float:
    """The standard scale at or above ``mu`` (1, 2, 2.5, 4, 5 × 10^k)."""
    return min(m for m in series_around(mu) if m >= mu * (1 - 1e-12))


def series_phi(mu_phi: float, rad: bool = True) -> float:
    """The standard μ_φ (rad/mm) at or coarser than ``mu_phi``: of the series in °/mm (1, 2, 2.5, 4,
    5·10^k °/mm: 1 °/mm is the lab's μ_φ = 2π/360 mm) and, ``rad``, of the series in rad/mm
    (0,02 рад/мм) the finer — the abscissa as long as the zone lets it be, its scale one a reader
    takes off it (the A1 sheet's 1,15 °/mm asked for 2 °/mm in degrees alone, half its length)."""
    deg = math.radians(nice(math.degrees(mu_phi)))
    return min(deg, nice(mu_phi)) if rad else deg


@dataclass
class CamConstruction:
    """The drawn construction: the division turns, the drawn ordinates (mm) and what they read."""
    phi: np.ndarray                 # division turns, degrees (rise and return, their ends included)
    phase: np.ndarray               # 0 rise, 1 return
    mu_phi: float                   # rad/mm
    mu_a: float                     # (m or rad)/rad² per mm
    mu_v: float
    mu_s: float
    H1: float
    H2: float
    precision: float
    a_mm: np.ndarray                # the analogue acceleration, drawn at the divisions
    v_mm: np.ndarray                # ds/dφ by the first integration
    s_mm: np.ndarray                # s by the second
    R0_min: float                   # measured off the phase diagram, m (rad for none)
    R0: float                       # the base radius drawn (the exact solution's)
    radius_mm: np.ndarray           # the centre profile's radius at each division, measured
    theta: np.ndarray               # the pressure angle measured at each division, degrees
    mu_l: float                     # m/mm of the profile
    warnings: list[tuple[str, str]] = field(default_factory=list)
    closing: tuple[float, float] = (0.0, 0.0)   # the integral's closing error of the rise and the return, mm
    # the chord construction as drawn: each interval's mean ordinate (read, mm; NaN where a phase's
    # ds/dφ is drawn directly) carried to the ordinate axis and joined to the pole, and the vertices of
    # the integral's chords laid parallel to those rays (before they are read; per division)
    a_mid: np.ndarray = field(default_factory=lambda: np.zeros(0))
    v_mid: np.ndarray = field(default_factory=lambda: np.zeros(0))
    v_chord: np.ndarray = field(default_factory=lambda: np.zeros(0))
    s_chord: np.ndarray = field(default_factory=lambda: np.zeros(0))
    # the closing error the s diagram may have (closing_bound, mm) and, where the drawing was redrawn
    # with more divisions for it, the first drawing's divisions and closing errors (mm)
    closing_bound: float = math.inf
    # n, Δ rise, Δ return, the bound (mm)[, whether the scene named those n]
    redrawn: tuple[int, float, float, float] | tuple[int, float, float, float, bool] | None = None
    rocking: bool = False           # a rocking follower: its displacement is the arm's angle ψ, not s
    # a rocking follower's phase diagram enlarged by the sheet where it has room (m/mm; None: at μ_l)
    mu_phase: float | None = None
    # a set of sheets draws s on a sheet of its own, d²s/dφ² and ds/dφ on the one before
    # (sheets.cam.set_sizes: the three on one sheet below the legibility minimum)
    split: bool = False
    R0_drawn: float = math.nan      # |OC₀| as drawn on the phase diagram (m), before it is read (R0_min)

    @property
    def closes(self) -> bool:
        """Whether both phases' s closed within the bound (closing_bound)."""
        return max(abs(self.closing[0]), abs(self.closing[1])) <= self.closing_bound + 1e-9

    @property
    def s(self) -> np.ndarray:
        return self.s_mm * self.mu_s

    @property
    def v(self) -> np.ndarray:
        return self.v_mm * self.mu_v

    @property
    def a(self) -> np.ndarray:
        return self.a_mm * self.mu_a


def working_angle(cam) -> float:
    """The working angle φ_р = φ_п + φ_вв + φ_с (rad) over which the lab draws the diagrams (the near
    dwell, where s, ds/dφ and d²s/dφ² are zero, left off the abscissa: μ_φ = φ_р/L)."""
    rise, far, ret, _ = cam.phases
    return math.radians(rise + far + ret)


def divisions(sol: Solution, n: int) -> tuple[np.ndarray, np.ndarray]:
    """The division turns of the rise and of the return (n intervals each), and their phases."""
    rise, far, ret, _ = sol.cam.phases
    up = np.linspace(0.0, rise, n + 1)
    down = rise + far + np.linspace(0.0, ret, n + 1)
    return np.concatenate([up, down]), np.concatenate([np.zeros(n + 1, int), np.ones(n + 1, int)])


def division_numbers(phases, count: int) -> list[int]:
    """The number each of the ``count`` division turns (divisions: rise then return, their ends
    included) carries on the sheet, 0… along the working angle: a point of the cam one number. With a
    far dwell the rise's end N and the return's start N+1 are two turns; with none (``phases``' far
    dwell 0) they are one point, numbered N once, and the return goes on N+1…2N (stop 49: "10; 11"
    on one point read as two, and Table 1 printed the row twice)."""
    half = count // 2
    shared = float(phases[1]) <= 0.0
    return [k if (k < half or not shared) else k - 1 for k in range(count)]


def _integrate_phase(x_mm: np.ndarray, y_mm: np.ndarray, pole: float, y0: float, precision: float,
                     mid: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """One phase integrated by chords: the middle ordinates (given, else the chord's middle of the
    drawn curve) read with the ruler, the chords laid parallel to the rays from the pole, their
    vertices' ordinates read too. Returns (read ordinates, mean ordinates, chord vertices)."""
    if mid is None:
        mid = 0.5 * (y_mm[:-1] + y_mm[1:])
    mid = read(mid, precision)
    chord = integrate_by_chords(x_mm, mid, pole, y0)
    return read(chord, precision), mid, chord


def mean_ordinates(cam, phi_deg: np.ndarray, phase: np.ndarray) -> np.ndarray:
    """Each interval's mean ordinate of d²s/dφ² (per rad²): the height of the step of equal area the
    chord method lays over the interval (Артоболевський, graphical integration: the curve replaced by
    steps, the areas cut off above and below the step equal), in closed form
    ā_k = (1/Δφ)∫ d²s/dφ² dφ = (ds/dφ(φ_{k+1}) − ds/dφ(φ_k))/Δφ. Where the curve is smooth over the
    interval this is its middle ordinate to within Δφ²·a''/24; where a law's corner falls inside it
    (the trapezoidal law's at 1/8, 3/8, 5/8, 7/8 of the phase: at 12 divisions the middles of
    intervals 2, 5, 8, 11) the middle ordinate is the corner's and overstates the step by up to
    1/12 of the peak, the error the second integration heaps up to ≈ peak·Δφ² — 3.4 % of the stroke
    at 12 divisions, more than the closing rule allows (stop 47)."""
    _, v, _ = motion(cam, phi_deg, phase)
    return np.diff(v) / np.radians(np.diff(np.asarray(phi_deg, dtype=float)))


def equal_area_shift(s: np.ndarray, v: np.ndarray, phi_deg: np.ndarray) -> np.ndarray:
    """How far the step of equal area of the curve ds/dφ over each interval stands from its chord's
    middle (per rad; REFERENCE §10, the lab's correction for chords: the horizontal moved up or down
    until the two curvilinear triangles it cuts off have equal areas), in closed form
    Δs/Δφ − (ds/dφ(φ_k) + ds/dφ(φ_{k+1}))/2 — the mean of the curve less the trapezoid's. Over a
    curve bending up (the cycloidal rise's first interval) the chord's middle stands above the curve
    and overstates the step; over one bending down (near the top) it understates it."""
    return np.diff(s) / np.radians(np.diff(np.asarray(phi_deg, dtype=float))) - 0.5 * (v[:-1] + v[1:])


def pole_distance(h: float) -> float:
    """A pole distance one sets with a ruler: ``h`` rounded to a whole millimetre within the lab's
    15–50 mm (POLE_MM)."""
    return float(min(POLE_MM[1], max(POLE_MM[0], round(h))))


def construct(sol: Solution, n: int | None = None, precision: float = 0.5, H1: float | None = None,
              H2: float | None = None, L: float | None = None, size: float = 1.0,
              profile_size: float = 1.0, height: float | None = None, measure: bool = True,
              accel: float | None = None, series: bool | str = False) -> CamConstruction:
    """The graphical construction of ``sol``'s cam with ``n`` intervals a phase (the scene's by default),
    read with a ruler of ``precision`` mm. ``size`` enlarges the diagrams (L, the tallest ordinate and
    the stroke drawn) and ``profile_size`` the profile, each scale then the standard one at or above
    what that asks (the sheet takes the largest that fit their zones, sheets.cam.cam_sizes); ``height``
    (default ``size``) enlarges the ordinates alone, ``accel`` (default ``height``) those of d²s/dφ²
    alone (μ_s kept: the poles move out, ds/dφ grows as its square root). ``measure=False`` leaves R0 unmeasured (NaN):
    a trial of the drawings' sizes. ``series``: the scales a drawing's reader takes off it from the
    standard series (GOST 2.302; the lab's 1, 2, 2.5, 4, 5·10^k) — μ_φ in °/mm (``series="rad"``: or in
    rad/mm, series_phi) and μ_s —, the poles
    whole millimetres and μ_a, μ_v the derived ones (μ_a = μ_s/(μ_φ²·H1·H2), μ_v = μ_a·μ_φ·H1: the
    a-diagram about ``accel``'s height); else μ_a standard and μ_s derived."""
    cam = sol.cam
    n = n or cam.divisions
    phi, phase = divisions(sol, n)
    L = L or L_MM * size
    height = size if height is None else height
    accel = height if accel is None else accel
    mu_phi = 2 * math.pi / L              # the turn's; the diagrams drawn over the working angle φ_р alone,
    #                                       its abscissa L_р = φ_р/μ_φ (the lab's μ_φ = φ_р/L_р)
    if series:                            # μ_φ of the series, at or coarser than L asks (no longer)
        mu_phi = series_phi(mu_phi, rad=series == "rad")
    fine = np.linspace(0.0, 360.0, 7201)
    _, _, a_fine = motion(cam, fine)
    peak = float(np.max(np.abs(a_fine))) or 1.0
    mu_a = nice(peak / (HEIGHT_MM * accel))
    if series:
        # μ_s of the series; H1·H2 = μ_s/(μ_a·μ_φ²) in whole millimetres (15–50), μ_a = the derived one
        mu_s_series = nice(cam.stroke / (STROKE_MM * height))
        if cam.rocking:                   # ψ is read in degrees: μ_ψ standard in °/mm
            mu_s_series = math.radians(nice(math.degrees(cam.stroke) / (STROKE_MM * height)))
        product = mu_s_series / ((peak / (HEIGHT_MM * accel)) * mu_phi ** 2)
        # H2 such that ds/dφ's tallest ordinate, v·μ_φ·H2/μ_s, is about d²s/dφ²'s (HEIGHT_MM·accel):
        # neither takes the height the s diagram needs
        v_peak = float(np.max(np.abs(motion(cam, fine)[1]))) or 1.0
        H2 = H2 or pole_distance(HEIGHT_MM * accel * mu_s_series / (v_peak * mu_phi))
        H1 = H1 or pole_distance(product / H2)
        mu_a = mu_s_series / (mu_phi ** 2 * H1 * H2)
    if H1 is None or H2 is None:
        # the stroke drawn about STROKE_MM high: H1 and H2 whole millimetres (15–50) near what that
        # asks; the scales follow from them, μ_v = μ_a·μ_φ·H1, μ_s = μ_v·μ_φ·H2 (the lab's formula)
        mu_s_target = nice(cam.stroke / (STROKE_MM * height))
        H = math.sqrt(mu_s_target / (mu_a * mu_phi ** 2))
        H1 = H1 or pole_distance(H)
        H2 = H2 or pole_distance(mu_s_target / (mu_a * mu_phi ** 2 * H1))
    mu_v = mu_a * mu_phi * H1
    mu_s = mu_v * mu_phi * H2
    s_ex, v_ex, a_ex = motion(cam, phi, phase)
    x_mm = np.radians(phi) / mu_phi
    a_mm = read(a_ex / mu_a, precision)
    v_mm = np.zeros_like(phi)
    s_mm = np.zeros_like(phi)
    v_chord, s_chord = np.zeros_like(phi), np.zeros_like(phi)
    a_mid, v_mid = [], []
    for k in (0, 1):
        sel = phase == k
        x = x_mm[sel]
        start = 0.0 if k == 0 else cam.stroke / mu_s
        if cam.laws[k] == "linear":                       # drawn directly: a constant ds/dφ
            v_mm[sel] = read(v_ex[sel] / mu_v, precision)
            v_chord[sel] = v_mm[sel]
            a_mid.append(np.full(len(x) - 1, np.nan))
        else:
            # each interval's mean ordinate of the drawn analogue acceleration (mean_ordinates: the
            # step of equal area the chord method lays over the interval, its middle ordinate where the
            # curve is straight or gently curved, not where a law's corner lies inside the interval)
            a_m = mean_ordinates(cam, phi[sel], phase[sel])
            v_mm[sel], mid, v_chord[sel] = _integrate_phase(x, a_mm[sel], H1, 0.0, precision, mid=a_m / mu_a)
            a_mid.append(mid)
        # the ds/dφ curve's step of equal area over each interval: the chord's middle moved by the
        # curvilinear triangles' difference (stop 48: the chord's middle alone, the trapezoid rule,
        # put ψ 48 % over at the cycloidal rise's first division, a 0.63 mm error on a 1.37 mm ordinate)
        s_mid = v_mm[sel][:-1] + 0.5 * np.diff(v_mm[sel]) + equal_area_shift(s_ex[sel], v_ex[sel], phi[sel]) / mu_v
        s_mm[sel], mid, s_chord[sel] = _integrate_phase(x, v_mm[sel], H2, start, precision, mid=s_mid)
        v_mid.append(mid)
    s_mm, closing = close_phases(s_mm, phase, cam.stroke / mu_s, precision)
    s_g, v_g = s_mm * mu_s, v_mm * mu_v
    # the phase diagram: the smallest base radius at which no drawn point exceeds the allowed angle
    R0_min = _phase_diagram_radius(sol, phi, phase, s_g, v_g) if measure else math.nan
    # the profile about 200 mm across: its largest radius 100 mm at a standard μ_l
    largest = float(np.max(np.abs(profile(cam, sol.geometry, np.linspace(0.0, 360.0, 721))["P"])))
    mu_l = nice(largest / (PROFILE_MM * profile_size))
    # R0 is measured where it is drawn: |OC₀| on the phase diagram, a translating follower's at μ_s (its s
    # axis reads across from the s diagram's), a rocking follower's at the profile's μ_l here and
    # again at the scale the sheet draws it at (phase_drawn_at: sheets.cam.construct_on for the terminal
    # and the JSON, the sheet's own choice on the sheet; stop 47). Stop 46: read at μ_l, the
    # translating phase diagram's 164.74 mm (65.897 mm at μ_s = 0.4 mm/mm) was printed 65.5 mm, −0.6 %
    mu_read = mu_l if cam.rocking else mu_s
    R0_drawn = R0_min
    R0_min = float(read(R0_min / mu_read, precision)) * mu_read
    prof = profile(cam, sol.geometry, phi, s_g, v_g, np.zeros_like(phi))
    radius_mm = read(prof["radius"] / mu_l, precision)
    theta = np.round(prof["theta"] * 2) / 2 if precision > 0 else prof["theta"]   # a protractor's ½°
    out = CamConstruction(phi, phase, mu_phi, mu_a, mu_v, mu_s, H1, H2, precision, a_mm, v_mm, s_mm, R0_min,
                          sol.geometry.R0, radius_mm, theta, mu_l, closing=closing, a_mid=np.concatenate(a_mid),
                          v_mid=np.concatenate(v_mid), v_chord=v_chord, s_chord=s_chord)
    out.R0_drawn = R0_drawn
    out.closing_bound = closing_bound(cam.stroke / mu_s, precision)
    out.rocking = cam.rocking
    if not out.closes:
        out.warnings.append(closing_warning(out))
    return out


def phase_drawn_at(g: CamConstruction, mu: float | None) -> CamConstruction:
    """``g`` with a rocking follower's phase diagram drawn at ``mu`` (m/mm; None: at the profile's
    μ_l) and R0 read off it there, with the ruler of ``g``'s precision: |OC₀|/μ mm read, times μ — the
    sheet's enlarged diagram (2.5:1) gives R0 to 0.2 mm where 1:1 gave it to 0.5 (stop 47: the sheet
    drew 2.5:1 and printed the 1:1 reading)."""
    import dataclasses
    if not g.rocking:                 # a translating follower's phase diagram stands at μ_s, read there
        return g
    at = mu or g.mu_l
    R0 = g.R0_min if not math.isfinite(g.R0_drawn) else float(read(g.R0_drawn / at, g.precision)) * at
    return dataclasses.replace(g, mu_phase=mu, R0_min=R0)


PHASE_CURVE_STEPS = 240   # the phase diagram's curve drawn through each active phase in this many steps


def phase_curve(cam) -> tuple[np.ndarray, np.ndarray]:
    """The turns (deg) at which the phase diagram's curve is drawn through the rise and the return, and
    their phases (0, 1): the curve the [ϑ] lines are laid tangent to (drawing.cam.phase_diagram)."""
    rise, far, ret, _ = cam.phases
    t = np.linspace(0.0, 1.0, PHASE_CURVE_STEPS + 1)
    return (np.concatenate([rise * t, rise + far + ret * t]),
            np.repeat([0, 1], PHASE_CURVE_STEPS + 1))


def _phase_diagram_radius(sol: Solution, phi, phase, s_g, v_g) -> float:
    """The smallest R0 at which no drawn point (s, ds/dφ) and no point of the curve drawn through them
    is seen at more than [ϑ] of its phase: the [ϑ] lines laid tangent to the curve (REFERENCE §11), not
    through its nearest drawn point — between two divisions the curve bulges past such a line (stop 50:
    the linear/cycloidal cam's return line through point 14 cut the curve between 13 and 14, R0 read
    35.8 mm of the exact 36.70, −2.5 %, a cam that would exceed [ϑ] = 40°)."""
    from scipy.optimize import brentq
    cam = sol.cam
    fine, fine_phase = phase_curve(cam)
    s_f, v_f, _ = motion(cam, fine, fine_phase)
    phi = np.concatenate([np.asarray(phi, dtype=float), fine])
    phase = np.concatenate([np.asarray(phase), fine_phase])
    s_g, v_g = np.concatenate([np.asarray(s_g, dtype=float), s_f]), np.concatenate([np.asarray(v_g, dtype=float), v_f])

    def worst(R0: float) -> float:
        try:
            g = geometry(cam, R0, sol.geometry.e)
        except Exception:
            return math.inf
        th = np.abs(profile(cam, g, phi, s_g, v_g, np.zeros_like(phi))["theta"])
        return max(float(np.max(th[phase == k])) / cam.allowed[k] for k in (0, 1)) - 1.0
    if cam.rocking:
        lo = abs(cam.centre_distance - cam.arm) * (1 + 1e-9) + 1e-9
        hi = (cam.centre_distance + cam.arm) * (1 - 1e-9)
        scan = np.linspace(lo, hi, 241)
        ok = [k for k, R in enumerate(scan) if worst(R) <= 0]
        if not ok:
            return math.nan
        if ok[0] == 0:
            return float(lo)
        return float(brentq(worst, scan[ok[0] - 1], scan[ok[0]], xtol=1e-12))
    lo = abs(sol.geometry.e) * (1 + 1e-9) + 1e-9
    hi = max(2 * sol.R0_min, lo * 2)
    while worst(hi) > 0:
        hi *= 2
    if worst(lo) <= 0:
        return float(lo)
    return float(brentq(worst, lo, hi, xtol=1e-12))


CLOSING_LIMIT = 2.0    # %: of the stroke drawn, the closing error of the s diagram the lab's 5 % allows


def closing_bound(stroke_mm: float, precision: float) -> float:
    """The closing error (mm) the s diagram may have: 2 % of the stroke drawn (CLOSING_LIMIT), plus
    the ruler's half division the end ordinate is read to. Laid back over the divisions (close_phases)
    Δ moves each ordinate by Δ·k/n; on the return an ordinate of a quarter of the stroke stands at
    k/n ≈ 0.7, so it moves by about 2.8·Δ/h of itself — at 2 % about the lab's 5 %. Past it the
    diagrams are redrawn with more divisions (sheets.cam.construct_on)."""
    return CLOSING_LIMIT / 100.0 * abs(stroke_mm) + 0.5 * precision


def divisions_of(g: "CamConstruction") -> int:
    """The intervals of each phase the construction was drawn with."""
    return int(len(g.phi) // 2 - 1)


def closing_warning(g: "CamConstruction", better: int | None = None, tried: bool = False) -> tuple[str, str]:
    """The warning of a closing past the rule (closing_bound): the closing errors, the bound,
    and how many divisions would close within the rule (``better``; ``tried``: none of those tried
    does)."""
    n = divisions_of(g)

    def mm(x: float, comma: bool) -> str:
        text = f"{x:.1f}".replace("-", "−")
        return text.replace(".", ",") if comma else text
    b2 = f"{g.closing_bound:.2f}"
    r, t = (mm(x, False) for x in g.closing)
    b = b2
    q = "ψ" if g.rocking else "s"      # a rocking follower's arm angle ψ
    en = (f"the graphical {q} at {n} divisions missed its closing by Δ = {r} mm (rise), {t} mm (return), more than "
          f"the {b} mm allowed ({CLOSING_LIMIT:g}\u00a0% of the stroke drawn and the ruler's half division)")
    r, t = (mm(x, True) for x in g.closing)
    b = b2.replace(".", ",")
    uk = (f"графічне {q} при {n} поділках не замкнулося на Δ = {r} мм (підйом), {t} мм (опускання) — більше за "
          f"допустимі {b} мм ({CLOSING_LIMIT:g}\u00a0% ходу на кресленні й половина поділки лінійки)")
    if better is not None:
        en += f"; {better} divisions would close within it"
        uk += f"; у межах допуску замкнулося б при {better} поділках"
    elif tried:
        en += "; no number of divisions tried closes within it: take a larger scale"
        uk += "; жодна випробувана кількість поділок не замикає в межах допуску: візьміть більший масштаб"
    else:
        en += ": take more divisions"
        uk += ": візьміть більше поділок"
    return en, uk


def close_phases(s_mm: np.ndarray, phase: np.ndarray, stroke_mm: float, precision: float
                 ) -> tuple[np.ndarray, tuple[float, float]]:
    """The s diagram closed as a traverse is: the integral's end ordinate of the rise should be the
    stroke (of the return, zero); its closing error Δ is laid off back over the phase's divisions in
    proportion to the turn, y_k ← y_k − Δ·k/n (each move read with the ruler), so the rise ends at the
    stroke and the return at zero. Returns the closed ordinates and Δ of the rise and the return (mm)."""
    out = np.array(s_mm, dtype=float)
    errors = []
    for k, target in ((0, float(read(stroke_mm, precision))), (1, 0.0)):
        idx = np.flatnonzero(phase == k)
        delta = float(out[idx[-1]] - target)
        frac = np.arange(len(idx)) / (len(idx) - 1)
        out[idx] = out[idx] - read(delta * frac, precision)
        errors.append(delta)
    return out, (errors[0], errors[1])


SHORT_DIVISIONS = 2    # an ordinate under this many ruler divisions: δ not judged (errors_pct)


def errors_pct(graphical: np.ndarray, exact: np.ndarray, scale: float, least: float = 0.0) -> list[float | None]:
    """The lab's percent error, None where the exact value is below 1 % of the quantity's largest or
    below ``least`` — the value whose ordinate is SHORT_DIVISIONS ruler divisions (2·0.5 mm·μ): read
    to half a division, a 0.4 mm ordinate is 0.5 mm, +25 %, and a 1 mm one ±25 %; a δ there says
    how short the ordinate is, not how well the construction was drawn, and the table prints "—"."""
    out = []
    for g, e in zip(np.asarray(graphical, float), np.asarray(exact, float)):
        pct = 100.0 * (g - e) / abs(e) if abs(e) >= max(0.01 * scale, least) * (1 - 1e-12) else None
        out.append(None if pct is None else (0.0 if abs(pct) < 1e-9 else float(pct)))   # round-off is 0
    return out
