"""Review 58 (kin58): a V-twin's kinematics sheet drew the diagrams of piston B only and said nothing
of piston C. The notes now say whose diagrams are drawn and, where the second piston repeats the
first's stroke at a phase (one crank, equal rods, both guides through the crank's pivot), by how much:
checked here against the closed form of the slider's stroke, s(θ) = r·cos(θ − γ) + √(l² − r²·sin²(θ − γ))."""
import math

import numpy as np
import pytest

from graphplan.sheets.kintables import other_outputs, phase_shift
from tests.conftest import scene_study
from tests.review_scenes import LINK58


def v_twin(left: float, right: float, direction: str = "cw", rod_c: float = 0.2) -> str:
    """LINK58 with its guides at ``left``° and ``right``°, the crank turning ``direction``, rod AC ``rod_c``."""
    text = (LINK58.replace("angle_deg = 60", f"angle_deg = {left}")
            .replace("angle_deg = 120", f"angle_deg = {right}")
            .replace('direction = "cw"', f'direction = "{direction}"'))
    head, tail = text.split('name = "AC"', 1)
    return head + 'name = "AC"' + tail.replace("length = 0.2", f"length = {rod_c}", 1)


def closed_form_shift(left: float, right: float, sense: int, r: float = 0.05, l: float = 0.2) -> float:
    """The turn Δ (deg, in (−180, 180]) with s_C(φ) = s_B(φ + Δ), φ the crank's turn in its sense
    (``sense`` +1 counter-clockwise, −1 clockwise), found on a 1° grid from the closed form."""
    theta = np.radians(np.arange(360.0)) * sense
    s = lambda g: r * np.cos(theta - math.radians(g)) + np.sqrt(l * l - (r * np.sin(theta - math.radians(g))) ** 2)  # noqa: E731
    sb, sc = s(left), s(right)
    k = next(k for k in range(360) if np.allclose(sc, np.roll(sb, -k), atol=1e-12))
    return k - 360.0 if k > 180 else float(k)


@pytest.mark.parametrize("left,right,direction", [(60, 120, "cw"), (60, 120, "ccw"), (45, 135, "cw"), (30, 120, "ccw")])
def test_the_second_piston_repeats_the_first_at_the_vee_angle(left, right, direction):
    st = scene_study(v_twin(left, right, direction))
    expected = closed_form_shift(left, right, 1 if direction == "ccw" else -1)
    assert abs(expected) == pytest.approx(right - left)          # the closed form: the V's angle
    assert phase_shift(st, "B", "C") == pytest.approx(expected, abs=1e-9)


def test_unequal_rods_have_no_phase_and_the_note_says_where_c_is_read():
    st = scene_study(v_twin(60, 120, rod_c=0.25))
    assert phase_shift(st, "B", "C") is None

    class Plans:        # one acceleration plan: Tables 1, 2
        positions = [type("P", (), {"acceleration": object()})()]
    uk, = other_outputs(st, Plans, "uk")
    en, = other_outputs(st, Plans, "en")
    assert "B" in uk and "v_{C}, a_{C}" in uk and "1, 2" in uk and "зсунут" not in uk
    assert "output B" in en and "shifted" not in en


def test_the_lead_v_twin_note_names_c_sixty_degrees_earlier():
    """LINK58's crank turns clockwise, B's guide at 60°, C's at 120°: C reaches each place 60° of the
    crank's turn before B (its top dead centre at position 10, B's at 0)."""
    st = scene_study(LINK58)

    class Plans:
        positions = [type("P", (), {"acceleration": object()})()]
    uk, = other_outputs(st, Plans, "uk")
    en, = other_outputs(st, Plans, "en")
    assert "випередженням на 60°" in uk and "s_{C}(φ)\u00a0=\u00a0s_{B}(φ\u00a0+\u00a060°)" in uk
    assert "60° earlier" in en
    phi = st.positions()
    kin = st.solve(phi)
    tb, tc = kin.slides["B"].t, kin.slides["C"].t
    assert np.allclose(tc, np.roll(tb, -2), atol=1e-12)           # C at position i is B at i + 2


# -- the English apostrophe (YOKE11's English notes: «lab's» read as two words) ----------------------------

@pytest.mark.parametrize("size", [3.5, 4.747])
def test_the_english_apostrophe_reads_as_part_of_its_word(size):
    """«the lab's 5 %», «the crank's», «the link's» rendered and grouped into words as overprint.py and
    tests/inkcheck group ink (the 0.8-mm closing at 4 px/mm): as many words as without the apostrophes,
    wherever the text falls on the pixel grid. Set at the font's advances, the apostrophe after b (its
    ink right of the stem only the bowl, at the x-height) stood 0.75 mm across and 1 mm above it and
    read as a mark of its own inside «lab»'s box at 4.7-mm letters (YOKE11's English kinematics notes)."""
    from test_cam56 import _words
    for dx in (0.0, 0.1, 0.2):
        for dy in (0.0, 0.1, 0.2):
            assert _words("lab's crank's link's", size, dx, dy) == _words("labs cranks links", size, dx, dy), (dx, dy)
    assert _words("b'", size, 0.0, 0.0, closing=False) == 2         # tucked in over the bowl, not touching
    assert _words("b's", size, 0.0, 0.0, closing=False) == 3


def test_the_two_slider_pumps_plunger_against_its_closed_form():
    """kin58's own mechanism (KIN58_TWOSLIDER): D's velocity at the twelve positions from the solver the
    sheet's tables are checked against equals the closed form — B = A + √(l² − y_A²) on the axis, C on the
    rod 0.1 m along and 0.05 m across it, D on x = 0.16 m at C + √(CD² − (0.16 − x_C)²) — differentiated
    numerically; and the note sends the reader to the tables for D (no phase repeats B's stroke)."""
    from tests.review_scenes import KIN58_TWOSLIDER
    st = scene_study(KIN58_TWOSLIDER)
    r, l, cd, w = 0.06, 0.26, 0.16, 240 * 2 * math.pi / 60

    def y_d(th):
        ax, ay = r * math.cos(th), r * math.sin(th)
        bx = ax + math.sqrt(l * l - ay * ay)
        ux, uy = (bx - ax) / l, -ay / l
        cx, cy = ax + 0.1 * ux - 0.05 * uy, ay + 0.1 * uy + 0.05 * ux
        return cy + math.sqrt(cd * cd - (0.16 - cx) ** 2)
    phi = st.positions()
    kin = st.solve(phi)
    h = 1e-6
    expected = [(y_d(math.radians(p) + h) - y_d(math.radians(p) - h)) / (2 * h) * w for p in phi]
    assert np.allclose(kin.slides["D"].v, expected, atol=1e-6)
    assert phase_shift(st, "B", "D") is None

    class Plans:
        positions = [type("P", (), {"acceleration": object()})()]
    uk, = other_outputs(st, Plans, "uk")
    assert "v_{D}, a_{D}" in uk
