"""Parser for wffs written in a readable ASCII (or Unicode) syntax.

Grammar, loosest binding first::

    formula := iff
    iff     := implies [ ("<->" | "↔" | "⇔") iff ]            right associative
    implies := or [ ("->" | "→" | "⇒") implies ]              right associative
    or      := and { ("|" | "∨") and }
    and     := unary { ("&" | "∧") unary }
    unary   := ("~" | "¬" | "not") unary
             | ("forall" | "∀" | "exists" | "∃") names ":" formula   body as far right as possible
             | ("forall" | ...) names "[" formula "]"               the paper's bracket form
             | primary
    primary := "(" formula ")" | "true" | "false" | atom | term ("=" | "!=" | "≠") term
    atom    := NAME [ "(" term { "," term } ")" ]
    term    := NAME [ "(" term { "," term } ")" ]

A quantifier may stand wherever an operand may (``A & forall x: B | C`` reads
``A & (forall x: (B | C))``), which an LALR grammar can only express through a
shift/reduce conflict that a parser generator such as lark resolves silently; recursive
descent states the rule in one line (:meth:`WffParser._unary`) and lets every error say in
plain words what was expected. The same parser reads the atoms, atom lists and names of
the native problem format, so positions and messages are uniform across a ``.strips``
file. It is also fast enough for large worlds (one regular expression drives the
tokenizer; tokens are named tuples), and the native loader reads plain ground facts
without it. Nesting deeper than :data:`~strips_framework.user_files.MAX_NESTING` is
refused with a clean error rather than a ``RecursionError``.

Identifiers are letters, digits and ``_``, with inner ``-`` (``three-boxes``, ``a1``).
A quantified identifier is a :class:`~strips_framework.logic.formulas.Var`, one of the
caller's parameter names is a :class:`~strips_framework.logic.terms.Param`, any other is
a constant (checked against the declared constants when the caller gives them).
"""

from __future__ import annotations

import re
from collections.abc import Collection, Iterable, Mapping

from strips_framework.errors import InputError
from strips_framework.logic.formulas import (
    And,
    Atomic,
    Exists,
    Forall,
    Formula,
    Iff,
    Implies,
    Not,
    Or,
    Truth,
    Var,
)
from strips_framework.logic.terms import EQUALITY, WILDCARD, Atom, Param, Term
from strips_framework.records import Record
from strips_framework.user_files import MAX_NESTING

_TOKEN = re.compile(
    r"""
    (?P<space>[ \t\r\f\v]+) | (?P<newline>\n) | (?P<comment>\#[^\n]*)
    | (?P<IFF><->|↔|⇔) | (?P<LARROW><-) | (?P<IMPLIES>->|→|⇒) | (?P<NEQ>!=|≠)
    | (?P<NOT>~|¬) | (?P<AND>&|∧) | (?P<OR>\||∨) | (?P<EQ>=) | (?P<FORALL>∀) | (?P<EXISTS>∃)
    | (?P<LPAREN>\() | (?P<RPAREN>\)) | (?P<LBRACKET>\[) | (?P<RBRACKET>\])
    | (?P<COMMA>,) | (?P<COLON>:) | (?P<SLASH>/) | (?P<WILDCARD>\$) | (?P<STRING>"[^"\n]*")
    | (?P<NAME>[A-Za-z0-9_]+(?:-[A-Za-z0-9_]+)*)
    """,
    re.VERBOSE,
)

_KEYWORDS = {"not": "NOT", "forall": "FORALL", "exists": "EXISTS", "true": "TRUE", "false": "FALSE"}


class Token(Record):
    """One lexeme with its 1-based position in the whole file (a slotted record: a large
    world has hundreds of thousands)."""

    kind: str
    text: str
    line: int
    column: int

    __slots__ = ("kind", "text", "line", "column")

    def __init__(self, kind: str, text: str, line: int, column: int) -> None:
        self.kind = kind
        self.text = text
        self.line = line
        self.column = column


def tokenize(
    text: str, path: str, line: int = 1, column: int = 1, end_name: str = "end of input"
) -> list[Token]:
    """Split ``text`` into tokens; the last one has kind ``END`` and text ``end_name``.

    ``line`` and ``column`` are where ``text`` starts in its file, so a wff cut out of a
    larger file reports positions in that file; later lines of ``text`` start at column 1.
    """
    tokens: list[Token] = []
    append, keywords, skipped = tokens.append, _KEYWORDS, ("space", "comment")
    shift = column  # column = offset + shift: on the first line, then after each newline
    end = 0
    for match in _TOKEN.finditer(text):
        pos = match.start()
        if pos != end:  # finditer skipped a character no token matches
            break
        end = match.end()
        kind = match.lastgroup
        if kind == "newline":
            line, shift = line + 1, 1 - end
        elif kind not in skipped:
            word = match.group()
            if kind == "NAME":
                kind = keywords.get(word, "NAME")
            append(Token(kind, word, line, pos + shift))  # type: ignore[arg-type]
    if end != len(text):
        raise InputError(path, line, end + shift, f"found unexpected character '{text[end]}'")
    if tokens:
        last = tokens[-1]
        tokens.append(Token("END", end_name, last.line, last.column + len(last.text)))
    else:
        tokens.append(Token("END", end_name, line, end + shift))
    return tokens


class Arities:
    """The arity of each predicate, fixed by a declaration or else by its first use.

    One instance per file makes "AT has two arguments everywhere" a single check, and
    lets the message say where the arity was fixed. Mutable: :meth:`fix` and
    :meth:`check` extend ``fixed``.
    """

    __slots__ = ("fixed",)

    def __init__(self, fixed: dict[str, tuple[int, str]] | None = None) -> None:
        self.fixed: dict[str, tuple[int, str]] = {} if fixed is None else fixed

    @classmethod
    def declared(cls, arities: Mapping[str, int]) -> Arities:
        return cls({name: (arity, "declared") for name, arity in arities.items()})

    def fix(self, name: str, arity: int, origin: str) -> None:
        self.fixed[name] = (arity, origin)

    def check(self, name: str, arity: int, origin: str) -> str | None:
        """Fix ``name`` at its first use; return a message when ``arity`` disagrees."""
        known = self.fixed.get(name)
        if known is None:
            self.fix(name, arity, f"as first used at {origin}")
            return None
        if known[0] == arity:
            return None
        return (
            f"expected {_arguments(known[0])} for {name} ({known[1]}) but found {_arguments(arity)}"
        )


def _arguments(count: int) -> str:
    return "1 argument" if count == 1 else f"{count} arguments"


class WffParser:
    """A cursor over the tokens of one wff, atom list or declaration line.

    ``params`` are the names that denote schema parameters; ``constants`` (when given)
    the declared constants (any collection: a file's parsers share one); ``arities`` (when given) is checked and extended at every
    atom. ``hint`` is added to the message about an unknown identifier, to say what the
    surrounding construct allows.
    """

    def __init__(
        self,
        tokens: list[Token],
        path: str,
        *,
        params: Iterable[str] = (),
        constants: Collection[str] | None = None,
        arities: Arities | None = None,
        hint: str = "",
    ) -> None:
        self.tokens, self.path, self.index = tokens, path, 0
        self.params = tuple(params)
        self.constants = constants  # looked into once per identifier: not copied per wff
        self.arities, self.hint = arities, hint
        self._bound: list[str] = []  # quantified variables in scope, innermost last
        self._wildcard = False
        self._depth = 0  # formulas, negations, implications and terms being read

    # --- cursor ---------------------------------------------------------------------

    @property
    def peek(self) -> Token:
        return self.tokens[self.index]

    def next(self) -> Token:
        token = self.tokens[self.index]
        if token.kind != "END":
            self.index += 1
        return token

    def accept(self, kind: str) -> Token | None:
        return self.next() if self.peek.kind == kind else None

    def expect(self, kind: str, expected: str) -> Token:
        """Consume a token of ``kind``; else fail with "expected <expected> but found ..."."""
        if self.peek.kind != kind:
            raise self.error(expected)
        return self.next()

    def end(self) -> None:
        """Require that nothing follows."""
        if self.peek.kind != "END":
            raise self.error(self.tokens[-1].text)

    def error(self, expected: str, token: Token | None = None) -> InputError:
        """``expected <expected> but found <token>`` at ``token`` (default: the next one)."""
        token = token or self.peek
        found = token.text if token.kind == "END" else f"'{token.text}'"
        return self.fail(token, f"expected {expected} but found {found}")

    def fail(self, token: Token, message: str) -> InputError:
        return InputError(self.path, token.line, token.column, message)

    def _descend(self) -> None:
        """One level deeper (undone by ``self._depth -= 1``); refuse input nested deeper
        than :data:`MAX_NESTING` at the token that goes too deep."""
        self._depth += 1
        if self._depth > MAX_NESTING:
            raise self.fail(self.peek, f"formula nested deeper than {MAX_NESTING} levels")

    # --- formulas -------------------------------------------------------------------

    def formula(self) -> Formula:
        """``iff``: the loosest-binding level."""
        self._descend()
        left = self._implies()
        if self.accept("IFF"):
            left = Iff(left, self.formula())
        self._depth -= 1
        return left

    def _implies(self) -> Formula:
        left = self._or()
        if self.accept("IMPLIES"):
            self._descend()
            left = Implies(left, self._implies())
            self._depth -= 1
        return left

    def _or(self) -> Formula:
        parts = [self._and()]
        while self.accept("OR"):
            parts.append(self._and())
        return parts[0] if len(parts) == 1 else Or(parts)

    def _and(self) -> Formula:
        parts = [self._unary()]
        while self.accept("AND"):
            parts.append(self._unary())
        return parts[0] if len(parts) == 1 else And(parts)

    def _unary(self) -> Formula:
        if self.accept("NOT"):
            self._descend()
            negated = Not(self._unary())
            self._depth -= 1
            return negated
        if self.peek.kind in ("FORALL", "EXISTS"):
            return self._quantified()
        return self._primary()

    def _quantified(self) -> Formula:
        kind = self.next().kind
        names = [self._variable_name()]
        while self.accept("COMMA"):
            names.append(self._variable_name())
        self._bound.extend(names)
        if self.accept("LBRACKET"):
            body = self.formula()
            self.expect("RBRACKET", "']'")
        elif self.accept("COLON"):
            body = self.formula()
        else:
            raise self.error("',' or ':' or '[' after the quantified variables")
        del self._bound[-len(names) :]
        variables = [Var(name) for name in names]
        return Forall(variables, body) if kind == "FORALL" else Exists(variables, body)

    def _variable_name(self) -> str:
        token = self.expect("NAME", "a variable name")
        return token.text

    def _primary(self) -> Formula:
        token = self.peek
        if self.accept("LPAREN"):
            inner = self.formula()
            self.expect("RPAREN", "')'")
            return inner
        if self.accept("TRUE"):
            return Truth(True)
        if self.accept("FALSE"):
            return Truth(False)
        if token.kind != "NAME":
            raise self.error("a formula (an atom, '~', '(', 'forall', 'exists', 'true' or 'false')")
        self.next()
        args = self._arguments() if self.peek.kind == "LPAREN" else None
        if self.peek.kind in ("EQ", "NEQ"):
            left = self._as_term(token, args)
            negated = self.next().kind == "NEQ"
            equality = Atomic((EQUALITY, left, self.term()))
            return Not(equality) if negated else equality
        return Atomic(self._checked_atom(token, args or ()))

    # --- atoms and terms ------------------------------------------------------------

    def atom(self, *, wildcard: bool = False) -> Atom:
        """``P`` or ``P(t1, ..., tn)``; with ``wildcard`` the terms may use ``$``."""
        name = self.expect("NAME", "an atom")
        self._wildcard = wildcard
        try:
            args = self._arguments() if self.peek.kind == "LPAREN" else ()
        finally:
            self._wildcard = False
        return self._checked_atom(name, args)

    def atom_list(self, *, wildcard: bool = False) -> list[tuple[Atom, Token]]:
        """Atoms separated by commas, each with its first token (for later messages)."""
        atoms = []
        while True:
            start = self.peek
            atoms.append((self.atom(wildcard=wildcard), start))
            if not self.accept("COMMA"):
                return atoms

    def term(self) -> Term | Var:
        token = self.peek
        if token.kind == "WILDCARD":
            if not self._wildcard:
                raise self.fail(token, "'$' (the wildcard) is allowed only in delete lists")
            self.next()
            return WILDCARD
        if token.kind != "NAME":
            raise self.error("a term (a constant, variable or parameter)")
        self.next()
        return self._as_term(token, self._arguments() if self.peek.kind == "LPAREN" else None)

    def _arguments(self) -> tuple[Term | Var, ...]:
        self.expect("LPAREN", "'('")
        self._descend()
        args = [self.term()]
        while self.accept("COMMA"):
            args.append(self.term())
        if self.peek.kind != "RPAREN":
            raise self.error("',' or ')'")
        self.next()
        self._depth -= 1
        return tuple(args)

    def _as_term(self, token: Token, args: tuple[Term | Var, ...] | None) -> Term | Var:
        name = token.text
        if args is None:
            return self._identifier(token)
        if name in self._bound or name in self.params:
            raise self.fail(token, f"'{name}' is a variable or parameter and takes no arguments")
        return (name, *args)

    def _identifier(self, token: Token) -> Term | Var:
        name = token.text
        if name in self._bound:
            return Var(name)
        if name in self.params:
            return Param(name)
        if self.constants is None or name in self.constants:
            return name
        known = ", ".join(sorted(self.constants)) or "none"
        if self.params:
            message = (
                f"'{name}' is neither a parameter ({', '.join(self.params)}) "
                f"nor a declared constant (declared constants: {known})"
            )
        else:
            message = f"undeclared constant '{name}' (declared constants: {known})"
        if self.hint:
            message += f"; {self.hint}"
        raise self.fail(token, message)

    def _checked_atom(self, name: Token, args: tuple[Term | Var, ...]) -> Atom:
        if self.arities is not None:
            where = f"{self.path}:{name.line}"
            problem = self.arities.check(name.text, len(args), where)
            if problem is not None:
                raise self.fail(name, problem)
        return (name.text, *args)


def parse_formula(
    text: str,
    *,
    path: str = "<string>",
    line: int = 1,
    column: int = 1,
    params: Iterable[str] = (),
    constants: Iterable[str] | None = None,
    arities: Arities | Mapping[str, int] | None = None,
) -> Formula:
    """Parse one wff; raise :class:`InputError` with ``path:line:column`` when it is bad.

    ``line``/``column`` say where ``text`` starts in its file. Identifiers in ``params``
    become :class:`Param` (tag 0); with ``constants`` given, any other free identifier
    must be one of them; with ``arities`` given, predicates must keep their arity.
    """
    if arities is not None and not isinstance(arities, Arities):
        arities = Arities.declared(arities)
    parser = WffParser(
        tokenize(text, path, line, column),
        path,
        params=params,
        constants=None if constants is None else frozenset(constants),
        arities=arities,
    )
    formula = parser.formula()
    parser.end()
    return formula
