"""ABSTRIPS: the criticality rule on the robot world, refinements valid at every level,
the final plan valid in the independent simulator, and backtracking across levels."""

from __future__ import annotations

from pathlib import Path

import pytest

from strips_abstrips.hierarchy import CRITICAL, DETAIL, STATIC, computed, given
from strips_framework.errors import ConfigError
from strips_framework.planner import Planner
from strips_framework.result import Status
from strips_framework.worldmodel.simulate import replay

ROBOT_WORLD = Path(__file__).resolve().parents[3] / "examples" / "robot-world"

#: The computed criticalities of the robot world with ``short_plan = 1`` (the rule of
#: strips_abstrips.hierarchy): (operator, literal) -> value.
ROBOT_TABLE = {
    ("goto1(m)", "ONFLOOR"): DETAIL,
    ("goto1(m)", "INROOM(ROBOT, x)"): CRITICAL,
    ("goto1(m)", "LOCINROOM(m, x)"): STATIC,
    ("goto2(m)", "ONFLOOR"): DETAIL,
    ("goto2(m)", "INROOM(ROBOT, x)"): CRITICAL,
    ("goto2(m)", "INROOM(m, x)"): CRITICAL,
    ("pushto(m, n)", "PUSHABLE(m)"): STATIC,
    ("pushto(m, n)", "ONFLOOR"): DETAIL,
    ("pushto(m, n)", "NEXTTO(ROBOT, m)"): DETAIL,
    ("pushto(m, n)", "INROOM(m, x)"): DETAIL,
    ("pushto(m, n)", "INROOM(n, x)"): DETAIL,
    ("turnonlight(m)", "TYPE(n, BOX)"): STATIC,
    ("turnonlight(m)", "ON(ROBOT, n)"): CRITICAL,
    ("turnonlight(m)", "NEXTTO(n, m)"): CRITICAL,
    ("turnonlight(m)", "TYPE(m, LIGHTSWITCH)"): STATIC,
    ("climbonbox(m)", "ONFLOOR"): DETAIL,
    ("climbonbox(m)", "TYPE(m, BOX)"): STATIC,
    ("climbonbox(m)", "NEXTTO(ROBOT, m)"): CRITICAL,
    ("climboffbox(m)", "TYPE(m, BOX)"): STATIC,
    ("climboffbox(m)", "ON(ROBOT, m)"): CRITICAL,
    ("gothrudoor(k, l, m)", "NEXTTO(ROBOT, k)"): CRITICAL,
    ("gothrudoor(k, l, m)", "CONNECTS(k, l, m)"): STATIC,
    ("gothrudoor(k, l, m)", "INROOM(ROBOT, l)"): DETAIL,
    ("gothrudoor(k, l, m)", "TYPE(k, DOOR)"): STATIC,
    ("gothrudoor(k, l, m)", "ONFLOOR"): DETAIL,
}


def load(name: str):
    return Planner.create().load(ROBOT_WORLD / name)


def test_robot_world_criticalities_follow_the_documented_rule():
    problem = load("light.strips")
    rows = computed(problem).table(problem.operators)
    table = {(op, literal): value for op, literal, value in rows}
    assert table == ROBOT_TABLE


def test_longer_short_plans_make_more_literals_details():
    problem = load("light.strips")
    one = computed(problem, 1).values
    two = computed(problem, 2).values
    assert all(two[key] <= one[key] for key in one)
    assert sum(two.values()) < sum(one.values())  # goto's INROOM(ROBOT, x): 2 steps


def test_given_criticalities_go_by_predicate():
    problem = load("light.strips")
    hierarchy = given(problem, {"INROOM": 3, "NEXTTO": 1})
    table = {(op, literal): value for op, literal, value in hierarchy.table(problem.operators)}
    assert table[("goto2(m)", "INROOM(m, x)")] == 3
    assert table[("pushto(m, n)", "NEXTTO(ROBOT, m)")] == 1
    assert table[("pushto(m, n)", "PUSHABLE(m)")] == 0
    assert hierarchy.levels == [3, 1, 0]


def solve(name: str, **strategy: object):
    planner = Planner.create({"strategy": {"name": "abstrips", **strategy}})
    problem = planner.load(ROBOT_WORLD / name)
    return planner, problem, planner.solve(problem)


def level_plans(result) -> dict[int, list[str]]:
    """Each level's plan: that of the last node of the level on the solution path (the
    goal node its refinement reached)."""
    plans: dict[int, list[str]] = {}
    for node in result.tree.solution_path():
        plans[node.level] = [str(step) for step in node.plan]
    return plans


@pytest.mark.parametrize("name", ["light.strips", "boxes.strips", "other-room.strips",
                                  "five-goals.strips", "door-room2.strips"])
def test_every_level_refines_into_a_valid_plan(name):
    planner, problem, result = solve(name)
    assert result.status is Status.SOLVED
    outcome = replay(problem, [str(step) for step in result.plan])
    assert outcome.valid, outcome.message
    strategy = planner.config.build(planner.registry, "strategy")
    hierarchy = strategy.hierarchy(problem)
    plans = level_plans(result)
    assert sorted(plans, reverse=True) == hierarchy.levels
    for level, plan in plans.items():
        abstract = hierarchy.problem_at(problem, level)
        outcome = replay(abstract, plan)
        assert outcome.valid, f"level {level}: {outcome.message}"
    # Each level's plan keeps the steps of the one above, in order (a refinement only
    # adds steps): ABSTRIPS's refinement, not a fresh plan.
    levels = hierarchy.levels
    for upper, lower in zip(levels, levels[1:]):
        rest = iter(plans[lower])
        assert all(step in rest for step in plans[upper]), (plans[upper], plans[lower])


def test_the_level_of_each_node_is_in_the_tree_and_the_picture():
    from strips_framework.cli.tree_dot import search_tree_to_dot

    _, _, result = solve("light.strips")
    levels = {node.level for node in result.tree.nodes}
    assert levels == {STATIC, CRITICAL, DETAIL}
    dot = search_tree_to_dot(result.tree)
    for level in levels:
        assert f'subgraph cluster_level_{level} {{ label="level {level}"' in dot


BACKTRACK = """\
problem backtrack
constants a
facts
  OK(a)
operator dead(x)
  pre    OK(x) & NEVER(x)
  add    G(x)
operator live(x)
  pre    OK(x) & B(x)
  add    G(x)
operator makeb(x)
  pre    OK(x)
  add    B(x)
operator makenever(x)
  pre    OK(x) & NEVER(x)
  add    NEVER(x)
goal G(a)
"""


def test_a_plan_that_cannot_be_refined_sends_the_search_back_up(tmp_path):
    # With OK the only critical literal, the top level cannot tell dead(a) from live(a)
    # and plans dead(a) first; NEVER(a) cannot be achieved, so that refinement fails and
    # the top level's next plan, live(a), is refined instead.
    path = tmp_path / "backtrack.strips"
    path.write_text(BACKTRACK)
    planner = Planner.create({"strategy": {"name": "abstrips", "criticality": {"OK": 1}}})
    problem = planner.load(path)
    result = planner.solve(problem)
    assert result.status is Status.SOLVED
    assert list(result.plan) == ["(makeb a)", "(live a)"]
    top_plans = [
        [str(step) for step in node.plan]
        for node in result.tree.nodes
        if node.level == 1 and node.difference is None and node.goals[0].operator is None
    ]
    assert top_plans[:2] == [["dead(a)"], ["live(a)"]]
    refinement_roots = [n for n in result.tree.nodes if n.level == 0 and n.parent.level == 1]
    assert len(refinement_roots) == 2


def test_a_bad_criticality_table_is_one_config_error():
    with pytest.raises(ConfigError, match="criticality"):
        Planner.create({"strategy": {"name": "abstrips", "criticality": {"OK": "high"}}})


FREE_CHOICE = """\
problem free-choice
constants a b
facts
  TOOL(a), TOOL(b), HERE(b)
operator use(t)
  pre    TOOL(t) & HERE(t)
  add    DONE
goal DONE
"""


def test_bindings_the_abstract_proof_chose_are_the_refinements_to_remake(tmp_path):
    # At the top level (TOOL only) the proof of use(t)'s precondition binds t to a, its
    # first answer; HERE(a) never holds. The refinement is given use(t), not use(a), and
    # its own proof finds b.
    path = tmp_path / "free-choice.strips"
    path.write_text(FREE_CHOICE)
    planner = Planner.create({"strategy": {"name": "abstrips", "criticality": {"TOOL": 1}}})
    result = planner.solve(planner.load(path))
    assert result.status is Status.SOLVED
    assert list(result.plan) == ["(use b)"]
    top = [n for n in result.tree.nodes if n.level == 1 and n.applied is not None]
    assert [str(n.applied) for n in top] == ["use(a)"]


def test_an_achiever_whose_static_literal_no_fact_matches_is_no_short_plan(tmp_path):
    # get(x) would achieve HAVE(x) in one step, but it needs SHOP(x), static and never a
    # fact: HAVE(x) is critical for use(x). With a shop, it is a detail.
    text = (
        "problem shops\nconstants a\nfacts\n  ITEM(a)\n{shop}"
        "operator use(x)\n  pre    ITEM(x) & HAVE(x)\n  add    DONE\n"
        "operator get(x)\n  pre    SHOP(x)\n  add    HAVE(x)\ngoal DONE\n"
    )
    values = {}
    for shop in ("", "  SHOP(a)\n"):
        path = tmp_path / "shops.strips"
        path.write_text(text.format(shop=shop))
        problem = Planner.create().load(path)
        values[bool(shop)] = computed(problem).values[("use", 1)]
    assert values == {False: CRITICAL, True: DETAIL}



# A crane takes a plate off whatever it sits on (the plate must be bare) and puts it
# on a bare base. Plate D is to go onto base P, where plate C sits under plate E.
PLATES = """\
problem plates
constants K C D E P Q
primitive FREE/1 BARE/1 ON/2 HOLDS/2
facts
  CRANE(K), FREE(K), ON(C, P), ON(E, C), BARE(E), ON(D, Q), BARE(D)
operator take(k, c, s)
  pre    CRANE(k) & FREE(k) & ON(c, s) & BARE(c)
  delete FREE(k), BARE(c), ON(c, s)
  add    HOLDS(k, c), BARE(s)
operator put(k, c, s)
  pre    CRANE(k) & HOLDS(k, c) & BARE(s)
  delete HOLDS(k, c), BARE(s)
  add    FREE(k), ON(c, s), BARE(c)
goal ON(D, P)
"""


@pytest.mark.parametrize("goal_loops", [False, True])
def test_refinements_push_no_goal_loops(tmp_path, goal_loops):
    # Refining put(k, D, P), take(k, c, P) is pushed to bare P; a partial proof binds c
    # to E (bare), leaving ON(E, P), which put(k, E, P) adds, but that put needs P bare:
    # a goal loop, which means-ends's goal_loops check (on by default) keeps out of
    # every level's search. (Neither search finds a plan in its nodes: plain
    # means-ends with the defaults does not either.)
    path = tmp_path / "plates.strips"
    path.write_text(PLATES)
    planner = Planner.create({"strategy": {"name": "abstrips", "goal_loops": goal_loops},
                              "limits": {"nodes": 300}})
    result = planner.solve(planner.load(path))
    loops = [
        node for node in result.tree.nodes
        if len(node.goals) > 2 and node.goals[1].operator is not None
        and str(node.goals[1].operator).startswith("take(")
        and str(node.goals[1].operator).endswith(", P)")
        and str(node.goals[0].operator).startswith("put(")
        and str(node.goals[0].operator).endswith(", P)")
    ]
    assert bool(loops) is not goal_loops
