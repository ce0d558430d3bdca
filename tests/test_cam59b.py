"""Review 59 #4 on the cam sheet: R0 rounded UP from the smallest read off the phase diagram (review 59's
scene (c), REVIEW_CAM59C: a translating knife-edge follower, the offset "auto", the cam ccw; R0min 33,2 mm,
R0 taken 34 mm). The [ϑ] lines' crossing, O_min, stood 3 mm above the drawn O unlettered under a caption
naming the smallest R₀ alone. Now, for a translating and a rocking follower (the lead's CAM58):

- O_min is dotted where the closed form puts it: on O's offset line (translating) the legs √(R0² − e²)
  apart over μ — (R0 − R0min)/μ to the ruler —, on O's arc of radius a about the arm's pivot (rocking)
  the chord 2a·sin(Δψ0/2) away, Δψ0 the arm's start angles of the two radii by the law of cosines;
- both O and O_min lettered once, O_min's letter clear of the [ϑ] lines and nearer its own dot than O's
  (or on a leader to it);
- the caption names both: «найменший і прийнятий R₀», 'smallest and taken R_0'.
The smallest R0 is the test's own: tg ϑ = (ds/dφ − e)/(s0 + s) over the laws' closed forms, brentq."""
from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import brentq

from graphplan.drawing.cam import phase_diagram
from graphplan.exact.cam import solve
from graphplan.graphic.cam import construct, phase_drawn_at
from graphplan.model.cam import load
from graphplan.sheets.cam import _captions
from review_scenes import CAM58, REVIEW_CAM59C


def _solved(tmp_path_factory, name: str, text: str):
    path = tmp_path_factory.mktemp(name) / f"{name}.toml"
    path.write_text(text, encoding="utf-8")
    sol = solve(load(path))
    return sol, construct(sol, series="rad")


def _built(solved, at: float | None = None):
    sol, g = solved
    g = phase_drawn_at(g, at)
    return sol, g, phase_diagram(sol, g, "uk")


@pytest.fixture(scope="module")
def knife(tmp_path_factory):
    return _built(_solved(tmp_path_factory, "cam59c", REVIEW_CAM59C))


@pytest.fixture(scope="module")
def cam58(tmp_path_factory):
    return _solved(tmp_path_factory, "cam58", CAM58)


@pytest.fixture(scope="module")
def rocking(cam58):
    """CAM58's diagram at 2,5:1, as the A1 sheet draws it (R0 33 mm taken, the smallest 32,0)."""
    return _built(cam58, 0.0004)


def _smallest_knife(e: float) -> float:
    """REVIEW_CAM59C's smallest R0 by the closed form: a cycloidal rise of 30 mm over 120°, a cosine return
    over 90°, [ϑ] 30°/35°, tg ϑ = (ds/dφ − e)/(s0 + s)."""
    h, rise, ret = 0.03, math.radians(120.0), math.radians(90.0)
    x = np.linspace(0.0, 1.0, 20001)
    s_up, v_up = h * (x - np.sin(2 * np.pi * x) / (2 * np.pi)), h / rise * (1 - np.cos(2 * np.pi * x))
    s_dn, v_dn = h * (1 + np.cos(np.pi * x)) / 2, -h * np.pi / (2 * ret) * np.sin(np.pi * x)

    def worst(R0: float) -> float:
        s0 = math.sqrt(R0 * R0 - e * e)
        up = np.degrees(np.abs(np.arctan((v_up - e) / (s0 + s_up)))).max() / 30.0
        dn = np.degrees(np.abs(np.arctan((v_dn - e) / (s0 + s_dn)))).max() / 35.0
        return max(up, dn) - 1.0
    return brentq(worst, abs(e) + 1e-4, 0.2, xtol=1e-9)


def _points(rec):
    (o,) = [complex(*q.points[0]) for q in rec.items if q.step == "O" and q.kind == "point"]
    (om,) = [complex(*q.points[0]) for q in rec.items if q.step == "O min" and q.kind == "point"]
    return o, om


def _lettered_clear(rec, o: complex, om: complex) -> None:
    """O and O_min lettered once each; O_min's letter off the [ϑ] lines, nearer its dot than O's or led to it."""
    texts = [q for q in rec.items if q.kind == "text"]
    assert sum(q.text == "O" for q in texts) == 1
    (t,) = [q for q in texts if q.text == "O_{min}"]
    x0, y0, x1, y1 = t.ink()
    for ph in (0, 1):
        (a, b) = next(q for q in rec.items if q.step == f"[ϑ] line {ph}").points
        p = np.linspace(complex(*a), complex(*b), 4001)
        inside = (p.real > x0) & (p.real < x1) & (p.imag > y0) & (p.imag < y1)
        assert not inside.any(), f"O_min's letter on the [ϑ] line {ph}"

    def gap(z: complex) -> float:
        return math.hypot(max(x0 - z.real, 0.0, z.real - x1), max(y0 - z.imag, 0.0, z.imag - y1))
    led = [q for q in rec.items if q.step == "O min" and q.kind == "segment"
           and min(abs(complex(*e) - om) for e in q.points) < 2.0]
    assert gap(om) < gap(o) or led


def test_knife_edge_o_min_where_the_closed_form_puts_it(knife):
    sol, g, rec = knife
    mu = rec.scales["mu_phase"]
    e, R0 = sol.geometry.e, sol.geometry.R0
    R0min = _smallest_knife(e)
    assert R0 == pytest.approx(0.034) and R0min * 1000 == pytest.approx(33.2, abs=0.05)
    o, om = _points(rec)
    assert abs(om.real - o.real) < 1e-9 and om.imag > o.imag          # on O's offset line, above it
    legs = (math.sqrt(R0 ** 2 - e ** 2) - math.sqrt(R0min ** 2 - e ** 2)) / mu
    assert abs(om - o) == pytest.approx(legs, abs=0.1)                 # the drawn smallest within 0.1 mm
    assert abs(abs(om - o) - (R0 - R0min) / mu) <= g.precision          # (R0 − R0min)/μ to the ruler
    _lettered_clear(rec, o, om)


def test_knife_edge_caption_names_both(knife):
    sol, g, _ = knife
    assert _captions(g, sol.cam, "uk")["phase"][0].endswith("найменший і прийнятий R_0")
    assert _captions(g, sol.cam, "en")["phase"][0].endswith("smallest and taken R_0")


@pytest.mark.slow          # CAM58's construction ~4 s on the shared machine
def test_rocking_o_min_on_o_s_arc(rocking):
    sol, g, rec = rocking
    mu = rec.scales["mu_phase"]
    a, l, R0 = sol.cam.centre_distance, sol.cam.arm, sol.geometry.R0
    R0min = g.R0_drawn
    assert R0 > R0min and abs(R0min - sol.R0_min) * 1000 < 0.25           # the drawn smallest to the ruler
    o, om = _points(rec)
    A = a / mu
    assert abs(om - A) == pytest.approx(A, rel=1e-9)                        # on the arc about the pivot
    psi = lambda R: math.acos((a * a + l * l - R * R) / (2 * a * l))        # noqa: E731
    chord = 2 * a * math.sin((psi(R0) - psi(R0min)) / 2) / mu
    assert abs(om - o) == pytest.approx(chord, rel=1e-6)
    assert abs(abs(om - o) - (R0 - R0min) / mu) < 0.5 * abs(om - o) + g.precision
    _lettered_clear(rec, o, om)
    assert _captions(g, sol.cam, "uk")["phase"][0].endswith("найменший і прийнятий R_0")


@pytest.mark.slow
def test_rocking_at_1_to_1_o_min_said_in_a_note(cam58):
    """At 1:1 CAM58's O_min lies 1,4 mm from O, the two dots would touch: no second dot, one note by O that
    says how far — the closed form's chord to the note's 0,1 mm."""
    sol, g, rec = _built(cam58)
    mu = rec.scales["mu_phase"]
    a, l = sol.cam.centre_distance, sol.cam.arm
    psi = lambda R: math.acos((a * a + l * l - R * R) / (2 * a * l))        # noqa: E731
    chord = 2 * a * math.sin((psi(sol.geometry.R0) - psi(g.R0_drawn)) / 2) / mu
    assert not [q for q in rec.items if q.step == "O min" and q.kind == "point"]
    (note,) = [q.text for q in rec.items if q.kind == "text" and q.text.startswith("O_{min} за ")]
    assert float(note.split()[2].replace(",", ".")) == pytest.approx(chord, abs=0.051)
    assert sum(q.text == "O" for q in rec.items if q.kind == "text") == 1
