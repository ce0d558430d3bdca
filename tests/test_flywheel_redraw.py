"""The flywheel construction redrawn on more divisions where the first drawing is past the lab's 5 %
(graphic.flywheel.redrawn): the review's offset press (M*_c jumps from 202 to 2221 N·m inside one of
its 12 intervals: +7.09 %), and generated crank-sliders with a steep load — the drawing handed in is
within 5 % of the exact flywheel or carries the note; it is redrawn only when the first drawing is
not, on the fewest divisions (a multiple of the scene's) that are. Every error here is computed in
the test from the construction's readings and the exact solver's flywheel and A_c/2π."""
from __future__ import annotations

import json
import math
import re
from types import SimpleNamespace

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings, strategies as st_

from conftest import scene_study
from graphplan.cli.main import main
from graphplan.exact.dynamics import analyse
from graphplan.graphic.flywheel import construct, redrawn
from graphplan.report.dynamics import redrawn_note, tangents_note
from graphplan.util.errors import GraphplanError
from graphplan.util.markup import inline, plain

LIMIT = 5.0     # %, the lab's

# the review's scene (an offset press, e = −30 mm, clockwise, 25 kN on a ramp, 1000 rpm motor line)
from review_scenes import OFFSET_SLIDER as PRESS  # noqa: E402



def errors_of(f, dyn) -> tuple[float, float, float]:
    """The graphical flywheel's and M*_d's errors, % — from the readings (|kl| through J, the ray's
    height on the moment diagram) against the exact flywheel and A_c/2π —, and the I* diagram's
    largest against the exact largest I* (sampled here every 0,05°; NaN for a constant I*)."""
    J = f.mu_T * f.kl / (dyn.omega_mean ** 2 * dyn.delta)
    fl = max(J - dyn.drive.rotor_reduced - dyn.drive.reducer_reduced, 0.0)
    e_fl = 100.0 * (fl - dyn.flywheel) / dyn.flywheel if dyn.flywheel > 0 else math.nan
    md = dyn.cycle.work / (2 * math.pi)
    i_star = dyn.cycle.inertia(np.linspace(0.0, 2 * math.pi, 7201))
    top = float(np.max(i_star))
    drawn = float(np.max(f.curve()[0])) * f.mu_I        # the I* diagram's peak (the energy–mass curve's abscissa)
    e_i = 100.0 * (drawn - top) / top if float(np.ptp(i_star)) > 1e-9 * top else math.nan
    return e_fl, 100.0 * (f.Md * f.mu_M - md) / md, e_i


def within(e: tuple[float, float]) -> bool:
    return all(not math.isfinite(v) or abs(v) <= LIMIT for v in e)


@pytest.fixture(scope="module")
def press():
    return analyse(scene_study(PRESS))


def test_the_press_is_within_the_lab_on_12_divisions_by_equal_area_heights(press):
    """The review's +7.09 % came from the middle ordinate of the interval the load jumps in; with
    that interval's equal-area mean ordinate (graphic.flywheel.mean_ordinates, review 10) the
    first drawing on the scene's 12 divisions is within the lab's 5 %, and is not redrawn."""
    first = construct(press, None, 0.5, L=330.0, size=1.0)
    assert first.divisions == 12 and within(errors_of(first, press)) and first.equal_area
    f = redrawn(press, None, 0.5, L=330.0, size=1.0)
    assert f.divisions == 12 and redrawn_note(f, "uk") is None


def test_given_divisions_are_kept(press):
    f = redrawn(press, 12, 0.5, L=330.0, size=1.0, given="option")
    assert f.divisions == 12 and within(errors_of(f, press)) and f.redrawn.better is None


def test_the_press_sheets_rows_check():
    from conftest import composed
    from graphplan.sheets.form import form
    st = scene_study(PRESS)
    args = SimpleNamespace(positions=None, accel=None, precision=0.5, lang="uk", sheet="dynamics")
    sheet = composed("dynamics", st, form("A1"), args)        # not numbered (the project's count not read)
    texts = {p.name: [i.text for i in p.record.items if i.kind == "text"] for p in sheet.placed}
    notes = " ".join(plain(t) for t in texts["notes"])
    assert "побудовано заново" not in notes
    chords = " ".join(plain(t) for t in texts["positions table"])          # under Table 1: the chords' heights
    # equal-area heights where M*_c curves; where it jumps a point is added at the jump (review 56), so the
    # note names the intervals still so taken
    assert "середня рівних площ" in chords or "Висоти хорд: середня ордината рівних площ" in chords
    assert "відтинають k" in notes                        # the tangents by their slope, not a protractor
    flywheel = [plain(t) for t in texts["flywheel table"]]
    assert "не потрібен (δ_дв = 0,0236 < 0,03)" in flywheel  # with the motor: none needed, its own δ
    table = next(p.record for p in sheet.placed if p.name == "positions table")
    lines: dict[float, list] = {}
    for item in table.items:                   # the body's cells by their baseline, left to right
        if item.kind == "text":
            lines.setdefault(round(item.points[0][1], 1), []).append(item)
    rows = []
    for y in sorted(lines, reverse=True):
        cells = [i.text for i in sorted(lines[y], key=lambda i: i.points[0][0])]
        if len(cells) == 11 and cells[0].isdigit():
            rows.append([float(c.replace(",", ".").replace("−", "-").rstrip("*")) for c in cells])
    assert [int(r[0]) for r in rows] == list(range(12))       # one row per division drawn
    dt_range = max(r[9] for r in rows) - min(r[9] for r in rows)
    for r in rows:                             # №, φ, I*, dI*/dφ, M*_с, M*_д, A_с гр., A_д гр., ΔT гр., ΔT
        a_c, a_d, dt_gr, dt = r[6], r[7], r[8], r[9]
        assert a_d - a_c == pytest.approx(dt_gr, abs=1.5)    # ΔT гр. = A_д гр. − A_с гр. (each to 4 figures)
        assert abs(dt_gr - dt) <= 0.05 * dt_range            # ΔT read within 5 % of its range (middle ordinates: 6.4 %)
        assert r[10] == pytest.approx(100 * (dt_gr - dt) / dt_range, abs=0.051)   # Table 1's δ of ΔT


@pytest.mark.parametrize("lang, want", [("uk", ("осі I*м", "при ψmax", "при ψmin")),
                                         ("en", ("at ψmax", "at ψmin", "of the I*m axis"))])
def test_the_terminal_writes_the_tangents_note_in_plain_text(lang, want):
    """The review's four-bar (ψ 4.4°/4.0°): `dynamics` printed "осі I*_м … при ψ_max"; the terminal
    writes its neighbours' ψmax, I*м (util.markup.inline), the sheet keeps the markup."""
    f = SimpleNamespace(tangent={"s_max": 0.0765, "s_min": 0.0693, "k": 51.8, "l": -13.8}, kl=65.5, precision=0.5)
    note = tangents_note(f, lang)
    assert "ψ_{max}" in note                                 # the sheet's markup …
    text = inline(note)                                      # … the terminal's plain text
    assert not any(c in text for c in "_^{}\\") and all(w in text for w in want)


def test_dynamics_in_english_is_headed_in_english(tmp_path, capsys):
    path = tmp_path / "press.toml"
    path.write_text(PRESS, encoding="utf-8")
    assert main(["dynamics", str(path), "--lang", "en"]) == 0
    out = capsys.readouterr().out
    assert out.splitlines()[0] == "Dynamics of the machine: Offset crank-slider mechanism of a press"
    assert "equal-area mean ordinate" in out and "not needed (δmot = 0.0236 < 0.03)" in out
    # the notes in plain text (the review: "I*_m", "ψ_max" printed raw), the motor in Latin
    notes = [line for line in out.splitlines() if "Chord heights" in line or "With the motor ωm mot = " in line]
    assert len(notes) == 2 and not re.search(r"[_^{}\\]", out)
    assert re.search(r"^Motor: 4AM\d+[A-Z]\d ", out, re.M)
    assert main(["dynamics", str(path), "--json", "--divisions", "12"]) == 0     # given: kept, with the note's data
    doc = json.loads(capsys.readouterr().out)
    rd = doc["flywheel"]["redrawn"]
    assert len(doc["positions"]) == 12 and rd["given"] == "option" and rd["better_divisions"] is None
    assert rd["errors_before"]["flywheel"] == pytest.approx(doc["flywheel"]["error_pct"]) and rd["right"]


TEMPLATE = """
title = "generated"
[params]
r = {r}
l = {l}
e = {e}
[frame.points]
O = [0, 0]
[frame.guides]
x = {{ through = [0, "e"], angle_deg = 0 }}
[crank]
name = "OA"
pivot = "O"
pin = "A"
length = "r"
rpm = {rpm}
direction = "{sense}"
points = {{ S1 = 0.3 }}
mass = 10
inertia = 0.05
[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = "l"
points = {{ S2 = 0.3 }}
mass = 15
inertia = 0.2
[[link]]
name = "B"
number = 3
joints = ["B"]
slides_on = "x"
mass = {m3}
[branch]
B = 1
[positions]
count = {count}
start = "outer"
working_stroke = "{stroke}"
[loads]
g = 9.81
[[force]]
point = "B"
magnitude = {P}
stroke = "working"
direction = "oppose"
{profile}
[dynamics]
delta = {delta}
efficiency = 0.9
synchronous_rpm = 1000
"""


@st_.composite
def presses(draw):
    """Crank-sliders with a load over part of the working stroke that rises steeply (over 0.5–8 % of
    the stroke: a moment that jumps inside an interval of the scene's divisions) or gently (30–45 %),
    or a constant load over the whole stroke of a centric one (its jumps at the dead centres, which
    are divisions: right at once)."""
    r = draw(st_.sampled_from([0.05, 0.07, 0.09, 0.12]))
    stroke = 2 * r
    kind = draw(st_.sampled_from(["steep", "gentle", "whole"]))
    a = draw(st_.floats(0.05, 0.5 if kind == "steep" else 0.2)) * stroke
    rise = draw(st_.floats(0.005, 0.08) if kind == "steep" else st_.floats(0.3, 0.45)) * stroke
    s3 = min(a + rise + draw(st_.floats(0.1, 0.3)) * stroke, 0.9 * stroke)
    profile = ("" if kind == "whole" else
               f"profile = [[0, 0], [{a:.5f}, 0], [{a + rise:.5f}, 1], [{s3:.5f}, 1], [{s3 + 0.01 * stroke:.5f}, 0]]")
    return TEMPLATE.format(r=r, l=round(r * draw(st_.floats(3.0, 5.0)), 4),
                           e=0.0 if kind == "whole" else round(draw(st_.floats(-0.4, 0.4)) * r, 4),
                           rpm=draw(st_.sampled_from([40, 60, 90])), sense=draw(st_.sampled_from(["cw", "ccw"])),
                           m3=draw(st_.sampled_from([20, 60])), count=draw(st_.sampled_from([8, 12])),
                           stroke=draw(st_.sampled_from(["to_min", "to_max"])),
                           P=draw(st_.sampled_from([5000, 25000])), profile=profile,
                           delta=draw(st_.sampled_from([0.02, 0.03, 0.05])))


def check_redrawing(text: str) -> None:
    """The drawing handed in: the first where it is within the lab; else the fewest multiple of the
    scene's divisions within it (flywheel and M*_d) — or, where none up to 360 has both, the fewest
    whose flywheel (the answer) is; else the first; and the note says which."""
    try:
        dyn = analyse(scene_study(text))
    except GraphplanError:                 # a motor that cannot carry this cycle: not this test's matter
        return
    first = construct(dyn, None, 0.5, L=330.0, size=1.0)
    f = redrawn(dyn, None, 0.5, L=330.0, size=1.0)
    note = redrawn_note(f, "uk")
    n0 = first.divisions
    if within(errors_of(first, dyn)):      # right at once: not redrawn, nothing said
        assert f.divisions == n0 and note is None
        return
    assert note is not None
    errs = {n: errors_of(construct(dyn, n, 0.5, L=330.0, size=1.0), dyn) for n in range(2 * n0, 361, n0)}
    both = [n for n, e in errs.items() if within(e)]
    answer = [n for n, e in errs.items() if within(e[:1])]
    if both:
        assert f.divisions == both[0] and within(errors_of(f, dyn))
        assert f"на {f.divisions} поділках замість {n0}" in plain(note)
    elif answer and not within(errors_of(first, dyn)[:1]):
        assert f.divisions == answer[0] and within(errors_of(f, dyn)[:1])
        assert f"на {f.divisions} поділках замість {n0}" in plain(note)
        assert "закоротка" in note or within(errors_of(f, dyn)[1:2])
    else:                                  # nothing up to 360 helps: the first stays, and says so
        assert f.divisions == n0 and "залишено" in note


@settings(max_examples=6, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(presses())
def test_generated_presses_are_within_the_lab_or_say_so(text):
    check_redrawing(text)


@pytest.mark.slow
@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(presses())
def test_generated_presses_are_within_the_lab_or_say_so_many(text):
    check_redrawing(text)
