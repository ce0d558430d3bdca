"""Review 45 #3: the pump six-bar's hodographs (PUMP45: a crank-slider whose coupler point drives a
rocker O2D; P_B on the working stroke, M5 = 25 N·m against the rocker's turning on both strokes).
M5 reverses with ω5's sign at the rocker's extremes, so the reactions jump there as they do where
P_B switches on or off: R24's and R05's hodographs drew those jumps as long solid segments, as if
the reaction swept across, and no caption named M5. The truth here is the loads' own samples and
the exact reactions at them, not the drawing's cuts."""
from __future__ import annotations

import numpy as np
import pytest

from conftest import scene_study
from review_scenes import PUMP45


@pytest.fixture(scope="module")
def pump():
    from graphplan.drawing import charts
    return charts.turn(scene_study(PUMP45))


def _samples(pump, name: str) -> tuple[list[int], list[int]]:
    """(switched on/off, reversed): the samples k where the external load ``name`` acts on one
    side of k − 1, k only, or acts on both with opposite signs — read off its own samples."""
    ld = next(x for x in pump.ks.loads if x.kind == "external" and x.name == name)
    n = len(pump.turn_deg)
    v = np.broadcast_to(ld.force, (n,)) + np.broadcast_to(ld.couple, (n,))     # P_B along x; M5 a couple
    sign = np.sign(np.where(np.abs(v.imag) > np.abs(v.real), v.imag, v.real))
    before = np.roll(sign, 1)
    return (np.flatnonzero((sign == 0) != (before == 0)).tolist(),
            np.flatnonzero((sign != 0) & (before != 0) & (sign != before)).tolist())


def _jumps(f: np.ndarray, ks: list[int]) -> list[int]:
    """Those of the samples where the exact reaction jumps: a step ten times its typical one."""
    step = np.abs(f - np.roll(f, 1))
    return [k for k in ks if step[k] > 10.0 * float(np.median(step))]


def test_the_loads_own_samples_are_where_the_reactions_jump(pump):
    """M5 reverses twice a turn (the rocker's two extremes), P_B switches twice; R05 and R24 jump
    at M5's reversals, R12 and R01 at both loads' changes — the exact reactions' own steps."""
    p_on, p_rev = _samples(pump, "P_B")
    m_on, m_rev = _samples(pump, "M_5")
    assert len(p_on) == 2 and not p_rev and not m_on and len(m_rev) == 2, (p_on, p_rev, m_on, m_rev)
    r = pump.ks.reactions
    for key in ("R05", "R24"):
        assert _jumps(r[key].force, m_rev) == m_rev, key
    for key in ("R12", "R01"):
        assert _jumps(r[key].force, m_rev) == m_rev and _jumps(r[key].force, p_on) == p_on, key


@pytest.mark.parametrize("key, loads", [("R05", ["M_{5}"]), ("R24", ["M_{5}"]), ("R12", ["P_{B}", "M_{5}"]),
                                        ("R01", ["P_{B}", "M_{5}"])])
def test_each_jump_is_dashed_and_captioned_by_its_load(pump, key, loads):
    """Each hodograph at every jump of its reaction (the loads' samples where the exact reaction
    jumps): no solid line from R[k − 1] to R[k], a dashed one there; its caption names the loads
    that jump it, both in Ukrainian and in English."""
    from graphplan.drawing import charts
    f = pump.ks.reactions[key].force
    p_on, _ = _samples(pump, "P_B")
    _, m_rev = _samples(pump, "M_5")
    jumps = _jumps(f, p_on + m_rev)
    for lang, word in (("uk", "стрибок від "), ("en", "the jump due to ")):
        rec = charts.hodograph_record(pump, key, lang=lang)
        mu = rec.scales["mu_R"]
        solid = [q.points for q in rec.items if q.kind == "polyline" and q.role == "curve"]
        dashed = [q.points for q in rec.items if q.role == "projection" and q.step.endswith("the jump")]
        for k in jumps:
            a, b = f[k - 1] / mu, f[k] / mu
            near = lambda p, z: abs(complex(*p) - z) < 1e-6      # noqa: E731
            assert not any(near(p, a) and near(q, b) for pts in solid for p, q in zip(pts, pts[1:])), (key, k)
            assert any(near(pts[0], a) and near(pts[-1], b) for pts in dashed), (key, k, lang)
        # no solid step of the curve longer than a third of the smallest jump (the sweep across)
        longest = max(abs(complex(*q) - complex(*p)) for pts in solid for p, q in zip(pts, pts[1:]))
        assert longest < min(abs(f[k] - f[k - 1]) / mu for k in jumps) / 3.0, (key, longest)
        caption = next(q.text for q in rec.items if q.kind == "text" and word in q.text)
        assert caption.split(word)[1].split(", ") == loads, (key, lang, caption)
