"""Allocator tuning for long vectorised runs.

glibc gives the top of its heap back to the operating system once more than 128 KB are free, and
takes it again — page by page — on the next allocation. numpy's temporaries for a few thousand crank
angles cross that line on nearly every operation, and the solver then spends most of its time in
page faults (measured: 3600 shaper positions 1.3 ms, 0.4–0.55 ms with the freed memory kept).
The program keeps freed memory; nothing else changes.
"""
from __future__ import annotations

import ctypes
import sys

M_TRIM_THRESHOLD = -1   # glibc <malloc.h>
M_MMAP_THRESHOLD = -3


def keep_freed_memory(trim: int = 256 << 20, mmap: int = 32 << 20) -> bool:
    """Raise glibc's trim and mmap thresholds (Linux only); True when applied."""
    if not sys.platform.startswith("linux"):
        return False
    try:
        libc = ctypes.CDLL("libc.so.6")
        return bool(libc.mallopt(M_TRIM_THRESHOLD, trim)) and bool(libc.mallopt(M_MMAP_THRESHOLD, mmap))
    except (OSError, AttributeError):
        return False


GC_THRESHOLDS = (20000, 20, 10)   # the cyclic collector's (Python's default: 700, 10, 10)


def collect_less_often(thresholds: tuple[int, int, int] = GC_THRESHOLDS) -> None:
    """The cyclic garbage collector run less often: a sheet's composition keeps hundreds of
    thousands of small objects alive (its drawings, the label placements remembered), which every
    collection of the oldest generation walks again; measured (stop 52): a numbered shaper
    kinematics sheet spent 0.36 s of 7.7 s of CPU collecting, 0.08 s so — a test worker holding the
    examples' sheets 1.9 s of 34. The program makes few reference cycles; nothing it computes
    depends on when they are freed."""
    import gc
    gc.set_threshold(*thresholds)
