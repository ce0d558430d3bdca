"""The gear sheet as a teacher signs it (issue 32): on A1 the meshing is the main drawing — on top, its
scale the title block's —; an A2/A3 set is a proper set: the meshing
first, at the largest GOST 2.302 scale in the 40–60 mm band that fits the first sheet (checked by
drawing the next larger one here), every sheet holding a drawing or a table (never the notes alone),
each table whole on one sheet and the tables in order, the sheets numbered 1…N of N, the later ones
under form 2a. Scenes: the examples, the second and third reviews' and two of this round's (17/40
"auto" with a type-B train, 10/25 shifted against undercut with a type-A train of four planets)."""
from __future__ import annotations

import functools
import tomllib

import pytest

import review_scenes
from conftest import ROOT

SCENES = {"gears": None, "gears_b": None, "review2": review_scenes.GEARS_REVIEW, "review3": review_scenes.GEARS12,
          "z17_40": review_scenes.GEARS_17_40, "z10_25": review_scenes.GEARS_10_25}
DRAWINGS = ("meshing", "sliding", "planetary")
TABLES = ("geometry", "quality", "train")             # Tables 1, 2, 3


def scene(name: str):
    from graphplan.model.gears import build, load
    text = SCENES[name]
    if text is None:
        return load(ROOT / "examples" / f"{name}.toml")
    return build(tomllib.loads(text), f"<{name}>")


@functools.lru_cache(maxsize=None)
def sheet(name: str, fmt: str):
    from graphplan.sheets.compose import SheetOptions
    from graphplan.sheets.form import form
    from graphplan.sheets.sheet import BUILDERS
    g = scene(name)
    lang = dict(g.meta).get("lang", "uk")
    if SCENES[name] is None:        # an example's: the very sheet the gallery's and test_gears' tests read, shared
        from conftest import example_sheet
        return example_sheet(name, "gears", fmt, lang)
    return BUILDERS["gears"](g, form(fmt), SheetOptions(lang=lang, sheet="gears"))


def size(b) -> tuple[float, float]:
    return b[2] - b[0], b[3] - b[1]


@pytest.mark.parametrize("name", list(SCENES))
def test_the_meshing_heads_the_a1_sheet_and_gives_its_scale(name):
    """The meshing on top, the planetary pictures in the row under it (stop 49: no longer capped by the
    meshing's size — capped, they left 61-mm bands empty over and under the drawings)."""
    s = sheet(name, "A1")
    boxes = {p.name: p.record.bounds() for p in s.placed if p.name in DRAWINGS}
    assert boxes["planetary"][3] <= boxes["meshing"][1] + 1e-6, (boxes["meshing"], boxes["planetary"])
    # the title block's scale is the meshing's
    k = 1e-3 / next(p for p in s.placed if p.name == "meshing").record.scales["mu_l"]
    assert s.fields["scale"] in (f"{k:g}:1".replace(".", ","), f"{k:g}:1", f"1:{1 / k:g}".replace(".", ","))


SETS = [("gears", "A3"), ("z17_40", "A3"), ("review2", "A3"), ("gears_b", "A2")]


@pytest.mark.parametrize("name, fmt", SETS)
def test_a_set_holds_a_drawing_or_a_table_on_every_sheet_the_tables_whole_and_in_order(name, fmt):
    from graphplan.sheets.compose import defects, field_of
    s = sheet(name, fmt)
    pages = s.pages
    assert len(pages) > 1 and defects(s) == []
    where: dict[str, list[int]] = {}
    for n, page in enumerate(pages, 1):
        names = [p.name for p in page.placed]
        assert any(x in DRAWINGS or x in TABLES for x in names), (n, names)       # never the notes alone
        for x in names:
            where.setdefault(x, []).append(n)
        x0, y0, x1, y1 = field_of(page.form)
        for p in page.placed:                                                   # whole, inside the field
            b = p.record.bounds()
            assert x0 - 1e-6 <= b[0] and b[2] <= x1 + 1e-6 and y0 - 1e-6 <= b[1] and b[3] <= y1 + 1e-6, p.name
        assert page.fields["sheet"] == str(n) and page.fields["sheets"] == str(len(pages))
    assert all(len(v) == 1 for v in where.values()), where                      # each block once
    assert [where[t][0] for t in TABLES] == sorted(where[t][0] for t in TABLES)  # Tables 1, 2, 3 in order
    assert where["meshing"] == [1]
    first = {p.name: size(p.record.bounds()) for p in pages[0].placed if p.name in DRAWINGS}
    area = {n: w * h for n, (w, h) in first.items()}
    assert max(area, key=area.get) == "meshing"


@pytest.mark.parametrize("name, fmt", SETS)
def test_a_set_carries_form_1_then_form_2a(name, fmt):
    from graphplan.sheets.form import BLOCK_2A_H, BLOCK_H
    for n, page in enumerate(sheet(name, fmt).pages, 1):
        block = [q for q in page.record.items if q.step == "title block"]
        ys = [y for q in block for _, y in q.points] if block else []
        tall = max(ys) - min(ys)
        assert abs(tall - (BLOCK_H if n == 1 else BLOCK_2A_H)) < 1.0, (n, tall)


@pytest.mark.parametrize("name, fmt", SETS[:3])
def test_the_set_draws_the_meshing_at_the_largest_band_scale_that_fits_its_first_sheet(name, fmt):
    """The next larger GOST 2.302 scale whose whole depth 2.25m stays at most 60 mm, drawn here with its
    caption, does not fit the first sheet's field over the title block nor beside it."""
    from graphplan.exact.gears import solve
    from graphplan.graphic.gears import ENLARGE, REDUCE, construct_mesh
    from graphplan.sheets.compose import field_of, keep_out
    from graphplan.sheets.gears import meshing_leaf
    s = sheet(name, fmt)
    mesh = next(p for p in s.pages[0].placed if p.name == "meshing").record
    k = 1e-3 / mesh.scales["mu_l"]
    pair = solve(scene(name)).pair
    m = pair.pair.module * 1000.0
    x0, y0, x1, y1 = field_of(s.form)
    keep = keep_out(s.form)
    lang = s.lang
    for g in sorted(v for v in ENLARGE + REDUCE if v > k + 1e-9 and 2.25 * m * v <= 60.0):
        w, h = size(meshing_leaf(construct_mesh(pair, 0.5, lang, module_mm=m * g), lang).bounds())
        assert not ((w <= x1 - x0 and h <= y1 - keep[3]) or (w <= keep[0] - x0 and h <= y1 - y0)), g


@pytest.mark.parametrize("fmt", ["A1", "A3"])
def test_the_terminal_reads_the_sheet_of_its_format(fmt, capsys):
    """`graphplan gears --format F` prints the contact ratio measured off the gear sheet on F: the
    graphical εα of the JSON, in the table's figures, is lettered in that sheet's (or set's) Table 1 —
    an A3 set's meshing is drawn at a smaller scale than the A1's, so its reading differs."""
    import json

    from graphplan.cli.main import main
    from graphplan.report.gears import contact_ratio_text
    assert main(["gears", str(ROOT / "examples" / "gears.toml"), "--format", fmt, "--json"]) == 0
    c = json.loads(capsys.readouterr().out)["pair"]["contact_ratio"]
    _, graphical, _ = contact_ratio_text(c["exact"], c["graphical"], "uk")
    s = sheet("gears", fmt)
    texts = {t.text for page in (s.pages or [s]) for p in page.placed for t in p.record.items
             if getattr(t, "text", None)}
    assert any(graphical in t for t in texts), (graphical, sorted(t for t in texts if t[:1].isdigit())[:40])


@pytest.mark.parametrize("name, fmt", [("gears", "A3"), ("gears_b", "A2")])
def test_the_terminal_reads_the_train_off_the_set_as_grown(name, fmt, capsys):
    """`graphplan gears --format A2/A3` prints the set's own readings of the train (issue 32): the
    set grows its planetary pictures after composing, and the terminal printed those of the first,
    smaller pictures (examples/gears_b.toml A2: h 25 mm, u1H 11,53 where the set drew h 67 mm and
    read 11,75). The JSON's pole distance is the drawn plan's — h measured on the record, the pole's
    foot to the pole —, every ω is its segment·μv/(μl·h) and u1H the sun's segment over the carrier's
    (the plan's rule); Table 3 of the set prints the JSON's u1H and ω in its figures."""
    import json

    from graphplan.cli.main import main
    from graphplan.report.gears import agreeing, bare, sig_decimals
    assert main(["gears", str(ROOT / "examples" / f"{name}.toml"), "--format", fmt, "--json"]) == 0
    t = json.loads(capsys.readouterr().out)["planetary"]
    g = t["graphical"]
    s = sheet(name, fmt)
    plan = next(p.record for page in s.pages for p in page.placed if p.name == "planetary")
    h = next(q for q in plan.items if q.step == "h")
    assert abs(abs(h.points[0][1] - h.points[1][1]) - g["h_mm"]) < 1e-6
    hH = g["h_carrier_mm"] or g["h_mm"]                   # the carrier's own pole where it has one
    for k, seg in g["segments_mm"].items():
        d = hH if k == "H" else g["h_mm"]
        assert g["omega_rad_s"][k] == pytest.approx(seg * g["mu_v_mm"] / (g["mu_l_m_mm"] * d), abs=1e-9)
    assert t["ratio"]["graphical"] == pytest.approx(g["segments_mm"]["1"] / g["h_mm"] / (g["segments_mm"]["H"] / hH))
    table = next(p.record for page in s.pages for p in page.placed if p.name == "train")
    cells = [q.text for q in table.items if getattr(q, "text", None)]
    lang = s.lang
    u = t["ratio"]
    assert bare(agreeing(u["exact"], u["graphical"], sig_decimals(u["exact"]), lang)[1]) in cells
    for k in ("1", "2", "H"):
        e = t["omega_rad_s"][k]
        assert bare(agreeing(e, g["omega_rad_s"][k], sig_decimals(e), lang)[1]) in cells, (k, cells)


def test_table_1_prints_the_pairs_constants_as_the_terminal_does(capsys):
    """αw, aw, a, y, Δy, p and pb in Table 1 are the terminal's figures (rev7 #14, rev8 #12: the sheet
    printed y = 0,72366 and Δy = 0,076345 where `graphplan gears` prints 0,7237 and 0,07634)."""
    import re

    from graphplan.cli.main import main
    assert main(["gears", str(ROOT / "examples" / "gears.toml")]) == 0
    geo = next(line for line in capsys.readouterr().out.splitlines() if line.startswith("αw"))
    said = {k: v.rstrip(",") for k, v in re.findall(r"(\w+|Δy) = ([−\d,]+)", geo)}
    s = sheet("gears", "A1")
    t1 = next(p for p in s.placed if p.name == "geometry")
    texts = [t.text for t in t1.record.items if getattr(t, "text", None)]
    for sym, key in (("α_w, °", "αw"), ("a_w, мм", "aw"), ("a, мм", "a"), ("y", "y"), ("Δy", "Δy"),
                     ("p, мм", "p"), ("p_b, мм", "pb")):
        i = texts.index(sym)
        assert texts[i + 1] == said[key], (sym, texts[i + 1], said[key])


@pytest.mark.parametrize("name", ["gears_b"])
def test_the_sliding_diagrams_stand_at_the_top_of_their_row_under_the_meshing(name):
    """Stop 46: the λ diagrams, shorter than the planetary pictures beside them, stood centred in the row's
    height with a hole over them under the meshing (the lead's "empty left middle"). In the row they now
    stand at its top, right under the meshing they are read off; beside the meshing, at its top."""
    s = sheet(name, "A1")
    placed = {p.name: p for p in s.placed if p.name in DRAWINGS}
    lam, mesh, plan = placed["sliding"], placed["meshing"], placed["planetary"]
    top = lam.record.bounds()[3]
    if lam.box[3] == pytest.approx(mesh.box[3]):                                 # beside the meshing
        assert lam.box[0] >= mesh.box[2]
    else:                                                                        # in the row under it
        assert top == pytest.approx(lam.box[3]) and lam.box[3] == pytest.approx(plan.box[3])
        assert lam.record.bounds()[1] > plan.record.bounds()[1] + 10.0       # (shorter: the room under it)
