"""The explorer's step-by-step replay: each plan's construction record cut into the draftsman's steps
in order (known vectors first, then each group's equation: the direction lines, their intersection,
the points by similarity), with captions in the page's language."""
from __future__ import annotations

import re
from typing import Any


from graphplan.graphic.plans import Plans
from graphplan.graphic.record import Primitive, Record

MM = 3              # decimals of drawing millimetres


def mm(x: float) -> float:
    """A drawing length for the page: 3 decimals, no −0."""
    v = round(float(x), MM)
    return 0.0 if v == 0 else v

# -- the construction records and their captions ---------------------------------------------------

GUIDE = {"en": "the guide", "uk": "напрямній"}


def split_pair(text: str, names: list[str]) -> tuple[str, str] | None:
    """"A3O" → ("A3", "O"): a subscript of two point names."""
    for k in range(1, len(text)):
        if text[:k] in names and text[k:] in names:
            return text[:k], text[k:]
    return None


def same_point(sub: str) -> bool:
    """"A3A2": two bodies' points at one place (a sliding pair) — the relative motion is along the guide."""
    return re.fullmatch(r"([A-Za-z]+)[\d_]+\1[\d_]*", sub) is not None


def parse_term(term: str) -> tuple[str, str, str]:
    """"a^τ_A3O" → ("a", "τ", "A3O"); "v_CB" → ("v", "", "CB")."""
    m = re.match(r"^([av])(?:\^(\S))?_(\S+)$", term.strip())
    return (m.group(1), m.group(2) or "", m.group(3)) if m else ("", "", term.strip())


def equations(step: str) -> tuple[str, list[list[str]]]:
    """The step's vector equations: "v_C = v_B + v_CB, v_C ∥ the guide" → ("v_C",
    [["v_B", "v_CB"], ["", "v_C"]]) — each a known base and the components laid off from it."""
    body, _, tail = step.partition(", ")
    parts = [s.strip() for s in body.split("=")]
    lhs, rhs = parts[0], [[t.strip() for t in p.split(" + ")] for p in parts[1:]]
    if tail.strip().startswith(lhs) and "∥" in tail:
        rhs.append(["", lhs])
    return lhs, rhs


class Captions:
    """Names plan points and words each primitive of a velocity or acceleration plan."""

    def __init__(self, plans: Plans, plan, lang: str):
        self.plan, self.lang = plan, lang
        mech = plans.study.mech
        self.names = mech.point_names() + list(plans.scheme.coincident.values())
        self.mech = mech
        self.pole = "p_v" if plan.kind == "velocity" else "π"
        self.named = dict(plan.named)

    def at(self, z: complex) -> str:
        if abs(z) < 1e-6:
            return self.pole
        best = min(self.named.items(), key=lambda kv: abs(kv[1] - z), default=None)
        return best[0] if best and abs(best[1] - z) < 1e-6 else ""

    def en(self) -> bool:
        return self.lang == "en"

    def crank(self) -> str:
        cr = self.mech.crank
        arm = f"{cr.pivot}{cr.pin}"
        a = self.at(complex(*_end(self.plan, cr.pin)))
        if self.plan.kind == "velocity":
            return (f"{self.pole}{a} = v_{cr.pin} = ω1·l_{arm} ⊥ {arm}, in the sense of ω1" if self.en() else
                    f"{self.pole}{a} = v_{cr.pin} = ω1·l_{arm} ⊥ {arm}, у бік ω1")
        tangential = f" + ε1·l_{arm} ⊥ {arm}" if cr.epsilon else ""
        return (f"{self.pole}{a} = a_{cr.pin} = ω1²·l_{arm} ∥ {cr.pin}{cr.pivot}, toward {cr.pivot}{tangential}"
                if self.en() else
                f"{self.pole}{a} = a_{cr.pin} = ω1²·l_{arm} ∥ {cr.pin}{cr.pivot}, до {cr.pivot}{tangential}")

    def base(self, term: str) -> str:
        """The plan point a vector equation starts from: v_B → b, v_O2 (a fixed point) → the pole."""
        _, _, point = parse_term(term)
        if point in self.mech.frame or not point:
            return self.pole
        return point.lower()

    def relation(self, term: str, guided: bool) -> str:
        """⊥ XY for a rotation about another point, ∥ the guide for a slide."""
        _, sup, sub = parse_term(term)
        if guided or sup == "r" or same_point(sub):
            return f"∥ {GUIDE[self.lang]}"
        return f"⊥ {sub}"

    def chain(self, term: str, role: str, end: str) -> str:
        _, sup, sub = parse_term(term)
        pair = split_pair(sub, self.names) or (sub, "")
        if role == "coriolis":
            return (f"Coriolis {term} = 2·ω·v_{sub}: v_{sub} turned 90° in the sense of ω → {end}" if self.en() else
                    f"прискорення Коріоліса {term} = 2·ω·v_{sub}: v_{sub}, повернута на 90° у бік ω → {end}")
        if role == "normal":
            return (f"{term} = v²_{sub}/l_{sub} ∥ {sub}, toward {pair[1]} → {end}" if self.en() else
                    f"{term} = v²_{sub}/l_{sub} ∥ {sub}, до {pair[1]} → {end}")
        return f"{term} → {end}"

    def line(self, term: str, through: str, guided: bool) -> str:
        rel = self.relation(term, guided)
        return (f"line {rel} through {through} (the direction of {term})" if self.en() else
                f"лінія {rel} через {through} (напрям {term})")

    def unknown(self, term: str, first: bool, found: str) -> str:
        if first:
            return f"{term} up to the intersection" if self.en() else f"{term} до перетину"
        return f"{found} at the intersection: {term}" if self.en() else f"{found} у точці перетину: {term}"

    def absolute(self, point: str, end: str, similarity: bool) -> str:
        sym = "v" if self.plan.kind == "velocity" else "a"
        if similarity:
            return (f"{end} by similarity; {self.pole}{end} = {sym}_{point}" if self.en() else
                    f"{end} за подібністю; {self.pole}{end} = {sym}_{point}")
        return f"{self.pole}{end} = {sym}_{point}"

    def figure(self, link: str) -> str:
        return (f"link {link} on the plan: its similar figure" if self.en() else
                f"ланка {link} на плані: подібна фігура")


def _end(plan, point: str) -> tuple[float, float]:
    z = plan.entries[point].vector / plan.mu
    return z.real, z.imag


def _z(p: tuple[float, float]) -> complex:
    return complex(p[0], p[1])


def replay(plans: Plans, plan, rec: Record, lang: str) -> list[dict[str, Any]]:
    """The construction in the draftsman's order: a list of steps, each with the indices of the
    record's primitives it draws and its caption. The crank's vector comes first."""
    cap = Captions(plans, plan, lang)
    items = rec.items
    mech = plans.study.mech
    steps: list[dict[str, Any]] = []
    pin_end = complex(*_end(plan, mech.crank.pin))
    crank_items = [i for i, p in enumerate(items) if p.kind == "vector" and p.role == "absolute"
                   and abs(_z(p.points[1]) - pin_end) < 1e-6]
    pre = [i for i, p in enumerate(items) if p.step.startswith(f"a_{mech.crank.pin} =") and p.kind != "text"]
    steps.append({"items": pre + crank_items, "caption": cap.crank(), "eq": ""})
    done = set(pre + crank_items)
    k = 0
    while k < len(items):
        p = items[k]
        if k in done or p.kind == "text" or p.role == "pole":
            k += 1
            continue
        if p.step and "=" in p.step and not p.step.startswith("similarity"):
            j_end = k       # a group's primitives are consecutive in the record
            while j_end < len(items) and items[j_end].step == p.step:
                j_end += 1
            steps += equation_steps(cap, items, list(range(k, j_end)), p.step)
            k = j_end
            continue
        if p.kind == "vector" and p.role == "absolute":
            end = _z(p.points[1])
            point = _point_named(plan, end)
            found = any(items[j].kind == "vector" and abs(_z(items[j].points[1]) - end) < 1e-6
                        for s in steps for j in s["items"])
            similar = p.step == "similarity" and not found
            steps.append({"items": [k], "caption": cap.absolute(point, cap.at(end), similar),
                          "eq": "", "similar": similar})
        elif p.step.startswith("similarity: link "):
            steps.append({"items": [k], "caption": cap.figure(p.step.removeprefix("similarity: link ")), "eq": ""})
        else:
            steps.append({"items": [k], "caption": p.step or p.role, "eq": ""})
        k += 1
    return known_first(steps, items)


def known_first(steps: list[dict[str, Any]], items: list[Primitive]) -> list[dict[str, Any]]:
    """A point found by similarity that a later group starts from (b for a_C = a_B + …) is drawn
    before that group, as a draftsman must: the record keeps all similarity vectors to the end."""
    out = list(steps)
    for st in [s for s in steps if s.pop("similar", False)]:
        end = _z(items[st["items"][0]].points[1])
        k = out.index(st)
        m = next((m for m in range(1, k) for j in out[m]["items"]
                  if items[j].kind == "vector" and abs(_z(items[j].points[0]) - end) < 1e-6), None)
        if m is None:
            continue
        while m > 1 and out[m]["eq"] and out[m - 1]["eq"] == out[m]["eq"]:
            m -= 1
        out.remove(st)
        out.insert(m, st)
    return out


def _point_named(plan, end: complex) -> str:
    for key, e in plan.entries.items():
        if e.kind == "point" and abs(e.vector / plan.mu - end) < 1e-6:
            return key
    return ""


def equation_steps(cap: Captions, items: list[Primitive], idx: list[int], step: str) -> list[dict[str, Any]]:
    """One group's vector equations, primitive by primitive: the known components laid off (normal,
    Coriolis), the direction line of each unknown, the unknowns up to their intersection."""
    lang_step = step.replace("the guide", GUIDE[cap.lang])
    lhs, eqs = equations(step)
    out: list[dict[str, Any]] = []
    q = list(idx)

    def take(pred) -> int | None:
        if q and pred(items[q[0]]):
            return q.pop(0)
        return None

    for n, terms in enumerate(eqs):
        chain, unknown = terms[1:-1], terms[-1]
        guided = terms[0] == ""
        through = cap.pole if guided else cap.base(terms[0])   # where the unknown's line starts
        for term in chain:
            _, sup, _ = parse_term(term)
            role = {"n": "normal", "k": "coriolis"}.get(sup)
            j = take(lambda p: p.kind == "vector" and p.role == role)
            if j is not None:
                end = cap.at(_z(items[j].points[1]))
                through = end or through
                out.append({"items": [j], "caption": cap.chain(term, role, end), "eq": lang_step})
        line = take(lambda p: p.kind == "segment" and p.role == "direction")
        vec = take(lambda p: p.kind == "vector" and p.role in ("relative", "tangential"))
        if line is not None:
            if vec is not None:
                through = cap.at(_z(items[vec].points[0])) or through
            out.append({"items": [line], "caption": cap.line(unknown, through or "…", guided), "eq": lang_step})
        if vec is not None:
            found = cap.at(_z(items[vec].points[1]))
            out.append({"items": [vec], "caption": cap.unknown(unknown, n == 0, found), "eq": lang_step})
    for j in q:     # anything the parse did not place keeps the equation as its caption
        out.append({"items": [j], "caption": lang_step, "eq": lang_step})
    return out


def record_data(rec: Record) -> dict[str, Any]:
    """A record's primitives as compact lists: [kind, flat points, role, radius, a0, a1, text]."""
    prims = []
    for p in rec.items:
        flat = [mm(c) for xy in p.points for c in xy]
        prims.append([p.kind, flat, p.role, mm(p.radius), round(p.angles[0], 2), round(p.angles[1], 2), p.text])
    return {"items": prims}


def label_steps(plan, rec: Record, steps: list[dict[str, Any]]) -> dict[int, int]:
    """Each label shows from the first step that draws its plan point (the pole's from the start)."""
    anchors = {req.text: req.at for req in plan.labels}
    out = {}
    for i, p in enumerate(rec.items):
        if p.kind != "text":
            continue
        at = anchors.get(p.text)
        out[i] = 0
        if at is None or abs(at) < 1e-6:
            continue
        out[i] = next((s for s, st in enumerate(steps) for j in st["items"]
                       if any(abs(_z(xy) - at) < 1e-6 for xy in rec.items[j].points)), 0)
    return out


def plan_records(plans: Plans, lang: str) -> list[dict[str, Any]]:
    """Every plan of the lab's positions with its replay."""
    from graphplan.drawing.plans import labelled
    out = []
    for p in plans.positions:
        for plan in (p.velocity, p.acceleration):
            if plan is None:
                continue
            rec = labelled(plan)
            steps = replay(plans, plan, rec, lang)
            labels = label_steps(plan, rec, steps)
            data = record_data(rec)
            data |= {"kind": plan.kind, "key": p.key, "index": p.index, "phi": round(p.phi, 6),
                     "mu": plan.mu, "steps": steps, "labels": {str(k): v for k, v in sorted(labels.items())}}
            out.append(data)
    return out
