"""The explorer draws each link as the sheets do (model.linkshape): through all its points — the
review four-bar's rocker O2–B–D to D = 1.3·O2B, a coupler with a point off AB as a plate — from the
outline the Python side exports (the names of the points it runs through), so the page and the sheets
cannot disagree. Checked against D placed by hand, O2 + 1.3·(B − O2), in the data and in chromium
(one browser, a few seconds); and the premise of exporting names once: a rigid motion keeps the
outline's order (hypothesis). A coulisse pivoted at its only joint runs to its end B; its ω3 is read
as the textbook reads it; every product and quotient the replay writes is right as written; ω1's
arc turns as the crank; no letter of the mechanism is overprinted; no dot floats in the serve
preview."""
from __future__ import annotations

import cmath
import functools
import json
import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as hs

from conftest import scene_study
from graphplan.model.linkshape import outline_order, rigid_outline
from review_scenes import FOURBAR   # the second review's four-bar: P_D at D = 1.3·O2B on the rocker

# a coulisse pivoted at its only joint O2, the block A sliding in it, its end B = 0.30 m from O2
COULISSE = """title = "Кулісний механізм"
title_en = "Slotted-lever mechanism"

[frame.points]
O1 = [0, 0.12]
O2 = [0, 0]

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.08
rpm = 60
direction = "ccw"
points = { S1 = 0.5 }

[[link]]
name = "2"
number = 2
joints = ["A"]
slides_on = "O2B"

[[link]]
name = "O2B"
number = 3
joints = ["O2"]
length = 0.30
points = { S3 = 0.5, B = 1.0 }

[branch]
A = 1

[positions]
count = 12
start = "max"
accel = [2]
"""

PLATE = FOURBAR.replace('points = { S2 = 0.5 }', 'points = { S2 = 0.5, E = [0.12, 0.06] }')


@functools.lru_cache(maxsize=None)
def _data(text: str):
    """(study, plans, the page's data at a 10° grid) of a scene, built once for the module."""
    from graphplan.graphic.plans import build_plans
    from graphplan.report.explorer import explorer_data
    st = scene_study(text)
    plans = build_plans(st, precision=0.5)
    return st, plans, explorer_data(st, step=10.0, plans=plans)


def _link(data, name: str) -> dict:
    return next(L for L in data["scheme"]["links"] if L["name"] == name)


def _dist(z: complex, a: complex, b: complex) -> float:
    """From z to the segment ab."""
    t = max(0.0, min(1.0, ((z - a) * (b - a).conjugate()).real / abs(b - a) ** 2))
    return abs(z - (a + t * (b - a)))


def test_the_rocker_runs_to_d_and_d_is_on_it():
    _, plans, data = _data(FOURBAR)
    rocker = _link(data, "O2B")
    assert rocker["outline"] == ["O2", "D"] and rocker["points"] == ["D"]
    assert _link(data, "AB")["outline"] == ["A", "B"]
    grid, O2 = data["grid"]["points"], complex(*data["scheme"]["frame"]["O2"])
    mu = plans.mu_l
    for i in range(len(data["grid"]["phi"])):
        B = complex(grid["B"]["x"][i], grid["B"]["y"][i]) / mu
        D = complex(grid["D"]["x"][i], grid["D"]["y"][i]) / mu
        assert abs(D - (O2 + 1.3 * (B - O2))) < 1e-4        # D where the scene puts it, by hand
        assert _dist(B, O2, D) < 1e-4                        # the drawn bar O2–D passes B


@pytest.mark.parametrize("text", [FOURBAR, PLATE], ids=["extension", "plate"])
def test_the_outline_is_the_sheets_at_every_lab_position(text):
    """At every lab position the page's outline, through the position plan's points, is the very
    polyline the sheets draw (rigid_outline of that position)."""
    from graphplan.model.linkshape import extra_points
    from graphplan.drawing.plans import joints_at
    st, plans, data = _data(text)
    for p in plans.positions:
        pts = joints_at(plans.scheme, p.layout)
        for L in data["scheme"]["links"]:
            link = st.mech.links[L["name"]]
            if len(link.joints) < 2:
                continue
            sheet = rigid_outline([pts[j] for j in link.joints], [pts[q] for q in extra_points(link) if q in pts])
            page = [pts[n] for n in L["outline"]]
            if len(sheet) > 2:           # a closed outline: the same polygon, from whichever corner
                k = min(range(len(page) - 1), key=lambda k: abs(page[k] - sheet[0]))
                page = page[k:-1] + page[:k] + [page[k]]
            assert page == pytest.approx(sheet, abs=1e-9), (p.key, L["name"])


def test_a_point_off_the_coupler_makes_it_a_plate():
    _, _, data = _data(PLATE)
    coupler = _link(data, "AB")
    assert coupler["points"] == ["E"]
    assert coupler["outline"][0] == coupler["outline"][-1] and sorted(coupler["outline"][:-1]) == ["A", "B", "E"]


@settings(max_examples=60, deadline=None)
@given(hs.lists(hs.tuples(hs.floats(-80, 80), hs.floats(-80, 80)), min_size=3, max_size=6),
       hs.floats(0, 2 * math.pi), hs.complex_numbers(max_magnitude=500))
def test_a_rigid_motion_keeps_the_outlines_order(xy, turn, shift):
    """The page draws every angle from one position's order: it must not depend on the position."""
    pts = [complex(x, y) for x, y in xy]
    if abs(pts[1] - pts[0]) < 1.0 or min(abs(a - b) for k, a in enumerate(pts) for b in pts[:k]) < 0.5:
        return
    moved = [z * cmath.exp(1j * turn) + shift for z in pts]
    near_line = [abs(((z - pts[0]) * ((pts[1] - pts[0]) / abs(pts[1] - pts[0])).conjugate()).imag)
                 for z in pts[2:]]
    if any(0.2 < d < 0.4 for d in near_line):       # the 0.3 mm threshold itself: round-off may tip it
        return
    a, b = outline_order(pts[:2], pts[2:]), outline_order(moved[:2], moved[2:])
    if len(a) > 2 and a[0] == a[-1]:                 # a closed outline: the same cycle, maybe rotated
        k = b.index(a[0])
        b = b[k:-1] + b[:k] + [a[0]]
    assert a == b


def test_the_coulisse_runs_to_b_as_on_the_sheet():
    """The coulisse O2A3 is drawn along its guide through O2, the block A and its end B (placed by
    hand: B = O2 + 0.30 m toward A) at every angle, 4 mm beyond its outermost points; at the lab's
    positions its ends are the position plan's (the sheet's) own."""
    from graphplan.drawing.plans import position_record
    st, plans, data = _data(COULISSE)
    lines = data["grid"]["slots"]["O2B"]
    assert len(lines) == 1 and len(lines[0]) == len(data["grid"]["phi"])
    pts, mu = data["grid"]["points"], plans.mu_l
    for i, (x0, y0, x1, y1) in enumerate(lines[0]):
        a, b = complex(x0, y0), complex(x1, y1)
        A = complex(pts["A"]["x"][i], pts["A"]["y"][i]) / mu
        B = 0.30 / mu * A / abs(A)                                   # O2 at the origin
        assert abs(complex(pts["B"]["x"][i], pts["B"]["y"][i]) / mu - B) < 1e-3
        for z in (0j, A, B):
            assert _dist(z, a, b) < 2e-3
        assert min(abs(a - B), abs(b - B)) == pytest.approx(4.0, abs=2e-3) or \
            min(abs(a - A), abs(b - A)) == pytest.approx(4.0, abs=2e-3)
    from graphplan.drawing.plans import joints_at
    rec = position_record(plans)
    drawn = [tuple(complex(*q) for q in it.points) for it in rec.items if it.kind == "segment" and it.role == "link"]
    for p in plans.positions:
        i = data["grid"]["phi"].index(min(data["grid"]["phi"], key=lambda f: abs(f - p.phi)))
        shift = joints_at(plans.scheme, p.layout)["O2"]            # the sheet's origin is the crank's pivot
        ends = complex(*lines[0][i][:2]) + shift, complex(*lines[0][i][2:]) + shift
        # (the sheet breaks a line where a letter or O2's support stands: its pieces on the line reach
        # both ends — the stub past O2 may stop at the support, but the line reaches O2 itself)
        pieces = [q for s in drawn if _dist(s[0], *ends) < 0.01 and _dist(s[1], *ends) < 0.01 for q in s]
        far = max(ends, key=lambda e: abs(e - shift))
        assert min(abs(q - far) for q in pieces) < 0.01, p.key
        near = min(ends, key=lambda e: abs(e - shift))
        assert min(min(abs(q - near), abs(q - shift)) for q in pieces) < 1.0, p.key


def test_the_coulisse_is_read_as_the_textbook_reads_it():
    """Its ω3 and ε3 are in the values' table under the sheets' symbols (ω_3, v_A3A2, a^k_A3A2), equal
    to the plans' readings; the velocity plan's last step reads ω3 off the group's point A3; the
    Coriolis step writes 2·ω_3·v_A3A2."""
    st, plans, data = _data(COULISSE)
    sym = {r["q"]: r.get("symbol") for r in data["rows"]}
    assert sym["omega_O2B"] == "ω_3" and sym["epsilon_O2B"] == "ε_3"
    assert sym["vrel_A"] == "v_A3A2" and sym["k_A"] == "a^k_A3A2"
    for p in plans.positions:
        got = data["readings"][str(p.key)]
        assert got["omega_O2B"][1] == pytest.approx(p.velocity.entries["omega_O2B"].vector.real, rel=1e-5)
    steps = [s["caption"]["en"] for r in data["records"] for s in r["steps"]]
    omega = [c for c in steps if c.startswith("ω_{3} = ")]
    assert len(omega) == len(plans.positions) and all(c.startswith("ω_{3} = v_{A3O2}/l_{O2A3}") for c in omega)
    coriolis = [c for c in steps if "a^k_{A3A2} = 2·" in c]
    assert coriolis and all("2·ω_{3}·v_{A3A2}" in c and "O2B" not in c.split("(")[0] for c in coriolis)


@pytest.mark.parametrize("text", [FOURBAR, PLATE, COULISSE], ids=["four-bar", "plate", "coulisse"])
def test_the_similarity_arithmetic_is_right_as_written(text):
    """Every product the replay writes, ratio × length = result (0,750838·144,0 = 108,1 mm), holds
    to the 0.1 mm it is written to, and every ω and ε, (mm · μ)/l = value, to the 4 figures it is
    written to (the coulisse's l_O2A3 is the ruler's 18.0 mm, as the plan divides by it): a student
    checking them with a calculator finds them right."""
    import re
    from graphplan.util.words import num
    _, _, data = _data(text)
    products = rates = 0
    for rec in data["records"]:
        for step in rec["steps"]:
            c = step["caption"]["en"]
            for m in re.finditer(r"([\d.]+)·([\d.]+) = ([\d.]+) mm", c):
                k, length, result = m.groups()
                assert f"{float(k) * float(length):.1f}" == result, m.group(0)
                products += 1
            m = re.search(r"\(([\d.]+) mm · ([\d.]+) \(m/s²?\)/mm\)/([\d.]+) m = ([\d.]+) rad", c)
            if m:
                mm_, mu, length, value = m.groups()
                assert num(float(mm_) * float(mu) / float(length), "en") == value, m.group(0)
                rates += 1
    assert products >= 5 and rates >= 5


# -- in the browser -------------------------------------------------------------------------------------

from test_view import driver, graphplan, open_page  # noqa: E402,F401

MECH = r"""
const svg = document.getElementById('mech');
const P = (s) => s.trim().split(/\s+/).map((q) => q.split(',').map(Number));
const links = [...svg.querySelectorAll('polyline.link, polygon.link')].map((e) => P(e.getAttribute('points')));
const lines = [...svg.querySelectorAll('line.link')].map((e) => [[+e.getAttribute('x1'), +e.getAttribute('y1')], [+e.getAttribute('x2'), +e.getAttribute('y2')]]);
const d = svg.querySelector('circle[data-point="D"]');
const texts = [...svg.querySelectorAll('#mech-labels text')].map((t) => t.textContent);
return {links: links.concat(lines), D: d ? [+d.getAttribute('cx'), +d.getAttribute('cy')] : null, texts: texts};
"""


def test_d_lies_on_the_drawn_rocker_at_every_angle(driver, tmp_path):  # noqa: F811
    scene = tmp_path / "fourbar.toml"
    scene.write_text(FOURBAR, encoding="utf-8")
    page = tmp_path / "fourbar.html"
    r = graphplan("view", str(scene), "-o", str(page), "--step", "10", "--lang", "en")
    assert r.returncode == 0, r.stderr
    open_page(driver, page)
    data = json.loads(driver.execute_script("return document.getElementById('explorer-data').textContent")
                      .replace("<\\/", "</"))
    mu, pts = data["scales"]["mu_l"], data["grid"]["points"]
    O2 = complex(*data["scheme"]["frame"]["O2"])
    for i in range(0, len(data["grid"]["phi"]), 4):
        driver.execute_script("window.graphplanExplorer.show(arguments[0])", i)
        got = driver.execute_script(MECH)
        B = complex(pts["B"]["x"][i], pts["B"]["y"][i]) / mu
        D = O2 + 1.3 * (B - O2)                               # by hand; the SVG's y runs down
        flip = lambda z: complex(z.real, -z.imag)              # noqa: E731
        assert got["D"] and abs(complex(*got["D"]) - flip(D)) < 0.01, (i, got["D"], D)
        segs = [(complex(*a), complex(*b)) for poly in got["links"] for a, b in zip(poly, poly[1:])]
        through = [s for s in segs if _dist(flip(D), *s) < 0.01 and _dist(flip(B), *s) < 0.01
                   and _dist(flip(O2), *s) < 0.01]
        assert through, f"angle {data['grid']['phi'][i]}: no drawn segment joins O2, B and D"
        assert got["texts"].count("D") == 1
        assert omega1_sense(driver) == 1
        assert driver.execute_script(OVERPRINT, ["mech"]) == [], data["grid"]["phi"][i]


# on a drawing: two letters overlapping, or a letter crossed by a link's line (screen boxes, 1 px in)
OVERPRINT = r"""
const out = [];
for (const id of arguments[0]) {
  const svg = document.getElementById(id); if (!svg) continue;
  const texts = [...svg.querySelectorAll('text')].filter(t => t.textContent.trim());
  const boxes = texts.map(t => { const r = t.getBoundingClientRect(); return [r.left + 1, r.top + 2, r.right - 1, r.bottom - 2, t.textContent]; });
  for (let i = 0; i < boxes.length; i++) for (let j = i + 1; j < boxes.length; j++) {
    const a = boxes[i], b = boxes[j];
    if (a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3]) out.push([id, 'text', a[4], b[4]]);
  }
  const segs = [];
  const M = svg.getScreenCTM();
  const P = (x, y) => { const p = svg.createSVGPoint(); p.x = x; p.y = y; const q = p.matrixTransform(M); return [q.x, q.y]; };
  svg.querySelectorAll('.link').forEach(e => {
    if (e.tagName === 'line') segs.push([P(+e.getAttribute('x1'), +e.getAttribute('y1')), P(+e.getAttribute('x2'), +e.getAttribute('y2'))]);
    else { const pts = e.getAttribute('points').trim().split(/\s+/).map(s => s.split(',').map(Number)).map(p => P(p[0], p[1]));
      for (let k = 0; k + 1 < pts.length; k++) segs.push([pts[k], pts[k + 1]]);
      if (e.tagName === 'polygon') segs.push([pts[pts.length - 1], pts[0]]); }
  });
  const hit = (a, b, box) => { let t0 = 0, t1 = 1; const dx = b[0] - a[0], dy = b[1] - a[1];
    const p = [-dx, dx, -dy, dy], q = [a[0] - box[0], box[2] - a[0], a[1] - box[1], box[3] - a[1]];
    for (let i = 0; i < 4; i++) { if (p[i] === 0) { if (q[i] < 0) return false; continue; } const t = q[i] / p[i];
      if (p[i] < 0) { if (t > t1) return false; if (t > t0) t0 = t; } else { if (t < t0) return false; if (t < t1) t1 = t; } } return true; };
  boxes.forEach(b => segs.forEach(s => { if (hit(s[0], s[1], b)) out.push([id, 'line', b[4]]); }));
}
return out;
"""


def omega1_sense(d) -> int:
    """The sense ω1's arc on the mechanism turns about the crank's pivot: +1 counter-clockwise (the
    drawing's y up), from the arc's ends; checked against the one the page says."""
    arc = json.loads(d.find_element("id", "mech").get_attribute("data-omega1"))
    (x0, y0), (x1, y1), (cx, cy) = arc["from"], arc["to"], arc["centre"]
    turn = (x0 - cx) * (y1 - cy) - (y0 - cy) * (x1 - cx)
    assert abs(math.hypot(x0 - cx, y0 - cy) - math.hypot(x1 - cx, y1 - cy)) < 1e-2 and abs(turn) > 1e-6
    assert (1 if turn > 0 else -1) == arc["sense"]
    return arc["sense"]


def test_the_serve_pages_preview_draws_the_rocker_to_d():
    """`graphplan serve`'s preview draws the mechanism with the sheets' own draw_links: at any angle
    of its slider a drawn bar runs from a joint (O2) through a joint (B) to a dot D = O2 + 1.3·(O2B),
    and D is lettered there."""
    from graphplan.web.jobs import _at
    st = scene_study(FOURBAR)
    for phi in (0.0, 100.0, 230.0):
        rec, _ = _at(st, phi, "en")
        joints = [complex(*q.points[0]) for q in rec.items if q.kind == "point" and q.role == "joint"]
        dots = [complex(*q.points[0]) for q in rec.items if q.kind == "point" and q.role == "dot"]
        segs = [(complex(*a), complex(*b)) for q in rec.items if q.kind in ("segment", "polyline")
                and q.role == "link" for a, b in zip(q.points, q.points[1:])]
        found = [(P, Q, R) for P in joints for Q in joints for R in dots
                 if abs(Q - P) > 1.0 and abs(R - (P + 1.3 * (Q - P))) < 1e-6]
        assert len(set(found)) == 1, found        # (a joint is drawn once per link meeting there)
        P, Q, R = found[0]
        assert any(_dist(P, *s) < 1e-6 and _dist(Q, *s) < 1e-6 and _dist(R, *s) < 1e-6 for s in segs)
        letter = next(q for q in rec.items if q.kind == "text" and q.text == "D")
        x0, y0, x1, y1 = letter.bounds()
        assert abs(complex(max(x0 - R.real, 0, R.real - x1), max(y0 - R.imag, 0, R.imag - y1))) < 3.0


def test_the_coulisse_reaches_b_in_the_browser(driver, tmp_path):  # noqa: F811
    """The page draws the coulisse through O2, the block's A and its end B (by hand: 0.30 m from O2
    toward A) at every angle shown, ω1's arc about O1 turning clockwise as the crank does (ccw in
    the four-bar's test), no letter overprinted, and letters B and ω_3 in its table."""
    scene = tmp_path / "coulisse.toml"
    scene.write_text(COULISSE.replace('direction = "ccw"', 'direction = "cw"'), encoding="utf-8")
    page = tmp_path / "coulisse.html"
    r = graphplan("view", str(scene), "-o", str(page), "--step", "10", "--lang", "en")
    assert r.returncode == 0, r.stderr
    open_page(driver, page)
    data = json.loads(driver.execute_script("return document.getElementById('explorer-data').textContent")
                      .replace("<\\/", "</"))
    mu, pts = data["scales"]["mu_l"], data["grid"]["points"]
    flip = lambda z: complex(z.real, -z.imag)              # noqa: E731
    for i in range(0, len(data["grid"]["phi"]), 5):
        driver.execute_script("window.graphplanExplorer.show(arguments[0])", i)
        got = driver.execute_script(MECH.replace('"D"', '"B"'))
        A = complex(pts["A"]["x"][i], pts["A"]["y"][i]) / mu
        B = 0.30 / mu * A / abs(A)                               # O2 at the origin
        assert got["D"] and abs(complex(*got["D"]) - flip(B)) < 0.01
        segs = [(complex(*a), complex(*b)) for poly in got["links"] for a, b in zip(poly, poly[1:])]
        assert any(all(_dist(flip(z), *s) < 0.01 for z in (0j, A, B)) for s in segs), data["grid"]["phi"][i]
        assert got["texts"].count("B") == 1
        assert omega1_sense(driver) == -1
        assert driver.execute_script(OVERPRINT, ["mech"]) == [], data["grid"]["phi"][i]
    heads = driver.execute_script("return [...document.querySelectorAll('#values th')].map((t) => t.textContent)")
    assert "ω3, rad/s" in heads and "vA3A2, m/s" in heads, heads


@pytest.mark.parametrize("text", [FOURBAR, PLATE, COULISSE], ids=["four-bar", "plate", "coulisse"])
def test_no_point_floats_in_the_serve_preview(text):
    """In `graphplan serve`'s preview every point drawn as a dot (S1, D, E, the coulisse's B) lies on a
    drawn line of its link — none is left floating off its link."""
    from graphplan.web.jobs import _at
    st = scene_study(text)
    for phi in (30.0, 150.0, 270.0):
        rec, _ = _at(st, phi, "en")
        dots = [complex(*q.points[0]) for q in rec.items if q.kind == "point" and q.role == "dot"]
        segs = [(complex(*a), complex(*b)) for q in rec.items if q.kind in ("segment", "polyline", "polygon")
                and q.role == "link" for a, b in zip(q.points, list(q.points[1:]) + list(q.points[:1]))
                if q.kind == "polygon" or (a, b) != (q.points[-1], q.points[0])]
        assert dots
        for z in dots:
            assert min(_dist(z, *s) for s in segs) < 1e-6, (phi, z)
