"""`graphplan sheet`: the drawing sheets — the kinematic analysis (sheets/kinematics.py), the force
analysis (sheets/forces.py), the dynamics and the flywheel (sheets/dynamics.py) — each composed by
construction in zones (sheets/compose.py, drawing/layout.py; docs/composition.md) and carried over to
further sheets of a set when a small format cannot hold them. The output's suffix picks SVG, PDF,
PNG or DXF; every format views the same construction record.

``BUILDERS[kind](study, form, options)`` → ``Sheet``; options: positions, accel (degrees or "#3"),
precision (mm), lang — a ``SheetOptions`` or any object with those attributes."""
from __future__ import annotations

from collections.abc import Callable

from graphplan.sheets.compose import (FORMATS_OUT, Sheet, SheetOptions, drawing_scale, options_of,  # noqa: F401
                                      page_path)

Options = SheetOptions


def build_kinematics_sheet(st, f, options) -> Sheet:
    """Sheet 1 (sheets/kinematics.py): plans, diagrams, tables."""
    from graphplan.sheets.kinematics import build_kinematics_sheet as build
    return build(st, f, options)


def build_forces_sheet(st, f, options) -> Sheet:
    """Sheet 2 (sheets/forces.py): the force analysis at the scene's force position."""
    from graphplan.sheets.forces import build_forces_sheet as build
    return build(st, f, options)


def build_dynamics_sheet(st, f, options) -> Sheet:
    """Sheet 3 (sheets/dynamics.py): the flywheel by the Wittenbauer construction and the motor."""
    from graphplan.sheets.dynamics import build_dynamics_sheet as build
    return build(st, f, options)


def build_cam_sheet(cam, f, options) -> Sheet:
    """Sheet 4 (sheets/cam.py): the cam synthesised — its first argument the cam (model.cam.Cam),
    not a lever mechanism's study."""
    from graphplan.sheets.cam import build_cam_sheet as build
    return build(cam, f, options)


def build_gears_sheet(gears, f, options) -> Sheet:
    """The gear synthesis sheet (sheets/gears.py): its first argument the gear scene (model.gears.Gears)."""
    from graphplan.sheets.gears import build_gears_sheet as build
    return build(gears, f, options)


def count_kinematics_sheets(st, f, options) -> int:
    from graphplan.sheets.kinematics import count_kinematics_sheets as count
    return count(st, f, options)


def count_forces_sheets(st, f, options) -> int:
    from graphplan.sheets.forces import count_forces_sheets as count
    return count(st, f, options)


def count_dynamics_sheets(st, f, options) -> int:
    from graphplan.sheets.dynamics import count_dynamics_sheets as count
    return count(st, f, options)


BUILDERS: dict[str, Callable[..., Sheet]] = {
    "kinematics": build_kinematics_sheet,
    "forces": build_forces_sheet,
    "dynamics": build_dynamics_sheet,
    "cam": build_cam_sheet,
    "gears": build_gears_sheet,
}

# -- the sheets as one project (docs/scenes.md, "The sheets of a scene") -------------------------

RAW = dict(BUILDERS)        # each kind's sheets numbered as their own set (counted by ``pages_of``)

# each kind's sheet count without drawing a document its plan makes one sheet (``pages_of``: the
# kinematics sheet of a scene composed its forces and dynamics documents whole only to count them)
COUNTS: dict[tuple[str, Callable[..., Sheet]], Callable[..., int]] = {
    ("kinematics", build_kinematics_sheet): count_kinematics_sheets,
    ("forces", build_forces_sheet): count_forces_sheets,
    ("dynamics", build_dynamics_sheet): count_dynamics_sheets,
}

ORDER = ("kinematics", "forces", "dynamics", "gears", "cam")   # the course project's documents in order


def document_number(kind: str) -> int:
    """The kind's document number in the project (its place in ``ORDER``; a kind not listed comes
    after them all): kinematics 1, forces 2, dynamics 3, gears 4, cam 5."""
    return ORDER.index(kind) + 1 if kind in ORDER else len(ORDER) + 1


def designation(base: str, kind: str, alone: bool = False) -> str:
    """The designation of the kind's document: the scene's ``base`` with its last group of digits
    replaced by the document's number, as wide as that group ("ТММ.КП.00.000" → "ТММ.КП.00.003"
    for the dynamics); a base not ending in digits gets ".N" appended; none stays none. The one
    document of a cam or gear scene (``alone``) is a project of its own ("Аркуш 1,
    Аркушів 1"): it carries the designation as the student wrote it — "ТММ.ЗП.54.000" stays, where
    ".004" would name document 4 of a project that has no documents 1–3."""
    import re
    if not base or alone:
        return base
    n = document_number(kind)
    m = re.search(r"(\d+)$", base)
    if m is None:
        return f"{base}.{n}"
    return base[:m.start()] + str(n).zfill(len(m.group(1)))


def kinds_of(scene, kind: str) -> tuple[str, ...]:
    """The sheets the scene makes, in the project's order: a lever mechanism's kinematics always,
    forces when it loads a link (a mass, an inertia or a [[force]]), dynamics when it has a
    [dynamics] table; a cam or gear scene its one sheet. ``kind`` (the sheet asked for) is among
    them."""
    kinds = {kind}
    mech = getattr(scene, "mech", None)
    if mech is not None:
        from graphplan.model.mechanism import Drive
        from graphplan.sheets.forces import has_loads
        kinds.add("kinematics")
        if has_loads(scene):
            kinds.add("forces")
        if mech.task.flywheel or mech.drive != Drive():
            kinds.add("dynamics")
    return tuple(sorted(kinds, key=lambda k: (document_number(k), k)))


_PAGES: dict[tuple, int] = {}


def _key(kind: str, scene, f, options) -> tuple:
    opts = options_of(options)
    return (kind, repr(getattr(scene, "mech", scene)), f.name, opts.positions, tuple(opts.accel or ()),
            opts.precision, opts.lang or "uk")


def cache_folder():
    """Where sheet counts are kept between processes: ``$GRAPHPLAN_CACHE`` (empty, "0" or "off":
    nowhere), else ``$XDG_CACHE_HOME/graphplan``, else ``~/.cache/graphplan``."""
    import os
    from pathlib import Path
    said = os.environ.get("GRAPHPLAN_CACHE")
    if said is not None:
        return None if said.strip().lower() in ("", "0", "off", "no") else Path(said)
    home = os.environ.get("XDG_CACHE_HOME") or str(Path.home() / ".cache")
    return Path(home) / "graphplan"


def _code_digest() -> str:
    """A digest of the package as it runs — every file of graphplan/ (the code, the fonts' metrics,
    the motors' catalogue) and the numeric libraries' versions: a count kept on disk is read back
    only by the very code that composed it."""
    global _DIGEST
    if _DIGEST is None:
        import hashlib
        from pathlib import Path

        import numpy
        import scipy
        import graphplan
        h = hashlib.sha256(f"{numpy.__version__} {scipy.__version__}".encode())
        root = Path(graphplan.__file__).parent
        for path in sorted(p for p in root.rglob("*") if p.is_file() and "__pycache__" not in p.parts
                           and p.suffix not in (".pyc", ".pyo")):
            h.update(str(path.relative_to(root)).encode())
            h.update(path.read_bytes())
        _DIGEST = h.hexdigest()
    return _DIGEST


_DIGEST: str | None = None


def _disk_path(key: tuple):
    folder = cache_folder()
    if folder is None:
        return None
    import hashlib
    return folder / "pages" / (hashlib.sha256(repr((_code_digest(), key)).encode()).hexdigest() + ".txt")


def _read_disk(key: tuple) -> int | None:
    """The count kept on disk for ``key`` by this very code, None when none is (or it cannot be read)."""
    path = _disk_path(key)
    try:
        return int(path.read_text()) if path is not None else None
    except (OSError, ValueError):
        return None


def _write_disk(key: tuple, n: int) -> None:
    """Keep the count on disk (written whole, then renamed: a reader never sees half a file); a
    folder that cannot be written is no error — the count is composed again next time."""
    import os
    path = _disk_path(key)
    if path is None:
        return
    import contextlib
    with contextlib.suppress(OSError):
        path.parent.mkdir(parents=True, exist_ok=True)
        tmp = path.with_suffix(f".{os.getpid()}.tmp")
        tmp.write_text(str(n))
        os.replace(tmp, path)


def remember_pages(key: tuple, n: int) -> None:
    """The kind's sheet count, in this process (a few dozen kept) and on disk."""
    if key not in _PAGES and len(_PAGES) >= 64:
        _PAGES.pop(next(iter(_PAGES)))
    if _PAGES.get(key) != n:
        _PAGES[key] = n
        _write_disk(key, n)


def pages_of(kind: str, scene, f, options) -> int:
    """How many sheets the kind's document takes on the format ``f``, counted by composing it in the
    sheet's own language — on A1 too: a document may flow onto a second A1 sheet (stop 47's six-bar:
    its force analysis takes two, and the kinematics sheet printed "Аркушів 3" where the forces'
    printed 4) — remembered
    per scene, format, options and language: the English notes may wrap to more lines and flow a
    document onto one more sheet — review 11's compressor: dynamics 3 A3 sheets in Ukrainian, 4 in
    English, so the set printed "Sheets 11" on kinematics and forces, "of 12" on dynamics).
    Composing a set takes long (stop 47's six-bar: its kinematics and forces A2 sets ~45 s of CPU,
    for the dynamics set's numbers only), so the count is also kept on disk (``cache_folder``),
    read back only by the same code for the same scene: ``graphplan serve``'s workers and later
    runs number a set without composing the other documents again."""
    key = _key(kind, scene, f, options)
    if key not in _PAGES:
        n = _read_disk(key)
        if n is None:
            opts = options_of(options)
            raw = SheetOptions(opts.positions, opts.accel, opts.precision, opts.lang or "uk", kind)
            count = COUNTS.get((kind, RAW[kind]))        # (a builder stood in for is asked itself)
            n = count(scene, f, raw) if count is not None else len(RAW[kind](scene, f, raw).pages)
        remember_pages(key, n)
    return _PAGES[key]


def _pages_or_zero(kind: str, scene, f, options) -> int:
    """``pages_of``, or 0 where the scene cannot make that document (its own sheet refuses it with
    one line, e.g. a cycle needing more than the catalogue's largest motor): asking for the
    kinematics sheet is no reason to refuse it for the dynamics' fault; the project is then numbered
    without the refused document, as the student's folder holds it."""
    from graphplan.util.errors import GraphplanError
    try:
        return pages_of(kind, scene, f, options)
    except GraphplanError:
        return 0


def numbered(kind: str, build: Callable[..., Sheet]) -> Callable[..., Sheet]:
    """``build`` with its sheets numbered in the scene's project: the designation ending in the
    kind's document number, "Аркуш" the running number over the project's documents in order (an
    A2/A3 set's later sheets continue it), "Аркушів" the project's total."""
    import functools

    @functools.wraps(build)
    def wrapper(scene, f, options) -> Sheet:
        sheet = build(scene, f, options)
        remember_pages(_key(kind, scene, f, options), len(sheet.pages))   # what the others' sheets read
        kinds = kinds_of(scene, kind)
        first, total = 1, 0
        for k in kinds:
            n = len(sheet.pages) if k == kind else _pages_or_zero(k, scene, f, options)
            if document_number(k) < document_number(kind):
                first += n
            total += n
        alone = kinds == (kind,) and kind in ("cam", "gears")     # a lever scene's documents: by kind
        return sheet.number(first, total, designation(sheet.fields.get("designation", ""), kind, alone=alone))
    return wrapper


BUILDERS = {kind: numbered(kind, build) for kind, build in RAW.items()}   # … numbered in the scene's project
