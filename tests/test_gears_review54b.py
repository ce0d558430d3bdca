"""Stop 54's blind review, scene 4 (helper gears54b): the pair 11/53 with "auto" shifts and a type-A
train for u1H = 5.5, K = 4 (GEARS11_53_54) — Table 3's deviation from the wanted ratio from Willis'
exact ratio, the English wording of the notes, and the A1 sheet's λ diagrams as large as their rule
allows (measured off the composed sheet, N1N2 from the closed form)."""
from __future__ import annotations

import math
import tomllib

import pytest

from review_scenes import GEARS11_53_54


@pytest.fixture(scope="module")
def scene():
    from graphplan.exact.gears import solve
    from graphplan.model.gears import build
    g = build(tomllib.loads(GEARS11_53_54), "GEARS11_53_54")
    return g, solve(g)


def _texts(rec) -> list[str]:
    return [p.text for p in rec.items if p.kind == "text"]


def test_the_wanted_ratios_delta_is_willis_against_the_task(scene):
    """Review 54, item 22: «u1H wanted … −0,47» was worked out from the printed 5,474; Willis' 1 + 85/19
    against 5,5 is −0,4785 % — printed −0,48 (uk) / −0.48 (en)."""
    from graphplan.report.gears import gears_json
    from graphplan.sheets.gears import train_table
    _, sol = scene
    assert tuple(sol.train.z) == (19, 33, 85)
    d = 100.0 * ((1 + 85 / 19) - 5.5) / 5.5
    doc = gears_json(sol, None, None, "")
    for lang, want in (("uk", f"{d:.2f}".replace(".", ",")), ("en", f"{d:.2f}")):
        t = _texts(train_table(doc, lang))
        i = next(k for k, x in enumerate(t) if x.startswith("u_{1H} ") and x != "u_{1H}")
        assert t[i + 1] in ("5,5", "5.5") and t[i + 2] == want.replace("-", "−"), t[i:i + 3]


def test_the_notes_say_the_smallest_maximum_sliding_and_rejected(scene):
    """Review 54, item 24: «least greatest specific sliding» and «… lost: D/m = 95 against 85». Stop 55:
    the set named is the nearest of all weighed, u1H = 5,5 exactly: 1 + z3/z1 = 5,5 → z3 = 4,5·z1, z1 even;
    z1 = 20 (z2 = 35, (20 + 90)/4 not whole) and 22 (z2 = 38,5) fail, 24, 42, 108 passes ((24 + 108)/4 = 33,
    66·sin 45° = 46,67 > 44): D/m = 108 against 85."""
    from graphplan.graphic.gears import construct_mesh, construct_train
    from graphplan.report.gears import gears_json
    from graphplan.sheets.gears import notes
    _, sol = scene
    mesh = construct_mesh(sol.pair, 0.5, "en", module_mm=20.0)
    assert (24 + 108) % 4 == 0 and 66 * math.sin(math.pi / 4) > 42 + 2 and 1 + 108 / 24 == 5.5
    for lang, rule, nearer in (("en", "the smallest maximum specific sliding",
                                "z = 24, 42, 108 gives u_{1H} = 5.5 (exactly) but D/m = 108 against 85"),
                               ("uk", "найменше з найбільших питомих ковзань",
                                "z = 24, 42, 108 дає u_{1H} = 5,5 (точно), але D/m = 108 проти 85")):
        vel = construct_train(sol.train, 0.5, lang)
        said = " ".join(notes(gears_json(sol, mesh, vel, ""), lang, mesh, vel))
        assert rule in said and nearer in said and "least greatest" not in said and " lost" not in said


def test_the_a1_lambda_diagrams_take_the_room_under_the_meshing(scene):
    """Review 54, item 23: the A1 sheet left 320 × 130 mm blank under λ drawn 40 mm a unit, the row's
    height capped at the meshing's. The unit is now the largest of 20/25/40/50 mm whose four units stay
    within 0.75 of N1N2 drawn — N1N2 = aw·sin αw at the meshing's 5:1 (about 1,5 s)."""
    from graphplan.sheets.form import form
    from graphplan.sheets.gears import on_sheet
    g, sol = scene
    # x = 0.65/0.70 (the reviewer's check): inv αw = 2(x1 + x2)tan α/(z1 + z2) + inv α by bisection
    inv = lambda a: math.tan(a) - a                                       # noqa: E731
    target = 2 * 1.35 * math.tan(math.radians(20)) / 64 + inv(math.radians(20))
    lo, hi = 0.0, 1.5
    for _ in range(200):
        lo, hi = ((lo + hi) / 2, hi) if inv((lo + hi) / 2) < target else (lo, (lo + hi) / 2)
    aw = 128.0 * math.cos(math.radians(20)) / math.cos(lo)                # mm
    mesh, _, pages = on_sheet(g, sol, form("A1"), 0.5, "uk")
    assert mesh.module_mm == pytest.approx(20.0)                          # the meshing at 5:1
    mu = mesh.lam.scales["mu_l"]
    assert mu == pytest.approx(0.0002)                                    # λ's abscissa at 5:1 too
    line = aw * math.sin(lo) * 5.0                                        # N1N2 drawn, mm (≈ 281)
    want = max(u for u in (20.0, 25.0, 40.0, 50.0) if 4 * u <= 0.75 * line)
    assert 1.0 / mesh.lam.scales["mu_lambda"] == pytest.approx(want) == 50.0


@pytest.mark.slow
def test_the_a3_set_keeps_the_notes_by_their_tables_in_three_sheets(scene):
    """Review 54, items 21: the A3 set of 11/53 took four sheets — the pair's notes under the planetary
    pictures, a sheet away from Tables 1 and 2, and a last sheet with Table 3 and its notes alone. With the
    λ diagrams and the tables side by side, the notes under them, it is three: every part of the notes
    on the sheet of the tables it explains, each sheet with a drawing, u1H read within the lab's 5 % of
    Willis' 104/19 (about 10 s)."""
    from graphplan.sheets.form import form
    from graphplan.sheets.gears import on_sheet
    g, sol = scene
    _, vel, pages = on_sheet(g, sol, form("A3"), 0.5, "en")
    names = [{p.name for p in page} for page in pages]
    assert len(pages) == 3
    assert all(n & {"meshing", "sliding", "planetary"} for n in names)
    assert any({"geometry", "quality", "notes"} <= n for n in names)
    assert any({"train", "train notes"} <= n for n in names)
    assert abs(vel.ratio - 104 / 19) / (104 / 19) <= 0.05
