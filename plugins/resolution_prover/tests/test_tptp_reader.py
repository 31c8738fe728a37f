"""The TPTP reader: syntax to formulas, problems to proof tasks, results to SZS lines."""

from __future__ import annotations

import pytest

from strips_framework.errors import InputError
from strips_framework.formats.tptp import (
    ANSWER_SEARCH_FACTOR,
    parse_tptp,
    prove_tptp,
    szs_report,
    szs_status,
)
from strips_framework.logic.formulas import (
    And,
    Atomic,
    Exists,
    Forall,
    Iff,
    Implies,
    Not,
    Or,
    Truth,
    Var,
)
from strips_framework.logic.terms import Param
from strips_framework.worldmodel.proving import ProofResult, ProofTask
from strips_resolution_prover import ResolutionProver

X, Y = Var("X"), Var("Y")


def _pair(outcome) -> tuple[str, str | None]:
    return outcome.status, outcome.answers


def only_formula(text: str):
    return parse_tptp(text).formulas[0].formula


def test_cnf_clause_is_closed_universally() -> None:
    formula = only_formula("cnf(c1, axiom, ( p(X) | ~ q(X, f(Y)) | X != a )).")
    assert formula == Forall(
        (X, Y),
        Or((Atomic(("p", X)), Not(Atomic(("q", X, ("f", Y)))), Not(Atomic(("=", X, "a"))))),
    )


def test_fof_connectives_and_quantifiers() -> None:
    text = """
    % a comment
    fof(f, conjecture, ! [X] : ? [Y] : ((p(X) & q) => (r(Y) <=> $true))).
    /* block
       comment */
    fof(g, axiom, (a <= b) & (a <~> b) & (a ~| b) & (a ~& b)).
    """
    problem = parse_tptp(text)
    assert problem.formulas[0].formula == Forall(
        (X,),
        Exists(
            (Y,),
            Implies(And((Atomic(("p", X)), Atomic(("q",)))), Iff(Atomic(("r", Y)), Truth(True))),
        ),
    )
    a, b = Atomic(("a",)), Atomic(("b",))
    assert problem.formulas[1].formula == And(
        (Implies(b, a), Not(Iff(a, b)), Not(Or((a, b))), Not(And((a, b))))
    )
    assert problem.has_conjecture


def test_quoted_names_and_annotations() -> None:
    formula = only_formula("fof('my name', axiom, 'p'('A b') = c, file('x.p', y), [z]).")
    assert formula == Atomic(("=", ("p", "'A b'"), "c"))


@pytest.mark.parametrize(
    ("text", "line", "column", "message"),
    [
        ("fof(a, axiom, p(X)", 1, 19, "expected ')', found end of file"),
        ("fof(a, axiom,\n  p(X) & ).", 2, 10, "expected a formula"),
        ("fof(a, wish, p).", 1, 8, "expected a formula role"),
        ("include('Axioms/SET001-0.ax').", 1, 1, "include"),
        ("fof(a, axiom, ! [x] : p(x)).", 1, 18, "expected a variable"),
        ("fof(a, axiom, p # q).", 1, 17, "unexpected character '#'"),
    ],
)
def test_errors_name_the_position(text: str, line: int, column: int, message: str) -> None:
    with pytest.raises(InputError) as caught:
        parse_tptp(text, "bad.p")
    assert (caught.value.path, caught.value.line, caught.value.column) == ("bad.p", line, column)
    assert message in caught.value.message


def test_conjecture_is_negated_into_the_set_of_support() -> None:
    problem = parse_tptp(
        "fof(a, axiom, ! [X] : (man(X) => mortal(X))).\n"
        "fof(s, axiom, man(socrates)).\n"
        "fof(c, conjecture, mortal(socrates)).\n",
        "syllogism.p",
    )
    task = problem.task(effort=50)
    assert [str(c) for c in task.negated_goal] == ["~mortal(socrates)"]
    assert len(task.axioms) == 2
    result = ResolutionProver().prove(task)
    assert szs_status(problem, result) == "Theorem"
    assert szs_report(problem, result) == "% SZS status Theorem for syllogism"


def test_cnf_without_negated_conjecture_is_all_support() -> None:
    problem = parse_tptp("cnf(a, axiom, p(X)).\ncnf(b, axiom, ~p(a)).")
    task = problem.task()
    assert task.axioms == () and len(task.negated_goal) == 2
    assert szs_status(problem, ResolutionProver().prove(task)) == "Unsatisfiable"
    satisfiable = parse_tptp("cnf(a, axiom, p(X)).\ncnf(b, axiom, ~q(a)).")
    assert szs_status(satisfiable, ResolutionProver().prove(satisfiable.task())) == "Satisfiable"


def test_question_variables_become_parameters_and_answers() -> None:
    problem = parse_tptp(
        "cnf(a, axiom, parent(tom, bob)).\n"
        "cnf(b, axiom, parent(bob, ann)).\n"
        "fof(q, question, ? [X, Y] : (parent(X, Y) & parent(Y, ann))).\n",
        "family.p",
    )
    assert problem.question_variables == (Param("X"), Param("Y"))
    result = ResolutionProver().prove(problem.task(max_answers=3))
    assert szs_report(problem, result) == (
        "% SZS status Theorem for family\n% SZS answers Tuple [[tom, bob]|_] for family"
    )


def test_saturated_question_gives_up() -> None:
    problem = parse_tptp("fof(a, axiom, ? [X] : p(X)).\nfof(q, question, ? [Y] : p(Y)).")
    result = ResolutionProver().prove(problem.task())
    assert result.status == "Satisfiable"
    assert szs_status(problem, result) == "GaveUp"
    assert szs_status(problem, ProofResult("GaveUp")) == "GaveUp"


QUESTIONS = {
    # Only a Skolem term witnesses it: E answers [[esk1_0]|_].
    "skolem": ("fof(a, axiom, ? [X] : p(X)).\nfof(q, question, ? [Y] : p(Y)).", "[[esk1_0]|_]"),
    # p(a) | p(b): E answers [([a]|[b])|_], a disjunction, no one binding.
    "disjunctive": (
        "cnf(a, axiom, p(a) | p(b)).\nfof(q, question, ? [X] : p(X)).",
        "[([a]|[b])|_]",
    ),
}


@pytest.mark.parametrize(("text", "answer"), QUESTIONS.values(), ids=list(QUESTIONS))
def test_a_theorem_without_a_definite_answer_binds_no_parameter(text: str, answer: str) -> None:
    # The TPTP side: the conjecture is a theorem, answered as E does (answer literals).
    # The planner's side: parameters, and no binding (III.A).
    problem = parse_tptp(text)
    assert _pair(prove_tptp(ResolutionProver(), problem, 100)) == ("Theorem", answer)
    result = ResolutionProver().prove(problem.task(100, max_answers=3))
    assert not result.proved and result.answers == ()


def test_a_question_is_answered_definitely_or_refuted() -> None:
    answered = parse_tptp("cnf(a, axiom, p(a)).\nfof(q, question, ? [X] : p(X)).")
    assert _pair(prove_tptp(ResolutionProver(), answered, 100)) == ("Theorem", "[[a]|_]")
    # No instance follows and the conjecture itself does not: the answer is "no".
    false = parse_tptp("cnf(a, axiom, p(a)).\nfof(q, question, ? [X] : r(X)).")
    assert _pair(prove_tptp(ResolutionProver(), false, 100)) == ("CounterSatisfiable", None)


class _Recording:
    """The resolution prover, recording each task's effort and whether it has parameters."""

    def __init__(self) -> None:
        self.calls: list[tuple[bool, int, int]] = []

    def prove(self, task: ProofTask) -> ProofResult:
        result = ResolutionProver().prove(task)
        asks = any(type(a) is Param for c in task.negated_goal for _, atom in c.literals for a in atom[1:])
        self.calls.append((asks, task.effort, result.effort_used))
        return result


def test_the_conjecture_goes_first_and_bounds_the_answer_search() -> None:
    # p(a) | p(b): the conjecture is proved at once, but no
    # definite answer exists, so the answer search would spend the whole effort.
    problem = parse_tptp("cnf(a, axiom, p(a) | p(b)).\nfof(q, question, ? [X] : p(X)).")
    prover = _Recording()
    assert _pair(prove_tptp(prover, problem, 10_000)) == ("Theorem", None)
    (plain, proof_effort, used), (asks, answer_effort, _) = prover.calls
    assert not plain and asks
    assert answer_effort == ANSWER_SEARCH_FACTOR * max(1, used) < 10_000
    # A false conjecture has no answer to look for: one attempt only.
    prover = _Recording()
    false = parse_tptp("cnf(a, axiom, p(a)).\nfof(q, question, ? [X] : r(X)).")
    assert _pair(prove_tptp(prover, false, 10_000)) == ("CounterSatisfiable", None)
    assert [asks for asks, _, _ in prover.calls] == [False]


def test_several_conjectures_are_proved_together() -> None:
    problem = parse_tptp("fof(a, axiom, p).\nfof(c1, conjecture, p).\nfof(c2, conjecture, q).")
    result = ResolutionProver().prove(problem.task())
    assert szs_status(problem, result) == "CounterSatisfiable"
    both = parse_tptp("fof(a, axiom, p & q).\nfof(c1, conjecture, p).\nfof(c2, conjecture, q).")
    assert szs_status(both, ResolutionProver().prove(both.task())) == "Theorem"


def test_false_axiom_and_true_conjecture() -> None:
    problem = parse_tptp("fof(a, axiom, $false).")
    assert szs_status(problem, ResolutionProver().prove(problem.task())) == "Unsatisfiable"
    problem = parse_tptp("fof(c, conjecture, $true).")
    assert szs_status(problem, ResolutionProver().prove(problem.task())) == "Theorem"
