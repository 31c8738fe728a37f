"""The lifted task as the lifted search reads it: every precondition, goal, effect
condition and derived-predicate body normalized once into conjunctive queries, and
nothing grounded.

A :class:`Query` is what the query engine answers: a conjunction of atoms (variables start
with ``?``) with negated atoms, inequalities and a set of allowed objects per variable
(the variable's type), whose answers are the bindings of its ``variables``. Normalizing
(:class:`~strips_framework.grounding.normalize.Normalizer`, the grounder's) turns a PDDL
formula into a disjunction of such conjunctions; ``exists`` variables become the query's
existential variables, and ``(= ?x ?y)`` is solved away by renaming before any join.
"""

from __future__ import annotations

from collections.abc import Iterable

from strips_framework.errors import InputError
from strips_framework.grounding.normalize import Clause, Normalizer
from strips_framework.lifted.components import GroundAtom, LiftedState, static_predicates
from strips_framework.pddl.formulas import Atom, Formula, Parameter
from strips_framework.pddl.task import Action, PddlTask, missing_cost
from strips_framework.records import Record

EQUALS = "="


class Query(Record):
    """``variables`` are answered in this order; the others are existential.

    ``positive`` and ``negative`` atoms have terms that are variables or objects;
    ``distinct`` pairs of terms must name different objects; ``domains`` gives, for each
    typed variable, the objects it may take (a variable missing from it takes any
    object). ``same`` maps each answer variable that an equality merged into another
    term to that term (its answer is the term's value)."""

    variables: tuple[str, ...]
    positive: tuple[Atom, ...]
    negative: tuple[Atom, ...]
    distinct: tuple[tuple[str, str], ...]
    domains: dict[str, frozenset[str]]
    same: dict[str, str]

    __slots__ = ("variables", "positive", "negative", "distinct", "domains", "same")

    def __init__(
        self,
        variables: tuple[str, ...],
        positive: tuple[Atom, ...] = (),
        negative: tuple[Atom, ...] = (),
        distinct: tuple[tuple[str, str], ...] = (),
        domains: dict[str, frozenset[str]] = {},
        same: dict[str, str] = {},
    ) -> None:
        self.variables = variables
        self.positive = positive
        self.negative = negative
        self.distinct = distinct
        self.domains = domains
        self.same = same

    def __hash__(self) -> int:
        return id(self)  # compiled once and used as a cache key by identity

    def __eq__(self, other: object) -> bool:
        return self is other

    def all_variables(self) -> tuple[str, ...]:
        """Every variable the query mentions (answer ones first), each once."""
        seen = dict.fromkeys(v for v in self.variables if v not in self.same)
        for atom in (*self.positive, *self.negative):
            seen.update(dict.fromkeys(a for a in atom.args if is_variable(a)))
        for pair in self.distinct:
            seen.update(dict.fromkeys(a for a in pair if is_variable(a)))
        return tuple(seen)


def is_variable(term: str) -> bool:
    return term.startswith("?")


class Effect(Record):
    """Atoms added and deleted when every ``condition`` query (a disjunction; empty:
    always) has an answer extending the action's binding; one application per answer of
    the ``params`` (a universal effect)."""

    params: tuple[str, ...]
    condition: tuple[Query, ...]
    add: tuple[Atom, ...]
    delete: tuple[Atom, ...]

    __slots__ = ("params", "condition", "add", "delete")

    def __init__(
        self,
        params: tuple[str, ...],
        condition: tuple[Query, ...],
        add: tuple[Atom, ...],
        delete: tuple[Atom, ...],
    ) -> None:
        self.params = params
        self.condition = condition
        self.add = add
        self.delete = delete


class ActionSchema(Record):
    """A lifted action: its precondition as queries over its parameters (one per
    disjunct), its unconditional effects and conditional ones, and its cost (a number,
    or a function term whose arguments are parameters or objects)."""

    name: str
    params: tuple[str, ...]
    precondition: tuple[Query, ...]
    add: tuple[Atom, ...]
    delete: tuple[Atom, ...]
    effects: tuple[Effect, ...]
    cost: int | Atom

    __slots__ = ("name", "params", "precondition", "add", "delete", "effects", "cost")

    def __init__(
        self,
        name: str,
        params: tuple[str, ...],
        precondition: tuple[Query, ...],
        add: tuple[Atom, ...],
        delete: tuple[Atom, ...],
        effects: tuple[Effect, ...],
        cost: int | Atom,
    ) -> None:
        self.name = name
        self.params = params
        self.precondition = precondition
        self.add = add
        self.delete = delete
        self.effects = effects
        self.cost = cost


class Rule(Record):
    """A derived predicate's rule: ``head`` holds for every answer of ``body`` (a
    disjunct of the definition), evaluated in order of ``stratum``."""

    head: Atom
    body: Query
    stratum: int

    __slots__ = ("head", "body", "stratum")

    def __init__(self, head: Atom, body: Query, stratum: int) -> None:
        self.head = head
        self.body = body
        self.stratum = stratum


class LiftedTask:
    """A PDDL task compiled for lifted search; see the module docstring."""

    def __init__(self, task: PddlTask) -> None:
        self.pddl = task
        normalizer = Normalizer(task)
        self._normalizer = normalizer
        self.objects: tuple[str, ...] = task.objects_by_type.get("object", ())
        self.static: frozenset[str] = static_predicates(task)
        #: The objects of each typed parameter's types, one set per type list, so that
        #: queries over the same types share it (the join engine files relations by it).
        self._domains: dict[tuple[str, ...], frozenset[str]] = {}
        self.actions = tuple(self._action(action) for action in task.domain.actions)
        self.goal = self._queries(task.problem.goal, ())
        self.rules = self._rules()
        self.derived = frozenset(rule.head.predicate for rule in self.rules)
        atoms = [(atom.predicate, *atom.args) for atom in task.problem.init]
        #: Atoms of static predicates, which no state repeats.
        self.static_atoms: frozenset[GroundAtom] = frozenset(a for a in atoms if a[0] in self.static)
        self.init: LiftedState = frozenset(
            a for a in atoms if a[0] not in self.static and a[0] not in self.derived
        )
        self.uses_costs = task.problem.minimize_cost
        self._numeric = {(term.predicate, *term.args): value for term, value in task.problem.numeric}

    @property
    def name(self) -> str:
        return self.pddl.name

    def cost(self, action: ActionSchema, binding: dict[str, str]) -> int:
        """The cost of an instance of ``action`` (1 for every action when the problem
        does not minimize total cost, as the grounder counts)."""
        if not self.uses_costs:
            return 1
        if isinstance(action.cost, int):
            return action.cost
        key = (action.cost.predicate, *(binding.get(a, a) for a in action.cost.args))
        value = self._numeric.get(key)
        if value is None:
            term = Atom(key[0], key[1:])
            raise missing_cost(self.pddl, term, self._pddl_action(action.name))
        return value

    def _pddl_action(self, name: str) -> Action:
        return next(a for a in self.pddl.domain.actions if a.name == name)

    def _action(self, action: Action) -> ActionSchema:
        params = tuple(p.name for p in action.params)
        effects = []
        for effect in action.conditional:
            own = tuple(p.name for p in effect.params)
            effects.append(
                Effect(
                    own,
                    self._queries(effect.condition, (*action.params, *effect.params), answer=own),
                    effect.add,
                    effect.delete,
                )
            )
        if not self.pddl.problem.minimize_cost or action.cost is None:
            cost: int | Atom = 0 if self.pddl.problem.minimize_cost else 1
        else:
            cost = action.cost
        return ActionSchema(
            action.name,
            params,
            self._queries(action.precondition, action.params),
            action.add,
            action.delete,
            tuple(effects),
            cost,
        )

    def _queries(
        self,
        formula: Formula,
        params: tuple[Parameter, ...],
        answer: tuple[str, ...] | None = None,
    ) -> tuple[Query, ...]:
        """``formula``'s disjuncts as queries answering ``answer`` (default: the names
        of ``params``), whose types restrict them."""
        names = tuple(p.name for p in params) if answer is None else answer
        return tuple(
            query
            for clause in self._normalizer.clauses(formula)
            if (query := self._query(clause, names, params)) is not None
        )

    def _query(
        self, clause: Clause, answer: tuple[str, ...], params: Iterable[Parameter]
    ) -> Query | None:
        """The clause as a query, or None when its equalities contradict each other."""
        domains: dict[str, frozenset[str]] = {}
        for param in (*params, *clause.params):
            if param.types != ("object",):
                found = self._domains.get(param.types)
                if found is None:
                    found = self._domains[param.types] = frozenset(self.pddl.objects_of(param.types))
                domains[param.name] = found
        merged = _Merged()
        for atom in clause.positive:
            if atom.predicate == EQUALS and not merged.union(*atom.args):
                return None
        rename = merged.representatives()
        for variable, term in rename.items():  # a merged variable takes both types
            if variable in domains:
                kept = domains.pop(variable)
                if is_variable(term):
                    domains[term] = domains.get(term, kept) & kept
                elif term not in kept:
                    return None
        positive = tuple(_renamed(a, rename) for a in clause.positive if a.predicate != EQUALS)
        negative = tuple(_renamed(a, rename) for a in clause.negative if a.predicate != EQUALS)
        distinct = tuple(
            (rename.get(a.args[0], a.args[0]), rename.get(a.args[1], a.args[1]))
            for a in clause.negative
            if a.predicate == EQUALS
        )
        if any(left == right for left, right in distinct):
            return None
        same = {v: rename[v] for v in answer if v in rename}
        return Query(answer, positive, negative, distinct, domains, same)

    def _rules(self) -> tuple[Rule, ...]:
        """Every derived predicate's rules (and the auxiliary ones the normalizer made
        for universal conditions), with their strata."""
        normalizer = self._normalizer
        rules: list[tuple[Atom, Query]] = []
        pending = list(self.pddl.domain.derived)
        done = 0
        while pending or done < len(normalizer.auxiliary):
            if pending:
                definition = pending.pop(0)
            else:
                definition = normalizer.auxiliary[done]
                done += 1
            head_vars = tuple(a for a in definition.head.args)
            for query in self._queries(definition.body, definition.params, head_vars):
                rules.append((definition.head, query))
        strata = _strata(rules)
        return tuple(Rule(head, body, strata[head.predicate]) for head, body in rules)


def _renamed(atom: Atom, rename: dict[str, str]) -> Atom:
    if not rename:
        return atom
    return Atom(atom.predicate, tuple(rename.get(a, a) for a in atom.args))


class _Merged:
    """Union-find over the terms of a clause's equalities."""

    def __init__(self) -> None:
        self.parent: dict[str, str] = {}

    def find(self, term: str) -> str:
        while self.parent.get(term, term) != term:
            term = self.parent[term]
        return term

    def union(self, left: str, right: str) -> bool:
        a, b = self.find(left), self.find(right)
        if a == b:
            return True
        if not is_variable(a) and not is_variable(b):
            return False  # two different objects
        if is_variable(a) and not is_variable(b):
            a, b = b, a
        # ``a`` is kept: an object, or the first variable.
        self.parent[b] = a
        return True

    def representatives(self) -> dict[str, str]:
        return {term: self.find(term) for term in self.parent if self.find(term) != term}


def _strata(rules: list[tuple[Atom, Query]]) -> dict[str, int]:
    """The least stratum of each derived predicate: at least that of every derived
    predicate in its bodies, above those it negates (PDDL requires stratifiable axioms)."""
    heads = {head.predicate for head, _ in rules}
    stratum = dict.fromkeys(heads, 0)
    for _ in range(len(heads) + 1):
        changed = False
        for head, body in rules:
            level = stratum[head.predicate]
            for atom in body.positive:
                if atom.predicate in heads and stratum[atom.predicate] > level:
                    level = stratum[atom.predicate]
            for atom in body.negative:
                if atom.predicate in heads and stratum[atom.predicate] + 1 > level:
                    level = stratum[atom.predicate] + 1
            if level != stratum[head.predicate]:
                stratum[head.predicate] = level
                changed = True
        if not changed:
            return stratum
    raise InputError("", None, None, "the derived predicates are not stratifiable")
