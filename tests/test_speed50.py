"""Stop 50's speed work: the program's short cuts give the answers of the long ways they replace."""
from __future__ import annotations

import pytest

from graphplan.exact import cam as C
from graphplan.model import cam as MC
from graphplan.model.bounds import parse_toml
from review_scenes import CAM47, CAM49


def _cam(text: str, name: str):
    return MC.build(parse_toml(text, name), name)


@pytest.mark.parametrize("text", [CAM47], ids=["CAM47"])
def test_the_best_offset_is_the_least_radius_that_bracketing_the_pressure_angle_finds(text):
    """The closed form's offset e* (tg ϑ = (ds/dφ − e)/(s0 + s)): ``min_base_radius`` — ϑ itself
    bracketed, independent of the closed form — gives the same R0 there, and a larger one 0.1 mm
    either side."""
    cam = _cam(text, "cam")
    e, r0 = C.best_offset(cam)
    assert C.min_base_radius(cam, e) == pytest.approx(r0, rel=1e-9)
    for step in (-1e-4, 1e-4):
        assert C.min_base_radius(cam, e + step) > r0 * (1 + 1e-7)


@pytest.mark.slow
@pytest.mark.parametrize("law", ["parabolic", "cosine", "cycloidal", "linear", "trapezoidal"])
def test_the_best_offset_is_the_brute_searchs(law):
    """The closed form against the search it replaced (min_base_radius at every trial offset)."""
    cam = _cam(CAM49.replace('laws = { rise = "cosine"', f'laws = {{ rise = "{law}"'), law)
    e, r0 = C.best_offset(cam)
    e_b, r0_b = C.best_offset_searched(cam)
    assert abs(e - e_b) < 1e-9 and round(e, 4) == round(e_b, 4)
    assert r0 == pytest.approx(r0_b, rel=1e-9)


def _counted_and_built(st, fmt: str) -> list[tuple[str, int, int]]:
    """Each document of the scene: (kind, ``COUNTS``' count, the pages of the document built whole)."""
    from graphplan.sheets import sheet as S
    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.form import form
    from graphplan.util.errors import GraphplanError

    def pages(make) -> int | str:
        try:
            return make()
        except GraphplanError:
            return "refused"            # a document the scene cannot make: refused by both, or a mismatch
    out = []
    for kind in S.kinds_of(st, "kinematics"):
        opts = SheetOptions(lang="uk", sheet=kind)
        count = S.COUNTS[kind, S.RAW[kind]]
        out.append((kind, pages(lambda: count(st, form(fmt), opts)),
                    pages(lambda: len(S.RAW[kind](st, form(fmt), opts).pages))))
    return out


@pytest.mark.slow          # the shaper's three documents composed whole: ~15 s of CPU
def test_a_documents_sheets_counted_without_drawing_it_are_the_sheets_it_draws():
    """``pages_of`` counts the other documents of a scene by their plans (one sheet where the plan
    says so, else composed): the same counts as the documents composed whole (the shaper at A1:
    kinematics, forces and dynamics)."""
    from conftest import ROOT
    from graphplan.exact.positions import study
    from graphplan.model.scene import load
    got = _counted_and_built(study(load(ROOT / "examples" / "shaper.toml")), "A1")
    assert len(got) == 3 and all(c == n for _, c, n in got), got


SCENES = ["LINK49", "WHITWORTH49", "SHEARS49", "OWN_SIX49", "LINK48", "BEATER48", "LINK47", "WATT47", "SIEVE47",
          "COUPLER47", "YOKE11", "COMPRESSOR11", "SIXBAR12", "PUMP45"]


@pytest.mark.slow
@pytest.mark.parametrize("fmt", ["A1", "A3"])
@pytest.mark.parametrize("name", SCENES + ["shaper", "slotter", "crank_slider", "four_bar"])
def test_every_scenes_documents_are_counted_as_they_are_drawn(name, fmt):
    import review_scenes as R
    from conftest import ROOT, scene_study
    from graphplan.exact.positions import study
    from graphplan.model.scene import load
    st = scene_study(getattr(R, name)) if name in SCENES else study(load(ROOT / "examples" / f"{name}.toml"))
    got = _counted_and_built(st, fmt)       # a refused document is compared too: refused by its count
    assert all(c == n for _, c, n in got), got
