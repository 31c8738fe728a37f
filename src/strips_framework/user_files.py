"""Reading and writing the user's files: text that must be UTF-8, TOML, the nesting depth
every parser allows, and result files written whole or not at all. Each failure is an
:class:`~strips_framework.errors.InputError` naming the file and, where there is one, the
line and column (a bad byte, a TOML syntax error, the parenthesis that nests too deep),
never a traceback.
"""

from __future__ import annotations

import contextlib
import os
import re
import sys
from collections.abc import Mapping
from pathlib import Path
from typing import Any

from strips_framework.errors import InputError

#: How deep parentheses, brackets, negations and terms may nest in any input. The parsers
#: refuse deeper input with a clean error at the opening that goes too deep: beyond the
#: parsers, clause form, grounding, unification and printing recurse once or more per
#: level on Python's stack (1000 frames by default), and no hand-written or generated
#: planning input comes near this depth.
MAX_NESTING = 100

_TOML_POSITION = re.compile(r"\s*\(at (?:line (\d+), column (\d+)|end of document)\)$")
_DIGITS = re.compile(r"[0-9][0-9_]*")


def is_file(path: Path) -> bool:
    """``path.is_file()``, false (not an exception) for names the system refuses: too
    long, or with a NUL byte."""
    try:
        return path.is_file()
    except (OSError, ValueError):
        return False


def read_text(path: Path, what: str = "the file") -> str:
    """The file's text, decoded as UTF-8; a bad byte is reported at its line and column."""
    try:
        data = path.read_bytes()
    except IsADirectoryError:
        raise InputError(str(path), None, None, f"is a folder, not {what}") from None
    except (OSError, ValueError) as error:
        reason = getattr(error, "strerror", None) or str(error)
        raise InputError(str(path), None, None, f"cannot read {what}: {reason}") from None
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as error:
        before = data[: error.start].decode("utf-8")  # the bytes before it are good
        line, column = _position(before, len(before))
        byte = data[error.start : error.start + 1].hex()
        message = f"{what} is not UTF-8 text: byte 0x{byte} ({error.reason})"
        raise InputError(str(path), line, column, message) from None


def read_toml(path: Path, what: str) -> dict[str, Any]:
    """The TOML file at ``path`` as a dict; syntax errors give their line and column."""
    return _parse_toml(read_text(path, what), path)


def read_toml_with_keys(path: Path, what: str) -> tuple[dict[str, Any], KeyLines]:
    """:func:`read_toml`, and where each key is written (for errors about values)."""
    text = read_text(path, what)
    return _parse_toml(text, path), KeyLines(str(path), key_lines(text))


def _parse_toml(text: str, path: Path) -> dict[str, Any]:
    import tomllib  # not at the top: a run without a config file does not pay for it

    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as error:
        message = str(error)
        position = _TOML_POSITION.search(message)
        line, column = _position(text, len(text))  # "(at end of document)"
        if position is not None:
            if position.group(1):
                line, column = int(position.group(1)), int(position.group(2))
            message = message[: position.start()]
        raise InputError(str(path), line, column, f"not valid TOML: {message}") from None
    except RecursionError:
        line, column = _deepest_opening(text)
        message = f"not valid TOML: arrays or inline tables nested deeper than {MAX_NESTING}"
        raise InputError(str(path), line, column, message) from None
    except ValueError:  # an integer longer than Python converts (sys.int_info)
        limit = sys.get_int_max_str_digits()
        long = [m.start() for m in _DIGITS.finditer(text) if len(m.group()) > limit]
        line, column = _position(text, long[0]) if long else (None, None)
        message = f"not valid TOML: an integer of more than {limit} digits"
        raise InputError(str(path), line, column, message) from None


_TABLE_HEADER = re.compile(r"\s*\[\[?([^\]\[]+)\]\]?\s*(?:#.*)?$")
_KEY_VALUE = re.compile(r"\s*((?:[\w-]+|\"[^\"]*\"|'[^']*')(?:\s*\.\s*(?:[\w-]+|\"[^\"]*\"|'[^']*'))*)\s*=")
_INLINE_KEY = re.compile(r"[{,]\s*([\w-]+)\s*=")


def key_lines(text: str) -> dict[str, int]:
    """The line on which each dotted key path of a TOML text is first written: table
    headers, ``key = value`` lines (dotted keys too) and the keys of one-line inline
    tables. tomllib returns values without positions; this is only used to point an
    error about a value at its line, so keys inside multi-line arrays are not sought."""
    lines: dict[str, int] = {}
    table = ""
    for number, line in enumerate(text.splitlines(), 1):
        header = _TABLE_HEADER.match(line)
        if header:
            table = _dotted(header.group(1))
            lines.setdefault(table, number)
            continue
        pair = _KEY_VALUE.match(line)
        if pair:
            key = ".".join(filter(None, (table, _dotted(pair.group(1)))))
            lines.setdefault(key, number)
            for inner in _INLINE_KEY.finditer(line, pair.end()):
                lines.setdefault(f"{key}.{inner.group(1)}", number)
    return lines


def _dotted(key: str) -> str:
    return ".".join(part.strip().strip("\"'") for part in key.split("."))


class KeyLines:
    """Where the keys of one TOML file are written, for error messages: ``at(key)`` is
    ``file:line`` of the key, or of the nearest table around it that the file writes, or
    the file alone (a default has no line). ``prefix`` locates a table nested in the file
    (a bench matrix's ``configs.NAME``, named after the location); ``str()`` is the file's
    name (and that table's)."""

    __slots__ = ("lines", "path", "prefix")

    def __init__(self, path: str, lines: Mapping[str, int] | None = None, prefix: str = "") -> None:
        self.path, self.lines, self.prefix = path, lines or {}, prefix

    def at(self, key: str) -> str:
        full = ".".join(filter(None, (self.prefix, key)))
        while full and full not in self.lines:
            full = full.rpartition(".")[0]
        line = f":{self.lines[full]}" if full else ""
        return f"{self.path}{line}{self._table()}"

    def _table(self) -> str:
        return f": '{self.prefix}'" if self.prefix else ""

    def within(self, prefix: str) -> KeyLines:
        """The same file, with keys looked up under the table ``prefix``."""
        return KeyLines(self.path, self.lines, ".".join(filter(None, (self.prefix, prefix))))

    def __str__(self) -> str:
        return self.path + self._table()

    def __repr__(self) -> str:
        return f"KeyLines({self.path!r}, prefix={self.prefix!r})"

    def __eq__(self, other: object) -> bool:
        return isinstance(other, KeyLines) and (self.path, self.prefix) == (other.path, other.prefix)

    def __hash__(self) -> int:
        return hash((self.path, self.prefix))


def _position(text: str, offset: int) -> tuple[int, int]:
    """The 1-based line and column of ``offset`` in ``text``."""
    return text.count("\n", 0, offset) + 1, offset - (text.rfind("\n", 0, offset) + 1) + 1


def _deepest_opening(text: str) -> tuple[int, int]:
    """Where ``[`` / ``{`` first nest deeper than :data:`MAX_NESTING` (strings and comments
    are not told apart: this only places an error tomllib has already found)."""
    depth = 0
    for offset, char in enumerate(text):
        if char in "[{":
            depth += 1
            if depth > MAX_NESTING:
                return _position(text, offset)
        elif char in "]}":
            depth -= 1
    return 1, 1


def check_writable(path: Path, what: str) -> None:
    """Fail now, not after a long search, if ``path`` cannot be written: its folder is
    missing or not a folder, or the path is a folder."""
    folder = path.parent
    try:
        ok = folder.is_dir() and not path.is_dir() and os.access(folder, os.W_OK)
    except (OSError, ValueError):
        ok = False
    if not ok:
        reason = "is a folder" if is_dir(path) else f"cannot write into {folder}"
        raise InputError(str(path), None, None, f"cannot write {what}: {reason}")


def is_dir(path: Path) -> bool:
    try:
        return path.is_dir()
    except (OSError, ValueError):
        return False


def write_atomically(path: Path, text: str, what: str = "the file") -> None:
    """Write ``text`` to ``path`` through a temporary file in the same folder, renamed over
    it: a reader (or an interrupted run) sees the old file or the new one, never half. A
    path that cannot be written (no such folder, no permission, a folder, ``/proc``) is an
    :class:`InputError` naming it and ``what`` it was for."""
    import tempfile  # with random, shutil, bz2, lzma: only runs that write a file pay

    try:
        handle, temporary = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
    except OSError as error:
        raise InputError(str(path), None, None, f"cannot write {what}: {error.strerror}") from None
    try:
        with os.fdopen(handle, "w", encoding="utf-8") as file:
            file.write(text)
        os.replace(temporary, path)
    except BaseException as error:
        with contextlib.suppress(FileNotFoundError):
            os.unlink(temporary)
        if isinstance(error, OSError):
            raise InputError(str(path), None, None, f"cannot write {what}: {error.strerror}") from None
        raise
