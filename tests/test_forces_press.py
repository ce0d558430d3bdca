"""The fourth review's six-bar press on the force sheet (review4, items 8–10): every force's letter at its
own arrow, the groups freed from the ram's guide, the groups drawn at least at the scheme's scale."""
from __future__ import annotations

import pytest

from conftest import example, scene_study

from review_scenes import PRESS4 as PRESS     # the fourth review's six-bar press


@pytest.fixture(scope="module")
def press():
    """The press's A1 force sheet: its plan and its drafter."""
    from conftest import scene_plan
    p, nat, dr = scene_plan(PRESS, "forces", "A1", precision=0.5)
    return scene_study(PRESS), p, dr


def _strays(rec, lang: str) -> list:
    """The force letters of a scheme or group that do not read as their own arrow's: the nearest
    force arrow to the letter's box is another's — unless it stands on a leader from its own arrow's
    end, at least 1.5 mm clear of every other arrow."""
    from graphplan.drawing.labels import box_to_segment
    from graphplan.util.words import force_symbol
    arrows = {q.text: (complex(*q.points[0]), complex(*q.points[1]))
              for q in rec.items if q.kind == "vector" and q.text}
    by_letter = {force_symbol(n, lang): n for n in arrows}
    leaders = [(complex(*q.points[0]), complex(*q.points[1])) for q in rec.items
               if q.kind == "segment" and q.role == "label"]
    out = []
    for q in rec.items:
        if q.kind != "text" or q.layer != "labels" or q.text not in by_letter:
            continue
        name, box = by_letter[q.text], q.bounds()
        gaps = sorted((box_to_segment(box, a, b), n) for n, (a, b) in arrows.items())
        if gaps[0][1] == name:
            continue
        ends = arrows[name]
        led = any(min(box_to_segment(box, z, z) for z in ld) < 1.5
                  and min(abs(z - e) for z in ld for e in ends) < 2.0 for ld in leaders)
        if not (led and all(g >= 1.5 for g, n in gaps if n != name)):
            out.append((rec.title, q.text, gaps[:2]))
    return out


def test_the_press_forces_letters_stand_at_their_own_arrows(press):
    """Review4 #9: the scheme lettered "Φ4" beside P_E's shaft and "P_E" by Φ4's head, group
    II(4–5) "Φ4" at the head of Φ5's arrow. On the sheet (both languages) every force's letter is
    nearer its own arrow than any other (or on a leader from it, clear of the others)."""
    st, p, dr = press
    for lang in ("uk", "en"):
        d = dr.drawings(p.mu, lang)
        assert not [s for rec in d["scheme"] + d["groups"] for s in _strays(rec, lang)], lang


@pytest.mark.parametrize("name", ["shaper", "slotter"])
def test_the_examples_forces_letters_stand_at_their_own_arrows(name):
    """The same on the examples' scheme and groups, drawn at their default scales."""
    from graphplan.drawing import forces as forcedraw
    from graphplan.sheets import forces as sf
    from graphplan.sheets.compose import SheetOptions
    dr = sf.ForceDrafter(example(name), SheetOptions(precision=0.5, sheet="forces"))
    fp = dr.fp()
    recs = [forcedraw.mechanism_record(fp, "uk")] + [forcedraw.group_record(fp, gp, "uk") for gp in fp.groups]
    assert not [s for rec in recs for s in _strays(rec, "uk")]


def test_a_group_freed_from_the_frame_keeps_no_guide(press):
    """Review4 #10: group II(4–5) kept the ram's hatched guide. A group is drawn freed from the
    frame — no frame line, no hatching, the reaction R05 in the guide's place — while the scheme keeps
    the guide (its frame line and hatch strokes)."""
    st, p, dr = press
    d = dr.drawings(p.mu, "uk")
    for rec in d["groups"]:
        assert not [q for q in rec.items if q.layer == "frame"], rec.title
    ram = next(rec for rec in d["groups"] if "4-5" in rec.title)
    assert "R_{05}" in {q.text for q in ram.items if q.kind == "text"}
    assert [q for q in d["scheme"][0].items if q.role == "hatch"]
    assert [q for q in d["scheme"][0].items if q.role == "frame"]


def test_the_press_groups_at_least_at_the_schemes_scale(press):
    """Review4 #8/#12: the groups at 1:10 beside a 1:4 scheme on a sheet half empty, the arms of
    II(4–5) 1 and 1.5 mm. Every group is drawn at least as large as the scheme (μl no coarser), so
    that each arm of its moment equations reads ≥ 4 times the 0.5-mm ruler."""
    st, p, dr = press
    fp = dr.groups_fp(p.mu)
    for gp in fp.groups:
        assert gp.mu_l <= p.mu["scheme"] * (1 + 1e-9), (gp.label, gp.mu_l, p.mu["scheme"])
        arms = [abs(t.arm_mm) for eq in gp.equations for t in eq.terms if not t.couple and abs(t.arm_mm) > 0]
        assert min(arms) >= 2.0, (gp.label, arms)


@pytest.mark.parametrize("name", ["SIXBAR10", "COMPRESSOR", "SIXBAR"])
def test_the_one_sheet_composition_never_draws_the_groups_smaller_than_the_scheme(name):
    """Review 4's rule on every scene, not only the press: the A1 composition's scales (before the
    drawings are drawn) put no group at a coarser μl than the scheme. Its families grown one after
    another left SIXBAR10's scheme at 1:2 beside groups at 1:4, the compressor's at 1:1 beside 1:2."""
    import review_scenes
    from graphplan.sheets import forces as sf
    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.form import form
    dr = sf.ForceDrafter(scene_study(getattr(review_scenes, name)), SheetOptions(precision=0.5, sheet="forces"))
    _, p = sf._one_sheet(sf.measure(dr), form("A1"))
    assert p.mu["groups"] <= p.mu["scheme"] * (1 + 1e-9), (p.mu["scheme"], p.mu["groups"])


@pytest.mark.slow
@pytest.mark.parametrize("name", ["shaper", "slotter"])
def test_the_examples_sheets_letter_each_force_at_its_own_arrow(name):
    """The examples' scheme and groups as their A1 force sheets draw them, in both languages."""
    from graphplan.sheets import forces as sf
    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.form import form
    p, _, dr = sf.plan(example(name), form("A1"), SheetOptions(precision=0.5, sheet="forces"))
    for lang in ("uk", "en"):
        d = dr.drawings(p.mu, lang)
        assert not [s for rec in d["scheme"] + d["groups"] for s in _strays(rec, lang)], lang
