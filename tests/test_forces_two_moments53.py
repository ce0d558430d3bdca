"""Review 53 #1 and #4: a slotted-lever pump drive with TWO resistance moments on its lever, 40 N·m on the
working stroke and 260 N·m on the idle stroke (TWO_MOMENTS53, the blind review's coulisse_en.toml).
The force sheet said "idle stroke: M3 = 0" at its idle-stroke position while the 260 N·m acted (its
arc drawn, Table 3 −260); the resistance chart's axis read "M₃, M₃, N·m" and hatched the working
stroke only. The truth here is the scene's own input: which moment acts on which stroke."""
import pytest

from tests.conftest import scene_study
from tests.review_scenes import TWO_MOMENTS53


@pytest.fixture(scope="module")
def st():
    return scene_study(TWO_MOMENTS53)


def _by_stroke(st) -> dict[str, float]:
    return {m.stroke: m.magnitude for m in st.mech.moments}


def test_the_force_position_names_the_moment_acting_on_its_stroke(st):
    """At the scene's force position (idle stroke) the words name the idle stroke's moment with its
    value, in both languages; half a turn on (the working stroke) the working stroke's."""
    import numpy as np

    from graphplan.exact.kinetostatics import at_scene_angle, working_stroke
    from graphplan.sheets.forces import force_position
    phi = float(at_scene_angle(st))
    given = _by_stroke(st)
    assert not bool(np.atleast_1d(working_stroke(st, np.array([phi])))[0])        # the scene's idle position
    en, uk = force_position(st, phi, "en"), force_position(st, phi, "uk", short=True)
    assert en.endswith(f"idle stroke: M_{{3}} = {given['idle']:g} N·m"), en
    assert uk.endswith(f"холостий хід: M_{{3}} = {given['idle']:g} Н·м"), uk
    assert "= 0" not in en
    other = (phi + 180.0) % 360.0
    assert bool(np.atleast_1d(working_stroke(st, np.array([other])))[0])
    assert force_position(st, other, "en").endswith(f"working stroke: M_{{3}} = {given['working']:g} N·m")


def test_the_resistance_chart_names_the_lever_once_and_hatches_both_strokes(st):
    """The chart's force axis is "M_3, N·m" (one symbol for the two moments of link 3); the moment is
    hatched down to the axis on both strokes, each hatch as high as the stroke's given moment."""
    from graphplan.drawing.charts import resistance_record, turn
    t = turn(st)
    rec = resistance_record(t, lang="en")
    labels = [q.text for q in rec.items if q.kind == "text" and "N·m" in q.text and q.text.startswith("M")]
    assert labels == ["M_{3}, N·m"], labels
    mu = rec.scales["mu_P"]
    heights = {round(abs(q.points[1][1] - q.points[0][1]) * mu, 6) for q in rec.items if q.role == "hatch"}
    given = _by_stroke(st)
    assert sorted(heights) == pytest.approx(sorted(given.values())), heights


def test_two_forces_on_one_slider_one_per_stroke():
    """OWN_SPRING_PRESS53: 2400 N on the press's working stroke, a return spring's 350 N on its idle
    stroke, both on B. The force position (idle) names P_B = 350 N; the chart names P_B once and
    hatches both strokes, each as high as its stroke's given force."""
    from graphplan.drawing.charts import resistance_record, turn
    from graphplan.exact.kinetostatics import at_scene_angle
    from graphplan.sheets.forces import force_position
    from tests.review_scenes import OWN_SPRING_PRESS53
    st = scene_study(OWN_SPRING_PRESS53)
    given = {f.stroke: f.magnitude for f in st.mech.forces}
    phi = float(at_scene_angle(st))
    assert force_position(st, phi, "uk").endswith(f"холостий хід: P_{{B}} = {given['idle']:g} Н")
    assert force_position(st, phi + 180.0, "en").endswith(f"working stroke: P_{{B}} = {given['working']:g} N")
    rec = resistance_record(turn(st), lang="en")
    assert [q.text for q in rec.items if q.kind == "text" and q.text.endswith(", N")] == ["P_{B}, N"]
    mu = rec.scales["mu_P"]
    heights = {round(abs(q.points[1][1] - q.points[0][1]) * mu, 6) for q in rec.items if q.role == "hatch"}
    assert sorted(heights) == pytest.approx(sorted(given.values())), heights
