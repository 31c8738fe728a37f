"""The builtin relevance filter: operators whose add lists continue the proof (III.C).

Two steps, as in the paper. Candidates are the schemata with an add-list atom whose
predicate occurs negated in a difference clause. Each add-list atom of a candidate is then
resolved against each such literal; every resolvent yields one relevant instance, with the
unifier applied to the schema's parameters. ``goto(m, n)`` against ``~ATR(a) | ~ATR(b)``
gives ``goto(m, a)`` (resolvent ``~ATR(b)``) and ``goto(m, b)`` (resolvent ``~ATR(a)``).

Instances are ranked by resolvent size: an instance that leaves less of the clause to
prove continues the proof further.
"""

from __future__ import annotations

from collections import defaultdict
from collections.abc import Sequence
from typing import ClassVar

from attrs import frozen

from strips_framework.hookspecs import hookimpl
from strips_framework.logic.clauses import Clause
from strips_framework.logic.formulas import params_in
from strips_framework.logic.terms import Atom, Param, Term, params_of, variables_of
from strips_framework.logic.unify import substitute, unify
from strips_framework.operators import OperatorInstance
from strips_framework.problem import OperatorSchema
from strips_framework.search.node import Difference, RelevantInstance

#: Schema parameters are renamed to this tag while unifying, so they never meet the goal's
#: own parameters (which carry tag 0: preconditions are built from the schemata).
_RENAMED = 1


@frozen
class AddListRelevance:
    """Relevant instances from resolving add-list atoms against difference clauses.

    An instance is dropped when a parameter that only its effects mention (not its
    precondition) stays unbound or is bound to another operator's parameter: applying it
    would need a value that neither this resolution nor the precondition proof provides.
    """

    name: ClassVar[str] = "add-list"

    def relevant(
        self, difference: Difference, operators: Sequence[OperatorSchema]
    ) -> list[RelevantInstance]:
        by_predicate = _add_atoms_by_predicate(operators)
        ranked: dict[OperatorInstance, tuple[tuple[int, int], RelevantInstance]] = {}
        order = 0
        for clause in difference.clauses:
            for position, (positive, atom) in enumerate(clause.literals):
                if positive:
                    continue
                for schema, renamed, add_atom in by_predicate.get((atom[0], len(atom)), ()):
                    found = _resolve(schema, renamed, add_atom, clause, position)
                    if found is None:
                        continue
                    key = (len(found.resolvent.literals), order)
                    order += 1
                    known = ranked.get(found.operator)
                    if known is None or key < known[0]:
                        ranked[found.operator] = (key, found)
        return [found for _, found in sorted(ranked.values(), key=lambda item: item[0])]


def _add_atoms_by_predicate(
    operators: Sequence[OperatorSchema],
) -> dict[tuple[str, int], list[tuple[OperatorSchema, dict[Param, Param], Atom]]]:
    """Candidate index: (predicate, arity) -> (schema, renaming, renamed add atom)."""
    index: dict[tuple[str, int], list[tuple[OperatorSchema, dict[Param, Param], Atom]]]
    index = defaultdict(list)
    for schema in operators:
        renaming = {p: Param(p.name, _RENAMED) for p in schema.parameters}
        for atom in schema.add_list:
            index[(atom[0], len(atom))].append((schema, renaming, substitute(atom, renaming)))
    return index


def _resolve(
    schema: OperatorSchema,
    renaming: dict[Param, Param],
    add_atom: Atom,
    clause: Clause,
    position: int,
) -> RelevantInstance | None:
    target = clause.literals[position][1]
    unifier = unify(add_atom, target, {})
    if unifier is None:
        return None
    binding: dict[Param, Term] = {}
    for own, renamed in renaming.items():
        value = substitute(renamed, unifier)
        if value == renamed:
            continue
        if params_of(value) or variables_of(value):
            return None  # bound to another operator's parameter, or to a variable
        binding[own] = value
    in_precondition = params_in(schema.precondition)
    for own in schema.parameters:
        if own not in binding and own not in in_precondition:
            return None
    rest = [
        (sign, substitute(atom, unifier))
        for i, (sign, atom) in enumerate(clause.literals)
        if i != position
    ]
    resolvent = Clause(list(dict.fromkeys(rest)), clause.bindings, label="relevance")
    return RelevantInstance(OperatorInstance(schema, binding.items()), resolvent)


@hookimpl
def strips_register_relevance_filters() -> list[type]:
    return [AddListRelevance]
