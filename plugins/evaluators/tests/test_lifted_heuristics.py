"""The lifted heuristics against their ground namesakes, on every state a breadth-first
search reaches (up to a bound) in small tasks: local PDDL tasks, random lifted tasks with
types, constants, equality, negative and disjunctive preconditions, derived predicates,
conditional effects and action costs (:mod:`random_pddl`), and the first task of a few
IPC domains (../shared, or the repository's copy of them).

hadd, hmax and goal count must be equal. hFF may differ where several supporters are
equally cheap, so it is checked for what holds whatever the choice: it lies between hmax
and hadd, its relaxed plan supports every goal fact and every precondition it uses, it
costs what the value says, and its preferred operators apply in the state and are ground
operators of the task.
"""

from __future__ import annotations

import math
from collections import deque
from pathlib import Path

import pytest
from random_pddl import random_pddl_task
from shared_bench import small_bench

from strips_evaluators.heuristics.additive import AdditiveHeuristic
from strips_evaluators.heuristics.ff import FFHeuristic
from strips_evaluators.heuristics.goal_count import GoalCountHeuristic
from strips_evaluators.heuristics.hmax import MaxHeuristic
from strips_evaluators.lifted.closure import DerivedClosure
from strips_evaluators.lifted.exploration import Exploration, action_instance, relaxed_plan
from strips_evaluators.lifted.heuristics import (
    LiftedAdditive,
    LiftedFF,
    LiftedGoalCount,
    LiftedMax,
)
from strips_evaluators.lifted.program import AXIOM, Program
from strips_framework.grounding import ground
from strips_framework.grounding.axioms import AxiomEvaluator
from strips_framework.grounding.task import GroundTask
from strips_framework.lifted.components import LiftedState
from strips_framework.pddl import PddlTask, find_domain, load_task

ROOT = Path(__file__).parents[3]
DATA = ROOT / "tests" / "pddl" / "data"
IPC = small_bench("ipc")
LOCAL = ["blocks-3", "briefcase-2", "crates-3", "elevator-1", "lamps-1", "rooms-1", "rooms-2",
         "switches-1"]  # fmt: skip
SMALL_IPC = ["blocks", "gripper", "logistics", "miconic", "satellite", "rovers"]


def lifted_state(task: GroundTask, state: int, basic: set[str]) -> LiftedState:
    """The fluent atoms of a ground state (derived and made-up facts left out)."""
    atoms = (tuple(name[1:-1].split()) for name in task.facts_of(state))
    return frozenset(atom for atom in atoms if atom[0] in basic)


def reachable(task: GroundTask, limit: int) -> list[int]:
    """The first ``limit`` states of a breadth-first search from the initial state."""
    evaluator = AxiomEvaluator(task)
    seen = {task.init}
    queue = deque([task.init])
    found = []
    while queue and len(found) < limit:
        state = queue.popleft()
        found.append(state)
        for op in task.operators:
            if op.applicable(state):
                successor = evaluator.evaluate(op.apply(state))
                if successor not in seen:
                    seen.add(successor)
                    queue.append(successor)
    return found


def compare(task: PddlTask, limit: int) -> int:
    """Compares every heuristic on up to ``limit`` reachable states; the number of
    states where lifted and ground hFF are equal."""
    grounded = ground(task, prune_irrelevant=False)
    changed = {atom.predicate for action in task.domain.actions for atom in action.changed_atoms()}
    ground_h = {
        "hadd": AdditiveHeuristic().for_task(grounded),
        "hmax": MaxHeuristic().for_task(grounded),
        "goal-count": GoalCountHeuristic().for_task(grounded),
        "ff": FFHeuristic().for_task(grounded),
    }
    lifted_h = {
        "hadd": LiftedAdditive().for_task(task),
        "hmax": LiftedMax().for_task(task),
        "goal-count": LiftedGoalCount().for_task(task),
        "ff": LiftedFF().for_task(task),
    }
    program = Program(task)
    exploration = Exploration(program)
    closure = DerivedClosure(program)
    names = {op.name for op in grounded.operators}
    equal_ff = 0
    for state in reachable(grounded, limit):
        lifted = lifted_state(grounded, state, changed)
        values = {}
        for name in ("hadd", "hmax", "goal-count"):
            values[name] = lifted_h[name].estimate(lifted)
            assert values[name] == ground_h[name].estimate(state), (name, sorted(lifted))
        ff, preferred = lifted_h["ff"].estimate_with_preferred(lifted)
        assert ff == lifted_h["ff"].estimate(lifted)
        assert values["hmax"] <= ff <= values["hadd"]
        assert (ff == 0) == (values["hadd"] == 0) and (ff == math.inf) == (values["hadd"] == math.inf)
        equal_ff += ff == ground_h["ff"].estimate(state)
        plan = check_relaxed_plan(program, exploration, lifted, ff)
        model = closure.model(lifted)
        assert {a for a in model if not a[0].startswith("@")} == lifted_state(
            grounded, state, changed | {rule.head.predicate for rule in task.domain.derived}
        )
        for action, args in preferred:
            name = "(" + " ".join((action, *args)) + ")"
            assert name in names
            assert any(op.name == name and op.applicable(state) for op in grounded.operators)
        # The relaxed plan is made of the task's own rule instances (split rules rebuilt
        # from their parts), and each action instance whose body holds is preferred.
        assert not any(f[0].startswith("@part") for _, body, _ in plan for f in body)
        expected = {
            action_instance(program, rule, slots)
            for rule, body, slots in plan
            if rule.action != AXIOM and all(fact in model for fact in body)
            and not any((n, *[slots[i] for i in terms]) in model for n, terms in rule.negative)
        }
        assert expected <= set(preferred)
        # Its guidance: the same value and preferred instances, and as useful atoms the
        # facts the plan achieves (the goal's and its instances' body facts the state
        # lacks), but for derived ones: no state holds those.
        guidance = lifted_h["ff"].estimate_with_guidance(lifted)
        assert (guidance.value, list(guidance.preferred)) == (ff, list(preferred))
        subgoals = [*program.fluent_goal, *(fact for _, body, _ in plan for fact in body)]
        useful = {f for f in subgoals if f not in lifted and f[0] not in program.derived}
        assert guidance.useful == (useful if ff != math.inf else set())
        assert all(fact[0] in changed for fact in guidance.useful)
    return equal_ff


def check_relaxed_plan(program: Program, exploration: Exploration, state, value: float) -> list:
    """Checks the relaxed plan behind ``value``; its rule instances."""
    cost, supporter = exploration.costs(state, additive=True)
    total, plan = relaxed_plan(program, cost, supporter)
    assert total == value
    if value == math.inf:
        return []
    achieved = set(state)
    for rule, body, slots in plan.values():
        achieved.update((name, *[slots[s] for s in terms]) for name, terms in rule.heads)
    for fact in program.fluent_goal:
        assert fact in achieved
    operators = {}
    for rule, body, slots in plan.values():
        assert all(fact in achieved for fact in body)
        if rule.action != AXIOM:
            operators[(rule.action, rule.operator, slots[: rule.identity])] = program.cost_of(
                rule, list(slots)
            )
    assert sum(operators.values()) == value
    return list(plan.values())


@pytest.mark.parametrize("name", LOCAL)
def test_local_tasks(name):
    domain = DATA / (name.rsplit("-", 1)[0] + "-domain.pddl")
    compare(load_task(domain, DATA / f"{name}.pddl"), limit=60)


@pytest.mark.parametrize("seed", range(60))
def test_random_tasks(seed):
    compare(random_pddl_task(seed), limit=40)


@pytest.mark.parametrize("domain", SMALL_IPC)
def test_ipc_first_tasks(domain):
    problem = IPC / domain / "task01.pddl"
    compare(load_task(find_domain(problem), problem), limit=25)


@pytest.mark.parametrize("seed", range(20))
def test_each_rule_instance_is_found_once_and_only_if_it_improves(seed, monkeypatch):
    """Semi-naive evaluation: an instance is joined when its last body fact is settled
    and from its first atom that fact matches, never twice (the values would not show
    it, the time would). Branch and bound: an instance is completed only if it makes one
    of its heads cheaper (organic synthesis has thousands of instances per head), unless
    its cost depends on it or its last step binds a head; and, exploring until the goal is settled, only if it costs no
    more than every goal fact so far (nothing dearer is settled before the end)."""
    from strips_evaluators.lifted import exploration

    found: list[tuple] = []
    improving: list[bool] = []
    goal: list[tuple] = []
    join = exploration.costed_join

    def recording(program, plan, fact, lookup, cost, fire, functions, additive, limit):
        assert limit == max([cost.get(g, math.inf) for g in goal], default=math.inf)

        def record(plan, slots, matched, body):
            before = [cost.get(make(slots), math.inf) for make in plan.rule.makers]
            value = fire(plan, slots, matched, body)
            found.append((plan.rule.number, tuple(slots)))
            # (a cost per instance is only known complete: bounded by 0 before; heads the
            # last step binds are compared by ``fire`` alone)
            improving.append(
                any(value < old for old in before)
                or plan.rule.cost is None
                or plan.heads_at >= len(plan.steps)
            )
            improving[-1] &= body + (plan.rule.cost or 0) <= limit
            return value

        join(program, plan, fact, lookup, cost, record, functions, additive, limit)

    monkeypatch.setattr(exploration, "costed_join", recording)
    task = random_pddl_task(seed)
    program = Program(task)
    explorer = Exploration(program)
    grounded = ground(task, prune_irrelevant=False)
    changed = {atom.predicate for action in task.domain.actions for atom in action.changed_atoms()}
    for state in reachable(grounded, 10):
        for additive, until in [(True, ()), (False, ()), (True, None), (False, None)]:
            found.clear()
            goal[:] = program.fluent_goal if until is None else until
            explorer.costs(lifted_state(grounded, state, changed), additive, until)
            assert len(found) == len(set(found))
            assert all(improving)


SUBSTITUENTS_DOMAIN = """(define (domain substituents)
  (:predicates (q ?x ?y) (r ?y ?z) (s ?x) (g ?x))
  (:action a :parameters (?x ?y ?z)
    :precondition (and (s ?x) (q ?x ?y) (r ?y ?z) (not (= ?y ?z)))
    :effect (and (g ?x) (not (s ?x)) (not (q ?x ?y)) (not (r ?y ?z)))))"""


def test_instances_sharing_heads_are_completed_once(tmp_path, monkeypatch):
    """The action's heads name one of its three parameters: of the 4 x 4 x 3 instances
    whose body holds, one per head is completed (the first; the others cost the same).
    The ``s`` facts are settled last (the state's facts are queued in order), so each is
    the trigger that binds its instances' head before ``q`` and ``r`` are joined."""
    from strips_evaluators.lifted import exploration

    objects = [f"o{i}" for i in range(4)]
    init = [f"(s {x})" for x in objects]
    init += [f"({name} {x} {y})" for name in "qr" for x in objects for y in objects]
    (tmp_path / "domain.pddl").write_text(SUBSTITUENTS_DOMAIN)
    (tmp_path / "problem.pddl").write_text(
        f"(define (problem p) (:domain substituents) (:objects {' '.join(objects)})"
        f" (:init {' '.join(init)}) (:goal (g o0)))"
    )
    task = load_task(tmp_path / "domain.pddl", tmp_path / "problem.pddl")
    fired: list[tuple] = []
    join = exploration.costed_join

    def recording(program, plan, fact, lookup, cost, fire, functions, additive, limit):
        def record(plan, slots, matched, body):
            fired.append(tuple(slots))
            return fire(plan, slots, matched, body)

        join(program, plan, fact, lookup, cost, record, functions, additive, limit)

    monkeypatch.setattr(exploration, "costed_join", recording)
    explorer = Exploration(Program(task))
    state = frozenset(tuple(atom[1:-1].split()) for atom in init)
    for additive in (True, False):
        fired.clear()
        cost, _ = explorer.costs(state, additive, until=())
        assert {fact: value for fact, value in cost.items() if fact[0] == "g"} == {
            ("g", x): 1 for x in objects
        }
        assert len(fired) == len(objects)


LIMIT_DOMAIN = """(define (domain limit)
  (:predicates (a) (h) (t) (u) (g) (w))
  (:action mk-h :precondition (a) :effect (and (h) (not (a))))
  (:action mk-g :precondition (h) :effect (g))
  (:action mk-t :precondition (a) :effect (t))
  (:action mk-u :precondition (a) :effect (u))
  (:action mk-w :precondition (and (t) (u)) :effect (w)))"""


def test_instances_dearer_than_the_goal_are_not_completed(tmp_path):
    """``h`` is settled first at cost 1, so ``g``, the goal, costs 2 from then on; ``u``
    completes ``mk-w`` at 1 + 1 + 1 = 3: dearer than the goal, never settled before the
    exploration stops, so not completed (``w`` gets no cost)."""
    (tmp_path / "domain.pddl").write_text(LIMIT_DOMAIN)
    (tmp_path / "problem.pddl").write_text(
        "(define (problem p) (:domain limit) (:init (a)) (:goal (g)))"
    )
    explorer = Exploration(Program(load_task(tmp_path / "domain.pddl", tmp_path / "problem.pddl")))
    cost, _ = explorer.costs(frozenset({("a",)}), additive=True)
    assert cost[("g",)] == 2
    assert ("w",) not in cost
    cost, _ = explorer.costs(frozenset({("a",)}), additive=True, until=())
    assert cost[("w",)] == 3


NO_INSTANCE_DOMAIN = """(define (domain no-instance)
  (:requirements :typing)
  (:types mol metal - object)
  (:predicates (p ?x - mol) (q ?x - mol ?y - mol) (has ?m - metal) (catalyst ?c - object)
               (done ?x - mol))
  (:action finish :parameters (?x ?y - mol)
    :precondition (and (p ?x) (p ?y)) :effect (and (done ?x) (not (p ?y))))
  %s)"""
REACTIONS = """
  (:action react-with-metal :parameters (?x ?y - mol ?m - metal)
    :precondition (and (p ?x) (p ?y) (has ?m)) :effect (and (q ?x ?y) (not (p ?x))))
  (:action react-with-catalyst :parameters (?x ?y - mol ?c)
    :precondition (and (p ?x) (p ?y) (catalyst ?c)) :effect (q ?y ?x))"""


def test_actions_without_instances_add_no_rules(tmp_path):
    """Both reactions fall into parts (one per molecule and one for the metal or the
    catalyst), but no state has an instance of either: the task has no metal, and no
    catalyst fact (a static predicate). Their parts are not explored for nothing: the
    program has the rules of the same task without them, and the values are still the
    ground heuristics'."""
    programs = []
    for reactions in (REACTIONS, ""):
        (tmp_path / "domain.pddl").write_text(NO_INSTANCE_DOMAIN % reactions)
        (tmp_path / "problem.pddl").write_text(
            "(define (problem p) (:domain no-instance) (:objects a b c - mol)"
            " (:init (p a) (p b) (p c)) (:goal (and (done a) (done b))))"
        )
        task = load_task(tmp_path / "domain.pddl", tmp_path / "problem.pddl")
        programs.append(Program(task))
        compare(task, 20)
    with_reactions, without = programs
    assert len(with_reactions.rules) == len(without.rules)
    assert {rule.action for rule in with_reactions.rules} == {AXIOM, 0}  # finish


SHARED_FACT_DOMAIN = """(define (domain shared-fact)
  (:predicates (a ?x) (p ?x) (g))
  (:action make-p :parameters (?x) :precondition (a ?x) :effect (p ?x))
  (:action both :parameters (?x ?y) :precondition (and (p ?x) (p ?y)) :effect (g)))"""


def test_split_rules_count_a_fact_both_parts_match_once(tmp_path):
    """``both`` falls into two parts that can match the same ``p`` fact; its cheapest
    instance does (x = y = o1): hadd(g) = 1 + cost(p o1) = 2, as in the ground task,
    where the split rule alone would count (p o1) twice (3). The relaxed plan's instance
    of the rule with the atoms unified has both arguments."""
    (tmp_path / "domain.pddl").write_text(SHARED_FACT_DOMAIN)
    (tmp_path / "problem.pddl").write_text(
        "(define (problem p) (:domain shared-fact) (:objects o1 o2) (:init (a o1)) (:goal (g)))"
    )
    task = load_task(tmp_path / "domain.pddl", tmp_path / "problem.pddl")
    compare(task, 10)
    cost, _ = Exploration(Program(task)).costs(frozenset({("a", "o1")}), additive=True)
    assert cost[("g",)] == 2
    value, preferred = LiftedFF().for_task(task).estimate_with_preferred(
        frozenset({("a", "o1"), ("p", "o1")})
    )
    assert (value, list(preferred)) == (1, [("both", ("o1", "o1"))])
