"""A cam mechanism as a scene gives it (the ``[cam]`` table, docs/cams.md), checked where it is read.

The follower translates (a knife-edge, or a roller of radius r, its axis offset e from the cam's
centre) or rocks (a roller on an arm of length l pivoted at the centre distance a from the cam's
centre). It rises by the stroke h (rocking: swings by ψ_max) during the phase φ_rise, dwells at the far
position for φ_far, returns in φ_return and dwells near for the rest of the turn, each active phase by
its law. The allowed pressure angles [ϑ] of the rise and the return bound the base radius R0 (the
centre profile's smallest radius); a scene may give R0 (else the smallest allowed, rounded up to a
whole millimetre as a draftsman would take it) and, for a translating follower, the offset e
(a number, or "auto": the one that allows the smallest R0).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from graphplan.model import bounds as B
from graphplan.util.errors import GraphplanError, SceneError, either, keyed_error, scenes_speaking

LAWS = ("parabolic", "cosine", "cycloidal", "linear", "trapezoidal")
KINDS = ("translating", "rocking")
_TOP = {"title", "title_en", "designation", "designation_en", "lang", "sheet", "cam", "diagrams"}
_CAM = {"follower", "roller_radius", "offset", "stroke", "swing_deg", "arm", "centre_distance", "phases_deg",
        "laws", "pressure_angle_deg", "omega", "rpm", "direction", "base_radius", "divisions"}
_PHASES = ("rise", "dwell_far", "return", "dwell_near")


@dataclass(frozen=True)
class Cam:
    """The cam mechanism in SI units and degrees. ``stroke`` is h in m (translating) or ψ_max in rad
    (rocking); ``offset`` is e (m, None = chosen, "auto"); ``sense`` +1 counter-clockwise."""
    title: str
    follower: str
    stroke: float
    phases: tuple[float, float, float, float]      # rise, far dwell, return, near dwell, degrees
    laws: tuple[str, str]                           # rise, return
    allowed: tuple[float, float]                    # [ϑ] rise, return, degrees
    omega: float                                    # rad/s, > 0
    sense: int
    roller: float = 0.0
    offset: float | None = 0.0
    arm: float = 0.0
    centre_distance: float = 0.0
    base_radius: float | None = None
    divisions: int = 8
    source: str | None = None
    meta: tuple[tuple[str, str], ...] = ()
    divisions_given: bool = False                   # the scene names its divisions (kept, warned of)

    @property
    def rocking(self) -> bool:
        return self.follower == "rocking"

    def title_in(self, lang: str) -> str:
        """The title in ``lang``: ``title_en`` on an English sheet where the scene gives it, else the
        title romanised (util/romanize.py; the default title "Кулачковий механізм": "Cam mechanism")."""
        from graphplan.util.romanize import scene_text
        d = dict(self.meta)
        if lang == "en" and not d.get("title_en") and self.title == "Кулачковий механізм":
            return "Cam mechanism"
        return scene_text({**d, "title": self.title}, "title", lang, self.title)


def is_cam(data: dict[str, Any]) -> bool:
    """Whether a parsed scene describes a cam mechanism."""
    return isinstance(data, dict) and "cam" in data


def load(path: str | Path) -> Cam:
    """The cam scene of a file: read as every scene is (bounds.parse_toml), then checked."""
    from graphplan.util.files import read_bytes
    where = str(path)
    data = read_bytes(path, "scene", B.MAX_SCENE_BYTES)
    try:
        text = data.decode("utf-8-sig")
    except UnicodeDecodeError:
        raise keyed_error(SceneError, where, "", "cm not utf8", utf="UTF-8") from None
    return build(B.parse_toml(text, where), where)


def build(data: dict[str, Any], where: str = "<scene>") -> Cam:
    """The checked cam from a parsed scene: one line naming the key for anything wrong, in the
    scene's ``lang`` (unless --lang says otherwise)."""
    try:
        return _build(data, where)
    except GraphplanError as exc:
        raise scenes_speaking(exc, data)


def _build(data: dict[str, Any], where: str) -> Cam:
    lang = data.get("lang") if isinstance(data, dict) and data.get("lang") in ("uk", "en") else None

    def fail(key: str, word: str, /, **fields: object) -> SceneError:
        """The refusal of ``key`` worded by the catalogue's ``word`` (util.words) in both languages."""
        return keyed_error(SceneError, where, key, word, lang, **fields)

    if "cam" not in data and ("gears" in data or "planetary" in data):
        raise fail("", "cm gear scene", table="[cam]", cmd1="graphplan gears", cmd2="graphplan sheet", doc="docs/gears.md")
    if "cam" not in data:
        raise fail("", "cm lever scene", table="[cam]", cmd="graphplan cam", doc="docs/cams.md")
    unknown = sorted(set(data) - _TOP)
    if unknown:
        raise fail(unknown[0], "cm unknown top", allowed=", ".join(sorted(_TOP)))
    cam = data.get("cam")
    if not isinstance(cam, dict):
        raise fail("cam", "sc table")
    unknown = sorted(set(cam) - _CAM)
    if unknown:
        raise fail(f"cam.{unknown[0]}", "sc unknown key", allowed=", ".join(sorted(_CAM)))

    def number(key: str, lo: float, hi: float, unit: str, default: float | None = None,
               lo_open: bool = False) -> float:
        if key not in cam:
            if default is None:
                raise fail(f"cam.{key}", "sc missing")
            return default
        v = cam[key]
        if isinstance(v, bool) or not isinstance(v, (int, float)):
            raise fail(f"cam.{key}", "cm number", got=B.short(repr(v)))
        v = B.to_float(v, f"cam.{key}", where)
        ok = math.isfinite(v) and (v > lo if lo_open else v >= lo) and v <= hi
        if not ok:
            span = B.Range(lo, hi, unit, lo_open)
            raise fail(f"cam.{key}", "bad range", range=lambda lang: span.text(lang), got=B._g(v))
        return v

    follower = cam.get("follower", "translating")
    if follower not in KINDS:
        raise fail("cam.follower", "sc one of", choices=either('translating', 'rocking'), got=B.short(repr(follower)))
    phases_raw = cam.get("phases_deg")
    if not isinstance(phases_raw, dict):
        raise fail("cam.phases_deg", "cm phases table", table="{ rise, dwell_far, return, dwell_near }")
    extra = sorted(set(phases_raw) - set(_PHASES))
    if extra:
        raise fail(f"cam.phases_deg.{extra[0]}", "cm unknown phase", allowed=", ".join(_PHASES))
    phases = []
    for name in _PHASES:
        v = phases_raw.get(name, None if name in ("rise", "return") else 0.0)
        if v is None:
            raise fail(f"cam.phases_deg.{name}", "sc missing")
        if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(float(v)) \
                or not 0 <= float(v) <= 360:
            raise fail(f"cam.phases_deg.{name}", "cm angle", lo=0, hi=360, got=B.short(repr(v)))
        phases.append(float(v))
    if phases[0] < 5 or phases[2] < 5:
        raise fail("cam.phases_deg", "cm short phase")
    if abs(sum(phases) - 360.0) > 1e-9:
        raise fail("cam.phases_deg", "cm phases sum", got=B._g(sum(phases)))
    laws_raw = cam.get("laws", {})
    if isinstance(laws_raw, str):
        laws_raw = {"rise": laws_raw, "return": laws_raw}
    if not isinstance(laws_raw, dict):
        raise fail("cam.laws", "cm laws table", table="{ rise, return }")
    laws = []
    for name in ("rise", "return"):
        law = laws_raw.get(name, "cosine")
        if law not in LAWS:
            raise fail(f"cam.laws.{name}", "cm unknown law", got=B.short(repr(law)), known=", ".join(LAWS))
        laws.append(law)
    rocking = follower == "rocking"
    allowed_raw = cam.get("pressure_angle_deg", 45.0 if rocking else 30.0)
    if isinstance(allowed_raw, (int, float)) and not isinstance(allowed_raw, bool):
        allowed_raw = {"rise": allowed_raw, "return": allowed_raw}
    if not isinstance(allowed_raw, dict):
        raise fail("cam.pressure_angle_deg", "cm pressure table", table="{ rise, return }")
    allowed = []
    for name in ("rise", "return"):
        v = allowed_raw.get(name, 45.0 if rocking else 30.0)
        if isinstance(v, bool) or not isinstance(v, (int, float)) or not 5 <= float(v) <= 80:
            raise fail(f"cam.pressure_angle_deg.{name}", "cm angle", lo=5, hi=80, got=B.short(repr(v)))
        allowed.append(float(v))
    if "omega" in cam and "rpm" in cam:
        raise fail("cam.rpm", "cm speed both", omega="omega", rpm="rpm")
    omega = number("rpm", 0.01, 1e5, "rpm") * math.pi / 30 if "rpm" in cam else number("omega", 1e-3, 1e4, "rad/s", 10.0)
    direction = cam.get("direction", "ccw")
    if direction not in ("ccw", "cw"):
        raise fail("cam.direction", "sc one of", choices=either('ccw', 'cw'), got=B.short(repr(direction)))
    roller = number("roller_radius", 0.0, 1.0, "m", 0.0)
    if 0 < roller < 1e-5:
        raise fail("cam.roller_radius", "cm roller tiny", got=B._g(roller))
    divisions = cam.get("divisions", 8)
    if isinstance(divisions, bool) or not isinstance(divisions, int) or not 2 <= divisions <= 360:
        raise fail("cam.divisions", "cm divisions", got=B.short(repr(divisions)))
    offset: float | None
    arm = centre = 0.0
    if rocking:
        for key in ("stroke", "offset"):
            if key in cam:
                raise fail(f"cam.{key}", "cm translating only", keys="swing_deg, arm, centre_distance")
        stroke = math.radians(number("swing_deg", 0.5, 90.0, "deg"))
        arm = number("arm", 1e-4, 10.0, "m")
        centre = number("centre_distance", 1e-4, 10.0, "m")
        offset = 0.0
    else:
        for key in ("swing_deg", "arm", "centre_distance"):
            if key in cam:
                raise fail(f"cam.{key}", "cm rocking only", keys="stroke, offset")
        stroke = number("stroke", 1e-5, 10.0, "m", lo_open=True)
        if cam.get("offset") == "auto":
            offset = None
        else:
            offset = number("offset", -10.0, 10.0, "m", 0.0)
    base = number("base_radius", 1e-4, 100.0, "m") if "base_radius" in cam else None
    if base is not None:
        if roller >= base:
            raise fail("cam.roller_radius", "cm roller base", roller=B._g(roller), base=B._g(base))
        if offset is not None and abs(offset) >= base:
            raise fail("cam.offset", "cm offset base", e=B._g(abs(offset)), base=B._g(base))
    if rocking:
        if base is not None and not abs(centre - arm) < base < centre + arm:
            raise fail("cam.base_radius", "cm arm reach", arm=B._g(arm), centre=B._g(centre),
                       lo=B._g(abs(centre - arm)), hi=B._g(centre + arm))
    meta = tuple((k, B.clean_text(data[k])) for k in ("title_en", "designation", "designation_en", "lang")
                  if k in data)
    sheet = data.get("sheet", {})
    if not isinstance(sheet, dict):
        raise fail("sheet", "sc table")
    meta += tuple((f"sheet.{B.clean_text(k)}", B.clean_text(v)) for k, v in sheet.items())
    return Cam(B.clean_text(data.get("title", "Кулачковий механізм")), follower, stroke,
               (phases[0], phases[1], phases[2], phases[3]), (laws[0], laws[1]), (allowed[0], allowed[1]),
               omega, 1 if direction == "ccw" else -1, roller, offset, arm, centre, base, divisions, where, meta,
               divisions_given="divisions" in cam)
