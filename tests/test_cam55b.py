"""Stop 55 (cam55b): the notes and `graphplan cam` list every law's shocks by kind with the cam turns φ
where they occur — judged from the one-sided values (exact.cam.shocks), not the law's name. The truth
here is the test's own: one-sided finite differences of the follower's s(φ) on a 0.25° grid over the
whole turn, for every pair of laws, with and without dwells (a jump of ds/dφ a rigid shock, of
d²s/dφ² alone a soft one); and the textbook's table for the cases it states."""
from __future__ import annotations

import itertools
import math

import numpy as np
import pytest

from graphplan.exact.cam import motion, shocks
from graphplan.model.cam import Cam

LAWS = ("parabolic", "cosine", "cycloidal", "linear", "trapezoidal")
# rise, far dwell, return, near dwell: dwells both; no far dwell (equal and unequal phases); no near
# dwell; no dwell at all — the knots (Φ/8 …) land on the 0.25° grid
PHASES = ((120.0, 30.0, 80.0, 130.0), (120.0, 0.0, 120.0, 120.0), (160.0, 0.0, 80.0, 120.0),
          (96.0, 64.0, 200.0, 0.0), (160.0, 0.0, 200.0, 0.0))
H = 0.02


def cam(phases, laws) -> Cam:
    return Cam("t", "translating", H, phases, laws, (30.0, 30.0), 10.0, 1)


def fd_shocks(c: Cam) -> list[tuple[float, str]]:
    """The jumps found by one-sided differences of s alone (no derivative of the package's)."""
    grid = np.arange(0.0, 360.0, 0.25)
    d = 2e-3                                   # degrees
    s = lambda x: motion(c, np.mod(x, 360.0))[0]          # noqa: E731
    r = math.radians(d)
    s0, l1, l2, r1, r2 = (s(grid + k * d) for k in (0, -1, -2, 1, 2))
    vl, vr = (3 * s0 - 4 * l1 + l2) / (2 * r), (-3 * s0 + 4 * r1 - r2) / (2 * r)
    al, ar = (s0 - 2 * l1 + l2) / r ** 2, (s0 - 2 * r1 + r2) / r ** 2
    rise, _, ret, _ = c.phases
    v_big = H / math.radians(min(rise, ret))
    a_big = H / math.radians(min(rise, ret)) ** 2
    out = []
    for k, phi in enumerate(grid):
        if abs(vr[k] - vl[k]) > 1e-3 * v_big:
            out.append((float(phi), "rigid"))
        elif abs(ar[k] - al[k]) > 1e-2 * a_big:
            out.append((float(phi), "soft"))
    return out


@pytest.mark.parametrize("phases", PHASES)
def test_shocks_are_the_finite_differences_jumps(phases):
    for laws in itertools.product(LAWS, LAWS):
        c = cam(phases, laws)
        got = [(round(x.phi_deg, 6), x.kind) for x in shocks(c)]
        assert got == fd_shocks(c), (phases, laws)


def test_the_textbooks_table_with_dwells():
    """Rise 120°, far dwell 30°, return 80° (from 150°), near dwell: linear — rigid at the phase's
    ends; parabolic — soft at its start, middle and end; cosine — soft at its ends; cycloidal and
    trapezoidal — none."""
    ph = (120.0, 30.0, 80.0, 130.0)
    want = {"linear": [(0, "rigid"), (120, "rigid")], "parabolic": [(0, "soft"), (60, "soft"), (120, "soft")],
            "cosine": [(0, "soft"), (120, "soft")], "cycloidal": [], "trapezoidal": []}
    for name, rise in want.items():
        got = [(round(x.phi_deg), x.kind) for x in shocks(cam(ph, (name, "cycloidal")))]
        assert got == rise, name
        ret = [(150 + p * 80 // 120, k) for p, k in rise]
        got = [(round(x.phi_deg), x.kind) for x in shocks(cam(ph, ("cycloidal", name)))]
        assert got == ret, name


def test_joins_without_a_dwell_judged_from_both_sides():
    """A cosine rise into a cosine return of the same angle: d²s/dφ² = −hπ²/(2Φ²) on both sides of
    the top — no shock there; of unequal angles a soft one; a parabolic into a linear return a rigid one."""
    kinds = lambda ph, laws: {round(x.phi_deg): x.kind for x in shocks(cam(ph, laws))}      # noqa: E731
    assert 120 not in kinds((120.0, 0.0, 120.0, 120.0), ("cosine", "cosine"))
    assert 120 not in kinds((120.0, 0.0, 120.0, 120.0), ("parabolic", "parabolic"))
    assert kinds((160.0, 0.0, 80.0, 120.0), ("cosine", "cosine"))[160] == "soft"
    assert kinds((160.0, 0.0, 80.0, 120.0), ("parabolic", "linear"))[160] == "rigid"


@pytest.mark.parametrize("lang", ["uk", "en"])
def test_the_notes_line(lang, tmp_path_factory):
    """The notes and the terminal say the shocks by kind with their φ (the lead's CAM55: a parabolic
    rise of 150° into a linear return of 90°, no far dwell), and a cycloidal cam has none."""
    from conftest import cam_constructed
    from graphplan.report.cam import cam_json, cam_lines, cam_table
    from review_scenes import CAM55
    sol, g = cam_constructed(CAM55, tmp_path_factory)
    doc = cam_json(sol, g, "x")
    lines = cam_lines(doc, lang)
    rise, far, ret, _ = sol.cam.phases
    assert sol.cam.laws == ("parabolic", "linear") and far == 0
    (line,) = [x for x in lines if x.startswith(("Удари", "Shocks"))]
    r, t = rise + far, rise + far + ret
    num = lambda x: f"{x:g}".replace(".", ",") if lang == "uk" else f"{x:g}"      # noqa: E731
    rigid = f"φ = {num(r)}°, {num(t)}°"
    soft = f"φ = 0°, {num(rise / 2)}°"
    if lang == "uk":
        assert line == f"Удари: жорсткі (стрибок ds/dφ) при {rigid}; м’які (стрибок d^{{2}}s/dφ^{{2}}) при {soft}"
    else:
        assert line == f"Shocks: rigid (a jump of ds/dφ) at {rigid}; soft (a jump of d^{{2}}s/dφ^{{2}}) at {soft}"
    assert ("ds/dφ) " + ("при " if lang == "uk" else "at ") + rigid) in cam_table(doc, lang, "T")
