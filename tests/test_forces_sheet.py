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
    st = _study(request.param)
    p, nat, dr = sf.plan(st, form("A1"), SheetOptions(precision=0.5, sheet="forces"))
    return {"st": st, "fp": dr.groups_fp(p.mu), "drawings": dr.drawings(p.mu, "uk"),
            "tables": sf._tables(dr, p.mu, "uk", p.tables), "name": request.param}


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
    for rec in records:
        arms = [p for p in rec.items if p.kind == "segment" and p.text.startswith("h")]
        forces = {v.text: v for v in _vectors(rec)}
        for arm in arms:
            m = re.match(r"h\d+ = ([0-9.]+) mm to (.+)$", arm.text)
            assert m, arm.text
            h, name = float(m.group(1)), m.group(2)
            (ax, ay), (fx, fy) = arm.points
            (px, py), (qx, qy) = forces[name].points
            ux, uy = qx - px, qy - py
            n = math.hypot(ux, uy)
            off = abs((fx - px) * uy - (fy - py) * ux) / n          # the foot's distance from the line
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
    """The shared overprint checker counts 0 overprinted words on the rendered sheet."""
    import subprocess
    import sys
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
    res = subprocess.run([sys.executable, "/work/shared/tools/overprint.py", str(out)], capture_output=True,
                         text=True, check=True)
    assert " 0 overprinted" in res.stdout, res.stdout
