"""Review 13 #9 (issue 32): the carrier of a large-ratio train read off a readable segment. Where the
plan of angular velocities leaves ωH's segment under ``SEGMENT_MIN`` (a 20-mm segment is out of reach
for u ≈ 16…40 while the sun's ray takes the zone's width), the carrier's ray is drawn from a pole
p'_ω of its own on h produced, h_H below the plan's line (any pole distance serves the plan:
ω = segment·μv/(μl·h)); elsewhere the notes say how short the segment is. Checked against Willis'
formula written here for the two-row train (type B): u1H = 1 + z2·z3/(z1·z2'), ωH = ω1/u1H."""
from __future__ import annotations

import math
import tomllib

import pytest

from review_scenes import GEARS_REV13


def _train(ratio: float | None = None, lang: str = "en"):
    from graphplan.exact.gears import solve
    from graphplan.model.gears import build
    d = tomllib.loads(GEARS_REV13)
    if ratio is not None:
        d["planetary"]["ratio"] = ratio
    d["lang"] = lang
    g = build(d, "<rev13>")
    return g, solve(g)


def _willis(tr) -> tuple[float, float]:
    z1, z2, z2b, z3 = tr.z
    u = 1 + z2 * z3 / (z1 * z2b)
    return u, math.pi * 1440 / 30 / u


def test_the_carriers_own_pole_reads_willis_and_is_drawn_as_read():
    """At precision 0 the carrier's own pole gives Willis' u1H and ωH to 1e-9; at 0.5 mm the ray H
    starts at p'_ω, h_H below the line (dimensioned so), the segment from the foot of h to the point H
    × μv/(μl·h_H) is the ωH read (20 mm and more, where the plan's own pole gave under 20), and
    u1H = (s1/h)/(sH/h_H) lies within its stated bound."""
    from graphplan.graphic.gears import construct_train
    _, sol = _train()
    tr = sol.train
    u, wH = _willis(tr)
    exact = construct_train(tr, 0.0, "en", ring_mm=56.5, sun_segment_mm=210.0, h_carrier=160.0)
    assert exact.h_carrier == 160.0 and exact.ratio == pytest.approx(u, rel=1e-9)
    assert exact.omega["H"] == pytest.approx(wH, rel=1e-9)
    v = construct_train(tr, 0.5, "en", ring_mm=56.5, sun_segment_mm=210.0, h_carrier=160.0)
    assert v.mu_v / (v.mu_l * 160.0) == pytest.approx(0.25, rel=1e-12)              # μ'ω round (review 48)
    rec = v.record
    line_y = next(q for q in rec.items if q.step == "plan of ω").points[0][1]
    foot_x = next(q for q in rec.items if q.step == "h").points[1][0]
    ray = next(q for q in rec.items if q.step == "ray H")
    assert ray.points[0] == pytest.approx((foot_x, line_y - 160.0))                 # from p'_ω
    assert ray.points[1][1] == pytest.approx(line_y)
    dim = [q for q in rec.items if q.step == "h_H dimension" and q.kind == "segment"]
    assert len(dim) == 1 and abs(dim[0].points[0][1] - dim[0].points[1][1]) == pytest.approx(160.0)
    seg = ray.points[1][0] - foot_x                                                 # as drawn
    assert abs(seg - v.segments["H"]) <= 0.25 + 1e-9                                # read with the ruler
    assert v.omega["H"] == pytest.approx(v.segments["H"] * v.mu_v / (v.mu_l * 160.0), rel=1e-12)
    assert abs(v.segments["H"]) >= 20.0 > abs(construct_train(tr, 0.5, "en", ring_mm=56.5,
                                                              sun_segment_mm=210.0).segments["H"])
    assert abs(v.ratio - u) <= v.ratio_bound
    assert v.ratio == pytest.approx(v.segments["1"] / v.h / (v.segments["H"] / 160.0), rel=1e-12)


def test_review_13s_a1_sheet_reads_the_carrier_off_twenty_millimetres_and_says_how():
    """Review 13's own sheet (u1H = 26,26, en): ωH's segment was 3,8 mm, then 8 mm on the plan's own
    pole; now at least ``SEGMENT_MIN`` from the carrier's pole, which the notes and the caption name."""
    from graphplan.graphic.gears import SEGMENT_MIN
    from graphplan.report.gears import gears_json
    from graphplan.sheets.form import form
    from graphplan.sheets.gears import _plan, note_parts, on_sheet
    g, sol = _train()
    mesh, vel, _ = on_sheet(g, sol, form("A1"), 0.5, "en")
    u, wH = _willis(sol.train)
    assert vel.h_carrier and vel.h_carrier >= 1.5 * vel.h
    assert abs(vel.segments["H"]) >= SEGMENT_MIN
    assert abs(vel.omega["H"] - wH) <= 0.25 * vel.mu_omega_carrier + 1e-9 + wH * 0.03     # ruler + heights
    notes = " ".join(note_parts(gears_json(sol, mesh, vel, ""), "en", mesh, vel)[-1])
    assert "p'_ω of its own" in notes and f"h_H = {vel.h_carrier:g} mm" in notes
    caption = [q.text for q in _plan(vel, "en").items if q.kind == "text"]
    assert any(f"h_H = {vel.h_carrier:g} mm" in t for t in caption)


def test_a_short_carrier_segment_is_said_with_its_share_of_the_ruler():
    """u = 40: where the carrier reads off its plan's own pole (pictures drawn small: no room for
    p'_ω), the notes say ωH's segment as read and the ruler's half division as a percent of it. On
    the A1 sheet the row under the meshing (no longer capped by its height: stop 49) holds the
    carrier's own pole, its segment over 1,5 times what the plan's pole gives."""
    import re

    from graphplan.graphic.gears import construct_train
    from graphplan.report.gears import gears_json
    from graphplan.sheets.form import form
    from graphplan.sheets.gears import construct_on, note_parts
    _, sol = _train(40.0, "uk")
    mesh, big, _ = construct_on(sol, form("A1"), 0.5, "uk")
    assert big.h_carrier and abs(big.segments["H"]) >= 1.5 * abs(big.segments["H"]) * big.h / big.h_carrier
    vel = construct_train(sol.train, 0.5, "uk")                     # the first, small pictures
    s = abs(vel.segments["H"])
    assert vel.h_carrier is None and 0 < s < 10.0
    notes = " ".join(note_parts(gears_json(sol, mesh, vel, ""), "uk", mesh, vel)[-1])
    said = re.search(r"Відрізок ω_H на плані лише ([\d,]+) мм \(ω_H = ω_1/([\d,]+)\): півподілки лінійки — "
                     r"([\d,]+) % від нього", notes)
    assert said, notes
    seg, u, share = (float(x.replace(",", ".")) for x in said.groups())
    assert seg == s and u == pytest.approx(_willis(sol.train)[0], abs=0.005)
    assert share == pytest.approx(100 * 0.25 / s, rel=0.05)
