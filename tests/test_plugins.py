"""The plugin manager, the registry and the hook documentation."""

import inspect
from pathlib import Path
from typing import ClassVar

import pytest

from strips_framework.errors import PluginError
from strips_framework.options import Configurable
from strips_framework.plugin import hookspecs
from strips_framework.plugin.hookspecs import hookimpl
from strips_framework.plugin.manager import get_plugin_manager
from strips_framework.plugin.registry import KINDS, Registry

DOCS = Path(__file__).resolve().parents[1] / "docs" / "hooks.md"
HOOKS = [
    (name, fn) for name, fn in inspect.getmembers(hookspecs, inspect.isfunction)
    if name.startswith("strips_")
]


def test_there_are_hooks_for_every_kind():
    assert {hook for hook, _, _ in KINDS.values()} == {name for name, _ in HOOKS}


@pytest.mark.parametrize(("name", "spec"), HOOKS, ids=[name for name, _ in HOOKS])
def test_every_hook_has_a_docstring_and_is_documented(name, spec):
    assert (spec.__doc__ or "").strip(), f"hook {name} has no docstring"
    signature = f"{name}() -> {inspect.signature(spec).return_annotation}"
    assert f"### `{signature}`" in DOCS.read_text(), f"{signature} is not in docs/hooks.md"


def test_builtins_register_through_the_hooks():
    registry = Registry(get_plugin_manager(load_entrypoints=False))
    assert registry.names("strategy") == ["means-ends", "model-astar"]
    assert registry.names("ground-strategy") == [
        "astar", "breadth-first", "ehc", "gbfs", "lazy-gbfs", "wastar"
    ]
    assert registry.names("difference") == ["uncompleted-proof"]
    assert registry.names("relevance") == ["add-list"]
    assert registry.names("evaluator") == ["paper"]  # the means-ends default, without plugins
    assert registry.names("prover") == ["joins"]
    assert "native" in registry.names("loader")
    assert registry.get("strategy", "means-ends").distribution is None


def test_installed_plugins_come_from_their_distributions():
    registry = Registry(get_plugin_manager(load_entrypoints=True))
    assert registry.get("prover", "resolution").distribution == "strips-resolution-prover"
    assert registry.get("evaluator", "goal-count").distribution == "strips-evaluators"
    assert registry.get("evaluator", "paper").distribution is None  # the core's builtin


def test_unknown_name_lists_the_available_ones_and_a_close_name(monkeypatch):
    monkeypatch.delenv("STRIPS_DISABLE_PLUGIN_AUTOLOAD", raising=False)
    registry = Registry(get_plugin_manager(load_entrypoints=False))
    with pytest.raises(PluginError) as error:
        registry.get("prover", "z3")
    assert str(error.value) == (
        "prover 'z3' is not registered (available: joins); is the plugin that provides it "
        "installed? 'strips plugins' lists them"
    )
    with pytest.raises(PluginError, match=r"'means-end' .*; did you mean 'means-ends'\?"):
        registry.get("strategy", "means-end")


def test_with_autoload_off_the_message_names_the_plugins_left_unloaded(monkeypatch):
    monkeypatch.setenv("STRIPS_DISABLE_PLUGIN_AUTOLOAD", "1")
    registry = Registry(get_plugin_manager(load_entrypoints=False))
    with pytest.raises(PluginError, match=r"plugin autoload is off .*installed: .*strips-resolution-prover"):
        registry.get("prover", "resolution")
    with pytest.raises(PluginError, match=r"strategy 'dfs' is not registered \(available: means-ends, "):
        registry.get("strategy", "dfs")


class _Clash(Configurable):
    """A second 'means-ends'."""

    name: ClassVar[str] = "means-ends"


class _ClashPlugin:
    @hookimpl
    def strips_register_strategies(self):
        return [_Clash]


def test_duplicate_names_are_errors_when_the_kind_is_looked_up():
    registry = Registry(get_plugin_manager([_ClashPlugin()], load_entrypoints=False))
    with pytest.raises(PluginError, match="'means-ends' is registered twice"):
        registry.names("strategy")


class _Misspelled:
    @hookimpl
    def strips_register_provrs(self):
        return []


def test_misspelled_hook_implementation_is_an_error():
    with pytest.raises(Exception, match="strips_register_provrs"):
        get_plugin_manager([_Misspelled()], load_entrypoints=False)


def test_autoload_switch(monkeypatch):
    monkeypatch.setenv("STRIPS_DISABLE_PLUGIN_AUTOLOAD", "1")
    assert Registry(get_plugin_manager()).names("prover") == ["joins"]  # the builtin one


class _OnlyHeuristic:
    @hookimpl
    def strips_register_heuristics(self):
        from strips_evaluators.heuristics.goal_count import GoalCountHeuristic

        return [GoalCountHeuristic]


def test_defaults_come_from_what_is_registered(monkeypatch):
    """The core alone: a preferred default that is missing ('resolution', 'ff') gives way
    to the one implementation registered (the builtin 'joins' prover, the builtin 'blind'
    heuristic); one the core has ('paper') stays; a table with several registered and
    none preferred keeps its first preference, whose lookup says what is missing."""
    from strips_framework.plugin.config import Config, default_name

    monkeypatch.setenv("STRIPS_DISABLE_PLUGIN_AUTOLOAD", "1")
    bare = Registry(get_plugin_manager())
    assert default_name(bare, ("prover",), ("resolution",)) == "joins"
    assert default_name(bare, ("heuristic",), ("ff",)) == "blind"
    config = Config.default().with_registered_defaults(bare, ("prover", "evaluator", "heuristic"))
    assert config.choices["prover"].name == "joins"
    assert config.choices["evaluator"].name == "paper"
    assert config.choices["heuristic"].name == "blind"
    registry = Registry(get_plugin_manager([_OnlyHeuristic()]))  # blind and goal-count
    assert default_name(registry, ("heuristic",), ("ff",)) == "ff"
    assert default_name(registry, ("heuristic",), ("goal-count", "ff")) == "goal-count"
    several = Config.default().with_registered_defaults(registry, ("heuristic",))
    assert several.choices["heuristic"].name == "ff"
    with pytest.raises(PluginError, match=r"no \[heuristic\] chosen, and the default state heuristic 'ff' is not registered"):
        several.registration(registry, "heuristic")
    chosen = Config.from_dict({"prover": "resolution"}).with_registered_defaults(registry, ("prover",))
    assert chosen.choices["prover"].name == "resolution"  # what the file chose stays
