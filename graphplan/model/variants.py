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

from graphplan.util.errors import GraphplanError, SaidValueError, SceneError, reason, said_error, speaking, where_said
from graphplan.model.mechanism import Mechanism
from graphplan.util.files import read_text
from graphplan.model.bounds import clean_text
from graphplan.model.scene import build
from graphplan.util.words import word

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
        """The place a refusal about this row names: "TABLE: variant ID" in each language."""
        return where_said("vt where", table=table, id=self.id)


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
            raise SaidValueError("nb in cell", text=repr(text[:30]), why=reason(exc)) from None
    try:
        check_numbers_in(text, delimiter)
    except ValueError as exc:
        raise SaidValueError("nb in cell", text=repr(text[:30]), why=reason(exc)) from None
    try:
        return tomllib.loads(f"v = {text}")["v"]
    except (tomllib.TOMLDecodeError, RecursionError, ValueError):
        return text


def read(path: str | Path) -> VariantTable:
    """Read a variant table (CSV, or TOML by the ``.toml`` suffix)."""
    path = Path(path)
    try:
        text = read_text(path, "variant table")
    except GraphplanError as exc:            # not UTF-8, say: the base scene's language still told
        from graphplan.util.files import read_bytes
        try:
            seen = read_bytes(path, "variant table").decode("utf-8", "replace")
        except GraphplanError:
            raise exc from None
        raise speaking(exc, base_lang(path, seen)) from None
    try:
        if path.suffix.lower() == ".toml":
            rows, directives = _toml_rows(text, path)
        else:
            rows, directives = _csv_rows(text, path)
        return _table(path, rows, directives)
    except GraphplanError as exc:
        raise speaking(exc, base_lang(path, text)) from None


def base_lang(path: Path, text: str) -> str | None:
    """The ``lang`` of the table's base scene (its ``base`` directive), the language a refusal of
    the table speaks without --lang; None where there is none or it does not read."""
    m = re.search(r"(?m)^\s*#?\s*base\s*=\s*(.+?)\s*$", text)
    if not m:
        return None
    name = m.group(1).strip().strip("'\"")
    base = Path(name) if Path(name).is_absolute() else path.parent / name
    try:
        from graphplan.model.bounds import MAX_SCENE_BYTES, parse_toml
        lang = parse_toml(read_text(base, "base scene", MAX_SCENE_BYTES), str(base)).get("lang")
    except (GraphplanError, OSError, ValueError):
        return None
    return lang if lang in ("uk", "en") else None


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
                    raise said_error(GraphplanError, "vt line", str(path), None, line=n + 1, why=reason(exc)) from None
            continue
        header_at = n
        break
    if header_at is None:
        raise said_error(GraphplanError, "vt no header", str(path), None)
    header_line = lines[header_at]
    delimiter = ";" if ";" in header_line else "\t" if "\t" in header_line else ","
    body = [(n + 1, line) for n, line in enumerate(lines) if n >= header_at
            and line.strip() and not line.strip().startswith("#")]
    reader = csv.reader(io.StringIO("\n".join(line for _, line in body)), delimiter=delimiter)
    records = list(reader)
    header = [h.strip() for h in records[0]]
    if len(set(header)) != len(header):
        dup = next(h for h in header if header.count(h) > 1)
        raise said_error(GraphplanError, "vt column twice", str(path), None, name=repr(dup))
    rows = []
    for (line_no, _), cells in zip(body[1:], records[1:]):
        if len(cells) > len(header):
            hint = (lambda lang: word("st comma hint", lang)) if delimiter == "," else ""
            raise said_error(GraphplanError, "vt cells", str(path), None, line=line_no, n=len(cells),
                             width=len(header), hint=hint)
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
                raise said_error(GraphplanError, "vt cell", str(path), None, line=line_no, column=name,
                                 why=reason(exc)) from None
        rows.append((line_no, row))
    for name in header:
        if name == "":
            raise said_error(GraphplanError, "vt no name", str(path), None)
    if "variant" not in header:
        raise said_error(GraphplanError, "vt no variant column", str(path), None)
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
    from graphplan.model.bounds import MAX_TOML_DEPTH, check_tree, toml_why
    from graphplan.util.errors import keyed_error
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise keyed_error(GraphplanError, str(path), "", "bad toml syntax", None, toml="TOML",
                          why=toml_why(str(exc))) from None
    except (RecursionError, ValueError):
        raise keyed_error(GraphplanError, str(path), "", "bad toml depth", None, toml="TOML", most=MAX_TOML_DEPTH) from None
    check_tree(data, str(path))
    _toml_numbers(text, path)
    raw = data.pop("variant", None)
    if not isinstance(raw, list) or not raw:
        raise said_error(GraphplanError, "vt no entries", str(path), None)
    directives = {}
    for key, value in data.items():
        if key == "tolerance" and isinstance(value, dict):
            directives.update({f"tolerance.{k}": v for k, v in value.items()})
        else:
            directives[key] = value
    rows = []
    for k, entry in enumerate(raw):
        if not isinstance(entry, dict):
            raise said_error(GraphplanError, "vt entry table", str(path), None, k=k)
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
                raise SaidValueError("nb in cell", text=repr(_TOML_WORDS.search(value).group(0).strip()),
                                     why=lambda lang: word("nb not finite", lang))
            check_numbers_in(value, ",")
        except ValueError as exc:
            where = f", {key.strip()}" if key.strip() else ""
            raise said_error(GraphplanError, "vt toml line", str(path), None, line=n, key=where,
                             why=reason(exc)) from None


def _percent(value: Any, at: object, key: str, path: Path) -> float:
    """A tolerance, % in (0, 100]; ``at`` the row's place ("line 3: ", a language's text) or ""."""
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not 0 < value <= 100:
        raise said_error(GraphplanError, "vt tolerance", str(path), None, at=at, key=key, got=repr(value))
    return float(value)


def _split_tolerances(row: dict[str, Any], at: object, path: Path) -> dict[str, float]:
    out = {}
    for key in list(row):
        if key == "tolerance":
            out["*"] = _percent(row.pop(key), at, key, path)
        elif key.startswith("tolerance."):
            out[key[len("tolerance."):]] = _percent(row.pop(key), at, key, path)
    return out


def _divisions(value: Any, at: object, path: Path) -> int:
    if isinstance(value, bool) or not isinstance(value, int) or not 2 <= value <= 720:
        raise said_error(GraphplanError, "vt divisions", str(path), None, at=at, got=repr(value))
    return value


def _table(path: Path, rows: list[tuple[int, dict[str, Any]]], directives: dict[str, Any]) -> VariantTable:
    known = {"base", "divisions", "tolerance", "title"}
    for key in directives:
        if key not in known and not key.startswith("tolerance."):
            raise said_error(GraphplanError, "vt directive", str(path), None, key=repr(key))
    file_tol = _split_tolerances(dict(directives), "", path)
    default_div = _divisions(directives["divisions"], "", path) if "divisions" in directives else None
    if not rows:
        raise said_error(GraphplanError, "vt no variants", str(path), None)
    if len(rows) > MAX_VARIANTS:
        raise said_error(GraphplanError, "vt too many", str(path), None, n=len(rows), most=MAX_VARIANTS)
    variants, seen = [], set()
    for line_no, row in rows:
        row = dict(row)
        where = ((lambda lang, n=line_no: word("vt at line", lang, line=n)) if path.suffix.lower() != ".toml"
                 else f"variant[{line_no}]: ")
        vid = str(row.pop("variant", "")).strip()
        if not vid:
            raise said_error(GraphplanError, "vt no id", str(path), None, at=where)
        if not _ID.match(vid):
            raise said_error(GraphplanError, "vt bad id", str(path), None, at=where, id=repr(vid))
        if vid.lower().startswith("summary.") or vid.strip(".") == "":
            raise said_error(GraphplanError, "vt summary id", str(path), None, at=where, id=repr(vid))
        if vid in seen:
            raise said_error(GraphplanError, "vt id twice", str(path), None, at=where, id=repr(vid))
        seen.add(vid)
        base_text = row.pop("base", directives.get("base"))
        if base_text is None:
            raise said_error(GraphplanError, "vt no base", str(path), None, at=where)
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
            raise said_error(SceneError, "vt unknown column", where, None, column=repr(column),
                             short=", ".join(sorted(SHORTHAND)))
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
        raise said_error(SceneError, "vt accel", where, None, got=repr(value))
    return [int(p) for p in parts]


def check_columns(table: VariantTable) -> None:
    """Every override column must mean something in its row's base scene (one error for the table)."""
    for v in table.variants:
        tree = table.base_tree(v.base)
        for column in v.overrides:
            if column in RESERVED:
                continue
            if target(tree, column) is None:
                raise speaking(said_error(GraphplanError, "vt unknown column in", str(table.path), None,
                                          column=repr(column), id=v.id, base=v.base.name,
                                          short=", ".join(sorted(SHORTHAND))), tree.get("lang"))


def scene_tree(table: VariantTable, variant: Variant) -> dict[str, Any]:
    """The variant's resolved scene tree (the base with the overrides)."""
    return apply(table.base_tree(variant.base), variant.overrides, variant.where(table.path))


def mechanism(table: VariantTable, variant: Variant) -> Mechanism:
    """The variant's mechanism; SceneError (naming the variant) when the row does not make one."""
    return build(scene_tree(table, variant), variant.where(table.path))
