"""Review 59 (kin59): the V-twin LINK58's position plan marked piston B's extreme positions (B′, B″)
and its stroke H, while piston C — as much an output of the compressor, named in the notes — had no
C′, C″ and no stroke. Each slider on a frame guide now gets its extreme positions and its stroke, the
two strokes lettered apart (H_B, H_C). Checked against the closed form of an axial crank-slider: the
piston stops where the crank lies along its guide (θ = γ, γ + 180°), at l ± r from the crank's pivot,
its stroke 2r."""
from __future__ import annotations

import cmath
import functools
import math

import pytest

from conftest import scene_study
from graphplan.drawing.plans import other_slides, position_record, slide_ends
from graphplan.graphic.plans import build_plans, where
from review_scenes import LINK58

R, L = 0.05, 0.2          # LINK58: the crank O1A, both rods AB and AC
GUIDES = {"B": 60.0, "C": 120.0}


@functools.lru_cache(maxsize=None)
def _drawn(scene: str):
    st = scene_study(scene)
    plans = build_plans(st)
    return st, plans, position_record(plans)


def _texts(rec) -> list:
    return [q for q in rec.items if q.kind == "text"]


def test_both_pistons_stop_where_the_crank_lies_along_their_guides():
    st, plans, _ = _drawn(LINK58)
    assert other_slides(plans) == ["C"]
    for name, gamma in GUIDES.items():
        ends = slide_ends(plans, name)
        assert len(ends) == 2
        got = sorted(lay.phi % 180.0 for lay in ends)
        assert got == pytest.approx([gamma % 180.0] * 2, abs=1e-6)
        assert {round(lay.phi % 360.0, 6) for lay in ends} == {gamma % 360.0, (gamma + 180.0) % 360.0}


def _gap(box, z: complex) -> float:
    return abs(complex(max(box[0] - z.real, 0.0, z.real - box[2]), max(box[1] - z.imag, 0.0, z.imag - box[3])))


@pytest.mark.parametrize("name", ["B", "C"])
def test_each_pistons_extremes_are_marked_and_lettered_at_its_dead_centres(name):
    """A joint's circle at l + r and at l − r from O1 along each guide, B′, B″ and C′, C″ by them (the
    first the crank reaches from position 0 primed once), each nearer its own dead centre than the other."""
    st, plans, rec = _drawn(LINK58)
    sc = plans.scheme
    O = where(sc, plans.positions[0].layout, sc.body_of("O1"), "O1")
    u = cmath.exp(1j * math.radians(GUIDES[name]))
    dead = {s: O + (L + s * R) / plans.mu_l * u for s in (1, -1)}
    marked = [complex(*q.points[0]) for q in rec.items if q.kind == "point" and q.step == "extreme position"
              and q.role == "joint"]
    assert all(min(abs(z - m) for m in marked) < 1e-6 for z in dead.values())
    turn = {s: min(float(st.from_position0(lay.phi)) for lay in slide_ends(plans, name)
                   if abs(where(sc, lay, sc.body_of(name), name) - z) < 1e-6) for s, z in dead.items()}
    first = min(turn, key=turn.get)
    for mark, s in (("′", first), ("″", -first)):
        box = next(q for q in _texts(rec) if q.text == f"{name}{mark}").ink()
        assert _gap(box, dead[s]) < 12.0 and _gap(box, dead[s]) < _gap(box, dead[-s]), (name, mark)


def test_the_two_strokes_are_lettered_apart_with_their_closed_form():
    st, plans, rec = _drawn(LINK58)
    words = [q.text for q in _texts(rec)]
    stroke = f"{2 * R * 1000:.0f} мм"
    assert f"H_{{B}} = {stroke}" in words and f"H_{{C}} = {stroke}" in words
    assert not any(w.startswith("H = ") for w in words)
    hb, hc = (next(q for q in _texts(rec) if q.text.startswith(f"H_{{{n}}}")) for n in "BC")
    assert abs(complex(*hb.points[0]) - complex(*hc.points[0])) > 50.0      # each by its own guide


def test_one_slider_keeps_its_plain_h():
    """A crank-slider has one stroke: lettered H, no second slider's primes."""
    from pathlib import Path
    text = (Path(__file__).parent.parent / "examples" / "crank_slider.toml").read_text(encoding="utf-8")
    st, plans, rec = _drawn(text)
    assert other_slides(plans) == []
    words = [q.text for q in _texts(rec)]
    assert any(w.startswith("H = ") for w in words) and not any(w.startswith("H_{") for w in words)



def test_a_number_that_stood_on_a_long_leader_is_read_with_its_dwell():
    """LINK57 at the A1's 1:2 (stop 57): the rocker's D dwells by D′ — positions 0, 1, 2, 11 within
    1.2 mm — and D₃, 2.1 mm on (less than a number's height), found no free spot among the rocker's
    lines nearer than 30 mm. It is numbered with the dwell's spot now; every number of D stands
    within ``LONG_LEADER`` of a point it names."""
    from graphplan.drawing.plans import LONG_LEADER
    from review_scenes import LINK57
    st = scene_study(LINK57)
    plans = build_plans(st, mu_l=0.002)
    rec = position_record(plans)
    sc = plans.scheme
    path = [where(sc, p.layout, sc.body_of("D"), "D") for p in plans.positions]
    assert abs(path[3] - path[2]) < 2.5 < abs(path[3] - path[4])        # the scene as measured
    numbers = [q for q in _texts(rec) if q.size <= 2.6 and all(t.isdigit() for t in q.text.split(", "))]
    dwell = next(q for q in numbers if set(q.text.split(", ")) >= {"0", "1", "2", "11"} and
                 min(_gap(q.ink(), path[k]) for k in (0, 1, 2, 11)) < LONG_LEADER)
    assert "3" in dwell.text.split(", ")
    for k, z in enumerate(path):       # each position of D read at a number near it
        assert any(str(k) in q.text.split(", ") and _gap(q.ink(), z) < LONG_LEADER for q in numbers), k
