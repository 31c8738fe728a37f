"""The goal agenda (means_ends/goal_order.py): reasonable orders between G0's atoms,
computed lifted from the operators and M0, and means-ends achieving them in turn."""

from pathlib import Path

from strips_framework.logic.formulas import conjuncts
from strips_framework.means_ends.goal_order import agenda_layers, goal_agenda
from strips_framework.pddl import to_problem
from strips_framework.worldmodel.simulate import replay

DATA = Path(__file__).parent / "pddl" / "data"

# A depot-like domain: a hoist lifts a crate off a surface (it must be clear) and drops
# it on a clear surface, or loads it into a truck and unloads it: ``lifting`` has two
# achievers, but the first one from M0 is ``lift`` (``in`` needs ``lifting`` first).
DEPOT = """
(define (domain depot-like)
  (:predicates (on ?c ?s) (clear ?s) (lifting ?h ?c) (available ?h) (in ?c ?t)
              (truck ?t) (hoist ?h))
  (:action lift :parameters (?h ?c ?s)
    :precondition (and (hoist ?h) (available ?h) (on ?c ?s) (clear ?c))
    :effect (and (lifting ?h ?c) (clear ?s) (not (available ?h)) (not (clear ?c))
                 (not (on ?c ?s))))
  (:action drop :parameters (?h ?c ?s)
    :precondition (and (hoist ?h) (lifting ?h ?c) (clear ?s))
    :effect (and (available ?h) (on ?c ?s) (clear ?c) (not (lifting ?h ?c))
                 (not (clear ?s))))
  (:action load :parameters (?h ?c ?t)
    :precondition (and (hoist ?h) (lifting ?h ?c) (truck ?t))
    :effect (and (in ?c ?t) (available ?h) (not (lifting ?h ?c))))
  (:action unload :parameters (?h ?c ?t)
    :precondition (and (hoist ?h) (available ?h) (in ?c ?t))
    :effect (and (lifting ?h ?c) (not (in ?c ?t)) (not (available ?h)))))
"""

# c2 sits on c1; the goal stacks c1 on c3 on p (written top first).
DEPOT_TASK = """
(define (problem stack) (:domain depot-like)
  (:objects h c1 c2 c3 p q t)
  (:init (hoist h) (truck t) (available h) (on c1 q) (on c2 c1) (clear c2) (on c3 p) (clear c3))
  (:goal (and (on c2 c1) (on c1 c3) (on c3 p))))
"""

BLOCKS_TOWER = """
(define (problem tower) (:domain BLOCKS)
  (:objects a b c d - block)
  (:init (CLEAR a) (ONTABLE a) (CLEAR b) (ONTABLE b) (CLEAR c) (ONTABLE c)
         (CLEAR d) (ONTABLE d) (HANDEMPTY))
  (:goal (and (ON a b) (ON b c) (ON c d))))
"""


def _layers(problem):
    goals = [part.atom for part in conjuncts(problem.goal)]
    return agenda_layers(goals, problem.operators, frozenset(problem.facts))


def test_blocks_towers_are_built_from_the_bottom(write_task):
    problem = to_problem(write_task((DATA / "blocks-domain.pddl").read_text(), BLOCKS_TOWER))
    assert _layers(problem) == [[("on", "c", "d")], [("on", "b", "c")], [("on", "a", "b")]]
    agenda = goal_agenda(problem)
    assert [len(list(conjuncts(entry))) for entry in agenda] == [1, 2, 3]
    assert agenda[-1] == problem.goal


def test_the_agenda_adds_one_atom_at_a_time(write_task):
    """A layer of several atoms is entered one atom at a time, in G0's order: the first
    layer here is the base of the tower and the unordered pair, so the entries grow
    1, 2, 3 (a layer at once would make 2, 3)."""
    task = """
    (define (problem two) (:domain BLOCKS) (:objects a b c d e - block)
      (:init (CLEAR a) (ONTABLE a) (CLEAR b) (ONTABLE b) (CLEAR c) (ONTABLE c)
             (CLEAR d) (ONTABLE d) (CLEAR e) (ONTABLE e) (HANDEMPTY))
      (:goal (and (ON a b) (ON b c) (ON d e))))
    """
    problem = to_problem(write_task((DATA / "blocks-domain.pddl").read_text(), task))
    assert _layers(problem) == [[("on", "b", "c"), ("on", "d", "e")], [("on", "a", "b")]]
    agenda = goal_agenda(problem)
    assert [[part.atom for part in conjuncts(entry)] for entry in agenda[:-1]] == [
        [("on", "b", "c")],
        [("on", "b", "c"), ("on", "d", "e")],
    ]
    assert agenda[-1] == problem.goal


def test_a_crate_goes_on_its_base_after_the_base_is_placed(write_task):
    """Achieving on(c1, c3) needs clear(c1) (through ``lift``: ``unload`` cannot come
    first), which on(c2, c1) destroys; on(c3, p) needs clear(c3) against on(c1, c3)."""
    problem = to_problem(write_task(DEPOT, DEPOT_TASK))
    assert _layers(problem) == [[("on", "c3", "p")], [("on", "c1", "c3")], [("on", "c2", "c1")]]


def test_goals_with_no_orders_make_g0_the_whole_agenda(write_task):
    task = """
    (define (problem apart) (:domain BLOCKS) (:objects a b c d - block)
      (:init (CLEAR a) (ONTABLE a) (CLEAR b) (ONTABLE b) (CLEAR c) (ONTABLE c)
             (CLEAR d) (ONTABLE d) (HANDEMPTY))
      (:goal (and (ON a b) (ON c d))))
    """
    problem = to_problem(write_task((DATA / "blocks-domain.pddl").read_text(), task))
    assert goal_agenda(problem) == (problem.goal,)


def test_means_ends_achieves_the_agenda_in_turn(make_planner, write_task):
    """With the agenda the root's goal list holds its entries above G0: the tower is
    built bottom first, and the plan replays in the simulator."""
    problem = to_problem(write_task(DEPOT, DEPOT_TASK))
    planner = make_planner(strategy={"name": "means-ends", "goal_agenda": True},
                           prover={"name": "resolution", "goal_selection": "fewest"},
                           evaluator="relaxed-plan", relevance={"name": "add-list",
                                                                "rank": "cost"})
    result = planner.solve(problem)
    assert result.solved, result.status
    root = result.tree.nodes[0]
    assert [len(list(conjuncts(goal.formula))) for goal in root.goals] == [1, 2, 3]
    outcome = replay(problem, [str(step) for step in result.plan])
    assert outcome.valid, outcome.message
