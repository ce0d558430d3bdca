"""The public API: the handful of calls a notebook or a script starts from.

Each call returns a *view*: the result of one room (a scene, a study, the plans, the diagrams, a
force analysis, a sheet) together with the ways to show it — ``to_json()`` (the contract's JSON,
SI units), ``table()`` (the terminal's tables; ``str(view)`` is the same), ``svg()`` (a drawing in
true millimetres) and the Jupyter hooks ``_repr_html_``/``_repr_svg_`` (on a white background, so
a dark theme shows it too). The result's own fields stay reachable through the view
(``plans.mu_v``, ``plans.positions``) and as ``view.value``.

The rooms below never show themselves: this module is the only target of the notebook's hooks,
so a low room (the model, the exact solution, a construction) needs no import of a drawing room.

    >>> import graphplan
    >>> s = graphplan.load("examples/shaper.toml")
    >>> p = graphplan.plans(s, precision=0.5)
    >>> p.velocity(1).svg()[:4]
    '<svg'
"""
from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

WHITE = ('<div style="background:#fff;color:#000;display:inline-block;padding:6px;'
         'max-width:100%;overflow:auto">{}</div>')


@dataclass
class View:
    """A result with the ways to show it; subclasses say how."""
    value: Any
    lang: str = "uk"

    def __getattr__(self, name: str) -> Any:   # the result's own fields: plans.mu_v, …
        if name.startswith("__") or name == "value":
            raise AttributeError(name)
        return getattr(self.value, name)

    def to_json(self) -> dict[str, Any]:
        raise TypeError(f"{type(self).__name__} has no JSON form")

    def table(self) -> str:
        return repr(self.value)

    def svg(self) -> str:
        raise TypeError(f"{type(self).__name__} has no drawing")

    def __str__(self) -> str:
        return self.table()

    def _repr_svg_(self) -> str:
        return self.svg()

    def _repr_html_(self) -> str:
        return WHITE.format(self.svg())


def _page(record, title: str | None = None) -> str:
    """A record on a page just large enough for it, as SVG in true millimetres."""
    from graphplan.drawing.svg import page_for, render
    rec, w, h = page_for(record)
    return render(rec, w, h, title or rec.title)


# -- the scene and its study -------------------------------------------------------------------------

class Scene(View):
    """A scene read into the mechanism model: its structure, shown as the position plan."""

    def study(self) -> Study:
        return study(self)

    def to_json(self) -> dict[str, Any]:
        return self.study().to_json()

    def table(self) -> str:
        return self.study().table()

    def svg(self) -> str:
        return self.study().svg()


class Study(View):
    """A mechanism with its structure, position 0 and extreme positions; the exact solution."""

    def _angles(self):
        return self.value.positions()

    def to_json(self) -> dict[str, Any]:
        """The contract's ``analyze --json`` over the scene's positions."""
        import numpy as np

        from graphplan.report.analysis import analyze_json
        phi = np.asarray(self._angles())
        return analyze_json(self.value, phi, list(range(len(phi))))

    def table(self) -> str:
        import numpy as np

        from graphplan.report.analysis import analyze_table
        phi = np.asarray(self._angles())
        return analyze_table(self.value, phi, list(range(len(phi))), self.lang)

    def svg(self) -> str:
        return plans(self, precision=0.0).svg()


# -- the graphical constructions ---------------------------------------------------------------------

class Plan(View):
    """One velocity or acceleration plan (the pole at the origin), with its readings."""

    def __init__(self, plans_view: Plans, key: int, kind: str):
        super().__init__(plans_view.value.at(key), plans_view.lang)
        self.plans_view, self.key, self.kind = plans_view, key, kind

    @property
    def plan(self):
        return self.value.velocity if self.kind == "velocity" else self.value.acceleration

    def to_json(self) -> dict[str, Any]:
        """This position's entry of the contract's ``plans --json``."""
        from graphplan.report.plans import position_json
        return position_json(self.plans_view.value, self.value)

    def table(self) -> str:
        doc = self.to_json()
        entries = doc["velocity" if self.kind == "velocity" else "acceleration"]
        from graphplan.util.words import fixed, num, pct, unit, word
        lang = self.lang
        lines = [f"{word(self.kind + ' plan', lang)}, φ = {fixed(doc['phi_deg'], lang, 2)}°"]
        for key, e in entries.items():
            err = "—" if e.get("error_pct") is None else f"{pct(e['error_pct'], lang)} %"
            mm = f"{fixed(e['mm'], lang, 1):>8} {unit('mm', lang)}" if "mm" in e else " " * 11
            lines.append(f"  {key:<14}{mm}  {num(e['value'], lang, 5):>12}  {num(e['analytic'], lang, 5):>12}  {err}")
        return "\n".join(lines) + "\n"

    def svg(self) -> str:
        from graphplan.drawing.plans import labelled
        rec = labelled(self.plan)
        from graphplan.util.words import fixed, word
        rec.title = f"{word(self.kind + ' plan', self.lang)}, φ = {fixed(self.value.phi, self.lang, 1)}°"
        return _page(rec)


class Plans(View):
    """The position plan, the velocity plans of every position and the acceleration plans."""

    def velocity(self, position: int) -> Plan:
        """The velocity plan of position ``position`` (an index from position 0)."""
        return Plan(self, self._key(position, "velocity"), "velocity")

    def acceleration(self, position: int | None = None) -> Plan:
        """An acceleration plan: of ``position``, or the first one drawn."""
        keys = self.value.accel_keys
        if position is None:
            if not keys:
                from graphplan.util.errors import GraphplanError
                raise GraphplanError("no acceleration plan was asked for (accel=…)")
            return Plan(self, keys[0], "acceleration")
        return Plan(self, self._key(position, "acceleration"), "acceleration")

    def _key(self, position: int, kind: str) -> int:
        from graphplan.util.errors import GraphplanError
        for p in self.value.positions:
            if p.index == position and (kind == "velocity" or p.acceleration is not None):
                return p.key
        raise GraphplanError(f"no {kind} plan at position {position}")

    def to_json(self) -> dict[str, Any]:
        from graphplan.report.plans import plans_json
        return plans_json(self.value)

    def table(self) -> str:
        from graphplan.report.plans import plans_table
        return plans_table(self.value, self.lang)

    def svg(self) -> str:
        from graphplan.drawing.plans import position_record
        return _page(position_record(self.value), self.value.study.mech.title)


class Diagrams(View):
    """The s–v–a diagrams with their pole constructions, measured and compared."""

    def to_json(self) -> dict[str, Any]:
        from graphplan.report.diagrams import diagrams_json
        return diagrams_json(self.value)

    def table(self) -> str:
        from graphplan.report.diagrams import diagrams_table
        return diagrams_table(self.value, self.lang)

    def svg(self) -> str:
        from graphplan.drawing.diagrams import diagrams_svg
        return diagrams_svg(self.value, self.lang)


class ForcePart(View):
    """A part of a force analysis drawn on its own: the force plans or the Zhukovsky lever."""

    def __init__(self, forces_view: Forces, part: str):
        super().__init__(forces_view.value, forces_view.lang)
        self.forces_view, self.part = forces_view, part

    def to_json(self) -> dict[str, Any]:
        doc = self.forces_view.to_json()
        if self.part == "lever":
            return {"mu_v": doc["mu_v"], "balancing_force": doc["balancing_force"],
                    "balancing_moment": doc["balancing_moment"]["lever"]}
        return {"mu_F": doc["mu_F"], "reactions": doc["reactions"]}

    def table(self) -> str:
        return self.forces_view.table()

    def svg(self) -> str:
        from graphplan.drawing.forces import drawing, lever_record
        return _page(lever_record(self.value, self.lang) if self.part == "lever" else drawing(self.value, self.lang))


class Forces(View):
    """Kinetostatics at one crank angle: reactions by force plans, the balancing moment four ways."""

    @property
    def plans(self) -> ForcePart:
        """The groups with their force plans."""
        return ForcePart(self, "plans")

    @property
    def lever(self) -> ForcePart:
        """The Zhukovsky lever: the velocity plan turned 90° with the forces at their images."""
        return ForcePart(self, "lever")

    def to_json(self) -> dict[str, Any]:
        from graphplan.report.forces import forces_json
        return forces_json(self.value)

    def table(self) -> str:
        from graphplan.report.forces import forces_table
        return forces_table(self.value, self.lang)

    def svg(self) -> str:
        return self.plans.svg()


class Dynamics(View):
    """The machine's dynamics reduced to the crank: the flywheel by the Wittenbauer construction
    against the exact one from the equation of motion, and the motor."""

    def to_json(self) -> dict[str, Any]:
        from graphplan.report.dynamics import dynamics_json
        return dynamics_json(self.value)

    def table(self) -> str:
        from graphplan.report.dynamics import dynamics_table
        return dynamics_table(self.value, self.lang)

    def svg(self) -> str:
        from graphplan.drawing.flywheel import wittenbauer_record
        return _page(wittenbauer_record(self.value, self.lang))


class Cam(View):
    """A cam mechanism synthesised graphically beside its exact solution: ``value`` is the pair
    (exact solution, graphical construction); shown as the profile by inversion."""

    def to_json(self) -> dict[str, Any]:
        from graphplan.report.cam import cam_json
        sol, g = self.value
        return cam_json(sol, g, sol.cam.source or "")

    def table(self) -> str:
        from graphplan.report.cam import cam_table
        sol, _ = self.value
        return cam_table(self.to_json(), self.lang, sol.cam.title_in(self.lang))

    def svg(self) -> str:
        from graphplan.drawing.cam import profile_drawing
        sol, g = self.value
        return _page(profile_drawing(sol, g, self.lang))


def cam(scene, divisions: int | None = None, precision: float = 0.5, lang: str = "uk") -> Cam:
    """A cam scene (a path to a file with a [cam] table) solved exactly and constructed graphically
    with ``divisions`` intervals a phase, read with a ruler of ``precision`` mm (docs/cams.md)."""
    from graphplan.exact.cam import solve
    from graphplan.model.cam import load as load_cam
    from graphplan.sheets.cam import construct_on
    from graphplan.sheets.form import form
    sol = solve(load_cam(scene))
    return Cam((sol, construct_on(sol, form("A1"), divisions, precision, lang)), lang)    # the A1 sheet's scales


class Gears(View):
    """A gear scene synthesised: the pair drawn in mesh and the planetary train's velocity pictures,
    each reading beside the closed forms; ``value`` is (gears, solution, mesh, velocities); shown as
    the meshing (else the train's pictures)."""

    def to_json(self) -> dict[str, Any]:
        from graphplan.report.gears import gears_json
        g, sol, mesh, vel = self.value
        return gears_json(sol, mesh, vel, g.source or "")

    def table(self) -> str:
        from graphplan.report.gears import gears_table
        g = self.value[0]
        return gears_table(self.to_json(), self.lang, g.title_in(self.lang))

    def svg(self) -> str:
        _, _, mesh, vel = self.value
        return _page(mesh.record if mesh is not None else vel.record)


def gears(scene, precision: float = 0.5, lang: str = "uk", fmt: str = "A1") -> Gears:
    """A gear scene (a path to a file with [gears] and/or [planetary]) solved by the closed forms and
    constructed graphically at the scales of the gear sheet on ``fmt``, read with a ruler of
    ``precision`` mm (docs/gears.md)."""
    from graphplan.exact.gears import solve
    from graphplan.model.gears import load
    from graphplan.sheets.form import form
    from graphplan.sheets.gears import on_sheet
    g = load(scene)
    sol = solve(g)
    mesh, vel, _ = on_sheet(g, sol, form(fmt), precision, lang)     # that sheet's (set's) readings
    return Gears((g, sol, mesh, vel), lang)


class Sheet(View):
    """A drawing sheet (frame, title block, blocks); ``save(path)`` writes .svg, .pdf, .png or .dxf."""

    def to_json(self) -> dict[str, Any]:
        f = self.value.form
        return {"format": f.name, "width_mm": f.width, "height_mm": f.height, "lang": self.value.lang,
                "blocks": [p.name for p in self.value.placed]}

    def table(self) -> str:
        doc = self.to_json()
        return (f"{doc['format']} {doc['width_mm']:g}×{doc['height_mm']:g} mm: "
                + ", ".join(doc["blocks"]) + "\n")

    def svg(self) -> str:
        return self.value.svg()

    def save(self, path: str | Path, text_as_paths: bool = False, dpi: float = 300) -> Path:
        return self.value.write(path, text_as_paths, dpi)


# -- the calls ------------------------------------------------------------------------------------

def _study_of(scene):
    """A study from a path, a Scene or Study view, a Mechanism or a Study."""
    from graphplan.exact.positions import Study as _Study
    from graphplan.exact.positions import study as _study
    if isinstance(scene, View):
        scene = scene.value
    if isinstance(scene, (str, Path)) or scene is None:
        scene = load(scene).value
    return scene if isinstance(scene, _Study) else _study(scene)


def load(path: str | Path | None = None, lang: str = "uk") -> Scene:
    """Read a scene file (TOML, docs/scenes.md); without a path, the built-in crank-slider."""
    from graphplan.model.scene import load as _load
    return Scene(_load(None if path is None else str(path)), lang)


def study(scene=None, lang: str = "uk") -> Study:
    """Structure, position 0 and the extreme positions: what every construction starts from."""
    return Study(_study_of(scene), lang)


def plans(scene=None, positions: int | None = None, accel: Sequence[str | int | float] | None = None,
          precision: float = 0.5, lang: str = "uk", format: str | None = "A1", **scales: float) -> Plans:
    """The position plan, every velocity plan and the acceleration plans (``accel``: indices, "#3",
    or crank angles), read with a ruler of ``precision`` mm, at the scales the kinematics sheet of
    ``format`` draws with (as ``graphplan plans`` prints them; None: the plans' own scales);
    ``mu_l``, ``mu_v``, ``mu_a`` fix scales."""
    from graphplan.graphic.plans import build_plans
    st = _study_of(scene)
    if format and any(scales.get(k) is None for k in ("mu_l", "mu_v", "mu_a")):
        from graphplan.sheets.kinematics import sheet_scales
        drawn = sheet_scales(st, format, positions, accel, precision)
        scales = {k: scales.get(k) if scales.get(k) is not None else drawn[k] for k in ("mu_l", "mu_v", "mu_a")}
    return Plans(build_plans(st, count=positions, accel=accel, precision=precision, **scales), lang)


def diagrams(scene=None, point: str | None = None, divisions: int | None = None, precision: float = 0.5,
             lang: str = "uk", **options: Any) -> Diagrams:
    """The s–v–a diagrams of ``point`` (default: the scene's output) by the method of chords (or
    ``method="tangents"``, ``angle_error_deg=``; ``correct=True`` for the lab's area correction);
    ``L``, ``H1``, ``H2`` (mm) and ``method`` default to the scene's ``[diagrams]`` table."""
    from graphplan.graphic.diagrams import chord_diagrams
    st = _study_of(scene)
    given = st.mech.task.diagram
    for key, name in (("L", "L_mm"), ("H1", "H1_mm"), ("H2", "H2_mm"), ("method", "method")):
        if key not in options and name in given:
            options[key] = given[name]
    if divisions is None and not {"L", "H1", "H2", "height"} & set(options):
        from graphplan.sheets.kinematics import sheet_scales     # as the A1 sheet draws them
        drawn = sheet_scales(st, "A1", precision=precision)
        options.update({k: drawn[k] for k in ("L", "H1", "H2", "height")})
        if not {"point", "method", "correct", "adaptive", "tolerance"} & set(options) and point is None:
            chosen = drawn["diagrams"]        # redrawn as the sheet redraws it (graphic.redraw)
            options.update({k: chosen[k] for k in ("correct", "adaptive", "tolerance", "redrawn", "fit") if k in chosen})
    return Diagrams(chord_diagrams(st, point=point, divisions=divisions, precision=precision, lang=lang,
                                   **options), lang)


def forces(scene=None, phi: float | None = None, precision: float = 0.5, lang: str = "uk") -> Forces:
    """Kinetostatics at crank angle ``phi`` (deg; default: the scene's force position)."""
    from graphplan.exact.kinetostatics import at_scene_angle
    from graphplan.graphic.forceplans import construct
    st = _study_of(scene)
    angle = at_scene_angle(st) if phi is None else float(phi) % 360.0
    scales = {}
    if phi is None:                   # the force position: the scales the A1 force sheet draws with
        from graphplan.sheets.forces import force_scales, has_loads
        if has_loads(st):
            scales = force_scales(st, "A1", precision)
    return Forces(construct(st, angle, precision, **scales), lang)


def dynamics(scene=None, delta: float | None = None, divisions: int | None = None, precision: float = 0.5,
             lang: str = "uk") -> Dynamics:
    """The exact dynamics (δ: the scene's [dynamics] delta, else 0.04) and the flywheel's graphical
    construction over ``divisions`` of the turn read with a ruler of ``precision`` mm."""
    from graphplan.exact.dynamics import analyse, check_divisions
    from graphplan.graphic.flywheel import redrawn
    from graphplan.sheets.dynamics import dynamics_scales
    if divisions is not None:
        check_divisions(divisions)
    st = _study_of(scene)
    dyn = analyse(st, delta)
    return Dynamics(redrawn(dyn, divisions, precision, given="option" if divisions is not None else None,
                            **dynamics_scales(st, dyn, "A1", divisions, precision)), lang)


def sheet(scene=None, kind: str = "kinematics", format: str = "A1", lang: str = "uk",
          precision: float = 0.5, positions: int | None = None,
          accel: Sequence[str | int | float] | None = None) -> Sheet:
    """A drawing sheet: ``kind`` "kinematics", "forces", "dynamics" or "gears" (a gear scene's path), on
    ``format`` A1…A3, in ``lang``."""
    from types import SimpleNamespace

    from graphplan.sheets.form import form
    from graphplan.sheets.sheet import BUILDERS
    from graphplan.util.errors import GraphplanError
    build = BUILDERS.get(kind)
    if build is None:
        raise GraphplanError(f"sheet kind {kind!r}: use one of {', '.join(BUILDERS)}")
    options = SimpleNamespace(positions=positions, accel=[f"#{a}" if isinstance(a, int) else str(a) for a in accel] if accel else None,
                              precision=precision, lang=lang, sheet=kind)
    if kind == "gears":                     # a gear scene: the sheet takes the gears themselves
        from graphplan.model.gears import Gears as GearScene
        from graphplan.model.gears import load as load_gears
        target = scene if isinstance(scene, GearScene) else load_gears(scene)
        return Sheet(build(target, form(format), options), lang)
    return Sheet(build(_study_of(scene), form(format), options), lang)
