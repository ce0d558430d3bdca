"""Stop 57 (web57): the explorer opens where the plans read, and the downloads are named after the scene.

* The explorer opened at position 0, which on the lead's six-bar pusher (FRC56_PUSHER, an extreme
  position) is a dead position: the slider stands still, the velocity plan a tuft of short vectors.
  It now opens at the first position with an acceleration plan (the scene's ``accel``: the one the
  sheet draws), else at position 1 when position 0 is an extreme position, and says why.
* Every download was "kinematics-A1.pdf", "explorer.html", "tables.zip", "scene.toml" whatever the
  scene: a student downloading two variants overwrote the first with the second. The files now carry
  the scene's designation (in Latin letters) and a fingerprint of its text."""
from __future__ import annotations

import functools
import io
import re
import zipfile

import numpy as np
import pytest

from conftest import ROOT, scene_study
from review_scenes import FRC56_PUSHER

CRANK = (ROOT / "examples" / "crank_slider.toml").read_text(encoding="utf-8")


@functools.lru_cache(maxsize=None)
def _opening(text: str):
    from graphplan.graphic.plans import build_plans
    from graphplan.report.explorer import opening
    st = scene_study(text)
    plans = build_plans(st, precision=0.5)
    return st, plans, opening(st, plans)


def _output_speed(st, phi: float) -> float:
    """|v| of the output (its slide's rate, or its link's ω) at crank angle φ, from the exact solver."""
    from graphplan.exact.kinematics import solve
    kin = solve(st.mech, st.structure, np.array([phi]))
    return float(abs(np.asarray(st.output.rate(kin))[0]))


def test_the_explorer_opens_the_six_bar_at_its_acceleration_position_not_at_the_dead_one():
    st, plans, o = _opening(FRC56_PUSHER)
    assert FRC56_PUSHER.count("accel = [3]") == 1
    assert (o["why"], o["index"], o["key"]) == ("accel", 3, 3)
    assert o["phi"] == pytest.approx(next(p.phi for p in plans.positions if p.index == 3))
    # the page's claim, against the solver: the output stands still at position 0 and moves at 3
    assert o["still0"] is True
    crank = st.mech.crank.length * abs(st.mech.omega1)
    assert _output_speed(st, st.phi0) < 1e-9 * crank
    assert _output_speed(st, o["phi"]) > 0.05 * crank


def test_without_an_acceleration_plan_it_opens_at_position_1_when_position_0_is_dead():
    """(build_plans always draws one — the scene's accel, else position 1 —; a caller's plans may not.)"""
    import dataclasses
    import types

    from graphplan.report.explorer import opening
    st, plans, _ = _opening(CRANK)                      # start = "max": position 0 is the outer dead centre
    bare = types.SimpleNamespace(positions=[dataclasses.replace(p, acceleration=None) for p in plans.positions])
    assert opening(st, bare) | {"phi": 0} == {"key": 1, "index": 1, "phi": 0, "why": "still", "still0": True}
    crank = st.mech.crank.length * abs(st.mech.omega1)
    assert _output_speed(st, st.phi0) < 1e-9 * crank


def test_an_acceleration_plan_at_position_0_opens_there():
    st, plans, o = _opening(CRANK.replace("accel = [1]", "accel = [0]"))
    assert (o["why"], o["index"]) == ("", 0)


# -- the downloads' names ---------------------------------------------------------------------------------

def test_the_file_stem_is_the_designation_in_latin_letters_and_the_text_s_fingerprint():
    import hashlib

    from graphplan.web.jobs import file_stem
    assert file_stem(CRANK) == "TMM.01.00.000-" + hashlib.sha256(CRANK.encode()).hexdigest()[:6]
    assert file_stem(CRANK) == file_stem(CRANK)                                   # deterministic
    other = CRANK.replace("r = 0.064", "r = 0.07", 1)
    assert other != CRANK and file_stem(other) != file_stem(CRANK)               # another variant, another name
    hostile = CRANK.replace('designation = "ТММ.01.00.000"', 'designation = "../../etc/passwd\\"; x=\\r\\n"')
    assert re.fullmatch(r"[A-Za-z0-9.-]+", file_stem(hostile)) and "/" not in file_stem(hostile)
    assert file_stem("not = [toml").startswith("scene-")                         # a scene that does not read
    no_designation = "\n".join(ln for ln in CRANK.splitlines() if not ln.startswith("designation"))
    assert file_stem(no_designation).startswith("Crank-slider-mechanism-")       # its English title
    no_title_en = "\n".join(ln for ln in no_designation.splitlines() if not ln.startswith("title_en"))
    assert file_stem(no_title_en).startswith("Kryvoshypno-povzunnyi-mekhanizm-")  # its title, romanised


@pytest.fixture
def client(web):
    """The worker's web app in the test client (conftest's ``web_client``, one for the worker)."""
    return web


def _named(r) -> str:
    assert r.status_code == 200, r.text
    return re.fullmatch(r'attachment; filename="([^"]+)"', r.headers["content-disposition"]).group(1)


def _variants(client) -> list[str]:
    texts = [client.post("/api/toml", json={"template": "crank_slider", "values": {"r": r}}).text
             for r in ("0,1", "0,12")]
    assert ["\nr = 0.1\n" in t for t in texts] == [True, False]
    assert all('designation = "ТММ.01.00.000"' in t for t in texts)
    return texts


def test_two_variants_of_one_template_download_under_two_names(client):
    """Two crank-sliders filled in on the page share the template's designation ТММ.01.00.000: the
    TOML the page saves (the preview's X-File-Stem) and the files the server sends are named apart; the same scene
    twice is named alike; a scene that does not assemble keeps its name (the page saves its TOML all
    the same)."""
    texts = _variants(client)
    stems = [client.post("/api/scene/preview?phi=30", content=t.encode()).headers["x-file-stem"] for t in texts]
    assert all(re.fullmatch(r"TMM\.01\.00\.000-[0-9a-f]{6}", s) for s in stems) and stems[0] != stems[1]
    assert client.post("/api/scene/preview?phi=30", content=texts[0].encode()).headers["x-file-stem"] == stems[0]
    broken = texts[0].replace("\nr = 0.1\n", "\nr = 0.5\n", 1)
    bad = client.post("/api/scene/preview?phi=30", content=broken.encode())
    assert bad.status_code == 422 and bad.headers["x-file-stem"].startswith("TMM.01.00.000-")


@pytest.mark.slow
def test_the_explorer_and_the_tables_download_under_the_scene_s_name(client):
    text = _variants(client)[1]
    stem = client.post("/api/scene/preview?phi=30", content=text.encode()).headers["x-file-stem"]
    tables = client.post("/api/tables?lang=en", content=text.encode())
    assert _named(tables) == f"{stem}-tables.zip"
    assert zipfile.ZipFile(io.BytesIO(tables.content)).namelist() == ["analyze.csv", "plans.csv"]
    assert _named(client.post("/api/view?lang=en", content=text.encode())) == f"{stem}-explorer.html"


def test_an_assembly_that_cannot_exist_says_why_in_its_box_without_the_server_s_file_name(client):
    """The box of an assembly that does not exist wrote «scene.toml: група II(4-5) … не складається …»
    — the server's name for the scene, where the student had uploaded link57.toml: the box says the
    line without it (the header keeps the command line's whole line; the page names the student's file)."""
    import json
    import urllib.parse
    import xml.etree.ElementTree as ET
    shaper = re.sub(r"\[branch\]\n(.+\n)+", "", (ROOT / "examples" / "shaper.toml").read_text(encoding="utf-8"))
    r = client.post("/api/scene/preview?phi=30&lang=uk", content=shaper.encode())
    said = json.loads(urllib.parse.unquote(r.headers["x-assemblies"]))
    assert said[1]["error"].startswith("scene.toml: ") and "не складається" in said[1]["error"]
    words = " ".join(" ".join(ET.fromstring(r.content).itertext()).split())
    assert "не складається за жодного кута кривошипа" in words and "scene.toml" not in words
