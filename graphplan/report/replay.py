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
        if plan.kind == "velocity":
            self.add(items, say("crank v", **common), letters=(a,))
        elif plan.crank_items:
            end = "n_1"         # the first end of a normal component: the crank's (AccelerationPlan.crank)
            self.add(items, say("crank a eps", n=seg(n.pole, end), t=seg(end, a), **common), letters=(end, a))
        else:
            self.add(items, say("crank a", **common), letters=(a,))

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
        self.add([plan.absolute_items.get(point)], join([rule, tail]), letters=(x,))

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
        throughs = []
        for side in g.sides:
            e = side.equation
            at = e.name
            for (vec, role, label, key), item in zip(e.chain, side.chain):
                sub_ = key.partition("_")[2]
                carrier = e.rule[1] if e.rule[0] == "link" else ""
                fields = dict(base=n.word(at), sub=sub_, carrier=carrier, end=label)
                if item is None:
                    self.add([], say("zero " + role, **fields), eq)
                    continue
                pair = split_pair(sub_, n.mech.point_names() + list(n.sc.coincident.values())) or (sub_, "")
                v = self.value(key) or {"mm": "—", "value": "—"}
                self.add([item], say(role, seg=seg(n.word(at), label), link=n.pair(sub_),
                                     toward=n.mech_label(pair[1]) if pair[1] else "",
                                     unit=both(lambda lang: unit("m/s²", lang)), **fields, **v), eq, letters=(label,))
                at = label
            throughs.append(at)
        for side, through in zip(g.sides, throughs):
            e = side.equation
            rule = say(e.rule[0], what=n.pair(e.rule[1])) if e.rule[0] else {"uk": "", "en": ""}
            self.add([side.line], say("line", through=n.word(through), rule=rule, term=e.term), eq, line=True)
        found = g.found
        point = n.of_plan.get(found, "")
        if abs(g.at) <= COINCIDE:
            caption = say("meet pole", found=found, pole=n.pole, sym=n.sym, X=point or found)
        else:
            caption = say("meet", found=found)
        self.add([], caption, eq, letters=(found,), meet=[found, mm(g.at.real), mm(g.at.imag)])
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
            self.add(items, say("found", list=join(parts)), eq)

    def figures(self) -> None:
        n = self.n
        for link, items in self.plan.figure_items.items():
            joints = [j for j in n.mech.links[link].joints]
            fig = "".join(braced(n.pole if n.sc.fixed(j) else sub(j)) for j in joints)
            self.add(items, say("figure", link=link, fig=fig))

    def build(self) -> list[dict[str, Any]]:
        plan = self.plan
        self.crank()
        for g in plan.solved:
            self.group(g)
        from graphplan.report.plans import ordered
        for e in ordered(plan):
            if e.kind == "point" and not self.known(sub(e.key)):
                self.similar(e.key)
        self.figures()
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


def plan_records(plans: Plans) -> list[dict[str, Any]]:
    """Every plan of the lab's positions with its replay (record indices skip no primitive: the
    labels are not in the record, the page letters the points)."""
    out = []
    for p in plans.positions:
        for plan in (p.velocity, p.acceleration):
            if plan is None:
                continue
            r = Replay(plans, plan)
            steps = r.build()
            out.append({"kind": plan.kind, "key": p.key, "index": p.index, "phi": round(p.phi, 6),
                        "mu": plan.mu, "items": record_data(plan.record), "steps": steps,
                        "points": r.points()})
    return out
