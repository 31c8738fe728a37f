"""Relevant operator instances from a difference (III.C)."""

from strips_framework.logic.clauses import Clause
from strips_framework.logic.formulas import And, Atomic
from strips_framework.logic.terms import Param
from strips_framework.means_ends.node import Difference
from strips_framework.means_ends.relevance import AddListRelevance
from strips_framework.worldmodel.problem import OperatorSchema
from strips_framework.worldmodel.world import InitialModel, WorldModel

k, m, n = Param("k"), Param("m"), Param("n")
GOTO = OperatorSchema("goto", [m, n], Atomic(("ATR", m)), [("ATR", n)], [("ATR", m)])
PUSH = OperatorSchema(
    "push", [k, m, n], And([Atomic(("AT", k, m)), Atomic(("ATR", m))]),
    [("AT", k, n), ("ATR", n)], [("AT", k, m), ("ATR", m)],
)
EMPTY = WorldModel(InitialModel([]))
#: What :func:`~strips_framework.worldmodel.world.rigid_predicates` finds for a world
#: whose operators never add PUSHABLE.
RIGID = {("PUSHABLE", 1)}


def _relevant(difference, operators, model):
    return AddListRelevance().for_problem(operators, model.initial).relevant(difference, model)


def test_papers_example_two_instances_of_goto():
    difference = Difference([Clause([(False, ("ATR", "a")), (False, ("ATR", "b"))])])
    found = _relevant(difference, [GOTO, PUSH], EMPTY)
    names = sorted(str(r.operator) for r in found)
    assert names == ["goto(m, a)", "goto(m, b)", "push(k, m, a)", "push(k, m, b)"]
    by_name = {str(r.operator): str(r.resolvent) for r in found}
    assert by_name["goto(m, a)"] == "~ATR(b)"


def test_smaller_resolvents_rank_first_and_unbindable_instances_are_dropped():
    difference = Difference([
        Clause([(False, ("AT", "BOX1", 0)), (False, ("AT", "BOX2", 0))]),
        Clause([(False, ("AT", "BOX2", "b"))]),
    ])
    found = _relevant(difference, [PUSH], EMPTY)
    # push(BOX1, m, x) would leave n unbound (it is not in the precondition): dropped.
    assert [str(r.operator) for r in found] == ["push(BOX2, m, b)"]
    assert found[0].resolvent.literals == ()


def test_instance_bound_to_another_operators_parameter_is_dropped():
    goal_param = Param("m")
    difference = Difference([Clause([(False, ("ATR", goal_param))])])
    assert _relevant(difference, [GOTO], EMPTY) == []


def test_instances_that_would_undo_what_the_proof_rests_on_rank_last():
    # Like the robot world's pushto: NEXTTO(BOX1, BOX2) already holds, NEXTTO(BOX2, BOX3)
    # is wanted; pushto(BOX2, BOX3) would delete NEXTTO($, BOX2), pushto(BOX3, BOX2) not.
    pushto = OperatorSchema(
        "pushto", [m, n], Atomic(("NEXTTO", "ROBOT", m)), [("NEXTTO", m, n), ("NEXTTO", n, m)],
        [("NEXTTO", m, "$"), ("NEXTTO", "$", m)],
    )
    goal = Clause([(False, ("NEXTTO", "BOX1", "BOX2")), (False, ("NEXTTO", "BOX2", "BOX3"))])
    difference = Difference([Clause([(False, ("NEXTTO", "BOX2", "BOX3"))])], [goal])
    model = WorldModel(InitialModel([Clause([(True, ("NEXTTO", "BOX1", "BOX2"))])]))
    found = _relevant(difference, [pushto], model)
    assert [str(r.operator) for r in found] == ["pushto(BOX3, BOX2)", "pushto(BOX2, BOX3)"]


def test_instances_needing_a_rigid_fact_that_does_not_hold_are_dropped():
    # PUSHABLE is rigid: no operator adds it and no rule concludes it.
    pushto = OperatorSchema(
        "pushto", [m, n], And([Atomic(("PUSHABLE", m)), Atomic(("NEXTTO", "ROBOT", m))]),
        [("NEXTTO", m, n)], [("NEXTTO", m, "$")],
    )
    model = WorldModel(InitialModel([Clause([(True, ("PUSHABLE", "BOX1"))])], rigid=RIGID))
    difference = Difference([
        Clause([(False, ("NEXTTO", "BOX1", "a"))]), Clause([(False, ("NEXTTO", "ROBOT", "a"))]),
    ])
    found = _relevant(difference, [pushto], model)
    assert [str(r.operator) for r in found] == ["pushto(BOX1, a)"]


def test_a_rigid_fact_inside_a_nested_conjunction_counts_too():
    # A translated PDDL precondition: the type atoms' conjunction holds the action's own.
    pushto = OperatorSchema(
        "pushto", [m, n],
        And([Atomic(("NEXTTO", "ROBOT", m)), And([Atomic(("PUSHABLE", m))])]),
        [("NEXTTO", m, n)], [("NEXTTO", m, "$")],
    )
    model = WorldModel(InitialModel([Clause([(True, ("PUSHABLE", "BOX1"))])], rigid=RIGID))
    difference = Difference([
        Clause([(False, ("NEXTTO", "BOX1", "a"))]), Clause([(False, ("NEXTTO", "ROBOT", "a"))]),
    ])
    found = _relevant(difference, [pushto], model)
    assert [str(r.operator) for r in found] == ["pushto(BOX1, a)"]


def test_rank_cost_puts_the_instance_whose_precondition_holds_first():
    # Two instances leave empty resolvents (a tie by resolvent size); make(b)'s
    # precondition READY(b) is a fact of the model, make(a)'s READY(a) is not. The
    # default ranking keeps the clauses' order; rank = "cost" puts make(b) first.
    x = Param("x")
    make = OperatorSchema("make", [x], Atomic(("READY", x)), [("G", x)], [])
    model = WorldModel(InitialModel([Clause([(True, ("READY", "b"))])]))
    difference = Difference([Clause([(False, ("G", "a"))]), Clause([(False, ("G", "b"))])])
    by_resolvent = _relevant(difference, [make], model)
    by_cost = AddListRelevance(rank="cost").for_problem([make], model.initial).relevant(
        difference, model
    )
    assert [str(r.operator) for r in by_resolvent] == ["make(a)", "make(b)"]
    assert [str(r.operator) for r in by_cost] == ["make(b)", "make(a)"]


#: Like GOTO, but its precondition names n (ADJ), so a proof of it can bind n.
MOVE = OperatorSchema(
    "move", [m, n], And([Atomic(("ATR", m)), Atomic(("ADJ", m, n))]), [("ATR", n)], [("ATR", m)]
)


def test_with_no_other_instance_a_parameter_bound_to_the_goals_own_is_left_to_the_proof():
    """A difference whose literals all hold the goal operator's unbound parameters (what
    an SLD proof leaves) would give no instance and end the search; move's n is in its
    precondition, so move is kept with n unbound. GOTO's n is not: still dropped."""
    goal_param = Param("p")
    difference = Difference([Clause([(False, ("ATR", goal_param))])])
    found = _relevant(difference, [MOVE, GOTO], EMPTY)
    assert [str(r.operator) for r in found] == ["move(m, n)"]
    assert found[0].operator.binding_map() == {}


def test_instances_with_parameters_left_unbound_only_when_none_binds_fully():
    difference = Difference([Clause([(False, ("ATR", Param("p")))]),
                             Clause([(False, ("ATR", "b"))])])
    found = _relevant(difference, [MOVE], EMPTY)
    assert [str(r.operator) for r in found] == ["move(m, b)"]


def test_instances_whose_rigid_atoms_with_unbound_parameters_match_no_facts_are_dropped():
    # Like elevators' move-up(lift, f1, f2) for lift-at(lift, f2): ABOVE is rigid, and
    # no floor is below the lowest, so move-up to "ground" can never be applied, whatever
    # f1 becomes. To "top", f1 has a value, but only jointly with REACHES: one floor is
    # below "top" and the lift does not reach it, so that instance is dropped too, and
    # only the move to "mid" (from "ground", which it reaches) is kept.
    lift, low, high = Param("lift"), Param("low"), Param("high")
    move_up = OperatorSchema(
        "move-up", [lift, low, high],
        And([Atomic(("LIFTAT", lift, low)), Atomic(("ABOVE", low, high)),
             Atomic(("REACHES", lift, low))]),
        [("LIFTAT", lift, high)], [("LIFTAT", lift, low)],
    )
    facts = [("ABOVE", "ground", "mid"), ("ABOVE", "mid", "top"), ("REACHES", "L", "ground")]
    model = WorldModel(InitialModel(
        [Clause([(True, fact)]) for fact in facts],
        rigid=frozenset({("ABOVE", 2), ("REACHES", 2)}),
    ))
    difference = Difference([
        Clause([(False, ("LIFTAT", "L", "ground"))]),
        Clause([(False, ("LIFTAT", "L", "mid"))]),
        Clause([(False, ("LIFTAT", "L", "top"))]),
    ])
    joined = AddListRelevance(rigid_join=True).for_problem([move_up], model.initial)
    assert [str(r.operator) for r in joined.relevant(difference, model)] == [
        "move-up(L, low, mid)"
    ]
    # Off (the default), only ground rigid atoms are checked: all three are kept.
    assert len(_relevant(difference, [move_up], model)) == 3


def test_model_bindings_bind_the_parameters_the_models_facts_settle():
    # lift(h, c, s, pl) for CLEAR(P): ON(?c, P) matches one fact (C0 is on P), which
    # binds c, then AT(C0, ?pl) binds pl; AT(?h, D) matches four facts, but joined with
    # HOIST(?h) only H1. For LIFTING(H2, C1), ON(C1, ?s) binds s, but AT(H2, ?pl) and
    # AT(C1, ?pl) each match one fact with another place: pl is left to the proof.
    # (CLEAR(?c) matches two facts; had it matched one other crate, c would stay too.)
    h, c, s, pl = Param("h"), Param("c"), Param("s"), Param("pl")
    lift = OperatorSchema(
        "lift", [h, c, s, pl],
        And([Atomic(("HOIST", h)), Atomic(("AT", h, pl)), Atomic(("AT", c, pl)),
             Atomic(("ON", c, s)), Atomic(("CLEAR", c))]),
        [("LIFTING", h, c), ("CLEAR", s)], [("ON", c, s), ("CLEAR", c)],
    )
    facts = [("HOIST", "H1"), ("HOIST", "H2"), ("ON", "C0", "P"), ("ON", "C1", "C0"),
             ("CLEAR", "C1"), ("CLEAR", "C2"), ("AT", "P", "D"), ("AT", "C0", "D"), ("AT", "C1", "D"),
             ("AT", "H1", "D"), ("AT", "H2", "E")]
    model = WorldModel(InitialModel([Clause([(True, fact)]) for fact in facts]))
    difference = Difference([Clause([(False, ("CLEAR", "P"))]),
                             Clause([(False, ("LIFTING", "H2", "C1"))])])
    bound = AddListRelevance(model_bindings=True).for_problem([lift], model.initial)
    assert sorted(str(r.operator) for r in bound.relevant(difference, model)) == [
        "lift(H1, C0, P, D)", "lift(H2, C1, C0, pl)",
    ]
    # Off (the default), only the difference's literal binds.
    assert sorted(str(r.operator) for r in _relevant(difference, [lift], model)) == [
        "lift(H2, C1, s, pl)", "lift(h, c, P, pl)",
    ]


def test_model_bindings_do_not_use_a_fact_the_subgoal_consumes():
    # drop(v, p, s1, s2) for DELIVERED(P) needs IN(P, ?v), which no fact matches, and
    # CAP(?v, ?s1) with PRED(?s1, ?s2): joined, only T2 at C1 can drop now (T1 is
    # empty, at C2). But the pick that makes IN(P, T2) deletes CAP(T2, C1), so the drop
    # bound to C1 could never follow it: the capacity binds nothing, and nothing else
    # settles v. LIFTING(?h, X) has no fact either, but the lift that makes it deletes
    # only FREE(H1): hold(h, X, pl) is still bound to the hoist at X's place.
    v, p, s1, s2 = Param("v"), Param("p"), Param("s1"), Param("s2")
    h, x, pl = Param("h"), Param("x"), Param("pl")
    pick = OperatorSchema(
        "pick", [v, p, s1, s2],
        And([Atomic(("CAP", v, s2)), Atomic(("PRED", s1, s2))]),
        [("IN", p, v), ("CAP", v, s1)], [("CAP", v, s2)],
    )
    drop = OperatorSchema(
        "drop", [v, p, s1, s2],
        And([Atomic(("IN", p, v)), Atomic(("CAP", v, s1)), Atomic(("PRED", s1, s2))]),
        [("DELIVERED", p), ("CAP", v, s2)], [("IN", p, v), ("CAP", v, s1)],
    )
    lift = OperatorSchema("lift", [h, x], Atomic(("FREE", h)), [("LIFTING", h, x)], [("FREE", h)])
    hold = OperatorSchema(
        "hold", [h, x, pl],
        And([Atomic(("HOIST", h)), Atomic(("LIFTING", h, x)), Atomic(("AT", h, pl)),
             Atomic(("AT", x, pl))]),
        [("HELD", x)], [],
    )
    facts = [("PRED", "C0", "C1"), ("PRED", "C1", "C2"), ("CAP", "T1", "C2"),
             ("CAP", "T2", "C1"), ("FREE", "H1"), ("HOIST", "H1"), ("AT", "H1", "D"), ("AT", "X", "D")]
    model = WorldModel(InitialModel([Clause([(True, fact)]) for fact in facts],
                                    rigid=frozenset({("PRED", 2), ("HOIST", 1)})))
    difference = Difference([Clause([(False, ("DELIVERED", "P"))]),
                             Clause([(False, ("HELD", "X"))])])
    index = AddListRelevance(model_bindings=True).for_problem([pick, drop, lift, hold],
                                                              model.initial)
    assert sorted(str(r.operator) for r in index.relevant(difference, model)) == [
        "drop(v, P, s1, s2)", "hold(H1, X, D)",
    ]


def test_model_bindings_rank_by_the_deletes_they_bind():
    # For DONE: fix(k) is bound by the model (SEL(K1) is the one fact) and deletes
    # KEEP(K1), which the goal rests on; make(m) stays unbound (no fact NEED) and its
    # KEEP(?m) names no fact yet. With model bindings only deletes that are bound count,
    # so make comes first; without, KEEP(?m) counts as deleting both KEEP facts.
    k, m = Param("k"), Param("m")
    fix = OperatorSchema("fix", [k], Atomic(("SEL", k)), [("DONE",)], [("KEEP", k)])
    make = OperatorSchema("make", [m], Atomic(("NEED", m)), [("DONE",)], [("KEEP", m)])
    facts = [("SEL", "K1"), ("KEEP", "K1"), ("KEEP", "K2")]
    model = WorldModel(InitialModel([Clause([(True, fact)]) for fact in facts]))
    goal = Clause([(False, ("DONE",)), (False, ("KEEP", "K1")), (False, ("KEEP", "K2"))])
    difference = Difference([Clause([(False, ("DONE",))])], [goal])
    bound = AddListRelevance(model_bindings=True).for_problem([fix, make], model.initial)
    assert [str(r.operator) for r in bound.relevant(difference, model)] == ["make(m)", "fix(K1)"]
    assert [str(r.operator) for r in _relevant(difference, [fix, make], model)] == [
        "fix(k)", "make(m)",
    ]


def test_model_bindings_keep_rigid_atoms_matched():
    # take(i, m) for HAVE(M): POWERON(?i) matches one fact, I2, but I2 does not support
    # M, and SUPPORTS is rigid (no operator adds it): bound to I2 the instance could
    # never be applied, and would be dropped. The binding is refused; joined, the
    # instruments that support M and the one powered on have none in common, so i is
    # left to the proof.
    i, m = Param("i"), Param("m")
    take = OperatorSchema(
        "take", [i, m], And([Atomic(("SUPPORTS", i, m)), Atomic(("POWERON", i))]),
        [("HAVE", m)], [],
    )
    facts = [("SUPPORTS", "I1", "M"), ("SUPPORTS", "I3", "M"), ("POWERON", "I2")]
    model = WorldModel(InitialModel([Clause([(True, fact)]) for fact in facts],
                                    rigid=frozenset({("SUPPORTS", 2)})))
    difference = Difference([Clause([(False, ("HAVE", "M"))])])
    bound = AddListRelevance(model_bindings=True).for_problem([take], model.initial)
    assert [str(r.operator) for r in bound.relevant(difference, model)] == ["take(i, M)"]


def test_a_model_binding_that_makes_the_instance_never_applicable_is_not_made():
    # take(x, y, z) for DONE(Z): HOLD(?x) matches one fact, A; then R1(A, ?y) one, B,
    # which is refused since R2(B) matches no fact. Bound to A alone the instance would
    # still never be applicable (no y has both R1(A, y) and R2(y), and R1, R2 are
    # rigid), so it keeps x unbound: with C and D it can be.
    x, y, z = Param("x"), Param("y"), Param("z")
    take = OperatorSchema(
        "take", [x, y, z],
        And([Atomic(("HOLD", x)), Atomic(("R1", x, y)), Atomic(("R2", y))]),
        [("DONE", z)], [],
    )
    facts = [("HOLD", "A"), ("R1", "A", "B"), ("R1", "C", "D"), ("R2", "D")]
    model = WorldModel(InitialModel([Clause([(True, fact)]) for fact in facts],
                                    rigid=frozenset({("R1", 2), ("R2", 1)})))
    difference = Difference([Clause([(False, ("DONE", "Z"))])])
    index = AddListRelevance(model_bindings=True, rigid_join=True).for_problem(
        [take], model.initial)
    assert [str(r.operator) for r in index.relevant(difference, model)] == ["take(x, y, Z)"]


def test_a_model_binding_whose_missing_atom_no_operator_can_make_is_not_made():
    # send(r, w, s) for SENT(S): SEES(?w) matches one fact, W3, and then AT(?r, W3)
    # one, R0. But HAVE(R0, S) is missing, and sample, the one operator that adds it,
    # needs EQUIPPED(R0), which is rigid and false: bound to R0 the instance could
    # never be applied (rovers 04 ended exhausted so). The instance is offered as the
    # difference made it. With R0 equipped the binding stands.
    r, w, s = Param("r"), Param("w"), Param("s")
    send = OperatorSchema(
        "send", [r, w, s],
        And([Atomic(("AT", r, w)), Atomic(("SEES", w)), Atomic(("HAVE", r, s))]),
        [("SENT", s)], [],
    )
    sample = OperatorSchema("sample", [r, s], Atomic(("EQUIPPED", r)), [("HAVE", r, s)], [])
    rigid = frozenset({("SEES", 1), ("EQUIPPED", 1)})
    difference = Difference([Clause([(False, ("SENT", "S"))])])
    for equipped, expected in (("R1", "send(r, w, S)"), ("R0", "send(R0, W3, S)")):
        facts = [("AT", "R0", "W3"), ("AT", "R1", "W2"), ("SEES", "W3"), ("EQUIPPED", equipped)]
        model = WorldModel(InitialModel([Clause([(True, fact)]) for fact in facts], rigid=rigid))
        index = AddListRelevance(model_bindings=True).for_problem([send, sample], model.initial)
        assert [str(i.operator) for i in index.relevant(difference, model)] == [expected]
