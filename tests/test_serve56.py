"""Stop 56 (misc56): `graphplan serve` says which assembly is the scene's default — the one a sheet
draws when [branch] leaves the group open (+1, docs/scenes.md) — in the preview's caption, in the
answer's X-Assemblies and on the page, in both languages; choosing one says the choice instead."""
from __future__ import annotations

import json
import os
import re
from pathlib import Path
from urllib.parse import unquote

import numpy as np
import pytest

from review_scenes import MISC56
from test_serve_browser import downloads, driver, server  # noqa: F401  (the worker's browser and server)

pytest.importorskip("starlette")
pytest.importorskip("multipart")

ROOT = Path(__file__).resolve().parents[1]
FOUR_BAR = re.sub(r"\[branch\]\n(.+\n)+", "", (ROOT / "examples" / "four_bar.toml").read_text(encoding="utf-8"))


@pytest.fixture
def client(web):
    """The worker's web app in the test client (conftest's ``web_client``, one for the worker)."""
    return web


def _captions(svg: bytes) -> list[str]:
    return re.findall(r'<g class="assembly"[^>]*>.*?<text[^>]*>([^<]*)</text>', svg.decode("utf-8"))


@pytest.mark.parametrize("text", [FOUR_BAR, MISC56], ids=["four-bar", "six-bar56"])
def test_the_default_assembly_is_the_one_the_sheet_draws_without_branch(client, text):
    """The default is +1 for every open group: the scene without [branch] studies exactly as with
    all +1 (api.study), and differently from −1 — and that is the drawing the page calls default."""
    from conftest import scene_study
    r = client.post("/api/scene/preview?phi=30&lang=en", content=text.encode())
    said = json.loads(unquote(r.headers["x-assemblies"]))
    keys = json.loads(unquote(r.headers["x-branch-keys"]))
    assert [a["default"] for a in said] == [True, False]
    assert said[0]["branch"] == {keys[0]: 1}
    plus = text + "\n[branch]\n" + "".join(f"{k} = 1\n" for k in keys)
    minus = text + "\n[branch]\n" + "".join(f"{k} = {-1 if i == 0 else 1}\n" for i, k in enumerate(keys))
    at = lambda s: complex(np.ravel(scene_study(s).solve(30.0).point(keys[0])[0])[0])      # noqa: E731
    assert abs(at(text) - at(plus)) < 1e-12 and abs(at(text) - at(minus)) > 1e-3
    en = _captions(r.content)
    assert en[0].endswith("(the default)") and "default" not in en[1]
    uk = _captions(client.post("/api/scene/preview?phi=30&lang=uk", content=text.encode()).content)
    assert uk[0].startswith("складання 1: [branch]") and uk[0].endswith("(типове)") and "типове" not in uk[1]
    assert "−1" in uk[1]                     # the minus sign the page's words use, not a hyphen


def test_an_assembly_that_does_not_assemble_is_nobody_s_default(client):
    shaper = re.sub(r"\[branch\]\n(.+\n)+", "", (ROOT / "examples" / "shaper.toml").read_text(encoding="utf-8"))
    said = json.loads(unquote(client.post("/api/scene/preview?phi=30&lang=uk", content=shaper.encode())
                              .headers["x-assemblies"]))
    assert said[0]["default"] is True and said[1]["error"] and said[1]["default"] is False


@pytest.mark.skipif(not Path("/usr/bin/chromium").exists() and not os.environ.get("CI"), reason="chromium is missing")
def test_the_page_says_which_assembly_the_sheets_take_in_both_languages(driver, server, tmp_path):
    from selenium.webdriver.common.by import By
    from selenium.webdriver.support.ui import Select

    import test_serve_browser as B
    scene = tmp_path / "six_bar56.toml"
    scene.write_text(MISC56, encoding="utf-8")
    d = driver                  # the worker's browser on a clean tab, the worker's server (test_serve_browser)
    d.get(f"{server}/?lang=uk")
    B.wait(d, lambda: B.preview_src(d), 90, what="the first preview")
    before = B.preview_src(d)
    d.find_element(By.ID, "upload").send_keys(str(scene))
    B.wait(d, lambda: (s := B.preview_src(d)) and s != before, 120, what="the six-bar's preview")
    B.settled(d)
    said = lambda: d.find_element(By.ID, "branch-said").text      # noqa: E731
    B.wait(d, lambda: "типове складання 1 ([branch] B = +1)" in said(), what="the default said")
    labels = [b.get_attribute("aria-label") for b in d.find_elements(By.CSS_SELECTOR, "#assemblies .assembly")]
    assert labels[0].endswith("(типове)") and "типове" not in labels[1]
    Select(d.find_element(By.ID, "lang")).select_by_value("en")
    B.wait(d, lambda: "the default, assembly 1 ([branch] B = +1)" in said(), what="said in English")
    assert not re.search("[а-яєіїґ]", said())
    d.find_elements(By.CSS_SELECTOR, "#assemblies .assembly")[1].click()
    B.wait(d, lambda: said().startswith("Assembly chosen: [branch] B = −1"), 120, what="the choice said")
    assert d.find_element(By.ID, "dl-view").is_displayed()
    before = B.preview_src(d)
    d.find_element(By.ID, "upload").send_keys(str(ROOT / "examples" / "gears.toml"))
    B.wait(d, lambda: (s := B.preview_src(d)) and s != before, 120, what="the gears' preview")
    B.settled(d)
    # the explorer shows lever mechanisms and cams: no button that only answers with a refusal
    assert not d.find_element(By.ID, "dl-view").is_displayed()
    assert B.console_errors(d) == []
