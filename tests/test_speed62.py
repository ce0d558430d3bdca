"""Stop 62's speed of building sheets: the searches made cheaper must find what they found before.

- ``labels.leads(…, lazy=True)`` judges a label's leader candidates ring by ring as ``Leads.first``
  reaches them (``place_beside``: a diagram's point number mostly finds its leader on the nearest
  rings): ``first`` takes the same candidate as from every candidate judged at once, for every
  ``extra``, ``off_lines`` and ``reject`` ``place_beside`` asks with, on random drawings with rivals.
- ``labels._owned_both`` (a leader's label nearer its point than any rival, strict and loose, in one
  pass over the rivals) answers as the per-rival passes did.
- The kinematics diagrams' candidates are measured once per drawing (``kinematics._drawing_key``: the
  s height as the μs it chooses — ``chord_diagrams`` reads ``height`` through μs alone): two heights
  choosing the same μs construct the same drawing to the bit (so the block measured for one is the
  other's), two choosing different μs do not share a key.
"""
from __future__ import annotations

import random

import numpy as np
import pytest

from graphplan.drawing import labels as L
from graphplan.graphic.record import LabelRequest, Primitive, Record


def _scene(seed: int) -> tuple[Record, list[complex]]:
    """A random diagram: a polyline through numbered points (thin), a few thick strokes and labels."""
    rng = random.Random(seed)
    rec = Record()
    pts = [complex(rng.uniform(-30, 30), rng.uniform(-30, 30)) for _ in range(rng.randint(4, 12))]
    for a, b in zip(pts, pts[1:]):
        rec.segment((a.real, a.imag), (b.real, b.imag), width=0.25)
    for _ in range(rng.randint(1, 6)):
        a = complex(rng.uniform(-25, 25), rng.uniform(-25, 25))
        b = a + complex(rng.uniform(-20, 20), rng.uniform(-20, 20))
        rec.segment((a.real, a.imag), (b.real, b.imag), width=rng.choice((0.25, 0.5, 0.7)))
    for _ in range(rng.randint(0, 8)):
        rec.label((rng.uniform(-25, 25), rng.uniform(-25, 25)), rng.choice(("A", "Φ_2", "S_{3}", "12", "7")),
                  size=3.5)
    return rec, pts


@pytest.mark.parametrize("seed", range(6))
def test_lazy_leads_take_the_candidate_every_candidate_judged_at_once_takes(seed):
    """``leads(…, lazy=True).first`` == ``leads(…).first`` (each candidate judged on its own, so ring by
    ring gives the same judgments), for numbers and words, with rivals and without, at each stage
    ``place_beside`` asks: "strict" or no extra, off the lines or not, a ``reject`` or none."""
    rec, pts = _scene(seed)
    ob = L.obstacles(rec.items)
    rng = random.Random(1000 + seed)
    found = 0
    for i, z in enumerate(pts[:3]):
        rivals = tuple(p for p in pts if p != z) if i % 2 == 0 else ()
        text = rng.choice(("3", "11", "B"))
        for steep, across in ((L.STEEP_CLEAR, False), (0.0, True)):
            req = LabelRequest(z, text, toward=complex(rng.uniform(-1, 1), rng.uniform(-1, 1)) or 1j, size=3.5,
                               across=across, rivals=rivals)
            ink = Primitive("text", ((0.0, 0.0),), text=req.text, size=req.size).ink()
            near = ob.near(z, L.FAR[-1] + 20.0)
            eager = L.leads(near, req, ink, steep=steep)
            lazy = L.leads(near, req, ink, steep=steep, lazy=True)
            assert lazy.base is None                 # judged only as asked
            cut = rng.uniform(-30, 30)
            for extra_eager, extra_lazy in ((None, None), (eager.strict, "strict")):
                for off in (True, False):
                    for reject in (None, lambda k, c=cut: float(eager.boxes[k][0]) < c):
                        want = eager.first(req, extra_eager, off_lines=off, reject=reject)
                        assert lazy.first(req, extra_lazy, off_lines=off, reject=reject) == want
                        found += want is not None
            # where every ring was reached the judgments are the eager ones, ring by ring
            for r in range(len(L.FAR)):
                for got, want in zip(lazy.ring(r), eager.ring(r)):
                    assert np.array_equal(got, want)
    assert found          # the drawings leave room for some leaders: the comparison is not vacuous


def _owned_reference(req, boxes, end, strict):
    """``labels._owned_all`` as stop 61 wrote it (each rival, strict and not in passes of their own)."""
    mine = L._gap_all(boxes, req.at)
    ok = np.ones(len(boxes), dtype=bool)
    d = end - req.at
    n2 = np.abs(d) ** 2
    for z in req.rivals:
        ok &= ~(L._gap_all(boxes, z) < (mine + 0.05 if strict else np.minimum(mine, L.RIVAL_BOX)))
        if abs(z - req.at) < L.RIVAL_CLEAR:
            ok &= ~(((z - req.at) * np.conj(d)).real > 0.0)
        else:
            with np.errstate(all="ignore"):
                t = np.where(np.abs(d) < 1e-12, 0.0, np.clip(((z - req.at) * np.conj(d)).real / n2, 0.0, 1.0))
            ok &= ~(np.abs(z - (req.at + t * d)) < L.RIVAL_CLEAR)
    return ok


@pytest.mark.parametrize("seed", range(6))
def test_owned_both_is_each_rival_tested_strict_and_not(seed):
    """``_owned_both`` == the per-rival passes, strict and loose, element for element — with rivals
    within ``RIVAL_CLEAR`` of the point and farther, leaders of zero length among them."""
    rng = random.Random(2000 + seed)
    at = complex(rng.uniform(-5, 5), rng.uniform(-5, 5))
    radii = (0.6, 0.9, 3.0, 8.0, 20.0) if seed % 2 == 0 else (3.0, 8.0, 20.0)    # odd: none within RIVAL_CLEAR
    rivals = tuple(at + complex(rng.uniform(-r, r), rng.uniform(-r, r)) for r in radii)
    req = LabelRequest(at, "5", rivals=rivals)
    ink = Primitive("text", ((0.0, 0.0),), text="5", size=3.5).ink()
    boxes, _ = L._candidates(req, ink, L.FAR, L.FAR_DIRECTIONS)
    _, end = L._led_all(at, boxes)
    end[::7] = at                                    # some leaders of no length
    strict, loose = L._owned_both(req, boxes, end)
    assert np.array_equal(strict, _owned_reference(req, boxes, end, True))
    assert np.array_equal(loose, _owned_reference(req, boxes, end, False))
    assert (~strict).any() and (seed % 2 == 0 or loose.any())     # both answers occur


@pytest.fixture(scope="module")
def crank_slider():
    from conftest import ROOT
    from graphplan.exact.positions import study
    from graphplan.model.scene import load
    return study(load(ROOT / "examples" / "crank_slider.toml"))


def test_heights_of_one_mu_s_draw_the_same_diagrams_and_share_a_key(crank_slider):
    """Two s heights that choose the same μs (``choose_mu_s``, the standard series) construct the same
    drawing, every ordinate equal (so measuring it once for both is exact); a height choosing another
    μs is another key. The heights are found by the series itself, not assumed."""
    from graphplan.graphic.diagrams import chord_diagrams
    from graphplan.sheets import kinematics as K
    st = crank_slider
    base = {"point": None, "divisions": 12, "L": 240.0, "H1": 30.0, "H2": 30.0}
    mus = {}
    for h in np.arange(40.0, 100.0, 2.5):
        d = chord_diagrams(st, precision=0.5, height=float(h), **base)
        mus.setdefault(d.mu_s, []).append(float(h))
    shared = [hs for hs in mus.values() if len(hs) >= 2]
    assert shared and len(mus) >= 2        # the heights span more than one μs, and some share one
    hs = shared[0]
    a = chord_diagrams(st, precision=0.5, height=hs[0], **base)
    b = chord_diagrams(st, precision=0.5, height=hs[-1], **base)
    for x, y in ((a.drawn.s, b.drawn.s), (a.drawn.v, b.drawn.v), (a.drawn.a, b.drawn.a), (a.x, b.x)):
        assert np.array_equal(x, y)
    key = K._drawing_key(st, {**base, "height": hs[0]}, 0.5)
    assert key == K._drawing_key(st, {**base, "height": hs[-1]}, 0.5)
    other = next(h for m, h in mus.items() if m != a.mu_s)[0]
    assert K._drawing_key(st, {**base, "height": other}, 0.5) != key
    # and the block measured through the memo is the block measured afresh
    K._MEASURED.clear()
    first = K._block_size(st, {**base, "height": hs[0]}, 0.5)
    K._MEASURED.clear()
    K._LAST.clear()
    assert K._block_size(st, {**base, "height": hs[-1]}, 0.5) == first
