"""What the explorer page shows of one search, recorded while it runs and turned into one
JSON document afterwards (:meth:`SearchRecord.document`).

World-model strategies keep their whole tree (``Result.tree``); the recorder adds what
the tree forgets: each score the evaluator gave a node and its parts, and the relevant
operator instances of the node when it was first queued (the strategy pops them as it
makes successors). Forward search keeps no tree: the recorder numbers nothing itself
but reads the run's state space, keeps the best h over expansions, and a bounded sample
of the states reached (the first ones, a uniform reservoir sample of the rest, the
solution path and the ancestors that connect them), decoded into facts at the end.

Strings are interned in one table (``strings``) that the nodes index: goal lists,
preconditions and model changes repeat across thousands of nodes, and the page's size
and its opening time are what the table saves.
"""

from __future__ import annotations

import math
import random
from array import array
from collections.abc import Mapping, Sequence
from typing import Any

from strips_framework.explore.watch import NO_PARENT, Watcher, finite, path_numbers

#: States of a forward search kept whole: this many first ones and as many sampled.
FIRST_STATES = 1500
SAMPLED_STATES = 1500
#: The most states (sample, path and connecting ancestors) the page draws.
MAX_STATES = 6000


class Strings:
    """An interning table: each distinct string once, referred to by its index."""

    def __init__(self) -> None:
        self.index: dict[str, int] = {}
        self.table: list[str] = []

    def __call__(self, text: str) -> int:
        found = self.index.get(text)
        if found is None:
            found = self.index[text] = len(self.table)
            self.table.append(text)
        return found

    def all(self, texts: Sequence[str]) -> list[int]:
        return [self(text) for text in texts]


class _NodeNotes:
    """What the recorder adds to one world-model node."""

    __slots__ = ("node", "scores", "relevant")

    def __init__(self, node: Any) -> None:
        self.node = node  # keeps the node alive, so its id() is not reused
        self.scores: list[tuple[float, Mapping[str, float] | None]] = []
        self.relevant = [(str(found.operator), str(found.resolvent)) for found in node.pending]


class SearchRecord(Watcher):
    """Records one search for the explorer (``--explore``); :meth:`document` gives the
    page's data once the search has finished."""

    def __init__(self, seed: int = 0) -> None:
        super().__init__()
        self.result: Any = None
        self.notes: dict[int, _NodeNotes] = {}
        self.h = array("d")
        self.curve: list[tuple[int, int, float]] = []  # (expansions, evaluations, best h)
        self.best = math.inf
        self.kept: list[int] = []
        self._random = random.Random(seed)
        self._reached = 0

    def finished(self, result: Any) -> None:
        self.result = result

    def _repr_html_(self) -> str:
        """The explorer page in a notebook, in a frame of its own."""
        from html import escape

        from strips_framework.explore.page import explorer_page

        if self.result is None:
            return "<p>no search recorded yet: pass this record to <code>Planner.create(observers=[...])</code> and run</p>"
        page = explorer_page(self.document("search"))
        return (f'<iframe srcdoc="{escape(page)}" style="width:100%;height:640px;'
                'border:1px solid #ccc"></iframe>')

    def node_scored(self, node: Any, score: float, parts: Mapping[str, float] | None) -> None:
        notes = self.notes.get(id(node))
        if notes is None:
            notes = self.notes[id(node)] = _NodeNotes(node)
        notes.scores.append((score, parts))

    def state_reached(self, number: int, parent: int, operator: int) -> None:
        self.h.append(math.nan)
        self._reached += 1
        if len(self.kept) < FIRST_STATES + SAMPLED_STATES:
            self.kept.append(number)
        elif number >= FIRST_STATES:  # reservoir sampling over the states after the first
            slot = self._random.randrange(self._reached - FIRST_STATES)
            if slot < SAMPLED_STATES:
                self.kept[FIRST_STATES + slot] = number

    def state_estimated(self, number: int, h: float, preferred: Sequence[int]) -> None:
        self.h[number] = h
        if h < self.best:
            self.best = h
            self.curve.append((self.expansions, self.evaluations, h))

    # The document.
    def document(self, title: str) -> dict[str, Any]:
        """The page's data (see docs/explore.md for its fields)."""
        if self.result is None:
            raise ValueError("the search has not finished: nothing to show yet")
        strings = Strings()
        base = {
            "title": title,
            "status": str(self.result.status),
            "plan": list(self.result.plan or ()),
            "statistics": self.result.statistics.as_dict(),
        }
        if self.result.tree is not None:
            body = _world_model(self.result.tree, self.notes, strings)
        elif self.run is not None:
            body = self._forward(strings)
        else:
            body = {"kind": "none", "nodes": []}
        return base | body | {"strings": strings.table}

    def _forward(self, strings: Strings) -> dict[str, Any]:
        space, task = self.run.space, self.task
        total = len(space)
        path = path_numbers(space, task, self.result.plan or ())
        shown = dict.fromkeys([*path, *(n for n in self.kept if n < total)])
        for number in list(shown):  # the ancestors that connect the sample to the root
            parent = space.parents[number]
            while parent != NO_PARENT and parent not in shown and len(shown) < MAX_STATES:
                shown[parent] = None
                parent = space.parents[parent]
        children = [0] * total
        for number in range(1, total):
            if space.parents[number] != NO_PARENT:
                children[space.parents[number]] += 1
        on_path = set(path)
        init = task.init
        g = _path_costs(space, shown)
        nodes = []
        for number in sorted(shown):
            state, parent = space.state(number), space.parents[number]
            nodes.append({
                "id": number,
                "parent": parent if parent in shown else None,
                "op": strings(task.operators[space.operators[number]].name) if parent != NO_PARENT else None,
                "g": g[number],
                "h": finite(self.h[number]) if not math.isnan(self.h[number]) else "-",
                "add": strings.all(_facts(task, state & ~init)),
                "del": strings.all(_facts(task, init & ~state)),
                "children": children[number],
                "path": number in on_path,
            })
        return {
            "kind": "forward",
            "init": strings.all(_facts(task, init)),
            "goal": strings.all(_facts(task, task.goal_mask)),
            "nodes": nodes,
            "curve": [[e, v, finite(h)] for e, v, h in self.curve],
            "reached": total,
            "expansions": self.expansions,
            "evaluations": self.evaluations,
        }


def _path_costs(space: Any, numbers: Any) -> dict[int, float]:
    """g of each of ``numbers`` along its final path (A* may have found a cheaper path,
    and reparented the state, after it was first reached)."""
    known: dict[int, float] = {}
    for number in numbers:
        chain = []
        while number != NO_PARENT and number not in known:
            chain.append(number)
            number = space.parents[number]
        cost = known.get(number, 0.0)
        for step in reversed(chain):
            cost += space.costs[space.operators[step]] if space.parents[step] != NO_PARENT else 0
            known[step] = cost
    return known


def _facts(task: Any, mask: int) -> list[str]:
    names, found, index = task.facts, [], 0
    while mask:
        if mask & 1:
            found.append(names[index])
        mask >>= 1
        index += 1
    return found


def _world_model(tree: Any, notes: Mapping[int, _NodeNotes], strings: Strings) -> dict[str, Any]:
    from strips_framework.logic.formulas import formula_to_str
    from strips_framework.logic.terms import atom_to_str

    on_path = {id(node) for node in tree.solution_path()}
    models: dict[Any, int] = {}
    model_rows: list[dict[str, list[int]]] = []
    differences: dict[int, int] = {}
    difference_rows: list[list[int]] = []
    nodes = []
    known = {"id", "model", "goals", "parent", "plan", "applied", "difference", "pending",
             "successors_generated"}
    for node in tree.nodes:
        model = models.get(node.model)
        if model is None:
            model = models[node.model] = len(model_rows)
            clauses = node.model.initial.clauses
            model_rows.append({
                "add": strings.all(sorted(atom_to_str(a) for a in node.model.additions)),
                "del": strings.all([str(clauses[i]) for i in sorted(node.model.deletions)]),
            })
        difference = None
        if node.difference is not None:
            difference = differences.get(id(node.difference))
            if difference is None:
                difference = differences[id(node.difference)] = len(difference_rows)
                difference_rows.append(strings.all([str(c) for c in node.difference.clauses]))
        mine = notes.get(id(node))
        row: dict[str, Any] = {
            "id": node.id,
            "parent": node.parent.id if node.parent is not None else None,
            "model": model,
            "goals": [[strings(formula_to_str(g.formula)),
                       strings(str(g.operator)) if g.operator is not None else None]
                      for g in node.goals],
            "applied": strings(str(node.applied)) if node.applied is not None else None,
            "cost": node.cost,
            "diff": difference,
            "path": id(node) in on_path,
        }
        if node.applied is not None and len(node.applied.steps()) > 1:
            row["macrop"] = strings.all([str(step) for step in node.applied.steps()])
        if mine is not None:
            row["scores"] = [[finite(score), dict(parts) if parts else None]
                             for score, parts in mine.scores]
            row["relevant"] = [[strings(op), strings(rest)] for op, rest in mine.relevant]
        extra = {name: str(value) for name, value in _fields(node).items()
                 if name not in known and value is not None}
        if extra:
            row["extra"] = extra
        nodes.append(row)
    return {"kind": "world-model", "nodes": nodes, "models": model_rows,
            "differences": difference_rows,
            "solution": tree.solution.id if tree.solution is not None else None}


def _fields(node: Any) -> dict[str, Any]:
    """A node's fields by name: any field a strategy adds (an ABSTRIPS level, say) shows
    on the page without the page knowing it. Fields are the public slots of the node's
    classes (a subclass's own first) and any instance attributes."""
    fields = {
        name: getattr(node, name)
        for cls in type(node).__mro__
        for name in cls.__dict__.get("__slots__", ())
        if not name.startswith("_") and hasattr(node, name)
    }
    fields.update(getattr(node, "__dict__", {}))
    return fields
