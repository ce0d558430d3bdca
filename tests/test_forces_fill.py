"""Review 7 #1 and #18 and the lead's notes: a force set's sheet left mostly empty because the next
drawing does not fit beside the last (the slotter's and the sieve's scheme alone on sheet 1 of an A3
set, 80–82 % of its 20 mm cells blank) takes a drawing that reads on its own (the acceleration plan,
the Zhukovsky lever) or has its drawings grown; two drawings stand at least ``SPACE`` apart, so a
label of one never stands nearer another's lettering than its own (group II(2-3)'s "R₀₃" read as one
label with group I(0-1)'s "A" across a 5 mm gap)."""
from __future__ import annotations

import itertools

import pytest

from graphplan.drawing.layout import Leaf, arrange
from graphplan.sheets.forceset import FILL_SHARE, SPACE, pack, units_of

REGION = (25.0, 10.0, 410.0, 287.0)           # an A3 sheet's field (385 × 277 mm)
KEEP = (224.0, 5.0, 415.0, 66.0)              # its title block


def _leaves(scheme=(152.0, 257.0), group=(42.0, 264.0), plan=(91.0, 140.0), lever=(126.0, 142.0),
            acc=(168.0, 265.0)):
    """A tall scheme (the slotter's at 1:2.5), a group as tall beside its force plan, the
    acceleration plan, the lever: no group fits beside the scheme, the lever does."""
    return {"scheme": [Leaf("scheme 0", *scheme)], "groups": [Leaf("groups 0", *group)],
            "forces": [Leaf("forces 0", *plan)], "acceleration": [Leaf("acceleration 0", *acc)],
            "lever": [Leaf("lever 0", *lever)], "charts": [], "hodographs": []}


def _names(sheet):
    out = []
    for spot in sheet:
        out += [leaf.name for leaf, _ in arrange(spot.node, (0.0, 0.0, spot.w, spot.h))]
    return out


def test_a_scheme_alone_on_its_sheet_takes_the_lever_beside_it():
    sheets = pack(units_of(_leaves(), REGION[2] - REGION[0], plan_first=False), [], None, REGION, KEEP, KEEP)
    names = [_names(s) for s in sheets]
    assert names[0] == ["scheme 0", "lever 0"], names
    assert [n for page in names for n in page if n.startswith("groups")] == ["groups 0"]   # each drawing once
    assert sum(len(p) for p in names) == 5


def test_a_sheet_already_half_full_keeps_the_reading_order():
    """A wide scheme that takes more than ``FILL_SHARE`` of the sheet: nothing is brought forward."""
    sheets = pack(units_of(_leaves(scheme=(370.0, 160.0)), REGION[2] - REGION[0], plan_first=False), [], None,
                  REGION, KEEP, KEEP)
    assert 370.0 * 160.0 / (385.0 * 277.0) >= FILL_SHARE
    flat = [n for s in sheets for n in _names(s)]
    assert flat.index("lever 0") > flat.index("groups 0")


def test_next_round_is_the_next_round_coefficient():
    """The next larger drawing's coefficient: round (the series 1, 2, 2.5, 4, 5 or GOST 2.302's 1.5,
    7.5 × 10^k), smaller than μ, and no round value between them."""
    from graphplan.graphic.scales import on_round
    from graphplan.sheets.forces import next_round
    rounds = sorted({m * 10.0 ** k for m in (1.0, 1.5, 2.0, 2.5, 4.0, 5.0, 7.5) for k in range(-5, 4)})
    for mu in rounds[3:-3]:
        nxt = next_round(mu)
        assert nxt is not None and on_round(nxt) and nxt < mu
        assert not [r for r in rounds if nxt * (1 + 1e-9) < r < mu * (1 - 1e-9)], (mu, nxt)


def test_one_sheet_tree_sets_the_groups_and_their_plans_the_space_apart():
    """The A1 composition's tree (every shape): the groups and the force plans (where review 7 #18
    read two groups' labels as one) at least ``SPACE`` apart, every other drawing the layout's gap."""
    from graphplan.drawing.layout import GAP
    from graphplan.sheets.forces import SHAPES, _tree
    leaves = {"scheme": [Leaf("scheme", 200, 150)], "groups": [Leaf("g0", 90, 80), Leaf("g1", 60, 70)],
              "forces": [Leaf("p0", 100, 60), Leaf("p1", 80, 50)], "acceleration": [Leaf("acc", 150, 100)],
              "lever": [Leaf("lever", 120, 140)], "charts": [Leaf("c0", 160, 90), Leaf("c1", 140, 90)],
              "hodographs": [Leaf(f"h{i}", 60, 60) for i in range(4)]}
    column = Leaf("column", 300, 300)
    for shape in SHAPES:
        boxes = [(leaf.name, b) for leaf, b in arrange(_tree(shape, leaves, 2, column), (0.0, 0.0, 1200.0, 900.0))]
        for (n, a), (m, b) in itertools.combinations(boxes, 2):
            apart = max(b[0] - a[2], a[0] - b[2], b[1] - a[3], a[1] - b[3])
            least = SPACE if n[0] in "gp" and m[0] in "gp" else GAP
            assert apart >= least - 1e-6, (shape, n, m, apart)


@pytest.mark.slow
@pytest.mark.parametrize("name", ["slotter", "SIEVE"])
def test_no_sheet_of_an_a3_force_set_is_mostly_empty(name):
    """The slotter's and the sieve's A3 force sets (sheet 1: the scheme alone, 82 and 80 % of its
    cells blank): no sheet but the last more than two-thirds empty, no more sheets than before (5),
    every drawing clear (``defects``)."""
    import review_scenes
    from conftest import example, scene_study
    from sheetfill import empty_share

    from graphplan.sheets.compose import SheetOptions, defects
    from graphplan.sheets.form import form
    from graphplan.sheets.forces import build_forces_sheet
    study = scene_study(getattr(review_scenes, name)) if name.isupper() else example(name)
    sheet = build_forces_sheet(study, form("A3"), SheetOptions(precision=0.5, sheet="forces"))
    empty = [empty_share(page) for page in sheet.pages]
    assert len(empty) <= 5 and max(empty[:-1]) <= 0.67, empty
    assert defects(sheet) == []
