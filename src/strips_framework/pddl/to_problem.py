"""A PDDL task as the framework's first-order :class:`Problem`, so that means-ends
analysis and the provers run on PDDL input.

- Objects and constants become constants (unique names, as in PDDL).
- Types become unary facts ``type:NAME(o)`` (``:`` cannot occur in a PDDL name, so they
  never clash with the domain's predicates); a typed parameter or quantified variable gets
  its type atom in the precondition (or the quantifier's body), which is how a proof binds
  it to objects of the right type.
- Derived predicates become axioms ``forall x: body -> head`` the prover uses.
- Action costs are dropped: means-ends analysis does not optimize cost.

The provers reason in an open world: a negated atom is proved only from axioms, never
from the absence of a fact. So negative literals over predicates (other than equality,
which unique names decide) are rejected with a clear error rather than searched for in
vain.
"""

from __future__ import annotations

from strips_framework.errors import InputError
from strips_framework.logic import formulas as logic
from strips_framework.logic.terms import Param
from strips_framework.pddl import formulas as pddl
from strips_framework.pddl.task import Action, DerivedPredicate, PddlTask
from strips_framework.problem import OperatorSchema, Problem

#: Term of a translated atom: a constant, an operator parameter or a quantified variable.
Term = str | Param | logic.Var


def type_predicate(kind: str) -> str:
    return f"type:{kind}"


def to_problem(task: PddlTask) -> Problem:
    """The framework problem of ``task``; see the module docstring."""
    return _Translator(task).problem()


class _Translator:
    def __init__(self, task: PddlTask) -> None:
        self.task = task

    def problem(self) -> Problem:
        task = self.task
        domain = task.domain
        objects = (*domain.constants, *task.problem.objects)
        kinds = sorted(kind for kind in task.objects_by_type if kind != "object")
        facts = [(atom.predicate, *atom.args) for atom in task.problem.init]
        for kind in kinds:
            facts.extend((type_predicate(kind), obj) for obj in task.objects_by_type[kind])
        derived = {rule.head.predicate for rule in domain.derived}
        primitive = {(pred.name, len(pred.params)) for pred in domain.predicates}
        primitive = {pair for pair in primitive if pair[0] not in derived}
        primitive |= {(type_predicate(kind), 1) for kind in kinds}
        operators = [self._operator(action) for action in domain.actions]
        axioms = [self._axiom(rule) for rule in domain.derived]
        goal = self._formula(task.problem.goal, {}, task.problem_path)
        return Problem(
            name=task.name,
            constants=tuple(obj.name for obj in objects),
            primitive_predicates=frozenset(primitive),
            facts=tuple(dict.fromkeys(facts)),
            axioms=tuple(axioms),
            derived=(),
            operators=tuple(operators),
            goal=goal,
            unique_names=True,
            source=task.problem_path,
        )

    def _operator(self, action: Action) -> OperatorSchema:
        params = {param.name: Param(param.name.lstrip("?")) for param in action.params}
        typed = [self._typed(param, params[param.name]) for param in action.params]
        body = self._formula(action.precondition, params, self.task.domain_path, action.line)
        precondition = _conjunction([*(t for t in typed if t is not None), body])
        return OperatorSchema(
            action.name,
            tuple(params.values()),
            precondition,
            tuple(_atom(atom, params) for atom in action.add),
            tuple(_atom(atom, params) for atom in action.delete),
        )

    def _axiom(self, rule: DerivedPredicate) -> logic.Formula:
        names = {param.name: logic.Var(param.name.lstrip("?")) for param in rule.params}
        typed = [self._typed(param, names[param.name]) for param in rule.params]
        body = self._formula(rule.body, names, self.task.domain_path)
        premise = _conjunction([*(t for t in typed if t is not None), body])
        implication = logic.Implies(premise, logic.Atomic(_atom(rule.head, names)))
        return logic.Forall(tuple(names.values()), implication) if names else implication

    def _typed(self, param: pddl.Parameter, term: Term) -> logic.Formula | None:
        """The type condition of ``param`` (none for ``object``)."""
        if "object" in param.types:
            return None
        options = [logic.Atomic((type_predicate(kind), term)) for kind in param.types]
        return options[0] if len(options) == 1 else logic.Or(options)

    def _formula(
        self, formula: pddl.Formula, names: dict[str, Term], path: str, line: int | None = None
    ) -> logic.Formula:
        if isinstance(formula, pddl.Atom):
            return logic.Atomic(_atom(formula, names))
        if isinstance(formula, pddl.Not):
            part = formula.part
            if isinstance(part, pddl.Atom) and part.predicate != "=":
                raise InputError(
                    path,
                    line,
                    None,
                    f"not supported by means-ends analysis: the negated atom {part} (the "
                    "provers reason in an open world); use a forward search strategy",
                )
            return logic.Not(self._formula(part, names, path, line))
        if isinstance(formula, pddl.And):
            return _conjunction([self._formula(p, names, path, line) for p in formula.parts])
        if isinstance(formula, pddl.Or):
            return logic.Or([self._formula(p, names, path, line) for p in formula.parts])
        if isinstance(formula, pddl.Imply):
            return logic.Implies(
                self._formula(formula.condition, names, path, line),
                self._formula(formula.consequence, names, path, line),
            )
        variables = [logic.Var(param.name.lstrip("?")) for param in formula.params]
        inner = {**names, **{p.name: v for p, v in zip(formula.params, variables)}}
        typed = [self._typed(param, inner[param.name]) for param in formula.params]
        conditions = [t for t in typed if t is not None]
        body = self._formula(formula.body, inner, path, line)
        if isinstance(formula, pddl.Exists):
            return logic.Exists(variables, _conjunction([*conditions, body]))
        premise = _conjunction(conditions)
        return logic.Forall(variables, logic.Implies(premise, body) if conditions else body)


def _atom(atom: pddl.Atom, names: dict[str, Term]) -> tuple:
    return (atom.predicate, *(names.get(arg, arg) for arg in atom.args))


def _conjunction(parts: list[logic.Formula]) -> logic.Formula:
    if len(parts) == 1:
        return parts[0]
    return logic.And(parts) if parts else logic.Truth(True)
