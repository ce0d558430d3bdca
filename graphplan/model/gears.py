"""A gear mechanism as a scene gives it (the ``[gears]`` and ``[planetary]`` tables, docs/gears.md),
checked where it is read.

``[gears]``: an external involute pair — the numbers of teeth z1, z2, the module m, the shifts
x1, x2 (numbers, or "auto": chosen by the rule of exact/gears.py), the profile angle α (20°), the
addendum h*a (1) and the clearance c* (0.25) of the generating rack.
``[planetary]``: a 2K-H train — type "A" (sun 1, planets 2, fixed ring 3, carrier H) or "B" (two
rows: external 1–2, then internal 2'–3 with the ring fixed), the ratio u1H wanted (the z's then
chosen, exact/gears.py) or the z's given, K planets, the module and ω of wheel 1.
A scene holds either table or both. Every refusal is one line naming the key and the failed bound.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from graphplan.model import bounds as B
from graphplan.util.errors import GraphplanError, SceneError, keyed_error, scenes_speaking

_TOP = {"title", "title_en", "designation", "designation_en", "lang", "sheet", "gears", "planetary"}
_PAIR = {"z", "module", "shifts", "pressure_angle_deg", "addendum", "clearance"}
_TRAIN = {"type", "ratio", "z", "planets", "module", "omega", "rpm"}
Z_PAIR = (5, 300)              # teeth of a pair's wheel
Z_TRAIN = (8, 400)             # teeth of a train's wheel (the ring's too)
MODULE = (1e-4, 0.1)           # m: 0.1 mm … 100 mm
SHIFT = (-1.0, 2.0)
ALPHA = (10.0, 35.0)           # degrees
ADDENDUM = (0.5, 1.5)
CLEARANCE = (0.0, 0.5)
RATIO = (1.2, 60.0)
PLANETS = (1, 12)


@dataclass(frozen=True)
class Pair:
    """The external pair: ``shifts`` None when the scene asks for "auto"."""
    z: tuple[int, int]
    module: float
    shifts: tuple[float, float] | None = (0.0, 0.0)
    alpha_deg: float = 20.0
    addendum: float = 1.0
    clearance: float = 0.25

    @property
    def alpha(self) -> float:
        return math.radians(self.alpha_deg)


@dataclass(frozen=True)
class Train:
    """The planetary train: ``z`` None when the ratio is given (the z's are then chosen);
    type A: z = (z1, z2, z3); type B: z = (z1, z2, z2', z3)."""
    kind: str
    planets: int
    module: float
    omega: float
    ratio: float | None = None
    z: tuple[int, ...] | None = None
    rpm: float | None = None      # n1, rpm, as the scene gives it (``omega`` = π·n1/30); None when ω1 is given


@dataclass(frozen=True)
class Gears:
    """A gear scene: the pair, the train or both."""
    title: str
    pair: Pair | None = None
    train: Train | None = None
    source: str | None = None
    meta: tuple[tuple[str, str], ...] = ()

    def title_in(self, lang: str) -> str:
        """The title in ``lang``: ``title_en`` on an English sheet where the scene gives it, else the
        title romanised (util/romanize.py; the default title "Зубчастий механізм": "Gear mechanism")."""
        from graphplan.util.romanize import scene_text
        d = dict(self.meta)
        if lang == "en" and not d.get("title_en") and self.title == "Зубчастий механізм":
            return "Gear mechanism"
        return scene_text({**d, "title": self.title}, "title", lang, self.title)


def is_gears(data: dict[str, Any]) -> bool:
    """Whether a parsed scene describes a gear mechanism."""
    return isinstance(data, dict) and ("gears" in data or "planetary" in data)


def load(path: str | Path) -> Gears:
    """The gear scene of a file: read as every scene is (bounds.parse_toml), then checked."""
    from graphplan.util.files import read_bytes
    where = str(path)
    data = read_bytes(path, "scene", B.MAX_SCENE_BYTES)
    try:
        text = data.decode("utf-8-sig")
    except UnicodeDecodeError:
        raise keyed_error(SceneError, where, "", "cm not utf8", utf="UTF-8") from None
    return build(B.parse_toml(text, where), where)


def _number(table: dict, prefix: str, key: str, lo: float, hi: float, unit: str, where: str,
            default: float | None = None, lo_open: bool = False) -> float:
    if key not in table:
        if default is None:
            raise keyed_error(SceneError, where, f"{prefix}.{key}", "sc missing")
        return default
    v = table[key]
    if isinstance(v, bool) or not isinstance(v, (int, float)):
        raise keyed_error(SceneError, where, f"{prefix}.{key}", "cm number", got=B.short(repr(v)))
    v = B.to_float(v, f"{prefix}.{key}", where)
    if not (math.isfinite(v) and (v > lo if lo_open else v >= lo) and v <= hi):
        span = B.Range(lo, hi, unit, lo_open)
        raise keyed_error(SceneError, where, f"{prefix}.{key}", "bad range", range=lambda lang: span.text(lang), got=B._g(v))
    return v


def _listed(value: Any) -> Any:
    """A variant table's cell for a list: "12 30" or "12;30" → [12, 30] (numbers as TOML reads them);
    anything else as it is."""
    if not isinstance(value, str) or value == "auto":
        return value
    import re
    parts = [p for p in re.split(r"[;\s]+", value.strip()) if p]
    out: list[Any] = []
    for p in parts:
        try:
            out.append(int(p))
        except ValueError:
            try:
                out.append(float(p.replace(",", ".")))
            except ValueError:
                return value
    return out


def _teeth(value: Any, key: str, count: tuple[int, ...], bounds: tuple[int, int], where: str) -> tuple[int, ...]:
    value = _listed(value)
    lo, hi = bounds
    names = "/".join(str(c) for c in count)
    if not isinstance(value, list) or len(value) not in count:
        raise keyed_error(SceneError, where, key, "gr teeth list", n=names, got=B.short(repr(value)))
    out = []
    for k, v in enumerate(value):
        if isinstance(v, bool) or not isinstance(v, int) or not lo <= v <= hi:
            raise keyed_error(SceneError, where, f"{key}[{k}]", "gr teeth", lo=lo, hi=hi, got=B.short(repr(v)))
        out.append(v)
    return tuple(out)


def _pair(t: Any, where: str) -> Pair:
    if not isinstance(t, dict):
        raise keyed_error(SceneError, where, "gears", "sc table")
    unknown = sorted(set(t) - _PAIR)
    if unknown:
        raise keyed_error(SceneError, where, f"gears.{unknown[0]}", "sc unknown key", allowed=", ".join(sorted(_PAIR)))
    if "z" not in t:
        raise keyed_error(SceneError, where, "gears.z", "gr z missing", z="z = [z1, z2]")
    z = _teeth(t["z"], "gears.z", (2,), Z_PAIR, where)
    m = _number(t, "gears", "module", *MODULE, "m", where)
    raw = _listed(t.get("shifts", [0.0, 0.0]))
    shifts: tuple[float, float] | None
    if raw == "auto":
        shifts = None
    else:
        if not isinstance(raw, list) or len(raw) != 2:
            raise keyed_error(SceneError, where, "gears.shifts", "gr shifts", pair="[x1, x2]", auto='"auto"', got=B.short(repr(raw)))
        xs = []
        for k, v in enumerate(raw):
            if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(float(v)) \
                    or not SHIFT[0] <= float(v) <= SHIFT[1]:
                raise keyed_error(SceneError, where, f"gears.shifts[{k}]", "gr shift", lo=B._g(SHIFT[0]), hi=B._g(SHIFT[1]),
                                  got=B.short(repr(v)))
            xs.append(float(v))
        shifts = (xs[0], xs[1])
    alpha = _number(t, "gears", "pressure_angle_deg", *ALPHA, "°", where, 20.0)
    ha = _number(t, "gears", "addendum", *ADDENDUM, "", where, 1.0)
    c = _number(t, "gears", "clearance", *CLEARANCE, "", where, 0.25)
    return Pair((z[0], z[1]), m, shifts, alpha, ha, c)


def _train(t: Any, where: str) -> Train:
    if not isinstance(t, dict):
        raise keyed_error(SceneError, where, "planetary", "sc table")
    unknown = sorted(set(t) - _TRAIN)
    if unknown:
        raise keyed_error(SceneError, where, f"planetary.{unknown[0]}", "sc unknown key", allowed=", ".join(sorted(_TRAIN)))
    kind = t.get("type", "A")
    if kind not in ("A", "B"):
        raise keyed_error(SceneError, where, "planetary.type", "gr type", a='"A"', b='"B"', got=B.short(repr(kind)))
    k = t.get("planets", 3)
    if isinstance(k, bool) or not isinstance(k, int) or not PLANETS[0] <= k <= PLANETS[1]:
        raise keyed_error(SceneError, where, "planetary.planets", "gr planets", lo=PLANETS[0], hi=PLANETS[1], got=B.short(repr(k)))
    m = _number(t, "planetary", "module", *MODULE, "m", where)
    if "omega" in t and "rpm" in t:
        raise keyed_error(SceneError, where, "planetary.rpm", "cm speed both", omega="omega", rpm="rpm")
    rpm = _number(t, "planetary", "rpm", 0.01, 1e6, "rpm", where) if "rpm" in t else None
    omega = rpm * math.pi / 30 if rpm is not None else _number(t, "planetary", "omega", 1e-3, 1e5, "rad/s", where, 100.0)
    if ("ratio" in t) == ("z" in t):
        raise keyed_error(SceneError, where, "planetary", "gr ratio or teeth", ratio="ratio = u1H", z="z = [...]")
    if "ratio" in t:
        u = _number(t, "planetary", "ratio", *RATIO, "", where)
        if u <= 2.0 and kind == "A":
            raise keyed_error(SceneError, where, "planetary.ratio", "gr type A ratio", got=B._g(u))
        return Train(kind, k, m, omega, ratio=u, rpm=rpm)
    z = _teeth(t["z"], "planetary.z", (3,) if kind == "A" else (4,), Z_TRAIN, where)
    return Train(kind, k, m, omega, z=z, rpm=rpm)


def build(data: dict[str, Any], where: str = "<scene>") -> Gears:
    """The checked gear scene from a parsed one: one line naming the key for anything wrong, in the
    scene's ``lang`` (unless --lang says otherwise)."""
    try:
        return _build(data, where)
    except GraphplanError as exc:
        raise scenes_speaking(exc, data)


def _build(data: dict[str, Any], where: str) -> Gears:
    if "cam" in data:         # a cam's scene first: it is not a lever mechanism either
        raise keyed_error(SceneError, where, "cam", "gr cam scene", table="[gears]", cmd="graphplan cam", doc="docs/cams.md")
    if not is_gears(data):
        raise keyed_error(SceneError, where, "", "gr lever scene", t1="[gears]", t2="[planetary]", cmd="graphplan gears",
                          doc="docs/gears.md")
    unknown = sorted(set(data) - _TOP)
    if unknown:
        raise keyed_error(SceneError, where, unknown[0], "gr unknown top", allowed=", ".join(sorted(_TOP)))
    pair = _pair(data["gears"], where) if "gears" in data else None
    train = _train(data["planetary"], where) if "planetary" in data else None
    meta = tuple((k, B.clean_text(data[k])) for k in ("title_en", "designation", "designation_en", "lang")
                  if k in data)
    sheet = data.get("sheet", {})
    if not isinstance(sheet, dict):
        raise keyed_error(SceneError, where, "sheet", "sc table")
    meta += tuple((f"sheet.{B.clean_text(k)}", B.clean_text(v)) for k, v in sheet.items())
    return Gears(B.clean_text(data.get("title", "Зубчастий механізм")), pair, train, where, meta)
