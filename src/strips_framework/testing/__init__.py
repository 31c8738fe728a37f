"""The conformance kit: checks any prover, node evaluator, state heuristic or search
strategy runs against itself, with one class in its own tests::

    from strips_framework.testing import ProverConformance

    class TestMyProver(ProverConformance):
        prover_class = MyProver

(``EvaluatorConformance`` with ``evaluator_class``, ``HeuristicConformance`` with
``heuristic_class``, ``StrategyConformance`` with ``strategy_class`` for a world-model
strategy, ``GroundStrategyConformance`` with ``strategy_class`` for a ground-task one.) What is checked depends on the capabilities the class
declares (see :mod:`strips_framework.capabilities`); ``docs/writing-plugins.md`` walks
through it. The
check functions can also be called directly; they raise :class:`ConformanceFailure`.
Needs pytest (``pip install strips-framework[testing]``).
"""

from strips_framework.testing.declaration import (
    ConformanceFailure,
    check_declaration,
    check_options_refuse_wrong_values,
)
from strips_framework.testing.ground_search_checks import (
    check_expansion_limit,
    check_solves_task,
    check_unsolvable,
)
from strips_framework.testing.ground_tasks import TASKS, UNSOLVABLE
from strips_framework.testing.heuristic_checks import check_heuristic
from strips_framework.testing.prover_cases import CASES, ProverCase
from strips_framework.testing.prover_checks import (
    check_case,
    check_effort_bound,
    check_refuses_unsupported,
    check_uncompleted_proof,
)
from strips_framework.testing.search_checks import (
    PROBLEMS,
    check_admissible,
    check_plan,
    check_solves,
    planner_for,
    recorded_search,
)
from strips_framework.testing.suites import (
    EvaluatorConformance,
    GroundStrategyConformance,
    HeuristicConformance,
    ProverConformance,
    StrategyConformance,
)

__all__ = [
    "CASES",
    "PROBLEMS",
    "TASKS",
    "UNSOLVABLE",
    "ConformanceFailure",
    "EvaluatorConformance",
    "HeuristicConformance",
    "ProverCase",
    "ProverConformance",
    "GroundStrategyConformance",
    "StrategyConformance",
    "check_admissible",
    "check_case",
    "check_declaration",
    "check_effort_bound",
    "check_expansion_limit",
    "check_heuristic",
    "check_options_refuse_wrong_values",
    "check_plan",
    "check_refuses_unsupported",
    "check_solves",
    "check_solves_task",
    "check_uncompleted_proof",
    "check_unsolvable",
    "planner_for",
    "recorded_search",
]
