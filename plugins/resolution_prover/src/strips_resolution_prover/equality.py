"""Equality: literal evaluation, equality resolution and paramodulation.

Evaluation is the paper's "predicate evaluation" of ``=``: ``t = t`` is true, and under
unique names two distinct constants are distinct objects, so ``a = b`` is false and
``a != b`` true. True literals make a clause redundant, false ones are dropped. Evaluation
only sees ground equations; :func:`unique_name_instances` makes the others ground where
that makes them false (``x = a`` with ``x := b``), which is resolution with the axioms
``c != d`` that unique names stand for, so ``exists x: x != a`` follows when ``b`` is known.

Paramodulation replaces a subterm ``u`` of one clause by ``r`` when a positive literal
``l = r`` of another unifies ``l`` with ``u``. To keep it from exploding it never
rewrites from a side that is smaller, in the weight part of a Knuth-Bendix ordering,
than the other (``r`` weighs more and has every variable of ``l`` at least as often), never
rewrites from or into a variable, and with the set-of-support it only runs between the
given clause and processed clauses. The ordering is not applied to equations of the
axioms: axioms are never rewritten by each other, so an axiom's equation must be usable in
both directions on set-of-support clauses (``f(a) = b, P(f(a)) |- P(b)`` needs ``b -> f(a)``
on ``~P(b)``). Problems without ``=`` never reach this module.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Callable, Iterable, Iterator

from strips_framework.logic.clauses import Literal
from strips_framework.logic.terms import EQUALITY, SKOLEM_PREFIX, Term
from strips_framework.logic.unify import Substitution, unify
from strips_resolution_prover.inference import Limits, build, merge_bindings
from strips_resolution_prover.pclause import PClause, term_weight

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


def _variable_counts(term: Term) -> Counter[int]:
    counts: Counter[int] = Counter()
    stack = [term]
    while stack:
        t = stack.pop()
        if type(t) is int:
            counts[t] += 1
        elif type(t) is tuple:
            stack.extend(t[1:])
    return counts


def _smaller(left: Term, right: Term) -> bool:
    """Whether ``left`` is below ``right`` in every KBO with our weights."""
    if term_weight(left) >= term_weight(right):
        return False
    needed, available = _variable_counts(left), _variable_counts(right)
    return all(available[v] >= n for v, n in needed.items())


def _rewrite_sides(atom: tuple, ordered: bool) -> Iterator[tuple[Term, Term]]:
    """The ``(l, r)`` orientations of ``l = r`` that paramodulation may use."""
    left, right = atom[1], atom[2]
    if type(left) is not int and not (ordered and _smaller(left, right)):
        yield left, right
    if type(right) is not int and not (ordered and _smaller(right, left)):
        yield right, left


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
) -> Iterator[PClause]:
    """Paramodulants of ``l = r`` (with side literals ``eq_literals``) into ``target``."""
    left, right = equation
    for i, (positive, atom) in enumerate(target):
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
    given: PClause, renamed: tuple[Literal, ...], partners: list[PClause], limits: Limits
) -> Iterator[PClause]:
    """Paramodulants between the given clause (renamed apart) and each processed partner."""
    for partner in partners:
        if partner.dead:
            continue
        base = merge_bindings(given.bindings, partner.bindings)
        if base is None:
            continue
        parents = (given.id, partner.id)
        sides = ((renamed, partner.literals, True), (partner.literals, renamed, partner.sos))
        for source, target, ordered in sides:
            for i, (positive, atom) in enumerate(source):
                if not positive or not is_equality(atom):
                    continue
                rest = source[:i] + source[i + 1 :]
                for equation in _rewrite_sides(atom, ordered):
                    yield from _into(equation, rest, target, base, parents, limits)


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
