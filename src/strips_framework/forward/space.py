"""The states a search has reached, numbered in the order they were reached.

Duplicate detection is a dict from state (an int bitset) to its number; the search tree
is kept as two compact arrays, the parent's number and the operator that led from it,
from which the plan is read back at the end. Derived facts are evaluated for every new
state when the task has axioms, and conditional effects tested when it has any;
otherwise successor states are a mask operation.
"""

from __future__ import annotations

from array import array
from collections.abc import Callable

from strips_framework.forward.successors import successor_generator
from strips_framework.grounding.task import GroundTask

NO_PARENT = -1


class StateSpace:
    def __init__(self, task: GroundTask) -> None:
        self.task = task
        self.successors = successor_generator(task)
        self.ids: dict[int, int] = {}
        self.states: list[int] = []
        self.parents = array("l")
        self.operators = array("l")
        self.costs = tuple(op.cost if task.uses_costs else 1 for op in task.operators)
        self.derive: Callable[[int], int] | None = None
        if task.axioms:
            from strips_framework.grounding.axioms import AxiomEvaluator

            self.derive = AxiomEvaluator(task).evaluate

    def successor(self, state: int, operator: int) -> int:
        """The state that applying ``operator`` in ``state`` makes, derived facts included.

        Deletes are taken out as ``state ^ (state & delete)``, not ``state & ~delete``:
        Python ints are positive here, and an operand's complement (a negative int)
        costs a conversion as long as the state, several times the other operations
        (0.17 ms at a million facts against 0.006 ms)."""
        successors = self.successors
        delete, add = successors.delete[operator], successors.add[operator]
        if successors.effects is not None:
            for condition, condition_neg, effect_delete, effect_add in successors.effects[operator]:
                if state & condition == condition and not state & condition_neg:
                    delete |= effect_delete
                    add |= effect_add
        result = (state ^ (state & delete)) | add
        return self.derive(result) if self.derive is not None else result

    def add(self, state: int, parent: int, operator: int) -> int:
        """Number a new state reached from state number ``parent`` by ``operator``."""
        number = len(self.states)
        self.ids[state] = number
        self.states.append(state)
        self.parents.append(parent)
        self.operators.append(operator)
        return number

    def reparent(self, number: int, parent: int, operator: int) -> None:
        """Record a cheaper way to reach state ``number``."""
        self.parents[number] = parent
        self.operators[number] = operator

    def clear(self) -> None:
        """Forget every state (a search out of memory frees it before reporting)."""
        self.ids.clear()
        self.states.clear()
        del self.parents[:], self.operators[:]

    def plan_to(self, number: int) -> list[int]:
        """The operator numbers on the path from the initial state to state ``number``."""
        steps = []
        while self.parents[number] != NO_PARENT:
            steps.append(self.operators[number])
            number = self.parents[number]
        steps.reverse()
        return steps
