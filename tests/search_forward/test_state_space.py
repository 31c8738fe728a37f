"""Successor generation, duplicate detection, plan extraction, open lists and axioms."""

from __future__ import annotations

from strips_framework.forward.openlists import AlternationOpenList, BestFirstOpenList
from strips_framework.forward.space import NO_PARENT, StateSpace
from strips_framework.forward.successors import SuccessorGenerator
from strips_framework.grounding.task import GroundAxiom, GroundTask


def reachable(task: GroundTask) -> set[int]:
    seen, todo = {task.init}, [task.init]
    while todo:
        state = todo.pop()
        for op in task.operators:
            if op.applicable(state) and op.apply(state) not in seen:
                seen.add(op.apply(state))
                todo.append(op.apply(state))
    return seen


def test_indexed_successors_are_exactly_the_applicable_operators(tasks):
    task = tasks["gripper-3"]
    generator = SuccessorGenerator(task)
    states = reachable(task)
    assert len(states) > 50
    for state in states:
        expected = {i for i, op in enumerate(task.operators) if op.applicable(state)}
        found = generator.applicable(state)
        assert sorted(found) == sorted(expected) and len(found) == len(set(found))


def test_operators_without_positive_preconditions_are_tested_everywhere(tasks):
    b = tasks.builder()
    b.op("(start)", [], ["running"], pre_neg=["running"])
    b.op("(stop)", ["running"], [], ["running"])
    task = b.task("switch", [], ["running"])
    generator = SuccessorGenerator(task)
    names = lambda state: [task.operators[i].name for i in generator.applicable(state)]
    assert names(task.init) == ["(start)"]
    assert names(task.operators[0].apply(task.init)) == ["(stop)"]


def test_plan_is_read_back_from_parent_pointers(tasks):
    task = tasks["gripper-1"]
    space = StateSpace(task)
    root = space.add(task.init, NO_PARENT, NO_PARENT)
    first = space.add(space.successor(task.init, 3), root, 3)
    second = space.add(space.successor(space.state(first), 5), first, 5)
    assert space.plan_to(second) == [3, 5] and space.plan_to(root) == []
    space.reparent(second, root, 7)
    assert space.plan_to(second) == [7]
    assert space.number(task.init) == root


def test_axioms_are_evaluated_for_every_successor(tasks):
    b = tasks.builder()
    b.op("(light)", [], ["lit"], pre_neg=["lit"])
    b.op("(douse)", ["lit"], [], ["lit"])
    plain = b.task("lamp", [], ["bright"])
    lit, bright = b.fact("lit"), b.fact("bright")
    task = GroundTask(plain.name, plain.facts, plain.operators, plain.init, plain.goal,
                      axioms=(GroundAxiom(bright, (lit,)),), derived=(bright,))
    space = StateSpace(task)
    light = next(i for i, op in enumerate(task.operators) if op.name == "(light)")
    douse = next(i for i, op in enumerate(task.operators) if op.name == "(douse)")
    on = space.successor(task.init, light)
    assert task.is_goal(on)
    assert not task.is_goal(space.successor(on, douse))


def test_best_first_ties_go_first_in_first_out():
    frontier: BestFirstOpenList[str] = BestFirstOpenList()
    for key, item in [(2, "late"), (1, "a"), ((1), "b"), (0, "first"), (1, "c")]:
        frontier.push(key, item)
    assert [frontier.pop() for _ in range(len(frontier))] == ["first", "a", "b", "c", "late"]


def test_alternation_takes_turns_and_boosts_the_preferred_list():
    frontier: AlternationOpenList[str] = AlternationOpenList(boost=2)
    for i in range(4):
        frontier.push(i, f"all{i}", preferred=False)
        frontier.push(10 + i, f"pref{i}", preferred=True)
    # Plain alternation (the full list first on a tie).
    assert [frontier.pop(), frontier.pop()] == ["all0", "pref0"]
    frontier.reward_progress()  # two extra turns for the preferred list, then a tie again
    assert [frontier.pop() for _ in range(4)] == ["pref1", "pref2", "all1", "pref3"]
    # Preferred list empty: the full list serves (it also holds the preferred entries).
    assert [frontier.pop() for _ in range(len(frontier))] == [
        "all2", "all3", "pref0", "pref1", "pref2", "pref3"
    ]
