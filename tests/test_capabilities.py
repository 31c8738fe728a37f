"""Capabilities: the vocabulary, the declarations and the checks when a planner is made."""

import warnings
from pathlib import Path
from typing import ClassVar

import pytest

from strips_framework.capabilities import (
    ADMISSIBLE,
    ANSWERS,
    SOUND,
    UNCOMPLETED_PROOF,
    VOCABULARY,
    declared,
    requirements,
)
from strips_framework.cli.main import main
from strips_framework.errors import ConfigError, PluginError
from strips_framework.options import Configurable
from strips_framework.planner import Planner
from strips_framework.plugin.config import Config
from strips_framework.plugin.hookspecs import hookimpl
from strips_framework.plugin.registry import KINDS, Registry
from strips_framework.worldmodel.proving import ProofResult, ProofTask

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


def test_every_declared_capability_of_a_registered_plugin_is_in_the_vocabulary():
    registry = Registry.from_plugins()
    for kind in KINDS:
        for registration in registry.registrations(kind):
            have = declared(registration.cls, kind) or frozenset()
            assert have <= set(VOCABULARY.get(kind, {})), (registration.name, have)
            for need in requirements(registration.cls):
                assert need.capability in VOCABULARY[need.kind], (registration.name, need)


def test_every_capability_is_documented_for_plugin_authors():
    table = (EXAMPLES.parent / "docs" / "writing-plugins.md").read_text()
    for kind, words in VOCABULARY.items():
        for capability in words:
            assert f"| `{capability}` |" in table, (kind, capability)


def test_evaluators_keep_admissible_and_their_capabilities_consistent():
    for registration in Registry.from_plugins().registrations("evaluator"):
        cls = registration.cls
        assert cls.admissible == (ADMISSIBLE in declared(cls, "evaluator")), cls


class _Guesser(Configurable):
    """A prover that cannot bind parameters."""

    name: ClassVar[str] = "guesser"
    capabilities: ClassVar[frozenset[str]] = frozenset({SOUND})

    def prove(self, task: ProofTask) -> ProofResult:
        return ProofResult("GaveUp", uncompleted=task.negated_goal)


class _Anonymous(_Guesser):
    """A prover that says nothing about itself."""

    name: ClassVar[str] = "anonymous"
    capabilities: ClassVar[None] = None


class _Provers:
    @hookimpl
    def strips_register_provers(self):
        return [_Guesser, _Anonymous]


def _write(tmp_path: Path, text: str) -> Config:
    path = tmp_path / "strips.toml"
    path.write_text(text)
    return Config.from_file(path)


def test_a_prover_without_answers_for_means_ends_fails_at_config_time(tmp_path):
    config = _write(tmp_path, 'prover = "guesser"\n')
    with pytest.raises(ConfigError) as error:
        Planner.create(config, extra_plugins=[_Provers()])
    assert str(error.value) == (
        f"{tmp_path / 'strips.toml'}: search strategy 'means-ends' ('strategy.name') needs a "
        "prover with 'answers' (it applies each operator with the parameter bindings of its "
        "precondition's proof), but prover 'guesser' ('prover.name') does not declare it "
        "(it declares: sound)"
    )


def test_an_undeclared_prover_is_a_warning_not_an_error(tmp_path):
    config = _write(tmp_path, 'prover = "anonymous"\n')
    with pytest.warns(UserWarning, match="prover 'anonymous' .* declares no capabilities"):
        Planner.create(config, extra_plugins=[_Provers()])


def test_astar_with_an_inadmissible_evaluator_warns_at_config_time(tmp_path):
    config = _write(tmp_path, 'strategy = "model-astar"\nevaluator = "paper"\n')
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        Planner.create(config)
    assert [str(w.message) for w in caught] == [(
        f"{tmp_path / 'strips.toml'}:1: search strategy 'model-astar' ('strategy.name') needs an "
        "evaluator with 'admissible' (its first plan is a shortest one only then), but "
        "evaluator 'paper' ('evaluator.name') does not declare it"
    )]
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        Planner.create(_write(tmp_path, 'strategy = "model-astar"\nevaluator = "breadth-first"\n'))


def test_a_problem_needing_what_the_prover_lacks_fails_before_the_search(tmp_path):
    class _Lookup(_Guesser):
        name: ClassVar[str] = "lookup"
        capabilities: ClassVar[frozenset[str]] = frozenset({SOUND, ANSWERS, UNCOMPLETED_PROOF})

    class _Plugin:
        @hookimpl
        def strips_register_provers(self):
            return [_Lookup]

    planner = Planner.create(_write(tmp_path, 'prover = "lookup"\n'), extra_plugins=[_Plugin()])
    problem = planner.load(EXAMPLES / "robot-world" / "light.strips")
    with pytest.raises(ConfigError, match=(
        r"light.strips: the problem has axioms that are not ground facts, which needs a "
        r"prover with 'quantified-axioms', but prover 'lookup' \('prover.name' in .*strips.toml\) "
        r"does not declare it"
    )):
        planner.solve(problem)


def test_capabilities_contradicting_admissible_are_a_plugin_error():
    class _Confused(Configurable):
        name: ClassVar[str] = "confused"
        admissible: ClassVar[bool] = True
        capabilities: ClassVar[frozenset[str]] = frozenset()

    with pytest.raises(PluginError, match="admissible = True but its capabilities lack"):
        declared(_Confused, "evaluator")


def test_strips_plugins_shows_capabilities_and_requirements(capsys):
    assert main(["plugins"]) == 0
    out = capsys.readouterr().out
    means_ends = out[out.index("  means-ends"):].splitlines()
    assert "      capabilities: none" in means_ends[:4]
    assert "      requires: prover with answers" in means_ends[:4]
    assert "requires: prover with answers; evaluator with admissible (soft: a warning if missing)" in out
    assert "capabilities: answers, effort-bound, equality, quantified-axioms, sound, uncompleted-proof" in out
