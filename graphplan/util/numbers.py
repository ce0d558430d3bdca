"""Numbers as a draftsman writes them on a sheet: significant figures in fixed notation (18200, 4.49,
0.0153, 0.00007146), a true minus, never e-notation."""
from __future__ import annotations

import math


def number(v: float | None, sig: int = 4, minus: str = "−") -> str:
    """``v`` to ``sig`` significant figures in fixed notation; "—" for none; "0" for zero."""
    if v is None or not math.isfinite(v):
        return "—"
    if v == 0:
        return "0"
    mag = math.floor(math.log10(abs(v)))
    decimals = max(0, sig - 1 - mag)
    if decimals == 0:
        text = f"{round(v, sig - 1 - mag):.0f}"
    else:
        text = f"{v:.{decimals}f}"
        if "." in text:
            text = text.rstrip("0").rstrip(".")
    if text in ("-0", "0", ""):
        return "0"
    return text.replace("-", minus)


def plain(v: float) -> str:
    """A scale coefficient or a tick value as it is (0.0025, 10000, 0.00007146): up to 10
    significant figures, fixed notation, an ASCII minus."""
    return number(v, 10, "-")
