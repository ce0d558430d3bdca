"""Stop 53 (cam53b): Table 1 prints each column to one count of decimals, its zeros too — CAM52's dwell
rows read «0» in columns of «12,22» (a bare zero reads as another precision). Checked against the
exact law: a dwell's s and ds/dφ are zero by the law itself, and the zero cell carries the decimals of
the column's other cells."""
from __future__ import annotations

import re
import tomllib

import pytest

from graphplan.exact.cam import solve
from graphplan.graphic.cam import construct
from graphplan.model.cam import build
from graphplan.report.cam import cam_json, table_columns
from review_scenes import CAM52

NUMBER = re.compile(r"^−?\d+(?:,(\d+))?\*?$")


@pytest.fixture(scope="module")
def cam52_doc():
    sol = solve(build(tomllib.loads(CAM52), "<cam52>"))
    g = construct(sol, measure=True, series="rad")
    return cam_json(sol, g, "")


def _places(cell: str) -> int:
    m = NUMBER.match(cell)
    assert m, cell
    return len(m.group(1) or "")


@pytest.mark.parametrize("column", ["s", "s_gr", "v", "v_gr", "R", "R_gr"])
def test_table_zeros_keep_the_columns_decimals(cam52_doc, column):
    cells = table_columns(cam52_doc, "uk")[column]
    plain = [c for c in cells if "→" not in c and c != "—"]
    assert len({_places(c) for c in plain}) == 1, plain
    # the law's zeros: s at the near dwell (0°, 290°…360°), ds/dφ on the far dwell (150°…190°)
    where = {"s": lambda phi: phi < 1e-9 or phi > 290.0 - 1e-9, "v": lambda phi: 150.0 - 1e-9 < phi < 190.0 + 1e-9}
    if column in where:
        zero = [c for c, p in zip(cells, cam52_doc["positions"]) if where[column](p["phi_deg"])]
        assert zero and all(c.replace("−", "").strip("0,") == "" and "," in c for c in zero), zero
