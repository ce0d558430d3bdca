"""Stop 49's dynamics sheet: the rocking coulisse LINK49 (tests/review_scenes.py) — crank O1A (r =
0.09 m, O1 0.22 m over O) turning clockwise, its stone sliding in the coulisse OB, which carries a
constant 160 N·m against its motion on the working stroke. Everything reduced to the crank has a
closed form here: the coulisse's angle ψ = atan2(d + r·sin φ, r·cos φ), dψ/dφ = r(r + d·sin φ)/|OA|²,
the stroke's ends where the crank is square to the coulisse (the working stroke 180° + 2·asin(r/d) of
the crank's turn), the work of the resistance over a cycle 160·2·asin(r/d) (the swing), gravity's
none."""
from __future__ import annotations

import math
import re

import numpy as np
import pytest
from conftest import scene_study
from review_scenes import LINK49, SHEARS49

R, D, G = 0.09, 0.22, 9.81            # the crank, O1 over O, g
M1, M2, M3 = 4.0, 1.5, 9.0            # crank (S1 at r/2), stone (at A), coulisse (S3 at 0.24 m from O)
I1, I3, MOMENT = 0.006, 0.18, 160.0
SWING = 2.0 * math.asin(R / D)        # the coulisse's swing, rad
STROKE = math.pi + SWING              # the working stroke's turn of the crank from position 0, rad


def closed(phi0: float, u: float) -> tuple[float, float]:
    """M*_c and I*_m at the crank's turn ``u`` (clockwise) from position 0 (crank angle ``phi0``):
    the resistance 160·|ω3/ω1| on the working stroke, gravity's G·dy_S/du, and the masses' kinetic
    energy over ω1²/2 (the stone a point at A)."""
    phi = phi0 - u
    x, y = R * math.cos(phi), D + R * math.sin(phi)
    psi = math.atan2(y, x)
    dpsi = -R * (R + D * math.sin(phi)) / (x * x + y * y)          # dψ/du: u turns clockwise
    resistance = MOMENT * abs(dpsi) if u < STROKE else 0.0
    gravity = G * (-M1 * R / 2 * math.cos(phi) - M2 * R * math.cos(phi) + M3 * 0.24 * math.cos(psi) * dpsi)
    inertia = I1 + M1 * (R / 2) ** 2 + M2 * R ** 2 + (I3 + M3 * 0.24 ** 2) * dpsi ** 2
    return resistance + gravity, inertia


@pytest.fixture(scope="module")
def coulisse():
    """LINK49's equation of motion (exact.dynamics ``analyse``) and its construction as the A1 sheet
    draws it (L = 330 mm, heights × 1.15), with its ``dynamics --json`` document."""
    from graphplan.exact.dynamics import analyse
    from graphplan.graphic.flywheel import redrawn
    from graphplan.report.dynamics import dynamics_json
    dyn = analyse(scene_study(LINK49), None)
    f = redrawn(dyn, None, 0.5, L=330.0, size=1.15)
    return dyn, f, dynamics_json(f)


def test_the_coulisses_reduced_moment_and_inertia_are_the_closed_forms(coulisse):
    """Table 1's M*_c and I*_m at every position equal the closed forms; A_c over a cycle is the
    moment times the swing (gravity's work is none), so M*_d = 160·2·asin(r/d)/2π."""
    _, _, doc = coulisse
    phi0 = math.radians(doc["start_phi_deg"])
    for p in doc["positions"]:
        m, i = closed(phi0, math.radians(p["turn_deg"]))
        assert p["moment_resistance"] == pytest.approx(m, abs=1e-6)
        assert p["inertia"] == pytest.approx(i, rel=1e-6)
    assert doc["work_resistance"] == pytest.approx(MOMENT * SWING, rel=1e-6)
    assert doc["moment_driving"] == pytest.approx(MOMENT * SWING / (2 * math.pi), rel=1e-6)


def test_the_moments_curve_turns_a_corner_where_the_working_stroke_ends(coulisse):
    """The resistance 160·|ω3/ω1| falls to 0 at the stroke's end (ω3 = 0 there): M*_c is continuous
    with a corner, not a jump. The drawn curve reads the closed form at the corner (within the
    ruler's 0.5 mm and a line's width), and on either side of it to a millimetre — not a French
    curve rounding the corner off — and the chords' note takes the equal-area mean in the interval
    that holds it."""
    from graphplan.drawing.flywheel import moments_record
    from graphplan.report.dynamics import chords_note
    _, f, doc = coulisse
    rec = moments_record(f, "uk")
    curve = np.array(next(it for it in rec.items if it.kind == "polyline" and it.step == "M*_c(φ)").points)
    phi0 = math.radians(doc["start_phi_deg"])
    for u in (STROKE - 0.08, STROKE, STROKE + 0.08):
        x = u / (2 * math.pi) * f.L
        drawn = float(np.interp(x, curve[:, 0], curve[:, 1]))
        assert drawn == pytest.approx(closed(phi0, u)[0] / f.mu_M, abs=1.0), u
    k = int(STROKE / (2 * math.pi) * f.divisions)              # the interval the corner is in
    assert f"{k}–{k + 1}" in chords_note(doc, "uk")


@pytest.mark.parametrize("lang", ["uk", "en"])
def test_both_speed_curves_letter_their_extremes_which_give_their_legends_delta(coulisse, lang):
    """ω(φ): each curve's ω_max and ω_min lettered at its highest and lowest drawn points (the
    ordinate axis's ticks give the heights), and (ω_max − ω_min)/ω_m from the printed numbers the
    legend's δ (and the motor's δ_дв) to the figures' rounding; the legend's motor flywheel printed
    as Table 2 prints it."""
    from graphplan.drawing.flywheel import speed_record
    from graphplan.report.dynamics import flywheel_decimals
    from graphplan.util.markup import plain
    _, f, doc = coulisse
    rec = speed_record(f, lang, width=330.0, height=160.0)
    texts = [it for it in rec.items if it.kind == "text"]
    num = lambda t: float(t.replace(",", ".").replace("−", "-"))                     # noqa: E731
    ticks = [(num(it.text), it.points[0][1] + 1.0) for it in texts if it.step == "ω ticks" and it.text != "0"]
    a, b = np.polyfit([v for v, _ in ticks], [y for _, y in ticks], 1)
    legends = [plain(it.text).replace("\u00a0", " ") for it in texts if ":" in it.text and "δ" in it.text]
    assert len(legends) == 2
    curves = [np.array(it.points) for it in rec.items if it.kind == "polyline" and it.role in ("curve", "projection")
              and len(it.points) > 20]
    assert len(curves) == 2
    for k, (curve, legend) in enumerate(zip(curves, legends)):
        got = {}
        for name, pick in (("max", np.max), ("min", np.min)):
            label = next(it for it in texts if it.step == f"ω_{name}" + ("" if k == 0 else " motor"))
            got[name] = num(plain(label.text).split("= ")[1].split()[0])
            assert got[name] == pytest.approx((pick(curve[:, 1]) - b) / a, abs=0.01)
        mean = num(re.search(r"ω_m(?: дв| mot)? = (\d+(?:[.,]\d+)?)", legend).group(1))
        delta = num(re.search(r"δ(?:_дв|_mot)? = (\d+(?:[.,]\d+)?)", legend).group(1))
        assert (got["max"] - got["min"]) / mean == pytest.approx(delta, rel=0.03)
    fl = re.search(r"(\d+[.,]\d+) (?:кг|kg)·m?м?²", legends[1]).group(1)
    assert len(fl.split(",")[-1].split(".")[-1]) == flywheel_decimals(doc)


@pytest.mark.parametrize("lang", ["uk", "en"])
def test_the_two_delta_t_ranges_on_the_sheet_are_named_apart(coulisse, lang):
    """Table 1's δ is a percent of the exact ΔT's range at the positions; the approximate flywheel
    takes ΔT_max − ΔT_min off the drawn curve between them (2,5 − (−55,0) beside 1,4 − (−54,1)),
    and says where (the curve's φ of each); the mean power beside the rule's peak is the motor's
    (through η), and the note a statement."""
    from graphplan.report.dynamics import approximate_note, chords_note, motor_note
    from graphplan.util.markup import plain
    _, _, doc = coulisse
    said = plain(approximate_note(doc, lang)).replace("\u00a0", " ")
    at = re.search(r"ΔT_max (?:гр|gr), ΔT_min (?:гр|gr) (?:з накресленої кривої ΔT\(φ\) при|read off the drawn ΔT\(φ\) curve at) (\d+)° (?:і|and) (\d+)°", said)
    assert at, said
    e = doc["flywheel"]["approximate_energy"]
    assert (int(at.group(1)), int(at.group(2))) == (round(e["max_deg"]), round(e["min_deg"]))
    hi = max(p["energy"] for p in doc["positions"])         # the table's extreme, 1,4 J at 30°
    assert e["max"] > hi                                    # the curve's peak between the positions: another
    assert re.search(r"ΔT_max − ΔT_min = [\d,.]+ − \(", plain(chords_note(doc, lang)).replace("\u00a0", " "))
    said = plain(motor_note(doc, lang)).replace("\u00a0", " ")
    mean = float(re.search(r"ω_m·[^=]*/η = (\d+[.,]\d+)", said).group(1).replace(",", "."))
    assert mean == pytest.approx(MOMENT * SWING / (2 * math.pi) * doc["omega_mean"] / 0.88 / 1000.0, rel=1e-3)
    assert not said.startswith(("Чому", "Why"))


@pytest.mark.parametrize("lang", ["uk", "en"])
def test_a_widened_band_draws_delta_t_over_its_own_phi_axis_and_says_each_scale(coulisse, lang):
    """The band with ΔT(φ)'s φ axis longer than the turned I*(φ)'s (stop 49: 115.5 mm, the height
    bound, beside 225.5 mm of width): ΔT(φ)'s division points span the longer axis, I*(φ)'s the
    shorter, each μ_φ printed is 2π over its own drawn axis, the band no taller than before and its
    nook under ΔT(φ) wider by what ΔT(φ) gained."""
    from graphplan.sheets.dynamics import _band_size, band, nooks
    from graphplan.util.markup import plain
    _, f, _ = coulisse
    base_parts, base_boxes = band(f, lang, 115.5)
    parts, boxes = band(f, lang, 115.5, 225.5)
    spans = {}
    for name, step, axis in (("energy", "ΔT read", 0), ("inertia", "I*_m read", 1)):
        at = [it.points[0][axis] for it in parts[name].items if it.kind == "point" and it.step == step]
        spans[name] = max(at) - min(at)
    assert spans["energy"] == pytest.approx(225.5, abs=1e-6) and spans["inertia"] == pytest.approx(115.5, abs=1e-6)
    for name in ("energy", "inertia"):
        prime = "′" if name == "energy" else "″"     # three scales of φ, three names (stop 52)
        scales = [plain(it.text).replace("\u00a0", " ") for it in parts[name].items if it.kind == "text"
                  and plain(it.text).startswith(f"μ{prime}_φ = 2π/")]
        assert len(scales) == 1, name
        length, mu = (float(v.replace(",", ".")) for v in re.findall(r"(\d+(?:[,.]\d+)?)", scales[0])[1:3])
        assert length == pytest.approx(spans[name], abs=0.05) and mu == pytest.approx(2 * math.pi / length, rel=2e-3)
    assert _band_size(boxes)[1] == pytest.approx(_band_size(base_boxes)[1], abs=1e-6)
    wide = lambda b: max(n[2] - n[0] for n in nooks(b))          # noqa: E731
    left = lambda b: min(v[0] for v in b.values())                # noqa: E731
    assert left(base_boxes) - left(boxes) > 0.8 * 110.0            # the band reaches left by about the gain
    assert wide(boxes) - wide(base_boxes) == pytest.approx(left(base_boxes) - left(boxes), abs=1e-6)


@pytest.fixture(scope="module")
def shears():
    """SHEARS49 (my own): a crank-rocker four-bar whose rocker's extension drives the table D along a
    horizontal guide through the rod CD, 2400 N against D on its working stroke."""
    from graphplan.exact.dynamics import analyse
    from graphplan.graphic.flywheel import redrawn
    from graphplan.report.dynamics import dynamics_json
    dyn = analyse(scene_study(SHEARS49), None)
    return dynamics_json(redrawn(dyn, None, 0.5, L=330.0, size=1.0))


def _table_stroke() -> float:
    """D's stroke along the guide, solved here: B the circles' intersection on the scene's branch
    (O2B turned counter-clockwise from O2→A's side: B = 1), C = O2 + 1.6·(B − O2), D on y = 0.40
    at 0.25 m from C, above it on the positive side (D = 1: the larger x)."""
    O2 = np.array([0.26, 0.05])
    xs = []
    for phi in np.linspace(0.0, 2 * math.pi, 20001):
        A = 0.07 * np.array([math.cos(phi), math.sin(phi)])
        d = float(np.linalg.norm(O2 - A))
        a = (0.25 ** 2 - 0.16 ** 2 + d * d) / (2 * d)
        u = (O2 - A) / d
        B = A + a * u + math.sqrt(0.25 ** 2 - a * a) * np.array([-u[1], u[0]])
        C = O2 + 1.6 * (B - O2)
        xs.append(C[0] + math.sqrt(0.25 ** 2 - (0.40 - C[1]) ** 2))
    return max(xs) - min(xs)


def test_the_shears_work_of_resistance_is_the_force_over_the_stroke(shears):
    """A constant 2400 N against D over its working stroke does 2400·h in a cycle (gravity's work over
    a cycle is none): A_c and M*_d = A_c/2π follow from D's stroke h, solved here from the geometry
    (either branch of B gives the same stroke only for the scene's; a wrong branch fails)."""
    h = _table_stroke()
    assert 0.05 < h < 0.5
    assert shears["work_resistance"] == pytest.approx(2400.0 * h, rel=2e-4)
    assert shears["moment_driving"] == pytest.approx(2400.0 * h / (2 * math.pi), rel=2e-4)


@pytest.mark.slow
def test_the_coulisses_a1_sheet_lets_delta_t_take_the_room_beside_the_band():
    """Stop 49's A1 sheet of LINK49 (~10 s): the band is bound by the turned I*(φ)'s height (φ axis
    115.5 mm), and stood centred under the wider moments with ~120 × 280 mm empty between I*(φ) and
    the tables. ΔT(φ) now takes its own longer φ axis: the drawn ΔT(φ) spans more than I*(φ), and
    between the band's right side and the tables' column at most the composition's gaps are left."""
    from graphplan.drawing.layout import GAP
    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.dynamics import WIDEN_STEP
    from graphplan.sheets.form import form
    from graphplan.sheets.sheet import RAW
    sheet = RAW["dynamics"](scene_study(LINK49), form("A1"), SheetOptions(lang="uk", sheet="dynamics"))
    got = {p.name: p for p in sheet.placed}
    span = lambda name, step, axis: np.ptp([it.points[0][axis] for it in got[name].record.items    # noqa: E731
                                            if it.kind == "point" and it.step == step])
    assert span("energy", "ΔT read", 0) > span("inertia", "I*_m read", 1) + 20.0
    right = max(got[n].record.bounds()[2] for n in ("energy", "wittenbauer", "inertia"))
    tables = min(got[n].record.bounds()[0] for n in ("positions table", "flywheel table"))
    assert tables - right <= 2 * GAP + WIDEN_STEP + 10.0


def test_the_coulisses_kl_and_motor_follow_from_the_exact_flywheel_and_the_catalogue(coulisse):
    """|kl| = J·ω_m²·δ/μ_T with the equation of motion's J (flywheel + rotor): the drawn |kl| within 1.5 of
    the ruler's 0.5-mm divisions of it (Table 2's 0,00 % is the ruler's luck, not a shortcut); and the motor is
    the smallest of the 1000-rpm line of the catalogue (model/motors.toml) whose P_n covers the rule's
    P = M*_c max·ω1/η, M*_c max the closed form's peak over the working stroke."""
    from graphplan.model.motors import catalogue
    dyn, f, doc = coulisse
    J = dyn.flywheel + dyn.constant
    # within 1.5 ruler divisions: the tangents rest on points each read to ±½ division, and since stop 56
    # the chords take the points added at M*_c's breaks (dead centres) too — one reading more each
    assert abs(abs(f.kl) - J * dyn.omega_mean ** 2 * dyn.delta / f.mu_T) <= 1.5 * f.precision
    phi0 = math.radians(doc["start_phi_deg"])
    peak = max(closed(phi0, u)[0] for u in np.linspace(0.0, STROKE, 4001))
    need = peak * doc["omega_mean"] / 0.88 / 1000.0
    assert doc["motor"]["power_needed_kW"] == pytest.approx(need, rel=1e-3)
    line = sorted((m.power_kW, m.name) for m in catalogue() if m.rpm_sync == 1000 and m.power_kW >= need)
    assert doc["motor"]["name"] == line[0][1]
