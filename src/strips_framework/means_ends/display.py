"""A search tree as HTML for notebooks (``Tree._repr_html_``): the tree as nested,
collapsible lists, each node with how it was made, its goal list and its model's
changes against M0, the solution path open and marked. For large trees and for the
scores, differences and relevant operators, the explorer page is the tool
(``strips solve --explore``, :class:`strips_framework.explore.record.SearchRecord`)."""

from __future__ import annotations

from html import escape
from typing import TYPE_CHECKING

from strips_framework.logic.formulas import formula_to_str
from strips_framework.logic.terms import atom_to_str

if TYPE_CHECKING:
    from strips_framework.means_ends.node import Node
    from strips_framework.means_ends.result import Tree

#: Nodes drawn at most (which also bounds the nesting); the rest are counted.
MAX_NODES = 300


def _node_line(node: Node, on_path: bool) -> str:
    if node.parent is None:
        how = "root"
    elif node.applied is not None:
        how = f"apply <b>{escape(str(node.applied))}</b>"
    else:
        how = f"subgoal for {escape(str(node.goals[0].operator))}"
    goals = "; ".join(
        ("G0" if g.operator is None else f"pre {g.operator}") + ": " + formula_to_str(g.formula)
        for g in node.goals
    )
    model = node.model
    changes = [f"+{atom_to_str(a)}" for a in sorted(model.additions, key=repr)]
    changes += [f"−{model.initial.clauses[i]}" for i in sorted(model.deletions)]
    mark = ' style="color:#c0392b"' if on_path else ""
    proved = "" if node.difference is None else " · first goal unproved"
    return (f"<span{mark}>n{node.id}</span> {how}{proved}<br><small>goals: <code>{escape(goals)}</code>"
            f"<br>M0 {escape(' '.join(changes) or '(unchanged)')}</small>")


def tree_html(tree: Tree) -> str:
    """The first :data:`MAX_NODES` nodes of ``tree`` as nested ``<details>`` lists."""
    path = {id(node) for node in tree.solution_path()}
    shown = tree.nodes[:MAX_NODES]
    children: dict[int, list[Node]] = {}
    roots = []
    kept = {id(node) for node in shown}
    for node in shown:
        if node.parent is not None and id(node.parent) in kept:
            children.setdefault(id(node.parent), []).append(node)
        else:
            roots.append(node)

    def item(node: Node) -> str:
        line = _node_line(node, id(node) in path)
        kids = children.get(id(node), [])
        if not kids:
            return f"<li>{line}</li>"
        opened = " open" if id(node) in path else ""
        inner = "".join(item(kid) for kid in kids)
        return f"<li><details{opened}><summary>{line}</summary><ul>{inner}</ul></details></li>"

    status = "solved" if tree.solution is not None else "no goal node"
    more = (f"<p>{len(tree.nodes) - MAX_NODES} more nodes not shown: see "
            "<code>strips solve --explore</code>.</p>") if len(tree.nodes) > MAX_NODES else ""
    body = "".join(item(root) for root in roots)
    return (f"<div><b>search tree</b>: {len(tree.nodes)} nodes, {status}"
            f"<ul style='list-style:none;padding-left:1em'>{body}</ul>{more}</div>")
