"""The composition on mechanisms nobody has drawn: sheets of random coursework mechanisms of every kind
of the examples (crank-slider, four-bar, the shaping and the slotting machines' slotted links; random
lengths, offsets, speeds, masses and resistances) carry no defect a teacher would send back, read off
the sheets' own records (sheets.compose.defects: no lettering on a line or on lettering, no drawing
in another's box, the velocity plans in position order, everything in the frame and out of the title
block) and counted on the rendered sheet as a reader's eye sees it (tests/inkcheck.py)."""
from __future__ import annotations

import json
import subprocess
import sys

import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from conftest import ROOT, composed
from coursework_scenes import crank_slider, four_bar, shaper, slotter
from graphplan.exact.positions import study
from graphplan.model.mechanism import Drive
from graphplan.model.scene import loads
from graphplan.sheets.compose import SheetOptions, defects
from graphplan.sheets.form import form
from graphplan.sheets.sheet import BUILDERS
from graphplan.util.errors import GraphplanError

RPM = st.floats(30.0, 1500.0)
KG_PER_M = st.floats(10.0, 200.0)
FORCE = st.floats(200.0, 8000.0)
KG = st.floats(1.0, 60.0)


@st.composite
def crank_sliders(draw):
    return crank_slider(draw(st.floats(0.03, 0.2)), draw(st.floats(2.8, 6.0)), draw(st.floats(-0.4, 0.4)),
                        draw(RPM), draw(KG_PER_M), draw(FORCE), draw(KG))


@st.composite
def four_bars(draw):
    """A Grashof crank-rocker with 5 % to spare on both assembly conditions, O2 above or below O1's
    level, either sense, the coupler a plate ABC loaded at C or a bar."""
    r = draw(st.floats(0.02, 0.15))
    d = r * draw(st.floats(2.2, 5.0))
    rocker = d * draw(st.floats(0.5, 1.2))
    m = 0.05 * d
    lo, hi = max(d + r - rocker, rocker - (d - r)) + m, rocker + (d - r) - m
    assume(hi > lo)
    coupler = lo + (hi - lo) * draw(st.floats(0.0, 1.0))
    plate = draw(st.none() | st.tuples(st.floats(0.2, 1.2), st.sampled_from([-1.0, 1.0]), st.floats(0.1, 0.4)))
    return four_bar(r, d, coupler, rocker, draw(RPM), draw(KG_PER_M), draw(st.floats(-25.0, 25.0)),
                    draw(st.booleans()), None if plate is None else (plate[0], plate[1] * plate[2]),
                    draw(FORCE))


@st.composite
def shapers(draw):
    return shaper(draw(st.floats(1.3, 2.0)), draw(st.floats(0.2, 0.6)), draw(st.floats(0.3, 0.7)),
                  draw(st.floats(0.75, 0.9)), draw(st.floats(0.4, 0.9)), draw(st.floats(30.0, 300.0)),
                  draw(KG_PER_M), draw(FORCE), draw(KG))


@st.composite
def slotters(draw):
    r = draw(st.floats(0.06, 0.2))
    return slotter(r, draw(st.floats(0.2, 0.5)), r * draw(st.floats(0.4, 0.9)), r * draw(st.floats(2.0, 4.0)),
                   draw(st.floats(-0.2, 0.2)), draw(st.floats(30.0, 300.0)), draw(KG_PER_M), draw(FORCE), draw(KG))


KINDS = {"crank_slider": crank_sliders(), "four_bar": four_bars(), "shaper": shapers(), "slotter": slotters()}


def _sheet(text: str, kind: str, fmt: str = "A1"):
    """The sheet of a generated scene, or a rejected example where the program refuses the scene
    (a mechanism that locks over the turn is refused with one line, as it should be)."""
    try:
        scene = study(loads(text, "<generated>"))
        # every sheet of a scene counts its dynamics document's sheets (sheets/sheet.py ``pages_of``):
        # a cycle no catalogue motor drives (~40 % of the generated crank-sliders) refuses them all —
        # refused here by the very analysis that sheet makes (remembered for it), not after the
        # kinematics and force sheets were composed for it (5–7 s an example)
        from graphplan.sheets.dynamics import _analysed
        if scene.mech.task.flywheel or scene.mech.drive != Drive():
            _analysed(scene, None)
        # composed alone (conftest ``composed``): the drawings, tables and notes are what is checked,
        # not the title block's project numbers (test_sheetset.py) — numbering a generated scene's
        # kinematics sheet planned its force analysis too, to count it (half the test's CPU)
        return composed(kind, scene, form(fmt), SheetOptions(sheet=kind))
    except GraphplanError:
        assume(False)


QUICK = settings(max_examples=2, deadline=None, derandomize=True, database=None,
                 suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])
LONG = settings(max_examples=40, deadline=None, database=None,
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])


@pytest.mark.parametrize("mechanism", list(KINDS))
@pytest.mark.parametrize("kind", ["kinematics", "forces"])
def test_sheets_of_new_mechanisms_have_no_defects(mechanism, kind):
    @QUICK
    @given(KINDS[mechanism])
    def check(text):
        sheet = _sheet(text, kind)
        assert defects(sheet) == [], text
        if kind == "kinematics":       # tables 1, 2, 3 … in reading order; one μ symbol, one value
            from test_sheets_composition import mu_values, table_numbers
            numbers = table_numbers(sheet)
            assert numbers == [str(k) for k in range(1, len(numbers) + 1)] and len(numbers) >= 3, (numbers, text)
            assert all(len(v) == 1 for v in mu_values(sheet).values()), (mu_values(sheet), text)
    check()


@pytest.mark.slow
@pytest.mark.parametrize("mechanism", ["crank_slider", "shaper"])
def test_sets_of_new_mechanisms_have_no_defects(mechanism):
    """(A set counts its scene's other sets' sheets too — the dynamics set's scale search: 7–25 s an
    example; the default run keeps the examples' sets in test_sheets_composition and test_sets_fill.)"""
    @QUICK
    @given(KINDS[mechanism])
    def check(text):
        sheet = _sheet(text, "kinematics", "A3")
        assert defects(sheet) == [], text
        from test_sheets_composition import mu_values, table_numbers
        numbers = table_numbers(sheet)
        assert numbers == [str(k) for k in range(1, len(numbers) + 1)] and len(numbers) >= 3, (numbers, text)
        assert all(len(v) == 1 for v in mu_values(sheet).values()), (mu_values(sheet), text)
    check()


@pytest.mark.slow
@pytest.mark.parametrize("mechanism,kind,fmt", [(m, k, f) for m in KINDS for k, f in
                                                (("kinematics", "A1"), ("forces", "A1"), ("kinematics", "A2"),
                                                 ("dynamics", "A1")) if not (m == "four_bar" and k == "dynamics")])
def test_many_new_mechanisms(mechanism, kind, fmt):
    @LONG
    @given(KINDS[mechanism])
    def check(text):
        assert defects(_sheet(text, kind, fmt)) == [], text
    check()


def test_a_dynamics_sheet_that_cannot_hold_its_diagrams_becomes_a_set():
    """A fast crank-slider with a small resistance: the energy–mass diagram's tangents cut the ΔT
    axis far apart; the diagrams are drawn smaller, else carried over to a second sheet — never
    past the frame. (Composed alone, ``conftest.composed``: the project's numbering is not read here.)"""
    from conftest import composed
    text = crank_slider(0.1875, 3.0, 0.0, 448.0, 10.0, 200.0, 1.0)
    sheet = composed("dynamics", study(loads(text, "<generated>")), form("A1"), SheetOptions(sheet="dynamics"))
    assert defects(sheet) == []


def _rendered(texts: dict[str, tuple[str, str]]) -> dict[str, list]:
    """Each scene's sheet drawn and rendered in a fresh process (the packaged fonts registered before
    cairo draws anything); its overprinted words (tests/inkcheck.py)."""
    code = ("import json, sys\n"
            f"sys.path.insert(0, {str(ROOT / 'tests')!r})\n"
            "from graphplan.drawing.fonts import register\n"
            "register()\n"
            "from inkcheck import overprinted\n"
            "from graphplan.exact.positions import study\n"
            "from graphplan.model.scene import loads\n"
            "from graphplan.sheets.compose import SheetOptions\n"
            "from graphplan.sheets.form import form\n"
            "from graphplan.sheets.sheet import BUILDERS\n"
            "out = {}\n"
            "for name, (text, kind) in json.loads(sys.stdin.read()).items():\n"
            "    sheet = BUILDERS[kind](study(loads(text, name)), form('A1'), SheetOptions(sheet=kind))\n"
            "    out[name] = [overprinted(page.svg()) for page in sheet.pages]\n"
            "print(json.dumps(out))\n")
    done = subprocess.run([sys.executable, "-c", code], input=json.dumps(texts), capture_output=True, text=True,
                          cwd=ROOT, check=True)
    return json.loads(done.stdout)


FRESH = {   # one new mechanism of each kind, as a teacher tried them (a 150 mm crank, a 40 mm one …)
    "crank_slider": (crank_slider(0.15, 4.0, 0.0, 300.0, 60.0, 2000.0, 20.0), ("kinematics", "forces")),
    "four_bar": (four_bar(0.04, 0.15, 0.15, 0.08, 90.0, 40.0), ("kinematics", "forces")),
    "shaper": (shaper(1.5, 0.35, 0.4, 0.8, 0.4, 120.0, 100.0, 3000.0, 30.0), ("kinematics", "forces")),
    "slotter": (slotter(0.1, 0.4, 0.07, 0.3, 0.1, 90.0, 50.0, 1000.0, 25.0), ("kinematics", "forces")),
}


@pytest.mark.parametrize("mechanism", list(FRESH))
def test_new_mechanisms_print_no_word_over_another(mechanism):
    """Counted on the rendered sheets (kinematics and forces) of a new mechanism of each kind."""
    text, kinds = FRESH[mechanism]
    found = _rendered({f"{mechanism} {k}": (text, k) for k in kinds})
    assert all(hits == [] for pages in found.values() for hits in pages), found
