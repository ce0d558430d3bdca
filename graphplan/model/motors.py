"""Induction motors (seed 003): the catalogue shipped as package data (graphplan/data/motors.toml)
and the working branch of a motor's mechanical characteristic as a straight line.

The stable part of the characteristic between the rated point (ω_n, M_n) and the synchronous
speed (ω_c, 0) is taken as the line  M = A·ω + B,  A = M_n/(ω_n − ω_c),  B = −A·ω_c  (A < 0),
with M_n = P_n/ω_n. The line reaches the breakdown moment M_max = λ·M_n at ω_k = ω_c + λ·M_n/A;
below ω_k the motor has left its working branch.
"""
from __future__ import annotations

import math
import tomllib
import unicodedata
from dataclasses import dataclass
from functools import lru_cache
from importlib import resources

from graphplan.util.errors import GraphplanError, keyed_error

CATALOGUE = "motors.toml"


@dataclass(frozen=True)
class Motor:
    """An induction motor's data sheet: rated power (kW), synchronous and rated speed (rpm),
    M_max/M_n, M_start/M_n and the rotor's moment of inertia (kg·m²) — ``inertia_estimated`` where
    the handbooks do not tabulate it (the 50–63 frames: estimated from the 71 frame's by M_n)."""
    name: str
    power_kW: float
    rpm_sync: float
    rpm_rated: float
    max_ratio: float = 2.2
    start_ratio: float = 2.0
    inertia: float = 0.0
    inertia_estimated: bool = False     # the rotor's inertia not tabulated, estimated (data/motors.toml's header)

    @property
    def omega_sync(self) -> float:
        """ω_c = π·n_c/30, rad/s."""
        return math.pi * self.rpm_sync / 30.0

    @property
    def omega_rated(self) -> float:
        """ω_n = π·n_n/30, rad/s."""
        return math.pi * self.rpm_rated / 30.0

    @property
    def moment_rated(self) -> float:
        """M_n = P_n/ω_n, N·m."""
        return self.power_kW * 1000.0 / self.omega_rated

    @property
    def moment_max(self) -> float:
        """M_max = λ·M_n, N·m."""
        return self.max_ratio * self.moment_rated

    @property
    def line(self) -> tuple[float, float]:
        """(A, B) of the working branch M = A·ω + B: A = M_n/(ω_n − ω_c), B = −A·ω_c."""
        a = self.moment_rated / (self.omega_rated - self.omega_sync)
        return a, -a * self.omega_sync

    @property
    def omega_breakdown(self) -> float:
        """ω_k where the line reaches M_max: ω_c + M_max/A (the end of the working branch)."""
        return self.omega_sync + self.moment_max / self.line[0]

    def moment(self, omega):
        """M = A·ω + B at the motor's speed ω (rad/s)."""
        a, b = self.line
        return a * omega + b


def _key(name: str) -> str:
    """Catalogue names compared without case and with Latin and Cyrillic look-alikes merged
    (4АМ80А2 = 4AM80A2)."""
    text = unicodedata.normalize("NFC", name).upper().replace(" ", "")
    return text.translate(str.maketrans("АВМСЕНКОРТХ", "ABMCEHKOPTX"))


_LOOKALIKE = str.maketrans("АВМСЕНКОРТХ", "ABMCEHKOPTX")


def latin(name: str) -> str:
    """A catalogue designation as an English sheet writes it: the series' Cyrillic capitals that
    look like Latin ones in Latin (4АМ132S4 → 4AM132S4, as the English catalogues print the 4A/4AM
    series); a name with any other Cyrillic letter stays as it is."""
    out = name.translate(_LOOKALIKE)
    return name if any("\u0400" <= c <= "\u04ff" for c in out) else out


@lru_cache(maxsize=1)
def catalogue() -> tuple[Motor, ...]:
    """The shipped catalogue, in file order (by line, then power)."""
    text = (resources.files("graphplan") / "data" / CATALOGUE).read_text(encoding="utf-8")
    return tuple(Motor(**m) for m in tomllib.loads(text)["motor"])


def _g(value: float) -> object:
    """A value for a refusal written "%g" in each language (a decimal comma in Ukrainian)."""
    return lambda lang: f"{value:g}".replace(".", ",") if lang == "uk" else f"{value:g}"


def _unit(key: str, lang: str) -> str:
    from graphplan.util.words import unit
    return unit(key, lang) if key else ""


def find(name: str, where: str | None = None) -> Motor:
    """The catalogue's motor of that name."""
    for m in catalogue():
        if _key(m.name) == _key(name):
            return m
    raise keyed_error(GraphplanError, where, "dynamics.motor", "mo no motor", name=repr(name),
                      first=catalogue()[0].name, last=catalogue()[-1].name)


def choose(power_kW: float, rpm_sync: float, where: str | None = None) -> Motor:
    """Seed 003's rule: the next size up — the smallest motor of the line with P_n ≥ the power."""
    line = sorted((m for m in catalogue() if m.rpm_sync == rpm_sync), key=lambda m: m.power_kW)
    if not line:
        lines = ", ".join(f"{v:g}" for v in sorted({m.rpm_sync for m in catalogue()}, reverse=True))
        raise keyed_error(GraphplanError, where, "dynamics.synchronous_rpm", "mo no line", speed=_g(rpm_sync),
                          lines=lines)
    for m in line:
        if m.power_kW >= power_kW * (1 - 1e-12):
            return m
    raise keyed_error(GraphplanError, where, "dynamics.motor", "mo too weak", power=float(power_kW),
                      speed=_g(rpm_sync), name=line[-1].name, largest=_g(line[-1].power_kW))


# what a motor's data may hold (lowest, highest, unit): the catalogue's motors reach 315 kW and 3000 rpm;
# a value beyond these is a typo, and 1e308 kW would overflow the dynamics' integration
_RANGES = {"power_kW": (0.0, 1e5, "kW"), "rpm_sync": (0.0, 1e5, "rpm"), "rpm_rated": (0.0, 1e5, "rpm"),
           "max_ratio": (1.0, 20.0, ""), "start_ratio": (0.0, 20.0, ""), "inertia": (0.0, 1e3, "kg·m²"),
           "omega_sync": (0.0, 1e4, "rad/s"), "omega_rated": (0.0, 1e4, "rad/s")}


def from_data(raw: dict, key: str, where: str | None = None) -> tuple[Motor, list[tuple[str, str]]]:
    """A motor given by its data in a scene: name, power_kW, rpm_sync, rpm_rated, max_ratio,
    start_ratio, inertia and, as papers print them, omega_sync/omega_rated (rad/s). The angular
    speeds are always computed from the rpm; printed ones that disagree (seed 003 lists
    ω_c = 298.3 and ω_n = 314 s⁻¹, swapped against 3000/2850 rpm) give a warning (English, Ukrainian)."""
    allowed = {"name", "power_kW", "rpm_sync", "rpm_rated", "max_ratio", "start_ratio", "inertia",
               "omega_sync", "omega_rated"}
    unknown = sorted(set(raw) - allowed)
    if unknown:
        raise keyed_error(GraphplanError, where, f"{key}.{unknown[0]}", "sc unknown key",
                          allowed=", ".join(sorted(allowed)))
    base = find(str(raw["name"]), where) if "name" in raw and not ({"power_kW", "rpm_rated"} & set(raw)) else None
    values = dict(base.__dict__) if base else {"name": str(raw.get("name", "motor"))}
    for field in ("power_kW", "rpm_sync", "rpm_rated", "max_ratio", "start_ratio", "inertia",
                  "omega_sync", "omega_rated"):
        if field in raw:
            v, (lo, hi, unit) = raw[field], _RANGES[field]
            if isinstance(v, bool) or not isinstance(v, (int, float)) or not (lo <= v <= hi) \
                    or not math.isfinite(v) or (v == 0 and field != "inertia"):    # a 200-digit int: no float()
                shown = repr(v) if isinstance(v, (int, float, str)) else type(v).__name__
                raise keyed_error(GraphplanError, where, f"{key}.{field}",
                                  "mo number" if field == "inertia" else "mo positive", hi=_g(hi),
                                  unit=lambda lang, u=unit: _unit(u, lang), got=shown[:40])
            if not field.startswith("omega"):
                values[field] = float(v)
    for need in ("power_kW", "rpm_sync", "rpm_rated"):
        if need not in values:
            raise keyed_error(GraphplanError, where, f"{key}.{need}", "mo missing")
    motor = Motor(**values)
    if motor.rpm_rated >= motor.rpm_sync:
        raise keyed_error(GraphplanError, where, key, "mo rated", rated=_g(motor.rpm_rated), sync=_g(motor.rpm_sync))
    warnings = []
    printed = {k: float(raw[k]) for k in ("omega_sync", "omega_rated") if k in raw}
    computed = {"omega_sync": motor.omega_sync, "omega_rated": motor.omega_rated}
    off = [k for k, v in printed.items() if abs(v - computed[k]) > 5e-3 * computed[k]]
    if off:
        swapped = (len(printed) == 2 and abs(printed["omega_sync"] - computed["omega_rated"]) < 5e-3 * computed["omega_rated"] + 0.5
                   and abs(printed["omega_rated"] - computed["omega_sync"]) < 5e-3 * computed["omega_sync"] + 0.5)
        symbol = {"omega_sync": "ω_c", "omega_rated": "ω_n"}
        def listed(comma: bool) -> str:
            text = ", ".join(f"{symbol[k]} = {printed[k]:g}" for k in sorted(printed))
            return text.replace(".", ",").replace(", ω", "; ω") if comma else text
        def computed_text(comma: bool) -> str:
            text = f"ω_c = {motor.omega_sync:.2f}, ω_n = {motor.omega_rated:.2f}"
            return text.replace(".", ",").replace(", ω", "; ω") if comma else text
        warnings.append((f"{key}: the given {listed(False)} rad/s {'are swapped' if swapped else 'disagree'} against "
                         f"{motor.rpm_sync:g}/{motor.rpm_rated:g} rpm; computed from the speeds: {computed_text(False)} rad/s",
                         f"двигун: задані {listed(True)} рад/с {'переставлені відносно' if swapped else 'не відповідають'} "
                         f"{motor.rpm_sync:g}/{motor.rpm_rated:g} об/хв; обчислено за швидкостями: {computed_text(True)} рад/с"))
    return motor, warnings
