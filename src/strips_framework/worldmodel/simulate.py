"""An independent plan simulator: replays a plan on sets of ground atoms.

Every plan the planner reports is checked here, so this module shares no reasoning with the
planner: it reads only the :class:`~strips_framework.worldmodel.problem.Problem` value and the formula
AST, never the theorem prover, the search, the world-model classes or
``OperatorInstance.apply``. A bug in any of those cannot hide itself by also being in the
check.

A state is the set of *primitive* ground atoms: the problem's facts, then each step's
delete list (``$`` matches any term) followed by its add list. Conditions are evaluated on
the state's *closure*:

- a derived fact (``Problem.derived``) holds while all of its supports are in the state, so
  it disappears when one is deleted (and comes back if that support is added again), as in
  the paper's world models (III.B);
- axioms are applied by forward chaining to a fixpoint. Only definite Horn axioms are
  supported, ``forall vars: A1 & ... & An -> B1 & ... & Bm`` over atoms (no premise for a
  plain fact schema); their least model is exactly what follows from the state, so positive
  conditions hold in the closure if and only if a complete prover could prove them.

Preconditions and the goal are model-checked on the closure, with quantifiers ranging over
the problem's constants and equality decided by the unique-names assumption. Negation is
evaluated under the closed world (what is not in the closure is false). That is the
intended world of a Horn problem, but it is more generous than the planner's open-world
prover, which cannot prove a negated atom from Horn axioms: a negated condition the
simulator accepts may be one the planner could never have proved.
"""

from __future__ import annotations

import itertools
from collections import defaultdict
from collections.abc import Iterator, Mapping, Sequence

from strips_framework.errors import StripsError
from strips_framework.plan_steps import split_step
from strips_framework.logic.formulas import (
    And,
    Atomic,
    Exists,
    Forall,
    Formula,
    Iff,
    Implies,
    Not,
    Or,
    Truth,
    Var,
    conjuncts,
    formula_to_str,
    substitute_free,
    term_variables,
)
from strips_framework.logic.terms import EQUALITY, WILDCARD, Atom, Param, Term
from strips_framework.records import Record
from strips_framework.worldmodel.problem import OperatorSchema, Problem

#: Values of quantified variables and schema parameters while a formula is evaluated.
Env = Mapping[Var | Param, Term]
State = frozenset[Atom]


class SimulationError(StripsError):
    """The problem uses something the simulator cannot decide (not: the plan is wrong)."""


class Replay(Record):
    """The verdict on a plan.

    ``step`` is the 0-based index of the first step that cannot be executed, or
    ``len(plan)`` when every step executes but the goal does not hold at the end; ``None``
    when the plan is valid. ``message`` says what failed, naming the step (counted from 1
    for people) and the precondition conjunct or goal conjunct that does not hold.
    """

    valid: bool
    step: int | None
    message: str

    __slots__ = ("valid", "step", "message")

    def __init__(self, valid: bool, step: int | None, message: str) -> None:
        self.valid = valid
        self.step = step
        self.message = message


class _Rule(Record):
    """A definite Horn axiom: when every ``body`` atom matches, every ``head`` atom holds.

    Head variables that the body does not bind range over the problem's constants.
    """

    body: tuple[Atom, ...]
    head: tuple[Atom, ...]
    free: tuple[Var, ...]

    __slots__ = ("body", "head", "free")

    def __init__(
        self,
        body: tuple[Atom, ...],
        head: tuple[Atom, ...],
        free: tuple[Var, ...],
    ) -> None:
        self.body = body
        self.head = head
        self.free = free


def replay(problem: Problem, plan: Sequence[str]) -> Replay:
    """Execute ``plan`` from the problem's initial state and check the goal at the end.

    Steps are written ``name(arg, ...)`` or in IPC form ``(name arg ...)``; operator names
    and constants are matched exactly, as the native format is case-sensitive (``AT`` and
    ``at`` are different predicates, ``BOX1`` and ``box1`` different constants). Raises :class:`SimulationError` when the
    problem has non-Horn axioms, or uses equality without unique names.
    """
    return Simulator(problem).run(plan)


class Simulator:
    """One problem's rules and name tables, set up once for the replay of a plan.

    Its state operations (:meth:`close`, :meth:`holds`, :meth:`apply`) are public so that
    the conformance kit can compute optimal plan lengths with the same semantics as the
    replay, independently of the planner.
    """

    def __init__(self, problem: Problem) -> None:
        self.problem = problem
        self.rules = [_horn_rule(number, axiom) for number, axiom in enumerate(problem.axioms, 1)]
        self.operators = {schema.name: schema for schema in problem.operators}
        self.constants = frozenset(problem.constants)

    def run(self, plan: Sequence[str]) -> Replay:
        state: State = frozenset(self.problem.facts)
        for index, text in enumerate(plan):
            where = f"step {index + 1} of {len(plan)}"
            step = self.parse_step(text)
            if isinstance(step, str):
                return Replay(False, index, f"{where}, {text.strip()!r}: {step}")
            schema, binding = step
            shown = f"{schema.name}({', '.join(str(binding[p]) for p in schema.parameters)})"
            closed = self.close(state)
            for conjunct in conjuncts(schema.precondition):
                if not self.holds(conjunct, binding, closed):
                    failed = formula_to_str(substitute_free(conjunct, binding))
                    return Replay(
                        False, index, f"{where}, {shown}: precondition {failed} does not hold"
                    )
            state = _apply(schema, binding, state)
        closed = self.close(state)
        for conjunct in conjuncts(self.problem.goal):
            if not self.holds(conjunct, {}, closed):
                return Replay(
                    False,
                    len(plan),
                    f"the goal fails in the final state: {formula_to_str(conjunct)} does not hold",
                )
        return Replay(True, None, f"valid plan of {len(plan)} steps: the goal holds at the end")

    def parse_step(self, text: str) -> tuple[OperatorSchema, dict[Param, Term]] | str:
        """The schema and parameter binding a step names, or why it names none."""
        words = split_step(text)
        if words is None:
            return "not a step: expected 'name(arg, ...)' or '(name arg ...)'"
        name, *args = words
        schema = self.operators.get(name)
        if schema is None:
            known = ", ".join(s.name for s in self.problem.operators)
            return f"no operator {name!r} in the problem (operators: {known}; names are case-sensitive)"
        if len(args) != len(schema.parameters):
            return (
                f"{schema.signature()} takes {len(schema.parameters)} argument(s), "
                f"got {len(args)}"
            )
        values = []
        for arg in args:
            if arg not in self.constants:
                return f"{arg!r} is not a constant of the problem (names are case-sensitive)"
            values.append(arg)
        return schema, dict(zip(schema.parameters, values))

    def close(self, state: State) -> State:
        """The state, the derived facts whose supports it holds, and the axioms' consequences."""
        derived = {d.atom for d in self.problem.derived if all(s in state for s in d.supports)}
        facts = set(state) | derived
        by_predicate: dict[tuple[str, int], set[Atom]] = defaultdict(set)
        for atom in facts:
            by_predicate[atom[0], len(atom)].add(atom)
        changed = True
        while changed:
            changed = False
            for rule in self.rules:
                for env in list(body_matches(rule.body, by_predicate, {})):
                    for values in itertools.product(self.problem.constants, repeat=len(rule.free)):
                        full = {**env, **dict(zip(rule.free, values))}
                        for atom in rule.head:
                            grounded = ground_term(atom, full)
                            if grounded not in facts:
                                facts.add(grounded)
                                by_predicate[grounded[0], len(grounded)].add(grounded)
                                changed = True
        return frozenset(facts)

    def apply(self, schema: OperatorSchema, binding: Env, state: State) -> State:
        """The state after the ground step ``schema`` with ``binding`` (no precondition
        check)."""
        return _apply(schema, binding, state)

    def holds(self, formula: Formula, env: Env, state: State) -> bool:
        """Whether ``formula`` is true in ``state`` under the closed world."""
        if isinstance(formula, Atomic):
            atom = ground_term(formula.atom, env)
            if atom[0] == EQUALITY:
                if not self.problem.unique_names:
                    raise SimulationError(
                        f"cannot decide {formula_to_str(formula)}: the simulator decides "
                        "equality only under the unique-names assumption"
                    )
                return atom[1] == atom[2]
            return atom in state
        if isinstance(formula, Truth):
            return formula.value
        if isinstance(formula, Not):
            return not self.holds(formula.body, env, state)
        if isinstance(formula, And):
            return all(self.holds(part, env, state) for part in formula.parts)
        if isinstance(formula, Or):
            return any(self.holds(part, env, state) for part in formula.parts)
        if isinstance(formula, Implies):
            return not self.holds(formula.premise, env, state) or self.holds(
                formula.conclusion, env, state
            )
        if isinstance(formula, Iff):
            return self.holds(formula.left, env, state) == self.holds(formula.right, env, state)
        assignments = (
            {**env, **dict(zip(formula.variables, values))}
            for values in itertools.product(self.problem.constants, repeat=len(formula.variables))
        )
        test = all if isinstance(formula, Forall) else any
        return test(self.holds(formula.body, inner, state) for inner in assignments)


def ground_term(term: Term | Var, env: Env) -> Term:
    """``term`` with variables and parameters replaced by their values in ``env``."""
    if isinstance(term, (Var, Param)):
        return env.get(term, term)
    if type(term) is tuple:
        return (term[0], *(ground_term(arg, env) for arg in term[1:]))
    return term


def _apply(schema: OperatorSchema, binding: Env, state: State) -> State:
    """Delete every atom a delete-list pattern matches, then add the add list."""
    patterns = [ground_term(atom, binding) for atom in schema.delete_list]
    kept = {atom for atom in state if not any(_matches(p, atom) for p in patterns)}
    return frozenset(kept | {ground_term(atom, binding) for atom in schema.add_list})


def _matches(pattern: Term, term: Term) -> bool:
    """Whether a ground delete-list ``pattern``, where ``$`` matches any term, matches."""
    if pattern == WILDCARD:
        return True
    if type(pattern) is tuple:
        return (
            type(term) is tuple
            and len(term) == len(pattern)
            and term[0] == pattern[0]
            and all(_matches(p, t) for p, t in zip(pattern[1:], term[1:]))
        )
    return pattern == term


def match_pattern(pattern: Term | Var, term: Term, env: dict) -> dict | None:
    """Extend ``env`` so that ``pattern`` (with variables or parameters) equals the ground
    ``term``; ``None`` when it cannot."""
    if isinstance(pattern, (Var, Param)):
        if pattern in env:
            return env if env[pattern] == term else None
        return {**env, pattern: term}
    if type(pattern) is tuple:
        if type(term) is not tuple or len(term) != len(pattern) or term[0] != pattern[0]:
            return None
        for p, t in zip(pattern[1:], term[1:]):
            env = match_pattern(p, t, env)
            if env is None:
                return None
        return env
    return env if pattern == term else None


def body_matches(
    body: tuple[Atom, ...], facts: Mapping[tuple[str, int], set[Atom]], env: dict
) -> Iterator[dict]:
    """Every assignment of the body's variables under which all its atoms are facts."""
    if not body:
        yield env
        return
    first, rest = body[0], body[1:]
    for fact in facts.get((first[0], len(first)), ()):
        extended = match_pattern(first, fact, env)
        if extended is not None:
            yield from body_matches(rest, facts, extended)


def _horn_rule(number: int, axiom: Formula) -> _Rule:
    """The rule of a definite Horn axiom; :class:`SimulationError` for any other axiom."""
    body_formula: Formula = Truth(True)
    inner = axiom
    while isinstance(inner, Forall):
        inner = inner.body
    head_formula = inner
    if isinstance(inner, Implies):
        body_formula, head_formula = inner.premise, inner.conclusion
    try:
        body = tuple(_atoms(body_formula))
        head = tuple(_atoms(head_formula))
    except ValueError as found:
        raise SimulationError(
            f"axiom {number}, {formula_to_str(axiom)}: the simulator handles only Horn axioms "
            f"'forall x, ...: A1 & ... & An -> B1 & ... & Bm' over atoms, and this one has "
            f"{found.args[0]}"
        ) from None
    bound = {t for atom in body for t in term_variables(atom)}
    free = dict.fromkeys(v for atom in head for v in term_variables(atom) if v not in bound)
    return _Rule(body, head, tuple(free))


def _atoms(formula: Formula) -> Iterator[Atom]:
    """The atoms of a conjunction of atoms; ``ValueError`` naming anything else in it."""
    if isinstance(formula, Atomic):
        if formula.atom[0] == EQUALITY:
            raise ValueError("an equality")
        yield formula.atom
    elif isinstance(formula, And):
        for part in formula.parts:
            yield from _atoms(part)
    elif isinstance(formula, Truth) and formula.value:
        return
    else:
        kinds = {Not: "a negation", Or: "a disjunction", Exists: "an existential",
                 Forall: "a nested quantifier", Implies: "a nested implication",
                 Iff: "an equivalence", Truth: "'false'"}
        raise ValueError(kinds[type(formula)] + f" ({formula_to_str(formula)})")
