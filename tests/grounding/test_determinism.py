"""Grounding does not depend on PYTHONHASHSEED: same facts, same operators, same order."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

from shared_bench import small_bench

DATA = Path(__file__).parents[1] / "pddl" / "data"
BLOCKS = Path(__file__).parents[2] / "examples" / "pddl" / "blocksworld"
KIT = Path(__file__).parents[2] / "src" / "strips_framework" / "testing" / "tasks"
IPC = small_bench("ipc")

SCRIPT = """
import sys
from pathlib import Path
from strips_framework.grounding import ground
from strips_framework.pddl import load_task
for domain, problem in zip(sys.argv[1::2], sys.argv[2::2]):
    task = ground(load_task(Path(domain), Path(problem)))
    print(task.facts, task.init, task.goal)
    for op in task.operators:
        print(op.name, op.pre, op.pre_neg, op.add, op.delete, op.cost)
    for axiom in task.axioms:
        print(axiom)
"""


def grounded_with_seed(seed: str, files: list[Path]) -> str:
    env = {**os.environ, "PYTHONHASHSEED": seed}
    args = [sys.executable, "-c", SCRIPT, *map(str, files)]
    return subprocess.run(args, env=env, capture_output=True, text=True, check=True).stdout


def test_same_grounding_whatever_the_hash_seed():
    files = [DATA / "rooms-domain.pddl", DATA / "rooms-2.pddl",
             BLOCKS / "domain.pddl", BLOCKS / "p4.pddl",  # enough lines without ../shared
             KIT / "gripper-domain.pddl", KIT / "gripper-3.pddl",
             KIT / "delivery-domain.pddl", KIT / "delivery-2.pddl",
             IPC / "depot" / "domain.pddl", IPC / "depot" / "task02.pddl"]
    first = grounded_with_seed("1", files)
    assert first.count("\n") > 100
    assert grounded_with_seed("2", files) == first
