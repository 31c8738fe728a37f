"""``strips prove`` as an automated theorem prover: exit codes by SZS status, the CPU
limit, unbounded effort by default, ``--json``, and strict reading of defined symbols."""

from __future__ import annotations

import json

import pytest

from strips_framework import exit_codes
from strips_framework.cli.main import main

#: A problem for each status, and the exit code ``strips prove`` gives it.
CASES = {
    "Theorem": ("fof(a, axiom, p(a)).\nfof(c, conjecture, ? [X] : p(X)).", 0),
    "Unsatisfiable": ("cnf(a, axiom, p(a)).\ncnf(b, negated_conjecture, ~p(X)).", 0),
    "CounterSatisfiable": ("fof(a, axiom, p(a)).\nfof(c, conjecture, p(b)).", 1),
    "Satisfiable": ("cnf(a, axiom, p(a)).\ncnf(b, negated_conjecture, ~p(b)).", 1),
    "Inappropriate": ("fof(x, axiom, $sum(1, 2) = 3).", 13),
}

#: Commutativity, associativity and a homomorphism with a false equation: superposition
#: goes on for many seconds (ordered rewriting of AC terms), decided neither way before.
ENDLESS = """
cnf(assoc, axiom, f(f(X,Y),Z) = f(X,f(Y,Z))).
cnf(comm, axiom, f(X,Y) = f(Y,X)).
cnf(g, axiom, g(f(X,Y)) = f(g(X),g(Y))).
cnf(goal, negated_conjecture, f(a,f(b,c)) != f(c,f(a,d))).
"""


@pytest.mark.parametrize("status", CASES)
def test_the_exit_code_follows_the_szs_status(tmp_path, capsys, status):
    text, code = CASES[status]
    problem = tmp_path / "case.p"
    problem.write_text(text + "\n")
    assert main(["prove", str(problem)]) == code == exit_codes.BY_SZS[status]
    assert capsys.readouterr().out.startswith(f"% SZS status {status} for case\n")


def test_gave_up_when_the_effort_given_is_spent(tmp_path, capsys):
    problem = tmp_path / "ac.p"
    problem.write_text(ENDLESS)
    assert main(["prove", str(problem), "--effort", "5"]) == exit_codes.UNSOLVED_INCOMPLETE == 12
    assert "% SZS status GaveUp for ac" in capsys.readouterr().out


def test_the_cpu_limit_stops_an_unbounded_search_with_timeout(tmp_path, capsys):
    # No --effort: the default effort has no bound a run reaches, the time limit stops it.
    problem = tmp_path / "ac.p"
    problem.write_text(ENDLESS)
    assert main(["prove", str(problem), "--time", "0.2", "--json"]) == exit_codes.OUT_OF_TIME
    document = json.loads(capsys.readouterr().out)
    assert document["status"] == "Timeout"
    assert document["limits"] == {"time": 0.2, "effort": None}
    # The profiling timer counts CPU in kernel ticks, process_time() in nanoseconds: the
    # two may differ by a tick, so the run is checked to have lasted about its limit.
    assert 0.18 <= document["statistics"]["cpu_seconds"] < 5


def test_the_default_effort_is_not_the_planners(tmp_path, capsys):
    # A chain of 400 implications needs 400 given clauses and more, past the planner's
    # 300 an attempt ([limits] effort): proved by default, GaveUp with the planner's.
    chain = ["cnf(start, axiom, p0)."]
    chain += [f"cnf(r{i}, axiom, ~p{i} | p{i + 1})." for i in range(400)]
    chain.append("cnf(goal, negated_conjecture, ~p400).")
    problem = tmp_path / "chain.p"
    problem.write_text("\n".join(chain) + "\n")
    assert main(["prove", str(problem), "--json"]) == 0
    document = json.loads(capsys.readouterr().out)
    assert document["status"] == "Unsatisfiable"
    assert document["statistics"]["effort_used"] > 300
    assert main(["prove", str(problem), "--effort", "300"]) == exit_codes.UNSOLVED_INCOMPLETE


def test_json_gives_status_answers_statistics_and_the_schedules_phases(tmp_path, capsys):
    problem = tmp_path / "q.p"
    problem.write_text("cnf(a, axiom, p(a) | q(b)).\ncnf(b, axiom, ~q(X) | p(X)).\n"
                       "fof(q, question, ? [X] : p(X)).\n")
    assert main(["prove", str(problem), "--json"]) == 0
    document = json.loads(capsys.readouterr().out)
    assert document["status"] == "Theorem"
    assert document["answers"] in ("[([a]|[b])|_]", "[([b]|[a])|_]")  # either order
    assert document["prover"] == "resolution"
    # The conjecture settles the status, the answer-literal search finds the answer.
    conjecture, answer_search = document["attempts"]
    assert (conjecture["attempt"], answer_search["attempt"]) == ("conjecture", "answer search")
    for attempt in (conjecture, answer_search):
        phases = [phase["calculus"] for phase in attempt["phases"]]
        assert phases[:2] == ["saturation", "set-of-support"]
        assert sum(p["effort_used"] for p in attempt["phases"]) == attempt["effort_used"] > 0
    used = conjecture["effort_used"] + answer_search["effort_used"]
    assert document["statistics"]["effort_used"] == used


@pytest.mark.parametrize(
    ("formula", "symbol"),
    [
        ("fof(x, axiom, $sum(1, 2) = 3).", "$sum"),
        ("fof(x, conjecture, $less(1, 2)).", "$less"),
        ("fof(x, axiom, ! [X] : p($int)).", "$int"),
        ("cnf(x, axiom, $$system(a)).", "$$system"),
    ],
)
def test_defined_symbols_are_refused_as_inappropriate(tmp_path, capsys, formula, symbol):
    problem = tmp_path / "arith.p"
    problem.write_text(formula + "\n")
    assert main(["prove", str(problem)]) == exit_codes.INAPPROPRIATE
    captured = capsys.readouterr()
    assert captured.out == "% SZS status Inappropriate for arith\n"
    assert f"{problem}:1:" in captured.err and symbol in captured.err


def test_distinct_objects_are_unequal(tmp_path, capsys):
    # TPTP interprets "a" and "b" as themselves: an axiom equating them is false.
    problem = tmp_path / "objects.p"
    problem.write_text('fof(a, axiom, "a" = "b").\nfof(c, conjecture, p).\n')
    assert main(["prove", str(problem)]) == 0
    assert "% SZS status Theorem" in capsys.readouterr().out


def test_a_syntax_error_is_bad_input(tmp_path, capsys):
    problem = tmp_path / "bad.p"
    problem.write_text("fof(a, axiom, p(X).\n")
    assert main(["prove", str(problem)]) == exit_codes.INPUT_ERROR
    assert f"{problem}:1:" in capsys.readouterr().err
