"""A PDDL task as the framework's first-order :class:`Problem`, so that means-ends
analysis and the provers run on PDDL input.

- Objects and constants become constants (unique names, as in PDDL).
- Types become unary facts ``type:NAME(o)`` (``:`` cannot occur in a PDDL name, so they
  never clash with the domain's predicates); a typed parameter or quantified variable gets
  its type atom in the precondition (or the quantifier's body), which is how a proof binds
  it to objects of the right type.
- Derived predicates become axioms ``forall x: body -> head`` the prover uses.
- Action costs are dropped: means-ends analysis does not optimize cost.
- Conditional and universal effects are refused: a STRIPS operator's add and delete lists
  are fixed, and compiling them away multiplies the operators.

The provers reason in an open world: the absence of a fact proves nothing. PDDL's closed
world is compiled in where it is used: negation is pushed down to the atoms, and a
negated atom ``(not (p a))`` becomes the atom ``not:p(a)`` of a complement predicate whose
initial facts are the type-correct tuples ``p`` lacks and which every action that adds or
deletes a ``p`` atom deletes or adds. Negated derived predicates have no such complement
(axioms only derive what holds) and are refused with a clear error; equality needs
none, unique names decide it.
"""

from __future__ import annotations

from itertools import product

from strips_framework.errors import InputError
from strips_framework.logic import formulas as logic
from strips_framework.logic.terms import Param
from strips_framework.pddl import formulas as pddl
from strips_framework.pddl.task import Action, DerivedPredicate, PddlTask, Predicate
from strips_framework.worldmodel.problem import OperatorSchema, Problem

#: Term of a translated atom: a constant, an operator parameter or a quantified variable.
Term = str | Param | logic.Var


def type_predicate(kind: str) -> str:
    return f"type:{kind}"


def complement_predicate(predicate: str) -> str:
    return f"not:{predicate}"


def to_problem(task: PddlTask) -> Problem:
    """The framework problem of ``task``; see the module docstring."""
    return _Translator(task).problem()


def _negated_predicates(formula: pddl.Formula, negated: bool = False) -> set[str]:
    """The predicates with an atom under an odd number of negations (after ``imply`` is
    read as ``or (not ...)``)."""
    if isinstance(formula, pddl.Atom):
        return {formula.predicate} if negated and formula.predicate != "=" else set()
    if isinstance(formula, pddl.Not):
        return _negated_predicates(formula.part, not negated)
    if isinstance(formula, pddl.And | pddl.Or):
        return set().union(*(_negated_predicates(p, negated) for p in formula.parts))
    if isinstance(formula, pddl.Imply):
        return _negated_predicates(formula.condition, not negated) | _negated_predicates(
            formula.consequence, negated
        )
    return _negated_predicates(formula.body, negated)


class _Translator:
    def __init__(self, task: PddlTask) -> None:
        self.task = task
        domain = task.domain
        self.derived = {rule.head.predicate for rule in domain.derived}
        formulas = [
            *(action.precondition for action in domain.actions),
            *(rule.body for rule in domain.derived),
            task.problem.goal,
        ]
        self.complemented = set().union(*(_negated_predicates(f) for f in formulas))

    def problem(self) -> Problem:
        task = self.task
        domain = task.domain
        objects = (*domain.constants, *task.problem.objects)
        kinds = sorted(kind for kind in task.objects_by_type if kind != "object")
        facts = [(atom.predicate, *atom.args) for atom in task.problem.init]
        for kind in kinds:
            facts.extend((type_predicate(kind), obj) for obj in task.objects_by_type[kind])
        primitive = {
            (pred.name, len(pred.params))
            for pred in domain.predicates
            if pred.name not in self.derived
        }
        primitive |= {(type_predicate(kind), 1) for kind in kinds}
        for pred in domain.predicates:
            if pred.name in self.complemented and pred.name not in self.derived:
                facts.extend(self._complement_facts(pred))
                primitive.add((complement_predicate(pred.name), len(pred.params)))
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

    def _complement_facts(self, predicate: Predicate) -> list[tuple]:
        """``not:p(t)`` for every type-correct tuple ``t`` with ``p(t)`` not initially true."""
        true = {atom.args for atom in self.task.problem.init if atom.predicate == predicate.name}
        domains = [self.task.objects_of(param.types) for param in predicate.params]
        name = complement_predicate(predicate.name)
        return [(name, *args) for args in product(*domains) if args not in true]

    def _operator(self, action: Action) -> OperatorSchema:
        if action.conditional:
            raise InputError(
                self.task.domain_path,
                action.line,
                None,
                f"not supported by means-ends analysis: the conditional or universal effects "
                f"of action {action.name!r} (STRIPS operators have fixed add and delete "
                "lists); use a forward search strategy",
            )
        params = {param.name: Param(param.name.lstrip("?")) for param in action.params}
        typed = [self._typed(param, params[param.name]) for param in action.params]
        body = self._formula(action.precondition, params, self.task.domain_path, action.line)
        precondition = _conjunction([*(t for t in typed if t is not None), body])
        adds = [_atom(atom, params) for atom in action.add]
        deletes = [_atom(atom, params) for atom in action.delete]
        # Complements mirror the effects; an atom both deleted and added ends up true.
        for atom in action.delete:
            if atom.predicate in self.complemented and atom not in action.add:
                adds.append(_atom(atom, params, complement_predicate(atom.predicate)))
        for atom in action.add:
            if atom.predicate in self.complemented:
                deletes.append(_atom(atom, params, complement_predicate(atom.predicate)))
        return OperatorSchema(action.name, tuple(params.values()), precondition, adds, deletes)

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
        self,
        formula: pddl.Formula,
        names: dict[str, Term],
        path: str,
        line: int | None = None,
        negated: bool = False,
    ) -> logic.Formula:
        """``formula`` (negated when ``negated``) with negation pushed down to the atoms."""

        def walk(part: pddl.Formula, flip: bool = False) -> logic.Formula:
            return self._formula(part, names, path, line, negated != flip)

        if isinstance(formula, pddl.Atom):
            return self._literal(formula, names, path, line, negated)
        if isinstance(formula, pddl.Not):
            return walk(formula.part, True)
        if isinstance(formula, pddl.Imply):
            return walk(pddl.Or((pddl.Not(formula.condition), formula.consequence)))
        if isinstance(formula, pddl.And | pddl.Or):
            parts = [walk(part) for part in formula.parts]
            if isinstance(formula, pddl.And) != negated:
                return _conjunction(parts)
            return logic.Or(parts) if parts else logic.Truth(False)
        variables = [logic.Var(param.name.lstrip("?")) for param in formula.params]
        inner = {**names, **{p.name: v for p, v in zip(formula.params, variables)}}
        typed = [self._typed(param, inner[param.name]) for param in formula.params]
        conditions = [t for t in typed if t is not None]
        body = self._formula(formula.body, inner, path, line, negated)
        if isinstance(formula, pddl.Exists) != negated:
            return logic.Exists(variables, _conjunction([*conditions, body]))
        if not conditions:
            return logic.Forall(variables, body)
        return logic.Forall(variables, logic.Implies(_conjunction(conditions), body))

    def _literal(
        self, atom: pddl.Atom, names: dict[str, Term], path: str, line: int | None, negated: bool
    ) -> logic.Formula:
        if not negated:
            return logic.Atomic(_atom(atom, names))
        if atom.predicate == "=":
            return logic.Not(logic.Atomic(_atom(atom, names)))
        if atom.predicate in self.derived:
            raise InputError(
                path,
                line,
                None,
                f"not supported by means-ends analysis: the negated derived atom {atom} "
                "(the provers' axioms derive only what holds); use a forward search strategy",
            )
        return logic.Atomic(_atom(atom, names, complement_predicate(atom.predicate)))


def _atom(atom: pddl.Atom, names: dict[str, Term], predicate: str | None = None) -> tuple:
    return (predicate or atom.predicate, *(names.get(arg, arg) for arg in atom.args))


def _conjunction(parts: list[logic.Formula]) -> logic.Formula:
    if len(parts) == 1:
        return parts[0]
    return logic.And(parts) if parts else logic.Truth(True)
