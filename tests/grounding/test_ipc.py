"""Every IPC domain's first task (../shared, or the repository's copy) parses and grounds, and its initial state and
applicable operators agree with the lifted semantics."""

from __future__ import annotations

import pytest
from shared_bench import small_bench

from strips_framework.grounding import ground
from strips_framework.pddl import find_domain, load_task

IPC = small_bench("ipc")

DOMAINS = sorted(path.name for path in IPC.iterdir() if path.is_dir())


@pytest.mark.parametrize("domain", DOMAINS)
def test_first_task_grounds(domain):
    problem = IPC / domain / "task01.pddl"
    task = ground(load_task(find_domain(problem), problem))
    assert task.operators and task.goal
    assert not task.is_goal(task.init)
    assert all(op.name.startswith("(") and op.name == op.name.lower() for op in task.operators)
