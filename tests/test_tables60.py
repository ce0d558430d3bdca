"""A table's header row holds its lettering clear of both rules (stop 60): the cam set's Table 1 at 3.5-mm
letters in 7- or 6.5-mm rows (CLOSER_ROWS) set the header «y_{ds/dφ}, мм» with its subscript's φ tail
0.49 mm from the thick rule's centre under it — a composition defect (labels.collisions) — so the sets
never took those rows and drew the table at 2.5 mm. The header row now grows to the lettering's ink
(capitals to the tail) and RULE_CLEAR on either side; rows that hold it are ruled as before."""
from __future__ import annotations

import pytest

HEAD = ["№", "φ, °", "ψ, °", "y_{ψ}, мм", "ψ гр.", "δ_ψ, %", "dψ/dφ, °/рад", "y_{dψ/dφ}, мм", "dψ/dφ гр.",
        "δ_{dψ/dφ}, %", "ϑ, °", "ϑ гр.", "R, мм", "R гр."]
BODY = [[str(k), "10,0", "0,08", "0,5", "0,10", "−", "1,28", "6,5", "1,27", "−0,78", "22,6", "22,5", "55,1", "55,0"]
        for k in range(4)]


def _rules(rec):
    """The y of each horizontal rule, top down."""
    return sorted({round(p.points[0][1], 9) for p in rec.items if p.kind == "segment"
                   and p.points[0][1] == p.points[1][1]}, reverse=True)


@pytest.mark.parametrize("size,row", [(3.5, 7.0), (3.5, 6.5), (2.5, 6.0), (3.5, 10.0)])
def test_the_header_lettering_keeps_its_clearance_from_both_rules(size, row):
    """Every header cell's ink (measured off the record) at least RULE_CLEAR from the rule over it and the
    rule under it; the body rows row mm apart; no collision by the sheets' own check; the header row only as
    tall as the ink needs where row mm cannot hold it (capitals 3.64 mm over the baseline, the subscript's φ
    1.79 mm under it at 3.5-mm letters: 7.03 mm with 0.8 mm each side), else row mm as before."""
    from graphplan.drawing.labels import collisions
    from graphplan.drawing.tables import RULE_CLEAR, table
    rec = table([HEAD] + BODY, [7.0] * len(HEAD), row_h=row, size=size, clear_header=True)
    ys = _rules(rec)
    assert len(ys) == len(BODY) + 2
    head = [p.ink() for p in rec.items if p.kind == "text" and p.text in HEAD]
    top, low = max(b[3] for b in head), min(b[1] for b in head)
    assert ys[0] - top >= RULE_CLEAR - 1e-9 and low - ys[1] >= RULE_CLEAR - 1e-9
    need = top - low + 2 * RULE_CLEAR
    assert ys[0] - ys[1] == pytest.approx(max(row, need))
    assert all(a - b == pytest.approx(row) for a, b in zip(ys[1:], ys[2:]))
    assert collisions(rec) == []
    if size == 3.5 and row <= 7.0:
        assert ys[0] - ys[1] > row                                       # it had to grow
    # a table that does not ask for it ruled as before: the header row mm tall
    plain = _rules(table([HEAD] + BODY, [7.0] * len(HEAD), row_h=row, size=size))
    assert plain[0] - plain[1] == pytest.approx(row)

