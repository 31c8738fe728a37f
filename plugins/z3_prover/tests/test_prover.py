"""The Z3 prover's contract with the STRIPS search, case by case."""

from __future__ import annotations

from pathlib import Path

import pytest
from strips_z3_prover import Z3Prover
from strips_z3_prover.session import GroundSession

from strips_framework.errors import ConfigError
from strips_framework.logic.clauses import Clause
from strips_framework.logic.terms import Param
from strips_framework.planner import Planner
from strips_framework.plugin.config import Config
from strips_framework.testing.prover_cases import pigeonhole
from strips_framework.worldmodel.proving import GAVE_UP, PROVED, SATURATED, ProofTask
from strips_framework.worldmodel.simulate import replay
from strips_framework.worldmodel.world import InitialModel, WorldModel

M, N = Param("m"), Param("n")
EXAMPLES = Path(__file__).resolve().parents[3] / "examples"


def pos(predicate: str, *args: object) -> tuple[bool, tuple]:
    return True, (predicate, *args)


def neg(predicate: str, *args: object) -> tuple[bool, tuple]:
    return False, (predicate, *args)


def clauses(*literal_lists: list) -> list[Clause]:
    return [Clause(lits) for lits in literal_lists]


@pytest.fixture(params=[True, False], ids=["incremental", "fresh"])
def prover(request: pytest.FixtureRequest) -> Z3Prover:
    return Z3Prover(incremental=request.param)


def test_ground_entailment_through_a_rule(prover: Z3Prover) -> None:
    axioms = clauses(
        [pos("on", "a", "b")],
        [pos("on", "b", "c")],
        [neg("on", 0, 1), neg("on", 1, 2), pos("above", 0, 2)],
    )
    assert prover.prove(ProofTask(axioms, clauses([neg("above", "a", "c")]))).answers == ((),)
    failed = prover.prove(ProofTask(axioms, clauses([neg("above", "a", "b")])))
    assert failed.status == SATURATED and failed.answers == ()


def test_witnesses_are_the_instances_that_follow(prover: Z3Prover) -> None:
    # AT(ROBOT, m) & AT(BOX, m): only r1 has both.
    axioms = clauses([pos("AT", "ROBOT", "r1")], [pos("AT", "BOX", "r2")], [pos("AT", "BOX", "r1")])
    goal = clauses([neg("AT", "ROBOT", M), neg("AT", "BOX", M)])
    assert prover.prove(ProofTask(axioms, goal, max_answers=5)).answers == (((M, "r1"),),)
    assert not prover.prove(ProofTask(axioms[:2], goal)).proved


def test_several_answers_up_to_max_answers(prover: Z3Prover) -> None:
    axioms = clauses([pos("P", "a")], [pos("P", "b")], [pos("P", "c")])
    goal = clauses([neg("P", M)])
    assert len(prover.prove(ProofTask(axioms, goal, max_answers=2)).answers) == 2
    everything = prover.prove(ProofTask(axioms, goal, max_answers=10)).answers
    assert sorted(everything) == [((M, c),) for c in "abc"]


def test_a_disjunction_of_instances_is_no_answer(prover: Z3Prover) -> None:
    # P(a) | P(b) entails "exists m: P(m)" but no single instance, like resolution.
    result = prover.prove(
        ProofTask(clauses([pos("P", "a"), pos("P", "b")]), clauses([neg("P", M)]))
    )
    assert result.status == SATURATED


def test_answers_derived_through_a_quantified_axiom(prover: Z3Prover) -> None:
    axioms = clauses(
        [pos("CONNECTS", "D1", "R1", "R2")], [neg("CONNECTS", 0, 1, 2), pos("CONNECTS", 0, 2, 1)]
    )
    goal = clauses([neg("CONNECTS", M, "R2", N)])
    assert prover.prove(ProofTask(axioms, goal)).answers == (((M, "D1"), (N, "R1")),)


def test_parameters_are_never_bound_to_skolem_constants(prover: Z3Prover) -> None:
    assert not prover.prove(ProofTask(clauses([pos("P", "sk!1")]), clauses([neg("P", M)]))).proved
    # With no constant to bind, a goal that holds for every value binds nothing.
    assert prover.prove(ProofTask(clauses([pos("P", 0)]), clauses([neg("P", M)]))).answers == ((),)


def test_equality_under_unique_names(prover: Z3Prover) -> None:
    goal = clauses([neg("=", "a", "b")])
    assert prover.prove(ProofTask([], clauses([pos("=", "a", "b")]), unique_names=True)).proved
    assert not prover.prove(ProofTask([], goal, unique_names=True)).proved
    assert not prover.prove(ProofTask([], goal)).proved
    # Without unique names an equation among the axioms is used by congruence.
    axioms = clauses([pos("=", "a", "b")], [pos("P", "a")])
    assert prover.prove(ProofTask(axioms, clauses([neg("P", "b")]))).proved
    # A Skolem constant may equal a named one even under unique names.
    axioms = clauses([pos("=", "sk!1", "a")], [pos("P", "sk!1")])
    assert prover.prove(ProofTask(axioms, clauses([neg("P", "a")]), unique_names=True)).proved


def test_function_symbols_go_to_quantifiers(prover: Z3Prover) -> None:
    axioms = clauses([pos("P", ("f", "a"))], [neg("P", 0), pos("Q", ("g", 0))])
    assert prover.prove(ProofTask(axioms, clauses([neg("Q", ("g", ("f", "a")))]))).proved
    answer = prover.prove(ProofTask(axioms, clauses([neg("P", M)]))).answers
    assert answer == (((M, ("f", "a")),),)
    assert prover.prove(ProofTask(axioms, clauses([neg("Q", "a")]))).status == SATURATED


def test_uncompleted_proof_holds_the_goal_literals_not_entailed(prover: Z3Prover) -> None:
    axioms = clauses(
        [pos("INROOM", "BOX1", "R1")],
        [pos("CONNECTS", "D1", "R1", "R2")],
        [neg("CONNECTS", 0, 1, 2), pos("CONNECTS", 0, 2, 1)],
    )
    goal = clauses([neg("NEXTTO", "ROBOT", M), neg("INROOM", M, 0), neg("CONNECTS", "D1", "R2", 0)])
    result = prover.prove(ProofTask(axioms, goal))
    assert result.status == SATURATED
    # INROOM is a fact; CONNECTS(D1, R2, R1) is entailed by symmetry, not a fact.
    assert Clause([neg("NEXTTO", "ROBOT", "BOX1")], [(M, "BOX1")]) in result.uncompleted


def test_a_failed_attempt_without_possible_lemmas_asks_z3_once(
    prover: Z3Prover, monkeypatch: pytest.MonkeyPatch
) -> None:
    # No ABOVE atom can hold, so no lemma can exist: the refutation check is the only
    # one (the lemma search would check the axioms again and read a model).
    from strips_z3_prover import budget

    checks = []
    real = budget._check
    monkeypatch.setattr(budget, "_check", lambda *args: checks.append(args) or real(*args))
    axioms = clauses([pos("on", "a", "b")], [neg("on", 0, 1), pos("under", 1, 0)])
    result = prover.prove(ProofTask(axioms, clauses([neg("above", "a", "b"), neg("on", "a", "b")])))
    assert result.status == SATURATED
    assert len(checks) == 1
    assert result.uncompleted == (Clause([neg("above", "a", "b")]),)


def test_the_uncompleted_proof_leaves_out_subsumed_clauses(prover: Z3Prover) -> None:
    # ONFLOOR is a fact: a clause that still holds ~ONFLOOR beside ~LOCINROOM(f, R1) adds
    # nothing to ~LOCINROOM(f, R1), and would make ONFLOOR look like something to achieve.
    axioms = clauses([pos("ONFLOOR")], [pos("LOCINROOM", "F1", "R2")])
    result = prover.prove(ProofTask(axioms, clauses([neg("ONFLOOR"), neg("LOCINROOM", M, "R1")])))
    assert result.status == SATURATED
    assert result.uncompleted == (Clause([neg("LOCINROOM", M, "R1")]),)


def test_effort_bound_gives_up_the_same_way_every_time() -> None:
    results = [Z3Prover(incremental=False).prove(pigeonhole(6)) for _ in range(3)]
    assert {r.status for r in results} == {GAVE_UP}
    assert len(set(results)) == 1
    assert results[0].effort_used <= 1
    hard = pigeonhole(6)
    generous = ProofTask(hard.axioms, hard.negated_goal, effort=100, unique_names=True)
    assert Z3Prover(incremental=False).prove(generous).status == PROVED


def test_a_malformed_term_is_a_value_error(prover: Z3Prover) -> None:
    with pytest.raises(ValueError, match="term"):
        prover.prove(ProofTask(clauses([pos("P", 1.5)]), clauses([neg("P", "a")])))


def test_bad_options_are_config_errors() -> None:
    config = Config.from_dict({"prover": {"name": "z3", "rlimit_per_effort": 0}}, "z3.toml")
    with pytest.raises(ConfigError, match="rlimit_per_effort"):
        Planner.create(config)


# The other robot-world tasks are solved by benchmarks/bench_paper_tasks.py, which runs
# every installed prover; five-goals takes Z3 over a minute (see the README).
@pytest.mark.parametrize(("problem", "nodes"), [
    ("three-boxes.strips", 9), ("robot-world/light.strips", 13),
    ("robot-world/other-room.strips", 12),
])
def test_means_ends_with_z3_solves_the_papers_tasks(problem: str, nodes: int) -> None:
    planner = Planner.create(Config.from_file(EXAMPLES / "configs" / "z3.toml"))
    task = planner.load(EXAMPLES / problem)
    result = planner.solve(task)
    assert result.solved, result.status
    assert replay(task, [str(step) for step in result.plan]).valid
    # The node counts of the resolution prover (tests/test_paper_tasks.py): the same
    # differences, so the same search.
    assert result.statistics.nodes == nodes


def test_a_session_grounds_only_the_instances_whose_conditions_can_hold() -> None:
    # Symmetry over 20 constants has 8,000 instances; two facts make four relevant.
    session = GroundSession(0)
    session.admit([f"c{i}" for i in range(17)] + ["d", "r1", "r2"])
    session.selector(Clause([pos("C", "d", "r1", "r2")]))
    session.selector(Clause([neg("C", 0, 1, 2), pos("C", 0, 2, 1)]))
    (_, rule) = session.relevance.rules
    assert rule.done == {("d", "r1", "r2"), ("d", "r2", "r1")}


def test_a_fact_arriving_later_fires_the_rules_asserted_before() -> None:
    # The session's second model adds Q(a): the chain Q -> R -> S must fire then.
    prover = Z3Prover()
    rules = clauses([neg("Q", 0), pos("R", 0)], [neg("R", 0), pos("S", 0)], [pos("P", "b")])
    session = prover.open(InitialModel(rules), False)
    goal = clauses([neg("S", M)])
    assert not session.prove(WorldModel(InitialModel(rules)), goal, 300).proved
    later = InitialModel((*rules, Clause([pos("Q", "a")])))
    assert session.prove(WorldModel(later), goal, 300).answers == (((M, "a"),),)


def test_a_goals_positive_atoms_count_as_possible(prover: Z3Prover) -> None:
    # "R(a) is false" follows: R(a) would give S(a), which is false.
    axioms = clauses([neg("R", 0), pos("S", 0)], [neg("S", "a")])
    assert prover.prove(ProofTask(axioms, clauses([pos("R", "a")]))).proved


def test_an_equation_grounds_every_instance(prover: Z3Prover) -> None:
    # Q(a), T(b) and a = b: no instance of the rule has both conditions among the facts.
    axioms = clauses(
        [pos("Q", "a")], [pos("T", "b")], [pos("=", "a", "b")],
        [neg("Q", 0), neg("T", 0), pos("R", 0)],
    )
    assert prover.prove(ProofTask(axioms, clauses([neg("R", "a")]))).proved
