"""Kernels in a world: which instances of a (generalized) triangle table's kernel i hold in
a state, and whether an instance's tail really replays there.

PLANEX asks the first question after every step; the soundness checks ask both, on many
states, of every MACROP learned. Both work on the simulator's states (sets of primitive
ground atoms, closed under the axioms), never on the planner's world models.
"""

from __future__ import annotations

import itertools
from collections import defaultdict
from collections.abc import Iterator, Sequence

from strips_framework.logic.terms import Atom, Param, Term
from strips_framework.logic.unify import substitute
from strips_framework.macrops.table import TriangleTable
from strips_framework.worldmodel.simulate import Simulator, State, match_pattern

Binding = dict[Param, Term]


def instances(
    table: TriangleTable,
    i: int,
    closed: State,
    constants: Sequence[str],
    binding: Binding | None = None,
    effort: int = 20000,
) -> Iterator[Binding]:
    """Every binding of the parameters of kernel ``i`` (extending ``binding``) under
    which its clauses are in ``closed`` and its :class:`Distinct` constraints hold, as
    far as ``effort`` attempts to match a clause against a fact go. Parameters of steps
    i .. n that the kernel leaves open range over ``constants``."""
    atoms = [substitute(a, binding or {}) for a in table.kernel(i)]
    by_predicate: dict[tuple[str, int], list[Atom]] = defaultdict(list)
    for atom in sorted(closed, key=repr):  # a fixed order: searches are reproducible
        by_predicate[atom[0], len(atom)].append(atom)
    distinct = table.kernel_distinct(i)
    open_params = [
        p for step in table.steps[i - 1:] for p in _params(step.arguments)
    ]
    for env in _join(atoms, by_predicate, dict(binding or {}), [effort]):
        rest = [p for p in dict.fromkeys(open_params) if p not in env]
        for values in itertools.product(constants, repeat=len(rest)):
            full = {**env, **dict(zip(rest, values))}
            if all(d.holds(full) for d in distinct):
                yield full


def holds(table: TriangleTable, i: int, closed: State, binding: Binding) -> bool:
    """Whether kernel ``i`` holds in ``closed`` under a full ``binding``."""
    atoms = (substitute(a, binding) for a in table.kernel(i))
    return all(a in closed for a in atoms) and all(
        d.holds(binding) for d in table.kernel_distinct(i)
    )


def replay_tail(
    simulator: Simulator, table: TriangleTable, i: int, binding: Binding, state: State
) -> str | None:
    """Run steps i .. n of ``table`` under ``binding`` from ``state``; ``None`` when each
    precondition holds and the goal row holds at the end, else what failed."""
    for number in range(i, table.size + 1):
        step = table.steps[number - 1].substituted(binding)
        schema_binding = step.binding()
        closed = simulator.close(state)
        if not simulator.holds(step.schema.precondition, schema_binding, closed):
            return f"step {number}, {step}: precondition does not hold"
        state = simulator.apply(step.schema, schema_binding, state)
    closed = simulator.close(state)
    for atom in table.goal_row():
        grounded = substitute(atom, binding)
        if grounded not in closed:
            return f"goal row clause {grounded} does not hold at the end"
    return None


def _params(terms: Sequence[Term]) -> Iterator[Param]:
    for term in terms:
        if type(term) is Param:
            yield term
        elif type(term) is tuple:
            yield from _params(term[1:])


def _join(
    atoms: list[Atom], facts: dict[tuple[str, int], list[Atom]], env: dict, budget: list[int]
) -> Iterator[dict]:
    """Bindings under which every atom is a fact, most bound atom first; gives up when
    ``budget[0]`` match attempts are spent (a long kernel that nearly holds can otherwise
    take exponential time to refute)."""
    if not atoms:
        yield env
        return
    pending = [substitute(a, env) for a in atoms]
    index = min(range(len(pending)), key=lambda k: len(list(_params(pending[k][1:]))))
    first, rest = pending[index], pending[:index] + pending[index + 1:]
    for fact in facts.get((first[0], len(first)), ()):
        budget[0] -= 1
        if budget[0] < 0:
            return
        extended = match_pattern(first, fact, dict(env))
        if extended is not None:
            yield from _join(rest, facts, extended, budget)


def counterexamples(
    simulator: Simulator, table: TriangleTable, states: Sequence[State], per_kernel: int = 25
) -> Iterator[tuple[State, int, Binding, str]]:
    """Instances of the table that break its promise: kernel i holds in a state, yet the
    tail from step i does not replay there (at most ``per_kernel`` instances tried per
    state and kernel). A sound table yields none."""
    constants = simulator.problem.constants
    for state in states:
        closed = simulator.close(state)
        for i in range(1, table.size + 1):
            for binding in itertools.islice(instances(table, i, closed, constants), per_kernel):
                failure = replay_tail(simulator, table, i, binding, state)
                if failure is not None:
                    yield state, i, binding, failure
