"""The example scenes the bench measures (a checkout's examples/, or the built-in crank-slider)."""
from __future__ import annotations

from importlib import resources
from pathlib import Path

from graphplan.exact.positions import Study, study
from graphplan.model.scene import load
from graphplan.util.errors import GraphplanError


def examples_dir() -> Path:
    """The examples folder of a checkout (the built-in crank-slider when installed elsewhere)."""
    here = Path(__file__).resolve().parents[2] / "examples"
    return here if here.is_dir() else Path(str(resources.files("graphplan") / "data"))


def example(name: str) -> Study:
    path = examples_dir() / f"{name}.toml"
    if not path.exists():
        raise GraphplanError(f"bench needs examples/{name}.toml (run it from a checkout)")
    return study(load(path))
