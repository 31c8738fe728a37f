"""One means-ends search (see :mod:`strips_framework.means_ends.strategy`): the queue of
nodes, the nodes made so far, and the GPS-style step from a node to its successor. Kept
apart from the strategy class so that registering the strategy imports none of this."""

from __future__ import annotations

import heapq
from collections.abc import Iterator

from strips_framework.limits import Clock, LimitReached, Limits
from strips_framework.logic.formulas import Formula, atoms_of
from strips_framework.logic.terms import Atom, is_ground
from strips_framework.means_ends.components import (
    DifferenceExtractor,
    NodeEvaluator,
    RelevanceFilter,
    evaluator_for_problem,
)
from strips_framework.means_ends.goal_order import needed_first
from strips_framework.means_ends.goal_prover import GoalProver
from strips_framework.means_ends.node import Difference, Goal, Node, RelevantInstance
from strips_framework.means_ends.tree import SearchTree
from strips_framework.result import Result, Status
from strips_framework.worldmodel.operators import OperatorInstance
from strips_framework.worldmodel.problem import Problem
from strips_framework.worldmodel.proving import ProofResult
from strips_framework.worldmodel.world import WorldModel


class MeansEndsRun:
    """The state of one means-ends search."""

    def __init__(
        self,
        max_goals: int,
        problem: Problem,
        goal_prover: GoalProver,
        differences: DifferenceExtractor,
        relevance: RelevanceFilter,
        evaluator: NodeEvaluator,
        limits: Limits,
        clock: Clock,
        tree: SearchTree | None = None,
        planned: tuple[Goal, ...] = (),
        parent: Node | None = None,
        max_nodes: int | None = None,
        distinct_plans: bool = False,
        goal_loops: bool = False,
        achiever_loops: bool = False,
        agenda_only: bool = False,
    ) -> None:
        self.max_goals = max_goals
        self.goal_prover = goal_prover
        self.differences = differences
        self.relevance = relevance.for_problem(problem.operators, goal_prover.initial)
        self.evaluator = evaluator_for_problem(evaluator, problem.operators, goal_prover.initial)
        self.tree = tree or SearchTree(limits, goal_prover, clock)
        self.queue: list[tuple[float, int, Node]] = []
        self.pushes = 0
        self.seen: set[tuple[object, ...]] = set()
        self.analysed: dict[
            tuple[WorldModel, Formula], tuple[Difference, list[RelevantInstance] | None]
        ] = {}
        self.top_goal = Goal(problem.goal)
        # The root's goal list: the goals of a plan made at a more abstract level, or
        # the entries of a goal agenda (conjunctions of G0's atoms; no operator), if
        # any, then G0. Subgoaling depth (``max_goals``) and the dropping of goals a deeper
        # one makes unnecessary count only the goals pushed above them.
        self.start = (*planned, self.top_goal)
        self.planned = frozenset(self.start)
        # The planned goals are a goal agenda, a guide the search may drop: see
        # :meth:`solutions`.
        self.agenda_only = agenda_only
        self.parent = parent
        self.max_nodes = max_nodes
        self.distinct_plans = distinct_plans
        self.goal_loops = goal_loops
        self.achiever_loops = achiever_loops
        self.operators = tuple(problem.operators)
        self.first_needs: dict[tuple[Atom, Atom, WorldModel], bool] = {}

    def solutions(self) -> Iterator[Node]:
        """The goal nodes of the search, in the order found: asked for another, the
        search goes on from where it stopped (ABSTRIPS asks again when a plan cannot be
        refined). Stops when the queue is empty or ``max_nodes`` nodes were made.

        With ``agenda_only``, an empty queue starts the search again from a second root
        whose goal list is G0 alone: the agenda commits the search to the models where
        its first entries hold, and means-ends, bounded by ``max_goals`` and offering
        only the instances its differences make relevant, may find no way on from any
        of them (depot 10 of IPC 2002 with means-ends-relaxed.toml: *exhausted* after
        2,042 nodes; solved in 2,869 without the agenda). Nodes of the first search
        stay in the tree and count against the limits."""
        first = len(self.tree.nodes)
        starts = [self.start]
        if self.agenda_only and len(self.start) > 1:
            starts.append((self.top_goal,))
        for start in starts:
            self.start, self.planned = start, frozenset(start)
            solution = self._make(self.goal_prover.root_model(), start, self.parent, ())
            if solution is not None:
                yield solution
            while self.queue:
                if self.max_nodes is not None and len(self.tree.nodes) - first >= self.max_nodes:
                    return
                self.tree.check_time()
                _, _, node = heapq.heappop(self.queue)
                solution = self._expand(node)
                if solution is not None:
                    yield solution

    def search(self) -> Result:
        try:
            solution = next(self.solutions(), None)
        except LimitReached as limit:
            return self.tree.result(limit.status, None)
        except KeyboardInterrupt:  # Ctrl-C: report what the search did so far
            return self.tree.result(Status.INTERRUPTED, None)
        return self.tree.result(Status.SOLVED if solution else Status.EXHAUSTED, solution)

    def _push(self, node: Node) -> None:
        self.pushes += 1
        heapq.heappush(self.queue, (self.evaluator.evaluate(node), self.pushes, node))

    def _expand(self, node: Node) -> Node | None:
        """Make the successor of ``node`` for its next relevant instance."""
        instance = node.pending.pop(0)
        node.successors_generated += 1
        if node.pending:
            self._push(node)
        subgoal = Goal(instance.operator.precondition(), instance.operator)
        return self._make(node.model, (subgoal, *node.goals), node, node.plan)

    def _make(
        self,
        model: WorldModel,
        goals: tuple[Goal, ...],
        parent: Node | None,
        plan: tuple[OperatorInstance, ...],
        applied: OperatorInstance | None = None,
    ) -> Node | None:
        """Make a node and try its first goal; return the goal node if the task is solved.
        A (model, goal list) already made is not made again: its node is the same
        problem, already in the tree (on depot, a quarter of the successors repeat one).

        After an application, goals a deeper goal makes unnecessary are dropped
        (:meth:`_skip_achieved`). Proved preconditions are applied in a loop rather than
        by recursion, since a chain of applications can be as long as the goal list.
        """
        while True:
            if applied is not None:
                goals = self._skip_achieved(model, goals)
            key = self._key(model, goals, plan)
            if key in self.seen:
                return None  # the same problem is already being worked on elsewhere
            self.seen.add(key)
            node = self.tree.new_node(model, goals, parent, plan, applied)
            first = goals[0]
            result = self.goal_prover.attempt(model, first.formula)
            if not result.proved:
                self._set_difference(node, result)
                return None
            if first.operator is None and len(goals) == 1:
                return node
            if first.operator is None:  # a goal-agenda entry achieved: on to the next
                goals, parent, applied = goals[1:], node, None
                continue
            operator = first.operator.bind(dict(result.answers[0]))
            if not operator.is_ground or not operator.admits():
                return None  # a parameter of the effects left unbound, or a binding refused
            model, goals, parent = operator.apply(model), goals[1:], node
            plan, applied = (*plan, *operator.steps()), operator

    def _key(
        self, model: WorldModel, goals: tuple[Goal, ...], plan: tuple[OperatorInstance, ...]
    ) -> tuple[object, ...]:
        """What makes a node a repeat: its model and goal list. With ``distinct_plans``
        (a search whose plans are refined further, where two plans to one model may
        refine differently) a node back at the root's goal list also keeps its plan."""
        if self.distinct_plans and goals == self.start:
            return (model, goals, plan)
        return (model, goals)

    def _skip_achieved(self, model: WorldModel, goals: tuple[Goal, ...]) -> tuple[Goal, ...]:
        """The goal list from its deepest goal that ``model`` already satisfies (``goals``
        when none below the first does). A goal-list operator is there to help achieve the
        goal below it, so once an application makes a deeper goal true the operators
        above it are not needed: STRIPS applies that goal's operator (or, at G0, is done)
        instead of working through them. Goals below the first planned one (a refined
        plan's steps, or G0) are not looked at: a planned step is there for what comes
        after it, not for the goal above it. Only a changed model can make a deeper goal true
        (each was unproved when it was pushed down), so only nodes made by an application
        are checked; the proofs are cached per (model, goal), and a goal with a
        conjunct no fact can match is not tried (:meth:`GoalProver.cannot_hold`)."""
        deepest = next(i for i, goal in enumerate(goals) if goal in self.planned)
        for depth in range(deepest, 0, -1):
            formula = goals[depth].formula
            if self.goal_prover.decide(model, formula) is False:
                continue
            if self.goal_prover.prove(model, formula).proved:
                return goals[depth:]
        return goals

    def _set_difference(self, node: Node, result: ProofResult) -> None:
        """The difference and relevant instances depend on the model and the first goal
        only, so nodes that share them (a subproblem reached under different goal
        lists) share one computation of each."""
        key = (node.model, node.goals[0].formula)
        known = self.analysed.get(key)
        if known is None:
            negated = self.goal_prover.negated(node.goals[0].formula)
            known = (self.differences.extract(result, negated), None)
            self.analysed[key] = known
        node.difference, relevant = known
        pushed = sum(1 for goal in node.goals if goal not in self.planned)
        if pushed + 1 >= self.max_goals:
            return
        if relevant is None:
            relevant = self.relevance.relevant(node.difference, node.model)
            self.analysed[key] = (node.difference, relevant)
        on_goal_list = {goal.operator for goal in node.goals}
        looping = self._looping_atoms(node) if self.goal_loops else set()
        wanted = self._wanted_atoms(node) if self.achiever_loops else set()
        node.pending = [
            found for found in relevant
            if found.operator not in on_goal_list
            and (not looping or looping.isdisjoint(atoms_of(found.operator.precondition())))
            and (not wanted or not self._needs_first(found.operator, wanted, node.model))
        ]
        if node.pending:
            self._push(node)

    def _wanted_atoms(self, node: Node) -> set[Atom]:
        """The ground atoms of the node's first goal that its model lacks: what a
        relevant instance for it is there to add."""
        return {
            atom for atom in atoms_of(node.goals[0].formula)
            if is_ground(atom) and not node.model.holds(atom)
        }

    def _needs_first(
        self, instance: OperatorInstance, wanted: set[Atom], model: WorldModel
    ) -> bool:
        """Whether ``instance`` needs, before it can add an atom of ``wanted``, an atom
        that only that wanted atom lets an operator make (``achiever_loops``): its
        subgoal would go round in a circle, two levels deep, where ``goal_loops`` looks
        one level deep. ``drop(x, crate5, z, p)``, offered for ``clear(crate5)``, needs
        ``lifting(x, crate5)``, and a crate on a stack is only lifted once it is clear
        (:func:`~strips_framework.means_ends.goal_order.needed_first`)."""
        adds = [atom for atom in instance.effects()[1] if atom in wanted]
        for atom in adds:
            for need in atoms_of(instance.precondition()):
                key = (need, atom, model)
                known = self.first_needs.get(key)
                if known is None:
                    known = self.first_needs[key] = needed_first(
                        need, atom, self.operators, model)
                if known:
                    return True
        return False

    def _looping_atoms(self, node: Node) -> set[Atom]:
        """What a subgoal pushed at ``node`` must not need: the ground atoms that the
        first goal's operator adds, that the goal below it needs and that the model
        lacks. That operator was pushed to achieve them, so an instance for its
        precondition that needs one of them first is a goal loop (GPS's check, one
        level deep): ``lift(x, y, pallet2, p)``, pushed to clear pallet2 for a drop onto
        it, would get ``drop(x, crate9, pallet2, p)`` for its ``on(y, pallet2)``, and
        that drop needs pallet2 clear. Only a pushed first goal is looked at (a planned
        one is not there for the goal below it)."""
        first = node.goals[0]
        if first.operator is None or first in self.planned or len(node.goals) < 2:
            return set()
        below = set(atoms_of(node.goals[1].formula))
        return {
            atom for atom in first.operator.effects()[1]
            if atom in below and is_ground(atom) and not node.model.holds(atom)
        }
