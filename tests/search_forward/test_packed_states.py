"""States stored packed (``forward/packing.py``, ``_packing.pyx``, the packed mode of
:class:`~strips_framework.forward.space.StateSpace`) against states stored as bitsets:
the packing and its compiled twin agree on ints whose bits straddle CPython's 30-bit
digits, the rule that picks the packed mode holds at its boundary, and every strategy
expands the same states and finds the same plan whichever way the space stores them, on
seeded random tasks (costs, negative preconditions, axioms, conditional effects) whose
facts are spread over many digits, with the compiled modules and with the references.
"""

from __future__ import annotations

import random
import sys
from collections.abc import Sequence
from pathlib import Path

import pytest

from strips_framework.compiled import PURE_PYTHON_SWITCH
from strips_framework.forward import packing as packing_module
from strips_framework.forward import space as space_module
from strips_framework.forward.breadth_first import BreadthFirstSearch
from strips_framework.forward.eager import AStarSearch, GreedySearch
from strips_framework.forward.ehc import EnforcedHillClimbing
from strips_framework.forward.lazy import LazyGreedySearch
from strips_framework.forward.packing import (
    code_of,
    codes_xor,
    held_counter,
    pack,
    packing,
    patch,
    unpack,
    zobrist,
)
from strips_framework.forward.space import SPARSE, StateSpace, stores_packed
from strips_framework.forward.successors import successor_generator
from strips_framework.grounding.task import (
    GroundAxiom,
    GroundEffect,
    GroundOperator,
    GroundTask,
    facts_in,
    mask_of,
)
from strips_framework.limits import Limits

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "plugins" / "evaluators" / "tests"))
from random_tasks import random_task  # the evaluators' seeded random tasks

#: Facts renumbered to ``fact * STRIDE + STRIDE - 1``: neighbours 31 bits apart, so each
#: lands in another 30-bit digit, at another place in it.
STRIDE = 31


def spread(task: GroundTask) -> GroundTask:
    """``task`` with its facts renumbered (:data:`STRIDE`) among unused ones."""

    def to(facts: Sequence[int]) -> tuple[int, ...]:
        return tuple(fact * STRIDE + STRIDE - 1 for fact in facts)

    def state(mask: int) -> int:
        return mask_of(to(facts_in(mask)))

    operators = tuple(
        GroundOperator(
            op.name,
            to(op.pre),
            to(op.add),
            to(op.delete),
            op.cost,
            to(op.pre_neg),
            tuple(
                GroundEffect(to(e.condition), to(e.condition_neg), to(e.add), to(e.delete))
                for e in op.effects
            ),
        )
        for op in task.operators
    )
    axioms = tuple(
        GroundAxiom(to((a.head,))[0], to(a.body), to(a.body_neg), a.stratum) for a in task.axioms
    )
    facts = tuple(f"(unused{i})" for i in range(len(task.facts) * STRIDE))
    return GroundTask(
        task.name,
        facts,
        operators,
        state(task.init),
        to(task.goal),
        axioms,
        to(task.derived),
        task.uses_costs,
    )


def random_states(seed: int) -> list[int]:
    """Ints with bits on and beside digit boundaries, sparse and dense, and zero."""
    rng = random.Random(seed)
    states = [0, 1, 1 << 29, 1 << 30, 1 << 31, (1 << 60) - 1, 1 << 60, (1 << 90) | 1]
    for size in (10, 61, 1000, 100_000):
        for count in (1, 3, 50):
            states.append(mask_of(tuple(rng.sample(range(size), min(count, size)))))
    return states


@pytest.mark.parametrize("compiled", [False, True])
def test_a_packing_lists_the_true_facts_and_unpacks_to_the_state(compiled: bool) -> None:
    pack_state, unpack_state = packing(compiled)
    for seed in range(5):
        for state in random_states(seed):
            packed = pack_state(state)
            assert packed == pack(state) and len(packed) == 4 * state.bit_count()
            assert unpack_state(packed) == unpack(packed) == state


def test_the_compiled_packing_is_built() -> None:
    assert packing()[0].__module__ == "strips_framework.forward._packing"


@pytest.mark.parametrize("true", [1, 3, 40])
def test_states_are_packed_from_one_true_fact_in_32_sparse_facts(true: int) -> None:
    """At the boundary (the initial state's bitset ``SPARSE`` times its packing) the
    space packs; one fact fewer, it stores bitsets."""
    for facts, packed in ((32 * SPARSE * true, True), (32 * SPARSE * true - 1, False)):
        task = GroundTask(
            "sparse", tuple(f"(f{i})" for i in range(facts)), (), mask_of(tuple(range(true))), ()
        )
        assert stores_packed(task) is packed and StateSpace(task).packed is packed


def test_a_packed_space_gives_back_the_states_it_stored(monkeypatch: pytest.MonkeyPatch) -> None:
    """More states than it keeps unpacked: the older ones are unpacked again."""
    monkeypatch.setattr(space_module, "RECENT", 2)
    task = spread(random_task(3))
    space = StateSpace(task, packed=True)
    states = random_states(1)[:12]
    for index, state in enumerate(states):
        assert space.number(state) is None
        assert space.add(state, index - 1, 0) == index
    for index, state in enumerate(states):
        assert space.state(index) == state and space.number(state) == index
    assert len(space) == len(states) and space.bytes_per_state() > 0


@pytest.mark.parametrize("compiled", [False, True])
def test_a_successors_change_and_code_follow_from_its_parents(compiled: bool) -> None:
    """``step_packed`` on every applicable operator of random states: the packing is
    the packing of the bitset successor, the change turns the parent's packing into it (``patch``), and
    the code updated by the change is the code of the successor's facts (the ground
    truth: each fact's code XORed); compiled and reference agree."""
    code_packing, patch_packing = zobrist(compiled)
    for seed in range(8):
        task = spread(random_task(seed))
        generator = successor_generator(task, compiled)
        reference = successor_generator(task, False)
        rng = random.Random(seed)
        states = [task.init] + [mask_of(tuple(rng.sample(range(len(task.facts)), 40)))]
        for state in states:
            packed = pack(state)
            code = code_packing(packed)
            assert code == code_of(packed) == codes_xor(facts_in(state))
            for op in range(len(task.operators)):
                made, change, made_code = generator.step_packed(packed, op, code)
                assert (made, change, made_code) == reference.step_packed(packed, op, code)
                assert made == pack(generator.apply(state, op))
                assert patch_packing(packed, change) == patch(packed, change) == made
                assert made_code == codes_xor(facts_in(unpack(made)))


def test_the_compiled_patch_refuses_a_change_of_another_state() -> None:
    patch_packing = zobrist(True)[1]
    packed = pack(mask_of((3, 40, 77)))
    for lost, gained in (((4,), ()), ((), (40,)), ((3, 3), ()), ((3, 40, 77, 78), ())):
        with pytest.raises(ValueError):
            patch_packing(packed, packing_module.change_of(lost, gained))


@pytest.mark.parametrize("pure", ["", "1"])
def test_states_stored_as_changes_are_given_back_whole(
    pure: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Successors filed as changes along chains longer than a checkpoint, with few
    packings kept, made by ``take`` from packings (as lazy search) or given as bitsets
    (as the eager searches): each state's packing, bitset and number come back as made."""
    monkeypatch.setenv(PURE_PYTHON_SWITCH, pure)
    monkeypatch.setattr(space_module, "KEPT", 2)
    monkeypatch.setattr(space_module, "RECENT", 1)
    monkeypatch.setattr(space_module, "CHECKPOINT", 3)
    task = without_axioms(spread(random_task(5)))
    space = StateSpace(task, packed=True)
    made = {space.add(task.init, -1, -1): task.init}
    given: list[int] = []  # the states added as bitsets
    rng = random.Random(5)
    for step in range(300):
        parent = rng.choice(sorted(made))
        operators = space.successors.applicable(made[parent])
        if not operators:
            continue
        op = rng.choice(operators)
        expected = space.successor(made[parent], op)
        if step % 2:  # as the eager searches: the bitset looked up, then added
            if space.number(expected) is None:
                assert expected not in made.values()
                given.append(space.add(expected, parent, op))
                made[given[-1]] = expected
            continue
        number = space.take(parent, op)
        if number < 0:
            assert expected in made.values()
            continue
        assert space.stored(number) == pack(expected) and expected not in made.values()
        made[number] = expected
    changes = {number for number in made if space._bases[number] != -1}
    assert changes & set(given) and changes - set(given)  # both ways stored changes
    for number, state in sorted(made.items(), reverse=True):
        assert space.stored(number) == pack(state)
        assert space.state(number) == state and space.number(state) == number


def test_states_with_the_same_code_are_told_apart(monkeypatch: pytest.MonkeyPatch) -> None:
    """Facts' codes made to collide (the reference's codes replaced by the fact's
    lowest bit): lazy search on packings still expands what it expands on bitsets."""
    monkeypatch.setenv(PURE_PYTHON_SWITCH, "1")
    monkeypatch.setattr(packing_module, "fact_code", lambda fact: fact & 1)
    expanded = 0
    for seed in range(8):
        task = without_axioms(spread(random_task(seed)))
        outcomes = []
        for sparse in (len(task.facts) + 1, 0):
            monkeypatch.setattr(space_module, "SPARSE", sparse)
            result = LazyGreedySearch().search_task(task, _MissingGoals(task), Limits(time=60))
            s = result.statistics
            outcomes.append((result.status, result.plan, s.expanded, s.generated, s.evaluated))
        assert outcomes[0] == outcomes[1], seed
        expanded += outcomes[0][2]
    assert expanded > 30  # searches long enough to meet states with the same code


class _MissingGoals:
    """Goal count with the operators that add a missing goal fact preferred: an estimate
    that orders the open lists, and preferred operators for the strategies that use them."""

    def __init__(self, task: GroundTask) -> None:
        self.task = task

    def estimate(self, state: int) -> float:
        return sum(not state >> fact & 1 for fact in self.task.goal)

    def estimate_with_preferred(self, state: int) -> tuple[float, list[int]]:
        missing = {fact for fact in self.task.goal if not state >> fact & 1}
        adds = [i for i, op in enumerate(self.task.operators) if missing & {*op.add}]
        return len(missing), adds


STRATEGIES = [
    LazyGreedySearch(),
    GreedySearch(),
    AStarSearch(),
    EnforcedHillClimbing(),
    BreadthFirstSearch(),
]


@pytest.mark.parametrize("pure", ["", "1"])
@pytest.mark.parametrize("seed", range(12))
def test_packed_and_bitset_spaces_search_alike(
    seed: int, pure: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv(PURE_PYTHON_SWITCH, pure)
    task = spread(random_task(seed, conditional=seed % 2 == 1))
    for strategy in STRATEGIES:
        outcomes = []
        for sparse in (len(task.facts) + 1, 0):  # never packed, always packed
            monkeypatch.setattr(space_module, "SPARSE", sparse)
            result = strategy.search_task(task, _MissingGoals(task), Limits(time=60))
            s = result.statistics
            outcomes.append((result.status, result.plan, s.expanded, s.generated, s.evaluated))
        assert outcomes[0] == outcomes[1], (strategy.name, seed)


class _PackedMissingGoals(_MissingGoals):
    """:class:`_MissingGoals` reading packings too, counting those it is given."""

    reads_packed = True

    def __init__(self, task: GroundTask) -> None:
        super().__init__(task)
        self.packings = 0

    def _bitset(self, state: int | bytes) -> int:
        if isinstance(state, bytes):
            self.packings += 1
            return unpack(state)
        return state

    def estimate(self, state: int | bytes) -> float:  # type: ignore[override]
        return super().estimate(self._bitset(state))

    def estimate_with_preferred(self, state: int | bytes) -> tuple[float, list[int]]:  # type: ignore[override]
        return super().estimate_with_preferred(self._bitset(state))


def without_axioms(task: GroundTask) -> GroundTask:
    """``task`` with no axioms (its derived facts never hold): a packed space makes such
    a task's successors' packings from their parents' (``StateSpace.merges``)."""
    return GroundTask(
        task.name, task.facts, task.operators, task.init, task.goal, (), (), task.uses_costs
    )


@pytest.mark.parametrize("pure", ["", "1"])
@pytest.mark.parametrize("seed", range(12))
def test_lazy_search_on_packings_expands_what_it_expands_on_bitsets(
    seed: int, pure: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A packed space without conditional effects or axioms: lazy search works on the
    successors' packings, hands them to an estimator that reads them (and unpacks them
    for one that does not), and expands the same states with the same plan."""
    monkeypatch.setenv(PURE_PYTHON_SWITCH, pure)
    task = without_axioms(spread(random_task(seed)))
    outcomes = []
    for sparse, estimator in (
        (len(task.facts) + 1, _MissingGoals(task)),
        (0, _MissingGoals(task)),
        (0, _PackedMissingGoals(task)),
    ):
        monkeypatch.setattr(space_module, "SPARSE", sparse)
        result = LazyGreedySearch().search_task(task, estimator, Limits(time=60))
        s = result.statistics
        outcomes.append((result.status, result.plan, s.expanded, s.generated, s.evaluated))
    assert outcomes[0] == outcomes[1] == outcomes[2], seed
    assert StateSpace(task, packed=True).merges
    assert estimator.packings == outcomes[2][4]  # every state evaluated as its packing


@pytest.mark.parametrize("compiled", [False, True])
def test_a_held_counter_counts_the_facts_a_bitset_or_its_packing_holds(compiled: bool) -> None:
    rng = random.Random(7)
    for state in random_states(3):
        for size in (1, 3, 40):
            facts = sorted(rng.sample(range(100_001), size))
            held = held_counter(facts, compiled)
            expected = sum(state >> fact & 1 for fact in facts)
            assert held(state) == held(pack(state)) == expected
