"""The teacher's review of the six-bar and the offset press (corrections 4, 5, 8, 10, 11, 17, 18),
each checked against a truth computed here: a tangential component from the moment of the exact
reaction, the crank's turn from position 0 by the scene's geometry, the documented minimum of a
velocity plan, the drawn lines against the links' lines."""
from __future__ import annotations

import math
import re

import pytest

from conftest import scene_study
from review_scenes import OFFSET_SLIDER, SIXBAR


def _cross(a: complex, b: complex) -> float:
    return a.real * b.imag - a.imag * b.real


@pytest.fixture(scope="module")
def sixbar_forces():
    """The six-bar's force sheet plan (A1, the ruler's 0.5 mm), its groups' force plans and tables."""
    from graphplan.sheets import forces as sf
    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.form import form
    st = scene_study(SIXBAR)
    p, _, dr = sf.plan(st, form("A1"), SheetOptions(precision=0.5, sheet="forces"))
    return {"st": st, "fp": dr.groups_fp(p.mu), "dr": dr, "mu": p.mu,
            "tables": dict(sf._tables(dr, p.mu, "uk", p.tables))}


def _row(rec, first: str) -> list[str]:
    """The cells of a table's row whose first cell reads ``first``, left to right."""
    head = next(p for p in rec.items if p.kind == "text" and p.text == first)
    y = head.points[0][1]
    cells = [p for p in rec.items if p.kind == "text" and abs(p.points[0][1] - y) < 0.05 and p is not head]
    return [p.text for p in sorted(cells, key=lambda p: p.points[0][0])]


def _value(text: str) -> float:
    return float(text.replace("−", "-").replace(",", "."))


def test_a_tangential_component_keeps_its_sign(sixbar_forces):
    """Correction 4: each group's table prints R^τ as its moment equation solves it, signed. The
    truth: the exact reaction R at its pair X has the moment (X − P) × R about the equation's point
    P; R^τ = that moment over the signed arm (its sign from the equation), |arm| = |X − P| — for
    R^τ03 of the six-bar −348 N, the minus that says «reverse the assumed direction»."""
    from graphplan.util.words import force_symbol, word
    fp = sixbar_forces["fp"]
    seen = 0
    for gp in fp.groups:
        rec = sixbar_forces["tables"][f"table {gp.label}"]
        heads = _row(rec, word("force", "uk"))
        values = _row(rec, word("force value", "uk"))
        assert len(heads) == len(values), gp.label
        for eq in gp.equations:
            if eq.unknown == "M_b":
                continue
            r = fp.ks.reactions[eq.unknown.replace("τ", "")]
            x = complex(r.at[0])
            p = next(complex(q.at[0]) for q in fp.ks.reactions.values()
                     if q.point == eq.about and q.group == gp.label)
            truth = _cross(x - p, complex(r.force[0])) / (math.copysign(1.0, eq.arm_mm) * abs(x - p))
            printed = _value(values[heads.index(force_symbol(eq.unknown, "uk"))])
            assert math.copysign(1.0, printed) == math.copysign(1.0, truth), (eq.unknown, printed, truth)
            assert printed == pytest.approx(truth, rel=0.03), (eq.unknown, printed, truth)
            seen += 1
    assert seen == 3
    gp = next(g for g in fp.groups if g.label.startswith("II(2-3)"))
    rec = sixbar_forces["tables"][f"table {gp.label}"]
    r03 = _row(rec, word("force value", "uk"))[_row(rec, word("force", "uk")).index(force_symbol("R03τ", "uk"))]
    assert r03.startswith("−") and _value(r03) == pytest.approx(-348.0, abs=1.0)


def test_a_negative_table_number_is_written_with_a_true_minus():
    """Every negative number in a ruled table is written with the minus sign (U+2212), as computed."""
    from graphplan.drawing.tables import table
    rec = table([["a", "b"], ["-348", "12,5"], ["-0,09*", "x-1"]], [10.0, 10.0])
    texts = {p.text for p in rec.items if p.kind == "text"}
    assert {"−348", "12,5", "−0,09*", "x-1"} <= texts
