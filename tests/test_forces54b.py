"""Stop 54 (forces54b): a force's letter set by its own arrow (labels.place_owned_line) never across a
line from its anchor — "Φ2" beside its head but beyond the link AC read as the side's name."""
from __future__ import annotations

from graphplan.graphic.record import LabelRequest, Record


def _crosses(a: complex, b: complex, c: complex, d: complex) -> bool:
    """Whether the segments ab and cd cross (strictly)."""
    def side(p, q, r):
        return ((q - p).conjugate() * (r - p)).imag
    return side(a, b, c) * side(a, b, d) < 0 and side(c, d, a) * side(c, d, b) < 0


def test_a_forces_letter_is_not_set_across_a_link_from_its_arrow():
    """An arrow up to (0, 10) under a thick link along y = 11.5: the letter asked above the head has
    free room only beyond the link (3 mm out) or beside the head below it; it stands where the
    straight line from the head to its nearest ink crosses no line of the drawing."""
    from graphplan.drawing.labels import place_owned_line
    rec = Record("group")
    rec.segment((-30.0, 11.5), (30.0, 11.5), role="link", width=0.7)
    rec.vector((0.0, 0.0), (0.0, 10.0), role="force", width=0.5)
    place_owned_line(rec, [LabelRequest(10j, "Φ_2", 1j, 3.5)], (0j, 10j), [])
    text = next(q for q in rec.items if q.kind == "text")
    x0, y0, x1, y1 = text.ink()
    near = complex(min(max(0.0, x0), x1), min(max(10.0, y0), y1))
    assert not _crosses(10j, near, -30 + 11.5j, 30 + 11.5j)
    assert y1 < 11.5 - 0.3


def test_a_scene_whose_output_never_moves_is_refused_in_one_line(capsys, tmp_path):
    """OWN_KNEE_PRESS54 with the other branch of C: BC = O2B = 0.30 m and O2 on the ram's guide, so
    the circle about B through O2 meets the guide at O2 itself — the ram sits on the fixed pivot for
    the whole turn. Refused with exit 2 in one line, in the language asked for, naming the output
    and [branch] (not a sheet whose path axis ran out of memory)."""
    from graphplan.cli.main import main
    from tests.review_scenes import OWN_KNEE_PRESS54
    assert "O2 = [0.40, 0.30]" in OWN_KNEE_PRESS54 and "through = [0.40, -0.30], angle_deg = 90" in OWN_KNEE_PRESS54
    path = tmp_path / "still.toml"
    path.write_text(OWN_KNEE_PRESS54.replace("\nC = -1\n", "\nC = 1\n"), encoding="utf-8")
    for lang, words in (("en", "the output C does not move"), ("uk", "вихідна ланка C не рухається")):
        code = main(["analyze", str(path), "--lang", lang])
        out, err = capsys.readouterr()
        assert code == 2
        assert len(err.strip().splitlines()) == 1 and words in err and "[branch]" in err, err


def test_a_sets_drawings_stand_on_the_sheets_the_plan_put_them_on():
    """A set's build keeps each drawing on the sheet its plan chose (``Plan.where``): a hodograph the
    plan set on sheet 2 with the tables, which the first sheet would still hold beside the scheme,
    stands on sheet 2 — LINK53's A2 hodographs were packed under sheet 2's charts while the plan put
    them on sheet 3, which held the tables alone spread across its width."""
    from types import SimpleNamespace

    from graphplan.drawing.layout import Leaf
    from graphplan.sheets.forces import _as_planned, _packed_as_planned, _where
    from graphplan.sheets.forceset import pack, units_of
    from graphplan.sheets.compose import later_keep
    from graphplan.sheets.form import form
    from graphplan.sheets.forces import field_of, keep_out
    f = form("A2")
    leaves = {fam: [] for fam in ("scheme", "groups", "forces", "acceleration", "lever", "charts", "hodographs")}
    leaves["scheme"] = [Leaf("mechanism", 150.0, 120.0)]
    leaves["hodographs"] = [Leaf("hodograph R12", 60.0, 60.0), Leaf("hodograph R01", 60.0, 60.0)]
    tables = [Leaf("results", 120.0, 60.0)]
    notes = Leaf("notes", 185.0, 30.0)
    p = SimpleNamespace(where=(("scheme 0",), ("hodographs 0", "hodographs 1", "results", "notes")),
                        plan_first=True, gap=10.0, sheets=2)
    region = field_of(f)
    free = pack(units_of(leaves, region[2] - region[0]), tables, notes, region, keep_out(f), later_keep(f), 10.0)
    assert len(free) == 1 and not _as_planned(free, p, leaves)       # one sheet holds all: not as planned
    pages = _packed_as_planned(p, leaves, tables, notes, f)
    assert pages is not None and _as_planned(pages, p, leaves)
    assert [sorted(n for n in page) for page in _where(pages)] == [
        ["mechanism"], sorted(["hodograph R12", "hodograph R01", "results", "notes"])]
