"""The structural PDDL parser's shared part: turning s-expressions (see :mod:`.sexpr`)
into typed lists, atoms and formulas, with checks. :mod:`.domain_file` and
:mod:`.problem_file` read the sections of the two kinds of file with it.

The parser is as loose as Fast Downward and pyperplan where IPC files are loose (any case, types
used without ``:typing``, ``object`` implicit, constants repeated as objects, any
requirement flag that changes nothing) and strict where looseness would give wrong plans:
what the planner cannot honour is an error saying ``not supported: ...``. Every error
names the file, the line and column, and what was expected there.
"""

from __future__ import annotations

import re
from collections.abc import Iterator

from strips_framework.pddl.formulas import (
    TRUE,
    And,
    Atom,
    Exists,
    Forall,
    Formula,
    Imply,
    Not,
    Or,
    Parameter,
)
from strips_framework.pddl.sexpr import Node, Source

#: Requirements whose features the planner does not have; asking for them is an error.
UNSUPPORTED_REQUIREMENTS = frozenset(
    {
        ":durative-actions",
        ":duration-inequalities",
        ":continuous-effects",
        ":timed-initial-literals",
        ":preferences",
        ":constraints",
        ":time",
    }
)
TOTAL_COST = "total-cost"


class Reader:
    """Parsing helpers shared by the domain and the problem: they know the source (for
    errors), the declared predicates (for arity checks) and the known objects."""

    def __init__(
        self,
        source: Source,
        predicates: dict[str, int],
        objects: set[str],
        types: frozenset[str] | None = None,
    ) -> None:
        self.source = source
        self.arities = predicates
        self.objects = objects
        #: The declared types (``object`` included); ``None`` while ``:types`` is read.
        self.types = types

    def error(self, where: Node | int, message: str) -> Exception:
        return self.source.error(where, message)

    def node(self, value: object, parent: Node, expected: str) -> Node:
        if not isinstance(value, Node):
            raise self.error(parent, f"expected {expected}, found {value!r}")
        return value

    def name(self, value: object, parent: Node, expected: str) -> str:
        if not isinstance(value, str) or value.startswith("?"):
            raise self.error(parent, f"expected {expected}, found {show_value(value)}")
        return value

    def requirements(self, node: Node) -> tuple[str, ...]:
        flags = tuple(self.name(flag, node, "a requirement flag") for flag in node[1:])
        for flag in flags:
            if flag in UNSUPPORTED_REQUIREMENTS:
                raise self.error(node, f"not supported: requirement {flag}")
        return flags

    def typed_list(self, node: Node, items: list[object], variables: bool) -> list[Parameter]:
        """``a b - t c - (either t1 t2) d``; names without a type are ``object``."""
        result: list[Parameter] = []
        pending: list[str] = []
        index = 0
        while index < len(items):
            item = items[index]
            if item == "-":
                if index + 1 >= len(items):
                    raise self.error(node, "expected a type after '-'")
                types = self.type_spec(items[index + 1], node)
                result.extend(Parameter(name, types) for name in pending)
                pending = []
                index += 2
                continue
            if not isinstance(item, str) or item.startswith("?") != variables:
                expected = "a variable (?name)" if variables else "a name"
                raise self.error(node, f"expected {expected}, found {show_value(item)}")
            pending.append(item)
            index += 1
        result.extend(Parameter(name) for name in pending)
        return result

    def type_spec(self, item: object, parent: Node) -> tuple[str, ...]:
        if isinstance(item, Node):
            if not item or item[0] != "either" or len(item) < 2:
                raise self.error(item, "expected a type name or (either type ...)")
            kinds = tuple(self.name(kind, item, "a type name") for kind in item[1:])
        else:
            kinds = (self.name(item, parent, "a type name"),)
        for kind in kinds:
            if self.types is not None and kind not in self.types:
                declared = ", ".join(sorted(self.types))
                where = item if isinstance(item, Node) else parent
                raise self.error(where, f"undeclared type {kind!r} (declared types: {declared})")
        return kinds

    def atom(self, node: Node, variables: frozenset[str]) -> Atom:
        head = node[0] if node else None
        predicate = self.name(head, node, "a predicate name")
        args = tuple(self.term(arg, node, variables) for arg in node[1:])
        arity = self.arities.get(predicate)
        if arity is None:
            raise self.error(node, f"undeclared predicate {predicate!r}")
        if arity != len(args):
            raise self.error(
                node, f"predicate {predicate!r} takes {arity} arguments, found {len(args)}"
            )
        return Atom(predicate, args)

    def term(self, value: object, parent: Node, variables: frozenset[str]) -> str:
        if not isinstance(value, str):
            raise self.error(parent, "expected a variable or an object, found a list")
        if value.startswith("?"):
            if value not in variables:
                raise self.error(parent, f"unknown variable {value}")
        elif value not in self.objects:
            raise self.error(parent, f"unknown object or constant {value!r}")
        return value

    def formula(self, value: object, parent: Node, variables: frozenset[str]) -> Formula:
        node = self.node(value, parent, "a formula in parentheses")
        if not node:
            return TRUE
        head = node[0]
        if head == "and":
            return And(tuple(self.formula(part, node, variables) for part in node[1:]))
        if head == "or":
            return Or(tuple(self.formula(part, node, variables) for part in node[1:]))
        if head == "not":
            self.arity(node, 1)
            return Not(self.formula(node[1], node, variables))
        if head == "imply":
            self.arity(node, 2)
            return Imply(
                self.formula(node[1], node, variables), self.formula(node[2], node, variables)
            )
        if head in ("exists", "forall"):
            self.arity(node, 2)
            params = tuple(
                self.typed_list(node, list(self.node(node[1], node, "a parameter list")), True)
            )
            inner = variables | {param.name for param in params}
            body = self.formula(node[2], node, inner)
            return Exists(params, body) if head == "exists" else Forall(params, body)
        if head == "=":
            self.arity(node, 2)
            return Atom(
                "=", (self.term(node[1], node, variables), self.term(node[2], node, variables))
            )
        if head in ("when", "preference") and head not in self.arities:
            raise self.error(node, f"not supported: '{head}' in a formula")
        if head in ("<", ">", "<=", ">="):
            raise self.error(node, "not supported: numeric conditions")
        return self.atom(node, variables)

    def arity(self, node: Node, count: int) -> None:
        if len(node) != count + 1:
            raise self.error(node, f"expected {count} argument(s) after {node[0]!r}")


def show_value(value: object) -> str:
    return "a list" if isinstance(value, Node) else repr(value)


def sections(reader: Reader, top: Node, kind: str, once: tuple[str, ...]) -> Iterator[Node]:
    """The ``(:section ...)`` lists after ``(define (kind name) ...)``; a section of
    ``once`` given again is an error (the later one must not silently win)."""
    seen: dict[str, Node] = {}
    for item in top[2:]:
        node = reader.node(item, top, f"a '(:section ...)' of the {kind}")
        if not node or not isinstance(node[0], str) or not node[0].startswith(":"):
            raise reader.error(node, f"expected a '(:section ...)' of the {kind}")
        key = node[0]
        if key in once and key in seen:
            line, _ = reader.source.position(seen[key].offset)
            raise reader.error(node, f"({key} ...) is given twice (first at line {line})")
        seen[key] = node
        yield node


def header(reader: Reader, top: Node, kind: str) -> str:
    if len(top) < 2 or top[0] != "define":
        raise reader.error(top, f"expected '(define ({kind} NAME) ...)'")
    head = reader.node(top[1], top, f"({kind} NAME)")
    if len(head) != 2 or head[0] != kind:
        raise reader.error(top, f"expected '({kind} NAME)' after 'define'")
    return reader.name(head[1], head, f"the {kind} name")


#: A number in PDDL: digits, with an optional fraction.
_NUMBER = re.compile(r"-?[0-9]+(?:\.[0-9]+)?")
#: The most digits a cost may have (beyond, it is no cost a search can add up).
_COST_DIGITS = 18


def integer(reader: Reader, text: str, node: Node) -> int:
    """A natural number (``5``, ``5.0``); ``inf``, ``nan`` and ``1e400`` are not numbers
    in PDDL, and a cost of more than 18 digits is refused rather than overflowed."""
    if not _NUMBER.fullmatch(text):
        raise reader.error(node, f"expected a number, found {text!r}")
    whole, _, fraction = text.partition(".")
    if whole.startswith("-") or fraction.strip("0") or len(whole) > _COST_DIGITS:
        raise reader.error(
            node, f"not supported: action cost {text} (costs are natural numbers below 10^18)"
        )
    return int(whole)
