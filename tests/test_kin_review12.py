"""Review 12's six-bar (tests/review_scenes.SIXBAR12: a crank-rocker whose rocker's extension C drives a
block in the slot of an oscillating lever O3E, crank clockwise): the block run past the lever's end
warned of, the rocker's end E lettered and its swing dimensioned, Table 4's data complete, the ε rows
by link number. Truths are closed forms written here (circle ∩ circle, the line O3C)."""
from __future__ import annotations

import math

import numpy as np
import pytest

from conftest import scene_study
from review_scenes import SIXBAR12, SIXBAR12_SHORT
from graphplan.graphic.plans import build_plans


def closed_form(phi_deg: np.ndarray, o3e: float = 0.46) -> tuple[np.ndarray, np.ndarray]:
    """|O3C| and the lever's angle at crank angles φ: A on the crank, B = circle(A, 0.27) ∩
    circle(O2, 0.20) on the scene's branch (the one the solver takes at φ = 0 — checked below by
    the rocker's length), C = O2 + 1.35·(B − O2), the lever along O3C."""
    O1, O2, O3 = 0j, 0.26 - 0.02j, 0.52 + 0.16j
    A = O1 + 0.07 * np.exp(1j * np.radians(phi_deg))
    d = np.abs(O2 - A)
    a = (0.27 ** 2 - 0.20 ** 2 + d ** 2) / (2 * d)
    h = np.sqrt(0.27 ** 2 - a ** 2)
    base = A + a * (O2 - A) / d
    both = [base + s * 1j * h * (O2 - A) / d for s in (1, -1)]
    return both, O3


def _reach(st, phi_deg: np.ndarray) -> np.ndarray:
    """|O3C| by the closed form on the branch the solver drew (matched at each angle)."""
    both, O3 = closed_form(phi_deg)
    kin = st.solve(phi_deg)
    B = kin.point("B")[0]
    pick = np.where(np.abs(both[0] - B) < np.abs(both[1] - B), both[0], both[1])
    O2 = 0.26 - 0.02j
    assert np.allclose(np.abs(pick - B), 0.0, atol=1e-9)          # the solver's B is the closed form's
    C = O2 + 1.35 * (pick - O2)
    return np.abs(C - O3)


def test_the_block_past_the_short_levers_end_is_warned_of_in_one_line():
    """Mark 9: with O3E = 420 mm the block's centre C runs |O3C| up to 421.5 mm from O3 — past E by
    the closed form's excess, at the crank angles where |O3C| > 420 mm (position 0 among them); one
    line in each language; the 460-mm lever of the fixed scene is not warned of."""
    st = scene_study(SIXBAR12_SHORT)
    phi = np.arange(0.0, 360.0, 0.01)
    reach = _reach(st, phi) * 1000.0
    far = float(reach.max())
    assert 421.0 < far < 422.0                                    # the reviewer's 421.5 mm
    said = [w for w in st.warnings if "past the end" in w]
    assert len(said) == 1 and "\n" not in said[0]
    line = said[0]
    assert f"{far - 420.0:.1f} mm past the end E of the link O3E" in line
    assert f"|O3C| up to {far:.1f} mm" in line
    over = phi[reach > 420.05]
    lo, hi = over.min(), over.max()                               # one run, not across 0°
    got = [float(x.rstrip("°")) for x in line.split("crank angles ")[1].split(" (")[0].split("–")]
    assert abs(got[0] - lo) <= 0.3 and abs(got[1] - hi) <= 0.3
    # the positions named: those whose closed-form |O3C| exceeds the lever
    at = _reach(st, st.positions()) * 1000.0
    named = [i for i in range(12) if at[i] > 420.05]
    assert named and f"position{'s' if len(named) > 1 else ''} {', '.join(map(str, named))})" in line
    uk = [w for w in st.warnings_uk if "виходить за кінець E ланки O3E" in w]
    assert len(uk) == 1 and f"{far - 420.0:.1f}".replace(".", ",") in uk[0]
    assert not any("past the end" in w for w in scene_study(SIXBAR12).warnings)


def test_the_sheets_notes_carry_the_warning_with_subscripts():
    """Mark 9 on the sheet: the kinematics notes say the warning, the link O₃E and |O₃C| in markup."""
    from graphplan.graphic.diagrams import chord_diagrams
    from graphplan.sheets.kintables import notes_lines
    st = scene_study(SIXBAR12_SHORT)
    lines = notes_lines(st, build_plans(st), chord_diagrams(st, precision=0.5), "en", 0.5)
    said = [line for line in lines if "past the end E of the link O_{3}E" in line]
    assert len(said) == 1 and "|O_{3}C| up to 421.5 mm" in said[0]


def test_analyze_prints_the_warning(capsys):
    """Mark 9: `analyze` says it (the terminal's warnings), in the scene's language."""
    import tempfile
    from pathlib import Path

    from graphplan.cli.main import main
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "short.toml"
        path.write_text(SIXBAR12_SHORT, encoding="utf-8")
        assert main(["analyze", str(path), "--lang", "en"]) == 0
    out = capsys.readouterr().out
    assert "Warnings:" in out and "the block C runs 1.5 mm past the end E of the link O3E" in out


def test_the_rocker_is_lettered_at_its_end_and_its_swing_is_the_closed_forms():
    """Mark 8: the output lever's extremes are lettered at its moving end E (not at the pivot O3),
    and ψ_max — dimensioned on the plan and said in the notes — is the closed form's swing of the
    line O3C (16.47° in the reviewer's check)."""
    from graphplan.drawing.plans import output_point, swing
    from graphplan.sheets.kintables import notes_lines
    from graphplan.graphic.diagrams import chord_diagrams
    st = scene_study(SIXBAR12)
    plans = build_plans(st)
    assert output_point(plans) == "E"
    phi = np.arange(0.0, 360.0, 0.005)
    both, O3 = closed_form(phi)
    kin = st.solve(phi)
    B = kin.point("B")[0]
    pick = np.where(np.abs(both[0] - B) < np.abs(both[1] - B), both[0], both[1])
    C = 0.26 - 0.02j + 1.35 * (pick - (0.26 - 0.02j))
    ang = np.unwrap(np.angle(C - O3))
    psi = math.degrees(float(ang.max() - ang.min()))
    assert abs(psi - 16.473) < 0.01
    assert abs(swing(plans) - psi) < 0.01
    lines = notes_lines(st, plans, chord_diagrams(st, precision=0.5), "uk", 0.5)
    assert any(f"ψ_max = {psi:.2f}°".replace(".", ",") in line for line in lines)


def test_table_4_gives_the_lever_the_frame_and_the_centres_of_mass():
    """Mark 10: O3E, O2S3 (0.6·O2B), the frame pivots' x, y from O1, and S2, S5 said at their
    links' middles; the notes name the link O₃E with its subscript (markup), never plain O3E."""
    from graphplan.sheets.kintables import dimensions_table, link_lengths, notes_lines
    from graphplan.graphic.diagrams import chord_diagrams
    st = scene_study(SIXBAR12)
    sizes = dict(link_lengths(st))
    assert sizes["O_{3}E"] == pytest.approx(0.46)
    assert sizes["O_{2}S_{3}"] == pytest.approx(0.6 * 0.20)
    assert (sizes["x_{O2}"], sizes["y_{O2}"], sizes["x_{O3}"], sizes["y_{O3}"]) == pytest.approx((0.26, -0.02, 0.52, 0.16))
    plans = build_plans(st)
    texts = [q.text for q in dimensions_table(st, plans.mu_l, "uk").items if q.kind == "text"]
    assert "−0,020" in texts or "-0,020" in texts
    assert any("S_2" in t and "S_5" in t and "посередині" in t for t in texts)
    lines = notes_lines(st, plans, chord_diagrams(st, precision=0.5), "uk", 0.5)
    assert not any("O3E" in line for line in lines)
    assert any("O_{3}E" in line for line in lines)


def test_epsilon_rows_follow_the_link_numbers():
    """Mark 19: Table 3's ε rows (and the forces sheet's Table 1, the same table) read ε2, ε3, ε4,
    ε5 — the block's ε4 after the slotted link's ε5 as found, put in order."""
    from graphplan.report.plans import plans_json
    st = scene_study(SIXBAR12)
    doc = plans_json(build_plans(st, accel=[8]))
    seen = 0
    for pos in doc["positions"]:
        for plan in ("velocity", "acceleration"):
            numbers = [e["link_number"] for k, e in pos.get(plan, {}).items() if "link_number" in e]
            assert numbers == sorted(numbers)
            seen += plan == "acceleration" and numbers == [2, 3, 4, 5]
    assert seen == 1


def test_the_last_wide_table_goes_under_the_columns_in_reading_order():
    """Mark 4's cause: the six-bar's tables T1, T2 | T3, T4, T5 were set 413 mm wide (T5, the
    diagrams' readings, 175 mm, in the second column); under the columns T1, T2 | T3, T4 they are
    328 mm wide and no taller. The boxes placed: inside the block, apart, read down each column,
    then the last under them at the block's right, running on under the first column."""
    from graphplan.drawing.layout import GAP, Leaf
    from graphplan.sheets.kinlayout import place_tables, table_groups, tables_size
    tabs = [Leaf("T1", 232.0, 84.1), Leaf("T2", 90.0, 151.5), Leaf("T3", 90.0, 151.5), Leaf("T4", 77.0, 89.2),
            Leaf("T5", 175.0, 51.2)]
    flat_ = table_groups(tabs, 2)
    under = table_groups(tabs, 2, under=True)
    assert [[t.name for t in g] for g in under] == [["T1", "T2"], ["T3", "T4"], ["T5"]]
    w0, h0 = tables_size(flat_)
    w1, h1 = tables_size(under, True)
    assert w0 == pytest.approx(232 + GAP + 175) and w1 == pytest.approx(232 + GAP + 90)
    assert h1 == pytest.approx(max(84.1 + GAP + 151.5, 151.5 + GAP + 89.2) + GAP + 51.2) and h1 <= h0 + 1e-9
    placed = place_tables(under, 500.0, 400.0, True)
    boxes = {q.name: q.box for q in placed}
    assert list(boxes) == ["T1", "T2", "T3", "T4", "T5"]
    for name, (x0, y0, x1, y1) in boxes.items():
        assert 500.0 - w1 - 1e-9 <= x0 and x1 <= 500.0 + 1e-9 and 400.0 - h1 - 1e-9 <= y0 and y1 <= 400.0 + 1e-9, name
    names = list(boxes)
    for i, a in enumerate(names):
        for b in names[i + 1:]:
            p, q = boxes[a], boxes[b]
            assert p[2] <= q[0] + 1e-9 or q[2] <= p[0] + 1e-9 or p[3] <= q[1] + 1e-9 or q[3] <= p[1] + 1e-9, (a, b)
    # at the block's right, under both columns: it runs on under the first (read after them all)
    assert boxes["T5"][2] == pytest.approx(500.0) and boxes["T5"][0] < boxes["T1"][2] - 1.0
    assert boxes["T5"][3] < min(boxes[n][1] for n in names[:4])


@pytest.mark.slow
def test_the_a1_gives_the_position_plan_its_room():
    """Mark 4: the A1 draws the six-bar's position plan at 1:4 or larger (GOST 2.302's series; the
    A3 set's 1:2.5), no longer 1:5 beside a 413-mm block of tables."""
    from graphplan.sheets.kinematics import sheet_scales
    st = scene_study(SIXBAR12)
    assert sheet_scales(st, "A1")["mu_l"] <= 0.004 + 1e-12
