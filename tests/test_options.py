"""Declared options (``strips_framework.options``), the one way options are declared: a
class declared otherwise (keyword arguments of its own ``__init__``, or attrs fields, as
third-party plugins once wrote them) has none."""

from __future__ import annotations

from typing import ClassVar

import pytest

from strips_framework import Planner
from strips_framework.errors import ConfigError
from strips_framework.options import Configurable, Option, OptionError, declared_options
from strips_framework.plugin.hookspecs import hookimpl


class Tuned(Configurable):
    """A heuristic with one option of each kind of check."""

    name: ClassVar[str] = "tuned"
    options = (
        Option("weight", float, 1.0, minimum=0, exclusive_minimum=True, maximum=10),
        Option("rounds", int, 3, minimum=1),
        Option("mode", str, "fast", choices=("fast", "exact")),
        Option("limit", int, None, optional=True),
        Option("verbose", bool, False),
    )

    def for_task(self, task: object) -> object:
        raise NotImplementedError


class OldStyle:
    """A heuristic whose options are its own ``__init__``'s keywords: none are declared."""

    name: ClassVar[str] = "old-style"

    def __init__(self, depth: int = 2) -> None:
        self.depth = depth

    def __eq__(self, other: object) -> bool:
        return type(other) is OldStyle and other.depth == self.depth

    __hash__ = None  # type: ignore[assignment]

    def for_task(self, task: object) -> object:
        raise NotImplementedError


class _Plugin:
    @hookimpl
    def strips_register_heuristics(self) -> list[type]:
        return [Tuned, OldStyle]


def test_defaults_and_given_values():
    assert Tuned().weight == 1.0 and Tuned().limit is None
    tuned = Tuned(weight=2, rounds=5, mode="exact", limit=7, verbose=True)
    assert (tuned.weight, tuned.rounds, tuned.mode, tuned.limit, tuned.verbose) == (2.0, 5, "exact", 7, True)
    assert type(tuned.weight) is float  # TOML writes 2 for 2.0
    assert tuned == Tuned(weight=2.0, rounds=5, mode="exact", limit=7, verbose=True)
    assert tuned != Tuned() and hash(tuned) != hash(Tuned())
    assert repr(Tuned()) == "Tuned(weight=1.0, rounds=3, mode='fast', limit=None, verbose=False)"


@pytest.mark.parametrize(("values", "message"), [
    ({"weight": "heavy"}, "'weight': expected an integer or a float, got a string 'heavy'"),
    ({"weight": 0}, r"'weight': expected a value > 0 \(got 0.0\)"),
    ({"weight": 11}, r"'weight': expected a value <= 10 \(got 11.0\)"),
    ({"rounds": 0}, r"'rounds': expected a value >= 1 \(got 0\)"),
    ({"rounds": True}, "'rounds': expected an integer, got a boolean True"),
    ({"rounds": None}, "'rounds': expected an integer, got NoneType None"),
    ({"mode": "slow"}, "'mode': expected one of 'fast', 'exact', got 'slow'"),
    ({"verbose": 1}, "'verbose': expected a boolean, got an integer 1"),
])
def test_wrong_values_are_refused_naming_the_option(values, message):
    with pytest.raises(OptionError, match=message) as error:
        Tuned(**values)
    assert error.value.option == next(iter(values))


def test_unknown_options_are_refused_and_instances_are_immutable():
    with pytest.raises(TypeError, match="has no option 'wieght'"):
        Tuned(wieght=1.0)
    with pytest.raises(AttributeError, match="immutable"):
        Tuned().weight = 3.0  # type: ignore[misc]


def test_declared_options_only_of_configurable_classes():
    assert declared_options(Tuned) == {
        "weight": 1.0, "rounds": 3, "mode": "fast", "limit": None, "verbose": False
    }
    assert declared_options(OldStyle) == {}
    assert declared_options(dict) == {}


def test_the_config_builds_them_and_reports_bad_values_by_key():
    config = {"strategy": "astar", "heuristic": {"name": "tuned", "weight": 3, "mode": "exact"}}
    planner = Planner.create(config, extra_plugins=[_Plugin()])
    assert planner.config.build(planner.registry, "heuristic") == Tuned(weight=3.0, mode="exact")
    old = Planner.create({"strategy": "astar", "heuristic": "old-style"}, extra_plugins=[_Plugin()])
    assert old.config.build(old.registry, "heuristic") == OldStyle()
    assert old.registry.get("heuristic", "old-style").options() == []
    with pytest.raises(ConfigError, match=r"has no option 'depth' \(options: none; a class declares "
                       r"options by deriving from strips_framework.options.Configurable\)"):
        Planner.create({"strategy": "astar", "heuristic": {"name": "old-style", "depth": 4}},
                       extra_plugins=[_Plugin()])
    with pytest.raises(ConfigError, match=r"bad value for 'heuristic.rounds': expected a value >= 1 \(got 0\)"):
        Planner.create({"strategy": "astar", "heuristic": {"name": "tuned", "rounds": 0}},
                       extra_plugins=[_Plugin()])
    with pytest.raises(ConfigError, match="bad value for 'heuristic.rounds': expected an integer, got a string 'deep'"):
        Planner.create({"strategy": "astar", "heuristic": {"name": "tuned", "rounds": "deep"}},
                       extra_plugins=[_Plugin()])
    with pytest.raises(ConfigError, match=r"has no option 'wieght'; did you mean 'weight'\? \(options: limit, mode, rounds, verbose, weight\)"):
        Planner.create({"strategy": "astar", "heuristic": {"name": "tuned", "wieght": 1}},
                       extra_plugins=[_Plugin()])
