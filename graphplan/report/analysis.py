"""`graphplan analyze`: the exact kinematics as the contract's JSON and as readable tables."""
from __future__ import annotations

import math
from typing import Any

import numpy as np


from graphplan.model.mechanism import FRAME
from graphplan.exact.positions import Study
from graphplan.util.markup import plain
from graphplan.util.words import fixed, num, pair_kind, unit, word
from graphplan.util.romanize import scene_title


def analyze_json(st: Study, phi_deg: np.ndarray, indices: list[int]) -> dict[str, Any]:
    """The contract's ``analyze --json`` document (SI units)."""
    mech = st.mech
    kin = st.solve(phi_deg)
    names = mech.point_names()
    positions = []
    for k, (index, phi) in enumerate(zip(indices, phi_deg)):
        points = {}
        for name in names:
            x, v, a = (float_c(q[k]) for q in kin.point(name))
            points[name] = {"x": x.real, "y": x.imag, "vx": v.real, "vy": v.imag, "ax": a.real, "ay": a.imag}
        links = {name: {"angle_deg": math.degrees(float(kin.bodies[name].theta[k])) % 360.0,
                        "omega": float(kin.bodies[name].omega[k]),
                        "epsilon": float(kin.bodies[name].eps[k])} for name in mech.links}
        slides = {key: {"s": float(s.t[k]) - st.t0[key], "v": float(s.v[k]), "a": float(s.a[k]),
                        "coriolis": float(s.coriolis_magnitude[k])} for key, s in kin.slides.items()}
        positions.append({"index": index, "phi_deg": float(phi) % 360.0, "points": points,
                          "links": links, "slides": slides})
    return {
        "scene": mech.title,
        "omega1": mech.omega1,
        "epsilon1": mech.crank.epsilon,
        "structure": structure_json(st),
        "output": {"kind": st.output.kind, "name": st.output.name},
        "position0_phi_deg": st.phi0,
        "extremes_phi_deg": list(st.extremes),
        "derived": mech.derived,
        "warnings": list(st.warnings),
        "positions": positions,
    }


def structure_json(st: Study) -> dict[str, Any]:
    s = st.structure
    return {"mobility": s.mobility, "n": s.n, "p5": s.p5, "p4": s.p4, "formula": s.formula,
            "groups": [{"label": d.label, "kind": d.kind, "links": [d.a, d.b]} for d in s.dyads]}


def float_c(z: complex) -> complex:
    return complex(float(np.real(z)), float(np.imag(z)))


# derived parameters (the quick-return synthesis, model.scene) written as the lab writes them
DERIVED = {"theta_deg": ("θ, °", "θ, °"), "crank": ("довжина кривошипа, м", "crank length, m"),
           "rocker": ("довжина куліси, м", "rocker length, m")}


def _translates(mech, name: str) -> bool:
    """A link whose ω and ε its sliding pair gives: on a guide the frame carries (a piston, a ram) it
    does not turn (ω = ε = 0), on the crank's guide (a slotted crank's block) it turns with the crank
    (ω1, ε1, given) — the tables of ω and ε leave it out (a block on a rocking guide turns with the
    guide, unknown till solved, and stays)."""
    guide = mech.links[name].slides_on
    return guide is not None and mech.guides[guide].body in (FRAME, mech.crank.link)


def analyze_table(st: Study, phi_deg: np.ndarray, indices: list[int], lang: str = "uk") -> str:
    """Readable tables: velocities and accelerations of the points, ω and ε, the slides; in ``lang``."""
    mech = st.mech
    kin = st.solve(phi_deg)
    s = st.structure
    w = lambda k_, **kw: plain(word(k_, lang, **kw))  # noqa: E731
    n = lambda v: num(v, lang)  # noqa: E731
    title = scene_title(mech.task.meta, mech.title, lang)
    lines = [title,
             f"ω₁ = {n(mech.omega1)} {unit('rad/s', lang)} ({n(abs(mech.omega1) * 30 / math.pi)} {unit('rpm', lang)}, "
             f"{w('ccw') if mech.omega1 > 0 else w('cw')}), ε₁ = {n(mech.crank.epsilon)} {unit('rad/s²', lang)}",
             f"W = 3n − 2p₅ − p₄ = 3·{s.n} − 2·{s.p5} − {s.p4} = {s.mobility};  {s.formula}"]
    for d in s.dyads:
        lines.append(w("dyad line", label=d.label, kind=pair_kind(d.kind, lang), a=d.a, b=d.b))
    for key, value in mech.derived.items():
        lines.append(w("derived", key=DERIVED.get(key, (key, key))[lang != "uk"], value=num(value, lang, 5)))
    ex = ", ".join(f"{fixed(e, lang, 3)}°" for e in st.extremes) or w("turns fully")
    lines.append(w("output line", name=st.output.name, ex=ex, phi0=fixed(st.phi0, lang, 3)))
    moving = [p for p in mech.point_names() if p not in mech.frame]
    head = [w("no"), "φ, °"]

    def table(title: str, columns: list[str], rows: list[list[float]]) -> None:
        lines.append("")
        lines.append(title)
        widths = [max(len(c), 9) for c in columns]
        lines.append("  ".join(c.rjust(wd) for c, wd in zip(head + columns, [3, 7] + widths)))
        tiny = 1e-10 * max((abs(v) for r in rows for v in r), default=0.0)  # round-off → 0
        for index, phi, row in zip(indices, phi_deg, rows):
            row = [0.0 if abs(v) <= tiny else v for v in row]
            cells = [f"{index:>3}", f"{fixed(phi, lang, 2):>7}"] + [f"{n(v):>{wd}}" for v, wd in zip(row, widths)]
            lines.append("  ".join(cells))

    vel = [np.abs(kin.point(p)[1]) for p in moving]
    acc = [np.abs(kin.point(p)[2]) for p in moving]
    count = len(phi_deg)
    table(w("point velocities"), [f"v_{p}" for p in moving], [[q[k] for q in vel] for k in range(count)])
    table(w("point accelerations"), [f"a_{p}" for p in moving], [[q[k] for q in acc] for k in range(count)])
    links = [name for name in mech.links if name != mech.crank.link and not _translates(mech, name)]
    if links:
        table(w("angular velocities"), [f"ω_{n_}" for n_ in links],
              [[kin.bodies[n_].omega[k] for n_ in links] for k in range(count)])
        table(w("angular accelerations"), [f"ε_{n_}" for n_ in links],
              [[kin.bodies[n_].eps[k] for n_ in links] for k in range(count)])
    for key, sl in kin.slides.items():
        table(w("slide table", key=key, slider=sl.slider, carrier=sl.carrier if sl.carrier != FRAME else w("the frame")),
              ["s", "v", "a", "a_k"],
              [[sl.t[k] - st.t0[key], sl.v[k], sl.a[k], sl.coriolis_magnitude[k]] for k in range(count)])
    if st.warnings:
        lines += ["", w("warnings") + ":"] + [f"  {wn}" for wn in st.says(lang)]
    return "\n".join(lines) + "\n"
