"""Reading PDDL text into s-expressions that remember where they start.

PDDL is case-insensitive, so the whole text is lowercased once; comments (``;`` to the end
of the line) are skipped by the tokenizer. A list is a :class:`Node` (a ``list`` that also
knows its offset in the text) and an atom is a plain ``str``: creating a few tens of
thousands of plain strings is what keeps reading a large IPC task fast, and an error about
an atom is reported at the list that holds it, which is nearly always on the same line.
"""

from __future__ import annotations

import re
from bisect import bisect_right

from strips_framework.errors import InputError
from strips_framework.input_files import MAX_NESTING

_TOKEN = re.compile(r";[^\n]*|[()]|[^\s();]+")


class Node(list[object]):
    """A parenthesized list; ``offset`` is the position of its ``(`` in the source text."""

    __slots__ = ("offset",)

    def __init__(self, offset: int) -> None:
        super().__init__()
        self.offset = offset


class Source:
    """A PDDL file's text, its name for messages, and a way to turn offsets into lines."""

    def __init__(self, text: str, path: str) -> None:
        self.text = text
        self.path = path
        self._line_starts: list[int] | None = None

    def position(self, offset: int) -> tuple[int, int]:
        """The 1-based line and column of ``offset``."""
        if self._line_starts is None:
            self._line_starts = [0] + [m.end() for m in re.finditer("\n", self.text)]
        line = bisect_right(self._line_starts, offset)
        return line, offset - self._line_starts[line - 1] + 1

    def error(self, where: Node | int, message: str) -> InputError:
        """An :class:`InputError` at a node (or a text offset)."""
        offset = where.offset if isinstance(where, Node) else where
        line, column = self.position(offset)
        return InputError(self.path, line, column, message)

    def read(self) -> Node:
        """The one top-level list of the file (``(define ...)``)."""
        stack: list[Node] = []
        top: Node | None = None
        for match in _TOKEN.finditer(self.text.lower()):
            token = match.group()
            if token == "(":
                node = Node(match.start())
                if stack:
                    stack[-1].append(node)
                elif top is not None:
                    raise self.error(node, "expected the end of the file after '(define ...)'")
                else:
                    top = node
                stack.append(node)
                if len(stack) > MAX_NESTING:
                    raise self.error(node, f"lists nested deeper than {MAX_NESTING} levels")
            elif token == ")":
                if not stack:
                    raise self.error(match.start(), "unbalanced ')'")
                stack.pop()
            elif token[0] == ";":
                continue
            elif stack:
                stack[-1].append(token)
            else:
                raise self.error(match.start(), f"expected '(define ...)', found {token!r}")
        if stack:
            raise self.error(stack[-1], "this '(' is never closed")
        if top is None:
            raise InputError(self.path, None, None, "expected '(define ...)', the file is empty")
        return top
