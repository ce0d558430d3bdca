"""A small progress bar on stderr for long batches (keys, bench); silent when stderr is not a terminal."""
from __future__ import annotations

import sys
import time
from collections.abc import Iterable, Iterator
from typing import TypeVar

T = TypeVar("T")


def progress(items: Iterable[T], total: int, label: str, enabled: bool | None = None) -> Iterator[T]:
    """Yield the items while drawing ``label [#####.....] k/total`` on stderr."""
    stream = sys.stderr
    show = stream.isatty() if enabled is None else enabled
    start = time.perf_counter()
    for k, item in enumerate(items):
        if show:
            _draw(stream, label, k, total, start)
        yield item
    if show:
        _draw(stream, label, total, total, start)
        stream.write("\n")
        stream.flush()


def _draw(stream, label: str, k: int, total: int, start: float) -> None:
    width = 30
    done = int(width * k / max(total, 1))
    elapsed = time.perf_counter() - start
    stream.write(f"\r{label} [{'#' * done}{'.' * (width - done)}] {k}/{total} {elapsed:5.1f} s")
    stream.flush()
