"""Exact plan lengths on small problems, for checking admissibility claims.

The state space is explored with the independent simulator's semantics
(:class:`~strips_framework.worldmodel.simulate.Simulator`: states are sets of ground atoms,
conditions are model-checked on their closure), never with the planner's prover or
world models, so a wrong optimum cannot come from the code under test. Every state
reachable from the initial one is enumerated once, and the distance of each to the goal
is found by breadth-first search backwards; that is only feasible for small problems,
which is what the kit uses.
"""

from __future__ import annotations

import itertools
from collections import defaultdict, deque
from collections.abc import Iterator, Mapping, Sequence

from strips_framework.logic.formulas import And, Atomic, Formula, params_in
from strips_framework.logic.terms import EQUALITY, Atom, Param, Term
from strips_framework.means_ends.node import Goal
from strips_framework.worldmodel.problem import OperatorSchema, Problem
from strips_framework.worldmodel.simulate import Simulator, State, match_pattern

UNREACHABLE = float("inf")


class TooLarge(Exception):
    """The problem has more reachable states than the kit explores."""


class StateSpace:
    """The reachable states of a problem, their successors and their goal distances."""

    def __init__(self, problem: Problem, max_states: int = 20_000) -> None:
        self.problem = problem
        self.simulator = Simulator(problem)
        self.initial: State = frozenset(problem.facts)
        self._closures: dict[State, State] = {}
        self.successors: dict[State, list[State]] = {}
        frontier = deque([self.initial])
        self.successors[self.initial] = []
        while frontier:
            state = frontier.popleft()
            following = [after for _, _, after in self._steps(state)]
            self.successors[state] = following
            for after in following:
                if after not in self.successors:
                    if len(self.successors) >= max_states:
                        raise TooLarge(f"{problem.name}: more than {max_states} states")
                    self.successors[after] = []
                    frontier.append(after)
        self.distance = self._distances_to_goal()
        self._cost_to_go: dict[tuple[State, tuple[Goal, ...]], float] = {}
        self._goal_successors: dict[tuple[Goal, State], list[State]] = {}

    @property
    def optimum(self) -> float:
        """The length of a shortest plan (``inf`` when there is none)."""
        return self.distance[self.initial]

    def _steps(self, state: State) -> Iterator[tuple[OperatorSchema, dict[Param, Term], State]]:
        closed = self._closed(state)
        for schema in self.problem.operators:
            for binding in self._bindings(schema.precondition, schema.parameters, {}, closed):
                yield schema, binding, self.simulator.apply(schema, binding, state)

    def _bindings(
        self,
        condition: Formula,
        parameters: Sequence[Param],
        bound: Mapping[Param, Term],
        closed: State,
    ) -> Iterator[dict[Param, Term]]:
        """Every binding of ``parameters`` (beyond ``bound``) under which ``condition``
        holds in the closed state: atoms among its conjuncts bind what they can, the
        rest range over the problem's constants."""
        by_predicate: dict[tuple[str, int], list[Atom]] = defaultdict(list)
        for atom in closed:
            by_predicate[atom[0], len(atom)].append(atom)
        envs: list[dict[Param, Term]] = [dict(bound)]
        for atom in _conjunct_atoms(condition):
            envs = [
                extended
                for env in envs
                for fact in by_predicate.get((atom[0], len(atom)), ())
                if (extended := match_pattern(atom, fact, env)) is not None
            ]
        wanted = list(dict.fromkeys([*parameters, *params_in(condition)]))
        for env in envs:
            free = [p for p in wanted if p not in env]
            for values in itertools.product(self.problem.constants, repeat=len(free)):
                full = {**env, **dict(zip(free, values))}
                if self.simulator.holds(condition, full, closed):
                    yield full

    def _distances_to_goal(self) -> dict[State, float]:
        predecessors: dict[State, list[State]] = defaultdict(list)
        for state, following in self.successors.items():
            for after in following:
                predecessors[after].append(state)
        distance: dict[State, float] = dict.fromkeys(self.successors, UNREACHABLE)
        frontier = deque(s for s in self.successors if self.goal_holds(s))
        for state in frontier:
            distance[state] = 0
        while frontier:
            state = frontier.popleft()
            for before in predecessors[state]:
                if distance[before] == UNREACHABLE:
                    distance[before] = distance[state] + 1
                    frontier.append(before)
        return distance

    def goal_holds(self, state: State) -> bool:
        return self.simulator.holds(self.problem.goal, {}, self._closed(state))

    def cost_to_go(self, state: State, goals: Sequence[Goal]) -> float:
        """The fewest steps from ``state`` that apply the operators of ``goals`` in order,
        each when its goal (its precondition) holds, and end where the last goal (G0)
        holds; any other steps may come in between. For the goal list of a forward
        search, ``(G0,)``, that is the distance to the goal."""
        key = (state, tuple(goals))
        known = self._cost_to_go.get(key)
        if known is None:
            known = self._cost_to_go[key] = self._search_cost_to_go(state, goals)
        return known

    def _search_cost_to_go(self, state: State, goals: Sequence[Goal]) -> float:
        """Breadth-first over (state, goals done); once only G0 is left the rest is the
        state's distance to the goal, so the search stops when no shorter total is left."""
        last = len(goals) - 1
        best = self.distance.get(state, UNREACHABLE) if last == 0 else UNREACHABLE
        seen = {(state, 0)}
        frontier: deque[tuple[State, int, int]] = deque([(state, 0, 0)])
        while frontier:
            current, index, steps = frontier.popleft()
            if steps + 1 >= best:
                break
            goal = goals[index]
            following = [(after, index) for after in self.successors.get(current, ())]
            if goal.operator is not None:
                following += [(after, index + 1) for after in self._goal_steps(goal, current)]
            for after, done in following:
                if done == last:
                    best = min(best, steps + 1 + self.distance.get(after, UNREACHABLE))
                elif (after, done) not in seen:
                    seen.add((after, done))
                    frontier.append((after, done, steps + 1))
        return best

    def _closed(self, state: State) -> State:
        closed = self._closures.get(state)
        if closed is None:
            closed = self._closures[state] = self.simulator.close(state)
        return closed

    def _goal_steps(self, goal: Goal, state: State) -> list[State]:
        """The states after applying the goal's operator where its goal holds (cached:
        the nodes of one search share goals)."""
        key = (goal, state)
        known = self._goal_successors.get(key)
        if known is None:
            operator = goal.operator
            assert operator is not None
            bindings = self._bindings(
                goal.formula, operator.schema.parameters, operator.binding_map(), self._closed(state)
            )
            known = [self.simulator.apply(operator.schema, b, state) for b in bindings]
            self._goal_successors[key] = known
        return known


def _conjunct_atoms(formula: Formula) -> Iterator[Atom]:
    if isinstance(formula, Atomic) and formula.atom[0] != EQUALITY:
        yield formula.atom
    elif isinstance(formula, And):
        for part in formula.parts:
            yield from _conjunct_atoms(part)

