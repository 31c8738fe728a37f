from __future__ import annotations

import inspect

import pluggy

from strips_evaluators import plugin
from strips_framework.means_ends.components import evaluator_for_problem
from strips_framework.options import Configurable
from strips_framework.plugin import hookspecs


def test_hook_returns_every_evaluator_with_a_unique_name_and_docs() -> None:
    """Every evaluator but the paper's, which is the core's builtin (tests/test_paper_evaluator.py)."""
    classes = plugin.strips_register_evaluators()
    names = [cls.name for cls in classes]
    assert sorted(names) == [
        "astar-goals", "breadth-first", "goal-count", "relaxed-max", "relaxed-plan",
    ]
    for cls in classes:
        assert issubclass(cls, Configurable)  # the core's one way to declare options
        assert isinstance(cls.admissible, bool)
        assert inspect.getdoc(cls) and len(inspect.getdoc(cls)) > 80
        assert all(option.doc for option in cls.options), f"{cls.name}: an option without doc"
        cls()  # every option has a valid default


def test_hook_implements_the_core_spec() -> None:
    manager = pluggy.PluginManager(hookspecs.PROJECT)
    manager.add_hookspecs(hookspecs)
    manager.register(plugin)
    manager.check_pending()
    assert manager.hook.strips_register_evaluators() == [plugin.strips_register_evaluators()]


def test_evaluators_are_frozen(make_node) -> None:
    for cls in plugin.strips_register_evaluators():
        evaluator = cls()
        node = make_node()
        evaluator_for_problem(evaluator, [], node.model.initial).evaluate(node)
        for option in cls.options:
            try:
                setattr(evaluator, option.name, 1.0)
            except AttributeError:
                continue
            raise AssertionError(f"{cls.name}.{option.name} is mutable")


def test_heuristic_hook_returns_documented_heuristics_with_unique_names() -> None:
    classes = plugin.strips_register_heuristics()
    names = [cls.name for cls in classes]
    assert len(set(names)) == len(names)
    assert {"goal-count", "ff"} <= set(names)
    for cls in classes:
        assert issubclass(cls, Configurable)  # declared options: no attrs at start-up
        assert isinstance(cls.admissible, bool)
        assert inspect.getdoc(cls) and len(inspect.getdoc(cls)) > 80
        cls()  # every option has a valid default


def test_heuristics_are_registered_through_the_core_spec() -> None:
    manager = pluggy.PluginManager(hookspecs.PROJECT)
    manager.add_hookspecs(hookspecs)
    manager.register(plugin)
    assert manager.hook.strips_register_heuristics() == [plugin.strips_register_heuristics()]
