"""Stop 58 (web58): the page's downloads on the lead's new mechanisms — the tables without float
noise (plans.csv's mm × μ to the ruler's meaningful digits), a rocking cam's tables (they failed with
a KeyError: its s is an angle), and the V-twin compressor with two groups on the crank pin."""
from __future__ import annotations

import csv
import io
import re
import zipfile

import pytest

from conftest import ROOT
from review_scenes import CAM58

CRANK = (ROOT / "examples" / "crank_slider.toml").read_text(encoding="utf-8")
NOISE = re.compile(r"\d\.\d*(0000000|9999999)\d$")      # 1.1720000000000002, 0.3999999999999999


@pytest.fixture
def client(web):
    """The worker's web app in the test client (conftest's ``web_client``, one for the worker)."""
    return web


def _tables(client, text: str) -> dict[str, list[dict[str, str]]]:
    """Every CSV of one /api/tables download, by name."""
    r = client.post("/api/tables?lang=en", content=text.encode())
    assert r.status_code == 200, r.text
    z = zipfile.ZipFile(io.BytesIO(r.content))
    return {name: list(csv.DictReader(io.StringIO(z.read(name).decode())))
            for name in z.namelist() if name.endswith(".csv")}


def _table(client, text: str, name: str) -> list[dict[str, str]]:
    return _tables(client, text)[name]


def test_plans_csv_is_the_reading_times_the_scale_without_float_noise(client):
    """Seed 004's crank-slider: v_A read as 55 mm at μv = 0.341 (m/s)/mm is 18.755 m/s; the CSV gives it
    to a tenth of the ruler's step (0.5 mm · μv = 0.17 m/s → 0.01), never 18.755000000000003."""
    from graphplan import api
    rows = _table(client, CRANK, "plans.csv")
    doc = api.plans(api.study(api.load(ROOT / "examples" / "crank_slider.toml")), precision=0.5).to_json()
    mu = {(str(p["index"]), "velocity"): p["mu_v"] for p in doc["positions"]}
    mu.update({(str(p["index"]), "acceleration"): p["mu_a"] for p in doc["positions"] if p.get("mu_a")})
    checked = 0
    for r in rows:
        for cell in ("mm", "value", "analytic", "error_pct"):
            assert not NOISE.search(r[cell]), r
        if r["mm"] and float(r["mm"]) > 0:
            step = 0.5 * mu[r["position"], r["plan"]]           # the ruler's 0.5 mm on this plan
            assert abs(float(r["value"]) - float(r["mm"]) * mu[r["position"], r["plan"]]) <= step / 20 + 1e-12, r
            decimals = len(r["value"].partition(".")[2])
            assert 10 ** -decimals <= step / 10 * 1.0001, (r, step)              # a tenth of the step resolved
            assert decimals == 0 or 10 ** -(decimals - 1) > step / 10, (r, step)  # and no digit more
            checked += 1
        if r["error_pct"]:
            assert re.fullmatch(r"-?\d+(\.\d{1,2})?", r["error_pct"]), r
    assert checked > 20
    v_a = next(r for r in rows if r["quantity"] == "A" and r["plan"] == "velocity")
    assert v_a["value"] == "18.76" and float(v_a["analytic"]) == pytest.approx(293.07 * 0.064, rel=1e-12)


def test_a_rocking_cam_s_tables_give_its_swing_in_degrees(client):
    """CAM58, a rocking follower with a 25° swing: cam.csv gives s in degrees; at the rise's end s = ψ."""
    rows = _table(client, CAM58, "cam.csv")
    s = {float(r["phi_deg"]): float(r["exact"]) for r in rows if r["quantity"] == "s_deg"}
    assert s[0.0] == 0.0 and s[150.0] == pytest.approx(25.0, abs=1e-9)
    assert {r["quantity"] for r in rows} == {"s_deg", "ds_dphi_deg", "pressure_angle_deg"}
    for r in rows:
        assert not any(NOISE.search(r[c]) for c in ("exact", "graphical", "error_pct")), r


def test_gear_tables_carry_no_float_noise(client):
    from review_scenes import GEARS58
    # the three tables read off one download (each request computes every table: four took 2,7 s)
    tables = _tables(client, GEARS58)
    for name in ("pair.csv", "sliding.csv", "train.csv"):
        for r in tables[name]:
            assert not any(NOISE.search(v or "") or re.search(r"e-1[3-9]", v or "") for v in r.values()), (name, r)
    sliding = tables["sliding.csv"]
    pitch = next(r for r in sliding if r["point"] == "P")
    assert float(pitch["lambda1"]) == 0.0 and float(pitch["lambda2"]) == 0.0     # no sliding at the pitch point


def test_the_preview_stacks_the_assemblies_for_a_phone(client):
    """LINK58 leaves both groups open: the preview draws B = +1 and B = −1 side by side, and with
    ?stack=1 (the page's one column) one above the other, the same drawings in the same order."""
    from review_scenes import LINK58
    import xml.etree.ElementTree as ET
    wide = client.post("/api/scene/preview?phi=30&lang=en", content=LINK58.encode())
    tall = client.post("/api/scene/preview?phi=30&lang=en&stack=1", content=LINK58.encode())
    assert wide.status_code == tall.status_code == 200
    assert wide.headers["x-assemblies"] == tall.headers["x-assemblies"]

    def cells(svg: bytes):
        root = ET.fromstring(svg)
        w, h = (float(v) for v in root.get("viewBox").split()[2:])
        moves = [tuple(float(v) for v in g.get("transform")[len("translate("):-1].split(","))
                 for g in root.iter("{http://www.w3.org/2000/svg}g") if g.get("class") == "assembly"]
        return w, h, moves
    w1, h1, m1 = cells(wide.content)
    w2, h2, m2 = cells(tall.content)
    assert len(m1) == len(m2) == 2
    assert m1[0] == m2[0] == (0.0, 0.0) and m1[1][1] == 0.0 and m1[1][0] > 0      # left to right
    assert m2[1][0] == 0.0 and m2[1][1] > 0                                       # top to bottom
    assert w2 == pytest.approx((w1 - 10) / 2, abs=0.01) and h2 == pytest.approx(2 * h1 + 10, abs=0.01)   # viewBox to 0.001
    assert wide.content.replace(b"\n", b"").count(b"<text") == tall.content.replace(b"\n", b"").count(b"<text")
