"""docs/dynamics.md's example tables (slotter, shaper) in step with the program: every number of each
table read here off `graphplan dynamics --json` (the construction the A1 sheet draws) and, for the
"precision 0" row, `--precision 0`. Stop 56: the shaper's table still gave L = 330 mm figures (327.5,
−0.24 %) when the sheet had drawn L = 290 for stops (328.33, +0.01 %)."""
from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
NUM = r"([+−-]?\d+(?:\.\d+)?)"


def _table(name: str) -> list[str]:
    text = (ROOT / "docs" / "dynamics.md").read_text(encoding="utf-8")
    start = text.index(f"**{name}** (seed")
    lines = text[start:].splitlines()
    first = next(i for i, line in enumerate(lines) if line.startswith("| method (12 divisions;"))
    rows = []
    for line in lines[first:]:
        if not line.startswith("|"):
            break
        rows.append(line)
    return rows


def _value(text: str) -> tuple[float, int]:
    """A printed number and its decimals."""
    text = text.replace("−", "-")
    return float(text), len(text.split(".")[1]) if "." in text else 0


def _agrees(printed: str, value: float) -> bool:
    v, d = _value(printed)
    return abs(v - value) <= 0.5 * 10 ** -d + 1e-9


def _json(capsys, example: str, *extra: str) -> dict:
    from graphplan.cli.main import main
    assert main(["dynamics", str(ROOT / "examples" / f"{example}.toml"), "--json", *extra]) == 0
    return json.loads(capsys.readouterr().out)


@pytest.mark.slow                     # four analyses with the sheet's construction search: ~20 s
@pytest.mark.parametrize("name,example", [("Slotter", "slotter"), ("Shaper", "shaper")])
def test_the_docs_example_table_is_the_programs(capsys, name, example):
    doc, zero = _json(capsys, example), _json(capsys, example, "--precision", "0")
    rows = _table(name)
    head = rows[0]
    L, mu_M, H, mu_I = (re.search(rf"{key} = {NUM}", head).group(1)
                        for key in ("L", "μ_M", "H", "μ_I"))
    assert _agrees(L, doc["L_mm"]) and _agrees(mu_M, doc["scales"]["mu_M"])
    assert _agrees(H, doc["H_mm"]) and _agrees(mu_I, doc["scales"]["mu_I"])
    fw = doc["flywheel"]
    split = [re.split(r"(?<!\\)\|", r) for r in rows[2:]]       # a cell's escaped \| is not a border
    cells = {r[1].strip(): [c.strip() for c in r[2:-1]] for r in split}
    (exact_name, exact), = [(k, v) for k, v in cells.items() if k.startswith("exact")]
    assert _agrees(exact[0], fw["exact"])
    assert _agrees(re.search(rf"ω_m = {NUM}", exact_name).group(1), doc["omega_mean"])
    (ruler_name, ruler), = [(k, v) for k, v in cells.items() if k.startswith("Wittenbauer, ruler")]
    assert _agrees(re.search(rf"kl\\\| = {NUM}", ruler_name).group(1), fw["kl_mm"])
    assert _agrees(ruler[0], fw["graphical"]) and _agrees(ruler[1].rstrip(" %"), fw["error_pct"])
    precise = cells["Wittenbauer, precision 0"]
    assert _agrees(precise[0], zero["flywheel"]["graphical"])
    assert _agrees(precise[1].rstrip(" %"), zero["flywheel"]["error_pct"])
    approx = next(v for k, v in cells.items() if k.startswith("approximate"))
    assert _agrees(approx[0], fw["approximate"]) and _agrees(approx[1].rstrip(" %"), fw["approximate_error_pct"])
    mertsalov = cells["Mertsalov"]
    assert _agrees(mertsalov[0], fw["merkalov"]) and _agrees(mertsalov[1].rstrip(" %"), fw["merkalov_error_pct"])
    (motor_name, motor), = [(k, v) for k, v in cells.items() if k.startswith("with the motor")]
    assert _agrees(motor[0], doc["motor"]["flywheel"])
    assert _agrees(re.search(rf"ω_{{m mot}} = {NUM}", motor_name).group(1), doc["motor"]["motion"]["omega_mean"])
