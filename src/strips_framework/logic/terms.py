"""Terms of the prover's language, as plain immutable Python values.

The prover's inner loops (unification, subsumption, renaming apart) touch terms millions of
times, so terms are ints, strings and tuples, which Python hashes and compares in C:

- variable:       ``int`` >= 0, local to one clause; renaming apart adds an offset.
- constant:       ``str`` such as ``"BOX1"``; Skolem constants start with ``SKOLEM_PREFIX``.
- parameter:      :class:`Param`, a schema parameter of an operator (paper, III.A).
- function term:  ``tuple`` ``(functor, *args)``; Skolem functors start with ``SKOLEM_PREFIX``.

Atoms have the shape of function terms, ``(predicate, *args)``; the predicate ``"="`` is
equality. ``ONFLOOR`` is the atom ``("ONFLOOR",)``.
"""

from __future__ import annotations

from collections.abc import Iterator

from strips_framework.records import Record

#: Skolem symbols start with this prefix; no name a user can write does (``!`` is not
#: allowed in identifiers), so Skolem terms are told apart without a lookup.
SKOLEM_PREFIX = "sk!"

EQUALITY = "="

#: The answer predicate of a TPTP question (Green's answer literals, as E's): the negated
#: question ``~F(X, Y)`` becomes ``~F(X, Y) | $answer(X, Y)``, and a clause of ``$answer``
#: literals alone is a refutation whose arguments are the answer, be they terms with
#: variables, Skolem terms or (several literals) a disjunction. No user can write it (the
#: TPTP reader refuses ``$`` symbols); a prover declaring ``answer-literals`` never
#: resolves on it. The planner binds parameters instead (paper, III.A).
ANSWER = "$answer"

#: In a delete-list atom, ``$`` matches any term: ``FACING($)`` deletes every FACING atom.
#: (A world-model notion, defined here because the formula parser reads it.)
WILDCARD = "$"


class Param(Record):
    """An operator-schema parameter such as ``m`` in ``goto(m, n)``.

    ``tag`` tells apart two instances of the same schema (or two schemata that both name a
    parameter ``m``) inside one proof; it is never shown to users. Parameters are ordered
    by name, then tag. The prover hashes and compares them in its inner loops, so the hash
    is computed once and equality is written out.
    """

    name: str
    tag: int

    FIELDS = ("name", "tag")
    __slots__ = ("name", "tag", "_hash")

    def __init__(self, name: str, tag: int = 0) -> None:
        self.name = name
        self.tag = tag
        self._hash = hash(("Param", name, tag))

    def __eq__(self, other: object) -> bool:
        return type(other) is Param and other.name == self.name and other.tag == self.tag

    def __hash__(self) -> int:
        return self._hash

    def __lt__(self, other: Param) -> bool:
        if type(other) is not Param:
            return NotImplemented
        return (self.name, self.tag) < (other.name, other.tag)

    def __le__(self, other: Param) -> bool:
        if type(other) is not Param:
            return NotImplemented
        return (self.name, self.tag) <= (other.name, other.tag)

    def __reduce__(self) -> tuple[type[Param], tuple[str, int]]:
        # Rebuilt from its fields: a string's hash differs between processes.
        return (Param, (self.name, self.tag))

    def __str__(self) -> str:
        return self.name


Term = int | str | Param | tuple
Atom = tuple  # (predicate, *args)


def subterms(term: Term) -> Iterator[Term]:
    """Yield ``term`` and every term inside it, depth first."""
    yield term
    if type(term) is tuple:
        for arg in term[1:]:
            yield from subterms(arg)


def variables_of(term: Term) -> set[int]:
    return {t for t in subterms(term) if type(t) is int}


def params_of(term: Term) -> set[Param]:
    return {t for t in subterms(term) if type(t) is Param}


def is_ground(term: Term) -> bool:
    """True when the term holds no variable and no parameter."""
    return all(type(t) is not int and type(t) is not Param for t in subterms(term))


def term_to_str(term: Term, var_names: dict[int, str] | None = None) -> str:
    """Readable ASCII text of a term, in the syntax the parsers accept."""
    if type(term) is int:
        if var_names and term in var_names:
            return var_names[term]
        return f"x{term}"
    if type(term) is str:
        return term
    if type(term) is Param:
        return term.name
    args = ", ".join(term_to_str(a, var_names) for a in term[1:])
    return f"{term[0]}({args})"


def atom_to_str(atom: Atom, var_names: dict[int, str] | None = None) -> str:
    if atom[0] == EQUALITY and len(atom) == 3:
        return f"{term_to_str(atom[1], var_names)} = {term_to_str(atom[2], var_names)}"
    if len(atom) == 1:
        return atom[0]
    return term_to_str(atom, var_names)
