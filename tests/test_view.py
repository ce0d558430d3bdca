"""`graphplan view`: the offline explorer — its file (no network reference, small, deterministic)
and its behaviour in a real browser (Debian's chromium through selenium): the values it shows at
angles set with the slider equal `graphplan analyze --phi`, the shaper's acceleration plan is
replayed in the textbook's order with its Coriolis step, no console error, no request but the file.

Without chromium, its driver or selenium the browser tests skip with the reason — except in CI
(env CI set), where they fail. Screenshots go to a temporary folder, and also to
$GRAPHPLAN_SHOTS when set (to look at them)."""
from __future__ import annotations

import json
import math
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
SHAPER = ROOT / "examples" / "shaper.toml"
CHROMIUM = "/usr/bin/chromium"
DRIVER = "/usr/bin/chromedriver"
NAMESPACES = {"http://www.w3.org/2000/svg", "http://www.w3.org/1999/xhtml"}


def graphplan(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "graphplan", *args], cwd=ROOT, capture_output=True,
                          text=True, timeout=300)


@pytest.fixture(scope="module")
def pages(tmp_path_factory) -> dict[str, Path]:
    folder = tmp_path_factory.mktemp("view")
    out = {}
    for lang in ("uk", "en"):
        path = folder / f"shaper_{lang}.html"
        r = graphplan("view", str(SHAPER), "-o", str(path), "--lang", lang)
        assert r.returncode == 0, r.stderr
        out[lang] = path
    return out


def page_data(path: Path) -> dict:
    text = path.read_text(encoding="utf-8")
    m = re.search(r'<script id="explorer-data" type="application/json">(.*?)</script>', text, re.S)
    return json.loads(m.group(1).replace("<\\/", "</"))


# -- the file -----------------------------------------------------------------------------------------

def test_no_network_reference(pages):
    """Nothing a page could load: the only URIs are the SVG/XHTML namespaces; no src/href, no
    @import, no fetch; a Content-Security-Policy that forbids any load."""
    for path in pages.values():
        text = path.read_text(encoding="utf-8")
        uris = set(re.findall(r"[a-zA-Z][a-zA-Z0-9+.-]*://[^\s\"'<>)]*", text))
        assert uris <= NAMESPACES, uris - NAMESPACES
        assert not re.search(r"\b(src|href)\s*=", text, re.I)
        for word in ("@import", "fetch(", "XMLHttpRequest", "WebSocket", "<link", "<iframe", "<img"):
            assert word not in text
        assert "default-src 'none'" in text


def test_size_and_determinism(pages, tmp_path):
    size = pages["uk"].stat().st_size
    assert 50_000 < size < 3_000_000, size
    again = tmp_path / "again.html"
    assert graphplan("view", str(SHAPER), "-o", str(again), "--lang", "uk").returncode == 0
    assert again.read_bytes() == pages["uk"].read_bytes()


def test_bad_output_name_is_one_line(tmp_path):
    r = graphplan("view", str(SHAPER), "-o", str(tmp_path / "page.txt"))
    assert r.returncode == 2 and r.stderr.count("\n") == 1 and ".html" in r.stderr
    assert not (tmp_path / "page.txt").exists()
    for bad in (["view", str(tmp_path / "missing.toml")], ["view", str(SHAPER), "--step", "0"],
                ["view", str(SHAPER), "--precision", "-1"]):
        r = graphplan(*bad, "-o", str(tmp_path / "v.html"))
        assert r.returncode == 2 and r.stderr.count("\n") == 1 and "Traceback" not in r.stderr, r.stderr
        assert not (tmp_path / "v.html").exists()


def test_data_is_the_exact_solution_and_the_plans(pages):
    """The page's grid holds the exact solution (as `analyze --json` gives it) at every lab
    position, and its readings are the plans' (`plans --json`)."""
    data = page_data(pages["en"])
    analyzed = json.loads(graphplan("analyze", str(SHAPER), "--json").stdout)
    planned = json.loads(graphplan("plans", str(SHAPER), "--json").stdout)
    grid = data["grid"]
    for pos in analyzed["positions"]:
        i = min(range(len(grid["phi"])), key=lambda k: abs(grid["phi"][k] - pos["phi_deg"]))
        assert grid["phi"][i] == pytest.approx(pos["phi_deg"], abs=1e-6)
        c = pos["points"]["C"]
        assert grid["points"]["C"]["vx"][i] == pytest.approx(c["vx"], rel=1e-8, abs=1e-9)
        assert grid["links"]["OB"]["omega"][i] == pytest.approx(pos["links"]["OB"]["omega"], rel=1e-8, abs=1e-9)
    for pos in planned["positions"]:
        got = data["readings"][str(pos["index"])]
        assert got["v_C"][1] == pytest.approx(pos["velocity"]["C"]["value"], rel=1e-6)
        assert got["v_C"][0] == pos["velocity"]["C"]["mm"]
        if "acceleration" in pos:
            assert got["k_A"][1] == pytest.approx(pos["acceleration"]["k_A3A2"]["value"], rel=1e-6)


# -- the replay's order, as the textbook writes the groups' equations -----------------------------------

# the shaper: crank, then the RPR group (a_A3 = a_A2 + a^k + a^r = a_O + a^n + a^τ), then the RRP group
# (a_C = a_B + a^n_CB + a^τ_CB, a_C ∥ the guide)
SHAPER_ACCEL_ORDER = ["a_A =", "a^k_A3A2", "a^r_A3A2", "a^n_A3O", "a^τ_A3O", "a^n_CB", "a^τ_CB", "a_C"]


def in_order(captions: list[str], terms: list[str]) -> list[int]:
    """The index of the first caption naming each term, each after the previous one."""
    found, start = [], 0
    for term in terms:
        k = next(k for k in range(start, len(captions)) if term in captions[k])
        found.append(k)
        start = k + 1
    return found


def test_replay_steps_in_textbook_order(pages):
    data = page_data(pages["en"])
    rec = next(r for r in data["records"] if r["kind"] == "acceleration" and r["index"] == 1)
    captions = [s["caption"] for s in rec["steps"]]
    in_order(captions, SHAPER_ACCEL_ORDER)
    assert sum("Coriolis" in c for c in captions) == 1
    drawn = sorted(j for s in rec["steps"] for j in s["items"])
    shown = [j for j, it in enumerate(rec["items"]) if it[0] != "text" and it[2] != "pole"]
    assert drawn == shown          # every primitive drawn exactly once, by some step
    uk = next(r for r in page_data(pages["uk"])["records"] if r["kind"] == "acceleration")
    assert any("Коріоліса" in s["caption"] for s in uk["steps"])


@pytest.mark.parametrize("kind", ["RRR", "RRP", "RPR", "PRP", "RPP", "RRP moving", "RPP moving"])
def test_replay_of_every_group_kind(kind):
    """Random mechanisms of every group kind: each plan's replay draws every primitive once, words
    every step of a group (none falls back to the bare equation), names the point each direction
    line goes through, and relates each line to the link (⊥) or the guide (∥) as the term says."""
    from hypothesis import HealthCheck, given, settings
    from test_plans import assemblable, mechanisms
    from graphplan.report.explorer import explorer_data

    @settings(max_examples=4, deadline=None, suppress_health_check=list(HealthCheck))
    @given(scene=mechanisms()[kind])
    def run(scene):
        st = assemblable(*scene, kind)
        for rec in explorer_data(st, step=10.0, lang="en")["records"]:
            drawn = sorted(j for s in rec["steps"] for j in s["items"])
            assert drawn == [j for j, it in enumerate(rec["items"]) if it[0] != "text" and it[2] != "pole"]
            for s in rec["steps"]:
                assert s["caption"] != s["eq"]
                line = re.match(r"line (⊥ (\S+)|∥ the guide) through (\S+) \(the direction of (\S+)\)", s["caption"])
                if s["caption"].startswith("line"):
                    assert line and line.group(3) != "…", s["caption"]
                    sup, sub = re.match(r"[av](?:\^(\S))?_(\S+)", line.group(4)).groups()
                    # a relative slide (a^r, or two bodies' points at one place: A3A2) runs along the guide
                    along = sup == "r" or re.fullmatch(r"([A-Z]+)[\d_]+\1[\d_]*", sub) or s["eq"].endswith("∥ the guide") \
                        and line.group(4) == s["eq"].split(" =")[0]
                    assert (line.group(2) is None) == bool(along), s["caption"]
    run()


# -- in the browser ------------------------------------------------------------------------------------

def _browser_missing() -> str | None:
    try:
        import selenium  # noqa: F401
    except ImportError:
        return "selenium is not installed (pip install -e '.[test]')"
    for path in (CHROMIUM, DRIVER):
        if not (os.path.exists(path) or shutil.which(Path(path).name)):
            return f"{path} is missing (apt-get install chromium chromium-driver)"
    return None


@pytest.fixture(scope="module")
def driver():
    reason = _browser_missing()
    if reason:
        if os.environ.get("CI"):
            pytest.fail(f"browser tests cannot run in CI: {reason}")
        pytest.skip(reason)
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    opts = webdriver.ChromeOptions()
    opts.binary_location = CHROMIUM if os.path.exists(CHROMIUM) else shutil.which("chromium")
    for arg in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                "--window-size=1400,1800", "--no-first-run", "--disable-extensions",
                "--disable-background-networking", "--disable-component-update"):
        opts.add_argument(arg)
    opts.set_capability("goog:loggingPrefs", {"browser": "ALL", "performance": "ALL"})
    d = webdriver.Chrome(options=opts, service=Service(DRIVER if os.path.exists(DRIVER) else shutil.which("chromedriver")))
    yield d
    d.quit()


@pytest.fixture
def shots(tmp_path):
    """Save a screenshot to the test's folder and, when $GRAPHPLAN_SHOTS is set, copy it there."""
    def shot(d, name: str, element: str = "") -> Path:
        if element:
            d.execute_script("document.getElementById(arguments[0]).scrollIntoView()", element)
        path = tmp_path / f"{name}.png"
        d.save_screenshot(str(path))
        assert path.stat().st_size > 10_000
        if os.environ.get("GRAPHPLAN_SHOTS"):
            folder = Path(os.environ["GRAPHPLAN_SHOTS"])
            folder.mkdir(parents=True, exist_ok=True)
            shutil.copy(path, folder / path.name)
        return path
    return shot


def open_page(d, path: Path) -> None:
    d.get_log("browser")
    d.get_log("performance")       # forget what an earlier page logged
    d.get(path.resolve().as_uri())


def set_slider(d, phi: float) -> None:
    d.execute_script("const s = document.getElementById('phi'); s.value = arguments[0];"
                     "s.dispatchEvent(new Event('input', {bubbles: true}));", str(phi))


def cell(d, q: str, col: str) -> str:
    return d.find_element("css selector", f'[data-q="{q}"] td.{col}').text


def analyze_shown(phis: list[float], scene: Path = SHAPER, lang: str = "uk") -> dict[float, dict[str, str]]:
    """The values `graphplan analyze --phi` prints, as text, per angle: column name → cell (in the
    page's language: the decimal comma in Ukrainian)."""
    r = graphplan("analyze", str(scene), "--phi", *map(str, phis), "--lang", lang)
    assert r.returncode == 0, r.stderr
    out: dict[float, dict[str, str]] = {phi: {} for phi in phis}
    header: list[str] = []
    for line in r.stdout.splitlines():
        cells = line.split()
        if cells[:2] in (["No", "φ,"], ["№", "φ,"]):
            header = cells[3:]
        elif header and len(cells) == len(header) + 2 and cells[0].isdigit():
            out[phis[int(cells[0])]].update(zip(header, cells[2:]))
        elif not cells:
            header = []
    return out


def check_clean(d, url: str) -> None:
    """No console error, no request but the page itself."""
    severe = [e for e in d.get_log("browser") if e["level"] in ("SEVERE", "ERROR")]
    assert not severe, severe
    urls = []
    for entry in d.get_log("performance"):
        msg = json.loads(entry["message"])["message"]
        if msg["method"] in ("Network.requestWillBeSent", "Network.webSocketCreated"):
            urls.append(msg["params"].get("request", {}).get("url") or msg["params"].get("url"))
    assert urls and set(urls) == {url}, urls


PHIS = [37.0, 142.0, 268.0]


def test_slider_values_equal_analyze(driver, pages, shots):
    """At three angles set with the slider the ram's velocity v_C and the rocker's ω_OB shown on
    the page are what `graphplan analyze --phi` prints, digit for digit."""
    open_page(driver, pages["uk"])
    shown = analyze_shown(PHIS)
    for phi in PHIS:
        set_slider(driver, phi)
        assert float(driver.find_element("id", "phi-value").get_attribute("data-phi")) == phi
        assert cell(driver, "v_C", "exact") == shown[phi]["v_C"]
        assert cell(driver, "omega_OB", "exact") == shown[phi]["ω_OB"]
        assert cell(driver, "a_C", "exact") == shown[phi]["a_C"]
        # and every other quantity both show, to the digit
        names = {"ω_": "omega_", "ε_": "epsilon_"}
        compared = 0
        for column, text in shown[phi].items():
            q = names.get(column[:2], column[:2]) + column[2:]
            found = driver.find_elements("css selector", f'[data-q="{q}"] td.exact')
            if found:
                assert found[0].text == text, (phi, column)
                compared += 1
        assert compared >= 14
        assert cell(driver, "v_C", "graphical") == ""      # no plan was drawn at this angle
        shots(driver, f"slider_{phi:g}")
    check_clean(driver, pages["uk"].resolve().as_uri())


def test_lab_position_shows_the_plan_reading(driver, pages, shots):
    """At a lab position the table adds the plan's reading and its percent error (`plans --json`)."""
    planned = json.loads(graphplan("plans", str(SHAPER), "--json").stdout)
    pos = planned["positions"][1]
    open_page(driver, pages["en"])
    driver.find_element("css selector", '#lab-positions button[data-key="1"]').click()
    v = pos["velocity"]["C"]
    got = driver.find_element("css selector", '[data-q="v_C"] td.graphical')
    assert float(got.get_attribute("data-value")) == pytest.approx(v["value"], rel=1e-6)
    assert f"({v['mm']:.1f} mm)" in got.text
    assert cell(driver, "v_C", "error") == f"{v['error_pct']:.2f}"
    rel = driver.find_element("css selector", '[data-q="vrel_A"] td.graphical')      # the block in the slot
    exact = float(driver.find_element("css selector", '[data-q="vrel_A"] td.exact').get_attribute("data-value"))
    assert float(rel.get_attribute("data-value")) == pytest.approx(
        math.copysign(pos["velocity"]["A3A2"]["value"], exact), rel=1e-6)
    k = pos["acceleration"]["k_A3A2"]
    assert cell(driver, "k_A", "error") == f"{k['error_pct']:.2f}"
    # the graphical plans are drawn over the exact ones
    assert driver.execute_script("return document.querySelectorAll('#vplan .g-vec').length") > 5
    assert driver.execute_script("return document.querySelectorAll('#aplan .g-vec').length") > 5
    shots(driver, "lab_position_1")
    check_clean(driver, pages["en"].resolve().as_uri())


def test_replay_of_the_acceleration_plan(driver, pages, shots):
    """Forward through the shaper's acceleration plan: each component in the textbook's order,
    one Coriolis step, the current step drawn highlighted; back returns to the previous caption."""
    open_page(driver, pages["en"])
    select = driver.find_element("id", "replay-plan")
    assert "acceleration plan, position 1" in select.find_element("css selector", "option:checked").text
    total = len(driver.find_elements("css selector", "#step-list li"))
    captions = []
    for k in range(total):
        captions.append(driver.find_element("id", "step-caption").text)
        assert driver.execute_script("return document.querySelectorAll('#replay .hl').length") >= 1
        assert driver.find_element("css selector", "#step-list li.current").get_attribute("data-step") == str(k)
        if "Coriolis" in captions[-1]:
            shots(driver, "replay_coriolis", "replay-section")
        driver.find_element("id", "step-next").click()
    order = in_order(captions, SHAPER_ACCEL_ORDER)
    assert "Coriolis" in captions[order[1]]
    assert driver.find_element("id", "step-caption").text == captions[-1]      # stays at the end
    shots(driver, "replay_end", "replay-section")
    driver.find_element("id", "step-back").click()
    assert driver.find_element("id", "step-caption").text == captions[-2]
    check_clean(driver, pages["en"].resolve().as_uri())


def test_play_moves_the_mechanism_and_the_cursor(driver, pages, shots):
    open_page(driver, pages["uk"])
    before = driver.find_element("id", "phi-value").get_attribute("data-phi")
    x0 = driver.find_element("id", "diagram-cursor").get_attribute("x1")
    driver.find_element("id", "play").click()
    driver.implicitly_wait(0)
    import time
    time.sleep(0.6)
    driver.find_element("id", "play").click()
    after = driver.find_element("id", "phi-value").get_attribute("data-phi")
    assert float(after) > float(before) or float(after) < float(before) - 180    # ccw: φ grows
    assert driver.find_element("id", "diagram-cursor").get_attribute("x1") != x0
    shots(driver, "played", "diagrams-section")
    check_clean(driver, pages["uk"].resolve().as_uri())


# -- the gallery's explorers -----------------------------------------------------------------------------

def test_gallery_explorers_are_current():
    from graphplan.cli.gallery import EXPLORERS, explorer
    for scene in EXPLORERS:
        path = ROOT / "drawings" / f"{scene}.html"
        assert path.exists(), f"drawings/{scene}.html is missing: run python -m graphplan.cli.gallery"
        assert path.stat().st_size < 400_000
        assert path.read_text(encoding="utf-8") == explorer(scene), \
            f"drawings/{scene}.html is out of date: run python -m graphplan.cli.gallery"


@pytest.mark.parametrize("scene", ["crank_slider", "lab_crank_slider", "four_bar", "shaper", "slotter"])
def test_gallery_explorer_runs(driver, scene, shots):
    """Every example's page works: angles around the turn, every plan replayed to its end, the
    exact column equal to `analyze` for the output point, no error, no request."""
    path = ROOT / "drawings" / f"{scene}.html"
    open_page(driver, path)
    out = page_data(path)["scheme"]["output"]["point"]
    shown = analyze_shown([10.0, 200.0], ROOT / "examples" / f"{scene}.toml")
    for phi in (10.0, 200.0):
        set_slider(driver, phi)
        assert cell(driver, f"v_{out}", "exact") == shown[phi][f"v_{out}"]
    options = driver.find_elements("css selector", "#replay-plan option")
    assert len(options) >= 2
    for option in options[-2:]:
        option.click()
        driver.find_element("id", "step-last").click()
        last = driver.find_elements("css selector", "#step-list li")[-1]
        assert "current" in last.get_attribute("class")
    shots(driver, f"gallery_{scene}", "replay-section")
    check_clean(driver, path.resolve().as_uri())


def test_notebook_frame_holds_the_same_page():
    """explorer_iframe (for a notebook's _repr_html_) carries explorer_html's page, escaped."""
    import html as html_
    from graphplan.exact.positions import study
    from graphplan.model.scene import load
    from graphplan.report.explorer import explorer_html, explorer_iframe
    st = study(load(SHAPER))
    frame = explorer_iframe(st, lang="en", step=5.0)
    page = re.fullmatch(r'<iframe srcdoc="(.*)" style=.*></iframe>', frame, re.S).group(1)
    assert html_.unescape(page) == explorer_html(st, lang="en", step=5.0)
