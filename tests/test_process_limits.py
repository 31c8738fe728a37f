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
