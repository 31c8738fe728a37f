"""How large grounding a task would be, estimated before grounding it, from the lifted
task alone: the choice between the ground and the lifted searches is made on this.

An action's instances are estimated the way a database estimates a join's size: its
parameters bound by static atoms of its precondition take the number of those atoms
(divided, for the parameters an earlier atom already bound, by their domains: the
independence assumption), and every other parameter the objects of its type. Fluent
atoms are not counted on: which of their atoms become reachable is what grounding would
find out. The sum over the actions costs time linear in the size of the lifted task.

Which lifted search suits a task is decided on a second cheap measure, the number of
action instances applicable in the initial state (:func:`initial_branching`), counted by
the query engine up to a cap.
"""

from __future__ import annotations

from collections import Counter
from itertools import islice

from strips_framework.lifted.successors import Successors
from strips_framework.lifted.task import LiftedTask, Query, is_variable

#: Estimated ground operators up to which grounding is considered cheap: the ground
#: search's set-up stays within a few seconds (see benchmarks/bench_scaling.py).
CHEAP_GROUNDING = 250_000
#: Applicable instances in the initial state above which a task counts as *wide*: a
#: search that measures every child of every state it expands (``lifted-alt-bfws``, some
#: 10 µs a child in Python) then pays a tenth of a second or more per expansion, while a
#: lazy search (``lifted-gbfs``) pays for the children it takes. Childsnack with contents
#: (parsize 3) has about 100,000; logistics with 1,000 cities 1,526; organic synthesis
#: 36-2,048.
WIDE_BRANCHING = 10_000


def estimated_operators(task: LiftedTask) -> float:
    """The estimated number of ground operators of ``task`` (see the module docstring)."""
    sizes = Counter(atom[0] for atom in task.static_atoms)
    objects = len(task.objects)
    total = 0.0
    for schema in task.actions:
        total += max(
            (_instances(q, schema.params, task.static, sizes, objects) for q in schema.precondition),
            default=0.0,
        )
    return total


def _instances(
    query: Query, params: tuple[str, ...], static: frozenset[str], sizes: Counter, objects: int
) -> float:
    def domain(variable: str) -> int:
        found = query.domains.get(variable)
        return len(found) if found is not None else objects

    wanted = {query.same.get(p, p) for p in params}
    wanted = {p for p in wanted if is_variable(p)}
    statics = sorted((a for a in query.positive if a.predicate in static), key=lambda a: sizes[a.predicate])
    estimate = 1.0
    bound: set[str] = set()
    for atom in statics:
        variables = {t for t in atom.args if is_variable(t)}
        if not variables - bound:
            continue
        denominator = 1.0
        for variable in variables & bound:
            denominator *= max(domain(variable), 1)
        estimate *= max(sizes[atom.predicate] / denominator, 1.0)
        bound |= variables
    for variable in wanted - bound:
        estimate *= domain(variable)
    return estimate


def initial_branching(task: LiftedTask, cap: int = WIDE_BRANCHING) -> int:
    """The number of action instances applicable in ``task``'s initial state, counted up
    to ``cap + 1`` (a wide task is not listed whole to find out that it is wide)."""
    successors = Successors(task)
    return sum(1 for _ in islice(successors.stream(successors.facts(task.init)), cap + 1))
