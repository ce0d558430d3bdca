"""Stop 58 (gears58b): the A1 gear sheet's column and the row under the meshing."""
import pytest

from graphplan.drawing.layout import GAP, Leaf
from graphplan.graphic.record import Record


def _box(name: str, w: float, h: float) -> Leaf:
    r = Record()
    r.segment((0.0, 0.0), (w, h))
    return Leaf(name, record=r)


def _column_room():
    from graphplan.sheets.compose import field_of, keep_out
    from graphplan.sheets.form import form
    f = form("A1")
    y1, keep = field_of(f)[3], keep_out(f)
    return f, y1 - keep[3] - GAP        # the column's height from the field's top to GAP over the title block


@pytest.mark.parametrize("over", [0.0, 1.01, 4.0, 5.9])
def test_the_column_closes_its_gaps_to_keep_its_tables_size(over):
    """Stop 58: GEARS51's English column needed 513,0 mm for 512 (x_min's note a line longer) and its tables
    fell to the ruled 2,5-mm letters. Parts GAP apart that overrun the room by less than 3·(GAP − COLUMN_GAP)
    now stand closer, never under COLUMN_GAP, each below the last, the notes on the title block."""
    from graphplan.sheets.gears import COLUMN_GAP, zones
    f, room = _column_room()
    hs = [120.0, 50.0, 85.0]
    notes = room + over - sum(hs) - 3 * GAP
    side = [_box(n, 180.0, h) for n, h in zip(("geometry", "quality", "train"), hs)] + [_box("notes", 180.0, notes)]
    pages = zones([_box("meshing", 300.0, 300.0)], side, f, 185.0)
    assert pages is not None
    got = sorted((p for p in pages[0] if p.name != "meshing"), key=lambda p: -p.box[3])
    assert [p.name for p in got] == ["geometry", "quality", "train", "notes"]
    gaps = [a.box[1] - b.box[3] for a, b in zip(got, got[1:])]
    assert all(g >= COLUMN_GAP - 1e-9 for g in gaps), gaps
    assert sum(gaps) == pytest.approx(3 * GAP - over, abs=1e-6) if over else all(g >= GAP - 1e-9 for g in gaps)
    from graphplan.sheets.compose import keep_out
    assert got[-1].box[1] == pytest.approx(keep_out(f)[3] + GAP)      # the notes stand on the title block


def test_a_column_too_tall_for_the_least_gaps_is_refused():
    """Past 3·(GAP − COLUMN_GAP) the column does not fit: the caller tries the smaller tables (``SIZES``)."""
    from graphplan.sheets.gears import COLUMN_GAP, zones
    f, room = _column_room()
    hs = [120.0, 50.0, 85.0]
    notes = room + 3 * (GAP - COLUMN_GAP) + 0.1 - sum(hs) - 3 * GAP
    side = [_box(n, 180.0, h) for n, h in zip(("geometry", "quality", "train"), hs)] + [_box("notes", 180.0, notes)]
    assert zones([_box("meshing", 300.0, 300.0)], side, f, 185.0) is None


def test_pictures_whose_printed_bounds_agree_tie():
    """``_rank`` with u1H compares the bounds as the notes print them (% of u1H to 0,01): ±0,805 % and
    ±0,808 % are both «±0,81 %» and tie (``_grown`` then keeps the larger scheme); ±0,80 against ±0,81 does not."""
    from types import SimpleNamespace as NS
    from graphplan.sheets.gears import _rank
    v = lambda b: NS(h=50.0, segments={"H": 30.0}, ratio_bound=b)      # noqa: E731
    u = 5.1
    assert _rank(v(0.0410747), u) == _rank(v(0.0412108), u)
    assert _rank(v(0.0410747)) < _rank(v(0.0412108))                  # (bare, the narrower still wins)
    assert _rank(v(0.0407), u) < _rank(v(0.0413), u)


@pytest.mark.slow
def test_the_planetary_pictures_take_the_larger_scheme_where_the_printed_bound_is_the_same():
    """Stop 58 (the blind reviewer's 13/30 + 20/31/82 on A1): the pictures stood at 1:2, 273 × 165 mm, in a
    257-mm row beside 146-mm λ diagrams, a 50-mm blank under their caption, because 1:2 read u1H within
    ±0,805 % where 1:1 read within ±0,808 % — one bound on the sheet, «±0,81 %». Now: of the pictures
    ``_grown`` tried, the chosen one has the narrowest printed bound and, among those, the largest scheme."""
    import tomllib
    import graphplan.sheets.gears as G
    from graphplan.exact.gears import solve
    from graphplan.model.gears import build
    from graphplan.sheets.form import form
    from review_scenes import GEARS58B
    tried = []
    filled = G.filled

    def spy(*a, **kw):
        d = filled(*a, **kw)
        if d is not None and not kw.get("full"):
            tried.append(d[0])
        return d
    G.filled = spy
    try:
        sol = solve(build(tomllib.loads(GEARS58B), "GEARS58B"))
        mesh, vel, plan = G.construct_on(sol, form("A1"), 0.5, "uk")
    finally:
        G.filled = filled
    u = sol.train.ratio
    pr = lambda v: (v.h < G.H_MIN - 1e-9, round(100.0 * v.ratio_bound / u, 2))     # noqa: E731
    assert len({round(v.mu_l, 9) for v in tried}) >= 2
    best = min(pr(v) for v in tried)
    assert pr(vel) == best
    assert vel.mu_l == min(v.mu_l for v in tried if pr(v) == best)      # the largest scheme of the tie
    assert vel.ratio_bound / u * 100 <= G.LAB_LIMIT
    # the pictures no shorter than the λ diagrams beside them (the row's blank under them gone)
    assert G._size(plan)[1] >= G._size(G.sliding_leaf(mesh.lam, "uk"))[1]
