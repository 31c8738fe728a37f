"""``lifted-alt-bfws``: Powerlifted's alternated BFWS over lifted states. What is named
here: the heuristic is computed only for states taken for expansion; every generated
child's (#g, #r) and width-1 novelty are those of its whole state; a child is preferred
exactly when it gains an atom useful in its parent's relaxed plan (or a preferred
instance made it); the four lists alternate as Powerlifted's; limits and counts; valid
plans on the seeded random tasks and the example domains."""

from __future__ import annotations

import math
import sys
from collections.abc import Sequence
from pathlib import Path

import pytest

from strips_framework.lifted.alt_bfws import LiftedAlternatedBFWS, _Alternation
from strips_framework.lifted.components import ActionInstance, Guidance, LiftedState, with_guidance
from strips_framework.lifted.goal_count import GoalLiterals, LiftedGoalCount
from strips_framework.lifted.novelty import Novelty
from strips_framework.lifted.search import LiftedRun
from strips_framework.lifted.space import NO_PARENT
from strips_framework.lifted.successors import Successors
from strips_framework.lifted.task import LiftedTask
from strips_framework.limits import Clock, Limits
from strips_framework.pddl import PddlTask, load_task, parse_task
from strips_framework.pddl.validate import validate_plan
from strips_framework.plugin.registry import Registry
from strips_framework.result import Status

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "plugins" / "evaluators" / "tests"))
from random_pddl import random_pddl_task  # noqa: E402 - the evaluators' seeded random tasks

EXAMPLES = Path(__file__).resolve().parents[1] / "examples" / "pddl"


def _ff(pddl: PddlTask):  # noqa: ANN202 - the plugin's estimator type
    registry = Registry.from_plugins()
    if "ff" not in registry.names("lifted-heuristic"):
        pytest.skip("the evaluators plugin (lifted hFF) is not installed")
    return registry.get("lifted-heuristic", "ff").cls().for_task(pddl)


class _Counting:
    """An estimator that records every state it rates, and what it answered."""

    def __init__(self, inner: object) -> None:
        self.guide = with_guidance(inner)  # type: ignore[arg-type]
        self.rated: dict[LiftedState, Guidance] = {}
        self.calls = 0

    def estimate(self, state: LiftedState) -> float:
        return self.estimate_with_guidance(state).value

    def estimate_with_preferred(self, state: LiftedState) -> tuple[float, Sequence[ActionInstance]]:
        guidance = self.estimate_with_guidance(state)
        return guidance.value, guidance.preferred

    def estimate_with_guidance(self, state: LiftedState) -> Guidance:
        self.calls += 1
        self.rated[state] = guidance = self.guide(state)
        return guidance


class _Trace:
    """A search run directly, with its pushes recorded, (state number, h key, novelty
    key, preferred) in the order made, the state numbers popped and the novelty
    partitions asked."""

    def __init__(
        self, pddl: PddlTask, estimator: object, limits: Limits | None = None, **options: object
    ) -> None:
        self.successors = Successors(LiftedTask(pddl))
        self.run = LiftedRun(self.successors, estimator, limits or Limits(time=60), Clock(60))  # type: ignore[arg-type]
        self.pushes: list[tuple[int, tuple, tuple, bool]] = []
        self.pops: list[int] = []
        self.partitions: list[object] = []
        push, pop, novelty = _Alternation.push, _Alternation.pop, Novelty.of

        def recording(
            lists: _Alternation, number: int, h_key: tuple, novelty_key: tuple, preferred: bool
        ) -> None:
            self.pushes.append((number, h_key, novelty_key, preferred))
            push(lists, number, h_key, novelty_key, preferred)

        def popping(lists: _Alternation) -> int:
            self.pops.append(pop(lists))
            return self.pops[-1]

        def partitioned(
            table: Novelty, state: object, partition: object, added: object = None
        ) -> int:
            self.partitions.append(partition)
            return novelty(table, state, partition, added)  # type: ignore[arg-type]

        with pytest.MonkeyPatch.context() as patch:
            patch.setattr(_Alternation, "push", recording)
            patch.setattr(_Alternation, "pop", popping)
            patch.setattr(Novelty, "of", partitioned)
            self.goal = LiftedAlternatedBFWS(**options).run(self.run)  # type: ignore[arg-type]


TASKS = [random_pddl_task(seed) for seed in range(30)]


@pytest.mark.parametrize("seed", range(30))
def test_plans_are_valid_and_unsolvable_means_unsolvable(seed: int) -> None:
    pddl = TASKS[seed]
    for estimator in (LiftedGoalCount().for_task(pddl), _ff(pddl)):
        result = LiftedAlternatedBFWS().search_task(
            Successors(LiftedTask(pddl)), estimator, Limits(time=30)
        )
        if result.status == Status.UNSOLVABLE:
            from strips_framework.lifted.search import LiftedLazyGreedySearch

            blind = LiftedLazyGreedySearch().search_task(
                Successors(LiftedTask(pddl)), LiftedGoalCount().for_task(pddl), Limits(time=30)
            )
            assert blind.status == Status.UNSOLVABLE
            continue
        assert result.status == Status.SOLVED
        check = validate_plan(pddl, result.plan)
        assert check.valid, check
        assert check.cost == result.cost


def test_the_heuristic_is_computed_only_for_states_taken_for_expansion() -> None:
    """Every state rated was expanded or found a dead end when taken; none merely
    generated was rated (Powerlifted's point: hFF costs, a child's counts do not)."""
    expanded = generated = 0
    for pddl in TASKS:
        counting = _Counting(_ff(pddl))
        trace = _Trace(pddl, counting)
        run = trace.run
        assert counting.calls == run.evaluated == run.expanded + run.dead_ends
        assert len(counting.rated) == counting.calls  # no state rated twice
        assert set(counting.rated) <= {run.space.state(number) for number in [0, *trace.pops]}
        expanded += run.expanded
        generated += len(run.space)
    assert generated > 3 * expanded > 30, (generated, expanded)


def _whole_state_keys(trace: _Trace, relevant: frozenset) -> list[tuple]:
    """Each pushed child's novelty key, computed from its whole state, with a fresh
    novelty table fed in the same order; the partitions, (#g, #r), are checked against
    those the search asked for."""
    space, goal = trace.run.space, GoalLiterals(trace.successors.task)
    novelty = Novelty()
    keys, partitions = [], []
    for number, _, _, _ in trace.pushes:
        state = space.state(number)
        if goal.simple:
            goals = goal.missing(state)
        else:
            goals = 0 if trace.successors.is_goal(trace.successors.facts(state)) else 1
        counts = (goals, sum(1 for atom in relevant if atom not in state))
        partitions.append(counts)
        keys.append((novelty.of(state, counts), goals, space.g[number]))
    assert partitions == trace.partitions
    return keys


def test_each_childs_counts_and_novelty_are_those_of_its_whole_state() -> None:
    """#g and #r kept from the parent's by the atoms an action changed, and novelty
    tested on the gained atoms within an unchanged partition, equal the whole state's;
    the h key is the parent's estimate and the child's g."""
    novel = stale = relevant_seen = 0
    blocks = [
        _blocks(6, "(and (on b1 b0) (on b2 b1) (on b5 b3) (on b4 b5))"),
        _blocks(5, "(and (on b0 b4))"),
    ]
    for pddl in [*TASKS, *blocks]:  # in blocks a relevant atom (holding b1) comes and goes
        counting = _Counting(_ff(pddl))
        trace = _Trace(pddl, counting)
        space = trace.run.space
        relevant = counting.rated.get(space.state(0), Guidance(math.inf)).useful
        relevant_seen += bool(relevant)
        assert [key for _, _, key, _ in trace.pushes] == _whole_state_keys(trace, relevant)
        for number, h_key, _, _ in trace.pushes[1:]:
            parent = space.parents[number]
            assert h_key == (counting.rated[space.state(parent)].value, space.g[number])
        novel += sum(key[0] == 1 for _, _, key, _ in trace.pushes)
        stale += sum(key[0] == 2 for _, _, key, _ in trace.pushes)
    assert novel > 20 and stale > 20 and relevant_seen > 10, (novel, stale, relevant_seen)


@pytest.mark.parametrize("useful_atoms", [False, True])
def test_a_child_is_preferred_when_a_preferred_instance_makes_it(useful_atoms: bool) -> None:
    """By default, when one of its parent's preferred instances made it; with
    ``useful_atoms``, also when it gains an atom useful in its parent's relaxed plan
    (Powerlifted's test). Without ``preferred``, none is."""
    preferred = plain = by_atoms_only = 0
    blocks = _blocks(6, "(and (on b1 b0) (on b2 b1) (on b5 b3) (on b4 b5))")
    for pddl in [*TASKS, blocks]:
        counting = _Counting(_ff(pddl))
        trace = _Trace(pddl, counting, useful_atoms=useful_atoms)
        space = trace.run.space
        for number, _, _, flagged in trace.pushes[1:]:
            parent = space.state(space.parents[number])
            gained = space.state(number) - parent
            guidance = counting.rated[parent]
            by_instance = space.steps[number] in guidance.preferred
            by_atoms = bool(gained & guidance.useful)
            assert flagged == (by_instance or (useful_atoms and by_atoms))
            preferred += flagged
            plain += not flagged
            by_atoms_only += by_atoms and not by_instance
        quiet = _Trace(pddl, _Counting(_ff(pddl)), preferred=False, useful_atoms=useful_atoms)
        assert not any(flagged for *_, flagged in quiet.pushes)
    assert preferred > 20 and plain > 20 and by_atoms_only > 5, (preferred, plain, by_atoms_only)


class _PreferredOnly:
    """Goal count with one preferred instance per state (the first applicable in name
    order), and no useful atoms: how a heuristic without a relaxed plan guides."""

    def __init__(self, pddl: PddlTask) -> None:
        self.count = LiftedGoalCount().for_task(pddl)
        self.successors = Successors(LiftedTask(pddl))

    def estimate(self, state: LiftedState) -> float:
        return self.count.estimate(state)

    def estimate_with_preferred(self, state: LiftedState) -> tuple[float, Sequence[ActionInstance]]:
        steps = sorted(self.successors.applicable(self.successors.facts(state)))
        return self.estimate(state), steps[:1]


def test_a_heuristic_without_useful_atoms_counts_no_relevant_atoms_and_prefers_its_instances() -> (
    None
):
    preferred = 0
    for pddl in TASKS[:15]:
        trace = _Trace(pddl, _PreferredOnly(pddl))
        space = trace.run.space
        assert [key for _, _, key, _ in trace.pushes] == _whole_state_keys(trace, frozenset())
        for number, _, _, flagged in trace.pushes[1:]:
            parent = space.state(space.parents[number])
            first = sorted(trace.successors.applicable(trace.successors.facts(parent)))[:1]
            assert flagged == (space.steps[number] in first)
            preferred += flagged
    assert preferred > 10


def test_the_lists_alternate_as_powerlifteds() -> None:
    """The estimate's kind first, then the novelty's; a preferred twin while credit lasts
    (one spent per pop from it); progress adds ``boost``; a regular list emptied first
    leaves its twin's entries."""
    lists = _Alternation(credit=1, boost=2)
    # state, h key, novelty key, preferred
    lists.push(0, (5, 0), (2, 3, 0), False)
    lists.push(1, (4, 1), (1, 3, 1), False)
    lists.push(2, (6, 1), (2, 1, 1), True)
    lists.push(3, (6, 1), (1, 1, 1), True)
    assert lists.pop() == 2  # h kind, the preferred twin (credit 1 -> 0), first in of (6, 1)
    assert lists.pop() == 3  # novelty kind, no credit: the regular list's lowest, (1, 1, 1)
    assert lists.pop() == 1  # h kind, regular: (4, 1)
    lists.reward_progress()  # credit 2
    assert lists.pop() == 3  # novelty kind, its twin: (1, 1, 1)
    assert lists.credit == 1
    assert lists.pop() == 3  # h kind, its twin: what is left there
    assert lists.credit == 0
    assert [lists.pop() for _ in range(7)] == [1, 0, 2, 2, 0, 3, 2]  # the last from a twin
    assert not lists
    with pytest.raises(IndexError):
        lists.pop()


def test_limits_stop_it_with_its_counts() -> None:
    pddl = load_task(EXAMPLES / "blocksworld" / "domain.pddl", EXAMPLES / "blocksworld" / "p4.pddl")
    result = LiftedAlternatedBFWS().search_task(
        Successors(LiftedTask(pddl)),
        LiftedGoalCount().for_task(pddl),
        Limits(time=30, expansions=2),
    )
    assert result.status == Status.EXPANSION_LIMIT
    statistics = result.statistics
    assert statistics.expanded == 2 and statistics.evaluated == 2
    assert statistics.generated >= statistics.states - 1 >= 2  # both expansions whole
    late = LiftedAlternatedBFWS().search_task(
        Successors(LiftedTask(pddl)),
        LiftedGoalCount().for_task(pddl),
        Limits(time=30),
        Clock(1, started=-10.0),
    )
    assert late.status == Status.TIME_LIMIT and late.statistics.expanded == 0


def _blocks(count: int, goal: str) -> PddlTask:
    domain = (EXAMPLES / "blocksworld" / "domain.pddl").read_text()
    names = " ".join(f"b{i}" for i in range(count))
    init = " ".join(f"(ontable b{i}) (clear b{i})" for i in range(count))
    problem = f"""(define (problem blocks{count}) (:domain blocksworld) (:objects {names} - block)
 (:init (handempty) {init}) (:goal {goal}))"""
    return parse_task(domain, problem)


_LOCKED = """(define (domain locked) (:requirements :strips)
 (:predicates (key ?k) (door ?d) (open ?d) (fits ?k ?d) (ready) (done))
 (:action drop :parameters (?k) :precondition (key ?k) :effect (not (key ?k)))
 (:action prepare :parameters () :precondition (and) :effect (ready))
 (:action unlock :parameters (?k ?d) :precondition (and (key ?k) (door ?d) (fits ?k ?d) (ready))
  :effect (open ?d))
 (:action finish :parameters (?d) :precondition (open ?d) :effect (done)))"""


def test_every_reachable_state_once_then_unsolvable_and_dead_ends_are_not_expanded() -> None:
    pddl = _blocks(4, "(and (on b0 b0))")
    result = LiftedAlternatedBFWS().search_task(
        Successors(LiftedTask(pddl)), LiftedGoalCount().for_task(pddl), Limits(time=30)
    )
    assert result.status == Status.UNSOLVABLE
    assert result.statistics.states == 125 == result.statistics.expanded
    assert result.statistics.generated > 125
    # k1 fits d2 only, d1 has no key: hFF finds the initial state a dead end.
    problem = """(define (problem p) (:domain locked) (:objects k1 d1 d2)
     (:init (key k1) (door d1) (door d2) (fits k1 d2)) (:goal (open d1)))"""
    locked = parse_task(_LOCKED, problem)
    dead = LiftedAlternatedBFWS().search_task(
        Successors(LiftedTask(locked)), _ff(locked), Limits(time=30)
    )
    assert dead.status == Status.UNSOLVABLE
    assert (dead.statistics.expanded, dead.statistics.evaluated, dead.statistics.dead_ends) == (
        0,
        1,
        1,
    )
    # Goal (done) with the key kept: a state that dropped it is a dead end, rated when
    # taken (the h list gives it first: its action comes first) and not expanded.
    locked = parse_task(
        _LOCKED, problem.replace("(:goal (open d1))", "(:goal (and (done) (key k1)))")
    )
    counting = _Counting(_ff(locked))
    trace = _Trace(locked, counting, preferred=False)
    assert trace.goal is not None
    space = trace.run.space
    dead_ends = {space.ids[space.pack(s)] for s, g in counting.rated.items() if g.value == math.inf}
    assert dead_ends and trace.run.dead_ends == len(dead_ends)
    assert dead_ends <= set(trace.pops)
    assert not dead_ends & set(space.parents)  # no state generated from a dead end


def test_the_goal_is_tested_on_generation_and_the_plan_read_back() -> None:
    pddl = _blocks(5, "(and (on b1 b0) (on b2 b1))")
    trace = _Trace(pddl, _Counting(_ff(pddl)))
    assert trace.goal is not None and trace.run.space.parents[0] == NO_PARENT
    steps = trace.run.space.plan_to(trace.goal)
    assert validate_plan(pddl, [f"({name} {' '.join(args)})" for name, args in steps]).valid
    assert trace.goal not in trace.pops  # found when generated, never taken
    assert trace.run.expanded >= len(steps)


_SWITCH = """(define (domain switch) (:requirements :strips :negative-preconditions)
 (:predicates (on ?s) (wired ?s) (lit))
 (:action flip :parameters (?s) :precondition (and (wired ?s) (not (on ?s))) :effect (and (on ?s) (lit)))
 (:action unflip :parameters (?s) :precondition (on ?s) :effect (not (on ?s))))"""


@pytest.mark.parametrize(
    ("goal", "missing", "unreachable"),
    [
        ("(and (lit) (not (on s1)))", 1, False),
        ("(and (lit) (wired s2))", 1, False),
        ("(and (lit) (wired s1))", 1, True),  # a static atom that is false
        ("(and (lit) (not (wired s2)))", 1, True),  # a static atom negated that holds
    ],
)
def test_goal_literals_count_fluent_literals_and_settle_static_ones(
    goal: str, missing: int, unreachable: bool
) -> None:
    problem = f"""(define (problem p) (:domain switch) (:objects s1 s2)
     (:init (wired s2)) (:goal {goal}))"""
    task = LiftedTask(parse_task(_SWITCH, problem))
    literals = GoalLiterals(task)
    assert literals.simple and literals.unreachable == unreachable
    assert literals.missing(task.init) == missing
    after = frozenset({("on", "s2"), ("lit",)})
    assert literals.missing(after) == 0 == missing + literals.change(set(), set(after))
    negated = int("(not (on s1))" in goal)
    on = {("on", "s1")}
    assert literals.change(set(), on) == negated == -literals.change(on, set())
    assert literals.missing(after | on) == negated
    estimate = LiftedGoalCount().for_task(parse_task(_SWITCH, problem)).estimate(task.init)
    assert estimate == (math.inf if unreachable else missing)
