"""Grading a student's long table (variant, position, quantity, value) against a key.

Each row gets the exact value, the percent error δ = (value − exact)/|exact|·100 % and pass/fail by
the key's tolerance. A failing row is searched over the crank's turn: the crank angles where the
quantity takes the student's value, the one nearest a listed position preferred; when that is
another position, the row is said to belong there (seed 004: v_B = 7.2 m/s written for position 1,
30°, fits 152°, position 5).
"""
from __future__ import annotations

import json
import re
import unicodedata
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from graphplan.util.words import Fixed, fixed, num, said, word
from graphplan.util.errors import GraphplanError, SceneError, reason, said_error
from graphplan.teach.keys import FORMAT, Quantity, diagram_phi, quantities
from graphplan.util.files import read_text
from graphplan.exact.positions import Study, study
from graphplan.model.scene import build

SEARCH_GRID = 1440      # 0.25° samples, then bisection to ~1e-9°
MAX_KEY_BYTES = 64 * 1024 * 1024   # a key of 3600 positions is a few MB
ABS_FLOOR = 1e-12       # SI: a floor for quantities that are zero over the whole turn


@dataclass(slots=True)
class Row:
    """One line of the student's table."""
    line: int
    variant: str
    position: str
    quantity: str
    value: float | None


@dataclass(slots=True)
class Graded:
    """A graded row: the exact value, the error and the verdict, and where the value fits."""
    row: Row
    status: str                      # "pass", "fail" or "unknown"
    quantity: str = ""               # the key's name for the quantity
    exact: float | None = None
    error: float | None = None       # value − exact (in the compared sense)
    error_pct: float | None = None
    tolerance_pct: float | None = None
    note: str = ""                   # English (the JSON's)
    fits: dict[str, Any] | None = None
    note_uk: str = ""

    def add(self, said: dict[str, str]) -> None:
        """Append a note given in every language (util.words.said)."""
        self.note = _join(self.note, said["en"])
        self.note_uk = _join(self.note_uk, said["uk"])

    def says(self, lang: str) -> str:
        return self.note_uk if lang == "uk" else self.note

    def json(self) -> dict[str, Any]:
        return {"line": self.row.line, "variant": self.row.variant, "position": self.row.position,
                "quantity": self.row.quantity, "key_quantity": self.quantity, "value": self.row.value,
                "exact": self.exact, "error": self.error, "error_pct": self.error_pct,
                "tolerance_pct": self.tolerance_pct, "pass": self.status == "pass",
                "status": self.status, "note": self.note, "fits": self.fits}


# -- reading -------------------------------------------------------------------------------------

def read_student(path: str | Path) -> list[Row]:
    """A long table with the columns position, quantity, value (and variant); ``,`` ``;`` or tab
    separated; the encodings, decimal commas, minus signs and thousands spaces a person's
    spreadsheet writes (teach.tables). Other columns are ignored. A table without a ``quantity``
    column is read as a wide one (see ``_wide``). The columns are found by their names in any order;
    a name given twice is refused, and so is a decimal comma split across cells wherever the value
    column stands ("7,2" read as 7 and a variant or position 2). Values and positions are read by the
    one reader of every table's numbers (model.bounds.read_number)."""
    from graphplan.teach.tables import read_rows, split_comma
    path = Path(path)
    records, delimiter = read_rows(path)
    header = [h.strip().lower() for h in records[0][1]]
    _no_twice(header, path)
    if "quantity" not in header:
        return _wide(records, header, delimiter, path)
    for need in ("position", "value"):
        if need not in header:
            raise said_error(GraphplanError, "st columns", str(path), None, need=repr(need))
    col = {name: header.index(name) for name in ("variant", "position", "quantity", "value") if name in header}
    rows = []
    one: dict[str, str] = {}         # a table's variants, positions and quantities repeat: one string each
    for i in range(1, len(records)):
        line_no, cells = records[i]

        def cell(name: str) -> str:
            k = col.get(name)
            return cells[k].strip() if k is not None and k < len(cells) else ""

        def once(name: str) -> str:
            text = cell(name)
            return one.setdefault(text, text)
        if split_comma(cells, col["value"], delimiter):
            _split(cells, col["value"], line_no, path)
        value = _number(cell("value"), delimiter, line_no, path, "value", col["value"])
        position = once("position")
        _position_number(position, delimiter, line_no, path, col["position"])
        rows.append(Row(line_no, once("variant"), position, once("quantity"), value))
    return rows


def _rows(n: int, lang: str, key: str = "rows") -> str:
    """"n rows" with the noun (and verb) agreeing with n: 1 рядок, 2 рядки, 5 рядків; 1 row, 2 rows."""
    from graphplan.util.words import uk_count
    form = uk_count(n, "one", "few", "many") if lang == "uk" else ("one" if n == 1 else "many")
    return word(f"{key} {form}", lang, n=n)


def _no_twice(header: list[str], path: Path) -> None:
    for name in ("variant", "position", "quantity", "value"):
        if header.count(name) > 1:
            raise said_error(GraphplanError, "st column twice", str(path), None, name=repr(name),
                             cols=", ".join(str(k + 1) for k, h in enumerate(header) if h == name))


def _number(text: str, delimiter: str, line_no: int, path: Path, column: str = "value",
            k: int | None = None) -> float | None:
    from graphplan.teach.tables import number
    if not text:
        return None
    try:
        return number(text, delimiter)
    except ValueError as exc:
        raise said_error(GraphplanError, "st cell", str(path), None, line=line_no, column=column,
                         text=repr(text[:30]), at=_at(k), why=reason(exc)) from None


def _at(k: int | None) -> object:
    """" (column k)" in each language (the 1-based column), or nothing."""
    return (lambda lang: word("st at column", lang, k=k + 1)) if k is not None else ""


def _position_number(text: str, delimiter: str, line_no: int, path: Path, k: int | None = None) -> None:
    """A position written as a number is read by the same rule as a value (1e-400 is not position 0);
    a word stays for the grading to call unknown."""
    from graphplan.model.bounds import numeric_like, read_number
    bare = text.lstrip("#")
    if bare and numeric_like(bare):
        try:
            read_number(bare, delimiter)
        except ValueError as exc:
            raise said_error(GraphplanError, "st cell", str(path), None, line=line_no, column="position",
                             text=repr(text[:30]), at=_at(k), why=reason(exc)) from None


def _split(cells: list[str], k: int, line_no: int, path: Path) -> None:
    raise said_error(GraphplanError, "st split", str(path), None, line=line_no, a=repr(cells[k].strip()),
                     b=repr(cells[k + 1].strip()[:12]), k1=k + 1, k2=k + 2)


def _wide(records, header, delimiter, path: Path) -> list[Row]:
    """A wide table (as a lab's sheet prints it): a position column — named ``position``, else the
    first — and one column per quantity; optionally a ``variant`` column. Empty cells are skipped.
    A table whose first column is the variant and which names no position column is refused (the
    variant is no position)."""
    var = header.index("variant") if "variant" in header else None
    if "position" in header:
        pos = header.index("position")
    elif var == 0:
        raise said_error(GraphplanError, "st no position", str(path), None)
    else:
        pos = 0
    from graphplan.teach.tables import split_comma
    names = [h.strip() for h in records[0][1]]
    rows = []
    for i in range(1, len(records)):
        line_no, cells = records[i]
        for k in range(len(cells) - 1):       # a value spilled into an unnamed column: "7,2" → 7 | 2
            if not (names[k + 1] if k + 1 < len(names) else "") and k not in (pos, var) \
                    and split_comma(cells, k, delimiter):
                _split(cells, k, line_no, path)
        position = cells[pos].strip() if pos < len(cells) else ""
        _position_number(position, delimiter, line_no, path, pos)
        for k, name in enumerate(names):
            if k in (pos, var) or k >= len(cells) or not cells[k].strip():
                continue
            value = _number(cells[k].strip(), delimiter, line_no, path, name or "value", k)
            rows.append(Row(line_no, cells[var].strip() if var is not None and var < len(cells) else "",
                            position, name, value))
    return rows


def load_keys(path: str | Path) -> dict[str, dict[str, Any]]:
    """Keys by variant: a key folder written by ``graphplan key`` (its summary.json), a variant's
    folder, or one variant's key.json."""
    path = Path(path)
    if path.is_dir():
        summary = path / "summary.json"
        if summary.exists():
            doc = _json(summary)
            out = {}
            for entry in doc.get("variants", []):
                if entry.get("status") == "ok":
                    out[entry["variant"]] = _key(path / entry["key"])
            if not out:
                raise said_error(GraphplanError, "ky no written", str(summary), None)
            return out
        single = path / "key.json"
        if single.exists():
            key = _key(single)
            return {key["variant"]: key}
        raise said_error(GraphplanError, "ky not folder", str(path), None)
    key = _key(path)
    return {key["variant"]: key}


def _json(path: Path) -> dict[str, Any]:
    text = read_text(path, "key file", MAX_KEY_BYTES)
    try:
        doc = json.loads(text)
    except json.JSONDecodeError as exc:
        raise said_error(GraphplanError, "ky not json", str(path), None, line=exc.lineno, col=exc.colno) from None
    except RecursionError:
        raise said_error(GraphplanError, "ky cannot read", str(path), None,
                         why=lambda lang: word("wb nested", lang)) from None
    if not isinstance(doc, dict):
        raise said_error(GraphplanError, "ky not object", str(path), None)
    return doc


def _key(path: Path) -> dict[str, Any]:
    doc = _json(path)
    if doc.get("format") != FORMAT:
        raise said_error(GraphplanError, "ky format", str(path), None, got=repr(doc.get("format")), want=repr(FORMAT))
    doc["_path"] = str(path)
    return doc


# -- names ---------------------------------------------------------------------------------------

_GREEK = {"ω": "omega", "Ω": "omega", "ε": "eps", "τ": "t", "ϵ": "eps"}


def normalise(name: str) -> str:
    """A quantity's name without case, underscores, carets, spaces or Greek letters:
    ``ω_AB``, ``omega_AB``, ``wAB`` → ``omegaab``; ``a^τ_BA`` → ``atba``; ``vS2`` → ``vs2``."""
    text = unicodedata.normalize("NFKC", name.strip())
    text = "".join(_GREEK.get(c, c) for c in text)
    text = re.sub(r"[\s_^(),.·{}]", "", text).lower()
    text = re.sub(r"^epsilon", "eps", text)
    text = re.sub(r"^w(?=\w)", "omega", text)
    return text


def aliases(key: dict[str, Any]) -> dict[str, str]:
    """Accepted spellings → the key's quantity names (ambiguous spellings are dropped)."""
    names = list(key["quantities"])
    numbers = key.get("links", {})
    table: dict[str, set[str]] = {}
    for name in names:
        spellings = {normalise(name)}
        m = re.match(r"^(omega|eps)_(.+)$", name)
        if m and m.group(2) in numbers:
            spellings.add(normalise(f"{m.group(1)}{numbers[m.group(2)]}"))
        for s in spellings:
            table.setdefault(s, set()).add(name)
    out = {s: next(iter(v)) for s, v in table.items() if len(v) == 1}
    out.update({n: n for n in names})
    return out


# -- grading -------------------------------------------------------------------------------------

class NoScene(GraphplanError):
    """A key without its resolved scene (written by hand): nothing can be computed beyond its values."""


@dataclass
class _Variant:
    """A key with its rebuilt mechanism (for quantities not in the key and for the search)."""
    key: dict[str, Any]
    names: dict[str, str]
    _study: Study | None = None
    _quantities: dict[str, Quantity] = field(default_factory=dict)
    computed: dict[tuple, tuple[float, bool]] = field(default_factory=dict)

    def study(self) -> Study:
        if self._study is None:
            if self.key.get("kind") == "cam":
                raise NoScene("a cam key: its values stand at the divisions only", self.key.get("_path"))
            if self.key.get("kind") == "gears":
                raise NoScene("a gear key: its values stand at position 0 only", self.key.get("_path"))
            scene = self.key.get("scene")
            if not scene:
                raise NoScene("the key has no scene to search other crank angles", self.key.get("_path"))
            self._study = study(build(scene, f"{self.key.get('_path', 'key')}: scene"))
            self._quantities = quantities(self._study)
        return self._study

    def quantity(self, name: str) -> Quantity:
        self.study()
        return self._quantities[name]


def grade(keys: dict[str, dict[str, Any]], rows: list[Row], signed: bool = False) -> list[Graded]:
    """Grade every row (see the module's docstring); ``signed`` compares signs where a quantity has one."""
    variants = {vid: _Variant(key, aliases(key)) for vid, key in keys.items()}
    single = next(iter(variants.values())) if len(variants) == 1 else None
    unpadded: dict[str, list[str]] = {}
    for vid in variants:                       # "7" finds variant "07" when that is the only one
        unpadded.setdefault(vid.lstrip("0") or "0", []).append(vid)
    out: list[Graded] = []
    pending: list = []
    for row in rows:
        var = variants.get(row.variant) or (single if not row.variant else None)
        if var is None and row.variant:
            ids = unpadded.get(row.variant.lstrip("0") or "0", [])
            var = variants[ids[0]] if len(ids) == 1 else None
        if var is None:
            known = ", ".join(sorted(variants)[:5]) + (" …" if len(variants) > 5 else "")
            out.append(_noted(Graded(row, "unknown"), said("grade no key", variant=repr(row.variant), known=known)))
            continue
        out.append(_grade_row(var, row, signed, pending))
    _explain_all(pending)           # the failed rows' searches, batched per variant and quantity
    return out


def _noted(g: Graded, *notes: dict[str, str]) -> Graded:
    for n in notes:
        if n:
            g.add(n)
    return g


def _position(key: dict[str, Any], family: str, text: str) -> tuple[float | None, dict[str, str]]:
    """The row's position as an index (positions) or an abscissa in divisions (diagram), and a note."""
    try:
        x = float(text.replace(",", ".").lstrip("#"))
    except ValueError:
        return None, said("grade not a number", text=repr(text))
    if family == "diagram":
        n = key["divisions"]
        if 0 <= x <= n and (2 * x).is_integer():
            return x, {}
        return None, said("grade abscissae", n=n, half=0.5)
    count = key["count"]
    if not x.is_integer() or not 0 <= x <= count:
        return None, said("grade positions", last=count - 1)
    if x == count:
        return 0.0, said("grade position is 0", count=count)
    return x, {}


def _exact(var: _Variant, name: str, family: str, x: float) -> tuple[float, bool]:
    """The exact value at a position/abscissa: the key's, else computed (False = not in the key);
    computed once a variant (a table asks for the same few values many times)."""
    memo = (name, family, x)
    if memo not in var.computed:
        var.computed[memo] = _exact_once(var, name, family, x)
    return var.computed[memo]


def _exact_once(var: _Variant, name: str, family: str, x: float) -> tuple[float, bool]:
    key = var.key
    if family == "diagram":
        k = int(round(2 * x))
        if k < len(key["diagram"]) and name in key["diagram"][k]["values"]:
            return key["diagram"][k]["values"][name], True
        st = var.study()
        phi = diagram_phi(st, [x], key["divisions"])
    else:
        values = key["positions"][int(x)]["values"]
        if name in values:
            return values[name], True
        phi = [key["positions"][int(x)]["phi_deg"]]
        st = var.study()
    return float(var.quantity(name)(st.solve(phi))[0]), False


def _grade_row(var: _Variant, row: Row, signed: bool, pending: list | None = None) -> Graded:
    key = var.key
    name = var.names.get(row.quantity) or var.names.get(normalise(row.quantity))
    if name is None:
        return _noted(Graded(row, "unknown"), said("grade unknown quantity", q=repr(row.quantity)))
    meta = key["quantities"][name]
    x, note = _position(key, meta["family"], row.position)
    if x is None:
        return _noted(Graded(row, "unknown", name), note)
    tol = meta["tolerance_pct"]
    if row.value is None:
        return _noted(Graded(row, "fail", name, tolerance_pct=tol), said("grade no value"))
    try:
        exact, in_key = _exact(var, name, meta["family"], x)
    except NoScene:
        return _noted(Graded(row, "unknown", name, tolerance_pct=tol), said("grade no scene"))
    notes = [note] + ([said("grade computed")] if not in_key else [])
    compare_signed = signed and meta["signed"]
    got, want = (row.value, exact) if compare_signed else (abs(row.value), abs(exact))
    floor, like = _zero_floor(key, name)
    error = got - want
    allowed = tol / 100.0 * max(abs(want), floor)
    passed = abs(error) <= allowed * (1 + 1e-9)
    error_pct = 100.0 * error / abs(want) if abs(want) >= floor else None
    if error_pct is None:
        notes.append(_zero_note(meta, float(tol), floor, like))
    graded = _noted(Graded(row, "pass" if passed else "fail", name, exact, error, error_pct, tol), *notes)
    if not passed and pending is not None:
        pending.append((var, graded, name, meta["family"], x, row.value, compare_signed))
    elif not passed:
        _explain_all([(var, graded, name, meta["family"], x, row.value, compare_signed)])
    return graded


def _zero_floor(key: dict[str, Any], name: str) -> tuple[float, str | None]:
    """The bound below which |exact| is "near zero" (a percent error means nothing there): the
    key's zero fraction of the quantity's largest |value| over the turn. A quantity that is 0 at
    every crank angle (v_S1 at the crank's pivot) has no largest value of its own: it takes the
    bound of the largest quantity of its unit in the key (the crank pin's v for a velocity), the
    name returned with it — a teacher reads a zero with the absolute accuracy of its plan."""
    meta = key["quantities"][name]
    if meta["scale"] > 0:
        return key["zero_fraction"] * meta["scale"], None
    peers = [(q["scale"], other) for other, q in key["quantities"].items()
             if q.get("unit") == meta.get("unit") and q["scale"] > 0]
    if not peers:
        return ABS_FLOOR, None
    scale, like = max(peers, key=lambda p: (p[0], p[1]))
    return key["zero_fraction"] * scale, like


def _zero_note(meta: dict[str, Any], tol: float, floor: float,
               like: str | None) -> dict[str, str]:
    """The near-zero row's tolerance as a teacher states it: an absolute bound in the quantity's
    unit (±0,0125 м/с), not a percent of a number the student never saw."""
    from graphplan.util.words import UNITS, unit as unit_in
    u = meta.get("unit", "")

    def with_unit(v: float):
        return lambda lang: num(v, lang) + ("" if u in ("°", "") else "\u00a0") \
            + (unit_in(u, lang) if u in UNITS else u)
    bound = with_unit(tol / 100.0 * floor)
    if like is not None:
        return said("grade zero", bound=bound, like=like)
    return said("grade near zero", bound=bound, tol=tol, floor=with_unit(floor))


def _explain_all(pending: list) -> None:
    """Search the turn for the crank angles where each failed row's quantity takes the student's
    value. The rows of one variant share one solution of the turn's grid (every quantity read off
    it) and one bisection of all their brackets, whatever the quantity: 45 vectorised solves a
    variant, so a faculty's 100 000 rows over hundreds of variants and every quantity cost what a few
    hundred variants do (was 46 solves a variant and quantity, 45 solves a row before that)."""
    by_variant: dict[int, list] = {}
    for item in pending:
        by_variant.setdefault(id(item[0]), []).append(item)
    grid = np.arange(SEARCH_GRID + 1) * 360.0 / SEARCH_GRID
    for items in by_variant.values():
        var = items[0][0]
        try:
            st = var.study()
        except NoScene:
            if var.key.get("kind") == "gears":     # a gear's geometry has no crank angle to search
                continue
            if var.key.get("kind") == "cam":       # a cam's row is its division of the cam's turn
                for _, g, _, _, x, *_ in items:
                    at = var.key["positions"][int(x)]
                    g.add(said("grade cam division", k=int(x), turn=Fixed(float(at.get("turn_deg", at["phi_deg"])), 1),
                               phase=lambda lang, ph=at.get("phase", "rise"): word(f"grade cam {ph}", lang)))
                continue
            for _, g, *_ in items:
                g.add(said("grade key no scene"))
            continue
        kin = st.solve(grid)
        groups: dict[tuple[str, bool], list[int]] = {}
        for k, (_, _, name, _, _, _, signed) in enumerate(items):
            groups.setdefault((name, signed), []).append(k)
        curves, span = [], {}
        for name, signed in groups:
            y = var.quantity(name)(kin)
            curve = y if signed else np.abs(y)
            lo_v, hi_v = float(np.min(curve)), float(np.max(curve))
            size = max(abs(lo_v), abs(hi_v))
            span[name, signed] = tuple(0.0 if abs(v) < 1e-12 * size else v for v in (lo_v, hi_v))  # round-off is 0
            curves.append((var.quantity(name), signed, curve, groups[name, signed]))
        roots = _roots_variant(st, grid, curves, [value if signed else abs(value)
                                                  for *_, value, signed in items])
        for k, item in enumerate(items):
            _explain(item, st, roots[k], *span[item[2], item[6]])


def _explain(item: tuple, st: Study, roots: np.ndarray, lo_v: float, hi_v: float) -> None:
    """The note of one failed row from the crank angles where its quantity takes its value."""
    var, g, name, family, claimed, value, signed = item
    key = var.key
    target = value if signed else abs(value)
    if hi_v - lo_v <= 1e-9 * max(abs(hi_v), abs(lo_v), ABS_FLOOR):
        g.add(said("grade constant", name=name, v=float(hi_v)))
        return
    if len(roots) == 0:
        g.add(said("grade no angle", name=name, v=float(target), lo=float(lo_v), hi=float(hi_v)))
        return
    turns = st.from_position0(roots)
    if family == "diagram":
        step = 360.0 / key["divisions"] / 2
        listed = np.arange(2 * key["divisions"]) * step
        label = lambda j: f"{j / 2:g}"                                  # noqa: E731
        claimed_turn = claimed * 2 * step
    else:
        step = 360.0 / key["count"]
        listed = np.arange(key["count"]) * step
        label = lambda j: str(j)                                        # noqa: E731
        claimed_turn = claimed * step

    def circ(a, b):
        d = np.mod(np.asarray(a) - b, 360.0)
        return np.minimum(d, 360.0 - d)

    nearest = [int(np.argmin(circ(listed, t))) for t in turns]
    dist = np.array([float(circ(listed[j], t)) for j, t in zip(nearest, turns)])
    best_d = float(np.min(dist))
    candidates = [k for k in range(len(turns)) if dist[k] <= best_d + 1e-6]
    k = min(candidates, key=lambda c: (float(circ(turns[c], claimed_turn)), float(turns[c])))
    j = nearest[k]
    there_x = j / 2 if family == "diagram" else float(j)
    there, _ = _exact(var, name, family, there_x)
    there_cmp = there if signed else abs(there)
    fits = {"phi_deg": float(roots[k]), "turn_deg": float(turns[k]), "position": label(j),
            "position_turn_deg": float(listed[j]), "exact_there": there,
            "error_pct_there": (100.0 * (target - there_cmp) / abs(there_cmp)) if there_cmp else None,
            "angles_deg": [float(t) for t in sorted(turns)]}
    same = float(circ(listed[j], claimed_turn)) < 1e-9
    fits["other_position"] = not same
    g.fits = fits
    if same:
        g.add(said("grade inaccurate", turn=Fixed(float(turns[k]), 1)))
    else:
        g.add(said("grade fits division" if family == "diagram" else "grade fits position", at=label(j),
                   turn=Fixed(float(turns[k]), 1), there=float(there_cmp), claimed=g.row.position))


def _roots_variant(st: Study, grid: np.ndarray, curves: list, targets: list[float],
                   chunk: int = 500) -> list[np.ndarray]:
    """For each target (row k), the crank angles where its quantity − target changes sign on the
    grid (or touches zero), refined by bisection to ~1e-9°. ``curves``: (quantity, signed, its values
    on the grid, the rows it serves). The sign tables are built ``chunk`` rows at a time (chunk ×
    grid, bounded memory); the brackets of every row and quantity are then refined together, one
    solve of the mechanism a step."""
    out: list[np.ndarray] = [np.empty(0)] * len(targets)
    found_rows, found_lo, found_hi, found_flo, found_goal, found_q = [], [], [], [], [], []
    touched: dict[int, np.ndarray] = {}
    for qi, (_, _, curve, rows) in enumerate(curves):
        rows = np.asarray(rows)
        # a sample within round-off of the value touches it: the value a quantity takes at an exact
        # sample, its 0 at a dead centre included (|ω_AB| = 1e-16 at 90° is no "no angle gives 0")
        tol = 1e-12 * float(np.max(np.abs(curve), initial=0.0))
        for first in range(0, len(rows), chunk):
            part_rows = rows[first:first + chunk]
            part = np.asarray([targets[k] for k in part_rows])
            y = curve[None, :] - part[:, None]
            # the signs as masks (a byte a sample, not float signs and their products): a sample
            # within tol is 0, "touched"; a sign change is + then − or − then +
            near = np.abs(y) <= tol
            above = ~near & (y > 0)
            below = ~near & (y < 0)
            crosses = (above[:, :-1] & below[:, 1:]) | (below[:, :-1] & above[:, 1:])
            del above, below
            row, idx = np.nonzero(crosses)                                 # row-major: grouped by target
            del crosses
            found_rows.append(part_rows[row])
            found_lo.append(grid[idx])
            found_hi.append(grid[idx + 1])
            found_flo.append(y[row, idx])
            found_goal.append(part[row])
            found_q.append(np.full(len(row), qi))
            touch_row, touch_idx = np.nonzero(near[:, :-1])
            for r, i in zip(part_rows[touch_row], touch_idx):
                touched.setdefault(int(r), [])
                touched[int(r)].append(grid[i])
    rows_of = np.concatenate(found_rows) if found_rows else np.empty(0, int)
    lo = np.concatenate(found_lo) if found_lo else np.empty(0)
    hi = np.concatenate(found_hi) if found_hi else np.empty(0)
    if len(lo):
        f_lo = np.concatenate(found_flo)
        goal = np.concatenate(found_goal)
        which = np.concatenate(found_q)
        sel = [(np.nonzero(which == qi)[0], q, signed) for qi, (q, signed, _, _) in enumerate(curves)]
        sel = [x for x in sel if len(x[0])]
        f_mid = np.empty(len(lo))
        for _ in range(45):
            mid = 0.5 * (lo + hi)
            kin = st.solve(mid)
            for at, q, signed in sel:
                y = q(kin)[at]
                f_mid[at] = (y if signed else np.abs(y)) - goal[at]
            left = np.sign(f_mid) == np.sign(f_lo)
            lo, f_lo = np.where(left, mid, lo), np.where(left, f_mid, f_lo)
            hi = np.where(left, hi, mid)
    mids = 0.5 * (lo + hi)
    order = np.argsort(rows_of, kind="stable")
    bounds = np.searchsorted(rows_of[order], np.arange(len(targets) + 1))
    for k in range(len(targets)):
        roots = mids[order[bounds[k]:bounds[k + 1]]]
        if k in touched:
            roots = np.concatenate([roots, np.asarray(touched[k])])
        out[k] = np.unique(np.round(roots % 360.0, 9))
    return out


def _join(a: str, b: str) -> str:
    return f"{a}; {b}" if a else b


# -- the report --------------------------------------------------------------------------------

def summary(graded: list[Graded]) -> dict[str, Any]:
    """Counts over all rows and per variant; the pass rate is over the graded rows."""
    def counts(items: list[Graded]) -> dict[str, Any]:
        passed = sum(g.status == "pass" for g in items)
        failed = sum(g.status == "fail" for g in items)
        unknown = sum(g.status == "unknown" for g in items)
        other = sum(1 for g in items if g.fits and g.fits["other_position"])
        return {"rows": len(items), "passed": passed, "failed": failed, "unknown": unknown,
                "pass_pct": round(100.0 * passed / (passed + failed), 2) if passed + failed else None,
                "other_position": other}
    by_variant: dict[str, list[Graded]] = {}
    for g in graded:
        by_variant.setdefault(g.row.variant, []).append(g)
    return {**counts(graded), "variants": {v: counts(items) for v, items in sorted(by_variant.items())}}


def report_json(graded: list[Graded], key_path: str, student_path: str, signed: bool) -> dict[str, Any]:
    return {"key": key_path, "student": student_path, "signed": signed,
            "rows": [g.json() for g in graded], "summary": summary(graded)}


def write_json(out, graded: list[Graded], key_path: str, student_path: str, signed: bool) -> None:
    """``report_json`` as the CLI's JSON text (util.files.json_text), written row by row to ``out``:
    the same bytes without the whole document in memory at once (100 000 rows are ~100 MB of dicts)."""
    import json
    from graphplan.util.files import json_text
    head = json_text({"key": key_path, "student": student_path, "signed": signed, "rows": [],
                      "summary": summary(graded)})
    if not graded:
        out.write(head)
        return
    before, after = head.split('"rows": []', 1)
    out.write(before + '"rows": [\n')
    last = len(graded) - 1
    for k, g in enumerate(graded):
        text = json.dumps(g.json(), ensure_ascii=False, indent=1, allow_nan=False)
        out.write("  " + text.replace("\n", "\n  ") + (",\n" if k < last else "\n"))
    out.write(" ]" + after)


def report_table(graded: list[Graded], key_path: str, student_path: str, lang: str = "uk") -> str:
    """The graded rows as a table for people, then the summary; in ``lang`` (``write_table``'s text)."""
    import io
    out = io.StringIO()
    write_table(out, graded, key_path, student_path, lang)
    return out.getvalue()


def write_table(out, graded: list[Graded], key_path: str, student_path: str, lang: str = "uk") -> None:
    """``report_table`` written line by line to ``out``: the columns' widths in a first pass over the
    rows, each line formatted again as it is written; the same text without 100 000 rows' cells,
    lines and their joined copy in memory at once (~100 MB)."""
    head = word("grade head", lang).split("|")
    cells = _Cells(lang)
    widths = [len(h) for h in head[:-1]]
    for g in graded:
        for i, c in enumerate(cells(g)[:len(widths)]):
            if len(c) > widths[i]:
                widths[i] = len(c)
    right = {0, 2, 4, 5, 6, 7}

    def line(r: list[str]) -> str:
        parts = [(c.rjust(w) if i in right else c.ljust(w)) for i, (c, w) in enumerate(zip(r, widths))]
        return "  ".join(parts + [r[-1]]).rstrip() + "\n"
    out.write(word("graded against", lang, student=student_path, key=key_path) + "\n")
    out.write(line(head))
    for g in graded:
        out.write(line(cells(g)))
    s = summary(graded)
    rate = f"{num(s['pass_pct'], lang)} %" if s["pass_pct"] is not None else "—"
    lines = [""]
    lines.append(word("grade summary", lang, rows=_rows(s["rows"], lang), passed=s["passed"], failed=s["failed"],
                      unknown=s["unknown"], rate=rate, other=_rows(s["other_position"], lang, "rows fit")))
    if len(s["variants"]) > 1:
        for v, c in s["variants"].items():
            rate = f"{num(c['pass_pct'], lang)} %" if c["pass_pct"] is not None else "—"
            lines.append(word("grade variant", lang, v=v or "—", passed=c["passed"], total=c["passed"] + c["failed"],
                              rate=rate)
                         + (word("grade variant unknown", lang, n=c["unknown"]) if c["unknown"] else "")
                         + (word("grade variant other", lang, n=c["other_position"]) if c["other_position"] else ""))
    out.write("\n".join(lines) + "\n")


class _Cells:
    """A graded row's cells in ``lang``: line, variant, position, quantity, value, exact, δ %,
    tolerance, verdict, note. The key's exact values and tolerances repeat over a table's rows and
    are formatted once."""

    def __init__(self, lang: str) -> None:
        self.lang = lang
        self.verdict = {"pass": word("pass", lang), "fail": word("fail", lang), "unknown": "?"}
        self.known: dict[float, str] = {}

    def _num(self, v: float) -> str:
        text = self.known.get(v)
        if text is None:
            text = self.known[v] = num(v, self.lang)
        return text

    def __call__(self, g: Graded) -> list[str]:
        lang = self.lang
        return [str(g.row.line), g.row.variant, g.row.position, g.row.quantity,
                "" if g.row.value is None else num(g.row.value, lang, 6),
                self._num(g.exact) if g.exact is not None else "",
                fixed(g.error_pct, lang, 1, plus=True) if g.error_pct is not None else
                ("—" if g.exact is not None else ""),
                self._num(g.tolerance_pct) if g.tolerance_pct is not None else "",
                self.verdict[g.status],
                g.says(lang)]
