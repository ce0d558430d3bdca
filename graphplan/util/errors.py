"""Errors a user can cause. The command line turns them into one line and exit code 2."""
from __future__ import annotations


class GraphplanError(Exception):
    """Bad input: a scene, an option or a geometry that cannot be assembled.

    The message is a single line that names the file, the key or part and,
    for geometry, the crank-angle range where it fails.
    """

    def __init__(self, message: str, where: str | None = None, said: dict[str, str] | None = None,
                 lang: str | None = None):
        self.where = where
        self.said = said or {}      # the message in each language (util.words.said); ``message`` its English
        self.lang = lang            # the scene's language: what ``line`` speaks unless told
        super().__init__(message)

    def line(self, lang: str | None = None) -> str:
        """The one line to print, in ``lang`` where the error says itself in both languages (else,
        and without ``lang``, its message as raised)."""
        text = self.said.get(lang, str(self)) if lang else str(self)
        text = " ".join(text.split())
        where = self.where.said.get(lang, self.where) if isinstance(self.where, Where) and lang else self.where
        return f"{where}: {text}" if where else text


class Where(str):
    """A refusal's place that says itself in each language ("variants.csv: variant v3" — "…: варіант
    v3"): a ``str`` (its English) wherever a place is used as text, ``said`` for ``line``."""

    said: dict[str, str]

    def __new__(cls, texts: dict[str, str]):
        obj = super().__new__(cls, texts["en"])
        obj.said = dict(texts)
        return obj

    def __reduce__(self):
        return (Where, (self.said,))


def where_said(key: str, /, **fields: object) -> Where:
    """A place worded by the catalogue (util.words ``key``) in both languages."""
    from graphplan.util.words import said
    return Where(said(key, **fields))


def said_error(cls: type[GraphplanError], key: str, where: str | None, lang: str | None, /, **fields) -> GraphplanError:
    """An error of ``cls`` worded by the catalogue (util.words ``key``) in both languages: English
    as its message, the scene's ``lang`` the one its line speaks."""
    from graphplan.util.words import said
    texts = said(key, **fields)
    return cls(texts["en"], where, texts, lang)


def keyed_error(cls: type[GraphplanError], where: str | None, key: str, word: str, lang: str | None = None, /,
                **fields) -> GraphplanError:
    """An error of ``cls`` about the scene key ``key`` (written as the file has it, in either language),
    worded by the catalogue's ``word``: "key: text" in both languages."""
    from graphplan.util.words import said
    texts = {k: f"{key}: {v}" if key else v for k, v in said(word, **fields).items()}
    return cls(texts["en"], where, texts, lang)


class SaidValueError(ValueError):
    """A reason (a number that cannot be read, a bad cell) worded by the catalogue in both languages:
    ``str`` its English, ``said`` every language — what a caller puts into its own one line."""

    def __init__(self, key: str, /, **fields: object):
        from graphplan.util.words import said
        self.said = said(key, **fields)
        super().__init__(self.said["en"])


def reason(exc: BaseException) -> object:
    """``exc``'s text as a catalogue field: in each language where it says itself in both
    (SaidValueError, GraphplanError), else as it is."""
    texts = getattr(exc, "said", None) or {}

    def text(lang: str) -> str:
        if isinstance(exc, GraphplanError):
            return exc.line(lang)
        return texts.get(lang, str(exc))
    return text


def either(*options: str) -> object:
    """Choices for a refusal, "a, b or c" in each language ("a, b або c")."""
    def text(lang: str) -> str:
        last = " або " if lang == "uk" else " or "
        return ", ".join(options[:-1]) + last + options[-1] if len(options) > 1 else options[0]
    return text


def speaking(exc: GraphplanError, lang: object) -> GraphplanError:
    """``exc`` told the scene's language ``lang`` (when it is one, and the error has none yet): a
    loader that read a scene's ``lang`` lets every refusal from inside it speak that language."""
    if exc.lang is None and lang in ("uk", "en"):
        exc.lang = str(lang)
    return exc


def scenes_speaking(exc: GraphplanError, data: object) -> GraphplanError:
    """``exc`` told the language of the parsed scene ``data`` (its ``lang``; a tree that is not a
    table has none): what a scene's loader raises from inside it (``speaking``)."""
    return speaking(exc, data.get("lang") if isinstance(data, dict) else None)


class SceneError(GraphplanError):
    """A scene file that is malformed or describes an impossible mechanism."""


class AssemblyError(SceneError):
    """A dyad that cannot be assembled over part of the crank's turn."""
