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


def read_text(path: str | Path, what: str) -> str:
    """A text file's contents (UTF-8, a BOM dropped), or one clear line naming the file."""
    try:
        return Path(path).read_text(encoding="utf-8-sig")
    except FileNotFoundError:
        raise GraphplanError(f"no such {what}", str(path)) from None
    except (OSError, UnicodeDecodeError) as exc:
        raise GraphplanError(f"cannot read the {what}: {exc}", str(path)) from None


def write_atomic(path: str | Path, data: bytes | str) -> Path:
    """Write ``data`` to ``path`` so that no half-written file is ever left behind."""
    path = Path(path)
    payload = data.encode("utf-8") if isinstance(data, str) else data
    folder = path.parent if str(path.parent) else Path(".")
    try:
        folder.mkdir(parents=True, exist_ok=True)
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
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise
    return path
