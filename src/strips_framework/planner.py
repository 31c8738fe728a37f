"""The typed facade over the plugin registry: load a problem, build the configured
components, and search. The CLI, the tests and library users all go through it (see
``docs/api.md``).

Two families of strategy meet here. World-model strategies (the ``strategy`` plugin kind:
``means-ends``, ``model-astar``) search first-order world models with a theorem prover
and take a :class:`Problem`: a native ``.strips`` file, or a PDDL task translated to one.
Ground-task strategies (the ``ground-strategy`` kind: ``astar``, ``lazy-gbfs``, ...)
search the states of a :class:`GroundTask` with a state heuristic and take PDDL input,
grounded. Both return a :class:`~strips_framework.result.Result`.
"""

from __future__ import annotations

import sys
from collections.abc import Iterable, Mapping
from pathlib import Path
from typing import TYPE_CHECKING, Any

from strips_framework.errors import ConfigError, InputError, StripsError
from strips_framework.limits import Clock
from strips_framework.pddl.files import is_pddl
from strips_framework.plugin.checks import check_combination, check_problem
from strips_framework.plugin.config import DEFAULTS, PDDL_DEFAULT_STRATEGY, Choice, Config
from strips_framework.plugin.registry import KINDS, Registry
from strips_framework.records import Record
from strips_framework.user_files import is_dir, is_file

if TYPE_CHECKING:
    from strips_framework.grounding.task import GroundTask
    from strips_framework.lifted.task import LiftedTask
    from strips_framework.macrops.macrop import Library
    from strips_framework.observer import SearchObserver
    from strips_framework.pddl import PddlTask
    from strips_framework.portfolio import Portfolio, Stage
    from strips_framework.progress import Progress
    from strips_framework.result import Result
    from strips_framework.worldmodel.problem import Problem
    from strips_framework.worldmodel.proving import TheoremProver

GROUND_STRATEGY = "ground-strategy"
LIFTED_STRATEGY = "lifted-strategy"
#: The strategy PDDL input gets when the config names none and grounding looks expensive,
#: unless the task is wide (:data:`~strips_framework.lifted.estimate.WIDE_BRANCHING`):
#: Powerlifted's alternated BFWS computes the heuristic only on the states it expands, so
#: the dead ends among a state's children cost it next to nothing.
PDDL_LIFTED_STRATEGY = "lifted-alt-bfws"
#: The strategy of a wide task whose grounding looks expensive: lazy greedy search, which
#: draws a state's children as it needs them (and rates each one it takes).
PDDL_WIDE_LIFTED_STRATEGY = "lifted-gbfs"
#: Beside either, a task whose grounding looks expensive gets the paper's means-ends
#: analysis for this share of the time limit, in CPU seconds of a second process (see
#: :mod:`strips_framework.portfolio`): it never grounds and works back from the goal, so
#: a small goal in a huge world costs it what the goal touches (3-5 ``on`` atoms among
#: 1,900 blocks: a second), where a progression search is lost among the world's other
#: branches. A tenth of the limit covers the tasks it solves (the hard-to-ground set's
#: blocks tasks take 0.1-2 s) and costs the lifted search at most that where it does not.
PDDL_MEANS_ENDS_SHARE = 0.1
#: The world-model strategy of that first stage.
PDDL_MEANS_ENDS_STRATEGY = "means-ends"
#: The lifted heuristic a lifted strategy gets when the config names no ``[heuristic]``:
#: the first of these that is registered (the evaluators plugin registers ``ff``; the
#: core's own ``goal-count`` is there without any plugin).
LIFTED_DEFAULT_HEURISTICS = ("ff", "goal-count")


class Planner(Record):
    """A checked config and the registry its components come from.

    Make one with :meth:`create`; :meth:`run` reads and solves a file, :meth:`solve` a
    :class:`Problem` made in code, :meth:`solve_pddl` a :class:`PddlTask`.
    """

    registry: Registry
    config: Config
    #: Counts the search's scores for a progress line (the CLI sets it on a terminal).
    progress: Progress | None
    #: Watch the search (the explorer page, the VS Code search debugger's feed); none by
    #: default, and then the search runs unwrapped (see :mod:`strips_framework.observer`).
    observers: tuple[SearchObserver, ...]

    __slots__ = ("config", "observers", "progress", "registry")

    def __init__(
        self,
        registry: Registry,
        config: Config,
        progress: Progress | None = None,
        observers: tuple[SearchObserver, ...] = (),
    ) -> None:
        self.registry = registry
        self.config = config
        self.progress = progress
        self.observers = tuple(observers)

    @classmethod
    def create(
        cls,
        config: Config | Mapping[str, Any] | None = None,
        extra_plugins: Iterable[object] = (),
        observers: Iterable[SearchObserver] = (),
    ) -> Planner:
        """A planner whose config is checked at once: every component the strategy uses is
        registered, its options valid and the chosen implementations fit together (each has
        the capabilities the others require), so mistakes show before any problem is read.

        ``config`` is a :class:`Config`, or a mapping in the shape of the TOML file
        (``{"strategy": "astar", "heuristic": {"name": "lmcut"}}``); ``None`` takes the
        defaults, the same as ``strips solve`` without ``--config``. ``observers`` watch
        every search (see :mod:`strips_framework.observer`; the explorer's
        :class:`~strips_framework.explore.record.SearchRecord`).
        """
        if config is None:
            config = Config.default()
        elif not isinstance(config, Config):
            config = Config.from_dict(dict(config), "<api>")
        return cls(Registry.from_plugins(extra_plugins), config, observers=tuple(observers)).checked()

    def checked(self) -> Planner:
        """This planner, after building each component it uses, and every one the config
        file names even if this strategy does not use it (a ``[heuristic]`` typo is a typo
        with means-ends too), and checking that the ones used fit together."""
        config = self.config.with_registered_defaults(self.registry, ("strategy",))
        if not self._replace(config=config)._can_search_ground_tasks_by_default():
            choices = {**config.choices, "strategy": Choice("strategy", PDDL_LIFTED_STRATEGY)}
            config = config._replace(choices=choices)
        # A lifted search's [heuristic] default is chosen below among lifted heuristics,
        # not among the state heuristics DEFAULTS["heuristic"] names.
        kinds = [k for k in self._replace(config=config).kinds_used() if k != "lifted-heuristic"]
        config = config.with_registered_defaults(self.registry, map(config.table_of, kinds))
        if config is not self.config:
            return self._replace(config=config).checked()
        if self.searches_lifted_tasks and "heuristic" not in self.config.chosen:
            names = self.registry.names("lifted-heuristic")
            default = next((n for n in LIFTED_DEFAULT_HEURISTICS if n in names), None)
            if default is not None and default != self.config.choices["heuristic"].name:
                choices = {**self.config.choices, "heuristic": Choice("heuristic", default)}
                return self._replace(config=self.config._replace(choices=choices)).checked()
        kinds = list(self.kinds_used())
        for table in sorted(self.config.chosen):
            kind = self.config.strategy_kind(self.registry) if table == "strategy" else table
            if table == "heuristic" and self.searches_lifted_tasks:
                kind = "lifted-heuristic"
            if kind not in kinds:
                kinds.append(kind)
        for kind in kinds:
            self.config.build(self.registry, kind)
        check_combination(self.registry, self.config, self.kinds_used())
        self._warn_unused_tables()
        return self

    def _warn_unused_tables(self) -> None:
        """A warning naming the tables the config file chose that this strategy never
        uses (``[prover]`` with a forward search, ``[heuristic]`` with means-ends): the
        run does not do what the file seems to ask. ``[learner]`` is ``strips learn``'s."""
        import warnings

        used = {self.config.table_of(kind) for kind in self.kinds_used()} | {"learner"}
        unused = sorted(self.config.chosen - used)
        if unused:
            kind = self.config.strategy_kind(self.registry)
            name = self.config.choices["strategy"].name
            tables = ", ".join(f"[{table}]" for table in unused)
            uses = ", ".join(f"[{self.config.table_of(k)}]" for k in self.kinds_used())
            warnings.warn(
                f"{self.config.source}: {tables} not used: {KINDS[kind][1]} {name!r} uses {uses}",
                stacklevel=3,
            )

    def kinds_used(self) -> tuple[str, ...]:
        """The components the configured strategy uses (only these are built, so a
        forward search never loads the prover, and a means-ends search no heuristic)."""
        if self.searches_ground_tasks:
            return (GROUND_STRATEGY, "heuristic")
        if self.searches_lifted_tasks:
            # The query engine is the builtin join engine unless [prover] names one.
            engine = ("prover",) if "prover" in self.config.chosen else ()
            return (LIFTED_STRATEGY, "lifted-heuristic", *engine)
        return ("strategy", "prover", "difference", "relevance", "evaluator")

    @property
    def searches_ground_tasks(self) -> bool:
        """True when the configured strategy searches ground tasks (PDDL input only)."""
        return self.config.strategy_kind(self.registry) == GROUND_STRATEGY

    @property
    def searches_lifted_tasks(self) -> bool:
        """True when the configured strategy searches PDDL tasks without grounding."""
        return self.config.strategy_kind(self.registry) == LIFTED_STRATEGY

    def for_pddl(self) -> Planner:
        """The planner for PDDL input: the config's, with the strategy defaulting to
        lazy greedy search (:data:`~strips_framework.plugin.config.PDDL_DEFAULT_STRATEGIES`) unless
        the config chose one, as ``strips solve`` does."""
        config = self.config.for_pddl(self.registry)
        if config is self.config:
            return self
        return Planner(self.registry, config, self.progress, self.observers).checked()

    def load(self, path: Path | str) -> Problem:
        """Read a problem file with the loader registered for its suffix."""
        path = Path(path)
        if not is_file(path):
            what = "is a folder, not a problem file" if is_dir(path) else "no such problem file"
            raise InputError(str(path), None, None, what)
        loader = self.registry.loader_for(path.suffix).cls()
        return loader.load(path)

    def load_pddl(
        self, problem_path: Path | str, domain_path: Path | str | None = None
    ) -> PddlTask:
        """Read a PDDL problem and its domain (found beside it when not given)."""
        from strips_framework.pddl import find_domain, load_task

        problem_path = Path(problem_path)
        domain = find_domain(problem_path) if domain_path is None else Path(domain_path)
        return load_task(domain, problem_path)

    def prover(self) -> TheoremProver:
        return self.config.build(self.registry, "prover")

    def run(
        self,
        problem_path: Path | str,
        domain_path: Path | str | None = None,
        clock: Clock | None = None,
        library: Path | None = None,
    ) -> Result:
        """Read the problem (PDDL when it ends in ``.pddl`` or a domain is given) and
        solve it, with the defaults of ``strips solve``: PDDL input gets lazy greedy
        search unless the config names a strategy. The time limit counts from the start
        of ``clock`` (default: now). With a MACROP ``library`` file, the search also uses
        its MACROPs (forward strategies as macro operators, see
        :mod:`strips_framework.macrops.forward`)."""
        clock = clock or Clock(self.config.limits.time)
        problem_path = Path(problem_path)
        domain_path = None if domain_path is None else Path(domain_path)
        if not is_pddl(problem_path, domain_path):
            self._require_world_model(problem_path)
            problem = self.load(problem_path)
            return self.solve(problem, clock, _read_library(library, problem))
        pddl = self.load_pddl(problem_path, domain_path)
        planner, reason = self.for_pddl_task(pddl)
        if reason:
            print(f"strips: {reason}", file=sys.stderr)
        return planner.solve_pddl(pddl, clock, parse_seconds=clock.elapsed(), library=library)

    def for_pddl_task(self, pddl: PddlTask) -> tuple[Planner | Portfolio, str | None]:
        """The planner for ``pddl`` and, when the config names no strategy, the line
        saying which search was chosen and why: the ground search
        (:data:`~strips_framework.plugin.config.PDDL_DEFAULT_STRATEGY`) when grounding
        looks cheap, else means-ends analysis for a share of the time limit
        (:data:`PDDL_MEANS_ENDS_SHARE`) and then a lifted search
        (:data:`PDDL_LIFTED_STRATEGY`, or :data:`PDDL_WIDE_LIFTED_STRATEGY` for a wide
        task), decided from :func:`~strips_framework.lifted.estimate.estimated_operators`
        and :func:`~strips_framework.lifted.estimate.initial_branching` before grounding
        anything."""
        if "strategy" in self.config.chosen:
            return self.for_pddl(), None
        from strips_framework.lifted.estimate import CHEAP_GROUNDING, estimated_operators
        from strips_framework.lifted.task import LiftedTask

        task = LiftedTask(pddl)
        estimate = estimated_operators(task)
        if not self._replace(config=self.config.for_pddl())._can_search_ground_tasks_by_default():
            name, how = _lifted_strategy(task)
            why = (
                f"the ground search's default heuristic ({', '.join(DEFAULTS['heuristic'])}) is "
                "not registered (the core alone has only 'blind'): searching without "
                f"grounding, {how}"
            )
        elif estimate <= CHEAP_GROUNDING:
            name = PDDL_DEFAULT_STRATEGY
            why = f"grounding looks cheap (about {estimate:,.0f} operators estimated)"
        else:
            name, how = _lifted_strategy(task)
            why = (
                f"grounding looks expensive (about {estimate:,.0f} operators estimated, more "
                f"than {CHEAP_GROUNDING:,}): searching without grounding, {how}"
            )
        planner = self._with_strategy(name)
        first = self._means_ends_stage() if estimate > CHEAP_GROUNDING else None
        if first is None:
            return planner, f"strategy {name}: {why}"
        from strips_framework.portfolio import Portfolio, Stage

        share = f"{PDDL_MEANS_ENDS_SHARE:.0%} of the time limit"
        stages = (first, Stage(planner))
        when = f"beside it, for at most {share} in CPU" if first.beside else f"first, for at most {share}"
        return Portfolio(stages), (
            f"strategy {first.name} and {name}: {why}; {first.name} {when} (it works back from "
            "the goal, so a small goal in a large world costs it what the goal touches)"
        )

    def _with_strategy(self, name: str) -> Planner:
        choices = {**self.config.choices, "strategy": Choice("strategy", name)}
        config = self.config._replace(choices=choices)
        return Planner(self.registry, config, self.progress, self.observers).checked()

    def _means_ends_stage(self) -> Stage | None:
        """The first stage of a task too large to ground, when the registry and the
        config allow it (the means-ends components built and fitting together); else
        None, and the lifted search runs alone. Warnings about tables this stage does
        not use are not shown: the lifted stage uses them.

        It runs beside the lifted search (:mod:`strips_framework.portfolio`) unless
        something in this process watches the search (observers, the progress line):
        what a second process did, they would not see, so a watched run keeps one
        process and gives means-ends its slice first."""
        import warnings

        from strips_framework.portfolio import Stage

        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            try:
                planner = self._with_strategy(PDDL_MEANS_ENDS_STRATEGY)
            except StripsError:
                return None
        watched = bool(self.observers) or self.progress is not None
        return Stage(planner, PDDL_MEANS_ENDS_SHARE, beside=not watched)

    def _can_search_ground_tasks_by_default(self) -> bool:
        """False when the strategy is a default ground search whose default heuristic is
        not registered (the core alone, with plugin autoload off, has only the blind state
        heuristic, but lifted goal count): then a default PDDL run searches lifted, guided,
        rather than ground and blind."""
        if "strategy" in self.config.chosen or "heuristic" in self.config.chosen:
            return True
        if not self.searches_ground_tasks:
            return True
        registered = self.registry.names("heuristic")
        return any(name in registered for name in DEFAULTS["heuristic"])

    def solve_pddl(
        self,
        pddl: PddlTask,
        clock: Clock | None = None,
        parse_seconds: float = 0.0,
        library: Path | None = None,
    ) -> Result:
        """Solve a PDDL task with the configured strategy: a ground-task strategy searches
        it grounded, a world-model strategy its translation to a :class:`Problem`.
        (Call :meth:`for_pddl` first for ``strips solve``'s default strategy.)"""
        clock = clock or Clock(self.config.limits.time)
        if self.searches_lifted_tasks:
            return self.solve_lifted(pddl, clock, parse_seconds)
        if not self.searches_ground_tasks:
            from strips_framework.pddl import to_problem

            problem = to_problem(pddl)
            return self.solve(problem, clock, _read_library(library, problem))
        from strips_framework.grounding import ground

        grounding_since = clock.elapsed()
        task = ground(pddl)
        searching_since = clock.elapsed()
        if library is None:
            result = self.solve_task(task, clock)
        else:
            from strips_framework.macrops.forward import solve_with_macros
            from strips_framework.pddl import to_problem

            macrops = _read_library(library, to_problem(pddl))
            result = solve_with_macros(self.solve_task, task, macrops, clock)
        statistics = result.statistics._replace(
            parse_seconds=parse_seconds,
            ground_seconds=searching_since - grounding_since,
            search_seconds=clock.elapsed() - searching_since,  # the heuristic's set-up included
        )
        return result._replace(statistics=statistics, seconds=clock.elapsed())

    def solve_lifted(
        self, pddl: PddlTask, clock: Clock | None = None, parse_seconds: float = 0.0
    ) -> Result:
        """Search ``pddl`` without grounding it, with the configured lifted strategy and
        lifted heuristic; the query engine is the ``[prover]`` the config names (a prover
        that is no query engine answers through
        :class:`~strips_framework.lifted.prover.ProverEngine`), else the join engine."""
        from strips_framework.lifted.prover import engine_of
        from strips_framework.lifted.successors import Successors
        from strips_framework.lifted.task import LiftedTask

        clock = clock or Clock(self.config.limits.time)
        setup_since = clock.elapsed()
        task = LiftedTask(pddl)
        prover = self.prover() if "prover" in self.config.chosen else None
        successors = Successors(task, engine_of(prover, task))
        strategy = self.config.build(self.registry, LIFTED_STRATEGY)
        heuristic = self.config.build(self.registry, "lifted-heuristic")
        estimator = heuristic.for_task(pddl)
        if self.progress is not None:
            estimator = self.progress.estimator(estimator)
        searching_since = clock.elapsed()
        result = strategy.search_task(successors, estimator, self.config.limits, clock)
        statistics = result.statistics._replace(
            parse_seconds=parse_seconds,
            setup_seconds=searching_since - setup_since,
            search_seconds=clock.elapsed() - searching_since,
        )
        return result._replace(statistics=statistics, seconds=clock.elapsed())

    def solve(
        self, problem: Problem, clock: Clock | None = None, library: Library | None = None
    ) -> Result:
        """Search for a plan with the strategy, prover, difference extractor, relevance
        filter and evaluator of the config (a world-model strategy; after checking that
        the prover handles what the problem uses). With a MACROP ``library`` the relevance
        filter also offers its MACROPs (see :mod:`strips_framework.macrops.search`)."""
        self._require_world_model(problem.source)
        check_problem(problem, self.registry, self.config)
        build = self.config.build
        strategy = build(self.registry, "strategy")
        evaluator = build(self.registry, "evaluator")
        relevance = build(self.registry, "relevance")
        if library is not None:
            from strips_framework.macrops.search import MacroRelevance

            use = self.config.section("macrops")
            relevance = MacroRelevance.of(relevance, library, use)
        if self.progress is not None:
            evaluator = self.progress.evaluator(evaluator)
        for observer in self.observers:
            evaluator = observer.evaluator(evaluator)
        result = strategy.search(
            problem,
            build(self.registry, "prover"),
            build(self.registry, "difference"),
            relevance,
            evaluator,
            self.config.limits,
            clock or Clock(self.config.limits.time),
        )
        return self._finished(result)

    def solve_task(self, task: GroundTask, clock: Clock | None = None) -> Result:
        """Search ``task`` with the configured ground-task strategy and heuristic; the
        time limit counts from the start of ``clock`` (default: now)."""
        if not self.searches_ground_tasks:
            raise ConfigError(
                f"{self.config.source}: strategy '{self.config.choices['strategy'].name}' "
                "searches world models, not ground tasks"
            )
        strategy = self.config.build(self.registry, GROUND_STRATEGY)
        heuristic = self.config.build(self.registry, "heuristic")
        clock = clock or Clock(self.config.limits.time)
        estimator = heuristic.for_task(task)
        if self.progress is not None:
            estimator = self.progress.estimator(estimator)
        for observer in self.observers:
            estimator = observer.estimator(estimator, task)
        return self._finished(strategy.search_task(task, estimator, self.config.limits, clock))

    def _finished(self, result: Result) -> Result:
        for observer in self.observers:
            observer.finished(result)
        return result

    def _require_world_model(self, problem: Path | str) -> None:
        if self.searches_ground_tasks:
            raise ConfigError(
                f"{self.config.source}: strategy '{self.config.choices['strategy'].name}' "
                f"searches ground tasks, which are made from PDDL input; {problem} is a "
                "native problem (first-order world models and axioms): use a world-model "
                "strategy such as 'means-ends' or 'model-astar'"
            )


def _lifted_strategy(task: LiftedTask) -> tuple[str, str]:
    """The lifted search for ``task`` and the words saying why (see
    :data:`PDDL_LIFTED_STRATEGY`)."""
    from strips_framework.lifted.estimate import WIDE_BRANCHING, initial_branching

    branching = initial_branching(task)
    if branching > WIDE_BRANCHING:
        return PDDL_WIDE_LIFTED_STRATEGY, (
            f"lazily (more than {WIDE_BRANCHING:,} action instances applicable in the initial "
            "state: a search that measures every child would pay for all of them)"
        )
    return PDDL_LIFTED_STRATEGY, (
        f"rating only the states it expands ({branching:,} action instances applicable in "
        f"the initial state, at most {WIDE_BRANCHING:,})"
    )


def _read_library(path: Path | None, problem: Problem) -> Library | None:
    if path is None:
        return None
    from strips_framework.macrops.library_file import read_library

    return read_library(path, problem)
