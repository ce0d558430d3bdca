"""Shared helpers: the examples, a scene builder and finite differences of exact positions."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from graphplan.exact.positions import study
from graphplan.model.scene import load, loads

ROOT = Path(__file__).resolve().parent.parent


def pytest_configure(config):
    """Tests and benchmarks run with the allocator as the program sets it (graphplan.util.memory)."""
    from graphplan.util.memory import keep_freed_memory
    keep_freed_memory()
EXAMPLES = ["crank_slider", "lab_crank_slider", "four_bar", "shaper", "slotter"]


def example(name: str):
    """An example studied — a cam example (cam_*) read as its cam, what the cam sheet takes."""
    if name.startswith("cam_"):
        from graphplan.model.cam import load as load_cam
        return load_cam(ROOT / "examples" / f"{name}.toml")
    if name.startswith("gears"):            # a gear example: the gear sheet takes the scene itself
        from graphplan.model.gears import load as load_gears
        return load_gears(ROOT / "examples" / f"{name}.toml")
    return study(load(ROOT / "examples" / f"{name}.toml"))


def scene_study(text: str):
    return study(loads(text, "<test>"))


def derivative(f, phi_deg: np.ndarray, omega: float, order: int = 1, h_deg: float = 0.05):
    """d/dt (order 1) or d²/dt² (order 2) of f(φ) at constant ω, five-point stencils in φ."""
    h = np.radians(h_deg)
    f2, f1, f0, g1, g2 = (f(phi_deg + k * h_deg) for k in (-2, -1, 0, 1, 2))
    if order == 1:
        return (f2 - 8 * f1 + 8 * g1 - g2) / (12 * h) * omega
    return (-f2 + 16 * f1 - 30 * f0 + 16 * g1 - g2) / (12 * h * h) * omega ** 2


@pytest.fixture(params=EXAMPLES)
def any_example(request):
    return example(request.param)


@pytest.fixture(scope="module")
def crank_slider_keys(tmp_path_factory):
    """Keys of two crank-slider variants (examples/crank_slider.toml with r, l changed), for the tests
    that grade students' tables."""
    from fuzz_scenes import run
    folder = tmp_path_factory.mktemp("keys")
    table = folder / "variants.csv"
    table.write_text(f"# base = {ROOT / 'examples' / 'crank_slider.toml'}\nvariant,r,l\n01,0.064,0.307\n"
                     "02,0.05,0.2\n", encoding="utf-8")
    code, _, err = run(["key", str(table), "-o", str(folder / "keys"), "--quiet", "--no-pdf", "--jobs", "1"])
    assert code == 0, err
    return folder / "keys"

