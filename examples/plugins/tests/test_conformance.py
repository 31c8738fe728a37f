"""The whole conformance kit, one line per implementation."""

from strips_example_plugins.facts_prover import FactsProver
from strips_example_plugins.goals_left import GoalsLeft
from strips_framework.testing import EvaluatorConformance, ProverConformance


class TestFactsProver(ProverConformance):
    prover_class = FactsProver


class TestGoalsLeft(EvaluatorConformance):
    evaluator_class = GoalsLeft
