"""The check at config time that the chosen implementations fit together and fit the
problem, from what each declares (:mod:`strips_framework.capabilities`).

A strict requirement that the chosen partner does not declare is a
:class:`~strips_framework.errors.ConfigError` naming the config file and keys; a soft one,
or a partner that declares nothing, is a warning.
"""

from __future__ import annotations

import warnings
from collections.abc import Iterable
from typing import TYPE_CHECKING

from strips_framework.capabilities import (
    DEFINITE_HORN,
    EQUALITY,
    QUANTIFIED_AXIOMS,
    declared,
    requirements,
)
from strips_framework.errors import ConfigError
from strips_framework.plugin.registry import KINDS

if TYPE_CHECKING:
    from strips_framework.plugin.config import Config
    from strips_framework.plugin.registry import Registry
    from strips_framework.worldmodel.problem import Problem


def check_combination(registry: Registry, config: Config, kinds: Iterable[str]) -> None:
    """Raise :class:`ConfigError` if a chosen implementation lacks a strictly required
    capability of another; warn for soft requirements and undeclared implementations.
    Only the ``kinds`` a run uses are looked at (a forward search has no prover)."""
    chosen = {kind: registry.get(kind, config.choice(kind).name) for kind in kinds}
    for kind, registration in chosen.items():
        for need in requirements(registration.cls):
            partner = chosen.get(need.kind)
            if partner is None:
                continue
            have = declared(partner.cls, need.kind)
            if have is not None and need.capability in have:
                continue
            words = KINDS[need.kind][1]
            message = (
                f"{config.source.at(config.table_of(kind) + '.name')}: "
                f"{KINDS[kind][1]} {registration.name!r} "
                f"('{config.table_of(kind)}.name') "
                f"needs {_article(words)} {words} with {need.capability!r} ({need.reason}), "
                f"but "
                f"{words} {partner.name!r} ('{need.kind}.name') "
            )
            if have is None:
                warnings.warn(message + "declares no capabilities", stacklevel=3)
            elif need.strict:
                shown = ", ".join(sorted(have)) or "none"
                raise ConfigError(message + f"does not declare it (it declares: {shown})")
            else:
                warnings.warn(message + "does not declare it", stacklevel=3)


def check_problem(problem: Problem, registry: Registry, config: Config) -> None:
    """Raise :class:`ConfigError` if ``problem`` uses what the chosen prover does not
    declare (:func:`_problem_needs`), or if the prover answers definite Horn tasks only
    (it declares ``definite-horn`` without ``quantified-axioms``) and the problem is not
    one; warn if the prover declares nothing. Called before a search, so a prover is
    never asked what it cannot answer halfway through."""
    prover = registry.get("prover", config.choices["prover"].name)
    have = declared(prover.cls, "prover")
    shape = _ProblemShape(problem)
    where_chosen = f"prover {prover.name!r} ('prover.name' in {config.source}) "
    if have is not None and DEFINITE_HORN in have and QUANTIFIED_AXIOMS not in have and shape.beyond_horn:
        raise ConfigError(
            f"{problem.source}: the problem is not a definite Horn task ({shape.beyond_horn}), "
            f"but {where_chosen}declares {DEFINITE_HORN!r} without {QUANTIFIED_AXIOMS!r}: "
            "it answers definite Horn tasks only"
        )
    for alternatives, where in _problem_needs(shape).items():
        if have is not None and have & set(alternatives):
            continue
        wanted = " or ".join(repr(c) for c in alternatives)
        message = f"{problem.source}: the problem has {where}, which needs a prover with {wanted}, but {where_chosen}"
        if have is None:
            warnings.warn(message + "declares no capabilities", stacklevel=3)
        else:
            raise ConfigError(message + "does not declare it")


class _ProblemShape:
    """What of a problem's logic a prover's capabilities are checked against: where it
    uses equality, whether its axioms are ground facts or safe definite Horn rules, and
    where it first leaves definite Horn tasks (:mod:`strips_framework.logic.horn`).
    (The logic is imported here: a forward search on PDDL never builds one.)"""

    def __init__(self, problem: Problem) -> None:
        from strips_framework.logic.cnf import SkolemNames, clausify, negated_goal_clauses
        from strips_framework.logic.formulas import Atomic, atoms_of
        from strips_framework.logic.horn import is_conjunctive_query, is_datalog_rule
        from strips_framework.logic.terms import EQUALITY as EQUALS_SIGN

        skolem = SkolemNames()
        self.ground_facts = all(isinstance(axiom, Atomic) for axiom in problem.axioms)
        self.horn_axioms = all(
            is_datalog_rule(clause)
            for number, axiom in enumerate(problem.axioms, start=1)
            for clause in clausify(axiom, label=f"axiom {number}", skolem=skolem)
        )
        goals = [
            ("the goal", problem.goal),
            *((f"the precondition of {s.name}", s.precondition) for s in problem.operators),
        ]
        #: Why the problem is not a definite Horn task ("" when it is).
        self.beyond_horn = "" if self.horn_axioms else "its axioms are not all definite Horn rules"
        for where, goal in goals:
            if self.beyond_horn:
                break
            if not is_conjunctive_query(negated_goal_clauses(goal, skolem), problem.unique_names):
                self.beyond_horn = f"{where} is not a conjunction of atoms and inequalities"
        formulas = [*goals, *(("the axioms", axiom) for axiom in problem.axioms)]
        #: Where ``=`` is first used ("" when nowhere).
        self.equality = next(
            (where for where, f in formulas if any(atom[0] == EQUALS_SIGN for atom in atoms_of(f))), ""
        )


def _problem_needs(shape: _ProblemShape) -> dict[tuple[str, ...], str]:
    """The prover capabilities a problem needs, each as the capabilities any one of which
    will do, with where the need comes from. A definite Horn task (safe Datalog rules,
    goals that are conjunctions of atoms and, under unique names, inequalities) is
    answered by a prover declaring ``definite-horn`` as well as by one declaring
    ``quantified-axioms`` (and ``equality``, for its inequalities)."""
    horn = () if shape.beyond_horn else (DEFINITE_HORN,)
    needs = {}
    if not shape.ground_facts:
        words = "axioms that are rules (definite Horn clauses)" if horn else "axioms that are not ground facts"
        needs[(QUANTIFIED_AXIOMS, *horn)] = words
    if shape.equality:
        needs[(EQUALITY, *horn)] = f"'=' in {shape.equality}"
    return needs


def _article(words: str) -> str:
    return "an" if words[0] in "aeiou" else "a"
