"""Why the diagrams' readings at the positions miss the lab's 5 %, measured (issue 32): the notes set
each failing reading beside the same construction with an exact ruler (the chords' own error) and
with the ruler on the s ordinates alone (graphic.diagrams.ruler_on_s) — an error no pole distance
or abscissa changes: after s the construction is linear and its values (mm × μ, μv = μs/(μt·H1),
μa = μv/(μt·H2), μt = T/L) scale out H1, H2 and L. Review 12's six-bar read ε5 +16.25 % at 2, where
the chords' own error is −0.5 %: the old note blamed the chords."""
from __future__ import annotations

import re

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st_

import random_mechanisms as rm
import review_scenes
from conftest import scene_study
from graphplan.exact.positions import exact_motion
from graphplan.graphic.diagrams import chord_diagrams, ruler_on_s
from graphplan.report.diagrams import limit_note


def judged(value, truth, big):
    """The lab's δ, % as Table 5 judges it, written here: of the exact value where it is at least a
    tenth of the cycle's maximum, else of the maximum."""
    value, truth = np.asarray(value, float), np.asarray(truth, float)
    return np.where(np.abs(truth) >= 0.1 * big, 100 * (value - truth) / np.where(truth == 0, 1, truth),
                    100 * (value - truth) / big)


@settings(max_examples=8, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(r=st_.floats(0.03, 0.1), d=st_.floats(0.2, 0.35), l2=st_.floats(0.15, 0.4), l3=st_.floats(0.1, 0.35),
       h1=st_.sampled_from([15.0, 25.0, 50.0]), h2=st_.sampled_from([15.0, 35.0, 50.0]),
       L=st_.sampled_from([150.0, 300.0]), correct=st_.booleans())
def test_the_ruler_on_s_alone_is_the_same_whatever_the_poles_and_L(r, d, l2, l3, h1, h2, L, correct):
    text, ok = rm.rrr(r, d, l2, l3, 6.0, 1)
    assume(ok)
    st = scene_study(text)
    base = ruler_on_s(chord_diagrams(st, precision=0.5, L=240.0, H1=30.0, H2=30.0, height=80.0, correct=correct))
    other = ruler_on_s(chord_diagrams(st, precision=0.5, L=L, H1=h1, H2=h2, height=80.0, correct=correct))
    for key in ("v_at", "a_at"):
        assert np.allclose(other[key], base[key], atol=1e-6), key


def test_the_ruler_on_s_of_a_finer_ruler_tends_to_the_chords_own_error():
    """With the ruler's division shrinking, the s-only readings come to the exact drawing's, and
    the exact drawing's δ is its chords' error against the exact solver (judged here)."""
    st = scene_study(review_scenes.SIXBAR12)
    opts = dict(L=240.0, H1=30.0, H2=30.0, height=80.0, correct=True)
    fine = ruler_on_s(chord_diagrams(st, precision=1e-7, **opts))
    d0 = chord_diagrams(st, precision=0.0, **opts)
    k = d0.at_positions
    _, v, a = exact_motion(st, d0.output, d0.turn[k])
    for key, got, truth, big in (("v_at", d0.exact.v_at, v, d0.maxima["v"]), ("a_at", d0.exact.a_at, a, d0.maxima["a"])):
        own = judged(d0.sign * got[k] * (d0.mu_v if key == "v_at" else d0.mu_a), truth, big)
        assert np.allclose(fine[key], own, atol=1e-3), key
        coarse = ruler_on_s(chord_diagrams(st, precision=0.5, **opts))
        assert np.max(np.abs(coarse[key] - own)) > 1.0, key      # the 0.5-mm ruler on s moves them


NUMBER = r"[+−]\d+\.\d"


def test_the_note_sets_each_failing_reading_beside_its_exact_ruler_and_ruler_on_s_shares():
    """Review 12's six-bar as its A1 sheet draws it (L 120 mm, ψ5 at μ 0.01 rad/mm, H1 34, H2 17 mm,
    the correction): ε5 reads +16.25 % at 2 where the chords' own error is −0.5 % and the ruler on
    ψ5 alone +19.5 %: the ruler, not the chords; at 9 the chords' own −18.3 % (a sharp bend)."""
    st = scene_study(review_scenes.SIXBAR12)
    d = chord_diagrams(st, precision=0.5, L=120.0, H1=34.0, H2=17.0, height=52.0, correct=True, lang="en")
    note = limit_note(d, "en", 5)
    errs, on_s = d.position_errors(), ruler_on_s(d)
    k = d.at_positions
    _, _, a = exact_motion(st, d.output, d.turn[k])
    own = judged(d.sign * d.exact.a_at[k] * d.mu_a, a, d.maxima["a"])
    listed = re.search(r"ε_\{5\} ((?:\d+ \([^)]*\)(?:, )?)+)", note).group(1)
    positions = [int(p) for p in re.findall(r"(\d+) \(", listed)]
    exact_part = re.search(r"with an exact ruler .*?ε_\{5\} ((?:" + NUMBER + r"(?:, )?)+) %", note).group(1)
    s_part = re.search(r"on ψ_\{5\} alone .*?ε_\{5\} ((?:" + NUMBER + r"(?:, )?)+) %", note).group(1)
    row = {d.position[kk]: i for i, kk in enumerate(k)}
    for p, e, s in zip(positions, exact_part.split(", "), s_part.split(", ")):
        i = row[p]
        assert abs(errs["a_at"][i]) > 5.0
        assert float(e.replace("−", "-")) == pytest.approx(own[i], abs=0.051)
        assert float(s.replace("−", "-")) == pytest.approx(on_s["a_at"][i], abs=0.051)
    assert positions[0] == 2 and "a bend sharp for the 30° step" in note
    i2 = row[2]
    assert abs(own[i2]) < 1.0 < 5.0 < abs(on_s["a_at"][i2])      # position 2: the ruler's, not the chords'
    assert "independent of H_{1}, H_{2} and L" in note
    uk = limit_note(chord_diagrams(st, precision=0.5, L=120.0, H1=34.0, H2=17.0, height=52.0, correct=True,
                                   lang="uk"), "uk", 5)
    assert "з точною лінійкою" in uk and "лише з відліком ψ_{5}" in uk and not re.search(r"\d\.\d", uk)   # decimal commas


def test_a_tangents_note_names_the_tangents_own_error():
    """The method of tangents has no chords and no ruler-on-s share (its v is read off tangents)."""
    st = scene_study(review_scenes.SIXBAR12)
    d = chord_diagrams(st, precision=0.5, L=240.0, H1=30.0, H2=30.0, height=80.0, method="tangents", lang="en")
    note = limit_note(d, "en", 5)
    assert d.worst_pct() > 5.0 and note is not None
    assert "the tangents' own error" in note and "chords' own" not in note and "alone" not in note
