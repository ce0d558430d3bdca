"""Stop 54's dynamics sheet. What grading marked on the gallery's shaper (A1): its energy–mass
diagram is ~330 mm tall (l far under the I* axis, ψ ≈ 57–59°), the band of the projections stood at
the right over the title block, and the room under ΔT(φ) left of that diagram — ~210 × 470 mm — was
empty paper while ω(φ) and the notes stood squeezed beside 2.5-mm tables. The "nook" composition
sets ω(φ) over the notes in that room; checked against the drawing's own boxes."""
from __future__ import annotations

import numpy as np
import pytest

from graphplan.drawing.layout import Leaf


def _boxes(dx: float = 0.0) -> dict[str, tuple]:
    """A band's boxes in its frame (``sheets.dynamics.band``): ΔT(φ) at the left over an empty room,
    the energy–mass diagram 400 mm tall right of it, the turned I*(φ) under that diagram."""
    return {"energy": (-260.0 + dx, -90.0, -10.0, 0.0), "wittenbauer": (-10.0, -400.0, 200.0, 10.0),
            "inertia": (20.0, -600.0, 200.0, -400.0)}


LINES = ["δ = 0,04; ω_m = 20,42 рад/с", "Масштаби: μ_M = 20 Н·м/мм, L = 290 мм", "J = 341,4 кг·м²"]


def test_the_nook_under_delta_t_holds_the_speed_over_the_notes():
    """The room under ΔT(φ) (250 × 500 mm less the gaps) holds a 180 × 130 mm ω(φ) over three
    lines of notes; it is the room's full height, from the band's foot to a gap under ΔT(φ)."""
    from graphplan.sheets.dynamics import GAP, speed_nook
    got = speed_nook(_boxes(), Leaf("speed", 180.0, 130.0), LINES)
    assert got is not None
    (x0, y0, x1, y1), w = got
    assert x0 == pytest.approx(-260.0) and y0 == pytest.approx(-600.0)
    assert y1 == pytest.approx(-90.0 - GAP)
    assert x1 <= -10.0 - GAP + 1e-9 and w == pytest.approx(x1 - x0)


@pytest.mark.parametrize("speed, dx", [((180.0, 560.0), 0.0), ((180.0, 130.0), 150.0)])
def test_no_nook_where_the_speed_or_its_width_does_not_fit(speed, dx):
    """Too tall an ω(φ) for the room with the notes, or a ΔT(φ) so short that the room is narrower
    than ``NOOK_SPEED``: no nook ("side" then keeps ω(φ) beside the column)."""
    from graphplan.sheets.dynamics import speed_nook
    assert speed_nook(_boxes(dx), Leaf("speed", *speed), LINES) is None


@pytest.fixture(scope="module")
def shaper():
    from conftest import example_sheet
    return example_sheet("shaper", "dynamics", "A1", "uk")


def test_the_shapers_room_under_delta_t_holds_the_speed_and_the_notes(shaper):
    """On the shaper's A1 sheet ω(φ) and the notes stand under ΔT(φ), left of the energy–mass
    diagram and of the turned I*(φ), clear of every box of the band; from ΔT(φ)'s foot to the
    field's, no strip of that room taller than 60 mm is left empty (it was ~470 mm)."""
    from graphplan.sheets.compose import field_of
    from graphplan.sheets.form import form
    by = {p.name: p for p in shaper.placed}
    ex0, ey0, ex1, _ = by["energy"].box
    wx0 = min(by["wittenbauer"].box[0], by["inertia"].box[0])
    under = []
    for name in ("speed", "notes"):
        x0, y0, x1, y1 = by[name].record.bounds()
        assert ex0 - 1e-6 <= x0 and x1 <= wx0 + 1e-6 and y1 <= ey0 + 1e-6, name
        for other in ("energy", "wittenbauer", "inertia"):
            b = by[other].box
            assert x1 <= b[0] or b[2] <= x0 or y1 <= b[1] or b[3] <= y0, (name, other)
        under.append((y0, y1))
    foot = field_of(form("A1"))[1]
    edges = sorted(under)
    gaps = [edges[0][0] - foot] + [b[0] - a[1] for a, b in zip(edges, edges[1:])] + [ey0 - edges[-1][1]]
    assert max(gaps) <= 60.0, gaps


# -- LINK54, the lead's jaw crusher: the flywheel and the motor against a calculation of our own -----------

O1, O2, O3 = np.array([0.0, 0.0]), np.array([0.17, -0.29]), np.array([-0.24, 0.10])
R1, AB, O2B, BC, O3C = 0.04, 0.36, 0.18, 0.20, 0.40
MASS = {2: 20.0, 3: 6.0, 4: 6.0, 5: 40.0}
INERTIA = {1: 0.08, 2: 0.25, 3: 0.02, 4: 0.025, 5: 0.9}
G, MOMENT, W1 = 9.81, 900.0, 250 * np.pi / 30


def _meet(p, rp, q, rq, side):
    """The intersection of the circles (p, rp) and (q, rq) on ``side`` of p→q (arrays of points)."""
    d = q - p
    D = np.hypot(d[..., 0], d[..., 1])[..., None]
    a = (rp ** 2 - rq ** 2 + D ** 2) / (2 * D)
    h = np.sqrt(rp ** 2 - a ** 2)
    e = d / D
    return p + a * e + side * h * np.stack([-e[..., 1], e[..., 0]], axis=-1)


def _crusher(phi):
    """The jaw crusher's points at crank angles ``phi`` (rad, from x, ccw): the knee B below the
    pitman (the toggle plates' joint under O2), the jaw's end C under O3."""
    A = O1 + R1 * np.stack([np.cos(phi), np.sin(phi)], axis=-1)
    B = _meet(A, AB, np.broadcast_to(O2, A.shape), O2B, -1.0)
    C = _meet(B, BC, np.broadcast_to(O3, A.shape), O3C, 1.0)
    return A, B, C


def _reduced(phi, h=1e-6):
    """I*_m and M*_c by the definitions (REFERENCE §8): Σ m(v_S/ω1)² + I_S(ω/ω1)², and −(the loads'
    power)/ω1 — gravity on the links 2–5 and 900 N·m against the jaw while its angle falls — with
    the analogues by central differences of the closed-form positions."""
    def state(p):
        A, B, C = _crusher(p)
        ang = lambda v: np.unwrap(np.arctan2(v[..., 1], v[..., 0]))  # noqa: E731
        return ({2: (A + B) / 2, 3: (O2 + B) / 2, 4: (B + C) / 2, 5: (O3 + C) / 2},
                {2: ang(B - A), 3: ang(B - O2), 4: ang(C - B), 5: ang(C - O3)})
    (s1, t1), (s0, t0) = state(phi + h), state(phi - h)
    I, P = np.full(phi.shape, INERTIA[1]), np.zeros(phi.shape)
    for k in (2, 3, 4, 5):
        v, w = (s1[k] - s0[k]) / (2 * h), (t1[k] - t0[k]) / (2 * h)
        I += MASS[k] * (v ** 2).sum(axis=-1) + INERTIA[k] * w ** 2
        P += -MASS[k] * G * v[..., 1]
        if k == 5:
            P += np.where(w < 0, MOMENT * w, 0.0)
    return I, -P


@pytest.fixture(scope="module")
def crusher():
    from conftest import scene_study
    from review_scenes import LINK54

    from graphplan.exact.dynamics import analyse
    return analyse(scene_study(LINK54))


def _position0() -> float:
    """Position 0: the jaw at its largest angle (start = "max")."""
    from scipy.optimize import minimize_scalar
    phi = np.radians(np.arange(0.0, 360.0, 0.5))
    jaw = np.unwrap(np.arctan2(*(_crusher(phi)[2] - O3).T[::-1]))
    k = int(np.argmax(jaw))
    got = minimize_scalar(lambda p: -np.arctan2(*(_crusher(np.array([p]))[2][0] - O3)[::-1]),
                          bracket=(phi[k] - 0.01, phi[k], phi[k] + 0.01))
    return float(got.x)


def test_the_crushers_reduced_inertia_and_moment_are_the_definitions():
    """At the twelve positions from the jaw's largest angle, I*_m and M*_c as the sheet's Table 1
    prints them equal the definitions computed here from the closed-form positions."""
    from conftest import scene_study
    from review_scenes import LINK54

    from graphplan.exact.dynamics import reduce
    turn = np.radians(np.arange(0.0, 360.0, 30.0))
    got = reduce(scene_study(LINK54), turn)
    I, M = _reduced(_position0() + turn)
    assert got.inertia == pytest.approx(I, rel=1e-5)
    assert got.moment == pytest.approx(M, abs=1e-3)


def test_the_crushers_flywheel_is_wittenbauers_and_its_motor_the_catalogues(crusher):
    """Over the turn (0.1° steps): ΔT = ∫(M*_d − M*_c)dφ, the tangents to the energy–mass curve at
    tg ψ = ω_m²(1 ± δ)/2 cut the ΔT axis at k and l, J = (k − l)/(ω_m²δ); the flywheel is J less
    the rotor reduced, I_rot·(n_n/n_1)² of the motor the rule picks: the 750-rpm line's smallest
    with P_n ≥ max M*_c·ω_1/η (motors.toml read here) — 4АМ132S8, 4 kW, 719 rpm."""
    import tomllib
    from pathlib import Path
    turn = np.radians(np.arange(0.0, 360.0, 0.1))
    I, M = _reduced(_position0() + turn)
    step = turn[1]
    work = np.concatenate([[0.0], np.cumsum((M[1:] + M[:-1]) / 2 * step)])
    total = work[-1] + (M[-1] + M[0]) / 2 * step
    dT = total / (2 * np.pi) * turn - work
    delta = 0.05
    k = np.max(dT - W1 ** 2 * (1 + delta) / 2 * I)
    l_ = np.min(dT - W1 ** 2 * (1 - delta) / 2 * I)
    J = (k - l_) / (W1 ** 2 * delta)
    assert crusher.flywheel_total == pytest.approx(J, rel=2e-3)
    power = M.max() * W1 / 0.85 / 1000
    assert power == pytest.approx(crusher.drive.power_needed_kW, rel=1e-3)
    path = Path(__file__).resolve().parents[1] / "graphplan" / "data" / "motors.toml"
    line = [m for m in tomllib.loads(path.read_text(encoding="utf-8"))["motor"] if m["rpm_sync"] == 750]
    chosen = min((m for m in line if m["power_kW"] >= power), key=lambda m: m["power_kW"])
    assert crusher.drive.motor.name == chosen["name"] == "4АМ132S8"
    rotor = chosen["inertia"] * (chosen["rpm_rated"] / 250.0) ** 2
    assert crusher.flywheel == pytest.approx(J - rotor, rel=3e-3)


def test_the_shapers_psi_are_lettered_to_one_count_of_decimals(shaper):
    """ψ_max and ψ_min on the energy–mass diagram and in the notes to two decimals both (the shaper's
    read "ψ_max = 59,06°" beside "ψ_min = 57°": its ψ_min is 57.00°), each arctan of its tg ψ =
    μ_I·ω_m²(1 ± δ)/(2μ_T) from the notes' own scales."""
    import re

    from graphplan.util.markup import plain
    texts = [plain(p.text) for q in shaper.placed for p in q.record.items if p.kind == "text"]
    said = [m for t in texts for m in re.findall(r"ψ_?(max|min) = (\d+),(\d+)°", t)]
    assert {m[0] for m in said} == {"max", "min"} and len(said) >= 4, said
    assert {len(m[2]) for m in said} == {2}, said
    notes = " ".join(t for q in shaper.placed if q.name == "notes" for t in
                     (plain(p.text) for p in q.record.items if p.kind == "text"))
    mu_T = float(re.search(r"μ_?T = [^=]*= (\d+(?:,\d+)?) Дж/мм", notes).group(1).replace(",", "."))
    mu_I = float(re.search(r"μ_?I = (\d+(?:,\d+)?) кг", notes).group(1).replace(",", "."))
    w = 195 * np.pi / 30
    for name, sign in (("max", 1), ("min", -1)):
        want = np.degrees(np.arctan(mu_I * w ** 2 * (1 + sign * 0.04) / (2 * mu_T)))
        for m in said:
            if m[0] == name:
                assert float(f"{m[1]}.{m[2]}") == pytest.approx(want, abs=0.006), (name, m)


@pytest.mark.slow
def test_the_crushers_a3_set_draws_delta_t_longer_than_the_turned_inertia():
    """LINK54's A3 set: the band's sheet held I*(φ) turned over 70 mm and ΔT(φ) over the same 70 mm
    (12 divisions 5.8 mm apart) with ~70 mm of the sheet empty beside it; ΔT(φ) is now drawn over a
    longer φ axis than I*(φ) (each stating its own μ_φ), the band still inside the sheet's field."""
    import re
    from types import SimpleNamespace

    from conftest import scene_study
    from review_scenes import LINK54

    from graphplan.sheets.compose import field_of
    from graphplan.sheets.form import form
    from graphplan.sheets.sheet import BUILDERS
    from graphplan.util.markup import plain
    args = SimpleNamespace(positions=None, accel=None, precision=0.5, lang="uk", sheet="dynamics")
    sheet = BUILDERS["dynamics"](scene_study(LINK54), form("A3"), args)
    page = next(pg for pg in sheet.pages if any(p.name == "energy" for p in pg.placed))
    by = {p.name: p.record for p in page.placed}
    spans = {}
    for name, step, axis in (("energy", "ΔT read", 0), ("inertia", "I*_m read", 1)):
        at = [p.points[0][axis] for p in by[name].items if p.kind == "point" and p.step == step]
        spans[name] = max(at) - min(at)
        said = [plain(p.text) for p in by[name].items if p.kind == "text" and "_φ = 2π/" in plain(p.text)]
        assert len(said) == 1 and float(re.search(r"2π/(\d+)", said[0]).group(1)) == pytest.approx(spans[name])
    assert spans["energy"] >= spans["inertia"] + 20.0 - 1e-6, spans
    x0, y0, x1, y1 = field_of(page.form)
    for name in ("energy", "wittenbauer", "inertia"):
        b = by[name].bounds()
        assert x0 - 1e-6 <= b[0] and b[2] <= x1 + 1e-6 and y0 - 1e-6 <= b[1] and b[3] <= y1 + 1e-6, name



@pytest.mark.slow
def test_the_energy_mass_diagram_outweighs_the_speed_chart():
    """Review 54 #15 (the coupler-slider six-bar, A1 en): the secondary ω(φ) chart (with its legend)
    no longer dwarfs the energy–mass diagram, the sheet's main construction (its axes and curve): at
    most twice its box's area — it was ~6 times (ω(φ) ~334 × 244 mm beside the diagram's ~130 × 99);
    measured on the placed drawings. (Added in 9ac95c5, lost with cc1263e's revert of another test.)"""
    from conftest import scene_sheet
    from review_scenes import COUPLER_SLIDER54
    sheet = scene_sheet(COUPLER_SLIDER54, "dynamics", "A1", "en")
    by = {p.name: p for p in sheet.placed}
    band = next(q for q in sheet.placed if q.name in ("band", "wittenbauer"))
    witt = [p for p in band.record.items if (p.step or "").startswith(("ΔT(I*)", "I* axis", "ΔT axis"))]
    xs = [x for p in witt for x, _ in p.points]
    ys = [y for p in witt for _, y in p.points]
    sx0, sy0, sx1, sy1 = by["speed"].record.bounds()
    assert (sx1 - sx0) * (sy1 - sy0) <= 2.0 * (max(xs) - min(xs)) * (max(ys) - min(ys))
