"""MACROPs on PDDL: learned from a forward-search plan, read back against the translated
task, used by forward search as macro operators (composed exactly) and by means-ends."""

from __future__ import annotations

import random
from pathlib import Path

from strips_framework.grounding import ground
from strips_framework.macrops.forward import expand, with_macros
from strips_framework.learning import learn_sequence
from strips_framework.macrops.learning import TriangleTableLearner
from strips_framework.macrops.library_file import library_text, read_library
from strips_framework.macrops.macrop import Library
from strips_framework.pddl import load_task, to_problem
from strips_framework.pddl.validate import validate_plan
from strips_framework.planner import Planner
from strips_framework.plugin.config import Config

BLOCKS = Path(__file__).parents[2] / "examples" / "pddl" / "blocksworld"
FORWARD = {"strategy": "lazy-gbfs"}


def _library(tmp_path) -> Path:
    planner = Planner.create(Config.from_dict(FORWARD))
    pairs = [(BLOCKS / "domain.pddl", BLOCKS / "p4.pddl")]
    library, lessons = learn_sequence(planner, pairs, Library(), TriangleTableLearner())
    assert lessons[0].status == "solved" and library.macrops
    path = tmp_path / "blocks.lib"
    path.write_text(library_text(library, "blocks"))
    return path


def test_macro_operators_compose_their_steps_exactly(tmp_path):
    pddl = load_task(BLOCKS / "domain.pddl", BLOCKS / "p4.pddl")
    library = read_library(_library(tmp_path), to_problem(pddl))
    task = ground(pddl)
    grown, steps_of = with_macros(task, library)
    assert len(grown.operators) > len(task.operators)
    by_name = {op.name: op for op in task.operators}
    rng = random.Random(5)
    macros = [op for op in grown.operators if op.name in steps_of]
    state = task.init
    checked = 0
    for _ in range(300):  # random walks: wherever a macro applies, it equals its steps
        for op in macros:
            if op.applicable(state):
                sequential = state
                for name in steps_of[op.name]:
                    assert by_name[name].applicable(sequential)
                    sequential = by_name[name].apply(sequential)
                assert op.apply(state) == sequential
                checked += 1
        moves = [op for op in task.operators if op.applicable(state)]
        state = rng.choice(moves).apply(state)
    assert checked > 0


def test_forward_search_with_the_library_gives_a_valid_plan(tmp_path):
    library = _library(tmp_path)
    planner = Planner.create(Config.from_dict(FORWARD).for_pddl())
    result = planner.run(BLOCKS / "p4.pddl", BLOCKS / "domain.pddl", library=library)
    assert result.solved
    assert not any(step.startswith("(macrop") for step in result.plan)
    assert result.cost == len(result.plan)
    pddl = load_task(BLOCKS / "domain.pddl", BLOCKS / "p4.pddl")
    assert validate_plan(pddl, list(result.plan)).valid


def test_means_ends_uses_a_library_learned_from_forward_search(tmp_path):
    library = _library(tmp_path)
    planner = Planner.create(Config.from_dict({"strategy": "means-ends"}))
    without = planner.run(BLOCKS / "p4.pddl", BLOCKS / "domain.pddl")
    with_library = planner.run(BLOCKS / "p4.pddl", BLOCKS / "domain.pddl", library=library)
    assert with_library.solved
    assert with_library.statistics.nodes < without.statistics.nodes


def test_expand_keeps_ordinary_steps():
    assert expand(["(a)", "(macrop M1 0)", "(b)"], {"(macrop M1 0)": ("(x)", "(y)")}) == [
        "(a)", "(x)", "(y)", "(b)"]
