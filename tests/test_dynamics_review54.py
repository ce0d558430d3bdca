"""Stop 54's dynamics sheet. What grading marked on the gallery's shaper (A1): its energy–mass
diagram is ~330 mm tall (l far under the I* axis, ψ ≈ 57–59°), the band of the projections stood at
the right over the title block, and the room under ΔT(φ) left of that diagram — ~210 × 470 mm — was
empty paper while ω(φ) and the notes stood squeezed beside 2.5-mm tables. The "nook" composition
sets ω(φ) over the notes in that room; checked against the drawing's own boxes."""
from __future__ import annotations

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
