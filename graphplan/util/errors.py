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
        return f"{self.where}: {text}" if self.where else text


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
