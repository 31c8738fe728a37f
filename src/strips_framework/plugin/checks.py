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

from strips_framework.capabilities import EQUALITY, QUANTIFIED_AXIOMS, declared, requirements
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
                f"{config.source}: {KINDS[kind][1]} {registration.name!r} "
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
    declare: axioms beyond ground facts (``quantified-axioms``) or ``=`` (``equality``);
    warn if the prover declares nothing. Called before a search, so a prover is never
    asked what it cannot answer halfway through."""
    prover = registry.get("prover", config.choices["prover"].name)
    have = declared(prover.cls, "prover")
    for capability, where in _problem_needs(problem).items():
        if have is not None and capability in have:
            continue
        message = (
            f"{problem.source}: the problem has {where}, which needs a prover with "
            f"{capability!r}, but prover {prover.name!r} ('prover.name' in {config.source}) "
        )
        if have is None:
            warnings.warn(message + "declares no capabilities", stacklevel=3)
        else:
            raise ConfigError(message + "does not declare it")


def _problem_needs(problem: Problem) -> dict[str, str]:
    """The prover capabilities a problem needs, each with where the need comes from.
    (The logic is imported here: a forward search on PDDL never calls this.)"""
    from strips_framework.logic.formulas import Atomic, atoms_of
    from strips_framework.logic.terms import EQUALITY as EQUALS_SIGN

    needs = {}
    if any(not isinstance(axiom, Atomic) for axiom in problem.axioms):
        needs[QUANTIFIED_AXIOMS] = "axioms that are not ground facts"
    formulas = [
        ("the goal", problem.goal),
        *(("the axioms", axiom) for axiom in problem.axioms),
        *((f"the precondition of {s.name}", s.precondition) for s in problem.operators),
    ]
    for where, formula in formulas:
        if any(atom[0] == EQUALS_SIGN for atom in atoms_of(formula)):
            needs[EQUALITY] = f"'=' in {where}"
            break
    return needs


def _article(words: str) -> str:
    return "an" if words[0] in "aeiou" else "a"
