"""The typed facade over the plugin registry: load a problem, build the configured
components, and search. The CLI, the tests and library users all go through it."""

from __future__ import annotations

from collections.abc import Iterable
from pathlib import Path

from attrs import frozen

from strips_framework.capabilities import check_combination, check_problem
from strips_framework.config import Config
from strips_framework.errors import InputError
from strips_framework.plugins import Registry
from strips_framework.problem import Problem
from strips_framework.proving import TheoremProver
from strips_framework.search.result import SearchResult


@frozen
class Planner:
    registry: Registry
    config: Config

    @classmethod
    def create(cls, config: Config | None = None, extra_plugins: Iterable[object] = ()) -> Planner:
        """A planner whose config is checked at once: every name is registered, every
        option valid and the chosen implementations fit together (each has the
        capabilities the others require), so mistakes show before any problem is read."""
        planner = cls(Registry.from_plugins(extra_plugins), config or Config.default())
        for kind in planner.config.choices:
            planner.config.build(planner.registry, kind)
        check_combination(planner.registry, planner.config)
        return planner

    def load(self, path: Path) -> Problem:
        """Read a problem file with the loader registered for its suffix."""
        if not path.is_file():
            raise InputError(str(path), None, None, "no such problem file")
        loader = self.registry.loader_for(path.suffix).cls()
        return loader.load(path)

    def prover(self) -> TheoremProver:
        return self.config.build(self.registry, "prover")

    def solve(self, problem: Problem) -> SearchResult:
        """Search for a plan with the strategy, prover, difference extractor, relevance
        filter and evaluator of the config (after checking that the prover handles what
        the problem uses)."""
        check_problem(problem, self.registry, self.config)
        build = self.config.build
        strategy = build(self.registry, "strategy")
        return strategy.search(
            problem,
            build(self.registry, "prover"),
            build(self.registry, "difference"),
            build(self.registry, "relevance"),
            build(self.registry, "evaluator"),
            self.config.limits,
        )
