"""A prover for world models of ground facts: goals are answered by looking facts up.

It accepts what a conjunctive goal over a model of facts gives: axioms that are ground
unit facts, and a negated goal that is one clause of negated atoms (variables from the
goal's existential quantifiers, parameters, constants). The goal follows exactly when one
substitution makes every atom a fact, so lookup with backtracking is sound and complete
for such tasks; anything else (axioms with variables, disjunctions, equality) is refused
with ``ValueError``, as the conformance kit expects of a prover that does not declare it.
"""

from __future__ import annotations

from collections import defaultdict
from collections.abc import Iterator
from typing import ClassVar

from strips_framework.capabilities import ANSWERS, COMPLETE, SOUND, UNCOMPLETED_PROOF
from strips_framework.logic.clauses import Clause
from strips_framework.logic.terms import EQUALITY, Atom, Param, Term, is_ground
from strips_framework.options import Configurable
from strips_framework.worldmodel.proving import GAVE_UP, PROVED, SATURATED, ProofResult, ProofTask

Binding = dict[int | Param, Term]


class FactsProver(Configurable):
    """Answers conjunctive goals by fact lookup (ground facts only, no axioms)."""

    name: ClassVar[str] = "facts"
    capabilities: ClassVar[frozenset[str]] = frozenset({ANSWERS, SOUND, COMPLETE, UNCOMPLETED_PROOF})

    def prove(self, task: ProofTask) -> ProofResult:
        facts = _facts(task)
        goal = _goal_atoms(task)
        search = _Lookup(facts, task.effort)
        answers: list[tuple[tuple[Param, Term], ...]] = []
        for binding in search.matches(goal, {}):
            answer = tuple(sorted(
                ((p, t) for p, t in binding.items() if type(p) is Param),
                key=lambda pair: (pair[0].name, pair[0].tag),
            ))
            if answer not in answers:
                answers.append(answer)
            if len(answers) == task.max_answers:
                break
        if answers:
            return ProofResult(PROVED, tuple(answers), effort_used=search.used)
        status = GAVE_UP if search.used >= task.effort else SATURATED
        left = [(False, atom) for atom in search.best_left]
        uncompleted = (*task.negated_goal, Clause(left, label="facts lookup"))
        return ProofResult(status, (), tuple(dict.fromkeys(uncompleted)), search.used)


def _facts(task: ProofTask) -> dict[tuple[str, int], list[Atom]]:
    facts: dict[tuple[str, int], list[Atom]] = defaultdict(list)
    for number, clause in enumerate(task.axioms, start=1):
        if not clause.is_unit or not clause.literals[0][0] or not is_ground(clause.literals[0][1]):
            raise ValueError(f"the facts prover reads only ground facts; axiom {number} is {clause}")
        atom = clause.literals[0][1]
        if atom[0] == EQUALITY:
            raise ValueError(f"the facts prover does not handle equality: axiom {number} is {clause}")
        facts[atom[0], len(atom)].append(atom)
    return facts


def _goal_atoms(task: ProofTask) -> list[Atom]:
    if len(task.negated_goal) != 1:
        raise ValueError(
            "the facts prover answers conjunctions of atoms; this negated goal has "
            f"{len(task.negated_goal)} clauses"
        )
    (clause,) = task.negated_goal
    atoms = []
    for positive, atom in clause.literals:
        if positive or atom[0] == EQUALITY:
            raise ValueError(f"the facts prover answers conjunctions of atoms, not {clause}")
        atoms.append(atom)
    return atoms


class _Lookup:
    """Backtracking over the goal atoms; ``used`` counts facts tried (the effort)."""

    def __init__(self, facts: dict[tuple[str, int], list[Atom]], effort: int) -> None:
        self.facts = facts
        self.effort = effort
        self.used = 0
        self.best_left: list[Atom] = []
        self._best_count = -1

    def matches(self, atoms: list[Atom], binding: Binding) -> Iterator[Binding]:
        if not atoms:
            yield binding
            return
        first, rest = _substitute(atoms[0], binding), atoms[1:]
        matched = False
        for fact in self.facts.get((first[0], len(first)), ()):
            if self.used >= self.effort:
                return
            self.used += 1
            extended = _match(first, fact, binding)
            if extended is not None:
                matched = True
                yield from self.matches(rest, extended)
        if not matched:
            self._remember([_substitute(a, binding) for a in atoms])

    def _remember(self, left: list[Atom]) -> None:
        """Keep the shortest list of goal atoms left unmatched: the uncompleted proof."""
        if self._best_count < 0 or len(left) < self._best_count:
            self.best_left, self._best_count = left, len(left)


def _substitute(term: Term, binding: Binding) -> Term:
    if type(term) is tuple:
        return (term[0], *(_substitute(arg, binding) for arg in term[1:]))
    return binding.get(term, term) if type(term) in (int, Param) else term


def _match(pattern: Term, fact: Term, binding: Binding) -> Binding | None:
    if type(pattern) in (int, Param):
        if pattern in binding:
            return binding if binding[pattern] == fact else None
        return {**binding, pattern: fact}
    if type(pattern) is tuple:
        if type(fact) is not tuple or len(fact) != len(pattern) or fact[0] != pattern[0]:
            return None
        for p, f in zip(pattern[1:], fact[1:]):
            found = _match(p, f, binding)
            if found is None:
                return None
            binding = found
        return binding
    return binding if pattern == fact else None
