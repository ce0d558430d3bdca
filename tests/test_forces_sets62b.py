"""Stop 62 (sets62b): the slotter's A3 force set drew its sheet 1 as the tall scheme with the Zhukovsky
lever beside it (the first later drawing that fit), 69 % of its 20 mm cells blank, where the charts
over the turn (M_b, the resistance) one under the other fill the room beside the scheme. A sheet the
next drawing would leave mostly empty now takes, of the drawings that read on their own (the
acceleration plan, the lever, the charts), those that leave it fullest."""
from __future__ import annotations

from graphplan.drawing.layout import Leaf, arrange
from graphplan.sheets.forceset import movable, pack, units_of

REGION = (25.0, 10.0, 410.0, 287.0)           # an A3 sheet's field (385 × 277 mm)
FIRST = (224.0, 5.0, 415.0, 66.0)             # form 1's title block (sheet 1)
LATER = (224.0, 5.0, 415.0, 26.0)             # form 2a's
FIELD = 385.0 * 277.0

# the slotter's cells as its A3 set draws them (stop 62, measured): (w, h) mm
SCHEME, ACC, LEVER = (135.0, 262.0), (147.0, 263.0), (153.0, 167.0)
MOMENT, RESISTANCE, R05 = (197.0, 104.0), (156.0, 106.0), (199.0, 79.0)
GROUPS = [(42.0, 263.0), (60.0, 150.0), (50.0, 104.0)]
PLANS = [(69.0, 263.0), (93.0, 150.0), (92.0, 104.0)]


def _leaves():
    return {"scheme": [Leaf("scheme 0", *SCHEME)],
            "groups": [Leaf(f"groups {i}", *g) for i, g in enumerate(GROUPS)],
            "forces": [Leaf(f"forces {i}", *p) for i, p in enumerate(PLANS)],
            "acceleration": [Leaf("acceleration 0", *ACC)], "lever": [Leaf("lever 0", *LEVER)],
            "charts": [Leaf("charts 0", *MOMENT), Leaf("charts 1", *RESISTANCE), Leaf("charts 2", *R05)],
            "hodographs": []}


def _names(sheet):
    out = []
    for spot in sheet:
        out += [leaf.name for leaf, _ in arrange(spot.node, (0.0, 0.0, spot.w, spot.h))]
    return out


def _packed(plan_first):
    return pack(units_of(_leaves(), REGION[2] - REGION[0], plan_first), [], None, REGION, FIRST, LATER)


def test_the_slotters_scheme_takes_the_charts_that_fill_its_sheet():
    for plan_first in (True, False):
        sheets = _packed(plan_first)
        names = [_names(s) for s in sheets]
        # beside the 135-mm scheme: 250 mm of width, 221 mm under form 1's title block; the lever
        # alone takes (135·262 + 153·167)/field = 0.57, the two charts one under the other
        # (104 + 10 + 106 = 220 mm ≤ 221) 0.68: the fuller
        assert names[0] == ["scheme 0", "charts 0", "charts 1"], names
        share = sum(s.w * s.h for s in sheets[0]) / FIELD
        assert abs(share - (135 * 262 + 197 * 104 + 156 * 106) / FIELD) < 1e-9
        assert share > (135 * 262 + 153 * 167) / FIELD
        flat = [n for page in names for n in page]
        assert sorted(flat) == sorted(x.name for xs in _leaves().values() for x in xs)    # each once
        # the groups still in the analysis' order, each beside its own force plan
        groups = [n for n in flat if n.startswith("groups")]
        assert groups == ["groups 0", "groups 1", "groups 2"]
        for page in names:
            for n in page:
                if n.startswith("groups"):
                    assert "forces " + n.split()[1] in page


def test_the_lever_is_still_brought_where_it_alone_fits():
    """No chart fits beside the scheme: the lever is brought forward, as before (test_forces_fill)."""
    leaves = _leaves()
    leaves["charts"] = [Leaf("charts 0", 300.0, 104.0)]
    sheets = pack(units_of(leaves, REGION[2] - REGION[0], False), [], None, REGION, FIRST, LATER)
    assert _names(sheets[0]) == ["scheme 0", "lever 0"]


def test_which_drawings_read_on_their_own():
    assert all(movable([Leaf(n, 1.0, 1.0)], charts=True) for n in ("acceleration 0", "lever 0", "charts 2", "moment",
                                                       "resistance", "reaction R05", "acceleration plan"))
    assert not any(movable([Leaf(n, 1.0, 1.0)], charts=True) for n in ("scheme 0", "groups 0", "forces 1", "hodograph R12"))
    assert not movable([Leaf("lever 0", 1.0, 1.0), Leaf("lever 0", 2.0, 2.0)])    # alternatives: not one drawing


def test_the_packing_is_deterministic():
    a, b = _packed(True), _packed(True)
    assert [[(_names([s]), s.x, s.d) for s in p] for p in a] == [[(_names([s]), s.x, s.d) for s in p] for p in b]


def test_a_sheet_of_two_drawings_takes_no_chart_before_the_groups():
    """The shaper's A3 set: a sheet holding the scheme and the acceleration plan already, the first
    group too tall for it, takes the lever (the rule before), never the charts over the turn — they
    would read before the groups."""
    leaves = _leaves()
    leaves["scheme"] = [Leaf("scheme 0", 100.0, 150.0)]
    leaves["acceleration"] = [Leaf("acceleration 0", 120.0, 150.0)]
    assert (100 * 150 + 120 * 150) / FIELD < 0.5           # mostly empty: the rule acts
    sheets = pack(units_of(leaves, REGION[2] - REGION[0], True), [], None, REGION, FIRST, LATER)
    names = [_names(s) for s in sheets]
    assert names[0] == ["scheme 0", "acceleration 0", "lever 0"], names
    flat = [n for page in names for n in page]
    assert all(flat.index(c) > flat.index("groups 2") for c in ("charts 0", "charts 1", "charts 2")), names
