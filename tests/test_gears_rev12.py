"""Reviews 12 and 13's gear sheets (review 12 marks 11, 12, 22; review 13 mark 9): Table 1's lengths to
one count of decimals (a_w to 0,01 mm), Table 2 judging εα ≥ 1,2 by the formula and apart from it on
the value read off the drawing, the λ diagrams' abscissa scale stated, the planetary plan of angular
velocities filling its zone — checked against closed forms written here and the sheet's own zones."""
from __future__ import annotations

import math
import re
import tomllib

import pytest

from review_scenes import GEARS_REV12, GEARS_REV13


def _constructed(tmp_path_factory, text: str, lang: str):
    from graphplan.exact.gears import solve
    from graphplan.model.gears import load
    from graphplan.sheets.form import form
    from graphplan.sheets.gears import construct_on
    path = tmp_path_factory.mktemp("rev12") / "gears.toml"
    path.write_text(text, encoding="utf-8")
    sol = solve(load(path))
    return sol, construct_on(sol, form("A1"), 0.5, lang)


@pytest.fixture(scope="module")
def rev12(tmp_path_factory):
    return _constructed(tmp_path_factory, GEARS_REV12, "uk")


def _rows(rec) -> list[list[str]]:
    rows: dict[float, list] = {}
    for q in rec.items:
        if q.kind == "text":
            rows.setdefault(round(q.points[0][1], 3), []).append((q.points[0][0], q.text))
    return [[t for _, t in sorted(r)] for _, r in sorted(rows.items(), key=lambda kv: -kv[0])]


def _pair(x1: float, x2: float):
    """Review 12's pair by the closed forms: (aw, αw, εα, N1N2) in mm and radians."""
    from scipy.optimize import brentq
    g = tomllib.loads(GEARS_REV12)["gears"]
    (z1, z2), m = g["z"], g["module"] * 1000
    al = math.radians(20.0)
    inv = lambda t: math.tan(t) - t                                           # noqa: E731
    aw_ = brentq(lambda t: inv(t) - (2 * (x1 + x2) * math.tan(al) / (z1 + z2) + inv(al)), 0.1, 0.8)
    aw = m * (z1 + z2) / 2 * math.cos(al) / math.cos(aw_)
    dy = x1 + x2 - (aw - m * (z1 + z2) / 2) / m
    ra = [m * (z / 2 + 1 + x - dy) for z, x in ((z1, x1), (z2, x2))]
    rb = [m * z / 2 * math.cos(al) for z in (z1, z2)]
    eps = (sum(math.sqrt(a * a - b * b) for a, b in zip(ra, rb)) - aw * math.sin(aw_)) / (math.pi * m * math.cos(al))
    return aw, aw_, eps, aw * math.sin(aw_)


def test_table_1_prints_lengths_to_one_count_of_decimals_and_table_2_judges_eps_both_ways(rev12):
    """Mark 12: a_w «110» for 109,977, r_f2 «69» among two-decimal numbers, δ «0» beside «0,40»; εα =
    1,2033 by the formula marked «викон.» while 1,196 was read. Now a_w 109,98, every length of Table 1
    to two decimals, δ 0,00; Table 2's εα row gives both values and both verdicts, the reading's
    against its bound, and the notes say the conditions are judged by the formulas."""
    from graphplan.report.gears import gears_json
    from graphplan.sheets.gears import geometry_table, notes, quality_table
    sol, (mesh, vel, _) = rev12
    doc = gears_json(sol, mesh, vel, "")
    x1, x2 = doc["pair"]["x"]
    aw, _, eps, _ = _pair(x1, x2)
    rows = _rows(geometry_table(doc, "uk"))
    a_w = next(r for r in rows if r[0] == "a_w, мм")
    assert a_w[1] == f"{aw:.2f}".replace(".", ",") == "109,98"
    for r in rows:
        if "мм" in r[0]:                  # the lengths, exact and read: two decimals down each column
            assert all(re.fullmatch(r"−?\d+,\d\d", c) for k, c in enumerate(r) if k in (1, 2, 4, 5) and c), r
    cells = [c for r in rows for c in r[1:]]
    assert "0" not in cells and "69" not in cells and "69,00" in cells
    c = doc["pair"]["contact_ratio"]
    assert c["exact"] == pytest.approx(eps, abs=1e-9) and eps >= 1.2
    row = next(r for r in _rows(quality_table(doc, "uk")) if r[0].startswith("ε_α"))
    ex, gr = (float(v.replace(",", ".")) for v in row[1].split(" / "))
    assert ex == pytest.approx(eps, abs=5e-4) and gr == pytest.approx(c["graphical"], abs=5e-4)
    want = "викон." if gr >= 1.2 else ("у межах" if c["graphical"] + c["bound"] >= 1.2 else "не викон.")
    assert row[-1] == f"викон. / {want}", row
    text = " ".join(notes(doc, "uk", mesh, vel))
    assert (gr < 1.2) == ("за формулами" in text)


def test_the_sliding_diagrams_state_their_abscissa_scale_and_are_sized_to_two_curves(rev12):
    """Mark 22: the abscissa had no scale and N1N2 = 48,58 mm at the meshing's 5:1 made a 300 × 220 mm
    zone. Now the abscissa is drawn at a GOST 2.302 scale (N1N2 at most 200 mm) that the caption
    states, and the drawn N1N2 is the closed form's over it."""
    from graphplan.sheets.gears import sliding_leaf
    sol, (mesh, vel, _) = rev12
    rec = sliding_leaf(mesh.lam, "uk")
    caption = " ".join(q.text for q in rec.items if q.kind == "text" and "μ_l" in q.text)
    m = re.search(r"М (\d+):1 \(μ_l = ([\d,]+) м/мм\)", caption)
    assert m, caption
    mu = float(m.group(2).replace(",", "."))
    assert mu == pytest.approx(0.001 / int(m.group(1)))
    _, _, _, line = _pair(*sol.pair.x)
    axis = next(q for q in mesh.lam.items if q.step == "λ axis").points
    drawn = axis[1][0] - axis[0][0] - 12.0                                      # N1 − 4 … N2 + 8
    assert drawn == pytest.approx(line / (mu * 1000), abs=1e-6) and drawn <= 200.0
    assert mu * 1000 > mesh.mu_l * 1000                                         # smaller than the meshing's 5:1
    b = mesh.lam.bounds()
    assert (b[2] - b[0]) * (b[3] - b[1]) <= 0.5 * 300 * 220


@pytest.mark.parametrize("scene", ["rev12", pytest.param("rev13", marks=pytest.mark.slow)])
def test_the_plan_of_angular_velocities_fills_its_zone_and_reads_u1h_within_its_bound(scene, rev12,
                                                                                        tmp_path_factory):
    """Review 12 mark 11 and review 13 mark 9: ωH read off a 9- and a 3,8-mm segment while the zone was
    two thirds empty. The pictures now reach their zone's width or height (the field less the tables'
    column and the λ diagrams beside them, less the meshing above), u1H by Willis — written here from
    the chosen teeth — is read within the stated bound, and ωH's segment is at least what the zone's width
    over the plan's span would give, half of it at least (the scheme and the velocity picture stand beside
    the plan)."""
    from graphplan.drawing.layout import GAP
    from graphplan.sheets.compose import field_of
    from graphplan.sheets.form import form
    from graphplan.sheets.gears import TITLE, meshing_leaf, sliding_leaf
    sol, (mesh, vel, plan) = rev12 if scene == "rev12" else _constructed(tmp_path_factory, GEARS_REV13, "en")
    z1, z2, z2b, z3 = sol.train.z
    u = 1 + z2 * z3 / (z1 * z2b)
    assert abs(vel.ratio - u) <= vel.ratio_bound
    x0, y0, x1, y1 = field_of(form("A1"))
    lam = sliding_leaf(mesh.lam, "uk").bounds()
    top = meshing_leaf(mesh, "uk").bounds()
    room_w = x1 - x0 - TITLE - GAP - (lam[2] - lam[0]) - 3 * GAP
    room_h = y1 - y0 - (top[3] - top[1]) - 3 * GAP                            # the row under the meshing
    b = plan.bounds()
    w, h = b[2] - b[0], b[3] - b[1]
    assert w <= room_w + 1e-9 and h <= room_h + 1e-9
    if not (w >= 0.95 * room_w or h >= 0.95 * room_h):
        # μω is round (review 48): the plan's segments are ωi/μω and grow by steps (0,5 → 0,4 (rad/s)/mm
        # makes every segment 1,25 times longer), so the pictures fill their zone when the plan at the next
        # round μω — the next longer pole distance h the ruler lays off, μl, μv, h_H as drawn — does not fit
        # (review 13 on A1: 380 × 253 mm in 420 × 308, the sun's segment 305 mm; at the next round μω 381 mm)
        from graphplan.graphic.gears import construct_train, pole_distances
        from graphplan.sheets.gears import _plan
        r = sol.train.radii
        longer = [q for q in pole_distances(vel.mu_v / vel.mu_l, vel.h, 1000.0) if q > vel.h + 1e-9]
        assert longer, vel.h
        va = sol.train.omega["1"] * r["1"] / vel.mu_v                           # vA at the drawn μv
        nxt = construct_train(sol.train, 0.5, "en", ring_mm=r["3"] / vel.mu_l * (1 + 1e-9), va_mm=va * (1 + 1e-9),
                              sun_segment_mm=longer[0] * vel.va_mm / vel.heights["A"] * (1 + 1e-6),
                              h_carrier=vel.h_carrier)
        assert (nxt.mu_l, nxt.mu_v, nxt.h) == pytest.approx((vel.mu_l, vel.mu_v, longer[0]))
        assert nxt.segments["1"] > vel.segments["1"]
        bn = _plan(nxt, "en").bounds()
        assert bn[2] - bn[0] > room_w or bn[3] - bn[1] > room_h, (w, h, bn, room_w, room_h)
    om = sol.train.omega
    span = 1 + abs(om["2"]) / om["1"]                                           # the plan from 2 to 1 over s1
    assert abs(vel.segments["H"]) >= 0.5 * room_w / span / u                  # (the scheme beside it)
