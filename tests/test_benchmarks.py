"""Benchmarks (pytest-benchmark; run them with `python -m pytest tests/test_benchmarks.py -n 0
--benchmark-enable`). By default they run once as plain tests: the hand-written closed form of
the shaper is also an independent check of the general solver."""
from __future__ import annotations

import os

import numpy as np
import pytest

from conftest import example

N = 3600


def shaper_by_hand(phi_deg: np.ndarray, r: float, l3: float, l4: float, h_guide: float,
                   o1: complex, w1: float):
    """The shaper's ram C by closed form: the rocker through A, then C on y = X, left of B."""
    e = np.exp(1j * np.radians(phi_deg))
    rho = o1 + r * e                       # A − O (rocker pivot at the origin)
    va, aa = 1j * w1 * r * e, -w1 ** 2 * r * e
    s = np.abs(rho)
    u = rho / s
    sd = np.real(np.conj(u) * va)                     # ṡ
    w3 = np.imag(np.conj(u) * va) / s                 # ω3
    rel = aa * np.conj(u)                             # ρ̈ in the rocker's axes
    e3 = (rel.imag - 2 * sd * w3) / s                 # ε3
    b = l3 * u
    vb, ab = 1j * w3 * b, (1j * e3 - w3 ** 2) * b
    h = h_guide - b.imag
    root = np.sqrt(l4 ** 2 - h ** 2)
    xc = b.real - root
    vxc = vb.real - h * vb.imag / root
    hd = -vb.imag
    rootd = -h * hd / root
    axc = ab.real - ((hd * vb.imag + h * ab.imag) * root - h * vb.imag * rootd) / root ** 2
    return xc, vxc, axc, w3, e3


def shaper_complete_by_hand(phi_deg, r, l3, l4, h_guide, o1, w1):
    """Everything the general solver returns for the shaper, by hand: the ram, the rocker and the rod
    (angle, ω, ε), the block's slide (s, ṡ, s̈, Coriolis 2ω3·ṡ) and the ram's slide."""
    xc, vxc, axc, w3, e3 = shaper_by_hand(phi_deg, r, l3, l4, h_guide, o1, w1)
    e = np.exp(1j * np.radians(phi_deg))
    rho = o1 + r * e
    s = np.abs(rho)
    u = rho / s
    va, aa = 1j * w1 * r * e, -w1 ** 2 * r * e
    sd = np.real(np.conj(u) * va)
    sdd = np.real(np.conj(u) * aa) + s * w3 ** 2
    cor = 2j * w3 * sd * u
    b = l3 * u
    vb, ab = 1j * w3 * b, (1j * e3 - w3 ** 2) * b
    c = xc + 1j * h_guide
    bc = c - b
    w4 = np.imag(np.conj(bc) * (vxc - vb)) / l4 ** 2
    e4 = (np.imag(np.conj(bc) * (axc - ab))) / l4 ** 2
    return (c, vxc, axc, u, w3, e3, bc / l4, w4, e4, s, sd, sdd, cor)


def _shaper_inputs():
    st = example("shaper")
    m = st.mech
    return st, (m.crank.length, m.links["OB"].length, m.links["BC"].length, 0.45, m.frame["O1"], m.omega1)


def test_hand_closed_form_agrees_with_the_solver():
    st, args = _shaper_inputs()
    phi = np.linspace(0, 360, 721)
    xc, vxc, axc, w3, e3 = shaper_by_hand(phi, *args)
    kin = st.solve(phi)
    x, v, a = kin.point("C")
    assert np.allclose(x.real, xc, atol=1e-12)
    assert np.allclose(v.real, vxc, atol=1e-9)
    assert np.allclose(a.real, axc, atol=1e-7)
    assert np.allclose(kin.bodies["OB"].omega, w3, atol=1e-10)
    assert np.allclose(kin.bodies["OB"].eps, e3, atol=1e-8)


def test_bench_solver_3600_shaper(benchmark):
    st, _ = _shaper_inputs()
    phi = np.linspace(0, 360, N, endpoint=False)
    kin = benchmark(lambda: st.solve(phi))
    assert kin.point("C")[0].shape == (N,)


def test_bench_hand_closed_form_3600_shaper(benchmark):
    _, args = _shaper_inputs()
    phi = np.linspace(0, 360, N, endpoint=False)
    c = benchmark(lambda: shaper_complete_by_hand(phi, *args))[0]
    assert c.shape == (N,)


def test_complete_hand_form_agrees_with_the_solver():
    st, args = _shaper_inputs()
    phi = np.linspace(0, 360, 361)
    c, vxc, axc, u, w3, e3, ubc, w4, e4, s, sd, sdd, cor = shaper_complete_by_hand(phi, *args)
    kin = st.solve(phi)
    assert np.allclose(kin.bodies["BC"].omega, w4, atol=1e-9)
    assert np.allclose(kin.bodies["BC"].eps, e4, atol=1e-6)
    slide = kin.slides["A"]
    assert np.allclose(slide.v, sd, atol=1e-10)
    assert np.allclose(slide.a, sdd, atol=1e-8)
    assert np.allclose(slide.coriolis, cor, atol=1e-8)


FREED = """
import numpy as np
import pytest
def rss():
    return int(open("/proc/self/statm").read().split()[1]) * 4096 / 2**20
if {keep}:
    from graphplan.util.memory import keep_freed_memory
    assert keep_freed_memory()
base = rss()
a = np.ones(2_000_000)   # 16 MB: above glibc's default mmap threshold, below the tuned one
del a
print(rss() - base)
"""


@pytest.mark.skipif(not os.path.exists("/proc/self/statm"), reason="needs Linux's /proc to read the RSS")
def test_freed_memory_is_kept_for_the_next_temporary():
    """With the tuning a freed 16 MB temporary stays in the process (no page faults to take it back);
    without it glibc returns it to the system at once."""
    import subprocess
    import sys
    kept = [float(subprocess.run([sys.executable, "-c", FREED.format(keep=k)], capture_output=True,
                                 text=True, check=True).stdout) for k in (True, False)]
    assert kept[0] > 12.0 and kept[1] < 4.0
