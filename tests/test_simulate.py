"""The independent plan simulator, on problems built directly from the AST classes."""

from __future__ import annotations

from pathlib import Path

import pytest

from strips_framework.formats.native import NativeLoader
from strips_framework.logic.formulas import (
    And,
    Atomic,
    Exists,
    Forall,
    Formula,
    Implies,
    Not,
    Or,
    Var,
)
from strips_framework.logic.terms import WILDCARD, Param
from strips_framework.worldmodel.problem import DerivedFact, OperatorSchema, Problem
from strips_framework.worldmodel.simulate import SimulationError, replay

x, y, z = Var("x"), Var("y"), Var("z")
k, l, m, n = Param("k"), Param("l"), Param("m"), Param("n")
S = WILDCARD


def atom(predicate: str, *args: object) -> Atomic:
    return Atomic((predicate, *args))


def conj(*parts: Formula) -> Formula:
    return And(parts)


def problem(
    *,
    facts: list[tuple],
    operators: list[OperatorSchema],
    goal: Formula,
    constants: list[str],
    axioms: tuple[Formula, ...] = (),
    derived: tuple[DerivedFact, ...] = (),
    unique_names: bool = True,
) -> Problem:
    predicates = {(a[0], len(a) - 1) for a in facts}
    return Problem("test", constants, predicates, facts, axioms, derived, operators, goal,
                   unique_names)


# The three-boxes example of the paper (II.E).
def three_boxes() -> Problem:
    goto = OperatorSchema("goto", [m, n], atom("ATR", m), [("ATR", n)], [("ATR", m)])
    push = OperatorSchema(
        "push", [k, m, n], conj(atom("AT", k, m), atom("ATR", m)),
        [("AT", k, n), ("ATR", n)], [("AT", k, m), ("ATR", m)],
    )
    goal = Exists([x], conj(atom("AT", "BOX1", x), atom("AT", "BOX2", x), atom("AT", "BOX3", x)))
    return problem(
        facts=[("ATR", "a"), ("AT", "BOX1", "b"), ("AT", "BOX2", "c"), ("AT", "BOX3", "d")],
        operators=[goto, push], goal=goal,
        constants=["a", "b", "c", "d", "BOX1", "BOX2", "BOX3"],
    )


# The robot world of section IV (Table 1, as reconstructed in docs/strips-1971.md).
ROBOT_CONSTANTS = [
    "ROBOT", "BOX1", "BOX2", "BOX3", "LIGHTSWITCH1", "DOOR1", "DOOR2", "DOOR3", "DOOR4",
    "ROOM1", "ROOM2", "ROOM3", "ROOM4", "ROOM5", "a", "b", "c", "d", "e", "f",
    "BOX", "DOOR", "LIGHTSWITCH", "ON", "OFF",
]
ROBOT_AXIOMS = (
    Forall([x, y, z], Implies(atom("CONNECTS", x, y, z), atom("CONNECTS", x, z, y))),
    Forall([x, y, z], Implies(atom("CONNECTS", x, y, z), atom("INROOM", x, y))),
)


def robot_world(goal: Formula) -> Problem:
    facts = [("INROOM", "ROBOT", "ROOM1"), ("AT", "ROBOT", "e"), ("ONFLOOR",),
             ("AT", "LIGHTSWITCH1", "d"), ("INROOM", "LIGHTSWITCH1", "ROOM1"),
             ("STATUS", "LIGHTSWITCH1", "OFF"), ("TYPE", "LIGHTSWITCH1", "LIGHTSWITCH"),
             ("LOCINROOM", "f", "ROOM4")]
    for box, place in (("BOX1", "a"), ("BOX2", "b"), ("BOX3", "c")):
        facts += [("AT", box, place), ("INROOM", box, "ROOM1"), ("PUSHABLE", box),
                  ("TYPE", box, "BOX")]
    for i in range(1, 5):
        facts += [("TYPE", f"DOOR{i}", "DOOR"), ("CONNECTS", f"DOOR{i}", f"ROOM{i}", "ROOM5")]
    robot_moves = [("AT", "ROBOT", S), ("NEXTTO", "ROBOT", S)]
    in_robots_room = lambda place: Exists(
        [x], conj(atom("INROOM", "ROBOT", x), atom(place, m, x))
    )
    operators = [
        OperatorSchema("goto1", [m], conj(atom("ONFLOOR"), in_robots_room("LOCINROOM")),
                       [("AT", "ROBOT", m)], robot_moves),
        OperatorSchema("goto2", [m], conj(atom("ONFLOOR"), in_robots_room("INROOM")),
                       [("NEXTTO", "ROBOT", m)], robot_moves),
        OperatorSchema(
            "pushto", [m, n],
            conj(atom("PUSHABLE", m), atom("ONFLOOR"), atom("NEXTTO", "ROBOT", m),
                 Exists([x], conj(atom("INROOM", m, x), atom("INROOM", n, x)))),
            [("NEXTTO", m, n), ("NEXTTO", n, m), ("NEXTTO", "ROBOT", m)],
            [*robot_moves, ("AT", m, S), ("NEXTTO", m, S), ("NEXTTO", S, m)],
        ),
        OperatorSchema(
            "turnonlight", [m],
            conj(Exists([n], conj(atom("TYPE", n, "BOX"), atom("ON", "ROBOT", n),
                                  atom("NEXTTO", n, m))),
                 atom("TYPE", m, "LIGHTSWITCH")),
            [("STATUS", m, "ON")], [("STATUS", m, "OFF")],
        ),
        OperatorSchema(
            "climbonbox", [m],
            conj(atom("ONFLOOR"), atom("TYPE", m, "BOX"), atom("NEXTTO", "ROBOT", m)),
            [("ON", "ROBOT", m)], [("AT", "ROBOT", S), ("ONFLOOR",)],
        ),
        OperatorSchema("climboffbox", [m], conj(atom("TYPE", m, "BOX"), atom("ON", "ROBOT", m)),
                       [("ONFLOOR",)], [("ON", "ROBOT", m)]),
        OperatorSchema(
            "gothrudoor", [k, l, m],
            conj(atom("NEXTTO", "ROBOT", k), atom("CONNECTS", k, l, m),
                 atom("INROOM", "ROBOT", l), atom("TYPE", k, "DOOR"), atom("ONFLOOR")),
            [("INROOM", "ROBOT", m)], [*robot_moves, ("INROOM", "ROBOT", S)],
        ),
    ]
    return problem(facts=facts, operators=operators, goal=goal, constants=ROBOT_CONSTANTS,
                   axioms=ROBOT_AXIOMS)


LIGHT_ON = atom("STATUS", "LIGHTSWITCH1", "ON")
BOXES_TOGETHER = conj(atom("NEXTTO", "BOX1", "BOX2"), atom("NEXTTO", "BOX2", "BOX3"))
ROBOT_AT_F = atom("AT", "ROBOT", "f")
OPTIMAL_LIGHT = ["goto2(BOX1)", "pushto(BOX1,LIGHTSWITCH1)", "climbonbox(BOX1)",
                 "turnonlight(LIGHTSWITCH1)"]


def test_three_boxes_plan_of_the_paper_is_valid() -> None:
    plan = ["goto(a,c)", "push(BOX2,c,b)", "goto(b,d)", "push(BOX3,d,b)"]
    result = replay(three_boxes(), plan)
    assert result.valid and result.step is None, result.message


@pytest.mark.parametrize(
    ("goal", "plan"),
    [
        (LIGHT_ON, ["goto2(BOX1)", "climbonbox(BOX1)", "climboffbox(BOX1)",
                    "pushto(BOX1,LIGHTSWITCH1)", "climbonbox(BOX1)", "turnonlight(LIGHTSWITCH1)"]),
        (LIGHT_ON, OPTIMAL_LIGHT),
        (BOXES_TOGETHER, ["goto2(BOX2)", "pushto(BOX2,BOX1)", "goto2(BOX3)", "pushto(BOX3,BOX2)"]),
        (ROBOT_AT_F, ["goto2(DOOR1)", "gothrudoor(DOOR1,ROOM1,ROOM5)", "goto2(DOOR4)",
                      "gothrudoor(DOOR4,ROOM5,ROOM4)", "goto1(f)"]),
    ],
    ids=["light-paper", "light-optimal", "boxes", "other-room"],
)
def test_paper_plans_for_the_robot_world_are_valid(goal: Formula, plan: list[str]) -> None:
    result = replay(robot_world(goal), plan)
    assert result.valid, result.message


EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
PAPER_PLANS = {
    "three-boxes.strips": ["goto(a, c)", "push(BOX2, c, b)", "goto(b, d)", "push(BOX3, d, b)"],
    "robot-world/light.strips": [
        "goto2(BOX1)", "climbonbox(BOX1)", "climboffbox(BOX1)", "pushto(BOX1, LIGHTSWITCH1)",
        "climbonbox(BOX1)", "turnonlight(LIGHTSWITCH1)",
    ],
    "robot-world/boxes.strips": [
        "goto2(BOX2)", "pushto(BOX2, BOX1)", "goto2(BOX3)", "pushto(BOX3, BOX2)",
    ],
    "robot-world/other-room.strips": [
        "goto2(DOOR1)", "gothrudoor(DOOR1, ROOM1, ROOM5)", "goto2(DOOR4)",
        "gothrudoor(DOOR4, ROOM5, ROOM4)", "goto1(f)",
    ],
}


@pytest.mark.parametrize("name", sorted(PAPER_PLANS))
def test_paper_plans_replay_on_the_native_examples(name: str) -> None:
    loaded = NativeLoader().load(EXAMPLES / name)
    result = replay(loaded, PAPER_PLANS[name])
    assert result.valid, result.message
    assert not replay(loaded, PAPER_PLANS[name][:-1]).valid


def test_optimal_light_plan_replays_on_the_native_example_in_both_syntaxes() -> None:
    loaded = NativeLoader().load(EXAMPLES / "robot-world" / "light.strips")
    assert replay(loaded, OPTIMAL_LIGHT).valid
    ipc = ["(goto2 BOX1)", "(pushto BOX1 LIGHTSWITCH1)", " ( climbonbox  BOX1 ) ",
           "(turnonlight LIGHTSWITCH1)"]
    assert replay(loaded, ipc).valid


@pytest.mark.parametrize("step", ["(CLIMBONBOX BOX1)", "(climbonbox box1)"])
def test_names_and_constants_are_matched_case_sensitively(step: str) -> None:
    plan = ["(goto2 BOX1)", "(pushto BOX1 LIGHTSWITCH1)", step, "(turnonlight LIGHTSWITCH1)"]
    result = replay(robot_world(LIGHT_ON), plan)
    assert not result.valid and result.step == 2
    assert "case-sensitive" in result.message


def test_constants_differing_only_in_case_are_different() -> None:
    touch = OperatorSchema("touch", [m], atom("HERE", m), [("TOUCHED", m)], [])
    both = problem(facts=[("HERE", "a")], operators=[touch], goal=atom("TOUCHED", "a"),
                   constants=["a", "A"])
    assert replay(both, ["touch(a)"]).valid
    assert not replay(both, ["touch(A)"]).valid


def test_failing_precondition_is_named_with_its_step() -> None:
    result = replay(robot_world(LIGHT_ON), ["goto2(BOX1)", "climbonbox(BOX1)",
                                             "pushto(BOX1,LIGHTSWITCH1)"])
    assert not result.valid and result.step == 2
    assert result.message == (
        "step 3 of 3, pushto(BOX1, LIGHTSWITCH1): precondition ONFLOOR does not hold"
    )


def test_failing_quantified_conjunct_is_shown_instantiated() -> None:
    result = replay(robot_world(ROBOT_AT_F), ["goto1(f)"])
    assert result.step == 0
    assert "precondition exists x: INROOM(ROBOT, x) & LOCINROOM(f, x) does not hold" in (
        result.message
    )


def test_goal_failing_at_the_end_is_reported_after_the_last_step() -> None:
    result = replay(robot_world(BOXES_TOGETHER), ["goto2(BOX2)", "pushto(BOX2,BOX1)"])
    assert not result.valid and result.step == 2
    assert result.message == (
        "the goal fails in the final state: NEXTTO(BOX2, BOX3) does not hold"
    )


@pytest.mark.parametrize(
    ("step", "expected"),
    [
        ("fly(BOX1)", "no operator 'fly' in the problem (operators: goto1, goto2, pushto,"),
        ("goto2(BOX1, BOX2)", "goto2(m) takes 1 argument(s), got 2"),
        ("goto2(BOX9)", "'BOX9' is not a constant of the problem"),
        ("goto2(BOX1", "not a step"),
        ("goto2(,BOX1)", "not a step"),
    ],
)
def test_malformed_steps_make_the_plan_invalid(step: str, expected: str) -> None:
    result = replay(robot_world(LIGHT_ON), ["goto2(BOX2)", step])
    assert not result.valid and result.step == 1
    assert result.message.startswith(f"step 2 of 2, {step!r}: {expected}")


def test_wildcard_deletes_every_matching_atom_and_nothing_else() -> None:
    clear = OperatorSchema("clear", [], atom("READY"), [], [("MARK", S), ("PAIR", "a", S)])
    facts = [("READY",), ("MARK", "a"), ("MARK", "b"), ("MARK", "a", "b"), ("PAIR", "a", "b"),
             ("PAIR", "b", "a")]
    none_left = conj(
        Not(Exists([x], Or([atom("MARK", x), atom("PAIR", "a", x)]))),
        atom("MARK", "a", "b"), atom("PAIR", "b", "a"),
    )
    tested = problem(facts=facts, operators=[clear], goal=none_left, constants=["a", "b"])
    assert not replay(tested, []).valid
    assert replay(tested, ["clear()"]).valid
    assert replay(tested, ["clear"]).valid
    assert replay(tested, ["(clear)"]).valid


def test_horn_axioms_are_closed_under_chaining() -> None:
    """CONNECTS symmetry, then the door axiom applied to the symmetric atom."""
    goal = conj(atom("CONNECTS", "DOOR4", "ROOM5", "ROOM4"), atom("INROOM", "DOOR4", "ROOM5"))
    assert replay(robot_world(goal), []).valid
    # Without the symmetry axiom, the second door cannot be reached from the corridor.
    plan = ["goto2(DOOR1)", "gothrudoor(DOOR1,ROOM1,ROOM5)", "goto2(DOOR4)"]
    assert replay(robot_world(ROBOT_AT_F), plan).message.startswith("the goal fails")
    asymmetric = robot_world(ROBOT_AT_F)._replace(axioms=ROBOT_AXIOMS[1:])
    result = replay(asymmetric, plan)
    assert result.step == 2
    assert "precondition exists x: INROOM(ROBOT, x) & INROOM(DOOR4, x)" in result.message


def test_horn_rules_with_conjunctions_and_unbound_head_variables() -> None:
    # forall x, y: P(x) & Q(x, y) -> R(y) & S(x);   forall x, y: T(x) -> U(x, y)
    axioms = (
        Forall([x, y], Implies(conj(atom("P", x), atom("Q", x, y)),
                               conj(atom("R", y), atom("S", x)))),
        Forall([x], Forall([y], Implies(atom("T", x), atom("U", x, y)))),
    )
    goal = conj(atom("R", "b"), atom("S", "a"), atom("U", "a", "a"), atom("U", "a", "b"),
                Not(atom("R", "a")))
    tested = problem(facts=[("P", "a"), ("Q", "a", "b"), ("T", "a")], operators=[], goal=goal,
                     constants=["a", "b"], axioms=axioms)
    assert replay(tested, []).valid


def test_consequences_of_a_deleted_fact_disappear() -> None:
    result = replay(robot_world(LIGHT_ON), ["goto2(DOOR1)", "gothrudoor(DOOR1,ROOM1,ROOM5)",
                                            "goto2(BOX1)"])
    assert result.step == 2
    assert "exists x: INROOM(ROBOT, x) & INROOM(BOX1, x)" in result.message


def test_derived_fact_holds_only_while_its_supports_do() -> None:
    move = OperatorSchema("move", [k, m, n], atom("AT", k, m), [("AT", k, n)], [("AT", k, S)])
    join = OperatorSchema("join", [], atom("NEXTTO", "B1", "B2"), [("JOINED",)], [])
    derived = DerivedFact(("NEXTTO", "B1", "B2"), [("AT", "B1", "a"), ("AT", "B2", "a")])
    tested = problem(facts=[("AT", "B1", "a"), ("AT", "B2", "a")], operators=[move, join],
                     goal=atom("JOINED"), constants=["a", "b", "B1", "B2"], derived=(derived,))
    assert replay(tested, ["join()"]).valid
    lost = replay(tested, ["move(B1,a,b)", "join()"])
    assert lost.step == 1 and "precondition NEXTTO(B1, B2) does not hold" in lost.message
    assert replay(tested, ["move(B1,a,b)", "move(B1,b,a)", "join()"]).valid


@pytest.mark.parametrize(
    ("axiom", "found"),
    [
        (Forall([x, y, z], Implies(conj(atom("AT", x, y), Not(atom("=", y, z)))
                                   , Not(atom("AT", x, z)))), "a negation (y != z)"),
        (Forall([x, y], Implies(conj(atom("BOX", x), atom("=", x, y)), atom("BOX", y))),
         "an equality"),
        (Forall([x], Implies(atom("BOX", x), Not(atom("DOOR", x)))), "a negation (~DOOR(x))"),
        (Forall([x], Implies(atom("BOX", x), Or([atom("BIG", x), atom("SMALL", x)]))),
         "a disjunction"),
        (Forall([x], Implies(atom("BOX", x), Exists([y], atom("AT", x, y)))), "an existential"),
    ],
)
def test_non_horn_axioms_are_refused_with_a_clear_error(axiom: Formula, found: str) -> None:
    tested = problem(facts=[("BOX", "a")], operators=[], goal=atom("BOX", "a"),
                     constants=["a"], axioms=(axiom,))
    with pytest.raises(SimulationError, match="handles only Horn axioms") as raised:
        replay(tested, [])
    assert "axiom 1, " in str(raised.value) and found in str(raised.value)


def test_negation_and_universal_goals_use_the_closed_world() -> None:
    goal = conj(Not(atom("STATUS", "LIGHTSWITCH1", "OFF")),
                Forall([x], Implies(atom("PUSHABLE", x), atom("INROOM", x, "ROOM1"))))
    assert replay(robot_world(goal), OPTIMAL_LIGHT).valid
    assert not replay(robot_world(goal), []).valid


def test_equality_follows_unique_names_or_is_refused() -> None:
    goto = OperatorSchema("goto", [m, n], conj(atom("ATR", m), Not(atom("=", m, n))),
                          [("ATR", n)], [("ATR", m)])
    kwargs = {"facts": [("ATR", "a")], "operators": [goto], "goal": atom("ATR", "b"),
                  "constants": ["a", "b"]}
    assert replay(problem(**kwargs), ["goto(a,b)"]).valid
    stay = replay(problem(**kwargs), ["goto(a,a)", "goto(a,b)"])
    assert stay.step == 0 and "precondition a != a does not hold" in stay.message
    with pytest.raises(SimulationError, match="unique-names"):
        replay(problem(**kwargs, unique_names=False), ["goto(a,b)"])
