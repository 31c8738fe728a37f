"""The means-ends search's bookkeeping: a node is a (world model, goal list) made once."""

from pathlib import Path

from strips_framework.formats.native import parse_problem
from strips_framework.limits import Clock, Limits
from strips_framework.means_ends.difference import UncompletedProofDifference
from strips_framework.means_ends.goal_prover import GoalProver
from strips_framework.means_ends.node import Goal, Node
from strips_framework.means_ends.relevance import AddListRelevance
from strips_framework.means_ends.run import MeansEndsRun
from strips_resolution_prover import ResolutionProver

THREE_BOXES = Path(__file__).resolve().parents[1] / "examples" / "three-boxes.strips"


class _Level:
    """Scores every node alike (the order does not matter here)."""

    name = "level"
    admissible = False

    def evaluate(self, node: Node) -> float:
        return 0.0


def test_a_model_and_goal_list_already_made_is_not_made_again():
    problem = parse_problem(THREE_BOXES.read_text(), str(THREE_BOXES))
    limits = Limits()
    prover = GoalProver(problem, ResolutionProver(), limits.effort)
    run = MeansEndsRun(8, problem, prover, UncompletedProofDifference(), AddListRelevance(),
                       _Level(), limits, Clock(limits.time))
    root, goals = prover.root_model(), (Goal(problem.goal),)
    assert run._make(root, goals, None, ()) is None  # the goal does not hold in M0
    assert len(run.tree.nodes) == 1
    assert run._make(root, goals, None, ()) is None
    assert len(run.tree.nodes) == 1  # the same problem: no second node, no second attempt
    assert prover.attempts == 1
