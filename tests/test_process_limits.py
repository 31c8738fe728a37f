"""The process-wide limits of ``strips solve`` (cli/process_limits.py)."""

from __future__ import annotations

import time

import pytest

from strips_framework.cli.process_limits import GRACE_SECONDS, enforced
from strips_framework.limits import Clock, LimitReached, Limits
from strips_framework.result import Status


def test_the_alarm_rings_after_the_deadline_not_at_it():
    """A search that stops at its own limit watches the same clock; the alarm must leave
    it time to write its result (its statistics were lost one run in two)."""
    clock = Clock(0.01, started=time.perf_counter() - 1)  # the deadline has passed
    with enforced(Limits(time=0.01), clock):
        time.sleep(0.1)  # inside the grace: no alarm yet
    with pytest.raises(LimitReached) as raised, enforced(Limits(time=0.01), clock):
        time.sleep(GRACE_SECONDS + 5)
    assert raised.value.status is Status.TIME_LIMIT


#: ``strips solve`` on the light task with a 1 s limit, the paper evaluator replaced by
#: one that never returns and catches what interrupts it (``{catch}``), as careless plugin
#: code (or a garbage-collection callback) would; it says on stderr what it swallowed.
_SWALLOWING_RUN = """
import sys, time
from strips_framework.means_ends.evaluator import PaperEvaluator
from strips_framework.cli.main import main

def evaluate(self, node):
    until = time.perf_counter() + 20
    while time.perf_counter() < until:
        try:
            time.sleep(0.01)
        except {catch} as error:
            print("swallowed", type(error).__name__, file=sys.stderr, flush=True)
    return 0.0

PaperEvaluator.evaluate = evaluate
sys.exit(main(["solve", {problem!r}, "--config", {config!r}]))
"""


def _swallowing_run(tmp_path, catch: str):
    import subprocess
    import sys
    from pathlib import Path

    config = tmp_path / "strips.toml"
    config.write_text("[limits]\ntime = 1\n")
    problem = Path(__file__).resolve().parents[1] / "examples/robot-world/light.strips"
    script = _SWALLOWING_RUN.format(catch=catch, problem=str(problem), config=str(config))
    started = time.perf_counter()
    run = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=60)
    return run, time.perf_counter() - started


def test_no_except_exception_on_the_search_path_catches_the_alarm(tmp_path):
    """The alarm raised inside a plugin, below the strategy, the registry and the CLI:
    ``except Exception`` anywhere on that path (the plugin's own here) lets it through,
    and the run ends as a time limit with the search's statistics."""
    run, _ = _swallowing_run(tmp_path, "Exception")
    assert "swallowed" not in run.stderr, run.stderr
    assert run.returncode == 23, run.stderr
    assert "; status: time-limit" in run.stdout


def test_a_swallowed_alarm_still_ends_the_run(tmp_path):
    """Even a bare ``except BaseException`` loop cannot keep the process past the limit:
    the alarm's next ring stops it with exit code 23 and the time it ran."""
    run, seconds = _swallowing_run(tmp_path, "BaseException")
    assert "swallowed LimitReached" in run.stderr
    assert run.returncode == 23, run.stderr
    assert "; status: time-limit" in run.stdout and "swallowed; stopped" in run.stderr
    assert seconds < 15  # the plugin's loop would hold it for 20 s
