"""Unification with the paper's rules for schema parameters (III.A).

A substitution is a dict from variables (ints) and parameters (:class:`Param`) to terms; it
is kept in triangular form (a bound value may itself contain bound variables) and resolved
lazily by :func:`walk`, which is what makes unification linear in practice.

What may replace what:
- a **variable** may be replaced by a variable, a constant, a parameter, or a function term
  that does not contain it (occurs check);
- a **parameter** may be replaced by a constant, another parameter, or a function term that
  contains no Skolem function, no variable and not the parameter itself.

A variable meeting a parameter is always the one bound, so parameters keep their identity
for as long as possible (the most general answer).
"""

from __future__ import annotations

from strips_framework.logic.terms import SKOLEM_PREFIX, Param, Term

Substitution = dict


def walk(term: Term, subst: Substitution) -> Term:
    """Follow bindings of a variable or parameter until an unbound one or a non-variable."""
    while (type(term) is int or type(term) is Param) and term in subst:
        term = subst[term]
    return term


def substitute(term: Term, subst: Substitution) -> Term:
    """Apply ``subst`` fully to ``term``."""
    term = walk(term, subst)
    if type(term) is tuple:
        return (term[0], *[substitute(arg, subst) for arg in term[1:]])
    return term


def _occurs(key: Term, term: Term, subst: Substitution) -> bool:
    term = walk(term, subst)
    if term == key:
        return True
    if type(term) is tuple:
        return any(_occurs(key, arg, subst) for arg in term[1:])
    return False


def _may_replace_param(param: Param, term: Term, subst: Substitution) -> bool:
    """Whether ``term`` (already walked) may be substituted for ``param`` (paper, III.A)."""
    kind = type(term)
    if kind is str:
        return not term.startswith(SKOLEM_PREFIX)
    if kind is Param:
        return True
    if kind is int:
        return False
    if term[0].startswith(SKOLEM_PREFIX):
        return False
    return all(
        walk(arg, subst) != param and _may_replace_param(param, walk(arg, subst), subst)
        for arg in term[1:]
    )


def unify(left: Term, right: Term, subst: Substitution) -> Substitution | None:
    """Extend ``subst`` (in place) so that ``left`` and ``right`` become equal.

    Returns the substitution, or ``None`` when no unifier exists; on ``None`` the dict may
    hold partial bindings, so callers pass a copy when they need the original afterwards.
    """
    stack = [(left, right)]
    while stack:
        a, b = stack.pop()
        a = walk(a, subst)
        b = walk(b, subst)
        if a == b:
            continue
        ta, tb = type(a), type(b)
        if ta is int:
            if _occurs(a, b, subst):
                return None
            subst[a] = b
        elif tb is int:
            if _occurs(b, a, subst):
                return None
            subst[b] = a
        elif ta is Param:
            if not _may_replace_param(a, b, subst):
                return None
            subst[a] = b
        elif tb is Param:
            if not _may_replace_param(b, a, subst):
                return None
            subst[b] = a
        elif ta is tuple and tb is tuple:
            if a[0] != b[0] or len(a) != len(b):
                return None
            stack.extend(zip(a[1:], b[1:]))
        else:
            return None
    return subst


def match(pattern: Term, target: Term, subst: Substitution) -> Substitution | None:
    """One-way matching: bind variables of ``pattern`` only, so that it equals ``target``.

    Used by subsumption; parameters and constants must match literally.
    """
    stack = [(pattern, target)]
    while stack:
        p, t = stack.pop()
        if type(p) is int:
            bound = subst.get(p)
            if bound is None:
                subst[p] = t
            elif bound != t:
                return None
        elif type(p) is tuple:
            if type(t) is not tuple or p[0] != t[0] or len(p) != len(t):
                return None
            stack.extend(zip(p[1:], t[1:]))
        elif p != t:
            return None
    return subst
