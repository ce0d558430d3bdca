"""Review 47 (a teacher's look at the kinematics sheet of the lead's six-bar compressor, LINK47, and a
four-bar with a coupler point, COUPLER47): the composition measured on the placed drawings."""
from __future__ import annotations

import numpy as np
import pytest

from conftest import scene_study
from review_scenes import LINK47


def _boxes_overlap(a, b) -> bool:
    return a[0] < b[2] - 1e-6 and b[0] < a[2] - 1e-6 and a[1] < b[3] - 1e-6 and b[1] < a[3] - 1e-6


def test_tables_accel_puts_the_acceleration_plans_beside_the_notes_under_the_tables():
    """The "tables-accel" composition: the position plan over the diagrams (left), the velocity plans
    the field's whole height (their first row at its top, the last at its foot), the tables at the top
    right, under them the acceleration plan beside the notes (which keep to the right, over the title
    block); no two boxes overlap and all lie in the field."""
    from graphplan.drawing.layout import Grid, Leaf, arrange
    from graphplan.sheets.kinlayout import tree
    field = (0.0, 0.0, 806.0, 574.0)
    P, D = Leaf("position", 205.0, 182.0), Leaf("diagrams", 361.0, 257.0)
    V = [Leaf(f"v{i}", 62.0, 63.0) for i in range(12)]
    A = [Leaf("a", 98.0, 137.0)]
    T, N = Leaf("tables", 288.0, 287.0), Leaf("notes", 185.0, 229.0)
    got = {leaf.name: b for leaf, b in arrange(tree("tables-accel", P, D, Grid(V, 2, fitted=True),
                                                    Grid(A, 1, fitted=True), None, (T, N)), field)}
    for b in got.values():
        assert field[0] - 1e-6 <= b[0] and b[2] <= field[2] + 1e-6 and field[1] - 1e-6 <= b[1] and b[3] <= field[3] + 1e-6
    names = list(got)
    assert not [(m, n) for i, m in enumerate(names) for n in names[i + 1:] if _boxes_overlap(got[m], got[n])]
    assert abs(got["tables"][3] - field[3]) < 1e-6 and abs(got["tables"][2] - field[2]) < 1e-6
    assert got["a"][3] <= got["tables"][1] + 1e-6 and got["a"][2] <= got["notes"][0] + 1e-6
    assert abs(got["notes"][2] - field[2]) < 1e-6 and abs(got["notes"][1] - field[1]) < 1e-6
    assert abs(got["v0"][3] - field[3]) < 1e-6 and abs(got["v11"][1] - field[1]) < 1e-6
    assert got["v0"][0] >= got["diagrams"][2] - 1e-6 and got["v1"][2] <= got["tables"][0] + 1e-6


def _holds(free: np.ndarray, w: int, h: int) -> bool:
    """Whether a w × h block of free cells lies anywhere in ``free`` (a summed-area table)."""
    s = np.zeros((free.shape[0] + 1, free.shape[1] + 1), dtype=int)
    s[1:, 1:] = np.cumsum(np.cumsum(free.astype(int), 0), 1)
    if h > free.shape[0] or w > free.shape[1]:
        return False
    win = s[h:, w:] - s[:-h, w:] - s[h:, :-w] + s[:-h, :-w]
    return bool((win == w * h).any())


@pytest.mark.slow
def test_link47_a1_leaves_no_blank_that_holds_its_acceleration_plan():
    """The six-bar's A1: no blank of the field (off every drawing's, table's and the notes' ink, and
    off the title block) is large enough to hold the acceleration plan with 5 mm around it — a
    blank that could hold a drawing is a zone the composition left unused ("stacked" left 290 × 170
    mm under the tables, the acceleration plan 98 × 137 mm under the velocity plans)."""
    from graphplan.sheets.compose import field_of, keep_out
    from graphplan.sheets.form import form
    from graphplan.sheets.kinematics import build_kinematics_sheet
    from graphplan.sheets.compose import SheetOptions
    f = form("A1")
    sheet = build_kinematics_sheet(scene_study(LINK47), f, SheetOptions(lang="uk"))
    x0, y0, x1, y1 = field_of(f)
    cell = 2.0
    nx, ny = int((x1 - x0) / cell), int((y1 - y0) / cell)
    free = np.ones((ny, nx), dtype=bool)

    def block(b) -> None:
        i0, i1 = int((b[0] - x0) // cell), int(np.ceil((b[2] - x0) / cell))
        j0, j1 = int((b[1] - y0) // cell), int(np.ceil((b[3] - y0) / cell))
        free[max(j0, 0):max(j1, 0), max(i0, 0):max(i1, 0)] = False
    accel = None
    for p in sheet.placed:
        b = p.record.bounds()
        block(b)
        if p.name.startswith("acceleration plan"):
            accel = b
    block(keep_out(f))
    assert accel is not None
    w, h = (int(np.ceil((accel[2] - accel[0] + 10.0) / cell)), int(np.ceil((accel[3] - accel[1] + 10.0) / cell)))
    assert not _holds(free, w, h)


def test_the_coupler_points_positions_are_dotted_and_numbered_on_its_path():
    """The four-bar's coupler point E (off its coupler AB): a dot at each of its twelve positions,
    where the exact solution puts E (relative to position 0, at μl), and each position's number
    nearer its own dot than any other of E's (a number read off the loop, as the joints' are);
    it drew the loop bare."""
    from graphplan.drawing.plans import position_record
    from graphplan.graphic.plans import build_plans
    from review_scenes import COUPLER47
    st = scene_study(COUPLER47)
    plans = build_plans(st, mu_l=0.002)
    rec = position_record(plans, lang="uk")
    dots = np.array([complex(*p.points[0]) for p in rec.items if p.kind == "point" and p.step == "trajectory of E"])
    regular = [p for p in plans.positions if p.index is not None]
    E = st.solve(np.array([p.phi for p in regular])).point("E")[0]
    assert len(dots) == len(regular) == 12
    assert np.abs((dots - dots[0]) - (E - E[0]) / plans.mu_l).max() < 0.01
    from test_position_numbers import _gap
    leaders = [(complex(*q.points[0]), complex(*q.points[-1])) for q in rec.items
               if q.kind == "segment" and q.role == "label"]

    def read_at(q) -> complex:
        """Where a number is read: its leader's far end where it has one (stop 51: a number on a
        leader is its point's as much as one beside it), else its anchor."""
        box = q.ink()
        for a, b in leaders:
            if min(_gap(box, a), _gap(box, b)) < 1.2:
                return a if _gap(box, a) > _gap(box, b) else b
        return complex(*q.points[0])
    numbers = [(p.text, read_at(p)) for p in rec.items if p.kind == "text" and p.text.isdigit()]
    for k, q in enumerate(regular):
        near = [z for t, z in numbers if t == str(q.index) and abs(z - dots[k]) < 8.0
                and abs(z - dots[k]) <= np.abs(z - np.delete(dots, k)).min()]
        assert near, f"position {q.index}: no number by E"
