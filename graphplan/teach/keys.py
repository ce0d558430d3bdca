"""Teachers' answer keys: the exact answers a lab asks for, for one variant, with their tolerances.

The answers come from the analytic solver only (``positions.study``): the velocities of every point,
the relative velocities read off a plan, ω of the links at every position; the accelerations with their
normal, tangential, Coriolis and relative components and ε at the acceleration-plan positions; the
output's s, v, a at the diagram's division abscissae and chord midpoints. Quantities are named as a
student's long table names them (docs/keys.md): ``v_B``, ``v_BA``, ``omega_AB``, ``an_BA``, ``s`` …
"""
from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from graphplan.util.errors import SceneError, said_error
from graphplan.exact.kinematics import Kinematics
from graphplan.model.mechanism import FRAME
from graphplan.exact.positions import Study
from graphplan.model.variants import tolerance_for

FORMAT = "graphplan-key/1"
ZERO_FRACTION = 0.05   # |exact| below 5 % of the largest |value| over the turn counts as "near zero"
SCAN = 720             # samples per turn for the scales (0.5°)
CURVE_POINTS = 180     # the s, v, a curves drawn on the key sheet: every 2°
FAMILIES = ("velocity", "acceleration", "diagram")


@dataclass(frozen=True)
class Quantity:
    """One answer of the lab as a function of the crank angle.

    ``signed`` quantities (ω, ε, the output's s, v, a, relative slides) carry a sign (+ counter-
    clockwise, + along the guide); the others are magnitudes of vectors, as a plan gives them."""
    name: str
    unit: str
    family: str
    signed: bool
    text: str
    fn: Callable[[Kinematics], np.ndarray]

    def __call__(self, kin: Kinematics) -> np.ndarray:
        return np.asarray(self.fn(kin), dtype=float)


def quantities(st: Study) -> dict[str, Quantity]:
    """Every answer a lab on this mechanism asks for, keyed by its name in a student's table."""
    mech = st.mech
    found: dict[str, Quantity] = {}

    def add(name, unit, family, signed, text, fn):
        found.setdefault(name, Quantity(name, unit, family, signed, text, fn))

    moving = [p for p in mech.point_names() if p not in mech.frame]
    for p in moving:
        add(f"v_{p}", "m/s", "velocity", False, f"|v| of point {p}",
            lambda kin, p=p: np.abs(kin.point(p)[1]))
    links = [link for name, link in mech.links.items()
             if name != mech.crank.link and link.slides_on is None]
    slides = _moving_slides(st)
    for key, (carrier_no, slider_no, point) in slides.items():
        add(f"v_{point}{carrier_no}", "m/s", "velocity", False,
            f"|v| of the point of link {carrier_no} under {point}",
            lambda kin, key=key: np.abs(_coincident(kin, key)[0]))
    for link in links:
        for p, q in _pairs(mech, link):
            if p not in mech.frame:
                add(f"v_{q}{p}", "m/s", "velocity", False, f"|v| of {q} relative to {p} (link {link.name})",
                    lambda kin, p=p, q=q: np.abs(kin.point(q)[1] - kin.point(p)[1]))
    for key, (carrier_no, slider_no, point) in slides.items():
        add(f"v_{point}{carrier_no}{point}{slider_no}", "m/s", "velocity", True,
            f"sliding velocity of {point}{carrier_no} relative to {point}{slider_no}, along the guide",
            lambda kin, key=key: kin.slides[key].v)
    for link in links:
        add(f"omega_{link.name}", "rad/s", "velocity", True, f"ω of link {link.name} (+ counter-clockwise)",
            lambda kin, n=link.name: kin.bodies[n].omega)

    for p in moving:
        add(f"a_{p}", "m/s²", "acceleration", False, f"|a| of point {p}",
            lambda kin, p=p: np.abs(kin.point(p)[2]))
    for key, (carrier_no, slider_no, point) in slides.items():
        add(f"a_{point}{carrier_no}", "m/s²", "acceleration", False,
            f"|a| of the point of link {carrier_no} under {point}",
            lambda kin, key=key: np.abs(_coincident(kin, key)[1]))
    for link in links:
        for p, q in _pairs(mech, link):
            length = abs(link.local[q] - link.local[p])
            if p not in mech.frame:
                add(f"a_{q}{p}", "m/s²", "acceleration", False, f"|a| of {q} relative to {p}",
                    lambda kin, p=p, q=q: np.abs(kin.point(q)[2] - kin.point(p)[2]))
            add(f"an_{q}{p}", "m/s²", "acceleration", False, f"normal a^n_{q}{p} = ω²·{q}{p}",
                lambda kin, n=link.name, l_=length: kin.bodies[n].omega ** 2 * l_)
            add(f"at_{q}{p}", "m/s²", "acceleration", False, f"tangential a^τ_{q}{p} = |ε|·{q}{p}",
                lambda kin, n=link.name, l_=length: np.abs(kin.bodies[n].eps) * l_)
    for key, (carrier_no, slider_no, point) in slides.items():
        rel = f"{point}{carrier_no}{point}{slider_no}"
        add(f"ak_{rel}", "m/s²", "acceleration", False, f"Coriolis a^k_{rel} = 2·ω·v_rel",
            lambda kin, key=key: kin.slides[key].coriolis_magnitude)
        add(f"ar_{rel}", "m/s²", "acceleration", True, f"relative a^r_{rel} along the guide",
            lambda kin, key=key: kin.slides[key].a)
    for link in links:
        add(f"eps_{link.name}", "rad/s²", "acceleration", True, f"ε of link {link.name} (+ counter-clockwise)",
            lambda kin, n=link.name: kin.bodies[n].eps)

    s_unit = "m" if st.output.kind == "slide" else "rad"
    s_fn = output_displacement(st)
    add("s", s_unit, "diagram", True, f"displacement of {st.output.name} from position 0", s_fn)
    add("v", f"{s_unit}/s", "diagram", True, f"velocity of {st.output.name} (ds/dt)", st.output.rate)
    add("a", f"{s_unit}/s²", "diagram", True, f"acceleration of {st.output.name} (d²s/dt²)", st.output.accel)
    return found


def _pairs(mech, link) -> list[tuple[str, str]]:
    """Joint pairs (p, q) of a link, p earlier in the joints' order; a frame pivot always first."""
    joints = list(link.joints)
    joints.sort(key=lambda j: j not in mech.frame)
    return [(joints[i], joints[k]) for i in range(len(joints)) for k in range(i + 1, len(joints))
            if not (joints[i] in mech.frame and joints[k] in mech.frame)]


def _moving_slides(st: Study) -> dict[str, tuple[int, int, str]]:
    """Sliding pairs on moving guides: key → (carrier's number, slider's number, point)."""
    mech = st.mech
    kin = st.solve([st.phi0])
    out = {}
    for key, sl in kin.slides.items():
        if sl.carrier == FRAME:
            continue
        out[key] = (mech.links[sl.carrier].number, mech.links[sl.slider].number, sl.point)
    return out


def _coincident(kin: Kinematics, key: str) -> tuple[np.ndarray, np.ndarray]:
    sl = kin.slides[key]
    x = kin.point(sl.point)[0]
    return kin.bodies[sl.carrier].coincident(x)


def output_displacement(st: Study) -> Callable[[Kinematics], np.ndarray]:
    """s(φ): the slide coordinate from position 0, or the output link's turn from position 0 in
    (−π, π] (a rocker swings less than a half turn either way)."""
    if st.output.kind == "slide":
        t0 = st.t0[st.output.name]
        return lambda kin: kin.slides[st.output.name].t - t0
    theta0 = float(st.solve([st.phi0]).bodies[st.output.name].theta[0])
    return lambda kin: np.angle(np.exp(1j * (kin.bodies[st.output.name].theta - theta0)))


# -- the key -----------------------------------------------------------------------------------

def _clean(values: np.ndarray, scale: float) -> list[float]:
    """Round-off below 1e-12 of the quantity's scale is zero (so a dead centre reads 0, not 3e-15)."""
    tiny = 1e-12 * scale
    return [0.0 if abs(v) <= tiny else float(v) for v in values]


def abscissae(divisions: int) -> np.ndarray:
    """The diagram's abscissae in divisions: 0, ½, 1, … N (divisions and chord midpoints)."""
    return np.arange(2 * divisions + 1) / 2.0


def diagram_phi(st: Study, abscissa, divisions: int) -> np.ndarray:
    """Crank angle of a diagram abscissa: position 0 plus k·360°/N in the crank's sense."""
    step = 360.0 / divisions * np.sign(st.mech.omega1)
    return np.mod(st.phi0 + step * np.asarray(abscissa, dtype=float), 360.0)


def stroke_and_k(st: Study) -> tuple[float | None, float | None]:
    """H: the output's stroke (swing, rad) between its extreme positions; K: the slower over the
    faster stroke's crank turn (the time-ratio coefficient)."""
    if len(st.extremes) < 2:
        return None, None
    s = output_displacement(st)(st.solve(list(st.extremes)))
    hi, lo = int(np.argmax(s)), int(np.argmin(s))
    turn = ((st.extremes[lo] - st.extremes[hi]) * np.sign(st.mech.omega1)) % 360.0
    return float(s[hi] - s[lo]), float(max(turn, 360 - turn) / min(turn, 360 - turn))


def make_key(st: Study, *, variant: str = "", student: str = "", base: str = "",
             overrides: dict[str, Any] | None = None, scene: dict[str, Any] | None = None,
             divisions: int | None = None,
             tolerances: Sequence[dict[str, float]] = ()) -> dict[str, Any]:
    """The key of one variant as a JSON-ready document (see docs/keys.md for the layout).

    ``tolerances`` are the layers of per-quantity percentages, most specific first (the row's, the
    command line's, the table's); ``scene`` is the resolved scene tree, kept so ``check`` can rebuild
    the mechanism and search other crank angles."""
    mech = st.mech
    qs = quantities(st)
    count = mech.task.count
    accel = sorted(set(mech.task.accel))
    for p in accel:
        if p >= count:
            raise said_error(SceneError, "ky accel", mech.source, mech.task.meta.get("lang"), p=p, count=count,
                             last=count - 1)
    divisions = divisions or count
    grid = st.solve(np.arange(SCAN) * 360.0 / SCAN)
    scales = {name: float(np.max(np.abs(q(grid)))) for name, q in qs.items()}

    phis = st.positions(count)
    kin = st.solve(phis)
    by_family = {f: [n for n, q in qs.items() if q.family == f] for f in FAMILIES}
    pos_values = {n: _clean(qs[n](kin), scales[n]) for n in by_family["velocity"] + by_family["acceleration"]}
    positions = []
    turn = st.from_position0(phis)
    for k, phi in enumerate(phis):
        names = by_family["velocity"] + (by_family["acceleration"] if k in accel else [])
        positions.append({"index": k, "phi_deg": float(phi), "turn_deg": float(turn[k]),
                          "values": {n: pos_values[n][k] for n in names}})

    xs = abscissae(divisions)
    dphi = diagram_phi(st, xs, divisions)
    dkin = st.solve(dphi)
    dvals = {n: _clean(qs[n](dkin), scales[n]) for n in by_family["diagram"]}
    period = mech.period
    diagram = [{"abscissa": float(x), "phi_deg": float(p), "t": float(x * period / divisions),
                "values": {n: dvals[n][k] for n in by_family["diagram"]}}
               for k, (x, p) in enumerate(zip(xs, dphi))]

    turn = np.arange(CURVE_POINTS + 1) * 360.0 / CURVE_POINTS
    ckin = st.solve(diagram_phi(st, turn / 360.0 * divisions, divisions))
    curves = {"turn_deg": [float(t) for t in turn],
              **{n: [round(v, 12) for v in _clean(qs[n](ckin), scales[n])] for n in by_family["diagram"]}}

    stroke, k_ratio = stroke_and_k(st)
    return {
        "format": FORMAT,
        "variant": variant,
        "student": student,
        "base": base,
        "overrides": dict(overrides or {}),
        "title": mech.task.meta.get("title", mech.title),
        "title_en": mech.task.meta.get("title_en", ""),
        "omega1": mech.omega1,
        "epsilon1": mech.crank.epsilon,
        "period": period,
        "formula": st.structure.formula,
        "links": {name: link.number for name, link in mech.links.items()},
        "output": {"kind": st.output.kind, "name": st.output.name},
        "position0_phi_deg": st.phi0,
        "extremes_phi_deg": list(st.extremes),
        "stroke": stroke,
        "K": k_ratio,
        "count": count,
        "accel": accel,
        "divisions": divisions,
        "zero_fraction": ZERO_FRACTION,
        "quantities": {n: {"unit": q.unit, "family": q.family, "signed": q.signed, "text": q.text,
                           "scale": scales[n], "tolerance_pct": tolerance_for(n, *tolerances)}
                       for n, q in qs.items()},
        "positions": positions,
        "diagram": diagram,
        "curves": curves,
        "scene": scene,
    }


def answers(key: dict[str, Any]) -> list[tuple[str, float, str, float]]:
    """The key as long rows (position label, crank angle, quantity, exact value)."""
    rows = []
    for pos in key["positions"]:
        for name, value in pos["values"].items():
            rows.append((str(pos["index"]), pos["phi_deg"], name, value))
    for point in key["diagram"]:
        for name, value in point["values"].items():
            rows.append((f"{point['abscissa']:g}", point["phi_deg"], name, value))
    return rows


def key_csv(key: dict[str, Any]) -> str:
    """The key in the student's long format plus the exact value's unit, tolerance and crank angle."""
    lines = ["variant,position,quantity,value,unit,tolerance_pct,phi_deg"]
    meta = key["quantities"]
    for position, phi, name, value in answers(key):
        q = meta[name]
        lines.append(f"{key['variant']},{position},{name},{fmt(value, 10)},{q['unit']},"
                     f"{q['tolerance_pct']:g},{fmt(phi, 10)}")
    return "\n".join(lines) + "\n"


def fmt(value: float | None, digits: int = 4) -> str:
    """A number with ``digits`` significant digits, no exponent for ordinary magnitudes."""
    if value is None:
        return ""
    if value == 0 or not math.isfinite(value):
        return "0" if value == 0 else str(value)
    mag = math.floor(math.log10(abs(value)))
    if mag < -5 or mag > 11:
        return f"{value:.{digits - 1}e}"
    decimals = max(0, digits - 1 - mag)
    text = f"{value:.{decimals}f}"
    if "." in text and digits > 6:
        text = text.rstrip("0").rstrip(".")
    return "0" if text in ("-0", "-0.0") else text


# -- the group's summary ------------------------------------------------------------------------

def summary_units(key: dict[str, Any]) -> dict[str, str]:
    """Units of the summary's computed columns."""
    qs = key["quantities"]
    units = {"phi0_deg": "°", "H": qs["s"]["unit"], "v_max": qs["v"]["unit"], "a_max": qs["a"]["unit"]}
    units.update({n: q["unit"] for n, q in qs.items()})
    return units


def summary_row(key: dict[str, Any]) -> dict[str, Any]:
    """One line of the group's summary: the variant's inputs and its headline answers."""
    row: dict[str, Any] = {"variant": key["variant"], "student": key["student"], "status": "ok"}
    row.update({k: v for k, v in key["overrides"].items()})
    row["phi0_deg"] = key["position0_phi_deg"]
    row["H"] = key["stroke"]
    row["K_calc"] = key["K"]
    qs = key["quantities"]
    row["v_max"] = qs["v"]["scale"]
    row["a_max"] = qs["a"]["scale"]
    if key["accel"]:
        p = key["accel"][0]
        values = key["positions"][p]["values"]
        row["pos_a"] = p
        out = key["output"]["name"]
        for name in (f"v_{out}", f"a_{out}"):
            if name in values:
                row[name] = values[name]
        for name, value in values.items():
            if name.startswith(("omega_", "eps_")):
                row[name] = value
    return row
