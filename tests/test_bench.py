"""`graphplan bench`: the rows and charts it writes, and every failure mode it sweeps toward —
there the program warns (and is still right) or refuses in one line, never a silent wrong number."""
from __future__ import annotations

import json

import re

import numpy as np
import pytest

from conftest import example, scene_study
from graphplan.bench import run as bench
from graphplan.util.errors import AssemblyError, GraphplanError
from graphplan.util.words import word


@pytest.fixture(scope="module")
def stability_rows():
    return list(bench.stability(quick=True))


def test_each_sweep_goes_ok_then_warned_then_refused(stability_rows):
    for setting in bench.SWEEPS:
        rows = [r for r in stability_rows if r["setting"] == setting]
        statuses = [r["status"] for r in rows]
        assert statuses[0] == "ok" and statuses[-1] == "refused", setting
        assert "warning" in statuses, setting
        order = {"ok": 0, "warning": 1, "refused": 2}
        assert [order[s] for s in statuses] == sorted(order[s] for s in statuses), setting
        refused = rows[-1]["message"]
        assert "\n" not in refused and ("°" in refused) and ("II(2-3)" in refused)
        for r in rows[:-1]:                        # where it answers, the answer is right
            assert r["max_error_pct"] < 1e-3, (setting, r["x"])


def test_plans_near_the_toggle_warn_and_stay_exact():
    """Four-bar with the coupler and rocker nearly in line (O2B = 0.151 m): warnings, yet the
    exact construction (precision 0) still agrees with the solver."""
    from graphplan.graphic.plans import build_plans
    st = scene_study(bench._scene_four_bar(0.151))
    assert st.warnings
    plans = build_plans(st, precision=0.0)
    from graphplan.report.plans import plans_json
    doc = plans_json(plans)
    assert any(p["warnings"] for p in doc["positions"])
    errs = [abs(e["error_pct"]) for p in doc["positions"] for e in p["velocity"].values()
            if e.get("error_pct") is not None]
    assert max(errs) < 1e-6


def test_slotted_link_near_its_pivot_is_warned_with_the_rate():
    st = scene_study(bench._scene_slotted(1.01))
    text = " ".join(st.warnings)
    assert "passes within" in text and "rad/s" in text
    uk = " ".join(st.says("uk"))
    assert "проходить на відстані" in uk and "рад/с" in uk and "група II(2-3) ВПВ" in uk
    assert not re.search(r"[A-Za-z]{3,}|\d\.\d", uk)
    w = np.max(np.abs(st.solve(np.linspace(0, 360, 3601)).bodies["PQ"].omega))
    assert w > 50 * abs(st.mech.omega1)        # it really does turn violently there


def test_chords_warn_at_the_quick_return():
    from graphplan.graphic.diagrams import chord_diagrams
    d = chord_diagrams(example("shaper"), divisions=12, precision=0.0)
    assert d.warnings, "the shaper's quick return at 12 divisions exceeds 5 % and must be reported"
    worst = float(np.nanmax(np.abs(d.errors_of_max("a_mid"))))
    assert worst > 5.0


def test_refusals_are_one_line_for_impossible_geometry():
    with pytest.raises(AssemblyError) as info:
        scene_study(bench._scene_crank_slider(0.9))     # the rod is shorter than the crank
    assert "cannot be assembled for crank angles" in info.value.line("en")


def test_run_writes_rows_and_charts(tmp_path, monkeypatch, capsys):
    small = {"stability": bench.SECTIONS["stability"], "plans": bench.SECTIONS["plans"]}
    monkeypatch.setattr(bench, "SECTIONS", small)
    rows = bench.run(tmp_path, quick=True, show_progress=True, lang="uk")
    bar = capsys.readouterr().err                  # the progress bar speaks the reader's language
    assert "2/2" in bar and word("bench done", "uk") in bar and not re.search(r"[A-Za-z]{2,}", bar)
    doc = json.loads((tmp_path / "bench.json").read_text())
    assert len(doc["rows"]) == len(rows) > 10
    for r in doc["rows"]:
        assert {"method", "setting", "time_s", "max_error_pct"} <= set(r)
    for name in ("stability", "plans"):
        assert (tmp_path / f"{name}.png").read_bytes()[:4] == b"\x89PNG"
        assert (tmp_path / f"{name}.svg").read_text().startswith("<?xml")
    exact = [r for r in doc["rows"] if r["section"] == "plans" and r["x"] == 0]
    assert exact and all(r["max_error_pct"] < 1e-7 for r in exact)
    ruler = [r for r in doc["rows"] if r["section"] == "plans" and r["x"] == 0.5]
    assert all(0.01 < r["max_error_pct"] < 5 for r in ruler)


# names a Ukrainian bench row keeps: the sheet's format, the libraries compared and the functions they
# and the flywheel call (a call written Package.method is a name and removed first, see latin_words)
BENCH_NAMES = {"SVG", "graphplan", "pylinkage", "mechanism", "fsolve", "brentq", "numba", "Python", "NaN"}


def latin_words(text: str) -> set[str]:
    """Words of three or more Latin letters, calls such as Linkage.step_fast left out."""
    return set(re.findall(r"[A-Za-z]{3,}", re.sub(r"\w+(?:\.\w+)+", " ", text)))


def test_summary_speaks_the_language(stability_rows):
    import re
    uk = bench.summary(stability_rows, "uk")
    assert "стійкість" in uk and "відмова" in uk and "гаразд" in uk
    assert not latin_words(uk) - BENCH_NAMES
    assert not re.search(r"\d\.\d", uk)
    en = bench.summary(stability_rows, "en")
    assert "stability" in en and "refused" in en and not re.search(r"[А-Яа-яіїє]", en)


def chart_texts(rows: list[dict], lang: str) -> str:
    """Every text of the rows' section chart, said in ``lang`` (the ticks' mathtext left out)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.text import Text
    fig = bench.CHARTS[rows[0]["section"]](rows, plt)
    bench.say_figure(fig, lang)
    fig.canvas.draw()
    texts = " ".join(t.get_text() for t in fig.findobj(Text))
    plt.close(fig)
    return re.sub(r"\$[^$]*\$", " ", texts)


def test_a_section_in_ukrainian_keeps_no_english_word(stability_rows):
    """The smallest section that names methods (cam: exact, graphical, the method's failures) and
    the sweeps: every word of their English table — sections, methods, scenes, settings, statuses,
    the head — is gone from the Ukrainian one, which words the laws as the cam's own tables do;
    the rows (bench.json) keep their English identifiers."""
    from graphplan.report.cam import WORDS as CAM
    cam = list(bench.SECTIONS["cam"](True))
    for rows in (cam, stability_rows):
        en, uk = bench.summary(rows, "en"), bench.summary(rows, "uk")
        english = latin_words(en)
        ids = {w for r in rows for w in latin_words(f"{r['section']} {r['method']} {r.get('status', '')}")}
        assert ids and ids <= english                       # the rows' identifiers, said in English
        assert len(english) > 10 and not latin_words(uk) & english, latin_words(uk) & english
        assert not latin_words(uk) and not re.search(r"\d\.\d", uk)
        assert not re.search(r"[А-Яа-яіїєґ]", en)
        assert len(uk.splitlines()) == len(en.splitlines()) == len(rows) + 1
    laws = CAM["uk"]["laws"]
    assert laws["linear"] in bench.summary(cam, "uk")
    english = latin_words(chart_texts(cam, "en"))          # the chart: titles, axes, legend
    assert len(english) > 10 and not latin_words(chart_texts(cam, "uk"))
    assert {r["section"] for r in cam} == {"cam"} and {"exact", "graphical", "failure"} <= {r["method"] for r in cam}


def test_another_packages_error_stays_as_it_said_it():
    """Only the program's own words change language: a failed package's message keeps every word."""
    said = "ValueError: the set of roots is empty near the view of a roller"
    row = {"section": "external", "method": "pylinkage", "setting": "four_bar positions N=360 (Linkage.step)",
           "time_s": None, "max_error_pct": None, "note": f"{word('bench failed', 'en')} {said}"}
    uk = bench.summary([row], "uk").splitlines()[1]
    assert uk.endswith(f"{word('bench failed', 'uk')} {said}") and "four_bar" not in uk


def test_unknown_section_is_one_line_in_the_language(capsys):
    from graphplan.cli.main import main
    assert main(["bench", "--section", "nope", "--lang", "uk", "-o", "/nonexistent/x"]) == 2
    err = capsys.readouterr().err.strip()
    known = ", ".join({**bench.SECTIONS, **bench.ON_REQUEST})
    assert err == "graphplan: " + word("bench unknown section", "uk", name="'nope'", known=known)


@pytest.mark.slow
def test_bench_quick_whole(tmp_path):
    import re
    rows = bench.run(tmp_path, quick=True, show_progress=False)
    assert {r["section"] for r in rows} >= {"speed", "chords", "plans", "stability", "sheet", "external"}
    uk = bench.summary(rows, "uk")
    theirs = (word("bench failed", "uk"), word("bench not compared", "uk"))   # a library's own error stays as said
    ours = "\n".join(ln for ln in uk.splitlines() if not any(w in ln for w in theirs))
    assert not latin_words(ours) - BENCH_NAMES
    en = bench.summary(rows, "en")
    assert not latin_words(ours) & (latin_words(en) - BENCH_NAMES)
    assert not re.search(r"[А-Яа-яіїєґ]", en)
    for name in bench.CHARTS:                                 # every chart, in Ukrainian
        section = [r for r in rows if r["section"] == name]
        assert not latin_words(chart_texts(section, "uk")) - BENCH_NAMES - {"numpy"}, name


def test_bench_refuses_outside_a_checkout(monkeypatch, tmp_path):
    from graphplan.bench import examples
    monkeypatch.setattr(examples, "examples_dir", lambda: tmp_path)
    with pytest.raises(GraphplanError, match="examples/shaper.toml"):
        bench.example("shaper")
