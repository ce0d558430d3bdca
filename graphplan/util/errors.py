"""Errors a user can cause. The command line turns them into one line and exit code 2."""
from __future__ import annotations


class GraphplanError(Exception):
    """Bad input: a scene, an option or a geometry that cannot be assembled.

    The message is a single line that names the file, the key or part and,
    for geometry, the crank-angle range where it fails.
    """

    def __init__(self, message: str, where: str | None = None):
        self.where = where
        super().__init__(message)

    def line(self) -> str:
        text = " ".join(str(self).split())
        return f"{self.where}: {text}" if self.where else text


class SceneError(GraphplanError):
    """A scene file that is malformed or describes an impossible mechanism."""


class AssemblyError(SceneError):
    """A dyad that cannot be assembled over part of the crank's turn."""
