"""The explorer as a tutor (issue 34), in Debian's chromium through selenium, one browser for the
module: the page at a phone's, a laptop's and a wide screen's size (no sideways scroll, lettering
11–16 px, contrast ≥ 4.5:1, no e-notation, one minus sign, no word broken in a table, the slider with
the mechanism and both plans in one screen at 1366×768, ◀ ▶ on one row on a phone); every control by
keyboard (Space ticks a checkbox; + − and the arrows zoom and pan a drawing; the arrows seek on the
diagrams); the step list follows the current step, its numbers at the first line of a step; the
per-angle scale says its μ; the mechanism's letters clear of the joints and the ground.

Step 0 (the pole and the scale), the marked vector equation, the mechanism beside the replay, ω and ε
at the end and the cam are tested further down. Without a browser these tests skip (fail in CI)."""
from __future__ import annotations

import json
import math
import re
from pathlib import Path

import pytest

from conftest import cli
from fuzz_scenes import run
from test_view import ROOT, SHAPER, check_clean, driver, graphplan, open_page, page_data  # noqa: F401

SIZES = [(390, 844), (1366, 768), (1920, 1080)]


@pytest.fixture(scope="module")
def shaper(tmp_path_factory) -> Path:
    """(Written by the command in the worker, ``main``: the file a ``python -m graphplan view`` process
    writes, byte for byte — test_view's determinism test compares the two — without the process.)"""
    from graphplan.cli.main import main
    path = tmp_path_factory.mktemp("tutor") / "shaper.html"
    assert main(["view", str(SHAPER), "-o", str(path), "--lang", "en"]) == 0
    return path


@pytest.fixture(scope="module")
def cam_page(tmp_path_factory) -> Path:
    from graphplan.cli.main import main
    path = tmp_path_factory.mktemp("tutor") / "cam.html"
    assert main(["view", str(ROOT / "examples" / "cam_translating.toml"), "-o", str(path), "--lang", "uk"]) == 0
    return path


def viewport(d, width: int, height: int) -> None:
    d.execute_cdp_cmd("Emulation.setDeviceMetricsOverride",
                      {"width": width, "height": height, "deviceScaleFactor": 1, "mobile": width < 600})


# the page's text as a reader meets it: the HTML's text nodes and the drawings' <text>, each with the
# colour it is set in and the background it stands on (the first opaque one up the tree; the page's
# white at the root)
TEXTS = r"""
const rgb = (s) => { const m = s.match(/rgba?\(([^)]+)\)/); if (!m) return null;
  const v = m[1].split(',').map(parseFloat); return v.length > 3 && v[3] === 0 ? null : v.slice(0, 3); };
const lum = (c) => { const f = c.map((x) => { x /= 255; return x <= 0.03928 ? x / 12.92 : Math.pow((x + 0.055) / 1.055, 2.4); });
  return 0.2126 * f[0] + 0.7152 * f[1] + 0.0722 * f[2]; };
const back = (e) => { for (let n = e; n && n.nodeType === 1; n = n.parentElement) {
  if (n.tagName.toLowerCase() === 'svg') return [255, 255, 255];
  const b = rgb(getComputedStyle(n).backgroundColor); if (b) return b; } return [255, 255, 255]; };
const out = [];
const walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
for (let t = walker.nextNode(); t; t = walker.nextNode()) {
  const e = t.parentElement, text = t.textContent.trim();
  if (!text || !e || e.closest('script, noscript, option, select') || !e.getClientRects().length) continue;
  const st = getComputedStyle(e);
  if (st.visibility === 'hidden' || st.display === 'none') continue;
  const svg = e.closest('svg');
  const fg = rgb(svg ? st.fill : st.color) || [0, 0, 0];
  const L1 = lum(fg), L2 = lum(back(e));
  const px = svg ? parseFloat(st.fontSize) * (e.getScreenCTM() ? e.getScreenCTM().a : 1) : parseFloat(st.fontSize);
  out.push({ text: text, svg: !!svg, where: (svg || e.closest('[id]') || {}).id || '', px: px,
    contrast: (Math.max(L1, L2) + 0.05) / (Math.min(L1, L2) + 0.05) });
}
return out;
"""

# every word of every table cell on one line: a word broken ("quan tity", "0. 02") has two boxes
BROKEN_WORDS = r"""
const out = [];
document.querySelectorAll('table th, table td').forEach((cell) => {
  if (!cell.getClientRects().length) return;
  const walker = document.createTreeWalker(cell, NodeFilter.SHOW_TEXT);
  for (let t = walker.nextNode(); t; t = walker.nextNode()) {
    const re = /\S+/g; let m;
    while ((m = re.exec(t.textContent))) {
      const r = document.createRange(); r.setStart(t, m.index); r.setEnd(t, m.index + m[0].length);
      const tops = new Set(Array.from(r.getClientRects()).filter((b) => b.width > 0).map((b) => Math.round(b.top)));
      if (tops.size > 1) out.push(m[0]);
    }
  }
});
return out;
"""


def rect(d, element_id: str) -> dict:
    return d.execute_script("const r = document.getElementById(arguments[0]).getBoundingClientRect();"
                            "return {top: r.top, bottom: r.bottom, left: r.left, right: r.right};", element_id)


@pytest.mark.parametrize("size", SIZES)
def test_the_page_reads_well_at_every_width(driver, shaper, size):  # noqa: F811
    reads_well(driver, shaper, size, ("mech", "vplan", "aplan", "replay", "rmech", "diagrams"))


@pytest.mark.slow
@pytest.mark.parametrize("size", SIZES)
def test_the_cam_page_reads_well_at_every_width(driver, cam_page, size):  # noqa: F811
    """The cam's page (in Ukrainian) by the same measures."""
    reads_well(driver, cam_page, size, ("mech", "phase", "diagrams", "replay"))


def reads_well(driver, page: Path, size: tuple[int, int], drawings: tuple[str, ...]) -> None:  # noqa: F811
    """At 390×844, 1366×768, 1920×1080: no sideways scroll; every letter of the drawings and the
    diagrams 11–16 px (subscripts included); every text at a contrast ≥ 4.5:1 on what it stands on;
    no number in e-notation and no hyphen for a minus anywhere; no word or number broken across two
    lines in a table. At 1366×768 the slider, the mechanism and both plans are in one screen; on a
    phone ◀ and ▶ stand on one row with the slider."""
    viewport(driver, *size)
    try:
        open_page(driver, page)
        if "vplan" in drawings:
            driver.find_element("css selector", '#lab-positions button[data-key="1"]').click()   # readings shown
            driver.execute_script("document.getElementById('check-reveal').click()")
        widths = driver.execute_script("return [document.documentElement.scrollWidth, document.documentElement.clientWidth]")
        assert widths[0] <= widths[1], widths
        texts = driver.execute_script(TEXTS)
        drawn = [t for t in texts if t["svg"]]
        assert {t["where"] for t in drawn} >= set(drawings), {t["where"] for t in drawn}
        small = [(t["where"], t["text"], round(t["px"], 1)) for t in drawn if not 11 - 0.05 <= t["px"] <= 16 + 0.05]
        assert not small, small[:10]
        dull = [(t["where"], t["text"], round(t["contrast"], 2)) for t in texts if t["contrast"] < 4.5]
        assert not dull, dull[:10]
        every = " ".join(t["text"] for t in texts)
        assert not re.search(r"\d[eE][+-]?\d", every), re.findall(r"\S*\d[eE][+-]?\d\S*", every)[:5]
        assert not re.search(r"·10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]", every), re.findall(r"\S*·10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]\S*", every)[:5]
        assert not re.search(r"(^|[\s(=:;,])-\d", every), re.findall(r"\S*-\d\S*", every)[:5]
        assert driver.execute_script(BROKEN_WORDS) == []
        if size == (1366, 768):
            for element in ("phi",) + drawings[:3]:
                r = rect(driver, element)
                assert r["top"] >= 0 and r["bottom"] <= size[1] + 0.5, (element, r)
        if size[0] < 600:
            prev, nxt, slider = rect(driver, "prev"), rect(driver, "next"), rect(driver, "phi")
            assert abs(prev["top"] - nxt["top"]) < 1 and prev["right"] <= slider["left"] < slider["right"] <= nxt["left"]
        for element in drawings:          # every drawing reachable by Tab, with a name
            assert driver.execute_script("const e = document.getElementById(arguments[0]);"
                                         "return e.tabIndex === 0 && !!e.getAttribute('aria-label')", element), element
        check_clean(driver, page.resolve().as_uri())
    finally:
        driver.execute_cdp_cmd("Emulation.clearDeviceMetricsOverride", {})


def test_every_control_by_keyboard(driver, shaper):  # noqa: F811
    """Space on a focused checkbox ticks it (and does not start the turn); + and − zoom a focused
    drawing, the arrows move it, 0 fits it again; ← → on the focused diagrams seek one grid step."""
    from selenium.webdriver.common.keys import Keys
    open_page(driver, shaper)
    box = driver.find_element("id", "per-angle")
    box.send_keys(Keys.SPACE)
    assert box.is_selected()
    assert driver.find_element("id", "play").get_attribute("aria-pressed") == "false"
    box.send_keys(Keys.SPACE)
    assert not box.is_selected()
    view = lambda: [float(v) for v in driver.execute_script(  # noqa: E731
        "return document.getElementById('mech').getAttribute('viewBox')").split()]
    mech = driver.find_element("id", "mech")
    whole = view()
    mech.send_keys("+")
    zoomed = view()
    assert zoomed[2] == pytest.approx(whole[2] / 1.25, rel=1e-3)
    mech.send_keys(Keys.ARROW_RIGHT)
    assert view()[0] > zoomed[0] and view()[2] == pytest.approx(zoomed[2])
    turn = float(driver.find_element("id", "turn-value").get_attribute("data-turn"))
    assert turn == float(driver.find_element("id", "turn-value").get_attribute("data-turn"))   # the arrow moved the drawing only
    mech.send_keys("0")
    assert view() == pytest.approx(whole, abs=1e-3)
    diagrams = driver.find_element("id", "diagrams")
    diagrams.send_keys(Keys.ARROW_RIGHT, Keys.ARROW_RIGHT)
    after = float(driver.find_element("id", "turn-value").get_attribute("data-turn"))
    assert after == pytest.approx(turn + 2 * page_data(shaper)["step"], abs=1e-6)
    for element in ("mech", "vplan", "aplan", "replay", "diagrams"):
        assert driver.find_element("id", element).get_attribute("tabindex") == "0"
    check_clean(driver, shaper.resolve().as_uri())


def test_the_step_list_follows_and_numbers_its_first_lines(driver, shaper):  # noqa: F811
    """The shaper's acceleration plan: at the last step and at step 17 the current step is inside the
    list's visible part; every step's number stands level with the first line of its text."""
    open_page(driver, shaper)
    driver.find_element("id", "step-last").click()
    seen = lambda: driver.execute_script(  # noqa: E731
        "const ol = document.getElementById('step-list'), li = ol.querySelector('li.current');"
        "const a = ol.getBoundingClientRect(), b = li.getBoundingClientRect(); return [a.top, a.bottom, b.top, b.bottom];")
    top, bottom, li_top, li_bottom = seen()
    assert top - 0.5 <= li_top and li_bottom <= bottom + 0.5
    driver.find_element("id", "step-first").click()
    for _ in range(16):
        driver.find_element("id", "step-next").click()
    top, bottom, li_top, li_bottom = seen()
    assert top - 0.5 <= li_top and li_bottom <= bottom + 0.5
    gaps = driver.execute_script(
        "return Array.from(document.querySelectorAll('#step-list li')).map((li) => {"
        " const no = li.querySelector('.no'), b = li.querySelector('button'), r = document.createRange();"
        " r.setStart(b.firstChild, 0); r.setEnd(b.firstChild, 1);"
        " const lines = new Set(Array.from(b.getClientRects()).map((x) => x.height));"
        " return [no.getBoundingClientRect().bottom - r.getClientRects()[0].bottom, b.getBoundingClientRect().height]; })")
    assert max(abs(g) for g, _ in gaps) < 3, gaps
    assert max(h for _, h in gaps) > 40          # some steps wrap: the numbers still stand at their first lines


def test_the_per_angle_scale_names_its_mu(driver, shaper):  # noqa: F811
    """Ticked, each plan is drawn at the standard scale that fills its panel at this angle, and its
    caption says that μ (a value of the series 1, 2, 2.5, 4, 5 × 10^k, not above the fixed one);
    unticked, the fixed μ again."""
    open_page(driver, shaper)
    data = page_data(shaper)
    driver.find_element("id", "per-angle").click()
    mus = []
    for turn in (20.0, 95.0):
        driver.execute_script("const s = document.getElementById('phi'); s.value = String(arguments[0]);"
                              "s.dispatchEvent(new Event('input', {bubbles: true}));", turn)
        for cap, fixed in (("cap-vplan", data["scales"]["mu_v"]), ("cap-aplan", data["scales"]["mu_a"])):
            mu = float(driver.find_element("id", cap).get_attribute("data-mu"))
            m, k = mu / 10 ** math.floor(math.log10(mu) + 1e-9), math.floor(math.log10(mu) + 1e-9)
            assert min(abs(m - s) for s in (1, 2, 2.5, 4, 5)) < 1e-9, mu
            assert mu <= fixed
            shown = driver.find_element("id", cap).text
            assert f"{mu:g}" in shown.replace("\n", ""), shown
            mus.append(mu)
    assert any(mu < data["scales"]["mu_a"] for mu in mus)
    driver.find_element("id", "per-angle").click()
    assert float(driver.find_element("id", "cap-aplan").get_attribute("data-mu")) == data["scales"]["mu_a"]


def test_the_mechanisms_letters_clear_the_joints_and_the_ground(driver, shaper):  # noqa: F811
    """At every lab position no letter of the mechanism (O_1, the positions' numbers) lies on a joint's
    circle or a ground hatch."""
    open_page(driver, shaper)
    for key in range(12):
        driver.find_element("css selector", f'#lab-positions button[data-key="{key}"]').click()
        kept = json.loads(driver.find_element("id", "mech").get_attribute("data-kept"))
        boxes = driver.execute_script(
            "return Array.from(document.querySelectorAll('#mech-labels text')).map((t) => { const b = t.getBBox();"
            " return [t.textContent, b.x, -b.y - b.height, b.x + b.width, -b.y]; })")
        for text, x0, y0, x1, y1 in boxes:
            for k in kept:
                overlap = min(x1, k[2]) - max(x0, k[0]), min(y1, k[3]) - max(y0, k[1])
                assert min(overlap) <= 0.05, (key, text, k)


def test_the_shapers_words_name_the_points_as_the_equation_does():
    """p_v a = v_A = v_A2 (the equation's name of the block's point), and the rocker's b found from
    OB : OA_3 (the rocker's own point), not OA."""
    from graphplan.exact.positions import study
    from graphplan.model.scene import load
    from graphplan.report.explorer import explorer_data
    data = explorer_data(study(load(SHAPER)), step=10.0, lang="en")
    for rec in data["records"]:
        first = rec["steps"][1]["caption"]["en"]
        assert first.startswith(("p_{v}a = v_A = v_{A2} =", "πa = a_A = a_{A2} =")), first
        b = next(s["caption"]["en"] for s in rec["steps"] if s["caption"]["en"].startswith("b by similarity"))
        assert "OB : OA_3" in b, b


# -- the replay as a lesson: step 0, the marked equation, the mechanism beside it, ω and ε ------------

TUTOR_WALK = r"""
const out = [];
const sel = document.getElementById('replay-plan'), rm = document.getElementById('rmech');
const json = (name) => { const v = rm.getAttribute(name); return v === null ? null : JSON.parse(v); };
for (let k = 0; k < sel.options.length; k++) {
  sel.value = String(k);
  sel.dispatchEvent(new Event('change', {bubbles: true}));
  document.getElementById('step-first').click();
  const n = document.querySelectorAll('#step-list li').length, steps = [];
  for (let s = 0; s < n; s++) {
    const terms = Array.from(document.querySelectorAll('#step-eq .term')).map((t) =>
      [t.querySelector('.vec').textContent, parseInt(t.getAttribute('data-marks'), 10), t.querySelector('.dir').textContent.trim(),
       getComputedStyle(t.querySelector('.vec')).borderBottomStyle, getComputedStyle(t.querySelector('.vec')).borderTopStyle]);
    const lines = Array.from(document.querySelectorAll('#replay .g-line.hl')).map((l) =>
      [parseFloat(l.getAttribute('x2')) - parseFloat(l.getAttribute('x1')), -(parseFloat(l.getAttribute('y2')) - parseFloat(l.getAttribute('y1')))]);
    steps.push({caption: document.getElementById('step-caption').textContent, terms: terms, link: rm.getAttribute('data-link'),
      xy: json('data-link-xy'), line: json('data-line'), carry: json('data-carry'), sense: json('data-sense'), planLines: lines,
      pole: !!document.getElementById('replay-pole')});
    document.getElementById('step-next').click();
  }
  out.push(steps);
}
return out;
"""


def series_at_least(value: float) -> float:
    """The smallest 1, 2, 2.5, 4, 5 × 10^k not below value (the draftsman's standard scales)."""
    k = math.floor(math.log10(value)) - 1
    while True:
        for m in (1, 2, 2.5, 4, 5):
            if m * 10 ** k >= value * (1 - 1e-12):
                return m * 10 ** k
        k += 1


def cross(a, b) -> float:
    return a[0] * b[1] - a[1] * b[0]


def walk_the_lessons(d, scene: Path, tmp: Path) -> int:
    """Every plan of the scene's page walked in the browser, checked against `plans --json` and the
    kinematics sheet's scales (`graphplan.sheets.kinematics.sheet_scales`); the count of plans."""
    from graphplan.exact.positions import study
    from graphplan.model.scene import load
    page = tmp / (scene.stem + ".html")
    # the page and `plans --json` by the commands in the worker (test_view checks their processes)
    code, _, err = run(["view", str(scene), "-o", str(page), "--lang", "en", "--step", "10"])
    assert code == 0, err
    planned = json.loads(cli("plans", str(scene), "--json")[1])     # at the A1 sheet's scales
    data = page_data(page)
    open_page(d, page)
    d.set_script_timeout(900)      # a hang guard, not a speed bound: the walk of the shaper's plans took > 30 s
    walked = d.execute_script(TUTOR_WALK)   # (selenium's default) at a load average of 33 on two cores, stop 58
    assert len(walked) == len(data["records"])
    st = study(load(scene))
    widest = {}         # each kind's largest plan across (mm, with its pole), from the drawn points
    for rec in data["records"]:
        xs, ys = [0.0] + [p[1] for p in rec["points"]], [0.0] + [p[2] for p in rec["points"]]
        widest[rec["kind"]] = max(widest.get(rec["kind"], 0.0), max(xs) - min(xs), max(ys) - min(ys))
    for rec, steps in zip(data["records"], walked):
        pos = next(p for p in planned["positions"] if p["index"] == rec["index"]) if rec["index"] is not None else None
        plan_json = pos[rec["kind"]] if pos else None
        mu_name = "mu_v" if rec["kind"] == "velocity" else "mu_a"
        # step 0: the pole and the scale — the sheet's μ, reached from the trial length by the series
        zero, scale = steps[0], rec["steps"][0]["scale"]
        assert zero["pole"] and zero["caption"].startswith("Step 0: the pole and the scale")
        sheet = next(p[mu_name] for p in planned["positions"] if mu_name in p)
        assert scale["mu"] == sheet == rec["mu"]
        pin = st.mech.crank
        exact = abs(st.mech.omega1) * pin.length if rec["kind"] == "velocity" else pin.length * math.hypot(
            st.mech.omega1 ** 2, pin.epsilon)
        assert scale["value"] == pytest.approx(exact, rel=1e-9)
        if abs(series_at_least(scale["mu"]) - scale["mu"]) < 1e-12 * scale["mu"]:
            assert series_at_least(exact / scale["trial"]) == pytest.approx(scale["mu"], rel=1e-12)
        elif round(scale["mu"] / 10 ** math.floor(math.log10(scale["mu"])), 9) in (1.5, 7.5):   # the sheet's room: GOST 2.302's 1.5, 7.5·10^k, the next round value up
            raw = exact / scale["trial"]
            k = math.floor(math.log10(raw))
            rounds = sorted(m * 10.0 ** j for j in (k, k + 1) for m in (1, 1.5, 2, 2.5, 4, 5, 7.5))
            assert next(m for m in rounds if m >= raw * (1 - 1e-12)) == pytest.approx(scale["mu"], rel=1e-12)
            assert "GOST 2.302" in zero["caption"]
        else:       # the sheet chose p_v a ≥ 40 mm (docs/scenes.md) and μ = v_A/p_v a, 3 figures down — or,
            raw = exact / scale["trial"]     # the plans reading by their size (a plan ≥ 100 mm across), a
            k = math.floor(math.log10(raw)) - 2     # shorter multiple of 5 mm the sheet's room held, said so
            assert scale["mu"] == pytest.approx(math.floor(raw / 10 ** k) * 10 ** k)
            if scale["trial"] < 40:
                assert scale["trial"] % 5 == 0 and "shorter than 40 mm: the plan reads by its size" in zero["caption"]
                assert widest[rec["kind"]] >= 100 - 1e-6, (scene.stem, rec["kind"], widest)
        assert scale["drawn"] == pytest.approx(exact / scale["mu"], abs=1e-6)
        shown = zero["caption"].replace("−", "-")
        assert f"μ{mu_name[-1]} = {scale['mu']:g} " in shown and f"= {scale['drawn']:.1f} mm" in shown, shown
        for k, (step, s) in enumerate(zip(rec["steps"], steps)):
            # the equation, every term barred and marked: two known only in direction, with their notes
            if step.get("equation"):
                terms = s["terms"]
                assert len(terms) == len([t for t in step["equation"]["tokens"] if "t" in t]) >= 3
                assert all(top == "solid" for *_, top in terms)
                assert all(m >= 1 for _, m, *_ in terms[1:]) and terms[0][1] in (0, 1)
                once = [t for t in terms if t[1] == 1]
                assert len(once) == 2, terms
                assert all(t[2][:1] in "⊥∥" and t[3] == "solid" for t in once), once
                assert all(t[3] == "double" for t in terms if t[1] == 2)
            # the highlighted link is the one the direction line names, the line drawn through the point
            m = re.match(r"Through \S+ draw a line (perpendicular to (\S+)|parallel to the link (\S+)|parallel to the guide of (\S+)):",
                         s["caption"])
            if m:
                line = s["line"]
                assert line and s["planLines"], (scene.stem, k, s["caption"])
                plan_line = s["planLines"][0]
                assert abs(cross(line, plan_line)) <= 1e-3 * math.hypot(*plan_line), (scene.stem, k)   # the same direction
                if m.group(2) or m.group(3):
                    assert s["xy"], (scene.stem, k, s["caption"])
                    a, b = s["xy"]
                    u = (b[0] - a[0], b[1] - a[1])
                    named = m.group(2) or m.group(3)
                    ends = s["link"].split()
                    if m.group(2):
                        assert flat_pair(named) == {flat_point(e) for e in ends}, (named, ends)
                        assert abs(line[0] * u[0] + line[1] * u[1]) <= 1e-3 * math.hypot(*u)
                    else:                # along the guide the link carries (at its own angle to the link)
                        assert ends[0] in st.mech.links[named].joints, (named, ends)
            # ω and ε at the end: the plan's reading with its sign, the carried vector turning that way
            if step.get("rate"):
                rate = step["rate"]
                got = plan_json[f"{rate['kind']}_{rate['link']}"] if plan_json else None
                if got is not None:
                    assert abs(rate["value"]) == pytest.approx(got["value"], rel=1e-9)
                    assert rate["sense"] == got["sense"]
                if rate["value"]:
                    a, b = s["xy"]
                    assert s["sense"] == (1 if rate["value"] > 0 else -1)
                    assert math.copysign(1, cross((b[0] - a[0], b[1] - a[1]), s["carry"])) == s["sense"]
                    word = "counter-clockwise" if rate["value"] > 0 else "clockwise"
                    assert f" {word}, so " in s["caption"]
        # every turning link's ω or ε but a block's (it turns with its coulisse; the coulisse is read)
        links = st.mech.links
        assert any(st_.get("rate") for st_ in rec["steps"]) == any(
            k.startswith(("omega_", "epsilon_")) and k.split("_", 1)[1] in links
            and (len(links[k.split("_", 1)[1]].joints) >= 2 or links[k.split("_", 1)[1]].slides_on is None)
            for k in (plan_json or {}))
    check_clean(d, page.resolve().as_uri())
    return len(walked)


def flat_point(name: str) -> str:
    """A3 → A: the point on the mechanism where a coincident point is."""
    return re.sub(r"\d+$", "", name) if re.match(r"^[A-Z]\d+$", name) and not name.startswith(("O", "S")) else name


def flat_pair(text: str) -> set[str]:
    """"BO_2" / "O_{1}A" → {"B", "O2"} / {"O1", "A"}."""
    names = re.findall(r"[A-Z][a-z]?(?:_\{?\d+\}?|\d*)", text)
    return {flat_point(re.sub(r"[_{}]", "", n)) for n in names}


def generated(kind: str, folder: Path) -> Path:
    import random_mechanisms as R
    made = {"RRR": lambda: R.rrr(0.1, 0.4, 0.35, 0.3, 10, 1), "RRP": lambda: R.rrp(0.1, 0.35, 0.03, 20, 12, 1),
            "RPR": lambda: R.rpr(0.1, 0.3, 0.02, 10, 1), "PRP": lambda: R.prp(0.1, 0.4, 0.35, 0.3, 30, 10, 10),
            "RPP": lambda: R.rpp(0.1, 60, 0, 10), "RRP moving": lambda: R.rrp_moving(0.1, 0.4, 0.35, 0.3, 0.6, 30, 10, 1),
            "RPP moving": lambda: R.rpp_moving(0.1, 0.4, 0.35, 0.3, 70, 20, 10)}
    text, ok = made[kind]()
    assert ok
    path = folder / f"generated_{kind.replace(' ', '_')}.toml"
    path.write_text(text, encoding="utf-8")
    return path


SLOW = pytest.mark.slow


@pytest.mark.parametrize("scene", ["four_bar"] + [pytest.param(s, marks=SLOW) for s in
                                   ("shaper", "crank_slider", "lab_crank_slider", "slotter")])
def test_every_plan_of_the_examples_is_a_lesson(driver, scene, tmp_path):  # noqa: F811
    """Every plan of the example, walked: step 0 states the pole and the sheet's scale (`plans --json`
    draws at the A1 sheet's scales, `sheets.kinematics.sheet_scales`; the trial length
    rounds to it by the standard series; the drawn length is v_A/μ); each group's equation marks every
    term (two known only in direction, each with its ⊥/∥ note); the mechanism's highlighted link is the
    one the direction line names and its direction line runs as the plan's; ω and ε at the end equal
    `plans --json` with their senses, the vector carried to the mechanism turning the link that way."""
    assert walk_the_lessons(driver, ROOT / "examples" / f"{scene}.toml", tmp_path) >= 2


@pytest.mark.parametrize("kind", ["RPR"] + [pytest.param(k, marks=SLOW) for k in
                                  ("RRR", "RRP", "PRP", "RPP", "RRP moving", "RPP moving")])
def test_every_plan_of_generated_mechanisms_is_a_lesson(driver, kind, tmp_path):  # noqa: F811
    """The same walk on generated mechanisms of every group kind (tests/random_mechanisms.py)."""
    assert walk_the_lessons(driver, generated(kind, tmp_path), tmp_path) >= 2


@pytest.mark.parametrize("scene", ["shaper", "four_bar", "slotter"])
def test_similarity_is_explained_with_its_numbers(scene):
    """Each point found by similarity from two known points says why the figure is similar (⊥ sides on
    the velocity plan, one angle on the acceleration plan), how it is turned, and the ratio with its
    numbers: the plan's segment over the link's (drawing mm), and the new segment it gives — which is
    where the construction put the point (its distance on the plan, to the 0.1 mm of the words)."""
    from graphplan.exact.positions import study
    from graphplan.model.scene import load
    from graphplan.report.explorer import explorer_data
    data = explorer_data(study(load(ROOT / "examples" / f"{scene}.toml")), step=10.0, lang="en")
    checked = 0
    for rec in data["records"]:
        at = {re.sub(r"[_{}]", "", name): complex(x, y) for name, x, y, _ in rec["points"]}
        at["p_v".replace("_", "")] = at["π"] = 0j
        for step in rec["steps"]:
            c = step["caption"]["en"]
            if " by similarity" not in c or "the ratio" not in c:
                continue
            assert ("perpendicular to those of" in c and "turned 90°" in c) if rec["kind"] == "velocity" else "turned by" in c
            m = re.search(r"the ratio (\S+)/(\S+) = ([\d.]+)/([\d.]+) = ([\d.]+); (\S+) = \S+·\S+ = (?:[\d.]+·[\d.]+ = )?([\d.]+) mm", c)
            assert m, c
            pq, _, pq_mm, PQ_mm, k, px, px_mm = m.groups()
            assert float(k) == pytest.approx(float(pq_mm) / float(PQ_mm), abs=0.006 * float(k) + 1e-3)
            ends = [n for n in at if pq.replace("_", "").replace("{", "").replace("}", "").startswith(n)]
            p = max(ends, key=len)
            q = pq.replace("_", "").replace("{", "").replace("}", "")[len(p):]
            assert abs(at[q] - at[p]) == pytest.approx(float(pq_mm), abs=0.051)
            flat_px = px.replace("_", "").replace("{", "").replace("}", "")
            x = flat_px[len(p):]
            assert abs(at[x] - at[p]) == pytest.approx(float(px_mm), abs=0.06 + 0.006 * float(px_mm)), c
            checked += 1
    assert checked >= 3


# -- the cam in the explorer ------------------------------------------------------------------------------

GENERATED_CAM = """title = "Generated cam"
[cam]
follower = "translating"
stroke = 0.03
roller_radius = 0
phases_deg = { rise = 150, dwell_far = 20, return = 110, dwell_near = 80 }
laws = { rise = "cycloidal", return = "cosine" }
pressure_angle_deg = { rise = 28, return = 35 }
omega = 12
direction = "cw"
divisions = 6
"""


@pytest.mark.parametrize("scene", ["cam_translating"] + [pytest.param(s, marks=pytest.mark.slow) for s in ("cam_rocking", "generated")])
def test_the_cam_in_the_explorer(driver, scene, tmp_path):  # noqa: F811
    """`graphplan view` on a cam scene (the two examples, and a generated knife-edge cam with the best
    offset): a page with 0 console errors; at every division of the construction the pressure angle the
    page shows equals `graphplan cam --json`'s exact one (and the construction's beside it), the angle
    drawn at the contact between the normal and the follower's velocity is that angle, the cursor of the
    diagrams and the point on the phase diagram move with the turn; the profile by inversion is replayed
    to its end, one point of the centre profile a division."""
    if scene == "generated":
        path = tmp_path / "generated_cam.toml"
        path.write_text(GENERATED_CAM, encoding="utf-8")
    else:
        path = ROOT / "examples" / f"{scene}.toml"
    page = tmp_path / f"{scene}.html"
    code, _, err = run(["view", str(path), "-o", str(page), "--lang", "en", "--step", "2"])   # in the worker
    assert code == 0, err
    doc = json.loads(cli("cam", str(path), "--json")[1])
    open_page(driver, page)
    shown = driver.execute_script("""
      return Array.from(document.querySelectorAll('#divisions button')).map((b, k) => {
        b.click();
        const t = document.getElementById('theta-value'), m = document.getElementById('mech');
        const cell = document.querySelector('#values tr[data-division="' + k + '"] td[data-value]');
        return [t.getAttribute('data-value'), t.textContent, document.getElementById('theta-graphical').textContent,
                m.getAttribute('data-angle'), cell.getAttribute('data-value'),
                document.getElementById('diagram-cursor').getAttribute('x1'), document.getElementById('phase-point').getAttribute('cx')];
      });""")
    assert len(shown) == len(doc["positions"])
    for k, (got, pos) in enumerate(zip(shown, doc["positions"])):
        value, text, graphical, drawn, cell, _, _ = got
        exact = pos["exact"]["pressure_angle_deg"]
        assert float(value) == pytest.approx(exact, abs=1e-6)
        assert text.replace("−", "-") == f"ϑ = {exact:.2f}°"
        angle = f"{pos['graphical']['pressure_angle_deg']:.1f}".replace("-0.0", "0.0")   # no "−0.0°"
        assert f"ϑ = {angle}° (division {k})" in graphical.replace("−", "-")
        assert float(drawn) == pytest.approx(abs(exact), abs=0.05 if scene != "generated" else 1.0)   # a knife edge: its normal from the drawn profile
        assert float(cell) == pytest.approx(exact, abs=1e-9)
    assert len({tuple(got[5:]) for got in shown}) >= len(doc["positions"]) - 2   # the dwells' ends coincide on the phase diagram only
    buttons = driver.find_elements("css selector", "#divisions button")
    if scene == "cam_translating":         # the pictures of docs/view.md (kept with GRAPHPLAN_SHOTS=docs/view)
        from test_view import element_shot, keep_picture
        buttons[3].click()
        element_shot(driver, "views", tmp_path / "cam.png")
        keep_picture(tmp_path / "cam.png", "cam_views")
        driver.find_element("id", "step-first").click()
        for _ in range(4):
            driver.find_element("id", "step-next").click()
        element_shot(driver, "replay-section", tmp_path / "inversion.png")
        keep_picture(tmp_path / "inversion.png", "cam_inversion")
    driver.find_element("id", "step-last").click()
    steps = driver.find_elements("css selector", "#step-list li")
    assert len(steps) == len(doc["positions"]) + 3 and "current" in steps[-1].get_attribute("class")
    assert driver.find_element("id", "step-caption").text
    check_clean(driver, page.resolve().as_uri())


def test_the_cam_page_is_one_offline_deterministic_file(tmp_path):
    """The cam's page, like the mechanism's: the same bytes twice, no URI but the namespaces, no src or
    href, a Content-Security-Policy that forbids every load, a word for a browser without JavaScript; a
    bad --step is one line on stderr and no file."""
    from test_view import NAMESPACES
    scene = ROOT / "examples" / "cam_rocking.toml"
    pages = []
    for k in (1, 2):
        out = tmp_path / f"cam{k}.html"
        r = graphplan("view", str(scene), "-o", str(out), "--step", "3")
        assert r.returncode == 0, r.stderr
        pages.append(out.read_bytes())
    assert pages[0] == pages[1] and 30_000 < len(pages[0]) < 1_000_000
    text = pages[0].decode("utf-8")
    assert set(re.findall(r"[a-zA-Z][a-zA-Z0-9+.-]*://[^\s\"'<>)]*", text)) <= NAMESPACES
    assert not re.search(r"\b(src|href)\s*=", text, re.I) and "default-src 'none'" in text
    assert "<noscript>" in text and "JavaScript" in text
    r = graphplan("view", str(scene), "-o", str(tmp_path / "bad.html"), "--step", "0")
    assert r.returncode == 2 and r.stderr.count("\n") == 1 and "Traceback" not in r.stderr
    assert not (tmp_path / "bad.html").exists()
