"""Errors a user can cause, reported without a traceback."""

from __future__ import annotations

from collections.abc import Iterable


class StripsError(Exception):
    """Base of every error the CLI reports as a one-line message."""


class InputError(StripsError):
    """Bad input: names the file, line and column, and what was expected there.

    ``line`` is ``None`` for a problem with the file as a whole (missing, unreadable).
    """

    def __init__(self, path: str, line: int | None, column: int | None, message: str) -> None:
        self.path, self.line, self.column, self.message = path, line, column, message
        where = path + (f":{line}" if line else "") + (f":{column}" if line and column else "")
        super().__init__(f"{where}: {message}")


class ConfigError(StripsError):
    """A config key or value that is wrong; the message names the key path."""


class PluginError(StripsError):
    """An unknown or duplicate implementation name."""


def did_you_mean(word: str, known: Iterable[str]) -> str:
    """``; did you mean 'x'?`` for the known word closest to a misspelled one, else ``""``."""
    import difflib  # only on the way to an error message

    close = difflib.get_close_matches(word, list(known), n=1)
    return f"; did you mean '{close[0]}'?" if close else ""
