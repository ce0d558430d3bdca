"""Kinematic diagrams by chords: exactness of the construction, its order, the lab's diagrams,
graphical integration, the failure diagnostics, the record and the command."""
from __future__ import annotations

import json
import math

import numpy as np
import pytest

from conftest import EXAMPLES, ROOT, derivative, example
from graphplan.cli.main import main
from graphplan.drawing.diagrams import draw
from graphplan.graphic.diagrams import chord_diagrams
from graphplan.report.diagrams import diagrams_json, diagrams_table
from graphplan.util.errors import GraphplanError


@pytest.fixture(scope="module")
def lab():
    return example("lab_crank_slider")


@pytest.fixture(scope="module")
def shaper():
    return example("shaper")


def chord_slopes(doc):
    s, v = doc["s"], doc["v"]
    return [(b["value"] - a["value"]) / (b["t"] - a["t"]) for a, b in zip(s, s[1:])], [e["value"] for e in v]


@pytest.mark.parametrize("name", EXAMPLES)
def test_exact_drawing_gives_the_chord_slopes_and_the_scales_follow_the_formulas(name):
    st = example(name)
    d = chord_diagrams(st, precision=0)
    doc = diagrams_json(d)
    slopes, v = chord_slopes(doc)
    assert np.allclose(v, slopes, rtol=1e-9, atol=1e-12 * max(map(abs, slopes)))
    assert doc["mu_t"] == 2 * math.pi / (abs(st.mech.omega1) * doc["L_mm"])
    assert doc["mu_v"] == doc["mu_s"] / (doc["mu_t"] * doc["H1_mm"])
    assert doc["mu_a"] == doc["mu_v"] / (doc["mu_t"] * doc["H2_mm"])
    # each ordinate's value is its drawn length times the scale, signed along the guide
    for key, mu in (("s", "mu_s"), ("v", "mu_v"), ("a", "mu_a")):
        for e in doc[key]:
            assert e["value"] == pytest.approx(doc["sign"] * e["mm"] * doc[mu], rel=1e-12, abs=1e-15)
    # the acceleration ordinates are the chord slopes of the v curve read at the division ordinates
    v_at = [p["v"]["value"] for p in doc["positions"]] + [doc["positions"][0]["v"]["value"]]
    t = [e["t"] for e in doc["s"]]
    a_chords = np.diff(v_at) / np.diff(t)
    assert np.allclose([e["value"] for e in doc["a"]], a_chords, rtol=1e-9, atol=1e-12 * np.max(np.abs(a_chords)))
    # abscissae: the division ordinates for s, the middles of the intervals for v and a
    assert len(doc["s"]) == doc["divisions"] + 1 and len(doc["v"]) == len(doc["a"]) == doc["divisions"]
    assert np.allclose([e["t"] for e in doc["v"]], (np.array(t[:-1]) + t[1:]) / 2)


def test_unequal_and_adaptive_divisions_are_still_chord_slopes(shaper):
    for d in (chord_diagrams(shaper, divisions=[0, 10, 30, 45, 90, 150, 200, 250, 300, 330], precision=0),
              chord_diagrams(shaper, divisions=12, precision=0, adaptive=True, tolerance=0.25)):
        slopes, v = chord_slopes(diagrams_json(d))
        assert np.allclose(v, slopes, rtol=1e-9)
        assert diagrams_json(d)["s"][0]["phi_deg"] == pytest.approx(shaper.phi0)


def _max_errors(st, counts, key):
    return np.array([np.max(np.abs(chord_diagrams(st, divisions=n, precision=0).errors_of_max(key)))
                     for n in counts])


@pytest.mark.parametrize("name, counts", [("crank_slider", (12, 24, 48, 96)), ("shaper", (24, 48, 96, 192))])
def test_error_falls_as_h_squared(name, counts):
    st = example(name)
    for key in ("v_mid", "a_mid", "v_at", "a_at"):
        slope = np.polyfit(np.log(counts), np.log(_max_errors(st, counts, key)), 1)[0]
        assert slope == pytest.approx(-2.0, abs=0.2), (key, slope)


def test_midpoint_error_is_h_squared_over_24_times_the_jerk():
    # the chord's slope misses the tangent's at the middle by h²/24·s''' (Taylor); the jerk from
    # finite differences of the solver's exact acceleration
    st = example("crank_slider")
    n = 96
    d = chord_diagrams(st, divisions=n, precision=0)
    h = st.mech.period / n
    jerk = derivative(lambda p: st.output.accel(st.solve(p)), d.phi_mid, st.mech.omega1)
    err = d.values(d.exact)["v_mid"] - d.truth["v_mid"]
    assert np.allclose(err, h ** 2 / 24 * jerk, rtol=0.01, atol=1e-3 * np.max(np.abs(err)))


def test_lab_diagrams_look_like_figure_2_7(lab):
    d = chord_diagrams(lab, divisions=8, L=240, H1=25, H2=25)
    assert (d.mu_s, d.mu_t) == (0.001, 0.0025)                 # μs = μl, T = 0.6 s over 240 mm
    assert d.mu_v == pytest.approx(0.016) and d.mu_a == pytest.approx(0.256)
    r = d.drawn
    # s: from the extreme position B0, rising to the stroke 2·OA = 80 mm at position 4 and back
    assert r.s[0] == r.s[8] == 0 and r.s[4] == 80 and np.all(r.s >= 0)
    assert np.all(np.diff(r.s[:5]) > 0) and np.all(np.diff(r.s[4:]) < 0)
    # v: positive while s grows, through zero at the far extreme, negative coming back
    assert np.all(r.v[:4] > 0) and np.all(r.v[4:] < 0) and r.v_at[4] == 0
    # a: the largest at the outer dead centre (the seed's drawn direction), negative around position 4
    assert r.a_at[0] == np.max(r.a_at) and r.a_at[4] < 0
    # the lab's table at two positions: percent errors against the analytic solver; v meets 5 %
    doc = diagrams_json(d)
    assert doc["chosen"] == [1, 5]
    for p in (doc["positions"][1], doc["positions"][5]):
        for key in ("s", "v", "a"):
            c = p[key]
            assert c["error_pct"] == pytest.approx(100 * (c["value"] - c["analytic"]) / c["analytic"])
        assert abs(p["v"]["error_pct"]) < 5
    table = diagrams_table(d, "uk")
    assert "У двох заданих положеннях" in table and "μ_vB = μ_sB/(μ_t·H₁) = 0,016" in table


def test_lab_values_against_the_closed_form_crank_slider(lab):
    # s, v, a of a centric crank-slider in closed form (independent of the solver)
    d = chord_diagrams(lab, divisions=8, L=240, H1=25, H2=25, precision=0)
    r, l, w = 0.040, 0.160, lab.mech.omega1
    lam = r / l
    phi = np.radians(d.phi_mid)
    root = np.sqrt(1 - lam ** 2 * np.sin(phi) ** 2)
    v = -r * w * (np.sin(phi) + lam * np.sin(2 * phi) / (2 * root))
    assert np.allclose(d.truth["v_mid"], v, rtol=1e-10)
    phi = np.radians(d.phi[:-1])
    x = r * np.cos(phi) + l * np.sqrt(1 - lam ** 2 * np.sin(phi) ** 2)
    assert np.allclose(d.truth["s"][:-1], x - (r + l), atol=1e-12)
    # the exact drawing's v misses by the chords' error only: below 4 % of the maximum at 8 divisions
    assert np.max(np.abs(d.values(d.exact)["v_mid"] - v)) < 0.04 * r * w * 1.03


def test_integration_reproduces_s(lab, shaper):
    d = chord_diagrams(lab, divisions=8, precision=0)
    assert np.allclose(d.exact.s_int_v, d.exact.s, atol=1e-9)         # v → s undoes s → v exactly
    assert abs(d.exact.v_int[-1] - d.exact.v_int[0]) < 1e-9           # ∫a over a period closes
    devs = []
    for n in (12, 24, 48):
        d = chord_diagrams(shaper, divisions=n, precision=0)
        devs.append(np.max(np.abs(d.exact.s_int - d.exact.s)) / np.max(d.exact.s))
    assert devs[0] < 0.02 and devs[2] < devs[1] < devs[0]
    doc = diagrams_json(chord_diagrams(shaper, divisions=12))["integration"]
    assert doc["s_from_a"]["max_dev_pct_of_max"] < 5 and len(doc["s_from_a"]["mm"]) == 13


def test_warnings_name_the_quick_return_and_the_ruler(shaper, lab):
    d = chord_diagrams(shaper, divisions=12)
    kinds = {w["kind"] for w in d.warnings}
    assert {"chord_error", "lab_limit", "ruler"} <= kinds
    chord = next(w for w in d.warnings if w["kind"] == "chord_error" and w["diagram"] == "a")
    assert "extreme position" in chord["message"] or "sharp bend" in chord["message"]
    # the worst chord interval is where the exact drawing's error is largest
    err = np.abs(d.errors_of_max("a_mid", d.exact))
    assert int(np.argmax(err)) in chord["intervals"]
    # fine exact drawing: nothing to warn about
    assert chord_diagrams(lab, divisions=48, precision=0).warnings == []


def test_ruler_error_grows_with_the_divisions_as_predicted(lab):
    # a ruler reading error σ = p/√12 at each end of a chord: the v ordinate's RMS error
    # ≈ σ·√(2(H1/h)² + 1) mm; the second differentiation multiplies the relative error further
    amp = []
    for n in (24, 48, 96):
        d = chord_diagrams(lab, divisions=n, precision=0.5)
        h = d.L / n
        predicted = 0.5 / math.sqrt(12) * math.sqrt(2 * (d.H1 / h) ** 2 + 1)
        got = math.sqrt(np.mean((d.drawn.v - d.exact.v) ** 2))
        assert 0.6 * predicted < got < 1.4 * predicted
        amp.append(next(w for w in d.warnings if w["kind"] == "ruler")["amplification_second"])
    assert amp[0] > 1 and amp[0] < amp[1] < amp[2]


def test_adaptive_refines_the_quick_return(shaper):
    uniform = chord_diagrams(shaper, divisions=12, precision=0)
    d = chord_diagrams(shaper, divisions=12, precision=0, adaptive=True, tolerance=0.25)
    assert d.divisions > 12
    h = np.diff(d.x)
    assert np.all(h <= 2.0001 * np.roll(h, 1)) and np.all(h <= 2.0001 * np.roll(h, -1))  # graded 2:1
    # the smallest intervals lie on the idle stroke (the fast return: the first part of the cycle)
    idle = float(shaper.from_position0(shaper.extremes[1] if shaper.phi0 == shaper.extremes[0]
                                       else shaper.extremes[0]))
    mids = (d.turn[:-1] + d.turn[1:]) / 2
    assert np.all(mids[h == h.min()] < idle)
    same = chord_diagrams(shaper, divisions=d.divisions, precision=0)
    worst = lambda x: np.max(np.abs(x.errors_of_max("a_mid", x.exact)))  # noqa: E731
    assert worst(d) < 0.5 * worst(same) and worst(d) < worst(uniform)
    # the original positions keep their numbers
    assert [p for p in d.position[:-1] if p is not None] == list(range(12))


def test_rocking_and_turning_outputs():
    four = chord_diagrams(example("four_bar"), precision=0, divisions=48)
    assert four.unit == "rad" and four.symbols == ("ψ", "ω", "ε")       # a rocker's angle: ψ
    assert np.max(np.abs(four.errors_of_max("v_mid"))) < 0.5
    slotter = example("slotter")
    d = chord_diagrams(slotter, point="BC", divisions=48, precision=0)  # the rotating slotted link
    assert abs(abs(d.truth["s"][-1]) - 2 * math.pi) < 1e-9 and d.sign * d.truth["s"][-1] > 0
    assert d.symbols[0] == "φ"            # a link turning round keeps φ (ψ is a rocker's)
    slopes, v = chord_slopes(diagrams_json(d))
    assert np.allclose(v, slopes, rtol=1e-9)
    assert np.max(np.abs(d.errors_of_max("a_mid"))) < 1.0


def test_other_points_and_bad_input(shaper):
    rel = chord_diagrams(shaper, point="A", precision=0)  # the block along the rocker
    assert rel.output.kind == "slide" and rel.unit == "m"
    with pytest.raises(GraphplanError, match="--point Q"):
        chord_diagrams(shaper, point="Q")
    with pytest.raises(GraphplanError, match="crank turns uniformly"):
        chord_diagrams(shaper, point="O1A")
    for kw in ({"divisions": 2}, {"H1": 0}, {"L": -5}, {"precision": -1}, {"divisions": [0, 90, 90, 180]},
               {"chosen": [12]}):
        with pytest.raises(GraphplanError):
            chord_diagrams(shaper, **kw)


def test_record_constructions(lab):
    d = chord_diagrams(lab, divisions=8, L=240, H1=25, H2=25)
    rec = draw(d, d.lang)
    roles = {}
    for p in rec.items:
        roles.setdefault(p.role, []).append(p)
    assert {p.layer for p in rec.items} == {"diagrams"}
    assert len(roles["chord"]) == 16 and len(roles["ray"]) == 16 and len(roles["projection"]) == 16
    assert len([p for p in rec.items if p.kind == "polyline" and p.role == "curve"]) == 3
    # every ray of the v diagram is parallel to its chord of the s diagram
    s_chords = [p for p in roles["chord"] if "of s(t)" in p.step]
    v_rays = [p for p in roles["ray"] if "ds/dt" in p.step]
    for chord, ray in zip(s_chords, v_rays):
        (x1, y1), (x2, y2) = chord.points
        (px, py), (qx, qy) = ray.points
        assert px == pytest.approx(-25.0) and qx == 0.0
        assert (y2 - y1) / (x2 - x1) == pytest.approx((qy - py) / (qx - px), rel=1e-12)
    assert rec.scales["mu_v"] == d.mu_v


@pytest.mark.parametrize("name, n", [("lab_crank_slider", 8), ("shaper", 12), ("crank_slider", 48)])
def test_labels_do_not_collide(name, n):
    d = chord_diagrams(example(name), divisions=n)
    for lang in ("uk", "en"):
        texts = [p.bounds() for p in draw(d, lang).items if p.kind == "text"]
        for i, a in enumerate(texts):
            for b in texts[i + 1:]:
                overlap = min(a[2], b[2]) - max(a[0], b[0]) > 0.05 and min(a[3], b[3]) - max(a[1], b[1]) > 0.05
                assert not overlap, (a, b)


def test_command_json_svg_and_errors(tmp_path, capsys):
    scene = str(ROOT / "examples" / "lab_crank_slider.toml")
    svg = tmp_path / "d.svg"
    argv = ["diagrams", scene, "--divisions", "8", "--L", "240", "--h1", "25", "--h2", "25", "--json",
            "--svg", str(svg)]
    assert main(argv) == 0
    out, err = capsys.readouterr()
    assert err == ""
    doc = json.loads(out)
    assert {"point", "divisions", "L_mm", "H1_mm", "H2_mm", "mu_s", "mu_t", "mu_v", "mu_a", "s", "v", "a"} <= set(doc)
    assert doc["point"] == "B" and doc["divisions"] == 8 and doc["H1_mm"] == 25
    assert {"phi_deg", "t", "mm", "value", "analytic", "error_pct"} <= set(doc["v"][0])
    assert [e["phi_deg"] for e in doc["v"]] == pytest.approx([22.5 + 45 * k for k in range(8)])
    main(argv)
    assert capsys.readouterr().out == out                           # byte-identical
    import svgelements
    page = svgelements.SVG.parse(str(svg))
    assert page.width > 240 and "mm" in svg.read_text()[:400]
    from graphplan.drawing.svg import to_png
    assert to_png(svg.read_text())[:4] == b"\x89PNG"
    assert main(["diagrams", scene, "--lang", "en"]) == 0
    assert "At the two chosen positions" in capsys.readouterr().out
    for bad in (["--divisions", "3"], ["--h1", "-2"], ["--point", "Z"], ["--divisions", "0,x"], ["--at", "9"]):
        assert main(["diagrams", scene, *bad]) == 2
        _, err = capsys.readouterr()
        assert len(err.strip().splitlines()) == 1 and err.startswith("graphplan: ")


def test_the_v_curve_passes_through_zero_at_the_dead_centres(lab):
    # seed 002: v = 0 where s has its extremum; the lab draws the French curve of v through the
    # middles' ordinates AND through 0 at an extreme position (an added point, not a changed reading)
    from review_scenes import REV11_A
    from conftest import scene_study
    from graphplan.graphic.chords import periodic_spline
    from graphplan.graphic.diagrams import v_knots
    st = scene_study(REV11_A)
    r, l, e = 0.045, 0.180, 0.012
    outer = math.degrees(math.asin(e / (r + l)))              # crank and rod in line: sin φ = e/(r + l)
    inner = 180.0 + math.degrees(math.asin(e / (l - r)))      # folded: sin(φ − 180°) = e/(l − r)
    d = chord_diagrams(st, H1=44, H2=32, precision=0.5)
    assert d.phi[0] == pytest.approx(outer, abs=1e-6)
    inner_turn = (outer - inner) % 360.0                      # clockwise crank: turn = φ0 − φ
    assert np.min(np.abs(d.turn - inner_turn)) > 1.0          # the inner one lies between ordinates
    assert list(d.drawn.v_zeros) == [0.0] and list(d.exact.v_zeros) == [0.0]
    curve = periodic_spline(*v_knots(d.x_mid, d.drawn.v, d.drawn.v_zeros), d.L)
    assert abs(float(curve(np.array([0.0]))[0])) < 1e-12
    assert d.drawn.v_at[0] == 0.0 and d.drawn.v_at[-1] == 0.0  # review 11: read −1.0 mm (−0.13 m/s) before
    assert d.values()["v_at"][0] == 0.0
    # the readings themselves are unchanged: still the chords' heights read with the ruler
    assert np.allclose(d.drawn.v, np.round(d.drawn.v_ray / 0.5) * 0.5)
    # a centric crank-slider stops at 0 and 180° (closed form), both on the 12 ordinates
    c = chord_diagrams(lab, divisions=12, H1=25, H2=25, precision=0.5)
    assert np.allclose(c.drawn.v_zeros, [0.0, c.L / 2])
    assert np.allclose(np.mod(c.phi[[0, 6]], 180.0), 0.0, atol=1e-6)
    assert c.drawn.v_at[0] == c.drawn.v_at[6] == 0.0
