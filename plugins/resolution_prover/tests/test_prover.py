"""Hand-written refutations: the prover's contract with the STRIPS search."""

from __future__ import annotations

import pytest

from strips_framework.logic.clauses import Clause
from strips_framework.logic.terms import Param
from strips_framework.options import OptionError
from strips_framework.worldmodel.proving import GAVE_UP, PROVED, SATURATED, ProofTask
from strips_framework.worldmodel.world import InitialModel, WorldModel
from strips_resolution_prover import ResolutionProver
from strips_resolution_prover.auto import plan
from strips_resolution_prover.prover import _attempt

M, N = Param("m"), Param("n")


def pos(predicate: str, *args: object) -> tuple[bool, tuple]:
    return True, (predicate, *args)


def neg(predicate: str, *args: object) -> tuple[bool, tuple]:
    return False, (predicate, *args)


def clauses(*literal_lists: list) -> list[Clause]:
    return [Clause(lits) for lits in literal_lists]


def prove(axioms: list[Clause], goal: list[Clause], **task: object):
    """The set-of-support calculus (most tests here are about it; the automatic mode,
    the default, picks it for world models and has tests of its own)."""
    return ResolutionProver(schedule=False).prove(ProofTask(axioms, goal, **task))


def test_propositional_refutation() -> None:
    axioms = clauses([pos("P")], [neg("P"), pos("Q")])
    result = prove(axioms, clauses([neg("Q")]))
    assert result.status == PROVED
    assert result.answers == ((),)
    assert result.uncompleted == ()
    assert result.proof[-1].is_empty
    # ~Q and ~P | Q resolve to ~P, which the unit P cuts to the empty clause at once.
    assert [str(c) for c in result.proof] == ["P", "~P | Q", "~Q", "false"]


def test_first_order_chain_with_variables() -> None:
    # on(x, y) & on(y, z) -> above(x, z), with variables 0..2.
    axioms = clauses(
        [pos("on", "a", "b")],
        [pos("on", "b", "c")],
        [neg("on", 0, 1), neg("on", 1, 2), pos("above", 0, 2)],
    )
    assert prove(axioms, clauses([neg("above", "a", "c")])).proved
    assert not prove(axioms, clauses([neg("above", "a", "b")])).proved


def test_parameter_answer_extraction() -> None:
    result = prove(clauses([pos("ATR", "a")]), clauses([neg("ATR", M)]))
    assert result.answers == (((M, "a"),),)


def test_binding_holds_for_all_descendants() -> None:
    # ~AT(ROBOT, m) | ~AT(BOX, m): one m for both literals.
    axioms = clauses([pos("AT", "ROBOT", "r1")], [pos("AT", "BOX", "r2")], [pos("AT", "BOX", "r1")])
    goal = clauses([neg("AT", "ROBOT", M), neg("AT", "BOX", M)])
    assert prove(axioms, goal).answers == (((M, "r1"),),)
    assert not prove(axioms[:2], goal).proved


def test_parameter_shared_between_goal_clauses_binds_once() -> None:
    # Goal P(m) & Q(m), negated as one clause; with two clauses ~P(m) | ~Q(m) must agree.
    axioms = clauses([pos("P", "a")], [pos("Q", "b")])
    assert not prove(axioms, clauses([neg("P", M), neg("Q", M)])).proved


def test_parameter_is_not_bound_to_skolem_or_variable_terms() -> None:
    assert not prove(clauses([pos("P", "sk!1")]), clauses([neg("P", M)])).proved
    assert not prove(clauses([pos("P", ("sk!2", "a"))]), clauses([neg("P", M)])).proved
    assert not prove(clauses([pos("P", ("f", 0))]), clauses([neg("P", M)])).proved
    assert prove(clauses([pos("P", 0)]), clauses([neg("P", M)])).answers == ((),)
    assert prove(clauses([pos("P", ("f", "a"))]), clauses([neg("P", M)])).answers == (
        ((M, ("f", "a")),),
    )


def test_multiple_answers() -> None:
    axioms = clauses([pos("ATR", "a")], [pos("ATR", "b")], [pos("ATR", "c")])
    result = prove(axioms, clauses([neg("ATR", M)]), max_answers=2)
    assert result.answers == (((M, "a"),), ((M, "b"),))
    result = prove(axioms, clauses([neg("ATR", M)]), max_answers=10)
    assert sorted(result.answers) == [((M, "a"),), ((M, "b"),), ((M, "c"),)]
    assert result.status == PROVED


def test_two_parameters_answer_sorted_by_name() -> None:
    axioms = clauses([pos("R", "a", "b")])
    result = prove(axioms, clauses([neg("R", N, M)]))
    assert result.answers == (((M, "b"), (N, "a")),)


def test_saturation_is_satisfiable_with_uncompleted_proof() -> None:
    axioms = clauses([pos("P", "a")], [neg("P", 0), pos("Q", 0)])
    result = prove(axioms, clauses([neg("R", M)], [neg("Q", "b")]))
    assert result.status == SATURATED
    assert result.answers == ()
    texts = [str(c) for c in result.uncompleted]
    assert texts == ["~R(m)", "~Q(b)", "~P(b)"]


def test_effort_bound_gives_up_with_uncompleted_proof() -> None:
    # N(s(x)) -> N(x): backward chaining from ~N(z) never ends.
    result = prove(clauses([neg("N", ("s", 0)), pos("N", 0)]), clauses([neg("N", "z")]), effort=5)
    assert result.status == GAVE_UP
    assert result.effort_used == 5
    assert result.uncompleted[:2] == tuple(clauses([neg("N", "z")], [neg("N", ("s", "z"))]))
    assert len(result.uncompleted) > 1


def test_tautologies_are_deleted() -> None:
    result = prove([], clauses([neg("P", "a"), pos("P", "a")], [neg("Q")]))
    assert result.status == SATURATED
    assert [str(c) for c in result.uncompleted] == ["~Q"]


def test_forward_and_backward_subsumption() -> None:
    axioms = clauses([pos("P", "a")], [neg("P", 0), pos("Q", 0), pos("R", 0)])
    goal = clauses([neg("Q", "a"), neg("S")], [neg("Q", "a")])
    result = prove(axioms, goal)
    texts = [str(c) for c in result.uncompleted]
    # ~Q(a) subsumes ~Q(a) | ~S and every descendant of it.
    assert "~Q(a) | ~S" not in texts
    assert texts[0] == "~Q(a)"
    assert result.status == SATURATED


def test_factoring_is_needed() -> None:
    # P(x) | P(y) and ~P(u) | ~P(v): refutable only with factoring.
    result = prove(clauses([pos("P", 0), pos("P", 1)]), clauses([neg("P", 0), neg("P", 1)]))
    assert result.proved


def test_unique_names_evaluation() -> None:
    # INROOM(ROBOT, r) with r != r1; the goal asks for a room different from r2.
    axioms = clauses([pos("IN", "ROBOT", "r1")])
    goal = clauses([neg("IN", "ROBOT", M), pos("=", M, "r2")])
    assert prove(axioms, goal, unique_names=True).answers == (((M, "r1"),),)
    assert not prove(axioms, goal).proved
    # a != a is false, so a clause with it is kept without that literal.
    assert prove(axioms, clauses([neg("=", "r1", "r1"), neg("IN", "ROBOT", "r1")])).proved
    # Distinct names are distinct: the goal a = b is refuted at once, b = b is true.
    # (Not "Satisfiable": that needs a calculus complete for equality.)
    assert prove([], clauses([neg("=", "a", "b")]), unique_names=True).status == GAVE_UP
    assert prove([], clauses([pos("=", "a", "b")]), unique_names=True).proved


def test_skolem_constants_are_not_unique_names() -> None:
    result = prove([], clauses([pos("=", "sk!1", "b")]), unique_names=True)
    assert not result.proved


def test_equality_by_paramodulation() -> None:
    # f(a) = b, P(f(a)) |- P(b); and symmetry: a = b |- b = a.
    axioms = clauses([pos("=", ("f", "a"), "b")], [pos("P", ("f", "a"))])
    assert prove(axioms, clauses([neg("P", "b")])).proved
    assert prove(clauses([pos("=", "a", "b")]), clauses([neg("=", "b", "a")])).proved
    # Transitivity through a parameter: the answer is found by rewriting.
    axioms = clauses([pos("=", "c", "d")], [pos("Q", "d")])
    assert prove(axioms, clauses([neg("Q", "c")])).proved


def test_equality_resolution() -> None:
    assert prove([], clauses([neg("=", ("f", 0), ("f", "a"))])).proved


def test_deterministic_output() -> None:
    axioms = clauses([pos("P", "a")], [pos("P", "b")], [neg("P", 0), pos("Q", 0, "c")])
    goal = clauses([neg("Q", M, N)])
    first = prove(axioms, goal, max_answers=5)
    assert first == prove(axioms, goal, max_answers=5)
    assert first.answers == (((M, "a"), (N, "c")), ((M, "b"), (N, "c")))


def test_options_are_validated() -> None:
    with pytest.raises(OptionError, match="'pick_given_ratio': expected a value >= 1"):
        ResolutionProver(pick_given_ratio=0)
    with pytest.raises(OptionError, match="'unit_preference'"):
        ResolutionProver(unit_preference=-1)
    with pytest.raises(AttributeError, match="immutable"):
        ResolutionProver().pick_given_ratio = 3  # type: ignore[misc]


def test_size_limits_discard_large_clauses_and_void_saturation() -> None:
    axioms = clauses([neg("N", ("s", 0)), pos("N", 0)])
    goal = clauses([neg("N", "z")])
    for prover in (
        ResolutionProver(max_term_depth=2, schedule=False),
        ResolutionProver(max_weight=8, schedule=False),
        ResolutionProver(max_clause_literals=1, schedule=False),
    ):
        result = prover.prove(ProofTask(axioms, goal, effort=100))
        assert result.status == GAVE_UP
        assert result.effort_used < 100
    wide = clauses([neg("N", 0), pos("M", 0), pos("K", 0)])
    prover = ResolutionProver(max_clause_literals=1, schedule=False)
    result = prover.prove(ProofTask(wide, goal, effort=100))
    assert result.status == GAVE_UP


def test_registered_as_plugin() -> None:
    from strips_resolution_prover import plugin

    assert plugin.strips_register_provers() == [ResolutionProver]
    assert ResolutionProver.name == "resolution"


def test_without_set_of_support_axioms_resolve_with_each_other() -> None:
    # The answer needs the axiom-only inference P(a), P(x) -> Q(x) |- Q(a): a parameter may
    # not be bound to the variable of Q(x), so only the derived fact Q(a) gives an answer.
    axioms = clauses([pos("P", "a")], [neg("P", 0), pos("Q", ("f", 0))])
    goal = clauses([neg("Q", M)])
    assert not prove(axioms, goal).proved
    result = ResolutionProver(schedule=False, set_of_support=False).prove(ProofTask(axioms, goal))
    assert result.answers == (((M, ("f", "a")),),)
    assert [str(c) for c in result.proof] == [
        "P(a)",
        "~P(x0) | Q(f(x0))",
        "~Q(m)",
        "Q(f(a))",
        "false  [m=f(a)]",
    ]


def test_ordered_resolution_saturates_where_selection_alone_does_not() -> None:
    # P(f(x)) | Q(x) has no negative literal to select; resolved on Q(x) with the selected
    # ~Q(y) of ~Q(y) | Q(f(y)) it would breed P(f(x)) | Q(f(x)), P(f(x)) | Q(f(f(x))), ...
    # forever. Under KBO, Q(x) is below P(f(x)) in every instance, so only P(f(x)) is
    # resolved on; nothing resolves with it, and the search saturates (all P true is a model).
    goal = clauses([pos("P", ("f", 0)), pos("Q", 0)], [neg("Q", 1), pos("Q", ("f", 1))])
    assert prove([], goal, effort=200).status == SATURATED
    # The same clauses with ~P(f(a)) and Q(a): refuted, so the restriction keeps what a
    # proof needs (P(f(a)) | Q(a) resolves on its maximal literal P(f(a))).
    refutable = [*goal, *clauses([neg("P", ("f", "a"))], [neg("Q", "a")])]
    assert prove([], refutable).proved


def test_an_answer_search_keeps_every_literal_of_a_positive_clause() -> None:
    # SYN031-1's question: the answer needs g(x, a) of g(x, a) | g(f(x), x), which KBO puts
    # below g(f(x), x). A parameter is bound once per derivation (III.A), not ordered, so
    # with parameters in the goal the saturation resolves on every positive literal.
    axioms = clauses(
        [pos("g", 0, "a"), pos("g", ("f", 0), 0)],
        [pos("g", 0, "a"), pos("g", 0, ("f", 0))],
        [neg("g", 0, 1), pos("g", ("f", 1), 1)],
        [neg("g", 0, 1), pos("g", 1, ("f", 1))],
    )
    goal = clauses([neg("g", M, N), neg("g", N, "a")])
    prover = ResolutionProver(schedule=False, set_of_support=False)
    assert prover.prove(ProofTask(axioms, goal)).proved


def test_literal_selection_saturates_without_usable_clauses() -> None:
    # With every clause in the queue, ~P(x) | P(f(x)) resolved with itself would breed
    # P(f(f(x))), P(f(f(f(x)))), ... forever; resolving only on its selected negative
    # literal, which needs a positive partner, the search saturates.
    goal = clauses([neg("P", 0), pos("P", ("f", 0))], [neg("Q")])
    result = prove([], goal, effort=50)
    assert result.status == SATURATED
    refutable = clauses(
        [neg("P", 0), pos("P", ("f", 0))], [pos("P", "a")], [neg("P", ("f", ("f", "a")))]
    )
    assert prove([], refutable).proved


def test_automatic_mode_picks_the_calculus_from_the_features() -> None:
    fact, rule = pos("P", "a"), [neg("P", 0), pos("Q", 0)]
    # Definite Horn, no equality, half of it ground facts: a world model, set of support.
    assert plan(clauses([fact], rule)) == "set-of-support"
    # A rule-only, non-Horn or equational axiom set: saturation and SOS side by side.
    assert plan(clauses(rule)) == "schedule"
    assert plan(clauses([fact], [pos("Q", 0), pos("R", 0)])) == "schedule"
    assert plan(clauses([fact], [pos("=", "a", "b")])) == "schedule"
    assert plan([]) == "saturation"
    # The schedule saturates: N(x) -> N(s(x)) from N(z) saturates under literal
    # selection (every clause resolves on its one negative literal), while the set of
    # support alone runs out of effort on ~N(z), N(s(z)) ... backward.
    axioms = clauses([neg("N", ("s", 0)), pos("N", 0)])
    goal = clauses([neg("N", "z")])
    assert ResolutionProver().prove(ProofTask(axioms, goal, effort=50)).status == SATURATED
    assert prove(axioms, goal, effort=50).status == GAVE_UP
    # A session on a world model runs the set of support on every attempt, on M0 indexed
    # once; on other axioms each attempt is a task of its own for the automatic mode.
    world = ResolutionProver().open(InitialModel(clauses([fact], rule)), unique_names=False)
    assert (world.calculus.schedule, world.calculus.set_of_support) == (False, True)
    # Horn but not a fact base: the session's attempt is the schedule's, as for the task.
    other = ResolutionProver().open(InitialModel(axioms), unique_names=False)
    assert other.prove(WorldModel(other.initial), goal, effort=50).status == SATURATED
    # An equation in the goal makes it the schedule's (SOS paramodulation would grow
    # f(f(...)) into Q(f(a)) for the whole effort; superposition saturates at once).
    assert plan(clauses([fact], rule), clauses([pos("=", 0, "a")])) == "schedule"
    grows = clauses([pos("Q", ("f", "a"))], [pos("R", "b", "a")], [pos("S")])
    goal = clauses([neg("Q", 0), pos("=", "a", 0)])
    result = ResolutionProver().prove(ProofTask(grows, goal, effort=2000))
    assert result.status == SATURATED
    assert result.effort_used < 50


def test_the_schedule_interleaves_saturation_and_the_set_of_support() -> None:
    # Six rules P(x) -> P(hi(x)) from P(a): forward, saturation builds every term up to
    # the goal's depth (hundreds of given clauses); backward, the set of support proves
    # ~P(h0(h1(h2(h3(a))))) in five. Run one after the other, the set of support would
    # start only after saturation's share (405 given clauses); side by side it is found
    # after a few rounds.
    rules = [[neg("P", 0), pos("P", (f"h{i}", 0))] for i in range(6)]
    axioms = clauses([pos("P", "a")], *rules, [neg("P", 0), pos("Q", 0), pos("R", 0)])
    goal = clauses([neg("P", ("h0", ("h1", ("h2", ("h3", "a")))))])
    assert plan(axioms, goal) == "schedule"
    result = ResolutionProver().prove(ProofTask(axioms, goal, effort=600))
    assert result.status == PROVED
    assert result.effort_used <= 3 * 5


def test_a_set_of_support_without_answers_leaves_the_question_to_saturation() -> None:
    # exists y: Q(y) over P(a), P(x) -> Q(f(x)): backward, m := f(X) is no binding (III.A),
    # so the set of support runs out of clauses at once; saturation derives Q(f(a)) and
    # answers m = f(a). The set of support's "no answer" must not end the schedule.
    axioms = clauses([pos("P", "a")], [neg("P", 0), pos("Q", ("f", 0))], [neg("Q", 0), pos("R", 0)])
    goal = clauses([neg("Q", M)])
    assert prove(axioms, goal).status == SATURATED  # the set of support alone
    result = ResolutionProver().prove(ProofTask(axioms, goal, effort=100))
    assert result.answers == (((M, ("f", "a")),),)


def _first_given(axioms: list[Clause], goal: list[Clause], **options: object) -> Clause:
    prover = ResolutionProver(schedule=False, set_of_support=False, **options)
    attempt = _attempt(prover, ProofTask(axioms, goal))
    attempt.start(1)
    given = attempt.queue.pop()
    assert given is not None
    return given.to_clause()


def test_unit_preference_only_where_there_are_axioms() -> None:
    # A light long clause (weight 9) and a heavy unit (weight 10): symbols only without
    # axioms (all negated conjecture: the long clauses are the lemmas, GRP012+5), the
    # penalty 4 per extra literal with them (17 against 10: short goal clauses first).
    X = 0
    light_long = Clause([neg("p", X), neg("q", X), pos("r", X)])
    heavy_unit = Clause([pos("s", ("f", ("f", ("f", "a"))))])
    goal = [heavy_unit, light_long]
    assert _first_given([], goal).literals == light_long.literals
    # The axiom is heavy enough (14, doubled as no goal descendant) not to come first.
    axiom = clauses([pos("t", ("f", ("f", ("f", ("f", ("f", "b"))))))])
    assert _first_given(axiom, goal).literals == heavy_unit.literals
    # An explicit option is what it says.
    assert _first_given([], goal, unit_preference=4).literals == heavy_unit.literals
