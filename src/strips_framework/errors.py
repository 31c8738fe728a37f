"""Errors a user can cause, reported without a traceback."""

from __future__ import annotations


class StripsError(Exception):
    """Base of every error the CLI reports as a one-line message."""


class InputError(StripsError):
    """Bad input: names the file, line and column, and what was expected there."""

    def __init__(self, path: str, line: int, column: int | None, message: str) -> None:
        self.path, self.line, self.column, self.message = path, line, column, message
        where = f"{path}:{line}" + (f":{column}" if column else "")
        super().__init__(f"{where}: {message}")


class ConfigError(StripsError):
    """A config key or value that is wrong; the message names the key path."""


class PluginError(StripsError):
    """An unknown or duplicate implementation name."""
