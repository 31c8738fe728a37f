"""The live feed to the VS Code PDDL search debugger, against a recorder on 127.0.0.1."""

from __future__ import annotations

import socket

import pytest

import figures
from debugger_recorder import protocol_problems, recorder
from strips_framework.cli.main import main

ROOT = figures.ROOT
BLOCKS = ROOT / "examples/pddl/blocksworld"


def _solve(*arguments: str, port: int) -> int:
    return main(["solve", *arguments, "--search-debugger", str(port), "--plan-file", "/dev/null"])


def test_blocks_p4_message_sequence_matches_the_protocol(capsys):
    with recorder() as (port, messages):
        assert _solve(str(BLOCKS / "domain.pddl"), str(BLOCKS / "p4.pddl"), port=port) == 0
    out = capsys.readouterr().out
    plan = [line.strip("()").strip() for line in out.splitlines() if line.startswith("(")]
    assert protocol_problems(messages) == []
    posts = [(path, body) for method, path, body in messages if method == "POST"]
    assert posts[0][0] == "/state/initial" and posts[-1][0] == "/plan"
    states = [body for path, body in posts if path in ("/state/initial", "/state")]
    estimates = [body for path, body in posts if path == "/state/heuristic"]
    evaluated = int(next(line for line in out.splitlines() if line.startswith("; evaluated:")).split()[-1])
    assert len(estimates) == evaluated  # every estimate the search made, once
    assert {e["id"] for e in estimates} <= {s["id"] for s in states}
    goal = posts[-1][1]
    assert [step["actionName"] for step in goal["planHead"]] == plan
    assert next(e for e in estimates if e["id"] == goal["id"])["h"] == 0


def test_means_ends_feed_sends_every_node_and_the_plan():
    with recorder() as (port, messages):
        assert _solve(str(ROOT / "examples/robot-world/light.strips"), port=port) == 0
    assert protocol_problems(messages) == []
    posts = [(path, body) for method, path, body in messages if method == "POST"]
    added = [body["id"] for path, body in posts if path in ("/state/initial", "/state")]
    assert sorted(map(int, added)) == list(range(13))  # the whole tree of 13 nodes
    assert posts[-1][0] == "/plan" and len(posts[-1][1]["planHead"]) == 6


def test_no_debugger_listening_is_one_clear_error(capsys):
    with socket.socket() as free:
        free.bind(("127.0.0.1", 0))
        port = free.getsockname()[1]
    assert _solve(str(BLOCKS / "domain.pddl"), str(BLOCKS / "p4.pddl"), port=port) == 2
    error = capsys.readouterr().err.strip().splitlines()
    assert len(error) == 1 and "no search debugger answers at http://127.0.0.1:" in error[0]


@pytest.mark.parametrize("where", ["ftp://127.0.0.1:1", "localhost"])
def test_a_bad_address_is_refused(where, capsys):
    assert main(["solve", str(BLOCKS / "p4.pddl"), "--search-debugger", where]) == 2
    assert "expected a port or an http:// URL" in capsys.readouterr().err
