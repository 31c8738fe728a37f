"""PLANEX: executing a plan with its triangle table in a world that does not always obey
(Fikes, Hart & Nilsson 1972, section 6).

After every step PLANEX looks at the world and finds the *highest-numbered kernel that
holds*: kernel i holding means op_i .. op_n will reach the goal from here, so op_i is
executed next. When an action fails or the world changes, that kernel is a lower one
(progress lost: steps are *redone*) or a higher one (the world did some of the work:
steps are *skipped*). When no kernel holds, PLANEX *replans* from the world as it is, with
the same planner and library, and monitors the new plan's table.

The world here is the simulator's (:mod:`strips_framework.worldmodel.simulate`) with a seeded
:class:`FaultModel`: an action fails (has no effect) with probability ``failure``; after a
step, with probability ``disturbance``, someone else acts: a randomly chosen instance of
an operator whose precondition holds is applied.
"""

from __future__ import annotations

import random
from collections.abc import Callable, Sequence

from strips_framework.macrops.ground_table import ground_table
from strips_framework.macrops.kernels import holds
from strips_framework.macrops.proofs import MacroError
from strips_framework.macrops.table import Step, TriangleTable
from strips_framework.options import Configurable, Option
from strips_framework.records import Record
from strips_framework.worldmodel.problem import Problem
from strips_framework.worldmodel.simulate import Simulator, State

class FaultModel(Configurable):
    """The ``[execution]`` table of the config."""

    options = (
        Option("failure", float, 0.1, minimum=0, maximum=1, doc="chance that an action has no effect"),
        Option("disturbance", float, 0.0, minimum=0, maximum=1,
               doc="chance that the world changes after a step"),
        Option("seed", int, 0, doc="the simulated world's random seed"),
        Option("max_steps", int, 200, minimum=1, doc="steps executed at most"),
        Option("max_replans", int, 10, minimum=0, doc="replans at most"),
    )
    failure: float
    disturbance: float
    seed: int
    max_steps: int
    max_replans: int


class Event(Record):
    """One line of the execution report."""

    step: int
    text: str

    __slots__ = ("step", "text")

    def __init__(self, step: int, text: str) -> None:
        self.step = step
        self.text = text


class Execution(Record):
    """What happened in one run."""

    reached: bool
    actions: int
    failures: int
    disturbances: int
    skipped: int
    redone: int
    replans: int
    events: tuple[Event, ...]

    __slots__ = ("reached", "actions", "failures", "disturbances", "skipped", "redone", "replans",
                 "events")  # fmt: skip

    def __init__(
        self,
        reached: bool,
        actions: int,
        failures: int,
        disturbances: int,
        skipped: int,
        redone: int,
        replans: int,
        events: tuple[Event, ...],
    ) -> None:
        self.reached = reached
        self.actions = actions
        self.failures = failures
        self.disturbances = disturbances
        self.skipped = skipped
        self.redone = redone
        self.replans = replans
        self.events = events


#: A planner from a problem (the world as it is now, as a problem) to a plan, or None.
Replanner = Callable[[Problem], Sequence[Step] | None]


def execute(
    problem: Problem,
    steps: Sequence[Step],
    replan: Replanner,
    faults: FaultModel,
    run: int = 0,
    world: State | None = None,
) -> Execution:
    """One monitored execution of ``steps`` (a valid plan for ``problem``) in a world that
    starts as ``world`` (default: the problem's initial state); the random choices come
    from ``faults.seed`` and the run number."""
    rng = random.Random(f"{faults.seed}/{run}")
    simulator = Simulator(problem)
    state: State = frozenset(problem.facts) if world is None else world
    table = ground_table(problem, steps).table
    events: list[Event] = []
    counts = {"actions": 0, "failures": 0, "disturbances": 0, "skipped": 0, "redone": 0,
              "replans": 0}
    expected = 1
    for clock in range(1, faults.max_steps + 1):
        closed = simulator.close(state)
        if simulator.holds(problem.goal, {}, closed):
            events.append(Event(clock, "the goal holds"))
            return Execution(True, events=tuple(events), **counts)
        kernel = _highest_kernel(table, closed)
        if kernel is None or kernel > table.size:
            if counts["replans"] >= faults.max_replans:
                events.append(Event(clock, f"no kernel holds; {faults.max_replans} replans "
                                    "made already: giving up"))
                break
            counts["replans"] += 1
            current = problem._replace(facts=tuple(sorted(state, key=repr)))
            plan = replan(current)
            if plan is None:
                events.append(Event(clock, "no kernel holds and replanning found no plan"))
                break
            table, expected = ground_table(current, plan).table, 1
            events.append(Event(clock, f"no kernel holds: replanned, {len(plan)} steps"))
            continue
        if kernel > expected:
            counts["skipped"] += kernel - expected
            events.append(Event(clock, f"kernel {kernel} holds: steps {expected}..{kernel - 1} "
                                "skipped (already done)"))
        elif kernel < expected:
            counts["redone"] += expected - kernel
            events.append(Event(clock, f"kernel {kernel} holds: progress lost, steps "
                                f"{kernel}..{expected - 1} to be redone"))
        step = table.steps[kernel - 1]
        counts["actions"] += 1
        if rng.random() < faults.failure:
            counts["failures"] += 1
            events.append(Event(clock, f"step {kernel}, {step}: the action failed"))
            expected = kernel
        else:
            state = simulator.apply(step.schema, step.binding(), state)
            events.append(Event(clock, f"step {kernel}, {step}"))
            expected = kernel + 1
        if faults.disturbance and rng.random() < faults.disturbance:
            changed = _disturb(simulator, state, rng)
            if changed is not None:
                counts["disturbances"] += 1
                state, what = changed
                events.append(Event(clock, f"the world changed: {what} happened"))
    else:
        events.append(Event(faults.max_steps, f"stopped after {faults.max_steps} steps"))
    return Execution(False, events=tuple(events), **counts)


def _highest_kernel(table: TriangleTable, closed: State) -> int | None:
    for i in range(table.size + 1, 0, -1):
        if holds(table, i, closed, {}):
            return i
    return None


def _disturb(
    simulator: Simulator, state: State, rng: random.Random, tries: int = 200
) -> tuple[State, str] | None:
    """Someone else's action: a random operator instance whose precondition holds."""
    problem = simulator.problem
    closed = simulator.close(state)
    for _ in range(tries):
        schema = rng.choice(problem.operators)
        args = [rng.choice(problem.constants) for _ in schema.parameters]
        binding = dict(zip(schema.parameters, args))
        if simulator.holds(schema.precondition, binding, closed):
            return simulator.apply(schema, binding, state), str(Step(schema, args))
    return None


class Summary(Record):
    """``runs`` executions of one task."""

    runs: int
    reached: int
    actions: float
    failures: float
    disturbances: float
    skipped: float
    redone: float
    replans: float

    __slots__ = ("runs", "reached", "actions", "failures", "disturbances", "skipped", "redone",
                 "replans")  # fmt: skip

    def __init__(
        self,
        runs: int,
        reached: int,
        actions: float,
        failures: float,
        disturbances: float,
        skipped: float,
        redone: float,
        replans: float,
    ) -> None:
        self.runs = runs
        self.reached = reached
        self.actions = actions
        self.failures = failures
        self.disturbances = disturbances
        self.skipped = skipped
        self.redone = redone
        self.replans = replans

    @classmethod
    def of(cls, executions: Sequence[Execution]) -> Summary:
        if not executions:
            raise MacroError("no executions to summarize")
        count = len(executions)

        def mean(name: str) -> float:
            return sum(getattr(e, name) for e in executions) / count

        return cls(count, sum(e.reached for e in executions), mean("actions"), mean("failures"),
                   mean("disturbances"), mean("skipped"), mean("redone"), mean("replans"))

    def lines(self) -> list[str]:
        return [
            f"goal reached: {self.reached}/{self.runs} ({100 * self.reached / self.runs:.0f}%)",
            f"per run: {self.actions:.1f} actions, {self.failures:.2f} failed, "
            f"{self.disturbances:.2f} world changes, {self.skipped:.2f} steps skipped, "
            f"{self.redone:.2f} redone, {self.replans:.2f} replans",
        ]
