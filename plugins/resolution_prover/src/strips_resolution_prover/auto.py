"""The automatic mode: which calculus a problem gets, chosen from its features.

The two configurations fail on different problems. A set of support (SOS) keeps the
search on the goal, which is what a large fact base needs: saturating a world model
would derive the consequences of every fact. Without literal selection, though, it
resolves every literal of every goal descendant, and on non-Horn axioms with Skolem
functions a thousand given clauses take seconds (KRS005-1, PUZ031-1 on the TPTP dev
set), and it can show satisfiability only over axioms known to be satisfiable and
without equality. Full saturation with literal selection (superposition with equality,
:mod:`.equality`) is complete, finds proofs that need derived facts (LCL077-1), answers
whose parameter bindings must be derived before the paper's rules let a parameter take
them (III.A: never a term with a variable), and saturates satisfiable sets.

So, from the features of the task (:func:`plan`):

- **no axioms** (every clause is support): saturation, there is nothing to keep apart;
- **a world model** (Horn axioms, each with a positive literal, at least half of them
  ground facts, and no equality in axioms or goal): the set of support on the whole
  effort. SOS is complete there (:mod:`.completeness`), it is backward chaining over the
  facts, and a session keeps M0 indexed for it (STRIPS asks thousands of such
  questions). With equality SOS is neither complete nor cheap (paramodulation into the
  axioms is unordered; ``~Q(x) | a = x`` over ``Q(f(a))`` grows ``f(f(...))`` for
  thousands of given clauses, where superposition saturates in 15);
- **otherwise**: saturation and the set of support side by side
  (:func:`~.prover.interleave`), saturation with :data:`SATURATION_SHARE` of the effort,
  as E's ``--auto-schedule`` gives strategies slices of the time. They are interleaved
  given clause by given clause, each keeping its state, rather than run one after the
  other: a problem that only the goal-directed search proves quickly (MSC002-1: 58
  given clauses, where saturation needs thousands at 4 ms each) is then found after
  about 170 given clauses instead of after saturation's whole share. The first that
  decides answers; if neither does, the goal-directed run's uncompleted proof is the
  difference. When SInE (:mod:`.axiom_relevance`) leaves axioms out, a third run saturates the
  relevant ones alone on :data:`PRUNED_SHARE` of the effort (SET018+4: 11 of 29
  clauses, proved where the whole set is not within 3,000 given clauses); only its
  refutations count, since a subset that saturates says nothing about the whole.

The run is as deterministic as each of its parts, and ``effort_used`` is their sum.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from typing import Literal


from strips_framework.logic.clauses import Clause
from strips_framework.logic.terms import EQUALITY
#: The share of the effort saturation gets when it goes first; the set of support gets
#: the rest.
SATURATION_SHARE = 2 / 3

#: The share of the effort that saturation of the relevant axioms alone gets, when
#: SInE leaves some out (:mod:`.axiom_relevance`); the other two share the rest as above.
PRUNED_SHARE = 1 / 5

Plan = Literal["saturation", "set-of-support", "schedule"]


def definite_facts(clauses: Sequence[Clause]) -> list[bool] | None:
    """Per clause, whether it is a ground fact, if every clause is definite Horn without
    equality (``None`` otherwise): the shape a world model has."""
    flags: list[bool] = []
    for clause in clauses:
        positives = 0
        for positive, atom in clause.literals:
            if atom[0] == EQUALITY:
                return None
            positives += positive
        if positives != 1:
            return None
        flags.append(len(clause.literals) == 1 and _is_ground(clause.literals[0][1]))
    return flags


def _is_ground(atom: tuple) -> bool:
    return all(type(arg) is str or (type(arg) is tuple and _is_ground(arg)) for arg in atom[1:])


def mentions_equality(clauses: Iterable[Clause]) -> bool:
    return any(atom[0] == EQUALITY for clause in clauses for _, atom in clause.literals)


def is_world_model(facts: int, clauses: int) -> bool:
    """Whether definite Horn axioms with ``facts`` ground facts among ``clauses`` are a
    world model: at least half of them facts."""
    return 2 * facts >= clauses


def plan(axioms: Sequence[Clause], negated_goal: Sequence[Clause] = ()) -> Plan:
    """The calculus the automatic mode runs on a task (see the module docstring)."""
    if not axioms:
        return "saturation"
    flags = definite_facts(axioms)
    if flags is not None and is_world_model(sum(flags), len(flags)):
        if not mentions_equality(negated_goal):
            return "set-of-support"
    return "schedule"
