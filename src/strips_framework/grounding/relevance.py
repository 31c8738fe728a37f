"""Backward relevance: dropping the facts and operators that cannot matter to the goal.

Relaxed reachability keeps everything that *can* happen; much of it cannot help: in
rovers, say, data about objectives no goal mentions. A fact is relevant when the goal
needs it, or a relevant operator's or axiom's condition does (positively or negated). An
operator is relevant when it adds a relevant fact or deletes one that some relevant
condition needs to be false; an axiom when its head is relevant. Every plan stays a plan
once the other operators are left out of it (they add nothing anyone reads and delete
nothing a negated condition waits for), and every state that differs only in irrelevant
facts is the same state to search, as in Fast Downward's translator.
"""

from __future__ import annotations

from attrs import evolve

from strips_framework.grounding.task import GroundAxiom, GroundOperator, GroundTask


def relevant_part(task: GroundTask) -> GroundTask:
    """``task`` without its irrelevant facts, operators and axioms (facts renumbered in
    their old order)."""
    needed: set[int] = set(task.goal)  # facts some relevant condition needs true
    needed_false: set[int] = set()  # ... or false
    operators: set[int] = set()
    axioms_by_head: dict[int, list[GroundAxiom]] = {}
    for axiom in task.axioms:
        axioms_by_head.setdefault(axiom.head, []).append(axiom)
    changed = True
    while changed:
        changed = False
        for index, op in enumerate(task.operators):
            if index in operators:
                continue
            if needed.intersection(op.add) or needed_false.intersection(op.delete):
                operators.add(index)
                needed.update(op.pre)
                needed_false.update(op.pre_neg)
                changed = True
        for head, axioms in axioms_by_head.items():
            if head in needed or head in needed_false:
                for axiom in axioms:
                    if not needed.issuperset(axiom.body) or not needed_false.issuperset(
                        axiom.body_neg
                    ):
                        needed.update(axiom.body)
                        needed_false.update(axiom.body_neg)
                        changed = True
    keep = sorted(needed | needed_false)
    if len(keep) == len(task.facts) and len(operators) == len(task.operators):
        return task
    new = {old: i for i, old in enumerate(keep)}
    # Operators whose relevant effects are already among their preconditions change
    # nothing that matters any more: they go too.
    kept = [_operator(task.operators[i], new) for i in sorted(operators)]
    return GroundTask(
        name=task.name,
        facts=tuple(task.facts[old] for old in keep),
        operators=tuple(op for op in kept if not set(op.add) <= set(op.pre) or op.delete),
        init=sum(
            1 << new[fact]
            for fact in range(len(task.facts))
            if task.init >> fact & 1 and fact in new
        ),
        goal=tuple(new[fact] for fact in task.goal),
        axioms=tuple(_axiom(axiom, new) for axiom in task.axioms if axiom.head in new),
        derived=tuple(new[fact] for fact in task.derived if fact in new),
        uses_costs=task.uses_costs,
    )


def _kept(facts: tuple[int, ...], new: dict[int, int]) -> tuple[int, ...]:
    return tuple(new[fact] for fact in facts if fact in new)


def _operator(op: GroundOperator, new: dict[int, int]) -> GroundOperator:
    return GroundOperator(
        name=op.name,
        pre=_kept(op.pre, new),
        add=_kept(op.add, new),
        delete=_kept(op.delete, new),
        cost=op.cost,
        pre_neg=_kept(op.pre_neg, new),
    )


def _axiom(axiom: GroundAxiom, new: dict[int, int]) -> GroundAxiom:
    return evolve(
        axiom,
        head=new[axiom.head],
        body=_kept(axiom.body, new),
        body_neg=_kept(axiom.body_neg, new),
    )
