"""The fourth review's corrections of the cam sheet (items 17, 18), on its clockwise knife-edge cam
(e = −6 mm, cycloidal rise, trapezoidal return): no division number threaded on a line — a near-zero
mean ordinate of ds/dφ carried along the number row made "0 _ 1 _ 2 _ 3" — and the cam's centre O
lettered by its dot, not across the follower's axis 8 mm away. Checked on the drawn records."""
from __future__ import annotations

import pytest

from graphplan.drawing.cam import diagrams, profile_drawing
from graphplan.exact.cam import solve
from graphplan.graphic.cam import construct
from graphplan.model.cam import load
from review_scenes import CAM_KN


@pytest.fixture(scope="module")
def cam_kn(tmp_path_factory):
    path = tmp_path_factory.mktemp("cam4") / "kn.toml"
    path.write_text(CAM_KN, encoding="utf-8")
    sol = solve(load(path))
    return sol, construct(sol, measure=False)


def _threaded(numbers, lines) -> list[tuple[str, str]]:
    """The numbers whose box (grown by 0.2 mm) a drawn line passes through."""
    from shapely.geometry import LineString, box
    drawn = [(LineString(p.points), p.step) for p in lines if len(p.points) >= 2]
    out = []
    for q in numbers:
        b = box(*q.bounds()).buffer(0.2)
        out += [(q.text, step) for line, step in drawn if line.intersects(b)]
    return out


@pytest.mark.parametrize("lang", ["uk", "en"])
def test_no_division_number_sits_on_a_line(cam_kn, lang):
    sol, g = cam_kn
    rec = diagrams(sol, g, lang)
    numbers = [q for q in rec.items if q.kind == "text" and q.text.isdigit()]
    assert len(numbers) >= 3 * 20
    lines = [q for q in rec.items if q.kind in ("segment", "polyline")]
    assert _threaded(numbers, lines) == []
    # nor a line broken around it: a horizontal piece in the number's row within 3 mm of its box
    beside = [(q.text, p.step) for q in numbers for p in lines for a, b in zip(p.points, p.points[1:])
              if abs(a[1] - b[1]) < 1e-6 and q.bounds()[1] - 0.5 <= a[1] <= q.bounds()[3] + 0.5
              and min(a[0], b[0]) <= q.bounds()[2] + 3.0 and max(a[0], b[0]) >= q.bounds()[0] - 3.0]
    assert beside == []


def test_o_is_lettered_by_its_centre(cam_kn):
    sol, g = cam_kn
    rec = profile_drawing(sol, g, "uk")
    o = next(q for q in rec.items if q.kind == "text" and q.text == "O")
    x0, y0, x1, y1 = o.bounds()
    gap = max(x0, 0.0, -x1) ** 2 + max(y0, 0.0, -y1) ** 2      # the box's distance from O = (0, 0)
    assert gap ** 0.5 < 3.0
