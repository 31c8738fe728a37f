"""The explorer page (``strips solve --explore``): what it records, and the page itself
opened in headless Chromium from file:// with every network request refused."""

from __future__ import annotations

import json
import re
from pathlib import Path
from typing import Any

import pytest

import figures
from strips_framework import Planner
from strips_framework.explore.page import explorer_page
from strips_framework.explore.record import SearchRecord
from strips_framework.logic.formulas import formula_to_str
from strips_framework.logic.terms import atom_to_str

ROOT = figures.ROOT
LIGHT = ROOT / "examples/robot-world/light.strips"
FIVE = ROOT / "examples/robot-world/five-goals.strips"
BLOCKS = ROOT / "examples/pddl/blocksworld"


def recorded(path: Path, domain: Path | None = None, config: dict | None = None) -> SearchRecord:
    record = SearchRecord()
    planner = Planner.create(config, observers=[record])
    planner.run(path, domain)
    return record


def page_data(html: str) -> dict:
    found = re.search(r'<script type="application/json" id="data">(.*?)</script>', html, re.S)
    return json.loads(found.group(1).replace("<\\/", "</"))


def test_world_model_document_keeps_scores_parts_differences_and_relevant_operators():
    record = recorded(LIGHT)
    document = record.document("light")
    strings = document["strings"]
    nodes = {node["id"]: node for node in document["nodes"]}
    tree = record.result.tree
    assert len(nodes) == len(tree.nodes) == 13
    assert [n["id"] for n in document["nodes"] if n["path"]] == [n.id for n in tree.solution_path()]
    for node in tree.nodes:
        row = nodes[node.id]
        assert [strings[f] for f, _ in row["goals"]] == [formula_to_str(g.formula) for g in node.goals]
        model = document["models"][row["model"]]
        assert sorted(strings[i] for i in model["add"]) == sorted(atom_to_str(a) for a in node.model.additions)
        assert len(model["del"]) == len(node.model.deletions)
        assert (row["diff"] is None) == (node.difference is None)
    scored = [row for row in document["nodes"] if "scores" in row]
    assert scored, "the paper evaluator scores queued nodes"
    for row in scored:
        for score, parts in row["scores"]:
            assert parts is not None and score == pytest.approx(sum(parts.values()))
        assert row["relevant"], "a queued node has relevant instances"
    # The paper evaluator's parts are named; a node's second score counts its first child.
    twice = next(row for row in scored if len(row["scores"]) > 1)
    assert twice["scores"][1][1]["successors"] > twice["scores"][0][1]["successors"]


def test_an_unwatched_search_runs_unwrapped(monkeypatch):
    """No observers: the strategy gets the configured evaluator itself, and a forward
    run's state space keeps its own ``add`` (nothing watched, nothing paid)."""
    from strips_framework.forward.base import SearchRun

    planner = Planner.create()
    given = []
    strategy_class = type(planner.config.build(planner.registry, "strategy"))
    original = strategy_class.search

    def spy(self, problem, prover, differences, relevance, evaluator, *rest):
        given.append(evaluator)
        return original(self, problem, prover, differences, relevance, evaluator, *rest)

    monkeypatch.setattr(strategy_class, "search", spy)
    planner.run(LIGHT)
    assert type(given[0]) is planner.registry.get("evaluator", "paper").cls  # no watcher around it
    runs = []
    monkeypatch.setattr(SearchRun, "__init__", _spy_init(SearchRun.__init__, runs))
    Planner.create().run(BLOCKS / "p4.pddl", BLOCKS / "domain.pddl")
    assert runs and "add" not in vars(runs[0].space) and "check" not in vars(runs[0].budget)


def _spy_init(init, runs):
    def spy(self, *args, **kwargs):
        init(self, *args, **kwargs)
        runs.append(self)
    return spy


def test_forward_document_samples_states_and_keeps_the_best_h_curve():
    record = recorded(BLOCKS / "p4.pddl", BLOCKS / "domain.pddl")
    document = record.document("p4")
    strings = document["strings"]
    path = [node for node in document["nodes"] if node["path"]]
    assert len(path) == len(record.result.plan) + 1
    assert path[-1]["h"] == 0
    assert [n["g"] for n in path] == list(range(len(path)))  # unit costs, along the plan
    # A state's ADDED/DELETED facts rebuild it from the initial state.
    task = record.task
    init = {task.facts[i] for i in range(len(task.facts)) if task.init >> i & 1}
    assert {strings[i] for i in document["init"]} == init
    for node in document["nodes"]:
        state = record.run.space.state(node["id"])
        facts = {task.facts[i] for i in range(len(task.facts)) if state >> i & 1}
        assert facts == (init - {strings[i] for i in node["del"]}) | {strings[i] for i in node["add"]}
    best = [h for _, _, h in document["curve"]]
    assert best == sorted(best, reverse=True) and len(set(best)) == len(best)
    assert best[-1] == 0


@pytest.mark.parametrize("strategy", ["lazy-gbfs", "gbfs", "astar", "ehc"])
def test_compiled_and_reference_loops_are_watched_alike(strategy, monkeypatch):
    """The compiled search loops and their pure-Python references report the same
    states, estimates and best-h curve to the explorer."""
    config = {"strategy": strategy, "heuristic": "lmcut" if strategy == "astar" else "ff"}
    compiled = recorded(BLOCKS / "p4.pddl", BLOCKS / "domain.pddl", config).document("p4")
    monkeypatch.setenv("STRIPS_PURE_PYTHON", "1")
    reference = recorded(BLOCKS / "p4.pddl", BLOCKS / "domain.pddl", config).document("p4")
    assert compiled["nodes"] == reference["nodes"] and compiled["curve"] == reference["curve"]
    assert len(compiled["nodes"]) > 1


def test_forward_sample_is_bounded(monkeypatch):
    import strips_framework.explore.record as record_module

    monkeypatch.setattr(record_module, "FIRST_STATES", 3)
    monkeypatch.setattr(record_module, "SAMPLED_STATES", 3)
    config = {"strategy": "astar", "heuristic": "blind"}
    record = recorded(BLOCKS / "p4.pddl", BLOCKS / "domain.pddl", config)
    document = record.document("p4")
    reached = document["reached"]
    assert reached > 40
    plain = [n for n in document["nodes"] if not n["path"]]
    # The sample, and the ancestors that connect it to the root: far fewer than reached.
    assert len(record.kept) == 6 and len(document["nodes"]) < reached / 2
    # A* estimates a state before numbering it: each shown state still has its h.
    assert all(isinstance(n["h"], (int, float)) for n in document["nodes"])
    assert any(n["id"] > 3 for n in plain), "the later states are sampled too"


def test_macrop_uses_are_marked(tmp_path):
    library = tmp_path / "robot.lib"
    robot = ROOT / "examples/robot-world"
    figures.solve(["learn", str(robot / "light.strips"), str(robot / "boxes.strips"), "-o", str(library)])
    record = SearchRecord()
    planner = Planner.create(observers=[record])
    planner.run(FIVE, library=library)
    document = record.document("five-goals")
    strings = document["strings"]
    used = [row for row in document["nodes"] if "macrop" in row]
    assert used
    by_id = {node.id: node for node in record.result.tree.nodes}
    for row in used:
        node = by_id[row["id"]]
        assert [strings[i] for i in row["macrop"]] == [str(step) for step in node.applied.steps()]
        assert len(row["macrop"]) > 1
    plain = [row for row in document["nodes"] if row["applied"] is not None and "macrop" not in row]
    assert all(len(by_id[row["id"]].applied.steps()) == 1 for row in plain)


def test_fields_a_strategy_adds_are_shown(monkeypatch):
    """A node field the page does not know (an ABSTRIPS level, say) is carried by name."""
    from strips_framework.explore import record as record_module

    record = recorded(LIGHT)
    real = record_module._fields
    monkeypatch.setattr(record_module, "_fields",
                        lambda node: real(node) | {"level": node.id % 3})
    rows = record.document("light")["nodes"]
    assert [row["extra"]["level"] for row in rows] == [str(i % 3) for i in range(len(rows))]
    # A strategy's own node class with one more field: the field is found by name.
    from strips_framework.means_ends.node import Node

    class RankedNode(Node):
        __slots__ = ("rank",)

        def __init__(self, *fields: Any, rank: int = 0) -> None:
            super().__init__(*fields)
            self.rank = rank

    node = record.result.tree.nodes[0]
    mine = RankedNode(node.id, node.model, node.goals, None, rank=2)
    assert real(mine)["rank"] == 2 and "rank" not in real(node)


def test_explorer_page_escapes_its_data():
    document = {"title": "</script><b>", "status": "solved", "plan": [], "statistics": {},
                "kind": "none", "nodes": [], "strings": ["</script>"]}
    html = explorer_page(document)
    assert html.count("</script>") == 2  # the data's and the code's, not the title's
    assert page_data(html)["strings"] == ["</script>"]


def test_notebook_reprs(tmp_path):
    record = recorded(LIGHT)
    result = record.result
    html = result._repr_html_()
    assert "<code>(turnonlight LIGHTSWITCH1)</code>" in html and "search tree" in html
    assert result.tree._repr_html_().count("<li>") == 13  # a list item per node
    assert "srcdoc=" in record._repr_html_()


# In the browser.

def test_light_page_click_shows_goal_list_and_model_changes(launched, tmp_path):
    page_file = tmp_path / "light.html"
    figures.solve(["solve", str(LIGHT), "--explore", str(page_file)])
    record = recorded(LIGHT)
    node = record.result.tree.nodes[5]
    page, problems = figures.open_page(launched, page_file)
    page.wait_for_function("window.explorer && window.explorer.ready")
    x, y = page.evaluate("window.explorer.position(5)")
    page.mouse.click(x, y)
    assert page.inner_text("#detail-title").startswith("n5 ")
    goals = page.locator("#detail-goals li").all_inner_texts()
    expected = [("G0" if g.operator is None else f"pre {g.operator}") + ": " + formula_to_str(g.formula)
                for g in node.goals]
    assert [" ".join(g.split()) for g in goals] == [" ".join(e.split()) for e in expected]
    added = page.locator("#detail-add li").all_inner_texts()
    assert sorted(added) == sorted(atom_to_str(a) for a in node.model.additions)
    deleted = page.locator("#detail-del li").all_inner_texts()
    assert sorted(deleted) == sorted(str(node.model.initial.clauses[i]) for i in node.model.deletions)
    assert page.locator("#detail-scores tr").count() >= 2
    page.screenshot(path=str(tmp_path / "light.png"))
    assert (tmp_path / "light.png").read_bytes().startswith(b"\x89PNG")
    assert not problems, problems


def test_search_box_finds_nodes_by_their_goals(launched, tmp_path):
    page_file = tmp_path / "five.html"
    figures.solve(["solve", str(FIVE), "--explore", str(page_file)])
    data = page_data(page_file.read_text())
    word = "INROOM(ROBOT, ROOM2)"
    strings = data["strings"]
    expected = sum(
        1 for n in data["nodes"]
        if any(word.lower() in strings[f].lower() for f, _ in n["goals"])
        or any(word.lower() in strings[i].lower()
               for i in data["models"][n["model"]]["add"] + data["models"][n["model"]]["del"])
        or (n["applied"] is not None and word.lower() in strings[n["applied"]].lower())
        or any(o is not None and word.lower() in strings[o].lower() for _, o in n["goals"])
    )
    page, problems = figures.open_page(launched, page_file)
    page.wait_for_function("window.explorer && window.explorer.ready")
    page.fill("#search", word)
    assert page.inner_text("#match-count") == f"{expected} nodes match"
    page.click("#matches li >> nth=0")
    assert word in " ".join(page.locator("#detail").all_inner_texts())
    assert not problems, problems


def test_forward_page_shows_states_and_the_best_h_plot(launched, tmp_path):
    page_file = tmp_path / "p4.html"
    figures.solve(["solve", str(BLOCKS / "domain.pddl"), str(BLOCKS / "p4.pddl"), "--explore", str(page_file)])
    page, problems = figures.open_page(launched, page_file)
    page.wait_for_function("window.explorer && window.explorer.ready")
    assert page.locator("#curve-svg path").count() == 1
    page.click("#goal")
    assert "h=0" in page.inner_text("#detail-title")
    assert page.locator("#detail-add li").count() > 0
    assert not problems, problems


def test_docs_figures_are_made(launched, tmp_path):
    for make in figures.FIGURES:
        shot = make(launched, tmp_path)
        assert shot.read_bytes().startswith(b"\x89PNG")


def test_ten_thousand_node_explorer_stays_small_and_opens(launched, tmp_path):
    """Size is asserted; the opening time is measured in benchmarks/bench_explorer.py."""
    config = tmp_path / "big.toml"
    config.write_text('[evaluator]\nname = "breadth-first"\n[limits]\nnodes = 10000\ntime = 600\n')
    page_file = tmp_path / "big.html"
    from strips_framework.cli.main import main

    assert main(["solve", str(FIVE), "--config", str(config), "--explore", str(page_file)]) == 12
    assert page_file.stat().st_size < 10 * 2**20
    page, problems = figures.open_page(launched, page_file)
    page.wait_for_function("window.explorer && window.explorer.ready")
    assert page.evaluate("window.explorer.count") == 10000
    assert not problems, problems
