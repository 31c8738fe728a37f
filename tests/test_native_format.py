"""The native ``.strips`` format: the examples load, and every bad input names its place."""

from __future__ import annotations

from pathlib import Path

import pytest

from strips_framework.errors import InputError
from strips_framework.formats.native import NativeLoader
from strips_framework.logic.formulas import And, Atomic, Exists, Var, formula_to_str
from strips_framework.logic.terms import Param
from strips_framework.plugin import builtins
from strips_framework.worldmodel.problem import DerivedFact, OperatorSchema, SourceSpan

EXAMPLES = Path(__file__).resolve().parent.parent / "examples"

BASE = """\
problem tiny
constants a b c BOX1
primitive ATR/1 AT/2

facts
  ATR(a)
  AT(BOX1, b)

operator goto(m, n)
  pre    ATR(m)
  delete ATR(m)
  add    ATR(n)

goal exists x: AT(BOX1, x) & ATR(x)
"""


def write(tmp_path: Path, text: str, name: str = "p.strips") -> Path:
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def load_error(tmp_path: Path, text: str) -> InputError:
    path = write(tmp_path, text)
    with pytest.raises(InputError) as caught:
        NativeLoader().load(path)
    assert caught.value.path == str(path)
    return caught.value


def position(error: InputError) -> tuple[int, int | None]:
    return error.line, error.column


# --- the examples -------------------------------------------------------------------


@pytest.mark.parametrize(
    "path", sorted(EXAMPLES.rglob("*.strips")), ids=lambda p: str(p.relative_to(EXAMPLES))
)
def test_every_example_loads(path: Path) -> None:
    problem = NativeLoader().load(path)
    assert problem.name and problem.operators and problem.facts
    assert problem.source == str(path)


def test_three_boxes_is_the_papers_problem() -> None:
    problem = NativeLoader().load(EXAMPLES / "three-boxes.strips")
    m, n, k = Param("m"), Param("n"), Param("k")
    x = Var("x")
    assert problem.name == "three-boxes"
    assert problem.constants == ("a", "b", "c", "d", "BOX1", "BOX2", "BOX3")
    assert problem.primitive_predicates == {("ATR", 1), ("AT", 2)}
    assert problem.facts == (
        ("ATR", "a"),
        ("AT", "BOX1", "b"),
        ("AT", "BOX2", "c"),
        ("AT", "BOX3", "d"),
    )
    assert problem.operators == (
        OperatorSchema("goto", [m, n], Atomic(("ATR", m)), [("ATR", n)], [("ATR", m)]),
        OperatorSchema(
            "push",
            [k, m, n],
            And([Atomic(("AT", k, m)), Atomic(("ATR", m))]),
            [("AT", k, n), ("ATR", n)],
            [("AT", k, m), ("ATR", m)],
        ),
    )
    assert problem.goal == Exists([x], And([Atomic(("AT", f"BOX{i}", x)) for i in (1, 2, 3)]))
    assert problem.unique_names
    assert problem.operators[0].source == SourceSpan(str(EXAMPLES / "three-boxes.strips"), 18)


def test_robot_world_tasks_share_the_world_of_table_1() -> None:
    folder = EXAMPLES / "robot-world"
    goals = {
        "light": "STATUS(LIGHTSWITCH1, ON)",
        "boxes": "NEXTTO(BOX1, BOX2) & NEXTTO(BOX2, BOX3)",
        "other-room": "AT(ROBOT, f)",
        "five-goals": "NEXTTO(BOX2, BOX3) & NEXTTO(BOX3, DOOR1) & STATUS(LIGHTSWITCH1, ON)"
        " & NEXTTO(BOX1, BOX2) & INROOM(ROBOT, ROOM2)",
    }
    worlds = set()
    for name, goal in goals.items():
        problem = NativeLoader().load(folder / f"{name}.strips")
        assert formula_to_str(problem.goal) == goal
        worlds.add((problem.facts, problem.axioms, problem.operators))
        assert problem.primitive_predicates == {
            ("AT", 2),
            ("NEXTTO", 2),
            ("INROOM", 2),
            ("ONFLOOR", 0),
            ("ON", 2),
            ("STATUS", 2),
        }
        assert {o.name for o in problem.operators} == {
            "goto1",
            "goto2",
            "pushto",
            "turnonlight",
            "climbonbox",
            "climboffbox",
            "gothrudoor",
        }
        assert ("TYPE", "BOX1", "BOX") in problem.facts
        assert ("LOCINROOM", "f", "ROOM4") in problem.facts
    assert len(worlds) == 1
    schema = problem.operator("gothrudoor")
    assert schema.source is not None and schema.source.path.endswith("world.inc")


def test_loader_is_registered_by_the_builtin_plugin() -> None:
    assert builtins.strips_register_loaders() == [NativeLoader]
    assert (NativeLoader.name, NativeLoader.suffixes) == ("native", (".strips",))


# --- features -----------------------------------------------------------------------


def test_axioms_derived_facts_continuations_and_unique_names(tmp_path: Path) -> None:
    text = (
        BASE.replace("goal", "unique-names no\ngoal")
        + """
axioms
  forall x, y: AT(BOX1, x) & x != y   # a comment
      -> ~AT(BOX1, y)
  forall x: ATR(x) -> HERE(x)
derived
  NEAR(BOX1, a) <- AT(BOX1, b), ATR(a)
"""
    )
    problem = NativeLoader().load(write(tmp_path, text))
    assert [formula_to_str(a) for a in problem.axioms] == [
        "forall x, y: AT(BOX1, x) & x != y -> ~AT(BOX1, y)",
        "forall x: ATR(x) -> HERE(x)",
    ]
    assert problem.derived == (
        DerivedFact(("NEAR", "BOX1", "a"), [("AT", "BOX1", "b"), ("ATR", "a")]),
    )
    assert problem.derived[0].source == SourceSpan(str(tmp_path / "p.strips"), 22)
    assert not problem.unique_names


def test_declarations_may_come_after_use_and_constants_span_lines(tmp_path: Path) -> None:
    text = "goal ATR(c)\n" + BASE.replace("goal exists x: AT(BOX1, x) & ATR(x)\n", "").replace(
        "constants a b c BOX1", "constants a b\n  c, BOX1"
    )
    problem = NativeLoader().load(write(tmp_path, text))
    assert problem.constants == ("a", "b", "c", "BOX1")
    assert problem.goal == Atomic(("ATR", "c"))


def test_operator_parts_may_be_omitted(tmp_path: Path) -> None:
    text = BASE + "operator wait\n  add ATR(a)\n"
    schema = NativeLoader().load(write(tmp_path, text)).operator("wait")
    assert formula_to_str(schema.precondition) == "true"
    assert schema.parameters == () and schema.delete_list == ()


def test_include_splices_a_file_relative_to_the_includer(tmp_path: Path) -> None:
    (tmp_path / "lib").mkdir()
    write(tmp_path, BASE.replace("problem tiny\n", "").split("goal")[0], "lib/world.inc")
    path = write(tmp_path, 'problem t\ninclude "lib/world.inc"\ngoal ATR(b)\n')
    problem = NativeLoader().load(path)
    assert problem.facts == (("ATR", "a"), ("AT", "BOX1", "b"))


def test_errors_in_included_files_name_the_included_file(tmp_path: Path) -> None:
    write(tmp_path, "facts\n  ATR(a)\n  AT(q, a)\n", "world.inc")
    path = write(tmp_path, 'problem t\nconstants a\ninclude "world.inc"\ngoal ATR(a)\n')
    with pytest.raises(InputError) as caught:
        NativeLoader().load(path)
    assert caught.value.path == str(tmp_path / "world.inc")
    assert position(caught.value) == (3, 6)


def test_include_problems(tmp_path: Path) -> None:
    error = load_error(tmp_path, 'problem t\ninclude "missing.inc"\n')
    assert position(error) == (2, 9)
    assert error.message == "cannot read the included file: No such file or directory"
    error = load_error(tmp_path, 'problem t\ninclude "p.strips"\n')
    assert error.message == "including 'p.strips' here would make a cycle"


def test_an_unreadable_file_is_an_input_error(tmp_path: Path) -> None:
    with pytest.raises(InputError, match="cannot read the file"):
        NativeLoader().load(tmp_path / "nothing.strips")


# --- validation: every rule, with file:line:column ----------------------------------


def with_lines(**replacements: str) -> str:
    text = BASE
    for old, new in replacements.items():
        assert old in text
        text = text.replace(old, new)
    return text


@pytest.mark.parametrize(
    ("text", "where", "message"),
    [
        pytest.param(
            BASE + "fact\n  ATR(b)\n",
            (15, 1),
            "expected a keyword (problem, constants, primitive, unique-names, include, facts, "
            "axioms, derived, operator, goal) but found 'fact'",
            id="unknown-keyword",
        ),
        pytest.param(
            "  ATR(a)\n" + BASE,
            (1, 3),
            "expected a keyword in column 1 but found an indented line",
            id="indented-first-line",
        ),
        pytest.param(
            with_lines(**{"  pre    ATR(m)": "  precondition ATR(m)"}),
            (10, 3),
            "expected 'pre', 'delete' or 'add' but found 'precondition'",
            id="unknown-operator-part",
        ),
        pytest.param(
            with_lines(**{"facts\n": "facts ATR(b)\n"}),
            (5, 7),
            "expected end of line but found 'ATR'",
            id="entries-on-section-line",
        ),
        pytest.param(
            with_lines(**{"AT(BOX1, b)": "AT(BOX1, b, c)"}),
            (7, 3),
            "expected 2 arguments for AT (declared at {path}:3) but found 3 arguments",
            id="arity-against-declaration",
        ),
        pytest.param(
            with_lines(**{"ATR(a)\n": "ATR(a), HOLDS(a)\n", "ATR(x)": "HOLDS(x, x)"}),
            (14, 30),
            "expected 1 argument for HOLDS (as first used at {path}:6) but found 2 arguments",
            id="arity-against-first-use",
        ),
        pytest.param(
            with_lines(**{"AT(BOX1, b)": "AT(BOX1, x)"}),
            (7, 12),
            "undeclared constant 'x' (declared constants: BOX1, a, b, c); facts must be "
            "ground; write quantified statements under 'axioms'",
            id="non-ground-fact",
        ),
        pytest.param(
            with_lines(**{"ATR(x)": "ATR(d)"}),
            (14, 34),
            "undeclared constant 'd' (declared constants: BOX1, a, b, c); a variable must "
            "be bound by 'forall' or 'exists'",
            id="undeclared-constant-in-goal",
        ),
        pytest.param(
            with_lines(**{"add    ATR(n)": "add    ATR(n), AT(q, n)"}),
            (12, 21),
            "'q' is neither a parameter (m, n) nor a declared constant "
            "(declared constants: BOX1, a, b, c)",
            id="unknown-identifier-in-add-list",
        ),
        pytest.param(
            with_lines(**{"delete ATR(m)": "delete ATR(m), AT(BOX9, $)"}),
            (11, 21),
            "'BOX9' is neither a parameter (m, n) nor a declared constant "
            "(declared constants: BOX1, a, b, c)",
            id="unknown-identifier-in-delete-list",
        ),
        pytest.param(
            BASE + "operator goto(a)\n  pre ATR(a)\n",
            (15, 10),
            "operator 'goto' is defined twice (first at {path}:9)",
            id="duplicate-operator",
        ),
        pytest.param(
            with_lines(**{"goto(m, n)": "goto(m, m)"}),
            (9, 18),
            "parameter 'm' is listed twice",
            id="duplicate-parameter",
        ),
        pytest.param(
            with_lines(**{"goto(m, n)": "goto(m, a)"}),
            (9, 18),
            "parameter 'a' is also a declared constant",
            id="parameter-named-like-a-constant",
        ),
        pytest.param(
            with_lines(**{"delete ATR(m)": "delete ATR(m), HERE(m)"}),
            (11, 18),
            "expected only primitive predicates on a delete list (paper III.B) but HERE/1 is "
            "not declared primitive",
            id="non-primitive-delete",
        ),
        pytest.param(
            with_lines(
                **{"goto(m, n)": "goto(m, n, k)", "delete ATR(m)": "delete ATR(m), AT(k, $)"}
            ),
            (9, 21),
            "parameter 'k' of goto occurs only in the delete list: neither the precondition "
            "nor the add list can bind it",
            id="parameter-only-in-delete-list",
        ),
        pytest.param(
            with_lines(**{"goto(m, n)": "goto(m, n, k)"}),
            (9, 21),
            "parameter 'k' of goto occurs nowhere: neither the precondition nor the add list "
            "can bind it",
            id="unused-parameter",
        ),
        pytest.param(
            with_lines(**{"add    ATR(n)": "add    ATR($)"}),
            (12, 14),
            "'$' (the wildcard) is allowed only in delete lists",
            id="wildcard-in-add-list",
        ),
        pytest.param(
            with_lines(**{"pre    ATR(m)": "pre    ATR($)"}),
            (10, 14),
            "'$' (the wildcard) is allowed only in delete lists",
            id="wildcard-in-precondition",
        ),
        pytest.param(
            with_lines(**{"AT(BOX1, b)": "AT(BOX1, $)"}),
            (7, 12),
            "'$' (the wildcard) is allowed only in delete lists",
            id="wildcard-in-fact",
        ),
        pytest.param(
            BASE + "derived\n  AT(BOX1, c) <- ATR(a)\n",
            (16, 3),
            "expected a non-primitive derived fact but AT is primitive",
            id="derived-fact-with-primitive-predicate",
        ),
        pytest.param(
            BASE + "derived\n  NEAR(BOX1, c) <- AT(BOX1, c)\n",
            (16, 20),
            "AT(BOX1, c) is not a fact of the initial model",
            id="support-not-a-fact",
        ),
        pytest.param(
            with_lines(**{"ATR(a)\n": "ATR(a), BIG(BOX1)\n"})
            + "derived\n  NEAR(BOX1, c) <- ATR(a), BIG(BOX1)\n",
            (16, 28),
            "expected a primitive fact to rest on but BIG is not primitive",
            id="support-not-primitive",
        ),
        pytest.param(
            with_lines(**{"add    ATR(n)": "add    ATR(n), NEAR(BOX1, n)"})
            + "derived\n  NEAR(BOX1, b) <- AT(BOX1, b)\n",
            (12, 18),
            "operator goto adds NEAR, which has derived facts ({path}:16); an added atom "
            "would rest on nothing",
            id="derived-predicate-on-add-list",
        ),
        pytest.param(
            with_lines(**{"goal exists x: AT(BOX1, x) & ATR(x)\n": ""}),
            (1, None),
            "expected a 'goal <wff>' line but found none",
            id="missing-goal",
        ),
        pytest.param(
            with_lines(**{"problem tiny\n": ""}),
            (1, None),
            "expected a 'problem <name>' line but found none",
            id="missing-problem-name",
        ),
        pytest.param(
            BASE + "goal ATR(b)\n",
            (15, 1),
            "'goal' is given twice (first at {path}:14)",
            id="duplicate-goal",
        ),
        pytest.param(
            with_lines(**{"constants a b c BOX1": "constants a b c a BOX1"}),
            (2, 17),
            "constant 'a' is declared twice (first at {path}:2)",
            id="duplicate-constant",
        ),
        pytest.param(
            with_lines(**{"ATR/1 AT/2": "ATR/1 AT/x"}),
            (3, 20),
            "expected an arity (a number below 1000000) but found 'x'",
            id="bad-arity",
        ),
        pytest.param(
            with_lines(**{"problem tiny": "problem tiny\nunique-names maybe"}),
            (2, 14),
            "expected 'yes' or 'no' but found 'maybe'",
            id="bad-unique-names",
        ),
    ],
)
def test_validation_errors(
    tmp_path: Path, text: str, where: tuple[int, int | None], message: str
) -> None:
    error = load_error(tmp_path, text)
    assert error.message == message.format(path=tmp_path / "p.strips")
    assert position(error) == where


def test_error_in_a_wff_continued_over_lines(tmp_path: Path) -> None:
    text = BASE.replace(
        "goal exists x: AT(BOX1, x) & ATR(x)",
        "goal exists x: AT(BOX1, x)\n     & ATR(x)\n     & (ATR(a) |\n        )",
    )
    error = load_error(tmp_path, text)
    assert position(error) == (17, 9)
    assert error.message.startswith("expected a formula") and error.message.endswith("')'")
    assert str(error) == f"{tmp_path / 'p.strips'}:17:9: {error.message}"


def test_error_at_the_end_of_an_entry(tmp_path: Path) -> None:
    error = load_error(tmp_path, BASE.replace("AT(BOX1, b)", "AT(BOX1, b"))
    assert position(error) == (7, 13)
    assert error.message == "expected ',' or ')' but found end of line"
