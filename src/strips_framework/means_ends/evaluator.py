"""The builtin node evaluator: the evaluation function of the paper (II.B and V), as a
weighted sum of its factors.

It is the core's, not a plugin's, because it is the means-ends search's default: with
plugin autoload off (``STRIPS_DISABLE_PLUGIN_AUTOLOAD``) the core alone still solves the
paper's tasks, with the paper's node counts. The other evaluators come with
strips-evaluators."""

from __future__ import annotations

from collections.abc import Mapping
from typing import ClassVar

from strips_framework.logic.formulas import atoms_of
from strips_framework.logic.terms import EQUALITY
from strips_framework.means_ends.features import subgoals, top_goal_atoms_missing, unproved_literals
from strips_framework.means_ends.node import Node
from strips_framework.means_ends.weights import weight, weight_table
from strips_framework.options import Configurable


class PaperEvaluator(Configurable):
    """STRIPS's own node ordering: a weighted sum of the factors the paper names.

    The paper lists the factors but publishes no weights. The score of a node is::

        goal_weight       * goals on the list besides G0                    (II.B)
      + sum of the predicate weights of the atoms in those goals          (II.B)
      + difference_weight * literals in the smallest difference clause    (II.B, V)
      + cost_weight       * operators applied so far                      (V)
      + successor_weight  * successors the node has already generated
      + pending_weight    * literals left by the next relevant instance    (V)
      + top_goal_weight   * ground atoms of G0 the node's model lacks      (II.B)

    *Predicates.* Each atom of a subgoal counts ``predicate_weights[name]``, or
    ``predicate_weight`` for a predicate the table does not name, so that hard predicates
    (say ``INROOM``, which needs a door) can weigh more than easy ones (``NEXTTO``).
    Equality is not counted: with unique names it is decided by evaluation, never by an
    operator. G0 is left out of both goal terms because every node carries it.

    *Difference.* Only the smallest clause counts. It is the partial proof nearest to
    completion, and each of its literals needs an operator or a fact of a later model. The
    number of clauses is not used: it grows with the prover's effort and with the number of
    alternative partial proofs kept, which says nothing about how far the node is from a
    proof (more alternatives would even be good news). A proved first goal counts 0.

    *Top goal.* The paper's "goals left" read at the level of the task: G0's ground
    conjuncts that are not facts of the node's model. The difference term measures only
    the first goal, the next application's distance; a subgoal one step from an
    application otherwise scores the same in a model where three of four goal atoms hold
    as in M0, and the search wanders among fresh subgoals of M0 instead of finishing the
    task it has nearly done (elevators 03 of IPC 2008, with the prover's ``goal_selection
    = "fewest"``: no plan in 10,000 nodes without the term, 26 steps in 5,554 with it).
    It weighs as much as an unproved literal. On the paper's tasks it orders no node differently (a one-atom G0
    adds the same to every node until the goal node; 3-boxes' and boxes' two atoms are
    achieved on the solution path, in the order the search already took).

    *Successors.* The means-ends strategy makes one successor per expansion and re-queues
    the node; this term makes a node that already has children give way to them, which is
    where the paper's strongly depth-first search comes from. It must outweigh what a new
    subgoal adds (one goal and its predicates), or the search turns breadth-first.

    *Pending.* The estimated difficulty of the subgoal the next expansion would make: the
    size of the resolvent its relevant instance left (the strategy takes instances in
    order, so this is the first pending one). 0 when nothing is pending.

    Defaults give the depth-leaning search of the paper: applying an operator pops a goal
    and so lowers the score, a fresh subgoal (about 1 + 0.5 per predicate, 3 for a typical
    precondition) scores below its parent once the parent has paid 6 for its first child,
    and cost only breaks near-ties. An unproved literal weighs 4, more than a goal with its
    predicates, so a node whose proof is nearly complete is preferred to one that merely has
    a short goal list. These weights were chosen on the robot world: they keep the paper's
    plans and node counts on its three tasks and solve the five-part goal in
    <!-- figure: five-goals-nodes -->87<!-- /figure --> nodes. Not admissible: the weights
    are not in units of operators.
    """

    name: ClassVar[str] = "paper"
    admissible: ClassVar[bool] = False
    capabilities: ClassVar[frozenset[str]] = frozenset()

    options = (
        weight("goal_weight", 1.0, "per goal on the list besides G0"),
        weight("predicate_weight", 0.5, "per atom of those goals, unless the table names it"),
        weight_table("predicate_weights", "per atom of a predicate, by predicate name"),
        weight("difference_weight", 4.0, "per literal of the smallest difference clause"),
        weight("cost_weight", 0.5, "per operator applied so far"),
        weight("successor_weight", 6.0, "per successor the node has generated"),
        weight("pending_weight", 1.0, "per literal left by the next relevant instance"),
        weight("top_goal_weight", 4.0, "per ground atom of G0 that the node's model lacks"),
    )
    goal_weight: float
    predicate_weight: float
    predicate_weights: Mapping[str, float]
    difference_weight: float
    cost_weight: float
    successor_weight: float
    pending_weight: float
    top_goal_weight: float

    def evaluate(self, node: Node) -> float:
        return sum(self.parts(node).values())

    def parts(self, node: Node) -> dict[str, float]:
        """The weighted terms of the score, by name (the explorer page shows them)."""
        pending = len(node.pending[0].resolvent.literals) if node.pending else 0
        return {
            "goals": self.goal_weight * subgoals(node),
            "predicates": self._predicate_score(node),
            "difference": self.difference_weight * unproved_literals(node),
            "cost": self.cost_weight * node.cost,
            "successors": self.successor_weight * node.successors_generated,
            "pending": self.pending_weight * pending,
            "top goal": self.top_goal_weight * top_goal_atoms_missing(node),
        }

    def _predicate_score(self, node: Node) -> float:
        table, default = self.predicate_weights, self.predicate_weight
        return sum(
            table.get(atom[0], default)
            for goal in node.goals[:-1]
            for atom in atoms_of(goal.formula)
            if atom[0] != EQUALITY
        )
