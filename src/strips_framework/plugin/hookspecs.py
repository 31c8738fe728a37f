"""Every hook a plugin can implement, in one place.

Hooks *register implementation classes*; each is called once, when the registry first
looks up its kind, never inside search or proving loops (a pluggy call costs microseconds). The core
keeps the classes in a :class:`~strips_framework.plugin.registry.Registry`, the config picks one
class of each kind by its ``name``, and the search calls the chosen objects directly.

Every implementation class has a ``name`` class attribute and declared options
(:mod:`strips_framework.options`: a ``Configurable`` with its ``Option`` tuple; a class
declared otherwise has none): the config passes ``[prover.options]`` and the
like as keyword arguments, and ``strips plugins`` lists the options with their defaults. It declares
``capabilities`` and, if it needs something of the other components, ``requires`` (see
:mod:`strips_framework.capabilities`); :mod:`strips_framework.testing` checks both.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import pluggy

if TYPE_CHECKING:
    from strips_framework.formats import ProblemLoader
    from strips_framework.forward.components import GroundTaskStrategy, StateHeuristic
    from strips_framework.lifted.components import LiftedHeuristic
    from strips_framework.lifted.search import LiftedStrategy
    from strips_framework.macrops.learning import MacroLearner
    from strips_framework.means_ends.components import (
        DifferenceExtractor,
        NodeEvaluator,
        RelevanceFilter,
        SearchStrategy,
    )
    from strips_framework.worldmodel.proving import TheoremProver

PROJECT = "strips_framework"
hookspec = pluggy.HookspecMarker(PROJECT)
hookimpl = pluggy.HookimplMarker(PROJECT)


@hookspec
def strips_register_provers() -> list[type[TheoremProver]]:
    """Return theorem-prover classes.

    A prover answers :class:`~strips_framework.worldmodel.proving.ProofTask` questions with a
    :class:`~strips_framework.worldmodel.proving.ProofResult`: whether ``axioms ∪ negated_goal`` is
    refuted, the parameter bindings of each refutation (answer extraction), and, when it
    fails within the effort bound, the uncompleted proof (paper, III.A and III.C).
    """


@hookspec
def strips_register_difference_extractors() -> list[type[DifferenceExtractor]]:
    """Return difference-extractor classes.

    A difference extractor turns a failed proof's uncompleted proof into the node's
    *difference*: the clauses that operators must help resolve away (paper, III.C,
    including its note that a large uncompleted proof may be cut down heuristically).
    """


@hookspec
def strips_register_relevance_filters() -> list[type[RelevanceFilter]]:
    """Return operator-relevance classes.

    A relevance filter's ``for_problem(operators, initial)`` indexes one problem's
    operator schemata and M0 once per search; the :class:`~strips_framework.means_ends.components.ProblemRelevance` it returns is
    asked ``relevant(difference, model)`` at every node and returns the relevant operator
    instances, best first: the candidates whose add lists mention the difference's
    predicates, instantiated by resolving add-list clauses against difference clauses
    (paper, III.C).
    """


@hookspec
def strips_register_evaluators() -> list[type[NodeEvaluator]]:
    """Return node-evaluator classes.

    An evaluator scores a search node (lower is better); strategies expand the best-scored
    node next (paper, II.B and V). An evaluator that never overestimates the number of
    operator applications still needed, added to those made so far, declares the
    capability ``admissible`` (and sets ``admissible = True``) so that optimal strategies
    can rely on it.
    """


@hookspec
def strips_register_strategies() -> list[type[SearchStrategy]]:
    """Return world-model search-strategy classes.

    A strategy searches from a problem's initial world model for a plan, using the prover,
    difference extractor, relevance filter and evaluator it is given, within the limits of
    the config; it returns a :class:`~strips_framework.result.Result` with the plan (if
    any), the search tree and the paper's Table 2 statistics
    (:class:`~strips_framework.means_ends.result.WorldModelStatistics`).
    """


@hookspec
def strips_register_ground_strategies() -> list[type[GroundTaskStrategy]]:
    """Return ground-task search-strategy classes.

    A ground-task strategy searches the states of a
    :class:`~strips_framework.grounding.task.GroundTask` (PDDL input, grounded) with the
    estimator of the configured state heuristic; it returns a
    :class:`~strips_framework.result.Result` with Fast Downward's counts
    (:class:`~strips_framework.forward.result.ForwardStatistics`). The config names
    it in the same ``[strategy]`` table as the world-model strategies, so its name must
    differ from theirs.
    """


@hookspec
def strips_register_lifted_strategies() -> list[type[LiftedStrategy]]:
    """Return lifted-task search-strategy classes.

    A lifted strategy searches a PDDL task without grounding it (see
    :mod:`strips_framework.lifted`): it is given the task's
    :class:`~strips_framework.lifted.successors.Successors` (the compiled task and the query
    engine that answers its preconditions) and the estimator of the configured lifted
    heuristic, and returns a :class:`~strips_framework.result.Result` with
    :class:`~strips_framework.lifted.result.LiftedStatistics`. The config names it in
    the ``[strategy]`` table, so its name must differ from every other strategy's.
    """


@hookspec
def strips_register_heuristics() -> list[type[StateHeuristic]]:
    """Return state-heuristic classes.

    A state heuristic estimates, for a state of a ground task (see
    :mod:`strips_framework.grounding.task`), the cost still needed to reach the goal;
    forward strategies (A*, greedy best-first, hill-climbing) use it. ``for_task`` is
    called once per task and does the precomputation; the estimator it returns is called
    for every state: it must have ``estimate``, and may have ``estimate_with_preferred``
    when it proposes *preferred operators* (an estimator without it proposes none). A
    heuristic that never overestimates sets ``admissible = True``.
    """


@hookspec
def strips_register_lifted_heuristics() -> list[type[LiftedHeuristic]]:
    """Return lifted-heuristic classes.

    A lifted heuristic estimates, for a state of a PDDL task that is never grounded (see
    :mod:`strips_framework.lifted.components`), the cost still needed to reach the goal;
    lifted strategies use it. ``for_task`` is called once per task and must not ground
    the task; the estimator it returns is called for every state.
    """


@hookspec
def strips_register_loaders() -> list[type[ProblemLoader]]:
    """Return problem-loader classes.

    A loader reads files with the suffixes it declares in ``suffixes`` and returns a
    :class:`~strips_framework.worldmodel.problem.Problem`; on bad input it raises
    :class:`~strips_framework.errors.InputError` naming the file, line and what was expected.
    """


@hookspec
def strips_register_macro_learners() -> list[type[MacroLearner]]:
    """Return macro-learner classes.

    A macro learner turns a solved problem and its plan into a MACROP library with what
    it learned (Fikes, Hart & Nilsson 1972): ``learn(problem, steps, library)`` returns
    the new :class:`~strips_framework.macrops.macrop.Library` and a line saying what
    happened. ``strips learn`` calls it after each problem of a sequence; the builtin
    ``triangle-table`` learner generalizes the plan's triangle table.
    """
