"""A planning problem in the paper's terms (II.A): initial world model, operators, goal.

These are the values a problem loader returns; they hold formulas and atoms, not clauses,
so that messages and plans can show what the user wrote.
"""

from __future__ import annotations

from collections.abc import Iterable

from strips_framework.logic.formulas import Formula, params_in
from strips_framework.logic.terms import Atom, Param
from strips_framework.records import Record


class SourceSpan(Record):
    """Where something was written, for error messages: ``file:line``."""

    path: str
    line: int

    __slots__ = ("path", "line")

    def __init__(self, path: str, line: int) -> None:
        self.path = path
        self.line = line

    def __str__(self) -> str:
        return f"{self.path}:{self.line}"


class OperatorSchema(Record):
    """An operator family such as ``goto(m, n)`` (II.A, III.B).

    ``add_list`` and ``delete_list`` hold atoms over the parameters and constants;
    delete-list atoms may use :data:`~strips_framework.logic.terms.WILDCARD`. The
    ``source`` is not compared.
    """

    name: str
    parameters: tuple[Param, ...]
    precondition: Formula
    add_list: tuple[Atom, ...]
    delete_list: tuple[Atom, ...]
    source: SourceSpan | None
    #: The parameters the precondition mentions: those a precondition proof can bind.
    #: Computed once, since relevance asks for every candidate instance.
    precondition_params: frozenset[Param]

    FIELDS = ("name", "parameters", "precondition", "add_list", "delete_list", "source")
    COMPARED = FIELDS[:-1]
    __slots__ = (*FIELDS, "precondition_params")

    def __init__(
        self,
        name: str,
        parameters: Iterable[Param],
        precondition: Formula,
        add_list: Iterable[Atom],
        delete_list: Iterable[Atom],
        source: SourceSpan | None = None,
    ) -> None:
        self.name = name
        self.parameters = tuple(parameters)
        self.precondition = precondition
        self.add_list = tuple(add_list)
        self.delete_list = tuple(delete_list)
        self.source = source
        self.precondition_params = frozenset(params_in(precondition))

    def signature(self) -> str:
        return f"{self.name}({', '.join(p.name for p in self.parameters)})"


class DerivedFact(Record):
    """A non-primitive ground fact and the primitive facts its validity rests on (III.B);
    the ``source`` is not compared."""

    atom: Atom
    supports: tuple[Atom, ...]
    source: SourceSpan | None

    __slots__ = ("atom", "supports", "source")
    COMPARED = ("atom", "supports")

    def __init__(
        self, atom: Atom, supports: Iterable[Atom], source: SourceSpan | None = None
    ) -> None:
        self.atom = atom
        self.supports = tuple(supports)
        self.source = source


class Problem(Record):
    """Everything the paper needs to state a task.

    ``facts`` are ground atoms of the initial model; ``axioms`` are closed wffs that hold in
    every model; ``derived`` are non-primitive facts with their supports; only predicates in
    ``primitive_predicates`` (pairs of name and arity) may appear on delete lists. With
    ``unique_names`` distinct constants denote distinct objects. The ``source`` (the file
    it was read from) is not compared.
    """

    name: str
    constants: tuple[str, ...]
    primitive_predicates: frozenset[tuple[str, int]]
    facts: tuple[Atom, ...]
    axioms: tuple[Formula, ...]
    derived: tuple[DerivedFact, ...]
    operators: tuple[OperatorSchema, ...]
    goal: Formula
    unique_names: bool
    source: str

    __slots__ = ("name", "constants", "primitive_predicates", "facts", "axioms", "derived",
                 "operators", "goal", "unique_names", "source")  # fmt: skip
    COMPARED = __slots__[:-1]

    def __init__(
        self,
        name: str,
        constants: Iterable[str],
        primitive_predicates: Iterable[tuple[str, int]],
        facts: Iterable[Atom],
        axioms: Iterable[Formula],
        derived: Iterable[DerivedFact],
        operators: Iterable[OperatorSchema],
        goal: Formula,
        unique_names: bool = True,
        source: str = "<memory>",
    ) -> None:
        self.name = name
        self.constants = tuple(constants)
        self.primitive_predicates = frozenset(primitive_predicates)
        self.facts = tuple(facts)
        self.axioms = tuple(axioms)
        self.derived = tuple(derived)
        self.operators = tuple(operators)
        self.goal = goal
        self.unique_names = unique_names
        self.source = source
        self._check_constants()

    def _check_constants(self) -> None:
        """Refuse a fact naming a constant the problem does not declare: a problem built
        in code with a typo (``("AT", "ROBOT", "e ")``) would otherwise be a different
        problem than meant, silently (the native and PDDL readers report it at its line).
        A problem that declares no constants at all (the conformance kit's prover cases)
        is not checked: its constants are whatever its facts name."""
        declared = set(self.constants)
        for fact in self.facts if declared else ():
            for term in fact[1:]:
                if isinstance(term, str) and term not in declared:
                    raise ValueError(
                        f"{self.source}: fact {fact!r} names the constant {term!r}, which is "
                        f"not among the problem's constants"
                    )

    def operator(self, name: str) -> OperatorSchema:
        for schema in self.operators:
            if schema.name == name:
                return schema
        raise KeyError(name)
