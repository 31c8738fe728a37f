"""The typed facade over the plugin registry: load a problem, build the configured
components, and search. The CLI, the tests and library users all go through it.

Two kinds of strategy meet here. World-model strategies (``means-ends``,
``model-astar``) search first-order world models with a theorem prover and take a
:class:`Problem`: a native ``.strips`` file, or a PDDL task translated to one. Strategies
that declare ``works_on = "ground-task"`` (``astar``, ``lazy-gbfs``, ...) search the
states of a :class:`GroundTask` with a state heuristic and take PDDL input, grounded.
"""

from __future__ import annotations

import time
from collections.abc import Iterable
from pathlib import Path
from typing import TYPE_CHECKING

import attrs
from attrs import frozen

from strips_framework.capabilities import check_combination, check_problem
from strips_framework.config import Config
from strips_framework.errors import ConfigError, InputError
from strips_framework.user_files import is_file
from strips_framework.plugins import Registry

if TYPE_CHECKING:
    from strips_framework.grounding.task import GroundTask
    from strips_framework.pddl import PddlTask
    from strips_framework.problem import Problem
    from strips_framework.proving import TheoremProver
    from strips_framework.search.forward.result import ForwardResult
    from strips_framework.search.result import SearchResult

GROUND_TASK = "ground-task"
PDDL_SUFFIX = ".pddl"


@frozen
class Planner:
    registry: Registry
    config: Config

    @classmethod
    def create(cls, config: Config | None = None, extra_plugins: Iterable[object] = ()) -> Planner:
        """A planner whose config is checked at once and whole: every component the
        strategy uses, and every one the config file names even if this strategy does not
        use it (a ``[heuristic]`` typo is a typo with means-ends too), is registered with
        valid options, and the implementations used fit together (each has the
        capabilities the others require), so mistakes show before any problem is read."""
        planner = cls(Registry.from_plugins(extra_plugins), config or Config.default())
        for kind in dict.fromkeys((*planner.kinds_used(), *sorted(planner.config.chosen))):
            planner.config.build(planner.registry, kind)
        check_combination(planner.registry, planner.config, planner.kinds_used())
        return planner

    def kinds_used(self) -> tuple[str, ...]:
        """The components the configured strategy uses (only these are built, so a
        forward search never loads the prover, and a means-ends search no heuristic)."""
        if self.searches_ground_tasks:
            return ("strategy", "heuristic")
        return ("strategy", "prover", "difference", "relevance", "evaluator")

    @property
    def searches_ground_tasks(self) -> bool:
        """True when the configured strategy searches ground tasks (PDDL input only)."""
        strategy = self.config.registration(self.registry, "strategy")
        return getattr(strategy.cls, "works_on", "problem") == GROUND_TASK

    def load(self, path: Path) -> Problem:
        """Read a problem file with the loader registered for its suffix."""
        if not is_file(path):
            raise InputError(str(path), None, None, "no such problem file")
        loader = self.registry.loader_for(path.suffix).cls()
        return loader.load(path)

    def load_pddl(self, problem_path: Path, domain_path: Path | None = None) -> PddlTask:
        """Read a PDDL problem and its domain (found beside it when not given)."""
        from strips_framework.pddl import find_domain, load_task

        return load_task(domain_path or find_domain(problem_path), problem_path)

    def prover(self) -> TheoremProver:
        return self.config.build(self.registry, "prover")

    def run(
        self, problem_path: Path, domain_path: Path | None = None
    ) -> SearchResult | ForwardResult:
        """Read the problem (PDDL when it ends in ``.pddl`` or a domain is given) and
        solve it with the configured strategy, whichever kind it is (a config's
        :meth:`~Config.for_pddl` gives PDDL input its default strategy)."""
        started = time.perf_counter()
        if not is_pddl(problem_path, domain_path):
            if self.searches_ground_tasks:
                raise ConfigError(
                    f"{self.config.source}: strategy '{self.config.choices['strategy'].name}' "
                    f"searches ground tasks, which are made from PDDL input; {problem_path} is a "
                    "native problem (first-order world models and axioms): use a world-model "
                    "strategy such as 'means-ends' or 'model-astar'"
                )
            return self.solve(self.load(problem_path))
        pddl = self.load_pddl(problem_path, domain_path)
        parsed = time.perf_counter()
        if not self.searches_ground_tasks:
            from strips_framework.pddl import to_problem

            return self.solve(to_problem(pddl))
        from strips_framework.grounding import ground

        task = ground(pddl)
        grounded = time.perf_counter()
        result = self.solve_task(task, started)
        statistics = attrs.evolve(
            result.statistics,
            parse_seconds=parsed - started,
            ground_seconds=grounded - parsed,
            search_seconds=time.perf_counter() - grounded,  # the heuristic's set-up included
        )
        return attrs.evolve(result, statistics=statistics)

    def solve(self, problem: Problem) -> SearchResult:
        """Search for a plan with the strategy, prover, difference extractor, relevance
        filter and evaluator of the config (a world-model strategy; after checking that the prover handles what
        the problem uses)."""
        check_problem(problem, self.registry, self.config)
        build = self.config.build
        strategy = build(self.registry, "strategy")
        if getattr(strategy, "works_on", "problem") == GROUND_TASK:
            raise ConfigError(
                f"{self.config.source}: strategy '{strategy.name}' searches ground tasks, "
                "not first-order problems: give it PDDL input"
            )
        return strategy.search(
            problem,
            build(self.registry, "prover"),
            build(self.registry, "difference"),
            build(self.registry, "relevance"),
            build(self.registry, "evaluator"),
            self.config.limits,
        )

    def solve_task(self, task: GroundTask, started: float | None = None) -> ForwardResult:
        """Search ``task`` with the configured ground-task strategy and heuristic; the time
        limit counts from ``started`` (default: now)."""
        build = self.config.build
        strategy = build(self.registry, "strategy")
        if getattr(strategy, "works_on", "problem") != GROUND_TASK:
            raise ConfigError(
                f"{self.config.source}: strategy '{strategy.name}' searches world models, "
                "not ground tasks"
            )
        heuristic = build(self.registry, "heuristic")
        started = time.perf_counter() if started is None else started
        return strategy.search_task(task, heuristic.for_task(task), self.config.limits, started)


def is_pddl(problem_path: Path, domain_path: Path | None = None) -> bool:
    """True for PDDL input: a domain is given, or the problem file ends in ``.pddl``."""
    return domain_path is not None or problem_path.suffix.lower() == PDDL_SUFFIX
