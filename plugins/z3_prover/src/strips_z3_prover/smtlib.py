"""Ground instances as SMT-LIB text, for Z3 to parse in one call.

Building Z3 terms through its Python API costs tens of microseconds a node, and the
robot world's axiom ``CONNECTS(x, y, z) -> CONNECTS(x, z, y)`` alone has 27^3 ground
instances; Z3 parses the same instances written as SMT-LIB text about ten times faster.
Symbols are written quoted (``|P/2|``) and declared with the names and signatures
:class:`~strips_z3_prover.encoding.Vocabulary` gives them, so Z3 identifies the parsed
symbols with the Python ones (its terms are hash-consed by name and signature), and models
are read back through the Python objects.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

from strips_framework.logic.clauses import Clause
from strips_framework.logic.terms import EQUALITY, Param, Term


class Batch:
    """Assertions being written, with the declarations they need.

    A solver's parser keeps what it was told, and refuses a second declaration of a
    symbol, so ``declared`` (shared by every batch of one solver) holds the symbols
    declared so far; :meth:`declarations` hands out only the new ones.
    """

    def __init__(self, declared: set[str]) -> None:
        self._declared = declared
        self._declarations: dict[str, str] = {}
        self._assertions: list[str] = []

    def assert_clause(
        self, clause: Clause, binding: Mapping[int | Param, str], selector: str | None = None
    ) -> None:
        """Assert the instance of ``clause`` under ``binding`` (which grounds it), as
        ``selector -> instance`` when a selector is given."""
        literals = [self._literal(positive, atom, binding) for positive, atom in clause.literals]
        if not literals:
            body = "false"
        elif len(literals) == 1:
            body = literals[0]
        else:
            body = f"(or {' '.join(literals)})"
        if selector is not None:
            self._declare(selector, f"(declare-const |{selector}| Bool)")
            body = f"(=> |{selector}| {body})"
        self._assertions.append(f"(assert {body})")

    def assert_distinct(self, names: Sequence[str], selector: str) -> None:
        """Assert ``selector -> names are pairwise distinct`` (unique names)."""
        self._declare(selector, f"(declare-const |{selector}| Bool)")
        constants = " ".join(self._constant(name) for name in names)
        self._assertions.append(f"(assert (=> |{selector}| (distinct {constants})))")

    def declarations(self) -> str:
        """The declarations not made before; from now on they count as made."""
        self._declared.update(self._declarations)
        text = "".join(self._declarations.values())
        self._declarations.clear()
        return text

    def assertions(self) -> str:
        return "".join(self._assertions)

    def _declare(self, name: str, declaration: str) -> None:
        if name not in self._declared:
            self._declarations.setdefault(name, declaration)

    def _literal(self, positive: bool, atom: tuple, binding: Mapping[int | Param, str]) -> str:
        args = [self._constant(binding.get(t, t)) for t in atom[1:]]
        if atom[0] == EQUALITY and len(atom) == 3:
            text = f"(= {args[0]} {args[1]})"
        else:
            symbol = f"{atom[0]}/{len(args)}"
            signature = " ".join(["U"] * len(args))
            self._declare(symbol, f"(declare-fun |{symbol}| ({signature}) Bool)")
            text = f"(|{symbol}| {' '.join(args)})" if args else f"|{symbol}|"
        return text if positive else f"(not {text})"

    def _constant(self, name: Term) -> str:
        if type(name) is not str:
            raise ValueError(f"ground instance expected, found the term {name!r}")
        self._declare(name, f"(declare-const |{name}| U)")
        return f"|{name}|"
