"""Stop 55 (misc55): `graphplan serve` used as a student would, in Debian's chromium — what a student
stumbled on, fixed:

- the sheets offered are those the scene makes (a six-bar with loads and a [dynamics] table: the
  kinematics, forces and dynamics; a cam: the cam's; gears: the gears') — the page offered all five,
  a cam sheet for a lever mechanism refused only after the wait;
- an uploaded scene hides the template's fields (they showed the crank-slider's l_OA = 0.064 beside a
  six-bar's scene) and says, where they were, which file the scene came from and how to return;
- a sheet being made says what it is and counts the seconds (it said "Обчислюється…" for two
  minutes), then the file and the time it took;
- switching the language leaves no line in the other one; the sheet's language reads as words;
- a broken scene file says its line above the drawing and again on a download, and no file comes.

The fixtures (the real server, chromium through selenium) are test_serve_browser's."""
from __future__ import annotations

import os
import re
import time
from pathlib import Path

import pytest

from test_serve_browser import (ROOT, console_errors, downloaded, driver, downloads, preview_src,  # noqa: F401
                                server, settled, wait)

pytestmark = pytest.mark.skipif(not Path("/usr/bin/chromium").exists() and not os.environ.get("CI"),
                                reason="chromium is missing")


def _offered(d) -> dict[str, bool]:
    from selenium.webdriver.common.by import By
    return {c.get_attribute("value"): c.is_selected()
            for c in d.find_elements(By.CSS_SELECTOR, "input[name=kind]") if c.is_displayed()}


def _upload(d, path: Path) -> None:
    from selenium.webdriver.common.by import By
    before = preview_src(d)
    d.find_element(By.ID, "upload").send_keys(str(path))
    wait(d, lambda: ((s := preview_src(d)) and s != before) or d.find_element(By.ID, "scene-error").text,
         60, what=f"{path.name}'s preview")
    settled(d)


def test_an_uploaded_scene_offers_its_own_sheets_and_hides_the_templates_fields(driver, server):
    from selenium.webdriver.common.by import By
    from selenium.webdriver.support.ui import Select
    d = driver
    d.get(server + "/?lang=uk")
    wait(d, lambda: preview_src(d), what="the first preview")
    _upload(d, ROOT / "examples" / "shaper.toml")          # loads and a [dynamics] table: three documents
    wait(d, lambda: set(_offered(d)) == {"kinematics", "forces", "dynamics"}, what="the shaper's sheets")
    assert _offered(d)["kinematics"]
    said = d.find_element(By.ID, "upload-said")
    assert said.is_displayed() and "shaper.toml" in said.text and "оберіть схему" in said.text
    assert not d.find_element(By.ID, "fields").is_displayed()

    _upload(d, ROOT / "examples" / "cam_translating.toml")
    wait(d, lambda: _offered(d) == {"cam": True}, what="the cam's sheet alone, ticked")
    _upload(d, ROOT / "examples" / "gears.toml")
    wait(d, lambda: _offered(d) == {"gears": True}, what="the gears' sheet alone, ticked")
    _upload(d, ROOT / "examples" / "four_bar.toml")          # no loads: the kinematics alone
    wait(d, lambda: _offered(d) == {"kinematics": True}, what="the four-bar's one sheet")

    Select(d.find_element(By.ID, "template")).select_by_value("four_bar")      # back to the form
    wait(d, lambda: d.find_element(By.ID, "fields").is_displayed(), what="the template's fields again")
    assert not d.find_element(By.ID, "upload-said").is_displayed()
    assert console_errors(d) == []


def test_a_sheet_being_made_says_what_and_counts_the_seconds_and_the_language_does_not_mix(
        driver, server, downloads):
    from selenium.webdriver.common.by import By
    from selenium.webdriver.support.ui import Select
    d = driver
    d.get(server + "/?lang=uk")
    wait(d, lambda: preview_src(d), what="the first preview")
    Select(d.find_element(By.ID, "template")).select_by_value("four_bar")
    wait(d, lambda: d.find_elements(By.ID, "f-l3"), what="the four-bar's fields")
    settled(d)
    assert [o.text for o in Select(d.find_element(By.ID, "sheet-lang")).options] == ["українська", "English"]
    Select(d.find_element(By.ID, "type")).select_by_value("svg")
    Select(d.find_element(By.ID, "format")).select_by_value("A1")
    for old in downloads.glob("*kinematics-A1*.svg"):
        old.unlink()
    d.find_element(By.ID, "dl-sheet").click()
    status = d.find_element(By.ID, "dl-status")
    seen = []
    deadline = time.monotonic() + 300
    while time.monotonic() < deadline:
        text = status.text
        if not seen or seen[-1] != text:
            seen.append(text)
        if text.startswith("Готово"):
            break
        time.sleep(0.25)
    counting = [s for s in seen if re.fullmatch(r"Обчислення: аркуш «кінематика», A1, SVG… \d+ с( \(.*\))?", s)]
    assert counting, seen
    assert re.fullmatch(r"Готово: TMM\.03\.00\.000-[0-9a-f]{6}-kinematics-A1\.svg \(\d+ с\)", seen[-1]), seen
    took = int(re.search(r"\((\d+) с\)", seen[-1]).group(1))
    if took >= 2:                    # a wait of seconds was counted as it went, not said once
        assert len({re.search(r"(\d+) с", s).group(1) for s in counting}) >= 2, seen
    assert downloaded(downloads, "-kinematics-A1.svg").stat().st_size > 10_000

    Select(d.find_element(By.ID, "lang")).select_by_value("en")       # no Ukrainian line left behind
    wait(d, lambda: d.find_element(By.ID, "dl-status").text == "", what="the status cleared")
    wait(d, lambda: d.find_element(By.ID, "tab-teacher").text == "Teacher", what="the page in English")
    assert [o.text for o in Select(d.find_element(By.ID, "sheet-lang")).options] == ["українська", "English"]
    assert not re.search("[А-Яа-яІіЇїЄє]", d.find_element(By.ID, "view-col").text.replace("українська", ""))
    assert console_errors(d) == []


def test_a_broken_scene_file_says_its_line_and_no_sheet_comes(driver, server, downloads, tmp_path):
    from selenium.webdriver.common.by import By
    d = driver
    d.get(server + "/?lang=en")
    wait(d, lambda: preview_src(d), what="the first preview")
    _upload(d, ROOT / "examples" / "gears.toml")
    wait(d, lambda: _offered(d) == {"gears": True}, what="the gears' sheet")
    d.execute_script("document.getElementById('dl-status').textContent = 'Ready: gears-A1.pdf (9 s)'")
    bad = tmp_path / "broken.toml"
    bad.write_text('title = "broken"\n[crank\nlength = 0.1\n', encoding="utf-8")
    d.find_element(By.ID, "upload").send_keys(str(bad))
    wait(d, lambda: d.find_element(By.ID, "scene-error").text, what="the scene's error")
    line = d.find_element(By.ID, "scene-error").text
    assert line.startswith("broken.toml: ") and "line 2" in line, line       # the student's file, not scene.toml
    assert "broken.toml" in d.find_element(By.ID, "upload-said").text
    assert d.find_element(By.ID, "dl-status").text == ""        # the previous scene's "Ready" not left
    assert _offered(d) == {"kinematics": True}          # a lever scene's (no [gears]): its fault said on download
    before = set(os.listdir(downloads))
    d.find_element(By.ID, "dl-sheet").click()
    wait(d, lambda: d.find_element(By.ID, "dl-error").text, what="the download's error")
    assert d.find_element(By.ID, "dl-error").text.startswith("broken.toml: ")
    assert "line 2" in d.find_element(By.ID, "dl-error").text
    assert d.find_element(By.ID, "dl-status").text == ""
    time.sleep(1.0)
    assert set(os.listdir(downloads)) == before
    assert console_errors(d) == []
