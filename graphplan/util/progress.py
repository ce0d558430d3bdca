"""One progress bar on stderr for long batches (keys, bench): ``[#####-----] k/total label``, drawn
only on a terminal (or when asked), with diagnostics printed above it."""
from __future__ import annotations

import sys
from collections.abc import Iterable, Iterator
from typing import TextIO, TypeVar

T = TypeVar("T")


class Progress:
    """A one-line bar: ``step(label)`` redraws it, ``advance()`` counts one item done, ``message``
    prints a diagnostic line (always) above the bar, ``close()`` ends the line."""

    def __init__(self, total: int, enabled: bool | None = None, stream: TextIO | None = None,
                 width: int = 24, done: str = "done"):
        self.stream = stream or sys.stderr
        self.enabled = self.stream.isatty() if enabled is None else enabled
        self.total, self.width, self.done = total, width, done
        self.done_count = 0
        self.shown = False

    def step(self, label: str) -> None:
        if not self.enabled:
            return
        filled = self.width * self.done_count // max(self.total, 1)
        bar = "#" * filled + "-" * (self.width - filled)
        self.stream.write(f"\r[{bar}] {self.done_count}/{self.total} {label[:30]:<30}")
        self.stream.flush()
        self.shown = True

    def advance(self) -> None:
        self.done_count += 1

    def message(self, text: str) -> None:
        """A diagnostic line (always shown), printed above the bar."""
        if self.shown:
            self.stream.write("\r" + " " * (self.width + 45) + "\r")
        self.stream.write(text + "\n")
        self.stream.flush()

    def close(self) -> None:
        if self.enabled and self.shown:
            self.step(self.done)
            self.stream.write("\n")
            self.stream.flush()


def progress(items: Iterable[T], total: int, label: str, enabled: bool | None = None,
             done: str = "done") -> Iterator[T]:
    """Yield the items while the bar counts them (``label`` and the item's number; ``done`` the
    last label, in the reader's language)."""
    bar = Progress(total, enabled, done=done)
    for k, item in enumerate(items):
        bar.step(f"{label} {k + 1}")
        yield item
        bar.advance()
    bar.close()
