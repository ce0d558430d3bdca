"""Cyrillic of the scene in Latin letters for an English sheet: Ukraine's official romanisation
(the Cabinet of Ministers' resolution No. 55 of 27 January 2010, the one passports and papers use
for names of people and organisations).

An English sheet drawn from a Ukrainian scene letters the scene's own text (its designation, its
title, the [sheet] fields) in English where the scene gives an ``_en`` variant, else in these Latin
letters: «Рецензент Р. Р.» → «Retsenzent R. R.», «НУБіП України» → «NUBiP Ukrainy», «ТММ.КП.77.001»
→ «TMM.KP.77.001». A Ukrainian sheet letters the text as written (a Latin name on it is normal).

The table: А a, Б b, В v, Г h, Ґ g, Д d, Е e, Є ie, Ж zh, З z, И y, І i, Ї i, Й i, К k, Л l, М m,
Н n, О o, П p, Р r, С s, Т t, У u, Ф f, Х kh, Ц ts, Ч ch, Ш sh, Щ shch, Ь and the apostrophe dropped,
Ю iu, Я ia; at the start of a word Є ye, Ї yi, Й y, Ю yu, Я ya; «зг» is «zgh» (Згорани → Zghorany,
apart from «zh» of Ж). A capital letter's several Latin letters are capitalised as a word
(Щербак → Shcherbak), all in capitals inside a word of capitals longer than four letters (ЩЕРБАК →
SHCHERBAK; an abbreviation keeps the usual «KhPI»). Letters of other Cyrillic alphabets the
resolution does not name (Ы, Э, Ё, Ъ …) get their nearest Latin so that no Cyrillic is left."""
from __future__ import annotations

import re
import unicodedata

_LOWER = {"а": "a", "б": "b", "в": "v", "г": "h", "ґ": "g", "д": "d", "е": "e", "є": "ie", "ж": "zh", "з": "z",
          "и": "y", "і": "i", "ї": "i", "й": "i", "к": "k", "л": "l", "м": "m", "н": "n", "о": "o", "п": "p",
          "р": "r", "с": "s", "т": "t", "у": "u", "ф": "f", "х": "kh", "ц": "ts", "ч": "ch", "ш": "sh",
          "щ": "shch", "ь": "", "ю": "iu", "я": "ia",
          # not Ukrainian letters (a Russian or Belarusian word in a scene): the usual Latin
          "ы": "y", "э": "e", "ё": "io", "ъ": "", "ў": "u"}
_INITIAL = {"є": "ye", "ї": "yi", "й": "y", "ю": "yu", "я": "ya", "ё": "yo"}
_APOSTROPHES = "'’ʼ`"
_ABBREVIATION = 4          # a word of capitals this long or shorter is an abbreviation («ХПІ» → «KhPI»)


def is_cyrillic(c: str) -> bool:
    return "\u0400" <= c <= "\u052f" or "\u2de0" <= c <= "\u2dff" or "\ua640" <= c <= "\ua69f" or "\u1c80" <= c <= "\u1c8f"


def has_cyrillic(text: str) -> bool:
    """Whether ``text`` has a Cyrillic letter."""
    return any(is_cyrillic(c) for c in text)


def _fallback(c: str) -> str:
    """A Cyrillic letter the table does not name: the Latin of its Unicode name («CYRILLIC SMALL
    LETTER DJE» → «dj»), accents and marks dropped."""
    name = unicodedata.name(c, "")
    m = re.search(r"LETTER (?:SMALL |CAPITAL )?([A-Z]+)", name.replace("SMALL LETTER", "LETTER").replace(
        "CAPITAL LETTER", "LETTER"))
    if not m or "LETTER" not in name:
        return ""
    word = m.group(1).lower()
    word = {"short": "i", "hard": "", "soft": ""}.get(word, word)
    if len(word) > 2:                    # "ghe", "dje", "lje" …: the consonant's letters
        word = word[:-1] if word.endswith("e") else word
    return word


def _latin(c: str, initial: bool) -> str:
    low = c.lower()
    if initial and low in _INITIAL:
        return _INITIAL[low]
    if low in _LOWER:
        return _LOWER[low]
    if unicodedata.category(c) == "Mn":  # a combining mark over a Cyrillic letter
        return ""
    return _fallback(c)


def romanize(text: str) -> str:
    """``text`` with its Cyrillic in Latin letters by the resolution No. 55 of 2010; anything else
    (Latin, digits, signs) as it is."""
    if not has_cyrillic(text):
        return text
    out: list[str] = []
    n = len(text)
    i = 0
    while i < n:
        c = text[i]
        if c in _APOSTROPHES and out and i > 0 and is_cyrillic(text[i - 1]) and i + 1 < n and is_cyrillic(text[i + 1]):
            i += 1                                       # «Мар'яна» → «Mariana»: the apostrophe dropped
            continue
        if not is_cyrillic(c):
            out.append(c)
            i += 1
            continue
        prev = text[i - 1] if i else ""
        if prev in _APOSTROPHES and i > 1:
            prev = text[i - 2]
        initial = not (prev.isalpha())
        low = c.lower()
        if low == "г" and i and text[i - 1].lower() == "з":
            lat = "gh"                                   # «зг» → «zgh»
        else:
            lat = _latin(c, initial)
        if c != low and lat:                             # a capital
            j, k = i, i
            while j > 0 and text[j - 1].isalpha():
                j -= 1
            while k < n and text[k].isalpha():
                k += 1
            word = text[j:k]
            caps = word.isupper() and len(word) > _ABBREVIATION
            lat = lat.upper() if caps else lat[0].upper() + lat[1:]
        out.append(lat)
        i += 1
    return "".join(out)


def in_latin(text: str, lang: str) -> str:
    """The scene's ``text`` as a sheet in ``lang`` letters it: romanised on an English sheet, as
    written on a Ukrainian one."""
    return romanize(text) if lang == "en" else text


def scene_text(meta: dict, key: str, lang: str, default: str = "") -> str:
    """A scene's own text (``title``, ``designation``, ``sheet.student`` …) in the sheet's language:
    on an English sheet its ``KEY_en`` variant where the scene gives one, else the text romanised
    (``romanize``; a Cyrillic letter typed into the ``_en`` variant is romanised too: nothing on an
    English sheet is Cyrillic); on a Ukrainian sheet the text as written."""
    if lang == "en":
        return romanize(meta.get(f"{key}_en") or meta.get(key, default) or default)
    return meta.get(key, default) or default


def scene_title(meta: dict, title: str, lang: str) -> str:
    """A scene's ``title`` in ``lang`` (the terminal's and the JSON's words as the sheets'): on an
    English sheet ``title_en`` where the scene gives it, else the title romanised."""
    if lang == "en":
        return romanize(meta.get("title_en") or title)
    return title
