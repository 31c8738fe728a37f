"""Seeded random lifted PDDL tasks for the lifted heuristics' tests: types with a subtype,
a constant, static and fluent predicates, equality and inequality, negative preconditions
(static and fluent), disjunctive and existential preconditions, a derived predicate with
negation, conditional effects and action costs from a numeric function. Small enough to
ground, so the lifted values can be compared with the ground heuristics'."""

from __future__ import annotations

import random

from strips_framework.grounding import ground
from strips_framework.grounding.axioms import AxiomEvaluator
from strips_framework.pddl import PddlTask, parse_task

OBJECTS = {"a": "item", "b": "item", "c": "special", "d": "place", "e": "place"}


def _term(rng: random.Random, variables: list[str]) -> str:
    return rng.choice(variables) if rng.random() < 0.85 else "k"


def _literal(rng: random.Random, variables: list[str], negative: float) -> str:
    kind = rng.random()
    if kind < 0.1 and len(variables) > 1:
        x, y = rng.sample(variables, 2)
        return f"(= {x} {y})" if rng.random() < 0.3 else f"(not (= {x} {y}))"
    name, arity = rng.choice([("p", 1), ("q", 2), ("r", 1), ("link", 2), ("good", 1), ("d", 1)])
    atom = "(" + " ".join([name] + [_term(rng, variables) for _ in range(arity)]) + ")"
    return f"(not {atom})" if rng.random() < negative else atom


def _effect_atom(rng: random.Random, variables: list[str]) -> str:
    name, arity = rng.choice([("p", 1), ("q", 2), ("r", 1)])
    return "(" + " ".join([name] + [_term(rng, variables) for _ in range(arity)]) + ")"


def random_pddl_task(seed: int) -> PddlTask:
    rng = random.Random(seed)
    actions = []
    for index in range(rng.randint(4, 6)):
        params = ["?x", "?y", "?z"][: rng.randint(0, 3)]
        typed = " ".join(f"{p} - {rng.choice(['item', 'special', 'place', 'object'])}" for p in params)
        pre = [_literal(rng, params or ["k"], 0.25) for _ in range(rng.randint(0, 3))]
        if rng.random() < 0.2 and pre:
            pre = [f"(or {pre[0]} {_literal(rng, params or ['k'], 0.2)})"] + pre[1:]
        if rng.random() < 0.2:
            pre.append(f"(exists (?w - item) {_literal(rng, (params or []) + ['?w'], 0.1)})")
        effects = [_effect_atom(rng, params or ["k"]) for _ in range(rng.randint(1, 2))]
        effects += [f"(not {_effect_atom(rng, params or ['k'])})" for _ in range(rng.randint(0, 1))]
        if rng.random() < 0.3:
            effects.append(
                f"(forall (?v - item) (when {_literal(rng, (params or []) + ['?v'], 0.2)} "
                f"{_effect_atom(rng, (params or []) + ['?v'])}))"
            )
        cost = f"(increase (total-cost) (weight {params[0]}))" if params and rng.random() < 0.5 else (
            f"(increase (total-cost) {rng.randint(0, 2)})"
        )
        actions.append(
            f"(:action act{index} :parameters ({typed})\n"
            f" :precondition (and {' '.join(pre)})\n"
            f" :effect (and {' '.join(effects)} {cost}))"
        )
    derived = (
        "(:derived (d ?x - object) (and (r ?x) (not (p ?x))))" if rng.random() < 0.5
        else "(:derived (d ?x - object) (exists (?y - object) (and (q ?x ?y) (good ?y))))"
    )  # fmt: skip
    domain = f"""(define (domain rnd{seed})
 (:requirements :adl :derived-predicates :action-costs)
 (:types item place - object special - item)
 (:constants k - item)
 (:predicates (p ?x - object) (q ?x ?y - object) (r ?x - object) (link ?x ?y - object)
              (good ?x - object) (d ?x - object))
 (:functions (total-cost) (weight ?x - object))
 {derived}
 {chr(10).join(actions)})"""
    everything = [*OBJECTS, "k"]
    fluent = [f"(p {o})" for o in everything if rng.random() < 0.3]
    fluent += [f"(q {o} {u})" for o in everything for u in everything if rng.random() < 0.08]
    static = [f"(link {o} {u})" for o in everything for u in everything if rng.random() < 0.3]
    static += [f"(good {o})" for o in everything if rng.random() < 0.5]
    weights = [f"(= (weight {o}) {rng.randint(0, 3)})" for o in everything]
    walked = _walk(rng, domain, _problem(seed, fluent + static + weights, "(and)"))
    goal = rng.sample(walked, min(len(walked), rng.randint(1, 3))) or [_effect_atom(rng, everything)]
    if rng.random() < 0.3:
        goal.append(f"(d {rng.choice(everything)})")
    goal_text = f"(and {' '.join(goal)})"
    if rng.random() < 0.1:
        goal_text = f"(or {goal_text} (and (not (p a)) (r b)))"
    problem = _problem(seed, fluent + static + weights, goal_text)
    return parse_task(domain, problem, f"rnd{seed}-domain", f"rnd{seed}-problem")


def _problem(seed: int, init: list[str], goal: str) -> str:
    objects = " ".join(f"{name} - {kind}" for name, kind in OBJECTS.items())
    return f"""(define (problem rnd{seed}-p) (:domain rnd{seed})
 (:objects {objects})
 (:init {' '.join(init)} (= (total-cost) 0))
 (:goal {goal})
 (:metric minimize (total-cost)))"""


def _walk(rng: random.Random, domain: str, problem: str) -> list[str]:
    """The fluent atoms a random walk of a few steps makes true that did not hold
    before it (so that most goals can be reached, at varying cost)."""
    task = ground(parse_task(domain, problem), prune_irrelevant=False)
    evaluator = AxiomEvaluator(task)
    state = task.init
    for _ in range(rng.randint(2, 6)):
        applicable = [op for op in task.operators if op.applicable(state)]
        if not applicable:
            break
        state = evaluator.evaluate(rng.choice(applicable).apply(state))
    new = state & ~task.init
    return [name for i, name in enumerate(task.facts) if new >> i & 1 and not name.startswith("(@")
            and not name.startswith("(d ")]  # fmt: skip
