"""The Knuth-Bendix ordering on terms, which orients equations for demodulation.

Every symbol and variable weighs 1; symbols are ordered by arity, then name (a total
precedence, so every ground equation between different terms is oriented). ``s > t`` if
no variable occurs more often in ``t`` than in ``s``, and ``s`` weighs more, or as much
with a greater head symbol, or the same head and greater arguments from the left. A
simplification ordering: rewriting with ``l = r``, ``l > r``, always terminates.
"""

from __future__ import annotations

from collections import Counter

from strips_framework.logic.terms import Term


def _weight_and_variables(term: Term, counts: Counter[object]) -> int:
    kind = type(term)
    if kind is tuple:
        return 1 + sum(_weight_and_variables(arg, counts) for arg in term[1:])
    if kind is int:
        counts[term] += 1
    return 1


def _head(term: Term) -> tuple[int, str]:
    if type(term) is tuple:
        return len(term) - 1, term[0]
    return 0, str(term)


def greater(s: Term, t: Term) -> bool:
    """Whether ``s`` is above ``t`` in the ordering (variables and parameters are
    variables here; a parameter only equals itself, so it is ordered like a variable)."""
    if s == t or type(s) is int:
        return False
    s_vars: Counter[object] = Counter()
    t_vars: Counter[object] = Counter()
    s_weight = _weight_and_variables(s, s_vars)
    t_weight = _weight_and_variables(t, t_vars)
    if any(s_vars[v] < n for v, n in t_vars.items()):
        return False
    if s_weight != t_weight:
        return s_weight > t_weight
    if _head(s) != _head(t):
        return _head(s) > _head(t)
    if type(s) is not tuple:
        return False
    for a, b in zip(s[1:], t[1:]):
        if a != b:
            return greater(a, b)
    return False


#: The least term: the other side of a non-equational atom read as ``A = TOP``.
TOP = ""


def _multiset(literal: tuple[bool, tuple]) -> list[Term]:
    """A literal as the multiset of terms the literal ordering compares: ``s = t`` as
    ``{s, t}``, ``s != t`` as ``{s, s, t, t}``, an atom ``A`` as ``A = TOP`` (so the
    negative literal of an atom is above the positive one)."""
    positive, atom = literal
    sides = [atom[1], atom[2]] if atom[0] == "=" and len(atom) == 3 else [atom, TOP]
    return sides if positive else sides * 2


def literal_greater(first: tuple[bool, tuple], second: tuple[bool, tuple]) -> bool:
    """Whether ``first`` is above ``second`` in the literal ordering: the multiset
    extension of KBO on :func:`_multiset` (every term ``second`` has more of is below
    one that ``first`` has more of). Like KBO it holds under every substitution, so a
    literal below another is below it in every instance."""
    left, right = _multiset(first), _multiset(second)
    for term in list(left):
        if term in right:
            right.remove(term)
            left.remove(term)
    if not left:
        return False
    return all(any(_above(m, n) for m in left) for n in right)


def _above(m: Term, n: Term) -> bool:
    if n == TOP:
        return m != TOP
    return m != TOP and greater(m, n)
