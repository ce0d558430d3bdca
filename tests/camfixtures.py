"""One builder for the cam tests' module fixtures (test_cam54, test_cam55, test_cam56): a scene's text
solved, constructed and written as the contract's JSON — each test file keeps its own brute force (the
independent truth) and only shares how the program's answer is obtained."""
from __future__ import annotations

import tomllib

import pytest


def built(text: str, where: str, divisions: int, precision: float = 0.5) -> tuple:
    """(cam, solution, construction at ``divisions``, the JSON document) of the scene ``text``."""
    from graphplan.exact.cam import solve
    from graphplan.graphic.cam import construct
    from graphplan.model.cam import build
    from graphplan.report.cam import cam_json
    cam = build(tomllib.loads(text), where)
    sol = solve(cam)
    g = construct(sol, divisions, precision)
    return cam, sol, g, cam_json(sol, g, "")


def cam_fixture(name: str, text: str, divisions: int, precision: float = 0.5):
    """A module-scoped fixture ``name`` giving ``built(text, "<name>", divisions, precision)``."""
    @pytest.fixture(scope="module", name=name)
    def fixture():
        return built(text, f"<{name}>", divisions, precision)
    return fixture
