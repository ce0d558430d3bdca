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
from graphplan.util.errors import SceneError

LAWS = ("parabolic", "cosine", "cycloidal", "linear", "trapezoidal")
KINDS = ("translating", "rocking")
_TOP = {"title", "title_en", "designation", "lang", "sheet", "cam", "diagrams"}
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
        d = dict(self.meta)
        return d.get("title_en", self.title) if lang == "en" else self.title


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
        raise SceneError("the scene is not UTF-8 text", where) from None
    return build(B.parse_toml(text, where), where)


def build(data: dict[str, Any], where: str = "<scene>") -> Cam:
    """The checked cam from a parsed scene: one line naming the key for anything wrong."""
    def fail(key: str, what: str) -> SceneError:
        return SceneError(f"{key}: {what}", where)

    if "cam" not in data and ("gears" in data or "planetary" in data):
        raise SceneError("the scene has no [cam] table: it describes a gear mechanism (graphplan gears and "
                         "graphplan sheet draw it, docs/gears.md)", where)
    if "cam" not in data:
        raise SceneError("the scene has no [cam] table: it describes a lever mechanism (graphplan cam reads a "
                         "cam scene, docs/cams.md)", where)
    unknown = sorted(set(data) - _TOP)
    if unknown:
        raise fail(unknown[0], f"unknown key in a cam scene (allowed: {', '.join(sorted(_TOP))})")
    cam = data.get("cam")
    if not isinstance(cam, dict):
        raise fail("cam", "must be a table")
    unknown = sorted(set(cam) - _CAM)
    if unknown:
        raise fail(f"cam.{unknown[0]}", f"unknown key (allowed: {', '.join(sorted(_CAM))})")

    def number(key: str, lo: float, hi: float, unit: str, default: float | None = None,
               lo_open: bool = False) -> float:
        if key not in cam:
            if default is None:
                raise fail(f"cam.{key}", "missing")
            return default
        v = cam[key]
        if isinstance(v, bool) or not isinstance(v, (int, float)):
            raise fail(f"cam.{key}", f"must be a number, got {B.short(repr(v))}")
        v = B.to_float(v, f"cam.{key}", where)
        ok = math.isfinite(v) and (v > lo if lo_open else v >= lo) and v <= hi
        if not ok:
            raise fail(f"cam.{key}", f"must be from {lo:g}{' (exclusive)' if lo_open else ''} to {hi:g} {unit}, "
                       f"got {v:g}")
        return v

    follower = cam.get("follower", "translating")
    if follower not in KINDS:
        raise fail("cam.follower", f"must be translating or rocking, got {B.short(repr(follower))}")
    phases_raw = cam.get("phases_deg")
    if not isinstance(phases_raw, dict):
        raise fail("cam.phases_deg", "must be a table { rise, dwell_far, return, dwell_near } in degrees")
    extra = sorted(set(phases_raw) - set(_PHASES))
    if extra:
        raise fail(f"cam.phases_deg.{extra[0]}", f"unknown phase (allowed: {', '.join(_PHASES)})")
    phases = []
    for name in _PHASES:
        v = phases_raw.get(name, None if name in ("rise", "return") else 0.0)
        if v is None:
            raise fail(f"cam.phases_deg.{name}", "missing")
        if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(float(v)) \
                or not 0 <= float(v) <= 360:
            raise fail(f"cam.phases_deg.{name}", f"must be from 0 to 360°, got {B.short(repr(v))}")
        phases.append(float(v))
    if phases[0] < 5 or phases[2] < 5:
        raise fail("cam.phases_deg", "the rise and the return take at least 5° each")
    if abs(sum(phases) - 360.0) > 1e-9:
        raise fail("cam.phases_deg", f"the four phases must sum to 360°, they sum to {sum(phases):g}°")
    laws_raw = cam.get("laws", {})
    if isinstance(laws_raw, str):
        laws_raw = {"rise": laws_raw, "return": laws_raw}
    if not isinstance(laws_raw, dict):
        raise fail("cam.laws", "must be a law's name or a table { rise, return }")
    laws = []
    for name in ("rise", "return"):
        law = laws_raw.get(name, "cosine")
        if law not in LAWS:
            raise fail(f"cam.laws.{name}", f"unknown law {B.short(repr(law))} (known: {', '.join(LAWS)})")
        laws.append(law)
    rocking = follower == "rocking"
    allowed_raw = cam.get("pressure_angle_deg", 45.0 if rocking else 30.0)
    if isinstance(allowed_raw, (int, float)) and not isinstance(allowed_raw, bool):
        allowed_raw = {"rise": allowed_raw, "return": allowed_raw}
    if not isinstance(allowed_raw, dict):
        raise fail("cam.pressure_angle_deg", "must be an angle or a table { rise, return } in degrees")
    allowed = []
    for name in ("rise", "return"):
        v = allowed_raw.get(name, 45.0 if rocking else 30.0)
        if isinstance(v, bool) or not isinstance(v, (int, float)) or not 5 <= float(v) <= 80:
            raise fail(f"cam.pressure_angle_deg.{name}", f"must be from 5 to 80°, got {B.short(repr(v))}")
        allowed.append(float(v))
    if "omega" in cam and "rpm" in cam:
        raise fail("cam.rpm", "give omega or rpm, not both")
    omega = number("rpm", 0.01, 1e5, "rpm") * math.pi / 30 if "rpm" in cam else number("omega", 1e-3, 1e4, "rad/s", 10.0)
    direction = cam.get("direction", "ccw")
    if direction not in ("ccw", "cw"):
        raise fail("cam.direction", f"must be ccw or cw, got {B.short(repr(direction))}")
    roller = number("roller_radius", 0.0, 1.0, "m", 0.0)
    if 0 < roller < 1e-5:
        raise fail("cam.roller_radius", f"must be 0 (a knife-edge) or from 1e-05 m, got {roller:g}")
    divisions = cam.get("divisions", 8)
    if isinstance(divisions, bool) or not isinstance(divisions, int) or not 2 <= divisions <= 360:
        raise fail("cam.divisions", f"must be a whole number from 2 to 360 (intervals of each phase), got "
                                    f"{B.short(repr(divisions))}")
    offset: float | None
    arm = centre = 0.0
    if rocking:
        for key in ("stroke", "offset"):
            if key in cam:
                raise fail(f"cam.{key}", "is for a translating follower; a rocking one has swing_deg, arm, "
                                         "centre_distance")
        stroke = math.radians(number("swing_deg", 0.5, 90.0, "deg"))
        arm = number("arm", 1e-4, 10.0, "m")
        centre = number("centre_distance", 1e-4, 10.0, "m")
        offset = 0.0
    else:
        for key in ("swing_deg", "arm", "centre_distance"):
            if key in cam:
                raise fail(f"cam.{key}", "is for a rocking follower; a translating one has stroke and offset")
        stroke = number("stroke", 1e-5, 10.0, "m", lo_open=True)
        if cam.get("offset") == "auto":
            offset = None
        else:
            offset = number("offset", -10.0, 10.0, "m", 0.0)
    base = number("base_radius", 1e-4, 100.0, "m") if "base_radius" in cam else None
    if base is not None:
        if roller >= base:
            raise fail("cam.roller_radius", f"the roller ({roller:g} m) must be smaller than the base circle "
                                            f"({base:g} m)")
        if offset is not None and abs(offset) >= base:
            raise fail("cam.offset", f"|e| = {abs(offset):g} m must be smaller than the base radius {base:g} m")
    if rocking:
        if base is not None and not abs(centre - arm) < base < centre + arm:
            raise fail("cam.base_radius", f"the arm {arm:g} m at {centre:g} m from the cam's centre reaches "
                                          f"radii from {abs(centre - arm):g} to {centre + arm:g} m only")
    meta = tuple((k, B.clean_text(data[k])) for k in ("title_en", "designation", "lang") if k in data)
    sheet = data.get("sheet", {})
    if not isinstance(sheet, dict):
        raise fail("sheet", "must be a table")
    meta += tuple((f"sheet.{B.clean_text(k)}", B.clean_text(v)) for k, v in sheet.items())
    return Cam(B.clean_text(data.get("title", "Кулачковий механізм")), follower, stroke,
               (phases[0], phases[1], phases[2], phases[3]), (laws[0], laws[1]), (allowed[0], allowed[1]),
               omega, 1 if direction == "ccw" else -1, roller, offset, arm, centre, base, divisions, where, meta,
               divisions_given="divisions" in cam)
