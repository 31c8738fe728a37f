"""The states a search has reached, numbered in the order they were reached.

Duplicate detection is a dict from a state's key to its number; the search tree is kept
as two compact arrays, the parent's number and the operator that led from it, from which
the plan is read back at the end. Derived facts are evaluated for every new state when
the task has axioms, and conditional effects tested when it has any; otherwise successor
states are a mask operation.

A state's key is the state itself (an int bitset) unless the task's states are sparse:
when the bitset of the initial state is at least :data:`SPARSE` times longer than its
packing (the sorted numbers of its true facts, 4 bytes each: :mod:`.packing`), states
are stored packed and keyed by their packing, and the last :data:`RECENT` states a
search stored or asked for are kept unpacked. A bitset's size, hash and comparison cost
as much as the task has facts; a packing's, as much as the state has true facts (blocks
with 900 blocks: 108 KB a state as bitsets, 4 KB packed). Either way the searches see
the same states in the same order: only their storage differs.

:meth:`StateSpace.child` is what lazy search asks of a stored state: its successor by an
operator, unless reached before. In a packed space the successor is made as a packing,
from its parent's (:meth:`~.successors.SuccessorGenerator.apply_packed`: copies of the
runs of facts between the operator's changes), and lazy search works on packings from
there: the duplicate test hashes the packing, the goal test searches it for the goal's
facts (:func:`~.packing.held_counter`), the successor generator walks it, and an
estimator that reads packings (``reads_packed``, see
:class:`~.components.StateEstimator`) gets it as it is; for the others the bitset is
made then (as long as the task has facts: 2 µs at 800,000 facts). What a successor
costs then grows with the facts that hold, not with those the task has.
"""

from __future__ import annotations

import sys
from array import array
from collections import OrderedDict
from collections.abc import Callable

from strips_framework.forward.packing import held_counter, packing
from strips_framework.forward.successors import successor_generator
from strips_framework.grounding.task import GroundTask

NO_PARENT = -1
#: States are stored packed when the initial state's bitset (one bit per fact) is at
#: least this many times the size of its packing (32 bits per true fact): when fewer
#: than one fact in ``32 * SPARSE`` holds.
SPARSE = 4
#: How many states stay unpacked in a packed space (a lazy search's children mostly
#: come from recently expanded states).
RECENT = 8


def stores_packed(task: GroundTask) -> bool:
    """Whether :class:`StateSpace` stores ``task``'s states packed (module docstring)."""
    return len(task.facts) >= 32 * SPARSE * max(task.init.bit_count(), 1)


class StateSpace:
    """The states reached, by number: :meth:`state` gives a state, :meth:`number` the
    number of a state reached before (or None), :meth:`add` numbers a new one."""

    def __init__(self, task: GroundTask, packed: bool | None = None) -> None:
        self.task = task
        self.successors = successor_generator(task)
        #: Whether states are stored packed (by default as :func:`stores_packed` says).
        self.packed = stores_packed(task) if packed is None else packed
        self._keys: dict[int | bytes, int] = {}
        self._stored: list[int | bytes] = []
        self.parents = array("l")
        self.operators = array("l")
        self.costs = tuple(op.cost if task.uses_costs else 1 for op in task.operators)
        self.derive: Callable[[int], int] | None = None
        if task.axioms:
            from strips_framework.grounding.axioms import AxiomEvaluator

            self.derive = AxiomEvaluator(task).evaluate
        self.state: Callable[[int], int]
        self.number: Callable[[int], int | None]
        #: A state as stored (by number): its bitset, or its packing in a packed space;
        #: the successor generator takes either.
        self.stored: Callable[[int], int | bytes] = self._stored.__getitem__
        #: Whether a state holds the goal's facts (in a packed space, a bitset or a packing).
        self.is_goal: Callable[[int | bytes], bool] = task.is_goal  # type: ignore[assignment]
        #: The bitset of a packing.
        self.unpack: Callable[[bytes], int] = packing()[1]
        #: Whether :meth:`child` makes a successor's packing from its parent's (a packed
        #: space without conditional effects or axioms, which need the whole state).
        self.merges = self.packed and self.successors.effects is None and self.derive is None
        if self.packed:
            self._pack, self._unpack = packing()
            self.unpack = self._unpack
            self._recent: OrderedDict[int, int] = OrderedDict()
            #: The state last packed and its packing (a search asks for a state's
            #: number and then adds it: one packing for both).
            self._last: tuple[int, bytes] = (0, self._pack(0))
            self.state, self.number = self._packed_state, self._packed_number
            goal = sorted(set(task.goal))
            held, goals = held_counter(goal), len(goal)
            self.is_goal = lambda state: held(state) == goals
        else:
            # A state is its own key: the list's and the dict's own methods, no call
            # in between on the searches' hottest path.
            self.state, self.number = self._stored.__getitem__, self._keys.get

    def __len__(self) -> int:
        return len(self._stored)

    def _key(self, state: int | bytes) -> int | bytes:
        if not self.packed or isinstance(state, bytes):
            return state
        last, packed = self._last
        if last is not state:
            packed = self._pack(state)
            self._last = (state, packed)
        return packed

    def _packed_number(self, state: int) -> int | None:
        return self._keys.get(self._key(state))

    def _packed_state(self, number: int) -> int:
        recent = self._recent
        state = recent.get(number)
        if state is None:
            state = self._unpack(self._stored[number])  # type: ignore[arg-type]
            self._remember(number, state)
        else:
            recent.move_to_end(number)
        return state

    def _remember(self, number: int, state: int) -> None:
        recent = self._recent
        recent[number] = state
        if len(recent) > RECENT:
            recent.popitem(last=False)

    def successor(self, state: int, operator: int) -> int:
        """The state that applying ``operator`` in ``state`` makes, derived facts included."""
        successors = self.successors
        if successors.effects is None:
            result = successors.apply(state, operator)
        else:  # the effects that fire join the unconditional ones (deletes, then adds)
            delete, add = successors.delete[operator], successors.add[operator]
            for condition, condition_neg, effect_delete, effect_add in successors.effects[operator]:
                if state & condition == condition and not state & condition_neg:
                    delete |= effect_delete
                    add |= effect_add
            result = (state ^ (state & delete)) | add
        return self.derive(result) if self.derive is not None else result

    def child(self, parent: int, operator: int) -> int | bytes | None:
        """The state ``operator`` makes of state number ``parent``, or None when it was
        reached before: as the space stores it where :attr:`merges` (its packing, for
        :meth:`add`, :attr:`is_goal`, the successor generator and the estimators that
        read packings), else its bitset."""
        if not self.merges:
            state = self.successor(self.state(parent), operator)
            return state if self.number(state) is None else None
        packed = self.successors.apply_packed(self._stored[parent], operator)  # type: ignore[arg-type]
        return None if packed in self._keys else packed

    def add(self, state: int | bytes, parent: int, operator: int) -> int:
        """Number a new state reached from state number ``parent`` by ``operator`` (its
        bitset, or in a packed space its packing)."""
        number = len(self._stored)
        key = self._key(state)
        self._keys[key] = number
        self._stored.append(key)
        if self.packed and not self.merges:  # lazy search asks for their parents' states
            self._remember(number, state)  # type: ignore[arg-type]
        self.parents.append(parent)
        self.operators.append(operator)
        return number

    def reparent(self, number: int, parent: int, operator: int) -> None:
        """Record a cheaper way to reach state ``number``."""
        self.parents[number] = parent
        self.operators[number] = operator

    def clear(self) -> None:
        """Forget every state (a search out of memory frees it before reporting)."""
        self._keys.clear()
        self._stored.clear()
        if self.packed:
            self._recent.clear()
        del self.parents[:], self.operators[:]

    def bytes_per_state(self) -> float:
        """What a stored state costs on average: its key (the state or its packing), its
        entries in the duplicate table and the list of states, its parent and operator.
        Not counted: the :data:`RECENT` states a packed space keeps unpacked, a fixed
        cost (as the lifted space's rebuilt states are not counted either)."""
        if not self._stored:
            return 0.0
        count = len(self._stored)
        total = sum(map(sys.getsizeof, self._stored))
        total += sys.getsizeof(self._keys) + sys.getsizeof(self._stored)
        total += (self.parents.itemsize + self.operators.itemsize) * count
        return total / count

    def plan_to(self, number: int) -> list[int]:
        """The operator numbers on the path from the initial state to state ``number``."""
        steps = []
        while self.parents[number] != NO_PARENT:
            steps.append(self.operators[number])
            number = self.parents[number]
        steps.reverse()
        return steps
