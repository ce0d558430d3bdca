"""Stop 58: the lead's V-twin compressor (LINK58): one crank, two groups II(2-3) and II(4-5) pinned
at the crank pin A, pistons B and C on guides through O1 at 60° and 120°, 900 N gas forces on each
piston's OWN working stroke — and frc58's opposed twin (BOXER_FRC58: guides at 0° and 180°, the
pistons' dead centres at the same crank angles, 1200 N on each piston's compression stroke).
Checked against an independent numpy model of the mechanism (closed-form slider positions, central
differences for velocities and accelerations, virtual power for M_b) — nothing of graphplan's but
the scene's numbers."""
from dataclasses import dataclass

import numpy as np
import pytest

from conftest import scene_study

G = 9.81


@dataclass
class Twin:
    r: float                 # crank, m
    l: float                 # rods, m
    s: float                 # the rods' centres of mass from A, share of l
    rpm: float               # + counter-clockwise
    piston: float            # kg
    load: float              # N on each piston's working stroke
    guides: dict             # piston → guide angle, deg
    inwards: bool            # the working stroke: the piston moving towards O1 (else away)
    q: float = 20.0          # kg/m
    k_i: float = 0.1         # I_S = k·m·l²

    @property
    def omega(self):
        return self.rpm * 2 * np.pi / 60

    def pos(self, phi):
        a = self.r * np.exp(1j * phi)
        out = {"A": a}
        for name, ang in self.guides.items():
            u = np.exp(1j * np.radians(ang))
            rel = a * np.conj(u)
            out[name] = (rel.real + np.sqrt(self.l ** 2 - rel.imag ** 2)) * u
            out["S" + name] = a + self.s * (out[name] - a)
            out["th" + name] = np.angle(out[name] - a)
        return out

    def motion(self, phi, h=1e-4):
        p0, pp, pm = self.pos(phi), self.pos(phi + h), self.pos(phi - h)
        v = {k: (pp[k] - pm[k]) / (2 * h) * self.omega for k in p0}
        a = {k: (pp[k] - 2 * p0[k] + pm[k]) / h ** 2 * self.omega ** 2 for k in p0}
        return v, a

    def working(self, name, phi_deg):
        v, _ = self.motion(np.radians(phi_deg))
        out = _dot(v[name], np.exp(1j * np.radians(self.guides[name])))
        return out < 0 if self.inwards else out > 0

    def balancing_moment(self, phi_deg):
        """M_b (+ counter-clockwise) from M_b·ω1 + Σ F·v + Σ M·ω = 0."""
        v, a = self.motion(np.radians(phi_deg))
        m_rod = self.q * self.l
        i_rod = self.k_i * m_rod * self.l ** 2
        power = 0.0
        for name in self.guides:
            for s, m in ("S" + name, m_rod), (name, self.piston):
                power += _dot(-1j * m * G - m * a[s], v[s])
            power += -i_rod * a["th" + name] * v["th" + name]
            if self.working(name, phi_deg):
                power += -self.load * abs(v[name])
        return -power / self.omega


def _dot(a, b):
    return (a * np.conj(b)).real


# the compressor's working stroke is each piston's compression, outwards to its cylinder head
# (working_stroke = "to_max" along each cylinder's own axis) — each piston on its own
VTWIN = Twin(r=0.05, l=0.2, s=0.35, rpm=-720, piston=2.5, load=900.0, guides={"B": 60.0, "C": 120.0}, inwards=False)
BOXER = Twin(r=0.06, l=0.24, s=0.3, rpm=600, piston=3.0, load=1200.0, guides={"B": 0.0, "C": 180.0}, inwards=False)
P, R = VTWIN.load, VTWIN.r


@pytest.fixture(scope="module")
def link58():
    from review_scenes import LINK58
    return scene_study(LINK58)


@pytest.fixture(scope="module")
def boxer():
    from review_scenes import BOXER_FRC58
    return scene_study(BOXER_FRC58)


@pytest.mark.parametrize("which", ["link58", "boxer"])
def test_each_piston_takes_its_gas_force_on_its_own_working_stroke(which, request):
    """LINK58's P_C followed B's strokes (on from B's dead centre at crank 60°, not C's at 120°): over
    the turn each force acts exactly where its own piston is on its working stroke, nil elsewhere. The
    opposed twin's pistons stop at the same crank angles, and C compresses while B draws in."""
    from graphplan.exact.kinetostatics import analyse
    st, twin = request.getfixturevalue(which), {"link58": VTWIN, "boxer": BOXER}[which]
    phi = np.arange(0.0, 360.0, 5.0) + 2.5          # off the dead centres
    ks = analyse(st, phi)
    for name in twin.guides:
        got = np.abs(next(ld.force for ld in ks.loads if ld.name == f"P_{name}"))
        want = np.array([twin.load if twin.working(name, f) else 0.0 for f in phi])
        assert np.allclose(got, want), (name, phi[~np.isclose(got, want)])
        assert 0 < np.count_nonzero(got) < len(phi)


@pytest.mark.parametrize("which", ["link58", "boxer"])
def test_the_balancing_moment_agrees_with_virtual_power_over_the_turn(which, request):
    """M_b at the force position (LINK58: crank 195°, 45° clockwise from B's inner dead centre, both
    pistons compressing) and round the turn."""
    from graphplan.exact.kinetostatics import analyse, at_scene_angle
    st, twin = request.getfixturevalue(which), {"link58": VTWIN, "boxer": BOXER}[which]
    phi0 = at_scene_angle(st)
    if which == "link58":
        assert abs(phi0 - 195.0) < 1e-9 and all(twin.working(name, phi0) for name in twin.guides)
    phi = np.r_[phi0, np.arange(0.0, 360.0, 10.0) + 2.5]
    got = analyse(st, phi).balancing
    want = np.array([twin.balancing_moment(f) for f in phi])
    assert np.allclose(got, want, rtol=1e-5, atol=1e-4), np.c_[phi, got, want]


def test_the_crank_group_carries_both_rods_reactions(link58):
    """I(0-1) is loaded by R21 and R41 (both rods at the pin A): R01 closes G1 + R21 + R41."""
    from graphplan.exact.kinetostatics import analyse, at_scene_angle
    ks = analyse(link58, [at_scene_angle(link58)])
    crank = next(g for g in ks.groups if g.label == "I(0-1)")
    r = {k: complex(np.atleast_1d(v.force)[0]) for k, v in ks.reactions.items()}
    assert crank.reactions == ("R01",)
    # action and reaction at A: R21 = −R12, R41 = −R14; the crank's balance with its weight
    total = -r["R12"] - r["R14"] + r["R01"] - 1j * VTWIN.q * R * G
    assert abs(total) < 1e-6 * abs(r["R01"])


def test_one_resistance_diagram_per_piston_each_over_its_own_path(link58):
    """The resistance diagram drew P_B only though C carries 900 N too: a second diagram draws P_C
    over s_C — its stroke 2r = 0.1 m out and back, 900 N on C's working stroke (positions 10 … 4),
    nil on its idle stroke."""
    from graphplan.drawing.charts import other_pistons, resistance_record, turn
    t = turn(link58, 360)
    assert other_pistons(t) == ["C"]
    for point, name in ((None, "B"), ("C", "C")):
        rec = resistance_record(t, lang="uk", point=point)
        curve = next(q for q in rec.items if q.kind == "polyline")
        xs = np.array([x for x, _ in curve.points]) * rec.scales["mu_s"]
        ys = np.array([y for _, y in curve.points]) * rec.scales["mu_P"]
        assert abs(xs.max() - 4 * R) < 1e-6 and abs(ys.max() - P) < 1e-6 and ys.min() == 0.0
        assert f"P_{{{name}}}, Н" in [q.text for q in rec.items if q.kind == "text"]
        # the loaded share of the abscissa is one stroke: 2r of the 4r out and back
        loaded = sum(b[0] - a[0] for a, b in zip(curve.points, curve.points[1:]) if a[1] > 0 and b[1] > 0)
        assert abs(loaded * rec.scales["mu_s"] - 2 * R) < 1e-3


def test_the_force_positions_note_names_a_piston_idle_while_the_output_works(link58):
    """The note said nothing where the output B works (every force bound to the working stroke) though
    C may be on its own idle stroke there: at crank 100° B draws 900 N and C none, at 270° the other
    way round — said; at the force position (crank 195°: 45° clockwise from B's inner dead centre at
    240°, where its compression starts) both work and the tables say it all."""
    from graphplan.sheets.forces import idle_words
    assert all(VTWIN.working(name, 195.0) for name in VTWIN.guides)
    assert idle_words(link58, 195.0, "en") == ""
    for phi in (270.0, 100.0):
        on = {name: VTWIN.working(name, phi) for name in VTWIN.guides}
        said = idle_words(link58, phi, "en")
        assert said.startswith(", working stroke" if on["B"] else ", idle stroke"), said
        for name in VTWIN.guides:
            assert (f"P_{{{name}}} = 900 N" if on[name] else f"P_{{{name}}} = 0") in said, said
