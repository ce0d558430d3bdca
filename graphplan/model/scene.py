"""Scene files (TOML) → the mechanism model. Every key is checked; errors name the key.

The format is documented in docs/scenes.md.
"""
from __future__ import annotations

import copy
import math
from importlib import resources
from dataclasses import replace
from pathlib import Path
from typing import Any

from graphplan.util.errors import GraphplanError, SceneError, either, keyed_error, scenes_speaking
from graphplan.util.files import read_text
from graphplan.util.words import word
from graphplan.model import bounds as B
from graphplan.model.expressions import evaluate
from graphplan.model.mechanism import FRAME, Crank, Drive, Force, Guide, Link, Mechanism, Moment, Task

BUILTIN = "crank_slider.toml"

_TOP = {"diagrams", "title", "title_en", "designation", "designation_en", "lang", "sheet", "params", "synthesis", "frame",
        "crank", "link", "branch", "positions", "loads", "force", "moment", "dynamics"}
_CRANK = {"name", "pivot", "pin", "length", "omega", "rpm", "direction", "epsilon", "points",
          "shape", "guide", "mass", "inertia", "com"}
_LINK = {"name", "number", "joints", "length", "shape", "points", "slides_on", "guide", "ref",
         "mass", "inertia", "com"}
_POSITIONS = {"count", "start", "accel", "output", "force_phi_deg", "working_stroke"}
_DIAGRAMS = {"L_mm", "H1_mm", "H2_mm", "divisions", "point", "method"}
_LOADS = {"g", "mass_per_length", "inertia_factor"}
_FORCE = {"point", "magnitude", "stroke", "direction", "profile"}
_MOMENT = {"link", "magnitude", "stroke", "direction", "profile"}
_SYNTH = {"type", "K", "stroke", "centre_distance"}
_DYNAMICS = {"delta", "motor", "synchronous_rpm", "ratio", "efficiency", "reducer_inertia", "rotor_inertia",
             "reducer_shafts", "first_stage_ratio", "L_mm", "H_mm", "divisions"}


def builtin_path() -> Path:
    """The built-in crank-slider scene shipped with the package."""
    return Path(str(resources.files("graphplan") / "data" / BUILTIN))


def load(path: str | Path | None) -> Mechanism:
    """Read a scene file (the built-in crank-slider when ``path`` is None)."""
    path = builtin_path() if path is None else Path(path)
    try:
        text = read_text(path, "scene file", B.MAX_SCENE_BYTES)
    except GraphplanError as exc:
        raise SceneError(str(exc), exc.where, exc.said, exc.lang) from None
    return loads(text, str(path))


def loads(text: str, where: str = "<scene>") -> Mechanism:
    """Parse scene text; ``where`` names the file in error messages."""
    return build(B.parse_toml(text, where), where)


def build(data: dict[str, Any], where: str = "<scene>") -> Mechanism:
    """A mechanism from an already parsed scene tree (e.g. a base scene with a variant's overrides)."""
    B.check_tree(data, where)
    try:
        return _Reader(copy.deepcopy(data), where).mechanism()
    except GraphplanError as exc:        # a refusal from below (bounds, expressions) speaks the scene's lang
        raise scenes_speaking(exc, data)


class _Reader:
    """Turns the TOML tree into a Mechanism, checking each key on the way."""

    def __init__(self, data: dict[str, Any], where: str):
        self.data = data
        self.where = where
        self.names: dict[str, float] = {}
        self.lang = data.get("lang") if isinstance(data, dict) and data.get("lang") in ("uk", "en") else None

    # -- small checked readers ------------------------------------------------------------
    def fail(self, key: str, word: str, /, **fields: object) -> SceneError:
        """The refusal of ``key`` worded by the catalogue's ``word`` (util.words) in both languages."""
        return keyed_error(SceneError, self.where, key, word, self.lang, **fields)

    def table(self, value: Any, key: str, allowed: set[str]) -> dict[str, Any]:
        if not isinstance(value, dict):
            raise self.fail(key, "sc table")
        unknown = sorted(set(value) - allowed)
        if unknown:
            raise self.fail(f"{key}.{unknown[0]}", "sc unknown key", allowed=", ".join(sorted(allowed)))
        return value

    def number(self, value: Any, key: str, positive: bool = False,
               bounds: B.Range | None = None) -> float:
        """A number or an expression; finite, positive if asked, within ``bounds`` if given."""
        if isinstance(value, bool):
            raise self.fail(key, "sc number")
        if isinstance(value, (int, float)):
            result = B.to_float(value, key, self.where)
        elif isinstance(value, str):
            result = evaluate(value, self.names, f"{self.where}: {key}")
        else:
            raise self.fail(key, "sc number or expression")
        if not math.isfinite(result):
            raise self.fail(key, "sc finite")
        if positive and result <= 0:
            raise self.fail(key, "sc positive", got=B._g(result),
                            within=lambda lang: f" ({bounds.text(lang)})" if bounds else "")
        return B.check(result, bounds, key, self.where) if bounds else result

    def xy(self, value: Any, key: str) -> complex:
        if not isinstance(value, list) or len(value) != 2:
            raise self.fail(key, "sc pair")
        return complex(self.number(value[0], key, bounds=B.COORDINATE),
                       self.number(value[1], key, bounds=B.COORDINATE))

    def name(self, value: Any, key: str) -> str:
        if not isinstance(value, (str, int)) or isinstance(value, bool) or str(value).strip() == "":
            raise self.fail(key, "sc name")
        if isinstance(value, int) and abs(value) > B.MAX_INT:
            raise self.fail(key, "sc name")
        name = str(value).strip()
        problem = B.name_problem(name)
        if problem:
            raise self.fail(key, "sc bad name", why=lambda lang: word(problem, lang), got=B.short(repr(name)))
        return name

    # -- sections ---------------------------------------------------------------------------
    def mechanism(self) -> Mechanism:
        if isinstance(self.data, dict) and "cam" in self.data:
            raise self.fail("cam", "sc cam scene", cmd1="graphplan cam", cmd2="graphplan sheet", doc="docs/cams.md")
        if isinstance(self.data, dict) and ("gears" in self.data or "planetary" in self.data):
            key = "gears" if "gears" in self.data else "planetary"
            raise self.fail(key, "sc gear scene", cmd1="graphplan gears", cmd2="graphplan sheet", doc="docs/gears.md")
        data = self.table(self.data, "scene", _TOP)
        derived = self.read_synthesis(data.get("synthesis"))
        self.read_params(data)
        frame, guides = self.read_frame(data.get("frame"))
        if "crank" not in data:
            raise self.fail("crank", "sc no crank")
        crank, crank_link, crank_guide = self.read_crank(data["crank"], frame)
        links = {crank_link.name: crank_link}
        if crank_guide:
            guides[crank_guide.name] = crank_guide
        raw_links = data.get("link", [])
        if not isinstance(raw_links, list):
            raise self.fail("link", "sc array", table="[[link]]")
        numbers = {1}
        for k, raw in enumerate(raw_links):
            link, guide = self.read_link(raw, f"link[{k}]", len(links) + 1, frame)
            if link.name in links or link.name in guides and guide is None:
                raise self.fail(f"link[{k}].name", "sc name twice", name=repr(link.name))
            if link.number in numbers:
                raise self.fail(f"link[{k}].number", "sc number twice", number=link.number)
            numbers.add(link.number)
            links[link.name] = link
            if guide:
                if guide.name in guides:
                    raise self.fail(f"link[{k}].guide", "sc guide twice", name=repr(guide.name))
                guides[guide.name] = guide
        for name, link in links.items():
            if link.slides_on is not None and link.slides_on not in guides:
                known = ", ".join(sorted(guides)) or "—"
                raise self.fail(f"link {name}.slides_on", "sc no guide", name=repr(link.slides_on), known=known)
        positions = self.table(data.get("positions", {}), "positions", _POSITIONS)
        loads = self.table(data.get("loads", {}), "loads", _LOADS)
        links = self.apply_loads(self.shape_joints(links, frame), loads)
        mech = Mechanism(
            title=B.clean_text(data.get("title", "mechanism")) or "mechanism", frame=frame, guides=guides, links=links,
            crank=crank, branches=self.read_branches(data.get("branch", {})),
            output=self.name(positions["output"], "positions.output") if "output" in positions else None,
            start=self.read_start(positions.get("start", "max")),
            working_stroke=self.read_working(positions.get("working_stroke", "slow")),
            forces=self.read_forces(data.get("force", [])),
            moments=self.read_moments(data.get("moment", []), links),
            g=self.number(loads.get("g", 9.81), "loads.g", bounds=B.GRAVITY),
            params=dict(self.names), derived=derived,
            task=Task(count=self.read_count(positions.get("count", 12)),
                      accel=self.read_accel(positions.get("accel", [])),
                      force_phi=(self.number(positions["force_phi_deg"], "positions.force_phi_deg",
                                             bounds=B.ANGLE)
                                 if "force_phi_deg" in positions else None),
                      diagram=self.read_diagram(data.get("diagrams", {})), meta=self.read_meta(data),
                      flywheel=self.read_flywheel(data.get("dynamics", {}))),
            drive=self.read_drive(data.get("dynamics", {})),
            source=self.where)
        self.check_names(mech)
        return mech

    def read_params(self, data: dict[str, Any]) -> None:
        params = data.get("params", {})
        if not isinstance(params, dict):
            raise self.fail("params", "sc table")
        for key, value in params.items():
            if not key.isidentifier():
                raise self.fail(f"params.{B.short(key)}", "sc param name", example="l_AB")
            self.names[key] = self.number(value, f"params.{key}", bounds=B.PARAMETER)

    def read_synthesis(self, raw: Any) -> dict[str, float]:
        """Quick-return synthesis (seed 000): θ = 180°(K−1)/(K+1), r = ℓ·sin(θ/2), l = H/(2 sin(θ/2))."""
        if raw is None:
            return {}
        raw = self.table(raw, "synthesis", _SYNTH)
        if raw.get("type") != "quick_return":
            raise self.fail("synthesis.type", "sc synthesis type", known='"quick_return"')
        for key in ("K", "stroke", "centre_distance"):
            if key not in raw:
                raise self.fail(f"synthesis.{key}", "sc missing")
        k = self.number(raw["K"], "synthesis.K", positive=True, bounds=B.TIME_RATIO)
        if k <= 1:
            raise self.fail("synthesis.K", "sc time ratio", got=B._g(k))
        stroke = self.number(raw["stroke"], "synthesis.stroke", positive=True, bounds=B.LENGTH)
        centre = self.number(raw["centre_distance"], "synthesis.centre_distance", positive=True,
                             bounds=B.LENGTH)
        theta = math.pi * (k - 1) / (k + 1)
        derived = {"theta_deg": math.degrees(theta), "crank": centre * math.sin(theta / 2),
                   "rocker": stroke / (2 * math.sin(theta / 2))}
        for key, value in {"K": k, "stroke": stroke, "centre_distance": centre, **derived}.items():
            self.names.setdefault(key, value)
        return derived

    def read_frame(self, raw: Any) -> tuple[dict[str, complex], dict[str, Guide]]:
        if raw is None:
            raise self.fail("frame", "sc no frame", table="[frame.points]")
        raw = self.table(raw, "frame", {"points", "guides"})
        points_raw = raw.get("points", {})
        if not isinstance(points_raw, dict) or not points_raw:
            raise self.fail("frame.points", "sc no fixed point")
        frame = {self.name(k, "frame.points"): self.xy(v, f"frame.points.{k}")
                 for k, v in points_raw.items()}
        guides = {}
        guides_raw = raw.get("guides", {})
        for name, g in self.table(guides_raw, "frame.guides",
                                  set(guides_raw) if isinstance(guides_raw, dict) else set()).items():
            name = self.name(name, "frame.guides")
            guides[name] = self.read_guide(g, f"frame.guides.{name}", name, FRAME)
        return frame, guides

    def read_guide(self, raw: Any, key: str, name: str, body: str) -> Guide:
        raw = self.table(raw, key, {"through", "angle_deg", "title_uk", "title_en"})
        through = self.xy(raw.get("through", [0, 0]), f"{key}.through")
        angle = math.radians(self.number(raw.get("angle_deg", 0), f"{key}.angle_deg", bounds=B.ANGLE))
        titles = tuple((lang, B.clean_text(raw[f"title_{lang}"])) for lang in ("uk", "en")
                       if B.clean_text(raw.get(f"title_{lang}", "")))
        return Guide(name=name, body=body, through=through, angle=angle, titles=titles)

    def read_points(self, raw: Any, key: str, length: float | None,
                    local: dict[str, complex]) -> None:
        """Extra points: a fraction along the link's axis, or [along, across] in metres."""
        if raw is None:
            return
        for name, value in self.table(raw, key, set(raw) if isinstance(raw, dict) else set()).items():
            name = self.name(name, key)
            if name in local:
                raise self.fail(f"{key}.{name}", "sc point twice")
            if isinstance(value, list):
                local[name] = self.xy(value, f"{key}.{name}")
            else:
                fraction = self.number(value, f"{key}.{name}")
                if length is None:
                    raise self.fail(f"{key}.{name}", "sc fraction", pair="[along, across]")
                B.check(fraction * length, B.COORDINATE, f"{key}.{name} (fraction × length)", self.where)
                local[name] = complex(fraction * length, 0.0)

    def read_crank(self, raw: Any, frame: dict[str, complex]) -> tuple[Crank, Link, Guide | None]:
        raw = self.table(raw, "crank", _CRANK)
        for key in ("pivot", "pin", "length"):
            if key not in raw:
                raise self.fail(f"crank.{key}", "sc missing")
        pivot = self.name(raw["pivot"], "crank.pivot")
        pin = self.name(raw["pin"], "crank.pin")
        if pivot not in frame:
            raise self.fail("crank.pivot", "sc not frame point", name=repr(pivot), known=", ".join(frame))
        length = self.number(raw["length"], "crank.length", positive=True, bounds=B.LENGTH)
        if ("omega" in raw) == ("rpm" in raw):
            raise self.fail("crank", "sc speed once", omega="omega", rpm="rpm")
        speed = (self.number(raw["omega"], "crank.omega", positive=True, bounds=B.OMEGA) if "omega" in raw
                 else self.number(raw["rpm"], "crank.rpm", positive=True, bounds=B.RPM) * math.pi / 30)
        direction = raw.get("direction", "ccw")
        if direction not in ("ccw", "cw"):
            raise self.fail("crank.direction", "sc one of", choices=either('"ccw"', '"cw"'), got=repr(direction))
        omega = speed if direction == "ccw" else -speed
        name = self.name(raw.get("name", pivot + pin), "crank.name")
        if name == FRAME:
            raise self.fail("crank.name", "sc frame name crank", name=repr(FRAME))
        local = {pivot: 0j, pin: complex(length, 0)}
        self.read_points(raw.get("shape"), "crank.shape", length, local)
        self.read_points(raw.get("points"), "crank.points", length, local)
        guide = self.read_guide(raw["guide"], "crank.guide", name, name) if "guide" in raw else None
        link = Link(name=name, number=1, joints=(pivot, pin), local=local, length=length,
                    mass=self.opt_bounded(raw, "mass", "crank", B.MASS),
                    inertia=self.opt_bounded(raw, "inertia", "crank", B.INERTIA),
                    com=self.com(raw, "crank", local, 1))
        crank = Crank(link=name, pivot=pivot, pin=pin, length=length, omega=omega,
                      epsilon=self.number(raw.get("epsilon", 0.0), "crank.epsilon", bounds=B.EPSILON))
        return crank, link, guide

    def read_link(self, raw: Any, key: str, number: int,
                  frame: dict[str, complex]) -> tuple[Link, Guide | None]:
        raw = self.table(raw, key, _LINK)
        if "joints" not in raw:
            raise self.fail(f"{key}.joints", "sc missing")
        joints_raw = raw["joints"]
        if not isinstance(joints_raw, list):
            raise self.fail(f"{key}.joints", "sc point list")
        joints = tuple(self.name(j, f"{key}.joints") for j in joints_raw)
        if len(set(joints)) != len(joints):
            raise self.fail(f"{key}.joints", "sc joint twice")
        number = B.check_count(raw.get("number", number), (1, 999), f"{key}.number", self.where)
        default_name = "".join(joints) if len(joints) >= 2 else str(number)
        name = self.name(raw.get("name", default_name), f"{key}.name")
        if name == FRAME:
            raise self.fail(f"{key}.name", "sc frame name link", name=repr(FRAME))
        key = f"link {name}"
        slides_on = self.name(raw["slides_on"], f"{key}.slides_on") if "slides_on" in raw else None
        length = (self.number(raw["length"], f"{key}.length", positive=True, bounds=B.LENGTH)
                  if "length" in raw else None)
        origin = joints[0] if joints else None
        if origin is None:
            if slides_on is None:
                raise self.fail(f"{key}.joints", "sc no joint")
            if "ref" not in raw:
                raise self.fail(f"{key}.ref", "sc no ref")
            origin = self.name(raw["ref"], f"{key}.ref")
        local = {origin: 0j}
        if slides_on is None and len(joints) >= 2:
            if length is None:
                raise self.fail(f"{key}.length", "sc no length", dist=f"{joints[0]}{joints[1]}")
            local[joints[1]] = complex(length, 0)
        shape = raw.get("shape", {})
        self.read_points(shape, f"{key}.shape", length, local)
        for j in joints:
            if j not in local:
                raise self.fail(f"{key}.shape.{j}", "sc no shape", joint=j)
        self.read_points(raw.get("points"), f"{key}.points", length, local)
        guide = self.read_guide(raw["guide"], f"{key}.guide", name, name) if "guide" in raw else None
        if guide is None:
            guide = Guide(name=name, body=name, through=0j, angle=0.0)  # the link's own axis
        if length is None and len(joints) >= 2:
            length = abs(local[joints[1]] - local[joints[0]])
            B.check(length, B.LENGTH, f"{key}.shape ({joints[0]}{joints[1]})", self.where)
        link = Link(name=name, number=number, joints=joints, local=local, slides_on=slides_on,
                    length=length, mass=self.opt_bounded(raw, "mass", key, B.MASS),
                    inertia=self.opt_bounded(raw, "inertia", key, B.INERTIA),
                    com=self.com(raw, key, local, number))
        return link, guide

    def opt_bounded(self, raw: dict[str, Any], key: str, where: str, bounds: B.Range) -> float | None:
        return self.number(raw[key], f"{where}.{key}", bounds=bounds) if key in raw else None

    def com(self, raw: dict[str, Any], where: str, local: dict[str, complex], number: int) -> str | None:
        if "com" in raw:
            com = self.name(raw["com"], f"{where}.com")
            if com not in local:
                raise self.fail(f"{where}.com", "sc com", name=repr(com))
            return com
        guess = f"S{number}"
        return guess if guess in local else None

    def apply_loads(self, links: dict[str, Link], loads: dict[str, Any]) -> dict[str, Link]:
        """Masses q·l and inertias k·m·l² where the scene gives q and k instead of the values."""
        q = self.number(loads["mass_per_length"], "loads.mass_per_length", bounds=B.MASS_PER_LENGTH) \
            if "mass_per_length" in loads else None
        k = self.number(loads["inertia_factor"], "loads.inertia_factor", bounds=B.INERTIA_FACTOR) \
            if "inertia_factor" in loads else None
        result = {}
        for name, link in links.items():
            mass, inertia = link.mass, link.inertia
            if mass is None and q is not None and link.slides_on is None and link.length:
                mass = q * link.length
            if inertia is None and k is not None and mass is not None and link.slides_on is None:
                inertia = k * mass * link.length ** 2
            result[name] = Link(**{**link.__dict__, "mass": mass, "inertia": inertia})
        return result

    def read_branches(self, raw: Any) -> dict[str, int]:
        raw = self.table(raw, "branch", set(raw) if isinstance(raw, dict) else set())
        out = {}
        for key, value in raw.items():
            if value not in (1, -1) or isinstance(value, bool):
                raise self.fail(f"branch.{key}", "sc branch", got=repr(value))
            out[key] = int(value)
        return out

    def read_start(self, value: Any) -> str | float:
        if value in ("max", "min", "working", "idle", "inner", "outer"):
            return value
        if isinstance(value, str) and not value.replace(".", "").replace("-", "").isdigit():
            raise self.fail("positions.start", "sc start", got=repr(value),
                            choices='"max", "min", "working", "idle", "inner", "outer"')
        return self.number(value, "positions.start", bounds=B.ANGLE) % 360.0

    def read_working(self, value: Any) -> str:
        if value not in ("slow", "fast", "to_max", "to_min"):
            raise self.fail("positions.working_stroke", "sc one of", choices=either('"slow"', '"fast"', '"to_max"', '"to_min"'),
                            got=repr(value))
        return value

    def read_count(self, value: Any) -> int:
        return B.check_count(value, B.COUNT, "positions.count", self.where)

    def read_accel(self, value: Any) -> tuple[int, ...]:
        values = value if isinstance(value, list) else [value]
        out = []
        for v in values:
            out.append(B.check_count(v, (0, B.COUNT[1] - 1), "positions.accel", self.where))
        return tuple(out)

    def read_forces(self, raw: Any) -> tuple[Force, ...]:
        if not isinstance(raw, list):
            raise self.fail("force", "sc array", table="[[force]]")
        out = []
        for k, f in enumerate(raw):
            key = f"force[{k}]"
            f = self.table(f, key, _FORCE)
            for need in ("point", "magnitude"):
                if need not in f:
                    raise self.fail(f"{key}.{need}", "sc missing")
            stroke = f.get("stroke", "working")
            if stroke not in ("working", "idle", "both"):
                raise self.fail(f"{key}.stroke", "sc one of", choices=either('"working"', '"idle"', '"both"'), got=repr(stroke))
            direction = f.get("direction", "oppose")
            if direction != "oppose":
                direction = self.number(direction, f"{key}.direction", bounds=B.ANGLE)
            out.append(Force(point=self.name(f["point"], f"{key}.point"),
                             magnitude=self.number(f["magnitude"], f"{key}.magnitude", bounds=B.FORCE),
                             stroke=stroke, direction=direction,
                             profile=self.read_profile(f.get("profile", []), f"{key}.profile")))
        return tuple(out)

    def read_moments(self, raw: Any, links: dict[str, Link]) -> tuple[Moment, ...]:
        """[[moment]]: an external couple on a link (given by its name or its number), N·m."""
        if not isinstance(raw, list):
            raise self.fail("moment", "sc array", table="[[moment]]")
        out = []
        for k, m in enumerate(raw):
            key = f"moment[{k}]"
            m = self.table(m, key, _MOMENT)
            for need in ("link", "magnitude"):
                if need not in m:
                    raise self.fail(f"{key}.{need}", "sc missing")
            stroke = m.get("stroke", "working")
            if stroke not in ("working", "idle", "both"):
                raise self.fail(f"{key}.stroke", "sc one of", choices=either('"working"', '"idle"', '"both"'), got=repr(stroke))
            direction = m.get("direction", "oppose")
            if direction not in ("oppose", "ccw", "cw"):
                raise self.fail(f"{key}.direction", "sc one of", choices=either('"oppose"', '"ccw"', '"cw"'), got=repr(direction))
            link = self.name(m["link"], f"{key}.link")
            numbers = {str(v.number): name for name, v in links.items()}
            if link not in links and link not in numbers:
                known = ", ".join(f"{name} ({v.number})" for name, v in links.items())
                raise self.fail(f"{key}.link", "sc no link", name=repr(link), known=known)
            link = link if link in links else numbers[link]
            out.append(Moment(link=link, magnitude=self.number(m["magnitude"], f"{key}.magnitude", bounds=B.MOMENT),
                              stroke=stroke, direction=direction,
                              profile=self.read_profile(m.get("profile", []), f"{key}.profile")))
        return tuple(out)

    def read_profile(self, raw: Any, key: str) -> tuple[tuple[float, float], ...]:
        """[[distance, factor], …] with the distances increasing."""
        if not isinstance(raw, list):
            raise self.fail(key, "sc profile", pair="[distance, factor]")
        pairs = []
        for p in raw:
            if not isinstance(p, list) or len(p) != 2:
                raise self.fail(key, "sc profile", pair="[distance, factor]")
            pairs.append((self.number(p[0], key, bounds=B.PROFILE_DISTANCE),
                          self.number(p[1], key, bounds=B.PROFILE_FACTOR)))
        if any(b[0] <= a[0] for a, b in zip(pairs, pairs[1:])):
            raise self.fail(key, "sc increase")
        return tuple(pairs)

    def read_diagram(self, raw: Any) -> dict[str, object]:
        """[diagrams]: the diagrams' abscissa L, pole distances H1, H2 (mm), divisions, point, method."""
        raw = self.table(raw, "diagrams", _DIAGRAMS)
        out: dict[str, object] = {}
        for key, bounds in (("L_mm", B.ABSCISSA_MM), ("H1_mm", B.POLE_MM), ("H2_mm", B.POLE_MM)):
            if key in raw:
                out[key] = self.number(raw[key], f"diagrams.{key}", bounds=bounds)
        if "divisions" in raw:
            out["divisions"] = B.check_count(raw["divisions"], B.DIVISIONS, "diagrams.divisions", self.where)
        if "point" in raw:
            out["point"] = self.name(raw["point"], "diagrams.point")
        if "method" in raw:
            if raw["method"] not in ("chords", "tangents"):
                raise self.fail("diagrams.method", "sc one of", choices=either('"chords"', '"tangents"'), got=repr(raw["method"]))
            out["method"] = raw["method"]
        return out

    def read_flywheel(self, raw: Any) -> dict[str, float]:
        """[dynamics]: the coefficient of unevenness δ and the flywheel construction's abscissa L,
        pole distance H (mm) and divisions."""
        raw = self.table(raw, "dynamics", _DYNAMICS)
        out: dict[str, float] = {}
        for key in ("delta", "L_mm", "H_mm"):
            if key in raw:
                out[key] = self.number(raw[key], f"dynamics.{key}", positive=True)
        if "delta" in out and not 0 < out["delta"] < 0.5:
            raise self.fail("dynamics.delta", "sc delta", got=B._g(out["delta"]))
        if "divisions" in raw:
            n = raw["divisions"]
            if isinstance(n, bool) or not isinstance(n, int) or not 4 <= n <= 3600:
                raise self.fail("dynamics.divisions", "bad count", lo=4, hi=3600, got=repr(n))
            out["divisions"] = n
        return out

    def read_drive(self, raw: Any) -> Drive:
        """[dynamics]: the motor (a catalogue name or a table of its data), the catalogue line for
        the choice, the reducer's ratio i, efficiency η and reduced inertia, a rotor inertia."""
        from graphplan.model import motors
        raw = self.table(raw, "dynamics", _DYNAMICS)
        motor, warnings = None, []
        if "motor" in raw:
            value = raw["motor"]
            if isinstance(value, str):
                motor = motors.find(value, self.where)
            elif isinstance(value, dict):
                motor, warnings = motors.from_data(value, "dynamics.motor", self.where)
            else:
                raise self.fail("dynamics.motor", "sc motor")
        rpm = self.number(raw.get("synchronous_rpm", 3000), "dynamics.synchronous_rpm", positive=True)
        eta = self.number(raw.get("efficiency", 1.0), "dynamics.efficiency", positive=True)
        if eta > 1:
            raise self.fail("dynamics.efficiency", "sc efficiency", got=B._g(eta))
        ratio = self.number(raw["ratio"], "dynamics.ratio", positive=True) if "ratio" in raw else None
        rotor = self.number(raw["rotor_inertia"], "dynamics.rotor_inertia") if "rotor_inertia" in raw else None
        reducer = self.number(raw.get("reducer_inertia", 0.0), "dynamics.reducer_inertia")
        for key, v in (("rotor_inertia", rotor), ("reducer_inertia", reducer)):
            if v is not None and v < 0:
                raise self.fail(f"dynamics.{key}", "sc nonnegative", got=B._g(v))
        shafts = raw.get("reducer_shafts", [0.0, 0.0, 0.0])
        if not isinstance(shafts, list) or len(shafts) != 3:
            raise self.fail("dynamics.reducer_shafts", "sc shafts", list="[input, intermediate, output]")
        shafts = tuple(self.number(v, "dynamics.reducer_shafts") for v in shafts)
        if any(v < 0 for v in shafts):
            raise self.fail("dynamics.reducer_shafts", "sc shafts nonnegative")
        first = (self.number(raw["first_stage_ratio"], "dynamics.first_stage_ratio", positive=True)
                 if "first_stage_ratio" in raw else None)
        if shafts[1] > 0 and first is None:
            raise self.fail("dynamics.first_stage_ratio", "sc first stage")
        return Drive(motor, rpm, ratio, eta, reducer, rotor, tuple(warnings), shafts, first)

    def read_meta(self, data: dict[str, Any]) -> dict[str, str]:
        meta = {k: B.clean_text(data[k]) for k in ("title", "title_en", "designation", "designation_en")
                if k in data}
        if "lang" in data:
            if data["lang"] not in ("uk", "en"):
                raise self.fail("lang", "sc one of", choices=either('"uk"', '"en"'), got=repr(data["lang"]))
            meta["lang"] = data["lang"]
        sheet = data.get("sheet", {})
        if not isinstance(sheet, dict):
            raise self.fail("sheet", "sc table")
        meta.update({f"sheet.{B.clean_text(k)}": B.clean_text(v) for k, v in sheet.items()})
        return meta

    def check_unique(self, mech: Mechanism) -> None:
        """A point that is not a joint (a centre of mass, an extra point, a reference) belongs to one
        body only: a frame point S1 and the crank's S1 would make S1 the fixed point in every table."""
        for name, link in mech.links.items():
            for p in link.local:
                if p in link.joints:
                    continue
                if p in mech.frame:
                    raise self.fail(f"link {name}.points.{p}", "sc also frame", name=repr(p))
                others = [n for n, other in mech.links.items() if n != name and p in other.local]
                if others:
                    raise self.fail(f"link {name}.points.{p}", "sc also link", name=repr(p), link=others[0])

    @staticmethod
    def shape_joints(links: dict[str, Link], frame: dict[str, complex]) -> dict[str, Link]:
        """A point placed in a link's ``shape`` (a triangular link's third vertex) that another link
        lists as a joint is a joint of this link too: the textbook draws it once, on the shape."""
        owners: dict[str, list[str]] = {}
        for link in links.values():
            for j in link.joints:
                owners.setdefault(j, []).append(link.name)
        out = dict(links)
        for j, bodies in owners.items():
            if len(bodies) != 1 or j in frame:
                continue
            carriers = [n for n, link in links.items() if n != bodies[0] and j in link.local
                        and j not in link.joints and link.slides_on is None]
            if len(carriers) == 1:
                link = out[carriers[0]]
                out[carriers[0]] = replace(link, joints=link.joints + (j,))
        return out

    def check_names(self, mech: Mechanism) -> None:
        """Every referenced point must exist somewhere; joints must be shared or fixed. The crank's
        pin may join nothing when the crank carries the guide of a slider (a slotted crank)."""
        owners: dict[str, list[str]] = {}
        for link in mech.links.values():
            for j in link.joints:
                owners.setdefault(j, []).append(link.name)
        carries = {mech.guides[link.slides_on].body for link in mech.links.values() if link.slides_on}
        for j, bodies in owners.items():
            if j == mech.crank.pin and bodies == [mech.crank.link] and mech.crank.link in carries:
                continue
            if len(bodies) == 1 and j not in mech.frame:
                sliding = [n for n, link in mech.links.items() if n != bodies[0] and j in link.local
                           and j not in link.joints and link.slides_on is not None]
                if sliding:           # a point of a slider or a yoke: it joins another link only as its joint
                    raise self.fail(f"link {bodies[0]}.joints", "sc joint on sliding", name=repr(j), link=sliding[0],
                                    joints=f'joints = ["{j}"]', ref="ref", through="guide.through")
                raise self.fail(f"link {bodies[0]}.joints", "sc joins nothing", name=repr(j))
        self.check_unique(mech)
        known = set(mech.point_names())
        for key in mech.branches:
            if key not in known:
                raise self.fail(f"branch.{key}", "sc no point")
        if mech.output is not None and mech.output not in known and mech.output not in mech.links:
            raise self.fail("positions.output", "sc output", name=repr(mech.output))
        for f in mech.forces:
            if f.point not in known:
                raise self.fail("force.point", "sc no point named", name=repr(f.point))
        if mech.crank.pin in mech.frame:
            raise self.fail("crank.pin", "sc pin frame")

