"""The exact values of derived predicates in a lifted state (PDDL axioms with negation as
failure), for the tests that need the real state rather than its relaxation: goal count
and the applicability of preferred operators.

Derived predicates are evaluated stratum by stratum (a predicate's stratum is above those
it uses negated, at least those it uses positively); within a stratum the rules are joined
over the facts known so far until nothing new is derived. Negated atoms belong to lower
strata or are basic, so they are final when tested.
"""

from __future__ import annotations

from strips_evaluators.lifted.exploration import Index, join
from strips_evaluators.lifted.program import Plan, RuleProgram
from strips_framework.errors import InputError
from strips_framework.lifted.components import GroundAtom


class DerivedClosure:
    """``model(state)``: the state's facts and the derived facts that hold in it."""

    def __init__(self, program: RuleProgram) -> None:
        self.program = program
        level = dict.fromkeys(program.derived, 0)
        changed = True
        while changed:
            changed = False
            for plan in program.derivations:
                head = plan.rule.heads[0][0]
                uses = [(step.predicate, 0) for step in plan.steps]
                uses += [(predicate, 1) for predicate, _ in plan.rule.negative]
                for predicate, step in uses:
                    if predicate in level and level[head] < level[predicate] + step:
                        level[head] = level[predicate] + step
                        changed = True
                if level[head] > len(level):
                    raise InputError(
                        program.source, None, None,
                        f"derived predicate {head!r} depends negatively on itself "
                        "(the axioms cannot be stratified)",
                    )
        strata: dict[int, list[Plan]] = {}
        for plan in program.derivations:
            strata.setdefault(level[plan.rule.heads[0][0]], []).append(plan)
        self.strata = [strata[key] for key in sorted(strata)]
        #: The index keys the derivations look facts up with.
        self.keys = sorted(
            {(s.predicate, s.positions) for p in program.derivations for s in p.steps if s.fluent}
        )

    def model(self, state: frozenset[GroundAtom]) -> frozenset[GroundAtom] | set[GroundAtom]:
        if not self.strata:
            return state
        facts = set(state)
        lookup: dict[tuple[str, tuple[int, ...]], Index] = {key: {} for key in self.keys}
        by_predicate: dict[str, list[tuple[tuple[int, ...], Index]]] = {}
        for (predicate, positions), index in lookup.items():
            by_predicate.setdefault(predicate, []).append((positions, index))

        def remember(fact: GroundAtom) -> None:
            for positions, index in by_predicate.get(fact[0], ()):
                index.setdefault(tuple([fact[i] for i in positions]), []).append(fact)

        for fact in state:
            remember(fact)
        for stratum in self.strata:
            while True:
                new: set[GroundAtom] = set()

                def derive(plan: Plan, slots: list, matched: list[GroundAtom]) -> None:
                    rule = plan.rule
                    for name, terms in rule.negative:
                        if (name, *[slots[s] for s in terms]) in facts:
                            return
                    for name, terms in rule.heads:
                        head = (name, *[slots[s] for s in terms])
                        if head not in facts:
                            new.add(head)

                for plan in stratum:
                    join(self.program, plan, None, lookup, derive)
                if not new:
                    break
                for fact in sorted(new):
                    facts.add(fact)
                    remember(fact)
        return facts
