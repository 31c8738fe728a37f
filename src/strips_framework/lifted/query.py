"""Answering conjunctive queries over the atoms of a state: the join engine behind the
lifted search (the paper's III.A question "which instances of this precondition hold?",
asked of a database instead of a resolution prover).

Each positive atom of a query becomes a *relation* over its variables: the atoms of its
predicate that match its objects, its repeated variables and its variables' types,
projected on its variables. The relations of static predicates are built once per task;
those of the state's predicates once per state and shared by every query that asks the
same atom pattern. The query's answers are the join of the relations, filtered by its
negated atoms and inequalities as soon as their variables are bound, and projected on the
answer variables. Facts are filed in sorted order, so no answer's order, and so no
search, depends on hash order.

A successor's fact base is made from its parent's and the few atoms the action changed
(:meth:`FactBase.changed`): the lists, relations and indexes of the predicates it did not
touch are shared, those it touched are copied and updated at the changed atoms only, so
that making it costs what the action touches rather than what the state holds.

An acyclic query (a join tree exists, found by GYO reduction) is answered the Yannakakis
way: semi-joins up and down the tree first remove every tuple that takes part in no
answer, so no join step makes a tuple the next one throws away. A cyclic query is joined
greedily: the smallest relation first, then always the smallest one sharing a variable
with what is joined. Each join is a hash join on the shared variables; the hash index of
a relation is built once per relation (so once per task for a static one).
"""

from __future__ import annotations

import weakref
from bisect import bisect_left, insort
from collections.abc import Callable, Collection, Iterable, Iterator, Sequence
from collections.abc import Set as AbstractSet
from operator import itemgetter
from typing import Protocol

from strips_framework.lifted.components import GroundAtom
from strips_framework.lifted.task import Query, is_variable
from strips_framework.pddl.formulas import Atom

Row = tuple[str, ...]

#: A relation (or index) a fact base lacks is made from its parent's while at most this
#: many fact bases in a row lack it, and the relation has at least :data:`SHARED` rows
#: (atoms): fewer are matched (indexed) again at less cost than walking and updating.
CHAIN = 8
SHARED = 32


class Relation:
    """Rows over ``columns`` (variables), with hash indexes on column subsets made on
    first use."""

    __slots__ = ("columns", "rows", "_indexes", "_base", "_change", "__weakref__")

    def __init__(self, columns: tuple[str, ...], rows: list[Row]) -> None:
        self.columns = columns
        self.rows = rows
        self._indexes: dict[tuple[int, ...], dict[object, list[Row]]] = {}
        #: The relation this one was made from by :meth:`changed` (while anything
        #: else keeps it) and the rows it lost and gained since.
        self._base: weakref.ref[Relation] | None = None
        self._change: tuple[Sequence[Row], Sequence[Row]] = ((), ())

    def index(self, positions: tuple[int, ...]) -> dict[object, list[Row]]:
        """The rows by their values at ``positions`` (a single value for one position):
        the index of the relation this one was made from, updated at the changed rows,
        when that one is still alive (made there first, so that the relations made
        from one share its building), else built from the rows (also when they are
        fewer than :data:`SHARED`, or :data:`CHAIN` relations lack it)."""
        found = self._indexes.get(positions)
        if found is not None:
            return found
        chain: list[Relation] = [self]  # the relations lacking it, nearest first
        while len(chain) < CHAIN and len(chain[-1].rows) >= SHARED:
            base = chain[-1]._base() if chain[-1]._base is not None else None
            if base is None:
                break
            found = base._indexes.get(positions)
            if found is not None:
                break
            chain.append(base)
        if found is None:
            found = _indexed(chain[-1].rows, positions)
            chain.pop()._indexes[positions] = found
        for relation in reversed(chain):
            found = _index_changed(found, positions, *relation._change)
            relation._indexes[positions] = found
        return found

    def renamed(self, columns: tuple[str, ...]) -> Relation:
        """The same rows over other variables, sharing this relation's rows and indexes
        (an index built through either is built for both)."""
        view = Relation(columns, self.rows)
        view._indexes = self._indexes
        view._base = self._base
        view._change = self._change
        return view

    def changed(self, removed: Sequence[Row], added: Sequence[Row]) -> Relation:
        """This relation less the rows ``removed`` (which it holds) and with the rows
        ``added`` (which it lacks), rows and built indexes kept in their sorted filing
        order: the same relation as one matched from scratch, in time linear in the
        changes plus a copy of the rows and of the touched index buckets."""
        rows = list(self.rows)
        for row in removed:
            del rows[bisect_left(rows, row)]
        for row in added:
            insort(rows, row)
        child = Relation(self.columns, rows)
        child._base = weakref.ref(self)
        child._change = (removed, added)
        for positions, index in self._indexes.items():
            child._indexes[positions] = _index_changed(index, positions, removed, added)
        return child


def _indexed(rows: list[Row], positions: tuple[int, ...]) -> dict[object, list[Row]]:
    """``rows`` by their values at ``positions``, each bucket in the rows' order."""
    found: dict[object, list[Row]] = {}
    key = _getter(positions)
    for row in rows:
        k = key(row)
        bucket = found.get(k)
        if bucket is None:
            found[k] = [row]
        else:
            bucket.append(row)
    return found


def _index_changed(
    index: dict[object, list[Row]],
    positions: tuple[int, ...],
    removed: Sequence[Row],
    added: Sequence[Row],
) -> dict[object, list[Row]]:
    """A copy of ``index`` (on ``positions``) less the rows ``removed`` and with the rows
    ``added``, its buckets kept in filing order; the untouched buckets are shared."""
    copy = dict(index)
    key = _getter(positions)
    for row in removed:
        k = key(row)
        bucket = copy[k] = list(copy[k])
        del bucket[bisect_left(bucket, row)]
        if not bucket:
            del copy[k]
    for row in added:
        k = key(row)
        bucket = copy[k] = list(copy.get(k, ()))
        insort(bucket, row)
    return copy


def _getter(positions: Sequence[int]):  # noqa: ANN202 - itemgetter or a lambda
    """A function from a row to its values at ``positions``: a single value for one
    position, a tuple for several (``()`` for none)."""
    if not positions:
        return lambda row: ()
    return itemgetter(*positions)


class FactBase:
    """Atoms filed by predicate, with the relation of each atom pattern built on first
    use. A state's fact base sits on the task's static one, which answers for the static
    predicates (and keeps its relations for the whole search)."""

    __slots__ = (
        "atoms", "_by_predicate", "_relations", "_pending", "static", "_static_predicates",
        "_parent", "_changes", "__weakref__",
    )  # fmt: skip

    def __init__(
        self,
        atoms: Iterable[GroundAtom],
        static: FactBase | None = None,
        static_predicates: frozenset[str] = frozenset(),
    ) -> None:
        #: A set, or the state itself for a fact base made by :meth:`changed`
        #: (copied into a set when :meth:`add` first adds to it).
        self.atoms: AbstractSet[GroundAtom] = set(atoms)
        # Filed by predicate and arity (a prover's task may use a name at two arities).
        by_predicate: dict[tuple[str, int], list[GroundAtom]] = {}
        for atom in sorted(self.atoms):  # so that no answer's order depends on hashing
            key = (atom[0], len(atom))
            found = by_predicate.get(key)
            if found is None:
                by_predicate[key] = [atom]
            else:
                found.append(atom)
        self._by_predicate = by_predicate
        self._relations: dict[object, tuple[Pattern, Relation]] = {}
        #: Relations of a parent fact base (see :meth:`changed`) with the atoms of their
        #: predicate removed and added since, updated on first use.
        self._pending: dict[object, tuple[Pattern, Relation, _Change]] = {}
        self.static = static
        self._static_predicates = static_predicates
        #: The fact base this one was made from by :meth:`changed` (while anything
        #: else keeps it), and the atoms of each predicate it lost and gained since.
        self._parent: weakref.ref[FactBase] | None = None
        self._changes: dict[tuple[str, int], _Change] = {}

    def holds(self, atom: GroundAtom) -> bool:
        if self.static is not None and atom[0] in self._static_predicates:
            return atom in self.static.atoms
        return atom in self.atoms

    def add(self, atoms: Iterable[GroundAtom]) -> list[GroundAtom]:
        """Add (derived) atoms; the new ones, whose predicates' relations are rebuilt."""
        new = sorted({atom for atom in atoms if atom not in self.atoms})
        if new:
            mine = self.atoms if isinstance(self.atoms, set) else set(self.atoms)
            mine.update(new)
            self.atoms = mine
            touched = set()
            for atom in new:
                self._by_predicate.setdefault((atom[0], len(atom)), []).append(atom)
                touched.add(atom[0])
            self._relations = {k: r for k, r in self._relations.items() if k[0] not in touched}
            self._pending = {k: p for k, p in self._pending.items() if k[0] not in touched}
            self._parent = None  # (its relations lack these atoms)
        return new

    def changed(
        self,
        state: AbstractSet[GroundAtom],
        removed: Collection[GroundAtom],
        added: Collection[GroundAtom],
    ) -> FactBase:
        """The fact base of ``state``, which this one's state becomes by losing
        ``removed`` and gaining ``added`` (none of a static predicate); equal to one made
        from scratch (same filing order, same relations) when this one holds no atoms
        added by :meth:`add`. The predicates it does not touch share this one's lists and
        relations, and ``state`` itself is its atom set (not copied); the relations of
        those it touches are updated when first asked for (a child whose goal test is
        all that is asked of it updates none but the goal's)."""
        for key, (pattern, _, _) in list(self._pending.items()):  # one level of pending
            self.relation(pattern)
        child = FactBase.__new__(FactBase)
        child.atoms = state
        child.static = self.static
        child._static_predicates = self._static_predicates
        child._parent = weakref.ref(self)
        by_predicate = dict(self._by_predicate)
        touched: dict[tuple[str, int], _Change] = {}
        for atom in removed:
            touched.setdefault((atom[0], len(atom)), ([], []))[0].append(atom)
        for atom in added:
            touched.setdefault((atom[0], len(atom)), ([], []))[1].append(atom)
        for key, (out, into) in touched.items():
            atoms = list(by_predicate.get(key, ()))
            for atom in out:
                del atoms[bisect_left(atoms, atom)]
            for atom in into:
                insort(atoms, atom)
            by_predicate[key] = atoms
        child._by_predicate = by_predicate
        child._changes = touched
        relations = {}
        pending = {}
        for key, (pattern, relation) in self._relations.items():
            change = touched.get((pattern.predicate, pattern.size))
            if change is None:
                relations[key] = (pattern, relation)
            elif pattern.columns:  # (a ground atom is looked up again on demand)
                pending[key] = (pattern, relation, change)
        child._relations = relations
        child._pending = pending
        return child

    def relation(self, pattern: Pattern) -> Relation:
        """The atoms matching ``pattern`` as rows over its variables."""
        if self.static is not None and pattern.predicate in self._static_predicates:
            return self.static.relation(pattern)
        found = self._relations.get(pattern.key)
        relation = self._made(pattern) if found is None else found[1]
        return (
            relation if relation.columns == pattern.columns else relation.renamed(pattern.columns)
        )

    def _made(self, pattern: Pattern) -> Relation:
        """The relation of ``pattern``'s key (of a fluent predicate), which this fact
        base lacks, made and kept. It is the parent's updated by this one's changes
        when a parent is still alive: that parent makes its own the same way first, so
        a relation is matched against a whole state once per chain of fact bases, not
        once per state (a lazy search makes a state's first children before it asks
        for all its relations, and their siblings then share what it makes)."""
        if not pattern.columns:  # a ground atom: held or not, no scan
            relation = Relation((), [()] if pattern.ground in self.atoms else [])
            self._relations[pattern.key] = (pattern, relation)
            return relation
        chain: list[FactBase] = []  # the fact bases lacking it, nearest first
        facts: FactBase | None = self
        base: Relation | None = None
        predicate = (pattern.predicate, pattern.size)
        while facts is not None:
            found = facts._relations.get(pattern.key)
            if found is not None:
                base = found[1]
                break
            pending = facts._pending.pop(pattern.key, None)
            if pending is not None:
                base = _updated(pattern, pending[1], pending[2])
                facts._relations[pattern.key] = (pattern, base)
                break
            chain.append(facts)
            if len(chain) == CHAIN or len(facts._by_predicate.get(predicate, ())) < SHARED:
                break
            facts = facts._parent() if facts._parent is not None else None
        if base is None:
            first = chain.pop()
            base = pattern.match(first._by_predicate.get((pattern.predicate, pattern.size), ()))
            first._relations[pattern.key] = (pattern, base)
        for facts in reversed(chain):
            change = facts._changes.get((pattern.predicate, pattern.size))
            if change is not None:
                base = _updated(pattern, base, change)
            facts._relations[pattern.key] = (pattern, base)
        return base


def _updated(pattern: Pattern, relation: Relation, change: _Change) -> Relation:
    """``relation`` (of ``pattern``) after its predicate lost and gained the atoms of
    ``change``."""
    out, into = change
    removed = [row for row in map(pattern.row, out) if row is not None]
    added = [row for row in map(pattern.row, into) if row is not None]
    return relation.changed(removed, added) if removed or added else relation


#: The atoms of one predicate a state lost and gained.
_Change = tuple[list[GroundAtom], list[GroundAtom]]


class Pattern:
    """A query atom compiled for matching: the objects it needs at which positions, its
    repeated variables, its variables' domains, and which positions become the
    relation's columns (each variable's first occurrence, in order). ``key`` is the same
    for atoms that differ at most in their variables' names (same predicate, objects,
    repeats and domains), so a state matches each pattern once and keeps one relation
    for, e.g., logistics' ``(at ?truck ?loc)`` and ``(at ?truck ?from)``: one copy to
    update when a truck moves."""

    __slots__ = (
        "predicate",
        "key",
        "columns",
        "taken",
        "checks",
        "repeats",
        "typed",
        "size",
        "ground",
    )

    def __init__(self, atom: Atom, domains: dict[str, frozenset[str]]) -> None:
        self.predicate = atom.predicate
        columns: list[str] = []
        self.taken: list[int] = []
        self.checks: list[tuple[int, str]] = []  # position, object
        self.repeats: list[tuple[int, int]] = []  # position, earlier position
        self.typed: list[tuple[int, frozenset[str]]] = []
        for position, term in enumerate(atom.args, start=1):
            if not is_variable(term):
                self.checks.append((position, term))
            elif term in columns:
                self.repeats.append((position, self.taken[columns.index(term)]))
            else:
                columns.append(term)
                self.taken.append(position)
                domain = domains.get(term)
                if domain is not None:
                    self.typed.append((position, domain))
        self.columns = tuple(columns)
        shape = tuple(columns.index(t) if t in columns else t for t in atom.args)
        self.key = (atom.predicate, shape, tuple(id(domains.get(a)) for a in atom.args))
        self.size = len(atom.args) + 1
        #: The atom itself when it has no variables (its relation is a membership test).
        self.ground: GroundAtom | None = None if columns else (atom.predicate, *atom.args)

    def match(self, atoms: Sequence[GroundAtom]) -> Relation:
        candidates = atoms  # of the pattern's predicate and arity
        for position, value in self.checks:
            candidates = [a for a in candidates if a[position] == value]
        for position, earlier in self.repeats:
            candidates = [a for a in candidates if a[position] == a[earlier]]
        for position, domain in self.typed:
            candidates = [a for a in candidates if a[position] in domain]
        taken = self.taken
        if len(taken) == 1:
            only = taken[0]
            rows = [(a[only],) for a in candidates]
        elif taken:
            rows = list(map(itemgetter(*taken), candidates))
        else:
            rows = [()] if candidates else []
        return Relation(self.columns, rows)

    def row(self, atom: GroundAtom) -> Row | None:
        """The row ``atom`` (of the pattern's predicate and arity) gives, None when it
        does not match; :meth:`match` of a single atom."""
        for position, value in self.checks:
            if atom[position] != value:
                return None
        for position, earlier in self.repeats:
            if atom[position] != atom[earlier]:
                return None
        for position, domain in self.typed:
            if atom[position] not in domain:
                return None
        return tuple(atom[p] for p in self.taken)


class QueryEngine(Protocol):
    """Answers conjunctive queries over a fact base (the lifted search's prover)."""

    def answers(
        self, query: Query, facts: FactBase, seed: dict[str, str] | None = None
    ) -> list[Row]:
        """Every binding of ``query.variables`` under which the query holds in
        ``facts`` (extending ``seed``, whose variables are already bound), each once,
        in an order that does not depend on hashing."""
        ...

    def stream(self, query: Query, facts: FactBase) -> Iterator[Row]:
        """The answers of :meth:`answers` (unseeded), in the same order, as an iterator
        that finds them as they are asked for."""
        ...


class _Plan:
    """How one query is joined: the order of its relations (and, for an acyclic one,
    the join tree's edges for the semi-join passes)."""

    __slots__ = ("tree",)

    def __init__(self, tree: list[tuple[int, int]] | None) -> None:
        #: ``(child, parent)`` in GYO order (leaves first), or None for a cyclic query.
        self.tree = tree


def join_tree(edges: Sequence[frozenset[str]]) -> list[tuple[int, int]] | None:
    """The edges of a join tree of the hypergraph ``edges`` as ``(child, parent)``,
    leaves first (GYO reduction: remove an *ear*, an edge whose variables shared with
    the others all lie in one other edge, its parent); None when it is cyclic."""
    alive = list(range(len(edges)))
    tree: list[tuple[int, int]] = []
    while len(alive) > 1:
        for e in alive:
            others = [o for o in alive if o != e]
            shared = edges[e] & frozenset().union(*(edges[o] for o in others))
            parent = next((f for f in others if shared <= edges[f]), None)
            if parent is not None:
                tree.append((e, parent))
                alive.remove(e)
                break
        else:
            return None
    return tree


class JoinEngine:
    """The query engine of the module docstring. ``yannakakis`` turns the semi-join
    passes off (for measuring them); answers are the same either way."""

    def __init__(self, objects: Sequence[str], yannakakis: bool = True) -> None:
        self.objects = tuple(objects)
        self.yannakakis = yannakakis
        self._plans: dict[tuple[Query, tuple[str, ...]], _Plan] = {}
        self._patterns: dict[Query, list[Pattern]] = {}
        #: The relation of each variable bound by no positive atom, by variable and
        #: domain: the same for every state, so made (and indexed) once.
        self._ranges: dict[tuple[str, frozenset[str] | None], Relation] = {}

    def relations(
        self, query: Query, facts: FactBase, seed: dict[str, str] | None
    ) -> list[Relation] | None:
        """The relations of the query's positive atoms (and one row for ``seed``);
        None when one is empty (the query has no answer)."""
        domains = query.domains
        patterns = self._patterns.get(query)
        if patterns is None:
            patterns = self._patterns[query] = [Pattern(atom, domains) for atom in query.positive]
        relations = [facts.relation(pattern) for pattern in patterns]
        if seed:
            if any(v in domains and value not in domains[v] for v, value in seed.items()):
                return None  # an equality merged a seeded variable with one of another type
            relations.append(Relation(tuple(seed), [tuple(seed.values())]))
        for relation in relations:
            if not relation.rows:
                return None
        return relations

    def answers(
        self, query: Query, facts: FactBase, seed: dict[str, str] | None = None
    ) -> list[Row]:
        prepared = self._prepared(query, facts, seed)
        if prepared is None:
            return []
        relations, plan = prepared
        if not relations:  # no variables: only ground negated atoms and inequalities
            columns, rows = [], _Filters(query, facts).apply([], [()])
        elif plan.tree is not None:
            columns, rows = self._acyclic(relations, plan.tree, query, facts)
        else:
            columns, rows = self._join_in_order(_greedy_order(relations), query, facts)
        return _project(columns, rows, query)

    def stream(self, query: Query, facts: FactBase) -> Iterator[Row]:
        """The rows :meth:`answers` gives, in the same order, found one at a time: a
        depth-first nested-loop join over the same relations in the same order, probing
        the same (filing-ordered) indexes. The hash join extends each row in turn by
        its matches in bucket order, so its result is exactly the nested loop's order;
        the semi-join passes only take out rows that lead to no answer, which here are
        dead ends. The first answers cost what reaching them costs, not what all of
        them cost (a lazy search asks for one successor at a time)."""
        prepared = self._prepared(query, facts, None)
        if prepared is None:
            return
        relations, plan = prepared
        if not relations:
            yield from _project([], _Filters(query, facts).apply([], [()]), query)
            return
        if plan.tree is not None:
            narrowed = _narrowed(relations, plan.tree)
            if narrowed is None:
                return
            root = plan.tree[-1][1] if plan.tree else 0
            order = [narrowed[root]] + [narrowed[child] for child, _ in reversed(plan.tree)]
        else:
            order = _greedy_order(relations)
        yield from _NestedLoop(order, query, facts).rows()

    def _prepared(
        self, query: Query, facts: FactBase, seed: dict[str, str] | None
    ) -> tuple[list[Relation], _Plan] | None:
        """The query's relations, each variable no positive atom binds ranging over its
        domain, and the join plan; None when a relation is empty."""
        relations = self.relations(query, facts, seed)
        if relations is None:
            return None
        seeded = tuple(seed) if seed else ()
        bound = {c for r in relations for c in r.columns}
        for variable in query.all_variables():
            if variable not in bound:  # only in negated atoms, inequalities or answers
                domain = query.domains.get(variable)
                found = self._ranges.get((variable, domain))
                if found is None:
                    values = sorted(domain) if domain is not None else self.objects
                    found = self._ranges[(variable, domain)] = Relation(
                        (variable,), [(v,) for v in values]
                    )
                relations.append(found)
                bound.add(variable)
        plan = self._plans.get((query, seeded))
        if plan is None:
            edges = [frozenset(r.columns) for r in relations]
            plan = self._plans[(query, seeded)] = _Plan(
                join_tree(edges) if self.yannakakis else None
            )
        return relations, plan

    def _acyclic(
        self, relations: list[Relation], tree: list[tuple[int, int]], query: Query, facts: FactBase
    ) -> tuple[list[str], list[Row]]:
        rows = [r.rows for r in relations]
        columns = [r.columns for r in relations]
        for child, parent in tree:  # up: a parent keeps the rows some child row agrees with
            rows[parent] = _reduce(relations[parent], rows[parent], columns[child], rows[child])
            if not rows[parent]:
                return [], []
        for child, parent in reversed(tree):  # down
            rows[child] = _reduce(relations[child], rows[child], columns[parent], rows[parent])
        root = tree[-1][1] if tree else 0
        order = [root] + [child for child, _ in reversed(tree)]
        return self._join_in_order(
            [
                Relation(columns[i], rows[i]) if rows[i] is not relations[i].rows else relations[i]
                for i in order
            ],
            query,
            facts,
        )

    def _join_in_order(
        self, order: list[Relation], query: Query, facts: FactBase
    ) -> tuple[list[str], list[Row]]:
        filters = _Filters(query, facts)
        first = order[0]
        columns = list(first.columns)
        rows = filters.apply(columns, first.rows)
        for relation in order[1:]:
            if not rows:
                return columns, []
            shared = [c for c in relation.columns if c in columns]
            extra = [i for i, c in enumerate(relation.columns) if c not in columns]
            index = relation.index(tuple(relation.columns.index(c) for c in shared))
            key = _getter([columns.index(c) for c in shared])
            joined: list[Row] = []
            if extra:
                pick = _getter(extra) if len(extra) > 1 else None
                single = extra[0]
                for row in rows:
                    for match in index.get(key(row), ()):
                        joined.append(row + (pick(match) if pick else (match[single],)))
            else:
                joined = [row for row in rows if key(row) in index]
            columns.extend(relation.columns[i] for i in extra)
            rows = filters.apply(columns, joined)
        return columns, rows


def _greedy_order(relations: list[Relation]) -> list[Relation]:
    """The join order of a cyclic query: the smallest relation first, then always the
    smallest one sharing a variable with what is joined (any, when none does)."""
    remaining = sorted(relations, key=lambda r: len(r.rows))
    order = [remaining.pop(0)]
    known = set(order[0].columns)
    while remaining:
        connected = [r for r in remaining if known.intersection(r.columns)]
        chosen = (connected or remaining)[0]
        remaining.remove(chosen)
        order.append(chosen)
        known.update(chosen.columns)
    return order


class _NestedLoop:
    """A join order run depth-first, one answer at a time (:meth:`JoinEngine.stream`):
    each level probes its relation's index on the columns bound above it, and each of
    the query's negated atoms and inequalities is tested at the first level that binds
    all its variables, as the hash join does."""

    def __init__(self, order: list[Relation], query: Query, facts: FactBase) -> None:
        self.first = order[0].rows
        self.query = query
        columns = list(order[0].columns)
        filters = _Filters(query, facts)
        self.tests = [filters.tests(columns)]
        #: Per level below the first: the index probed, the key of a row above, and
        #: the columns a match adds (None: a semi-join level, which only tests).
        self.levels: list[tuple[dict[object, list[Row]], Callable, Callable | None]] = []
        for relation in order[1:]:
            shared = [c for c in relation.columns if c in columns]
            extra = [i for i, c in enumerate(relation.columns) if c not in columns]
            index = relation.index(tuple(relation.columns.index(c) for c in shared))
            key = _getter([columns.index(c) for c in shared])
            pick = None
            if len(extra) == 1:
                only = extra[0]
                pick = lambda match, only=only: (match[only],)
            elif extra:
                pick = _getter(extra)
            self.levels.append((index, key, pick))
            columns.extend(relation.columns[i] for i in extra)
            self.tests.append(filters.tests(columns))
        self.columns = columns

    def rows(self) -> Iterator[Row]:
        """The answers (projected on the answer variables, each once)."""
        project, unique = _projection(self.columns, self.query)
        seen: set[Row] | None = None if unique else set()
        levels, tests = self.levels, self.tests
        last = len(levels)
        iterators: list[Iterator[Row]] = [iter(self.first)] * (last + 1)
        depth = 0
        while depth >= 0:
            checks = tests[depth]
            for row in iterators[depth]:
                if checks and not all(check(row) for check in checks):
                    continue
                if depth == last:
                    answer = row if project is None else project(row)
                    if seen is not None:
                        if answer in seen:
                            continue
                        seen.add(answer)
                    yield answer
                    continue
                index, key, pick = levels[depth]
                depth += 1
                if pick is None:
                    iterators[depth] = iter((row,) if key(row) in index else ())
                else:
                    iterators[depth] = _extended(row, pick, index.get(key(row), ()))
                break
            else:
                depth -= 1


def _extended(row: Row, pick: Callable, matches: list[Row]) -> Iterator[Row]:
    for match in matches:
        yield row + pick(match)


def _reduce(
    relation: Relation, rows: list[Row], other: tuple[str, ...], other_rows: list[Row]
) -> list[Row]:
    """The semi-join of ``rows`` (``relation``'s, perhaps already reduced) with
    ``other_rows``. When the relation is unreduced and many times larger, its index on
    the shared columns is probed with the few keys of the other side, so the cost follows
    the rows kept, not the relation's size (a large state relation, e.g. every ``on``
    atom of a thousand blocks, against the one block held); the kept rows are sorted
    back into filing order."""
    if rows is relation.rows and len(other_rows) * 8 < len(rows):
        shared = [c for c in relation.columns if c in other]
        if shared:
            index = relation.index(tuple(relation.columns.index(c) for c in shared))
            theirs = _getter([other.index(c) for c in shared])
            kept = [row for key in set(map(theirs, other_rows)) for row in index.get(key, ())]
            if len(kept) == len(rows):
                return rows
            kept.sort()
            return kept
    return _semijoin(relation.columns, rows, other, other_rows)


def _narrowed(relations: list[Relation], tree: list[tuple[int, int]]) -> list[Relation] | None:
    """The relations of an acyclic query after the upward semi-join pass of
    :meth:`JoinEngine.stream`, None when it leaves a relation empty (the query has no
    answer). Two unreduced relations are first tested for a common key of their indexes
    on the shared columns (a disjointness test in C over the smaller key set, no row
    visited), so an action with no instance is refuted without a scan of its large
    relations (e.g. the trucks' ``at`` atoms against the packages' places); a relation
    is replaced by its reduced rows (in filing order) only when the other side has many
    times fewer keys, the cost following those keys; otherwise the nested loop meets
    its dead ends itself."""
    rows = [r.rows for r in relations]
    for child, parent in tree:
        ours, theirs = relations[parent], relations[child]
        if rows[parent] is ours.rows and rows[child] is theirs.rows:
            shared = [c for c in ours.columns if c in theirs.columns]
            if not shared:
                continue
            mine = ours.index(tuple(ours.columns.index(c) for c in shared))
            keys = theirs.index(tuple(theirs.columns.index(c) for c in shared)).keys()
            if mine.keys().isdisjoint(keys):
                return None
            if len(keys) * 8 < len(mine):
                rows[parent] = sorted(row for key in keys if key in mine for row in mine[key])
        else:
            rows[parent] = _reduce(ours, rows[parent], theirs.columns, rows[child])
            if not rows[parent]:
                return None
    return [
        r if rows[i] is r.rows else Relation(r.columns, rows[i]) for i, r in enumerate(relations)
    ]


def _semijoin(
    columns: tuple[str, ...], rows: list[Row], other: tuple[str, ...], other_rows: list[Row]
) -> list[Row]:
    """The rows that agree with some row of ``other_rows`` on the shared columns."""
    shared = [c for c in columns if c in other]
    if not shared:
        return rows if other_rows else []
    mine = _getter([columns.index(c) for c in shared])
    theirs = _getter([other.index(c) for c in shared])
    keys = set(map(theirs, other_rows))
    kept = [row for row in rows if mine(row) in keys]
    return rows if len(kept) == len(rows) else kept


class _Filters:
    """The query's negated atoms and inequalities, each applied once all its variables
    are bound."""

    def __init__(self, query: Query, facts: FactBase) -> None:
        self.facts = facts
        self.pending: list[tuple[str, object]] = [("neq", pair) for pair in query.distinct]
        self.pending += [("not", atom) for atom in query.negative]

    def tests(self, columns: list[str]) -> list[Callable[[Row], bool]]:
        """The filters whose variables ``columns`` now bind, as tests on one row (and
        no longer pending): the row-at-a-time form of :meth:`apply`."""
        ready = self._take_ready(columns)
        tests: list[Callable[[Row], bool]] = []
        for kind, item in ready:
            if kind == "neq":
                left, right = item  # type: ignore[misc]
                get_left, get_right = _term_getter(left, columns), _term_getter(right, columns)
                tests.append(lambda row, a=get_left, b=get_right: a(row) != b(row))
            else:
                atom: Atom = item  # type: ignore[assignment]
                getters = [_term_getter(t, columns) for t in atom.args]
                tests.append(
                    lambda row, p=atom.predicate, g=getters, holds=self.facts.holds: (
                        not holds((p, *[get(row) for get in g]))
                    )
                )
        return tests

    def _take_ready(self, columns: list[str]) -> list[tuple[str, object]]:
        ready = []
        waiting = []
        for kind, item in self.pending:
            terms = item if kind == "neq" else item.args  # type: ignore[union-attr]
            if all(not is_variable(t) or t in columns for t in terms):
                ready.append((kind, item))
            else:
                waiting.append((kind, item))
        self.pending = waiting
        return ready

    def apply(self, columns: list[str], rows: list[Row]) -> list[Row]:
        if not self.pending or not rows:
            return rows
        ready = self._take_ready(columns)
        for kind, item in ready:
            if kind == "neq":
                left, right = item  # type: ignore[misc]
                get_left = _term_getter(left, columns)
                get_right = _term_getter(right, columns)
                rows = [row for row in rows if get_left(row) != get_right(row)]
            else:
                atom: Atom = item  # type: ignore[assignment]
                holds = self.facts.holds
                getters = [_term_getter(t, columns) for t in atom.args]
                predicate = atom.predicate
                rows = [row for row in rows if not holds((predicate, *[g(row) for g in getters]))]
        return rows


def _term_getter(term: str, columns: list[str]):  # noqa: ANN202
    if is_variable(term):
        return itemgetter(columns.index(term))
    return lambda row: term


def _projection(columns: list[str], query: Query) -> tuple[Callable[[Row], Row] | None, bool]:
    """A function from a joined row (over ``columns``) to its answer (the answer
    variables' values; None when the row is its answer), and whether distinct rows give distinct answers (only a
    projection that drops a column can repeat one)."""
    picks: list[int | str] = []
    for variable in query.variables:
        term = query.same.get(variable, variable)
        picks.append(columns.index(term) if is_variable(term) else term)
    unique = len({p for p in picks if isinstance(p, int)}) == len(columns)
    if not all(isinstance(p, int) for p in picks):
        return (lambda row: tuple(row[p] if isinstance(p, int) else p for p in picks)), unique
    if picks == list(range(len(columns))):
        return None, unique
    if not picks:
        return (lambda row: ()), unique
    if len(picks) == 1:
        only = picks[0]
        return (lambda row: (row[only],)), unique  # type: ignore[index]
    return itemgetter(*picks), unique


def _project(columns: list[str], rows: list[Row], query: Query) -> list[Row]:
    """The rows as bindings of the answer variables, each once. The rows are distinct
    already (every relation's are, and so are their joins'); only a projection that
    drops a column can repeat one. Their order is the fact base's filing order, which
    does not depend on hashing."""
    if not rows:
        return []
    project, unique = _projection(columns, query)
    answers = rows if project is None else list(map(project, rows))
    return answers if unique else list(dict.fromkeys(answers))
