"""Proof attempts with quantifiers: the fallback for models with function symbols.

With function symbols the Herbrand universe is infinite, so the clauses go to Z3 as
universally quantified formulas and its model-based quantifier instantiation decides them
(a semi-decision: ``unknown`` becomes ``GaveUp``). The same encoding serves effectively
propositional tasks too large to ground.

Answers: one check first asks whether the goal follows for *any* parameter values, with
the parameters quantified like variables; a model there shows that no instance follows
(``Satisfiable``). Otherwise the candidates are the ground terms of the task that a
parameter may be bound to, smallest first, each checked like the ground encoding does.
Those are all the answers when the task has no function symbol a parameter could be
bound through; otherwise an answer built from a term that does not occur in the task
can be missed, and exhausting the candidates is ``GaveUp``, never ``Satisfiable``.
"""

from __future__ import annotations

from collections.abc import Sequence
from itertools import product

import z3

from strips_framework.logic.clauses import Clause
from strips_framework.logic.terms import Param, Term, is_ground
from strips_framework.worldmodel.proving import GAVE_UP, PROVED, SATURATED, Answer, ProofTask
from strips_z3_prover.budget import Budget
from strips_z3_prover.encoding import Vocabulary, clause_params, is_named, task_terms
from strips_z3_prover.outcome import Outcome, status_of


def prove_quantified(
    task: ProofTask, params: Sequence[Param], budget: Budget, seed: int
) -> Outcome:
    vocabulary = Vocabulary()
    solver = z3.Solver(ctx=vocabulary.context)
    solver.set("random_seed", seed)
    clauses = (*task.axioms, *task.negated_goal)
    if task.unique_names:
        named = sorted({t for t in task_terms(clauses) if type(t) is str and is_named(t)})
        if len(named) > 1:
            solver.add(z3.Distinct([vocabulary.constant(c) for c in named]))
    axioms = [c for c in task.axioms if not clause_params(c)]
    for clause in axioms:
        solver.add(vocabulary.quantified_clause(clause, {}))
    # Axioms that mention a parameter are instantiated with the goal.
    goal = [*(c for c in task.axioms if clause_params(c)), *task.negated_goal]
    if not params:
        result = _check(solver, vocabulary, goal, {}, budget)
        return Outcome(status_of(result), ((),) if result == z3.unsat else ())
    if _check(solver, vocabulary, goal, _quantified(vocabulary, params), budget) == z3.sat:
        return Outcome(SATURATED)
    answers: list[Answer] = []
    gave_up = False
    for values in product(_candidates(clauses), repeat=len(params)):
        if len(answers) >= task.max_answers or budget.exhausted:
            gave_up = gave_up or budget.exhausted
            break
        binding = dict(zip(params, values))
        result = _check(solver, vocabulary, goal, binding, budget)
        if result == z3.unsat:
            answers.append(tuple(binding.items()))
        gave_up = gave_up or result == z3.unknown
    if answers:
        return Outcome(PROVED, tuple(answers))
    complete = not gave_up and not any(
        type(t) is tuple and is_named(t) for t in task_terms(clauses)
    )
    return Outcome(SATURATED if complete else GAVE_UP)


def _quantified(vocabulary: Vocabulary, params: Sequence[Param]) -> dict[Param, z3.ExprRef]:
    return {p: z3.Const(f"p!{p.name}!{p.tag}", vocabulary.sort) for p in params}


def _check(
    solver: z3.Solver,
    vocabulary: Vocabulary,
    goal: Sequence[Clause],
    binding: dict[Param, Term | z3.ExprRef],
    budget: Budget,
) -> z3.CheckSatResult:
    """Check the axioms with ``goal`` under ``binding``; parameters bound to Z3 constants
    are universally quantified in each clause, like its variables.

    The goal is switched on by a fresh assumption rather than pushed: Z3 preprocesses
    quantified assertions at a push, outside the resource limit, which a problem with
    54-variable clauses (TPTP's PUZ037-1) turned into a hang."""
    switch = z3.Bool(f"goal!{len(solver.assertions())}", vocabulary.context)
    for clause in goal:
        encoded = vocabulary.quantified_clause(clause, binding)
        bound = [
            binding[p] for p in sorted(clause_params(clause)) if isinstance(binding[p], z3.ExprRef)
        ]
        solver.add(z3.Implies(switch, z3.ForAll(bound, encoded) if bound else encoded))
    result = budget.check(solver, [switch])
    return result


def _candidates(clauses: Sequence[Clause]) -> list[Term]:
    """The task's ground terms free of Skolem symbols, smallest first."""
    found = {t for t in task_terms(clauses) if is_ground(t) and is_named(t)}
    return sorted(found, key=lambda t: (len(repr(t)), repr(t)))
