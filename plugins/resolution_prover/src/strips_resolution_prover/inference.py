"""Generating inferences: binary resolution and factoring, with the paper's parameter rules.

Every inference starts from a substitution seeded with the premises' parameter bindings
(:func:`merge_bindings`), so a parameter bound in one premise is bound in the other too and
two premises that bound it differently produce nothing. The unifier then extends it, and
:func:`build` applies it to the surviving literals, renumbers variables and records every
parameter binding in the conclusion, which is how "a binding made in one step holds for all
descendants" (paper, III.A).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator, Sequence
from functools import lru_cache
from collections.abc import Set as AbstractSet

from strips_framework.logic.clauses import Literal
from strips_framework.logic.terms import (
    ANSWER,
    Param,
    Term,
    is_ground,
    params_of,
    subterms,
    variables_of,
)
from strips_framework.logic.unify import Substitution, substitute, unify
from strips_resolution_prover.kbo import literal_greater
from strips_resolution_prover.pclause import Bindings, PClause, binding_key, term_weight

#: Offset added to the given clause's variables; processed clauses number theirs from 0, and
#: no clause has this many variables, so one renaming of the given clause serves every partner.
RENAME_OFFSET = 1 << 20


def merge_bindings(left: Bindings, right: Bindings) -> Substitution | None:
    """The substitution both premises' bindings impose, or ``None`` when they conflict."""
    subst: Substitution = dict(left)
    for param, value in right:
        if unify(param, value, subst) is None:
            return None
    return subst


def instantiate(term: Term, subst: Substitution, numbering: dict[int, int]) -> Term:
    """Apply ``subst`` and renumber the remaining variables in one pass."""
    kind = type(term)
    if kind is int or kind is Param:
        bound = subst.get(term)
        if bound is not None:
            return instantiate(bound, subst, numbering)
        if kind is Param:
            return term
        number = numbering.get(term)
        if number is None:
            number = numbering[term] = len(numbering)
        return number
    if kind is tuple:
        return (term[0], *[instantiate(arg, subst, numbering) for arg in term[1:]])
    return term


class Limits:
    """The weight bound on conclusions, and whether it ever discarded one.

    Self-resolving clauses with Skolem functions can double a term's size with every step;
    building such terms (and their occurs checks) is what makes a search hang. A conclusion
    is weighed under the substitution before it is built, in time linear in the premises.
    Once a clause was discarded, saturation no longer shows satisfiability.
    """

    __slots__ = ("discarded", "max_weight")

    def __init__(self, max_weight: int | None) -> None:
        self.max_weight = max_weight
        self.discarded = False

    def weigh(self, literals: Iterable[Literal], subst: Substitution) -> int | None:
        """The weight of ``literals``·``subst`` (``None``: over the limit, or no limit)."""
        if self.max_weight is None:
            return None
        memo: dict[object, int] = {}
        total = 0
        for _, atom in literals:
            total += _weight_under(atom, subst, memo)
            if total > self.max_weight:
                self.discarded = True
                return None
        return total


def _weight_under(term: Term, subst: Substitution, memo: dict[object, int]) -> int:
    """``term_weight(substitute(term, subst))`` without building the term."""
    kind = type(term)
    if kind is int or kind is Param:
        if term in subst:
            weight = memo.get(term)
            if weight is None:
                weight = memo[term] = _weight_under(subst[term], subst, memo)
            return weight
        return 1 if kind is int else 2
    if kind is tuple:
        return 2 + sum(_weight_under(arg, subst, memo) for arg in term[1:])
    return 2


def build(
    literals: Sequence[Literal], subst: Substitution, parents: tuple[int, ...], limits: Limits
) -> PClause | None:
    """The conclusion ``literals``·``subst``, or ``None`` for a tautology or too heavy."""
    weight = limits.weigh(literals, subst)
    if weight is None and limits.max_weight is not None:
        return None
    numbering: dict[int, int] = {}
    out: list[Literal] = []
    seen: set[Literal] = set()
    for positive, atom in literals:
        literal = (positive, instantiate(atom, subst, numbering))
        if literal in seen:
            weight = None  # a repeated literal is dropped: weigh the clause as built
            continue
        if (not positive, literal[1]) in seen:
            return None
        seen.add(literal)
        out.append(literal)
    bindings = tuple(
        sorted(
            ((key, substitute(key, subst)) for key in subst if type(key) is Param),
            key=binding_key,
        )
    )
    return PClause(tuple(out), len(numbering), bindings, sos=True, parents=parents, weight=weight)


def _clash(atom: tuple, other: tuple) -> bool:
    """Whether two atoms have different constants at the same argument position, which no
    unifier can fix; most resolution partners fail this cheap test."""
    for a, b in zip(atom, other):
        if a != b and type(a) is str and type(b) is str:
            return True
    return False


def eligible(
    literals: tuple[Literal, ...], selecting: bool, ordered: bool = False
) -> tuple[int, ...]:
    """The positions of the literals that may be resolved upon.

    Without literal selection, all of them. With it (resolution without a set of support,
    as in PyRes and E), a clause with negative literals resolves only on one of them, the
    heaviest (first on ties); a clause without any resolves on all of its literals, or
    with ``ordered`` on those not below another under the Knuth-Bendix ordering (ordered
    resolution, :func:`_maximal`). So two clauses only resolve when one of them is
    positive, and an ordered positive clause only on what may be its largest literal,
    which keeps saturation of satisfiable problems
    finite far more often and remains refutationally complete (Bachmair and Ganzinger's
    resolution with selection and ordering).
    """
    if selecting:
        best = -1
        for i, (positive, atom) in enumerate(literals):
            if not positive and (best < 0 or term_weight(atom) > term_weight(literals[best][1])):
                best = i
        if best >= 0:
            return (best,)
        if ordered:
            return _maximal(literals)
    return tuple(i for i, (_, atom) in enumerate(literals) if atom[0] != ANSWER)


@lru_cache(maxsize=1 << 16)
def _maximal(literals: tuple[Literal, ...]) -> tuple[int, ...]:
    """The positions of the literals no other literal of the clause is above in the
    literal ordering (:func:`~.kbo.literal_greater`: KBO's multiset extension, equations
    as the multisets of their sides, an atom ``A`` as ``A = TOP``). It holds under every
    substitution, so a literal left out is below another in every instance too: it
    could never be the maximal literal an ordered inference (resolution, superposition,
    paramodulation into a clause) needs. Answer literals
    (:data:`~strips_framework.logic.terms.ANSWER`) are below every other literal and
    never resolved upon, so they neither count nor are kept. Cached: a retained clause
    is a paramodulation partner of every later given clause, and the comparisons (KBO
    on multisets) cost more than hashing its literals."""
    positions = [i for i, (_, atom) in enumerate(literals) if atom[0] != ANSWER]
    if len(positions) < 2:
        return tuple(positions)
    return tuple(
        i
        for i in positions
        if not any(j != i and literal_greater(literals[j], literals[i]) for j in positions)
    )


#: The retained literals a literal may resolve with: ``(clause, position)`` pairs of the
#: opposite sign (see :class:`~strips_resolution_prover.partners.PartnerIndex`).
Partners = Callable[[Literal], Iterable[tuple[PClause, int]]]


def _unifiers(
    given: PClause, renamed: tuple[Literal, ...], i: int, partners: Partners
) -> Iterator[tuple[PClause, int, Substitution]]:
    """The partners literal ``i`` of the given clause resolves with, and each unifier."""
    atom = renamed[i][1]
    for partner, j in partners(renamed[i]):
        if partner.dead or _clash(atom, partner.literals[j][1]):
            continue
        if given.bindings or partner.bindings:
            subst = merge_bindings(given.bindings, partner.bindings)
            if subst is None:
                continue
        else:
            subst = {}
        if unify(atom, partner.literals[j][1], subst) is not None:
            yield partner, j, subst


def resolvents(
    given: PClause,
    renamed: tuple[Literal, ...],
    selected: tuple[int, ...],
    partners: Partners,
    limits: Limits,
) -> Iterator[PClause]:
    """Binary resolvents of the given clause (renamed apart) on its ``selected`` literals
    with indexed partners (which hold only their own eligible literals)."""
    for i in selected:
        rest = renamed[:i] + renamed[i + 1 :]
        for partner, j, subst in _unifiers(given, renamed, i, partners):
            others = partner.literals
            literals = rest + others[:j] + others[j + 1 :]
            clause = build(literals, subst, (given.id, partner.id), limits)
            if clause is not None:
                yield clause


def partner_count(
    given: PClause, renamed: tuple[Literal, ...], i: int, partners: Partners, offers: Offers
) -> int:
    """How many partners literal ``i`` of a goal clause (renamed apart) has (see
    :func:`_offer`)."""
    return _offer(given, renamed, i, partners, offers)[0]


def fewest_partners(
    given: PClause,
    renamed: tuple[Literal, ...],
    partners: Partners,
    shared: bool,
    rigid: AbstractSet[tuple[str, int]],
    offers: Offers,
) -> tuple[int, ...]:
    """The literals a goal clause over Horn axioms resolves on: a ground one with a
    partner if there is one (the first); else, if a variable is *unsettled*, the literals
    of ``rigid`` predicates (as ``(name, arity)``) with partners that hold one, tied at
    the fewest partners; else every literal tied at the fewest partners among those
    that have any; with ``shared`` also every literal with a partner that shares a
    variable with the first of them; none when no literal has a partner.

    Any nonempty choice keeps SLD resolution complete, so the choice only shapes the
    search. Resolving a ground literal binds nothing, so the order in which ground
    literals go changes no answer and no difference: one at a time leaves one clause
    where resolving each would make every subset of them. Which literal binds a variable
    decides what a failed proof leaves as differences. Binding it through the model's
    facts ("first fail": fewest partners first) offers the values it has now, which is
    cheap and usually enough. It is not when the model cannot settle the variable: when
    it occurs in a literal of a changeable predicate that nothing resolves
    (``leave(p, lift, f)`` with ``p`` in no lift: binding ``lift`` through
    ``lift-at(lift, f)`` offers only the lifts now at ``f``), or in two such literals
    whose partners give it no value in common (``load-airplane(obj, plane, loc)`` with
    the package and the plane in different places: the airport where they must meet may
    be neither). The partners of a rigid literal, which no operator changes, are every
    value a variable can ever take, so an unsettled variable is bound through them, and
    the difference is left with literals operators can change (the paper's
    "heuristically select some part of P"). ``shared`` lets every literal that could bind the same variable do so
    too, which keeps more alternatives at the price of more clauses. A literal nothing
    resolves is left for the difference. ``offers`` is the attempt's memo of what each
    literal's partners offer (see :func:`_offer`).
    """
    open_literals = []
    for i, (_, atom) in enumerate(renamed):
        if not is_ground(atom):
            open_literals.append(i)
        elif partner_count(given, renamed, i, partners, offers):
            return (i,)
    counts: list[tuple[int, int]] = []
    unsettled: set[object] = set()
    #: The values the changeable literals with partners leave each variable.
    offered: dict[object, frozenset[Term]] = {}
    for i in open_literals:
        atom = renamed[i][1]
        count, values_of = _offer(given, renamed, i, partners, offers)
        if count:
            counts.append((count, i))
        if (atom[0], len(atom) - 1) in rigid:
            continue
        for variable, values in zip(_open_terms(atom), values_of):
            if not count:
                unsettled.add(variable)
                continue
            known = offered.get(variable)
            offered[variable] = values if known is None else known & values
            if known is not None and not offered[variable]:
                unsettled.add(variable)
    if not counts:
        return ()
    drawn = [
        (count, i)
        for count, i in counts
        if (renamed[i][1][0], len(renamed[i][1]) - 1) in rigid and unsettled & _unbound(renamed[i][1])
    ]
    pool = drawn or counts
    fewest, first = min(pool)
    unbound = _unbound(renamed[first][1]) if shared else set()
    return tuple(
        i
        for count, i in counts
        if (count == fewest and (count, i) in pool) or unbound & _unbound(renamed[i][1])
    )


#: What an attempt has found a goal literal's partners offer, by the literal's pattern.
Offers = dict[tuple, tuple[int, tuple[frozenset[Term], ...]]]


def _offer(
    given: PClause, renamed: tuple[Literal, ...], i: int, partners: Partners, offers: Offers
) -> tuple[int, tuple[frozenset[Term], ...]]:
    """How many partners literal ``i`` has, and the values they give each of its open
    terms (:func:`_open_terms`). Over Horn axioms a goal literal's partners are the
    attempt's axioms, which do not change while it runs, so the answer depends only on the
    literal's pattern (its variables numbered in order) and is worked out once."""
    atom = renamed[i][1]
    opened = _open_terms(atom)
    numbering = {term: n for n, term in enumerate(opened) if type(term) is int}
    key = _pattern(atom, numbering)
    known = offers.get(key)
    if known is None:
        unifiers = [subst for _, _, subst in _unifiers(given, renamed, i, partners)]
        values = tuple(frozenset(substitute(term, subst) for subst in unifiers) for term in opened)
        known = (len(unifiers), values)
        offers[key] = known
    return known


def _open_terms(atom: tuple) -> list[object]:
    """The variables and unbound parameters of ``atom``, in order of first occurrence."""
    found: dict[object, None] = {}
    for arg in atom[1:]:
        for term in subterms(arg):
            if type(term) is int or type(term) is Param:
                found.setdefault(term)
    return list(found)


def _pattern(term: object, numbering: dict[object, int]) -> object:
    if type(term) is int:
        return ("?", numbering[term])
    if type(term) is tuple:
        return tuple(_pattern(arg, numbering) if n else arg for n, arg in enumerate(term))
    return term


def _unbound(atom: tuple) -> set[object]:
    """The variables and unbound parameters of ``atom``."""
    return {*variables_of(atom), *params_of(atom)}


def factors(given: PClause, limits: Limits, selecting: bool = False) -> Iterator[PClause]:
    """Factors of ``given``: two literals of the same sign and predicate unified into one.

    With literal selection only clauses without negative literals are factored: a clause
    resolves on its one selected literal, so merging others gains nothing.
    """
    literals = given.literals
    if selecting and any(not positive for positive, _ in literals):
        return
    for i, (positive, atom) in enumerate(literals):
        for j in range(i + 1, len(literals)):
            other_positive, other = literals[j]
            if other_positive is not positive or other[0] != atom[0] or len(other) != len(atom):
                continue
            if atom[0] == ANSWER:
                continue  # a disjunctive answer is kept as it is (as E does)
            subst: Substitution = dict(given.bindings)
            if unify(atom, other, subst) is None:
                continue
            clause = build(literals[:j] + literals[j + 1 :], subst, (given.id,), limits)
            if clause is not None:
                yield clause
