"""The query engine behind the prover boundary, both ways round.

:class:`JoinProver` is the join engine (:mod:`.query`) registered as a theorem prover
(``[prover] name = "joins"``): it answers the :class:`ProofTask` questions whose axioms are
a definite Horn program (ground facts and rules with one positive literal, no equations)
and whose negated goal is one clause of negated atoms (a conjunctive query, with the
goal's inequalities as equations under unique names), computing the program's least
model with the same joins and returning every answer. Anything else it refuses with
``ValueError`` (it declares ``definite-horn``). A least model says only that a goal
fails, not what is left of it; the uncompleted proof a means-ends search needs is the
core's residue (:mod:`strips_framework.worldmodel.residue`: the goal cut down by the
model's facts and rewritten through its rules, as resolution leaves it), so the paper's
tasks take the resolution prover's nodes under ``joins`` too. The conformance kit checks
it like any prover, and against the resolution prover on random Horn models.

:class:`ProverEngine` goes the other way: any prover answers the lifted search's queries,
one :class:`ProofTask` per query (the atoms of the query's predicates as facts, the
query's positive atoms as the negated goal, all answers asked for); negated atoms,
inequalities and types are then checked on the answers as the join engine does. That
is how the resolution prover serves the same search, slowly.
"""

from __future__ import annotations

from collections.abc import Sequence
from itertools import product
from typing import ClassVar

from strips_framework.capabilities import (
    ALL_ANSWERS,
    ANSWERS,
    COMPLETE,
    DEFINITE_HORN,
    SOUND,
    UNCOMPLETED_PROOF,
)
from strips_framework.lifted.query import FactBase, JoinEngine, QueryEngine, Relation, Row
from strips_framework.lifted.task import LiftedTask, Query, is_variable
from strips_framework.logic.clauses import Clause
from strips_framework.logic.terms import Param
from strips_framework.options import Configurable
from strips_framework.pddl.formulas import Atom
from strips_framework.worldmodel.proving import (
    PROVED,
    SATURATED,
    ProofResult,
    ProofTask,
    TheoremProver,
)
from strips_framework.worldmodel.residue import residue

#: Effort and answers a :class:`ProverEngine` allows a prover per query: all of them.
UNBOUNDED = 10**9


def engine_of(prover: TheoremProver | None, task: LiftedTask) -> QueryEngine:
    """The query engine for ``task``: the join engine when no prover is chosen (or the
    prover is the join engine), else the prover behind a :class:`ProverEngine`."""
    if prover is None or isinstance(prover, JoinProver):
        return JoinEngine(task.objects)
    return ProverEngine(prover, task.objects)


class ProverEngine(JoinEngine):
    """The lifted search's queries answered by a theorem prover (module docstring)."""

    def __init__(self, prover: TheoremProver, objects: Sequence[str]) -> None:
        super().__init__(objects)
        self.prover = prover

    def relations(self, query: Query, facts: FactBase, seed: dict[str, str] | None) -> list[Relation] | None:
        seed = seed or {}
        atoms = [Atom(a.predicate, tuple(seed.get(t, t) for t in a.args)) for a in query.positive]
        relations = []
        if atoms:
            variables = list(dict.fromkeys(t for a in atoms for t in a.args if is_variable(t)))
            params = {v: Param(v[1:]) for v in variables}
            wanted = {a.predicate for a in atoms}
            every = facts.atoms | (facts.static.atoms if facts.static is not None else set())
            axioms = [Clause([(True, atom)]) for atom in sorted(every) if atom[0] in wanted]
            goal = Clause([(False, (a.predicate, *[params.get(t, t) for t in a.args])) for a in atoms])
            task = ProofTask(axioms, [goal], effort=UNBOUNDED, max_answers=UNBOUNDED, unique_names=True)
            result = self.prover.prove(task)
            if not result.proved:
                return None
            rows: set[Row] = set()
            for answer in result.answers:
                bound = {param.name: value for param, value in answer}
                choices = [
                    [bound[p.name]] if p.name in bound else list(self.objects) for p in params.values()
                ]
                rows.update(product(*choices))
            domains = query.domains
            kept = [
                row for row in rows
                if all(domains.get(v) is None or value in domains[v] for v, value in zip(variables, row))
            ]
            if not kept:
                return None
            relations.append(Relation(tuple(variables), sorted(kept)))
        if seed:
            if any(v in query.domains and value not in query.domains[v] for v, value in seed.items()):
                return None
            relations.append(Relation(tuple(seed), [tuple(seed.values())]))
        return relations


class JoinProver(Configurable):
    """The join engine as a prover: every answer, from a definite Horn task's least model.

    No options: it needs no effort bound, since such a model is finite (module docstring)."""

    name: ClassVar[str] = "joins"
    capabilities: ClassVar[frozenset[str]] = frozenset(
        {ANSWERS, SOUND, COMPLETE, DEFINITE_HORN, ALL_ANSWERS, UNCOMPLETED_PROOF}
    )

    def prove(self, task: ProofTask) -> ProofResult:
        program = _HornProgram(task)
        facts = program.least_model()
        answers = program.answers(facts)
        if not answers:
            return ProofResult(SATURATED, uncompleted=residue(task))
        return ProofResult(PROVED, tuple(answers[: task.max_answers]))


class _HornProgram:
    """A task's axioms as facts and rules over string terms (variables ``?v<n>``,
    objects named by :meth:`_name`), refused unless definite Horn."""

    def __init__(self, task: ProofTask) -> None:
        self._names: dict[object, str] = {}
        self._terms: dict[str, object] = {}
        self.facts: list[tuple[str, ...]] = []
        self.rules: list[tuple[Atom, Query]] = []
        for number, clause in enumerate(task.axioms, start=1):
            positive = [atom for sign, atom in clause.literals if sign]
            if len(positive) != 1:
                raise ValueError(f"axiom {number} ({clause}) is not a definite Horn clause")
            head = positive[0]
            if head[0] == "=":
                raise ValueError(f"axiom {number} ({clause}) is an equation")
            body = [atom for sign, atom in clause.literals if not sign]
            if not body and not _has_variables(head):
                self.facts.append(self._atom(head))
                continue
            query = self._query([self._pattern(a) for a in body], [], ())
            head_pattern = self._pattern(head)
            if any(is_variable(t) and t not in query.all_variables() for t in head_pattern.args):
                raise ValueError(f"axiom {number} ({clause}) has a head variable its body does not bind")
            self.rules.append((head_pattern, Query(tuple(t for t in head_pattern.args if is_variable(t)), query.positive)))
        if len(task.negated_goal) != 1:
            raise ValueError("the negated goal is not one clause (the goal is not a conjunction)")
        goal_atoms, distinct = [], []
        for sign, atom in task.negated_goal[0].literals:
            if not sign:
                goal_atoms.append(self._pattern(atom))
            elif atom[0] == "=" and task.unique_names:
                left, right = (self._term(t) for t in atom[1:])
                distinct.append((left, right))
            else:
                raise ValueError(f"the goal has a negated literal {atom} (negation is not Horn)")
        self.params = sorted(
            {t for _, a in task.negated_goal[0].literals for t in a[1:] if type(t) is Param},
            key=lambda p: (p.name, p.tag),
        )
        self.goal = self._query(goal_atoms, distinct, tuple(self._term(p) for p in self.params))

    def least_model(self) -> FactBase:
        """The facts and everything the rules derive from them (naive fixpoint)."""
        facts = FactBase(self.facts)
        engine = JoinEngine(self.objects())
        while True:
            new = [
                (head.predicate, *[dict(zip(body.variables, row)).get(t, t) for t in head.args])
                for head, body in self.rules
                for row in engine.answers(body, facts)
            ]
            if not facts.add(new):
                return facts

    def answers(self, facts: FactBase) -> list[tuple[tuple[Param, object], ...]]:
        rows = JoinEngine(self.objects()).answers(self.goal, facts)
        return [
            tuple((param, self._terms.get(value, value)) for param, value in zip(self.params, row))
            for row in rows
        ]

    def objects(self) -> tuple[str, ...]:
        return tuple(sorted(set(self._names.values())))

    def _query(self, atoms: list[Atom], distinct: list[tuple[str, str]], answer: tuple[str, ...]) -> Query:
        return Query(answer, tuple(atoms), (), tuple(distinct))

    def _pattern(self, atom: tuple) -> Atom:
        return Atom(atom[0], tuple(self._term(t) for t in atom[1:]))

    def _atom(self, atom: tuple) -> tuple[str, ...]:
        return (atom[0], *[self._term(t) for t in atom[1:]])

    def _term(self, term: object) -> str:
        if type(term) is int or type(term) is Param:
            return f"?v{term}" if type(term) is int else f"?p{term.tag}.{term.name}"
        if type(term) is tuple and _has_variables(term):
            raise ValueError(f"the function term {term} has variables (not a Datalog program)")
        name = self._names.get(term)
        if name is None:
            name = self._names[term] = term if type(term) is str and not term.startswith("?") else f"#{len(self._names)}"
            self._terms[name] = term
        return name


def _has_variables(term: object) -> bool:
    if type(term) is int or type(term) is Param:
        return True
    return type(term) is tuple and any(_has_variables(t) for t in term[1:])
