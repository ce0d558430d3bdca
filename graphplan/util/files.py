"""Writing files whole or not at all: a temporary file in the same folder, then a rename."""
from __future__ import annotations

import json
import os
import tempfile
from pathlib import Path
from typing import Any

from graphplan.util.errors import GraphplanError


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
            raise GraphplanError(f"no such {what}", str(path))
        if path.is_dir():
            raise GraphplanError(f"the {what} is a folder, not a file", str(path))
        if not (path.is_file() or path.is_fifo()):          # a pipe (/dev/stdin, <(…)) ends
            raise GraphplanError(f"the {what} is not a regular file", str(path))
        with open(path, "rb") as handle:
            data = handle.read(limit + 1)
    except OSError as exc:
        raise GraphplanError(f"cannot read the {what}: {exc.strerror or exc}", str(path)) from None
    if len(data) > limit:
        raise GraphplanError(f"the {what} is larger than {limit // (1024 * 1024)} MB", str(path))
    return data


def read_text(path: str | Path, what: str, limit: int = MAX_INPUT_BYTES) -> str:
    """A text file's contents (UTF-8, a BOM dropped), or one clear line naming the file."""
    data = read_bytes(path, what, limit)
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        raise GraphplanError(f"cannot read the {what}: not UTF-8 text (byte {exc.start})",
                             str(path)) from None


def write_atomic(path: str | Path, data: bytes | str) -> Path:
    """Write ``data`` to ``path`` so that no half-written file is ever left behind."""
    path = Path(path)
    payload = data.encode("utf-8") if isinstance(data, str) else data
    folder = path.parent if str(path.parent) else Path(".")
    try:
        folder.mkdir(parents=True, exist_ok=True)
        if path.is_dir():
            raise GraphplanError("is a folder; name a file to write", str(path))
        for parent in (folder, *folder.parents):
            if parent.exists():
                if not parent.is_dir():
                    raise GraphplanError(f"cannot write: {parent} is not a folder", str(path))
                break
        fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".part", dir=folder)
    except OSError as exc:
        raise GraphplanError(f"cannot write: {exc.strerror or exc}", str(path)) from None
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
        raise GraphplanError(f"cannot write: {exc.strerror or exc}", str(path)) from None
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise
    return path
