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
        r"light.strips: the problem has axioms that are rules \(definite Horn clauses\), which "
        r"needs a prover with 'quantified-axioms' or 'definite-horn', but prover 'lookup' "
        r"\('prover.name' in .*strips.toml\) does not declare it"
    )):
        planner.solve(problem)


ONE_BOX = """problem one-box
constants a b BOX1
primitive ATR/1 AT/2
facts
  ATR(a)
  AT(BOX1, a)
  PUSHABLE(BOX1)
{axioms}
operator push(k, m, n)
  pre    AT(k, m) & ATR(m) & {pushable}
  delete AT(k, m), ATR(m)
  add    AT(k, n), ATR(n)
goal AT(BOX1, b)
"""


def _one_box(tmp_path: Path, axioms: str = "", pushable: str = "PUSHABLE(k)") -> Path:
    path = tmp_path / "one-box.strips"
    path.write_text(ONE_BOX.format(axioms=axioms, pushable=pushable))
    return path


@pytest.mark.parametrize(
    "axioms",
    ["", "axioms\n  forall x: BOX(x) -> PUSHABLE(x)\n  forall x, y: AT(x, y) -> PLACE(y)"],
    ids=["facts", "safe-rules"],
)
def test_a_definite_horn_task_is_answered_by_a_definite_horn_prover(tmp_path, axioms):
    planner = Planner.create(_write(tmp_path, 'prover = "joins"\n'))
    result = planner.solve(planner.load(_one_box(tmp_path, axioms)))
    assert result.solved and [str(s) for s in result.plan] == ["(push BOX1 a b)"]


@pytest.mark.parametrize(
    ("axioms", "pushable", "where"),
    [
        ("axioms\n  forall x: PUSHABLE(x) -> HEAVY(x) | LIGHT(x)", "PUSHABLE(k)",
         "its axioms are not all definite Horn rules"),
        ("axioms\n  forall x, y: PUSHABLE(x) -> NEAR(x, y)", "PUSHABLE(k)",
         "its axioms are not all definite Horn rules"),  # y is bound by no premise
        ("", "~FIXED(k)", "the precondition of push is not a conjunction of atoms and inequalities"),
    ],
    ids=["disjunctive-axiom", "unsafe-rule", "negated-precondition"],
)
def test_what_is_not_a_definite_horn_task_is_refused_before_a_horn_prover_sees_it(
    tmp_path, axioms, pushable, where
):
    planner = Planner.create(_write(tmp_path, 'prover = "joins"\n'))
    problem = planner.load(_one_box(tmp_path, axioms, pushable))
    with pytest.raises(ConfigError) as error:
        planner.solve(problem)
    assert str(error.value) == (
        f"{problem.source}: the problem is not a definite Horn task ({where}), but prover "
        f"'joins' ('prover.name' in {tmp_path / 'strips.toml'}) declares 'definite-horn' "
        "without 'quantified-axioms': it answers definite Horn tasks only"
    )


def test_a_first_order_prover_takes_what_a_horn_prover_refuses(tmp_path):
    planner = Planner.create(_write(tmp_path, 'prover = "resolution"\n'))
    problem = planner.load(_one_box(tmp_path, "axioms\n  forall x: PUSHABLE(x) -> HEAVY(x) | LIGHT(x)"))
    assert planner.solve(problem).solved


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
