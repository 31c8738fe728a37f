"""What an implementation can do, what it needs of the others, and the check at config time.

Each implementation class declares ``capabilities: ClassVar[frozenset[str]]``, words from
:data:`VOCABULARY`; a class that needs something of the components it works with (a
strategy of its prover, a difference extractor of the prover that feeds it) declares
``requires: ClassVar[tuple[Requirement, ...]]``. :func:`check_combination` runs when a
planner is created: a strict requirement that the chosen partner does not declare is a
:class:`~strips_framework.errors.ConfigError` naming the config file and keys, a soft one
(``strict=False``: the combination runs but loses a guarantee) is a warning.

A class without a ``capabilities`` attribute is *undeclared*: nothing is known about it,
so a requirement on it is a warning, never an error (it may well work; declaring says so).
Evaluators and state heuristics that only set the older ``admissible`` class attribute
count as declaring ``{"admissible"}`` or nothing accordingly; a class setting both must
keep them consistent.
"""

from __future__ import annotations

import warnings
from collections.abc import Iterable
from typing import TYPE_CHECKING

from attrs import frozen

from strips_framework.errors import ConfigError, PluginError
from strips_framework.plugins import KINDS

if TYPE_CHECKING:
    from strips_framework.config import Config
    from strips_framework.plugins import Registry
    from strips_framework.problem import Problem

# Provers
EQUALITY = "equality"
QUANTIFIED_AXIOMS = "quantified-axioms"
ANSWERS = "answers"
UNCOMPLETED_PROOF = "uncompleted-proof"
SOUND = "sound"
COMPLETE = "complete"
EFFORT_BOUND = "effort-bound"
# Evaluators and state heuristics
ADMISSIBLE = "admissible"
PREFERRED_OPERATORS = "preferred-operators"
# Strategies
OPTIMAL = "optimal"

#: Every capability a class of each kind may declare, with what declaring it promises.
#: The conformance kit (:mod:`strips_framework.testing`) checks these promises.
VOCABULARY: dict[str, dict[str, str]] = {
    "prover": {
        EQUALITY: "'=' is equality: identical terms are equal, distinct constants differ "
        "under unique names, and equations among the axioms are used",
        QUANTIFIED_AXIOMS: "axioms with universally quantified variables (and Skolem "
        "terms from existentials) are reasoned with, not only ground facts",
        ANSWERS: "parameters of the goal are bound: each refutation gives a binding that "
        "makes the goal follow, up to task.max_answers distinct ones",
        UNCOMPLETED_PROOF: "a failed attempt returns the clauses still to be refuted "
        "(the negated goal's unresolved part), from which differences are made",
        SOUND: "a goal reported proved follows from the axioms; 'Satisfiable' is reported "
        "only for goals that do not follow",
        COMPLETE: "with enough effort every goal that follows is proved, and every binding "
        "among the answers is found when max_answers allows",
        EFFORT_BOUND: "task.effort bounds the work deterministically: the same task gives "
        "the same result, and effort_used never exceeds effort",
    },
    "evaluator": {
        ADMISSIBLE: "the score never exceeds the cost so far plus the least cost still "
        "needed to reach the goal through the node",
    },
    "heuristic": {
        ADMISSIBLE: "the estimate never exceeds the cost of an optimal plan from the state",
        PREFERRED_OPERATORS: "estimate_with_preferred names operators applicable in the "
        "state that lead towards the goal (heuristics without it name none)",
    },
    "strategy": {
        OPTIMAL: "the plan found is a shortest one when the strategy's soft requirements "
        "(e.g. an admissible evaluator) hold",
    },
    "ground-strategy": {
        OPTIMAL: "the plan found is a cheapest one when the strategy's soft requirements "
        "(e.g. an admissible heuristic) hold",
    },
    "difference": {},
    "relevance": {},
    "loader": {},
}


@frozen
class Requirement:
    """A capability that the chosen implementation of ``kind`` must declare.

    ``reason`` completes "needs a prover with 'answers' ..." in messages; ``strict=False``
    makes a missing capability a warning: the search still runs but loses what ``reason``
    says (a shortest plan, say).
    """

    kind: str
    capability: str
    reason: str
    strict: bool = True


#: What an optimal ground-task strategy (``astar``) needs of its state heuristic.
ADMISSIBLE_HEURISTIC = Requirement(
    "heuristic", ADMISSIBLE, "its first plan is a cheapest one only then", strict=False
)


def declared(cls: type, kind: str) -> frozenset[str] | None:
    """The capabilities ``cls`` declares (``None`` when it declares none).

    Raises :class:`PluginError` when ``capabilities`` is not a set of strings, or when it
    contradicts the class's ``admissible`` attribute.
    """
    capabilities = getattr(cls, "capabilities", None)
    admissible = getattr(cls, "admissible", None)
    if capabilities is None:
        if kind in ("evaluator", "heuristic") and isinstance(admissible, bool):
            return frozenset({ADMISSIBLE}) if admissible else frozenset()
        return None
    if not isinstance(capabilities, (frozenset, set)) or not all(
        isinstance(c, str) for c in capabilities
    ):
        raise PluginError(
            f"{cls.__qualname__}.capabilities must be a frozenset of strings, "
            f"got {capabilities!r}"
        )
    if isinstance(admissible, bool) and admissible != (ADMISSIBLE in capabilities):
        raise PluginError(
            f"{cls.__qualname__} says admissible = {admissible} but its capabilities "
            f"{'lack' if admissible else 'include'} {ADMISSIBLE!r}"
        )
    return frozenset(capabilities)


def requirements(cls: type) -> tuple[Requirement, ...]:
    return tuple(getattr(cls, "requires", ()))


def unknown(capabilities: Iterable[str], kind: str) -> list[str]:
    """The capabilities not in the vocabulary of ``kind`` (typos, or a newer framework's)."""
    known = VOCABULARY.get(kind, {})
    return sorted(c for c in capabilities if c not in known)


def check_combination(registry: Registry, config: Config, kinds: Iterable[str]) -> None:
    """Raise :class:`ConfigError` if a chosen implementation lacks a strictly required
    capability of another; warn for soft requirements and undeclared implementations.
    Only the ``kinds`` a run uses are looked at (a forward search has no prover)."""
    chosen = {kind: registry.get(kind, config.choice(kind).name) for kind in kinds}
    for kind, registration in chosen.items():
        for need in requirements(registration.cls):
            partner = chosen.get(need.kind)
            if partner is None:
                continue
            have = declared(partner.cls, need.kind)
            if have is not None and need.capability in have:
                continue
            words = KINDS[need.kind][1]
            message = (
                f"{config.source}: {KINDS[kind][1]} {registration.name!r} "
                f"('{config.table_of(kind)}.name') "
                f"needs {_article(words)} {words} with {need.capability!r} ({need.reason}), "
                f"but "
                f"{words} {partner.name!r} ('{need.kind}.name') "
            )
            if have is None:
                warnings.warn(message + "declares no capabilities", stacklevel=3)
            elif need.strict:
                shown = ", ".join(sorted(have)) or "none"
                raise ConfigError(message + f"does not declare it (it declares: {shown})")
            else:
                warnings.warn(message + "does not declare it", stacklevel=3)


def check_problem(problem: Problem, registry: Registry, config: Config) -> None:
    """Raise :class:`ConfigError` if ``problem`` uses what the chosen prover does not
    declare: axioms beyond ground facts (``quantified-axioms``) or ``=`` (``equality``);
    warn if the prover declares nothing. Called before a search, so a prover is never
    asked what it cannot answer halfway through."""
    prover = registry.get("prover", config.choices["prover"].name)
    have = declared(prover.cls, "prover")
    for capability, where in _problem_needs(problem).items():
        if have is not None and capability in have:
            continue
        message = (
            f"{problem.source}: the problem has {where}, which needs a prover with "
            f"{capability!r}, but prover {prover.name!r} ('prover.name' in {config.source}) "
        )
        if have is None:
            warnings.warn(message + "declares no capabilities", stacklevel=3)
        else:
            raise ConfigError(message + "does not declare it")


def _problem_needs(problem: Problem) -> dict[str, str]:
    """The prover capabilities a problem needs, each with where the need comes from.
    (The logic is imported here: a forward search on PDDL never calls this.)"""
    from strips_framework.logic.formulas import Atomic, atoms_of
    from strips_framework.logic.terms import EQUALITY as EQUALS_SIGN

    needs = {}
    if any(not isinstance(axiom, Atomic) for axiom in problem.axioms):
        needs[QUANTIFIED_AXIOMS] = "axioms that are not ground facts"
    formulas = [
        ("the goal", problem.goal),
        *(("the axioms", axiom) for axiom in problem.axioms),
        *((f"the precondition of {s.name}", s.precondition) for s in problem.operators),
    ]
    for where, formula in formulas:
        if any(atom[0] == EQUALS_SIGN for atom in atoms_of(formula)):
            needs[EQUALITY] = f"'=' in {where}"
            break
    return needs


def _article(words: str) -> str:
    return "an" if words[0] in "aeiou" else "a"
