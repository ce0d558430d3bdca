"""The flywheel construction as records (drawing mm, y up): the moments' diagram with the pole
construction of the integration, the work diagrams A_c and A_d, the ΔT diagram, the I*_m diagram,
the energy–mass (Wittenbauer) diagram with its two tangents and the intercept kl, and the speed
ω(φ) of the steady states — each a record for the sheet (graphic.flywheel measured them)."""
from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from graphplan.drawing.diagrams import fmt
from graphplan.drawing.labels import FAR, place_beside, place_labels, row_clear
from graphplan.graphic.record import POINT_INK, LabelRequest, Primitive, Record, line_pitch
from graphplan.model.motors import latin
from graphplan.util.words import column_decimals, fixed, num

if TYPE_CHECKING:
    from graphplan.graphic.flywheel import Flywheel

LAYER = "diagrams"
AXIS_W = 0.35
TEXT = 3.5
NUM = 2.5

WORDS = {
    "uk": {"moments": "Зведені моменти сил опору і рушійних сил", "work": "Роботи сил опору і рушійних сил",
           "energy": "Зміна кінетичної енергії ΔT = A_д − A_с", "inertia": "Зведений момент інерції механізму",
           "witt": "Діаграма енергія–маса (Віттенбауера)", "speed": "Кутова швидкість кривошипа ω(φ) за оберт",
           "classical": "сталий M^*_д, маховик точно", "motor": "двигун {name}, маховик {fl} кг·м²", "motor_none": "двигун {name}, маховик не потрібен",
           "classical_none": "сталий M^*_д, маховик не потрібен",
           "mm": "мм", "Nm": "Н·м", "J": "Дж", "kgm2": "кг·м²", "rad": "рад", "s": "с",
           "kl": "|kl| = {kl} мм", "axis": "вісь ΔT", "Mc": "M^*_с", "Md": "M^*_д", "Ac": "A_с", "Ad": "A_д",
           "Im": "I^*_м"},
    "en": {"moments": "Reduced moments of the resistance and driving forces", "work": "Work of the resistance and driving forces",
           "energy": "Change of kinetic energy ΔT = A_d − A_c", "inertia": "Reduced moment of inertia of the mechanism",
           "witt": "Energy–mass (Wittenbauer) diagram", "speed": "Crank speed ω(φ) over a turn",
           "classical": "constant M^*_d, exact flywheel", "motor": "motor {name}, flywheel {fl} kg·m²", "motor_none": "motor {name}, no flywheel needed",
           "classical_none": "constant M^*_d, no flywheel needed",
           "mm": "mm", "Nm": "N·m", "J": "J", "kgm2": "kg·m²", "rad": "rad", "s": "s",
           "kl": "|kl| = {kl} mm", "axis": "ΔT axis", "Mc": "M^*_c", "Md": "M^*_d", "Ac": "A_c", "Ad": "A_d",
           "Im": "I^*_m"},
}


DELTA_DIGITS = 3     # significant figures of every achieved δ on the sheet and in the notes (0,0236 < 0,03)


def delta_text(value: float, lang: str) -> str:
    """An achieved coefficient of unevenness δ = (ω_max − ω_min)/ω_m as the sheet writes it
    everywhere (legend, Tables 2 and 3, notes): ``DELTA_DIGITS`` significant figures, 0,0156 —
    one value written one way (stop 50: 0,01559 in the legend beside 0,0156 in Table 2)."""
    return num(value, lang, DELTA_DIGITS)


def achieved(value: float, given: float, lang: str) -> str:
    """The δ a steady state achieves as the lab writes it: the given value as given (0,05, not
    0,050000) where the two agree to ``DELTA_DIGITS`` significant figures, else the value itself
    (``delta_text``)."""
    return num(given, lang) if delta_text(value, lang) == delta_text(given, lang) else delta_text(value, lang)


def motor_omega(lang: str) -> str:
    """The symbol of the crank's mean speed in the motor's steady state (markup): ω_m is the
    flywheel's, the scene's n_1 (πn_1/30); the motor's, through the reducer, is another speed."""
    return "ω_{m дв}" if lang == "uk" else "ω_{m mot}"


def motor_delta(lang: str) -> str:
    """The symbol of the coefficient of unevenness the motor's steady state achieves (markup): δ is
    the one asked for; the motor's, below it where no flywheel is needed, is another value."""
    return "δ_{дв}" if lang == "uk" else "δ_{mot}"


def _extent(*arrays) -> tuple[float, float]:
    v = np.concatenate([np.atleast_1d(np.asarray(a, dtype=float)) for a in arrays] + [[0.0]])
    return float(v.min()), float(v.max())


def _text(rec: Record, at: tuple[float, float], text: str, step: str = "", anchor: str = "start") -> None:
    """A symbol or a caption in the diagrams' lettering (markup: M^*_с, I^*_м)."""
    rec.label(at, text, size=TEXT, anchor=anchor, layer=LAYER, step=step)


def _axes(rec: Record, lo: float, hi: float, x_from: float, L: float, sym: str,
          xsym: str = "φ", step: str = "") -> None:
    rec.vector((0.0, lo - 1.0), (0.0, hi + 8.0), role="construction", width=AXIS_W, layer=LAYER, step=f"axes {step}")
    rec.vector((x_from, 0.0), (L + 10.0, 0.0), role="construction", width=AXIS_W, layer=LAYER, step=f"axes {step}")
    _text(rec, (1.8, hi + 5.0), sym, step=f"axes {step}")
    rec.label((L + 11.5, -1.2), xsym, size=TEXT, layer=LAYER, step=f"axes {step}")


def _every(length: float, n: int) -> int:
    """Every how many divisions a number is lettered: 1, 2, 4 … so that numbers stand ≥ 5 mm apart."""
    every = 1
    while length / n * every < 5.0:
        every *= 2
    return every


def _lettered(k: int, n: int, every: int) -> bool:
    """Whether division ``k`` of ``n`` is numbered: every ``every``-th and the last, n — but not a
    multiple of ``every`` closer than that to n (93 divisions numbered by twos: 90 and 93, not 92
    and 93 on one another)."""
    return k == n or (k % every == 0 and n - k >= every)


def _number(at: tuple[float, float], k: int, anchor: str = "middle") -> Primitive:
    """Division ``k``'s number (not yet on the record: ``_numbers`` sets the row clear of the lines)."""
    return Primitive("text", (at,), role="label", layer=LAYER, step="division numbers", text=str(k), size=NUM,
                     anchor=anchor)


def _numbers(rec: Record, row: list[Primitive], away: tuple[float, float] = (0.0, -1.0)) -> None:
    """The division numbers added once every line is drawn, the row moved as one ``away`` from its
    axis until it keeps clear of them (drawing.labels.row_clear: the French curve dips below its
    lowest division point, a turned curve beyond its axis)."""
    rec.items.extend(row_clear(rec, row, away))


def _added_numbers(rec: Record, f: Flywheel, at: list[complex], rivals: list[complex],
                   avoid: np.ndarray | None = None) -> None:
    """The added points (where M*_c jumps or bends: graphic.flywheel ``division_points``) lettered as
    the draftsman letters them, the division before primed (6′: Flywheel ``added_label``), each beside
    its dot (``at``, in the order of ``f.added``) or on a leader, nearer it than any of ``rivals`` (the
    divisions' points) — a dot between two divisions with no name was a point the teacher could not
    name (stop 57)."""
    for j, z in zip(f.added, at):
        others = tuple(r for r in (*rivals, *at) if abs(r - z) > 1e-6)
        text = f.added_label(j)
        place_beside(rec, [LabelRequest(z, text, 1j, NUM, step="added point number", sight=True, across=False,
                                        rivals=others)], layer=LAYER, avoid=avoid, keep_whole=KEEP_WHOLE)


def _ordinates(rec: Record, f: Flywheel, lo: float, hi: float, numbers_at: float | None) -> list[Primitive]:
    """The division ordinates; the numbers under them at ``numbers_at`` (returned, for ``_numbers``)."""
    n = f.divisions
    every = _every(f.L, n)
    row = []
    for k, xk in enumerate(f.x):
        if k:
            rec.segment((xk, lo), (xk, hi), role="grid", layer=LAYER, step="division ordinates")
        if numbers_at is not None and _lettered(k, n, every):
            row.append(_number((float(xk), numbers_at), k))
    return row


DRAWN = 0.01      # mm: the most a drawn curve's polyline departs from the construction's samples


def drawn(X: np.ndarray, Y: np.ndarray) -> list[tuple[float, float]]:
    """The polyline a pen draws of a sampled curve: the samples (graphic.flywheel: 40 an interval,
    14 400 at 360 divisions) simplified by Douglas–Peucker (shapely) to within ``DRAWN`` mm of them —
    a few hundred vertices, the same line on paper, what the lettering keeps clear of."""
    from shapely import LineString
    line = LineString(np.column_stack([X, Y])).simplify(DRAWN, preserve_topology=False)
    return [(float(x), float(y)) for x, y in line.coords]


def _smooth(f: Flywheel, y: np.ndarray, positive: bool = False) -> tuple[np.ndarray, np.ndarray]:
    """The French curve through a periodic diagram's division ordinates; a ``positive`` quantity's
    (I*_m) as the energy–mass curve draws it (graphic.flywheel.inertia_curve: the spline, the
    shape-preserving cubic only in an interval where the spline would dip below zero) — the I*(φ)
    diagram and the Wittenbauer curve beside it are one I*."""
    from graphplan.graphic.flywheel import inertia_curve
    fine = np.linspace(0.0, f.L, 4 * int(f.L) + 1)
    x, corners = f.x, ()
    for name in ("dT", "I", "A_drawn"):          # the divisions' ordinates: the curve passes every constructed
        if y is getattr(f, name):                # point, the added ones (where M*_c bends) too
            x, y = f.points(name)
            corners = f.corners if name == "dT" else ()
            fine = np.union1d(fine, x)
    if positive:
        return fine, inertia_curve(x, y, f.L, fine)
    from graphplan.graphic.flywheel import energy_curve
    return fine, energy_curve(x, y, f.L, fine, corners)


ORDINATE_LEAST = 1.0   # mm: an ordinate shorter than this is neither projected to the M axis nor rayed to P (a
#                        draftsman omits it: its line would run along the φ axis; the chord is drawn level)
PROJECTION_LEAST = 2.5  # mm: one shorter than this is not projected (its dashed line would lie along the φ axis);
#                         its ray to P still marks its height on the M axis
PROJECTION_SPACING = 3.0  # mm: the least distance between two projections, and from a projection to M*_d's line


def projected_middles(M_mid, Md: float, x_mid) -> list[int]:
    """The middles of the intervals whose ordinates are projected (dashed) to the M axis: every
    projection runs from its point to the axis, so any two overlap over the shorter one's length and
    must stand ``PROJECTION_SPACING`` apart, as must a projection and the line of M*_d; none nearer
    the φ axis than ``PROJECTION_LEAST``. Taken from the largest ordinate down (the diagram's
    extremes carry its readings; of two alike the one nearer the M axis: the shorter line), each kept
    where it clears those kept before — the rest are carried by their rays alone (the ray from P ends
    at the ordinate's height on the M axis), so the idle stroke's small ordinates draw no striped
    band over the φ axis."""
    kept: list[int] = []
    for k in sorted(range(len(M_mid)), key=lambda j: (-abs(float(M_mid[j])), float(x_mid[j]), j)):
        y = float(M_mid[k])
        if abs(y) < PROJECTION_LEAST or abs(y - Md) < PROJECTION_SPACING:
            continue
        if all(abs(y - float(M_mid[j])) >= PROJECTION_SPACING for j in kept):
            kept.append(k)
    return sorted(kept)


def moments_record(f: Flywheel, lang: str = "uk") -> Record:
    """a) M*_c(φ) with the constant M*_d, the pole P at H and the rays to the middles' heights;
    b) below it, A_c by chords and the straight A_d on the same abscissa."""
    w = WORDS[lang]
    rec = Record(w["moments"], scales={"mu_M": f.mu_M, "mu_phi": f.mu_phi, "mu_A": f.mu_A, "H_mm": f.H})
    lo, hi = _extent(f.M, f.M_mid, [f.Md], f.dyn.cycle.samples.moment / f.mu_M)
    _axes(rec, lo, hi, -f.H - 4.0, f.L, f"{w['Mc']}, {w['Md']}, {w['Nm']}", step="M")
    row = _ordinates(rec, f, lo, hi, lo - 5.0)
    fine = np.linspace(0.0, f.L, 4 * int(f.L) + 1)
    curve = f.dyn.cycle.moment(fine * f.mu_phi) / f.mu_M     # the diagram plotted from the computed M*_c
    rec.add("polyline", list(zip(fine, curve)), role="curve", layer=LAYER, step="M*_c(φ)")
    for xk, yk in zip(f.x, f.M):
        rec.point((xk, yk), role="construction", layer=LAYER, step="M*_c at the divisions")
    xa = f.points("M")[0]                      # the intervals: between divisions and added points
    for j in f.added:
        rec.point((float(xa[j]), float(f.M_all[j])), role="construction", layer=LAYER, step="M*_c at the added points")
        rec.segment((float(xa[j]), 0.0), (float(xa[j]), float(f.M_all[j])), role="grid", layer=LAYER,
                    step="added ordinates")
    xm = 0.5 * (xa[:-1] + xa[1:])
    pole = (-f.H, 0.0)
    rec.point(pole, role="joint", layer=LAYER, step="pole P")
    rec.label((-f.H - 1.8, 1.2), "P", size=TEXT, anchor="end", layer=LAYER, step="pole P")
    shown = set(projected_middles(f.M_mid, f.Md, xm))
    for k, (xk, yk) in enumerate(zip(xm, f.M_mid)):
        if abs(yk) >= ORDINATE_LEAST:        # a near-zero ordinate is not rayed: its ray would lie on the axis
            if k in shown:                   # projected where it reads (``projected_middles``)
                rec.segment((xk, yk), (0.0, yk), role="projection", layer=LAYER, step=f"M at the middle of {k}–{k + 1}")
            rec.segment(pole, (0.0, yk), role="ray", layer=LAYER, step=f"ray P–{k + 1}")
        rec.point((xk, yk), role="construction", layer=LAYER, step=f"M at the middle of {k}–{k + 1}")
        if k in (f.equal_area_all if f.added else f.equal_area):   # the equal-area mean: its horizontal
            rec.segment((float(xa[k]), yk), (float(xa[k + 1]), yk), role="construction", layer=LAYER,
                        step=f"equal-area mean of {k}–{k + 1}")
    rec.segment((0.0, f.Md), (f.L, f.Md), role="result", layer=LAYER, step="M*_d = A_c/2π")
    _dimension(rec, -f.H, 0.0, lo - 10.0, "H")
    _numbers(rec, row)
    _added_numbers(rec, f, [complex(float(xa[j]), float(f.M_all[j])) for j in f.added],
                   [complex(float(xk), float(yk)) for xk, yk in zip(f.x, f.M)])
    place_labels(rec, [LabelRequest(complex(f.L, f.Md), w["Md"], 1 + 0.3j, TEXT, step="M*_d"),
                       LabelRequest(complex(f.L, float(f.M[-1])), w["Mc"], 1 - 0.3j, TEXT, step="M*_c")],
                 layer=LAYER)
    graduate_axis(rec, graduation(hi, f.mu_M, bottom_mm=lo), f.mu_M, lang, step="M graduation")
    # b) the work diagrams, below
    a_lo, a_hi = _extent(f.A_drawn)
    y0 = lo - 22.0 - a_hi - 8.0
    rec.extend(_work(f, w, lang).moved(0.0, y0))
    return rec


def moments_least(f: Flywheel) -> tuple[float, float]:
    """The least box (w, h mm) ``moments_record`` can take, its lettering left out: the M axis from
    the pole's side (−H − 4) to L + 10, and from under the work diagram's axis (set 30 mm + its
    height under M's lowest ordinate) to 8 mm over M's highest — a drawing composed where this
    box does not fit need not be drawn to know it does not."""
    lo, hi = _extent(f.M, f.M_mid, [f.Md], f.dyn.cycle.samples.moment / f.mu_M)
    a_lo, a_hi = _extent(f.A_drawn)
    return f.L + f.H + 14.0, (hi + 8.0) - (lo - 31.0 - a_hi + a_lo)


def _work(f: Flywheel, w: dict, lang: str) -> Record:
    rec = Record("work")
    lo, hi = _extent(f.A_drawn)
    _axes(rec, lo, hi, -3.0, f.L, f"{w['Ac']}, {w['Ad']}, {w['J']}", step="A")
    row = _ordinates(rec, f, lo, hi, lo - 5.0)
    xa, ya = f.points("A_drawn")               # the chords: over the divisions and the added points
    for k in range(len(xa) - 1):
        rec.segment((xa[k], ya[k]), (xa[k + 1], ya[k + 1]), role="chord", layer=LAYER,
                    step=f"chord {k}–{k + 1} ∥ ray P–{k + 1}")
        rec.point((xa[k + 1], ya[k + 1]), role="construction", layer=LAYER, step=f"A_c at {k + 1}")
    for j in f.added:
        rec.segment((float(xa[j]), 0.0), (float(xa[j]), float(ya[j])), role="grid", layer=LAYER,
                    step="added ordinates")
    fine, curve = _smooth(f, f.A_drawn)
    rec.add("polyline", list(zip(fine, curve)), role="curve", layer=LAYER, step="A_c(φ)")
    rec.segment((0.0, 0.0), (f.L, float(f.A_drawn[-1])), role="result", layer=LAYER, step="A_d (constant M_d)")
    _numbers(rec, row)
    graduate_axis(rec, graduation(hi, f.mu_A, bottom_mm=lo), f.mu_A, lang, step="A graduation")
    return place_labels(rec, [LabelRequest(complex(f.L, float(f.A_drawn[-1])), f"{w['Ad']} = {w['Ac']}", 1 + 0.3j,
                                           TEXT, step="A_d")], layer=LAYER)


def _dimension(rec: Record, x0: float, x1: float, y: float, text: str) -> None:
    rec.segment((x0, 0.0), (x0, y - 1.5), role="construction", layer=LAYER, step=text)
    mid = 0.5 * (x0 + x1)
    rec.vector((mid, y), (x0, y), role="construction", layer=LAYER, step=text)
    rec.vector((mid, y), (x1, y), role="construction", layer=LAYER, step=text)
    rec.label((mid, y - 4.5), text, size=TEXT, anchor="middle", layer=LAYER, step=text)


def _read_diagram(f: Flywheel, title: str, scales: dict[str, float], values: np.ndarray,
                  sym: str, name: str, lang: str, positive: bool = False) -> Record:
    """A diagram over φ of ordinates read at the divisions, joined by the French curve
    (``_smooth``: shape-preserving for a ``positive`` quantity)."""
    rec = Record(title, scales=scales)
    fine, curve = _smooth(f, values, positive)
    lo, hi = _extent(values, curve)          # the axis and its values span the curve's peaks too
    _axes(rec, lo, hi, -3.0, f.L, sym, step=name)
    row = _ordinates(rec, f, lo, hi, lo - 5.0)
    for xk, yk in zip(f.x, values):
        rec.point((xk, yk), role="construction", layer=LAYER, step=f"{name} read")
    for nm in ("dT", "I"):
        if values is getattr(f, nm):
            xa, ya = f.points(nm)
            for j in f.added:
                rec.segment((float(xa[j]), 0.0), (float(xa[j]), float(ya[j])), role="grid", layer=LAYER,
                            step="added ordinates")
                rec.point((float(xa[j]), float(ya[j])), role="construction", layer=LAYER, step=f"{name} at an added point")
    rec.add("polyline", list(zip(fine, curve)), role="curve", layer=LAYER, step=f"{name}(φ)")
    _numbers(rec, row)
    mu = next(iter(scales.values()))
    graduate_axis(rec, graduation(hi, mu, bottom_mm=lo), mu, lang, step=f"{name} graduation")
    return rec


def energy_axis(f: Flywheel, lang: str) -> str:
    """The ΔT axis's lettering: the quantity, its unit and its scale ("ΔT, Дж; μ_T = 0,6093 Дж/мм")."""
    w = WORDS[lang]
    return f"ΔT, {w['J']}; μ_T = {num(f.mu_T, lang)} {w['J']}/{w['mm']}"


def energy_record(f: Flywheel, lang: str = "uk") -> Record:
    """ΔT(φ) = A_d − A_c, read between the lines of the work diagram (μ_T = μ_A)."""
    return _read_diagram(f, WORDS[lang]["energy"], {"mu_T": f.mu_T}, f.dT, energy_axis(f, lang), "ΔT", lang)


def inertia_record(f: Flywheel, lang: str = "uk") -> Record:
    """I*_m(φ) at μ_I."""
    return _read_diagram(f, WORDS[lang]["inertia"], {"mu_I": f.mu_I}, f.I, WORDS[lang]["Im"], "I*_m", lang,
                         positive=True)


PROJ_LAYER = "construction"   # the thin projection lines that carry ΔT across and I* up
PROJECTED = 24                # at most this many points carried across by projection lines


def projected(n: int) -> range:
    """The division points whose projections are drawn: all of up to ``PROJECTED``, else every 2nd,
    4th … (a draftsman projects the numbered points; 360 divisions would bury the diagram)."""
    every = 1
    while n / every > PROJECTED:
        every *= 2
    return range(0, n, every)


CROWDED = 2.0   # mm: two parallel projections nearer than this (about 1 mm of paper between their dashes) run as a
#                 striped band (review SIXBAR7: ΔT of positions 16–22 0,4–1,7 mm apart) — each drawn short instead
STUB = 5.0      # mm: a crowded projection's length at each of its ends (from its point toward the other diagram)


def crowded(values, js) -> set[int]:
    """The projected divisions ``js`` whose projection would run within ``CROWDED`` of one drawn
    through (their ``values`` in mm: ΔT_k for the horizontal ones, I_k for the vertical; all of one
    kind run side by side along the whole gap between the diagrams): taken in order of division, each
    drawn through where it clears those drawn through before, else short — from each end's point
    ``STUB`` mm toward the other diagram, the ruler carrying the height between (the point still
    where its two projections meet), as a draftsman stops a thin line where it would run by a
    neighbour: no striped band, the lines drawn through ≥ ``CROWDED`` apart."""
    through: list[float] = []
    short: set[int] = set()
    for j in js:
        v = float(values[j])
        if any(abs(v - u) < CROWDED for u in through):
            short.add(j)
        else:
            through.append(v)
    return short


def _projection(rec: Record, a: tuple[float, float], b: tuple[float, float], short: bool, step: str) -> None:
    """The projection from the point ``a`` toward ``b`` (along one horizontal or vertical): the whole
    line, or ``short`` only its first ``STUB`` mm from ``a`` (``crowded``)."""
    if short:
        d = math.hypot(b[0] - a[0], b[1] - a[1])
        if d > STUB:
            b = (a[0] + (b[0] - a[0]) * STUB / d, a[1] + (b[1] - a[1]) * STUB / d)
    rec.segment(a, b, role="projection", layer=PROJ_LAYER, step=step)


def projected_x(f: Flywheel, length: float) -> np.ndarray:
    """The divisions' abscissae on a φ axis ``length`` mm long (the ΔT(φ) and the turned I*(φ)
    diagrams of the projection: their φ scale is free, their ordinates' μ_T and μ_I are not)."""
    return np.asarray(f.x) * (length / f.L)


def energy_projected(f: Flywheel, lang: str, length: float, reach: float) -> Record:
    """ΔT(φ) beside the energy–mass diagram (the textbook's elimination of φ): the read ordinates
    ΔT_k at μ_T = μ_A over a φ axis ``length`` mm long, and from each division point a thin
    horizontal projection line to x = ``reach`` (the energy–mass diagram's side, same height)."""
    w = WORDS[lang]
    rec = Record(w["energy"], scales={"mu_T": f.mu_T})
    xs = projected_x(f, length)
    fine, curve = _smooth(f, f.dT)
    lo, hi = _extent(f.dT, curve)              # the axis title over the curve's highest point, not through it
    n = f.divisions
    rec.vector((0.0, lo - 1.0), (0.0, hi + 8.0), role="construction", width=AXIS_W, layer=LAYER, step="axes ΔT")
    rec.vector((-3.0, 0.0), (length + 10.0, 0.0), role="construction", width=AXIS_W, layer=LAYER, step="axes ΔT")
    _text(rec, (1.8, hi + 5.0), energy_axis(f, lang), step="axes ΔT")
    every = _every(length, n)
    row = []
    for k, xk in enumerate(xs):
        if k:
            rec.segment((xk, lo), (xk, hi), role="grid", layer=LAYER, step="division ordinates")
        if _lettered(k, n, every):
            row.append(_number((float(xk), lo - 5.0), k))
    for xk, yk in zip(xs, f.dT):
        rec.point((xk, yk), role="construction", layer=LAYER, step="ΔT read")
    xa, ya = f.points("dT")
    for j in f.added:                          # the added points (where M*_c bends): their ordinates drawn
        xj = float(xa[j]) * (length / f.L)
        rec.segment((xj, 0.0), (xj, float(ya[j])), role="grid", layer=LAYER, step="added ordinates")
        rec.point((xj, float(ya[j])), role="construction", layer=LAYER, step="ΔT at an added point")
    rec.add("polyline", list(zip(fine * (length / f.L), curve)), role="curve", layer=LAYER, step="ΔT(φ)")
    short = crowded(f.dT, projected(n))
    for j in projected(n):
        _projection(rec, (float(xs[j]), float(f.dT[j])), (reach, float(f.dT[j])), j in short,
                    f"projection of ΔT at {j}")
    _numbers(rec, row)
    graduate_axis(rec, graduation(hi, f.mu_T, bottom_mm=lo), f.mu_T, lang, step="ΔT graduation")
    _added_numbers(rec, f, [complex(float(xa[j]) * (length / f.L), float(ya[j])) for j in f.added],
                   [complex(float(xk), float(yk)) for xk, yk in zip(xs, f.dT)])
    place_labels(rec, [LabelRequest(complex(length + 10.0, 0.0), "φ", 1 - 1j, TEXT, step="axes ΔT",
                                    breaks=True)], layer=LAYER)   # at its arrow, the projections broken under it
    return _cleared(rec, "axes ΔT", "φ")


PHI_CLEAR = 1.5    # mm: the projections stop this far from φ (a dash's own gap is about 1 mm: broken nearer, φ
#                    read as standing on the dashed line — review 7 #11)


def _cleared(rec: Record, step: str, text: str) -> Record:
    """The thin projection lines broken ``PHI_CLEAR`` around the letter ``text`` of ``step``."""
    from graphplan.drawing.labels import break_under
    for word in [p for p in rec.items if p.kind == "text" and p.step == step and p.text == text]:
        ink = word.ink()
        rec.items[:] = [q for p in rec.items for q in
                        (break_under(p, ink, PHI_CLEAR) if p.role == "projection" and p.kind == "segment" else [p])]
    return rec


CONSTANT_TURNED = 60.0    # mm: the φ axis of a constant I*_m's turned diagram (a line: nothing to read along φ)


def constant_inertia(f: Flywheel) -> bool:
    """I*_m the same at every division (a moment-loaded four-bar whose only masses turn about fixed
    axes): its diagram is a line, the energy–mass curve the ΔT axis's parallel through it."""
    return float(np.ptp(f.I)) == 0.0


def turned_length(f: Flywheel, length: float) -> float:
    """The φ axis of the turned I*_m(φ): ``length`` (ΔT(φ)'s), or ``CONSTANT_TURNED`` where I*_m is
    constant — a 250 mm panel holding one straight line is drawn compactly, with its note."""
    return min(length, CONSTANT_TURNED) if constant_inertia(f) else length


def inertia_turned(f: Flywheel, lang: str, length: float, reach: float) -> Record:
    """I*_m(φ) turned by 90° under the energy–mass diagram: I* to the right at the same μ_I (its
    I* axis the energy–mass diagram's), φ running downward over ``length`` mm (``turned_length``:
    shorter for a constant I*, which is then said beside the line); from each division point a thin
    vertical projection line up to y = ``reach``."""
    w = WORDS[lang]
    rec = Record(w["inertia"], scales={"mu_I": f.mu_I})
    length = turned_length(f, length)
    ys = -projected_x(f, length)
    fine, curve = _smooth(f, f.I, positive=True)            # I* > 0: never drawn left of its φ axis
    hi = max(float(np.max(f.I)), float(np.max(curve)))       # the grid and the values span the curve's peak
    n = f.divisions
    rec.vector((0.0, 1.0), (0.0, -length - 10.0), role="construction", width=AXIS_W, layer=LAYER, step="axes I*_m")
    rec.vector((-1.0, 0.0), (hi + 8.0, 0.0), role="construction", width=AXIS_W, layer=LAYER, step="axes I*_m")
    _text(rec, (hi + 9.5, -1.2), f"{w['Im']}, {w['kgm2']}", step="axes I*_m")
    rec.label((0.0, -length - 15.0), "φ", size=TEXT, anchor="middle", layer=LAYER, step="axes I*_m")
    every = _every(length, n)
    row = []
    for k, yk in enumerate(ys):
        if k:
            rec.segment((0.0, yk), (hi, yk), role="grid", layer=LAYER, step="division ordinates")
        if _lettered(k, n, every):
            row.append(_number((-2.0, float(yk) - 0.9), k, anchor="end"))
    for yk, ik in zip(ys, f.I):
        rec.point((ik, yk), role="construction", layer=LAYER, step="I*_m read")
    rec.add("polyline", list(zip(curve, -fine * (length / f.L))), role="curve", layer=LAYER, step="I*_m(φ)")
    xa, ia = f.points("I")
    added = [complex(float(ia[j]), -float(xa[j]) * (length / f.L)) for j in f.added]
    for z in added:                            # the added points (where M*_c bends), as on ΔT(φ)
        rec.point((z.real, z.imag), role="construction", layer=LAYER, step="I*_m at an added point")
    short = crowded(f.I, projected(n))
    for j in projected(n):
        _projection(rec, (float(f.I[j]), float(ys[j])), (float(f.I[j]), reach), j in short,
                    f"projection of I* at {j}")
    _numbers(rec, row, away=(-1.0, 0.0))
    _graduate(rec, hi, f.mu_I, lang, float(ys[-1]))
    _added_numbers(rec, f, added, [complex(float(ik), float(yk)) for yk, ik in zip(ys, f.I)])
    if constant_inertia(f):               # the line's meaning said beside it, right of the grid
        value = f"{num(float(f.I[0]) * f.mu_I, lang)} {w['kgm2']}"
        text = (f"{w['Im']} = {value} — стала" if lang == "uk" else f"{w['Im']} = {value}, constant")
        rec.label((hi + 3.0, -0.5 * length - 1.2), text, size=NUM, layer=LAYER, step="I*_m constant")
    return rec


GRADUATION = (12.0, 8.0)     # mm: the least distance between two graduated values of an axis, and
#                              the closest allowed where that leaves fewer than two values on it


def graduation(top_mm: float, mu: float, least: tuple[float, ...] = GRADUATION, bottom_mm: float = 0.0,
               step: float | None = None) -> list[float]:
    """The values graduated along an axis drawn at ``mu`` (units a mm) from ``bottom_mm`` (≤ 0) up to
    ``top_mm`` mm: the multiples of the smallest round step (1, 2, 2,5, 5 ×10^k) whose ticks stand
    ``least[0]`` mm apart or more — closer (down to ``least[-1]``) where that gives fewer than two
    values —, or of ``step`` where given (another diagram's at the same μ: the same ticks); zero left
    out (the origin carries its own number)."""
    if top_mm - bottom_mm <= 0.0 or mu <= 0.0:
        return []

    def at(step_: float) -> list[float]:
        low, high = math.ceil(bottom_mm * mu / step_ - 1e-9), math.floor(top_mm * mu / step_ + 1e-9)
        return [k * step_ for k in range(low, high + 1) if k]
    if step is not None:
        return at(step)
    values: list[float] = []
    for gap in least:
        values = at(_nice(gap * mu))
        if len(values) >= 2:
            break
    return values


def graduation_step(values: list[float]) -> float | None:
    """The step of a graduation (``graduation``), None where it has fewer than two values; zero, left
    out of the values (the origin's own number), counted among them (−10 and 10 step by 10, not 20:
    no multiple of 20 among them, the axis was left unlettered — stop 53's screen)."""
    if len(values) < 2:
        return None
    ticks = sorted({*values, 0.0}) if min(values) < 0.0 < max(values) else list(values)
    return min(abs(b - a) for a, b in zip(ticks, ticks[1:]))


GRADUATION_CLEAR = 0.5   # mm of paper between a graduation's value and any line (labels.CLEAR)
TICK = 1.5               # mm: a graduation's tick


def _free_boxes(rec: Record, breaking: bool = False):
    """A test whether a box of lettering keeps ``GRADUATION_CLEAR`` of paper from every line of
    ``rec`` (each by its half width) and ``labels.APART`` from its lettering (shapely's STRtree over
    the strokes ``labels.strokes`` gives); ``breaking``: from every line but the thin construction
    lines a value may break (``labels.breakable``: the projections, the rays, the grid), and
    ``labels.NUMBERS_APART`` from a number in any case (a point's 11 by −50 read −50,11)."""
    from shapely import STRtree, box, linestrings
    from graphplan.drawing.labels import APART, breakable, strokes
    ends, halves = [], []
    for p in rec.items:
        if p.kind == "text" or (breaking and breakable(p)):
            continue
        for a, b, hw in strokes(p):
            ends.append((a, b))
            halves.append(hw)
    segs = linestrings(np.asarray(ends, dtype=float)) if ends else []   # all at once (shapely ≥ 2)
    tree = STRtree(segs) if ends else None
    from graphplan.drawing.labels import NUMBERS_APART, is_number
    texts = [(box(*p.ink()), NUMBERS_APART if is_number(p.text) else APART)
             for p in rec.items if p.kind == "text" and (p.text or "").strip()]

    reach = GRADUATION_CLEAR + (max(halves) if halves else 0.0)

    def free(bx: tuple[float, float, float, float]) -> bool:
        g = box(*bx)
        if tree is not None:     # the box grown along x and y, as the sheet's check grows it
            x0, y0, x1, y1 = bx  # (labels.collisions): a slanted line by a corner is nearer than the
            for i in tree.query(box(x0 - reach, y0 - reach, x1 + reach, y1 + reach)):   # distance says
                d = GRADUATION_CLEAR + halves[i]
                if segs[i].intersects(box(x0 - d, y0 - d, x1 + d, y1 + d)):
                    return False
        return all(t.distance(g) >= apart for t, apart in texts)
    return free


def lettered_steps(unit: float) -> tuple[int, ...]:
    """Every how many ticks of step ``unit`` an axis may be lettered: each tick, every 2nd, or every
    4th, 5th or 10th where that lettered step is itself round — 1, 2, 2,5 or 5 × 10^k (a draftsman
    letters 0,1 and 0,2 over ticks every 0,025, never 0,125 and 0,25: stop 49's A2 energy–mass axis)."""
    def round_(v: float) -> bool:
        if v <= 0.0:
            return False
        m = v / 10 ** math.floor(math.log10(v) + 1e-9)
        return any(abs(m - r) < 1e-6 for r in (1.0, 2.0, 2.5, 5.0, 10.0))
    return tuple(e for e in (1, 2, 4, 5, 10) if e <= 2 or round_(unit * e))


def axis_decimals(values) -> int:
    """The decimals an axis's lettered ``values`` are all written to: the most any of them needs
    (0,02 … 0,12 → 2: "0,10", not "0,1" among "0,08" and "0,12"; 12,2 … 13,4 → 1: "13,0") — a
    scale's numbers to one count of decimals, as a draftsman letters them."""
    def own(v: float) -> int:
        for d in range(7):
            if abs(v * 10 ** d - round(v * 10 ** d)) < 1e-6 * max(1.0, abs(v) * 10 ** d):
                return d
        return 6
    return max((own(float(v)) for v in values), default=0)


def axis_value(v: float, decimals: int, lang: str) -> str:
    """``v`` lettered on an axis to ``decimals`` (``axis_decimals``); 0 as "0", a power of ten as
    ``num`` writes it."""
    text = num(v, lang)
    if v == 0 or "·10" in text:
        return text
    return fixed(v, lang, decimals)


def graduate_axis(rec: Record, values: list[float], mu: float, lang: str, vertical: bool = True,
                  sides: tuple[float, ...] = (-1.0, 1.0), step: str = "graduation", letter: bool = True
                  ) -> list[float]:
    """An ordinate axis through the record's origin graduated in its quantity at ``mu`` (units a
    mm), as the lab's sheets graduate them: a ``TICK`` at each of ``values`` (``graduation``: round
    numbers) and the values lettered beside their ticks on one side of the axis (``sides``: −1 left
    of a vertical axis, under a horizontal one; the first preferred) where they keep clear of the
    lines and lettering already drawn (the pole's rays left of the M axis, the projections): every
    value, else every 2nd, 4th, 5th or 10th tick's (a draftsman letters the major ticks, at a round
    step: ``lettered_steps``) — the finest such run of at least two values that all keep clear on one side; where none does, on one side
    among the thin lines, broken under them (``_breaking_run``). ``letter`` False: the ticks alone
    (an axis whose values read across from a diagram beside it). Returns the values lettered."""
    if not values:
        return []
    free = _free_boxes(rec) if letter else None
    from shapely import box as shape_box
    words = [shape_box(*p.ink()) for p in rec.items if p.kind == "text" and (p.text or "").strip()]

    def number(v: float, side: float, decimals: int | None = None) -> Primitive:
        """The value beside its tick, its ink ``TICK`` + 0.6 mm off the axis (a comma's tail too),
        to the run's ``decimals`` (``axis_decimals``; all the ticks' where not given)."""
        at = v / mu
        text = axis_value(v, axis_decimals(values) if decimals is None else decimals, lang)
        if vertical:                     # by its ink, not its advance (a "1" inks past its anchor)
            p = Primitive("text", ((0.0, at - 0.45 * NUM),), role="label", layer=LAYER, step=step,
                          text=text, size=NUM, anchor="end" if side < 0 else "start")
            x0, y0, x1, y1 = p.ink()
            return p.moved((-(TICK + 0.6) - x1) if side < 0 else (TICK + 0.6 - x0), 0.0)
        p = Primitive("text", ((at, 0.0),), role="label", layer=LAYER, step=step, text=text, size=NUM,
                      anchor="middle")
        x0, y0, x1, y1 = p.ink()
        return p.moved(0.0, (TICK + 0.6 - y0) if side > 0 else (-(TICK + 0.6) - y1))
    shown: list[float] = []
    side = sides[0]
    if letter:
        unit = graduation_step(values) or abs(values[0])
        for every in lettered_steps(unit):
            run = [v for v in values if abs(v / (unit * every) - round(v / (unit * every))) < 1e-6]
            ok = [sd for sd in sides if len(run) >= 2
                  and all(free(number(v, sd, axis_decimals(run)).ink()) for v in run)]
            if ok:
                shown, side = run, ok[0]
                break
        else:               # no whole run clear: on one side, the thin lines broken under them
            shown, side = _breaking_run(rec, values, sides, number)
    for v in values:                     # a tick that would run into a word (k, l) is left out
        at = v / mu
        a, b = ((0.0, at), (side * TICK, at)) if vertical else ((at, 0.0), (at, side * TICK))
        tick = shape_box(min(a[0], b[0]), min(a[1], b[1]), max(a[0], b[0]), max(a[1], b[1]))
        if all(wd.distance(tick) >= GRADUATION_CLEAR + AXIS_W / 2 for wd in words):
            rec.segment(a, b, role="construction", width=AXIS_W, layer=LAYER, step=step)
    for v in shown:
        rec.items.append(number(v, side, axis_decimals(shown)))
    return shown


def whole_run(values: list[float], shown: list[float]) -> bool:
    """Whether the lettered ``shown`` of an axis's ``values`` (``graduate_axis``) are a whole run —
    every value, or every 2nd, 4th, 5th or 10th tick's along the whole axis (a draftsman letters the major
    ticks) — and not a stretch with a tick left bare among or before the lettered ones (0,04 and 0,06
    beside 0,02's bare tick reads as a value forgotten)."""
    unit = graduation_step(values) or (abs(values[0]) if values else 0.0)
    if not shown or unit <= 0.0:
        return False
    runs = ([v for v in values if abs(v / (unit * every) - round(v / (unit * every))) < 1e-6] for every in lettered_steps(unit))
    return any(len(run) >= 2 and run == list(shown) for run in runs)


BREAK_CLEAR = 1.2    # mm: a thin line broken under a value this far from its ink


def _breaking_run(rec: Record, values: list[float], sides: tuple[float, ...], number) -> tuple[list[float], float]:
    """An axis's values where no two keep clear of its lines on either side (the projections and
    rays crowd it): as a draftsman letters them among his construction lines — on one side (the
    one where most are clear of all but the thin lines, the preferred first), every value, else
    every 2nd, 4th, 5th or 10th, clear of the drawing's other lines and lettering, the thin lines
    (``labels.breakable``) broken under each (``labels.break_under``): of the runs of every value,
    every 2nd, 4th, 5th or 10th, the longest stretch of consecutive values that keep clear (one step,
    none skipped: not 0,1 beside 0,125 and 0,225). The values lettered and their side."""
    from graphplan.drawing.labels import break_under, breakable
    free = _free_boxes(rec, breaking=True)
    side = max(sides, key=lambda sd: (sum(free(number(v, sd).ink()) for v in values), -sides.index(sd)))
    unit = graduation_step(values) or abs(values[0])
    shown: list[float] = []
    for every in lettered_steps(unit):           # the longest unbroken stretch of a run, the finest first
        block: list[float] = []
        for v in (v for v in values if abs(v / (unit * every) - round(v / (unit * every))) < 1e-6):
            block = block + [v] if free(number(v, side).ink()) else []
            if len(block) > len(shown):
                shown = block
    for v in shown:                 # a dash ending by a value would read as its minus: a wider gap
        ink = number(v, side).ink()
        rec.items[:] = [q for p in rec.items for q in (break_under(p, ink, BREAK_CLEAR) if breakable(p) else [p])]
    return shown, side


def _graduate(rec: Record, hi: float, mu: float, lang: str, foot: float) -> None:
    """The turned I*(φ) graduated in I* at μ_I along its foot, the line of φ = 2π at y = ``foot``
    (no projection line crosses it: each runs up from its point; the top axis, the energy–mass
    diagram's, is crossed by every one of them): a tick under it at each value of ``graduation``,
    the value under the tick; the scale lettered under the axis's symbol (I^*_м, кг·м²), as the ΔT
    axis's is."""
    w = WORDS[lang]
    values = graduation(hi, mu)
    for v in values:
        x = v / mu
        rec.segment((x, foot), (x, foot - 1.5), role="construction", width=AXIS_W, layer=LAYER, step="I* graduation")
        rec.label((x, foot - 1.5 - 0.6 - NUM), axis_value(v, axis_decimals(values), lang), size=NUM, anchor="middle", layer=LAYER,
                  step="I* graduation")
    rec.label((hi + 9.5, -1.2 - line_pitch(TEXT)), f"μ_I = {num(mu, lang)} {w['kgm2']}/{w['mm']}",
              size=NUM, layer=LAYER, step="axes I*_m")


_WITT: dict = {}
WITT_KEPT = 256      # energy–mass diagrams kept (``wittenbauer_record``): a construction's search draws ~130


TANGENT_PAST = 20.0      # mm: a tangent drawn past its touch point at most this far along it (15 mm across as
#                          before where that is shorter: tangents under 41° as they were)


def wittenbauer_record(f: Flywheel, lang: str = "uk", projections: tuple[float, float] | None = None) -> Record:
    """``energy_mass`` once per flywheel, language, projections and sketching (a copy each time): a
    sheet's composition asks for the same diagram many times, and its numbers' leaders are the
    costly part (a moment-loaded four-bar's dynamics took 41 s, 48 drawings of one diagram)."""
    from graphplan.drawing import labels as lb
    key = (id(f), lang, None if projections is None else tuple(round(v, 9) for v in projections), lb._SKETCH[-1])
    hit = _WITT.get(key)
    if hit is None or hit[0] is not f:
        if len(_WITT) >= WITT_KEPT:         # the oldest forgotten (all of them at once had the dynamics
            _WITT.pop(next(iter(_WITT)))    # construction draw 15 of its 129 diagrams twice: the drag-link)
        hit = _WITT[key] = (f, energy_mass(f, lang, projections))
    return hit[1].moved(0.0, 0.0)


def energy_mass(f: Flywheel, lang: str = "uk", projections: tuple[float, float] | None = None) -> Record:
    """ΔT over I*_m: the points of the divisions numbered, the French curve, the tangents at
    ψ_max and ψ_min cutting the ΔT axis at k and l, and |kl|. With ``projections`` (x of the
    left side, y of the foot) each point i is where the horizontal projection of ΔT(φ)'s point i
    from the left meets the vertical projection of the turned I*(φ)'s point i from below (the
    lettering then keeps off the lines: k, l to the left of the ΔT axis, |kl| under l)."""
    w = WORDS[lang]
    rec = Record(w["witt"], scales={"mu_I": f.mu_I, "mu_T": f.mu_T})
    X, Y = f.curve()
    tg = f.tangent
    k, l = tg["k"], tg["l"]
    x_hi = float(max(np.max(X), np.max(f.I))) + 8.0
    lo, hi = _extent(Y, f.dT, [k, l])
    rec.vector((0.0, lo - 6.0), (0.0, hi + 10.0), role="construction", width=AXIS_W, layer=LAYER, step="ΔT axis")
    rec.vector((-3.0, 0.0), (x_hi + 6.0, 0.0), role="construction", width=AXIS_W, layer=LAYER, step="I* axis")
    _text(rec, (x_hi + 7.5, -1.2), f"{w['Im']}, {w['kgm2']}", step="axes")     # its unit, as I*(φ)'s axis
    labels = [LabelRequest(complex(0.0, hi + 10.0), f"ΔT, {w['J']}", 1 + 0j, TEXT, step="axes")]
    numbers: list[list[LabelRequest]] = []
    rec.add("polyline", drawn(X, Y), role="curve", layer=LAYER, step="ΔT(I*): φ eliminated")
    n = f.divisions
    if projections is not None:
        left, foot = projections
        across, up = crowded(f.dT, projected(n)), crowded(f.I, projected(n))
        for j in projected(n):
            at = (float(f.I[j]), float(f.dT[j]))
            _projection(rec, at, (left, at[1]), j in across, f"projection of ΔT at {j}")
            _projection(rec, at, (at[0], foot), j in up, f"projection of I* at {j}")
    every = 1
    while n / every > 24:
        every *= 2
    dots = [complex(float(f.I[j]), float(f.dT[j])) for j in range(n)]
    middle = complex(float(np.mean(X)), float(np.mean(Y)))
    added = [complex(float(f.I_all[j]), float(f.dT_all[j])) for j in f.added]
    for j in f.added:                          # the added points (where M*_c bends): on the curve, dotted
        rec.point((float(f.I_all[j]), float(f.dT_all[j])), role="construction", layer=LAYER, step="added point")
    for j in range(n):
        rec.point((f.I[j], f.dT[j]), role="construction", layer=LAYER, step=f"point {j}")
    # the lettered points whose dots overlap (``coinciding``) take one number between them, as a student
    # letters them («0, 12»; the baler's «11′; 11′′; 12; 12′»): no leader says which of two overlapping
    # dots it points at (the baler's 12, 0.5 mm from 11′′, found none and was set 80 mm off, stop 62)
    lettered = [(float(f.x[j]), dots[j], str(j), f"point {j}") for j in range(0, n, every)]
    lettered += [(float(f.x_all[j]), z, f.added_label(j), "added point number") for j, z in zip(f.added, added)]
    for group in coinciding([z for _, z, _, _ in lettered]):
        members = sorted((lettered[i] for i in group), key=lambda m: m[0])
        at = sum(m[1] for m in members) / len(members)
        # «0, 12» as the lab letters it; «9′; 14′» where a number is primed (after a prime the comma stands
        # apart under it, a mark of its own by the prime's number, in the sheet's font)
        text = ("; " if any("′" in m[2] for m in members) else ", ").join(m[2] for m in members)
        step = members[0][3] if len(members) == 1 else "point " + text
        # every other point a rival (drawing.plans position_numbers): the number nearer its own point
        # than any other, else on a leader to it that passes none; outside the curve first
        mine = [m[1] for m in members]
        rivals = tuple(z for z in (*dots, *added) if min(abs(z - m) for m in mine) > 1e-6)
        toward = at - middle if abs(at - middle) > 1e-6 else 1 + 1j
        asked = [LabelRequest(at, text, toward, NUM, step=step, sight=True, across=False, rivals=rivals)]
        if all(m[2] != "0" for m in members):   # point 0 lies on the I* axis, its own projection: its number
            asked.append(LabelRequest(at, text, toward, NUM, step=step, across=False, rivals=rivals))   # never across it
        numbers.append(asked)
    for name, s, b, tx, ty in (("max", tg["s_max"], k, tg["touch_max_x"], tg["touch_max_y"]),
                               ("min", tg["s_min"], l, tg["touch_min_x"], tg["touch_min_y"])):
        # past the touch point 15 mm across, no more than TANGENT_PAST along the line: a steep tangent
        # (the frame saw's 78°) ran 74 mm up past the curve to its ψ, over bare paper
        x_end = tx + min(15.0, TANGENT_PAST / math.hypot(1.0, s))
        top = float(np.max(f.dT)) + 4.0
        if projections is not None and b + s * x_end < top:       # among the projections: its ψ right of
            x_end = max(x_end, min(x_hi + 4.0, (top - b) / s if s > 0 else math.inf))   # them or over them
        rec.segment((0.0, b), (x_end, b + s * x_end), role="result", layer=LAYER, step=f"tangent at ψ_{name}")
        rec.point((tx, ty), role="joint", layer=LAYER, step=f"tangent at ψ_{name} touches")
        psi = math.degrees(math.atan(s))
        labels.append(LabelRequest(complex(x_end, b + s * x_end), f"ψ_{{{name}}} = {fixed(psi, lang, PSI_DECIMALS)}°", 1 + 0j, TEXT,
                                   step=f"ψ_{name}"))
    rec.point((0.0, k), role="joint", layer=LAYER, step="k")
    rec.point((0.0, l), role="joint", layer=LAYER, step="l")
    xd = -9.0
    # k over its extension line, l under its own, each halfway between the dimension line and the ΔT
    # axis: "l" is one upright stroke, and set 2 mm beside the axis it read as a third line along
    # it (stop 47); halfway, under the line it names, it reads as that line's letter, as k over its own
    labels += [LabelRequest(complex(0.5 * xd, k), "k", 1j, TEXT, step="k"),
               LabelRequest(complex(0.5 * xd, l), "l", -1j, TEXT, step="l")]
    rec.vector((xd, 0.5 * (k + l)), (xd, k), role="construction", layer=LAYER, step="kl")
    rec.vector((xd, 0.5 * (k + l)), (xd, l), role="construction", layer=LAYER, step="kl")
    rec.segment((xd - 1.5, k), (0.0, k), role="construction", layer=LAYER, step="kl")
    rec.segment((xd - 1.5, l), (0.0, l), role="construction", layer=LAYER, step="kl")
    y_kl = 0.5 * (k + l) - 1.2 if projections is None else l - 8.5    # the ΔT projections pass between k and l;
    #                                                               under the row of the letter l (stop 47)
    rec.label((xd - 1.5, y_kl), w["kl"].format(kl=num(f.kl, lang)), size=TEXT, anchor="end", layer=LAYER,
              step="kl read")
    # both axes graduated at their own scales (the same μ_T and μ_I as ΔT(φ) and I*(φ) beside them), before
    # any number or letter is placed (review 12 #23: point 2's number stood where I*'s 0,02 goes, the tick
    # left bare): a tick keeps its value, the numbers and letters move
    before = list(rec.items)      # kept whole: the graduation breaks projections under its numbers, which
    #                               renumbers the items (a count kept dropped the last ones, |kl|'s value: stop 52)
    i_values = graduation(x_hi - 8.0, f.mu_I)
    shown = graduate_axis(rec, i_values, f.mu_I, lang, vertical=False, sides=(1.0, -1.0),
                          step="I* graduation",   # lettered as on I*(φ)'s foot, the projections broken under them
                          letter=not constant_inertia(f))   # a constant I*: ticks only (its value on I*(φ), point
    #                                                         0's number on the axis read as the next value)
    if not constant_inertia(f) and len(i_values) >= 2 and not whole_run(i_values, shown):
        # the French curve crosses the I* axis all along it (ΔT changes sign at most divisions: review
        # 10's six-bar on A3 lettered one value, 0,025), or by a value the run needs (review 12 #23: the
        # branch from point 1 to 2 ran where 0,02 goes, 0,04 and 0,06 lettered beside a bare tick): the
        # axis keeps its ticks, and the values go on a scale line parallel to it at the diagram's foot,
        # from the ΔT axis's end, as a chart's frame
        rec.items[:] = before
        _ticks_only = Record("ticks")
        graduate_axis(_ticks_only, i_values, f.mu_I, lang, vertical=False, sides=(1.0,), step="I* axis ticks",
                      letter=False)
        rec.items.extend(_ticks_only.items)
        foot = lo - 6.0
        low = rec.moved(0.0, -foot)
        low.segment((0.0, 0.0), (x_hi, 0.0), role="construction", width=AXIS_W, layer=LAYER, step="I* scale")
        graduate_axis(low, i_values, f.mu_I, lang, vertical=False, sides=(-1.0,), step="I* graduation")
        rec.items[:] = low.moved(0.0, foot).items
    dt_lo, dt_hi = _extent(f.dT)                   # ΔT(φ)'s step, ticked at its heights beside
    graduate_axis(rec, graduation(hi, f.mu_T, bottom_mm=lo, step=graduation_step(
        graduation(dt_hi, f.mu_T, bottom_mm=dt_lo))), f.mu_T, lang, sides=(-1.0, 1.0), step="ΔT graduation")
    place_labels(rec, labels[:1], layer=LAYER)
    # k and l before the points' numbers: a letter of the construction beside its own circle, the number
    # of a curve point near it moves (review 58: point 12's number took l's place, l ran into |kl|'s text)
    place_labels(rec, labels[-2:], layer=LAYER)
    curve = np.asarray([complex(x, y) for x, y in drawn(X, Y)])
    fence = _value_rows(rec)       # no number in the row of the I* values
    for asked in numbers:        # a point's number beside it with no line between them where it can be (a
        # number across a projection reads as that line's), else on a leader that crosses no branch of
        # the French curve where one can (it would read as a point of that branch): drawing.labels
        place_beside(rec, asked, layer=LAYER, avoid=curve, keep_whole=KEEP_WHOLE, farthest=NUMBER_FARTHEST)
    if fence:                    # taken out again, pieces too (a number beside its point may break a thin line)
        rec.items[:] = [p for p in rec.items if p.step != "values' row"]
    place_labels(rec, labels[1:-2], layer=LAYER)
    return rec


COINCIDE = 2.0 * POINT_INK["dot"]    # mm: two points' dots nearer than this overlap
NUMBER_FARTHEST = FAR[-1] * math.sqrt(2.0)   # mm of paper at most between a point and its number: the placer's
#                                      farthest leader ring (32 mm, √2 times that along a diagonal); a number that
#                                      finds no place so near is left off, not set past the drawing's edge


def coinciding(at: list[complex]) -> list[list[int]]:
    """The points grouped where their dots overlap (nearer than ``COINCIDE``, chained: 12′ on 12 on 11′′
    is one group), each group in the order of its first point, the points in ``at``'s order."""
    group = list(range(len(at)))

    def root(i: int) -> int:
        while group[i] != i:
            i = group[i]
        return i
    for i in range(len(at)):
        for k in range(i):
            if abs(at[i] - at[k]) < COINCIDE:
                group[root(i)] = root(k)
    out: dict[int, list[int]] = {}
    for i in range(len(at)):
        out.setdefault(root(i), []).append(i)
    return sorted(out.values(), key=lambda g: g[0])


def _value_rows(rec: Record) -> list[Primitive]:
    """Fences, for as long as the points' numbers are placed, around each row of the I* axis's values: a
    point's number set between two values read as one of them (the saw's «0 5 11 10 15», stop 56). Each
    a closed outline 0.6 mm round the row, from the ΔT axis to its last value, added to ``rec`` and
    returned (the caller takes them out again)."""
    out = []
    inks = [p.ink() for p in rec.items if p.kind == "text" and p.step == "I* graduation" and p.text.strip()]
    rows: dict[float, list] = {}
    for b in inks:                            # one row per line of values (above and below a scale line)
        rows.setdefault(round(0.5 * (b[1] + b[3]), 1), []).append(b)
    for row in rows.values():
        if len(row) < 2:
            continue
        x0, y0 = min(min(b[0] for b in row) - 0.6, 0.0), min(b[1] for b in row) - 0.6   # from the ΔT axis: a
        #                                  number before the first value read as the axis's 0 (the saw's «0 5 10»)
        x1, y1 = max(b[2] for b in row) + 0.6, max(b[3] for b in row) + 0.6
        p = Primitive("polyline", ((x0, y0), (x1, y0), (x1, y1), (x0, y1), (x0, y0)), role="construction",
                      layer=LAYER, step="values' row")
        rec.items.append(p)
        out.append(p)
    return out


KEEP_WHOLE = ("I* axis", "ΔT axis")    # lines no number breaks (the projections may be broken)


BREAK = 10.0     # mm between the φ axis (ω = 0) and the foot of ω(φ)'s scale, the axis broken there


def speed_record(f: Flywheel, lang: str = "uk", width: float | None = None, height: float = 100.0) -> Record:
    """ω(φ) of the steady states (classical with the exact flywheel, and the motor's) over one
    turn, with a scale of ω on the ordinate axis (ticks in rad/s) that starts near ω_min: the φ axis
    is ω = 0, the ordinate axis broken (a zigzag) ``BREAK`` mm above it. Each legend gives its own
    mean speed: ω_m the flywheel's (the scene's n_1), ``motor_omega`` the motor-driven crank's."""
    w = WORDS[lang]
    dyn = f.dyn
    L = width or f.L
    rec = Record(w["speed"])
    name = dyn.drive.motor.name if lang == "uk" else latin(dyn.drive.motor.name)
    motor = (w["motor"].format(name=name, fl=fixed(dyn.motor_flywheel, lang, _flywheel_places(f)))
             if dyn.motor_flywheel > 0
             else w["motor_none"].format(name=name))     # δ < the request without one: beside it
    # the flywheel's ω_m is the scene's n_1; the motor's crank turns at its own mean speed (another symbol)
    curves = [(dyn.motion, "curve", w["classical"] if dyn.needs_flywheel else w["classical_none"], "ω_m", "δ"),
              (dyn.motor_motion, "projection", motor, motor_omega(lang), motor_delta(lang))]
    lo = min(float(np.min(m.omega)) for m, *_ in curves)
    hi = max(float(np.max(m.omega)) for m, *_ in curves)
    pad = 0.08 * (hi - lo)
    lo, hi = lo - pad, hi + pad
    # ω swings a few per cent about ω_m: its axis starts at lo, not at 0 — the φ axis stays ω = 0 and
    # the ordinate axis is broken between them (the textbook's ω(φ) about ω_m, GOST 2.303's zigzag)
    top = BREAK + height
    y = lambda v: BREAK + (np.asarray(v) - lo) / (hi - lo) * height  # noqa: E731
    zig = 0.5 * BREAK
    rec.add("polyline", [(0.0, 0.0), (0.0, zig - 2.0), (-1.8, zig - 1.0), (1.8, zig + 1.0), (0.0, zig + 2.0)],
            role="construction", width=AXIS_W, layer=LAYER, step="axes ω: break")
    rec.vector((0.0, zig + 2.0), (0.0, top + 8.0), role="construction", width=AXIS_W, layer=LAYER, step="axes ω")
    rec.vector((0.0, 0.0), (L + 10.0, 0.0), role="construction", width=AXIS_W, layer=LAYER, step="axes ω")
    rec.label((-1.5, -1.0), "0", size=NUM, anchor="end", layer=LAYER, step="ω ticks")
    _text(rec, (1.8, top + 5.0), f"ω, {w['rad']}/{w['s']}", step="axes ω")
    rec.label((L + 11.5, -1.2), "φ", size=TEXT, layer=LAYER)
    step = _nice((hi - lo) / SPEED_TICKS)
    v = math.ceil(lo / step - 1e-9) * step
    decimals = axis_decimals([step])           # 12,8 13,0 13,2: the step's decimals (``axis_decimals``)
    while v <= hi + 1e-9 * step:
        yy = float(y(v))
        rec.segment((0.0, yy), (L, yy), role="grid", layer=LAYER, step="ω grid")
        rec.segment((-1.5, yy), (0.0, yy), role="construction", layer=LAYER, step="ω ticks")
        rec.label((-3.0, yy - 1.0), axis_value(v, decimals, lang), size=NUM, anchor="end", layer=LAYER, step="ω ticks")
        v += step
    for deg in range(0, 361, 30):
        xx = L * deg / 360.0
        rec.segment((xx, 0.0), (xx, -1.5), role="construction", layer=LAYER, step="φ ticks")
        rec.label((xx, -5.0), f"{deg}°", size=NUM, anchor="middle", layer=LAYER, step="φ ticks")
    means: list[LabelRequest] = []
    for k, (m, role, text, sym, dsym) in enumerate(curves):
        xs = m.turn / (2 * math.pi) * L
        rec.add("polyline", list(zip(xs[::10], y(m.omega[::10]))), role=role, layer=LAYER, step=text,
                width=0.5 if k == 0 else 0.35)
        yl = -10.0 - line_pitch(NUM) * k
        rec.segment((0.0, yl + 1.0), (10.0, yl + 1.0), role=role, layer=LAYER, step=text, width=0.5 if k == 0 else 0.35)
        rec.label((12.0, yl), f"{text}: {dsym} = {achieved(m.delta, dyn.delta, lang)}, {sym} = {fmt(m.mean, lang)} "
                              f"{w['rad']}/{w['s']}", size=NUM, layer=LAYER)
        # each mean speed a dash-dot line across the turn, named at its right end (the textbook's ω_m
        # about which ω(φ) swings)
        ym = float(y(m.mean))
        rec.segment((0.0, ym), (L, ym), role="axis", layer=LAYER, step=f"{sym} line")
        means.append(LabelRequest(complex(L, ym), sym, 1 + 0j, NUM, step=f"{sym} line"))
    place_labels(rec, means, layer=LAYER)
    # each curve's extremes, from which its δ = (ω_max − ω_min)/ω_m is read (the motor's too: its
    # legend's δ_дв is read off its own curve — stop 49, the dashed curve had none lettered)
    asked = []
    for k, m in enumerate((dyn.motion, dyn.motor_motion)):
        tail = "" if k == 0 else (" дв" if lang == "uk" else " mot")
        for name, j, toward in (("max", int(np.argmax(m.omega)), 1j), ("min", int(np.argmin(m.omega)), -1j)):
            at = (float(m.turn[j] / (2 * math.pi) * L), float(y(m.omega[j])))
            step = f"ω_{name}" + ("" if k == 0 else " motor")
            rec.point(at, role="joint", layer=LAYER, step=step)
            asked.append(LabelRequest(complex(*at), f"ω_{{{name}{tail}}} = {fixed(float(m.omega[j]), lang, _four(m.omega[j]))} "
                                                    f"{w['rad']}/{w['s']}", toward, NUM, step=step))
    return _extremes_lettered(rec, asked, top + 8.0)


def _four(v: float) -> int:
    """The decimals that print ``v`` to four significant figures, as ω_m's legend (stop 62: LINK62's motor
    curve lettered 10,37 and 9,96 — the extremes to the decimals of its mean 10,17 — beside the flywheel's
    9,613 and 9,236: an ω_min of three figures among four-figure values on one axis)."""
    v = abs(float(v))
    return max(3 - math.floor(math.log10(v)), 0) if v > 0 else 2


def tick_column(rec: Record, top: float) -> tuple[float, float, float, float]:
    """The ordinate axis's column of ω values: from the left of their ink to the axis, from the φ
    axis up to the axis's arrow (``top``) — the scale's, where no other lettering belongs."""
    left = min((p.ink()[0] for p in rec.items if p.kind == "text" and p.step == "ω ticks"), default=-3.0)
    return left - 0.5, 0.0, 0.0, top


def _extremes_lettered(rec: Record, asked: list[LabelRequest], top: float) -> Record:
    """The extremes' labels placed clear of the curves and out of the ordinate axis's column of
    values (``tick_column``) and the paper left of it (a label there reads as the scale's, or leaves
    the zone the plot was fitted to): placed on a copy that holds that strip as a closed figure, whose
    inside ``place_labels`` keeps free — an extreme by the axis (the slotter's ω_max at φ ≈ 5°, the
    steep motor curve on its right) took the free spot among the ticks' values, read as one of them —
    and the labels and leaders it adds moved over (the column itself not drawn)."""
    x0, y0, x1, y1 = tick_column(rec, top)
    x0 -= max((Primitive("text", ((0.0, 0.0),), text=q.text, size=q.size).ink()[2] for q in asked), default=0.0)
    probe = Record(rec.title)
    probe.items = list(rec.items)
    probe.add("polygon", [(x0, y0), (x1, y0), (x1, y1), (x0, y1)], role="construction", layer=LAYER,
              step="ω ticks column")
    start = len(probe.items)
    place_labels(probe, asked, layer=LAYER)
    rec.items.extend(probe.items[start:])
    return rec


def _flywheel_places(f: Flywheel) -> int:
    """The decimals Table 2 prints its flywheels to (report.dynamics ``flywheel_decimals``: four
    figures for the smallest, ``column_decimals``), so the legend's motor flywheel reads as Table 2's
    (9,08, not 9,077 beside it — stop 49)."""
    dyn = f.dyn
    values = [v for v in (f.flywheel, f.approximate, f.merkalov, dyn.motor_flywheel) if v > 0]
    return column_decimals(values + ([dyn.flywheel] if dyn.needs_flywheel else []), least=4)


SPEED_TICKS = 8      # about this many graduations of ω over the plot's height (5 left its extremes between ticks)


SPEED_MIN = (150.0, 50.0)     # mm: the smallest ω(φ) plot (abscissa × height) that still reads
SPEED_ASPECT = 0.75           # the plot no taller than ¾ of its abscissa …
SPEED_TALLEST = 220.0         # … nor than this (mm; 160 left ~55 mm over the tables of stop 49's coulisse)


PSI_DECIMALS = 2     # ψ_max and ψ_min to one count of decimals (the shaper's "59,06°" beside "57°")


def speed_fitted(f: Flywheel, lang: str, w: float, h: float, aspect: float = SPEED_ASPECT,
                 tallest: float = SPEED_TALLEST) -> Record:
    """ω(φ) drawn as large as a zone of w × h mm holds (its lettering included): ω has no standard
    scale — its ticks are read off the ordinate axis —, so the plot takes the zone, no taller than
    ``aspect`` (``SPEED_ASPECT``) of its abscissa or ``tallest`` (``SPEED_TALLEST``); never below ``SPEED_MIN``."""
    pw, ph = SPEED_MIN
    probe = speed_record(f, lang, width=pw, height=ph)
    x0, y0, x1, y1 = probe.bounds()
    pw = max(SPEED_MIN[0], w - (x1 - x0 - pw))            # the lettering's overhang is fixed …
    ph = max(SPEED_MIN[1], min(h - (y1 - y0 - SPEED_MIN[1]), aspect * pw, tallest))
    rec = speed_record(f, lang, width=pw, height=ph)
    # … but for the labels of the extremes, placed clear of the curves at the probe's size and not at
    # this one (stop 49: the motor's ω_max lettered left of the axis on the small probe cost ω(φ) 25 mm
    # of its zone): once more with the overhang measured at this size, where the zone still holds it
    x0, y0, x1, y1 = rec.bounds()
    more = w - (x1 - x0)
    if more > 1.0 and pw > SPEED_MIN[0]:
        wider = speed_record(f, lang, width=pw + more, height=ph)
        b = wider.bounds()
        if b[2] - b[0] <= w + 1e-9 and b[3] - b[1] <= max(h, y1 - y0) + 1e-9:
            return wider
    return rec


def _nice(raw: float) -> float:
    e = math.floor(math.log10(raw))
    for m in (1, 2, 2.5, 5, 10):
        if m * 10 ** e >= raw:
            return m * 10 ** e
    return 10 ** (e + 1)


def records(f: Flywheel, lang: str = "uk", speed_height: float = 100.0,
            speed_zone: tuple[float, float] | None = None) -> dict[str, Record]:
    """Every drawing of the construction by name; ω(φ) over the abscissa L ``speed_height`` mm
    high, or as large as ``speed_zone`` (w, h mm) holds (``speed_fitted``)."""
    return {"moments": moments_record(f, lang), "energy": energy_record(f, lang),
            "inertia": inertia_record(f, lang), "wittenbauer": wittenbauer_record(f, lang),
            "speed": speed_record(f, lang, height=speed_height) if speed_zone is None
            else speed_fitted(f, lang, *speed_zone)}
