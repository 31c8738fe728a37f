"""A planning problem in the paper's terms (II.A): initial world model, operators, goal.

These are the values a problem loader returns; they hold formulas and atoms, not clauses,
so that messages and plans can show what the user wrote.
"""

from __future__ import annotations

from attrs import field, frozen

from strips_framework.logic.formulas import Formula, params_in
from strips_framework.logic.terms import Atom, Param


@frozen
class SourceSpan:
    """Where something was written, for error messages: ``file:line``."""

    path: str
    line: int

    def __str__(self) -> str:
        return f"{self.path}:{self.line}"


@frozen
class OperatorSchema:
    """An operator family such as ``goto(m, n)`` (II.A, III.B).

    ``add_list`` and ``delete_list`` hold atoms over the parameters and constants;
    delete-list atoms may use :data:`~strips_framework.logic.terms.WILDCARD`.
    """

    name: str
    parameters: tuple[Param, ...] = field(converter=tuple)
    precondition: Formula = field()
    add_list: tuple[Atom, ...] = field(converter=tuple)
    delete_list: tuple[Atom, ...] = field(converter=tuple)
    source: SourceSpan | None = field(default=None, eq=False)
    #: The parameters the precondition mentions: those a precondition proof can bind.
    #: Computed once, since relevance asks for every candidate instance.
    precondition_params: frozenset[Param] = field(init=False, eq=False, repr=False)

    def __attrs_post_init__(self) -> None:
        object.__setattr__(self, "precondition_params", frozenset(params_in(self.precondition)))

    def signature(self) -> str:
        return f"{self.name}({', '.join(p.name for p in self.parameters)})"


@frozen
class DerivedFact:
    """A non-primitive ground fact and the primitive facts its validity rests on (III.B)."""

    atom: Atom
    supports: tuple[Atom, ...] = field(converter=tuple)
    source: SourceSpan | None = field(default=None, eq=False)


@frozen
class Problem:
    """Everything the paper needs to state a task.

    ``facts`` are ground atoms of the initial model; ``axioms`` are closed wffs that hold in
    every model; ``derived`` are non-primitive facts with their supports; only predicates in
    ``primitive_predicates`` (pairs of name and arity) may appear on delete lists. With
    ``unique_names`` distinct constants denote distinct objects.
    """

    name: str
    constants: tuple[str, ...] = field(converter=tuple)
    primitive_predicates: frozenset[tuple[str, int]] = field(converter=frozenset)
    facts: tuple[Atom, ...] = field(converter=tuple)
    axioms: tuple[Formula, ...] = field(converter=tuple)
    derived: tuple[DerivedFact, ...] = field(converter=tuple)
    operators: tuple[OperatorSchema, ...] = field(converter=tuple)
    goal: Formula = field()
    unique_names: bool = True
    source: str = field(default="<memory>", eq=False)

    def __attrs_post_init__(self) -> None:
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
