"""A group's variants: one row per student over a base scene, each row overriding a few numbers.

The table is CSV (``,`` ``;`` or tab separated; a decimal comma where the comma is not the separator,
or quoted) or TOML; its numbers are read as a student's table's are (model.bounds.read_number).
Directives in ``#`` lines above the CSV header (``# base = crank_slider.toml``) or top-level TOML keys
set the defaults; the ``variant`` column names each row. Columns override the base scene's tree:
a ``[params]`` name, a shorthand (``rpm``, ``K``, ``accel`` …) or a dotted path (``crank.length``,
``link.AB.points.S2``). The format is documented in docs/keys.md.
"""
from __future__ import annotations

import copy
import csv
import fnmatch
import io
import re
import tomllib
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from graphplan.util.errors import GraphplanError, SceneError
from graphplan.model.mechanism import Mechanism
from graphplan.util.files import read_text
from graphplan.model.bounds import clean_text
from graphplan.model.scene import build

DEFAULT_TOLERANCE = 5.0   # percent, the lab's criterion (REFERENCE §1.6)

# columns that are not scene overrides
MAX_VARIANTS = 2000     # a course's groups; each variant takes about a second
RESERVED = {"variant", "base", "student", "divisions", "tolerance"}
# shorthand columns → their table in the scene tree
SHORTHAND = {"rpm": "crank", "omega": "crank", "direction": "crank", "epsilon": "crank",
             "K": "synthesis", "stroke": "synthesis", "centre_distance": "synthesis",
             "count": "positions", "start": "positions", "accel": "positions", "output": "positions"}
_DIRECTIVE = re.compile(r"^#\s*([A-Za-z_][\w.*?\[\]]*)\s*=\s*(.*?)\s*$")
_ID = re.compile(r"^[A-Za-z0-9][A-Za-z0-9._-]*$")


@dataclass
class Variant:
    """One row: its id, base scene, the overrides as given, and its own tolerance settings."""
    id: str
    base: Path
    overrides: dict[str, Any]
    student: str = ""
    divisions: int | None = None
    tolerances: dict[str, float] = field(default_factory=dict)   # pattern → percent ("*" = all)
    row: int = 0                                                   # line in the file (CSV) or index

    def where(self, table: Path) -> str:
        return f"{table}: variant {self.id}"


@dataclass
class VariantTable:
    """The whole table: where it came from, its variants and the file-level tolerances."""
    path: Path
    variants: list[Variant]
    tolerances: dict[str, float]
    trees: dict[Path, dict[str, Any]] = field(default_factory=dict)   # base scenes read so far

    def base_tree(self, path: Path) -> dict[str, Any]:
        """The parsed base scene (read once per table)."""
        key = path.resolve()
        if key not in self.trees:
            self.trees[key] = read_tree(path)
        return copy.deepcopy(self.trees[key])


def tolerance_for(quantity: str, *layers: dict[str, float]) -> float:
    """The tolerance of a quantity: the first layer naming it by a pattern other than "*" wins,
    then the first layer with a general "*" value, else the default ±5 %."""
    for layer in layers:
        for pattern, value in layer.items():
            if pattern != "*" and fnmatch.fnmatchcase(quantity, pattern):
                return value
    for layer in layers:
        if "*" in layer:
            return layer["*"]
    return DEFAULT_TOLERANCE


def parse_cell(text: str, delimiter: str = ";") -> Any:
    """A cell's value: a number (read by model.bounds.read_number, the one reader of every table's
    numbers: students' tables too), a TOML value (``[0, 0.5]``, ``"text"``, ``true``), else the text
    itself (an expression such as ``0.7 * rocker`` or a word such as ``ccw``). ValueError with the
    reason for a number that cannot be read for sure (0x10, 7_2, 1e-400, "2.800" in a ';' table),
    also inside an expression or a list."""
    from graphplan.model.bounds import check_numbers_in, numeric_like, read_number
    text = text.strip()
    if numeric_like(text):
        try:
            return read_number(text, delimiter)
        except ValueError as exc:
            raise ValueError(f"{text[:30]!r}: {exc}") from None
    try:
        check_numbers_in(text, delimiter)
    except ValueError as exc:
        raise ValueError(f"{text[:30]!r}: {exc}") from None
    try:
        return tomllib.loads(f"v = {text}")["v"]
    except (tomllib.TOMLDecodeError, RecursionError, ValueError):
        return text


def read(path: str | Path) -> VariantTable:
    """Read a variant table (CSV, or TOML by the ``.toml`` suffix)."""
    path = Path(path)
    text = read_text(path, "variant table")
    if path.suffix.lower() == ".toml":
        rows, directives = _toml_rows(text, path)
    else:
        rows, directives = _csv_rows(text, path)
    return _table(path, rows, directives)


def _csv_rows(text: str, path: Path) -> tuple[list[tuple[int, dict[str, Any]]], dict[str, Any]]:
    directives: dict[str, Any] = {}
    lines = text.splitlines()
    header_at = None
    for n, line in enumerate(lines):
        stripped = line.strip()
        if not stripped:
            continue
        if stripped.startswith("#"):
            m = _DIRECTIVE.match(stripped)
            if m:
                try:
                    directives[m.group(1)] = parse_cell(m.group(2), ";")
                except ValueError as exc:
                    raise GraphplanError(f"line {n + 1}: {exc}", str(path)) from None
            continue
        header_at = n
        break
    if header_at is None:
        raise GraphplanError("the table has no header row (a 'variant' column and the overrides)", str(path))
    header_line = lines[header_at]
    delimiter = ";" if ";" in header_line else "\t" if "\t" in header_line else ","
    body = [(n + 1, line) for n, line in enumerate(lines) if n >= header_at
            and line.strip() and not line.strip().startswith("#")]
    reader = csv.reader(io.StringIO("\n".join(line for _, line in body)), delimiter=delimiter)
    records = list(reader)
    header = [h.strip() for h in records[0]]
    if len(set(header)) != len(header):
        dup = next(h for h in header if header.count(h) > 1)
        raise GraphplanError(f"column {dup!r} appears twice", str(path))
    rows = []
    for (line_no, _), cells in zip(body[1:], records[1:]):
        if len(cells) > len(header):
            raise GraphplanError(f"line {line_no}: {len(cells)} cells for {len(header)} columns", str(path))
        row: dict[str, Any] = {}
        for name, cell in zip(header, cells):
            if cell.strip() == "":
                continue
            if name in ("variant", "student", "base"):
                row[name] = cell.strip()
                continue
            try:
                row[name] = parse_cell(cell, delimiter)
            except ValueError as exc:
                raise GraphplanError(f"line {line_no}, column {name}: {exc}", str(path)) from None
        rows.append((line_no, row))
    for name in header:
        if name == "":
            raise GraphplanError("a column has no name", str(path))
    if "variant" not in header:
        raise GraphplanError("the table needs a 'variant' column", str(path))
    return rows, directives


def _flatten(tree: dict[str, Any], prefix: str = "") -> dict[str, Any]:
    out: dict[str, Any] = {}
    for key, value in tree.items():
        name = f"{prefix}{key}"
        if isinstance(value, dict) and name != "tolerance":
            out.update(_flatten(value, name + "."))
        else:
            out[name] = value
    return out


def _toml_rows(text: str, path: Path) -> tuple[list[tuple[int, dict[str, Any]]], dict[str, Any]]:
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise GraphplanError(f"TOML syntax error: {exc}", str(path)) from None
    _toml_numbers(text, path)
    raw = data.pop("variant", None)
    if not isinstance(raw, list) or not raw:
        raise GraphplanError("the table needs [[variant]] entries", str(path))
    directives = {}
    for key, value in data.items():
        if key == "tolerance" and isinstance(value, dict):
            directives.update({f"tolerance.{k}": v for k, v in value.items()})
        else:
            directives[key] = value
    rows = []
    for k, entry in enumerate(raw):
        if not isinstance(entry, dict):
            raise GraphplanError(f"variant[{k}] must be a table", str(path))
        row = _flatten({key: value for key, value in entry.items() if key != "tolerance"})
        tol = entry.get("tolerance")
        if isinstance(tol, dict):
            row.update({f"tolerance.{q}": v for q, v in tol.items()})
        elif tol is not None:
            row["tolerance"] = tol
        if "variant" in row:
            row["variant"] = str(row["variant"])
        rows.append((k, row))
    return rows, directives


_TOML_STRING = re.compile(r'"""[\s\S]*?"""|\'\'\'[\s\S]*?\'\'\'|"(?:[^"\\\\\n]|\\\\.)*"|\'[^\'\n]*\'')
_TOML_WORDS = re.compile(r"(?<![\w.])[+-]?(inf|nan)(?![\w.])")


def _toml_numbers(text: str, path: Path) -> None:
    """A TOML variant table's numbers by the rule of the CSV's and the students' tables
    (model.bounds.read_number): TOML itself reads 0x10, 0o7000, 0b101, 1_000, inf, nan and 1e-400
    (as 0) — each is refused here, naming the line, as it is in a CSV cell."""
    from graphplan.model.bounds import check_numbers_in
    blanked = _TOML_STRING.sub(lambda m: re.sub(r"[^\n]", " ", m.group(0)), text)   # keeps the lines
    for n, line in enumerate(blanked.split("\n"), 1):
        line = line.split("#", 1)[0]
        key, value = line.split("=", 1) if "=" in line else ("", line)
        try:
            if _TOML_WORDS.search(value):
                raise ValueError(f"{_TOML_WORDS.search(value).group(0).strip()!r}: not a finite number")
            check_numbers_in(value, ",")
        except ValueError as exc:
            where = f", {key.strip()}" if key.strip() else ""
            raise GraphplanError(f"line {n}{where}: {exc}", str(path)) from None


def _percent(value: Any, where: str, path: Path) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not 0 < value <= 100:
        raise GraphplanError(f"{where}: a tolerance must be a percentage in (0, 100], got {value!r}", str(path))
    return float(value)


def _split_tolerances(row: dict[str, Any], where: str, path: Path) -> dict[str, float]:
    out = {}
    for key in list(row):
        if key == "tolerance":
            out["*"] = _percent(row.pop(key), f"{where}tolerance", path)
        elif key.startswith("tolerance."):
            out[key[len("tolerance."):]] = _percent(row.pop(key), f"{where}{key}", path)
    return out


def _divisions(value: Any, where: str, path: Path) -> int:
    if isinstance(value, bool) or not isinstance(value, int) or not 2 <= value <= 720:
        raise GraphplanError(f"{where}divisions must be a whole number from 2 to 720, got {value!r}", str(path))
    return value


def _table(path: Path, rows: list[tuple[int, dict[str, Any]]], directives: dict[str, Any]) -> VariantTable:
    known = {"base", "divisions", "tolerance", "title"}
    for key in directives:
        if key not in known and not key.startswith("tolerance."):
            raise GraphplanError(f"unknown directive {key!r} (known: base, divisions, tolerance, "
                                 "tolerance.<quantity>)", str(path))
    file_tol = _split_tolerances(dict(directives), "", path)
    default_div = _divisions(directives["divisions"], "", path) if "divisions" in directives else None
    if not rows:
        raise GraphplanError("the table has no variants", str(path))
    if len(rows) > MAX_VARIANTS:
        raise GraphplanError(f"{len(rows)} variants; a table holds at most {MAX_VARIANTS} "
                             "(split the group's table)", str(path))
    variants, seen = [], set()
    for line_no, row in rows:
        row = dict(row)
        where = f"line {line_no}: " if path.suffix.lower() != ".toml" else f"variant[{line_no}]: "
        vid = str(row.pop("variant", "")).strip()
        if not vid:
            raise GraphplanError(f"{where}the variant has no id", str(path))
        if not _ID.match(vid):
            raise GraphplanError(f"{where}variant id {vid!r}: use letters, digits, '.', '_' or '-'", str(path))
        if vid.lower().startswith("summary.") or vid.strip(".") == "":
            raise GraphplanError(f"{where}variant id {vid!r} is the name of a summary file; "
                                 "call the variant otherwise", str(path))
        if vid in seen:
            raise GraphplanError(f"{where}variant {vid!r} appears twice", str(path))
        seen.add(vid)
        base_text = row.pop("base", directives.get("base"))
        if base_text is None:
            raise GraphplanError(f"{where}no base scene: add '# base = SCENE.toml' or a 'base' column",
                                 str(path))
        base = Path(str(base_text))
        if not base.is_absolute():
            base = path.parent / base
        tolerances = _split_tolerances(row, where, path)
        divisions = _divisions(row.pop("divisions"), where, path) if "divisions" in row else default_div
        student = clean_text(row.pop("student", ""))
        variants.append(Variant(vid, base, row, student, divisions, tolerances, line_no))
    return VariantTable(path, variants, file_tol)


# -- applying overrides to a base scene's tree ------------------------------------------------------

def read_tree(path: Path) -> dict[str, Any]:
    """A scene file's TOML tree (errors name the file)."""
    from graphplan.model.bounds import MAX_SCENE_BYTES, parse_toml
    try:
        text = read_text(path, "base scene", MAX_SCENE_BYTES)
    except GraphplanError as exc:
        raise SceneError(str(exc), exc.where, exc.said, exc.lang) from None
    return parse_toml(text, str(path))


def target(tree: dict[str, Any], column: str) -> tuple[str, ...] | None:
    """Where a column writes in the scene tree, or None for an unknown column.

    Order: a ``[params]`` name, a shorthand (rpm, K, accel …), a dotted path whose parent exists
    (``link.<name>.…`` picks the ``[[link]]`` of that name)."""
    if column in tree.get("params", {}):
        return ("params", column)
    if column in SHORTHAND:
        section = SHORTHAND[column]
        if section == "synthesis" and "synthesis" not in tree:
            return None
        return (section, column)
    parts = tuple(column.split("."))
    if len(parts) < 2:
        return None
    node: Any = tree
    for part in parts[:-1]:
        node = _child(node, part)
        if node is None:
            return None
    return parts if isinstance(node, dict) else None


def _child(node: Any, part: str) -> Any:
    if isinstance(node, dict):
        value = node.get(part)
        return value
    if isinstance(node, list):   # [[link]] addressed by its name
        for entry in node:
            if isinstance(entry, dict) and _link_name(entry) == part:
                return entry
    return None


def _link_name(entry: dict[str, Any]) -> str:
    if "name" in entry:
        return str(entry["name"])
    joints = entry.get("joints", [])
    return "".join(str(j) for j in joints) if isinstance(joints, list) else ""


def apply(tree: dict[str, Any], overrides: dict[str, Any], where: str) -> dict[str, Any]:
    """The base tree with a variant's overrides written in (a new tree)."""
    tree = copy.deepcopy(tree)
    for column, value in overrides.items():
        path = target(tree, column)
        if path is None:
            raise SceneError(f"column {column!r}: not a [params] name, a shorthand "
                             f"({', '.join(sorted(SHORTHAND))}) or a path in the base scene", where)
        node: Any = tree
        for part in path[:-1]:
            if isinstance(node, dict):
                node = node.setdefault(part, {})
            else:
                node = _child(node, part)
        if column == "accel":
            value = _accel(value, where)
        if path[0] == "crank" and column in ("rpm", "omega"):
            node.pop("omega" if column == "rpm" else "rpm", None)
        node[path[-1]] = value
    return tree


def _accel(value: Any, where: str) -> list[int]:
    """``1``, ``"1;4"``, ``"1 4"`` or ``[1, 4]`` → [1, 4]."""
    if isinstance(value, list):
        return value
    if isinstance(value, int) and not isinstance(value, bool):
        return [value]
    parts = [p for p in re.split(r"[;\s|/]+", str(value).strip()) if p]
    if not parts or not all(re.fullmatch(r"\d+", p) for p in parts):
        raise SceneError(f"accel: position numbers separated by ';' or spaces, got {value!r}", where)
    return [int(p) for p in parts]


def check_columns(table: VariantTable) -> None:
    """Every override column must mean something in its row's base scene (one error for the table)."""
    for v in table.variants:
        tree = table.base_tree(v.base)
        for column in v.overrides:
            if column in RESERVED:
                continue
            if target(tree, column) is None:
                raise GraphplanError(f"column {column!r} (variant {v.id}): not a [params] name of "
                                     f"{v.base.name}, a shorthand ({', '.join(sorted(SHORTHAND))}) "
                                     "or a dotted path in it", str(table.path))


def scene_tree(table: VariantTable, variant: Variant) -> dict[str, Any]:
    """The variant's resolved scene tree (the base with the overrides)."""
    return apply(table.base_tree(variant.base), variant.overrides, variant.where(table.path))


def mechanism(table: VariantTable, variant: Variant) -> Mechanism:
    """The variant's mechanism; SceneError (naming the variant) when the row does not make one."""
    return build(scene_tree(table, variant), variant.where(table.path))
