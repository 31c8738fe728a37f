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
from collections.abc import Iterator

from strips_framework.errors import InputError
from strips_framework.user_files import MAX_NESTING

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
                    raise self._extra(match.start()) or self.error(
                        node, "expected the end of the file after '(define ...)'"
                    )
                else:
                    top = node
                stack.append(node)
                if len(stack) > MAX_NESTING:
                    raise self.error(node, f"lists nested deeper than {MAX_NESTING} levels")
            elif token == ")":
                if not stack:
                    raise self._extra(match.start()) or self.error(match.start(), "unbalanced ')'")
                stack.pop()
            elif token[0] == ";":
                continue
            elif stack:
                stack[-1].append(token)
            elif top is not None:
                raise self._extra(match.start()) or self.error(
                    match.start(), f"expected the end of the file after '(define ...)', found {token!r}"
                )
            else:
                raise self.error(match.start(), f"expected '(define ...)', found {token!r}")
        if stack:
            raise self._unclosed() or self.error(stack[-1], "this '(' is never closed")
        if top is None:
            raise InputError(self.path, None, None, "expected '(define ...)', the file is empty")
        return top

    # --- where a missing or extra parenthesis probably is -----------------------------
    #
    # When the parentheses do not balance, the place the parser notices (the end of the
    # file, or text after the closing of '(define') is rarely the place of the mistake.
    # Indentation usually tells, as it does a reader: a line indented no deeper than the
    # line that opened a list, yet inside that list, says the list should have been
    # closed before it; a line indented deeper than the line that opened a list just
    # closed says that ')' came too early. Only consulted once the file is known to be
    # unbalanced, and only for lists inside the top-level one.

    def _lines(self) -> Iterator[tuple[int, int, str, int, bool]]:
        """``(offset, line, token, indentation, first on its line)`` for each token."""
        text = self.text
        last_line = 0
        for match in _TOKEN.finditer(text):
            token = match.group()
            if token[0] == ";":
                continue
            line, _ = self.position(match.start())
            start = self._line_starts[line - 1]  # type: ignore[index]
            before = text[start : match.start()]
            first = line != last_line and not before.strip()
            yield match.start(), line, token, len(before.expandtabs(8)), first
            last_line = line

    def _unclosed(self) -> InputError | None:
        """The innermost open list that a later line, indented no deeper than the list's
        own first line, lies inside."""
        indents: dict[int, int] = {}
        stack: list[tuple[int, int]] = []  # (offset, line) of each open list
        for offset, line, token, indent, first in self._lines():
            indents.setdefault(line, indent)
            if first and token != ")":
                for open_offset, open_line in reversed(stack[1:]):
                    if open_line < line and indents[open_line] >= indent:
                        return self.error(
                            open_offset,
                            f"this '(' is not closed before line {line}, which is indented "
                            "as if outside it",
                        )
            if token == "(":
                stack.append((offset, line))
            elif token == ")" and stack:
                stack.pop()
        return None

    def _extra(self, failed_at: int) -> InputError | None:
        """The first ')' before ``failed_at`` after which the next line is indented deeper
        than the line that opened the list it closed (and that list was not opened on its
        parent's line, where the next line may belong to the parent). The first: the lines
        after the mistake are all out of place."""
        indents: dict[int, int] = {}
        stack: list[int] = []  # the line of each open list
        pending: list[tuple[int, int, int]] = []  # closes since the last line began
        suspect: tuple[int, int] | None = None
        for offset, line, token, indent, first in self._lines():
            if offset >= failed_at:
                break
            indents.setdefault(line, indent)
            if first and token != ")":
                for close_offset, open_line, parent_line in pending:
                    if indent > indents[open_line] and open_line != parent_line:
                        suspect = suspect or (close_offset, open_line)
            if first:
                pending = []
            if token == "(":
                stack.append(line)
            elif token == ")" and stack:
                open_line = stack.pop()
                if stack:
                    pending.append((offset, open_line, stack[-1]))
        if suspect is None:
            return None
        offset, open_line = suspect
        return self.error(
            offset,
            f"this ')' closes the '(' of line {open_line} too early: the next line is "
            "indented as if inside it (an extra ')'?)",
        )
