"""The small typesetting markup of the lab's notation: sub- and superscripts in drawn text.

``a^τ_BA`` is a with τ above and BA below (stacked, as the lab writes it); ``p_v``, ``μ_l``,
``M_зр``, ``R^n_34``, ``W = 3n − 2p_5 − p_4``. After ``_`` (subscript) or ``^`` (superscript)
comes either a ``{group}``, a run of letters and digits or a single ``*`` (``M^*_с``, the reduced
quantity's star); ``\\_``, ``\\^``, ``\\{``, ``\\}`` and
``\\\\`` are the characters themselves (``escape`` makes any name from a scene literal). A
superscript directly followed by a subscript (or the other way round) is stacked over it. A subscript
group may hold a subscript of its own, the lab's a^n_{BO₂}: ``v_{O_2}`` sets O at level −1 and its 2 at
level −2 (as small as the index, its baseline lower by the index's own drop).

Renderers read ``runs``; the terminal reads ``plain``. Plain data and tiny functions.
"""
from __future__ import annotations

from dataclasses import dataclass

SMALL = 0.7        # the size of a sub- or superscript relative to its text
SUB_SHIFT = 0.3    # how far a subscript's baseline drops, in the text's height
SUP_SHIFT = 0.45   # how far a superscript's baseline rises, in the text's height
_SPECIAL = "_^{}\\"


def baseline_shift(level: int, size: float) -> float:
    """How far a run's baseline lies above the text's (mm, + up) at letter height ``size``: a
    subscript SUB_SHIFT down, a superscript SUP_SHIFT up, a subscript's subscript (level −2) lower
    again by the index's own drop (SUB_SHIFT of its SMALL height)."""
    return {0: 0.0, -1: -SUB_SHIFT * size, -2: -SUB_SHIFT * (1.0 + SMALL) * size, 1: SUP_SHIFT * size}[level]


@dataclass(frozen=True)
class Run:
    """A piece of text on one level: 0 the line, −1 a subscript, −2 a subscript's subscript, +1 a superscript. ``stacked``: it
    starts where the previous run (the other script of the same base) started."""
    text: str
    level: int = 0
    stacked: bool = False


def escape(text: str) -> str:
    """``text`` with the markup characters made literal (names, titles and files from a scene)."""
    return "".join("\\" + c if c in _SPECIAL else c for c in text)


def _word_char(c: str) -> bool:
    return c.isalnum() or c in "'′"


def runs(text: str) -> list[Run]:
    """The text split into runs of one level (see the module's docstring)."""
    out: list[Run] = []
    base: list[str] = []
    i, n = 0, len(text)

    def flush() -> None:
        if base:
            out.append(Run("".join(base)))
            base.clear()

    while i < n:
        c = text[i]
        if c == "\\" and i + 1 < n and text[i + 1] in _SPECIAL:
            base.append(text[i + 1])
            i += 2
            continue
        if c in "_^" and i + 1 < n:
            if text[i + 1] == "{":
                end = text.find("}", i + 2)
                if end < 0:
                    base.append(c)
                    i += 1
                    continue
                body, i = text[i + 2:end], end + 1
            elif text[i + 1] == "*":            # M^*_с: the reduced quantity's star
                body, i = "*", i + 2
            elif _word_char(text[i + 1]):
                j = i + 1
                while j < n and _word_char(text[j]):
                    j += 1
                body, i = text[i + 1:j], j
            else:
                base.append(c)
                i += 1
                continue
            flush()
            level = -1 if c == "_" else 1
            prev = out[-1] if out else None
            stacked = prev is not None and prev.level == -level and not prev.stacked
            if level == -1 and "_" in body and not is_plain(body):     # v_{O_2}: O₂ an index's index
                for k, r in enumerate(runs(body)):    # h_{Φ3,P_B}: Φ₃'s digit an index's index too
                    if r.level == 0 and r.text[:1].isalpha() and any(ch.isdigit() for ch in r.text):
                        out.extend(_sub_digits(r.text, stacked and k == 0))
                    else:
                        out.append(Run(r.text, -2 if r.level < 0 else -1, stacked and k == 0))
            elif level < 0 and body[:1].isalpha() and any(ch.isdigit() for ch in body):
                out.extend(_sub_digits(body, stacked))
            else:
                out.append(Run(body, level, stacked))
            continue
        base.append(c)
        i += 1
    flush()
    return out


def _sub_digits(body: str, stacked: bool) -> list[Run]:
    """A subscript that starts with a letter split so its digits after a letter sit one level
    lower, a subscript inside the subscript as the lab writes it: a^n_BO2 → a^n_{BO₂}, v_S2 →
    v_{S₂}, l_O1A → l_{O₁A}; an all-digit subscript (R_05, H_1) stays one subscript."""
    levels = []
    for k, ch in enumerate(body):
        levels.append(-2 if ch.isdigit() and k and (body[k - 1].isalpha() or levels[-1] == -2) else -1)
    out: list[Run] = []
    k = 0
    while k < len(body):
        j = k + 1
        while j < len(body) and levels[j] == levels[k]:
            j += 1
        out.append(Run(body[k:j], levels[k], stacked and not out))
        k = j
    return out


def indexed(name: str) -> str:
    """A point's name with its number as a subscript: S4 → S_4, O1 → O_1, s3 → s_3, B → B."""
    head = name.rstrip("0123456789")
    return f"{escape(head)}_{name[len(head):]}" if head and head != name else escape(name)


def subscripted(name: str) -> str:
    """A link's or a segment's name with each number after a letter as a subscript, as the
    drawing letters its points: O3E → O_{3}E, O2B → O_{2}B, AB → AB, 4 → 4 (review 12: the notes
    wrote «O3E» where Table 4 writes O₃E)."""
    import re
    parts = re.split(r"(?<=[A-Za-z])(\d+)", name)
    return "".join(escape(p) if k % 2 == 0 else f"_{{{p}}}" for k, p in enumerate(parts))


def is_plain(text: str) -> bool:
    """No markup at all (the renderers' fast path)."""
    return not any(c in text for c in _SPECIAL)


_SUB = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")
_SUP = str.maketrans("0123456789nk-*", "⁰¹²³⁴⁵⁶⁷⁸⁹ⁿᵏ⁻*")


def plain(text: str) -> str:
    """The text for a terminal: digits and n, k as Unicode sub-/superscripts (p₅, aⁿ), a
    superscript star in line (M*_с), the rest written with _ and ^ (a^τ_BA, M_зр); braces and
    escapes gone."""
    if is_plain(text):
        return text
    parts = []
    level = 0
    for r in runs(text):
        if r.level == 0:
            parts.append(r.text)
        elif r.level < 0:
            parts.append(r.text.translate(_SUB) if r.text.isdigit() else
                         ("" if level < 0 else "_") + r.text)
        else:
            ok = all(c in "0123456789nk-*" for c in r.text)
            parts.append(r.text.translate(_SUP) if ok else "^" + r.text)
        level = r.level
    return "".join(parts)


def inline(text: str) -> str:
    """The text for a terminal line written as its neighbours are (ψmax, I*м, ω₁): digits as
    Unicode sub-/superscripts, the star in line, any other sub- or superscript written in line
    without its marker (``ψ_{max}`` → ψmax, ``I^*_м`` → I*м, ``ω_{m дв}`` → ωm дв);
    braces and escapes gone — no raw ``_``, ``^`` or ``{``."""
    if is_plain(text):
        return text
    parts = []
    for r in runs(text):
        if r.level == 0:
            parts.append(r.text)
        elif r.text.isdigit():
            parts.append(r.text.translate(_SUB if r.level < 0 else _SUP))
        else:
            parts.append(r.text)
    return "".join(parts)


def flat(text: str) -> str:
    """The characters that are drawn, in order (for widths and searching)."""
    return "".join(r.text for r in runs(text)) if not is_plain(text) else text


def split(text: str) -> list[str]:
    """The text's words: split at spaces outside ``{groups}`` (``M^*_{с max}`` stays one word) and
    not at a no-break space, for wrapping a line of markup without breaking a group."""
    out, cur, depth = [], [], 0
    for i, c in enumerate(text):
        escaped = i > 0 and text[i - 1] == "\\"
        if c == "{" and not escaped:
            depth += 1
        elif c == "}" and not escaped and depth:
            depth -= 1
        if c.isspace() and c != "\u00a0" and depth == 0:      # a no-break space keeps "гр. МБ-21" whole
            if cur:
                out.append("".join(cur))
                cur = []
            continue
        cur.append(c)
    if cur:
        out.append("".join(cur))
    return out
