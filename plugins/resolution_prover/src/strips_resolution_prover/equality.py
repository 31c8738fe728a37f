"""Equality: literal evaluation, equality resolution and paramodulation.

Evaluation is the paper's "predicate evaluation" of ``=``: ``t = t`` is true, and under
unique names two distinct constants are distinct objects, so ``a = b`` is false and
``a != b`` true. True literals make a clause redundant, false ones are dropped. Evaluation
only sees ground equations; :func:`unique_name_instances` makes the others ground where
that makes them false (``x = a`` with ``x := b``), which is resolution with the axioms
``c != d`` that unique names stand for, so ``exists x: x != a`` follows when ``b`` is known.

Paramodulation replaces a subterm ``u`` of one clause by ``r`` when a positive literal
``l = r`` of another unifies ``l`` with ``u``. It never rewrites from a side that is
below the other in the Knuth-Bendix ordering (:mod:`.kbo`; the ordering is stable under
substitution, so no instance could be used that way either) and never rewrites into a
variable. Without a set of support (*saturation*) it is the superposition calculus's
rule: a variable side ``x`` of ``x = t`` rewrites too (``x`` not in ``t``), and
:func:`equality_factors` adds equality factoring; with literal selection, equality
resolution and subsumption and demodulation as simplifications, that calculus is
refutationally complete (Bachmair and Ganzinger), so a saturated clause set is
satisfiable (:mod:`.completeness`). The calculus keeps every inference superposition
makes, and more (it does not restrict inferences to maximal literals), which costs
search, not completeness. With a set of support paramodulation skips variable sides,
which would unify with every subterm of a world model, and only runs between the given
clause and processed clauses; there the ordering is not applied to equations of the
axioms: axioms are never rewritten by each other, so an axiom's equation must be usable
in both directions on set-of-support clauses (``f(a) = b, P(f(a)) |- P(b)`` needs
``b -> f(a)`` on ``~P(b)``). Problems without ``=`` never reach this module.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator

from strips_framework.logic.clauses import Literal
from strips_framework.logic.terms import EQUALITY, SKOLEM_PREFIX, Term
from strips_framework.logic.unify import Substitution, unify
from strips_resolution_prover.inference import Limits, build, eligible, merge_bindings
from strips_resolution_prover.kbo import greater
from strips_resolution_prover.pclause import PClause

Path = tuple[int, ...]


def is_equality(atom: tuple) -> bool:
    return atom[0] == EQUALITY and len(atom) == 3


def _distinct_names(left: Term, right: Term) -> bool:
    return (
        type(left) is str
        and type(right) is str
        and left != right
        and not left.startswith(SKOLEM_PREFIX)
        and not right.startswith(SKOLEM_PREFIX)
    )


def evaluate(literals: tuple[Literal, ...], unique_names: bool) -> tuple[Literal, ...] | None:
    """``literals`` without its false equalities, or ``None`` when one of them is true."""
    kept: list[Literal] = []
    for literal in literals:
        positive, atom = literal
        if is_equality(atom):
            if atom[1] == atom[2]:
                if positive:
                    return None
                continue
            if unique_names and _distinct_names(atom[1], atom[2]):
                if not positive:
                    return None
                continue
        kept.append(literal)
    return tuple(kept) if len(kept) < len(literals) else literals


def _rewrite_sides(atom: tuple, ordered: bool, variables: bool) -> Iterator[tuple[Term, Term]]:
    """The ``(l, r)`` orientations of ``l = r`` that paramodulation may use: not
    ``l < r`` when ``ordered``, and ``l`` a variable only with ``variables``."""
    left, right = atom[1], atom[2]
    for side, other in ((left, right), (right, left)):
        if type(side) is int and not variables:
            continue
        if ordered and greater(other, side):
            continue
        yield side, other


def _positions(term: Term, path: Path) -> Iterator[tuple[Path, Term]]:
    """Non-variable subterms of ``term`` with their paths (argument indexes from 1)."""
    if type(term) is int:
        return
    yield path, term
    if type(term) is tuple:
        for k in range(1, len(term)):
            yield from _positions(term[k], path + (k,))


def _replace(term: tuple, path: Path, new: Term) -> Term:
    if not path:
        return new
    k = path[0]
    return term[:k] + (_replace(term[k], path[1:], new),) + term[k + 1 :]


def _into(
    equation: tuple[Term, Term],
    eq_literals: tuple[Literal, ...],
    target: tuple[Literal, ...],
    base: Substitution,
    parents: tuple[int, ...],
    limits: Limits,
    positions: Iterable[int],
) -> Iterator[PClause]:
    """Paramodulants of ``l = r`` (with side literals ``eq_literals``) into the literals
    of ``target`` at ``positions``."""
    left, right = equation
    for i in positions:
        positive, atom = target[i]
        for k in range(1, len(atom)):
            for path, sub in _positions(atom[k], (k,)):
                subst = dict(base)
                if unify(left, sub, subst) is None:
                    continue
                rewritten = (positive, _replace(atom, path, right))
                literals = eq_literals + target[:i] + (rewritten,) + target[i + 1 :]
                clause = build(literals, subst, parents, limits)
                if clause is not None:
                    yield clause


def paramodulants(
    given: PClause,
    renamed: tuple[Literal, ...],
    partners: list[PClause],
    limits: Limits,
    *,
    saturating: bool = False,
    ordered: bool = False,
) -> Iterator[PClause]:
    """Paramodulants between the given clause (renamed apart) and each processed partner.

    ``saturating``: superposition with literal selection. Every equation is ordered, a
    clause with a selected literal (a negative one) is rewritten only in that literal,
    and variable sides rewrite from clauses without one. (Superposition needs no
    equation of a clause with a selected literal at all; the others are kept since they
    find proofs sooner, PUZ001+1 in 74 given clauses instead of 451.) With ``ordered``
    too, a clause without a selected literal rewrites, and is rewritten, only in its
    maximal literals (:func:`~.inference.eligible`), as superposition requires."""
    for partner in partners:
        if partner.dead:
            continue
        base = merge_bindings(given.bindings, partner.bindings)
        if base is None:
            continue
        parents = (given.id, partner.id)
        sides = (
            (renamed, partner.literals, True),
            (partner.literals, renamed, saturating or partner.sos),
        )
        for source, target, oriented in sides:
            # Superposition needs no equation from a clause with a selected literal;
            # taking them all but variable sides costs little and finds proofs sooner.
            variables = saturating and all(positive for positive, _ in source)
            positions = eligible(target, saturating, ordered)
            sources = eligible(source, saturating, ordered) if variables else range(len(source))
            for i in sources:
                positive, atom = source[i]
                if not positive or not is_equality(atom):
                    continue
                rest = source[:i] + source[i + 1 :]
                for equation in _rewrite_sides(atom, oriented, variables):
                    yield from _into(equation, rest, target, base, parents, limits, positions)


def equality_resolvents(given: PClause, limits: Limits) -> Iterator[PClause]:
    """From ``s != t | C`` with ``s``, ``t`` unifiable, derive ``C``·σ."""
    for i, (positive, atom) in enumerate(given.literals):
        if positive or not is_equality(atom):
            continue
        subst: Substitution = dict(given.bindings)
        if unify(atom[1], atom[2], subst) is None:
            continue
        clause = build(given.literals[:i] + given.literals[i + 1 :], subst, (given.id,), limits)
        if clause is not None:
            yield clause


def equality_factors(given: PClause, limits: Limits) -> Iterator[PClause]:
    """From ``s = t | u = v | C`` with ``s``, ``u`` unifiable, derive
    ``t != v | u = v | C``·σ (superposition's equality factoring: without it
    ``a = b | a = c`` and the like are never used as a whole, and saturation would not
    show satisfiability)."""
    literals = given.literals
    for i, (positive, atom) in enumerate(literals):
        if not positive or not is_equality(atom):
            continue
        for j, (other_positive, other) in enumerate(literals):
            if j == i or not other_positive or not is_equality(other):
                continue
            rest = literals[:i] + literals[i + 1 :]
            for s, t in ((atom[1], atom[2]), (atom[2], atom[1])):
                if greater(t, s):
                    continue
                for u, v in ((other[1], other[2]), (other[2], other[1])):
                    subst: Substitution = dict(given.bindings)
                    if unify(s, u, subst) is None:
                        continue
                    clause = build(((False, (EQUALITY, t, v)), *rest), subst, (given.id,), limits)
                    if clause is not None:
                        yield clause


def names_of(literals: Iterable[Literal]) -> tuple[str, ...]:
    """The constants (not Skolem constants) of ``literals``, in order of first occurrence."""
    found: dict[str, None] = {}
    stack: list[Term] = [arg for _, atom in literals for arg in atom[1:]]
    while stack:
        term = stack.pop()
        if type(term) is tuple:
            stack.extend(term[1:])
        elif type(term) is str and not term.startswith(SKOLEM_PREFIX):
            found[term] = None
    return tuple(sorted(found))


def unique_name_instances(
    given: PClause, names_known: Callable[[], tuple[str, ...]], limits: Limits
) -> Iterator[PClause]:
    """From ``s = t | C`` with ``s``, ``t`` variables, parameters or names, derive
    ``C``·σ for each σ mapping them to two different names (the equation is then false).
    ``names_known`` is asked only when such an equation turns up (it scans the task)."""
    for i, (positive, atom) in enumerate(given.literals):
        if not positive or not is_equality(atom):
            continue
        left, right = atom[1], atom[2]
        if type(left) is tuple or type(right) is tuple or (type(left) is str and type(right) is str):
            continue
        if any(type(side) is str and side.startswith(SKOLEM_PREFIX) for side in (left, right)):
            continue
        rest = given.literals[:i] + given.literals[i + 1 :]
        names = names_known()
        for first in names if type(left) is not str else (left,):
            for second in names if type(right) is not str else (right,):
                if first == second:
                    continue
                subst: Substitution = dict(given.bindings)
                if unify(left, first, subst) is None or unify(right, second, subst) is None:
                    continue
                clause = build(rest, subst, (given.id,), limits)
                if clause is not None:
                    yield clause
