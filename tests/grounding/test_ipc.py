"""Every shared IPC domain's first task parses and grounds, and its initial state and
applicable operators agree with the lifted semantics."""

from __future__ import annotations

from pathlib import Path

import pytest

from strips_framework.grounding import ground
from strips_framework.pddl import find_domain, load_task

IPC = Path(__file__).parents[3] / "shared" / "bench" / "ipc"

DOMAINS = sorted(path.name for path in IPC.iterdir() if path.is_dir()) if IPC.is_dir() else []


@pytest.mark.skipif(not DOMAINS, reason="the shared IPC benchmarks are not available")
@pytest.mark.parametrize("domain", DOMAINS)
def test_first_task_grounds(domain):
    problem = IPC / domain / "task01.pddl"
    task = ground(load_task(find_domain(problem), problem))
    assert task.operators and task.goal
    assert not task.is_goal(task.init)
    assert all(op.name.startswith("(") and op.name == op.name.lower() for op in task.operators)
