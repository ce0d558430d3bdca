"""The force sheet drawn and named by the textbook's rules (issue 32 item 3), read off the sheet's own
records: R_ij is the force of link i on link j, so every force drawn on a group is R<from><to> with
<to> in the group (the crank loaded at A by R21, an inner group by R43 from the outer one); the crank
group carries M_зр with its sense; each arm h ends on its own force's line, perpendicular to it, as
long as it reads; the groups' tables' "on the drawing, mm" at the ruler's 0.5 mm; the tables numbered
1, 2, 3 … in reading order; hodograph numbers not crowded. On the examples and on generated
mechanisms (a four-bar, an offset crank-slider)."""
from __future__ import annotations

import math
import re

import pytest

import random_mechanisms as rm
from conftest import example, scene_study
from test_forces import loaded

SCENES = ["shaper", "slotter", "fourbar", "offset slider"]
FORCE_NAME = re.compile(r"^R(\d+)-?(\d+)$")


def _study(name: str):
    if name == "fourbar":
        return scene_study(loaded(rm.rrr(0.05, 0.3, 0.3, 0.25, 10.0, 1)[0], "B", 30.0))
    if name == "offset slider":
        return scene_study(loaded(rm.rrp(0.05, 0.2, 0.02, 0, 7.5, 1)[0], "B", 180.0))
    return example(name)


@pytest.fixture(scope="module", params=SCENES)
def sheet(request):
    """The force sheet's plan (A1), its drawings and its tables as the sheet draws them."""
    from graphplan.sheets import forces as sf
    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.form import form
    from conftest import shared

    def build():
        st = _study(request.param)
        # the plan shared with test_lever_hodographs (the same scene, format and options: one search)
        p, nat, dr = shared(f"force plan A1 0.5 {request.param}",
                            lambda: sf.plan(st, form("A1"), SheetOptions(precision=0.5, sheet="forces")))
        return {"st": st, "fp": dr.groups_fp(p.mu), "drawings": dr.drawings(p.mu, "uk"),
                "tables": sf._tables(dr, p.mu, "uk", p.tables), "name": request.param}
    return shared(f"test_forces_sheet.sheet[{request.param}]", build)


def _numbers(mech, links) -> set[int]:
    return {mech.links[link].number for link in links}


def _split(name: str, mech) -> tuple[int, int]:
    """R<from><to> → (from, to): one digit each, or dashed once a number has two (R10-11)."""
    m = FORCE_NAME.match(name)
    assert m, name
    if "-" in name:
        return int(m.group(1)), int(m.group(2))
    assert len(name) == 3, name
    return int(name[1]), int(name[2])


def _vectors(rec):
    return [p for p in rec.items if p.kind == "vector"]


def test_every_force_on_a_group_is_named_from_its_source_to_the_group(sheet):
    """R<from><to>: <to> in the group drawn, <from> outside it (the frame, or a link of another
    group); the crank group is loaded at its pin by R21, every group after the first (the outer one
    solved first) by a reaction handed over from the group before it (R43 on the shaper's II(2-3))."""
    st, fp = sheet["st"], sheet["fp"]
    mech = st.mech
    groups = sheet["drawings"]["groups"]
    assert len(groups) == len(fp.groups)
    for gp, rec in zip(fp.groups, groups):
        inside = _numbers(mech, gp.links)
        names = [v.text for v in _vectors(rec) if FORCE_NAME.match(v.text)]
        assert names, gp.label
        for name in names:
            frm, to = _split(name, mech)
            assert to in inside and frm not in inside, (gp.label, name)
    crank = [v.text for v in _vectors(groups[-1])]
    assert "R21" in crank and "R12" not in crank
    if len(fp.groups) > 2:                      # an outer group hands R43 (or its like) inward
        second = [v.text for v in _vectors(groups[1])]
        handed = [n for n in second if FORCE_NAME.match(n) and _split(n, mech)[0] in _numbers(mech, fp.groups[0].links)]
        assert handed, second
        if sheet["name"] == "shaper":
            assert "R43" in second and "R34" not in second


def test_the_crank_group_shows_the_balancing_moment_with_its_sense(sheet):
    """M_зр at the crank's pivot: an arc with an arrowhead turning in the sense of M_b's sign."""
    fp = sheet["fp"]
    rec = sheet["drawings"]["groups"][-1]
    heads = [v for v in _vectors(rec) if v.text == "M_b"]
    assert len(heads) == 1
    arcs = [p for p in rec.items if p.kind == "arc" and p.step == heads[0].step]
    (cx, cy), = arcs[0].points[:1]
    (x0, y0), (x1, y1) = heads[0].points
    turning = (x0 - cx) * (y1 - y0) - (y0 - cy) * (x1 - x0)       # > 0: counter-clockwise
    assert math.copysign(1.0, turning) == math.copysign(1.0, fp.balancing)
    assert any(p.kind == "text" and "зр" in p.text for p in rec.items)


def _arms_on_their_lines(records) -> None:
    from graphplan.drawing.forces import arm_symbol
    for rec in records:
        arms = [p for p in rec.items if p.kind == "segment" and p.text.startswith("h")]
        forces = {v.text: v for v in _vectors(rec)}
        for arm in arms:
            m = re.match(r"h_\{(.+)\} = ([0-9.]+) mm to (.+)$", arm.text)
            assert m, arm.text
            h, name = float(m.group(2)), m.group(3)
            assert m.group(1) == arm_symbol(name)[3:-1], arm.text     # lettered by its own force: h_{G2}
            (ax, ay), (fx, fy) = arm.points
            (px, py), (qx, qy) = forces[name].points
            ux, uy = qx - px, qy - py
            n = math.hypot(ux, uy)
            off = abs((fx - px) * uy - (fy - py) * ux) / n          # the foot's distance from the line
            if off >= 0.01:
                # an arrow set beside its link in a lane: its line of action drawn thin along it,
                # as long as it, within a few lanes — the arm ends on that line
                lines = [q for q in rec.items if q.kind == "segment" and q.role == "projection"
                         and abs(math.hypot(q.points[1][0] - q.points[0][0], q.points[1][1] - q.points[0][1]) - n) < 0.01
                         and abs((q.points[1][0] - q.points[0][0]) * uy - (q.points[1][1] - q.points[0][1]) * ux) < 1e-6 * n * n
                         and abs((q.points[0][0] - px) * uy - (q.points[0][1] - py) * ux) / n <= 3 * 2.5 + 1e-6]
                off = min([abs((fx - q.points[0][0]) * uy - (fy - q.points[0][1]) * ux) / n for q in lines] + [off])
            assert off < 0.01, (rec.title, arm.text, off)
            assert abs((fx - ax) * ux + (fy - ay) * uy) / n < 0.01   # perpendicular
            assert abs(math.hypot(fx - ax, fy - ay) - h) <= 0.25 + 1e-9


def test_each_arm_ends_on_its_own_forces_line(sheet):
    """The foot of each arm h lies on the line of the force it is named for (within 0.01 mm),
    the arm is perpendicular to it, and its drawn length reads as the ruler's value printed."""
    _arms_on_their_lines(sheet["drawings"]["groups"])


@pytest.mark.parametrize("kind", ["RRR", "RRP", "RPR", "PRP", "RPP"])
def test_every_dyad_kind_is_named_and_armed_by_the_rule(kind):
    """Generated mechanisms of every dyad kind (tests/random_mechanisms.py): each force drawn on a
    group is R<from><to> with <to> in it, the crank group gets R21 and M_зр, each arm ends on its
    own force's line."""
    from graphplan.drawing import forces as forcedraw
    from graphplan.graphic.forceplans import construct
    from test_forces import KINDS
    make, point = KINDS[kind]
    st = scene_study(loaded(make()[0], point, 30.0))
    fp = construct(st, 40.0, precision=0.5)
    recs = [forcedraw.group_record(fp, gp, "uk") for gp in fp.groups]
    for gp, rec in zip(fp.groups, recs):
        inside = _numbers(st.mech, gp.links)
        for name in [v.text for v in _vectors(rec) if FORCE_NAME.match(v.text)]:
            frm, to = _split(name, st.mech)
            assert to in inside and frm not in inside, (kind, gp.label, name)
    assert "R21" in [v.text for v in _vectors(recs[-1])]
    assert [v for v in _vectors(recs[-1]) if v.text == "M_b"]
    _arms_on_their_lines(recs)


def _number(text: str) -> float | None:
    try:
        return float(text.replace(",", ".").replace("−", "-"))
    except ValueError:
        return None


def test_tables_numbered_in_reading_order_and_lengths_to_the_ruler(sheet):
    """Table 1, 2, 3 … in the order the sheet reads them, each titled; the groups' "на
    кресленні, мм" to the ruler's 0.5 mm."""
    seen = []
    for name, rec in sheet["tables"]:
        titles = sorted((p for p in rec.items if p.kind == "text" and re.match(r"^Таблиця \d", p.text)),
                        key=lambda p: -p.points[0][1])
        assert titles, name
        seen += [int(re.match(r"^Таблиця (\d+)\.", p.text).group(1)) for p in titles]
        if name.startswith("table "):
            row = next(p for p in rec.items if p.kind == "text" and p.text == "на кресленні, мм")
            cells = [_number(p.text) for p in rec.items if p.kind == "text" and p is not row
                     and abs(p.points[0][1] - row.points[0][1]) < 0.05]
            values = [c for c in cells if c is not None]
            assert values and all(abs(v * 2 - round(v * 2)) < 1e-9 for v in values), (name, values)
    assert seen == list(range(1, len(seen) + 1))


def test_hodograph_numbers_are_not_crowded(sheet):
    """No two position numbers of a hodograph start within 2.5 mm of each other."""
    for rec in sheet["drawings"]["hodographs"]:
        spots = [p.points[0] for p in rec.items if p.kind == "text" and re.match(r"^\d+(–\d+)?$", p.text)]
        for i, a in enumerate(spots):
            for b in spots[i + 1:]:
                assert math.dist(a, b) >= 2.5, (rec.title, a, b)


@pytest.mark.slow
@pytest.mark.parametrize("name", SCENES)
def test_force_sheets_have_no_overprint(name, tmp_path):
    """The reader's-eye check (tests/inkcheck.py) counts 0 overprinted words on the rendered sheet."""
    from graphplan.cli.main import main
    path = tmp_path / "scene.toml"
    if name in ("shaper", "slotter"):
        from conftest import ROOT
        path = ROOT / "examples" / f"{name}.toml"
    else:
        make = {"fourbar": lambda: loaded(rm.rrr(0.05, 0.3, 0.3, 0.25, 10.0, 1)[0], "B", 30.0),
                "offset slider": lambda: loaded(rm.rrp(0.05, 0.2, 0.02, 0, 7.5, 1)[0], "B", 180.0)}[name]
        path.write_text(make(), encoding="utf-8")
    out = tmp_path / "forces.svg"
    assert main(["sheet", str(path), "--sheet", "forces", "-o", str(out)]) == 0
    from inkcheck import overprinted
    from graphplan.drawing.fonts import register
    register()                                    # the packaged font, as a browser loads it
    svg = out.read_text(encoding="utf-8")
    assert overprinted(svg) == []
    from svgboxes import off_field
    from graphplan.sheets.form import form
    assert off_field(svg, form("A1")) == []


def _shaft(v):
    (px, py), (qx, qy) = v.points
    return complex(px, py), complex(qx, qy)


def _shared(a, b, c, d, tol: float = 0.3) -> float:
    """How long (mm) the segments a–b and c–d run on one line (0 when they do not)."""
    u = (b - a) / abs(b - a)
    if any(abs(((p - a) * u.conjugate()).imag) > tol for p in (c, d)):
        return 0.0
    lo, hi = sorted((((c - a) * u.conjugate()).real, ((d - a) * u.conjugate()).real))
    return max(0.0, min(hi, abs(b - a)) - max(lo, 0.0))


def test_no_force_is_drawn_over_another_or_inside_a_link(sheet):
    """Each force on a group's drawing reads on its own: no two arrows share a stretch of one line
    (Φ5 over P_D at the ram), and no force lies inside a link's line (Φ1 along the crank at S1)."""
    for rec in sheet["drawings"]["groups"]:
        vs = [v for v in _vectors(rec) if not v.text.startswith("M")]
        for i, v in enumerate(vs):
            a, b = _shaft(v)
            for w in vs[i + 1:]:
                c, d = _shaft(w)
                assert _shared(a, b, c, d) < 1.0, (sheet["name"], rec.title, v.text, w.text)
            for p in rec.items:
                if p.kind == "polyline" and p.role == "link" and p.layer == "mechanism":
                    pts = [complex(x, y) for x, y in p.points]
                    for s, e in zip(pts, pts[1:]):
                        if abs(e - s) > 1e-6:
                            assert _shared(s, e, a, b) < 1.0, (sheet["name"], rec.title, v.text)


def test_a_load_at_a_centre_of_mass_is_applied_at_a_marked_point(sheet):
    """A weight or inertia force at a link's centre of mass starts at a point lettered S_i
    (or the link's named centre) on the group's drawing, as the teacher reads "applied at S1"."""
    fp = sheet["fp"]
    for gp, rec in zip(fp.groups, sheet["drawings"]["groups"]):
        mu = gp.mu_l or fp.mu_l
        texts = [p.text for p in rec.items if p.kind == "text"]
        points = [complex(*p.points[0]) for p in rec.items if p.kind == "point"]
        for f in gp.forces:
            if f.force and f.name[0] in "GΦ":
                z = f.at / mu
                assert any(abs(z - w) < 0.05 for w in points), (sheet["name"], gp.label, f.name)
        kin, mech = fp.ks.kin, fp.ks.mech
        joints = [complex(kin.bodies[k].at(mech.links[k].local[j])[0][0]) for k in gp.links
                  for j in mech.links[k].joints]
        for f in gp.forces:
            if f.force and f.name[0] == "G" and all(abs(f.at - w) > 1e-6 for w in joints):
                lk = mech.links[f.link]          # not at a lettered joint: its centre lettered
                centre = lk.com or f"S{lk.number}"
                assert any(t.replace("_", "").replace("{", "").replace("}", "") == centre
                           for t in texts), (sheet["name"], gp.label, centre, texts)


def _box_gap(p, q) -> float:
    ax0, ay0, ax1, ay1 = p.bounds()
    bx0, by0, bx1, by1 = q.bounds()
    dx = max(0.0, max(ax0, bx0) - min(ax1, bx1))
    dy = max(0.0, max(ay0, by0) - min(ay1, by1))
    return math.hypot(dx, dy)


def test_force_plan_labels_stand_apart(sheet):
    """No two labels of a force plan closer than their letter height (R23, R12 and Rⁿ12 on
    near-parallel sides named apart; the crank plan's tiny G1, Φ1 not lettered in a clump)."""
    for rec in sheet["drawings"]["forces"]:
        labels = [p for p in rec.items if p.kind == "text" and not p.text.startswith("μ")]
        for i, p in enumerate(labels):
            for q in labels[i + 1:]:
                assert _box_gap(p, q) >= min(p.size, q.size) - 1e-9, (sheet["name"], rec.title, p.text, q.text)


def test_tiny_plan_vectors_are_named_under_the_plan(sheet):
    """A force plan's vector too short to letter (< 3 mm) is named in the line under the plan with
    its bound ("G_1, Φ_1 < 2 мм"), the bound above its drawn length."""
    from graphplan.drawing.forces import TINY_MM
    from graphplan.util.words import force_symbol
    fp = sheet["fp"]
    for gp, rec in zip(fp.groups, sheet["drawings"]["forces"]):
        caption = next(p.text for p in rec.items if p.kind == "text" and p.text.startswith("μ"))
        for s in gp.sides:
            if 1e-9 < s.mm < TINY_MM:
                sym = force_symbol(s.name, "uk")
                assert sym in caption, (sheet["name"], gp.label, s.name, caption)
                bound = float(caption.split("<")[1].split()[0].replace(",", "."))
                assert s.mm < bound, (s.name, s.mm, caption)


def test_lever_forces_at_one_image_do_not_cover_each_other(sheet):
    """On the Zhukovsky lever two forces at one image on one line (the slotter's Φ5 and P_D at d)
    are drawn side by side: no two arrows share a stretch of a line."""
    for rec in sheet["drawings"]["lever"]:
        vs = [v for v in _vectors(rec)]
        for i, v in enumerate(vs):
            a, b = _shaft(v)
            for w in vs[i + 1:]:
                c, d = _shaft(w)
                assert _shared(a, b, c, d) < 1.0, (sheet["name"], v.text, w.text)


def _dist(z: complex, a: complex, b: complex) -> float:
    """The distance (mm) from the point z to the segment a–b."""
    d = b - a
    if abs(d) < 1e-12:
        return abs(z - a)
    t = min(max(((z - a) * d.conjugate()).real / abs(d) ** 2, 0.0), 1.0)
    return abs(z - (a + t * d))


def _strokes(p) -> list[tuple[complex, complex]]:
    """A primitive's ink as segments (an arc as 5° chords)."""
    if p.kind == "arc":
        (cx, cy), r = p.points[0], p.radius
        a0, a1 = p.angles
        n = max(2, int(abs(a1 - a0) / 5.0))
        pts = [complex(cx, cy) + r * complex(math.cos(math.radians(a0 + (a1 - a0) * k / n)),
                                             math.sin(math.radians(a0 + (a1 - a0) * k / n))) for k in range(n + 1)]
    else:
        pts = [complex(x, y) for x, y in p.points]
        if p.kind == "polygon":
            pts.append(pts[0])
    return list(zip(pts, pts[1:]))


def _box_dist(z: complex, box) -> float:
    x0, y0, x1, y1 = box
    return abs(complex(max(x0 - z.real, 0.0, z.real - x1), max(y0 - z.imag, 0.0, z.imag - y1)))


def test_the_schemes_supports_stand_clear_of_links_arrows_and_labels(sheet):
    """Every frame pivot's support on the scheme (issue 32, the teacher's mark: drawn straight down
    under each pivot whatever the links did, the crank through its hatching): its bar and hatch
    strokes at least 0.5 mm from every link's bar, every force's arrow and moment's arc, and off
    every label."""
    rec = sheet["drawings"]["scheme"][0]
    pivots = [complex(*p.points[0]) for p in rec.items if p.kind == "point" and p.layer == "frame"]
    assert len(pivots) == sum(1 for n in sheet["st"].mech.frame
                              if any(n in lk.joints for lk in sheet["st"].mech.links.values()))
    lines = [s for p in rec.items if p.layer in ("mechanism", "vectors") and p.kind in
             ("segment", "polyline", "polygon", "vector", "arc") for s in _strokes(p)]
    texts = [p.ink() for p in rec.items if p.kind == "text"]
    for z in pivots:
        strokes = [s for p in rec.items if p.layer == "frame" and p.kind == "segment"
                   for s in _strokes(p) if all(abs(e - z) <= 10.0 for e in s)
                   and min(pivots, key=lambda w: abs(w - s[0])) == z]
        assert len(strokes) == 8, (sheet["name"], z, len(strokes))       # 2 sides, the bar, 5 strokes
        far = [s for s in strokes if min(abs(e - z) for e in s) >= 4.0]  # the bar and the hatching
        assert len(far) == 6
        for a, b in far:
            for k in range(11):
                w = a + (b - a) * k / 10
                near = min(_dist(w, c, d) for c, d in lines)
                assert near >= 0.5, (sheet["name"], z, w, near)
                assert all(_box_dist(w, box) > 0.0 for box in texts), (sheet["name"], z, w)


def test_every_lever_arm_is_drawn_to_its_forces_line_and_lettered_by_it(sheet):
    """The Zhukovsky lever's arms were unlettered: each arm h (from the pole, perpendicular to its
    force's line on the turned plan, the foot on that line or on a lane SIDE_MM beside it) carries
    h with its force's name (h_{G2}, the groups' notation) within a few mm, on a leader at most."""
    from graphplan.drawing.forces import SIDE_MM, arm_symbol
    fp = sheet["fp"]
    rec = sheet["drawings"]["lever"][0]
    forces = {v.text.split(":")[0]: v for v in _vectors(rec) if ": h = " in v.text}
    armed = [t for t in fp.lever.terms if t.vector and abs(t.arm_mm) >= 1.0]
    assert armed
    arms = [p for p in rec.items if p.kind == "segment" and p.text.startswith("h_{")]
    texts = [p for p in rec.items if p.kind == "text"]
    leaders = [p for p in rec.items if p.kind == "segment" and p.role == "label"]
    for t in armed:
        mine = [p for p in arms if p.text.endswith(f" mm to {t.name}")]
        assert mine, t.name
        assert mine[0].text.startswith(arm_symbol(t.name) + " = ")
        pts = [complex(x, y) for p in mine for x, y in p.points]
        foot = max(pts, key=abs)
        assert abs(abs(foot) - abs(t.arm_mm)) <= 0.25 + 1e-9                 # as long as it reads
        (px, py), (qx, qy) = forces[t.name].points
        u = complex(qx - px, qy - py) / abs(complex(qx - px, qy - py))
        assert abs((foot.conjugate() * u).real) < 0.01 * abs(foot)           # perpendicular to the force
        off = abs(((foot - complex(px, py)).conjugate() * u).imag)           # on its line, or a lane's
        assert min(abs(off - k * SIDE_MM) for k in range(4)) < 0.01, (t.name, off)
        sub = arm_symbol(t.name)[3:-1]
        letters = [q for q in texts if q.text.startswith("h_{") and sub in q.text[3:-1].split(",")]
        assert len(letters) == 1, (t.name, [q.text for q in texts if q.text.startswith("h")])
        box = letters[0].ink()
        on_arm = [(a, b) for p in mine for a, b in _strokes(p)]
        near = min(_box_dist(w, box) for a, b in on_arm for w in (a + (b - a) * k / 20 for k in range(21)))
        # a leader runs from 1.2 mm off its anchor on the arm to just short of the letter
        led = any(_box_dist(complex(*q.points[1]), box) < 1.0 and min(_dist(complex(*q.points[0]), a, b)
                                                                     for a, b in on_arm) < 1.5
                  for q in leaders)
        assert near <= 5.0 or led, (sheet["name"], t.name, near)


def test_no_two_leaders_cross(sheet):
    """Two labels' leaders crossing read as an X (the four-bar's lever had h_Φ3's and h_G3's so):
    on every drawing of the force sheet no leader crosses another."""
    def side(p, q, r):
        return ((q - p).conjugate() * (r - p)).imag
    for fam, recs in sheet["drawings"].items():
        for rec in recs:
            leaders = [(complex(*p.points[0]), complex(*p.points[1])) for p in rec.items
                       if p.kind == "segment" and p.role == "label" and len(p.points) == 2]
            for i, (a, b) in enumerate(leaders):
                for c, d in leaders[i + 1:]:
                    assert not (side(a, b, c) * side(a, b, d) < 0 and side(c, d, a) * side(c, d, b) < 0), \
                        (sheet["name"], rec.title, a, b, c, d)


def test_no_leader_crosses_a_link_on_the_scheme_or_a_group(sheet):
    """A force's name on a leader across the link (the four-bar's crank group named G1, laid beside
    the crank, across it once h_G1 had taken the room under its head) reads as the other side's: on
    the scheme and every group no leader crosses a link's bar."""
    def side(p, q, r):
        return ((q - p).conjugate() * (r - p)).imag
    for rec in sheet["drawings"]["scheme"] + sheet["drawings"]["groups"]:
        bars = [s for p in rec.items if p.role == "link" and p.layer == "mechanism"
                and p.kind in ("segment", "polyline") for s in _strokes(p)]
        for p in rec.items:
            if p.kind == "segment" and p.role == "label" and len(p.points) == 2:
                a, b = complex(*p.points[0]), complex(*p.points[1])
                for c, d in bars:
                    assert not (side(a, b, c) * side(a, b, d) < 0 and side(c, d, a) * side(c, d, b) < 0), \
                        (sheet["name"], rec.title, a, b)
