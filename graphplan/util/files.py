"""Writing files whole or not at all: a temporary file in the same folder, then a rename."""
from __future__ import annotations

import json
import os
import tempfile
from pathlib import Path
from typing import Any

from graphplan.util.errors import GraphplanError, said_error

# what a file is, as a refusal names it (read_bytes's ``what``): Ukrainian (nominative, genitive)
WHAT_UK = {"scene": ("сцена", "сцени"), "scene file": ("файл сцени", "файлу сцени"),
           "variant table": ("таблиця варіантів", "таблиці варіантів"), "base scene": ("базова сцена", "базової сцени"),
           "key file": ("файл ключа", "файлу ключа"), "table": ("таблиця", "таблиці"),
           "student table": ("таблиця студента", "таблиці студента"), "file": ("файл", "файлу")}


def _what(what: str, case: int = 0):
    """``what`` in the reader's language (a name the catalogue's ``said`` calls with the language);
    ``case`` 1: the Ukrainian genitive ("не знайдено файлу сцени")."""
    return lambda lang: WHAT_UK[what][case] if lang == "uk" and what in WHAT_UK else what


what_said = _what       # the name other rooms use


def _why(exc: OSError):
    """An OS error's reason in the reader's language: the common ones worded by the catalogue."""
    import errno
    from graphplan.util.words import word
    key = {errno.EACCES: "fl no permission", errno.EPERM: "fl no permission", errno.ENOENT: "fl no folder"}.get(
        exc.errno)
    return lambda lang: word(key, lang) if key else str(exc.strerror or exc)


def json_text(doc: Any) -> str:
    """Deterministic JSON for stdout and files: keys in the order given, no NaN, one indent."""
    return json.dumps(doc, ensure_ascii=False, indent=1, allow_nan=False) + "\n"


MAX_INPUT_BYTES = 4 * 1024 * 1024     # a scene, a variant table or a student's table is far smaller


def read_bytes(path: str | Path, what: str, limit: int = MAX_INPUT_BYTES) -> bytes:
    """A regular file's bytes, at most ``limit`` of them, or one clear line naming the file.

    Only regular files and pipes are read: a folder or a device (``/dev/zero`` never ends) is
    refused before anything is read, and whatever holds more than ``limit`` bytes is refused after
    reading ``limit`` + 1 of them (an endless pipe too)."""
    path = Path(path)
    try:
        if not path.exists():
            raise said_error(GraphplanError, "fl missing", str(path), None, what=_what(what), of=_what(what, 1))
        if path.is_dir():
            raise said_error(GraphplanError, "fl folder", str(path), None, what=_what(what))
        if not (path.is_file() or path.is_fifo()):          # a pipe (/dev/stdin, <(…)) ends
            raise said_error(GraphplanError, "fl not regular", str(path), None, what=_what(what))
        with open(path, "rb") as handle:
            data = handle.read(limit + 1)
    except OSError as exc:
        raise said_error(GraphplanError, "fl cannot read", str(path), None, what=_what(what),
                         why=_why(exc)) from None
    if len(data) > limit:
        raise said_error(GraphplanError, "fl too large", str(path), None, what=_what(what),
                         mb=limit // (1024 * 1024))
    return data


def read_text(path: str | Path, what: str, limit: int = MAX_INPUT_BYTES) -> str:
    """A text file's contents (UTF-8, a BOM dropped), or one clear line naming the file."""
    data = read_bytes(path, what, limit)
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        raise said_error(GraphplanError, "fl not utf8", str(path), None, what=_what(what), utf="UTF-8",
                         byte=exc.start) from None


def write_atomic(path: str | Path, data: bytes | str) -> Path:
    """Write ``data`` to ``path`` so that no half-written file is ever left behind."""
    path = Path(path)
    payload = data.encode("utf-8") if isinstance(data, str) else data
    folder = path.parent if str(path.parent) else Path(".")
    try:
        if path.is_dir():
            raise said_error(GraphplanError, "fl write folder", str(path), None)
        for parent in (folder, *folder.parents):      # the nearest existing ancestor must be a folder
            if parent.exists():
                if not parent.is_dir():
                    raise said_error(GraphplanError, "fl write not folder", str(path), None, parent=parent)
                break
        folder.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".part", dir=folder)
    except OSError as exc:
        raise said_error(GraphplanError, "fl cannot write", str(path), None, why=_why(exc)) from None
    try:
        with os.fdopen(fd, "wb") as handle:
            handle.write(payload)
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(tmp, 0o666 & ~umask)          # an ordinary file, not mkstemp's private one
        os.replace(tmp, path)
    except OSError as exc:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise said_error(GraphplanError, "fl cannot write", str(path), None, why=_why(exc)) from None
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise
    return path
