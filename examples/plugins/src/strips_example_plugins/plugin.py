"""The entry-point module: one hook per kind of implementation this distribution adds."""

from __future__ import annotations

from strips_example_plugins.facts_prover import FactsProver
from strips_example_plugins.goals_left import GoalsLeft
from strips_framework.plugin.hookspecs import hookimpl


@hookimpl
def strips_register_provers() -> list[type]:
    return [FactsProver]


@hookimpl
def strips_register_evaluators() -> list[type]:
    return [GoalsLeft]
