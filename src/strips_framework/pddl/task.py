"""The lifted PDDL task: a domain and a problem as read, plus the object-type table every
later step (grounding, validation, translation to a framework problem) needs."""

from __future__ import annotations

from collections.abc import Iterator

from strips_framework.errors import InputError
from strips_framework.pddl.formulas import Atom, Formula, Parameter
from strips_framework.records import Record

#: An action's cost: a number, or a numeric function term whose value the problem's init gives.
Cost = int | Atom


class Predicate(Record):
    name: str
    params: tuple[Parameter, ...]

    __slots__ = ("name", "params")

    def __init__(self, name: str, params: tuple[Parameter, ...]) -> None:
        self.name = name
        self.params = params


class ConditionalEffect(Record):
    """``(forall (params) (when condition effect))``: for every binding of ``params`` to
    objects under which ``condition`` holds in the state the action is applied in, the
    ``add`` atoms become true and the ``delete`` atoms false. A universal effect without
    ``when`` has the condition ``TRUE``; a ``when`` without ``forall`` has no params."""

    params: tuple[Parameter, ...]
    condition: Formula
    add: tuple[Atom, ...]
    delete: tuple[Atom, ...]

    __slots__ = ("params", "condition", "add", "delete")

    def __init__(
        self,
        params: tuple[Parameter, ...],
        condition: Formula,
        add: tuple[Atom, ...],
        delete: tuple[Atom, ...],
    ) -> None:
        self.params = params
        self.condition = condition
        self.add = add
        self.delete = delete


class Action(Record):
    """A lifted action: the unconditional STRIPS add/delete effects, the conditional and
    universal ones (``when``, ``forall``), and an optional ``total-cost`` increase. All
    conditions are evaluated in the state before the action; deletes apply before adds."""

    name: str
    params: tuple[Parameter, ...]
    precondition: Formula
    add: tuple[Atom, ...]
    delete: tuple[Atom, ...]
    cost: Cost | None
    line: int
    conditional: tuple[ConditionalEffect, ...]

    __slots__ = ("name", "params", "precondition", "add", "delete", "cost", "line", "conditional")

    def __init__(
        self,
        name: str,
        params: tuple[Parameter, ...],
        precondition: Formula,
        add: tuple[Atom, ...],
        delete: tuple[Atom, ...],
        cost: Cost | None = None,
        line: int = 0,
        conditional: tuple[ConditionalEffect, ...] = (),
    ) -> None:
        self.name = name
        self.params = params
        self.precondition = precondition
        self.add = add
        self.delete = delete
        self.cost = cost
        self.line = line
        self.conditional = conditional

    def changed_atoms(self) -> Iterator[Atom]:
        """Every atom an effect of the action may add or delete."""
        yield from self.add
        yield from self.delete
        for effect in self.conditional:
            yield from effect.add
            yield from effect.delete


class DerivedPredicate(Record):
    """``(:derived (head ?x ...) body)``: the head holds exactly when the body does."""

    head: Atom
    params: tuple[Parameter, ...]
    body: Formula

    __slots__ = ("head", "params", "body")

    def __init__(self, head: Atom, params: tuple[Parameter, ...], body: Formula) -> None:
        self.head = head
        self.params = params
        self.body = body


class Domain(Record):
    name: str
    requirements: tuple[str, ...]
    #: ``(type, parent)`` pairs; ``object`` is the root and needs no entry.
    types: tuple[tuple[str, str], ...]
    constants: tuple[Parameter, ...]
    predicates: tuple[Predicate, ...]
    functions: tuple[str, ...]
    actions: tuple[Action, ...]
    derived: tuple[DerivedPredicate, ...]

    __slots__ = (
        "name",
        "requirements",
        "types",
        "constants",
        "predicates",
        "functions",
        "actions",
        "derived",
    )

    def __init__(
        self,
        name: str,
        requirements: tuple[str, ...],
        types: tuple[tuple[str, str], ...],
        constants: tuple[Parameter, ...],
        predicates: tuple[Predicate, ...],
        functions: tuple[str, ...],
        actions: tuple[Action, ...],
        derived: tuple[DerivedPredicate, ...],
    ) -> None:
        self.name = name
        self.requirements = requirements
        self.types = types
        self.constants = constants
        self.predicates = predicates
        self.functions = functions
        self.actions = actions
        self.derived = derived


class Problem(Record):
    name: str
    domain_name: str
    objects: tuple[Parameter, ...]
    init: tuple[Atom, ...]
    #: Initial values of numeric functions, e.g. ``(= (road-length a b) 5)``.
    numeric: tuple[tuple[Atom, int], ...]
    goal: Formula
    #: ``(:metric minimize (total-cost))``.
    minimize_cost: bool

    __slots__ = ("name", "domain_name", "objects", "init", "numeric", "goal", "minimize_cost")

    def __init__(
        self,
        name: str,
        domain_name: str,
        objects: tuple[Parameter, ...],
        init: tuple[Atom, ...],
        numeric: tuple[tuple[Atom, int], ...],
        goal: Formula,
        minimize_cost: bool,
    ) -> None:
        self.name = name
        self.domain_name = domain_name
        self.objects = objects
        self.init = init
        self.numeric = numeric
        self.goal = goal
        self.minimize_cost = minimize_cost


def _objects_by_type(domain: Domain, problem: Problem) -> dict[str, tuple[str, ...]]:
    parents: dict[str, set[str]] = {}
    for child, parent in domain.types:
        parents.setdefault(child, set()).add(parent)

    def ancestors(kind: str) -> set[str]:
        seen = {kind, "object"}
        todo = [kind]
        while todo:
            for parent in parents.get(todo.pop(), ()):
                if parent not in seen:
                    seen.add(parent)
                    todo.append(parent)
        return seen

    members: dict[str, set[str]] = {"object": set()}
    for child, parent in domain.types:
        members.setdefault(child, set())
        members.setdefault(parent, set())
    for obj in (*domain.constants, *problem.objects):
        for kind in obj.types:
            for ancestor in ancestors(kind):
                members.setdefault(ancestor, set()).add(obj.name)
    return {kind: tuple(sorted(names)) for kind, names in members.items()}


class PddlTask:
    """A domain and a problem, with the files they came from (for messages)."""

    __slots__ = ("domain", "problem", "domain_path", "problem_path", "objects_by_type")

    def __init__(
        self, domain: Domain, problem: Problem, domain_path: str = "", problem_path: str = ""
    ) -> None:
        self.domain = domain
        self.problem = problem
        self.domain_path = domain_path
        self.problem_path = problem_path
        #: Every type's objects (including subtypes' objects), sorted.
        self.objects_by_type = _objects_by_type(domain, problem)

    def _key(self) -> tuple[Domain, Problem, str, str]:
        return (self.domain, self.problem, self.domain_path, self.problem_path)

    def __eq__(self, other: object) -> bool:
        return isinstance(other, PddlTask) and other._key() == self._key()

    def __hash__(self) -> int:
        return hash(self._key())

    def __repr__(self) -> str:
        return f"PddlTask({self.name!r}, {self.domain_path!r}, {self.problem_path!r})"

    def objects_of(self, types: tuple[str, ...]) -> tuple[str, ...]:
        """The objects of any of ``types`` (one type, or the members of ``(either ...)``)."""
        if len(types) == 1:
            return self.objects_by_type.get(types[0], ())
        return tuple(sorted({o for kind in types for o in self.objects_by_type.get(kind, ())}))

    @property
    def name(self) -> str:
        return self.problem.name


def missing_cost(task: PddlTask, term: Atom, action: Action) -> InputError:
    """The error for an action cost term the problem gives no value."""
    return InputError(
        task.problem_path, None, None, f"no initial value for {term}, the cost of {action.name!r}"
    )
