"""The explorer's step-by-step replay of a velocity or acceleration plan, in the textbook's order.

The plan's construction (graphic.plan: each group's ``Solved`` with its two equations, the points'
vectors from the pole, the links' similar figures) is cut into the steps a student draws:

1. the crank's vector (p_v a = v_A, or π a = a_A);
2. for each Assur group, first any known point it starts from that is not found yet (by
   similarity: b on the rocker before the rod's group uses it), then the known components laid
   off (normal a^n, Coriolis a^k), then BOTH direction lines through their points, then the
   intersection marked and lettered, then the found vectors with their arrows;
3. the remaining points by similarity (centres of mass), the links' similar figures.

A plan point is lettered from the step that finds it, never before. Each step's caption says the
rule in words ("through b, perpendicular to CB") in Ukrainian and English, in the typesetting
markup of util.markup (the page sets sub- and superscripts). Nothing is drawn here: a step names
the record's primitives it shows.
"""
from __future__ import annotations

import re
from typing import Any

from graphplan.graphic.plan import Plan, Solved
from graphplan.graphic.plans import Plans
from graphplan.graphic.position_plan import sub, where
from graphplan.graphic.record import Record
from graphplan.util.markup import indexed
from graphplan.util.words import LANGS, fixed, num, unit

MM = 3              # decimals of drawing millimetres
COINCIDE = 0.3      # mm: plan points this close are one place (nothing shorter is drawn)


def mm(x: float) -> float:
    """A drawing length for the page: 3 decimals, no −0."""
    v = round(float(x), MM)
    return 0.0 if v == 0 else v


def same_point(sub_: str) -> bool:
    """"A3A2": two bodies' points at one place (a sliding pair) — the relative motion is along the guide."""
    return re.fullmatch(r"([A-Za-z]+)[\d_]+\1[\d_]*", sub_) is not None


def braced(name: str) -> str:
    """A plan name ready to be followed by another: "n_1" → "n_{1}", "p_v" → "p_{v}" (util.markup
    would read "p_vb" as p with the subscript vb)."""
    return re.sub(r"_([^{}\s]+)$", r"_{\1}", name)


def seg(a: str, b: str) -> str:
    """The plan segment from a to b as the lab writes it: "p_{v}b", "n_{1}c"."""
    return braced(a) + b


# -- the words, Ukrainian and English (markup of util.markup) ----------------------------------------

SAY: dict[str, tuple[str, str]] = {
    "crank v": ("{seg} = v_{pin}{also} = ω_1·l_{{{arm}}} = {value} {unit}: {mm} мм перпендикулярно до {arm_l}, у бік ω_1",
                "{seg} = v_{pin}{also} = ω_1·l_{{{arm}}} = {value} {unit}: {mm} mm perpendicular to {arm_l}, in the sense of ω_1"),
    "crank a": ("{seg} = a_{pin}{also} = ω_1^2·l_{{{arm}}} = {value} {unit}: {mm} мм паралельно до {back}, до {pivot}",
                "{seg} = a_{pin}{also} = ω_1^2·l_{{{arm}}} = {value} {unit}: {mm} mm parallel to {back}, toward {pivot}"),
    "crank a eps": ("{n} = a^n_{pin} = ω_1^2·l_{{{arm}}}, паралельно до {back}, до {pivot}; {t} = a^τ_{pin} = "
                    "ε_1·l_{{{arm}}}, перпендикулярно до {arm_l}; {seg} = a_{pin}{also} = {value} {unit}: {mm} мм",
                    "{n} = a^n_{pin} = ω_1^2·l_{{{arm}}}, parallel to {back}, toward {pivot}; {t} = a^τ_{pin} = "
                    "ε_1·l_{{{arm}}}, perpendicular to {arm_l}; {seg} = a_{pin}{also} = {value} {unit}: {mm} mm"),
    "normal": ("Від {base} відкладаємо {seg} = a^n_{{{sub}}} = v^2_{{{sub}}}/l_{{{sub}}} = {value} {unit}: "
               "{mm} мм паралельно до {link}, до {toward}",
               "From {base} lay off {seg} = a^n_{{{sub}}} = v^2_{{{sub}}}/l_{{{sub}}} = {value} {unit}: "
               "{mm} mm parallel to {link}, toward {toward}"),
    "coriolis": ("Від {base} відкладаємо {seg} = a^k_{{{sub}}} = 2·ω_{{{carrier}}}·v_{{{sub}}} = {value} {unit}: "
                 "{mm} мм уздовж v_{{{sub}}}, повернутої на 90° у бік ω_{{{carrier}}} (прискорення Коріоліса)",
                 "From {base} lay off {seg} = a^k_{{{sub}}} = 2·ω_{{{carrier}}}·v_{{{sub}}} = {value} {unit}: "
                 "{mm} mm along v_{{{sub}}} turned 90° in the sense of ω_{{{carrier}}} (the Coriolis acceleration)"),
    "zero normal": ("a^n_{{{sub}}} = v^2_{{{sub}}}/l_{{{sub}}} ≈ 0: відкладати нічого, {end} збігається з {base}",
                    "a^n_{{{sub}}} = v^2_{{{sub}}}/l_{{{sub}}} ≈ 0: nothing to lay off, {end} coincides with {base}"),
    "zero coriolis": ("a^k_{{{sub}}} = 2·ω_{{{carrier}}}·v_{{{sub}}} ≈ 0: відкладати нічого, {end} збігається з {base}",
                      "a^k_{{{sub}}} = 2·ω_{{{carrier}}}·v_{{{sub}}} ≈ 0: nothing to lay off, {end} coincides with {base}"),
    "line": ("Через {through} проводимо пряму {rule} — напрям {term}",
             "Through {through} draw a line {rule}: the direction of {term}"),
    "perp": ("перпендикулярно до {what}", "perpendicular to {what}"),
    "link": ("паралельно до ланки {what}", "parallel to the link {what}"),
    "guide": ("паралельно до напрямної точки {what}", "parallel to the guide of {what}"),
    "meet": ("Прямі перетинаються в точці {found}: точку {found} знайдено",
             "The two lines cross at {found}: the point {found} is found"),
    "meet pole": ("Прямі перетинаються в полюсі {pole}: точка {found} збігається з {pole}, {sym}_{{{X}}} = 0 "
                  "(мертве положення)",
                  "The two lines cross at the pole {pole}: {found} coincides with {pole}, {sym}_{{{X}}} = 0 "
                  "(a dead centre)"),
    "found": ("Знайдені вектори: {list}", "The found vectors: {list}"),
    "reading": ("{seg} = {term}: {mm} мм → {value} {unit}", "{seg} = {term}: {mm} mm → {value} {unit}"),
    "zero reading": ("{term} = 0", "{term} = 0"),
    "on line": ("{x} за подібністю: на прямій {pq}, {px} : {pq} = {PX} : {PQ}",
                "{x} by similarity: on the line {pq}, {px} : {pq} = {PX} : {PQ}"),
    "triangle": ("{x} за подібністю: трикутник {pqx} подібний до {PQX}",
                 "{x} by similarity: the triangle {pqx} is similar to {PQX}"),
    "similar": ("{x} за подібністю", "{x} by similarity"),
    "together": ("{x} за подібністю: {p} і {q} збігаються, тож і {x} там само",
                 "{x} by similarity: {p} and {q} coincide, so {x} is there too"),
    "pole point": ("{x}: точка нерухомої ланки, збігається з полюсом {pole}",
                   "{x}: a point of the frame, at the pole {pole}"),
    "absolute": ("{seg} = {sym}_{{{X}}}: {mm} мм → {value} {unit}", "{seg} = {sym}_{{{X}}}: {mm} mm → {value} {unit}"),
    "at pole": ("{x} збігається з {pole}: {sym}_{{{X}}} = 0", "{x} coincides with {pole}: {sym}_{{{X}}} = 0"),
    "figure": ("Подібна фігура ланки {link} на плані: {fig}", "The similar figure of the link {link} on the plan: {fig}"),
    "rest": ("{eq}", "{eq}"),
    "scale": ("Крок 0: полюс і масштаб. Полюс {pole} ставимо в будь-якому місці аркуша. Беремо {seg} ≈ {trial} мм "
              "для {sym}_{pin} = {value} {unit} ⇒ μ_{s} = {sym}_{pin}/{seg} = {value}/{trial} = {raw} {munit}; "
              "заокруглюємо до стандартного масштабу (1; 2; 2,5; 4; 5·10^k), не дрібнішого{why}: "
              "μ_{s} = {mu} {munit}; тоді {seg} = {sym}_{pin}/μ_{s} = {drawn} мм",
              "Step 0: the pole and the scale. Put the pole {pole} anywhere on the sheet. Take {seg} ≈ {trial} mm "
              "for {sym}_{pin} = {value} {unit} ⇒ μ_{s} = {sym}_{pin}/{seg} = {value}/{trial} = {raw} {munit}; "
              "round it to a standard scale (1, 2, 2.5, 4, 5·10^k), not finer{why}: "
              "μ_{s} = {mu} {munit}; then {seg} = {sym}_{pin}/μ_{s} = {drawn} mm"),
    "scale chosen": ("Крок 0: полюс і масштаб. Полюс {pole} ставимо в будь-якому місці аркуша. Беремо {seg} = {trial} мм "
                     "(не коротше {least} мм, щоб план читався) для {sym}_{pin} = {value} {unit} ⇒ μ_{s} = "
                     "{sym}_{pin}/{seg} = {value}/{trial} = {raw} {munit}; записуємо три значущі цифри, заокругливши "
                     "вниз: μ_{s} = {mu} {munit}; тоді {seg} = {sym}_{pin}/μ_{s} = {drawn} мм",
                     "Step 0: the pole and the scale. Put the pole {pole} anywhere on the sheet. Take {seg} = {trial} mm "
                     "(not shorter than {least} mm, for the plan to read) for {sym}_{pin} = {value} {unit} ⇒ μ_{s} = "
                     "{sym}_{pin}/{seg} = {value}/{trial} = {raw} {munit}; write it to three significant figures, "
                     "rounded down: μ_{s} = {mu} {munit}; then {seg} = {sym}_{pin}/μ_{s} = {drawn} mm"),
    "scale chosen size": ("Крок 0: полюс і масштаб. Полюс {pole} ставимо в будь-якому місці аркуша. Беремо {seg} = {trial} мм "
                          "(коротше {least} мм: план читається за розміром — найбільший план не менше {across} мм "
                          "завширшки — і довшого місце аркуша не вміщує) для {sym}_{pin} = {value} {unit} ⇒ μ_{s} = "
                          "{sym}_{pin}/{seg} = {value}/{trial} = {raw} {munit}; записуємо три значущі цифри, заокругливши "
                          "вниз: μ_{s} = {mu} {munit}; тоді {seg} = {sym}_{pin}/μ_{s} = {drawn} мм",
                          "Step 0: the pole and the scale. Put the pole {pole} anywhere on the sheet. Take {seg} = {trial} mm "
                          "(shorter than {least} mm: the plan reads by its size — the largest plan at least {across} mm "
                          "across — and the sheet's room holds no longer) for {sym}_{pin} = {value} {unit} ⇒ μ_{s} = "
                          "{sym}_{pin}/{seg} = {value}/{trial} = {raw} {munit}; write it to three significant figures, "
                          "rounded down: μ_{s} = {mu} {munit}; then {seg} = {sym}_{pin}/μ_{s} = {drawn} mm"),
    "scale rounded": ("Крок 0: полюс і масштаб. Полюс {pole} ставимо в будь-якому місці аркуша. Беремо {seg} = {trial} мм "
                      "(не коротше {least} мм, щоб план читався) для {sym}_{pin} = {value} {unit} ⇒ μ_{s} = "
                      "{sym}_{pin}/{seg} = {value}/{trial} = {raw} {munit}; записуємо дві значущі цифри: "
                      "μ_{s} = {mu} {munit}; тоді {seg} = {sym}_{pin}/μ_{s} = {drawn} мм (за лінійкою {trial} мм)",
                      "Step 0: the pole and the scale. Put the pole {pole} anywhere on the sheet. Take {seg} = {trial} mm "
                      "(not shorter than {least} mm, for the plan to read) for {sym}_{pin} = {value} {unit} ⇒ μ_{s} = "
                      "{sym}_{pin}/{seg} = {value}/{trial} = {raw} {munit}; write it to two significant figures: "
                      "μ_{s} = {mu} {munit}; then {seg} = {sym}_{pin}/μ_{s} = {drawn} mm ({trial} mm by the ruler)"),
    "scale gost": ("Крок 0: полюс і масштаб. Полюс {pole} ставимо в будь-якому місці аркуша. Беремо {seg} ≈ {trial} мм "
                   "для {sym}_{pin} = {value} {unit} ⇒ μ_{s} = {sym}_{pin}/{seg} = {value}/{trial} = {raw} {munit}; "
                   "аркуш має місце для більшого плану, тож заокруглюємо до масштабу ГОСТ 2.302 між стандартними "
                   "(1,5; 7,5·10^k), не дрібнішого: μ_{s} = {mu} {munit}; тоді {seg} = {sym}_{pin}/μ_{s} = {drawn} мм",
                   "Step 0: the pole and the scale. Put the pole {pole} anywhere on the sheet. Take {seg} ≈ {trial} mm "
                   "for {sym}_{pin} = {value} {unit} ⇒ μ_{s} = {sym}_{pin}/{seg} = {value}/{trial} = {raw} {munit}; "
                   "the sheet has room for a larger plan, so round it to a GOST 2.302 scale between the standard ones "
                   "(1.5, 7.5·10^k), not finer: μ_{s} = {mu} {munit}; then {seg} = {sym}_{pin}/μ_{s} = {drawn} mm"),
    "why sheet": ("; аркуш {f} бере той, з яким усі плани вміщуються на ньому", "; the {f} sheet takes the one with which every plan fits on it"),
    "why own": ("; той, з яким найдовший вектор плану вміщується", "; the one with which the plan's longest vector fits"),
    "equation": ("Група {group}: векторне рівняння точки {X}. Двічі підкреслене — відоме за величиною і напрямом, "
                 "один раз — лише за напрямом; невідомих величин дві ({unknown}), тож рівняння розв'язує план",
                 "The group {group}: the vector equation of the point {X}. Underlined twice: known in size and "
                 "direction; once: in direction only; two sizes are unknown ({unknown}), so the plan solves it"),
    "guide note": ("∥ напрямної", "∥ the guide"),
    "known note": ("відома", "known"),
    "zero note": ("= 0", "= 0"),
    "to note": ("до {p}", "toward {p}"),
    "rate": ("{w}_{{{link}}} = {rel}/l_{{{pair}}} = ({seg}·μ_{s})/l_{{{pair}}} = ({mm} мм · {mu} {munit})/{l} м = {value} {unit}. "
             "Переносимо вектор {seg} у точку {C} механізму: він повертає {C} навколо {P} {sense}, тож {w}_{{{link}}} = {signed} {unit}",
             "{w}_{{{link}}} = {rel}/l_{{{pair}}} = ({seg}·μ_{s})/l_{{{pair}}} = ({mm} mm · {mu} {munit})/{l} m = {value} {unit}. "
             "Carried to the point {C} of the mechanism, the vector {seg} turns {C} about {P} {sense}, so {w}_{{{link}}} = {signed} {unit}"),
    "ccw": ("проти годинникової стрілки", "counter-clockwise"),
    "cw": ("за годинниковою стрілкою", "clockwise"),
    "rate zero": ("{w}_{{{link}}} = {rel}/l_{{{pair}}} = 0: {seg} має нульову довжину", "{w}_{{{link}}} = {rel}/l_{{{pair}}} = 0: {seg} has no length"),
    "why similar v": ("швидкості точок однієї ланки одна відносно одної перпендикулярні до відрізків між ними, тож "
                      "фігура {fig} має сторони, перпендикулярні до сторін {FIG}: вона подібна до ланки й повернута на 90° у бік ω_{{{link}}}",
                      "the velocities of one link's points relative to each other are perpendicular to the lines joining them, "
                      "so the figure {fig} has its sides perpendicular to those of {FIG}: it is similar to the link, turned 90° "
                      "in the sense of ω_{{{link}}}"),
    "why similar a": ("відносні прискорення точок однієї ланки всі складають з відрізками між ними той самий кут "
                      "(tg = ε/ω^2) і пропорційні їм, тож фігура {fig} подібна до {FIG}, повернута на {turn}°",
                      "the relative accelerations of one link's points all make the same angle with the lines joining "
                      "them (tan = ε/ω^2) and are proportional to them, so the figure {fig} is similar to {FIG}, turned by {turn}°"),
    "ratio line": ("відношення {pq}/{PQ} = {pqmm}/{PQmm} = {k}; {px} = {k}·{PX} = {k}·{PXmm} = {pxmm} мм",
                   "the ratio {pq}/{PQ} = {pqmm}/{PQmm} = {k}; {px} = {k}·{PX} = {k}·{PXmm} = {pxmm} mm"),
    "ratio triangle": ("відношення {pq}/{PQ} = {pqmm}/{PQmm} = {k}; {px} = {k}·{PX} = {k}·{PXmm} = {pxmm} мм, "
                       "{qx} = {k}·{QX} = {k}·{QXmm} = {qxmm} мм "
                       "(дуги з {p} і {q}; трикутник обходимо в тому самому напрямі, що й на ланці)",
                       "the ratio {pq}/{PQ} = {pqmm}/{PQmm} = {k}; {px} = {k}·{PX} = {k}·{PXmm} = {pxmm} mm, "
                       "{qx} = {k}·{QX} = {k}·{QXmm} = {qxmm} mm "
                       "(arcs from {p} and {q}; the triangle is gone round in the same sense as on the link)"),
    "guide word": ("напрямній", "the guide"),
}


def say(key: str, **fields: object) -> dict[str, str]:
    """The caption in both languages; a field may be a dict {lang: text} (already worded)."""
    out = {}
    for lang in LANGS:
        text = SAY[key][0 if lang == "uk" else 1]
        out[lang] = text.format(**{k: (v[lang] if isinstance(v, dict) else v) for k, v in fields.items()})
    return out


def both(f) -> dict[str, str]:
    """A field worded per language: ``f(lang)`` for each."""
    return {lang: f(lang) for lang in LANGS}


def join(parts: list[dict[str, str]], sep: str = "; ") -> dict[str, str]:
    return {lang: sep.join(p[lang] for p in parts) for lang in LANGS}


# -- reading a plan's names ---------------------------------------------------------------------------

class Names:
    """The plan's points: mechanism name ↔ plan name (util.markup), where each lies on the plan."""

    def __init__(self, plans: Plans, plan: Plan):
        self.plan, self.sc = plan, plans.scheme
        self.mech = plans.study.mech
        self.pole = "p_v" if plan.kind == "velocity" else "π"
        self.sym = "v" if plan.kind == "velocity" else "a"
        self.unit = "m/s" if plan.kind == "velocity" else "m/s²"
        self.of_plan: dict[str, str] = {}           # plan name → mechanism name (points with entries)
        for key, e in plan.entries.items():
            if e.kind == "point":
                self.of_plan[sub(key)] = key
        self.at = dict(plan.named)
        self.body: dict[str, str] = {}               # a coincident point → its body; A3 → the rocker
        self.base: dict[str, str] = {}               # A3 → A
        for (point, body), name in self.sc.coincident.items():
            self.body[name], self.base[name] = body, point

    def place(self, plan_name: str) -> complex:
        return 0j if plan_name == "" else self.at.get(plan_name, 0j)

    def word(self, plan_name: str) -> str:
        """A plan name for the words ("" → the pole)."""
        return plan_name or self.pole

    def mech_label(self, point: str) -> str:
        """A mechanism point as the lab letters it: A3 (the rocker's point at A) → A, O1 → O_1."""
        return indexed(self.base.get(point, point))

    def own_label(self, point: str) -> str:
        """A point with its own number kept: the rocker's point at A is A_3 (OB : OA_3)."""
        return indexed(point) if point in self.base else self.mech_label(point)

    def position(self, point: str) -> complex:
        """Where the mechanism's point is on the position plan (drawing mm) at this position."""
        if point in self.base:
            point = self.base[point]
        return where(self.sc, self.plan.lay, self.sc.body_of(point), point)

    def pair(self, text: str) -> str:
        """Two points' names run together ("BO2", "A3O") as the lab letters them: B O_2, A O."""
        names = self.mech.point_names() + list(self.sc.coincident.values())
        if text in names:
            return self.mech_label(text)
        two = split_pair(text, names)
        return braced(self.mech_label(two[0])) + self.mech_label(two[1]) if two else text

    def body_of(self, point: str) -> str:
        return self.body.get(point) or self.sc.body_of(point)


def entry_key(term: str) -> str:
    """The plan entry a term is read into: a^τ_CB → t_CB, a^r_X → r_X, v_CB → CB, a_C → C."""
    m = re.match(r"^[av](?:\^(\S))?_\{?([^{}\s]+)\}?$", term)
    if not m:
        return ""
    mark, rest = m.groups()
    return {"τ": "t_", "r": "r_", "n": "n_", "k": "k_"}.get(mark or "", "") + rest


def split_pair(text: str, names: list[str]) -> tuple[str, str] | None:
    """"A3O" → ("A3", "O"): a subscript of two point names."""
    for k in range(1, len(text)):
        if text[:k] in names and text[k:] in names:
            return text[:k], text[k:]
    return None


def numbers(plan: Plan, key: str, lang: str) -> tuple[str, str] | None:
    """(mm, value) of an entry, as the page's language writes them."""
    e = plan.entries.get(key)
    if e is None or e.mm is None:
        return None
    return fixed(e.mm, lang, 1), num(e.value, lang)


def ratio_digits(k: float, lengths: list[float]) -> int:
    """The fewest significant figures (3 … 5) of a similarity ratio ``k`` for which each written
    product k·PX, with PX written to 0.1 mm, gives the 0.1 mm written for the true k·PX; 0 if none
    does (PX itself rounded: the caller then writes the products of the written numbers)."""
    for d in (3, 4, 5):
        shown = float(f"{k:.{d}g}")
        if all(f"{shown * float(f'{L:.1f}'):.1f}" == f"{k * L:.1f}" for L in lengths):
            return d
    return 0            # none: a length is itself written rounded


# -- the replay ---------------------------------------------------------------------------------------

class Replay:
    """Builds the steps of one plan (see the module's docstring)."""

    def __init__(self, plans: Plans, plan: Plan):
        self.plans, self.plan = plans, plan
        self.n = Names(plans, plan)
        self.steps: list[dict[str, Any]] = []
        self.lettered: dict[str, int] = {}       # plan name → the step that letters it
        self.used: set[int] = set()

    # bookkeeping ---------------------------------------------------------------------------------
    def add(self, items: list[int | None], caption: dict[str, str], eq: dict[str, str] | None = None,
            letters: tuple[str, ...] = (), **extra: Any) -> None:
        k = len(self.steps)
        drawn = [i for i in items if i is not None and i not in self.used]
        self.used.update(drawn)
        self.steps.append({"items": drawn, "caption": caption, "eq": eq or {"uk": "", "en": ""}, **extra})
        for name in letters:
            self.lettered.setdefault(name, k)

    def known(self, plan_name: str) -> bool:
        return plan_name == "" or plan_name in self.lettered

    def eq(self, step: str) -> dict[str, str]:
        return {lang: step.replace("the guide", SAY["guide word"][0 if lang == "uk" else 1]) for lang in LANGS}

    def value(self, key: str) -> dict[str, dict[str, str]] | None:
        got = {lang: numbers(self.plan, key, lang) for lang in LANGS}
        if got["en"] is None:
            return None
        return {"mm": {lang: got[lang][0] for lang in LANGS}, "value": {lang: got[lang][1] for lang in LANGS}}

    # the steps -----------------------------------------------------------------------------------
    def crank(self) -> None:
        n, plan, cr = self.n, self.plan, self.n.mech.crank
        a = sub(cr.pin)
        v = self.value(cr.pin) or {"mm": {"uk": "—", "en": "—"}, "value": {"uk": "—", "en": "—"}}
        e = plan.entries.get(cr.pin)
        if e is not None and e.mm is not None:
            # ω_1·l, ω_1²·l computed, as the scale's step wrote it (the plan's reading, 70,5 mm × μ,
            # differs in the last figure: "ω_1^2·l_{O1A} = 9,473" beside a_A = 9,475 one step before)
            v["value"] = {lang: num(e.analytic, lang) for lang in LANGS}
        units = both(lambda lang: unit(n.unit, lang))
        arm = f"{cr.pivot}{cr.pin}"
        said = {m.group(1) for g in plan.solved
                for m in re.finditer(rf"\b{n.sym}_{re.escape(cr.pin)}(\d+)(?![\dA-Za-z])", g.step)}
        others = set(n.sc.coincident.values())      # A3: the rocker's point at A moves otherwise
        also = "".join(f" = {n.sym}_{{{cr.pin}{d}}}" for d in sorted(said) if f"{cr.pin}{d}" not in others)
        common = dict(seg=seg(n.pole, a), pin=cr.pin, also=also, arm=arm, unit=units, **v,
                      back=braced(n.mech_label(cr.pin)) + n.mech_label(cr.pivot), pivot=n.mech_label(cr.pivot),
                      arm_l=braced(n.mech_label(cr.pivot)) + n.mech_label(cr.pin))
        items = list(plan.crank_items) + [plan.absolute_items.get(cr.pin)]
        mark = {"link": [cr.pivot, cr.pin], "point": cr.pin, "line": "perp" if plan.kind == "velocity" else "along"}
        if plan.kind == "velocity":
            self.add(items, say("crank v", **common), letters=(a,), mech=mark)
        elif plan.crank_items:
            end = "n_1"         # the first end of a normal component: the crank's (AccelerationPlan.crank)
            self.add(items, say("crank a eps", n=seg(n.pole, end), t=seg(end, a), **common), letters=(end, a), mech=mark)
        else:
            self.add(items, say("crank a", **common), letters=(a,), mech=mark)

    def scale(self, sheet: str | None) -> None:
        """Step 0: the pole anywhere; a trial length of the crank's vector, the scale it gives, rounded
        to the standard series (graphic.scales.at_least) — to the very μ the plans are drawn with
        (the sheet's, which may be coarser so that every plan fits) — and the length drawn; where
        the sheet chose the length instead (a μ off the series: graphic.scales.chosen_length), that
        length and μ = v_A / p_v a at three figures rounded down; where the sheet had room for a larger
        plan (GOST 2.302's 1.5, 7.5·10^k between the series' steps), the trial rounded to that."""
        import math

        from graphplan.graphic.scales import LEGIBLE_MM, PLAN_MM, at_least, on_round, on_series
        n, plan, cr = self.n, self.plan, self.n.mech.crank
        e = plan.entries.get(cr.pin)
        if e is None or not float(e.analytic) > 0:
            return                  # no crank vector to scale by (nothing the plans draw does this)
        value, mu = float(e.analytic), plan.mu
        drawn = value / mu
        gost = not on_series(mu) and on_round(mu)   # GOST 2.302's 1.5, 7.5·10^k: the sheet's room (kinlayout.into_room)
        chosen = not on_round(mu)      # the sheet chose the length (kinlayout.legible_where_room)
        # a chosen length whose μ the sheet wrote to two figures draws it a little short of that
        # length (graphic.scales.chosen_length: 39.94 mm for 40, read 40.0 on the ruler)
        rounded = chosen and drawn < round(drawn) - 1e-9
        trial = round(drawn) if rounded else math.floor(drawn + 1e-9) if chosen else math.ceil(drawn - 1e-9)
        if not chosen and not gost and abs(at_least(value / trial) - mu) > 1e-12 * mu:
            trial = round(drawn, 1)
        raw = value / trial
        s_ = "v" if plan.kind == "velocity" else "a"
        munit = "(m/s)/mm" if plan.kind == "velocity" else "(m/s²)/mm"
        why = say("why sheet", f=sheet) if sheet else say("why own")
        a = sub(cr.pin)
        # a length chosen under LEGIBLE_MM: the sheet's room grew a plan that reads by its size
        # (sheets.kinlayout.into_room, readable: docs/scenes.md's "the plans read by their size")
        short = chosen and not rounded and trial < LEGIBLE_MM - 1e-9
        key = "scale rounded" if rounded else "scale chosen size" if short else "scale chosen" if chosen else \
            "scale gost" if gost else "scale"
        self.add([], say(key, least=both(lambda lang: num(LEGIBLE_MM, lang)), across=both(lambda lang: num(PLAN_MM, lang)), pole=n.pole, seg=seg(n.pole, a), trial=both(lambda lang: fixed(trial, lang, 0 if trial == int(trial) else 1)),
                         sym=n.sym, pin=cr.pin, value=both(lambda lang: num(value, lang)),
                         unit=both(lambda lang: unit(n.unit, lang)), s=s_,
                         raw=both(lambda lang: num(raw, lang)), munit=both(lambda lang: unit(munit, lang)), why=why,
                         mu=both(lambda lang: num(mu, lang)), drawn=both(lambda lang: fixed(drawn, lang, 1))),
                 scale={"symbol": f"mu_{s_}", "mu": mu, "value": value, "trial": trial, "raw": raw, "drawn": round(drawn, 6)},
                 mech={"link": [cr.pivot, cr.pin], "point": cr.pin})

    def equation(self, g: Solved) -> dict[str, Any]:
        """The group's vector equation as the textbook marks it: each term with its vector bar, its
        marks (2: known in size and direction, 1: in direction only, 0: the sought point's own
        vector) and its direction note (⊥ CB, ∥ OB, ∥ the guide, ∥ CB toward B)."""
        n = self.n
        names = n.mech.point_names() + list(n.sc.coincident.values())
        unknown = {side.equation.term: side.equation for side in g.sides}
        text = g.step.split(", ")[0]
        tokens: list[dict[str, Any]] = []
        for k, part in enumerate(text.split(" = ")):
            if k:
                tokens.append({"op": "="})
            for j, term in enumerate(part.split(" + ")):
                if j:
                    tokens.append({"op": "+"})
                term = term.strip()
                m = re.match(r"^([av])(?:\^(\S))?_\{?([^{}\s]+)\}?$", term)
                sym, mark, sub_ = m.groups() if m else (term, None, "")
                shown = sym + (f"^{mark}" if mark else "") + (f"_{{{sub_}}}" if sub_ else "")
                pair = split_pair(sub_, names) if sub_ else None
                if term in unknown:
                    e = unknown[term]
                    kind, what = e.rule
                    if kind == "guide":
                        note = say("guide note")
                    elif kind == "link":
                        note = {lang: f"∥ {n.pair(what)}" for lang in LANGS}
                    elif kind == "perp":
                        note = {lang: f"⊥ {n.pair(what)}" for lang in LANGS}
                    else:
                        note = {lang: "" for lang in LANGS}
                    tokens.append({"t": shown, "m": 1, "note": note})
                elif mark in ("n",) and pair:
                    note = join([{lang: f"∥ {n.pair(sub_)}" for lang in LANGS}, say("to note", p=n.mech_label(pair[1]))], ", ")
                    tokens.append({"t": shown, "m": 2, "note": note})
                elif mark == "k":
                    carrier = next((s_.equation.rule[1] for s_ in g.sides if s_.equation.rule[0] == "link"), "")
                    tokens.append({"t": shown, "m": 2, "note": {lang: f"⊥ {n.pair(carrier)}" if carrier else "" for lang in LANGS}})
                elif k == 0 and j == 0:
                    tokens.append({"t": shown, "m": 0, "note": {lang: "" for lang in LANGS}})
                else:
                    point = sub_ if sub_ in names else ""
                    fixed_ = bool(point) and n.sc.fixed(n.base.get(point, point))
                    tokens.append({"t": shown, "m": 2, "note": say("zero note") if fixed_ else say("known note")})
        return {"tokens": tokens}

    def similarity_words(self, point: str, body: str, chosen: tuple[str, str, str, str]) -> list[dict[str, str]]:
        """Why the figure on the plan is similar to the link, how it is turned, and the ratio with its
        numbers (plan mm over the position plan's mm)."""
        import cmath
        import math
        n = self.n
        P, p, Q, q = chosen
        x = sub(point)
        XP, XQ, X = n.position(P), n.position(Q), n.position(point)
        pp, qq, xx = n.place(p), n.place(q), n.place(x)
        PQ = abs(XQ - XP)
        k = abs(qq - pp) / PQ if abs(qq - pp) > 1e-6 else 0.0     # a dead centre: the figure shrinks to a point
        pw, qw = n.word(p), n.word(q)
        PL, QL, XL = n.own_label(P), n.own_label(Q), n.own_label(point)
        fig, FIG = seg(seg(pw, qw), x), seg(seg(PL, QL), XL)
        collinear = abs(((XQ - XP).conjugate() * (X - XP)).imag) <= 1e-6 * max(PQ * abs(X - XP), 1e-12)
        if self.plan.kind == "velocity":
            # ω3 by the link's number, as the sheet's tables write it
            why = say("why similar v", fig=fig, FIG=FIG,
                      link=str(n.mech.links[body].number) if body in n.mech.links else body)
        else:
            turn = math.degrees(cmath.phase((qq - pp) / (XQ - XP))) if abs(qq - pp) > 1e-9 else 0.0
            why = say("why similar a", fig=fig, FIG=FIG, turn=both(lambda lang: fixed(turn, lang, 1)))
        mmf = lambda v: both(lambda lang: fixed(v, lang, 1))    # noqa: E731
        # the ratio to as many figures as make the written products come out as written (1,33·50,0
        # would give 66,5 where the construction's 66,4 stands: 1,328·50,0 = 66,4)
        kd = ratio_digits(k, [abs(X - XP)] + ([] if collinear else [abs(X - XQ)]))
        kf = both(lambda lang: num(k, lang, kd or 4))
        if not kd:          # a length written rounded (144.04 as 144,0): the products of what is written
            ks = float(f"{k:.4g}")
            k_of = lambda L: ks * float(f"{L:.1f}") / L if L else k     # noqa: E731
        else:
            k_of = lambda L: k      # noqa: E731
        if collinear:
            ratio = say("ratio line", pq=seg(pw, qw), PQ=seg(PL, QL), pqmm=mmf(abs(qq - pp)), PQmm=mmf(PQ), k=kf,
                        px=seg(pw, x), PX=seg(PL, XL), PXmm=mmf(abs(X - XP)),
                        pxmm=mmf(k_of(abs(X - XP)) * abs(X - XP)))
        else:
            ratio = say("ratio triangle", pq=seg(pw, qw), PQ=seg(PL, QL), pqmm=mmf(abs(qq - pp)), PQmm=mmf(PQ), k=kf,
                        px=seg(pw, x), PX=seg(PL, XL), PXmm=mmf(abs(X - XP)), pxmm=mmf(k_of(abs(X - XP)) * abs(X - XP)),
                        qx=seg(qw, x), QX=seg(QL, XL), QXmm=mmf(abs(X - XQ)), qxmm=mmf(k_of(abs(X - XQ)) * abs(X - XQ)),
                        p=pw, q=qw)
        return [why, ratio]

    def rates(self) -> None:
        """ω (velocity plan) or ε (acceleration plan) of every turning link at the end: the segment
        read off the plan (v_CP, or a^τ_CP) over the link's length, and the sense found by carrying
        the segment to C on the mechanism (its turn about P). The value is the plan's own reading."""
        n, plan = self.n, self.plan
        mech, sc = n.mech, n.sc
        kind = "omega" if plan.kind == "velocity" else "epsilon"
        w = "ω" if kind == "omega" else "ε"
        s_ = "v" if plan.kind == "velocity" else "a"
        munit = "(m/s)/mm" if plan.kind == "velocity" else "(m/s²)/mm"
        names = mech.point_names() + list(sc.coincident.values())
        mu_l = self.plans.mu_l
        for link_name, link in mech.links.items():
            rate = plan.entries.get(f"{kind}_{link_name}")
            if rate is None or link_name == mech.crank.link or (len(link.joints) < 2 and link.slides_on is not None):
                continue        # (a block turns with its coulisse; the coulisse O2A3 itself is read: ω3 = v_A3/l_O2A3)
            own = set(link.joints) | set(link.local) | {nm for (pt, b), nm in sc.coincident.items() if b == link_name}
            best = None
            for key, e in plan.entries.items():
                if e.mm is None:
                    continue
                if plan.kind == "velocity":
                    if e.kind == "relative":
                        pair = split_pair(key, names)
                    elif e.kind == "point":
                        fixed_ = [j for j in link.joints if sc.fixed(j)]
                        pair = (key, fixed_[0]) if fixed_ else None
                    else:
                        continue
                else:
                    if e.kind != "tangential":
                        continue
                    pair = split_pair(key.removeprefix("t_"), names)
                if not pair or pair[0] not in own or pair[1] not in own or pair[0] == pair[1]:
                    continue
                length = abs(n.position(pair[0]) - n.position(pair[1])) * mu_l
                if length <= 0:
                    continue
                # the textbook reads ω3 off the point its group found (v_A3/l_O2A3, v_BA/l_AB), not one
                # found from it by similarity (S3, D): a joint or a coincident point first
                found = 0 if pair[0] in link.joints or pair[0] not in link.local else 1
                gap = (found, abs(e.value / length - abs(rate.vector.real)))
                if best is None or gap < best[0]:
                    best = (gap, key, e, pair, length)
            if best is None:
                continue
            _, key, e, (C, P), length = best
            signed = float(rate.vector.real)
            if signed and e.value and abs(e.value / abs(signed) - length) <= 0.02 * length:
                length = e.value / abs(signed)      # the length the plan divided by: a coulisse's l_O2A3 as the
                #                                    ruler reads it off the position plan (18.0 mm, not 17.92)
            c = sub(C)
            vec = e.vector / plan.mu
            start = n.place(c) - vec        # the segment ends at c: from a (v_CA), n_1 (a^τ_CA) or the pole
            p = min([""] + list(plan.named), key=lambda name: abs(n.place(name) - start))
            if abs(n.place(p) - start) > 1e-3:
                p = ""
            rel = (f"{s_}_{{{C}{P}}}" if plan.kind == "velocity" else f"a^τ_{{{C}{P}}}")
            pair_l = braced(n.own_label(P)) + n.own_label(C)
            # ω3 by the link's number, as the sheet's tables write it
            fields = dict(w=w, link=str(link.number), rel=rel, pair=f"{P}{C}", seg=seg(n.word(p), c), s=s_,
                          unit=both(lambda lang: unit("rad/s" if kind == "omega" else "rad/s²", lang)))
            # l to the figures that make (mm·μ)/l come out as the value written (0.40334, not 0.4033)
            ld = next((d for d in (4, 5, 6) if num(e.mm * plan.mu / float(f"{length:.{d}g}"), "en")
                       == num(abs(signed), "en")), 4) if e.mm and signed else 4
            if e.value == 0 or signed == 0:
                caption = say("rate zero", **fields)
            else:
                caption = say("rate", **fields, mm=both(lambda lang: fixed(e.mm, lang, 1)),
                              mu=both(lambda lang: num(plan.mu, lang)), munit=both(lambda lang: unit(munit, lang)),
                              l=both(lambda lang: num(length, lang, ld)), value=both(lambda lang: num(abs(signed), lang)),
                              C=n.own_label(C), P=n.own_label(P), sense=say("ccw" if signed > 0 else "cw"),
                              signed=both(lambda lang: ("+" if signed > 0 else "−") + num(abs(signed), lang)))
            del pair_l
            self.add([], caption, rate={"kind": kind, "link": link_name, "value": signed, "C": C, "P": P,
                                        "sense": "ccw" if signed > 0 else "cw" if signed < 0 else None,
                                        "from": [mm(start.real), mm(start.imag)],
                                        "to": [mm((start + vec).real), mm((start + vec).imag)]},
                     mech={"link": [P, C], "point": C, "carry": [mm(vec.real), mm(vec.imag)],
                           "sense": 1 if signed > 0 else -1 if signed < 0 else 0})

    def similar(self, point: str) -> None:
        """A point of a link found by similarity from two of the link's points already found."""
        n, plan = self.n, self.plan
        x = sub(point)
        if self.n.sc.fixed(point):
            self.add([], say("pole point", x=x, pole=n.pole), letters=(x,))
            return
        body = n.body_of(point)
        link = n.mech.links.get(body)
        candidates = []
        if link is not None:
            for q in list(link.joints) + [p for p in link.local if p not in link.joints]:
                if q == point:
                    continue
                if n.sc.fixed(q):
                    candidates.append((q, ""))
                elif sub(q) in self.lettered:
                    candidates.append((q, sub(q)))
        for (name, (point_, b)) in [(nm, pb) for pb, nm in n.sc.coincident.items()]:
            if b == body and name != point and sub(name) in self.lettered:
                candidates.append((name, sub(name)))
        X = n.position(point)
        chosen = None
        for i, (P, p) in enumerate(candidates):
            for Q, q in candidates[i + 1:]:
                if abs(n.position(P) - n.position(Q)) > 1e-6:
                    chosen = (P, p, Q, q)
                    break
            if chosen:
                break
        at = n.place(x)
        why: list[dict[str, str]] = []
        if chosen is not None:
            why = self.similarity_words(point, body, chosen)
        if chosen is None and len(candidates) >= 2:
            (P, p), (Q, q) = candidates[:2]
            rule = say("together", x=x, p=n.word(p), q=n.word(q))
        elif chosen is None:
            rule = say("similar", x=x)
        else:
            P, p, Q, q = chosen
            XP, XQ = n.position(P), n.position(Q)
            cross = ((XQ - XP).conjugate() * (X - XP)).imag
            pw, qw = n.word(p), n.word(q)
            PL, QL, XL = (n.own_label(P), n.own_label(Q), n.own_label(point))
            if abs(cross) <= 1e-6 * max(abs(XQ - XP) * abs(X - XP), 1e-12):
                rule = say("on line", x=x, pq=seg(pw, qw), px=seg(pw, x), PX=seg(PL, XL), PQ=seg(PL, QL))
            else:
                rule = say("triangle", x=x, pqx=seg(seg(pw, qw), x), PQX=seg(seg(PL, QL), XL))
        if abs(at) <= COINCIDE:
            tail = say("at pole", x=x, pole=n.pole, sym=n.sym, X=point)
        else:
            v = self.value(point)
            tail = say("absolute", seg=seg(n.pole, x), sym=n.sym, X=point,
                       unit=both(lambda lang: unit(n.unit, lang)), **(v or {"mm": "—", "value": "—"}))
        mark = {"link": [chosen[0], chosen[2]], "point": point} if chosen else {"point": point}
        self.add([plan.absolute_items.get(point)], join([rule] + why + [tail]), letters=(x,), mech=mark)

    def ensure(self, plan_name: str) -> None:
        """A known point an equation starts from, found by similarity first if it is not yet."""
        if self.known(plan_name):
            return
        point = self.n.of_plan.get(plan_name)
        if point is None:
            # the point of a moving guide under the slider (no entry of its own): lettered here
            self.add([], {lang: plan_name for lang in LANGS}, letters=(plan_name,))
            return
        self.similar(point)

    def group(self, g: Solved) -> None:
        n, plan = self.n, self.plan
        eq = self.eq(g.step)
        for side in g.sides:
            self.ensure(side.equation.name)
        names = n.mech.point_names() + list(n.sc.coincident.values())
        X = n.of_plan.get(g.found, "")
        equation = self.equation(g)
        unknown = [t["t"] for t in equation["tokens"] if t.get("m") == 1]
        self.add([], say("equation", group=g.group, X=n.mech_label(X) if X else g.found,
                         unknown=", ".join(unknown)), eq, equation=equation, mech={"point": X})
        throughs = []
        for side in g.sides:
            e = side.equation
            at = e.name
            for (vec, role, label, key), item in zip(e.chain, side.chain):
                sub_ = key.partition("_")[2]
                carrier = e.rule[1] if e.rule[0] == "link" else ""
                if carrier in n.mech.links:          # ω3 in 2·ω3·v_A3A2: the link's number, as the sheets
                    carrier = str(n.mech.links[carrier].number)
                fields = dict(base=n.word(at), sub=sub_, carrier=carrier, end=label)
                if item is None:
                    self.add([], say("zero " + role, **fields), eq)
                    continue
                pair = split_pair(sub_, names) or (sub_, "")
                v = self.value(key) or {"mm": "—", "value": "—"}
                mark = {"point": pair[0], "link": [pair[0], pair[1]]} if pair[1] and role == "normal" else {"point": X}
                self.add([item], say(role, seg=seg(n.word(at), label), link=n.pair(sub_),
                                     toward=n.mech_label(pair[1]) if pair[1] else "",
                                     unit=both(lambda lang: unit("m/s²", lang)), **fields, **v), eq, letters=(label,),
                         equation=equation, mech=mark)
                at = label
            throughs.append(at)
        for side, through in zip(g.sides, throughs):
            e = side.equation
            rule = say(e.rule[0], what=n.pair(e.rule[1])) if e.rule[0] else {"uk": "", "en": ""}
            ends = self.plan.record.items[side.line].points
            u = complex(ends[1][0] - ends[0][0], ends[1][1] - ends[0][1])
            u = u / abs(u) if abs(u) else 0j
            direction = [round(u.real, 6), round(u.imag, 6)]
            if e.rule[0] == "perp":
                two = split_pair(e.rule[1], names)
                mark = {"point": X, "link": list(two), "line": "perp"} if two else {"point": X}
            elif e.rule[0] == "link":
                joints = list(n.mech.links[e.rule[1]].joints) if e.rule[1] in n.mech.links else []
                ends = [joints[0], joints[-1]] if len(joints) >= 2 else [joints[0], X] if joints and X else []
                mark = {"point": X, "link": ends, "line": "along"} if ends else {"point": X, "line": "along"}
            elif e.rule[0] == "guide":
                mark = {"point": X, "guide": e.rule[1], "line": "guide"}
            else:
                mark = {"point": X}
            if "line" in mark:
                mark["dir"] = direction        # drawn through the point as on the plan (the same directions)
            self.add([side.line], say("line", through=n.word(through), rule=rule, term=e.term), eq, line=True,
                     equation=equation, mech=mark)
        found = g.found
        point = n.of_plan.get(found, "")
        if abs(g.at) <= COINCIDE:
            caption = say("meet pole", found=found, pole=n.pole, sym=n.sym, X=point or found)
        else:
            caption = say("meet", found=found)
        self.add([], caption, eq, letters=(found,), meet=[found, mm(g.at.real), mm(g.at.imag)], equation=equation,
                 mech={"point": X})
        parts, items = [], []
        absolute = f"{n.sym}_{point}"
        said_absolute = False
        units = both(lambda lang: unit(n.unit, lang))
        for side, through in zip(g.sides, throughs):
            e = side.equation
            if side.unknown is None:
                parts.append(say("zero reading", term=e.term))
                continue
            items.append(side.unknown)
            term, key = e.term, entry_key(e.term)
            if through == "" and point:
                # the unknown runs from the pole: it is the found point's own vector
                term = e.term if e.term == absolute else f"{e.term} = {absolute}"
                key, said_absolute = point, True
            v = self.value(key)
            if v is None:
                parts.append({lang: f"{seg(n.word(through), found)} = {term}" for lang in LANGS})
            else:
                parts.append(say("reading", seg=seg(n.word(through), found), term=term, unit=units, **v))
        if point:
            v = self.value(point)
            items.append(plan.absolute_items.get(point))
            if v is not None and abs(g.at) > COINCIDE and not said_absolute:
                parts.append(say("absolute", seg=seg(n.pole, found), sym=n.sym, X=point, unit=units, **v))
        if items or parts:
            self.add(items, say("found", list=join(parts)), eq, equation=equation, mech={"point": X})

    def figures(self) -> None:
        n = self.n
        for link, items in self.plan.figure_items.items():
            joints = [j for j in n.mech.links[link].joints]
            fig = "".join(braced(n.pole if n.sc.fixed(j) else sub(j)) for j in joints)
            self.add(items, say("figure", link=link, fig=fig))

    def build(self, sheet: str | None = None) -> list[dict[str, Any]]:
        plan = self.plan
        self.scale(sheet)
        self.crank()
        for g in plan.solved:
            self.group(g)
        from graphplan.report.plans import ordered
        for e in ordered(plan):
            if e.kind == "point" and not self.known(sub(e.key)):
                self.similar(e.key)
        self.figures()
        self.rates()
        rest = [i for i, p in enumerate(plan.record.items)
                if i not in self.used and p.kind != "text" and p.role != "pole"]
        for i in rest:      # nothing should be left; if it is, it is still drawn, worded by its equation
            self.add([i], self.eq(plan.record.items[i].step or plan.record.items[i].role))
        return self.steps

    def points(self) -> list[list[Any]]:
        """Every lettered plan point: [name, x, y, the step that letters it] — the pole from the start."""
        out = [[self.n.pole, 0.0, 0.0, 0]]
        last = len(self.steps) - 1
        for name, z in self.plan.named.items():
            out.append([name, mm(z.real), mm(z.imag), self.lettered.get(name, last)])
        return out


def record_data(rec: Record) -> list[list[Any]]:
    """A record's drawn primitives as compact lists: [kind, flat points, role] (circles and arcs
    add radius, start and end angles); the labels are the page's to place."""
    prims = []
    for p in rec.items:
        if p.kind == "text":
            continue
        flat = [mm(c) for xy in p.points for c in xy]
        item: list[Any] = [p.kind, flat, p.role]
        if p.kind in ("circle", "arc"):
            item += [mm(p.radius), round(p.angles[0], 2), round(p.angles[1], 2)]
        prims.append(item)
    return prims


def plan_records(plans: Plans, sheet: str | None = None) -> list[dict[str, Any]]:
    """Every plan of the lab's positions with its replay (record indices skip no primitive: the
    labels are not in the record, the page letters the points)."""
    out = []
    for p in plans.positions:
        for plan in (p.velocity, p.acceleration):
            if plan is None:
                continue
            r = Replay(plans, plan)
            steps = r.build(sheet)
            out.append({"kind": plan.kind, "key": p.key, "index": p.index, "phi": round(p.phi, 6),
                        "mu": plan.mu, "items": record_data(plan.record), "steps": steps,
                        "points": r.points()})
    return out
