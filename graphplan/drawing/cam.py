"""The cam's construction drawn (records in drawing mm, y up): the three diagrams of the law with
their chords and poles, the phase diagram with the lines at the allowed pressure angle, and the
profile by inversion with the base circle, the follower's turned positions, the centre and working
profiles. Each record carries its scales."""
from __future__ import annotations

import math

import numpy as np

from graphplan.exact.cam import Solution, centre_path, motion, profile
from graphplan.graphic.cam import CamConstruction
from graphplan.graphic.record import Record

LAYER = "cam"
TEXT = 3.5


def _clear_label(rec: Record, at: complex, text: str) -> None:
    """A point's letter where the lines leave most room: of eight places around the point, the one
    whose letter box lies farthest from every line drawn so far."""
    segs = []
    for p in rec.items:
        if p.kind in ("segment", "vector", "polyline") and len(p.points) >= 2:
            segs += [(complex(*a), complex(*b)) for a, b in zip(p.points[:-1], p.points[1:])]

    def dist(q: complex, a: complex, b: complex) -> float:
        d = b - a
        t = 0.0 if abs(d) == 0 else max(0.0, min(1.0, ((q - a) * d.conjugate()).real / abs(d) ** 2))
        return abs(q - (a + t * d))
    best, where = -1.0, at
    for k in range(8):
        c = at + 5.0 * complex(math.cos(k * math.pi / 4), math.sin(k * math.pi / 4))
        box = [c + complex(dx, dy) for dx in (-1.5, 0.0, 1.5) for dy in (-2.0, 0.0, 2.0)]
        room = min((dist(q, a, b) for q in box for a, b in segs), default=99.0)
        if room > best:
            best, where = room, c
    rec.label((where.real - 1.2, where.imag - 1.7), text, size=TEXT, layer=LAYER)


def _axes(rec: Record, y0: float, width: float, top: float, bottom: float, letter: str, k: int) -> None:
    rec.segment((0.0, y0), (width + 6.0, y0), role="axis", layer=LAYER, step=f"axis {k}")
    rec.segment((0.0, y0 + bottom - 3.0), (0.0, y0 + top + 3.0), role="axis", layer=LAYER)
    rec.label((2.0, y0 + top + 4.0), letter, size=TEXT, layer=LAYER)


def diagrams(sol: Solution, g: CamConstruction, lang: str) -> Record:
    """d²s/dφ², ds/dφ and s over the turn (L mm), one above another; the drawn ordinates at the
    divisions, the chords of each integration, the poles H1, H2 on the left."""
    cam = sol.cam
    rec = Record("cam diagrams")
    L = 2 * math.pi / g.mu_phi
    fine = np.linspace(0.0, 360.0, 721)
    s, v, a = motion(cam, fine)
    xf = np.radians(fine) / g.mu_phi
    x = np.radians(g.phi) / g.mu_phi
    bands = []
    y = 0.0
    for key, curve, drawn, letter in (("s", s / g.mu_s, g.s_mm, "s"), ("v", v / g.mu_v, g.v_mm, "ds/dφ"),
                                      ("a", a / g.mu_a, g.a_mm, "d^2s/dφ^2")):
        lo, hi = min(float(np.min(curve)), 0.0), max(float(np.max(curve)), 0.0)
        y0 = y - lo
        bands.append((key, y0))
        _axes(rec, y0, L, hi, lo, letter, len(bands))
        rec.add("polyline", list(zip(xf, y0 + curve)), role="curve", layer=LAYER, step=f"{key}(φ) exact")
        for k in range(len(x)):
            rec.segment((x[k], y0), (x[k], y0 + drawn[k]), role="construction", layer=LAYER)
        for ph in (0, 1):
            sel = np.flatnonzero(g.phase == ph)
            for j in range(len(sel) - 1):
                p, q = sel[j], sel[j + 1]
                rec.segment((x[p], y0 + drawn[p]), (x[q], y0 + drawn[q]), role="chord", layer=LAYER)
        y = y0 + hi + 14.0
    for name, H, (_, y0) in (("H_1", g.H1, bands[1]), ("H_2", g.H2, bands[0])):
        rec.point((-H, y0), role="pole", layer=LAYER)
        rec.segment((-H, y0), (0.0, y0), role="construction", layer=LAYER)
        rec.label((-H, y0 + 2.0), name, size=TEXT, layer=LAYER)
    rec.label((L + 2.0, bands[0][1] - 5.0), "φ", size=TEXT, layer=LAYER)
    rec.scales.update(mu_phi=g.mu_phi, mu_a=g.mu_a, mu_v=g.mu_v, mu_s=g.mu_s, H1=g.H1, H2=g.H2)
    return rec


def phase_points(sol: Solution, g: CamConstruction) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The phase diagram's construction in the fixed frame (complex, m; the cam's centre O at 0): at
    each division the roller's centre C from the drawn s, the direction u of its motion as s grows, and
    the point K = C + iσ·dC/dφ — the velocity analogue (ds/dφ, rocking l·dψ/dφ) laid off from C along
    u turned by 90° in the sense of ω. The line OK is the profile's normal (dP/dφ·e^{iσφ} = C′ − iσC =
    −iσ·(C + iσC′)), so the angle between OK and u is the pressure angle ϑ (exact.cam.profile)."""
    cam = sol.cam
    C, C1, _, u = centre_path(cam, sol.geometry, g.s, g.v, np.zeros_like(g.s))
    return C, u, C + 1j * cam.sense * C1


def phase_diagram(sol: Solution, g: CamConstruction, lang: str) -> Record:
    """The phase diagram as the textbook draws it, in the fixed frame at the scale of s (rocking: the
    arm's arcs l·ψ at μ_s·l): the follower's axis (rocking: the arc of the roller's centre and the arm's
    lines toward its pivot), the drawn ds/dφ laid off from each position of the roller's centre turned
    by 90° in the sense of ω, the lines at [ϑ] to the follower's motion through the points seen at the
    largest angle, bounding the region of the cam's centre, and the centre O chosen in it, joined to
    those points: the angles drawn at O's lines are the pressure angles."""
    cam = sol.cam
    rec = Record("phase diagram")
    mu = g.mu_s * (cam.arm if cam.rocking else 1.0)
    C, u, K = phase_points(sol, g)
    C, K = C / mu, K / mu
    sig = cam.sense
    # the exact curve of K over the active phases, thin
    fine = np.concatenate([np.linspace(0.0, cam.phases[0], 241),
                           cam.phases[0] + cam.phases[1] + np.linspace(0.0, cam.phases[2], 241)])
    s, v, a = motion(cam, fine)
    Cf, C1f, _, _ = centre_path(cam, sol.geometry, s, v, a)
    Kf = (Cf + 1j * sig * C1f) / mu
    half = len(fine) // 2
    for part in (Kf[:half], Kf[half:]):
        rec.add("polyline", list(zip(part.real, part.imag)), role="curve", layer=LAYER, step="phase curve exact")
    if cam.rocking:        # the arc of the roller's centre about the arm's pivot
        A = cam.centre_distance / mu
        ang = np.angle(C - A)
        t = np.linspace(float(np.min(ang)) - 0.05, float(np.max(ang)) + 0.05, 61)
        arc = A + cam.arm / mu * np.exp(1j * t)
        rec.add("polyline", list(zip(arc.real, arc.imag)), role="trajectory", layer=LAYER, step="roller path")
        for k in range(len(C)):     # the arm's line through C (toward the pivot) and K
            w = (C[k] - A) / abs(C[k] - A)
            ends = sorted([0.0, float(((K[k] - C[k]) * w.conjugate()).real)])
            p0, p1 = C[k] + (ends[0] - 4.0) * w, C[k] + (ends[1] + 4.0) * w
            rec.segment((p0.real, p0.imag), (p1.real, p1.imag), role="construction", layer=LAYER, step=f"arm {k}")
    else:                  # the follower's axis
        x = float(C[0].real)
        top = float(max(np.max(C.imag), np.max(K.imag))) + 6.0
        rec.segment((x, -4.0), (x, top), role="axis", layer=LAYER, step="follower axis")
        rec.label((x + 1.5, top - 3.0), "s", size=TEXT, layer=LAYER)
    for k in range(len(C)):
        if abs(K[k] - C[k]) > 1e-9:
            rec.segment((C[k].real, C[k].imag), (K[k].real, K[k].imag), role="construction", layer=LAYER,
                        step=f"ds/dφ {k}")
        rec.point((K[k].real, K[k].imag), role="construction", layer=LAYER, step=f"K {k}")
    O = 0j
    for ph in (0, 1):
        # the boundary of the allowed region: through the drawn point seen from O at the largest angle
        # to the follower's motion, at [ϑ] to it, down past O; O joined to that point
        idx = np.flatnonzero(g.phase == ph)
        seen = [abs(float(np.angle((O - K[k]) / -u[k]))) for k in idx]
        k = int(idx[int(np.argmax(seen))])
        beta = float(np.angle((O - K[k]) / -u[k]))
        turn = math.radians(cam.allowed[ph]) * (1.0 if beta >= 0 else -1.0)
        d = -u[k] * complex(math.cos(turn), math.sin(turn))
        length = abs(O - K[k]) * 1.15 + 8.0
        end = K[k] + d * length
        rec.segment((K[k].real, K[k].imag), (end.real, end.imag), role="direction", layer=LAYER,
                    step=f"[ϑ] line {ph}")
        rec.segment((K[k].real, K[k].imag), (O.real, O.imag), role="construction", layer=LAYER, step=f"OK {ph}")
    rec.point((O.real, O.imag), role="pole", layer=LAYER, step="O")
    _clear_label(rec, O, "O")
    rec.scales.update(mu_phase=mu)
    return rec


def profile_drawing(sol: Solution, g: CamConstruction, lang: str) -> Record:
    """The profile by inversion at μ_l: the base circle, the follower's axis at each division turned
    against ω, the drawn s laid off, the centre profile through those points, the roller circles and
    the working profile."""
    cam = sol.cam
    rec = Record("cam profile")
    mu = g.mu_l
    rec.circle((0.0, 0.0), sol.geometry.R0 / mu, role="construction", layer=LAYER)
    fine = np.linspace(0.0, 360.0, 1441)
    p = sol.at(fine)
    P, W = p["P"] / mu, p["working"] / mu
    rec.add("polyline", list(zip(P.real, P.imag)), role="curve", layer=LAYER, step="centre profile")
    if cam.roller > 0:
        rec.add("polyline", list(zip(W.real, W.imag)), role="link", layer=LAYER, step="working profile")
    pts = profile(cam, sol.geometry, g.phi, g.s, g.v, np.zeros_like(g.phi))["P"] / mu
    back = np.exp(-1j * cam.sense * np.radians(g.phi))     # the follower turned against ω
    if cam.rocking:        # the pivot's circle; each arm from its turned pivot to the roller's centre
        rec.circle((0.0, 0.0), cam.centre_distance / mu, role="trajectory", layer=LAYER)
        feet = cam.centre_distance / mu * back
    else:                  # the offset's circle; each axis from its foot on it to the point laid off
        e = sol.geometry.e / mu
        if abs(e) > 0.5:
            rec.circle((0.0, 0.0), abs(e), role="trajectory", layer=LAYER)
        feet = cam.sense * e * back
    for k, q in enumerate(pts):
        rec.segment((feet[k].real, feet[k].imag), (q.real, q.imag), role="construction", layer=LAYER)
        rec.point((q.real, q.imag), role="construction", layer=LAYER)
        if cam.roller > 0 and k % 2 == 0:
            rec.circle((q.real, q.imag), cam.roller / mu, role="construction", layer=LAYER)
    rec.point((0.0, 0.0), role="pole", layer=LAYER)
    r0 = sol.geometry.R0 / mu
    rays = np.sort(np.mod(np.angle(pts), 2 * math.pi))
    gaps = np.diff(np.append(rays, rays[0] + 2 * math.pi))
    k = int(np.argmax(gaps))
    mid = rays[k] + gaps[k] / 2                           # the widest sector without a ray
    side = mid - gaps[k] / 4                              # R0 drawn there, O's letter on the bisector
    rec.segment((0.0, 0.0), (r0 * math.cos(side), r0 * math.sin(side)), role="construction", layer=LAYER)
    along = complex(math.cos(side), math.sin(side))
    near = 7.0 if cam.rocking else max(7.0, abs(sol.geometry.e / mu) + 5.0)   # outside the offset's circle
    for text, c in (("O", near * complex(math.cos(mid), math.sin(mid))),
                    ("R_0", 0.6 * r0 * along + 4.0 * along * 1j)):      # beside the radius, toward O's side
        rec.label((c.real - 1.2 * len(text.replace("_", "")), c.imag - 1.7), text, size=TEXT, layer=LAYER)
    rec.scales.update(mu_l=mu)
    return rec


def records(sol: Solution, g: CamConstruction, lang: str) -> dict[str, Record]:
    return {"diagrams": diagrams(sol, g, lang), "phase": phase_diagram(sol, g, lang),
            "profile": profile_drawing(sol, g, lang)}
