"""What an implementation can do and what it needs of the others: the vocabulary.

Each implementation class declares ``capabilities: ClassVar[frozenset[str]]``, words from
:data:`VOCABULARY`; a class that needs something of the components it works with (a
strategy of its prover, a difference extractor of the prover that feeds it) declares
``requires: ClassVar[tuple[Requirement, ...]]``. :func:`~strips_framework.plugin.checks.check_combination` runs when
a planner is created: a strict requirement that the chosen partner does not declare is a
:class:`~strips_framework.errors.ConfigError` naming the config file and keys, a soft one
(``strict=False``: the combination runs but loses a guarantee) is a warning.

A class without a ``capabilities`` attribute is *undeclared*: nothing is known about it,
so a requirement on it is a warning, never an error (it may well work; declaring says so).
Evaluators and state heuristics that only set the older ``admissible`` class attribute
count as declaring ``{"admissible"}`` or nothing accordingly; a class setting both must
keep them consistent.
"""

from __future__ import annotations

from collections.abc import Iterable

from strips_framework.errors import PluginError
from strips_framework.records import Record

# Provers
EQUALITY = "equality"
QUANTIFIED_AXIOMS = "quantified-axioms"
ANSWERS = "answers"
UNCOMPLETED_PROOF = "uncompleted-proof"
DEFINITE_HORN = "definite-horn"
ALL_ANSWERS = "all-answers"
SOUND = "sound"
COMPLETE = "complete"
EFFORT_BOUND = "effort-bound"
ANSWER_LITERALS = "answer-literals"
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
        DEFINITE_HORN: "answers every task whose axioms are definite Horn clauses (ground "
        "facts, rules with one positive literal whose head's variables occur in its body, "
        "no equations, no function terms with variables: logic.horn.is_datalog_rule) and "
        "whose negated goal is one clause of negated atoms (and, under unique names, the "
        "goal's inequalities); refuses other tasks with ValueError",
        ALL_ANSWERS: "finds every answer in one pass, however large max_answers is, at a "
        "cost that does not grow with the effort (what the lifted search asks for)",
        EFFORT_BOUND: "task.effort bounds the work deterministically: the same task gives "
        "the same result, and effort_used never exceeds effort",
        ANSWER_LITERALS: "a clause of positive $answer literals alone (logic.terms.ANSWER) "
        "is a refutation, the last clause of result.proof; $answer literals are never "
        "resolved upon, so a TPTP question gets answers as E gives them",
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
    "lifted-heuristic": {
        ADMISSIBLE: "the estimate never exceeds the cost of an optimal plan from the state",
        PREFERRED_OPERATORS: "estimate_with_preferred names action instances applicable in "
        "the state that lead towards the goal (heuristics without it name none)",
    },
    "lifted-strategy": {},
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


class Requirement(Record):
    """A capability that the chosen implementation of ``kind`` must declare.

    ``reason`` completes "needs a prover with 'answers' ..." in messages; ``strict=False``
    makes a missing capability a warning: the search still runs but loses what ``reason``
    says (a shortest plan, say).
    """

    kind: str
    capability: str
    reason: str
    strict: bool

    __slots__ = ("kind", "capability", "reason", "strict")

    def __init__(self, kind: str, capability: str, reason: str, strict: bool = True) -> None:
        self.kind = kind
        self.capability = capability
        self.reason = reason
        self.strict = strict


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
        if kind in ("evaluator", "heuristic", "lifted-heuristic") and isinstance(admissible, bool):
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
