"""Marks on the position plan and in the kinematics tables a teacher reads (reviews 6 and 7): the
crank's support upright among its twelve lines, the extreme positions lettered A′, A″ / B′, B″ as the
textbook letters them, every thick (acceleration) position's joints lettered, a link's number by its
own link and outside a plate's outline, a plate coupler defined by all its sides. Checked against
plain geometry written here: the dead centres of a crank-slider in closed form, distances to the
links' lines, point in polygon."""
from __future__ import annotations

import cmath
import math

import pytest
from shapely.geometry import LineString, Point, Polygon, box

from conftest import scene_study
from review_scenes import COMPRESSOR, SIXBAR6, SIXBAR7
from graphplan.drawing.plans import joints_at, position_record
from graphplan.graphic.plans import build_plans

# review 6: a crank-rocker whose coupler is a plate ABC; C drives the rod CD to a slider on a 15° guide
PLATE = SIXBAR6

# review 7: a ccw crank-rocker; the rocker's end B drives a slider D on a vertical guide
VERTICAL = SIXBAR7


LEADER_AT = 1.2    # mm: a leader starting this near a label's box is its leader
SAME = 1.0         # mm: a drawn point this near another is drawn on it


def _plans(text: str, mu_l: float | None = None):
    st = scene_study(text)
    return st, build_plans(st, mu_l=mu_l)


def _gap(b, z: complex) -> float:
    return abs(complex(max(b[0] - z.real, 0.0, z.real - b[2]), max(b[1] - z.imag, 0.0, z.imag - b[3])))


def _reads_as(rec, text: str, X: complex) -> bool:
    """Whether a label ``text`` on the drawing reads as the point X: on a leader that ends at X, or
    beside X, nearer it than any other drawn point (a point drawn on X is X's)."""
    labels = [q for q in rec.items if q.kind == "text" and q.text == text]
    assert labels, f"{text} not lettered"
    b = labels[0].ink()
    dots = [complex(*q.points[0]) for q in rec.items if q.kind == "point"]
    for q in rec.items:
        if q.kind == "segment" and q.role == "label":
            ends = [complex(*e) for e in q.points]
            if min(_gap(b, z) for z in ends) < LEADER_AT:
                a = max(ends, key=lambda z: _gap(b, z))            # the end at the point
                c = min(ends, key=lambda z: _gap(b, z))
                ahead = a + 1.2 * (a - c) / abs(a - c)             # the leader produced past its end
                seen = min(dots + [X], key=lambda z: abs(z - ahead))
                return abs(seen - X) < SAME
    return all(_gap(b, z) > _gap(b, X) for z in dots if abs(z - X) > SAME)


@pytest.mark.parametrize("mu_l", [None, 0.004], ids=["default", "A1 sheet's 1:4"])
def test_the_cranks_support_stands_upright_clear_of_the_thick_links(mu_l):
    """review 7 #6: among its twelve lines the crank's support stood tilted 13°, the thick crank of
    position 8 leaving its pivot 40° from straight down: it stands upright (its bar level or plumb)
    where the thick positions' links leave it room, no thick link across its bar or hatching."""
    st, plans = _plans(VERTICAL, mu_l)
    rec = position_record(plans, lettered=False)
    mine = [q for q in rec.items if q.kind == "segment" and q.step == "support O1"]
    bars = [q for q in mine if q.role == "frame" and abs(complex(*q.points[1]) - complex(*q.points[0])) > 9.0]
    assert len(bars) == 1, bars
    (x0, y0), (x1, y1) = bars[0].points
    tilt = math.degrees(math.atan2(y1 - y0, x1 - x0)) % 90.0
    assert min(tilt, 90.0 - tilt) < 1e-6, tilt
    thick = [LineString(q.points) for q in rec.items if q.kind == "segment" and q.role == "link"
             and q.line_width > 0.4]
    assert thick
    symbol = [LineString(q.points) for q in mine if q.role == "hatch"] + [LineString(bars[0].points)]
    assert not any(s.intersects(t) for s in symbol for t in thick)


def _dead_centres(r: float, l: float, e: float, angle_deg: float, side: complex) -> list[tuple[complex, complex]]:
    """A crank-slider's dead centres (scene metres, the crank's pivot at 0, the guide through (e, 0)
    at ``angle_deg``): the slider B where |OB| = l + r (the crank along the rod, A = r·B/|B|) and
    l − r (the crank folded back, A = −r·B/|B|), on the guide's side ``side`` of the crank."""
    P, u = complex(e, 0.0), cmath.exp(1j * math.radians(angle_deg))
    out = []
    for L, sign in ((l + r, 1.0), (l - r, -1.0)):
        b = (P * u.conjugate()).real
        roots = [-b + k * math.sqrt(b * b - abs(P) ** 2 + L * L) for k in (1.0, -1.0)]
        B = min((P + t * u for t in roots), key=lambda z: abs(z - side))
        out.append((B, sign * r * B / abs(B)))
    return out


def test_the_extreme_positions_are_lettered_at_the_dead_centres():
    """review 7 #6: the second dead centre of A was an unlabelled dot beside A6. Both extremes are
    lettered as the textbook letters them — the slider B′, B″ and the crank pin A′, A″ — each at its
    dead centre found in closed form here, the first (′) at position 0 (start = "min")."""
    st, plans = _plans(COMPRESSOR)
    rec = position_record(plans)
    sc = plans.scheme
    lay0 = plans.positions[0].layout
    pts0 = joints_at(sc, lay0)
    O, mu = pts0["O"], plans.mu_l
    path = [joints_at(sc, p.layout)["B"] for p in plans.positions]
    side = (sum(path, 0j) / len(path) - O) * mu
    drawn = {}
    for B, A in _dead_centres(0.065, 0.26, -0.025, 150.0, side):
        drawn[(O + B / mu, O + A / mu)] = abs(O + B / mu - pts0["B"]) < 0.05
    assert sorted(drawn.values()) == [False, True], drawn        # position 0 is one of them
    for (B, A), first in drawn.items():
        mark = "′" if first else "″"
        assert _reads_as(rec, "B" + mark, B), ("B" + mark, B)
        assert _reads_as(rec, "A" + mark, A), ("A" + mark, A)


def test_the_six_bars_second_dead_centre_of_the_crank_pin_is_lettered():
    """review 7's six-bar: A″ stands by the dead centre's dot 2.6 mm from A6, read as its own, and
    the slider's D′ (position 0, start = "max") and D″ likewise."""
    st, plans = _plans(VERTICAL, 0.004)
    rec = position_record(plans)
    texts = {q.text for q in rec.items if q.kind == "text"}
    assert {"A′", "A″", "D′", "D″"} <= texts, texts
    sc = plans.scheme
    r = st.mech.crank.length / plans.mu_l
    O = joints_at(sc, plans.positions[0].layout)["O1"]
    for lay in plans.extremes:
        A = joints_at(sc, lay)["A"]
        assert abs(abs(A - O) - r) < 1e-6
    A0 = joints_at(sc, plans.positions[0].layout)["A"]
    other = next(joints_at(sc, lay)["A"] for lay in plans.extremes
                 if abs(joints_at(sc, lay)["A"] - A0) > SAME)
    assert _reads_as(rec, "A″", other)
    assert _reads_as(rec, "A′", A0)


@pytest.mark.parametrize("text, names", [(PLATE, "ABCD"), (VERTICAL, "ABD")], ids=["plate six-bar", "vertical six-bar"])
def test_every_thick_positions_joints_are_lettered(text, names):
    """review 6 #11: the accel positions 3 and 8 drawn thick, only 3's joints lettered. Position 8's
    joints are lettered with its number, A₈, B₈ …, each read as its own point at position 8."""
    st, plans = _plans(text)
    rec = position_record(plans)
    eight = next(p.layout for p in plans.positions if p.index == 8)
    pts = joints_at(plans.scheme, eight)
    for name in names:
        assert _reads_as(rec, f"{name}_{{8}}", pts[name]), name


def test_a_links_number_stands_by_its_own_link_outside_the_plate():
    """review 6 #8: the rod CD's "4" stood 3 mm under CD and 3 mm over the plate's edge CB, read as
    the plate's. Each number is nearer its own link (at the thick positions) than any other — at most
    half as far (less 0.5 mm) or 1.5 mm nearer, as a reader tells them apart — or on a leader to its
    own link, and no number but the plate's own inside the plate ABC."""
    st, plans = _plans(PLATE)
    rec = position_record(plans)
    sc = plans.scheme
    thick = [p.layout for p in plans.positions if p.key in set(plans.accel_keys)]
    lines, plates = {}, []
    for lay in thick:
        pts = joints_at(sc, lay)
        for name, link in st.mech.links.items():
            js = [pts[j] for j in link.joints]
            geom = (LineString([(z.real, z.imag) for z in js]) if len(js) >= 2
                    else Point(js[0].real, js[0].imag).buffer(2.5))
            lines.setdefault(str(link.number), []).append(geom)
        plates.append(Polygon([(pts[p].real, pts[p].imag) for p in "ABC"]))
    numbers = [q for q in rec.items if q.kind == "text" and q.size == 5.0]
    assert sorted(q.text for q in numbers) == ["1", "2", "3", "4", "5"]
    leaders = [q for q in rec.items if q.kind == "segment" and q.role == "label"]
    for q in numbers:
        b = q.ink()
        r = box(*b)
        if q.text != "2":
            assert not any(p.contains(r.centroid) for p in plates), q.text
        led = [s for s in leaders if min(_gap(b, complex(*e)) for e in s.points) < LEADER_AT]
        if led:
            far = max((complex(*e) for e in led[0].points), key=lambda z: _gap(b, z))
            assert min(g.distance(Point(far.real, far.imag)) for g in lines[q.text]) < 0.5, q.text
            continue
        own = min(r.distance(g) for g in lines[q.text])
        rest = min(r.distance(g) for k, gs in lines.items() if k != q.text for g in gs)
        assert rest >= min(2.0 * own + 0.5, own + 1.5), (q.text, own, rest)


def test_a_plate_coupler_is_given_by_all_its_sides():
    """review 6 #8: Table 4 gave the plate's AB and BC but not AC — two sides do not fix C. The
    plate's three sides, from the scene's C = (0.12, 0.09) m in AB's frame: AB 0.22, AC 0.15,
    BC √(0.1² + 0.09²)."""
    from graphplan.sheets.kintables import dimensions_table, link_lengths
    st, plans = _plans(PLATE)
    sides = dict(link_lengths(st))
    assert sides["AB"] == pytest.approx(0.22) and sides["AC"] == pytest.approx(0.15)
    assert sides["BC"] == pytest.approx(math.hypot(0.22 - 0.12, 0.09))
    rows = [q.text for q in dimensions_table(st, plans.mu_l, "en").items if q.kind == "text"]
    assert {"AB", "AC", "BC", "0.150"} <= set(rows), rows


def _terminal_rows(text: str, head: str) -> dict[str, list[str]]:
    """The terminal's table under the line starting ``head``: row label → its cells."""
    lines = text.splitlines()
    start = next(i for i, l in enumerate(lines) if l.strip().startswith(head))
    out = {}
    for line in lines[start + 1:]:
        if not line.strip():
            break
        cells = line.split()
        out[cells[0]] = cells[1:]
    return out


@pytest.mark.parametrize("lang", ["en", "uk"])
def test_omega_and_epsilon_are_the_same_figures_on_the_sheet_and_in_the_terminal(lang):
    """review 6 #9: Table 1 printed ω3(0) 0.10, ω2(3) −0.94 where `plans` printed 0.096, −0.938.
    Read from a vector drawn to the ruler's 0.5 mm, ω is known to half a division × μv / l — here
    about ±0.02 rad/s — so two decimals, as the sheet writes them; both now write every ω and ε
    cell alike. The check: that bound from the scene's own lengths, then cell by cell."""
    from graphplan.report.plans import plans_json, plans_table
    from graphplan.sheets.kintables import acceleration_table, velocity_table
    st, plans = _plans(PLATE)
    lengths = {"ABC": 0.22, "O2B": 0.18, "CD": 0.32}
    for l in lengths.values():
        assert 0.005 < 0.25 * plans.precision * 2 * plans.mu_v / l < 0.05   # half a division: the 2nd decimal
    doc = plans_json(plans)
    sheet = [[c for c in r] for r in _table_rows(velocity_table(doc, lang, plans.precision))]
    head = sheet[0]
    cols = [i for i, h in enumerate(head) if h.startswith("ω")]
    term = plans_table(plans, lang)
    rows = _terminal_rows(term, "No." if lang == "en" else "№")
    assert len(cols) == 3                                   # ω2, ω3, ω4: the terminal's last three columns
    for r in sheet[1:]:
        mine = [r[i].replace("−", "-").rstrip("*") for i in cols]
        theirs = rows[r[0]][-3:]
        assert mine == theirs, (r[0], mine, theirs)
        assert all(c == "0" or len(c.split("." if lang == "en" else ",")[1]) == 2 for c in mine), mine
    for k, pos in enumerate(p for p in doc["positions"] if "acceleration" in p):
        grid = _table_rows(acceleration_table(pos, 2 + k, lang, plans.precision))
        eps = {r[0]: r[2].replace("−", "-").rstrip("*") for r in grid if r[0].startswith("ε")}
        block = term.split(f" {pos['index']} (φ")[1]
        for sym, cell in eps.items():
            n = sym[3:-1]
            line = next(l for l in block.splitlines() if l.strip().startswith("ε" + "₀₁₂₃₄₅₆₇₈₉"[int(n)]))
            assert line.split()[1] == cell, (sym, cell, line)


def _table_rows(rec) -> list[list[str]]:
    """A table record's rows of cells (texts on one baseline, left to right), the full-width ones."""
    rows: dict[float, list] = {}
    for q in rec.items:
        if q.kind == "text":
            rows.setdefault(round(q.points[0][1], 1), []).append(q)
    grid = [[t.text for t in sorted(r, key=lambda t: t.points[0][0])] for _, r in sorted(rows.items(), reverse=True)]
    width = max(len(r) for r in grid)
    return [r for r in grid if len(r) == width]


@pytest.mark.parametrize("lang", ["en", "uk"])
def test_the_terminals_diagrams_name_the_sheets_table_as_the_sheet_does(lang):
    """review 6 #9: `diagrams` said δ "as the sheet's Table 4 gives it" where the sheet's diagram
    table is Table 5 (Table 4 is the dimensions). The terminal names no table by a number the sheet
    may not give it; it names the table by the title the sheet prints over it."""
    import re

    from graphplan.graphic.diagrams import chord_diagrams
    from graphplan.report.diagrams import diagrams_table
    from graphplan.sheets.kintables import sheet_tables
    st, plans = _plans(PLATE)
    d = chord_diagrams(st, divisions=12, L=240, H1=25, H2=25)
    text = diagrams_table(d, lang)
    assert not re.search(r"Table \d|[Тт]абл(\.|иц\w*) \d", text), text
    tables = dict(sheet_tables(st, plans, d, lang, plans.precision, 1.0))
    title = next(q.text for q in tables["diagram readings table"].items if q.kind == "text"
                 and q.text.startswith(("Table", "Таблиця")))
    assert title.split(". ", 1)[1] in text, (title, text)


def test_each_row_of_the_diagrams_table_writes_one_format():
    """review 7 #17: Table 5's a_D row mixed −10,6 with a bare "0" (a 0 mm ordinate at position 3).
    Every row of the table — the diagrams' s, v, a and the plans' v, a under them — writes its
    numbers to one count of decimals, a zero included."""
    import re

    from graphplan.graphic.diagrams import chord_diagrams
    from graphplan.report.plans import plans_json
    from graphplan.sheets.kintables import readings_table
    st, plans = _plans(VERTICAL, 0.004)
    d = chord_diagrams(st, divisions=12, L=153.6, H1=27, H2=25)
    grid = _table_rows(readings_table(d, plans_json(plans), "uk", 5, plans.precision))
    zeros = 0
    counted = []
    for row in grid[1:]:
        if row[0].startswith("δ"):
            continue
        cells = [c.rstrip("*") for c in row[1:] if c != "—"]
        counts = {len(m.group(1) or "") for m in (re.fullmatch(r"−?\d+(?:,(\d+))?", c) for c in cells) if m}
        assert len(counts) == 1, row
        counted.append((row[0], counts.pop()))
        zeros += sum(1 for c in cells if float(c.replace("−", "-").replace(",", ".")) == 0)
    assert zeros >= 1                      # the dead centre's v = 0 and a 0 mm ordinate of a are there
    # … and a plan's row to the decimals of the diagram's row over it (a column compares like with
    # like: a_D −10,6 over the plan's 2,77 was the mark)
    for (above, d_above), (name, d) in zip(counted, counted[1:]):
        if not name.startswith(("s", "v", "a")):
            assert d == d_above, (above, name)
