"""Checks of a prover against cases with known answers and against its own declaration.

Every check raises :class:`~strips_framework.testing.declaration.ConformanceFailure`
with a message saying which case, what the prover answered and what was expected.
Whatever a prover declares, it must never call a goal that follows ``Satisfiable``,
return a binding that does not make the goal follow, or answer a proof without a binding
(the searches read ``answers[0]``); the rest depends on its capabilities.
"""

from __future__ import annotations

import itertools
from collections.abc import Set as AbstractSet

from strips_framework.capabilities import (
    ANSWERS,
    COMPLETE,
    EFFORT_BOUND,
    EQUALITY,
    QUANTIFIED_AXIOMS,
    SOUND,
    UNCOMPLETED_PROOF,
)
from strips_framework.logic.clauses import Clause
from strips_framework.testing.declaration import ConformanceFailure
from strips_framework.testing.prover_cases import CASES, ProverCase, pigeonhole
from strips_framework.worldmodel.proving import (
    GAVE_UP,
    PROVED,
    SATURATED,
    Answer,
    ProofResult,
    ProofTask,
    TheoremProver,
)


def ask(prover: TheoremProver, task: ProofTask, what: str) -> ProofResult:
    """``prover.prove(task)``, checked to be a well-formed :class:`ProofResult`."""
    result = prover.prove(task)
    if not isinstance(result, ProofResult):
        raise ConformanceFailure(f"{what}: prove() returned {result!r}, not a ProofResult")
    if result.status not in (PROVED, SATURATED, GAVE_UP):
        raise ConformanceFailure(f"{what}: unknown status {result.status!r}")
    if result.proved and not 1 <= len(result.answers) <= task.max_answers:
        raise ConformanceFailure(
            f"{what}: proved with {len(result.answers)} answers; a proof gives 1 to "
            f"max_answers={task.max_answers} (the empty binding () for a goal without "
            "parameters)"
        )
    if not result.proved and result.answers:
        raise ConformanceFailure(f"{what}: status {result.status} but answers {result.answers}")
    if result.proved and result.uncompleted:
        raise ConformanceFailure(f"{what}: proved, yet an uncompleted proof is returned")
    return result


def check_case(prover: TheoremProver, case: ProverCase, capabilities: AbstractSet[str]) -> ProofResult:
    """The prover's answer to ``case`` is right as far as its capabilities promise."""
    what = f"case {case.name!r} ({case.why})"
    result = ask(prover, case.task, what)
    if result.proved and not case.provable:
        raise ConformanceFailure(f"{what}: claims a proof, but the goal does not follow")
    if result.status == SATURATED and case.provable:
        raise ConformanceFailure(f"{what}: says Satisfiable, but the goal follows")
    if case.provable and not result.proved and COMPLETE in capabilities:
        raise ConformanceFailure(
            f"{what}: {result.status} after {result.effort_used} of {case.task.effort} "
            "effort on a goal that follows, though the prover declares 'complete'"
        )
    if result.proved:
        _check_answers(case, result.answers, capabilities, what)
    if not result.proved and UNCOMPLETED_PROOF in capabilities and not result.uncompleted:
        raise ConformanceFailure(
            f"{what}: no proof and no uncompleted proof, though the prover declares "
            "'uncompleted-proof'"
        )
    if EFFORT_BOUND in capabilities:
        if result.effort_used > case.task.effort:
            raise ConformanceFailure(
                f"{what}: effort_used {result.effort_used} exceeds the effort {case.task.effort}"
            )
        again = ask(prover, case.task, what)
        if (again.status, again.answers) != (result.status, result.answers):
            raise ConformanceFailure(
                f"{what}: asked twice, answers {result.status} {result.answers} then "
                f"{again.status} {again.answers}; 'effort-bound' promises deterministic runs"
            )
    return result


def _check_answers(
    case: ProverCase, answers: tuple[Answer, ...], capabilities: AbstractSet[str], what: str
) -> None:
    if len(set(answers)) != len(answers):
        raise ConformanceFailure(f"{what}: the same binding is returned twice: {answers}")
    for answer in answers:
        wrong = _wrong_binding(case, answer)
        if wrong:
            raise ConformanceFailure(f"{what}: binding {_show(answer)} {wrong}")
    if COMPLETE in capabilities and ANSWERS in capabilities:
        wanted = min(len(case.answers), case.task.max_answers)
        if len(answers) < wanted:
            raise ConformanceFailure(
                f"{what}: {len(answers)} binding(s) {[_show(a) for a in answers]} of the "
                f"{wanted} asked for and available ({sorted(map(_show, case.answers))}), "
                "though the prover declares 'complete' and 'answers'"
            )


def _wrong_binding(case: ProverCase, answer: Answer) -> str | None:
    """Why ``answer`` does not make the goal follow, or ``None`` if it does.

    A parameter the answer leaves open must work with every value."""
    if not isinstance(answer, tuple) or not all(
        isinstance(pair, tuple) and len(pair) == 2 for pair in answer
    ):
        return "is not a tuple of (parameter, term) pairs"
    bound = dict(answer)
    strange = [p for p in bound if p not in case.params]
    if strange:
        return f"binds {strange}, which are not parameters of the goal"
    if list(answer) != sorted(answer, key=lambda pair: (pair[0].name, pair[0].tag)):
        return "is not sorted by parameter name (as Clause.bindings are)"
    open_params = [p for p in case.params if p not in bound]
    for values in itertools.product(case.constants, repeat=len(open_params)):
        full = {**bound, **dict(zip(open_params, values))}
        complete = tuple((p, full[p]) for p in case.params)
        if complete not in case.answers:
            return f"does not make the goal follow (e.g. with {_show(complete)})"
    return None


def _show(answer: Answer) -> str:
    return "{" + ", ".join(f"{p.name}={t}" for p, t in answer) + "}"


def check_uncompleted_proof(prover: TheoremProver) -> None:
    """For ``P(a) & Q(a)`` with only ``P(a)`` known, the uncompleted proof holds ``~Q(a)``:
    what is left to refute once the model has done what it can (the difference the
    means-ends search works on)."""
    case = next(c for c in CASES if c.name == "conjunction-with-a-missing-part")
    result = ask(prover, case.task, f"case {case.name!r}")
    wanted = Clause([(False, ("Q", "a"))])
    if wanted not in result.uncompleted:
        shown = [str(c) for c in result.uncompleted]
        raise ConformanceFailure(
            f"case {case.name!r}: the uncompleted proof {shown} lacks {wanted}, the part of "
            "the goal the model does not give"
        )


def check_effort_bound(prover: TheoremProver) -> None:
    """Effort 1 on a pigeonhole goal gives up, the same way every time."""
    task = pigeonhole(6)
    results = [ask(prover, task, "pigeonhole(6) at effort 1") for _ in range(3)]
    first = results[0]
    if first.status != GAVE_UP:
        raise ConformanceFailure(
            f"pigeonhole(6) at effort 1: {first.status}; a prover declaring 'effort-bound' "
            "must give up on a hard goal when allowed the least effort"
        )
    if first.effort_used > task.effort:
        raise ConformanceFailure(f"effort_used {first.effort_used} exceeds the effort 1")
    if any(r != first for r in results[1:]):
        raise ConformanceFailure("pigeonhole(6) at effort 1: the results differ between runs")


#: What a prover that does not declare a capability is shown, to see that it refuses it.
_UNSUPPORTED = {
    EQUALITY: "unique-names",
    QUANTIFIED_AXIOMS: "horn-axiom",
}


def check_refuses_unsupported(prover: TheoremProver, capabilities: AbstractSet[str]) -> None:
    """A task using what the prover does not declare is answered correctly anyway or
    refused with ``ValueError`` (or ``NotImplementedError``); never a wrong answer or a
    stray exception."""
    for capability, name in _UNSUPPORTED.items():
        if capability in capabilities:
            continue
        case = next(c for c in CASES if c.name == name)
        if not case.needs - {capability, SOUND} <= capabilities:
            continue
        try:
            check_case(prover, case, capabilities | {SOUND})
        except (ValueError, NotImplementedError):
            continue
        except ConformanceFailure as failure:
            raise ConformanceFailure(
                f"without {capability!r} declared: {failure}; refuse such tasks with "
                "ValueError instead"
            ) from failure
