"""Entailment questions with known answers, built the way a search builds them.

Each case is a small world model (facts, axioms, derived facts with their supports, and
operator effects applied to it, ``$`` deletes included), a goal wff schema and every
binding of its parameters that makes it follow. The tasks come from the same code the
searches use (:func:`~strips_framework.worldmodel.world.initial_model`,
:meth:`~strips_framework.worldmodel.operators.OperatorInstance.apply`,
:func:`~strips_framework.logic.cnf.negated_goal_clauses`), so a prover that passes them
answers the questions it will really be asked.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

from strips_framework.capabilities import ANSWERS, EQUALITY, QUANTIFIED_AXIOMS, SOUND
from strips_framework.logic.cnf import SkolemNames, clausify, negated_goal_clauses
from strips_framework.logic.formulas import Atomic, Truth
from strips_framework.logic.parser import parse_formula
from strips_framework.logic.terms import WILDCARD, Atom, Param
from strips_framework.records import Record
from strips_framework.worldmodel.operators import OperatorInstance
from strips_framework.worldmodel.problem import DerivedFact, OperatorSchema, Problem
from strips_framework.worldmodel.proving import Answer, ProofTask
from strips_framework.worldmodel.world import WorldModel, initial_model

#: Effort for the cases: far more than any of them needs, so a complete prover proves
#: every goal that follows.
EFFORT = 2000


class ProverCase(Record):
    """A task and its known answer.

    ``answers`` holds every correct binding of the goal's parameters, each complete (all
    parameters bound) and sorted by parameter name; it is ``((),)`` for a goal without
    parameters that follows and empty for one that does not. ``constants`` are the names a
    parameter may take, for judging a returned binding that leaves a parameter open.
    ``needs`` are the capabilities the case exercises: a prover that does not declare them
    is not asked (a case expecting no proof needs ``sound``).
    """

    name: str
    why: str
    task: ProofTask
    params: tuple[Param, ...]
    answers: frozenset[Answer]
    constants: tuple[str, ...]
    needs: frozenset[str]

    __slots__ = ("name", "why", "task", "params", "answers", "constants", "needs")

    def __init__(
        self,
        name: str,
        why: str,
        task: ProofTask,
        params: tuple[Param, ...],
        answers: frozenset[Answer],
        constants: tuple[str, ...],
        needs: frozenset[str],
    ) -> None:
        self.name = name
        self.why = why
        self.task = task
        self.params = params
        self.answers = answers
        self.constants = constants
        self.needs = needs

    @property
    def provable(self) -> bool:
        return bool(self.answers)


Change = tuple[Sequence[Atom], Sequence[Atom]]  # (delete list, add list) of one step


def case(
    name: str,
    why: str,
    *,
    facts: str = "",
    axioms: Sequence[str] = (),
    derived: Mapping[str, str] = {},
    changes: Sequence[Change] = (),
    goal: str,
    params: str = "",
    answers: Sequence[Mapping[str, str]] = (),
    provable: bool | None = None,
    needs: Sequence[str] = (),
    max_answers: int = 8,
    unique_names: bool = True,
) -> ProverCase:
    """Build a case from wff text: ``facts`` separated by ``;``, ``derived`` maps a derived
    atom to its supports (``;``-separated), ``changes`` are applied in order."""
    param_names = params.split()
    ordered = tuple(sorted(Param(p) for p in param_names))
    skolem = SkolemNames()
    problem = Problem(
        name=name,
        constants=(),
        primitive_predicates=(),
        facts=[_atom(text) for text in facts.split(";") if text.strip()],
        axioms=[parse_formula(text) for text in axioms],
        derived=[
            DerivedFact(_atom(atom), [_atom(s) for s in supports.split(";")])
            for atom, supports in derived.items()
        ],
        operators=(),
        goal=Truth(True),
    )
    model = WorldModel(initial_model(problem, skolem))
    for step, (deletes, adds) in enumerate(changes):
        schema = OperatorSchema(f"change{step}", (), Truth(True), adds, deletes)
        model = OperatorInstance(schema, ()).apply(model)
    formula = parse_formula(goal, params=param_names)
    expected = frozenset(tuple((p, binding[p.name]) for p in ordered) for binding in answers)
    if provable and not expected:
        expected = frozenset({()})
    task = ProofTask.of_model(
        model,
        negated_goal_clauses(formula, skolem),
        effort=EFFORT,
        max_answers=max_answers,
        unique_names=unique_names,
    )
    wanted = set(needs) | ({ANSWERS} if ordered else set()) | (set() if expected else {SOUND})
    return ProverCase(name, why, task, ordered, expected, _constants(task), frozenset(wanted))


def _atom(text: str) -> Atom:
    formula = parse_formula(text.strip())
    if not isinstance(formula, Atomic):
        raise TypeError(f"not an atom: {text!r}")
    return formula.atom


def _constants(task: ProofTask) -> tuple[str, ...]:
    found: dict[str, None] = {}

    def walk(term: object) -> None:
        if type(term) is str:
            found[term] = None
        elif type(term) is tuple:
            for arg in term[1:]:
                walk(arg)

    for clause in (*task.axioms, *task.negated_goal):
        for _, atom in clause.literals:
            for arg in atom[1:]:
                walk(arg)
    return tuple(found)


_MOVE_ROBOT = ([("AT", "ROBOT", WILDCARD), ("NEXTTO", "ROBOT", WILDCARD)], [("AT", "ROBOT", "c")])
_DOOR = "CONNECTS(DOOR1, ROOM1, ROOM2)"
_SYMMETRY = "forall x, y, z: CONNECTS(x, y, z) -> CONNECTS(x, z, y)"
_DOOR_IN_ROOM = "forall x, r1, r2: CONNECTS(x, r1, r2) -> INROOM(x, r1)"
_NEAR = {"NEAR(ROBOT, BOX1)": "NEXTTO(ROBOT, BOX1)"}
_ROBOT_FACTS = "AT(ROBOT, a); NEXTTO(ROBOT, BOX1); AT(BOX1, b)"

CASES: tuple[ProverCase, ...] = (
    case("fact", "a ground fact of the model", facts="P(a)", goal="P(a)", provable=True),
    case("missing-fact", "a ground atom the model does not have", facts="P(a)", goal="P(b)"),
    case("conjunction-with-a-missing-part", "one conjunct holds, the other does not",
         facts="P(a)", goal="P(a) & Q(a)"),
    case("one-parameter", "the parameter's only witness",
         facts="ATR(a)", goal="ATR(m)", params="m", answers=[{"m": "a"}]),
    case("several-answers", "three witnesses, all wanted",
         facts="ATR(a); ATR(b); ATR(c)", goal="ATR(m)", params="m",
         answers=[{"m": "a"}, {"m": "b"}, {"m": "c"}]),
    case("answers-capped", "three witnesses, at most two asked for", max_answers=2,
         facts="ATR(a); ATR(b); ATR(c)", goal="ATR(m)", params="m",
         answers=[{"m": "a"}, {"m": "b"}, {"m": "c"}]),
    case("shared-parameter", "one binding must serve both conjuncts",
         facts="AT(ROBOT, r1); AT(BOX, r2); AT(BOX, r1)", goal="AT(ROBOT, m) & AT(BOX, m)",
         params="m", answers=[{"m": "r1"}]),
    case("shared-parameter-unsatisfied", "each conjunct has a witness, but not the same one",
         facts="AT(ROBOT, r1); AT(BOX, r2)", goal="AT(ROBOT, m) & AT(BOX, m)", params="m"),
    case("two-parameters", "a join over two parameters",
         facts="R(a, b); R(c, d); S(d)", goal="R(n, m) & S(m)", params="m n",
         answers=[{"m": "d", "n": "c"}]),
    case("existential-goal", "the paper's 3-boxes goal form",
         facts="AT(BOX1, b); AT(BOX2, c); AT(BOX2, b)",
         goal="exists x: AT(BOX1, x) & AT(BOX2, x)", provable=True),
    case("horn-axiom", "a door connects its rooms both ways",
         facts=_DOOR, axioms=[_SYMMETRY], goal="CONNECTS(DOOR1, ROOM2, m)", params="m",
         answers=[{"m": "ROOM1"}], needs=[QUANTIFIED_AXIOMS]),
    case("axiom-chain", "two axioms in a row give both rooms of the door",
         facts=_DOOR, axioms=[_SYMMETRY, _DOOR_IN_ROOM], goal="INROOM(DOOR1, m)", params="m",
         answers=[{"m": "ROOM1"}, {"m": "ROOM2"}], needs=[QUANTIFIED_AXIOMS]),
    case("non-horn-axiom", "a disjunctive axiom and a universal negation",
         facts="P(a)", axioms=["forall x: P(x) -> Q(x) | R(x)", "forall x: ~R(x)"],
         goal="Q(m)", params="m", answers=[{"m": "a"}], needs=[QUANTIFIED_AXIOMS]),
    case("universal-goal", "a universal goal that an axiom gives",
         axioms=["forall x: Q(x) -> P(x)"], goal="forall x: Q(x) -> P(x)", provable=True,
         needs=[QUANTIFIED_AXIOMS]),
    case("universal-goal-open-world", "facts about a and b say nothing of other objects",
         facts="P(a); P(b)", goal="forall x: P(x)", needs=[QUANTIFIED_AXIOMS]),
    case("unique-names", "m != r2 is evaluated under unique names",
         facts="IN(ROBOT, r1)", goal="IN(ROBOT, m) & m != r2", params="m",
         answers=[{"m": "r1"}], needs=[EQUALITY]),
    case("unique-names-unsatisfied", "the only witness is excluded",
         facts="IN(ROBOT, r1)", goal="IN(ROBOT, m) & m != r1", params="m", needs=[EQUALITY]),
    case("equation", "an equation among the axioms rewrites the goal", unique_names=False,
         facts="P(f(a))", axioms=["f(a) = b"], goal="P(b)", provable=True, needs=[EQUALITY]),
    case("dollar-delete-hides-derived", "deleting NEXTTO(ROBOT, $) hides the derived fact "
         "resting on it", facts=_ROBOT_FACTS, derived=_NEAR, changes=[_MOVE_ROBOT],
         goal="NEAR(ROBOT, m)", params="m"),
    case("derived-fact", "the derived fact is visible while its support is",
         facts=_ROBOT_FACTS, derived=_NEAR, goal="NEAR(ROBOT, m)", params="m",
         answers=[{"m": "BOX1"}]),
    case("dollar-delete-keeps-the-rest", "AT(ROBOT, $) deletes the robot's place only",
         facts=_ROBOT_FACTS, derived=_NEAR, changes=[_MOVE_ROBOT], goal="AT(n, m)",
         params="m n", answers=[{"n": "ROBOT", "m": "c"}, {"n": "BOX1", "m": "b"}]),
    case("derived-fact-revived", "adding the support back makes the derived fact visible",
         facts=_ROBOT_FACTS, derived=_NEAR,
         changes=[_MOVE_ROBOT, ([], [("NEXTTO", "ROBOT", "BOX1")])],
         goal="NEAR(ROBOT, m)", params="m", answers=[{"m": "BOX1"}]),
)


def pigeonhole(pigeons: int) -> ProofTask:
    """``pigeons`` pigeons in one hole fewer, as a goal that follows: hard for resolution
    and not trivial for a SAT solver, so a tiny effort must give up on it."""
    holes = pigeons - 1
    placed = [
        " | ".join(f"IN(p{i}, h{j})" for j in range(holes)) for i in range(pigeons)
    ]
    apart = [
        f"~IN(p{i}, h{j}) | ~IN(p{k}, h{j})"
        for j in range(holes)
        for i in range(pigeons)
        for k in range(i + 1, pigeons)
    ]
    skolem = SkolemNames()
    axioms = [c for text in apart for c in clausify(parse_formula(text), skolem=skolem)]
    goal = parse_formula("~(" + " & ".join(f"({p})" for p in placed) + ")")
    return ProofTask(axioms, negated_goal_clauses(goal, skolem), effort=1, unique_names=True)
