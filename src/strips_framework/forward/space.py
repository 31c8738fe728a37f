"""The states a search has reached, numbered in the order they were reached.

Duplicate detection is a dict from a state's key to its number; the search tree is kept
as two compact arrays, the parent's number and the operator that led from it, from which
the plan is read back at the end. Derived facts are evaluated for every new state when
the task has axioms, and conditional effects tested when it has any; otherwise successor
states are a mask operation.

A state's key is the state itself (an int bitset) unless the task's states are sparse:
when the bitset of the initial state is at least :data:`SPARSE` times longer than its
packing (the sorted numbers of its true facts, 4 bytes each: :mod:`.packing`), states
are stored packed. A bitset's size, hash and comparison cost as much as the task has
facts; a packing's, as much as the state has true facts (blocks with 900 blocks: 108 KB
a state as bitsets, 4 KB packed). Either way the searches see the same states in the
same order: only their storage differs.

A packed space files a state by its Zobrist code (:func:`~.packing.code_of`: its true
facts' 63-bit codes XORed), and stores a state that :meth:`StateSpace.take` made as its
change from its parent (the facts lost and gained), every :data:`CHECKPOINT`-th along a
chain of changes whole, as the lifted space does (``lifted/space.py``). The packings of
the last :data:`KEPT` states stored or asked for are kept; the others are rebuilt from
their chains. The duplicate test compares packings only between states with the same
code (a 63-bit code: mostly the same state), so it is exact.

:meth:`StateSpace.take` is what lazy search asks of a stored state: its successor by an
operator, unless reached before. In a packed space the successor is made as a packing,
from its parent's (:meth:`~.successors.SuccessorGenerator.step_packed`: copies of the
runs of facts between the operator's changes), with its change and its code from its
parent's code and the changed facts' codes, so that filing it costs what the operator
touches; lazy search works on packings from there: the goal test searches the packing
for the goal's facts (:func:`~.packing.held_counter`), the successor generator walks it,
and an estimator that reads packings (``reads_packed``, see
:class:`~.components.StateEstimator`) gets it as it is; for the others the bitset is
made then (as long as the task has facts: 2 µs at 800,000 facts). What a successor
costs then grows with the facts that hold (a copy of its parent's packing), not with
those the task has, and what it stores with the facts it changes.
"""

from __future__ import annotations

import sys
from array import array
from collections import OrderedDict
from collections.abc import Callable

from strips_framework.forward.packing import held_counter, packing, zobrist
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
#: How many states' packings a packed space keeps (the others are rebuilt from their
#: chains of changes).
KEPT = 64
#: A packed space stores a state whole after this many stored as changes along a chain.
CHECKPOINT = 16


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
        #: Per key (a bitset, or in a packed space a Zobrist code), the state's number.
        self._keys: dict[int, int] = {}
        #: A bitset per state, or in a packed space a packing or a change (see
        #: :attr:`_bases`).
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
        #: A state by number as the successor generator takes it: its bitset, or its
        #: packing in a packed space.
        self.stored: Callable[[int], int | bytes] = self._stored.__getitem__
        #: Whether a state holds the goal's facts (in a packed space, a bitset or a packing).
        self.is_goal: Callable[[int | bytes], bool] = task.is_goal  # type: ignore[assignment]
        #: The bitset of a packing.
        self.unpack: Callable[[bytes], int] = packing()[1]
        #: Whether :meth:`take` makes a successor's packing from its parent's (a packed
        #: space without conditional effects or axioms, which need the whole state).
        self.merges = self.packed and self.successors.effects is None and self.derive is None
        if self.packed:
            self._pack, self._unpack = packing()
            self._code_of, self._patch = zobrist()
            self._step = self.successors.step_packed
            self.unpack = self._unpack
            #: Per state: the state its change is from (NO_PARENT: stored whole), that
            #: chain's length so far, and its Zobrist code.
            self._bases = array("l")
            self._depths = bytearray()
            self._codes = array("Q")
            #: The states whose code another state had first (by code; see :meth:`_find`).
            self._more: dict[int, list[int]] = {}
            self._recent: OrderedDict[int, int] = OrderedDict()
            #: The packings of the last :data:`KEPT` states stored or asked for, by
            #: number (the searches look here before calling :attr:`stored`).
            self.kept: OrderedDict[int, bytes] = OrderedDict()
            #: The state last packed, its packing and its code (a search asks for a
            #: state's number and then adds it: one packing for both).
            self._last: tuple[int, bytes, int] = (0, b"", 0)
            self.state, self.number = self._packed_state, self._packed_number
            self.stored, self.add = self._packing, self._add_packed  # type: ignore[method-assign]
            if self.merges:
                self.take = self._packed_take  # type: ignore[method-assign]
            goal = sorted(set(task.goal))
            held, goals = held_counter(goal), len(goal)
            self.is_goal = lambda state: held(state) == goals
        else:
            # A state is its own key: the list's and the dict's own methods, no call
            # in between on the searches' hottest path.
            self.state, self.number = self._stored.__getitem__, self._keys.get

    def __len__(self) -> int:
        return len(self._stored)

    def _key(self, state: int | bytes) -> tuple[bytes, int]:
        """The packing and the Zobrist code of a state given whole (a bitset or its
        packing)."""
        last, packed, code = self._last
        if last is not state:
            packed = state if isinstance(state, bytes) else self._pack(state)
            code = self._code_of(packed)
            self._last = (state, packed, code)  # type: ignore[assignment]
        return packed, code

    def _find(self, code: int, packed: bytes) -> int | None:
        """The number of the state packed as ``packed`` whose code is ``code``, if
        stored: the states with that code are compared whole (a code is 63 bits, so
        there is mostly one, and it is that state)."""
        number = self._keys.get(code)
        if number is None or self._packing(number) == packed:
            return number
        for number in self._more.get(code, ()):
            if self._packing(number) == packed:
                return number
        return None

    def _packed_number(self, state: int | bytes) -> int | None:
        packed, code = self._key(state)
        return self._find(code, packed)

    def _packed_state(self, number: int) -> int:
        recent = self._recent
        state = recent.get(number)
        if state is None:
            state = self._unpack(self._packing(number))
            recent[number] = state
            if len(recent) > RECENT:
                recent.popitem(last=False)
        else:
            recent.move_to_end(number)
        return state

    def _packing(self, number: int) -> bytes:
        """State ``number``'s packing: kept, or rebuilt from its chain (:meth:`_rebuild`)."""
        packed = self.kept.get(number)
        return self._rebuild(number) if packed is None else packed

    def _rebuild(self, number: int) -> bytes:
        """State ``number``'s packing rebuilt from the nearest kept or whole state of its
        chain of changes (and kept)."""
        packings, bases = self.kept, self._bases
        chain = []
        at = number
        while at not in packings and bases[at] != NO_PARENT:
            chain.append(at)
            at = bases[at]
        patch, stored = self._patch, self._stored
        kept = packings.get(at)
        packed = stored[at] if kept is None else kept
        for at in reversed(chain):
            packed = patch(packed, stored[at])  # type: ignore[arg-type]
        self._keep(number, packed)  # type: ignore[arg-type]
        return packed  # type: ignore[return-value]

    def _keep(self, number: int, packed: bytes) -> None:
        packings = self.kept
        packings[number] = packed
        if len(packings) > KEPT:
            packings.popitem(last=False)

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

    def take(self, parent: int, operator: int) -> int:
        """Number the state ``operator`` makes of state number ``parent`` (what lazy
        search asks of a stored state), or give -1 when it was reached before. Where
        :attr:`merges`, :attr:`stored` then gives its packing (for :attr:`is_goal`, the
        successor generator and the estimators that read packings), else :attr:`state`
        its bitset."""
        state = self.successor(self.state(parent), operator)
        return -1 if self.number(state) is not None else self.add(state, parent, operator)

    def _packed_take(self, parent: int, operator: int) -> int:
        """:meth:`take` where :attr:`merges`: the packing made from the parent's, its
        change and its code from the operator's changes (``step_packed``), the states
        with that code compared whole (only those), and a new state filed as its
        change (whole after :data:`CHECKPOINT` changes in a row)."""
        packed = self.kept.get(parent)
        made, change, code = self._step(
            self._rebuild(parent) if packed is None else packed, operator, self._codes[parent]
        )
        if code in self._keys and self._find(code, made) is not None:
            return -1
        number = len(self._stored)
        self._store(number, code, made, change, parent, operator)
        return number

    def add(self, state: int | bytes, parent: int, operator: int) -> int:
        """Number a new state reached from state number ``parent`` by ``operator`` (its
        bitset, or in a packed space its packing)."""
        if self.packed:
            return self._add_packed(state, parent, operator)
        number = len(self._stored)
        self._keys[state] = number  # type: ignore[index]
        self._stored.append(state)
        self.parents.append(parent)
        self.operators.append(operator)
        return number

    def _add_packed(self, state: int | bytes, parent: int, operator: int) -> int:
        """:meth:`add` in a packed space: where :attr:`merges` a state that is
        ``parent``'s successor by ``operator`` is filed as its change from ``parent``
        (the eager searches give bitsets: the change is made from the parent's
        packing), whole after :data:`CHECKPOINT` changes in a row; others whole."""
        number = len(self._stored)
        packed, code = self._key(state)
        change: bytes | None = None
        if not self.merges:  # lazy search asks for their parents' states
            self._recent[number] = state  # type: ignore[assignment]
            if len(self._recent) > RECENT:
                self._recent.popitem(last=False)
        elif parent != NO_PARENT:
            made, step_change, _ = self._step(self._packing(parent), operator, 0)
            if made == packed:
                change = step_change
        self._store(number, code, packed, change, parent, operator)
        return number

    def _store(
        self,
        number: int,
        code: int,
        packed: bytes,
        change: bytes | None,
        parent: int,
        operator: int,
    ) -> None:
        """Store new state ``number``: as ``change`` (from ``parent``) if there is one
        and the chain of changes is shorter than :data:`CHECKPOINT`, else whole; enter
        it in the duplicate table and the tree, and keep its packing."""
        depth = CHECKPOINT if change is None else self._depths[parent] + 1
        if depth < CHECKPOINT:
            self._stored.append(change)  # type: ignore[arg-type]
            self._bases.append(parent)
            self._depths.append(depth)
        else:
            self._stored.append(packed)
            self._bases.append(NO_PARENT)
            self._depths.append(0)
        if code in self._keys:  # another state's code (the search asked: not this state)
            self._more.setdefault(code, []).append(number)
        else:
            self._keys[code] = number
        self._codes.append(code)
        self.parents.append(parent)
        self.operators.append(operator)
        self._keep(number, packed)

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
            self.kept.clear()
            self._more.clear()
            del self._bases[:], self._codes[:], self._depths[:]
        del self.parents[:], self.operators[:]

    def bytes_per_state(self) -> float:
        """What a stored state costs on average: what is stored of it (the state, its
        packing or its change), its entries in the duplicate table (with a packed
        space's codes) and the list of states, its parent and operator, and in a packed
        space its base, chain length and code. Not counted: the :data:`RECENT` states
        and :data:`KEPT` packings a packed space keeps, a fixed cost (as the lifted
        space's rebuilt states are not counted either)."""
        if not self._stored:
            return 0.0
        count = len(self._stored)
        total = sum(map(sys.getsizeof, self._stored))
        total += sys.getsizeof(self._keys) + sys.getsizeof(self._stored)
        total += (self.parents.itemsize + self.operators.itemsize) * count
        if self.packed:
            total += sum(map(sys.getsizeof, self._keys)) + sys.getsizeof(self._more)
            total += (self._bases.itemsize + self._codes.itemsize + 1) * count
        return total / count

    def plan_to(self, number: int) -> list[int]:
        """The operator numbers on the path from the initial state to state ``number``."""
        steps = []
        while self.parents[number] != NO_PARENT:
            steps.append(self.operators[number])
            number = self.parents[number]
        steps.reverse()
        return steps
