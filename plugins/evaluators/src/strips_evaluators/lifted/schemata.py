"""The relaxed program of the framework's operator schemata (``worldmodel.problem``), for
the means-ends relaxed-plan evaluator on problems too large to ground its relaxation.

It is the relaxation :mod:`strips_evaluators.relaxed_plan` grounds, read lifted: a schema
becomes a rule whose body is its precondition's positive atoms (equalities are tests),
whose heads are its add atoms that the body binds, at cost 1. Atoms of predicates no
schema adds are static: joined against M0's facts, free of cost. Schema parameters become
variables ``?0``, ``?1``, ... and a precondition's own variables ``?v0``, ...; constants
stay as they are.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence

from strips_evaluators.lifted.program import RuleProgram
from strips_framework.grounding.normalize import Clause
from strips_framework.logic.terms import Param
from strips_framework.pddl.formulas import Atom, Parameter

#: A framework atom: ``(predicate, *terms)``.
SchemaAtom = tuple


class SchemaProgram(RuleProgram):
    """``operators``' relaxation over the ground atoms ``facts`` of M0."""

    def __init__(
        self,
        operators: Sequence[tuple[str, list[SchemaAtom], list[tuple[bool, SchemaAtom]], list[SchemaAtom]]],
        facts: Iterable[SchemaAtom],
    ) -> None:
        """``operators``: per schema its name, positive precondition atoms, equality
        constraints ``(equal, atom)`` and add atoms."""
        facts = list(facts)
        added = {atom[0] for _, _, _, adds in operators for atom in adds}
        mentioned = {atom[0] for atom in facts}
        mentioned |= {atom[0] for _, body, _, _ in operators for atom in body}
        constants = sorted({str(term) for atom in facts for term in atom[1:]})
        super().__init__(
            frozenset(mentioned - added), facts, lambda types: tuple(constants), "<operators>"
        )
        self.action_names = [name for name, _, _, _ in operators]
        for number, (_, body, constraints, adds) in enumerate(operators):
            names: dict[object, str] = {}

            def term(value: object) -> str:
                if isinstance(value, Param) or type(value) is int:
                    names.setdefault(value, f"?{len(names)}")
                    return names[value]
                return value  # type: ignore[return-value]

            positive = tuple(Atom(a[0], tuple(term(t) for t in a[1:])) for a in body)
            bound = set(names.values())
            params = tuple(Parameter(name) for name in bound)
            equal, unequal = [], []
            for is_equal, (_, left, right) in constraints:
                pair = Atom("=", (term(left), term(right)))
                if all(not t.startswith("?") or t in bound for t in pair.args):
                    (equal if is_equal else unequal).append(pair)
            heads = []
            for atom in adds:
                head = Atom(atom[0], tuple(term(t) for t in atom[1:]))
                if all(not t.startswith("?") or t in bound for t in head.args):
                    heads.append(head)
            clause = Clause((), positive + tuple(equal), tuple(unequal))
            self._add(clause, tuple(sorted(params, key=lambda p: p.name)), tuple(heads), number, 0, 1)
        self._index_static_facts()
