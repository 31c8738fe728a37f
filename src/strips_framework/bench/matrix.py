"""The matrix file: problem sets x configurations x repetitions, under limits.

    repetitions = 1            # runs of each (problem, configuration)
    seed = 0                   # repetition r runs with PYTHONHASHSEED = seed + r

    [limits]
    time = 60                  # wall-clock seconds per run (then its process group is killed)
    memory = 2048              # MiB of address space per run (RLIMIT_AS)

    [problems]                 # named sets of globs, relative to this file
    paper = ["../three-boxes.strips", "../robot-world/*.strips"]

    [product]                  # one configuration per combination
    evaluator = ["paper", "goal-count"]
    base = "../configs/paper.toml"

    [configs.optimal]          # named configurations (see configs.py for the kinds)
    file = "../configs/optimal.toml"

Every mistake is reported with the file, the key path and what was expected.
"""

from __future__ import annotations

import itertools
import warnings
from pathlib import Path
from typing import Any, NoReturn

from strips_framework.bench import anchors
from strips_framework.bench.configs import (
    PLACEHOLDERS,
    AnchorConfig,
    CommandConfig,
    Configuration,
    PlannerConfig,
)
from strips_framework.bench.problems import ProblemFile, expand_problem_set
from strips_framework.errors import ConfigError, InputError, StripsError
from strips_framework.limits import MAX_MEMORY, MAX_TIME
from strips_framework.planner import Planner
from strips_framework.plugin.config import COMPONENTS, DEFAULT_CHOICES, Config
from strips_framework.plugin.registry import Registry
from strips_framework.records import Record
from strips_framework.user_files import KeyLines, read_toml, read_toml_with_keys

PRODUCT_KINDS = (*COMPONENTS, "heuristic")
TOP_KEYS = ("repetitions", "seed", "limits", "problems", "product", "configs")
CONFIG_KINDS = ("file", "command", "anchor")


DEFAULT_TIME, DEFAULT_MEMORY = 60.0, 2048
MAX_REPETITIONS = 10_000
#: Repetition r runs with PYTHONHASHSEED = seed + r, which Python takes up to this.
MAX_HASH_SEED = 2**32 - 1


class RunLimits(Record):
    time: float
    memory: int  # MiB

    __slots__ = ("time", "memory")

    def __init__(self, time: float = DEFAULT_TIME, memory: int = DEFAULT_MEMORY) -> None:
        self.time = time
        self.memory = memory


class RunSpec(Record):
    """One run: everything a worker needs, picklable, so it can travel to a Dask worker."""

    problem: ProblemFile
    config: Configuration
    repetition: int
    seed: int
    limits: RunLimits
    position: int  # in the matrix's order, which reports keep

    __slots__ = ("problem", "config", "repetition", "seed", "limits", "position")

    def __init__(
        self,
        problem: ProblemFile,
        config: Configuration,
        repetition: int,
        seed: int,
        limits: RunLimits,
        position: int = 0,
    ) -> None:
        self.problem = problem
        self.config = config
        self.repetition = repetition
        self.seed = seed
        self.limits = limits
        self.position = position

    @property
    def key(self) -> str:
        return run_key(self.problem.name, self.config.name, self.repetition)


def run_key(problem: str, config: str, repetition: int) -> str:
    return f"{problem} | {config} | {repetition}"


class Matrix(Record):
    source: str
    problems: tuple[ProblemFile, ...]
    configs: tuple[Configuration, ...]
    repetitions: int
    seed: int
    limits: RunLimits

    __slots__ = ("source", "problems", "configs", "repetitions", "seed", "limits")

    def __init__(
        self,
        source: str,
        problems: tuple[ProblemFile, ...],
        configs: tuple[Configuration, ...],
        repetitions: int,
        seed: int,
        limits: RunLimits,
    ) -> None:
        self.source = source
        self.problems = problems
        self.configs = configs
        self.repetitions = repetitions
        self.seed = seed
        self.limits = limits

    @classmethod
    def from_file(cls, path: Path) -> Matrix:
        data, keys = read_toml_with_keys(path, "the matrix")
        return cls.from_dict(data, keys, path.resolve().parent)

    @classmethod
    def from_dict(cls, data: dict[str, Any], source: str | KeyLines, base: Path) -> Matrix:
        keys = KeyLines(source) if isinstance(source, str) else source
        source = str(keys)
        reader = _Reader(keys, base)
        for key in data:
            if key not in TOP_KEYS:
                reader.fail(key, f"unknown key (expected one of: {', '.join(TOP_KEYS)})")
        problem_sets = reader.table(data, "problems", required=True)
        problems: list[ProblemFile] = []
        for set_name, patterns in problem_sets.items():
            patterns = [patterns] if isinstance(patterns, str) else patterns
            reader.expect(patterns, list, f"problems.{set_name}", "an array of glob patterns")
            for index, pattern in enumerate(patterns):
                reader.expect(pattern, str, f"problems.{set_name}[{index}]", "a glob pattern (a string)")
            where = f"{keys.at('problems.' + set_name)}: 'problems.{set_name}'"
            problems += expand_problem_set(set_name, patterns, base, where)
        configs = reader.product(reader.table(data, "product"))
        for name, table in reader.table(data, "configs").items():
            configs.append(reader.named_config(name, table))
        if not configs:
            reader.fail("configs", "no configuration: give a [product] table or [configs.NAME] tables")
        names = [config.name for config in configs]
        for name in names:
            if names.count(name) > 1:
                reader.fail("configs", f"the configuration name {name!r} is used twice")
        repetitions = reader.integer(data, "repetitions", 1, MAX_REPETITIONS)
        seed = reader.integer(data, "seed", 0, MAX_HASH_SEED + 1 - repetitions)
        limits = reader.limits(reader.table(data, "limits"))
        return cls(source, tuple(_unique(problems)), tuple(configs), repetitions, seed, limits)

    def runs(self) -> list[RunSpec]:
        """Every run, problem-major so that early results cover every configuration."""
        combinations = [
            (problem, config, repetition)
            for problem in self.problems
            for repetition in range(self.repetitions)
            for config in self.configs
            if config.accepts(problem) and config.missing() is None
        ]
        return [
            RunSpec(problem, config, repetition, self.seed + repetition, self.limits, position)
            for position, (problem, config, repetition) in enumerate(combinations)
        ]

    def notes(self) -> list[str]:
        """Why configurations or problems are left out (not installed, PDDL only)."""
        notes = []
        for config in self.configs:
            missing = config.missing()
            if missing:
                notes.append(f"configuration {config.name!r} skipped: {missing}")
                continue
            refused = [p.name for p in self.problems if not config.accepts(p)]
            if refused:
                notes.append(
                    f"configuration {config.name!r} runs PDDL problems only (a ground-task "
                    "strategy, or an anchor planner): "
                    f"{len(refused)} problem(s) skipped"
                )
        return notes


def _unique(problems: list[ProblemFile]) -> list[ProblemFile]:
    return list({problem.name: problem for problem in problems}.values())


class _Reader:
    """Reads the matrix's tables, failing with the file and key path."""

    def __init__(self, keys: KeyLines, base: Path) -> None:
        self.keys, self.source, self.base = keys, str(keys), base
        self.registry = Registry.from_plugins()

    def fail(self, path: str, message: str) -> NoReturn:
        raise ConfigError(f"{self.keys.at(path.split('[')[0])}: '{path}': {message}")

    def expect(self, value: object, kind: type | tuple[type, ...], path: str, what: str) -> None:
        if not isinstance(value, kind) or isinstance(value, bool) and kind is not bool:
            self.fail(path, f"expected {what}, got {value!r}")

    def table(self, data: dict[str, Any], key: str, required: bool = False) -> dict[str, Any]:
        if key not in data and required:
            self.fail(key, "missing (expected a table)")
        value = data.get(key, {})
        self.expect(value, dict, key, "a table")
        return value

    def integer(self, data: dict[str, Any], key: str, default: int, maximum: int) -> int:
        """An integer from 0 (1 for a count) to ``maximum``."""
        minimum = 1 if key == "repetitions" else 0
        value = data.get(key, default)
        what = f"an integer from {minimum} to {maximum}"
        self.expect(value, int, key, what)
        if not minimum <= value <= maximum:
            self.fail(key, f"expected {what}, got {value}")
        return value

    def limits(self, table: dict[str, Any]) -> RunLimits:
        for key in table:
            if key not in ("time", "memory"):
                self.fail(f"limits.{key}", "unknown key (expected time or memory)")
        time = table.get("time", DEFAULT_TIME)
        self.expect(time, (int, float), "limits.time", "seconds > 0")
        memory = table.get("memory", DEFAULT_MEMORY)
        self.expect(memory, int, "limits.memory", "MiB (an integer) > 0")
        if not 0 < time <= MAX_TIME:
            self.fail("limits.time", f"expected seconds > 0 and <= {MAX_TIME}, got {time}")
        if not 0 < memory <= MAX_MEMORY:
            self.fail("limits.memory", f"expected MiB > 0 and <= {MAX_MEMORY}, got {memory}")
        return RunLimits(float(time), memory)

    def strips_toml(self, relative: str, path: str) -> dict[str, Any]:
        self.expect(relative, str, path, "a path to a strips.toml")
        try:
            return read_toml(self.base / relative, "the config")
        except InputError as error:
            self.fail(path, str(error))

    def checked(self, name: str, data: dict[str, Any], path: str) -> PlannerConfig:
        """A planner configuration, checked now so that no run fails on a typo."""
        try:
            with warnings.catch_warnings():
                # A product crosses every strategy with every prover and evaluator: that
                # a forward search leaves [prover] unused is the matrix's design.
                warnings.filterwarnings("ignore", message=r".* not used: ")
                Planner.create(Config.from_dict(data, self.keys.within(path)))
        except StripsError as error:  # config errors name the file; plugin errors do not
            message = str(error)
            if not message.startswith(self.source):
                message = f"{self.keys.at(path)}: '{path}': {message}"
            raise ConfigError(message) from None
        return PlannerConfig(name, data)

    def product(self, table: dict[str, Any]) -> list[Configuration]:
        if not table:
            return []
        base = self.strips_toml(table["base"], "product.base") if "base" in table else {}
        axes = {}
        for key, values in table.items():
            if key == "base":
                continue
            if key not in PRODUCT_KINDS:
                self.fail(f"product.{key}", f"unknown key (expected base or one of: {', '.join(PRODUCT_KINDS)})")
            values = [values] if isinstance(values, str | dict) else values
            self.expect(values, list, f"product.{key}", "an array of names or tables")
            for index, value in enumerate(values):
                where = f"product.{key}[{index}]"
                self.expect(value, (str, dict), where, "a name or a table with 'name'")
                if isinstance(value, dict) and not isinstance(value.get("name"), str):
                    self.fail(where, f"a table needs a 'name' (a string), got {value!r}")
            axes[key] = [{"name": v} if isinstance(v, str) else v for v in values]
        configs = []
        varying = [kind for kind, values in axes.items() if len(values) > 1] or list(axes)
        for combination in itertools.product(*axes.values()):
            choices = dict(zip(axes, combination, strict=True))
            data = dict(base)
            for kind, choice in choices.items():
                data[kind] = _merge_choice(kind, base.get(kind), choice)
            name = "+".join(_label(choices[kind]) for kind in varying) or "base"
            configs.append(self.checked(name, data, f"product ({name})"))
        return configs

    def named_config(self, name: str, table: object) -> Configuration:
        path = f"configs.{name}"
        if not isinstance(table, dict):
            self.fail(path, f"expected a table, got {table!r}")
        kinds = [key for key in CONFIG_KINDS if key in table]
        if len(kinds) > 1:
            self.fail(path, f"give one of {', '.join(CONFIG_KINDS)}, not {' and '.join(kinds)}")
        if "command" in table:
            return self.command(name, table, path)
        if "anchor" in table:
            return self.anchor(name, table, path)
        data = dict(table)
        if "file" in data:
            data = self.strips_toml(data.pop("file"), f"{path}.file") | data
        return self.checked(name, data, path)

    def command(self, name: str, table: dict[str, Any], path: str) -> CommandConfig:
        for key in table:
            if key != "command":
                self.fail(f"{path}.{key}", "unknown key (a command configuration has only 'command')")
        command = table["command"]
        self.expect(command, list, f"{path}.command", "an array of strings")
        if not command or not all(isinstance(part, str) for part in command):
            self.fail(f"{path}.command", f"expected a non-empty array of strings, got {command!r}")
        for part in command:
            try:
                part.format(**dict.fromkeys(PLACEHOLDERS, ""))
            except (KeyError, IndexError, ValueError) as error:
                known = ", ".join("{" + p + "}" for p in PLACEHOLDERS)
                self.fail(f"{path}.command", f"bad placeholder in {part!r}: {error} (known: {known})")
        return CommandConfig(name, tuple(command))

    def anchor(self, name: str, table: dict[str, Any], path: str) -> AnchorConfig:
        for key in table:
            if key not in ("anchor", "args", "search"):
                self.fail(f"{path}.{key}", "unknown key (expected anchor, args, search)")
        planner = table["anchor"]
        if planner not in anchors.PLANNERS:
            self.fail(f"{path}.anchor", f"expected one of {', '.join(anchors.PLANNERS)}, got {planner!r}")
        args = table.get("args", [])
        if not isinstance(args, list) or not all(isinstance(a, str) for a in args):
            self.fail(f"{path}.args", f"expected an array of strings, got {args!r}")
        search = table.get("search")
        if search is not None and (planner != anchors.FAST_DOWNWARD or not isinstance(search, str)):
            self.fail(f"{path}.search", "expected a string, for fast-downward only")
        return AnchorConfig(name, planner, tuple(args), search)


def _merge_choice(kind: str, base: object, choice: dict[str, Any]) -> dict[str, Any]:
    """The product's choice, keeping the base's options when it names the same class
    (another class's options would not fit)."""
    base_table = {"name": base} if isinstance(base, str) else dict(base or {})
    if base_table.get("name", DEFAULT_CHOICES.get(kind)) == choice.get("name"):
        return base_table | choice
    return dict(choice)


def _label(choice: dict[str, Any]) -> str:
    options = ",".join(f"{k}={v}" for k, v in choice.items() if k != "name")
    return f"{choice['name']}({options})" if options else str(choice["name"])
