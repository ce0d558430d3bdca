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
    """A run of the command line with a hang guard (not a speed bound: `plans --json` of a generated
    mechanism took over 300 s of wall time at a load average of 33 on two cores, stop 58)."""
    return subprocess.run([sys.executable, "-m", "graphplan", *args], cwd=ROOT, capture_output=True,
                          text=True, timeout=1800)


@pytest.fixture(scope="module")
def pages(tmp_path_factory) -> dict[str, Path]:
    """The shaper's page in either language, written by the command (``main``) in the worker: the same
    files byte for byte as two ``python -m graphplan view`` processes, for 3.7 s of CPU instead of 7.3
    (the second language reads the compositions the first remembered; the commands' own runs are
    tested below)."""
    from graphplan.cli.main import main
    folder = tmp_path_factory.mktemp("view")
    out = {}
    for lang in ("uk", "en"):
        path = folder / f"shaper_{lang}.html"
        assert main(["view", str(SHAPER), "-o", str(path), "--lang", lang]) == 0
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
SHAPER_ACCEL_ORDER = ["a_A =", "a^k_{A3A2}", "a^n_{A3O}", "direction of a^r_A3A2", "direction of a^τ_A3O",
                      "cross at a_3", "a^n_{CB}", "direction of a^τ_CB", "direction of a_C", "cross at c"]


def in_order(captions: list[str], terms: list[str]) -> list[int]:
    """The index of the first caption naming each term, each after the previous one."""
    found, start = [], 0
    for term in terms:
        k = next(k for k in range(start, len(captions)) if term in captions[k])
        found.append(k)
        start = k + 1
    return found


def textbook_order(rec: dict) -> None:
    """The replay of one plan draws as a student does (issue 25): every primitive once; a point is
    lettered at the step that finds it and no vector reaches a point before it is lettered; a group's
    two direction lines are drawn, each in full, before the step that marks their intersection, and
    the found vectors come after it."""
    drawn = sorted(j for s in rec["steps"] for j in s["items"])
    assert drawn == [j for j, it in enumerate(rec["items"]) if it[0] != "text" and it[2] != "pole"]
    step_of = {j: k for k, s in enumerate(rec["steps"]) for j in s["items"]}
    lettered = {name: (x, y, k) for name, x, y, k in rec["points"]}
    for j, it in enumerate(rec["items"]):
        if it[0] != "vector":
            continue
        tip = (it[1][2], it[1][3])
        there = [(k, name) for name, (x, y, k) in lettered.items() if math.hypot(tip[0] - x, tip[1] - y) < 1e-3]
        # a vector reaches a place only where some point is lettered by then (points may coincide)
        assert not there or min(there)[0] <= step_of[j], (rec["kind"], rec["key"], there, step_of[j])
    for k, s in enumerate(rec["steps"]):
        if not s.get("meet"):
            continue
        name = s["meet"][0]
        assert lettered[name][2] == k, (name, lettered[name], k)
        lines = [i for i in range(k) if rec["steps"][i].get("line")]
        assert len(lines) >= 2 and lines[-1] == k - 1, (rec["key"], k, lines)
        for i in lines[-2:]:
            (item,) = rec["steps"][i]["items"]
            kind, f, role = rec["items"][item][:3]
            assert kind == "segment" and role == "direction"
            a, b = complex(f[0], f[1]), complex(f[2], f[3])
            at = complex(s["meet"][1], s["meet"][2])
            # drawn through the intersection and on past it (in full), not stopped at the point
            assert abs(((at - a) / (b - a)).imag) * abs(b - a) < 0.01
            assert min(abs(at - a), abs(at - b)) > 3.0
        found = rec["steps"][k + 1]
        assert found["caption"]["en"].startswith("The found vectors") or not found["items"]


def test_replay_steps_in_textbook_order(pages):
    data = page_data(pages["en"])
    rec = next(r for r in data["records"] if r["kind"] == "acceleration" and r["index"] == 1)
    captions = [s["caption"]["en"] for s in rec["steps"]]
    in_order(captions, SHAPER_ACCEL_ORDER)
    assert sum("Coriolis" in c for c in captions) == 1
    assert any("Коріоліса" in s["caption"]["uk"] for s in rec["steps"])
    for r in data["records"]:
        textbook_order(r)


@pytest.mark.parametrize("scene", ["crank_slider", "lab_crank_slider", "four_bar", "slotter"])
def test_every_plan_of_the_examples_is_replayed_in_textbook_order(scene):
    """Every plan the page offers, for a crank-slider, the four-bar and the slotter (the shaper above):
    the four-bar's a^τ_CB is no longer drawn to c before the second line is; the shaper's dead
    centre finds b before a line goes through it."""
    from graphplan.exact.positions import study
    from graphplan.model.scene import load
    from graphplan.report.explorer import explorer_data
    for rec in explorer_data(study(load(ROOT / "examples" / f"{scene}.toml")), step=10.0, lang="en")["records"]:
        textbook_order(rec)


def test_dead_centre_finds_every_point_it_draws_through():
    """The shaper's velocity plan 0 (a dead centre): b is found (by similarity, at the pole) before
    the line ⊥ CB goes through it, and the points at the pole are lettered one by one."""
    from graphplan.exact.positions import study
    from graphplan.model.scene import load
    from graphplan.report.explorer import explorer_data
    rec = next(r for r in explorer_data(study(load(SHAPER)), step=10.0, lang="en")["records"]
               if r["kind"] == "velocity" and r["index"] == 0)
    captions = [s["caption"]["en"] for s in rec["steps"]]
    b = next(k for k, c in enumerate(captions) if c.startswith("b by similarity"))
    line = next(k for k, c in enumerate(captions) if c.startswith("Through b draw"))
    assert b < line
    steps = sorted(k for name, _, _, k in rec["points"] if name != "p_v")
    assert len(set(steps)) == len(steps)          # no two points lettered at one step (no pile of labels)


@pytest.mark.parametrize("kind", ["RRR", "RRP", "RPR", "PRP", "RPP", "RRP moving", "RPP moving"])
def test_replay_of_every_group_kind(kind):
    """Random mechanisms of every group kind: each plan's replay is in the textbook's order; every
    direction line names the point it goes through and relates to the link (⊥) or the guide (∥)
    as its term says."""
    from hypothesis import HealthCheck, given, settings
    from test_plans import assemblable, mechanisms
    from graphplan.report.explorer import explorer_data

    @settings(max_examples=4, deadline=None, suppress_health_check=list(HealthCheck))
    @given(scene=mechanisms()[kind])
    def run(scene):
        st = assemblable(*scene, kind)
        for rec in explorer_data(st, step=10.0, lang="en")["records"]:
            textbook_order(rec)
            for s in rec["steps"]:
                c = s["caption"]["en"]
                m = re.match(r"Through (\S+) draw a line (perpendicular to (\S+)|parallel to the (link|guide of) (\S+)): "
                             r"the direction of (\S+)$", c)
                if c.startswith("Through"):
                    assert m, c
                    sup, sub = re.match(r"[av](?:\^(\S))?_\{?([^{}]+)\}?", m.group(6)).groups()
                    along = sup == "r" or re.fullmatch(r"([A-Z]+)[\d_]+\1[\d_]*", sub) or (
                        m.group(4) == "guide of" and sup is None)
                    assert (m.group(3) is None) == bool(along), c
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


@pytest.fixture
def driver(request):
    """The worker's one Chromium (conftest's ``chromium``) on a clean tab of 1400 × 1800 for each test."""
    reason = _browser_missing()
    if reason:
        if os.environ.get("CI"):
            pytest.fail(f"browser tests cannot run in CI: {reason}")
        pytest.skip(reason)
    from conftest import browser_tab
    return browser_tab(request.getfixturevalue("chromium"), 1400, 1800)


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
    """The slider set to the crank angle φ: it runs over the turn from position 0 (the diagrams'
    convention), so φ is turned into that first."""
    d.execute_script("const s = document.getElementById('phi');"
                     "s.value = String(window.graphplanExplorer.turnOf(arguments[0]));"
                     "s.dispatchEvent(new Event('input', {bubbles: true}));", phi)


def cell(d, q: str, col: str) -> str:
    """A cell's text with the page's minus sign (U+2212) written as the terminal writes it."""
    return d.find_element("css selector", f'[data-q="{q}"] td.{col}').text.replace("−", "-")


def analyze_shown(phis: list[float], scene: Path = SHAPER, lang: str = "uk") -> dict[float, dict[str, str]]:
    """The values `graphplan analyze --phi` prints, as text, per angle: column name → cell (in the
    page's language: the decimal comma in Ukrainian)."""
    r = graphplan("analyze", str(scene), "--phi", *map(str, phis), "--lang", lang)
    assert r.returncode == 0, r.stderr
    out: dict[float, dict[str, str]] = {phi: {} for phi in phis}
    header: list[str] = []
    for line in r.stdout.splitlines():
        cells = line.split()
        if cells[:2] in (["No.", "φ,"], ["№", "φ,"]):
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


def on_grid(path: Path, phis: list[float]) -> list[float]:
    """The page's grid angles nearest to ``phis`` (the grid runs every step of the turn from
    position 0)."""
    grid = page_data(path)["grid"]["phi"]
    return [min(grid, key=lambda g: abs((g - phi + 180) % 360 - 180)) for phi in phis]


def test_slider_values_equal_analyze(driver, pages, shots):
    """At three angles set with the slider the ram's velocity v_C and the rocker's ω_OB shown on
    the page are what `graphplan analyze --phi` prints, digit for digit."""
    open_page(driver, pages["uk"])
    phis = on_grid(pages["uk"], PHIS)
    shown = analyze_shown(phis)
    for phi in phis:
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
                assert found[0].text.replace("−", "-") == text, (phi, column)
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
    """Forward through the shaper's acceleration plan: each component in the textbook's order, one
    Coriolis step, the current step's lines drawn highlighted and the intersection marked; back
    returns to the previous caption; a click on a step of the list goes there."""
    open_page(driver, pages["en"])
    select = driver.find_element("id", "replay-plan")
    assert "acceleration plan, position 1" in select.find_element("css selector", "option:checked").text
    total = len(driver.find_elements("css selector", "#step-list li"))
    captions = []
    for k in range(total):
        captions.append(driver.find_element("id", "step-caption").text)
        marked = driver.execute_script("return document.querySelectorAll('#replay .hl, #replay .meet').length")
        assert marked >= 1, captions[-1]
        assert driver.find_element("css selector", "#step-list li.current").get_attribute("data-step") == str(k)
        if "Coriolis" in captions[-1]:
            shots(driver, "replay_coriolis", "replay-section")
        driver.find_element("id", "step-next").click()
    order = in_order(captions, ["aA =", "akA3A2", "anA3O", "direction of arA3A2", "direction of aτA3O", "cross at a3"])
    assert "Coriolis" in captions[order[1]]
    assert driver.find_element("id", "step-caption").text == captions[-1]      # stays at the end
    driver.find_element("id", "step-back").click()
    assert driver.find_element("id", "step-caption").text == captions[-2]
    driver.find_elements("css selector", "#step-list li button")[2].click()
    assert driver.find_element("id", "step-count").get_attribute("data-step") == "2"
    check_clean(driver, pages["en"].resolve().as_uri())


REPLAY_WALK = """
const out = [];
const sel = document.getElementById('replay-plan');
for (let k = 0; k < sel.options.length; k++) {
  sel.value = String(k);
  sel.dispatchEvent(new Event('change', {bubbles: true}));
  document.getElementById('step-first').click();
  const n = document.querySelectorAll('#step-list li').length;
  const steps = [];
  for (let s = 0; s < n; s++) {
    const labels = Array.from(document.querySelectorAll('#replay-labels text')).map((t) => t.textContent);
    const tips = Array.from(document.querySelectorAll('#replay g.g-vec line')).map((l) =>
      [parseFloat(l.getAttribute('x2')), -parseFloat(l.getAttribute('y2'))]);
    steps.push([labels, tips]);
    document.getElementById('step-next').click();
  }
  out.push(steps);
}
return out;
"""


def flat(name: str) -> str:
    return re.sub(r"[_^{}]", "", name)


@pytest.mark.parametrize("scene", ["crank_slider", "four_bar", "shaper", "slotter"])
def test_the_page_replays_every_plan_in_textbook_order(driver, scene, tmp_path):
    """Walked through in the browser, step by step, for every plan the page offers: the letters on
    the drawing are exactly the points found so far, and no vector reaches a point before it is
    lettered (the four-bar's τ component used to reach c two steps before c's second line)."""
    path = tmp_path / f"{scene}.html"
    assert graphplan("view", str(ROOT / "examples" / f"{scene}.toml"), "-o", str(path), "--lang", "en").returncode == 0
    open_page(driver, path)
    # the walk over every step of every plan is one script: selenium's 30-s default cut the slotter's
    # (the most steps) at load 20 on two cores (stop 56's slow run); the walk, not its speed, is tested
    driver.set_script_timeout(600)
    walked = driver.execute_script(REPLAY_WALK)
    records = page_data(path)["records"]
    assert len(walked) == len(records)
    for rec, steps in zip(records, walked):
        assert len(steps) == len(rec["steps"])
        for k, (labels, tips) in enumerate(steps):
            expected = sorted(flat(n) for n, _, _, s in rec["points"] if s <= k)
            assert sorted(labels) == expected, (rec["kind"], rec["key"], k)
            for x, y in tips:
                near = [s for n, px, py, s in rec["points"] if math.hypot(px - x, py - y) < 0.01]
                assert not near or min(near) <= k, (rec["kind"], rec["key"], k, (x, y))
    check_clean(driver, path.resolve().as_uri())


def test_keyboard(driver, pages):
    """One grid step per arrow key on the slider, Home/End to the first and last lab positions, Space
    plays and pauses; in the replay ← → step the construction."""
    from selenium.webdriver.common.keys import Keys
    open_page(driver, pages["en"])
    data = page_data(pages["en"])
    step = data["step"]
    slider = driver.find_element("id", "phi")
    turn = lambda: float(driver.find_element("id", "turn-value").get_attribute("data-turn"))  # noqa: E731
    slider.send_keys(Keys.HOME)
    assert turn() == 0 and driver.find_element("id", "lab-now").text == "position 0"
    slider.send_keys(Keys.ARROW_RIGHT)
    assert turn() == pytest.approx(step, abs=1e-6)
    slider.send_keys(Keys.ARROW_RIGHT, Keys.ARROW_RIGHT, Keys.ARROW_LEFT)
    assert turn() == pytest.approx(2 * step, abs=1e-6)
    slider.send_keys(Keys.END)
    assert driver.find_element("id", "lab-now").text == "position 11"
    assert turn() == pytest.approx(330.0, abs=1e-6)
    driver.find_element("tag name", "body").send_keys(Keys.SPACE)
    assert driver.find_element("id", "play").get_attribute("aria-pressed") == "true"
    import time
    time.sleep(0.3)
    driver.find_element("tag name", "body").send_keys(Keys.SPACE)
    assert driver.find_element("id", "play").get_attribute("aria-pressed") == "false"
    assert turn() != pytest.approx(330.0, abs=1e-6)
    count = driver.find_element("id", "step-count")
    driver.find_element("id", "step-first").click()
    driver.find_element("id", "step-first").send_keys(Keys.ARROW_RIGHT)
    assert count.get_attribute("data-step") == "1"
    driver.find_element("id", "step-first").send_keys(Keys.ARROW_RIGHT, Keys.ARROW_RIGHT, Keys.ARROW_LEFT)
    assert count.get_attribute("data-step") == "2"
    check_clean(driver, pages["en"].resolve().as_uri())


def _viewport(d, width: int, height: int) -> None:
    d.execute_cdp_cmd("Emulation.setDeviceMetricsOverride",
                      {"width": width, "height": height, "deviceScaleFactor": 1, "mobile": width < 600})


@pytest.mark.parametrize("size", [(390, 844), (800, 900), (1920, 1200)])
def test_the_page_fits_the_window(driver, pages, size, shots):
    """No sideways scroll on a phone or at 800 px; at 1920 px the largest drawing takes ≥ 40 % of the
    width; the drawings' letters are at least 11 px high; buttons at least 36 px."""
    _viewport(driver, *size)
    try:
        open_page(driver, pages["uk"])
        widths = driver.execute_script("return [document.documentElement.scrollWidth, document.documentElement.clientWidth]")
        assert widths[0] <= widths[1], widths
        widest = driver.execute_script("return Math.max(...Array.from(document.querySelectorAll('svg')).map((s) => s.getBoundingClientRect().width))")
        if size[0] >= 1900:
            assert widest >= 0.4 * size[0], widest
        letters = driver.execute_script(
            "return Array.from(document.querySelectorAll('#mech text, #vplan text, #replay text'))"
            ".map((t) => parseFloat(getComputedStyle(t).fontSize) * t.getScreenCTM().a)")
        assert letters and min(letters) >= 11 - 1e-6, min(letters)
        heights = driver.execute_script("return Array.from(document.querySelectorAll('#controls button')).map((b) => b.getBoundingClientRect().height)")
        assert min(heights) >= 36 - 0.5
        shots(driver, f"window_{size[0]}")
        check_clean(driver, pages["uk"].resolve().as_uri())
    finally:
        driver.execute_cdp_cmd("Emulation.clearDeviceMetricsOverride", {})


def test_the_language_switch(driver, pages):
    """Українська ↔ English in the page: the title, the captions, the replay and the decimal sign."""
    open_page(driver, pages["uk"])
    data = page_data(pages["uk"])
    assert driver.find_element("id", "title").text == data["title"]["uk"]
    driver.find_element("css selector", '#langs button[data-lang="en"]').click()
    assert driver.find_element("id", "title").text == data["title"]["en"]
    assert driver.execute_script("return document.documentElement.lang") == "en"
    assert driver.find_element("id", "cap-replay").text == "The construction, step by step"
    assert "acceleration plan" in driver.find_element("css selector", "#replay-plan option:checked").text
    assert "." in driver.find_element("css selector", '[data-q="v_A"] td.exact').text
    driver.find_element("css selector", '#langs button[data-lang="uk"]').click()
    assert driver.find_element("id", "cap-replay").text == "Побудова крок за кроком"
    assert "," in driver.find_element("css selector", '[data-q="v_A"] td.exact').text
    check_clean(driver, pages["uk"].resolve().as_uri())


def test_the_self_check_gives_the_terminals_error(driver, pages):
    """At lab position 1 a student types the lengths graphplan read: the page's percent errors are
    `plans --json`'s, digit for digit (2 decimals), and a length of their own gives its own error."""
    planned = json.loads(graphplan("plans", str(SHAPER), "--json").stdout)
    pos = next(p for p in planned["positions"] if p["index"] == 1)
    open_page(driver, pages["en"])
    from selenium.webdriver.support.ui import Select
    Select(driver.find_element("id", "check-position")).select_by_value("1")
    checked = 0
    for plan, entries in (("velocity", pos["velocity"]), ("acceleration", pos["acceleration"])):
        for key, e in entries.items():
            rows = driver.find_elements("css selector", f'#check tr[data-entry="{plan}:{key}"]')
            if not rows or e.get("mm") is None or e.get("error_pct") is None:
                continue
            box = rows[0].find_element("tag name", "input")
            box.clear()
            box.send_keys(f"{e['mm']:g}")
            err = rows[0].find_element("css selector", "td.error")
            assert err.text == f"{e['error_pct']:.2f}".replace("-", "−"), (plan, key)
            checked += 1
    assert checked >= 10
    row = driver.find_element("css selector", '#check tr[data-entry="velocity:C"]')
    box = row.find_element("tag name", "input")
    box.clear()
    box.send_keys("40")
    exact = pos["velocity"]["C"]["analytic"]
    mu = planned["positions"][0]["mu_v"]
    assert float(row.find_element("css selector", "td.error").get_attribute("data-value")) == pytest.approx(
        100 * (40 * mu - abs(exact)) / abs(exact), rel=1e-9)
    check_clean(driver, pages["en"].resolve().as_uri())


def test_choosing_a_plan_moves_the_mechanism(driver, pages):
    """A plan chosen in the replay turns the mechanism to its position (and the return button brings
    the angle back); a lab position's button turns the replay to that position's plan; a click on
    the diagrams seeks the angle there."""
    from selenium.webdriver.support.ui import Select
    open_page(driver, pages["en"])
    data = page_data(pages["en"])
    before = driver.find_element("id", "phi-value").get_attribute("data-phi")
    k = next(i for i, r in enumerate(data["records"]) if r["kind"] == "velocity" and r["index"] == 5)
    Select(driver.find_element("id", "replay-plan")).select_by_value(str(k))
    assert float(driver.find_element("id", "phi-value").get_attribute("data-phi")) == pytest.approx(data["records"][k]["phi"])
    assert driver.find_element("id", "lab-now").text == "position 5"
    driver.find_element("id", "replay-return").click()
    assert driver.find_element("id", "phi-value").get_attribute("data-phi") == before
    driver.find_element("css selector", '#lab-positions button[data-key="8"]').click()
    assert "velocity plan, position 8" in driver.find_element("css selector", "#replay-plan option:checked").text
    svg = driver.find_element("id", "diagrams")
    from selenium.webdriver.common.action_chains import ActionChains
    box = driver.execute_script("const r = document.getElementById('diagrams').getBoundingClientRect();"
                                "const m = document.getElementById('diagrams').getScreenCTM();"
                                "return [r.width, r.height, m.a, m.e - r.left];")
    x0, w = (float(svg.get_attribute(a)) for a in ("data-x0", "data-width"))     # the axis of the turn, 0…360°
    x = box[3] + box[2] * (x0 + w / 2)      # 180° of the turn
    ActionChains(driver).move_to_element_with_offset(svg, x - box[0] / 2, 0).click().perform()
    assert float(driver.find_element("id", "turn-value").get_attribute("data-turn")) == pytest.approx(180.0, abs=1.01)
    check_clean(driver, pages["en"].resolve().as_uri())


def test_play_moves_the_mechanism_and_the_cursor(driver, pages, shots):
    open_page(driver, pages["uk"])
    before = driver.find_element("id", "turn-value").get_attribute("data-turn")
    x0 = driver.find_element("id", "diagram-cursor").get_attribute("x1")
    driver.find_element("id", "play").click()
    import time
    time.sleep(0.6)
    driver.find_element("id", "play").click()
    after = driver.find_element("id", "turn-value").get_attribute("data-turn")
    assert float(after) > float(before)
    assert driver.find_element("id", "diagram-cursor").get_attribute("x1") != x0
    shots(driver, "played", "diagrams-section")
    check_clean(driver, pages["uk"].resolve().as_uri())


def test_without_javascript_the_page_says_so(pages):
    text = pages["uk"].read_text(encoding="utf-8")
    m = re.search(r"<noscript>(.*?)</noscript>", text, re.S)
    assert m and "JavaScript" in m.group(1) and "увімкніть" in m.group(1) and "turn it on" in m.group(1)


# -- the gallery's explorers -----------------------------------------------------------------------------

def test_gallery_explorers_are_current():
    from graphplan.cli.gallery import EXPLORERS, explorer
    for scene in EXPLORERS:
        path = ROOT / "drawings" / f"{scene}.html"
        assert path.exists(), f"drawings/{scene}.html is missing: run python -m graphplan.cli.gallery"
        assert path.stat().st_size < 500_000        # both languages' words in one offline file
        assert path.read_text(encoding="utf-8") == explorer(scene), \
            f"drawings/{scene}.html is out of date: run python -m graphplan.cli.gallery"


@pytest.mark.parametrize("scene", ["crank_slider"] + [pytest.param(s, marks=pytest.mark.slow) for s in
                                   ("lab_crank_slider", "four_bar", "shaper", "slotter")])   # the walk covers them
def test_gallery_explorer_runs(driver, scene, shots):
    """Every example's page works: angles around the turn, every plan replayed to its end, the
    exact column equal to `analyze` for the output point, no error, no request."""
    path = ROOT / "drawings" / f"{scene}.html"
    open_page(driver, path)
    out = page_data(path)["scheme"]["output"]["point"]
    phis = on_grid(path, [10.0, 200.0])
    shown = analyze_shown(phis, ROOT / "examples" / f"{scene}.toml")
    for phi in phis:
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


def element_shot(d, element: str, path: Path) -> None:
    """A PNG of one element whole, as laid out (Chrome's DevTools capture, beyond the viewport too)."""
    import base64
    r = d.execute_script("const r = document.getElementById(arguments[0]).getBoundingClientRect();"
                         "return [r.x + window.scrollX, r.y + window.scrollY, r.width, r.height];", element)
    png = d.execute_cdp_cmd("Page.captureScreenshot", {"format": "png", "captureBeyondViewport": True,
                            "clip": {"x": r[0], "y": r[1], "width": r[2], "height": r[3], "scale": 1}})
    path.write_bytes(base64.b64decode(png["data"]))


def keep_picture(shot: Path, name: str) -> None:
    """A test's picture kept for the docs when $GRAPHPLAN_SHOTS is set (64 colours keep it small)."""
    if os.environ.get("GRAPHPLAN_SHOTS"):
        folder = Path(os.environ["GRAPHPLAN_SHOTS"])
        folder.mkdir(parents=True, exist_ok=True)
        from PIL import Image              # matplotlib's
        Image.open(shot).convert("RGB").quantize(64).save(folder / f"{name}.png", optimize=True)


def test_replay_pictures_for_the_docs(driver, tmp_path):
    """The four-bar's acceleration plan replayed from a blank sheet in the browser at 1366×900, the replay
    section photographed at the steps docs/view.md's walk-through shows (GRAPHPLAN_SHOTS=docs/view keeps
    them): step 0 the pole and the scale, the group's marked equation, the known vector, the first and the
    second direction line (the mechanism beside with the link and its line), the intersection, the found
    vectors, a point by similarity, ε at the end. At each the caption says the rule and the point b is
    lettered only from the intersection on."""
    path = tmp_path / "four_bar.html"
    assert graphplan("view", str(ROOT / "examples" / "four_bar.toml"), "-o", str(path), "--lang", "en").returncode == 0
    driver.set_window_size(1366, 900)
    open_page(driver, path)
    records = page_data(path)["records"]
    k = next(i for i, r in enumerate(records) if r["kind"] == "acceleration")
    driver.execute_script("const s = document.getElementById('replay-plan'); s.value = String(arguments[0]);"
                          "s.dispatchEvent(new Event('change', {bubbles: true}));", k)
    driver.find_element("id", "step-first").click()
    steps = records[k]["steps"]
    found_at = {n: s for n, _, _, s in records[k]["points"]}
    meet = next(i for i, s in enumerate(steps) if s.get("meet"))
    lines = [i for i, s in enumerate(steps) if s.get("line") and i < meet][-2:]
    equation = next(i for i, s in enumerate(steps) if s.get("equation"))
    similar = next(i for i, s in enumerate(steps) if " by similarity" in s["caption"]["en"])
    rate = next(i for i, s in enumerate(steps) if s.get("rate"))
    wanted = {0: "scale", 1: "known", equation: "equation", lines[0]: "line_1", lines[1]: "line_2", meet: "meet",
              meet + 1: "found", similar: "similar", rate: "epsilon"}
    seen = {}
    for i in range(len(steps)):
        if i in wanted:
            caption = driver.find_element("id", "step-caption").text
            labels = [t.text for t in driver.find_elements("css selector", "#replay-labels text")]
            point = steps[meet]["meet"][0]
            assert (flat(point) in labels) == (i >= found_at[point]), (i, labels)
            seen[wanted[i]] = caption
            shot = tmp_path / f"replay_{i:02d}_{wanted[i]}.png"
            element_shot(driver, "replay-section", shot)
            assert shot.stat().st_size > 5_000
            keep_picture(shot, f"replay_{wanted[i]}")
        driver.find_element("id", "step-next").click()
    assert seen["scale"].startswith("Step 0: the pole and the scale")
    assert "Underlined twice" in seen["equation"]
    assert "perpendicular" in seen["line_1"] and "perpendicular" in seen["line_2"]
    assert "cross" in seen["meet"] and "found" in seen["found"].lower()
    assert "the ratio" in seen["similar"] and "Carried to the point" in seen["epsilon"]
    driver.set_window_size(1366, 768)
    driver.execute_script("window.scrollTo(0, 0)")
    shot = tmp_path / "window.png"
    driver.save_screenshot(str(shot))
    keep_picture(shot, "window_1366")
