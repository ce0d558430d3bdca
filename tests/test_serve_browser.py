"""`graphplan serve` end to end: the real server (`python -m graphplan serve`) and Debian's chromium
through selenium. A student fills in a template, the preview follows the values and the angle, an
assembly is chosen by clicking its drawing, a PDF sheet is downloaded and read back with pdftotext; a
teacher turns a variants table into keys and students' tables into grades. No console error.

Without chromium, its driver or selenium these tests skip with the reason — except in CI (env CI
set), where they fail. Screenshots go to the test's folder, and to $GRAPHPLAN_SHOTS when set
(docs/serve/ holds the ones docs/serve.md shows)."""
from __future__ import annotations

import csv
import io
import os
import re
import shutil
import socket
import subprocess
import sys
import time
import zipfile
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
CHROMIUM = "/usr/bin/chromium"
DRIVER = "/usr/bin/chromedriver"


def _browser_missing() -> str | None:
    try:
        import selenium  # noqa: F401
        import starlette  # noqa: F401
        import uvicorn  # noqa: F401
    except ImportError as exc:
        return f"{exc.name} is not installed (pip install -e '.[test]')"
    for path in (CHROMIUM, DRIVER):
        if not (os.path.exists(path) or shutil.which(Path(path).name)):
            return f"{path} is missing (apt-get install chromium chromium-driver)"
    if not shutil.which("pdftotext"):
        return "pdftotext is missing (apt-get install poppler-utils)"
    return None


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def start_server(port: int) -> subprocess.Popen:
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    proc = subprocess.Popen([sys.executable, "-m", "graphplan", "serve", "--port", str(port)], cwd=ROOT, env=env,
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 30
    while time.monotonic() < deadline:
        try:
            with socket.create_connection(("127.0.0.1", port), 0.2):
                return proc
        except OSError:
            if proc.poll() is not None:
                raise RuntimeError(proc.stderr.read())
            time.sleep(0.1)
    proc.kill()
    raise RuntimeError("the server did not start in 30 s")


@pytest.fixture
def server(served):
    """The worker's one ``graphplan serve`` (conftest's ``served``, started at its first browser test)."""
    return served


@pytest.fixture
def downloads(tmp_path_factory):
    return tmp_path_factory.mktemp("downloads")


@pytest.fixture
def driver(server, downloads, chromium):
    """The worker's one Chromium (conftest's ``chromium``) on a clean tab of 1300 × 1000 for each test,
    its downloads going to the test's own folder."""
    from conftest import browser_tab
    return browser_tab(chromium, 1300, 1000, downloads)


def shot(d, tmp_path: Path, name: str) -> Path:
    path = tmp_path / f"{name}.png"
    d.save_screenshot(str(path))
    assert path.stat().st_size > 10_000
    if os.environ.get("GRAPHPLAN_SHOTS"):
        folder = Path(os.environ["GRAPHPLAN_SHOTS"])
        folder.mkdir(parents=True, exist_ok=True)
        shutil.copy(path, folder / path.name)
    return path


def wait(d, condition, timeout: float = 30.0, what: str = ""):
    """Until ``condition()`` holds; an element the page redrew while it was read (the assemblies'
    buttons re-rendered after a choice) is "not yet", read again on the next poll."""
    from selenium.common.exceptions import StaleElementReferenceException
    from selenium.webdriver.support.ui import WebDriverWait
    return WebDriverWait(d, timeout, poll_frequency=0.1,
                         ignored_exceptions=(StaleElementReferenceException,)).until(lambda _: condition(), message=what)


def preview_src(d) -> str:
    return d.execute_script("const i = document.getElementById('preview-img');"
                            "return i.complete && i.naturalWidth > 0 ? i.src : '';")


def settled(d) -> None:
    """Wait until the page has drawn the last change (no request pending or running)."""
    wait(d, lambda: d.execute_script("return !document.getElementById('preview').dataset.busy"),
         what="the preview settled")


def downloaded(folder: Path, suffix: str, timeout: float = 60.0) -> Path:
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        done = [p for p in folder.iterdir() if p.name.endswith(suffix)]
        if done and not any(p.name.endswith(".crdownload") for p in folder.iterdir()):
            return done[0]
        time.sleep(0.1)
    raise AssertionError(f"no {suffix} downloaded; the folder holds {[p.name for p in folder.iterdir()]}")


def console_errors(d) -> list[str]:
    """Severe console entries, but the 422 answers the test provoked on purpose (the network's log)."""
    return [e["message"] for e in d.get_log("browser") if e["level"] == "SEVERE"
            and not (e.get("source") == "network" and "status of 422" in e["message"])]


def set_value(d, element_id: str, value: str) -> None:
    from selenium.webdriver.common.by import By
    from selenium.webdriver.common.keys import Keys
    el = d.find_element(By.ID, element_id)
    el.send_keys(Keys.CONTROL, "a")
    el.send_keys(value)


def test_a_student_fills_a_template_sees_it_move_chooses_the_assembly_and_takes_the_pdf_home(
        driver, server, downloads, tmp_path):
    from selenium.webdriver.common.by import By
    from selenium.webdriver.support.ui import Select
    d = driver
    d.get(server + "/?lang=en")
    wait(d, lambda: preview_src(d), what="the first preview")
    Select(d.find_element(By.ID, "template")).select_by_value("four_bar")
    wait(d, lambda: d.find_elements(By.ID, "f-l3"), what="the four-bar's fields")
    first = wait(d, lambda: preview_src(d), what="the four-bar's preview")
    set_value(d, "f-r", "0.08")                                          # the crank shorter
    second = wait(d, lambda: (s := preview_src(d)) and s != first and s, what="the preview after a value")
    t0 = time.monotonic()
    set_value(d, "phi-num", "150")                                       # the crank turned
    # the preview follows the angle (typing, the debounce, the TOML and the drawing: ~0.5 s alone); its
    # latency is docs/benchmarks.md's, not a bound here: a 5 s bound measured the machine's other load
    wait(d, lambda: (s := preview_src(d)) and s != second, 120, what="the preview after the angle")
    print(f"\nthe preview after the angle: {time.monotonic() - t0:.1f} s")
    settled(d)
    toml = d.find_element(By.ID, "toml").get_attribute("value")
    assert "length = 0.08" in toml and "[branch]" not in toml
    buttons = d.find_elements(By.CSS_SELECTOR, "#assemblies .assembly")
    assert len(buttons) == 2 and "B = −1" in buttons[1].get_attribute("aria-label")
    shot(d, tmp_path, "serve_student")
    from selenium.webdriver.common.keys import Keys
    buttons[1].send_keys(Keys.ENTER)                                     # the lower one, by the keyboard
    wait(d, lambda: "B = −1" in d.find_element(By.ID, "branch-said").text, what="the chosen assembly said")
    wait(d, lambda: "[branch]\nB = -1" in d.find_element(By.ID, "toml").get_attribute("value"),
         what="the TOML with the assembly")
    wait(d, lambda: not d.find_elements(By.CSS_SELECTOR, "#assemblies .assembly"), what="one drawing left")

    # a value that is not a number: said beside its field, the field keeps what was typed
    set_value(d, "f-l2", "0,35x")
    wait(d, lambda: "not a number" in d.find_element(By.ID, "f-l2-err").text, what="the field's error")
    assert d.find_element(By.ID, "f-l2").get_attribute("aria-invalid") == "true"
    assert d.find_element(By.ID, "f-l2").get_attribute("value") == "0,35x"
    # a rod too short: the crank angles where it does not assemble, in the scene's one line
    set_value(d, "f-l2", "0.05")
    wait(d, lambda: "crank angle" in d.find_element(By.ID, "scene-error").text, what="the assembly's ranges")
    shot(d, tmp_path, "serve_error")
    Select(d.find_element(By.ID, "lang")).select_by_value("uk")          # the same line in Ukrainian
    wait(d, lambda: "не складається для кутів кривошипа" in d.find_element(By.ID, "scene-error").text,
         what="the assembly's ranges in Ukrainian")
    assert d.find_element(By.ID, "f-l2").get_attribute("value") == "0.05"   # the values kept
    assert "довжина шатуна" in d.find_element(By.ID, "fields").text
    Select(d.find_element(By.ID, "lang")).select_by_value("en")
    set_value(d, "f-l2", "0.35")
    wait(d, lambda: not d.find_element(By.ID, "scene-error").text, what="the error gone")

    # a cam: its profile, no crank angle to set
    Select(d.find_element(By.ID, "template")).select_by_value("cam_translating")
    wait(d, lambda: not d.find_element(By.ID, "phi-row").is_displayed(), what="no crank angle for a cam")
    assert d.find_element(By.CSS_SELECTOR, "input[name=kind][value=cam]").is_selected()
    Select(d.find_element(By.ID, "template")).select_by_value("four_bar")
    wait(d, lambda: d.find_element(By.ID, "phi-row").is_displayed(), what="the crank angle again")

    # the other way in: a scene file
    before = preview_src(d)
    d.find_element(By.ID, "upload").send_keys(str(ROOT / "examples" / "shaper.toml"))
    wait(d, lambda: (s := preview_src(d)) and s != before, what="the uploaded scene's preview")
    assert d.find_element(By.ID, "toml").get_attribute("value").startswith("# Seed 000's shaping machine")
    assert d.find_element(By.ID, "fields").get_attribute("disabled") == "true"
    Select(d.find_element(By.ID, "template")).select_by_value("four_bar")      # back to the form
    wait(d, lambda: d.find_element(By.ID, "fields").get_attribute("disabled") is None, what="the form again")
    set_value(d, "f-r", "0.08")
    wait(d, lambda: "[branch]" not in d.find_element(By.ID, "toml").get_attribute("value")
         and "length = 0.08" in d.find_element(By.ID, "toml").get_attribute("value"), what="the form's scene")
    d.find_elements(By.CSS_SELECTOR, "#assemblies .assembly")
    settled(d)
    wait(d, lambda: len(d.find_elements(By.CSS_SELECTOR, "#assemblies .assembly")) == 2, what="two assemblies")
    d.find_elements(By.CSS_SELECTOR, "#assemblies .assembly")[1].click()
    wait(d, lambda: "[branch]\nB = -1" in d.find_element(By.ID, "toml").get_attribute("value"), what="chosen again")

    Select(d.find_element(By.ID, "type")).select_by_value("pdf")
    Select(d.find_element(By.ID, "format")).select_by_value("A1")
    d.find_element(By.ID, "dl-sheet").click()
    pdf = downloaded(downloads, ".pdf", 900)   # 118 s at load 25 (stop 57): the 60 s wait measured the load
    # the scene's designation (the four-bar template's ТММ.03.00.000) and its text's fingerprint (test_web57.py)
    assert re.fullmatch(r"TMM\.03\.00\.000-[0-9a-f]{6}-kinematics-A1\.pdf", pdf.name), pdf.name
    text = subprocess.run(["pdftotext", str(pdf), "-"], capture_output=True, text=True).stdout
    assert "Four-bar" in text or "four-bar" in text.lower()
    assert "0.08" in text or "80" in text                              # the student's crank on the sheet
    assert console_errors(d) == []


def test_a_teacher_turns_variants_into_keys_and_students_tables_into_grades(driver, server, downloads, tmp_path):
    from selenium.webdriver.common.by import By
    d = driver
    d.get(server + "/?lang=en")
    d.find_element(By.ID, "tab-teacher").click()
    rows = (ROOT / "examples" / "crank_slider_variants.csv").read_text(encoding="utf-8").splitlines()
    header = next(i for i, ln in enumerate(rows) if ln.startswith("variant"))
    variants = tmp_path / "variants.csv"
    variants.write_text("\n".join(rows[:header + 4]) + "\n", encoding="utf-8")     # three variants
    d.find_element(By.ID, "variants").send_keys(str(variants))
    d.find_element(By.ID, "base").send_keys(str(ROOT / "examples" / "crank_slider.toml"))
    d.find_element(By.ID, "make-keys").click()
    keys = downloaded(downloads, "keys.zip", 120)
    assert "3 / 3" in d.find_element(By.ID, "key-status").text or "keys.zip" in d.find_element(By.ID, "key-status").text
    z = zipfile.ZipFile(keys)
    import json
    key = json.loads(z.read("02/key.json"))
    exact = key["positions"][2]["values"]["v_B"]
    student = tmp_path / "student.csv"
    with open(student, "w", newline="", encoding="utf-8") as f:
        w = csv.writer(f)
        w.writerow(["variant", "position", "quantity", "value"])
        w.writerow(["02", "2", "v_B", f"{exact * 1.01:.5f}"])            # 1 % off: passes
        w.writerow(["02", "2", "v_B", f"{exact * 1.5:.5f}"])             # 50 % off: fails
    d.find_element(By.ID, "keyfile").send_keys(str(keys))
    d.find_element(By.ID, "students").send_keys(str(student))
    d.find_element(By.ID, "grade").click()
    wait(d, lambda: len(d.find_elements(By.CSS_SELECTOR, "#grades tbody tr")) == 2, what="the graded rows")
    statuses = [tr.get_attribute("class") for tr in d.find_elements(By.CSS_SELECTOR, "#grades tbody tr")]
    assert statuses == ["pass", "fail"]
    assert "1 passed, 1 failed" in d.find_element(By.ID, "grade-summary").text
    shot(d, tmp_path, "serve_teacher")
    d.find_element(By.ID, "grade-csv").click()
    grades = downloaded(downloads, "grades.csv")
    table = list(csv.DictReader(io.StringIO(grades.read_text(encoding="utf-8"))))
    assert [r["status"] for r in table] == ["pass", "fail"]
    assert console_errors(d) == []


def test_on_a_phone_one_column_and_nothing_wider_than_the_screen(driver, server, tmp_path):
    from selenium.webdriver.common.by import By
    d = driver
    d.execute_cdp_cmd("Emulation.setDeviceMetricsOverride",
                      {"width": 390, "height": 844, "deviceScaleFactor": 2, "mobile": True})
    try:
        d.get(server + "/?lang=uk")
        wait(d, lambda: preview_src(d), what="the preview on a phone")
        wide = d.execute_script("""const w = document.documentElement.clientWidth, out = [];
            document.querySelectorAll('body *').forEach((e) => { const r = e.getBoundingClientRect();
              if (r.width && r.right > w + 1) out.push(e.tagName + '#' + e.id + ' ' + Math.round(r.right)); });
            return [w, out];""")
        assert wide[0] == 390 and wide[1] == [], wide
        form = d.find_element(By.ID, "scene-form").rect
        view = d.find_element(By.ID, "view-col").rect
        assert view["y"] >= form["y"] + form["height"] - 1              # under the form, not beside it
        shot(d, tmp_path, "serve_phone")
    finally:
        d.execute_cdp_cmd("Emulation.clearDeviceMetricsOverride", {})


def test_on_a_phone_the_two_assemblies_stand_one_above_the_other(driver, server, tmp_path):
    """web58: the V-twin compressor (LINK58, two groups on the crank pin) uploaded on a 390 px phone:
    the two assemblies are drawn one above the other, each across the column (side by side each had
    half the screen, its letters unreadable), each button over its own drawing; choosing the second
    writes B = −1 and the second group (C) is offered the same way."""
    from selenium.webdriver.common.by import By
    from review_scenes import LINK58
    d = driver
    scene = tmp_path / "link58.toml"
    scene.write_text(LINK58, encoding="utf-8")
    d.execute_cdp_cmd("Emulation.setDeviceMetricsOverride",
                      {"width": 390, "height": 844, "deviceScaleFactor": 2, "mobile": True})
    try:
        d.get(server + "/?lang=en")
        wait(d, lambda: preview_src(d), 300, "the template's preview")         # the page is ready
        d.find_element(By.ID, "upload").send_keys(str(scene))
        wait(d, lambda: "V-twin" in d.find_element(By.ID, "toml").get_attribute("value"), 300, "the scene read")
        wait(d, lambda: any("[branch] B = +1" in (b.get_attribute("aria-label") or "") for b in
                            d.find_elements(By.CSS_SELECTOR, "#assemblies .assembly"))
             and not d.find_element(By.ID, "preview").get_attribute("data-busy"), 300, "the V-twin's assemblies")
        box = d.find_element(By.ID, "preview").rect
        img = d.find_element(By.ID, "preview-img")
        wait(d, lambda: img.size["height"] > 1.5 * img.size["width"], 300, "the drawings stacked")
        first, second = [b.rect for b in d.find_elements(By.CSS_SELECTOR, "#assemblies .assembly")]
        for r in (first, second):
            assert r["width"] >= 0.95 * box["width"], (r, box)
        assert second["y"] >= first["y"] + first["height"] - 1 and abs(first["height"] - second["height"]) <= 1
        shot(d, tmp_path, "serve_phone_assemblies")
        d.execute_script("arguments[0].scrollIntoView()", d.find_elements(By.CSS_SELECTOR, "#assemblies .assembly")[1])
        d.find_elements(By.CSS_SELECTOR, "#assemblies .assembly")[1].click()
        wait(d, lambda: "B = −1" in d.find_element(By.ID, "branch-said").text, 300, "the choice said")
        wait(d, lambda: any("C = −1" in (b.get_attribute("aria-label") or "")
                            for b in d.find_elements(By.CSS_SELECTOR, "#assemblies .assembly")), 300, "C offered")
        assert console_errors(d) == []
    finally:
        d.execute_cdp_cmd("Emulation.clearDeviceMetricsOverride", {})
