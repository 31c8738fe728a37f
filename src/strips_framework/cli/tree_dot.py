"""The means-ends search tree as Graphviz DOT, in the spirit of the paper's Figure 1.

Each node shows its number, its world model (as M0 plus the changes made so far) and its
goal list (long preconditions wrapped, never cut); an edge into a node made by applying
an operator is labelled with it and drawn bold; the solution path is drawn in red. The
explorer page (``--explore``) shows much more: this is the static picture. A hierarchical
search (ABSTRIPS) draws the nodes of each abstraction level in a box of their own,
labelled with the level.
"""

from __future__ import annotations

import textwrap

from strips_framework.logic.formulas import formula_to_str
from strips_framework.means_ends.node import Node
from strips_framework.means_ends.result import Tree
from strips_framework.worldmodel.world import WorldModel

_MAX_GOAL_TEXT = 60


def _escape(text: str) -> str:
    return text.replace("\\", "\\\\").replace('"', '\\"')


def _goal_text(node: Node) -> str:
    """The goal list, one goal a line; a long precondition wraps onto indented lines
    (whole: a cut formula would hide the very literal a reader looks for)."""
    goals = []
    for goal in node.goals:
        text = "G0" if goal.operator is None else f"pre {goal.operator}"
        if goal.operator is not None:
            pieces = textwrap.wrap(f"{text}: {formula_to_str(goal.formula)}", _MAX_GOAL_TEXT,
                                   break_on_hyphens=False, subsequent_indent="    ")
            goals.extend(pieces)
        else:
            goals.append(text)
    return "\\l".join(_escape(g) for g in goals) + "\\l"


def search_tree_to_dot(tree: Tree, title: str = "STRIPS search tree") -> str:
    on_path = {id(node) for node in tree.solution_path()}
    lines = [
        "digraph search_tree {",
        f'  label="{_escape(title)}"; labelloc=t;',
        '  node [shape=box, fontname="Helvetica", fontsize=10];',
        '  edge [fontname="Helvetica", fontsize=9];',
    ]
    model_names: dict[WorldModel, str] = {}
    by_level: dict[int | None, list[str]] = {}
    for node in tree.nodes:
        # Models are numbered in order of appearance, as M0, M1, ... in the paper's figure.
        model = model_names.setdefault(node.model, f"M{len(model_names)}")
        label = f"n{node.id}: {model}\\l{_goal_text(node)}"
        style = ', color=red, penwidth=2' if id(node) in on_path else ""
        if node is tree.solution:
            style += ", peripheries=2"
        by_level.setdefault(node.level, []).append(f'n{node.id} [label="{label}"{style}];')
    for level, nodes in by_level.items():
        if level is None:
            lines += [f"  {line}" for line in nodes]
            continue
        lines.append(f'  subgraph cluster_level_{level} {{ label="level {level}"; style=dashed;')
        lines += [f"    {line}" for line in nodes]
        lines.append("  }")
    for node in tree.nodes:
        if node.parent is None:
            continue
        attributes = []
        if node.applied is not None:
            attributes += [f'label="{_escape(str(node.applied))}"', "style=bold"]
        if id(node) in on_path and id(node.parent) in on_path:
            attributes += ["color=red", "penwidth=2"]
        suffix = f" [{', '.join(attributes)}]" if attributes else ""
        lines.append(f"  n{node.parent.id} -> n{node.id}{suffix};")
    lines.append("}")
    return "\n".join(lines) + "\n"
